//! Every path into the `gen_rapid` library that the integration tests use, in one place (the rest
//! of the tests drive the binary or read files). When the library's modules move, mend them here.

pub use gen_rapid::cell::{ActionKind, Base, Cell, Target, Tool, ToolGeometry};
pub use gen_rapid::place::Survey;
pub use gen_rapid::robot::{LinkFrame, Robot};

use gen_rapid::cell;
use gen_rapid::error::Error;
use gen_rapid::output::rapid::ModuleTemplate;
use gen_rapid::pipeline::{self, Options};
use gen_rapid::place::Placed;
use gen_rapid::plan::{Certified, Legs, Method, Route};
use gen_rapid::refine::{Plan, Refined};
use std::path::Path;

/// How the controller's axis 3 relates to the URDF's (the OPW check converts its solutions),
/// and the cell's process and program keys the controller-like re-check holds a module to.
pub use gen_rapid::cell::{Arrival, Point, RobotFrame};
pub use gen_rapid::robot::Coupling;

/// The bundled IRB 1400.
pub fn irb1400() -> Robot {
    let path = super::root().join("robots/irb1400.urdf");
    Robot::load(&path, None).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A refusal as the user sees it: the rendered message, the place it points at (line, column)
/// and the exit status.
#[derive(Debug)]
pub struct Refusal {
    pub message: String,
    pub loc: Option<(u64, u64)>,
    pub exit: u8,
}

fn refusal(error: Error, file: &str, text: Option<&str>) -> Refusal {
    Refusal {
        message: error.render(file, text),
        loc: error.loc().map(|l| (l.line, l.column)),
        exit: error.exit_code(),
    }
}

/// The load stage's reading of a cell file's bytes (UTF-8, YAML, validation), as if read from
/// `path` (`file` names it in messages); no file is read.
pub fn cell_from_bytes(path: &Path, file: &str, bytes: Vec<u8>) -> Result<(Cell, String), Refusal> {
    let text = cell::text_of(bytes).map_err(|e| refusal(e.into(), file, None))?;
    match cell::parse(path, &text) {
        Ok(c) => Ok((c, text)),
        Err(e) => Err(refusal(e.into(), file, Some(&text))),
    }
}

/// The whole run after load (place, inspect, plan, refine, render) for a cell with `robot`, on a
/// grid of `grid_deg`: the module text.
pub fn run_with(
    cell: &Cell,
    text: &str,
    file: &str,
    robot: &Robot,
    grid_deg: f64,
) -> Result<String, Refusal> {
    let job = pipeline::Loaded {
        cell: cell.clone(),
        text: text.to_string(),
        robot: robot.clone(),
    };
    match pipeline::run(&job, &Options::new(cell.planner.method, grid_deg)) {
        Ok(out) => Ok(out.rendered.text),
        Err(halted) => Err(refusal(*halted.error, file, Some(text))),
    }
}

/// The place stage for a cell with `robot` (whatever URDF the cell names): the number of points
/// placed.
pub fn place_with(cell: &Cell, text: &str, file: &str, robot: &Robot) -> Result<usize, Refusal> {
    let job = pipeline::Loaded {
        cell: cell.clone(),
        text: text.to_string(),
        robot: robot.clone(),
    };
    match pipeline::place(&job) {
        Ok(placed) => Ok(placed.points.len()),
        Err(e) => Err(refusal(e, file, Some(text))),
    }
}

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

/// The cell's robot (its URDF and controller file, or the shipped model it names), as the
/// load stage reads it.
pub fn load_robot(cell: &Cell) -> Robot {
    pipeline::robot_of(cell).unwrap_or_else(|e| panic!("{}: {e}", cell.path.display()))
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

/// `cell` loaded with its robot, placed, and its grid of `grid_deg` inspected.
fn placed_and_inspected(
    cell: &Cell,
    grid_deg: f64,
) -> Result<(pipeline::Loaded, Placed, pipeline::Inspected), String> {
    let robot = pipeline::robot_of(cell).map_err(|e| e.to_string())?;
    let job = pipeline::Loaded {
        cell: cell.clone(),
        text: String::new(),
        robot,
    };
    let placed = pipeline::place(&job).map_err(|e| e.to_string())?;
    let inspected = pipeline::inspect(&job, &placed, grid_deg);
    Ok((job, placed, inspected))
}

/// Plans `cell` with every method on one inspected grid of `grid_deg`, as a run does (the
/// process moves followed, every air leg on the grid, refined, spliced and rendered). Any error but a planning failure (the cell, the robot, a point, rendering)
/// is `Err` with its message.
pub fn plan_every_method(cell: &Cell, grid_deg: f64) -> Result<Vec<(String, Planned)>, String> {
    let (job, placed, inspected) = placed_and_inspected(cell, grid_deg)?;
    let template = ModuleTemplate::embedded();
    Method::ALL
        .into_iter()
        .map(|m| {
            let planned = match pipeline::plan_all(&job, &placed, &inspected, m, Legs::GridOnly)
                .and_then(|r| pipeline::render(&job, &placed, &r.plan, &template))
            {
                Ok(out) => Planned::Module(out.text),
                Err(e @ Error::Plan { .. }) => Planned::PlanningFailed(e.to_string()),
                Err(e) => return Err(format!("{m}: {e}")),
            };
            Ok((m.name().to_string(), planned))
        })
        .collect()
}

/// `cell` on a grid of `grid_deg` through the plan stage and the refine stage, as a run: the
/// job, its placed points and inspected grid, the plan stage's route and the refined plan.
fn through_refine(
    cell: &Cell,
    grid_deg: f64,
) -> Result<(pipeline::Loaded, Placed, pipeline::Inspected, Route, Plan), String> {
    let (job, placed, inspected) = placed_and_inspected(cell, grid_deg)?;
    let route = pipeline::route(&job, &placed, &inspected, cell.planner.method)
        .map_err(|e| e.to_string())?;
    let shortcut = cell.planner.shortcut;
    let Refined { plan, .. } = pipeline::refine(&job, &placed, &inspected, route.clone(), shortcut);
    Ok((job, placed, inspected, route, plan))
}

/// A run's plan of `cell` on a grid of `grid_deg` as the binary makes it, the plan stage's
/// route it started from, and the plan's route with its clearances certified anew by
/// `plan::certify` (an independent computation to compare the refine stage's certificate with).
pub struct Recertified {
    pub paper: Route,
    pub refined: Plan,
    pub again: Certified,
}

pub fn refined_and_recertified(cell: &Cell, grid_deg: f64) -> Result<Recertified, String> {
    let (_, _, inspected, paper, refined) = through_refine(cell, grid_deg)?;
    let again = gen_rapid::plan::certify(refined.route.clone(), &inspected.model);
    Ok(Recertified {
        paper,
        refined,
        again,
    })
}

/// The paper's method alone (the plan stage's route and the time the plan states for it) and
/// the refined route (shortcut and zones, as a run writes it) of `cell` on a grid of
/// `grid_deg`: `(moves, estimated s)` of each, the waypoints of both routes (all six axes) and
/// the module a run writes (the process moves spliced in).
pub struct PaperAndRefined {
    pub paper: (usize, f64),
    pub refined: (usize, f64),
    pub paper_route: Vec<[f64; 6]>,
    pub refined_route: Vec<[f64; 6]>,
    pub refined_module: String,
}

pub fn paper_and_refined(cell: &Cell, grid_deg: f64) -> Result<PaperAndRefined, String> {
    let (job, placed, inspected, route, plan) = through_refine(cell, grid_deg)?;
    let six = |r: &Route| r.waypoints.iter().map(|w| w.joints_deg).collect();
    // The module as a run writes it: the process moves followed and spliced in.
    let method = cell.planner.method;
    let whole = pipeline::plan_all(&job, &placed, &inspected, method, Legs::GridOnly)
        .map_err(|e| e.to_string())?;
    let module = pipeline::render(&job, &placed, &whole.plan, &ModuleTemplate::embedded())
        .map(|r| r.text)
        .map_err(|e| e.to_string())?;
    let paper = plan
        .paper
        .ok_or("the plan stage's route is the paper's: a figure")?;
    Ok(PaperAndRefined {
        paper: (paper.moves, paper.time_s),
        refined: (plan.route.moves(), plan.total_s),
        paper_route: six(&route),
        refined_route: six(&plan.route),
        refined_module: module,
    })
}

/// A robot read from URDF text and controller-file text (as if from `urdf` and `controller`):
/// `Err` is the refusal rendered as the user sees it (a cell pointing at the robot files), with
/// its exit status.
pub fn robot_from_texts(
    urdf: &Path,
    urdf_text: &str,
    controller: &Path,
    controller_text: Option<&str>,
) -> Result<Robot, Refusal> {
    gen_rapid::robot::urdf::robot_from_urdf(
        urdf,
        urdf_text,
        controller_text.map(|t| (controller, t)),
    )
    .map_err(|source| {
        refusal(
            Error::Robot {
                source,
                loc: Default::default(),
            },
            "cell.yaml",
            None,
        )
    })
}

/// Renders the trunk cell's plan (10 deg grid) through each template text given: the module
/// text, or the refusal (a template error is exit 1, located in the template).
pub struct TemplateBench {
    job: pipeline::Loaded,
    placed: Placed,
    plan: Plan,
}

impl TemplateBench {
    pub fn new() -> TemplateBench {
        let path = super::root().join("cells/trunk.yaml");
        let job = pipeline::load(&path).unwrap_or_else(|f| panic!("{}", f.render()));
        let out = pipeline::run(&job, &Options::new(Method::Extensile, 10.0))
            .unwrap_or_else(|h| panic!("{}", h.error));
        let (placed, plan) = (out.placed, out.plan);
        TemplateBench { job, placed, plan }
    }

    /// The template `source` (as if read from `path`): compiled, then rendered.
    pub fn render(&self, path: &Path, source: &str) -> Result<String, Refusal> {
        let template = gen_rapid::output::rapid::ModuleTemplate::user(path, source.to_string())
            .map_err(|e| refusal(Error::Template(e), "cell.yaml", None))?;
        pipeline::render(&self.job, &self.placed, &self.plan, &template)
            .map(|r| r.text)
            .map_err(|e| refusal(e, "cell.yaml", None))
    }
}
