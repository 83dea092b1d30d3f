//! The row wave (beyond the paper, for speed only): the 26-neighbour wave over a graph whose
//! every step between usable nodes counts, numbered a level at a time on bit sets of axis-3
//! rows. The row wave
//! spreads only the front's words that hold front nodes (inside a wide front a row's new nodes
//! are its two ends, so its other words are not spread again level after level), and finds the
//! next candidates by groups of rows marked, in ascending order (no list of touched rows). In
//! the row wave, the free nodes a graph need not look at ([`Graph::look_bits`]: for a leg, those
//! whose code says the tool stays clear) come a word at a time from the grid's row words
//! ([`Row::plain`](crate::plan::cspace::Row::plain)). Before each level the wave asks the grid
//! for the blocks around its front ([`CSpace::inspect_around`]): the grid is inspected as the
//! wave reaches it. The row wave keeps no numbers: it keeps each numbered node's number
//! modulo 3 in two bit planes (2 bits a node, written a word at a time per level), which is all
//! a walk back needs. A walk knows the number of the node it stands on (it starts at the end,
//! numbered n), and in this wave every step between numbered nodes is a wave step, so a
//! numbered neighbour's number is one less, the same or one more: the residue tells which
//! ([`Wave::label_next_to`](super::Wave::label_next_to)).

use super::reach::Reach;
use super::{label_word, residue_code, Graph, Labels};
use crate::plan::cspace::{CSpace, Node, FREE};
use crate::zeroed::ZeroBuf;

/// The expansion for 26 neighbours over a graph whose every step between usable nodes is a
/// wave step ([`Graph::wave_steps_all`]), level by level on bit sets of axis-3 rows (a row: the
/// nodes of fixed axes 1 and 2, one bit each, axis-3 index `64 j + b` at bit `b` of word `j`).
/// The nodes next numbered are the front's neighbours ([`Reach`]) not yet decided; each of
/// those is looked at once (free on the grid, [`Graph::node_ok_coded`]) and numbered or decided
/// unusable. A level's new nodes are labelled a word at a time, OR-ed into the residue planes
/// its number's residue code picks ([`Labels::Residues`]: 2 bits a node, no node written one by
/// one, nothing to clear and no number too long), so a level costs a few word operations per
/// front word and per row it reaches, and one look per node it numbers. When the graph names
/// the code bits its answer depends on ([`Graph::look_bits`]) and the grid keeps its row words
/// for those bits ([`CSpace::kept_bits`]), the free nodes without them come a word at a time
/// from the row words: numbered without a look; only the other candidates (blocked, or with
/// those bits) are looked at one by one. No node past the end in the end's word is
/// looked at. `K`: the words a row, or 0 for any number. Returns the labels and the end's
/// number, `None` when the end cannot be reached.
pub(super) fn number_rows<G: Graph + ?Sized, const K: usize>(
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
pub(super) enum Level {
    /// The end node was numbered (the level was left there).
    End,
    /// The level was numbered whole.
    Numbered,
    /// Nothing was left to number: the front was empty.
    Exhausted,
}

/// A row wave between levels ([`number_rows`], [`corridor_rows`](super::corridor::corridor_rows)).
pub(super) struct RowWave<'a, G: Graph + ?Sized, const K: usize> {
    cs: &'a CSpace,
    graph: &'a G,
    pub(super) reach: Reach<K>,
    /// Whether the grid's row words ([`Row::plain`](crate::plan::cspace::Row::plain)) are the
    /// free nodes usable without a look.
    plain: bool,
    /// The bits of a row's last word that are nodes.
    last_mask: u64,
    /// The end's word, its bit, and its bits up to the end's (no end: a word past the grid).
    end_word: usize,
    end_bit: u64,
    upto_end: u64,
    /// The residue planes.
    pub(super) planes: ZeroBuf<u64>,
    /// Decided nodes: numbered, not free, or not usable.
    pub(super) decided: ZeroBuf<u64>,
    /// The front: its words that hold front nodes, as (row word index, the front's bits), by
    /// ascending index.
    pub(super) front: Vec<(usize, u64)>,
    next_front: Vec<(usize, u64)>,
    /// The number of the last level numbered (below `MAX_NODES`, a `u32`).
    pub(super) level: u32,
    /// The bound of a corridor wave ([`corridor_rows`](super::corridor::corridor_rows)): the
    /// other end's node (grid indices) and the most steps a path between the ends may take; a
    /// node farther from the start than that less its grid distance (steps ignoring obstacles,
    /// the largest index difference) to the other end is left out. `None`: every node counts.
    bound: Option<([i64; 3], i64)>,
    /// A node was left out by the bound.
    pub(super) pruned: bool,
    /// The end was numbered ([`Level::End`]).
    ended: bool,
}

impl<'a, G: Graph + ?Sized, const K: usize> RowWave<'a, G, K> {
    /// The wave with its start (linear index) numbered 1; `end` the linear index at which it
    /// stops, if any; over the 6 axis neighbours when `six`, else the 26.
    pub(super) fn new(
        cs: &'a CSpace,
        graph: &'a G,
        start: usize,
        end: Option<usize>,
        six: bool,
    ) -> Self {
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
        let plain = graph.look_bits().is_some() && graph.look_bits() == cs.kept_bits();
        RowWave {
            cs,
            graph,
            reach,
            plain,
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
    pub(super) fn bounded(mut self, to: Node, steps: i64) -> Self {
        self.bound = Some((to.map(i64::from), steps));
        self
    }

    pub(super) fn labels(self) -> Labels {
        Labels::Residues {
            planes: self.planes,
            words: self.reach.words,
        }
    }

    /// Numbers the next level: the front's neighbours not decided yet, looked at by ascending
    /// row, numbered when usable; they become the front. After [`Level::End`] the wave is left
    /// mid-level (its gathered words not cleared): it must not be asked for another.
    pub(super) fn next_level(&mut self) -> Level {
        debug_assert!(!self.ended, "a row wave asked for a level past its end");
        let (Some(&(first, _)), Some(&(last, _))) = (self.front.first(), self.front.last()) else {
            return Level::Exhausted;
        };
        let next = self.level + 1;
        let rc = residue_code(next);
        self.reach.spread(&self.front);
        let (cs, graph) = (self.cs, self.graph);
        let d1 = cs.grid.dims[1];
        let words = self.reach.words;
        let plain = self.plain;
        let (last_mask, end_word, end_bit, upto_end) =
            (self.last_mask, self.end_word, self.end_bit, self.upto_end);
        let (decided, planes, next_front) =
            (&mut self.decided, &mut self.planes, &mut self.next_front);
        // The bound: nodes numbered `next` lie `next - 1` steps from the start, so those kept
        // lie within `r` of the other end on every axis.
        let keep = self
            .bound
            .map(|(to, steps)| (to, steps - i64::from(next - 1)));
        // The blocks this level reads, inspected together (on all cores when there are several).
        cs.inspect_around(
            self.front
                .iter()
                .map(|&(w, bits)| (w / words, w % words, bits)),
            keep,
        );
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
            let row = cs.row_word(t, j, c);
            // The usable candidates: the plain ones at once, the others looked at.
            let (mut numbered, mut look) = if plain {
                (c & row.plain, c & !row.plain)
            } else {
                (0, c)
            };
            while look != 0 {
                let b = look.trailing_zeros() as usize;
                look &= look - 1;
                let code = row.code(b);
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
    pub(super) fn numbered(&self, w: usize) -> u64 {
        self.planes[2 * w] | self.planes[2 * w + 1]
    }
}

/// The bits of word `j` of row `(i0, i1)` whose nodes lie within `r` of node `to` on every axis
/// (grid indices): all or none by the row, a run of bits by axis 3.
#[inline]
pub(super) fn within(to: [i64; 3], r: i64, i0: i64, i1: i64, j: usize) -> u64 {
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

#[cfg(test)]
thread_local! {
    /// The nodes this thread's row waves numbered (for tests of the bound).
    pub(super) static ROW_NUMBERED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

#[cfg(test)]
mod tests {
    use super::super::testing::*;
    use super::super::{expand, Connectivity, Open, Wave};
    use super::*;
    use crate::plan::cspace::Grid;

    /// Random codes: free or blocked, and free nodes with or without a "look" bit (0x40, like
    /// the tool-near bit); a graph that refuses a third of the nodes with the bit, pseudo-
    /// randomly, and accepts every other free node. The row wave that numbers the nodes without
    /// the bit from the grid's row words (`look_bits` `Some(0x40)`, the bits the grid keeps)
    /// and the one that looks at every node (`None`) give every node below the end's number its
    /// breadth-first distance over the usable nodes. A graph that wrongly says its answer needs
    /// no bits (`Some(0)`, on a grid keeping the row words of every free node) numbers refused
    /// nodes, and the same check catches it.
    #[test]
    fn row_wave_from_the_row_bits_numbers_like_the_look_at_every_node() {
        use crate::plan::search::testing::hash;
        /// The codes, with the row words of the bits given kept.
        struct Codes(Option<u8>);
        impl crate::plan::cspace::Inspector for Codes {
            fn row_bits_ahead(&self) -> Option<u8> {
                self.0
            }
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
            let cs = CSpace::build(g, &Codes(Some(0x40)));
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
                // The row words of every free node kept, and a graph that says none needs a
                // look.
                let all = CSpace::build(g, &Codes(Some(0)));
                let lying = expand(
                    &all,
                    &Tool(&all, Some(0)),
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
}
