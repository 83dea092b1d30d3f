//! `gen-rapid locate <CELL> [--svg FILE] [--json]`: the robot-location stage on its own (paper
//! section 2, eq. 1-2 and Fig. 1).
//!
//! Computes the feasible region `R` of base positions for the cell's points and reports its
//! area, its bounding box, a base in it and its margin, and the number of points; as text, or as
//! JSON with `--json` (one object on stdout, fields of [`Report`]).
//!
//! - `base: auto`: the points must be `xyz` points; the reported base is the one `gen-rapid
//!   CELL` plans from (the same rule of the place stage, [`place::survey`](crate::place::survey)).
//! - A fixed base: `R` is computed all the same, from the `xyz` points and from the wrist
//!   centres of the `joints` points by forward kinematics at the given base and yaw, at the
//!   given base's height; the report says whether the given base lies in `R` (exact test, with
//!   its margin) besides the position with the largest margin.
//!
//! `--svg FILE` draws the top view ([`topview_svg`]), written atomically; stdout gets the report
//! only when everything succeeded. Errors are the run's: an empty `R` exits 3 naming the points
//! or obstacles, pointing at `robot.base`; then `--svg` draws why (the reach circles, the
//! obstacles' footprints, R where it is not empty: [`topview_svg::render_failure`]).

use super::{emit, write_for};
use crate::error::{Error, Failure};
use crate::output::location::{self, Report};
use crate::output::topview_svg;
use crate::pipeline;
use crate::pipeline::Loaded;
use crate::place::PlaceError;
use std::path::PathBuf;
use std::time::Instant;

pub struct LocateOptions {
    pub cell: PathBuf,
    pub svg: Option<PathBuf>,
    pub json: bool,
}

/// Locates, reports and draws. Returns the summary line for stderr.
pub fn locate(opts: &LocateOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let job = pipeline::load(&opts.cell)?;
    super::warn(&job);
    let survey = match pipeline::survey(&job) {
        Ok(survey) => survey,
        Err(e) => return Err(failed(&job, opts, e)),
    };
    let rep: Report = location::report(&job.cell, &survey);
    let out = if opts.json {
        super::to_json(&rep).map_err(|e| job.fail(e))?
    } else {
        location::render_text(&rep)
    };
    if let Some(path) = &opts.svg {
        let svg = topview_svg::render(&job.cell, &survey, &rep).map_err(|message| {
            job.fail(Error::Write {
                path: path.clone(),
                source: std::io::Error::other(format!("drawing failed: {message}")),
            })
        })?;
        write_for(&job, &[(path, svg.as_bytes())]).map_err(|e| job.fail(e))?;
    }
    emit(out.as_bytes()).map_err(|e| job.fail(e))?;
    Ok(format!(
        "gen-rapid locate: {}: R {:.3} m^2, {} points{}, {:.2} s",
        opts.cell.display(),
        rep.area_m2,
        rep.points,
        opts.svg
            .as_ref()
            .map(|p| format!(", drawn to {}", p.display()))
            .unwrap_or_default(),
        started.elapsed().as_secs_f64()
    ))
}

/// `locate` failed. With `--svg`, when no base position will do, the top view of why: every
/// point's reach region, the obstacles' footprints, R where it is not empty (written
/// atomically; the exit status stays the failure's); a note says what was drawn.
fn failed(job: &Loaded, opts: &LocateOptions, error: Error) -> Failure {
    let Some(path) = &opts.svg else {
        return job.fail(error);
    };
    let note = match &error {
        Error::Place(PlaceError::Locate { .. }) => {
            let drawn = pipeline::sketch(job).and_then(|sketch| {
                let svg = topview_svg::render_failure(&job.cell, &sketch).map_err(|message| {
                    Error::Write {
                        path: path.clone(),
                        source: std::io::Error::other(format!("drawing failed: {message}")),
                    }
                })?;
                write_for(job, &[(path, svg.as_bytes())])
            });
            match drawn {
                Ok(()) => format!(
                    "the reach regions and the obstacles' footprints are drawn to {}",
                    path.display()
                ),
                Err(e) => format!("no picture: {e}"),
            }
        }
        _ => format!(
            "nothing drawn to {}: the failure is not about where the base stands",
            path.display()
        ),
    };
    let mut failure = job.fail(error);
    failure.notes.push(note);
    failure
}
