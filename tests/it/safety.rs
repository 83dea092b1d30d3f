//! The independent check of every golden module (see `common/dense.rs`), and a check that the
//! trunk cell really blocks the direct moves it claims to block.

use crate::common::dense::{boxes_of, check_module, min_distance};
use crate::common::{files, root};
use gen_rapid::cell;
use gen_rapid::robot::Robot;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

fn check_golden(golden: &std::path::Path) -> (usize, f64) {
    let stem = golden.file_name().and_then(|s| s.to_str()).expect("name");
    let cell_stem = stem.split('.').next().expect("stem");
    let cell_path = root().join(format!("cells/{cell_stem}.yaml"));
    let text = std::fs::read_to_string(&cell_path).expect("cell");
    let cell = cell::parse(&cell_path, &text).expect("cell parses");
    let robot = Robot::load(&cell.robot.urdf_path).expect("robot");
    check_module(
        &cell,
        &robot,
        &std::fs::read_to_string(golden).expect("golden"),
        stem,
    )
}

#[test]
fn every_move_of_every_golden_module_keeps_the_clearance() {
    let goldens = files(&root().join("tests/golden"), ".mod");
    assert!(!goldens.is_empty(), "no golden modules found");
    for g in goldens {
        let (samples, smallest) = check_golden(&g);
        assert!(samples > 100, "{}: only {samples} samples", g.display());
        eprintln!(
            "{}: {samples} samples, smallest distance {smallest:.2} mm",
            g.display()
        );
    }
}

#[test]
fn the_trunk_cells_direct_moves_are_blocked_so_planning_matters() {
    // cells/trunk.yaml claims that the straight moves A -> B, C -> D and E -> F hit something
    // (the quarter panels and the clamp post); the same dense check must see it.
    let cell_path = root().join("cells/trunk.yaml");
    let text = std::fs::read_to_string(&cell_path).expect("cell");
    let cell = cell::parse(&cell_path, &text).expect("cell parses");
    let robot = Robot::load(&cell.robot.urdf_path).expect("robot");
    let cell::Base::Fixed(base) = cell.robot.base else {
        panic!("the trunk cell has a fixed base")
    };
    let cell_from_robot = Isometry3::from_parts(
        Translation3::new(base[0], base[1], base[2]),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), cell.robot.yaw_deg.to_radians()),
    );
    let boxes = boxes_of(&cell);
    let joints = |name: &str| match cell
        .points
        .iter()
        .find(|p| p.name == name)
        .map(|p| &p.target)
    {
        Some(cell::Target::Joints { axes_deg, .. }) => *axes_deg,
        _ => panic!("point {name}"),
    };
    for (from, to) in [("A", "B"), ("C", "D"), ("E", "F")] {
        let (a, b) = (joints(from), joints(to));
        let d_ends = min_distance(&robot, &cell_from_robot, &boxes, a).min(min_distance(
            &robot,
            &cell_from_robot,
            &boxes,
            b,
        ));
        assert!(
            d_ends > cell.planner.clearance_mm,
            "{from} and {to} are free"
        );
        let worst = (0..=200)
            .map(|i| {
                let t = i as f64 / 200.0;
                min_distance(
                    &robot,
                    &cell_from_robot,
                    &boxes,
                    [
                        a[0] + t * (b[0] - a[0]),
                        a[1] + t * (b[1] - a[1]),
                        a[2] + t * (b[2] - a[2]),
                    ],
                )
            })
            .fold(f64::INFINITY, f64::min);
        assert!(
            worst < cell.planner.clearance_mm,
            "the direct move {from} -> {to} keeps {worst:.1} mm: the cell should block it"
        );
    }
}
