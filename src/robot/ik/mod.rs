//! Inverse kinematics: controller values for a position the cell gives.
//!
//! [`wrist`] solves axes 1..3 for a wrist-centre position in closed form (the paper's lumped
//! arm, section 3); [`six`] solves all six axes for a tool pose (all solutions, confdata, the chooser);
//! [`follow`] follows a TCP path (a process move's line or arc) with the solution that continues. This file holds what
//! they share: the branch names a cell may force, the solution type and the errors, each of
//! which says why (out of reach by how much, which axis out of range by how much, which link
//! hits which obstacle).

pub mod follow;
pub mod interval;
#[cfg(test)]
mod interval_tests;
pub mod six;
pub mod wrist;

pub use wrist::{choose, forward, reach_interval_mm, solve, ArmGeometry};

use crate::robot::{Axes3, RangeViolation};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// Which of the (up to) four solutions: axis 1 front/back, elbow up/down (see the module docs).
/// Deserializes from kebab-case (`front-elbow-up`), as the cell file's `branch:` key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Branch {
    FrontElbowUp,
    FrontElbowDown,
    BackElbowUp,
    BackElbowDown,
}

impl Branch {
    /// The order [`solve`] returns them in (also the last tie-break of [`choose`]).
    pub const ALL: [Branch; 4] = [
        Branch::FrontElbowUp,
        Branch::FrontElbowDown,
        Branch::BackElbowUp,
        Branch::BackElbowDown,
    ];

    pub(crate) fn of(front: bool, up: bool) -> Branch {
        match (front, up) {
            (true, true) => Branch::FrontElbowUp,
            (true, false) => Branch::FrontElbowDown,
            (false, true) => Branch::BackElbowUp,
            (false, false) => Branch::BackElbowDown,
        }
    }

    pub fn is_front(self) -> bool {
        matches!(self, Branch::FrontElbowUp | Branch::FrontElbowDown)
    }

    pub fn is_elbow_up(self) -> bool {
        matches!(self, Branch::FrontElbowUp | Branch::BackElbowUp)
    }

    /// The kebab-case name the cell file uses.
    pub fn name(self) -> &'static str {
        match self {
            Branch::FrontElbowUp => "front-elbow-up",
            Branch::FrontElbowDown => "front-elbow-down",
            Branch::BackElbowUp => "back-elbow-up",
            Branch::BackElbowDown => "back-elbow-down",
        }
    }

    pub(crate) fn index(self) -> usize {
        match self {
            Branch::FrontElbowUp => 0,
            Branch::FrontElbowDown => 1,
            Branch::BackElbowUp => 2,
            Branch::BackElbowDown => 3,
        }
    }
}

impl fmt::Display for Branch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Branch {
    type Err = String;
    fn from_str(s: &str) -> Result<Branch, String> {
        Branch::ALL
            .into_iter()
            .find(|b| b.name() == s)
            .ok_or_else(|| {
                format!(
                    "unknown branch `{s}`; expected one of front-elbow-up, front-elbow-down, \
                     back-elbow-up, back-elbow-down"
                )
            })
    }
}

/// One solution: controller values of axes 1..3, degrees, each in (-180, 180].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkSolution {
    pub branch: Branch,
    pub axes_deg: Axes3,
}

/// Why no solution was chosen. Positions in the robot base frame, mm.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum IkError {
    #[error("robot {robot} is not the ABB-like arm the closed-form IK handles: {message}")]
    Structure { robot: String, message: String },
    #[error("wrist centre {} is not a finite position", fmt_p(.wrist_mm))]
    NotFinite { wrist_mm: [f64; 3] },
    #[error(
        "wrist centre {} is out of reach: it is {front_mm:.1} mm from the shoulder \
         ({back_mm:.1} mm with axis 1 turned half a turn); the arm reaches {min_mm:.1} .. \
         {max_mm:.1} mm",
        fmt_p(.wrist_mm)
    )]
    Unreachable {
        wrist_mm: [f64; 3],
        front_mm: f64,
        back_mm: f64,
        min_mm: f64,
        max_mm: f64,
    },
    #[error(
        "no solution for wrist centre {} lies within the axis ranges: {}",
        fmt_p(.wrist_mm),
        fmt_violations(.violations)
    )]
    OutOfRange {
        wrist_mm: [f64; 3],
        violations: Vec<(Branch, RangeViolation)>,
    },
    /// Every solution in range is refused by the collision check: per solution, the branch and
    /// the check's reason (which link hits which obstacle).
    #[error(
        "every solution for wrist centre {} within the axis ranges collides ({}){}",
        fmt_p(.wrist_mm),
        fmt_branches(.blocked),
        fmt_reasons(.blocked)
    )]
    InCollision {
        wrist_mm: [f64; 3],
        blocked: Vec<(Branch, String)>,
    },
    #[error("wrist centre {}: the required branch {branch} {reason}", fmt_p(.wrist_mm))]
    ForcedBranch {
        wrist_mm: [f64; 3],
        branch: Branch,
        reason: String,
    },
}

/// A position as the messages give it: the frame is named, since a cell gives positions in the
/// cell frame and these are in the robot's.
fn fmt_p(p: &[f64; 3]) -> String {
    format!("({:.1}, {:.1}, {:.1}) mm (robot frame)", p[0], p[1], p[2])
}

fn fmt_branches(b: &[(Branch, String)]) -> String {
    b.iter()
        .map(|(b, _)| b.name())
        .collect::<Vec<_>>()
        .join(", ")
}

fn fmt_reasons(b: &[(Branch, String)]) -> String {
    b.iter().map(|(b, why)| format!("; {b}: {why}")).collect()
}

/// A range violation with values rounded to 0.1 deg.
pub fn describe_violation(v: &RangeViolation) -> String {
    match v {
        RangeViolation::Axis {
            axis,
            value_deg,
            min_deg,
            max_deg,
        } => format!("axis {axis} = {value_deg:.1} deg is outside {min_deg} .. {max_deg} deg"),
        RangeViolation::Coupled {
            value_deg,
            min_deg,
            max_deg,
        } => format!(
            "axis 3 - axis 2 = {value_deg:.1} deg is outside the coupled range {min_deg} .. \
             {max_deg} deg"
        ),
    }
}

fn fmt_violations(v: &[(Branch, RangeViolation)]) -> String {
    v.iter()
        .map(|(b, v)| format!("{b}: {}", describe_violation(v)))
        .collect::<Vec<_>>()
        .join("; ")
}

/// Wraps an angle into (-180, 180].
pub fn wrap_deg(a: f64) -> f64 {
    let w = a - 360.0 * ((a + 180.0) / 360.0).floor();
    if w <= -180.0 {
        w + 360.0
    } else if w > 180.0 {
        w - 360.0
    } else {
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn branch_names_parse_from_kebab_case() {
        #[derive(Deserialize)]
        struct W {
            branch: Branch,
        }
        let w: W = serde_saphyr::from_str("branch: back-elbow-down\n").expect("parses");
        assert_eq!(w.branch, Branch::BackElbowDown);
        assert!(serde_saphyr::from_str::<W>("branch: elbow-up\n").is_err());
        assert_eq!("front-elbow-up".parse::<Branch>(), Ok(Branch::FrontElbowUp));
        assert!("FrontElbowUp".parse::<Branch>().is_err());
    }

    #[test]
    fn wrap_is_half_open() {
        assert_eq!(wrap_deg(180.0), 180.0);
        assert_eq!(wrap_deg(-180.0), 180.0);
        assert_eq!(wrap_deg(190.0), -170.0);
        assert_eq!(wrap_deg(-540.0), 180.0);
        assert_eq!(wrap_deg(359.0), -1.0);
    }
}
