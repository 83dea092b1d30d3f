//! Node inspection of a whole grid column at once: the hot path of the configuration-space
//! grid (paper section 3). Per node it writes the code of `grid.rs`: the free bit is exactly
//! [`CollisionModel::arm_is_free`]'s answer; the depths are lower bounds, quantised. The work that
//! does not depend on axis 3 is done once per column, boxes the links moved by axis 3 cannot
//! come near are culled, and the coherence along the column skips boxes that stay far.

use super::grid::{GridCheck, COLUMN_LEVELS, DEPTH_LEVELS};
use super::{link_clear_of_box, CylData};
use crate::geometry::{
    distance_capsule_aabb, distance_point_aabb, distance_segment_aabb, Aabb, Cylinder, Point,
};
use crate::robot::RangeViolation;
use nalgebra::Vector3;

/// Safety margin (mm) of the per-column culling of boxes.
const CULL_MARGIN_MM: f64 = 1e-6;

/// Obstacles per chunk of the per-column culling (the kept indices live on the stack).
const CULL_CHUNK: usize = 64;

/// The arm-depth bits of a code.
const ARM_BITS: u8 = 7;

impl GridCheck<'_> {
    /// The hot path of the grid build: the node code (`grid.rs`) of `[a1, a2, a3[k]]` for one
    /// column into `out[k]`; 0 for a node that is not free.
    ///
    /// Per column: the range of axes 1 and 2, the poses of links 1 and 2 and their cylinders'
    /// checks and depths, the frame of joint 3, and the culling of boxes the cylinders moved by
    /// axis 3 (and the tool's wrist centre) cannot come near: a sphere about joint 3 and a slab
    /// along its axis hold their whole sweep. Per node: the range of axis 3, one `sin_cos`, the
    /// end points and the remaining boxes. No allocation. Only `min(a3_deg.len(), out.len())`
    /// nodes are inspected; any further entries of `out` are set to 0.
    pub fn inspect_column(
        &self,
        a1_deg: f64,
        a2_deg: f64,
        a3_deg: &[f64],
        out: &mut [u8],
        column: &mut [u8],
    ) {
        let model = self.model;
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
        let deepest = Self::code(false, DEPTH_LEVELS, DEPTH_LEVELS);
        for (f, &a3) in out.iter_mut().zip(a3_deg) {
            *f = match model.robot.check_range3(&[a1_deg, a2_deg, a3]) {
                Ok(()) => deepest,
                Err(_) => 0,
            };
        }
        let poses = model.cell_link_poses(&[a1_deg, a2_deg, 0.0]);
        let c = model.clearance_mm;
        // Cylinders that axis 3 does not move: their test holds for the whole column, and their
        // depths go into the column's bytes.
        for (l, &i) in self.fixed.iter().enumerate() {
            let cyl = model.cylinder_in(i, &poses);
            let span = self.fixed_span[l];
            let deep = self.deep_mm(span);
            let mut nearest = f64::INFINITY;
            for (_, b) in model.checked_boxes(i) {
                let lo = distance_capsule_aabb(&cyl, b);
                if lo <= c && !link_clear_of_box(&cyl, b, c) {
                    out.fill(0);
                    column.fill(0);
                    return;
                }
                nearest = nearest.min(depth_bound(&cyl, b, lo, deep));
            }
            if let Some(slot) = column.get_mut(l) {
                *slot = self.depth_of(nearest, span, COLUMN_LEVELS);
            }
        }
        // Frame of joint 3 (before its rotation), cell frame.
        let j3 = poses[1] * model.robot.joints[2].origin;
        let origin = Point::from(j3.translation.vector);
        let axis = j3.rotation * model.robot.joints[2].axis.into_inner();
        let q3_of = |a3: f64| {
            model
                .robot
                .urdf_joints_deg(&[a1_deg, a2_deg, a3, 0.0, 0.0, 0.0])[2]
                .to_radians()
        };
        for (i, cd) in model.cyl.iter().enumerate().filter(|(_, d)| d.joint == 2) {
            let radius = model.robot.cylinders[i].radius_mm;
            let span = self.arm_span;
            let deep = self.deep_mm(span);
            let ends = cd.split.map(|[par, perp, cross]| {
                (
                    origin + j3.rotation * par,
                    j3.rotation * perp,
                    j3.rotation * cross,
                )
            });
            for chunk in model.obstacles.chunks(CULL_CHUNK) {
                // Boxes the cylinder's sweep keeps farther than the clearance from are culled;
                // the nearest of them still bounds the depth of every node of the column.
                let mut kept = [0usize; CULL_CHUNK];
                let mut nk = 0;
                let mut culled = f64::INFINITY;
                for (k, o) in chunk.iter().enumerate() {
                    let gap = sweep_gap(&o.aabb, &origin, &axis, cd);
                    if gap <= c + CULL_MARGIN_MM {
                        kept[nk] = k;
                        nk += 1;
                    } else {
                        culled = culled.min(gap - CULL_MARGIN_MM);
                    }
                }
                if culled < deep {
                    let q = self.depth(culled, span);
                    for f in out.iter_mut().filter(|f| **f != 0) {
                        *f = (*f & !ARM_BITS) | q.min(*f & ARM_BITS);
                    }
                }
                if nk == 0 {
                    continue;
                }
                // Coherence along the column: the capsule distance to a box changes by at most
                // `reach` per radian of joint 3 (`R[2][L]` of `proof.rs`; the capsule's points
                // obey the same bound). A box whose last capsule distance `lb[j]`, taken at
                // joint-3 angle `at[j]`, minus that motion still exceeds the clearance is clear
                // here, as `cylinder_clear_of_aabb`'s fast accept would find; that lower bound
                // serves the depth as it is (the depth is a lower bound, kept cheap: it matters
                // only to the step check's fast path).
                let reach = cd.reach_mm[2];
                let mut lb = [f64::NEG_INFINITY; CULL_CHUNK];
                let mut at = [0.0f64; CULL_CHUNK];
                for (f, &a3) in out.iter_mut().zip(a3_deg) {
                    if *f == 0 {
                        continue;
                    }
                    let q3 = q3_of(a3);
                    let mut cyl: Option<Cylinder> = None;
                    let mut nearest = f64::INFINITY;
                    for (slot, &k) in kept[..nk].iter().enumerate() {
                        let coherent = lb[slot] - reach * (q3 - at[slot]).abs() - CULL_MARGIN_MM;
                        if coherent > c {
                            nearest = nearest.min(coherent);
                            continue;
                        }
                        let cy = *cyl.get_or_insert_with(|| {
                            let (s, co) = q3.sin_cos();
                            Cylinder {
                                a: ends[0].0 + ends[0].1 * co + ends[0].2 * s,
                                b: ends[1].0 + ends[1].1 * co + ends[1].2 * s,
                                radius,
                            }
                        });
                        let b = &chunk[k].aabb;
                        let lo = distance_capsule_aabb(&cy, b);
                        lb[slot] = lo;
                        at[slot] = q3;
                        if lo <= c && !link_clear_of_box(&cy, b, c) {
                            nearest = f64::NEG_INFINITY;
                            break;
                        }
                        nearest = nearest.min(lo);
                    }
                    if nearest == f64::NEG_INFINITY {
                        *f = 0;
                    } else if nearest < deep {
                        let q = self.depth(nearest, span).min(*f & ARM_BITS);
                        *f = (*f & !ARM_BITS) | q;
                    }
                }
            }
        }
        self.tool_codes(a3_deg, out, &origin, &j3, q3_of);
    }

    /// The tool's bits of the column's free nodes (`grid.rs`): the wrist centre `C` (a point of
    /// link 3, split about joint 3's axis as the cylinders' ends are), its distance to the
    /// boxes less the tool's radius `R_T`, and from it the near bit and the tool's depth.
    fn tool_codes(
        &self,
        a3_deg: &[f64],
        out: &mut [u8],
        origin: &Point,
        j3: &nalgebra::Isometry3<f64>,
        q3_of: impl Fn(f64) -> f64,
    ) {
        let model = self.model;
        let Some(tool) = &model.tool else {
            return;
        };
        let u = model.robot.joints[2].axis.into_inner();
        let par = u * u.dot(&tool.centre);
        let perp = tool.centre - par;
        let (p0, p1, p2): (Point, Vector3<f64>, Vector3<f64>) = (
            origin + j3.rotation * par,
            j3.rotation * perp,
            j3.rotation * u.cross(&perp),
        );
        // C stays within |par| + |perp| of joint 3's origin: boxes farther than that plus the
        // radius, the clearance and one step's motion never matter.
        let r_t = tool.radius_mm;
        let deep = self.deep_mm(self.centre_span) + r_t;
        let sweep = par.norm() + perp.norm();
        let boxes: Vec<&Aabb> = model
            .obstacles
            .iter()
            .map(|o| &o.aabb)
            .filter(|b| distance_point_aabb(origin, b) <= sweep + deep + CULL_MARGIN_MM)
            .collect();
        for (f, &a3) in out.iter_mut().zip(a3_deg) {
            if *f == 0 {
                continue;
            }
            let (s, co) = q3_of(a3).sin_cos();
            let centre = p0 + p1 * co + p2 * s;
            let d = boxes
                .iter()
                .map(|b| distance_point_aabb(&centre, b))
                .fold(f64::INFINITY, f64::min);
            let f_t = d - r_t;
            // Tool free for any wrist where f_t > c (with room for rounding).
            let near = f_t.is_nan() || f_t <= model.clearance_mm + 1e-6 * (1.0 + f_t.abs());
            let q_t = self.depth(f_t, self.centre_span);
            *f = Self::code(near, q_t, *f & ARM_BITS);
        }
    }
}

/// A lower bound of the cylinder–box distance good enough for the depth: the capsule distance
/// `capsule` where it is already `deep` (the depth is then K anyway), else also the capsules
/// about shortened axes that still hold the cap rims (as in `link_clear_of_box`), which are much
/// closer where a flat cap faces the box.
#[inline]
fn depth_bound(c: &Cylinder, b: &Aabb, capsule: f64, deep: f64) -> f64 {
    if capsule >= deep {
        return capsule;
    }
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius.max(0.0);
    let mut best = capsule;
    if len > 0.0 && r > 0.0 {
        let u = d / len;
        for k in [1.0, 2.5, 6.0] {
            let s = (k * r).min(0.5 * len);
            let lb = distance_segment_aabb(&(c.a + u * s), &(c.b - u * s), b) - r.hypot(s);
            best = best.max(lb);
        }
    }
    best
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
