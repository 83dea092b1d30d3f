//! One leg of the route, from one cell point to the next, on all six axes (beyond the paper,
//! whose planner moves axes 1..3 and holds the wrist).
//!
//! # The wrist schedule
//!
//! Axes 4..6 turn with the leg's progress ([`WristSchedule`]): a waypoint at axes-1..3 position
//! `q` gets the wrist `w_from + s (w_to - w_from)`, `s` the projection of `q` onto the leg's
//! straight line in axes 1..3, `p_from -> p_to`, clamped to `[0, 1]`, rounded to the written
//! 0.001 deg. The cell points keep their own wrists (`s` is 0 and 1 there). Every `MoveAbsJ`
//! interpolates all six axes linearly, so the moves proven are the six-axis straight segments
//! between consecutive waypoints, with these (rounded) wrists: what is proven is what is
//! written, and what the robot does.
//!
//! # The leg's graph
//!
//! The grid of axes 1..3 is inspected once for the arm (`collision::grid`). A leg's nodes are the
//! arm-free nodes whose tool, at the leg's wrist there, is also free; the tool is looked at only
//! where the node's code says it could reach a box (the wrist centre within the tool's radius
//! plus the clearance of one), only when the wave gets there, and once per node for the whole
//! leg ([`ToolMemo`], shared by its waves and walks; again only where a racing write dropped
//! the answer). Where the tool shapes' balls keep a
//! margin from every box (`CollisionModel::tool_look`), that margin also answers the nodes
//! around, up to two steps out, whose straight six-axis move from the node (the wrist as the
//! schedule turns it, plus its rounding) moves the tool less than the margin: the same answers
//! as the exact test (up to the flange pose's rounding, far inside the margin's slack; every
//! move is proven again on `link_poses`), found with about a fifth of the tool placements on
//! `torch-trunk` (a node well inside the grid reaches the nodes around it by their index
//! deltas, kept with the offsets). The balls are measured against the boxes their cube (30 mm,
//! larger in a very large cell) names (`collision/near.rs`: the others are farther than the
//! margin can use), so the margin is capped at about `LOOK_REACH_MM` (150 mm, two steps on most
//! offsets at 1 deg). Where a shape's inner ball, or an upper bound of its distance to a box,
//! lies within the clearance, the look answers blocked without the exact test (the exact test's
//! answer: `CollisionModel::tool_look_sincos`); a shape whose ball the look found
//! farther than the clearance from every box is passed by the exact test without its boxes. A
//! look places the flange from sines and cosines: those of axes 1..3 from the memo's tables of
//! the grid's values, and link 1's pose from the memo's table per value of axis 1
//! (`CollisionModel::tool_look_link1`: the same steps after it, the same flange to the bit), so
//! a look takes no `sin_cos` and places five joints, not six. Its wrist comes from the memo's
//! tables too: the progress from each axis's term of its dot product per grid value, and the
//! wrist, before its rounding, goes to the sines' table as whole thousandths
//! (`CollisionModel::tool_look_link1_rounding`, `MilliDegSinCos::get_rounded`: the look of
//! [`LegGraph::six`], to the bit, without its degrees). A node already answered costs
//! the memo's load alone (inline; the look is out of line). The graph's steps are the neighbour
//! steps whose
//! six-axis move the step check accepts (`GridCheck::step_is_safe`: node depths first, the
//! whole-move proof where they do not suffice), asked with the two ends in index order so the
//! answer is symmetric. Without a tool this costs nothing beyond the step check.
//!
//! # The leg
//!
//! Join both points to the grid (a point on a node is that node; a point off the grid joins the
//! nearest usable node whose six-axis move to it is proven), search the leg's graph with the
//! method, shorten (extensile), merge collinear moves, round to the written precision, and prove
//! every move again.

use super::merge;
use super::search::{Method, SearchFailure};
use super::shorten;
use super::wave::Graph;
use crate::collision::{Ends, GridCheck};
use crate::place::PlacedPoint;
use crate::plan::cspace::{CSpace, Node};
use crate::precision::quantize_joints;
use crate::robot::Pose;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::OnceLock;

/// The wrist schedule of a leg (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct WristSchedule {
    from: [f64; 3],
    dir: [f64; 3],
    len2: f64,
    w_from: [f64; 3],
    w_to: [f64; 3],
}

impl WristSchedule {
    /// The schedule from one six-axis point to the next (controller values, deg).
    pub fn new(from: &[f64; 6], to: &[f64; 6]) -> WristSchedule {
        let dir = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
        WristSchedule {
            from: [from[0], from[1], from[2]],
            dir,
            len2: dir.iter().map(|d| d * d).sum(),
            w_from: [from[3], from[4], from[5]],
            w_to: [to[3], to[4], to[5]],
        }
    }

    /// `s` of the module doc for axes-1..3 position `q`: 0 for a leg that does not move axes
    /// 1..3.
    pub fn progress(&self, q: &[f64; 3]) -> f64 {
        self.progress_of(std::array::from_fn(|k| self.progress_term(k, q[k])))
    }

    /// Axis `k`'s term of the dot product of `progress`, at controller value `q_deg` (a leg's
    /// memo keeps them per grid value, [`ToolMemo`]).
    #[inline]
    fn progress_term(&self, k: usize, q_deg: f64) -> f64 {
        (q_deg - self.from[k]) * self.dir[k]
    }

    /// `progress` from the three terms of its dot product ([`progress_term`](Self::progress_term)):
    /// summed in axis order, divided by the squared length, clamped.
    #[inline]
    fn progress_of(&self, terms: [f64; 3]) -> f64 {
        if self.len2 <= 0.0 {
            return 0.0;
        }
        let dot: f64 = terms.into_iter().sum();
        (dot / self.len2).clamp(0.0, 1.0)
    }

    /// The wrist at progress `s`, before its rounding.
    #[inline]
    fn wrist_unrounded(&self, s: f64) -> [f64; 3] {
        std::array::from_fn(|k| self.w_from[k] + s * (self.w_to[k] - self.w_from[k]))
    }

    /// The wrist at `q`, rounded to the written precision.
    pub fn wrist_at(&self, q: &[f64; 3]) -> [f64; 3] {
        quantize_joints(self.wrist_unrounded(self.progress(q)))
    }

    /// The most the progress `s` can change between two axes-1..3 positions `dq_deg` apart.
    pub fn progress_change(&self, dq_deg: &[f64; 3]) -> f64 {
        if self.len2 <= 0.0 {
            return 0.0;
        }
        (0..3).map(|k| dq_deg[k] * self.dir[k]).sum::<f64>().abs() / self.len2
    }

    /// How far each wrist axis turns over the whole leg, deg.
    pub fn wrist_span(&self) -> [f64; 3] {
        std::array::from_fn(|k| (self.w_to[k] - self.w_from[k]).abs())
    }

    /// All six axes at `q`.
    pub fn six(&self, q: &[f64; 3]) -> [f64; 6] {
        let w = self.wrist_at(q);
        [q[0], q[1], q[2], w[0], w[1], w[2]]
    }
}

/// What a leg has learned about its tool at the grid's nodes, shared by every wave and walk of
/// the leg (the extensile search's two walks back run at once, as do the eager search's two
/// whole waves, and the eager waves follow the optimistic ones): per node 0 (not looked at
/// yet), [`TOOL_CLEAR`] or [`TOOL_BLOCKED`], 2 bits a node, 32 nodes a word (a quarter of the
/// memory of a byte a node: fewer cache misses where a look's margin answers the nodes around
/// it). Empty without a tool (then no node needs a
/// look). Filled in any order, by any thread: the answer at a node is a pure function of the
/// node and the leg, so a race only repeats the work. A word is read and written back whole
/// (no atomic read-modify-write, which would cost more than it saves): a write racing another in
/// the same word may drop the other's answer, never change one, so that node is looked at
/// again; bits `11` (never written: a node's two answers agree) are neither answer, and the node
/// is looked at again.
/// Beside it, made on the first spread ([`LegGraph::spread_clear`]), the neighbour offsets with
/// the tool's motion over each, in increasing motion, and their grid index deltas: the same at
/// every node of the leg.
pub struct ToolMemo {
    /// Per node of the grid, 2 bits (node `i` at bits `2 (i mod 32)` of word `i / 32`): 0,
    /// [`TOOL_CLEAR`] or [`TOOL_BLOCKED`].
    answers: Vec<AtomicU64>,
    /// The neighbour offsets and the tool's motion over each, in increasing motion, with each
    /// offset's change of the grid's linear index.
    spread: OnceLock<Vec<(f64, [i32; 3], isize)>>,
    /// Per axis 1..3, per grid index along it: the sine and cosine of the controller value
    /// (`CollisionModel::tool_look_sincos`) and the axis's term of the leg's progress there
    /// (`WristSchedule::progress_term`); empty without a tool.
    axis_values: [Vec<AxisValue>; 3],
    /// Per grid index along axis 1: link 1's pose (`CollisionModel::tool_link1`); empty
    /// without a tool.
    link1: Vec<Pose>,
}

const TOOL_CLEAR: u8 = 1;
const TOOL_BLOCKED: u8 = 2;

/// What a look needs of one grid value of one of axes 1..3 ([`ToolMemo`]).
#[derive(Clone, Copy, Debug)]
struct AxisValue {
    /// The value's sine and cosine.
    sincos: (f64, f64),
    /// The axis's term of the leg's progress at the value (`WristSchedule::progress_term`).
    progress: f64,
}

/// What a look at a node reads of the memo's tables ([`ToolMemo`]).
struct NodeTables<'a> {
    /// The sines and cosines of the node's controller axes 1..3.
    sincos: [(f64, f64); 3],
    /// Link 1's pose at the node's axis 1.
    link1: &'a Pose,
    /// The three terms of the leg's progress at the node (`WristSchedule::progress_term`).
    progress: [f64; 3],
}

impl ToolMemo {
    /// A memo for the leg of `schedule` on the grid of `cs`.
    pub fn new(cs: &CSpace, check: &GridCheck, schedule: &WristSchedule) -> ToolMemo {
        let n = if check.model().has_tool() {
            cs.grid.len()
        } else {
            0
        };
        let axis_values: [Vec<AxisValue>; 3] = std::array::from_fn(|k| {
            let along = if n > 0 { cs.grid.dims[k] } else { 0 };
            (0..along)
                .map(|i| {
                    let v = cs.grid.value(k, i as i64);
                    AxisValue {
                        sincos: v.to_radians().sin_cos(),
                        progress: schedule.progress_term(k, v),
                    }
                })
                .collect()
        });
        let model = check.model();
        // Every value's pose, or none at all (no tool): never a table shorter than axis 1's.
        let link1 = axis_values[0]
            .iter()
            .map(|a| model.tool_link1(a.sincos))
            .collect::<Option<Vec<_>>>()
            .unwrap_or_default();
        ToolMemo {
            answers: (0..n.div_ceil(32)).map(|_| AtomicU64::new(0)).collect(),
            spread: OnceLock::new(),
            axis_values,
            link1,
        }
    }

    /// The answer at node index `i`: 0, [`TOOL_CLEAR`] or [`TOOL_BLOCKED`].
    #[inline]
    fn answer(&self, i: usize) -> u8 {
        match self.answers.get(i / 32) {
            Some(w) => ((w.load(Ordering::Relaxed) >> (2 * (i % 32))) & 3) as u8,
            None => 0,
        }
    }

    /// Records answer `a` at node index `i`.
    #[inline]
    fn record(&self, i: usize, a: u8) {
        if let Some(w) = self.answers.get(i / 32) {
            let old = w.load(Ordering::Relaxed);
            let new = old | (u64::from(a) << (2 * (i % 32)));
            if new != old {
                w.store(new, Ordering::Relaxed);
            }
        }
    }

    /// The sines and cosines of node `n`'s controller axes 1..3, and link 1's pose there
    /// (`None` without a tool).
    #[cfg(test)]
    fn arm_at(&self, n: Node) -> Option<([(f64, f64); 3], &Pose)> {
        self.look_at(n).map(|at| (at.sincos, at.link1))
    }

    /// What a look at node `n` reads of the tables (`None` without a tool).
    #[inline]
    fn look_at(&self, n: Node) -> Option<NodeTables<'_>> {
        let [a1, a2, a3] = &self.axis_values;
        let i = usize::try_from(n[0]).ok()?;
        let v = [
            *a1.get(i)?,
            *a2.get(usize::try_from(n[1]).ok()?)?,
            *a3.get(usize::try_from(n[2]).ok()?)?,
        ];
        Some(NodeTables {
            sincos: [v[0].sincos, v[1].sincos, v[2].sincos],
            link1: self.link1.get(i)?,
            progress: [v[0].progress, v[1].progress, v[2].progress],
        })
    }
}

/// The leg's graph on the inspected grid (module doc).
pub struct LegGraph<'a> {
    pub cs: &'a CSpace,
    pub check: &'a GridCheck,
    pub schedule: &'a WristSchedule,
    /// Whether the wave numbers over accepted steps only (else over every step between usable
    /// nodes, the optimistic first try of [`search`]).
    pub eager: bool,
    /// A floor of the ends' distance over the graph's steps, where known (the eager graph's:
    /// the optimistic wave's distance, over a graph that holds this one): its node-by-node
    /// waves are then bounded (`Graph::steps_floor`).
    pub floor: Option<u32>,
    /// The tool's answers so far (the same memo for every graph of one leg).
    pub memo: &'a ToolMemo,
}

impl LegGraph<'_> {
    /// Node `n` on all six axes, the wrist as the leg schedules it.
    pub fn six(&self, n: Node) -> [f64; 6] {
        self.schedule.six(&self.cs.grid.axes_deg(n))
    }

    /// What the grid keeps of node `n` for the step check.
    #[inline]
    fn ends(&self, n: Node) -> Ends<'_> {
        Ends {
            code: self.cs.code(n),
            column: self.cs.column(n),
        }
    }

    /// Whether the leg may use node `n`: free on the grid, and the tool clear at its wrist.
    pub fn usable(&self, n: Node) -> bool {
        self.cs.is_free(n) && self.node_ok(n)
    }

    /// Whether the tool is clear at node `n` (a node whose code says it may come near a box),
    /// looked at once per node for the leg ([`ToolMemo`]). The memo's answer inline (about nine
    /// in ten calls on torch-trunk), the look out of line ([`look`](Self::look)).
    #[inline]
    fn tool_clear(&self, n: Node) -> bool {
        let i = self.cs.grid.index(n);
        match self.memo.answer(i) {
            TOOL_CLEAR => true,
            TOOL_BLOCKED => false,
            _ => self.look(n, i),
        }
    }

    /// The tool's look at node `n` (grid index `index`), its answer recorded in the memo. The
    /// wrist of [`six`](Self::six) from the memo's tables: the progress from the terms of its
    /// dot product, the wrist before its rounding, which the look rounds as it reads the
    /// wrist's sines and cosines (`CollisionModel::tool_look_link1_rounding`): the look of
    /// `six`, to the bit, without placing axes 1..3 or rounding the wrist to degrees.
    #[inline(never)]
    fn look(&self, n: Node, index: usize) -> bool {
        let model = self.check.model();
        // Cheap bounds first; where they leave a margin, it proves the nodes around too.
        let (clear, margin) = match self.memo.look_at(n) {
            Some(at) => {
                let s = self.schedule.progress_of(at.progress);
                let wrist = self.schedule.wrist_unrounded(s);
                model.tool_look_link1_rounding(&wrist, &at.sincos, at.link1)
            }
            None => model.tool_look(&self.six(n)),
        };
        self.memo
            .record(index, if clear { TOOL_CLEAR } else { TOOL_BLOCKED });
        if margin > 0.0 && margin.is_finite() {
            self.spread_clear(n, margin);
        }
        clear
    }

    /// Marks the tool clear at the nodes around `n`, up to [`SPREAD_STEPS`] steps out on each
    /// axis, that the tool reaches from `n` by a straight six-axis move of motion below
    /// `margin` (`CollisionModel::tool_motion_mm`): axes 1..3 by the offset, the wrist by the
    /// most the leg's schedule turns it over that offset plus the rounding of both wrists to
    /// 0.001 deg (whenever the leg turns that wrist axis at all). Such a node's tool keeps more
    /// than the clearance, so the exact test would answer clear there too: the memo holds the
    /// same answers, found with fewer placements of the tool. The offsets' motions are the same
    /// at every node of the leg: reckoned once, in increasing order, so a node visits only the
    /// offsets it proves (and one more). A node [`SPREAD_STEPS`] or more inside every face of
    /// the grid finds them by its index plus each offset's delta; others test the bounds.
    fn spread_clear(&self, n: Node, margin: f64) {
        let grid = &self.cs.grid;
        let offsets = self.memo.spread.get_or_init(|| {
            let model = self.check.model();
            let step = grid.step_deg;
            let span = self.schedule.wrist_span();
            let r = SPREAD_STEPS;
            let mut all = Vec::new();
            for i in -r..=r {
                for j in -r..=r {
                    for k in -r..=r {
                        if (i, j, k) == (0, 0, 0) {
                            continue;
                        }
                        let dq = [i, j, k].map(|o| f64::from(o) * step);
                        let ds = self.schedule.progress_change(&dq);
                        // The rounding of both wrists: 0.001 deg whenever the wrist turns
                        // on the leg at all (two nodes of equal computed progress can still
                        // differ by an ulp).
                        let dw = span.map(|w| if w > 0.0 { ds * w + 1e-3 } else { 0.0 });
                        let motion =
                            model.tool_motion_mm(&[dq[0], dq[1], dq[2], dw[0], dw[1], dw[2]]);
                        let along = |a: usize| grid.dims[a] as isize;
                        let delta = (i as isize * along(1) + j as isize) * along(2) + k as isize;
                        all.push((motion, [i, j, k], delta));
                    }
                }
            }
            all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            all
        });
        // A node SPREAD_STEPS or more inside every face of the grid has all its offsets on it:
        // their indices are its own plus the offsets' deltas.
        let inside = (0..3).all(|k| {
            n[k] >= SPREAD_STEPS
                && usize::try_from(n[k] + SPREAD_STEPS).is_ok_and(|e| e < grid.dims[k])
        });
        let base = grid.index(n) as isize;
        for &(motion, o, delta) in offsets {
            if motion >= margin {
                break;
            }
            let i = if inside {
                usize::try_from(base + delta).ok()
            } else {
                let m = [n[0] + o[0], n[1] + o[1], n[2] + o[2]];
                grid.contains(m).then(|| grid.index(m))
            };
            if let Some(i) = i {
                self.memo.record(i, TOOL_CLEAR);
            }
        }
    }
}

/// How many grid steps out a tool answer is spread ([`LegGraph::spread_clear`]).
const SPREAD_STEPS: i32 = 2;

impl Graph for LegGraph<'_> {
    fn node_ok(&self, n: Node) -> bool {
        self.node_ok_coded(n, self.cs.code(n))
    }

    #[inline]
    fn node_ok_coded(&self, n: Node, code: u8) -> bool {
        if !GridCheck::tool_near(code) {
            return true;
        }
        self.tool_clear(n)
    }

    fn wave_steps_all(&self) -> bool {
        !self.eager
    }

    /// `node_ok_coded` answers from the tool-near bit alone unless it is set.
    fn look_bits(&self) -> Option<u8> {
        Some(GridCheck::TOOL_NEAR_BITS)
    }

    fn steps_floor(&self) -> Option<u32> {
        self.floor
    }

    fn wave_step_ok(&self, a: Node, b: Node) -> bool {
        !self.eager || self.step_ok(a, b)
    }

    #[inline]
    fn step_ok(&self, a: Node, b: Node) -> bool {
        let g = &self.cs.grid;
        let (a, b) = if g.index(a) <= g.index(b) {
            (a, b)
        } else {
            (b, a)
        };
        let (ca, cb) = (self.ends(a), self.ends(b));
        let o = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        if let (true, true) = self.check.proven_by_codes(ca, cb, o) {
            return true;
        }
        self.check
            .step_is_safe(&self.six(a), ca, &self.six(b), cb, o)
    }
}

/// Why a leg could not be planned.
#[derive(Clone, Debug, PartialEq)]
pub enum LegFailure {
    /// The leg's first (`false`) or last (`true`) point joins no usable node by a proven move.
    NoJoin { last: bool },
    /// The search failed.
    Search(SearchFailure),
    /// A move could not be proven after rounding (a defect: every move was proven before).
    Unsafe { from: [f64; 6], to: [f64; 6] },
}

/// A planned leg: the grid path the search returned (for pictures) and the six-axis waypoints,
/// both points included, at the written precision, every move proven.
pub struct PlannedLeg {
    pub grid_path: Vec<Node>,
    pub waypoints: Vec<[f64; 6]>,
}

/// Plans the leg `from -> to` (two placed points whose axes 1..3 differ) with `method` on the
/// inspected grid `cs` (module doc for the steps).
pub fn plan_leg(
    cs: &CSpace,
    check: &GridCheck,
    from: &PlacedPoint,
    to: &PlacedPoint,
    method: Method,
) -> Result<PlannedLeg, LegFailure> {
    let model = check.model();
    let schedule = WristSchedule::new(&from.joints_deg, &to.joints_deg);
    let memo = ToolMemo::new(cs, check, &schedule);
    let graph = LegGraph {
        cs,
        check,
        schedule: &schedule,
        eager: false,
        floor: None,
        memo: &memo,
    };
    let s = join(&graph, &from.joints_deg).ok_or(LegFailure::NoJoin { last: false })?;
    let g = join(&graph, &to.joints_deg).ok_or(LegFailure::NoJoin { last: true })?;
    let grid_path = search(&graph, method, s, g).map_err(LegFailure::Search)?;
    let (p, q) = (from.arm_deg(), to.arm_deg());
    let mut arm = vec![p];
    arm.extend(grid_path.iter().map(|&n| cs.grid.axes_deg(n)));
    arm.push(q);
    arm.dedup();
    let mut prove = |a: &[f64; 6], b: &[f64; 6]| model.move_is_safe(a, b);
    if method == Method::Extensile {
        shorten::shorten(cs, &mut arm, &|n| graph.usable(n), &mut |a, b| {
            prove(&schedule.six(a), &schedule.six(b))
        });
    }
    // Six axes: the points as given, the vias by the schedule.
    let last = arm.len() - 1;
    let six: Vec<[f64; 6]> = arm
        .iter()
        .enumerate()
        .map(|(k, a)| match k {
            0 => from.joints_deg,
            k if k == last => to.joints_deg,
            _ => schedule.six(a),
        })
        .collect();
    // The vias rounded as written; the two points as placed (a robtarget point's are the exact
    // joints the controller computes from its robtarget).
    let mut waypoints: Vec<[f64; 6]> = merge::collinear_proven(&six, &mut prove);
    let inner = 1..waypoints.len().saturating_sub(1);
    for w in &mut waypoints[inner] {
        *w = quantize6(*w);
    }
    waypoints.dedup();
    if waypoints.len() == 1 {
        // The two points coincide: one (empty) move keeps both in the program.
        waypoints.push(to.joints_deg);
    }
    for w in waypoints.windows(2) {
        if !model.move_is_safe(&w[0], &w[1]) {
            return Err(LegFailure::Unsafe {
                from: w[0],
                to: w[1],
            });
        }
    }
    Ok(PlannedLeg {
        grid_path,
        waypoints,
    })
}

/// The leg's search, complete on its grid (module doc): first on the optimistic wave (numbered
/// over every step between usable nodes, as the paper's wave is), walking back over accepted
/// steps only; where that walk runs out, on the eager wave (numbered over accepted steps only),
/// whose walk cannot run out. The optimistic wave's graph holds the true one, so where it does
/// not join the nodes, nothing does, and the ends' distance on it is a floor of their distance
/// over accepted steps: the eager waves, which ask the step proof at every node they number,
/// are bounded from it (`Graph::steps_floor`) and number the nodes between the ends, not the
/// balls around them.
fn search(
    graph: &LegGraph<'_>,
    method: Method,
    s: Node,
    g: Node,
) -> Result<Vec<Node>, SearchFailure> {
    match method.search(graph.cs, s, g, graph) {
        Err(failure @ (SearchFailure::OnlyDiagonal | SearchFailure::WalkFailed { .. })) => {
            let floor = match failure {
                SearchFailure::WalkFailed { steps } => Some(steps),
                _ => None,
            };
            let eager = LegGraph {
                eager: true,
                floor,
                ..*graph
            };
            method.search(graph.cs, s, g, &eager)
        }
        other => other,
    }
}

/// The node a point joins: the node it sits on (if the leg may use it), else the nearest usable
/// node within three rings whose six-axis move to the point is proven.
fn join(graph: &LegGraph<'_>, p: &[f64; 6]) -> Option<Node> {
    let grid = &graph.cs.grid;
    let arm = [p[0], p[1], p[2]];
    if let Some(n) = grid.node_at(&arm) {
        return graph.usable(n).then_some(n);
    }
    let model = graph.check.model();
    for rings in 1..=3 {
        for n in grid.nodes_near(&arm, rings) {
            if graph.usable(n) && model.move_is_safe(p, &graph.six(n)) {
                return Some(n);
            }
        }
    }
    None
}

/// Six controller values rounded to the written precision.
fn quantize6(j: [f64; 6]) -> [f64; 6] {
    let a = quantize_joints([j[0], j[1], j[2]]);
    let w = quantize_joints([j[3], j[4], j[5]]);
    [a[0], a[1], a[2], w[0], w[1], w[2]]
}

#[cfg(test)]
#[path = "leg_tests.rs"]
mod leg_tests;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_memo_keeps_two_bits_a_node_across_its_words() {
        let memo = ToolMemo {
            answers: (0..3).map(|_| AtomicU64::new(0)).collect(),
            spread: OnceLock::new(),
            axis_values: Default::default(),
            link1: Vec::new(),
        };
        let put = [
            (0, TOOL_BLOCKED),
            (31, TOOL_CLEAR),
            (32, TOOL_BLOCKED),
            (95, TOOL_CLEAR),
        ];
        for (i, a) in put {
            memo.record(i, a);
            memo.record(i, a);
        }
        for i in 0..96 {
            let want = put.iter().find(|p| p.0 == i).map_or(0, |p| p.1);
            assert_eq!(memo.answer(i), want, "node {i}");
        }
        // Word 0 holds node 0 in its lowest bits and node 31 in its highest.
        assert_eq!(memo.answers[0].load(Ordering::Relaxed), 2 | 1 << 62);
        // A node answered both ways (never, as the answers agree) holds neither answer, so
        // `tool_clear` looks at it again.
        memo.record(40, TOOL_CLEAR);
        memo.record(40, TOOL_BLOCKED);
        assert_eq!(memo.answer(40), TOOL_CLEAR | TOOL_BLOCKED);
        // Past the grid: nothing kept, nothing read.
        memo.record(96, TOOL_CLEAR);
        assert_eq!(memo.answer(96), 0);
    }

    #[test]
    fn the_wrist_follows_the_projection_clamped_and_rounded() {
        let from = [0.0, 0.0, 0.0, 0.0, 30.0, -90.0];
        let to = [10.0, 0.0, 0.0, 90.0, 30.0, 90.0];
        let s = WristSchedule::new(&from, &to);
        // On the line: in proportion.
        assert_eq!(s.wrist_at(&[5.0, 0.0, 0.0]), [45.0, 30.0, 0.0]);
        assert_eq!(s.wrist_at(&[2.5, 0.0, 0.0]), [22.5, 30.0, -45.0]);
        // Off the line: the projection decides (axis 2 and 3 are across the line).
        assert_eq!(s.wrist_at(&[2.5, 7.0, -3.0]), [22.5, 30.0, -45.0]);
        // Behind the start and beyond the end: clamped.
        assert_eq!(s.wrist_at(&[-4.0, 1.0, 0.0]), [0.0, 30.0, -90.0]);
        assert_eq!(s.wrist_at(&[13.0, 0.0, 0.0]), [90.0, 30.0, 90.0]);
        // The ends are the points' own wrists, exactly.
        assert_eq!(s.six(&[0.0, 0.0, 0.0]), from);
        assert_eq!(s.six(&[10.0, 0.0, 0.0]), to);
        // Rounded to 0.001 deg: a third of the way gives 30 deg, 1/3 of 100 gives 33.333.
        let t = WristSchedule::new(
            &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            &[3.0, 3.0, 3.0, 100.0, -100.0, 1.0],
        );
        assert_eq!(t.wrist_at(&[1.0, 1.0, 1.0]), [33.333, -33.333, 0.333]);
        // Along a diagonal leg a point off it projects onto it.
        assert_eq!(t.progress(&[3.0, 0.0, 0.0]), 1.0 / 3.0);
        // A leg that does not move axes 1..3 keeps the first wrist.
        let still = WristSchedule::new(&from, &[0.0, 0.0, 0.0, 9.0, 9.0, 9.0]);
        assert_eq!(still.wrist_at(&[0.0, 0.0, 0.0]), [0.0, 30.0, -90.0]);
    }
}
