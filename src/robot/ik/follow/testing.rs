//! The example cells' frames and targets for the tests of following paths (here and in the
//! collision proof along a path): `cells/torch-trunk.yaml`'s torch, work object and seams, and
//! `cells/gripper-pick.yaml`'s gripper and descents, as the cell files give them.

use super::{follow, FollowedPath, TcpFrames};
use crate::geometry::path::CartesianPath;
use crate::robot::ik::six::SixAxisIk;
use crate::robot::{Axes6, Robot};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};
use std::f64::consts::FRAC_1_SQRT_2;

pub(crate) fn irb() -> (Robot, SixAxisIk) {
    let robot = Robot::irb1400();
    let ik = SixAxisIk::from_robot(&robot).expect("the IRB 1400 is a spherical-wrist arm");
    (robot, ik)
}

pub(crate) fn pose(p: [f64; 3], q: [f64; 4]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3])),
    )
}

/// A base at `base_mm` turned `yaw_deg` about z.
pub(crate) fn base(base_mm: [f64; 3], yaw_deg: f64) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(base_mm[0], base_mm[1], base_mm[2]),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), yaw_deg.to_radians()),
    )
}

/// No tool (the TCP is the flange), the base at the cell's origin.
pub(crate) fn bare_frames() -> TcpFrames {
    TcpFrames {
        cell_from_robot: Isometry3::identity(),
        tframe: Isometry3::identity(),
    }
}

/// torch-trunk: the base at (0, -850, 0) turned 90 deg, the bent torch.
pub(crate) fn torch_frames() -> TcpFrames {
    TcpFrames {
        cell_from_robot: base([0.0, -850.0, 0.0], 90.0),
        tframe: pose([116.673, 0.0, 336.673], [0.9238795, 0.0, 0.3826834, 0.0]),
    }
}

/// torch-trunk's seam orientation (in its work object, whose axes are the cell's).
pub(crate) const SEAM_Q: [f64; 4] = [0.1830127, -0.6830127, -0.6830127, -0.1830127];

/// A seam point of torch-trunk in the cell frame (work object at (-830, -380, 100)).
pub(crate) fn seam(x: f64, y: f64) -> Isometry3<f64> {
    pose([-830.0, -380.0, 100.0], [1.0, 0.0, 0.0, 0.0]) * pose([x, y, 0.0], SEAM_Q)
}

/// The joints torch-trunk's module writes for L1 and R1 (the seams' starts).
pub(crate) const L1: Axes6 = [33.816, 20.956, 52.462, 10.745, 50.586, -153.966];
pub(crate) const R1: Axes6 = [-24.514, 44.727, 39.355, -6.833, 64.506, -200.820];

/// gripper-pick: the base on the pedestal, the gripper's TCP 180 mm out.
pub(crate) fn gripper_frames() -> TcpFrames {
    TcpFrames {
        cell_from_robot: base([0.0, 0.0, 400.0], 0.0),
        tframe: pose([0.0, 0.0, 180.0], [1.0, 0.0, 0.0, 0.0]),
    }
}

/// A gripper-pick robtarget (in its conveyor work object) in the cell frame.
pub(crate) fn conveyor(x: f64, y: f64, z: f64) -> Isometry3<f64> {
    pose(
        [700.0, 0.0, 750.0],
        [FRAC_1_SQRT_2, 0.0, 0.0, FRAC_1_SQRT_2],
    ) * pose([x, y, z], [0.0, 1.0, 0.0, 0.0])
}

/// The joints gripper-pick's module writes for above_pick and above_place.
pub(crate) const ABOVE_PICK: Axes6 = [-18.435, 11.508, 30.997, 0.0, 59.003, 71.565];
pub(crate) const ABOVE_PLACE: Axes6 = [90.0, 9.123, 35.675, 0.0, 54.325, 180.0];

/// Random joints of the IRB 1400 about its working pose (axis 5 from 20 to 90 deg, clear of the
/// wrist singularity), not all in range: the random paths' starts.
pub(crate) fn random_joints(rng: &mut crate::geometry::testing::Rng) -> Axes6 {
    [
        rng.range(-120.0, 120.0),
        rng.range(-30.0, 50.0),
        rng.range(-20.0, 40.0),
        rng.range(-90.0, 90.0),
        rng.range(20.0, 90.0),
        rng.range(-180.0, 180.0),
    ]
}

/// A random move: start joints, the TCP there, the end pose, the direction to it.
pub(crate) type RandomMove = (Axes6, Isometry3<f64>, Isometry3<f64>, Vector3<f64>);

/// A random process move's start and end (cell frame): `random_joints` in range, the TCP
/// there, and a pose 100 to 300 mm away along a random direction (returned too), turned up
/// to 30 deg about a random axis; `None` for joints out of range.
pub(crate) fn random_move(
    rng: &mut crate::geometry::testing::Rng,
    robot: &Robot,
    frames: &TcpFrames,
) -> Option<RandomMove> {
    let start = random_joints(rng);
    robot.check_range6(&start).ok()?;
    let a = tcp(robot, frames, &start);
    let dir = rng.point(-1.0, 1.0).coords.normalize();
    let axis = rng.point(-1.0, 1.0).coords.normalize();
    let end = Isometry3::from_parts(
        (a.translation.vector + dir * rng.range(100.0, 300.0)).into(),
        UnitQuaternion::from_scaled_axis(axis * rng.range(0.0, 30f64.to_radians())) * a.rotation,
    );
    Some((start, a, end, dir))
}

/// The TCP (cell frame) at `joints`.
pub(crate) fn tcp(robot: &Robot, frames: &TcpFrames, joints: &Axes6) -> Isometry3<f64> {
    frames.cell_from_robot * robot.tool0(joints) * frames.tframe
}

/// The line a controller runs from `joints` to `end` (cell frame): from the TCP of the joints.
pub(crate) fn line_from(
    robot: &Robot,
    frames: &TcpFrames,
    joints: &Axes6,
    end: &Isometry3<f64>,
) -> CartesianPath {
    CartesianPath::line(&tcp(robot, frames, joints), end).expect("a line")
}

/// The example cells' process lines, followed: torch-trunk's seams L1 -> L2 and R1 -> R2, and
/// gripper-pick's descents above_pick -> pick and above_place -> place. Each with its name, its
/// frames and the start joints.
pub(crate) fn example_lines() -> Vec<(&'static str, TcpFrames, Axes6, CartesianPath)> {
    let (robot, _) = irb();
    let (torch, grip) = (torch_frames(), gripper_frames());
    vec![
        (
            "L1 -> L2",
            torch,
            L1,
            line_from(&robot, &torch, &L1, &seam(330.0, 630.0)),
        ),
        (
            "R1 -> R2",
            torch,
            R1,
            line_from(&robot, &torch, &R1, &seam(1330.0, 280.0)),
        ),
        (
            "above_pick -> pick",
            grip,
            ABOVE_PICK,
            line_from(&robot, &grip, &ABOVE_PICK, &conveyor(-300.0, -200.0, 30.0)),
        ),
        (
            "above_place -> place",
            grip,
            ABOVE_PLACE,
            line_from(&robot, &grip, &ABOVE_PLACE, &conveyor(900.0, 700.0, -20.0)),
        ),
    ]
}

/// [`example_lines`] followed (each must follow).
pub(crate) fn example_followed() -> Vec<(&'static str, TcpFrames, FollowedPath)> {
    let (_, ik) = irb();
    example_lines()
        .into_iter()
        .map(|(name, frames, start, path)| {
            let f =
                follow(&ik, &frames, &path, &start, None).unwrap_or_else(|e| panic!("{name}: {e}"));
            (name, frames, f)
        })
        .collect()
}
