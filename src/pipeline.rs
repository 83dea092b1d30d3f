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

use crate::collision::{CollisionModel, GridCheck};
use crate::error::{Error, Failure};
pub use crate::load::{check_budgets, load, robot_of, Loaded};
use crate::output::program::{self, RobotFacts};
use crate::output::rapid::{self, ModuleTemplate, RapidError, TemplateError};
use crate::place::near_limit::{near_limits, NearLimit};
use crate::place::{self, locate::Sketch, Placed, Survey};
use crate::plan::cspace::{CSpace, Grid};
use crate::plan::{self, Legs, Method, Route};
use crate::process;
use crate::progress::{Progress, Silent};
use crate::refine::{self, Plan, Refined};
use crate::timing;
use std::path::Path;
use std::sync::Arc;

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
/// 1..3 (paper section 3), its nodes inspected as the plan stage's waves reach them
/// (`plan::cspace`: the same codes as inspecting every node first).
pub struct Inspected {
    pub model: Arc<CollisionModel>,
    pub cspace: CSpace,
}

/// Inspect: the model at the placement and the grid at `grid_deg` over the ranges of axes 1..3,
/// each node inspected when a wave first reads it (nothing inspected yet:
/// `CSpace::inspect_all` inspects the whole grid).
pub fn inspect(job: &Loaded, placed: &Placed, grid_deg: f64) -> Inspected {
    let model = CollisionModel::of_cell(&job.cell, &job.robot, placed.placement);
    let model = Arc::new(model);
    let a = &job.robot.controller.axes;
    let grid = Grid::over([0, 1, 2].map(|k| [a[k].min_deg, a[k].max_deg]), grid_deg);
    let check = GridCheck::new(Arc::clone(&model), grid_deg);
    let cspace = CSpace::lazy(grid, Arc::new(check));
    Inspected { model, cspace }
}

/// Plan: the route through the points with `method` (the paper's method: every leg on the
/// grid), every move proven; a failure points at the point it is about.
pub fn route(
    job: &Loaded,
    placed: &Placed,
    got: &Inspected,
    method: Method,
) -> Result<Route, Error> {
    route_with(job, placed, got, method, Legs::GridOnly)
}

/// [`route`] with `legs` saying which legs the grid plans (`plan::direct`).
pub fn route_with(
    job: &Loaded,
    placed: &Placed,
    got: &Inspected,
    method: Method,
    legs: Legs,
) -> Result<Route, Error> {
    let (cs, model, points) = (&got.cspace, &got.model, &placed.points);
    plan::route_with(cs, model, points, method, legs).map_err(|source| {
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

/// Follow, plan and refine: the process moves followed and proven (`process::follow`), the air
/// route planned (`plan::route`) and refined (`refine::refine`) over each run of stops joined
/// through the air, and the whole spliced into one plan (`process::splice`). A cell without
/// process keys is one run of its points: the plan as `route` and `refine` make it.
pub fn plan_all(
    job: &Loaded,
    placed: &Placed,
    got: &Inspected,
    method: Method,
    legs: Legs,
) -> Result<Refined, Error> {
    let shortcut = job.cell.planner.shortcut;
    let cell = &job.cell;
    let followed =
        process::follow(cell, &job.robot, placed, &got.model).map_err(|e| Error::Process {
            source: Box::new(e),
        })?;
    let model = timing::TimeModel::new(&job.robot, cell.tool.as_ref());
    let time = |r: &Route, m: &[place::MoveMotion]| timing::estimate(r, m, &model);
    let mut warnings = followed.warnings.clone();
    let mut plans = Vec::new();
    for run in followed.air_runs() {
        let points = followed.points_of(&run, placed);
        let route = plan::route_with(&got.cspace, &got.model, &points, method, legs);
        let route = route.map_err(|source| {
            let entry = followed.entry_of(&run, source.point());
            let loc = cell.points.get(entry).map(|p| p.loc);
            Error::Plan {
                source,
                loc: loc.unwrap_or_default(),
            }
        })?;
        let settings = refine::Settings {
            shortcut,
            via_zone: &cell.motion.via_zone,
            explicit_zone: followed.stops[run.clone()]
                .iter()
                .map(|s| match s.kind {
                    process::StopKind::Entry(i) => {
                        cell.points.get(i).is_some_and(|p| p.zone.is_some())
                    }
                    _ => false,
                })
                .collect(),
        };
        let refined = refine::refine(route, &got.model, &points, &settings, &time);
        warnings.extend(refined.warnings);
        plans.push((run, refined.plan));
    }
    let waits_s: f64 = (cell.points.iter())
        .flat_map(|p| &p.actions)
        .map(|a| match a.kind {
            crate::cell::ActionKind::WaitTime { time_s } => time_s,
            _ => 0.0,
        })
        .sum();
    let grid_deg = got.cspace.grid.step_deg;
    let plan = process::splice(&followed, plans, method, grid_deg, waits_s);
    Ok(Refined { plan, warnings })
}

/// The render stage's result: the module's content, its text, its names of the waypoints and
/// its moves as written (instruction, target, actions).
pub struct Rendered {
    pub program: rapid::Program,
    pub text: String,
    pub names: Vec<String>,
    pub moves: Vec<rapid::WrittenMove>,
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
    let moves = rapid::written_moves(&program, &names)?;
    Ok(Rendered {
        program,
        text,
        names,
        moves,
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
    check_budgets(job, opts.grid_deg, 1)?;
    let progress = opts.progress;
    progress.stage("placing the robot", 0);
    let placed = place(job)?;
    let inspected = inspect(job, &placed, opts.grid_deg);
    progress.stage("planning and proving the moves", 0);
    let legs = Legs::of(&job.cell.planner);
    let Refined {
        plan,
        warnings: refined,
    } = match plan_all(job, &placed, &inspected, opts.method, legs) {
        Ok(r) => r,
        Err(error) => {
            let searched = match error {
                Error::Plan { .. } => Some(Box::new(Searched { placed, inspected })),
                _ => None,
            };
            return Err(Halted {
                error: Box::new(error),
                searched,
            });
        }
    };
    // The place stage's warnings (axes 4 and 6 near a limit), then the refine stage's.
    let mut warnings: Vec<String> = near_limits(&placed, &job.robot)
        .iter()
        .map(NearLimit::warning)
        .collect();
    warnings.extend(refined);
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
