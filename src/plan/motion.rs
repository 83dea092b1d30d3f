//! The motion of each move: which speeddata and zonedata the move into a waypoint uses, for the
//! module and for the time estimate (both read it here, neither imports the other), and the
//! shape of a move's estimated time ([`MoveEstimate`]: its time, its [`Profile`], its
//! [`Limit`]), which the time stage makes and the output reads.
//!
//! The rule: the move into a cell point uses the point's own `speed`/`zone`, else the cell's
//! `motion.speed`/`motion.zone` (the place stage resolves that into [`PlacedPoint::motion`]);
//! the moves into a leg's vias use the speed of the leg's end point (the leg is one job:
//! reaching that point). The zone of each waypoint is the one the caller gives ([`motions`]):
//! as planned ([`planned`]), a cell point's own and a via's [`VIA_ZONE`], a stop point, since
//! a fly-by corner is not proven there; once the refine stage has proven the corners
//! (`refine::zones`), the zones it certified (a via's `motion.via_zone` where its corner
//! triangle is proven, a cell point's own zone where its corner is proven, else `fine`, the
//! first and last `fine`). The first waypoint's "move into" is the move from wherever the robot
//! stands to the first point: the first point's motion. [`is_stop_zone`] says whether a zone
//! stops the robot (the time estimate flies through the others).

use super::{Route, WaypointKind};
use crate::place::{MoveMotion, PlacedPoint};

/// The zone of every move into a via as planned: a stop point.
pub const VIA_ZONE: &str = "fine";

/// Whether the robot comes to rest at the end of a move with zonedata `zone`: a predefined zone's
/// `finep`; a name RAPID does not predefine (data declared on the controller) is taken as a
/// fly-by zone unless it is `fine` (an empty name, which no move has, as a stop).
pub fn is_stop_zone(zone: &str) -> bool {
    match crate::rapid_data::predefined_zone(zone) {
        Some(z) => z.finep,
        None => zone.is_empty() || zone.eq_ignore_ascii_case("fine"),
    }
}

/// The speed and zone of the move into each waypoint of `route` as planned, before any corner
/// is proven: a cell point's own zone, a via's [`VIA_ZONE`] (module docs). `points` are the
/// placed points the route was made from.
pub fn planned(route: &Route, points: &[PlacedPoint]) -> Vec<MoveMotion> {
    (0..route.waypoints.len())
        .map(|k| {
            let zone = match route.waypoints[k].kind {
                WaypointKind::CellPoint(i)
                | WaypointKind::Approach(i)
                | WaypointKind::Retract(i) => point(points, i).zone,
                WaypointKind::Via { .. } => VIA_ZONE.to_string(),
            };
            MoveMotion {
                speed: speed_into(route, points, k),
                zone,
            }
        })
        .collect()
}

/// The speed and zone of the move into each waypoint of `route`, its zone `zones[k]` (one a
/// waypoint: the refine stage's certified zones) and its speed by the rule (module docs).
pub fn motions(route: &Route, points: &[PlacedPoint], zones: &[String]) -> Vec<MoveMotion> {
    (0..route.waypoints.len())
        .map(|k| MoveMotion {
            speed: speed_into(route, points, k),
            zone: zones.get(k).cloned().unwrap_or_default(),
        })
        .collect()
}

/// The speed of the move into waypoint `k`: a cell point's own, a via's the speed of its leg's
/// end point.
fn speed_into(route: &Route, points: &[PlacedPoint], k: usize) -> String {
    match route.waypoints[k].kind {
        WaypointKind::CellPoint(i) | WaypointKind::Approach(i) | WaypointKind::Retract(i) => {
            point(points, i).speed
        }
        WaypointKind::Via { leg, .. } => point(points, leg + 1).speed,
    }
}

/// The motion into placed point `i` (empty names for a point that is not there, which a route
/// made from `points` never names).
fn point(points: &[PlacedPoint], i: usize) -> MoveMotion {
    points.get(i).map_or(
        MoveMotion {
            speed: String::new(),
            zone: String::new(),
        },
        |p| p.motion.clone(),
    )
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

/// One move's estimated time (`timing`): from rest to rest, less what flying through a zoned
/// waypoint at either end saves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveEstimate {
    pub time_s: f64,
    /// How its progress runs in time (for pictures of the motion).
    pub profile: Profile,
    /// What set its stop-to-stop time: the axes, the TCP speed or the reorientation speed of
    /// its speeddata.
    pub limit: Limit,
}

/// The manipulation time of a route (paper section 5, with the speeddata and the fly-by at
/// zoned waypoints: `timing::estimate`).
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Per move, in move order.
    pub moves: Vec<MoveEstimate>,
    /// The sum of the moves' times, s.
    pub total_s: f64,
}

/// A placed point at the zero pose with this speed and zone (tests of the motion's readers).
#[cfg(test)]
pub(crate) fn point_with_motion(name: &str, speed: &str, zone: &str) -> PlacedPoint {
    PlacedPoint {
        name: name.into(),
        joints_deg: [0.0; 6],
        loc: crate::cell::Loc::default(),
        origin: crate::place::Origin::Joints,
        motion: MoveMotion {
            speed: speed.into(),
            zone: zone.into(),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::{Method, Waypoint};

    use super::point_with_motion as point;

    #[test]
    fn cell_points_keep_theirs_and_vias_take_the_legs_end_speed_and_the_zone_given() {
        let points = [
            point("A", "v300", "z10"),
            point("B", "v100", "z5"),
            point("C", "v2000", "fine"),
        ];
        let kinds = [
            WaypointKind::CellPoint(0),
            WaypointKind::Via { leg: 0, index: 1 },
            WaypointKind::CellPoint(1),
            WaypointKind::Via { leg: 1, index: 1 },
            WaypointKind::Via { leg: 1, index: 2 },
            WaypointKind::CellPoint(2),
        ];
        let route = Route {
            method: Method::Extensile,
            grid_deg: 1.0,
            waypoints: kinds
                .iter()
                .map(|&kind| Waypoint {
                    kind,
                    joints_deg: [0.0; 6],
                })
                .collect(),
            legs: Vec::new(),
        };
        let pairs = |m: Vec<MoveMotion>| -> Vec<(String, String)> {
            m.into_iter().map(|m| (m.speed, m.zone)).collect()
        };
        let want = |w: [(&str, &str); 6]| w.map(|(s, z)| (s.to_string(), z.to_string()));
        // As planned: a cell point's own zone, every via a stop point.
        let as_planned = want([
            ("v300", "z10"),
            ("v100", "fine"),
            ("v100", "z5"),
            ("v2000", "fine"),
            ("v2000", "fine"),
            ("v2000", "fine"),
        ]);
        assert_eq!(pairs(planned(&route, &points)), as_planned);
        // With certified zones: each waypoint's zone as given, the speeds by the same rule.
        let zones = ["fine", "z50", "fine", "z50", "fine", "fine"].map(String::from);
        let certified = want([
            ("v300", "fine"),
            ("v100", "z50"),
            ("v100", "fine"),
            ("v2000", "z50"),
            ("v2000", "fine"),
            ("v2000", "fine"),
        ]);
        assert_eq!(pairs(motions(&route, &points, &zones)), certified);
    }

    #[test]
    fn stop_zones_are_fine_and_other_names_fly_by() {
        assert!(is_stop_zone("fine") && is_stop_zone("FINE") && is_stop_zone(""));
        for z in ["z0", "z10", "Z50", "z200", "zMine"] {
            assert!(!is_stop_zone(z), "{z}");
        }
    }
}
