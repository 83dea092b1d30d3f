//! A point's actions as written against the cell's: exactly the cell's actions of the point, in
//! its order, with its arguments (`SetDO signal, 0|1;`, `PulseDO signal;`, `WaitDI signal,
//! 0|1;`, `WaitTime s;` within 0.0005 s, the module's 3 decimals; `GripLoad load;` naming
//! `load0` or the cell's load). The routine's grammar (`routine.rs`) already refuses optional
//! arguments and any other instruction; where actions stand (between the move that reaches the
//! point and the next motion instruction, nowhere else) is `program.rs`'s walk.

use super::library::{ActionKind, Cell, Point};
use super::routine::{Action, Statement};

/// The RAPID an action of the cell is written as (`WaitTime` with the module's 3 decimals).
pub fn rapid(cell: &Cell, kind: &ActionKind) -> String {
    match kind {
        ActionKind::SetDo { signal, value } => format!("SetDO {signal}, {};", u8::from(*value)),
        ActionKind::PulseDo { signal } => format!("PulseDO {signal};"),
        ActionKind::WaitDi { signal, value } => format!("WaitDI {signal}, {};", u8::from(*value)),
        ActionKind::WaitTime { time_s } => format!("WaitTime {time_s:.3};"),
        ActionKind::GripLoad { load } => format!(
            "GripLoad {};",
            load.and_then(|i| cell.loads.get(i))
                .map_or("load0", |l| l.name.as_str())
        ),
    }
}

/// Whether a written action is the cell's.
fn same(cell: &Cell, written: &Action, kind: &ActionKind) -> bool {
    match (written, kind) {
        (
            Action::SetDo { signal, value },
            ActionKind::SetDo {
                signal: s,
                value: v,
            },
        )
        | (
            Action::WaitDi { signal, value },
            ActionKind::WaitDi {
                signal: s,
                value: v,
            },
        ) => signal == s && *value == u8::from(*v),
        (Action::PulseDo { signal }, ActionKind::PulseDo { signal: s }) => signal == s,
        (Action::WaitTime { s }, ActionKind::WaitTime { time_s }) => (s - time_s).abs() <= 5e-4,
        (Action::GripLoad { load }, ActionKind::GripLoad { .. }) => {
            format!("GripLoad {load};") == rapid(cell, kind)
        }
        _ => false,
    }
}

/// The actions written after the move that reaches `point` against the cell's: the failures
/// (one, listing both, where they differ).
pub fn check_actions(cell: &Cell, point: &Point, written: &[(&Statement, &Action)]) -> Vec<String> {
    let agree = written.len() == point.actions.len()
        && written
            .iter()
            .zip(&point.actions)
            .all(|((_, w), a)| same(cell, w, &a.kind));
    match agree {
        true => Vec::new(),
        false => {
            let wrote: Vec<&str> = written.iter().map(|(s, _)| s.text.as_str()).collect();
            let want: Vec<String> = point.actions.iter().map(|a| rapid(cell, &a.kind)).collect();
            let at = written
                .first()
                .map_or(String::new(), |(s, _)| format!(" (line {})", s.line));
            vec![format!(
                "{}: its actions are written {wrote:?}{at}, the cell says {want:?}",
                point.label()
            )]
        }
    }
}
