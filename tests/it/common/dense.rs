//! The independent whole-move check: read a `.mod` as written (targets, moves, the header's base
//! and yaw), place the robot's link cylinders with the URDF kinematics, and sample every straight
//! move so densely that no point of the arm moves more than 1 mm between samples, measuring the
//! exact distance to every box with parry3d's own shapes. It shares no code with `collision` or
//! `geometry`: only the cell parser and the robot's kinematics (which `robot`'s tests hold
//! against RobotStudio).
#![allow(dead_code)]

use gen_rapid::cell;
use gen_rapid::robot::Robot;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use parry3d::math::{Pose, Vector};
use parry3d::shape::{Cuboid, Cylinder};

pub struct Module {
    pub base_mm: [f64; 3],
    pub yaw_deg: f64,
    pub clearance_mm: f64,
    pub targets: Vec<(String, [f64; 6])>,
    pub moves: Vec<String>,
    pub header_moves: usize,
}

fn numbers(s: &str) -> Vec<f64> {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'E'))
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f64>().unwrap_or_else(|_| panic!("number '{t}'")))
        .collect()
}

pub fn parse_module(text: &str) -> Module {
    let mut m = Module {
        base_mm: [f64::NAN; 3],
        yaw_deg: f64::NAN,
        clearance_mm: f64::NAN,
        targets: vec![],
        moves: vec![],
        header_moves: usize::MAX,
    };
    for line in text.lines().map(str::trim) {
        if let Some(rest) = line.strip_prefix("! base: ") {
            let v = numbers(rest);
            m.base_mm = [v[0], v[1], v[2]];
            m.yaw_deg = v[3];
        } else if let Some(rest) = line.strip_prefix("! clearance (mm): ") {
            m.clearance_mm = rest.parse().expect("clearance");
        } else if let Some(rest) = line.strip_prefix("! moves: ") {
            m.header_moves = rest.parse().expect("moves");
        } else if let Some(rest) = line.strip_prefix("CONST jointtarget ") {
            let (name, value) = rest.split_once(" := ").expect("jointtarget shape");
            let inner = value
                .trim_start_matches("[[")
                .split(']')
                .next()
                .expect("axes");
            let v = numbers(inner);
            assert_eq!(v.len(), 6, "{line}");
            m.targets
                .push((name.to_string(), [v[0], v[1], v[2], v[3], v[4], v[5]]));
            assert!(value.ends_with(",[9E9,9E9,9E9,9E9,9E9,9E9]];"), "{line}");
        } else if let Some(rest) = line.strip_prefix("MoveAbsJ ") {
            let name = rest.split('\\').next().expect("target name");
            m.moves.push(name.to_string());
        }
    }
    m
}

/// Smallest distance from the arm's link cylinders to the boxes at one configuration. The
/// stated model rule (README, `collision` module doc): link 1's cylinder is not checked against
/// a box whose top is at or below the base's mounting plane (the floor the robot stands on).
pub fn min_distance(
    robot: &Robot,
    cell_from_robot: &Isometry3<f64>,
    boxes: &[(Cuboid, Pose)],
    axes: [f64; 3],
) -> f64 {
    let base_z = cell_from_robot.translation.vector.z;
    let poses = robot.arm_link_poses(&axes);
    let mut best = f64::INFINITY;
    for c in &robot.cylinders {
        let frame = cell_from_robot * poses[c.joint_index];
        let (a, b) = (frame * c.a, frame * c.b);
        let axis = b - a;
        let len = axis.norm();
        let rot =
            UnitQuaternion::rotation_between(&Vector3::y(), &(axis / len)).unwrap_or_else(|| {
                UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
            });
        let q = rot.quaternion();
        let mid = nalgebra::center(&a, &b);
        let pose = Pose::from_parts(
            Vector::new(mid.x, mid.y, mid.z),
            parry3d::math::Rotation::from_xyzw(q.i, q.j, q.k, q.w),
        );
        let cyl = Cylinder::new(len / 2.0, c.radius_mm);
        for (cub, bp) in boxes {
            let top = bp.translation.z + cub.half_extents.z;
            if c.joint_index == 0 && top <= base_z + 1e-6 {
                continue;
            }
            let d = parry3d::query::distance(&pose, &cyl, bp, cub)
                .expect("convex shapes")
                .distance;
            best = best.min(d);
        }
    }
    best
}

/// The cell's boxes as parry3d cuboids in the cell frame.
pub fn boxes_of(cell: &cell::Cell) -> Vec<(Cuboid, Pose)> {
    cell.obstacles
        .iter()
        .map(|o| {
            let h = [0, 1, 2].map(|k| (o.max_mm[k] - o.min_mm[k]) / 2.0);
            let c = [0, 1, 2].map(|k| (o.max_mm[k] + o.min_mm[k]) / 2.0);
            (
                Cuboid::new(Vector::new(h[0], h[1], h[2])),
                Pose::from_translation(Vector::new(c[0], c[1], c[2])),
            )
        })
        .collect()
}

/// Checks a module written for `cell` (see the module doc); `stem` names it in messages.
/// Returns the number of samples taken and the smallest distance seen.
pub fn check_module(cell: &cell::Cell, robot: &Robot, text: &str, stem: &str) -> (usize, f64) {
    let module = parse_module(text);
    assert!(
        module.base_mm.iter().all(|v| v.is_finite()) && module.yaw_deg.is_finite(),
        "{stem}: header base"
    );
    assert_eq!(
        module.clearance_mm, cell.planner.clearance_mm,
        "{stem}: header clearance"
    );
    assert_eq!(
        module.header_moves + 1,
        module.moves.len(),
        "{stem}: header moves"
    );
    // Moves name the targets one to one, in order.
    let names: Vec<&str> = module.targets.iter().map(|t| t.0.as_str()).collect();
    assert_eq!(
        names,
        module.moves.iter().map(String::as_str).collect::<Vec<_>>(),
        "{stem}"
    );
    // Every cell point appears, in order, exactly as given (joint points).
    let mut k = 0;
    for p in &cell.points {
        let at = module.targets[k..]
            .iter()
            .position(|t| t.0 == p.name)
            .unwrap_or_else(|| panic!("{stem}: point {} missing or out of order", p.name));
        k += at;
        if let cell::Target::Joints {
            axes_deg,
            wrist_deg,
        } = &p.target
        {
            assert_eq!(
                &module.targets[k].1[..3],
                &axes_deg[..],
                "{stem}: point {}",
                p.name
            );
            let w = wrist_deg.unwrap_or(cell.robot.wrist_deg);
            assert_eq!(
                &module.targets[k].1[3..],
                &w[..],
                "{stem}: point {} wrist",
                p.name
            );
        }
    }
    assert_eq!(
        module.targets.first().map(|t| t.0.as_str()),
        cell.points.first().map(|p| p.name.as_str())
    );
    assert_eq!(
        module.targets.last().map(|t| t.0.as_str()),
        cell.points.last().map(|p| p.name.as_str())
    );

    let cell_from_robot = Isometry3::from_parts(
        Translation3::new(module.base_mm[0], module.base_mm[1], module.base_mm[2]),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), module.yaw_deg.to_radians()),
    );
    let boxes = boxes_of(cell);
    // No point of the arm is farther than this from any joint axis (IRB 1400: reach 1.44 m plus
    // the wrist, radius and offsets stay well below 2 m); 1 mm per step of displacement.
    const ARM_RADIUS_MM: f64 = 2000.0;
    let mut samples = 0;
    let mut smallest = f64::INFINITY;
    for (name, axes) in &module.targets {
        robot
            .check_range6(axes)
            .unwrap_or_else(|e| panic!("{stem}: target {name} out of range: {e}"));
    }
    for w in module.targets.windows(2) {
        let (a, b) = (w[0].1, w[1].1);
        let qa = robot.urdf_joints_deg(&a);
        let qb = robot.urdf_joints_deg(&b);
        let turn_rad: f64 = (0..3).map(|k| (qb[k] - qa[k]).abs().to_radians()).sum();
        let n = ((ARM_RADIUS_MM * turn_rad) / 1.0).ceil().max(1.0) as usize;
        for i in 0..=n {
            let t = i as f64 / n as f64;
            let axes = [
                a[0] + t * (b[0] - a[0]),
                a[1] + t * (b[1] - a[1]),
                a[2] + t * (b[2] - a[2]),
            ];
            let d = min_distance(robot, &cell_from_robot, &boxes, axes);
            assert!(
                d >= cell.planner.clearance_mm - 1e-6,
                "{stem}: move {} -> {} at t = {t:.4} ({axes:?}) is {d:.3} mm from an obstacle, below the clearance {} mm",
                w[0].0,
                w[1].0,
                cell.planner.clearance_mm
            );
            smallest = smallest.min(d);
            samples += 1;
        }
    }
    (samples, smallest)
}
