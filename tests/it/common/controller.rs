//! The routine run as a controller runs it, move by move from the joints where the previous
//! move ended, with the test suite's own inverse kinematics (`opw.rs`) and the robot's forward
//! kinematics (`Robot::tool0`), never the library's IK:
//!
//! - `MoveAbsJ`: joint interpolation to the jointtarget.
//! - `MoveJ`: joint interpolation to the robtarget's solution with its written confdata (ConfJ
//!   on): the pose is the robtarget (or `RelTool`'s displacement of it in its own tool frame) in
//!   the move's work object (its uframe in the world frame; wobj0 is the world), the TCP the
//!   move's tooldata's tframe on tool0, the world frame the cell frame with the robot base at
//!   the header's placement, or the robot base itself (`robot.frame: base`). A confdata that
//!   matches no solution in range fails (quadrants admitted within `QUADRANT_TOL_DEG`).
//! - `MoveL`, `MoveC`: the TCP path from the current TCP pose (`paths.rs`; a circle point's
//!   orientation must be the path's at its arc fraction), followed by the IK
//!   branch that continues from the current joints (`follow.rs`: jumps, ranges and the wrist
//!   singularity fail, located by progress and TCP position), ending in the target's written
//!   confdata (ConfL on). Every sample's TCP (forward kinematics of its joints) must lie on the
//!   path within [`TCP_PATH_MM`] and [`TCP_PATH_DEG`], and a `MoveJ`'s end on its target.
//!
//! `ConfJ \On` must be written before the first `MoveJ`, `ConfL \On` before the first `MoveL` or
//! `MoveC` (the contract writes both), and neither turned off. The first motion instruction
//! reaches its target from wherever the robot is (a `MoveL` or `MoveC` cannot be first). The
//! result, [`Run`], holds each move's joint path for the clearance check (`dense.rs`).

use super::data::iso;
use super::follow::{follow, Sample};
use super::library::Robot;
use super::module::Module;
use super::opw::{conf_admits, max_diff, Ik};
use super::paths::TcpPath;
use super::reach::Reach;
use super::routine::{Instruction, MoveKind, ToPoint};
use super::tcp::confdata;
use nalgebra::{Isometry3, Point3, Translation3, Vector3};

/// A sample's TCP lies this close to the programmed path (mm, deg).
pub const TCP_PATH_MM: f64 = 0.01;
pub const TCP_PATH_DEG: f64 = 0.001;
/// A `MoveC` circle point's orientation lies this close to the path's at its arc fraction, deg
/// (it only tells the way the orientation turns; a start reached by rounded joints moves it).
pub const CIRCLE_POINT_DEG: f64 = 0.01;

/// What the controller needs besides the module.
pub struct Setup<'a> {
    pub robot: &'a Robot,
    /// The inverse kinematics, or why this robot has none here (a module of `MoveAbsJ` alone
    /// needs none).
    pub ik: Result<Ik<'a>, String>,
    /// The robot base in the controller's world frame.
    pub world_from_base: Isometry3<f64>,
    /// How far points move per radian of each joint, and the most any point may move between
    /// samples, mm (`reach.rs`).
    pub reach: Reach,
    pub step_mm: f64,
}

/// How a move's joints go.
#[derive(Clone, Debug)]
pub enum JointPath {
    /// Straight joint interpolation (`MoveAbsJ`, `MoveJ`).
    Straight,
    /// The followed branch of a `MoveL` or `MoveC`, sampled as `follow.rs` says.
    Followed {
        samples: Vec<Sample>,
        /// The TCP path in the robot base frame.
        tcp: Box<TcpPath>,
        /// The move's work object frame in the robot base frame, and its name, for messages.
        wobj_in_base: Isometry3<f64>,
        wobj: String,
    },
}

/// One move as the controller runs it.
#[derive(Clone, Debug)]
pub struct Moved {
    /// Index of its statement in `Module::body`.
    pub index: usize,
    /// The statement as messages name it.
    pub label: String,
    /// Its target as written (`L2_rt`, `RelTool(L2_rt,0,0,-40)`, a jointtarget's name).
    pub target: String,
    pub kind: MoveKind,
    /// Where it starts (`None`: the first, from wherever the robot is).
    pub from: Option<[f64; 6]>,
    pub to: [f64; 6],
    pub zone: String,
    pub path: JointPath,
}

impl Moved {
    /// Where the TCP is at progress `s` of a followed move, in its work object (mm), for
    /// messages: `" (TCP [x, y, z] mm in wobj)"`, or empty for a joint move.
    pub fn tcp_at(&self, s: f64) -> String {
        match &self.path {
            JointPath::Followed {
                tcp,
                wobj_in_base,
                wobj,
                ..
            } => tcp_in(tcp, wobj_in_base, wobj, s),
            JointPath::Straight => String::new(),
        }
    }
}

/// `" (TCP [x, y, z] mm in wobj)"`: the TCP of `tcp` at progress `s` in the work object `wobj`
/// (its frame `wobj_in_base` in the robot base frame).
fn tcp_in(tcp: &TcpPath, wobj_in_base: &Isometry3<f64>, wobj: &str, s: f64) -> String {
    let v = (wobj_in_base.inverse() * tcp.at(s)).translation.vector;
    format!(" (TCP [{:.2}, {:.2}, {:.2}] mm in {wobj})", v.x, v.y, v.z)
}

/// The routine as the controller runs it, and what following it measured.
#[derive(Clone, Debug, Default)]
pub struct Run {
    pub moves: Vec<Moved>,
    /// Moves followed along a TCP path, and their samples.
    pub followed: usize,
    pub followed_samples: usize,
    /// The largest distance of a sample's TCP from its path, or of a MoveJ's end from its
    /// target (mm, deg).
    pub tcp_worst_mm: f64,
    pub tcp_worst_deg: f64,
    /// The smallest |axis 5| along the followed moves, deg (infinite without any).
    pub wrist_least_deg: f64,
}

/// The tframe of tooldata `tool` (tool0: the flange).
fn tframe(module: &Module, tool: &str) -> Result<Isometry3<f64>, String> {
    if tool == "tool0" {
        return Ok(Isometry3::identity());
    }
    match module.tooldata.iter().find(|(n, _)| n == tool) {
        Some((_, d)) => {
            let t = d.tframe;
            Ok(iso([t[0], t[1], t[2]], [t[3], t[4], t[5], t[6]]))
        }
        None => Err(format!(
            "tooldata '{tool}' is not declared in the module: its TCP is unknown here"
        )),
    }
}

/// The frame of work object `wobj` in the world frame (wobj0, or none: the world itself).
fn uframe(module: &Module, wobj: Option<&str>) -> Isometry3<f64> {
    match wobj.and_then(|w| module.wobjdata.iter().find(|(n, _)| n == w)) {
        Some((_, u)) => iso([u[0], u[1], u[2]], [u[3], u[4], u[5], u[6]]),
        None => Isometry3::identity(),
    }
}

/// A robtarget argument's confdata and pose in its work object.
fn target(module: &Module, to: &ToPoint) -> ([i32; 4], Isometry3<f64>) {
    let r = module
        .robtarget(to.data())
        .expect("resolved when the module was read");
    let pose = iso(r.pos_mm, r.quat_wxyz);
    let pose = match to {
        ToPoint::Name(_) => pose,
        ToPoint::RelTool { offset_mm: d, .. } => {
            pose * Translation3::from(Vector3::new(d[0], d[1], d[2]))
        }
    };
    (r.conf, pose)
}

/// Why the circle point `circle` (its pose in the robot base frame) of the arc `tcp` is not as
/// the module's contract writes it: its orientation the path's at its arc fraction (the
/// controller reads it to tell which way the orientation turns), within
/// [`CIRCLE_POINT_DEG`]; `None` when it is.
fn circle_point_fault(tcp: &TcpPath, circle: &Isometry3<f64>) -> Option<String> {
    let s = tcp.progress_at(&Point3::from(circle.translation.vector))?;
    let off = tcp.at(s).rotation.angle_to(&circle.rotation).to_degrees();
    (off > CIRCLE_POINT_DEG).then(|| {
        format!(
            "the circle point's orientation lies {off:.4} deg from the path's at its arc fraction {s:.4} (at most {CIRCLE_POINT_DEG} deg)"
        )
    })
}

/// Runs every instruction of `module` (module doc): the moves run, and every failure. A move the
/// controller cannot complete ends the run there.
pub fn run(module: &Module, setup: &Setup) -> (Run, Vec<String>) {
    let robot = setup.robot;
    let base_from_world = setup.world_from_base.inverse();
    let mut failures = Vec::new();
    let mut out = Run {
        wrist_least_deg: f64::INFINITY,
        ..Run::default()
    };
    let (mut conf_j, mut conf_l) = (false, false);
    let mut at: Option<[f64; 6]> = None;
    for (index, st) in module.body.iter().enumerate() {
        let label = st.label();
        let m = match &st.ins {
            Instruction::ConfJ(on) | Instruction::ConfL(on) if !on => {
                failures.push(format!(
                    "{label}: configuration monitoring off; this check (and the contract) needs it on"
                ));
                continue;
            }
            Instruction::ConfJ(_) => {
                conf_j = true;
                continue;
            }
            Instruction::ConfL(_) => {
                conf_l = true;
                continue;
            }
            Instruction::Action(_) => continue,
            Instruction::Move(m) => m,
        };
        let mut fail = |why: String| failures.push(format!("{label}: {why}"));
        // A move to a robtarget: this check's IK and the move's TCP on tool0.
        let cartesian = match m.kind {
            MoveKind::AbsJ => None,
            _ => {
                let ik = match &setup.ik {
                    Ok(ik) => ik,
                    Err(e) => {
                        fail(format!(
                            "this check's inverse kinematics cannot solve the robot: {e}"
                        ));
                        break;
                    }
                };
                match tframe(module, &m.tool) {
                    Ok(t) => Some((ik, t)),
                    Err(e) => {
                        fail(e);
                        break;
                    }
                }
            }
        };
        let (to, path) = match (m.kind, cartesian) {
            (MoveKind::AbsJ, _) => (module.target(m.to.data()), JointPath::Straight),
            (MoveKind::J, Some((ik, tframe))) => {
                if !conf_j {
                    fail("MoveJ before ConfJ \\On".into());
                }
                let (conf, pose) = target(module, &m.to);
                let tcp = base_from_world * uframe(module, m.wobj.as_deref()) * pose;
                let tool0 = tcp * tframe.inverse();
                let mut sols = ik.with_conf(&tool0, &conf);
                let near = at.unwrap_or([0.0; 6]);
                sols.sort_by(|a, b| max_diff(&a.axes, &near).total_cmp(&max_diff(&b.axes, &near)));
                let Some(end) = sols.first().map(|s| s.axes) else {
                    let have: Vec<[i32; 4]> = ik.in_range(&tool0).iter().map(|s| s.conf).collect();
                    fail(format!(
                        "confdata {conf:?} of {} matches no solution in range (the solutions in range have {have:?})",
                        m.to
                    ));
                    break;
                };
                let back = robot.tool0(&end) * tframe;
                out.tcp_worst_mm = out
                    .tcp_worst_mm
                    .max((back.translation.vector - tcp.translation.vector).norm());
                out.tcp_worst_deg = out
                    .tcp_worst_deg
                    .max(back.rotation.angle_to(&tcp.rotation).to_degrees());
                (end, JointPath::Straight)
            }
            (MoveKind::L | MoveKind::C, Some((ik, tframe))) => {
                if !conf_l {
                    fail(format!("{} before ConfL \\On", m.kind.name()));
                }
                let Some(start) = at else {
                    fail(format!(
                        "{} as the first motion: the TCP path has no start",
                        m.kind.name()
                    ));
                    break;
                };
                let wobj_in_base = base_from_world * uframe(module, m.wobj.as_deref());
                let (conf, pose) = target(module, &m.to);
                let from = robot.tool0(&start) * tframe;
                let to = wobj_in_base * pose;
                let circle = m
                    .circle
                    .as_ref()
                    .map(|c| wobj_in_base * target(module, c).1);
                let tcp = match &circle {
                    None => TcpPath::line(&from, &to),
                    Some(c) => TcpPath::arc(&from, &Point3::from(c.translation.vector), &to),
                };
                let tcp = match tcp {
                    Ok(t) => t,
                    Err(e) => {
                        fail(e);
                        break;
                    }
                };
                if let Some(e) = circle.as_ref().and_then(|c| circle_point_fault(&tcp, c)) {
                    fail(e);
                }
                let tool0_at = |s: f64| tcp.at(s) * tframe.inverse();
                let samples = match follow(ik, &tool0_at, start, &setup.reach, setup.step_mm) {
                    Ok(samples) => samples,
                    Err(stop) => {
                        let wobj = m.wobj.as_deref().unwrap_or("wobj0");
                        fail(format!(
                            "at {:.2} %{}: {}",
                            100.0 * stop.s,
                            tcp_in(&tcp, &wobj_in_base, wobj, stop.s),
                            stop.why
                        ));
                        break;
                    }
                };
                for smp in &samples {
                    let fk = robot.tool0(&smp.axes) * tframe;
                    let want = tcp.at(smp.s);
                    out.tcp_worst_mm = out
                        .tcp_worst_mm
                        .max((fk.translation.vector - want.translation.vector).norm());
                    out.tcp_worst_deg = out
                        .tcp_worst_deg
                        .max(fk.rotation.angle_to(&want.rotation).to_degrees());
                    out.wrist_least_deg = out.wrist_least_deg.min(smp.axes[4].abs());
                }
                let end = samples.last().map_or(start, |s| s.axes);
                let reached = confdata(robot, &end);
                if !conf_admits(&end, reached[3], &conf) {
                    fail(format!(
                        "the branch followed from the start ends at {end:?}, confdata {reached:?}; {} says {conf:?} (ConfL would stop the controller)",
                        m.to
                    ));
                }
                out.followed += 1;
                out.followed_samples += samples.len();
                (
                    end,
                    JointPath::Followed {
                        samples,
                        tcp: Box::new(tcp),
                        wobj_in_base,
                        wobj: m.wobj.clone().unwrap_or_else(|| "wobj0".into()),
                    },
                )
            }
            (_, None) => unreachable!("a move to a robtarget has its IK and tframe"),
        };
        if let Err(e) = robot.check_range6(&to) {
            fail(format!("ends out of range: {e}"));
        }
        out.moves.push(Moved {
            index,
            label,
            target: m.to.to_string(),
            kind: m.kind,
            from: at,
            to,
            zone: m.zone.clone(),
            path,
        });
        at = Some(to);
    }
    if out.tcp_worst_mm > TCP_PATH_MM || out.tcp_worst_deg > TCP_PATH_DEG {
        failures.push(format!(
            "a TCP by forward kinematics lies {:.5} mm and {:.5} deg from where the controller puts it (at most {TCP_PATH_MM} mm, {TCP_PATH_DEG} deg)",
            out.tcp_worst_mm, out.tcp_worst_deg
        ));
    }
    (out, failures)
}
