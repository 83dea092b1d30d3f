//! The grid against its statement: the lattice over the ranges, a node's code as its column
//! alone gives it, and the grid inspected as it is read against the whole grid inspected first.

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
    for i in 0..g.len() {
        assert_eq!(built.code_index(i), direct.code_index(i));
    }
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

/// The row words the blocks keep, made 8 codes at a time, against each node's code read
/// alone: pseudo-random codes (free or not, any other bits), rows of 1 to 130 nodes (partly
/// used last words, whole words, several words, words of one block and of two), several sets
/// of bits kept, blocks whole and cut short at the grid's edges, a word read for some of its
/// blocks (the others' bits clear); without kept bits no row words.
#[test]
fn row_words_match_each_nodes_code() {
    for d2 in [1usize, 7, 63, 64, 65, 70, 128, 130] {
        let g = Grid::over([[-4.0, 5.0], [-3.0, 3.0], [0.0, (d2 - 1) as f64]], 1.0);
        for bits in [0u8, 0x40, 0x41, 0x7f, 0x08] {
            let cs = CSpace::build(g, &Noise(Some(bits)));
            let words = d2.div_ceil(64);
            let (mut plain, mut looked) = (0, 0);
            for t in 0..g.dims[0] * g.dims[1] {
                let row = |j| cs.row_word(t, j, u64::MAX);
                for z in 0..d2 {
                    let code = cs.code_index(t * d2 + z);
                    assert_eq!(row(z / 64).code(z % 64), code);
                    let bit = row(z / 64).plain >> (z % 64) & 1 == 1;
                    let want = code & FREE != 0 && code & bits == 0;
                    assert_eq!(bit, want, "d2 {d2} bits {bits:#x} row {t} z {z}");
                    // Asked for its own block only, the node's bit is the same.
                    let alone = cs.row_word(t, z / 64, 1 << (z % 64));
                    assert_eq!(alone.plain >> (z % 64) & 1 == 1, want);
                    assert_eq!(alone.code(z % 64), code);
                    plain += usize::from(want);
                    looked += usize::from(code & FREE != 0 && !want);
                }
                let past = if d2 % 64 == 0 { 0 } else { !0u64 << (d2 % 64) };
                assert_eq!(row(words - 1).plain & past, 0);
                // A word asked for its first block only: the other block's bits clear.
                let first = cs.row_word(t, 0, 1);
                assert_eq!(first.plain & !((1u64 << BLOCK_NODES) - 1), 0);
            }
            assert!(plain + looked > 0);
            if bits == 0x40 && d2 >= 64 {
                assert!(plain > 0 && looked > 0, "{d2}: {plain} {looked}");
            }
        }
        let none = CSpace::build(g, &Noise(None));
        assert_eq!(none.row_word(0, 0, u64::MAX).plain, 0);
    }
}

/// A grid inspected as it is read holds, node by node and column by column, the codes and
/// bytes of the grid inspected whole; a read inspects the one block holding the node; the
/// blocks around a front word (the rows next to its row, the axis-3 values next to its bits,
/// and only those, within a bound when given) are inspected together.
#[test]
fn a_lazy_grid_reads_what_the_whole_inspection_holds() {
    /// `Noise` with two column bytes from the column's values.
    struct Own;
    impl Inspector for Own {
        fn column_bytes(&self) -> usize {
            2
        }
        fn row_bits_ahead(&self) -> Option<u8> {
            Some(0x40)
        }
        fn inspect_column(&self, a1: f64, a2: f64, a3: &[f64], code: &mut [u8], own: &mut [u8]) {
            Noise(None).inspect_column(a1, a2, a3, code, own);
            own[0] = a1 as i8 as u8;
            own[1] = a2 as i8 as u8;
        }
    }
    let g = Grid::over([[-17.0, 13.0], [-9.0, 10.0], [0.0, 100.0]], 1.0);
    let whole = CSpace::build(g, &Own);
    let lazy = CSpace::lazy(g, Arc::new(Own));
    assert_eq!(lazy.inspected_blocks(), 0);
    assert_eq!(whole.inspected_blocks(), whole.block_count());
    let n = [9, 13, 5];
    assert_eq!(lazy.code(n), whole.code(n));
    assert_eq!(lazy.inspected_blocks(), 1);
    // Only the read column block holds its blocks along axis 3; asking whether the others
    // were inspected makes none.
    let made = |cs: &CSpace| cs.blocks.iter().filter(|b| b.get().is_some()).count();
    assert_eq!(made(&lazy), 1);
    assert!(
        (0..lazy.block_count())
            .filter(|&b| lazy.inspected(b))
            .count()
            == 1
    );
    assert_eq!(made(&lazy), 1);
    assert_eq!(
        lazy.column(n),
        &[(9 - 17) as i8 as u8, (13 - 9) as i8 as u8]
    );
    // Around a front word: the blocks holding the 3 x 3 rows about it, at the axis-3 values
    // next to its bits.
    let [d0, d1, d2] = g.dims;
    let around = |cs: &CSpace, t: usize, j: usize, bits: u64, bound| {
        cs.inspect_around([(t, j, bits), (t, j, bits)].into_iter(), bound);
        cs.inspected_blocks()
    };
    let blocks_of = |rows: &[(i64, i64)], z: std::ops::RangeInclusive<i64>| {
        let mut b: Vec<(i64, i64, i64)> = rows
            .iter()
            .filter(|&&(i, j)| i >= 0 && j >= 0 && i < d0 as i64 && j < d1 as i64)
            .flat_map(|&(i, j)| {
                z.clone()
                    .filter(|&z| z >= 0 && z < d2 as i64)
                    .map(move |z| (i, j, z))
            })
            .map(|(i, j, z)| {
                let [c0, c1] = BLOCK_COLUMNS.map(|c| c as i64);
                (i / c0, j / c1, z / BLOCK_NODES as i64)
            })
            .collect();
        b.sort_unstable();
        b.dedup();
        b.len()
    };
    let fresh = CSpace::lazy(g, Arc::new(Own));
    // A row at a block's corner (4, 4): its neighbours reach four blocks' columns; one node
    // inside a block along axis 3 (bit 5 of word 0) only that block's values.
    let corner = |i: i64, j: i64| [-1, 0, 1].map(|a| [-1, 0, 1].map(move |b| (i + a, j + b)));
    let rows: Vec<(i64, i64)> = corner(4, 4).into_iter().flatten().collect();
    assert_eq!(
        around(&fresh, 4 * d1 + 4, 0, 1 << 5, None),
        blocks_of(&rows, 4..=6)
    );
    assert_eq!(blocks_of(&rows, 4..=6), 4);
    // Nodes at the edge of an axis-3 block (bits 31 and 40 of word 1: values 95 and 104) reach
    // the next block along axis 3 (the grid ends at 100).
    let fresh = CSpace::lazy(g, Arc::new(Own));
    let bits = 1 << 31 | 1 << 40;
    assert_eq!(
        around(&fresh, 4 * d1 + 4, 1, bits, None),
        blocks_of(&rows, 94..=105)
    );
    assert_eq!(blocks_of(&rows, 94..=105), 8);
    // Bounded to the row's own column band and axis-3 values: only its own block.
    let fresh = CSpace::lazy(g, Arc::new(Own));
    assert_eq!(
        around(&fresh, 4 * d1 + 4, 0, 1 << 5, Some(([5, 5, 5], 1))),
        1
    );
    // Two front words of one row far apart along axis 3 (values 0..2 and 93..95): the blocks
    // between them are inspected with them (a column block's wanted blocks together, from the
    // first to the last), every code the whole grid's.
    let fresh = CSpace::lazy(g, Arc::new(Own));
    let words = [(4 * d1 + 4, 0, 1 << 1), (4 * d1 + 4, 1, 1 << 30)];
    fresh.inspect_around(words.into_iter(), None);
    assert_eq!(fresh.inspected_blocks(), blocks_of(&rows, 0..=95));
    assert_eq!(blocks_of(&rows, 0..=95), 12);
    for i in 0..g.len() {
        let m = g.node(i);
        let (cb, _) = fresh.block_of(m[0] as usize, m[1] as usize);
        if fresh.inspected_at(cb, m[2] as usize / BLOCK_NODES) {
            assert_eq!(fresh.code_index(i), whole.code_index(i), "{m:?}");
            assert_eq!(fresh.column(m), whole.column(m), "{m:?}");
        }
    }
    assert_eq!(fresh.inspected_blocks(), 12);
    // On the grid's edge.
    let rows: Vec<(i64, i64)> = corner(0, 0).into_iter().flatten().collect();
    let fresh = CSpace::lazy(g, Arc::new(Own));
    assert_eq!(around(&fresh, 0, 0, 1, None), blocks_of(&rows, -1..=1));
    // Every node in a scattered order: the same codes and bytes.
    let mut next = crate::plan::search::testing::xorshift(0x9e37_79b9_7f4a_7c15);
    for _ in 0..4000 {
        let i = next() as usize % g.len();
        let m = g.node(i);
        assert_eq!(lazy.code_index(i), whole.code_index(i), "{m:?}");
        assert_eq!(lazy.column(m), whole.column(m), "{m:?}");
        let (t, z) = (i / d2, i % d2);
        let word = |cs: &CSpace| cs.row_word(t, z / 64, u64::MAX).plain;
        assert_eq!(word(&lazy), word(&whole));
    }
    assert_eq!(lazy.free_count(), whole.free_count());
    assert_eq!(lazy.inspected_blocks(), lazy.block_count());
    assert!(whole.free_count() < g.len() && whole.free_count() > g.len() / 2);
}
