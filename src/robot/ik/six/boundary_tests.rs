//! Tests of confdata on quadrant boundaries (`conf.rs`, "On a quadrant boundary"): the confdata
//! of values is that of the written values, a value on a boundary is admitted for both
//! quadrants, and the round trip FK -> IK with the written confdata -> the same joints holds on
//! the boundaries of axes 1, 4, 6 and where the axis-5 bit of cfx flips. The oracle is the
//! robot's own forward kinematics (`Robot::tool0`).

use super::*;
use crate::geometry::testing::Rng;
use crate::precision::quantize_joints;

fn irb() -> (Robot, SixAxisIk) {
    let robot = Robot::irb1400();
    let ik = SixAxisIk::from_robot(&robot).expect("the IRB 1400 is a spherical-wrist arm");
    (robot, ik)
}

fn max_diff(a: &Axes6, b: &Axes6) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The quadrants of the unrounded values (`floor(axis / 90)`), as a reader of the manual
/// computes them: what a cell may also give for a pose on a boundary.
fn raw_conf(ik: &SixAxisIk, a: &Axes6) -> ConfData {
    let q = |v: f64| (v / 90.0).floor() as i32;
    let own = ik.conf(a);
    ConfData {
        cf1: q(a[0]),
        cf4: q(a[3]),
        cf6: q(a[5]),
        cfx: (own.cfx & 6) + i32::from(a[4] < 0.0),
    }
}

/// Values a hair either side of a boundary get the confdata of their written values; `-0` is
/// 0. Fails with the quadrant of the unrounded value (the gripper cell's `above_place`: axis 4
/// at -1e-15 was cf4 -1 while the module writes 0.000).
#[test]
fn the_confdata_of_values_is_that_of_the_written_values() {
    let (_, ik) = irb();
    let a = [90.0 - 1e-13, 9.123, 35.675, -1e-15, 54.325, 180.0 - 3e-14];
    assert_eq!(ik.conf(&a).to_array(), [1, 0, 2, 0]);
    let b = [-0.0, 0.0, 0.0, -0.0, 30.0, -0.0];
    assert_eq!(ik.conf(&b).to_array(), [0, 0, 0, 0]);
    // Axis 5 written -0.000 is not negative; -0.001 is.
    let mut c = a;
    c[4] = -0.0004;
    assert_eq!(ik.conf(&c).cfx & 1, 0);
    c[4] = -0.0006;
    assert_eq!(ik.conf(&c).cfx & 1, 1);
    // 89.9996 is written 90.000: quadrant 1; 89.9994 is written 89.999: quadrant 0.
    let mut d = a;
    d[0] = 89.9996;
    assert_eq!(ik.conf(&d).cf1, 1);
    d[0] = 89.9994;
    assert_eq!(ik.conf(&d).cf1, 0);
}

/// A value within half the written step of a quadrant is admitted for it, one farther is not;
/// a cfx outside 0..7 admits nothing. Fails with an exact quadrant test or a tolerance of
/// another size.
#[test]
fn values_on_a_boundary_are_admitted_for_both_quadrants() {
    let (_, ik) = irb();
    let base = [0.0, 10.0, 20.0, 0.0, 40.0, 0.0];
    let with = |i: usize, v: f64| {
        let mut a = base;
        a[i] = v;
        a
    };
    let conf = |cf1, cf4, cf6, cfx| ConfData { cf1, cf4, cf6, cfx };
    for (i, pick) in [(0usize, 0usize), (3, 1), (5, 2)] {
        let wanted = |cf: i32| {
            let mut c = [0, 0, 0, ik.conf(&base).cfx];
            c[pick] = cf;
            conf(c[0], c[1], c[2], c[3])
        };
        for v in [
            90.0,
            90.0 - 1e-12,
            90.0 + 1e-12,
            90.0 - 0.0004,
            90.0 + 0.0004,
        ] {
            assert!(
                ik.conf_admits(&with(i, v), wanted(0)),
                "axis {} = {v}",
                i + 1
            );
            assert!(
                ik.conf_admits(&with(i, v), wanted(1)),
                "axis {} = {v}",
                i + 1
            );
        }
        assert!(!ik.conf_admits(&with(i, 90.0 + 0.0006), wanted(0)));
        assert!(!ik.conf_admits(&with(i, 90.0 - 0.0006), wanted(1)));
        for v in [-0.0, -1e-15, 1e-15] {
            assert!(
                ik.conf_admits(&with(i, v), wanted(0)),
                "axis {} = {v}",
                i + 1
            );
            assert!(
                ik.conf_admits(&with(i, v), wanted(-1)),
                "axis {} = {v}",
                i + 1
            );
            assert!(!ik.conf_admits(&with(i, v), wanted(1)));
        }
    }
    let own = ik.conf(&base);
    assert!(ik.conf_admits(&base, own));
    assert!(!ik.conf_admits(&base, conf(0, 0, 0, own.cfx + 8)));
    // Axis 5: within the tolerance of 0 on either side for either bit.
    let cfx = own.cfx & 6;
    assert!(ik.conf_admits(&with(4, -0.0004), conf(0, 0, 0, cfx)));
    assert!(ik.conf_admits(&with(4, 0.0004), conf(0, 0, 0, cfx + 1)));
    assert!(!ik.conf_admits(&with(4, -0.0006), conf(0, 0, 0, cfx)));
}

/// FK -> IK with the written confdata (of the written values) -> the same joints, and with the
/// confdata of the unrounded values too, on quadrant boundaries of axes 1, 4 and 6 (exactly on
/// them, a hair either side, and within the written step) and where the axis-5 bit of cfx flips
/// (axis 5 within the written step of 0), over random arms. Fails, for example, with the choice
/// by exact confdata: a pose with axis 4 at 0 solves to -1e-15 and its written [.., 0, ..] is
/// "not reachable".
#[test]
fn the_round_trip_holds_on_quadrant_boundaries_and_cfx_flips() {
    let (robot, ik) = irb();
    let mut rng = Rng(27);
    let hairs = [0.0, -1e-13, 1e-13, -0.0004, 0.0004];
    let axis1 = [90.0, -90.0, 0.0];
    let axis4 = [0.0, 90.0, -90.0];
    let axis6 = [0.0, 90.0, 180.0, -180.0, -90.0, 270.0, -270.0];
    let axis5 = [35.0, -60.0, 0.0004, -0.0004, 0.0007, -0.0007];
    let (mut cases, mut worst) = (0usize, 0.0f64);
    for _ in 0..60 {
        let (a2, a3) = loop {
            let a2 = rng.range(-60.0, 60.0);
            let a3 = rng.range(-55.0, 60.0);
            if robot.axis3_in_range(a2, a3) {
                break (a2, a3);
            }
        };
        let a1 = axis1[rng.below(3) as usize] + hairs[rng.below(5) as usize];
        let a4 = axis4[rng.below(3) as usize] + hairs[rng.below(5) as usize];
        let a5 = axis5[rng.below(6) as usize];
        let a6 = axis6[rng.below(7) as usize] + hairs[rng.below(5) as usize];
        let a = [a1, a2, a3, a4, a5, a6];
        if robot.check_range6(&a).is_err() {
            continue;
        }
        let tool0 = robot.tool0(&a);
        for wanted in [ik.conf(&quantize_joints(a)), raw_conf(&ik, &a)] {
            let chosen = ik
                .choose(&tool0, Some(wanted), None, |_| Ok::<(), ()>(()))
                .unwrap_or_else(|e| panic!("{a:?} with {wanted}: {e:?}"));
            let d = max_diff(&chosen.axes_deg, &a);
            assert!(d < 1e-6, "{a:?} with {wanted}: chose {:?}", chosen.axes_deg);
            assert!(ik.conf_admits(&quantize_joints(chosen.axes_deg), wanted));
            worst = worst.max(d);
            cases += 1;
        }
    }
    assert!(cases > 60, "{cases}");
    eprintln!("{cases} round trips on quadrant boundaries: the joints within {worst:.2e} deg");
}
