//! `gen-rapid robots [--json]`: the robots built into gen-rapid, the names `robot.model` takes,
//! each with its reach, coupling and axis ranges (`output::robots`), as text or, with `--json`,
//! as a JSON array on stdout. Reads no file: the robots' files are built in.

use super::emit;
use crate::error::{Error, Failure};
use crate::output::robots::{self, Listed};
use crate::robot::ik::wrist::{horizontal_reach_mm, ArmGeometry};
use crate::robot::models::MODELS;
use crate::robot::Robot;

pub struct RobotsOptions {
    pub json: bool,
}

/// Lists the shipped robots. Returns the summary line for stderr.
pub fn list(opts: &RobotsOptions) -> Result<String, Failure> {
    let fail_in = |error: Error, file: String| Failure {
        error: Box::new(error),
        file,
        text: None,
        notes: Vec::new(),
    };
    let fail = |error: Error| fail_in(error, "<stdout>".into());
    let mut list: Vec<Listed> = Vec::new();
    for m in MODELS {
        // The built-in files are tested; a failure here would be a build defect, said as such.
        let robot = Robot::shipped(m.name).map_err(|source| {
            let error = Error::Robot {
                source,
                loc: Default::default(),
            };
            fail_in(error, format!("{}.urdf (built in)", m.name))
        })?;
        let reach = ArmGeometry::from_robot(&robot)
            .ok()
            .map(|g| horizontal_reach_mm(&robot, &g));
        list.push(robots::listed(m.name, m.title, &robot, reach));
    }
    let out = if opts.json {
        super::to_json(&list).map_err(fail)?
    } else {
        robots::render_text(&list)
    };
    emit(out.as_bytes()).map_err(fail)?;
    Ok(format!(
        "gen-rapid robots: {} robots built in; a cell names one with robot.model",
        list.len()
    ))
}
