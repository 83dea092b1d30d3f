//! The comment header of the module: what was planned with what (the cell, the robot files and
//! their convention, the planner, the base, the tool and work object) and what came out (moves,
//! certified clearance, time). Free text is made printable ASCII on one line.

use super::{finite, format_fixed, Program, RapidError};
use crate::cell::RobotFrame;
use crate::precision::{GRID_DECIMALS, LENGTH_DECIMALS, TIME_DECIMALS, YAW_DECIMALS};

/// What the module says about the controller without a controller file.
pub const NO_CONTROLLER: &str = "none: serial arm, the URDF's limits";

/// The header's note on frames, for a module with robtargets or a work object: wobj0's frame
/// (and a wobjdata's user frame) is the controller's world frame, the cell's positions are in the
/// cell frame; they agree only if the controller's base frame is the placement.
pub const FRAMES_NOTE: &str = "frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above";

/// The note with `robot.frame: base`: the user frame and wobj0's robtargets are written in the
/// robot's base frame, which is the world frame of a controller whose base frame is not moved.
pub const FRAMES_NOTE_BASE: &str = "frames: the user frame and robtargets in wobj0 are written in the robot's base frame; they mean the cell's poses when the controller's world frame is its base frame (the IRC5 default)";

/// Values printed as comments at the top of the module.
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    /// Generator name and version, e.g. `"gen-rapid 0.1.0"`.
    pub generator: String,
    /// Cell file name only (no directory), e.g. `"trunk.yaml"`.
    pub cell_file: String,
    /// The shipped robot the cell names (`robot.model`), as the header states it (its name and
    /// ABB's name of the variant); `None` for a robot read from a URDF file.
    pub model: Option<String>,
    /// The URDF's file name, e.g. `"irb1400.urdf"`.
    pub urdf: String,
    /// The controller file's name, or `None` without one.
    pub controller: Option<String>,
    /// Whether the controller couples axis 3 to axis 2 (parallelogram), else serial.
    pub parallelogram: bool,
    /// Planner used: `"extensile"`, `"neighboring"` or `"depth-first"`.
    pub planner: String,
    /// Grid step in degrees (printed with 3 decimals).
    pub grid_deg: f64,
    /// Required clearance in mm (printed with 1 decimal).
    pub clearance_mm: f64,
    /// Robot base position in mm (printed with 1 decimal each).
    pub base_mm: [f64; 3],
    /// Robot base yaw in degrees (printed with 3 decimals).
    pub yaw_deg: f64,
    /// Number of `MoveAbsJ` after the first (the straight moves); must equal
    /// `targets.len() - 1` (0 for no targets).
    pub moves: usize,
    /// Smallest clearance along the whole path in mm (printed with 1 decimal).
    /// None when the cell has no obstacles (the header then says so).
    pub min_clearance_mm: Option<f64>,
    /// Manipulation time estimate in seconds, when known (printed with 2 decimals).
    pub estimated_time_s: Option<f64>,
    /// The vias whose move in has a fly-by zone, and all vias (`Plan::zoned_vias`).
    pub zoned_vias: (usize, usize),
    /// The zone a via gets where it is proven (the cell's via zone; `fine` until vias may fly by).
    pub via_zone: String,
    /// The paper's method alone on the same cell: its moves and estimated time (s), when known.
    pub paper: Option<(usize, f64)>,
    /// The frame the user frame and wobj0's robtargets are written in (`robot.frame`).
    pub frame: RobotFrame,
    /// Where the routine ends, against where it starts.
    pub ends: Ends,
}

/// Where the routine ends: where it starts (a closed cycle, `motion.cycle` or a last entry
/// that reaches the first one's target), or elsewhere.
#[derive(Debug, Clone, PartialEq)]
pub enum Ends {
    /// At the first entry's target: the estimated time is a cycle time.
    AtStart,
    /// Elsewhere: at `last` (the last stop), not at `first` (the first entry).
    Elsewhere { first: String, last: String },
}

/// Header free text as printable ASCII on one line (see module doc).
pub(super) fn comment_text(text: &str) -> String {
    let mapped: String = text
        .chars()
        .map(|c| if (' '..='~').contains(&c) { c } else { '?' })
        .collect();
    let trimmed = mapped.trim_matches(' ');
    if trimmed.is_empty() {
        "-".to_string()
    } else {
        trimmed.to_string()
    }
}

/// The header's facts, each formatted as the header writes it (and as a template sees them,
/// `facts.*`; docs/outputs.md). Free text is printable ASCII on one line.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Facts {
    pub generator: String,
    pub cell: String,
    /// The shipped robot (`robot.model`), or none for a URDF read from a file.
    pub model: Option<String>,
    pub urdf: String,
    /// The controller file's name, or `none: serial arm, the URDF's limits`.
    pub controller: String,
    pub coupling: String,
    pub planner: String,
    /// 3 decimals.
    pub grid_deg: String,
    /// 1 decimal.
    pub clearance_mm: String,
    /// x, y, z, 1 decimal each.
    pub base_mm: [String; 3],
    /// 3 decimals.
    pub yaw_deg: String,
    /// The tool, work object and frames lines (only for a module with a tool, a work object or
    /// robtargets; else none).
    pub tool: Option<String>,
    pub wobj: Option<String>,
    pub frames: Option<String>,
    /// The number of moves.
    pub moves: usize,
    /// 1 decimal, or none without obstacles.
    pub min_clearance_mm: Option<String>,
    /// 2 decimals, or none when not estimated.
    pub estimated_time_s: Option<String>,
    /// `N of M (via zone Z)`: the vias that fly by, of all vias, and the cell's via zone.
    pub zoned_vias: String,
    /// `n moves, t s` (t with 2 decimals): the paper's method alone, or none when not known.
    pub paper_method: Option<String>,
    /// Whether the routine ends where it starts: `closed (...)` or `open (...)`.
    pub cycle: String,
}

impl Facts {
    /// The header lines (without the leading `! `).
    pub fn lines(&self) -> Vec<String> {
        let [x, y, z] = &self.base_mm;
        let mut lines = vec![
            format!("generator: {}", self.generator),
            format!("cell: {}", self.cell),
        ];
        if let Some(m) = &self.model {
            lines.push(format!("model: {m}"));
        }
        lines.extend([
            format!("urdf: {}", self.urdf),
            format!("controller: {}", self.controller),
            format!("coupling: {}", self.coupling),
            format!("planner: {}", self.planner),
            format!("grid (deg): {}", self.grid_deg),
            format!("clearance (mm): {}", self.clearance_mm),
            format!("base: [{x}, {y}, {z}] yaw: {}", self.yaw_deg),
        ]);
        for line in [&self.tool, &self.wobj, &self.frames].into_iter().flatten() {
            lines.push(line.clone());
        }
        lines.push(format!("moves: {}", self.moves));
        lines.push(format!(
            "min clearance (mm): {}",
            self.min_clearance_mm
                .as_deref()
                .unwrap_or("none (no obstacles)")
        ));
        if let Some(t) = &self.estimated_time_s {
            lines.push(format!("estimated time (s): {t}"));
        }
        lines.push(format!("cycle: {}", self.cycle));
        lines.push(format!("zoned vias: {}", self.zoned_vias));
        if let Some(p) = &self.paper_method {
            lines.push(format!("the paper's method alone: {p}"));
        }
        lines
    }
}

/// The header facts of `p`.
pub(super) fn facts(p: &Program) -> Result<Facts, RapidError> {
    let h = &p.header;
    let grid = finite("header grid_deg", h.grid_deg)?;
    let clearance = finite("header clearance_mm", h.clearance_mm)?;
    let [x, y, z] = h.base_mm;
    let base_mm = [
        format_fixed(finite("header base_mm[0]", x)?, LENGTH_DECIMALS),
        format_fixed(finite("header base_mm[1]", y)?, LENGTH_DECIMALS),
        format_fixed(finite("header base_mm[2]", z)?, LENGTH_DECIMALS),
    ];
    let yaw = finite("header yaw_deg", h.yaw_deg)?;
    let min_clearance_mm = match h.min_clearance_mm {
        Some(c) => Some(format_fixed(
            finite("header min_clearance_mm", c)?,
            LENGTH_DECIMALS,
        )),
        None => None,
    };
    let estimated_time_s = match h.estimated_time_s {
        Some(t) => Some(format_fixed(
            finite("header estimated_time_s", t)?,
            TIME_DECIMALS,
        )),
        None => None,
    };
    let paper_method = match h.paper {
        Some((moves, t)) => Some(format!(
            "{moves} move{}, {} s",
            if moves == 1 { "" } else { "s" },
            format_fixed(finite("header paper time_s", t)?, TIME_DECIMALS)
        )),
        None => None,
    };
    let coupling = match h.parallelogram {
        true => "parallelogram (axis 3 = URDF joint 3 + joint 2)",
        false => "serial (axes 1..6 = URDF joints 1..6)",
    };
    let (tool, wobj, frames) = match tcp_lines(p) {
        Some([t, w, f]) => (Some(t), Some(w), Some(f)),
        None => (None, None, None),
    };
    Ok(Facts {
        generator: comment_text(&h.generator),
        cell: comment_text(&h.cell_file),
        model: h.model.as_deref().map(comment_text),
        urdf: comment_text(&h.urdf),
        controller: comment_text(h.controller.as_deref().unwrap_or(NO_CONTROLLER)),
        coupling: coupling.to_string(),
        planner: comment_text(&h.planner),
        grid_deg: format_fixed(grid, GRID_DECIMALS),
        clearance_mm: format_fixed(clearance, LENGTH_DECIMALS),
        base_mm,
        yaw_deg: format_fixed(yaw, YAW_DECIMALS),
        tool,
        wobj,
        frames,
        moves: h.moves,
        min_clearance_mm,
        estimated_time_s,
        zoned_vias: format!(
            "{} of {} (via zone {})",
            h.zoned_vias.0,
            h.zoned_vias.1,
            comment_text(&h.via_zone)
        ),
        paper_method,
        cycle: match &h.ends {
            Ends::AtStart => "closed: the routine ends where it starts; its time is a cycle time".to_string(),
            Ends::Elsewhere { first, last } => format!(
                "open: the routine ends at {}, not where it starts ({}); motion.cycle: true closes it",
                comment_text(last),
                comment_text(first)
            ),
        },
    })
}

/// The tool, the work object and the frame note: only for a module that declares a tool or a
/// work object or writes robtargets (a module of joint moves alone says nothing of them).
fn tcp_lines(p: &Program) -> Option<[String; 3]> {
    let robtargets = p.targets.iter().any(|t| t.robtarget.is_some());
    if p.tooldata.is_none() && p.wobjs.is_empty() && !robtargets {
        return None;
    }
    let tool = match &p.tooldata {
        Some(t) if t.shapes.is_empty() => format!(
            "tool: {} (declared below; no collision shapes)",
            comment_text(&p.tool)
        ),
        Some(t) => format!(
            "tool: {} (declared below; collision shapes: {})",
            comment_text(&p.tool),
            comment_text(&t.shapes.join(", "))
        ),
        None if p.tool.eq_ignore_ascii_case("tool0") => {
            "tool: tool0 (predefined: the flange; no tool volume)".to_string()
        }
        None => format!(
            "tool: {} (not declared by this module; no tool volume)",
            comment_text(&p.tool)
        ),
    };
    let wobj = match p.wobjs.as_slice() {
        [w] => format!(
            "wobj: {} (declared below; robtargets are in its user frame)",
            comment_text(&w.name)
        ),
        [] => "wobj: wobj0 (robtargets are in the world frame)".to_string(),
        several => {
            let names: Vec<&str> = several.iter().map(|w| w.name.as_str()).collect();
            format!(
                "wobjs: {} (declared below; each robtarget is in the user frame of the one it names)",
                comment_text(&names.join(", "))
            )
        }
    };
    let frames = match p.header.frame {
        RobotFrame::Cell => FRAMES_NOTE,
        RobotFrame::Base => FRAMES_NOTE_BASE,
    };
    Some([tool, wobj, frames.to_string()])
}
