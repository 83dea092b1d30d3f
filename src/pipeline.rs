//! The stages in order, for the command line, the tests and the benchmarks:
//!
//! ```text
//! load -> place -> inspect -> plan (Route) -> refine (certify, zone, time: Plan) -> render
//! ```
//!
//! Orchestration only: each function calls one stage's module with what the earlier stages
//! made, and the policy lives in the stages. Only [`load`] and [`load_template`] read files;
//! everything after them is a pure function of their results. Errors are the stages' own,
//! wrapped in [`Error`] with the place in the cell file they point at.

use crate::collision::CollisionModel;
use crate::error::{Error, Failure};
pub use crate::load::{load, robot_of, Loaded};
use crate::output::program::{self, RobotFacts};
use crate::output::rapid::{self, ModuleTemplate, RapidError, TemplateError};
use crate::place::{self, locate::Sketch, Placed, Survey};
use crate::plan::cspace::{CSpace, Grid};
use crate::plan::{self, Method, Route};
use crate::progress::{Progress, Silent};
use crate::refine::{self, Plan, Refined};
use crate::timing;
use std::path::Path;

/// The warnings for stderr right after loading: the robot's convention when it has no
/// controller file, and the speeddata the time stage cannot estimate.
pub fn warnings(job: &Loaded) -> Vec<String> {
    let mut warnings = job.controller_warning();
    warnings.extend(timing::speed_warnings(&job.cell));
    warnings
}

/// Load, the user's module template (`--template FILE`): read and compiled here, so a template
/// that does not parse fails before any planning, pointing at its line (an input error).
pub fn load_template(path: &Path) -> Result<ModuleTemplate, Failure> {
    let fail = |e| Failure {
        error: Box::new(Error::Template(e)),
        file: path.display().to_string(),
        text: None,
        notes: Vec::new(),
    };
    let source = crate::input::read_text(path).map_err(|source| {
        let path = path.to_path_buf();
        fail(TemplateError::Read { path, source })
    })?;
    ModuleTemplate::user(path, source).map_err(fail)
}

/// Place: where the robot stands and every point on all six axes.
pub fn place(job: &Loaded) -> Result<Placed, Error> {
    let model = |p| CollisionModel::of_cell(&job.cell, &job.robot, p);
    Ok(place::place(&job.cell, &job.robot, model)?)
}

/// The place stage's survey of the feasible base region (`gen-rapid locate`).
pub fn survey(job: &Loaded) -> Result<Survey, Error> {
    let model = |p| CollisionModel::of_cell(&job.cell, &job.robot, p);
    Ok(place::survey(&job.cell, &job.robot, model)?)
}

/// What the place stage can draw when [`survey`] finds no base position.
pub fn sketch(job: &Loaded) -> Result<Sketch, Error> {
    Ok(place::sketch(&job.cell, &job.robot)?)
}

/// The inspect stage's result: the collision model of the placed robot and the grid over axes
/// 1..3 with every node inspected (paper section 3).
pub struct Inspected {
    pub model: CollisionModel,
    pub cspace: CSpace,
}

/// Inspect: the model at the placement and the grid at `grid_deg` over the ranges of axes 1..3,
/// reporting the grid fill to `progress` (one unit per axis-1 slice).
pub fn inspect(job: &Loaded, placed: &Placed, grid_deg: f64, progress: &dyn Progress) -> Inspected {
    let model = CollisionModel::of_cell(&job.cell, &job.robot, placed.placement);
    let a = &job.robot.controller.axes;
    let grid = Grid::over([0, 1, 2].map(|k| [a[k].min_deg, a[k].max_deg]), grid_deg);
    progress.stage("inspecting the grid", grid.dims[0] as u64);
    let cspace = CSpace::build_observed(grid, &model.grid_check(grid_deg), progress);
    Inspected { model, cspace }
}

/// Plan: the route through the points with `method`, every move proven; a failure points at the
/// point it is about.
pub fn route(
    job: &Loaded,
    placed: &Placed,
    got: &Inspected,
    method: Method,
) -> Result<Route, Error> {
    plan::route(&got.cspace, &got.model, &placed.points, method).map_err(|source| {
        let loc = job.cell.points.get(source.point()).map(|p| p.loc);
        Error::Plan {
            source,
            loc: loc.unwrap_or_default(),
        }
    })
}

/// Refine: the route certified, zoned and timed (`refine`), with the shortcut pass when
/// `shortcut`; the time estimate is the time stage's for the job's robot and tool.
pub fn refine(
    job: &Loaded,
    placed: &Placed,
    got: &Inspected,
    route: Route,
    shortcut: bool,
) -> Refined {
    let settings = refine::Settings {
        shortcut,
        via_zone: &job.cell.motion.via_zone,
        explicit_zone: job.cell.points.iter().map(|p| p.zone.is_some()).collect(),
    };
    let model = timing::TimeModel::new(&job.robot, job.cell.tool.as_ref());
    let time = |r: &Route, m: &[place::MoveMotion]| timing::estimate(r, m, &model);
    refine::refine(route, &got.model, &placed.points, &settings, &time)
}

/// The render stage's result: the module's content, its text and its names of the waypoints.
pub struct Rendered {
    pub program: rapid::Program,
    pub text: String,
    pub names: Vec<String>,
}

/// Render: the RAPID module of a plan through `template`; a user template's error is an input
/// error pointing at its line.
pub fn render(
    job: &Loaded,
    placed: &Placed,
    plan: &Plan,
    template: &ModuleTemplate,
) -> Result<Rendered, Error> {
    let program = program::build(&job.cell, placed, plan, &RobotFacts::of(&job.robot));
    let text = rapid::render_with(&program, template).map_err(|e| match e {
        RapidError::UserTemplate(t) => Error::Template(t),
        e => Error::Rapid(e),
    })?;
    let names = rapid::module_target_names(&program)?;
    Ok(Rendered {
        program,
        text,
        names,
    })
}

/// How [`run`] runs: the method, the grid, the module template and where progress goes.
pub struct Options<'a> {
    pub method: Method,
    pub grid_deg: f64,
    pub template: ModuleTemplate,
    pub progress: &'a dyn Progress,
}

impl Options<'static> {
    /// `method` on a grid of `grid_deg`, the embedded template, no progress reported.
    pub fn new(method: Method, grid_deg: f64) -> Options<'static> {
        let template = ModuleTemplate::embedded();
        Options {
            method,
            grid_deg,
            template,
            progress: &Silent,
        }
    }
}

/// A whole run after load: the placed job, the inspected grid, the plan, the module and the
/// refine stage's warnings for stderr.
pub struct Outcome {
    pub placed: Placed,
    pub inspected: Inspected,
    pub plan: Plan,
    pub rendered: Rendered,
    pub warnings: Vec<String>,
}

/// A run that stopped at a stage's error; when the plan stage failed, with the placed points and
/// the grid it searched, for a picture of why.
pub struct Halted {
    /// Boxed: the error is large and a `Result` carrying it should not be.
    pub error: Box<Error>,
    pub searched: Option<Box<Searched>>,
}

/// The place and inspect stages' results, kept for a picture when the plan stage fails.
pub struct Searched {
    pub placed: Placed,
    pub inspected: Inspected,
}

impl From<Error> for Halted {
    fn from(error: Error) -> Halted {
        Halted {
            error: Box::new(error),
            searched: None,
        }
    }
}

impl std::fmt::Debug for Halted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(&self.error, f)
    }
}

/// Place, inspect, plan, refine and render, in that order, reporting each stage to
/// `opts.progress`; the shortcut pass as `planner.shortcut` says.
pub fn run(job: &Loaded, opts: &Options) -> Result<Outcome, Halted> {
    let progress = opts.progress;
    progress.stage("placing the robot", 0);
    let placed = place(job)?;
    let inspected = inspect(job, &placed, opts.grid_deg, progress);
    progress.stage("planning and proving the moves", 0);
    let route = match route(job, &placed, &inspected, opts.method) {
        Ok(route) => route,
        Err(error) => {
            let searched = Some(Box::new(Searched { placed, inspected }));
            return Err(Halted {
                error: Box::new(error),
                searched,
            });
        }
    };
    progress.stage("shortening the route and proving the zones", 0);
    let shortcut = job.cell.planner.shortcut;
    let Refined { plan, warnings } = refine(job, &placed, &inspected, route, shortcut);
    progress.stage("writing the module", 0);
    let rendered = render(job, &placed, &plan, &opts.template)?;
    Ok(Outcome {
        placed,
        inspected,
        plan,
        rendered,
        warnings,
    })
}
