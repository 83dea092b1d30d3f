//! The guard between the cell file and the later stages: the keys the cell validation reads but
//! the place, plan and render stages do not carry out yet (revisits, the closed cycle, several
//! work objects). A cell that uses one is refused at its line, so no module is written that
//! leaves out what the cell asks for. Orientations given as `zyx` need no guard: they are read into the same
//! quaternions. Once the later stages carry out a key, its line here goes; once they carry out
//! all, this file goes.

use super::{Cell, CellError, Loc};

/// Refuses a cell that uses a key the later stages do not carry out yet (module docs): the first
/// such key in the file.
pub fn unsupported(cell: &Cell) -> Result<(), CellError> {
    let mut uses: Vec<(Loc, String)> = Vec::new();
    for p in &cell.points {
        let who = p.label();
        if p.revisit_of.is_some() {
            uses.push((p.loc, format!("{who}: `revisit`")));
        }
    }
    if let Some(w) = cell.wobjs.get(1) {
        uses.push((w.loc, "a second work object".into()));
    }
    if cell.motion.cycle {
        uses.push((cell.motion.cycle_loc, "`motion.cycle: true`".into()));
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
