//! How far the TCP can move when the joint values of a solution are rounded for the module.
//!
//! The module writes joints to a fixed number of decimals (0.001 deg), so every controller axis
//! changes by at most `e` (0.0005 deg). Through the coupling each URDF joint `j` changes by at
//! most `dq_j = e * sum_i |A_ji|` (the parallelogram's `q3 = a3 - a2` by `2e`). The bound is
//! rigorous, not a linearisation:
//! - rotation: the frame turns by at most `sum_j dq_j` (the angle of a product of rotations is at
//!   most the sum of their angles);
//! - position: along the straight joint path from the solution to the rounded values, the TCP's
//!   speed is at most `sum_j dq_j * dist(TCP, axis j)`, and each distance grows along the path
//!   by at most `L * sum_k dq_k`, where `L` bounds the TCP's distance from any axis in any pose
//!   (the chain TCP -> wrist centre -> axis 3 -> axis 2 -> axis 1, each link rigid). So
//!   `|dp| <= sum_j dq_j * (dist_j + L * sum_k dq_k)` with the distances at the solution.

use super::SixAxisIk;
use crate::robot::Axes6;
use nalgebra::{Isometry3, Point3};

/// An upper bound on how far a pose moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseBound {
    pub position_mm: f64,
    pub rotation_rad: f64,
}

impl SixAxisIk {
    /// Bound on the TCP's move (tool `tframe`, TCP in the tool0 frame) when every controller
    /// axis of `axes_deg` changes by at most `max_change_deg` (rounding to 0.001 deg: 0.0005).
    pub fn rounding_bound(
        &self,
        axes_deg: &Axes6,
        tframe: &Isometry3<f64>,
        max_change_deg: f64,
    ) -> PoseBound {
        let e = max_change_deg.abs().to_radians();
        let dq: [f64; 6] = std::array::from_fn(|j| {
            e * (0..6)
                .map(|i| self.coupling.to_urdf[(j, i)].abs())
                .sum::<f64>()
        });
        let total: f64 = dq.iter().sum();
        let q = self.coupling.urdf_rad(axes_deg);
        let tcp = (self.robot.tool0(axes_deg) * tframe) * Point3::origin();
        let wrist = self.carry(&q, 3, self.wrist_zero);
        let reach = (tcp - wrist).norm()
            + self.forearm_mm
            + self.upper_arm_mm
            + (self.shoulder - self.axis1_foot).norm();
        let position_mm = (0..6)
            .map(|j| dq[j] * (self.axis_at(&q, j).distance(&tcp) + reach * total))
            .sum();
        PoseBound {
            position_mm,
            rotation_rad: total,
        }
    }
}
