//! Node inspection of a whole grid column at once: the hot path of the configuration-space
//! grid (paper section 3). Per node it writes the code of `grid.rs`: the free bit is exactly
//! [`CollisionModel::arm_is_free`]'s answer; the depths are lower bounds, quantised. The work that
//! depends on axis 1 alone is done once per slice of axis 1 ([`Slice`]: link 1's checks,
//! [`GridCheck::slice_bytes`], and link 1's pose); the axis-3 values' sines and cosines once per
//! grid (`block.rs`'s `Angles`: the nodes' and every run's middle); the work that does not
//! depend on axis 3 once per column (the range of axes 1 and 2, link 2 placed from link 1's
//! pose and checked, the frame of joint 3), and boxes the links moved by axis 3 cannot come near
//! are culled. Joint 3 is axis 3 plus an angle set by axis 2 (the coupling), so the column turns
//! the cylinders' split ends, and the tool's wrist centre's, by that angle once and every node
//! and run reads its axis-3 value's sine and cosine from the table: no `sin_cos` per node or
//! run, and no pose per column beyond link 2's (the tool's bits, too, from link 2's pose). Axis 3's range and the coupled
//! one hold on one run of the column's ascending values, found by two bisections (node by node
//! where the values are not ascending). The rest goes by runs of the column (`block.rs`, beyond
//! the paper), 32 nodes to start with: a run whose motion bound proves it free (with the run's
//! own depth, or full depth far from the boxes), or blocked, or the tool near at every node,
//! costs one pose at its middle and no per-node work; only runs near an obstacle's boundary are
//! halved down to the node test.
//!
//! *Carried along a slice* ([`FixedMemo`], beyond the paper). From one column of a slice to the
//! next only axis 2 moves. A link-2 cylinder's capsule distance to a box changes by at most
//! `R[1][L] |da2|`, and the middle cylinder of a top run of the cylinders axis 3 moves by at most
//! their shift `|da2|` (`grid.rs`: under the IRB 1400's parallelogram coupling link 3 only
//! translates, by joint 3's origin's chord about joint 2). A box whose last measured bound, less
//! that motion and a margin of 1e-6 mm, is still `deep_mm` or more is dropped unmeasured: its
//! measurement would have dropped it too (clear, depth `K`), so every code and column byte is
//! the column's alone (`block_tests.rs`), whatever order the columns come in.

use super::angles::Angles;
use super::block::{motion, Centre, Split, Swept, MARGIN_MM, SET, TOP_RUN_NODES};
use super::clear::link_clear_of_box;
use super::grid::{GridCheck, ARM_BITS, COLUMN_LEVELS, DEPTH_LEVELS};
use super::proof::tight_lower_bound;
use super::CylData;
use crate::geometry::{distance_capsule_aabb, distance_point_aabb, Aabb, Cylinder, Point, Solid};
use crate::robot::{Pose, RangeViolation};
use nalgebra::Vector3;
use std::borrow::Cow;

/// Safety margin (mm) of the per-column culling of boxes.
const CULL_MARGIN_MM: f64 = 1e-6;

pub use super::grid::{SliceBytes, MAX_FIXED};

/// What the columns of one slice of axis 1 share ([`GridCheck::slice`]): link 1's answers
/// ([`GridCheck::slice_bytes`]) and pose, and the axis-3 values with their sines and cosines
/// (`block.rs`'s [`Angles`]).
pub(crate) struct Slice<'a> {
    a1_deg: f64,
    bytes: SliceBytes,
    pose1: Pose,
    angles: Cow<'a, Angles>,
}

/// Per fixed cylinder and box, the capsule distance last measured along a slice and URDF joint
/// 2's angle there (rad), for [`GridCheck::inspect_column_in`]'s next columns: one per slice
/// ([`GridCheck::fixed_memo`]); link 1's slots unused (the slice's answers, or, past
/// [`MAX_FIXED`], checked whole in every column).
/// Also, per cylinder moved by axis 3, chunk of boxes, top run and box, the run's free bound
/// measured last and axis 2 there (rad) (`block.rs`, [`GridCheck::arm_run`]'s `memo`).
pub(crate) struct FixedMemo(Vec<(f64, f64)>, Vec<(f64, f64)>);

/// Obstacles per chunk of the per-column culling (the kept indices live on the stack).
const CULL_CHUNK: usize = SET;

impl GridCheck {
    /// The hot path of the grid build: the node code (`grid.rs`) of `[a1, a2, a3[k]]` for one
    /// column into `out[k]`; 0 for a node that is not free.
    ///
    /// Per column: the range of axes 1 and 2, link 2's pose (from link 1's, kept per slice) and
    /// its cylinders' checks and depths (link 1's from [`slice_bytes`](Self::slice_bytes), which
    /// the grid build makes once per slice), the frame of joint 3, and the culling of boxes the
    /// cylinders moved by axis 3 (and the tool's wrist centre) cannot come near: a sphere about
    /// joint 3 and a slab along its axis hold their whole sweep. The range of axis 3 and the
    /// coupled one by bisection of the (ascending) values. The cylinders moved by axis 3 and the
    /// tool's wrist centre by runs (`block.rs`; node by node when the axis-3 values are not
    /// ascending): per run its middle pose from the slice's table of sines and cosines and the
    /// remaining boxes; per node, in runs near a boundary, the end points from the table and the
    /// remaining boxes (the tool's wrist centre still takes a `sin_cos` per run or node). This
    /// one column makes its own `Slice` and `FixedMemo` (the grid build makes them once per
    /// slice and calls [`inspect_column_in`](Self::inspect_column_in)). Only
    /// `min(a3_deg.len(), out.len())` nodes are inspected; any further entries of `out` are set
    /// to 0.
    pub fn inspect_column(
        &self,
        a1_deg: f64,
        a2_deg: f64,
        a3_deg: &[f64],
        out: &mut [u8],
        column: &mut [u8],
    ) {
        let mut memo = self.fixed_memo();
        let slice = self.slice(a1_deg, a3_deg);
        self.inspect_column_in(a2_deg, out, column, &slice, &mut memo, 0..a3_deg.len());
    }

    /// An empty `FixedMemo` (nothing measured yet) for the columns of one slice.
    pub(crate) fn fixed_memo(&self) -> FixedMemo {
        let n = self.fixed.len() * self.model.obstacles.len();
        FixedMemo(vec![(f64::NEG_INFINITY, 0.0); n], Vec::new())
    }

    /// What every column `[a1_deg, *, a3_deg]` of one slice of axis 1 shares
    /// (`Slice`): made once per block of the slice by the grid build, link 1's part once per
    /// slice (`grid.rs`, `SliceMemo`).
    pub(crate) fn slice(&self, a1_deg: f64, a3_deg: &[f64]) -> Slice<'_> {
        // The grid's slices share their axis-3 values: their angles are made once.
        let kept = self.angles.get_or_init(|| Angles::new(a3_deg));
        let same = kept.deg.len() == a3_deg.len()
            && kept
                .deg
                .iter()
                .zip(a3_deg)
                .all(|(a, b)| a.to_bits() == b.to_bits());
        let (bytes, pose1) = self.slices.get(a1_deg, || {
            let pose1 = self.chain.pose1(a1_deg.to_radians().sin_cos());
            (self.slice_bytes(a1_deg), pose1)
        });
        Slice {
            a1_deg,
            bytes,
            pose1,
            angles: if same {
                Cow::Borrowed(kept)
            } else {
                Cow::Owned(Angles::new(a3_deg))
            },
        }
    }

    /// What the cylinders of link 1 (moved by axis 1 alone) give every column of the slice at
    /// `a1_deg`: per fixed cylinder, in the order of `fixed`, `Some(Some(byte))` (its column
    /// byte: clear of every box), `Some(None)` (within the clearance: every node of the slice is
    /// blocked) or `None` (a link-2 cylinder, which each column checks itself).
    pub fn slice_bytes(&self, a1_deg: f64) -> SliceBytes {
        let model = &*self.model;
        let poses = model.cell_link_poses(&[a1_deg, 0.0, 0.0]);
        let mut bytes = [None; MAX_FIXED];
        for (l, &i) in self.fixed.iter().enumerate().take(MAX_FIXED) {
            if model.cyl[i].joint == 0 {
                bytes[l] = Some(self.fixed_byte(l, &model.cylinder_in(i, &poses)));
            }
        }
        bytes
    }

    /// Fixed cylinder `l` (index into `fixed`) placed as `cyl`: its column byte, or `None` when
    /// it comes within the clearance of a box.
    fn fixed_byte(&self, l: usize, cyl: &Cylinder) -> Option<u8> {
        self.fixed_byte_along(l, cyl, None)
    }

    /// [`fixed_byte`](Self::fixed_byte), for a link-2 cylinder at URDF joint 2 = `q2` (rad)
    /// with `memo` (`Some((memo, q2))`) its capsule distances measured at other columns of the
    /// slice (by box index): only joint 2 moved since, so a box whose last distance less the
    /// motion `R[1][L] |dq2|` (and the margin) is still `deep_mm` or more is neither within the
    /// clearance nor below depth `K_c`, and is not measured again; the byte is the same.
    fn fixed_byte_along(
        &self,
        l: usize,
        cyl: &Cylinder,
        mut memo: Option<(&mut [(f64, f64)], f64)>,
    ) -> Option<u8> {
        let model = &*self.model;
        let c = model.clearance_mm;
        let span = self.fixed_span[l];
        let deep = self.deep_mm(span);
        let reach = model.cyl[self.fixed[l]].reach_mm[1];
        let mut nearest = f64::INFINITY;
        for (k, b) in model.checked_boxes(self.fixed[l]) {
            if let Some((memo, q2)) = &mut memo {
                let (last, at) = memo[k];
                if last - motion(reach, (*q2 - at).abs()) - MARGIN_MM >= deep {
                    continue;
                }
            }
            let lo = distance_capsule_aabb(cyl, b);
            if let Some((memo, q2)) = &mut memo {
                memo[k] = (lo, *q2);
            }
            if lo <= c && !link_clear_of_box(cyl, b, c) {
                return None;
            }
            nearest = nearest.min(depth_bound(cyl, b, lo, deep));
        }
        Some(self.depth_of(nearest, span, COLUMN_LEVELS))
    }

    /// [`inspect_column`](Self::inspect_column) of the column at `a2_deg` of `slice`
    /// ([`slice`](Self::slice): its `a1_deg`, axis-3 values, link 1's answers and pose), with
    /// `memo` the link-2 distances of the slice's columns inspected before (any order). Only
    /// the codes of the nodes `part` are asked for: the runs (`block.rs`) that hold none of
    /// them are left out, so the other codes of `out` are not the column's (where the axis-3
    /// values do not ascend every node is inspected). A node's code does not depend on which
    /// runs are inspected: each run's work is its own, the per-column work (the ranges, the
    /// fixed cylinders, the culled boxes) covers every node, and the memo drops a box only
    /// where its measurement would (module doc).
    pub(crate) fn inspect_column_in(
        &self,
        a2_deg: f64,
        out: &mut [u8],
        column: &mut [u8],
        slice: &Slice<'_>,
        memo: &mut FixedMemo,
        part: std::ops::Range<usize>,
    ) {
        let asked = |&(_, (lo, hi)): &(usize, (usize, usize))| lo < part.end && hi > part.start;
        let model = &*self.model;
        let (a1_deg, ang) = (slice.a1_deg, &*slice.angles);
        let a3_deg = &ang.deg[..];
        column.fill(0);
        let n = a3_deg.len().min(out.len());
        let (out, rest) = out.split_at_mut(n);
        rest.fill(0);
        if n == 0 {
            return;
        }
        // Axes 1 and 2 out of range: the whole column is.
        if let Err(RangeViolation::Axis { axis: 1 | 2, .. }) =
            model.robot.check_range3(&[a1_deg, a2_deg, a3_deg[0]])
        {
            out.fill(0);
            return;
        }
        // A link-1 cylinder within the clearance blocks the whole slice.
        if slice.bytes.contains(&Some(None)) {
            out.fill(0);
            return;
        }
        let deepest = Self::code(false, DEPTH_LEVELS, DEPTH_LEVELS);
        // Axes 1 and 2 are in range (above): per node axis 3 and the coupled range, which on
        // ascending values (the grid's) hold on one run of the column, found by bisection. The
        // runs of `block.rs` need the same order; without it every node is looked at.
        let runs = ang.ascending;
        if runs {
            let robot = &model.robot;
            let first = a3_deg[..n].partition_point(|&v| robot.axis3_below(a2_deg, v));
            let end = a3_deg[..n].partition_point(|&v| !robot.axis3_above(a2_deg, v));
            out.fill(0);
            if first < end {
                out[first..end].fill(deepest);
            }
        } else {
            for (f, &a3) in out.iter_mut().zip(a3_deg) {
                *f = if model.robot.axis3_in_range(a2_deg, a3) {
                    deepest
                } else {
                    0
                };
            }
        }
        // Link 2's pose from the slice's link 1 (URDF joint 2 is axis 2).
        let a2_rad = a2_deg.to_radians();
        let sc2 = a2_rad.sin_cos();
        let pose2 = self.chain.pose2_from1(&slice.pose1, sc2);
        let c = model.clearance_mm;
        // Cylinders that axis 3 does not move: their test holds for the whole column, and their
        // depths go into the column's bytes (link 1's are the slice's).
        for (l, &i) in self.fixed.iter().enumerate() {
            let answer = match slice.bytes.get(l).copied().flatten() {
                Some(known) => known,
                None => {
                    // A link-2 cylinder, or one of link 1's past the slice's kept answers
                    // (`MAX_FIXED`): placed on its own link.
                    let on_link_1 = model.cyl[i].joint == 0;
                    let pose = if on_link_1 { &slice.pose1 } else { &pose2 };
                    let cy = &model.robot.cylinders[i];
                    let cyl = Cylinder {
                        a: pose.point(&cy.a),
                        b: pose.point(&cy.b),
                        radius: cy.radius_mm,
                    };
                    if on_link_1 {
                        self.fixed_byte(l, &cyl)
                    } else {
                        let boxes = self.model.obstacles.len();
                        let memo = &mut memo.0[l * boxes..(l + 1) * boxes];
                        self.fixed_byte_along(l, &cyl, Some((memo, a2_rad)))
                    }
                }
            };
            let Some(byte) = answer else {
                out.fill(0);
                column.fill(0);
                return;
            };
            if let Some(slot) = column.get_mut(l) {
                *slot = byte;
            }
        }
        // Joint 3's origin and axis, cell frame.
        let origin = pose2.point(&self.joint3.0);
        let axis = pose2.vector(&self.joint3.1);
        // URDF joint 3 is `a3 + t` with `t` set by axis 2 (the coupling): a split point
        // `par + cos q perp + sin q cross` is `par + cos a3 perp' + sin a3 cross'` with
        // `perp' = cos t perp + sin t cross`, `cross' = cos t cross - sin t perp`, so the
        // nodes read the sines and cosines of their axis-3 values from the slice's tables.
        let (st, ct) = model.robot.urdf_arm_sincos(&[(0.0, 1.0), sc2, (0.0, 1.0)])[2];
        // The top runs' bounds carried along the slice: per cylinder, chunk, top run, box.
        let chunks = model.obstacles.len().div_ceil(CULL_CHUNK);
        let tops = n.div_ceil(TOP_RUN_NODES);
        let need = self.split3.len() * chunks * tops * CULL_CHUNK;
        if memo.1.len() < need {
            memo.1.resize(need, (f64::NEG_INFINITY, 0.0));
        }
        for (slot, (i, split, shift)) in self.split3.iter().enumerate() {
            let (i, cd) = (*i, &model.cyl[*i]);
            let span = self.arm_span;
            let deep = self.deep_mm(span);
            let ends = split.map(|[par, perp, cross]| {
                let (perp, cross) = (pose2.vector(&perp), pose2.vector(&cross));
                (
                    pose2.point(&Point::from(par)),
                    perp * ct + cross * st,
                    cross * ct - perp * st,
                )
            });
            for (ch, chunk) in model.obstacles.chunks(CULL_CHUNK).enumerate() {
                // Boxes the cylinder's sweep keeps farther than the clearance from are culled;
                // the nearest of them still bounds the depth of every node of the column.
                let mut kept = [0u8; CULL_CHUNK];
                let mut nk = 0;
                let mut culled = f64::INFINITY;
                for (k, o) in chunk.iter().enumerate() {
                    let gap = sweep_gap(&o.aabb, &origin, &axis, cd);
                    if gap <= c + CULL_MARGIN_MM {
                        kept[nk] = k as u8;
                        nk += 1;
                    } else {
                        culled = culled.min(gap - CULL_MARGIN_MM);
                    }
                }
                if culled < deep {
                    // Every code at once (a blocked node's 0 stays 0).
                    let q = self.depth(culled, span);
                    for f in out.iter_mut() {
                        *f = (*f & !ARM_BITS) | q.min(*f & ARM_BITS);
                    }
                }
                let swept = Swept {
                    ends,
                    radius: model.robot.cylinders[i].radius_mm,
                    reach_mm: cd.reach_mm[2],
                    shift_mm: *shift,
                    boxes: chunk,
                    deep,
                    span,
                };
                if runs {
                    for (t, (lo, hi)) in top_runs(n).enumerate().filter(asked) {
                        let at = ((slot * chunks + ch) * tops + t) * CULL_CHUNK;
                        let memo = (&mut memo.1[at..at + CULL_CHUNK], a2_rad);
                        self.arm_run(&swept, ang, out, lo, hi, &kept[..nk], Some(memo));
                    }
                } else {
                    self.arm_nodes(&swept, ang, out, 0, n, &kept[..nk]);
                }
            }
        }
        if let Some([par, perp, cross]) = self.centre3 {
            // The wrist centre split as the cylinders' ends are: from link 2's pose, the
            // coupling folded in, so the nodes read the slice's sines and cosines.
            let (perp, cross) = (pose2.vector(&perp), pose2.vector(&cross));
            let split = (
                pose2.point(&Point::from(par)),
                perp * ct + cross * st,
                cross * ct - perp * st,
            );
            self.tool_codes(ang, out, &origin, split, runs, &part);
        }
    }

    /// The tool's bits of the column's free nodes (`grid.rs`): the wrist centre `C` (a point of
    /// link 3, `split` about joint 3's axis for axis 3's values as the cylinders' ends are,
    /// joint 3's origin at `origin`), its distance to the boxes less the tool's radius `R_T`,
    /// and from it the near bit and the tool's depth; by runs where `runs` (`block.rs`: those
    /// holding nodes of `part`), else node by node. The nodes' sines and cosines are the
    /// slice's (`ang`).
    fn tool_codes(
        &self,
        ang: &Angles,
        out: &mut [u8],
        origin: &Point,
        split: Split,
        runs: bool,
        part: &std::ops::Range<usize>,
    ) {
        let model = &*self.model;
        let Some(tool) = &model.tool else {
            return;
        };
        // Every free node starts with the tool far and deep; the boxes make it nearer.
        for f in out.iter_mut().filter(|f| **f != 0) {
            *f = Self::code(false, DEPTH_LEVELS, *f & ARM_BITS);
        }
        // C stays within |par| + |perp| of joint 3's origin: boxes farther than that plus the
        // radius, the clearance and one step's motion never matter.
        let r_t = tool.radius_mm;
        let deep = self.deep_mm(self.centre_span);
        let sweep = self.centre_sweep;
        let n = out.len();
        for chunk in model.obstacles.chunks(CULL_CHUNK) {
            let mut boxes: [&Aabb; CULL_CHUNK] = [&chunk[0].aabb; CULL_CHUNK];
            let mut nk = 0;
            for o in chunk {
                if distance_point_aabb(origin, &o.aabb) <= sweep + deep + r_t + CULL_MARGIN_MM {
                    boxes[nk] = &o.aabb;
                    nk += 1;
                }
            }
            let set: [u8; CULL_CHUNK] = std::array::from_fn(|k| k as u8);
            let centre = Centre {
                split,
                reach_mm: tool.centre_reach_mm[2],
                radius: r_t,
                boxes: &boxes[..nk],
                deep,
            };
            if runs {
                let asked = |&(lo, hi): &(usize, usize)| lo < part.end && hi > part.start;
                for (lo, hi) in top_runs(n).filter(asked) {
                    self.tool_run(&centre, ang, out, lo, hi, &set[..nk]);
                }
            } else {
                self.tool_nodes(&centre, ang, out, 0, n, &set[..nk]);
            }
        }
    }
}

/// The runs a column of `n` nodes starts from (`block.rs`): [`TOP_RUN_NODES`] nodes each, the
/// last one shorter.
fn top_runs(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n)
        .step_by(TOP_RUN_NODES)
        .map(move |lo| (lo, (lo + TOP_RUN_NODES).min(n)))
}

/// A lower bound of the cylinder–box distance good enough for the depth: the capsule distance
/// `capsule` where it is already `deep` (the depth is then K anyway), else also the capsules
/// about shortened axes that still hold the cap rims (`proof::tight_lower_bound`), which are much
/// closer where a flat cap faces the box.
#[inline]
fn depth_bound(c: &Cylinder, b: &Aabb, capsule: f64, deep: f64) -> f64 {
    if capsule >= deep {
        return capsule;
    }
    tight_lower_bound(&Solid::Cylinder(*c), b, capsule)
}

/// A lower bound of the distance between box `b` and every point a cylinder about joint 3
/// (origin `o`, unit axis `u`, cell frame) can take: every point of the cylinder stays within
/// its sweep radius of `o` and within its axial range along `u`.
#[inline]
fn sweep_gap(b: &Aabb, o: &Point, u: &Vector3<f64>, cd: &CylData) -> f64 {
    let radial = distance_point_aabb(o, b) - cd.sweep_radius_mm;
    let centre = nalgebra::center(&b.min, &b.max) - o;
    let half = (b.max - b.min) * 0.5;
    let mid = centre.dot(u);
    let ext = half.x * u.x.abs() + half.y * u.y.abs() + half.z * u.z.abs();
    let axial = (cd.axial_mm[0] - (mid + ext)).max((mid - ext) - cd.axial_mm[1]);
    radial.max(axial)
}
