//! [`Plan`] -> [`rapid::Program`](Program): the targets in visiting order with all six axes,
//! the header facts (the cell file, the planner and grid, the clearance asked for, the base
//! used, the moves, the certified smallest clearance, the time estimate), and the cell's speed,
//! zone and tool. Everything comes from the cell, the placed job and the plan; no text is
//! produced here (`rapid` does).

use super::rapid::{Header, JointTarget, Program, TargetKind};
use crate::cell::Cell;
use crate::place::Placed;
use crate::plan::{Plan, WaypointKind};

/// The module's content for a plan of `cell`, placed as `placed`.
pub fn build(cell: &Cell, placed: &Placed, plan: &Plan) -> Program {
    let name = |i: usize| {
        placed
            .points
            .get(i)
            .map(|p| p.name.clone())
            .unwrap_or_default()
    };
    let targets = plan
        .waypoints
        .iter()
        .map(|w| JointTarget {
            kind: match w.kind {
                WaypointKind::CellPoint(i) => TargetKind::CellPoint { name: name(i) },
                WaypointKind::Via { leg, index } => TargetKind::Via { leg, index },
            },
            axes_deg: w.joints_deg,
        })
        .collect();
    let cell_file = cell
        .path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    Program {
        module: cell.module.clone(),
        header: Header {
            generator: format!("gen-rapid {}", env!("CARGO_PKG_VERSION")),
            cell_file,
            planner: plan.method.name().to_string(),
            grid_deg: plan.grid_deg,
            clearance_mm: cell.planner.clearance_mm,
            base_mm: placed.placement.base_mm,
            yaw_deg: placed.placement.yaw_deg,
            moves: plan.moves(),
            min_clearance_mm: plan.min_clearance.as_ref().map(|c| c.mm),
            estimated_time_s: plan.estimate.as_ref().map(|e| e.total_s),
        },
        targets,
        speed: cell.motion.speed.clone(),
        zone: cell.motion.zone.clone(),
        tool: cell.motion.tool.clone(),
    }
}
