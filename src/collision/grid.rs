//! The collision model on a grid of axes 1..3: per node one byte that says whether the arm is
//! free there and how deep in free space it lies, per column a few bytes for the links axis 3
//! does not move, and the step check between neighbouring nodes that reads those bytes before
//! it proves anything (beyond the paper: its grid has 0/-1 nodes and no steps). The planner asks
//! the step check wherever it needs to know whether a grid step exists (`plan::leg`).
//!
//! # What the grid keeps
//!
//! [`GridCheck::inspect_column`] (`column.rs`) writes, per node, a code: bit 7 ([`CODE_FREE`])
//! the paper's node test of the arm; bit 6 whether the tool could come within the clearance of a
//! box there (then a leg must look at its tool with its own wrist, [`GridCheck::tool_near`]);
//! bits 0..2 the depth `q_3` of the cylinders axis 3 moves and bits 3..5 the tool's depth `q_T`,
//! each `0 ..= K` with `K` = [`DEPTH_LEVELS`]. Per column (fixed axes 1 and 2) it writes one
//! byte per cylinder axis 3 does not move (links 1 and 2): its depth on `K_c` =
//! [`COLUMN_LEVELS`] levels.
//!
//! *Depth.* For a part `P` and a neighbour offset `o` let `M_P(o)` be the most any point of `P`
//! moves over that grid step (`sum_i R[i][P] |Dq_i|` of `proof.rs`). A depth `q` on `K` levels
//! with scale `S` says `d - c >= q S / K`, `d` a lower bound of the part's distance to the
//! nearest box and `c` the clearance. The cylinders axis 3 moves share one code and one scale,
//! `S_3 = max_o max_L M_L(o)`; each fixed cylinder has its own byte and scale `S_L = max_o
//! M_L(o)` (a link that barely moves, like the base, would otherwise hold every step to its
//! own small scale). For the tool, `C` is the wrist centre of `parts.rs` (fixed in link 3, so
//! moved by axes 1..3 only) and `R_T` the radius about it that holds every tool shape for any
//! wrist angles: `f = d(C, boxes) - R_T` is a lower bound of every tool shape's distance whatever
//! axes 4..6 do, and `q_T` quantises `f` with `S_C = max_o M_C(o)`. The depths are computed from
//! the cheap lower bounds the node test has at hand (`column.rs`), so they are conservative;
//! where a run of a column is proven at once (`block.rs`), a part whose bound over the whole run
//! (its lower bound at the run's middle less its motion across the run) is above the clearance
//! gets that bound's depth (`K` from `deep_mm` on) at every node of the run without being
//! measured there.
//!
//! *Steps proven by the codes.* A step between neighbours `n`, `m` with offset `o` is safe for a
//! set of parts sharing a scale `S` when `q(n) + q(m) >= need(o) = ceil(K max_P M_P(o) / S)`:
//! for every such part and box, `(d(n) - c) + (d(m) - c) >= M_P(o)`, and the interval bound of
//! `proof.rs` gives `d(t) >= (d(n) + d(m) - M_P(o)) / 2 >= c` all along. The same holds for the
//! tool with `q_T` and `f`, which is `M_C(o)`-Lipschitz along the step whatever the wrist does
//! on it, at nodes without bit 6 (there `f > c`; a node with bit 6 has no depth to give, its `f`
//! may be below the clearance). Otherwise the part is proven along the six-axis step with the
//! whole-move proof, so a step the codes accept is one the proof accepts too (the codes use the
//! proof's `M` and lower bounds of its distances): the planner's graph is the proof's. Every
//! `M(o)` is raised by 1e-9 relative (and 1e-9 mm) over its float value, which covers the
//! rounding of the quotients.
//!
//! *Tool near.* Where `f > c` at a node, no tool shape comes within the clearance there for any
//! wrist: bit 6 is clear and the tool needs no look at that node. Where bit 6 is set, the leg's
//! wrist at the node decides ([`CollisionModel::tool_is_free`]).

use super::angles::Angles;
use super::proof::lowered;
use super::CollisionModel;
use crate::robot::{Pose, SinCosChain};
use nalgebra::{Point3, Vector3};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// The node-code bit of a free node (the paper's node test of the arm); the grid
/// (`plan::cspace`) reads only this bit.
pub const CODE_FREE: u8 = 0x80;

/// The node-code bit of a node where the tool might come within the clearance of a box.
const CODE_TOOL_NEAR: u8 = 0x40;

/// `K` of the node codes: depth is quantised to `0 ..= K` steps of `S / K`.
pub const DEPTH_LEVELS: u8 = 7;

/// The arm-depth bits of a code (bits 0..2).
pub(super) const ARM_BITS: u8 = 7;

/// `K` of the column bytes (one byte per link not moved by axis 3).
pub const COLUMN_LEVELS: u8 = 100;

/// Index of a neighbour offset in `{-1, 0, 1}^3`.
#[inline]
fn offset_index(o: [i32; 3]) -> usize {
    ((o[0] + 1) * 9 + (o[1] + 1) * 3 + (o[2] + 1)) as usize
}

/// The collision model on a grid of spacing `step_deg`: writes node codes and checks steps. It
/// shares the model (an `Arc`), so a grid inspected as its waves ask (`plan::cspace`) can keep
/// its check beside the model it checks.
#[derive(Clone, Debug)]
pub struct GridCheck {
    pub(super) model: Arc<CollisionModel>,
    /// The link cylinders axis 3 does not move (joint 1 or 2), in order: one column byte each.
    pub(super) fixed: Vec<usize>,
    /// Their `S_L`, mm.
    pub(super) fixed_span: Vec<f64>,
    /// `S_3`: the most any point of a cylinder moved by axis 3 moves over one step, mm.
    pub(super) arm_span: f64,
    /// `S_C` of the wrist centre (0 without a tool), mm.
    pub(super) centre_span: f64,
    /// `need_L(o)` of the fixed cylinders, `need_3(o)`, `need_T(o)`, by offset index.
    need_fixed: Vec<[u8; 27]>,
    need_arm: [u8; 27],
    need_tool: [u8; 27],
    /// Links 1 and 2 placed from sines and cosines, cell frame (the columns' frames of joint 3,
    /// `column.rs`).
    pub(super) chain: SinCosChain,
    /// Joint 3's origin and unit axis in link 2's frame, and per cylinder moved by axis 3 (by
    /// index into `model.cyl`) its ends' split (`CylData::split`) in link 2's frame (the
    /// parallel part as a point of link 2, the two others as its vectors) and its shift: the
    /// most any of its points moves per radian of axis 2 with axes 1 and 3 fixed, mm.
    pub(super) joint3: (Point3<f64>, Vector3<f64>),
    pub(super) split3: Vec<(usize, EndsSplit, f64)>,
    /// With a tool: its wrist centre `C` (`parts.rs`, a point of link 3) split about joint 3's
    /// axis in link 2's frame as `split3`'s ends are, and how far `C` can lie from joint 3's
    /// origin (the parallel part's length plus the turning part's), mm.
    pub(super) centre3: Option<[Vector3<f64>; 3]>,
    pub(super) centre_sweep: f64,
    /// The first slice's axis-3 angles, for every slice with the same values (the grid's).
    pub(super) angles: OnceLock<Angles>,
    /// Link 1's answers and pose per value of axis 1 (`column.rs`, [`SliceMemo`]).
    pub(super) slices: SliceMemo,
}

/// Most fixed cylinders (links 1 and 2) whose slice answers are kept (link 1's beyond them are
/// placed and checked per column, on link 1's pose of the slice; `column.rs`).
pub const MAX_FIXED: usize = 8;

/// Per fixed cylinder, the slice's answer for link 1 (`GridCheck::slice_bytes`, `column.rs`).
pub type SliceBytes = [Option<Option<u8>>; MAX_FIXED];

/// What link 1 gives every column of a slice of axis 1 (`column.rs`: its column bytes or
/// blocked, and its pose), per value of axis 1 (its bits), made by the first block of the
/// slice that is inspected and read by the others: the grid inspects a slice a block at a
/// time. A clone starts empty (what it holds is the model's alone, made again when asked).
#[derive(Debug, Default)]
pub(super) struct SliceMemo(Mutex<HashMap<u64, (SliceBytes, Pose)>>);

impl Clone for SliceMemo {
    fn clone(&self) -> SliceMemo {
        SliceMemo::default()
    }
}

impl SliceMemo {
    /// The answers for `a1_deg`, made by `make` when no thread has made them yet (two threads
    /// asking at once may both make them: the same values).
    pub(super) fn get(
        &self,
        a1_deg: f64,
        make: impl FnOnce() -> (SliceBytes, Pose),
    ) -> (SliceBytes, Pose) {
        let key = a1_deg.to_bits();
        let lock = || self.0.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(&known) = lock().get(&key) {
            return known;
        }
        let made = make();
        lock().insert(key, made);
        made
    }
}

impl CollisionModel {
    /// The model on a grid of spacing `step_deg` (deg): node codes and the step check, on a copy
    /// of the model ([`GridCheck::new`] shares one).
    pub fn grid_check(&self, step_deg: f64) -> GridCheck {
        GridCheck::new(Arc::new(self.clone()), step_deg)
    }
}

/// A cylinder's two ends split about joint 3's axis (`CylData::split`): per end the parallel
/// part and the two turning vectors.
pub(super) type EndsSplit = [[Vector3<f64>; 3]; 2];

/// The most any point of cylinder `i` (moved by axis 3) moves per radian of axis 2 with axes 1
/// and 3 fixed, mm. URDF joint 2 moves with axis 2 and joint 3 by `dq3 / da2` (-1 under a
/// parallelogram coupling, else 0): in general `R[1] + R[2] |dq3 / da2|` (`proof.rs`). Where
/// the coupling takes joint 3 back by joint 2's angle about the same axis (joint 3's origin
/// not rotated, both axes the same vector), link 3 keeps its orientation and only joint 3's
/// origin moves, on a circle about joint 2's axis: the shift is that circle's radius.
fn shift3(model: &CollisionModel, i: usize) -> f64 {
    let robot = &model.robot;
    let urdf = |a2: f64| robot.urdf_joints_deg(&[0.0, a2, 0.0, 0.0, 0.0, 0.0]);
    let (dq2, dq3) = (urdf(1.0)[1] - urdf(0.0)[1], urdf(1.0)[2] - urdf(0.0)[2]);
    let reach = model.cyl[i].reach_mm;
    let general = reach[1] * dq2.abs() + reach[2] * dq3.abs();
    let (j2, j3) = (&robot.joints[1], &robot.joints[2]);
    if dq2 == 1.0 && dq3 == -1.0 && j2.axis == j3.axis && j3.origin.rotation == Default::default() {
        let t = j3.origin.translation.vector;
        let u = j2.axis.into_inner();
        (t - u * u.dot(&t)).norm().min(general)
    } else {
        general
    }
}

/// `ceil(k m / s)`: the depth sum a step of motion `m` needs on a scale `s`.
fn need(k: u8, m: f64, s: f64) -> u8 {
    if s > 0.0 {
        (f64::from(k) * m / s).ceil().min(255.0) as u8
    } else {
        0
    }
}

impl GridCheck {
    /// `model` on a grid of spacing `step_deg` (deg): node codes and the step check.
    pub fn new(model: Arc<CollisionModel>, step_deg: f64) -> GridCheck {
        let mut moves = Vec::with_capacity(27);
        for i in 0..27 {
            let o = [i / 9, i / 3 % 3, i % 3].map(|v| (v as f64 - 1.0) * step_deg);
            let q = model
                .robot
                .urdf_joints_deg(&[o[0], o[1], o[2], 0.0, 0.0, 0.0]);
            moves.push([q[0], q[1], q[2]].map(|v| v.abs().to_radians()));
        }
        // M(o) of a part with reach R, raised a little over its float value (module doc).
        let motion = |reach: &[f64; 3]| -> [f64; 27] {
            std::array::from_fn(|o| {
                let m: f64 = (0..3).map(|i| reach[i] * moves[o][i]).sum();
                m * (1.0 + 1e-9) + 1e-9
            })
        };
        let max = |m: &[f64; 27]| m.iter().copied().fold(0.0, f64::max);
        let fixed: Vec<usize> = (0..model.cyl.len())
            .filter(|&i| model.cyl[i].joint < 2)
            .collect();
        let fixed_moves: Vec<[f64; 27]> = fixed
            .iter()
            .map(|&i| motion(&model.cyl[i].reach_mm))
            .collect();
        let fixed_span: Vec<f64> = fixed_moves.iter().map(max).collect();
        let need_fixed = fixed_moves
            .iter()
            .zip(&fixed_span)
            .map(|(m, &s)| std::array::from_fn(|o| need(COLUMN_LEVELS, m[o], s)))
            .collect();
        // One scale for the cylinders axis 3 moves.
        let moved: Vec<[f64; 27]> = (0..model.cyl.len())
            .filter(|&i| model.cyl[i].joint == 2)
            .map(|i| motion(&model.cyl[i].reach_mm))
            .collect();
        let worst: [f64; 27] =
            std::array::from_fn(|o| moved.iter().map(|m| m[o]).fold(0.0, f64::max));
        let arm_span = max(&worst);
        let need_arm = std::array::from_fn(|o| need(DEPTH_LEVELS, worst[o], arm_span));
        let centre: [f64; 27] = match &model.tool {
            Some(t) => motion(&t.centre_reach_mm),
            None => [0.0; 27],
        };
        let centre_span = max(&centre);
        let j3 = model.robot.joints[2].origin;
        let split3 = (0..model.cyl.len())
            .filter(|&i| model.cyl[i].joint == 2)
            .map(|i| {
                let turn = |[par, perp, cross]: [Vector3<f64>; 3]| {
                    [
                        (j3 * Point3::from(par)).coords,
                        j3.rotation * perp,
                        j3.rotation * cross,
                    ]
                };
                (i, model.cyl[i].split.map(turn), shift3(&model, i))
            })
            .collect();
        let need_tool = std::array::from_fn(|o| need(DEPTH_LEVELS, centre[o], centre_span));
        let u3 = model.robot.joints[2].axis.into_inner();
        let centre_parts = model.tool.as_ref().map(|t| {
            let par = u3 * u3.dot(&t.centre);
            let perp = t.centre - par;
            (par, perp, u3.cross(&perp))
        });
        let centre3 = centre_parts.map(|(par, perp, cross)| {
            [
                (j3 * Point3::from(par)).coords,
                j3.rotation * perp,
                j3.rotation * cross,
            ]
        });
        let centre_sweep = centre_parts.map_or(0.0, |(par, perp, _)| par.norm() + perp.norm());
        GridCheck {
            model: Arc::clone(&model),
            fixed,
            fixed_span,
            arm_span,
            centre_span,
            need_fixed,
            need_arm,
            need_tool,
            chain: SinCosChain::new(&model.robot, &model.cell_from_robot),
            joint3: (
                Point3::from(j3.translation.vector),
                j3.rotation * model.robot.joints[2].axis.into_inner(),
            ),
            split3,
            centre3,
            centre_sweep,
            angles: OnceLock::new(),
            slices: SliceMemo::default(),
        }
    }

    /// The collision model.
    pub fn model(&self) -> &CollisionModel {
        &self.model
    }

    /// Whether a node's code says the tool might come within the clearance there (then the
    /// tool must be looked at with the leg's wrist; `false` without a tool).
    #[inline]
    pub fn tool_near(code: u8) -> bool {
        code & CODE_TOOL_NEAR != 0
    }

    /// The code bits [`tool_near`](Self::tool_near) reads: a code with none of them set is not
    /// tool-near.
    pub const TOOL_NEAR_BITS: u8 = CODE_TOOL_NEAR;

    /// The depth `q` of a lower bound `d` of a part's distance to the nearest box, for a part
    /// that moves at most `span` mm over one step, on `levels` levels: the largest
    /// `q <= levels` with `d - c >= q span / levels` (after the slack of `proof.rs`).
    #[inline]
    pub(super) fn depth_of(&self, d: f64, span: f64, levels: u8) -> u8 {
        let k = f64::from(levels);
        let above = lowered(d) - self.model.clearance_mm;
        if above.is_nan() || above < 0.0 {
            return 0;
        }
        if span <= 0.0 || above >= span {
            return levels;
        }
        // `as` truncates, which is `floor` here (the quotient is at least 0).
        ((k * above / span) as u8).min(levels)
    }

    /// [`depth_of`](Self::depth_of) on the node codes' [`DEPTH_LEVELS`].
    #[inline]
    pub(super) fn depth(&self, d: f64, span: f64) -> u8 {
        self.depth_of(d, span, DEPTH_LEVELS)
    }

    /// The smallest distance a part must keep for its depth to be `K`, mm (a distance above it
    /// quantises to `K`; see [`depth`](Self::depth)).
    #[inline]
    pub(super) fn deep_mm(&self, span: f64) -> f64 {
        (self.model.clearance_mm + span + 1e-6) / (1.0 - 1e-6) + 1e-9
    }

    /// A node code from its parts: free, tool near, and the two depths.
    #[inline]
    pub(super) fn code(tool_near: bool, q_tool: u8, q_arm: u8) -> u8 {
        CODE_FREE | if tool_near { CODE_TOOL_NEAR } else { 0 } | (q_tool << 3) | q_arm
    }

    /// The bytes the grid keeps per column: one per link cylinder not moved by axis 3.
    pub fn column_bytes(&self) -> usize {
        self.fixed.len()
    }

    /// Whether the codes alone prove the step between neighbours safe: `(links, tool)`; the
    /// tool is always `true` without one. `a`, `b` are the two nodes' codes and `ca`, `cb` their
    /// columns' bytes; `o` the offset (each component -1, 0 or 1).
    #[inline]
    pub fn proven_by_codes(&self, a: Ends<'_>, b: Ends<'_>, o: [i32; 3]) -> (bool, bool) {
        let i = offset_index(o);
        let arm = (a.code & 7) + (b.code & 7) >= self.need_arm[i]
            && (0..self.fixed.len()).all(|l| {
                u16::from(a.column[l]) + u16::from(b.column[l]) >= u16::from(self.need_fixed[l][i])
            });
        // A node where the tool may come near a box has no depth to give (its `f` may be below
        // the clearance).
        let tool = self.model.tool.is_none()
            || (a.code | b.code) & CODE_TOOL_NEAR == 0
                && ((a.code >> 3) & 7) + ((b.code >> 3) & 7) >= self.need_tool[i];
        (arm, tool)
    }

    /// THE step check: is the straight six-axis move between neighbouring free nodes `from`
    /// and `to` (controller values, the wrist as the leg schedules it; `a`, `b` what the grid
    /// keeps of them; offset `o` = `to - from` in grid steps) safe? The codes first (module
    /// doc), then the whole-move proof of each part they do not prove. Both ends must be in
    /// range (free nodes are, and a leg's wrists lie between two in-range wrists). Symmetric in
    /// its answer only up to the proof's bisection order: callers that need symmetry put the
    /// ends in a fixed order.
    pub fn step_is_safe(
        &self,
        from: &[f64; 6],
        a: Ends<'_>,
        to: &[f64; 6],
        b: Ends<'_>,
        o: [i32; 3],
    ) -> bool {
        let (arm, tool) = self.proven_by_codes(a, b, o);
        (arm || self.model.links_move_is_safe(from, to))
            && (tool || self.model.tool_move_is_safe(from, to))
    }
}

/// What the grid keeps of one end of a step: the node's code and its column's bytes.
#[derive(Clone, Copy, Debug)]
pub struct Ends<'a> {
    pub code: u8,
    pub column: &'a [u8],
}
