//! Forward kinematics from the joints' sines and cosines, with rotation matrices: the same poses
//! as [`Robot::link_poses`] (which composes quaternions and takes a `sin_cos` per joint), for
//! callers that place many poses whose angles repeat (a leg's tool looks at grid nodes: axes
//! 1..3 take grid values, whose sines and cosines a table holds).
//!
//! Per joint `i` the chain composes `origin_i * Rot(u_i, q_i)`; with `A` the origin's rotation
//! and `K` the cross-product matrix of the unit axis `u`, Rodrigues' formula gives
//! `A Rot(u, q) = A + sin q (A K) + (1 - cos q) (A K^2)`, the three matrices made once. The
//! poses agree with `link_poses` to rounding (about 1e-12 mm at a metre; the tests hold them
//! to 1e-9 mm on random poses). A joint whose origin does not rotate and whose axis is a
//! coordinate axis (most URDF joints; the first carries the robot's placement in the cell) turns
//! two columns of the pose instead (`turn`, the columns named at compile time). A caller keeps
//! link 1's pose per value of joint 1 ([`SinCosChain::pose1`]) and places the rest from it
//! ([`SinCosChain::pose6_from1`]); the tests hold that to the whole chain from the base, step by
//! step (`pose6`), to the bit. Beyond the paper: a speed device only.

use super::Robot;
use nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, UnitQuaternion, Vector3};

/// A 3x3 matrix as rows, for the hand-unrolled products of the chain.
type M3 = [[f64; 3]; 3];

#[inline(always)]
fn rows(m: &Matrix3<f64>) -> M3 {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)]))
}

/// `p` with columns `A` and `B` turned by the angle of sine `s` and cosine `c`: `p Rot(e_k,
/// q)` for the axis `e_k` that completes `A`, `B` to a right-handed cycle.
#[inline(always)]
fn turn<const A: usize, const B: usize>(p: &M3, s: f64, c: f64) -> M3 {
    let mut r = *p;
    for row in &mut r {
        let (pa, pb) = (row[A], row[B]);
        row[A] = c * pa + s * pb;
        row[B] = c * pb - s * pa;
    }
    r
}

/// One joint of the chain: `A`, `A K`, `A K^2` and the origin's translation (module doc).
#[derive(Clone, Copy, Debug)]
struct Joint {
    a: M3,
    ak: M3,
    ak2: M3,
    t: [f64; 3],
    /// `Some((k, sign))` when the origin does not rotate and the axis is `sign * e_k` (most
    /// URDFs): then the step turns two columns of the pose instead of composing matrices.
    aligned: Option<(usize, f64)>,
    /// Which coordinates of `t` are not 0 (bit `k` for coordinate `k`): the step leaves out
    /// the products by the others (most URDF origins lie on one or two axes).
    t_nonzero: u8,
}

/// A pose of the chain (rotation rows and translation, mm), without nalgebra's types, for
/// placing points in the unrolled products.
#[derive(Clone, Copy, Debug)]
pub struct Pose {
    r: M3,
    t: [f64; 3],
}

impl Pose {
    /// The pose as an isometry (the rotation turned into a unit quaternion: rounding only).
    pub fn isometry(&self) -> Isometry3<f64> {
        let m = Matrix3::from_fn(|r, c| self.r[r][c]);
        Isometry3::from_parts(
            Translation3::from(Vector3::from(self.t)),
            UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m)),
        )
    }

    /// `x` (in this pose's frame) in the parent frame.
    #[inline(always)]
    pub fn apply(&self, x: &[f64; 3]) -> [f64; 3] {
        let (r, t) = (&self.r, &self.t);
        std::array::from_fn(|k| t[k] + r[k][0] * x[0] + r[k][1] * x[1] + r[k][2] * x[2])
    }

    /// Point `p` (in this pose's frame) in the parent frame.
    #[inline(always)]
    pub fn point(&self, p: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.apply(&[p.x, p.y, p.z]))
    }

    /// Vector `v` (in this pose's frame) turned into the parent frame.
    #[inline(always)]
    pub fn vector(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let r = &self.r;
        Vector3::from_fn(|k, _| r[k][0] * v.x + r[k][1] * v.y + r[k][2] * v.z)
    }
}

/// The robot's six joints ready for poses from sines and cosines, with a base frame folded into
/// the first joint's origin (module doc).
#[derive(Clone, Debug)]
pub struct SinCosChain {
    joints: [Joint; 6],
}

impl SinCosChain {
    /// The chain of `robot` whose poses are given in the frame where the robot's base frame is
    /// `base` (the identity for the robot base frame).
    pub fn new(robot: &Robot, base: &Isometry3<f64>) -> SinCosChain {
        SinCosChain {
            joints: std::array::from_fn(|i| {
                let j = &robot.joints[i];
                let origin = if i == 0 { base * j.origin } else { j.origin };
                let a = origin.rotation.to_rotation_matrix().into_inner();
                let u = j.axis.into_inner();
                let k = u.cross_matrix();
                let aligned = (0..3)
                    .find(|&e| u[e].abs() == 1.0 && u[(e + 1) % 3] == 0.0 && u[(e + 2) % 3] == 0.0)
                    .filter(|_| a == Matrix3::identity())
                    .map(|e| (e, u[e]));
                let t: [f64; 3] = origin.translation.vector.into();
                Joint {
                    aligned,
                    t_nonzero: (0..3).filter(|&k| t[k] != 0.0).fold(0, |m, k| m | 1 << k),
                    a: rows(&a),
                    ak: rows(&(a * k)),
                    ak2: rows(&(a * (k * k))),
                    t: origin.translation.vector.into(),
                }
            }),
        }
    }

    /// `pose * origin_i * Rot(u_i, q_i)` with `sc = (sin q_i, cos q_i)`.
    #[inline(always)]
    fn step(&self, pose: &Pose, i: usize, sc: (f64, f64)) -> Pose {
        let j = &self.joints[i];
        let p = &pose.r;
        // The translation's products by the coordinates of `t` that are not 0 (a product by 0
        // adds nothing: the same sums, up to the sign of a zero).
        let t: [f64; 3] = match j.t_nonzero {
            0b001 => std::array::from_fn(|r| pose.t[r] + p[r][0] * j.t[0]),
            0b010 => std::array::from_fn(|r| pose.t[r] + p[r][1] * j.t[1]),
            0b100 => std::array::from_fn(|r| pose.t[r] + p[r][2] * j.t[2]),
            0b101 => std::array::from_fn(|r| pose.t[r] + p[r][0] * j.t[0] + p[r][2] * j.t[2]),
            _ => std::array::from_fn(|r| {
                pose.t[r] + p[r][0] * j.t[0] + p[r][1] * j.t[1] + p[r][2] * j.t[2]
            }),
        };
        if let Some((k, sign)) = j.aligned {
            // pose * Rot(sign e_k, q): columns a = k+1, b = k+2 turn, column k stays (the
            // columns named at compile time, so the pose stays in registers).
            let (s, c) = (sign * sc.0, sc.1);
            let r = match k {
                0 => turn::<1, 2>(p, s, c),
                1 => turn::<2, 0>(p, s, c),
                _ => turn::<0, 1>(p, s, c),
            };
            return Pose { r, t };
        }
        let (s, v) = (sc.0, 1.0 - sc.1);
        let m: M3 = std::array::from_fn(|r| {
            std::array::from_fn(|c| j.a[r][c] + s * j.ak[r][c] + v * j.ak2[r][c])
        });
        Pose {
            r: std::array::from_fn(|r| {
                std::array::from_fn(|c| p[r][0] * m[0][c] + p[r][1] * m[1][c] + p[r][2] * m[2][c])
            }),
            t,
        }
    }

    /// The pose of link 3 for the sines and cosines of URDF joints 1..3 (for tests).
    #[cfg(test)]
    fn pose3(&self, sc: &[(f64, f64); 3]) -> Pose {
        let p1 = self.pose1(sc[0]);
        let p2 = self.step(&p1, 1, sc[1]);
        self.step(&p2, 2, sc[2])
    }

    /// The pose of link 6 (the flange's link) for the sines and cosines of URDF joints 1..3
    /// (`arm`) and 4..6 (`wrist`), every step from the base (for tests: the looks use
    /// [`pose6_from1`](Self::pose6_from1)).
    #[cfg(test)]
    pub fn pose6(&self, arm: &[(f64, f64); 3], wrist: &[(f64, f64); 3]) -> Pose {
        let p3 = self.pose3(arm);
        let p4 = self.step(&p3, 3, wrist[0]);
        let p5 = self.step(&p4, 4, wrist[1]);
        self.step(&p5, 5, wrist[2])
    }

    /// The pose of link 1 for the sine and cosine of URDF joint 1: the first step of
    /// [`pose6`](Self::pose6), for callers that keep one per value of joint 1.
    #[inline(always)]
    pub fn pose1(&self, sc: (f64, f64)) -> Pose {
        let first = Pose {
            r: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            t: [0.0; 3],
        };
        self.step(&first, 0, sc)
    }

    /// The pose of link 2 from link 1's pose `p1` ([`pose1`](Self::pose1)) and the sine and
    /// cosine of URDF joint 2: the second step of `pose6` (the grid build's
    /// columns, `collision::column`).
    #[inline(always)]
    pub fn pose2_from1(&self, p1: &Pose, sc: (f64, f64)) -> Pose {
        self.step(p1, 1, sc)
    }

    /// [`pose6`](Self::pose6) from link 1's pose `p1` ([`pose1`](Self::pose1) of the same
    /// joint 1), the sines and cosines of joints 2 and 3 (`arm23`) and the wrist's: the same
    /// steps, so the same pose to the bit.
    #[inline(always)]
    pub fn pose6_from1(&self, p1: &Pose, arm23: &[(f64, f64); 2], wrist: &[(f64, f64); 3]) -> Pose {
        let p2 = self.step(p1, 1, arm23[0]);
        let p3 = self.step(&p2, 2, arm23[1]);
        let p4 = self.step(&p3, 3, wrist[0]);
        let p5 = self.step(&p4, 4, wrist[1]);
        self.step(&p5, 5, wrist[2])
    }
}

/// Sines and cosines of angles on the written 0.001 deg lattice (`precision`), from a table
/// of whole degrees and one of thousandths by the angle-sum formulas: a leg's wrist angles are
/// rounded to that lattice, so the tool's looks need no `sin_cos` (rounding about 1e-16, as
/// the chain's). An angle within 1e-9 deg of the lattice is read as on it: at most 1.7e-11 rad,
/// under 1e-7 mm of motion at 2 m of reach, inside the 1e-6 mm by which the looks' margins are
/// lowered. Any other angle, or one outside the table, gets `sin_cos`.
#[derive(Clone, Debug)]
pub struct MilliDegSinCos {
    lo_deg: i64,
    whole: Vec<(f64, f64)>,
    milli: Vec<(f64, f64)>,
}

impl MilliDegSinCos {
    /// The table for angles in `[lo_deg, hi_deg]`.
    pub fn new(lo_deg: f64, hi_deg: f64) -> MilliDegSinCos {
        let lo = lo_deg.floor().max(-100_000.0) as i64;
        let hi = hi_deg.ceil().min(100_000.0) as i64;
        MilliDegSinCos {
            lo_deg: lo,
            whole: (lo..=hi.max(lo))
                .map(|d| (d as f64).to_radians().sin_cos())
                .collect(),
            milli: (0..1000)
                .map(|m| (f64::from(m) * 1e-3).to_radians().sin_cos())
                .collect(),
        }
    }

    /// `(sin, cos)` of `deg`.
    ///
    /// The nearest integer to the scaled angle by adding and taking off `1.5 * 2^52` (ties to
    /// even, unlike `round`; a tie is half a lattice step off the lattice and gets `sin_cos`
    /// either way), and the whole degrees and thousandths counted from the table's first
    /// degree, so both are divisions of a non-negative integer by a constant.
    #[inline]
    pub fn get(&self, deg: f64) -> (f64, f64) {
        const NEAREST: f64 = 6_755_399_441_055_744.0; // 1.5 * 2^52
        let scaled = deg * 1000.0;
        let m = (scaled + NEAREST) - NEAREST;
        if (scaled - m).abs() <= 1e-6 && m.abs() < 1e11 {
            // `m` is an integer below 1e11 in magnitude: exact as an i64.
            if let Some(sc) = self.thousandths(m as i64) {
                return sc;
            }
        }
        deg.to_radians().sin_cos()
    }

    /// `(sin, cos)` of `r` thousandths of a degree from the two tables, `None` off them.
    #[inline(always)]
    fn thousandths(&self, r: i64) -> Option<(f64, f64)> {
        let u = u64::try_from(r - self.lo_deg * 1000).ok()?;
        let (d, f) = ((u / 1000) as usize, (u % 1000) as usize);
        Some(angle_sum(*self.whole.get(d)?, *self.milli.get(f)?))
    }

    /// [`get`](Self::get) of `deg` rounded to the written 0.001 deg (`quantize_joints`), to the
    /// bit, from the rounded thousandths as an integer: no division by 1000, no
    /// multiplication back and no second rounding (a leg's looks, whose wrists are rounded so,
    /// `plan::leg`).
    ///
    /// Why the same bits: for `x = deg * 1000` below `1e9` in magnitude, `R =
    /// round_half_away(x)` (`precision`, an integer below `2^52`, exact as an `i64`) is the
    /// integer `quantize_joints` divides by its scale `10^JOINT_DECIMALS = 1000` (exact),
    /// giving `q = fl(R / 1000)` (`0.0` for `R = 0`, whose sign `get` does not see). `get(q)`
    /// scales back to `fl(q * 1000) = R (1 + e1) (1 + e2)`, `|e1|, |e2| <= 2^-53`, within
    /// `1e9 * 2^-52 < 3e-7` of `R`: below half a unit, so its nearest integer is `R` (no tie
    /// arises), within its `1e-6` of the lattice and below its `1e11`; so `get(q)` counts
    /// `R - lo * 1000` into the same two entries and returns their [`angle_sum`], as this does.
    /// A larger `x`, a NaN or an `R` off the table takes `get(q)` itself: the same path.
    #[inline(always)]
    pub fn get_rounded(&self, deg: f64) -> (f64, f64) {
        const _: () = assert!(crate::precision::JOINT_DECIMALS == 3);
        let x = deg * 1000.0;
        if x.abs() < 1e9 {
            if let Some(sc) = self.thousandths(crate::precision::round_half_away(x) as i64) {
                return sc;
            }
        }
        self.get_rounded_off_table(deg)
    }

    /// [`get_rounded`](Self::get_rounded) off the table: `get` of the rounded angle.
    #[cold]
    #[inline(never)]
    fn get_rounded_off_table(&self, deg: f64) -> (f64, f64) {
        self.get(crate::precision::quantize_joints([deg])[0])
    }
}

/// `(sin, cos)` of `x + y` from those of `x` (`a`) and `y` (`b`).
#[inline(always)]
fn angle_sum((sa, ca): (f64, f64), (sb, cb): (f64, f64)) -> (f64, f64) {
    (sa * cb + ca * sb, ca * cb - sa * sb)
}

impl Robot {
    /// The sines and cosines of URDF joints 1..3 from those of controller axes 1..3: the
    /// coupling of [`urdf_joints_deg`](Robot::urdf_joints_deg) by the angle-difference
    /// formulas (`q3 = a3 - a2` under a parallelogram coupling).
    #[inline]
    pub fn urdf_arm_sincos(&self, axes: &[(f64, f64); 3]) -> [(f64, f64); 3] {
        let [s1, s2, s3] = *axes;
        if self.controller.coupling == super::Coupling::Parallelogram {
            let (sa3, ca3) = s3;
            let (sa2, ca2) = s2;
            [s1, s2, (sa3 * ca2 - ca3 * sa2, ca3 * ca2 + sa3 * sa2)]
        } else {
            *axes
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::Coupling;
    use nalgebra::Point3;

    /// A small deterministic generator (xorshift), uniform in `[lo, hi)`.
    struct Rng(u64);
    impl Rng {
        fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
        }
    }

    fn sc(deg: f64) -> (f64, f64) {
        deg.to_radians().sin_cos()
    }

    /// Largest distance between the points a ring of probes 300 mm out takes when placed by
    /// `place` and by `iso`.
    fn gap_mm(place: impl Fn(&Point3<f64>) -> Point3<f64>, iso: &Isometry3<f64>) -> f64 {
        [
            [0.0, 0.0, 0.0],
            [300.0, 0.0, 0.0],
            [0.0, 300.0, 0.0],
            [0.0, 0.0, 300.0],
            [-200.0, 150.0, 250.0],
        ]
        .iter()
        .map(|p| {
            let p = Point3::from(*p);
            (place(&p) - iso * p).norm()
        })
        .fold(0.0, f64::max)
    }

    /// `p` placed by a chain's pose.
    fn by(pose: &Pose) -> impl Fn(&Point3<f64>) -> Point3<f64> + '_ {
        |p| Point3::from(pose.apply(&p.coords.into()))
    }

    fn check(robot: &Robot, base: &Isometry3<f64>, seed: u64) {
        let chain = SinCosChain::new(robot, base);
        let mut rng = Rng(seed);
        for _ in 0..2000 {
            let axes: [f64; 6] = std::array::from_fn(|_| rng.uniform(-200.0, 200.0));
            let poses = robot.link_poses(&axes);
            // Controller axes' sines and cosines, coupled as the controller says.
            let arm = robot.urdf_arm_sincos(&[sc(axes[0]), sc(axes[1]), sc(axes[2])]);
            let wrist = [sc(axes[3]), sc(axes[4]), sc(axes[5])];
            let l3 = chain.pose3(&arm);
            let l6 = chain.pose6(&arm, &wrist);
            // From link 1's pose: the same pose to the bit.
            let from1 = chain.pose6_from1(&chain.pose1(arm[0]), &[arm[1], arm[2]], &wrist);
            assert_eq!(
                format!("{from1:?}"),
                format!("{l6:?}"),
                "pose6_from1 at {axes:?}"
            );
            let probe = [[0.0, 0.0, 0.0], [120.0, -40.0, 300.0]];
            let pose = chain.pose6(&arm, &wrist);
            for p in &probe {
                let want = base * poses[5] * Point3::from(*p);
                let got = Point3::from(pose.apply(p));
                assert!((got - want).norm() < 1e-9, "pose6 at {axes:?}");
            }
            let iso = pose.isometry();
            assert!(
                gap_mm(|p| iso * p, &(base * poses[5])) < 1e-9,
                "isometry at {axes:?}"
            );
            assert!(
                gap_mm(by(&l3), &(base * poses[2])) < 1e-9,
                "link 3 at {axes:?}"
            );
            assert!(
                gap_mm(by(&l6), &(base * poses[5])) < 1e-9,
                "link 6 at {axes:?}"
            );
        }
    }

    #[test]
    fn poses_agree_with_link_poses_coupled_and_serial_with_a_base() {
        let mut robot = Robot::irb1400();
        assert_eq!(robot.controller.coupling, Coupling::Parallelogram);
        let base = Isometry3::new(
            Vector3::new(120.0, -850.0, 35.0),
            Vector3::new(0.1, -0.2, 1.3),
        );
        check(&robot, &Isometry3::identity(), 1);
        check(&robot, &base, 2);
        robot.controller.coupling = Coupling::Serial;
        check(&robot, &base, 3);
        // Turned origins and tilted or negative axes take the general step (the IRB 1400's
        // joints are all aligned): every joint in turn, then all at once.
        let mut rng = Rng(4);
        for i in 0..7 {
            let mut bent = Robot::irb1400();
            for (k, j) in bent.joints.iter_mut().enumerate() {
                if i == 6 || k == i {
                    let turn = Vector3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), 0.3);
                    j.origin.rotation = nalgebra::UnitQuaternion::new(turn) * j.origin.rotation;
                    let tilt = Vector3::new(rng.uniform(-1.0, 1.0), 0.5, rng.uniform(-1.0, 1.0));
                    j.axis = nalgebra::Unit::new_normalize(tilt);
                }
            }
            check(&bent, &base, 10 + i as u64);
        }
        // Negative aligned axes keep the aligned step.
        let mut neg = Robot::irb1400();
        for j in neg.joints.iter_mut() {
            j.axis = -j.axis;
        }
        check(&neg, &base, 20);
        assert!(SinCosChain::new(&neg, &base).joints[1..]
            .iter()
            .all(|j| j.aligned.is_some_and(|(_, s)| s == -1.0)));
    }

    #[test]
    fn the_millidegree_table_agrees_with_sin_cos() {
        let t = MilliDegSinCos::new(-300.0, 300.0);
        let mut rng = Rng(7);
        for _ in 0..20_000 {
            // On the lattice (as `quantize_joints` rounds), off it, and beyond the table.
            let on = crate::precision::quantize_joints([rng.uniform(-300.0, 300.0); 3])[0];
            for deg in [on, rng.uniform(-300.0, 300.0), rng.uniform(300.0, 900.0)] {
                let (s, c) = t.get(deg);
                let (s0, c0) = deg.to_radians().sin_cos();
                assert!((s - s0).abs() < 1e-14 && (c - c0).abs() < 1e-14, "{deg}");
            }
        }
        // The ends and negative thousandths.
        for deg in [-300.0, 300.0, -0.001, -179.999, 0.0] {
            let (s, c) = t.get(deg);
            let (s0, c0) = f64::to_radians(deg).sin_cos();
            assert!((s - s0).abs() < 1e-14 && (c - c0).abs() < 1e-14, "{deg}");
        }
    }

    /// `get_rounded` is `get` of the angle `quantize_joints` rounds, to the bit: random angles
    /// on and off the table, halves of the lattice step and their neighbours an ulp away
    /// (positive and negative), the table's ends and just past them, zeros, angles too large
    /// for the table or the integer path, and NaN and infinities. Fails if the halves went to
    /// even or were truncated, if the table were counted from another degree, or if an angle
    /// off the table took another path.
    #[test]
    fn get_rounded_is_get_of_the_rounded_angle_bit_for_bit() {
        let t = MilliDegSinCos::new(-300.0, 300.0);
        let same = |deg: f64| {
            let (a, b) = (
                t.get_rounded(deg),
                t.get(crate::precision::quantize_joints([deg])[0]),
            );
            let bits = |x: f64| if x.is_nan() { u64::MAX } else { x.to_bits() };
            assert!(
                bits(a.0) == bits(b.0) && bits(a.1) == bits(b.1),
                "{deg:e}: {a:?} vs {b:?}"
            );
        };
        let near = |deg: f64| {
            same(deg);
            same(-deg);
            // The neighbours by their bits, wrapping (below +0.0 they wrap to NaNs, which
            // both take by the same path; a plain `-` would overflow in a debug build).
            for k in 1..4 {
                let (up, down) = (deg.to_bits().wrapping_add(k), deg.to_bits().wrapping_sub(k));
                same(f64::from_bits(up));
                same(f64::from_bits(down));
                same(-f64::from_bits(up));
                same(-f64::from_bits(down));
            }
        };
        let mut rng = Rng(11);
        for _ in 0..100_000 {
            same(rng.uniform(-320.0, 320.0));
            same(rng.uniform(-2e6, 2e6));
            // Halves of the 0.001 deg step (in thousandths), and their neighbours.
            let m = (rng.uniform(-301_000.0, 301_000.0)).trunc();
            near((m + 0.5) / 1000.0);
            near(m / 1000.0);
        }
        for deg in [
            0.0005,
            0.0015,
            0.0025,
            0.4995,
            1.0005,
            179.9995,
            299.9995,
            300.0,
            300.0005,
            300.999,
            300.9995,
            301.0,
            301.0005,
            299.999,
            -300.0,
            -300.0005,
            -300.001,
            -299.9995,
            1e-300,
            999_999.999,
            999_999.999_5,
            1e6,
            1e7,
            1e12,
            4.6e15,
            1e300,
        ] {
            near(deg);
        }
        for deg in [0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            same(deg);
        }
    }

    #[test]
    fn a_mis_wired_angle_is_seen() {
        // The check above would fail if an angle went to the wrong joint: two wrist angles
        // swapped move the flange by far more than its tolerance.
        let robot = Robot::irb1400();
        let chain = SinCosChain::new(&robot, &Isometry3::identity());
        let axes = [10.0, 20.0, 30.0, 40.0, 50.0, 60.0];
        let poses = robot.link_poses(&axes);
        let arm = robot.urdf_arm_sincos(&[sc(10.0), sc(20.0), sc(30.0)]);
        let swapped = chain.pose6(&arm, &[sc(50.0), sc(40.0), sc(60.0)]);
        assert!(gap_mm(by(&swapped), &poses[5]) > 1.0);
        // And the coupling left out moves link 3.
        let uncoupled = chain.pose3(&[sc(10.0), sc(20.0), sc(30.0)]);
        assert!(gap_mm(by(&uncoupled), &poses[2]) > 1.0);
    }
}
