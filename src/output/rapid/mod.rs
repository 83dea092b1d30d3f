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
//!     ! urdf: <the URDF's file name>
//!     ! controller: <the controller file's name, or `none: serial arm, the URDF's limits`>
//!     ! coupling: <parallelogram (axis 3 = URDF joint 3 + joint 2) | serial (...)>
//!     ! planner: <planner>
//!     ! grid (deg): <grid_deg, 3 decimals>
//!     ! clearance (mm): <clearance_mm, 1 decimal>
//!     ! base: [<x>, <y>, <z>] yaw: <yaw_deg>      (x, y, z 1 decimal in mm; yaw 3 decimals in deg)
//!     ! tool: <tool> (...)        \
//!     ! wobj: <wobj> (...)         > only with a tool or wobj block or robtarget points
//!     ! frames: ...               /
//!     ! moves: <moves>
//!     ! min clearance (mm): <min_clearance_mm, 1 decimal, or `none (no obstacles)`>
//!     ! estimated time (s): <estimated_time_s, 2 decimals>   (only when known)
//!
//!     PERS tooldata <tool> := [TRUE,[[x,y,z],[q1,q2,q3,q4]],[mass,[cx,cy,cz],[1,0,0,0],0,0,0]];
//!     PERS wobjdata <wobj> := [FALSE,TRUE,"",[[x,y,z],[q1,q2,q3,q4]],[[0,0,0],[1,0,0,0]]];
//!                                                     (each only when declared, then a blank line)
//!     CONST jointtarget <name> := [[a1,a2,a3,a4,a5,a6],[9E9,9E9,9E9,9E9,9E9,9E9]];   (one per target)
//!     CONST robtarget <name>_rt := [[x,y,z],[q1,q2,q3,q4],[cf1,cf4,cf6,cfx],[9E9,...]];
//!                                                     (after a robtarget point's jointtarget)
//!
//!     PROC main()
//!         MoveAbsJ <name>\NoEOffs, <speed>, <zone>, <tool>[\WObj:=<wobj>];   (one per target)
//!     ENDPROC
//! ENDMODULE
//! ```
//!
//! Axis values are printed with exactly 3 decimals (degrees), positions with 3 (mm),
//! quaternions with 9, the mass with 3. The decimals come from the one table of output
//! precisions, [`crate::precision`], which the cell validation reads too. Each target carries
//! the speed and zone of the move into it.
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
//! - Every joint value lies in the robot's ranges ([`Program::ranges`], all six
//!   axes and the coupled axis-3 range): a last guard, the earlier stages
//!   never produce another ([`RapidError::OutOfRange`], an internal error).
//! - The module name and every declared name (`CONST`s, the tool and work
//!   object when declared) pass [`check_identifier`]; speed, zone and tool
//!   names pass [`check_data_name`] (RAPID identifiers that are not reserved
//!   words; predefined names such as `v300`, `fine`, `tool0` are of course
//!   allowed there). It is the rule of [`crate::names`], which the cell
//!   validation applies first, at the cell's lines: here it is a last guard.
//!   All declared names are unique ignoring case and differ from the module
//!   name, `main` and every speed and zone name (see [`target_names`]); a via
//!   whose name is taken by any of them steps aside (`via01_01_x1`, ...).
//! - One `CONST jointtarget` per target and one `MoveAbsJ` per target, in the
//!   same order, so each name is used by exactly one move.
//! - Free text in the header (`generator`, `cell_file`, paths, `planner`) is
//!   made printable ASCII: each character outside `' '..='~'` becomes `?`,
//!   surrounding spaces are trimmed, and empty text becomes `-`.

mod data;
mod format;
mod header;
mod target_names;

pub use data::{AxisRanges, Pose, RobTarget, ToolData, WobjData, NO_EXTERNAL_AXES};
pub use format::format_fixed;
pub use header::{Header, NO_CONTROLLER};
pub use target_names::{target_names, target_names_avoiding};

use crate::names::{check_data_name, check_identifier, robtarget_name, IdentifierError};
use crate::precision::JOINT_DECIMALS;
#[cfg(test)]
use header::comment_text;
use header::header_lines;

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
    /// RAPID tooldata every move uses, e.g. `"tool0"` (declared by the module when
    /// [`tooldata`](Self::tooldata) is given).
    pub tool: String,
    /// The tooldata the module declares under the name [`tool`](Self::tool), if any.
    pub tooldata: Option<ToolData>,
    /// The work object the module declares and every move names (`\WObj:=`), if any.
    pub wobj: Option<WobjData>,
    /// The robot's axis ranges: no joint value outside them is written.
    pub ranges: AxisRanges,
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

/// One `CONST jointtarget` of the module (a joint position to visit) and the move into it.
#[derive(Debug, Clone, PartialEq)]
pub struct JointTarget {
    /// Cell point or via.
    pub kind: TargetKind,
    /// Controller values of axes 1..6 in degrees.
    pub axes_deg: [f64; 6],
    /// RAPID speeddata of the move into it, e.g. `"v300"`.
    pub speed: String,
    /// RAPID zonedata of the move into it, e.g. `"fine"`.
    pub zone: String,
    /// For a cell point given as a robtarget: the `CONST robtarget` written beside it (named
    /// by [`robtarget_name`]).
    pub robtarget: Option<RobTarget>,
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
    /// A generated name (a via's, a robtarget's) is not a valid RAPID identifier (too long).
    #[error("generated name `{name}` for {what} is not a valid RAPID name: {source}")]
    InvalidGeneratedName {
        /// The generated name.
        name: String,
        /// What it names ("via 2 of leg 0", "the robtarget of point `W1`").
        what: String,
        /// The rule it breaks.
        source: IdentifierError,
    },
    /// The speed, zone, tool or work object name is not a RAPID identifier.
    #[error("invalid RAPID {role} name `{name}`: {source}")]
    InvalidDataName {
        /// `"speed"`, `"zone"`, `"tool"` or `"wobj"`.
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
    /// A joint value lies outside the robot's ranges (the earlier stages never give one).
    #[error("internal error: target `{name}` is out of range: {why}; the controller would refuse it, so no module is written")]
    OutOfRange {
        /// The target's name.
        name: String,
        /// The limit broken.
        why: String,
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
    speed: String,
    zone: String,
    /// `(name, value)` of the robtarget written beside it.
    robtarget: Option<(String, String)>,
}

#[derive(Serialize)]
struct ModuleCtx<'a> {
    module: &'a str,
    header: Vec<String>,
    /// `(name, value)` of the declared tooldata and wobjdata.
    tooldata: Option<(String, String)>,
    wobjdata: Option<(String, String)>,
    targets: Vec<TargetCtx>,
    tool: &'a str,
    /// `\WObj:=<name>`, or empty.
    wobj_arg: String,
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

/// Renders `program` as the complete text of a RAPID module (see the module
/// documentation for the exact shape and the guarantees).
///
/// Checks, in this order: module name ([`check_identifier`]); tool and work
/// object names (declared: [`check_identifier`]; used: identifier shape, not a
/// reserved word); every speed and zone name; header numbers finite;
/// `header.moves == targets.len() - 1`; target names ([`target_names_avoiding`]:
/// a via steps aside for the module's other names), the robtarget names
/// ([`robtarget_name`]); no declared name equal to another, to
/// `main` or to a speed, zone or tool name (ignoring case); axis values finite
/// and in range. The first failure is returned.
pub fn render(program: &Program) -> Result<String, RapidError> {
    check_identifier(&program.module).map_err(|source| RapidError::InvalidModuleName {
        name: program.module.clone(),
        source,
    })?;
    let data_name = |role: &'static str, name: &str, declared: bool| {
        match declared {
            true => check_identifier(name),
            false => check_data_name(name),
        }
        .map_err(|source| RapidError::InvalidDataName {
            role,
            name: name.to_string(),
            source,
        })
    };
    data_name("tool", &program.tool, program.tooldata.is_some())?;
    if let Some(w) = &program.wobj {
        data_name("wobj", &w.name, true)?;
    }
    for t in &program.targets {
        data_name("speed", &t.speed, false)?;
        data_name("zone", &t.zone, false)?;
    }

    let header = header_lines(program)?;
    let actual = program.targets.len().saturating_sub(1);
    if program.header.moves != actual {
        return Err(RapidError::MovesMismatch {
            header: program.header.moves,
            actual,
        });
    }

    // Vias step aside for the module's other names (a cell point that takes one is a clash,
    // refused by the cell validation at its line, and below as a last guard).
    let others = other_names(program);
    let reserved: Vec<&str> = others.iter().map(String::as_str).collect();
    let target_names = target_names_avoiding(&program.targets, &reserved)?;
    check_name_space(program, &target_names)?;

    let mut targets = Vec::with_capacity(program.targets.len());
    for (target, name) in program.targets.iter().zip(target_names) {
        let mut axes = Vec::with_capacity(6);
        for (k, &value) in target.axes_deg.iter().enumerate() {
            let value = finite(format!("axis {} of target `{name}`", k + 1), value)?;
            axes.push(format_fixed(value, JOINT_DECIMALS));
        }
        if let Some(why) = program.ranges.violation(&target.axes_deg) {
            return Err(RapidError::OutOfRange { name, why });
        }
        let robtarget = match &target.robtarget {
            Some(r) => {
                let rname = robtarget_name(&name);
                let value = data::robtarget(&rname, r)?;
                Some((rname, value))
            }
            None => None,
        };
        targets.push(TargetCtx {
            name,
            axes: axes.join(","),
            speed: target.speed.clone(),
            zone: target.zone.clone(),
            robtarget,
        });
    }

    let ctx = ModuleCtx {
        module: &program.module,
        header,
        tooldata: match &program.tooldata {
            Some(t) => Some((program.tool.clone(), data::tooldata(&program.tool, t)?)),
            None => None,
        },
        wobjdata: match &program.wobj {
            Some(w) => Some((w.name.clone(), data::wobjdata(w)?)),
            None => None,
        },
        targets,
        tool: &program.tool,
        wobj_arg: match &program.wobj {
            Some(w) => format!("\\WObj:={}", w.name),
            None => String::new(),
        },
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

/// The module's names other than its `CONST jointtarget`s: the module, `main`, the tool, the
/// work object, every speed and zone, and the `CONST robtarget`s of the cell points that have
/// one. The vias' names avoid them ([`target_names_avoiding`]).
fn other_names(program: &Program) -> Vec<String> {
    let mut names = vec![
        program.module.clone(),
        "main".to_string(),
        program.tool.clone(),
    ];
    names.extend(program.wobj.iter().map(|w| w.name.clone()));
    for t in &program.targets {
        names.push(t.speed.clone());
        names.push(t.zone.clone());
        if let (TargetKind::CellPoint { name }, Some(_)) = (&t.kind, &t.robtarget) {
            names.push(robtarget_name(name));
        }
    }
    names.sort_unstable();
    names.dedup();
    names
}

/// One name space: the declared names (the module, the tool and work object when declared,
/// every `CONST`) differ from each other and from the names the module uses (`main`, the tool
/// when not declared, every speed and zone).
fn check_name_space(program: &Program, target_names: &[String]) -> Result<(), RapidError> {
    let mut used: Vec<(String, String)> = vec![(
        "main".to_string(),
        "PROC main of the generated module".to_string(),
    )];
    let mut declared: Vec<(String, String)> = vec![(
        program.module.clone(),
        format!("the module name `{}`", program.module),
    )];
    let tool = (
        program.tool.clone(),
        format!("the tool data `{}`", program.tool),
    );
    match program.tooldata {
        Some(_) => declared.push(tool),
        None => used.push(tool),
    }
    if let Some(w) = &program.wobj {
        declared.push((w.name.clone(), format!("the work object `{}`", w.name)));
    }
    for t in &program.targets {
        for (role, name) in [("speed", &t.speed), ("zone", &t.zone)] {
            if !used.iter().any(|(n, _)| n == name) {
                used.push((name.clone(), format!("the {role} data `{name}`")));
            }
        }
    }
    for name in target_names {
        declared.push((name.clone(), format!("the target `{name}`")));
    }
    for (t, name) in program.targets.iter().zip(target_names) {
        if t.robtarget.is_some() {
            let r = robtarget_name(name);
            check_identifier(&r).map_err(|source| RapidError::InvalidGeneratedName {
                name: r.clone(),
                what: format!("the robtarget of point `{name}`"),
                source,
            })?;
            declared.push((r.clone(), format!("the robtarget `{r}`")));
        }
    }
    for (i, (name, _)) in declared.iter().enumerate() {
        let clash = used
            .iter()
            .chain(&declared[..i])
            .find(|(n, _)| n.eq_ignore_ascii_case(name));
        if let Some((_, other)) = clash {
            return Err(RapidError::NameClash {
                name: name.clone(),
                other: other.clone(),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
