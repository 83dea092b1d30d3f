//! The leg's graph against brute force on small grids: the per-leg tool inspection (lazy, only
//! where the node codes say the tool may reach a box) against the six-axis node test at every
//! node, and the complete search against a breadth-first search over every accepted step.

use super::*;
use crate::cell::{Loc, Obstacle};
use crate::collision::tool_tests::torch;
use crate::collision::CollisionModel;
use crate::geometry::{Aabb, Point};
use crate::place::{Origin, Placement};
use crate::plan::cspace::Grid;
use crate::plan::search::{add, testing::grid};
use crate::plan::wave::{offsets, Connectivity, Graph};
use crate::robot::Robot;
use std::collections::VecDeque;

fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
    Obstacle::new(name, Aabb::new(Point::from(min), Point::from(max)))
}

/// The robot at the origin among a few boxes in front of it, with the torch or without; with
/// `split`, walls in the x-z plane in front of and behind the robot, too high to pass over,
/// cut its free space in two halves (y > 0 and y < 0).
fn model(with_torch: bool, split: bool) -> CollisionModel {
    let tool = torch();
    let mut boxes = vec![
        bx("table", [600.0, -900.0, 0.0], [1500.0, 900.0, 500.0]),
        bx("post", [900.0, 200.0, 500.0], [1050.0, 360.0, 1250.0]),
        bx("beam", [500.0, -900.0, 1500.0], [1400.0, -600.0, 1600.0]),
    ];
    if split {
        boxes.push(bx("front", [380.0, -20.0, 0.0], [2500.0, 20.0, 3000.0]));
        boxes.push(bx("back", [-2500.0, -20.0, 0.0], [-380.0, 20.0, 3000.0]));
    }
    CollisionModel::new(
        &Robot::irb1400(),
        Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        },
        boxes,
        10.0,
        with_torch.then_some(&tool),
    )
}

fn point(name: &str, joints_deg: [f64; 6]) -> PlacedPoint {
    PlacedPoint {
        name: name.into(),
        joints_deg,
        loc: Loc::default(),
        origin: Origin::Joints,
        motion: crate::place::MoveMotion {
            speed: "v300".into(),
            zone: "fine".into(),
        },
    }
}

/// The leg's graph of `schedule` on `cs` with `memo`, numbering over every step.
fn graph_of<'a>(
    cs: &'a CSpace,
    check: &'a GridCheck,
    schedule: &'a WristSchedule,
    memo: &'a ToolMemo,
) -> LegGraph<'a> {
    LegGraph {
        cs,
        check,
        schedule,
        eager: false,
        floor: None,
        memo,
    }
}

/// A small grid in front of the robot, 3 deg.
fn small_grid() -> Grid {
    Grid::over([[-45.0, 45.0], [-30.0, 51.0], [-30.0, 60.0]], 3.0)
}

#[test]
fn per_leg_inspection_is_the_six_axis_node_test_at_every_node() {
    let m = model(true, false);
    // The robot's whole range at 6 deg.
    let g = Grid::over([[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]], 6.0);
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    // A leg that turns the wrist a long way: the torch points up at the start, down at the end.
    let schedule = WristSchedule::new(
        &[-40.0, 0.0, 10.0, 0.0, -80.0, 0.0],
        &[40.0, 30.0, 30.0, 90.0, 80.0, 180.0],
    );
    let memo = ToolMemo::new(&cs, &check, &schedule);
    let graph = LegGraph {
        cs: &cs,
        check: &check,
        schedule: &schedule,
        eager: true,
        floor: None,
        memo: &memo,
    };
    // The code bits the row wave trusts (`Graph::look_bits`): a free node without them is free
    // on all six axes.
    let look = graph.look_bits().expect("the leg names its look bits");
    let (mut arm_free, mut looked, mut tool_blocked) = (0, 0, 0);
    for i in 0..g.len() {
        let n = g.node(i);
        let six = graph.six(n);
        assert_eq!(graph.usable(n), m.is_free(&six), "{six:?}");
        if cs.is_free(n) {
            assert!(cs.code(n) & look != 0 || m.is_free(&six), "{six:?}");
            arm_free += 1;
            if GridCheck::tool_near(cs.code(n)) {
                looked += 1;
            }
            if !m.is_free(&six) {
                tool_blocked += 1;
            }
        }
    }
    // The tool blocks some nodes the arm leaves free, and most nodes need no look at it.
    assert!(
        tool_blocked > 20,
        "{tool_blocked} nodes blocked by the tool"
    );
    assert!(
        looked > tool_blocked && looked * 2 < arm_free,
        "{looked} looked at of {arm_free} arm-free nodes"
    );
    // Asked again, the memo answers, the same.
    let memo_again = (0..g.len()).all(|i| {
        let n = g.node(i);
        graph.usable(n) == m.is_free(&graph.six(n))
    });
    assert!(memo_again);
    // Without a tool no node asks for a look.
    let bare = model(false, false);
    let check = bare.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    assert!((0..g.len()).all(|i| !GridCheck::tool_near(cs.code_index(i))));
}

/// Breadth-first search over the leg's graph, every step asked of `step_ok`: whether `s` and `g`
/// are joined with the given neighbourhood.
fn joined(graph: &LegGraph<'_>, s: Node, g: Node, c: Connectivity) -> bool {
    let grid = &graph.cs.grid;
    let mut seen = vec![false; grid.len()];
    let mut queue = VecDeque::from([s]);
    seen[grid.index(s)] = true;
    while let Some(n) = queue.pop_front() {
        if n == g {
            return true;
        }
        for &o in offsets(c) {
            let m = add(n, o);
            if grid.contains(m) && !seen[grid.index(m)] && graph.usable(m) && graph.step_ok(n, m) {
                seen[grid.index(m)] = true;
                queue.push_back(m);
            }
        }
    }
    false
}

#[test]
fn the_search_finds_a_path_exactly_where_the_accepted_steps_join_the_points() {
    let m = model(true, true);
    let g = small_grid();
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    let mut rng = crate::geometry::testing::Rng(0x1E6_C0DE);
    let (mut joined_legs, mut apart_legs, mut diagonal_only) = (0, 0, 0);
    let mut legs = 0;
    while legs < 16 {
        let pick = |rng: &mut crate::geometry::testing::Rng| {
            let n = [
                rng.below(g.dims[0] as u64) as i32,
                rng.below(g.dims[1] as u64) as i32,
                rng.below(g.dims[2] as u64) as i32,
            ];
            let w = [
                rng.range(-120.0, 120.0),
                rng.range(-100.0, 100.0),
                rng.range(-200.0, 200.0),
            ];
            let a = g.axes_deg(n);
            (n, [a[0], a[1], a[2], w[0], w[1], w[2]])
        };
        let ((s, from), (e, to)) = (pick(&mut rng), pick(&mut rng));
        if s == e || !m.is_free(&from) || !m.is_free(&to) {
            continue;
        }
        legs += 1;
        let schedule = WristSchedule::new(&from, &to);
        let memo = ToolMemo::new(&cs, &check, &schedule);
        let graph = graph_of(&cs, &check, &schedule, &memo);
        let (j26, j6) = (
            joined(&graph, s, e, Connectivity::TwentySix),
            joined(&graph, s, e, Connectivity::Six),
        );
        if j26 {
            joined_legs += 1;
        } else {
            apart_legs += 1;
        }
        if j26 && !j6 {
            diagonal_only += 1;
        }
        for method in Method::ALL {
            let got = search(&graph, method, s, e);
            let want_path = if method == Method::DepthFirst {
                j6
            } else {
                j26
            };
            match got {
                Ok(path) => {
                    assert!(want_path, "{method}: a path where brute force finds none");
                    assert_eq!((path.first(), path.last()), (Some(&s), Some(&e)));
                    for w in path.windows(2) {
                        assert!(graph.usable(w[1]) && graph.step_ok(w[0], w[1]), "{w:?}");
                    }
                }
                Err(SearchFailure::NotConnected) => assert!(!j26, "{method}: gave up"),
                Err(SearchFailure::OnlyDiagonal) => {
                    assert!(method == Method::DepthFirst && j26 && !j6, "{method}")
                }
                Err(SearchFailure::WalkFailed { .. }) => panic!("{method}: the walk ran out"),
            }
        }
        // The whole leg: every move proven on six axes.
        let p = plan_leg(
            &cs,
            &check,
            &point("P", from),
            &point("Q", to),
            Method::Extensile,
        );
        match p {
            Ok(leg) => {
                assert!(j26);
                for w in leg.waypoints.windows(2) {
                    assert!(m.move_is_safe(&w[0], &w[1]));
                }
            }
            Err(f) => assert!(!j26 || matches!(f, LegFailure::NoJoin { .. }), "{f:?}"),
        }
    }
    assert!(
        joined_legs >= 4 && apart_legs >= 1,
        "{joined_legs} joined, {apart_legs} apart"
    );
    eprintln!(
        "{legs} legs: {joined_legs} joined, {apart_legs} apart, {diagonal_only} only diagonally"
    );
}

/// A graph whose wave numbers over every step (the paper's wave) while its walk asks `F`.
struct Optimistic<F>(F);

impl<F: Fn(Node, Node) -> bool + Sync> Graph for Optimistic<F> {
    fn node_ok(&self, _: Node) -> bool {
        true
    }
    fn step_ok(&self, a: Node, b: Node) -> bool {
        (self.0)(a, b)
    }
    fn wave_step_ok(&self, _: Node, _: Node) -> bool {
        true
    }
}

#[test]
fn where_the_optimistic_walk_runs_out_the_eager_wave_finds_the_way() {
    // 9 x 5 nodes, every node free; no step crosses between axis-1 index 3 and 4 except in the
    // top row (axis-2 index 4). The paper's wave numbers straight across; every path down its
    // numbers crosses where no step exists. Over accepted steps the wave goes round by the top.
    let cs = grid(9, 5, 1, |_| true);
    let crosses = |a: Node, b: Node| (a[0] <= 3) != (b[0] <= 3);
    let step = move |a: Node, b: Node| !crosses(a, b) || (a[1] == 4 && b[1] == 4);
    let (s, e) = ([0, 0, 0], [8, 0, 0]);
    for method in Method::ALL {
        assert!(
            matches!(
                method.search(&cs, s, e, &Optimistic(step)),
                Err(SearchFailure::WalkFailed { .. })
            ),
            "{method}"
        );
        let path = method.search(&cs, s, e, &step).expect("round by the top");
        assert!(path.iter().any(|n| n[1] == 4), "{method}: {path:?}");
        for w in path.windows(2) {
            assert!(step(w[0], w[1]), "{method}: {w:?}");
        }
    }
}

/// The boxes of tests/ok/complete_search_2deg.yaml (found by a seeded generator of random
/// cells): on a 2 deg grid the paper's wave from P to Q offers only steps the step check refuses.
fn refusing_boxes() -> Vec<Obstacle> {
    vec![
        bx("b0", [641.0, 453.0, 0.0], [1041.0, 933.0, 199.0]),
        bx("b1", [-137.0, 537.0, 0.0], [57.0, 1047.0, 1383.0]),
        bx("b3", [623.0, 648.0, 0.0], [767.0, 980.0, 382.0]),
        bx("b4", [-650.0, -1388.0, 0.0], [-56.0, -1060.0, 872.0]),
        bx("b5", [581.0, 291.0, 319.0], [1075.0, 445.0, 775.0]),
        bx("b6", [197.0, 526.0, 383.0], [631.0, 830.0, 635.0]),
    ]
}

/// The leg of [`refusing_boxes`] from P to Q on its 2 deg grid, and its two nodes.
struct RefusingLeg {
    m: CollisionModel,
    check: GridCheck,
    cs: CSpace,
    from: [f64; 6],
    to: [f64; 6],
    s: Node,
    e: Node,
}

fn refusing_leg() -> RefusingLeg {
    let robot = Robot::irb1400();
    let placement = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let m = CollisionModel::new(&robot, placement, refusing_boxes(), 25.0, None);
    let a = &robot.controller.axes;
    let g = Grid::over([0, 1, 2].map(|k| [a[k].min_deg, a[k].max_deg]), 2.0);
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    let (from, to) = (
        [-34.0, 34.0, 36.0, 0.0, 0.0, 0.0],
        [120.0, 30.0, 40.0, 0.0, 0.0, 0.0],
    );
    let node = |p: &[f64; 6]| g.node_at(&[p[0], p[1], p[2]]).expect("on the grid");
    let (s, e) = (node(&from), node(&to));
    RefusingLeg {
        m,
        check,
        cs,
        from,
        to,
        s,
        e,
    }
}

#[test]
fn a_real_cell_where_the_papers_wave_offers_only_refused_steps_plans_on_the_accepted_ones() {
    // tests/ok/complete_search_2deg.yaml (found by a seeded generator of random cells): on a
    // 2 deg grid every path the paper's wave offers from P to Q has a step the step check
    // refuses, so the walk on it runs out (a search on that wave alone gives up here); the
    // wave over accepted steps has a path, and the leg plans.
    let RefusingLeg {
        m,
        check,
        cs,
        from,
        to,
        s,
        e,
    } = refusing_leg();
    let schedule = WristSchedule::new(&from, &to);
    let memo = ToolMemo::new(&cs, &check, &schedule);
    let optimistic = graph_of(&cs, &check, &schedule, &memo);
    let eager = LegGraph {
        eager: true,
        ..optimistic
    };
    for method in [Method::Neighboring, Method::Extensile] {
        assert!(
            matches!(
                method.search(&cs, s, e, &optimistic),
                Err(SearchFailure::WalkFailed { .. })
            ),
            "{method}: the paper's wave offers a path of accepted steps here"
        );
        let path = method
            .search(&cs, s, e, &eager)
            .unwrap_or_else(|f| panic!("{method}: {f:?}"));
        for w in path.windows(2) {
            assert!(eager.usable(w[1]) && eager.step_ok(w[0], w[1]), "{w:?}");
        }
        let leg = plan_leg(&cs, &check, &point("P", from), &point("Q", to), method)
            .unwrap_or_else(|f| panic!("{method}: {f:?}"));
        for w in leg.waypoints.windows(2) {
            assert!(m.move_is_safe(&w[0], &w[1]));
        }
    }
}

/// A leg's graph counting the steps its waves ask (each a step proof where the codes do not
/// prove it).
struct Counted<'a> {
    graph: &'a LegGraph<'a>,
    asked: std::sync::atomic::AtomicUsize,
}

impl Graph for Counted<'_> {
    fn node_ok(&self, n: Node) -> bool {
        self.graph.node_ok(n)
    }
    fn node_ok_coded(&self, n: Node, code: u8) -> bool {
        self.graph.node_ok_coded(n, code)
    }
    fn step_ok(&self, a: Node, b: Node) -> bool {
        self.graph.step_ok(a, b)
    }
    fn wave_step_ok(&self, a: Node, b: Node) -> bool {
        self.asked
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        self.graph.wave_step_ok(a, b)
    }
    fn wave_steps_all(&self) -> bool {
        self.graph.wave_steps_all()
    }
    fn look_bits(&self) -> Option<u8> {
        self.graph.look_bits()
    }
    fn steps_floor(&self) -> Option<u32> {
        self.graph.steps_floor()
    }
}

#[test]
fn the_eager_waves_bounded_by_the_optimistic_distance_ask_a_fraction_of_the_proofs() {
    // The cell of the test above: the optimistic walk runs out, the eager waves find the way.
    // Bounded from the optimistic wave's distance (what `search` gives them) they find the same
    // path, asking the step check at a small part of the steps the whole waves ask.
    let RefusingLeg {
        check,
        cs,
        from,
        to,
        s,
        e,
        ..
    } = refusing_leg();
    let schedule = WristSchedule::new(&from, &to);
    let memo = ToolMemo::new(&cs, &check, &schedule);
    let optimistic = graph_of(&cs, &check, &schedule, &memo);
    for method in [Method::Neighboring, Method::Extensile] {
        let Err(SearchFailure::WalkFailed { steps }) = method.search(&cs, s, e, &optimistic) else {
            panic!("{method}: the optimistic walk finds a way here");
        };
        let (whole, bounded) = (
            LegGraph {
                eager: true,
                ..optimistic
            },
            LegGraph {
                eager: true,
                floor: Some(steps),
                ..optimistic
            },
        );
        let count = |graph| Counted {
            graph,
            asked: Default::default(),
        };
        let (whole, bounded) = (count(&whole), count(&bounded));
        let want = method.search(&cs, s, e, &whole);
        assert!(want.is_ok(), "{method}: {want:?}");
        assert_eq!(method.search(&cs, s, e, &bounded), want, "{method}");
        let asked = |c: &Counted| c.asked.load(std::sync::atomic::Ordering::Relaxed);
        let (all, few) = (asked(&whole), asked(&bounded));
        assert!(
            few > 0 && 4 * few < all,
            "{method}: {few} steps asked, whole {all}"
        );
    }
}

/// The tool answers a leg spreads from a node with a margin (`LegGraph::spread_clear`) are the
/// exact test's: visit every seventh node of a 3 deg grid in a scattered order, then every node
/// the memo holds clear (most of them never visited) must have its tool clear by the six-axis
/// node test, at the leg's wrist there. The spreading must have happened (clear nodes beyond
/// those visited), and the exact test must block some nodes, so both answers are exercised.
#[test]
fn tool_answers_spread_from_a_margin_are_the_exact_tests() {
    // A long leg, and a short one whose wrist turns far per grid step (the wrist's share of
    // the spread's motion bound matters there).
    for (from, to) in [
        (
            [-60.0, -10.0, 0.0, -30.0, -60.0, 20.0],
            [60.0, 40.0, 40.0, 120.0, 70.0, 200.0],
        ),
        (
            [-3.0, 10.0, 20.0, -150.0, -110.0, -300.0],
            [3.0, 10.0, 20.0, 150.0, 110.0, 300.0],
        ),
    ] {
        spread_answers_are_exact(&WristSchedule::new(&from, &to));
    }
}

fn spread_answers_are_exact(schedule: &WristSchedule) {
    let m = model(true, false);
    let g = Grid::over([[-90.0, 90.0], [-60.0, 70.0], [-60.0, 70.0]], 3.0);
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    let memo = ToolMemo::new(&cs, &check, schedule);
    let graph = graph_of(&cs, &check, schedule, &memo);
    let mut visited = vec![false; g.len()];
    for i in (0..g.len()).step_by(7).map(|i| (i * 7919) % g.len()) {
        visited[i] = true;
        let _ = graph.node_ok(g.node(i));
    }
    let (mut clear, mut spread, mut blocked) = (0, 0, 0);
    // No node was answered both ways (its bits 11 would be neither answer, skipped below).
    for w in &memo.answers {
        let v = w.load(Ordering::Relaxed);
        assert_eq!(
            v & (v >> 1) & 0x5555_5555_5555_5555,
            0,
            "a node answered both ways"
        );
    }
    for (i, seen) in visited.iter().enumerate() {
        match memo.answer(i) {
            TOOL_CLEAR => {
                let six = graph.six(g.node(i));
                assert!(
                    m.tool_is_free(&six),
                    "marked clear, tool blocked at {six:?}"
                );
                clear += 1;
                if !seen {
                    spread += 1;
                }
            }
            TOOL_BLOCKED => blocked += 1,
            _ => {}
        }
    }
    assert!(
        spread > clear / 4 && blocked > 100,
        "{clear} clear ({spread} spread), {blocked} blocked"
    );
}

#[test]
fn the_tool_looks_place_the_flange_where_link_poses_does_at_every_node() {
    // A placed, turned robot (the chain folds the placement in) and a grid whose origin is
    // off zero on every axis: the memo's tables, indexed by the node, with the leg's wrist,
    // give the flange `link_poses` gives, to 1e-9 mm at points 300 mm out.
    let tool = torch();
    let m = CollisionModel::new(
        &Robot::irb1400(),
        Placement {
            base_mm: [250.0, -850.0, 40.0],
            yaw_deg: 90.0,
        },
        vec![bx("table", [600.0, -900.0, 0.0], [1500.0, 900.0, 500.0])],
        10.0,
        Some(&tool),
    );
    let g = Grid::over([[-169.0, 160.0], [-67.0, 68.0], [-61.0, 69.0]], 7.0);
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    let schedule = WristSchedule::new(
        &[-40.0, 0.0, 10.0, -170.0, -80.0, 33.3333],
        &[40.0, 30.0, 30.0, 90.0, 80.0, 280.0],
    );
    let memo = ToolMemo::new(&cs, &check, &schedule);
    let probes = [[0.0, 0.0, 0.0], [300.0, 0.0, 0.0], [0.0, -200.0, 220.0]].map(Point::from);
    for i in 0..g.len() {
        let n = g.node(i);
        let six = schedule.six(&g.axes_deg(n));
        let (sc, link1) = memo.arm_at(n).expect("a memo with a tool has tables");
        let fast = m
            .flange_sincos_for_test(&six, &sc, Some(link1))
            .expect("a model with a tool");
        let slow = m.flange_pose_for_test(&six);
        for p in &probes {
            assert!((fast * p - slow * p).norm() < 1e-9, "node {n:?}, {six:?}");
        }
    }
}

/// A look reads the leg's progress from the memo's terms and rounds the wrist as it reads its
/// sines and cosines (`LegGraph::look`): at every node of a grid off zero, for legs along a
/// diagonal, along one axis, with a still wrist axis, with wrists far past a turn, and one
/// that does not move axes 1..3, the progress is `WristSchedule::progress` to the bit, and the
/// look's answer and margin are those of `tool_look_link1` at `six`, to the bit. Fails if the
/// terms were summed in another order, a term were taken at another node, or the wrist were
/// rounded otherwise (the margins move by a wrist's thousandth).
#[test]
fn a_look_from_the_memo_tables_is_the_look_at_six_to_the_bit() {
    let m = model(true, false);
    let g = Grid::over([[-61.0, 59.0], [-43.0, 61.0], [-37.0, 68.0]], 4.0);
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    // Ends off the grid's values (3 decimals, as a cell writes them), so that the terms'
    // products and sums round.
    let legs = [
        (
            [-40.123, 0.017, 10.333, -170.0, -80.0, 33.333],
            [40.457, 30.001, 29.999, 90.0, 80.0, 280.0],
        ),
        (
            [-50.5, -30.25, 60.125, 0.0, -80.0, 0.0],
            [50.001, 40.7, -30.3, 12.345, 80.0, -0.001],
        ),
        (
            [-33.3, 7.1, 7.1, 1.0, 45.0, -300.0],
            [31.9, 7.1, 7.1, -1.0, 45.0, 300.0],
        ),
        (
            [3.0, 5.0, 7.0, 10.0, 20.0, 30.0],
            [3.0, 5.0, 7.0, 90.0, -20.0, 130.0],
        ),
    ];
    let mut margins = 0;
    for (from, to) in legs {
        let schedule = WristSchedule::new(&from, &to);
        let memo = ToolMemo::new(&cs, &check, &schedule);
        for i in 0..g.len() {
            let n = g.node(i);
            let at = memo.look_at(n).expect("a memo with a tool has tables");
            let (sc, link1) = (at.sincos, at.link1);
            let s = schedule.progress_of(at.progress);
            assert_eq!(
                s.to_bits(),
                schedule.progress(&g.axes_deg(n)).to_bits(),
                "progress at {n:?}"
            );
            let six = schedule.six(&g.axes_deg(n));
            let fast = m.tool_look_link1_rounding(&schedule.wrist_unrounded(s), &sc, link1);
            let slow = m.tool_look_link1(&six, &sc, link1);
            assert_eq!(
                (fast.0, fast.1.to_bits()),
                (slow.0, slow.1.to_bits()),
                "look at {six:?}"
            );
            if slow.1 > 0.0 && slow.1.is_finite() {
                margins += 1;
            }
        }
    }
    assert!(margins > 1000, "{margins} looks with a margin");
}

/// The spread marks exactly the nodes of the offsets whose motion is below the margin that lie
/// on the grid: at a node well inside (reached by the offsets' index deltas) and at nodes on
/// the grid's faces and corners (bounds tested), each node found here by its own coordinates.
#[test]
fn the_spread_marks_its_offsets_nodes_inside_and_at_the_faces() {
    let m = model(true, false);
    let g = small_grid();
    let check = m.grid_check(g.step_deg);
    let cs = CSpace::build(g, &check);
    let schedule = WristSchedule::new(
        &[-30.0, 0.0, 10.0, 0.0, -80.0, 0.0],
        &[30.0, 30.0, 30.0, 90.0, 80.0, 180.0],
    );
    let [d0, d1, d2] = g.dims.map(|d| d as i32);
    let nodes = [
        [d0 / 2, d1 / 2, d2 / 2],
        [2, 2, 2],
        [0, 0, 0],
        [d0 - 1, d1 / 2, 1],
        [1, d1 - 2, d2 - 1],
        [d0 - 3, d1 - 3, d2 - 3],
        [1, d1 / 2, d2 / 2],
        [d0 / 2, d1 - 2, d2 / 2],
    ];
    // Margins that take a few offsets, about half of them, and all, from the offsets' motions.
    let motions: Vec<f64> = {
        let memo = ToolMemo::new(&cs, &check, &schedule);
        let graph = graph_of(&cs, &check, &schedule, &memo);
        graph.spread_clear(nodes[0], 1.0);
        let offsets = memo.spread.get().expect("made on the first spread");
        offsets.iter().map(|o| o.0).collect()
    };
    for n in nodes {
        for margin in [motions[5] + 1e-6, motions[60] + 1e-6, 1e9] {
            let memo = ToolMemo::new(&cs, &check, &schedule);
            let graph = graph_of(&cs, &check, &schedule, &memo);
            graph.spread_clear(n, margin);
            let offsets = memo.spread.get().expect("made on the first spread");
            let want: Vec<usize> = {
                let mut w: Vec<usize> = offsets
                    .iter()
                    .filter(|(motion, _, _)| *motion < margin)
                    .map(|&(_, o, _)| add(n, o))
                    .filter(|&m| g.contains(m))
                    .map(|m| g.index(m))
                    .collect();
                w.sort_unstable();
                w
            };
            let got: Vec<usize> = (0..g.len())
                .filter(|&i| memo.answer(i) == TOOL_CLEAR)
                .collect();
            assert_eq!(got, want, "node {n:?}, margin {margin}");
            assert!(!want.is_empty(), "node {n:?}, margin {margin}");
        }
    }
}

/// A leg planned on a grid inspected as its waves read it (`CSpace::lazy`) is the leg planned on
/// the grid inspected whole, node for node of its grid path and bit for bit of its waypoints,
/// with each method, with the torch and without; the lazy grid inspected part of its blocks
/// only (the waves between the points, not the whole range of axis 1). Among the legs: one
/// where the paper's wave offers only refused steps (the eager, node-by-node waves run too).
#[test]
fn a_leg_on_the_grid_inspected_as_read_is_the_leg_on_the_whole_grid() {
    use std::sync::Arc;
    let refusing = refusing_boxes();
    let robot = Robot::irb1400();
    let placement = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let cases = [
        (
            model(true, false),
            [-40.0, 10.0, 20.0, 0.0, 30.0, 0.0],
            [40.0, 30.0, 10.0, 90.0, 60.0, 90.0],
        ),
        (
            model(false, false),
            [-40.0, 10.0, 20.0, 0.0, 30.0, 0.0],
            [40.0, 30.0, 10.0, 90.0, 60.0, 90.0],
        ),
        (
            CollisionModel::new(&robot, placement, refusing, 25.0, None),
            [-34.0, 34.0, 36.0, 0.0, 0.0, 0.0],
            [120.0, 30.0, 40.0, 0.0, 0.0, 0.0],
        ),
    ];
    let a = &robot.controller.axes;
    let g = Grid::over([0, 1, 2].map(|k| [a[k].min_deg, a[k].max_deg]), 2.0);
    let mut planned = 0;
    for (k, (m, from, to)) in cases.into_iter().enumerate() {
        let m = Arc::new(m);
        let check = GridCheck::new(Arc::clone(&m), g.step_deg);
        let whole = CSpace::build(g, &check);
        for method in Method::ALL {
            let lazy = CSpace::lazy(g, Arc::new(GridCheck::new(Arc::clone(&m), g.step_deg)));
            let (p, q) = (point("P", from), point("Q", to));
            let on_whole = plan_leg(&whole, &check, &p, &q, method);
            let on_lazy = plan_leg(&lazy, &check, &p, &q, method);
            match (on_whole, on_lazy) {
                (Ok(w), Ok(l)) => {
                    assert_eq!(w.grid_path, l.grid_path, "{method}");
                    assert_eq!(w.waypoints, l.waypoints, "{method}");
                    planned += 1;
                }
                (Err(w), Err(l)) => assert_eq!(w, l, "{method}"),
                (w, l) => panic!("{method}: {:?} against {:?}", w.err(), l.err()),
            }
            // The corridor waves of the first two legs read a small part of the grid; the
            // depth-first one (unbounded, over axis steps) and the eager waves more.
            let (done, all) = (lazy.inspected_blocks(), lazy.block_count());
            let most = if k < 2 && method != Method::DepthFirst {
                all / 8
            } else {
                all - all / 20
            };
            assert!(
                done > 0 && done < most,
                "{k} {method}: {done} of {all} blocks"
            );
        }
    }
    assert!(planned >= 7, "{planned} legs planned");
}
