//! The plan stage: the route through the cell's points, leg by leg (paper section 4, applied to
//! A -> B -> ... -> F), as the [`Plan`] the output stage prints.
//!
//! For each leg ([`leg`]): join both points to the grid (a point on a node is that node; a point
//! off the grid joins the nearest usable node whose straight move to it is proven safe); search
//! the leg's graph with the chosen method ([`search`]): its nodes are the free grid nodes where
//! the tool (if any) is clear at the leg's wrist, its steps the neighbour steps whose straight
//! six-axis move is proven safe, and the walk back takes those steps only (on a wave numbered
//! over every step between usable nodes first, else over those steps only: `leg`), so the
//! search never runs out of steps (complete on its grid); for the extensile method shorten
//! recursively ([`shorten`]); merge collinear moves ([`merge`]); round to the written precision
//! (0.001 deg) and prove every move again. The route starts at the first point, visits every point in the
//! cell's order, and each cell point is a waypoint exactly as given ([`route`]). Then the
//! smallest clearance along every move, and so along the whole route, is certified
//! ([`certify`]; [`plan`] does both, a run routes here and certifies in the refine stage the
//! route it keeps).
//!
//! Beyond the paper, for speed only: the legs are independent (each a pure function of the grid,
//! the model, its two points and the method), so [`route`] plans two at once where the memory
//! of the second is small ([`legs_at_once`]), the longest first ([`longest_first`]), and puts
//! them together in order: the same plan, and the same error (the first failing leg's), as leg
//! by leg.
//!
//! Axes 4..6: the grid is over axes 1..3 (the paper's lumped arm); a waypoint carries all six. A
//! cell point keeps its own wrist ([`PlacedPoint::joints_deg`]); a via gets the leg's wrist
//! schedule: the wrist turns in proportion to the leg's progress along axes 1..3
//! ([`leg::WristSchedule`]). Every move is proven on all six axes, links and tool shapes.
//!
//! Files: [`cspace`] (the grid, paper section 3; knows no geometry), [`wave`] (wave expansion),
//! [`search`] (the three methods, and [`Method`]), [`leg`] (one leg, the wrist schedule, the
//! leg's graph), [`shorten`], [`merge`]; [`motion`] the speed and zone of each move.

pub mod cspace;
pub mod leg;
pub mod merge;
pub mod motion;
pub mod search;
pub mod shorten;
pub mod wave;

pub use search::Method;

use crate::collision::{Blocked, CollisionModel, GridCheck};
/// The smallest clearance along a move, as the plan holds it (certified by the collision model),
/// and the part of the robot model it is about.
pub use crate::collision::{Clearance, Part};
use crate::place::PlacedPoint;
use cspace::{CSpace, Node};
use leg::LegFailure;
use search::SearchFailure;
use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// The collision model's node codes mark a free node with the bit the grid reads.
const _: () = assert!(crate::collision::CODE_FREE == cspace::FREE);

/// Tolerance of the certified smallest clearance along the route, mm.
pub const MIN_CLEARANCE_TOL_MM: f64 = 0.05;

/// What a waypoint is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WaypointKind {
    /// A cell point (index into the placed points).
    CellPoint(usize),
    /// A via the planner inserted: the `index`-th (from 1) of leg `leg` (from 0; leg `i` runs
    /// from point `i` to point `i + 1`).
    Via { leg: usize, index: usize },
}

/// A waypoint of the route: where a move starts or ends.
#[derive(Clone, Debug, PartialEq)]
pub struct Waypoint {
    pub kind: WaypointKind,
    /// Controller values of axes 1..6, deg, at the written precision.
    pub joints_deg: [f64; 6],
}

impl Waypoint {
    /// Axes 1..3 (the planning axes), deg.
    pub fn arm_deg(&self) -> [f64; 3] {
        [self.joints_deg[0], self.joints_deg[1], self.joints_deg[2]]
    }
}

/// One leg: from point `from` to point `to` (indices into the points).
#[derive(Clone, Debug)]
pub struct Leg {
    pub from: usize,
    pub to: usize,
    /// The grid path the search returned (before shortening and merging), for pictures.
    pub grid_path: Vec<Node>,
    /// Its waypoints in [`Plan::waypoints`], both ends included (a leg shares its first
    /// waypoint with the previous leg's last).
    pub waypoints: Range<usize>,
}

/// The manipulation time of a route (paper section 5, with the speeddata and the fly-by at
/// zoned waypoints: `timing`), filled by the time stage.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Per move, s: from rest to rest, less what flying through a zoned waypoint at either end
    /// saves.
    pub move_s: Vec<f64>,
    /// Per move, how its progress runs in time (for pictures of the motion).
    pub move_profile: Vec<Profile>,
    /// Per move, what set its stop-to-stop time: the axes, the TCP speed or the reorientation
    /// speed of its speeddata (`timing`).
    pub move_limit: Vec<Limit>,
    /// The sum, s.
    pub total_s: f64,
}

/// What set a move's time (`timing`): the longest of the three.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// The axes' own speeds and accelerations (the leading axis' profile).
    Axis,
    /// The TCP path length at the speeddata's `v_tcp`.
    Tcp,
    /// The tool's reorientation angle at the speeddata's `v_ori`.
    Reorientation,
}

impl Limit {
    /// The name the report writes: `axis`, `tcp` or `reorientation`.
    pub fn name(self) -> &'static str {
        match self {
            Limit::Axis => "axis",
            Limit::Tcp => "tcp",
            Limit::Reorientation => "reorientation",
        }
    }
}

/// The route of the paper's method alone (search, shortening, merge, every via a stop point) and
/// its estimated time: the figure a later refinement of the route is measured against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperFigure {
    pub moves: usize,
    pub time_s: f64,
}

/// How a move's progress runs in time: the profile of its leading axis (paper Fig. 9, chosen by
/// the time stage). A picture moves all axes along it, together, on the straight joint move
/// (`MoveAbsJ`); the time stage's other axes finish with the leading one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    /// One rest-to-rest quintic `h(s) = 10 s^3 - 15 s^4 + 6 s^5` over the whole move (Fig. 9b);
    /// also a move that does not move.
    Quintic,
    /// A quintic speed ramp of `ramp_s` up to a cruise and one down from it (Fig. 9a): the speed
    /// follows `v h(t / ramp_s)` on the way up.
    Cruise { ramp_s: f64 },
}

impl Profile {
    /// The share of the move done (0 at the start, 1 at the end) at time `t_s` of a move taking
    /// `total_s`; `t_s` is clamped into the move.
    pub fn progress(&self, t_s: f64, total_s: f64) -> f64 {
        if total_s <= 0.0 {
            return 1.0;
        }
        let t = t_s.clamp(0.0, total_s);
        // The rest-to-rest quintic and its integral (the distance covered on a ramp, in units of
        // speed x ramp time: 1/2 at the ramp's end).
        let h = |s: f64| s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
        let ramp = |s: f64| s.powi(4) * (2.5 + s * (-3.0 + s));
        match *self {
            Profile::Cruise { ramp_s } if ramp_s > 0.0 && 2.0 * ramp_s <= total_s => {
                // Distance 1 at cruise speed v over total_s = 1 / v + ramp_s.
                let v = 1.0 / (total_s - ramp_s);
                let p = if t < ramp_s {
                    v * ramp_s * ramp(t / ramp_s)
                } else if t <= total_s - ramp_s {
                    v * (0.5 * ramp_s + (t - ramp_s))
                } else {
                    1.0 - v * ramp_s * ramp((total_s - t) / ramp_s)
                };
                p.clamp(0.0, 1.0)
            }
            _ => h(t / total_s),
        }
    }
}

/// The route through all points: everything the output stage prints.
#[derive(Clone, Debug)]
pub struct Plan {
    pub method: Method,
    /// The grid spacing it was planned on, deg.
    pub grid_deg: f64,
    /// Every waypoint in visiting order; the first is the first cell point, the last the last.
    pub waypoints: Vec<Waypoint>,
    pub legs: Vec<Leg>,
    /// The certified smallest clearance along the whole route (within
    /// [`MIN_CLEARANCE_TOL_MM`], [`certify`]); `None` without obstacles (or before [`certify`]).
    pub min_clearance: Option<Clearance>,
    /// The certified smallest clearance along each move, in move order (move `i` runs from
    /// waypoint `i` to `i + 1`), with the part (link or tool shape) and obstacle where it occurs;
    /// each `None` without obstacles. Empty before [`certify`] (`compare` does without).
    pub move_clearances: Vec<Option<Clearance>>,
    /// The manipulation time, once the time stage has run.
    pub estimate: Option<Estimate>,
    /// The paper's method alone on the same cell (moves and estimated time), kept by the pipeline
    /// after the first time stage; `None` before.
    pub paper: Option<PaperFigure>,
    /// The zone of the move into each waypoint as the refine stage certified it (issue 10:
    /// a via's `motion.via_zone` where its corner is proven, a cell point's own zone where its
    /// corner is proven, else `fine`; the first and last waypoints `fine`). Empty before that
    /// stage: then [`Plan::motion_into`] gives the paper's rule (every via `fine`).
    pub zones: Vec<String>,
}

impl Plan {
    /// Number of straight moves.
    pub fn moves(&self) -> usize {
        self.waypoints.len().saturating_sub(1)
    }

    /// Every straight move on axes 1..3, in order.
    pub fn segments(&self) -> impl Iterator<Item = ([f64; 3], [f64; 3])> + '_ {
        self.waypoints
            .windows(2)
            .map(|w| (w[0].arm_deg(), w[1].arm_deg()))
    }

    /// Every straight move on all six axes, in order: what the module's `MoveAbsJ`s do.
    pub fn moves6(&self) -> impl Iterator<Item = ([f64; 6], [f64; 6])> + '_ {
        self.waypoints
            .windows(2)
            .map(|w| (w[0].joints_deg, w[1].joints_deg))
    }

    /// Sum of the moves' lengths in joint space (Euclidean over axes 1..3, deg).
    pub fn path_length_deg(&self) -> f64 {
        self.segments()
            .map(|(a, b)| (0..3).map(|k| (b[k] - a[k]).powi(2)).sum::<f64>().sqrt())
            .sum()
    }
}

/// Why a route could not be planned. Each variant names the point(s) concerned.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    #[error("point '{name}' cannot be used: {reason}")]
    PointBlocked {
        point: usize,
        name: String,
        reason: Blocked,
    },
    #[error("point '{name}' is off the grid and no free grid node next to it can be reached by a safe straight move")]
    NoJoin { point: usize, name: String },
    #[error("no collision-free path from '{from_name}' to '{to_name}': the free space between them is not connected on a {grid_deg} deg grid with {clearance_mm} mm clearance")]
    NoPath {
        from: usize,
        to: usize,
        from_name: String,
        to_name: String,
        grid_deg: f64,
        clearance_mm: f64,
    },
    #[error("the {method} search found no path from '{from_name}' to '{to_name}'{}", method_hint(*.method))]
    SearchFailed {
        from: usize,
        to: usize,
        from_name: String,
        to_name: String,
        method: Method,
    },
    #[error("the robot cannot go from '{from_name}' to '{to_name}': the two points share axes 1..3, so the wrist turns in place, and on the way {reason}")]
    WristTurn {
        from: usize,
        to: usize,
        from_name: String,
        to_name: String,
        /// Boxed: it is large and errors travel in `Result`s.
        reason: Box<Blocked>,
    },
    #[error("internal error: the move {from_axes:?} -> {to_axes:?} on the leg '{from_name}' -> '{to_name}' could not be proven safe after rounding")]
    Unsafe {
        from: usize,
        from_name: String,
        to_name: String,
        from_axes: Box<[f64; 6]>,
        to_axes: Box<[f64; 6]>,
    },
}

/// Why the search failed: for depth-first, the paper's Fig. 8 (the grid's safe steps join the two
/// points, but not through axis steps); for the others a defect, since the walk back only takes
/// steps the wave took (`search`).
fn method_hint(m: Method) -> &'static str {
    match m {
        Method::DepthFirst => " (depth-first walks axis steps only and the free space there is joined only diagonally, the paper's Fig. 8; try --planner extensile)",
        _ => " (internal error: the walk back found no step the wave had taken)",
    }
}

impl PlanError {
    /// The cell point an error is about, for pointing at the input.
    pub fn point(&self) -> usize {
        match self {
            PlanError::PointBlocked { point, .. } | PlanError::NoJoin { point, .. } => *point,
            PlanError::NoPath { to, .. }
            | PlanError::SearchFailed { to, .. }
            | PlanError::WristTurn { to, .. } => *to,
            PlanError::Unsafe { from, .. } => *from,
        }
    }
}

/// The grid asks the collision model, on its spacing, which nodes are free and how deep.
impl cspace::Inspector for GridCheck {
    fn column_bytes(&self) -> usize {
        GridCheck::column_bytes(self)
    }
    /// Every leg's graph (`leg::LegGraph`) looks at the nodes with the tool-near bit.
    fn row_bits_ahead(&self) -> Option<u8> {
        Some(GridCheck::TOOL_NEAR_BITS)
    }
    fn inspect_column(
        &self,
        a1_deg: f64,
        a2_deg: f64,
        a3_deg: &[f64],
        code: &mut [u8],
        column: &mut [u8],
    ) {
        GridCheck::inspect_column(self, a1_deg, a2_deg, a3_deg, code, column)
    }
    fn inspect_slice(
        &self,
        a1_deg: f64,
        a2_deg: &[f64],
        a3_deg: &[f64],
        code: &mut [u8],
        column: &mut [u8],
    ) {
        // Link 1's checks and pose and the axis-3 angles once for the slice (`collision::column`).
        let slice = self.slice(a1_deg, a3_deg);
        let mut memo = self.fixed_memo();
        let width = GridCheck::column_bytes(self);
        cspace::each_column(
            a2_deg,
            a3_deg.len(),
            width,
            code,
            column,
            |a2, codes, own| self.inspect_column_in(a2, codes, own, &slice, &mut memo),
        );
    }
}

/// Plans the route through `points` (at least two), in order, on the inspected grid `cs` of the
/// collision model `model`, and certifies its smallest clearance: [`route`], then [`certify`].
pub fn plan(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[PlacedPoint],
    method: Method,
) -> Result<Plan, PlanError> {
    Ok(certify(route(cs, model, points, method)?, model))
}

/// The smallest clearance along every move and along the whole route (the least of the moves'),
/// each certified within [`MIN_CLEARANCE_TOL_MM`] (`None` without obstacles), into the plan.
/// The moves are certified on all cores (`crate::parallel`), each as alone.
pub fn certify(plan: Plan, model: &CollisionModel) -> Plan {
    let moves: Vec<_> = plan.moves6().collect();
    let clearances = crate::parallel::map(&moves, |(a, b)| {
        model.min_clearance_along(a, b, MIN_CLEARANCE_TOL_MM)
    });
    with_clearances(plan, clearances)
}

/// [`certify`], where every move of `plan` is proven safe again
/// ([`CollisionModel::move_is_safe`]): each move proven, then certified, a move at a time on
/// all cores; `None` when a move is not proven (then no move started after it is proven or
/// certified).
pub fn certify_proven(plan: Plan, model: &CollisionModel) -> Option<Plan> {
    let moves: Vec<_> = plan.moves6().collect();
    let failed = AtomicBool::new(false);
    let clearances = crate::parallel::map(&moves, |(a, b)| {
        if failed.load(Ordering::Relaxed) || !model.move_is_safe(a, b) {
            failed.store(true, Ordering::Relaxed);
            return None;
        }
        Some(model.min_clearance_along(a, b, MIN_CLEARANCE_TOL_MM))
    });
    let clearances: Option<Vec<_>> = clearances.into_iter().collect();
    Some(with_clearances(plan, clearances?))
}

/// `plan` with the smallest clearance of each move (`clearances`, one a move) and the least of
/// them.
fn with_clearances(mut plan: Plan, clearances: Vec<Option<Clearance>>) -> Plan {
    plan.move_clearances = clearances;
    plan.min_clearance = plan
        .move_clearances
        .iter()
        .flatten()
        .cloned()
        .reduce(|least, c| if c.mm < least.mm { c } else { least });
    plan
}

/// The route alone (every move proven safe; the smallest clearance not yet certified, which
/// costs a branch and bound over every move: `compare` does without).
pub fn route(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[PlacedPoint],
    method: Method,
) -> Result<Plan, PlanError> {
    route_on(cs, model, points, method, legs_at_once(cs, model))
}

/// [`route`] planning up to `at_once` legs at once (1: leg by leg; for tests and benchmarks:
/// the plan is the same whatever `at_once`).
pub fn route_on(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[PlacedPoint],
    method: Method,
    at_once: usize,
) -> Result<Plan, PlanError> {
    for (i, p) in points.iter().enumerate() {
        if let Some(reason) = model.why_blocked(&p.joints_deg) {
            return Err(PlanError::PointBlocked {
                point: i,
                name: p.name.clone(),
                reason,
            });
        }
    }
    let grid = &cs.grid;
    let check = model.grid_check(grid.step_deg);
    let legs = if at_once > 1 {
        longest_first(points)
    } else {
        (0..points.len() - 1).collect()
    };
    // The legs on up to `at_once` threads. A leg after a failed one is not started (every leg
    // before the first failure is planned, whatever the order they are handed out in): the
    // error is the first failing leg's, as leg by leg.
    let first_failed = AtomicUsize::new(usize::MAX);
    let mut planned: Vec<Option<_>> = (0..legs.len()).map(|_| None).collect();
    let done = crate::parallel::map_on(at_once, &legs, |&i| {
        if i > first_failed.load(Ordering::Relaxed) {
            return None;
        }
        let leg = route_leg(cs, model, &check, points, i, method);
        if leg.is_err() {
            first_failed.fetch_min(i, Ordering::Relaxed);
        }
        Some(leg)
    });
    for (&i, leg) in legs.iter().zip(done) {
        planned[i] = leg;
    }
    let mut made = Route::default();
    for (i, leg) in planned.into_iter().enumerate() {
        // A leg not started follows a failed one, whose error returned first: planned here
        // only if that ever did not hold.
        let (grid_path, six) = match leg {
            Some(leg) => leg?,
            None => route_leg(cs, model, &check, points, i, method)?,
        };
        made.add_leg(i, grid_path, six);
    }
    Ok(Plan {
        method,
        grid_deg: grid.step_deg,
        waypoints: made.waypoints,
        legs: made.legs,
        min_clearance: None,
        move_clearances: Vec::new(),
        estimate: None,
        paper: None,
        zones: Vec::new(),
    })
}

/// The legs of the route through `points`, longest first: by the most any of axes 1..3 turns
/// between the leg's two points (the number of levels its waves need, which the leg's time
/// grows with), then by their summed turn, then in route order. Handed out in this order, the
/// long legs start first, so no long leg starts last while the other core idles (the
/// longest-processing-time rule of scheduling). The plan is the same in any order.
fn longest_first(points: &[PlacedPoint]) -> Vec<usize> {
    let turn = |i: usize| {
        let (a, b) = (points[i].arm_deg(), points[i + 1].arm_deg());
        let d = [0, 1, 2].map(|k| (a[k] - b[k]).abs());
        (d[0].max(d[1]).max(d[2]), d[0] + d[1] + d[2])
    };
    let mut legs: Vec<usize> = (0..points.len().saturating_sub(1)).collect();
    legs.sort_by(|&i, &j| {
        let ((mi, si), (mj, sj)) = (turn(i), turn(j));
        mj.total_cmp(&mi).then(sj.total_cmp(&si)).then(i.cmp(&j))
    });
    legs
}

/// Leg `i` of the route (point `i` to point `i + 1`): its grid path (empty for a wrist turn in
/// place) and its six-axis waypoints, both ends included.
fn route_leg(
    cs: &CSpace,
    model: &CollisionModel,
    check: &GridCheck,
    points: &[PlacedPoint],
    i: usize,
    method: Method,
) -> Result<(Vec<Node>, Vec<[f64; 6]>), PlanError> {
    let (from, to) = (&points[i], &points[i + 1]);
    if from.arm_deg() == to.arm_deg() {
        // The same axes 1..3 twice (the wrist may differ): one move that stays put, proven
        // like any other (the tool turns).
        let (a, b) = (from.joints_deg, to.joints_deg);
        if let Some((_, reason)) = model.why_move_unsafe(&a, &b) {
            // Name the closest approach along the turn (not where it first comes within
            // the clearance).
            let reason = match (
                reason,
                model.min_clearance_along(&a, &b, MIN_CLEARANCE_TOL_MM),
            ) {
                (Blocked::Contact { .. }, Some(c)) if c.mm < model.clearance_mm() => {
                    Blocked::Contact {
                        part: c.part,
                        obstacle: c.obstacle,
                        distance_mm: c.mm.max(0.0),
                    }
                }
                (reason, _) => reason,
            };
            return Err(PlanError::WristTurn {
                from: i,
                to: i + 1,
                from_name: from.name.clone(),
                to_name: to.name.clone(),
                reason: Box::new(reason),
            });
        }
        return Ok((Vec::new(), vec![a, b]));
    }
    let names = || (from.name.clone(), to.name.clone());
    let planned = leg::plan_leg(cs, check, from, to, method).map_err(|failure| {
        let (from_name, to_name) = names();
        match failure {
            LegFailure::NoJoin { last } => PlanError::NoJoin {
                point: i + usize::from(last),
                name: if last { to_name } else { from_name },
            },
            LegFailure::Search(SearchFailure::NotConnected) => PlanError::NoPath {
                from: i,
                to: i + 1,
                from_name,
                to_name,
                grid_deg: cs.grid.step_deg,
                clearance_mm: model.clearance_mm(),
            },
            LegFailure::Search(SearchFailure::OnlyDiagonal | SearchFailure::WalkFailed) => {
                PlanError::SearchFailed {
                    from: i,
                    to: i + 1,
                    from_name,
                    to_name,
                    method,
                }
            }
            LegFailure::Unsafe { from: a, to: b } => PlanError::Unsafe {
                from: i,
                from_name,
                to_name,
                from_axes: Box::new(a),
                to_axes: Box::new(b),
            },
        }
    })?;
    Ok((planned.grid_path, planned.waypoints))
}

/// The most legs [`route`] plans at once: two keep two cores busy where one leg alone leaves
/// one idle (its waves, numbered together from both ends, run on one thread, and so do its
/// merge, shortening and proofs; only its two walks back run side by side). When the extensile
/// search's two waves were numbered whole on two threads, on `torch-trunk` at 1 deg (2 cores)
/// the route took 168 ms instead of 196 and the whole run 0.33 s instead of 0.35
/// (`benches/README.md`).
pub const LEGS_AT_ONCE_MAX: usize = 2;

/// The most memory the legs planned beside the first may hold, bytes ([`legs_at_once`]).
const LEGS_EXTRA_MAX_BYTES: usize = 64 << 20;

/// How many legs [`route`] plans at once: [`LEGS_AT_ONCE_MAX`] where the legs beside the first
/// hold at most [`LEGS_EXTRA_MAX_BYTES`], else one (leg by leg, the memory of one leg as
/// ever). A leg in hand holds, per grid node, at most: its two waves' labels (2 bytes each,
/// `u16`, for a node-by-node wave; the row wave's residues take 2 bits, and the two waves
/// numbered together from both ends hold four sets of 2-bit residues while they gather the
/// shortest paths' nodes), their bit sets (the decided nodes and the candidates, with the
/// rows' words rounded up: up to 4 bits a node a wave) and its tool memo (2 bits with a tool,
/// `leg::ToolMemo`): 5.25 bytes a node with a tool, 5 without. Over the IRB 1400's ranges at 1
/// deg (341 x 141 x 136 = 6.5 M nodes) that is 34 MB with a tool: two legs at once; at 0.5 deg
/// (681 x 281 x 271 = 52 M nodes) 272 MB: leg by leg, as on any grid of more than 12.8 M nodes
/// (13.4 M without a tool). A wave whose numbers
/// outgrow `u16` takes `u32` labels, twice the bytes, but only at more than 65 533 steps from
/// its start: on grids far past these.
pub fn legs_at_once(cs: &CSpace, model: &CollisionModel) -> usize {
    // Quarter bytes a node: two waves' labels and bit sets, and the tool memo.
    let quarters = 2 * (4 * std::mem::size_of::<u16>() + 2) + usize::from(model.has_tool());
    let leg_bytes = cs.grid.len().saturating_mul(quarters) / 4;
    if leg_bytes.saturating_mul(LEGS_AT_ONCE_MAX - 1) <= LEGS_EXTRA_MAX_BYTES {
        LEGS_AT_ONCE_MAX
    } else {
        1
    }
}

/// The waypoints and legs as they are made.
#[derive(Default)]
struct Route {
    waypoints: Vec<Waypoint>,
    legs: Vec<Leg>,
}

impl Route {
    /// Adds leg `i` (point `i` to point `i + 1`) with its six-axis waypoints (both ends
    /// included, the ends the points as given).
    fn add_leg(&mut self, i: usize, grid_path: Vec<Node>, six: Vec<[f64; 6]>) {
        let start = self.waypoints.len().saturating_sub(1);
        if self.waypoints.is_empty() {
            if let Some(&first) = six.first() {
                self.waypoints.push(Waypoint {
                    kind: WaypointKind::CellPoint(i),
                    joints_deg: first,
                });
            }
        }
        let n = six.len();
        for (k, &joints_deg) in six.iter().enumerate().skip(1) {
            let kind = if k == n - 1 {
                WaypointKind::CellPoint(i + 1)
            } else {
                WaypointKind::Via { leg: i, index: k }
            };
            self.waypoints.push(Waypoint { kind, joints_deg });
        }
        self.legs.push(Leg {
            from: i,
            to: i + 1,
            grid_path,
            waypoints: start..self.waypoints.len(),
        });
    }
}

#[cfg(test)]
mod tests {
    //! The paper's figures through the plan layer: a hand-made grid (`CSpace::from_fn`) with the
    //! real IRB 1400 model and no obstacles, so every move inside the axis ranges is safe and
    //! only the hand-made free nodes steer the search.
    use super::*;
    use crate::cell::Loc;
    use crate::place::{Origin, Placement};
    use crate::plan::cspace::Grid;
    use crate::robot::Robot;

    fn open_model() -> CollisionModel {
        let placement = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        CollisionModel::new(&Robot::irb1400(), placement, Vec::new(), 0.0, None)
    }

    fn point(name: &str, a: [f64; 3], wrist: [f64; 3]) -> PlacedPoint {
        PlacedPoint {
            name: name.into(),
            joints_deg: [a[0], a[1], a[2], wrist[0], wrist[1], wrist[2]],
            loc: Loc::default(),
            origin: Origin::Joints,
            motion: crate::place::MoveMotion {
                speed: "v300".into(),
                zone: "fine".into(),
            },
        }
    }

    /// Axes 1..3 of a leg's waypoints.
    fn leg_arm(p: &Plan, leg: usize) -> Vec<[f64; 3]> {
        p.waypoints[p.legs[leg].waypoints.clone()]
            .iter()
            .map(Waypoint::arm_deg)
            .collect()
    }

    #[test]
    fn fig8_depth_first_fails_with_the_leg_named_and_extensile_takes_the_diagonal() {
        // 3 x 3 nodes in the axis 1 - axis 2 plane; free only on the diagonal, so the free
        // nodes touch only at corners (paper Fig. 8).
        let g = Grid::over([[0.0, 2.0], [0.0, 2.0], [0.0, 0.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| n[0] == n[1]);
        let model = open_model();
        let pts = [
            point("P", [0.0, 0.0, 0.0], [0.0; 3]),
            point("Q", [2.0, 2.0, 0.0], [0.0; 3]),
        ];
        match plan(&cs, &model, &pts, Method::DepthFirst) {
            Err(e @ PlanError::SearchFailed { from: 0, to: 1, .. }) => {
                let msg = e.to_string();
                assert!(
                    msg.contains("depth-first search found no path from 'P' to 'Q'"),
                    "{msg}"
                );
                assert_eq!(e.point(), 1);
            }
            other => panic!("expected SearchFailed, got {other:?}"),
        }
        let p = plan(&cs, &model, &pts, Method::Extensile).expect("extensile plans");
        assert_eq!(p.moves(), 1);
        assert_eq!(leg_arm(&p, 0), vec![[0.0, 0.0, 0.0], [2.0, 2.0, 0.0]]);
        assert_eq!(p.legs[0].grid_path, vec![[0, 0, 0], [1, 1, 0], [2, 2, 0]]);
        // No obstacles: no clearance to certify, on any move.
        assert_eq!(p.min_clearance, None);
        assert_eq!(p.move_clearances, vec![None; p.moves()]);
        // Not joined at all: no path, for every method (one wave tells).
        let cs = CSpace::from_fn(g, |n| n[0] != 1);
        for m in Method::ALL {
            assert!(
                matches!(plan(&cs, &model, &pts, m), Err(PlanError::NoPath { .. })),
                "{m}"
            );
        }
    }

    #[test]
    fn fig6_neighboring_saw_tooth_and_extensile_straightens_it() {
        // A band of free nodes along axis 2 = axis 1 / 2 (|2 n2 - n1| <= 1), from (0, 0) to
        // (10, 5). On the 26-neighbour wave node (x, y) carries x + 1. Back from (10, 5) the
        // neighbouring search takes, among the smaller numbers in the band, the node nearest the
        // start: (9, 4) (97 against 106 for (9, 5)), then only (8, 4), then (7, 3), ...
        // a diagonal step and an axis step in turn: ten steps, no two in the same direction, so
        // ten moves even after the collinear merge (the saw-tooth of Fig. 6).
        let g = Grid::over([[0.0, 10.0], [0.0, 5.0], [0.0, 0.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| (2 * n[1] - n[0]).abs() <= 1);
        let model = open_model();
        let pts = [
            point("P", [0.0, 0.0, 0.0], [0.0; 3]),
            point("Q", [10.0, 5.0, 0.0], [0.0; 3]),
        ];
        let nb = plan(&cs, &model, &pts, Method::Neighboring).expect("neighboring plans");
        assert_eq!(nb.moves(), 10, "{:?}", leg_arm(&nb, 0));
        assert_eq!(leg_arm(&nb, 0)[1], [1.0, 0.0, 0.0]);
        assert_eq!(leg_arm(&nb, 0)[2], [2.0, 1.0, 0.0]);
        // Extensile: search, shorten (k -> k+2 where the inspected nodes are free) and merge.
        // The straight line (0, 0) -> (10, 5) passes only band nodes (at x = i its axis-2 value
        // i / 2 rounds into the band), but the shortening cuts k -> k+2 greedily from the start,
        // so it ends with at most a few pieces and never more than the saw-tooth.
        let ex = plan(&cs, &model, &pts, Method::Extensile).expect("extensile plans");
        assert!(ex.moves() <= 2, "{:?}", leg_arm(&ex, 0));
        assert!(ex.path_length_deg() < nb.path_length_deg());
        for (a, b) in ex.segments() {
            let (na, nb_) = (cs.grid.node_at(&a), cs.grid.node_at(&b));
            let (Some(na), Some(nb_)) = (na, nb_) else {
                panic!("waypoints on the grid")
            };
            assert!(crate::plan::shorten::inspected_nodes(na, nb_)
                .iter()
                .all(|&q| cs.is_free(q)));
        }
    }

    #[test]
    fn waypoints_carry_six_axes_and_the_wrist_turns_with_the_legs_progress() {
        // Three points on a free grid; the wrist differs at each. Each leg is one diagonal run
        // merged into one move, so force vias with a band like Fig. 6 on leg 1.
        let g = Grid::over([[0.0, 10.0], [0.0, 5.0], [0.0, 0.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| (2 * n[1] - n[0]).abs() <= 1);
        let model = open_model();
        let pts = [
            point("P", [0.0, 0.0, 0.0], [0.0, 30.0, 0.0]),
            point("Q", [10.0, 5.0, 0.0], [0.0, 30.0, 100.0]),
            point("R", [10.0, 5.0, 0.0], [5.0, 30.0, 100.0]),
        ];
        let p = plan(&cs, &model, &pts, Method::Neighboring).expect("plans");
        assert_eq!(p.legs.len(), 2);
        assert_eq!(p.legs[0].waypoints, 0..11);
        assert_eq!(p.legs[1].waypoints, 10..12, "the same axes 1..3: one move");
        assert_eq!(p.waypoints[0].kind, WaypointKind::CellPoint(0));
        assert_eq!(p.waypoints[3].kind, WaypointKind::Via { leg: 0, index: 3 });
        assert_eq!(p.waypoints[10].kind, WaypointKind::CellPoint(1));
        assert_eq!(p.waypoints[11].kind, WaypointKind::CellPoint(2));
        // Vias get the wrist schedule: the saw-tooth runs (0,0) (1,0) (2,1) (3,1) ... (9,4)
        // (10,5); a via at (x, y) projects onto the leg's line (10, 5) at s = (10 x + 5 y) / 125
        // and axis 6 turns to 100 s: (3,1) at s = 0.28, (9,4) at s = 0.88. Cell points keep
        // their own wrists.
        assert_eq!(p.waypoints[3].joints_deg, [3.0, 1.0, 0.0, 0.0, 30.0, 28.0]);
        assert_eq!(p.waypoints[9].joints_deg, [9.0, 4.0, 0.0, 0.0, 30.0, 88.0]);
        assert_eq!(p.waypoints[10].joints_deg[3..], [0.0, 30.0, 100.0]);
        // Every move interpolates all six axes: the moves the plan proved.
        for (a, b) in p.moves6() {
            assert!(model.move_is_safe(&a, &b));
        }
        assert_eq!(
            p.waypoints[11].joints_deg,
            [10.0, 5.0, 0.0, 5.0, 30.0, 100.0]
        );
        assert_eq!(p.moves(), 11);
    }

    /// The real IRB 1400 with the torch among a table, a post and a beam, and walls in the x-z
    /// plane in front of and behind it, too high to pass over, that cut its free space into a
    /// half at axis 1 > 0 and one at axis 1 < 0; its grid at 3 deg in front of the robot.
    fn split_cell() -> (CollisionModel, CSpace) {
        use crate::cell::Obstacle;
        use crate::geometry::{Aabb, Point};
        let bx = |name: &str, min: [f64; 3], max: [f64; 3]| {
            Obstacle::new(name, Aabb::new(Point::from(min), Point::from(max)))
        };
        let boxes = vec![
            bx("table", [600.0, -900.0, 0.0], [1500.0, 900.0, 500.0]),
            bx("post", [900.0, 200.0, 500.0], [1050.0, 360.0, 1250.0]),
            bx("beam", [500.0, -900.0, 1500.0], [1400.0, -600.0, 1600.0]),
            bx("front", [380.0, -20.0, 0.0], [2500.0, 20.0, 3000.0]),
            bx("back", [-2500.0, -20.0, 0.0], [-380.0, 20.0, 3000.0]),
        ];
        let tool = crate::collision::tool_tests::torch();
        let placement = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        let model = CollisionModel::new(&Robot::irb1400(), placement, boxes, 10.0, Some(&tool));
        let g = Grid::over([[-45.0, 45.0], [-30.0, 51.0], [-30.0, 60.0]], 3.0);
        let cs = CSpace::build(g, &model.grid_check(g.step_deg));
        (model, cs)
    }

    #[test]
    fn legs_planned_at_once_give_the_route_leg_by_leg_and_the_first_failing_legs_error() {
        let (model, cs) = split_cell();
        assert_eq!(legs_at_once(&cs, &model), LEGS_AT_ONCE_MAX);
        // Axis 1 > 0: one half; the third and fourth points turn the wrist in place.
        let a = point("A", [30.0, -6.0, -9.0], [0.0, 30.0, 0.0]);
        let b = point("B", [39.0, 21.0, -21.0], [10.0, 35.0, 20.0]);
        let c = point("C", [42.0, 21.0, 12.0], [0.0, 30.0, 0.0]);
        let c2 = point("C2", [42.0, 21.0, 12.0], [0.0, 30.0, 30.0]);
        let d = point("D", [39.0, -24.0, 0.0], [-10.0, 25.0, 0.0]);
        // Axis 1 < 0: the other half.
        let e = point("E", [-30.0, 9.0, 0.0], [0.0, 30.0, 0.0]);
        let f = point("F", [-39.0, -6.0, 12.0], [0.0, 30.0, -20.0]);
        for p in [&a, &b, &c, &c2, &d, &e, &f] {
            assert!(model.is_free(&p.joints_deg), "{} blocked", p.name);
        }
        for method in Method::ALL {
            let pts = [&a, &b, &c, &c2, &d, &b, &a].map(Clone::clone);
            let one = route_on(&cs, &model, &pts, method, 1);
            let two = route_on(&cs, &model, &pts, method, 2);
            let (one, two) = match (one, two) {
                (Ok(one), Ok(two)) => (one, two),
                // Depth-first may find no path (paper Fig. 8): then both alike.
                (Err(x), Err(y)) if method == Method::DepthFirst => {
                    assert_eq!(format!("{x:?}"), format!("{y:?}"), "{method}");
                    continue;
                }
                (x, y) => panic!("{method}: {x:?} against {y:?}"),
            };
            assert_eq!(one.legs.len(), 6, "{method}");
            assert_eq!(one.waypoints, two.waypoints, "{method}");
            assert_eq!(
                format!("{:?}", one.legs),
                format!("{:?}", two.legs),
                "{method}"
            );
            // Each leg is the leg planned alone, in its place.
            for (i, leg) in one.legs.iter().enumerate() {
                let alone = route_on(&cs, &model, &pts[i..i + 2], method, 1).expect("alone");
                let six = |w: &[Waypoint]| w.iter().map(|w| w.joints_deg).collect::<Vec<_>>();
                assert_eq!(
                    six(&one.waypoints[leg.waypoints.clone()]),
                    six(&alone.waypoints)
                );
                assert_eq!(leg.grid_path, alone.legs[0].grid_path);
            }
        }
        // Legs 1 (B -> E) and 3 (F -> C) cross the walls: the error names leg 1, whether the
        // legs are planned one at a time or two.
        let pts = [&a, &b, &e, &f, &c, &d].map(Clone::clone);
        let fails: Vec<usize> = (0..pts.len() - 1)
            .filter(|&i| route_on(&cs, &model, &pts[i..i + 2], Method::Extensile, 1).is_err())
            .collect();
        assert_eq!(fails, [1, 3], "the legs that cross the walls");
        for at_once in [1, 2] {
            match route_on(&cs, &model, &pts, Method::Extensile, at_once) {
                Err(e @ PlanError::NoPath { from: 1, to: 2, .. }) => {
                    assert!(e.to_string().contains("from 'B' to 'E'"), "{e}");
                }
                other => panic!("{at_once} at once: {other:?}"),
            }
        }
    }

    #[test]
    fn a_route_proven_again_is_certified_as_by_certify_and_one_through_a_wall_is_not() {
        let (model, cs) = split_cell();
        let a = point("A", [30.0, -6.0, -9.0], [0.0, 30.0, 0.0]);
        let b = point("B", [39.0, 21.0, -21.0], [10.0, 35.0, 20.0]);
        let c = point("C", [42.0, 21.0, 12.0], [0.0, 30.0, 0.0]);
        let route = route_on(&cs, &model, &[a, b, c], Method::Extensile, 1).expect("planned");
        let once = certify(route.clone(), &model);
        let again = certify_proven(route.clone(), &model).expect("every move proven");
        assert!(once.min_clearance.is_some());
        assert_eq!(again.move_clearances, once.move_clearances);
        assert_eq!(again.min_clearance, once.min_clearance);
        // The last point moved to the other side of the walls (E of the test above): its move
        // crosses them.
        let mut through = route;
        let last = through.waypoints.len() - 1;
        through.waypoints[last].joints_deg = [-30.0, 9.0, 0.0, 0.0, 30.0, 0.0];
        assert!(certify_proven(through, &model).is_none());
    }

    #[test]
    fn legs_are_handed_out_longest_first() {
        let w = [0.0, 30.0, 0.0];
        let pts = [
            point("A", [30.0, -6.0, -9.0], w),
            point("B", [39.0, 21.0, -21.0], w), // A -> B: most 27 (axis 2), in all 48
            point("E", [-30.0, 9.0, 0.0], w),   // B -> E: most 69
            point("F", [-39.0, -6.0, 12.0], w), // E -> F: most 15
            point("C", [42.0, 21.0, 12.0], w),  // F -> C: most 81
            point("G", [42.0, -6.0, 0.0], w),   // C -> G: most 27, in all 39
            point("H", [42.0, 21.0, 0.0], w),   // G -> H: most 27, in all 27
            point("I", [42.0, 48.0, 0.0], w),   // H -> I: most 27, in all 27 (after G -> H)
        ];
        assert_eq!(longest_first(&pts), [3, 1, 0, 4, 5, 6, 2]);
        assert!(longest_first(&pts[..1]).is_empty());
    }

    #[test]
    fn a_wrist_turn_in_place_through_a_box_is_refused_naming_the_tool_shape() {
        use crate::cell::Obstacle;
        use crate::geometry::{Aabb, Point};
        let tool = crate::collision::tool_tests::torch();
        // The flange faces +x at the zero pose; the torch pointing ahead goes into the post,
        // tilted 60 deg up or down it clears it.
        let post = Obstacle::new(
            "post",
            Aabb::new(
                Point::new(1150.0, -20.0, 1100.0),
                Point::new(1250.0, 20.0, 1300.0),
            ),
        );
        let placement = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        let model =
            CollisionModel::new(&Robot::irb1400(), placement, vec![post], 10.0, Some(&tool));
        let g = Grid::over([[-2.0, 2.0], [-2.0, 2.0], [-2.0, 2.0]], 1.0);
        let cs = CSpace::build(g, &model.grid_check(1.0));
        let pts = [
            point("Up", [0.0, 0.0, 0.0], [0.0, -60.0, 0.0]),
            point("Down", [0.0, 0.0, 0.0], [0.0, 60.0, 0.0]),
        ];
        assert!(pts.iter().all(|p| model.is_free(&p.joints_deg)));
        match plan(&cs, &model, &pts, Method::Extensile) {
            Err(e @ PlanError::WristTurn { from: 0, to: 1, .. }) => {
                let msg = e.to_string();
                assert!(
                    msg.contains("from 'Up' to 'Down'")
                        && msg.contains("tool shape")
                        && msg.contains("obstacle 'post'"),
                    "{msg}"
                );
                assert_eq!(e.point(), 1);
            }
            other => panic!("{other:?}"),
        }
        // Turning about axis 6 instead keeps the torch up: one move.
        let pts = [
            point("Up", [0.0, 0.0, 0.0], [0.0, -60.0, 0.0]),
            point("Turned", [0.0, 0.0, 0.0], [0.0, -60.0, 90.0]),
        ];
        let p = plan(&cs, &model, &pts, Method::Extensile).expect("the wrist turns up there");
        assert_eq!(p.moves(), 1);
    }
}
