//! Whole moves: the guarantee the paper lacks.
//!
//! The paper checks grid nodes only; the straight joint moves written to the RAPID module pass
//! between them. [`CollisionModel::move_is_safe`] proves that every configuration on the straight
//! joint-space segment keeps at least `clearance` from every box. It is conservative: it may
//! reject a safe move, it never accepts an unsafe one.
//!
//! *Range.* The axis ranges and the coupled range `lo <= a3 - a2 <= hi` are convex sets of
//! controller values, so a segment whose ends are in range stays in range: the ends are checked.
//!
//! *Lipschitz bound.* Let cylinder `L` hang on the child link of URDF joint `j_L`. For joint
//! `i <= j_L`, `R[i][L]` bounds the distance of any point of `L` from joint `i`'s axis, in every
//! configuration. Joint `i`'s axis passes through the origin of link `i` along `axis_i`, fixed in
//! link `i`'s frame; write `t_k` for the translation of `joints[k].origin`, `P_i` for the
//! projection orthogonal to `axis_i` and `a`, `b`, `r` for the cylinder's end points (link frame)
//! and radius. Then
//!
//! ```text
//! R[i][L] = max(|P_i a|, |P_i b|) + r                                      if i == j_L
//! R[i][L] = |P_i t_{i+1}| + sum_{k=i+2..=j_L} |t_k| + max(|a|, |b|) + r    if i <  j_L
//! ```
//!
//! (a point of the cylinder is `a + s (b - a) + w` with `|w| <= r`, and the norm is convex; the
//! chain from link `i`'s origin to link `j_L`'s origin is `t_{i+1}`, whose component across
//! `axis_i` is constant in link `i`'s frame, followed by vectors of constant length). A point `p`
//! of `L` moves with velocity `sum_i qdot_i axis_i x (p - o_i)`, of norm at most
//! `sum_i R[i][L] |qdot_i|`. A straight move changes URDF joint `i` by `Dq_i` (the controller
//! coupling is linear, so the move is straight in URDF values too; `Dq` from
//! [`Robot::urdf_joints_deg`]), hence over a sub-interval of parameter length `h` no point of `L`
//! moves more than `M_L h`, with `M_L = sum_i R[i][L] |Dq_i| (rad)`. The distance `d(t)` between
//! `L` and a box is therefore `M_L`-Lipschitz in `t`, and with exact distances `d0`, `d1` at the
//! ends of the sub-interval,
//!
//! ```text
//! d(t) >= max(d0 - M_L (t - t0), d1 - M_L (t1 - t)) >= (d0 + d1 - M_L h) / 2.
//! ```
//!
//! Each (cylinder, box) pair is certified on `[0, 1]` by bisection, left half first: an interval
//! whose bound is `>= clearance` is done; a midpoint closer than `clearance` proves the move
//! unsafe; an interval with `M_L h` below [`MOVE_FLOOR_MM`] (a grazing move) is rejected
//! conservatively. Distances come from [`distance_cylinder_aabb`] (closed-form capsule bounds,
//! parry3d-f64 GJK only in the narrow band between them) and are lowered by
//! [`DISTANCE_SLACK_REL`] before use, which covers GJK's relative stopping tolerance (about
//! `5e-8` in f64) and rounding.
//!

use super::{Blocked, CollisionModel};
use crate::geometry::distance_cylinder_aabb;

/// Bisection of a move stops (and rejects it) when the largest displacement of a link over the
/// interval, `M_L h`, falls below this, mm.
pub const MOVE_FLOOR_MM: f64 = 1e-3;

/// Distances used in proofs are lowered by `DISTANCE_SLACK_REL * (1 mm + d)`: parry's GJK stops at
/// a relative gap of about 5e-8 in f64 and errs from above.
pub const DISTANCE_SLACK_REL: f64 = 1e-6;

/// Most distance evaluations one (cylinder, box) pair may spend on a move before the move is
/// rejected (or, in [`CollisionModel::min_clearance_along`], before its bound is returned as is).
const MAX_EVALS_PER_PAIR: usize = 1 << 20;

/// The smallest clearance along a move (or a route): a certified lower bound, and the link and
/// obstacle it belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Clearance {
    pub mm: f64,
    pub link: String,
    pub obstacle: String,
}

/// Result of certifying one (cylinder, box) pair along a move.
enum PairVerdict {
    Safe,
    /// Fails at parameter `t`, where the distance (or its failing bound) is `d`.
    Fails {
        t: f64,
        d: f64,
    },
}

impl CollisionModel {
    /// Conservative whole-move check: `true` only if every configuration on the straight
    /// joint-space segment `from -> to` (controller values, linear interpolation) is in range and
    /// keeps at least the clearance from every box. May reject a safe move (a grazing one, see
    /// [`MOVE_FLOOR_MM`]); never accepts an unsafe one. See the module doc for the proof.
    pub fn move_is_safe(&self, from: &[f64; 3], to: &[f64; 3]) -> bool {
        if self.robot.check_range3(from).is_err() || self.robot.check_range3(to).is_err() {
            return false;
        }
        let speeds = self.link_speeds(from, to);
        for (i, &m) in speeds.iter().enumerate() {
            let d0 = self.pair_distances(i, from);
            let d1 = self.pair_distances(i, to);
            for (k, _) in self.checked_boxes(i) {
                if let PairVerdict::Fails { .. } =
                    self.certify_pair(i, k, from, to, m, d0[k], d1[k], false)
                {
                    return false;
                }
            }
        }
        true
    }

    /// A certified lower bound of the smallest distance (mm) between any link cylinder and any
    /// box along the move `from -> to`, within `tol_mm` of the true minimum (branch and bound on
    /// the Lipschitz bound of the module doc; `tol_mm` below 1e-6 is raised to it; the bound is
    /// further lowered by the [`DISTANCE_SLACK_REL`] slack). The (link, obstacle) pair named is
    /// the witness: the pair seen closest at some instant of the move, within `tol_mm` (plus the
    /// slack) of the bound. Geometry only: the range is not checked. `None` without obstacles.
    pub fn min_clearance_along(
        &self,
        from: &[f64; 3],
        to: &[f64; 3],
        tol_mm: f64,
    ) -> Option<Clearance> {
        let tol = if tol_mm >= 1e-6 { tol_mm } else { 1e-6 };
        let speeds = self.link_speeds(from, to);
        let ends: Vec<_> = (0..self.cyl.len())
            .map(|i| (self.pair_distances(i, from), self.pair_distances(i, to)))
            .collect();
        // Best attained distance so far: an upper bound of the minimum, and its pair.
        let mut upper = (f64::INFINITY, None);
        for (i, (a, b)) in ends.iter().enumerate() {
            for (k, &d) in a.iter().chain(b).enumerate() {
                if d < upper.0 {
                    upper = (d, Some((i, k % a.len())));
                }
            }
        }
        let mut result = f64::INFINITY;
        for (i, &m) in speeds.iter().enumerate() {
            for (k, _) in self.checked_boxes(i) {
                let (d0, d1) = (ends[i].0[k], ends[i].1[k]);
                let mut evals = 0usize;
                let mut stack = vec![(0.0f64, 1.0f64, d0, d1)];
                while let Some((t0, t1, d0, d1)) = stack.pop() {
                    let reach = m * (t1 - t0);
                    // Prune on the raw bound (so the slack cannot stall the search), record the
                    // slack-lowered one.
                    let raw = (0.5 * (d0 + d1 - reach)).min(d0).min(d1);
                    if raw >= upper.0 - tol || evals >= MAX_EVALS_PER_PAIR {
                        result = result.min(interval_bound(d0, d1, reach));
                        continue;
                    }
                    let tm = 0.5 * (t0 + t1);
                    let dm = self.pair_distance_at(i, k, from, to, tm);
                    evals += 1;
                    if dm < upper.0 {
                        upper = (dm, Some((i, k)));
                    }
                    stack.push((tm, t1, dm, d1));
                    stack.push((t0, tm, d0, dm));
                }
            }
        }
        // Every interval was pruned within `tol` of `upper`, so the witness is within `tol` of
        // the bound. Distances are never negative: the slack may have taken the bound below 0.
        let (i, k) = upper.1?;
        Some(Clearance {
            mm: result.min(upper.0).max(0.0),
            link: self.robot.cylinders[i].link.clone(),
            obstacle: self.obstacles[k].name.clone(),
        })
    }

    /// Where a move fails: `(t, why)`, `t` in `[0, 1]`. An end out of range gives `t` = 0 or 1
    /// and [`Blocked::Range`]. Otherwise `t` is the earliest point over all (cylinder, box) pairs
    /// where a pair comes closer than the clearance (everything before it certified, to
    /// [`MOVE_FLOOR_MM`] of link motion), or could not be proven clear (a grazing move; then
    /// `distance_mm` is the failing lower bound). `None` exactly when
    /// [`move_is_safe`](Self::move_is_safe) holds.
    pub fn why_move_unsafe(&self, from: &[f64; 3], to: &[f64; 3]) -> Option<(f64, Blocked)> {
        if let Err(v) = self.robot.check_range3(from) {
            return Some((0.0, Blocked::Range(v)));
        }
        if let Err(v) = self.robot.check_range3(to) {
            return Some((1.0, Blocked::Range(v)));
        }
        let speeds = self.link_speeds(from, to);
        let mut first: Option<(f64, usize, usize, f64)> = None;
        for (i, &m) in speeds.iter().enumerate() {
            let d0 = self.pair_distances(i, from);
            let d1 = self.pair_distances(i, to);
            for (k, _) in self.checked_boxes(i) {
                if let PairVerdict::Fails { t, d } =
                    self.certify_pair(i, k, from, to, m, d0[k], d1[k], true)
                {
                    if first.is_none_or(|(tf, _, _, df)| t < tf || (t == tf && d < df)) {
                        first = Some((t, i, k, d));
                    }
                }
            }
        }
        first.map(|(t, i, k, d)| (t, self.contact(i, k, d.max(0.0))))
    }

    /// `M_L` of the module doc for every cylinder: the most any of its points moves over the
    /// whole move, mm.
    pub(super) fn link_speeds(&self, from: &[f64; 3], to: &[f64; 3]) -> Vec<f64> {
        let q0 = self
            .robot
            .urdf_joints_deg(&[from[0], from[1], from[2], 0.0, 0.0, 0.0]);
        let q1 = self
            .robot
            .urdf_joints_deg(&[to[0], to[1], to[2], 0.0, 0.0, 0.0]);
        let dq: [f64; 3] = std::array::from_fn(|i| (q1[i] - q0[i]).abs().to_radians());
        self.cyl
            .iter()
            .map(|cd| (0..3).map(|i| cd.reach_mm[i] * dq[i]).sum())
            .collect()
    }

    /// Distances from cylinder `i` to every box at `axes` (`f64::INFINITY` for an exempt pair;
    /// callers skip those pairs, the slack of `lowered` is not meant for infinities).
    fn pair_distances(&self, i: usize, axes: &[f64; 3]) -> Vec<f64> {
        let c = self.cylinder_in(i, &self.cell_link_poses(axes));
        self.obstacles
            .iter()
            .zip(&self.cyl[i].exempt)
            .map(|(o, &exempt)| {
                if exempt {
                    f64::INFINITY
                } else {
                    distance_cylinder_aabb(&c, &o.aabb)
                }
            })
            .collect()
    }

    /// Distance from cylinder `i` to box `k` at parameter `t` of the move.
    fn pair_distance_at(&self, i: usize, k: usize, from: &[f64; 3], to: &[f64; 3], t: f64) -> f64 {
        let axes = lerp(from, to, t);
        let c = self.cylinder_in(i, &self.cell_link_poses(&axes));
        distance_cylinder_aabb(&c, &self.obstacles[k].aabb)
    }

    /// Bisection proof that cylinder `i` keeps the clearance from box `k` along the move; `m` is
    /// its `M_L`, `d0`, `d1` the distances at the ends. Left-first depth-first bisection: when an
    /// interval is examined, everything left of it is certified. Without `earliest` the first
    /// failure found is returned; with it, the search goes on left of each witness, so the
    /// witness returned has everything left of it certified (to [`MOVE_FLOOR_MM`] resolution).
    #[allow(clippy::too_many_arguments)]
    fn certify_pair(
        &self,
        i: usize,
        k: usize,
        from: &[f64; 3],
        to: &[f64; 3],
        m: f64,
        d0: f64,
        d1: f64,
        earliest: bool,
    ) -> PairVerdict {
        let c = self.clearance_mm;
        if lowered(d0) < c {
            return PairVerdict::Fails { t: 0.0, d: d0 };
        }
        // The earliest witness found so far.
        let mut best: Option<(f64, f64)> = None;
        if lowered(d1) < c {
            if !earliest {
                return PairVerdict::Fails { t: 1.0, d: d1 };
            }
            best = Some((1.0, d1));
        }
        // The stack holds (t0, t1, d0, d1); the left half is pushed last, popped first.
        let mut stack = [(0.0f64, 0.0f64, 0.0f64, 0.0f64); 64];
        stack[0] = (0.0, 1.0, d0, d1);
        let mut top = 1usize;
        let mut evals = 0usize;
        while top > 0 {
            top -= 1;
            let (t0, t1, d0, d1) = stack[top];
            if best.is_some_and(|(tb, _)| t0 >= tb) {
                continue; // right of a witness
            }
            let reach = m * (t1 - t0);
            let lb = interval_bound(d0, d1, reach);
            if lb >= c {
                continue;
            }
            let tm = 0.5 * (t0 + t1);
            if reach < MOVE_FLOOR_MM || evals >= MAX_EVALS_PER_PAIR || top + 2 > stack.len() {
                // Everything left of t0 is certified. A failing right end (t = 1 or a witness)
                // is the answer; otherwise this interval could not be proven clear.
                return if lowered(d1) < c {
                    PairVerdict::Fails { t: t1, d: d1 }
                } else {
                    PairVerdict::Fails { t: tm, d: lb }
                };
            }
            let dm = self.pair_distance_at(i, k, from, to, tm);
            evals += 1;
            if lowered(dm) < c {
                if !earliest {
                    return PairVerdict::Fails { t: tm, d: dm };
                }
                best = Some((tm, dm));
                stack[top] = (t0, tm, d0, dm);
                top += 1;
                continue;
            }
            stack[top] = (tm, t1, dm, d1);
            stack[top + 1] = (t0, tm, d0, dm);
            top += 2;
        }
        match best {
            Some((t, d)) => PairVerdict::Fails { t, d },
            None => PairVerdict::Safe,
        }
    }
}

/// A distance lowered by the slack that covers GJK's tolerance.
#[inline]
fn lowered(d: f64) -> f64 {
    if d.is_finite() {
        d - DISTANCE_SLACK_REL * (1.0 + d.abs())
    } else {
        d
    }
}

/// Certified lower bound of an `M`-Lipschitz distance on an interval where the link moves at
/// most `reach` mm, from its raw end values (lowered by the slack here).
#[inline]
fn interval_bound(d0: f64, d1: f64, reach: f64) -> f64 {
    let (l0, l1) = (lowered(d0), lowered(d1));
    (0.5 * (l0 + l1 - reach)).min(l0).min(l1)
}

/// Linear interpolation of controller values.
#[inline]
pub(super) fn lerp(from: &[f64; 3], to: &[f64; 3], t: f64) -> [f64; 3] {
    std::array::from_fn(|i| from[i] + t * (to[i] - from[i]))
}
