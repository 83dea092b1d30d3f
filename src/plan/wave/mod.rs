//! Wave expansion (paper section 4): free nodes are numbered 1 at the start node and outward,
//! one more per step, until the end node is numbered n.
//!
//! The expansion is breadth-first over the free nodes with 26 neighbours (every node that
//! differs by at most one step on each axis), as the pipeline specifies; [`Connectivity::Six`]
//! (axis neighbours only) serves the depth-first search, which walks axis steps (see
//! `search`). It stops once the end node is numbered: every node numbered below n is then final,
//! and those are the only ones a search back from the end node visits.
//!
//! Beyond the paper, for speed only: the 26-neighbour wave over a graph whose every step between
//! usable nodes counts (the optimistic wave of a leg, the common one) is numbered a level at a
//! time on bit sets of axis-3 rows (`rows.rs`, its neighbours gathered by `reach.rs`), the
//! others node by node from a queue (`queue.rs`). The numbers below n are the same (each node's
//! breadth-first distance, plus one). The searches' waves are numbered from both ends at once,
//! only on the shortest paths between them (`corridor.rs`). The planes, the row wave's decided
//! and candidate words and the node-by-node numbers span the whole grid but are [`ZeroBuf`]s
//! (`crate::zeroed`): a wave pays for the pages it touches (the ball it numbers), not for
//! zeroing the whole grid. This file holds what they share: the graph, the wave and its labels,
//! and [`expand`], which picks the queue or the rows.
//!
//! Beyond the paper: the wave runs on a [`Graph`], whose nodes are the grid's free nodes that the
//! graph accepts (a leg's tool at its wrist) and whose edges are the neighbour steps it accepts
//! (the whole-move check). So the numbers count accepted steps, and every numbered node but the
//! start has a neighbour one number lower joined to it by an accepted step: a walk back over
//! accepted steps from the end node always reaches the start node (`search`). More: an accepted
//! step never joins two nodes whose numbers differ by more than one (when the lower one was
//! expanded, the step numbered the other), so every accepted step down from a node numbered `l`
//! leads to `l - 1`.

/// Calls a row wave function with the row's word count as a constant where it is small (the
/// loops over a row's words unrolled): 3 at 1 deg, 5 at 0.5 deg, 9 at 0.25 deg over the IRB
/// 1400's axis 3; 0 (any count) otherwise.
macro_rules! by_row_words {
    ($cs:expr, $f:ident::<$g:ty>($($arg:expr),*)) => {
        match $cs.grid.dims[2].div_ceil(64) {
            1 => $f::<$g, 1>($($arg),*),
            2 => $f::<$g, 2>($($arg),*),
            3 => $f::<$g, 3>($($arg),*),
            4 => $f::<$g, 4>($($arg),*),
            5 => $f::<$g, 5>($($arg),*),
            9 => $f::<$g, 9>($($arg),*),
            _ => $f::<$g, 0>($($arg),*),
        }
    };
}

mod bounded;
mod corridor;
mod queue;
mod reach;
mod rows;
#[cfg(test)]
mod testing;

pub use corridor::{expand_both, expand_corridor};

use crate::plan::cspace::{CSpace, Node};
use crate::zeroed::ZeroBuf;
use queue::{number_of, number_scalar, Bound, Numbered, TooLong};
use rows::number_rows;

/// What a wave and a search walk on: which free nodes of the grid they may use and which
/// neighbour steps between them exist.
pub trait Graph: Sync {
    /// Whether a node free on the grid may be used. A wave asks at most once per node in each
    /// numbering pass (a wave numbered again in wider words asks again, and so do the corridor
    /// waves' tries with a larger bound).
    fn node_ok(&self, n: Node) -> bool;
    /// Whether the step between two neighbouring usable nodes exists. Must be symmetric.
    fn step_ok(&self, a: Node, b: Node) -> bool;
    /// The steps the wave numbers over: [`step_ok`](Self::step_ok) (the default), or, for an
    /// optimistic wave, any step that might exist (every step `step_ok` accepts must be
    /// accepted here too). A walk back always asks `step_ok`.
    fn wave_step_ok(&self, a: Node, b: Node) -> bool {
        self.step_ok(a, b)
    }
    /// [`node_ok`](Self::node_ok) for a node whose grid code is `code` (the wave has read it
    /// already): the same answer; a graph may decide from the code alone.
    #[inline]
    fn node_ok_coded(&self, n: Node, _code: u8) -> bool {
        self.node_ok(n)
    }
    /// Whether [`wave_step_ok`](Self::wave_step_ok) accepts every step between usable
    /// neighbours (then the wave need not ask it, and need not look twice at a node).
    fn wave_steps_all(&self) -> bool {
        false
    }
    /// The code bits on which [`node_ok_coded`](Self::node_ok_coded) may depend: a free node
    /// whose code has none of them set must be usable (`node_ok_coded` true), and then the
    /// row-by-row wave numbers it without asking. `None` (the default): every free node is
    /// asked. A graph whose answer depends on more than its code's bits keeps `None`.
    fn look_bits(&self) -> Option<u8> {
        None
    }
    /// A lower bound of the ends' distance in steps of this graph, where one is known (a leg's
    /// eager graph knows its optimistic wave's: that graph holds this one). A node-by-node wave
    /// is then bounded as A* is, first by this floor, the bound grown until the wave reaches its
    /// end (`bounded.rs`): the same numbers on the shortest paths between the ends, far fewer
    /// nodes numbered and steps asked. `None` (the default): numbered whole.
    fn steps_floor(&self) -> Option<u32> {
        None
    }
}

/// The grid's own graph: every free node, every step between free neighbours (the paper's).
#[derive(Clone, Copy, Debug, Default)]
pub struct Open;

impl Graph for Open {
    fn node_ok(&self, _: Node) -> bool {
        true
    }
    fn step_ok(&self, _: Node, _: Node) -> bool {
        true
    }
    fn wave_steps_all(&self) -> bool {
        true
    }
    fn look_bits(&self) -> Option<u8> {
        Some(0)
    }
}

/// Every free node, and the steps a (symmetric) predicate accepts: hand-made graphs in tests.
impl<F: Fn(Node, Node) -> bool + Sync> Graph for F {
    fn node_ok(&self, _: Node) -> bool {
        true
    }
    fn step_ok(&self, a: Node, b: Node) -> bool {
        self(a, b)
    }
}

/// The labels of a wave.
#[derive(Clone, Debug)]
enum Labels {
    /// Node by node, in the narrowest word that held them: the numbers.
    Narrow(ZeroBuf<u16>),
    Wide(ZeroBuf<u32>),
    /// Row by row: each node's residue code, 0 when not numbered, else `(l - 1) mod 3 + 1` for
    /// number `l`, in two bit planes laid out like the row wave's row words (`words` words a
    /// row of the grid's axis-3 nodes): bit `b` of word `2 w` is the code's low bit of the node
    /// at bit `b` of row word `w`, word `2 w + 1` its high bit (the two planes of a word side by
    /// side).
    Residues {
        planes: ZeroBuf<u64>,
        words: usize,
    },
}

/// The residue code of number `l` (`l >= 1`): 1, 2 or 3.
#[inline]
fn residue_code(l: u32) -> u32 {
    (l - 1) % 3 + 1
}

/// Numbers the nodes `bits` of row word `w` in residue `planes` with the residue code `c` of
/// their number.
#[inline]
fn label_word(planes: &mut [u64], w: usize, bits: u64, c: u32) {
    if c & 1 != 0 {
        planes[2 * w] |= bits;
    }
    if c & 2 != 0 {
        planes[2 * w + 1] |= bits;
    }
}

/// The nodes of row word `w` of residue `planes` numbered with residue code `code` (1, 2 or 3).
#[inline]
fn with_code(planes: &[u64], w: usize, code: u32) -> u64 {
    let (lo, hi) = (planes[2 * w], planes[2 * w + 1]);
    match code {
        1 => lo & !hi,
        2 => !lo & hi,
        _ => lo & hi,
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Connectivity {
    /// The 6 axis neighbours.
    Six,
    /// All 26 neighbours.
    TwentySix,
}

/// Neighbour offsets in a fixed order: lexicographic over (d1, d2, d3) in {-1, 0, 1}^3.
pub fn offsets(c: Connectivity) -> &'static [[i32; 3]] {
    const SIX: [[i32; 3]; 6] = [
        [-1, 0, 0],
        [0, -1, 0],
        [0, 0, -1],
        [0, 0, 1],
        [0, 1, 0],
        [1, 0, 0],
    ];
    const ALL: [[i32; 3]; 26] = {
        let mut out = [[0; 3]; 26];
        let mut i = 0;
        let mut a = -1;
        while a <= 1 {
            let mut b = -1;
            while b <= 1 {
                let mut c = -1;
                while c <= 1 {
                    if !(a == 0 && b == 0 && c == 0) {
                        out[i] = [a, b, c];
                        i += 1;
                    }
                    c += 1;
                }
                b += 1;
            }
            a += 1;
        }
        out
    };
    match c {
        Connectivity::Six => &SIX,
        Connectivity::TwentySix => &ALL,
    }
}

/// A wave: which nodes it numbered and their numbers, 0 = not numbered (blocked or beyond the
/// end node's wave). A node-by-node wave holds the numbers; the row wave only their residues
/// modulo 3, which give a numbered node's number from a neighbour's
/// ([`label_next_to`](Self::label_next_to)).
#[derive(Clone, Debug)]
pub struct Wave {
    pub start: Node,
    pub end: Node,
    pub connectivity: Connectivity,
    labels: Labels,
    dims: [usize; 3],
    /// The end node's number.
    n: u32,
}

impl Wave {
    /// The number of node `m`, a neighbour (26 neighbours: at most one step on each axis) of a
    /// node numbered `l_here`; 0 when `m` is not numbered or outside the grid. Exact for every
    /// numbered `m` joined to that node by a step of the wave, for any `m` of a node-by-node
    /// wave, and for any numbered `m` of the row wave (it numbers over every step between
    /// usable nodes): breadth-first, such a neighbour is numbered `l_here - 1`, `l_here` or
    /// `l_here + 1`, told apart by the residue. Of the row wave, a numbered neighbour of a
    /// node not numbered `l_here` reads as one of those three.
    #[inline]
    pub fn label_next_to(&self, m: Node, l_here: u32) -> u32 {
        if !(0..3).all(|k| m[k] >= 0 && (m[k] as usize) < self.dims[k]) {
            return 0;
        }
        let (t, z) = (m[0] as usize * self.dims[1] + m[1] as usize, m[2] as usize);
        match &self.labels {
            Labels::Narrow(l) => number_of(l[t * self.dims[2] + z]),
            Labels::Wide(l) => number_of(l[t * self.dims[2] + z]),
            Labels::Residues { planes, words } => {
                let w = t * words + z / 64;
                let b = z % 64;
                let code = ((planes[2 * w] >> b) & 1) | (((planes[2 * w + 1] >> b) & 1) << 1);
                match code {
                    0 => 0,
                    // (code - here's code) mod 3: 0 the same number, 1 one more, 2 one less.
                    c => match (c as u32 + 3 - residue_code(l_here.max(1))) % 3 {
                        0 => l_here,
                        1 => l_here + 1,
                        _ => l_here.saturating_sub(1),
                    },
                }
            }
        }
    }

    /// n, the end node's number.
    pub fn n(&self) -> u32 {
        self.n
    }

    /// How many nodes were numbered.
    pub fn numbered(&self) -> usize {
        match &self.labels {
            Labels::Narrow(l) => l.iter().filter(|&&x| number_of(x) > 0).count(),
            Labels::Wide(l) => l.iter().filter(|&&x| number_of(x) > 0).count(),
            Labels::Residues { planes, .. } => planes
                .chunks_exact(2)
                .map(|p| (p[0] | p[1]).count_ones() as usize)
                .sum(),
        }
    }
}

#[cfg(test)]
impl Wave {
    /// The same wave keeping only its numbers' residues, as the row wave does: for tests of the
    /// walk on a wave with fewer steps than every step between numbered nodes.
    pub(crate) fn as_residues(&self) -> Wave {
        let [d0, d1, d2] = self.dims;
        let words = d2.div_ceil(64);
        let mut planes = ZeroBuf::zeros(2 * d0 * d1 * words);
        for t in 0..d0 * d1 {
            for z in 0..d2 {
                let m = [(t / d1) as i32, (t % d1) as i32, z as i32];
                // A node-by-node wave: the number itself, whatever the node beside.
                let l = self.label_next_to(m, 1);
                if l > 0 {
                    let (w, b) = (t * words + z / 64, z % 64);
                    label_word(&mut planes, w, 1 << b, residue_code(l));
                }
            }
        }
        Wave {
            labels: Labels::Residues { planes, words },
            ..self.clone()
        }
    }
}

/// Numbers the nodes of `graph` from `start` (1) outward over its steps until `end` is numbered;
/// `None` when `end` cannot be reached. Both nodes must be free and usable. Row by row
/// ([`number_rows`], residues) for 26 neighbours when every step between usable nodes is a
/// wave step (the optimistic wave, the common one), else node by node ([`number_scalar`],
/// numbers). The numbers below the end's are the same either way (each node's distance in
/// steps from the start node, plus one); of the nodes numbered like the end, either may number
/// more or fewer, and nobody reads those (a walk back from the end only steps to lower
/// numbers).
pub fn expand<G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
) -> Option<Wave> {
    let g = &cs.grid;
    if !ends_usable(cs, graph, start, end) {
        return None;
    }
    let (labels, n) = if graph.wave_steps_all() && connectivity == Connectivity::TwentySix {
        by_row_words!(cs, number_rows::<G>(cs, graph, start, end))?
    } else if let Some(floor) = graph.steps_floor() {
        bounded::number(cs, graph, start, end, connectivity, floor)?
    } else {
        number_nodes(cs, graph, start, end, connectivity, None).ok()??
    };
    Some(Wave {
        start,
        end,
        connectivity,
        labels,
        dims: g.dims,
        n,
    })
}

/// The node-by-node wave ([`number_scalar`]) in narrow words, again in wide ones where a
/// number does not fit: the labels and the end's number, `Ok(None)` when the end cannot be
/// reached, `Err(Pruned)` when the bound left nodes out and the end was not reached.
fn number_nodes<G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
    bound: Option<Bound<'_>>,
) -> Result<Option<(Labels, u32)>, Pruned> {
    let end_index = cs.grid.index(end);
    let narrow = number_scalar::<u16, G>(cs, graph, start, end, connectivity, bound);
    let (labels, n) = match narrow {
        Ok(Numbered::Reached(labels)) => {
            let n = number_of(labels[end_index]);
            (Labels::Narrow(labels), n)
        }
        Ok(Numbered::Exhausted { pruned }) => return exhausted(pruned),
        Err(TooLong) => match number_scalar::<u32, G>(cs, graph, start, end, connectivity, bound) {
            Ok(Numbered::Reached(labels)) => {
                let n = number_of(labels[end_index]);
                (Labels::Wide(labels), n)
            }
            Ok(Numbered::Exhausted { pruned }) => return exhausted(pruned),
            Err(TooLong) => return Ok(None),
        },
    };
    Ok(Some((labels, n)))
}

/// A bounded wave ran out having left nodes out: a larger bound may reach the end.
struct Pruned;

/// [`number_nodes`]'s answer for a wave that ran out.
fn exhausted(pruned: bool) -> Result<Option<(Labels, u32)>, Pruned> {
    if pruned {
        Err(Pruned)
    } else {
        Ok(None)
    }
}

/// Whether both ends are free on the grid and usable in `graph` (a wave needs both).
fn ends_usable<G: Graph + ?Sized>(cs: &CSpace, graph: &G, start: Node, end: Node) -> bool {
    cs.is_free(start) && cs.is_free(end) && graph.node_ok(start) && graph.node_ok(end)
}

#[cfg(test)]
mod tests {
    use super::testing::*;
    use super::*;
    use crate::plan::cspace::Grid;

    #[test]
    fn numbers_are_chebyshev_steps_in_free_space() {
        let cs = open(10.0);
        let w =
            expand(&cs, &Open, [0, 0, 0], [7, 3, 5], Connectivity::TwentySix).expect("reachable");
        assert_eq!(w.n(), 8); // 7 steps, numbered from 1
        assert!(matches!(w.labels, Labels::Residues { .. }));
        // A wave from a node to itself: that node numbered 1, its neighbours not yet.
        let same = expand(&cs, &Open, [2, 2, 2], [2, 2, 2], Connectivity::TwentySix)
            .expect("the start is the end");
        assert_eq!(same.n(), 1);
        assert!(matches!(same.labels, Labels::Residues { .. }));
        assert_eq!(same.label_next_to([2, 2, 2], 2), 1);
        assert_eq!(same.label_next_to([2, 2, 3], 1), 0);
        let l = numbers(&w);
        assert_eq!(l[cs.grid.index([3, 3, 3])], 4);
        assert_eq!(l[cs.grid.index([1, 0, 1])], 2);
        // Read from a neighbour's number: one less, the same, one more; not numbered.
        assert_eq!(w.label_next_to([3, 3, 3], 5), 4);
        assert_eq!(w.label_next_to([3, 3, 3], 4), 4);
        assert_eq!(w.label_next_to([3, 3, 3], 3), 4);
        assert_eq!(w.label_next_to([9, 9, 9], 9), 0);
        assert_eq!(w.label_next_to([-1, 0, 0], 2), 0);
    }

    #[test]
    fn six_neighbour_numbers_are_manhattan_steps() {
        let cs = open(10.0);
        let w = expand(&cs, &Open, [0, 0, 0], [3, 2, 1], Connectivity::Six).expect("reachable");
        assert_eq!(w.n(), 7);
        assert_eq!(numbers(&w)[cs.grid.index([1, 1, 0])], 3);
    }

    #[test]
    fn walls_force_a_detour_and_a_closed_wall_fails() {
        // A wall at x = 5 with a hole at (5, 9, *).
        let g = Grid::over([[0.0, 10.0], [0.0, 10.0], [0.0, 0.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| n[0] != 5 || n[1] == 9);
        let w = expand(&cs, &Open, [0, 0, 0], [10, 0, 0], Connectivity::TwentySix)
            .expect("through the hole");
        // Out to y = 9 and back: 9 steps up (x rising to 5 on the way), then 5 + ... at least 18 steps.
        assert_eq!(w.n(), 19);
        let closed = CSpace::from_fn(g, |n| n[0] != 5);
        assert!(expand(
            &closed,
            &Open,
            [0, 0, 0],
            [10, 0, 0],
            Connectivity::TwentySix
        )
        .is_none());
    }

    #[test]
    fn every_numbered_node_below_n_has_a_predecessor() {
        let g = Grid::over([[0.0, 12.0], [0.0, 12.0], [0.0, 6.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| (n[0] != 6 || n[1] >= 10) && (n[1] != 4 || n[2] != 3));
        let w =
            expand(&cs, &Open, [0, 0, 0], [12, 0, 6], Connectivity::TwentySix).expect("reachable");
        let labels = numbers(&w);
        let label = |m: Node| if g.contains(m) { labels[g.index(m)] } else { 0 };
        for i in 0..g.len() {
            let n = g.node(i);
            let l = label(n);
            if l > 1 && l < w.n() {
                let has = offsets(Connectivity::TwentySix)
                    .iter()
                    .any(|o| label([n[0] + o[0], n[1] + o[1], n[2] + o[2]]) == l - 1);
                assert!(
                    has,
                    "{n:?} numbered {l} has no neighbour numbered {}",
                    l - 1
                );
            }
        }
    }

    /// Free nodes and usable ones scattered pseudo-randomly; every step between usable nodes
    /// exists. The wave row by row (`wave_steps_all`) and node by node (not) both give every
    /// node below the end's number its breadth-first distance (a plain queue over the 26
    /// neighbours), number nothing else below it, and agree on n.
    #[test]
    fn row_and_node_waves_number_the_breadth_first_distances() {
        struct Holes(bool);
        fn hash(n: Node) -> u32 {
            let h = (n[0] as u32).wrapping_mul(73_856_093)
                ^ (n[1] as u32).wrapping_mul(19_349_663)
                ^ (n[2] as u32).wrapping_mul(83_492_791);
            h.wrapping_mul(2_654_435_761) >> 7
        }
        impl Graph for Holes {
            fn node_ok(&self, n: Node) -> bool {
                hash(n) % 7 != 0
            }
            fn step_ok(&self, _: Node, _: Node) -> bool {
                true
            }
            fn wave_steps_all(&self) -> bool {
                self.0
            }
        }
        // 70 nodes along axis 3: two words a row, the second partly used.
        let g = Grid::over([[0.0, 23.0], [0.0, 17.0], [0.0, 69.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| hash([n[2], n[0], n[1]]) % 4 != 0);
        let usable = |n: Node| cs.is_free(n) && Holes(true).node_ok(n);
        let start = (0..g.len())
            .map(|i| g.node(i))
            .find(|&n| usable(n))
            .expect("a start");
        let dist = bfs(&g, start, usable);
        let far = (0..g.len())
            .max_by_key(|&i| (dist[i], i))
            .map(|i| g.node(i));
        let mid = (0..g.len()).find(|&i| dist[i] == dist[g.index(far.unwrap())] / 2);
        for end in [far.unwrap(), g.node(mid.unwrap())] {
            let n = dist[g.index(end)];
            assert!(n > 10, "too near to test: {n}");
            for every in [true, false] {
                let w = expand(&cs, &Holes(every), start, end, Connectivity::TwentySix)
                    .expect("joined");
                assert_labels_are_distances(&w, &g, &dist, n, &format!("every {every}"));
            }
        }
    }
}
