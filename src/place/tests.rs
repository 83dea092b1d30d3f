//! Tests of the place stage's robtarget points (the frames chain, rounding, confdata, reasons),
//! the range rule for the cell's own values, and the motion of each point. The robot is the
//! bundled IRB 1400; forward kinematics (`Robot::tool0`, the URDF chain) is the reference.

use super::*;
use crate::geometry::testing::Rng;
use crate::robot::ik::six::SixAxisIk;
use crate::robot::Axes6;
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};
use std::path::Path;

/// Accepts every pose (no obstacles).
struct Open;
impl PoseCheck for Open {
    fn why_blocked(&self, _: &[f64; 6]) -> Option<String> {
        None
    }
}

/// Refuses every pose with axis 1 above `limit`.
struct Fence(f64);
impl PoseCheck for Fence {
    fn why_blocked(&self, j: &[f64; 6]) -> Option<String> {
        (j[0] > self.0).then(|| {
            format!(
                "link 'link_3' of the robot hits obstacle 'fence' (axis 1 = {:.1})",
                j[0]
            )
        })
    }
}

const TORCH: &str =
    "tool:\n  name: tTorch\n  tframe: [[0, 0, 350], [0.9238795, 0, 0.3826834, 0]]\n";
const WOBJ: &str =
    "wobj:\n  name: wobjTrunk\n  uframe: [[400, -200, 100], [0.9659258, 0, 0, 0.2588190]]\n";
const PLACEMENT: Placement = Placement {
    base_mm: [100.0, -850.0, 50.0],
    yaw_deg: 90.0,
};

fn cell(extra: &str, points: &str) -> Cell {
    let text = format!(
        "module: M\nrobot:\n  urdf: r.urdf\n  base: [100, -850, 50]\n  yaw: 90\n{extra}points:\n{points}"
    );
    crate::cell::parse(Path::new("x.yaml"), &text).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn frame(f: &Isometry3<f64>) -> Frame {
    let q = f.rotation.quaternion();
    Frame {
        pos_mm: f.translation.vector.into(),
        quat_wxyz: [q.w, q.i, q.j, q.k],
    }
}

fn iso(f: &Frame) -> Isometry3<f64> {
    let [w, x, y, z] = f.quat_wxyz;
    Isometry3::from_parts(
        Translation3::new(f.pos_mm[0], f.pos_mm[1], f.pos_mm[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z)),
    )
}

/// A robtarget point line for a pose (positions to 3 decimals, as a cell gives them).
fn robtarget_line(name: &str, pose: &Frame, conf: Option<[i32; 4]>) -> String {
    let p = pose.pos_mm.map(|v| crate::precision::round(v, 3));
    let q = pose.quat_wxyz;
    let conf = conf
        .map(|c| format!(", [{}, {}, {}, {}]", c[0], c[1], c[2], c[3]))
        .unwrap_or_default();
    format!(
        "  - {{ name: {name}, robtarget: [[{}, {}, {}], [{}, {}, {}, {}]{conf}] }}\n",
        p[0], p[1], p[2], q[0], q[1], q[2], q[3]
    )
}

/// The TCP pose of `axes` in the work object of `c`, as a robtarget would give it.
fn pose_of(c: &Cell, robot: &Robot, axes: &Axes6) -> Frame {
    let tframe = c.tool.as_ref().map_or(Frame::IDENTITY, |t| t.tframe);
    let uframe = c.wobjs.first().map_or(Frame::IDENTITY, |w| w.uframe);
    frame(
        &(iso(&uframe).inverse() * PLACEMENT.cell_from_robot() * robot.tool0(axes) * iso(&tframe)),
    )
}

fn random_in_range(rng: &mut Rng, robot: &Robot) -> Axes6 {
    loop {
        let a: Axes6 = std::array::from_fn(|i| {
            let s = &robot.controller.axes[i];
            rng.range(s.min_deg, s.max_deg)
        });
        // Away from the wrist singularity (axis 5 = 0), where the pose fixes axes 4 and 6 only
        // as a sum.
        if robot.check_range6(&a).is_ok() && a[4].abs() > 2.0 {
            return a;
        }
    }
}

#[test]
fn robtargets_are_reached_within_0_1_mm_and_0_01_deg_through_tool_wobj_and_placement() {
    let robot = Robot::irb1400();
    let ik = SixAxisIk::from_robot(&robot).expect("IRB 1400");
    let blocks = format!("{TORCH}{WOBJ}");
    let frame_cell = cell(
        &blocks,
        "  - { name: a, joints: [0, 0, 0] }\n  - { name: b, joints: [0, 0, 0] }\n",
    );
    let mut rng = Rng(2024);
    let (mut worst_mm, mut worst_deg, mut worst_axis) = (0.0f64, 0.0f64, 0.0f64);
    let n = 1500;
    for k in 0..n {
        let a = random_in_range(&mut rng, &robot);
        let pose = pose_of(&frame_cell, &robot, &a);
        // Every other point asks for the pose's own confdata; the others have the original
        // joint values as the previous point, so the nearest solution is the original one.
        let conf = (k % 2 == 0).then(|| ik.conf(&a).to_array());
        let points = format!(
            "  - {{ name: start, joints: [{:.3}, {:.3}, {:.3}, {:.3}, {:.3}, {:.3}] }}\n{}",
            a[0],
            a[1],
            a[2],
            a[3],
            a[4],
            a[5],
            robtarget_line("P", &pose, conf)
        );
        let c = cell(&blocks, &points);
        let placed = match place(&c, &robot, |_| Open) {
            Ok(p) => p,
            // The start point rounded to 0.001 deg may leave the coupled range by a hair.
            Err(PlaceError::Range { .. }) => continue,
            Err(e) => panic!("{a:?}: {e}"),
        };
        let q = placed.points[1].joints_deg;
        let Origin::Robtarget {
            pose: given,
            conf: written,
        } = &placed.points[1].origin
        else {
            panic!("origin")
        };
        // The joints: in range, the exact inverse of the robtarget as written (to the
        // written quaternion's 1e-9), not rounded to 0.001 deg.
        assert!(robot.check_range6(&q).is_ok(), "{q:?}");
        let target = iso(&c.wobjs.first().expect("wobj").uframe) * iso(given);
        let reached = PLACEMENT.cell_from_robot()
            * robot.tool0(&q)
            * iso(&c.tool.as_ref().expect("tool").tframe);
        let (mm, deg) = pose_error(&reached, &target);
        assert!(
            mm <= 1e-5 && deg <= 1e-6 && mm <= POSITION_TOL_MM && deg <= ANGLE_TOL_DEG,
            "{a:?} -> {q:?}: {mm} mm {deg} deg"
        );
        worst_mm = worst_mm.max(mm);
        worst_deg = worst_deg.max(deg);
        // Its confdata: the one asked for, else the one of the written values; and the original
        // solution is the one chosen (nearest the previous point, or of that confdata).
        assert_eq!(*written, ik.conf(&q));
        if let Some(c) = conf {
            assert_eq!(written.to_array(), c);
        }
        let d = (0..6).map(|i| (q[i] - a[i]).abs()).fold(0.0, f64::max);
        worst_axis = worst_axis.max(d);
        assert!(d < 0.05, "{a:?} -> {q:?}");
    }
    eprintln!(
        "{n} random robtargets through a bent torch, a turned work object and a turned base: \
         TCP within {worst_mm:.5} mm and {worst_deg:.6} deg of the robtarget, \
         the original axes within {worst_axis:.4} deg"
    );
}

#[test]
fn failures_name_the_point_and_why() {
    let robot = Robot::irb1400();
    let start = "  - { name: home, joints: [90, 0, 0, 0, 30, 0] }\n";
    let fail = |points: &str, check: &dyn Fn() -> Fence| {
        let c = cell(TORCH, &format!("{start}{points}"));
        match place(&c, &robot, |_| check()) {
            Err(e) => {
                assert!(!e.is_input(), "{e}");
                assert_eq!(e.loc().line, 11, "{e}");
                e.to_string()
            }
            Ok(p) => panic!("placed {:?}", p.points[1]),
        }
    };
    let open = || Fence(f64::INFINITY);
    // 3 m away from the base.
    let msg = fail(
        "  - { name: far, robtarget: [[100, 2500, 500], [0, 0, 1, 0]] }\n",
        &open,
    );
    assert!(
        msg.starts_with(
            "point 'far' (robot base at [100.0, -850.0, 50.0] mm, yaw 90 deg): out of reach by"
        ),
        "{msg}"
    );
    // In reach, but the torch pointing back at the robot: axis 5 would have to fold beyond 115.
    let msg = fail(
        "  - { name: back, robtarget: [[100, -100, 900], [0.7071068, 0.7071068, 0, 0]] }\n",
        &open,
    );
    assert!(
        msg.contains("point 'back'")
            && (msg.contains("axis 5") || msg.contains("no solution lies within")),
        "{msg}"
    );
    // A confdata that the pose has no solution for: the reachable ones are listed.
    let msg = fail(
        "  - { name: W, robtarget: [[100, 200, 300], [0, 0, 1, 0], [0, 0, 0, 6]] }\n",
        &open,
    );
    assert!(
        msg.contains("confdata [0, 0, 0, 6] is not reachable") && msg.contains("reachable: ["),
        "{msg}"
    );
    // Every solution refused by the collision check: each reason kept.
    let msg = fail(
        "  - { name: W, robtarget: [[100, 200, 300], [0, 0, 1, 0]] }\n",
        &|| Fence(-180.0),
    );
    assert!(msg.contains("every solution is refused: confdata"), "{msg}");
    assert!(msg.contains("hits obstacle 'fence'"), "{msg}");
}

#[test]
fn cell_values_out_of_range_are_input_errors_at_their_line() {
    let robot = Robot::irb1400();
    let refuse = |extra: &str, points: &str, line: u64, needle: &str| {
        let c = cell(extra, points);
        let e = place(&c, &robot, |_| Open).expect_err(needle);
        assert!(e.is_input(), "{e}");
        assert_eq!(e.loc().line, line, "{e}");
        assert!(e.to_string().contains(needle), "'{e}' lacks '{needle}'");
    };
    let ok = "  - { name: A, joints: [0, 0, 0] }\n";
    refuse("", &format!("{ok}  - {{ name: B, joints: [0, 0, 0, 0, 160, 0] }}\n"), 8,
        "point 'B' is out of range: axis 5 = 160 deg is outside its range -115 .. 115 deg (ranges from irb1400.controller.yaml)");
    refuse(
        "",
        &format!("{ok}  - {{ name: B, joints: [0, 0, 0, 151, 0, 0] }}\n"),
        8,
        "axis 4 = 151 deg",
    );
    refuse(
        "",
        &format!("{ok}  - {{ name: B, joints: [0, 0, 0, 0, 0, -300.5] }}\n"),
        8,
        "axis 6 = -300.5 deg",
    );
    refuse(
        "",
        &format!("{ok}  - {{ name: B, joints: [0, -70, 70] }}\n"),
        8,
        "axis 3 - axis 2 = 140 deg is outside the coupled range",
    );
    // robot.wrist, given: at its line, whether or not a point uses it.
    let c = crate::cell::parse(
        Path::new("x.yaml"),
        "module: M\nrobot:\n  urdf: r.urdf\n  base: [0, 0, 0]\n  wrist: [0, 200, 400]\npoints:\n  - { name: A, joints: [0, 0, 0, 0, 0, 0] }\n  - { name: B, joints: [1, 0, 0, 0, 0, 0] }\n",
    )
    .expect("cell");
    let e = place(&c, &robot, |_| Open).expect_err("wrist");
    assert!(e.is_input() && e.loc().line == 5, "{e}");
    assert!(
        e.to_string()
            .contains("robot.wrist is out of range: axis 5 = 200 deg"),
        "{e}"
    );
    // At the limits: in range.
    let c = cell("", "  - { name: A, joints: [170, 70, 70, 150, 115, 300] }\n  - { name: B, joints: [-170, -65, -65, -150, -115, -300] }\n");
    assert!(place(&c, &robot, |_| Open).is_ok());
}

#[test]
fn each_point_carries_the_motion_of_the_move_into_it() {
    let robot = Robot::irb1400();
    let text = "module: M\nrobot: { urdf: r.urdf, base: [0, 0, 0] }\npoints:\n  - { name: A, joints: [0, 0, 0] }\n  - { name: B, joints: [10, 0, 0], speed: v100 }\n  - { name: C, joints: [20, 0, 0], zone: z10 }\nmotion: { speed: v500, zone: z1 }\n";
    let c = crate::cell::parse(Path::new("x.yaml"), text).expect("cell");
    let placed = place(&c, &robot, |_| Open).expect("placed");
    let m: Vec<(&str, &str)> = placed
        .points
        .iter()
        .map(|p| (p.motion.speed.as_str(), p.motion.zone.as_str()))
        .collect();
    assert_eq!(m, [("v500", "z1"), ("v100", "z1"), ("v500", "z10")]);
}

#[test]
fn base_auto_takes_a_robtargets_wrist_centre_from_its_pose_and_tool() {
    let robot = Robot::irb1400();
    let a = [20.0, 10.0, 15.0, 30.0, 50.0, -40.0];
    let probe = cell(
        TORCH,
        "  - { name: a, joints: [0, 0, 0] }\n  - { name: b, joints: [0, 0, 0] }\n",
    );
    let pose = pose_of(&probe, &robot, &a);
    let c = cell(
        TORCH,
        &format!(
            "{}{}",
            robtarget_line("P", &pose, None),
            robtarget_line("Q", &pose, None)
        ),
    );
    let tcp = Tcp::of(&c, &robot).expect("six-axis arm");
    let w = tcp.wrist_centre(&pose, c.points[0].wobj);
    let expected = PLACEMENT.cell_from_robot() * robot.wrist_centre(&a);
    let off = (nalgebra::Point3::from(w) - expected).norm();
    assert!(off < 0.01, "{w:?} vs {expected:?}");
}

/// `cells/gripper-pick.yaml` with the confdata its own module writes for the points above and
/// at the fixture (`[1, 0, 2, 0]`: axis 1 at 90, axis 4 at 0, axis 6 at 180, each solved a
/// hair off the boundary) asked for: the same joints are chosen, and the confdata written is
/// the one asked. Fails with the choice by exact confdata ("[1, 0, 2, 0] is not reachable").
#[test]
fn the_gripper_cell_s_own_confdata_on_quadrant_boundaries_is_reachable() {
    let text = include_str!("../../cells/gripper-pick.yaml");
    let robot = Robot::irb1400();
    let parse = |text: &str| {
        crate::cell::parse(Path::new("cells/gripper-pick.yaml"), text)
            .unwrap_or_else(|e| panic!("{e}"))
    };
    let plain = place(&parse(text), &robot, |_| Open).expect("the cell places");
    // The place point (its approach and retract poses are RelTool of it, in its confdata).
    let from = "robtarget: [[900, 700, -20], [0, 1, 0, 0]]";
    assert!(text.contains(from), "the place point's line");
    let asked = text.replace(
        from,
        "robtarget: [[900, 700, -20], [0, 1, 0, 0], [1, 0, 2, 0]]",
    );
    assert_eq!(asked.matches("[1, 0, 2, 0]").count(), 1, "{asked}");
    let with = place(&parse(&asked), &robot, |_| Open).unwrap_or_else(|e| panic!("{e}"));
    for (a, b) in plain.points.iter().zip(&with.points) {
        assert_eq!(a.joints_deg, b.joints_deg, "{}", a.name);
        if a.name == "place" {
            let Origin::Robtarget { conf, .. } = &b.origin else {
                panic!("{} is a robtarget", b.name)
            };
            assert_eq!(conf.to_array(), [1, 0, 2, 0], "{}", b.name);
            // On the quadrant boundaries, to the solver's rounding.
            for (k, v) in [(0, 90.0), (3, 0.0), (5, 180.0)] {
                assert!((b.joints_deg[k] - v).abs() < 1e-9, "{}", b.name);
            }
        }
    }
}
