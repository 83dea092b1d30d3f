//! One error type for the whole run, and the one message a user sees.
//!
//! Each stage has its own typed error; this wraps them, says which exit status each one gets,
//! and renders it pointing at the input: `file:line:column`, the offending line of the cell with
//! a caret, the reason, and a help line where one helps. Errors found after parsing (a point that
//! cannot be reached, no path between two points) carry the location of the item they are about.

use crate::cell::{CellError, Loc};
use crate::excerpt;
use crate::output::cspace_svg::PictureError;
use crate::output::preview::PreviewError;
use crate::output::rapid::{RapidError, TemplateError};
use crate::output::report::ReportError;
use crate::place::locate::LocateError;
use crate::place::PlaceError;
use crate::plan::PlanError;
use crate::process::ProcessError;
use crate::robot::ik::IkError;
use crate::robot::RobotError;
use std::path::PathBuf;

/// Exit statuses (also in docs/errors.md).
pub mod exit {
    /// The cell file or the robot files are wrong (syntax, unknown key, bad value, bad URDF).
    pub const INPUT: u8 = 1;
    /// Command-line usage (clap's own status).
    pub const USAGE: u8 = 2;
    /// The input is valid but cannot be planned: a point out of reach or in collision, no base
    /// position, no path, a search that fails.
    pub const PLANNING: u8 = 3;
    /// The module could not be rendered or written.
    pub const OUTPUT: u8 = 4;
}

#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error(transparent)]
    Cell(#[from] CellError),
    #[error("{source}")]
    Robot { source: RobotError, loc: Loc },
    #[error(transparent)]
    Place(#[from] PlaceError),
    #[error("{source}")]
    Plan { source: PlanError, loc: Loc },
    /// A process move (approach, retract, linear, circular) that cannot be followed or proven.
    #[error(transparent)]
    Process {
        /// Boxed: it is large and errors travel in `Result`s.
        source: Box<ProcessError>,
    },
    #[error(transparent)]
    Rapid(#[from] RapidError),
    #[error("cannot write {path}: {source}")]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error(transparent)]
    Picture(#[from] PictureError),
    /// The user's module template (`--template`): an input error at the template's line.
    #[error(transparent)]
    Template(TemplateError),
    #[error(transparent)]
    Preview(#[from] PreviewError),
    #[error(transparent)]
    Report(#[from] ReportError),
    /// A budget of the run is passed (`budget`): an input error, before any work.
    #[error("{source}")]
    Budget {
        source: crate::budget::Exceeded,
        loc: Loc,
    },
    /// `compare`: every method failed (each reason is in the table).
    #[error("no method found a route through the cell ({})", .failures.join("; "))]
    NoMethodSucceeded { failures: Vec<String> },
}

impl Error {
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Cell(_) | Error::Robot { .. } | Error::Template(_) | Error::Budget { .. } => {
                exit::INPUT
            }
            Error::Rapid(RapidError::UserTemplate(_)) => exit::INPUT,
            Error::Place(e) if e.is_input() => exit::INPUT,
            Error::Place(_)
            | Error::Plan { .. }
            | Error::Process { .. }
            | Error::NoMethodSucceeded { .. } => exit::PLANNING,
            Error::Rapid(_)
            | Error::Write { .. }
            | Error::Picture(_)
            | Error::Preview(_)
            | Error::Report(_) => exit::OUTPUT,
        }
    }

    /// Where in the cell file the error points, if anywhere.
    pub fn loc(&self) -> Option<Loc> {
        match self {
            Error::Cell(e) => e.loc(),
            Error::Place(e) => Some(e.loc()),
            Error::Robot { loc, .. } | Error::Plan { loc, .. } | Error::Budget { loc, .. } => {
                Some(*loc)
            }
            Error::Process { source } => Some(source.loc()),
            Error::Rapid(_)
            | Error::Write { .. }
            | Error::Picture(_)
            | Error::Template(_)
            | Error::Preview(_)
            | Error::Report(_)
            | Error::NoMethodSucceeded { .. } => None,
        }
    }

    pub(crate) fn help(&self) -> Option<String> {
        match self {
            Error::Cell(e) => e.help().map(str::to_string),
            Error::Process { source } => Some(source.help().to_string()),
            Error::Budget { .. } => Some("every input that drives memory or time has a budget, checked before the work: docs/limits.md lists them, what each bounds and how to stay within it".into()),
            Error::Plan {
                source: PlanError::PointBlocked { .. },
                ..
            } => Some("every cell point must be in range and keep the clearance from every obstacle; move the point or the obstacle, or lower planner.clearance".into()),
            Error::Plan {
                source: PlanError::NoPath { .. },
                ..
            } => Some("a finer planner.grid or a smaller planner.clearance may open a passage; `gen-rapid --svg FILE` draws the blocked nodes".into()),
            Error::Plan {
                source: PlanError::SearchFailed { .. },
                ..
            } => Some("the extensile search (the default) and the neighboring search step diagonally too; `gen-rapid compare CELL` runs all three".into()),
            Error::Plan {
                source: PlanError::NoJoin { .. },
                ..
            } => Some("move the point away from the obstacles, or try a smaller planner.clearance or another planner.grid; `gen-rapid --svg FILE` draws the blocked nodes".into()),
            Error::Plan {
                source: PlanError::WristTurn { .. },
                ..
            } => Some("only axes 4..6 move between these two points; add a point between them whose axes 1..3 take the tool away from the obstacle, or give the second point a wrist the tool can turn to".into()),
            Error::Robot {
                source: RobotError::ReadController { .. },
                ..
            } => Some("robot.controller is resolved relative to the cell file; without it, the <stem>.controller.yaml beside the URDF is read if there is one".into()),
            Error::Robot {
                source: RobotError::Controller { .. },
                ..
            } => {
                use crate::robot::controller::{AXIS_ACCELERATION_DEG_S2 as A, AXIS_SPEED_DEG_S as V, MAX_AXIS_DEG as R};
                Some(format!("the fault is in the controller file named above (robot.controller, or the <stem>.controller.yaml beside the URDF): each axis a range within -{R} .. {R} deg, a speed within {} .. {} deg/s and an acceleration within {} .. {} deg/s^2 (docs/cell.md)", V[0], V[1], A[0], A[1]))
            }
            Error::Robot {
                source: RobotError::Model { .. },
                ..
            } => {
                use crate::robot::controller::MAX_AXIS_DEG as R;
                Some(format!("the fault is in the URDF named above: gen-rapid reads one serial chain of six revolute joints up to tool0, finite numbers, lengths within {} km, ranges within -{R} .. {R} deg, cylinders on the links of joints 1..3 (docs/cell.md)", crate::input::MAX_MAGNITUDE / 1e6))
            }
            Error::Robot {
                source: RobotError::UnknownModel { .. },
                ..
            } => Some(format!("the robots built into gen-rapid are {} (`gen-rapid robots` lists them); any other robot is named by its URDF file with robot.urdf", crate::robot::models::names())),
            Error::Robot { .. } => Some("robot.urdf is resolved relative to the cell file".into()),
            Error::Place(PlaceError::Range { .. }) => Some("joint values are controller values (what a jointtarget holds) and must lie in the robot's ranges, all six axes; a point without axes 4..6 takes robot.wrist".into()),
            Error::Place(PlaceError::Robtarget { hint: Some(h), .. }) => Some(h.clone()),
            Error::Place(PlaceError::Robtarget { .. }) => Some("a robtarget is the TCP pose [[x, y, z], [q1, q2, q3, q4]] in the work object's frame (mm, quaternion [w, x, y, z]) of the tool's TCP (tool.tframe); confdata [cf1, cf4, cf6, cfx] picks one of the arm's solutions, without it the one nearest the previous point is taken".into()),
            Error::Template(TemplateError::Invalid { out_of_fuel: true, .. })
            | Error::Rapid(RapidError::UserTemplate(TemplateError::Invalid { out_of_fuel: true, .. })) => Some(format!("a template may burn at most {} of minijinja's fuel (one an instruction, one for every 64 bytes of strings, lists and output it makes: a loop that never ends, runs too often or builds a huge string stops here); loop over the program's lists (docs/outputs.md, \"Your own module template\"), not over ranges of your own", crate::output::rapid::TEMPLATE_FUEL)),
            Error::Template(TemplateError::Invalid { over_cap: true, .. })
            | Error::Rapid(RapidError::UserTemplate(TemplateError::Invalid { over_cap: true, .. })) => Some(format!("a module holds at most {} MiB (docs/limits.md); a template writes each target and move once (docs/outputs.md, \"Your own module template\"), not in loops of its own", crate::output::rapid::MAX_MODULE_BYTES >> 20)),
            Error::Template(_) | Error::Rapid(RapidError::UserTemplate(_)) => Some("the template is minijinja (Jinja2) text rendered with strict undefined names: docs/outputs.md, \"Your own module template\" lists every name it may use".into()),
            Error::Rapid(RapidError::OutOfRange { .. }) => Some("this is a bug in gen-rapid: an earlier stage let an out-of-range value through; please report it with the cell file".into()),
            Error::Place(PlaceError::Locate { source: LocateError::PointOutOfReach { .. }, .. }) => Some("with `base: auto` the base stands on z = 0: move the point within the arm's reach of a base there, or give `base: [x, y, z]`".into()),
            Error::Place(PlaceError::Locate { .. }) => Some("`gen-rapid locate CELL --svg FILE` draws every point's reach region; move the points closer together or give `base: [x, y, z]`".into()),
            Error::Write { path, .. } if path.as_os_str() == "<stdout>" || path.as_os_str() == "<stderr>" => Some("stdout takes the module (without -o), compare's table and locate's report, stderr the summary line and the messages: each must be open and writable to the end of the run, or the run fails (exit status 4) and puts no file in place".into()),
            Error::Write { .. } => Some("the file's directory must exist and be writable, and the file must be neither a directory nor a file the run reads; no file of the run is written unless all of them can be (a device or pipe is written last, after them)".into()),
            Error::Place(PlaceError::Ik { source, .. }) if matches!(**source, IkError::Unreachable { .. }) => Some("`xyz` is the wrist centre in the cell frame (mm); `gen-rapid locate CELL` shows which base positions reach every point".into()),
            Error::Place(PlaceError::Ik { .. }) => Some("`xyz` is the wrist centre in the cell frame (mm); `branch:` picks one of its four arm solutions (front or back, elbow up or down), else the one nearest the previous point is taken".into()),
            Error::Place(PlaceError::Arm { .. } | PlaceError::SixAxis { .. }) => Some("gen-rapid's inverse kinematics needs a six-axis arm whose axis 2 is perpendicular to axis 1 and whose axes 4..6 meet in one point (a spherical wrist), as robots/irb1400.urdf".into()),
            Error::Plan {
                source: PlanError::Unsafe { .. },
                ..
            } => Some("this is a bug in gen-rapid: a move it planned could not be proven after rounding; please report it with the cell file (another planner.grid may avoid it)".into()),
            _ => None,
        }
    }

    /// The place of a fault in a file other than the cell (the user's template, the controller
    /// file): its path, 1-based line and column when known, and that line.
    fn elsewhere(&self) -> Option<Elsewhere<'_>> {
        match self {
            Error::Template(TemplateError::Invalid {
                path,
                line,
                column,
                line_text,
                ..
            })
            | Error::Rapid(RapidError::UserTemplate(TemplateError::Invalid {
                path,
                line,
                column,
                line_text,
                ..
            })) => Some((
                path,
                line.map(|l| l as u64),
                column.map(|c| c as u64),
                line_text.as_deref(),
            )),
            Error::Robot {
                source:
                    RobotError::Controller {
                        path,
                        line,
                        column,
                        line_text,
                        ..
                    },
                ..
            } if *line > 0 => Some((
                path,
                Some(*line),
                (*column > 0).then_some(*column),
                line_text.as_deref(),
            )),
            _ => None,
        }
    }

    /// The message for stderr: `error: ...`, then the place in the cell, then help. Bounded
    /// whatever the input ([`crate::excerpt`]): a long source line is shown as a window around
    /// the column, a long message is cut.
    pub fn render(&self, file: &str, text: Option<&str>) -> String {
        let mut out = format!("error: {}\n", excerpt::message(&self.to_string()));
        if let Some((path, line, column, line_text)) = self.elsewhere() {
            // The place in the file at fault (the template, the controller file), not the
            // cell's (bounded like a cell's line).
            out += &match line {
                Some(l) => format!(
                    "  --> {}:{l}{}\n",
                    path.display(),
                    column.map(|c| format!(":{c}")).unwrap_or_default()
                ),
                None => format!("  --> {}\n", path.display()),
            };
            if let (Some(l), Some(t)) = (line, line_text) {
                let window = excerpt::line_window(t, column.unwrap_or(1));
                let num = l.to_string();
                let pad = " ".repeat(num.len());
                out += &format!("{pad} |\n{num} | {}\n", window.text);
                if column.is_some() {
                    out += &format!("{pad} | {}^\n", window.caret_pad());
                }
            }
        } else if let Some(loc) = self.loc().filter(|l| l.line > 0) {
            out += &format!("  --> {file}:{}:{}\n", loc.line, loc.column);
            if let Some(line) = text.and_then(|t| excerpt::nth_line(t, loc.line)) {
                let window = excerpt::line_window(line, loc.column);
                let num = loc.line.to_string();
                let pad = " ".repeat(num.len());
                let caret = window.caret_pad();
                out += &format!("{pad} |\n{num} | {}\n{pad} | {caret}^\n", window.text);
            }
        } else if matches!(
            self,
            Error::Cell(CellError::Read { .. }) | Error::Template(TemplateError::Read { .. })
        ) {
            // The message names the file already.
        } else if !matches!(self, Error::Write { .. }) {
            out += &format!("  --> {file}\n");
        }
        if let Some(h) = self.help() {
            out += &format!("help: {}\n", excerpt::message(&h));
        }
        out
    }
}

/// A place in a file other than the cell: its path, the 1-based line and column when known,
/// and that line's text.
type Elsewhere<'a> = (
    &'a std::path::Path,
    Option<u64>,
    Option<u64>,
    Option<&'a str>,
);

/// A failure with the cell file's name and text, ready to print (the text, when it could be
/// read, lets the message show the offending line), and notes on what was done about it (a
/// picture of the failure drawn, or why none was).
#[derive(Debug)]
pub struct Failure {
    /// Boxed: the error is large and a `Result` carrying it should not be.
    pub error: Box<Error>,
    pub file: String,
    pub text: Option<String>,
    /// Printed after the message, one `note:` line each.
    pub notes: Vec<String>,
}

impl Failure {
    pub fn render(&self) -> String {
        let mut out = self.error.render(&self.file, self.text.as_deref());
        for note in &self.notes {
            out += &format!("note: {}\n", excerpt::message(note));
        }
        out
    }
}
