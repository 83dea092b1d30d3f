//! Cells nobody wrote by hand: random boxes around a randomly placed and turned robot, random
//! free points, random clearances, sometimes a floor. Every method's module is held to the
//! independent dense check of `common/dense.rs`; a method may fail only with a planning error
//! (no path, a depth-first dead end), never otherwise. Deterministic (fixed seed).

use crate::common::dense::{check_module, Scene};
use crate::common::library::{parse_cell, plan_every_method, Planned, Robot};
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

fn random_cell(rng: &mut Rng, robot: &Robot, index: usize) -> Option<RandomCell> {
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
    // Free points, found with the dense check's own distances (1 mm beyond the clearance, so
    // that the generator's model agrees that they are free).
    let scene = Scene::from_boxes(robot, base, yaw, &boxes);
    let mut points = Vec::new();
    for _ in 0..400 {
        let a = [
            rng.range(-150.0, 150.0),
            rng.range(-60.0, 60.0),
            rng.range(-55.0, 60.0),
        ]
        .map(|x| (x * 10.0).round() / 10.0); // one decimal: off a 3 deg grid mostly
        if robot.check_range3(&a).is_ok() && scene.nearest(a).mm > clearance + 1.0 {
            points.push(a);
            if points.len() == 3 {
                break;
            }
        }
    }
    if points.len() < 3 {
        return None;
    }
    let urdf = root().join("robots/irb1400.urdf");
    let mut yaml = format!(
        "module: Random{index}\nrobot:\n  urdf: {}\n  base: [{}, {}, {}]\n  yaw: {yaw}\nobstacles:\n",
        urdf.display(),
        base[0],
        base[1],
        base[2]
    );
    for (n, a, b) in &boxes {
        yaml += &format!(
            "  - {{ name: {n}, box: {{ min: [{}, {}, {}], max: [{}, {}, {}] }} }}\n",
            a[0], a[1], a[2], b[0], b[1], b[2]
        );
    }
    if boxes.is_empty() {
        yaml = yaml.replace("obstacles:\n", "obstacles: []\n");
    }
    yaml += "points:\n";
    for (i, p) in points.iter().enumerate() {
        yaml += &format!(
            "  - {{ name: P{i}, joints: [{}, {}, {}] }}\n",
            p[0], p[1], p[2]
        );
    }
    yaml += &format!("planner:\n  clearance: {clearance}\n");
    Some(RandomCell {
        yaml,
        grid_deg: 3.0,
    })
}

#[test]
fn random_cells_plan_safe_modules_or_fail_cleanly() {
    let robot = Robot::irb1400();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut planned, mut failed, mut cells) = (0, 0, 0);
    let mut index = 0;
    while cells < 10 {
        index += 1;
        assert!(index < 100, "could not make enough random cells");
        let Some(rc) = random_cell(&mut rng, &robot, index) else {
            continue;
        };
        cells += 1;
        let path = root().join(format!("tests/random{index}.yaml"));
        let cell = parse_cell(&path, &rc.yaml).unwrap_or_else(|e| panic!("{e}\n{}", rc.yaml));
        let results = plan_every_method(&cell, rc.grid_deg)
            .unwrap_or_else(|e| panic!("random cell {index}: unexpected error {e}\n{}", rc.yaml));
        for (m, result) in results {
            match result {
                Planned::Module(text) => {
                    let label = format!("random cell {index}, {m}");
                    let report = check_module(&cell, &robot, &text, &label)
                        .unwrap_or_else(|f| panic!("{}\n{}", f.join("\n"), rc.yaml));
                    assert_eq!(report.module.planner, m, "{label}");
                    planned += 1;
                }
                Planned::PlanningFailed(_) => failed += 1,
            }
        }
    }
    eprintln!("{cells} random cells: {planned} modules planned and checked, {failed} plans failed cleanly");
    assert!(
        planned >= 15,
        "too few successes to mean anything: {planned} of {}",
        3 * cells
    );
}
