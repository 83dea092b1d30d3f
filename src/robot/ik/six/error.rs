//! Why a pose has no solution: typed, with the figures a message needs.

use super::ConfData;
use crate::robot::{Axes6, RangeViolation};

/// One branch of the inverse kinematics (in range or not), for diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate {
    /// Controller values, deg: the full turn of each axis nearest to its range.
    pub axes_deg: Axes6,
    pub conf: ConfData,
    /// Every limit it breaks; empty when it is in range.
    pub violations: Vec<RangeViolation>,
}

/// Why the six-axis inverse kinematics has no (in-range) solution. Positions in the robot base
/// frame, mm; angles in degrees (controller values).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SixAxisError {
    #[error("robot {robot} is not a spherical-wrist arm the six-axis IK handles: {message}")]
    Structure { robot: String, message: String },
    #[error("the pose is not finite")]
    NotFinite,
    #[error(
        "out of reach by {by_mm:.1} mm: the wrist centre {} is {front_mm:.1} mm from axis 2 \
         ({back_mm:.1} mm with axis 1 turned half a turn); the arm reaches {min_mm:.1} .. \
         {max_mm:.1} mm",
        fmt_p(.wrist_mm)
    )]
    OutOfReach {
        wrist_mm: [f64; 3],
        /// Distance axis 2 -> wrist centre with axis 1 turned towards it, and turned away.
        front_mm: f64,
        back_mm: f64,
        /// The arm's reach from axis 2 (geometry, no axis ranges).
        min_mm: f64,
        max_mm: f64,
        /// How far the nearer stance misses that reach.
        by_mm: f64,
    },
    #[error(
        "the wrist centre {} is {from_axis1_mm:.1} mm from axis 1, inside the shoulder offset \
         of {offset_mm:.1} mm",
        fmt_p(.wrist_mm)
    )]
    BesideShoulder {
        wrist_mm: [f64; 3],
        from_axis1_mm: f64,
        offset_mm: f64,
    },
    #[error(
        "the orientation needs axis 5 = {needed_deg:.1} deg, {by_deg:.1} deg beyond its range \
         {min_deg} .. {max_deg} deg (wrist centre {})",
        fmt_p(.wrist_mm)
    )]
    Axis5 {
        wrist_mm: [f64; 3],
        /// The axis-5 value nearest to the range among the arm stances within range.
        needed_deg: f64,
        min_deg: f64,
        max_deg: f64,
        by_deg: f64,
    },
    #[error(
        "no solution lies within the axis ranges (wrist centre {}): {}",
        fmt_p(.wrist_mm),
        fmt_candidates(.candidates)
    )]
    OutOfRange {
        wrist_mm: [f64; 3],
        /// Every branch with every limit it breaks.
        candidates: Vec<Candidate>,
    },
}

/// A position as the messages give it (the frame named: cells give positions in their own).
pub(super) fn fmt_p(p: &[f64; 3]) -> String {
    format!("({:.1}, {:.1}, {:.1}) mm (robot frame)", p[0], p[1], p[2])
}

/// How far the value lies beyond the limit it breaks, deg.
pub fn excess_deg(v: &RangeViolation) -> f64 {
    let (value, lo, hi) = match *v {
        RangeViolation::Axis {
            value_deg,
            min_deg,
            max_deg,
            ..
        }
        | RangeViolation::Coupled {
            value_deg,
            min_deg,
            max_deg,
        } => (value_deg, min_deg, max_deg),
    };
    super::solve::outside(value, lo, hi)
}

/// A range violation with the amount, values to 0.1 deg: "axis 4 = 170.0 deg is 20.0 deg
/// outside -150 .. 150 deg".
pub fn describe_violation(v: &RangeViolation) -> String {
    let by = excess_deg(v);
    match v {
        RangeViolation::Axis {
            axis,
            value_deg,
            min_deg,
            max_deg,
        } => format!(
            "axis {axis} = {value_deg:.1} deg is {by:.1} deg outside {min_deg} .. {max_deg} deg"
        ),
        RangeViolation::Coupled {
            value_deg,
            min_deg,
            max_deg,
        } => format!(
            "axis 3 - axis 2 = {value_deg:.1} deg is {by:.1} deg outside the coupled range \
             {min_deg} .. {max_deg} deg"
        ),
    }
}

pub(super) fn fmt_axes(a: &Axes6) -> String {
    let v: Vec<String> = a.iter().map(|x| format!("{x:.1}")).collect();
    format!("[{}]", v.join(", "))
}

pub(super) fn fmt_candidates(c: &[Candidate]) -> String {
    c.iter()
        .map(|c| {
            let why: Vec<String> = c.violations.iter().map(describe_violation).collect();
            format!(
                "confdata {} (axes {}): {}",
                c.conf,
                fmt_axes(&c.axes_deg),
                if why.is_empty() {
                    "in range".to_string()
                } else {
                    why.join(", ")
                }
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}
