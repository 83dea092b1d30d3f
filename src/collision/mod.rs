//! The robot placed in a cell among box obstacles, with its tool: which configurations are free,
//! and which straight joint moves are safe.
//!
//! The inspect stage's model: [`Robot`] + [`Placement`] + obstacles + clearance + the cell's tool
//! -> [`CollisionModel`], queried by the place stage (are a point's IK solutions usable?
//! [`PoseCheck`]), by the configuration-space grid (node codes, `grid.rs`, `column.rs`) and by
//! the planner (whole moves, `proof.rs`). The parts of the model ([`Part`]): the link
//! cylinders on links 1..3 (the paper's lumped arm, with the cylinders that hold base_link's and
//! link 4's: `Robot::cylinders`) and the flange's shapes, carried by axes 4..6 on the flange
//! (the robot's `tool0`): the robot's own of links 5 and 6 (`Robot::flange_parts`) and the
//! tool's (cylinder, box in the flange frame, ball), `parts.rs`.
//! Every query takes all six axes, except the grid's node test of the arm. `clear.rs` holds the
//! test of one part against one box, `look.rs` the tool looks of a leg's search. Tests in
//! `tests.rs` (links, against parry3d and dense sampling), `tool_tests.rs` (the tool, the grid
//! codes), `look_tests.rs` (the looks against the exact test) and `robots_tests.rs` (every
//! link of every shipped robot).
//!
//! # Node inspection (Ting & Jar 2006, section 3)
//! The paper marks a configuration -1 when the arm hits an obstacle or is out of range, 0
//! otherwise, with the arm lumped into the cylinders of its first three links (section 6). Here a
//! configuration of axes 1..3 (controller values, degrees) is *free* for the arm
//! ([`CollisionModel::arm_is_free`]) when it is in range, the coupled axis-3 range included
//! ([`Robot::check_range3`]), and every link cylinder keeps MORE than `clearance` mm from every
//! box. [`GridCheck::inspect_column`] is the same test for a whole column `[a1, a2, a3[k]]` of the
//! grid, with the work that does not depend on axis 3 done once per column (`column.rs`); it
//! also keeps per node how deep in free space the node lies and whether the tool could reach a
//! box there (`grid.rs`). Beyond the paper, a whole pose ([`CollisionModel::is_free`]) is free
//! when all six axes are in range and every link cylinder and every tool shape keeps more than
//! the clearance; the tool's part is [`CollisionModel::tool_is_free`], which the planner asks
//! per leg, with the leg's wrist, where the grid says the tool could reach a box.
//!
//! The whole-move proof (`proof.rs`) is the guarantee the paper lacks: every straight six-axis
//! move written is proven to keep the clearance at every instant, links and tool, not only at
//! grid nodes.
//! `path.rs` extends it to process moves: along the path a `MoveL` or `MoveC` runs, followed
//! by the continuing inverse kinematics, each chord between two samples proven with the
//! clearance raised by how far the true joint path may stray from it.
//!
//! Frames: the robot base frame sits in the cell frame at [`Placement`] (translation, then yaw
//! about z); obstacles are axis-aligned boxes of the cell frame; tool shapes are given in the
//! flange (tool0) frame. Units: mm and degrees.
//!
//! Nodes and moves: a node is free when every part keeps *more* than the clearance (a node at
//! exactly the clearance counts as blocked, the paper's "comes within"); a move is accepted when
//! the proven lower bound is *at least* the clearance (the guarantee the module header states).
//! Messages name the part: links as "link 'link_3' of the robot", tool shapes as "tool shape
//! 'neck'".
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
//! The tool's shapes are checked against every box: the robot stands on the floor, its tool
//! does not.
//!
//! Boxes are clipped to the robot's workspace (plus a 10 m margin) when the model is built, so
//! that every distance is computed on cell-sized shapes ([`CLIP_MARGIN_MM`]).

mod angles;
mod block;
#[cfg(test)]
mod block_tests;
mod clear;
mod column;
mod corner;
mod grid;
mod look;
#[cfg(test)]
mod look_tests;
mod memo;
mod near;
mod parts;
mod path;
#[cfg(test)]
mod path_tests;
mod proof;
#[cfg(test)]
mod proof_tests;
#[cfg(test)]
mod robots_tests;
mod slots;
#[cfg(test)]
mod tests;
#[cfg(test)]
pub(crate) mod tool_tests;

pub use grid::{Ends, GridCheck, CODE_FREE};
pub use path::{PathBlocked, PathClearance, PATH_CLEARANCE_TOL_MM};
pub use proof::{Clearance, DISTANCE_SLACK_REL, MOVE_FLOOR_MM};

pub use crate::cell::Obstacle;
use crate::cell::{Cell, Tool};
use crate::geometry::{distance_sq_point_aabb, gap_sq_aabb_aabb, Aabb, Cylinder, Point, Solid};
use crate::place::{Placement, PoseCheck};
use crate::robot::{RangeViolation, Robot};
use clear::{link_clear_of_box, solid_clear_of_box};
use look::{ToolLook, UPPER_BOUND_SLACK_MM};
use nalgebra::{Isometry3, Vector3};
use parts::ToolData;

/// A box whose top is within this of the base's mounting plane (or below it) counts as what the
/// robot stands on, mm.
pub const STANDS_ON_TOL_MM: f64 = 1e-6;

/// Boxes are clipped to a cube about the base this much larger than the arm's reach plus the
/// clearance, mm (see `clip_to_workspace`).
pub const CLIP_MARGIN_MM: f64 = 10_000.0;

/// A part of the robot model, by name: a link cylinder or a tool shape.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Part {
    /// A collision volume of a link (a cylinder of the lumped arm, or a link-5 or link-6 part
    /// on the flange), by the name of the link whose geometry it holds.
    Link(String),
    /// A shape of the cell's tool, by its name in the `tool:` block.
    ToolShape(String),
}

impl std::fmt::Display for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Part::Link(name) => write!(f, "link '{name}' of the robot"),
            Part::ToolShape(name) => write!(f, "tool shape '{name}'"),
        }
    }
}

/// Why a configuration (or a move) is not free.
#[derive(Clone, Debug, PartialEq)]
pub enum Blocked {
    /// An axis, or the coupled axis-3 range, is violated.
    Range(RangeViolation),
    /// A part (link cylinder or tool shape) comes closer than the clearance to a box.
    /// `distance_mm` is the distance (0 when they touch or overlap); for a move rejected without
    /// a witness it is the certified lower bound that failed.
    Contact {
        part: Part,
        obstacle: String,
        distance_mm: f64,
    },
}

impl std::fmt::Display for Blocked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Blocked::Range(v) => write!(f, "the robot cannot reach this pose: {v}"),
            Blocked::Contact {
                part,
                obstacle,
                distance_mm,
            } if *distance_mm <= 0.0 => write!(f, "{part} hits obstacle '{obstacle}'"),
            // Links keep the wording (and the 0.01 mm) of the messages users know; tool shapes
            // read "tool shape 'neck' comes within 4.2 mm of ..." (0.1 mm).
            Blocked::Contact {
                part: part @ Part::Link(_),
                obstacle,
                distance_mm,
            } => write!(
                f,
                "{part} comes within {distance_mm:.2} mm of obstacle '{obstacle}', less than the \
                 required clearance"
            ),
            Blocked::Contact {
                part,
                obstacle,
                distance_mm,
            } => write!(
                f,
                "{part} comes within {distance_mm:.1} mm of obstacle '{obstacle}', less than the \
                 required clearance"
            ),
        }
    }
}

/// Per-cylinder data fixed at construction.
#[derive(Clone, Debug)]
struct CylData {
    /// Index of the URDF joint whose child link carries the cylinder (0, 1 or 2).
    joint: usize,
    /// `R[i]` of the module doc of `proof.rs` for `i <= joint`, 0 beyond: distance bound from
    /// joint `i`'s axis.
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
    /// The tool's shapes (none: no tool volume).
    tool: Option<ToolData>,
    /// With a tool: the chain that places the flange from the joints' sines and cosines, and
    /// the boxes by coordinate (the tool looks of a leg's search,
    /// [`tool_look_sincos`](Self::tool_look_sincos)).
    look: Option<Box<ToolLook>>,
    /// The whole moves [`move_is_safe`](Self::move_is_safe) has answered (`memo.rs`).
    proven: memo::ProofMemo,
}

/// The poses a configuration puts the parts at: links 1..3, and link 6 (the flange) when the
/// model has a tool; cell frame.
pub(crate) struct Poses {
    arm: [Isometry3<f64>; 3],
    flange: Option<Isometry3<f64>>,
}

/// Axes 1..3 of six.
#[inline]
pub(crate) fn arm_of(six: &[f64; 6]) -> [f64; 3] {
    [six[0], six[1], six[2]]
}

impl CollisionModel {
    /// Places `robot` (cloned) at `placement` among `obstacles` (cell frame, mm), with the
    /// shapes of `tool` on its flange (`None`, or a tool without shapes: no tool volume);
    /// `clearance_mm` is the distance every link and tool shape must keep from every box (0
    /// allowed; negative is taken as 0).
    ///
    /// The robot's cylinders must hang on links 1..3 (`joint_index` 0, 1 or 2), as
    /// [`Robot::load`] guarantees.
    pub fn new(
        robot: &Robot,
        placement: Placement,
        obstacles: Vec<Obstacle>,
        clearance_mm: f64,
        tool: Option<&Tool>,
    ) -> CollisionModel {
        let tool = ToolData::new(robot, tool);
        let obstacles = clip_to_workspace(
            robot,
            tool.as_ref(),
            &placement,
            obstacles,
            clearance_mm.max(0.0),
        );
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
                let reach = parts::reach(robot, j, &[c.a, c.b], r);
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
                    reach_mm: [reach[0], reach[1], reach[2]],
                    split: [split_of(c.a.coords), split_of(c.b.coords)],
                    sweep_radius_mm: far,
                    axial_mm: [sa.min(sb) - r, sa.max(sb) + r],
                    exempt,
                }
            })
            .collect();
        let look = tool
            .as_ref()
            .map(|_| Box::new(ToolLook::new(robot, &cell_from_robot, &obstacles)));
        CollisionModel {
            robot: robot.clone(),
            placement,
            cell_from_robot,
            obstacles,
            clearance_mm: clearance_mm.max(0.0),
            cyl,
            tool,
            look,
            proven: memo::ProofMemo::default(),
        }
    }

    /// The model of `cell`'s obstacles, clearance and tool with `robot` at `placement`.
    pub fn of_cell(cell: &Cell, robot: &Robot, placement: Placement) -> CollisionModel {
        CollisionModel::new(
            robot,
            placement,
            cell.obstacles.clone(),
            cell.planner.clearance_mm,
            cell.tool.as_ref(),
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

    /// The clearance every link and tool shape must keep from every box, mm.
    pub fn clearance_mm(&self) -> f64 {
        self.clearance_mm
    }

    /// The same model asking `extra_mm` more clearance of the moves it proves (the refine
    /// stage's margin: a route that keeps it leaves room for the zones' corners). Only the
    /// whole-move and corner proofs are meant to be asked of it; the boxes stay clipped for the
    /// cell's clearance, so whatever it accepts is proven again on the cell's model.
    pub fn with_margin(&self, extra_mm: f64) -> CollisionModel {
        let mut m = self.clone();
        m.clearance_mm += extra_mm.max(0.0);
        m
    }

    /// Where the robot stands in the cell.
    pub fn placement(&self) -> Placement {
        self.placement
    }

    /// Whether the model carries flange shapes, the tool's or the robot's own links 5 and 6
    /// (then axes 4..6 matter to every check).
    pub fn has_tool(&self) -> bool {
        self.tool.is_some()
    }

    /// The radius about the wrist centre of the ball that holds every flange shape for any wrist
    /// angles, mm (`parts.rs`); `None` without one.
    pub fn tool_radius_mm(&self) -> Option<f64> {
        self.tool.as_ref().map(|t| t.radius_mm)
    }

    /// Every part placed in the cell frame for `axes` (controller values of axes 1..6): the
    /// link cylinders, then the tool shapes, each with its name.
    pub fn solids(&self, axes: &[f64; 6]) -> Vec<(Part, Solid)> {
        let poses = self.poses(axes);
        (0..self.part_count())
            .map(|p| (self.part(p), self.solid(p, &poses)))
            .collect()
    }

    /// Node inspection of the arm (the paper's node test, axes 1..3): `true` when the
    /// configuration is in range (coupled axis-3 range included) and every link cylinder keeps
    /// MORE than the clearance from every box. The tool is not looked at.
    pub fn arm_is_free(&self, axes: &[f64; 3]) -> bool {
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

    /// Whether every tool shape keeps MORE than the clearance from every box at `axes` (axes
    /// 1..6); `true` without a tool. Neither the range nor the links are looked at. Per shape,
    /// a box farther than the clearance from the shape's ball (`parts.rs`, one point placed) is
    /// passed; then the shape's enclosing box, then the exact test.
    pub fn tool_is_free(&self, axes: &[f64; 6]) -> bool {
        self.tool.is_none() || self.tool_is_free_at::<false>(&self.flange_pose(axes), &[])
    }

    /// [`tool_is_free`](Self::tool_is_free) with link 6 at `flange` (cell frame). With `INNER`,
    /// a shape near a box is first measured by an upper bound of its distance
    /// (`Solid::upper_distance_aabb`: points of the shape, a cylinder's inner capsule, which
    /// the exact cylinder test's distance never exceeds): within the clearance less
    /// [`UPPER_BOUND_SLACK_MM`] it is within the clearance by the exact test too, answered
    /// without it (the same answer).
    ///
    /// A shape `i` with `far[i]` true is passed without a look at the boxes: the caller vouches
    /// that every box is farther than the clearance from its ball (by more than the rounding
    /// of `flange`), which the ball test below would find for each box, so the answer is the
    /// same.
    fn tool_is_free_at<const INNER: bool>(&self, flange: &Isometry3<f64>, far: &[bool]) -> bool {
        let Some(tool) = &self.tool else {
            return true;
        };
        let c = self.clearance_mm;
        tool.shapes.iter().enumerate().all(|(i, s)| {
            if far.get(i) == Some(&true) {
                return true;
            }
            // First the shape's ball (one point placed): most boxes are farther than that. Then
            // the enclosing box of the shape, placed once, and the exact test.
            let (centre, radius) = s.ball;
            let centre = flange * centre;
            let far = radius + c;
            let mut placed: Option<(Solid, Aabb)> = None;
            self.obstacles.iter().all(|o| {
                if distance_sq_point_aabb(&centre, &o.aabb) > far * far {
                    return true;
                }
                let (solid, e) = placed.get_or_insert_with(|| {
                    let solid = s.local.placed(flange);
                    let e = solid.enclosing_aabb();
                    (solid, e)
                });
                if gap_sq_aabb_aabb(e, &o.aabb) > c * c {
                    return true;
                }
                if INNER && solid.upper_distance_aabb(&o.aabb) <= c - UPPER_BOUND_SLACK_MM {
                    return false;
                }
                solid_clear_of_box(solid, &o.aabb, c)
            })
        })
    }

    /// The flange's pose (link 6, cell frame) by [`Robot::link_poses`] (for tests).
    #[cfg(test)]
    pub(crate) fn flange_pose_for_test(&self, axes: &[f64; 6]) -> Isometry3<f64> {
        self.flange_pose(axes)
    }

    /// The most any point of any tool shape moves over a straight move of `delta_deg`
    /// (controller axes 1..6, deg; axes 1..3 signed, as the coupling of axis 3 mixes them, axes
    /// 4..6 as magnitudes): `max_S sum_i R[i][S] |Dq_i|` over the
    /// robot's joints (`proof.rs`), raised a little over its float value; 0 without a tool.
    pub fn tool_motion_mm(&self, delta_deg: &[f64; 6]) -> f64 {
        let Some(tool) = &self.tool else {
            return 0.0;
        };
        let dq = self.robot.urdf_joints_deg(delta_deg);
        tool.shapes
            .iter()
            .map(|s| {
                (0..6)
                    .map(|i| s.reach_mm[i] * dq[i].abs().to_radians())
                    .sum::<f64>()
            })
            .fold(0.0, f64::max)
            * (1.0 + 1e-9)
            + 1e-9
    }

    /// Node test of a whole pose: all six axes in range (the coupled axis-3 range included),
    /// every link cylinder and every tool shape MORE than the clearance from every box.
    pub fn is_free(&self, axes: &[f64; 6]) -> bool {
        self.robot.check_range6(axes).is_ok()
            && self.arm_is_free(&arm_of(axes))
            && self.tool_is_free(axes)
    }

    /// Why a pose is not free: the first range violation, else the closest offending (part,
    /// obstacle) pair; `None` when [`is_free`](Self::is_free) holds.
    pub fn why_blocked(&self, axes: &[f64; 6]) -> Option<Blocked> {
        if let Err(v) = self.robot.check_range6(axes) {
            return Some(Blocked::Range(v));
        }
        let poses = self.poses(axes);
        let mut worst: Option<(usize, usize, f64)> = None;
        for p in 0..self.part_count() {
            let solid = self.solid(p, &poses);
            for (k, b) in self.part_boxes(p) {
                if !solid_clear_of_box(&solid, b, self.clearance_mm) {
                    let d = solid.distance_aabb(b);
                    if worst.is_none_or(|(_, _, w)| d < w) {
                        worst = Some((p, k, d));
                    }
                }
            }
        }
        worst.map(|(p, k, d)| self.contact(p, k, d))
    }

    /// Smallest distance (mm) between any part (link cylinder or tool shape) and any box;
    /// `f64::INFINITY` without obstacles. Geometry only: the range is not checked.
    pub fn clearance_at(&self, axes: &[f64; 6]) -> f64 {
        let poses = self.poses(axes);
        let mut best = f64::INFINITY;
        for p in 0..self.part_count() {
            let solid = self.solid(p, &poses);
            for (_, b) in self.part_boxes(p) {
                best = best.min(solid.distance_aabb(b));
            }
        }
        best
    }

    /// Number of parts: the link cylinders, then the tool shapes.
    #[inline]
    fn part_count(&self) -> usize {
        self.cyl.len() + self.tool.as_ref().map_or(0, |t| t.shapes.len())
    }

    /// Part `p` by name.
    fn part(&self, p: usize) -> Part {
        match p.checked_sub(self.cyl.len()) {
            None => Part::Link(self.robot.cylinders[p].link.clone()),
            Some(s) => self
                .tool
                .as_ref()
                .map(|t| t.shapes[s].part.clone())
                .unwrap_or_else(|| Part::ToolShape(String::new())),
        }
    }

    /// Whether part `p` is a tool shape.
    #[inline]
    fn is_tool_part(&self, p: usize) -> bool {
        p >= self.cyl.len()
    }

    /// The boxes part `p` is checked against, with their indices: every box but those the
    /// robot stands on, for link 1 (module doc).
    fn part_boxes(&self, p: usize) -> impl Iterator<Item = (usize, &Aabb)> + '_ {
        let exempt = self.cyl.get(p).map(|c| &c.exempt);
        self.obstacles
            .iter()
            .enumerate()
            .filter(move |(k, _)| !exempt.is_some_and(|e| e[*k]))
            .map(|(k, o)| (k, &o.aabb))
    }

    /// The boxes cylinder `i` is checked against, with their indices.
    fn checked_boxes(&self, i: usize) -> impl Iterator<Item = (usize, &Aabb)> + '_ {
        self.part_boxes(i)
    }

    /// Poses of links 1..3 in the cell frame.
    fn cell_link_poses(&self, axes: &[f64; 3]) -> [Isometry3<f64>; 3] {
        self.robot
            .arm_link_poses(axes)
            .map(|p| self.cell_from_robot * p)
    }

    /// Pose of link 6 (the flange's link) in the cell frame.
    fn flange_pose(&self, axes: &[f64; 6]) -> Isometry3<f64> {
        self.cell_from_robot * self.robot.link_poses(axes)[5]
    }

    /// The poses every part needs (link 6 only with a tool).
    pub(crate) fn poses(&self, axes: &[f64; 6]) -> Poses {
        if self.tool.is_some() {
            let all = self.robot.link_poses(axes);
            Poses {
                arm: [0, 1, 2].map(|i| self.cell_from_robot * all[i]),
                flange: Some(self.cell_from_robot * all[5]),
            }
        } else {
            Poses {
                arm: self.cell_link_poses(&arm_of(axes)),
                flange: None,
            }
        }
    }

    /// Part `p` placed by `poses` (cell frame).
    #[inline]
    fn solid(&self, p: usize, poses: &Poses) -> Solid {
        match (p.checked_sub(self.cyl.len()), &self.tool, &poses.flange) {
            (None, _, _) => Solid::Cylinder(self.cylinder_in(p, &poses.arm)),
            (Some(s), Some(t), Some(f)) => t.shapes[s].local.placed(f),
            // Poses without the flange are made only for models without a tool.
            (Some(_), _, _) => unreachable!("a tool part needs the flange pose"),
        }
    }

    /// `R[i][P]` of part `p` for joints 1..6, mm.
    #[inline]
    fn part_reach(&self, p: usize) -> [f64; 6] {
        match p.checked_sub(self.cyl.len()) {
            None => {
                let r = self.cyl[p].reach_mm;
                [r[0], r[1], r[2], 0.0, 0.0, 0.0]
            }
            Some(s) => self
                .tool
                .as_ref()
                .map_or([0.0; 6], |t| t.shapes[s].reach_mm),
        }
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

    fn contact(&self, p: usize, k: usize, d: f64) -> Blocked {
        Blocked::Contact {
            part: self.part(p),
            obstacle: self.obstacles[k].name.clone(),
            distance_mm: d,
        }
    }
}

/// The boxes clipped to a cube about the base of half-size (reach + clearance +
/// [`CLIP_MARGIN_MM`]), where the reach bounds every point of every link cylinder and tool shape. Within that
/// cube nothing changes for any pose: a box point nearest to a link within the clearance (plus
/// the margin) lies inside it. Outside, a box (even one wholly outside, which becomes a flat box
/// on the cube's face) stays more than the margin away. Why: exact distances come from GJK, whose
/// rounding grows with the shapes' size (a 2 km floor overestimated a distance by 2e-5 mm, more
/// than the proofs' slack); clipping keeps every box within cell size, and keeps every number
/// finite.
fn clip_to_workspace(
    robot: &Robot,
    tool: Option<&ToolData>,
    placement: &Placement,
    obstacles: Vec<Obstacle>,
    clearance_mm: f64,
) -> Vec<Obstacle> {
    let reach: f64 = robot
        .cylinders
        .iter()
        .map(|c| parts::extent_from_base(robot, c.joint_index, &[c.a, c.b], c.radius_mm))
        .chain(tool.map(|t| t.extent_from_base(robot)))
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

/// The place stage's question: why a pose (an IK solution, or a point given as joints) cannot be
/// used from this placement: out of range, or a link or a tool shape within the clearance.
impl PoseCheck for CollisionModel {
    fn why_blocked(&self, joints_deg: &[f64; 6]) -> Option<String> {
        CollisionModel::why_blocked(self, joints_deg).map(|b| b.to_string())
    }
}
