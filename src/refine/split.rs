//! Split corners (beyond the paper): room for a fly-by zone at a via whose corner triangle
//! comes too close to an obstacle.
//!
//! The corner triangle of via `V` between the moves `A -> V` and `V -> B` reaches to the
//! midpoints of both moves (`collision::corner`); where it cuts into the clearance (a via that
//! hugs an obstacle, as on `cells/gripper-pick.yaml`'s cabinet), the via keeps `fine`. This pass
//! inserts two vias `P = V + f (A - V)` and `Q = V + f (B - V)` on the two moves (axes 1..3
//! rounded to the written precision, axes 4..6 from the leg's wrist schedule as for every via,
//! which is affine in axes 1..3, so they lie on the moves up to the rounding), for `f` in
//! [`FRACTIONS`] in order: `V`'s corner
//! triangle then reaches only to the midpoints of the short moves `P -> V` and `V -> Q`, and the
//! corners at `P` and `Q` are thin triangles along the proven moves. A split is tried only where
//! the moves `A -> P`, `P -> V`, `V -> Q`, `Q -> B` and `V`'s new corner are proven on the
//! rounded values; it is kept only when the time estimate (with the zones each corner's proof
//! allows) goes down. `P` and `Q` are vias of `V`'s leg (renumbered in order, the later legs'
//! ranges shifted). Runs only where a fly-by `motion.via_zone` is asked. Deterministic: route
//! order, fixed fractions.

use super::shortcut::with_leg;
use super::zones::{self, FINE};
use crate::collision::CollisionModel;
use crate::place::PlacedPoint;
use crate::plan::leg::WristSchedule;
use crate::plan::{Route, Waypoint, WaypointKind};
use crate::precision::quantize_joints;

/// The fractions of the moves at which the new vias are tried, in order.
pub const FRACTIONS: [f64; 4] = [0.5, 0.25, 0.125, 0.0625];

/// The zone waypoint `k` of `route` gets (as [`zones::certify_zones`] gives it, without the
/// warnings): the one it asks for where its corner is proven, else its own.
fn zone_at(
    route: &Route,
    model: &CollisionModel,
    points: &[PlacedPoint],
    wanted: &[Option<String>],
    k: usize,
) -> String {
    match (&wanted[k], route.waypoints[k].kind) {
        (Some(z), _) if zones::corner_is_proven(route, model, k) => z.clone(),
        (None, WaypointKind::CellPoint(i)) if k > 0 && k + 1 < route.waypoints.len() => points
            .get(i)
            .map_or(FINE.to_string(), |p| p.motion.zone.clone()),
        _ => FINE.to_string(),
    }
}

/// The split pass (module doc); `time_s` estimates the time of a route whose waypoints have
/// the zones given (one a waypoint). The zones the pass works with are provisional: the caller
/// certifies the route's (`zones::certify_zones`).
pub fn split_corners(
    route: Route,
    model: &CollisionModel,
    points: &[PlacedPoint],
    via_zone: &str,
    time_s: &dyn Fn(&Route, &[String]) -> f64,
) -> Route {
    if !zones::is_fly_by(via_zone) {
        return route;
    }
    let wanted = zones::wanted(&route, points, via_zone);
    let zones: Vec<String> = (0..route.waypoints.len())
        .map(|k| zone_at(&route, model, points, &wanted, k))
        .collect();
    let mut best_s = time_s(&route, &zones);
    let mut best = (route, zones);
    let mut k = 1;
    while k + 1 < best.0.waypoints.len() {
        let WaypointKind::Via { leg, .. } = best.0.waypoints[k].kind else {
            k += 1;
            continue;
        };
        if zones::is_fly_by(&best.1[k]) {
            k += 1;
            continue;
        }
        let mut kept = false;
        for f in FRACTIONS {
            let Some(c) = split_at(&best, model, points, via_zone, k, leg, f) else {
                continue;
            };
            let t = time_s(&c.0, &c.1);
            if t < best_s {
                (best, best_s, kept) = (c, t, true);
                break;
            }
        }
        // Past `Q` (its corner is a thin triangle along a proven move, not split again).
        k += if kept { 3 } else { 1 };
    }
    best.0
}

/// `route` (with its `zones`) with via `k` (of leg `leg`) split at fraction `f` (module doc), its
/// zones updated around the split, or `None` where a new move or `V`'s new corner is not proven.
fn split_at(
    (route, zones): &(Route, Vec<String>),
    model: &CollisionModel,
    points: &[PlacedPoint],
    via_zone: &str,
    k: usize,
    leg: usize,
    f: f64,
) -> Option<(Route, Vec<String>)> {
    let w = &route.waypoints;
    let (a, v, b) = (w[k - 1].joints_deg, w[k].joints_deg, w[k + 1].joints_deg);
    // Axes 1..3 on the moves, axes 4..6 on the leg's wrist schedule, as every via's are (the
    // schedule is affine in axes 1..3 between its ends, so these lie on the moves up to the
    // rounding; what is proven is the rounded values).
    let range = route.legs[leg].waypoints.clone();
    let schedule = WristSchedule::new(&w[range.start].joints_deg, &w[range.end - 1].joints_deg);
    let on = |to: &[f64; 6]| {
        let x = lerp(&v, to, f);
        schedule.six(&quantize_joints([x[0], x[1], x[2]]))
    };
    let (p, q) = (on(&a), on(&b));
    if p == v || p == a || q == v || q == b {
        return None;
    }
    if !(model.move_is_safe(&a, &p)
        && model.move_is_safe(&p, &v)
        && model.move_is_safe(&v, &q)
        && model.move_is_safe(&q, &b)
        && model.corner_is_safe(&p, &v, &q))
    {
        return None;
    }
    let via = |joints_deg| Waypoint {
        kind: WaypointKind::Via { leg, index: 0 },
        joints_deg,
    };
    let mut new_leg: Vec<Waypoint> = w[range.clone()].to_vec();
    let at = k - range.start;
    new_leg.splice(at..at + 1, [via(p), w[k].clone(), via(q)]);
    let c = with_leg(route, leg, new_leg);
    // Zones: as before up to `A`, recomputed for `A, P, V, Q, B`, as before from past `B`.
    let wanted = zones::wanted(&c, points, via_zone);
    let mut z = zones[..k - 1].to_vec();
    z.extend((k - 1..k + 4).map(|j| zone_at(&c, model, points, &wanted, j)));
    z.extend_from_slice(&zones[k + 2..]);
    Some((c, z))
}

/// The point at fraction `t` of the way from `from` to `to`.
fn lerp(from: &[f64; 6], to: &[f64; 6], t: f64) -> [f64; 6] {
    std::array::from_fn(|i| from[i] + t * (to[i] - from[i]))
}
