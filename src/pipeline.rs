//! The stages in order, for the command line, the tests and the benchmarks:
//!
//! ```text
//! load (cell + robot files) -> place -> inspect -> plan -> time -> refine -> time -> render
//! ```
//!
//! Each stage is a function of the previous stages' results. Only [`load`] reads files (the cell,
//! the URDF and its controller file; [`load_template`] the user's module template); everything after it is a pure function of its inputs, so a
//! benchmark loads once and runs the rest as often as it likes. Errors are the stages' own,
//! wrapped in [`Error`] with the place in the cell file they point at.

use crate::cell::{self, Cell};
use crate::collision::{CollisionModel, GridCheck};
use crate::error::{Error, Failure};
use crate::excerpt;
use crate::output::program::{self, RobotFacts};
use crate::output::rapid::{self, AxisRanges, ModuleTemplate, RapidError, TemplateError};
use crate::place::locate::Sketch;
use crate::place::{self, Placed, Survey};
use crate::plan::cspace::{CSpace, Grid};
use crate::plan::{self, Method, Plan};
use crate::progress::{Progress, Silent};
use crate::refine::{self, Refined};
use crate::robot::{Coupling, Robot, RobotError};
use crate::timing;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// The load stage's result: the cell, its text (for pointing at lines) and its robot.
pub struct Loaded {
    pub cell: Cell,
    pub text: String,
    pub robot: Robot,
}

impl Loaded {
    /// What the module states about the robot files (file names, like the cell's: the module
    /// names the files, not where they lie, so a cell moved elsewhere gives the same bytes).
    pub fn robot_facts(&self) -> RobotFacts {
        let shown = |p: &Path| {
            p.file_name()
                .map(|f| f.to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        let c = &self.robot.controller;
        RobotFacts {
            urdf: shown(&self.robot.urdf_path),
            controller: c.source.as_deref().map(shown),
            parallelogram: c.coupling == Coupling::Parallelogram,
            ranges: AxisRanges {
                axes_deg: c.axes.map(|a| [a.min_deg, a.max_deg]),
                coupled_axis3_deg: c.coupled_axis3_deg,
            },
        }
    }

    /// Warnings for stderr: the robot convention is never silent (issue 8); a speeddata the
    /// moves use that RAPID does not predefine, once per name (issue 10: the estimate cannot
    /// know its values and takes those moves at full axis speed).
    pub fn warnings(&self) -> Vec<String> {
        let mut warnings = self.controller_warning();
        warnings.extend(self.speed_warnings());
        warnings
    }

    /// The speeddata names the moves use (each point's own, else `motion.speed`) that RAPID does
    /// not predefine, each once (ignoring case, in the cell's order), as warnings.
    fn speed_warnings(&self) -> Vec<String> {
        let cell = &self.cell;
        let mut seen: Vec<String> = Vec::new();
        for p in &cell.points {
            let name = p.speed.as_deref().unwrap_or(&cell.motion.speed);
            let known = crate::rapid_data::predefined_speed(name).is_some();
            if !known && !seen.iter().any(|s| s.eq_ignore_ascii_case(name)) {
                seen.push(name.to_string());
            }
        }
        seen.iter()
            .map(|name| {
                excerpt::message(&format!(
                    "warning: speed '{}' is not a predefined speeddata: the estimated time takes the moves that use it at full axis speed (its v_tcp and v_ori are declared on the controller, not known here)",
                    excerpt::value(name)
                ))
                .into_owned()
            })
            .collect()
    }

    /// The robot convention is never silent (issue 8).
    fn controller_warning(&self) -> Vec<String> {
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

/// The inspect stage's result: the collision model of the placed robot and the grid over axes
/// 1..3 (paper section 3), its nodes inspected as the plan stage's waves reach them
/// (`plan::cspace`: the same codes as inspecting every node first).
pub struct Inspected {
    pub model: Arc<CollisionModel>,
    pub cspace: CSpace,
}

/// The render stage's result: the module's content, its text and the names it gives the
/// plan's waypoints (in order).
pub struct Rendered {
    pub program: rapid::Program,
    pub text: String,
    pub names: Vec<String>,
}

/// Load: reads the cell file and the robot it names (the only file reads of the pipeline).
pub fn load(path: &Path) -> Result<Loaded, Failure> {
    let fail = |error: Error, text: Option<String>| Failure {
        error: Box::new(error),
        file: path.display().to_string(),
        text,
        notes: Vec::new(),
    };
    let text = cell::read(path).map_err(|e| fail(e.into(), None))?;
    let cell = match cell::parse(path, &text).and_then(|c| cell::unsupported(&c).map(|()| c)) {
        Ok(c) => c,
        Err(e) => return Err(fail(e.into(), Some(text))),
    };
    match Robot::load(&cell.robot.urdf_path, cell.robot.controller_path.as_deref()) {
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

/// Load, the user's module template (`--template FILE`): read and compiled here, so a template
/// that does not parse fails before any planning, pointing at its line (an input error).
pub fn load_template(path: &Path) -> Result<ModuleTemplate, Failure> {
    let fail = |error: Error| Failure {
        error: Box::new(error),
        file: path.display().to_string(),
        text: None,
        notes: Vec::new(),
    };
    let source = crate::input::read_text(path).map_err(|source| {
        fail(Error::Template(TemplateError::Read {
            path: path.to_path_buf(),
            source,
        }))
    })?;
    ModuleTemplate::user(path, source).map_err(|e| fail(Error::Template(e)))
}

/// Place: where the robot stands and every point on all six axes.
pub fn place(job: &Loaded) -> Result<Placed, Error> {
    let (cell, robot) = (&job.cell, &job.robot);
    Ok(place::place(cell, robot, |p| {
        CollisionModel::of_cell(cell, robot, p)
    })?)
}

/// The place stage's survey of the feasible base region (for `gen-rapid locate`).
pub fn survey(job: &Loaded) -> Result<Survey, Error> {
    let (cell, robot) = (&job.cell, &job.robot);
    Ok(place::survey(cell, robot, |p| {
        CollisionModel::of_cell(cell, robot, p)
    })?)
}

/// What the place stage can draw of its location problem when [`survey`] fails for want of a
/// base position (the points' reach regions, the obstacles, R where not empty).
pub fn sketch(job: &Loaded) -> Result<Sketch, Error> {
    Ok(place::sketch(&job.cell, &job.robot)?)
}

/// Inspect: the collision model at the placement and the grid at spacing `grid_deg` over the
/// robot's ranges of axes 1..3, each node inspected when a wave first reads it (nothing
/// inspected yet: `CSpace::inspect_all` inspects the whole grid).
pub fn inspect(job: &Loaded, placed: &Placed, grid_deg: f64) -> Inspected {
    let model = Arc::new(CollisionModel::of_cell(
        &job.cell,
        &job.robot,
        placed.placement,
    ));
    let a = &job.robot.controller.axes;
    let ranges = [0, 1, 2].map(|k| [a[k].min_deg, a[k].max_deg]);
    let grid = Grid::over(ranges, grid_deg);
    let check = GridCheck::new(Arc::clone(&model), grid_deg);
    let cspace = CSpace::lazy(grid, Arc::new(check));
    Inspected { model, cspace }
}

/// Plan: the route through the points with `method`, every move proven, its smallest
/// clearances certified.
pub fn plan(
    job: &Loaded,
    placed: &Placed,
    inspected: &Inspected,
    method: Method,
) -> Result<Plan, Error> {
    route(job, placed, inspected, method).map(|p| plan::certify(p, &inspected.model))
}

/// [`plan`] without certifying the smallest clearances: the refine stage certifies the route it
/// keeps, so a run does not certify a route the shortcut pass then replaces.
pub fn route(
    job: &Loaded,
    placed: &Placed,
    inspected: &Inspected,
    method: Method,
) -> Result<Plan, Error> {
    let Inspected { model, cspace } = inspected;
    plan::route(cspace, model, &placed.points, method).map_err(|e| plan_error(job, e))
}

/// A plan stage error, pointing at the point it is about.
fn plan_error(job: &Loaded, source: plan::PlanError) -> Error {
    let loc = job.cell.points.get(source.point()).map(|p| p.loc);
    let loc = loc.unwrap_or_default();
    Error::Plan { source, loc }
}

/// Time: the manipulation time of every move (paper section 5, with the speeddata of each move
/// and the fly-by at zoned waypoints: `timing`), into the plan. `placed` holds the points the
/// plan was made from (the speed and zone of each move).
pub fn time(job: &Loaded, placed: &Placed, mut plan: Plan) -> Plan {
    let model = timing::TimeModel::new(&job.robot, job.cell.tool.as_ref());
    plan.estimate = Some(timing::estimate(&plan, &placed.points, &model));
    plan
}

/// Keeps a timed plan's moves and time as the figure of the paper's method alone (`Plan::paper`),
/// for the header and the summary line. Called on the plan stage's timed route, before any
/// refinement of it.
pub fn keep_paper_figure(
    job: &Loaded,
    placed: &Placed,
    inspected: &Inspected,
    mut plan: Plan,
) -> Plan {
    // The paper's route as the module would write it: every via `fine`, a cell point's own
    // fly-by zone only where its corner is proven (the refine stage's rule), then timed.
    let mut alone = plan.clone();
    let explicit: Vec<bool> = job.cell.points.iter().map(|p| p.zone.is_some()).collect();
    let _ = refine::zones::certify_zones(
        &mut alone,
        &inspected.model,
        &placed.points,
        &explicit,
        crate::plan::motion::VIA_ZONE,
    );
    let alone = time(job, placed, alone);
    plan.paper = alone.estimate.as_ref().map(|e| plan::PaperFigure {
        moves: alone.moves(),
        time_s: e.total_s,
    });
    plan
}

/// Refine (issue 10): the shortcut pass (`planner.shortcut`) and the certified zones
/// (`motion.via_zone`, the points' zones), each change kept only when the time estimate does not
/// grow; then the time again. The warnings are for stderr (a point's zone written `fine`).
pub fn refine(job: &Loaded, placed: &Placed, inspected: &Inspected, plan: Plan) -> Refined {
    let settings = refine::Settings {
        shortcut: job.cell.planner.shortcut,
        via_zone: &job.cell.motion.via_zone,
        explicit_zone: job.cell.points.iter().map(|p| p.zone.is_some()).collect(),
    };
    let model = timing::TimeModel::new(&job.robot, job.cell.tool.as_ref());
    let time_s = |p: &Plan| timing::estimate(p, &placed.points, &model).total_s;
    let paper = plan.paper;
    let mut refined = refine::refine(plan, &inspected.model, &placed.points, &settings, &time_s);
    // The paper's figure stays the one of the route before refinement.
    refined.plan.paper = paper;
    Refined {
        plan: time(job, placed, refined.plan),
        warnings: refined.warnings,
    }
}

/// Render: the RAPID module of a plan, through the embedded template.
pub fn render(job: &Loaded, placed: &Placed, plan: &Plan) -> Result<Rendered, Error> {
    render_with(job, placed, plan, &ModuleTemplate::embedded())
}

/// Render through `template` (the user's, `--template`, or the embedded one). An error of the
/// user's template is an input error pointing at its line.
pub fn render_with(
    job: &Loaded,
    placed: &Placed,
    plan: &Plan,
    template: &ModuleTemplate,
) -> Result<Rendered, Error> {
    let program = program::build(&job.cell, placed, plan, &job.robot_facts());
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

/// A whole run after load: the placed job, the inspected grid, the timed plan and the module.
pub struct Outcome {
    pub placed: Placed,
    pub inspected: Inspected,
    pub plan: Plan,
    pub rendered: Rendered,
    /// Warnings of the refine stage, for stderr.
    pub warnings: Vec<String>,
}

/// A run that stopped at a stage's error, with what the stages before it made that a picture of
/// the failure needs.
pub struct Halted {
    /// Boxed: the error is large and a `Result` carrying it should not be.
    pub error: Box<Error>,
    /// Set when the plan stage failed: the placed points and the grid it searched.
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

/// Place, inspect, plan, time and render, in that order. A failure of the plan stage keeps the
/// placed points and the inspected grid (a picture of why the plan failed).
pub fn run(job: &Loaded, method: Method, grid_deg: f64) -> Result<Outcome, Halted> {
    run_with(job, method, grid_deg, &ModuleTemplate::embedded())
}

/// [`run`] with the module rendered through `template`.
pub fn run_with(
    job: &Loaded,
    method: Method,
    grid_deg: f64,
    template: &ModuleTemplate,
) -> Result<Outcome, Halted> {
    run_observed(job, method, grid_deg, template, &Silent)
}

/// [`run_with`], reporting each stage to `progress` (a bar on a terminal, `cli::progress`).
pub fn run_observed(
    job: &Loaded,
    method: Method,
    grid_deg: f64,
    template: &ModuleTemplate,
    progress: &dyn Progress,
) -> Result<Outcome, Halted> {
    progress.stage("placing the robot", 0);
    let placed = place(job)?;
    let inspected = inspect(job, &placed, grid_deg);
    progress.stage("planning and proving the moves", 0);
    let paper = match route(job, &placed, &inspected, method) {
        // The paper's method alone: search, shorten, merge, every via a stop point, timed.
        Ok(plan) => keep_paper_figure(job, &placed, &inspected, time(job, &placed, plan)),
        Err(error) => {
            return Err(Halted {
                error: Box::new(error),
                searched: Some(Box::new(Searched { placed, inspected })),
            })
        }
    };
    progress.stage("shortening the route and proving the zones", 0);
    let Refined { plan, warnings } = refine(job, &placed, &inspected, paper);
    progress.stage("writing the module", 0);
    let rendered = render_with(job, &placed, &plan, template)?;
    Ok(Outcome {
        placed,
        inspected,
        plan,
        rendered,
        warnings,
    })
}

/// One method's attempt in a comparison: the timed route (its smallest clearance not
/// certified) or why it failed, and the wall-clock time of planning it.
pub struct Attempt {
    pub method: Method,
    pub result: Result<Plan, Error>,
    pub planning_time_ms: f64,
}

/// The three methods of the paper on one inspected grid: the whole grid inspected first, as the
/// paper does (so no method's planning time holds the inspection).
pub fn compare(job: &Loaded, placed: &Placed, inspected: &Inspected) -> Vec<Attempt> {
    inspected.cspace.inspect_all(&Silent);
    Method::ALL
        .into_iter()
        .map(|method| {
            let Inspected { model, cspace } = inspected;
            let started = Instant::now();
            let result =
                plan::route(cspace, model, &placed.points, method).map_err(|e| plan_error(job, e));
            let planning_time_ms = started.elapsed().as_secs_f64() * 1e3;
            Attempt {
                method,
                result: result.map(|p| time(job, placed, p)),
                planning_time_ms,
            }
        })
        .collect()
}

/// The row beyond the paper in a comparison (issue 10): the extensile attempt's route through the
/// refine stage with the shortcut pass (whatever `planner.shortcut` says), timed; with the
/// wall-clock time of planning it (the extensile search's and the pass's). `None` when the
/// extensile search failed.
pub fn compare_shortcut(
    job: &Loaded,
    placed: &Placed,
    inspected: &Inspected,
    attempts: &[Attempt],
) -> Option<(Plan, f64)> {
    let extensile = attempts.iter().find(|a| a.method == Method::Extensile)?;
    let paper = extensile.result.as_ref().ok()?.clone();
    let started = Instant::now();
    let mut job_shortcut = Loaded {
        cell: job.cell.clone(),
        text: String::new(),
        robot: job.robot.clone(),
    };
    job_shortcut.cell.planner.shortcut = true;
    let refined = refine(&job_shortcut, placed, inspected, paper);
    let ms = extensile.planning_time_ms + started.elapsed().as_secs_f64() * 1e3;
    Some((refined.plan, ms))
}
