//! Manipulation time of a planned route (paper section 5, Fig. 9): the figure the paper uses,
//! besides the number of moves, to compare its three search methods.
//!
//! Every straight move is a `MoveAbsJ ... fine`: it starts and ends at rest, and the route's time
//! is the sum of its moves' times. Within a move each axis k covers D_k = |delta_k| degrees
//! under its maximum speed v_k and peak acceleration a_k (the controller file,
//! `robot::controller`), and all axes start and stop together: the move takes as long as its
//! slowest axis needs (the *leading* axis), and the others are slowed down (their profiles
//! stretched in time) to finish with it. All six axes count: axes 4..6 move only on a leg's last
//! move and only when a cell point gives its own wrist (see `plan`), but then they may lead.
//!
//! # One axis, one move: the two profiles of Fig. 9
//!
//! The paper gives the motion as a polynomial S(t) = C5 t^5 + ... + C0 and two cases. With
//! h(s) = 10 s^3 - 15 s^4 + 6 s^5 (the rest-to-rest quintic: h(0) = 0, h(1) = 1, h' and h'' zero
//! at both ends; max h' = h'(1/2) = 15/8, max |h''| = h''((3 -+ sqrt 3)/6) = 10/sqrt 3):
//!
//! * **(a) ramp, cruise, ramp.** The speed rises 0 -> v along v(t) = v h(t/T_r), cruises at v,
//!   and falls back symmetrically. Each ramp starts and ends with zero acceleration; its peak
//!   acceleration is 15 v / (8 T_r), so the shortest ramp the limit allows is
//!   T_r = 15 v / (8 a), and it covers v T_r / 2 (the mean of h over [0, 1] is 1/2). Possible
//!   when D >= v T_r (the two ramps alone), taking T_a = 2 T_r + (D - v T_r) / v = D / v + T_r.
//! * **(b) one quintic.** S(t) = D h(t/T): peak speed 15 D / (8 T) <= v and peak acceleration
//!   10 D / (sqrt 3 T^2) <= a, so T_b = max(15 D / (8 v), sqrt(10 D / (sqrt 3 a))). Possible at
//!   any D; below 64 * 10 / (225 sqrt 3) v^2/a ~ 1.64 v^2/a it never reaches v (Fig. 9b).
//!
//! The axis takes the faster of the two: T(D) = min(T_a, T_b) (T_b alone when (a) does not fit).
//! Choosing "(a) whenever it fits" instead would make the time jump *down* as a move grows past
//! D = v T_r: there (a) has no cruise and needs 2 T_r = 3.75 v/a, while (b) needs only
//! 15 D / (8 v) = 3.52 v/a. With the minimum, (b) serves short moves and (a) takes over where the
//! two tie, at D* = 15 v^2 / (7 a) (from 15 D / (8 v) = D / v + T_r; (b) is speed-limited there).
//! T(D) is continuous and strictly increasing, so a longer move never takes less time.
//!
//! # Values
//!
//! Speeds: the controller file (IRB 1400: 110 deg/s for axes 1-3, 280 for axes 4-6, from
//! `docs/irb1400.md`). Accelerations: ABB does not publish them; the IRB 1400 file states
//! 515.625 deg/s^2 (axes 1-3) and 1312.5 deg/s^2 (axes 4-6), i.e. full speed in a 0.4 s ramp,
//! an *estimate* whose reasoning is in `robots/irb1400.controller.yaml` (the paper's own results
//! cost ~0.39 s per extra move). An axis without a stated acceleration gets the same 0.4 s ramp
//! ([`crate::robot::controller::DEFAULT_RAMP_S`]). The result is a planning figure for comparing
//! routes, not a cycle time: the real controller blends, limits torques and plans its own
//! profiles.

use crate::plan::{Estimate, Plan, Profile};
use crate::robot::AxisSpec;

/// Ramp time (s) of the quintic speed ramp for speed `v` under peak acceleration `a`.
pub fn ramp_time_s(v: f64, a: f64) -> f64 {
    15.0 * v / (8.0 * a)
}

/// Time (s) of profile (a), ramp-cruise-ramp, or `None` when the distance is shorter than the
/// two ramps.
pub fn cruise_profile_s(d: f64, v: f64, a: f64) -> Option<f64> {
    let tr = ramp_time_s(v, a);
    (d >= v * tr).then(|| d / v + tr)
}

/// Time (s) of profile (b), the single rest-to-rest quintic.
pub fn quintic_profile_s(d: f64, v: f64, a: f64) -> f64 {
    let by_speed = 15.0 * d / (8.0 * v);
    let by_acceleration = (10.0 * d / (3f64.sqrt() * a)).sqrt();
    by_speed.max(by_acceleration)
}

/// The shortest time (s) for one axis to move `d` degrees from rest to rest, at most `v` deg/s
/// and `a` deg/s^2: the faster of the two profiles (module doc).
pub fn axis_time_s(d: f64, v: f64, a: f64) -> f64 {
    let d = d.abs();
    if d == 0.0 {
        return 0.0;
    }
    let b = quintic_profile_s(d, v, a);
    match cruise_profile_s(d, v, a) {
        Some(t) => t.min(b),
        None => b,
    }
}

/// Time (s) of one straight move from rest to rest: its leading axis' time.
pub fn move_time_s(from: &[f64; 6], to: &[f64; 6], axes: &[AxisSpec; 6]) -> f64 {
    (0..6)
        .map(|k| axis_time_s(to[k] - from[k], axes[k].speed_deg_s, axes[k].acceleration()))
        .fold(0.0, f64::max)
}

/// The leading axis of a move (0-based): the one needing the most time; ties to the lowest.
pub fn leading_axis(from: &[f64; 6], to: &[f64; 6], axes: &[AxisSpec; 6]) -> usize {
    let mut best = (0, -1.0);
    for k in 0..6 {
        let t = axis_time_s(to[k] - from[k], axes[k].speed_deg_s, axes[k].acceleration());
        if t > best.1 {
            best = (k, t);
        }
    }
    best.0
}

/// The profile a move's leading axis follows (module doc): ramp, cruise and ramp where that is
/// the faster, else one quintic.
pub fn move_profile(from: &[f64; 6], to: &[f64; 6], axes: &[AxisSpec; 6]) -> Profile {
    let k = leading_axis(from, to, axes);
    let (d, v, a) = (
        (to[k] - from[k]).abs(),
        axes[k].speed_deg_s,
        axes[k].acceleration(),
    );
    match cruise_profile_s(d, v, a) {
        Some(t) if d > 0.0 && t <= quintic_profile_s(d, v, a) => Profile::Cruise {
            ramp_s: ramp_time_s(v, a),
        },
        _ => Profile::Quintic,
    }
}

/// The time stage: the manipulation time of every move of the route and their sum (s), each
/// move from rest to rest over all six axes of its waypoints, and each move's profile.
pub fn estimate(plan: &Plan, axes: &[AxisSpec; 6]) -> Estimate {
    let move_s: Vec<f64> = plan
        .waypoints
        .windows(2)
        .map(|w| move_time_s(&w[0].joints_deg, &w[1].joints_deg, axes))
        .collect();
    let move_profile = plan
        .waypoints
        .windows(2)
        .map(|w| move_profile(&w[0].joints_deg, &w[1].joints_deg, axes))
        .collect();
    Estimate {
        total_s: move_s.iter().sum(),
        move_s,
        move_profile,
    }
}

#[cfg(test)]
mod tests {
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
        assert!(
            axis_time_s(d_star - 1.0, v, a) < cruise_profile_s(d_star - 1.0, v, a).unwrap_or(0.0)
        );
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

    #[test]
    fn a_route_sums_its_moves_over_all_six_axes() {
        use crate::plan::{Method, Waypoint, WaypointKind};
        let w = |kind, joints_deg| Waypoint { kind, joints_deg };
        let plan = Plan {
            method: Method::Extensile,
            grid_deg: 1.0,
            waypoints: vec![
                w(WaypointKind::CellPoint(0), [0.0, 0.0, 0.0, 0.0, 30.0, 0.0]),
                w(
                    WaypointKind::Via { leg: 0, index: 1 },
                    [10.0, 0.0, 0.0, 0.0, 30.0, 0.0],
                ),
                w(
                    WaypointKind::CellPoint(1),
                    [10.0, 10.0, 0.0, 0.0, 30.0, 100.0],
                ),
            ],
            legs: Vec::new(),
            min_clearance: None,
            move_clearances: Vec::new(),
            estimate: None,
            zones: Vec::new(),
        };
        let mut axes = [axis(110.0, 515.625); 6];
        for a in axes.iter_mut().skip(3) {
            *a = axis(280.0, 1312.5);
        }
        // Move 1: axis 1, 10 deg: 0.334621 s. Move 2: axis 2 10 deg (0.334621 s) and axis 6
        // 100 deg (0.669643 s, above): 0.669643 s. Total 1.004264 s.
        let e = estimate(&plan, &axes);
        assert_eq!(e.move_s.len(), 2);
        assert!(close(e.move_s[0], 0.334621, 1e-6) && close(e.move_s[1], 0.669643, 1e-6));
        assert!(close(e.total_s, 1.004264, 1e-6));
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
}
