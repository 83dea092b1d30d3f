//! The preview's [`Scene`] from a run's results: the cell's boxes, the robot's link cylinders
//! and the tool's shapes posed by forward kinematics ([`Poser`]) at keyframes sampled along
//! every move with the estimated timing, the waypoints with the names the module gives them,
//! the TCP trace, and the place of the smallest clearance; or, for a failed plan, the cell, the
//! robot where it could be placed and the points that could not be joined.
//!
//! **Keyframes.** Move `i` starts when move `i - 1` ends and lasts its estimated time; within an
//! air move all six axes run together along the straight joint move (`MoveAbsJ`, `MoveJ`); along
//! a process move (`MoveL`, `MoveC`, approach and retract lines) the TCP runs its line or arc and
//! the joints are the follow stage's (the plan's followed path: its samples, between them
//! linearly), so the trace is the path the controller runs; both
//! at the progress of the move's profile (`Profile::progress`, the leading axis' profile of the
//! time stage: the leading axis', or the TCP path's when the speeddata leads). A move is sampled
//! piece by piece (a ramp, the cruise, a ramp; or its one quintic) every [`KEYFRAME_STEP_S`] of
//! time and every [`KEYFRAME_STEP_DEG`] of its largest axis change (whichever gives more
//! samples), a ramp into at least [`RAMP_KEYFRAMES`] (a TCP-limited move's ramps are short and
//! steep), both ends included, so the page's linear interpolation between keyframes stays within
//! about a millimetre of the kinematics (a test measures it). A run of more than
//! [`MAX_KEYFRAMES`] keyframes (slow speeds, long moves) is thinned to about that many: every
//! `stride`-th keyframe and every waypoint kept, so the page stays a few MB; its motion between
//! them is then coarser.
//!
//! **The smallest clearance** is the plan's certified figure, with the link and obstacle the
//! plan names, on the move whose clearance is [`Plan::least`], or, where the least is a zoned
//! corner's (a fly-by `via_zone`: no move has it), on the corner of a fly-by waypoint: the page
//! names that waypoint and marks the nearest place on the two half moves through it (the path
//! the page draws; the controller's blend runs inside their corner). Where it occurs is only for
//! the picture: the move (or each half move) is sampled ([`CLEARANCE_SAMPLES`]) and at each sample the closest points of the
//! named shape and box are found by alternating projections (two convex sets: project onto one,
//! then the other, until the pair stops moving); the nearest sample gives the time and the two
//! points the page joins with a red line. That search certifies nothing.

use super::{
    FailedPoint, Keyframe, Scene, SceneBase, SceneClearance, SceneFailure, SceneMove,
    SceneObstacle, ScenePose, SceneWaypoint, ShapeDef, ShapeGeometry, ShapeKind, WaypointKind,
};
use crate::cell::{Cell, Target, ToolGeometry};
use crate::output::poses::Poser;
use crate::output::rapid::WrittenMove;
use crate::place::{Placed, PlacedPoint, Placement};
use crate::plan::motion::Profile;
use crate::refine::Plan;
use crate::robot::ik::follow::FollowedPath;
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

/// The robot at one pose: every shape's frame and the TCP (on a process move's path: the path's
/// point, `tcp`).
fn keyframe(poser: &Poser, carriers: &[Carrier], time_s: f64, axes: &[f64; 6]) -> Keyframe {
    keyframe_at(poser, carriers, time_s, axes, None)
}

fn keyframe_at(
    poser: &Poser,
    carriers: &[Carrier],
    time_s: f64,
    axes: &[f64; 6],
    tcp: Option<[f64; 3]>,
) -> Keyframe {
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
        tcp_mm: tcp.unwrap_or_else(|| poser.tcp_mm(axes)),
    }
}

/// The joints a process move runs at progress `s` (0..1 of its path): between the follow
/// stage's samples (each the controller's continuing solution, the chords between them within
/// the follower's small deviation bound), linearly.
fn along(path: &FollowedPath, s: f64) -> [f64; 6] {
    let samples = path.samples();
    let k = samples.partition_point(|p| p.s <= s);
    match (
        k.checked_sub(1).and_then(|j| samples.get(j)),
        samples.get(k),
    ) {
        (Some(a), Some(b)) if b.s > a.s => {
            lerp6(&a.joints_deg, &b.joints_deg, (s - a.s) / (b.s - a.s))
        }
        (Some(a), _) => a.joints_deg,
        (None, Some(b)) => b.joints_deg,
        (None, None) => [0.0; 6],
    }
}

/// Move `i` of `plan` at `fraction` (0..1) of its progress: the joints, and on a process move
/// the TCP on its path (the line or arc the controller runs, not the joint interpolation).
fn move_at(plan: &Plan, i: usize, fraction: f64) -> ([f64; 6], Option<[f64; 3]>) {
    let w = &plan.route.waypoints;
    let (from, to) = (&w[i].joints_deg, &w[i + 1].joints_deg);
    match plan.moves.get(i).and_then(|m| m.path.as_ref()) {
        Some(path) => (
            along(path, fraction),
            Some(path.tcp_at(fraction).coords.into()),
        ),
        None => (lerp6(from, to, fraction), None),
    }
}

fn lerp6(a: &[f64; 6], b: &[f64; 6], s: f64) -> [f64; 6] {
    std::array::from_fn(|k| a[k] + s * (b[k] - a[k]))
}

/// Keyframes ramps are cut into at least (module docs).
const RAMP_KEYFRAMES: f64 = 4.0;

/// The pieces of a move's keyframes (module docs): each piece of the profile (a ramp, the
/// cruise, a ramp; or the whole quintic) from `a` to `b` (s, after the move's start) cut into
/// `n` equal steps of at most [`KEYFRAME_STEP_S`] and [`KEYFRAME_STEP_DEG`] of the largest axis
/// change over the piece, a ramp into at least [`RAMP_KEYFRAMES`]. Counted, not listed: a slow
/// move of a large arm has millions.
fn keyframe_pieces(duration: f64, profile: Profile, largest_deg: f64) -> Vec<(f64, f64, u64)> {
    let pieces: Vec<(f64, f64, f64)> = match profile {
        Profile::Cruise { ramp_s } if ramp_s > 0.0 && 2.0 * ramp_s <= duration => vec![
            (0.0, ramp_s, RAMP_KEYFRAMES),
            (ramp_s, duration - ramp_s, 1.0),
            (duration - ramp_s, duration, RAMP_KEYFRAMES),
        ],
        _ => vec![(0.0, duration, 1.0)],
    };
    pieces
        .into_iter()
        .map(|(a, b, least)| {
            let share = profile.progress(b, duration) - profile.progress(a, duration);
            let n = ((b - a) / KEYFRAME_STEP_S)
                .ceil()
                .max((largest_deg * share / KEYFRAME_STEP_DEG).ceil())
                .max(least);
            // A NaN or a count past u64 (it cannot be listed anyway) becomes the most.
            let n = if n.is_finite() { n as u64 } else { u64::MAX };
            (a, b, n.max(1))
        })
        .collect()
}

/// The most keyframes a page holds: a page past it is thinned (every `stride`-th keyframe of
/// the run kept, and every waypoint's), so the page stays a few MB (60 points at `v5`
/// sampled every 1/30 s made a 157 MB page).
pub const MAX_KEYFRAMES: u64 = 20_000;

/// The times (s, after the move's start, the last `duration`) of a move's keyframes: of its
/// pieces ([`keyframe_pieces`]), the keyframes numbered `first + j` (counting on from the
/// keyframes of the moves before) that are multiples of `stride`, and the move's end.
fn keyframe_times(pieces: &[(f64, f64, u64)], first: u64, stride: u64) -> Vec<f64> {
    let mut times = Vec::new();
    let mut before = first;
    for (k, &(a, b, n)) in pieces.iter().enumerate() {
        let at = |j: u64| {
            if j == n {
                b
            } else {
                a + (b - a) * j as f64 / n as f64
            }
        };
        // The first j in 1..=n with (before + j) a multiple of the stride, then every stride.
        let mut j = stride - before % stride;
        while j <= n {
            times.push(at(j));
            j = j.saturating_add(stride);
        }
        let last = k + 1 == pieces.len();
        if last && times.last() != Some(&b) {
            times.push(b);
        }
        before = before.saturating_add(n);
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
/// cell points' own, `via<leg>_<index>` for the vias), in order; `written` the module's moves
/// (move `k` into waypoint `k`: its instruction and the actions after it).
pub fn scene(
    cell: &Cell,
    robot: &Robot,
    placed: &Placed,
    plan: &Plan,
    names: &[String],
    written: &[WrittenMove],
) -> Scene {
    let poser = Poser::new(robot, placed.placement, cell.tool.as_ref());
    let (defs, carriers) = shapes(robot, cell);
    let timing = timing(plan);
    let route = &plan.route;
    let mut keyframes = Vec::new();
    let mut waypoints = Vec::with_capacity(route.waypoints.len());
    let mut starts = Vec::with_capacity(route.moves());
    let mut t0 = 0.0;
    let pieces: Vec<Vec<(f64, f64, u64)>> = route
        .waypoints
        .windows(2)
        .zip(&timing)
        .zip(&plan.moves)
        .map(|((pair, &(duration, profile)), m)| {
            let largest = match &m.path {
                Some(path) => path.axis_travel_deg().into_iter().fold(0.0, f64::max),
                None => (0..6)
                    .map(|a| (pair[1].joints_deg[a] - pair[0].joints_deg[a]).abs())
                    .fold(0.0, f64::max),
            };
            keyframe_pieces(duration, profile, largest)
        })
        .collect();
    let total = pieces
        .iter()
        .flatten()
        .fold(1u64, |sum, p| sum.saturating_add(p.2));
    let stride = total.div_ceil(MAX_KEYFRAMES).max(1);
    let mut counted = 0u64;
    for (k, w) in route.waypoints.iter().enumerate() {
        if k == 0 {
            keyframes.push(keyframe(&poser, &carriers, 0.0, &w.joints_deg));
        } else {
            let (duration, profile) = timing[k - 1];
            starts.push(t0);
            let times = keyframe_times(&pieces[k - 1], counted, stride);
            counted = pieces[k - 1]
                .iter()
                .fold(counted, |sum, p| sum.saturating_add(p.2));
            let last = times.len() - 1;
            for (j, &t) in times.iter().enumerate() {
                let (axes, tcp) = if j == last {
                    (w.joints_deg, move_at(plan, k - 1, 1.0).1)
                } else {
                    move_at(plan, k - 1, profile.progress(t, duration))
                };
                keyframes.push(keyframe_at(&poser, &carriers, t0 + t, &axes, tcp));
            }
            t0 += duration;
        }
        waypoints.push(SceneWaypoint {
            name: names.get(k).cloned().unwrap_or_default(),
            kind: match w.kind {
                crate::plan::WaypointKind::CellPoint(_) => WaypointKind::Cell,
                crate::plan::WaypointKind::Via { .. } => WaypointKind::Via,
                crate::plan::WaypointKind::Approach(_) => WaypointKind::Approach,
                crate::plan::WaypointKind::Retract(_) => WaypointKind::Retract,
            },
            time_s: t0,
            tcp_mm: poser.tcp_mm(&w.joints_deg),
            actions: written
                .get(k)
                .map(|m| m.actions.iter().map(|a| a.text.clone()).collect())
                .unwrap_or_default(),
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
        moves: (plan.moves.iter().enumerate())
            .map(|(i, m)| SceneMove {
                kind: m.kind.name().to_string(),
                instruction: written
                    .get(i + 1)
                    .map(|w| format!("{} {}", w.instruction, w.target()))
                    .unwrap_or_default(),
            })
            .collect(),
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

/// The pieces of moves the least clearance is looked for on (module docs): `(move, from, to,
/// corner)`, `from`/`to` fractions of the move, `corner` the waypoint whose zoned corner it is.
fn searched_pieces(
    plan: &Plan,
    least: &crate::plan::Clearance,
) -> Vec<(usize, f64, f64, Option<usize>)> {
    if let Some(i) = (plan.moves.iter()).position(|m| m.clearance.as_ref() == Some(least)) {
        return vec![(i, 0.0, 1.0, None)];
    }
    // A zoned corner's: the halves of the two moves through each fly-by waypoint.
    (1..plan.moves.len())
        .filter(|&k| crate::refine::zones::is_fly_by(&plan.moves[k - 1].motion.zone))
        .flat_map(|k| [(k - 1, 0.5, 1.0, Some(k)), (k, 0.0, 0.5, Some(k))])
        .collect()
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
    // (move, time in it, distance, points, corner)
    type Best = (usize, f64, f64, [[f64; 3]; 2], Option<usize>);
    let mut best: Option<Best> = None;
    for (i, u0, u1, corner) in searched_pieces(plan, least) {
        let (duration, profile) = timing.get(i).copied().unwrap_or((0.0, Profile::Quintic));
        for j in 0..=CLEARANCE_SAMPLES {
            let u = u0 + (u1 - u0) * j as f64 / CLEARANCE_SAMPLES as f64;
            let t = duration * u;
            let (axes, _) = move_at(plan, i, profile.progress(t, duration));
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
            if best.is_none_or(|b| d < b.2) {
                best = Some((i, t, d, pts, corner));
            }
        }
    }
    let (i, t, _, points, corner) = best?;
    Some(SceneClearance {
        distance_mm: crate::precision::round(least.mm, crate::precision::LENGTH_DECIMALS),
        move_index: i,
        corner_waypoint: corner,
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
        moves: Vec::new(),
        clearance: None,
        total_time_s: None,
        failure: Some(SceneFailure {
            message: message.to_string(),
            points,
        }),
    }
}

#[cfg(test)]
#[path = "scene_tests.rs"]
mod tests;
