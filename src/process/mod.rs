//! The follow stage (beyond the paper; long: the stops, how each is reached and their splice
//! into one plan are one stage): the cell's process moves resolved, followed and proven
//! before the air route is planned between them. [`follow`]: `Cell` + `Placed` + the collision
//! model -> [`Followed`], the *stops* in the routine's order and how each is reached; [`splice`]
//! puts the refined air plans and the process moves together into the one `Plan` the module
//! writes.
//!
//! **Stops.** A stop is where an air leg starts or ends: an entry's target, its approach pose
//! (`RelTool(p, 0, 0, -D)`, reached by the planned route and left by the approach line into the
//! point) and its retract pose (reached by the retract line after the actions). Between two
//! consecutive stops the robot moves either through the air (the plan stage's route, proven
//! as today) or by a process move: the approach line, a `move: linear` line, a `move:
//! circular` arc, the retract line.
//!
//! **A process move is checked, not planned.** Its TCP path (`geometry::path`: the line, or
//! the arc through the cell's `via`; the orientation turning evenly) runs from the controller's
//! TCP at the stop before (the forward kinematics of its joints) to the target's pose as
//! written. The joints follow the inverse kinematics that continues from the stop before
//! (`robot::ik::follow`), ending in the confdata written for the end (a `RelTool` pose inherits
//! its point's); the path is proven to keep the clearance for every link and tool shape
//! between the samples too (`CollisionModel::prove_path`) and timed by `timing::process`. A
//! path that leaves the reach or an axis range, jumps, passes the wrist singularity, ends in
//! another configuration or comes too close to an obstacle is refused ([`ProcessError`], exit
//! 3) at the point's line, naming the move, how far along it and why.
//!
//! **The joints at a stop** are those the controller reaches there: at an entry its placed
//! joints (a robtarget's the inverse of its robtarget as written, in its confdata; the end of
//! a followed move must agree with them); at an approach pose the inverse of the pose in the
//! point's confdata (what `MoveJ RelTool(p, 0, 0, -D)` reaches with ConfJ on); at a retract
//! pose the followed line's end. An approach pose with no solution in the point's
//! configuration is reached in the configuration the approach line, run backwards from the
//! point, reaches it in, and a retract line that ends in another configuration ends there: such
//! a pose is written as its own robtarget (`OwnTarget`, `<point>_app` / `<point>_ret`: the pose
//! moved back along the tool's z axis, its position rounded as written, in that configuration),
//! and its joints are the exact inverse of those written numbers.
//!
//! **As written.** Every pose is built from the numbers the module writes, in the frame it
//! writes them in (`Placement::robtarget_data`, `Placement::data_frame`: the cell frame, or
//! with `robot.frame: base` the robot's base frame, a wobj0 robtarget rounded there): the
//! target, its `RelTool` poses, the circle point's position. So the path proven is the one the
//! controller computes from the module. The circle point is written with the orientation at its
//! arc fraction and the confdata of the followed joints there.
//!
//! **Zones.** A corner next to a process move (the point reached or left by one) is not proven
//! yet: the point is reached `fine`, and a zone asked there is warned about.

mod poses;

use crate::cell::{Arrival, Cell, Frame, Loc, Point, RobotFrame, Target};
use crate::collision::{CollisionModel, PathBlocked, PathClearance};
use crate::geometry::path::{CartesianPath, PathError};
use crate::place::{MoveMotion, Origin, Placed, PlacedPoint, Placement};
use crate::plan::motion::MoveEstimate;
use crate::plan::{Leg, Route, Waypoint, WaypointKind};
use crate::rapid_data::predefined_speed;
use crate::refine::{Move, MoveKind, PaperFigure, Plan};
use crate::robot::ik::follow::{follow as follow_path, FollowError, FollowedPath, TcpFrames};
use crate::robot::ik::six::{ConfData, SixAxisError, SixAxisIk};
use crate::robot::{Axes6, Robot};
use crate::timing::process::{process_move_time, ProcessTime};
use nalgebra::{Isometry3, Point3};
use poses::{approach_pose, retract_line, Written};
use std::ops::Range;

/// How far the end of a followed move may lie from the joints placed for its target, deg: the
/// same inverse in the same configuration, to the solver's rounding.
pub const END_AGREEMENT_DEG: f64 = 1e-6;

/// What a stop is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopKind {
    /// Entry `i`'s target.
    Entry(usize),
    /// Entry `i`'s approach pose.
    Approach(usize),
    /// Entry `i`'s retract pose.
    Retract(usize),
    /// The first entry's target again, at the end of the leg that closes the cycle
    /// (`motion.cycle`); `n` is the number of entries (the leg is the `n`th).
    Closing(usize),
}

impl StopKind {
    /// The entry it belongs to (the closing stop: the first).
    pub fn entry(self) -> usize {
        match self {
            StopKind::Entry(i) | StopKind::Approach(i) | StopKind::Retract(i) => i,
            StopKind::Closing(_) => 0,
        }
    }

    /// The leg that ends at it is the `leg_end() - 1`th (0-based; the closing leg after the
    /// last entry's).
    pub fn leg_end(self) -> usize {
        match self {
            StopKind::Closing(n) => n,
            other => other.entry(),
        }
    }
}

/// One stop: what it is, the joints the controller has there and the motion of the move into
/// it.
#[derive(Clone, Debug, PartialEq)]
pub struct Stop {
    pub kind: StopKind,
    /// Controller values, deg (module docs, "The joints at a stop").
    pub joints_deg: Axes6,
    pub motion: MoveMotion,
}

/// A followed and proven process move.
#[derive(Clone, Debug)]
pub struct ProcessMove {
    pub kind: MoveKind,
    pub followed: FollowedPath,
    pub proof: PathClearance,
    pub time: ProcessTime,
}

/// How a stop is reached from the one before.
#[derive(Clone, Debug)]
pub enum Reach {
    /// Through the air: the plan stage's route (the first stop: from wherever the robot is).
    Air,
    /// By a process move.
    Process(Box<ProcessMove>),
}

/// The follow stage's result: the stops in order and how each is reached (`into[k]` for
/// `stops[k]`; `into[0]` is [`Reach::Air`]), and the warnings for stderr.
#[derive(Clone, Debug)]
pub struct Followed {
    pub stops: Vec<Stop>,
    pub into: Vec<Reach>,
    pub warnings: Vec<String>,
}

impl Followed {
    /// The runs of stops joined by air legs, in order: each a range of at least two stops
    /// (a stop reached and left by process moves belongs to none).
    pub fn air_runs(&self) -> Vec<Range<usize>> {
        let mut runs = Vec::new();
        let mut start = 0;
        for k in 1..=self.stops.len() {
            let air = k < self.stops.len() && matches!(self.into[k], Reach::Air);
            if !air {
                if k - start >= 2 {
                    runs.push(start..k);
                }
                start = k;
            }
        }
        runs
    }

    /// The stops of `run` as the plan stage's points (the same points as the cell's when every
    /// stop is an entry).
    pub fn points_of(&self, run: &Range<usize>, placed: &Placed) -> Vec<PlacedPoint> {
        self.stops[run.clone()]
            .iter()
            .map(|s| {
                let i = s.kind.entry();
                match (s.kind, placed.points.get(i)) {
                    (StopKind::Entry(_) | StopKind::Closing(_), Some(p)) => PlacedPoint {
                        motion: s.motion.clone(),
                        ..p.clone()
                    },
                    (kind, p) => PlacedPoint {
                        name: match (kind, p) {
                            (StopKind::Approach(_), Some(p)) => format!("{} (approach)", p.name),
                            (_, Some(p)) => format!("{} (retract)", p.name),
                            _ => String::new(),
                        },
                        joints_deg: s.joints_deg,
                        loc: p.map(|p| p.loc).unwrap_or_default(),
                        origin: crate::place::Origin::Joints,
                        motion: s.motion.clone(),
                    },
                }
            })
            .collect()
    }

    /// The entry a stop of `run` (run-local index) belongs to.
    pub fn entry_of(&self, run: &Range<usize>, k: usize) -> usize {
        self.stops.get(run.start + k).map_or(0, |s| s.kind.entry())
    }

    /// The leg (0-based) that ends at stop `k` of `run` (run-local index): the vias' numbers.
    fn leg_into(&self, run: &Range<usize>, k: usize) -> usize {
        let end = self
            .stops
            .get(run.start + k)
            .map_or(0, |s| s.kind.leg_end());
        end.saturating_sub(1)
    }
}

/// What a process move is called in messages.
fn move_name(kind: &MoveKind) -> &'static str {
    match kind {
        MoveKind::Joint => "the joint move",
        MoveKind::Linear => "the linear move (MoveL)",
        MoveKind::Circular { .. } => "the circular move (MoveC)",
        MoveKind::Approach { .. } => "the approach line (MoveL)",
        MoveKind::Retract { .. } => "the retract line (MoveL)",
    }
}

/// Why a process move cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum ProcessError {
    /// The path cannot be made (a collinear or too long arc, a half turn of the tool).
    #[error("{label}: {what}: {source}")]
    Path {
        label: String,
        what: &'static str,
        source: PathError,
        loc: Loc,
    },
    /// The joints cannot follow the path.
    #[error("{label}: {what}: {source}")]
    Follow {
        label: String,
        what: &'static str,
        /// Boxed: it is large and errors travel in `Result`s.
        source: Box<FollowError>,
        loc: Loc,
    },
    /// The path comes too close to an obstacle.
    #[error("{label}: {what}: {source}")]
    Blocked {
        label: String,
        what: &'static str,
        /// Boxed: it is large and errors travel in `Result`s.
        source: Box<PathBlocked>,
        loc: Loc,
    },
    /// An approach or retract pose has no solution in its point's configuration.
    #[error("{label}: {what}: {why}")]
    Pose {
        label: String,
        what: &'static str,
        why: String,
        loc: Loc,
    },
}

impl ProcessError {
    /// Where in the cell file it points.
    pub fn loc(&self) -> Loc {
        match self {
            ProcessError::Path { loc, .. }
            | ProcessError::Follow { loc, .. }
            | ProcessError::Blocked { loc, .. }
            | ProcessError::Pose { loc, .. } => *loc,
        }
    }

    /// The help line.
    pub fn help(&self) -> &'static str {
        match self {
            ProcessError::Path { .. } => "give a `via` strictly between the ends, off their line, on an arc of at most 240 deg, and keep the tool's turn between the ends under 180 deg",
            ProcessError::Follow { source, .. } if matches!(**source, FollowError::WristSingularity { .. }) => "tilt the tool's orientation at the ends so that axis 5 stays away from 0 along the path, or split the move with a point in between",
            ProcessError::Follow { source, .. } if matches!(**source, FollowError::EndConf { .. }) => "give the end point the confdata the path reaches, or none (then the path's own is written)",
            ProcessError::Follow { .. } => "move the path's ends (or the robot's base) so the arm reaches the whole path in one configuration within its axis ranges",
            ProcessError::Blocked { .. } => "move the path or the obstacle, or lower planner.clearance; `gen-rapid --html FILE` shows the cell",
            ProcessError::Pose { .. } => "shorten the approach or retract, or turn the point's tool orientation so axes 4 and 6 stay in their quadrants along it",
        }
    }
}

/// The robot, tool and work object a cell's process moves run with, and the frame the module
/// writes their robtargets in.
struct Setting<'a> {
    ik: SixAxisIk,
    robot: &'a Robot,
    frames: TcpFrames,
    placement: Placement,
    /// `robot.frame`: the frame the module writes the uframe and wobj0 robtargets in.
    frame: RobotFrame,
    /// The work objects' user frames as the cell gives them, in the cell's order.
    uframes: Vec<Frame>,
}

impl Setting<'_> {
    /// The controller's TCP at `joints`, cell frame.
    fn tcp(&self, joints: &Axes6) -> Isometry3<f64> {
        self.frames.cell_from_robot * self.robot.tool0(joints) * self.frames.tframe
    }

    /// The user frame of work object `wobj` as the cell gives it (`Point::wobj`; `None`:
    /// wobj0).
    fn uframe(&self, wobj: Option<usize>) -> Option<&Frame> {
        wobj.and_then(|i| self.uframes.get(i))
    }

    /// The numbers the module writes for a robtarget pose of the cell in work object `wobj`
    /// (`Placement::robtarget_data`).
    fn data(&self, pose: &Frame, wobj: Option<usize>) -> Frame {
        self.placement
            .robtarget_data(self.frame, self.uframe(wobj), pose)
    }

    /// The cell pose of robtarget numbers as written in work object `wobj`: what the
    /// controller runs to.
    fn in_cell(&self, data: &Frame, wobj: Option<usize>) -> Isometry3<f64> {
        self.placement.data_frame(self.frame, self.uframe(wobj)) * data.isometry()
    }

    /// Pose `tcp` (cell frame) as robtarget numbers written in the module's frame and work
    /// object `wobj`, its quaternion of the sign nearest `like`'s (the point it belongs to).
    fn written(&self, tcp: &Isometry3<f64>, like: &Frame, wobj: Option<usize>) -> Frame {
        let d = self
            .placement
            .data_frame(self.frame, self.uframe(wobj))
            .inverse()
            * tcp;
        let q = d.rotation.into_inner();
        let quat = [q.w, q.i, q.j, q.k];
        let dot: f64 = quat.iter().zip(like.quat_wxyz).map(|(a, b)| a * b).sum();
        let sign = if dot < 0.0 { -1.0 } else { 1.0 };
        Frame {
            pos_mm: [d.translation.x, d.translation.y, d.translation.z],
            quat_wxyz: quat.map(|v| sign * v),
        }
        .written()
    }

    /// The joints `MoveJ` reaches for TCP pose `tcp` (cell frame) in configuration `conf`: the
    /// in-range solution admitted for it nearest `near`.
    fn joints_in(&self, tcp: &Isometry3<f64>, conf: ConfData, near: &Axes6) -> Option<Axes6> {
        let tool0 = self.frames.cell_from_robot.inverse() * tcp * self.frames.tframe.inverse();
        let solutions = self.ik.solve(&tool0, Some(near)).ok()?;
        solutions
            .into_iter()
            .map(|s| s.axes_deg)
            .filter(|a| self.ik.conf_admits(a, conf))
            .min_by(|a, b| max_diff(a, near).total_cmp(&max_diff(b, near)))
    }
}

fn max_diff(a: &Axes6, b: &Axes6) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The follow stage (module docs): the stops of `cell` placed as `placed`, each process move
/// followed and proven on `model`. A cell without process keys gives its entries as stops, all
/// reached through the air.
pub fn follow(
    cell: &Cell,
    robot: &Robot,
    placed: &Placed,
    model: &CollisionModel,
) -> Result<Followed, ProcessError> {
    let mut out = Followed {
        stops: Vec::new(),
        into: Vec::new(),
        warnings: Vec::new(),
    };
    let uses_process = cell
        .points
        .iter()
        .any(|p| p.arrival.is_process() || p.approach_mm.is_some() || p.retract_mm.is_some());
    let setting = match uses_process {
        true => Some(setting_of(cell, robot, placed)?),
        false => None,
    };
    for (i, (p, placed_point)) in cell.points.iter().zip(&placed.points).enumerate() {
        let motion = placed_point.motion.clone();
        let fine = MoveMotion {
            speed: motion.speed.clone(),
            zone: "fine".into(),
        };
        // A point reached through the air keeps its zone unless it stops there or the move out
        // of it is a process move (its corner is not proven: `fine`, with a warning).
        let before_process = cell
            .points
            .get(i + 1)
            .is_some_and(|q| q.arrival.is_process());
        if before_process && !p.arrival.is_process() {
            warn_zone(&mut out.warnings, p, &motion);
        }
        let air_motion = match p.stops() || before_process {
            true => fine.clone(),
            false => motion.clone(),
        };
        let (Some(s), Target::Robtarget { pose, .. }, Origin::Robtarget { conf, .. }) =
            (&setting, &p.target, &placed_point.origin)
        else {
            out.stops.push(Stop {
                kind: StopKind::Entry(i),
                joints_deg: placed_point.joints_deg,
                motion: air_motion,
            });
            out.into.push(Reach::Air);
            continue;
        };
        let point = Written {
            data: s.data(pose, p.wobj),
            conf: *conf,
        };
        let target = s.in_cell(&point.data, p.wobj);
        let at = placed_point.joints_deg;
        // Into the point: an approach line, a process move, or the air.
        if let Some(d) = p.approach_mm {
            let (app, app_joints, own) = approach_pose(s, p, &point, &target, &at, d)?;
            out.stops.push(Stop {
                kind: StopKind::Approach(i),
                joints_deg: app_joints,
                motion: fine.clone(),
            });
            out.into.push(Reach::Air);
            let m = process_move(
                s,
                model,
                p,
                &motion.speed,
                MoveKind::Approach { dz_mm: d, own },
                &app,
                &target,
                None,
                &app_joints,
                Some(point.conf),
            )?;
            agree(p, &m, &at, p.approach_loc)?;
            warn_speed(s, &mut out.warnings, p, &m, &motion.speed);
            out.stops.push(Stop {
                kind: StopKind::Entry(i),
                joints_deg: at,
                motion: fine.clone(),
            });
            out.into.push(Reach::Process(Box::new(m)));
        } else if let (true, Some(before)) = (p.arrival.is_process(), out.stops.last()) {
            let from = before.joints_deg;
            let start = s.tcp(&from);
            let via = match p.arrival {
                // The circle point's position as written, in the cell frame.
                Arrival::Circular { via_mm, .. } => {
                    let given = Frame {
                        pos_mm: via_mm,
                        quat_wxyz: Frame::IDENTITY.quat_wxyz,
                    };
                    let written = Frame {
                        quat_wxyz: Frame::IDENTITY.quat_wxyz,
                        ..s.data(&given, p.wobj)
                    };
                    Some((
                        written,
                        s.in_cell(&written, p.wobj).translation.vector.into(),
                    ))
                }
                _ => None,
            };
            let m = process_move(
                s,
                model,
                p,
                &motion.speed,
                MoveKind::Linear,
                &start,
                &target,
                via.map(|(w, cell)| (w.pos_mm, cell, point.data)),
                &from,
                Some(point.conf),
            )?;
            agree(p, &m, &at, p.arrival_loc)?;
            warn_speed(s, &mut out.warnings, p, &m, &motion.speed);
            // A corner next to a process move is not proven yet: `fine`.
            warn_zone(&mut out.warnings, p, &motion);
            out.stops.push(Stop {
                kind: StopKind::Entry(i),
                joints_deg: at,
                motion: fine.clone(),
            });
            out.into.push(Reach::Process(Box::new(m)));
        } else {
            out.stops.push(Stop {
                kind: StopKind::Entry(i),
                joints_deg: at,
                motion: air_motion,
            });
            out.into.push(Reach::Air);
        }
        // Out of the point: the retract line, after the actions.
        if let Some(d) = p.retract_mm {
            let m = retract_line(s, model, p, &motion.speed, &point, &target, &at, d)?;
            warn_speed(s, &mut out.warnings, p, &m, &motion.speed);
            out.stops.push(Stop {
                kind: StopKind::Retract(i),
                joints_deg: m.followed.end_joints(),
                motion: fine.clone(),
            });
            out.into.push(Reach::Process(Box::new(m)));
        }
    }
    // The leg that closes the cycle: through the air at `motion.speed`, ending `fine` at the
    // first entry's target (none of its zone or actions).
    if let (true, Some(first)) = (cell.closing_leg(), placed.points.first()) {
        out.stops.push(Stop {
            kind: StopKind::Closing(cell.points.len()),
            joints_deg: first.joints_deg,
            motion: MoveMotion {
                speed: cell.motion.speed.clone(),
                zone: "fine".into(),
            },
        });
        out.into.push(Reach::Air);
    }
    Ok(out)
}

/// The IK, frames and work object of a cell with process moves.
fn setting_of<'a>(
    cell: &Cell,
    robot: &'a Robot,
    placed: &Placed,
) -> Result<Setting<'a>, ProcessError> {
    let ik = SixAxisIk::from_robot(robot).map_err(|e: SixAxisError| ProcessError::Pose {
        label: "robot.urdf".into(),
        what: "the six-axis inverse kinematics",
        why: e.to_string(),
        loc: cell.robot.urdf_loc,
    })?;
    Ok(Setting {
        ik,
        robot,
        frames: TcpFrames {
            cell_from_robot: placed.placement.cell_from_robot(),
            tframe: cell
                .tool
                .as_ref()
                .map_or(Frame::IDENTITY, |t| t.tframe)
                .written()
                .isometry(),
        },
        placement: placed.placement,
        frame: cell.robot.frame,
        uframes: cell.wobjs.iter().map(|w| w.uframe).collect(),
    })
}

/// The circle point of an arc: its position as written (the module's frame for the point's
/// robtargets), the same in the cell frame, and the point's robtarget numbers (whose
/// quaternion's sign the circle point's takes).
type CirclePoint = ([f64; 3], Point3<f64>, Frame);

/// Follows, proves and times one process move of point `p` from `start` (joints `from`) to
/// `end` (through `via` for an arc), ending in `conf` if given, timed at `speed` (the speeddata
/// it is written with: the point's own, else `motion.speed`).
#[allow(clippy::too_many_arguments)]
fn process_move(
    s: &Setting,
    model: &CollisionModel,
    p: &Point,
    speed: &str,
    kind: MoveKind,
    start: &Isometry3<f64>,
    end: &Isometry3<f64>,
    via: Option<CirclePoint>,
    from: &Axes6,
    conf: Option<ConfData>,
) -> Result<ProcessMove, ProcessError> {
    let loc = match (&kind, via, p.arrival) {
        (MoveKind::Approach { .. }, _, _) => p.approach_loc,
        (MoveKind::Retract { .. }, _, _) => p.retract_loc,
        (_, Some(_), Arrival::Circular { via_loc, .. }) => via_loc,
        _ => p.arrival_loc,
    };
    let label = p.label();
    let path = match via {
        Some((_, v, _)) => CartesianPath::arc(start, &v, end),
        None => CartesianPath::line(start, end),
    };
    // Named as a circular move in messages before it is followed.
    let what = match via {
        Some(_) => "the circular move (MoveC)",
        None => move_name(&kind),
    };
    let path = path.map_err(|source| ProcessError::Path {
        label: label.clone(),
        what,
        source,
        loc,
    })?;
    let followed = follow_path(&s.ik, &s.frames, &path, from, conf).map_err(|source| {
        ProcessError::Follow {
            label: label.clone(),
            what,
            source: Box::new(source),
            loc,
        }
    })?;
    let kind = match (via, path.cir_point(), path.via_fraction()) {
        (Some((pos_mm, _, like)), Some(cir), Some(f)) => {
            // The circle point as written: the via's position as written, the orientation at
            // its arc fraction; its confdata those of the followed joints there.
            let via = Frame {
                pos_mm,
                ..s.written(&cir, &like, p.wobj)
            };
            let via_conf =
                s.ik.conf(
                    &joints_at(s, &followed, f).ok_or_else(|| ProcessError::Pose {
                        label: label.clone(),
                        what,
                        why: "the joints at the circle point cannot be found".into(),
                        loc,
                    })?,
                );
            MoveKind::Circular { via, via_conf }
        }
        _ => kind,
    };
    let proof = model
        .prove_path(&followed)
        .map_err(|source| ProcessError::Blocked {
            label: label.clone(),
            what,
            source: Box::new(source),
            loc,
        })?;
    let time = process_move_time(&followed, &s.robot.controller.axes, predefined_speed(speed));
    Ok(ProcessMove {
        kind,
        followed,
        proof,
        time,
    })
}

/// The joints of a followed path at progress `f`: the continuing solution from the last sample
/// at or before it (a sample's chord moves no axis far, so the nearest branch continues).
fn joints_at(s: &Setting, followed: &FollowedPath, f: f64) -> Option<Axes6> {
    let samples = followed.samples();
    let before = samples.iter().rev().find(|x| x.s <= f)?;
    if before.s == f {
        return Some(before.joints_deg);
    }
    let tool0 =
        s.frames.cell_from_robot.inverse() * followed.path().pose_at(f) * s.frames.tframe.inverse();
    s.ik.continuing(&tool0, &before.joints_deg).ok()
}

/// The end of a followed move into point `p` must be the joints placed for it.
fn agree(p: &Point, m: &ProcessMove, at: &Axes6, loc: Loc) -> Result<(), ProcessError> {
    let end = m.followed.end_joints();
    if max_diff(&end, at) <= END_AGREEMENT_DEG {
        return Ok(());
    }
    let fmt = |a: &Axes6| {
        let v: Vec<String> = a.iter().map(|x| format!("{x:.3}")).collect();
        format!("[{}]", v.join(", "))
    };
    Err(ProcessError::Pose {
        label: p.label(),
        what: move_name(&m.kind),
        why: format!(
            "the path ends at axes {} but the point's robtarget is reached at {} (another solution of the same configuration)",
            fmt(&end),
            fmt(at)
        ),
        loc,
    })
}

/// The warning for a zone point `p` asks on a corner next to a process move: it is written
/// `fine` (such a corner is not proven).
fn warn_zone(warnings: &mut Vec<String>, p: &Point, motion: &MoveMotion) {
    if p.zone.as_deref().is_some_and(|z| z != "fine") {
        warnings.push(format!(
            "warning: {}: zone {} is written fine: the corner next to a process move is not proven",
            p.label(),
            motion.zone
        ));
    }
}

/// A warning where the point's speed needs an axis beyond its maximum along the move.
fn warn_speed(s: &Setting, warnings: &mut Vec<String>, p: &Point, m: &ProcessMove, speed: &str) {
    let Some(data) = predefined_speed(speed) else {
        return;
    };
    if let Some(e) = m.followed.speed_excess(&data, &s.robot.controller.axes) {
        warnings.push(format!(
            "warning: {}: {} at {speed}: {e}; the controller slows down there",
            p.label(),
            move_name(&m.kind)
        ));
    }
}

/// The one plan the module writes (module docs): the refined air plans of `runs` (each the
/// plan of [`Followed::air_runs`]'s range) and the process moves between them, in the stops'
/// order; waypoints and vias named by the entries they belong to; the least clearance over
/// every move; the total time with the `wait_time` actions.
pub fn splice(
    followed: &Followed,
    runs: Vec<(Range<usize>, Plan)>,
    method: crate::plan::Method,
    grid_deg: f64,
    waits_s: f64,
) -> Plan {
    let stops = &followed.stops;
    // Every stop an entry, all joined through the air: the one plan as it is.
    if let [(run, plan)] = runs.as_slice() {
        let entries = (stops.iter().enumerate()).all(|(k, s)| s.kind == StopKind::Entry(k));
        let air = followed.into.iter().all(|i| matches!(i, Reach::Air));
        if *run == (0..stops.len()) && entries && air {
            let mut plan = plan.clone();
            plan.total_s += waits_s;
            if let Some(p) = &mut plan.paper {
                p.time_s += waits_s;
            }
            return plan;
        }
    }
    let kind_of = |s: &Stop| match s.kind {
        StopKind::Entry(i) => WaypointKind::CellPoint(i),
        StopKind::Closing(_) => WaypointKind::CellPoint(0),
        StopKind::Approach(i) => WaypointKind::Approach(i),
        StopKind::Retract(i) => WaypointKind::Retract(i),
    };
    let mut waypoints: Vec<Waypoint> = Vec::new();
    let mut legs: Vec<Leg> = Vec::new();
    let mut moves: Vec<Move> = Vec::new();
    // The paper's figure: of the whole program when every run's route is the paper's.
    let mut paper = Some(PaperFigure {
        moves: 0,
        time_s: waits_s,
    });
    let mut total_s = waits_s;
    let mut into_first = stops.first().map(|s| s.motion.clone());
    let mut least: Option<crate::plan::Clearance> = None;
    let mut keep_least = |c: Option<&crate::plan::Clearance>| {
        if let Some(c) = c {
            if least.as_ref().is_none_or(|l| c.mm < l.mm) {
                least = Some(c.clone());
            }
        }
    };
    let mut runs = runs.into_iter().peekable();
    let mut k = 0;
    loop {
        let mut advanced = false;
        if let Some((run, plan)) = runs.next_if(|(r, _)| r.start == k) {
            advanced = true;
            if k == 0 {
                into_first = Some(plan.into_first.clone());
            }
            let offset = waypoints.len().saturating_sub(1);
            let skip = usize::from(!waypoints.is_empty());
            for w in plan.route.waypoints.iter().skip(skip) {
                let kind = match w.kind {
                    WaypointKind::CellPoint(j) => stops.get(run.start + j).map_or(w.kind, kind_of),
                    WaypointKind::Via { leg, index } => WaypointKind::Via {
                        leg: followed.leg_into(&run, leg + 1),
                        index,
                    },
                    other => other,
                };
                waypoints.push(Waypoint {
                    kind,
                    joints_deg: w.joints_deg,
                });
            }
            for l in &plan.route.legs {
                legs.push(Leg {
                    from: followed.entry_of(&run, l.from),
                    to: followed.entry_of(&run, l.to),
                    waypoints: l.waypoints.start + offset..l.waypoints.end + offset,
                    ..l.clone()
                });
            }
            keep_least(plan.least.as_ref());
            moves.extend(plan.moves);
            total_s += plan.total_s;
            paper = paper.zip(plan.paper).map(|(p, q)| PaperFigure {
                moves: p.moves + q.moves,
                time_s: p.time_s + q.time_s,
            });
            k = run.end - 1;
        } else if waypoints.is_empty() {
            if let Some(s) = stops.get(k) {
                waypoints.push(Waypoint {
                    kind: kind_of(s),
                    joints_deg: s.joints_deg,
                });
            }
        }
        // The process moves out of stop k.
        while let Some((Reach::Process(m), s)) = followed.into.get(k + 1).zip(stops.get(k + 1)) {
            waypoints.push(Waypoint {
                kind: kind_of(s),
                joints_deg: s.joints_deg,
            });
            let estimate = MoveEstimate {
                time_s: m.time.stop_s,
                profile: m.time.profile,
                limit: m.time.limit,
            };
            keep_least(m.proof.clearance.as_ref());
            total_s += m.time.stop_s;
            if let Some(p) = &mut paper {
                p.moves += 1;
                p.time_s += m.time.stop_s;
            }
            moves.push(Move {
                motion: s.motion.clone(),
                clearance: m.proof.clearance.clone(),
                estimate,
                kind: m.kind,
                path: Some(std::sync::Arc::new(m.followed.clone())),
            });
            k += 1;
            advanced = true;
        }
        // Every stop is reached through the air (in a run from the stop before) or by a
        // process move: nothing left when neither goes on.
        if !advanced {
            break;
        }
    }
    Plan {
        route: Route {
            method,
            grid_deg,
            waypoints,
            legs,
        },
        into_first: into_first.unwrap_or(MoveMotion {
            speed: String::new(),
            zone: String::new(),
        }),
        moves,
        least,
        total_s,
        paper,
    }
}
