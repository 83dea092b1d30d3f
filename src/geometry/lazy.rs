//! A solid's distance to a box known only as well as a decision needs it: bounds `[lo, hi]`
//! of the value [`Solid::distance_aabb`] gives, narrowed on demand, in four stages for a
//! cylinder (its capsule bounds, two segment queries; the lower one raised by the rim capsules,
//! three more; the alternating projections stopped at [`NARROW_REL`]; the value itself) and the
//! value at once for a ball or a box (closed forms).
//!
//! The rim capsules bound the true distance, which the value may lie below by the bracket's
//! width (at most [`BRACKET_TOL_REL`](super::BRACKET_TOL_REL) of `1 mm + d`, as it is the
//! lower end of a bracket that narrow, or parry's value, which errs from above): so their bound
//! is lowered by twice that ([`RIM_SLACK_REL`]) before it raises `lo`.
//!
//! A decision that is a monotone test of distances (a proof's "this interval keeps the
//! clearance", "this point is nearer than the best so far") is taken on the bounds when both
//! ends of them answer alike ([`decide`], [`decide2`]), else on narrower ones, down to the
//! value: so it is always the decision the value itself gives, and a proof or a certified
//! figure built from such decisions is the same, bit for bit, as one built from the values.

use super::{
    distance_cylinder_aabb_bounds, distance_cylinder_aabb_in_band, distance_cylinder_aabb_narrowed,
    rim_capsules_lower_bound, Aabb, Solid,
};

/// The relative width (of `1 mm + upper`) at which the middle stage stops its alternating
/// projections: wide enough to stop after a few steps, narrow enough that few decisions are
/// left open by it.
pub const NARROW_REL: f64 = 1e-4;

/// The rim capsules' bound is lowered by this times `1 mm + |bound|` (module doc).
const RIM_SLACK_REL: f64 = 2.0 * super::BRACKET_TOL_REL;

/// How well a [`Measured`] distance is known.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Stage {
    /// A cylinder's capsule bounds.
    Capsule,
    /// The capsule bounds, the lower one raised by the rim capsules.
    Rims,
    /// The alternating projections' bracket at [`NARROW_REL`].
    Narrowed,
    /// The value of [`Solid::distance_aabb`].
    Exact,
}

/// The distance from `solid` to a box: `lo <= Solid::distance_aabb(box) <= hi`, both equal to
/// it once exact. The box is passed to every call (the same box each time).
#[derive(Clone, Copy, Debug)]
pub struct Measured {
    pub lo: f64,
    pub hi: f64,
    /// A cylinder's capsule lower bound (the value is read from the band above it).
    capsule: f64,
    stage: Stage,
    solid: Solid,
}

impl Measured {
    /// The first bounds: a cylinder's capsule bounds (exact where they agree), a ball's or a
    /// box's distance.
    #[inline]
    pub fn new(solid: Solid, b: &Aabb) -> Measured {
        if let Solid::Cylinder(c) = &solid {
            let (lo, hi) = distance_cylinder_aabb_bounds(c, b);
            let stage = if lo == hi {
                Stage::Exact
            } else {
                Stage::Capsule
            };
            return Measured {
                lo,
                hi,
                capsule: lo,
                stage,
                solid,
            };
        }
        Measured::exact_of(solid, b)
    }

    /// The value itself at once.
    #[inline]
    pub fn exact_of(solid: Solid, b: &Aabb) -> Measured {
        let d = solid.distance_aabb(b);
        Measured {
            lo: d,
            hi: d,
            capsule: d,
            stage: Stage::Exact,
            solid,
        }
    }

    /// An exempt pair's: infinitely far, exact.
    pub fn infinite(solid: Solid) -> Measured {
        Measured {
            lo: f64::INFINITY,
            hi: f64::INFINITY,
            capsule: f64::INFINITY,
            stage: Stage::Exact,
            solid,
        }
    }

    /// Whether the bounds are the value.
    #[inline]
    pub fn is_exact(&self) -> bool {
        self.stage == Stage::Exact
    }

    /// The value (made exact first).
    #[inline]
    pub fn value(&mut self, b: &Aabb) -> f64 {
        self.make_exact(b);
        self.lo
    }

    /// The next stage's bounds (none after exact).
    #[inline]
    pub fn narrow(&mut self, b: &Aabb) {
        match (self.stage, &self.solid) {
            (Stage::Capsule, Solid::Cylinder(c)) => {
                let rims = rim_capsules_lower_bound(c, b);
                let rims = rims - RIM_SLACK_REL * (1.0 + rims.abs());
                self.lo = self.lo.max(rims.min(self.hi));
                self.stage = Stage::Rims;
            }
            (Stage::Rims, Solid::Cylinder(c)) => {
                let (lo, hi) =
                    distance_cylinder_aabb_narrowed(c, b, self.capsule, self.hi, NARROW_REL);
                if lo == hi {
                    (self.lo, self.hi, self.stage) = (lo, hi, Stage::Exact);
                } else {
                    (self.lo, self.hi) = (self.lo.max(lo), self.hi.min(hi));
                    self.stage = Stage::Narrowed;
                }
            }
            (Stage::Exact, _) => {}
            _ => self.make_exact(b),
        }
    }

    /// The value as [`Solid::distance_aabb`] gives it. From the capsule stage, without
    /// measuring the capsule bounds again.
    #[inline]
    pub fn make_exact(&mut self, b: &Aabb) {
        let d = match (self.stage, &self.solid) {
            (Stage::Exact, _) => return,
            (Stage::Capsule | Stage::Rims, Solid::Cylinder(c)) => {
                distance_cylinder_aabb_in_band(c, b, self.capsule, self.hi)
            }
            _ => self.solid.distance_aabb(b),
        };
        (self.lo, self.hi, self.stage) = (d, d, Stage::Exact);
    }
}

/// `test(d)` for the value `d` of `m`, where `test` is monotone (true at some `x` means true at
/// every `y >= x`, or false at every `y >= x` for a test that is true low): taken on the
/// bounds, narrowed until both ends answer alike.
#[inline]
pub fn decide(m: &mut Measured, b: &Aabb, test: impl Fn(f64) -> bool) -> bool {
    loop {
        let at_lo = test(m.lo);
        if m.is_exact() || at_lo == test(m.hi) {
            return at_lo;
        }
        m.narrow(b);
    }
}

/// `test(d0, d1)` for the values of `m0` and `m1` (distances to the same box), where `test` is
/// monotone in each, the same way in both: taken on the bounds, the less known one (the wider,
/// on a tie the first) narrowed until the bounds' two corners answer alike.
#[inline]
pub fn decide2(
    m0: &mut Measured,
    m1: &mut Measured,
    b: &Aabb,
    test: impl Fn(f64, f64) -> bool,
) -> bool {
    loop {
        let at_lo = test(m0.lo, m1.lo);
        if (m0.is_exact() && m1.is_exact()) || at_lo == test(m0.hi, m1.hi) {
            return at_lo;
        }
        let first = !m0.is_exact()
            && (m1.is_exact()
                || m0.stage < m1.stage
                || (m0.stage == m1.stage && m0.hi - m0.lo >= m1.hi - m1.lo));
        if first {
            m0.narrow(b);
        } else {
            m1.narrow(b);
        }
    }
}
