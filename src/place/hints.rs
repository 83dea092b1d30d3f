//! What would make an unreachable robtarget reachable: the help line of a robtarget that fails
//! because axis 5 (or another axis) would leave its range or the pose is out of reach
//! ([`SixAxisError::Axis5`], [`SixAxisError::OutOfRange`], [`SixAxisError::OutOfReach`]), when
//! a change a programmer can make does it.
//!
//! 1. **A turn of the tool about its own z axis** (the TCP's, `pose * Rz(turn)`), tried in
//!    [`TURN_STEP_DEG`] steps, the smallest turn first (positive before negative at equal size,
//!    up to half a turn). With a tool whose TCP is off the flange's axis, or tilted against it
//!    (a torch), such a turn moves the wrist centre and changes axis 5; for a weld torch or a
//!    round gripper it is often free to choose. The orientation is given as the cell writes one
//!    (7 decimals) and that quaternion, read back as the cell reads it, is what is verified.
//! 2. **Out of reach: a move of the base** along the floor, straight towards the point's wrist
//!    centre (away from it when it is too near), in [`BASE_STEP_MM`] steps from the shortfall on,
//!    at most [`BASE_MOVE_MAX_MM`] beyond it, keeping the confdata the point asks for.
//!
//! A suggestion is made only when the six-axis IK of the changed pose (or from the moved base)
//! has a solution that the place stage accepts as it would accept any: in range after rounding,
//! reaching the pose, free of collision there (from the moved base, with the collision model of
//! that base). Only this point is verified: the help line says so for a base move, which moves
//! every point. Only a fixed base gets hints (`base: auto` searches the base itself).

use super::robtarget::Tcp;
use super::{PlaceError, Placement, PoseCheck};
use crate::cell::{Cell, Frame, Target};
use crate::robot::ik::six::{ChooseError, SixAxisError};
use crate::robot::Robot;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// The step of the turns tried, deg.
pub const TURN_STEP_DEG: f64 = 15.0;
/// The step of the base moves tried, mm.
pub const BASE_STEP_MM: f64 = 10.0;
/// How far beyond the shortfall a base move is tried, mm.
pub const BASE_MOVE_MAX_MM: f64 = 200.0;

/// The turns tried, deg: 15, -15, 30, -30, ..., 165, -165, 180.
fn turns() -> Vec<f64> {
    let n = (180.0 / TURN_STEP_DEG).round() as i32;
    let mut t = Vec::new();
    for k in 1..n {
        let a = f64::from(k) * TURN_STEP_DEG;
        t.extend([a, -a]);
    }
    t.push(180.0);
    t
}

/// `q` as the cell writes a quaternion (7 decimals), and as the cell reads it back
/// (normalised).
fn as_written(q: &UnitQuaternion<f64>) -> ([f64; 4], [f64; 4]) {
    let r = |v: f64| (v * 1e7).round() / 1e7 + 0.0;
    let mut w = [r(q.w), r(q.i), r(q.j), r(q.k)];
    if let Some(first) = w.iter().find(|v| **v != 0.0) {
        if *first < 0.0 {
            w = w.map(|v| -v + 0.0);
        }
    }
    let read = UnitQuaternion::from_quaternion(Quaternion::new(w[0], w[1], w[2], w[3]));
    (w, [read.w, read.i, read.j, read.k])
}

fn fmt_quat(q: &[f64; 4]) -> String {
    let v: Vec<String> = q.iter().map(|x| format!("{x:.7}")).collect();
    format!("[{}]", v.join(", "))
}

/// `e` with its help line ([`PlaceError::Robtarget`]'s `hint`) when a turn of the tool or a move
/// of the base makes the point reachable (module docs); `e` as it is otherwise.
pub(super) fn with_hint<C: PoseCheck>(
    e: PlaceError,
    cell: &Cell,
    robot: &Robot,
    placement: Placement,
    check: &C,
    check_at: &impl Fn(Placement) -> C,
) -> PlaceError {
    let PlaceError::Robtarget {
        point,
        base_mm,
        yaw_deg,
        source,
        loc,
        hint: None,
    } = e
    else {
        return e;
    };
    let hint = find(&source, &point, cell, robot, placement, check, check_at);
    PlaceError::Robtarget {
        point,
        base_mm,
        yaw_deg,
        source,
        loc,
        hint,
    }
}

fn find<C: PoseCheck>(
    source: &ChooseError<String>,
    point: &str,
    cell: &Cell,
    robot: &Robot,
    placement: Placement,
    check: &C,
    check_at: &impl Fn(Placement) -> C,
) -> Option<String> {
    let reach = match source {
        ChooseError::Ik(SixAxisError::Axis5 { .. } | SixAxisError::OutOfRange { .. }) => None,
        ChooseError::Ik(SixAxisError::OutOfReach {
            wrist_mm,
            front_mm,
            max_mm,
            by_mm,
            ..
        }) => Some((*wrist_mm, *front_mm > *max_mm, *by_mm)),
        _ => return None,
    };
    let p = cell.points.iter().find(|p| p.name == point)?;
    let Target::Robtarget { pose, conf } = &p.target else {
        return None;
    };
    let tcp = Tcp::of(cell, robot).ok()?;
    let q = pose.isometry().rotation;
    for turn in turns() {
        let turned = q * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), turn.to_radians());
        let (shown, read) = as_written(&turned);
        let changed = Frame {
            pos_mm: pose.pos_mm,
            quat_wxyz: read,
        };
        if let Ok(s) = tcp.choose(&changed, p.wobj, None, placement, None, check) {
            return Some(format!(
                "turned {turn} deg about its own z axis, the tool reaches point '{point}': orientation {} (the smallest such turn in {TURN_STEP_DEG} deg steps; by the inverse kinematics axes {}, in range and free of collision; without confdata); a torch or a round gripper is often free to turn so",
                fmt_quat(&shown),
                fmt_axes(&s)
            ));
        }
    }
    let (wrist_mm, towards, by_mm) = reach?;
    // The horizontal direction from the base to the wrist centre, in the cell frame.
    let w = placement.to_cell_frame(wrist_mm);
    let d = [w[0] - placement.base_mm[0], w[1] - placement.base_mm[1]];
    let len = d[0].hypot(d[1]);
    if len < 1.0 {
        return None;
    }
    let sign = if towards { 1.0 } else { -1.0 };
    let first = (by_mm / BASE_STEP_MM).ceil() * BASE_STEP_MM;
    let mut step = first;
    while step <= first + BASE_MOVE_MAX_MM {
        let k = sign * step / len;
        let moved = Placement {
            base_mm: [
                round1(placement.base_mm[0] + k * d[0]),
                round1(placement.base_mm[1] + k * d[1]),
                placement.base_mm[2],
            ],
            yaw_deg: placement.yaw_deg,
        };
        if let Ok(s) = tcp.choose(pose, p.wobj, *conf, moved, None, &check_at(moved)) {
            let [x, y, z] = moved.base_mm;
            return Some(format!(
                "no turn of the tool about its z axis ({TURN_STEP_DEG} deg steps) makes point '{point}' reachable; moving the robot's base {step} mm {} it, to robot.base [{x:.1}, {y:.1}, {z:.1}], does (by the inverse kinematics axes {}, in range and free of collision; the other points are not checked from there)",
                if towards { "towards" } else { "away from" },
                fmt_axes(&s)
            ));
        }
        step += BASE_STEP_MM;
    }
    None
}

/// To the 0.1 mm a cell's base is given in.
fn round1(v: f64) -> f64 {
    (v * 10.0).round() / 10.0 + 0.0
}

fn fmt_axes(a: &[f64; 6]) -> String {
    let v: Vec<String> = a.iter().map(|x| format!("{x:.1}")).collect();
    format!("[{}]", v.join(", "))
}

#[cfg(test)]
mod tests {
    //! Each hint is checked by the place stage itself: the cell changed as the hint says places.
    use super::*;
    use crate::robot::Robot;
    use std::path::Path;

    /// Accepts every pose (no obstacles).
    struct Open;
    impl PoseCheck for Open {
        fn why_blocked(&self, _: &[f64; 6]) -> Option<String> {
            None
        }
    }

    /// A torch tilted 45 deg against the flange, 350 mm out, on a robot at the origin.
    fn cell(w1: &str) -> Cell {
        let text = format!(
            "module: M\nrobot:\n  urdf: r.urdf\n  base: [0, 0, 0]\ntool:\n  name: tTorch\n  tframe: [[0, 0, 350], [0.9238795, 0, 0.3826834, 0]]\npoints:\n  - {{ name: P1, joints: [0, 0, 0] }}\n  - {{ name: W1, robtarget: {w1} }}\n"
        );
        crate::cell::parse(Path::new("x.yaml"), &text).unwrap_or_else(|e| panic!("{e}\n{text}"))
    }

    fn placed(cell: &Cell) -> Result<super::super::Placed, PlaceError> {
        super::super::place(cell, &Robot::irb1400(), |_| Open)
    }

    /// The text between `from` and the next `to` in `s`.
    fn between<'a>(s: &'a str, from: &str, to: &str) -> &'a str {
        let a = s.find(from).unwrap_or_else(|| panic!("no {from} in {s}")) + from.len();
        &s[a..a + s[a..].find(to).unwrap_or_else(|| panic!("no {to} in {s}"))]
    }

    /// The torch at the pose of axes [0, -20, 0, 0, 50, 0], turned half a turn about its z: axis
    /// 5 would need 147.3 deg. The hint's turn (75 deg) places, every smaller turn tried (15, -15,
    /// .., 60, -60) does not.
    #[test]
    fn an_axis_5_failure_suggests_the_smallest_turn_that_places() {
        let pos = "[944.401, 0, 825.586]";
        let c = cell(&format!("[{pos}, [0, 0.9990482, 0, -0.0436194]]"));
        let Err(e @ PlaceError::Robtarget { .. }) = placed(&c) else {
            panic!("W1 places")
        };
        let PlaceError::Robtarget { source, hint, .. } = &e else {
            unreachable!()
        };
        assert!(
            matches!(**source, ChooseError::Ik(SixAxisError::Axis5 { .. })),
            "{source}"
        );
        let hint = hint.as_deref().expect("a hint");
        assert!(
            hint.starts_with("turned 75 deg about its own z axis"),
            "{hint}"
        );
        let q = between(hint, "orientation ", " (the");
        let turned = placed(&cell(&format!("[{pos}, {q}]"))).expect("the hinted turn places");
        assert!(turned.points[1].joints_deg[4].abs() <= 115.0);
        let given =
            UnitQuaternion::from_quaternion(Quaternion::new(0.0, 0.9990482, 0.0, -0.0436194));
        for turn in [15.0, -15.0, 30.0, -30.0, 45.0, -45.0, 60.0, -60.0] {
            let r =
                given * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), f64::to_radians(turn));
            let q = format!("[{}, {}, {}, {}]", r.w, r.i, r.j, r.k);
            assert!(
                placed(&cell(&format!("[{pos}, {q}]"))).is_err(),
                "{turn} deg places"
            );
        }
    }

    /// 1280 mm out of reach: no turn helps; the base moved as the hint says reaches it (with
    /// the confdata asked for).
    #[test]
    fn an_out_of_reach_failure_suggests_the_base_move_that_places() {
        let w1 = "[[2200, 300, 150], [0, 0, 1, 0], [0, -1, 0, 0]]";
        let e = placed(&cell(w1)).expect_err("out of reach");
        let PlaceError::Robtarget { source, hint, .. } = &e else {
            panic!("{e}")
        };
        assert!(
            matches!(**source, ChooseError::Ik(SixAxisError::OutOfReach { .. })),
            "{source}"
        );
        let hint = hint.as_deref().expect("a hint");
        assert!(hint.starts_with("no turn of the tool"), "{hint}");
        let base = between(hint, "to robot.base ", ", does");
        let with_base = |base: &str| {
            let text = format!(
                "module: M\nrobot:\n  urdf: r.urdf\n  base: {base}\ntool:\n  name: tTorch\n  tframe: [[0, 0, 350], [0.9238795, 0, 0.3826834, 0]]\npoints:\n  - {{ name: P1, joints: [0, 0, 0] }}\n  - {{ name: W1, robtarget: {w1} }}\n"
            );
            crate::cell::parse(Path::new("x.yaml"), &text).expect("cell")
        };
        let moved = placed(&with_base(base)).unwrap_or_else(|e| panic!("from {base}: {e}"));
        // From the origin: 10 mm less of the same move (the step) does not reach it.
        let [x, y, z] = moved.placement.base_mm;
        let n = x.hypot(y);
        let shorter = format!("[{:.1}, {:.1}, {z}]", x - 10.0 * x / n, y - 10.0 * y / n);
        assert!(
            placed(&with_base(&shorter)).is_err(),
            "{shorter} reaches it"
        );
    }

    /// Other failures get no hint: the generic help stays.
    #[test]
    fn a_confdata_failure_gets_no_hint() {
        let e = placed(&cell("[[1000, 0, 800], [0, 0, 1, 0], [2, 0, 0, 0]]")).expect_err("cf1 2");
        let PlaceError::Robtarget { hint, .. } = &e else {
            panic!("{e}")
        };
        assert_eq!(*hint, None, "{e}");
    }
}
