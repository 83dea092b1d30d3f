//! The neighbours of a row wave's level: the front's row words spread over the 3 x 3 rows
//! around (or the axis neighbours), gathered and taken back by ascending row.

use crate::zeroed::ZeroBuf;

/// The rows of the row wave's candidates marked together (one bit a group; a group's scan also
/// reads the row just below and just above it, so a front word marks one group a plane of rows).
const GROUP_ROWS: usize = 4;
const _: () = assert!(GROUP_ROWS >= 2, "the row wave's front stays ascending");

/// The neighbours of a set of row words, gathered a level at a time: each word's bits spread
/// by one along axis 3 (themselves included), a bit at either end carried into the word
/// beside, into the same words of the 3 x 3 rows around its row. Only the words given are
/// spread (inside a wide front, a row's front is its two ends). The rows spread into are
/// marked by groups of [`GROUP_ROWS`] rows, and [`drain`](Self::drain) takes the gathered words
/// from the rows of the groups marked and the rows just beside them, leaving every word clear.
pub(super) struct Reach<const K: usize> {
    d0: usize,
    d1: usize,
    pub(super) words: usize,
    pub(super) rows: usize,
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
    pub(super) fn new(dims: [usize; 3], six: bool) -> Self {
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
    pub(super) fn spread(&mut self, front: &[(usize, u64)]) {
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
    pub(super) fn drain(
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
