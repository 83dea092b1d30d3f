//! The values of the data the module declares beside its jointtargets: `CONST robtarget`,
//! `PERS tooldata`, `PERS wobjdata` (formats in `docs/rapid.md`), and the last guard on the
//! jointtargets' axis ranges.
//!
//! Numbers are fixed decimals from [`crate::precision`]: positions 3 (mm), quaternions 9, the
//! mass 3; confdata are integers; the constant parts (loaddata's `aom` and inertias, wobjdata's
//! `oframe`) are written as RAPID's identity and zeros.

use super::{finite, format_fixed, RapidError};
use crate::precision::{MASS_DECIMALS, POSITION_DECIMALS, QUATERNION_DECIMALS};

/// External axes of every target: none connected.
pub const NO_EXTERNAL_AXES: &str = "[9E9,9E9,9E9,9E9,9E9,9E9]";

/// A frame: position (mm) and unit quaternion `[q1, q2, q3, q4]` = `[w, x, y, z]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    pub pos_mm: [f64; 3],
    pub quat_wxyz: [f64; 4],
}

/// A `CONST robtarget` written beside a cell point's jointtarget.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobTarget {
    /// The TCP pose in the work object (as the cell gives it, normalised; in wobj0 with
    /// `robot.frame: base`, in the robot's base frame).
    pub pose: Pose,
    /// `[cf1, cf4, cf6, cfx]` of the jointtarget beside it.
    pub conf: [i32; 4],
}

/// The `PERS tooldata` the module declares (under [`Program::tool`](super::Program::tool)).
#[derive(Debug, Clone, PartialEq)]
pub struct ToolData {
    /// The TCP in the flange (tool0) frame.
    pub tframe: Pose,
    pub mass_kg: f64,
    /// Centre of gravity in the flange frame, mm.
    pub cog_mm: [f64; 3],
    /// The names of its collision shapes (for the header).
    pub shapes: Vec<String>,
}

/// The `PERS wobjdata` the module declares.
#[derive(Debug, Clone, PartialEq)]
pub struct WobjData {
    pub name: String,
    /// The user frame in the world frame (the cell frame, or the robot's base frame with
    /// `robot.frame: base`).
    pub uframe: Pose,
}

/// The robot's axis ranges, deg (controller values), for the last guard.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisRanges {
    /// `[min, max]` of axes 1..6.
    pub axes_deg: [[f64; 2]; 6],
    /// `[min, max]` of axis 3 - axis 2, when the controller bounds it.
    pub coupled_axis3_deg: Option<[f64; 2]>,
}

impl AxisRanges {
    /// No limits at all (for tests of the text alone).
    pub const UNBOUNDED: AxisRanges = AxisRanges {
        axes_deg: [[f64::NEG_INFINITY, f64::INFINITY]; 6],
        coupled_axis3_deg: None,
    };

    /// The first limit `axes` breaks, as words.
    pub fn violation(&self, axes: &[f64; 6]) -> Option<String> {
        for (k, (&v, [lo, hi])) in axes.iter().zip(self.axes_deg).enumerate() {
            if !(lo..=hi).contains(&v) {
                return Some(format!(
                    "axis {} = {v} deg is outside {lo} .. {hi} deg",
                    k + 1
                ));
            }
        }
        if let Some([lo, hi]) = self.coupled_axis3_deg {
            let v = axes[2] - axes[1];
            if !(lo..=hi).contains(&v) {
                return Some(format!(
                    "axis 3 - axis 2 = {v} deg is outside the coupled range {lo} .. {hi} deg"
                ));
            }
        }
        None
    }
}

/// `[[x,y,z],[q1,q2,q3,q4]]`.
fn pose(what: &str, p: &Pose) -> Result<String, RapidError> {
    let mut pos = Vec::with_capacity(3);
    for (k, &v) in p.pos_mm.iter().enumerate() {
        pos.push(format_fixed(
            finite(format!("{what} position {k}"), v)?,
            POSITION_DECIMALS,
        ));
    }
    let mut quat = Vec::with_capacity(4);
    for (k, &v) in p.quat_wxyz.iter().enumerate() {
        quat.push(format_fixed(
            finite(format!("{what} quaternion q{}", k + 1), v)?,
            QUATERNION_DECIMALS,
        ));
    }
    Ok(format!("[[{}],[{}]]", pos.join(","), quat.join(",")))
}

/// A robtarget's value: `[[x,y,z],[q1,q2,q3,q4],[cf1,cf4,cf6,cfx],[9E9,...]]`.
pub(super) fn robtarget(name: &str, r: &RobTarget) -> Result<String, RapidError> {
    let p = pose(&format!("robtarget `{name}`"), &r.pose)?;
    let [c1, c4, c6, cx] = r.conf;
    Ok(format!(
        "[{},[{c1},{c4},{c6},{cx}],{NO_EXTERNAL_AXES}]",
        &p[1..p.len() - 1]
    ))
}

/// A tooldata's value: `[TRUE,[[x,y,z],[q..]],[mass,[cx,cy,cz],[1,0,0,0],0,0,0]]` (held by the
/// robot; the tool a point mass at its centre of gravity).
pub(super) fn tooldata(name: &str, t: &ToolData) -> Result<String, RapidError> {
    let tframe = pose(&format!("tooldata `{name}` tframe"), &t.tframe)?;
    let mass = format_fixed(
        finite(format!("tooldata `{name}` mass"), t.mass_kg)?,
        MASS_DECIMALS,
    );
    let mut cog = Vec::with_capacity(3);
    for (k, &v) in t.cog_mm.iter().enumerate() {
        cog.push(format_fixed(
            finite(format!("tooldata `{name}` cog {k}"), v)?,
            POSITION_DECIMALS,
        ));
    }
    Ok(format!(
        "[TRUE,{tframe},[{mass},[{}],[1,0,0,0],0,0,0]]",
        cog.join(",")
    ))
}

/// A wobjdata's value: `[FALSE,TRUE,"",[[x,y,z],[q..]],[[0,0,0],[1,0,0,0]]]` (not held by the
/// robot, a fixed user frame, no mechanical unit, the identity object frame).
pub(super) fn wobjdata(w: &WobjData) -> Result<String, RapidError> {
    let uframe = pose(&format!("wobjdata `{}` uframe", w.name), &w.uframe)?;
    Ok(format!("[FALSE,TRUE,\"\",{uframe},[[0,0,0],[1,0,0,0]]]"))
}

/// A loaddata's value: `[mass,[cx,cy,cz],[1,0,0,0],0,0,0]` (a point mass at its centre of
/// gravity, in the tool frame).
pub(super) fn loaddata(l: &super::LoadData) -> Result<String, RapidError> {
    let name = &l.name;
    let mass = format_fixed(
        finite(format!("loaddata `{name}` mass"), l.mass_kg)?,
        MASS_DECIMALS,
    );
    let mut cog = Vec::with_capacity(3);
    for (k, &v) in l.cog_mm.iter().enumerate() {
        cog.push(format_fixed(
            finite(format!("loaddata `{name}` cog {k}"), v)?,
            POSITION_DECIMALS,
        ));
    }
    Ok(format!("[{mass},[{}],[1,0,0,0],0,0,0]", cog.join(",")))
}
