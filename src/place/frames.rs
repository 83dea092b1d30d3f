//! Where the robot stands, and the two frames that meet there: the cell frame (the cell file's
//! positions and boxes) and the robot base frame (kinematics, inverse kinematics).

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
}
