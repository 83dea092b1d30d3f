//! The guard between the cell file and the later stages: the keys the cell validation reads but
//! the place, plan and render stages do not carry out yet (the base frame together with process
//! moves). A
//! cell that uses one is refused at its line, so no module is written that leaves out what the
//! cell asks for. Orientations given as `zyx` need no guard: they are read into the same
//! quaternions. Once the later stages carry out a key, its line here goes; once they carry out
//! all, this file goes.

use super::{Cell, CellError, Loc};

/// Refuses a cell that uses a key the later stages do not carry out yet (module docs): the first
/// such key in the file.
pub fn unsupported(cell: &Cell) -> Result<(), CellError> {
    let mut uses: Vec<(Loc, String)> = Vec::new();
    // The base frame with process moves: the follow stage works from the cell-frame poses, not
    // yet from the data as the base frame writes them.
    let process = |p: &super::Point| {
        p.approach_mm.is_some() || p.retract_mm.is_some() || p.arrival != super::Arrival::Joint
    };
    if cell.robot.frame == super::RobotFrame::Base && cell.points.iter().any(process) {
        uses.push((
            cell.robot.frame_loc,
            "`robot.frame: base` with process moves (approach, retract, `move: linear | circular`)"
                .into(),
        ));
    }
    match uses.into_iter().min_by_key(|(l, _)| (l.line, l.column)) {
        None => Ok(()),
        Some((loc, what)) => Err(CellError::Invalid {
            loc,
            message: format!("{what} is read but not yet planned or written"),
            help: Some("not yet supported: gen-rapid reads this key (docs/cell.md) but does not yet plan and write it, and writes no module that leaves it out; remove it for now".into()),
        }),
    }
}
