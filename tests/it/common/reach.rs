//! How far any point of the arm or the tool can move when the joints turn, and how finely the
//! dense check samples so that the clearance cannot slip between two samples.
//!
//! A point carried by the child link of joint j moves, when joint k <= j turns by dq radians,
//! by at most its distance from joint k's axis times |dq|, and that distance is at most its
//! distance from joint k's origin: at most the lengths of the joint origins from k + 1 to j
//! (`RevoluteJoint::origin`, fixed joints folded in) plus its own distance from its link
//! frame's origin (`LinkShape::extent_mm`; for the tool, tool0's offset from the flange plus
//! the tool's extent). The bound R_k is the largest of those over everything joint k carries,
//! and a joint move dq (URDF joints: the coupling is linear, so a straight move of the
//! controller's axes is straight in the URDF's) moves no point more than `sum_k R_k |dq_k|`.
//!
//! The sampling step is a tenth of the cell's clearance, at most 1 mm and at least 0.05 mm:
//! every point of the robot is between two samples within half a step of where it is at one of
//! them, so the true minimum along a move lies at most half a step below the smallest sample.

use super::library::Robot;
use super::links::LinkShape;

/// The largest sampling step, mm.
pub const STEP_MAX_MM: f64 = 1.0;
/// The smallest sampling step (a cell whose clearance is nearly 0), mm.
pub const STEP_MIN_MM: f64 = 0.05;

/// The dense check's sampling step for a clearance (module doc), mm.
pub fn sample_step_mm(clearance_mm: f64) -> f64 {
    (clearance_mm / 10.0).clamp(STEP_MIN_MM, STEP_MAX_MM)
}

/// The bound R_k of each joint (module doc), mm per radian.
#[derive(Clone, Copy, Debug)]
pub struct Reach {
    pub radii_mm: [f64; 6],
}

impl Reach {
    /// The bounds for `robot` carrying `links` and a tool whose points lie within
    /// `tool_extent_mm` of tool0 (0 without a tool).
    pub fn new(robot: &Robot, links: &[LinkShape], tool_extent_mm: f64) -> Reach {
        let origin = |i: usize| robot.joints[i].origin.translation.vector.norm();
        // From joint k's origin to the origin of joint j's child link frame, at most.
        let chain = |k: usize, j: usize| (k + 1..=j).map(origin).sum::<f64>();
        let flange = robot.flange_to_tool0.translation.vector.norm();
        let radii_mm = std::array::from_fn(|k| {
            let tool = match tool_extent_mm > 0.0 {
                true => chain(k, 5) + flange + tool_extent_mm,
                false => 0.0,
            };
            links
                .iter()
                .filter_map(|l| {
                    l.carrier
                        .filter(|&j| j >= k)
                        .map(|j| chain(k, j) + l.extent_mm)
                })
                .fold(tool, f64::max)
        });
        Reach { radii_mm }
    }

    /// The most any point moves along the straight joint move `a -> b` (controller values), mm.
    pub fn motion_mm(&self, robot: &Robot, a: &[f64; 6], b: &[f64; 6]) -> f64 {
        let (qa, qb) = (robot.urdf_joints_deg(a), robot.urdf_joints_deg(b));
        (0..6)
            .map(|k| self.radii_mm[k] * (qb[k] - qa[k]).abs().to_radians())
            .sum()
    }
}
