//! The motion of each move: which speeddata and zonedata the move into a waypoint uses, for the
//! module and for the time estimate (both read it here, neither imports the other).
//!
//! The rule: the move into a cell point uses the point's own `speed`/`zone`, else the
//! cell's `motion.speed`/`motion.zone` (the place stage resolves that into
//! [`PlacedPoint::motion`]); the moves into a leg's vias use the speed of the leg's end point
//! (the leg is one job: reaching that point) and [`VIA_ZONE`], a stop point, since a fly-by
//! corner at a via is not proven to keep the clearance. Once the refine stage has
//! certified the corners ([`Plan::zones`], `refine::zones`), its zone of each waypoint is the
//! zone of the move into it: a via's `motion.via_zone` where its corner triangle is proven, a
//! cell point's own zone where its corner is proven (else `fine`), the first and last `fine`.
//! The first waypoint's "move into" is the move from wherever the robot stands to the first
//! point: the first point's motion. [`is_stop_zone`] says whether a zone stops the robot (the
//! time estimate flies through the others), [`Plan::zoned_vias`] counts the vias that fly by
//! (the header's `zoned vias`).

use super::{Plan, WaypointKind};
use crate::place::{MoveMotion, PlacedPoint};

/// The zone of every move into a via: a stop point.
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

impl Plan {
    /// The speed and zone of the move into waypoint `k` (module docs); `points` are the placed
    /// points the plan was made from.
    pub fn motion_into(&self, k: usize, points: &[PlacedPoint]) -> MoveMotion {
        let of = |i: usize| {
            points
                .get(i)
                .map(|p| p.motion.clone())
                .unwrap_or(MoveMotion {
                    speed: String::new(),
                    zone: String::new(),
                })
        };
        match self.waypoints.get(k).map(|w| w.kind) {
            Some(WaypointKind::CellPoint(i)) => MoveMotion {
                zone: self.zones.get(k).cloned().unwrap_or(of(i).zone),
                ..of(i)
            },
            Some(WaypointKind::Via { leg, .. }) => MoveMotion {
                speed: of(leg + 1).speed,
                zone: self
                    .zones
                    .get(k)
                    .cloned()
                    .unwrap_or_else(|| VIA_ZONE.to_string()),
            },
            None => of(usize::MAX),
        }
    }

    /// The zoned vias: `(zoned, vias)`, the number of vias whose move in has a fly-by zone
    /// ([`is_stop_zone`] false) and the number of all vias.
    pub fn zoned_vias(&self, points: &[PlacedPoint]) -> (usize, usize) {
        let vias: Vec<usize> = (0..self.waypoints.len())
            .filter(|&k| matches!(self.waypoints[k].kind, WaypointKind::Via { .. }))
            .collect();
        let zoned = vias
            .iter()
            .filter(|&&k| !is_stop_zone(&self.motion_into(k, points).zone))
            .count();
        (zoned, vias.len())
    }
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
    fn cell_points_keep_theirs_and_vias_take_the_legs_end_speed_and_fine() {
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
        let plan = Plan {
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
            min_clearance: None,
            move_clearances: Vec::new(),
            estimate: None,
            paper: None,
            zones: Vec::new(),
        };
        let got: Vec<(String, String)> = (0..kinds.len())
            .map(|k| {
                let m = plan.motion_into(k, &points);
                (m.speed, m.zone)
            })
            .collect();
        let want = [
            ("v300", "z10"),
            ("v100", "fine"),
            ("v100", "z5"),
            ("v2000", "fine"),
            ("v2000", "fine"),
            ("v2000", "fine"),
        ];
        assert_eq!(got, want.map(|(s, z)| (s.to_string(), z.to_string())));
        // Three vias, all `fine` today.
        assert_eq!(plan.zoned_vias(&points), (0, 3));
    }

    #[test]
    fn stop_zones_are_fine_and_other_names_fly_by() {
        assert!(is_stop_zone("fine") && is_stop_zone("FINE") && is_stop_zone(""));
        for z in ["z0", "z10", "Z50", "z200", "zMine"] {
            assert!(!is_stop_zone(z), "{z}");
        }
    }
}
