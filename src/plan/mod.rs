//! The plan stage: the route through the cell's points, leg by leg (paper section 4, applied to
//! A -> B -> ... -> F), as a [`Route`]: waypoints on six axes and legs, every move proven.
//!
//! For each leg ([`leg`]): join both points to the grid (a point on a node is that node; a point
//! off the grid joins the nearest usable node whose straight move to it is proven safe); search
//! the leg's graph with the chosen method ([`search`]): its nodes are the free grid nodes where
//! the tool (if any) is clear at the leg's wrist, its steps the neighbour steps whose straight
//! six-axis move is proven safe, and the walk back takes those steps only (on a wave numbered
//! over every step between usable nodes first, else over those steps only: `leg`), so the
//! search never runs out of steps (complete on its grid); for the extensile method shorten
//! recursively ([`shorten`]); merge collinear moves ([`merge`]); round the vias to the written
//! precision (0.001 deg; the cell points stay as placed) and prove every move again. The route starts at the first point, visits every
//! point in the cell's order, and each cell point is a waypoint exactly as given ([`route`]).
//! The smallest clearance along every move, and so along the whole route, is certified apart
//! ([`certify`] into a [`Certified`] route): the refine stage certifies only the route it keeps,
//! not the candidates it turns down.
//!
//! Beyond the paper, for speed only: the legs are independent (each a pure function of the grid,
//! the model, its two points and the method), so [`route`] plans two at once where the memory
//! of the second is small ([`legs_at_once`]), the longest first ([`longest_first`]), and puts
//! them together in order: the same route, and the same error (the first failing leg's), as leg
//! by leg.
//!
//! Axes 4..6: the grid is over axes 1..3 (the paper's lumped arm); a waypoint carries all six. A
//! cell point keeps its own wrist ([`PlacedPoint::joints_deg`]); a via gets the leg's wrist
//! schedule: the wrist turns in proportion to the leg's progress along axes 1..3
//! ([`leg::WristSchedule`]). Every move is proven on all six axes, links and tool shapes.
//!
//! Files: [`cspace`] (the grid, paper section 3; knows no geometry), [`wave`] (wave expansion),
//! [`search`] (the three methods, and [`Method`]), [`leg`] (one leg, the wrist schedule, the
//! leg's graph), [`shorten`], [`merge`]; [`motion`] the motion of each move (its speed and
//! zone, and the shape of its time estimate); `tests.rs` the paper's figures through this layer.

pub mod cspace;
pub mod direct;
mod lattice;
pub mod leg;
pub mod merge;
pub mod motion;
pub mod search;
pub mod shorten;
pub mod wave;

pub use direct::Legs;
pub use search::Method;

use crate::collision::{Blocked, CollisionModel, GridCheck};
/// The smallest clearance along a move, as a [`Certified`] route holds it (certified by the
/// collision model), and the part of the robot model it is about.
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
    /// Point `i`'s approach pose (a stop of the follow stage, `process`).
    Approach(usize),
    /// Point `i`'s retract pose (a stop of the follow stage, `process`).
    Retract(usize),
}

/// A waypoint of the route: where a move starts or ends.
#[derive(Clone, Debug, PartialEq)]
pub struct Waypoint {
    pub kind: WaypointKind,
    /// Controller values of axes 1..6, deg: a via's at the written precision, a cell point's as
    /// placed (a robtarget point's exact, `PlacedPoint::joints_deg`).
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
    /// Planned as its straight move, proven without the grid (beyond the paper: [`direct`]).
    pub straight: bool,
    /// Its waypoints in [`Route::waypoints`], both ends included (a leg shares its first
    /// waypoint with the previous leg's last).
    pub waypoints: Range<usize>,
}

/// The route through all points, the plan stage's result: every move proven to keep the
/// clearance ([`route`]), nothing measured or timed yet. Move `i` runs from waypoint `i` to
/// waypoint `i + 1`.
#[derive(Clone, Debug)]
pub struct Route {
    pub method: Method,
    /// The grid spacing it was planned on, deg.
    pub grid_deg: f64,
    /// Every waypoint in visiting order; the first is the first cell point, the last the last.
    pub waypoints: Vec<Waypoint>,
    pub legs: Vec<Leg>,
}

impl Route {
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

/// A route with the smallest clearance along every move certified ([`certify`]).
#[derive(Clone, Debug)]
pub struct Certified {
    pub route: Route,
    /// Per move, in move order: the certified smallest clearance along it (within
    /// [`MIN_CLEARANCE_TOL_MM`]), with the part (link or tool shape) and obstacle where it
    /// occurs; `None` without obstacles.
    pub clearances: Vec<Option<Clearance>>,
    /// The least of the moves' clearances; `None` without obstacles.
    pub least: Option<Clearance>,
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
            |a2, codes, own| {
                self.inspect_column_in(a2, codes, own, &slice, &mut memo, 0..a3_deg.len())
            },
        );
    }
    /// The slice's work once, then each column's runs that hold nodes of `part`
    /// (`collision::column`), the part copied out.
    fn inspect_slice_part(
        &self,
        a1_deg: f64,
        a2_deg: &[f64],
        a3_deg: &[f64],
        part: std::ops::Range<usize>,
        code: &mut [u8],
        column: &mut [u8],
    ) {
        let slice = self.slice(a1_deg, a3_deg);
        let mut memo = self.fixed_memo();
        let width = GridCheck::column_bytes(self);
        let mut whole = vec![0u8; a3_deg.len()];
        let len = part.len();
        cspace::each_column(a2_deg, len, width, code, column, |a2, codes, own| {
            self.inspect_column_in(a2, &mut whole, own, &slice, &mut memo, part.clone());
            codes.copy_from_slice(&whole[part.clone()]);
        });
    }
}

/// The smallest clearance along every move of `route` and along the whole route (the least of
/// the moves'), each certified within [`MIN_CLEARANCE_TOL_MM`] (`None` without obstacles). The
/// moves are certified on all cores (`crate::parallel`), each as alone.
pub fn certify(route: Route, model: &CollisionModel) -> Certified {
    let moves: Vec<_> = route.moves6().collect();
    let clearances = crate::parallel::map(&moves, |(a, b)| {
        model.min_clearance_along(a, b, MIN_CLEARANCE_TOL_MM)
    });
    with_clearances(route, clearances)
}

/// [`certify`], where every move of `route` is proven safe again
/// ([`CollisionModel::move_is_safe`]): each move proven, then certified, a move at a time on
/// all cores; `None` when a move is not proven (then no move started after it is proven or
/// certified).
pub fn certify_proven(route: Route, model: &CollisionModel) -> Option<Certified> {
    let moves: Vec<_> = route.moves6().collect();
    let failed = AtomicBool::new(false);
    let clearances = crate::parallel::map(&moves, |(a, b)| {
        if failed.load(Ordering::Relaxed) || !model.move_is_safe(a, b) {
            failed.store(true, Ordering::Relaxed);
            return None;
        }
        Some(model.min_clearance_along(a, b, MIN_CLEARANCE_TOL_MM))
    });
    let clearances: Option<Vec<_>> = clearances.into_iter().collect();
    Some(with_clearances(route, clearances?))
}

/// `route` with the smallest clearance of each move (`clearances`, one a move) and the least
/// of them (the first of equals).
fn with_clearances(route: Route, clearances: Vec<Option<Clearance>>) -> Certified {
    let least =
        clearances
            .iter()
            .flatten()
            .cloned()
            .reduce(|least, c| if c.mm < least.mm { c } else { least });
    Certified {
        route,
        clearances,
        least,
    }
}

/// The plan stage: the route through `points` (at least two), in order, on the inspected grid
/// `cs` of the collision model `model`, every move proven safe. Its clearances are measured
/// apart ([`certify`], a branch and bound over every move), only for a route that is written.
pub fn route(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[PlacedPoint],
    method: Method,
) -> Result<Route, PlanError> {
    route_with(cs, model, points, method, Legs::GridOnly)
}

/// [`route`], with `legs` saying which legs the grid plans: with [`Legs::StraightFirst`] a leg
/// whose straight move is proven is that move ([`direct`]) and the grid plans the others (none
/// of its nodes is read when every leg goes straight).
pub fn route_with(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[PlacedPoint],
    method: Method,
    legs: Legs,
) -> Result<Route, PlanError> {
    route_on(cs, model, points, method, legs, legs_at_once(cs, model))
}

/// [`route_with`] planning up to `at_once` grid legs at once (1: leg by leg; for tests and
/// benchmarks: the route is the same whatever `at_once`).
pub fn route_on(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[PlacedPoint],
    method: Method,
    legs: Legs,
    at_once: usize,
) -> Result<Route, PlanError> {
    for (i, p) in points.iter().enumerate() {
        if let Some(reason) = model.why_blocked(&p.joints_deg) {
            return Err(PlanError::PointBlocked {
                point: i,
                name: p.name.clone(),
                reason,
            });
        }
    }
    let straight = match legs {
        Legs::GridOnly => vec![false; points.len().saturating_sub(1)],
        Legs::StraightFirst => direct::proven_straight(model, points),
    };
    let grid = &cs.grid;
    // The grid's check only for a leg the grid plans (it copies the model).
    let grid_check = std::sync::OnceLock::new();
    let check = || grid_check.get_or_init(|| model.grid_check(grid.step_deg));
    let on_grid = |i: usize| !straight[i];
    let legs: Vec<usize> = if at_once > 1 {
        longest_first(points)
    } else {
        (0..points.len() - 1).collect()
    };
    let legs: Vec<usize> = legs.into_iter().filter(|&i| on_grid(i)).collect();
    // The legs on up to `at_once` threads. A leg after a failed one is not started (every leg
    // before the first failure is planned, whatever the order they are handed out in): the
    // error is the first failing leg's, as leg by leg.
    let first_failed = AtomicUsize::new(usize::MAX);
    let mut planned: Vec<Option<_>> = (0..points.len() - 1).map(|_| None).collect();
    let done = crate::parallel::map_on(at_once, &legs, |&i| {
        if i > first_failed.load(Ordering::Relaxed) {
            return None;
        }
        let leg = route_leg(cs, model, check(), points, i, method);
        if leg.is_err() {
            first_failed.fetch_min(i, Ordering::Relaxed);
        }
        Some(leg)
    });
    for (&i, leg) in legs.iter().zip(done) {
        planned[i] = leg;
    }
    let mut made = Joined::default();
    for (i, leg) in planned.into_iter().enumerate() {
        if straight[i] {
            let six = vec![points[i].joints_deg, points[i + 1].joints_deg];
            made.add_leg(i, Vec::new(), six, true);
            continue;
        }
        // A leg not started follows a failed one, whose error returned first: planned here
        // only if that ever did not hold.
        let (grid_path, six) = match leg {
            Some(leg) => leg?,
            None => route_leg(cs, model, check(), points, i, method)?,
        };
        made.add_leg(i, grid_path, six, false);
    }
    Ok(Route {
        method,
        grid_deg: grid.step_deg,
        waypoints: made.waypoints,
        legs: made.legs,
    })
}

/// The legs of the route through `points`, longest first: by the most any of axes 1..3 turns
/// between the leg's two points (the number of levels its waves need, which the leg's time
/// grows with), then by their summed turn, then in route order. Handed out in this order, the
/// long legs start first, so no long leg starts last while the other core idles (the
/// longest-processing-time rule of scheduling). The route is the same in any order.
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
            LegFailure::Search(SearchFailure::OnlyDiagonal | SearchFailure::WalkFailed { .. }) => {
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
/// merge, shortening and proofs; only its two walks back run side by side). The measurements
/// are in `benches/README.md`.
pub const LEGS_AT_ONCE_MAX: usize = 2;

/// The most memory the legs planned beside the first may hold, bytes ([`legs_at_once`]).
const LEGS_EXTRA_MAX_BYTES: usize = 64 << 20;

/// How many legs [`route`] plans at once: [`LEGS_AT_ONCE_MAX`] where the legs beside the first
/// hold at most [`LEGS_EXTRA_MAX_BYTES`], else one (leg by leg, one leg's memory at a
/// time). A leg in hand holds, per grid node, at most: its two waves' labels (2 bytes each,
/// `u16`, for a node-by-node wave; the row wave's residues take 2 bits, and the two waves
/// numbered together from both ends hold four sets of 2-bit residues while they gather the
/// shortest paths' nodes), their bit sets (the decided nodes and the candidates, with the
/// rows' words rounded up: up to 4 bits a node a wave; a node-by-node wave bounded from a floor
/// keeps its estimates in their place, a row wave's, then its 2-bit residues:
/// `wave/bounded.rs`) and its tool memo (2 bits with a tool,
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
struct Joined {
    waypoints: Vec<Waypoint>,
    legs: Vec<Leg>,
}

impl Joined {
    /// Adds leg `i` (point `i` to point `i + 1`) with its six-axis waypoints (both ends
    /// included, the ends the points as given); `straight`: planned without the grid.
    fn add_leg(&mut self, i: usize, grid_path: Vec<Node>, six: Vec<[f64; 6]>, straight: bool) {
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
            straight,
            waypoints: start..self.waypoints.len(),
        });
    }
}

#[cfg(test)]
mod tests;
