//! Tests of the tool looks (`look.rs`): every answer the exact test's, the shapes called far,
//! the balls' passes by the cubes' masks and over every box, the least distances to the bit.

use super::look::{bounds_by_coordinate, least_sq_distances, FAR_SHAPES};
use super::tool_tests::{shape, torch, torch_model, trunk, TRUNK_PLACEMENT};
use super::*;
use crate::cell::{Frame, Loc, ToolGeometry};
use crate::geometry::testing::Rng;
use crate::geometry::{distance_point_aabb, distance_sq_point_aabb};

/// The IRB 1400 at the trunk's placement with `tool`, at `clearance`.
fn trunk_model(tool: &Tool, clearance: f64) -> CollisionModel {
    CollisionModel::new(
        &Robot::irb1400(),
        TRUNK_PLACEMENT,
        trunk(),
        clearance,
        Some(tool),
    )
}

/// The grid of the look tests: 5 deg in front of the robot over the trunk.
fn look_grid() -> crate::plan::cspace::Grid {
    crate::plan::cspace::Grid::over([[-90.0, 90.0], [-60.0, 70.0], [-60.0, 70.0]], 5.0)
}

/// The look tests' two legs' wrist schedules: a long leg, and a short one whose wrist turns
/// far per step.
fn look_schedules() -> [crate::plan::leg::WristSchedule; 2] {
    use crate::plan::leg::WristSchedule;
    [
        WristSchedule::new(
            &[-60.0, -10.0, 0.0, -30.0, -60.0, 20.0],
            &[60.0, 40.0, 40.0, 120.0, 70.0, 200.0],
        ),
        WristSchedule::new(
            &[-3.0, 10.0, 20.0, -150.0, -110.0, -300.0],
            &[3.0, 10.0, 20.0, 150.0, 110.0, 300.0],
        ),
    ]
}

/// Node `i` of `g` with `schedule`'s wrist, and the sines and cosines of axes 1..3 as a leg's
/// memo holds them.
fn look_pose(
    schedule: &crate::plan::leg::WristSchedule,
    g: &crate::plan::cspace::Grid,
    i: usize,
) -> ([f64; 6], [(f64, f64); 3]) {
    let six = schedule.six(&g.axes_deg(g.node(i)));
    (six, [0, 1, 2].map(|k| six[k].to_radians().sin_cos()))
}

/// The tool looks' blocked answers from upper bounds are the exact test's: at every node of a
/// 5 deg grid in front of the robot, with the wrist of a long leg and of a short one whose
/// wrist turns far per step, the look (`tool_look_sincos`, memo tables' sines and cosines)
/// answers what `tool_is_free` (no shortcut, `link_poses`) answers. Both shortcuts must have
/// answered blocked at many nodes: a shape's inner ball within the clearance (the ball pass)
/// and, where that did not, a shape's `Solid::upper_distance_aabb` within it (counted here
/// independently of the look).
#[test]
fn blocked_answers_from_upper_bounds_are_the_exact_tests() {
    let m = torch_model(10.0);
    let (tool, c) = (m.tool.as_ref().expect("a torch"), m.clearance_mm());
    let g = look_grid();
    for schedule in look_schedules() {
        let (mut blocked, mut by_balls, mut by_upper) = (0, 0, 0);
        for i in 0..g.len() {
            let (six, sc) = look_pose(&schedule, &g, i);
            let exact = m.tool_is_free(&six);
            assert_eq!(m.tool_look_sincos(&six, &sc).0, exact, "at {six:?}");
            if exact {
                continue;
            }
            blocked += 1;
            let flange = m.flange_pose_for_test(&six);
            let ball_within = tool.shapes.iter().any(|s| {
                let centre = flange * s.ball.0;
                m.obstacles()
                    .iter()
                    .any(|o| distance_point_aabb(&centre, &o.aabb) - s.inner_mm < c)
            });
            let upper_within = tool.shapes.iter().any(|s| {
                let solid = s.local.placed(&flange);
                m.obstacles()
                    .iter()
                    .any(|o| solid.upper_distance_aabb(&o.aabb) < c)
            });
            if ball_within {
                by_balls += 1;
            } else if upper_within {
                by_upper += 1;
            }
        }
        assert!(
            by_balls > 200 && by_upper > 200 && blocked > by_balls + by_upper,
            "{blocked} blocked, {by_balls} by the inner balls, {by_upper} by the upper bounds"
        );
    }
}

/// The shapes the balls' pass calls far (whose boxes the exact test then skips) are clear of
/// every box by the exact test, and the exact test's own ball filter, on the flange as
/// `link_poses` places it, passes every box for them; and a look from link 1's pose (as the
/// leg's memo keeps it) answers as the look, margin to the bit. At the nodes of the 5 deg grid
/// of the test above with its two wrists, at clearances 0, 10 and 60 mm; shapes called far
/// occur at many nodes where the balls left the answer to the exact test.
#[test]
fn shapes_called_far_are_clear_and_looks_from_link_1_are_the_looks() {
    let g = look_grid();
    for clearance in [0.0, 10.0, 60.0] {
        let m = torch_model(clearance);
        let (tool, c) = (m.tool.as_ref().expect("a torch"), m.clearance_mm());
        let mut far_at_exact = 0;
        for schedule in look_schedules() {
            for i in 0..g.len() {
                let (six, sc) = look_pose(&schedule, &g, i);
                let look = m.tool_look_sincos(&six, &sc);
                let link1 = m.tool_link1(sc[0]).expect("a tool");
                let from1 = m.tool_look_link1(&six, &sc, &link1);
                assert_eq!(
                    (from1.0, from1.1.to_bits()),
                    (look.0, look.1.to_bits()),
                    "at {six:?}"
                );
                let flange = m.flange_pose_for_test(&six);
                let far = m.far_shapes_for_test(&six, &sc);
                for (s, _) in tool.shapes.iter().zip(far).filter(|(_, f)| *f) {
                    let centre = flange * s.ball.0;
                    let reach = s.ball.1 + c;
                    let solid = s.local.placed(&flange);
                    for o in m.obstacles() {
                        assert!(
                            distance_sq_point_aabb(&centre, &o.aabb) > reach * reach
                                && solid_clear_of_box(&solid, &o.aabb, c),
                            "{} called far but near '{}' at {six:?}",
                            s.part,
                            o.name
                        );
                    }
                    if look.1 == 0.0 {
                        far_at_exact += 1;
                    }
                }
            }
        }
        assert!(
            far_at_exact > 100,
            "{far_at_exact} far shapes where the balls did not answer"
        );
    }
}

/// A tool of 10 shapes (more than the balls' pass marks, and not a multiple of its groups of
/// three): every shape the pass calls far is farther than its ball's radius plus the clearance
/// from every box on the flange `link_poses` places; shapes past the pass's first
/// [`FAR_SHAPES`] have no mark (they keep the exact test's own ball filter); every
/// marked shape is called far somewhere (a mis-indexed mark shows as a near shape called far);
/// and the look answers as the exact test on `link_poses`, and as the exact test without the
/// far marks where the balls left the answer to it.
#[test]
fn a_tool_of_many_shapes_marks_only_far_shapes_and_answers_as_the_exact_test() {
    let mut tool = torch();
    tool.shapes = (0..10)
        .map(|k| {
            let z = 30.0 * k as f64;
            let x = if k % 2 == 0 { 40.0 } else { -20.0 } * k as f64;
            let geometry = match k % 3 {
                0 => ToolGeometry::Sphere {
                    centre_mm: [x, 0.0, z],
                    radius_mm: 10.0 + k as f64,
                },
                1 => ToolGeometry::Box {
                    min_mm: [x - 10.0, -10.0, z],
                    max_mm: [x + 10.0, 10.0, z + 30.0],
                },
                _ => ToolGeometry::Cylinder {
                    from_mm: [0.0, 0.0, z],
                    to_mm: [x, 5.0, z + 40.0],
                    radius_mm: 8.0,
                },
            };
            shape(&format!("s{k}"), geometry)
        })
        .collect();
    let g = look_grid();
    let mut called_far = [0usize; FAR_SHAPES];
    let mut by_exact = 0;
    for clearance in [0.0, 10.0, 60.0] {
        let m = trunk_model(&tool, clearance);
        let (shapes, c) = (&m.tool.as_ref().expect("a tool").shapes, m.clearance_mm());
        assert_eq!(shapes.len(), 10);
        for schedule in look_schedules() {
            for i in 0..g.len() {
                let (six, sc) = look_pose(&schedule, &g, i);
                let look = m.tool_look_sincos(&six, &sc);
                assert_eq!(look.0, m.tool_is_free(&six), "the look at {six:?}");
                if look.1 == 0.0 {
                    by_exact += 1;
                    let flange = m.flange_sincos_for_test(&six, &sc, None).expect("a tool");
                    let unmarked = m.tool_is_free_at::<true>(&flange, &[]);
                    assert_eq!(
                        look.0, unmarked,
                        "the far marks changed the answer at {six:?}"
                    );
                }
                let flange = m.flange_pose_for_test(&six);
                let far = m.far_shapes_for_test(&six, &sc);
                for (k, s) in shapes.iter().enumerate().take(FAR_SHAPES) {
                    if !far[k] {
                        continue;
                    }
                    called_far[k] += 1;
                    let (centre, reach) = (flange * s.ball.0, s.ball.1 + c);
                    for o in m.obstacles() {
                        assert!(
                            distance_sq_point_aabb(&centre, &o.aabb) > reach * reach,
                            "{} called far but near '{}' at {six:?}",
                            s.part,
                            o.name
                        );
                    }
                }
            }
        }
    }
    assert!(
        called_far.iter().all(|&n| n > 100) && by_exact > 1000,
        "shapes called far {called_far:?}, {by_exact} looks left to the exact test"
    );
}

/// The balls' pass by the cubes' masks (`near.rs`) is the pass over every box: the same inner
/// balls within the clearance and far shapes, and the same least, capped at the masks' reach
/// less the largest ball radius, to the bit; at every node of a 5 deg grid in front of the
/// robot, two legs' wrists, three clearances. Both some leasts above the cap and many below it
/// (the bit-equality holds there), and blocked and far answers, must occur.
#[test]
fn the_masked_balls_pass_is_the_whole_pass() {
    let g = look_grid();
    let (mut capped, mut equal, mut within, mut far) = (0, 0, 0, 0);
    for clearance in [0.0, 10.0, 60.0] {
        let m = torch_model(clearance);
        for schedule in look_schedules() {
            for i in 0..g.len() {
                let (six, sc) = look_pose(&schedule, &g, i);
                let (masked, all, cap) = m.ball_passes_for_test(&six, &sc).expect("masks");
                assert_eq!((masked.1, masked.2), (all.1, all.2), "at {six:?}");
                assert_eq!(masked.0.to_bits(), all.0.min(cap).to_bits(), "at {six:?}");
                if all.0 > cap {
                    capped += 1;
                } else {
                    equal += 1;
                }
                within += usize::from(all.1);
                far += all.2.iter().filter(|f| **f).count();
            }
        }
    }
    assert!(
        capped > 100 && equal > 1000,
        "{capped} capped, {equal} below the cap"
    );
    assert!(within > 100 && far > 1000, "{within} within, {far} far");
}

/// A model whose clearance grew after its masks were made (`with_margin` clones the masks made
/// for the smaller clearance: their reach is too short for the new one) takes the whole pass:
/// the same least, within and far answers to the bit.
#[test]
fn a_clearance_grown_past_the_masks_takes_the_whole_pass() {
    let g = look_grid();
    let m = torch_model(10.0);
    let schedules = look_schedules();
    // A look on the small clearance makes the masks, then the clone shares them.
    let (six, sc) = look_pose(&schedules[0], &g, 0);
    m.ball_passes_for_test(&six, &sc).expect("masks made");
    let grown = m.with_margin(200.0);
    let mut differ_if_masked = 0;
    for schedule in &schedules {
        for i in 0..g.len() {
            let (six, sc) = look_pose(schedule, &g, i);
            let (pass, all, cap) = grown.ball_passes_for_test(&six, &sc).expect("masks");
            assert_eq!((pass.1, pass.2), (all.1, all.2), "at {six:?}");
            assert_eq!(pass.0.to_bits(), all.0.to_bits(), "at {six:?}");
            differ_if_masked += usize::from(all.0 > cap);
        }
    }
    // Poses where the shared masks, had they been used, would have capped the least.
    assert!(differ_if_masked > 100, "{differ_if_masked}");
}

/// A gripper of oriented boxes (a housing, two fingers) and a ball, as cells/gripper-pick.yaml.
fn gripper() -> Tool {
    let b = |name: &str, min_mm: [f64; 3], max_mm: [f64; 3]| {
        shape(name, ToolGeometry::Box { min_mm, max_mm })
    };
    Tool {
        name: "tGripper".into(),
        tframe: Frame::IDENTITY,
        mass_kg: 3.2,
        cog_mm: [0.0, 0.0, 80.0],
        shapes: vec![
            b("housing", [-60.0, -60.0, 0.0], [60.0, 60.0, 110.0]),
            b("finger_a", [-50.0, -15.0, 110.0], [-35.0, 15.0, 165.0]),
            b("finger_b", [35.0, -15.0, 110.0], [50.0, 15.0, 165.0]),
            shape(
                "sensor",
                ToolGeometry::Sphere {
                    centre_mm: [75.0, 0.0, 70.0],
                    radius_mm: 20.0,
                },
            ),
        ],
        loc: Loc::default(),
    }
}

/// The looks' exact test of an oriented tool box (`geometry::obb_clear_of_aabb`, by separating
/// axes first) answers as the distance does (`distance_obb_aabb > c`): at the nodes of
/// the 5 deg grid of the look tests with both wrists, every box shape of a gripper, placed on
/// the look's flange, against every box, at the model's clearance, at the distance to the bit
/// and one ulp below it. And the look answers as a plain exact test written out here (boxes
/// by `distance_obb_aabb`, the ball by its distance), at the poses where no shape comes within
/// 1e-6 mm of the clearance (at a pose nearer than that the cheap bounds before the exact test
/// may differ from the distance by rounding, in either test).
/// Boxes near the clearance, and both answers of the look after the balls, must occur often.
#[test]
fn a_tool_box_is_tested_as_its_distance_at_the_looks() {
    let tool = gripper();
    let g = look_grid();
    let (mut near, mut exact_clear, mut exact_blocked) = (0usize, 0usize, 0usize);
    for clearance in [0.0, 10.0, 60.0] {
        let m = trunk_model(&tool, clearance);
        let (shapes, c) = (&m.tool.as_ref().expect("a tool").shapes, m.clearance_mm());
        for schedule in look_schedules() {
            for i in 0..g.len() {
                let (six, sc) = look_pose(&schedule, &g, i);
                let flange = m.flange_sincos_for_test(&six, &sc, None).expect("a tool");
                let mut old = true;
                let mut boundary = false;
                for s in shapes {
                    let solid = s.local.placed(&flange);
                    for o in m.obstacles() {
                        let d = solid.distance_aabb(&o.aabb);
                        old &= d > c;
                        boundary |= (d - c).abs() <= 1e-6;
                        let Solid::Box(ob) = &solid else {
                            continue;
                        };
                        let below = if d > 0.0 { d.next_down() } else { d };
                        for cc in [c, d, below] {
                            assert_eq!(
                                crate::geometry::obb_clear_of_aabb(ob, &o.aabb, cc),
                                d > cc,
                                "{} and '{}' at {cc} (distance {d}) at {six:?}",
                                s.part,
                                o.name
                            );
                        }
                        near += usize::from((d - c).abs() < 20.0);
                    }
                }
                let (look, margin) = m.tool_look_sincos(&six, &sc);
                if !boundary {
                    assert_eq!(look, old, "the look at {six:?}");
                }
                if margin == 0.0 {
                    exact_clear += usize::from(look);
                    exact_blocked += usize::from(!look);
                }
            }
        }
    }
    assert!(
        near > 1000 && exact_clear > 300 && exact_blocked > 300,
        "{near} boxes near the clearance, {exact_clear} clear and {exact_blocked} blocked \
         after the balls"
    );
}

#[test]
fn the_tool_looks_least_distance_is_distance_sq_point_aabb_to_the_bit() {
    // The branch-free pass over the bounds against the per-box function, on points inside,
    // beside and far from the boxes, flat boxes included; and no boxes at all.
    let mut rng = Rng(11);
    for _ in 0..200 {
        let boxes: Vec<Obstacle> = (0..rng.below(12))
            .map(|k| {
                let a = rng.point(-1000.0, 1000.0);
                let mut b = rng.point(-1000.0, 1000.0);
                if k % 4 == 0 {
                    b.z = a.z; // flat
                }
                let (lo, hi) = (a.inf(&b), a.sup(&b));
                Obstacle::new(format!("b{k}"), Aabb::new(lo, hi))
            })
            .collect();
        let bounds = bounds_by_coordinate(&boxes);
        for _ in 0..50 {
            // Three points in one pass, each its own least.
            let ps: [Point; 3] = std::array::from_fn(|_| rng.point(-1500.0, 1500.0));
            let got = least_sq_distances(&ps, &bounds);
            for (p, got) in ps.iter().zip(got) {
                let want = boxes
                    .iter()
                    .map(|o| distance_sq_point_aabb(p, &o.aabb))
                    .fold(f64::INFINITY, f64::min);
                assert_eq!(got.to_bits(), want.to_bits());
            }
        }
    }
}
