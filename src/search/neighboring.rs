//! Neighboring search (paper section 4.1): from the end node, step to the neighbour (26 in 3D)
//! with the smallest number; ties go to the first in the fixed lexicographic order of offsets
//! (d1, d2, d3) in {-1, 0, 1}^3. When a chosen node leads nowhere, back up and take the next.

use super::{descend, Accept, GridPath};
use crate::cspace::{CSpace, Node};
use crate::wave::{self, offsets, Connectivity, Wave};

fn candidates(w: &Wave, n: Node, _prev: Option<[i32; 3]>) -> Vec<[i32; 3]> {
    let mut c: Vec<[i32; 3]> = offsets(Connectivity::TwentySix).to_vec();
    // Stable sort: smallest number first, the fixed order among equals. Unnumbered last.
    c.sort_by_key(|o| match w.label(super::add(n, *o)) {
        0 => u32::MAX,
        l => l,
    });
    c
}

/// The path start -> end on the 26-neighbour wave from `start`, or `None`.
pub fn search(cs: &CSpace, start: Node, end: Node, accept: &mut Accept<'_>) -> Option<GridPath> {
    let w = wave::expand(cs, start, end, Connectivity::TwentySix)?;
    descend(&w, &candidates, accept)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::testing::{assert_path, grid};

    #[test]
    fn finds_a_shortest_path_and_prefers_the_first_offset_in_order() {
        let cs = grid(6, 6, 1, |_| true);
        let p = search(&cs, [0, 0, 0], [5, 2, 0], &mut |_, _| true).expect("path");
        assert_path(&p, [0, 0, 0], [5, 2, 0]);
        assert_eq!(p.len(), 6, "5 steps");
        // Back from (5,2): the first offset in order numbered 5 is (-1,-1,0) -> (4,1), then
        // (-1,-1,0) -> (3,0), then only (-1,0,0) keeps the numbers falling.
        assert_eq!(p[4], [4, 1, 0]);
        assert_eq!(p[3], [3, 0, 0]);
    }

    #[test]
    fn backs_up_when_a_step_is_refused() {
        let cs = grid(4, 4, 1, |_| true);
        // Back from (3,1) the first choice is (2,0); refuse every move into it.
        let open = search(&cs, [0, 0, 0], [3, 1, 0], &mut |_, _| true).expect("path");
        assert_eq!(open[2], [2, 0, 0]);
        let p = search(&cs, [0, 0, 0], [3, 1, 0], &mut |_, to| to != [2, 0, 0]);
        let p = p.expect("path around the refused node");
        assert_path(&p, [0, 0, 0], [3, 1, 0]);
        assert!(!p.contains(&[2, 0, 0]));
        // Along the diagonal every descending path passes (1,1): refusing it leaves none.
        assert!(search(&cs, [0, 0, 0], [3, 3, 0], &mut |_, to| to != [1, 1, 0]).is_none());
    }
}
