//! Where the robot's frames are in the cell frame, for the preview page and the report: the
//! robot's forward kinematics (the load stage's model, `Robot::link_poses`, held against
//! RobotStudio in its tests) at the placement, carried through the tool's `tframe` to the TCP.
//! Kinematics only: no collision model, no timing.

use crate::cell::Tool;
use crate::place::Placement;
use crate::robot::Robot;
use nalgebra::Isometry3;

/// The robot placed in the cell with its tool.
pub struct Poser<'a> {
    robot: &'a Robot,
    cell_from_robot: Isometry3<f64>,
    /// The TCP in the flange (tool0) frame: the tool's `tframe`, identity without a tool.
    tframe: Isometry3<f64>,
}

impl<'a> Poser<'a> {
    pub fn new(robot: &'a Robot, placement: Placement, tool: Option<&Tool>) -> Poser<'a> {
        Poser {
            robot,
            cell_from_robot: placement.cell_from_robot(),
            tframe: tool.map_or(Isometry3::identity(), |t| t.tframe.isometry()),
        }
    }

    /// The robot's base (base_link) in the cell frame.
    pub fn base(&self) -> Isometry3<f64> {
        self.cell_from_robot
    }

    /// Links 1..6 (the children of joints 1..6) in the cell frame.
    pub fn links(&self, axes_deg: &[f64; 6]) -> [Isometry3<f64>; 6] {
        self.robot
            .link_poses(axes_deg)
            .map(|l| self.cell_from_robot * l)
    }

    /// The flange (tool0) frame in the cell frame: the frame the tool's shapes are given in.
    pub fn tool0(&self, axes_deg: &[f64; 6]) -> Isometry3<f64> {
        self.cell_from_robot * self.robot.tool0(axes_deg)
    }

    /// The TCP (tool0 without a tool) in the cell frame.
    pub fn tcp(&self, axes_deg: &[f64; 6]) -> Isometry3<f64> {
        self.tool0(axes_deg) * self.tframe
    }

    /// The TCP position in the cell frame, mm.
    pub fn tcp_mm(&self, axes_deg: &[f64; 6]) -> [f64; 3] {
        let t = self.tcp(axes_deg).translation.vector;
        [t.x, t.y, t.z]
    }

    /// The wrist centre (where axes 4, 5 and 6 meet) in the cell frame, mm.
    pub fn wrist_centre_mm(&self, axes_deg: &[f64; 6]) -> [f64; 3] {
        let w = self.cell_from_robot * self.robot.wrist_centre(axes_deg);
        [w.x, w.y, w.z]
    }
}
