//! The comparison of the three search methods on one cell (paper sections 4-6: manipulation
//! steps and manipulation time of the neighboring, depth-first and extensile searches): one row
//! per method, as a table for the terminal or as JSON (`--json`).

use crate::plan::{Method, Route};
use serde::Serialize;

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

impl Row {
    /// The row of one method: its route and its estimated time (s), or why it failed.
    pub fn of(method: Method, result: Result<(&Route, f64), String>, planning_time_ms: f64) -> Row {
        let timed = result.as_ref().ok();
        Row {
            method: method.name().to_string(),
            ok: timed.is_some(),
            moves: timed.map(|(r, _)| r.moves()),
            path_length_deg: timed.map(|(r, _)| r.path_length_deg()),
            manipulation_time_s: timed.map(|&(_, t)| t),
            planning_time_ms,
            error: result.err(),
        }
    }
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
            "{:<20} {:>6} {:>18} {:>22} {:>19}\n",
            "method", "moves", "path length (deg)", "manipulation time (s)", "planning time (ms)"
        );
        for r in &self.methods {
            match (r.moves, r.path_length_deg, r.manipulation_time_s) {
                (Some(m), Some(l), Some(t)) => {
                    out += &format!(
                        "{:<20} {:>6} {:>18.1} {:>22.2} {:>19.0}\n",
                        r.method, m, l, t, r.planning_time_ms
                    )
                }
                _ => {
                    out += &format!(
                        "{:<20} failed: {}\n",
                        r.method,
                        r.error.as_deref().unwrap_or("unknown reason")
                    )
                }
            }
        }
        out += "(manipulation time: each move from rest to rest, quintic ramps and cruise or one quintic, paper section 5, and no faster than the TCP path and the reorientation at the speeddata's v_tcp and v_ori; planning time varies from run to run)\n";
        out
    }
}
