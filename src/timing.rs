//! Manipulation time of a planned route (paper section 5, Fig. 9; long: half of it is the tests
//! against hand-computed moves): the figure the paper uses, besides the number of moves, to
//! compare its three search methods; extended by the speeddata of each move and the fly-by at
//! zoned waypoints.
//!
//! A move from rest to rest: within a move each axis k covers D_k = |delta_k| degrees under its
//! maximum speed v_k and peak acceleration a_k (the controller file, `robot::controller`), and
//! all axes start and stop together: the axes need as long as their slowest axis (the *leading*
//! axis), and the others are slowed down (their profiles stretched in time) to finish with it.
//! All six axes count: axes 4..6 move only on a leg's last move and only when a cell point gives
//! its own wrist (see `plan`), but then they may lead. The route's time is the sum of its moves'
//! times, less what the fly-by saves (below).
//!
//! # The speeddata (beyond the paper)
//!
//! A move takes the longest of three times ([`move_time`]):
//!
//! 1. **the axes**: the leading axis' profile (below), as in the paper;
//! 2. **the TCP path** of length L (mm) at the speeddata's `v_tcp`;
//! 3. **the reorientation**, the total angle Θ (deg) the TCP frame turns along the move, at
//!    `v_ori`.
//!
//! Each of 2 and 3 is taken as one more "axis" of the move with the same profiles as an axis:
//! distance L (or Θ), speed `v_tcp` (or `v_ori`), and the acceleration the axes allow the move's
//! progress, min_k a_k / D_k (share of the move per s^2), times L (or Θ). So a TCP-limited move
//! takes L / v_tcp plus one ramp at that speed (never less than L / v_tcp: the TCP never runs
//! faster than `v_tcp` on average), its ramps are short at low speeds, and a move too short to
//! reach `v_tcp` is one quintic. The three times are continuous in the move, so is their maximum.
//! Ties go to the axes ([`Limit`] says which led, for the report).
//!
//! **The TCP path.** The module's moves are `MoveAbsJ`: every axis runs linearly from its start
//! to its end value, so the TCP runs along the forward kinematics of the straight joint move
//! (`Robot::tool0` through the tool's `tframe`; tool0, the flange centre, without a tool). L is
//! the length of the polyline through equally spaced samples of the move, Θ the sum of the
//! rotation angles between consecutive samples' TCP frames (the same for any `tframe` rotation).
//! The samples start at one per 4 degrees of the largest axis motion, at least 8 steps (rounded
//! up to a power of two), and the steps are halved until one halving changes L by at most
//! [`PATH_TOL_MM`] (0.1 mm) and Θ by at most [`ANGLE_TOL_DEG`] (0.01 deg), at most 2^14 steps
//! ([`tcp_path`]). A polyline never overestimates its curve, and for a smooth path the last
//! halving's change is about three times the error left, so L is within about 0.05 mm of the
//! path. Deterministic: the samples depend only on the move.
//!
//! **Speed names.** The speeddata of the move into waypoint k is `Plan::motion_into(k, points)`'s
//! (a cell point's own or `motion.speed`; a via's that of its leg's end point). A predefined name
//! (`v5` .. `v7000`, `vmax`, any case) has its values from [`crate::rapid_data`]; `vmax`'s
//! `v_tcp` is the robot's maximum TCP speed where the robot files give one (none do yet), else
//! the table's 5000 mm/s, which an IRB 1400 (about 2.1 m/s) never reaches: at `vmax` the axes
//! lead. A name RAPID does not predefine (speeddata declared on the controller) is unknown here:
//! those moves take the axes alone, and the load stage warns once per name
//! (`pipeline::Loaded::warnings`).
//!
//! # Fly-by (beyond the paper)
//!
//! A waypoint between two moves whose move in has a fly-by zone (`motion::is_stop_zone` false:
//! a predefined zone other than `fine`, or a zone name RAPID does not predefine) is flown
//! through; the first and the last waypoint always stop. The model: at a stop point every axis
//! ramps down to rest and up again; flying through, the robot keeps its speed instead. For one
//! limit of a move (an axis, the TCP path, the reorientation) on ramp-cruise-ramp with its own
//! time T_l and ramp r_l, stretched to the move's time t, holding the cruise speed instead of
//! the last ramp saves r_l t / (2 T_l) (a ramp covers half the distance cruising would); on one
//! quintic, holding its peak speed (15/8 of the mean) over the second half saves 7 t / 30. A
//! move's end saving e is the least over its limits (7 t / 30 where none cruises): every axis
//! must keep its pace, and the least is continuous in the move. A flown waypoint takes
//! min(e_in, e_out) off each of its two moves (the move in does not ramp down, the move out does
//! not ramp up: two cruising moves save one whole ramp between them); so a move is never
//! shorter than its distance at its peak speed throughout (2 e <= r for a cruise), the time
//! never exceeds the stop-point time, and it is strictly shorter when both moves move. The
//! model ignores the zone's size (z1 saves as much as z200) and the corner's direction change;
//! `docs/rapid.md` says what the controller does instead. A flown move keeps its profile's shape,
//! compressed in time (for the preview).
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
//! profiles (`docs/rapid.md`, "What the controller does that gen-rapid's time estimate does
//! not").

use crate::cell::Tool;
use crate::place::PlacedPoint;
use crate::plan::motion::is_stop_zone;
use crate::plan::{Estimate, Limit, Plan, Profile};
use crate::rapid_data::{self, SpeedData};
use crate::robot::{AxisSpec, Robot};
use nalgebra::Isometry3;

/// The sampled TCP path has converged when one more halving of the steps changes its length by
/// at most this (mm) ...
pub const PATH_TOL_MM: f64 = 0.1;
/// ... and its reorientation angle by at most this (deg).
pub const ANGLE_TOL_DEG: f64 = 0.01;
/// The fewest steps a move is sampled with (one more halving always follows).
const MIN_STEPS: usize = 8;
/// At most one step per this many degrees of the largest axis motion before the first check.
const FIRST_STEP_DEG: f64 = 4.0;
/// The most steps a move is sampled with (reached only by a path that never converges).
const MAX_STEPS: usize = 1 << 14;
/// Relative difference under which the TCP's or the reorientation's time counts as a tie with
/// the axes' (the axes then lead; the time is the larger either way).
const TIE: f64 = 1e-9;

/// What the time stage knows of the robot: its axes (speeds, accelerations), its forward
/// kinematics and the tool's TCP, and the `vmax` of this robot.
pub struct TimeModel<'a> {
    pub axes: &'a [AxisSpec; 6],
    pub robot: &'a Robot,
    /// The TCP in the flange (tool0) frame: the tool's `tframe`, identity without a tool.
    pub tframe: Isometry3<f64>,
    /// `vmax` for this robot: [`rapid_data::vmax_for`] the robot's maximum TCP speed where
    /// the robot files give one (none do yet), else the table's.
    pub vmax: SpeedData,
}

impl<'a> TimeModel<'a> {
    /// The model of `robot` (its controller's axes) carrying `tool` (tool0 without one).
    pub fn new(robot: &'a Robot, tool: Option<&Tool>) -> TimeModel<'a> {
        TimeModel {
            axes: &robot.controller.axes,
            robot,
            tframe: tool.map_or(Isometry3::identity(), |t| t.tframe.isometry()),
            vmax: rapid_data::predefined_speed("vmax")
                .unwrap_or(rapid_data::vmax_for(rapid_data::VMAX_GENERIC_V_TCP_MM_S)),
        }
    }

    /// The speeddata called `name`: a predefined one (with this robot's `vmax`), or `None` for a
    /// name RAPID does not predefine (data declared on the controller, unknown here).
    pub fn speed(&self, name: &str) -> Option<SpeedData> {
        if name.eq_ignore_ascii_case("vmax") {
            return Some(self.vmax);
        }
        rapid_data::predefined_speed(name)
    }

    /// The TCP in the robot's base frame at controller axis values `axes_deg`.
    pub fn tcp(&self, axes_deg: &[f64; 6]) -> Isometry3<f64> {
        self.robot.tool0(axes_deg) * self.tframe
    }
}

/// The TCP's path along a straight joint move, sampled (module doc, "The TCP path").
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TcpPath {
    /// Length of the TCP's path, mm.
    pub length_mm: f64,
    /// Total rotation angle of the TCP frame along the move, deg.
    pub angle_deg: f64,
    /// Steps of the polyline it was measured on.
    pub steps: usize,
}

fn lerp6(a: &[f64; 6], b: &[f64; 6], s: f64) -> [f64; 6] {
    std::array::from_fn(|k| a[k] + s * (b[k] - a[k]))
}

/// Length (mm) and summed rotation angle (deg) of a polyline of frames.
fn polyline(poses: &[Isometry3<f64>]) -> (f64, f64) {
    let mut length = 0.0;
    let mut angle = 0.0;
    for w in poses.windows(2) {
        length += (w[1].translation.vector - w[0].translation.vector).norm();
        // The angle of the relative rotation, 2 atan2(|v|, |w|): exact also for tiny steps.
        let q = w[0].rotation.inverse() * w[1].rotation;
        angle += 2.0 * q.imag().norm().atan2(q.w.abs());
    }
    (length, angle.to_degrees())
}

/// The TCP's path length and reorientation along the straight joint move `from` -> `to`, with
/// `tcp` the TCP frame at given axis values: the polyline through equally spaced samples of
/// the move, its steps halved until one halving changes the length by at most [`PATH_TOL_MM`]
/// and the angle by at most [`ANGLE_TOL_DEG`] (module doc). Deterministic: the samples depend
/// only on the move.
pub fn tcp_path(
    from: &[f64; 6],
    to: &[f64; 6],
    tcp: impl Fn(&[f64; 6]) -> Isometry3<f64>,
) -> TcpPath {
    let largest = (0..6).map(|k| (to[k] - from[k]).abs()).fold(0.0, f64::max);
    if largest == 0.0 {
        return TcpPath {
            length_mm: 0.0,
            angle_deg: 0.0,
            steps: 0,
        };
    }
    let at = |i: usize, n: usize| tcp(&lerp6(from, to, i as f64 / n as f64));
    let first = ((largest / FIRST_STEP_DEG).ceil() as usize).clamp(MIN_STEPS, MAX_STEPS / 2);
    let mut n = first.next_power_of_two();
    let mut poses: Vec<Isometry3<f64>> = (0..=n).map(|i| at(i, n)).collect();
    let (mut length, mut angle) = polyline(&poses);
    while n < MAX_STEPS {
        let finer_n = 2 * n;
        let mut finer = Vec::with_capacity(finer_n + 1);
        for (i, p) in poses.iter().enumerate().take(n) {
            finer.push(*p);
            finer.push(at(2 * i + 1, finer_n));
        }
        finer.push(poses[n]);
        let (l, a) = polyline(&finer);
        let converged = (l - length).abs() <= PATH_TOL_MM && (a - angle).abs() <= ANGLE_TOL_DEG;
        (poses, n, length, angle) = (finer, finer_n, l, a);
        if converged {
            break;
        }
    }
    TcpPath {
        length_mm: length,
        angle_deg: angle,
        steps: n,
    }
}

/// One move's time from rest to rest and what set it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveTime {
    /// The axes alone (the leading axis' profile), s.
    pub axis_s: f64,
    /// The TCP path at `v_tcp` with its ramps, s (0 without known speeddata).
    pub tcp_s: f64,
    /// The reorientation at `v_ori` with its ramps, s (0 without known speeddata).
    pub reorientation_s: f64,
    /// The longest of the three: the move from rest to rest, s.
    pub stop_s: f64,
    pub limit: Limit,
    /// The profile of the limit that leads (the leading axis', or the TCP path's or the
    /// reorientation's at the speeddata's speed).
    pub profile: Profile,
    /// What flying through one end of the move saves at most, s (module doc, "Fly-by").
    pub end_saving_s: f64,
    pub path: TcpPath,
}

/// One of the limits a move's time is the longest of: a distance covered from rest to rest at
/// most at a speed and an acceleration (an axis: degrees; the TCP path: mm; the reorientation:
/// degrees), with the paper's profiles.
#[derive(Clone, Copy, Debug)]
struct Course {
    d: f64,
    v: f64,
    a: f64,
}

impl Course {
    fn time_s(&self) -> f64 {
        axis_time_s(self.d, self.v, self.a)
    }

    /// The ramp of its ramp-cruise-ramp profile where that profile is the faster, else `None`
    /// (one quintic).
    fn cruise_ramp_s(&self) -> Option<f64> {
        match cruise_profile_s(self.d, self.v, self.a) {
            Some(t) if self.d > 0.0 && t <= quintic_profile_s(self.d, self.v, self.a) => {
                Some(ramp_time_s(self.v, self.a))
            }
            _ => None,
        }
    }
}

/// The time of the move `from` -> `to` from rest to rest under `speed` (`None`: a speeddata
/// that is not predefined; the axes alone): the longest of the axis-limited profile, the TCP
/// path at `v_tcp` and the reorientation at `v_ori`, each of the last two with the ramps the
/// axes allow it (module doc, "The speeddata").
pub fn move_time(
    from: &[f64; 6],
    to: &[f64; 6],
    model: &TimeModel,
    speed: Option<SpeedData>,
) -> MoveTime {
    let axis_s = move_time_s(from, to, model.axes);
    let path = match speed {
        Some(_) => tcp_path(from, to, |q| model.tcp(q)),
        None => TcpPath::default(),
    };
    let axes: Vec<Course> = (0..6)
        .map(|k| Course {
            d: (to[k] - from[k]).abs(),
            v: model.axes[k].speed_deg_s,
            a: model.axes[k].acceleration(),
        })
        .filter(|l| l.d > 0.0)
        .collect();
    // The least acceleration of the move's progress (share of the move per s^2) any axis allows.
    let progress_acceleration = axes.iter().map(|l| l.a / l.d).fold(f64::INFINITY, f64::min);
    // And the highest speed of the progress every axis allows: a TCP or turn course never runs
    // an axis over its speed (it leads only where it is slower than the axes).
    let progress_speed = axes.iter().map(|l| l.v / l.d).fold(f64::INFINITY, f64::min);
    let along = |d: f64, v: f64| Course {
        d,
        v: v.min(progress_speed * d),
        a: progress_acceleration * d,
    };
    let (tcp, reorientation) = match speed {
        Some(s) if s.v_tcp_mm_s > 0.0 && s.v_ori_deg_s > 0.0 && !axes.is_empty() => (
            (path.length_mm > 0.0).then(|| along(path.length_mm, s.v_tcp_mm_s)),
            (path.angle_deg > 0.0).then(|| along(path.angle_deg, s.v_ori_deg_s)),
        ),
        _ => (None, None),
    };
    let tcp_s = tcp.map_or(0.0, |l| l.time_s());
    let reorientation_s = reorientation.map_or(0.0, |l| l.time_s());
    let speed_lead = if tcp_s >= reorientation_s {
        tcp.map(|l| (tcp_s, Limit::Tcp, l))
    } else {
        reorientation.map(|l| (reorientation_s, Limit::Reorientation, l))
    };
    // Ties go to the axes, also where rounding puts the other a hair above them: where the
    // axis that accelerates least is on one quintic at its acceleration bound, a short TCP path
    // or turn is on the same quintic (the same time, up to rounding).
    let (stop_s, limit, profile) = match speed_lead {
        Some((t, limit, course)) if t > axis_s * (1.0 + TIE) => (
            t,
            limit,
            match course.cruise_ramp_s() {
                Some(ramp_s) => Profile::Cruise { ramp_s },
                None => Profile::Quintic,
            },
        ),
        _ => (
            axis_s.max(tcp_s).max(reorientation_s),
            Limit::Axis,
            move_profile(from, to, model.axes),
        ),
    };
    // What flying through one end saves: the least over the limits (module doc, "Fly-by").
    let mut end_saving_s = 7.0 * stop_s / 30.0;
    for course in axes.iter().chain(tcp.iter()).chain(reorientation.iter()) {
        if let Some(ramp_s) = course.cruise_ramp_s() {
            end_saving_s = end_saving_s.min(ramp_s * stop_s / (2.0 * course.time_s()));
        }
    }
    MoveTime {
        axis_s,
        tcp_s,
        reorientation_s,
        stop_s,
        limit,
        profile,
        end_saving_s,
        path,
    }
}

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

/// The time stage: every move's time and profile and their sum (s). Move `i` runs into waypoint
/// `i + 1` with the speeddata of `plan.motion_into(i + 1, points)`; a waypoint between two moves
/// whose move in has a fly-by zone is flown through (module doc, "Fly-by"); the first and the
/// last waypoint are stop points. `points` are the placed points the plan was made from.
pub fn estimate(plan: &Plan, points: &[PlacedPoint], model: &TimeModel) -> Estimate {
    let n = plan.moves();
    let stops: Vec<MoveTime> = (0..n)
        .map(|i| {
            let speed = model.speed(&plan.motion_into(i + 1, points).speed);
            move_time(
                &plan.waypoints[i].joints_deg,
                &plan.waypoints[i + 1].joints_deg,
                model,
                speed,
            )
        })
        .collect();
    // The time saved at each waypoint (0 at a stop point, the first and the last).
    let saved: Vec<f64> = (0..=n)
        .map(|k| {
            if k == 0 || k >= n || is_stop_zone(&plan.motion_into(k, points).zone) {
                0.0
            } else {
                stops[k - 1].end_saving_s.min(stops[k].end_saving_s)
            }
        })
        .collect();
    let move_s: Vec<f64> = (0..n)
        .map(|i| (stops[i].stop_s - saved[i] - saved[i + 1]).max(0.0))
        .collect();
    // A flown move keeps its profile's shape, compressed to its shorter time.
    let move_profile = (0..n)
        .map(|i| match stops[i].profile {
            Profile::Cruise { ramp_s } if stops[i].stop_s > 0.0 => Profile::Cruise {
                ramp_s: ramp_s * move_s[i] / stops[i].stop_s,
            },
            p => p,
        })
        .collect();
    Estimate {
        total_s: move_s.iter().sum(),
        move_s,
        move_profile,
        move_limit: stops.iter().map(|m| m.limit).collect(),
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

    use crate::cell::{Frame, Loc};
    use crate::plan::{Method, Waypoint, WaypointKind};

    fn point(speed: &str, zone: &str) -> PlacedPoint {
        crate::plan::motion::point_with_motion("P", speed, zone)
    }

    /// A plan through `joints`: the first and last cell points 0 and 1, vias of leg 0 between.
    fn plan_of(joints: &[[f64; 6]]) -> Plan {
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
        Plan {
            method: Method::Extensile,
            grid_deg: 1.0,
            waypoints,
            legs: Vec::new(),
            min_clearance: None,
            move_clearances: Vec::new(),
            estimate: None,
            paper: None,
            zones: Vec::new(),
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
        let e = estimate(&plan, &points, &model);
        assert_eq!(e.move_s.len(), 2);
        assert!(close(e.move_s[0], 0.334621, 1e-6) && close(e.move_s[1], 0.669643, 1e-6));
        assert!(close(e.total_s, 1.004264, 1e-6));
        assert_eq!(e.move_limit, [Limit::Axis, Limit::Axis]);
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
            estimate(&plan, &points, &model)
        };
        let fine = timed("fine");
        // The vias stop (`motion_into` gives them `fine`) and the last point always stops,
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
            fine.move_s,
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
            estimate(&plan, &points, &model).total_s
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
        let total = |plan: &Plan, zone: &str| {
            let points = [
                point("v300", "fine"),
                point("v300", zone),
                point("v300", "fine"),
            ];
            estimate(plan, &points, &model).total_s
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
}
