//! Picking one solution: the configuration a robtarget asks for, or the one nearest the previous
//! point, among those the caller accepts.
//!
//! The metric (documented choice): a move from `a` to `b` costs
//! 1. the time of a synchronised joint move at the controller's axis speeds,
//!    `max_i |b_i - a_i| / speed_i` (the axis that takes longest sets the duration), then
//! 2. the Euclidean distance in degrees, `sqrt(sum_i (b_i - a_i)^2)`, then
//! 3. the room to the limits, more first: each axis's distance to the nearer limit of its range,
//!    sorted from the smallest, compared from the smallest on ([`SixAxisIk::rooms_deg`]), so that
//!    of two solutions equally near the one further from a stop wins (from axis 6 at 100 deg,
//!    280 and -80 are equally near; -80, 220 deg from its limit, wins over 280, 20 deg), then
//! 4. the fixed order [`SixAxisIk::solve`] returns (cfx, cf1, cf4, cf6, axis values).
//!
//! Ties in 1, 2 and 3 are exact comparisons of floating-point numbers, so the result is
//! deterministic. Without a previous point the zero pose (all axes 0, the calibration position
//! of ABB arms) stands in for it. Differences are plain differences of controller values (no
//! wrapping): an axis moves through its range, not across +-180.

use super::error::fmt_axes;
use super::{Candidate, ConfData, SixAxisError, SixAxisIk, Solution};
use crate::robot::Axes6;
use nalgebra::Isometry3;
use std::fmt;

/// The cost of a joint move under the documented metric.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveCost {
    /// `max_i |delta_i| / speed_i`, s.
    pub seconds: f64,
    /// `sqrt(sum_i delta_i^2)`, deg.
    pub euclidean_deg: f64,
}

/// The cost of moving from `from` to `to` at `speeds_deg_s` (controller values, deg).
pub fn move_cost(from: &Axes6, to: &Axes6, speeds_deg_s: &[f64; 6]) -> MoveCost {
    let mut seconds = 0.0_f64;
    let mut sum = 0.0;
    for i in 0..6 {
        let d = to[i] - from[i];
        seconds = seconds.max(d.abs() / speeds_deg_s[i]);
        sum += d * d;
    }
    MoveCost {
        seconds,
        euclidean_deg: sum.sqrt(),
    }
}

/// `Less` when rooms `a` (smallest first) leave more room than `b`: the first that differs is
/// larger.
fn more_room(a: &[f64; 6], b: &[f64; 6]) -> std::cmp::Ordering {
    a.iter()
        .zip(b)
        .map(|(x, y)| y.total_cmp(x))
        .find(|o| o.is_ne())
        .unwrap_or(std::cmp::Ordering::Equal)
}

/// Why no solution was chosen. `R` is the caller's refusal reason.
#[derive(Clone, Debug, PartialEq)]
pub enum ChooseError<R> {
    /// No solution in range at all.
    Ik(SixAxisError),
    /// Solutions exist, but none of the configuration asked for.
    ConfUnreachable {
        wanted: ConfData,
        /// The confdata of the in-range solutions, in [`SixAxisIk::solve`] order.
        reachable: Vec<ConfData>,
        /// The solution of that configuration, out of range (its violations say why); `None`
        /// when no solution of the pose has that configuration at all.
        wanted_solution: Option<Box<Candidate>>,
    },
    /// Every candidate was refused by the caller's predicate, each with its reason, in the
    /// order they were tried.
    AllRefused { refused: Vec<(Solution, R)> },
}

impl<R: fmt::Display> fmt::Display for ChooseError<R> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ChooseError::Ik(e) => write!(f, "{e}"),
            ChooseError::ConfUnreachable {
                wanted,
                reachable,
                wanted_solution,
            } => {
                write!(f, "confdata {wanted} is not reachable: ")?;
                match wanted_solution {
                    Some(c) => {
                        let why: Vec<String> =
                            c.violations.iter().map(super::describe_violation).collect();
                        write!(
                            f,
                            "its solution (axes {}) breaks the ranges: {}",
                            fmt_axes(&c.axes_deg),
                            why.join(", ")
                        )?;
                    }
                    None => write!(f, "no solution of this pose has that configuration")?,
                }
                let r: Vec<String> = reachable.iter().map(ConfData::to_string).collect();
                write!(f, "; reachable: {}", r.join(", "))
            }
            ChooseError::AllRefused { refused } => {
                write!(f, "every solution is refused: ")?;
                let parts: Vec<String> = refused
                    .iter()
                    .map(|(s, r)| {
                        format!("confdata {} (axes {}): {r}", s.conf, fmt_axes(&s.axes_deg))
                    })
                    .collect();
                write!(f, "{}", parts.join("; "))
            }
        }
    }
}

impl<R: fmt::Debug + fmt::Display> std::error::Error for ChooseError<R> {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ChooseError::Ik(e) => Some(e),
            _ => None,
        }
    }
}

impl SixAxisIk {
    /// The controller's axis speeds, deg/s (the metric's weights).
    pub fn speeds_deg_s(&self) -> [f64; 6] {
        std::array::from_fn(|i| self.robot.controller.axes[i].speed_deg_s)
    }

    /// The room of `axes` to the limits, deg: each axis's distance to the nearer limit of its
    /// range, smallest first (the metric's third key).
    pub fn rooms_deg(&self, axes: &Axes6) -> [f64; 6] {
        let ranges = &self.robot.controller.axes;
        let mut r: [f64; 6] =
            std::array::from_fn(|i| (axes[i] - ranges[i].min_deg).min(ranges[i].max_deg - axes[i]));
        r.sort_by(f64::total_cmp);
        r
    }

    /// Sorts solutions by the module's metric from `previous` (the zero pose when `None`);
    /// stable, so exact ties keep their order.
    pub fn order_by_move(&self, solutions: &mut [Solution], previous: Option<&Axes6>) {
        let from = previous.copied().unwrap_or([0.0; 6]);
        let speeds = self.speeds_deg_s();
        solutions.sort_by(|a, b| {
            let (ca, cb) = (
                move_cost(&from, &a.axes_deg, &speeds),
                move_cost(&from, &b.axes_deg, &speeds),
            );
            ca.seconds
                .total_cmp(&cb.seconds)
                .then(ca.euclidean_deg.total_cmp(&cb.euclidean_deg))
                .then_with(|| more_room(&self.rooms_deg(&a.axes_deg), &self.rooms_deg(&b.axes_deg)))
        });
    }

    /// Chooses one solution for a tool0 pose (robot base frame, mm).
    ///
    /// With `wanted` confdata: the solutions of that configuration, a value on a quadrant
    /// boundary admitted for both quadrants ([`SixAxisIk::conf_admits`]; one solution, except
    /// at singular poses; several are ordered by the metric). Without: all solutions, ordered by the metric
    /// from `previous`. The first that `is_acceptable` accepts wins (the caller's collision
    /// check; its refusals are kept). `previous` also settles the singular choices.
    pub fn choose<R>(
        &self,
        tool0: &Isometry3<f64>,
        wanted: Option<ConfData>,
        previous: Option<&Axes6>,
        mut is_acceptable: impl FnMut(&Axes6) -> Result<(), R>,
    ) -> Result<Solution, ChooseError<R>> {
        let analysis = self.analyse(tool0, previous).map_err(ChooseError::Ik)?;
        if analysis.solutions.is_empty() {
            return Err(ChooseError::Ik(self.why_none(analysis)));
        }
        let mut pool: Vec<Solution> = match wanted {
            None => analysis.solutions,
            Some(w) => {
                let pool: Vec<Solution> = analysis
                    .solutions
                    .iter()
                    .filter(|s| self.conf_admits(&s.axes_deg, w))
                    .copied()
                    .collect();
                if pool.is_empty() {
                    let mut reachable: Vec<ConfData> = Vec::new();
                    for s in &analysis.solutions {
                        if !reachable.contains(&s.conf) {
                            reachable.push(s.conf);
                        }
                    }
                    return Err(ChooseError::ConfUnreachable {
                        wanted: w,
                        reachable,
                        wanted_solution: self.of_conf(&analysis.candidates, w),
                    });
                }
                pool
            }
        };
        self.order_by_move(&mut pool, previous);
        let mut refused = Vec::new();
        for s in pool {
            match is_acceptable(&s.axes_deg) {
                Ok(()) => return Ok(s),
                Err(r) => refused.push((s, r)),
            }
        }
        Err(ChooseError::AllRefused { refused })
    }

    /// [`choose`](Self::choose) for a TCP pose and the tool's `tframe` (TCP in tool0 frame).
    pub fn choose_tcp<R>(
        &self,
        tcp: &Isometry3<f64>,
        tframe: &Isometry3<f64>,
        wanted: Option<ConfData>,
        previous: Option<&Axes6>,
        is_acceptable: impl FnMut(&Axes6) -> Result<(), R>,
    ) -> Result<Solution, ChooseError<R>> {
        self.choose(
            &Self::tool0_for_tcp(tcp, tframe),
            wanted,
            previous,
            is_acceptable,
        )
    }

    /// The branch of configuration `w`, with axes 1, 4 and 6 turned into its quadrants: the
    /// out-of-range solution a robtarget with that confdata would mean.
    fn of_conf(&self, candidates: &[Candidate], w: ConfData) -> Option<Box<Candidate>> {
        candidates.iter().find_map(|c| {
            if c.conf.cfx != w.cfx {
                return None;
            }
            let mut axes = c.axes_deg;
            for (i, cf) in [(0, w.cf1), (3, w.cf4), (5, w.cf6)] {
                let k = cf - super::conf::quadrant(axes[i]);
                if k.rem_euclid(4) != 0 {
                    return None;
                }
                axes[i] += 90.0 * f64::from(k);
            }
            let conf = self.conf(&axes);
            (conf == w).then(|| {
                Box::new(Candidate {
                    axes_deg: axes,
                    conf,
                    violations: self.violations(&axes),
                })
            })
        })
    }
}
