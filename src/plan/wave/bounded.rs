//! The node-by-node wave of a graph that knows a floor of its ends' distance
//! ([`Graph::steps_floor`]: a leg's eager graph, whose optimistic wave numbered the ends at that
//! distance over a graph that holds it), bounded as A* is ([`number_scalar`]). A wave over
//! accepted steps asks the step proof at every node it numbers; the bound keeps it to the nodes
//! between the ends rather than the ball around its start.
//!
//! *The estimate.* Over 26 neighbours, a node's steps to the end over every step between usable
//! nodes ([`Every`]), numbered by a row wave from the end ([`Ahead`]; bitwise, no proofs, the
//! same tool looks the wave needs, its residues kept: 2 bits a node): no more than its steps
//! over the graph's (which are among them), and consistent (neighbours' distances differ by at
//! most one). Where a wave is forced round a few refused steps, that keeps it within about
//! those few steps of the shortest paths, where the ends' grid steps (the largest index difference, which the estimate never falls
//! below) would keep the whole region the obstacles' detour leaves room for. The row wave is
//! itself bounded by the grid steps to the wave's start (a node it leaves out lies on no path
//! within its bound: its estimate is "too far"). Over 6 neighbours the estimate is the sum of the
//! index differences.
//!
//! *The bound.* First the floor (or the ends' grid steps, if more). Every try with a bound no
//! less than the ends' distance gives the numbers of the whole wave on the shortest paths between
//! the ends, so the walks back take the same steps ([`number_scalar`]). A try that runs out
//! having left nodes out is numbered again with the bound grown by 1, 2, 4, ... steps, the
//! steps it asked kept ([`Remembered`]), so a try again costs the wave's bookkeeping, not the
//! proofs; after [`TRIES`] tries the wave is numbered whole. One that runs out having left
//! nothing out has numbered everything the start reaches: the ends are not joined.
//!
//! [`number_scalar`]: super::queue::number_scalar

use super::queue::grid_steps;
use super::rows::{Level, RowWave};
use super::{number_nodes, Bound, Connectivity, Graph, Labels, Pruned, Wave};
use crate::plan::cspace::{CSpace, Node};
use std::collections::HashMap;
use std::sync::Mutex;

/// Bounded tries before the wave is numbered whole (the bound grown by 1, 2, 4, ... steps: up to
/// 63 steps over the floor).
const TRIES: usize = 7;

/// The labels and the end's number of the wave from `start` to `end` over `connectivity`,
/// bounded from `floor` up (module doc); `None` when the end cannot be reached.
pub(super) fn number<G: Graph + ?Sized>(
    cs: &CSpace,
    graph: &G,
    start: Node,
    end: Node,
    connectivity: Connectivity,
    floor: u32,
) -> Option<(Labels, u32)> {
    let remembered = Remembered {
        graph,
        cs,
        steps: Mutex::new(HashMap::new()),
    };
    let mut steps = floor.max(grid_steps(start, end, connectivity));
    let mut grow = 1u32;
    let mut ahead: Option<Ahead> = None;
    let grid = |m: Node, _: u32| grid_steps(m, end, connectivity);
    for _ in 0..TRIES {
        if connectivity == Connectivity::TwentySix && ahead.as_ref().is_none_or(|a| a.steps < steps)
        {
            // Room for the next two tries (the bound grown by `grow`, then twice that): a wider
            // reach numbers more of the open side's ball.
            let reach = steps.saturating_add(3 * grow);
            ahead = Some(Ahead::new(cs, graph, end, start, reach));
        }
        let next_to = |m: Node, h: u32| ahead.as_ref().map_or(u32::MAX, |a| a.steps_next_to(m, h));
        let bound = match ahead.as_ref().and_then(|a| a.start) {
            Some(h) => Bound {
                steps,
                start: h,
                estimate: &next_to,
            },
            None => Bound {
                steps,
                start: grid_steps(start, end, connectivity),
                estimate: &grid,
            },
        };
        match number_nodes(cs, &remembered, start, end, connectivity, Some(bound)) {
            Ok(numbered) => return numbered,
            Err(Pruned) => {
                steps = steps.saturating_add(grow);
                grow = grow.saturating_mul(2);
            }
        }
    }
    number_nodes(cs, &remembered, start, end, connectivity, None).ok()?
}

/// Every node's steps to one end over every step between the graph's usable nodes (the module
/// doc's estimate), for the nodes within a bound: the residues of a row wave from that end
/// (2 bits a node, as the row waves keep them), read next to a node whose steps are known (the
/// node-by-node wave carries them from its start, whose steps the row wave gives): a step
/// between usable nodes changes them by at most one.
struct Ahead {
    /// The row wave's residues, from the end.
    wave: Wave,
    /// The other end's (the node-by-node wave's start's) steps, if the row wave numbered it.
    start: Option<u32>,
    /// The bound: a node whose steps from the end plus its grid steps to the other end exceed
    /// it was left out.
    steps: u32,
}

impl Ahead {
    /// The steps from `from` over [`Every`] step of `graph`, for the nodes whose steps plus
    /// their grid steps to `toward` are at most `steps`.
    fn new<G: Graph + ?Sized>(
        cs: &CSpace,
        graph: &G,
        from: Node,
        toward: Node,
        steps: u32,
    ) -> Ahead {
        let every = Every(graph);
        let (labels, start) =
            by_row_words!(cs, residues::<Every<G>>(cs, &every, from, toward, steps));
        Ahead {
            wave: Wave {
                start: from,
                end: toward,
                connectivity: Connectivity::TwentySix,
                labels,
                dims: cs.grid.dims,
                n: 0,
            },
            start,
            steps,
        }
    }

    /// The steps of node `m`, a usable neighbour of a node `h` steps from the end;
    /// `u32::MAX` for a node left out.
    #[inline]
    fn steps_next_to(&self, m: Node, h: u32) -> u32 {
        match self.wave.label_next_to(m, h.saturating_add(1)) {
            0 => u32::MAX,
            l => l - 1,
        }
    }
}

/// [`Ahead::new`]'s row wave from `from` bounded by `steps` toward `toward`, numbered until it
/// runs out: its residues, and the steps at which it numbered `toward`.
fn residues<G: Graph + ?Sized, const K: usize>(
    cs: &CSpace,
    graph: &G,
    from: Node,
    toward: Node,
    steps: u32,
) -> (Labels, Option<u32>) {
    let g = &cs.grid;
    let (first, target) = (g.index(from), g.index(toward));
    let mut wave =
        RowWave::<G, K>::new(cs, graph, first, None, false).bounded(toward, i64::from(steps));
    let (words, d2) = (wave.reach.words, g.dims[2]);
    let (word, bit) = (
        (target / d2) * words + (target % d2) / 64,
        1u64 << ((target % d2) % 64),
    );
    let mut at = (first == target).then_some(0);
    while let Level::Numbered = wave.next_level() {
        if at.is_none() && wave.front.iter().any(|&(w, b)| w == word && b & bit != 0) {
            at = Some(wave.level - 1);
        }
    }
    (wave.labels(), at)
}

/// A graph's usable nodes with every step between them (the optimistic graph of any graph).
struct Every<'a, G: ?Sized>(&'a G);

impl<G: Graph + ?Sized> Graph for Every<'_, G> {
    fn node_ok(&self, n: Node) -> bool {
        self.0.node_ok(n)
    }

    fn node_ok_coded(&self, n: Node, code: u8) -> bool {
        self.0.node_ok_coded(n, code)
    }

    fn step_ok(&self, _: Node, _: Node) -> bool {
        true
    }

    fn wave_steps_all(&self) -> bool {
        true
    }

    fn look_bits(&self) -> Option<u8> {
        self.0.look_bits()
    }
}

/// The most steps a bounded wave remembers (about 40 bytes each with the map's own share: some
/// 20 MB), so a leg's memory does not grow with the grid.
const REMEMBERED_STEPS: usize = 1 << 19;

/// A graph's wave steps, each asked once over the tries of one bounded wave (up to
/// [`REMEMBERED_STEPS`]); the rest is the graph's.
struct Remembered<'a, G: ?Sized> {
    graph: &'a G,
    cs: &'a CSpace,
    /// Per step (its two grid indices, lower first), the graph's answer.
    steps: Mutex<HashMap<(usize, usize), bool>>,
}

impl<G: Graph + ?Sized> Graph for Remembered<'_, G> {
    fn node_ok(&self, n: Node) -> bool {
        self.graph.node_ok(n)
    }

    fn node_ok_coded(&self, n: Node, code: u8) -> bool {
        self.graph.node_ok_coded(n, code)
    }

    fn step_ok(&self, a: Node, b: Node) -> bool {
        self.graph.step_ok(a, b)
    }

    /// The graph's answer, asked once per step (a wave step is symmetric, as `step_ok` is).
    fn wave_step_ok(&self, a: Node, b: Node) -> bool {
        let (i, j) = (self.cs.grid.index(a), self.cs.grid.index(b));
        let key = (i.min(j), i.max(j));
        let known = self.steps.lock().ok().and_then(|s| s.get(&key).copied());
        if let Some(answer) = known {
            return answer;
        }
        let answer = self.graph.wave_step_ok(a, b);
        if let Ok(mut s) = self.steps.lock() {
            // Past the cap a step is asked again on a later try: the same answer, at the cost
            // of its proof, and the memory stays bounded whatever the grid.
            if s.len() < REMEMBERED_STEPS {
                s.insert(key, answer);
            }
        }
        answer
    }

    fn look_bits(&self) -> Option<u8> {
        self.graph.look_bits()
    }
}

#[cfg(test)]
mod tests {
    use super::super::{expand, Connectivity, Graph};
    use crate::plan::cspace::Node;
    use crate::plan::search::testing::{refusing_cases, Refusing};
    use crate::plan::search::{Method, SearchFailure};
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// [`Refusing`]'s graph numbered over its accepted steps only (as a leg's eager graph is),
    /// with a floor or none, counting the steps its waves ask.
    struct Eager<'a> {
        graph: &'a Refusing,
        floor: Option<u32>,
        asked: AtomicUsize,
    }

    impl Graph for Eager<'_> {
        fn node_ok(&self, n: Node) -> bool {
            self.graph.node_ok(n)
        }
        fn step_ok(&self, a: Node, b: Node) -> bool {
            self.graph.step_ok(a, b)
        }
        fn wave_step_ok(&self, a: Node, b: Node) -> bool {
            self.asked.fetch_add(1, Ordering::Relaxed);
            self.graph.step_ok(a, b)
        }
        fn steps_floor(&self) -> Option<u32> {
            self.floor
        }
    }

    /// Every method on the graph over accepted steps, bounded from a floor (none, the ends'
    /// distance over every step, which the optimistic wave gives, and 0), gives the path or the
    /// failure it gives on the whole waves; the bounded waves of the extensile search ask under
    /// three fifths of the steps (about half, on these small grids that one step in five
    /// refused sends round long detours).
    #[test]
    fn bounded_waves_search_as_the_whole_ones_and_ask_fewer_steps() {
        let (mut whole_asked, mut bounded_asked, mut detours) = (0, 0, 0);
        for (cs, graph, start, end) in refusing_cases() {
            let eager = |floor| Eager {
                graph: &graph,
                floor,
                asked: AtomicUsize::new(0),
            };
            let optimistic =
                expand(&cs, &graph, start, end, Connectivity::TwentySix).map(|w| w.n() - 1);
            for method in Method::ALL {
                let plain = eager(None);
                let whole = method.search(&cs, start, end, &plain);
                for floor in [optimistic, Some(0)].into_iter().flatten() {
                    let bounded = eager(Some(floor));
                    let got = method.search(&cs, start, end, &bounded);
                    assert_eq!(got, whole, "{method} {end:?} floor {floor}");
                    if method == Method::Extensile && Some(floor) == optimistic {
                        whole_asked += plain.asked.load(Ordering::Relaxed);
                        bounded_asked += bounded.asked.load(Ordering::Relaxed);
                        let over = whole.as_ref().map_or(0, |p| p.len() as u32 - 1);
                        detours += usize::from(optimistic.is_some_and(|d| over > d));
                    }
                }
                assert!(
                    !matches!(whole, Err(SearchFailure::WalkFailed { .. })),
                    "{method}"
                );
            }
        }
        assert!(
            detours >= 5,
            "only {detours} paths longer than the optimistic wave's"
        );
        assert!(
            5 * bounded_asked < 3 * whole_asked,
            "bounded {bounded_asked} steps asked, whole {whole_asked}"
        );
    }
}
