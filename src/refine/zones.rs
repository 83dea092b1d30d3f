//! Certified zones: which waypoints the robot may fly by.
//!
//! A waypoint asks for a fly-by zone when it is a via and `motion.via_zone` is not a stop point,
//! or when it is a cell point whose zone (its own `zone`, else `motion.zone`) is not a stop point
//! (a predefined zonedata with `finep`, i.e. `fine`; a zonedata the controller declares is taken
//! as a fly-by zone, since only the predefined ones are known here). It gets the zone only where
//! its corner triangle (the midpoint of the move into it, the waypoint, the midpoint of the move
//! out of it; `collision::corner`) is proven to keep the clearance; otherwise it is written
//! `fine`, and a cell point whose zone is dropped gets a warning. The first and last waypoints
//! are always `fine`: the route starts from a stop and ends at one (a point's own zone there is
//! dropped with a warning; `motion.zone` there is dropped silently, it is a default). Every
//! zoned corner's smallest clearance is certified and joins the route's, so the header's
//! smallest clearance covers everything the robot traverses.

use crate::collision::CollisionModel;
use crate::excerpt;
use crate::place::PlacedPoint;
use crate::plan::motion::is_stop_zone;
use crate::plan::{Clearance, Route, WaypointKind, MIN_CLEARANCE_TOL_MM};

/// The zone of a stop point.
pub const FINE: &str = "fine";

/// Whether a zone name asks for a fly-by: anything but a stop point (the one rule,
/// [`is_stop_zone`], which the time estimate reads too).
pub fn is_fly_by(zone: &str) -> bool {
    !is_stop_zone(zone)
}

/// The zone each waypoint asks for, `None` for a stop point (module doc); the first and last
/// ask for none.
pub fn wanted(route: &Route, points: &[PlacedPoint], via_zone: &str) -> Vec<Option<String>> {
    let n = route.waypoints.len();
    route
        .waypoints
        .iter()
        .enumerate()
        .map(|(k, w)| {
            if k == 0 || k + 1 >= n {
                return None;
            }
            let zone = match w.kind {
                WaypointKind::Via { .. } => via_zone,
                WaypointKind::CellPoint(i) => points.get(i).map_or(FINE, |p| &p.motion.zone),
                // The follow stage's stops: never a corner the plan stage sees.
                WaypointKind::Approach(_) | WaypointKind::Retract(_) => FINE,
            };
            is_fly_by(zone).then(|| zone.to_string())
        })
        .collect()
}

/// The proof of the corner at waypoint `k` (`0 < k < n - 1`).
pub fn corner_is_proven(route: &Route, model: &CollisionModel, k: usize) -> bool {
    let w = &route.waypoints;
    k > 0
        && k + 1 < w.len()
        && model.corner_is_safe(&w[k - 1].joints_deg, &w[k].joints_deg, &w[k + 1].joints_deg)
}

/// The zones [`certify_zones`] gives a route, and the warnings for stderr.
pub struct Zoning {
    /// The zone of the move into each waypoint, one a waypoint.
    pub zones: Vec<String>,
    pub warnings: Vec<String>,
}

/// Certifies the zones of `route` (module doc): the zone of the move into each waypoint and the
/// warnings for stderr. `explicit[i]`: cell point `i` gives its own `zone`.
pub fn certify_zones(
    route: &Route,
    model: &CollisionModel,
    points: &[PlacedPoint],
    explicit: &[bool],
    via_zone: &str,
) -> Zoning {
    let n = route.waypoints.len();
    let wanted = wanted(route, points, via_zone);
    // The corners that want a fly-by zone, proven on all cores (each alone).
    let asked: Vec<usize> = (0..n).filter(|&k| wanted[k].is_some()).collect();
    let mut proven = vec![false; n];
    let answers = crate::parallel::map(&asked, |&k| corner_is_proven(route, model, k));
    for (&k, ok) in asked.iter().zip(answers) {
        proven[k] = ok;
    }
    let mut warnings = Vec::new();
    let mut zones = vec![FINE.to_string(); n];
    for k in 0..n {
        let WaypointKind::CellPoint(i) = route.waypoints[k].kind else {
            if let Some(z) = &wanted[k] {
                if proven[k] {
                    zones[k] = z.clone();
                }
            }
            continue;
        };
        let Some(p) = points.get(i) else { continue };
        let own = &p.motion.zone;
        if k == 0 || k + 1 == n {
            if explicit.get(i).copied().unwrap_or(false) && is_fly_by(own) {
                warnings.push(format!(
                    "warning: point '{}' is the {} point: its zone {} is written fine (the route starts and ends at a stop point)",
                    p.name,
                    if k == 0 { "first" } else { "last" },
                    excerpt::value(own)
                ));
            }
            continue;
        }
        match &wanted[k] {
            None => zones[k] = own.clone(),
            Some(z) if proven[k] => zones[k] = z.clone(),
            Some(z) => warnings.push(format!(
                "warning: point '{}': the corner of its zone {} (between the midpoints of the moves into and out of it) could not be proven to keep the {} mm clearance; it is written fine",
                p.name,
                excerpt::value(z),
                model.clearance_mm()
            )),
        }
    }
    Zoning {
        zones,
        warnings: warnings
            .into_iter()
            .map(|w| excerpt::message(&w).into_owned())
            .collect(),
    }
}

/// `least`, a route's smallest clearance along its moves, with the smallest clearance over each
/// corner `zones` flies by folded in, in route order (a corner's replaces it only when smaller).
pub fn fold_corners(
    least: Option<Clearance>,
    route: &Route,
    zones: &[String],
    model: &CollisionModel,
) -> Option<Clearance> {
    let n = route.waypoints.len();
    // The zoned corners' smallest clearances, on all cores, folded in in their order.
    let zoned: Vec<usize> = (1..n.saturating_sub(1))
        .filter(|&k| zones.get(k).is_some_and(|z| is_fly_by(z)))
        .collect();
    let w = &route.waypoints;
    let corners = crate::parallel::map(&zoned, |&k| {
        model.min_clearance_over_corner(
            &w[k - 1].joints_deg,
            &w[k].joints_deg,
            &w[k + 1].joints_deg,
            MIN_CLEARANCE_TOL_MM,
        )
    });
    let mut least = least;
    for mut c in corners.into_iter().flatten() {
        // The corner is proven to keep the clearance: a bound below it (a search budget
        // spent) is raised to it, still a certified lower bound.
        c.mm = c.mm.max(model.clearance_mm());
        if least.as_ref().is_none_or(|m| c.mm < m.mm) {
            least = Some(c);
        }
    }
    least
}
