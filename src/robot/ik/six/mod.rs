//! Six-axis inverse kinematics for a spherical-wrist arm: a flange (tool0) or TCP pose -> every
//! set of controller axis values that reaches it, each with its ABB confdata.
//!
//! Stage: a pose in the robot base frame (mm, [`Isometry3`]) -> [`Solution`]s (controller values
//! in degrees, what a RAPID `jointtarget` holds, and `[cf1, cf4, cf6, cfx]`). Paper: Ting & Jar
//! (2006) plan axes 1..3 for a wrist-centre position (section 3, `crate::robot::ik::wrist`); this module goes
//! beyond the paper: it solves the whole pose, so points can be given as robtargets with a tool.
//!
//! # The arm it handles, derived from the URDF
//! Nothing here knows IRB 1400 figures. [`SixAxisIk::from_robot`] puts the robot in its zero
//! pose (URDF joints all 0) through the robot's own forward kinematics and reads each joint's
//! axis as a line in the base frame. It accepts the arm when:
//! - axis 2 is perpendicular to axis 1, and axis 3 is parallel to axis 2 (a planar arm turned by
//!   axis 1; a lateral shoulder offset along axis 2 is allowed);
//! - axes 4, 5 and 6 meet in one point, the wrist centre (within 1e-6 mm), with axis 5
//!   perpendicular to axes 4 and 6;
//! - both arm links have a length, and the arm's forward direction and the front side of the
//!   lower arm can be told at the zero pose (see `conf.rs`);
//! - the controller's coupling is an integer-linear map (Serial, or the parallelogram's
//!   `axis 3 = q3 + q2`), read by probing the public `Robot::urdf_joints_deg`, so any axis
//!   turned by a full turn gives the same pose.
//!
//! Anything else is refused with [`SixAxisError::Structure`] saying which condition fails.
//!
//! # How it solves (product of exponentials, Paden-Kahan subproblems)
//! With the zero-pose axis lines `S1..S6` and the zero-pose tool0 `M`, the forward kinematics is
//! `T(q) = e^{S1 q1} ... e^{S6 q6} M` (URDF joint values `q`). The wrist centre `W` lies on
//! axes 4..6, so the tool0 pose gives it at once; then:
//! 1. axis 1: turning back by `q1` must bring `W` into the arm plane (offset along axis 2 as at
//!    the zero pose): `rho cos(q1 - phi) = offset`, two solutions (half a turn apart without a
//!    shoulder offset);
//! 2. axis 3: the distance from axis 2 to `W` fixes the elbow: two solutions (law of cosines);
//! 3. axis 2: one rotation carries the elbow's wrist centre onto `W`;
//! 4. wrist: `R4 R5 R6 = (R1 R2 R3)^T R_tool0 M^T`; axes 4 and 5 bring axis 6 onto its target
//!    direction (two solutions, the wrist flip), axis 6 the rest.
//!
//! That gives up to 8 solutions; each is wrapped into (-180, 180] in controller values and then
//! repeated by every full turn that keeps its axes in range (IRB 1400 axis 6, +-300 deg, gives
//! two of each). Values within 1e-9 deg outside a limit are snapped onto it, the coupled axis-3
//! range by moving axis 3 (a target given at a limit solves). All six ranges and the coupled
//! range apply (`Robot::check_range6`); [`SixAxisIk::candidates`] keeps the out-of-range
//! branches with every limit they break, for messages.
//!
//! # Singular poses: deterministic choices
//! - **Wrist** (axes 4 and 6 in line, `|sin(axis 5)| < 1e-10`): only `q4 + q6` is fixed. Axis 4
//!   keeps the `previous` pose's axis-4 value (0 without one); axis 6 takes the rest. One wrist
//!   solution instead of two (the flip is the same joint vector family). Its cf4 is that of the
//!   kept axis 4, so at an exact wrist singularity a robtarget asking another cf4 is reported
//!   unreachable (with the confdata that are reachable).
//! - **Wrist centre on the axis-1 line** (within 1e-9 mm): axis 1 keeps the previous value (0
//!   without one), and that plus half a turn gives the second stance.
//! - **Wrist centre on axis 2** (only arms with equal link lengths): axis 2 keeps the previous
//!   value (0 without one).
//!
//! # Confdata
//! [`ConfData`]: cf1, cf4, cf6 are `floor(axis / 90 deg)` of axes 1, 4, 6; cfx is
//! `4 * (wrist centre behind axis 1) + 2 * (wrist centre behind the lower arm) + 1 * (axis 5 < 0)`
//! (RAPID reference manual, `confdata`). "Behind axis 1" is measured from axis 1 itself
//! ([`CFX_BEHIND_AXIS_1_FROM`]; `conf.rs` says why, and keeps the alternative). With that reading
//! the cfx bits are exactly the three branch choices above, so every solution of a pose has its
//! own confdata, apart from the singular poses. On a quadrant boundary one rule holds
//! (`conf.rs`): the confdata of values is that of the values rounded as written, and a value
//! within [`QUADRANT_TOL_DEG`] of a quadrant is admitted for it when choosing by confdata.
//!
//! # Choosing one
//! [`SixAxisIk::choose`] takes the confdata a robtarget asks for, or else orders the solutions
//! by the time of the joint move from the previous point at the controller's axis speeds, then
//! the Euclidean joint distance, then the fixed order of [`SixAxisIk::solve`] (`choose.rs`), and
//! returns the first the caller's predicate (its collision check) accepts, keeping the reasons
//! of those it refused. [`SixAxisIk::rounding_bound`] bounds how far the TCP moves when the
//! chosen joints are rounded for the module (`bound.rs`).
//!
//! # Why not the `rs-opw-kinematics` crate
//! We read it (3.0.0 and the nalgebra-based 1.8.20; BSD-3, actively maintained, with a
//! `Parallelogram` wrapper that adds `q2` to `q3` as our coupling does). Its OPW parameters could
//! be derived from our URDF (`a1` = 150, `a2` = -120, `c1` = 475, `c2` = 600, `c3` = 720,
//! `c4` = 85, joint-3 offset -90 deg for the IRB 1400). It does not fit:
//! - 3.0.0 needs Rust 1.88 (let-chains in always-compiled code; no `rust-version` declared), we
//!   promise 1.85; it speaks `glam` poses beside our nalgebra; and it pulls `rand` 0.10 with
//!   `chacha20`/`getrandom`, `anyhow` and `once_cell` even with default features off. 1.8.x is a
//!   superseded major line;
//! - it returns an unlabelled list of joint vectors (unreachable and non-verifying candidates
//!   dropped silently), so the failure reasons this module must give (out of reach by how much,
//!   axis 5 beyond its range, each branch's range violations, which confdata exist) need the
//!   branch analysis done here anyway; the arm and wrist closed forms are the small part;
//! - its singular-pose handling (sampled searches near a reference) is not the single documented
//!   choice above, and it does not enumerate the extra turns of axes whose range exceeds 360 deg.
//!
//! The tests hold this solver against the robot's own forward kinematics (`Robot::tool0`, the
//! URDF chain), a different computation from the one solved here.

mod bound;
#[cfg(test)]
mod boundary_tests;
mod choose;
#[cfg(test)]
mod choose_tests;
mod conf;
mod enclose;
#[cfg(test)]
mod enclose_tests;
mod error;
mod solve;
#[cfg(test)]
mod tests;

pub use bound::PoseBound;
pub use choose::{move_cost, ChooseError, MoveCost};
pub use conf::{BehindAxis1From, ConfData, CFX_BEHIND_AXIS_1_FROM, QUADRANT_TOL_DEG};
pub use enclose::{Enclosure, PoseForm, Signs, CONSTANT_EPS};
pub use error::{describe_violation, excess_deg, Candidate, SixAxisError};

use crate::robot::{Axes6, Robot};
use nalgebra::{Isometry3, Matrix6, Point3, Rotation3, Unit, Vector3, Vector6};

/// Tolerance on products of unit vectors (perpendicular / parallel axes).
const DIRECTION_TOL: f64 = 1e-9;
/// Tolerance on offsets that must be zero (axes meeting in a point), mm.
const OFFSET_TOL_MM: f64 = 1e-6;
/// Distance of the wrist centre from the axis-1 (or axis-2) line below which that axis is free.
const SINGULAR_LINE_MM: f64 = 1e-9;
/// `|sin(axis 5)|` below which axes 4 and 6 count as in line.
const SINGULAR_WRIST: f64 = 1e-10;
/// A value this close outside a limit is snapped onto it, deg.
const LIMIT_SNAP_DEG: f64 = 1e-9;
/// Slack on the elbow cosine, so poses exactly on the reach boundary solve.
const COS_SLACK: f64 = 1e-10;
/// Two solutions closer than this in every axis are one, deg.
const SAME_DEG: f64 = 1e-9;

/// One solution: controller values of axes 1..6 (degrees, all in range) and their confdata.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solution {
    pub axes_deg: Axes6,
    pub conf: ConfData,
}

/// A line in the robot base frame, mm.
#[derive(Clone, Copy, Debug)]
struct Line {
    point: Point3<f64>,
    dir: Unit<Vector3<f64>>,
}

impl Line {
    /// `p` turned by `angle_rad` about this line.
    fn rotate(&self, angle_rad: f64, p: &Point3<f64>) -> Point3<f64> {
        self.point + Rotation3::from_axis_angle(&self.dir, angle_rad) * (p - self.point)
    }

    /// The foot of the perpendicular from `p`.
    fn foot(&self, p: &Point3<f64>) -> Point3<f64> {
        self.point + self.dir.into_inner() * self.dir.dot(&(p - self.point))
    }

    fn distance(&self, p: &Point3<f64>) -> f64 {
        (p - self.foot(p)).norm()
    }
}

/// Controller values `a` <-> URDF joint values `q = A a + c` (degrees), `A` integer.
#[derive(Clone, Debug)]
struct LinearCoupling {
    to_urdf: Matrix6<f64>,
    offset_deg: Vector6<f64>,
    to_controller: Matrix6<f64>,
}

impl LinearCoupling {
    fn probe(robot: &Robot) -> Result<LinearCoupling, String> {
        let f = |a: [f64; 6]| Vector6::from(robot.urdf_joints_deg(&a));
        let offset_deg = f([0.0; 6]);
        let mut to_urdf = Matrix6::zeros();
        for k in 0..6 {
            let mut e = [0.0; 6];
            e[k] = 1.0;
            let col = f(e) - offset_deg;
            for (i, v) in col.iter().enumerate() {
                if (v - v.round()).abs() > 1e-12 {
                    return Err(format!(
                        "the controller's coupling gives URDF joint {} a factor {v} of axis {}; \
                         only integer-linear couplings keep full turns of an axis pose-neutral",
                        i + 1,
                        k + 1
                    ));
                }
                to_urdf[(i, k)] = v.round();
            }
        }
        for probe in [
            [13.0, -27.0, 41.0, -55.0, 67.0, -79.0],
            [170.0, 70.0, -65.0, 150.0, 115.0, 300.0],
        ] {
            let lin = to_urdf * Vector6::from(probe) + offset_deg;
            if (f(probe) - lin).amax() > 1e-9 {
                return Err("the controller's coupling is not linear".into());
            }
        }
        let inv = to_urdf
            .try_inverse()
            .ok_or("the controller's coupling cannot be inverted")?;
        // A unimodular coupling (the parallelogram) has an integer inverse: make it exact.
        let to_controller = if inv.iter().all(|v| (v - v.round()).abs() < 1e-12) {
            inv.map(f64::round)
        } else {
            inv
        };
        Ok(LinearCoupling {
            to_urdf,
            offset_deg,
            to_controller,
        })
    }

    fn urdf_rad(&self, axes_deg: &Axes6) -> [f64; 6] {
        let q = self.to_urdf * Vector6::from(*axes_deg) + self.offset_deg;
        std::array::from_fn(|i| q[i].to_radians())
    }

    fn controller_deg(&self, q_rad: &[f64; 6]) -> Axes6 {
        let q = Vector6::from(q_rad.map(f64::to_degrees)) - self.offset_deg;
        let a = self.to_controller * q;
        std::array::from_fn(|i| a[i])
    }
}

/// The six-axis solver of one robot (owns a copy of it; cheap to clone).
#[derive(Clone, Debug)]
pub struct SixAxisIk {
    robot: Robot,
    coupling: LinearCoupling,
    /// URDF joint axes at the zero pose, base frame.
    axes: [Line; 6],
    /// tool0 at the zero pose.
    tool0_zero: Isometry3<f64>,
    /// Wrist centre at the zero pose.
    wrist_zero: Point3<f64>,
    /// Wrist centre in the tool0 frame (constant).
    wrist_in_tool0: Vector3<f64>,
    /// Points of axes 1, 2, 3 in the arm plane (the plane through the wrist centre normal to
    /// axis 2) at the zero pose: feet of the perpendiculars.
    axis1_foot: Point3<f64>,
    shoulder: Point3<f64>,
    elbow: Point3<f64>,
    upper_arm_mm: f64,
    forearm_mm: f64,
    /// Offset of the arm plane from axis 1 along axis 2 (0 for most arms), mm.
    shoulder_offset_mm: f64,
    /// The arm's forward direction at the zero pose (normal to axes 1 and 2).
    forward_zero: Unit<Vector3<f64>>,
    /// Sign of `u2 . ((elbow - shoulder) x (W - shoulder))` on the lower arm's front side.
    front_sign: f64,
}

impl SixAxisIk {
    /// Derives the solver from the robot's joint layout and controller (see the module docs).
    pub fn from_robot(robot: &Robot) -> Result<SixAxisIk, SixAxisError> {
        let refuse = |message: String| SixAxisError::Structure {
            robot: robot.name.clone(),
            message,
        };
        if robot.joints.len() != 6 {
            return Err(refuse(format!(
                "it has {} joints; 6 are needed",
                robot.joints.len()
            )));
        }
        let coupling = LinearCoupling::probe(robot).map_err(refuse)?;
        let zero_axes = coupling.controller_deg(&[0.0; 6]);
        let poses = robot.link_poses(&zero_axes);
        let axes: [Line; 6] = std::array::from_fn(|i| Line {
            point: Point3::from(poses[i].translation.vector),
            dir: poses[i].rotation * robot.joints[i].axis,
        });
        let tool0_zero = robot.tool0(&zero_axes);
        let [a1, a2, a3, a4, a5, a6] = axes;

        if a1.dir.dot(&a2.dir).abs() > DIRECTION_TOL {
            return Err(refuse(format!(
                "axis 2 is not perpendicular to axis 1 (cos = {:.3e})",
                a1.dir.dot(&a2.dir)
            )));
        }
        if a2.dir.cross(&a3.dir).norm() > DIRECTION_TOL {
            return Err(refuse("axis 3 is not parallel to axis 2".into()));
        }
        for (i, (x, y)) in [(a4, a5), (a5, a6)].iter().enumerate() {
            if x.dir.dot(&y.dir).abs() > DIRECTION_TOL {
                return Err(refuse(format!(
                    "axis {} is not perpendicular to axis {} (a spherical wrist needs axes 4 _|_ 5 \
                     _|_ 6)",
                    i + 5,
                    i + 4
                )));
            }
        }
        // Wrist centre: nearest points of axes 4 and 5 (perpendicular, so never parallel).
        let (p4, p5) = closest_points(&a4, &a5);
        let gap = (p4 - p5).norm();
        let wrist_zero = Point3::from((p4.coords + p5.coords) / 2.0);
        let gap6 = a6.distance(&wrist_zero);
        if gap > OFFSET_TOL_MM || gap6 > OFFSET_TOL_MM {
            return Err(refuse(format!(
                "axes 4, 5 and 6 do not meet in one point (axes 4 and 5 pass {gap:.6} mm apart, \
                 axis 6 {gap6:.6} mm from their meeting point); the closed form needs a spherical \
                 wrist"
            )));
        }
        let shoulder = a2.foot(&wrist_zero);
        let elbow = a3.foot(&wrist_zero);
        let axis1_foot = a1.foot(&shoulder);
        let upper_arm_mm = (elbow - shoulder).norm();
        let forearm_mm = (wrist_zero - elbow).norm();
        if upper_arm_mm <= OFFSET_TOL_MM {
            return Err(refuse("axes 2 and 3 coincide (no upper arm)".into()));
        }
        if forearm_mm <= OFFSET_TOL_MM {
            return Err(refuse(
                "the wrist centre lies on axis 3 (no forearm)".into(),
            ));
        }
        let shoulder_offset_mm = a2.dir.dot(&(wrist_zero - a1.point));

        // Forward: normal to axes 1 and 2, towards the wrist centre (or axis 2) at zero pose.
        let (n1, n2) = (a1.dir.into_inner(), a2.dir.into_inner());
        let horizontal = |v: Vector3<f64>| v - n1 * n1.dot(&v) - n2 * n2.dot(&v);
        let forward_zero = [wrist_zero - a1.point, shoulder - a1.point]
            .into_iter()
            .map(horizontal)
            .find(|v| v.norm() > OFFSET_TOL_MM)
            .map(Unit::new_normalize)
            .ok_or_else(|| {
                refuse(
                    "at the zero pose the wrist centre and axis 2 both lie on axis 1, so the arm's \
                     forward direction is undefined"
                        .into(),
                )
            })?;
        let lower = elbow - shoulder;
        let sigma_wrist = a2.dir.dot(&lower.cross(&(wrist_zero - shoulder)));
        let sigma_forward = a2.dir.dot(&lower.cross(&forward_zero));
        let front_sign = if sigma_wrist.abs() > 1e-9 * upper_arm_mm * forearm_mm {
            sigma_wrist.signum()
        } else if sigma_forward.abs() > 1e-9 * upper_arm_mm {
            sigma_forward.signum()
        } else {
            return Err(refuse(
                "at the zero pose the wrist centre lies on the lower arm's line and the lower arm \
                 points forward, so its front side is undefined"
                    .into(),
            ));
        };
        let wrist_in_tool0 = tool0_zero.inverse_transform_point(&wrist_zero).coords;
        Ok(SixAxisIk {
            robot: robot.clone(),
            coupling,
            axes,
            tool0_zero,
            wrist_zero,
            wrist_in_tool0,
            axis1_foot,
            shoulder,
            elbow,
            upper_arm_mm,
            forearm_mm,
            shoulder_offset_mm,
            forward_zero,
            front_sign,
        })
    }

    /// The robot this solver was built from.
    pub fn robot(&self) -> &Robot {
        &self.robot
    }

    /// Distance from axis 2 to axis 3 and from axis 3 to the wrist centre, mm.
    pub fn link_lengths_mm(&self) -> (f64, f64) {
        (self.upper_arm_mm, self.forearm_mm)
    }

    /// The wrist centre at the zero pose (all URDF joints 0), robot base frame, mm.
    pub fn wrist_centre_zero(&self) -> Point3<f64> {
        self.wrist_zero
    }

    /// The wrist centre in the tool0 (flange) frame, mm: the same in every pose. With a tool's
    /// `tframe` it gives the wrist centre of a TCP pose without solving anything (`base: auto`).
    pub fn wrist_in_tool0(&self) -> Vector3<f64> {
        self.wrist_in_tool0
    }

    /// Shortest and longest distance from axis 2 to the wrist centre the arm can make, mm
    /// (geometry only; the axis ranges are not applied).
    pub fn reach_mm(&self) -> (f64, f64) {
        (
            (self.upper_arm_mm - self.forearm_mm).abs(),
            self.upper_arm_mm + self.forearm_mm,
        )
    }

    /// The flange (tool0) pose that puts a tool's TCP (`tframe`: TCP in the tool0 frame) at
    /// `tcp` (robot base frame).
    pub fn tool0_for_tcp(tcp: &Isometry3<f64>, tframe: &Isometry3<f64>) -> Isometry3<f64> {
        tcp * tframe.inverse()
    }

    /// Every in-range solution for a tool0 pose (robot base frame, mm), in a fixed order (by cfx,
    /// cf1, cf4, cf6, then axis values). `previous` only settles the singular choices (module
    /// docs). An error says why there is none.
    pub fn solve(
        &self,
        tool0: &Isometry3<f64>,
        previous: Option<&Axes6>,
    ) -> Result<Vec<Solution>, SixAxisError> {
        let a = self.analyse(tool0, previous)?;
        if !a.solutions.is_empty() {
            return Ok(a.solutions);
        }
        Err(self.why_none(a))
    }

    /// [`solve`](Self::solve) for a TCP pose and the tool's `tframe` (TCP in the tool0 frame).
    pub fn solve_tcp(
        &self,
        tcp: &Isometry3<f64>,
        tframe: &Isometry3<f64>,
        previous: Option<&Axes6>,
    ) -> Result<Vec<Solution>, SixAxisError> {
        self.solve(&Self::tool0_for_tcp(tcp, tframe), previous)
    }

    /// Every branch for a tool0 pose, in range or not: one [`Candidate`] per branch (up to 8;
    /// the full turn of each axis nearest to its range), with its range violations (empty when
    /// in range). Errors only for a pose that is not finite or out of the arm's reach.
    pub fn candidates(
        &self,
        tool0: &Isometry3<f64>,
        previous: Option<&Axes6>,
    ) -> Result<Vec<Candidate>, SixAxisError> {
        Ok(self.analyse(tool0, previous)?.candidates)
    }

    /// The confdata of controller values (any values, in range or not), as written: of the
    /// values rounded to the written precision (`conf.rs`).
    pub fn conf(&self, axes_deg: &Axes6) -> ConfData {
        self.conf_with(axes_deg, CFX_BEHIND_AXIS_1_FROM)
    }

    /// tool0 pose of controller values, by the robot's own forward kinematics.
    pub fn tool0(&self, axes_deg: &Axes6) -> Isometry3<f64> {
        self.robot.tool0(axes_deg)
    }

    /// `p` carried by URDF joints `q[..n]` (product of exponentials, zero-pose lines).
    fn carry(&self, q_rad: &[f64; 6], n: usize, p: Point3<f64>) -> Point3<f64> {
        (0..n)
            .rev()
            .fold(p, |p, i| self.axes[i].rotate(q_rad[i], &p))
    }

    /// Axis `j` (0-based) as a line at URDF joints `q`.
    fn axis_at(&self, q_rad: &[f64; 6], j: usize) -> Line {
        let l = self.axes[j];
        let tip = self.carry(q_rad, j, l.point + l.dir.into_inner());
        let point = self.carry(q_rad, j, l.point);
        Line {
            point,
            dir: Unit::new_normalize(tip - point),
        }
    }

    /// Rotation of axes `1..=n` about their zero-pose directions, composed.
    fn rotation(&self, q_rad: &[f64], first: usize) -> Rotation3<f64> {
        q_rad
            .iter()
            .enumerate()
            .fold(Rotation3::identity(), |r, (k, &q)| {
                r * Rotation3::from_axis_angle(&self.axes[first + k].dir, q)
            })
    }
}

/// Nearest points of two non-parallel lines (one on each).
fn closest_points(a: &Line, b: &Line) -> (Point3<f64>, Point3<f64>) {
    let w0 = a.point - b.point;
    let (da, db) = (a.dir.into_inner(), b.dir.into_inner());
    let k = da.dot(&db);
    let (d, e) = (da.dot(&w0), db.dot(&w0));
    let den = 1.0 - k * k;
    let s = (k * e - d) / den;
    let t = (e - k * d) / den;
    (a.point + da * s, b.point + db * t)
}
