//! The closed form itself: arm and wrist subproblems, full turns, and the reasons when no
//! solution is in range (see the parent module's docs for the method and its choices).

use super::{
    excess_deg, Candidate, SixAxisError, SixAxisIk, Solution, COS_SLACK, LIMIT_SNAP_DEG,
    OFFSET_TOL_MM, SAME_DEG, SINGULAR_LINE_MM, SINGULAR_WRIST,
};
use crate::robot::{Axes6, RangeViolation};
use nalgebra::{Isometry3, Point3, Rotation3, Unit, Vector3};
use std::f64::consts::PI;

/// What [`SixAxisIk::analyse`] found: every branch, in range or not.
pub(super) struct Analysis {
    pub(super) wrist_mm: [f64; 3],
    /// In-range solutions, all turns.
    pub(super) solutions: Vec<Solution>,
    /// One candidate per branch (the turn nearest to range), with its violations.
    pub(super) candidates: Vec<Candidate>,
}

impl SixAxisIk {
    pub(super) fn analyse(
        &self,
        tool0: &Isometry3<f64>,
        previous: Option<&Axes6>,
    ) -> Result<Analysis, SixAxisError> {
        let (wrist_mm, bases) = self.bases(tool0, previous)?;
        let mut solutions = Vec::new();
        let mut candidates = Vec::new();
        for base in &bases {
            let (in_range, nearest) = self.turns(base);
            for axes in in_range {
                if !solutions
                    .iter()
                    .any(|s: &Solution| same(&s.axes_deg, &axes))
                {
                    solutions.push(Solution {
                        axes_deg: axes,
                        conf: self.conf(&axes),
                    });
                }
            }
            candidates.push(Candidate {
                axes_deg: nearest,
                conf: self.conf(&nearest),
                violations: self.violations(&nearest),
            });
        }
        solutions.sort_by(|a, b| order_key(a).cmp(&order_key(b)).then(lex(a, b)));
        candidates.sort_by(|a, b| {
            let key = |c: &Candidate| (c.conf.cfx, c.conf.cf1, c.conf.cf4, c.conf.cf6);
            key(a).cmp(&key(b)).then(lex_axes(&a.axes_deg, &b.axes_deg))
        });
        Ok(Analysis {
            wrist_mm,
            solutions,
            candidates,
        })
    }

    /// Every branch of a tool0 pose (robot base frame, mm), each axis wrapped into (-180, 180]
    /// and no range applied: up to 8 (arm stance, elbow, wrist flip), in the solver's fixed
    /// order. `previous` settles the singular choices (module docs). What a caller that turns
    /// the axes itself needs, such as the continuing inverse (`ik::follow`); an error only for a
    /// pose that is not finite or out of the arm's reach.
    pub fn branches(
        &self,
        tool0: &Isometry3<f64>,
        previous: Option<&Axes6>,
    ) -> Result<Vec<Axes6>, SixAxisError> {
        Ok(self.bases(tool0, previous)?.1)
    }

    /// The wrist centre of a tool0 pose and its branches ([`branches`](Self::branches)).
    fn bases(
        &self,
        tool0: &Isometry3<f64>,
        previous: Option<&Axes6>,
    ) -> Result<([f64; 3], Vec<Axes6>), SixAxisError> {
        let finite = tool0.translation.vector.iter().all(|v| v.is_finite())
            && tool0.rotation.coords.iter().all(|v| v.is_finite());
        if !finite {
            return Err(SixAxisError::NotFinite);
        }
        let reference = previous
            .map(|p| self.coupling.urdf_rad(p))
            .unwrap_or([0.0; 6]);
        let w = tool0 * Point3::from(self.wrist_in_tool0);
        let wrist_mm = [w.x, w.y, w.z];
        let arms = self.arm_solutions(&w, &reference)?;
        let r_target = tool0.rotation.to_rotation_matrix()
            * self.tool0_zero.rotation.to_rotation_matrix().inverse();
        let mut bases: Vec<Axes6> = Vec::with_capacity(8);
        for arm in &arms {
            let m = self.rotation(&arm[..3], 0).inverse() * r_target;
            for wrist in self.wrist_solutions(&m, reference[3]) {
                let q = [arm[0], arm[1], arm[2], wrist[0], wrist[1], wrist[2]];
                let axes = self.coupling.controller_deg(&q).map(wrap_deg);
                if !bases.iter().any(|b| same(b, &axes)) {
                    bases.push(axes);
                }
            }
        }
        Ok((wrist_mm, bases))
    }

    /// URDF `(q1, q2, q3)` (rad) putting the wrist centre at `w`, up to four.
    pub(super) fn arm_solutions(
        &self,
        w: &Point3<f64>,
        reference: &[f64; 6],
    ) -> Result<Vec<[f64; 6]>, SixAxisError> {
        let [a1, a2, a3, ..] = self.axes;
        let v = w - a1.point;
        let e_a = a2.dir.into_inner();
        let e_b = a1.dir.cross(&e_a);
        let (x, y) = (e_a.dot(&v), e_b.dot(&v));
        let rho = x.hypot(y);
        let m = self.shoulder_offset_mm;
        let wrist_mm = [w.x, w.y, w.z];
        let q1s: Vec<f64> = if rho <= SINGULAR_LINE_MM && m.abs() <= OFFSET_TOL_MM {
            vec![reference[0], reference[0] + PI]
        } else if rho < m.abs() {
            return Err(SixAxisError::BesideShoulder {
                wrist_mm,
                from_axis1_mm: rho,
                offset_mm: m.abs(),
            });
        } else {
            let phi = y.atan2(x);
            let d = (m / rho).clamp(-1.0, 1.0).acos();
            vec![phi + d, phi - d]
        };
        let (lu, lf) = (self.upper_arm_mm, self.forearm_mm);
        let wv = self.wrist_zero - self.elbow;
        let pv = self.elbow - self.shoulder;
        let psi = signed_angle(&a3.dir, &wv, &pv);
        let mut out = Vec::with_capacity(4);
        let mut distances = Vec::with_capacity(2);
        for q1 in q1s {
            let w_arm = a1.rotate(-q1, w);
            let b = w_arm - self.shoulder;
            let delta = b.norm();
            distances.push((q1, delta));
            let c = (delta * delta - lf * lf - lu * lu) / (2.0 * lf * lu);
            if c.is_nan() || c.abs() > 1.0 + COS_SLACK {
                continue;
            }
            let e = c.clamp(-1.0, 1.0).acos();
            for q3 in [psi + e, psi - e] {
                let w3 = a3.rotate(q3, &self.wrist_zero);
                let a = w3 - self.shoulder;
                let q2 = if a.norm() <= SINGULAR_LINE_MM || b.norm() <= SINGULAR_LINE_MM {
                    reference[1]
                } else {
                    signed_angle(&a2.dir, &a, &b)
                };
                out.push([q1, q2, q3, 0.0, 0.0, 0.0]);
            }
        }
        if out.is_empty() {
            let (lo, hi) = self.reach_mm();
            let front = |q1: f64| {
                let f = Rotation3::from_axis_angle(&a1.dir, q1) * self.forward_zero;
                f.dot(&(w - a1.point)) >= 0.0
            };
            let pick = |want_front: bool| {
                distances
                    .iter()
                    .filter(|(q1, _)| front(*q1) == want_front)
                    .map(|&(_, d)| d)
                    .next()
            };
            let front_mm = pick(true).unwrap_or(distances[0].1);
            let back_mm = pick(false).unwrap_or(distances[distances.len() - 1].1);
            let miss = |d: f64| (d - hi).max(lo - d);
            return Err(SixAxisError::OutOfReach {
                wrist_mm,
                front_mm,
                back_mm,
                min_mm: lo,
                max_mm: hi,
                by_mm: miss(front_mm).min(miss(back_mm)),
            });
        }
        Ok(out)
    }

    /// URDF `(q4, q5, q6)` (rad) with `R4 R5 R6 = m`: two (the wrist flip), or one when axes 4
    /// and 6 are in line (axis 4 then keeps `q4_reference`).
    pub(super) fn wrist_solutions(&self, m: &Rotation3<f64>, q4_reference: f64) -> Vec<[f64; 3]> {
        let (u4, u5, u6) = (self.axes[3].dir, self.axes[4].dir, self.axes[5].dir);
        let t = m * u6.into_inner();
        let finish = |q4: f64, c: Vector3<f64>| {
            let q5 = signed_angle(&u5, &u6, &c);
            let rest = self.rotation(&[q4, q5], 3).inverse() * m;
            let q6 = signed_angle(&u6, &u5, &(rest * u5.into_inner()));
            [q4, q5, q6]
        };
        if u4.cross(&t).norm() <= SINGULAR_WRIST {
            let c = Rotation3::from_axis_angle(&u4, -q4_reference) * t;
            return vec![finish(q4_reference, c)];
        }
        let alpha = u4.dot(&t);
        // sin of the angle between axis 4 and axis 6's target; the cross product keeps its
        // precision near the singularity, where sqrt(1 - alpha^2) would lose it.
        let gamma = u4.cross(&t).norm();
        let n = u4.cross(&u5);
        [gamma, -gamma]
            .into_iter()
            .map(|g| {
                let c = u4.into_inner() * alpha + n * g;
                let q4 = signed_angle(&u4, &c, &t);
                finish(q4, c)
            })
            .collect()
    }

    /// Every full-turn variant of `base` within all ranges (the coupled one too), and the one
    /// variant nearest to range (for messages).
    pub(super) fn turns(&self, base: &Axes6) -> (Vec<Axes6>, Axes6) {
        let specs = &self.robot.controller.axes;
        let mut per_axis: Vec<Vec<f64>> = Vec::with_capacity(6);
        let mut nearest = *base;
        for (i, (&v, spec)) in base.iter().zip(specs).enumerate() {
            let (lo, hi) = (spec.min_deg, spec.max_deg);
            let snap = |x: f64| {
                if x < lo && lo - x <= LIMIT_SNAP_DEG {
                    lo
                } else if x > hi && x - hi <= LIMIT_SNAP_DEG {
                    hi
                } else {
                    x
                }
            };
            let k_lo = ((lo - LIMIT_SNAP_DEG - v) / 360.0).ceil() as i64;
            let k_hi = ((hi + LIMIT_SNAP_DEG - v) / 360.0).floor() as i64;
            let values: Vec<f64> = (k_lo..=k_hi).map(|k| snap(v + 360.0 * k as f64)).collect();
            nearest[i] = match values.iter().find(|x| (**x - v).abs() < 1e-9) {
                Some(&x) => x,
                None => values.first().copied().unwrap_or_else(|| {
                    [v, v - 360.0, v + 360.0]
                        .into_iter()
                        .min_by(|a, b| outside(*a, lo, hi).total_cmp(&outside(*b, lo, hi)))
                        .unwrap_or(v)
                }),
            };
            per_axis.push(values);
        }
        let mut all: Vec<Axes6> = vec![[0.0; 6]];
        for (i, values) in per_axis.iter().enumerate() {
            all = all
                .into_iter()
                .flat_map(|a| {
                    values.iter().map(move |&x| {
                        let mut b = a;
                        b[i] = x;
                        b
                    })
                })
                .collect();
        }
        if let Some([lo, hi]) = self.robot.controller.coupled_axis3_deg {
            // The coupled range snaps too, by moving axis 3 (its own range already snapped).
            for a in &mut all {
                let d = a[2] - a[1];
                if d > hi && d - hi <= LIMIT_SNAP_DEG {
                    a[2] = a[1] + hi;
                } else if d < lo && lo - d <= LIMIT_SNAP_DEG {
                    a[2] = a[1] + lo;
                }
            }
        }
        all.retain(|a| self.robot.check_range6(a).is_ok());
        // A branch with an in-range variant is represented by the one nearest to its wrap.
        let distance = |a: &Axes6| a.iter().zip(base).map(|(x, y)| (x - y).abs()).sum::<f64>();
        if let Some(first) = all
            .iter()
            .min_by(|a, b| distance(a).total_cmp(&distance(b)).then(lex_axes(a, b)))
        {
            nearest = *first;
        }
        (all, nearest)
    }

    /// Every limit `axes_deg` breaks (empty exactly when `Robot::check_range6` accepts it).
    pub fn violations(&self, axes_deg: &Axes6) -> Vec<RangeViolation> {
        let c = &self.robot.controller;
        let mut out = Vec::new();
        for (i, (&v, spec)) in axes_deg.iter().zip(&c.axes).enumerate() {
            if !(v >= spec.min_deg && v <= spec.max_deg) {
                out.push(RangeViolation::Axis {
                    axis: i + 1,
                    value_deg: v,
                    min_deg: spec.min_deg,
                    max_deg: spec.max_deg,
                });
            }
        }
        if let Some([lo, hi]) = c.coupled_axis3_deg {
            let v = axes_deg[2] - axes_deg[1];
            if !(v >= lo && v <= hi) {
                out.push(RangeViolation::Coupled {
                    value_deg: v,
                    min_deg: lo,
                    max_deg: hi,
                });
            }
        }
        out
    }

    /// The specific reason when no candidate is in range.
    pub(super) fn why_none(&self, a: Analysis) -> SixAxisError {
        let arm_ok: Vec<&Candidate> = a
            .candidates
            .iter()
            .filter(|c| {
                c.violations.iter().all(|v| match v {
                    RangeViolation::Axis { axis, .. } => *axis > 3,
                    RangeViolation::Coupled { .. } => false,
                })
            })
            .collect();
        let axis5 = |c: &Candidate| {
            c.violations
                .iter()
                .find(|v| matches!(v, RangeViolation::Axis { axis: 5, .. }))
                .cloned()
        };
        if !arm_ok.is_empty() && arm_ok.iter().all(|c| axis5(c).is_some()) {
            let nearest = arm_ok
                .iter()
                .filter_map(|c| axis5(c))
                .min_by(|x, y| excess_deg(x).total_cmp(&excess_deg(y)));
            if let Some(RangeViolation::Axis {
                value_deg,
                min_deg,
                max_deg,
                ..
            }) = nearest
            {
                return SixAxisError::Axis5 {
                    wrist_mm: a.wrist_mm,
                    needed_deg: value_deg,
                    min_deg,
                    max_deg,
                    by_deg: outside(value_deg, min_deg, max_deg),
                };
            }
        }
        SixAxisError::OutOfRange {
            wrist_mm: a.wrist_mm,
            candidates: a.candidates,
        }
    }
}

/// Signed angle about `axis` turning `from` onto `to` (both projected normal to it), rad.
pub(super) fn signed_angle(
    axis: &Unit<Vector3<f64>>,
    from: &Vector3<f64>,
    to: &Vector3<f64>,
) -> f64 {
    let u = axis.into_inner();
    let a = from - u * u.dot(from);
    let b = to - u * u.dot(to);
    u.dot(&a.cross(&b)).atan2(a.dot(&b))
}

/// How far `v` lies outside `[lo, hi]` (0 inside).
pub(super) fn outside(v: f64, lo: f64, hi: f64) -> f64 {
    (lo - v).max(v - hi).max(0.0)
}

/// Wraps an angle into (-180, 180], deg.
pub(super) fn wrap_deg(a: f64) -> f64 {
    let w = a - 360.0 * ((a + 180.0) / 360.0).floor();
    if w <= -180.0 {
        w + 360.0
    } else if w > 180.0 {
        w - 360.0
    } else {
        w
    }
}

pub(super) fn same(a: &Axes6, b: &Axes6) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= SAME_DEG)
}

pub(super) fn order_key(s: &Solution) -> (i32, i32, i32, i32) {
    (s.conf.cfx, s.conf.cf1, s.conf.cf4, s.conf.cf6)
}

pub(super) fn lex_axes(a: &Axes6, b: &Axes6) -> std::cmp::Ordering {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.total_cmp(y))
        .find(|o| o.is_ne())
        .unwrap_or(std::cmp::Ordering::Equal)
}

pub(super) fn lex(a: &Solution, b: &Solution) -> std::cmp::Ordering {
    lex_axes(&a.axes_deg, &b.axes_deg)
}
