//! Path search back from the end node over a wave-numbered grid (paper section 4).
//!
//! The three methods of the paper share one walk: start at the end node (number n) and step to
//! a neighbour with a smaller number until the start node (number 1) is reached; when a chosen
//! node leads nowhere, back up and take the next candidate (section 4.1). They differ in which
//! neighbours they look at and in what order:
//!
//! * [`neighboring`] (4.1): the 26 neighbours, smallest number first, ties to the neighbour
//!   nearest the start node. Along obstacles it follows the grid squares and so produces the
//!   saw-tooth of Fig. 6.
//! * [`depth_first`] (4.2): the 6 axis neighbours whose number is exactly one less, in a fixed
//!   order, depth first. It walks axis steps, so it runs on a wave numbered over the 6 axis
//!   neighbours (on a 26-neighbour wave a chain of axis steps, each one number lower, exists only
//!   along a single axis). It fails (Fig. 8) where the free space is joined only diagonally.
//! * [`extensile`] (4.3): the 26 neighbours; where no axis neighbour carries n-1 it takes a
//!   diagonal one. In the paper's 2D figures the wave counts axis steps, so a diagonal neighbour
//!   is two numbers down ("it also considers n-2", Fig. 8); on our 26-neighbour wave the same
//!   node carries n-1, and the rule reads "axis neighbours first, then diagonals". It keeps the
//!   previous direction when it can, searches both ways (waves from either end) and merges the
//!   two paths (Fig. 4-5); `shorten` then straightens it.
//!
//! The searches run on a [`Graph`] (`wave`): its steps are the ones the whole-move check
//! accepts, and the wave numbers nodes over accepted steps only (a leg first tries an
//! optimistic wave numbered over every step between usable nodes and falls back to this one
//! where the walk on it runs out: `leg`). Every step of a walk is again
//! a step of the graph, so every edge of a returned path is a proven-safe straight move; and
//! since every numbered node has an accepted step one number down, the walk never runs out
//! (**complete on its grid**, beyond the paper): if the graph joins the two nodes, the
//! neighboring and extensile searches find a path. The only failure left to them is
//! [`SearchFailure::NotConnected`]. The depth-first search lives on the graph's axis steps; it
//! fails, as in the paper's Fig. 8, where the graph joins the nodes only through diagonal steps
//! ([`SearchFailure::OnlyDiagonal`]).

pub mod depth_first;
pub mod extensile;
pub mod neighboring;

/// The searches' names, as the cell chooses one ([`Method`], `planner.method`).
pub use crate::cell::Method;

/// The searches themselves (the names are the cell's).
impl Method {
    /// The path `start -> end` by this method on the inspected grid `cs`, over the nodes and
    /// steps of `graph` (the whole-move check decides which steps exist).
    pub fn search<G: Graph>(
        self,
        cs: &CSpace,
        start: Node,
        end: Node,
        graph: &G,
    ) -> Result<GridPath, SearchFailure> {
        match self {
            Method::Neighboring => neighboring::search(cs, start, end, graph),
            Method::DepthFirst => depth_first::search(cs, start, end, graph),
            Method::Extensile => extensile::search(cs, start, end, graph),
        }
    }
}

/// Why a search found no path; the wave of the search's first expansion tells, so nobody
/// expands a wave again to find out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SearchFailure {
    /// The graph (free nodes, accepted steps, 26 neighbours) does not join the two nodes: no
    /// method can.
    NotConnected,
    /// The depth-first search: the graph joins the nodes, but not through axis steps (the
    /// paper's Fig. 8).
    OnlyDiagonal,
    /// The walk back found no step: impossible on a wave of the same graph (module doc); on
    /// a leg's optimistic wave, the sign to number the eager one. `steps`: the ends' distance
    /// on the wave walked, a floor of their distance over the steps the walk may take.
    WalkFailed { steps: u32 },
}

use crate::plan::cspace::{CSpace, Node};
use crate::plan::wave::{Graph, Wave};
use std::collections::HashSet;

/// A path of grid nodes from the start node to the end node, each step to a neighbour.
pub type GridPath = Vec<Node>;

/// A method's neighbour order: the offsets to try from `node`, best first, given its number
/// (the neighbours' numbers read from it: [`Wave::label_next_to`]) and the offset of the step
/// that led there.
pub(crate) type Candidates = dyn Fn(&Wave, Node, u32, Option<[i32; 3]>) -> Vec<[i32; 3]>;

#[inline]
pub(crate) fn add(n: Node, o: [i32; 3]) -> Node {
    [n[0] + o[0], n[1] + o[1], n[2] + o[2]]
}

/// Number of axes an offset moves (1 axis step, 2 face diagonal, 3 corner diagonal).
#[inline]
pub(crate) fn order_of(o: [i32; 3]) -> usize {
    o.iter().filter(|&&c| c != 0).count()
}

/// The shared walk. `candidates(node, number, previous_offset)` lists the neighbours to try,
/// best first; only those with a number strictly between 0 and the current node's and a step of
/// `graph` are taken. Returns the path from the wave's start to its end, or `None` when every
/// branch dead-ends (never, on a wave of the same graph: module doc).
///
/// The walk carries the number of the node it stands on (n at the end; a step taken leads to a
/// number one less) and reads a neighbour's number from it ([`Wave::label_next_to`]). That
/// reading is exact for every neighbour joined by a step of the wave, so for every step the walk
/// can take (a method lists neighbours of the wave's connectivity, and `graph.step_ok` accepts
/// only wave steps among them) and for every numbered neighbour of the row wave (which keeps
/// only residues). A neighbour of a wave with fewer steps than that, numbered but not joined by
/// a wave step, could read wrongly if that wave kept residues (the node-by-node waves keep
/// numbers); it is never taken (`step_ok` refuses it), and the stable sorts of the candidates
/// keep the others in their order.
pub(crate) fn descend<G: Graph + ?Sized>(
    wave: &Wave,
    candidates: &Candidates,
    graph: &G,
) -> Option<GridPath> {
    struct Frame {
        node: Node,
        /// The node's number.
        label: u32,
        options: Vec<[i32; 3]>,
        next: usize,
    }
    let first = candidates(wave, wave.end, wave.n(), None);
    let mut stack = vec![Frame {
        node: wave.end,
        label: wave.n(),
        options: first,
        next: 0,
    }];
    let mut dead: HashSet<Node> = HashSet::new();
    while let Some(top) = stack.last_mut() {
        if top.node == wave.start {
            let mut path: GridPath = stack.iter().map(|f| f.node).collect();
            path.reverse();
            return Some(path);
        }
        let here = top.node;
        let label = top.label;
        let mut chosen = None;
        while top.next < top.options.len() {
            let o = top.options[top.next];
            top.next += 1;
            let m = add(here, o);
            let l = wave.label_next_to(m, label);
            if l == 0 || l >= label || dead.contains(&m) {
                continue;
            }
            if graph.step_ok(here, m) {
                chosen = Some((m, o, l));
                break;
            }
        }
        match chosen {
            Some((m, o, l)) => {
                let options = candidates(wave, m, l, Some(o));
                stack.push(Frame {
                    node: m,
                    label: l,
                    options,
                    next: 0,
                });
            }
            None => {
                dead.insert(here);
                stack.pop();
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::testing::{assert_path, grid};
    use super::*;
    use crate::plan::wave::{self, offsets, Connectivity};

    /// A wave over accepted steps only (as the eager wave is) where the walk passes nodes with
    /// a numbered neighbour not joined by an accepted step and numbered two more or two less:
    /// kept as residues, such a neighbour reads one less or one more than it is, some as one
    /// less than the node the walk stands on. The walk of each method on the residues never
    /// takes one: it returns the path it returns on the numbers, every step accepted.
    #[test]
    fn a_walk_on_residues_never_takes_a_neighbour_they_misread() {
        // No step crosses between axis-1 indices 1 and 2 below axis-2 index 4: the wave from
        // (0, 0) climbs the left strip, crosses at the top and comes down the right one.
        let cs = grid(6, 7, 1, |_| true);
        let graph = |a: Node, b: Node| (a[0] <= 1) == (b[0] <= 1) || (a[1] >= 4 && b[1] >= 4);
        let (start, end) = ([0, 0, 0], [3, 0, 0]);
        let methods: [(&str, &Candidates, Connectivity); 3] = [
            (
                "neighboring",
                &neighboring::candidates,
                Connectivity::TwentySix,
            ),
            ("extensile", &extensile::candidates, Connectivity::TwentySix),
            ("depth-first", &depth_first::candidates, Connectivity::Six),
        ];
        for (name, candidates, conn) in methods {
            let mut misleading = 0;
            let numbers = wave::expand(&cs, &graph, start, end, conn).expect("joined");
            let residues = numbers.as_residues();
            let p = descend(&numbers, candidates, &graph).expect("a path");
            assert_path(&p, start, end);
            assert!(p.windows(2).all(|s| graph(s[0], s[1])), "{name}: {p:?}");
            let q = descend(&residues, candidates, &graph);
            assert_eq!(q.as_ref(), Some(&p), "{name}");
            // The neighbours along the path that the residues misread as one less, of the
            // wave's connectivity (the depth-first walk lists only axis neighbours; a diagonal
            // one of its wave may be joined by an accepted step, never by a wave step).
            for &x in &p {
                let l = numbers.label_next_to(x, 1);
                for o in offsets(conn) {
                    let m = add(x, *o);
                    let (exact, read) = (numbers.label_next_to(m, 1), residues.label_next_to(m, l));
                    if exact > 0 && read != exact && read + 1 == l {
                        assert!(!graph(x, m), "{name}: {x:?} -> {m:?} accepted");
                        misleading += 1;
                    }
                }
            }
            assert!(
                misleading > 0,
                "{name}: no misleading neighbour, nothing tested"
            );
        }
    }
}

#[cfg(test)]
pub(crate) mod testing {
    use crate::plan::cspace::{CSpace, Grid, Node};
    use crate::plan::wave::Graph;

    /// A fixed pseudo-random sequence (xorshift64) from a nonzero `seed`.
    pub fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        }
    }

    /// A grid of `nx` x `ny` x `nz` nodes at 1 deg, free where `free` says.
    pub fn grid(nx: usize, ny: usize, nz: usize, free: impl Fn(Node) -> bool) -> CSpace {
        let g = Grid::over(
            [
                [0.0, nx as f64 - 1.0],
                [0.0, ny as f64 - 1.0],
                [0.0, nz as f64 - 1.0],
            ],
            1.0,
        );
        CSpace::from_fn(g, free)
    }

    /// A fixed pseudo-random number of a node (or any three integers) and a salt.
    pub fn hash(v: [i32; 3], salt: u32) -> u32 {
        let h = (v[0] as u32).wrapping_mul(73_856_093)
            ^ (v[1] as u32).wrapping_mul(19_349_663)
            ^ (v[2] as u32).wrapping_mul(83_492_791)
            ^ salt.wrapping_mul(2_246_822_519);
        h.wrapping_mul(2_654_435_761) >> 5
    }

    /// A graph like a leg's optimistic one: one node in `every` refused (scattered), and, when
    /// `steps`, one step in 5 refused when walked, though the wave counts every step between
    /// usable nodes.
    pub struct Refusing {
        pub salt: u32,
        pub every: u32,
        pub steps: bool,
    }

    impl Graph for Refusing {
        fn node_ok(&self, n: Node) -> bool {
            hash(n, self.salt) % self.every != 0
        }
        fn step_ok(&self, a: Node, b: Node) -> bool {
            let (lo, hi) = if a < b { (a, b) } else { (b, a) };
            let key = [lo[0] * 3 + hi[0], lo[1] * 5 + hi[1], lo[2] * 7 + hi[2]];
            !self.steps || hash(key, self.salt + 1) % 5 != 0
        }
        fn wave_step_ok(&self, _: Node, _: Node) -> bool {
            true
        }
        fn wave_steps_all(&self) -> bool {
            true
        }
    }

    /// Searches on three grids of scattered blocked nodes with a [`Refusing`] graph, from a
    /// corner to many usable ends (joined or not): (grid, graph, start, end).
    pub fn refusing_cases() -> Vec<(CSpace, Refusing, Node, Node)> {
        let mut cases = Vec::new();
        for salt in 1..4u32 {
            let cs = grid(14, 12, 70, |n| hash(n, salt + 50) % 5 != 0);
            let graph = |salt| Refusing {
                salt,
                every: 9,
                steps: true,
            };
            let start = [0, 0, 0];
            for k in 0..40 {
                let end = [(k * 5) % 14, (k * 7) % 12, (k * 13) % 70];
                if [start, end]
                    .iter()
                    .all(|&n| cs.is_free(n) && graph(salt).node_ok(n))
                {
                    cases.push((cs.clone(), graph(salt), start, end));
                }
            }
        }
        cases
    }

    /// Every step moves to a neighbour; ends are right.
    pub fn assert_path(p: &[Node], start: Node, end: Node) {
        assert_eq!(p.first(), Some(&start));
        assert_eq!(p.last(), Some(&end));
        for w in p.windows(2) {
            let d: Vec<i32> = (0..3).map(|k| (w[1][k] - w[0][k]).abs()).collect();
            assert!(
                d.iter().all(|&x| x <= 1) && d.contains(&1),
                "{:?} -> {:?}",
                w[0],
                w[1]
            );
        }
    }
}
