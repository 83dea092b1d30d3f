//! Timing of the hand-written geometry queries against parry3d.
use criterion::{criterion_group, criterion_main, Criterion};
use gen_rapid::geometry::{
    bracket_by_projection, clear_by_projection, cylinder_clear_of_aabb, distance_capsule_aabb,
    distance_cylinder_aabb, distance_cylinder_aabb_exact, distance_inner_capsule_aabb,
    distance_segment_aabb, Aabb, Cylinder, Point, BRACKET_TOL_REL,
};
use parry3d::math::{Pose, Vector};
use std::hint::black_box;

fn cases() -> Vec<(Cylinder, Aabb)> {
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut r = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64 * 2000.0
    };
    (0..256)
        .map(|_| {
            let c = Point::new(r(), r(), r());
            let h = nalgebra::Vector3::new(r() * 0.2, r() * 0.2, r() * 0.2);
            let bx = Aabb::new(c - h, c + h);
            let cyl = Cylinder {
                a: Point::new(r(), r(), r()),
                b: Point::new(r(), r(), r()),
                radius: 20.0 + r() * 0.05,
            };
            (cyl, bx)
        })
        .collect()
}

fn bench(cr: &mut Criterion) {
    let cs = cases();
    let n = cs.len();
    let parry: Vec<_> = cs
        .iter()
        .map(|(c, bx)| {
            let m = nalgebra::center(&bx.min, &bx.max);
            let h = (bx.max - bx.min) * 0.5;
            let cub = parry3d::shape::Cuboid::new(Vector::new(h.x, h.y, h.z));
            let (a, b) = (c.a - m, c.b - m);
            let seg = parry3d::shape::Segment::new(
                Vector::new(a.x, a.y, a.z),
                Vector::new(b.x, b.y, b.z),
            );
            (cub, seg)
        })
        .collect();
    let mut i = 0usize;
    cr.bench_function("distance_segment_aabb", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx) = &cs[i];
            distance_segment_aabb(black_box(&c.a), black_box(&c.b), black_box(bx))
        })
    });
    cr.bench_function("parry_segment_cuboid", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (cub, seg) = &parry[i];
            parry3d::query::distance(
                &Pose::identity(),
                black_box(cub),
                &Pose::identity(),
                black_box(seg),
            )
            .map(|d| d.distance)
            .unwrap_or(0.0)
        })
    });
    cr.bench_function("cylinder_clear_of_aabb_50mm", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx) = &cs[i];
            cylinder_clear_of_aabb(black_box(c), black_box(bx), 50.0)
        })
    });
    cr.bench_function("distance_cylinder_aabb_exact", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx) = &cs[i];
            distance_cylinder_aabb_exact(black_box(c), black_box(bx))
        })
    });
}

/// The cases of [`cases`] whose capsule bounds disagree (the band), with a clearance inside the
/// band: where the node test used to call GJK.
fn band(cs: &[(Cylinder, Aabb)]) -> Vec<(Cylinder, Aabb, f64)> {
    cs.iter()
        .filter_map(|&(c, bx)| {
            let (lo, hi) = (
                distance_capsule_aabb(&c, &bx),
                distance_inner_capsule_aabb(&c, &bx),
            );
            (hi - lo > 1e-6).then_some((c, bx, 0.5 * (lo + hi)))
        })
        .collect()
}

/// The band's decision and distance: the alternating projections (`certify.rs`) against
/// parry's GJK, which they replace in the band.
fn bench_band(cr: &mut Criterion) {
    let cs = band(&cases());
    let n = cs.len();
    assert!(n > 20, "{n} band cases");
    let mut i = 0usize;
    cr.bench_function("band_clear_by_projection", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx, cl) = &cs[i];
            clear_by_projection(black_box(c), black_box(bx), *cl)
        })
    });
    cr.bench_function("band_bracket_by_projection", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx, _) = &cs[i];
            bracket_by_projection(
                black_box(c),
                black_box(bx),
                0.0,
                f64::INFINITY,
                BRACKET_TOL_REL,
            )
        })
    });
    cr.bench_function("band_distance_cylinder_aabb", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx, _) = &cs[i];
            distance_cylinder_aabb(black_box(c), black_box(bx))
        })
    });
    cr.bench_function("band_gjk_exact", |bn| {
        bn.iter(|| {
            i = (i + 1) % n;
            let (c, bx, _) = &cs[i];
            distance_cylinder_aabb_exact(black_box(c), black_box(bx))
        })
    });
}

criterion_group!(benches, bench, bench_band);
criterion_main!(benches);
