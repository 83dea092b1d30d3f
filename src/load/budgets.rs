//! The budgets of a loaded job, checked before any work: the counts of the cell and the robot
//! files, the grid's nodes, the inspection, the legs and the fly-by zones (`crate::budget`
//! holds the figures), each refusal pointing at the place in the input that passes it.

use super::Loaded;
use crate::cell::Cell;
use crate::error::Error;
use crate::robot::RobotError;

/// The budgets of a run on a grid of `grid_deg` with `searches` searches a leg (1 for a run, 4
/// for `compare`), checked before any work (`budget`): the refusal points at the grid where the
/// cell sets it (none: the grid comes from `--grid`, or the ranges from the robot files, named
/// in the message), else at the point or obstacle that passes the budget.
pub fn check_budgets(job: &Loaded, grid_deg: f64, searches: usize) -> Result<(), Error> {
    use crate::budget::{self, Exceeded};
    let (cell, robot) = (&job.cell, &job.robot);
    let counts = [
        ("points", cell.points.len(), budget::MAX_POINTS),
        ("obstacles", cell.obstacles.len(), budget::MAX_OBSTACLES),
        (
            "tool shapes",
            cell.tool.as_ref().map_or(0, |t| t.shapes.len()),
            budget::MAX_TOOL_SHAPES,
        ),
    ];
    let count_loc = |what: &str, at: usize| match what {
        "points" => cell.points.get(at).map(|p| p.loc),
        "obstacles" => cell.obstacles.get(at).map(|o| o.loc),
        _ => cell
            .tool
            .as_ref()
            .and_then(|t| t.shapes.get(at))
            .map(|s| s.loc),
    };
    for (what, found, max) in counts {
        if let Err(source) = budget::count_within(what, found, max) {
            let loc = count_loc(what, max).unwrap_or_default();
            return Err(Error::Budget { source, loc });
        }
    }
    if robot.cylinders.len() > budget::MAX_LINK_CYLINDERS {
        return Err(Error::Robot {
            source: RobotError::Model {
                path: robot.urdf_path.clone(),
                message: format!(
                    "its links carry {} collision cylinders, more than the {} a run takes (each is checked at every node of the grid)",
                    robot.cylinders.len(),
                    budget::MAX_LINK_CYLINDERS
                ),
            },
            loc: cell.robot.urdf_loc,
        });
    }
    let a = &robot.controller.axes;
    let demand = budget::Demand {
        ranges_deg: [0, 1, 2].map(|k| [a[k].min_deg, a[k].max_deg]),
        grid_deg,
        parts: robot.cylinders.len() + cell.tool.as_ref().map_or(0, |t| t.shapes.len()),
        obstacles: cell.obstacles.len(),
        // The leg closing the cycle is one more.
        points: cell.points.len() + usize::from(cell.closing_leg()),
        searches,
        fly_by: fly_by(cell),
    };
    let Err(source) = budget::check(&demand) else {
        return Ok(());
    };
    // The grid's own line, where the cell sets the grid the run uses.
    let grid_loc = cell
        .planner
        .grid_loc
        .filter(|_| cell.planner.grid_deg == grid_deg);
    let point = |k: usize| cell.points.get(k).map(|p| p.loc);
    let loc = match &source {
        Exceeded::GridNodes { .. } => grid_loc.or(Some(match cell.robot.controller_path {
            Some(_) => cell.robot.controller_loc,
            None => cell.robot.urdf_loc,
        })),
        Exceeded::Inspection { at, .. } => {
            grid_loc.or_else(|| at.and_then(|k| cell.obstacles.get(k)).map(|o| o.loc))
        }
        Exceeded::Legs { at, .. } => grid_loc.or_else(|| at.and_then(point)),
        Exceeded::ZonedLegs { at, .. } => point(*at),
        Exceeded::Count { .. } => None,
    };
    Err(Error::Budget {
        source,
        loc: loc.unwrap_or_default(),
    })
}

/// Whether any move of the cell asks a zone other than `fine` (a fly-by zone to certify).
fn fly_by(cell: &Cell) -> bool {
    let fine = |z: &str| z.eq_ignore_ascii_case("fine");
    !fine(&cell.motion.via_zone)
        || !fine(&cell.motion.zone)
        || cell
            .points
            .iter()
            .any(|p| p.zone.as_deref().is_some_and(|z| !fine(z)))
}
