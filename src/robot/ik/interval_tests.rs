//! Tests of the interval arithmetic against sampling: every operation's result holds the
//! results at points sampled from its arguments (the ends included), and a chain's derivative
//! enclosure holds central differences; what is undefined is invalid.

use super::interval::{Dual, Interval};
use crate::geometry::testing::Rng;
use std::f64::consts::PI;

/// A random interval of centre within `+-spread` and width up to `width`.
fn random(rng: &mut Rng, spread: f64, width: f64) -> Interval {
    let c = rng.range(-spread, spread);
    let w = rng.range(0.0, width);
    Interval::new(c - w / 2.0, c + w / 2.0)
}

/// `n + 2` points of `a`: its ends and `n` inside.
fn members(rng: &mut Rng, a: &Interval, n: usize) -> Vec<f64> {
    let mut out = vec![a.lo(), a.hi()];
    out.extend((0..n).map(|_| rng.range(a.lo(), a.hi())));
    out
}

/// Whether `x` lies in `a` up to full turns.
fn holds_angle(a: &Interval, x: f64) -> bool {
    let k = ((a.mid() - x) / (2.0 * PI)).round();
    a.contains(x + 2.0 * PI * k)
}

/// The four operations, the square, sqrt, sin, cos and acos hold every sampled result, on
/// narrow and wide intervals (sin and cos over their extremes too). Fails with a result not
/// rounded outward or an extreme of sin or cos missed.
#[test]
fn operations_hold_sampled_results() {
    let mut rng = Rng(41);
    for round in 0..4000 {
        let width = if round % 2 == 0 { 1e-6 } else { 4.0 };
        let (a, b) = (random(&mut rng, 10.0, width), random(&mut rng, 10.0, width));
        let (sa, sb) = (members(&mut rng, &a, 6), members(&mut rng, &b, 6));
        for (&x, &y) in sa.iter().zip(&sb) {
            assert!((a + b).contains(x + y));
            assert!((a - b).contains(x - y));
            assert!((a * b).contains(x * y));
            assert!(a.sqr().contains(x * x));
            assert!(a.sin().contains(x.sin()), "{a:?} {x}");
            assert!(a.cos().contains(x.cos()), "{a:?} {x}");
            if !(b.lo() <= 0.0 && 0.0 <= b.hi()) {
                assert!(b.recip().contains(1.0 / y));
            }
            if a.lo() >= 0.0 {
                assert!(a.sqrt().contains(x.sqrt()));
            }
            let c = Interval::new(a.lo() / 11.0, a.hi() / 11.0);
            if c.lo() > -1.0 && c.hi() < 1.0 {
                let z = x / 11.0;
                if c.contains(z) {
                    assert!(c.acos().contains(z.acos()));
                }
            }
        }
    }
    // Extremes inside the interval.
    let around_peak = Interval::new(PI / 2.0 - 0.1, PI / 2.0 + 0.2);
    assert_eq!(around_peak.sin().hi(), 1.0);
    assert_eq!(Interval::new(PI - 0.1, PI + 0.1).cos().lo(), -1.0);
}

/// `atan2` of boxes in every direction (across the negative x axis too, where the angle wraps)
/// holds every sampled angle up to full turns, and is narrower than a half turn. Fails with
/// corners read in the wrong order or the wrap at +-pi mishandled.
#[test]
fn atan2_holds_sampled_angles_in_every_direction() {
    let mut rng = Rng(43);
    for round in 0..4000 {
        let width = if round % 2 == 0 { 1e-3 } else { 1.5 };
        let angle = rng.range(-PI, PI);
        let r = rng.range(1.0, 3.0);
        let (x, y) = (
            random(&mut rng, 0.0, width).shift(r * angle.cos()),
            random(&mut rng, 0.0, width).shift(r * angle.sin()),
        );
        let a = y.atan2(&x);
        assert!(a.is_valid() && a.width() < PI, "{x:?} {y:?}");
        for (&u, &v) in members(&mut rng, &x, 8)
            .iter()
            .zip(&members(&mut rng, &y, 8))
        {
            assert!(
                holds_angle(&a, v.atan2(u)),
                "{x:?} {y:?} {a:?} {}",
                v.atan2(u)
            );
        }
    }
    // Straddling the negative x axis: an interval about pi, not the whole circle.
    let a = Interval::new(-0.1, 0.1).atan2(&Interval::new(-2.0, -1.0));
    assert!(a.contains(PI) && a.width() < 0.3, "{a:?}");
}

/// Undefined cases are invalid: a division by an interval holding 0, acos reaching 1, atan2
/// of a box holding the origin, and everything computed from an invalid interval.
#[test]
fn undefined_operations_are_invalid() {
    let zero = Interval::new(-1.0, 1.0);
    assert!(!zero.recip().is_valid());
    assert!(!Interval::new(0.5, 1.0).acos().is_valid());
    assert!(!zero.atan2(&zero).is_valid());
    assert!(!Interval::new(1.0, 0.0).is_valid());
    let bad = zero.recip();
    assert!(!(bad + Interval::point(1.0)).is_valid());
    assert!(!(bad * Interval::point(0.0)).is_valid());
    assert!(!bad.sin().is_valid());
}

/// A chain of every operation on `s`: `atan2(sin 3s + 2, s cos s + 3) + acos(0.3 s)
/// + sqrt(s^2 + 1) / (s + 2)`.
fn chain(s: Dual) -> Dual {
    let k = |x: f64| Dual::constant(Interval::point(x));
    let y = (k(3.0) * s).sin() + k(2.0);
    let x = s * s.cos() + k(3.0);
    y.atan2(&x) + (k(0.3) * s).acos() + (s.sqr() + k(1.0)).sqrt().div(&(s + k(2.0)))
}

fn chain_f64(s: f64) -> f64 {
    ((3.0 * s).sin() + 2.0).atan2(s * s.cos() + 3.0)
        + (0.3 * s).acos()
        + (s * s + 1.0).sqrt() / (s + 2.0)
}

/// Over random intervals of `s`, the chain's enclosure holds its value and its central
/// difference at sampled points. Fails with a derivative rule wrong (a sign, a factor).
#[test]
fn a_chain_encloses_its_values_and_derivatives() {
    let mut rng = Rng(47);
    for _ in 0..2000 {
        let s = random(&mut rng, 1.0, 0.2);
        let e = chain(Dual::variable(s));
        assert!(e.is_valid(), "{s:?}");
        for &t in &members(&mut rng, &s, 8) {
            assert!(e.v.contains(chain_f64(t)), "{s:?} {t}");
            let h = 1e-6;
            let fd = (chain_f64(t + h) - chain_f64(t - h)) / (2.0 * h);
            let slack = 1e-7;
            assert!(
                e.d.lo() - slack <= fd && fd <= e.d.hi() + slack,
                "{s:?} {t}: {fd} not in {:?}",
                e.d
            );
        }
        // The enclosure narrows with the interval: a point's is tight.
        let p = chain(Dual::variable(Interval::point(s.mid())));
        assert!(p.v.width() < 1e-11 && p.d.width() < 1e-10, "{p:?}");
    }
}
