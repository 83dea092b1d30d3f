//! The load stage: the cell file and the robot it names, the only file reads of a run besides
//! the user's module template (`pipeline::load_template`). Everything after it is a pure
//! function of what it read, so a benchmark loads once and runs the rest as often as it likes.

mod budgets;
pub use budgets::check_budgets;

use crate::cell::{self, Cell};
use crate::error::{Error, Failure};
use crate::excerpt;
use crate::robot::{Robot, RobotError};
use std::path::Path;

/// The load stage's result: the cell, its text (for pointing at lines) and its robot.
pub struct Loaded {
    pub cell: Cell,
    pub text: String,
    pub robot: Robot,
}

impl Loaded {
    /// The robot convention is never silent: a warning for stderr when the URDF has no
    /// controller file (the robot is then a serial arm with the URDF's limits and speeds).
    pub fn controller_warning(&self) -> Vec<String> {
        match &self.robot.controller.source {
            Some(_) => Vec::new(),
            // Bounded like every message (the path comes from the cell).
            None => vec![excerpt::message(&format!(
                "warning: {} has no controller file beside it ({}): the robot is taken as a serial arm with the URDF's joint limits and speeds; name one with robot.controller if this robot has another convention",
                self.robot.urdf_path.display(),
                crate::robot::controller::path_beside(&self.robot.urdf_path)
                    .file_name()
                    .map(|f| f.to_string_lossy().into_owned())
                    .unwrap_or_default()
            ))
            .into_owned()],
        }
    }

    /// A later stage's error, with the cell file's name and text for the message.
    pub fn fail(&self, error: Error) -> Failure {
        Failure {
            error: Box::new(error),
            file: self.cell.path.display().to_string(),
            text: Some(self.text.clone()),
            notes: Vec::new(),
        }
    }
}

/// Reads the cell file and the robot it names. A robot file's error points at
/// the cell's line that names it (`robot.controller` for the controller file when given, else
/// `robot.urdf`).
pub fn load(path: &Path) -> Result<Loaded, Failure> {
    let fail = |error: Error, text: Option<String>| Failure {
        error: Box::new(error),
        file: path.display().to_string(),
        text,
        notes: Vec::new(),
    };
    let text = cell::read(path).map_err(|e| fail(e.into(), None))?;
    let cell = match cell::parse(path, &text) {
        Ok(c) => c,
        Err(e) => return Err(fail(e.into(), Some(text))),
    };
    match robot_of(&cell) {
        Ok(robot) => Ok(Loaded { cell, text, robot }),
        Err(source) => {
            let loc = match source {
                RobotError::ReadController { .. } | RobotError::Controller { .. }
                    if cell.robot.controller_path.is_some() =>
                {
                    cell.robot.controller_loc
                }
                _ => cell.robot.urdf_loc,
            };
            Err(fail(Error::Robot { source, loc }, Some(text)))
        }
    }
}

/// The cell's robot: the shipped model `robot.model` names (read from the text built into the
/// binary), or the URDF `robot.urdf` names with its controller file (read from files).
pub fn robot_of(cell: &Cell) -> Result<Robot, RobotError> {
    match &cell.robot.model {
        Some(name) => Robot::shipped(name),
        None => Robot::load(&cell.robot.urdf_path, cell.robot.controller_path.as_deref()),
    }
}
