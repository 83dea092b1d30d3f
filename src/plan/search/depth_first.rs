//! Depth-first search (paper section 4.2): from the end node, only the 6 axis neighbours whose
//! number is exactly one less, tried depth first, backing up on dead ends. The order is fixed:
//! the direction of the previous step first (so runs stay straight and merge into one move),
//! then -axis1, -axis2, -axis3, +axis3, +axis2, +axis1 (the order of [`crate::plan::wave::offsets`]).
//!
//! It walks axis steps, so the wave it descends is numbered over the 6 axis neighbours (the
//! graph's axis steps: those the whole-move check accepts). It fails (the paper's Fig. 8) when
//! the start and end are joined only through diagonal steps; the plan then reports the leg.
//! Same-direction steps are merged afterwards by `merge`.

use super::{descend, GridPath, SearchFailure};
use crate::plan::cspace::{CSpace, Node};
use crate::plan::wave::{self, offsets, Connectivity, Graph, Wave};

pub(crate) fn candidates(w: &Wave, n: Node, label: u32, prev: Option<[i32; 3]>) -> Vec<[i32; 3]> {
    let want = label.saturating_sub(1);
    let mut c: Vec<[i32; 3]> = offsets(Connectivity::Six)
        .iter()
        .copied()
        .filter(|o| w.label_next_to(super::add(n, *o), label) == want)
        .collect();
    // The previous direction first: the stable sort keeps the fixed order among the rest.
    c.sort_by_key(|o| Some(*o) != prev);
    c
}

/// The path start -> end by axis steps of `graph`. When the axis-step wave cannot reach the
/// end, a 26-neighbour wave tells whether the graph joins the nodes only through diagonal steps
/// (the paper's Fig. 8: [`SearchFailure::OnlyDiagonal`]) or not at all
/// ([`SearchFailure::NotConnected`]). The walk back only steps to axis neighbours numbered one
/// less, so the axis-step wave numbers only the nodes on shortest axis-step paths between the
/// ends where it can ([`wave::expand_corridor`]): the same steps.
pub fn search<G: Graph>(
    cs: &CSpace,
    start: Node,
    end: Node,
    graph: &G,
) -> Result<GridPath, SearchFailure> {
    let Some(w) = wave::expand_corridor(cs, graph, start, end, Connectivity::Six) else {
        return Err(
            match wave::expand(cs, graph, start, end, Connectivity::TwentySix) {
                Some(_) => SearchFailure::OnlyDiagonal,
                None => SearchFailure::NotConnected,
            },
        );
    };
    descend(&w, &candidates, graph).ok_or(SearchFailure::WalkFailed { steps: w.n() - 1 })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::search::testing::{assert_path, grid, refusing_cases};
    use crate::plan::wave::Open;

    /// Where the graph refuses nodes and steps, the search over the axis-step wave of the
    /// shortest paths' nodes gives the same path, or the same failure, as over the whole wave.
    #[test]
    fn the_corridor_wave_changes_no_search() {
        let (mut found, mut failed) = (0, 0);
        for (cs, graph, start, end) in refusing_cases() {
            let got = search(&cs, start, end, &graph);
            let whole = match wave::expand(&cs, &graph, start, end, Connectivity::Six) {
                Some(w) => {
                    let steps = w.n() - 1;
                    descend(&w, &candidates, &graph).ok_or(SearchFailure::WalkFailed { steps })
                }
                None => Err(
                    match wave::expand(&cs, &graph, start, end, Connectivity::TwentySix) {
                        Some(_) => SearchFailure::OnlyDiagonal,
                        None => SearchFailure::NotConnected,
                    },
                ),
            };
            assert_eq!(got, whole, "{end:?}");
            match got {
                Ok(_) => found += 1,
                Err(_) => failed += 1,
            }
        }
        assert!(found >= 20 && failed >= 1, "found {found}, failed {failed}");
    }

    #[test]
    fn walks_axis_steps_in_the_fixed_order() {
        let cs = grid(5, 5, 5, |_| true);
        let p = search(&cs, [0, 0, 0], [2, 1, 1], &Open).expect("path");
        assert_path(&p, [0, 0, 0], [2, 1, 1]);
        assert_eq!(p.len(), 5, "4 axis steps");
        // Back from the end: -axis1 twice first, then -axis2, then -axis3.
        assert_eq!(
            p,
            vec![[0, 0, 0], [0, 0, 1], [0, 1, 1], [1, 1, 1], [2, 1, 1]]
        );
    }

    #[test]
    fn fails_where_only_a_diagonal_joins_the_free_space() {
        // Fig. 8: the free nodes touch only at a corner.
        let cs = grid(3, 3, 1, |n| n[0] == n[1]);
        let err = search(&cs, [0, 0, 0], [2, 2, 0], &Open);
        assert_eq!(err, Err(SearchFailure::OnlyDiagonal));
        // Not joined at all: no method could.
        let cs = grid(3, 3, 1, |n| n[0] != 1);
        let err = search(&cs, [0, 0, 0], [2, 2, 0], &Open);
        assert_eq!(err, Err(SearchFailure::NotConnected));
    }
}
