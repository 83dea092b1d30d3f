//! The closed form over an interval of a path's progress: for one branch (arm stance, elbow,
//! wrist flip), enclosures of every controller axis and of its rate of change along the path,
//! in interval arithmetic with derivatives (`ik::interval`). The follower's deviation bound
//! rests on it (`ik::follow`, "The deviation bound").
//!
//! The path's tool0 pose at progress `s` (robot base frame) is written in `s` the way
//! [`CartesianPath::pose_at`] makes it: the TCP position affine in `s` (a line) or on a circle
//! (`cos`, `sin` of `angle s`), the orientation `start * exp(s turn)` (a rotation about one
//! fixed axis by `|turn| s`), then the base and tool frames, both constant. Every constant (the
//! frames' rotation matrices and their products, the robot's zero-pose axis lines) is computed
//! once in floating point and enters as an interval [`CONSTANT_EPS`] wide relative to its size,
//! far above the rounding of its construction. The solver's steps (`mod.rs`, "How it solves")
//! then run on those enclosures with the branch's signs fixed: axis 1 from `atan2` and `acos`,
//! the elbow by the law of cosines (`acos`), axis 2 as a signed angle, the wrist from
//! `R_arm^T R_target` (axis 6's target direction, then axes 4, 5 and 6).
//!
//! An enclosure is given only where every step is defined with room on the whole interval:
//! the wrist centre off the axis-1 line and outside the shoulder offset (`rho > |offset|`), the
//! elbow neither stretched nor folded (`|cos| < 1`), axis 5 off 0 (axis 6's target not along
//! axis 4), every signed angle's two vectors off its axis. On such an interval the branch's
//! joints are a smooth function of `s`, its derivative the one enclosed, and no other branch
//! meets it (two branches meet only where one of those conditions fails).
//!
//! The values are enclosed modulo a full turn: each axis lies in `value + 360 k` for some
//! integer `k` (an angle from `atan2` is known up to full turns, and the coupling is
//! integer-linear). The rates need no turn.

use super::solve::signed_angle;
use super::SixAxisIk;
use crate::geometry::path::{CartesianPath, PathForm};
use crate::robot::ik::interval::{Dual, Interval};
use nalgebra::{Isometry3, Matrix3, Vector3};

/// The relative width of the interval a floating-point constant enters with (module docs).
pub const CONSTANT_EPS: f64 = 1e-12;

/// The signs that pick a branch (`mod.rs`, "How it solves"): axis 1 `phi +- d`, the elbow
/// `psi +- e`, the wrist `+-gamma`; `true` is `+`, the first the solver lists.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Signs {
    pub stance: bool,
    pub elbow: bool,
    pub flip: bool,
}

impl Signs {
    /// All eight.
    pub fn all() -> [Signs; 8] {
        std::array::from_fn(|k| Signs {
            stance: k & 4 == 0,
            elbow: k & 2 == 0,
            flip: k & 1 == 0,
        })
    }
}

/// Controller axes along a range of progress (module docs), deg: each axis's value modulo a
/// full turn and its derivative with respect to the progress.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Enclosure {
    pub value_deg: [Interval; 6],
    pub rate_deg: [Interval; 6],
}

/// A path's tool0 pose as a function of the progress, in constants (module docs): the wrist
/// centre `w0 + w_line s + w_cos cos(a s) + w_sin sin(a s) + t_cos cos(th s) + t_sin sin(th s)`
/// and the target rotation `R_target = r_const + r_cos cos(th s) + r_sin sin(th s)`.
#[derive(Clone, Copy, Debug)]
pub struct PoseForm {
    w0: Vector3<f64>,
    w_line: Vector3<f64>,
    /// The arc's angle `a` and its terms (zero for a line).
    arc_rad: f64,
    w_cos: Vector3<f64>,
    w_sin: Vector3<f64>,
    /// The turn's angle `th` and its terms.
    turn_rad: f64,
    t_cos: Vector3<f64>,
    t_sin: Vector3<f64>,
    r_const: Matrix3<f64>,
    r_cos: Matrix3<f64>,
    r_sin: Matrix3<f64>,
}

type V3 = [Dual; 3];
type M3 = [[Dual; 3]; 3];

/// A constant computed in floating point (module docs).
fn k(x: f64) -> Dual {
    Dual::near(x, CONSTANT_EPS)
}

/// A number that is exact: a sign, an integer of the coupling, 0.
fn exact(x: f64) -> Dual {
    Dual::constant(Interval::point(x))
}

/// A constant that is a product or quotient of exact inputs: within `CONSTANT_EPS` of its own
/// size (no cancellation in its construction).
fn kr(x: f64) -> Dual {
    Dual::constant(Interval::around(x, CONSTANT_EPS * x.abs()))
}

fn kv(v: &Vector3<f64>) -> V3 {
    [k(v.x), k(v.y), k(v.z)]
}

fn add(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| a[i] + b[i])
}

fn sub(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| a[i] - b[i])
}

fn times(a: &V3, x: &Dual) -> V3 {
    std::array::from_fn(|i| a[i] * *x)
}

fn dot(a: &V3, b: &V3) -> Dual {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &V3, b: &V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn mat_vec(m: &M3, v: &V3) -> V3 {
    std::array::from_fn(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2])
}

fn mat_mul(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j])
    })
}

fn transpose(m: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]))
}

/// The rotation by `angle` about the unit axis `u`: `cos (I - u u^T) + sin [u]x + u u^T`.
fn rot(u: &Vector3<f64>, angle: &Dual) -> M3 {
    let (c, s) = (angle.cos(), angle.sin());
    let skew = u.cross_matrix();
    let outer = u * u.transpose();
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let id = if i == j { 1.0 } else { 0.0 };
            k(id - outer[(i, j)]) * c + k(skew[(i, j)]) * s + k(outer[(i, j)])
        })
    })
}

/// [`signed_angle`] on enclosures: the angle about `axis` turning `from` onto `to`.
fn signed(axis: &Vector3<f64>, from: &V3, to: &V3) -> Dual {
    let u = kv(axis);
    let a = sub(from, &times(&u, &dot(&u, from)));
    let b = sub(to, &times(&u, &dot(&u, to)));
    dot(&u, &cross(&a, &b)).atan2(&dot(&a, &b))
}

impl SixAxisIk {
    /// The tool0 pose along `path` (cell frame), for the robot base `robot_from_cell` and the
    /// tool's `tframe` inverse, as constants (module docs).
    pub fn pose_form(
        &self,
        robot_from_cell: &Isometry3<f64>,
        path: &CartesianPath,
        tframe_inverse: &Isometry3<f64>,
    ) -> PoseForm {
        let (form, start, turn) = path.form();
        let rb = robot_from_cell.rotation.to_rotation_matrix().into_inner();
        let tb = robot_from_cell.translation.vector;
        let turn_rad = turn.norm();
        let axis = if turn_rad > 0.0 {
            turn / turn_rad
        } else {
            Vector3::z()
        };
        // tool0 = base^-1 * tcp(s) * tframe^-1; tcp(s) rotation = start exp(s turn).
        let a = rb * start.to_rotation_matrix().into_inner();
        let fi = tframe_inverse.rotation.to_rotation_matrix().into_inner();
        // The wrist centre seen from the TCP frame.
        let v = tframe_inverse.translation.vector + fi * self.wrist_in_tool0;
        let along = axis * axis.dot(&v);
        let b = fi
            * self
                .tool0_zero
                .rotation
                .to_rotation_matrix()
                .into_inner()
                .transpose();
        let outer = axis * axis.transpose();
        let (w0, w_line, arc_rad, w_cos, w_sin) = match form {
            PathForm::Line { from, to } => (
                rb * from + tb,
                rb * (to - from),
                0.0,
                Vector3::zeros(),
                Vector3::zeros(),
            ),
            PathForm::Arc {
                centre,
                radius_mm,
                u,
                w,
                angle_rad,
            } => (
                rb * centre + tb,
                Vector3::zeros(),
                angle_rad,
                rb * u * radius_mm,
                rb * w * radius_mm,
            ),
        };
        PoseForm {
            w0: w0 + a * along,
            w_line,
            arc_rad,
            w_cos,
            w_sin,
            turn_rad,
            t_cos: a * (v - along),
            t_sin: a * axis.cross(&v),
            r_const: a * outer * b,
            r_cos: a * (Matrix3::identity() - outer) * b,
            r_sin: a * axis.cross_matrix() * b,
        }
    }

    /// The branch `signs` of the tool0 pose `pose` over the progress `s` (module docs), or
    /// `None` where a step is not defined with room on all of `s`.
    pub fn enclose(&self, pose: &PoseForm, s: Interval, signs: Signs) -> Option<Enclosure> {
        let sign = |plus: bool| exact(if plus { 1.0 } else { -1.0 });
        let var = Dual::variable(s);
        let (arc, turn) = (var * k(pose.arc_rad), var * k(pose.turn_rad));
        let (ca, sa, ct, st) = (arc.cos(), arc.sin(), turn.cos(), turn.sin());
        let w = add(
            &add(
                &add(&kv(&pose.w0), &times(&kv(&pose.w_line), &var)),
                &add(&times(&kv(&pose.w_cos), &ca), &times(&kv(&pose.w_sin), &sa)),
            ),
            &add(&times(&kv(&pose.t_cos), &ct), &times(&kv(&pose.t_sin), &st)),
        );
        let target: M3 = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                k(pose.r_const[(i, j)]) + k(pose.r_cos[(i, j)]) * ct + k(pose.r_sin[(i, j)]) * st
            })
        });
        let [a1, a2, a3, a4, a5, a6] = self.axes;
        let (d1, d2, d3) = (
            a1.dir.into_inner(),
            a2.dir.into_inner(),
            a3.dir.into_inner(),
        );
        // Axis 1.
        let v = sub(&w, &kv(&a1.point.coords));
        let (x, y) = (dot(&kv(&d2), &v), dot(&kv(&d1.cross(&d2)), &v));
        let rho = (x.sqr() + y.sqr()).sqrt();
        let d = k(self.shoulder_offset_mm).div(&rho).acos();
        let q1 = y.atan2(&x) + d * sign(signs.stance);
        // The elbow.
        let b = sub(
            &add(&kv(&a1.point.coords), &mat_vec(&rot(&d1, &-q1), &v)),
            &kv(&self.shoulder.coords),
        );
        let (lu, lf) = (self.upper_arm_mm, self.forearm_mm);
        let cosine = (dot(&b, &b) - kr(lf * lf + lu * lu)) * kr(1.0 / (2.0 * lf * lu));
        let psi = signed_angle(
            &a3.dir,
            &(self.wrist_zero - self.elbow),
            &(self.elbow - self.shoulder),
        );
        let q3 = k(psi) + cosine.acos() * sign(signs.elbow);
        // Axis 2.
        let w3 = add(
            &kv(&a3.point.coords),
            &mat_vec(&rot(&d3, &q3), &kv(&(self.wrist_zero - a3.point))),
        );
        let q2 = signed(&d2, &sub(&w3, &kv(&self.shoulder.coords)), &b);
        // The wrist.
        let arm = mat_mul(&mat_mul(&rot(&d1, &q1), &rot(&d2, &q2)), &rot(&d3, &q3));
        let m = mat_mul(&transpose(&arm), &target);
        let (u4, u5, u6) = (
            a4.dir.into_inner(),
            a5.dir.into_inner(),
            a6.dir.into_inner(),
        );
        let t = mat_vec(&m, &kv(&u6));
        let alpha = dot(&kv(&u4), &t);
        let across = cross(&kv(&u4), &t);
        let gamma = dot(&across, &across).sqrt() * sign(signs.flip);
        let c = add(
            &times(&kv(&u4), &alpha),
            &times(&kv(&u4.cross(&u5)), &gamma),
        );
        let q4 = signed(&u4, &c, &t);
        let q5 = signed(&u5, &kv(&u6), &c);
        let rest = mat_mul(&transpose(&mat_mul(&rot(&u4, &q4), &rot(&u5, &q5))), &m);
        let q6 = signed(&u6, &kv(&u5), &mat_vec(&rest, &kv(&u5)));
        let q = [q1, q2, q3, q4, q5, q6];
        self.controller_enclosure(&q)
    }

    /// URDF joints (rad) to controller axes (deg), through the coupling.
    fn controller_enclosure(&self, q: &[Dual; 6]) -> Option<Enclosure> {
        let deg = kr(180.0 / std::f64::consts::PI);
        let q_deg: [Dual; 6] = std::array::from_fn(|j| q[j] * deg - k(self.coupling.offset_deg[j]));
        let axes: [Dual; 6] = std::array::from_fn(|i| {
            (0..6).fold(exact(0.0), |sum, j| {
                // The coupling's inverse is exact where it is integer (`LinearCoupling::probe`).
                let t = self.coupling.to_controller[(i, j)];
                let factor = if t.fract() == 0.0 { exact(t) } else { k(t) };
                if t == 0.0 {
                    sum
                } else {
                    sum + q_deg[j] * factor
                }
            })
        });
        if !axes.iter().all(Dual::is_valid) {
            return None;
        }
        Some(Enclosure {
            value_deg: axes.map(|a| a.v),
            rate_deg: axes.map(|a| a.d),
        })
    }
}
