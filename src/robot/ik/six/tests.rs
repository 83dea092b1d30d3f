//! Tests of the six-axis IK. The oracle is the robot's own forward kinematics
//! (`Robot::tool0`, the URDF chain of `crate::robot`), never this module's formulas.

use super::solve::wrap_deg;
use super::*;
use crate::geometry::testing::Rng;
use crate::robot::{urdf, RangeViolation};
use nalgebra::{Translation3, UnitQuaternion};
use std::path::Path;

const IRB_URDF: &str = include_str!("../../../../robots/irb1400.urdf");
const IRB_CONTROLLER: &str = include_str!("../../../../robots/irb1400.controller.yaml");

fn irb() -> (Robot, SixAxisIk) {
    let robot = Robot::irb1400();
    let ik = SixAxisIk::from_robot(&robot).expect("the IRB 1400 is a spherical-wrist arm");
    (robot, ik)
}

/// A robot from URDF text: with the IRB 1400 controller file (parallelogram) or without (serial,
/// the URDF's own limits).
fn robot_from(text: &str, parallelogram: bool) -> Robot {
    let controller = parallelogram.then_some((Path::new("c.yaml"), IRB_CONTROLLER));
    urdf::robot_from_urdf(Path::new("x.urdf"), text, controller).expect("loads")
}

/// `text` with `from` (which must occur) replaced by `to`.
fn replaced(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from}");
    text.replace(from, to)
}

fn pose_error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    (
        (a.translation.vector - b.translation.vector).norm(),
        a.rotation.angle_to(&b.rotation),
    )
}

fn max_diff(a: &Axes6, b: &Axes6) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn random_in_range(rng: &mut Rng, robot: &Robot) -> Axes6 {
    loop {
        let a: Axes6 = std::array::from_fn(|i| {
            let s = &robot.controller.axes[i];
            rng.range(s.min_deg, s.max_deg)
        });
        if robot.check_range6(&a).is_ok() {
            return a;
        }
    }
}

fn torch() -> Isometry3<f64> {
    // A bent torch: 350 mm out, tilted 45 deg about y.
    Isometry3::from_parts(
        Translation3::new(0.0, 0.0, 350.0),
        UnitQuaternion::new_normalize(nalgebra::Quaternion::new(0.9238795, 0.0, 0.3826834, 0.0)),
    )
}

/// Worst errors of a round trip, for the report.
#[derive(Default)]
struct Worst {
    poses: usize,
    solutions: usize,
    mm: f64,
    rad: f64,
    original_deg: f64,
}

/// FK -> IK -> FK on random in-range poses: every solution reproduces the pose, lies in range,
/// has its own confdata, and the pose's own joint values are among them.
fn round_trip(
    robot: &Robot,
    ik: &SixAxisIk,
    n: usize,
    seed: u64,
    tframe: &Isometry3<f64>,
) -> Worst {
    let mut rng = Rng(seed);
    let mut w = Worst::default();
    for _ in 0..n {
        let a = random_in_range(&mut rng, robot);
        let tcp = robot.tool0(&a) * tframe;
        let sols = ik
            .solve_tcp(&tcp, tframe, None)
            .unwrap_or_else(|e| panic!("{a:?}: {e}"));
        for (i, s) in sols.iter().enumerate() {
            let (mm, rad) = pose_error(&(robot.tool0(&s.axes_deg) * tframe), &tcp);
            assert!(
                mm <= 1e-6 && rad <= 1e-9,
                "{a:?} -> {s:?}: {mm} mm, {rad} rad"
            );
            assert!(robot.check_range6(&s.axes_deg).is_ok(), "{s:?}");
            assert_eq!(s.conf, ik.conf(&s.axes_deg));
            assert!(sols[i + 1..].iter().all(|t| t.conf != s.conf), "{sols:?}");
            w.mm = w.mm.max(mm);
            w.rad = w.rad.max(rad);
        }
        let nearest = sols
            .iter()
            .map(|s| max_diff(&s.axes_deg, &a))
            .fold(f64::INFINITY, f64::min);
        assert!(nearest <= 1e-6, "{a:?} not among {sols:?}");
        w.original_deg = w.original_deg.max(nearest);
        w.poses += 1;
        w.solutions += sols.len();
    }
    w
}

#[test]
fn derives_the_irb1400_geometry_from_the_urdf() {
    let (_, ik) = irb();
    let (lu, lf) = ik.link_lengths_mm();
    assert!((lu - 600.0).abs() < 1e-9 && (lf - 120.0f64.hypot(720.0)).abs() < 1e-9);
    assert!((ik.wrist_centre_zero().coords - Vector3::new(870.0, 0.0, 1195.0)).norm() < 1e-9);
    let (lo, hi) = ik.reach_mm();
    assert!(
        (lo - 129.93).abs() < 0.01 && (hi - 1329.93).abs() < 0.01,
        "{lo} {hi}"
    );
    assert_eq!(ik.shoulder_offset_mm, 0.0);
    // The parallelogram's inverse: axis 3 = q3 + q2.
    let q = ik.coupling.controller_deg(&[0.0, 0.2, 0.3, 0.0, 0.0, 0.0]);
    assert!((q[2] - 0.5f64.to_degrees()).abs() < 1e-12, "{q:?}");
}

#[test]
fn round_trip_on_10000_random_poses_of_the_irb1400() {
    let (robot, ik) = irb();
    let w = round_trip(&robot, &ik, 10_000, 0x1400_2026, &Isometry3::identity());
    eprintln!(
        "tool0 round trip: {} poses, {} solutions, worst {:.3e} mm, {:.3e} rad, original \
         within {:.3e} deg",
        w.poses, w.solutions, w.mm, w.rad, w.original_deg
    );
    // Axis 6 (+-300) gives most solutions a second turn.
    assert!(w.solutions > 2 * w.poses, "{}", w.solutions);
}

/// FK -> IK -> FK on 5000 random in-range poses of every shipped robot (tool0, and a bent
/// torch): every solution reproduces the pose, lies in range, has its own confdata, and the
/// pose's own joint values are among them; and the confdata of those joint values, asked for,
/// give them back (`choose` with that confdata), as a robtarget's confdata must. Fails with a
/// solver that drops a branch, a wrong confdata bit, or a coupling left out.
#[test]
fn round_trip_on_every_shipped_robot() {
    let mut total = (0, 0);
    for (k, m) in crate::robot::models::MODELS.iter().enumerate() {
        let robot = Robot::shipped(m.name).expect("shipped");
        let ik = SixAxisIk::from_robot(&robot).unwrap_or_else(|e| panic!("{}: {e}", m.name));
        for (tframe, n) in [(Isometry3::identity(), 5000), (torch(), 1000)] {
            let w = round_trip(&robot, &ik, n, 0x30 + k as u64, &tframe);
            eprintln!(
                "{}: round trip of {} poses, {} solutions, worst {:.3e} mm, {:.3e} rad, original \
                 within {:.3e} deg",
                m.name, w.poses, w.solutions, w.mm, w.rad, w.original_deg
            );
            total.0 += w.poses;
            total.1 += w.solutions;
        }
        let mut rng = Rng(0x3000 + k as u64);
        let mut asked = 0;
        for _ in 0..2000 {
            let a = random_in_range(&mut rng, &robot);
            let conf = ik.conf(&a);
            let chosen = ik
                .choose(&robot.tool0(&a), Some(conf), None, |_| Ok::<(), ()>(()))
                .unwrap_or_else(|e| panic!("{}: {a:?} with {conf:?}: {e:?}", m.name));
            assert!(
                max_diff(&chosen.axes_deg, &a) <= 1e-6,
                "{}: {conf:?} gave {:?} for {a:?}",
                m.name,
                chosen.axes_deg
            );
            asked += 1;
        }
        assert_eq!(asked, 2000);
    }
    eprintln!(
        "every shipped robot: {} poses, {} solutions",
        total.0, total.1
    );
}

#[test]
fn round_trip_with_a_bent_torch() {
    let (robot, ik) = irb();
    let w = round_trip(&robot, &ik, 1000, 77, &torch());
    eprintln!(
        "TCP round trip: {} poses, worst {:.3e} mm, {:.3e} rad",
        w.poses, w.mm, w.rad
    );
}

/// Without ranges (the serial URDF, all axes over the full circle): every one of the 8
/// branches is found, so the in-range filter works on a complete set.
#[test]
fn all_branches_over_the_full_circle() {
    let robot = robot_from(IRB_URDF, false);
    let ik = SixAxisIk::from_robot(&robot).expect("serial IRB 1400");
    let mut rng = Rng(9);
    let mut branches = 0;
    for _ in 0..2000 {
        let a: Axes6 = std::array::from_fn(|_| rng.range(-180.0, 180.0));
        let pose = robot.tool0(&a);
        let cands = ik
            .candidates(&pose, None)
            .expect("reachable by construction");
        for c in &cands {
            let (mm, rad) = pose_error(&robot.tool0(&c.axes_deg), &pose);
            assert!(
                mm <= 1e-6 && rad <= 1e-9,
                "{a:?} -> {c:?}: {mm} mm {rad} rad"
            );
        }
        let found = cands.iter().any(|c| {
            c.axes_deg
                .iter()
                .zip(&a)
                .all(|(x, y)| wrap_deg(x - y).abs() <= 1e-6)
        });
        assert!(found, "{a:?} not among {cands:?}");
        // Four branches (elbow x wrist) for each stance whose shoulder, 150 mm towards or away
        // from the wrist centre at 475 mm height, is within the arm's reach of it.
        let w = robot.wrist_centre(&a);
        let r = w.x.hypot(w.y);
        let l = 120.0f64.hypot(720.0);
        let expected: usize = [r - 150.0, r + 150.0]
            .iter()
            .filter(|d| (l - 600.0..=l + 600.0).contains(&d.hypot(w.z - 475.0)))
            .count()
            * 4;
        assert_eq!(cands.len(), expected, "{a:?}: {cands:?}");
        branches += cands.len();
    }
    assert!(branches > 7 * 2000, "{branches}: mostly 8 per pose");
}

/// Joint values read in ABB RobotStudio with the tool0 position it reported (IRB 1410, same
/// arm geometry as the IRB 1400). Public source: the repository OmarMalla/ABB-IRB1410 that
/// accompanies O. Malla and M. Shanmugavel, Industrial Robot 51(5), 2024. The confdata are
/// worked out by hand from the joint values (quadrants of axes 1, 4, 6; every wrist centre is
/// in front of axis 1 and of the lower arm; axis 5 negative only in the last row).
const ROBOTSTUDIO: [(Axes6, [f64; 3], [i32; 4]); 4] = [
    (
        [30.80, -12.13, 15.33, -40.0, 59.80, -28.0],
        [691.03, 356.96, 921.35],
        [0, -1, -1, 0],
    ),
    (
        [9.07, 39.20, 46.50, -8.0, 62.87, 44.0],
        [1072.34, 160.46, 420.62],
        [0, -1, 0, 0],
    ),
    (
        [-95.20, 28.93, 6.17, -20.0, 21.47, 40.0],
        [-123.39, -1238.42, 1004.51],
        [-2, -1, 0, 0],
    ),
    (
        [31.73, -8.40, 61.17, 12.0, -36.80, 24.0],
        [508.35, 301.93, 460.09],
        [0, 0, 0, 1],
    ),
];

#[test]
fn robotstudio_rows() {
    let (robot, ik) = irb();
    for (axes, position, conf) in ROBOTSTUDIO {
        let ours = robot.tool0(&axes);
        let off = (ours.translation.vector - Vector3::from(position)).norm();
        assert!(off < 0.2, "{axes:?}: {off} mm from RobotStudio");
        assert_eq!(ik.conf(&axes).to_array(), conf, "{axes:?}");
        // RobotStudio's position with our orientation: the row's joints come back.
        let pose =
            Isometry3::from_parts(Translation3::from(Vector3::from(position)), ours.rotation);
        let sols = ik.solve(&pose, None).expect("in range");
        let best = sols
            .iter()
            .min_by(|a, b| max_diff(&a.axes_deg, &axes).total_cmp(&max_diff(&b.axes_deg, &axes)))
            .expect("some");
        assert!(max_diff(&best.axes_deg, &axes) < 0.01, "{axes:?}: {best:?}");
        eprintln!(
            "RobotStudio row {axes:?}: tool0 {off:.3} mm off; IK of its position within {:.4} deg",
            max_diff(&best.axes_deg, &axes)
        );
        assert_eq!(best.conf.to_array(), conf);
        // And asked by its confdata, that is the one chosen.
        let chosen = ik
            .choose(&pose, Some(ConfData::from_array(conf)), None, |_| {
                Ok::<(), ()>(())
            })
            .expect("reachable");
        assert_eq!(chosen, *best);
    }
}

#[test]
fn confdata_of_hand_checked_poses() {
    let (_, ik) = irb();
    let c = |a: Axes6| ik.conf(&a).to_array();
    assert_eq!(c([0.0; 6]), [0, 0, 0, 0]);
    // Quadrants: floor(axis / 90).
    assert_eq!(c([90.0, 0.0, 0.0, -0.5, 30.0, -300.0]), [1, -1, -4, 0]);
    assert_eq!(c([-90.0, 0.0, 0.0, 179.9, 30.0, 299.0]), [-1, 1, 3, 0]);
    assert_eq!(c([-170.0, 0.0, 0.0, -150.0, -30.0, -1.0]), [-2, -2, -1, 1]);
    // Leaning far back with the forearm down: r = 150 + 600 sin(-70) + 720 cos(-65)
    // + 120 sin(-65) = -218.2 mm, the wrist centre behind axis 1 (and behind axis 2).
    assert_eq!(c([0.0, -70.0, -65.0, 0.0, 30.0, 0.0])[3], 4);
    assert_eq!(c([0.0, -70.0, -65.0, 0.0, -30.0, 0.0])[3], 5);
    // r = 150 + 600 sin(-60) + 720 cos(-40) + 120 sin(-40) = 104.9 mm: in front of axis 1 but
    // 45.1 mm behind axis 2; the two readings differ here and only here.
    let a = [0.0, -60.0, -40.0, 0.0, 30.0, 0.0];
    assert_eq!(ik.conf_with(&a, BehindAxis1From::Axis1).cfx, 0);
    assert_eq!(ik.conf_with(&a, BehindAxis1From::Axis2).cfx, 4);
    assert_eq!(CFX_BEHIND_AXIS_1_FROM, BehindAxis1From::Axis1);
    // Axis 3 at -90 deg: the forearm's wrist centre 120 mm behind the vertical lower arm
    // (the elbow bent backwards); at -80 deg still 1.3 mm in front of it.
    assert_eq!(c([0.0, 0.0, -90.0, 0.0, 30.0, 0.0])[3], 2);
    assert_eq!(c([0.0, 0.0, -80.0, 0.0, 30.0, 0.0])[3], 0);
    // Turned by axis 1, the same arm keeps its cfx.
    assert_eq!(c([135.0, 0.0, -90.0, 0.0, -30.0, 0.0]), [1, 0, 0, 3]);
    assert_eq!(
        ConfData::from_array([1, -2, 3, 5]).to_string(),
        "[1, -2, 3, 5]"
    );
}

#[test]
fn out_of_reach_says_by_how_much() {
    let (_, ik) = irb();
    // tool0 at the zero pose's orientation (its z along +x), 2000 mm ahead at shoulder height:
    // wrist centre (1915, 0, 475); 1765 mm from axis 2 (2065 turned round); reach 129.9 .. 1329.9.
    let r = ik.tool0(&[0.0; 6]).rotation;
    let pose = Isometry3::from_parts(Translation3::new(2000.0, 0.0, 475.0), r);
    let err = ik.solve(&pose, None).unwrap_err();
    let SixAxisError::OutOfReach {
        front_mm,
        back_mm,
        by_mm,
        max_mm,
        ..
    } = err
    else {
        panic!("{err}")
    };
    assert!((front_mm - 1765.0).abs() < 1e-9 && (back_mm - 2065.0).abs() < 1e-9);
    let l = 120.0f64.hypot(720.0);
    assert!((max_mm - (600.0 + l)).abs() < 1e-9 && (by_mm - (1765.0 - 600.0 - l)).abs() < 1e-9);
    let text = err.to_string();
    assert!(text.contains("out of reach by 435.1 mm"), "{text}");
    assert!(
        text.contains("(1915.0, 0.0, 475.0) mm (robot frame)"),
        "{text}"
    );
    let nan = Isometry3::from_parts(Translation3::new(f64::NAN, 0.0, 0.0), r);
    assert_eq!(ik.solve(&nan, None), Err(SixAxisError::NotFinite));
}

#[test]
fn orientation_beyond_axis_5() {
    let (_, ik) = irb();
    // The arm at its zero pose, the tool bent back 150 deg: the only arm stance in range needs
    // axis 5 = +-150 (the range is +-115); the other stances need axis 1 = 180 or break the
    // coupled axis-3 range.
    let pose = ik.tool0(&[0.0, 0.0, 0.0, 0.0, 150.0, 0.0]);
    let err = ik.solve(&pose, None).unwrap_err();
    let SixAxisError::Axis5 {
        needed_deg, by_deg, ..
    } = err
    else {
        panic!("{err}")
    };
    assert!((needed_deg.abs() - 150.0).abs() < 1e-9 && (by_deg - 35.0).abs() < 1e-9);
    assert!(
        err.to_string()
            .contains("35.0 deg beyond its range -115 .. 115"),
        "{err}"
    );
}

#[test]
fn out_of_range_lists_every_branch() {
    let (_, ik) = irb();
    // The wrist centre straight behind the robot (axis 1 would need 180 deg).
    let pose = ik.tool0(&[180.0, 0.0, 0.0, 0.0, 30.0, 0.0]);
    let err = ik.solve(&pose, None).unwrap_err();
    let SixAxisError::OutOfRange { candidates, .. } = &err else {
        panic!("{err}")
    };
    assert_eq!(candidates.len(), 8);
    assert!(candidates.iter().all(|c| !c.violations.is_empty()));
    let text = err.to_string();
    assert!(
        text.contains("axis 1 = 180.0 deg is 10.0 deg outside -170 .. 170 deg"),
        "{text}"
    );
    assert!(text.contains("coupled range"), "{text}");
}

#[test]
fn unreachable_confdata_names_the_reachable_ones() {
    let (_, ik) = irb();
    // Only one solution in range: axes 4..6 = (0, 100, 0); its flip (180, -100, 180) breaks
    // axis 4 (+-150), and axis 6 = 0 has no second turn within +-300.
    let pose = ik.tool0(&[0.0, 0.0, 0.0, 0.0, 100.0, 0.0]);
    let sols = ik.solve(&pose, None).expect("in range");
    assert_eq!(sols.len(), 1);
    assert_eq!(sols[0].conf.to_array(), [0, 0, 0, 0]);
    let ok = |_: &Axes6| Ok::<(), String>(());
    for (wanted, axis4) in [([0, 2, 2, 1], 180.0), ([0, -2, -2, 1], -180.0)] {
        let err = ik
            .choose(&pose, Some(ConfData::from_array(wanted)), None, ok)
            .unwrap_err();
        let ChooseError::ConfUnreachable {
            reachable,
            wanted_solution: Some(c),
            ..
        } = &err
        else {
            panic!("{err}")
        };
        assert_eq!(reachable, &[ConfData::from_array([0, 0, 0, 0])]);
        assert!((c.axes_deg[3] - axis4).abs() < 1e-9 && c.conf.to_array() == wanted);
        let text = err.to_string();
        assert!(
            text.contains("is 30.0 deg outside -150 .. 150 deg")
                && text.contains("reachable: [0, 0, 0, 0]"),
            "{text}"
        );
    }
    let err = ik
        .choose(&pose, Some(ConfData::from_array([1, 0, 0, 0])), None, ok)
        .unwrap_err();
    assert!(
        matches!(
            err,
            ChooseError::ConfUnreachable {
                wanted_solution: None,
                ..
            }
        ),
        "{err}"
    );
    assert!(err
        .to_string()
        .contains("no solution of this pose has that configuration"));
}

#[test]
fn chooses_by_confdata_or_nearest_previous() {
    let (_, ik) = irb();
    let a = [10.0, 20.0, 30.0, 40.0, 50.0, 100.0];
    let pose = ik.tool0(&a);
    let sols = ik.solve(&pose, None).expect("in range");
    let other_turn = [10.0, 20.0, 30.0, 40.0, 50.0, -260.0];
    assert!(sols
        .iter()
        .any(|s| max_diff(&s.axes_deg, &other_turn) < 1e-9));
    let ok = |_: &Axes6| Ok::<(), String>(());
    // From the zero pose: the original (0.357 s for axis 6) beats its flip (0.5 s, axis 4).
    let c = ik.choose(&pose, None, None, ok).expect("ok");
    assert!(max_diff(&c.axes_deg, &a) < 1e-9, "{c:?}");
    // From axis 6 at -200: the other turn.
    let prev = [10.0, 20.0, 30.0, 40.0, 50.0, -200.0];
    let c = ik.choose(&pose, None, Some(&prev), ok).expect("ok");
    assert!(max_diff(&c.axes_deg, &other_turn) < 1e-9, "{c:?}");
    // The confdata decides over the distance.
    let conf = ConfData::from_array([0, 0, -3, 0]);
    let c = ik.choose(&pose, Some(conf), None, ok).expect("ok");
    assert!(max_diff(&c.axes_deg, &other_turn) < 1e-9, "{c:?}");
    // The caller's predicate: refusals are kept in the order tried.
    let mut order = sols.clone();
    ik.order_by_move(&mut order, None);
    let c = ik
        .choose(&pose, None, None, |x| {
            if x[5] > 0.0 {
                Err(format!("axis 6 at {}", x[5]))
            } else {
                Ok(())
            }
        })
        .expect("one with axis 6 <= 0");
    let first_ok = order.iter().find(|s| s.axes_deg[5] <= 0.0).expect("some");
    assert_eq!(c, *first_ok);
    let err = ik
        .choose(&pose, None, None, |_| Err("hits the fixture"))
        .unwrap_err();
    let ChooseError::AllRefused { refused } = &err else {
        panic!("{err}")
    };
    assert_eq!(refused.len(), sols.len());
    assert!(refused
        .iter()
        .zip(&order)
        .all(|((s, r), o)| s == o && *r == "hits the fixture"));
    assert!(err
        .to_string()
        .starts_with("every solution is refused: confdata"));
}

#[test]
fn metric_is_axis_time_then_euclidean_then_order() {
    let (_, ik) = irb();
    let conf = ConfData::from_array([0, 0, 0, 0]);
    let s = |axes_deg: Axes6| Solution { axes_deg, conf };
    // Speeds 110 (axes 1..3) and 280 deg/s (axes 4..6).
    let a = s([11.0, 0.0, 0.0, 0.0, 0.0, 0.0]); // 0.1 s, 11 deg
    let b = s([0.0, 0.0, 0.0, 27.0, 27.0, 27.0]); // 0.0964 s, 46.8 deg
    let c = s([0.0, 0.0, 0.0, 0.0, 0.0, 28.0]); // 0.1 s, 28 deg
    let d = s([-11.0, 0.0, 0.0, 0.0, 0.0, 0.0]); // the same cost as a
    let mut v = vec![c, a, d, b];
    ik.order_by_move(&mut v, None);
    assert_eq!(v, vec![b, a, d, c]);
    let mut v = vec![d, c, a, b];
    ik.order_by_move(&mut v, None);
    assert_eq!(v, vec![b, d, a, c], "exact ties keep the given order");
    let m = move_cost(&[0.0; 6], &b.axes_deg, &ik.speeds_deg_s());
    assert!((m.seconds - 27.0 / 280.0).abs() < 1e-15);
}

/// The coupling comes from the controller file, not from an assumption: the same URDF without
/// it is a serial arm whose axis 3 is the angle between the arms.
#[test]
fn coupling_is_honoured_not_assumed() {
    let (_, para) = irb();
    let serial_robot = robot_from(IRB_URDF, false);
    let serial = SixAxisIk::from_robot(&serial_robot).expect("serial");
    // In range for both: the serial axis 3 is the parallelogram's axis 3 - axis 2.
    let a = [20.0, 10.0, 30.0, 40.0, 50.0, 60.0];
    let pose = para.tool0(&a);
    let s = serial.solve(&pose, None).expect("serial");
    assert!(s
        .iter()
        .any(|s| max_diff(&s.axes_deg, &[20.0, 10.0, 20.0, 40.0, 50.0, 60.0]) < 1e-9));
    // Serial (60, 30) is the parallelogram's axis 3 = 90, beyond its 70 deg.
    let b = [0.0, 60.0, 30.0, 0.0, 30.0, 0.0];
    let pose = serial.tool0(&b);
    let s = serial.solve(&pose, None).expect("serial in range");
    assert!(s.iter().any(|s| max_diff(&s.axes_deg, &b) < 1e-9));
    let err = para.solve(&pose, None).unwrap_err();
    let SixAxisError::OutOfRange { candidates, .. } = &err else {
        panic!("{err}")
    };
    let up = candidates
        .iter()
        .find(|c| max_diff(&c.axes_deg, &[0.0, 60.0, 90.0, 0.0, 30.0, 0.0]) < 1e-9)
        .expect("the same arm in controller values");
    assert_eq!(
        up.violations,
        vec![RangeViolation::Axis {
            axis: 3,
            value_deg: up.axes_deg[2],
            min_deg: -65.0,
            max_deg: 70.0
        }]
    );
}

/// Another layout of joint frames: a shoulder offset along axis 2, a yawed joint-2 origin and
/// flipped axis signs. The geometry is read from the chain, so the round trip still holds.
#[test]
fn other_joint_layouts_round_trip() {
    let text = replaced(
        &replaced(
            IRB_URDF,
            r#"<origin xyz="0.150 0 0.475" rpy="0 0 0"/><axis xyz="0 1 0"/>"#,
            r#"<origin xyz="0.150 0.2 0.475" rpy="0 0 0.3"/><axis xyz="0 -1 0"/>"#,
        ),
        r#"<origin xyz="0 0 0.120" rpy="0 0 0"/><axis xyz="1 0 0"/>"#,
        r#"<origin xyz="0 0 0.120" rpy="0 0 0"/><axis xyz="-1 0 0"/>"#,
    );
    for parallelogram in [false, true] {
        let robot = robot_from(&text, parallelogram);
        let ik = SixAxisIk::from_robot(&robot).expect("still a spherical-wrist arm");
        assert!(
            ik.shoulder_offset_mm.abs() > 100.0,
            "{}",
            ik.shoulder_offset_mm
        );
        let w = round_trip(&robot, &ik, 500, 5, &torch());
        assert_eq!(w.poses, 500);
    }
    assert!(crate::robot::ik::ArmGeometry::from_robot(&robot_from(&text, false)).is_err());
}

#[test]
fn refuses_arms_of_another_kind() {
    let cases = [
        (
            r#"<origin xyz="0.085 0 0" rpy="0 0 0"/><axis xyz="1 0 0"/>"#,
            r#"<origin xyz="0.085 0 0.01" rpy="0 0 0"/><axis xyz="1 0 0"/>"#,
            "axes 4, 5 and 6 do not meet",
        ),
        (
            r#"<origin xyz="0 0 0.600" rpy="0 0 0"/><axis xyz="0 1 0"/>"#,
            r#"<origin xyz="0 0 0.600" rpy="0 0 0"/><axis xyz="1 0 0"/>"#,
            "axis 3 is not parallel to axis 2",
        ),
        (
            r#"<origin xyz="0.720 0 0" rpy="0 0 0"/><axis xyz="0 1 0"/>"#,
            r#"<origin xyz="0.720 0 0" rpy="0 0 0"/><axis xyz="1 1 0"/>"#,
            "axis 5 is not perpendicular to axis 4",
        ),
    ];
    for (from, to, says) in cases {
        let text = replaced(IRB_URDF, from, to);
        let err = SixAxisIk::from_robot(&robot_from(&text, false)).unwrap_err();
        assert!(matches!(err, SixAxisError::Structure { .. }));
        assert!(err.to_string().contains(says), "{err}");
    }
}

#[test]
fn wrist_singularity_keeps_axis_4() {
    let (robot, ik) = irb();
    let a = [10.0, 20.0, 30.0, 40.0, 0.0, 50.0];
    let pose = robot.tool0(&a);
    let sols = ik.solve(&pose, None).expect("in range");
    for s in &sols {
        let (mm, rad) = pose_error(&robot.tool0(&s.axes_deg), &pose);
        assert!(mm <= 1e-6 && rad <= 1e-9, "{s:?}");
        assert_eq!(
            s.axes_deg[3], 0.0,
            "axis 4 kept at 0 without a previous pose"
        );
    }
    // Axis 4 = 0 leaves axis 6 = 40 + 50, and its turn -270.
    assert!(sols
        .iter()
        .any(|s| max_diff(&s.axes_deg, &[10.0, 20.0, 30.0, 0.0, 0.0, 90.0]) < 1e-9));
    let prev = [0.0, 0.0, 0.0, 40.0, 10.0, 0.0];
    let sols = ik.solve(&pose, Some(&prev)).expect("in range");
    assert!(sols.iter().all(|s| s.axes_deg[3] == 40.0));
    assert!(
        sols.iter().any(|s| max_diff(&s.axes_deg, &a) < 1e-9),
        "{sols:?}"
    );
}

/// Close to the wrist singularity (but not on it) the flip pair is still solved, and every
/// solution still reproduces the pose; the original comes back while axis 5 is not tiny.
#[test]
fn near_the_wrist_singularity() {
    let (robot, ik) = irb();
    for q5 in [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, -1e-7] {
        let a = [10.0, 20.0, 30.0, 40.0, q5, 50.0];
        let pose = robot.tool0(&a);
        let sols = ik.solve(&pose, None).expect("in range");
        for s in &sols {
            let (mm, rad) = pose_error(&robot.tool0(&s.axes_deg), &pose);
            assert!(mm <= 1e-6 && rad <= 1e-9, "{q5}: {s:?}: {mm} mm {rad} rad");
        }
        let nearest = sols
            .iter()
            .map(|s| max_diff(&s.axes_deg, &a))
            .fold(f64::INFINITY, f64::min);
        eprintln!(
            "axis 5 = {q5:e} deg: {} solutions, original within {nearest:.2e} deg",
            sols.len()
        );
        if q5.abs() >= 1e-4 {
            assert!(nearest < 1e-6, "{q5}: {sols:?}");
        }
    }
}

#[test]
fn wrist_centre_on_axis_1_keeps_axis_1() {
    let robot = robot_from(IRB_URDF, false);
    let ik = SixAxisIk::from_robot(&robot).expect("serial");
    // r = 150 + 600 sin(q2) + L cos(q2 + q3 - beta) = 0 (L, beta of the forearm).
    let (l, beta) = (120.0f64.hypot(720.0), 120.0f64.atan2(720.0));
    let q2 = -40.0f64.to_radians();
    let phi = beta + (-(150.0 + 600.0 * q2.sin()) / l).acos();
    let a = [
        0.0,
        q2.to_degrees(),
        (phi - q2).to_degrees(),
        10.0,
        40.0,
        20.0,
    ];
    let pose = robot.tool0(&a);
    let w = ik.carry(&ik.coupling.urdf_rad(&a), 3, ik.wrist_zero);
    assert!(w.x.hypot(w.y) < 1e-9, "{w:?}");
    let prev = [25.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let cands = ik.candidates(&pose, Some(&prev)).expect("reachable");
    assert!(!cands.is_empty());
    for c in &cands {
        let (mm, rad) = pose_error(&robot.tool0(&c.axes_deg), &pose);
        assert!(mm <= 1e-6 && rad <= 1e-9, "{c:?}");
        let d = wrap_deg(c.axes_deg[0] - 25.0).abs();
        assert!(d < 1e-9 || (d - 180.0).abs() < 1e-9, "{c:?}");
    }
}

#[test]
fn violations_agree_with_check_range6() {
    let (robot, ik) = irb();
    let mut rng = Rng(3);
    for _ in 0..5000 {
        let a: Axes6 = std::array::from_fn(|i| {
            let s = &robot.controller.axes[i];
            rng.range(s.min_deg - 30.0, s.max_deg + 30.0)
        });
        let v = ik.violations(&a);
        assert_eq!(v.is_empty(), robot.check_range6(&a).is_ok(), "{a:?}");
        if let Err(first) = robot.check_range6(&a) {
            assert!(v.contains(&first));
        }
        assert!(v.iter().all(|v| excess_deg(v) > 0.0));
    }
}

#[test]
fn a_target_at_a_limit_solves() {
    let (robot, ik) = irb();
    let a = [170.0, 0.0, 70.0, -150.0, 115.0, 300.0];
    let sols = ik
        .solve(&robot.tool0(&a), None)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        sols.iter().any(|s| max_diff(&s.axes_deg, &a) < 1e-9),
        "{sols:?}"
    );
}

/// Rounding a solution to 0.001 deg moves the TCP no more than the bound, and for the IRB 1400
/// with a 350 mm torch the bound stays within the 0.1 mm and 0.01 deg a robtarget's
/// jointtarget must keep.
#[test]
fn rounding_bound_holds() {
    let (robot, ik) = irb();
    let tframe = torch();
    let mut rng = Rng(11);
    let (mut worst_bound, mut worst_ratio) = (0.0f64, 0.0f64);
    for _ in 0..1000 {
        let a = random_in_range(&mut rng, &robot);
        let tcp = robot.tool0(&a) * tframe;
        let b = ik.rounding_bound(&a, &tframe, 0.0005);
        assert!(
            b.position_mm < 0.1 && b.rotation_rad < 0.01f64.to_radians(),
            "{b:?}"
        );
        worst_bound = worst_bound.max(b.position_mm);
        let mut check = |r: Axes6| {
            let (mm, rad) = pose_error(&(robot.tool0(&r) * tframe), &tcp);
            assert!(
                mm <= b.position_mm && rad <= b.rotation_rad,
                "{a:?}: {mm} > {b:?}"
            );
            worst_ratio = worst_ratio.max(mm / b.position_mm);
        };
        check(a.map(|x| (x * 1000.0).round() / 1000.0));
        for corner in 0..64u32 {
            check(std::array::from_fn(|i| {
                a[i] + if corner >> i & 1 == 1 {
                    0.0005
                } else {
                    -0.0005
                }
            }));
        }
    }
    eprintln!("rounding bound: worst {worst_bound:.4} mm; worst actual/bound {worst_ratio:.3}");
}
