//! The whole-move proofs already made, so a move is not proven twice: the refine stage proves
//! again the moves the plan stage proved (each candidate route as a whole, after the shortcut
//! pass), and the pass's slides prove a via's moves to its neighbours round after round.
//!
//! A proof is a pure function of the model, its clearance and the move's two ends, so an
//! answer read back under the same clearance and ends (their exact bits) is the one the proof
//! would give: the memo changes no result, whatever thread fills it first. A clone of the model
//! starts with an empty memo, as a clone may change what a proof depends on (`with_margin`
//! raises the clearance). It holds at most [`MEMO_MOVES`] moves; beyond that, moves are proven
//! as if it were not there.

use std::collections::HashMap;
use std::sync::Mutex;

/// Most moves the memo keeps (about 120 bytes each).
pub const MEMO_MOVES: usize = 1 << 16;

/// The clearance and a move's two ends, their bits.
type Key = (u64, [u64; 6], [u64; 6]);

/// Proven (or refused) moves and their verdicts. A clone starts empty (module doc).
#[derive(Debug, Default)]
pub(crate) struct ProofMemo {
    moves: Mutex<HashMap<Key, bool>>,
}

impl Clone for ProofMemo {
    fn clone(&self) -> ProofMemo {
        ProofMemo::default()
    }
}

impl ProofMemo {
    /// The verdict of the move `from -> to` at clearance `c`: read back where it was given
    /// before, else `prove()`'s, kept while there is room.
    pub(crate) fn verdict(
        &self,
        c: f64,
        from: &[f64; 6],
        to: &[f64; 6],
        prove: impl FnOnce() -> bool,
    ) -> bool {
        let key = (c.to_bits(), from.map(f64::to_bits), to.map(f64::to_bits));
        if let Some(&v) = self.lock().get(&key) {
            return v;
        }
        let v = prove();
        let mut moves = self.lock();
        if moves.len() < MEMO_MOVES {
            moves.insert(key, v);
        }
        v
    }

    /// How many moves it holds.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.lock().len()
    }

    /// The map; a thread that panicked while holding it left it whole (an insert is the only
    /// change), so a poisoned lock is taken as it is.
    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<Key, bool>> {
        self.moves
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }
}
