//! Cells nobody wrote by hand: random boxes around a randomly placed and turned robot, random
//! free points, random clearances, sometimes a floor, and (in the second test) a random torch on
//! the flange and points with their own wrists. Every method's module is held to the
//! independent dense check of `common/dense.rs` (arm and tool, every via's wrist on the
//! schedule); a method may fail only with a planning error, never otherwise. The searches are
//! complete on their grid, so the neighboring and extensile searches (one graph: the grid's
//! free nodes, the steps the whole-move check accepts, 26 neighbours) plan exactly the same
//! cells, and a cell the depth-first search plans (its axis steps) they plan too: the second
//! method shows the first one's cells solvable. Deterministic (fixed seeds).

use crate::common::dense::{check_module, Scene};
use crate::common::library::{
    paper_and_refined, parse_cell, plan_every_method, Cell, Planned, Robot,
};
use crate::common::root;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
}

struct RandomCell {
    yaml: String,
    grid_deg: f64,
}

/// A random torch or gripper on the flange, as the cell's `tool:` block (tool0 frame, mm): a
/// neck along z, sometimes a body box at the flange and a ball at the tip, off the axis.
fn random_tool(rng: &mut Rng) -> String {
    let len = rng.range(80.0, 350.0).round();
    let bend = rng.range(-120.0, 120.0).round();
    let mut yaml = format!(
        "tool:\n  name: tRandom\n  tframe: [[{bend}, 0, {len}], [1, 0, 0, 0]]\n  mass: 1\n  cog: [0, 0, {}]\n  shapes:\n",
        (len / 2.0).round()
    );
    yaml += &format!(
        "    - {{ name: neck, cylinder: {{ from: [0, 0, 0], to: [{bend}, 0, {len}], radius: {} }} }}\n",
        rng.range(10.0, 40.0).round()
    );
    if rng.int(0, 1) == 1 {
        let h = rng.range(20.0, 60.0).round();
        yaml += &format!(
            "    - {{ name: body, box: {{ min: [-{h}, -{h}, 0], max: [{h}, {h}, {}] }} }}\n",
            rng.range(30.0, 120.0).round()
        );
    }
    if rng.int(0, 1) == 1 {
        yaml += &format!(
            "    - {{ name: tip, sphere: {{ centre: [{bend}, 0, {len}], radius: {} }} }}\n",
            rng.range(5.0, 30.0).round()
        );
    }
    yaml
}

fn random_cell(rng: &mut Rng, robot: &Robot, index: usize) -> Option<RandomCell> {
    random_cell_with(rng, robot, index, None)
}

/// A random cell; with `tool` (a `tool:` block), the points give all six axes (random wrists)
/// and are free with the tool on (by the dense check's own measure, the tool as the cell file
/// gives it).
fn random_cell_with(
    rng: &mut Rng,
    robot: &Robot,
    index: usize,
    tool: Option<String>,
) -> Option<RandomCell> {
    let base = [rng.int(-500, 500) as f64, rng.int(-500, 500) as f64, 0.0];
    let yaw = rng.int(-180, 180) as f64;
    let clearance = [0.0, 5.0, 10.0, 25.0][rng.int(0, 3) as usize];
    let mut boxes: Vec<(String, [f64; 3], [f64; 3])> = Vec::new();
    if rng.int(0, 1) == 1 {
        boxes.push((
            "floor".into(),
            [-3000.0, -3000.0, -50.0],
            [3000.0, 3000.0, 0.0],
        ));
    }
    for k in 0..rng.int(2, 6) {
        let theta = rng.range(0.0, std::f64::consts::TAU);
        let rho = rng.range(650.0, 1400.0);
        let (hx, hy) = (
            rng.range(50.0, 300.0).round(),
            rng.range(50.0, 300.0).round(),
        );
        if rho - hx.hypot(hy) < 350.0 + clearance + 20.0 {
            continue; // would touch the base
        }
        let c = [
            (base[0] + rho * theta.cos()).round(),
            (base[1] + rho * theta.sin()).round(),
        ];
        let z0 = if rng.int(0, 2) == 0 {
            rng.range(200.0, 900.0).round()
        } else {
            0.0
        };
        let h = rng.range(150.0, 1300.0).round();
        boxes.push((
            format!("box{k}"),
            [c[0] - hx, c[1] - hy, z0],
            [c[0] + hx, c[1] + hy, z0 + h],
        ));
    }
    let urdf = root().join("robots/irb1400.urdf");
    let mut yaml = format!(
        "module: Random{index}\nrobot:\n  urdf: {}\n  base: [{}, {}, {}]\n  yaw: {yaw}\n",
        urdf.display(),
        base[0],
        base[1],
        base[2]
    );
    yaml += tool.as_deref().unwrap_or_default();
    if !boxes.is_empty() {
        yaml += "obstacles:\n";
    }
    for (n, a, b) in &boxes {
        yaml += &format!(
            "  - {{ name: {n}, box: {{ min: [{}, {}, {}], max: [{}, {}, {}] }} }}\n",
            a[0], a[1], a[2], b[0], b[1], b[2]
        );
    }
    if boxes.is_empty() {
        yaml += "obstacles: []\n";
    }
    // The scene with the cell's tool as the cell file gives it (two stand-in points make it a
    // cell).
    let stub = format!(
        "{yaml}points:\n  - {{ name: S0, joints: [0, 0, 0] }}\n  - {{ name: S1, joints: [1, 0, 0] }}\n"
    );
    let stub = cell_of(&stub, index);
    let scene = Scene::new(robot, base, yaw, &stub);
    // Free points, found with the dense check's own distances (1 mm beyond the clearance, so
    // that the generator's model agrees that they are free).
    let mut points: Vec<[f64; 6]> = Vec::new();
    for _ in 0..400 {
        let arm = [
            rng.range(-150.0, 150.0),
            rng.range(-60.0, 60.0),
            rng.range(-55.0, 60.0),
        ];
        let wrist = match tool {
            Some(_) => [
                rng.range(-150.0, 150.0),
                rng.range(-115.0, 115.0),
                rng.range(-300.0, 300.0),
            ],
            None => [0.0; 3],
        };
        // One decimal: off a 3 deg grid mostly.
        let a = [arm[0], arm[1], arm[2], wrist[0], wrist[1], wrist[2]]
            .map(|x| (x * 10.0).round() / 10.0);
        if robot.check_range6(&a).is_ok() && scene.nearest(a).mm > clearance + 1.0 {
            points.push(a);
            if points.len() == 3 {
                break;
            }
        }
    }
    if points.len() < 3 {
        return None;
    }
    yaml += "points:\n";
    for (i, p) in points.iter().enumerate() {
        // Every third cell asks a fly-by zone at its second point (checked, else fine).
        let zone = if index % 3 == 0 && i == 1 {
            ", zone: z10"
        } else {
            ""
        };
        yaml += &match &tool {
            Some(_) => format!(
                "  - {{ name: P{i}, joints: [{}, {}, {}, {}, {}, {}]{zone} }}\n",
                p[0], p[1], p[2], p[3], p[4], p[5]
            ),
            None => format!(
                "  - {{ name: P{i}, joints: [{}, {}, {}]{zone} }}\n",
                p[0], p[1], p[2]
            ),
        };
    }
    yaml += &format!("planner:\n  clearance: {clearance}\n");
    // Every other cell flies by its vias where their corners are proven (the refine stage).
    if index % 2 == 1 {
        yaml += "motion:\n  via_zone: z50\n";
    }
    Some(RandomCell {
        yaml,
        grid_deg: 3.0,
    })
}

/// The cell of a random cell's YAML.
fn cell_of(yaml: &str, index: usize) -> Cell {
    let path = root().join(format!("tests/random{index}.yaml"));
    parse_cell(&path, yaml).unwrap_or_else(|e| panic!("{e}\n{yaml}"))
}

/// The complete searches agree (module doc): neighboring and extensile plan the same cells, a
/// cell depth-first plans they plan too, and the only failures are "not connected" and
/// depth-first's Fig. 8.
fn assert_searches_agree(results: &[(String, Planned)], what: &str) {
    let ok = |m: &str| {
        results
            .iter()
            .any(|(name, r)| name == m && matches!(r, Planned::Module(_)))
    };
    assert_eq!(
        ok("neighboring"),
        ok("extensile"),
        "the 26-neighbour searches disagree: {what}"
    );
    if ok("depth-first") {
        assert!(ok("extensile"), "depth-first plans, extensile not: {what}");
    }
    for (m, r) in results {
        if let Planned::PlanningFailed(msg) = r {
            assert!(
                msg.contains("is not connected")
                    || (m == "depth-first" && msg.contains("only diagonally")),
                "{m}: {msg}: {what}"
            );
        }
    }
}

#[test]
fn random_cells_plan_safe_modules_or_fail_cleanly() {
    let robot = Robot::irb1400();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut planned, mut failed, mut cells, mut corners) = (0, 0, 0, 0);
    let mut index = 0;
    while cells < 10 {
        index += 1;
        assert!(index < 100, "could not make enough random cells");
        let Some(rc) = random_cell(&mut rng, &robot, index) else {
            continue;
        };
        cells += 1;
        let cell = cell_of(&rc.yaml, index);
        let results = plan_every_method(&cell, rc.grid_deg)
            .unwrap_or_else(|e| panic!("random cell {index}: unexpected error {e}\n{}", rc.yaml));
        assert_searches_agree(&results, &format!("random cell {index}\n{}", rc.yaml));
        // The cell's own method (which `paper_and_refined` plans) fails only where it failed
        // among every method's results (`plan_every_method`: with a planning error).
        let own = cell.planner.method.name();
        let own_planned = results
            .iter()
            .any(|(m, p)| m == own && matches!(p, Planned::Module(_)));
        let paper_refined = paper_and_refined(&cell, rc.grid_deg);
        assert_eq!(
            paper_refined.is_ok(),
            own_planned,
            "random cell {index}: {own} planned {own_planned}, paper and refined {:?}\n{}",
            paper_refined.as_ref().err(),
            rc.yaml
        );
        // The shortcut never lengthens a route, in moves or in estimated time; where the vias
        // fly by (odd cells), a via whose corner is too tight may be split in three
        // (`refine::split`), more moves for less time.
        if let Ok(r) = paper_refined {
            let fly_by = index % 2 == 1;
            assert!(
                (fly_by || r.refined.0 <= r.paper.0) && r.refined.1 <= r.paper.1 + 1e-9,
                "random cell {index}: paper {:?}, refined {:?}\n{}",
                r.paper,
                r.refined,
                rc.yaml
            );
        }
        for (m, result) in results {
            match result {
                Planned::Module(text) => {
                    let label = format!("random cell {index}, {m}");
                    let report = check_module(&cell, &robot, &text, &label)
                        .unwrap_or_else(|f| panic!("{}\n{}", f.join("\n"), rc.yaml));
                    assert_eq!(report.module.planner, m, "{label}");
                    corners += report.corners;
                    planned += 1;
                }
                Planned::PlanningFailed(_) => failed += 1,
            }
        }
    }
    eprintln!("{cells} random cells: {planned} modules planned and checked ({corners} zoned corners sampled), {failed} plans failed cleanly");
    assert!(corners > 0, "no zoned corner to check");
    assert!(
        planned >= 15,
        "too few successes to mean anything: {planned} of {}",
        3 * cells
    );
}

/// Random cells with a random tool and random wrists at the points: every method's module keeps
/// the clearance for the arm and the tool (dense check), the vias follow the wrist schedule, and
/// the complete searches agree on which cells they plan.
#[test]
fn random_tool_cells_plan_safe_modules_and_the_searches_agree() {
    let robot = Robot::irb1400();
    let mut rng = Rng(0x7001_C311_5EED_0042);
    let (mut cells, mut planned, mut no_path) = (0, 0, 0);
    let mut tool_closest = 0;
    let mut index = 100;
    while cells < 12 {
        index += 1;
        assert!(index < 400, "could not make enough random tool cells");
        let tool = random_tool(&mut rng);
        let Some(rc) = random_cell_with(&mut rng, &robot, index, Some(tool)) else {
            continue;
        };
        cells += 1;
        let cell = cell_of(&rc.yaml, index);
        let results = plan_every_method(&cell, rc.grid_deg).unwrap_or_else(|e| {
            panic!(
                "random tool cell {index}: unexpected error {e}\n{}",
                rc.yaml
            )
        });
        assert_searches_agree(&results, &format!("random tool cell {index}\n{}", rc.yaml));
        for (m, result) in results {
            match result {
                Planned::Module(text) => {
                    let label = format!("random tool cell {index}, {m}");
                    let report = check_module(&cell, &robot, &text, &label)
                        .unwrap_or_else(|f| panic!("{}\n{}", f.join("\n"), rc.yaml));
                    if report.smallest.link.starts_with("tool shape") {
                        tool_closest += 1;
                    }
                    planned += 1;
                }
                Planned::PlanningFailed(_) => no_path += 1,
            }
        }
    }
    eprintln!("{cells} random tool cells: {planned} modules planned and checked, {no_path} not connected, tool closest in {tool_closest}");
    assert!(
        planned >= 18,
        "too few successes: {planned} of {}",
        3 * cells
    );
    assert!(
        tool_closest >= 3,
        "the tool came closest in only {tool_closest} modules"
    );
}
