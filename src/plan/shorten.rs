//! The extensile method's recursive shortening (paper section 4.3, "Recursive Algorithm"):
//! replace k -> k+1 -> k+2 by the straight k -> k+2 wherever the grid nodes around that segment
//! are free, and repeat until nothing shortens.
//!
//! The inspected nodes follow the paper's three conditions, in one rule: sort the axes so that
//! |x-a| >= |y-b| >= |z-c|, let N = |x-a| / d; at each of the N-1 inner steps along the major
//! axis take the line's position on the two minor axes and inspect every node at the floor and
//! the ceiling of each (1 node when both are whole: condition 1; 2 when one is: condition 2; 4
//! otherwise: condition 3). Node inspection alone does not prove the straight move safe between
//! nodes, so a shortcut is also taken only when `accept` (the whole-move safety check, on all
//! six axes with the leg's wrist schedule) holds. A node counts as free when the leg may use it
//! (`usable`: free on the grid, and the tool clear at the leg's wrist there). Waypoints off the
//! grid (cell points) have no nodes around them: there `accept` decides alone.

use crate::plan::cspace::{CSpace, Grid, Node};

/// The nodes the paper inspects for the segment between two grid nodes.
pub fn inspected_nodes(a: Node, b: Node) -> Vec<Node> {
    let delta = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let mut axes = [0usize, 1, 2];
    axes.sort_by_key(|&k| std::cmp::Reverse(delta[k].abs()));
    let [m, s, t] = axes;
    let n = delta[m].abs();
    let mut out = Vec::new();
    for i in 1..n {
        let mut node = a;
        node[m] = a[m] + i * delta[m].signum();
        // Exact rational position a + i * delta / n on each minor axis.
        let minor = |k: usize| {
            let num = a[k] * n + i * delta[k];
            (num.div_euclid(n), (num + n - 1).div_euclid(n))
        };
        let (s0, s1) = minor(s);
        let (t0, t1) = minor(t);
        for sv in [s0, s1] {
            for tv in [t0, t1] {
                let mut q = node;
                q[s] = sv;
                q[t] = tv;
                if !out.contains(&q) {
                    out.push(q);
                }
            }
        }
    }
    out
}

fn on_grid(grid: &Grid, p: &[f64; 3]) -> Option<Node> {
    grid.node_at(p)
}

/// Shortens a path of waypoints (controller values of axes 1..3, deg) in place, recursively,
/// keeping the first and last waypoint. `usable(node)` says whether an inspected node is free for
/// the leg; `accept(from, to)` is the whole-move safety check.
pub fn shorten(
    cs: &CSpace,
    path: &mut Vec<[f64; 3]>,
    usable: &dyn Fn(Node) -> bool,
    accept: &mut dyn FnMut(&[f64; 3], &[f64; 3]) -> bool,
) {
    loop {
        let mut changed = false;
        let mut k = 0;
        while k + 2 < path.len() {
            let (a, b) = (path[k], path[k + 2]);
            let inspected = match (on_grid(&cs.grid, &a), on_grid(&cs.grid, &b)) {
                (Some(na), Some(nb)) => inspected_nodes(na, nb).into_iter().all(usable),
                _ => true,
            };
            if inspected && accept(&a, &b) {
                path.remove(k + 1);
                changed = true;
            } else {
                k += 1;
            }
        }
        if !changed {
            break;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::search::testing::grid;

    #[test]
    fn condition_1_diagonal_inspects_the_nodes_on_the_line() {
        assert_eq!(
            inspected_nodes([0, 0, 0], [3, 3, 3]),
            vec![[1, 1, 1], [2, 2, 2]]
        );
    }

    #[test]
    fn condition_2_inspects_two_nodes_per_step() {
        // |p| = |q| != |r|: x and y move 4, z moves 2.
        let n = inspected_nodes([0, 0, 0], [4, 4, 2]);
        assert_eq!(
            n,
            vec![[1, 1, 0], [1, 1, 1], [2, 2, 1], [3, 3, 1], [3, 3, 2]]
        );
    }

    #[test]
    fn condition_3_inspects_four_nodes_per_step() {
        let n = inspected_nodes([0, 0, 0], [3, 2, 1]);
        // Step 1: y = 2/3, z = 1/3 -> floor/ceil 0/1 each; step 2: y = 4/3, z = 2/3.
        assert_eq!(
            n,
            vec![
                [1, 0, 0],
                [1, 0, 1],
                [1, 1, 0],
                [1, 1, 1],
                [2, 1, 0],
                [2, 1, 1],
                [2, 2, 0],
                [2, 2, 1]
            ]
        );
    }

    #[test]
    fn fig_6a_checks_only_node_e() {
        // A (0,0) -> B (1,1) -> C (2,1): A -> C inspects (1,0) (= E) and (1,1) (= B, on the path).
        assert_eq!(
            inspected_nodes([0, 0, 0], [2, 1, 0]),
            vec![[1, 0, 0], [1, 1, 0]]
        );
    }

    #[test]
    fn negative_directions_mirror() {
        assert_eq!(
            inspected_nodes([3, 2, 0], [0, 0, 0]),
            vec![[2, 1, 0], [2, 2, 0], [1, 0, 0], [1, 1, 0]]
        );
    }

    fn nodes(p: &[[i32; 3]]) -> Vec<[f64; 3]> {
        p.iter()
            .map(|n| [n[0] as f64, n[1] as f64, n[2] as f64])
            .collect()
    }

    #[test]
    fn straightens_a_saw_tooth_in_free_space() {
        let cs = grid(10, 10, 1, |_| true);
        let mut p = nodes(&[
            [0, 0, 0],
            [1, 1, 0],
            [2, 1, 0],
            [3, 2, 0],
            [4, 2, 0],
            [5, 3, 0],
            [6, 3, 0],
        ]);
        shorten(&cs, &mut p, &|n| cs.is_free(n), &mut |_, _| true);
        assert_eq!(p, nodes(&[[0, 0, 0], [6, 3, 0]]));
    }

    #[test]
    fn keeps_a_corner_around_a_blocked_node() {
        // (1,1) blocked: the path (0,0) (1,0) (2,0) (2,1) (2,2) may cut to (2,0)->... but not across (1,1).
        let cs = grid(4, 4, 1, |n| n != [1, 1, 0]);
        let mut p = nodes(&[[0, 0, 0], [1, 0, 0], [2, 0, 0], [2, 1, 0], [2, 2, 0]]);
        shorten(&cs, &mut p, &|n| cs.is_free(n), &mut |_, _| true);
        assert_eq!(p, nodes(&[[0, 0, 0], [2, 0, 0], [2, 2, 0]]));
        // A node the leg may not use (the tool at its wrist) counts as blocked too.
        let cs = grid(4, 4, 1, |_| true);
        let mut p = nodes(&[[0, 0, 0], [1, 0, 0], [2, 0, 0], [2, 1, 0], [2, 2, 0]]);
        shorten(&cs, &mut p, &|n| n != [1, 1, 0], &mut |_, _| true);
        assert_eq!(p, nodes(&[[0, 0, 0], [2, 0, 0], [2, 2, 0]]));
    }

    #[test]
    fn a_refused_move_is_never_taken() {
        let cs = grid(10, 10, 1, |_| true);
        let mut p = nodes(&[[0, 0, 0], [1, 0, 0], [2, 0, 0], [2, 1, 0]]);
        shorten(&cs, &mut p, &|n| cs.is_free(n), &mut |a, b| {
            !(a[0] == 0.0 && b[1] > 0.0)
        });
        assert_eq!(p, nodes(&[[0, 0, 0], [2, 0, 0], [2, 1, 0]]));
    }
}
