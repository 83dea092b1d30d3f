//! The robot placed in a cell among box obstacles: which configurations are free, and which
//! straight joint moves are safe.
//!
//! Stage: [`Robot`] + [`Placement`] + obstacles + clearance -> [`CollisionModel`], queried by the
//! configuration-space builder (node inspection) and by the path shortener (whole moves).
//!
//! # Node inspection (Ting & Jar 2006, section 3)
//! The paper marks a configuration -1 when the arm hits an obstacle or is out of range, 0
//! otherwise, with the arm lumped into the cylinders of its first three links (section 6). Here a
//! configuration of axes 1..3 (controller values, degrees) is *free* ([`CollisionModel::is_free`])
//! when it is in range, the coupled axis-3 range included ([`Robot::check_range3`]), and every
//! link cylinder keeps MORE than `clearance` mm from every box. [`CollisionModel::inspect_column`]
//! is the same test for a whole column `[a1, a2, a3[k]]` of the grid, with the work that does not
//! depend on axis 3 done once per column.
//!
//! # Whole moves: the guarantee the paper lacks
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

use crate::geometry::{
    cylinder_clear_of_aabb, distance_capsule_aabb, distance_cylinder_aabb, distance_point_aabb,
    distance_segment_aabb, Aabb, Cylinder, Point,
};
use crate::robot::{RangeViolation, Robot};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

/// A box whose top is within this of the base's mounting plane (or below it) counts as what the
/// robot stands on, mm.
pub const STANDS_ON_TOL_MM: f64 = 1e-6;

/// Boxes are clipped to a cube about the base this much larger than the arm's reach plus the
/// clearance, mm (see [`clip_to_workspace`]).
pub const CLIP_MARGIN_MM: f64 = 10_000.0;

/// Bisection of a move stops (and rejects it) when the largest displacement of a link over the
/// interval, `M_L h`, falls below this, mm.
pub const MOVE_FLOOR_MM: f64 = 1e-3;

/// Distances used in proofs are lowered by `DISTANCE_SLACK_REL * (1 mm + d)`: parry's GJK stops at
/// a relative gap of about 5e-8 in f64 and errs from above.
pub const DISTANCE_SLACK_REL: f64 = 1e-6;

/// Most distance evaluations one (cylinder, box) pair may spend on a move before the move is
/// rejected (or, in [`CollisionModel::min_clearance_along`], before its bound is returned as is).
const MAX_EVALS_PER_PAIR: usize = 1 << 20;

/// Safety margin (mm) of the per-column culling of boxes.
const CULL_MARGIN_MM: f64 = 1e-6;

/// Obstacles per chunk of the per-column culling (the kept indices live on the stack).
const CULL_CHUNK: usize = 64;

/// A box obstacle of the cell.
#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    /// Name used in messages.
    pub name: String,
    /// The box, cell frame, mm.
    pub aabb: Aabb,
}

/// Where the robot stands: its base frame in the cell frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Translation of the base frame origin, cell frame, mm.
    pub base_mm: [f64; 3],
    /// Rotation of the base frame about the cell's z axis, degrees (counter-clockwise from above).
    pub yaw_deg: f64,
}

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
        let cell_from_robot = Isometry3::from_parts(
            Translation3::new(
                placement.base_mm[0],
                placement.base_mm[1],
                placement.base_mm[2],
            ),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), placement.yaw_deg.to_radians()),
        );
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
    /// further lowered by the [`DISTANCE_SLACK_REL`] slack). Geometry
    /// only: the range is not checked. `f64::INFINITY` without obstacles.
    pub fn min_clearance_along(&self, from: &[f64; 3], to: &[f64; 3], tol_mm: f64) -> f64 {
        let tol = if tol_mm >= 1e-6 { tol_mm } else { 1e-6 };
        let speeds = self.link_speeds(from, to);
        let ends: Vec<_> = (0..self.cyl.len())
            .map(|i| (self.pair_distances(i, from), self.pair_distances(i, to)))
            .collect();
        // Best attained distance so far: an upper bound of the minimum.
        let mut upper = ends
            .iter()
            .flat_map(|(a, b)| a.iter().chain(b))
            .fold(f64::INFINITY, |m, &d| m.min(d));
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
                    if raw >= upper - tol || evals >= MAX_EVALS_PER_PAIR {
                        result = result.min(interval_bound(d0, d1, reach));
                        continue;
                    }
                    let tm = 0.5 * (t0 + t1);
                    let dm = self.pair_distance_at(i, k, from, to, tm);
                    evals += 1;
                    upper = upper.min(dm);
                    stack.push((tm, t1, dm, d1));
                    stack.push((t0, tm, d0, dm));
                }
            }
        }
        // Distances are never negative: the slack may have taken the bound below 0.
        result.min(upper).max(0.0)
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

    // ---- internals ----

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

    /// `M_L` of the module doc for every cylinder: the most any of its points moves over the
    /// whole move, mm.
    fn link_speeds(&self, from: &[f64; 3], to: &[f64; 3]) -> Vec<f64> {
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

    fn contact(&self, i: usize, k: usize, d: f64) -> Blocked {
        Blocked::Contact {
            link: self.robot.cylinders[i].link.clone(),
            obstacle: self.obstacles[k].name.clone(),
            distance_mm: d,
        }
    }
}

/// A distance lowered by the slack that covers GJK's tolerance.
#[inline]
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
                name: o.name,
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
fn lerp(from: &[f64; 3], to: &[f64; 3], t: f64) -> [f64; 3] {
    std::array::from_fn(|i| from[i] + t * (to[i] - from[i]))
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

impl crate::plan::cspace::Inspector for CollisionModel {
    fn inspect_column(&self, a1_deg: f64, a2_deg: f64, a3_deg: &[f64], free: &mut [bool]) {
        CollisionModel::inspect_column(self, a1_deg, a2_deg, a3_deg, free)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;
    use parry3d::math::{Pose, Rotation, Vector};

    use crate::geometry::testing::Rng;

    fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
        Obstacle {
            name: name.to_string(),
            aabb: Aabb::new(Point3::from(min), Point3::from(max)),
        }
    }

    const TRUNK_PLACEMENT: Placement = Placement {
        base_mm: [0.0, -850.0, 0.0],
        yaw_deg: 90.0,
    };

    /// The trunk-like scene of the paper's section 6 (cell frame, mm).
    fn trunk() -> Vec<Obstacle> {
        vec![
            bx("floor", [-900.0, -450.0, 0.0], [900.0, 450.0, 100.0]),
            bx("near wall", [-900.0, -450.0, 0.0], [900.0, -430.0, 500.0]),
            bx("far wall", [-900.0, 430.0, 0.0], [900.0, 450.0, 500.0]),
            bx("left wall", [-900.0, -450.0, 0.0], [-880.0, 450.0, 500.0]),
            bx("right wall", [880.0, -450.0, 0.0], [900.0, 450.0, 500.0]),
            bx("tower", [-150.0, 0.0, 0.0], [150.0, 300.0, 1000.0]),
        ]
    }

    fn trunk_model(clearance: f64) -> CollisionModel {
        CollisionModel::new(&Robot::irb1400(), TRUNK_PLACEMENT, trunk(), clearance)
    }

    /// Cylinders in the cell frame computed independently of the model (robot FK + placement).
    fn reference_cylinders(robot: &Robot, pl: Placement, axes: &[f64; 3]) -> Vec<Cylinder> {
        let yaw = pl.yaw_deg.to_radians();
        let to_cell = |p: Point3<f64>| {
            Point3::new(
                yaw.cos() * p.x - yaw.sin() * p.y + pl.base_mm[0],
                yaw.sin() * p.x + yaw.cos() * p.y + pl.base_mm[1],
                p.z + pl.base_mm[2],
            )
        };
        let poses = robot.arm_link_poses(axes);
        robot
            .cylinders
            .iter()
            .map(|c| Cylinder {
                a: to_cell(poses[c.joint_index] * c.a),
                b: to_cell(poses[c.joint_index] * c.b),
                radius: c.radius_mm,
            })
            .collect()
    }

    /// Exact cylinder-box distance straight from parry3d-f64 (its own shapes, GJK).
    fn parry_distance(c: &Cylinder, b: &Aabb) -> f64 {
        let centre = nalgebra::center(&b.min, &b.max);
        let h = (b.max - b.min) * 0.5;
        let cuboid = parry3d::shape::Cuboid::new(Vector::new(h.x, h.y, h.z));
        let d = c.b - c.a;
        let len = d.norm();
        let u = d / len;
        let cyl = parry3d::shape::Cylinder::new(0.5 * len, c.radius);
        let m = nalgebra::center(&c.a, &c.b);
        let rot = Rotation::from_rotation_arc(Vector::Y, Vector::new(u.x, u.y, u.z));
        let pc = Pose::from_parts(Vector::new(m.x, m.y, m.z), rot);
        let pb = Pose::from_parts(
            Vector::new(centre.x, centre.y, centre.z),
            Rotation::IDENTITY,
        );
        parry3d::query::distance(&pc, &cyl, &pb, &cuboid)
            .expect("cylinder-cuboid is supported")
            .distance
    }

    /// Dense minimum of the parry distance along a move, with steps so that no point of any link
    /// moves more than 1 mm between samples; also the step count.
    fn dense_min(model: &CollisionModel, from: &[f64; 3], to: &[f64; 3]) -> (f64, usize) {
        let m = model
            .link_speeds(from, to)
            .into_iter()
            .fold(0.0f64, f64::max);
        let n = (m / 1.0).ceil().max(1.0) as usize;
        let mut best = f64::INFINITY;
        for s in 0..=n {
            let axes = lerp(from, to, s as f64 / n as f64);
            for c in reference_cylinders(model.robot(), model.placement(), &axes) {
                for o in model.obstacles() {
                    best = best.min(parry_distance(&c, &o.aabb));
                }
            }
        }
        (best, n)
    }

    fn random_in_range(rng: &mut Rng, model: &CollisionModel) -> [f64; 3] {
        loop {
            let a = [
                rng.range(-170.0, 170.0),
                rng.range(-70.0, 70.0),
                rng.range(-65.0, 70.0),
            ];
            if model.robot().check_range3(&a).is_ok() {
                return a;
            }
        }
    }

    /// Random moves with both ends free, spans up to `span` degrees per axis.
    fn random_free_moves(
        rng: &mut Rng,
        model: &CollisionModel,
        count: usize,
        span: f64,
    ) -> Vec<([f64; 3], [f64; 3])> {
        let mut out = Vec::new();
        while out.len() < count {
            let from = random_in_range(rng, model);
            if !model.is_free(&from) {
                continue;
            }
            let to = [0, 1, 2].map(|i| from[i] + rng.range(-span, span));
            // Two moves in three start near an obstacle, where the check has work to do.
            let near = model.clearance_at(&from).min(model.clearance_at(&to)) < 150.0;
            if model.is_free(&to) && (near || out.len() % 3 == 2) {
                out.push((from, to));
            }
        }
        out
    }

    #[test]
    fn placement_puts_the_zero_pose_wrist_centre_where_irb1400_md_says() {
        let robot = Robot::irb1400();
        let model = CollisionModel::new(&robot, TRUNK_PLACEMENT, vec![], 10.0);
        let want = Vector3::new(0.0, -850.0 + 870.0, 1195.0);
        let via_frame = model.cell_from_robot * robot.wrist_centre(&[0.0; 6]);
        assert!((via_frame.coords - want).norm() < 1e-9, "{via_frame:?}");
        // The wrist centre lies on the forearm cylinder's axis, 1020 mm from its back end.
        let cyls = model.cylinders(&[0.0; 3]);
        let (i, fore) = cyls[2];
        assert_eq!(robot.cylinders[i].link, "link_3");
        let u = (fore.b - fore.a).normalize();
        let on_axis = fore.a + u * 1020.0;
        assert!((on_axis.coords - want).norm() < 1e-9, "{on_axis:?}");
        // The base cylinder stands on the placement point.
        assert!((cyls[0].1.a.coords - Vector3::new(0.0, -850.0, 0.0)).norm() < 1e-9);
    }

    #[test]
    fn why_blocked_names_the_link_and_the_obstacle() {
        let robot = Robot::irb1400();
        let here = Placement {
            base_mm: [0.0; 3],
            yaw_deg: 0.0,
        };
        // Zero pose: forearm along x at z = 1195 (r 120); upper arm along z at x = 150 (r 150).
        let front = bx("front", [600.0, -50.0, 1100.0], [700.0, 50.0, 1300.0]);
        let side = bx("side", [305.0, -50.0, 800.0], [400.0, 50.0, 900.0]);
        let both = CollisionModel::new(&robot, here, vec![side.clone(), front.clone()], 10.0);
        assert!(!both.is_free(&[0.0; 3]));
        match both.why_blocked(&[0.0; 3]) {
            Some(Blocked::Contact {
                link,
                obstacle,
                distance_mm,
            }) => {
                assert_eq!((link.as_str(), obstacle.as_str()), ("link_3", "front"));
                assert_eq!(distance_mm, 0.0);
            }
            other => panic!("{other:?}"),
        }
        let only_side = CollisionModel::new(&robot, here, vec![side], 10.0);
        let why = only_side.why_blocked(&[0.0; 3]);
        match &why {
            Some(Blocked::Contact {
                link,
                obstacle,
                distance_mm,
            }) => {
                assert_eq!((link.as_str(), obstacle.as_str()), ("link_2", "side"));
                assert!((distance_mm - 5.0).abs() < 1e-9, "{distance_mm}");
            }
            other => panic!("{other:?}"),
        }
        let text = why.map(|w| w.to_string()).unwrap_or_default();
        assert!(
            text.contains("link_2") && text.contains("'side'") && text.contains("5.00 mm"),
            "{text}"
        );
        // Raising the box clears the upper arm: 5 mm is not more than 10, 15 mm is.
        let clear = CollisionModel::new(
            &robot,
            here,
            vec![bx("side", [315.0, -50.0, 800.0], [400.0, 50.0, 900.0])],
            10.0,
        );
        assert!(clear.is_free(&[0.0; 3]) && clear.why_blocked(&[0.0; 3]).is_none());
        assert!((clear.clearance_at(&[0.0; 3]) - 15.0).abs() < 1e-9);
        // Range comes first, the coupled range included.
        assert!(matches!(
            both.why_blocked(&[0.0, -70.0, 70.0]),
            Some(Blocked::Range(RangeViolation::Coupled { .. }))
        ));
    }

    #[test]
    fn is_free_and_inspect_column_agree_on_a_coarse_grid() {
        let model = trunk_model(10.0);
        // A few values outside the ranges exercise the range checks.
        let a3: Vec<f64> = (-14..=15).map(|k| k as f64 * 5.0).collect();
        let mut col = vec![false; a3.len()];
        let (mut free, mut blocked, mut range) = (0, 0, 0);
        for i1 in -18..=18 {
            for i2 in -8..=8 {
                let (a1, a2) = (i1 as f64 * 10.0 - 0.5, i2 as f64 * 9.0 + 0.25);
                model.inspect_column(a1, a2, &a3, &mut col);
                for (k, &v) in a3.iter().enumerate() {
                    let axes = [a1, a2, v];
                    let want = model.is_free(&axes);
                    assert_eq!(col[k], want, "{axes:?}");
                    assert_eq!(model.why_blocked(&axes).is_none(), want, "{axes:?}");
                    if want {
                        free += 1;
                        assert!(model.clearance_at(&axes) > 10.0, "{axes:?}");
                    } else if model.robot().check_range3(&axes).is_err() {
                        range += 1;
                    } else {
                        blocked += 1;
                        assert!(model.clearance_at(&axes) <= 10.0 + 1e-6, "{axes:?}");
                    }
                }
            }
        }
        assert!(
            free > 1000 && blocked > 500 && range > 1000,
            "{free} {blocked} {range}"
        );
        // At 1 degree, as the planner fills the grid (exercises the skipping along the column).
        let fine: Vec<f64> = (-65..=70).map(f64::from).collect();
        let mut col = vec![false; fine.len()];
        let mut rng = Rng(0xF1E1_D000_0000_0001);
        let (mut free, mut blocked) = (0, 0);
        for _ in 0..300 {
            let (a1, a2) = (rng.range(-170.0, 170.0), rng.range(-70.0, 70.0));
            model.inspect_column(a1, a2, &fine, &mut col);
            for (k, &v) in fine.iter().enumerate() {
                assert_eq!(col[k], model.is_free(&[a1, a2, v]), "{:?}", [a1, a2, v]);
                if col[k] {
                    free += 1;
                } else {
                    blocked += 1;
                }
            }
        }
        assert!(free > 5000 && blocked > 5000, "{free} {blocked}");
        // A free slice longer than the column is padded with `false`.
        let mut longer = vec![true; 4];
        model.inspect_column(0.0, 0.0, &[0.0, -5.0], &mut longer);
        assert_eq!(longer, [true, true, false, false]);
    }

    #[test]
    fn extra_bounds_of_link_clear_of_box_agree_with_parry() {
        let mut rng = Rng(0xB0B0_CAFE_1234_5678);
        let (mut clear, mut blocked) = (0, 0);
        for k in 0..4000 {
            let b = Aabb::new(
                Point::new(
                    rng.range(-300.0, 0.0),
                    rng.range(-300.0, 0.0),
                    rng.range(-300.0, 0.0),
                ),
                Point::new(
                    rng.range(0.0, 300.0),
                    rng.range(0.0, 300.0),
                    rng.range(0.0, 300.0),
                ),
            );
            // Cylinders near the box, often with a cap facing it.
            let a = Point::new(
                rng.range(-600.0, 600.0),
                rng.range(-600.0, 600.0),
                rng.range(-600.0, 600.0),
            );
            let dir = if k % 2 == 0 {
                (a - nalgebra::center(&b.min, &b.max)).normalize()
            } else {
                Vector3::new(
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                )
                .normalize()
            };
            let c = Cylinder {
                a,
                b: a + dir * rng.range(50.0, 1100.0),
                radius: rng.range(20.0, 150.0),
            };
            let exact = parry_distance(&c, &b);
            let clearance = if k % 3 == 0 {
                rng.range(0.0, 30.0)
            } else {
                exact + rng.range(-20.0, 20.0)
            };
            let got = link_clear_of_box(&c, &b, clearance.max(0.0));
            if (exact - clearance.max(0.0)).abs() > 1e-6 {
                assert_eq!(
                    got,
                    exact > clearance.max(0.0),
                    "case {k}: exact {exact}, clearance {clearance}, {c:?} {b:?}"
                );
            }
            if got {
                clear += 1
            } else {
                blocked += 1
            }
        }
        assert!(clear > 1000 && blocked > 1000, "{clear} {blocked}");
    }

    #[test]
    fn lipschitz_bound_holds_for_small_random_deltas() {
        let model = trunk_model(10.0);
        let robot = model.robot().clone();
        let mut rng = Rng(0x5EED_0123_4567_89AB);
        let mut worst_ratio = 0.0f64;
        for _ in 0..3000 {
            let q = random_in_range(&mut rng, &model);
            let d = [0, 1, 2].map(|_| rng.range(-3.0, 3.0));
            let q2 = [q[0] + d[0], q[1] + d[1], q[2] + d[2]];
            let bound = model.link_speeds(&q, &q2);
            let (p1, p2) = (model.cell_link_poses(&q), model.cell_link_poses(&q2));
            for (i, c) in robot.cylinders.iter().enumerate() {
                let j = c.joint_index;
                // End points and rim points of both caps.
                let axis = (c.b - c.a).normalize();
                let n1 = axis
                    .cross(&Vector3::x())
                    .try_normalize(1e-9)
                    .unwrap_or_else(|| axis.cross(&Vector3::y()).normalize());
                let n2 = axis.cross(&n1);
                let mut pts = vec![c.a, c.b];
                for end in [c.a, c.b] {
                    for n in [n1, -n1, n2, -n2] {
                        pts.push(end + n * c.radius_mm);
                    }
                }
                for p in pts {
                    let moved = (p2[j] * p - p1[j] * p).norm();
                    assert!(
                        moved <= bound[i] * (1.0 + 1e-9) + 1e-9,
                        "{} at {q:?} + {d:?}: moved {moved} > bound {}",
                        c.link,
                        bound[i]
                    );
                    if bound[i] > 1e-6 {
                        worst_ratio = worst_ratio.max(moved / bound[i]);
                    }
                }
            }
        }
        // The bound is not absurdly loose either.
        assert!(
            worst_ratio > 0.5,
            "largest displacement / bound = {worst_ratio}"
        );
    }

    #[test]
    fn accepted_moves_keep_the_clearance_at_dense_samples() {
        // The trunk, plus a pillar and a shelf beside the robot.
        let mut boxes = trunk();
        boxes.push(bx("pillar", [500.0, -1000.0, 0.0], [700.0, -800.0, 1600.0]));
        boxes.push(bx(
            "shelf",
            [-900.0, -1300.0, 900.0],
            [-500.0, -900.0, 1000.0],
        ));
        let model = CollisionModel::new(&Robot::irb1400(), TRUNK_PLACEMENT, boxes, 10.0);
        let mut rng = Rng(0x0DDB_A11C_0FFE_E123);
        let moves = random_free_moves(&mut rng, &model, 150, 90.0);
        let (mut accepted, mut roomy, mut roomy_accepted, mut unsafe_seen) = (0, 0, 0, 0);
        for (from, to) in &moves {
            let safe = model.move_is_safe(from, to);
            let (dmin, n) = dense_min(&model, from, to);
            if safe {
                accepted += 1;
                assert!(
                    dmin >= 10.0 - 1e-6,
                    "accepted {from:?} -> {to:?}, dense min {dmin} ({n} samples)"
                );
                assert!(model.why_move_unsafe(from, to).is_none());
            } else {
                let why = model.why_move_unsafe(from, to);
                assert!(why.is_some(), "{from:?} -> {to:?}");
            }
            if dmin < 10.0 {
                unsafe_seen += 1;
                assert!(!safe);
            }
            if dmin >= 15.0 {
                roomy += 1;
                if safe {
                    roomy_accepted += 1;
                }
            }
        }
        eprintln!("moves {} accepted {accepted} unsafe {unsafe_seen} roomy {roomy} roomy accepted {roomy_accepted}", moves.len());
        assert!(
            unsafe_seen > 10 && roomy > 30,
            "the scene must exercise both: unsafe {unsafe_seen}, roomy {roomy}"
        );
        assert!(
            roomy_accepted as f64 >= 0.9 * roomy as f64,
            "only {roomy_accepted} of {roomy} roomy moves accepted"
        );
    }

    #[test]
    fn min_clearance_along_brackets_the_dense_minimum() {
        let model = trunk_model(10.0);
        let mut rng = Rng(0xC1EA_4A4C_E000_0001);
        let tol = 0.5;
        let mut checked = 0;
        for (from, to) in random_free_moves(&mut rng, &model, 40, 40.0) {
            let got = model.min_clearance_along(&from, &to, tol);
            let (dmin, _) = dense_min(&model, &from, &to);
            // Certified lower bound of the true minimum, itself <= any sample.
            assert!(
                got <= dmin + 1e-6,
                "{from:?} -> {to:?}: {got} > dense {dmin}"
            );
            // Within tol of the true minimum, which is within 0.5 mm (1 mm steps) of the samples.
            assert!(
                got >= dmin - tol - 0.5 - 1e-3,
                "{from:?} -> {to:?}: {got} << dense {dmin}"
            );
            checked += 1;
        }
        assert_eq!(checked, 40);
    }

    #[test]
    fn a_move_through_a_box_is_refused_and_located() {
        let robot = Robot::irb1400();
        let here = Placement {
            base_mm: [0.0; 3],
            yaw_deg: 0.0,
        };
        // A post in front of the zero-pose forearm; swinging axis 1 from -60 to +60 sweeps
        // the forearm through it, while both ends are free.
        let model = CollisionModel::new(
            &robot,
            here,
            vec![bx("post", [600.0, -50.0, 1000.0], [700.0, 50.0, 1400.0])],
            10.0,
        );
        let (from, to) = ([-60.0, 0.0, 0.0], [60.0, 0.0, 0.0]);
        assert!(model.is_free(&from) && model.is_free(&to));
        assert!(!model.move_is_safe(&from, &to));
        let (t, why) = model.why_move_unsafe(&from, &to).expect("unsafe");
        assert!(
            t > 0.3 && t < 0.5,
            "the forearm reaches the post before axis 1 = 0: t = {t}"
        );
        assert!(
            matches!(&why, Blocked::Contact { link, obstacle, distance_mm } if link == "link_3" && obstacle == "post" && *distance_mm < 10.0),
            "{why:?}"
        );
        assert!(model.min_clearance_along(&from, &to, 0.1) <= 0.0 + 1e-9);
        // Lifting the forearm over the post makes the move safe.
        let (up0, up1) = ([-60.0, 0.0, -40.0], [60.0, 0.0, -40.0]);
        assert!(
            model.move_is_safe(&up0, &up1),
            "{:?}",
            model.why_move_unsafe(&up0, &up1)
        );
        // An end out of range is reported at its end.
        let bad = [0.0, 0.0, 75.0];
        assert!(!model.move_is_safe(&up0, &bad));
        assert!(
            matches!(model.why_move_unsafe(&up0, &bad), Some((t, Blocked::Range(_))) if t == 1.0)
        );
    }

    #[test]
    fn no_obstacles_and_zero_clearance_are_fine() {
        let model = CollisionModel::new(&Robot::irb1400(), TRUNK_PLACEMENT, vec![], 0.0);
        assert_eq!(model.clearance_at(&[0.0; 3]), f64::INFINITY);
        assert_eq!(
            model.min_clearance_along(&[0.0; 3], &[90.0, 30.0, 20.0], 0.0),
            f64::INFINITY
        );
        assert!(model.is_free(&[0.0; 3]) && !model.is_free(&[0.0, 0.0, -70.0]));
        assert!(model.move_is_safe(&[-170.0, -70.0, -65.0], &[170.0, 70.0, 70.0]));
        let mut col = [true; 3];
        model.inspect_column(0.0, 0.0, &[-66.0, 0.0, 71.0], &mut col);
        assert_eq!(col, [false, true, false]);
        model.inspect_column(171.0, 0.0, &[0.0, 10.0, 20.0], &mut col);
        assert_eq!(col, [false; 3]);
        model.inspect_column(0.0, 0.0, &[], &mut []);
    }

    #[test]
    fn the_robot_stands_on_a_floor_but_the_arm_may_not_touch_it() {
        let robot = Robot::irb1400();
        let on_floor = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        let floor = bx("floor", [-3000.0, -3000.0, -50.0], [3000.0, 3000.0, 0.0]);
        let m = CollisionModel::new(&robot, on_floor, vec![floor], 10.0);
        // The base cylinder rests on the floor: not a contact.
        assert!(m.is_free(&[0.0, 0.0, 0.0]));
        assert!(m.move_is_safe(&[-90.0, 0.0, 0.0], &[90.0, 0.0, 0.0]));
        // Nearest to the floor: the upper arm's bottom cap, at axis 2's height of 475 mm.
        let d = m.min_clearance_along(&[-90.0, 0.0, 0.0], &[90.0, 0.0, 0.0], 0.1);
        assert!((474.8..=475.0).contains(&d), "{d}");
        // The forearm reaching down to the floor is a contact (wrist centre at z = 44 mm).
        match m.why_blocked(&[0.0, 70.0, 70.0]) {
            Some(Blocked::Contact { link, obstacle, .. }) => {
                assert_eq!((link.as_str(), obstacle.as_str()), ("link_3", "floor"))
            }
            other => panic!("expected a contact, got {other:?}"),
        }
        // A box reaching 1 mm above the mounting plane is no floor: the base touches it.
        let mat = bx("mat", [-3000.0, -3000.0, -50.0], [3000.0, 3000.0, 1.0]);
        let m = CollisionModel::new(&robot, on_floor, vec![mat], 10.0);
        assert!(
            matches!(m.why_blocked(&[0.0, 0.0, 0.0]), Some(Blocked::Contact { ref link, .. }) if link == "link_1")
        );
        // On a 400 mm pedestal the pedestal is what it stands on; the floor below still counts
        // for the arm.
        let raised = Placement {
            base_mm: [0.0, 0.0, 400.0],
            yaw_deg: 0.0,
        };
        let pedestal = bx("pedestal", [-400.0, -400.0, 0.0], [400.0, 400.0, 400.0]);
        let m = CollisionModel::new(&robot, raised, vec![pedestal], 10.0);
        assert!(m.is_free(&[0.0, 0.0, 0.0]));
    }

    #[test]
    fn a_huge_box_is_measured_as_exactly_as_a_cell_sized_one() {
        // Review finding: a 2 km floor let GJK's rounding overestimate a distance beyond the
        // proofs' slack (0.4861370 against 0.4861155 mm). Boxes are clipped to the workspace.
        let robot = Robot::irb1400();
        let at = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        let q = [0.0, 63.0, 68.1];
        let floor = |s: f64| bx("floor", [-s, -s, -1000.0], [s, s, 0.0]);
        let small = CollisionModel::new(&robot, at, vec![floor(5000.0)], 0.0).clearance_at(&q);
        let huge = CollisionModel::new(&robot, at, vec![floor(1e6)], 0.0).clearance_at(&q);
        assert!((small - huge).abs() < 1e-9, "{small} vs {huge}");
        let c = small + 1e-5; // just above the true distance: the pose is not free
        let m = CollisionModel::new(&robot, at, vec![floor(1e6)], c);
        assert!(!m.is_free(&q) && !m.move_is_safe(&q, &q));
    }

    #[test]
    fn a_box_far_away_blocks_nothing() {
        let robot = Robot::irb1400();
        let at = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        let m = CollisionModel::new(&robot, at, vec![bx("far", [1e160; 3], [2e160; 3])], 10.0);
        assert!(m.is_free(&[0.0, 0.0, 0.0]));
        assert!(m.move_is_safe(&[0.0, 0.0, 0.0], &[10.0, 0.0, 0.0]));
        let d = m.min_clearance_along(&[0.0, 0.0, 0.0], &[10.0, 0.0, 0.0], 0.1);
        assert!(d.is_finite() && d > CLIP_MARGIN_MM, "{d}");
    }

    #[test]
    fn a_base_cylinder_below_its_mounting_plane_is_not_exempt() {
        // The same robot with its base cylinder lowered 125 mm into the floor: the floor counts.
        let text = include_str!("../../robots/irb1400.urdf").replace(
            r#"<origin xyz="0 0 0.325" rpy="0 0 0"/>"#,
            r#"<origin xyz="0 0 0.2" rpy="0 0 0"/>"#,
        );
        let robot =
            crate::robot::urdf::robot_from_urdf(std::path::Path::new("x.urdf"), &text, None)
                .expect("loads");
        let at = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        let floor = bx("floor", [-3000.0, -3000.0, -50.0], [3000.0, 3000.0, 0.0]);
        let m = CollisionModel::new(&robot, at, vec![floor.clone()], 10.0);
        assert!(
            matches!(m.why_blocked(&[0.0, 0.0, 0.0]), Some(Blocked::Contact { ref link, .. }) if link == "link_1")
        );
        // The bundled robot stands on the same floor.
        assert!(
            CollisionModel::new(&Robot::irb1400(), at, vec![floor], 10.0).is_free(&[0.0, 0.0, 0.0])
        );
    }
}
