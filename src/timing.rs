//! Manipulation time of a planned route (paper section 5, Fig. 9): the figure the paper uses,
//! besides the number of moves, to compare its three search methods; extended by the speeddata
//! of each move and the fly-by at zoned waypoints.
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
//! **Speed names.** The speeddata of the move into waypoint k is the one its motion names
//! (`plan::motion`: a cell point's own or `motion.speed`; a via's that of its leg's end point).
//! A predefined name
//! (`v5` .. `v7000`, `vmax`, any case) has its values from [`crate::rapid_data`]; `vmax`'s
//! `v_tcp` is the robot's maximum TCP speed where the robot files give one (none do yet), else
//! the table's 5000 mm/s, which an IRB 1400 (about 2.1 m/s) never reaches: at `vmax` the axes
//! lead. A name RAPID does not predefine (speeddata declared on the controller) is unknown here:
//! those moves take the axes alone, and the run warns once per name, right after loading
//! ([`speed_warnings`]: what this stage cannot estimate).
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
//!
//! A process move (a `MoveL` line or `MoveC` arc the controller runs along its path) has its own
//! time, [`process::process_move_time`], by the same three limits ([`limits`]).

pub mod process;

use crate::cell::{Cell, Tool};
use crate::excerpt;
use crate::place::MoveMotion;
use crate::plan::motion::{is_stop_zone, Estimate, Limit, MoveEstimate, Profile};
use crate::plan::Route;
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
pub(crate) struct Course {
    pub(crate) d: f64,
    pub(crate) v: f64,
    pub(crate) a: f64,
}

impl Course {
    pub(crate) fn time_s(&self) -> f64 {
        axis_time_s(self.d, self.v, self.a)
    }

    /// The ramp of its ramp-cruise-ramp profile where that profile is the faster, else `None`
    /// (one quintic).
    pub(crate) fn cruise_ramp_s(&self) -> Option<f64> {
        match cruise_profile_s(self.d, self.v, self.a) {
            Some(t) if self.d > 0.0 && t <= quintic_profile_s(self.d, self.v, self.a) => {
                Some(ramp_time_s(self.v, self.a))
            }
            _ => None,
        }
    }
}

/// What the three limits of a move give (module doc, "The speeddata"): each one's time, the
/// longest, which led and its profile, and the fly-by saving at one end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Limits {
    pub(crate) axis_s: f64,
    pub(crate) tcp_s: f64,
    pub(crate) reorientation_s: f64,
    pub(crate) stop_s: f64,
    pub(crate) limit: Limit,
    pub(crate) profile: Profile,
    pub(crate) end_saving_s: f64,
}

/// The longest of the axes (`axes`: each axis's course, those that move; `axis_s` their
/// longest time and `axis_profile` its profile), the TCP path of `length_mm` at `v_tcp` and the
/// reorientation of `turn_deg` at `v_ori` under `speed` (`None`: the axes alone), each of the
/// last two with the ramps the axes allow it; ties to the axes (module doc, "The speeddata";
/// the fly-by saving, "Fly-by"). Shared with the process moves' time (`process_time`), whose
/// axes' distances are their travel summed along the path.
pub(crate) fn limits(
    axes: &[Course],
    axis_s: f64,
    axis_profile: Profile,
    length_mm: f64,
    turn_deg: f64,
    speed: Option<SpeedData>,
) -> Limits {
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
            (length_mm > 0.0).then(|| along(length_mm, s.v_tcp_mm_s)),
            (turn_deg > 0.0).then(|| along(turn_deg, s.v_ori_deg_s)),
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
            axis_profile,
        ),
    };
    // What flying through one end saves: the least over the limits (module doc, "Fly-by").
    let mut end_saving_s = 7.0 * stop_s / 30.0;
    for course in axes.iter().chain(tcp.iter()).chain(reorientation.iter()) {
        if let Some(ramp_s) = course.cruise_ramp_s() {
            end_saving_s = end_saving_s.min(ramp_s * stop_s / (2.0 * course.time_s()));
        }
    }
    Limits {
        axis_s,
        tcp_s,
        reorientation_s,
        stop_s,
        limit,
        profile,
        end_saving_s,
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
    let l = limits(
        &axes,
        move_time_s(from, to, model.axes),
        move_profile(from, to, model.axes),
        path.length_mm,
        path.angle_deg,
        speed,
    );
    MoveTime {
        axis_s: l.axis_s,
        tcp_s: l.tcp_s,
        reorientation_s: l.reorientation_s,
        stop_s: l.stop_s,
        limit: l.limit,
        profile: l.profile,
        end_saving_s: l.end_saving_s,
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

/// The time stage: every move's time, profile and limit, and their sum (s). Move `i` runs into
/// waypoint `i + 1` with the speeddata of `motions[i + 1]`; a waypoint between two moves whose
/// move in has a fly-by zone is flown through (module doc, "Fly-by"); the first and the last
/// waypoint are stop points. `motions` holds the speed and zone of the move into each waypoint
/// of `route` (`plan::motion`).
pub fn estimate(route: &Route, motions: &[MoveMotion], model: &TimeModel) -> Estimate {
    let n = route.moves();
    let motion = |k: usize| motions.get(k);
    let stops: Vec<MoveTime> = (0..n)
        .map(|i| {
            let speed = motion(i + 1).and_then(|m| model.speed(&m.speed));
            move_time(
                &route.waypoints[i].joints_deg,
                &route.waypoints[i + 1].joints_deg,
                model,
                speed,
            )
        })
        .collect();
    // The time saved at each waypoint (0 at a stop point, the first and the last).
    let saved: Vec<f64> = (0..=n)
        .map(|k| {
            if k == 0 || k >= n || motion(k).is_none_or(|m| is_stop_zone(&m.zone)) {
                0.0
            } else {
                stops[k - 1].end_saving_s.min(stops[k].end_saving_s)
            }
        })
        .collect();
    let moves: Vec<MoveEstimate> = (0..n)
        .map(|i| {
            let stop = &stops[i];
            let time_s = (stop.stop_s - saved[i] - saved[i + 1]).max(0.0);
            // A flown move keeps its profile's shape, compressed to its shorter time.
            let profile = match stop.profile {
                Profile::Cruise { ramp_s } if stop.stop_s > 0.0 => Profile::Cruise {
                    ramp_s: ramp_s * time_s / stop.stop_s,
                },
                p => p,
            };
            MoveEstimate {
                time_s,
                profile,
                limit: stop.limit,
            }
        })
        .collect();
    Estimate {
        total_s: moves.iter().map(|m| m.time_s).sum(),
        moves,
    }
}

/// What this stage cannot estimate, as warnings for stderr: the speeddata names the cell's
/// moves use (each point's own, else `motion.speed`) that RAPID does not predefine, each once
/// (ignoring case, in the cell's order). Their values are declared on the controller, not known
/// here, so the estimate takes those moves at full axis speed (module doc, "Speed names").
pub fn speed_warnings(cell: &Cell) -> Vec<String> {
    let mut seen: Vec<String> = Vec::new();
    for p in &cell.points {
        let name = p.speed.as_deref().unwrap_or(&cell.motion.speed);
        let known = rapid_data::predefined_speed(name).is_some();
        if !known && !seen.iter().any(|s| s.eq_ignore_ascii_case(name)) {
            seen.push(name.to_string());
        }
    }
    seen.iter()
        .map(|name| {
            excerpt::message(&format!(
                "warning: speed '{}' is not a predefined speeddata: the estimated time takes the moves that use it at full axis speed (its v_tcp and v_ori are declared on the controller, not known here)",
                excerpt::value(name)
            ))
            .into_owned()
        })
        .collect()
}

#[cfg(test)]
mod tests;
