//! What the waves' tests share: open grids, breadth-first distances to hold the waves to, and
//! the numbers rebuilt from what a wave keeps.

use super::{offsets, Connectivity, Wave};
use crate::plan::cspace::{CSpace, Grid, Node};
use std::collections::VecDeque;

pub(super) fn open(n: f64) -> CSpace {
    let g = Grid::over([[0.0, n], [0.0, n], [0.0, n]], 1.0);
    CSpace::from_fn(g, |_| true)
}

pub(super) fn open_dims(a: usize, b: usize, c: usize) -> CSpace {
    let g = Grid::over([[0.0, a as f64], [0.0, b as f64], [0.0, c as f64]], 1.0);
    CSpace::from_fn(g, |_| true)
}

/// The wave numbers its end `n` (the end's breadth-first distance plus one, from `dist`),
/// every node below it its distance, and nothing else below it (a node as far as the end
/// may be numbered or not): the numbers rebuilt from what the wave keeps ([`numbers`]), and
/// each node's neighbours read from its distance ([`Wave::label_next_to`]) by every node
/// the wave numbered.
pub(super) fn assert_labels_are_distances(w: &Wave, g: &Grid, dist: &[u32], n: u32, what: &str) {
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
pub(super) fn numbers(w: &Wave) -> Vec<u32> {
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

/// The farthest node reached (the last by index) and the first node half as far.
pub(super) fn far_and_middle(dist: &[u32]) -> (usize, usize) {
    let far = (0..dist.len())
        .max_by_key(|&i| (dist[i], i))
        .expect("nodes");
    let mid = (0..dist.len())
        .find(|&i| dist[i] == dist[far] / 2)
        .expect("a middle");
    (far, mid)
}

/// Breadth-first distances (plus one, 0 = not reached) over the usable nodes of `g` and
/// their 26 neighbours, from `start`.
pub(super) fn bfs(g: &Grid, start: Node, usable: impl Fn(Node) -> bool) -> Vec<u32> {
    bfs_over(g, start, usable, Connectivity::TwentySix)
}

/// [`bfs`] over the neighbours of `connectivity`.
pub(super) fn bfs_over(
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
