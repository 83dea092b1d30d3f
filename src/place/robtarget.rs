//! Robtarget points: a TCP pose in the work object -> controller values of all six axes, through
//! the six-axis inverse kinematics ([`SixAxisIk`]). Beyond the paper (which plans wrist centres).
//!
//! **Frames.** The cell gives the TCP pose in its point's work object's user frame (`uframe`,
//! itself in the cell frame; the point's `wobj:`, the one work object when the cell has one, else
//! wobj0, whose frame is the cell frame). So
//! `TCP (cell) = uframe * pose`, `TCP (robot base) = placement^-1 * TCP (cell)`, and the flange
//! (tool0) pose the arm must reach is `TCP (robot base) * tframe^-1` (`tool.tframe`: the TCP in
//! the flange frame; without a `tool:` block tool0, the identity). With `robot.frame: base` the
//! uframe (or, in wobj0, the pose itself) is first taken as the module writes it in the base
//! frame, rounded ([`Placement::written`]), so the joints solved are the controller's for the
//! written data.
//!
//! **As written.** The module moves to a robtarget point by its `CONST robtarget` with ConfJ and
//! ConfL on, so the controller's joints there are the inverse kinematics of the robtarget *as
//! written* (positions to 0.001 mm, quaternions to 9 decimals, normalised; the tooldata and
//! wobjdata likewise, [`Frame::written`]) on the written confdata. Those exact joints (not
//! rounded to 0.001 deg: no jointtarget of them is written) are the point's placed joints, the
//! ones the plan proves.
//!
//! **Choice.** With confdata, the solution of that configuration (a value on a quadrant boundary
//! admitted for both quadrants, [`SixAxisIk::conf_admits`]); without, the one nearest the
//! previous point under the IK's documented metric (time of the joint move at the controller's
//! axis speeds, then the joint distance; the zero pose for the first point). Among those, the
//! first whose values are in range (all six axes and the coupled axis-3 range), are admitted for
//! the confdata written (the one asked for, else their own as rounded), reach the pose within
//! [`POSITION_TOL_MM`] and [`ANGLE_TOL_DEG`] by the robot's forward kinematics, and pass the
//! place stage's [`PoseCheck`] (collisions). Every refusal is kept, so a failure says why each
//! solution was refused, or that the pose is out of reach by how much, or that axis 5 would have
//! to leave its range, or which confdata are reachable when the one asked for is not.
//!
//! **The wrist centre without a base** (`base: auto`): the wrist centre is fixed in the flange
//! frame ([`SixAxisIk::wrist_in_tool0`]), so `W (cell) = uframe * pose * tframe^-1 * w` follows
//! from the cell alone; the location stage takes it as an `xyz` point.

use super::{PlaceError, Placement, PoseCheck};
use crate::cell::{Cell, Frame, Point, RobotFrame};
use crate::robot::ik::six::{describe_violation, ChooseError, ConfData, SixAxisIk};
use crate::robot::{Axes6, Robot};
use nalgebra::{Isometry3, Point3};

/// The written joint values must put the TCP within this of the robtarget's position, mm.
pub const POSITION_TOL_MM: f64 = 0.1;
/// ... and its orientation within this angle, deg.
pub const ANGLE_TOL_DEG: f64 = 0.01;

/// The tool and work object of a cell, with the solver of its robot.
pub(super) struct Tcp {
    ik: SixAxisIk,
    /// TCP in the flange frame.
    tframe: Isometry3<f64>,
    /// The work objects' user frames in the cell frame, as given, in the cell's order
    /// (`Point::wobj` indexes them; `None` there: wobj0).
    wobjs: Vec<Frame>,
    /// The frame the module writes the uframes and wobj0 robtargets in.
    written: RobotFrame,
}

impl Tcp {
    /// The cell's tool and work object; a robot the six-axis IK cannot handle is an input error
    /// pointing at `robot.urdf`.
    pub(super) fn of(cell: &Cell, robot: &Robot) -> Result<Tcp, PlaceError> {
        let ik = SixAxisIk::from_robot(robot).map_err(|source| PlaceError::SixAxis {
            source,
            loc: cell.robot.urdf_loc,
        })?;
        // The frames as written (tooldata, wobjdata): what the controller computes with.
        let frame = |f: Option<Frame>| f.unwrap_or(Frame::IDENTITY).written().isometry();
        Ok(Tcp {
            ik,
            tframe: frame(cell.tool.as_ref().map(|t| t.tframe)),
            wobjs: cell.wobjs.iter().map(|w| w.uframe).collect(),
            written: cell.robot.frame,
        })
    }

    /// The user frame of work object `wobj` as given (`None`, or an index the cell does not
    /// have: wobj0).
    fn wobj(&self, wobj: Option<usize>) -> Option<&Frame> {
        wobj.and_then(|i| self.wobjs.get(i))
    }

    /// The TCP pose of a robtarget in work object `wobj`, in the cell frame, as written (module
    /// docs, "Choice").
    fn tcp_in_cell(&self, pose: &Frame, wobj: Option<usize>) -> Isometry3<f64> {
        let uframe = self.wobj(wobj).copied().unwrap_or(Frame::IDENTITY);
        uframe.written().isometry() * pose.written().isometry()
    }

    /// The TCP pose of a robtarget in work object `wobj`, in the robot base frame, from the
    /// data the module writes (module docs).
    fn tcp_in_base(
        &self,
        pose: &Frame,
        wobj: Option<usize>,
        placement: Placement,
    ) -> Isometry3<f64> {
        match (self.written, self.wobj(wobj)) {
            (RobotFrame::Cell, _) => {
                placement.cell_from_robot().inverse() * self.tcp_in_cell(pose, wobj)
            }
            (RobotFrame::Base, Some(u)) => {
                placement.written(RobotFrame::Base, u).isometry() * pose.written().isometry()
            }
            (RobotFrame::Base, None) => placement.written(RobotFrame::Base, pose).isometry(),
        }
    }

    /// The wrist centre of a robtarget in work object `wobj`, cell frame, mm (module docs).
    pub(super) fn wrist_centre(&self, pose: &Frame, wobj: Option<usize>) -> [f64; 3] {
        let w = self.tcp_in_cell(pose, wobj)
            * self.tframe.inverse()
            * Point3::from(self.ik.wrist_in_tool0());
        [w.x, w.y, w.z]
    }

    /// The joints of `pose` as written from `placement` (module docs): the solution the IK
    /// chooses among those in range, admitted for the confdata `wanted`, reaching the pose and
    /// accepted by `check`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn choose(
        &self,
        pose: &Frame,
        wobj: Option<usize>,
        wanted: Option<ConfData>,
        placement: Placement,
        previous: Option<&Axes6>,
        check: &impl PoseCheck,
    ) -> Result<Axes6, ChooseError<String>> {
        let tcp = self.tcp_in_base(pose, wobj, placement);
        let robot = self.ik.robot();
        let accept = |axes: &Axes6| -> Result<(), String> {
            if let Err(v) = robot.check_range6(axes) {
                return Err(describe_violation(&v));
            }
            // The confdata written is the one asked for, else that of the values rounded as
            // the module would round them; the solution must be admitted for it.
            let conf = wanted.unwrap_or_else(|| self.ik.conf(axes));
            if !self.ik.conf_admits(axes, conf) {
                return Err(format!("it is confdata {}, not {conf}", self.ik.conf(axes)));
            }
            let (mm, deg) = pose_error(&(robot.tool0(axes) * self.tframe), &tcp);
            if mm > POSITION_TOL_MM || deg > ANGLE_TOL_DEG {
                return Err(format!("it misses the pose by {mm:.3} mm and {deg:.4} deg"));
            }
            match check.why_blocked(axes) {
                None => Ok(()),
                Some(why) => Err(why),
            }
        };
        let solution = self
            .ik
            .choose_tcp(&tcp, &self.tframe, wanted, previous, accept)?;
        Ok(solution.axes_deg)
    }

    /// Solves robtarget point `p` from `placement` (module docs): the written joint values and
    /// the confdata the module states with them.
    pub(super) fn solve(
        &self,
        p: &Point,
        pose: &Frame,
        wanted: Option<ConfData>,
        placement: Placement,
        previous: Option<&Axes6>,
        check: &impl PoseCheck,
    ) -> Result<(Axes6, ConfData), PlaceError> {
        let q = self
            .choose(pose, p.wobj, wanted, placement, previous, check)
            .map_err(|source| PlaceError::Robtarget {
                point: p.name.clone(),
                base_mm: placement.base_mm,
                yaw_deg: placement.yaw_deg,
                source: Box::new(source),
                loc: p.loc,
                hint: None,
            })?;
        // The confdata asked for is written as asked (the joints are admitted for it, also on a
        // quadrant boundary); without one, the joints' own as written.
        Ok((q, wanted.unwrap_or_else(|| self.ik.conf(&q))))
    }
}

/// How far pose `a` is from pose `b`: position (mm) and rotation angle (deg).
pub fn pose_error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> (f64, f64) {
    let mm = (a.translation.vector - b.translation.vector).norm();
    let deg = a.rotation.angle_to(&b.rotation).to_degrees();
    (mm, deg)
}
