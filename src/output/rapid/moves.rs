//! The instruction each move is written with, and its actions, as data: what the module's
//! routine says move by move (`MoveAbsJ`, `MoveJ`, `MoveL`, `MoveC`; the target and circle point
//! data, a `RelTool` offset; `SetDO`, `PulseDO`, `WaitDI`, `WaitTime`, `GripLoad`), for the
//! template context, the report and the preview page alike, so the three say the same.
//!
//! Move `i` goes to target `i` of the [`Program`]; move 0 reaches the first target from wherever
//! the robot stands. A joint target and a via are reached by `MoveAbsJ` to their jointtarget; a
//! robtarget point by `MoveJ` to its robtarget (an air move), `MoveL` (a `move: linear` line or
//! its approach line) or `MoveC` through its circle point `<point>_via`; an approach pose by
//! `MoveJ RelTool(<point>_rt,0,0,-D)` (the air move's end), a retract pose by
//! `MoveL RelTool(<point>_rt,0,0,-D)`, or where such a pose has a robtarget of its own (another
//! configuration than its point's) by `MoveJ <point>_app` or `MoveL <point>_ret`.

use super::{data_name_of, finite, format_fixed, Action, MoveHow, Program, RapidError, TargetKind};
use crate::names::robtarget_name;
use crate::precision::{POSITION_DECIMALS, WAIT_TIME_DECIMALS};
use serde::Serialize;

/// One move of the routine as the module writes it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WrittenMove {
    /// `MoveAbsJ`, `MoveJ`, `MoveL` or `MoveC`.
    pub instruction: &'static str,
    /// `joint` (an air move, joint interpolation: `MoveAbsJ` or `MoveJ`), `approach` (the
    /// approach line into a point), `linear`, `circular` or `retract` (the retract line out of
    /// a point).
    pub kind: &'static str,
    /// The cell point the move belongs to (its target's, its approach or retract pose's); none
    /// for a via.
    pub point: Option<String>,
    /// The `ToPoint` argument as written: a jointtarget's or robtarget's name, or
    /// `RelTool(<point>_rt,0,0,-D)`.
    pub to: String,
    /// The robtarget the move goes to or stands on (`RelTool`'s first argument); none for a
    /// `MoveAbsJ`.
    pub robtarget: Option<String>,
    /// The jointtarget a `MoveAbsJ` goes to; none otherwise.
    pub jointtarget: Option<String>,
    /// `MoveC`'s circle point (`<point>_via`); none otherwise.
    pub circle_point: Option<String>,
    /// `RelTool`'s offset along the tool's z axis, mm, as written (`-40.000`); none without.
    pub offset_mm: Option<String>,
    /// The speeddata and zonedata it is written with.
    pub speed: String,
    pub zone: String,
    /// The actions written after it, in order.
    pub actions: Vec<WrittenAction>,
}

/// One action written after a move.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WrittenAction {
    /// `set_do`, `pulse_do`, `wait_di`, `wait_time` or `grip_load` (the cell's key).
    pub kind: &'static str,
    /// The signal of `set_do`, `pulse_do`, `wait_di`; none otherwise.
    pub signal: Option<String>,
    /// The value `set_do` sets or `wait_di` waits for, 0 or 1; none otherwise.
    pub value: Option<u8>,
    /// The loaddata `grip_load` names (`load0` or a `loads:` entry); none otherwise.
    pub load: Option<String>,
    /// `wait_time`'s seconds, as written (`0.300`); none otherwise.
    pub seconds: Option<String>,
    /// The instruction as written, without its `;` (`SetDO doWeld, 1`).
    pub text: String,
}

impl WrittenMove {
    /// The instruction's arguments before the speed: `<ToPoint>`, `<CirPoint>, <ToPoint>` for
    /// `MoveC`, with `\NoEOffs` after a `MoveAbsJ`'s jointtarget.
    pub fn points(&self) -> String {
        match self.instruction {
            "MoveAbsJ" => format!("{}\\NoEOffs", self.target()),
            _ => self.target(),
        }
    }

    /// The move's targets: `<ToPoint>`, or `<CirPoint>, <ToPoint>` for `MoveC`.
    pub fn target(&self) -> String {
        match &self.circle_point {
            Some(c) => format!("{c}, {}", self.to),
            None => self.to.clone(),
        }
    }
}

/// Every move of `program` as the module writes it, the targets named `names` (the module's
/// names, [`super::module_target_names`]).
pub fn written_moves(program: &Program, names: &[String]) -> Result<Vec<WrittenMove>, RapidError> {
    let mut moves = Vec::with_capacity(program.targets.len());
    for (target, name) in program.targets.iter().zip(names) {
        let rel_tool = |point: &str| -> Result<(String, String, String), RapidError> {
            let d = finite(
                format!("the offset of `{name}`"),
                target.offset_mm.unwrap_or(0.0),
            )?;
            let rt = robtarget_name(point);
            let dz = format_fixed(-d, POSITION_DECIMALS);
            Ok((format!("RelTool({rt},0,0,{dz})"), rt, dz))
        };
        let own = target
            .robtarget
            .as_ref()
            .map(|_| data_name_of(target, name));
        let (instruction, to, robtarget, offset, circle) = match (&target.kind, &target.how, own) {
            // An approach or retract pose in another configuration than its point: its own
            // robtarget.
            (TargetKind::Approach { .. }, _, Some(r)) => ("MoveJ", r.clone(), Some(r), None, None),
            (TargetKind::Retract { .. }, _, Some(r)) => ("MoveL", r.clone(), Some(r), None, None),
            (TargetKind::Approach { point }, _, _) => {
                let (to, rt, dz) = rel_tool(point)?;
                ("MoveJ", to, Some(rt), Some(dz), None)
            }
            (TargetKind::Retract { point }, _, _) => {
                let (to, rt, dz) = rel_tool(point)?;
                ("MoveL", to, Some(rt), Some(dz), None)
            }
            (_, MoveHow::Circular { .. }, Some(r)) => (
                "MoveC",
                r.clone(),
                Some(r),
                None,
                Some(format!("{name}_via")),
            ),
            (_, MoveHow::Linear, Some(r)) => ("MoveL", r.clone(), Some(r), None, None),
            (_, _, Some(r)) => ("MoveJ", r.clone(), Some(r), None, None),
            (_, _, None) => ("MoveAbsJ", name.clone(), None, None, None),
        };
        let kind = match (&target.kind, &target.how) {
            (TargetKind::Approach { .. }, _) => "joint",
            (TargetKind::Retract { .. }, _) => "retract",
            (_, MoveHow::Circular { .. }) => "circular",
            (_, MoveHow::Linear) if target.offset_mm.is_some() => "approach",
            (_, MoveHow::Linear) => "linear",
            (_, MoveHow::Joint) => "joint",
        };
        let point = match &target.kind {
            TargetKind::CellPoint { name: p }
            | TargetKind::Revisit { point: p }
            | TargetKind::Approach { point: p }
            | TargetKind::Retract { point: p } => Some(p.clone()),
            TargetKind::Via { .. } => None,
        };
        let actions = (target.actions.iter())
            .map(written_action)
            .collect::<Result<Vec<_>, _>>()?;
        moves.push(WrittenMove {
            instruction,
            kind,
            point,
            jointtarget: robtarget.is_none().then(|| to.clone()),
            to,
            robtarget,
            circle_point: circle,
            offset_mm: offset,
            speed: target.speed.clone(),
            zone: target.zone.clone(),
            actions,
        });
    }
    Ok(moves)
}

fn written_action(a: &Action) -> Result<WrittenAction, RapidError> {
    let none = WrittenAction {
        kind: "",
        signal: None,
        value: None,
        load: None,
        seconds: None,
        text: String::new(),
    };
    Ok(match a {
        Action::SetDo { signal, value } => WrittenAction {
            kind: "set_do",
            text: format!("SetDO {signal}, {}", u8::from(*value)),
            signal: Some(signal.clone()),
            value: Some(u8::from(*value)),
            ..none
        },
        Action::PulseDo { signal } => WrittenAction {
            kind: "pulse_do",
            text: format!("PulseDO {signal}"),
            signal: Some(signal.clone()),
            ..none
        },
        Action::WaitDi { signal, value } => WrittenAction {
            kind: "wait_di",
            text: format!("WaitDI {signal}, {}", u8::from(*value)),
            signal: Some(signal.clone()),
            value: Some(u8::from(*value)),
            ..none
        },
        Action::WaitTime { time_s } => {
            let s = format_fixed(finite("a wait time", *time_s)?, WAIT_TIME_DECIMALS);
            WrittenAction {
                kind: "wait_time",
                text: format!("WaitTime {s}"),
                seconds: Some(s),
                ..none
            }
        }
        Action::GripLoad { load } => WrittenAction {
            kind: "grip_load",
            text: format!("GripLoad {load}"),
            load: Some(load.clone()),
            ..none
        },
    })
}
