//! The refine stage (beyond the paper): after the paper's route is planned and timed,
//! a continuous shortcut pass ([`shortcut`], `planner.shortcut`, on by default) and the
//! certified zones at the waypoints ([`zones`], `motion.via_zone` and the cell points' own
//! zones), with the vias whose corner comes too close split for room ([`split`]). Every move it writes is proven on the written (rounded) values; every zone it
//! writes has its corner triangle proven (`collision::corner`).
//!
//! It knows no time model: the pipeline hands it the time estimate as a closure (the time stage,
//! `timing`, lies to its left), and a change is kept only when that estimate does not grow.

pub mod shortcut;
pub mod split;
pub mod zones;

use crate::collision::CollisionModel;
use crate::place::PlacedPoint;
use crate::plan::{self, Plan};

/// What the refine stage needs besides the plan.
pub struct Settings<'a> {
    /// Run the shortcut pass (`planner.shortcut`, `--no-shortcut`).
    pub shortcut: bool,
    /// `motion.via_zone`.
    pub via_zone: &'a str,
    /// Per cell point: it gives its own `zone` (for the warnings of [`zones`]).
    pub explicit_zone: Vec<bool>,
}

/// The refined plan and the warnings for stderr.
pub struct Refined {
    pub plan: Plan,
    pub warnings: Vec<String>,
}

/// Shortcut (when asked) and certified zones; `time_s` estimates a plan's manipulation time.
/// `plan` may come with its smallest clearances certified (`plan::plan`) or not
/// (`plan::route`): the plan returned has them certified, and a route no candidate keeps is
/// never certified. Clearances given are trusted (one a move): they must be those of `plan`'s
/// waypoints.
pub fn refine(
    plan: Plan,
    model: &CollisionModel,
    points: &[PlacedPoint],
    settings: &Settings,
    time_s: &dyn Fn(&Plan) -> f64,
) -> Refined {
    if !settings.shortcut {
        return zoned(certified(plan, model), model, points, settings);
    }
    let paper = plan.clone();
    // The paper's route certified once, and only if a candidate keeps it.
    let mut paper_certified: Option<Plan> = None;
    // A: the shortest route the proofs allow. B (a fly-by zone asked anywhere): the same pass
    // keeping [`MARGIN_MM`] more clearance, which leaves room for the corners. With a fly-by
    // `via_zone`, each also with its tight via corners split (`split`).
    let mut candidates = vec![shortcut::shortcut(plan.clone(), model, time_s)];
    let fly_by = zones::is_fly_by(settings.via_zone)
        || points.iter().any(|p| zones::is_fly_by(&p.motion.zone));
    if fly_by {
        let margined = model.with_margin(MARGIN_MM);
        candidates.push(shortcut::shortcut(plan, &margined, time_s));
        // The paper's route too: on a tie in time, the most zoned corners win.
        candidates.push(paper.clone());
    }
    // Each candidate also with its unproven via corners split (`split`), where vias fly by.
    let split_vias = zones::is_fly_by(settings.via_zone);
    let mut all = Vec::new();
    for c in candidates {
        if split_vias {
            let s = split::split_corners(c.clone(), model, points, settings.via_zone, time_s);
            if s.waypoints != c.waypoints {
                all.push(s);
            }
        }
        all.push(c);
    }
    let mut best: Option<(f64, usize, Refined)> = None;
    for c in all {
        // Every move proven again on the cell's model (and then certified), or the paper's
        // route stays (proven as it was planned).
        let proven = if c.waypoints == paper.waypoints {
            Err(c)
        } else {
            plan::certify_proven(c, model).ok_or_else(|| paper.clone())
        };
        let c = match proven {
            Ok(c) => c,
            Err(c) => {
                let p = paper_certified.get_or_insert_with(|| certified(paper.clone(), model));
                Plan {
                    move_clearances: p.move_clearances.clone(),
                    min_clearance: p.min_clearance.clone(),
                    ..c
                }
            }
        };
        let r = zoned(c, model, points, settings);
        let t = time_s(&r.plan);
        let z = r.plan.zones.iter().filter(|z| zones::is_fly_by(z)).count();
        if best
            .as_ref()
            .is_none_or(|(bt, bz, _)| t < *bt || (t == *bt && z > *bz))
        {
            best = Some((t, z, r));
        }
    }
    match best {
        Some((_, _, r)) => r,
        None => zoned(certified(paper, model), model, points, settings),
    }
}

/// `plan` with its smallest clearances certified ([`plan::certify`]), unless the caller
/// certified them already (a clearance per move: `plan::plan` does, `plan::route` does not).
fn certified(plan: Plan, model: &CollisionModel) -> Plan {
    if plan.move_clearances.len() == plan.moves() {
        plan
    } else {
        plan::certify(plan, model)
    }
}

/// The extra clearance of the shortcut pass's second candidate, mm (module doc).
pub const MARGIN_MM: f64 = 5.0;

/// `plan` with its zones certified.
fn zoned(
    mut plan: Plan,
    model: &CollisionModel,
    points: &[PlacedPoint],
    settings: &Settings,
) -> Refined {
    let warnings = zones::certify_zones(
        &mut plan,
        model,
        points,
        &settings.explicit_zone,
        settings.via_zone,
    );
    Refined { plan, warnings }
}
