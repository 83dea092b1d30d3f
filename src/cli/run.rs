//! `gen-rapid <CELL>`: plan the cell and write the RAPID module (and, with `--svg`, a picture
//! of the search).

use super::{emit, write_atomically};
use crate::error::Failure;
use crate::output::cspace_svg;
use crate::pipeline;
use crate::plan::Method;
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
/// returned for stderr. On any error nothing is written: the picture is drawn before the module
/// is emitted and written only after it.
pub fn run(opts: &RunOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let job = pipeline::load(&opts.cell)?;
    super::warn(&job);
    let method = opts.planner.unwrap_or(job.cell.planner.method);
    let grid_deg = opts.grid_deg.unwrap_or(job.cell.planner.grid_deg);
    let out = pipeline::run(&job, method, grid_deg).map_err(|e| job.fail(e))?;
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
