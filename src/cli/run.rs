//! `gen-rapid <CELL>`: plan the cell and write the RAPID module; with `--svg` a picture of the
//! search, with `--html` the 3D preview page, with `--report` the JSON report; `--template`
//! renders the module through the user's template, `--proc` names its routine.
//!
//! On success every file is made in memory first, then written atomically, and the module goes
//! to stdout (or `-o FILE`) last. On a planning failure (exit 3) `--svg` draws why (the blocked
//! nodes, the points of the failed leg ringed) and `--html` writes a page of the cell and the
//! points that could not be joined (what those files hold succeeded); nothing else is written,
//! stdout stays empty, and a note on stderr says what was drawn.

use super::progress::TerminalProgress;
use super::{emit, write_for};
use crate::cell;
use crate::error::{exit, Error, Failure};
use crate::output::cspace_svg::{self, Marked};
use crate::output::rapid::ModuleTemplate;
use crate::output::{preview, report};
use crate::pipeline::{self, Halted, Loaded, Outcome, Searched};
use crate::place::{PlaceError, Placement};
use crate::plan::{Method, PlanError};
use crate::progress::{Progress, Silent};
use std::path::{Path, PathBuf};
use std::time::Instant;

pub struct RunOptions {
    pub cell: PathBuf,
    pub output: Option<PathBuf>,
    pub planner: Option<Method>,
    pub grid_deg: Option<f64>,
    /// Also draw the route over the configuration space (`cspace_svg`) to this file.
    pub svg: Option<PathBuf>,
    /// Also write the 3D preview page (`preview`) to this file.
    pub html: Option<PathBuf>,
    /// Also write the JSON report (`report`) to this file.
    pub report: Option<PathBuf>,
    /// Render the module through this minijinja template instead of the embedded one.
    pub template: Option<PathBuf>,
    /// The template settings (`--set NAME=VALUE`), by name.
    pub settings: std::collections::BTreeMap<String, String>,
    /// The routine's name, overriding the cell's `motion.proc`.
    pub proc_name: Option<String>,
    /// No progress bar (`--quiet`; the caller also leaves out the summary line).
    pub quiet: bool,
    /// `--no-shortcut`: the paper's method alone (overrides `planner.shortcut`).
    pub no_shortcut: bool,
}

/// Runs the pipeline; on success the module (and the files asked for) are written and a summary
/// line is returned for stderr (module docs).
pub fn run(opts: &RunOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let mut job = pipeline::load(&opts.cell)?;
    super::warn(&job);
    if let Some(name) = &opts.proc_name {
        if let Err(e) = cell::override_proc(&mut job.cell, name) {
            return Err(job.fail(e.into()));
        }
    }
    if opts.no_shortcut {
        job.cell.planner.shortcut = false;
    }
    let template = match &opts.template {
        Some(path) => pipeline::load_template(path)?,
        None => ModuleTemplate::embedded(),
    };
    let template = template.with_settings(opts.settings.clone());
    let method = opts.planner.unwrap_or(job.cell.planner.method);
    let grid_deg = opts.grid_deg.unwrap_or(job.cell.planner.grid_deg);
    let bar = if opts.quiet {
        None
    } else {
        TerminalProgress::for_stderr()
    };
    let progress: &dyn Progress = match &bar {
        Some(bar) => bar,
        None => &Silent,
    };
    let options = pipeline::Options {
        method,
        grid_deg,
        template,
        progress,
    };
    let planned = pipeline::run(&job, &options);
    // The bar is cleared before anything else reaches stderr.
    drop(bar);
    let out = match planned {
        Ok(out) => out,
        Err(halted) => return Err(failed(&job, opts, method, grid_deg, halted)),
    };
    let files = files(&job, opts, &out, method, grid_deg).map_err(|e| job.fail(e))?;
    // The files first, all or none (the module's FILE among them): if one cannot be written,
    // none is, and nothing has reached stdout yet.
    let mut all: Vec<(&Path, &[u8])> = files
        .iter()
        .map(|(path, text)| (path.as_path(), text.as_bytes()))
        .collect();
    if let Some(path) = opts.output.as_deref() {
        all.push((path, out.rendered.text.as_bytes()));
    }
    write_for(&job, &all).map_err(|e| job.fail(e))?;
    if opts.output.is_none() {
        emit(out.rendered.text.as_bytes()).map_err(|e| job.fail(e))?;
    }
    super::warn_lines(&out.warnings);
    let clearance = match &out.plan.least {
        Some(c) => format!("smallest clearance {:.1} mm", c.mm),
        None => "no obstacles".to_string(),
    };
    let time = format!(", about {:.2} s of motion", out.plan.total_s);
    let (zoned, vias) = out.plan.zoned_vias();
    let zoned = format!(
        ", zoned vias: {zoned} of {vias} (via zone {})",
        out.rendered.program.header.via_zone
    );
    let paper = match out.plan.paper {
        Some(p) => format!(
            ", the paper's method alone: {} move{}, {:.2} s",
            p.moves,
            if p.moves == 1 { "" } else { "s" },
            p.time_s
        ),
        // A leg went straight without the grid: the paper's method did not run.
        None => String::new(),
    };
    let moves = out.plan.route.moves();
    Ok(format!(
        "gen-rapid: {}: {} move{}{time}{zoned}{paper}, {}, {} on a {} deg grid, {:.2} s",
        opts.cell.display(),
        moves,
        if moves == 1 { "" } else { "s" },
        clearance,
        method,
        grid_deg,
        started.elapsed().as_secs_f64()
    ))
}

/// The files asked for besides the module, made in memory: `(path, text)`.
fn files(
    job: &Loaded,
    opts: &RunOptions,
    out: &Outcome,
    method: Method,
    grid_deg: f64,
) -> Result<Vec<(PathBuf, String)>, Error> {
    let mut files = Vec::new();
    if let Some(path) = &opts.svg {
        let title = format!(
            "{}: {} on a {} deg grid",
            opts.cell.display(),
            method,
            grid_deg
        );
        let in_range = |a: &[f64; 3]| job.robot.check_range3(a).is_ok();
        let text = cspace_svg::render_svg(
            &out.inspected.cspace,
            &in_range,
            &out.placed.points,
            &[&out.plan.route],
            &title,
        )?;
        files.push((path.clone(), text));
    }
    if let Some(path) = &opts.html {
        let scene = preview::scene(
            &job.cell,
            &job.robot,
            &out.placed,
            &out.plan,
            &out.rendered.names,
            &out.rendered.moves,
        );
        files.push((path.clone(), preview::render_html(&scene)?));
    }
    if let Some(path) = &opts.report {
        let r = report::report(&report::Input {
            cell: &job.cell,
            robot: &job.robot,
            placed: &out.placed,
            plan: &out.plan,
            program: &out.rendered.program,
            names: &out.rendered.names,
            written: &out.rendered.moves,
        })?;
        files.push((path.clone(), report::to_json(&r)?));
    }
    Ok(files)
}

/// A run that failed. When the plan stage failed, `--svg` draws the failure: the grid's blocked
/// nodes and the cell points, those the failure is about ringed. When it failed for want of a
/// plan (exit 3), `--html` writes the page of the failure: the cell, the robot where it was
/// placed, the points the failure is about and the message. Both are written atomically, the
/// exit status stays the planning failure's, and a note says what was drawn, or why nothing was.
fn failed(
    job: &Loaded,
    opts: &RunOptions,
    method: Method,
    grid_deg: f64,
    halted: Halted,
) -> Failure {
    let Halted { error, searched } = halted;
    let error = *error;
    let mut notes = Vec::new();
    if let Some(path) = &opts.svg {
        notes.push(failure_svg(
            job,
            opts,
            method,
            grid_deg,
            path,
            &error,
            searched.as_deref(),
        ));
    }
    if let Some(path) = &opts.html {
        if let Some(note) = failure_page(job, path, &error, searched.as_deref()) {
            notes.push(note);
        }
    }
    let mut failure = job.fail(error);
    failure.notes.extend(notes);
    failure
}

/// `--svg` of a failed run (see [`failed`]): the note to print.
fn failure_svg(
    job: &Loaded,
    opts: &RunOptions,
    method: Method,
    grid_deg: f64,
    path: &Path,
    error: &Error,
    searched: Option<&Searched>,
) -> String {
    match (error, searched) {
        (Error::Plan { source, .. }, Some(searched)) => {
            let marked = failed_points(source);
            let why = source.to_string();
            let title = format!(
                "{}: {} on a {} deg grid: no route",
                opts.cell.display(),
                method,
                grid_deg
            );
            let in_range = |a: &[f64; 3]| job.robot.check_range3(a).is_ok();
            let drawn = cspace_svg::render_failure_svg(
                &searched.inspected.cspace,
                &in_range,
                &searched.placed.points,
                &Marked {
                    points: &marked,
                    why: &why,
                },
                &title,
            )
            .map_err(Error::from)
            .and_then(|svg| write_for(job, &[(path, svg.as_bytes())]));
            let names: Vec<&str> = marked
                .iter()
                .filter_map(|&k| searched.placed.points.get(k))
                .map(|p| p.name.as_str())
                .collect();
            match drawn {
                Ok(()) => format!(
                    "the blocked nodes of the grid are drawn to {}, with {} ringed in red",
                    path.display(),
                    names.join(" and ")
                ),
                Err(e) => format!("no picture: {e}"),
            }
        }
        _ => format!(
            "nothing drawn to {}: the run stopped before the grid was searched",
            path.display()
        ),
    }
}

/// `--html` of a failed run (see [`failed`]): the note to print, `None` when the run did not
/// fail for want of a plan (an input or output error: there is nothing to show).
fn failure_page(
    job: &Loaded,
    path: &Path,
    error: &Error,
    searched: Option<&Searched>,
) -> Option<String> {
    if error.exit_code() != exit::PLANNING {
        return None;
    }
    let index = |name: &str| job.cell.points.iter().position(|p| p.name == name);
    let (placement, points, marked) = match (error, searched) {
        (Error::Plan { source, .. }, Some(s)) => (
            Some(s.placed.placement),
            Some(&s.placed.points[..]),
            failed_points(source),
        ),
        (
            Error::Place(
                PlaceError::Ik {
                    point,
                    base_mm,
                    yaw_deg,
                    ..
                }
                | PlaceError::Robtarget {
                    point,
                    base_mm,
                    yaw_deg,
                    ..
                },
            ),
            _,
        ) => (
            Some(Placement {
                base_mm: *base_mm,
                yaw_deg: *yaw_deg,
            }),
            None,
            index(point).into_iter().collect(),
        ),
        _ => (None, None, Vec::new()),
    };
    let scene = preview::failure_scene(
        &job.cell,
        &job.robot,
        placement,
        points,
        &marked,
        &error.to_string(),
    );
    let written = preview::render_html(&scene)
        .map_err(Error::from)
        .and_then(|html| write_for(job, &[(path, html.as_bytes())]));
    Some(match written {
        Ok(()) => format!(
            "the preview page of the failure is written to {}",
            path.display()
        ),
        Err(e) => format!("no preview page: {e}"),
    })
}

/// The points a planning failure is about: both ends of a leg that could not be planned, or the
/// one point that cannot be used.
pub(super) fn failed_points(e: &PlanError) -> Vec<usize> {
    match e {
        PlanError::NoPath { from, to, .. }
        | PlanError::SearchFailed { from, to, .. }
        | PlanError::WristTurn { from, to, .. } => vec![*from, *to],
        PlanError::Unsafe { from, .. } => vec![*from, from + 1],
        PlanError::PointBlocked { point, .. } | PlanError::NoJoin { point, .. } => vec![*point],
    }
}
