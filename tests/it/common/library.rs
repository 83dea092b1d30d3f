//! Every path into the `gen_rapid` library that the integration tests use, in one place (the rest
//! of the tests drive the binary or read files). When the library's modules move, mend them here.

pub use gen_rapid::cell::{Base, Cell, Target};
pub use gen_rapid::place::Survey;
pub use gen_rapid::robot::Robot;

use gen_rapid::cell;
use gen_rapid::error::Error;
use gen_rapid::pipeline;
use gen_rapid::plan::Method;
use std::path::Path;

/// Reads and validates a cell file.
pub fn load_cell(path: &Path) -> Cell {
    cell::load(path)
        .map(|(c, _)| c)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Validates cell text as if read from `path`.
pub fn parse_cell(path: &Path, text: &str) -> Result<Cell, String> {
    cell::parse(path, text).map_err(|e| e.to_string())
}

/// The cell's robot (its URDF and controller file).
pub fn load_robot(cell: &Cell) -> Robot {
    Robot::load(&cell.robot.urdf_path, cell.robot.controller_path.as_deref())
        .unwrap_or_else(|e| panic!("{}: {e}", cell.robot.urdf_path.display()))
}

/// The feasible region of the base for a `base: auto` cell (paper section 2), with its
/// positions by margin and the base the place stage chooses.
pub fn locate_auto(path: &Path) -> Survey {
    let job = pipeline::load(path).unwrap_or_else(|f| panic!("{}", f.render()));
    pipeline::survey(&job).unwrap_or_else(|e| panic!("{e}"))
}

/// What planning with one method gave.
pub enum Planned {
    /// The module text, as the binary would write it.
    Module(String),
    /// A planning failure (no path, a search that fails): its message.
    PlanningFailed(String),
}

/// Plans `cell` with every method on one inspected grid of `grid_deg`. Any error but a planning
/// failure (the cell, the robot, a point, rendering) is `Err` with its message.
pub fn plan_every_method(cell: &Cell, grid_deg: f64) -> Result<Vec<(String, Planned)>, String> {
    let robot = Robot::load(&cell.robot.urdf_path, cell.robot.controller_path.as_deref())
        .map_err(|e| e.to_string())?;
    let job = pipeline::Loaded {
        cell: cell.clone(),
        text: String::new(),
        robot,
    };
    let placed = pipeline::place(&job).map_err(|e| e.to_string())?;
    let inspected = pipeline::inspect(&job, &placed, grid_deg);
    Method::ALL
        .into_iter()
        .map(|m| {
            let planned = match pipeline::plan(&job, &placed, &inspected, m)
                .map(|p| pipeline::time(&job, p))
                .and_then(|p| pipeline::render(&job, &placed, &p))
            {
                Ok(out) => Planned::Module(out.text),
                Err(e @ Error::Plan { .. }) => Planned::PlanningFailed(e.to_string()),
                Err(e) => return Err(format!("{m}: {e}")),
            };
            Ok((m.name().to_string(), planned))
        })
        .collect()
}
