//! Tests of the block inspection (`block.rs`) on random cells (random placements, boxes,
//! clearances, with and without a tool): the run-wise codes' free bits are the node test's at
//! every node; their depths are lower bounds of exact distances; every step the codes accept is
//! accepted by the whole-move proof; a grid built on threads equals a column-by-column fill;
//! and the blocked bound holds under random motions.

use super::block::{blocked_bound, blocked_bound_at, rim_ball_bound, signed_distance_point_aabb};
use super::grid::{COLUMN_LEVELS, DEPTH_LEVELS};
use super::tool_tests::torch;
use super::*;
use crate::geometry::distance_point_aabb;
use crate::geometry::testing::Rng;
use crate::plan::cspace::{CSpace, Grid};
use crate::robot::LinkCylinder;
use nalgebra::{Point3, Rotation3, Unit};

/// A random cell about a random placement of the IRB 1400: 1..6 boxes of 20..900 mm within
/// reach (some through the arm's space, some thin), sometimes a floor, a clearance of 0..30 mm,
/// the torch on half of them.
fn random_model(rng: &mut Rng) -> CollisionModel {
    random_model_of(rng, &Robot::irb1400())
}

/// [`random_model`] for `robot`.
fn random_model_of(rng: &mut Rng, robot: &Robot) -> CollisionModel {
    let placement = Placement {
        base_mm: [rng.range(-300.0, 300.0), rng.range(-300.0, 300.0), 0.0],
        yaw_deg: rng.range(-180.0, 180.0),
    };
    let mut boxes = Vec::new();
    if rng.below(2) == 0 {
        boxes.push(Obstacle::new(
            "floor",
            Aabb::new(
                Point3::new(-2000.0, -2000.0, -100.0),
                Point3::new(2000.0, 2000.0, rng.range(-50.0, 300.0)),
            ),
        ));
    }
    for k in 0..1 + rng.below(6) {
        let centre = Point3::new(
            placement.base_mm[0] + rng.range(-1500.0, 1500.0),
            placement.base_mm[1] + rng.range(-1500.0, 1500.0),
            rng.range(0.0, 1800.0),
        );
        let half = [0, 1, 2].map(|_| {
            if rng.below(4) == 0 {
                rng.range(5.0, 40.0)
            } else {
                rng.range(10.0, 300.0)
            }
        });
        let h = Vector3::from(half);
        boxes.push(Obstacle::new(
            format!("box{k}"),
            Aabb::new(centre - h, centre + h),
        ));
    }
    let clearance = [0.0, 5.0, 10.0, 30.0][rng.below(4) as usize];
    let tool = (rng.below(2) == 0).then(torch);
    CollisionModel::new(robot, placement, boxes, clearance, tool.as_ref())
}

/// The axis-3 values of a column on a grid of spacing `step` (ascending, as the grid's).
fn column_values(step: f64) -> Vec<f64> {
    let g = Grid::over([[0.0, 0.0], [0.0, 0.0], [-65.0, 70.0]], step);
    (0..g.dims[2] as i64).map(|i| g.value(2, i)).collect()
}

/// The least exact distance of part `p` to its boxes at `six`.
fn part_distance(model: &CollisionModel, p: usize, six: &[f64; 6]) -> f64 {
    let solids = model.solids(six);
    model
        .part_boxes(p)
        .map(|(_, b)| solids[p].1.distance_aabb(b))
        .fold(f64::INFINITY, f64::min)
}

/// On random cells, at every node of random columns: the free bit of the run-wise codes is
/// `arm_is_free`; every arm and column depth is a lower bound of the exact distance; a node
/// without the near bit has its wrist centre's ball clear, with the depth it claims. The
/// node-by-node path (a column of one node) agrees on the free bit and the tool's near bit.
#[test]
fn run_wise_codes_match_the_node_test_and_bound_the_distances() {
    let mut rng = Rng(0xB10C_0001_2345_6789);
    let (mut free, mut blocked, mut deeper, mut shallower, mut with_tool) = (0, 0, 0, 0, 0);
    let k = f64::from(DEPTH_LEVELS);
    for cell in 0..120 {
        let model = random_model(&mut rng);
        let step = [1.0, 2.0, 2.5][cell % 3];
        let check = model.grid_check(step);
        let a3 = column_values(step);
        let c = model.clearance_mm();
        let mut codes = vec![0u8; a3.len()];
        let mut column = vec![0u8; check.column_bytes()];
        for _ in 0..8 {
            let (a1, a2) = (
                (rng.range(-170.0, 170.0) / step).round() * step,
                (rng.range(-70.0, 70.0) / step).round() * step,
            );
            check.inspect_column(a1, a2, &a3, &mut codes, &mut column);
            for (&v, &code) in a3.iter().zip(&codes) {
                let axes = [a1, a2, v];
                assert_eq!(code & CODE_FREE != 0, model.arm_is_free(&axes), "{axes:?}");
                let mut one = [0u8];
                let mut one_column = vec![0u8; check.column_bytes()];
                check.inspect_column(a1, a2, &[v], &mut one, &mut one_column);
                assert_eq!(one[0] & CODE_FREE, code & CODE_FREE, "{axes:?}");
                // The tool's near bit is decided exactly by the runs too.
                assert_eq!(
                    GridCheck::tool_near(one[0]),
                    GridCheck::tool_near(code),
                    "{axes:?}"
                );
                if code == 0 {
                    if model.robot().check_range3(&axes).is_ok() {
                        blocked += 1;
                    }
                    continue;
                }
                free += 1;
                match (code & 7).cmp(&(one[0] & 7)) {
                    std::cmp::Ordering::Greater => deeper += 1,
                    std::cmp::Ordering::Less => shallower += 1,
                    _ => {}
                }
                let six = [a1, a2, v, 0.0, 0.0, 0.0];
                for i in 0..model.cyl.len() {
                    let (q, span, levels) = match check.fixed.iter().position(|&f| f == i) {
                        Some(l) => (column[l], check.fixed_span[l], f64::from(COLUMN_LEVELS)),
                        None => (code & 7, check.arm_span, k),
                    };
                    let need = c + f64::from(q) * span / levels;
                    let d = part_distance(&model, i, &six);
                    assert!(d >= need - 1e-6, "{axes:?} cylinder {i}: {d} < {need}");
                }
                if let Some(tool) = &model.tool {
                    with_tool += 1;
                    if !GridCheck::tool_near(code) {
                        // The wrist centre, placed independently of the grid's split.
                        let pose = model.cell_link_poses(&axes)[2];
                        let centre = pose * Point::from(tool.centre);
                        let f = model
                            .obstacles()
                            .iter()
                            .map(|o| distance_point_aabb(&centre, &o.aabb))
                            .fold(f64::INFINITY, f64::min)
                            - tool.radius_mm;
                        let q_t = f64::from((code >> 3) & 7);
                        assert!(f > c, "{axes:?}: tool ball {f} within {c}");
                        assert!(f >= c + q_t * check.centre_span / k - 1e-6, "{axes:?}");
                    }
                }
            }
        }
    }
    assert!(
        free > 20_000 && blocked > 20_000 && with_tool > 10_000,
        "{free} free, {blocked} blocked, {with_tool} with a tool"
    );
    // A column of one node measures every box at its node: the runs are never deeper, and
    // shallower (a run proven free gives its nodes its own bound; a run's halves reuse a bound
    // along the column) at a minority of the nodes (about 14 %).
    assert!(
        deeper == 0 && shallower * 4 < free,
        "{deeper} deeper, {shallower} shallower of {free}"
    );
}

/// On random cells: every step between neighbouring free nodes (codes from whole columns)
/// that the codes accept is accepted by the whole-move proof, links and tool (random wrists).
#[test]
fn steps_the_run_wise_codes_accept_are_accepted_by_the_proof() {
    let mut rng = Rng(0xB10C_0002_5AFE_57E9);
    let (mut tried, mut proven) = (0, 0);
    for cell in 0..40 {
        let model = random_model(&mut rng);
        let step = [1.0, 2.0][cell % 2];
        let check = model.grid_check(step);
        let a3 = column_values(step);
        let column = |a1: f64, a2: f64| {
            let mut codes = vec![0u8; a3.len()];
            let mut bytes = vec![0u8; check.column_bytes()];
            check.inspect_column(a1, a2, &a3, &mut codes, &mut bytes);
            (codes, bytes)
        };
        for _ in 0..6 {
            let (a1, a2) = (
                (rng.range(-168.0, 168.0) / step).round() * step,
                (rng.range(-68.0, 68.0) / step).round() * step,
            );
            let o12 = [rng.below(3) as i32 - 1, rng.below(3) as i32 - 1];
            let (b1, b2) = (a1 + f64::from(o12[0]) * step, a2 + f64::from(o12[1]) * step);
            let (ca, cola) = column(a1, a2);
            let (cb, colb) = column(b1, b2);
            for _ in 0..60 {
                let i = 1 + rng.below(a3.len() as u64 - 2) as usize;
                let o3 = rng.below(3) as i32 - 1;
                let o = [o12[0], o12[1], o3];
                let j = (i as i32 + o3) as usize;
                if o == [0, 0, 0] || ca[i] == 0 || cb[j] == 0 {
                    continue;
                }
                tried += 1;
                let (arm, tool) = check.proven_by_codes(
                    Ends {
                        code: ca[i],
                        column: &cola,
                    },
                    Ends {
                        code: cb[j],
                        column: &colb,
                    },
                    o,
                );
                let w0 = [
                    rng.range(-150.0, 150.0),
                    rng.range(-115.0, 115.0),
                    rng.range(-300.0, 300.0),
                ];
                let w1 = [0, 1, 2].map(|k| w0[k] + rng.range(-30.0, 30.0));
                let from = [a1, a2, a3[i], w0[0], w0[1], w0[2]];
                let to = [b1, b2, a3[j], w1[0], w1[1], w1[2]];
                if arm {
                    proven += 1;
                    assert!(model.links_move_is_safe(&from, &to), "{from:?} -> {to:?}");
                }
                if tool && model.has_tool() {
                    assert!(model.tool_move_is_safe(&from, &to), "{from:?} -> {to:?}");
                }
            }
        }
    }
    assert!(
        tried > 4000 && proven > 3000,
        "{tried} tried, {proven} proven"
    );
}

/// The grid built on threads holds the same codes and column bytes as a column-by-column fill
/// on this thread (the runs depend on the column alone).
#[test]
fn a_grid_built_on_threads_equals_a_column_by_column_fill() {
    // The build goes slice by slice (link 1's checks once per slice of axis 1): it must equal
    // the columns inspected alone, also where link 1 meets a box in some slices only.
    let mut rng = Rng(0xB10C_0003_7412_0000);
    for _ in 0..8 {
        let model = random_model(&mut rng);
        let grid = Grid::over([[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]], 5.0);
        let check = model.grid_check(grid.step_deg);
        let built = CSpace::build(grid, &check);
        each_column_alone(&check, &grid, &built, |_, _| {});
    }
}

/// Every column of `grid` inspected alone (`inspect_column`: a fresh slice and memo) gives the
/// codes and column bytes of `built` (the bytes as every block of the column along axis 3
/// holds them), and `at_node` sees every node with its axes.
fn each_column_alone(
    check: &GridCheck,
    grid: &Grid,
    built: &CSpace,
    mut at_node: impl FnMut([i32; 3], [f64; 3]),
) {
    let a3: Vec<f64> = (0..grid.dims[2] as i64).map(|i| grid.value(2, i)).collect();
    let mut codes = vec![0u8; a3.len()];
    let mut bytes = vec![0u8; check.column_bytes()];
    for i1 in 0..grid.dims[0] {
        for i2 in 0..grid.dims[1] {
            let (a1, a2) = (grid.value(0, i1 as i64), grid.value(1, i2 as i64));
            check.inspect_column(a1, a2, &a3, &mut codes, &mut bytes);
            let n = [i1 as i32, i2 as i32, 0];
            assert_eq!(built.column(n), &bytes[..], "{a1} {a2}");
            for (i3, &code) in codes.iter().enumerate() {
                let n = [i1 as i32, i2 as i32, i3 as i32];
                assert_eq!(built.code(n), code, "{n:?}");
                assert_eq!(built.column(n), &bytes[..], "{n:?}");
                at_node(n, [a1, a2, a3[i3]]);
            }
        }
    }
}

/// A part of a slice's columns (`Inspector::inspect_slice_part`: only the runs holding nodes
/// of the part inspected) holds the codes and column bytes of the whole slice's inspection
/// there, on random cells (with and without the torch) at 1 deg, for parts on the runs'
/// boundaries and across them, of one node, of the last nodes, and the whole column; the free
/// bits are `arm_is_free`'s. A part that left out a run holding one of its nodes, or read a
/// run's carried bound from another run's slot, would leave a code the whole slice does not
/// have.
#[test]
fn a_part_of_a_slice_holds_the_whole_slices_codes() {
    use crate::plan::cspace::Inspector;
    let mut rng = Rng(0x9A27_0001_5EED_0042);
    let grid = Grid::over([[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]], 1.0);
    let a3: Vec<f64> = (0..grid.dims[2] as i64).map(|i| grid.value(2, i)).collect();
    let d2 = a3.len();
    let parts = [
        0..32,
        32..64,
        128..d2,
        5..40,
        31..33,
        70..71,
        0..d2,
        100..d2,
    ];
    let (mut free, mut compared) = (0, 0);
    for _ in 0..12 {
        let model = random_model(&mut rng);
        let check = model.grid_check(grid.step_deg);
        let a1 = rng.range(-160.0, 160.0).round();
        let lo2 = rng.range(-60.0, 50.0).round();
        let a2: Vec<f64> = (0..4).map(|k| lo2 + f64::from(k)).collect();
        let width = check.column_bytes();
        let mut whole = vec![0u8; a2.len() * d2];
        let mut bytes = vec![0u8; a2.len() * width];
        Inspector::inspect_slice(&check, a1, &a2, &a3, &mut whole, &mut bytes);
        for part in parts.clone() {
            let mut code = vec![0u8; a2.len() * part.len()];
            let mut own = vec![0u8; a2.len() * width];
            check.inspect_slice_part(a1, &a2, &a3, part.clone(), &mut code, &mut own);
            assert_eq!(own, bytes, "{a1} {a2:?} {part:?}");
            for (j, &v2) in a2.iter().enumerate() {
                let want = &whole[j * d2..][part.clone()];
                assert_eq!(
                    &code[j * part.len()..][..part.len()],
                    want,
                    "{a1} {v2} {part:?}"
                );
                for (k, &c) in want.iter().enumerate() {
                    if k % 3 == 0 {
                        let axes = [a1, v2, a3[part.start + k]];
                        assert_eq!(c & 0x80 != 0, model.arm_is_free(&axes), "{axes:?}");
                        compared += 1;
                        free += usize::from(c != 0);
                    }
                }
            }
        }
    }
    assert!(
        free > compared / 10 && free < compared,
        "{free} of {compared}"
    );
}

/// The blocked bound of `block.rs` under random rigid motions of at most `m` per point: the
/// moved cylinder's exact distance never exceeds `max(0, bound)`; the signed distance is the
/// distance outside and minus the depth inside. The same for the bound from any point of the
/// axis (`blocked_bound_at` with a random `t`: its inner axis point is still one), and for the
/// ball at a cap's rim (`rim_ball_bound`, for either cap), which must be better than the inner
/// capsule's in some cases (a cap's rim towards the box). A third of the cylinders are short
/// discs (the rim ball must stay inside the cap's thickness too).
#[test]
fn the_blocked_bound_holds_under_bounded_motions() {
    let mut rng = Rng(0xB10C_0004_0000_0001);
    let b = Aabb::new(
        Point3::new(-100.0, -50.0, 0.0),
        Point3::new(100.0, 50.0, 300.0),
    );
    assert_eq!(
        signed_distance_point_aabb(&Point3::new(0.0, 0.0, 10.0), &b),
        -10.0
    );
    assert_eq!(
        signed_distance_point_aabb(&Point3::new(0.0, 80.0, 340.0), &b),
        50.0
    );
    assert_eq!(
        signed_distance_point_aabb(&Point3::new(-100.0, 0.0, 100.0), &b),
        0.0
    );
    let (mut tight, mut rim_better) = (0, 0);
    for k in 0..4500 {
        // A third of the cylinders short (a disc up to twice its radius long), where a ball
        // too large for the cap would poke out of its face.
        let (a, radius) = (rng.point(-400.0, 400.0), rng.range(0.0, 150.0));
        let b_end = if k % 3 == 0 {
            let dir = rng.point(-1.0, 1.0).coords + Vector3::new(1e-9, 0.0, 0.0);
            a + dir.normalize() * rng.range(0.01, 2.0 * radius.max(0.01))
        } else {
            rng.point(-400.0, 400.0)
        };
        let cyl = Cylinder {
            a,
            b: b_end,
            radius,
        };
        let m = rng.range(0.0, 120.0);
        let bound = blocked_bound(&cyl, &b, m);
        // A rotation about the cylinder's middle and a translation, together moving no point
        // of the cylinder more than m.
        let half = 0.5 * (cyl.b - cyl.a).norm() + cyl.radius;
        let mid = nalgebra::center(&cyl.a, &cyl.b);
        let turn = rng.range(0.0, 1.0) * m;
        let angle = if half > 0.0 {
            (turn / half).min(0.5)
        } else {
            0.0
        };
        let axis = Unit::new_normalize(rng.point(-1.0, 1.0).coords + Vector3::new(1e-9, 0.0, 0.0));
        let rot = Rotation3::from_axis_angle(&axis, angle);
        let shift = rng.point(-1.0, 1.0).coords;
        let shift = if shift.norm() > 0.0 {
            shift * ((m - angle * half).max(0.0) / shift.norm()) * rng.range(0.0, 1.0)
        } else {
            shift
        };
        let moved = |p: Point| mid + rot * (p - mid) + shift;
        let c2 = Cylinder {
            a: moved(cyl.a),
            b: moved(cyl.b),
            radius: cyl.radius,
        };
        let d = Solid::Cylinder(c2).distance_aabb(&b);
        assert!(d <= bound.max(0.0) + 1e-6, "{cyl:?} m {m}: {d} > {bound}");
        if d > 0.0 && d > bound - 5.0 {
            tight += 1;
        }
        let t = rng.range(0.0, 1.0);
        let at = blocked_bound_at(&cyl, &b, m, t);
        assert!(d <= at.max(0.0) + 1e-6, "{cyl:?} m {m} t {t}: {d} > {at}");
        let rim = rim_ball_bound(&cyl, &b, m, t);
        assert!(
            d <= rim.max(0.0) + 1e-6,
            "{cyl:?} m {m} t {t}: {d} > rim {rim}"
        );
        if rim < bound.min(at) - 1.0 {
            rim_better += 1;
        }
    }
    assert!(tight > 40 && rim_better > 100, "{tight} {rim_better}");
}

/// The slice-wise build (link 1's checks once per slice of axis 1) against the node test at
/// every node, with link 1's cylinder moved off axis 1 (the IRB 1400's stands on it, so its
/// checks are the same in every slice and a slice mix-up would not show): boxes beside the base
/// block some slices of axis 1 and not others, and every free bit must be `arm_is_free`'s.
#[test]
fn a_slice_wise_build_keeps_an_off_axis_link_1_exact() {
    slice_wise_link_1_exact(off_axis_link_1());
}

/// The IRB 1400 with its link-1 cylinder 400 mm off axis 1.
fn off_axis_link_1() -> Robot {
    let mut robot = Robot::irb1400();
    let l1 = robot
        .cylinders
        .iter()
        .position(|c| c.joint_index == 0)
        .expect("the IRB 1400 has a link-1 cylinder");
    robot.cylinders[l1].a.x += 400.0;
    robot.cylinders[l1].b.x += 400.0;
    robot
}

/// The same with link 1's cylinder after [`MAX_FIXED`](super::column::MAX_FIXED) others of
/// link 1 (tiny, at the base, clear of every post): its slice answer is not kept, so each
/// column places it itself, on link 1 (placed on link 2, its free bits come out wrong).
#[test]
fn a_link_1_cylinder_past_the_slices_answers_is_placed_on_link_1() {
    let mut robot = off_axis_link_1();
    let tiny = LinkCylinder {
        link: "link_1".into(),
        joint_index: 0,
        a: Point3::new(0.0, 0.0, 0.0),
        b: Point3::new(0.0, 0.0, 1.0),
        radius_mm: 0.5,
    };
    for _ in 0..super::column::MAX_FIXED {
        robot.cylinders.insert(0, tiny.clone());
    }
    slice_wise_link_1_exact(robot);
}

/// Every free bit of a slice-wise build of `robot` among posts around its base is
/// `arm_is_free`'s, with some slices of axis 1 blocked and some open.
fn slice_wise_link_1_exact(robot: Robot) {
    let mut rng = Rng(0x511C_E0FF_A815_0001);
    let (mut slices_blocked, mut slices_open) = (0, 0);
    for _ in 0..4 {
        let placement = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: rng.range(-180.0, 180.0),
        };
        // Posts around the base, as high as link 1 reaches, at random angles.
        let boxes: Vec<Obstacle> = (0..3)
            .map(|k| {
                let t = rng.range(-3.2, 3.2);
                let r = rng.range(600.0, 900.0);
                let c = Point3::new(r * t.cos(), r * t.sin(), 300.0);
                let h = Vector3::new(80.0, 80.0, 300.0);
                Obstacle::new(format!("post{k}"), Aabb::new(c - h, c + h))
            })
            .collect();
        let model = CollisionModel::new(&robot, placement, boxes, 10.0, None);
        let grid = Grid::over([[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]], 10.0);
        let check = model.grid_check(grid.step_deg);
        let built = CSpace::build(grid, &check);
        for i1 in 0..grid.dims[0] {
            let mut any_free = false;
            for i2 in 0..grid.dims[1] {
                for i3 in 0..grid.dims[2] {
                    let n = [i1 as i32, i2 as i32, i3 as i32];
                    let axes = [0, 1, 2].map(|k| grid.value(k, n[k] as i64));
                    let free = model.arm_is_free(&axes);
                    assert_eq!(built.is_free(n), free, "{axes:?}");
                    any_free |= free;
                }
            }
            if any_free {
                slices_open += 1;
            } else {
                slices_blocked += 1;
            }
        }
    }
    assert!(
        slices_blocked > 0 && slices_open > 0,
        "{slices_blocked} blocked, {slices_open} open"
    );
}

/// What the columns of a slice carry along (`column.rs`, `FixedMemo`): link 2's capsule
/// distances and the top runs' free bounds of the cylinders axis 3 moves. On random cells at 1
/// deg, where a box stays unmeasured over many columns, the slice-wise build's codes and column
/// bytes equal each column inspected alone (a fresh memo), and the free bits are `arm_is_free`'s.
/// A motion bound too small for axis 2's steps would keep a box that came nearer unmeasured and
/// leave a code or byte too deep (or a blocked column free). The IRB 1400 as it is (its
/// parallelogram coupling: link 3 only translates with axis 2, `grid.rs`'s `shift3`) and
/// with a serial coupling (axis 2 turns link 3: the general bound).
#[test]
fn bounds_carried_along_a_slice_change_no_byte() {
    let mut serial = Robot::irb1400();
    serial.controller.coupling = crate::robot::controller::Coupling::Serial;
    for (robot, cells) in [(Robot::irb1400(), 7), (serial, 4)] {
        carried_bounds_change_no_byte(&robot, cells);
    }
}

/// [`bounds_carried_along_a_slice_change_no_byte`] on `want` open random cells of `robot`.
fn carried_bounds_change_no_byte(robot: &Robot, want: usize) {
    let mut rng = Rng(0xF1ED_0002_C0DE_0001);
    let (mut cells, mut compared) = (0, 0);
    for _ in 0..200 {
        if cells == want {
            break;
        }
        let model = random_model_of(&mut rng, robot);
        let a1 = (rng.range(-160.0, 160.0)).round();
        let grid = Grid::over([[a1 - 2.0, a1 + 2.0], [-70.0, 70.0], [-65.0, 70.0]], 1.0);
        let check = model.grid_check(grid.step_deg);
        let built = CSpace::build(grid, &check);
        // Most random cells block link 1 or 2 in a few slices: only open ones are compared.
        if built.free_count() < 10_000 {
            continue;
        }
        cells += 1;
        each_column_alone(&check, &grid, &built, |n, axes| {
            if n[2] % 5 == 0 {
                assert_eq!(built.is_free(n), model.arm_is_free(&axes), "{axes:?}");
                compared += 1;
            }
        });
    }
    assert!(
        cells == want && compared > 5_000 * want,
        "{cells} {compared}"
    );
}

/// The shift of the cylinders axis 3 moves (`grid.rs`, `shift3`): with axes 1 and 3 fixed, no
/// end of such a cylinder moves more than `shift |da2|` (rad) between random poses; under the
/// IRB 1400's parallelogram coupling link 3 only translates, by joint 3's origin's chord about
/// joint 2 (600 mm of radius), far less than the general bound `R[1] + R[2]`.
#[test]
fn the_axis_2_shift_bounds_link_3s_motion() {
    let mut rng = Rng(0x5A1F_7000_0000_0003);
    let model = random_model(&mut rng);
    let check = model.grid_check(1.0);
    let mut tight = 0;
    for &(i, _, shift) in &check.split3 {
        let general = model.cyl[i].reach_mm[1] + model.cyl[i].reach_mm[2];
        assert!(shift <= general, "{shift} {general}");
        if shift < 0.5 * general {
            tight += 1;
        }
        for _ in 0..2000 {
            let a1 = rng.range(-170.0, 170.0);
            let (a2, b2) = (rng.range(-70.0, 70.0), rng.range(-70.0, 70.0));
            let a3 = rng.range(-65.0, 70.0);
            let at = |a2: f64| model.cylinder_in(i, &model.cell_link_poses(&[a1, a2, a3]));
            let (p, q) = (at(a2), at(b2));
            let bound = shift * (a2 - b2).abs().to_radians() + 1e-9;
            assert!((p.a - q.a).norm() <= bound, "{a1} {a2} {b2} {a3}");
            assert!((p.b - q.b).norm() <= bound, "{a1} {a2} {b2} {a3}");
        }
    }
    assert!(tight > 0, "{tight}");
}
