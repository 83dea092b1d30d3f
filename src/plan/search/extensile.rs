//! Extensile neighboring search (paper section 4.3), the search half: walk back on the
//! 26-neighbour wave preferring the previous direction, then axis neighbours, then face
//! diagonals, then corner diagonals (each group in the fixed lexicographic order), so that a
//! diagonal is taken where no axis neighbour carries n-1 (Fig. 8); do it both ways (a wave from
//! each end, Fig. 4) and merge the two paths into one (Fig. 5).
//!
//! The merge (our reading of Fig. 5, where the two paths differ in parallelograms that are known
//! to be free): take the union of the two paths' nodes, join every two of them that are grid
//! neighbours and whose straight move is accepted, and choose the path from start to end with
//! the fewest changes of direction, then the fewest steps, then the lowest node order. Where the
//! paths agree it follows them; where they part it crosses between them to keep straight. The
//! recursive k -> k+2 shortening (`shorten`) then cuts across the parallelograms.

use super::{add, descend, order_of, GridPath, SearchFailure};
use crate::plan::cspace::{CSpace, Node};
use crate::plan::wave::{self, offsets, Connectivity, Graph, Wave};
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

pub(crate) fn candidates(w: &Wave, n: Node, label: u32, prev: Option<[i32; 3]>) -> Vec<[i32; 3]> {
    let mut c: Vec<[i32; 3]> = offsets(Connectivity::TwentySix).to_vec();
    // Stable, each key read once (a label read per neighbour, not per comparison).
    c.sort_by_cached_key(|o| {
        let l = match w.label_next_to(add(n, *o), label) {
            0 => u32::MAX,
            l => l,
        };
        (l, Some(*o) != prev, order_of(*o))
    });
    c
}

/// One walk back on the wave of `graph` from `start` to `end`: the path start -> end.
pub fn one_way<G: Graph>(cs: &CSpace, start: Node, end: Node, graph: &G) -> Option<GridPath> {
    let w = wave::expand(cs, graph, start, end, Connectivity::TwentySix)?;
    descend(&w, &candidates, graph)
}

/// Both ways and merged: the path start -> end. The two waves are numbered together
/// ([`wave::expand_both`]: only the nodes on shortest paths between the ends, on which the
/// walks back take the same steps as over the whole waves); the two walks back run on two
/// threads and the merge after them, so the result is the same.
pub fn search<G: Graph>(
    cs: &CSpace,
    start: Node,
    end: Node,
    graph: &G,
) -> Result<GridPath, SearchFailure> {
    let (from_start, from_end) = wave::expand_both(cs, graph, start, end);
    let from_start = from_start.ok_or(SearchFailure::NotConnected)?;
    // The wave from the end, walked back from the start node, gives end -> start.
    let walk_back = || {
        from_end.as_ref().and_then(|w| {
            descend(w, &candidates, graph).map(|mut p| {
                p.reverse();
                p
            })
        })
    };
    let (forward, backward) = std::thread::scope(|s| {
        let other = s.spawn(walk_back);
        let here = descend(&from_start, &candidates, graph);
        // A panic in the other walk is a defect; fall back to walking it here.
        (here, other.join().unwrap_or_else(|_| walk_back()))
    });
    let steps = from_start.n() - 1;
    let forward = forward.ok_or(SearchFailure::WalkFailed { steps })?;
    Ok(match backward {
        Some(b) => merge_paths(&forward, &b, graph),
        None => forward,
    })
}

/// The merge of Fig. 5 (see the module doc). Both paths run start -> end.
pub fn merge_paths<G: Graph + ?Sized>(a: &[Node], b: &[Node], graph: &G) -> GridPath {
    let (Some(&start), Some(&end)) = (a.first(), a.last()) else {
        return b.to_vec();
    };
    // Nodes of the union, in a fixed order.
    let mut nodes: Vec<Node> = a.iter().chain(b).copied().collect();
    nodes.sort();
    nodes.dedup();
    let id: HashMap<Node, usize> = nodes.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let on_path = |p: &[Node], x: Node, y: Node| {
        p.windows(2)
            .any(|w| (w[0] == x && w[1] == y) || (w[0] == y && w[1] == x))
    };
    // Edges: path steps, and accepted moves between neighbouring union nodes.
    let mut edges: Vec<Vec<(usize, [i32; 3])>> = vec![Vec::new(); nodes.len()];
    for (i, &n) in nodes.iter().enumerate() {
        for &o in offsets(Connectivity::TwentySix) {
            let m = add(n, o);
            if let Some(&j) = id.get(&m) {
                if on_path(a, n, m)
                    || on_path(b, n, m)
                    || (i < j && graph.step_ok(n, m))
                    || (i > j && edges[j].iter().any(|&(k, _)| k == i))
                {
                    edges[i].push((j, o));
                }
            }
        }
    }
    // Dijkstra over (node, direction of arrival), cost (turns, steps).
    let dir_index = |o: [i32; 3]| ((o[0] + 1) * 9 + (o[1] + 1) * 3 + (o[2] + 1)) as usize;
    let ns = nodes.len() * 27;
    let mut best = vec![(u32::MAX, u32::MAX); ns];
    let mut from = vec![usize::MAX; ns];
    let s = id[&start] * 27 + 13; // 13: no direction yet
    best[s] = (0, 0);
    let mut heap = BinaryHeap::new();
    heap.push(Reverse((0u32, 0u32, s)));
    let mut goal_state = None;
    while let Some(Reverse((turns, steps, st))) = heap.pop() {
        if best[st] != (turns, steps) {
            continue;
        }
        let (i, d) = (st / 27, st % 27);
        if nodes[i] == end {
            goal_state = Some(st);
            break;
        }
        for &(j, o) in &edges[i] {
            let nd = dir_index(o);
            let t = turns + u32::from(d != 13 && d != nd);
            let cost = (t, steps + 1);
            let ns_ = j * 27 + nd;
            if cost < best[ns_] {
                best[ns_] = cost;
                from[ns_] = st;
                heap.push(Reverse((cost.0, cost.1, ns_)));
            }
        }
    }
    let Some(mut st) = goal_state else {
        return a.to_vec();
    };
    let mut path = vec![nodes[st / 27]];
    while from[st] != usize::MAX {
        st = from[st];
        path.push(nodes[st / 27]);
    }
    path.reverse();
    path
}

/// The search with both waves whole (`wave::expand`), not numbered together: the reference
/// the search must equal.
#[cfg(test)]
pub(crate) fn search_with_whole_waves<G: Graph>(
    cs: &CSpace,
    start: Node,
    end: Node,
    graph: &G,
) -> Result<GridPath, SearchFailure> {
    let from_start = wave::expand(cs, graph, start, end, Connectivity::TwentySix)
        .ok_or(SearchFailure::NotConnected)?;
    let steps = from_start.n() - 1;
    let forward =
        descend(&from_start, &candidates, graph).ok_or(SearchFailure::WalkFailed { steps })?;
    let backward = wave::expand(cs, graph, end, start, Connectivity::TwentySix)
        .and_then(|w| descend(&w, &candidates, graph))
        .map(|mut p| {
            p.reverse();
            p
        });
    Ok(match backward {
        Some(b) => merge_paths(&forward, &b, graph),
        None => forward,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::search::testing::{assert_path, grid, refusing_cases};
    use crate::plan::wave::Open;

    #[test]
    fn takes_the_diagonal_where_depth_first_fails() {
        // Fig. 8: free nodes joined only at corners.
        let cs = grid(3, 3, 1, |n| n[0] == n[1]);
        let p = search(&cs, [0, 0, 0], [2, 2, 0], &Open).expect("extensile finds it");
        assert_eq!(p, vec![[0, 0, 0], [1, 1, 0], [2, 2, 0]]);
        assert!(
            crate::plan::search::depth_first::search(&cs, [0, 0, 0], [2, 2, 0], &Open).is_err()
        );
    }

    #[test]
    fn keeps_its_direction_in_open_space() {
        let cs = grid(8, 8, 8, |_| true);
        let p = one_way(&cs, [0, 0, 0], [6, 2, 0], &Open).expect("path");
        assert_path(&p, [0, 0, 0], [6, 2, 0]);
        // Back from the end: axis steps along -axis1 while they keep the numbers falling
        // (4 of them), then the diagonal: two straight pieces, one turn.
        let turns = p
            .windows(3)
            .filter(|w| (0..3).any(|k| w[1][k] - w[0][k] != w[2][k] - w[1][k]))
            .count();
        assert_eq!(turns, 1, "{p:?}");
    }

    /// Scattered blocked nodes and refused steps (an optimistic wave's graph: the wave counts
    /// every step, the walk and the merge ask): the search over the corridor's waves gives the
    /// same path, or the same failure, as with both waves whole, from one corner to many ends.
    #[test]
    fn the_corridor_waves_change_no_search() {
        let (mut found, mut failed) = (0, 0);
        for (cs, graph, start, end) in refusing_cases() {
            let got = search(&cs, start, end, &graph);
            assert_eq!(
                got,
                search_with_whole_waves(&cs, start, end, &graph),
                "{end:?}"
            );
            match got {
                Ok(_) => found += 1,
                Err(_) => failed += 1,
            }
        }
        assert!(found >= 20 && failed >= 1, "found {found}, failed {failed}");
    }

    #[test]
    fn merge_crosses_between_two_paths_to_keep_straight() {
        // Two staircases around a free square; the straight diagonal is in the union.
        let a = vec![[0, 0, 0], [1, 0, 0], [2, 1, 0], [2, 2, 0]];
        let b = vec![[0, 0, 0], [1, 1, 0], [1, 2, 0], [2, 2, 0]];
        let m = merge_paths(&a, &b, &Open);
        assert_eq!(m, vec![[0, 0, 0], [1, 1, 0], [2, 2, 0]]);
        // Refuse the cross moves: it stays on one of the given paths.
        let m = merge_paths(&a, &b, &|_: Node, _: Node| false);
        assert!(m == a || m == b, "{m:?}");
    }
}
