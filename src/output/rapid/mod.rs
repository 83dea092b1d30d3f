//! RAPID output stage: turns an already planned joint path into the text of an
//! ABB RAPID module (IRB 1400 on an IRC5 controller, loaded by RobotStudio).
//!
//! Everything the text needs is decided by earlier stages and handed over as a
//! [`Program`]; this stage only validates names, formats numbers and fills the
//! template `templates/module.mod.j2` (embedded at compile time, rendered with
//! minijinja in strict-undefined mode, no auto-escaping, trailing newline kept).
//! The template holds no logic beyond loops and variable output; every number
//! is formatted here with [`format_fixed`].
//!
//! # Shape of the module
//!
//! ```text
//! MODULE <module>
//!     ! generator: <generator>
//!     ! cell: <cell_file>
//!     ! planner: <planner>
//!     ! grid (deg): <grid_deg, 3 decimals>
//!     ! clearance (mm): <clearance_mm, 1 decimal>
//!     ! base: [<x>, <y>, <z>] yaw: <yaw_deg>      (x, y, z 1 decimal in mm; yaw 3 decimals in deg)
//!     ! moves: <moves>
//!     ! min clearance (mm): <min_clearance_mm, 1 decimal, or `none (no obstacles)`>
//!     ! estimated time (s): <estimated_time_s, 2 decimals>   (only when known)
//!
//!     CONST jointtarget <name> := [[a1,a2,a3,a4,a5,a6],[9E9,9E9,9E9,9E9,9E9,9E9]];   (one per target)
//!
//!     PROC main()
//!         MoveAbsJ <name>\NoEOffs, <speed>, <zone>, <tool>;   (one per target, same order)
//!     ENDPROC
//! ENDMODULE
//! ```
//!
//! Axis values are printed with exactly 3 decimals (degrees). The decimals come from the one
//! table of output precisions, [`crate::precision`], which the cell validation reads too.
//!
//! # Guarantees of [`render`]
//!
//! - ASCII only, LF line endings, exactly one final newline, no trailing
//!   spaces, no tabs; 4 spaces of indentation inside `MODULE`, 8 inside `PROC`.
//! - Deterministic: same [`Program`], same bytes (no timestamps, nothing
//!   machine-dependent).
//! - Numbers in fixed notation only: no exponent, never `-0.000`; the only
//!   `E` in numeric position is the literal `9E9` RAPID uses for unused
//!   external axes. Non-finite values are refused ([`RapidError::NonFinite`]).
//! - The module name and every `CONST` name pass [`check_identifier`]; speed,
//!   zone and tool names pass [`check_data_name`] (RAPID identifiers that are
//!   not reserved words; predefined names such as `v300`, `fine`, `tool0` are
//!   of course allowed there). It is the rule of [`crate::names`], which the
//!   cell validation applies first, at the cell's lines: here it is a last
//!   guard. All `CONST` names are unique ignoring case and differ from the
//!   module name, `main` and the speed/zone/tool names (see [`target_names`]).
//! - One `CONST` per target and one `MoveAbsJ` per target, in the same order,
//!   so each name is used by exactly one move.
//! - Free text in the header (`generator`, `cell_file`, `planner`) is made
//!   printable ASCII: each character outside `' '..='~'` becomes `?`,
//!   surrounding spaces are trimmed, and empty text becomes `-`.

mod format;
mod target_names;

pub use format::format_fixed;
pub use target_names::{target_names, target_names_avoiding};

use crate::names::{check_data_name, check_identifier, IdentifierError};
use crate::precision::{
    GRID_DECIMALS, JOINT_DECIMALS, LENGTH_DECIMALS, TIME_DECIMALS, YAW_DECIMALS,
};

use minijinja::{value::Serde, AutoEscape, Environment, UndefinedBehavior};
use serde::Serialize;

/// The module template, embedded at compile time.
pub const TEMPLATE: &str = include_str!("../../../templates/module.mod.j2");

/// Everything the module text needs, already decided by earlier stages.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// RAPID module name from the cell (must pass [`check_identifier`]).
    pub module: String,
    /// Values for the comment header.
    pub header: Header,
    /// Targets in visiting order; target 0 is the first cell point (the start).
    pub targets: Vec<JointTarget>,
    /// RAPID speeddata name, e.g. `"v300"`.
    pub speed: String,
    /// RAPID zonedata name, e.g. `"fine"`.
    pub zone: String,
    /// RAPID tooldata name, e.g. `"tool0"`.
    pub tool: String,
}

/// Values printed as comments at the top of the module.
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    /// Generator name and version, e.g. `"gen-rapid 0.1.0"`.
    pub generator: String,
    /// Cell file name only (no directory), e.g. `"trunk.yaml"`.
    pub cell_file: String,
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
}

/// What a target is: a named cell point or an intermediate via point.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TargetKind {
    /// A point from the cell file; keeps its name.
    CellPoint {
        /// The point's name in the cell file.
        name: String,
    },
    /// An intermediate point inserted by the planner.
    Via {
        /// 0-based index of the leg (from cell point `leg` to `leg + 1`).
        leg: usize,
        /// 1-based index of the via within its leg.
        index: usize,
    },
}

/// One `CONST jointtarget` of the module: a joint position to visit.
#[derive(Debug, Clone, PartialEq)]
pub struct JointTarget {
    /// Cell point or via.
    pub kind: TargetKind,
    /// Controller values of axes 1..6 in degrees.
    pub axes_deg: [f64; 6],
}

/// Why a module could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum RapidError {
    /// The module name is not a valid RAPID identifier.
    #[error("invalid RAPID module name `{name}`: {source}")]
    InvalidModuleName {
        /// The rejected name.
        name: String,
        /// The rule it breaks.
        source: IdentifierError,
    },
    /// A cell point name is not a valid RAPID identifier.
    #[error("cell point `{name}` (target {position}) is not a valid RAPID name: {source}")]
    InvalidTargetName {
        /// The rejected cell point name.
        name: String,
        /// Its 0-based position in [`Program::targets`].
        position: usize,
        /// The rule it breaks.
        source: IdentifierError,
    },
    /// A generated via name is not a valid RAPID identifier (e.g. too long).
    #[error(
        "generated name `{name}` for via {index} of leg {leg} is not a valid RAPID name: {source}"
    )]
    InvalidGeneratedName {
        /// The generated name.
        name: String,
        /// Leg of the via target (0-based).
        leg: usize,
        /// Index of the via target within its leg (1-based).
        index: usize,
        /// The rule it breaks.
        source: IdentifierError,
    },
    /// The speed, zone or tool name is not a RAPID identifier.
    #[error("invalid RAPID {role} name `{name}`: {source}")]
    InvalidDataName {
        /// `"speed"`, `"zone"` or `"tool"`.
        role: &'static str,
        /// The rejected name.
        name: String,
        /// The rule it breaks.
        source: IdentifierError,
    },
    /// Two names in the module would be the same RAPID name (RAPID names are case-insensitive).
    #[error("name `{name}` clashes with {other} (RAPID names are case-insensitive)")]
    NameClash {
        /// The name that cannot be used.
        name: String,
        /// What it clashes with.
        other: String,
    },
    /// A value to print is NaN or infinite.
    #[error("{what} is not a finite number ({value})")]
    NonFinite {
        /// Which value.
        what: String,
        /// The value.
        value: f64,
    },
    /// `header.moves` does not match the number of targets.
    #[error("header says {header} moves but the program has {actual} MoveAbsJ after the first")]
    MovesMismatch {
        /// [`Header::moves`].
        header: usize,
        /// `targets.len() - 1` (0 for no targets).
        actual: usize,
    },
    /// The template failed to compile or render.
    #[error("RAPID template error: {0}")]
    Template(#[from] minijinja::Error),
}

#[derive(Serialize)]
struct TargetCtx {
    name: String,
    axes: String,
}

#[derive(Serialize)]
struct ModuleCtx<'a> {
    module: &'a str,
    header: Vec<String>,
    targets: Vec<TargetCtx>,
    speed: &'a str,
    zone: &'a str,
    tool: &'a str,
}

/// Header free text as printable ASCII on one line (see module doc).
fn comment_text(text: &str) -> String {
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

fn finite(what: impl Into<String>, value: f64) -> Result<f64, RapidError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(RapidError::NonFinite {
            what: what.into(),
            value,
        })
    }
}

fn header_lines(h: &Header) -> Result<Vec<String>, RapidError> {
    let grid = finite("header grid_deg", h.grid_deg)?;
    let clearance = finite("header clearance_mm", h.clearance_mm)?;
    let [x, y, z] = h.base_mm;
    let (x, y, z) = (
        finite("header base_mm[0]", x)?,
        finite("header base_mm[1]", y)?,
        finite("header base_mm[2]", z)?,
    );
    let yaw = finite("header yaw_deg", h.yaw_deg)?;
    let min_clearance = match h.min_clearance_mm {
        Some(c) => format_fixed(finite("header min_clearance_mm", c)?, LENGTH_DECIMALS),
        None => "none (no obstacles)".to_string(),
    };
    let mut lines = vec![
        format!("generator: {}", comment_text(&h.generator)),
        format!("cell: {}", comment_text(&h.cell_file)),
        format!("planner: {}", comment_text(&h.planner)),
        format!("grid (deg): {}", format_fixed(grid, GRID_DECIMALS)),
        format!(
            "clearance (mm): {}",
            format_fixed(clearance, LENGTH_DECIMALS)
        ),
        format!(
            "base: [{}, {}, {}] yaw: {}",
            format_fixed(x, LENGTH_DECIMALS),
            format_fixed(y, LENGTH_DECIMALS),
            format_fixed(z, LENGTH_DECIMALS),
            format_fixed(yaw, YAW_DECIMALS)
        ),
        format!("moves: {}", h.moves),
        format!("min clearance (mm): {min_clearance}"),
    ];
    if let Some(t) = h.estimated_time_s {
        let t = finite("header estimated_time_s", t)?;
        lines.push(format!(
            "estimated time (s): {}",
            format_fixed(t, TIME_DECIMALS)
        ));
    }
    Ok(lines)
}

/// Renders `program` as the complete text of a RAPID module (see the module
/// documentation for the exact shape and the guarantees).
///
/// Checks, in this order: module name ([`check_identifier`]); speed, zone and
/// tool names (identifier shape, not a reserved word); header numbers finite;
/// `header.moves == targets.len() - 1`; target names ([`target_names`]);
/// no target name equal to the module, `main`, speed, zone or tool name and
/// the module name not equal to `main`, speed, zone or tool (ignoring case);
/// axis values finite. The first failure is returned.
pub fn render(program: &Program) -> Result<String, RapidError> {
    check_identifier(&program.module).map_err(|source| RapidError::InvalidModuleName {
        name: program.module.clone(),
        source,
    })?;
    let roles = [
        ("speed", &program.speed),
        ("zone", &program.zone),
        ("tool", &program.tool),
    ];
    for (role, name) in roles {
        check_data_name(name).map_err(|source| RapidError::InvalidDataName {
            role,
            name: name.clone(),
            source,
        })?;
    }

    let header = header_lines(&program.header)?;
    let actual = program.targets.len().saturating_sub(1);
    if program.header.moves != actual {
        return Err(RapidError::MovesMismatch {
            header: program.header.moves,
            actual,
        });
    }

    // Names used by the module itself, other than the CONSTs.
    let mut others: Vec<(String, String)> = vec![
        (
            program.module.clone(),
            format!("the module name `{}`", program.module),
        ),
        (
            "main".to_string(),
            "PROC main of the generated module".to_string(),
        ),
    ];
    for (role, name) in roles {
        others.push((name.clone(), format!("the {role} data `{name}`")));
    }
    if let Some((_, what)) = others[1..]
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(&program.module))
    {
        return Err(RapidError::NameClash {
            name: program.module.clone(),
            other: what.clone(),
        });
    }
    // Vias avoid them (a cell point that takes one is a clash, refused above at its line).
    let reserved: Vec<&str> = others.iter().map(|(n, _)| n.as_str()).collect();
    let target_names = target_names_avoiding(&program.targets, &reserved)?;
    for name in &target_names {
        if let Some((_, what)) = others.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)) {
            return Err(RapidError::NameClash {
                name: name.clone(),
                other: what.clone(),
            });
        }
    }

    let mut targets = Vec::with_capacity(program.targets.len());
    for (target, name) in program.targets.iter().zip(target_names) {
        let mut axes = Vec::with_capacity(6);
        for (k, &value) in target.axes_deg.iter().enumerate() {
            let value = finite(format!("axis {} of target `{name}`", k + 1), value)?;
            axes.push(format_fixed(value, JOINT_DECIMALS));
        }
        targets.push(TargetCtx {
            name,
            axes: axes.join(","),
        });
    }

    let ctx = ModuleCtx {
        module: &program.module,
        header,
        targets,
        speed: &program.speed,
        zone: &program.zone,
        tool: &program.tool,
    };

    let mut env = Environment::new();
    env.set_undefined_behavior(UndefinedBehavior::Strict);
    env.set_auto_escape_callback(|_| AutoEscape::None);
    env.set_syntax(
        minijinja::syntax::SyntaxConfig::builder()
            .trim_blocks(true)
            .lstrip_blocks(true)
            .keep_trailing_newline(true)
            .build()?,
    );
    env.add_template("module.mod.j2", TEMPLATE)?;
    let text = env.get_template("module.mod.j2")?.render(Serde(&ctx))?;
    debug_assert!(text.is_ascii() && !text.contains('\r') && text.ends_with('\n'));
    Ok(text)
}

#[cfg(test)]
mod tests;
