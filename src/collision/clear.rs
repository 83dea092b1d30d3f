//! The clearance test of one part and one box: `true` when the part keeps MORE than the
//! clearance from the box, from cheap bounds to the exact distance, the exact test's answer
//! whatever bound decides.

use crate::geometry::{
    clamp_to_box, closest_param_segment_aabb, distance_cylinder_aabb_exact, distance_point_aabb,
    distance_segment_aabb, obb_clear_of_aabb, Aabb, Cylinder, Point, Solid,
};
use nalgebra::Vector3;

/// The node test of a link used everywhere in the collision model: `true` when the cylinder
/// keeps MORE than `clearance` from the box. Cheap bounds first, from the axis point nearest the
/// box (the capsule's lower bound; that point and the point of its disc nearest the box lie in
/// the cylinder: upper bounds), then the cap centres and their rim points nearest the box
/// (upper bounds), a capsule about a shortened axis that still holds the rims (a lower bound),
/// the alternating projections of `geometry::certify` (a certified separating plane or point
/// pair: nearly every case), two more shortened capsules, and then parry's GJK. All are valid
/// bounds, so the answer is the exact test's whatever their order. The cheap bounds decide most
/// of the calls before the projections (`benches/README.md`).
#[inline]
pub(super) fn link_clear_of_box(c: &Cylinder, b: &Aabb, clearance: f64) -> bool {
    let (near, axis) = axis_nearest(c, b);
    link_clear_near(c, b, clearance, &near, axis)
}

/// The point of the cylinder's axis nearest the box and its distance from the box: less the
/// radius (at least 0), the capsule distance of `distance_capsule_aabb` (the same numbers).
#[inline]
pub(super) fn axis_nearest(c: &Cylinder, b: &Aabb) -> (Point, f64) {
    let d = c.b - c.a;
    let near = c.a + d * closest_param_segment_aabb(&c.a, &d, b);
    (near, distance_point_aabb(&near, b))
}

/// [`link_clear_of_box`] with [`axis_nearest`]'s answer given (a caller that measured the
/// capsule distance already need not find the nearest axis point again).
#[inline]
pub(super) fn link_clear_near(
    c: &Cylinder,
    b: &Aabb,
    clearance: f64,
    near: &Point,
    axis: f64,
) -> bool {
    let near = *near;
    let d = c.b - c.a;
    let r = c.radius.max(0.0);
    // The capsule's distance (`distance_capsule_aabb`).
    if (axis - r).max(0.0) > clearance {
        return true;
    }
    if axis <= clearance {
        return false;
    }
    let len = d.norm();
    if len > 0.0 && r > 0.0 {
        let u = d / len;
        // Upper bounds: on the disc about the axis point nearest the box and on both caps, the
        // point nearest the box point nearest the disc's centre.
        for p in [near, c.a, c.b] {
            let w = clamp_to_box(&p, b) - p;
            let perp = w - u * u.dot(&w);
            let n = perp.norm();
            let rim = if n > 0.0 {
                p + perp * (r.min(n) / n)
            } else {
                p
            };
            if distance_point_aabb(&rim, b) <= clearance {
                return false;
            }
        }
        // Segment shortened by s at both ends, radius sqrt(r^2 + s^2): contains the cylinder.
        // The first shortening settles most clear cylinders; where it does not, the
        // projections come before the two longer ones: in the grid build they settle nearly
        // all of what is left (most of it within the clearance, which no lower bound can show)
        // for less than the two segment queries.
        if shortened_clear(c, b, clearance, &u, len, r, 1.0) {
            return true;
        }
        if let Some(clear) = crate::geometry::clear_by_projection(c, b, clearance) {
            return clear;
        }
        if shortened_clear(c, b, clearance, &u, len, r, 2.5)
            || shortened_clear(c, b, clearance, &u, len, r, 6.0)
        {
            return true;
        }
    }
    // What the projections left open (a distance within their slack of the clearance, or no
    // radius or length to project onto): GJK.
    distance_cylinder_aabb_exact(c, b) > clearance
}

/// Whether the capsule about `c`'s axis shortened by `s = min(k r, len / 2)` at both ends, of
/// radius `sqrt(r^2 + s^2)` (it contains the cylinder), keeps more than `clearance` from the
/// box (`u` the unit axis, `len` its length, `r > 0` the radius).
#[inline]
fn shortened_clear(
    c: &Cylinder,
    b: &Aabb,
    clearance: f64,
    u: &Vector3<f64>,
    len: f64,
    r: f64,
    k: f64,
) -> bool {
    let s = (k * r).min(0.5 * len);
    // sqrt(r^2 + s^2) raised over its rounding (`hypot` costs about ten times more).
    let radius = (r * r + s * s).sqrt() * (1.0 + 1e-15);
    distance_segment_aabb(&(c.a + u * s), &(c.b - u * s), b) - radius > clearance
}
/// The node test for any solid: `true` when it keeps MORE than `clearance` from the box. First
/// the distance of the solid's enclosing box (a few comparisons; most boxes are far from most
/// parts); then link cylinders go through [`link_clear_of_box`] (fast bounds before parry's
/// GJK), oriented boxes through `geometry::obb_clear_of_aabb` (separating axes before the exact
/// distance, the exact distance's answer), balls are measured exactly.
#[inline]
pub(super) fn solid_clear_of_box(s: &Solid, b: &Aabb, clearance: f64) -> bool {
    if s.coarse_lower_bound_aabb(b) > clearance {
        return true;
    }
    match s {
        Solid::Cylinder(c) => link_clear_of_box(c, b, clearance),
        Solid::Box(o) => obb_clear_of_aabb(o, b, clearance),
        Solid::Sphere(_) => s.distance_aabb(b) > clearance,
    }
}
