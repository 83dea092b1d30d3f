//! Where the robot stands, and the two frames that meet there: the cell frame (the cell file's
//! positions and boxes) and the robot base frame (kinematics, inverse kinematics); and the frame
//! the module writes a pose in (`robot.frame`, [`Placement::written`]).

use crate::cell::{Frame, RobotFrame};
use crate::precision::{round, POSITION_DECIMALS, QUATERNION_DECIMALS};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

/// Where the robot stands: its base frame in the cell frame (a translation, then a turn about
/// the cell's z axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Translation of the base frame origin, cell frame, mm.
    pub base_mm: [f64; 3],
    /// Rotation of the base frame about the cell's z axis, degrees (counter-clockwise from above).
    pub yaw_deg: f64,
}

impl Placement {
    /// Robot-base-frame position -> cell-frame position (inverse of [`Self::to_robot_frame`]).
    pub fn to_cell_frame(&self, p: [f64; 3]) -> [f64; 3] {
        let (s, c) = self.yaw_deg.to_radians().sin_cos();
        let b = self.base_mm;
        [
            b[0] + c * p[0] - s * p[1],
            b[1] + s * p[0] + c * p[1],
            b[2] + p[2],
        ]
    }

    /// Cell-frame position -> robot-base-frame position.
    pub fn to_robot_frame(&self, p: [f64; 3]) -> [f64; 3] {
        let (s, c) = self.yaw_deg.to_radians().sin_cos();
        let d = [
            p[0] - self.base_mm[0],
            p[1] - self.base_mm[1],
            p[2] - self.base_mm[2],
        ];
        [c * d[0] + s * d[1], -s * d[0] + c * d[1], d[2]]
    }

    /// The robot base frame in the cell frame, as an isometry (for poses, not only positions).
    pub fn cell_from_robot(&self) -> Isometry3<f64> {
        Isometry3::from_parts(
            Translation3::new(self.base_mm[0], self.base_mm[1], self.base_mm[2]),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.yaw_deg.to_radians()),
        )
    }

    /// A pose the cell gives in the cell frame (a work object's uframe, a robtarget in wobj0) as
    /// the module writes it under `robot.frame`: as given with `cell`; with `base`, in the
    /// robot's base frame (`placement^-1 * pose`), its position rounded to the module's 3
    /// decimals and its quaternion to 9, of its two signs the one whose first non-zero
    /// component is positive (as `zyx` orientations are read). The rounded pose is the one the
    /// place stage solves, so the joints proven are those the controller computes from what is
    /// written.
    pub fn written(&self, frame: RobotFrame, pose: &Frame) -> Frame {
        if frame == RobotFrame::Cell {
            return *pose;
        }
        let b = self.cell_from_robot().inverse() * pose.isometry();
        let t = b.translation.vector;
        let q = b.rotation.into_inner();
        // `+ 0.0` turns a rounded `-0.0` into `0.0`.
        let r = |v: f64, d: usize| round(v, d) + 0.0;
        let quat = [q.w, q.i, q.j, q.k].map(|v| r(v, QUATERNION_DECIMALS));
        let sign = match quat.iter().find(|v| **v != 0.0) {
            Some(v) if *v < 0.0 => -1.0,
            _ => 1.0,
        };
        Frame {
            pos_mm: [t.x, t.y, t.z].map(|v| r(v, POSITION_DECIMALS)),
            quat_wxyz: quat.map(|v| sign * v + 0.0),
        }
    }

    /// The numbers the module writes for a robtarget pose the cell gives in a work object whose
    /// user frame is `uframe` (`None`: wobj0), rounded as written: in a work object the pose as
    /// given (the uframe carries the frame), in wobj0 [`Self::written`].
    pub fn robtarget_data(&self, frame: RobotFrame, uframe: Option<&Frame>, pose: &Frame) -> Frame {
        match uframe {
            Some(_) => pose.written(),
            None => self.written(frame, pose).written(),
        }
    }

    /// The frame a robtarget's written numbers ([`Self::robtarget_data`]) are in, as the
    /// controller reads them, in the cell frame: the user frame as written (with `base`, written
    /// in the base frame and placed by the base), or without a work object the world frame (the
    /// cell frame; with `base`, the base frame). So a pose written `d` is the cell pose
    /// `data_frame * d`.
    pub fn data_frame(&self, frame: RobotFrame, uframe: Option<&Frame>) -> Isometry3<f64> {
        match (frame, uframe) {
            (RobotFrame::Cell, Some(u)) => u.written().isometry(),
            (RobotFrame::Cell, None) => Isometry3::identity(),
            (RobotFrame::Base, Some(u)) => {
                self.cell_from_robot() * self.written(RobotFrame::Base, u).isometry()
            }
            (RobotFrame::Base, None) => self.cell_from_robot(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    #[test]
    fn the_frames_are_inverse_and_agree_with_the_isometry() {
        let pl = Placement {
            base_mm: [100.0, -850.0, 20.0],
            yaw_deg: 90.0,
        };
        // Robot +x is cell +y at yaw 90.
        let c = pl.to_cell_frame([870.0, 0.0, 1195.0]);
        assert!((c[0] - 100.0).abs() < 1e-9 && (c[1] - 20.0).abs() < 1e-9 && c[2] == 1215.0);
        let back = pl.to_robot_frame(c);
        assert!((back[0] - 870.0).abs() < 1e-9 && back[1].abs() < 1e-9);
        let iso = pl.cell_from_robot() * Point3::new(870.0, 0.0, 1195.0);
        assert!((iso.coords - Point3::from(c).coords).norm() < 1e-9);
    }

    /// By hand: the base at (0, -850, 0) turned 90 deg about z. A cell point (x, y, z) is, from
    /// the base, d = (x, y + 850, z) turned back by 90 deg: (d_y, -d_x, d_z). A frame turned 90
    /// deg about z in the cell (q = [c45, 0, 0, s45]) is not turned at all from the base; one
    /// pointing down (q = [0, 0, 1, 0], Ry(180)) becomes Rz(-90) Ry(180) =
    /// [0, s45, c45, 0] (q1 = 0: the sign makes q2 positive).
    #[test]
    fn written_in_the_base_frame_by_hand() {
        let pl = Placement {
            base_mm: [0.0, -850.0, 0.0],
            yaw_deg: 90.0,
        };
        let s45 = 0.5_f64.sqrt();
        let uframe = Frame {
            pos_mm: [-830.0, -380.0, 100.0],
            quat_wxyz: [s45, 0.0, 0.0, s45],
        };
        assert_eq!(pl.written(RobotFrame::Cell, &uframe), uframe);
        let w = pl.written(RobotFrame::Base, &uframe);
        assert_eq!(w.pos_mm, [470.0, 830.0, 100.0]);
        assert_eq!(w.quat_wxyz, [1.0, 0.0, 0.0, 0.0]);
        let down = Frame {
            pos_mm: [330.0, 280.5, 0.0],
            quat_wxyz: [0.0, 0.0, 1.0, 0.0],
        };
        let w = pl.written(RobotFrame::Base, &down);
        assert_eq!(w.pos_mm, [1130.5, -330.0, 0.0]);
        let r = round(s45, QUATERNION_DECIMALS);
        assert_eq!(w.quat_wxyz, [0.0, r, r, 0.0]);
        // A yaw that is no multiple of 90 deg: the position is rounded to 0.001 mm.
        let pl = Placement {
            base_mm: [100.0, 0.0, 50.0],
            yaw_deg: 30.0,
        };
        let p = Frame {
            pos_mm: [200.0, 0.0, 50.0],
            quat_wxyz: [1.0, 0.0, 0.0, 0.0],
        };
        let w = pl.written(RobotFrame::Base, &p);
        // d = (100, 0, 0) turned back by 30 deg: (100 cos 30, -100 sin 30, 0) = (86.603, -50, 0).
        assert_eq!(w.pos_mm, [86.603, -50.0, 0.0]);
        // Rz(-30) = [cos 15, 0, 0, -sin 15].
        let (s15, c15) = 15f64.to_radians().sin_cos();
        assert_eq!(w.quat_wxyz, [round(c15, 9), 0.0, 0.0, round(-s15, 9)]);
    }

    /// The written data in their frame are the cell's pose, in each of the four cases (the cell
    /// or the base frame, a work object or wobj0), to the written rounding.
    #[test]
    fn data_in_their_frame_are_the_cells_pose() {
        let pl = Placement {
            base_mm: [100.0, -850.0, 20.0],
            yaw_deg: 30.0,
        };
        let u = Frame {
            pos_mm: [-830.0, -380.0, 100.0],
            quat_wxyz: [0.9238795, 0.0, 0.0, 0.3826834],
        };
        let u = Frame {
            quat_wxyz: {
                let q = u.isometry().rotation.into_inner();
                [q.w, q.i, q.j, q.k]
            },
            ..u
        };
        let pose = Frame {
            pos_mm: [330.0, 280.0, 0.0],
            quat_wxyz: [0.1830127, -0.6830127, -0.6830127, -0.1830127],
        };
        for frame in [RobotFrame::Cell, RobotFrame::Base] {
            for uframe in [Some(&u), None] {
                let want = uframe.map_or(Isometry3::identity(), |u| u.isometry()) * pose.isometry();
                let data = pl.robtarget_data(frame, uframe, &pose);
                let got = pl.data_frame(frame, uframe) * data.isometry();
                let mm = (got.translation.vector - want.translation.vector).norm();
                let deg = got.rotation.angle_to(&want.rotation).to_degrees();
                assert!(
                    mm < 2e-3 && deg < 1e-5,
                    "{frame:?} {uframe:?}: {mm} mm {deg} deg"
                );
                // The data are as written: rounding them again changes nothing.
                assert_eq!(data.written(), data, "{frame:?} {uframe:?}");
            }
        }
        // In the base frame without a work object the data are the base-frame pose.
        let d = pl.robtarget_data(RobotFrame::Base, None, &pose);
        assert_eq!(d, pl.written(RobotFrame::Base, &pose));
        assert_eq!(pl.data_frame(RobotFrame::Base, None), pl.cell_from_robot());
    }
}
