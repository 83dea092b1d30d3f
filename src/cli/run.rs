//! `gen-rapid <CELL>`: plan the cell and write the RAPID module (and, with `--svg`, a picture
//! of the search; when the plan fails, a picture of why: the blocked nodes and the points of the
//! leg that failed).

use super::{emit, write_atomically};
use crate::error::{Error, Failure};
use crate::output::cspace_svg::{self, Marked};
use crate::pipeline::{self, Halted, Loaded};
use crate::plan::Method;
use crate::plan::PlanError;
use std::path::PathBuf;
use std::time::Instant;

pub struct RunOptions {
    pub cell: PathBuf,
    pub output: Option<PathBuf>,
    pub planner: Option<Method>,
    pub grid_deg: Option<f64>,
    /// Also draw the route over the configuration space (`cspace_svg`) to this file.
    pub svg: Option<PathBuf>,
}

/// Runs the pipeline; on success the module (and the picture) is written and a summary line is
/// returned for stderr. On any error no module is written and stdout stays empty: the picture
/// is drawn before the module is emitted and written only after it. When the plan stage fails,
/// `--svg` draws the failure instead.
pub fn run(opts: &RunOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let job = pipeline::load(&opts.cell)?;
    super::warn(&job);
    let method = opts.planner.unwrap_or(job.cell.planner.method);
    let grid_deg = opts.grid_deg.unwrap_or(job.cell.planner.grid_deg);
    let out = match pipeline::run(&job, method, grid_deg) {
        Ok(out) => out,
        Err(halted) => return Err(failed(&job, opts, method, grid_deg, halted)),
    };
    let svg = match &opts.svg {
        Some(path) => {
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
                &[&out.plan],
                &title,
            )
            .map_err(|e| job.fail(e.into()))?;
            Some((path, text))
        }
        None => None,
    };
    // The picture first: if it cannot be written, nothing has reached stdout yet.
    if let Some((path, text)) = svg {
        write_atomically(path, text.as_bytes()).map_err(|e| job.fail(e))?;
    }
    emit(opts.output.as_deref(), out.rendered.text.as_bytes()).map_err(|e| job.fail(e))?;
    let clearance = match &out.plan.min_clearance {
        Some(c) => format!("smallest clearance {:.1} mm", c.mm),
        None => "no obstacles".to_string(),
    };
    let time = match &out.plan.estimate {
        Some(e) => format!(", about {:.2} s of motion", e.total_s),
        None => String::new(),
    };
    let moves = out.plan.moves();
    Ok(format!(
        "gen-rapid: {}: {} move{}{time}, {}, {} on a {} deg grid, {:.2} s",
        opts.cell.display(),
        moves,
        if moves == 1 { "" } else { "s" },
        clearance,
        method,
        grid_deg,
        started.elapsed().as_secs_f64()
    ))
}

/// A run that failed. With `--svg`, when the plan stage failed, the picture of the failure: the
/// grid's blocked nodes and the cell points, those the failure is about ringed (written
/// atomically; the exit status stays the planning failure's); a note says what was drawn, or
/// why nothing was.
fn failed(
    job: &Loaded,
    opts: &RunOptions,
    method: crate::plan::Method,
    grid_deg: f64,
    halted: Halted,
) -> Failure {
    let Halted { error, searched } = halted;
    let error = *error;
    let Some(path) = &opts.svg else {
        return job.fail(error);
    };
    let note = match (&error, searched) {
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
            .and_then(|svg| write_atomically(path, svg.as_bytes()));
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
    };
    let mut failure = job.fail(error);
    failure.notes.push(note);
    failure
}

/// The points a planning failure is about: both ends of a leg that could not be planned, or the
/// one point that cannot be used.
pub(super) fn failed_points(e: &PlanError) -> Vec<usize> {
    match e {
        PlanError::NoPath { from, to, .. } | PlanError::SearchFailed { from, to, .. } => {
            vec![*from, *to]
        }
        PlanError::Unsafe { from, .. } => vec![*from, from + 1],
        PlanError::PointBlocked { point, .. } | PlanError::NoJoin { point, .. } => vec![*point],
    }
}
