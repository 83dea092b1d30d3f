//! Tests of the collision model: node inspection against an independent placement of the
//! cylinders and parry3d's distances, the Lipschitz bound, and the whole-move proof against dense
//! sampling.

use super::proof::lerp;
use super::*;
use nalgebra::Point3;
use parry3d::math::{Pose, Rotation, Vector};

use crate::geometry::testing::Rng;

/// Six axes from three, the wrist at zero (links do not depend on it).
fn s6(a: [f64; 3]) -> [f64; 6] {
    [a[0], a[1], a[2], 0.0, 0.0, 0.0]
}

fn link(name: &str) -> Part {
    Part::Link(name.into())
}

/// The free bits of a column's node codes (the grid's node test).
fn column_free(model: &CollisionModel, a1: f64, a2: f64, a3: &[f64], len: usize) -> Vec<bool> {
    let check = model.grid_check(1.0);
    let mut codes = vec![0xffu8; len];
    let mut column = vec![0u8; check.column_bytes()];
    check.inspect_column(a1, a2, a3, &mut codes, &mut column);
    codes.iter().map(|&c| c & CODE_FREE != 0).collect()
}

fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
    Obstacle::new(name, Aabb::new(Point3::from(min), Point3::from(max)))
}

const TRUNK_PLACEMENT: Placement = Placement {
    base_mm: [0.0, -850.0, 0.0],
    yaw_deg: 90.0,
};

/// The trunk-like scene of the paper's section 6 (cell frame, mm).
fn trunk() -> Vec<Obstacle> {
    vec![
        bx("floor", [-900.0, -450.0, 0.0], [900.0, 450.0, 100.0]),
        bx("near wall", [-900.0, -450.0, 0.0], [900.0, -430.0, 500.0]),
        bx("far wall", [-900.0, 430.0, 0.0], [900.0, 450.0, 500.0]),
        bx("left wall", [-900.0, -450.0, 0.0], [-880.0, 450.0, 500.0]),
        bx("right wall", [880.0, -450.0, 0.0], [900.0, 450.0, 500.0]),
        bx("tower", [-150.0, 0.0, 0.0], [150.0, 300.0, 1000.0]),
    ]
}

fn trunk_model(clearance: f64) -> CollisionModel {
    CollisionModel::new(&Robot::irb1400(), TRUNK_PLACEMENT, trunk(), clearance, None)
}

/// Cylinders in the cell frame computed independently of the model (robot FK + placement).
pub(super) fn reference_cylinders(robot: &Robot, pl: Placement, axes: &[f64; 3]) -> Vec<Cylinder> {
    let yaw = pl.yaw_deg.to_radians();
    let to_cell = |p: Point3<f64>| {
        Point3::new(
            yaw.cos() * p.x - yaw.sin() * p.y + pl.base_mm[0],
            yaw.sin() * p.x + yaw.cos() * p.y + pl.base_mm[1],
            p.z + pl.base_mm[2],
        )
    };
    let poses = robot.arm_link_poses(axes);
    robot
        .cylinders
        .iter()
        .map(|c| Cylinder {
            a: to_cell(poses[c.joint_index] * c.a),
            b: to_cell(poses[c.joint_index] * c.b),
            radius: c.radius_mm,
        })
        .collect()
}

/// Exact cylinder-box distance straight from parry3d-f64 (its own shapes, GJK).
pub(super) fn parry_distance(c: &Cylinder, b: &Aabb) -> f64 {
    let centre = nalgebra::center(&b.min, &b.max);
    let h = (b.max - b.min) * 0.5;
    let cuboid = parry3d::shape::Cuboid::new(Vector::new(h.x, h.y, h.z));
    let d = c.b - c.a;
    let len = d.norm();
    let u = d / len;
    let cyl = parry3d::shape::Cylinder::new(0.5 * len, c.radius);
    let m = nalgebra::center(&c.a, &c.b);
    let rot = Rotation::from_rotation_arc(Vector::Y, Vector::new(u.x, u.y, u.z));
    let pc = Pose::from_parts(Vector::new(m.x, m.y, m.z), rot);
    let pb = Pose::from_parts(
        Vector::new(centre.x, centre.y, centre.z),
        Rotation::IDENTITY,
    );
    parry3d::query::distance(&pc, &cyl, &pb, &cuboid)
        .expect("cylinder-cuboid is supported")
        .distance
}

/// Dense minimum of the parry distance along a move, with steps so that no point of any link
/// moves more than 1 mm between samples; also the step count.
fn dense_min(model: &CollisionModel, from: &[f64; 3], to: &[f64; 3]) -> (f64, usize) {
    let m = model
        .part_speeds(&s6(*from), &s6(*to))
        .into_iter()
        .fold(0.0f64, f64::max);
    let n = (m / 1.0).ceil().max(1.0) as usize;
    let mut best = f64::INFINITY;
    for s in 0..=n {
        let axes = lerp(from, to, s as f64 / n as f64);
        for c in reference_cylinders(model.robot(), model.placement(), &axes) {
            for o in model.obstacles() {
                best = best.min(parry_distance(&c, &o.aabb));
            }
        }
    }
    (best, n)
}

/// [`dense_min`] for one (link, obstacle) pair.
fn dense_min_of_pair(
    model: &CollisionModel,
    from: &[f64; 3],
    to: &[f64; 3],
    link: &str,
    obstacle: &str,
) -> f64 {
    let m = model
        .part_speeds(&s6(*from), &s6(*to))
        .into_iter()
        .fold(0.0f64, f64::max);
    let n = (m / 1.0).ceil().max(1.0) as usize;
    let robot = model.robot();
    let mut best = f64::INFINITY;
    for s in 0..=n {
        let axes = lerp(from, to, s as f64 / n as f64);
        let cyls = reference_cylinders(robot, model.placement(), &axes);
        for (c, lc) in cyls.iter().zip(&robot.cylinders) {
            for o in model.obstacles().iter().filter(|o| o.name == obstacle) {
                if lc.link == link {
                    best = best.min(parry_distance(c, &o.aabb));
                }
            }
        }
    }
    best
}

fn random_in_range(rng: &mut Rng, model: &CollisionModel) -> [f64; 3] {
    loop {
        let a = [
            rng.range(-170.0, 170.0),
            rng.range(-70.0, 70.0),
            rng.range(-65.0, 70.0),
        ];
        if model.robot().check_range3(&a).is_ok() {
            return a;
        }
    }
}

/// Random moves with both ends free, spans up to `span` degrees per axis.
fn random_free_moves(
    rng: &mut Rng,
    model: &CollisionModel,
    count: usize,
    span: f64,
) -> Vec<([f64; 3], [f64; 3])> {
    let mut out = Vec::new();
    while out.len() < count {
        let from = random_in_range(rng, model);
        if !model.is_free(&s6(from)) {
            continue;
        }
        let to = [0, 1, 2].map(|i| from[i] + rng.range(-span, span));
        // Two moves in three start near an obstacle, where the check has work to do.
        let near = model
            .clearance_at(&s6(from))
            .min(model.clearance_at(&s6(to)))
            < 150.0;
        if model.is_free(&s6(to)) && (near || out.len() % 3 == 2) {
            out.push((from, to));
        }
    }
    out
}

#[test]
fn placement_puts_the_zero_pose_wrist_centre_where_irb1400_md_says() {
    let robot = Robot::irb1400();
    let model = CollisionModel::new(&robot, TRUNK_PLACEMENT, vec![], 10.0, None);
    let want = Vector3::new(0.0, -850.0 + 870.0, 1195.0);
    let via_frame = model.cell_from_robot * robot.wrist_centre(&[0.0; 6]);
    assert!((via_frame.coords - want).norm() < 1e-9, "{via_frame:?}");
    // The wrist centre lies on the forearm cylinder's axis, 1020 mm from its back end.
    let solids = model.solids(&[0.0; 6]);
    let (Solid::Cylinder(base), Solid::Cylinder(fore)) = (solids[0].1, solids[2].1) else {
        panic!("{solids:?}")
    };
    assert_eq!(solids[2].0, Part::Link("link_3".into()));
    let u = (fore.b - fore.a).normalize();
    let on_axis = fore.a + u * 1020.0;
    assert!((on_axis.coords - want).norm() < 1e-9, "{on_axis:?}");
    // The base cylinder stands on the placement point.
    assert!((base.a.coords - Vector3::new(0.0, -850.0, 0.0)).norm() < 1e-9);
}

#[test]
fn why_blocked_names_the_link_and_the_obstacle() {
    let robot = Robot::irb1400();
    let here = Placement {
        base_mm: [0.0; 3],
        yaw_deg: 0.0,
    };
    // Zero pose: forearm along x at z = 1195 (r 120); upper arm along z at x = 150 (r 150).
    let front = bx("front", [600.0, -50.0, 1100.0], [700.0, 50.0, 1300.0]);
    let side = bx("side", [305.0, -50.0, 800.0], [400.0, 50.0, 900.0]);
    let both = CollisionModel::new(&robot, here, vec![side.clone(), front.clone()], 10.0, None);
    assert!(!both.is_free(&s6([0.0; 3])));
    match both.why_blocked(&s6([0.0; 3])) {
        Some(Blocked::Contact {
            part,
            obstacle,
            distance_mm,
        }) => {
            assert_eq!((part, obstacle.as_str()), (link("link_3"), "front"));
            assert_eq!(distance_mm, 0.0);
        }
        other => panic!("{other:?}"),
    }
    let only_side = CollisionModel::new(&robot, here, vec![side], 10.0, None);
    let why = only_side.why_blocked(&s6([0.0; 3]));
    match &why {
        Some(Blocked::Contact {
            part,
            obstacle,
            distance_mm,
        }) => {
            assert_eq!((part, obstacle.as_str()), (&link("link_2"), "side"));
            assert!((distance_mm - 5.0).abs() < 1e-9, "{distance_mm}");
        }
        other => panic!("{other:?}"),
    }
    let text = why.map(|w| w.to_string()).unwrap_or_default();
    assert!(
        text.contains("link_2") && text.contains("'side'") && text.contains("5.00 mm"),
        "{text}"
    );
    // Raising the box clears the upper arm: 5 mm is not more than 10, 15 mm is.
    let clear = CollisionModel::new(
        &robot,
        here,
        vec![bx("side", [315.0, -50.0, 800.0], [400.0, 50.0, 900.0])],
        10.0,
        None,
    );
    assert!(clear.is_free(&s6([0.0; 3])) && clear.why_blocked(&s6([0.0; 3])).is_none());
    assert!((clear.clearance_at(&s6([0.0; 3])) - 15.0).abs() < 1e-9);
    // Range comes first, the coupled range included.
    assert!(matches!(
        both.why_blocked(&s6([0.0, -70.0, 70.0])),
        Some(Blocked::Range(RangeViolation::Coupled { .. }))
    ));
}

#[test]
fn is_free_and_inspect_column_agree_on_a_coarse_grid() {
    let model = trunk_model(10.0);
    // A few values outside the ranges exercise the range checks.
    let a3: Vec<f64> = (-14..=15).map(|k| k as f64 * 5.0).collect();
    let (mut free, mut blocked, mut range) = (0, 0, 0);
    for i1 in -18..=18 {
        for i2 in -8..=8 {
            let (a1, a2) = (i1 as f64 * 10.0 - 0.5, i2 as f64 * 9.0 + 0.25);
            let col = column_free(&model, a1, a2, &a3, a3.len());
            for (k, &v) in a3.iter().enumerate() {
                let axes = [a1, a2, v];
                let want = model.is_free(&s6(axes));
                assert_eq!(model.arm_is_free(&axes), want, "{axes:?}");
                assert_eq!(col[k], want, "{axes:?}");
                assert_eq!(model.why_blocked(&s6(axes)).is_none(), want, "{axes:?}");
                if want {
                    free += 1;
                    assert!(model.clearance_at(&s6(axes)) > 10.0, "{axes:?}");
                } else if model.robot().check_range3(&axes).is_err() {
                    range += 1;
                } else {
                    blocked += 1;
                    assert!(model.clearance_at(&s6(axes)) <= 10.0 + 1e-6, "{axes:?}");
                }
            }
        }
    }
    assert!(
        free > 1000 && blocked > 500 && range > 1000,
        "{free} {blocked} {range}"
    );
    // At 1 degree, as the planner fills the grid (exercises the skipping along the column).
    let fine: Vec<f64> = (-65..=70).map(f64::from).collect();
    let mut rng = Rng(0xF1E1_D000_0000_0001);
    let (mut free, mut blocked) = (0, 0);
    for _ in 0..300 {
        let (a1, a2) = (rng.range(-170.0, 170.0), rng.range(-70.0, 70.0));
        let col = column_free(&model, a1, a2, &fine, fine.len());
        for (k, &v) in fine.iter().enumerate() {
            assert_eq!(col[k], model.is_free(&s6([a1, a2, v])), "{:?}", [a1, a2, v]);
            if col[k] {
                free += 1;
            } else {
                blocked += 1;
            }
        }
    }
    assert!(free > 5000 && blocked > 5000, "{free} {blocked}");
    // A code slice longer than the column is padded with blocked nodes.
    let longer = column_free(&model, 0.0, 0.0, &[0.0, -5.0], 4);
    assert_eq!(longer, [true, true, false, false]);
}

#[test]
fn extra_bounds_of_link_clear_of_box_agree_with_parry() {
    let mut rng = Rng(0xB0B0_CAFE_1234_5678);
    let (mut clear, mut blocked) = (0, 0);
    for k in 0..4000 {
        let b = Aabb::new(
            Point::new(
                rng.range(-300.0, 0.0),
                rng.range(-300.0, 0.0),
                rng.range(-300.0, 0.0),
            ),
            Point::new(
                rng.range(0.0, 300.0),
                rng.range(0.0, 300.0),
                rng.range(0.0, 300.0),
            ),
        );
        // Cylinders near the box, often with a cap facing it.
        let a = Point::new(
            rng.range(-600.0, 600.0),
            rng.range(-600.0, 600.0),
            rng.range(-600.0, 600.0),
        );
        let dir = if k % 2 == 0 {
            (a - nalgebra::center(&b.min, &b.max)).normalize()
        } else {
            Vector3::new(
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
            )
            .normalize()
        };
        let c = Cylinder {
            a,
            b: a + dir * rng.range(50.0, 1100.0),
            radius: rng.range(20.0, 150.0),
        };
        let exact = parry_distance(&c, &b);
        let clearance = if k % 3 == 0 {
            rng.range(0.0, 30.0)
        } else {
            exact + rng.range(-20.0, 20.0)
        };
        let got = link_clear_of_box(&c, &b, clearance.max(0.0));
        if (exact - clearance.max(0.0)).abs() > 1e-6 {
            assert_eq!(
                got,
                exact > clearance.max(0.0),
                "case {k}: exact {exact}, clearance {clearance}, {c:?} {b:?}"
            );
        }
        if got {
            clear += 1
        } else {
            blocked += 1
        }
    }
    assert!(clear > 1000 && blocked > 1000, "{clear} {blocked}");
}

#[test]
fn lipschitz_bound_holds_for_small_random_deltas() {
    let model = trunk_model(10.0);
    let robot = model.robot().clone();
    let mut rng = Rng(0x5EED_0123_4567_89AB);
    let mut worst_ratio = 0.0f64;
    for _ in 0..3000 {
        let q = random_in_range(&mut rng, &model);
        let d = [0, 1, 2].map(|_| rng.range(-3.0, 3.0));
        let q2 = [q[0] + d[0], q[1] + d[1], q[2] + d[2]];
        let bound = model.part_speeds(&s6(q), &s6(q2));
        let (p1, p2) = (model.cell_link_poses(&q), model.cell_link_poses(&q2));
        for (i, c) in robot.cylinders.iter().enumerate() {
            let j = c.joint_index;
            // End points and rim points of both caps.
            let axis = (c.b - c.a).normalize();
            let n1 = axis
                .cross(&Vector3::x())
                .try_normalize(1e-9)
                .unwrap_or_else(|| axis.cross(&Vector3::y()).normalize());
            let n2 = axis.cross(&n1);
            let mut pts = vec![c.a, c.b];
            for end in [c.a, c.b] {
                for n in [n1, -n1, n2, -n2] {
                    pts.push(end + n * c.radius_mm);
                }
            }
            for p in pts {
                let moved = (p2[j] * p - p1[j] * p).norm();
                assert!(
                    moved <= bound[i] * (1.0 + 1e-9) + 1e-9,
                    "{} at {q:?} + {d:?}: moved {moved} > bound {}",
                    c.link,
                    bound[i]
                );
                if bound[i] > 1e-6 {
                    worst_ratio = worst_ratio.max(moved / bound[i]);
                }
            }
        }
    }
    // The bound is not absurdly loose either.
    assert!(
        worst_ratio > 0.5,
        "largest displacement / bound = {worst_ratio}"
    );
}

#[test]
fn accepted_moves_keep_the_clearance_at_dense_samples() {
    // The trunk, plus a pillar and a shelf beside the robot.
    let mut boxes = trunk();
    boxes.push(bx("pillar", [500.0, -1000.0, 0.0], [700.0, -800.0, 1600.0]));
    boxes.push(bx(
        "shelf",
        [-900.0, -1300.0, 900.0],
        [-500.0, -900.0, 1000.0],
    ));
    let model = CollisionModel::new(&Robot::irb1400(), TRUNK_PLACEMENT, boxes, 10.0, None);
    let mut rng = Rng(0x0DDB_A11C_0FFE_E123);
    let moves = random_free_moves(&mut rng, &model, 150, 90.0);
    let (mut accepted, mut roomy, mut roomy_accepted, mut unsafe_seen) = (0, 0, 0, 0);
    for (from, to) in &moves {
        let safe = model.move_is_safe(&s6(*from), &s6(*to));
        let (dmin, n) = dense_min(&model, from, to);
        if safe {
            accepted += 1;
            assert!(
                dmin >= 10.0 - 1e-6,
                "accepted {from:?} -> {to:?}, dense min {dmin} ({n} samples)"
            );
            assert!(model.why_move_unsafe(&s6(*from), &s6(*to)).is_none());
        } else {
            let why = model.why_move_unsafe(&s6(*from), &s6(*to));
            assert!(why.is_some(), "{from:?} -> {to:?}");
        }
        if dmin < 10.0 {
            unsafe_seen += 1;
            assert!(!safe);
        }
        if dmin >= 15.0 {
            roomy += 1;
            if safe {
                roomy_accepted += 1;
            }
        }
    }
    eprintln!("moves {} accepted {accepted} unsafe {unsafe_seen} roomy {roomy} roomy accepted {roomy_accepted}", moves.len());
    assert!(
        unsafe_seen > 10 && roomy > 30,
        "the scene must exercise both: unsafe {unsafe_seen}, roomy {roomy}"
    );
    assert!(
        roomy_accepted as f64 >= 0.9 * roomy as f64,
        "only {roomy_accepted} of {roomy} roomy moves accepted"
    );
}

#[test]
fn min_clearance_along_brackets_the_dense_minimum() {
    // The trunk with the robot 150 mm further back than in the paper, so that its base keeps
    // 200 mm from the trunk and the arm is what comes closest.
    let back = Placement {
        base_mm: [0.0, -1000.0, 0.0],
        yaw_deg: 90.0,
    };
    let model = CollisionModel::new(&Robot::irb1400(), back, trunk(), 10.0, None);
    let mut rng = Rng(0xC1EA_4A4C_E000_0001);
    let tol = 0.5;
    let (mut near, mut links) = (0, std::collections::BTreeSet::new());
    for (from, to) in random_free_moves(&mut rng, &model, 40, 40.0) {
        let got = model
            .min_clearance_along(&s6(from), &s6(to), tol)
            .expect("the trunk has obstacles");
        let (dmin, _) = dense_min(&model, &from, &to);
        // Certified lower bound of the true minimum, itself <= any sample.
        assert!(
            got.mm <= dmin + 1e-6,
            "{from:?} -> {to:?}: {got:?} > dense {dmin}"
        );
        // Within tol of the true minimum, which is within 0.5 mm (1 mm steps) of the samples.
        assert!(
            got.mm >= dmin - tol - 0.5 - 1e-3,
            "{from:?} -> {to:?}: {got:?} << dense {dmin}"
        );
        // The pair named is a witness: it comes that close itself.
        let Part::Link(name) = &got.part else {
            panic!("no tool here: {got:?}")
        };
        let pair = dense_min_of_pair(&model, &from, &to, name, &got.obstacle);
        assert!(
            pair <= got.mm + tol + 0.5 + 1e-3,
            "{from:?} -> {to:?}: {got:?}, but that pair keeps {pair}"
        );
        links.insert(got.part.clone());
        if dmin < 50.0 {
            near += 1;
        }
    }
    // The moves come near the obstacles, where the bound has work to do, and different links
    // come closest.
    assert!(near >= 10, "only {near} of 40 moves come within 50 mm");
    assert!(links.len() >= 3, "{links:?}");
}

#[test]
fn a_move_through_a_box_is_refused_and_located() {
    let robot = Robot::irb1400();
    let here = Placement {
        base_mm: [0.0; 3],
        yaw_deg: 0.0,
    };
    // A post in front of the zero-pose forearm; swinging axis 1 from -60 to +60 sweeps
    // the forearm through it, while both ends are free.
    let model = CollisionModel::new(
        &robot,
        here,
        vec![bx("post", [600.0, -50.0, 1000.0], [700.0, 50.0, 1400.0])],
        10.0,
        None,
    );
    let (from, to) = ([-60.0, 0.0, 0.0], [60.0, 0.0, 0.0]);
    assert!(model.is_free(&s6(from)) && model.is_free(&s6(to)));
    assert!(!model.move_is_safe(&s6(from), &s6(to)));
    let (t, why) = model.why_move_unsafe(&s6(from), &s6(to)).expect("unsafe");
    assert!(
        t > 0.3 && t < 0.5,
        "the forearm reaches the post before axis 1 = 0: t = {t}"
    );
    assert!(
        matches!(&why, Blocked::Contact { part, obstacle, distance_mm } if *part == link("link_3") && obstacle == "post" && *distance_mm < 10.0),
        "{why:?}"
    );
    let touching = model
        .min_clearance_along(&s6(from), &s6(to), 0.1)
        .expect("a post");
    assert!(touching.mm <= 0.0 + 1e-9, "{touching:?}");
    assert_eq!(
        (&touching.part, touching.obstacle.as_str()),
        (&link("link_3"), "post")
    );
    // Lifting the forearm over the post makes the move safe.
    let (up0, up1) = ([-60.0, 0.0, -40.0], [60.0, 0.0, -40.0]);
    assert!(
        model.move_is_safe(&s6(up0), &s6(up1)),
        "{:?}",
        model.why_move_unsafe(&s6(up0), &s6(up1))
    );
    // An end out of range is reported at its end.
    let bad = [0.0, 0.0, 75.0];
    assert!(!model.move_is_safe(&s6(up0), &s6(bad)));
    assert!(
        matches!(model.why_move_unsafe(&s6(up0), &s6(bad)), Some((t, Blocked::Range(_))) if t == 1.0)
    );
}

#[test]
fn no_obstacles_and_zero_clearance_are_fine() {
    let model = CollisionModel::new(&Robot::irb1400(), TRUNK_PLACEMENT, vec![], 0.0, None);
    assert_eq!(model.clearance_at(&s6([0.0; 3])), f64::INFINITY);
    assert_eq!(
        model.min_clearance_along(&s6([0.0; 3]), &s6([90.0, 30.0, 20.0]), 0.0),
        None
    );
    assert!(model.is_free(&s6([0.0; 3])) && !model.is_free(&s6([0.0, 0.0, -70.0])));
    assert!(model.move_is_safe(&s6([-170.0, -70.0, -65.0]), &s6([170.0, 70.0, 70.0])));
    assert_eq!(
        column_free(&model, 0.0, 0.0, &[-66.0, 0.0, 71.0], 3),
        [false, true, false]
    );
    assert_eq!(
        column_free(&model, 171.0, 0.0, &[0.0, 10.0, 20.0], 3),
        [false; 3]
    );
    assert!(column_free(&model, 0.0, 0.0, &[], 0).is_empty());
}

#[test]
fn the_robot_stands_on_a_floor_but_the_arm_may_not_touch_it() {
    let robot = Robot::irb1400();
    let on_floor = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let floor = bx("floor", [-3000.0, -3000.0, -50.0], [3000.0, 3000.0, 0.0]);
    let m = CollisionModel::new(&robot, on_floor, vec![floor], 10.0, None);
    // The base cylinder rests on the floor: not a contact.
    assert!(m.is_free(&s6([0.0, 0.0, 0.0])));
    assert!(m.move_is_safe(&s6([-90.0, 0.0, 0.0]), &s6([90.0, 0.0, 0.0])));
    // Nearest to the floor: the upper arm's bottom cap, at axis 2's height of 475 mm.
    let d = m
        .min_clearance_along(&s6([-90.0, 0.0, 0.0]), &s6([90.0, 0.0, 0.0]), 0.1)
        .map_or(f64::NAN, |c| c.mm);
    assert!((474.8..=475.0).contains(&d), "{d}");
    // The forearm reaching down to the floor is a contact (wrist centre at z = 44 mm).
    match m.why_blocked(&s6([0.0, 70.0, 70.0])) {
        Some(Blocked::Contact { part, obstacle, .. }) => {
            assert_eq!((part, obstacle.as_str()), (link("link_3"), "floor"))
        }
        other => panic!("expected a contact, got {other:?}"),
    }
    // A box reaching 1 mm above the mounting plane is no floor: the base touches it.
    let mat = bx("mat", [-3000.0, -3000.0, -50.0], [3000.0, 3000.0, 1.0]);
    let m = CollisionModel::new(&robot, on_floor, vec![mat], 10.0, None);
    assert!(
        matches!(m.why_blocked(&s6([0.0, 0.0, 0.0])), Some(Blocked::Contact { ref part, .. }) if *part == link("link_1"))
    );
    // On a 400 mm pedestal the pedestal is what it stands on; the floor below still counts
    // for the arm.
    let raised = Placement {
        base_mm: [0.0, 0.0, 400.0],
        yaw_deg: 0.0,
    };
    let pedestal = bx("pedestal", [-400.0, -400.0, 0.0], [400.0, 400.0, 400.0]);
    let m = CollisionModel::new(&robot, raised, vec![pedestal], 10.0, None);
    assert!(m.is_free(&s6([0.0, 0.0, 0.0])));
}

#[test]
fn a_huge_box_is_measured_as_exactly_as_a_cell_sized_one() {
    // Review finding: a 2 km floor let GJK's rounding overestimate a distance beyond the
    // proofs' slack (0.4861370 against 0.4861155 mm). Boxes are clipped to the workspace.
    let robot = Robot::irb1400();
    let at = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let q = [0.0, 63.0, 68.1];
    let floor = |s: f64| bx("floor", [-s, -s, -1000.0], [s, s, 0.0]);
    let small =
        CollisionModel::new(&robot, at, vec![floor(5000.0)], 0.0, None).clearance_at(&s6(q));
    let huge = CollisionModel::new(&robot, at, vec![floor(1e6)], 0.0, None).clearance_at(&s6(q));
    assert!((small - huge).abs() < 1e-9, "{small} vs {huge}");
    let c = small + 1e-5; // just above the true distance: the pose is not free
    let m = CollisionModel::new(&robot, at, vec![floor(1e6)], c, None);
    assert!(!m.is_free(&s6(q)) && !m.move_is_safe(&s6(q), &s6(q)));
}

#[test]
fn a_box_far_away_blocks_nothing() {
    let robot = Robot::irb1400();
    let at = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let m = CollisionModel::new(
        &robot,
        at,
        vec![bx("far", [1e160; 3], [2e160; 3])],
        10.0,
        None,
    );
    assert!(m.is_free(&s6([0.0, 0.0, 0.0])));
    assert!(m.move_is_safe(&s6([0.0, 0.0, 0.0]), &s6([10.0, 0.0, 0.0])));
    let d = m
        .min_clearance_along(&s6([0.0, 0.0, 0.0]), &s6([10.0, 0.0, 0.0]), 0.1)
        .map_or(f64::NAN, |c| c.mm);
    assert!(d.is_finite() && d > CLIP_MARGIN_MM, "{d}");
}

#[test]
fn a_base_cylinder_below_its_mounting_plane_is_not_exempt() {
    // The same robot with its base cylinder lowered 125 mm into the floor: the floor counts.
    let text = include_str!("../../robots/irb1400.urdf").replace(
        r#"<origin xyz="0 0 0.325" rpy="0 0 0"/>"#,
        r#"<origin xyz="0 0 0.2" rpy="0 0 0"/>"#,
    );
    let robot = crate::robot::urdf::robot_from_urdf(std::path::Path::new("x.urdf"), &text, None)
        .expect("loads");
    let at = Placement {
        base_mm: [0.0, 0.0, 0.0],
        yaw_deg: 0.0,
    };
    let floor = bx("floor", [-3000.0, -3000.0, -50.0], [3000.0, 3000.0, 0.0]);
    let m = CollisionModel::new(&robot, at, vec![floor.clone()], 10.0, None);
    assert!(
        matches!(m.why_blocked(&s6([0.0, 0.0, 0.0])), Some(Blocked::Contact { ref part, .. }) if *part == link("link_1"))
    );
    // The bundled robot stands on the same floor.
    assert!(
        CollisionModel::new(&Robot::irb1400(), at, vec![floor], 10.0, None)
            .is_free(&s6([0.0, 0.0, 0.0]))
    );
}

/// The proof's interval bound grows with both ends (for any reach): a pair passed on lower
/// bounds of the ends' distances (the mount box's enclosing-box gap in `parts_are_safe`) would
/// be passed on the distances themselves.
#[test]
fn the_interval_bound_grows_with_both_ends() {
    let mut rng = crate::geometry::testing::Rng(0x1B0_0D5_6A0);
    for _ in 0..20_000 {
        let (d0, d1) = (rng.range(-50.0, 500.0), rng.range(-50.0, 500.0));
        let (e0, e1) = (d0 + rng.range(0.0, 80.0), d1 + rng.range(0.0, 80.0));
        let reach = rng.range(0.0, 300.0);
        let (lo, hi) = (
            super::proof::interval_bound(d0, d1, reach),
            super::proof::interval_bound(e0, e1, reach),
        );
        assert!(
            lo <= hi,
            "{d0} {d1} -> {e0} {e1}, reach {reach}: {lo} > {hi}"
        );
    }
    assert_eq!(
        super::proof::interval_bound(f64::INFINITY, f64::INFINITY, 10.0),
        f64::INFINITY
    );
}
