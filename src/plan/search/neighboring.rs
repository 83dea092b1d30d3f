//! Neighboring search (paper section 4.1): from the end node, step to the neighbour (26 in 3D)
//! with the smallest number. When a chosen node leads nowhere, back up and take the next.
//!
//! The tie-break (the paper gives none; on a 26-neighbour wave every candidate carries n-1):
//! among the smallest numbers, the neighbour nearest the start node (squared grid distance),
//! then the fixed lexicographic order of offsets (d1, d2, d3) in {-1, 0, 1}^3. Heading for the
//! target is what one does when the numbers do not decide, and unlike an order of offsets it
//! treats the axes and their directions alike (a mirrored cell gets the mirrored path). In open
//! space it gives a diagonal run and then a straight one; where the wave front bends around an
//! obstacle the nearest neighbour flips from step to step, and the path follows the grid
//! squares along the obstacle's edge: the saw-tooth of the paper's Fig. 6, with many short
//! moves, which the extensile method's shortening straightens.

use super::{descend, GridPath, SearchFailure};
use crate::plan::cspace::{CSpace, Node};
use crate::plan::wave::{self, offsets, Connectivity, Graph, Wave};

pub(crate) fn candidates(w: &Wave, n: Node, here: u32, _prev: Option<[i32; 3]>) -> Vec<[i32; 3]> {
    let mut c: Vec<[i32; 3]> = offsets(Connectivity::TwentySix).to_vec();
    // Stable sort (each key read once): smallest number first; among equals the node nearest
    // the start node (squared grid distance), then the fixed order. Unnumbered last.
    c.sort_by_cached_key(|o| {
        let m = super::add(n, *o);
        let label = match w.label_next_to(m, here) {
            0 => u32::MAX,
            l => l,
        };
        let d2: i64 = (0..3).map(|k| i64::from(m[k] - w.start[k]).pow(2)).sum();
        (label, d2)
    });
    c
}

/// The path start -> end on the 26-neighbour wave of `graph` from `start`. The walk back only
/// steps to neighbours numbered one less, so the wave numbers only the nodes on shortest paths
/// between the ends where it can ([`wave::expand_corridor`]): the same steps.
pub fn search<G: Graph>(
    cs: &CSpace,
    start: Node,
    end: Node,
    graph: &G,
) -> Result<GridPath, SearchFailure> {
    let w = wave::expand_corridor(cs, graph, start, end, Connectivity::TwentySix)
        .ok_or(SearchFailure::NotConnected)?;
    descend(&w, &candidates, graph).ok_or(SearchFailure::WalkFailed { steps: w.n() - 1 })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::search::testing::{assert_path, grid, refusing_cases};
    use crate::plan::wave::Open;

    /// Where the graph refuses nodes and steps, the search over the wave of the shortest
    /// paths' nodes gives the same path, or the same failure, as over the whole wave.
    #[test]
    fn the_corridor_wave_changes_no_search() {
        let (mut found, mut failed) = (0, 0);
        for (cs, graph, start, end) in refusing_cases() {
            let got = search(&cs, start, end, &graph);
            let whole = wave::expand(&cs, &graph, start, end, Connectivity::TwentySix)
                .ok_or(SearchFailure::NotConnected)
                .and_then(|w| {
                    let steps = w.n() - 1;
                    descend(&w, &candidates, &graph).ok_or(SearchFailure::WalkFailed { steps })
                });
            assert_eq!(got, whole, "{end:?}");
            match got {
                Ok(_) => found += 1,
                Err(_) => failed += 1,
            }
        }
        assert!(found >= 20 && failed >= 1, "found {found}, failed {failed}");
    }

    #[test]
    fn finds_a_shortest_path_heading_for_the_start() {
        let cs = grid(6, 6, 1, |_| true);
        let p = search(&cs, [0, 0, 0], [5, 2, 0], &Open).expect("path");
        assert_path(&p, [0, 0, 0], [5, 2, 0]);
        assert_eq!(p.len(), 6, "5 steps");
        // Back from (5,2) the nodes numbered 5 are (4,1), (4,2), (4,3): (4,1) is nearest the
        // start (17 against 20 and 25); then (3,0) (9 against 10, 13); then along axis 1.
        assert_eq!(p[4], [4, 1, 0]);
        assert_eq!(p[3], [3, 0, 0]);
    }

    #[test]
    fn zig_zags_along_a_wall_the_saw_tooth_of_fig_6() {
        // A wall across axis 1 at x = 4 with a gap at y >= 6; start (0, 0), end (8, 0). Back
        // from the end the path climbs to the gap and comes down again; on the way the nearest
        // neighbour to the start alternates, so it holds no direction for long.
        let cs = grid(9, 9, 1, |n| n[0] != 4 || n[1] >= 6);
        let p = search(&cs, [0, 0, 0], [8, 0, 0], &Open).expect("path");
        assert_path(&p, [0, 0, 0], [8, 0, 0]);
        assert!(p.iter().all(|n| n[0] != 4 || n[1] >= 6));
        let turns = p
            .windows(3)
            .filter(|w| (0..3).any(|k| w[1][k] - w[0][k] != w[2][k] - w[1][k]))
            .count();
        let ext = crate::plan::search::extensile::one_way(&cs, [0, 0, 0], [8, 0, 0], &Open)
            .expect("path");
        let ext_turns = ext
            .windows(3)
            .filter(|w| (0..3).any(|k| w[1][k] - w[0][k] != w[2][k] - w[1][k]))
            .count();
        assert!(
            turns > ext_turns,
            "neighboring {turns} turns {p:?}, extensile walk {ext_turns} {ext:?}"
        );
    }

    #[test]
    fn mirrored_cells_get_mirrored_paths() {
        // An obstacle off-centre: the path for the mirrored grid is the mirror image.
        let cs = grid(9, 9, 1, |n| !(n[0] == 4 && (2..=7).contains(&n[1])));
        let mirrored = grid(9, 9, 1, |n| !(n[0] == 4 && (1..=6).contains(&n[1])));
        let p = search(&cs, [0, 4, 0], [8, 4, 0], &Open).expect("path");
        let q = search(&mirrored, [0, 4, 0], [8, 4, 0], &Open).expect("path");
        let flipped: Vec<_> = q.iter().map(|n| [n[0], 8 - n[1], n[2]]).collect();
        assert_eq!(p, flipped);
    }

    #[test]
    fn refused_steps_are_not_in_the_graph_and_the_wave_goes_around() {
        let cs = grid(4, 4, 1, |_| true);
        // Back from (3,1) the first choice is (2,0); refuse every step into or out of it.
        let open = search(&cs, [0, 0, 0], [3, 1, 0], &Open).expect("path");
        assert_eq!(open[2], [2, 0, 0]);
        let avoid = |n: Node| move |a: Node, b: Node| a != n && b != n;
        let p = search(&cs, [0, 0, 0], [3, 1, 0], &avoid([2, 0, 0]));
        let p = p.expect("path around the refused node");
        assert_path(&p, [0, 0, 0], [3, 1, 0]);
        assert!(!p.contains(&[2, 0, 0]));
        // Along the diagonal every 3-step path passes (1,1); with its steps refused the wave
        // numbers around it and the search takes the longer way (a walk on the wave that
        // numbered over the refused steps would give up here).
        let p = search(&cs, [0, 0, 0], [3, 3, 0], &avoid([1, 1, 0])).expect("around (1,1)");
        assert_path(&p, [0, 0, 0], [3, 3, 0]);
        assert!(!p.contains(&[1, 1, 0]) && p.len() == 5, "{p:?}");
        // No step crosses from axis-1 index 1 to 2: not connected, though every node is free.
        let wall = |a: Node, b: Node| (a[0] <= 1) == (b[0] <= 1);
        assert_eq!(
            search(&cs, [0, 0, 0], [3, 3, 0], &wall),
            Err(SearchFailure::NotConnected)
        );
    }
}
