//! The configuration-space grid of axes 1..3 (paper section 3, "Collision Inspection").
//!
//! Nodes sit at integer multiples of the spacing d (degrees) within the controller's axis
//! ranges; a node is free (the paper's 0) or blocked (-1: out of range, coupled axis-3 range
//! included, or a link cylinder within the clearance of a box). Which nodes are free is asked of
//! an [`Inspector`]; this module knows no geometry. The grid is filled once per cell, in parallel
//! over axis-1 slices; the result does not depend on the number of threads.
//!
//! Each node holds one byte, its *code*: bit 7 ([`FREE`]) is the paper's free/blocked; the other
//! bits belong to the inspector (the collision model keeps there how deep in free space the node
//! lies, which its step check reads, `collision::grid`). A blocked node's code is 0. Each column
//! (fixed axes 1 and 2) also holds a few bytes of the inspector's own ([`Inspector::column_bytes`]:
//! what does not depend on axis 3).

use crate::progress::{Progress, Silent};
use std::sync::{Arc, Mutex};

/// A grid node: indices along axes 1..3 (0-based within the grid).
pub type Node = [i32; 3];

/// The lattice: node `n` has controller values `(origin[k] + n[k]) * step_deg`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub step_deg: f64,
    /// Integer multiple of `step_deg` of the first node along each axis.
    pub origin: [i64; 3],
    pub dims: [usize; 3],
}

/// Largest grid accepted (nodes); 0.25 deg over the IRB 1400's ranges is ~420 M.
pub const MAX_NODES: usize = 500_000_000;

impl Grid {
    /// The nodes k*step inside `[lo, hi]` of each axis (deg).
    pub fn over(ranges_deg: [[f64; 2]; 3], step_deg: f64) -> Grid {
        let mut origin = [0i64; 3];
        let mut dims = [0usize; 3];
        for k in 0..3 {
            let [lo, hi] = ranges_deg[k];
            let first = (lo / step_deg - 1e-9).ceil() as i64;
            let last = (hi / step_deg + 1e-9).floor() as i64;
            origin[k] = first;
            dims[k] = (last - first + 1).max(0) as usize;
        }
        Grid {
            step_deg,
            origin,
            dims,
        }
    }

    pub fn len(&self) -> usize {
        self.dims.iter().product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn contains(&self, n: Node) -> bool {
        (0..3).all(|k| n[k] >= 0 && (n[k] as usize) < self.dims[k])
    }

    /// Linear index; axis 3 varies fastest so a column (fixed axes 1, 2) is contiguous.
    #[inline]
    pub fn index(&self, n: Node) -> usize {
        (n[0] as usize * self.dims[1] + n[1] as usize) * self.dims[2] + n[2] as usize
    }

    #[inline]
    pub fn node(&self, i: usize) -> Node {
        let z = i % self.dims[2];
        let r = i / self.dims[2];
        [
            (r / self.dims[1]) as i32,
            (r % self.dims[1]) as i32,
            z as i32,
        ]
    }

    /// Controller value (deg) of index `i` along axis `k`.
    #[inline]
    pub fn value(&self, k: usize, i: i64) -> f64 {
        (self.origin[k] + i) as f64 * self.step_deg
    }

    /// Controller values of a node, deg.
    pub fn axes_deg(&self, n: Node) -> [f64; 3] {
        [
            self.value(0, n[0] as i64),
            self.value(1, n[1] as i64),
            self.value(2, n[2] as i64),
        ]
    }

    /// The node at `axes` if `axes` lies on the lattice (within 1e-9 deg) and in the grid.
    pub fn node_at(&self, axes: &[f64; 3]) -> Option<Node> {
        let mut n = [0i32; 3];
        for k in 0..3 {
            let f = axes[k] / self.step_deg;
            let r = f.round();
            if (f - r).abs() * self.step_deg > 1e-9 {
                return None;
            }
            n[k] = (r as i64 - self.origin[k]) as i32;
        }
        self.contains(n).then_some(n)
    }

    /// Grid nodes within `rings` cells of `axes` (Chebyshev), nearest first (Euclidean in
    /// degrees, ties by index): the candidates to join an off-grid point to the grid.
    pub fn nodes_near(&self, axes: &[f64; 3], rings: i32) -> Vec<Node> {
        let base: Vec<i64> = (0..3)
            .map(|k| (axes[k] / self.step_deg).floor() as i64 - self.origin[k])
            .collect();
        let mut out = Vec::new();
        for d0 in -rings + 1..=rings {
            for d1 in -rings + 1..=rings {
                for d2 in -rings + 1..=rings {
                    let n = [
                        (base[0] + d0 as i64) as i32,
                        (base[1] + d1 as i64) as i32,
                        (base[2] + d2 as i64) as i32,
                    ];
                    if self.contains(n) {
                        out.push(n);
                    }
                }
            }
        }
        let dist = |n: &Node| {
            let v = self.axes_deg(*n);
            (0..3).map(|k| (v[k] - axes[k]).powi(2)).sum::<f64>()
        };
        out.sort_by(|a, b| dist(a).total_cmp(&dist(b)).then(a.cmp(b)));
        out
    }
}

/// The code bit of a free node; the other bits of a code are the inspector's.
pub const FREE: u8 = 0x80;

/// Answers "is this node free?" (and whatever else it keeps in a node's code) for a whole column
/// of axis-3 values at once, so an implementation can hoist the work that does not depend on
/// axis 3. A blocked node's code must be 0; a free node's has [`FREE`] set.
pub trait Inspector: Sync {
    /// How many bytes of its own the inspector keeps per column (0 by default).
    fn column_bytes(&self) -> usize {
        0
    }
    /// The code bits whose row bit set ([`CSpace::row_bits`]) the planner asks for on every
    /// leg: that set is then made with the codes, slice by slice while they are in cache,
    /// instead of in a pass of its own over the whole grid before the first wave (`None` by
    /// default: every set made on its first ask).
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
    /// The columns `[a1, a2[j], a3[k]]` of one slice of axis 1: column `j`'s codes into
    /// `code[j * a3.len()..][..a3.len()]` and its own bytes into
    /// `column[j * column_bytes()..][..column_bytes()]`. By default column by column; an
    /// inspector overrides it to do once what the whole slice shares.
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

/// The inspected grid.
#[derive(Clone, Debug)]
pub struct CSpace {
    pub grid: Grid,
    code: Vec<u8>,
    /// The inspector's bytes per column, `column_bytes` each, columns in index order.
    column: Vec<u8>,
    column_bytes: usize,
    /// The row bit sets made so far ([`CSpace::row_bits`]).
    rows: RowCache,
}

/// A per-row bit set of some of the grid's free nodes, for the row wave (`wave::rows`). A
/// row holds the nodes of fixed axes 1 and 2, `words` words each, rows in index order; axis-3
/// index `64 j + b` is bit `b` of the row's word `j`, and the bits past the row's last node are
/// clear.
#[derive(Debug, PartialEq, Eq)]
pub struct RowBits {
    /// Words per row: `dims[2]` bits rounded up to whole words.
    pub words: usize,
    /// The free nodes whose code has none of the bits asked for ([`CSpace::row_bits`]).
    pub plain: Vec<u64>,
}

/// The chunks of rows a row bit set is made in ([`CSpace::row_bits`]), handed to the cores one
/// at a time.
const ROW_BITS_CHUNKS: usize = 16;

/// The row bit sets made so far, one per set of code bits asked for; a copy of the grid starts
/// with none.
#[derive(Debug, Default)]
struct RowCache(Mutex<Vec<(u8, Arc<RowBits>)>>);

impl Clone for RowCache {
    fn clone(&self) -> RowCache {
        RowCache::default()
    }
}

impl CSpace {
    /// Inspects every node, axis-1 slices spread over the available cores.
    pub fn build(grid: Grid, inspector: &dyn Inspector) -> CSpace {
        CSpace::build_observed(grid, inspector, &Silent)
    }

    /// [`CSpace::build`], reporting one unit of `progress` per axis-1 slice inspected (the
    /// caller announces the stage with `grid.dims[0]` units).
    pub fn build_observed(
        grid: Grid,
        inspector: &dyn Inspector,
        progress: &dyn Progress,
    ) -> CSpace {
        let mut code = vec![0u8; grid.len()];
        let width = inspector.column_bytes();
        let mut column = vec![0u8; grid.dims[0] * grid.dims[1] * width];
        let slice = grid.dims[1] * grid.dims[2];
        if slice == 0 {
            return CSpace {
                grid,
                code,
                column,
                column_bytes: width,
                rows: RowCache::default(),
            };
        }
        let threads = std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
            .min(grid.dims[0].max(1));
        let a3: Vec<f64> = (0..grid.dims[2] as i64).map(|i| grid.value(2, i)).collect();
        let a2: Vec<f64> = (0..grid.dims[1] as i64).map(|i| grid.value(1, i)).collect();
        // Per-column bytes in chunks that match the code chunks (never empty, for `zip`).
        let col_slice = (grid.dims[1] * width).max(1);
        let mut spare = vec![0u8; col_slice * grid.dims[0]];
        let columns: &mut [u8] = if width > 0 { &mut column } else { &mut spare };
        // The slices go to the threads one at a time, as each asks for the next: slices cost
        // very different amounts (a side of axis 1 with the obstacles, one without), so fixed
        // shares would leave a core idle. Each slice's codes are the same whoever inspects it.
        // The row bit set made with the codes, a slice's rows at a time (one word a slice,
        // never read, where it is not; a slice has rows of at least one word here).
        let words = grid.dims[2].div_ceil(64);
        let ahead = inspector
            .row_bits_ahead()
            .filter(|_| grid.dims[0] * grid.dims[1] * words * 8 <= ROW_BITS_MAX_BYTES);
        let row_slice = if ahead.is_some() {
            grid.dims[1] * words
        } else {
            1
        };
        let mut plain = vec![0u64; grid.dims[0] * row_slice];
        let slices = Mutex::new(
            code.chunks_mut(slice)
                .zip(columns.chunks_mut(col_slice))
                .zip(plain.chunks_mut(row_slice))
                .enumerate(),
        );
        std::thread::scope(|s| {
            for _ in 0..threads {
                let (a2, a3, slices) = (&a2, &a3, &slices);
                s.spawn(move || loop {
                    // A poisoned lock only means another slice panicked; the scope re-raises it.
                    let next = slices.lock().map(|mut it| it.next()).ok().flatten();
                    let Some((i, ((slab, colslab), rowslab))) = next else {
                        break;
                    };
                    inspector.inspect_slice(
                        grid.value(0, i as i64),
                        a2,
                        a3,
                        slab,
                        &mut colslab[..grid.dims[1] * width],
                    );
                    if let Some(bits) = ahead {
                        row_words(slab, grid.dims[2], bits, rowslab);
                    }
                    progress.advance(1);
                });
            }
        });
        let rows = RowCache::default();
        if let Some(bits) = ahead {
            let made = Arc::new(RowBits { words, plain });
            rows.0
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .push((bits, made));
        }
        CSpace {
            grid,
            code,
            column,
            column_bytes: width,
            rows,
        }
    }

    /// A grid from explicit node states (tests and hand-made examples): free nodes get the code
    /// [`FREE`] alone (nothing else known about them).
    pub fn from_fn(grid: Grid, is_free: impl Fn(Node) -> bool) -> CSpace {
        let code = (0..grid.len())
            .map(|i| if is_free(grid.node(i)) { FREE } else { 0 })
            .collect();
        CSpace {
            grid,
            code,
            column: Vec::new(),
            column_bytes: 0,
            rows: RowCache::default(),
        }
    }

    /// The inspector's bytes of the column holding node `n` (empty when it keeps none).
    #[inline]
    pub fn column(&self, n: Node) -> &[u8] {
        let w = self.column_bytes;
        let i = (n[0] as usize * self.grid.dims[1] + n[1] as usize) * w;
        &self.column[i..i + w]
    }

    #[inline]
    pub fn is_free(&self, n: Node) -> bool {
        self.grid.contains(n) && self.code[self.grid.index(n)] & FREE != 0
    }

    #[inline]
    pub fn is_free_index(&self, i: usize) -> bool {
        self.code[i] & FREE != 0
    }

    /// The code of node `n` (0 outside the grid).
    #[inline]
    pub fn code(&self, n: Node) -> u8 {
        if self.grid.contains(n) {
            self.code[self.grid.index(n)]
        } else {
            0
        }
    }

    /// The code of the node with linear index `i`.
    #[inline]
    pub fn code_index(&self, i: usize) -> u8 {
        self.code[i]
    }

    pub fn free_count(&self) -> usize {
        self.code.iter().filter(|&&c| c & FREE != 0).count()
    }

    /// The grid's free nodes whose code has none of `bits` set, as a per-row bit set
    /// ([`RowBits`], one bit a node). Made on the first ask for these `bits` and kept for the
    /// next (every wave of every leg asks the same): one pass over the codes, 8 at a time.
    pub fn row_bits(&self, bits: u8) -> Arc<RowBits> {
        // A poisoned lock only means another thread panicked while making a set: the sets
        // kept are whole (pushed after they were made).
        let mut made = self.rows.0.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, r)) = made.iter().find(|(b, _)| *b == bits) {
            return Arc::clone(r);
        }
        let r = Arc::new(self.make_row_bits(bits));
        made.push((bits, Arc::clone(&r)));
        r
    }

    /// [`row_bits`](Self::row_bits)' set, made in [`ROW_BITS_CHUNKS`] chunks of rows on all
    /// cores: the first wave of a route waits for it (unless the inspector made it with the
    /// codes: [`Inspector::row_bits_ahead`]).
    fn make_row_bits(&self, bits: u8) -> RowBits {
        let d2 = self.grid.dims[2];
        let words = d2.div_ceil(64);
        let rows = self.grid.dims[0] * self.grid.dims[1];
        if d2 == 0 || rows == 0 {
            return RowBits {
                words,
                plain: vec![0u64; rows * words],
            };
        }
        // Rows in chunks on all cores (each word depends on its row's codes alone), put
        // together in order.
        let chunk = rows.div_ceil(ROW_BITS_CHUNKS);
        let codes: Vec<&[u8]> = self.code.chunks(chunk * d2).collect();
        let parts = crate::parallel::map(&codes, |codes| {
            let mut plain = vec![0u64; codes.len() / d2 * words];
            row_words(codes, d2, bits, &mut plain);
            plain
        });
        let plain = parts.concat();
        RowBits { words, plain }
    }
}

/// The largest row bit set the row wave asks of the grid ([`CSpace::row_bits`]) and the
/// inspection makes ahead ([`Inspector::row_bits_ahead`]), bytes: the set is kept for the rest
/// of the run (52 MB at 0.25 deg over the IRB 1400's ranges); above it every candidate is
/// looked at (the same numbers; `wave`). At 0.25 deg the set makes the trunk faster for a
/// little more memory (`benches/README.md`).
pub const ROW_BITS_MAX_BYTES: usize = 64 << 20;

/// The row words ([`RowBits`]) of whole rows of `d2` codes (`codes`) into `out`, `d2` bits
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
mod tests {
    use super::*;

    #[test]
    fn lattice_covers_the_ranges_at_multiples_of_the_step() {
        let g = Grid::over([[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]], 1.0);
        assert_eq!(g.dims, [341, 141, 136]);
        assert_eq!(g.axes_deg([0, 0, 0]), [-170.0, -70.0, -65.0]);
        let g = Grid::over([[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]], 3.0);
        // -168 .. 168, -69 .. 69, -63 .. 69
        assert_eq!(g.dims, [113, 47, 45]);
        assert_eq!(g.axes_deg([0, 0, 0]), [-168.0, -69.0, -63.0]);
    }

    #[test]
    fn index_and_node_are_inverse() {
        let g = Grid::over([[-10.0, 10.0], [-5.0, 5.0], [0.0, 3.0]], 1.0);
        for i in 0..g.len() {
            assert_eq!(g.index(g.node(i)), i);
        }
        assert_eq!(g.node_at(&[3.0, -2.0, 1.0]), Some([13, 3, 1]));
        assert_eq!(g.node_at(&[3.5, -2.0, 1.0]), None);
        assert_eq!(g.node_at(&[30.0, -2.0, 1.0]), None);
    }

    #[test]
    fn nodes_near_are_sorted_by_distance() {
        let g = Grid::over([[-10.0, 10.0], [-10.0, 10.0], [-10.0, 10.0]], 1.0);
        let n = g.nodes_near(&[0.2, 0.7, 0.4], 1);
        assert_eq!(n.len(), 8);
        assert_eq!(g.axes_deg(n[0]), [0.0, 1.0, 0.0]);
        assert_eq!(g.axes_deg(n[7]), [1.0, 0.0, 1.0]);
    }

    struct Ball;
    impl Inspector for Ball {
        fn inspect_column(&self, a1: f64, a2: f64, a3: &[f64], code: &mut [u8], _: &mut [u8]) {
            for (f, &c) in code.iter_mut().zip(a3) {
                *f = if a1 * a1 + a2 * a2 + c * c > 25.0 {
                    FREE
                } else {
                    0
                };
            }
        }
    }

    #[test]
    fn parallel_build_matches_a_direct_fill() {
        let g = Grid::over([[-9.0, 9.0], [-8.0, 8.0], [-7.0, 7.0]], 1.0);
        let built = CSpace::build(g, &Ball);
        let direct = CSpace::from_fn(g, |n| {
            let v = g.axes_deg(n);
            v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 25.0
        });
        assert_eq!(built.code, direct.code);
        assert!(built.free_count() < g.len());
    }

    /// Pseudo-random codes (free or not, any other bits) from the node's values.
    struct Noise(Option<u8>);
    impl Inspector for Noise {
        fn row_bits_ahead(&self) -> Option<u8> {
            self.0
        }
        fn inspect_column(&self, a1: f64, a2: f64, a3: &[f64], code: &mut [u8], _: &mut [u8]) {
            for (f, &c) in code.iter_mut().zip(a3) {
                let h = ((a1 * 7919.0 + a2 * 104_729.0 + c * 1_299_709.0) as i64)
                    .wrapping_mul(0x2545_f491_4f6c_dd1d) as u64
                    >> 40;
                *f = if h & 3 == 0 {
                    0
                } else {
                    FREE | (h >> 8) as u8 & 0x7f
                };
            }
        }
    }

    /// The row bit set made with the codes, slice by slice, is the one made after them, on
    /// rows of partly used, whole and several words; a set of other bits is still made on its
    /// first ask.
    #[test]
    fn row_bits_made_ahead_are_the_ones_made_after() {
        for last in [6.0, 63.0, 64.0, 69.0, 130.0] {
            let g = Grid::over([[-4.0, 5.0], [-3.0, 3.0], [0.0, last]], 1.0);
            let ahead = CSpace::build(g, &Noise(Some(0x40)));
            let after = CSpace::build(g, &Noise(None));
            assert_eq!(ahead.code, after.code);
            assert!(ahead.code.iter().any(|&c| c & 0xc0 == 0xc0));
            assert!(ahead.code.iter().any(|&c| c & 0xc0 == 0x80));
            let kept = ahead.rows.0.lock().map(|r| r.len()).unwrap_or(0);
            assert_eq!(kept, 1, "made with the codes");
            assert_eq!(*ahead.row_bits(0x40), after.make_row_bits(0x40));
            assert_eq!(*ahead.row_bits(0x08), after.make_row_bits(0x08));
        }
    }

    /// The row bit set, made 8 codes at a time, against each node's code read alone: random
    /// codes (free or not, any other bits), rows of 1 to 130 nodes (partly used last words,
    /// whole words, several words), several sets of bits asked for; a second ask returns the
    /// set kept.
    #[test]
    fn row_bits_match_each_nodes_code() {
        let mut next = crate::plan::search::testing::xorshift(0x2545_f491_4f6c_dd1d);
        for d2 in [1usize, 7, 63, 64, 65, 70, 128, 130] {
            let g = Grid::over([[0.0, 2.0], [0.0, 3.0], [0.0, (d2 - 1) as f64]], 1.0);
            let mut cs = CSpace::from_fn(g, |_| false);
            for c in cs.code.iter_mut() {
                let r = next();
                // Blocked nodes have code 0; free ones any other bits.
                *c = if r & 3 == 0 {
                    0
                } else {
                    FREE | (r >> 8) as u8 & 0x7f
                };
            }
            for bits in [0u8, 0x40, 0x41, 0x7f, 0x08] {
                let r = cs.row_bits(bits);
                assert_eq!(r.words, d2.div_ceil(64));
                for i in 0..g.len() {
                    let (row, z) = (i / d2, i % d2);
                    let w = row * r.words + z / 64;
                    let bit = |set: &[u64]| set[w] >> (z % 64) & 1 == 1;
                    let code = cs.code[i];
                    assert_eq!(
                        bit(&r.plain),
                        code & FREE != 0 && code & bits == 0,
                        "d2 {d2} bits {bits:#x} node {i} code {code:#x}"
                    );
                }
                for row in 0..g.dims[0] * g.dims[1] {
                    let last = row * r.words + r.words - 1;
                    let past = if d2 % 64 == 0 { 0 } else { !0u64 << (d2 % 64) };
                    assert_eq!(r.plain[last] & past, 0);
                }
                assert!(Arc::ptr_eq(&r, &cs.row_bits(bits)));
            }
        }
    }
}
