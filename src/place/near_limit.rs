//! Axes 4 and 6 near their limits: a cell point whose written axis 4 or 6 lies within
//! [`NEAR_LIMIT_DEG`] of a limit of its range gets a warning (stderr) and a report entry naming
//! it. Such a point is valid and proven; the warning is for the programmer, who may later move on
//! from it (a weave, a reorientation, a touched-up target) and find the wrist against its stop,
//! and who can often choose another turn of the tool or other confdata.
//!
//! Only cell points are looked at: a via's axes 4..6 follow its leg's wrist schedule, a blend of
//! the leg's two points' values (README, "The output"), so no via is nearer a limit than the
//! nearer of its leg's points.

use super::Placed;
use crate::robot::Robot;

/// How near a limit (deg) an axis-4 or axis-6 value draws a warning (inclusive).
pub const NEAR_LIMIT_DEG: f64 = 20.0;

/// A written axis value near its limit.
#[derive(Clone, Debug, PartialEq)]
pub struct NearLimit {
    /// The cell point's name.
    pub point: String,
    /// 4 or 6.
    pub axis: usize,
    /// The written value, deg.
    pub value_deg: f64,
    /// The limit it is near, deg.
    pub limit_deg: f64,
    /// `|limit - value|`, deg.
    pub room_deg: f64,
}

impl NearLimit {
    /// The warning for stderr.
    pub fn warning(&self) -> String {
        format!(
            "warning: point '{}': axis {} = {:.3} deg is {:.3} deg from its limit {} deg; moving on from it (a reorientation, a touched-up target) may meet the stop: another turn of the tool about its z or other confdata may leave more room",
            self.point, self.axis, self.value_deg, self.room_deg, self.limit_deg
        )
    }
}

/// Every written axis-4 and axis-6 value of `placed`'s points within [`NEAR_LIMIT_DEG`] of a
/// limit of `robot`'s range, in point order, axis 4 before axis 6.
pub fn near_limits(placed: &Placed, robot: &Robot) -> Vec<NearLimit> {
    let mut out = Vec::new();
    for p in &placed.points {
        for axis in [4, 6] {
            let range = &robot.controller.axes[axis - 1];
            let value = p.joints_deg[axis - 1];
            let (room, limit) = match value - range.min_deg <= range.max_deg - value {
                true => (value - range.min_deg, range.min_deg),
                false => (range.max_deg - value, range.max_deg),
            };
            // A revisit has its point's name and joints: said once.
            let said = out
                .iter()
                .any(|n: &NearLimit| n.point == p.name && n.axis == axis);
            if room <= NEAR_LIMIT_DEG && !said {
                out.push(NearLimit {
                    point: p.name.clone(),
                    axis,
                    value_deg: value,
                    limit_deg: limit,
                    room_deg: room,
                });
            }
        }
    }
    out
}
