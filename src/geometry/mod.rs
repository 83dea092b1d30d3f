//! Shapes and distance queries for the collision checker.
//!
//! The arm is lumped into three link cylinders, following Ting & Jar (2006),
//! sections 3 and 6 ("the shape of the first three links is assumed to be
//! cylinder"); the obstacles of the cell are axis-aligned boxes. All lengths
//! are millimetres in the cell frame.
//!
//! The planner calls these queries millions of times, so the hot functions
//! ([`distance_point_aabb`], [`distance_segment_aabb`], the two capsule
//! bounds and [`cylinder_clear_of_aabb`]) are hand-written, closed-form,
//! allocation-free and exact in `f64`. The exact cylinder–box distance has no
//! closed form: where the two capsule bounds disagree, alternating projections
//! between the two solids narrow a certified bracket (`certify.rs`: point pairs
//! above, separating planes below), and parry3d's GJK
//! ([`distance_cylinder_aabb_exact`]) answers only what they leave open. Every
//! fast query is checked against parry3d in the tests of this module.
//!
//! The tool's shapes add a ball and an oriented box (`solids.rs`: exact closed forms, held
//! against parry3d there), and [`Solid`], the one type for any placed part of the robot model.
//! [`path`] holds the TCP paths of process moves (`MoveL` lines, `MoveC` arcs, `RelTool`).
//!
//! Inputs are assumed finite (validated upstream): no function panics on
//! finite input, and behaviour for NaN is out of scope (it may return NaN or
//! an arbitrary value, but does not panic).

use nalgebra::{Point3, Vector3};

mod certify;
mod lazy;
pub mod path;
mod solids;
pub use certify::{bracket_by_projection, clamp_to_box, clear_by_projection, Bracket};
pub use lazy::{decide, decide2, Measured, NARROW_REL};
pub use solids::{
    distance_obb_aabb, distance_sphere_aabb, gap_sq_aabb_aabb, obb_clear_of_aabb, Obb, Solid,
    Sphere, OBB_AXIS_SLACK_MM,
};

/// A point of the cell frame, mm.
pub type Point = Point3<f64>;

/// Bounds within which the two capsule bounds are considered to agree in
/// [`distance_cylinder_aabb`]: below this band width (mm) the lower bound is
/// returned without calling parry.
pub const BOUNDS_AGREE_TOL: f64 = 1e-9;

/// [`distance_cylinder_aabb`] in the band: a bracket of the alternating projections narrower
/// than this times `(1 mm + d)` gives its lower end as the distance. A tenth of the slack the
/// collision proofs take off every distance (`collision::proof::DISTANCE_SLACK_REL`), so the
/// bracket's width never decides a proof that the exact distance would not.
pub const BRACKET_TOL_REL: f64 = 1e-7;

/// Axis-aligned box in the cell frame, mm. Invariant: `min <= max` per axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lower corner, mm.
    pub min: Point,
    /// Upper corner, mm.
    pub max: Point,
}

/// Solid right circular cylinder with flat caps: axis segment `a -> b` (mm)
/// and `radius` (mm, assumed `>= 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    /// Centre of the first cap, mm.
    pub a: Point,
    /// Centre of the second cap, mm.
    pub b: Point,
    /// Radius, mm.
    pub radius: f64,
}

impl Aabb {
    /// Box spanned by two corners (mm). The corners are sorted per axis, so
    /// any two opposite corners may be given.
    pub fn new(min: Point, max: Point) -> Aabb {
        Aabb {
            min: min.inf(&max),
            max: min.sup(&max),
        }
    }

    /// Centre of the box, mm.
    fn center(&self) -> Point {
        nalgebra::center(&self.min, &self.max)
    }
}

/// Signed excess of coordinate `x` outside the interval `[lo, hi]`:
/// negative below, positive above, zero inside.
#[inline(always)]
fn excess(x: f64, lo: f64, hi: f64) -> f64 {
    // Without branches: at most one term is not 0 (`lo <= hi`), and a NaN `x` gives 0 as
    // `min`/`max` return the other operand.
    (x - lo).min(0.0) + (x - hi).max(0.0)
}

/// Squared distance from a point to a box, mm².
#[inline(always)]
pub fn distance_sq_point_aabb(p: &Point, b: &Aabb) -> f64 {
    let ex = excess(p.x, b.min.x, b.max.x);
    let ey = excess(p.y, b.min.y, b.max.y);
    let ez = excess(p.z, b.min.z, b.max.z);
    ex * ex + ey * ey + ez * ez
}

/// Euclidean distance from point `p` to box `b`, mm; 0 inside or on it.
#[inline]
pub fn distance_point_aabb(p: &Point, b: &Aabb) -> f64 {
    distance_sq_point_aabb(p, b).sqrt()
}

/// Parameter `t` in `[0, 1]` of the point of segment `a + t d` closest to the
/// box (one minimiser when several exist).
///
/// `g(t)`, the squared distance from `a + t d` to the box, is a convex, C¹,
/// piecewise quadratic function of `t`, with breakpoints where a coordinate
/// crosses a face plane (at most 6). Its derivative is
/// `g'(t) / 2 = sum_i d_i * excess_i(t)`, non-decreasing and linear between
/// breakpoints. The minimiser is 0 where `g'(0) >= 0`, 1 where `g'(1) <= 0`;
/// else it lies in a bracket `[lo, hi]`, `g'(lo) <= 0 <= g'(hi)`, which every
/// breakpoint inside it narrows (the sign of `g'` there says which end it
/// replaces). After the six breakpoints no breakpoint is left inside the
/// bracket, so `g'` is linear on it, and the minimiser is the root of that
/// line, clamped to the bracket. No sorting, no iteration, no allocation.
#[inline]
pub fn closest_param_segment_aabb(a: &Point, d: &Vector3<f64>, bx: &Aabb) -> f64 {
    let slope = |t: f64| {
        let mut s = 0.0;
        for i in 0..3 {
            let x = a[i] + t * d[i];
            s += d[i] * excess(x, bx.min[i], bx.max[i]);
        }
        s
    };
    if slope(0.0) >= 0.0 {
        return 0.0;
    }
    if slope(1.0) <= 0.0 {
        return 1.0;
    }
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for i in 0..3 {
        let di = d[i];
        if di == 0.0 {
            continue;
        }
        let inv = 1.0 / di;
        for face in [bx.min[i], bx.max[i]] {
            let t = (face - a[i]) * inv;
            if t > lo && t < hi {
                let s = slope(t);
                if s <= 0.0 {
                    lo = t;
                }
                if s >= 0.0 {
                    hi = t;
                }
            }
        }
    }
    if lo >= hi {
        return lo;
    }
    // g'(t) / 2 = A t + B on the bracket: its state read at the midpoint.
    let mid = 0.5 * (lo + hi);
    let mut ca = 0.0f64;
    let mut cb = 0.0f64;
    for i in 0..3 {
        let di = d[i];
        let x = a[i] + mid * di;
        // The face plane the coordinate is beyond, if any (selects, not branches).
        let bound = x.max(bx.min[i]).min(bx.max[i]);
        let outside = x < bx.min[i] || x > bx.max[i];
        ca += if outside { di * di } else { 0.0 };
        cb += if outside { di * (a[i] - bound) } else { 0.0 };
    }
    if ca > 0.0 {
        (-cb / ca).max(lo).min(hi)
    } else {
        lo
    }
}

/// Exact Euclidean distance between segment `a -> b` and box `bx`, mm;
/// 0 when they touch or intersect. Closed form (see the module source); a
/// degenerate segment (`a == b`) is a point.
#[inline]
pub fn distance_segment_aabb(a: &Point, b: &Point, bx: &Aabb) -> f64 {
    let d = b - a;
    let t = closest_param_segment_aabb(a, &d, bx);
    distance_point_aabb(&(a + d * t), bx)
}

/// Lower bound of the cylinder–box distance, mm: the distance of the capsule
/// of the same radius on the same axis segment, which contains the cylinder
/// (segment distance minus radius, clamped at 0).
#[inline]
pub fn distance_capsule_aabb(c: &Cylinder, bx: &Aabb) -> f64 {
    (distance_segment_aabb(&c.a, &c.b, bx) - c.radius.max(0.0)).max(0.0)
}

/// Radius `rho` and axis segment of the largest inner capsule used for the
/// upper bound: `rho = min(r, L/2)`, segment shortened by `rho` at each end.
#[inline(always)]
fn inner_capsule(c: &Cylinder) -> (Point, Point, f64) {
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius.max(0.0);
    if len <= 2.0 * r {
        // Segment shorter than the diameter: the midpoint sphere of radius
        // L/2 (the largest ball centred on the axis inside the cylinder).
        let m = nalgebra::center(&c.a, &c.b);
        (m, m, 0.5 * len)
    } else {
        let s = r / len;
        (c.a + d * s, c.b - d * s, r)
    }
}

/// Upper bound of the cylinder–box distance, mm: the distance of the capsule
/// of radius `r` on the axis segment shortened by `r` at each end (it lies
/// inside the cylinder). If the axis is shorter than `2r`, the midpoint
/// sphere of radius `L/2` is used instead (the largest axis-centred ball
/// inside the cylinder). A result of 0 proves the cylinder meets the box.
#[inline]
pub fn distance_inner_capsule_aabb(c: &Cylinder, bx: &Aabb) -> f64 {
    let (p, q, rho) = inner_capsule(c);
    (distance_segment_aabb(&p, &q, bx) - rho).max(0.0)
}

/// Both bounds at once: (capsule lower bound, inner-capsule upper bound).
#[inline(always)]
fn bounds(c: &Cylinder, bx: &Aabb) -> (f64, f64) {
    (
        distance_capsule_aabb(c, bx),
        distance_inner_capsule_aabb(c, bx),
    )
}

/// Exact distance between the solid cylinder and the box, mm (0 when they
/// touch or overlap), via parry3d's GJK. Slow path.
///
/// Precision: we use parry3d's f64 build (`parry3d-f64`, renamed in Cargo.toml). GJK returns a
/// pair of points on the two shapes, so it errs from above, and its rounding grows with the
/// shapes' size: measured against closed forms, below 1e-8 mm for cell-sized boxes (up to about
/// 10 m), but 2e-6 mm for a 200 m box and 2e-3 mm for a 20 km one. `collision` therefore clips
/// every box to the robot's workspace before asking. The query is made in a frame centred on
/// the box, run in both argument orders (a single run can stall far above the true distance;
/// `benches/README.md` has a case), and the result is clamped into the exact capsule bounds, so
/// it always lies in `[distance_capsule_aabb, distance_inner_capsule_aabb]`.
///
/// Degenerate inputs: radius 0 gives the segment distance; an axis of zero
/// length has no orientation, and is answered conservatively with the ball of
/// radius `r` around `a` (which contains every disc it could stand for).
pub fn distance_cylinder_aabb_exact(c: &Cylinder, bx: &Aabb) -> f64 {
    let (lo, hi) = bounds(c, bx);
    if hi <= 0.0 {
        return 0.0;
    }
    let r = c.radius.max(0.0);
    if r == 0.0 {
        return hi; // lo == hi == segment distance
    }
    let d = c.b - c.a;
    let len = d.norm();
    if len == 0.0 {
        return lo;
    }
    clamp_into(parry_cylinder_aabb(c, bx, &(d / len), len, r), lo, hi)
}

/// `x` clamped into `[lo, hi]` without panicking when rounding makes
/// `lo > hi` (then the bounds coincide and `lo` is returned).
#[inline(always)]
fn clamp_into(x: f64, lo: f64, hi: f64) -> f64 {
    x.min(hi).max(lo)
}

/// The raw parry3d (f64, GJK) cylinder–cuboid distance in a box-centred frame.
/// `u` is the unit axis, `len` its length, `r > 0`.
fn parry_cylinder_aabb(c: &Cylinder, bx: &Aabb, u: &Vector3<f64>, len: f64, r: f64) -> f64 {
    use parry3d::math::{Pose, Rotation, Vector};

    let centre = bx.center();
    let half = (bx.max - bx.min) * 0.5;
    let cuboid = parry3d::shape::Cuboid {
        half_extents: Vector::new(half.x, half.y, half.z),
    };
    // Built from the fields: `Cylinder::new` asserts on its arguments.
    let cyl = parry3d::shape::Cylinder {
        half_height: (0.5 * len),
        radius: r,
    };
    // Shortest rotation taking parry's local +Y axis onto `u`, in f64.
    // Y × u = (u.z, 0, -u.x), w = 1 + Y·u.
    let w = 1.0 + u.y;
    let (qx, qy, qz, qw) = if w < 1e-12 {
        (1.0, 0.0, 0.0, 0.0) // u = -Y: half turn about X
    } else {
        let n = (u.z * u.z + u.x * u.x + w * w).sqrt();
        (u.z / n, 0.0, -u.x / n, w / n)
    };
    let rot = Rotation::from_xyzw(qx, qy, qz, qw);
    let mid = nalgebra::center(&c.a, &c.b) - centre;
    let pos12 = Pose::from_parts(Vector::new(mid.x, mid.y, mid.z), rot);
    // GJK (seen with the f32 build) can stall far from the optimum (70.8 mm
    // returned for a true 2.88 mm). Its result is a pair of points on the
    // shapes, so an upper bound: run it in both orders and keep the smaller.
    let d12 = parry3d::query::details::distance_support_map_support_map(&pos12, &cuboid, &cyl);
    let d21 =
        parry3d::query::details::distance_support_map_support_map(&pos12.inverse(), &cyl, &cuboid);
    d12.min(d21)
}

/// The query the planner uses: `true` when the cylinder keeps MORE than
/// `clearance` mm from the box.
///
/// The capsule bound accepts fast (`lower > clearance`), the inner-capsule
/// bound rejects fast (`upper <= clearance`); when `clearance` lies in
/// `[lower, upper)` the alternating projections of `certify.rs` decide (a
/// separating plane farther than `clearance`, or a point pair nearer), and
/// only what they leave open goes to parry's GJK. The answer is exact except
/// when the true distance is within parry's tolerance of `clearance` (see
/// [`distance_cylinder_aabb_exact`]; there parry errs towards "clear").
#[inline]
pub fn cylinder_clear_of_aabb(c: &Cylinder, bx: &Aabb, clearance: f64) -> bool {
    let lo = distance_capsule_aabb(c, bx);
    if lo > clearance {
        return true;
    }
    let hi = distance_inner_capsule_aabb(c, bx);
    if hi <= clearance {
        return false;
    }
    // Alternating projections decide nearly every case (`certify.rs`); GJK the rest.
    if let Some(clear) = clear_by_projection(c, bx, clearance) {
        return clear;
    }
    distance_cylinder_aabb_exact_in_band(c, bx, lo, hi) > clearance
}

/// Parry query for a cylinder whose bounds `lo < hi` are already known.
#[inline]
fn distance_cylinder_aabb_exact_in_band(c: &Cylinder, bx: &Aabb, lo: f64, hi: f64) -> f64 {
    let r = c.radius.max(0.0);
    let d = c.b - c.a;
    let len = d.norm();
    if r == 0.0 || len == 0.0 {
        return lo;
    }
    clamp_into(parry_cylinder_aabb(c, bx, &(d / len), len, r), lo, hi)
}

/// Distance between the solid cylinder and the box, mm, computed through the
/// capsule bounds.
///
/// Returns the lower (capsule) bound when the two bounds are within
/// [`BOUNDS_AGREE_TOL`] of each other — then it is the exact distance to
/// that tolerance; this is the common case where the closest point of the
/// axis lies at least `r` from both ends, or the inner capsule touches the
/// box (0). Otherwise the lower end of the certified bracket of `certify.rs`
/// when it is narrower than [`BRACKET_TOL_REL`] (so the result errs low, by
/// less than that), else parry's value clamped into the bracket. The result is
/// always within `[distance_capsule_aabb, distance_inner_capsule_aabb]`.
#[inline]
pub fn distance_cylinder_aabb(c: &Cylinder, bx: &Aabb) -> f64 {
    let (lo, hi) = distance_cylinder_aabb_bounds(c, bx);
    if lo == hi {
        return lo;
    }
    distance_cylinder_aabb_in_band(c, bx, lo, hi)
}

/// A lower bound of the cylinder–box distance, mm, good where a flat cap faces the box (where
/// the capsule bound is up to the radius low): the best of three capsules about the axis
/// shortened by `k r` (k = 1, 2.5, 6, at most half the length) at each end, of radius
/// `hypot(r, k r)`, each holding the cap rims and so the cylinder. `-inf` for a cylinder
/// without radius or length.
#[inline]
pub fn rim_capsules_lower_bound(c: &Cylinder, bx: &Aabb) -> f64 {
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius.max(0.0);
    let mut best = f64::NEG_INFINITY;
    if len > 0.0 && r > 0.0 {
        let u = d / len;
        for k in [1.0, 2.5, 6.0] {
            let sh = (k * r).min(0.5 * len);
            let lb = distance_segment_aabb(&(c.a + u * sh), &(c.b - u * sh), bx) - r.hypot(sh);
            best = best.max(lb);
        }
    }
    best
}

/// Bounds of the value [`distance_cylinder_aabb`] gives, mm, from the capsule bounds alone (two
/// segment queries): `(lo, hi)` with `lo <= distance_cylinder_aabb(c, bx) <= hi`, equal where
/// that value is `lo` itself (bounds within [`BOUNDS_AGREE_TOL`]). Narrowed by
/// [`distance_cylinder_aabb_narrowed`], made exact by [`distance_cylinder_aabb_in_band`].
#[inline]
pub fn distance_cylinder_aabb_bounds(c: &Cylinder, bx: &Aabb) -> (f64, f64) {
    let (lo, hi) = bounds(c, bx);
    if hi - lo <= BOUNDS_AGREE_TOL {
        (lo, lo)
    } else {
        (lo, hi.max(lo))
    }
}

/// Bounds of the value [`distance_cylinder_aabb`] gives in the band `lo < hi` of
/// [`distance_cylinder_aabb_bounds`], narrower than them: the same alternating projections
/// stopped once their bracket is within `rel_tol (1 + upper)`. Their steps are a prefix of
/// the steps that value is read from (the bracket only narrows from step to step, and a
/// narrower tolerance stops no sooner), so the bracket holds it: its lower end where the
/// steps ran to [`BRACKET_TOL_REL`], parry's value clamped into the final bracket where they
/// gave up. Both ends that value where it is reached as cheaply.
#[inline]
pub fn distance_cylinder_aabb_narrowed(
    c: &Cylinder,
    bx: &Aabb,
    lo: f64,
    hi: f64,
    rel_tol: f64,
) -> (f64, f64) {
    let Some(b) = bracket_by_projection(c, bx, lo, hi, rel_tol.max(BRACKET_TOL_REL)) else {
        let d = distance_cylinder_aabb_exact_in_band(c, bx, lo, hi);
        return (d, d);
    };
    if b.upper - b.lower <= BRACKET_TOL_REL * (1.0 + b.upper) {
        return (b.lower, b.lower);
    }
    (b.lower, b.upper.max(b.lower))
}

/// [`distance_cylinder_aabb`] where its capsule bounds `lo < hi` are known (from
/// [`distance_cylinder_aabb_bounds`]): the same value, without measuring them again. The lower
/// end of the alternating projections' bracket (`certify.rs`) when it is within
/// [`BRACKET_TOL_REL`]` (1 + d)` of its upper end, else parry's GJK clamped into the bracket.
#[inline]
pub fn distance_cylinder_aabb_in_band(c: &Cylinder, bx: &Aabb, lo: f64, hi: f64) -> f64 {
    let (lower, upper) = distance_cylinder_aabb_narrowed(c, bx, lo, hi, BRACKET_TOL_REL);
    if lower == upper {
        return lower;
    }
    distance_cylinder_aabb_exact_in_band(c, bx, lower, upper)
}

/// Shared by the tests of this crate's geometry and collision modules.
#[cfg(test)]
pub(crate) mod testing {
    use super::Point;

    /// Tiny deterministic xorshift64* generator (no `rand` dependency).
    pub(crate) struct Rng(pub(crate) u64);
    impl Rng {
        pub(crate) fn next_u64(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
        }
        /// Uniform in [lo, hi).
        pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
            let u = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
            lo + (hi - lo) * u
        }
        pub(crate) fn below(&mut self, n: u64) -> u64 {
            self.next_u64() % n
        }
        pub(crate) fn point(&mut self, lo: f64, hi: f64) -> Point {
            Point::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
        }
    }
}

#[cfg(test)]
mod tests;
