//! The program of a module that moves to robtargets or runs actions, against the cell, as the
//! module format of process moves lays it out: the declarations (`data.rs`), every robtarget
//! point's `CONST robtarget <point>_rt` (the cell's pose, in the frame the module writes; the
//! cell's confdata where it gives one), the header's frames line and count of moves, and the
//! routine walked entry by entry in the cell's order (a revisit reaches its point's data again;
//! with `motion.cycle` a closing leg back to the first entry's target follows):
//!
//! ```text
//! ConfJ \On; ConfL \On;                      (only before the first motion)
//! for each entry e:
//!   joint (after the first): MoveAbsJ via..\NoEOffs ... (the air leg's vias), then
//!     MoveAbsJ e\NoEOffs (joints or xyz) | MoveJ e_rt
//!     | with approach D: MoveJ RelTool(e_rt,0,0,-D) | MoveJ X (X: that pose); MoveL e_rt
//!   linear: MoveL e_rt;  circular: MoveC X, e_rt (X at the cell's via)
//!   the actions of e (`actions.rs`)
//!   retract D: MoveL RelTool(e_rt,0,0,-D) | MoveL X (X: that pose)
//! closing leg: MoveAbsJ via.. ..., then MoveAbsJ e0 | MoveJ e0_rt
//! ```
//!
//! Each move's speed is its entry's (`motion.speed` by default and on the closing leg); its
//! zone the entry's (or `motion.zone`) or `fine` where it reaches a point, `motion.via_zone` or
//! `fine` at a via, and `fine` into a point that stops (actions, approach or retract), into an
//! approach pose, on approach and retract lines and at the ends; its tool the cell's; its work
//! object the robtarget point's (with one work object, every move names it; with several, a
//! move towards a jointtarget point names none). A jointtarget point's written joints are the
//! cell's (xyz points: the wrist centre by forward kinematics within 0.05 mm). The walk stops
//! at the first instruction out of place, naming it.
//!
//! What the moves do (the joints the controller reaches, the paths, the confdata at the end) is
//! `controller.rs`'s; this file holds the program to the cell.

use super::actions::check_actions;
use super::data::{check_declarations, iso, same_pose, written_frame};
use super::library::{Arrival, Cell, Point, Robot, Target};
use super::module::Module;
use super::routine::{Action, Instruction, Motion, MoveKind, Statement, ToPoint};
use nalgebra::{Isometry3, Point3, Translation3, Vector3};

/// A cell-frame xyz point's written joints must give it back within this, mm (the module's
/// 0.001 deg moves the wrist centre by less than 0.05 mm).
pub const XYZ_TOL_MM: f64 = 0.05;

/// What [`check_program`] walked.
#[derive(Clone, Debug, Default)]
pub struct ProgramReport {
    /// Cell entries walked (with the closing leg as one).
    pub entries: usize,
    /// `MoveL` and `MoveC` instructions (process moves, approach and retract lines).
    pub lines_and_arcs: usize,
    /// Actions held to the cell's.
    pub actions: usize,
    /// Robtarget points whose `CONST robtarget` was held to the cell's pose.
    pub robtargets: usize,
}

/// Whether a jointtarget point's written joints `axes` are the cell's (module doc); `None` when
/// they are, else why not. `cell_from_robot` is the header's placement.
pub fn point_as_written(
    cell: &Cell,
    robot: &Robot,
    cell_from_robot: &Isometry3<f64>,
    p: &Point,
    axes: &[f64; 6],
) -> Option<String> {
    match &p.target {
        Target::Joints {
            axes_deg,
            wrist_deg,
        } => {
            let w = wrist_deg.unwrap_or(cell.robot.wrist_deg);
            (axes[..3] != axes_deg[..] || axes[3..] != w[..]).then(|| {
                format!(
                    "point {} written as {axes:?}, given as {axes_deg:?} wrist {w:?}",
                    p.name
                )
            })
        }
        Target::Xyz {
            wrist_centre_mm, ..
        } => {
            let back = cell_from_robot * robot.wrist_centre(axes);
            let off = (back - Point3::from(*wrist_centre_mm)).norm();
            (off > XYZ_TOL_MM).then(|| {
                format!(
                    "point {}: its written joints {axes:?} reach {back:?}, {off:.3} mm from the given {wrist_centre_mm:?}",
                    p.name
                )
            })
        }
        Target::Robtarget { .. } => None,
    }
}

/// The pose a robtarget point's `CONST robtarget` holds: the cell's, or with `robot.frame: base`
/// and no work object, the same in the robot's base frame.
fn written_pose(
    cell: &Cell,
    cell_from_robot: &Isometry3<f64>,
    p: &Point,
) -> Option<Isometry3<f64>> {
    let Target::Robtarget { pose, .. } = &p.target else {
        return None;
    };
    Some(match p.wobj {
        Some(_) => pose.isometry(),
        None => written_frame(cell, cell_from_robot).inverse() * pose.isometry(),
    })
}

/// Walks the routine against the cell (module doc).
struct Walk<'a> {
    cell: &'a Cell,
    robot: &'a Robot,
    module: &'a Module,
    cell_from_robot: Isometry3<f64>,
    body: &'a [Statement],
    at: usize,
    failures: Vec<String>,
    report: ProgramReport,
}

/// What a move into an entry must say besides its target.
struct Expect<'a> {
    speed: &'a str,
    /// Zones allowed besides `fine`.
    zone: Option<&'a str>,
    wobj: Option<&'a str>,
    what: String,
}

impl<'a> Walk<'a> {
    fn next(&self) -> Option<&'a Statement> {
        self.body.get(self.at)
    }

    /// The next statement as a motion of `kind`, or a failure naming what was expected (and the
    /// walk ends: `None`).
    fn motion(&mut self, kind: MoveKind, expect: &Expect) -> Option<(&'a Statement, &'a Motion)> {
        let st = self.next();
        let found = st.map_or("the routine's end".to_string(), Statement::label);
        match st.and_then(|s| s.motion().map(|m| (s, m))) {
            Some((s, m)) if m.kind == kind => {
                self.at += 1;
                let tool = self
                    .cell
                    .tool
                    .as_ref()
                    .map_or(self.cell.motion.tool.as_str(), |t| t.name.as_str());
                let zone_ok =
                    m.zone.eq_ignore_ascii_case("fine") || expect.zone.is_some_and(|z| z == m.zone);
                if m.speed != expect.speed
                    || !zone_ok
                    || m.tool != tool
                    || m.wobj.as_deref() != expect.wobj
                {
                    self.failures.push(format!(
                        "{}: {} must be {kind} with {}, {} (or fine), {tool}{}",
                        s.label(),
                        expect.what,
                        expect.speed,
                        expect.zone.unwrap_or("fine"),
                        expect
                            .wobj
                            .map_or(String::new(), |w| format!("\\WObj:={w}")),
                        kind = kind.name(),
                    ));
                }
                Some((s, m))
            }
            _ => {
                self.failures.push(format!(
                    "expected {} ({}), found {found}",
                    expect.what,
                    kind.name()
                ));
                None
            }
        }
    }

    /// Holds a move's target to `name`, or to a robtarget (other than `name`) holding `pose`
    /// (`RelTool(name,0,0,dz)` with `offset_dz`).
    fn target(
        &mut self,
        st: &Statement,
        to: &ToPoint,
        name: &str,
        offset_dz: Option<f64>,
        pose: &Isometry3<f64>,
    ) {
        let ok = match (to, offset_dz) {
            (ToPoint::Name(n), None) => n == name,
            (ToPoint::RelTool { base, offset_mm }, Some(dz)) => {
                base == name
                    && offset_mm[0] == 0.0
                    && offset_mm[1] == 0.0
                    && (offset_mm[2] - dz).abs() <= 5e-4
            }
            (ToPoint::Name(n), Some(dz)) => {
                let want = pose * Translation3::from(Vector3::new(0.0, 0.0, dz));
                n != name
                    && self
                        .module
                        .robtarget(n)
                        .is_some_and(|r| same_pose(&iso(r.pos_mm, r.quat_wxyz), &want))
            }
            _ => false,
        };
        if !ok {
            let want = match offset_dz {
                None => name.to_string(),
                Some(dz) => format!("RelTool({name},0,0,{dz:.3}) or a robtarget holding that pose"),
            };
            self.failures
                .push(format!("{}: its target must be {want}", st.label()));
        }
    }

    /// The entry `p` (index `k`; `closing`: the leg back to the first entry).
    fn entry(&mut self, k: usize, p: &'a Point, closing: bool) -> Option<()> {
        let cell = self.cell;
        let first = k == 0 && !closing;
        let last = closing || (k + 1 == cell.points.len() && !cell.closing_leg());
        let speed = match closing {
            true => cell.motion.speed.as_str(),
            false => p.speed.as_deref().unwrap_or(&cell.motion.speed),
        };
        let rob = matches!(p.target, Target::Robtarget { .. });
        let rt = format!("{}_rt", p.name);
        let wobj = match rob {
            true => cell.wobj_of(p).map(|w| w.name.as_str()),
            false => match cell.wobjs.as_slice() {
                [w] => Some(w.name.as_str()),
                _ => None,
            },
        };
        let asked = p.zone.as_deref().unwrap_or(&cell.motion.zone);
        let reach_zone = match p.stops() || first || last {
            true => None,
            false => Some(asked),
        };
        let expect = |what: String, zone: Option<&'a str>| Expect {
            speed,
            zone,
            wobj,
            what,
        };
        let pose = written_pose(cell, &self.cell_from_robot, p);
        let arrival = if closing { Arrival::Joint } else { p.arrival };
        if arrival == Arrival::Joint && !first {
            // The air leg's vias.
            while let Some((s, m)) = self.next().and_then(|s| s.motion().map(|m| (s, m))) {
                let via = m.kind == MoveKind::AbsJ && (rob || m.to.data() != p.name);
                if !via {
                    break;
                }
                if cell.points.iter().any(|q| q.name == m.to.data()) {
                    self.failures.push(format!(
                        "{}: a via named like a cell point, before {}",
                        s.label(),
                        p.label()
                    ));
                }
                let e = expect(
                    format!("a via of the leg into {}", p.label()),
                    Some(cell.motion.via_zone.as_str()),
                );
                self.motion(MoveKind::AbsJ, &e);
            }
        }
        let who = match closing {
            true => format!("the closing leg to {}", p.label()),
            false => p.label(),
        };
        match arrival {
            Arrival::Joint => match (rob, p.approach_mm.filter(|_| !closing)) {
                (false, _) => {
                    let (s, m) = self.motion(
                        MoveKind::AbsJ,
                        &expect(format!("the move into {who}"), reach_zone),
                    )?;
                    if m.to.data() != p.name {
                        self.failures
                            .push(format!("{}: its target must be {}", s.label(), p.name));
                    } else if let Some(e) = point_as_written(
                        cell,
                        self.robot,
                        &self.cell_from_robot,
                        p,
                        &self.module.target(&p.name),
                    ) {
                        self.failures.push(e);
                    }
                }
                (true, None) => {
                    let (s, m) = self.motion(
                        MoveKind::J,
                        &expect(format!("the move into {who}"), reach_zone),
                    )?;
                    self.target(s, &m.to, &rt, None, &pose?);
                }
                (true, Some(d)) => {
                    let e = expect(format!("the move to {who}'s approach pose"), None);
                    let (s, m) = self.motion(MoveKind::J, &e)?;
                    self.target(s, &m.to, &rt, Some(-d), &pose?);
                    let e = expect(format!("{who}'s approach line"), None);
                    let (s, m) = self.motion(MoveKind::L, &e)?;
                    self.target(s, &m.to, &rt, None, &pose?);
                }
            },
            Arrival::Linear => {
                let (s, m) = self.motion(
                    MoveKind::L,
                    &expect(format!("the line into {who}"), reach_zone),
                )?;
                self.target(s, &m.to, &rt, None, &pose?);
            }
            Arrival::Circular { via_mm, .. } => {
                let (s, m) = self.motion(
                    MoveKind::C,
                    &expect(format!("the arc into {who}"), reach_zone),
                )?;
                self.target(s, &m.to, &rt, None, &pose?);
                let via = match p.wobj {
                    Some(_) => Point3::from(via_mm),
                    None => {
                        written_frame(cell, &self.cell_from_robot).inverse() * Point3::from(via_mm)
                    }
                };
                let circle = m.circle.as_ref().and_then(|c| match c {
                    ToPoint::Name(n) => self.module.robtarget(n),
                    ToPoint::RelTool { .. } => None,
                });
                if !circle.is_some_and(|r| (Point3::from(r.pos_mm) - via).norm() <= 1e-3) {
                    self.failures.push(format!(
                        "{}: its circle point must be a robtarget at the cell's via {via:?}",
                        s.label()
                    ));
                }
            }
        }
        if closing {
            return Some(());
        }
        let mut written: Vec<(&Statement, &Action)> = Vec::new();
        while let Some(s) = self.next() {
            let Instruction::Action(a) = &s.ins else {
                break;
            };
            written.push((s, a));
            self.at += 1;
        }
        self.report.actions += written.len();
        let f = check_actions(cell, p, &written);
        self.failures.extend(f);
        if let Some(d) = p.retract_mm {
            let e = expect(format!("{who}'s retract line"), None);
            let (s, m) = self.motion(MoveKind::L, &e)?;
            self.target(s, &m.to, &rt, Some(-d), &pose?);
        }
        Some(())
    }
}

/// Holds `module`'s program to `cell` (module doc); `cell_from_robot` is the header's
/// placement.
pub fn check_program(
    cell: &Cell,
    robot: &Robot,
    module: &Module,
    cell_from_robot: &Isometry3<f64>,
) -> Result<ProgramReport, Vec<String>> {
    let mut failures = check_declarations(cell, module, cell_from_robot);
    let mut report = ProgramReport::default();
    let motions = module.motions().count();
    if module.header_moves + 1 != motions {
        failures.push(format!(
            "header says {} moves, the routine has {motions} motion instructions (one reaches the start)",
            module.header_moves
        ));
    }
    match (module.frames.as_deref(), cell.robot.frame) {
        (Some(f), super::library::RobotFrame::Base)
            if f.contains("base frame") && !f.contains("in the cell frame") => {}
        (Some(f), super::library::RobotFrame::Cell) if f.contains("cell frame") => {}
        (f, frame) if !module.robtargets.is_empty() || !module.wobjdata.is_empty() => failures
            .push(format!(
                "the header's frames line {f:?} does not say the {frame:?} frame the cell asks"
            )),
        _ => {}
    }
    // Every robtarget point's data: the cell's pose, the cell's confdata where given.
    for p in cell.points.iter().filter(|p| p.revisit_of.is_none()) {
        let (Target::Robtarget { conf, .. }, Some(want)) =
            (&p.target, written_pose(cell, cell_from_robot, p))
        else {
            continue;
        };
        let name = format!("{}_rt", p.name);
        match module.robtarget(&name) {
            None => failures.push(format!(
                "robtarget point {} has no CONST robtarget {name}",
                p.name
            )),
            Some(r) => {
                report.robtargets += 1;
                if !same_pose(&iso(r.pos_mm, r.quat_wxyz), &want) {
                    failures.push(format!(
                        "{name} holds {:?} {:?}, the cell's pose is {want} in the frame the module writes",
                        r.pos_mm, r.quat_wxyz
                    ));
                }
                if let Some(c) = conf.filter(|c| c.to_array() != r.conf) {
                    failures.push(format!(
                        "{name} has confdata {:?}, the cell asks {:?}",
                        r.conf,
                        c.to_array()
                    ));
                }
            }
        }
    }
    let mut walk = Walk {
        cell,
        robot,
        module,
        cell_from_robot: *cell_from_robot,
        body: &module.body,
        at: 0,
        failures: Vec::new(),
        report,
    };
    while matches!(
        walk.next().map(|s| &s.ins),
        Some(Instruction::ConfJ(_) | Instruction::ConfL(_))
    ) {
        walk.at += 1;
    }
    let closing = cell.closing_leg().then(|| &cell.points[0]);
    let entries = cell
        .points
        .iter()
        .map(|p| (p, false))
        .chain(closing.map(|p| (p, true)));
    let mut done = true;
    for (k, (p, is_closing)) in entries.enumerate() {
        if walk.entry(k, p, is_closing).is_none() {
            done = false;
            break;
        }
        walk.report.entries += 1;
    }
    if done {
        if let Some(s) = walk.next() {
            walk.failures
                .push(format!("{}: after the cell's last entry", s.label()));
        }
    }
    walk.report.lines_and_arcs = module
        .motions()
        .filter(|(_, m)| m.kind.is_process())
        .count();
    failures.extend(walk.failures);
    match failures.is_empty() {
        true => Ok(walk.report),
        false => Err(failures),
    }
}
