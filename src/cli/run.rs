//! `gen-rapid <CELL>`: plan the cell and write the RAPID module.

use super::{emit, load, Failure};
use crate::cell::Method;
use crate::pipeline;
use std::path::PathBuf;
use std::time::Instant;

pub struct RunOptions {
    pub cell: PathBuf,
    pub output: Option<PathBuf>,
    pub planner: Option<Method>,
    pub grid_deg: Option<f64>,
}

/// Runs the pipeline; on success the module is written and a summary line is returned for
/// stderr.
pub fn run(opts: &RunOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let loaded = load(&opts.cell)?;
    let method = opts.planner.unwrap_or(loaded.cell.planner.method);
    let grid_deg = opts.grid_deg.unwrap_or(loaded.cell.planner.grid_deg);
    let prep = pipeline::prepare(loaded.cell.clone()).map_err(|e| loaded.fail(e))?;
    let cs = pipeline::cspace(&prep, grid_deg);
    let outcome =
        pipeline::plan_and_render(&prep, &cs, method, |_| None).map_err(|e| loaded.fail(e))?;
    emit(opts.output.as_deref(), outcome.text.as_bytes()).map_err(|e| loaded.fail(e))?;
    let clearance = match outcome.program.header.min_clearance_mm {
        Some(c) => format!("smallest clearance {c:.1} mm"),
        None => "no obstacles".to_string(),
    };
    Ok(format!(
        "gen-rapid: {}: {} moves, {}, {} on a {} deg grid, {:.2} s",
        opts.cell.display(),
        outcome.plan.moves(),
        clearance,
        method,
        grid_deg,
        started.elapsed().as_secs_f64()
    ))
}
