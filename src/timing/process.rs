//! The time of a process move: a `MoveL` line or a `MoveC` arc (seams, approach and retract
//! lines) followed by the continuing inverse kinematics (`robot::ik::follow`). Beside the
//! joint-move estimate of `timing` (a `MoveAbsJ`'s straight joint move, `timing::move_time`),
//! sharing its rule of three limits (`timing::limits`): the time stage calls
//! [`process_move_time`] for process moves and adds `WaitTime`'s seconds as they are written.
//!
//! # The yardstick
//! A process move's TCP runs along its path at the speeddata's `v_tcp`, no faster than its axes
//! allow. The yardstick is the larger of
//! 1. the path length `L` over `v_tcp`, and
//! 2. the rest-to-rest time of the axis that needs longest for its travel summed along the
//!    path (`D_k = sum |dq_k|` over the follower's chords: an axis that turns back and forth
//!    covers both ways), at its own speed and acceleration (`timing::axis_time_s`, the paper's
//!    profiles),
//!
//! and the reorientation `Theta` over `v_ori` is a third term, as in the joint-move estimate
//! (it leads only on a path that mostly turns the tool). [`ProcessTime::yardstick_s`] is that
//! larger value without ramps.
//!
//! # The ramps
//! As in the joint-move estimate (`timing`, "The speeddata"), the TCP path and the
//! reorientation are each one more "axis" of the move with the axes' profiles: distance `L`
//! (or `Theta`), speed `v_tcp` (or `v_ori`) but no more than the progress every axis allows
//! (`min_k v_k / D_k` of the path, times `L`), and the acceleration the axes allow the
//! progress, `min_k a_k / D_k`, times `L`. So a TCP-limited move takes `L / v_tcp` plus one
//! ramp at that speed, a move too short to reach `v_tcp` is one quintic, and the time is never
//! below the yardstick. The move's time is the longest of the three (ties to the axes), with
//! the profile of the limit that leads, and what flying through one end saves at most, by the
//! same rule as the joint moves' (`timing`, "Fly-by"), for a zone between consecutive process
//! moves.
//!
//! The speeds an axis needs at points of the path (where the programmed `v_tcp` asks an axis for
//! more than its maximum and the controller slows down) are the follower's
//! (`FollowedPath::speed_excess`): this estimate spreads the travel over the path and does not
//! add that local slowing.

use super::{limits, Course};
use crate::plan::motion::{Limit, Profile};
use crate::rapid_data::SpeedData;
use crate::robot::ik::follow::FollowedPath;
use crate::robot::AxisSpec;

/// A process move's time from rest to rest, and what set it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProcessTime {
    /// The axes alone: the longest rest-to-rest time of an axis over its summed travel, s.
    pub axis_s: f64,
    /// The path at `v_tcp` with its ramps, s (0 without known speeddata).
    pub tcp_s: f64,
    /// The reorientation at `v_ori` with its ramps, s (0 without known speeddata).
    pub reorientation_s: f64,
    /// The longest of the three: the move from rest to rest, s.
    pub stop_s: f64,
    /// The larger of `L / v_tcp` and `axis_s` (module docs), s.
    pub yardstick_s: f64,
    pub limit: Limit,
    /// The profile of the limit that leads.
    pub profile: Profile,
    /// What flying through one end of the move saves at most, s (as `timing`'s fly-by).
    pub end_saving_s: f64,
    /// Each axis's travel summed along the path, deg.
    pub travel_deg: [f64; 6],
}

/// The time of a followed process move at `speed` (`None`: a speeddata that is not predefined;
/// the axes alone), on the robot's `axes` (module docs).
pub fn process_move_time(
    followed: &FollowedPath,
    axes: &[AxisSpec; 6],
    speed: Option<SpeedData>,
) -> ProcessTime {
    let path = followed.path();
    process_time(
        path.length_mm(),
        path.turn_deg(),
        followed.axis_travel_deg(),
        axes,
        speed,
    )
}

/// [`process_move_time`] from the path's length (mm), the tool's total turn (deg) and each
/// axis's summed travel (deg).
pub fn process_time(
    length_mm: f64,
    turn_deg: f64,
    travel_deg: [f64; 6],
    axes: &[AxisSpec; 6],
    speed: Option<SpeedData>,
) -> ProcessTime {
    let courses: Vec<Course> = (0..6)
        .map(|k| Course {
            d: travel_deg[k].abs(),
            v: axes[k].speed_deg_s,
            a: axes[k].acceleration(),
        })
        .filter(|c| c.d > 0.0)
        .collect();
    // The axis that needs longest (ties to the first) and its profile.
    let lead = courses
        .iter()
        .copied()
        .fold(None::<Course>, |best, c| match best {
            Some(b) if b.time_s() >= c.time_s() => Some(b),
            _ => Some(c),
        });
    let axis_s = lead.map_or(0.0, |c| c.time_s());
    let axis_profile = match lead.and_then(|c| c.cruise_ramp_s()) {
        Some(ramp_s) => Profile::Cruise { ramp_s },
        None => Profile::Quintic,
    };
    let l = limits(&courses, axis_s, axis_profile, length_mm, turn_deg, speed);
    let by_tcp = match speed {
        Some(s) if s.v_tcp_mm_s > 0.0 => length_mm / s.v_tcp_mm_s,
        _ => 0.0,
    };
    ProcessTime {
        axis_s: l.axis_s,
        tcp_s: l.tcp_s,
        reorientation_s: l.reorientation_s,
        stop_s: l.stop_s,
        yardstick_s: by_tcp.max(l.axis_s),
        limit: l.limit,
        profile: l.profile,
        end_saving_s: l.end_saving_s,
        travel_deg: travel_deg.map(f64::abs),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rapid_data::predefined_speed;
    use crate::robot::ik::follow::testing::example_followed;
    use crate::robot::Robot;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    fn irb_axes() -> [AxisSpec; 6] {
        Robot::irb1400().controller.axes
    }

    const TRAVEL: [f64; 6] = [10.0, 20.0, 5.0, 3.0, 8.0, 6.0];

    /// Hand-computed: a 350 mm seam at v50 on the IRB 1400 (110 deg/s and 515.625 deg/s^2 on
    /// axes 1-3, 280 and 1312.5 on 4-6) whose axis 2 travels most, 20 deg. The progress may
    /// accelerate at min_k a_k / D_k = 515.625 / 20 = 25.78 /s^2, so the TCP at
    /// 25.78 * 350 = 9023.4 mm/s^2: ramp 15 * 50 / (8 * 9023.4) = 0.010390 s, time
    /// 350 / 50 + 0.010390 = 7.010390 s (cruising: 350 mm >= 50 * 0.01039). Axis 2 alone: 20 deg
    /// cannot cruise (110 * 0.4 = 44 deg of ramps), one quintic: max(15 * 20 / (8 * 110),
    /// sqrt(10 * 20 / (sqrt 3 * 515.625))) = max(0.3409, 0.473225) = 0.473225 s. The TCP leads.
    #[test]
    fn a_slow_seam_takes_its_length_over_the_tcp_speed_plus_a_ramp() {
        let t = process_time(350.0, 0.0, TRAVEL, &irb_axes(), predefined_speed("v50"));
        assert!(close(t.axis_s, 0.473_225, 1e-6), "{t:?}");
        assert!(close(t.tcp_s, 7.010_390, 1e-6), "{t:?}");
        assert!(close(t.stop_s, t.tcp_s, 0.0));
        assert_eq!(t.limit, Limit::Tcp);
        match t.profile {
            Profile::Cruise { ramp_s } => assert!(close(ramp_s, 0.010_390, 1e-6)),
            p => panic!("{p:?}"),
        }
        assert!(close(t.yardstick_s, 7.0, 1e-12));
        assert!(t.stop_s >= t.yardstick_s);
    }

    /// Hand-computed: the same seam at v7000. The TCP may run no faster than the progress every
    /// axis allows, min_k v_k / D_k = 110 / 20 = 5.5 /s, so 1925 mm/s; its ramp would be
    /// 15 * 1925 / (8 * 9023.4) = 0.4 s covering 770 mm of ramps > 350: one quintic,
    /// max(15 * 350 / (8 * 1925), sqrt(10 * 350 / (sqrt 3 * 9023.4))) = 0.4733 s, axis 2's own
    /// time: a tie, the axes lead. The yardstick: max(350 / 7000, 0.4733).
    #[test]
    fn a_fast_seam_takes_the_axes_time() {
        let t = process_time(350.0, 0.0, TRAVEL, &irb_axes(), predefined_speed("v7000"));
        assert_eq!(t.limit, Limit::Axis, "{t:?}");
        assert!(close(t.stop_s, 0.473_225, 1e-6), "{t:?}");
        assert!(close(t.tcp_s, t.axis_s, 1e-9), "{t:?}");
        assert_eq!(t.profile, Profile::Quintic);
        assert!(close(t.yardstick_s, t.axis_s, 0.0));
        // Without a known speeddata, the axes alone.
        let none = process_time(350.0, 0.0, TRAVEL, &irb_axes(), None);
        assert_eq!(
            (none.stop_s, none.tcp_s, none.limit),
            (t.axis_s, 0.0, Limit::Axis)
        );
    }

    /// Over random paths and speeds: never below the yardstick, longer paths and more travel
    /// never take less time, and slower speeds never less.
    #[test]
    fn the_time_is_at_least_the_yardstick_and_grows_with_the_path() {
        let axes = irb_axes();
        let mut rng = crate::geometry::testing::Rng(5);
        for _ in 0..500 {
            let travel: [f64; 6] = std::array::from_fn(|_| rng.range(0.0, 60.0));
            let (l, turn) = (rng.range(1.0, 800.0), rng.range(0.0, 90.0));
            let v =
                predefined_speed(["v5", "v50", "v200", "v1000", "v5000"][rng.below(5) as usize]);
            let t = process_time(l, turn, travel, &axes, v);
            assert!(t.stop_s >= t.yardstick_s * (1.0 - 1e-12), "{t:?}");
            let longer = process_time(l * 1.1, turn, travel, &axes, v);
            assert!(longer.stop_s >= t.stop_s * (1.0 - 1e-12));
            let more: [f64; 6] = std::array::from_fn(|k| travel[k] * 1.2);
            assert!(process_time(l, turn, more, &axes, v).stop_s >= t.stop_s * (1.0 - 1e-12));
            let slower = process_time(l, turn, travel, &axes, predefined_speed("v5"));
            assert!(slower.stop_s >= t.stop_s * (1.0 - 1e-12));
            assert!(t.end_saving_s >= 0.0 && t.end_saving_s <= 0.5 * t.stop_s);
        }
    }

    /// The example seams and descents: the travel is the joints' changes summed over the
    /// samples, and at the cells' speeds (v50 seams, v100 descents) the TCP leads.
    #[test]
    fn the_example_lines_are_timed_by_their_tcp_speed() {
        let axes = irb_axes();
        for (name, _, f) in example_followed() {
            let speed = if name.starts_with('L') || name.starts_with('R') {
                "v50"
            } else {
                "v100"
            };
            let v = predefined_speed(speed).expect("predefined");
            let t = process_move_time(&f, &axes, Some(v));
            let mut travel = [0.0; 6];
            for w in f.samples().windows(2) {
                for (k, x) in travel.iter_mut().enumerate() {
                    *x += (w[1].joints_deg[k] - w[0].joints_deg[k]).abs();
                }
            }
            assert_eq!(t.travel_deg, travel, "{name}");
            assert_eq!(t.limit, Limit::Tcp, "{name}: {t:?}");
            let by_speed = f.path().length_mm() / v.v_tcp_mm_s;
            assert!(
                t.stop_s > by_speed && t.stop_s < by_speed + 0.1,
                "{name}: {t:?}"
            );
        }
    }
}
