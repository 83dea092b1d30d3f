//! Whole moves: the guarantee the paper lacks.
//!
//! The paper checks grid nodes only; the straight joint moves written to the RAPID module pass
//! between them. [`CollisionModel::move_is_safe`] proves that every configuration on the straight
//! six-axis segment (a `MoveAbsJ` interpolates all six axes linearly) keeps every part of the
//! model (the link cylinders and the tool's shapes) at least `clearance` from every box. It is
//! conservative: it may reject a safe move, it never accepts an unsafe one.
//!
//! *Range.* The axis ranges and the coupled range `lo <= a3 - a2 <= hi` are convex sets of
//! controller values, so a segment whose ends are in range stays in range: the ends are checked.
//!
//! *Lipschitz bound.* Let part `P` (a link cylinder, or a tool shape on link 6) hang on the
//! child link of URDF joint `j_P`. For joint `i <= j_P`, `R[i][P]` bounds the distance of any
//! point of `P` from joint `i`'s axis, in every configuration. Joint `i`'s axis passes through
//! the origin of link `i` along `axis_i`, fixed in link `i`'s frame; write `t_k` for the
//! translation of `joints[k].origin`, `P_i` for the projection orthogonal to `axis_i`, and let
//! the part lie in the convex hull of points `h` of its link's frame grown by `g` (a cylinder:
//! its end points `a`, `b` and its radius `r`; a ball: its centre and radius; a box: its eight
//! corners and 0). Then
//!
//! ```text
//! R[i][P] = max |P_i h| + g                                          if i == j_P
//! R[i][P] = |P_i t_{i+1}| + sum_{k=i+2..=j_P} |t_k| + max |h| + g    if i <  j_P
//! ```
//!
//! (the norm is convex, so its maximum over the hull is at a point `h`; the chain from link
//! `i`'s origin to link `j_P`'s origin is `t_{i+1}`, whose component across `axis_i` is constant
//! in link `i`'s frame, followed by vectors of constant length). For a cylinder this is
//! `max(|P_i a|, |P_i b|) + r` and `... + max(|a|, |b|) + r`. For a tool shape, joints 4 and 5
//! get the smaller of this and a bound through the wrist centre (`parts.rs`: their axes pass
//! through the wrist, so no tool point is farther from them than from the wrist centre). A
//! point `p` of `P` moves with velocity `sum_i qdot_i axis_i x (p - o_i)`, of norm at most
//! `sum_i R[i][P] |qdot_i|`. A straight move changes URDF joint `i` by `Dq_i` (the controller
//! coupling is linear, so the move is straight in URDF values too; `Dq` from
//! [`Robot::urdf_joints_deg`], all six joints), hence over a sub-interval of parameter length
//! `h` no point of `P` moves more than `M_P h`, with `M_P = sum_{i=1..6} R[i][P] |Dq_i|` (rad;
//! `R[i][P]` = 0 for `i > j_P`, so axes 4..6 never count for a link). The distance `d(t)`
//! between `P` and a box is therefore `M_P`-Lipschitz in `t`, and with exact distances `d0`,
//! `d1` at the ends of the sub-interval (or lower bounds of them),
//!
//! ```text
//! d(t) >= max(d0 - M_P (t - t0), d1 - M_P (t1 - t)) >= (d0 + d1 - M_P h) / 2.
//! ```
//!
//! Each (part, box) pair is first tried on cheap lower bounds at the two ends (the capsule of a
//! cylinder; balls and boxes are exact anyway): where they prove the whole move, no exact
//! distance is computed. Otherwise it is certified on `[0, 1]` by bisection, left half first: an
//! interval whose bound is `>= clearance` is done; a midpoint closer than `clearance` proves the
//! move unsafe; an interval with `M_P h` below [`MOVE_FLOOR_MM`] (a grazing move) is rejected
//! conservatively. The verdict is the one the bisection alone gives (a pair the lower bounds
//! prove passes the bisection's first interval, exact distances being no smaller). Distances
//! come from [`Solid::distance_aabb`](crate::geometry::Solid) (cylinders: closed-form capsule
//! bounds, parry3d-f64 GJK only in the narrow band between them; balls and oriented boxes:
//! closed forms) and are lowered by [`DISTANCE_SLACK_REL`] before use, which covers GJK's
//! relative stopping tolerance (about `5e-8` in f64) and rounding.
//!
//! The bisection (and [`CollisionModel::min_clearance_along`]'s branch and bound) uses each
//! distance only through monotone tests: an interval's bound against the clearance, a midpoint
//! against the clearance or the best distance so far. Each test is taken on bounds of the
//! distance ([`Measured`]: the capsule bounds, the rim capsules, a loose bracket) and the
//! distance itself is computed only where they leave it open, so every decision, and every
//! figure reported, is the one the distances themselves give (`proof_tests.rs` holds them
//! against the bisections on exact distances, bit for bit).
//!
//! [`Robot::urdf_joints_deg`]: crate::robot::Robot::urdf_joints_deg

use super::slots::Slots;
use super::{Blocked, CollisionModel, Part, Poses};
use crate::geometry::{decide, decide2, rim_capsules_lower_bound, Aabb, Measured, Solid};
use std::ops::Range;

/// Bisection of a move stops (and rejects it) when the largest displacement of a part over the
/// interval, `M_P h`, falls below this, mm.
pub const MOVE_FLOOR_MM: f64 = 1e-3;

/// Distances used in proofs are lowered by `DISTANCE_SLACK_REL * (1 mm + d)`: parry's GJK stops at
/// a relative gap of about 5e-8 in f64 and errs from above.
pub const DISTANCE_SLACK_REL: f64 = 1e-6;

/// Levels of the bisection on cheap lower bounds tried before the exact one
/// (`certify_pair_on_bounds`).
const BOUND_LEVELS: usize = 10;

/// Most distance evaluations one (part, box) pair may spend on a move before the move is
/// rejected (or, in [`CollisionModel::min_clearance_along`], before its bound is returned as is).
pub(super) const MAX_EVALS_PER_PAIR: usize = 1 << 20;

/// The smallest clearance along a move (or a route): a certified lower bound, and the part
/// (link or tool shape) and obstacle it belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Clearance {
    pub mm: f64,
    pub part: Part,
    pub obstacle: String,
}

/// Result of certifying one (part, box) pair along a move.
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
    /// six-axis segment `from -> to` (controller values, linear interpolation) is in range and
    /// keeps every link cylinder and every tool shape at least the clearance from every box. May
    /// reject a safe move (a grazing one, see [`MOVE_FLOOR_MM`]); never accepts an unsafe one.
    /// See the module doc for the proof.
    /// A move answered before is answered again from the model's memo (`memo.rs`), with the
    /// verdict the proof gave.
    pub fn move_is_safe(&self, from: &[f64; 6], to: &[f64; 6]) -> bool {
        self.robot.check_range6(from).is_ok()
            && self.robot.check_range6(to).is_ok()
            && self.proven.verdict(self.clearance_mm, from, to, || {
                self.parts_are_safe(from, to, 0..self.part_count(), self.clearance_mm)
            })
    }

    /// The geometry of [`move_is_safe`](Self::move_is_safe) at another clearance: `true` only if
    /// every configuration on the straight six-axis segment `from -> to` keeps every link
    /// cylinder and tool shape at least `clearance_mm` from every box. The boxes are clipped
    /// [`CLIP_MARGIN_MM`](super::CLIP_MARGIN_MM) beyond the model's own clearance, so a
    /// clearance up to that much larger is measured as on the whole boxes (the proof along a
    /// path asks a fraction of a millimetre more). The range is not checked.
    pub fn move_keeps(&self, from: &[f64; 6], to: &[f64; 6], clearance_mm: f64) -> bool {
        self.parts_are_safe(from, to, 0..self.part_count(), clearance_mm)
    }

    /// The whole-move proof for the link cylinders alone (they depend on axes 1..3 only). The
    /// range is not checked: the caller knows both ends are in range.
    pub(crate) fn links_move_is_safe(&self, from: &[f64; 6], to: &[f64; 6]) -> bool {
        self.parts_are_safe(from, to, 0..self.cyl.len(), self.clearance_mm)
    }

    /// The whole-move proof for the tool shapes alone; `true` without a tool. The range is not
    /// checked.
    pub(crate) fn tool_move_is_safe(&self, from: &[f64; 6], to: &[f64; 6]) -> bool {
        self.parts_are_safe(
            from,
            to,
            self.cyl.len()..self.part_count(),
            self.clearance_mm,
        )
    }

    /// Every (part, box) pair of `parts` certified along the move at clearance `c`. A pair whose cheap lower
    /// bounds at the ends already prove it (the interval bound of the module doc on lower
    /// bounds: the distance is at least a lower bound) costs no exact distance; the others go
    /// through the bisection on distances known as far as each decision needs (`Measured`),
    /// which gives the verdict the exact distances give.
    fn parts_are_safe(&self, from: &[f64; 6], to: &[f64; 6], parts: Range<usize>, c: f64) -> bool {
        if parts.is_empty() {
            return true;
        }
        let flange = parts.end > self.cyl.len();
        let (p0, p1) = (self.poses_for(from, flange), self.poses_for(to, flange));
        let speeds = self.part_speeds(from, to);
        for p in parts {
            let m = speeds[p];
            let (s0, s1) = (self.solid(p, &p0), self.solid(p, &p1));
            for (k, b) in self.part_boxes(p) {
                // A box (a tool's mount) has no closed-form bound cheaper than its exact
                // distance: its enclosing box's gap first. `interval_bound` grows with both
                // ends, so where the gaps keep the clearance over the move the exact distances
                // do too, and the pair is passed as it would be below.
                if matches!(s0, Solid::Box(_)) {
                    let (g0, g1) = (s0.coarse_lower_bound_aabb(b), s1.coarse_lower_bound_aabb(b));
                    if interval_bound(g0, g1, m) >= c {
                        continue;
                    }
                }
                let (l0, l1) = (s0.lower_bound_aabb(b), s1.lower_bound_aabb(b));
                if interval_bound(l0, l1, m) >= c {
                    continue;
                }
                let (l0, l1) = (tight_lower_bound(&s0, b, l0), tight_lower_bound(&s1, b, l1));
                if self.certify_pair_on_bounds(p, k, from, to, m, (l0, l1), c) {
                    continue;
                }
                let ends = (Measured::new(s0, b), Measured::new(s1, b));
                if let PairVerdict::Fails { .. } =
                    self.certify_pair(p, k, from, to, m, ends, c, false)
                {
                    return false;
                }
            }
        }
        true
    }

    /// The bisection of [`certify_pair`](Self::certify_pair) on cheap lower bounds (no GJK),
    /// to [`BOUND_LEVELS`] levels: `true` when it proves the pair. It never proves a pair the
    /// exact bisection refuses: on every interval the exact distances are no smaller, so the
    /// exact bisection proves each interval this one proves, at the same level or sooner.
    #[allow(clippy::too_many_arguments)]
    fn certify_pair_on_bounds(
        &self,
        p: usize,
        k: usize,
        from: &[f64; 6],
        to: &[f64; 6],
        m: f64,
        (l0, l1): (f64, f64),
        c: f64,
    ) -> bool {
        if lowered(l0) < c || lowered(l1) < c {
            return false;
        }
        let b = &self.obstacles[k].aabb;
        let mut stack = [(0.0f64, 0.0f64, 0.0f64, 0.0f64, 0u32); BOUND_LEVELS + 2];
        stack[0] = (0.0, 1.0, l0, l1, 0);
        let mut top = 1usize;
        while top > 0 {
            top -= 1;
            let (t0, t1, d0, d1, level) = stack[top];
            let reach = m * (t1 - t0);
            if interval_bound(d0, d1, reach) >= c {
                continue;
            }
            if level as usize >= BOUND_LEVELS || reach < MOVE_FLOOR_MM {
                return false;
            }
            let tm = 0.5 * (t0 + t1);
            let axes = lerp(from, to, tm);
            let solid = self.solid(p, &self.poses_for(&axes, self.is_tool_part(p)));
            let dm = tight_lower_bound(&solid, b, solid.lower_bound_aabb(b));
            if lowered(dm) < c {
                return false;
            }
            stack[top] = (tm, t1, dm, d1, level + 1);
            stack[top + 1] = (t0, tm, d0, dm, level + 1);
            top += 2;
        }
        true
    }

    /// A certified lower bound of the smallest distance (mm) between any part (link cylinder or
    /// tool shape) and any box along the six-axis move `from -> to`, within `tol_mm` of the true
    /// minimum (branch and bound on the Lipschitz bound of the module doc; `tol_mm` below 1e-6
    /// is raised to it; the bound is further lowered by the [`DISTANCE_SLACK_REL`] slack). The
    /// (part, obstacle) pair named is the witness: the pair seen closest at some instant of the
    /// move, within `tol_mm` (plus the slack) of the bound. Geometry only: the range is not
    /// checked. `None` without obstacles.
    pub fn min_clearance_along(
        &self,
        from: &[f64; 6],
        to: &[f64; 6],
        tol_mm: f64,
    ) -> Option<Clearance> {
        let tol = if tol_mm >= 1e-6 { tol_mm } else { 1e-6 };
        let speeds = self.part_speeds(from, to);
        let mut ends: Vec<_> = (0..self.part_count())
            .map(|p| (self.pair_measures(p, from), self.pair_measures(p, to)))
            .collect();
        // Best attained distance so far: an upper bound of the minimum, and its pair; the first
        // pair (in part, end, box order) at the least distance of the ends. Only the ends whose
        // bounds reach below every end's upper bound can be it: those are made exact.
        let least_hi = ends
            .iter()
            .flat_map(|(a, b)| a.iter().chain(b))
            .fold(f64::INFINITY, |m, d| m.min(d.hi));
        let mut upper = (f64::INFINITY, None);
        for (p, (a, b)) in ends.iter_mut().enumerate() {
            let n = a.len();
            for (k, d) in a.iter_mut().chain(b.iter_mut()).enumerate() {
                let bx = &self.obstacles[k % n].aabb;
                if d.lo <= least_hi && d.value(bx) < upper.0 {
                    upper = (d.lo, Some((p, k % n)));
                }
            }
        }
        let mut result = f64::INFINITY;
        // The distances measured along one pair that the intervals on the stack name.
        let mut seen: Slots<Measured> = Slots::new();
        let mut stack = Vec::new();
        for (p, &m) in speeds.iter().enumerate() {
            for (k, bx) in self.part_boxes(p) {
                seen.clear();
                let (e0, e1) = (seen.put(ends[p].0[k], 1), seen.put(ends[p].1[k], 1));
                let mut evals = 0usize;
                stack.push((0.0f64, 1.0f64, e0, e1));
                while let Some((t0, t1, i0, i1)) = stack.pop() {
                    let reach = m * (t1 - t0);
                    // Prune on the raw bound (so the slack cannot stall the search), record the
                    // slack-lowered one. Every decision is the one the distances themselves
                    // give (`geometry::decide2`).
                    let (d0, d1) = seen.two(i0, i1);
                    let prune = evals >= MAX_EVALS_PER_PAIR
                        || decide2(d0, d1, bx, |x, y| {
                            (0.5 * (x + y - reach)).min(x).min(y) >= upper.0 - tol
                        });
                    if prune {
                        // An interval whose bound is no lower than the best attained distance
                        // cannot lower the result (which is at most that distance).
                        if interval_bound(d0.lo, d1.lo, reach) < upper.0 {
                            let (x, y) = (d0.value(bx), d1.value(bx));
                            result = result.min(interval_bound(x, y, reach));
                        }
                        seen.release(i0);
                        seen.release(i1);
                        continue;
                    }
                    let tm = 0.5 * (t0 + t1);
                    let mut dm = self.pair_measured_at(p, k, from, to, tm);
                    evals += 1;
                    if decide(&mut dm, bx, |x| x < upper.0) {
                        upper = (dm.value(bx), Some((p, k)));
                    }
                    let im = seen.put(dm, 2);
                    stack.push((tm, t1, im, i1));
                    stack.push((t0, tm, i0, im));
                }
            }
        }
        // Every interval was pruned within `tol` of `upper`, so the witness is within `tol` of
        // the bound. Distances are never negative: the slack may have taken the bound below 0.
        let (p, k) = upper.1?;
        Some(Clearance {
            mm: result.min(upper.0).max(0.0),
            part: self.part(p),
            obstacle: self.obstacles[k].name.clone(),
        })
    }

    /// Where a move fails: `(t, why)`, `t` in `[0, 1]`. An end out of range gives `t` = 0 or 1
    /// and [`Blocked::Range`]. Otherwise `t` is the earliest point over all (part, box) pairs
    /// where a pair comes closer than the clearance (everything before it certified, to
    /// [`MOVE_FLOOR_MM`] of part motion), or could not be proven clear (a grazing move; then
    /// `distance_mm` is the failing lower bound). `None` exactly when
    /// [`move_is_safe`](Self::move_is_safe) holds.
    pub fn why_move_unsafe(&self, from: &[f64; 6], to: &[f64; 6]) -> Option<(f64, Blocked)> {
        if let Err(v) = self.robot.check_range6(from) {
            return Some((0.0, Blocked::Range(v)));
        }
        if let Err(v) = self.robot.check_range6(to) {
            return Some((1.0, Blocked::Range(v)));
        }
        self.first_contact(from, to, self.clearance_mm)
    }

    /// The geometry of [`why_move_unsafe`](Self::why_move_unsafe) at clearance `c` (the range
    /// is not checked): the earliest `(t, Contact)` where a pair comes closer than `c` or
    /// cannot be proven to keep it; `None` exactly when [`move_keeps`](Self::move_keeps)
    /// holds at `c`.
    pub fn first_contact(&self, from: &[f64; 6], to: &[f64; 6], c: f64) -> Option<(f64, Blocked)> {
        let speeds = self.part_speeds(from, to);
        let mut first: Option<(f64, usize, usize, f64)> = None;
        for (p, &m) in speeds.iter().enumerate() {
            let d0 = self.pair_measures(p, from);
            let d1 = self.pair_measures(p, to);
            for (k, _) in self.part_boxes(p) {
                if let PairVerdict::Fails { t, d } =
                    self.certify_pair(p, k, from, to, m, (d0[k], d1[k]), c, true)
                {
                    if first.is_none_or(|(tf, _, _, df)| t < tf || (t == tf && d < df)) {
                        first = Some((t, p, k, d));
                    }
                }
            }
        }
        first.map(|(t, p, k, d)| (t, self.contact(p, k, d.max(0.0))))
    }

    /// `M_P` of the module doc for every part: the most any of its points moves over the whole
    /// six-axis move, mm.
    pub(crate) fn part_speeds(&self, from: &[f64; 6], to: &[f64; 6]) -> Vec<f64> {
        let q0 = self.robot.urdf_joints_deg(from);
        let q1 = self.robot.urdf_joints_deg(to);
        let dq: [f64; 6] = std::array::from_fn(|i| (q1[i] - q0[i]).abs().to_radians());
        (0..self.part_count())
            .map(|p| {
                let r = self.part_reach(p);
                (0..6).map(|i| r[i] * dq[i]).sum()
            })
            .collect()
    }

    /// The poses of a configuration, with the flange only when asked for (and the model has a
    /// tool): links alone need three links' poses.
    pub(crate) fn poses_for(&self, axes: &[f64; 6], flange: bool) -> Poses {
        if flange {
            self.poses(axes)
        } else {
            Poses {
                arm: self.cell_link_poses(&super::arm_of(axes)),
                flange: None,
            }
        }
    }

    /// Part `p` placed at `axes`.
    fn part_solid(&self, p: usize, axes: &[f64; 6]) -> Solid {
        self.solid(p, &self.poses_for(axes, self.is_tool_part(p)))
    }

    /// The distances from part `p` to every box at `axes`, as first bounds ([`Measured`]; an
    /// exempt pair's infinite: callers skip those pairs, the slack of `lowered` is not meant
    /// for infinities).
    fn pair_measures(&self, p: usize, axes: &[f64; 6]) -> Vec<Measured> {
        let solid = self.part_solid(p, axes);
        let mut out = vec![Measured::infinite(solid); self.obstacles.len()];
        for (k, b) in self.part_boxes(p) {
            out[k] = Measured::new(solid, b);
        }
        out
    }

    /// The distance from part `p` to box `k` at parameter `t` of the move, as first bounds.
    fn pair_measured_at(
        &self,
        p: usize,
        k: usize,
        from: &[f64; 6],
        to: &[f64; 6],
        t: f64,
    ) -> Measured {
        let solid = self.part_solid(p, &lerp(from, to, t));
        Measured::new(solid, &self.obstacles[k].aabb)
    }

    /// Bisection proof that part `p` keeps clearance `c` from box `k` along the move; `m` is
    /// its `M_P`, `d0`, `d1` the distances at the ends. Left-first depth-first bisection: when an
    /// interval is examined, everything left of it is certified. Without `earliest` the first
    /// failure found is returned; with it, the search goes on left of each witness, so the
    /// witness returned has everything left of it certified (to [`MOVE_FLOOR_MM`] resolution).
    #[allow(clippy::too_many_arguments)]
    fn certify_pair(
        &self,
        p: usize,
        k: usize,
        from: &[f64; 6],
        to: &[f64; 6],
        m: f64,
        (e0, e1): (Measured, Measured),
        c: f64,
        earliest: bool,
    ) -> PairVerdict {
        // Every test below is taken as the distances themselves answer it
        // (`geometry::decide`); a distance reported is exact.
        let b = &self.obstacles[k].aabb;
        let fails = |d: f64| lowered(d) < c;
        let mut seen = Slots::new();
        let (e0, e1) = (seen.put(e0, 1), seen.put(e1, 1));
        if decide(seen.get(e0), b, fails) {
            return PairVerdict::Fails {
                t: 0.0,
                d: seen.get(e0).value(b),
            };
        }
        // The earliest witness found so far.
        let mut best: Option<(f64, f64)> = None;
        if decide(seen.get(e1), b, fails) {
            let d = seen.get(e1).value(b);
            if !earliest {
                return PairVerdict::Fails { t: 1.0, d };
            }
            best = Some((1.0, d));
        }
        // The stack holds (t0, t1, i0, i1), the ends' distances in `seen`; the left half is
        // pushed last, popped first.
        let mut stack = [(0.0f64, 0.0f64, 0usize, 0usize); 64];
        stack[0] = (0.0, 1.0, e0, e1);
        let mut top = 1usize;
        let mut evals = 0usize;
        while top > 0 {
            top -= 1;
            let (t0, t1, i0, i1) = stack[top];
            if best.is_some_and(|(tb, _)| t0 >= tb) {
                // Right of a witness.
                seen.release(i0);
                seen.release(i1);
                continue;
            }
            let reach = m * (t1 - t0);
            let (d0, d1) = seen.two(i0, i1);
            if decide2(d0, d1, b, |x, y| interval_bound(x, y, reach) >= c) {
                seen.release(i0);
                seen.release(i1);
                continue;
            }
            let tm = 0.5 * (t0 + t1);
            if reach < MOVE_FLOOR_MM || evals >= MAX_EVALS_PER_PAIR || top + 2 > stack.len() {
                // Everything left of t0 is certified. A failing right end (t = 1 or a witness)
                // is the answer; otherwise this interval could not be proven clear.
                return if decide(d1, b, fails) {
                    PairVerdict::Fails {
                        t: t1,
                        d: d1.value(b),
                    }
                } else {
                    let lb = interval_bound(d0.value(b), d1.value(b), reach);
                    PairVerdict::Fails { t: tm, d: lb }
                };
            }
            let mut dm = self.pair_measured_at(p, k, from, to, tm);
            evals += 1;
            let failing = decide(&mut dm, b, fails);
            if failing {
                let d = dm.value(b);
                if !earliest {
                    return PairVerdict::Fails { t: tm, d };
                }
                best = Some((tm, d));
                // Only the left half stays: it names the start and the midpoint.
                seen.release(i1);
                let im = seen.put(dm, 1);
                stack[top] = (t0, tm, i0, im);
                top += 1;
                continue;
            }
            let im = seen.put(dm, 2);
            stack[top] = (tm, t1, im, i1);
            stack[top + 1] = (t0, tm, i0, im);
            top += 2;
        }
        match best {
            Some((t, d)) => PairVerdict::Fails { t, d },
            None => PairVerdict::Safe,
        }
    }
}

/// A lower bound of a solid's distance to a box, better than `capsule` (its cheap bound) where a
/// flat cap of a cylinder faces the box: capsules about shortened axes that still hold the cap
/// rims (`geometry::rim_capsules_lower_bound`), as `link_clear_of_box` uses them. Closed forms
/// only, no GJK.
#[inline]
pub(super) fn tight_lower_bound(s: &Solid, b: &Aabb, capsule: f64) -> f64 {
    match s {
        Solid::Cylinder(c) => capsule.max(rim_capsules_lower_bound(c, b)),
        _ => capsule,
    }
}

/// A distance lowered by the slack that covers GJK's tolerance.
#[inline]
pub(super) fn lowered(d: f64) -> f64 {
    if d.is_finite() {
        d - DISTANCE_SLACK_REL * (1.0 + d.abs())
    } else {
        d
    }
}

/// Certified lower bound of an `M`-Lipschitz distance on an interval where the part moves at
/// most `reach` mm, from its raw end values or lower bounds of them (lowered by the slack here).
#[inline]
pub(super) fn interval_bound(d0: f64, d1: f64, reach: f64) -> f64 {
    let (l0, l1) = (lowered(d0), lowered(d1));
    (0.5 * (l0 + l1 - reach)).min(l0).min(l1)
}

/// Linear interpolation of controller values.
#[inline]
pub(super) fn lerp<const N: usize>(from: &[f64; N], to: &[f64; N], t: f64) -> [f64; N] {
    std::array::from_fn(|i| from[i] + t * (to[i] - from[i]))
}
