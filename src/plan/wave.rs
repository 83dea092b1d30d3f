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
//! time on bit sets of axis-3 rows (`number_rows`), the others node by node from a queue. The
//! numbers below n are the same (each node's breadth-first distance, plus one). The row wave
//! spreads only the front's words that hold front nodes (inside a wide front a row's new nodes
//! are its two ends, so its other words are not spread again level after level), and finds the
//! next candidates by groups of rows marked, in ascending order (no list of touched rows). In
//! the row wave, the free nodes a graph need not look at ([`Graph::look_bits`]: for a leg, those
//! whose code says the tool stays clear) come a word at a time from the grid's row bit set
//! ([`CSpace::row_bits`]). The row wave keeps no numbers: it keeps each numbered node's number
//! modulo 3 in two bit planes (2 bits a node, written a word at a time per level), which is all
//! a walk back needs. A walk knows the number of the node it stands on (it starts at the end,
//! numbered n), and in this wave every step between numbered nodes is a wave step, so a
//! numbered neighbour's number is one less, the same or one more: the residue tells which
//! ([`Wave::label_next_to`]). The node-by-node wave keeps the numbers (2 bytes a node, 4 for a
//! path of over 65 533 steps). The planes, the row wave's decided and candidate words and the
//! node-by-node numbers span the whole grid but are [`ZeroBuf`]s (`crate::zeroed`): a wave
//! pays for the pages it touches (the ball it numbers), not for zeroing the whole grid.
//!
//! Beyond the paper, for speed only: the searches walk back only to neighbours numbered one
//! less (extensile and neighboring over 26 neighbours, depth-first over the 6 axis
//! neighbours), so they get row waves with the numbers kept only on the nodes of the shortest
//! paths between the ends ([`expand_both`], [`expand_corridor`]): a wave
//! from each end, the one with the smaller front a level at a time, until they meet (about two
//! balls of half the distance instead of one or two of the whole), then the shortest paths'
//! nodes gathered back from where they met. Every walk back takes the same steps as over the
//! whole wave (`corridor_rows` says why); the tests hold both against the whole waves. The two
//! waves are bounded, as A* is by its estimate: a node whose distance from its wave's start
//! plus its grid distance to the other end (the largest index difference, the steps it would
//! take without obstacles) exceeds a bound on the ends' distance is left out, and the bound
//! grows until the waves meet within it (`corridor_rows`). The corridor is the same; the waves
//! number the nodes between the ends rather than the balls around them, and a leg looks at
//! its tool at fewer nodes (torch-trunk at 1 deg: 17 % fewer instructions; gripper-pick 31 %).
//!
//! Beyond the paper: the wave runs on a [`Graph`], whose nodes are the grid's free nodes that the
//! graph accepts (a leg's tool at its wrist) and whose edges are the neighbour steps it accepts
//! (the whole-move check). So the numbers count accepted steps, and every numbered node but the
//! start has a neighbour one number lower joined to it by an accepted step: a walk back over
//! accepted steps from the end node always reaches the start node (`search`). More: an accepted
//! step never joins two nodes whose numbers differ by more than one (when the lower one was
//! expanded, the step numbered the other), so every accepted step down from a node numbered `l`
//! leads to `l - 1`.

use crate::plan::cspace::{CSpace, Node, FREE, ROW_BITS_MAX_BYTES};
use crate::zeroed::ZeroBuf;

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

/// A node's label word in the node-by-node wave. It is numbered in `u16` words (2 bytes a
/// node: half the memory and memory traffic of `u32`) and again in `u32` only if a number would
/// not fit: when a node numbered 65 533 is expanded, i.e. the end's number would be 65 534 or
/// more (or the end is unreachable from a component that deep, numbered again only to return
/// `None`). The numbers are the same either way.
trait Word: bytemuck::Pod + PartialEq + Default + Send + 'static {
    /// The node was looked at and may not be used.
    const BLOCKED: Self;
    /// The node may be used but no accepted step has reached it yet.
    const CHECKED: Self;
    /// Number 1.
    const ONE: Self;
    /// The number as `u32` (sentinels included).
    fn wide(self) -> u32;
    /// The next number, `None` when it would reach the sentinels.
    fn next(self) -> Option<Self>;
}

impl Word for u16 {
    const BLOCKED: u16 = u16::MAX;
    const CHECKED: u16 = u16::MAX - 1;
    const ONE: u16 = 1;
    fn wide(self) -> u32 {
        self as u32
    }
    fn next(self) -> Option<u16> {
        (self + 1 < Self::CHECKED).then_some(self + 1)
    }
}

impl Word for u32 {
    const BLOCKED: u32 = u32::MAX;
    const CHECKED: u32 = u32::MAX - 1;
    const ONE: u32 = 1;
    fn wide(self) -> u32 {
        self
    }
    fn next(self) -> Option<u32> {
        (self + 1 < Self::CHECKED).then_some(self + 1)
    }
}

/// The rows of the row wave's candidates marked together (one bit a group; a group's scan also
/// reads the row just below and just above it, so a front word marks one group a plane of rows).
const GROUP_ROWS: usize = 4;
const _: () = assert!(GROUP_ROWS >= 2, "the row wave's front stays ascending");

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

#[inline]
fn number_of<W: Word>(l: W) -> u32 {
    if l == W::CHECKED || l == W::BLOCKED {
        0
    } else {
        l.wide()
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
    } else {
        let end_index = g.index(end);
        match number_scalar::<u16, G>(cs, graph, start, end, connectivity) {
            Ok(labels) => {
                let labels = labels?;
                let n = number_of(labels[end_index]);
                (Labels::Narrow(labels), n)
            }
            Err(TooLong) => {
                let labels =
                    number_scalar::<u32, G>(cs, graph, start, end, connectivity).ok()??;
                let n = number_of(labels[end_index]);
                (Labels::Wide(labels), n)
            }
        }
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

/// Both waves of the extensile search, from `start` to `end` and from `end` to `start`, with
/// the numbers [`expand`] gives them (26 neighbours) on the nodes of the shortest paths between
/// the two; off those, either may number fewer nodes. When every step between usable nodes is
/// a wave step, the two are numbered together and only the nodes between the ends within a
/// bound are numbered ([`corridor_rows`], which says why a walk back over either takes the same
/// steps as over the whole wave); otherwise each is numbered whole, on two threads. `None`
/// for a wave whose end cannot be reached.
pub fn expand_both<G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
) -> (Option<Wave>, Option<Wave>) {
    if !graph.wave_steps_all() {
        return std::thread::scope(|s| {
            let other = s.spawn(|| expand(cs, graph, end, start, Connectivity::TwentySix));
            let here = expand(cs, graph, start, end, Connectivity::TwentySix);
            // A panic in the other wave is a defect; fall back to computing it here.
            let there = other
                .join()
                .unwrap_or_else(|_| expand(cs, graph, end, start, Connectivity::TwentySix));
            (here, there)
        });
    }
    corridor_waves(cs, graph, start, end, Connectivity::TwentySix).unzip()
}

/// The wave from `start` to `end` over `connectivity` with the numbers [`expand`] gives it on
/// the nodes of the shortest paths between the two, for a search that walks back over it and
/// only ever steps to a neighbour (of that connectivity) numbered one less (the neighboring and
/// the depth-first searches): numbered with the wave from the end as [`expand_both`] does when
/// every step between usable nodes is a wave step, else whole ([`expand`]). `None` when the
/// end cannot be reached.
pub fn expand_corridor<G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
) -> Option<Wave> {
    if !graph.wave_steps_all() {
        return expand(cs, graph, start, end, connectivity);
    }
    corridor_waves(cs, graph, start, end, connectivity).map(|(here, _)| here)
}

/// [`corridor_rows`]'s two waves, from `start` and from `end`, for a graph whose every step
/// between usable nodes is a wave step.
fn corridor_waves<G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
) -> Option<(Wave, Wave)> {
    if !ends_usable(cs, graph, start, end) {
        return None;
    }
    let six = connectivity == Connectivity::Six;
    let (ls, le, n) = by_row_words!(cs, corridor_rows::<G>(cs, graph, start, end, six))?;
    let wave = |start, end, labels| Wave {
        start,
        end,
        connectivity,
        labels,
        dims: cs.grid.dims,
        n,
    };
    Some((wave(start, end, ls), wave(end, start, le)))
}

/// Whether both ends are free on the grid and usable in `graph` (a wave needs both).
fn ends_usable<G: Graph + ?Sized>(cs: &CSpace, graph: &G, start: Node, end: Node) -> bool {
    cs.is_free(start) && cs.is_free(end) && graph.node_ok(start) && graph.node_ok(end)
}

/// A number outgrew the label word of the node-by-node wave.
struct TooLong;
/// The expansion for 26 neighbours over a graph whose every step between usable nodes is a
/// wave step ([`Graph::wave_steps_all`]), level by level on bit sets of axis-3 rows (a row: the
/// nodes of fixed axes 1 and 2, one bit each, axis-3 index `64 j + b` at bit `b` of word `j`).
/// The nodes next numbered are the front's neighbours ([`Reach`]) not yet decided; each of
/// those is looked at once (free on the grid, [`Graph::node_ok_coded`]) and numbered or decided
/// unusable. A level's new nodes are labelled a word at a time, OR-ed into the residue planes
/// its number's residue code picks ([`Labels::Residues`]: 2 bits a node, no node written one by
/// one, nothing to clear and no number too long), so a level costs a few word operations per
/// front word and per row it reaches, and one look per node it numbers. When the graph names
/// the code bits its answer depends on ([`Graph::look_bits`]), the free nodes without them come
/// a word at a time from the grid's row bit set ([`CSpace::row_bits`], grids up to
/// [`ROW_BITS_MAX_BYTES`] of it): numbered without a look; only the other candidates (blocked,
/// or with those bits) are looked at one by one. No node past the end in the end's word is
/// looked at. `K`: the words a row, or 0 for any number. Returns the labels and the end's
/// number, `None` when the end cannot be reached.
fn number_rows<G: Graph + ?Sized, const K: usize>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
) -> Option<(Labels, u32)> {
    let end_index = cs.grid.index(end);
    let mut wave = RowWave::<G, K>::new(cs, graph, cs.grid.index(start), Some(end_index), false);
    if cs.grid.index(start) == end_index {
        return Some((wave.labels(), 1));
    }
    loop {
        match wave.next_level() {
            Level::End => {
                let n = wave.level;
                return Some((wave.labels(), n));
            }
            Level::Numbered => {}
            Level::Exhausted => return None,
        }
    }
}

/// How a row wave's level ended.
enum Level {
    /// The end node was numbered (the level was left there).
    End,
    /// The level was numbered whole.
    Numbered,
    /// Nothing was left to number: the front was empty.
    Exhausted,
}

/// A row wave between levels ([`number_rows`], [`corridor_rows`]).
struct RowWave<'a, G: Graph + ?Sized, const K: usize> {
    cs: &'a CSpace,
    graph: &'a G,
    reach: Reach<K>,
    /// The grid's row bit set of the free nodes usable without a look, if any.
    rows_kept: Option<std::sync::Arc<crate::plan::cspace::RowBits>>,
    /// The bits of a row's last word that are nodes.
    last_mask: u64,
    /// The end's word, its bit, and its bits up to the end's (no end: a word past the grid).
    end_word: usize,
    end_bit: u64,
    upto_end: u64,
    /// The residue planes.
    planes: ZeroBuf<u64>,
    /// Decided nodes: numbered, not free, or not usable.
    decided: ZeroBuf<u64>,
    /// The front: its words that hold front nodes, as (row word index, the front's bits), by
    /// ascending index.
    front: Vec<(usize, u64)>,
    next_front: Vec<(usize, u64)>,
    /// The number of the last level numbered (below `MAX_NODES`, a `u32`).
    level: u32,
    /// The bound of a corridor wave ([`corridor_rows`]): the other end's node (grid indices)
    /// and the most steps a path between the ends may take; a node farther from the start
    /// than that less its grid distance (steps ignoring obstacles, the largest index
    /// difference) to the other end is left out. `None`: every node counts.
    bound: Option<([i64; 3], i64)>,
    /// A node was left out by the bound.
    pruned: bool,
    /// The end was numbered ([`Level::End`]).
    ended: bool,
}

impl<'a, G: Graph + ?Sized, const K: usize> RowWave<'a, G, K> {
    /// The wave with its start (linear index) numbered 1; `end` the linear index at which it
    /// stops, if any; over the 6 axis neighbours when `six`, else the 26.
    fn new(cs: &'a CSpace, graph: &'a G, start: usize, end: Option<usize>, six: bool) -> Self {
        let g = &cs.grid;
        let d2 = g.dims[2];
        let reach = Reach::<K>::new(g.dims, six);
        let words = reach.words;
        let rows = reach.rows;
        let mut planes = ZeroBuf::zeros(2 * rows * words);
        let mut decided = ZeroBuf::zeros(rows * words);
        let (r0, j0, b0) = (start / d2, (start % d2) / 64, (start % d2) % 64);
        // Number 1's code, 1: the low plane only.
        planes[2 * (r0 * words + j0)] |= 1 << b0;
        decided[r0 * words + j0] |= 1 << b0;
        let last_mask = match d2 % 64 {
            0 => u64::MAX,
            r => (1u64 << r) - 1,
        };
        let (end_word, end_bit) = match end {
            Some(e) => ((e / d2) * words + (e % d2) / 64, 1u64 << ((e % d2) % 64)),
            None => (usize::MAX, 1),
        };
        let rows_kept = graph
            .look_bits()
            .filter(|_| rows * words * 8 <= ROW_BITS_MAX_BYTES)
            .map(|bits| cs.row_bits(bits));
        RowWave {
            cs,
            graph,
            reach,
            rows_kept,
            last_mask,
            end_word,
            end_bit,
            upto_end: end_bit | (end_bit - 1),
            planes,
            decided,
            front: vec![(r0 * words + j0, 1 << b0)],
            next_front: Vec::new(),
            level: 1,
            ended: false,
            bound: None,
            pruned: false,
        }
    }

    /// The same wave bounded (the field's doc): the other end `to` and at most `steps` steps.
    fn bounded(mut self, to: Node, steps: i64) -> Self {
        self.bound = Some((to.map(i64::from), steps));
        self
    }

    fn labels(self) -> Labels {
        Labels::Residues {
            planes: self.planes,
            words: self.reach.words,
        }
    }

    /// Numbers the next level: the front's neighbours not decided yet, looked at by ascending
    /// row, numbered when usable; they become the front. After [`Level::End`] the wave is left
    /// mid-level (its gathered words not cleared): it must not be asked for another.
    fn next_level(&mut self) -> Level {
        debug_assert!(!self.ended, "a row wave asked for a level past its end");
        let (Some(&(first, _)), Some(&(last, _))) = (self.front.first(), self.front.last()) else {
            return Level::Exhausted;
        };
        let next = self.level + 1;
        let rc = residue_code(next);
        self.reach.spread(&self.front);
        let (cs, graph) = (self.cs, self.graph);
        let d1 = cs.grid.dims[1];
        let d2 = cs.grid.dims[2];
        let words = self.reach.words;
        let plain = self.rows_kept.as_deref().map(|r| r.plain.as_slice());
        let (last_mask, end_word, end_bit, upto_end) =
            (self.last_mask, self.end_word, self.end_bit, self.upto_end);
        let (decided, planes, next_front) =
            (&mut self.decided, &mut self.planes, &mut self.next_front);
        // The bound: nodes numbered `next` lie `next - 1` steps from the start, so those kept
        // lie within `r` of the other end on every axis.
        let keep = self
            .bound
            .map(|(to, steps)| (to, steps - i64::from(next - 1)));
        let pruned = &mut self.pruned;
        let ended = self.reach.drain(first, last, |t, j, w, taken| {
            let mut c = taken & !decided[w];
            if c == 0 {
                return false;
            }
            if j + 1 == words {
                c &= last_mask;
            }
            if let Some((to, r)) = keep {
                let inside = within(to, r, (t / d1) as i64, (t % d1) as i64, j);
                if c & !inside != 0 {
                    *pruned = true;
                    // Never kept later either (`r` only falls): decided.
                    decided[w] |= c & !inside;
                    c &= inside;
                    if c == 0 {
                        return false;
                    }
                }
            }
            if w == end_word && c & end_bit != 0 {
                c &= upto_end;
            }
            decided[w] |= c;
            let base = t * d2 + j * 64;
            // The usable candidates: the plain ones at once, the others looked at.
            let (mut numbered, mut look) = match plain {
                Some(p) => (c & p[w], c & !p[w]),
                None => (0, c),
            };
            while look != 0 {
                let b = look.trailing_zeros() as usize;
                look &= look - 1;
                let code = cs.code_index(base + b);
                if code & FREE != 0
                    && graph.node_ok_coded(
                        [(t / d1) as i32, (t % d1) as i32, (j * 64 + b) as i32],
                        code,
                    )
                {
                    numbered |= 1 << b;
                }
            }
            label_word(planes, w, numbered, rc);
            #[cfg(test)]
            ROW_NUMBERED.with(|c| c.set(c.get() + u64::from(numbered.count_ones())));
            if w == end_word && numbered & end_bit != 0 {
                return true;
            }
            if numbered != 0 {
                next_front.push((w, numbered));
            }
            false
        });
        self.level = next;
        if ended {
            self.ended = true;
            return Level::End;
        }
        // Ascending: a group's scan starts below the rows of the group before only on rows
        // that group's scan cleared (with `GROUP_ROWS` at least 2), so the bounds above hold.
        debug_assert!(self.next_front.windows(2).all(|p| p[0].0 < p[1].0));
        std::mem::swap(&mut self.front, &mut self.next_front);
        self.next_front.clear();
        Level::Numbered
    }

    /// The numbered nodes of row word `w`.
    #[inline]
    fn numbered(&self, w: usize) -> u64 {
        self.planes[2 * w] | self.planes[2 * w + 1]
    }
}

/// The bits of word `j` of row `(i0, i1)` whose nodes lie within `r` of node `to` on every axis
/// (grid indices): all or none by the row, a run of bits by axis 3.
#[inline]
fn within(to: [i64; 3], r: i64, i0: i64, i1: i64, j: usize) -> u64 {
    if r < 0 || (i0 - to[0]).abs() > r || (i1 - to[1]).abs() > r {
        return 0;
    }
    let lo = (to[2] - r - 64 * j as i64).max(0);
    let hi = (to[2] + r - 64 * j as i64).min(63);
    if lo > hi {
        return 0;
    }
    let width = (hi - lo + 1) as u32;
    let run = if width == 64 {
        u64::MAX
    } else {
        (1u64 << width) - 1
    };
    run << lo
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

/// The neighbours of a set of row words, gathered a level at a time: each word's bits spread
/// by one along axis 3 (themselves included), a bit at either end carried into the word
/// beside, into the same words of the 3 x 3 rows around its row. Only the words given are
/// spread (inside a wide front, a row's front is its two ends). The rows spread into are
/// marked by groups of [`GROUP_ROWS`] rows, and [`drain`](Self::drain) takes the gathered words
/// from the rows of the groups marked and the rows just beside them, leaving every word clear.
struct Reach<const K: usize> {
    d0: usize,
    d1: usize,
    words: usize,
    rows: usize,
    /// The gathered words (`words` a row, every row).
    cand: ZeroBuf<u64>,
    /// The groups of `GROUP_ROWS` rows whose words, or those of the rows just beside them, may
    /// hold some (a bit a group).
    groups: Vec<u64>,
    /// A word's neighbour words in the 3 x 3 rows around, from the first (a row off the
    /// grid's border on axes 1 and 2).
    around: [usize; 9],
    /// Over the 6 axis neighbours only: a word spreads along axis 3 in its own row and only
    /// into the same bits of the 4 rows beside along axes 1 and 2.
    six: bool,
}

impl<const K: usize> Reach<K> {
    fn new(dims: [usize; 3], six: bool) -> Self {
        let [d0, d1, d2] = dims;
        let words = if K == 0 { d2.div_ceil(64) } else { K };
        debug_assert_eq!(words, d2.div_ceil(64));
        let rows = d0 * d1;
        Reach {
            d0,
            d1,
            words,
            rows,
            cand: ZeroBuf::zeros(rows * words),
            groups: vec![0u64; rows.div_ceil(GROUP_ROWS * 64)],
            around: std::array::from_fn(|k| ((k / 3) * d1 + k % 3) * words),
            six,
        }
    }

    /// Gathers the neighbours of `front` (row words by ascending index).
    fn spread(&mut self, front: &[(usize, u64)]) {
        if self.six {
            return self.spread_six(front);
        }
        let (d0, d1, words) = (self.d0, self.d1, self.words);
        let (cand, groups) = (&mut self.cand, &mut self.groups);
        for &(w, bits) in front {
            let (t, j) = (w / words, w % words);
            let (i0, i1) = (
                (t as u32 / d1 as u32) as usize,
                (t as u32 % d1 as u32) as usize,
            );
            let spread = bits | (bits << 1) | (bits >> 1);
            let below = if j > 0 { (bits & 1) << 63 } else { 0 };
            let above = if j + 1 < words { bits >> 63 } else { 0 };
            if below | above == 0 && i0 > 0 && i0 + 1 < d0 && i1 > 0 && i1 + 1 < d1 {
                let from = w - self.around[4];
                for a in self.around {
                    cand[from + a] |= spread;
                }
                for t0 in [t - d1, t, t + d1] {
                    let g = t0 / GROUP_ROWS;
                    groups[g / 64] |= 1 << (g % 64);
                }
                continue;
            }
            let (b0, b1) = (i1.saturating_sub(1), (i1 + 1).min(d1 - 1));
            for t0 in i0.saturating_sub(1)..=(i0 + 1).min(d0 - 1) {
                // The same word of rows `b0..=b1` along axis 2, and the words beside.
                let (x0, x1) = ((t0 * d1 + b0) * words + j, (t0 * d1 + b1) * words + j);
                for x in (x0..=x1).step_by(words) {
                    cand[x] |= spread;
                    if below != 0 {
                        cand[x - 1] |= below;
                    }
                    if above != 0 {
                        cand[x + 1] |= above;
                    }
                }
                let g = (t0 * d1 + i1) / GROUP_ROWS;
                groups[g / 64] |= 1 << (g % 64);
            }
        }
    }

    /// [`spread`](Self::spread) over the 6 axis neighbours: a word's bits spread by one along
    /// axis 3 in its own row (a bit at either end carried into the word beside), and the same
    /// bits into the same word of the rows one step along axis 1 and along axis 2.
    fn spread_six(&mut self, front: &[(usize, u64)]) {
        let (d0, d1, words) = (self.d0, self.d1, self.words);
        let (cand, groups) = (&mut self.cand, &mut self.groups);
        let mut mark = |t: usize| {
            let g = t / GROUP_ROWS;
            groups[g / 64] |= 1 << (g % 64);
        };
        for &(w, bits) in front {
            let (t, j) = (w / words, w % words);
            let (i0, i1) = (
                (t as u32 / d1 as u32) as usize,
                (t as u32 % d1 as u32) as usize,
            );
            cand[w] |= bits | (bits << 1) | (bits >> 1);
            if j > 0 {
                cand[w - 1] |= (bits & 1) << 63;
            }
            if j + 1 < words {
                cand[w + 1] |= bits >> 63;
            }
            if i0 > 0 {
                cand[w - d1 * words] |= bits;
                mark(t - d1);
            }
            if i0 + 1 < d0 {
                cand[w + d1 * words] |= bits;
                mark(t + d1);
            }
            if i1 > 0 {
                cand[w - words] |= bits;
            }
            if i1 + 1 < d1 {
                cand[w + words] |= bits;
            }
            // The rows beside along axis 2 are within a row of `t`'s group: its scan reads them.
            mark(t);
        }
    }

    /// Takes the gathered words by ascending row (the rows of each group marked and those just
    /// beside it; the groups marked lie within a plane of rows of the spread front's `first`
    /// and `last` words), clearing them, and hands each nonzero one to `f` as (row, word in
    /// the row, row word index, bits). Stops when `f` says so (true), leaving words gathered;
    /// returns whether it stopped.
    #[inline]
    fn drain(
        &mut self,
        first: usize,
        last: usize,
        mut f: impl FnMut(usize, usize, usize, u64) -> bool,
    ) -> bool {
        let (d1, words, rows) = (self.d1, self.words, self.rows);
        let (lo, hi) = (
            (first / words).saturating_sub(d1 + 1) / (GROUP_ROWS * 64),
            (last / words + d1 + 1) / (GROUP_ROWS * 64),
        );
        for gi in lo..=hi.min(self.groups.len() - 1) {
            let mut m = std::mem::take(&mut self.groups[gi]);
            while m != 0 {
                let g = gi * 64 + m.trailing_zeros() as usize;
                m &= m - 1;
                for t in (g * GROUP_ROWS).saturating_sub(1)..((g + 1) * GROUP_ROWS + 1).min(rows) {
                    for j in 0..words {
                        let w = t * words + j;
                        let c = std::mem::take(&mut self.cand[w]);
                        if c != 0 && f(t, j, w, c) {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }
}

/// Both waves of the extensile search at once, from `start` and from `end`, numbering only the
/// nodes on shortest paths between the two (the corridor), each with its number in that wave:
/// the two labels and n, `None` when the ends are not joined. Beyond the paper, for speed only:
/// each walk back takes the same steps as over the whole wave.
///
/// Why the corridor is enough, with `d_s` and `d_e` a node's distances in steps from `start`
/// and from `end`, and `D` the ends' distance: a walk back from the end over the wave from the
/// start ([`descend`](crate::plan::search::descend)) only ever steps to a neighbour numbered
/// one less. Every step between usable neighbours is a step of these waves (the graph's
/// [`Graph::wave_steps_all`], which `expand_both` asks), so distances differ by at most one
/// between neighbours. The end has `d_s + d_e = D`; if a walked node `x` has it and
/// `d_s(x) = l`, any neighbour `m` numbered `l - 1` (whether or not the graph accepts the
/// step to it) has `d_e(m) <= d_e(x) + 1 = D - d_s(m)`, so `d_s(m) + d_e(m) <= D`, which the
/// triangle inequality makes `= D`. So every node the walk stands on, and every neighbour it
/// may step to, lies on the corridor; a wave that numbers exactly the corridor, each node with
/// its `d_s`, offers the walk the same choices: the neighbours numbered one less are the same
/// nodes, in the same order (the candidates' order ranks one less before the rest), and the
/// others it skips whatever they read. The same holds the other way round.
///
/// How: two row waves ([`RowWave`]), each numbering whole levels, the one with the smaller
/// front (fewer row words) next, until a level of one meets nodes the other numbered. When the
/// wave from the start numbers its level `a` (distance) and meets the other's levels up to `b`,
/// `D = a + b`
/// and the nodes met are the corridor's nodes at `d_s = a`, `d_e = b`: before that level no
/// node had `d_s < a` and `d_e <= b`, so a shortest path's node at `d_s = a - 1` had `d_e >
/// b` (`D >= a + b`), and a node met has `d_e <= b` (`D <= a + b`), so `d_e(x) >= D - a = b`.
/// (The same with the sides swapped.) From the nodes met, the corridor is gathered back down
/// each wave: its nodes at `d_s = k - 1` are the neighbours of those at `k` that the wave
/// numbered at `k - 1` (a node on a shortest path is followed on it by a node one step
/// farther; a numbered neighbour of a corridor node at `k` at distance `k - 1` has `d_e <= D -
/// k + 1`, so it is on the corridor). A neighbour's distance is `k - 1`, `k` or `k + 1`, which
/// the residue tells apart. Each wave's labels are then its own residues on its half of the
/// corridor and, on the other half, the other wave's turned round (`d_s = D - d_e`); both
/// numbered about two balls of half the radius instead of two of the whole.
///
/// *The bound.* Each wave leaves out a node `x` with `d(x) + g(x) > B`, `d` its distance from
/// the wave's start and `g` its grid distance to the other end (the largest difference of the
/// grid indices: every step changes it by at most one, so `g <= ` the distance to the other end
/// and `g(x) <= 1 + g(y)` for neighbours). A node kept keeps its distance: a shortest path to it
/// from the start has `d(y) + g(y) <= d(y) + 1 + g(next) ...<= d(x) + g(x) <= B` at every node
/// `y`, so it is kept whole (A*'s argument for a consistent estimate; the bound only falls
/// level by level, so what it leaves out is never numbered later). So with `D <= B`, every node
/// on a shortest path between the ends (`d + g <= d_s + d_e = D`) is kept by both waves with its
/// distances, the waves meet at the same `D` and the corridor gathered is the unbounded one
/// (it is a set of nodes with their distances, whichever levels the waves met at). Waves that
/// meet at `d > B` (`d >= D`) prove a path that long exists: they are numbered again bounded by
/// it. A wave that runs out having left nothing out has numbered everything it reaches: the
/// ends are not joined. One that runs out having left nodes out is numbered again with the
/// bound grown by an eighth ([`BOUND_GROWTH`]; doubled after [`BOUND_FINE_TRIES`] tries); the
/// first bound is the ends' grid distance. A leg's tool
/// memo keeps its looks across the tries (`plan::leg`): a try again costs the waves' word
/// operations and the fresh pages they touch, not the looks. Over 6 neighbours the waves are
/// not bounded: the grid distance estimates axis steps poorly (up to a third of them), and the
/// tries cost more than they save (an open grid took twice as long).
fn corridor_rows<G: Graph + ?Sized, const K: usize>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    six: bool,
) -> Option<(Labels, Labels, u32)> {
    let (si, ei) = (cs.grid.index(start), cs.grid.index(end));
    if si == ei {
        let from_start = RowWave::<G, K>::new(cs, graph, si, None, six);
        let from_end = RowWave::<G, K>::new(cs, graph, ei, None, six);
        return Some((from_start.labels(), from_end.labels(), 1));
    }
    // First bounded by the ends' grid distance, then by more (module doc); over 6 neighbours
    // not at all.
    let bounded = !six;
    let mut steps = (0..3)
        .map(|k| i64::from((start[k] - end[k]).abs()))
        .max()
        .unwrap_or(0);
    let mut tries = 0;
    let (mut from_start, mut from_end, met) = loop {
        tries += 1;
        let mut from_start = RowWave::<G, K>::new(cs, graph, si, None, six);
        let mut from_end = RowWave::<G, K>::new(cs, graph, ei, None, six);
        if bounded {
            from_start = from_start.bounded(end, steps);
            from_end = from_end.bounded(start, steps);
        }
        match meet(&mut from_start, &mut from_end) {
            Met::Nodes(met) => {
                // The ends' distance in steps: within the bound, the waves' numbers are the
                // unbounded ones (module doc); past it, a path that long exists, so bound by it.
                let d = i64::from(from_start.level + from_end.level) - 2;
                if !bounded || d <= steps {
                    break (from_start, from_end, met);
                }
                steps = d;
            }
            // A wave left nothing out and ran out: the ends are not joined.
            Met::Exhausted { pruned: false } => return None,
            Met::Exhausted { pruned: true } => {
                steps += if tries < BOUND_FINE_TRIES {
                    (steps / BOUND_GROWTH).max(2)
                } else {
                    steps.max(2)
                }
            }
        }
    };
    // The end's number in the wave from the start: d_s + d_e + 1 of the nodes met.
    let n = from_start.level + from_end.level - 1;
    // The labels, in fresh planes: each wave's half of the corridor, gathered back down it from
    // the nodes met, a level at a time. A node numbered `k` by one wave is numbered `n + 1 - k`
    // by the other. The decided sets are not needed any more.
    for wave in [&mut from_start, &mut from_end] {
        wave.decided = ZeroBuf::zeros(0);
    }
    let words = from_start.reach.words;
    let (mut ls, mut le) = (
        ZeroBuf::zeros(from_start.planes.len()),
        ZeroBuf::zeros(from_start.planes.len()),
    );
    for (wave, forward) in [(&mut from_start, true), (&mut from_end, false)] {
        let (own, other) = if forward {
            (&mut ls, &mut le)
        } else {
            (&mut le, &mut ls)
        };
        let mut here = met.clone();
        let mut k = wave.level;
        loop {
            let (code, turned) = (residue_code(k), residue_code(n + 1 - k));
            for &(w, bits) in &here {
                label_word(own, w, bits, code);
                label_word(other, w, bits, turned);
            }
            let (Some(&(first, _)), Some(&(last, _))) = (here.first(), here.last()) else {
                break;
            };
            if k == 1 {
                break;
            }
            let below = residue_code(k - 1);
            let mut down = Vec::new();
            wave.reach.spread(&here);
            let planes = &wave.planes;
            wave.reach.drain(first, last, |_, _, w, taken| {
                let on = taken & with_code(planes, w, below);
                if on != 0 {
                    down.push((w, on));
                }
                false
            });
            // Ascending, as the drain's bounds need (it takes the rows in order).
            debug_assert!(down.windows(2).all(|p| p[0].0 < p[1].0));
            here = down;
            k -= 1;
        }
    }
    let labels = |planes| Labels::Residues { planes, words };
    Some((labels(ls), labels(le), n))
}

/// The corridor waves' bound grows by `1 / BOUND_GROWTH` of itself (at least 2) when a wave ran
/// out having left nodes out ([`corridor_rows`]). Instructions of whole runs at 1 deg (M) by
/// the divisor, torch-trunk / the same without tool shapes / trunk: 2 -> 2056 / 1254 / 1100;
/// 4 -> 1931 / 1261 / 1059; 8 -> 1812 / 1244 / 1045; 16 -> 1828 / 1270 / 1044; 32 -> 1930 /
/// 1313 / 1041 (unbounded: 2179 / 1298 / 1147).
const BOUND_GROWTH: i64 = 8;

/// After this many tries the bound doubles instead: ends that are not joined stop being
/// numbered again once the bound leaves nothing out, and doubling gets there in a few more
/// tries, each numbering more than the one before (so the tries together cost a small
/// multiple of the last). Waves whose ends a wall keeps apart took about twice as long as
/// unbounded ones in a review's open test grid (no looks); the example cells all gain.
const BOUND_FINE_TRIES: u32 = 6;

#[cfg(test)]
thread_local! {
    /// The nodes this thread's row waves numbered (for tests of the bound).
    static ROW_NUMBERED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// How two corridor waves ended ([`meet`]).
enum Met {
    /// The nodes met, as row words.
    Nodes(Vec<(usize, u64)>),
    /// One wave ran out; whether its bound had left a node out.
    Exhausted { pruned: bool },
}

/// Numbers the two waves level by level, the one with the smaller front (fewer row words)
/// next, until a level of one meets nodes the other numbered.
fn meet<'a, G: Graph + ?Sized, const K: usize>(
    from_start: &mut RowWave<'a, G, K>,
    from_end: &mut RowWave<'a, G, K>,
) -> Met {
    loop {
        let forward = from_start.front.len() <= from_end.front.len();
        let (side, other) = if forward {
            (&mut *from_start, &*from_end)
        } else {
            (&mut *from_end, &*from_start)
        };
        match side.next_level() {
            Level::Numbered => {}
            Level::Exhausted => {
                return Met::Exhausted {
                    pruned: side.pruned,
                }
            }
            // Neither wave has an end to stop at.
            Level::End => unreachable!("a wave without an end numbered its end"),
        }
        let met: Vec<(usize, u64)> = side
            .front
            .iter()
            .map(|&(w, bits)| (w, bits & other.numbered(w)))
            .filter(|&(_, bits)| bits != 0)
            .collect();
        if !met.is_empty() {
            return Met::Nodes(met);
        }
    }
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

/// The expansion node by node in words `W`: the labels when `end` was numbered, `Ok(None)`
/// when it cannot be reached, `Err(TooLong)` when a number does not fit in `W`. A first-in
/// first-out queue, each node's neighbours in the order of
/// [`offsets`], the wave's steps asked of the graph.
fn number_scalar<W: Word, G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
) -> Result<Option<ZeroBuf<W>>, TooLong> {
    let g = &cs.grid;
    let mut labels = ZeroBuf::<W>::zeros(g.len());
    let mut queue = std::collections::VecDeque::new();
    labels[g.index(start)] = W::ONE;
    queue.push_back(start);
    let offs = offsets(connectivity);
    let dims = [g.dims[0] as i32, g.dims[1] as i32, g.dims[2] as i32];
    // Linear-index steps of the offsets, for nodes off the grid's border (no bounds checks).
    let stride = [(g.dims[1] * g.dims[2]) as isize, g.dims[2] as isize, 1isize];
    let steps: Vec<isize> = offs
        .iter()
        .map(|o| o[0] as isize * stride[0] + o[1] as isize * stride[1] + o[2] as isize * stride[2])
        .collect();
    let end_index = g.index(end);
    let mut found = start == end;
    while let Some(n) = queue.pop_front() {
        if found {
            break;
        }
        let here = g.index(n);
        let next = labels[here].next().ok_or(TooLong)?;
        let interior = (0..3).all(|k| n[k] > 0 && n[k] < dims[k] - 1);
        for (o, &step) in offs.iter().zip(&steps) {
            let i = if interior {
                (here as isize + step) as usize
            } else {
                let m = [n[0] + o[0], n[1] + o[1], n[2] + o[2]];
                if m[0] < 0
                    || m[1] < 0
                    || m[2] < 0
                    || m[0] >= dims[0]
                    || m[1] >= dims[1]
                    || m[2] >= dims[2]
                {
                    continue;
                }
                g.index(m)
            };
            let l = labels[i];
            if l != W::default() && l != W::CHECKED {
                continue; // numbered, or not usable
            }
            let m = [n[0] + o[0], n[1] + o[1], n[2] + o[2]];
            if l == W::default() {
                let code = cs.code_index(i);
                if code & FREE == 0 {
                    continue;
                }
                if !graph.node_ok_coded(m, code) {
                    labels[i] = W::BLOCKED;
                    continue;
                }
            }
            if !graph.wave_step_ok(n, m) {
                labels[i] = W::CHECKED;
                continue;
            }
            labels[i] = next;
            if i == end_index {
                found = true;
                break;
            }
            queue.push_back(m);
        }
    }
    Ok(found.then_some(labels))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::cspace::Grid;
    use std::collections::VecDeque;

    fn open(n: f64) -> CSpace {
        let g = Grid::over([[0.0, n], [0.0, n], [0.0, n]], 1.0);
        CSpace::from_fn(g, |_| true)
    }

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

    /// Random codes: free or blocked, and free nodes with or without a "look" bit (0x40, like
    /// the tool-near bit); a graph that refuses a third of the nodes with the bit, pseudo-
    /// randomly, and accepts every other free node. The row wave that numbers the nodes without
    /// the bit from the grid's row bit set (`look_bits` `Some(0x40)`) and the one that looks at
    /// every node (`None`) give every node below the end's number its breadth-first distance
    /// over the usable nodes. A graph that wrongly says its answer needs no bits
    /// (`Some(0)`) numbers refused nodes, and the same check catches it.
    #[test]
    fn row_wave_from_the_row_bits_numbers_like_the_look_at_every_node() {
        use crate::plan::search::testing::hash;
        struct Codes;
        impl crate::plan::cspace::Inspector for Codes {
            fn inspect_column(&self, a1: f64, a2: f64, a3: &[f64], code: &mut [u8], _: &mut [u8]) {
                for (c, &z) in code.iter_mut().zip(a3) {
                    let h = hash([a1 as i32, a2 as i32, z as i32], 1);
                    *c = if h % 5 == 0 {
                        0
                    } else {
                        FREE | (h >> 8) as u8 & 0x7f
                    };
                }
            }
        }
        struct Tool<'a>(&'a CSpace, Option<u8>);
        impl Graph for Tool<'_> {
            fn node_ok(&self, n: Node) -> bool {
                self.node_ok_coded(n, self.0.code(n))
            }
            fn node_ok_coded(&self, n: Node, code: u8) -> bool {
                code & 0x40 == 0 || hash(n, 2) % 3 != 0
            }
            fn step_ok(&self, _: Node, _: Node) -> bool {
                true
            }
            fn wave_steps_all(&self) -> bool {
                true
            }
            fn look_bits(&self) -> Option<u8> {
                self.1
            }
        }
        // 128 nodes along axis 3: two whole words a row; 130: three words, the last partly
        // used (the row words a constant); 450: eight words (their number read at run time).
        for d2 in [128usize, 130, 450] {
            let g = Grid::over([[0.0, 19.0], [0.0, 15.0], [0.0, (d2 - 1) as f64]], 1.0);
            let cs = CSpace::build(g, &Codes);
            let looked = (0..g.len())
                .filter(|&i| cs.code_index(i) & (FREE | 0x40) == FREE | 0x40)
                .count();
            assert!(looked > g.len() / 4, "too few nodes with the bit: {looked}");
            let usable = |n: Node| cs.is_free(n) && Tool(&cs, None).node_ok(n);
            let start = (0..g.len())
                .map(|i| g.node(i))
                .find(|&n| usable(n))
                .expect("a start");
            let dist = bfs(&g, start, usable);
            let (far, mid) = far_and_middle(&dist);
            // The labels below n against the distances: how many disagree.
            let wrong = |w: &Wave, n: u32| {
                let labels = numbers(w);
                (0..g.len())
                    .filter(|&i| {
                        let l = labels[i];
                        if dist[i] < n {
                            l != dist[i]
                        } else {
                            !(l == 0 || (l == n && dist[i] == n))
                        }
                    })
                    .count()
            };
            for end in [far, mid] {
                let n = dist[end];
                assert!(n > 10, "too near to test: {n}");
                for bits in [Some(0x40), None] {
                    let w = expand(
                        &cs,
                        &Tool(&cs, bits),
                        start,
                        g.node(end),
                        Connectivity::TwentySix,
                    )
                    .expect("joined");
                    assert_eq!(w.n(), n, "{bits:?}");
                    assert_eq!(wrong(&w, n), 0, "{bits:?}");
                }
                let lying = expand(
                    &cs,
                    &Tool(&cs, Some(0)),
                    start,
                    g.node(end),
                    Connectivity::TwentySix,
                );
                assert!(lying.is_none_or(|w| w.n() != n || wrong(&w, n) > 0));
            }
        }
    }

    /// Long rows (200 nodes: 4 words a row, the last partly used; 700: 11 words, their
    /// number read at run time) between slabs across axis 3 pierced by two holes, a block whose
    /// faces lie on a word border (axis 3 from 64 to 127) and scattered blocked nodes: inside,
    /// the row wave's front is mostly rows' two ends, spread across word borders (bits 63 and
    /// 64) and into the rows along the grid's borders. Several waves in a row over the same
    /// grid (from the middle, from two corners, each to its farthest node and to a middle one)
    /// give every node below the end's number its breadth-first distance and number nothing
    /// else below it (the residues of every level, up to some hundreds of levels).
    #[test]
    fn row_wave_over_long_rows_numbers_the_breadth_first_distances() {
        fn hash(n: Node) -> u32 {
            let h = (n[0] as u32).wrapping_mul(73_856_093)
                ^ (n[1] as u32).wrapping_mul(19_349_663)
                ^ (n[2] as u32).wrapping_mul(83_492_791);
            h.wrapping_mul(2_654_435_761) >> 9
        }
        for d2 in [200i32, 700] {
            let g = Grid::over([[0.0, 10.0], [0.0, 8.0], [0.0, (d2 - 1) as f64]], 1.0);
            let free = |n: Node| {
                let slab = n[2] % 50 == 37 && n != [2, 7, n[2]] && n != [9, 1, n[2]];
                let block = (64..128).contains(&n[2]) && (3..=7).contains(&n[0]) && n[1] >= 2;
                !slab && !block && hash(n) % 13 != 0
            };
            let cs = CSpace::from_fn(g, free);
            for near in [[5, 4, 100], [0, 0, 0], [10, 8, d2 - 5]] {
                let start = (g.index(near)..g.len())
                    .map(|i| g.node(i))
                    .find(|&n| free(n))
                    .expect("a free node");
                let dist = bfs(&g, start, free);
                let (far, mid) = far_and_middle(&dist);
                for end in [far, mid] {
                    let n = dist[end];
                    assert!(n > 20, "too near to test: {n}");
                    let w = expand(&cs, &Open, start, g.node(end), Connectivity::TwentySix)
                        .expect("joined");
                    assert_labels_are_distances(&w, &g, &dist, n, &format!("from {start:?}"));
                }
            }
        }
    }

    /// Waves one after another over the same grid: one that numbers the whole grid, then short
    /// ones from two corners, which number nothing past their end's level and every node below
    /// it its Chebyshev distance plus one.
    #[test]
    fn short_waves_after_a_long_one_number_the_chebyshev_distances() {
        let cs = open_dims(13, 11, 70);
        let far = expand(&cs, &Open, [0, 0, 0], [13, 11, 70], Connectivity::TwentySix);
        assert_eq!(far.map(|w| w.numbered()), Some(cs.grid.len()));
        for (start, end) in [([0, 0, 0], [2, 1, 1]), ([13, 11, 70], [11, 11, 69])] {
            let w = expand(&cs, &Open, start, end, Connectivity::TwentySix).expect("open");
            let n = w.n();
            let labels = numbers(&w);
            for (i, &l) in labels.iter().enumerate() {
                let m = cs.grid.node(i);
                let d = (0..3).map(|k| (m[k] - start[k]).abs()).max().unwrap_or(0) as u32 + 1;
                if d < n {
                    assert_eq!(l, d, "{m:?}");
                } else {
                    assert!(l == 0 || (l == n && d == n), "{m:?}: {l}");
                }
            }
        }
    }

    fn open_dims(a: usize, b: usize, c: usize) -> CSpace {
        let g = Grid::over([[0.0, a as f64], [0.0, b as f64], [0.0, c as f64]], 1.0);
        CSpace::from_fn(g, |_| true)
    }

    /// The wave numbers its end `n` (the end's breadth-first distance plus one, from `dist`),
    /// every node below it its distance, and nothing else below it (a node as far as the end
    /// may be numbered or not): the numbers rebuilt from what the wave keeps ([`numbers`]), and
    /// each node's neighbours read from its distance ([`Wave::label_next_to`]) by every node
    /// the wave numbered.
    fn assert_labels_are_distances(w: &Wave, g: &Grid, dist: &[u32], n: u32, what: &str) {
        assert_eq!(w.n(), n, "{what}");
        let ok = |d: u32, l: u32| {
            if d < n {
                l == d
            } else {
                l == 0 || (l == n && d == n)
            }
        };
        let labels = numbers(w);
        for (i, &d) in dist.iter().enumerate() {
            let (m, l) = (g.node(i), labels[i]);
            assert!(ok(d, l), "{m:?}: {l}, distance {d} {what}");
            if l == 0 {
                continue;
            }
            for o in offsets(Connectivity::TwentySix) {
                let k = [m[0] + o[0], m[1] + o[1], m[2] + o[2]];
                let dk = if g.contains(k) { dist[g.index(k)] } else { 0 };
                let lk = w.label_next_to(k, d);
                assert!(
                    ok(dk, lk),
                    "{k:?} next to {m:?}: {lk}, distance {dk} {what}"
                );
            }
        }
    }

    /// The wave's numbers by linear index, rebuilt from what it keeps: breadth-first from its
    /// start (1) over the nodes it numbered and their 26 neighbours, each node's number read
    /// from the node that first reaches it ([`Wave::label_next_to`]). Numbers (a node-by-node
    /// wave) come back as they are; residues (the row wave) give the numbers only where every
    /// level's residue is right. Every numbered node's numbered neighbours must read as their
    /// rebuilt numbers from it (else a panic).
    fn numbers(w: &Wave) -> Vec<u32> {
        let [d0, d1, d2] = w.dims;
        let g = Grid::over(
            [
                [0.0, (d0 - 1) as f64],
                [0.0, (d1 - 1) as f64],
                [0.0, (d2 - 1) as f64],
            ],
            1.0,
        );
        assert_eq!(g.dims, w.dims);
        let mut out = vec![0u32; g.len()];
        out[g.index(w.start)] = 1;
        let mut queue = VecDeque::from([w.start]);
        while let Some(m) = queue.pop_front() {
            let l = out[g.index(m)];
            for o in offsets(Connectivity::TwentySix) {
                let k = [m[0] + o[0], m[1] + o[1], m[2] + o[2]];
                let lk = w.label_next_to(k, l);
                if lk == 0 {
                    continue;
                }
                let i = g.index(k);
                if out[i] == 0 && k != w.start {
                    out[i] = lk;
                    queue.push_back(k);
                }
                assert_eq!(lk, out[i], "{k:?} read from {m:?} numbered {l}");
            }
        }
        assert_eq!(
            out.iter().filter(|&&l| l > 0).count(),
            w.numbered(),
            "numbered nodes not reached from the start"
        );
        out
    }

    /// The two waves numbered together (`expand_both`, and `expand_corridor`'s one) hold
    /// exactly the nodes on shortest paths between the ends (distance from the start plus
    /// distance from the end equal to the ends' distance, by two plain breadth-first counts),
    /// each with the residue code of its distance from its own start, read straight from the
    /// planes (no other bit set anywhere); they exist exactly when the whole waves do; a walk
    /// back over either (extensile's and neighboring's candidates) takes the same steps as over
    /// the whole wave, and the extensile search equals its reference on whole waves. On thin and
    /// flat grids, rows of 1 to 11 words (every `K`, partial last words), scattered blocked
    /// and refused nodes and refused steps, from random starts to themselves, a neighbour, any
    /// node and any usable node.
    #[test]
    fn both_waves_hold_the_shortest_paths_and_walk_like_the_whole_waves() {
        use crate::plan::search::testing::{hash, xorshift, Refusing};
        use crate::plan::search::{depth_first, descend, extensile, neighboring, Candidates};
        let mut sequence = xorshift(0x9e37_79b9_7f4a_7c15);
        let mut next = move || sequence() as usize;
        let shapes: [[usize; 3]; 20] = [
            [1, 1, 1],
            [1, 1, 2],
            [1, 1, 70],
            [1, 1, 700],
            [40, 1, 1],
            [1, 40, 1],
            [2, 1, 1],
            [3, 3, 700],
            [2, 2, 257],
            [2, 3, 576],
            [3, 2, 384],
            [4, 3, 64],
            [5, 4, 128],
            [6, 5, 65],
            [9, 7, 3],
            [12, 11, 130],
            [8, 8, 200],
            [1, 30, 30],
            [30, 30, 1],
            [3, 40, 63],
        ];
        let (mut joined, mut joined_six, mut corridor_nodes, mut walks) = (0, 0, 0, 0);
        for round in 0..6u32 {
            for [a, b, c] in shapes {
                let g = Grid::over(
                    [
                        [0.0, (a - 1) as f64],
                        [0.0, (b - 1) as f64],
                        [0.0, (c - 1) as f64],
                    ],
                    1.0,
                );
                let density = [0, 2, 3, 4][round as usize % 4];
                let salt = round * 31 + (a * 7 + b * 13 + c) as u32;
                let cs =
                    CSpace::from_fn(g, |n| density == 0 || hash(n, salt + 100) % 10 >= density);
                for steps in [false, true] {
                    let graph = Refusing {
                        salt,
                        every: 6,
                        steps,
                    };
                    let usable = |n: Node| cs.is_free(n) && graph.node_ok(n);
                    let us: Vec<usize> = (0..g.len()).filter(|&i| usable(g.node(i))).collect();
                    if us.is_empty() {
                        continue;
                    }
                    for t in 0..8 {
                        let start = g.node(us[next() % us.len()]);
                        let end = match t {
                            0 => start,
                            1 => {
                                let o = offsets(Connectivity::TwentySix)[next() % 26];
                                let m = [start[0] + o[0], start[1] + o[1], start[2] + o[2]];
                                if !g.contains(m) {
                                    continue;
                                }
                                m
                            }
                            2 => g.node(next() % g.len()),
                            _ => g.node(us[next() % us.len()]),
                        };
                        let what = format!("{:?} {density} {steps} {start:?} -> {end:?}", g.dims);
                        // The axis-step wave (the depth-first search's) first.
                        let whole6 = expand(&cs, &graph, start, end, Connectivity::Six);
                        let f6 = expand_corridor(&cs, &graph, start, end, Connectivity::Six);
                        assert_eq!(whole6.is_some(), f6.is_some(), "six: {what}");
                        if let (Some(whole6), Some(f6)) = (whole6, f6) {
                            let ds = bfs_over(&g, start, usable, Connectivity::Six);
                            let de = bfs_over(&g, end, usable, Connectivity::Six);
                            joined_six += 1;
                            assert_corridor(&g, &f6, &whole6, &ds, &de, &format!("six: {what}"));
                            let path = descend(&f6, &depth_first::candidates, &graph);
                            assert_eq!(
                                path,
                                descend(&whole6, &depth_first::candidates, &graph),
                                "six: {what}"
                            );
                            walks += usize::from(path.is_some());
                        }
                        let whole = |a, b| expand(&cs, &graph, a, b, Connectivity::TwentySix);
                        let (there, back) = (whole(start, end), whole(end, start));
                        let (fs, fe) = expand_both(&cs, &graph, start, end);
                        let fc = expand_corridor(&cs, &graph, start, end, Connectivity::TwentySix);
                        assert_eq!(there.is_some(), fs.is_some(), "{what}");
                        assert_eq!(back.is_some(), fe.is_some(), "{what}");
                        assert_eq!(there.is_some(), fc.is_some(), "{what}");
                        let (Some(there), Some(back), Some(fs), Some(fe), Some(fc)) =
                            (there, back, fs, fe, fc)
                        else {
                            continue;
                        };
                        joined += 1;
                        let (ds, de) = (bfs(&g, start, usable), bfs(&g, end, usable));
                        for (w, from, to, whole) in [
                            (&fs, &ds, &de, &there),
                            (&fe, &de, &ds, &back),
                            (&fc, &ds, &de, &there),
                        ] {
                            corridor_nodes += assert_corridor(&g, w, whole, from, to, &what);
                            let orders: [&Candidates; 2] =
                                [&extensile::candidates, &neighboring::candidates];
                            for c in orders {
                                let path = descend(w, c, &graph);
                                assert_eq!(path, descend(whole, c, &graph), "{what}");
                                walks += usize::from(path.is_some());
                            }
                        }
                        assert_eq!(
                            extensile::search(&cs, start, end, &graph),
                            extensile::search_with_whole_waves(&cs, start, end, &graph),
                            "{what}"
                        );
                    }
                }
            }
        }
        assert!(
            joined_six > 300,
            "too few axis-step cases: {joined_six} joined"
        );
        assert!(
            joined > 500 && corridor_nodes > 20_000 && walks > 1000,
            "too few cases: {joined} joined, {corridor_nodes} corridor nodes, {walks} walks"
        );
    }

    /// `expand_both` of a node with itself numbers it alone; of ends that are not joined (or
    /// not usable), neither wave; over a graph whose wave does not count every step, both
    /// waves whole (`expand`'s numbers).
    #[test]
    fn both_waves_of_one_node_of_parted_ends_and_of_a_stepwise_graph() {
        let cs = open(12.0);
        let (fs, fe) = expand_both(&cs, &Open, [3, 4, 5], [3, 4, 5]);
        for w in [fs.expect("itself"), fe.expect("itself")] {
            assert_eq!((w.n(), w.numbered()), (1, 1));
            assert_eq!(w.label_next_to([3, 4, 5], 2), 1);
        }
        let walled = CSpace::from_fn(cs.grid, |n| n[0] != 6);
        let (fs, fe) = expand_both(&walled, &Open, [0, 0, 0], [12, 12, 12]);
        assert!(fs.is_none() && fe.is_none());
        let (fs, fe) = expand_both(&walled, &Open, [0, 0, 0], [6, 0, 0]);
        assert!(fs.is_none() && fe.is_none());
        // A closure graph counts only the steps it accepts: whole waves, numbered node by node.
        let stepwise = |_: Node, _: Node| true;
        let (a, b) = ([0, 0, 0], [9, 4, 7]);
        let (fs, fe) = expand_both(&cs, &stepwise, a, b);
        let whole = |a, b| expand(&cs, &stepwise, a, b, Connectivity::TwentySix).expect("joined");
        for (w, whole) in [
            (fs.expect("joined"), whole(a, b)),
            (fe.expect("joined"), whole(b, a)),
        ] {
            assert_eq!(w.numbered(), whole.numbered());
            assert_eq!(numbers(&w), numbers(&whole));
        }
        // Over the open graph: fewer nodes, the same n.
        let (fs, _) = expand_both(&cs, &Open, a, b);
        let (fs, whole) = (fs.expect("joined"), whole(a, b));
        assert_eq!(fs.n(), whole.n());
        assert!(fs.numbered() < whole.numbered());
    }

    /// The bounded corridor waves (`corridor_rows`): ends a wall apart, so the first bounds
    /// (from their grid distance) leave the way round out and the waves are numbered again,
    /// and ends close on either side of the wall. Both corridors are exactly the nodes on
    /// shortest paths with their distances (two plain breadth-first counts), on both sides,
    /// over 26 and over 6 neighbours; ends the wall parts have no corridor (this fails when a
    /// wave that ran out having left nodes out is taken for parted ends). `within` is the box
    /// of nodes within `r` of a node, bit by bit. In the open the bounded waves number only
    /// nodes between the ends (this fails with no bound). (Waves that meet past the bound must be
    /// numbered again: the random grids of the test above fail when they are not, and when
    /// the bound is one step too tight.)
    #[test]
    fn bounded_corridor_waves_are_numbered_again_until_they_meet_within_the_bound() {
        let g = Grid::over([[0.0, 23.0], [0.0, 19.0], [0.0, 69.0]], 1.0);
        // A wall at x = 11 and 12 open only at y >= 17, and a pillar.
        let usable = |n: Node| !((n[0] == 11 || n[0] == 12) && n[1] < 17) && n != [5, 8, 30];
        let cs = CSpace::from_fn(g, usable);
        for (a, b) in [
            ([3, 2, 30], [20, 2, 33]),
            ([10, 0, 30], [13, 1, 30]),
            ([10, 3, 25], [13, 3, 40]),
        ] {
            for connectivity in [Connectivity::TwentySix, Connectivity::Six] {
                let what = format!("{a:?} -> {b:?} over {connectivity:?}");
                let from = bfs_over(&g, a, usable, connectivity);
                let to = bfs_over(&g, b, usable, connectivity);
                let d = from[g.index(b)] - 1;
                let grid = (0..3).map(|k| (a[k] - b[k]).unsigned_abs()).max();
                assert!(Some(d) > grid, "no detour: {what}");
                let (fs, fe) = corridor_waves(&cs, &Open, a, b, connectivity).expect(&what);
                let whole = |a, b| expand(&cs, &Open, a, b, connectivity).expect("joined");
                assert_corridor(&g, &fs, &whole(a, b), &from, &to, &what);
                assert_corridor(&g, &fe, &whole(b, a), &to, &from, &what);
            }
        }
        let parted = CSpace::from_fn(g, |n| n[0] != 11);
        for connectivity in [Connectivity::TwentySix, Connectivity::Six] {
            let none = corridor_waves(&parted, &Open, [3, 2, 30], [20, 2, 33], connectivity);
            assert!(none.is_none(), "{connectivity:?}");
        }
        // In the open the first bound is the ends' distance: neither wave numbers a node off
        // `cheb(s, x) + cheb(x, e) <= D` (counted here node by node; a node both number counts
        // twice), far fewer than the two half balls the unbounded waves numbered.
        let open = CSpace::from_fn(g, |_| true);
        let (a, b) = ([2, 3, 10], [21, 9, 30]);
        let cheb = |p: Node, q: Node| (0..3).map(|k| (p[k] - q[k]).abs()).max().unwrap_or(0);
        let d = cheb(a, b);
        let between = (0..g.len())
            .filter(|&i| cheb(a, g.node(i)) + cheb(g.node(i), b) <= d)
            .count() as u64;
        let half_balls = (0..g.len())
            .filter(|&i| cheb(a, g.node(i)) <= d / 2 || cheb(g.node(i), b) <= d / 2)
            .count() as u64;
        let before = ROW_NUMBERED.with(|c| c.get());
        corridor_waves(&open, &Open, a, b, Connectivity::TwentySix).expect("open");
        let numbered = ROW_NUMBERED.with(|c| c.get()) - before;
        assert!(
            numbered <= 2 * between && 4 * numbered < half_balls,
            "{numbered} numbered, {between} between the ends, {half_balls} in the half balls"
        );
        for (to, r) in [
            ([5i64, 6, 70], 9i64),
            ([0, 0, 3], 0),
            ([2, 2, 130], 64),
            ([1, 1, 1], -1),
        ] {
            for (i0, i1) in [(5i64, 6i64), (0, 0), (14, 6), (15, 6), (2, 11)] {
                for j in 0..4 {
                    let want = (0..64).fold(0u64, |m, b| {
                        let z = 64 * j as i64 + b;
                        let near = [i0 - to[0], i1 - to[1], z - to[2]]
                            .iter()
                            .all(|v| v.abs() <= r);
                        m | u64::from(near) << b
                    });
                    assert_eq!(within(to, r, i0, i1, j), want, "{to:?} {r} {i0} {i1} {j}");
                }
            }
        }
    }

    /// The farthest node reached (the last by index) and the first node half as far.
    fn far_and_middle(dist: &[u32]) -> (usize, usize) {
        let far = (0..dist.len())
            .max_by_key(|&i| (dist[i], i))
            .expect("nodes");
        let mid = (0..dist.len())
            .find(|&i| dist[i] == dist[far] / 2)
            .expect("a middle");
        (far, mid)
    }

    /// That the corridor wave `w` holds exactly the nodes on shortest paths between its ends
    /// (`from` and `to`: the breadth-first distances plus one from its start and its end), each
    /// with the residue code of its number in `from`, read straight from its planes, with no
    /// other bit set anywhere (past a row's last node either), and the same ends and n as the
    /// whole wave: the corridor's size.
    fn assert_corridor(
        g: &Grid,
        w: &Wave,
        whole: &Wave,
        from: &[u32],
        to: &[u32],
        what: &str,
    ) -> usize {
        let n = from[g.index(w.end)];
        assert_eq!((w.n(), whole.n()), (n, n), "{what}");
        assert_eq!((w.start, w.end), (whole.start, whole.end), "{what}");
        assert_eq!(w.connectivity, whole.connectivity, "{what}");
        let on = |i: usize| from[i] > 0 && to[i] > 0 && from[i] + to[i] == n + 1;
        let Labels::Residues { planes, words } = &w.labels else {
            panic!("not a row wave: {what}");
        };
        for (i, &d) in from.iter().enumerate() {
            let want = if on(i) { residue_code(d) } else { 0 };
            let [x, y, z] = g.node(i);
            let word = (x as usize * g.dims[1] + y as usize) * words + z as usize / 64;
            let bit = z as usize % 64;
            let code = ((planes[2 * word] >> bit) & 1) | (((planes[2 * word + 1] >> bit) & 1) << 1);
            assert_eq!(code as u32, want, "{:?}: {what}", g.node(i));
        }
        let corridor = (0..g.len()).filter(|&i| on(i)).count();
        let set: usize = planes
            .chunks_exact(2)
            .map(|p| (p[0] | p[1]).count_ones() as usize)
            .sum();
        assert_eq!(set, corridor, "{what}");
        corridor
    }

    /// Breadth-first distances (plus one, 0 = not reached) over the usable nodes of `g` and
    /// their 26 neighbours, from `start`.
    fn bfs(g: &Grid, start: Node, usable: impl Fn(Node) -> bool) -> Vec<u32> {
        bfs_over(g, start, usable, Connectivity::TwentySix)
    }

    /// [`bfs`] over the neighbours of `connectivity`.
    fn bfs_over(
        g: &Grid,
        start: Node,
        usable: impl Fn(Node) -> bool,
        connectivity: Connectivity,
    ) -> Vec<u32> {
        let mut dist = vec![0u32; g.len()];
        dist[g.index(start)] = 1;
        let mut queue = VecDeque::from([start]);
        while let Some(n) = queue.pop_front() {
            for o in offsets(connectivity) {
                let m = [n[0] + o[0], n[1] + o[1], n[2] + o[2]];
                if g.contains(m) && usable(m) && dist[g.index(m)] == 0 {
                    dist[g.index(m)] = dist[g.index(n)] + 1;
                    queue.push_back(m);
                }
            }
        }
        dist
    }

    /// A serpentine corridor over 80 000 steps long: the node-by-node wave's numbers outgrow
    /// the 16-bit words and it is numbered again in 32 bits; the row wave's residues have no
    /// such limit. n and every label of both agree with a plain breadth-first count.
    #[test]
    fn a_path_longer_than_the_narrow_words_is_numbered_in_wide_ones() {
        let (w, h) = (400usize, 401usize);
        let g = Grid::over(
            [[0.0, (w - 1) as f64], [0.0, (h - 1) as f64], [0.0, 0.0]],
            1.0,
        );
        // Even rows free; odd row y open at one end only, alternating sides.
        let free =
            |x: i32, y: i32| y % 2 == 0 || x == if (y / 2) % 2 == 0 { w as i32 - 1 } else { 0 };
        let cs = CSpace::from_fn(g, |n| free(n[0], n[1]));
        let end = [
            if ((h - 1) / 2) % 2 == 0 {
                w as i32 - 1
            } else {
                0
            },
            h as i32 - 1,
            0,
        ];
        // Every step (the row wave) and a graph that does not say so (node by node).
        let rows = expand(&cs, &Open, [0, 0, 0], end, Connectivity::TwentySix).expect("joined");
        assert!(matches!(rows.labels, Labels::Residues { .. }));
        let all = |_: Node, _: Node| true;
        let wave = expand(&cs, &all, [0, 0, 0], end, Connectivity::TwentySix).expect("joined");
        assert!(matches!(wave.labels, Labels::Wide(_)));
        // The reference: breadth-first over the same 8-neighbourhood in the plane.
        let mut dist = vec![0u32; w * h];
        let mut queue = VecDeque::from([(0i32, 0i32)]);
        dist[0] = 1;
        while let Some((x, y)) = queue.pop_front() {
            for dx in -1..=1 {
                for dy in -1..=1 {
                    let (a, b) = (x + dx, y + dy);
                    if (a, b) == (x, y) || a < 0 || b < 0 || a >= w as i32 || b >= h as i32 {
                        continue;
                    }
                    let i = b as usize * w + a as usize;
                    if free(a, b) && dist[i] == 0 {
                        dist[i] = dist[y as usize * w + x as usize] + 1;
                        queue.push_back((a, b));
                    }
                }
            }
        }
        let n = dist[end[1] as usize * w + end[0] as usize];
        assert!(
            n > u16::MAX as u32,
            "the corridor is too short to test: {n}"
        );
        // The distances by the grid's linear index.
        let by_index: Vec<u32> = (0..g.len())
            .map(|i| {
                let m = g.node(i);
                dist[m[1] as usize * w + m[0] as usize]
            })
            .collect();
        for wave in [&rows, &wave] {
            assert_labels_are_distances(wave, &g, &by_index, n, "corridor");
        }
        // A short wave stays in narrow words.
        let short = expand(&cs, &all, [0, 0, 0], [9, 0, 0], Connectivity::TwentySix);
        assert!(matches!(short.map(|w| w.labels), Some(Labels::Narrow(_))));
    }

    /// The exact limit: an end numbered 65 533 stays in 16-bit words, one node further goes wide.
    #[test]
    fn the_narrow_words_hold_up_to_65533_exactly() {
        for (last, wide) in [(65_532.0, false), (65_533.0, true)] {
            let g = Grid::over([[0.0, last], [0.0, 0.0], [0.0, 0.0]], 1.0);
            let cs = CSpace::from_fn(g, |_| true);
            let end = [last as i32, 0, 0];
            let w = expand(&cs, &Open, [0, 0, 0], end, Connectivity::Six).expect("a line");
            assert_eq!(w.n(), last as u32 + 1);
            assert_eq!(matches!(w.labels, Labels::Wide(_)), wide, "end at {last}");
            assert_eq!(numbers(&w)[1000], 1001);
        }
    }
}
