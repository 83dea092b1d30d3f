//! Tests of the tool's part of the model: the shapes placed and measured as parry3d measures
//! them, the six-axis Lipschitz bound, the ball about the wrist centre, the move proof with a
//! tool, the messages, and the grid's node codes and steps against dense sampling.

use super::grid::{COLUMN_LEVELS, DEPTH_LEVELS};
use super::proof::lerp;
use super::*;
use crate::cell::{Frame, Loc, ToolGeometry, ToolShape};
use crate::geometry::testing::Rng;
use nalgebra::{Point3, UnitQuaternion};
use parry3d::math::{Pose, Rotation, Vector};

fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
    Obstacle::new(name, Aabb::new(Point3::from(min), Point3::from(max)))
}

pub(super) fn shape(name: &str, geometry: ToolGeometry) -> ToolShape {
    ToolShape {
        name: name.into(),
        geometry,
        loc: Loc::default(),
    }
}

/// A bent welding torch on the flange (tool0 frame, mm): a neck along z, a box body at the
/// flange, a cup off to the side at the tip. (Shared with the plan's tests.)
pub(crate) fn torch() -> Tool {
    Tool {
        name: "tTorch".into(),
        tframe: Frame::IDENTITY,
        mass_kg: 2.5,
        cog_mm: [0.0, 0.0, 120.0],
        shapes: vec![
            shape(
                "neck",
                ToolGeometry::Cylinder {
                    from_mm: [0.0, 0.0, 0.0],
                    to_mm: [0.0, 0.0, 300.0],
                    radius_mm: 25.0,
                },
            ),
            shape(
                "body",
                ToolGeometry::Box {
                    min_mm: [-45.0, -45.0, 0.0],
                    max_mm: [45.0, 45.0, 110.0],
                },
            ),
            shape(
                "cup",
                ToolGeometry::Sphere {
                    centre_mm: [120.0, 0.0, 320.0],
                    radius_mm: 15.0,
                },
            ),
        ],
        loc: Loc::default(),
    }
}

const ORIGIN: Placement = Placement {
    base_mm: [0.0, 0.0, 0.0],
    yaw_deg: 0.0,
};

pub(super) const TRUNK_PLACEMENT: Placement = Placement {
    base_mm: [0.0, -850.0, 0.0],
    yaw_deg: 90.0,
};

pub(super) fn trunk() -> Vec<Obstacle> {
    vec![
        bx("floor", [-900.0, -450.0, 0.0], [900.0, 450.0, 100.0]),
        bx("near wall", [-900.0, -450.0, 0.0], [900.0, -430.0, 500.0]),
        bx("far wall", [-900.0, 430.0, 0.0], [900.0, 450.0, 500.0]),
        bx("tower", [-150.0, 0.0, 0.0], [150.0, 300.0, 1000.0]),
        bx("rail", [-600.0, -300.0, 700.0], [600.0, -250.0, 760.0]),
    ]
}

pub(super) fn torch_model(clearance: f64) -> CollisionModel {
    let tool = torch();
    CollisionModel::new(
        &Robot::irb1400(),
        TRUNK_PLACEMENT,
        trunk(),
        clearance,
        Some(&tool),
    )
}

pub(super) fn random_six(rng: &mut Rng, robot: &Robot) -> [f64; 6] {
    loop {
        let a = [
            rng.range(-170.0, 170.0),
            rng.range(-70.0, 70.0),
            rng.range(-65.0, 70.0),
            rng.range(-150.0, 150.0),
            rng.range(-115.0, 115.0),
            rng.range(-300.0, 300.0),
        ];
        if robot.check_range6(&a).is_ok() {
            return a;
        }
    }
}

/// The tool's shapes placed independently of the model: the robot's own tool0 pose, then
/// parry3d's shapes, each with its pose in the cell frame.
pub(super) fn parry_tool(
    robot: &Robot,
    placement: Placement,
    tool: &Tool,
    axes: &[f64; 6],
) -> Vec<(String, Pose, Box<dyn parry3d::shape::Shape>)> {
    let flange = placement.cell_from_robot() * robot.tool0(axes);
    let pose_of = |iso: nalgebra::Isometry3<f64>| {
        let t = iso.translation.vector;
        let q = iso.rotation.quaternion();
        Pose::from_parts(
            Vector::new(t.x, t.y, t.z),
            Rotation::from_xyzw(q.i, q.j, q.k, q.w),
        )
    };
    tool.shapes
        .iter()
        .map(|s| {
            let (iso, shape): (nalgebra::Isometry3<f64>, Box<dyn parry3d::shape::Shape>) =
                match s.geometry {
                    ToolGeometry::Cylinder {
                        from_mm,
                        to_mm,
                        radius_mm,
                    } => {
                        let (a, b) = (Point3::from(from_mm), Point3::from(to_mm));
                        let axis = b - a;
                        let rot = UnitQuaternion::rotation_between(&Vector3::y(), &axis)
                            .unwrap_or_else(|| {
                                UnitQuaternion::from_axis_angle(
                                    &Vector3::x_axis(),
                                    std::f64::consts::PI,
                                )
                            });
                        let mid = nalgebra::center(&a, &b);
                        (
                            flange * nalgebra::Isometry3::from_parts(mid.coords.into(), rot),
                            Box::new(parry3d::shape::Cylinder::new(axis.norm() / 2.0, radius_mm)),
                        )
                    }
                    ToolGeometry::Box { min_mm, max_mm } => {
                        let c = Vector3::from_fn(|k, _| (min_mm[k] + max_mm[k]) / 2.0);
                        let h = Vector3::from_fn(|k, _| (max_mm[k] - min_mm[k]) / 2.0);
                        (
                            flange * nalgebra::Isometry3::from_parts(c.into(), Default::default()),
                            Box::new(parry3d::shape::Cuboid::new(Vector::new(h.x, h.y, h.z))),
                        )
                    }
                    ToolGeometry::Sphere {
                        centre_mm,
                        radius_mm,
                    } => (
                        flange
                            * nalgebra::Isometry3::from_parts(
                                Vector3::from(centre_mm).into(),
                                Default::default(),
                            ),
                        Box::new(parry3d::shape::Ball::new(radius_mm)),
                    ),
                };
            (s.name.clone(), pose_of(iso), shape)
        })
        .collect()
}

pub(super) fn parry_box(b: &Aabb) -> (Pose, parry3d::shape::Cuboid) {
    let c = nalgebra::center(&b.min, &b.max);
    let h = (b.max - b.min) * 0.5;
    (
        Pose::from_translation(Vector::new(c.x, c.y, c.z)),
        parry3d::shape::Cuboid::new(Vector::new(h.x, h.y, h.z)),
    )
}

/// The smallest parry distance of any tool shape to any box at `axes`, and the shape's name.
pub(super) fn parry_tool_min(
    model: &CollisionModel,
    tool: &Tool,
    axes: &[f64; 6],
) -> (f64, String) {
    let mut best = (f64::INFINITY, String::new());
    for (name, pose, shape) in parry_tool(model.robot(), model.placement(), tool, axes) {
        for o in model.obstacles() {
            let (bp, cub) = parry_box(&o.aabb);
            let d = parry3d::query::distance(&pose, shape.as_ref(), &bp, &cub)
                .expect("convex shapes")
                .distance;
            if d < best.0 {
                best = (d, name.clone());
            }
        }
    }
    best
}

/// The smallest distance of the model's link cylinders to the boxes (the link test of
/// `tests.rs` holds these against parry).
fn links_min(model: &CollisionModel, axes: &[f64; 6]) -> f64 {
    let arm = CollisionModel::new(
        model.robot(),
        model.placement(),
        model.obstacles().to_vec(),
        model.clearance_mm(),
        None,
    );
    arm.clearance_at(axes)
}

#[test]
fn tool_shapes_are_placed_and_measured_as_parry_measures_them() {
    let tool = torch();
    let model = torch_model(10.0);
    let mut rng = Rng(0x7001_5AFE_0000_0001);
    let (mut near, mut far) = (0, 0);
    for _ in 0..1500 {
        let axes = random_six(&mut rng, model.robot());
        let (want, _) = parry_tool_min(&model, &tool, &axes);
        let mine = model
            .solids(&axes)
            .into_iter()
            .filter(|(p, _)| matches!(p, Part::ToolShape(_)))
            .flat_map(|(_, s)| {
                model
                    .obstacles()
                    .iter()
                    .map(move |o| s.distance_aabb(&o.aabb))
            })
            .fold(f64::INFINITY, f64::min);
        assert!(
            (mine - want).abs() <= 1e-6 * (1.0 + want),
            "{axes:?}: model {mine}, parry {want}"
        );
        // The whole pose: links and tool.
        let all = model.clearance_at(&axes);
        assert!((all - want.min(links_min(&model, &axes))).abs() <= 1e-6 * (1.0 + all));
        if want < 50.0 {
            near += 1;
        } else {
            far += 1;
        }
    }
    assert!(near > 100 && far > 100, "{near} near, {far} far");
}

#[test]
fn the_six_axis_bound_holds_for_tool_shapes_and_is_not_loose() {
    let tool = torch();
    let model = torch_model(10.0);
    let robot = model.robot().clone();
    let nc = robot.cylinders.len();
    let mut rng = Rng(0x5EED_7001_0000_0002);
    let mut worst: f64 = 0.0;
    for round in 0..2000 {
        let q = random_six(&mut rng, &robot);
        // Small and large moves, sometimes only the wrist.
        let span = if round % 2 == 0 { 3.0 } else { 30.0 };
        let d: [f64; 6] = std::array::from_fn(|k| {
            if round % 5 == 0 && k < 3 {
                0.0
            } else {
                rng.range(-span, span)
            }
        });
        let q2: [f64; 6] = std::array::from_fn(|k| q[k] + d[k]);
        let bound = model.part_speeds(&q, &q2);
        // Points of each shape (tool0 frame): ends, rims, corners, poles; at samples along the
        // move, each sample's displacement from the start.
        for (s, sh) in tool.shapes.iter().enumerate() {
            let pts: Vec<Point3<f64>> = match sh.geometry {
                ToolGeometry::Cylinder {
                    from_mm,
                    to_mm,
                    radius_mm,
                } => {
                    let mut v = Vec::new();
                    for e in [from_mm, to_mm] {
                        for (x, y) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
                            v.push(Point3::new(
                                e[0] + x * radius_mm,
                                e[1] + y * radius_mm,
                                e[2],
                            ));
                        }
                    }
                    v
                }
                ToolGeometry::Box { min_mm, max_mm } => (0..8)
                    .map(|k| {
                        Point3::new(
                            if k & 1 == 1 { max_mm[0] } else { min_mm[0] },
                            if k & 2 == 2 { max_mm[1] } else { min_mm[1] },
                            if k & 4 == 4 { max_mm[2] } else { min_mm[2] },
                        )
                    })
                    .collect(),
                ToolGeometry::Sphere {
                    centre_mm,
                    radius_mm,
                } => [
                    Vector3::x(),
                    -Vector3::x(),
                    Vector3::y(),
                    Vector3::z(),
                    -Vector3::z(),
                ]
                .iter()
                .map(|u| Point3::from(centre_mm) + u * radius_mm)
                .collect(),
            };
            let start = robot.tool0(&q);
            for i in 1..=4 {
                let t = i as f64 / 4.0;
                let here = robot.tool0(&lerp(&q, &q2, t));
                for p in &pts {
                    let moved = (here * p - start * p).norm();
                    let b = bound[nc + s] * t;
                    assert!(
                        moved <= b * (1.0 + 1e-9) + 1e-9,
                        "{} at {q:?} + {d:?}, t {t}: moved {moved} > bound {b}",
                        sh.name
                    );
                    if i == 4 && b > 1e-6 {
                        worst = worst.max(moved / b);
                    }
                }
            }
        }
    }
    assert!(worst > 0.4, "largest displacement / bound = {worst}");
}

#[test]
fn the_tool_ball_about_the_wrist_centre_holds_every_shape() {
    let tool = torch();
    let model = torch_model(10.0);
    let robot = model.robot();
    let r = model.tool_radius_mm().expect("a tool");
    // IRB 1400: a spherical wrist, so the centre is the wrist centre, and the flange lies
    // 85 mm out along axis 6. The farthest point is the cup's far side: its centre 85 + 320 mm
    // along the flange axis and 120 mm off it, plus its 15 mm radius (the neck's rim reaches
    // sqrt(385^2 + 25^2) = 385.8 mm, the body's corners 205 mm).
    let want = 405.0f64.hypot(120.0) + 15.0;
    assert!((r - want).abs() < 1e-9, "{r} against {want}");
    let mut rng = Rng(31);
    let mut closest_to_rim: f64 = f64::INFINITY;
    for _ in 0..3000 {
        let axes = random_six(&mut rng, robot);
        let wc = model.placement().cell_from_robot() * robot.wrist_centre(&axes);
        for (_, pose, shape) in parry_tool(robot, model.placement(), &tool, &axes) {
            // The farthest point of the shape from the wrist centre, by parry's support map.
            let c = wc.coords;
            let local = pose.inverse() * Vector::new(c.x, c.y, c.z);
            for dir in [
                Vector::X,
                -Vector::X,
                Vector::Y,
                -Vector::Y,
                Vector::Z,
                -Vector::Z,
            ] {
                let far = shape
                    .as_support_map()
                    .expect("convex")
                    .local_support_point(dir);
                let d = (far - local).length();
                assert!(d <= r + 1e-9, "{axes:?}: {d} > {r}");
                closest_to_rim = closest_to_rim.min(r - d);
            }
        }
    }
    assert!(
        closest_to_rim < 20.0,
        "the radius is loose by {closest_to_rim}"
    );
}

#[test]
fn a_move_sweeping_the_torch_through_a_box_is_refused_and_one_clearing_it_is_accepted() {
    let tool = torch();
    let robot = Robot::irb1400();
    // Zero pose: the flange at (955, 0, 1195) facing +x; the neck reaches to x = 1255. A post
    // in the torch's sweep about axis 1, 150 mm beyond the forearm's end.
    let post = bx("post", [1150.0, -20.0, 1100.0], [1250.0, 20.0, 1300.0]);
    let arm = CollisionModel::new(&robot, ORIGIN, vec![post.clone()], 10.0, None);
    let with = CollisionModel::new(&robot, ORIGIN, vec![post], 10.0, Some(&tool));
    let (from, to) = (
        [-30.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [30.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    );
    assert!(with.is_free(&from) && with.is_free(&to));
    assert!(arm.move_is_safe(&from, &to), "the arm alone keeps clear");
    assert!(
        !with.move_is_safe(&from, &to),
        "the torch sweeps through the post"
    );
    let (t, why) = with.why_move_unsafe(&from, &to).expect("unsafe");
    assert!(t > 0.3 && t < 0.55, "{t}");
    assert!(
        matches!(&why, Blocked::Contact { part: Part::ToolShape(n), obstacle, .. } if n == "neck" && obstacle == "post"),
        "{why:?}"
    );
    let least = with.min_clearance_along(&from, &to, 0.1).expect("a post");
    assert_eq!(least.part, Part::ToolShape("neck".into()));
    assert!(least.mm <= 1e-9, "{least:?}");
    // Turning the wrist up (axis 5 to -60) on the way lifts the torch over the post: accepted,
    // and the dense check agrees.
    let (up0, up1) = (
        [-30.0, 0.0, 0.0, 0.0, -60.0, 0.0],
        [30.0, 0.0, 0.0, 0.0, -60.0, 0.0],
    );
    assert!(
        with.move_is_safe(&up0, &up1),
        "{:?}",
        with.why_move_unsafe(&up0, &up1)
    );
    // Turning the wrist during the move: only the wrist moves, from up to down in front of
    // the post (axis 1 at 0): the torch swings into it.
    let (a, b) = (
        [0.0, 0.0, 0.0, 0.0, -60.0, 0.0],
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    );
    assert!(!with.is_free(&b) && !with.move_is_safe(&a, &b));
    assert!(arm.move_is_safe(&a, &b));
}

#[test]
fn accepted_tool_moves_keep_the_clearance_at_dense_samples() {
    let tool = torch();
    let model = torch_model(10.0);
    let mut rng = Rng(0xD3_05E0_7001);
    let (mut accepted, mut refused, mut tool_closest) = (0, 0, 0);
    let mut tried = 0;
    while accepted + refused < 120 {
        tried += 1;
        assert!(tried < 200_000, "could not find enough moves");
        let from = random_six(&mut rng, model.robot());
        let d: [f64; 6] =
            std::array::from_fn(|k| rng.range(-20.0, 20.0) * if k < 3 { 1.0 } else { 3.0 });
        let to: [f64; 6] = std::array::from_fn(|k| from[k] + d[k]);
        if !model.is_free(&from) || !model.is_free(&to) {
            continue;
        }
        // Keep moves whose tool comes near a box.
        if parry_tool_min(&model, &tool, &from).0 > 120.0 {
            continue;
        }
        let safe = model.move_is_safe(&from, &to);
        let m = model
            .part_speeds(&from, &to)
            .into_iter()
            .fold(0.0, f64::max);
        let n = m.ceil().max(1.0) as usize;
        let mut least = f64::INFINITY;
        let mut tool_least = f64::INFINITY;
        for s in 0..=n {
            let axes = lerp(&from, &to, s as f64 / n as f64);
            let (t, _) = parry_tool_min(&model, &tool, &axes);
            tool_least = tool_least.min(t);
            least = least.min(t).min(links_min(&model, &axes));
        }
        if safe {
            accepted += 1;
            assert!(least >= 10.0 - 1e-6, "{from:?} -> {to:?}: dense {least}");
            if tool_least <= least + 1e-9 {
                tool_closest += 1;
            }
        } else {
            refused += 1;
        }
        if least < 10.0 {
            assert!(!safe);
        }
    }
    assert!(
        accepted > 30 && refused > 10,
        "{accepted} accepted, {refused} refused"
    );
    assert!(
        tool_closest > 10,
        "the tool came closest in only {tool_closest} moves"
    );
}

#[test]
fn messages_name_the_tool_shape_and_links_keep_their_words() {
    let contact = |part: Part, d: f64| {
        Blocked::Contact {
            part,
            obstacle: "roof_rail".into(),
            distance_mm: d,
        }
        .to_string()
    };
    assert_eq!(
        contact(Part::ToolShape("neck".into()), 4.2),
        "tool shape 'neck' comes within 4.2 mm of obstacle 'roof_rail', less than the required \
         clearance"
    );
    assert_eq!(
        contact(Part::ToolShape("cup".into()), 0.0),
        "tool shape 'cup' hits obstacle 'roof_rail'"
    );
    assert_eq!(
        contact(Part::Link("link_3".into()), 4.2),
        "link 'link_3' of the robot comes within 4.20 mm of obstacle 'roof_rail', less than the \
         required clearance"
    );
    assert_eq!(
        contact(Part::Link("link_3".into()), 0.0),
        "link 'link_3' of the robot hits obstacle 'roof_rail'"
    );
    // The place stage's question names the shape too.
    let tool = torch();
    let post = bx("post", [1150.0, -20.0, 1100.0], [1250.0, 20.0, 1300.0]);
    let m = CollisionModel::new(&Robot::irb1400(), ORIGIN, vec![post], 10.0, Some(&tool));
    let why = PoseCheck::why_blocked(&m, &[0.0; 6]).expect("the neck is in the post");
    assert!(
        why.contains("tool shape 'neck'") && why.contains("'post'"),
        "{why}"
    );
    // Axes 4..6 out of range: a range error, before any contact.
    let why = PoseCheck::why_blocked(&m, &[0.0, 0.0, 0.0, 0.0, 160.0, 0.0]).expect("range");
    assert!(why.contains("axis 5"), "{why}");
    // A tool without shapes is no tool volume.
    let bare = Tool {
        shapes: Vec::new(),
        ..torch()
    };
    let m = CollisionModel::new(&Robot::irb1400(), ORIGIN, vec![], 10.0, Some(&bare));
    assert!(!m.has_tool() && m.tool_radius_mm().is_none());
}

/// The grid's node codes, checked node by node against exact distances: the free bit is the
/// arm's node test; every depth is a true lower bound; a node without the near bit has its tool
/// clear for any wrist.
#[test]
fn node_codes_are_lower_bounds_of_the_true_distances() {
    let model = torch_model(10.0);
    let robot = model.robot().clone();
    let check = model.grid_check(1.0);
    let a3: Vec<f64> = (-65..=70).map(f64::from).collect();
    let mut codes = vec![0u8; a3.len()];
    let mut column = vec![0u8; check.column_bytes()];
    let mut rng = Rng(0x000C_0DE5);
    let (mut shallow, mut near, mut far) = (0, 0, 0);
    let k = f64::from(DEPTH_LEVELS);
    for _ in 0..120 {
        let (a1, a2) = (
            rng.range(-170.0, 170.0).round(),
            rng.range(-70.0, 70.0).round(),
        );
        check.inspect_column(a1, a2, &a3, &mut codes, &mut column);
        for (&v, &code) in a3.iter().zip(&codes) {
            let axes = [a1, a2, v];
            assert_eq!(code & CODE_FREE != 0, model.arm_is_free(&axes), "{axes:?}");
            if code == 0 {
                continue;
            }
            let six = [a1, a2, v, 0.0, 0.0, 0.0];
            let solids = model.solids(&six);
            let dist = |i: usize| {
                model
                    .part_boxes(i)
                    .map(|(_, b)| solids[i].1.distance_aabb(b))
                    .fold(f64::INFINITY, f64::min)
            };
            let c = model.clearance_mm();
            for (i, cd) in model.cyl.iter().enumerate() {
                let (q, span, levels) = match check.fixed.iter().position(|&f| f == i) {
                    Some(l) => (column[l], check.fixed_span[l], f64::from(COLUMN_LEVELS)),
                    None => (code & 7, check.arm_span, k),
                };
                let need = c + f64::from(q) * span / levels;
                assert!(
                    dist(i) >= need - 1e-6,
                    "{axes:?} link {} (joint {}): {} < {need}",
                    robot.cylinders[i].link,
                    cd.joint,
                    dist(i)
                );
                if q < levels as u8 {
                    shallow += 1;
                }
            }
            // The tool: its depth bounds every wrist; without the near bit it is clear.
            let q_t = f64::from((code >> 3) & 7);
            for _ in 0..3 {
                let w = [
                    rng.range(-150.0, 150.0),
                    rng.range(-115.0, 115.0),
                    rng.range(-300.0, 300.0),
                ];
                let six = [a1, a2, v, w[0], w[1], w[2]];
                let solids = model.solids(&six);
                let tool_d = (robot.cylinders.len()..solids.len())
                    .flat_map(|p| {
                        let s = solids[p].1;
                        model
                            .obstacles()
                            .iter()
                            .map(move |o| s.distance_aabb(&o.aabb))
                    })
                    .fold(f64::INFINITY, f64::min);
                if GridCheck::tool_near(code) {
                    near += 1;
                } else {
                    far += 1;
                    assert!(tool_d > c && model.tool_is_free(&six), "{six:?}");
                    assert!(tool_d >= c + q_t * check.centre_span / k - 1e-6, "{six:?}");
                }
            }
        }
    }
    assert!(
        shallow > 500 && near > 300 && far > 300,
        "{shallow} {near} {far}"
    );
}

/// Steps the codes prove are safe by the dense check (links and tool, any wrists between two
/// random ones), and the codes do prove most steps far from the boxes.
#[test]
fn steps_proven_by_the_codes_keep_the_clearance() {
    let tool = torch();
    let model = torch_model(10.0);
    let check = model.grid_check(1.0);
    let mut rng = Rng(0x57E9_5AFE);
    let (mut proven, mut tried, mut near_proven) = (0, 0, 0);
    let column_of = |a1: f64, a2: f64, a3: f64| {
        let mut code = [0u8; 1];
        let mut column = vec![0u8; check.column_bytes()];
        check.inspect_column(a1, a2, &[a3], &mut code, &mut column);
        (code[0], column)
    };
    while tried < 3000 {
        let n = [
            rng.range(-170.0, 169.0).round(),
            rng.range(-69.0, 69.0).round(),
            rng.range(-64.0, 69.0).round(),
        ];
        let o = [0, 1, 2].map(|_| rng.below(3) as i32 - 1);
        if o == [0, 0, 0] {
            continue;
        }
        let m = [0, 1, 2].map(|k| n[k] + f64::from(o[k]));
        let (ca, cola) = column_of(n[0], n[1], n[2]);
        let (cb, colb) = column_of(m[0], m[1], m[2]);
        if ca == 0 || cb == 0 {
            continue;
        }
        tried += 1;
        let ends = |code, column: &[u8]| -> (u8, Vec<u8>) { (code, column.to_vec()) };
        let (ea, eb) = (ends(ca, &cola), ends(cb, &colb));
        let (arm, tool_ok) = check.proven_by_codes(
            Ends {
                code: ea.0,
                column: &ea.1,
            },
            Ends {
                code: eb.0,
                column: &eb.1,
            },
            o,
        );
        if !(arm && tool_ok) {
            continue;
        }
        proven += 1;
        let w0 = [
            rng.range(-150.0, 150.0),
            rng.range(-115.0, 115.0),
            rng.range(-300.0, 300.0),
        ];
        let w1 = [0, 1, 2].map(|k| w0[k] + rng.range(-40.0, 40.0));
        let a = [n[0], n[1], n[2], w0[0], w0[1], w0[2]];
        let b = [m[0], m[1], m[2], w1[0], w1[1], w1[2]];
        let steps = model.part_speeds(&a, &b).into_iter().fold(0.0, f64::max);
        let samples = steps.ceil().max(1.0) as usize;
        let mut least = f64::INFINITY;
        for s in 0..=samples {
            let axes = lerp(&a, &b, s as f64 / samples as f64);
            least = least
                .min(parry_tool_min(&model, &tool, &axes).0)
                .min(links_min(&model, &axes));
        }
        assert!(least >= 10.0 - 1e-6, "{a:?} -> {b:?}: {least}");
        if least < 60.0 {
            near_proven += 1;
        }
    }
    assert!(
        proven > 1000 && near_proven > 20,
        "{proven} proven, {near_proven} near"
    );
}

/// The tool's node test (shape balls first, then each shape's enclosing box and the exact test)
/// against parry's smallest tool distance, at random poses and at clearances drawn around that
/// distance: whenever parry is sure (beyond 1e-6 mm), the answers agree. Both answers occur.
#[test]
fn tool_is_free_agrees_with_parry_at_random_poses() {
    let tool = torch();
    let mut rng = Rng(0x7001_5AFE_0000_0B17);
    let (mut clear, mut blocked) = (0, 0);
    for k in 0..1200 {
        let clearance = [5.0, 40.0, 150.0][k % 3];
        let model = torch_model(clearance);
        let axes = random_six(&mut rng, model.robot());
        let (want, _) = parry_tool_min(&model, &tool, &axes);
        if (want - clearance).abs() <= 1e-6 * (1.0 + want) {
            continue;
        }
        let got = model.tool_is_free(&axes);
        assert_eq!(
            got,
            want > clearance,
            "{axes:?} at {clearance}: parry {want}"
        );
        if got {
            clear += 1;
        } else {
            blocked += 1;
        }
    }
    assert!(
        clear > 100 && blocked > 100,
        "{clear} clear, {blocked} blocked"
    );
}
