//! Plan -> [`rapid::Program`]: the targets in visiting order with all six axes, the header
//! facts (base, grid, clearance, moves, the smallest clearance along the path, the time
//! estimate), and the cell's speed, zone and tool. No text is produced here (`rapid` does).
//!
//! Axes 4..6: a cell point keeps its own when it gives all six axes, otherwise the cell's
//! `robot.wrist`; the intermediate targets of a leg hold the wrist of the leg's first point, so
//! the wrist turns (if at all) on the leg's last move. The wrist does not enter the collision
//! model: the forearm cylinder covers it (paper section 6).

use crate::collision::CollisionModel;
use crate::output::rapid::{Header, JointTarget, Program, TargetKind};
use crate::plan::Plan;
use crate::timing::six_axis_targets;

/// Tolerance of the reported smallest clearance, mm.
pub const MIN_CLEARANCE_TOL_MM: f64 = 0.05;

/// What the program needs besides the plan.
pub struct ProgramInput<'a> {
    pub module: &'a str,
    pub cell_file: &'a str,
    pub names: &'a [String],
    /// Axes 4..6 of each cell point, deg.
    pub wrists_deg: &'a [[f64; 3]],
    pub grid_deg: f64,
    pub base_mm: [f64; 3],
    pub yaw_deg: f64,
    pub speed: &'a str,
    pub zone: &'a str,
    pub tool: &'a str,
    pub estimated_time_s: Option<f64>,
}

/// The smallest clearance along all moves (a certified lower bound within
/// [`MIN_CLEARANCE_TOL_MM`]); None without obstacles.
pub fn min_clearance_mm(plan: &Plan, model: &CollisionModel) -> Option<f64> {
    if model.obstacles().is_empty() {
        return None;
    }
    plan.segments()
        .map(|(a, b)| model.min_clearance_along(&a, &b, MIN_CLEARANCE_TOL_MM))
        .reduce(f64::min)
}

pub fn build(plan: &Plan, model: &CollisionModel, input: &ProgramInput) -> Program {
    // The kind of each target, in the order of `timing::six_axis_targets`, which holds the one
    // rule for the wrist axes (so the time estimate and the module agree).
    let mut kinds = Vec::with_capacity(plan.moves() + 1);
    if let Some(first) = plan.legs.first() {
        kinds.push(TargetKind::CellPoint {
            name: input.names[first.from].clone(),
        });
    }
    for (leg_index, leg) in plan.legs.iter().enumerate() {
        let n = leg.waypoints.len();
        for k in 1..n {
            kinds.push(if k == n - 1 {
                TargetKind::CellPoint {
                    name: input.names[leg.to].clone(),
                }
            } else {
                TargetKind::Via {
                    leg: leg_index,
                    index: k,
                }
            });
        }
    }
    let targets = kinds
        .into_iter()
        .zip(six_axis_targets(plan, input.wrists_deg))
        .map(|(kind, axes_deg)| JointTarget { kind, axes_deg })
        .collect();
    Program {
        module: input.module.to_string(),
        header: Header {
            generator: format!("gen-rapid {}", env!("CARGO_PKG_VERSION")),
            cell_file: input.cell_file.to_string(),
            planner: plan.method.name().to_string(),
            grid_deg: input.grid_deg,
            clearance_mm: model.clearance_mm(),
            base_mm: input.base_mm,
            yaw_deg: input.yaw_deg,
            moves: plan.moves(),
            min_clearance_mm: min_clearance_mm(plan, model),
            estimated_time_s: input.estimated_time_s,
        },
        targets,
        speed: input.speed.to_string(),
        zone: input.zone.to_string(),
        tool: input.tool.to_string(),
    }
}
