//! [`Plan`] -> [`rapid::Program`](Program): the targets in visiting order with all six axes and
//! the speed and zone of the move into each ([`Plan::motions`]), the robtarget written
//! beside each robtarget point, the tooldata and wobjdata the cell declares, the header facts
//! (the cell file, the robot files and their convention, the planner and grid, the clearance
//! asked for, the base used, the moves, the certified smallest clearance, the time estimate, the
//! zoned vias and the via zone, the paper's method alone) and the robot's ranges for the
//! renderer's last guard. Everything comes from the cell, the placed job, the plan and the
//! [`RobotFacts`] of the robot files; no text is produced here (`rapid` does).

use super::rapid::{
    Action, AxisRanges, Ends, Header, JointTarget, LoadData, MoveHow, Pose, Program, RobTarget,
    TargetKind, ToolData, WobjData,
};
use crate::cell::{ActionKind, Cell, Frame};
use crate::place::{Origin, Placed};
use crate::plan::WaypointKind;
use crate::refine::{MoveKind, OwnTarget, Plan};
use crate::robot::{Coupling, Robot};
use std::path::Path;

/// What the module states about the robot and checks against it, from the robot files.
#[derive(Clone, Debug, PartialEq)]
pub struct RobotFacts {
    /// The shipped robot the cell names, as the header states it (`None`: a URDF file).
    pub model: Option<String>,
    /// The URDF's file name.
    pub urdf: String,
    /// The controller file's name, `None` when there is none (serial arm, URDF limits).
    pub controller: Option<String>,
    /// Axis 3 coupled to axis 2 (parallelogram).
    pub parallelogram: bool,
    pub ranges: AxisRanges,
}

impl RobotFacts {
    /// The facts of `robot`: its files by name, like the cell's (the module names the files,
    /// not where they lie, so a cell moved elsewhere gives the same bytes), its coupling and its
    /// axis ranges.
    pub fn of(robot: &Robot) -> RobotFacts {
        let shown = |p: &Path| {
            p.file_name()
                .map(|f| f.to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        let c = &robot.controller;
        // A shipped model by its name and ABB's name of the variant.
        let model = robot
            .model
            .as_deref()
            .map(|name| match crate::robot::models::find(name) {
                Some(m) => format!("{name} ({}, built into gen-rapid)", m.title),
                None => format!("{name} (built into gen-rapid)"),
            });
        RobotFacts {
            model,
            urdf: shown(&robot.urdf_path),
            controller: c.source.as_deref().map(shown),
            parallelogram: c.coupling == Coupling::Parallelogram,
            ranges: AxisRanges {
                axes_deg: c.axes.map(|a| [a.min_deg, a.max_deg]),
                coupled_axis3_deg: c.coupled_axis3_deg,
            },
        }
    }
}

fn pose(f: &Frame) -> Pose {
    Pose {
        pos_mm: f.pos_mm,
        quat_wxyz: f.quat_wxyz,
    }
}

/// The module's content for a plan of `cell`, placed as `placed`, on the robot of `robot`.
pub fn build(cell: &Cell, placed: &Placed, plan: &Plan, robot: &RobotFacts) -> Program {
    // `robot.frame`: a robtarget in wobj0 and a uframe as the module writes them.
    let frame = cell.robot.frame;
    // A robtarget of entry `i` as written: in wobj0 in the frame `robot.frame` says, in a work
    // object as given.
    let robtarget_as_written = |i: usize, f: &Frame| match cell.points.get(i).and_then(|p| p.wobj) {
        None => placed.placement.written(frame, f),
        Some(_) => *f,
    };
    let robtarget_of = |i: usize| match placed.points.get(i).map(|p| &p.origin) {
        Some(Origin::Robtarget { pose: f, conf }) => Some(RobTarget {
            pose: pose(&robtarget_as_written(i, f)),
            conf: conf.to_array(),
        }),
        _ => None,
    };
    // The work object a move towards entry `i` names: with one work object always it, with
    // several the entry's own (none towards a jointtarget point).
    let wobj_towards = |i: usize| match cell.wobjs.len() {
        1 => Some(0),
        _ => cell.points.get(i).and_then(|p| p.wobj),
    };
    let n = cell.points.len();
    let name_of = |i: usize| {
        placed
            .points
            .get(i)
            .map(|p| p.name.clone())
            .unwrap_or_default()
    };
    let kinds: Vec<MoveKind> = std::iter::once(MoveKind::Joint)
        .chain(plan.moves.iter().map(|m| m.kind))
        .collect();
    // An approach or retract pose's own robtarget: on the approach line out of it, on the
    // retract line into it.
    let own = |o: &Option<OwnTarget>| {
        o.map(|o| RobTarget {
            pose: pose(&o.pose),
            conf: o.conf.to_array(),
        })
    };
    // The entries reached so far: an entry reached again (the leg closing the cycle) is a
    // revisit without actions.
    let mut reached = vec![false; cell.points.len()];
    let targets = plan
        .route
        .waypoints
        .iter()
        .zip(plan.motions())
        .enumerate()
        .map(|(k, (w, motion))| {
            let move_kind = kinds.get(k).copied().unwrap_or(MoveKind::Joint);
            let (kind, robtarget, actions) = match w.kind {
                WaypointKind::CellPoint(i) => {
                    let again = reached.get(i).copied().unwrap_or(false);
                    if let Some(r) = reached.get_mut(i) {
                        *r = true;
                    }
                    let revisit = cell.points.get(i).is_some_and(|p| p.revisit_of.is_some());
                    let kind = match revisit || again {
                        true => TargetKind::Revisit { point: name_of(i) },
                        false => TargetKind::CellPoint { name: name_of(i) },
                    };
                    let actions = match again {
                        true => Vec::new(),
                        false => actions(cell, i),
                    };
                    (kind, robtarget_of(i), actions)
                }
                WaypointKind::Via { leg, index } => {
                    (TargetKind::Via { leg, index }, None, Vec::new())
                }
                WaypointKind::Approach(i) => (
                    TargetKind::Approach { point: name_of(i) },
                    match kinds.get(k + 1) {
                        Some(MoveKind::Approach { own: o, .. }) => own(o),
                        _ => None,
                    },
                    Vec::new(),
                ),
                WaypointKind::Retract(i) => (
                    TargetKind::Retract { point: name_of(i) },
                    match move_kind {
                        MoveKind::Retract { own: o, .. } => own(&o),
                        _ => None,
                    },
                    Vec::new(),
                ),
            };
            // The entry the move goes towards: a via's is its leg's end (the first entry for
            // the leg closing the cycle).
            let towards = match w.kind {
                WaypointKind::CellPoint(i)
                | WaypointKind::Approach(i)
                | WaypointKind::Retract(i) => i,
                WaypointKind::Via { leg, .. } => (leg + 1) % n.max(1),
            };
            let (how, offset_mm) = match move_kind {
                MoveKind::Joint => (MoveHow::Joint, None),
                MoveKind::Linear => (MoveHow::Linear, None),
                MoveKind::Approach { dz_mm, .. } => (MoveHow::Linear, Some(dz_mm)),
                MoveKind::Retract { dz_mm, .. } => (MoveHow::Linear, Some(dz_mm)),
                // The circle point's numbers as the follow stage wrote them.
                MoveKind::Circular { via, via_conf } => (
                    MoveHow::Circular {
                        via: RobTarget {
                            pose: pose(&via),
                            conf: via_conf.to_array(),
                        },
                    },
                    None,
                ),
            };
            // The move into an approach pose: its point's approach length.
            let offset_mm = match w.kind {
                WaypointKind::Approach(i) => cell.points.get(i).and_then(|p| p.approach_mm),
                _ => offset_mm,
            };
            JointTarget {
                kind,
                axes_deg: w.joints_deg,
                speed: motion.speed.clone(),
                zone: motion.zone.clone(),
                robtarget,
                how,
                offset_mm,
                actions,
                wobj: wobj_towards(towards),
            }
        })
        .collect();
    let cell_file = cell
        .path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tooldata = cell.tool.as_ref().map(|t| ToolData {
        tframe: pose(&t.tframe),
        mass_kg: t.mass_kg,
        cog_mm: t.cog_mm,
        shapes: t.shapes.iter().map(|s| s.name.clone()).collect(),
    });
    Program {
        module: cell.module.clone(),
        header: Header {
            generator: format!("gen-rapid {}", env!("CARGO_PKG_VERSION")),
            cell_file,
            model: robot.model.clone(),
            urdf: robot.urdf.clone(),
            controller: robot.controller.clone(),
            parallelogram: robot.parallelogram,
            planner: plan.route.method.name().to_string(),
            grid_deg: plan.route.grid_deg,
            clearance_mm: cell.planner.clearance_mm,
            base_mm: placed.placement.base_mm,
            yaw_deg: placed.placement.yaw_deg,
            moves: plan.route.moves(),
            min_clearance_mm: plan.least.as_ref().map(|c| c.mm),
            estimated_time_s: Some(plan.total_s),
            zoned_vias: plan.zoned_vias(),
            // The zone a via gets where its corner is proven (`motion.via_zone`).
            via_zone: cell.motion.via_zone.clone(),
            paper: plan.paper.map(|p| (p.moves, p.time_s)),
            frame,
            ends: ends(cell, plan),
        },
        targets,
        // The tool block's name when there is one (the cell validation sees to it).
        tool: cell.motion.tool.clone(),
        tooldata,
        wobjs: (cell.wobjs.iter())
            .map(|w| WobjData {
                name: w.name.clone(),
                uframe: pose(&placed.placement.written(frame, &w.uframe)),
            })
            .collect(),
        ranges: robot.ranges,
        proc_name: cell.motion.proc.clone(),
        loads: cell
            .loads
            .iter()
            .map(|l| LoadData {
                name: l.name.clone(),
                mass_kg: l.mass_kg,
                cog_mm: l.cog_mm,
            })
            .collect(),
    }
}

/// The actions of cell entry `i`, as the module writes them (a `grip_load` names its loaddata,
/// or `load0`).
fn actions(cell: &Cell, i: usize) -> Vec<Action> {
    let Some(p) = cell.points.get(i) else {
        return Vec::new();
    };
    p.actions
        .iter()
        .map(|a| match &a.kind {
            ActionKind::SetDo { signal, value } => Action::SetDo {
                signal: signal.clone(),
                value: *value,
            },
            ActionKind::PulseDo { signal } => Action::PulseDo {
                signal: signal.clone(),
            },
            ActionKind::WaitDi { signal, value } => Action::WaitDi {
                signal: signal.clone(),
                value: *value,
            },
            ActionKind::WaitTime { time_s } => Action::WaitTime { time_s: *time_s },
            ActionKind::GripLoad { load } => Action::GripLoad {
                load: load
                    .and_then(|k| cell.loads.get(k))
                    .map_or_else(|| "load0".to_string(), |l| l.name.clone()),
            },
        })
        .collect()
}

/// Where the routine of `plan` ends: at the first entry's target (its last waypoint is that
/// target: the first entry, a revisit of it, the point the first entry revisits, or a point at
/// the very same joints), or elsewhere (the last entry's target or its retract pose).
fn ends(cell: &Cell, plan: &Plan) -> Ends {
    let origin = |i: usize| cell.points.get(i).and_then(|p| p.revisit_of).unwrap_or(i);
    let name = |i: usize| {
        cell.points
            .get(i)
            .map(|p| p.name.clone())
            .unwrap_or_default()
    };
    let (first, last) = (plan.route.waypoints.first(), plan.route.waypoints.last());
    let same_joints = first
        .zip(last)
        .is_some_and(|(a, b)| a.joints_deg == b.joints_deg);
    match last.map(|w| w.kind) {
        Some(WaypointKind::CellPoint(i)) if origin(i) == origin(0) || same_joints => Ends::AtStart,
        last => Ends::Elsewhere {
            first: name(0),
            last: match last {
                Some(WaypointKind::Retract(i)) => format!("{}'s retract pose", name(i)),
                Some(WaypointKind::Approach(i)) => format!("{}'s approach pose", name(i)),
                Some(WaypointKind::CellPoint(i)) => name(i),
                _ => "a via".to_string(),
            },
        },
    }
}
