//! The run's results as data (`--report FILE`, JSON): every waypoint (its module name, all six
//! axes, the TCP and wrist-centre positions in the cell frame, cell point or via), every move
//! (from, to, the certified smallest clearance along it with the link or tool shape and the
//! obstacle, its estimated time and what limited it, speed and zone), the base, the grid, the
//! method, the totals (with the zoned vias and the paper's method alone) and the tool and work
//! object. `docs/report.schema.json` is its JSON Schema (draft 2020-12); `format` names the
//! version of that layout (version 2 added each move's `limit`, `totals.zoned_vias` and
//! `totals.paper_method`, version 3 `near_limits`, the cell points whose axis 4 or 6 lies near a
//! limit; version 4 each move's `kind`, `instruction`, `target`, `circle_point`, `offset_mm`
//! and `actions`, and `start`, the instruction that reaches the first waypoint; later versions
//! add keys and change the name).
//!
//! Goes beyond the paper (a script's view of a run). Made from the run's results only: the cell,
//! the placed job, the plan and the module's content ([`Program`]: the names, speeds and zones
//! the module writes), with positions by the robot's forward kinematics ([`Poser`]).
//!
//! Deterministic bytes: keys in a fixed order, numbers with the module's decimals from
//! [`crate::precision`] (joint values 3, positions 3, clearances 1, times 2, the grid and the
//! yaw 3), written as fixed-decimal JSON numbers (`90.000`, never `9e1` or `-0.000`); a
//! non-finite number is refused ([`ReportError::NotFinite`]) rather than written as `null`.

use super::clearance_part;
use super::poses::Poser;
use super::rapid::{format_fixed, Program, TargetKind, WrittenMove};
use crate::cell::{Base, Cell};
use crate::place::near_limit::near_limits;
use crate::place::Placed;
use crate::plan::WaypointKind;
use crate::precision::{
    REPORT_CLEARANCE_DECIMALS, REPORT_GRID_DECIMALS, REPORT_JOINT_DECIMALS,
    REPORT_POSITION_DECIMALS, REPORT_TIME_DECIMALS, REPORT_YAW_DECIMALS,
};
use crate::refine::Plan;
use crate::robot::Robot;
use serde::{Serialize, Serializer};

/// The layout's name and version (the `format` key).
pub const FORMAT: &str = "gen-rapid report 4";

/// Why a report could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    #[error("cannot write the report: {what} is not a finite number")]
    NotFinite { what: String },
    #[error("cannot write the report: {0}")]
    Json(#[from] serde_json::Error),
}

/// A number written with a fixed number of decimals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fixed {
    pub value: f64,
    pub decimals: usize,
}

impl Serialize for Fixed {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let raw = serde_json::value::RawValue::from_string(format_fixed(self.value, self.decimals))
            .map_err(serde::ser::Error::custom)?;
        raw.serialize(s)
    }
}

/// The report; field order is the JSON's key order.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub format: &'static str,
    pub generator: String,
    /// The cell file's name.
    pub cell: String,
    pub module: String,
    /// The routine that makes the moves.
    pub proc: String,
    pub robot: RobotInfo,
    pub base: BaseInfo,
    /// The search method of the paper used.
    pub method: String,
    pub grid_deg: Fixed,
    /// The clearance asked for, mm.
    pub clearance_mm: Fixed,
    /// The tooldata every move uses.
    pub tool: String,
    /// The work object every move names (`wobj0` when the module declares none).
    pub wobj: String,
    pub totals: Totals,
    pub waypoints: Vec<WaypointInfo>,
    /// The instruction that reaches the first waypoint from wherever the robot stands (not a
    /// move of `moves`: neither proven nor timed), and its actions.
    pub start: Option<Written>,
    pub moves: Vec<MoveInfo>,
    /// The cell points whose axis 4 or 6 lies near a limit (the warnings of
    /// [`near_limit`](crate::place::near_limit)).
    pub near_limits: Vec<NearLimitInfo>,
}

#[derive(Clone, Debug, Serialize)]
pub struct NearLimitInfo {
    /// The cell point.
    pub point: String,
    /// 4 or 6.
    pub axis: usize,
    /// Its written value, the limit it is near and the room left, deg.
    pub value_deg: Fixed,
    pub limit_deg: Fixed,
    pub room_deg: Fixed,
}

#[derive(Clone, Debug, Serialize)]
pub struct RobotInfo {
    /// The URDF's file name.
    pub urdf: String,
    /// The controller file's name; `null` without one.
    pub controller: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct BaseInfo {
    /// The robot base's origin in the cell frame, mm.
    pub position_mm: [Fixed; 3],
    pub yaw_deg: Fixed,
    /// `true` when the place stage chose it (`base: auto`).
    pub chosen: bool,
}

#[derive(Clone, Debug, Serialize)]
pub struct Totals {
    pub waypoints: usize,
    pub cell_points: usize,
    pub vias: usize,
    pub moves: usize,
    /// The sum of the moves' estimated times, s.
    pub estimated_time_s: Fixed,
    /// The smallest of the moves' clearances; `null` without obstacles.
    pub min_clearance: Option<ClearanceInfo>,
    /// The vias that fly by (a zone other than a stop point) and the zone a proven via gets.
    pub zoned_vias: ZonedVias,
    /// The paper's method alone on the same cell; `null` when not known.
    pub paper_method: Option<PaperMethod>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ZonedVias {
    /// Vias whose move in has a fly-by zone.
    pub zoned: usize,
    /// All vias.
    pub vias: usize,
    /// The zonedata a via gets where its corner is proven.
    pub via_zone: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct PaperMethod {
    pub moves: usize,
    /// Its estimated time, s.
    pub time_s: Fixed,
}

#[derive(Clone, Debug, Serialize)]
pub struct WaypointInfo {
    /// Its name in the module.
    pub name: String,
    /// `cell` (a point of the cell file) or `via` (the planner's).
    pub kind: &'static str,
    /// Controller values of axes 1..6, deg (the jointtarget's).
    pub joints_deg: [Fixed; 6],
    /// The TCP (tool0 without a tool) in the cell frame, mm.
    pub tcp_mm: [Fixed; 3],
    /// The wrist centre in the cell frame, mm.
    pub wrist_centre_mm: [Fixed; 3],
}

#[derive(Clone, Debug, Serialize)]
pub struct MoveInfo {
    /// The waypoints it joins (names).
    pub from: String,
    pub to: String,
    /// The certified smallest clearance along it; `null` without obstacles.
    pub min_clearance: Option<ClearanceInfo>,
    /// Its estimated time, s.
    pub time_s: Fixed,
    /// What set its time from rest to rest: `axis`, `tcp` or `reorientation`.
    pub limit: &'static str,
    /// The speeddata and zonedata it is written with.
    pub speed: String,
    pub zone: String,
    /// How it is written: the instruction, its kind, its target and its actions.
    #[serde(flatten)]
    pub written: Written,
}

/// A move as the module writes it (`rapid::WrittenMove`).
#[derive(Clone, Debug, Serialize)]
pub struct Written {
    /// `joint` (an air move), `approach` (the approach line into a point), `linear`,
    /// `circular` or `retract` (the retract line out of a point).
    pub kind: &'static str,
    /// `MoveAbsJ`, `MoveJ`, `MoveL` or `MoveC`.
    pub instruction: &'static str,
    /// The data its `ToPoint` names: a jointtarget (`MoveAbsJ`) or a robtarget (`<point>_rt`,
    /// also under `RelTool`).
    pub target: String,
    /// `MoveC`'s circle point (`<point>_via`); `null` otherwise.
    pub circle_point: Option<String>,
    /// `RelTool(target,0,0,dz)`'s `dz`, mm; `null` without `RelTool`.
    pub offset_mm: Option<Fixed>,
    /// The actions written after it, in order.
    pub actions: Vec<ActionInfo>,
}

/// One action (`SetDO`, `PulseDO`, `WaitDI`, `WaitTime`, `GripLoad`) as data: `kind` and the
/// keys of that kind only.
#[derive(Clone, Debug, Serialize)]
pub struct ActionInfo {
    /// `set_do`, `pulse_do`, `wait_di`, `wait_time` or `grip_load`.
    pub kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub signal: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<u8>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds: Option<Fixed>,
    /// The instruction as the module writes it, without its `;`.
    pub text: String,
}

fn written(w: &WrittenMove) -> Result<Written, ReportError> {
    let number = |what: &str, text: &str| -> Result<Fixed, ReportError> {
        let value: f64 = text.parse().map_err(|_| ReportError::NotFinite {
            what: format!("{what} '{text}'"),
        })?;
        let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
        fixed(|| what.to_string(), value, decimals)
    };
    let mut actions = Vec::with_capacity(w.actions.len());
    for a in &w.actions {
        actions.push(ActionInfo {
            kind: a.kind,
            signal: a.signal.clone(),
            value: a.value,
            load: a.load.clone(),
            seconds: match &a.seconds {
                Some(s) => Some(number("a wait time", s)?),
                None => None,
            },
            text: a.text.clone(),
        });
    }
    Ok(Written {
        kind: w.kind,
        instruction: w.instruction,
        target: w.robtarget.clone().unwrap_or_else(|| w.to.clone()),
        circle_point: w.circle_point.clone(),
        offset_mm: match &w.offset_mm {
            Some(d) => Some(number("a RelTool offset", d)?),
            None => None,
        },
        actions,
    })
}

#[derive(Clone, Debug, Serialize)]
pub struct ClearanceInfo {
    /// A certified lower bound of the smallest distance, mm (within 0.05 mm).
    pub mm: Fixed,
    /// `link` (a link cylinder) or `tool` (a tool shape).
    pub part: &'static str,
    /// The link's or the tool shape's name.
    pub name: String,
    /// The obstacle.
    pub obstacle: String,
}

/// What the report is made from.
pub struct Input<'a> {
    pub cell: &'a Cell,
    pub robot: &'a Robot,
    pub placed: &'a Placed,
    pub plan: &'a Plan,
    /// The module's content: its names, speeds, zones, tool and work object.
    pub program: &'a Program,
    /// The module's names of the plan's waypoints, in order.
    pub names: &'a [String],
    /// The module's moves as written (move `i` into waypoint `i`).
    pub written: &'a [WrittenMove],
}

/// Checks that a number is finite before it is written.
fn fixed(what: impl Fn() -> String, value: f64, decimals: usize) -> Result<Fixed, ReportError> {
    if value.is_finite() {
        Ok(Fixed { value, decimals })
    } else {
        Err(ReportError::NotFinite { what: what() })
    }
}

fn fixed_n<const N: usize>(
    what: impl Fn() -> String,
    v: [f64; N],
    decimals: usize,
) -> Result<[Fixed; N], ReportError> {
    for x in v {
        fixed(&what, x, decimals)?;
    }
    Ok(v.map(|value| Fixed { value, decimals }))
}

fn clearance(c: &crate::plan::Clearance, what: &str) -> Result<ClearanceInfo, ReportError> {
    let (part, name) = clearance_part(c);
    Ok(ClearanceInfo {
        mm: fixed(|| what.to_string(), c.mm, REPORT_CLEARANCE_DECIMALS)?,
        part,
        name: name.to_string(),
        obstacle: c.obstacle.clone(),
    })
}

/// The report of a planned run.
pub fn report(input: &Input) -> Result<Report, ReportError> {
    let Input {
        cell,
        robot,
        placed,
        plan,
        program,
        names,
        written: written_moves,
    } = input;
    let poser = Poser::new(robot, placed.placement, cell.tool.as_ref());
    let name = |k: usize| names.get(k).cloned().unwrap_or_default();
    let route = &plan.route;
    let mut waypoints = Vec::with_capacity(route.waypoints.len());
    for (k, w) in route.waypoints.iter().enumerate() {
        let what = |field: &str| format!("{field} of waypoint '{}'", name(k));
        waypoints.push(WaypointInfo {
            name: name(k),
            kind: match w.kind {
                WaypointKind::CellPoint(_) => "cell",
                WaypointKind::Via { .. } => "via",
                WaypointKind::Approach(_) => "approach",
                WaypointKind::Retract(_) => "retract",
            },
            joints_deg: fixed_n(|| what("an axis"), w.joints_deg, REPORT_JOINT_DECIMALS)?,
            tcp_mm: fixed_n(
                || what("the TCP"),
                poser.tcp_mm(&w.joints_deg),
                REPORT_POSITION_DECIMALS,
            )?,
            wrist_centre_mm: fixed_n(
                || what("the wrist centre"),
                poser.wrist_centre_mm(&w.joints_deg),
                REPORT_POSITION_DECIMALS,
            )?,
        });
    }
    let mut moves = Vec::with_capacity(plan.moves.len());
    for (i, m) in plan.moves.iter().enumerate() {
        let what = format!("the clearance of move {}", i + 1);
        let target = program.targets.get(i + 1);
        moves.push(MoveInfo {
            from: name(i),
            to: name(i + 1),
            min_clearance: match &m.clearance {
                Some(c) => Some(clearance(c, &what)?),
                None => None,
            },
            time_s: fixed(
                || format!("the time of move {}", i + 1),
                m.estimate.time_s,
                REPORT_TIME_DECIMALS,
            )?,
            limit: m.estimate.limit.name(),
            speed: target.map(|t| t.speed.clone()).unwrap_or_default(),
            zone: target.map(|t| t.zone.clone()).unwrap_or_default(),
            written: match written_moves.get(i + 1) {
                Some(w) => written(w)?,
                None => Written {
                    kind: m.kind.name(),
                    instruction: "",
                    target: name(i + 1),
                    circle_point: None,
                    offset_mm: None,
                    actions: Vec::new(),
                },
            },
        });
    }
    let mut near = Vec::new();
    for n in near_limits(placed, robot) {
        let what = || format!("axis {} of point '{}'", n.axis, n.point);
        near.push(NearLimitInfo {
            value_deg: fixed(what, n.value_deg, REPORT_JOINT_DECIMALS)?,
            limit_deg: fixed(what, n.limit_deg, REPORT_JOINT_DECIMALS)?,
            room_deg: fixed(what, n.room_deg, REPORT_JOINT_DECIMALS)?,
            point: n.point,
            axis: n.axis,
        });
    }
    let cell_points = program
        .targets
        .iter()
        .filter(|t| matches!(t.kind, TargetKind::CellPoint { .. }))
        .count();
    let h = &program.header;
    Ok(Report {
        format: FORMAT,
        generator: h.generator.clone(),
        cell: h.cell_file.clone(),
        module: program.module.clone(),
        proc: program.proc_name.clone(),
        robot: RobotInfo {
            urdf: h.urdf.clone(),
            controller: h.controller.clone(),
        },
        base: BaseInfo {
            position_mm: fixed_n(
                || "the base".to_string(),
                placed.placement.base_mm,
                REPORT_POSITION_DECIMALS,
            )?,
            yaw_deg: fixed(
                || "the yaw".to_string(),
                placed.placement.yaw_deg,
                REPORT_YAW_DECIMALS,
            )?,
            chosen: cell.robot.base == Base::Auto,
        },
        method: route.method.name().to_string(),
        grid_deg: fixed(|| "the grid".into(), route.grid_deg, REPORT_GRID_DECIMALS)?,
        clearance_mm: fixed(
            || "the clearance".into(),
            cell.planner.clearance_mm,
            REPORT_CLEARANCE_DECIMALS,
        )?,
        tool: program.tool.clone(),
        wobj: program
            .wobj
            .as_ref()
            .map_or_else(|| "wobj0".to_string(), |w| w.name.clone()),
        totals: Totals {
            waypoints: route.waypoints.len(),
            cell_points,
            vias: route.waypoints.len() - cell_points.min(route.waypoints.len()),
            moves: route.moves(),
            estimated_time_s: fixed(
                || "the total time".into(),
                plan.total_s,
                REPORT_TIME_DECIMALS,
            )?,
            min_clearance: match &plan.least {
                Some(c) => Some(clearance(c, "the smallest clearance")?),
                None => None,
            },
            zoned_vias: ZonedVias {
                zoned: h.zoned_vias.0,
                vias: h.zoned_vias.1,
                via_zone: h.via_zone.clone(),
            },
            paper_method: match h.paper {
                Some((moves, t)) => Some(PaperMethod {
                    moves,
                    time_s: fixed(
                        || "the paper's method's time".into(),
                        t,
                        REPORT_TIME_DECIMALS,
                    )?,
                }),
                None => None,
            },
        },
        waypoints,
        start: match written_moves.first() {
            Some(w) => Some(written(w)?),
            None => None,
        },
        moves,
        near_limits: near,
    })
}

/// The report as pretty JSON with a final newline.
pub fn to_json(report: &Report) -> Result<String, ReportError> {
    let mut text = serde_json::to_string_pretty(report)?;
    text.push('\n');
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_have_fixed_decimals_and_no_negative_zero() {
        let v = [
            Fixed {
                value: 90.0,
                decimals: 3,
            },
            Fixed {
                value: -0.0004,
                decimals: 3,
            },
            Fixed {
                value: 4.335,
                decimals: 2,
            },
            Fixed {
                value: 1e21,
                decimals: 1,
            },
        ];
        let text = serde_json::to_string(&v).unwrap();
        assert_eq!(text, "[90.000,0.000,4.33,1000000000000000000000.0]");
        // Still JSON numbers.
        let back: Vec<f64> = serde_json::from_str(&text).unwrap();
        assert_eq!(back, [90.0, 0.0, 4.33, 1e21]);
    }

    #[test]
    fn a_number_that_is_not_finite_is_refused() {
        let e = fixed_n(|| "axis 2".into(), [1.0, f64::NAN], 3).unwrap_err();
        assert!(
            e.to_string().contains("axis 2 is not a finite number"),
            "{e}"
        );
    }
}
