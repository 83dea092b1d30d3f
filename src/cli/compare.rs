//! `gen-rapid compare <CELL>`: the paper's comparison of its three search methods (sections 4-6:
//! manipulation steps and manipulation time of the neighboring, depth-first and extensile
//! searches) on one cell.
//!
//! The grid is inspected once and all three methods plan on it. One row per method: moves, path
//! length in joint space (axes 1..3, deg), manipulation time (`timing`, s: the route as planned,
//! every via a stop point) and planning time (ms, wall clock of the search, shortening, merging
//! and move proofs). A last row, beyond the paper, is the extensile route through the refine
//! stage with the shortcut pass (whatever `planner.shortcut` says), its planning time the
//! search's and the refine stage's. A method that fails is a row saying why, not an error: the
//! exit status is 0 when at least one method found a route, 3 (planning failed) when none did.
//! Everything is deterministic except the planning time.

use super::{emit, write_for};
use crate::error::{Error, Failure};
use crate::output::comparison::{Comparison, Row};
use crate::output::cspace_svg::{self, Marked};
use crate::pipeline::{self, Inspected, Loaded};
use crate::place::Placed;
use crate::plan::motion::{self, Estimate};
use crate::plan::{Method, Route};
use crate::progress::Silent;
use crate::timing;
use std::path::PathBuf;
use std::time::Instant;

pub struct CompareOptions {
    pub cell: PathBuf,
    /// Print JSON instead of the table.
    pub json: bool,
    /// Draw every route found over the configuration space to this file.
    pub svg: Option<PathBuf>,
    pub grid_deg: Option<f64>,
}

/// Runs the comparison. The table (or JSON) goes to stdout even when every method fails; then
/// the error is [`Error::NoMethodSucceeded`] (exit status 3) and `--svg` draws the grid with the
/// points the methods failed at ringed.
pub fn compare(opts: &CompareOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let job = pipeline::load(&opts.cell)?;
    super::warn(&job);
    let grid_deg = opts.grid_deg.unwrap_or(job.cell.planner.grid_deg);
    // Three searches and the shortcut row on every leg.
    pipeline::check_budgets(&job, grid_deg, 4).map_err(|e| job.fail(e))?;
    let placed = pipeline::place(&job).map_err(|e| {
        let mut failure = job.fail(e);
        if let Some(path) = &opts.svg {
            failure.notes.push(format!(
                "nothing drawn to {}: the comparison stopped before the grid was searched",
                path.display()
            ));
        }
        failure
    })?;
    let inspected = pipeline::inspect(&job, &placed, grid_deg);
    // The whole grid inspected first, as the paper does: no method's planning time holds it.
    inspected.cspace.inspect_all(&Silent);
    let attempts = attempts(&job, &placed, &inspected);
    let mut rows: Vec<Row> = attempts
        .iter()
        .map(|a| {
            let result = match &a.result {
                Ok((route, estimate)) => Ok((route, estimate.total_s)),
                Err(e) => Err(e.to_string()),
            };
            Row::of(a.method, result, a.planning_time_ms)
        })
        .collect();
    // Beyond the paper: the extensile route with the shortcut pass.
    let extensile = attempts.iter().find(|a| a.method == Method::Extensile);
    let shortcut = extensile.and_then(|a| {
        let (route, _) = a.result.as_ref().ok()?;
        let started = Instant::now();
        let plan = pipeline::refine(&job, &placed, &inspected, route.clone(), true).plan;
        let ms = a.planning_time_ms + started.elapsed().as_secs_f64() * 1e3;
        Some((plan, ms))
    });
    rows.push(match &shortcut {
        Some((plan, ms)) => Row::of(Method::Extensile, Ok((&plan.route, plan.total_s)), *ms),
        None => Row::of(
            Method::Extensile,
            Err("the extensile search found no route".into()),
            0.0,
        ),
    });
    if let Some(last) = rows.last_mut() {
        last.method = format!("{} + shortcut", Method::Extensile.name());
    }
    let failures: Vec<String> = attempts
        .iter()
        .filter_map(|a| {
            a.result
                .as_ref()
                .err()
                .map(|e| format!("{}: {e}", a.method))
        })
        .collect();
    let plans: Vec<&Route> = attempts
        .iter()
        .filter_map(|a| a.result.as_ref().ok().map(|(route, _)| route))
        .collect();
    let comparison = Comparison {
        cell: opts.cell.display().to_string(),
        grid_deg,
        nodes: inspected.cspace.grid.len(),
        free_nodes: inspected.cspace.free_count(),
        points: placed.points.iter().map(|p| p.name.clone()).collect(),
        methods: rows,
    };
    let title = |what: &str| {
        format!(
            "{}: the three searches on a {} deg grid{what}",
            opts.cell.display(),
            grid_deg
        )
    };
    let in_range = |a: &[f64; 3]| job.robot.check_range3(a).is_ok();
    let svg = match &opts.svg {
        Some(path) if !plans.is_empty() => {
            let text = cspace_svg::render_svg(
                &inspected.cspace,
                &in_range,
                &placed.points,
                &plans,
                &title(""),
            )
            .map_err(|e| job.fail(e.into()))?;
            Some((path, text))
        }
        Some(path) => {
            // No route: the picture of why, the points every method failed at ringed.
            let mut marked: Vec<usize> = Vec::new();
            for a in &attempts {
                if let Err(Error::Plan { source, .. }) = &a.result {
                    marked.extend(super::run::failed_points(source));
                }
            }
            marked.sort_unstable();
            marked.dedup();
            let text = cspace_svg::render_failure_svg(
                &inspected.cspace,
                &in_range,
                &placed.points,
                &Marked {
                    points: &marked,
                    why: &failures.join("; "),
                },
                &title(": no route"),
            )
            .map_err(|e| job.fail(e.into()))?;
            Some((path, text))
        }
        None => None,
    };
    let text = if opts.json {
        super::to_json(&comparison).map_err(|e| job.fail(e))?
    } else {
        comparison.table()
    };
    // The picture first: if it cannot be written, nothing has reached stdout yet.
    if let Some((path, svg_text)) = &svg {
        write_for(&job, &[(path, svg_text.as_bytes())]).map_err(|e| job.fail(e))?;
    }
    emit(text.as_bytes()).map_err(|e| job.fail(e))?;
    if plans.is_empty() {
        let mut failure = job.fail(Error::NoMethodSucceeded { failures });
        if let Some((path, _)) = &svg {
            failure.notes.push(format!(
                "the blocked nodes of the grid are drawn to {}, with the points the methods failed at ringed in red",
                path.display()
            ));
        }
        return Err(failure);
    }
    Ok(format!(
        "gen-rapid compare: {}: {} of 3 methods found a route, {:.2} s",
        opts.cell.display(),
        plans.len(),
        started.elapsed().as_secs_f64()
    ))
}

/// One method's attempt: its route timed as planned (every via a stop point, no clearance
/// measured) or why it failed, and the wall-clock time of planning it.
struct Attempt {
    method: Method,
    result: Result<(Route, Estimate), Error>,
    planning_time_ms: f64,
}

/// The paper's three methods on one inspected grid.
fn attempts(job: &Loaded, placed: &Placed, inspected: &Inspected) -> Vec<Attempt> {
    let model = timing::TimeModel::new(&job.robot, job.cell.tool.as_ref());
    let timed = |r: Route| {
        let estimate = timing::estimate(&r, &motion::planned(&r, &placed.points), &model);
        (r, estimate)
    };
    let attempt = |method| {
        let started = Instant::now();
        let result = pipeline::route(job, placed, inspected, method);
        let planning_time_ms = started.elapsed().as_secs_f64() * 1e3;
        Attempt {
            method,
            result: result.map(timed),
            planning_time_ms,
        }
    };
    Method::ALL.into_iter().map(attempt).collect()
}
