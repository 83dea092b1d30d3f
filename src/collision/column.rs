//! Node inspection of a whole grid column at once: the hot path of the configuration-space
//! grid (paper section 3). The answer is [`CollisionModel::is_free`]'s for every node; the work
//! that does not depend on axis 3 is done once per column, boxes the links moved by axis 3
//! cannot come near are culled, and the coherence along the column skips boxes that stay clear.

use super::{link_clear_of_box, CollisionModel, CylData};
use crate::geometry::{distance_capsule_aabb, distance_point_aabb, Aabb, Cylinder, Point};
use crate::robot::RangeViolation;
use nalgebra::Vector3;

/// Safety margin (mm) of the per-column culling of boxes.
const CULL_MARGIN_MM: f64 = 1e-6;

/// Obstacles per chunk of the per-column culling (the kept indices live on the stack).
const CULL_CHUNK: usize = 64;

impl CollisionModel {
    /// The hot path of the grid build: `free[k] = is_free([a1, a2, a3[k]])` for one column.
    ///
    /// Per column: the range of axes 1 and 2, the poses of links 1 and 2 and their cylinders'
    /// checks, the frame of joint 3, and the culling of boxes the cylinders moved by axis 3 cannot
    /// come near (a sphere about joint 3 and a slab along its axis hold their whole sweep). Per
    /// node: the range of axis 3, one `sin_cos`, the end points and the remaining boxes. No
    /// allocation. Only `min(a3_deg.len(), free.len())` nodes are inspected; any further entries
    /// of `free` are set to `false`.
    pub fn inspect_column(&self, a1_deg: f64, a2_deg: f64, a3_deg: &[f64], free: &mut [bool]) {
        let n = a3_deg.len().min(free.len());
        let (free, rest) = free.split_at_mut(n);
        rest.fill(false);
        if n == 0 {
            return;
        }
        // Axes 1 and 2 out of range: the whole column is.
        if let Err(RangeViolation::Axis { axis: 1 | 2, .. }) =
            self.robot.check_range3(&[a1_deg, a2_deg, a3_deg[0]])
        {
            free.fill(false);
            return;
        }
        for (f, &a3) in free.iter_mut().zip(a3_deg) {
            *f = self.robot.check_range3(&[a1_deg, a2_deg, a3]).is_ok();
        }
        let poses = self.cell_link_poses(&[a1_deg, a2_deg, 0.0]);
        let c = self.clearance_mm;
        // Cylinders that axis 3 does not move.
        for i in (0..self.cyl.len()).filter(|&i| self.cyl[i].joint < 2) {
            let cyl = self.cylinder_in(i, &poses);
            if !self
                .checked_boxes(i)
                .all(|(_, b)| link_clear_of_box(&cyl, b, c))
            {
                free.fill(false);
                return;
            }
        }
        // Frame of joint 3 (before its rotation), cell frame.
        let j3 = poses[1] * self.robot.joints[2].origin;
        let origin = Point::from(j3.translation.vector);
        let axis = j3.rotation * self.robot.joints[2].axis.into_inner();
        for (i, cd) in self.cyl.iter().enumerate().filter(|(_, d)| d.joint == 2) {
            let radius = self.robot.cylinders[i].radius_mm;
            let ends = cd.split.map(|[par, perp, cross]| {
                (
                    origin + j3.rotation * par,
                    j3.rotation * perp,
                    j3.rotation * cross,
                )
            });
            for chunk in self.obstacles.chunks(CULL_CHUNK) {
                let mut kept = [0usize; CULL_CHUNK];
                let mut nk = 0;
                for (k, o) in chunk.iter().enumerate() {
                    if may_meet_sweep(&o.aabb, &origin, &axis, cd, c) {
                        kept[nk] = k;
                        nk += 1;
                    }
                }
                if nk == 0 {
                    continue;
                }
                // Coherence along the column: the capsule distance to a box changes by at most
                // `reach` per radian of joint 3 (module doc, `R[2][L]`; the capsule's points obey
                // the same bound). A box whose last capsule distance `lb[j]`, taken at joint-3
                // angle `at[j]`, minus that motion still exceeds the clearance is clear here, as
                // `cylinder_clear_of_aabb`'s fast accept would find.
                let reach = cd.reach_mm[2];
                let mut lb = [f64::NEG_INFINITY; CULL_CHUNK];
                let mut at = [0.0f64; CULL_CHUNK];
                for (f, &a3) in free.iter_mut().zip(a3_deg) {
                    if !*f {
                        continue;
                    }
                    let q3 = self
                        .robot
                        .urdf_joints_deg(&[a1_deg, a2_deg, a3, 0.0, 0.0, 0.0])[2]
                        .to_radians();
                    let mut cyl: Option<Cylinder> = None;
                    for (slot, &k) in kept[..nk].iter().enumerate() {
                        if lb[slot] - reach * (q3 - at[slot]).abs() - CULL_MARGIN_MM > c {
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
                            *f = false;
                            break;
                        }
                    }
                }
            }
        }
    }
}

/// Whether box `b` may come within `clearance` of the sweep of a cylinder about joint 3 (origin
/// `o`, unit axis `u`, cell frame): every point of the cylinder stays within its sweep radius of
/// `o` and within its axial range along `u`.
#[inline]
fn may_meet_sweep(b: &Aabb, o: &Point, u: &Vector3<f64>, cd: &CylData, clearance: f64) -> bool {
    let grow = clearance + CULL_MARGIN_MM;
    if distance_point_aabb(o, b) > cd.sweep_radius_mm + grow {
        return false;
    }
    let centre = nalgebra::center(&b.min, &b.max) - o;
    let half = (b.max - b.min) * 0.5;
    let mid = centre.dot(u);
    let ext = half.x * u.x.abs() + half.y * u.y.abs() + half.z * u.z.abs();
    mid + ext >= cd.axial_mm[0] - grow && mid - ext <= cd.axial_mm[1] + grow
}
