//! The tool looks of a leg's search: whether the tool is clear at a node, with a margin that
//! answers the nodes around it, placed from sine tables and measured by balls first.
//!
//! A look places the flange by [`SinCosChain`] (the arm's sines given, the wrist's from a table
//! of the written 0.001 deg, [`MilliDegSinCos`]), measures each tool shape's ball against the
//! boxes its cube names (`near.rs`) for a margin, answers blocked from a shape's inner ball or
//! an upper bound of its distance, and leaves only the rest to the exact test of
//! [`CollisionModel::tool_is_free`]; every answer is the exact test's
//! ([`CollisionModel::tool_look`] says why).

use super::near::NearBoxes;
use super::parts::{self, ToolData};
use super::{proof, CollisionModel, Obstacle};
use crate::geometry::Point;
use crate::robot::{MilliDegSinCos, Pose, Robot, SinCosChain};
use nalgebra::Isometry3;
use std::sync::OnceLock;

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

/// What the tool looks of a leg's search use besides the shapes
/// ([`CollisionModel::tool_look_sincos`]).
#[derive(Clone, Debug)]
pub(super) struct ToolLook {
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

impl ToolLook {
    /// The look's tables for `robot` placed by `cell_from_robot` among `obstacles` (the model's
    /// boxes, clipped).
    pub(super) fn new(
        robot: &Robot,
        cell_from_robot: &Isometry3<f64>,
        obstacles: &[Obstacle],
    ) -> ToolLook {
        let wrist = &robot.controller.axes[3..6];
        let lo = wrist
            .iter()
            .map(|a| a.min_deg)
            .fold(f64::INFINITY, f64::min);
        let hi = wrist
            .iter()
            .map(|a| a.max_deg)
            .fold(f64::NEG_INFINITY, f64::max);
        ToolLook {
            chain: SinCosChain::new(robot, cell_from_robot),
            wrist: MilliDegSinCos::new(lo, hi),
            bounds: bounds_by_coordinate(obstacles),
            by_box: obstacles
                .iter()
                .map(|o| {
                    let (a, b) = (o.aabb.min, o.aabb.max);
                    [a.x, a.y, a.z, b.x, b.y, b.z]
                })
                .collect(),
            near: OnceLock::new(),
        }
    }
}

/// The boxes' bounds by coordinate (the layout of `ToolLook::bounds`).
pub(super) fn bounds_by_coordinate(obstacles: &[Obstacle]) -> [Vec<f64>; 6] {
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
/// one, and all points in one pass over the boxes (each box's bounds loaded once): both cost
/// the tool looks fewer instructions (`benches/README.md`).
#[inline]
pub(super) fn least_sq_distances<const N: usize>(
    ps: &[Point; N],
    bounds: &[Vec<f64>; 6],
) -> [f64; N] {
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
/// more boxes a ball; torch-trunk's whole runs cost about the same from 120 to 180 mm, more at
/// 80 mm (`benches/README.md`).
const LOOK_REACH_MM: f64 = 150.0;

/// How many tool shapes a look tells its exact test are far from every box
/// ([`CollisionModel::tool_look_sincos`]); the exact test looks at the boxes for any further
/// shape.
pub(super) const FAR_SHAPES: usize = 8;

/// How much a flange pose from [`SinCosChain`] may be trusted to differ from
/// [`Robot::link_poses`] at a tool ball's centre, mm: far above the rounding (about 1e-12 mm
/// at a metre, held to 1e-9 mm by the chain's tests), taken off the margin its ball test gives.
const SINCOS_POSE_SLACK_MM: f64 = 1e-6;

/// How far inside the clearance an upper bound of a tool shape's distance to a box must be for
/// the tool looks to answer blocked from it without the exact test, mm: far above the rounding
/// of the bound and of the exact test's own (about 1e-12 mm at cell sizes) and of the flange
/// pose from [`SinCosChain`] ([`SINCOS_POSE_SLACK_MM`]), so the answer is the exact test's.
pub(super) const UPPER_BOUND_SLACK_MM: f64 = 1e-4;

impl CollisionModel {
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
}
