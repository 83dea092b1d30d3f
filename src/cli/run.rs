//! `gen-rapid <CELL>`: plan the cell and write the RAPID module (and, with `--svg`, a picture
//! of the search).

use super::{emit, load, write_atomically, Failure};
use crate::cell::Method;
use crate::output::cspace_svg as picture;
use crate::pipeline;
use std::path::PathBuf;
use std::time::Instant;

pub struct RunOptions {
    pub cell: PathBuf,
    pub output: Option<PathBuf>,
    pub planner: Option<Method>,
    pub grid_deg: Option<f64>,
    /// Also draw the route over the configuration space (`picture`) to this file.
    pub svg: Option<PathBuf>,
}

/// Runs the pipeline; on success the module (and the picture) is written and a summary line is
/// returned for stderr. On any error nothing is written: the picture is drawn before the module
/// is emitted and written only after it.
pub fn run(opts: &RunOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let loaded = load(&opts.cell)?;
    let method = opts.planner.unwrap_or(loaded.cell.planner.method);
    let grid_deg = opts.grid_deg.unwrap_or(loaded.cell.planner.grid_deg);
    let prep = pipeline::prepare(loaded.cell.clone()).map_err(|e| loaded.fail(e))?;
    let cs = pipeline::cspace(&prep, grid_deg);
    let outcome = pipeline::plan_and_render(&prep, &cs, method, |plan| {
        Some(pipeline::manipulation_time_s(&prep, plan))
    })
    .map_err(|e| loaded.fail(e))?;
    let svg = match &opts.svg {
        Some(path) => {
            let title = format!(
                "{}: {} on a {} deg grid",
                opts.cell.display(),
                method,
                grid_deg
            );
            let in_range = |a: &[f64; 3]| prep.robot.check_range3(a).is_ok();
            let text = picture::render_svg(&cs, &in_range, &prep.points, &[&outcome.plan], &title)
                .map_err(|e| loaded.fail(e.into()))?;
            Some((path, text))
        }
        None => None,
    };
    // The picture first: if it cannot be written, nothing has reached stdout yet.
    if let Some((path, text)) = svg {
        write_atomically(path, text.as_bytes()).map_err(|e| loaded.fail(e))?;
    }
    emit(opts.output.as_deref(), outcome.text.as_bytes()).map_err(|e| loaded.fail(e))?;
    let clearance = match outcome.program.header.min_clearance_mm {
        Some(c) => format!("smallest clearance {c:.1} mm"),
        None => "no obstacles".to_string(),
    };
    let time = match outcome.program.header.estimated_time_s {
        Some(t) => format!(", about {t:.2} s of motion"),
        None => String::new(),
    };
    Ok(format!(
        "gen-rapid: {}: {} move{}{time}, {}, {} on a {} deg grid, {:.2} s",
        opts.cell.display(),
        outcome.plan.moves(),
        if outcome.plan.moves() == 1 { "" } else { "s" },
        clearance,
        method,
        grid_deg,
        started.elapsed().as_secs_f64()
    ))
}
