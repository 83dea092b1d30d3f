//! The preview's [`Scene`] from a run's results: the cell's boxes, the robot's link cylinders
//! and the tool's shapes posed by forward kinematics ([`Poser`]) at keyframes sampled along
//! every move with the estimated timing, the waypoints with the names the module gives them,
//! the TCP trace, and the place of the smallest clearance; or, for a failed plan, the cell, the
//! robot where it could be placed and the points that could not be joined.
//!
//! **Keyframes.** Move `i` starts when move `i - 1` ends and lasts its estimated time; within it all six axes run together along the straight joint move (`MoveAbsJ`)
//! at the progress of the move's profile (`Profile::progress`, the leading axis' profile of the
//! time stage: the leading axis', or the TCP path's when the speeddata leads). A move is sampled
//! piece by piece (a ramp, the cruise, a ramp; or its one quintic) every [`KEYFRAME_STEP_S`] of
//! time and every [`KEYFRAME_STEP_DEG`] of its largest axis change (whichever gives more
//! samples), a ramp into at least [`RAMP_KEYFRAMES`] (a TCP-limited move's ramps are short and
//! steep), both ends included, so the page's linear interpolation between keyframes stays within
//! about a millimetre of the kinematics (a test measures it).
//!
//! **The smallest clearance** is the plan's certified figure, on the move, link and obstacle the
//! plan names (the move whose clearance is [`Plan::least`]; none where the least is a zoned
//! corner's). Where on the move it occurs is only for the picture:
//! the move is sampled ([`CLEARANCE_SAMPLES`]) and at each sample the closest points of the
//! named shape and box are found by alternating projections (two convex sets: project onto one,
//! then the other, until the pair stops moving); the nearest sample gives the time and the two
//! points the page joins with a red line. That search certifies nothing.

use super::{
    FailedPoint, Keyframe, Scene, SceneBase, SceneClearance, SceneFailure, SceneObstacle,
    ScenePose, SceneWaypoint, ShapeDef, ShapeGeometry, ShapeKind, WaypointKind,
};
use crate::cell::{Cell, Target, ToolGeometry};
use crate::output::poses::Poser;
use crate::place::{Placed, PlacedPoint, Placement};
use crate::plan::motion::Profile;
use crate::refine::Plan;
use crate::robot::{LinkFrame, Robot};
use nalgebra::{Isometry3, Point3, Vector3};

/// Keyframes at least this often along a move, s.
pub const KEYFRAME_STEP_S: f64 = 1.0 / 30.0;
/// Keyframes at least every this many degrees of a move's largest axis change.
pub const KEYFRAME_STEP_DEG: f64 = 1.0;
/// Samples along the move of the smallest clearance, to place its marker.
pub const CLEARANCE_SAMPLES: usize = 400;

/// One shape of the robot model and the frame it hangs on.
enum Carrier {
    /// The robot's base (base_link).
    Base,
    /// Link `k` (0-based: the child of joint `k + 1`).
    Link(usize),
    /// The flange (tool0), which carries the tool's shapes.
    Flange,
}

/// The robot's link cylinders as the URDF gives them (every link's, on its own link: what the
/// checks' enclosures hold, `robot/lumped.rs`), then the tool's shapes, each with the frame it
/// hangs on.
fn shapes(robot: &Robot, cell: &Cell) -> (Vec<ShapeDef>, Vec<Carrier>) {
    let mut defs = Vec::new();
    let mut carriers = Vec::new();
    for c in &robot.collision {
        defs.push(ShapeDef {
            name: c.link.clone(),
            kind: ShapeKind::Link,
            geometry: ShapeGeometry::Cylinder {
                radius_mm: c.radius_mm,
                from_mm: c.a.coords.into(),
                to_mm: c.b.coords.into(),
            },
        });
        carriers.push(match c.frame {
            LinkFrame::Base => Carrier::Base,
            LinkFrame::Child(k) => Carrier::Link(k),
        });
    }
    for s in cell.tool.iter().flat_map(|t| &t.shapes) {
        let geometry = match s.geometry {
            ToolGeometry::Cylinder {
                from_mm,
                to_mm,
                radius_mm,
            } => ShapeGeometry::Cylinder {
                radius_mm,
                from_mm,
                to_mm,
            },
            ToolGeometry::Box { min_mm, max_mm } => ShapeGeometry::Box { min_mm, max_mm },
            ToolGeometry::Sphere {
                centre_mm,
                radius_mm,
            } => ShapeGeometry::Sphere {
                centre_mm,
                radius_mm,
            },
        };
        defs.push(ShapeDef {
            name: s.name.clone(),
            kind: ShapeKind::Tool,
            geometry,
        });
        carriers.push(Carrier::Flange);
    }
    (defs, carriers)
}

fn obstacles(cell: &Cell) -> Vec<SceneObstacle> {
    cell.obstacles
        .iter()
        .map(|o| SceneObstacle {
            name: o.name.clone(),
            min_mm: o.aabb.min.coords.into(),
            max_mm: o.aabb.max.coords.into(),
        })
        .collect()
}

fn scene_pose(iso: &Isometry3<f64>) -> ScenePose {
    let q = iso.rotation.quaternion();
    let t = iso.translation.vector;
    ScenePose {
        position_mm: [t.x, t.y, t.z],
        quat_wxyz: [q.w, q.i, q.j, q.k],
    }
}

/// The robot at one pose: every shape's frame and the TCP.
fn keyframe(poser: &Poser, carriers: &[Carrier], time_s: f64, axes: &[f64; 6]) -> Keyframe {
    let links = poser.links(axes);
    let flange = poser.tool0(axes);
    Keyframe {
        time_s,
        poses: carriers
            .iter()
            .map(|c| match c {
                Carrier::Base => scene_pose(&poser.base()),
                Carrier::Link(k) => scene_pose(&links[*k]),
                Carrier::Flange => scene_pose(&flange),
            })
            .collect(),
        tcp_mm: poser.tcp_mm(axes),
    }
}

fn lerp6(a: &[f64; 6], b: &[f64; 6], s: f64) -> [f64; 6] {
    std::array::from_fn(|k| a[k] + s * (b[k] - a[k]))
}

/// Keyframes ramps are cut into at least (module docs).
const RAMP_KEYFRAMES: f64 = 4.0;

/// The times (s, after the move's start, the last `duration`) of a move's keyframes (module
/// docs): each piece of the profile (a ramp, the cruise, a ramp; or the whole quintic) cut into
/// equal steps of at most [`KEYFRAME_STEP_S`] and [`KEYFRAME_STEP_DEG`] of the largest axis
/// change over the piece, a ramp into at least [`RAMP_KEYFRAMES`].
fn keyframe_times(duration: f64, profile: Profile, largest_deg: f64) -> Vec<f64> {
    let pieces: Vec<(f64, f64, f64)> = match profile {
        Profile::Cruise { ramp_s } if ramp_s > 0.0 && 2.0 * ramp_s <= duration => vec![
            (0.0, ramp_s, RAMP_KEYFRAMES),
            (ramp_s, duration - ramp_s, 1.0),
            (duration - ramp_s, duration, RAMP_KEYFRAMES),
        ],
        _ => vec![(0.0, duration, 1.0)],
    };
    let mut times = Vec::new();
    for (a, b, least) in pieces {
        let share = profile.progress(b, duration) - profile.progress(a, duration);
        let n = ((b - a) / KEYFRAME_STEP_S)
            .ceil()
            .max((largest_deg * share / KEYFRAME_STEP_DEG).ceil())
            .max(least) as usize;
        times.extend((1..=n).map(|j| {
            if j == n {
                b
            } else {
                a + (b - a) * j as f64 / n as f64
            }
        }));
    }
    times
}

/// The title the page shows: the module and the cell file's name.
fn title(cell: &Cell) -> (String, String) {
    let file = cell
        .path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    (format!("{} - {file}", cell.module), file)
}

/// Each move's estimated duration and profile.
fn timing(plan: &Plan) -> Vec<(f64, Profile)> {
    (plan.moves.iter())
        .map(|m| (m.estimate.time_s, m.estimate.profile))
        .collect()
}

/// The scene of a planned run: `names` are the module's names of the plan's waypoints (the
/// cell points' own, `via<leg>_<index>` for the vias), in order.
pub fn scene(cell: &Cell, robot: &Robot, placed: &Placed, plan: &Plan, names: &[String]) -> Scene {
    let poser = Poser::new(robot, placed.placement, cell.tool.as_ref());
    let (defs, carriers) = shapes(robot, cell);
    let timing = timing(plan);
    let route = &plan.route;
    let mut keyframes = Vec::new();
    let mut waypoints = Vec::with_capacity(route.waypoints.len());
    let mut starts = Vec::with_capacity(route.moves());
    let mut t0 = 0.0;
    for (k, w) in route.waypoints.iter().enumerate() {
        if k == 0 {
            keyframes.push(keyframe(&poser, &carriers, 0.0, &w.joints_deg));
        } else {
            let from = &route.waypoints[k - 1].joints_deg;
            let (duration, profile) = timing[k - 1];
            starts.push(t0);
            let largest = (0..6)
                .map(|a| (w.joints_deg[a] - from[a]).abs())
                .fold(0.0, f64::max);
            let times = keyframe_times(duration, profile, largest);
            let last = times.len() - 1;
            for (j, &t) in times.iter().enumerate() {
                let axes = if j == last {
                    w.joints_deg
                } else {
                    lerp6(from, &w.joints_deg, profile.progress(t, duration))
                };
                keyframes.push(keyframe(&poser, &carriers, t0 + t, &axes));
            }
            t0 += duration;
        }
        waypoints.push(SceneWaypoint {
            name: names.get(k).cloned().unwrap_or_default(),
            kind: match w.kind {
                crate::plan::WaypointKind::CellPoint(_) => WaypointKind::Cell,
                crate::plan::WaypointKind::Via { .. } => WaypointKind::Via,
            },
            time_s: t0,
            tcp_mm: poser.tcp_mm(&w.joints_deg),
        });
    }
    let clearance = clearance(cell, plan, &poser, &defs, &carriers, &timing, &starts);
    let (title, cell_file) = title(cell);
    Scene {
        title,
        module: cell.module.clone(),
        cell_file,
        obstacles: obstacles(cell),
        base: Some(base(placed.placement)),
        shapes: defs,
        keyframes,
        waypoints,
        clearance,
        // As the module header states it.
        total_time_s: Some(crate::precision::round(
            plan.total_s,
            crate::precision::TIME_DECIMALS,
        )),
        failure: None,
    }
}

fn base(p: Placement) -> SceneBase {
    SceneBase {
        position_mm: p.base_mm,
        yaw_deg: p.yaw_deg,
    }
}

/// The smallest clearance of the plan, marked where it occurs (module docs).
fn clearance(
    cell: &Cell,
    plan: &Plan,
    poser: &Poser,
    defs: &[ShapeDef],
    carriers: &[Carrier],
    timing: &[(f64, Profile)],
    starts: &[f64],
) -> Option<SceneClearance> {
    let least = plan.least.as_ref()?;
    let i = (plan.moves.iter()).position(|m| m.clearance.as_ref() == Some(least))?;
    // The link (or tool shape) named by the clearance, and the obstacle.
    let (part, shape_name) = crate::output::clearance_part(least);
    let kind = if part == "tool" {
        ShapeKind::Tool
    } else {
        ShapeKind::Link
    };
    let s = defs
        .iter()
        .position(|d| d.kind == kind && d.name == shape_name)?;
    let obstacle = cell.obstacles.iter().find(|o| o.name == least.obstacle)?;
    let (from, to) = (
        &plan.route.waypoints[i].joints_deg,
        &plan.route.waypoints[i + 1].joints_deg,
    );
    let (duration, profile) = timing.get(i).copied().unwrap_or((0.0, Profile::Quintic));
    let mut best: Option<(f64, f64, [[f64; 3]; 2])> = None;
    for j in 0..=CLEARANCE_SAMPLES {
        let u = j as f64 / CLEARANCE_SAMPLES as f64;
        let t = duration * u;
        let axes = lerp6(from, to, profile.progress(t, duration));
        let frame = match carriers[s] {
            Carrier::Base => poser.base(),
            Carrier::Link(k) => poser.links(&axes)[k],
            Carrier::Flange => poser.tool0(&axes),
        };
        let (d, pts) = closest_points(
            &defs[s].geometry,
            &frame,
            &obstacle.aabb.min,
            &obstacle.aabb.max,
        );
        if best.is_none_or(|b| d < b.1) {
            best = Some((t, d, pts));
        }
    }
    let (t, _, points) = best?;
    Some(SceneClearance {
        distance_mm: crate::precision::round(least.mm, crate::precision::LENGTH_DECIMALS),
        move_index: i,
        shape: shape_name.to_string(),
        obstacle: least.obstacle.clone(),
        time_s: Some(starts.get(i).copied().unwrap_or(0.0) + t),
        points_mm: Some(points),
    })
}

/// The closest points of a shape (in `frame`) and a box `[lo, hi]` (cell frame), and their
/// distance, by alternating projections (module docs): for the picture only.
fn closest_points(
    g: &ShapeGeometry,
    frame: &Isometry3<f64>,
    lo: &Point3<f64>,
    hi: &Point3<f64>,
) -> (f64, [[f64; 3]; 2]) {
    let on_box = |p: &Point3<f64>| Point3::from(p.coords.sup(&lo.coords).inf(&hi.coords));
    // The closest point of the shape to `q` (cell frame).
    let on_shape = |q: &Point3<f64>| -> Point3<f64> {
        let local = frame.inverse_transform_point(q);
        let p = match g {
            ShapeGeometry::Cylinder {
                radius_mm,
                from_mm,
                to_mm,
            } => {
                let a = Point3::from(*from_mm);
                let axis = Point3::from(*to_mm) - a;
                let len = axis.norm();
                let u = if len > 0.0 { axis / len } else { Vector3::z() };
                let v = local - a;
                let along = v.dot(&u).clamp(0.0, len);
                let radial = v - u * v.dot(&u);
                let r = radial.norm();
                let radial = if r > *radius_mm {
                    radial * (*radius_mm / r)
                } else {
                    radial
                };
                a + u * along + radial
            }
            ShapeGeometry::Box { min_mm, max_mm } => Point3::from(
                local
                    .coords
                    .sup(&Vector3::from(*min_mm))
                    .inf(&Vector3::from(*max_mm)),
            ),
            ShapeGeometry::Sphere {
                centre_mm,
                radius_mm,
            } => {
                let c = Point3::from(*centre_mm);
                let d = local - c;
                let n = d.norm();
                if n > *radius_mm {
                    c + d * (*radius_mm / n)
                } else {
                    local
                }
            }
        };
        frame.transform_point(&p)
    };
    let mut q = nalgebra::center(lo, hi);
    let mut p = on_shape(&q);
    for _ in 0..200 {
        let q_next = on_box(&p);
        let p_next = on_shape(&q_next);
        let settled = (q_next - q).norm() < 1e-6 && (p_next - p).norm() < 1e-6;
        (p, q) = (p_next, q_next);
        if settled {
            break;
        }
    }
    ((p - q).norm(), [p.coords.into(), q.coords.into()])
}

/// The scene of a failed plan: the cell, the robot still at the first of `failed` (the points
/// the failure is about, indices into the cell's points) where the points were placed, and
/// those points (TCP, or the wrist centre an `xyz` point gives) with `message`. `placement` is
/// where the robot stands, if that was decided; `placed` the placed points, if the place stage
/// got that far.
pub fn failure_scene(
    cell: &Cell,
    robot: &Robot,
    placement: Option<Placement>,
    placed: Option<&[PlacedPoint]>,
    failed: &[usize],
    message: &str,
) -> Scene {
    let (defs, carriers) = shapes(robot, cell);
    let poser = placement.map(|p| Poser::new(robot, p, cell.tool.as_ref()));
    let joints = |i: usize| -> Option<[f64; 6]> {
        match (placed.and_then(|p| p.get(i)), cell.points.get(i)) {
            (Some(p), _) => Some(p.joints_deg),
            (
                None,
                Some(crate::cell::Point {
                    target:
                        Target::Joints {
                            axes_deg,
                            wrist_deg,
                        },
                    ..
                }),
            ) => {
                let w = wrist_deg.unwrap_or(cell.robot.wrist_deg);
                Some([axes_deg[0], axes_deg[1], axes_deg[2], w[0], w[1], w[2]])
            }
            _ => None,
        }
    };
    let position = |i: usize| -> Option<[f64; 3]> {
        if let (Some(poser), Some(j)) = (&poser, joints(i)) {
            return Some(poser.tcp_mm(&j));
        }
        match &cell.points.get(i)?.target {
            Target::Xyz {
                wrist_centre_mm, ..
            } => Some(*wrist_centre_mm),
            Target::Robtarget { pose, .. } => {
                let uframe = cell
                    .wobj_of(cell.points.get(i)?)
                    .map_or(Isometry3::identity(), |w| w.uframe.isometry());
                let p = uframe * Point3::from(pose.pos_mm);
                Some([p.x, p.y, p.z])
            }
            Target::Joints { .. } => None,
        }
    };
    let keyframes = match (&poser, failed.first().and_then(|&i| joints(i))) {
        (Some(poser), Some(j)) => vec![keyframe(poser, &carriers, 0.0, &j)],
        _ => Vec::new(),
    };
    let points = failed
        .iter()
        .filter_map(|&i| {
            Some(FailedPoint {
                name: cell.points.get(i)?.name.clone(),
                position_mm: position(i)?,
            })
        })
        .collect();
    let (title, cell_file) = title(cell);
    Scene {
        title,
        module: cell.module.clone(),
        cell_file,
        obstacles: obstacles(cell),
        base: placement.map(base),
        shapes: defs,
        keyframes,
        waypoints: Vec::new(),
        clearance: None,
        total_time_s: None,
        failure: Some(SceneFailure {
            message: message.to_string(),
            points,
        }),
    }
}

#[cfg(test)]
mod tests {
    //! The scene of a real (small) run: the bundled IRB 1400 with a tool, a table and a post.
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
                let shown: [f64; 3] =
                    std::array::from_fn(|a| 0.5 * (w[0].tcp_mm[a] + w[1].tcp_mm[a]));
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
        let s = scene(
            &job.cell,
            &job.robot,
            &out.placed,
            &out.plan,
            &out.rendered.names,
        );
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
        let s = scene(
            &job.cell,
            &job.robot,
            &out.placed,
            &out.plan,
            &out.rendered.names,
        );
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
}
