//! ABB confdata `[cf1, cf4, cf6, cfx]` of controller axis values.
//!
//! Source: the RAPID reference manual's `confdata` entry (ABB, Technical reference manual -
//! RAPID Instructions, Functions and Data types), as also quoted by public code (ARTE's
//! `compute_configuration.m`, RoboDK's ABB post processor, py-opw-kinematics'
//! `AXIS_CONFIGURATION.md`):
//! - cf1, cf4, cf6: the quadrant of axes 1, 4, 6, `floor(axis / 90 deg)`: 0 for 0 .. 90, 1 for
//!   90 .. 180, -1 for -90 .. 0, -2 for -180 .. -90; an axis of +-300 deg spans -4 .. 3.
//! - cfx, 0..7: `4 * (wrist centre behind axis 1) + 2 * (wrist centre behind the lower arm)
//!   + 1 * (axis 5 negative)`.
//!
//! # On a quadrant boundary: one rule
//! A solution of the inverse kinematics is a float: an axis the pose puts on a boundary comes
//! out a hair either side of it (`-1e-15` for 0, `179.99999999999997` for 180), and the module
//! writes it rounded to 0.001 deg (`0.000`, `180.000`). So:
//! - **The confdata of values** ([`SixAxisIk::conf`]) is that of the values *as written*: the
//!   quadrant of each of axes 1, 4, 6 rounded to [`JOINT_DECIMALS`] decimals (`-0` counting as
//!   0), and "axis 5 negative" of axis 5 rounded the same way. A robtarget's written confdata
//!   and its written joint values then always agree.
//! - **A value admitted for a quadrant** ([`SixAxisIk::conf_admits`], the choice by confdata): it
//!   lies within [`QUADRANT_TOL_DEG`] (half the written step) of the quadrant's closed interval
//!   `[90 cf, 90 (cf + 1)]`; axis 5 within it of its side of 0. A value on a boundary is admitted
//!   for both quadrants, so the confdata written for a pose (rounded, as above) and the one its
//!   unrounded solution has both choose that solution. No two solutions of one pose are confused
//!   by the tolerance: they differ by a full turn of an axis, by the wrist flip (axes 4 and 6 by
//!   half a turn) or in the cfx bits of the arm, each far beyond it (at the exact wrist
//!   singularity the flip is one solution anyway).
//!
//! Readings (the manual gives pictures, not formulas):
//! - **Behind axis 1**: the wrist centre's component along the arm's forward direction (the
//!   zero pose's direction from axis 1 to the wrist centre, normal to axes 1 and 2, turned by
//!   axis 1)
//!   is negative. Sources differ on where it is measured from: axis 1 itself, or axis 2 (on the
//!   IRB 1400, 150 mm further forward). [`CFX_BEHIND_AXIS_1_FROM`] is the one choice: **axis 1**,
//!   the manual's own words ("wrist centre relative to axis 1") and what py-opw-kinematics
//!   computes. With it this bit is exactly the stance the inverse kinematics chooses (reaching
//!   forward or over backwards), so each solution of a pose has its own cfx. Measured from axis 2
//!   instead, a forward stance with the wrist centre between axes 1 and 2 would share the bit
//!   with the backward stance. [`BehindAxis1From::Axis2`] stays available for comparison.
//! - **Behind the lower arm**: the wrist centre lies on the other side of the line axis 2 ->
//!   axis 3 than at the zero pose (the elbow bent the other way). On the IRB 1400 the coupled
//!   axis-3 range keeps it in front in every pose within the limits.
//! - **Axis 5 negative**: the controller value of axis 5, rounded as written, is below 0 (0
//!   counts as positive).
//! - On a boundary (the wrist centre exactly on axis 1's plane or on the lower arm's line) the
//!   wrist centre counts as in front; these are singular poses.
//!
//! MoveAbsJ ignores confdata; a robtarget's confdata only says which solution is meant. Some ABB
//! arms (the IRB 1400 among them) are said to use only cf1, cf4 and cf6 in the controller; cfx
//! still names the configuration a cell asks for.

use super::SixAxisIk;
use crate::precision::{round, JOINT_DECIMALS};
use crate::robot::Axes6;
use nalgebra::Rotation3;
use std::fmt;

/// Where "the wrist centre behind axis 1" is measured from (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BehindAxis1From {
    /// From the axis-1 line.
    Axis1,
    /// From the axis-2 line (ahead of axis 1 by the shoulder's forward offset).
    Axis2,
}

/// The one reading gen-rapid uses.
pub const CFX_BEHIND_AXIS_1_FROM: BehindAxis1From = BehindAxis1From::Axis1;

/// RAPID `confdata`, written `[cf1, cf4, cf6, cfx]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ConfData {
    pub cf1: i32,
    pub cf4: i32,
    pub cf6: i32,
    pub cfx: i32,
}

impl ConfData {
    /// From `[cf1, cf4, cf6, cfx]` as a robtarget writes it.
    pub fn from_array([cf1, cf4, cf6, cfx]: [i32; 4]) -> ConfData {
        ConfData { cf1, cf4, cf6, cfx }
    }

    /// `[cf1, cf4, cf6, cfx]`.
    pub fn to_array(self) -> [i32; 4] {
        [self.cf1, self.cf4, self.cf6, self.cfx]
    }
}

impl fmt::Display for ConfData {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "[{}, {}, {}, {}]",
            self.cf1, self.cf4, self.cf6, self.cfx
        )
    }
}

/// A value this close to a quadrant's closed interval is admitted for it, deg: half the step
/// of the written joint values (module docs, "On a quadrant boundary").
pub const QUADRANT_TOL_DEG: f64 = 0.0005;

/// `floor(axis / 90 deg)` of the value rounded as written (`-0` is 0: `floor(-0.0)` is `-0.0`,
/// which converts to 0).
pub(super) fn quadrant(axis_deg: f64) -> i32 {
    (round(axis_deg, JOINT_DECIMALS) / 90.0).floor() as i32
}

/// Whether `axis_deg` lies within [`QUADRANT_TOL_DEG`] of quadrant `cf`, `[90 cf, 90 (cf + 1)]`.
fn admitted(axis_deg: f64, cf: i32) -> bool {
    let lo = 90.0 * f64::from(cf);
    axis_deg >= lo - QUADRANT_TOL_DEG && axis_deg <= lo + 90.0 + QUADRANT_TOL_DEG
}

impl SixAxisIk {
    /// Whether controller values `axes_deg` are a solution of configuration `wanted` (module
    /// docs, "On a quadrant boundary"): axes 1, 4 and 6 each admitted for its quadrant, axis 5
    /// within [`QUADRANT_TOL_DEG`] of the side of 0 the cfx asks, and the wrist centre on the
    /// sides of axis 1 and the lower arm the cfx asks. A cfx outside 0..7 admits nothing.
    pub fn conf_admits(&self, axes_deg: &Axes6, wanted: ConfData) -> bool {
        let own = self.conf(axes_deg);
        let axis5 = axes_deg[4];
        let side5 = if wanted.cfx & 1 == 1 {
            axis5 <= QUADRANT_TOL_DEG
        } else {
            axis5 >= -QUADRANT_TOL_DEG
        };
        (0..8).contains(&wanted.cfx)
            && own.cfx & 6 == wanted.cfx & 6
            && side5
            && admitted(axes_deg[0], wanted.cf1)
            && admitted(axes_deg[3], wanted.cf4)
            && admitted(axes_deg[5], wanted.cf6)
    }

    /// The confdata of controller values under either reading of "behind axis 1".
    pub fn conf_with(&self, axes_deg: &Axes6, reading: BehindAxis1From) -> ConfData {
        let q = self.coupling.urdf_rad(axes_deg);
        let w = self.carry(&q, 3, self.wrist_zero);
        let shoulder = self.carry(&q, 1, self.shoulder);
        let elbow = self.carry(&q, 2, self.elbow);
        let turn1 = Rotation3::from_axis_angle(&self.axes[0].dir, q[0]);
        let forward = turn1 * self.forward_zero;
        let u2 = turn1 * self.axes[1].dir;
        let from = match reading {
            BehindAxis1From::Axis1 => self.axis1_foot,
            BehindAxis1From::Axis2 => shoulder,
        };
        let behind_axis1 = forward.dot(&(w - from)) < 0.0;
        let sigma = u2.dot(&(elbow - shoulder).cross(&(w - shoulder)));
        let behind_lower_arm = sigma * self.front_sign < 0.0;
        let axis5_negative = round(axes_deg[4], JOINT_DECIMALS) < 0.0;
        ConfData {
            cf1: quadrant(axes_deg[0]),
            cf4: quadrant(axes_deg[3]),
            cf6: quadrant(axes_deg[5]),
            cfx: 4 * i32::from(behind_axis1)
                + 2 * i32::from(behind_lower_arm)
                + i32::from(axis5_negative),
        }
    }
}
