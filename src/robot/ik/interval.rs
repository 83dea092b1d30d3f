//! Interval arithmetic with first derivatives: what the follower's deviation bound is computed
//! with (`six::enclose`, `follow`).
//!
//! An [`Interval`] `[lo, hi]` encloses a real number; every operation returns an interval that
//! encloses every result the operation can give on members of its arguments. A [`Dual`] encloses
//! a function of one variable `s` on an interval `S` of it: its values (`v`) and its derivatives
//! (`d`) at every `s` in `S` (forward-mode differentiation: `(f g)' = f' g + f g'`, and each
//! elementary function's derivative), so a chain of operations encloses the derivative of the
//! whole chain over `S`.
//!
//! # Rounding
//! The four operations and `sqrt` are rounded to nearest by IEEE 754, within half a unit in the
//! last place (ulp) of the result: each result is widened outward by `2^-51 |x|` (at least two
//! ulp) plus the smallest normal number (underflow). `sin`, `cos`, `acos` and `atan2` come from
//! the platform's mathematics library, which is not correctly rounded but is accurate to about
//! one ulp (glibc documents at most 1-2 ulp for them): their results are widened by an absolute
//! [`ELEMENTARY_EPS`] (1e-13), which is hundreds of ulp at the magnitudes met here (angles below
//! 10 rad, sines and cosines below 1). That widening is the one assumption about the platform.
//!
//! # Failure
//! An operation that is not defined on all of its arguments (a division by an interval holding
//! 0, `acos` reaching +-1 where its derivative is infinite, `atan2` of a box holding the origin),
//! or whose result is not finite, gives the invalid interval (both ends NaN), and every operation
//! on an invalid interval is invalid: a caller checks [`Interval::is_valid`] at the end, never a
//! partial result.
//!
//! Why hand-written: `inari`, the maintained interval crate (IEEE 1788), needs a nightly
//! toolchain for most versions, a Haswell target CPU set in the consuming crate's build
//! configuration, and GMP/MPFR (a C build) for its elementary functions; we promise stable Rust
//! 1.85 on any x86-64 or ARM machine. The operations needed here are few.

use std::f64::consts::{FRAC_PI_2, PI};
use std::ops::{Add, Mul, Neg, Sub};

/// The absolute widening of the results of `sin`, `cos`, `acos` and `atan2` (module docs).
pub const ELEMENTARY_EPS: f64 = 1e-13;

/// A closed interval of reals, or the invalid interval (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    lo: f64,
    hi: f64,
}

const INVALID: Interval = Interval {
    lo: f64::NAN,
    hi: f64::NAN,
};

/// `x` rounded down by at least the error of one IEEE operation that gave it.
fn down(x: f64) -> f64 {
    x - (x.abs() * f64::EPSILON * 2.0 + f64::MIN_POSITIVE)
}

/// `x` rounded up likewise.
fn up(x: f64) -> f64 {
    x + (x.abs() * f64::EPSILON * 2.0 + f64::MIN_POSITIVE)
}

impl Interval {
    /// `[lo, hi]` as given (no widening); invalid unless `lo <= hi`, both finite.
    pub fn new(lo: f64, hi: f64) -> Interval {
        if lo.is_finite() && hi.is_finite() && lo <= hi {
            Interval { lo, hi }
        } else {
            INVALID
        }
    }

    /// The one number `x`.
    pub fn point(x: f64) -> Interval {
        Interval::new(x, x)
    }

    /// `[x - eps, x + eps]` (`eps >= 0`), rounded outward.
    pub fn around(x: f64, eps: f64) -> Interval {
        Interval::new(down(x - eps), up(x + eps))
    }

    /// The result of one rounded operation whose exact ends are `lo`, `hi` (module docs).
    fn rounded(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return INVALID;
        }
        Interval::new(down(lo), up(hi))
    }

    /// The result of an elementary function (module docs).
    fn elementary(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return INVALID;
        }
        Interval::new(down(lo - ELEMENTARY_EPS), up(hi + ELEMENTARY_EPS))
    }

    pub fn lo(&self) -> f64 {
        self.lo
    }

    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// Both ends finite (every valid interval).
    pub fn is_valid(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    pub fn width(&self) -> f64 {
        self.hi - self.lo
    }

    pub fn mid(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }

    /// Whether `x` lies in the interval.
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Whether 0 lies in the interval (or it is invalid).
    fn holds_zero(&self) -> bool {
        !self.is_valid() || (self.lo <= 0.0 && 0.0 <= self.hi)
    }

    /// The common part, or invalid when there is none.
    pub fn intersect(&self, other: &Interval) -> Interval {
        Interval::new(self.lo.max(other.lo), self.hi.min(other.hi))
    }

    /// The interval shifted by `x` (rounded outward).
    pub fn shift(&self, x: f64) -> Interval {
        *self + Interval::point(x)
    }

    /// The square, `[0, ..]` when the interval holds 0 (tighter than `self * self`).
    pub fn sqr(&self) -> Interval {
        if !self.is_valid() {
            return INVALID;
        }
        let (a, b) = (self.lo * self.lo, self.hi * self.hi);
        if self.lo >= 0.0 {
            Interval::rounded(a, b)
        } else if self.hi <= 0.0 {
            Interval::rounded(b, a)
        } else {
            Interval::new(0.0, up(a.max(b)))
        }
    }

    pub fn recip(&self) -> Interval {
        if self.holds_zero() {
            return INVALID;
        }
        Interval::rounded(1.0 / self.hi, 1.0 / self.lo)
    }

    /// The square root of the interval's part at or above 0 (invalid when it lies below 0).
    pub fn sqrt(&self) -> Interval {
        if !self.is_valid() || self.hi < 0.0 {
            return INVALID;
        }
        Interval::rounded(self.lo.max(0.0).sqrt(), self.hi.sqrt()).max_zero()
    }

    /// The interval with its lower end raised to 0 (for quantities that are never negative).
    fn max_zero(self) -> Interval {
        if !self.is_valid() {
            return INVALID;
        }
        Interval::new(self.lo.max(0.0), self.hi.max(0.0))
    }

    pub fn sin(&self) -> Interval {
        periodic(self, f64::sin, FRAC_PI_2)
    }

    pub fn cos(&self) -> Interval {
        periodic(self, f64::cos, 0.0)
    }

    /// `acos` of an interval inside `(-1, 1)` (invalid when it reaches +-1: there the derivative
    /// is infinite and the two solutions it separates meet).
    pub fn acos(&self) -> Interval {
        if !self.is_valid() || self.lo <= -1.0 || self.hi >= 1.0 {
            return INVALID;
        }
        Interval::elementary(self.hi.acos(), self.lo.acos())
    }

    /// The angle of the points `(x, y)` of the box `x` x `y` (`y` is `self`), as one interval
    /// of width below pi about the angle of the box's centre (which lies in (-pi, pi]); invalid
    /// when the box holds the origin. Its members are the angles modulo a full turn.
    pub fn atan2(&self, x: &Interval) -> Interval {
        let y = self;
        if !x.is_valid() || !y.is_valid() || (x.holds_zero() && y.holds_zero()) {
            return INVALID;
        }
        // A box without the origin lies in an open half-plane through it, so every point's
        // angle is within a half turn of the centre's: measured from the centre's direction
        // (cross and dot products), the extremes are at corners (the box is convex).
        let (xm, ym) = (x.mid(), y.mid());
        let centre = ym.atan2(xm);
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for cx in [x.lo, x.hi] {
            for cy in [y.lo, y.hi] {
                let a = (xm * cy - ym * cx).atan2(xm * cx + ym * cy);
                lo = lo.min(a);
                hi = hi.max(a);
            }
        }
        // The cross and dot products' rounding turns each corner's angle by far less than
        // ELEMENTARY_EPS; the centre's own angle is one more elementary result.
        Interval::elementary(centre + lo - ELEMENTARY_EPS, centre + hi + ELEMENTARY_EPS)
    }
}

/// `f` (sin or cos, period 2 pi) on `a`, whose maxima lie at `peak + 2 k pi` and minima half a
/// turn further.
fn periodic(a: &Interval, f: fn(f64) -> f64, peak: f64) -> Interval {
    if !a.is_valid() {
        return INVALID;
    }
    if a.width() >= 2.0 * PI {
        return Interval::new(-1.0, 1.0);
    }
    let (fa, fb) = (f(a.lo), f(a.hi));
    let mut lo = fa.min(fb);
    let mut hi = fa.max(fb);
    // A critical point counts when it lies within a margin of the interval: including one
    // costs nothing there (f is flat at its extremes), missing one would be wrong.
    let margin = 1e-9;
    let hits = |at: f64| {
        let k = ((a.lo - margin - at) / (2.0 * PI)).ceil();
        at + 2.0 * PI * k <= a.hi + margin
    };
    if hits(peak) {
        hi = 1.0;
    }
    if hits(peak + PI) {
        lo = -1.0;
    }
    let r = Interval::elementary(lo, hi);
    Interval::new(r.lo.max(-1.0), r.hi.min(1.0))
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval::rounded(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        Interval::rounded(self.lo - o.hi, self.hi - o.lo)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval::new(-self.hi, -self.lo)
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return INVALID;
        }
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::rounded(lo, hi)
    }
}

/// A function of one variable on an interval of it: its values and its derivatives there
/// (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual {
    pub v: Interval,
    pub d: Interval,
}

impl Dual {
    /// The variable itself on `s`.
    pub fn variable(s: Interval) -> Dual {
        Dual {
            v: s,
            d: Interval::point(1.0),
        }
    }

    /// A constant known within `value`.
    pub fn constant(value: Interval) -> Dual {
        Dual {
            v: value,
            d: Interval::point(0.0),
        }
    }

    /// A constant computed in floating point from exact inputs: the number within `eps`
    /// relative to `1 + |x|` (the rounding of its construction).
    pub fn near(x: f64, eps: f64) -> Dual {
        Dual::constant(Interval::around(x, eps * (1.0 + x.abs())))
    }

    pub fn is_valid(&self) -> bool {
        self.v.is_valid() && self.d.is_valid()
    }

    pub fn scale(&self, k: Interval) -> Dual {
        Dual {
            v: self.v * k,
            d: self.d * k,
        }
    }

    pub fn sqr(&self) -> Dual {
        Dual {
            v: self.v.sqr(),
            d: Interval::point(2.0) * self.v * self.d,
        }
    }

    pub fn recip(&self) -> Dual {
        let r = self.v.recip();
        Dual {
            v: r,
            d: -(self.d * r.sqr()),
        }
    }

    pub fn div(&self, o: &Dual) -> Dual {
        *self * o.recip()
    }

    /// The square root of a quantity that is never negative; its derivative needs it above 0.
    pub fn sqrt(&self) -> Dual {
        let r = self.v.sqrt();
        Dual {
            v: r,
            d: self.d * (Interval::point(2.0) * r).recip(),
        }
    }

    pub fn sin(&self) -> Dual {
        Dual {
            v: self.v.sin(),
            d: self.v.cos() * self.d,
        }
    }

    pub fn cos(&self) -> Dual {
        Dual {
            v: self.v.cos(),
            d: -(self.v.sin() * self.d),
        }
    }

    pub fn acos(&self) -> Dual {
        let root = (Interval::point(1.0) - self.v.sqr()).max_zero().sqrt();
        Dual {
            v: self.v.acos(),
            d: -(self.d * root.recip()),
        }
    }

    /// `atan2(self, x)`: the angle of `(x, self)` (see [`Interval::atan2`]), derivative
    /// `(x y' - y x') / (x^2 + y^2)`.
    pub fn atan2(&self, x: &Dual) -> Dual {
        let y = self;
        let r2 = x.v.sqr() + y.v.sqr();
        Dual {
            v: y.v.atan2(&x.v),
            d: (x.v * y.d - y.v * x.d) * r2.recip(),
        }
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        Dual {
            v: self.v + o.v,
            d: self.d + o.d,
        }
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual {
            v: self.v - o.v,
            d: self.d - o.d,
        }
    }
}

impl Neg for Dual {
    type Output = Dual;
    fn neg(self) -> Dual {
        Dual {
            v: -self.v,
            d: -self.d,
        }
    }
}

impl Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        Dual {
            v: self.v * o.v,
            d: self.d * o.v + self.v * o.d,
        }
    }
}
