//! The configuration-space grid of axes 1..3 (paper section 3, "Collision Inspection").
//!
//! Nodes sit at integer multiples of the spacing d (degrees) within the controller's axis
//! ranges; a node is free (the paper's 0) or blocked (-1: out of range, coupled axis-3 range
//! included, or a link cylinder within the clearance of a box). Which nodes are free is asked of
//! an [`Inspector`]; this module knows no geometry.
//!
//! Each node holds one byte, its *code*: bit 7 ([`FREE`]) is the paper's free/blocked; the other
//! bits belong to the inspector (the collision model keeps there how deep in free space the node
//! lies, which its step check reads, `collision::grid`). A blocked node's code is 0. Each column
//! (fixed axes 1 and 2) also holds a few bytes of the inspector's own ([`Inspector::column_bytes`]:
//! what does not depend on axis 3).
//!
//! *Inspected as the route needs it* (beyond the paper, for speed only). The paper inspects
//! every node before the first wave; a wave between two points reaches a small part of the
//! grid. The grid is kept in *blocks* of [`BLOCK_COLUMNS`] columns by [`BLOCK_NODES`] values of
//! axis 3 (a column's part), each inspected the first time anything reads one of its nodes
//! ([`CSpace::lazy`]) and kept for the rest of the run (every wave and leg of the route, every
//! method of a comparison). A row wave asks, before each level, for the blocks around its front
//! ([`CSpace::inspect_around`]: the rows next to the front's, the axis-3 values next to its
//! nodes): those not yet inspected are inspected together, on all cores when there are several.
//! A node's code is its column's alone, whichever part of the column is inspected (the
//! inspector's contract), so every read gives the code the whole grid's inspection would: the
//! same waves, the same plans; the work and the memory grow with the part of the grid the
//! waves explore. [`CSpace::build`] inspects every block at once (the paper's order; tests,
//! `compare`, the `--svg` picture).

use crate::progress::{Progress, Silent};
use std::sync::{Arc, OnceLock};

pub use super::lattice::{Grid, Node, MAX_NODES};

/// The code bit of a free node; the other bits of a code are the inspector's.
pub const FREE: u8 = 0x80;

/// Answers "is this node free?" (and whatever else it keeps in a node's code) for a whole column
/// of axis-3 values at once, so an implementation can hoist the work that does not depend on
/// axis 3. A blocked node's code must be 0; a free node's has [`FREE`] set. A column's codes and
/// bytes must be the column's alone, whichever columns were inspected before it and in what
/// order (the grid inspects its blocks as its waves ask: [`CSpace::lazy`]).
pub trait Inspector: Sync {
    /// How many bytes of its own the inspector keeps per column (0 by default).
    fn column_bytes(&self) -> usize {
        0
    }
    /// The code bits whose row bit set ([`Row::plain`]) the planner asks for on every leg: that
    /// set is made with each block's codes (`None` by default: none is made, and a row wave
    /// looks at every candidate).
    fn row_bits_ahead(&self) -> Option<u8> {
        None
    }
    /// The codes of the column `[a1, a2, a3[k]]` into `code[k]`, and the column's own bytes
    /// into `column` ([`column_bytes`](Self::column_bytes) of them).
    fn inspect_column(
        &self,
        a1_deg: f64,
        a2_deg: f64,
        a3_deg: &[f64],
        code: &mut [u8],
        column: &mut [u8],
    );
    /// The nodes `part` (indices into `a3_deg`) of the columns `[a1, a2[j], a3[k]]` of one
    /// value of axis 1: column `j`'s codes of `a3[part]` into
    /// `code[j * part.len()..][..part.len()]` and its own bytes into
    /// `column[j * column_bytes()..][..column_bytes()]`, each what the whole column's
    /// inspection ([`inspect_slice`](Self::inspect_slice)) gives there. By default the whole
    /// columns, the part copied out; an inspector overrides it to inspect little more than
    /// the part.
    fn inspect_slice_part(
        &self,
        a1_deg: f64,
        a2_deg: &[f64],
        a3_deg: &[f64],
        part: std::ops::Range<usize>,
        code: &mut [u8],
        column: &mut [u8],
    ) {
        let d2 = a3_deg.len();
        let mut whole = vec![0u8; a2_deg.len() * d2];
        self.inspect_slice(a1_deg, a2_deg, a3_deg, &mut whole, column);
        for (to, from) in code
            .chunks_mut(part.len().max(1))
            .zip(whole.chunks(d2.max(1)))
        {
            to.copy_from_slice(&from[part.clone()]);
        }
    }
    /// The columns `[a1, a2[j], a3[k]]` of one value of axis 1: column `j`'s codes into
    /// `code[j * a3.len()..][..a3.len()]` and its own bytes into
    /// `column[j * column_bytes()..][..column_bytes()]`. By default column by column; an
    /// inspector overrides it to do once what the columns of one axis-1 value share.
    fn inspect_slice(
        &self,
        a1_deg: f64,
        a2_deg: &[f64],
        a3_deg: &[f64],
        code: &mut [u8],
        column: &mut [u8],
    ) {
        each_column(
            a2_deg,
            a3_deg.len(),
            self.column_bytes(),
            code,
            column,
            |a2, codes, own| self.inspect_column(a1_deg, a2, a3_deg, codes, own),
        );
    }
}

/// The columns of one slice (layout of [`Inspector::inspect_slice`]): `each(a2, codes, own)`
/// for every `a2_deg[j]` with column `j`'s `len` codes and `width` own bytes.
pub fn each_column(
    a2_deg: &[f64],
    len: usize,
    width: usize,
    code: &mut [u8],
    column: &mut [u8],
    mut each: impl FnMut(f64, &mut [u8], &mut [u8]),
) {
    for (j, (&a2, codes)) in a2_deg.iter().zip(code.chunks_mut(len.max(1))).enumerate() {
        let at = (j * width).min(column.len());
        each(a2, codes, &mut column[at..][..width]);
    }
}

/// The columns of a block along axes 1 and 2 (the last blocks of an axis may hold fewer).
/// Smaller blocks inspect less past what the waves read, larger ones share more of a slice's
/// work; whole runs at 1 deg took the fewest instructions from 1 x 4 to 2 x 4 columns, 3 % more
/// at 4 x 4, 15 % more at 8 x 8 (`benches/README.md`).
pub const BLOCK_COLUMNS: [usize; 2] = [2, 4];

/// The values of axis 3 a block holds of each of its columns (the last block of a column may
/// hold fewer): half a row word, so a row word is read from at most two blocks, and a whole
/// run of the collision model's column inspection (`collision::block`), which a block
/// inspects alone. The waves read about a third of a column at 1 deg on the trunk cell, so
/// blocks whole along axis 3 inspected about three times the nodes (`benches/README.md`).
pub const BLOCK_NODES: usize = 32;
const _: () = assert!(64 % BLOCK_NODES == 0, "a row word holds whole blocks");

/// Blocks inspected one after another on the asking thread below this many at once; from it on
/// all cores (`crate::parallel`: handing work to threads costs about as much as inspecting a
/// few blocks).
const PARALLEL_BLOCKS: usize = 12;

/// One block of the grid, inspected: its columns in order (axis 1, then axis 2), each with its
/// codes (its axis-3 part's), its own bytes ([`Inspector::column_bytes`], the column's) and its
/// row word's bits ([`Row::plain`], when the grid keeps them; in their place in the word).
#[derive(Clone)]
struct Block {
    code: Box<[u8]>,
    column: Box<[u8]>,
    plain: Box<[u64]>,
}

/// The grid, its nodes inspected as they are read (module doc).
#[derive(Clone)]
pub struct CSpace {
    pub grid: Grid,
    /// The inspector's bytes per column.
    column_bytes: usize,
    /// The code bits of the row words the blocks keep ([`Row::plain`]), if any.
    kept: Option<u8>,
    /// Blocks along axes 1, 2 and 3.
    blocks_along: [usize; 3],
    /// Every block: per column block (the blocks of the same columns, by `b0 * blocks_along[1]
    /// + b1`) its blocks along axis 3, made when the first of them is read (so a grid costs
    /// memory for the columns its waves reach, a fraction of a page per column block it does
    /// not); each block filled once, when first read. Block `b` of the flat numbering is block
    /// `b % blocks_along[2]` of column block `b / blocks_along[2]`.
    blocks: Vec<OnceLock<Box<[OnceLock<Block>]>>>,
    /// The controller values of axis 3's nodes.
    a3_deg: Arc<[f64]>,
    /// What inspects a block not inspected yet (`None`: every block was inspected when made).
    inspector: Option<Arc<dyn Inspector + Send>>,
}

impl std::fmt::Debug for CSpace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CSpace")
            .field("grid", &self.grid)
            .field("inspected_blocks", &self.inspected_blocks())
            .field("blocks", &self.blocks.len())
            .finish()
    }
}

/// One word of a row of the grid (the nodes of fixed axes 1 and 2): axis-3 indices `64 j ..
/// 64 j + 64`, read from the blocks that hold the bits asked for ([`CSpace::row_word`]).
#[derive(Clone, Copy, Debug)]
pub struct Row<'a> {
    /// The free nodes whose code has none of the kept bits ([`CSpace::kept_bits`]), one bit a
    /// node: axis-3 index `64 j + b` is bit `b`; the bits past the row's last node, and those
    /// of blocks not asked for, clear. 0 when the grid keeps none.
    pub plain: u64,
    /// Per block of the word (`BLOCK_NODES` bits each) its codes of the row; empty for a block
    /// not asked for.
    code: [&'a [u8]; 64 / BLOCK_NODES],
}

impl Row<'_> {
    /// The code of bit `b` of the word, which must be a bit asked for.
    #[inline]
    pub fn code(&self, b: usize) -> u8 {
        self.code[b / BLOCK_NODES][b % BLOCK_NODES]
    }
}

impl CSpace {
    /// The grid with nothing inspected yet: each block is inspected by `inspector` when first
    /// read (module doc).
    pub fn lazy(grid: Grid, inspector: Arc<dyn Inspector + Send>) -> CSpace {
        let mut cs = CSpace::empty(grid, &*inspector);
        cs.inspector = Some(inspector);
        cs
    }

    /// Inspects every node at once, blocks spread over the available cores; the result does
    /// not depend on the number of threads.
    pub fn build(grid: Grid, inspector: &dyn Inspector) -> CSpace {
        let cs = CSpace::empty(grid, inspector);
        let all: Vec<usize> = (0..cs.block_count()).collect();
        let n2 = cs.blocks_along[2];
        crate::parallel::map(&all, |&b| {
            let _ = cs.along(b / n2)[b % n2].set(cs.inspect_block(b, inspector));
        });
        cs
    }

    /// The grid's layout with no block inspected and no inspector.
    fn empty(grid: Grid, inspector: &dyn Inspector) -> CSpace {
        let blocks_along = [
            grid.dims[0].div_ceil(BLOCK_COLUMNS[0]),
            grid.dims[1].div_ceil(BLOCK_COLUMNS[1]),
            grid.dims[2].div_ceil(BLOCK_NODES),
        ];
        let n = if blocks_along[2] == 0 {
            0
        } else {
            blocks_along[0] * blocks_along[1]
        };
        CSpace {
            grid,
            column_bytes: inspector.column_bytes(),
            kept: inspector.row_bits_ahead(),
            blocks_along,
            blocks: (0..n).map(|_| OnceLock::new()).collect(),
            a3_deg: (0..grid.dims[2] as i64).map(|i| grid.value(2, i)).collect(),
            inspector: None,
        }
    }

    /// A grid from explicit node states (tests and hand-made examples): free nodes get the code
    /// [`FREE`] alone (nothing else known about them); the row words of every free node kept.
    pub fn from_fn(grid: Grid, is_free: impl Fn(Node) -> bool) -> CSpace {
        /// Keeps the row words of every free node.
        struct Plain;
        impl Inspector for Plain {
            fn row_bits_ahead(&self) -> Option<u8> {
                Some(0)
            }
            fn inspect_column(&self, _: f64, _: f64, _: &[f64], _: &mut [u8], _: &mut [u8]) {}
        }
        let cs = CSpace::empty(grid, &Plain);
        let n2 = cs.blocks_along[2];
        for b in 0..cs.block_count() {
            let [_, r1, r2] = cs.block_range(b);
            let made = cs.make_block(b, |i0, code, _| {
                for (j, i1) in r1.clone().enumerate() {
                    let codes = &mut code[j * r2.len()..][..r2.len()];
                    for (z, c) in r2.clone().zip(codes) {
                        let n = [i0 as i32, i1 as i32, z as i32];
                        *c = if is_free(n) { FREE } else { 0 };
                    }
                }
            });
            let _ = cs.along(b / n2)[b % n2].set(made);
        }
        cs
    }

    /// The code bits of the row words the grid keeps ([`Row::plain`]), if any.
    pub fn kept_bits(&self) -> Option<u8> {
        self.kept
    }

    /// The node ranges of block `b` along axes 1, 2 and 3.
    fn block_range(&self, b: usize) -> [std::ops::Range<usize>; 3] {
        let [_, n1, n2] = self.blocks_along;
        let at = [b / n2 / n1, b / n2 % n1, b % n2];
        let size = [BLOCK_COLUMNS[0], BLOCK_COLUMNS[1], BLOCK_NODES];
        [0, 1, 2].map(|k| {
            let lo = at[k] * size[k];
            lo..(lo + size[k]).min(self.grid.dims[k])
        })
    }

    /// Inspects block `b` with `inspector`.
    fn inspect_block(&self, b: usize, inspector: &dyn Inspector) -> Block {
        let [_, r1, r2] = self.block_range(b);
        let a2: Vec<f64> = r1.map(|i| self.grid.value(1, i as i64)).collect();
        self.make_block(b, |i0, code, column| {
            let a1 = self.grid.value(0, i0 as i64);
            inspector.inspect_slice_part(a1, &a2, &self.a3_deg, r2.clone(), code, column)
        })
    }

    /// Blocks `b2s` (along axis 3) of column block `cb` inspected together by the grid's
    /// inspector: each column's part that the blocks cover inspected at once (what the
    /// column's parts share is done once), then cut into the blocks, each kept unless another
    /// thread kept it first (the same codes either way).
    fn inspect_run(&self, cb: usize, b2s: std::ops::Range<usize>) {
        let inspector = self.inspector();
        let n2 = self.blocks_along[2];
        let [r0, r1, first] = self.block_range(cb * n2 + b2s.start);
        let z = first.start..self.block_range(cb * n2 + b2s.end - 1)[2].end;
        let a2: Vec<f64> = r1.clone().map(|i| self.grid.value(1, i as i64)).collect();
        let (len, width) = (z.len(), self.column_bytes);
        let (slab, colslab) = (r1.len() * len, r1.len() * width);
        let mut code = vec![0u8; r0.len() * slab];
        let mut column = vec![0u8; r0.len() * colslab];
        for (k, i0) in r0.clone().enumerate() {
            let a1 = self.grid.value(0, i0 as i64);
            let (code, own) = (&mut code[k * slab..][..slab], &mut column[k * colslab..]);
            inspector.inspect_slice_part(
                a1,
                &a2,
                &self.a3_deg,
                z.clone(),
                code,
                &mut own[..colslab],
            );
        }
        let along = self.along(cb);
        for b2 in b2s {
            let b = cb * n2 + b2;
            let part = self.block_range(b)[2].clone();
            let at = part.start - z.start;
            let made = self.make_block(b, |i0, out, own| {
                let k = i0 - r0.start;
                for (j, out) in out.chunks_mut(part.len()).enumerate() {
                    out.copy_from_slice(&code[k * slab + j * len + at..][..part.len()]);
                }
                own.copy_from_slice(&column[k * colslab..][..colslab]);
            });
            let _ = along[b2].set(made);
        }
    }

    /// Block `b`, its columns of each value `i0` of axis 1 filled by `fill(i0, codes, bytes)`
    /// (the layout of [`Inspector::inspect_slice_part`]), with its row words' bits.
    fn make_block(&self, b: usize, mut fill: impl FnMut(usize, &mut [u8], &mut [u8])) -> Block {
        let [r0, r1, r2] = self.block_range(b);
        let (len, width) = (r2.len(), self.column_bytes);
        let columns = r0.len() * r1.len();
        let mut code = vec![0u8; columns * len];
        let mut column = vec![0u8; columns * width];
        let (slab, colslab) = (r1.len() * len, r1.len() * width);
        for (k, i0) in r0.enumerate() {
            fill(
                i0,
                &mut code[k * slab..][..slab],
                &mut column[k * colslab..][..colslab],
            );
        }
        let plain = match self.kept {
            Some(bits) => {
                // A block's part of a row fits one word (`BLOCK_NODES` divides 64): its bits
                // moved to their place in the row's word.
                let mut plain = vec![0u64; columns];
                row_words(&code, len, bits, &mut plain);
                let shift = r2.start % 64;
                plain.iter_mut().for_each(|p| *p <<= shift);
                plain
            }
            None => Vec::new(),
        };
        Block {
            code: code.into(),
            column: column.into(),
            plain: plain.into(),
        }
    }

    /// The blocks along axis 3 of column block `cb`, made now if they were not yet.
    #[inline]
    fn along(&self, cb: usize) -> &[OnceLock<Block>] {
        self.blocks[cb].get_or_init(|| (0..self.blocks_along[2]).map(|_| OnceLock::new()).collect())
    }

    /// Whether block `b2` of column block `cb` has been inspected.
    #[inline]
    fn inspected_at(&self, cb: usize, b2: usize) -> bool {
        self.blocks[cb]
            .get()
            .is_some_and(|along| along[b2].get().is_some())
    }

    /// Whether block `b` (flat numbering) has been inspected.
    fn inspected(&self, b: usize) -> bool {
        let n2 = self.blocks_along[2];
        self.inspected_at(b / n2, b % n2)
    }

    /// Block `b2` along axis 3 of column block `cb`, inspected now if it was not yet.
    #[inline]
    fn block(&self, cb: usize, b2: usize) -> &Block {
        match self.blocks[cb].get().and_then(|along| along[b2].get()) {
            Some(block) => block,
            None => self.fill(cb, b2),
        }
    }

    /// Block `b` of the flat numbering, inspected now if it was not yet.
    fn block_flat(&self, b: usize) -> &Block {
        let n2 = self.blocks_along[2];
        self.block(b / n2, b % n2)
    }

    /// Block `b2` of column block `cb`, inspected by the grid's inspector (once, whichever
    /// thread asks first; the others wait for it).
    #[cold]
    #[inline(never)]
    fn fill(&self, cb: usize, b2: usize) -> &Block {
        let b = cb * self.blocks_along[2] + b2;
        self.along(cb)[b2].get_or_init(|| self.inspect_block(b, self.inspector()))
    }

    /// The grid's inspector (never `Blocked`: a grid without an inspector had every block
    /// inspected when made).
    fn inspector(&self) -> &dyn Inspector {
        match &self.inspector {
            Some(inspector) => &**inspector,
            None => &Blocked,
        }
    }

    /// The column block of column `(i0, i1)`, and the column's place in its blocks.
    #[inline]
    fn block_of(&self, i0: usize, i1: usize) -> (usize, usize) {
        let [c0, c1] = BLOCK_COLUMNS;
        let (b0, b1) = (i0 / c0, i1 / c1);
        let width = (self.grid.dims[1] - b1 * c1).min(c1);
        (
            b0 * self.blocks_along[1] + b1,
            (i0 - b0 * c0) * width + (i1 - b1 * c1),
        )
    }

    /// The codes of column `c` (its place in its blocks) in `block`, block `b2` along axis 3.
    #[inline]
    fn codes_of<'a>(&self, block: &'a Block, b2: usize, c: usize) -> &'a [u8] {
        let len = (self.grid.dims[2] - b2 * BLOCK_NODES).min(BLOCK_NODES);
        &block.code[c * len..][..len]
    }

    /// Word `j` of row `t` (axes 1 and 2 at `t / dims[1]`, `t % dims[1]`) for the bits `want`:
    /// the blocks holding those bits inspected now if they were not yet ([`Row`]; bits past
    /// the row's last node ask for nothing).
    #[inline]
    pub fn row_word(&self, t: usize, j: usize, want: u64) -> Row<'_> {
        const PER_WORD: usize = 64 / BLOCK_NODES;
        const HALF: u64 = u64::MAX >> (64 - BLOCK_NODES);
        let d1 = self.grid.dims[1] as u32;
        let (i0, i1) = ((t as u32 / d1) as usize, (t as u32 % d1) as usize);
        let (cb, c) = self.block_of(i0, i1);
        let mut row = Row {
            plain: 0,
            code: [&[]; PER_WORD],
        };
        for (k, code) in row.code.iter_mut().enumerate() {
            let b2 = j * PER_WORD + k;
            if want & (HALF << (k * BLOCK_NODES)) == 0 || b2 >= self.blocks_along[2] {
                continue;
            }
            let block = self.block(cb, b2);
            *code = self.codes_of(block, b2, c);
            row.plain |= block.plain.get(c).copied().unwrap_or(0);
        }
        row
    }

    /// Inspects, together (on all cores when there are several), the blocks not inspected yet
    /// that a row wave's next level reads around its front: per front word (`(t, j, bits)`:
    /// bits `bits` of word `j` of row `t`, [`row_word`](Self::row_word)) the rows next to row
    /// `t` (axes 1 and 2 at most one step away), at the axis-3 values at most one step from
    /// the bits; with a `bound` (a node and `r`), only those within `r` of the node on every
    /// axis.
    pub fn inspect_around(
        &self,
        front: impl Iterator<Item = (usize, usize, u64)>,
        bound: Option<([i64; 3], i64)>,
    ) {
        let [d0, d1, d2] = self.grid.dims.map(|d| d as i64);
        let mut wanted: Vec<usize> = Vec::new();
        for (t, j, bits) in front {
            if bits == 0 {
                continue;
            }
            let (i0, i1) = ((t as i64 / d1), (t as i64 % d1));
            let z = 64 * j as i64;
            let mut lo = [
                (i0 - 1).max(0),
                (i1 - 1).max(0),
                (z + i64::from(bits.trailing_zeros()) - 1).max(0),
            ];
            let mut hi = [
                (i0 + 1).min(d0 - 1),
                (i1 + 1).min(d1 - 1),
                (z + 64 - i64::from(bits.leading_zeros())).min(d2 - 1),
            ];
            if let Some((to, r)) = bound {
                for k in 0..3 {
                    lo[k] = lo[k].max(to[k] - r);
                    hi[k] = hi[k].min(to[k] + r);
                }
            }
            if (0..3).any(|k| lo[k] > hi[k]) {
                continue;
            }
            let [c0, c1] = BLOCK_COLUMNS.map(|c| c as i64);
            let c2 = BLOCK_NODES as i64;
            let [_, n1, n2] = self.blocks_along.map(|n| n as i64);
            for b0 in lo[0] / c0..=hi[0] / c0 {
                for b1 in lo[1] / c1..=hi[1] / c1 {
                    let cb = b0 * n1 + b1;
                    for b2 in lo[2] / c2..=hi[2] / c2 {
                        if !self.inspected_at(cb as usize, b2 as usize) {
                            wanted.push((cb * n2 + b2) as usize);
                        }
                    }
                }
            }
        }
        self.inspect_blocks(wanted);
    }

    /// Inspects the blocks of `wanted` not inspected yet: one after another here when they are
    /// few, else on all cores.
    fn inspect_blocks(&self, mut wanted: Vec<usize>) {
        wanted.sort_unstable();
        wanted.dedup();
        wanted.retain(|&b| !self.inspected(b));
        // The blocks of one column block together, from its first wanted to its last.
        let n2 = self.blocks_along[2];
        let mut runs: Vec<(usize, std::ops::Range<usize>)> = Vec::new();
        for &b in &wanted {
            let (cb, b2) = (b / n2, b % n2);
            match runs.last_mut() {
                Some((last, b2s)) if *last == cb => b2s.end = b2 + 1,
                _ => runs.push((cb, b2..b2 + 1)),
            }
        }
        if wanted.len() < PARALLEL_BLOCKS {
            for (cb, b2s) in runs {
                self.inspect_run(cb, b2s);
            }
        } else {
            crate::parallel::map(&runs, |(cb, b2s)| self.inspect_run(*cb, b2s.clone()));
        }
    }

    /// Inspects every block not inspected yet, on all cores, reporting one unit of `progress`
    /// per block (the caller announces nothing: this announces the stage when there is work).
    pub fn inspect_all(&self, progress: &dyn Progress) {
        let wanted: Vec<usize> = (0..self.block_count())
            .filter(|&b| !self.inspected(b))
            .collect();
        if wanted.is_empty() {
            return;
        }
        progress.stage("inspecting the grid", wanted.len() as u64);
        crate::parallel::map(&wanted, |&b| {
            self.block_flat(b);
            progress.advance(1);
        });
    }

    /// How many blocks have been inspected so far, of [`block_count`](Self::block_count).
    pub fn inspected_blocks(&self) -> usize {
        let along = self.blocks.iter().filter_map(OnceLock::get);
        along.flatten().filter(|b| b.get().is_some()).count()
    }

    /// How many blocks the grid has.
    pub fn block_count(&self) -> usize {
        self.blocks.len() * self.blocks_along[2]
    }

    /// The inspector's bytes of the column holding node `n` (empty when it keeps none), read
    /// from the block holding the node (every block of a column holds them).
    #[inline]
    pub fn column(&self, n: Node) -> &[u8] {
        let (cb, c) = self.block_of(n[0] as usize, n[1] as usize);
        let w = self.column_bytes;
        &self.block(cb, n[2] as usize / BLOCK_NODES).column[c * w..][..w]
    }

    #[inline]
    pub fn is_free(&self, n: Node) -> bool {
        self.code(n) & FREE != 0
    }

    #[inline]
    pub fn is_free_index(&self, i: usize) -> bool {
        self.code_index(i) & FREE != 0
    }

    /// The code of node `n` (0 outside the grid).
    #[inline]
    pub fn code(&self, n: Node) -> u8 {
        if self.grid.contains(n) {
            self.code_in(n)
        } else {
            0
        }
    }

    /// The code of node `n`, which lies in the grid.
    #[inline]
    pub fn code_in(&self, n: Node) -> u8 {
        let (cb, c) = self.block_of(n[0] as usize, n[1] as usize);
        let z = n[2] as usize;
        let b2 = z / BLOCK_NODES;
        self.codes_of(self.block(cb, b2), b2, c)[z % BLOCK_NODES]
    }

    /// The code of the node with linear index `i`.
    #[inline]
    pub fn code_index(&self, i: usize) -> u8 {
        self.code_in(self.grid.node(i))
    }

    /// The free nodes of the whole grid (every block inspected first).
    pub fn free_count(&self) -> usize {
        self.inspect_all(&Silent);
        (0..self.block_count())
            .map(|b| {
                let code = &self.block_flat(b).code;
                code.iter().filter(|&&c| c & FREE != 0).count()
            })
            .sum()
    }
}

/// An inspector that finds every node blocked (what a block reads that no inspector can fill:
/// never, see [`CSpace::fill`]).
struct Blocked;

impl Inspector for Blocked {
    fn inspect_column(&self, _: f64, _: f64, _: &[f64], code: &mut [u8], _: &mut [u8]) {
        code.fill(0);
    }
}

/// The row words ([`Row::plain`]) of whole rows of `d2` codes (`codes`) into `out`, `d2` bits
/// rounded up to whole words a row: the free nodes whose code has none of `bits`, 8 codes at a
/// time.
fn row_words(codes: &[u8], d2: usize, bits: u8, out: &mut [u64]) {
    const HIGH: u64 = 0x8080_8080_8080_8080;
    const LOW7: u64 = 0x7f7f_7f7f_7f7f_7f7f;
    // Each byte's high bit, gathered into the top byte (bit 7 of byte k to bit 56 + k).
    const GATHER: u64 = 0x0102_0408_1020_4080;
    const _: () = assert!(FREE == 0x80, "the free bit is each byte's high bit");
    if d2 == 0 {
        return;
    }
    let words = d2.div_ceil(64);
    let spread = u64::from_ne_bytes([bits; 8]);
    let top = |x: u64| ((x >> 7) & 0x0101_0101_0101_0101).wrapping_mul(GATHER) >> 56;
    for (row, out) in codes.chunks_exact(d2).zip(out.chunks_mut(words)) {
        for (sixty_four, o) in row.chunks(64).zip(out) {
            let mut p = 0u64;
            for (k, eight) in sixty_four.chunks(8).enumerate() {
                let mut b = [0u8; 8];
                b[..eight.len()].copy_from_slice(eight);
                let x = u64::from_le_bytes(b);
                let hit = x & spread;
                // The high bit of each byte of `hit` that is not zero.
                let any = ((hit & LOW7).wrapping_add(LOW7) | hit) & HIGH;
                p |= top(x & HIGH & !any) << (8 * k);
            }
            *o = p;
        }
    }
}

#[cfg(test)]
#[path = "cspace_tests.rs"]
mod tests;
