//! Block inspection along a grid column (beyond the paper): a run of consecutive nodes
//! `a3[lo..hi]` of one column is proven free, or blocked, at once by the motion bound of
//! `proof.rs`, and split in halves only where neither proof holds, down to runs of
//! [`LEAF_NODES`] nodes, which are tried for blocked at once (*Blocked leaves* below) and else
//! inspected node by node (`column.rs`). A column starts as runs of [`TOP_RUN_NODES`] nodes.
//!
//! *Motion over a run.* Within a column axes 1 and 2 are fixed, so between the run's middle
//! angle `q_c` (URDF joint 3, from the slice's table, *Angles* below, for the arm's runs and
//! the tool's alike) and any of its nodes only joint 3 moves, by at most `h` (the most any
//! node lies from `q_c`): no point of a part with reach `R[2][P]` moves more than `M = R[2][P] h` (raised by 1e-9 relative and 1e-9 mm over its
//! float value, as in `grid.rs`). The runs need the column's values in ascending order (the
//! grid's are); a column that is not is inspected node by node.
//!
//! *Free.* For a (cylinder, box) pair with capsule distance `l` at `q_c`, every node of the
//! run keeps at least `l - M` from the box. Where `l - M` is at least `deep_mm` of the arm's
//! scale (`grid.rs`: the distance from which the depth is `K`), the pair leaves every node of
//! the run free with depth `K`; where it is only above the clearance `c`, every node of the run
//! is free as far as this pair goes, and its depth is at most that of `l - M` (the run's own
//! bound, shallower than a node measured alone would get). Either way the pair is dropped from
//! the run's halves. A run without pairs left keeps its codes as they are: no per-node work at
//! all. So the free bit stays the node test's (a dropped pair's exact test would answer free,
//! above the clearance by more than the margin), and every depth stays a lower bound. The
//! depths only decide which steps the codes prove before the whole-move proof is asked
//! (`grid.rs`), so shallower ones cost the planner time, never a different answer; runs stop
//! at the clearance rather than at `deep_mm`, which makes the grid build cheaper
//! (`benches/README.md`).
//!
//! *Blocked.* A ball of radius `rho = min(r, L/2)` about a point of the cylinder's axis at
//! least `rho` from both ends lies in the cylinder (the inner capsule of `geometry`). With `s`
//! an upper bound of the least signed distance (negative inside) from the box of such points
//! at `q_c` (the segment's distance when it stays outside, else 0 or a deeper sample),
//! every node of the run has a ball within `max(0, s + M)` of the box, hence a cylinder
//! distance of at most `max(0, s + M - rho)`. Where `s + M - rho <= c - margin` the whole run
//! is within the clearance (at distance 0 when `c` = 0): every node is blocked, as the node
//! test would find (the margin, `1e-6 (1 mm + c)`, is far above the exact decision's rounding).
//! `s` needs no second segment query: the axis' squared distance from the box is convex along
//! it, so the inner axis' nearest point is the whole axis' (found for `l`) clamped into the
//! inner part; and any point of the inner axis would give an upper bound.
//!
//! *Blocked leaves* (beyond the paper). A run of [`LEAF_NODES`] nodes is not proven free at
//! once (its nodes' own depths are kept), but it is tried for *Blocked* before its node tests,
//! with a second ball besides the inner capsule's: radius `rho' = min(r, L / 2) / 8` at the rim
//! of the cap nearer the box (centre `rho'` inside the cap and `r - rho'` off the axis towards
//! the box, so the ball lies in the cylinder, a short one's thickness too; `s'` its centre's
//! signed distance, bound `s' + m - rho'`). Where a leaf's motion `m` is below the clearance,
//! a leaf whose middle pose is within `c - m` of a box is blocked without penetrating it (else
//! the middle must touch the box), and the rim ball proves the
//! cap's rim near a box, which the inner capsule (held `rho` back from the caps) cannot. A
//! blocked proof changes no code: its nodes are 0, what their node tests would find; it only
//! spares those tests (a good part of the leaves: `benches/README.md`). Runs of up to
//! `2 LEAF_NODES` nodes try the rim ball too where the inner capsule's bound fails; longer
//! runs do not (their `m` needs a deep penetration, which the inner capsule mostly shows
//! already: there the ball cost more than it spared).
//!
//! *The tool.* The wrist centre `C` moves at most `m = R[2][C] h` over a run; `f` is a box's
//! distance from `C` at `q_c` less the tool's radius `R_T`. Where `f - m` is at least `deep_mm`
//! of the tool's scale, the box leaves every node of the run with the tool far (bit 6 clear)
//! and depth `K`; where it is only above the near test's threshold (`c + 1e-6 (1 + f)`, for any
//! `f`), far with the depth of `f - m`. Where `f + m` is at most `c` (less the margin), every
//! node of the run is near with tool depth 0, what each node measured alone would get (the near
//! bit is an OR over the boxes, the depth a least), and the run is done. So the near bits are
//! exactly the node path's (`block_tests.rs`); only depths may be shallower.
//!
//! Nodes of halved runs get the node path's depths, where the second node of a 2-node run may
//! reuse the first's bound (`block_tests.rs`: about 14 % of the free nodes of random cells come
//! out shallower than measured alone, none deeper). The split points depend on the
//! column alone, so the result does not depend on the threads. A top run may drop a box
//! unmeasured by its bound carried from an earlier column of the slice (`column.rs`), only
//! where the measurement would have dropped it with depth `K`: the same codes.
//!
//! *Angles.* The run's middle is read from the slice's table (`Angles`: the value between
//! its two central nodes, inside the run), and `h` is the larger of its distances to the run's
//! first and last values: every node of the run lies within `h` of it.

use super::angles::Angles;
use super::clear::{axis_nearest, link_clear_near};
use super::grid::{GridCheck, ARM_BITS, DEPTH_LEVELS};
use crate::cell::Obstacle;
use crate::geometry::{closest_param_segment_aabb, distance_point_aabb, Aabb, Cylinder, Point};
use nalgebra::Vector3;

/// A column is cut into runs of this many nodes before any halving. Longer runs almost never
/// prove anything (the column's culling has already dropped the boxes its whole sweep keeps
/// clear of), and halving the whole column costs calls at levels that rarely drop a box; 32
/// costs the trunk's grid build fewest instructions of 16, 32 and 64 (`benches/README.md`).
pub(super) const TOP_RUN_NODES: usize = 32;

/// Runs of at most this many nodes are inspected node by node.
pub(super) const LEAF_NODES: usize = 2;

/// Most boxes one run looks at (the indices live on the stack): the column's chunk of boxes.
pub(super) const SET: usize = 64;

/// Margin (mm) of the proofs against the rounding of the distances.
pub(super) const MARGIN_MM: f64 = 1e-6;

/// The tool-near bit and tool-depth bits of a code.
const TOOL_BITS: u8 = 0x78;

/// A point of link 3 (or an end of a cylinder's axis) split about joint 3's axis, cell frame:
/// `p(q) = par + cos q perp + sin q cross` after a joint-3 rotation `q`.
pub(super) type Split = (Point, Vector3<f64>, Vector3<f64>);

/// `p(q)` of a split point from `sin q` and `cos q`.
#[inline]
fn turned(s: &Split, sn: f64, co: f64) -> Point {
    s.0 + s.1 * co + s.2 * sn
}

/// A cylinder moved by axis 3 in one column, and the chunk of boxes it is checked against.
pub(super) struct Swept<'b> {
    pub ends: [Split; 2],
    pub radius: f64,
    /// `R[2][L]`, mm.
    pub reach_mm: f64,
    /// The most any point moves per radian of axis 2, axes 1 and 3 fixed, mm (`grid.rs`).
    pub shift_mm: f64,
    pub boxes: &'b [Obstacle],
    /// `deep_mm` of the arm's scale.
    pub deep: f64,
    pub span: f64,
}

impl Swept<'_> {
    /// The cylinder at the axis-3 angle of sine `sn` and cosine `co` (the ends are split for
    /// axis 3's value, not URDF joint 3's: `column.rs`).
    #[inline]
    fn at(&self, (sn, co): (f64, f64)) -> Cylinder {
        Cylinder {
            a: turned(&self.ends[0], sn, co),
            b: turned(&self.ends[1], sn, co),
            radius: self.radius,
        }
    }
}

/// The wrist centre in one column, and the chunk of boxes the tool is checked against.
pub(super) struct Centre<'b> {
    pub split: Split,
    /// `R[2][C]`, mm.
    pub reach_mm: f64,
    /// The tool's radius `R_T` about `C`, mm.
    pub radius: f64,
    pub boxes: &'b [&'b Aabb],
    /// `deep_mm` of the tool's scale.
    pub deep: f64,
}

/// Signed distance of a point from a box: the distance outside, minus the depth inside.
#[inline]
pub(super) fn signed_distance_point_aabb(p: &Point, b: &Aabb) -> f64 {
    let e = (b.min - p).sup(&(p - b.max));
    let out = e.sup(&Vector3::zeros()).norm();
    out + e.x.max(e.y).max(e.z).min(0.0)
}

/// A bound `s + m - rho` whose positive part is an upper bound of the distance between
/// cylinder `c` and box `b` at every pose where no point of `c` moved more than `m` (module
/// doc, *Blocked*): `s` is the least signed distance of the inner capsule's axis from the box
/// where the axis stays outside (the segment's distance), else the least of 0 and five samples.
#[inline]
#[cfg(test)]
pub(super) fn blocked_bound(c: &Cylinder, b: &Aabb, m: f64) -> f64 {
    blocked_bound_at(c, b, m, closest_param_segment_aabb(&c.a, &(c.b - c.a), b))
}

/// [`blocked_bound`] with `t` the parameter of the point of the whole axis `c.a + t (c.b -
/// c.a)` nearest the box (`closest_param_segment_aabb`, which the capsule distance found
/// already). The squared distance from the box along the axis is convex in `t`, so on the
/// inner capsule's axis, the part `[rho / L, 1 - rho / L]` of it, the nearest point is at `t`
/// clamped into that range: one point, not a second segment query. Any point of the inner axis
/// serves for `s` (its distance is at least the least signed distance), so the bound is an
/// upper bound whatever `t` is; with the nearest `t` it is the segment's distance.
#[inline]
pub(super) fn blocked_bound_at(c: &Cylinder, b: &Aabb, m: f64, t: f64) -> f64 {
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius.max(0.0);
    let rho = r.min(0.5 * len);
    let (p, q, inner) = if len > 0.0 {
        let f = rho / len;
        (c.a + d * f, c.b - d * f, c.a + d * t.max(f).min(1.0 - f))
    } else {
        (c.a, c.a, c.a)
    };
    // Outside the box the least signed distance is the inner axis' distance; an inner axis
    // that meets the box has a least signed distance of at most 0 and of at most each sample's.
    let outside = distance_point_aabb(&inner, b);
    let s = if outside > 0.0 {
        outside
    } else {
        [0.0, 0.25, 0.5, 0.75, 1.0]
            .iter()
            .map(|&t| signed_distance_point_aabb(&(p + (q - p) * t), b))
            .fold(0.0, f64::min)
    };
    s + m - rho
}

/// A bound `s + m - rho'` like [`blocked_bound`]'s with a small ball at the rim of the cap
/// nearer the box: radius `rho' = min(r, L/2) / 8`, its centre `rho'` inside the cap and
/// `r - rho'` off the axis towards the box point nearest the cap's axis point, so the ball
/// lies in the cylinder (beyond the paper).
#[inline]
pub(super) fn rim_ball_bound(c: &Cylinder, b: &Aabb, m: f64, t: f64) -> f64 {
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius.max(0.0);
    if !(len > 0.0 && r > 0.0) {
        return f64::INFINITY;
    }
    let u = d / len;
    let rho = 0.125 * r.min(0.5 * len);
    let axial = if t <= 0.5 {
        c.a + u * rho
    } else {
        c.b - u * rho
    };
    let w = crate::geometry::clamp_to_box(&axial, b) - axial;
    let perp = w - u * u.dot(&w);
    let n = perp.norm();
    let centre = if n > 0.0 {
        axial + perp * ((r - rho) / n)
    } else {
        axial
    };
    signed_distance_point_aabb(&centre, b) + m - rho
}

/// Link 3's cylinder at the middle of nodes `lo..hi` of a column, its axis, and the most any
/// node of the run lies from it (`motion`: joint 3 moves by the same angle as axis 3 within a
/// column). This and the two below are forced inline: left to the compiler they stay calls,
/// which cost the grid build more instructions (`benches/README.md`).
#[inline(always)]
fn run_middle(s: &Swept<'_>, a: &Angles, lo: usize, hi: usize) -> (Cylinder, Vector3<f64>, f64) {
    let mid = lo + hi - 1;
    let v = a.mid_deg[mid];
    let h = (v - a.deg[lo]).max(a.deg[hi - 1] - v).to_radians();
    let cyl = s.at(a.mid_sc[mid]);
    (cyl, cyl.b - cyl.a, motion(s.reach_mm, h))
}

/// The capsule distance of `cyl` (axis `axis`) to `b` (`distance_capsule_aabb`'s very
/// operations), with the axis parameter of the point nearest the box, for the blocked bound.
#[inline(always)]
fn capsule_near(cyl: &Cylinder, axis: &Vector3<f64>, b: &Aabb) -> (f64, f64) {
    let t = closest_param_segment_aabb(&cyl.a, axis, b);
    let lb = (distance_point_aabb(&(cyl.a + axis * t), b) - cyl.radius.max(0.0)).max(0.0);
    (t, lb)
}

/// Whether box `b`, at capsule distance `lb` (nearest axis parameter `t`) from a run's middle
/// cylinder, blocks every node of a run that moves it at most `m`, by the inner capsule's bound
/// or, when `rim`, the rim ball's (module doc, *Blocked leaves*); `c` the clearance.
#[inline(always)]
fn blocks_run(cyl: &Cylinder, b: &Aabb, m: f64, t: f64, lb: f64, c: f64, rim: bool) -> bool {
    let enough = c - MARGIN_MM * (1.0 + c);
    lb <= (c - m).max(0.0)
        && (blocked_bound_at(cyl, b, m, t) <= enough
            || (rim && rim_ball_bound(cyl, b, m, t) <= enough))
}

/// The least tool distance `f` that is not near for `tool_nodes` whatever its size: `f > c +
/// 1e-6 (1 + f)` holds for every `f` above it.
#[inline]
fn not_near(c: f64) -> f64 {
    (c + 1e-6) / (1.0 - 1e-6) + 1e-9
}

/// Lowers the depth at bits `shift..shift + 3` of every free code to at most `q` (the arm's at
/// 0, the tool's at 3).
#[inline]
fn cap_depth(codes: &mut [u8], shift: u8, q: u8) {
    let mask = DEPTH_LEVELS << shift;
    for f in codes.iter_mut().filter(|f| **f != 0) {
        if (*f & mask) >> shift > q {
            *f = (*f & !mask) | (q << shift);
        }
    }
}

/// The motion bound over a run: `reach * h`, raised over its float value (module doc).
#[inline]
pub(super) fn motion(reach: f64, h: f64) -> f64 {
    (reach * h) * (1.0 + 1e-9) + 1e-9
}

impl GridCheck {
    /// The codes of nodes `lo..hi` of a column for cylinder `s` against the boxes `set` (indices
    /// into `s.boxes`): the run's proofs (module doc), else its halves, else node by node.
    /// `a.deg` must be ascending.
    ///
    /// `memo` (a top run's): per box of `s.boxes`, the free bound `l - M` (less the margin)
    /// this run had at an earlier column of the slice and axis 2 there (rad), with axis 2 here:
    /// the run's middle cylinder has moved at most `shift_mm |da2|` since, so a box whose bound
    /// less that is still `deep` or more is dropped unmeasured (what the capsule would give).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn arm_run(
        &self,
        s: &Swept<'_>,
        a: &Angles,
        out: &mut [u8],
        lo: usize,
        hi: usize,
        set: &[u8],
        mut memo: Option<(&mut [(f64, f64)], f64)>,
    ) {
        if set.is_empty() || out[lo..hi].iter().all(|&f| f == 0) {
            return;
        }
        if hi - lo <= LEAF_NODES {
            if hi - lo == LEAF_NODES && self.leaf_blocked(s, a, lo, hi, set) {
                out[lo..hi].fill(0);
            } else {
                self.arm_nodes(s, a, out, lo, hi, set);
            }
            return;
        }
        let (cyl, axis, m) = run_middle(s, a, lo, hi);
        let c = self.model.clearance_mm;
        let mut kept = [0u8; SET];
        let mut nk = 0;
        for &k in set {
            let b = &s.boxes[k as usize].aabb;
            if let Some((memo, a2)) = &mut memo {
                let (last, at) = memo[k as usize];
                if last - motion(s.shift_mm, (*a2 - at).abs()) - MARGIN_MM >= s.deep {
                    continue;
                }
            }
            let (t, lb) = capsule_near(&cyl, &axis, b);
            let free = lb - m - MARGIN_MM;
            if let Some((memo, a2)) = &mut memo {
                memo[k as usize] = (free, *a2);
            }
            if free > c {
                // Free at every node of the run; the run's bound serves the depth.
                if free < s.deep {
                    cap_depth(&mut out[lo..hi], 0, self.depth(free, s.span));
                }
                continue;
            }
            // The rim ball on short runs only (module doc, *Blocked leaves*).
            if blocks_run(&cyl, b, m, t, lb, c, hi - lo <= 2 * LEAF_NODES) {
                out[lo..hi].fill(0);
                return;
            }
            kept[nk] = k;
            nk += 1;
        }
        if nk == 0 {
            return;
        }
        let mid = lo + (hi - lo) / 2;
        self.arm_run(s, a, out, lo, mid, &kept[..nk], None);
        self.arm_run(s, a, out, mid, hi, &kept[..nk], None);
    }

    /// Whether a box of `set` blocks every node `lo..hi` by the blocked bound at the run's
    /// middle, the inner capsule's or the rim ball's (module doc, *Blocked leaves*): then
    /// every node of the run is within the clearance, as its node test would find.
    fn leaf_blocked(&self, s: &Swept<'_>, a: &Angles, lo: usize, hi: usize, set: &[u8]) -> bool {
        let (cyl, axis, m) = run_middle(s, a, lo, hi);
        let c = self.model.clearance_mm;
        set.iter().any(|&k| {
            let b = &s.boxes[k as usize].aabb;
            let (t, lb) = capsule_near(&cyl, &axis, b);
            blocks_run(&cyl, b, m, t, lb, c, true)
        })
    }

    /// Nodes `lo..hi` one by one (the node test of `column.rs`), with the coherence along the
    /// run: the capsule distance to a box changes by at most `R[2][L]` per radian of joint 3, so
    /// a box whose last capsule distance less that motion still exceeds the clearance is clear,
    /// as `link_clear_of_box`'s fast accept would find; that bound serves the depth.
    pub(super) fn arm_nodes(
        &self,
        s: &Swept<'_>,
        a: &Angles,
        out: &mut [u8],
        lo: usize,
        hi: usize,
        set: &[u8],
    ) {
        // The per-box memory on the stack, as small as the set allows (no 1 KB to clear per call).
        if set.len() <= 4 {
            self.arm_nodes_in::<4>(s, a, out, lo, hi, set);
        } else {
            self.arm_nodes_in::<SET>(s, a, out, lo, hi, set);
        }
    }

    /// [`arm_nodes`](Self::arm_nodes) for a set of at most `N` boxes.
    fn arm_nodes_in<const N: usize>(
        &self,
        s: &Swept<'_>,
        a: &Angles,
        out: &mut [u8],
        lo: usize,
        hi: usize,
        set: &[u8],
    ) {
        let c = self.model.clearance_mm;
        let reach = s.reach_mm;
        let mut lb = [f64::NEG_INFINITY; N];
        let mut at = [0.0f64; N];
        let nodes = out[lo..hi]
            .iter_mut()
            .zip(&a.rad[lo..hi])
            .zip(&a.sc[lo..hi]);
        for ((f, &q3), &sc) in nodes {
            if *f == 0 {
                continue;
            }
            let mut cyl: Option<Cylinder> = None;
            let mut nearest = f64::INFINITY;
            for (slot, &k) in set.iter().enumerate() {
                let coherent = lb[slot] - reach * (q3 - at[slot]).abs() - MARGIN_MM;
                if coherent > c {
                    nearest = nearest.min(coherent);
                    continue;
                }
                let cy = *cyl.get_or_insert_with(|| s.at(sc));
                let b = &s.boxes[k as usize].aabb;
                // The capsule distance, and the axis point behind it for the node test.
                let (near, axis) = axis_nearest(&cy, b);
                let lo = (axis - cy.radius.max(0.0)).max(0.0);
                lb[slot] = lo;
                at[slot] = q3;
                if lo <= c && !link_clear_near(&cy, b, c, &near, axis) {
                    nearest = f64::NEG_INFINITY;
                    break;
                }
                nearest = nearest.min(lo);
            }
            if nearest == f64::NEG_INFINITY {
                *f = 0;
            } else if nearest < s.deep {
                let q = self.depth(nearest, s.span).min(*f & ARM_BITS);
                *f = (*f & !ARM_BITS) | q;
            }
        }
    }

    /// The tool's bits of the free nodes `lo..hi` for the boxes `set` (indices into
    /// `t.boxes`): a run whose boxes are all far is left as it is (tool far, depth `K`);
    /// else its halves, else node by node. Each node's tool bits only get nearer and
    /// shallower (the boxes come in chunks: the near bit is the OR, the depth the least).
    /// The centre's split is for axis 3's values (`column.rs`): the run's middle and its
    /// nodes read their sines and cosines from `a` (*Angles*).
    pub(super) fn tool_run(
        &self,
        t: &Centre<'_>,
        a: &Angles,
        out: &mut [u8],
        lo: usize,
        hi: usize,
        set: &[u8],
    ) {
        if set.is_empty() || out[lo..hi].iter().all(|&f| f == 0) {
            return;
        }
        if hi - lo > LEAF_NODES {
            // The middle value and the most any node of the run lies from it (joint 3 moves by
            // the same angle as axis 3 within a column).
            let mid = lo + hi - 1;
            let v = a.mid_deg[mid];
            let h = (v - a.deg[lo]).max(a.deg[hi - 1] - v).to_radians();
            let m = motion(t.reach_mm, h);
            let (sn, co) = a.mid_sc[mid];
            let centre = turned(&t.split, sn, co);
            let c = self.model.clearance_mm;
            let mut kept = [0u8; SET];
            let mut nk = 0;
            // The least bound of the boxes far at every node: the depth of the least is the least
            // of the depths (`depth` does not fall with the distance), so the codes are capped
            // once.
            let mut least_far = f64::INFINITY;
            for &k in set {
                let f = distance_point_aabb(&centre, t.boxes[k as usize]) - t.radius;
                let far = f - m - MARGIN_MM;
                if far > not_near(c) {
                    // Not near for this box at any node; the run's bound serves the depth.
                    least_far = least_far.min(far);
                    continue;
                }
                if f + m + MARGIN_MM <= c {
                    // Near at every node of the run, with depth 0: what the nodes would get.
                    for f in out[lo..hi].iter_mut().filter(|f| **f != 0) {
                        *f = (*f & !TOOL_BITS) | Self::code(true, 0, 0) & TOOL_BITS;
                    }
                    return;
                }
                kept[nk] = k;
                nk += 1;
            }
            if least_far < t.deep {
                cap_depth(&mut out[lo..hi], 3, self.depth(least_far, self.centre_span));
            }
            if nk > 0 {
                let mid = lo + (hi - lo) / 2;
                self.tool_run(t, a, out, lo, mid, &kept[..nk]);
                self.tool_run(t, a, out, mid, hi, &kept[..nk]);
            }
            return;
        }
        self.tool_nodes(t, a, out, lo, hi, set);
    }

    /// The tool's bits of the free nodes `lo..hi`, node by node, for the boxes `set`.
    pub(super) fn tool_nodes(
        &self,
        t: &Centre<'_>,
        a: &Angles,
        out: &mut [u8],
        lo: usize,
        hi: usize,
        set: &[u8],
    ) {
        let clearance = self.model.clearance_mm;
        for (f, &(sn, co)) in out[lo..hi].iter_mut().zip(&a.sc[lo..hi]) {
            if *f == 0 {
                continue;
            }
            let centre = turned(&t.split, sn, co);
            let d = set
                .iter()
                .map(|&k| distance_point_aabb(&centre, t.boxes[k as usize]))
                .fold(f64::INFINITY, f64::min);
            let f_t = d - t.radius;
            // Tool free for any wrist where f_t > c (with room for rounding).
            let near = f_t.is_nan() || f_t <= clearance + 1e-6 * (1.0 + f_t.abs());
            let q_t = self
                .depth(f_t, self.centre_span)
                .min((*f >> 3) & DEPTH_LEVELS);
            let near = near || GridCheck::tool_near(*f);
            *f = (*f & !TOOL_BITS) | Self::code(near, q_t, 0) & TOOL_BITS;
        }
    }
}
