//! Wrist-centre inverse kinematics for axes 1..3 of an ABB-like arm, in closed form.
//!
//! Stage: a wrist-centre position (robot base frame, mm) -> controller values of axes 1..3
//! (degrees). Paper: Ting & Jar (2006) lump the arm into its first three links (section 3), so
//! the planner works on axes 1..3 and needs, for every working point, the axis values that put
//! the wrist centre there. This module is the closed form of the wrist centre
//! (`docs/irb1400.md`, "Wrist centre in closed form"), inverted:
//!
//! ```text
//! r = a1 + a2 sin(rax2) + d4 cos(phi) + a3 sin(phi)
//! z = d1 + a2 cos(rax2) - d4 sin(phi) + a3 cos(phi)
//! x = r cos(rax1),  y = r sin(rax1)
//! ```
//!
//! where `phi` is the forearm angle to the horizontal: `phi = rax3` for a
//! [`Coupling::Parallelogram`] robot (the IRB 1400: the controller's axis 3 *is* that angle) and
//! `phi = rax2 + rax3` for a [`Coupling::Serial`] one (controller values are URDF values). The
//! [`ArmGeometry`] carries the robot's coupling, so [`forward`] and [`solve`] always speak
//! controller values of the robot they were built from.
//!
//! Readings chosen where the sources are silent:
//! - The forearm is one rigid vector of length `L = sqrt(a3^2 + d4^2)` at the fixed angle
//!   `beta = atan2(d4, a3)` from the forearm's own "up"; the elbow angle `delta = q3 + beta`
//!   (`q3` the URDF joint-3 value, the angle between the arms) makes the planar problem the
//!   textbook two-link one.
//! - **Branches.** *Front*: axis 1 points at the wrist centre (`atan2(y, x)`); *back*: axis 1
//!   half a turn from that, the arm reaching over backwards. *Elbow up*: `sin(delta) >= 0`, the
//!   side of the zero pose (the wrist centre lies on the forward side of the upper arm, ABB's
//!   "wrist centre relative to the lower arm" bit); *elbow down*: `sin(delta) < 0`. On the
//!   IRB 1400 the coupled axis-3 range keeps `delta` within 15.5 .. 150.5 deg, so elbow-down
//!   solutions are always out of range there; they are still returned by [`solve`].
//! - All three axes are wrapped into (-180, 180]; [`solve`] does no range filtering.
//! - On the axis-1 line (`x = y = 0`) every axis-1 value gives the same wrist centre; [`solve`]
//!   returns axis 1 = 0 for the front branches and 180 for the back ones (whose planar solutions
//!   then coincide with the front ones). [`choose`] replaces that by the previous axis-1 value
//!   (front) and that +- 180 (back) when there is a previous pose.
//! - On the reach boundary the two elbow solutions coincide; both labels are returned.

use super::{describe_violation, wrap_deg};
use super::{Branch, IkError, IkSolution};
use crate::robot::{Axes3, Coupling, Robot};
use nalgebra::Vector3;

/// Tolerance on joint-origin offsets that must be zero, mm.
const OFFSET_TOL_MM: f64 = 1e-6;
/// Tolerance on axis directions and origin rotations (radians / unit-vector components).
const ANGLE_TOL: f64 = 1e-9;
/// Slack on the cosine of the elbow angle, so points exactly on the reach boundary solve.
const COS_SLACK: f64 = 1e-10;
/// Distance from the axis-1 line below which the wrist counts as on it, mm.
const SINGULAR_MM: f64 = 1e-9;

/// The five lengths of an ABB-like arm (axes z, y, y, x, y), mm, plus how the controller counts
/// axis 3 and which angles between the arms the controller allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmGeometry {
    /// Height of axis 2 above the base mounting plane (joint 1's own z offset folded in).
    pub d1_mm: f64,
    /// Horizontal offset axis 1 -> axis 2.
    pub a1_mm: f64,
    /// Upper arm, axis 2 -> axis 3.
    pub a2_mm: f64,
    /// Forearm offset, axis 3 -> axis-4 line (up at the zero pose).
    pub a3_mm: f64,
    /// Along axis 4 from that offset to the wrist centre (joint 4's own offset along axis 4
    /// and joint 5's, summed: the IRB 1600 splits it 300 + 300).
    pub d4_mm: f64,
    /// How controller axis 3 relates to the URDF joint 3.
    pub coupling: Coupling,
    /// Range of the angle between the arms (URDF q3: `rax3 - rax2` for a parallelogram robot,
    /// `rax3` for a serial one) that the controller's ranges allow; `None`: unrestricted.
    /// Only [`reach_interval_mm`] uses it.
    pub q3_range_deg: Option<[f64; 2]>,
}

impl ArmGeometry {
    /// Reads the lengths from the robot's joint origins: `joints[1]` gives a1 (x) and d1 (z,
    /// plus `joints[0]`'s z), `joints[2]` z gives a2, `joints[3]` z gives a3, `joints[3]` x plus
    /// `joints[4]` x gives d4 (both lie along axis 4). Refuses any other structure: axes must be
    /// +z, +y, +y, +x, +y, origins unrotated, every other offset zero within 1e-6 mm, a2 > 0 and
    /// the forearm of non-zero length.
    pub fn from_robot(robot: &Robot) -> Result<ArmGeometry, IkError> {
        let refuse = |message: String| IkError::Structure {
            robot: robot.name.clone(),
            message,
        };
        if robot.joints.len() < 5 {
            return Err(refuse(format!(
                "it has {} joints; axes 1..5 are needed",
                robot.joints.len()
            )));
        }
        let want: [(&str, Vector3<f64>); 5] = [
            ("+z", Vector3::z()),
            ("+y", Vector3::y()),
            ("+y", Vector3::y()),
            ("+x", Vector3::x()),
            ("+y", Vector3::y()),
        ];
        // Offset components (x, y, z) that may be non-zero, per joint.
        let free: [[bool; 3]; 5] = [
            [false, false, true],
            [true, false, true],
            [false, false, true],
            [true, false, true],
            [true, false, false],
        ];
        for (i, ((name, axis), free)) in want.iter().zip(free).enumerate() {
            let j = &robot.joints[i];
            let a = j.axis.into_inner();
            if (a - axis).amax() > ANGLE_TOL {
                return Err(refuse(format!(
                    "joint {} ({}) turns about ({:.4}, {:.4}, {:.4}); the closed form needs {} \
                     (axes z, y, y, x, y)",
                    i + 1,
                    j.name,
                    a.x,
                    a.y,
                    a.z,
                    name
                )));
            }
            let angle = j.origin.rotation.angle();
            if angle > ANGLE_TOL {
                return Err(refuse(format!(
                    "joint {} ({}) origin is rotated by {:.6} deg; the closed form needs \
                     unrotated joint origins",
                    i + 1,
                    j.name,
                    angle.to_degrees()
                )));
            }
            let t = j.origin.translation.vector;
            for (k, c) in ["x", "y", "z"].iter().enumerate() {
                if !free[k] && t[k].abs() > OFFSET_TOL_MM {
                    return Err(refuse(format!(
                        "joint {} ({}) origin has {} = {:.6} mm; the closed form needs it 0 \
                         (only joint 1 z, joint 2 x and z, joint 3 z, joint 4 x and z and joint \
                         5 x may be non-zero)",
                        i + 1,
                        j.name,
                        c,
                        t[k]
                    )));
                }
            }
        }
        let t = |i: usize| robot.joints[i].origin.translation.vector;
        let geom = ArmGeometry {
            d1_mm: t(0).z + t(1).z,
            a1_mm: t(1).x,
            a2_mm: t(2).z,
            a3_mm: t(3).z,
            d4_mm: t(3).x + t(4).x,
            coupling: robot.controller.coupling,
            q3_range_deg: None,
        };
        if geom.a2_mm <= OFFSET_TOL_MM {
            return Err(refuse(format!(
                "upper arm length a2 = {:.3} mm; it must be positive",
                geom.a2_mm
            )));
        }
        if geom.forearm_mm() <= OFFSET_TOL_MM {
            return Err(refuse("the forearm (a3, d4) has zero length".into()));
        }
        let ax = &robot.controller.axes;
        let q3 = match robot.controller.coupling {
            Coupling::Serial => [ax[2].min_deg, ax[2].max_deg],
            Coupling::Parallelogram => {
                let mut lo = ax[2].min_deg - ax[1].max_deg;
                let mut hi = ax[2].max_deg - ax[1].min_deg;
                if let Some([clo, chi]) = robot.controller.coupled_axis3_deg {
                    lo = lo.max(clo);
                    hi = hi.min(chi);
                }
                [lo, hi]
            }
        };
        if q3[0] > q3[1] {
            return Err(refuse(format!(
                "the axis ranges leave no angle between the arms ({} .. {} deg)",
                q3[0], q3[1]
            )));
        }
        Ok(ArmGeometry {
            q3_range_deg: Some(q3),
            ..geom
        })
    }

    /// The IRB 1400 lengths of `docs/irb1400.md`, parallelogram coupling, no q3 restriction.
    pub fn irb1400_nominal() -> ArmGeometry {
        ArmGeometry {
            d1_mm: 475.0,
            a1_mm: 150.0,
            a2_mm: 600.0,
            a3_mm: 120.0,
            d4_mm: 720.0,
            coupling: Coupling::Parallelogram,
            q3_range_deg: None,
        }
    }

    /// Axis 3 -> wrist centre distance, `sqrt(a3^2 + d4^2)`, mm.
    pub fn forearm_mm(&self) -> f64 {
        self.a3_mm.hypot(self.d4_mm)
    }

    /// Fixed angle of the axis-3 -> wrist vector from the forearm's "up", `atan2(d4, a3)`, deg.
    pub fn forearm_angle_deg(&self) -> f64 {
        self.d4_mm.atan2(self.a3_mm).to_degrees()
    }

    /// Distances from the shoulder (axis 2) to the wrist centre with axis 1 pointing at it
    /// (front) and turned half a turn from that (back), mm.
    pub fn shoulder_distances_mm(&self, wrist_mm: [f64; 3]) -> (f64, f64) {
        let rxy = wrist_mm[0].hypot(wrist_mm[1]);
        let v = wrist_mm[2] - self.d1_mm;
        ((rxy - self.a1_mm).hypot(v), (rxy + self.a1_mm).hypot(v))
    }
}

/// Wrist centre (robot base frame, mm) for controller axes 1..3 (degrees), closed form.
pub fn forward(geom: &ArmGeometry, axes_deg: Axes3) -> [f64; 3] {
    let [r1, r2, r3] = axes_deg.map(f64::to_radians);
    let phi = match geom.coupling {
        Coupling::Parallelogram => r3,
        Coupling::Serial => r2 + r3,
    };
    let r = geom.a1_mm + geom.a2_mm * r2.sin() + geom.d4_mm * phi.cos() + geom.a3_mm * phi.sin();
    let z = geom.d1_mm + geom.a2_mm * r2.cos() - geom.d4_mm * phi.sin() + geom.a3_mm * phi.cos();
    [r * r1.cos(), r * r1.sin(), z]
}

/// Minimum and maximum of cos over [lo, hi] degrees.
fn cos_extremes_deg(lo: f64, hi: f64) -> (f64, f64) {
    if hi - lo >= 360.0 {
        return (-1.0, 1.0);
    }
    let (cl, ch) = (lo.to_radians().cos(), hi.to_radians().cos());
    let (mut cmin, mut cmax) = (cl.min(ch), cl.max(ch));
    let mut k = (lo / 180.0).ceil();
    while k * 180.0 <= hi {
        if k.rem_euclid(2.0) == 0.0 {
            cmax = 1.0;
        } else {
            cmin = -1.0;
        }
        k += 1.0;
    }
    (cmin, cmax)
}

/// Minimum and maximum distance, mm, from the shoulder (axis 2) to the wrist centre.
///
/// Geometrically (`q3_range_deg` None) this is `|a2 - L| .. a2 + L` with
/// `L = sqrt(a3^2 + d4^2)` (IRB 1400: 129.9 .. 1329.9 mm). With a `q3_range_deg` (what
/// [`ArmGeometry::from_robot`] fills in from the controller's ranges) the elbow angle
/// `delta = q3 + atan2(d4, a3)` is confined and the interval is the law of cosines
/// `rho^2 = a2^2 + L^2 + 2 a2 L cos(delta)` over that range (IRB 1400: 360.8 .. 1317.8 mm).
/// The axis-1 and axis-2 ranges are not applied, so the interval is an outer bound of what the
/// arm reaches: reach regions built on it are outer bounds too, and the final plan still checks
/// every pose against the ranges.
pub fn reach_interval_mm(geom: &ArmGeometry) -> (f64, f64) {
    let (a2, l) = (geom.a2_mm, geom.forearm_mm());
    match geom.q3_range_deg {
        None => ((a2 - l).abs(), a2 + l),
        Some([lo, hi]) => {
            let beta = geom.forearm_angle_deg();
            let (cmin, cmax) = cos_extremes_deg(lo + beta, hi + beta);
            let rho = |c: f64| (a2 * a2 + l * l + 2.0 * a2 * l * c).max(0.0).sqrt();
            (rho(cmin), rho(cmax))
        }
    }
}

/// How far from axis 1 the wrist centre reaches horizontally, mm, within the controller's ranges
/// of axes 2 and 3 (the coupled axis-3 range included): the "reach" of ABB's data sheets
/// (IRB 1400: 1443.7 mm at axis 2 = 70, axis 3 = 9.46). With `r = a1 + a2 sin(rax2) +
/// L cos(phi - b)` (`L`, `b = atan2(a3, d4)` the forearm's length and angle, `phi` the forearm's
/// angle to the horizontal), for each axis-2 value the best `phi` is `b` clamped into the
/// interval the ranges leave it (a cosine is unimodal about its peak), and axis 2 is searched
/// on a 0.001 deg raster between its limits (both included): within a micrometre of the true
/// maximum for any arm of a few metres.
pub fn horizontal_reach_mm(robot: &Robot, geom: &ArmGeometry) -> f64 {
    let ax = &robot.controller.axes;
    let (lo2, hi2) = (ax[1].min_deg, ax[1].max_deg);
    let (lo3, hi3) = (ax[2].min_deg, ax[2].max_deg);
    let l = geom.forearm_mm();
    let b = geom.a3_mm.atan2(geom.d4_mm).to_degrees();
    let steps = ((hi2 - lo2) * 1000.0).ceil().max(1.0) as usize;
    let mut best = f64::NEG_INFINITY;
    for k in 0..=steps {
        let a2 = if k == steps {
            hi2
        } else {
            lo2 + k as f64 * (hi2 - lo2) / steps as f64
        };
        // The forearm's angle to the horizontal the ranges leave at this axis 2.
        let (mut lo, mut hi) = match geom.coupling {
            Coupling::Parallelogram => (lo3, hi3),
            Coupling::Serial => (a2 + lo3, a2 + hi3),
        };
        if let (Coupling::Parallelogram, Some([clo, chi])) =
            (geom.coupling, robot.controller.coupled_axis3_deg)
        {
            lo = lo.max(a2 + clo);
            hi = hi.min(a2 + chi);
        }
        if lo > hi {
            continue;
        }
        let phi = b.clamp(lo, hi);
        let r = geom.a1_mm + geom.a2_mm * a2.to_radians().sin() + l * (phi - b).to_radians().cos();
        best = best.max(r);
    }
    best
}

/// All real solutions for a wrist centre (robot base frame, mm), in the order of
/// [`Branch::ALL`]: up to four, fewer when the wrist is out of reach for the front or back
/// stance; empty when neither reaches or the input is not finite. No range filtering. Axes
/// wrapped into (-180, 180]; on the axis-1 line axis 1 is 0 (front) and 180 (back).
pub fn solve(geom: &ArmGeometry, wrist_mm: [f64; 3]) -> Vec<IkSolution> {
    let [x, y, z] = wrist_mm;
    let mut out = Vec::with_capacity(4);
    if !(x.is_finite() && y.is_finite() && z.is_finite()) {
        return out;
    }
    let rxy = x.hypot(y);
    let th1 = if rxy <= SINGULAR_MM {
        0.0
    } else {
        y.atan2(x).to_degrees()
    };
    let (a2, l) = (geom.a2_mm, geom.forearm_mm());
    let beta = geom.forearm_angle_deg();
    let v = z - geom.d1_mm;
    for (front, r, t1) in [(true, rxy, th1), (false, -rxy, th1 + 180.0)] {
        let u = r - geom.a1_mm;
        let c = (u * u + v * v - a2 * a2 - l * l) / (2.0 * a2 * l);
        if c.is_nan() || c.abs() > 1.0 + COS_SLACK {
            continue;
        }
        let d = c.clamp(-1.0, 1.0).acos();
        let alpha = u.atan2(v); // direction to the wrist, from vertical towards +r
        for up in [true, false] {
            let delta = if up { d } else { -d };
            let th2 = alpha - (l * delta.sin()).atan2(a2 + l * delta.cos());
            let rax2 = th2.to_degrees();
            let q3 = delta.to_degrees() - beta;
            let rax3 = match geom.coupling {
                Coupling::Parallelogram => rax2 + q3,
                Coupling::Serial => q3,
            };
            out.push(IkSolution {
                branch: Branch::of(front, up),
                axes_deg: [wrap_deg(t1), wrap_deg(rax2), wrap_deg(rax3)],
            });
        }
    }
    out
}

/// Picks one solution for a wrist centre (robot base frame, mm).
///
/// Keeps the solutions of [`solve`] that are of `branch` (when given), inside the axis ranges
/// (`robot.check_range3`, the coupled axis-3 range included) and that `usable` accepts (the
/// caller's collision check; its `Err` is the reason, kept in [`IkError::InCollision`]).
/// Among them:
/// - with a `previous` pose: the one closest to it in the **max-norm** (axes 1..3 share one
///   speed, so the max-norm is the duration of a synchronised joint move), ties broken by the
///   Euclidean distance, then by [`Branch::ALL`] order. Axis 1 differences are plain
///   differences (no wrap): axis 1 cannot pass through 180 deg.
/// - without: the smallest `|axis 2| + |axis 3|` (the most upright arm), then branch order.
///
/// On the axis-1 line with a `previous` pose, axis 1 is taken from it (see the module docs).
/// Errors say why: out of reach (distance from the shoulder against [`reach_interval_mm`]
/// without joint limits), out of range (each solution's first violated limit), in collision,
/// or the required branch impossible.
pub fn choose(
    robot: &Robot,
    geom: &ArmGeometry,
    wrist_mm: [f64; 3],
    previous: Option<Axes3>,
    branch: Option<Branch>,
    usable: impl Fn(Axes3) -> Result<(), String>,
) -> Result<IkSolution, IkError> {
    if !wrist_mm.iter().all(|c| c.is_finite()) {
        return Err(IkError::NotFinite { wrist_mm });
    }
    let mut sols = solve(geom, wrist_mm);
    let (front_mm, back_mm) = geom.shoulder_distances_mm(wrist_mm);
    let (min_mm, max_mm) = reach_interval_mm(&ArmGeometry {
        q3_range_deg: None,
        ..*geom
    });
    if sols.is_empty() {
        return Err(IkError::Unreachable {
            wrist_mm,
            front_mm,
            back_mm,
            min_mm,
            max_mm,
        });
    }
    if let Some(p) = previous {
        if wrist_mm[0].hypot(wrist_mm[1]) <= SINGULAR_MM {
            for s in &mut sols {
                s.axes_deg[0] = if s.branch.is_front() {
                    wrap_deg(p[0])
                } else {
                    // The half turn nearer to zero keeps it inside symmetric ranges.
                    let a = p[0] + 180.0;
                    let b = p[0] - 180.0;
                    if a.abs() <= b.abs() {
                        a
                    } else {
                        b
                    }
                };
            }
        }
    }
    if let Some(b) = branch {
        sols.retain(|s| s.branch == b);
        if sols.is_empty() {
            let (d, stance) = if b.is_front() {
                (front_mm, "")
            } else {
                (back_mm, " with axis 1 turned half a turn")
            };
            return Err(IkError::ForcedBranch {
                wrist_mm,
                branch: b,
                reason: format!(
                    "cannot reach it: it is {d:.1} mm from the shoulder{stance}; the arm \
                     reaches {min_mm:.1} .. {max_mm:.1} mm"
                ),
            });
        }
    }
    let mut violations = Vec::new();
    let mut in_range = Vec::new();
    for s in sols {
        match robot.check_range3(&s.axes_deg) {
            Ok(()) => in_range.push(s),
            Err(v) => violations.push((s.branch, v)),
        }
    }
    if in_range.is_empty() {
        return Err(match (branch, violations.first()) {
            (Some(b), Some((_, v))) => IkError::ForcedBranch {
                wrist_mm,
                branch: b,
                reason: format!("is out of range: {}", describe_violation(v)),
            },
            _ => IkError::OutOfRange {
                wrist_mm,
                violations,
            },
        });
    }
    let mut blocked = Vec::new();
    let mut free: Vec<IkSolution> = Vec::with_capacity(in_range.len());
    for s in in_range {
        match usable(s.axes_deg) {
            Ok(()) => free.push(s),
            Err(why) => blocked.push((s.branch, why)),
        }
    }
    let key = |s: &IkSolution| -> (f64, f64, usize) {
        let a = s.axes_deg;
        match previous {
            Some(p) => {
                let d = [a[0] - p[0], a[1] - p[1], a[2] - p[2]];
                let maxn = d.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
                let eucl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                (maxn, eucl, s.branch.index())
            }
            None => (a[1].abs() + a[2].abs(), 0.0, s.branch.index()),
        }
    };
    free.into_iter()
        .min_by(|a, b| {
            let (ka, kb) = (key(a), key(b));
            ka.0.total_cmp(&kb.0)
                .then(ka.1.total_cmp(&kb.1))
                .then(ka.2.cmp(&kb.2))
        })
        .ok_or(IkError::InCollision { wrist_mm, blocked })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::urdf;
    use std::path::Path;

    fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    }

    fn geom() -> (Robot, ArmGeometry) {
        let robot = Robot::irb1400();
        let g = ArmGeometry::from_robot(&robot).expect("IRB 1400 is ABB-like");
        (robot, g)
    }

    fn urdf_wrist(robot: &Robot, a: Axes3) -> [f64; 3] {
        let w = robot.wrist_centre(&[a[0], a[1], a[2], 0.0, 0.0, 0.0]);
        [w.x, w.y, w.z]
    }

    #[test]
    fn geometry_of_the_irb1400() {
        let (_, g) = geom();
        assert_eq!(
            (g.d1_mm, g.a1_mm, g.a2_mm, g.a3_mm, g.d4_mm),
            (475.0, 150.0, 600.0, 120.0, 720.0)
        );
        assert_eq!(g.coupling, Coupling::Parallelogram);
        // rax3 - rax2 in -65 .. 70 (coupled range tighter than -135 .. 140 from the axes).
        assert_eq!(g.q3_range_deg, Some([-65.0, 70.0]));
    }

    #[test]
    fn zero_pose_wrist_and_its_solution() {
        let (robot, g) = geom();
        let w = forward(&g, [0.0, 0.0, 0.0]);
        assert!(dist(w, [870.0, 0.0, 1195.0]) < 1e-9, "{w:?}");
        let sols = solve(&g, [870.0, 0.0, 1195.0]);
        let zero = sols
            .iter()
            .find(|s| s.axes_deg.iter().all(|a| a.abs() < 1e-9))
            .expect("(0, 0, 0) among the solutions");
        assert_eq!(zero.branch, Branch::FrontElbowUp);
        let c =
            choose(&robot, &g, [870.0, 0.0, 1195.0], None, None, |_| Ok(())).expect("reachable");
        assert!(c.axes_deg.iter().all(|a| a.abs() < 1e-9), "{c:?}");
    }

    /// Every solution of every point goes back to the point, by the closed form and by the
    /// URDF chain; the pose the point came from is among them; every branch label matches the
    /// sign of the elbow angle; all four branches occur.
    #[test]
    fn round_trips_on_a_grid_of_poses() {
        let (robot, g) = geom();
        let beta = (720.0f64).atan2(120.0).to_degrees();
        let mut seen = [false; 4];
        let mut n = 0;
        for a1 in [-165.0, -120.0, -45.0, -5.0, 0.0, 30.0, 95.0, 160.0] {
            for a2 in [-100.0, -60.0, -20.0, 0.0, 15.0, 45.0, 69.0, 120.0] {
                for a3 in [-150.0, -60.0, -10.0, 0.0, 25.0, 65.0, 140.0] {
                    let w = forward(&g, [a1, a2, a3]);
                    assert!(dist(w, urdf_wrist(&robot, [a1, a2, a3])) < 1e-6);
                    if w[0].hypot(w[1]) < 1.0 {
                        continue; // near the axis-1 line: axis 1 is arbitrary
                    }
                    let sols = solve(&g, w);
                    assert!(!sols.is_empty(), "{a1} {a2} {a3}: {w:?}");
                    for s in &sols {
                        seen[s.branch.index()] = true;
                        assert!(dist(forward(&g, s.axes_deg), w) < 0.01, "{s:?} for {w:?}");
                        assert!(dist(urdf_wrist(&robot, s.axes_deg), w) < 0.01, "{s:?}");
                        let q3 = s.axes_deg[2] - s.axes_deg[1];
                        let sin_delta = (q3 + beta).to_radians().sin();
                        assert_eq!(sin_delta >= -1e-9, s.branch.is_elbow_up(), "{s:?}");
                        assert!(s.axes_deg.iter().all(|a| *a > -180.0 && *a <= 180.0));
                    }
                    let same = |x: f64, y: f64| wrap_deg(x - y).abs() < 1e-6;
                    assert!(
                        sols.iter().any(|s| same(s.axes_deg[0], a1)
                            && same(s.axes_deg[1], a2)
                            && same(s.axes_deg[2], a3)),
                        "({a1}, {a2}, {a3}) not among {sols:?}"
                    );
                    n += 1;
                }
            }
        }
        assert!(n > 400, "{n}");
        assert_eq!(seen, [true; 4]);
    }

    #[test]
    fn four_distinct_branches_for_one_point() {
        let (robot, g) = geom();
        let p = [300.0, 400.0, 900.0];
        let sols = solve(&g, p);
        let branches: Vec<Branch> = sols.iter().map(|s| s.branch).collect();
        assert_eq!(branches, Branch::ALL.to_vec());
        for (i, a) in sols.iter().enumerate() {
            assert!(dist(urdf_wrist(&robot, a.axes_deg), p) < 0.01);
            for b in &sols[i + 1..] {
                let d = (0..3)
                    .map(|k| (a.axes_deg[k] - b.axes_deg[k]).abs())
                    .fold(0.0, f64::max);
                assert!(d > 1.0, "{a:?} vs {b:?}");
            }
        }
        // Front stance: axis 1 points at the point.
        assert!((sols[0].axes_deg[0] - 53.130_102_354).abs() < 1e-6);
        assert!((sols[2].axes_deg[0] - (53.130_102_354 - 180.0)).abs() < 1e-6);
    }

    #[test]
    fn unreachable_point_says_how_far() {
        let (robot, g) = geom();
        // 1612 mm straight ahead of the shoulder (150, 0, 475).
        let err = choose(&robot, &g, [1762.0, 0.0, 475.0], None, None, |_| Ok(())).unwrap_err();
        let text = err.to_string();
        // 600 + sqrt(120^2 + 720^2) = 1329.93; |600 - 729.93| = 129.93; back: 1762 + 150.
        assert!(text.contains("1612.0 mm from the shoulder"), "{text}");
        assert!(text.contains("1912.0 mm with axis 1 turned"), "{text}");
        assert!(text.contains("129.9 .. 1329.9 mm"), "{text}");
    }

    #[test]
    fn reach_intervals() {
        let g = ArmGeometry::irb1400_nominal();
        let l = (120.0f64 * 120.0 + 720.0 * 720.0).sqrt();
        let (lo, hi) = reach_interval_mm(&g);
        assert!((lo - (l - 600.0)).abs() < 1e-9 && (hi - (600.0 + l)).abs() < 1e-9);
        // With the IRB 1400's angle between the arms in -65 .. 70 deg: elbow angle
        // 15.54 .. 150.54 deg; law of cosines at the ends.
        let (_, g) = geom();
        let beta = (720.0f64).atan2(120.0).to_degrees();
        let rho =
            |d: f64| (600.0f64.powi(2) + l * l + 2.0 * 600.0 * l * d.to_radians().cos()).sqrt();
        let (lo, hi) = reach_interval_mm(&g);
        assert!((lo - rho(70.0 + beta)).abs() < 1e-9, "{lo}");
        assert!((hi - rho(-65.0 + beta)).abs() < 1e-9, "{hi}");
        assert!(
            lo > 360.0 && lo < 362.0 && hi > 1317.0 && hi < 1319.0,
            "{lo} {hi}"
        );
        // A range through delta = 0 reaches full stretch.
        let g0 = ArmGeometry {
            q3_range_deg: Some([-100.0, 0.0]),
            ..g
        };
        assert!((reach_interval_mm(&g0).1 - (600.0 + l)).abs() < 1e-9);
    }

    #[test]
    fn forced_branch() {
        let (robot, g) = geom();
        // Behind and above axis 1: only the back stance is in range (front needs axis 1 = 180).
        let p = [-100.0, 0.0, 1400.0];
        let back =
            choose(&robot, &g, p, None, Some(Branch::BackElbowUp), |_| Ok(())).expect("back");
        assert_eq!(back.branch, Branch::BackElbowUp);
        assert!(back.axes_deg[0].abs() < 1e-9, "{back:?}");
        assert!(dist(urdf_wrist(&robot, back.axes_deg), p) < 0.01);
        let free = choose(&robot, &g, p, None, None, |_| Ok(())).expect("some");
        assert_eq!(free.branch, Branch::BackElbowUp);
        let err = choose(&robot, &g, p, None, Some(Branch::FrontElbowUp), |_| Ok(())).unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, IkError::ForcedBranch { .. }), "{text}");
        assert!(
            text.contains("front-elbow-up") && text.contains("axis 1 = 180.0"),
            "{text}"
        );
        // Elbow down is never inside the IRB 1400's coupled range.
        let err = choose(&robot, &g, p, None, Some(Branch::BackElbowDown), |_| Ok(())).unwrap_err();
        assert!(err.to_string().contains("back-elbow-down"), "{err}");
    }

    #[test]
    fn out_of_range_names_the_axis() {
        let (robot, g) = geom();
        // Straight below the shoulder, close to the floor: needs axis 2 far beyond 70 deg.
        let err = choose(&robot, &g, [700.0, 0.0, -300.0], None, None, |_| Ok(())).unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, IkError::OutOfRange { .. }), "{text}");
        assert!(text.contains("axis 2") || text.contains("axis 3"), "{text}");
    }

    #[test]
    fn closest_to_previous_and_first_point_rule() {
        let (robot, g) = geom();
        // Above and just beside axis 1: front (axis 1 = 90) and back (axis 1 = -90) in range.
        let p = [0.0, 50.0, 1500.0];
        let in_range: Vec<IkSolution> = solve(&g, p)
            .into_iter()
            .filter(|s| robot.check_range3(&s.axes_deg).is_ok())
            .collect();
        let br: Vec<Branch> = in_range.iter().map(|s| s.branch).collect();
        assert_eq!(br, vec![Branch::FrontElbowUp, Branch::BackElbowUp]);
        let near_front = choose(&robot, &g, p, Some([80.0, -40.0, -40.0]), None, |_| Ok(()));
        assert_eq!(near_front.map(|s| s.branch), Ok(Branch::FrontElbowUp));
        let near_back = choose(&robot, &g, p, Some([-80.0, -40.0, -40.0]), None, |_| Ok(()));
        assert_eq!(near_back.map(|s| s.branch), Ok(Branch::BackElbowUp));
        // First point: the front arm is more upright (|a2| + |a3| about 101 vs 112 deg).
        let first = choose(&robot, &g, p, None, None, |_| Ok(())).expect("ok");
        assert_eq!(first.branch, Branch::FrontElbowUp);
        // A collision test that rejects the front solution leaves the back one.
        let not_front = choose(&robot, &g, p, None, None, |a| match a[0] < 0.0 {
            true => Ok(()),
            false => Err("front".into()),
        })
        .expect("ok");
        assert_eq!(not_front.branch, Branch::BackElbowUp);
        let err = choose(&robot, &g, p, None, None, |_| Err("in the way".into())).unwrap_err();
        // Each solution's reason is kept, in the order of the branches.
        assert!(
            err.to_string().contains(
                "collides (front-elbow-up, back-elbow-up); front-elbow-up: in the way; \
                 back-elbow-up: in the way"
            ),
            "{err}"
        );
    }

    #[test]
    fn on_the_axis_1_line() {
        let (robot, g) = geom();
        let p = [0.0, 0.0, 1500.0];
        let sols = solve(&g, p);
        assert_eq!(sols.len(), 4);
        assert_eq!(sols[0].axes_deg[0], 0.0);
        assert_eq!(sols[2].axes_deg[0], 180.0);
        for s in &sols {
            assert!(dist(urdf_wrist(&robot, s.axes_deg), p) < 0.01);
        }
        let c = choose(&robot, &g, p, Some([42.0, -30.0, -40.0]), None, |_| Ok(())).expect("ok");
        assert_eq!(c.axes_deg[0], 42.0);
        assert!(dist(urdf_wrist(&robot, c.axes_deg), p) < 0.01);
    }

    #[test]
    fn serial_robot_speaks_its_own_controller_values() {
        let text = include_str!("../../../robots/irb1400.urdf");
        let robot = urdf::robot_from_urdf(Path::new("x.urdf"), text, None).expect("loads");
        let g = ArmGeometry::from_robot(&robot).expect("same structure");
        assert_eq!(g.coupling, Coupling::Serial);
        for a in [
            [10.0, 20.0, -30.0],
            [-100.0, -40.0, 60.0],
            [150.0, 60.0, -60.0],
        ] {
            let w = urdf_wrist(&robot, a);
            assert!(dist(forward(&g, a), w) < 1e-9);
            let sols = solve(&g, w);
            assert!(sols
                .iter()
                .any(|s| dist([s.axes_deg[0], s.axes_deg[1], s.axes_deg[2]], a) < 1e-6));
            for s in sols {
                assert!(dist(urdf_wrist(&robot, s.axes_deg), w) < 0.01);
            }
        }
    }

    #[test]
    fn refuses_other_structures() {
        let (robot, _) = geom();
        let mut r = robot.clone();
        r.joints[3].axis = nalgebra::Unit::new_normalize(Vector3::y());
        let err = ArmGeometry::from_robot(&r).unwrap_err().to_string();
        assert!(err.contains("joint 4") && err.contains("+x"), "{err}");
        let mut r = robot.clone();
        r.joints[2].origin.translation.vector.x = 5.0;
        let err = ArmGeometry::from_robot(&r).unwrap_err().to_string();
        assert!(err.contains("joint 3") && err.contains("x = 5.0"), "{err}");
        let mut r = robot;
        r.joints[1].origin.rotation = nalgebra::UnitQuaternion::from_euler_angles(0.0, 0.0, 0.1);
        let err = ArmGeometry::from_robot(&r).unwrap_err().to_string();
        assert!(err.contains("joint 2") && err.contains("rotated"), "{err}");
    }
}
