//! The test suite's own inverse kinematics, independent of the library's (`robot::ik`): the OPW
//! closed form of Brandstötter, Angerer and Hofbaur (2014), "An analytical solution of the
//! inverse kinematics problem of industrial serial manipulators with an ortho-parallel basis and
//! a spherical wrist" (Austrian Robotics Workshop), for any six-axis arm of that kind.
//!
//! # The parameters, read off the robot's joints
//!
//! The arm must be the URDF chain of an OPW robot (the ROS-Industrial layout of ABB's arms):
//! every joint origin without rotation, axes z, y, y, x, y, x (each may point the other way:
//! that joint's sign), joint 3 straight above joint 2 in link 2's frame, joints 5 and 6 and
//! `tool0` on axis 4 and axis 6 (a spherical wrist), `tool0` turned +90 deg about link 6's y
//! axis (its z along axis 6). Then, with `t_k` joint k's origin in its parent's frame:
//!
//! - the OPW base frame is the robot base moved to axis 1 (`t_1.x`, `t_1.y`);
//! - `a1 = t_2.x`, `c1 = t_1.z + t_2.z`, `c2 = t_3.z`, `a2 = -t_4.z`, `c3 = t_4.x + t_5.x`,
//!   `c4 = t_6.x + tool0.x`, `b = t_2.y + t_3.y + t_4.y`;
//! - OPW's angles are the URDF's with the signs, and `theta3 = q3 + 90 deg` (OPW's zero pose
//!   stands upright, the URDF's holds the forearm level).
//!
//! Anything else is refused with why, so a robot this cannot solve fails the test instead of
//! being checked wrongly.
//!
//! # The solutions
//!
//! [`Ik::branches`] gives OPW's eight (shoulder front or back, elbow up or down, wrist flipped or
//! not) as controller values (axis 3 = URDF q3 + q2 on a parallelogram robot), each axis in
//! -180 .. 180 deg; [`Ik::in_range`] turns every axis by whole turns into the controller's range
//! (axes 4 and 6 often have two turns in range), keeps the coupled axis-3 range, and says each
//! one's confdata (`tcp::confdata`, the RAPID definition); [`Ik::nearest`] turns each axis by
//! whole turns nearest given joints and takes the branch nearest them.

use super::library::{Coupling, Robot};
use super::tcp::confdata;
use nalgebra::{Isometry3, Matrix3, UnitQuaternion, Vector3};

/// Geometric tolerance of the layout checks (mm, and radians of the frames' rotations).
const LAYOUT_TOL: f64 = 1e-9;

/// A value within this of a quadrant boundary (deg) is taken to lie in either quadrant: half
/// the 0.001 deg step of the module's joint values.
pub const QUADRANT_TOL_DEG: f64 = 0.0005;

/// The OPW parameters of an arm (mm) and how its URDF joints map to OPW's angles.
#[derive(Clone, Debug, PartialEq)]
pub struct Opw {
    pub a1: f64,
    pub a2: f64,
    pub b: f64,
    pub c1: f64,
    pub c2: f64,
    pub c3: f64,
    pub c4: f64,
    /// Where axis 1 meets the base plane, in the robot base frame, mm.
    origin: Vector3<f64>,
    /// +1 or -1: the URDF axis along or against OPW's.
    sign: [f64; 6],
}

fn near(a: f64, b: f64) -> bool {
    (a - b).abs() <= LAYOUT_TOL * (1.0 + a.abs().max(b.abs()))
}

impl Opw {
    /// Reads the parameters off `robot`'s joints (module doc), or says why the arm is not one
    /// this closed form solves.
    pub fn of(robot: &Robot) -> Result<Opw, String> {
        let j = &robot.joints;
        if j.len() != 6 {
            return Err(format!("{} joints, an OPW arm has 6", j.len()));
        }
        let expected = [
            Vector3::z(),
            Vector3::y(),
            Vector3::y(),
            Vector3::x(),
            Vector3::y(),
            Vector3::x(),
        ];
        let mut sign = [0.0; 6];
        for k in 0..6 {
            if j[k].origin.rotation.angle() > LAYOUT_TOL {
                return Err(format!("joint {}'s origin is turned", k + 1));
            }
            let dot = j[k].axis.dot(&expected[k]);
            if !near(dot.abs(), 1.0) {
                return Err(format!(
                    "joint {}'s axis {:?} is not {:?} (either way)",
                    k + 1,
                    j[k].axis.into_inner(),
                    expected[k]
                ));
            }
            sign[k] = dot.signum();
        }
        let t = |k: usize| j[k].origin.translation.vector;
        let flange = &robot.flange_to_tool0;
        let f = flange.translation.vector;
        let zero = |v: f64, what: &str| match near(v, 0.0) {
            true => Ok(()),
            false => Err(format!("{what} is {v} mm, an OPW arm has 0")),
        };
        zero(t(2).x, "joint 3's origin x (along the upper arm's normal)")?;
        zero(t(4).y, "joint 5's origin y (off axis 4)")?;
        zero(t(4).z, "joint 5's origin z (off axis 4)")?;
        zero(t(5).y, "joint 6's origin y (off axis 5's centre)")?;
        zero(t(5).z, "joint 6's origin z (off axis 5's centre)")?;
        zero(f.y, "tool0's y (off axis 6)")?;
        zero(f.z, "tool0's z (off axis 6)")?;
        let want = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2);
        if flange.rotation.angle_to(&want) > LAYOUT_TOL {
            return Err("tool0 is not turned +90 deg about link 6's y axis".into());
        }
        Ok(Opw {
            a1: t(1).x,
            a2: -t(3).z,
            b: t(1).y + t(2).y + t(3).y,
            c1: t(0).z + t(1).z,
            c2: t(2).z,
            c3: t(3).x + t(4).x,
            c4: t(5).x + f.x,
            origin: Vector3::new(t(0).x, t(0).y, 0.0),
            sign,
        })
    }

    /// OPW's eight solutions for `tool0` (its pose in the robot base frame) as URDF joint
    /// values, deg, each in -180 .. 180; `None` for a branch that does not reach the pose.
    pub fn urdf_solutions(&self, tool0: &Isometry3<f64>) -> [Option<[f64; 6]>; 8] {
        let r: Matrix3<f64> = tool0.rotation.to_rotation_matrix().into_inner();
        let u = tool0.translation.vector - self.origin;
        let (a1, a2, b, c1, c2, c3, c4) =
            (self.a1, self.a2, self.b, self.c1, self.c2, self.c3, self.c4);
        // The wrist centre: c4 back along the end frame's z.
        let c = u - c4 * r.column(2);
        let nx1 = (c.x * c.x + c.y * c.y - b * b).sqrt() - a1;
        let tmp1 = c.y.atan2(c.x);
        let tmp2 = b.atan2(nx1 + a1);
        let theta1 = [tmp1 - tmp2, tmp1 + tmp2 - std::f64::consts::PI];
        let dz = c.z - c1;
        let s1_2 = nx1 * nx1 + dz * dz;
        let s2_2 = (nx1 + 2.0 * a1).powi(2) + dz * dz;
        let kappa_2 = a2 * a2 + c3 * c3;
        let c2_2 = c2 * c2;
        let (s1, s2) = (s1_2.sqrt(), s2_2.sqrt());
        let t13 = ((s1_2 + c2_2 - kappa_2) / (2.0 * s1 * c2)).acos();
        let t14 = nx1.atan2(dz);
        let t15 = ((s2_2 + c2_2 - kappa_2) / (2.0 * s2 * c2)).acos();
        let t16 = (nx1 + 2.0 * a1).atan2(dz);
        let theta2 = [-t13 + t14, t13 + t14, -t15 - t16, t15 - t16];
        let t9 = 2.0 * c2 * kappa_2.sqrt();
        let t10 = a2.atan2(c3);
        let t11 = ((s1_2 - c2_2 - kappa_2) / t9).acos();
        let t12 = ((s2_2 - c2_2 - kappa_2) / t9).acos();
        let theta3 = [t11 - t10, -t11 - t10, t12 - t10, -t12 - t10];
        let mut out = [None; 8];
        for i in 0..4 {
            let th1 = theta1[i / 2];
            let (s1, c1) = th1.sin_cos();
            let (s23, c23) = (theta2[i] + theta3[i]).sin_cos();
            let m = r[(0, 2)] * s23 * c1 + r[(1, 2)] * s23 * s1 + r[(2, 2)] * c23;
            let th4 = (r[(1, 2)] * c1 - r[(0, 2)] * s1)
                .atan2(r[(0, 2)] * c23 * c1 + r[(1, 2)] * c23 * s1 - r[(2, 2)] * s23);
            let th5 = (1.0 - m * m).max(0.0).sqrt().atan2(m);
            let th6 = (r[(0, 1)] * s23 * c1 + r[(1, 1)] * s23 * s1 + r[(2, 1)] * c23)
                .atan2(-r[(0, 0)] * s23 * c1 - r[(1, 0)] * s23 * s1 - r[(2, 0)] * c23);
            let pi = std::f64::consts::PI;
            for (k, wrist) in [[th4, th5, th6], [th4 + pi, -th5, th6 - pi]]
                .into_iter()
                .enumerate()
            {
                let theta = [th1, theta2[i], theta3[i], wrist[0], wrist[1], wrist[2]];
                if theta.iter().any(|v| !v.is_finite()) {
                    continue;
                }
                let q: [f64; 6] = std::array::from_fn(|a| {
                    let opw = if a == 2 {
                        theta[a] - std::f64::consts::FRAC_PI_2
                    } else {
                        theta[a]
                    };
                    wrap180((self.sign[a] * opw).to_degrees())
                });
                out[i + 4 * k] = Some(q);
            }
        }
        out
    }
}

/// `v` turned by whole turns into -180 .. 180 deg.
pub fn wrap180(v: f64) -> f64 {
    v - 360.0 * ((v + 180.0) / 360.0).floor()
}

/// A solution with the confdata the RAPID definition gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solution {
    /// Controller values, deg.
    pub axes: [f64; 6],
    pub conf: [i32; 4],
}

/// Whether controller values `axes` have confdata `conf` (the cf1, cf4, cf6 quadrants admitted
/// within [`QUADRANT_TOL_DEG`] of their bounds, cfx exactly); `cfx` is theirs.
pub fn conf_admits(axes: &[f64; 6], cfx: i32, conf: &[i32; 4]) -> bool {
    let admits = |v: f64, c: i32| {
        let lo = 90.0 * f64::from(c);
        (lo - QUADRANT_TOL_DEG..lo + 90.0 + QUADRANT_TOL_DEG).contains(&v)
    };
    admits(axes[0], conf[0])
        && admits(axes[3], conf[1])
        && admits(axes[5], conf[2])
        && cfx == conf[3]
}

/// The independent inverse kinematics of one robot in controller values.
#[derive(Clone, Debug)]
pub struct Ik<'a> {
    pub robot: &'a Robot,
    pub opw: Opw,
}

impl<'a> Ik<'a> {
    pub fn new(robot: &'a Robot) -> Result<Ik<'a>, String> {
        Ok(Ik {
            robot,
            opw: Opw::of(robot)?,
        })
    }

    /// Controller values of URDF joint values (the coupling: axis 3 = q3 + q2 on a
    /// parallelogram robot).
    pub fn controller(&self, q: &[f64; 6]) -> [f64; 6] {
        let mut a = *q;
        if self.robot.controller.coupling == Coupling::Parallelogram {
            a[2] = q[2] + q[1];
        }
        a
    }

    /// The eight branches for `tool0` (base frame) in controller values, each axis in
    /// -180 .. 180 deg (`None`: the branch does not reach the pose).
    pub fn branches(&self, tool0: &Isometry3<f64>) -> [Option<[f64; 6]>; 8] {
        self.opw
            .urdf_solutions(tool0)
            .map(|s| s.map(|q| self.controller(&q).map(wrap180)))
    }

    /// Every solution in the controller's ranges (the coupled axis-3 range too): each branch with
    /// its axes turned by whole turns into range, every combination, with its confdata.
    pub fn in_range(&self, tool0: &Isometry3<f64>) -> Vec<Solution> {
        let mut out = Vec::new();
        for b in self.branches(tool0).into_iter().flatten() {
            let turns: Vec<Vec<f64>> = (0..6)
                .map(|k| {
                    let spec = &self.robot.controller.axes[k];
                    (-3..=3)
                        .map(|n| b[k] + 360.0 * f64::from(n))
                        .filter(|v| (spec.min_deg..=spec.max_deg).contains(v))
                        .collect()
                })
                .collect();
            let mut combos = vec![[0.0; 6]];
            for (k, values) in turns.iter().enumerate() {
                combos = combos
                    .iter()
                    .flat_map(|c| {
                        values.iter().map(move |v| {
                            let mut c = *c;
                            c[k] = *v;
                            c
                        })
                    })
                    .collect();
            }
            for axes in combos {
                if self.robot.check_range6(&axes).is_ok() {
                    out.push(Solution {
                        axes,
                        conf: confdata(self.robot, &axes),
                    });
                }
            }
        }
        out
    }

    /// The in-range solutions whose confdata admits `conf` ([`conf_admits`]).
    pub fn with_conf(&self, tool0: &Isometry3<f64>, conf: &[i32; 4]) -> Vec<Solution> {
        self.in_range(tool0)
            .into_iter()
            .filter(|s| conf_admits(&s.axes, s.conf[3], conf))
            .collect()
    }

    /// The branch nearest `prev` (the largest axis difference smallest), each of its axes turned
    /// by whole turns nearest `prev`'s; `None` when no branch reaches the pose. Not limited to
    /// the ranges.
    pub fn nearest(&self, tool0: &Isometry3<f64>, prev: &[f64; 6]) -> Option<[f64; 6]> {
        self.branches(tool0)
            .into_iter()
            .flatten()
            .map(|b| {
                let a: [f64; 6] =
                    std::array::from_fn(|k| b[k] + 360.0 * ((prev[k] - b[k]) / 360.0).round());
                (max_diff(&a, prev), a)
            })
            .min_by(|x, y| x.0.total_cmp(&y.0))
            .map(|(_, a)| a)
    }
}

/// The largest axis difference of two configurations, deg.
pub fn max_diff(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    (0..6).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max)
}
