//! `gen-rapid compare <CELL>`: the paper's comparison of its three search methods (sections 4-6:
//! manipulation steps and manipulation time of the neighboring, depth-first and extensile
//! searches) on one cell.
//!
//! The grid is inspected once and all three methods plan on it. One row per method: moves, path
//! length in joint space (axes 1..3, deg), manipulation time (`timing`, s) and planning time
//! (ms, wall clock of the search, shortening and merging). A method that fails is a row saying
//! why, not an error: the exit status is 0 when at least one method found a route, 3 (planning
//! failed) when none did. Everything is deterministic except the planning time.

use super::{emit, load, write_atomically, Failure};
use crate::cell::Method;
use crate::error::Error;
use crate::output::cspace_svg as picture;
use crate::pipeline;
use crate::plan::Plan;
use serde::Serialize;
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

/// One method's result.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub method: String,
    pub ok: bool,
    pub moves: Option<usize>,
    pub path_length_deg: Option<f64>,
    pub manipulation_time_s: Option<f64>,
    /// Wall clock, varies from run to run.
    pub planning_time_ms: f64,
    /// Why the method failed.
    pub error: Option<String>,
}

/// The whole comparison (what `--json` prints).
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    pub cell: String,
    pub grid_deg: f64,
    pub nodes: usize,
    pub free_nodes: usize,
    pub points: Vec<String>,
    pub methods: Vec<Row>,
}

impl Comparison {
    /// The table for the terminal.
    pub fn table(&self) -> String {
        let mut out = format!(
            "{}: {} points, {} deg grid, {} nodes ({} free)\n",
            self.cell,
            self.points.len(),
            self.grid_deg,
            self.nodes,
            self.free_nodes
        );
        out += &format!(
            "{:<12} {:>6} {:>18} {:>22} {:>19}\n",
            "method", "moves", "path length (deg)", "manipulation time (s)", "planning time (ms)"
        );
        for r in &self.methods {
            match (r.moves, r.path_length_deg, r.manipulation_time_s) {
                (Some(m), Some(l), Some(t)) => {
                    out += &format!(
                        "{:<12} {:>6} {:>18.1} {:>22.2} {:>19.0}\n",
                        r.method, m, l, t, r.planning_time_ms
                    )
                }
                _ => {
                    out += &format!(
                        "{:<12} failed: {}\n",
                        r.method,
                        r.error.as_deref().unwrap_or("unknown reason")
                    )
                }
            }
        }
        out += "(manipulation time: each move from rest to rest, quintic ramps and cruise or one quintic, paper section 5; planning time varies from run to run)\n";
        out
    }
}

/// Runs the comparison. The table (or JSON) goes to stdout even when every method fails; then
/// the error is [`Error::NoMethodSucceeded`] (exit status 3) and no picture is written.
pub fn compare(opts: &CompareOptions) -> Result<String, Failure> {
    let started = Instant::now();
    let loaded = load(&opts.cell)?;
    let grid_deg = opts.grid_deg.unwrap_or(loaded.cell.planner.grid_deg);
    let prep = pipeline::prepare(loaded.cell.clone()).map_err(|e| loaded.fail(e))?;
    let cs = pipeline::cspace(&prep, grid_deg);
    let mut rows = Vec::new();
    let mut plans: Vec<Plan> = Vec::new();
    let mut failures = Vec::new();
    for method in Method::ALL {
        let t = Instant::now();
        let result = pipeline::plan_route(&prep, &cs, method);
        let planning_time_ms = t.elapsed().as_secs_f64() * 1e3;
        match result {
            Ok(plan) => {
                rows.push(Row {
                    method: method.name().to_string(),
                    ok: true,
                    moves: Some(plan.moves()),
                    path_length_deg: Some(plan.path_length_deg()),
                    manipulation_time_s: Some(pipeline::manipulation_time_s(&prep, &plan)),
                    planning_time_ms,
                    error: None,
                });
                plans.push(plan);
            }
            Err(e) => {
                let message = e.to_string();
                failures.push(format!("{method}: {message}"));
                rows.push(Row {
                    method: method.name().to_string(),
                    ok: false,
                    moves: None,
                    path_length_deg: None,
                    manipulation_time_s: None,
                    planning_time_ms,
                    error: Some(message),
                });
            }
        }
    }
    let comparison = Comparison {
        cell: opts.cell.display().to_string(),
        grid_deg,
        nodes: cs.grid.len(),
        free_nodes: cs.free_count(),
        points: prep.points.iter().map(|p| p.name.clone()).collect(),
        methods: rows,
    };
    let svg = match (&opts.svg, plans.is_empty()) {
        (Some(path), false) => {
            let title = format!(
                "{}: the three searches on a {} deg grid",
                opts.cell.display(),
                grid_deg
            );
            let routes: Vec<&Plan> = plans.iter().collect();
            let in_range = |a: &[f64; 3]| prep.robot.check_range3(a).is_ok();
            let text = picture::render_svg(&cs, &in_range, &prep.points, &routes, &title)
                .map_err(|e| loaded.fail(e.into()))?;
            Some((path, text))
        }
        _ => None,
    };
    let text = if opts.json {
        super::to_json(&comparison).map_err(|e| loaded.fail(e))?
    } else {
        comparison.table()
    };
    // The picture first: if it cannot be written, nothing has reached stdout yet. (With no
    // route there is no picture; the table still says why each method failed.)
    if let (Some((path, svg_text)), false) = (&svg, plans.is_empty()) {
        write_atomically(path, svg_text.as_bytes()).map_err(|e| loaded.fail(e))?;
    }
    emit(None, text.as_bytes()).map_err(|e| loaded.fail(e))?;
    if plans.is_empty() {
        return Err(loaded.fail(Error::NoMethodSucceeded { failures }));
    }
    Ok(format!(
        "gen-rapid compare: {}: {} of 3 methods found a route, {:.2} s",
        opts.cell.display(),
        plans.len(),
        started.elapsed().as_secs_f64()
    ))
}
