//! Tests of the preview's scene: keyframes, the clearance's place, the shapes each link and
//! tool part is drawn with. The scene of a real (small) run: the bundled IRB 1400 with a tool,
//! a table and a post.

use super::*;
use crate::pipeline::{self, Loaded, Options};
use crate::plan::Method;
use std::path::Path;

const CELL: &str = "\
module: Demo
robot: { urdf: irb1400.urdf, base: [0, 0, 0] }
tool:
  name: tStick
  tframe: [[0, 0, 200], [1, 0, 0, 0]]
  shapes:
    - { name: stick, cylinder: { from: [0, 0, 0], to: [0, 0, 150], radius: 20 } }
    - { name: knob, sphere: { centre: [0, 0, 160], radius: 15 } }
    - { name: plate, box: { min: [-40, -40, 0], max: [40, 40, 10] } }
obstacles:
  - { name: table, box: { min: [600, -300, 0], max: [1000, 300, 400] } }
  - { name: post, box: { min: [700, -60, 400], max: [820, 60, 1300] } }
points:
  - { name: P1, joints: [-40, 10, 0, 0, 30, 0] }
  - { name: P2, joints: [40, 10, 0, 0, 60, 0] }
planner: { grid: 5 }
";

/// The scene of a run's outcome.
fn scene_of(job: &Loaded, out: &pipeline::Outcome) -> Scene {
    scene(
        &job.cell,
        &job.robot,
        &out.placed,
        &out.plan,
        &out.rendered.names,
        &out.rendered.moves,
    )
}

fn job() -> Loaded {
    let cell = crate::cell::parse(Path::new("demo.yaml"), CELL).expect("the cell");
    Loaded {
        cell,
        text: CELL.to_string(),
        robot: Robot::irb1400(),
    }
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() <= tol)
}

#[test]
fn keyframes_follow_the_estimate_and_the_kinematics() {
    let job = job();
    let out = pipeline::run(&job, &Options::new(Method::Extensile, 5.0)).expect("plans");
    let plan = &out.plan;
    let route = &plan.route;
    assert!(route.moves() >= 2, "the post makes a via");
    let s = scene(
        &job.cell,
        &job.robot,
        &out.placed,
        plan,
        &out.rendered.names,
        &out.rendered.moves,
    );
    // Links 1..3, then the tool's three shapes; one pose each per keyframe.
    let kinds: Vec<_> = s.shapes.iter().map(|d| d.kind).collect();
    assert_eq!(
        kinds,
        [ShapeKind::Link; 3]
            .into_iter()
            .chain([ShapeKind::Tool; 3])
            .collect::<Vec<_>>()
    );
    assert!(s.keyframes.iter().all(|k| k.poses.len() == 6));
    // Time runs from 0 to the estimate, never backwards.
    assert_eq!(s.keyframes[0].time_s, 0.0);
    let last = s.keyframes.last().expect("keyframes");
    assert!((last.time_s - plan.total_s).abs() < 1e-9);
    assert!(s.keyframes.windows(2).all(|w| w[0].time_s <= w[1].time_s));
    // Each waypoint is reached when its moves' times add up, where forward kinematics puts
    // its TCP (the tool's 200 mm beyond the flange), with the module's names.
    let poser = Poser::new(&job.robot, out.placed.placement, job.cell.tool.as_ref());
    let mut t = 0.0;
    for (k, w) in s.waypoints.iter().enumerate() {
        if k > 0 {
            t += plan.moves[k - 1].estimate.time_s;
        }
        assert!((w.time_s - t).abs() < 1e-9);
        assert_eq!(w.name, out.rendered.names[k]);
        let tcp = poser.tcp_mm(&route.waypoints[k].joints_deg);
        assert_eq!(w.tcp_mm, tcp);
        let flange = poser
            .tool0(&route.waypoints[k].joints_deg)
            .translation
            .vector;
        let reach = (0..3)
            .map(|a| (tcp[a] - flange[a]).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!((reach - 200.0).abs() < 1e-9);
        let at = s.keyframes.iter().find(|f| (f.time_s - t).abs() < 1e-9);
        assert_eq!(at.map(|f| f.tcp_mm), Some(tcp), "a keyframe at {}", w.name);
    }
    assert_eq!(s.waypoints[0].kind, WaypointKind::Cell);
    assert_eq!(s.waypoints[1].kind, WaypointKind::Via);
    // Halfway through the first move in time the robot is where the move's profile says:
    // the straight joint move at the profile's progress (0.5 by symmetry).
    let half = plan.moves[0].estimate.time_s / 2.0;
    let mid = lerp6(
        &route.waypoints[0].joints_deg,
        &route.waypoints[1].joints_deg,
        0.5,
    );
    let kf = s
        .keyframes
        .iter()
        .min_by(|a, b| (a.time_s - half).abs().total_cmp(&(b.time_s - half).abs()))
        .expect("keyframes");
    assert!((kf.time_s - half).abs() < KEYFRAME_STEP_S);
    if (kf.time_s - half).abs() < 1e-9 {
        assert!(close(kf.tcp_mm, poser.tcp_mm(&mid), 1e-6));
    }
    // Keyframes are dense: halfway between two, the page's straight interpolation of the
    // TCP is within a millimetre of the kinematics at that time (about 0.5 mm here).
    let mut worst: f64 = 0.0;
    let mut t0 = 0.0;
    for (i, m) in plan.moves.iter().enumerate() {
        let (duration, profile) = (m.estimate.time_s, m.estimate.profile);
        let (from, to) = (
            &route.waypoints[i].joints_deg,
            &route.waypoints[i + 1].joints_deg,
        );
        let within = |t: f64| t >= t0 - 1e-9 && t <= t0 + duration + 1e-9;
        for w in s.keyframes.windows(2) {
            if w[0].time_s == w[1].time_s || !within(w[0].time_s) || !within(w[1].time_s) {
                continue;
            }
            let tm = 0.5 * (w[0].time_s + w[1].time_s);
            let truth = poser.tcp_mm(&lerp6(from, to, profile.progress(tm - t0, duration)));
            let shown: [f64; 3] = std::array::from_fn(|a| 0.5 * (w[0].tcp_mm[a] + w[1].tcp_mm[a]));
            let off = (0..3)
                .map(|a| (truth[a] - shown[a]).powi(2))
                .sum::<f64>()
                .sqrt();
            worst = worst.max(off);
        }
        t0 += duration;
    }
    eprintln!("the page's TCP is at most {worst:.3} mm off between keyframes");
    assert!(
        worst < 1.0,
        "the page's TCP is {worst:.3} mm off between keyframes"
    );
}

/// A shipped robot with cylinders on every link: the page draws each where its own link is
/// (base_link at the base, links 4..6 by the six-axis kinematics), the URDF's cylinders, not
/// the enclosures the checks carry them by. Fails with links 4..6 left out or drawn on link 3.
#[test]
fn every_link_of_a_shipped_robot_is_drawn_on_its_own_link() {
    let text = CELL.replace("urdf: irb1400.urdf,", "model: irb2600_12_165,");
    let cell = crate::cell::parse(Path::new("demo.yaml"), &text).expect("the cell");
    let job = Loaded {
        cell,
        text,
        robot: Robot::shipped("irb2600_12_165").expect("shipped"),
    };
    let out = pipeline::run(&job, &Options::new(Method::Extensile, 5.0)).expect("plans");
    let s = scene_of(&job, &out);
    let links: Vec<String> = s.shapes.iter().take(7).map(|d| d.name.clone()).collect();
    let want: Vec<String> = (0..7).map(|k| format!("link_{k}")).collect();
    assert_eq!(links[1..], want[1..]);
    assert_eq!(links[0], "base_link");
    assert!(s.shapes[..7].iter().all(|d| d.kind == ShapeKind::Link));
    let poser = Poser::new(&job.robot, out.placed.placement, job.cell.tool.as_ref());
    let at = &out.plan.route.waypoints[1].joints_deg;
    let frame = s
        .keyframes
        .iter()
        .find(|k| (k.time_s - s.waypoints[1].time_s).abs() < 1e-9)
        .expect("a keyframe at the second waypoint");
    let links = poser.links(at);
    for (i, own) in job.robot.collision.iter().enumerate() {
        let want = match own.frame {
            crate::robot::LinkFrame::Base => poser.base(),
            crate::robot::LinkFrame::Child(k) => links[k],
        };
        let got = frame.poses[i].position_mm;
        let t = want.translation.vector;
        assert!(
            close(got, [t.x, t.y, t.z], 1e-6),
            "{}: {got:?} vs {t:?}",
            own.link
        );
    }
}

#[test]
fn the_smallest_clearance_is_marked_where_it_occurs() {
    let job = job();
    let out = pipeline::run(&job, &Options::new(Method::Extensile, 5.0)).expect("plans");
    let s = scene_of(&job, &out);
    let least = out.plan.least.as_ref().expect("obstacles");
    let c = s.clearance.expect("marked");
    assert_eq!(c.shape, crate::output::clearance_part(least).1);
    assert_eq!(c.obstacle, least.obstacle);
    assert_eq!(out.plan.moves[c.move_index].clearance.as_ref(), Some(least));
    assert_eq!(
        c.distance_mm,
        crate::precision::round(least.mm, crate::precision::LENGTH_DECIMALS)
    );
    // The marker's two points are that far apart (the certified figure is a lower bound
    // within 0.05 mm; the sampled marker lies at most a few tenths of a millimetre above
    // the true minimum), the second on the obstacle's box.
    let [p, q] = c.points_mm.expect("points");
    let d = (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>().sqrt();
    assert!(
        d >= least.mm - 0.01 && d < least.mm + 1.0,
        "{d} against {}",
        least.mm
    );
    let o = job
        .cell
        .obstacles
        .iter()
        .find(|o| o.name == c.obstacle)
        .expect("the obstacle");
    assert!((0..3).all(|k| q[k] >= o.aabb.min[k] - 1e-6 && q[k] <= o.aabb.max[k] + 1e-6));
    // It happens during its move.
    let t = c.time_s.expect("a time");
    let (w0, w1) = (&s.waypoints[c.move_index], &s.waypoints[c.move_index + 1]);
    assert!(t >= w0.time_s - 1e-9 && t <= w1.time_s + 1e-9);
}

/// With a fly-by zone the least may be a zoned corner's, which no move has: the page still
/// marks it, on the half moves through that corner's waypoint, and names the waypoint.
#[test]
fn a_zoned_corners_clearance_is_marked_at_its_waypoint() {
    let job = job();
    let out = pipeline::run(&job, &Options::new(Method::Extensile, 5.0)).expect("plans");
    let mut plan = out.plan.clone();
    assert!(plan.route.moves() >= 2, "the post makes a via");
    let least = plan.least.clone().expect("obstacles");
    // As `refine::zones::fold_corners` leaves it: the via flown by, its corner 0.3 mm closer
    // than any move (the same part and obstacle).
    plan.moves[0].motion.zone = "z50".into();
    plan.least = Some(crate::plan::Clearance {
        mm: least.mm - 0.3,
        ..least.clone()
    });
    let scene_of_plan = |plan: &crate::refine::Plan| {
        scene(
            &job.cell,
            &job.robot,
            &out.placed,
            plan,
            &out.rendered.names,
            &out.rendered.moves,
        )
    };
    let s = scene_of_plan(&plan);
    let c = s.clearance.expect("marked");
    assert_eq!(c.corner_waypoint, Some(1));
    assert!(c.move_index <= 1, "{}", c.move_index);
    assert_eq!(
        c.distance_mm,
        crate::precision::round(least.mm - 0.3, crate::precision::LENGTH_DECIMALS)
    );
    assert_eq!(
        (c.shape.as_str(), c.obstacle.as_str()),
        (
            crate::output::clearance_part(&least).1,
            least.obstacle.as_str()
        )
    );
    // On the second half of the move into the via or the first half of the move out.
    let t = c.time_s.expect("a time");
    let (w0, w1, w2) = (&s.waypoints[0], &s.waypoints[1], &s.waypoints[2]);
    let (a, b) = (0.5 * (w0.time_s + w1.time_s), 0.5 * (w1.time_s + w2.time_s));
    assert!(t >= a - 1e-9 && t <= b + 1e-9, "{t} outside {a} .. {b}");
    // Without the fly-by zone no corner holds it: nothing is marked rather than a wrong move.
    plan.moves[0].motion.zone = "fine".into();
    let s = scene_of_plan(&plan);
    assert!(s.clearance.is_none());
}

#[test]
fn closest_points_of_each_shape_and_a_box_by_hand() {
    let lo = Point3::new(100.0, -50.0, -50.0);
    let hi = Point3::new(200.0, 50.0, 50.0);
    let shifted = Isometry3::translation(0.0, 0.0, 0.0);
    // A ball of radius 20 at the origin: 80 mm from the box's face x = 100.
    let ball = ShapeGeometry::Sphere {
        centre_mm: [0.0; 3],
        radius_mm: 20.0,
    };
    let (d, [p, q]) = closest_points(&ball, &shifted, &lo, &hi);
    assert!((d - 80.0).abs() < 1e-6 && close(p, [20.0, 0.0, 0.0], 1e-6));
    assert!(close(q, [100.0, 0.0, 0.0], 1e-6));
    // A cylinder along its z, radius 10, length 100, turned -90 deg about y: it runs from
    // x = 0 to x = -100 in the cell, so its cap at x = 0 is 100 mm from the face.
    let turned = Isometry3::rotation(Vector3::y() * -std::f64::consts::FRAC_PI_2);
    let cyl = ShapeGeometry::Cylinder {
        radius_mm: 10.0,
        from_mm: [0.0; 3],
        to_mm: [0.0, 0.0, 100.0],
    };
    let (d, _) = closest_points(&cyl, &turned, &lo, &hi);
    assert!((d - 100.0).abs() < 1e-6, "{d}");
    // The same cylinder turned the other way reaches x = 100: it touches the box.
    let towards = Isometry3::rotation(Vector3::y() * std::f64::consts::FRAC_PI_2);
    let (d, _) = closest_points(&cyl, &towards, &lo, &hi);
    assert!(d < 1e-6, "{d}");
    // A box 10 mm wide at x in [40, 50], moved 30 mm along x: 20 mm from the face.
    let plate = ShapeGeometry::Box {
        min_mm: [40.0, -5.0, -5.0],
        max_mm: [50.0, 5.0, 5.0],
    };
    let (d, _) = closest_points(&plate, &Isometry3::translation(30.0, 0.0, 0.0), &lo, &hi);
    assert!((d - 20.0).abs() < 1e-6, "{d}");
}

#[test]
fn a_failure_shows_the_cell_the_robot_and_the_points_not_joined() {
    let job = job();
    let placed = pipeline::place(&job).expect("placed");
    let s = failure_scene(
        &job.cell,
        &job.robot,
        Some(placed.placement),
        Some(&placed.points),
        &[0, 1],
        "no path",
    );
    assert_eq!(s.keyframes.len(), 1);
    let f = s.failure.expect("a failure");
    let poser = Poser::new(&job.robot, placed.placement, job.cell.tool.as_ref());
    assert_eq!(f.points.len(), 2);
    assert_eq!(f.points[1].name, "P2");
    assert_eq!(
        f.points[1].position_mm,
        poser.tcp_mm(&placed.points[1].joints_deg)
    );
    assert_eq!(s.keyframes[0].tcp_mm, f.points[0].position_mm);
    assert!(s.waypoints.is_empty() && s.clearance.is_none());
    // Nothing placed and no base known: the cell and what the cell itself says, no robot.
    let s = failure_scene(&job.cell, &job.robot, None, None, &[0], "no base");
    assert!(s.keyframes.is_empty() && s.base.is_none());
    assert!(s.failure.as_ref().is_some_and(|f| f.points.is_empty()));
    assert_eq!(s.obstacles.len(), 2);
    // The page renders either way.
    assert!(super::super::render_html(&s).is_ok());
}

/// The torch cell's process moves on the page: every keyframe of a seam, an approach or a
/// retract line puts the TCP on the straight line between the move's ends (within 0.01 mm),
/// and the robot drawn there (the tool's frame in the keyframe, through the tooldata) within
/// 0.5 mm of it, where the straight joint move between the same ends strays by millimetres
/// (so keyframes of the joint interpolation would fail); the moves carry their kind and
/// instruction, the waypoints the actions the module writes there.
#[test]
fn process_moves_follow_their_tcp_path_and_carry_their_actions() {
    let job = pipeline::load(Path::new("cells/torch-trunk.yaml")).expect("the torch cell");
    let out = pipeline::run(&job, &Options::new(Method::Extensile, 1.0)).expect("plans");
    let s = scene_of(&job, &out);
    let plan = &out.plan;
    assert_eq!(s.moves.len(), s.waypoints.len() - 1);
    let kinds: Vec<&str> = (s.moves.iter())
        .map(|m| m.kind.as_str())
        .filter(|k| *k != "joint")
        .collect();
    assert_eq!(
        kinds,
        ["approach", "linear", "retract", "approach", "linear", "retract"]
    );
    let tool = job.cell.tool.as_ref().expect("a tool");
    let tframe = tool.tframe.written().isometry();
    // The first tool shape's keyframe pose is the flange's.
    let flange_shape = s
        .shapes
        .iter()
        .position(|d| d.kind == ShapeKind::Tool)
        .expect("tool shapes");
    let poser = Poser::new(&job.robot, out.placed.placement, Some(tool));
    let off_line = |p: [f64; 3], a: [f64; 3], b: [f64; 3]| {
        let (p, a, b) = (Vector3::from(p), Vector3::from(a), Vector3::from(b));
        let d = b - a;
        let u = ((p - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
        (p - (a + d * u)).norm()
    };
    let mut checked = 0;
    let mut straying: f64 = 0.0;
    for (i, m) in s.moves.iter().enumerate() {
        let (a, b) = (&s.waypoints[i], &s.waypoints[i + 1]);
        if m.kind == "joint" {
            continue;
        }
        assert!(m.instruction.starts_with("MoveL "), "{}", m.instruction);
        let (t0, t1) = (a.time_s, b.time_s);
        for k in s
            .keyframes
            .iter()
            .filter(|k| k.time_s >= t0 && k.time_s <= t1)
        {
            let on = off_line(k.tcp_mm, a.tcp_mm, b.tcp_mm);
            assert!(on < 0.01, "move {}: the TCP {on} mm off its line", i + 1);
            let f = &k.poses[flange_shape];
            let q = f.quat_wxyz;
            let flange = Isometry3::from_parts(
                nalgebra::Translation3::from(Vector3::from(f.position_mm)),
                nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
                    q[0], q[1], q[2], q[3],
                )),
            );
            let drawn = (flange * tframe).translation.vector;
            let on = off_line(drawn.into(), a.tcp_mm, b.tcp_mm);
            assert!(
                on < 0.5,
                "move {}: the drawn TCP {on} mm off its line",
                i + 1
            );
            checked += 1;
        }
        let w = &plan.route.waypoints;
        let mid = lerp6(&w[i].joints_deg, &w[i + 1].joints_deg, 0.5);
        straying = straying.max(off_line(poser.tcp_mm(&mid), a.tcp_mm, b.tcp_mm));
    }
    assert!(checked > 20, "{checked} keyframes on process moves");
    assert!(
        straying > 1.0,
        "the joint interpolation strays only {straying} mm: the test would not tell"
    );
    let actions = |name: &str| -> Vec<String> {
        (s.waypoints.iter())
            .find(|w| w.name == name)
            .map(|w| w.actions.clone())
            .unwrap_or_default()
    };
    assert_eq!(actions("L1"), ["SetDO doWeld, 1"]);
    assert_eq!(actions("L2"), ["SetDO doWeld, 0"]);
    assert_eq!(actions("home"), Vec::<String>::new());
    let approach = s
        .waypoints
        .iter()
        .filter(|w| w.kind == WaypointKind::Approach);
    assert_eq!(approach.count(), 2);
}
