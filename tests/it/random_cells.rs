//! Cells nobody wrote by hand: random boxes around a randomly placed and turned robot, random
//! free points, random clearances, sometimes a floor. Every method's module is held to the
//! independent dense check of `common/dense.rs`; a method may fail only with a planning error
//! (no path, a depth-first dead end), never otherwise. Deterministic (fixed seed).

use crate::common::dense::check_module;
use crate::common::root;
use gen_rapid::cell::{self, Method};
use gen_rapid::collision::{CollisionModel, Obstacle, Placement};
use gen_rapid::error::Error;
use gen_rapid::geometry::Aabb;
use gen_rapid::pipeline;
use gen_rapid::robot::Robot;
use nalgebra::Point3;

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
    // Free points, found with the library's model (it only picks inputs here; the check of the
    // result is independent).
    let obstacles = boxes
        .iter()
        .map(|(n, a, b)| Obstacle {
            name: n.clone(),
            aabb: Aabb::new(Point3::from(*a), Point3::from(*b)),
        })
        .collect();
    let model = CollisionModel::new(
        robot,
        Placement {
            base_mm: base,
            yaw_deg: yaw,
        },
        obstacles,
        clearance,
    );
    let mut points = Vec::new();
    for _ in 0..400 {
        let a = [
            rng.range(-150.0, 150.0),
            rng.range(-60.0, 60.0),
            rng.range(-55.0, 60.0),
        ]
        .map(|x| (x * 10.0).round() / 10.0); // one decimal: off a 3 deg grid mostly
        if model.is_free(&a) {
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
        let cell = cell::parse(&path, &rc.yaml).unwrap_or_else(|e| panic!("{e}\n{}", rc.yaml));
        let prep = pipeline::prepare(cell.clone()).unwrap_or_else(|e| panic!("{e}\n{}", rc.yaml));
        let cs = pipeline::cspace(&prep, rc.grid_deg);
        for m in Method::ALL {
            match pipeline::plan_and_render(&prep, &cs, m, |p| {
                Some(pipeline::manipulation_time_s(&prep, p))
            }) {
                Ok(out) => {
                    let label = format!("random cell {index}, {m}");
                    let (samples, smallest) = check_module(&cell, &prep.robot, &out.text, &label);
                    assert!(
                        samples > 0 && smallest >= cell.planner.clearance_mm - 1e-6,
                        "{label}"
                    );
                    planned += 1;
                }
                Err(Error::Plan { .. }) => failed += 1,
                Err(e) => panic!(
                    "random cell {index}, {m}: unexpected error {e}\n{}",
                    rc.yaml
                ),
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
