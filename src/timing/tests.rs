//! The time stage against hand-computed profiles, the TCP path and the fly-by rule.
use super::*;

fn axis(v: f64, a: f64) -> AxisSpec {
    AxisSpec {
        min_deg: -180.0,
        max_deg: 180.0,
        speed_deg_s: v,
        acceleration_deg_s2: Some(a),
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn long_move_cruises_hand_computed() {
    // v = 100 deg/s, a = 1000 deg/s^2: ramp T_r = 15 * 100 / 8000 = 0.1875 s, covering
    // 100 * 0.1875 / 2 = 9.375 deg each. D = 100 deg: cruise 100 - 18.75 = 81.25 deg at
    // 100 deg/s = 0.8125 s; total 0.1875 + 0.8125 + 0.1875 = 1.1875 s. The one quintic
    // would need 15 * 100 / 800 = 1.875 s, slower.
    assert!(close(axis_time_s(100.0, 100.0, 1000.0), 1.1875, 1e-12));
    assert!(close(
        cruise_profile_s(100.0, 100.0, 1000.0).unwrap_or(f64::NAN),
        1.1875,
        1e-12
    ));
    // The IRB 1400's axis 1 (110 deg/s, 515.625 deg/s^2, ramp 0.4 s) sweeping 180 deg:
    // 180 / 110 + 0.4 = 1.636364 + 0.4 = 2.036364 s.
    assert!(close(axis_time_s(-180.0, 110.0, 515.625), 2.036364, 1e-6));
}

#[test]
fn short_move_is_one_quintic_hand_computed() {
    // v = 100, a = 1000, D = 1 deg: far shorter than two ramps (18.75 deg), so profile (b).
    // Speed bound 15 * 1 / 800 = 0.01875 s; acceleration bound
    // sqrt(10 * 1 / (1.7320508 * 1000)) = sqrt(0.0057735) = 0.0759836 s: the acceleration
    // limits it, and the peak speed 15 / (8 * 0.0759836) = 24.7 deg/s stays below v (Fig. 9b).
    assert!(cruise_profile_s(1.0, 100.0, 1000.0).is_none());
    assert!(close(axis_time_s(1.0, 100.0, 1000.0), 0.0759836, 1e-6));
    // IRB 1400 axis 2, D = 10 deg: sqrt(100 / (1.7320508 * 515.625)) = sqrt(0.1119709)
    // = 0.334621 s (the speed bound is 150 / 880 = 0.170 s).
    assert!(close(axis_time_s(10.0, 110.0, 515.625), 0.334621, 1e-6));
}

#[test]
fn continuous_and_increasing_at_the_cruise_boundary() {
    let (v, a) = (100.0, 1000.0);
    // The tie: D* = 15 v^2 / (7 a) = 150000 / 7000 = 21.428571 deg, where both profiles
    // take 15 D* / (8 v) = D* / v + T_r = 0.214286 + 0.1875 = 0.401786 s.
    let d_star = 15.0 * v * v / (7.0 * a);
    assert!(close(axis_time_s(d_star, v, a), 0.401786, 1e-6));
    let eps = 1e-7;
    let below = axis_time_s(d_star - eps, v, a);
    let above = axis_time_s(d_star + eps, v, a);
    assert!(below < above && above - below < 1e-8, "{below} {above}");
    // Below D* the quintic is used although (a) fits; above it the cruise is.
    assert!(cruise_profile_s(d_star - 1.0, v, a).is_some());
    assert!(axis_time_s(d_star - 1.0, v, a) < cruise_profile_s(d_star - 1.0, v, a).unwrap_or(0.0));
    // Also where (a) starts to fit (D = v T_r = 18.75): no jump.
    let d_fit = v * ramp_time_s(v, a);
    assert!(axis_time_s(d_fit + eps, v, a) - axis_time_s(d_fit - eps, v, a) < 1e-8);
    // Strictly increasing over a sweep across both boundaries.
    let mut last = 0.0;
    for i in 1..=4000 {
        let t = axis_time_s(i as f64 * 0.01, v, a);
        assert!(t > last, "not increasing at D = {}", i as f64 * 0.01);
        last = t;
    }
}

#[test]
fn the_leading_axis_sets_the_time_and_all_six_count() {
    let mut axes = [axis(110.0, 515.625); 6];
    for a in axes.iter_mut().skip(3) {
        *a = axis(280.0, 1312.5);
    }
    let from = [0.0; 6];
    // Axis 1 moves 10 deg (0.334621 s, above); axis 6 moves 100 deg: its ramp is
    // 15 * 280 / (8 * 1312.5) = 0.4 s and two ramps cover 280 * 0.4 = 112 deg > 100, so one
    // quintic: speed bound 15 * 100 / (8 * 280) = 0.669643 s, acceleration bound
    // sqrt(1000 / (1.7320508 * 1312.5)) = 0.663243 s -> 0.669643 s. Axis 6 leads.
    let to = [10.0, 0.0, 0.0, 0.0, 0.0, 100.0];
    assert_eq!(leading_axis(&from, &to, &axes), 5);
    assert!(close(move_time_s(&from, &to, &axes), 0.669643, 1e-6));
    let to = [10.0, 0.0, 0.0, 0.0, 0.0, 5.0];
    assert_eq!(leading_axis(&from, &to, &axes), 0);
    assert!(close(move_time_s(&from, &to, &axes), 0.334621, 1e-6));
    assert_eq!(move_time_s(&from, &from, &axes), 0.0);
}

#[test]
fn the_profile_of_a_move_is_its_leading_axis_and_progress_follows_it() {
    let axes = [axis(110.0, 515.625); 6];
    let from = [0.0; 6];
    // 180 deg cruises (ramp 15 * 110 / (8 * 515.625) = 0.4 s); 10 deg is one quintic.
    let long = [180.0, 20.0, 0.0, 0.0, 0.0, 0.0];
    assert_eq!(
        move_profile(&from, &long, &axes),
        Profile::Cruise { ramp_s: 0.4 }
    );
    let short = [10.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    assert_eq!(move_profile(&from, &short, &axes), Profile::Quintic);
    assert_eq!(move_profile(&from, &from, &axes), Profile::Quintic);
    // Cruise, ramp 0.4 s, 2 s in all: speed 1 / 1.6 = 0.625 of the move per second; a ramp
    // covers 0.625 * 0.4 / 2 = 0.125; halfway 0.125 + 0.625 * 0.6 = 0.5.
    let p = Profile::Cruise { ramp_s: 0.4 };
    assert!(close(p.progress(0.4, 2.0), 0.125, 1e-12));
    assert!(close(p.progress(1.0, 2.0), 0.5, 1e-12));
    assert!(close(p.progress(1.6, 2.0), 0.875, 1e-12));
    assert_eq!((p.progress(0.0, 2.0), p.progress(2.0, 2.0)), (0.0, 1.0));
    // The quintic: h(1/4) = (1/64) (10 - 15/4 + 6/16) = 0.103515625.
    assert!(close(
        Profile::Quintic.progress(0.25, 1.0),
        0.103515625,
        1e-12
    ));
    assert!(close(Profile::Quintic.progress(0.5, 1.0), 0.5, 1e-12));
    // Both rise steadily, never faster than their peak speed: the cruise's 0.625 per second,
    // the quintic's 15 / 8 over 2 s.
    for (profile, peak) in [(p, 0.625), (Profile::Quintic, 15.0 / 16.0)] {
        let mut last = 0.0;
        for i in 1..=2000 {
            let now = profile.progress(i as f64 * 0.001, 2.0);
            assert!(now >= last && now - last <= peak * 0.001 * (1.0 + 1e-9));
            last = now;
        }
    }
}

use crate::cell::{Frame, Loc};
use crate::place::PlacedPoint;
use crate::plan::{Method, Waypoint, WaypointKind};

fn point(speed: &str, zone: &str) -> PlacedPoint {
    crate::plan::motion::point_with_motion("P", speed, zone)
}

/// The estimate of `route` with the motions as planned from `points` (`motion::planned`).
fn planned(route: &Route, points: &[PlacedPoint], model: &TimeModel) -> Estimate {
    estimate(route, &crate::plan::motion::planned(route, points), model)
}

/// The time of each move of an estimate, s.
fn move_s(e: &Estimate) -> Vec<f64> {
    e.moves.iter().map(|m| m.time_s).collect()
}

/// A route through `joints`: the first and last cell points 0 and 1, vias of leg 0 between.
fn plan_of(joints: &[[f64; 6]]) -> Route {
    let last = joints.len() - 1;
    let waypoints = joints
        .iter()
        .enumerate()
        .map(|(k, &joints_deg)| Waypoint {
            kind: match k {
                0 => WaypointKind::CellPoint(0),
                k if k == last => WaypointKind::CellPoint(1),
                k => WaypointKind::Via { leg: 0, index: k },
            },
            joints_deg,
        })
        .collect();
    Route {
        method: Method::Extensile,
        grid_deg: 1.0,
        waypoints,
        legs: Vec::new(),
    }
}

/// A tool whose TCP is 200 mm along the flange's z axis (the axis-6 line), turned 30 deg.
fn tool_on_axis6() -> Tool {
    let half = 15f64.to_radians();
    Tool {
        name: "tPen".into(),
        tframe: Frame {
            pos_mm: [0.0, 0.0, 200.0],
            quat_wxyz: [half.cos(), half.sin(), 0.0, 0.0],
        },
        mass_kg: 1.0,
        cog_mm: [0.0; 3],
        shapes: Vec::new(),
        loc: Loc::default(),
    }
}

#[test]
fn a_route_sums_its_moves_over_all_six_axes() {
    let robot = Robot::irb1400();
    let model = TimeModel::new(&robot, None);
    let plan = plan_of(&[
        [0.0, 0.0, 0.0, 0.0, 30.0, 0.0],
        [10.0, 0.0, 0.0, 0.0, 30.0, 0.0],
        [10.0, 10.0, 0.0, 0.0, 30.0, 100.0],
    ]);
    // vmax: the axes lead (the TCP covers at most ~200 mm here, 0.04 s at 5000 mm/s; the
    // wrist turns 100 deg, 0.2 s at 500 deg/s).
    let points = [point("v300", "fine"), point("vmax", "fine")];
    // Move 1: axis 1, 10 deg: 0.334621 s. Move 2: axis 2 10 deg (0.334621 s) and axis 6
    // 100 deg (0.669643 s, above): 0.669643 s. Total 1.004264 s. The via is `fine`.
    let e = planned(&plan, &points, &model);
    let t = move_s(&e);
    assert_eq!(t.len(), 2);
    assert!(close(t[0], 0.334621, 1e-6) && close(t[1], 0.669643, 1e-6));
    assert!(close(e.total_s, 1.004264, 1e-6));
    let limits: Vec<Limit> = e.moves.iter().map(|m| m.limit).collect();
    assert_eq!(limits, [Limit::Axis, Limit::Axis]);
}

#[test]
fn the_tcp_speed_limits_an_axis_1_swing_on_its_circle() {
    // The IRB 1400 at zero: the flange lies 150 + 720 + 85 = 955 mm from axis 1 (the URDF's
    // joint origins: joint 2 at x 150, joint 5 at x 720 beyond joint 4, joint 6 at x 85
    // beyond it). Turning axis 1 by 90 deg moves tool0 on a circle of radius 955 mm: an arc
    // of 955 pi / 2 = 1500.1 mm, whatever the polyline.
    let robot = Robot::irb1400();
    let model = TimeModel::new(&robot, None);
    let (from, to) = ([0.0; 6], [90.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let arc_mm = 955.0 * std::f64::consts::FRAC_PI_2;
    let path = tcp_path(&from, &to, |q| model.tcp(q));
    assert!(path.length_mm <= arc_mm + 1e-9, "{path:?}");
    assert!(arc_mm - path.length_mm < 0.1, "{path:?}");
    // The flange turns 90 deg about the vertical as well.
    assert!(close(path.angle_deg, 90.0, 1e-6), "{path:?}");
    // Axes alone: 90 / 110 + 0.4 = 1.218182 s.
    let axis_s = 90.0 / 110.0 + 0.4;
    let v100 = move_time(&from, &to, &model, model.speed("v100"));
    let v1000 = move_time(&from, &to, &model, model.speed("v1000"));
    let vmax = move_time(&from, &to, &model, model.speed("vmax"));
    // The TCP's path as one more axis: length L = 1500.1 mm at v_tcp, with the acceleration
    // axis 1 allows the move's progress, a_1 / D_1 = 515.625 / 90 per s^2, i.e.
    // 515.625 L / 90 mm/s^2: its ramp is 15 v 90 / (8 515.625 L) s, and a long path cruises:
    // t = L / v + ramp. v100: 15.0012 + 0.0218 = 15.023 s (at least L / 100: the TCP never
    // runs faster than v_tcp on average); v1000: 1.5001 + 0.2182 = 1.718 s, still above the
    // axes; vmax (5000 mm/s: 0.30 + 1.09, but two ramps would cover 5456 mm > L, so one
    // quintic) leaves the axes in the lead: its course never runs faster than axis 1's
    // pace allows, L v_1 / D_1 = 1833 mm/s, so at vmax it is axis 1's own profile.
    let tcp_s = |v: f64| arc_mm / v + 15.0 * v * 90.0 / (8.0 * 515.625 * arc_mm);
    assert!(v100.stop_s >= arc_mm / 100.0 - 0.01, "{v100:?}");
    assert!(
        close(v100.stop_s, tcp_s(100.0), PATH_TOL_MM / 100.0),
        "{v100:?}"
    );
    assert!(close(v1000.stop_s, tcp_s(1000.0), 1e-4), "{v1000:?}");
    assert!(close(vmax.stop_s, axis_s, 1e-9));
    assert!(close(vmax.tcp_s, axis_s, 1e-9), "{vmax:?}");
    assert_eq!(
        (v100.limit, v1000.limit, vmax.limit),
        (Limit::Tcp, Limit::Tcp, Limit::Axis)
    );
    // An unknown speeddata: the axes alone.
    let unknown = move_time(&from, &to, &model, model.speed("vMine"));
    assert!(close(unknown.stop_s, axis_s, 1e-9));
    // The profile of the TCP's limit: its own ramp.
    match v100.profile {
        Profile::Cruise { ramp_s } => assert!(close(ramp_s, tcp_s(100.0) - 15.0012, 1e-4)),
        p => panic!("{p:?}"),
    }
}

#[test]
fn a_turn_of_axis_6_reorients_the_tool_without_moving_its_tcp() {
    // With the TCP on the axis-6 line (200 mm along tool0's z axis, which is that line),
    // turning axis 6 by 120 deg leaves the TCP where it is and turns the tool 120 deg.
    let robot = Robot::irb1400();
    let tool = tool_on_axis6();
    let model = TimeModel::new(&robot, Some(&tool));
    let (from, to) = ([0.0; 6], [0.0, 0.0, 0.0, 0.0, 0.0, 120.0]);
    let path = tcp_path(&from, &to, |q| model.tcp(q));
    assert!(path.length_mm < 1e-6, "{path:?}");
    assert!(close(path.angle_deg, 120.0, 1e-6), "{path:?}");
    // Every predefined speeddata turns the tool at 500 deg/s: 0.24 s, below axis 6's
    // 0.803571 s (120 deg is below the tie D* = 15 280^2 / (7 1312.5) = 128 deg: one
    // quintic, 15 120 / (8 280)), so even v5 leaves the axes in the lead.
    let v5 = move_time(&from, &to, &model, model.speed("v5"));
    assert!(close(v5.stop_s, 0.803571, 1e-6), "{v5:?}");
    assert_eq!(v5.limit, Limit::Axis);
    // A slow reorientation speed leads: 120 deg at 20 deg/s with the acceleration axis 6
    // allows (1312.5 / 120 of the move per s^2, i.e. 1312.5 deg/s^2 for the 120 deg): ramp
    // 15 20 / (8 1312.5) = 0.028571 s, t = 6 + 0.028571 s.
    let slow = SpeedData {
        v_ori_deg_s: 20.0,
        ..rapid_data::vmax_for(100.0)
    };
    let m = move_time(&from, &to, &model, Some(slow));
    assert!(
        m.stop_s >= 120.0 / 20.0 && close(m.stop_s, 6.028571, 1e-5),
        "{m:?}"
    );
    assert_eq!(m.limit, Limit::Reorientation);
}

#[test]
fn the_sampled_path_converges_and_is_deterministic() {
    let robot = Robot::irb1400();
    let tool = tool_on_axis6();
    let model = TimeModel::new(&robot, Some(&tool));
    let (from, to) = (
        [-40.0, 10.0, -20.0, 30.0, 45.0, -60.0],
        [60.0, -20.0, 40.0, -50.0, -30.0, 90.0],
    );
    let a = tcp_path(&from, &to, |q| model.tcp(q));
    let b = tcp_path(&from, &to, |q| model.tcp(q));
    assert_eq!(a, b);
    // Independently: 100 000 equal steps (a polyline never overestimates the path; the
    // converged one is within the tolerance of this much finer one).
    let n = 100_000;
    let poses: Vec<_> = (0..=n)
        .map(|i| model.tcp(&lerp6(&from, &to, i as f64 / n as f64)))
        .collect();
    let (fine_mm, fine_deg) = polyline(&poses);
    assert!(a.length_mm <= fine_mm + 1e-6 && fine_mm - a.length_mm < PATH_TOL_MM);
    assert!(a.angle_deg <= fine_deg + 1e-6 && fine_deg - a.angle_deg < ANGLE_TOL_DEG);
    assert!(a.steps < MAX_STEPS, "{a:?}");
    // The move back is as long.
    let back = tcp_path(&to, &from, |q| model.tcp(q));
    assert!(close(back.length_mm, a.length_mm, PATH_TOL_MM));
}

#[test]
fn what_flying_through_a_move_end_saves() {
    let robot = Robot::irb1400();
    let model = TimeModel::new(&robot, None);
    // An axis-1 move of 60 deg, a move of axes 2 and 3, a last small move.
    let plan = plan_of(&[
        [0.0, 0.0, 0.0, 0.0, 30.0, 0.0],
        [60.0, 0.0, 0.0, 0.0, 30.0, 0.0],
        [60.0, 30.0, 20.0, 0.0, 30.0, 0.0],
        [65.0, 30.0, 20.0, 0.0, 30.0, 0.0],
    ]);
    let timed = |zone: &str| {
        let points = [point("vmax", "fine"), point("vmax", zone)];
        planned(&plan, &points, &model)
    };
    let fine = timed("fine");
    // The vias stop (as planned they are `fine`) and the last point always stops,
    // whatever its zone.
    assert_eq!(fine.total_s, timed("z50").total_s);
    let stops: Vec<MoveTime> = plan
        .moves6()
        .map(|(a, b)| move_time(&a, &b, &model, model.speed("vmax")))
        .collect();
    // Move 1 cruises (60 deg, ramp 0.4 s): flying through its end saves 0.2 s on axis 1;
    // axis 1 alone moves, so the least of the six is axis 1's r/2 = 0.2 s.
    assert!(close(stops[0].end_saving_s, 0.2, 1e-9), "{stops:?}");
    // Move 2: axes 2 and 3 by 30 and 20 deg (30 deg: 15 D / (8 v) = 0.511 s against
    // D / v + T_r = 0.673 s: one quintic, and so is 20 deg): 7 t / 30.
    assert!(close(
        stops[1].end_saving_s,
        7.0 * stops[1].stop_s / 30.0,
        1e-9
    ));
    for (k, m) in stops.iter().enumerate() {
        // Never shorter than the move at its peak speed throughout.
        assert!(2.0 * m.end_saving_s < m.stop_s, "move {k}");
    }
    assert_eq!(
        move_s(&fine),
        stops.iter().map(|m| m.stop_s).collect::<Vec<_>>()
    );
}

#[test]
fn two_cruising_moves_flown_through_save_one_whole_ramp() {
    let robot = Robot::irb1400();
    let model = TimeModel::new(&robot, None);
    // Axis 1 by 60 deg twice, through a cell point: each move cruises (60 >= v T_r = 44
    // deg) and takes 60 / 110 + 0.4 s by hand; flown through, the first does not ramp down
    // and the second does not ramp up: each loses half its 0.4 s ramp, 0.4 s in all.
    let mut plan = plan_of(&[
        [0.0, 0.0, 0.0, 0.0, 30.0, 0.0],
        [60.0, 0.0, 0.0, 0.0, 30.0, 0.0],
        [120.0, 0.0, 0.0, 0.0, 30.0, 0.0],
    ]);
    plan.waypoints[1].kind = WaypointKind::CellPoint(1);
    plan.waypoints[2].kind = WaypointKind::CellPoint(2);
    let total = |zone: &str| {
        let points = [
            point("vmax", "fine"),
            point("vmax", zone),
            point("vmax", "fine"),
        ];
        planned(&plan, &points, &model).total_s
    };
    let by_hand_s = 2.0 * (60.0 / 110.0 + 0.4);
    assert!(close(total("fine"), by_hand_s, 1e-9), "{}", total("fine"));
    assert!(
        close(total("z50"), by_hand_s - 0.4, 1e-9),
        "{}",
        total("z50")
    );
}

#[test]
fn fly_by_is_never_slower_strictly_faster_and_continuous() {
    let robot = Robot::irb1400();
    let model = TimeModel::new(&robot, None);
    // A route of three cell points (the middle one is the only waypoint between two moves),
    // its zone fine or z50.
    let route = |mid: [f64; 6]| {
        let mut plan = plan_of(&[[0.0, 0.0, 0.0, 0.0, 30.0, 0.0], mid, [80.0; 6]]);
        plan.waypoints[1].kind = WaypointKind::CellPoint(1);
        plan.waypoints[2].kind = WaypointKind::CellPoint(2);
        plan.waypoints[2].joints_deg = [80.0, 10.0, 10.0, 0.0, 30.0, 0.0];
        plan
    };
    let total = |plan: &Route, zone: &str| {
        let points = [
            point("v300", "fine"),
            point("v300", zone),
            point("v300", "fine"),
        ];
        planned(plan, &points, &model).total_s
    };
    let mut last = None;
    for i in 0..=400 {
        // The middle point slides along axis 1 through both profiles' boundary.
        let a1 = 0.1 * i as f64;
        let plan = route([a1, 5.0, 0.0, 0.0, 30.0, 0.0]);
        let (stop, fly) = (total(&plan, "fine"), total(&plan, "z50"));
        assert!(fly < stop, "at {a1}: {fly} vs {stop}");
        // A user zonedata is a fly-by zone too, and the model does not read its size.
        assert_eq!(fly, total(&plan, "zMine"));
        if let Some(prev) = last {
            let jump: f64 = fly - prev;
            // Continuous, not Lipschitz: a short one-quintic move's time grows as the square
            // root of its length (a steep slope near the start). A jump of 0.01 s for a
            // 0.1 deg step is what a step in the model would show.
            assert!(jump.abs() < 0.01, "jump {jump} at {a1}");
        }
        last = Some(fly);
    }
    // A middle point that is the start (a move of zero length) saves nothing.
    let plan = route([0.0, 0.0, 0.0, 0.0, 30.0, 0.0]);
    assert_eq!(total(&plan, "z50"), total(&plan, "fine"));
}

/// Every shipped robot's controller file states its accelerations as its speeds x 4.6875
/// /s (full speed in 0.4 s on the quintic ramp, as the IRB 1400's: docs/robots.md), so a
/// move of each axis over one second's worth of its own speed takes 1.4 s in the estimate.
/// Fails with an axis that reaches its speed faster or slower, or a speed the estimate does
/// not take from the robot's own file.
#[test]
fn every_shipped_robot_reaches_full_speed_in_0_4_s() {
    for m in crate::robot::models::MODELS {
        let robot = crate::robot::Robot::shipped(m.name).expect("shipped");
        for (k, a) in robot.controller.axes.iter().enumerate() {
            let v = a.speed_deg_s;
            assert!(
                close(a.acceleration(), v * 4.6875, 1e-9),
                "{} axis {}: {} deg/s^2 for {v} deg/s",
                m.name,
                k + 1,
                a.acceleration()
            );
            assert!(close(axis_time_s(v, v, a.acceleration()), 1.4, 1e-12));
        }
    }
}

#[test]
fn missing_acceleration_defaults_to_a_0_4_s_ramp() {
    let a = AxisSpec {
        acceleration_deg_s2: None,
        ..axis(110.0, 1.0)
    };
    // 15 * 110 / (8 * 0.4) = 515.625
    assert!(close(a.acceleration(), 515.625, 1e-12));
}
