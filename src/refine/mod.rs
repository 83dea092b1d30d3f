//! The refine stage (beyond the paper): from the plan stage's [`Route`] to the [`Plan`] the
//! module writes. With `planner.shortcut` (on by default) a continuous shortcut pass
//! ([`shortcut`]) makes shorter candidates; every candidate's zones at the waypoints are
//! certified ([`zones`], `motion.via_zone` and the cell points' own zones), with the vias whose
//! corner comes too close split for room ([`split`]); the fastest candidate wins. Every move it
//! writes is proven on the written (rounded) values; every zone it writes has its corner
//! triangle proven (`collision::corner`).
//!
//! The chain of types, each a stage's result and the next one's input:
//!
//! ```text
//! Route (plan::route)
//!   -> Certified (plan::certify: each move's clearance, the least)
//!   -> zones (zones::certify_zones: the zone into each waypoint; fold_corners: the least)
//!   -> Estimate (the time function: each move's time, profile, limit; the total)
//!   -> Plan (one Move a move: motion, clearance, estimate; the least; the total; the paper's)
//! ```
//!
//! It knows no time model: the caller hands it the time estimate as a function of a route and
//! the motion into each waypoint (the time stage, `timing`, lies to its left), called once per
//! candidate; the winner's estimate is the plan's. A change inside the passes is kept only when
//! that estimate does not grow. The paper's method alone is timed here too ([`paper_figure`]),
//! the figure the plan is measured against, when the route is the paper's (`Route::paper_alone`).
//!
//! A candidate route is certified only when it is proven again on the cell's model; the plan
//! stage's route (proven as it was planned) is certified once, only if a candidate keeps it.

pub mod shortcut;
pub mod split;
pub mod zones;

use crate::cell::Frame;
use crate::collision::CollisionModel;
use crate::place::{MoveMotion, PlacedPoint};
use crate::plan::motion::{self, Estimate, MoveEstimate, VIA_ZONE};
use crate::plan::{self, Certified, Clearance, Route, WaypointKind};
use crate::robot::ik::follow::FollowedPath;
use crate::robot::ik::six::ConfData;
use std::sync::Arc;

/// What the refine stage needs besides the route.
pub struct Settings<'a> {
    /// Run the shortcut pass (`planner.shortcut`, `--no-shortcut`; `compare` asks for it).
    pub shortcut: bool,
    /// `motion.via_zone`.
    pub via_zone: &'a str,
    /// Per cell point: it gives its own `zone` (for the warnings of [`zones`]).
    pub explicit_zone: Vec<bool>,
}

/// The time estimate the stage is handed: a route's time with the speed and zone of the move
/// into each waypoint (`timing::estimate` with the robot's time model).
pub type TimeFn<'a> = dyn Fn(&Route, &[MoveMotion]) -> Estimate + 'a;

/// How a move runs: a straight joint move (planned through the air), or a process move the
/// follow stage (`process`) followed and proved along its TCP path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MoveKind {
    /// Joint interpolation (`MoveAbsJ`, `MoveJ`).
    Joint,
    /// A `move: linear` line (`MoveL`).
    Linear,
    /// A `move: circular` arc (`MoveC`) through its circle point: `via`, the numbers the module
    /// writes (in the frame of the point's robtarget: the via position, the orientation at its
    /// arc fraction), in `via_conf`, the configuration of the followed joints there.
    Circular { via: Frame, via_conf: ConfData },
    /// The approach line into a point, from `dz_mm` back along its tool's z axis (`MoveL`);
    /// `own`: the approach pose's own robtarget, where its configuration is not the point's.
    Approach { dz_mm: f64, own: Option<OwnTarget> },
    /// The retract line out of a point, `dz_mm` back along its tool's z axis (`MoveL`); `own`:
    /// the retract pose's own robtarget, where its configuration is not the point's.
    Retract { dz_mm: f64, own: Option<OwnTarget> },
}

/// An approach or retract pose written as a robtarget of its own (`<point>_app`,
/// `<point>_ret`) because the controller reaches it in another configuration than its point:
/// the numbers written (in the frame of the point's robtarget) and its confdata.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OwnTarget {
    pub pose: Frame,
    pub conf: ConfData,
}

impl MoveKind {
    /// The name the report and templates use.
    pub fn name(&self) -> &'static str {
        match self {
            MoveKind::Joint => "joint",
            MoveKind::Linear => "linear",
            MoveKind::Circular { .. } => "circular",
            MoveKind::Approach { .. } => "approach",
            MoveKind::Retract { .. } => "retract",
        }
    }
}

/// One move of the plan, from waypoint `i` to waypoint `i + 1` of its route: everything the
/// module, the report and the pictures say of it.
#[derive(Clone, Debug)]
pub struct Move {
    /// How it runs.
    pub kind: MoveKind,
    /// Its speeddata and zonedata (the zone: the one certified at the waypoint it ends at).
    pub motion: MoveMotion,
    /// The certified smallest clearance along it (within [`plan::MIN_CLEARANCE_TOL_MM`]), with
    /// the part and obstacle where it occurs; `None` without obstacles.
    pub clearance: Option<Clearance>,
    /// Its estimated time, profile and limit.
    pub estimate: MoveEstimate,
    /// A process move's TCP path and the joints the controller runs along it (the follow
    /// stage's samples, what was proven); `None` for a straight joint move.
    pub path: Option<Arc<FollowedPath>>,
}

/// The route as the module writes it: every move proven, certified and timed, every zone
/// certified. Nothing in it waits for a later stage.
#[derive(Clone, Debug)]
pub struct Plan {
    pub route: Route,
    /// The motion of the move into the first waypoint, from wherever the robot stands: the first
    /// point's speed and a stop point (not part of the route: neither proven nor timed).
    pub into_first: MoveMotion,
    /// The route's moves in order, one record each.
    pub moves: Vec<Move>,
    /// The certified smallest clearance along the whole route, its moves and its zoned corners;
    /// `None` without obstacles.
    pub least: Option<Clearance>,
    /// The manipulation time, the sum of the moves', s.
    pub total_s: f64,
    /// The paper's method alone on the same cell; `None` when the route is not the paper's
    /// (a leg gone straight without the grid: `plan::direct`), whose method then did not run.
    pub paper: Option<PaperFigure>,
}

impl Plan {
    /// The motion of the move into each waypoint, in order (one a waypoint).
    pub fn motions(&self) -> impl Iterator<Item = &MoveMotion> + '_ {
        std::iter::once(&self.into_first).chain(self.moves.iter().map(|m| &m.motion))
    }

    /// The zoned vias: `(zoned, vias)`, the number of vias whose move in has a fly-by zone and
    /// the number of all vias.
    pub fn zoned_vias(&self) -> (usize, usize) {
        let vias: Vec<&MoveMotion> = (self.route.waypoints.iter())
            .zip(self.motions())
            .filter(|(w, _)| matches!(w.kind, WaypointKind::Via { .. }))
            .map(|(_, m)| m)
            .collect();
        let zoned = vias.iter().filter(|m| zones::is_fly_by(&m.zone)).count();
        (zoned, vias.len())
    }
}

/// The route of the paper's method alone (search, shortening, merge, every via a stop point) and
/// its estimated time: the figure a refined route is measured against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperFigure {
    pub moves: usize,
    pub time_s: f64,
}

/// The refined plan and the warnings for stderr (a point's zone written `fine`).
pub struct Refined {
    pub plan: Plan,
    pub warnings: Vec<String>,
}

/// The extra clearance of the shortcut pass's second candidate, mm (module doc).
pub const MARGIN_MM: f64 = 5.0;

/// The refine stage (module doc): `route` is the plan stage's, made from `points` on `model`;
/// `time` estimates a route's time.
pub fn refine(
    route: Route,
    model: &CollisionModel,
    points: &[PlacedPoint],
    settings: &Settings,
    time: &TimeFn,
) -> Refined {
    let paper = route
        .paper_alone()
        .then(|| paper_figure(&route, model, points, time));
    let all = match settings.shortcut {
        true => candidates(&route, model, points, settings.via_zone, time),
        false => vec![route.clone()],
    };
    // The plan stage's route certified once, and only if a candidate keeps it.
    let mut paper_certified: Option<Certified> = None;
    let mut as_paper = |r: Route| {
        let p = paper_certified.get_or_insert_with(|| plan::certify(route.clone(), model));
        Certified {
            route: r,
            clearances: p.clearances.clone(),
            least: p.least.clone(),
        }
    };
    let mut best: Option<(usize, Refined)> = None;
    for c in all {
        // Every move proven again on the cell's model (and then certified), or the plan
        // stage's route stays (proven as it was planned).
        let certified = if c.waypoints == route.waypoints {
            as_paper(c)
        } else {
            match plan::certify_proven(c, model) {
                Some(c) => c,
                None => as_paper(route.clone()),
            }
        };
        let r = finish(certified, model, points, settings, time, paper);
        let z = (r.plan.moves.iter())
            .filter(|m| zones::is_fly_by(&m.motion.zone))
            .count();
        if best.as_ref().is_none_or(|(bz, b)| {
            r.plan.total_s < b.plan.total_s || (r.plan.total_s == b.plan.total_s && z > *bz)
        }) {
            best = Some((z, r));
        }
    }
    match best {
        Some((_, r)) => r,
        // No candidate: never (there is one at least).
        None => finish(
            as_paper(route.clone()),
            model,
            points,
            settings,
            time,
            paper,
        ),
    }
}

/// The shortcut pass's candidates (module doc): A, the shortest route the proofs allow; B (a
/// fly-by zone asked anywhere), the same pass keeping [`MARGIN_MM`] more clearance, which leaves
/// room for the corners, and the plan stage's route (on a tie in time, the most zoned corners
/// win); with a fly-by `via_zone`, each also with its tight via corners split (`split`).
fn candidates(
    route: &Route,
    model: &CollisionModel,
    points: &[PlacedPoint],
    via_zone: &str,
    time: &TimeFn,
) -> Vec<Route> {
    // The shortcut pass times its routes with their motions as planned, the split pass with
    // the zones it tries.
    let planned_s = |r: &Route| time(r, &motion::planned(r, points)).total_s;
    let zoned_s = |r: &Route, zones: &[String]| time(r, &motion::motions(r, points, zones)).total_s;
    let mut candidates = vec![shortcut::shortcut(route.clone(), model, &planned_s)];
    let fly_by =
        zones::is_fly_by(via_zone) || points.iter().any(|p| zones::is_fly_by(&p.motion.zone));
    if fly_by {
        let margined = model.with_margin(MARGIN_MM);
        candidates.push(shortcut::shortcut(route.clone(), &margined, &planned_s));
        candidates.push(route.clone());
    }
    let split_vias = zones::is_fly_by(via_zone);
    let mut all = Vec::new();
    for c in candidates {
        if split_vias {
            let s = split::split_corners(c.clone(), model, points, via_zone, &zoned_s);
            if s.waypoints != c.waypoints {
                all.push(s);
            }
        }
        all.push(c);
    }
    all
}

/// The paper's method alone as the module would write it, timed: its route with every via a
/// stop point ([`VIA_ZONE`]) and a cell point's own fly-by zone only where its corner is proven
/// (the rule of [`zones`]).
pub fn paper_figure(
    route: &Route,
    model: &CollisionModel,
    points: &[PlacedPoint],
    time: &TimeFn,
) -> PaperFigure {
    let zoning = zones::certify_zones(route, model, points, &[], VIA_ZONE);
    let estimate = time(route, &motion::motions(route, points, &zoning.zones));
    PaperFigure {
        moves: route.moves(),
        time_s: estimate.total_s,
    }
}

/// A certified candidate made a plan: its zones certified (their corners' clearances folded into
/// the least), its moves' motions and its estimate (the one call of `time` for it).
fn finish(
    certified: Certified,
    model: &CollisionModel,
    points: &[PlacedPoint],
    settings: &Settings,
    time: &TimeFn,
    paper: Option<PaperFigure>,
) -> Refined {
    let Certified {
        route,
        clearances,
        least,
    } = certified;
    let zoning = zones::certify_zones(
        &route,
        model,
        points,
        &settings.explicit_zone,
        settings.via_zone,
    );
    let least = zones::fold_corners(least, &route, &zoning.zones, model);
    let motions = motion::motions(&route, points, &zoning.zones);
    let estimate = time(&route, &motions);
    let mut motions = motions.into_iter();
    let into_first = motions.next().unwrap_or(MoveMotion {
        speed: String::new(),
        zone: String::new(),
    });
    let moves = motions
        .zip(clearances)
        .zip(estimate.moves)
        .map(|((motion, clearance), estimate)| Move {
            kind: MoveKind::Joint,
            motion,
            clearance,
            estimate,
            path: None,
        })
        .collect();
    Refined {
        plan: Plan {
            route,
            into_first,
            moves,
            least,
            total_s: estimate.total_s,
            paper,
        },
        warnings: zoning.warnings,
    }
}

#[cfg(test)]
mod tests {
    //! The plan's records against the stages computed anew on the plan's own route: the time
    //! stage on its motions, `plan::certify` on its moves, the zones on its corners.
    use super::*;
    use crate::pipeline;
    use crate::plan::Method;
    use crate::timing;
    use std::cell::Cell;
    use std::path::Path;

    #[test]
    fn the_plan_holds_the_winners_estimate_and_each_move_its_own_records() {
        let path = format!("{}/cells/trunk.yaml", env!("CARGO_MANIFEST_DIR"));
        let mut job = pipeline::load(Path::new(&path)).expect("the trunk cell loads");
        // Fly-by vias where their corners are proven: zones differ from move to move.
        job.cell.motion.via_zone = "z50".into();
        let placed = pipeline::place(&job).expect("placed");
        let inspected = pipeline::inspect(&job, &placed, 2.0);
        let route = pipeline::route(&job, &placed, &inspected, Method::Extensile).expect("route");
        let time_model = timing::TimeModel::new(&job.robot, job.cell.tool.as_ref());
        let calls = Cell::new(0);
        let time = |r: &Route, m: &[MoveMotion]| {
            calls.set(calls.get() + 1);
            timing::estimate(r, m, &time_model)
        };
        for shortcut in [false, true] {
            let settings = Settings {
                shortcut,
                via_zone: "z50",
                explicit_zone: vec![false; placed.points.len()],
            };
            calls.set(0);
            let plan = refine(
                route.clone(),
                &inspected.model,
                &placed.points,
                &settings,
                &time,
            )
            .plan;
            if !shortcut {
                // The paper's figure and the one candidate: timed once each.
                assert_eq!(calls.get(), 2);
            }
            let w = &plan.route.waypoints;
            assert_eq!(plan.moves.len(), plan.route.moves());
            // The motion into each waypoint: the first and last stop, a via flies by exactly
            // where its corner is proven, a cell point keeps its own zone (`fine` on the trunk).
            let motions: Vec<MoveMotion> = plan.motions().cloned().collect();
            assert_eq!(motions.len(), w.len());
            assert_eq!(motions[0].zone, "fine");
            assert_eq!(motions[w.len() - 1].zone, "fine");
            for k in 1..w.len() - 1 {
                let fly_by = zones::is_fly_by(&motions[k].zone);
                match w[k].kind {
                    WaypointKind::Via { .. } => {
                        let proven = zones::corner_is_proven(&plan.route, &inspected.model, k);
                        assert_eq!(fly_by, proven, "via {k}");
                    }
                    WaypointKind::CellPoint(_)
                    | WaypointKind::Approach(_)
                    | WaypointKind::Retract(_) => assert!(!fly_by, "point {k}"),
                }
            }
            let (zoned, vias) = plan.zoned_vias();
            assert!(zoned > 0 && zoned <= vias, "{zoned} of {vias}");
            // The time of those motions, computed anew, is the plan's, move by move.
            let again = timing::estimate(&plan.route, &motions, &time_model);
            assert_eq!(again.total_s.to_bits(), plan.total_s.to_bits());
            let estimates: Vec<MoveEstimate> = plan.moves.iter().map(|m| m.estimate).collect();
            assert_eq!(again.moves, estimates);
            // Each move's clearance is the one `certify` finds on it; the least is at most
            // theirs (the zoned corners may come closer).
            let certified = plan::certify(plan.route.clone(), &inspected.model);
            let clearances: Vec<_> = plan.moves.iter().map(|m| m.clearance.clone()).collect();
            assert_eq!(clearances, certified.clearances);
            let (least, moves_least) = (plan.least.expect("obstacles"), certified.least);
            assert!(least.mm <= moves_least.expect("obstacles").mm);
            // Flying by never takes longer than the paper's route with its vias stopping.
            let paper = plan.paper.expect("the paper's route");
            assert!(plan.total_s <= paper.time_s, "{shortcut}");
            assert_eq!(paper.moves, route.moves());
        }
    }
}
