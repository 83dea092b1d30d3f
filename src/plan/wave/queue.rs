//! The node-by-node wave: a first-in first-out queue over the neighbours of either
//! connectivity, every step asked of the graph, keeping the numbers (2 bytes a node, 4 for a
//! path of over 65 533 steps). The wave of a graph whose wave does not count every step between
//! usable nodes, and of the 6 axis neighbours numbered whole; bounded as A* is where the graph
//! knows a floor of the ends' distance ([`Graph::steps_floor`], `expand`).

use super::{offsets, Connectivity, Graph};
use crate::plan::cspace::{CSpace, Node, FREE};
use crate::zeroed::ZeroBuf;

/// A node's label word in the node-by-node wave. It is numbered in `u16` words (2 bytes a
/// node: half the memory and memory traffic of `u32`) and again in `u32` only if a number would
/// not fit: when a node numbered 65 533 is expanded, i.e. the end's number would be 65 534 or
/// more (or the end is unreachable from a component that deep, numbered again only to return
/// `None`). The numbers are the same either way.
pub(super) trait Word: bytemuck::Pod + PartialEq + Default + Send + 'static {
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

#[inline]
pub(super) fn number_of<W: Word>(l: W) -> u32 {
    if l == W::CHECKED || l == W::BLOCKED {
        0
    } else {
        l.wide()
    }
}

/// A number outgrew the label word of the node-by-node wave.
pub(super) struct TooLong;

/// What a node-by-node wave came to.
pub(super) enum Numbered<W: Word> {
    /// The end was numbered: the labels.
    Reached(ZeroBuf<W>),
    /// The end cannot be reached; `pruned` when the bound left nodes out (then a larger bound
    /// may reach it).
    Exhausted { pruned: bool },
}

/// The steps a wave over `connectivity` needs from `a` to `b` without obstacles: the largest
/// index difference over 26 neighbours, their sum over the 6 axis neighbours. A step changes it
/// by at most one, so it never exceeds the distance in any graph of those steps.
pub(super) fn grid_steps(a: Node, b: Node, connectivity: Connectivity) -> u32 {
    let d = [0, 1, 2].map(|k| a[k].abs_diff(b[k]));
    match connectivity {
        Connectivity::TwentySix => d[0].max(d[1]).max(d[2]),
        Connectivity::Six => d[0] + d[1] + d[2],
    }
}

/// The bound of a node-by-node wave ([`number_scalar`]): the most steps, and the estimate of a
/// node's steps to the end: the start's, and a neighbour's from the node and the estimate at the
/// numbered node it is reached from (`u32::MAX` rules it out).
#[derive(Clone, Copy)]
pub(super) struct Bound<'a> {
    pub steps: u32,
    pub start: u32,
    pub estimate: &'a dyn Fn(Node, u32) -> u32,
}

/// The expansion node by node in words `W`: the labels when `end` was numbered, `Exhausted`
/// when it cannot be reached, `Err(TooLong)` when a number does not fit in `W`. A first-in
/// first-out queue, each node's neighbours in the order of
/// [`offsets`], the wave's steps asked of the graph.
///
/// With a [`Bound`], a node `x` whose distance `d(x)` from `start` plus its estimate `h(x)` of
/// the steps to `end` exceeds the bound's steps is left out (never numbered, never asked of the
/// graph), as A* leaves out what its estimate rules out. The estimate must never exceed the
/// distance to `end` and be consistent (`h(x) <= 1 + h(y)` across a step of the graph), so every
/// node of a shortest path to a kept node is kept too, and a kept node gets its distance over
/// the whole wave: with a bound no less than the ends' distance, every node of a shortest path
/// between them is kept with its number, and a walk back from `end` (which only stands on such
/// nodes, and reads every other node as unnumbered or refuses the step to it) takes the same
/// steps as over the whole wave (`corridor.rs` says why for the row waves).
pub(super) fn number_scalar<W: Word, G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
    bound: Option<Bound<'_>>,
) -> Result<Numbered<W>, TooLong> {
    let g = &cs.grid;
    let mut labels = ZeroBuf::<W>::zeros(g.len());
    let mut queue = std::collections::VecDeque::new();
    labels[g.index(start)] = W::ONE;
    // Each queued node with its estimate (0 without a bound).
    queue.push_back((start, bound.map_or(0, |b| b.start)));
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
    let mut pruned = false;
    while let Some((n, estimate)) = queue.pop_front() {
        if found {
            break;
        }
        let here = g.index(n);
        let next = labels[here].next().ok_or(TooLong)?;
        // A neighbour's distance from the start is this node's number (numbers start at 1).
        let distance = labels[here].wide();
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
            let ahead = bound.map_or(0, |b| (b.estimate)(m, estimate));
            if bound.is_some_and(|b| distance.saturating_add(ahead) > b.steps) {
                pruned = true;
                continue;
            }
            if l == W::default() {
                let code = cs.code_in(m);
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
            queue.push_back((m, ahead));
        }
    }
    Ok(if found {
        Numbered::Reached(labels)
    } else {
        Numbered::Exhausted { pruned }
    })
}

#[cfg(test)]
mod tests {
    use super::super::testing::*;
    use super::super::{expand, Labels, Open};
    use super::*;
    use crate::plan::cspace::Grid;
    use std::collections::VecDeque;

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
