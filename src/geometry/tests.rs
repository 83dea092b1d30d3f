//! Tests of the shapes and distance queries, each fast query held against parry3d.

use super::*;
use parry3d::math::{Pose, Vector};

use super::testing::Rng;

fn p(x: f64, y: f64, z: f64) -> Point {
    Point::new(x, y, z)
}

fn random_box(rng: &mut Rng) -> Aabb {
    let c = rng.point(600.0, 1400.0);
    let h = Vector3::new(
        rng.range(0.0, 400.0),
        rng.range(0.0, 400.0),
        rng.range(0.0, 400.0),
    );
    Aabb::new(c - h, c + h)
}

/// Random segment of one of several kinds: generic, degenerate,
/// parallel to one or two axes, crossing the box, starting on a face.
fn random_segment(rng: &mut Rng, bx: &Aabb) -> (Point, Point) {
    let a = rng.point(0.0, 2000.0);
    match rng.below(6) {
        0 => (a, a),
        1 => {
            let mut b = a;
            let i = rng.below(3) as usize;
            b[i] = rng.range(0.0, 2000.0);
            (a, b)
        }
        2 => {
            let mut b = rng.point(0.0, 2000.0);
            let i = rng.below(3) as usize;
            b[i] = a[i];
            (a, b)
        }
        3 => {
            // Through the box centre, well beyond both sides.
            let c = bx.center();
            (a, c + (c - a) * rng.range(0.5, 1.5))
        }
        4 => {
            // Endpoint exactly on a face plane, parallel to it.
            let i = rng.below(3) as usize;
            let plane = if rng.below(2) == 0 {
                bx.min[i]
            } else {
                bx.max[i]
            };
            let mut a2 = a;
            a2[i] = plane;
            let mut b = rng.point(0.0, 2000.0);
            b[i] = plane;
            (a2, b)
        }
        _ => (a, rng.point(0.0, 2000.0)),
    }
}

fn parry_segment_aabb(a: &Point, b: &Point, bx: &Aabb) -> f64 {
    let c = bx.center();
    let h = (bx.max - bx.min) * 0.5;
    let cub = parry3d::shape::Cuboid::new(Vector::new(h.x, h.y, h.z));
    let (a, b) = (a - c, b - c);
    let seg = parry3d::shape::Segment::new(Vector::new(a.x, a.y, a.z), Vector::new(b.x, b.y, b.z));
    parry3d::query::distance(&Pose::identity(), &cub, &Pose::identity(), &seg)
        .expect("segment-cuboid is supported")
        .distance as f64
}

/// Brute-force reference in f64: dense sampling of t then golden-section
/// refinement of the convex g(t) (an f64 reference besides parry).
fn reference_segment_aabb(a: &Point, b: &Point, bx: &Aabb) -> f64 {
    let f = |t: f64| distance_point_aabb(&(a + (b - a) * t), bx);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..200 {
        let m1 = lo + (hi - lo) * 0.381_966;
        let m2 = hi - (hi - lo) * 0.381_966;
        if f(m1) <= f(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    f(0.5 * (lo + hi)).min(f(0.0)).min(f(1.0))
}

#[test]
fn aabb_new_sorts_corners() {
    let b = Aabb::new(p(10.0, 0.0, 5.0), p(0.0, 20.0, -5.0));
    assert_eq!(b.min, p(0.0, 0.0, -5.0));
    assert_eq!(b.max, p(10.0, 20.0, 5.0));
}

#[test]
fn point_aabb_hand_cases() {
    let b = Aabb::new(p(0.0, 0.0, 0.0), p(100.0, 200.0, 300.0));
    // Above the top face.
    assert_eq!(distance_point_aabb(&p(50.0, 50.0, 310.0), &b), 10.0);
    // Near the edge x = 100, z = 300: 3-4-5.
    assert!((distance_point_aabb(&p(103.0, 50.0, 304.0), &b) - 5.0).abs() < 1e-12);
    // Near the corner (0, 0, 0): 2-3-6 -> 7.
    assert!((distance_point_aabb(&p(-2.0, -3.0, -6.0), &b) - 7.0).abs() < 1e-12);
    // Inside and on the boundary.
    assert_eq!(distance_point_aabb(&p(50.0, 50.0, 50.0), &b), 0.0);
    assert_eq!(distance_point_aabb(&p(100.0, 200.0, 300.0), &b), 0.0);
}

#[test]
fn segment_aabb_hand_cases() {
    let b = Aabb::new(p(0.0, 0.0, 0.0), p(100.0, 100.0, 100.0));
    // Parallel to the top face, 10 above, spanning beyond it.
    assert_eq!(
        distance_segment_aabb(&p(-50.0, 50.0, 110.0), &p(150.0, 50.0, 110.0), &b),
        10.0
    );
    // Skew over the edge x = 100, z = 100: the closest point is at the
    // middle of the segment, above the edge at (103, y, 104): 5.
    let d = distance_segment_aabb(&p(103.0, -50.0, 104.0), &p(103.0, 150.0, 104.0), &b);
    assert!((d - 5.0).abs() < 1e-12, "{d}");
    // A diagonal passing the corner (100,100,100): the line
    // (110 + s, 110 - s, 120) is closest at s = 0 -> sqrt(100+100+400).
    let d = distance_segment_aabb(&p(100.0, 120.0, 120.0), &p(120.0, 100.0, 120.0), &b);
    assert!((d - 600f64.sqrt()).abs() < 1e-12, "{d}");
    // Crossing the box, no endpoint inside.
    assert_eq!(
        distance_segment_aabb(&p(-10.0, -10.0, -10.0), &p(110.0, 110.0, 110.0), &b),
        0.0
    );
    // Degenerate segment = point.
    assert_eq!(
        distance_segment_aabb(&p(50.0, 50.0, 130.0), &p(50.0, 50.0, 130.0), &b),
        30.0
    );
    // Pointing away: closest point is the start.
    assert_eq!(
        distance_segment_aabb(&p(50.0, 50.0, 120.0), &p(50.0, 50.0, 900.0), &b),
        20.0
    );
}

#[test]
fn segment_aabb_matches_parry_and_reference_on_random_cases() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut zero = 0;
    let mut worst = 0.0f64;
    let mut loose = 0;
    for k in 0..5000 {
        let bx = random_box(&mut rng);
        let (a, b) = random_segment(&mut rng, &bx);
        let ours = distance_segment_aabb(&a, &b, &bx);
        let theirs = parry_segment_aabb(&a, &b, &bx);
        let reference = reference_segment_aabb(&a, &b, &bx);
        // The f64 reference is a sampled minimum, hence never below the
        // exact value: ours may be lower only by rounding.
        assert!(
            ours <= reference + 1e-9,
            "case {k}: {ours} > ref {reference}"
        );
        assert!(
            ours >= reference - 1e-6,
            "case {k}: {ours} < ref {reference}"
        );
        // Parry (f64) stops at a relative gap of about 5e-8, from above
        // (it returns points on the shapes).
        let tol = 1e-6 + 1e-7 * theirs;
        assert!(
            ours <= theirs + 1e-9 && theirs - ours <= tol,
            "case {k}: ours {ours} parry {theirs} a {a:?} b {b:?} box {bx:?}"
        );
        worst = worst.max((ours - theirs).abs());
        if (ours - theirs).abs() > 1e-5 {
            loose += 1;
        }
        if ours == 0.0 {
            zero += 1;
        }
    }
    // The generator must exercise both hits and misses.
    assert!(zero > 300 && zero < 4700, "zero-distance cases: {zero}");
    eprintln!("segment vs parry: worst {worst} mm, {loose} cases beyond 1e-5 mm");
    assert!(
        loose == 0,
        "{loose} cases beyond 1e-5 mm of parry, worst {worst}"
    );
}

fn random_cylinder(rng: &mut Rng, bx: &Aabb) -> Cylinder {
    let a = rng.point(0.0, 2000.0);
    let kind = rng.below(4);
    let b = match kind {
        0 => {
            // Short, fat (L < 2r possible).
            let dir = rng.point(-1.0, 1.0).coords;
            a + dir * rng.range(1.0, 80.0)
        }
        1 => {
            // Axis-parallel.
            let mut b = a;
            let i = rng.below(3) as usize;
            b[i] += rng.range(-800.0, 800.0);
            b
        }
        2 => {
            // Pointing at the box.
            a + (bx.center() - a) * rng.range(0.1, 0.9)
        }
        _ => rng.point(0.0, 2000.0),
    };
    Cylinder {
        a,
        b,
        radius: rng.range(5.0, 150.0),
    }
}

#[test]
fn capsule_bounds_bracket_exact_cylinder_distance() {
    let mut rng = Rng(0x1234_5678_9ABC_DEF1);
    let mut strict = 0;
    let mut loose = 0;
    let mut worst_over = 0.0f64;
    let mut worst_rel = 0.0f64;
    for k in 0..3000 {
        let bx = random_box(&mut rng);
        let c = random_cylinder(&mut rng, &bx);
        let lo = distance_capsule_aabb(&c, &bx);
        let hi = distance_inner_capsule_aabb(&c, &bx);
        let ex = distance_cylinder_aabb_exact(&c, &bx);
        assert!(lo <= hi + 1e-9, "case {k}: lo {lo} > hi {hi}");
        // The exact value is clamped into the bounds by construction;
        // check the raw parry value too, within parry's tolerance.
        assert!(lo <= ex && ex <= hi + 1e-9, "case {k}: {lo} {ex} {hi}");
        let d = c.b - c.a;
        let len = d.norm();
        let raw = parry_cylinder_aabb(&c, &bx, &(d / len), len, c.radius);
        // GJK returns points on the shapes: never below the true value
        // beyond rounding, but above it by up to its stopping gap.
        assert!(
            raw >= lo - 1e-6,
            "case {k}: raw {raw} < lo {lo} ({c:?} {bx:?})"
        );
        let over = raw - hi;
        worst_over = worst_over.max(over);
        worst_rel = worst_rel.max(over / raw.max(1.0));
        if over > 1e-4 {
            loose += 1;
        }
        if lo < ex && ex < hi {
            strict += 1;
        }
    }
    // The band must actually be exercised.
    assert!(strict > 100, "cases strictly inside the band: {strict}");
    eprintln!(
        "parry cylinder above inner bound: worst {worst_over} mm (rel {worst_rel}), {loose} cases beyond 1e-4 mm, {strict} in band"
    );
    assert!(
        worst_over < 1e-4 && loose == 0,
        "parry exceeded the upper bound by {worst_over} mm; {loose} cases beyond 1e-4 mm"
    );
}

#[test]
fn clear_of_aabb_agrees_with_exact_distance() {
    let mut rng = Rng(0xDEAD_BEEF_CAFE_F00D);
    let mut clear = 0;
    let mut blocked = 0;
    for k in 0..3000 {
        let bx = random_box(&mut rng);
        let c = random_cylinder(&mut rng, &bx);
        let ex = distance_cylinder_aabb_exact(&c, &bx);
        // Clearances near the distance, and far from it.
        let clearance = match k % 3 {
            0 => ex + rng.range(-5.0, 5.0),
            1 => rng.range(0.0, 300.0),
            _ => distance_capsule_aabb(&c, &bx) + rng.range(0.0, 50.0),
        };
        let got = cylinder_clear_of_aabb(&c, &bx, clearance);
        let tol = 1e-5 + 1e-7 * ex;
        if (ex - clearance).abs() > tol {
            assert_eq!(
                got,
                ex > clearance,
                "case {k}: exact {ex} clearance {clearance}"
            );
        }
        if got {
            clear += 1;
        } else {
            blocked += 1;
        }
        // distance_cylinder_aabb errs low (a certified lower bound, `certify.rs`) where GJK's
        // point pair errs high: never above GJK, and within GJK's tolerance plus the bracket's
        // width below it.
        let d = distance_cylinder_aabb(&c, &bx);
        assert!(d <= ex + BOUNDS_AGREE_TOL, "case {k}: {d} above GJK's {ex}");
        assert!(
            d >= ex - tol - BRACKET_TOL_REL * (1.0 + ex),
            "case {k}: {d} vs {ex}"
        );
    }
    assert!(
        clear > 300 && blocked > 300,
        "clear {clear} blocked {blocked}"
    );
}

#[test]
fn cylinder_standing_on_box_cap_touching_and_above() {
    let bx = Aabb::new(p(0.0, 0.0, 0.0), p(500.0, 500.0, 300.0));
    let c = Cylinder {
        a: p(250.0, 250.0, 300.0),
        b: p(250.0, 250.0, 700.0),
        radius: 60.0,
    };
    assert_eq!(distance_cylinder_aabb(&c, &bx), 0.0);
    assert_eq!(distance_cylinder_aabb_exact(&c, &bx), 0.0);
    assert!(!cylinder_clear_of_aabb(&c, &bx, 0.0));
    // Lifted by 7.5: the flat cap is 7.5 above the top face. The capsule
    // bound is 0 (its end sphere dips into the box); the inner capsule
    // gives the exact 7.5.
    let up = Vector3::new(0.0, 0.0, 7.5);
    let c2 = Cylinder {
        a: c.a + up,
        b: c.b + up,
        ..c
    };
    assert_eq!(distance_capsule_aabb(&c2, &bx), 0.0);
    assert!((distance_inner_capsule_aabb(&c2, &bx) - 7.5).abs() < 1e-12);
    let d = distance_cylinder_aabb(&c2, &bx);
    assert!((d - 7.5).abs() < 2e-3, "{d}");
    assert!(cylinder_clear_of_aabb(&c2, &bx, 7.0));
    assert!(!cylinder_clear_of_aabb(&c2, &bx, 8.0));
}

#[test]
fn cylinder_lying_parallel_to_face_at_known_gap() {
    let bx = Aabb::new(p(0.0, 0.0, 0.0), p(1000.0, 400.0, 200.0));
    // Axis along x, above the top face, side 12.25 above it.
    let c = Cylinder {
        a: p(100.0, 200.0, 200.0 + 40.0 + 12.25),
        b: p(900.0, 200.0, 200.0 + 40.0 + 12.25),
        radius: 40.0,
    };
    assert_eq!(distance_capsule_aabb(&c, &bx), 12.25);
    assert_eq!(distance_inner_capsule_aabb(&c, &bx), 12.25);
    assert_eq!(distance_cylinder_aabb(&c, &bx), 12.25);
    let ex = distance_cylinder_aabb_exact(&c, &bx);
    assert!((ex - 12.25).abs() < 1e-3, "{ex}");
    assert!(cylinder_clear_of_aabb(&c, &bx, 12.0));
    assert!(!cylinder_clear_of_aabb(&c, &bx, 12.25));
}

#[test]
fn cylinder_rim_near_box_edge() {
    // Vertical cylinder beside the edge x = 0, z = 100 and above it: the
    // closest pair is the cap rim point (-10, 50, 110) and the edge.
    let bx = Aabb::new(p(0.0, 0.0, 0.0), p(100.0, 100.0, 100.0));
    let c = Cylinder {
        a: p(-20.0, 50.0, 110.0),
        b: p(-20.0, 50.0, 200.0),
        radius: 10.0,
    };
    let want = 200f64.sqrt();
    let lo = distance_capsule_aabb(&c, &bx);
    let hi = distance_inner_capsule_aabb(&c, &bx);
    assert!((lo - (500f64.sqrt() - 10.0)).abs() < 1e-12);
    assert!((hi - (800f64.sqrt() - 10.0)).abs() < 1e-12);
    let d = distance_cylinder_aabb(&c, &bx);
    assert!((d - want).abs() < 2e-3 + 1.2e-3 * want, "{d} vs {want}");
    assert!(cylinder_clear_of_aabb(&c, &bx, 14.0));
    assert!(!cylinder_clear_of_aabb(&c, &bx, 14.3));
}

#[test]
fn degenerate_and_extreme_inputs_do_not_panic() {
    let bx = Aabb::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.0));
    let pt = p(3.0, 4.0, 0.0);
    assert_eq!(distance_segment_aabb(&pt, &pt, &bx), 5.0);
    // Zero-length axis: ball of radius r around a.
    let c = Cylinder {
        a: pt,
        b: pt,
        radius: 1.0,
    };
    assert_eq!(distance_cylinder_aabb_exact(&c, &bx), 4.0);
    assert_eq!(distance_cylinder_aabb(&c, &bx), 4.0);
    // Zero radius: the segment.
    let c = Cylinder {
        a: pt,
        b: p(3.0, 4.0, 9.0),
        radius: 0.0,
    };
    assert_eq!(distance_cylinder_aabb_exact(&c, &bx), 5.0);
    assert!(cylinder_clear_of_aabb(&c, &bx, 4.9));
    // Huge coordinates: finite, non-negative.
    let far = p(1e300, -1e300, 1e300);
    let d = distance_segment_aabb(&far, &p(-1e300, 1e300, -1e300), &bx);
    assert!(d.is_finite() && d >= 0.0, "{d}");
    // Cylinder pointing exactly along -Y (quaternion half-turn branch).
    let bx = Aabb::new(p(0.0, 0.0, 0.0), p(100.0, 100.0, 100.0));
    let c = Cylinder {
        a: p(130.0, 90.0, 50.0),
        b: p(130.0, -500.0, 50.0),
        radius: 10.0,
    };
    let ex = distance_cylinder_aabb_exact(&c, &bx);
    assert!((ex - 20.0).abs() < 1e-3, "{ex}");
    // And capped end pointing at the box along -Y: the cap is 15 away.
    let c = Cylinder {
        a: p(50.0, 700.0, 50.0),
        b: p(50.0, 115.0, 50.0),
        radius: 30.0,
    };
    let ex = distance_cylinder_aabb_exact(&c, &bx);
    assert!((ex - 15.0).abs() < 1e-3, "{ex}");
}

/// The alternating projections' bracket (`certify.rs`) against parry's GJK on random cylinders
/// and boxes whose capsule bounds disagree: GJK returns a point pair, so its value is at least the
/// true distance, and the bracket's lower end must not exceed it; its upper end is a point pair
/// too, at most GJK's value plus GJK's own error (measured here below 1e-4 mm on cell-sized
/// shapes). And the steps settle almost every case: at least 97 % within the tolerance.
#[test]
fn projection_bracket_holds_parry_and_settles() {
    let mut rng = Rng(12345);
    let (mut cases, mut settled) = (0, 0);
    while cases < 20_000 {
        let bx = random_box(&mut rng);
        let c = random_cylinder(&mut rng, &bx);
        let lo = distance_capsule_aabb(&c, &bx);
        let hi = distance_inner_capsule_aabb(&c, &bx);
        if hi - lo <= BOUNDS_AGREE_TOL || hi <= 0.0 {
            continue;
        }
        cases += 1;
        let gjk = distance_cylinder_aabb_exact(&c, &bx);
        let b = bracket_by_projection(&c, &bx, lo, hi, BRACKET_TOL_REL).expect("a real cylinder");
        assert!(
            b.lower <= gjk + 1e-9,
            "{c:?} {bx:?}: {b:?} above GJK's {gjk}"
        );
        assert!(
            b.upper >= gjk - 1e-4,
            "{c:?} {bx:?}: {b:?} far below GJK's {gjk}"
        );
        assert!(
            lo <= b.lower && b.lower <= b.upper && b.upper <= hi,
            "{b:?} in [{lo}, {hi}]"
        );
        if b.upper - b.lower <= BRACKET_TOL_REL * (1.0 + b.upper) {
            settled += 1;
        }
        // The node test's decision agrees with GJK's wherever GJK is sure.
        let clearance = gjk + rng.range(-2.0, 2.0);
        if (gjk - clearance).abs() > 1e-4 {
            assert_eq!(
                cylinder_clear_of_aabb(&c, &bx, clearance),
                gjk > clearance,
                "{c:?} {bx:?} at clearance {clearance}, GJK {gjk}"
            );
        }
    }
    assert!(
        settled * 1000 >= cases * 995,
        "{settled} of {cases} settled"
    );
}

/// Hand cases the projections must get exactly (no GJK): a cylinder standing on a box face
/// (its flat cap 7 mm above), one lying along a face (side 12 mm away), a rim over a box edge
/// (distance from the rim circle's nearest point to the edge, by hand), and one meeting a box.
#[test]
fn projection_bracket_hand_cases() {
    let bx = Aabb::new(p(0.0, 0.0, 0.0), p(100.0, 100.0, 100.0));
    let exact = |c: &Cylinder, d: f64| {
        let b = bracket_by_projection(c, &bx, 0.0, f64::INFINITY, 1e-12).expect("cylinder");
        assert!(b.lower <= d + 1e-9 && b.upper >= d - 1e-9, "{b:?} vs {d}");
        assert!(b.upper - b.lower < 1e-6, "{b:?} not settled");
    };
    // Standing on the top face, axis vertical, cap 7 mm above it (partly overhanging).
    exact(
        &Cylinder {
            a: p(90.0, 50.0, 107.0),
            b: p(90.0, 50.0, 300.0),
            radius: 30.0,
        },
        7.0,
    );
    // Lying along y beside the x = 100 face, its side 12 mm off.
    exact(
        &Cylinder {
            a: p(152.0, -50.0, 50.0),
            b: p(152.0, 150.0, 50.0),
            radius: 40.0,
        },
        12.0,
    );
    // Axis along z above the edge x = 100, z = 100 (parallel to y): cap centre at (130, 50,
    // 120), radius 20: the rim's nearest point to the edge is (110, 50, 120), 10 mm in x and
    // 20 mm in z from it: sqrt(500).
    exact(
        &Cylinder {
            a: p(130.0, 50.0, 120.0),
            b: p(130.0, 50.0, 400.0),
            radius: 20.0,
        },
        500f64.sqrt(),
    );
    // Through the box.
    exact(
        &Cylinder {
            a: p(50.0, 50.0, 50.0),
            b: p(50.0, 50.0, 400.0),
            radius: 20.0,
        },
        0.0,
    );
}

/// The branch-free `excess` gives the values of its definition (below: `x - lo`, above:
/// `x - hi`, else 0), infinities included, and reads a NaN coordinate as inside (0), as the
/// branching form did.
#[test]
fn excess_matches_its_definition() {
    let by_cases = |x: f64, lo: f64, hi: f64| {
        if x < lo {
            x - lo
        } else if x > hi {
            x - hi
        } else {
            0.0
        }
    };
    let mut rng = Rng(0x5EED_0FE8_CE55);
    let special = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        1e-300,
        1e300,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    for k in 0..20_000 {
        let pick = |rng: &mut Rng| {
            if rng.below(4) == 0 {
                special[rng.below(special.len() as u64) as usize]
            } else {
                rng.range(-1000.0, 1000.0)
            }
        };
        let (u, v) = (pick(&mut rng), pick(&mut rng));
        let (lo, hi) = (u.min(v), u.max(v));
        let x = if k % 3 == 0 { lo } else { pick(&mut rng) };
        let (ours, theirs) = (excess(x, lo, hi), by_cases(x, lo, hi));
        assert!(
            ours == theirs || (ours.is_nan() && theirs.is_nan()),
            "x {x} in [{lo}, {hi}]: {ours} != {theirs}"
        );
    }
    assert_eq!(excess(f64::NAN, 0.0, 1.0), 0.0);
    assert_eq!(
        distance_point_aabb(
            &p(f64::NAN, 5.0, 0.5),
            &Aabb::new(p(0.0, 0.0, 0.0), p(1.0, 1.0, 1.0))
        ),
        4.0
    );
}

/// `Measured` (`lazy.rs`) on random cylinders and boxes: at every stage its bounds hold the
/// value `distance_cylinder_aabb` gives (the rim capsules' bound, lowered by its slack, too),
/// its last stage is that value bit for bit, and `decide` / `decide2` answer as that value
/// does, at thresholds from far off to within 1e-9 mm of it. Every stage is reached often.
#[test]
fn measured_bounds_hold_the_value_at_every_stage() {
    let mut rng = Rng(0x1A2B_0000_0031);
    let mut stages = [0usize; 4];
    let mut raised = 0;
    for _ in 0..20_000 {
        let bx = random_box(&mut rng);
        let c = random_cylinder(&mut rng, &bx);
        let d = distance_cylinder_aabb(&c, &bx);
        let mut m = Measured::new(Solid::Cylinder(c), &bx);
        let mut n = 0;
        loop {
            assert!(
                m.lo <= d && d <= m.hi,
                "{c:?} {bx:?}: {d} outside [{}, {}] after {n} narrowings",
                m.lo,
                m.hi
            );
            if m.is_exact() {
                assert_eq!((m.lo.to_bits(), m.hi.to_bits()), (d.to_bits(), d.to_bits()));
                break;
            }
            let before = m.lo;
            m.narrow(&bx);
            n += 1;
            if n == 1 && m.lo > before {
                raised += 1;
            }
        }
        stages[n] += 1;
        // Straight to the value from the first bounds.
        let mut v = Measured::new(Solid::Cylinder(c), &bx);
        assert_eq!(v.value(&bx).to_bits(), d.to_bits());
        // Decisions at a threshold near the value, on fresh bounds.
        let t = d + rng.range(-1.0, 1.0) * 10f64.powf(rng.range(-9.0, 1.0));
        let mut m = Measured::new(Solid::Cylinder(c), &bx);
        assert_eq!(decide(&mut m, &bx, |x| x < t), d < t, "{c:?} {bx:?} at {t}");
        let other = random_cylinder(&mut rng, &bx);
        let e = distance_cylinder_aabb(&other, &bx);
        let reach = rng.range(0.0, 2.0) * (d + e);
        let test = |x: f64, y: f64| (0.5 * (x + y - reach)).min(x).min(y) >= t;
        let (mut m0, mut m1) = (
            Measured::new(Solid::Cylinder(c), &bx),
            Measured::new(Solid::Cylinder(other), &bx),
        );
        assert_eq!(decide2(&mut m0, &mut m1, &bx, test), test(d, e));
    }
    // Exact at once (bounds that agree), by the loose bracket (after the rims, which are never
    // the value), or only at the end.
    assert!(
        stages[0] >= 200 && stages[1] == 0 && stages[2] >= 200 && stages[3] >= 200,
        "{stages:?}"
    );
    assert!(
        raised >= 200,
        "the rims raised the lower bound {raised} times"
    );
}
