//! RAPID output stage (long: the render pass, its template context and the module's guards):
//! turns an already planned path into the text of an ABB RAPID module (IRB 1400 on an IRC5
//! controller, loaded by RobotStudio).
//!
//! Everything the text needs is decided by earlier stages and handed over as a
//! [`Program`]; this stage only validates names, formats numbers and fills the
//! template `templates/module.mod.j2` (embedded at compile time, rendered with
//! minijinja in strict-undefined mode, no auto-escaping, trailing newline kept),
//! or the user's template (`--template FILE`, [`ModuleTemplate`]), which sees the
//! same context (docs/outputs.md, "Your own module template": `module`, `proc`, `header`,
//! `facts`, `tool`, `wobj`, `wobj_arg`, `targets`, `moves` with each move's instruction, kind,
//! target and actions ([`written_moves`]), `loads`, `conf_on`, and `settings`, the template
//! settings of `--set`). A template holds no
//! logic beyond loops and variable output; every number is formatted here with
//! [`format_fixed`]. An error of the user's template is an input error at its
//! line ([`TemplateError`]). The guarantees below are the embedded template's; a
//! user's template keeps the names and numbers, its text is its own.
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
//!     ! cycle: closed: ... | open: the routine ends at <last>, not where it starts (<first>); ...
//!     ! zoned vias: <N> of <M> (via zone <zone>)
//!     ! the paper's method alone: <n> moves, <t, 2 decimals> s   (only when known)
//!
//!     PERS tooldata <tool> := [TRUE,[[x,y,z],[q1,q2,q3,q4]],[mass,[cx,cy,cz],[1,0,0,0],0,0,0]];
//!     PERS wobjdata <wobj> := [FALSE,TRUE,"",[[x,y,z],[q1,q2,q3,q4]],[[0,0,0],[1,0,0,0]]];
//!                                                     (each only when declared, then a blank line)
//!     CONST jointtarget <name> := [[a1,a2,a3,a4,a5,a6],[9E9,9E9,9E9,9E9,9E9,9E9]];
//!                                                     (one per joint target and via)
//!     CONST robtarget <name>_rt := [[x,y,z],[q1,q2,q3,q4],[cf1,cf4,cf6,cfx],[9E9,...]];
//!                                                     (one per robtarget point, in its place)
//!
//!     PROC <proc>()                                   (`main` unless the cell or --proc names it)
//!         ConfJ \On;                                  (both only when the module moves to a
//!         ConfL \On;                                   robtarget)
//!         MoveAbsJ <name>\NoEOffs, <speed>, <zone>, <tool>[\WObj:=<wobj>];   (a joint target, a via)
//!         MoveJ <name>_rt, <speed>, <zone>, <tool>[\WObj:=<wobj>];           (a robtarget point)
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
//!   name, the routine's and every speed and zone name (see [`target_names`]); a via
//!   whose name is taken by any of them steps aside (`via01_01_x1`, ...).
//! - One `CONST jointtarget` per joint target and via, one `CONST robtarget` per
//!   robtarget point, and one move per target (`MoveAbsJ` to a jointtarget, `MoveJ`
//!   to a robtarget), in the same order, so each name is used by exactly one move.
//! - Free text in the header (`generator`, `cell_file`, paths, `planner`) is
//!   made printable ASCII: each character outside `' '..='~'` becomes `?`,
//!   surrounding spaces are trimmed, and empty text becomes `-`.

mod data;
mod format;
mod header;
mod moves;
mod settings;
mod tags;
mod target_names;

pub use data::{AxisRanges, Pose, RobTarget, ToolData, WobjData, NO_EXTERNAL_AXES};
pub use format::format_fixed;
pub use header::{Ends, Header, NO_CONTROLLER};
pub use moves::{written_moves, WrittenAction, WrittenMove};
pub use settings::{parse_setting, settings_map};
pub use target_names::{target_names, target_names_avoiding};

use crate::names::{check_data_name, check_identifier, robtarget_name, IdentifierError};
use crate::precision::JOINT_DECIMALS;
#[cfg(test)]
use header::comment_text;

use minijinja::{value::Serde, AutoEscape, Environment, UndefinedBehavior};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

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
    /// The work objects the module declares, in the cell's order; each move names the one of
    /// its target ([`JointTarget::wobj`]).
    pub wobjs: Vec<WobjData>,
    /// The robot's axis ranges: no joint value outside them is written.
    pub ranges: AxisRanges,
    /// The name of the routine that makes the moves (`motion.proc`, `--proc`; default `main`).
    pub proc_name: String,
    /// The loaddata the module declares (`loads:`), in the cell's order.
    pub loads: Vec<LoadData>,
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
    /// A point's target reached again (a `{ revisit: NAME }` entry, or the leg closing the
    /// cycle): moved to by the point's own data, declares nothing.
    Revisit {
        /// The point's name.
        point: String,
    },
    /// A robtarget point's approach pose, `RelTool(<point>_rt, 0, 0, -D)` (declares nothing), or
    /// with a robtarget of its own (another configuration than the point's) `<point>_app`.
    Approach {
        /// The point's name.
        point: String,
    },
    /// A robtarget point's retract pose, `RelTool(<point>_rt, 0, 0, -D)` (declares nothing), or
    /// with a robtarget of its own `<point>_ret`.
    Retract {
        /// The point's name.
        point: String,
    },
}

/// How the move into a target runs.
#[derive(Debug, Clone, PartialEq)]
pub enum MoveHow {
    /// Joint interpolation: `MoveAbsJ` to a jointtarget, `MoveJ` to a robtarget point's robtarget
    /// or to an approach pose (`RelTool`).
    Joint,
    /// `MoveL` to the point's robtarget, or to a retract pose (`RelTool`).
    Linear,
    /// `MoveC <point>_via, <point>_rt`: the circle point written as its own robtarget.
    Circular { via: RobTarget },
}

/// An action done after the move into a target, as RAPID writes it.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// `SetDO signal, 0|1;`
    SetDo { signal: String, value: bool },
    /// `PulseDO signal;`
    PulseDo { signal: String },
    /// `WaitDI signal, 0|1;`
    WaitDi { signal: String, value: bool },
    /// `WaitTime s;` (3 decimals)
    WaitTime { time_s: f64 },
    /// `GripLoad load;`
    GripLoad { load: String },
}

/// A `PERS loaddata` the module declares.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadData {
    pub name: String,
    pub mass_kg: f64,
    /// Centre of gravity in the tool frame, mm.
    pub cog_mm: [f64; 3],
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
    /// by [`robtarget_name`]); for an approach or retract pose, its own robtarget (named as the
    /// target), if it has one.
    pub robtarget: Option<RobTarget>,
    /// How the move into it runs.
    pub how: MoveHow,
    /// For an approach or retract pose: how far back along the tool's z axis, mm.
    pub offset_mm: Option<f64>,
    /// The actions done after the move into it, in order.
    pub actions: Vec<Action>,
    /// The work object the move into it names (`\WObj:=`): an index into
    /// [`Program::wobjs`]; `None`: none (wobj0).
    pub wobj: Option<usize>,
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
    /// The routine's name is not a valid RAPID identifier.
    #[error("invalid RAPID routine name `{name}`: {source}")]
    InvalidProcName {
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
    /// The embedded template failed to compile or render (a defect of gen-rapid).
    #[error("RAPID template error: {0}")]
    Template(#[from] minijinja::Error),
    /// The user's template (`--template`) failed to render: an input error at its line.
    #[error(transparent)]
    UserTemplate(TemplateError),
}

/// Why the user's module template cannot be used: an input error pointing at the template.
#[derive(Debug, thiserror::Error)]
pub enum TemplateError {
    #[error("cannot read template {path}: {source}")]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    /// It does not parse, or rendering it fails (an undefined name: the context is strict).
    #[error("template {}: {message}", .path.display())]
    Invalid {
        path: PathBuf,
        /// 1-based line and column of the fault in the template, when minijinja knows it.
        line: Option<usize>,
        column: Option<usize>,
        /// That line of the template.
        line_text: Option<String>,
        message: String,
        /// Rendering ran past [`TEMPLATE_FUEL`].
        out_of_fuel: bool,
        /// The module passed [`MAX_MODULE_BYTES`].
        over_cap: bool,
    },
}

impl TemplateError {
    fn of(path: &Path, source: &str, e: &minijinja::Error) -> TemplateError {
        let line = e.line();
        let line_text =
            line.and_then(|l| source.lines().nth(l.checked_sub(1)?).map(str::to_string));
        // The column of the range's start, on its line, in characters (as a cell's columns and
        // the caret count them; the range is in bytes).
        let column = e.range().and_then(|r| {
            let before = source.get(..r.start)?;
            let line_start = before.rfind('\n').map_or(0, |i| i + 1);
            Some(before[line_start..].chars().count() + 1)
        });
        let message = match e.detail() {
            Some(d) => format!("{}: {d}", e.kind()),
            None => e.kind().to_string(),
        };
        TemplateError::Invalid {
            path: path.to_path_buf(),
            line,
            column,
            line_text,
            message,
            out_of_fuel: e.kind() == minijinja::ErrorKind::OutOfFuel,
            over_cap: false,
        }
    }
}

/// A module template: the embedded `templates/module.mod.j2`, or the user's (`--template FILE`).
/// Both see the same context, which docs/outputs.md lists for template writers.
#[derive(Clone, Debug)]
pub struct ModuleTemplate {
    /// The user's file; `None` for the embedded template.
    path: Option<PathBuf>,
    source: String,
    /// The template settings (`--set NAME=VALUE`), the context's `settings`.
    settings: BTreeMap<String, String>,
}

impl ModuleTemplate {
    /// The embedded template.
    pub fn embedded() -> ModuleTemplate {
        ModuleTemplate {
            path: None,
            source: TEMPLATE.to_string(),
            settings: BTreeMap::new(),
        }
    }

    /// The user's template read from `path`, compiled once here so that a syntax error is found
    /// before any planning (pointing at its line).
    pub fn user(path: &Path, source: String) -> Result<ModuleTemplate, TemplateError> {
        if let Some(long) = tags::long_tag(&source) {
            return Err(TemplateError::Invalid {
                path: path.to_path_buf(),
                line: Some(long.line),
                column: Some(long.column),
                line_text: source.lines().nth(long.line - 1).map(str::to_string),
                message: format!(
                    "this tag holds {} characters, more than the {} a tag may hold",
                    long.chars,
                    tags::MAX_TAG_CHARS
                ),
                out_of_fuel: false,
                over_cap: false,
            });
        }
        let t = ModuleTemplate {
            path: Some(path.to_path_buf()),
            source,
            settings: BTreeMap::new(),
        };
        on_template_stack(|| t.environment().map(drop))
            .map_err(|e| TemplateError::of(path, &t.source, &e))?;
        Ok(t)
    }

    /// This template with `settings` (`--set`), which it reads as `settings.NAME`.
    pub fn with_settings(self, settings: BTreeMap<String, String>) -> ModuleTemplate {
        ModuleTemplate { settings, ..self }
    }

    /// The name minijinja knows it by (its file name; `module.mod.j2` for the embedded one).
    fn name(&self) -> String {
        self.path
            .as_ref()
            .and_then(|p| p.file_name())
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_else(|| "module.mod.j2".to_string())
    }

    /// The environment with this one template: strict undefined (a name the context lacks is an
    /// error, never an empty string), no auto-escaping, blocks trimmed, the final newline kept,
    /// and at most [`TEMPLATE_FUEL`] instructions (a user's template that loops for ever, or
    /// 10^10 times, is an error, not a hang).
    fn environment(&self) -> Result<Environment<'_>, minijinja::Error> {
        self.environment_counting(Arc::new(AtomicUsize::new(0)))
    }

    /// [`environment`](Self::environment) whose expressions refuse to write past
    /// [`MAX_MODULE_BYTES`]: `written` counts the bytes the render has written (its writer
    /// adds them), and each `{{ ... }}` checks it after writing, so a template that passes the
    /// cap fails at that expression's line.
    fn environment_counting(
        &self,
        written: Arc<AtomicUsize>,
    ) -> Result<Environment<'_>, minijinja::Error> {
        let mut env = Environment::new();
        env.set_fuel(Some(TEMPLATE_FUEL));
        env.set_formatter(move |out, state, value| {
            minijinja::escape_formatter(out, state, value)?;
            if written.load(Ordering::Relaxed) > MAX_MODULE_BYTES {
                return Err(minijinja::Error::new(
                    minijinja::ErrorKind::InvalidOperation,
                    over_cap_message(),
                ));
            }
            Ok(())
        });
        env.set_undefined_behavior(UndefinedBehavior::Strict);
        env.set_auto_escape_callback(|_| AutoEscape::None);
        env.set_syntax(
            minijinja::syntax::SyntaxConfig::builder()
                .trim_blocks(true)
                .lstrip_blocks(true)
                .keep_trailing_newline(true)
                .build()?,
        );
        env.add_template_owned(self.name(), self.source.clone())?;
        Ok(env)
    }

    /// Renders the context; an error of the user's template becomes [`TemplateError`].
    fn render(&self, ctx: &ModuleCtx) -> Result<String, RapidError> {
        let name = self.name();
        let written = Arc::new(AtomicUsize::new(0));
        let mut out = Capped {
            bytes: Vec::new(),
            written: Arc::clone(&written),
        };
        let rendered = on_template_stack(|| {
            self.environment_counting(Arc::clone(&written))
                .and_then(|env| {
                    env.get_template(&name)?
                        .render_captured_to(Serde(ctx), &mut out)
                        .map(drop)
                })
        })
        .and_then(|()| {
            // Raw text past the cap with no expression after it: the cap, at no line.
            if written.load(Ordering::Relaxed) > MAX_MODULE_BYTES {
                Err(minijinja::Error::new(
                    minijinja::ErrorKind::InvalidOperation,
                    over_cap_message(),
                ))
            } else {
                Ok(())
            }
        });
        let over_cap = written.load(Ordering::Relaxed) > MAX_MODULE_BYTES;
        match (rendered, &self.path) {
            (Ok(()), _) => String::from_utf8(out.bytes).map_err(|e| {
                RapidError::Template(minijinja::Error::new(
                    minijinja::ErrorKind::InvalidOperation,
                    e.to_string(),
                ))
            }),
            (Err(e), Some(path)) => {
                let mut t = TemplateError::of(path, &self.source, &e);
                if let TemplateError::Invalid { over_cap: o, .. } = &mut t {
                    *o = over_cap;
                }
                Err(RapidError::UserTemplate(t))
            }
            (Err(e), None) => Err(RapidError::Template(e)),
        }
    }
}

/// The stack minijinja parses, compiles and renders a template on: it descends an expression
/// by recursion, and the tags' length (`tags::MAX_TAG_CHARS`) bounds the depth to what this
/// holds, whatever thread calls (a test's thread has 2 MiB).
const TEMPLATE_STACK_BYTES: usize = 32 << 20;

/// Runs `f` on a thread with [`TEMPLATE_STACK_BYTES`] of stack (an error if no thread can be
/// made).
fn on_template_stack<T: Send>(
    f: impl FnOnce() -> Result<T, minijinja::Error> + Send,
) -> Result<T, minijinja::Error> {
    let failed = |what: &str| {
        minijinja::Error::new(
            minijinja::ErrorKind::InvalidOperation,
            format!("the template's thread {what}"),
        )
    };
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .stack_size(TEMPLATE_STACK_BYTES)
            .spawn_scoped(scope, f)
            .map_err(|_| failed("could not be made"))?
            .join()
            .map_err(|_| failed("stopped"))?
    })
}

/// The most bytes a module may hold, through any template: far more than a module of the
/// largest cell a run takes (2 000 points and their vias: a few MB), the size of the largest
/// input file.
pub const MAX_MODULE_BYTES: usize = 64 << 20;

fn over_cap_message() -> String {
    format!(
        "the module passes {} MiB here, the most a module may hold",
        MAX_MODULE_BYTES >> 20
    )
}

/// The render's writer: keeps the module's bytes up to [`MAX_MODULE_BYTES`] and counts every
/// byte written, so the template's expressions can refuse to go on past the cap (memory stays
/// bounded: what passes the cap is counted, not kept).
struct Capped {
    bytes: Vec<u8>,
    written: Arc<AtomicUsize>,
}

impl std::io::Write for Capped {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        let total = self.written.fetch_add(b.len(), Ordering::Relaxed) + b.len();
        if total <= MAX_MODULE_BYTES {
            self.bytes.extend_from_slice(b);
        }
        Ok(b.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The fuel a template may burn (minijinja's: one a instruction, and one for every 64 bytes of
/// data it makes, strings, lists and output alike, so it bounds both time and memory): the
/// embedded template renders a module of 20 000 targets well within it (tests), a runaway
/// loop stops within a second, and a template that builds strings (a macro doubling one, a
/// string repeated) stops before it has made 1 GiB of them.
pub const TEMPLATE_FUEL: u64 = 16_000_000;

/// The template context (docs/outputs.md, "Your own module template"): every value already formatted;
/// templates hold no logic.
#[derive(Serialize)]
struct ModuleCtx {
    /// The module name.
    module: String,
    /// The routine's name (`main` unless `motion.proc` or `--proc` says otherwise).
    proc: String,
    /// The comment header's lines, without the leading `! `.
    header: Vec<String>,
    /// The header's facts one by one, formatted as the header writes them.
    facts: header::Facts,
    /// The tooldata the moves use: its name, and its value when the module declares it.
    tool: ToolCtx,
    /// The work object the module declares when it declares exactly one, or none.
    wobj: Option<DataCtx>,
    /// `\WObj:=<name>` of that one work object, or empty (each move's own: `moves[i].wobj_arg`).
    wobj_arg: String,
    /// Every work object the module declares, in the cell's order.
    wobjs: Vec<DataCtx>,
    /// One per `CONST jointtarget`, in visiting order.
    targets: Vec<TargetCtx>,
    /// One per move instruction, in order (move `i` goes to target `i`).
    moves: Vec<MoveCtx>,
    /// Whether the routine starts with `ConfJ \On; ConfL \On;`: the module moves to a
    /// robtarget, and the controller must reach it in its written confdata.
    conf_on: bool,
    /// The `PERS loaddata` the module declares.
    loads: Vec<DataCtx>,
    /// The template settings (`--set NAME=VALUE`), by name.
    settings: BTreeMap<String, String>,
}

#[derive(Serialize)]
struct ToolCtx {
    name: String,
    /// Whether the module declares it (`PERS tooldata`); else predefined or on the controller.
    declared: bool,
    /// The tooldata value `[TRUE,[[x,y,z],[q1,q2,q3,q4]],[mass,[cx,cy,cz],...]]` when declared.
    value: Option<String>,
}

/// A declared datum: its name and its value as RAPID writes it.
#[derive(Serialize)]
struct DataCtx {
    name: String,
    value: String,
}

#[derive(Serialize)]
struct TargetCtx {
    /// The target's name (a robtarget point's: the point's; its data is `robtarget.name`).
    name: String,
    /// Whether the module declares it as a `CONST jointtarget` (joint targets and vias; a
    /// robtarget point is moved to by its `CONST robtarget` alone).
    jointtarget: bool,
    /// `cell` (a point of the cell) or `via` (the planner's).
    kind: &'static str,
    /// `a1,a2,a3,a4,a5,a6` (deg, 3 decimals).
    axes: String,
    /// The jointtarget value `[[a1,...,a6],[9E9,9E9,9E9,9E9,9E9,9E9]]`.
    value: String,
    /// The speed and zone of the move into it.
    speed: String,
    zone: String,
    /// The `CONST robtarget` written beside a robtarget point, or none.
    robtarget: Option<DataCtx>,
    /// A circular move's circle point, `CONST robtarget <point>_via`, or none.
    via: Option<DataCtx>,
}

#[derive(Serialize)]
struct MoveCtx {
    /// `MoveAbsJ` (to a jointtarget), `MoveJ`, `MoveL` or `MoveC` (to a robtarget).
    instruction: &'static str,
    /// `joint` (an air move), `approach`, `linear`, `circular` or `retract`.
    kind: &'static str,
    /// The actions written after it, in order, as data (`kind`, `signal`, `value`, `load`,
    /// `seconds`) with their `text` (the instruction without its `;`).
    actions: Vec<WrittenAction>,
    /// The arguments before the speed, without `\NoEOffs`: the `ToPoint`, or `<CirPoint>,
    /// <ToPoint>` for `MoveC`.
    target: String,
    /// The `ToPoint` as written: a jointtarget or robtarget name, or `RelTool(...)`.
    to: String,
    /// The cell point it belongs to, or none (a via).
    point: Option<String>,
    /// The robtarget it goes to or stands on, or none (`MoveAbsJ`).
    robtarget: Option<String>,
    /// The jointtarget of a `MoveAbsJ`, or none.
    jointtarget: Option<String>,
    /// `MoveC`'s circle point, or none.
    circle_point: Option<String>,
    /// `RelTool`'s z offset as written (`-40.000`), or none.
    offset_mm: Option<String>,
    /// The digital outputs the routine's own `SetDO` have left at 1 while it runs, and after
    /// its actions (sorted).
    outputs_on: Vec<String>,
    outputs_on_after: Vec<String>,
    speed: String,
    zone: String,
    tool: String,
    /// The work object's name, or none.
    wobj: Option<String>,
    /// `\WObj:=<name>`, or empty.
    wobj_arg: String,
    /// The whole argument list: `<target>\NoEOffs, <speed>, <zone>, <tool>[\WObj:=<wobj>]`
    /// (without `\NoEOffs` for a robtarget).
    args: String,
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
/// the routine or to a speed, zone or tool name (ignoring case); axis values finite
/// and in range. The first failure is returned.
pub fn render(program: &Program) -> Result<String, RapidError> {
    render_with(program, &ModuleTemplate::embedded())
}

/// [`render`] through `template` (the same checks; the context is the same for every
/// template, so a user's template writes the same names and numbers).
pub fn render_with(program: &Program, template: &ModuleTemplate) -> Result<String, RapidError> {
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
    check_identifier(&program.proc_name).map_err(|source| RapidError::InvalidProcName {
        name: program.proc_name.clone(),
        source,
    })?;
    data_name("tool", &program.tool, program.tooldata.is_some())?;
    for w in &program.wobjs {
        data_name("wobj", &w.name, true)?;
    }
    for t in &program.targets {
        data_name("speed", &t.speed, false)?;
        data_name("zone", &t.zone, false)?;
    }

    let facts = header::facts(program)?;
    let header = facts.lines();
    let actual = program.targets.len().saturating_sub(1);
    if program.header.moves != actual {
        return Err(RapidError::MovesMismatch {
            header: program.header.moves,
            actual,
        });
    }

    let target_names = module_target_names(program)?;
    check_name_space(program, &target_names)?;

    let wobj_arg_of = |w: Option<&WobjData>| match w {
        Some(w) => format!("\\WObj:={}", w.name),
        None => String::new(),
    };
    // The one work object's argument, for a template that writes one for every move.
    let wobj_arg = match program.wobjs.as_slice() {
        [w] => wobj_arg_of(Some(w)),
        _ => String::new(),
    };
    let written = moves::written_moves(program, &target_names)?;
    let mut outputs: BTreeSet<String> = BTreeSet::new();
    let mut targets = Vec::with_capacity(program.targets.len());
    let mut moves = Vec::with_capacity(program.targets.len());
    for ((target, name), w) in program.targets.iter().zip(target_names).zip(&written) {
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
                let rname = data_name_of(target, &name);
                let value = data::robtarget(&rname, r)?;
                Some(DataCtx { name: rname, value })
            }
            None => None,
        };
        let axes = axes.join(",");
        let via = match &target.how {
            MoveHow::Circular { via } => {
                let vname = format!("{name}_via");
                let value = data::robtarget(&vname, via)?;
                Some(DataCtx { name: vname, value })
            }
            _ => None,
        };
        // The digital outputs the routine's own SetDO leave at 1 before this move and after
        // its actions (a template tells a seam by them, e.g. the weld signal on).
        let outputs_on = outputs.clone();
        for a in &target.actions {
            if let Action::SetDo { signal, value } = a {
                match value {
                    true => outputs.insert(signal.clone()),
                    false => outputs.remove(signal),
                };
            }
        }
        let wobj = target.wobj.and_then(|i| program.wobjs.get(i));
        let wobj_arg = wobj_arg_of(wobj);
        moves.push(MoveCtx {
            args: format!(
                "{}, {}, {}, {}{wobj_arg}",
                w.points(),
                target.speed,
                target.zone,
                program.tool
            ),
            instruction: w.instruction,
            kind: w.kind,
            actions: w.actions.clone(),
            target: w.target(),
            to: w.to.clone(),
            point: w.point.clone(),
            robtarget: w.robtarget.clone(),
            jointtarget: w.jointtarget.clone(),
            circle_point: w.circle_point.clone(),
            offset_mm: w.offset_mm.clone(),
            outputs_on: outputs_on.into_iter().collect(),
            outputs_on_after: outputs.iter().cloned().collect(),
            speed: target.speed.clone(),
            zone: target.zone.clone(),
            tool: program.tool.clone(),
            wobj: wobj.map(|w| w.name.clone()),
            wobj_arg,
        });
        // A revisit moves to its point's data and declares none.
        let robtarget = match target.kind {
            TargetKind::Revisit { .. } => None,
            _ => robtarget,
        };
        targets.push(TargetCtx {
            jointtarget: robtarget.is_none()
                && matches!(
                    target.kind,
                    TargetKind::CellPoint { .. } | TargetKind::Via { .. }
                ),
            value: format!("[[{axes}],{NO_EXTERNAL_AXES}]"),
            kind: match target.kind {
                TargetKind::CellPoint { .. } => "cell",
                TargetKind::Revisit { .. } => "revisit",
                TargetKind::Via { .. } => "via",
                TargetKind::Approach { .. } => "approach",
                TargetKind::Retract { .. } => "retract",
            },
            name,
            axes,
            speed: target.speed.clone(),
            zone: target.zone.clone(),
            robtarget,
            via,
        });
    }
    let mut wobjs = Vec::with_capacity(program.wobjs.len());
    for w in &program.wobjs {
        wobjs.push(DataCtx {
            name: w.name.clone(),
            value: data::wobjdata(w)?,
        });
    }
    let mut loads = Vec::with_capacity(program.loads.len());
    for l in &program.loads {
        loads.push(DataCtx {
            name: l.name.clone(),
            value: data::loaddata(l)?,
        });
    }

    let ctx = ModuleCtx {
        loads,
        conf_on: program.targets.iter().any(|t| t.robtarget.is_some()),
        module: program.module.clone(),
        proc: program.proc_name.clone(),
        header,
        facts,
        tool: ToolCtx {
            name: program.tool.clone(),
            declared: program.tooldata.is_some(),
            value: match &program.tooldata {
                Some(t) => Some(data::tooldata(&program.tool, t)?),
                None => None,
            },
        },
        wobj: match wobjs.as_slice() {
            [w] => Some(DataCtx {
                name: w.name.clone(),
                value: w.value.clone(),
            }),
            _ => None,
        },
        wobj_arg,
        wobjs,
        targets,
        moves,
        settings: template.settings.clone(),
    };
    let text = template.render(&ctx)?;
    debug_assert!(
        template.path.is_some()
            || (text.is_ascii() && !text.contains('\r') && text.ends_with('\n'))
    );
    Ok(text)
}

/// The name of a target's `CONST robtarget`: a cell point's `<name>_rt`; an approach or retract
/// pose's own robtarget is named as the target (`<point>_app`, `<point>_ret`).
fn data_name_of(target: &JointTarget, name: &str) -> String {
    match target.kind {
        TargetKind::Approach { .. } | TargetKind::Retract { .. } => name.to_string(),
        _ => robtarget_name(name),
    }
}

/// The names of the module's `CONST jointtarget`s, in order: the cell points' own, and the
/// vias' (`via<leg>_<index>`), which step aside for the module's other names (a cell point that
/// takes one is a clash, refused by the cell validation at its line, and by [`render`] as a
/// last guard). The preview and the report name the waypoints with it.
pub fn module_target_names(program: &Program) -> Result<Vec<String>, RapidError> {
    let others = other_names(program);
    let reserved: Vec<&str> = others.iter().map(String::as_str).collect();
    target_names_avoiding(&program.targets, &reserved)
}

/// The module's names other than its `CONST jointtarget`s: the module, the routine, the tool, the
/// work object, the loads, every speed and zone, and the `CONST robtarget`s of the cell points that have
/// one. The vias' names avoid them ([`target_names_avoiding`]).
fn other_names(program: &Program) -> Vec<String> {
    let mut names = vec![
        program.module.clone(),
        program.proc_name.clone(),
        program.tool.clone(),
    ];
    names.extend(program.wobjs.iter().map(|w| w.name.clone()));
    names.extend(program.loads.iter().map(|l| l.name.clone()));
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
/// every `CONST`, the routine) differ from each other and from the names the module uses (the tool
/// when not declared, every speed and zone).
fn check_name_space(program: &Program, target_names: &[String]) -> Result<(), RapidError> {
    let mut used: Vec<(String, String)> = Vec::new();
    let mut declared: Vec<(String, String)> = vec![
        (
            program.module.clone(),
            format!("the module name `{}`", program.module),
        ),
        (
            program.proc_name.clone(),
            format!("PROC {} of the generated module", program.proc_name),
        ),
    ];
    let tool = (
        program.tool.clone(),
        format!("the tool data `{}`", program.tool),
    );
    match program.tooldata {
        Some(_) => declared.push(tool),
        None => used.push(tool),
    }
    for w in &program.wobjs {
        declared.push((w.name.clone(), format!("the work object `{}`", w.name)));
    }
    let mut listed: HashSet<String> = used.iter().map(|(n, _)| n.clone()).collect();
    for t in &program.targets {
        for (role, name) in [("speed", &t.speed), ("zone", &t.zone)] {
            if listed.insert(name.clone()) {
                used.push((name.clone(), format!("the {role} data `{name}`")));
            }
        }
    }
    for (t, name) in program.targets.iter().zip(target_names) {
        if matches!(
            t.kind,
            TargetKind::CellPoint { .. } | TargetKind::Via { .. }
        ) {
            declared.push((name.clone(), format!("the target `{name}`")));
        }
    }
    for l in &program.loads {
        declared.push((l.name.clone(), format!("the load data `{}`", l.name)));
    }
    for (t, name) in program.targets.iter().zip(target_names) {
        if let MoveHow::Circular { .. } = t.how {
            let v = format!("{name}_via");
            declared.push((v.clone(), format!("the circle point `{v}`")));
        }
        if let (Some(_), false) = (&t.robtarget, matches!(t.kind, TargetKind::Revisit { .. })) {
            let r = data_name_of(t, name);
            check_identifier(&r).map_err(|source| RapidError::InvalidGeneratedName {
                name: r.clone(),
                what: format!("the robtarget of point `{name}`"),
                source,
            })?;
            declared.push((r.clone(), format!("the robtarget `{r}`")));
        }
    }
    // Each name (RAPID's case folding) and what it first was: the used names, then the
    // declared ones in order (a clash names the first, as a scan in that order would).
    let mut taken: HashMap<String, &str> = HashMap::new();
    for (n, what) in &used {
        taken.entry(n.to_ascii_lowercase()).or_insert(what.as_str());
    }
    for (name, what) in &declared {
        let key = name.to_ascii_lowercase();
        if let Some(other) = taken.get(&key) {
            return Err(RapidError::NameClash {
                name: name.clone(),
                other: (*other).to_string(),
            });
        }
        taken.insert(key, what.as_str());
    }
    Ok(())
}

#[cfg(test)]
mod tests;
