//! The paper's figures through the plan layer: a hand-made grid (`CSpace::from_fn`) with the
//! real IRB 1400 model and no obstacles, so every move inside the axis ranges is safe and
//! only the hand-made free nodes steer the search.
use super::*;
use crate::cell::Loc;
use crate::place::{Origin, Placement};
use crate::plan::cspace::Grid;
use crate::robot::Robot;

fn open_model() -> CollisionModel {
    let placement = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    CollisionModel::new(&Robot::irb1400(), placement, Vec::new(), 0.0, None)
}

fn point(name: &str, a: [f64; 3], wrist: [f64; 3]) -> PlacedPoint {
    PlacedPoint {
        name: name.into(),
        joints_deg: [a[0], a[1], a[2], wrist[0], wrist[1], wrist[2]],
        loc: Loc::default(),
        origin: Origin::Joints,
        motion: crate::place::MoveMotion {
            speed: "v300".into(),
            zone: "fine".into(),
        },
    }
}

/// Axes 1..3 of a leg's waypoints.
fn leg_arm(p: &Route, leg: usize) -> Vec<[f64; 3]> {
    p.waypoints[p.legs[leg].waypoints.clone()]
        .iter()
        .map(Waypoint::arm_deg)
        .collect()
}

#[test]
fn fig8_depth_first_fails_with_the_leg_named_and_extensile_takes_the_diagonal() {
    // 3 x 3 nodes in the axis 1 - axis 2 plane; free only on the diagonal, so the free
    // nodes touch only at corners (paper Fig. 8).
    let g = Grid::over([[0.0, 2.0], [0.0, 2.0], [0.0, 0.0]], 1.0);
    let cs = CSpace::from_fn(g, |n| n[0] == n[1]);
    let model = open_model();
    let pts = [
        point("P", [0.0, 0.0, 0.0], [0.0; 3]),
        point("Q", [2.0, 2.0, 0.0], [0.0; 3]),
    ];
    match route(&cs, &model, &pts, Method::DepthFirst) {
        Err(e @ PlanError::SearchFailed { from: 0, to: 1, .. }) => {
            let msg = e.to_string();
            assert!(
                msg.contains("depth-first search found no path from 'P' to 'Q'"),
                "{msg}"
            );
            assert_eq!(e.point(), 1);
        }
        other => panic!("expected SearchFailed, got {other:?}"),
    }
    let p = route(&cs, &model, &pts, Method::Extensile).expect("extensile plans");
    assert_eq!(p.moves(), 1);
    assert_eq!(leg_arm(&p, 0), vec![[0.0, 0.0, 0.0], [2.0, 2.0, 0.0]]);
    assert_eq!(p.legs[0].grid_path, vec![[0, 0, 0], [1, 1, 0], [2, 2, 0]]);
    // No obstacles: no clearance to certify, on any move.
    let certified = certify(p.clone(), &model);
    assert_eq!(certified.least, None);
    assert_eq!(certified.clearances, vec![None; p.moves()]);
    // Not joined at all: no path, for every method (one wave tells).
    let cs = CSpace::from_fn(g, |n| n[0] != 1);
    for m in Method::ALL {
        assert!(
            matches!(route(&cs, &model, &pts, m), Err(PlanError::NoPath { .. })),
            "{m}"
        );
    }
}

#[test]
fn fig6_neighboring_saw_tooth_and_extensile_straightens_it() {
    // A band of free nodes along axis 2 = axis 1 / 2 (|2 n2 - n1| <= 1), from (0, 0) to
    // (10, 5). On the 26-neighbour wave node (x, y) carries x + 1. Back from (10, 5) the
    // neighbouring search takes, among the smaller numbers in the band, the node nearest the
    // start: (9, 4) (97 against 106 for (9, 5)), then only (8, 4), then (7, 3), ...
    // a diagonal step and an axis step in turn: ten steps, no two in the same direction, so
    // ten moves even after the collinear merge (the saw-tooth of Fig. 6).
    let g = Grid::over([[0.0, 10.0], [0.0, 5.0], [0.0, 0.0]], 1.0);
    let cs = CSpace::from_fn(g, |n| (2 * n[1] - n[0]).abs() <= 1);
    let model = open_model();
    let pts = [
        point("P", [0.0, 0.0, 0.0], [0.0; 3]),
        point("Q", [10.0, 5.0, 0.0], [0.0; 3]),
    ];
    let nb = route(&cs, &model, &pts, Method::Neighboring).expect("neighboring plans");
    assert_eq!(nb.moves(), 10, "{:?}", leg_arm(&nb, 0));
    assert_eq!(leg_arm(&nb, 0)[1], [1.0, 0.0, 0.0]);
    assert_eq!(leg_arm(&nb, 0)[2], [2.0, 1.0, 0.0]);
    // Extensile: search, shorten (k -> k+2 where the inspected nodes are free) and merge.
    // The straight line (0, 0) -> (10, 5) passes only band nodes (at x = i its axis-2 value
    // i / 2 rounds into the band), but the shortening cuts k -> k+2 greedily from the start,
    // so it ends with at most a few pieces and never more than the saw-tooth.
    let ex = route(&cs, &model, &pts, Method::Extensile).expect("extensile plans");
    assert!(ex.moves() <= 2, "{:?}", leg_arm(&ex, 0));
    assert!(ex.path_length_deg() < nb.path_length_deg());
    for (a, b) in ex.segments() {
        let (na, nb_) = (cs.grid.node_at(&a), cs.grid.node_at(&b));
        let (Some(na), Some(nb_)) = (na, nb_) else {
            panic!("waypoints on the grid")
        };
        assert!(crate::plan::shorten::inspected_nodes(na, nb_)
            .iter()
            .all(|&q| cs.is_free(q)));
    }
}

#[test]
fn waypoints_carry_six_axes_and_the_wrist_turns_with_the_legs_progress() {
    // Three points on a free grid; the wrist differs at each. Each leg is one diagonal run
    // merged into one move, so force vias with a band like Fig. 6 on leg 1.
    let g = Grid::over([[0.0, 10.0], [0.0, 5.0], [0.0, 0.0]], 1.0);
    let cs = CSpace::from_fn(g, |n| (2 * n[1] - n[0]).abs() <= 1);
    let model = open_model();
    let pts = [
        point("P", [0.0, 0.0, 0.0], [0.0, 30.0, 0.0]),
        point("Q", [10.0, 5.0, 0.0], [0.0, 30.0, 100.0]),
        point("R", [10.0, 5.0, 0.0], [5.0, 30.0, 100.0]),
    ];
    let p = route(&cs, &model, &pts, Method::Neighboring).expect("plans");
    assert_eq!(p.legs.len(), 2);
    assert_eq!(p.legs[0].waypoints, 0..11);
    assert_eq!(p.legs[1].waypoints, 10..12, "the same axes 1..3: one move");
    assert_eq!(p.waypoints[0].kind, WaypointKind::CellPoint(0));
    assert_eq!(p.waypoints[3].kind, WaypointKind::Via { leg: 0, index: 3 });
    assert_eq!(p.waypoints[10].kind, WaypointKind::CellPoint(1));
    assert_eq!(p.waypoints[11].kind, WaypointKind::CellPoint(2));
    // Vias get the wrist schedule: the saw-tooth runs (0,0) (1,0) (2,1) (3,1) ... (9,4)
    // (10,5); a via at (x, y) projects onto the leg's line (10, 5) at s = (10 x + 5 y) / 125
    // and axis 6 turns to 100 s: (3,1) at s = 0.28, (9,4) at s = 0.88. Cell points keep
    // their own wrists.
    assert_eq!(p.waypoints[3].joints_deg, [3.0, 1.0, 0.0, 0.0, 30.0, 28.0]);
    assert_eq!(p.waypoints[9].joints_deg, [9.0, 4.0, 0.0, 0.0, 30.0, 88.0]);
    assert_eq!(p.waypoints[10].joints_deg[3..], [0.0, 30.0, 100.0]);
    // Every move interpolates all six axes: the moves the plan proved.
    for (a, b) in p.moves6() {
        assert!(model.move_is_safe(&a, &b));
    }
    assert_eq!(
        p.waypoints[11].joints_deg,
        [10.0, 5.0, 0.0, 5.0, 30.0, 100.0]
    );
    assert_eq!(p.moves(), 11);
}

/// The real IRB 1400 with the torch among a table, a post and a beam, and walls in the x-z
/// plane in front of and behind it, too high to pass over, that cut its free space into a
/// half at axis 1 > 0 and one at axis 1 < 0; its grid at 3 deg in front of the robot.
fn split_cell() -> (CollisionModel, CSpace) {
    use crate::cell::Obstacle;
    use crate::geometry::{Aabb, Point};
    let bx = |name: &str, min: [f64; 3], max: [f64; 3]| {
        Obstacle::new(name, Aabb::new(Point::from(min), Point::from(max)))
    };
    let boxes = vec![
        bx("table", [600.0, -900.0, 0.0], [1500.0, 900.0, 500.0]),
        bx("post", [900.0, 200.0, 500.0], [1050.0, 360.0, 1250.0]),
        bx("beam", [500.0, -900.0, 1500.0], [1400.0, -600.0, 1600.0]),
        bx("front", [380.0, -20.0, 0.0], [2500.0, 20.0, 3000.0]),
        bx("back", [-2500.0, -20.0, 0.0], [-380.0, 20.0, 3000.0]),
    ];
    let tool = crate::collision::tool_tests::torch();
    let placement = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let model = CollisionModel::new(&Robot::irb1400(), placement, boxes, 10.0, Some(&tool));
    let g = Grid::over([[-45.0, 45.0], [-30.0, 51.0], [-30.0, 60.0]], 3.0);
    let cs = CSpace::build(g, &model.grid_check(g.step_deg));
    (model, cs)
}

#[test]
fn legs_planned_at_once_give_the_route_leg_by_leg_and_the_first_failing_legs_error() {
    let (model, cs) = split_cell();
    assert_eq!(legs_at_once(&cs, &model), LEGS_AT_ONCE_MAX);
    // Axis 1 > 0: one half; the third and fourth points turn the wrist in place.
    let a = point("A", [30.0, -6.0, -9.0], [0.0, 30.0, 0.0]);
    let b = point("B", [39.0, 21.0, -21.0], [10.0, 35.0, 20.0]);
    let c = point("C", [42.0, 21.0, 12.0], [0.0, 30.0, 0.0]);
    let c2 = point("C2", [42.0, 21.0, 12.0], [0.0, 30.0, 30.0]);
    let d = point("D", [39.0, -24.0, 0.0], [-10.0, 25.0, 0.0]);
    // Axis 1 < 0: the other half.
    let e = point("E", [-30.0, 9.0, 0.0], [0.0, 30.0, 0.0]);
    let f = point("F", [-39.0, -6.0, 12.0], [0.0, 30.0, -20.0]);
    for p in [&a, &b, &c, &c2, &d, &e, &f] {
        assert!(model.is_free(&p.joints_deg), "{} blocked", p.name);
    }
    for method in Method::ALL {
        let pts = [&a, &b, &c, &c2, &d, &b, &a].map(Clone::clone);
        let one = route_on(&cs, &model, &pts, method, Legs::GridOnly, 1);
        let two = route_on(&cs, &model, &pts, method, Legs::GridOnly, 2);
        let (one, two) = match (one, two) {
            (Ok(one), Ok(two)) => (one, two),
            // Depth-first may find no path (paper Fig. 8): then both alike.
            (Err(x), Err(y)) if method == Method::DepthFirst => {
                assert_eq!(format!("{x:?}"), format!("{y:?}"), "{method}");
                continue;
            }
            (x, y) => panic!("{method}: {x:?} against {y:?}"),
        };
        assert_eq!(one.legs.len(), 6, "{method}");
        assert_eq!(one.waypoints, two.waypoints, "{method}");
        assert_eq!(
            format!("{:?}", one.legs),
            format!("{:?}", two.legs),
            "{method}"
        );
        // Each leg is the leg planned alone, in its place.
        for (i, leg) in one.legs.iter().enumerate() {
            let alone =
                route_on(&cs, &model, &pts[i..i + 2], method, Legs::GridOnly, 1).expect("alone");
            let six = |w: &[Waypoint]| w.iter().map(|w| w.joints_deg).collect::<Vec<_>>();
            assert_eq!(
                six(&one.waypoints[leg.waypoints.clone()]),
                six(&alone.waypoints)
            );
            assert_eq!(leg.grid_path, alone.legs[0].grid_path);
        }
    }
    // Legs 1 (B -> E) and 3 (F -> C) cross the walls: the error names leg 1, whether the
    // legs are planned one at a time or two.
    let pts = [&a, &b, &e, &f, &c, &d].map(Clone::clone);
    let fails: Vec<usize> = (0..pts.len() - 1)
        .filter(|&i| {
            route_on(
                &cs,
                &model,
                &pts[i..i + 2],
                Method::Extensile,
                Legs::GridOnly,
                1,
            )
            .is_err()
        })
        .collect();
    assert_eq!(fails, [1, 3], "the legs that cross the walls");
    for at_once in [1, 2] {
        match route_on(
            &cs,
            &model,
            &pts,
            Method::Extensile,
            Legs::GridOnly,
            at_once,
        ) {
            Err(e @ PlanError::NoPath { from: 1, to: 2, .. }) => {
                assert!(e.to_string().contains("from 'B' to 'E'"), "{e}");
            }
            other => panic!("{at_once} at once: {other:?}"),
        }
    }
}

/// Legs first tried straight (`direct`): a leg whose straight move the whole-move proof
/// proves (computed here apart) is its two points and nothing else; every other leg is the
/// paper's leg on the grid, the same waypoints and grid path as with every leg on the grid.
/// Legs all proven read no node of a grid inspected as it is read.
#[test]
fn proven_legs_go_straight_and_the_others_are_the_papers() {
    let (model, built) = split_cell();
    let lazy = || {
        CSpace::lazy(
            built.grid,
            std::sync::Arc::new(model.grid_check(built.grid.step_deg)),
        )
    };
    let a = point("A", [30.0, -6.0, -9.0], [0.0, 30.0, 0.0]);
    let b = point("B", [39.0, 21.0, -21.0], [10.0, 35.0, 20.0]);
    let c = point("C", [42.0, 21.0, 12.0], [0.0, 30.0, 0.0]);
    let c2 = point("C2", [42.0, 21.0, 12.0], [0.0, 30.0, 30.0]);
    let d = point("D", [39.0, -24.0, 0.0], [-10.0, 25.0, 0.0]);
    let pts = [&a, &b, &c, &c2, &d, &b, &a].map(Clone::clone);
    let proven: Vec<bool> = pts
        .windows(2)
        .map(|w| {
            w[0].arm_deg() != w[1].arm_deg()
                && model.move_is_safe(&w[0].joints_deg, &w[1].joints_deg)
        })
        .collect();
    assert!(
        proven.contains(&true) && proven.contains(&false),
        "{proven:?}"
    );
    for method in [Method::Extensile, Method::Neighboring] {
        let cs = lazy();
        let first = route_with(&cs, &model, &pts, method, Legs::StraightFirst).expect("first");
        let paper = route_with(&built, &model, &pts, method, Legs::GridOnly).expect("paper");
        assert!(!first.paper_alone() && paper.paper_alone());
        assert_eq!(first.legs.len(), pts.len() - 1);
        for (i, leg) in first.legs.iter().enumerate() {
            let six: Vec<[f64; 6]> = first.waypoints[leg.waypoints.clone()]
                .iter()
                .map(|w| w.joints_deg)
                .collect();
            assert_eq!(leg.straight, proven[i], "{method} leg {i}");
            if proven[i] {
                assert_eq!(six, [pts[i].joints_deg, pts[i + 1].joints_deg]);
                assert!(leg.grid_path.is_empty());
            } else {
                let p = &paper.legs[i];
                let want: Vec<[f64; 6]> = paper.waypoints[p.waypoints.clone()]
                    .iter()
                    .map(|w| w.joints_deg)
                    .collect();
                assert_eq!(six, want, "{method} leg {i}");
                assert_eq!(leg.grid_path, p.grid_path);
            }
        }
    }
    // The legs proven in a row, alone: not one node read.
    let run = (0..proven.len())
        .find(|&i| proven[i])
        .expect("a proven leg");
    let end = (run..proven.len())
        .find(|&i| !proven[i])
        .unwrap_or(proven.len());
    let cs = lazy();
    let route = route_with(
        &cs,
        &model,
        &pts[run..=end],
        Method::Extensile,
        Legs::StraightFirst,
    )
    .expect("straight");
    assert!(route.legs.iter().all(|l| l.straight));
    assert_eq!(cs.inspected_blocks(), 0);
}

#[test]
fn a_route_proven_again_is_certified_as_by_certify_and_one_through_a_wall_is_not() {
    let (model, cs) = split_cell();
    let a = point("A", [30.0, -6.0, -9.0], [0.0, 30.0, 0.0]);
    let b = point("B", [39.0, 21.0, -21.0], [10.0, 35.0, 20.0]);
    let c = point("C", [42.0, 21.0, 12.0], [0.0, 30.0, 0.0]);
    let route = route_on(
        &cs,
        &model,
        &[a, b, c],
        Method::Extensile,
        Legs::GridOnly,
        1,
    )
    .expect("planned");
    let once = certify(route.clone(), &model);
    let again = certify_proven(route.clone(), &model).expect("every move proven");
    assert!(once.least.is_some());
    assert_eq!(again.clearances, once.clearances);
    assert_eq!(again.least, once.least);
    // The last point moved to the other side of the walls (E of the test above): its move
    // crosses them.
    let mut through = route;
    let last = through.waypoints.len() - 1;
    through.waypoints[last].joints_deg = [-30.0, 9.0, 0.0, 0.0, 30.0, 0.0];
    assert!(certify_proven(through, &model).is_none());
}

#[test]
fn legs_are_handed_out_longest_first() {
    let w = [0.0, 30.0, 0.0];
    let pts = [
        point("A", [30.0, -6.0, -9.0], w),
        point("B", [39.0, 21.0, -21.0], w), // A -> B: most 27 (axis 2), in all 48
        point("E", [-30.0, 9.0, 0.0], w),   // B -> E: most 69
        point("F", [-39.0, -6.0, 12.0], w), // E -> F: most 15
        point("C", [42.0, 21.0, 12.0], w),  // F -> C: most 81
        point("G", [42.0, -6.0, 0.0], w),   // C -> G: most 27, in all 39
        point("H", [42.0, 21.0, 0.0], w),   // G -> H: most 27, in all 27
        point("I", [42.0, 48.0, 0.0], w),   // H -> I: most 27, in all 27 (after G -> H)
    ];
    assert_eq!(longest_first(&pts), [3, 1, 0, 4, 5, 6, 2]);
    assert!(longest_first(&pts[..1]).is_empty());
}

#[test]
fn a_wrist_turn_in_place_through_a_box_is_refused_naming_the_tool_shape() {
    use crate::cell::Obstacle;
    use crate::geometry::{Aabb, Point};
    let tool = crate::collision::tool_tests::torch();
    // The flange faces +x at the zero pose; the torch pointing ahead goes into the post,
    // tilted 60 deg up or down it clears it.
    let post = Obstacle::new(
        "post",
        Aabb::new(
            Point::new(1150.0, -20.0, 1100.0),
            Point::new(1250.0, 20.0, 1300.0),
        ),
    );
    let placement = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let model = CollisionModel::new(&Robot::irb1400(), placement, vec![post], 10.0, Some(&tool));
    let g = Grid::over([[-2.0, 2.0], [-2.0, 2.0], [-2.0, 2.0]], 1.0);
    let cs = CSpace::build(g, &model.grid_check(1.0));
    let pts = [
        point("Up", [0.0, 0.0, 0.0], [0.0, -60.0, 0.0]),
        point("Down", [0.0, 0.0, 0.0], [0.0, 60.0, 0.0]),
    ];
    assert!(pts.iter().all(|p| model.is_free(&p.joints_deg)));
    match route(&cs, &model, &pts, Method::Extensile) {
        Err(e @ PlanError::WristTurn { from: 0, to: 1, .. }) => {
            let msg = e.to_string();
            assert!(
                msg.contains("from 'Up' to 'Down'")
                    && msg.contains("tool shape")
                    && msg.contains("obstacle 'post'"),
                "{msg}"
            );
            assert_eq!(e.point(), 1);
        }
        other => panic!("{other:?}"),
    }
    // Turning about axis 6 instead keeps the torch up: one move.
    let pts = [
        point("Up", [0.0, 0.0, 0.0], [0.0, -60.0, 0.0]),
        point("Turned", [0.0, 0.0, 0.0], [0.0, -60.0, 90.0]),
    ];
    let p = route(&cs, &model, &pts, Method::Extensile).expect("the wrist turns up there");
    assert_eq!(p.moves(), 1);
}
