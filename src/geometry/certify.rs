//! The cylinder–box distance where the capsule bounds disagree, without GJK when it can be
//! avoided: alternating projections between the two solids, each step giving an upper bound (a
//! pair of points, one on each solid) and a lower bound (a separating direction: the gap between
//! the two solids' support planes along it). Beyond the paper, which only says the links are
//! cylinders; for speed only: parry's GJK in the band would be a large part of a whole run
//! (`benches/README.md`).
//!
//! *Upper bound.* `y` on the cylinder and `x` on the box: `|x - y| >= dist`. Projections onto
//! both solids are closed forms: the box's is a clamp; the solid cylinder is an interval along
//! its axis times a disc across it, so its projection clamps the axial coordinate into
//! `[0, len]` and the radial vector to length `r`.
//!
//! *Lower bound.* For a unit `n`, `min_{x in B} n.x - max_{y in C} n.y <= dist(C, B)` (every
//! point pair's distance is at least its extent along `n`). Both support values are closed
//! forms: the box's `sum_k n_k (min_k or max_k)`, the cylinder's `n.a + max(0, len n.u) +
//! r sqrt(1 - (n.u)^2)`. The direction is the last pair's `x - y`; at the closest pair it gives
//! the distance itself, so the two bounds close in on it together.
//!
//! Alternating projections converge to the closest pair of two disjoint convex sets; here a few
//! steps settle nearly every case. Both bounds are computed in `f64` with a slack
//! ([`SLACK_MM`]) that covers their rounding, so a decision is certain; what the steps leave
//! undecided (a distance within the slack of the clearance, or slow convergence) is answered by
//! parry's GJK as before (`super::distance_cylinder_aabb_exact`).

use super::{Aabb, Cylinder, Point};
use nalgebra::Vector3;

/// Rounding slack of both bounds, mm: the queries' coordinates are workspace-sized (metres), so
/// their `f64` rounding is below 1e-11 mm; the slack is a hundred times that and far below
/// parry's own tolerance.
pub const SLACK_MM: f64 = 1e-9;

/// Steps of alternating projection before the bounds give up.
const MAX_STEPS: usize = 32;

/// Lower and upper bounds of the distance between a solid cylinder and a box, mm, after the
/// alternating projections stopped: `lower <= dist <= upper` (both with the rounding slack
/// taken off and added on).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bracket {
    pub lower: f64,
    pub upper: f64,
}

/// Whether the cylinder keeps MORE than `clearance` from the box: `Some(true)` proven clear,
/// `Some(false)` proven within, `None` undecided (the caller asks GJK). `r > 0`, `len > 0`
/// expected; other inputs return `None`.
#[inline]
pub fn clear_by_projection(c: &Cylinder, bx: &Aabb, clearance: f64) -> Option<bool> {
    let mut verdict = None;
    run(c, bx, |lower, upper| {
        if lower > clearance {
            verdict = Some(true);
        } else if upper <= clearance {
            verdict = Some(false);
        }
        verdict.is_some()
    });
    verdict
}

/// Bounds of the cylinder–box distance, mm, starting from known bounds `lo <= dist <= hi` (the
/// capsule bounds) and narrowed until `upper - lower <= rel_tol (1 + upper)` or the steps give
/// up; `None` for a cylinder without radius or length (the capsule bounds are then exact).
pub fn bracket_by_projection(
    c: &Cylinder,
    bx: &Aabb,
    lo: f64,
    hi: f64,
    rel_tol: f64,
) -> Option<Bracket> {
    let mut out = None;
    run(c, bx, |lower, upper| {
        let b = Bracket {
            lower: lower.max(lo),
            upper: upper.min(hi),
        };
        out = Some(b);
        b.upper - b.lower <= rel_tol * (1.0 + b.upper)
    });
    out
}

/// The steps: calls `enough(lower, upper)` after each with the bounds so far (best of all
/// steps), stops when it says so or after [`MAX_STEPS`]. Nothing at all for a cylinder
/// without radius or length, or a non-finite one.
#[inline]
fn run(c: &Cylinder, bx: &Aabb, mut enough: impl FnMut(f64, f64) -> bool) {
    let d = c.b - c.a;
    let len = d.norm();
    let r = c.radius;
    if !(len > 0.0 && r > 0.0 && len.is_finite() && r.is_finite()) {
        return;
    }
    let cyl = Solid {
        a: c.a,
        u: d / len,
        len,
        r,
    };
    // Start from the box point nearest the axis' midpoint.
    let mid = nalgebra::center(&c.a, &c.b);
    let mut x = clamp_to_box(&mid, bx);
    let mut prev = x;
    let mut momentum = 0.0f64;
    let mut lower = f64::NEG_INFINITY;
    let mut upper = f64::INFINITY;
    for k in 0..MAX_STEPS {
        // Projected gradient step on half the squared distance to the cylinder over the box,
        // from an extrapolated point (Nesterov); the box's clamp keeps it on the box.
        let z = clamp_to_box(&(x + (x - prev) * momentum), bx);
        let y = cyl.project(&z);
        let mut x_next = clamp_to_box(&y, bx);
        let gap = x_next - y;
        let dist = gap.norm();
        if dist <= 0.0 || !dist.is_finite() {
            // The point pair coincides: the solids meet.
            enough(0.0, upper.min(dist.max(0.0) + SLACK_MM));
            return;
        }
        if dist + SLACK_MM < upper {
            upper = dist + SLACK_MM;
            momentum = k as f64 / (k as f64 + 3.0);
        } else {
            momentum = 0.0;
        }
        // Directions to try: the pair's; where its box point lies on one face only, or its
        // cylinder point on a cap, that face's or cap's normal (the separating direction at
        // the closest pair in those cases).
        let n = gap / dist;
        let mut best = (separation(&n, &cyl, bx), n);
        let mut consider = |m: Vector3<f64>| {
            let g = separation(&m, &cyl, bx);
            if g > best.0 {
                best = (g, m);
            }
        };
        if let Some(face) = face_normal(&x_next, &y, bx) {
            consider(face);
        }
        let along = (y - c.a).dot(&cyl.u);
        if along <= 0.0 || along >= len {
            consider(if along <= 0.0 { -cyl.u } else { cyl.u });
        }
        lower = lower.max(best.0 - SLACK_MM);
        // The cylinder's farthest point along the best direction and the box's point nearest
        // it: another pair, exact at once where that direction is the closest pair's (a rim
        // facing a face, which the projections alone approach slowly along the rim).
        // Projected onto the cylinder: a point of it whatever the rounding of the support.
        let y_s = cyl.project(&cyl.support(&best.1, bx));
        let x_s = clamp_to_box(&y_s, bx);
        let d_s = (x_s - y_s).norm();
        if d_s + SLACK_MM < upper {
            upper = d_s + SLACK_MM;
            if d_s < dist {
                x_next = x_s;
                momentum = 0.0;
            }
        }
        if enough(lower.max(0.0), upper) {
            return;
        }
        if x_next == x {
            break;
        }
        prev = x;
        x = x_next;
    }
}

/// The face's normal pointing into the box (from `y` towards the box) when `x`, the box's
/// point nearest `y`, lies on exactly one face (clamped on one axis only), else `None`.
#[inline(always)]
fn face_normal(x: &Point, y: &Point, bx: &Aabb) -> Option<Vector3<f64>> {
    let mut normal = None;
    for k in 0..3 {
        let side = if y[k] < bx.min[k] && x[k] == bx.min[k] {
            -1.0
        } else if y[k] > bx.max[k] && x[k] == bx.max[k] {
            1.0
        } else {
            continue;
        };
        if normal.is_some() {
            return None;
        }
        // From the cylinder towards the box: against the face's outward normal.
        let mut n = Vector3::zeros();
        n[k] = -side;
        normal = Some(n);
    }
    normal
}

/// The box's point nearest `p`.
#[inline(always)]
pub fn clamp_to_box(p: &Point, bx: &Aabb) -> Point {
    Point::new(
        p.x.clamp(bx.min.x, bx.max.x),
        p.y.clamp(bx.min.y, bx.max.y),
        p.z.clamp(bx.min.z, bx.max.z),
    )
}

/// The solid cylinder as the steps use it: axis from `a` along the unit `u`, length `len`,
/// radius `r` (both positive), mm.
struct Solid {
    a: Point,
    u: Vector3<f64>,
    len: f64,
    r: f64,
}

impl Solid {
    /// The cylinder's point nearest `p`: the axial coordinate clamped into `[0, len]`, the
    /// radial vector to length `r` (the solid is an interval along its axis times a disc).
    #[inline(always)]
    fn project(&self, p: &Point) -> Point {
        let w = p - self.a;
        let t = w.dot(&self.u);
        let radial = w - self.u * t;
        let rho = radial.norm();
        let radial = if rho > self.r {
            radial * (self.r / rho)
        } else {
            radial
        };
        self.a + self.u * t.clamp(0.0, self.len) + radial
    }

    /// A point farthest along the unit `n` (a support point), chosen near the box where the
    /// farthest points form a whole cap: the cap end `n` points to, then across the axis the
    /// rim point towards `n`; when `n` is (within 1e-9) along the axis, the cap's point
    /// nearest the box point nearest the cap's centre. Callers project it back onto the
    /// cylinder ([`project`](Self::project)) against rounding.
    #[inline(always)]
    fn support(&self, n: &Vector3<f64>, bx: &Aabb) -> Point {
        let u = &self.u;
        let nu = n.dot(u);
        let end = if nu > 0.0 {
            self.a + u * self.len
        } else {
            self.a
        };
        let across = n - u * nu;
        // Once more against rounding: `across` must be square to the axis.
        let across = across - u * across.dot(u);
        let w = across.norm();
        if w > 1e-9 {
            return end + across * (self.r / w);
        }
        let to_box = clamp_to_box(&end, bx) - end;
        let flat = to_box - u * to_box.dot(u);
        let f = flat.norm();
        if f > self.r {
            end + flat * (self.r / f)
        } else {
            end + flat
        }
    }

    /// `max_{y in C} n.y` for a unit `n`: the cap end `n` leans to, and the rim across.
    #[inline(always)]
    fn reach_along(&self, n: &Vector3<f64>) -> f64 {
        let nu = n.dot(&self.u);
        n.dot(&self.a.coords) + (self.len * nu).max(0.0) + self.r * (1.0 - nu * nu).max(0.0).sqrt()
    }
}

/// `min_{x in B} n.x - max_{y in C} n.y` for a unit `n`: the gap between the two solids'
/// support planes across `n`, a lower bound of their distance (negative when they overlap
/// along `n`).
#[inline(always)]
fn separation(n: &Vector3<f64>, cyl: &Solid, bx: &Aabb) -> f64 {
    let boxed: f64 = (0..3)
        .map(|k| {
            if n[k] > 0.0 {
                n[k] * bx.min[k]
            } else {
                n[k] * bx.max[k]
            }
        })
        .sum();
    boxed - cyl.reach_along(n)
}
