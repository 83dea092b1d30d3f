//! Following a TCP path with the inverse kinematics that continues (long: the follower's
//! contract, its refusals and its speeds are one idea): the joints a controller runs along a
//! `MoveL` line or a `MoveC` arc ([`CartesianPath`]), from the configuration the move starts in.
//!
//! Stage: a path in the cell frame + the start joints -> [`FollowedPath`] (joint samples along
//! the path, and per chord between two samples a proven bound on how far the controller's
//! joints stray from the straight joint chord), or a [`FollowError`] that says where (progress
//! in percent and the TCP position) and why. Beyond the paper, which plans joint moves only.
//!
//! # The continuing solution
//! At every progress `s` the controller's joints are the inverse kinematics of the path's pose
//! on the branch that continues from the joints just before ([`SixAxisIk::continuing`]): of the
//! pose's branches (arm stance, elbow, wrist flip), each axis turned by whole turns to lie
//! nearest the previous joints (so axes 4 and 6 keep counting their turns: 179 deg goes on to
//! 181, not to -179; no range applied), the branch nearest the previous joints on every axis
//! (the largest axis difference, then the solver's fixed order). Far from singular poses the
//! branches of a pose lie tens of degrees apart or more, so with steps of at most
//! [`MAX_PROBE_STEP_DEG`] the nearest branch is the one that continues; the deviation bound
//! (below) proves it of every sample.
//!
//! # Samples and chords
//! The path is cut into chords `[s0, s1]` with adaptive steps. On each, the continuing solution
//! is taken at four probes `s0 + h j / 4` (`j` = 1..4, each continuing from the one before):
//! they locate a jump, a range exit or the wrist singularity, and the last is the chord's end
//! sample. A chord is refined (halved) where its deviation bound (below) exceeds the tolerance,
//! [`DEVIATION_TOL_DEG`], where the bound cannot be had, or where a probe moves an axis more
//! than [`MAX_PROBE_STEP_DEG`]; accepted chords double the next step where the bound is under
//! a quarter of the tolerance.
//!
//! # The deviation bound
//! Per chord and axis, a bound `delta` on how far the controller's joints stray from the
//! straight joint chord `q0 -> q1` between the two samples, proven as follows.
//!
//! *What the controller runs (the one assumption).* The controller's joints along the path are
//! the continuous solution of the inverse kinematics of the path's pose ([`CartesianPath`]'s
//! formula: the position on the line or the circle, the orientation slerped) that starts at the
//! start joints. Of the closed form's eight branches (`six::Signs`: arm stance, elbow, wrist
//! flip), that is the one whose solution of the start pose is the start joints
//! (`start_branch`: the start pose is the forward kinematics of the start joints, so they agree
//! to rounding, `e_0` below), for as long as no two branches meet; and two meet only where the
//! branch's closed form has a singular step, which every enclosure below excludes.
//!
//! *Enclosures.* On an interval `S` of progress, `six::enclose` evaluates that branch's closed
//! form in interval arithmetic with derivatives (`ik::interval`, outward rounding): per axis an
//! interval `[a, b]` holding `dq/ds` at every `s` in `S`, and, at a point, an interval holding
//! the axis value modulo a full turn. It gives nothing where a step may be singular on `S` (the
//! wrist centre on the axis-1 line, the elbow stretched or folded, axis 5 at 0); there the
//! chord is refined, and at the smallest step refused as a jump.
//!
//! *The end sample.* With `q0` within `e0` of the controller's joints at `s0` (`e0` from the
//! chord before; at the start from `start_branch`), the controller's axis at `s1` lies in
//! `q0 +- e0 + h [a, b]` (mean value theorem, `h = s1 - s0`) and, up to full turns, in the
//! branch's value at `s1`. Where the first interval is narrower than a half turn these meet in
//! one interval, which holds the controller's axis; `e1` is how far `q1` (the probe) may lie
//! from it. A probe on another branch, or a turn off, gives a large `e1` and the chord is
//! refined: the samples are the controller's joints, within `e1`, not only the nearest branch.
//!
//! *Between the samples.* Let `m = (q1 - q0) / h` (the chord's slope) and `g(s) = q(s) - q0 -
//! (s - s0) m` the deviation of the controller's axis `q` from the chord. Then `|g(s0)| <= e0`,
//! `|g(s1)| <= e1` and `g' = q' - m` lies in `[a - m, b - m]`, so with `A = m - a`,
//! `B = b - m` (taken as 0 when negative):
//!
//! ```text
//! g(s) <= e0 + (s - s0) B   and   g(s) <= e1 + (s1 - s) A     (and the same for -g, A and B
//! |g(s)| <= max(e0, e1) + h A B / (A + B)  =: delta               swapped)
//! ```
//!
//! the minimum of the two lines being largest where they cross. `h A B / (A + B)` is at most
//! `h (b - a) / 4`: second order in `h`, since `b - a` shrinks with `S` (about `h max |q''|`
//! times the enclosure's overestimate). Every step of it is computed in interval arithmetic and
//! rounded up. The tests hold `delta` against the continuing solution sampled densely along
//! every chord of the shipped process cells and of random lines and arcs, and show a joint path
//! with a narrow bump between the probes that an estimate from the probes' second differences
//! misses and this bound does not.
//!
//! # What is refused, and where
//! Each is located by refining down to a step of [`MIN_STEP`] (of the progress) at the place it
//! happens, and reported there:
//! - a pose out of the arm's reach ([`FollowError::Unreachable`]; where the joints bend too
//!   fast to follow at the smallest step and the reach ends within [`REACH_AHEAD`] after, the
//!   arm stretching to its limit, the end of the reach is what is reported);
//! - an axis leaving its range, the coupled axis-3 range of a parallelogram arm included
//!   ([`FollowError::Range`]): at every probe exactly; between samples, the chord's axis values
//!   widened by `delta` must lie in range (within [`RANGE_SLACK_DEG`]; the ranges are convex, so
//!   the chord's extremes are at its ends);
//! - a configuration change or axis jump ([`FollowError::Jump`]): the continuing solution jumps,
//!   seen as a chord that cannot be refined below the tolerance (or a probe step over
//!   [`MAX_PROBE_STEP_DEG`]) at the smallest step: the joints change far beyond what the TCP's
//!   motion there allows;
//! - passing within [`WRIST_SINGULARITY_DEG`] of the wrist singularity, axis 5 = 0
//!   ([`FollowError::WristSingularity`]): `|axis 5|` at every probe, and widened by `delta`
//!   between, with no change of sign on a chord;
//! - ending in another configuration than the end target's confdata, when one is asked
//!   ([`FollowError::EndConf`]; admission as the inverse kinematics chooses,
//!   [`SixAxisIk::conf_admits`]).
//!
//! The start joints must put the TCP on the path's start (within [`START_TOL_MM`] and
//! [`START_TOL_DEG`]: a caller builds the path from the forward kinematics of the joints the
//! move starts from, as the controller does). A path takes at most [`MAX_CHORDS`] chords
//! (a budget: refining never runs away).
//!
//! # Axis speeds
//! At a speeddata the controller runs the path in `T = max(L / v_tcp, Theta / v_ori)` (length
//! `L`, total turn `Theta`; ramps aside), so the progress runs at `1 / T` and an axis needs
//! `|dq / ds| / T`. [`FollowedPath::axis_speeds_deg_s`] gives it per sample from the chords on
//! either side (the faster), [`FollowedPath::speed_excess`] the sample where the programmed
//! speed needs an axis most beyond its maximum: there the controller slows down.
//!
//! Same input, same output: the steps depend on the path and the start joints only.

use super::interval::Interval;
use super::six::{
    describe_violation, ConfData, Enclosure, PoseForm, Signs, SixAxisError, SixAxisIk,
};
use crate::geometry::path::CartesianPath;
use crate::rapid_data::SpeedData;
use crate::robot::{Axes6, AxisSpec, RangeViolation, Robot};
use nalgebra::{Isometry3, Point3};
use std::fmt;

/// The deviation bound asked of every chord, deg (per axis).
pub const DEVIATION_TOL_DEG: f64 = 0.005;
/// `|axis 5|` must stay at least this far from the wrist singularity, deg.
pub const WRIST_SINGULARITY_DEG: f64 = 1.0;
/// The start joints must put the TCP this close to the path's start, mm ...
pub const START_TOL_MM: f64 = 0.1;
/// ... and turned this close, deg.
pub const START_TOL_DEG: f64 = 0.01;
/// The most a probe may move an axis from the probe before it, deg: the step at which the
/// nearest branch is the continuing one (module docs).
pub const MAX_PROBE_STEP_DEG: f64 = 1.0;
/// How far a chord widened by its bound may pass a limit (rounding), deg.
pub const RANGE_SLACK_DEG: f64 = 1e-6;
/// The smallest step (of the progress) a chord is refined to before a refusal.
pub const MIN_STEP: f64 = 1e-7;
/// The most chords a path may take.
pub const MAX_CHORDS: usize = 100_000;
/// How far past a jump found at the smallest step the follower looks for the end of the reach
/// (of the progress; module docs).
pub const REACH_AHEAD: f64 = 1e-3;
/// The first step tried (of the progress).
const FIRST_STEP: f64 = 1.0 / 16.0;

/// Where the path is run: the robot base frame in the cell frame, and the tool's TCP in the
/// flange (tool0) frame (`tframe`; identity for tool0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TcpFrames {
    pub cell_from_robot: Isometry3<f64>,
    pub tframe: Isometry3<f64>,
}

/// What the follower asks of a path (the defaults are the module's constants; tests may
/// loosen or tighten them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FollowSettings {
    /// The deviation bound every chord is refined to, deg.
    pub deviation_tol_deg: f64,
    /// `|axis 5|` kept from the wrist singularity, deg.
    pub wrist_singularity_deg: f64,
}

impl Default for FollowSettings {
    fn default() -> FollowSettings {
        FollowSettings {
            deviation_tol_deg: DEVIATION_TOL_DEG,
            wrist_singularity_deg: WRIST_SINGULARITY_DEG,
        }
    }
}

/// A place on the path: the progress (percent) and the TCP position there (cell frame, mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Where {
    pub progress_pct: f64,
    pub tcp_mm: [f64; 3],
}

impl fmt::Display for Where {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let p = self.tcp_mm;
        write!(
            f,
            "at {:.1} % of the path (TCP at ({:.1}, {:.1}, {:.1}) mm)",
            self.progress_pct, p[0], p[1], p[2]
        )
    }
}

/// Why a path cannot be followed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FollowError {
    #[error(
        "the joints the move starts from put the TCP {mm:.3} mm and {deg:.4} deg from the \
         path's start"
    )]
    StartMismatch { mm: f64, deg: f64 },
    #[error("{at}: the pose is out of reach: {source}")]
    Unreachable { at: Where, source: SixAxisError },
    #[error("{at}: {}", describe_violation(.violation))]
    Range {
        at: Where,
        violation: RangeViolation,
    },
    #[error(
        "{at}: the arm would change configuration: axis {axis} jumps by {change_deg:.3} deg \
         while the TCP moves {tcp_move_mm:.4} mm and turns {turn_deg:.4} deg"
    )]
    Jump {
        at: Where,
        /// 1-based.
        axis: usize,
        change_deg: f64,
        tcp_move_mm: f64,
        turn_deg: f64,
    },
    #[error(
        "{at}: axis 5 = {axis5_deg:.3} deg, within {limit_deg} deg of the wrist singularity \
         (axis 5 = 0)"
    )]
    WristSingularity {
        at: Where,
        axis5_deg: f64,
        limit_deg: f64,
    },
    #[error(
        "the path ends in configuration {reached} (axes {}), not in the end target's {wanted}",
        fmt_axes(.joints_deg)
    )]
    EndConf {
        reached: ConfData,
        wanted: ConfData,
        joints_deg: Axes6,
    },
    #[error("following the path takes more than {MAX_CHORDS} chords")]
    Budget,
}

fn fmt_axes(a: &Axes6) -> String {
    let v: Vec<String> = a.iter().map(|x| format!("{x:.3}")).collect();
    format!("[{}]", v.join(", "))
}

/// One sample of a followed path: the progress and the continuing solution there (controller
/// values, deg, not rounded).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathSample {
    pub s: f64,
    pub joints_deg: Axes6,
}

/// A path followed by the continuing inverse kinematics (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct FollowedPath {
    /// The path, cell frame.
    path: CartesianPath,
    /// Where it was run (the base and the tool).
    frames: TcpFrames,
    /// From `s` = 0 (the start joints) to `s` = 1, increasing.
    samples: Vec<PathSample>,
    /// Per chord (samples `k` -> `k + 1`): per axis, how far the joints along the path stray
    /// from the straight joint chord at most, deg.
    deviation_deg: Vec<[f64; 6]>,
    /// The confdata of the end joints (as written, `SixAxisIk::conf`).
    end_conf: ConfData,
}

/// Where the programmed speed needs an axis faster than its maximum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedExcess {
    pub at: Where,
    /// 1-based.
    pub axis: usize,
    pub needed_deg_s: f64,
    pub max_deg_s: f64,
}

impl fmt::Display for SpeedExcess {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: axis {} would need {:.0} deg/s, beyond its {:.0} deg/s",
            self.at, self.axis, self.needed_deg_s, self.max_deg_s
        )
    }
}

impl SixAxisIk {
    /// The inverse continuing from `previous` (module docs, "The continuing solution"): the
    /// branch of the tool0 pose (robot base frame, mm) nearest `previous` on every axis, each
    /// axis turned by whole turns to lie nearest it. No range is applied. Errors for a pose that
    /// is not finite or out of reach.
    pub fn continuing(
        &self,
        tool0: &Isometry3<f64>,
        previous: &Axes6,
    ) -> Result<Axes6, SixAxisError> {
        let mut best: Option<(f64, Axes6)> = None;
        for b in self.branches(tool0, Some(previous))? {
            let turned: Axes6 =
                std::array::from_fn(|i| b[i] + 360.0 * ((previous[i] - b[i]) / 360.0).round());
            let d = max_abs_diff(&turned, previous);
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, turned));
            }
        }
        // `branches` returns at least one branch or an error.
        best.map(|(_, a)| a).ok_or(SixAxisError::NotFinite)
    }
}

fn max_abs_diff(a: &Axes6, b: &Axes6) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Follows `path` (cell frame) from the joints `start` the move starts in, with the default
/// settings; `end_conf` is the confdata the end target asks for, if any (module docs).
pub fn follow(
    ik: &SixAxisIk,
    frames: &TcpFrames,
    path: &CartesianPath,
    start: &Axes6,
    end_conf: Option<ConfData>,
) -> Result<FollowedPath, FollowError> {
    follow_with(
        ik,
        frames,
        path,
        start,
        end_conf,
        &FollowSettings::default(),
    )
}

/// [`follow`] with other settings.
pub fn follow_with(
    ik: &SixAxisIk,
    frames: &TcpFrames,
    path: &CartesianPath,
    start: &Axes6,
    end_conf: Option<ConfData>,
    settings: &FollowSettings,
) -> Result<FollowedPath, FollowError> {
    let robot = ik.robot();
    let at_start = frames.cell_from_robot * robot.tool0(start) * frames.tframe;
    let mm = (at_start.translation.vector - path.start().translation.vector).norm();
    let deg = at_start
        .rotation
        .angle_to(&path.start().rotation)
        .to_degrees();
    if !(mm <= START_TOL_MM && deg <= START_TOL_DEG) {
        return Err(FollowError::StartMismatch { mm, deg });
    }
    let robot_from_cell = frames.cell_from_robot.inverse();
    let tframe_inverse = frames.tframe.inverse();
    let solve = |s: f64, previous: &Axes6| {
        ik.continuing(
            &(robot_from_cell * path.pose_at(s) * tframe_inverse),
            previous,
        )
    };
    let form = ik.pose_form(&robot_from_cell, path, &tframe_inverse);
    let (signs, start_error) = start_branch(ik, &form, start);
    let enclose = |s: Interval| ik.enclose(&form, s, signs);
    let (samples, deviation_deg) = track(
        start,
        &start_error,
        &solve,
        &enclose,
        &Limits::of(robot),
        settings,
    )
    .map_err(|stop| stop.into_error(path, settings))?;
    let end = samples.last().map_or(*start, |x| x.joints_deg);
    let reached = ik.conf(&end);
    if let Some(wanted) = end_conf {
        if !ik.conf_admits(&end, wanted) {
            return Err(FollowError::EndConf {
                reached,
                wanted,
                joints_deg: end,
            });
        }
    }
    Ok(FollowedPath {
        path: *path,
        frames: *frames,
        samples,
        deviation_deg,
        end_conf: reached,
    })
}

/// The branch the controller runs from `start` (module docs, "The deviation bound"): the signs
/// whose solution of the path's start pose, modulo full turns, lies nearest `start`, and per axis
/// how far from `start` that solution may lie (deg; infinite when no branch is defined there).
fn start_branch(ik: &SixAxisIk, form: &PoseForm, start: &Axes6) -> (Signs, [f64; 6]) {
    let mut best = (Signs::all()[0], [f64::INFINITY; 6]);
    for signs in Signs::all() {
        let Some(e) = ik.enclose(form, Interval::point(0.0), signs) else {
            continue;
        };
        let error: [f64; 6] = std::array::from_fn(|i| {
            let v = e.value_deg[i];
            let turned = v.shift(360.0 * ((start[i] - v.mid()) / 360.0).round());
            farthest(start[i], &turned)
        });
        if max_of(&error) < max_of(&best.1) {
            best = (signs, error);
        }
    }
    best
}

/// The largest of six numbers.
fn max_of(a: &[f64; 6]) -> f64 {
    a.iter().fold(0.0, |m, x| m.max(*x))
}

/// How far `x` may lie from a member of `within` at most, rounded up.
fn farthest(x: f64, within: &Interval) -> f64 {
    let p = Interval::point(x);
    (p - Interval::point(within.lo()))
        .hi()
        .max((Interval::point(within.hi()) - p).hi())
}

/// The ranges a path must keep (controller values, deg).
#[derive(Clone, Debug)]
pub(crate) struct Limits {
    axes: [(f64, f64); 6],
    coupled: Option<[f64; 2]>,
}

impl Limits {
    pub(crate) fn of(robot: &Robot) -> Limits {
        let c = &robot.controller;
        Limits {
            axes: std::array::from_fn(|i| (c.axes[i].min_deg, c.axes[i].max_deg)),
            coupled: c.coupled_axis3_deg,
        }
    }

    /// The first limit `a` breaks, exactly.
    fn check(&self, a: &Axes6) -> Option<RangeViolation> {
        self.check_band(a, a, &[0.0; 6], 0.0)
    }

    /// The first limit the chord `a -> b` widened by `delta` breaks by more than `slack`.
    fn check_band(
        &self,
        a: &Axes6,
        b: &Axes6,
        delta: &[f64; 6],
        slack: f64,
    ) -> Option<RangeViolation> {
        for (i, &(lo, hi)) in self.axes.iter().enumerate() {
            let (low, high) = (a[i].min(b[i]) - delta[i], a[i].max(b[i]) + delta[i]);
            let outside = if low < lo - slack || !low.is_finite() {
                Some(low)
            } else if high > hi + slack || !high.is_finite() {
                Some(high)
            } else {
                None
            };
            if let Some(value_deg) = outside {
                return Some(RangeViolation::Axis {
                    axis: i + 1,
                    value_deg,
                    min_deg: lo,
                    max_deg: hi,
                });
            }
        }
        let [lo, hi] = self.coupled?;
        let d = delta[1] + delta[2];
        let (da, db) = (a[2] - a[1], b[2] - b[1]);
        let (low, high) = (da.min(db) - d, da.max(db) + d);
        let value_deg = if low < lo - slack {
            low
        } else if high > hi + slack {
            high
        } else {
            return None;
        };
        Some(RangeViolation::Coupled {
            value_deg,
            min_deg: lo,
            max_deg: hi,
        })
    }
}

/// What a probe or a chord ran into.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Trouble {
    Unreachable(SixAxisError),
    Range(RangeViolation),
    Singular(f64),
    /// The joints change by `change_deg` on `axis` (0-based) between progress `from` and `to`.
    Jump {
        axis: usize,
        change_deg: f64,
        from: f64,
        to: f64,
    },
    Budget,
}

/// Where tracking stopped (progress) and why.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Stop {
    pub(crate) s: f64,
    pub(crate) why: Trouble,
}

impl Stop {
    fn into_error(self, path: &CartesianPath, settings: &FollowSettings) -> FollowError {
        let at = |s: f64| Where {
            progress_pct: 100.0 * s,
            tcp_mm: path.position_at(s).coords.into(),
        };
        match self.why {
            Trouble::Unreachable(source) => FollowError::Unreachable {
                at: at(self.s),
                source,
            },
            Trouble::Range(violation) => FollowError::Range {
                at: at(self.s),
                violation,
            },
            Trouble::Singular(axis5_deg) => FollowError::WristSingularity {
                at: at(self.s),
                axis5_deg,
                limit_deg: settings.wrist_singularity_deg,
            },
            Trouble::Jump {
                axis,
                change_deg,
                from,
                to,
            } => {
                let (a, b) = (path.pose_at(from), path.pose_at(to));
                FollowError::Jump {
                    at: at(self.s),
                    axis: axis + 1,
                    change_deg,
                    tcp_move_mm: (b.translation.vector - a.translation.vector).norm(),
                    turn_deg: a.rotation.angle_to(&b.rotation).to_degrees(),
                }
            }
            Trouble::Budget => FollowError::Budget,
        }
    }
}

/// A chord tried: accepted with its end joints, its deviation bound and the bound on how far
/// the end joints lie from the controller's, or to be refined because of what happened at
/// progress `s`.
enum Outcome {
    Accept {
        end: Axes6,
        deviation: [f64; 6],
        end_error: [f64; 6],
    },
    Refine {
        s: f64,
        why: Trouble,
    },
}

/// The deviation bound of the chord `q0 -> q1` over `[s0, s1]` (module docs, "The deviation
/// bound"): `q0` within `e0` of the controller's joints at `s0`; `over` the branch's enclosure
/// on `[s0, s1]`, `end` at `s1`. Per axis the bound and how far `q1` may lie from the
/// controller's joints at `s1`; `None` where the end cannot be placed on the branch.
pub(crate) fn chord_bound(
    (s0, q0, e0): (f64, &Axes6, &[f64; 6]),
    (s1, q1): (f64, &Axes6),
    over: &Enclosure,
    end: &Enclosure,
) -> Option<([f64; 6], [f64; 6])> {
    let h = Interval::point(s1) - Interval::point(s0);
    let mut deviation = [0.0; 6];
    let mut end_error = [0.0; 6];
    for i in 0..6 {
        let rate = over.rate_deg[i];
        // Where the controller's axis is at s1: reached from q0 at a rate within `rate`, and
        // the branch's value there up to full turns.
        let reach = Interval::around(q0[i], e0[i]) + h * rate;
        let v = end.value_deg[i];
        if !(reach.is_valid() && v.is_valid()) || reach.width() + v.width() >= 180.0 {
            return None;
        }
        let there = v
            .shift(360.0 * ((reach.mid() - v.mid()) / 360.0).round())
            .intersect(&reach);
        if !there.is_valid() {
            return None;
        }
        let e1 = farthest(q1[i], &there);
        // The chord's slope against the rates: the joints stray from it by at most
        // h a b / (a + b) beyond the ends' errors.
        let slope = (Interval::point(q1[i]) - Interval::point(q0[i])) * h.recip();
        let a = (slope - rate).hi().max(0.0);
        let b = (rate - slope).hi().max(0.0);
        let bend = if a + b > 0.0 {
            let (a, b) = (Interval::point(a), Interval::point(b));
            (h * a * b * (a + b).recip()).hi()
        } else {
            0.0
        };
        let d = (Interval::point(e0[i].max(e1)) + Interval::point(bend)).hi();
        if !d.is_finite() {
            return None;
        }
        deviation[i] = d;
        end_error[i] = e1;
    }
    Some((deviation, end_error))
}

/// The chord `[s0, s1]` from joints `q0` (module docs, "Samples, chords and the deviation
/// bound").
#[allow(clippy::too_many_arguments)]
fn try_chord<F, G>(
    s0: f64,
    q0: &Axes6,
    e0: &[f64; 6],
    s1: f64,
    solve: &F,
    enclose: &G,
    limits: &Limits,
    settings: &FollowSettings,
) -> Outcome
where
    F: Fn(f64, &Axes6) -> Result<Axes6, SixAxisError>,
    G: Fn(Interval) -> Option<Enclosure>,
{
    let h = s1 - s0;
    let mut probes = [*q0; 5];
    let mut at = [s0; 5];
    for j in 1..5 {
        let s = if j == 4 { s1 } else { s0 + h * j as f64 / 4.0 };
        at[j] = s;
        probes[j] = match solve(s, &probes[j - 1]) {
            Ok(q) => q,
            Err(e) => {
                return Outcome::Refine {
                    s,
                    why: Trouble::Unreachable(e),
                }
            }
        };
        let (axis, change_deg) = largest_change(&probes[j - 1], &probes[j]);
        if change_deg > MAX_PROBE_STEP_DEG {
            return Outcome::Refine {
                s,
                why: Trouble::Jump {
                    axis,
                    change_deg,
                    from: at[j - 1],
                    to: s,
                },
            };
        }
    }
    let wrist = settings.wrist_singularity_deg;
    for j in 1..5 {
        if let Some(v) = limits.check(&probes[j]) {
            return Outcome::Refine {
                s: at[j],
                why: Trouble::Range(v),
            };
        }
        if probes[j][4].is_nan() || probes[j][4].abs() < wrist {
            return Outcome::Refine {
                s: at[j],
                why: Trouble::Singular(probes[j][4]),
            };
        }
    }
    let bound = match (enclose(Interval::new(s0, s1)), enclose(Interval::point(s1))) {
        (Some(over), Some(end)) => chord_bound((s0, q0, e0), (s1, &probes[4]), &over, &end),
        _ => None,
    };
    let within = bound.filter(|(d, _)| d.iter().all(|d| *d <= settings.deviation_tol_deg));
    let Some((deviation, end_error)) = within else {
        // Report the probe step that moves the worst axis most (the axis that moves most
        // where the branch could not be enclosed).
        let worst = match bound {
            Some((d, _)) => (0..6).max_by(|a, b| d[*a].total_cmp(&d[*b])).unwrap_or(0),
            None => largest_change(q0, &probes[4]).0,
        };
        let (j, change_deg) = (1..5)
            .map(|j| (j, (probes[j][worst] - probes[j - 1][worst]).abs()))
            .fold((1, -1.0), |b, x| if x.1 > b.1 { x } else { b });
        return Outcome::Refine {
            s: at[j],
            why: Trouble::Jump {
                axis: worst,
                change_deg,
                from: at[j - 1],
                to: at[j],
            },
        };
    };
    let end = probes[4];
    let mid = 0.5 * (s0 + s1);
    if let Some(v) = limits.check_band(q0, &end, &deviation, RANGE_SLACK_DEG) {
        return Outcome::Refine {
            s: mid,
            why: Trouble::Range(v),
        };
    }
    let (a5, b5) = (q0[4], end[4]);
    let nearest = a5.abs().min(b5.abs()) - deviation[4];
    if a5.signum() != b5.signum() || nearest < wrist {
        return Outcome::Refine {
            s: mid,
            why: Trouble::Singular(if a5.abs() < b5.abs() { a5 } else { b5 }),
        };
    }
    Outcome::Accept {
        end,
        deviation,
        end_error,
    }
}

/// The axis (0-based) that changes most from `a` to `b`, and by how much (deg).
fn largest_change(a: &Axes6, b: &Axes6) -> (usize, f64) {
    (0..6)
        .map(|i| (i, (b[i] - a[i]).abs()))
        .fold((0, -1.0), |best, x| if x.1 > best.1 { x } else { best })
}

/// The samples and chord bounds of a path whose continuing solution at progress `s` from the
/// previous joints is `solve(s, previous)` and whose branch over a range of progress is
/// enclosed by `enclose`, from joints `start`, within `start_error` of the branch's (module
/// docs).
pub(crate) fn track<F, G>(
    start: &Axes6,
    start_error: &[f64; 6],
    solve: &F,
    enclose: &G,
    limits: &Limits,
    settings: &FollowSettings,
) -> Result<(Vec<PathSample>, Vec<[f64; 6]>), Stop>
where
    F: Fn(f64, &Axes6) -> Result<Axes6, SixAxisError>,
    G: Fn(Interval) -> Option<Enclosure>,
{
    if let Some(v) = limits.check(start) {
        return Err(Stop {
            s: 0.0,
            why: Trouble::Range(v),
        });
    }
    if start[4].is_nan() || start[4].abs() < settings.wrist_singularity_deg {
        return Err(Stop {
            s: 0.0,
            why: Trouble::Singular(start[4]),
        });
    }
    let mut samples = vec![PathSample {
        s: 0.0,
        joints_deg: *start,
    }];
    let mut deviations = Vec::new();
    let (mut s, mut q, mut h) = (0.0f64, *start, FIRST_STEP);
    let mut error = *start_error;
    // Every try either accepts a chord or halves the step, which it can do at most
    // log2(1 / MIN_STEP) times in a row: a budget on tries follows from the one on chords.
    let mut tries = 0usize;
    while s < 1.0 {
        tries += 1;
        if deviations.len() >= MAX_CHORDS || tries > 64 * MAX_CHORDS {
            return Err(Stop {
                s,
                why: Trouble::Budget,
            });
        }
        let step = h.min(1.0 - s);
        let s1 = if s + step >= 1.0 || 1.0 - (s + step) < 0.5 * MIN_STEP {
            1.0
        } else {
            s + step
        };
        match try_chord(s, &q, &error, s1, solve, enclose, limits, settings) {
            Outcome::Accept {
                end,
                deviation,
                end_error,
            } => {
                let largest = deviation.iter().fold(0.0f64, |m, d| m.max(*d));
                samples.push(PathSample {
                    s: s1,
                    joints_deg: end,
                });
                deviations.push(deviation);
                h = if largest < 0.25 * settings.deviation_tol_deg {
                    (2.0 * (s1 - s)).min(1.0)
                } else {
                    s1 - s
                };
                (s, q, error) = (s1, end, end_error);
            }
            Outcome::Refine { s: at, why } => {
                if s1 - s <= MIN_STEP {
                    return Err(match why {
                        Trouble::Jump { .. } => {
                            reach_ends_ahead(s1, &q, solve).unwrap_or(Stop { s: at, why })
                        }
                        why => Stop { s: at, why },
                    });
                }
                h = 0.5 * (s1 - s);
            }
        }
    }
    Ok((samples, deviations))
}

/// Where a jump at the smallest step is the arm stretching to the end of its reach (the
/// joints bend ever faster as the elbow straightens): the first pose out of reach within
/// [`REACH_AHEAD`] of progress past `s`, looking at `s + MIN_STEP 2^m`.
fn reach_ends_ahead<F>(s: f64, q: &Axes6, solve: &F) -> Option<Stop>
where
    F: Fn(f64, &Axes6) -> Result<Axes6, SixAxisError>,
{
    let mut step = MIN_STEP;
    while step <= REACH_AHEAD {
        let t = (s + step).min(1.0);
        if let Err(e) = solve(t, q) {
            return Some(Stop {
                s: t,
                why: Trouble::Unreachable(e),
            });
        }
        if t >= 1.0 {
            break;
        }
        step *= 2.0;
    }
    None
}

impl FollowedPath {
    /// The path followed, cell frame.
    pub fn path(&self) -> &CartesianPath {
        &self.path
    }

    /// The robot base and the tool the path was run with.
    pub fn frames(&self) -> &TcpFrames {
        &self.frames
    }

    /// The samples, from `s` = 0 (the start joints) to `s` = 1.
    pub fn samples(&self) -> &[PathSample] {
        &self.samples
    }

    /// Per chord (samples `k` -> `k + 1`), per axis, the bound on how far the joints along the
    /// path stray from the straight joint chord, deg (module docs).
    pub fn deviations_deg(&self) -> &[[f64; 6]] {
        &self.deviation_deg
    }

    /// The joints at the end of the path (the continuing solution, not rounded).
    pub fn end_joints(&self) -> Axes6 {
        self.samples.last().map_or([0.0; 6], |s| s.joints_deg)
    }

    /// The confdata the path ends in (of the end joints as written).
    pub fn end_conf(&self) -> ConfData {
        self.end_conf
    }

    /// The TCP position at progress `s`, cell frame, mm.
    pub fn tcp_at(&self, s: f64) -> Point3<f64> {
        self.path.position_at(s)
    }

    /// The place at progress `s` (for messages).
    pub fn place_at(&self, s: f64) -> Where {
        Where {
            progress_pct: 100.0 * s,
            tcp_mm: self.tcp_at(s).coords.into(),
        }
    }

    /// How far each axis travels along the path, summed over the chords, deg.
    pub fn axis_travel_deg(&self) -> [f64; 6] {
        let mut travel = [0.0; 6];
        for w in self.samples.windows(2) {
            for (i, t) in travel.iter_mut().enumerate() {
                *t += (w[1].joints_deg[i] - w[0].joints_deg[i]).abs();
            }
        }
        travel
    }

    /// The time the path takes at `speed` by the TCP and the reorientation alone, ramps aside:
    /// `max(L / v_tcp, Theta / v_ori)`, s (0 for a speed of 0 or a path that does not move).
    pub fn paced_seconds(&self, speed: &SpeedData) -> f64 {
        let by = |d: f64, v: f64| if v > 0.0 { d / v } else { 0.0 };
        by(self.path.length_mm(), speed.v_tcp_mm_s).max(by(self.path.turn_deg(), speed.v_ori_deg_s))
    }

    /// Per sample, the speed each axis needs when the path runs at `speed` (module docs, "Axis
    /// speeds"): the faster of the chords on either side, deg/s.
    pub fn axis_speeds_deg_s(&self, speed: &SpeedData) -> Vec<[f64; 6]> {
        let t = self.paced_seconds(speed);
        let rates: Vec<[f64; 6]> = self
            .samples
            .windows(2)
            .map(|w| {
                let ds = w[1].s - w[0].s;
                std::array::from_fn(|i| {
                    if t > 0.0 && ds > 0.0 {
                        (w[1].joints_deg[i] - w[0].joints_deg[i]).abs() / (ds * t)
                    } else {
                        0.0
                    }
                })
            })
            .collect();
        (0..self.samples.len())
            .map(|k| {
                let before = k.checked_sub(1).and_then(|j| rates.get(j));
                let after = rates.get(k);
                std::array::from_fn(|i| {
                    before
                        .map_or(0.0, |r| r[i])
                        .max(after.map_or(0.0, |r| r[i]))
                })
            })
            .collect()
    }

    /// The sample where running at `speed` needs an axis most beyond its maximum speed (the
    /// largest ratio; ties to the earliest sample and lowest axis), or `None` when every axis
    /// keeps within its own.
    pub fn speed_excess(&self, speed: &SpeedData, axes: &[AxisSpec; 6]) -> Option<SpeedExcess> {
        let mut worst: Option<(f64, usize, usize, f64)> = None;
        for (k, v) in self.axis_speeds_deg_s(speed).iter().enumerate() {
            for i in 0..6 {
                let ratio = v[i] / axes[i].speed_deg_s;
                if ratio > 1.0 && worst.is_none_or(|(r, ..)| ratio > r) {
                    worst = Some((ratio, k, i, v[i]));
                }
            }
        }
        worst.map(|(_, k, i, needed)| SpeedExcess {
            at: self.place_at(self.samples[k].s),
            axis: i + 1,
            needed_deg_s: needed,
            max_deg_s: axes[i].speed_deg_s,
        })
    }
}

#[cfg(test)]
pub(crate) mod testing;
#[cfg(test)]
mod tests;
