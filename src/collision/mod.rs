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
//! Every query takes all six axes, except the grid's node test of the arm. Tests in `tests.rs`
//! (links, against parry3d and dense sampling) and `tool_tests.rs` (the tool, the grid codes).
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

mod block;
#[cfg(test)]
mod block_tests;
mod column;
mod corner;
mod grid;
mod near;
mod parts;
mod proof;
#[cfg(test)]
mod tests;
#[cfg(test)]
pub(crate) mod tool_tests;

pub use grid::{Ends, GridCheck, CODE_FREE};
pub use proof::{Clearance, DISTANCE_SLACK_REL, MOVE_FLOOR_MM};

pub use crate::cell::Obstacle;
use crate::cell::{Cell, Tool};
use crate::geometry::{
    clamp_to_box, closest_param_segment_aabb, distance_cylinder_aabb_exact, distance_point_aabb,
    distance_segment_aabb, distance_sq_point_aabb, gap_sq_aabb_aabb, obb_clear_of_aabb, Aabb,
    Cylinder, Point, Solid,
};
use crate::place::{Placement, PoseCheck};
use crate::robot::{MilliDegSinCos, Pose, RangeViolation, Robot, SinCosChain};
use nalgebra::{Isometry3, Vector3};
use near::NearBoxes;
use parts::ToolData;
use std::sync::OnceLock;

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
            // read as the issue gives them ("tool shape 'neck' comes within 4.2 mm of ...").
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

/// The wrist's angles of a tool look, deg.
#[derive(Clone, Copy, Debug)]
enum WristAngles<'a> {
    /// Controller axes 4..6 of the six axes, on the written 0.001 deg.
    Lattice(&'a [f64; 6]),
    /// Controller axes 4..6 before their rounding to the written 0.001 deg.
    Unrounded(&'a [f64; 3]),
}

impl WristAngles<'_> {
    /// The angles' sines and cosines from the table (the unrounded ones rounded first:
    /// `MilliDegSinCos::get_rounded`).
    #[inline(always)]
    fn sincos(self, t: &MilliDegSinCos) -> [(f64, f64); 3] {
        match self {
            WristAngles::Lattice(a) => [t.get(a[3]), t.get(a[4]), t.get(a[5])],
            WristAngles::Unrounded(w) => [
                t.get_rounded(w[0]),
                t.get_rounded(w[1]),
                t.get_rounded(w[2]),
            ],
        }
    }
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
}

/// What the tool looks of a leg's search use besides the shapes
/// ([`CollisionModel::tool_look_sincos`]).
#[derive(Clone, Debug)]
struct ToolLook {
    /// The chain that places the flange, in the cell frame.
    chain: SinCosChain,
    /// The wrist angles' sines and cosines on the 0.001 deg lattice.
    wrist: MilliDegSinCos,
    /// The boxes' bounds by coordinate, `[min x, min y, min z, max x, max y, max z]` per box
    /// index, for the balls' distances in one pass ([`least_sq_distances`]).
    bounds: [Vec<f64>; 6],
    /// The same bounds by box, for the passes over the boxes a ball's cube names
    /// ([`least_sq_masked`]).
    by_box: Vec<[f64; 6]>,
    /// Which boxes a ball can come near, by cube (`near.rs`), made on the first look; `None`
    /// for a model with too many boxes, or whose boxes' region would take too many cubes.
    near: OnceLock<Option<NearBoxes>>,
}

/// The boxes' bounds by coordinate (the layout of `ToolLook::bounds`).
fn bounds_by_coordinate(obstacles: &[Obstacle]) -> [Vec<f64>; 6] {
    std::array::from_fn(|k| {
        obstacles
            .iter()
            .map(|o| {
                if k < 3 {
                    o.aabb.min[k]
                } else {
                    o.aabb.max[k - 3]
                }
            })
            .collect()
    })
}

/// The least squared distance from each point of `ps` to the boxes of `bounds`
/// ([`bounds_by_coordinate`]): per box the same number as `geometry::distance_sq_point_aabb`
/// (each axis's excess is the same up to its sign, which the square drops), laid out so the
/// loop runs without branches.
///
/// Its own excess (the larger of the two gaps, clamped at 0) rather than `geometry`'s signed
/// one: about 5 % fewer instructions in the tool looks on torch-trunk. All points in one pass
/// over the boxes (each box's bounds loaded once): about 4 % fewer than one pass per point.
#[inline]
fn least_sq_distances<const N: usize>(ps: &[Point; N], bounds: &[Vec<f64>; 6]) -> [f64; N] {
    let [x0, y0, z0, x1, y1, z1] = bounds;
    let n = x0.len();
    let (x0, y0, z0, x1, y1, z1) = (&x0[..n], &y0[..n], &z0[..n], &x1[..n], &y1[..n], &z1[..n]);
    let mut least = [f64::INFINITY; N];
    for k in 0..n {
        for (l, p) in least.iter_mut().zip(ps) {
            let ex = excess(p.x, x0[k], x1[k]);
            let ey = excess(p.y, y0[k], y1[k]);
            let ez = excess(p.z, z0[k], z1[k]);
            let d = ex * ex + ey * ey + ez * ez;
            *l = if d < *l { d } else { *l };
        }
    }
    least
}

/// How far `x` lies outside `lo..hi` (0 inside), written with selects, not branches, for the
/// balls' passes ([`least_sq_distances`], [`least_sq_masked`]: the same number in both).
#[inline]
fn excess(x: f64, lo: f64, hi: f64) -> f64 {
    let (a, b) = (lo - x, x - hi);
    let e = if a > b { a } else { b };
    if e > 0.0 {
        e
    } else {
        0.0
    }
}

/// The least squared distance from `p` to the boxes of `by_box` whose bits `mask` sets (bit `b`
/// for box `b`), each the same number as [`least_sq_distances`]'s (the same sums in the same
/// order); `INFINITY` for an empty mask.
#[inline]
fn least_sq_masked(p: &Point, mut mask: u16, by_box: &[[f64; 6]]) -> f64 {
    let mut least = f64::INFINITY;
    while mask != 0 {
        let k = mask.trailing_zeros() as usize;
        mask &= mask - 1;
        let Some(&[x0, y0, z0, x1, y1, z1]) = by_box.get(k) else {
            continue;
        };
        let ex = excess(p.x, x0, x1);
        let ey = excess(p.y, y0, y1);
        let ez = excess(p.z, z0, z1);
        let d = ex * ex + ey * ey + ez * ez;
        least = if d < least { d } else { least };
    }
    least
}

/// What a balls' pass gathers ([`CollisionModel::ball_pass`]): the least ball distance less its
/// radius, whether an inner ball comes within the clearance less [`UPPER_BOUND_SLACK_MM`], and
/// per shape (the first [`FAR_SHAPES`]) whether its ball is farther than the clearance plus
/// [`SINCOS_POSE_SLACK_MM`].
struct Balls {
    nearest: f64,
    within: bool,
    far: [bool; FAR_SHAPES],
}

impl Balls {
    fn new() -> Balls {
        Balls {
            nearest: f64::INFINITY,
            within: false,
            far: [false; FAR_SHAPES],
        }
    }

    /// Shape `i` (`s`) whose ball's centre lies `d` from the nearest box, at clearance `c`.
    #[inline]
    fn add(&mut self, i: usize, s: &parts::ShapeData, d: f64, c: f64) {
        let radius = s.ball.1;
        self.nearest = self.nearest.min(d - radius);
        // The inner ball's point nearest to the box is a point of the shape.
        self.within |= d - s.inner_mm <= c - UPPER_BOUND_SLACK_MM;
        if let Some(f) = self.far.get_mut(i) {
            *f = d > radius + c + SINCOS_POSE_SLACK_MM;
        }
    }
}

/// How far beyond its radius and the clearance a tool ball measures the boxes in a look, mm: a
/// box farther is left out of its balls' pass (`near.rs`), and the look's margin is at most
/// about this. A larger margin would spread a look only over the farthest of a leg's 124
/// offsets (at 1 deg on torch-trunk, up to about 240 mm of motion), and a larger reach keeps
/// more boxes a ball: whole runs of torch-trunk at 1 deg took 4123 / 4073 / 4073 / 4080 M
/// instructions at 80 / 120 / 150 / 180 mm (30 mm cubes).
const LOOK_REACH_MM: f64 = 150.0;

/// How many tool shapes a look tells its exact test are far from every box
/// ([`CollisionModel::tool_look_sincos`]); the exact test looks at the boxes for any further
/// shape.
const FAR_SHAPES: usize = 8;

/// How much a flange pose from [`SinCosChain`] may be trusted to differ from
/// [`Robot::link_poses`] at a tool ball's centre, mm: far above the rounding (about 1e-12 mm
/// at a metre, held to 1e-9 mm by the chain's tests), taken off the margin its ball test gives.
const SINCOS_POSE_SLACK_MM: f64 = 1e-6;

/// How far inside the clearance an upper bound of a tool shape's distance to a box must be for
/// the tool looks to answer blocked from it without the exact test, mm: far above the rounding
/// of the bound and of the exact test's own (about 1e-12 mm at cell sizes) and of the flange
/// pose from [`SinCosChain`] ([`SINCOS_POSE_SLACK_MM`]), so the answer is the exact test's.
const UPPER_BOUND_SLACK_MM: f64 = 1e-4;

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
        let look = tool.as_ref().map(|_| {
            let wrist = &robot.controller.axes[3..6];
            let lo = wrist
                .iter()
                .map(|a| a.min_deg)
                .fold(f64::INFINITY, f64::min);
            let hi = wrist
                .iter()
                .map(|a| a.max_deg)
                .fold(f64::NEG_INFINITY, f64::max);
            Box::new(ToolLook {
                chain: SinCosChain::new(robot, &cell_from_robot),
                wrist: MilliDegSinCos::new(lo, hi),
                bounds: bounds_by_coordinate(&obstacles),
                by_box: obstacles
                    .iter()
                    .map(|o| {
                        let (a, b) = (o.aabb.min, o.aabb.max);
                        [a.x, a.y, a.z, b.x, b.y, b.z]
                    })
                    .collect(),
                near: OnceLock::new(),
            })
        });
        CollisionModel {
            robot: robot.clone(),
            placement,
            cell_from_robot,
            obstacles,
            clearance_mm: clearance_mm.max(0.0),
            cyl,
            tool,
            look,
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

    /// The tool at `axes` for a leg's search: whether it is clear ([`tool_is_free`]'s answer,
    /// on the flange placed from sines and cosines, within about 1e-7 mm of `link_poses`'; every
    /// move is proven again on `link_poses`) and a margin, mm: how much more than the clearance
    /// every tool shape keeps from every box at least, from each shape's ball (`parts.rs`, one
    /// point placed per shape), after the slack of `proof.rs`; 0 where the balls do not show
    /// the tool clear (`INFINITY` without a tool or boxes), capped at about [`LOOK_REACH_MM`]
    /// where the balls are measured by the cubes of `near.rs`. Where the margin is not positive,
    /// a shape whose inner ball (`parts.rs`: about the ball's centre, inside the shape) comes
    /// within the clearance less [`UPPER_BOUND_SLACK_MM`] of a box answers blocked; else the
    /// exact test runs, each shape near a box first measured by an upper bound
    /// (`Solid::upper_distance_aabb`). Both answer as the exact test: what they find within
    /// the clearance, every bound of the exact test finds within it too (the exact cylinder
    /// distance never exceeds the inner capsule's). With
    /// [`tool_motion_mm`](Self::tool_motion_mm), a margin `m`
    /// proves the tool clear at every pose a straight move of motion below `m` away
    /// (`plan::leg` spreads a leg's answers so).
    ///
    /// [`tool_is_free`]: Self::tool_is_free
    pub fn tool_look(&self, axes: &[f64; 6]) -> (bool, f64) {
        let arm = [0, 1, 2].map(|k| axes[k].to_radians().sin_cos());
        self.tool_look_sincos(axes, &arm)
    }

    /// [`tool_look`](Self::tool_look) with the sines and cosines of controller axes 1..3 given
    /// (`arm_sincos`, from a table of the grid's values; they must be those of `axes`): the
    /// flange is placed by [`SinCosChain`] (the wrist's sines and cosines from a table of the
    /// written 0.001 deg), which agrees with [`Robot::link_poses`] to rounding; the balls'
    /// margin is lowered by [`SINCOS_POSE_SLACK_MM`] for it. Where the balls do not show the
    /// tool clear, the upper bounds of [`tool_look`](Self::tool_look) may answer blocked, and
    /// only what they leave goes to the exact test of [`tool_is_free`](Self::tool_is_free) on
    /// that flange, which passes the shapes the balls' pass found far from every box without
    /// looking at their boxes ([`ball_pass`](Self::ball_pass)).
    pub fn tool_look_sincos(&self, axes: &[f64; 6], arm_sincos: &[(f64, f64); 3]) -> (bool, f64) {
        self.tool_look_from(WristAngles::Lattice(axes), arm_sincos, None)
    }

    /// [`tool_look_sincos`](Self::tool_look_sincos) with link 1's pose given (`link1`, from
    /// [`tool_link1`](Self::tool_link1) of the same axis 1: `plan::leg` keeps one per grid value
    /// of axis 1): the same steps after it, so the same answer and margin to the bit.
    pub fn tool_look_link1(
        &self,
        axes: &[f64; 6],
        arm_sincos: &[(f64, f64); 3],
        link1: &Pose,
    ) -> (bool, f64) {
        self.tool_look_from(WristAngles::Lattice(axes), arm_sincos, Some(link1))
    }

    /// [`tool_look_link1`](Self::tool_look_link1) of the wrist `wrist_deg` (controller axes
    /// 4..6) before its rounding to the written 0.001 deg: the answer and margin of
    /// `tool_look_link1` at the rounded wrist, to the bit (the wrist's sines and cosines by
    /// `MilliDegSinCos::get_rounded`, the same table entries); axes 1..3 are given by their
    /// sines and cosines alone. `plan::leg`'s looks, which need the rounded wrist only there.
    pub fn tool_look_link1_rounding(
        &self,
        wrist_deg: &[f64; 3],
        arm_sincos: &[(f64, f64); 3],
        link1: &Pose,
    ) -> (bool, f64) {
        self.tool_look_from(WristAngles::Unrounded(wrist_deg), arm_sincos, Some(link1))
    }

    /// [`tool_look_sincos`](Self::tool_look_sincos) with the wrist's angles as `wrist` gives
    /// them, link 1 placed unless given.
    #[inline]
    fn tool_look_from(
        &self,
        wrist: WristAngles<'_>,
        arm_sincos: &[(f64, f64); 3],
        link1: Option<&Pose>,
    ) -> (bool, f64) {
        let Some((tool, look, flange)) = self.look_parts(wrist, arm_sincos, link1) else {
            return (true, f64::INFINITY);
        };
        let c = self.clearance_mm;
        let (nearest, within, far) = self.ball_pass(tool, look, &flange);
        let margin = proof::lowered(nearest) - c - SINCOS_POSE_SLACK_MM;
        if margin > 0.0 {
            (true, margin)
        } else if within {
            (false, 0.0)
        } else {
            (self.tool_is_free_at::<true>(&flange.isometry(), &far), 0.0)
        }
    }

    /// The balls' pass of a look ([`tool_look_sincos`](Self::tool_look_sincos)) with the
    /// flange at `flange`: the least over the shapes of the ball's distance to a box less its
    /// radius; whether a shape's inner ball comes within the clearance less
    /// [`UPPER_BOUND_SLACK_MM`] of a box; and per shape (the first [`FAR_SHAPES`]) whether its
    /// ball is farther than the clearance plus [`SINCOS_POSE_SLACK_MM`] (which covers the
    /// rounding between `flange` and its isometry) from every box, so that the exact test need
    /// not look at the boxes for it (its own ball test would pass every one).
    ///
    /// Each ball is measured against the boxes its cube names (`near.rs`): a box left out is
    /// farther from the ball's centre than the masks' reach `L`, which is above the ball's
    /// radius plus the clearance and [`LOOK_REACH_MM`] (for a model with a margin sharing its
    /// parent's masks, at least plus the clearance and 1 mm), so it is far for the shape and its
    /// inner ball is not within the clearance of it, and it keeps more than `L - r_max` from
    /// the ball (`r_max` the largest ball radius): the least is capped there, the rest is the
    /// pass over every box to the bit ([`ball_pass_all`](Self::ball_pass_all); the tests hold
    /// them to that).
    #[inline]
    fn ball_pass(
        &self,
        tool: &ToolData,
        look: &ToolLook,
        flange: &Pose,
    ) -> (f64, bool, [bool; FAR_SHAPES]) {
        let c = self.clearance_mm;
        let near = look
            .near
            .get_or_init(|| {
                let r_max = tool.shapes.iter().map(|s| s.ball.1).fold(0.0, f64::max);
                NearBoxes::new(&self.obstacles, r_max, r_max + c + LOOK_REACH_MM)
            })
            .as_ref()
            // Made for this clearance (a model with a margin shares its parent's masks).
            .filter(|n| n.reach_mm >= n.ball_mm + c + 1.0);
        if let Some(near) = near {
            let mut balls = Balls::new();
            for (i, s) in tool.shapes.iter().enumerate() {
                let centre = flange.point(&s.ball.0);
                let d = least_sq_masked(&centre, near.mask(&centre), &look.by_box).sqrt();
                balls.add(i, s, d, c);
            }
            // A box a ball's cube leaves out is farther than the reach from it (`near.rs`).
            return (
                balls.nearest.min(near.reach_mm - near.ball_mm),
                balls.within,
                balls.far,
            );
        }
        self.ball_pass_all(tool, look, flange)
    }

    /// [`ball_pass`](Self::ball_pass) against every box (a model without masks: more boxes
    /// than a mask names, or a region of too many cubes; or one whose clearance grew so far
    /// after the masks were made, by `with_margin`, that their reach no longer covers the
    /// balls' radius and the clearance plus 1 mm).
    #[inline]
    fn ball_pass_all(
        &self,
        tool: &ToolData,
        look: &ToolLook,
        flange: &Pose,
    ) -> (f64, bool, [bool; FAR_SHAPES]) {
        let c = self.clearance_mm;
        let mut balls = Balls::new();
        for (i, three) in tool.shapes.chunks(3).enumerate() {
            let centre = |k: usize| flange.point(&three[k.min(three.len() - 1)].ball.0);
            let sq = least_sq_distances(&[centre(0), centre(1), centre(2)], &look.bounds);
            for (t, (s, sq)) in three.iter().zip(sq).enumerate() {
                balls.add(3 * i + t, s, sq.sqrt(), c);
            }
        }
        (balls.nearest, balls.within, balls.far)
    }

    /// The shapes the balls' pass at `axes` calls far ([`ball_pass`](Self::ball_pass)), the
    /// flange placed as [`tool_look_sincos`](Self::tool_look_sincos) places it (for tests).
    #[cfg(test)]
    pub(crate) fn far_shapes_for_test(
        &self,
        axes: &[f64; 6],
        arm_sincos: &[(f64, f64); 3],
    ) -> [bool; FAR_SHAPES] {
        match self.look_parts(WristAngles::Lattice(axes), arm_sincos, None) {
            Some((tool, look, flange)) => self.ball_pass(tool, look, &flange).2,
            None => [false; FAR_SHAPES],
        }
    }

    /// The balls' pass at `axes` by the cubes' masks and over every box
    /// ([`ball_pass`](Self::ball_pass), [`ball_pass_all`](Self::ball_pass_all)), and the cap
    /// of the masked pass's least (for tests; `None` without a tool or masks).
    #[cfg(test)]
    #[allow(clippy::type_complexity)]
    pub(crate) fn ball_passes_for_test(
        &self,
        axes: &[f64; 6],
        arm_sincos: &[(f64, f64); 3],
    ) -> Option<(
        (f64, bool, [bool; FAR_SHAPES]),
        (f64, bool, [bool; FAR_SHAPES]),
        f64,
    )> {
        let (tool, look, flange) = self.look_parts(WristAngles::Lattice(axes), arm_sincos, None)?;
        let masked = self.ball_pass(tool, look, &flange);
        let near = look.near.get()?.as_ref()?;
        Some((
            masked,
            self.ball_pass_all(tool, look, &flange),
            near.reach_mm - near.ball_mm,
        ))
    }

    /// What a look works with: the tool, its look tables and the flange placed from sines and
    /// cosines ([`flange_sincos`](Self::flange_sincos)); `None` without a tool.
    #[inline]
    fn look_parts(
        &self,
        wrist: WristAngles<'_>,
        arm_sincos: &[(f64, f64); 3],
        link1: Option<&Pose>,
    ) -> Option<(&ToolData, &ToolLook, Pose)> {
        Some((
            self.tool.as_ref()?,
            self.look.as_ref()?,
            self.flange_sincos(wrist, arm_sincos, link1)?,
        ))
    }

    /// The flange's pose (link 6, cell frame) from the chain of sines and cosines, the arm's
    /// given, the wrist's from the table as `wrist` gives it (`None` without a tool).
    #[inline]
    fn flange_sincos(
        &self,
        wrist: WristAngles<'_>,
        arm_sincos: &[(f64, f64); 3],
        link1: Option<&Pose>,
    ) -> Option<Pose> {
        let look = self.look.as_ref()?;
        let wrist = wrist.sincos(&look.wrist);
        let arm = self.robot.urdf_arm_sincos(arm_sincos);
        let p1 = match link1 {
            Some(p1) => *p1,
            None => look.chain.pose1(arm[0]),
        };
        Some(look.chain.pose6_from1(&p1, &[arm[1], arm[2]], &wrist))
    }

    /// Link 1's pose (cell frame) from the sine and cosine of controller axis 1, for
    /// [`tool_look_link1`](Self::tool_look_link1) (`None` without a tool). Axis 1 goes through
    /// the controller's coupling as the looks' axes do (`Robot::urdf_arm_sincos`; it couples
    /// axis 3 only, so this is axis 1's own sine and cosine, but the rule lives in one place).
    pub fn tool_link1(&self, axis1_sincos: (f64, f64)) -> Option<Pose> {
        let look = self.look.as_ref()?;
        let [urdf1, _, _] = self
            .robot
            .urdf_arm_sincos(&[axis1_sincos, (0.0, 1.0), (0.0, 1.0)]);
        Some(look.chain.pose1(urdf1))
    }

    /// [`flange_sincos`](Self::flange_sincos) as an isometry (for tests).
    #[cfg(test)]
    pub(crate) fn flange_sincos_for_test(
        &self,
        axes: &[f64; 6],
        arm_sincos: &[(f64, f64); 3],
        link1: Option<&Pose>,
    ) -> Option<Isometry3<f64>> {
        self.flange_sincos(WristAngles::Lattice(axes), arm_sincos, link1)
            .map(|p| p.isometry())
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

/// The node test used everywhere in this module: `true` when the cylinder keeps MORE than
/// `clearance` from the box. Cheap bounds first, from the axis point nearest the box (the
/// capsule's lower bound; that point and the point of its disc nearest the box lie in the
/// cylinder: upper bounds), then the cap centres and their rim points nearest the box (upper
/// bounds), a capsule about a shortened axis that still holds the rims (a lower bound), the
/// alternating projections of `geometry::certify` (a certified separating plane or point pair:
/// nearly every case), two more shortened capsules, and then parry's GJK. All are valid
/// bounds, so the answer is the exact test's whatever their order. On the trunk's 1 deg grid build the cheap bounds
/// decide about seven in ten of the calls the projections used to take (81 k of 283 k left).
#[inline]
fn link_clear_of_box(c: &Cylinder, b: &Aabb, clearance: f64) -> bool {
    let (near, axis) = axis_nearest(c, b);
    link_clear_near(c, b, clearance, &near, axis)
}

/// The point of the cylinder's axis nearest the box and its distance from the box: less the
/// radius (at least 0), the capsule distance of `distance_capsule_aabb` (the same numbers).
#[inline]
pub(super) fn axis_nearest(c: &Cylinder, b: &Aabb) -> (Point, f64) {
    let d = c.b - c.a;
    let near = c.a + d * closest_param_segment_aabb(&c.a, &d, b);
    (near, distance_point_aabb(&near, b))
}

/// [`link_clear_of_box`] with [`axis_nearest`]'s answer given (a caller that measured the
/// capsule distance already need not find the nearest axis point again).
#[inline]
pub(super) fn link_clear_near(
    c: &Cylinder,
    b: &Aabb,
    clearance: f64,
    near: &Point,
    axis: f64,
) -> bool {
    let near = *near;
    let d = c.b - c.a;
    let r = c.radius.max(0.0);
    // The capsule's distance (`distance_capsule_aabb`).
    if (axis - r).max(0.0) > clearance {
        return true;
    }
    if axis <= clearance {
        return false;
    }
    let len = d.norm();
    if len > 0.0 && r > 0.0 {
        let u = d / len;
        // Upper bounds: on the disc about the axis point nearest the box and on both caps, the
        // point nearest the box point nearest the disc's centre.
        for p in [near, c.a, c.b] {
            let w = clamp_to_box(&p, b) - p;
            let perp = w - u * u.dot(&w);
            let n = perp.norm();
            let rim = if n > 0.0 {
                p + perp * (r.min(n) / n)
            } else {
                p
            };
            if distance_point_aabb(&rim, b) <= clearance {
                return false;
            }
        }
        // Segment shortened by s at both ends, radius sqrt(r^2 + s^2): contains the cylinder.
        // The first shortening settles most clear cylinders; where it does not, the
        // projections come before the two longer ones: in the grid build they settle nearly
        // all of what is left (most of it within the clearance, which no lower bound can show)
        // for less than the two segment queries.
        if shortened_clear(c, b, clearance, &u, len, r, 1.0) {
            return true;
        }
        if let Some(clear) = crate::geometry::clear_by_projection(c, b, clearance) {
            return clear;
        }
        if shortened_clear(c, b, clearance, &u, len, r, 2.5)
            || shortened_clear(c, b, clearance, &u, len, r, 6.0)
        {
            return true;
        }
    }
    // What the projections left open (a distance within their slack of the clearance, or no
    // radius or length to project onto): GJK.
    distance_cylinder_aabb_exact(c, b) > clearance
}

/// Whether the capsule about `c`'s axis shortened by `s = min(k r, len / 2)` at both ends, of
/// radius `sqrt(r^2 + s^2)` (it contains the cylinder), keeps more than `clearance` from the
/// box (`u` the unit axis, `len` its length, `r > 0` the radius).
#[inline]
fn shortened_clear(
    c: &Cylinder,
    b: &Aabb,
    clearance: f64,
    u: &Vector3<f64>,
    len: f64,
    r: f64,
    k: f64,
) -> bool {
    let s = (k * r).min(0.5 * len);
    // sqrt(r^2 + s^2) raised over its rounding (`hypot` costs about ten times more).
    let radius = (r * r + s * s).sqrt() * (1.0 + 1e-15);
    distance_segment_aabb(&(c.a + u * s), &(c.b - u * s), b) - radius > clearance
}

/// The place stage's question: why a pose (an IK solution, or a point given as joints) cannot be
/// used from this placement: out of range, or a link or a tool shape within the clearance.
impl PoseCheck for CollisionModel {
    fn why_blocked(&self, joints_deg: &[f64; 6]) -> Option<String> {
        CollisionModel::why_blocked(self, joints_deg).map(|b| b.to_string())
    }
}

/// The node test for any solid: `true` when it keeps MORE than `clearance` from the box. First
/// the distance of the solid's enclosing box (a few comparisons; most boxes are far from most
/// parts); then link cylinders go through [`link_clear_of_box`] (fast bounds before parry's
/// GJK), oriented boxes through `geometry::obb_clear_of_aabb` (separating axes before the exact
/// distance, the exact distance's answer), balls are measured exactly.
#[inline]
fn solid_clear_of_box(s: &Solid, b: &Aabb, clearance: f64) -> bool {
    if s.coarse_lower_bound_aabb(b) > clearance {
        return true;
    }
    match s {
        Solid::Cylinder(c) => link_clear_of_box(c, b, clearance),
        Solid::Box(o) => obb_clear_of_aabb(o, b, clearance),
        Solid::Sphere(_) => s.distance_aabb(b) > clearance,
    }
}
