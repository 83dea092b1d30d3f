//! The robot placed in a cell among box obstacles: which configurations are free, and which
//! straight joint moves are safe.
//!
//! The inspect stage's model: [`Robot`] + [`Placement`] + obstacles + clearance ->
//! [`CollisionModel`], queried by the place stage (are a point's IK solutions usable?), by the
//! configuration-space grid (node inspection, `column.rs`) and by the planner (whole moves,
//! `proof.rs`). Tests in `tests.rs`.
//!
//! # Node inspection (Ting & Jar 2006, section 3)
//! The paper marks a configuration -1 when the arm hits an obstacle or is out of range, 0
//! otherwise, with the arm lumped into the cylinders of its first three links (section 6). Here a
//! configuration of axes 1..3 (controller values, degrees) is *free* ([`CollisionModel::is_free`])
//! when it is in range, the coupled axis-3 range included ([`Robot::check_range3`]), and every
//! link cylinder keeps MORE than `clearance` mm from every box. [`CollisionModel::inspect_column`]
//! is the same test for a whole column `[a1, a2, a3[k]]` of the grid, with the work that does not
//! depend on axis 3 done once per column (`column.rs`).
//!
//! The whole-move proof (`proof.rs`) is the guarantee the paper lacks: every straight joint move
//! written is proven to keep the clearance at every instant, not only at grid nodes.
//!
//! Frames: the robot base frame sits in the cell frame at [`Placement`] (translation, then yaw
//! about z); obstacles are axis-aligned boxes of the cell frame. Units: mm and degrees.
//!
//! Nodes and moves: a node is free when every link keeps *more* than the clearance (a node at
//! exactly the clearance counts as blocked, the paper's "comes within"); a move is accepted when
//! the proven lower bound is *at least* the clearance (the guarantee the module header states).
//!
//! # What the robot stands on
//!
//! The base cylinder (link 1) starts at the mounting plane, so a floor or pedestal under the
//! robot would touch it in every pose. Boxes that lie wholly at or below the base's mounting
//! plane (their top `z <= base z`) are therefore not checked against the cylinders of link 1:
//! the robot stands on them. Links 2 and 3 are checked against every box, floors included, and
//! link 1 against every box that reaches above the mounting plane (a wall beside the base).
//! The exemption holds only where it is sound: joint 1 turns about the base's vertical axis and
//! no point of the link-1 cylinder lies below the mounting plane (else every box counts).
//!
//! Boxes are clipped to the robot's workspace (plus a 10 m margin) when the model is built, so
//! that every distance is computed on cell-sized shapes ([`CLIP_MARGIN_MM`]).

mod column;
mod proof;
#[cfg(test)]
mod tests;

pub use proof::{Clearance, DISTANCE_SLACK_REL, MOVE_FLOOR_MM};

use crate::cell::Cell;
pub use crate::cell::Obstacle;
use crate::geometry::{
    cylinder_clear_of_aabb, distance_capsule_aabb, distance_cylinder_aabb, distance_point_aabb,
    distance_segment_aabb, Aabb, Cylinder, Point,
};
use crate::place::{Placement, PoseCheck};
use crate::robot::{RangeViolation, Robot};
use nalgebra::{Isometry3, Vector3};

/// A box whose top is within this of the base's mounting plane (or below it) counts as what the
/// robot stands on, mm.
pub const STANDS_ON_TOL_MM: f64 = 1e-6;

/// Boxes are clipped to a cube about the base this much larger than the arm's reach plus the
/// clearance, mm (see `clip_to_workspace`).
pub const CLIP_MARGIN_MM: f64 = 10_000.0;

/// Why a configuration (or a move) is not free.
#[derive(Clone, Debug, PartialEq)]
pub enum Blocked {
    /// An axis, or the coupled axis-3 range, is violated.
    Range(RangeViolation),
    /// A link cylinder comes closer than the clearance to a box. `distance_mm` is the distance
    /// (0 when they touch or overlap); for a move rejected without a witness it is the certified
    /// lower bound that failed.
    Contact {
        link: String,
        obstacle: String,
        distance_mm: f64,
    },
}

impl std::fmt::Display for Blocked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Blocked::Range(v) => write!(f, "the robot cannot reach this pose: {v}"),
            Blocked::Contact {
                link,
                obstacle,
                distance_mm,
            } if *distance_mm <= 0.0 => {
                write!(f, "link '{link}' of the robot hits obstacle '{obstacle}'")
            }
            Blocked::Contact {
                link,
                obstacle,
                distance_mm,
            } => write!(
                f,
                "link '{link}' of the robot comes within {distance_mm:.2} mm of obstacle \
                 '{obstacle}', less than the required clearance"
            ),
        }
    }
}

/// Per-cylinder data fixed at construction.
#[derive(Clone, Debug)]
struct CylData {
    /// Index of the URDF joint whose child link carries the cylinder (0, 1 or 2).
    joint: usize,
    /// `R[i]` of the module doc for `i <= joint`, 0 beyond: distance bound from joint `i`'s axis.
    reach_mm: [f64; 3],
    /// For cylinders moved by axis 3 (`joint == 2`): the end points split about joint 3's axis
    /// `u` (link frame): `p = par + cos q perp + sin q (u x perp)` after a rotation `q`.
    split: [[Vector3<f64>; 3]; 2],
    /// Radius of the sphere about the link origin holding every point, mm.
    sweep_radius_mm: f64,
    /// Range of `p . u` over the cylinder's points (link frame), mm.
    axial_mm: [f64; 2],
    /// Per obstacle: not checked against this cylinder (link 1 and a box the robot stands on,
    /// module doc).
    exempt: Vec<bool>,
}

/// The robot in its cell, ready for node and move checks.
#[derive(Clone, Debug)]
pub struct CollisionModel {
    robot: Robot,
    placement: Placement,
    cell_from_robot: Isometry3<f64>,
    obstacles: Vec<Obstacle>,
    clearance_mm: f64,
    cyl: Vec<CylData>,
}

impl CollisionModel {
    /// Places `robot` (cloned) at `placement` among `obstacles` (cell frame, mm); `clearance_mm`
    /// is the distance every link must keep from every box (0 allowed; negative is taken as 0).
    ///
    /// The robot's cylinders must hang on links 1..3 (`joint_index` 0, 1 or 2), as
    /// [`Robot::load`] guarantees.
    pub fn new(
        robot: &Robot,
        placement: Placement,
        obstacles: Vec<Obstacle>,
        clearance_mm: f64,
    ) -> CollisionModel {
        let obstacles = clip_to_workspace(robot, &placement, obstacles, clearance_mm.max(0.0));
        let cell_from_robot = placement.cell_from_robot();
        let cyl = robot
            .cylinders
            .iter()
            .map(|c| {
                assert!(
                    c.joint_index < 3,
                    "cylinder of link '{}' hangs on joint {}: only links 1..3 carry cylinders",
                    c.link,
                    c.joint_index + 1
                );
                let j = c.joint_index;
                let r = c.radius_mm.max(0.0);
                let far = c.a.coords.norm().max(c.b.coords.norm()) + r;
                let mut reach_mm = [0.0; 3];
                for (i, slot) in reach_mm.iter_mut().enumerate().take(j + 1) {
                    let u = robot.joints[i].axis.into_inner();
                    let perp = |v: Vector3<f64>| (v - u * u.dot(&v)).norm();
                    *slot = if i == j {
                        perp(c.a.coords).max(perp(c.b.coords)) + r
                    } else {
                        let first = perp(robot.joints[i + 1].origin.translation.vector);
                        let rest: f64 = (i + 2..=j)
                            .map(|k| robot.joints[k].origin.translation.vector.norm())
                            .sum();
                        first + rest + far
                    };
                }
                let u = robot.joints[2].axis.into_inner();
                let split_of = |p: Vector3<f64>| {
                    let par = u * u.dot(&p);
                    let perp = p - par;
                    [par, perp, u.cross(&perp)]
                };
                let (sa, sb) = (u.dot(&c.a.coords), u.dot(&c.b.coords));
                let stands = j == 0 && stands_on_its_mounting_plane(robot, c);
                let exempt = obstacles
                    .iter()
                    .map(|o| stands && o.aabb.max.z <= placement.base_mm[2] + STANDS_ON_TOL_MM)
                    .collect();
                CylData {
                    joint: j,
                    reach_mm,
                    split: [split_of(c.a.coords), split_of(c.b.coords)],
                    sweep_radius_mm: far,
                    axial_mm: [sa.min(sb) - r, sa.max(sb) + r],
                    exempt,
                }
            })
            .collect();
        CollisionModel {
            robot: robot.clone(),
            placement,
            cell_from_robot,
            obstacles,
            clearance_mm: clearance_mm.max(0.0),
            cyl,
        }
    }

    /// The model of `cell`'s obstacles and clearance with `robot` at `placement`.
    pub fn of_cell(cell: &Cell, robot: &Robot, placement: Placement) -> CollisionModel {
        CollisionModel::new(
            robot,
            placement,
            cell.obstacles.clone(),
            cell.planner.clearance_mm,
        )
    }

    /// The robot being checked.
    pub fn robot(&self) -> &Robot {
        &self.robot
    }

    /// The box obstacles, cell frame.
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// The clearance every link must keep from every box, mm.
    pub fn clearance_mm(&self) -> f64 {
        self.clearance_mm
    }

    /// Where the robot stands in the cell.
    pub fn placement(&self) -> Placement {
        self.placement
    }

    /// The link cylinders in the cell frame for axes 1..3 (controller values, degrees), each with
    /// its index into `robot().cylinders`.
    pub fn cylinders(&self, axes: &[f64; 3]) -> Vec<(usize, Cylinder)> {
        let poses = self.cell_link_poses(axes);
        (0..self.cyl.len())
            .map(|i| (i, self.cylinder_in(i, &poses)))
            .collect()
    }

    /// Node inspection: `true` when the configuration is in range (coupled axis-3 range included)
    /// and every link cylinder keeps MORE than the clearance from every box.
    pub fn is_free(&self, axes: &[f64; 3]) -> bool {
        if self.robot.check_range3(axes).is_err() {
            return false;
        }
        let poses = self.cell_link_poses(axes);
        (0..self.cyl.len()).all(|i| {
            let c = self.cylinder_in(i, &poses);
            self.checked_boxes(i)
                .all(|(_, b)| link_clear_of_box(&c, b, self.clearance_mm))
        })
    }

    /// Why a configuration is not free: the first range violation, else the closest offending
    /// (link, obstacle) pair; `None` when [`is_free`](Self::is_free) holds.
    pub fn why_blocked(&self, axes: &[f64; 3]) -> Option<Blocked> {
        if let Err(v) = self.robot.check_range3(axes) {
            return Some(Blocked::Range(v));
        }
        let poses = self.cell_link_poses(axes);
        let mut worst: Option<(usize, usize, f64)> = None;
        for i in 0..self.cyl.len() {
            let c = self.cylinder_in(i, &poses);
            for (k, b) in self.checked_boxes(i) {
                if !link_clear_of_box(&c, b, self.clearance_mm) {
                    let d = distance_cylinder_aabb(&c, b);
                    if worst.is_none_or(|(_, _, w)| d < w) {
                        worst = Some((i, k, d));
                    }
                }
            }
        }
        worst.map(|(i, k, d)| self.contact(i, k, d))
    }

    /// Smallest distance (mm) between any link cylinder and any box; `f64::INFINITY` without
    /// obstacles. Geometry only: the range is not checked.
    pub fn clearance_at(&self, axes: &[f64; 3]) -> f64 {
        let poses = self.cell_link_poses(axes);
        let mut best = f64::INFINITY;
        for i in 0..self.cyl.len() {
            let c = self.cylinder_in(i, &poses);
            for (_, b) in self.checked_boxes(i) {
                best = best.min(distance_cylinder_aabb(&c, b));
            }
        }
        best
    }

    /// The boxes cylinder `i` is checked against, with their indices: every box but those the
    /// robot stands on, for link 1 (module doc).
    fn checked_boxes(&self, i: usize) -> impl Iterator<Item = (usize, &Aabb)> + '_ {
        self.obstacles
            .iter()
            .enumerate()
            .filter(move |(k, _)| !self.cyl[i].exempt[*k])
            .map(|(k, o)| (k, &o.aabb))
    }

    /// Poses of links 1..3 in the cell frame.
    fn cell_link_poses(&self, axes: &[f64; 3]) -> [Isometry3<f64>; 3] {
        self.robot
            .arm_link_poses(axes)
            .map(|p| self.cell_from_robot * p)
    }

    /// Cylinder `i` in the cell frame for the given cell link poses.
    fn cylinder_in(&self, i: usize, poses: &[Isometry3<f64>; 3]) -> Cylinder {
        let c = &self.robot.cylinders[i];
        let p = &poses[self.cyl[i].joint];
        Cylinder {
            a: p * c.a,
            b: p * c.b,
            radius: c.radius_mm,
        }
    }

    fn contact(&self, i: usize, k: usize, d: f64) -> Blocked {
        Blocked::Contact {
            link: self.robot.cylinders[i].link.clone(),
            obstacle: self.obstacles[k].name.clone(),
            distance_mm: d,
        }
    }
}

/// The boxes clipped to a cube about the base of half-size (reach + clearance +
/// [`CLIP_MARGIN_MM`]), where the reach bounds every point of every link cylinder. Within that
/// cube nothing changes for any pose: a box point nearest to a link within the clearance (plus
/// the margin) lies inside it. Outside, a box (even one wholly outside, which becomes a flat box
/// on the cube's face) stays more than the margin away. Why: exact distances come from GJK, whose
/// rounding grows with the shapes' size (a 2 km floor overestimated a distance by 2e-5 mm, more
/// than the proofs' slack); clipping keeps every box within cell size, and keeps every number
/// finite.
fn clip_to_workspace(
    robot: &Robot,
    placement: &Placement,
    obstacles: Vec<Obstacle>,
    clearance_mm: f64,
) -> Vec<Obstacle> {
    let reach: f64 = robot
        .cylinders
        .iter()
        .map(|c| {
            let chain: f64 = (0..=c.joint_index)
                .map(|k| robot.joints[k].origin.translation.vector.norm())
                .sum();
            chain + c.a.coords.norm().max(c.b.coords.norm()) + c.radius_mm
        })
        .fold(0.0, f64::max);
    let half = reach + clearance_mm + CLIP_MARGIN_MM;
    let lo = Point::from(placement.base_mm.map(|v| v - half));
    let hi = Point::from(placement.base_mm.map(|v| v + half));
    obstacles
        .into_iter()
        .map(|o| {
            let clamp = |p: &Point| {
                Point::new(
                    p.x.clamp(lo.x, hi.x),
                    p.y.clamp(lo.y, hi.y),
                    p.z.clamp(lo.z, hi.z),
                )
            };
            Obstacle {
                aabb: Aabb::new(clamp(&o.aabb.min), clamp(&o.aabb.max)),
                ..o
            }
        })
        .collect()
}

/// Whether the exemption of boxes below the mounting plane (module doc) is sound for link-1
/// cylinder `c`: joint 1 turns about the base's vertical axis (so the cylinder's height is the
/// same in every pose) and no point of the cylinder lies below the mounting plane.
fn stands_on_its_mounting_plane(robot: &Robot, c: &crate::robot::LinkCylinder) -> bool {
    let j1 = &robot.joints[0];
    let axis = j1.origin.rotation * j1.axis.into_inner();
    if (axis.z.abs() - 1.0).abs() > 1e-9 {
        return false;
    }
    // Lowest point of the cylinder in the base frame (joint 1 at 0; its height is the same at
    // any angle): each end disc reaches r * sin(tilt) below its centre.
    let (a, b) = (j1.origin * c.a, j1.origin * c.b);
    let dir = (b - a).try_normalize(1e-12).unwrap_or_else(Vector3::z);
    let drop = c.radius_mm * (1.0 - dir.z * dir.z).max(0.0).sqrt();
    a.z.min(b.z) - drop >= -STANDS_ON_TOL_MM
}

/// The node test used everywhere in this module: `true` when the cylinder keeps MORE than
/// `clearance` from the box. [`cylinder_clear_of_aabb`] after two cheap extra bounds that keep
/// most queries out of parry's GJK (the capsule bounds are loose where a flat cap faces a box):
/// a lower bound from capsules around shortened axes that still contain the rim, and an upper
/// bound from points of the cylinder. Both are valid bounds, so the answer is the same.
#[inline]
fn link_clear_of_box(c: &Cylinder, b: &Aabb, clearance: f64) -> bool {
    if distance_capsule_aabb(c, b) > clearance {
        return true;
    }
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius.max(0.0);
    if len > 0.0 && r > 0.0 {
        let u = d / len;
        // Segment shortened by s at both ends, radius sqrt(r^2 + s^2): contains the cylinder.
        for k in [1.0, 2.5, 6.0] {
            let s = (k * r).min(0.5 * len);
            let lb = distance_segment_aabb(&(c.a + u * s), &(c.b - u * s), b) - r.hypot(s);
            if lb > clearance {
                return true;
            }
        }
        // Cap centres and the rim point of each cap nearest to the box lie on the cylinder.
        let mut ub = f64::INFINITY;
        for p in [c.a, c.b] {
            let q = Point::new(
                p.x.clamp(b.min.x, b.max.x),
                p.y.clamp(b.min.y, b.max.y),
                p.z.clamp(b.min.z, b.max.z),
            );
            let w = q - p;
            let perp = w - u * u.dot(&w);
            let n = perp.norm();
            let rim = if n > 0.0 {
                p + perp * (r.min(n) / n)
            } else {
                p
            };
            ub = ub
                .min(distance_point_aabb(&p, b))
                .min(distance_point_aabb(&rim, b));
        }
        if ub <= clearance {
            return false;
        }
    }
    cylinder_clear_of_aabb(c, b, clearance)
}

/// The place stage's question: why an IK solution cannot be used from this placement.
impl PoseCheck for CollisionModel {
    fn why_blocked(&self, joints_deg: &[f64; 6]) -> Option<String> {
        let arm = [joints_deg[0], joints_deg[1], joints_deg[2]];
        CollisionModel::why_blocked(self, &arm).map(|b| b.to_string())
    }
}
