//! Corners: the proof behind a fly-by zone at a waypoint (beyond the paper, whose moves all
//! stop).
//!
//! With a zone at waypoint `V` between the moves `P -> V` and `V -> N`, the controller leaves the
//! first move before `V` and joins the second after it, never cutting more than half of either
//! move; the corner path of a joint move is a blend of the two moves, so it stays inside the
//! triangle of six-axis joint space spanned by `A` (the midpoint of `P -> V`), `V` and `B` (the
//! midpoint of `V -> N`). The rest of the path lies on the two moves, which are proven apart
//! ([`CollisionModel::move_is_safe`]). [`CollisionModel::corner_is_safe`] proves that every
//! configuration of that triangle keeps every part (link cylinders and tool shapes) at least the
//! clearance from every box. Conservative, like the move proof: it may refuse a safe corner,
//! it never accepts an unsafe one.
//!
//! *Range.* The axis ranges and the coupled range are convex and `A`, `V`, `B` lie on proven
//! moves, so the whole triangle is in range.
//!
//! *Bound.* The controller coupling is linear, so the triangle is a triangle in URDF values too.
//! For part `P` write `N_P(x) = sum_i R[i][P] |x_i|` (rad; `R` the reach bounds of `proof.rs`):
//! no point of `P` moves more than `N_P(q - q')` between configurations `q` and `q'` (the
//! straight move between them is `N_P`-Lipschitz, module doc of `proof.rs`). For `q` in the
//! triangle with vertices `v_j` and barycentric weights `l_j`, and `d` the distance of `P` to a
//! box:
//!
//! ```text
//! d(q) >= d(v_j) - N_P(q - v_j) >= d(v_j) - M_j,   M_j = sum_i R[i][P] max_l |v_l,i - v_j,i|
//! d(q) >= sum_j l_j (d(v_j) - N_P(q - v_j)) >= min_j d(v_j) - 2/3 max_{j,l} N_P(v_l - v_j)
//! ```
//!
//! (the first by convexity of `|.|` over the triangle; the second since
//! `sum_j l_j N_P(q - v_j) <= sum_{j,l} l_j l_l N_P(v_l - v_j) <= e (1 - sum_j l_j^2)` and
//! `sum_j l_j^2 >= 1/3`). The larger of the two is the triangle's bound. Each (part, box) pair is
//! tried on the cheap lower bounds at the three vertices first; otherwise the triangle is split
//! in two at the midpoint of its longest edge (in `N_P`), recursively, on exact distances (lowered by the slack of
//! `proof.rs`): a triangle whose bound keeps the clearance is done, a vertex closer than the
//! clearance refuses the corner, and so does a triangle whose parts move less than
//! [`CORNER_FLOOR_MM`] across it, a depth of [`CORNER_LEVELS`], or a pair that spends
//! [`MAX_TRIANGLES_PER_PAIR`] triangles.
//!
//! [`CollisionModel::min_clearance_over_corner`] certifies the smallest clearance over the
//! triangle the same way (branch and bound within a tolerance), so the route's smallest
//! clearance covers its zoned corners too.

use super::proof::{lerp, lowered, tight_lower_bound};
use super::{Clearance, CollisionModel};
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// A corner triangle whose parts move less than this across it, with the clearance still
/// unproven, refuses the corner, mm.
pub const CORNER_FLOOR_MM: f64 = 0.05;

/// Most levels of the bisection (two levels halve every edge, as one four-way split would).
pub const CORNER_LEVELS: u32 = 40;

/// Most triangles one (part, box) pair may split before the corner is refused (or, for the
/// smallest clearance, its bound is returned as is).
pub const MAX_TRIANGLES_PER_PAIR: usize = 1 << 16;

/// A triangle of controller values with the distances of one pair at its vertices.
#[derive(Clone, Copy)]
struct Tri {
    v: [[f64; 6]; 3],
    d: [f64; 3],
    level: u32,
}

/// A triangle ranked by its bound, smallest first in a `BinaryHeap`.
struct Ranked(f64, Tri);

impl PartialEq for Ranked {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Ranked {}
impl PartialOrd for Ranked {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Ranked {
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0)
    }
}

impl CollisionModel {
    /// The corner triangle at `via` between the moves `prev -> via` and `via -> next`: the
    /// midpoint of the first move, the via and the midpoint of the second (module doc).
    pub fn corner_triangle(prev: &[f64; 6], via: &[f64; 6], next: &[f64; 6]) -> [[f64; 6]; 3] {
        [lerp(prev, via, 0.5), *via, lerp(via, next, 0.5)]
    }

    /// `true` only if every configuration of the corner triangle at `via` (module doc) keeps
    /// every part at least the clearance from every box. The moves `prev -> via` and
    /// `via -> next` are the caller's to prove (and must be, for the range argument).
    pub fn corner_is_safe(&self, prev: &[f64; 6], via: &[f64; 6], next: &[f64; 6]) -> bool {
        let tri = Self::corner_triangle(prev, via, next);
        let c = self.clearance_mm;
        let flange = self.tool.is_some();
        let poses: Vec<_> = tri.iter().map(|q| self.poses_for(q, flange)).collect();
        for p in 0..self.part_count() {
            let solids: Vec<_> = poses.iter().map(|ps| self.solid(p, ps)).collect();
            for (k, b) in self.part_boxes(p) {
                let cheap: [f64; 3] = std::array::from_fn(|j| {
                    tight_lower_bound(&solids[j], b, solids[j].lower_bound_aabb(b))
                });
                if self.triangle_bound(p, &tri, &cheap) >= c {
                    continue;
                }
                let d: [f64; 3] = std::array::from_fn(|j| solids[j].distance_aabb(b));
                if !self.certify_triangle(
                    p,
                    k,
                    Tri {
                        v: tri,
                        d,
                        level: 0,
                    },
                ) {
                    return false;
                }
            }
        }
        true
    }

    /// A certified lower bound (mm) of the smallest distance between any part and any box over
    /// the corner triangle at `via`, within `tol_mm` of the true minimum where the budget allows
    /// (slack-lowered, never negative), with the pair seen closest. `None` without obstacles.
    pub fn min_clearance_over_corner(
        &self,
        prev: &[f64; 6],
        via: &[f64; 6],
        next: &[f64; 6],
        tol_mm: f64,
    ) -> Option<Clearance> {
        let tol = tol_mm.max(1e-6);
        let tri = Self::corner_triangle(prev, via, next);
        let mut upper = (f64::INFINITY, None);
        let mut roots = Vec::new();
        for p in 0..self.part_count() {
            for (k, _) in self.part_boxes(p) {
                let d: [f64; 3] = std::array::from_fn(|j| self.pair_distance(p, k, &tri[j]));
                for &dj in &d {
                    if dj < upper.0 {
                        upper = (dj, Some((p, k)));
                    }
                }
                roots.push((
                    p,
                    k,
                    Tri {
                        v: tri,
                        d,
                        level: 0,
                    },
                ));
            }
        }
        // Best first: the triangle with the smallest bound is split next, so when a pair's
        // budget runs out the bound left is the best that budget gives.
        let mut result = f64::INFINITY;
        for (p, k, root) in roots {
            let mut heap = BinaryHeap::new();
            heap.push(Ranked(self.raw_bound(p, &root.v, &root.d), root));
            let mut spent = 0usize;
            while let Some(Ranked(raw, t)) = heap.pop() {
                if raw >= upper.0 - tol
                    || spent >= MAX_TRIANGLES_PER_PAIR
                    || t.level >= CORNER_LEVELS
                {
                    // Every triangle left has a bound no smaller.
                    result = result.min(self.triangle_bound(p, &t.v, &t.d));
                    for Ranked(_, rest) in heap.drain() {
                        result = result.min(self.triangle_bound(p, &rest.v, &rest.d));
                    }
                    break;
                }
                spent += 1;
                for ch in self.split(p, k, &t) {
                    for &dj in &ch.d {
                        if dj < upper.0 {
                            upper = (dj, Some((p, k)));
                        }
                    }
                    heap.push(Ranked(self.raw_bound(p, &ch.v, &ch.d), ch));
                }
            }
        }
        let (p, k) = upper.1?;
        Some(Clearance {
            mm: result.min(upper.0).max(0.0),
            part: self.part(p),
            obstacle: self.obstacles[k].name.clone(),
        })
    }

    /// The bisection proof of one pair over a triangle (module doc).
    fn certify_triangle(&self, p: usize, k: usize, root: Tri) -> bool {
        let c = self.clearance_mm;
        if root.d.iter().any(|&d| !d.is_finite() || lowered(d) < c) {
            return false;
        }
        let mut stack = vec![root];
        let mut spent = 0usize;
        while let Some(t) = stack.pop() {
            if self.triangle_bound(p, &t.v, &t.d) >= c {
                continue;
            }
            if t.level >= CORNER_LEVELS
                || spent >= MAX_TRIANGLES_PER_PAIR
                || self.triangle_reach(p, &t.v) < CORNER_FLOOR_MM
            {
                return false;
            }
            spent += 1;
            let children = self.split(p, k, &t);
            if children
                .iter()
                .any(|ch| ch.d.iter().any(|&d| lowered(d) < c))
            {
                return false;
            }
            stack.extend(children);
        }
        true
    }

    /// The two triangles of `t` split at the midpoint of its longest edge (in `N_P`), with the
    /// pair's distances: one new distance per split, and a thin triangle (a corner along a
    /// nearly straight route) is cut across its length, like a move.
    fn split(&self, p: usize, k: usize, t: &Tri) -> [Tri; 2] {
        let r = self.part_reach(p);
        let q: Vec<[f64; 6]> = t.v.iter().map(|x| self.robot.urdf_joints_deg(x)).collect();
        let edge = |j: usize, l: usize| -> f64 {
            (0..6)
                .map(|i| r[i] * (q[l][i] - q[j][i]).abs().to_radians())
                .sum()
        };
        // The longest edge `j -> j + 1`, opposite vertex `o`.
        let j = (0..3)
            .max_by(|&a, &b| edge(a, (a + 1) % 3).total_cmp(&edge(b, (b + 1) % 3)))
            .unwrap_or(0);
        let (l, o) = ((j + 1) % 3, (j + 2) % 3);
        let m = lerp(&t.v[j], &t.v[l], 0.5);
        let dm = self.pair_distance(p, k, &m);
        let level = t.level + 1;
        [
            Tri {
                v: [t.v[j], m, t.v[o]],
                d: [t.d[j], dm, t.d[o]],
                level,
            },
            Tri {
                v: [m, t.v[l], t.v[o]],
                d: [dm, t.d[l], t.d[o]],
                level,
            },
        ]
    }

    /// Distance from part `p` to box `k` at `axes`.
    fn pair_distance(&self, p: usize, k: usize, axes: &[f64; 6]) -> f64 {
        let solid = self.solid(p, &self.poses_for(axes, self.is_tool_part(p)));
        solid.distance_aabb(&self.obstacles[k].aabb)
    }

    /// Per vertex `j`, `M_j` of the module doc, and the largest edge in `N_P`, mm.
    fn triangle_spans(&self, p: usize, v: &[[f64; 6]; 3]) -> ([f64; 3], f64) {
        let r = self.part_reach(p);
        let q: Vec<[f64; 6]> = v.iter().map(|x| self.robot.urdf_joints_deg(x)).collect();
        let m: [f64; 3] = std::array::from_fn(|j| {
            (0..6)
                .map(|i| {
                    let most = (0..3)
                        .map(|l| (q[l][i] - q[j][i]).abs())
                        .fold(0.0, f64::max);
                    r[i] * most.to_radians()
                })
                .sum()
        });
        let edge = |j: usize, l: usize| -> f64 {
            (0..6)
                .map(|i| r[i] * (q[l][i] - q[j][i]).abs().to_radians())
                .sum()
        };
        (m, edge(0, 1).max(edge(1, 2)).max(edge(2, 0)))
    }

    /// The most any point of part `p` moves across the triangle, mm.
    fn triangle_reach(&self, p: usize, v: &[[f64; 6]; 3]) -> f64 {
        self.triangle_spans(p, v).1
    }

    /// The certified lower bound of the module doc on (slack-lowered) vertex distances `d`.
    fn triangle_bound(&self, p: usize, v: &[[f64; 6]; 3], d: &[f64; 3]) -> f64 {
        let (m, e) = self.triangle_spans(p, v);
        let l = d.map(lowered);
        if l.iter().any(|x| x.is_nan()) {
            return f64::NEG_INFINITY;
        }
        let least = l[0].min(l[1]).min(l[2]);
        let by_vertex = (0..3)
            .map(|j| l[j] - m[j])
            .fold(f64::NEG_INFINITY, f64::max);
        by_vertex.max(least - 2.0 / 3.0 * e)
    }

    /// The same bound on raw distances (pruning in the branch and bound).
    fn raw_bound(&self, p: usize, v: &[[f64; 6]; 3], d: &[f64; 3]) -> f64 {
        let (m, e) = self.triangle_spans(p, v);
        let least = d[0].min(d[1]).min(d[2]);
        let by_vertex = (0..3)
            .map(|j| d[j] - m[j])
            .fold(f64::NEG_INFINITY, f64::max);
        by_vertex.max(least - 2.0 / 3.0 * e)
    }
}

#[cfg(test)]
mod tests {
    //! The corner proof against dense sampling of the triangle on the real IRB 1400 model.
    use super::*;
    use crate::cell::Obstacle;
    use crate::geometry::{Aabb, Point};
    use crate::place::Placement;
    use crate::robot::Robot;

    fn model(boxes: Vec<Obstacle>) -> CollisionModel {
        let placement = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        CollisionModel::new(&Robot::irb1400(), placement, boxes, 10.0, None)
    }

    /// The smallest distance seen on a barycentric grid of `n` steps over the triangle.
    fn sampled_min(m: &CollisionModel, tri: &[[f64; 6]; 3], n: usize) -> f64 {
        let mut least = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=(n - i) {
                let (a, b) = (i as f64 / n as f64, j as f64 / n as f64);
                let q: [f64; 6] = std::array::from_fn(|x| {
                    (1.0 - a - b) * tri[0][x] + a * tri[1][x] + b * tri[2][x]
                });
                for (_, s) in m.solids(&q) {
                    for o in &m.obstacles {
                        least = least.min(s.distance_aabb(&o.aabb));
                    }
                }
            }
        }
        least
    }

    #[test]
    fn a_corner_is_accepted_only_where_dense_sampling_keeps_the_clearance() {
        // A post in front of the arm; corners swing past it at various depths.
        let post = Obstacle::new(
            "post",
            Aabb::new(
                Point::new(700.0, -100.0, 0.0),
                Point::new(900.0, 100.0, 1000.0),
            ),
        );
        let m = model(vec![post]);
        let (mut accepted, mut refused) = (0, 0);
        // The ends lean towards the post, the via stands back: the corner cuts towards it.
        for k in 0..36 {
            let (lean, back) = ((k % 6) as f64 * 14.0, (k / 6) as f64 * 8.0);
            let prev = [-50.0, lean, 0.0, 0.0, 30.0, 0.0];
            let via = [0.0, -back, 0.0, 0.0, 30.0, 0.0];
            let next = [50.0, lean, 0.0, 0.0, 30.0, 0.0];
            if !(m.move_is_safe(&prev, &via) && m.move_is_safe(&via, &next)) {
                continue;
            }
            let tri = CollisionModel::corner_triangle(&prev, &via, &next);
            let sampled = sampled_min(&m, &tri, 40);
            let bound = m.min_clearance_over_corner(&prev, &via, &next, 0.05);
            if let Some(b) = &bound {
                assert!(
                    b.mm <= sampled + 1e-6,
                    "bound {} above sample {sampled}",
                    b.mm
                );
            }
            if m.corner_is_safe(&prev, &via, &next) {
                accepted += 1;
                assert!(sampled >= 10.0, "corner {k} accepted, sampled {sampled}");
                assert!(
                    bound.as_ref().is_some_and(|b| b.mm >= 10.0 - 0.05),
                    "{k}: {bound:?} sampled {sampled}"
                );
            } else {
                refused += 1;
            }
        }
        assert!(
            accepted > 0 && refused > 0,
            "{accepted} accepted, {refused} refused"
        );
    }
}
