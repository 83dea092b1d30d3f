//! The corridor waves (beyond the paper, for speed only): the searches walk back only to
//! neighbours numbered one
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
//! its tool at fewer nodes.

use super::rows::{Level, RowWave};
use super::{ends_usable, expand, label_word, residue_code, with_code, Connectivity, Graph};
use super::{Labels, Wave};
use crate::plan::cspace::{CSpace, Node};
use crate::zeroed::ZeroBuf;

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
pub(super) fn corridor_waves<G: Graph + ?Sized>(
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
/// tries cost more than they save (`benches/README.md`).
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
/// out having left nodes out ([`corridor_rows`]): of the divisors 2 to 32, 8 costs the example
/// cells' whole runs about the fewest instructions (`benches/README.md`).
const BOUND_GROWTH: i64 = 8;

/// After this many tries the bound doubles instead: ends that are not joined stop being
/// numbered again once the bound leaves nothing out, and doubling gets there in a few more
/// tries, each numbering more than the one before (so the tries together cost a small
/// multiple of the last). Without the doubling, waves whose ends a wall keeps apart cost far
/// more than unbounded ones on an open test grid (no looks, `benches/README.md`); the example
/// cells all gain.
const BOUND_FINE_TRIES: u32 = 6;

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

#[cfg(test)]
mod tests {
    use super::super::rows::{within, ROW_NUMBERED};
    use super::super::testing::*;
    use super::super::{offsets, Open};
    use super::*;
    use crate::plan::cspace::Grid;

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
}
