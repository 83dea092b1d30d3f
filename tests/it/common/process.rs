//! The example cells with process moves (approach and retract lines, linear and circular seams,
//! actions, loads), their modules run as a controller runs them, independently of the
//! library's inverse kinematics and proofs: every motion instruction in order from the joints
//! the one before left (MoveAbsJ to its axis values; MoveJ to the solution of its robtarget,
//! `RelTool` applied, in the robtarget's confdata, by the tests' own OPW inverse kinematics;
//! MoveL and MoveC with the TCP on the line, or on the circle through the start, the circle
//! point and the end, the orientation slerped, sampled every 0.25 mm and 0.05 deg of turn, each
//! sample the branch nearest the one before). Each move is held to: no axis jump between
//! samples (2 deg), every axis in range, axis 5 at least 1 deg from 0 along MoveL/MoveC, the
//! end admitted for the target's confdata, the clearance at every sample and along each chord
//! between samples (the dense check, links and tool), and the header's smallest clearance a
//! lower bound of what the samples measure. The robtargets are the cell's poses; the actions
//! the cell's, in order, after the move into their point. Arc-welding instructions run as the
//! `MoveL`/`MoveC` they make (`routine.rs`); with a weld signal given
//! ([`check_process_welding`]), an `ArcLStart`/`ArcCStart` counts as `SetDO <signal>, 1` and an
//! `ArcLEnd`/`ArcCEnd` as `SetDO <signal>, 0` right after its move (where the arc goes on and
//! off), so the weld is switched where and in the order the cell switches it.
//! A MoveC's circle point has the confdata of the joints at its arc fraction. With
//! `robot.frame: base` (the header's frames line) the controller's world frame is its base
//! frame, placed as the header says: the user frame and wobj0 robtargets are read in it.

use super::dense::Scene;
use super::library::{load_robot, Cell, Target};
use super::module::Module;
use super::opw::{conf_admits, max_diff, Ik};
use super::routine::{Action, Instruction, MoveKind, ToPoint};
use super::tcp::confdata;
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};

/// Samples along a process move: at most this far apart, mm ...
const STEP_MM: f64 = 0.25;
/// ... and turned at most this much, deg.
const STEP_DEG: f64 = 0.05;
/// A larger change of any axis between samples is a jump (a configuration change).
const JUMP_DEG: f64 = 2.0;

fn iso(p: &[f64], q: &[f64]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3])),
    )
}

/// A process move's start and end poses and its circle point (cell frame, mm).
pub type Ends = (Isometry3<f64>, Isometry3<f64>, Option<Point3<f64>>);

/// What running a module measured.
#[derive(Debug, Default)]
pub struct Run {
    /// Samples along process moves.
    pub samples: usize,
    /// The nearest approach seen, mm.
    pub nearest_mm: f64,
    /// Process moves run (MoveL, MoveC).
    pub process_moves: usize,
    /// The farthest a process sample's TCP (by forward kinematics) lies from its path, mm.
    pub off_path_mm: f64,
    /// Each process move's start and end poses and its circle point (cell frame, mm).
    pub ends: Vec<Ends>,
    /// Circle points whose confdata were checked against the joints at their arc fraction.
    pub circle_points: usize,
}

/// A point of the circle through `a`, `b`, `c` from `a` (s = 0) over `b` to `c` (s = 1).
fn arc(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> impl Fn(f64) -> Point3<f64> {
    let k = Circle::through(a, b, c);
    let end = k.angle(c);
    move |s| k.centre + k.radius * ((s * end).cos() * k.e1 + (s * end).sin() * k.e2)
}

/// The circle through three points: its centre and radius, the unit vector from the centre to
/// the first, and the one a quarter turn ahead in the direction first -> second -> third.
struct Circle {
    centre: Point3<f64>,
    radius: f64,
    e1: Vector3<f64>,
    e2: Vector3<f64>,
}

impl Circle {
    fn through(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> Circle {
        let (u, v) = (b - a, c - a);
        let n = u.cross(&v);
        let centre = a
            + (n.cross(&u) * v.norm_squared() + v.cross(&n) * u.norm_squared())
                / (2.0 * n.norm_squared());
        let r1 = a - centre;
        let radius = r1.norm();
        let e1 = r1 / radius;
        let e2 = n.normalize().cross(&e1);
        Circle {
            centre,
            radius,
            e1,
            e2,
        }
    }

    /// The angle of `p` from the first point in the direction of travel (0 .. 2 pi).
    fn angle(&self, p: Point3<f64>) -> f64 {
        let d = p - self.centre;
        let t = d.dot(&self.e2).atan2(d.dot(&self.e1));
        if t < 0.0 {
            t + std::f64::consts::TAU
        } else {
            t
        }
    }
}

/// The arc fraction of `b` on the arc from `a` through `b` to `c`: the angle at the centre from
/// `a` to `b` over the one from `a` to `c`.
fn arc_fraction(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> f64 {
    let k = Circle::through(a, b, c);
    k.angle(b) / k.angle(c)
}

/// Runs `text`, the module written for `cell`, as the module docs say; `label` names it in
/// messages. Every failure is collected.
pub fn check_process(cell: &Cell, text: &str, label: &str) -> Result<Run, Vec<String>> {
    check_process_welding(cell, text, label, None)
}

/// [`check_process`] of a module whose seams are arc-welding instructions switching `signal`
/// (module docs).
pub fn check_process_welding(
    cell: &Cell,
    text: &str,
    label: &str,
    signal: Option<&str>,
) -> Result<Run, Vec<String>> {
    let module = Module::parse(text).map_err(|e| vec![format!("{label}: {e}")])?;
    let robot = load_robot(cell);
    let ik = Ik::new(&robot).map_err(|e| vec![e])?;
    let scene = Scene::new(&robot, module.base_mm, module.yaw_deg, cell);
    let placed = Isometry3::from_parts(
        Translation3::new(module.base_mm[0], module.base_mm[1], module.base_mm[2]),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), module.yaw_deg.to_radians()),
    );
    let mut failures = Vec::new();
    let mut fail = |m: String| failures.push(format!("{label}: {m}"));
    let mut run = Run {
        nearest_mm: f64::INFINITY,
        ..Run::default()
    };
    let tframe = module
        .tooldata
        .first()
        .map_or(Isometry3::identity(), |(_, t)| {
            iso(&t.tframe[..3], &t.tframe[3..])
        });
    // The controller's world frame: the cell frame, or with `robot.frame: base` (the header's
    // frames line) its base frame, placed in the cell as the header says.
    let world = match module.frames.as_deref() {
        Some(f) if f.contains("written in the robot's base frame") => placed,
        _ => Isometry3::identity(),
    };
    let uframe_of = |w: &Option<String>| {
        world
            * module
                .wobjdata
                .iter()
                .find(|(n, _)| Some(n) == w.as_ref())
                .map_or(Isometry3::identity(), |(_, u)| iso(&u[..3], &u[3..]))
    };
    // A written target as a TCP pose in the cell frame, with its confdata.
    let pose_of = |to: &ToPoint, w: &Option<String>| -> Option<(Isometry3<f64>, [i32; 4])> {
        let r = module.robtarget(to.data())?;
        let mut p = iso(&r.pos_mm, &r.quat_wxyz);
        if let ToPoint::RelTool { offset_mm: d, .. } = to {
            p *= Translation3::new(d[0], d[1], d[2]);
        }
        Some((uframe_of(w) * p, r.conf))
    };
    let tcp = |q: &[f64; 6]| placed * robot.tool0(q) * tframe;
    let tool0_for = |p: &Isometry3<f64>| placed.inverse() * p * tframe.inverse();
    let clearance = cell.planner.clearance_mm;
    let mut q: Option<[f64; 6]> = None;
    let mut near = |a: &[f64; 6], b: &[f64; 6], what: &str, fail: &mut dyn FnMut(String)| {
        let (n, _) = scene.nearest_along(a, b);
        run.nearest_mm = run.nearest_mm.min(n.mm);
        // The dense check's 1 mm of motion between samples: the true minimum is at most 0.5 mm
        // below the samples'.
        if n.mm < clearance - 0.5 {
            fail(format!(
                "{what}: {} comes {:.3} mm from {}",
                n.link, n.mm, n.obstacle
            ));
        }
    };
    for (s, m) in module.motions() {
        let what = s.label();
        match m.kind {
            MoveKind::AbsJ => {
                let to = module.target(m.to.data());
                if let Some(from) = q {
                    near(&from, &to, &what, &mut fail);
                }
                q = Some(to);
            }
            MoveKind::J => {
                let Some((pose, conf)) = pose_of(&m.to, &m.wobj) else {
                    fail(format!("{what}: no robtarget"));
                    continue;
                };
                let prev = q.unwrap_or([0.0; 6]);
                let Some(to) = ik
                    .with_conf(&tool0_for(&pose), &conf)
                    .into_iter()
                    .map(|s| s.axes)
                    .min_by(|a, b| max_diff(a, &prev).total_cmp(&max_diff(b, &prev)))
                else {
                    fail(format!("{what}: no solution in range of confdata {conf:?}"));
                    continue;
                };
                if let Some(from) = q {
                    near(&from, &to, &what, &mut fail);
                }
                q = Some(to);
            }
            MoveKind::L | MoveKind::C => {
                run.process_moves += 1;
                let (Some(from), Some((end, conf))) = (q, pose_of(&m.to, &m.wobj)) else {
                    fail(format!("{what}: no start or no robtarget"));
                    continue;
                };
                let start = tcp(&from);
                let (pa, pc) = (
                    Point3::from(start.translation.vector),
                    Point3::from(end.translation.vector),
                );
                // The circle point: its position, its confdata and its arc fraction.
                let mut circle: Option<(Point3<f64>, [i32; 4], f64)> = None;
                let position: Box<dyn Fn(f64) -> Point3<f64>> = match &m.circle {
                    Some(c) => {
                        let Some((cp, cconf)) = pose_of(c, &m.wobj) else {
                            fail(format!("{what}: no circle point"));
                            continue;
                        };
                        let b = Point3::from(cp.translation.vector);
                        let f = arc_fraction(pa, b, pc);
                        circle = Some((b, cconf, f));
                        Box::new(arc(pa, b, pc))
                    }
                    None => Box::new(move |s| pa + s * (pc - pa)),
                };
                run.ends.push((start, end, circle.map(|c| c.0)));
                let length: f64 = (1..=1000)
                    .map(|k| {
                        (position(k as f64 / 1000.0) - position((k - 1) as f64 / 1000.0)).norm()
                    })
                    .sum();
                let turn = start.rotation.angle_to(&end.rotation).to_degrees();
                let n = ((length / STEP_MM).max(turn / STEP_DEG).ceil() as usize).max(1);
                let mut prev = from;
                for k in 1..=n {
                    let s = k as f64 / n as f64;
                    // The circle point's confdata: those of the joints at its arc fraction (the
                    // branch nearest the sample before).
                    if let Some((b, cconf, f)) = circle {
                        if f <= s {
                            let rot = start.rotation.slerp(&end.rotation, f);
                            let pose = Isometry3::from_parts(b.coords.into(), rot);
                            match ik.nearest(&tool0_for(&pose), &prev) {
                                Some(j) if conf_admits(&j, confdata(&robot, &j)[3], &cconf) => {
                                    run.circle_points += 1;
                                }
                                Some(j) => fail(format!(
                                    "{what}: the circle point's confdata {cconf:?}, the joints there {:?} ({j:?})",
                                    confdata(&robot, &j)
                                )),
                                None => fail(format!("{what}: no joints at the circle point")),
                            }
                            circle = None;
                        }
                    }
                    let rot = start.rotation.slerp(&end.rotation, s);
                    let pose = Isometry3::from_parts(position(s).coords.into(), rot);
                    let Some(next) = ik.nearest(&tool0_for(&pose), &prev) else {
                        fail(format!("{what}: out of reach at {:.1} %", 100.0 * s));
                        break;
                    };
                    run.samples += 1;
                    let jump = max_diff(&next, &prev);
                    if jump > JUMP_DEG {
                        fail(format!(
                            "{what}: axes jump {jump:.2} deg at {:.1} %",
                            100.0 * s
                        ));
                        break;
                    }
                    if robot.check_range6(&next).is_err() {
                        fail(format!(
                            "{what}: out of range at {:.1} %: {next:?}",
                            100.0 * s
                        ));
                        break;
                    }
                    if next[4].abs() < 1.0 {
                        fail(format!(
                            "{what}: axis 5 = {:.3} at {:.1} %",
                            next[4],
                            100.0 * s
                        ));
                    }
                    let off = (tcp(&next).translation.vector - pose.translation.vector).norm();
                    run.off_path_mm = run.off_path_mm.max(off);
                    near(&prev, &next, &what, &mut fail);
                    prev = next;
                }
                if !conf_admits(&prev, confdata(&robot, &prev)[3], &conf) {
                    fail(format!(
                        "{what}: ends in confdata {:?}, the target's is {conf:?}",
                        confdata(&robot, &prev)
                    ));
                }
                q = Some(prev);
            }
        }
    }
    // The header's smallest clearance: a lower bound of the dense samples (to its 0.1 mm).
    if let Some(h) = module.min_clearance_mm {
        if h > run.nearest_mm + 0.05 + 1e-9 {
            fail(format!(
                "header min clearance {h} mm, the dense samples come to {:.3} mm",
                run.nearest_mm
            ));
        }
    }
    // The robtargets are the cell's poses; the actions the cell's, in order.
    for p in &cell.points {
        if let Target::Robtarget { pose, .. } = &p.target {
            match module.robtarget(&format!("{}_rt", p.name)) {
                // In wobj0 with `robot.frame: base`: the cell's pose written in the base frame,
                // rounded (0.0005 mm a coordinate, 5e-10 a quaternion component).
                Some(r) if world != Isometry3::identity() && module.wobjdata.is_empty() => {
                    let w = world * iso(&r.pos_mm, &r.quat_wxyz);
                    let want = iso(&pose.pos_mm, &pose.quat_wxyz);
                    let mm = (w.translation.vector - want.translation.vector).norm();
                    let deg = w.rotation.angle_to(&want.rotation).to_degrees();
                    if mm > 1e-3 || deg > 1e-6 {
                        fail(format!(
                            "{}_rt is not the cell's pose: {mm:.6} mm, {deg:.2e} deg off",
                            p.name
                        ));
                    }
                }
                Some(r) => {
                    let off = (0..3)
                        .map(|k| (r.pos_mm[k] - pose.pos_mm[k]).abs())
                        .fold(0.0, f64::max);
                    let qoff = (0..4)
                        .map(|k| (r.quat_wxyz[k] - pose.quat_wxyz[k]).abs())
                        .fold(0.0, f64::max);
                    if off > 1e-9 || qoff > 1e-9 + 5e-10 {
                        fail(format!("{}_rt is not the cell's pose", p.name));
                    }
                }
                None => fail(format!("no robtarget {}_rt", p.name)),
            }
        }
    }
    let written: Vec<String> = module
        .body
        .iter()
        .filter_map(|s| match &s.ins {
            Instruction::Move(m) => {
                let arc = m.arc.as_ref()?.instruction.as_str();
                let value = match () {
                    _ if arc.ends_with("Start") => 1,
                    _ if arc.ends_with("End") => 0,
                    _ => return None,
                };
                signal.map(|signal| format!("SetDO {signal}, {value}"))
            }
            Instruction::Action(a) => Some(match a {
                Action::SetDo { signal, value } => format!("SetDO {signal}, {value}"),
                Action::PulseDo { signal } => format!("PulseDO {signal}"),
                Action::WaitDi { signal, value } => format!("WaitDI {signal}, {value}"),
                Action::WaitTime { s } => format!("WaitTime {s:.3}"),
                Action::GripLoad { load } => format!("GripLoad {load}"),
            }),
            _ => None,
        })
        .collect();
    let asked: Vec<String> = cell
        .points
        .iter()
        .flat_map(|p| &p.actions)
        .map(|a| action_text(cell, &a.kind))
        .collect();
    if written != asked {
        fail(format!("actions {written:?}, the cell asks {asked:?}"));
    }
    match failures.is_empty() {
        true => Ok(run),
        false => Err(failures),
    }
}

/// An action as RAPID writes it, from the cell (the tests' own wording of docs/rapid.md).
fn action_text(cell: &Cell, a: &super::library::ActionKind) -> String {
    use super::library::ActionKind as K;
    match a {
        K::SetDo { signal, value } => format!("SetDO {signal}, {}", u8::from(*value)),
        K::PulseDo { signal } => format!("PulseDO {signal}"),
        K::WaitDi { signal, value } => format!("WaitDI {signal}, {}", u8::from(*value)),
        K::WaitTime { time_s } => format!("WaitTime {time_s:.3}"),
        K::GripLoad { load } => format!(
            "GripLoad {}",
            load.and_then(|k| cell.loads.get(k))
                .map_or("load0", |l| l.name.as_str())
        ),
    }
}
