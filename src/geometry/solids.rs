//! The tool's solids besides the cylinder: a ball and an oriented box, with exact distances to
//! an axis-aligned box, and [`Solid`], the one type the collision model places and measures
//! (a link cylinder or a tool shape).
//!
//! - **Ball–box** ([`distance_sphere_aabb`]): the distance of the centre minus the radius,
//!   clamped at 0. Exact.
//! - **Oriented box–box** ([`distance_obb_aabb`]): closed form, exact. Of a closest pair of
//!   points of two disjoint convex polytopes, either the point on the first lies on one of its
//!   edges, or it lies inside a face; then the pair can be slid (parallel faces: to a vertex of
//!   the overlap of their projections) until the point on the second lies on one of *its*
//!   edges. So the distance is the least of the 12 edges of the oriented box measured against
//!   the axis-aligned box and the 12 edges of the axis-aligned box measured against the oriented
//!   box (in the oriented box's frame, where it is axis-aligned), each an exact segment–box
//!   distance ([`distance_segment_aabb`]). When the boxes meet, the least is 0: the meet is a
//!   convex polytope, and any of its vertices lies on two facet planes of one box (an edge of
//!   it) and inside the other. The tests hold it against parry3d's cuboid–cuboid distance.
//! - **Oriented box–box, clear or not** ([`obb_clear_of_aabb`], beyond the paper): whether that
//!   distance exceeds a clearance, the same answer for finite inputs at cell sizes, by
//!   separating axes first
//!   (with a slack above both's rounding) and the 24 distances only where they do not decide.

use super::{
    distance_capsule_aabb, distance_cylinder_aabb, distance_inner_capsule_aabb,
    distance_point_aabb, distance_segment_aabb, Aabb, Cylinder, Point,
};
use nalgebra::{Matrix3, Vector3};

/// A solid ball, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub centre: Point,
    /// mm, assumed `>= 0`.
    pub radius: f64,
}

/// A box with its own orientation: the points `centre + axes * v` with `|v_k| <= half[k]`;
/// `axes` is a rotation (its columns the box's unit axes in the cell frame), mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Obb {
    pub centre: Point,
    pub axes: Matrix3<f64>,
    /// Half extents along the box's axes, mm, each `>= 0`.
    pub half: Vector3<f64>,
}

/// A solid of the robot model placed in the cell frame: a link cylinder or a tool shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Solid {
    Cylinder(Cylinder),
    Sphere(Sphere),
    Box(Obb),
}

/// Distance between a ball and a box, mm; 0 when they touch or overlap. Exact.
#[inline]
pub fn distance_sphere_aabb(s: &Sphere, b: &Aabb) -> f64 {
    (distance_point_aabb(&s.centre, b) - s.radius.max(0.0)).max(0.0)
}

/// The 8 corners of a box given as centre, axes and half extents; corner `k` takes `+half[i]`
/// where bit `i` of `k` is set.
fn corners(centre: &Point, axes: &Matrix3<f64>, half: &Vector3<f64>) -> [Point; 8] {
    std::array::from_fn(|k| {
        let s = |i: usize| if k >> i & 1 == 1 { half[i] } else { -half[i] };
        centre + axes * Vector3::new(s(0), s(1), s(2))
    })
}

/// The 12 edges of a box as pairs of corner indices (corners as in [`corners`]).
const EDGES: [(usize, usize); 12] = [
    (0, 1),
    (2, 3),
    (4, 5),
    (6, 7),
    (0, 2),
    (1, 3),
    (4, 6),
    (5, 7),
    (0, 4),
    (1, 5),
    (2, 6),
    (3, 7),
];

/// Exact distance between an oriented box and an axis-aligned box, mm; 0 when they touch or
/// overlap (module doc for why 24 segment–box distances are the answer).
pub fn distance_obb_aabb(o: &Obb, b: &Aabb) -> f64 {
    edge_distances(o, b, 0.0)
}

/// The least of [`distance_obb_aabb`]'s 24 segment distances (the oriented box's 12 edges to
/// `b`, then `b`'s 12 edges to the oriented box in its frame), in that order, returned as soon
/// as the least so far is at most `stop` (distances are not negative: with `stop` 0, once it is
/// 0).
#[inline]
fn edge_distances(o: &Obb, b: &Aabb, stop: f64) -> f64 {
    let half = o.half.map(|h| h.max(0.0));
    let mut best = f64::INFINITY;
    let oc = corners(&o.centre, &o.axes, &half);
    for (i, j) in EDGES {
        best = best.min(distance_segment_aabb(&oc[i], &oc[j], b));
        if best <= stop {
            return best;
        }
    }
    // The axis-aligned box's edges in the oriented box's frame, where that box is [-half, half].
    let inv = o.axes.transpose();
    let local = Aabb {
        min: Point::from(-half),
        max: Point::from(half),
    };
    let bc = nalgebra::center(&b.min, &b.max);
    let bh = (b.max - b.min) * 0.5;
    let centre = Point::from(inv * (bc - o.centre));
    let bcorners = corners(&centre, &inv, &bh);
    for (i, j) in EDGES {
        best = best.min(distance_segment_aabb(&bcorners[i], &bcorners[j], &local));
        if best <= stop {
            return best;
        }
    }
    best
}

/// How far beyond the clearance the gap of [`obb_clear_of_aabb`]'s separating axes must be
/// for it to answer clear without the 24 segment distances, mm: far above the rounding of the
/// gap and of [`distance_obb_aabb`] (about 1e-12 mm at cell sizes: a few operations on
/// coordinates below the 10 m the model clips boxes to), so the answer is that distance's.
pub const OBB_AXIS_SLACK_MM: f64 = 1e-6;

/// Whether the oriented box keeps MORE than `clearance` from the box: `distance_obb_aabb(o, b) >
/// clearance` for finite inputs at cell sizes (coordinates well below 1e8 mm: the model's boxes
/// are clipped to the workspace plus 10 m, and cell values are at most 1e6 mm), cheaper. Far
/// beyond (about 1e10 mm) the rounding of the gap outgrows [`OBB_AXIS_SLACK_MM`], and a box
/// with a NaN axis or an infinite side may answer clear where the distance is 0.
///
/// First the box's own three axes as separating axes: along a unit axis `u` of `o`, the boxes'
/// projections are `u . oc +- half_u` and `u . bc +- sum_i |u_i| bh_i`, and the gap between
/// them is a lower bound of the distance (projection onto a line shortens no distance). A gap
/// beyond the clearance plus [`OBB_AXIS_SLACK_MM`] puts the true distance, and so
/// [`distance_obb_aabb`]'s number (within its rounding of it), above the clearance: the same
/// answer. (The axes of `b` are the enclosing box's gap, which callers test first.) Then the 9
/// axes `n = u_k x e_i` across an edge of each box (`e_i` the cell's axes; each component of
/// `n` is one of `u_k`'s, exact): the projections' radii are `sum_j half_j |u_j . n|` and
/// `sum_i bh_i |n_i|`, a bound for any three axes, and the gap over `|n|` is again a lower
/// bound; an axis with `|n|` below 1e-3 (an edge nearly along a cell axis, which the face axes
/// cover) is passed over, so the gap's rounding over `|n|` stays far inside the slack. A gap
/// that is not a number answers nothing. Else the 24 segment distances of [`distance_obb_aabb`], the same numbers in the same order, with
/// their running least, stopping once it is within the clearance (the least of all is then
/// within it too; `distance_obb_aabb`'s own stop at 0 answers the same: distances are not
/// negative).
pub fn obb_clear_of_aabb(o: &Obb, b: &Aabb, clearance: f64) -> bool {
    let half = o.half.map(|h| h.max(0.0));
    let bc = nalgebra::center(&b.min, &b.max);
    let bh = (b.max - b.min) * 0.5;
    let off = bc - o.centre;
    let beyond = clearance + OBB_AXIS_SLACK_MM;
    for k in 0..3 {
        let u = o.axes.column(k);
        let reach = half[k] + u[0].abs() * bh[0] + u[1].abs() * bh[1] + u[2].abs() * bh[2];
        if u.dot(&off).abs() - reach > beyond {
            return true;
        }
    }
    for k in 0..3 {
        let u = o.axes.column(k);
        for n in [
            Vector3::new(0.0, u[2], -u[1]),
            Vector3::new(-u[2], 0.0, u[0]),
            Vector3::new(u[1], -u[0], 0.0),
        ] {
            let len = n.norm();
            if len < 1e-3 {
                continue;
            }
            let reach = (0..3)
                .map(|j| half[j] * o.axes.column(j).dot(&n).abs() + bh[j] * n[j].abs())
                .sum::<f64>();
            if n.dot(&off).abs() - reach > beyond * len {
                return true;
            }
        }
    }
    // The running least of `distance_obb_aabb`, the same numbers in the same order; once it is
    // within the clearance, the least of all is too.
    edge_distances(o, b, clearance) > clearance
}

/// The squared distance between two axis-aligned boxes, mm²; 0 when they touch or overlap.
#[inline]
pub fn gap_sq_aabb_aabb(a: &Aabb, b: &Aabb) -> f64 {
    (0..3)
        .map(|k| {
            let g = (b.min[k] - a.max[k]).max(a.min[k] - b.max[k]).max(0.0);
            g * g
        })
        .sum()
}

impl Solid {
    /// Distance to the box, mm (0 on contact): exact for the ball and the oriented box, the
    /// cylinder's as [`distance_cylinder_aabb`] gives it.
    #[inline]
    pub fn distance_aabb(&self, b: &Aabb) -> f64 {
        match self {
            Solid::Cylinder(c) => distance_cylinder_aabb(c, b),
            Solid::Sphere(s) => distance_sphere_aabb(s, b),
            Solid::Box(o) => distance_obb_aabb(o, b),
        }
    }

    /// An upper bound of [`distance_aabb`](Self::distance_aabb)'s true distance, mm, cheaper
    /// than it: a cylinder's inner capsule ([`distance_inner_capsule_aabb`], which the exact
    /// cylinder distance never exceeds), a ball's exact distance, an oriented box's least over
    /// its 8 corners and its centre less its least half side (points of the box, a ball in it).
    #[inline]
    pub fn upper_distance_aabb(&self, b: &Aabb) -> f64 {
        match self {
            Solid::Cylinder(c) => distance_inner_capsule_aabb(c, b),
            Solid::Sphere(s) => distance_sphere_aabb(s, b),
            Solid::Box(o) => {
                let half = o.half.map(|h| h.max(0.0));
                let centre = distance_point_aabb(&o.centre, b) - half.min();
                corners(&o.centre, &o.axes, &half)
                    .iter()
                    .map(|p| distance_point_aabb(p, b))
                    .fold(centre.max(0.0), f64::min)
            }
        }
    }

    /// The smallest axis-aligned box holding the solid, mm: a cylinder's from its caps' discs
    /// (along axis `k` a cap of radius `r` about a unit axis `u` reaches `r sqrt(1 - u_k^2)`),
    /// a ball's and an oriented box's exact.
    #[inline]
    pub fn enclosing_aabb(&self) -> Aabb {
        let (c, h) = match self {
            Solid::Cylinder(cy) => {
                let d = cy.b - cy.a;
                let len = d.norm();
                let r = cy.radius.max(0.0);
                let h = Vector3::from_fn(|k, _| {
                    let u = if len > 0.0 { d[k] / len } else { 0.0 };
                    0.5 * d[k].abs() + r * (1.0 - u * u).max(0.0).sqrt()
                });
                (nalgebra::center(&cy.a, &cy.b), h)
            }
            Solid::Sphere(s) => (s.centre, Vector3::repeat(s.radius.max(0.0))),
            Solid::Box(o) => {
                let half = o.half.map(|x| x.max(0.0));
                (o.centre, o.axes.abs() * half)
            }
        };
        Aabb {
            min: c - h,
            max: c + h,
        }
    }

    /// A bound below [`distance_aabb`](Self::distance_aabb) that costs a few comparisons, mm:
    /// the distance between [`enclosing_aabb`](Self::enclosing_aabb) and `b` (the solid lies in
    /// that box, so nothing of it is nearer).
    #[inline]
    pub fn coarse_lower_bound_aabb(&self, b: &Aabb) -> f64 {
        gap_sq_aabb_aabb(&self.enclosing_aabb(), b).sqrt()
    }

    /// A cheap lower bound of [`distance_aabb`](Self::distance_aabb), mm: the capsule bound for
    /// a cylinder (one closed-form segment query, no GJK), the exact distance otherwise.
    #[inline]
    pub fn lower_bound_aabb(&self, b: &Aabb) -> f64 {
        match self {
            Solid::Cylinder(c) => distance_capsule_aabb(c, b),
            _ => self.distance_aabb(b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::testing::Rng;
    use nalgebra::{Rotation3, Unit};
    use parry3d::math::{Pose, Rotation, Vector};
    use std::f64::consts::FRAC_PI_2;

    fn random_rotation(rng: &mut Rng) -> Matrix3<f64> {
        let axis = Vector3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        );
        let angle = rng.range(-3.2, 3.2);
        match Unit::try_new(axis, 1e-9) {
            Some(u) => Rotation3::from_axis_angle(&u, angle).into_inner(),
            None => Matrix3::identity(),
        }
    }

    fn parry_obb_aabb(o: &Obb, b: &Aabb) -> f64 {
        let q = nalgebra::UnitQuaternion::from_matrix(&o.axes);
        let pose_o = Pose::from_parts(
            Vector::new(o.centre.x, o.centre.y, o.centre.z),
            Rotation::from_xyzw(q.i, q.j, q.k, q.w),
        );
        let bc = nalgebra::center(&b.min, &b.max);
        let bh = (b.max - b.min) * 0.5;
        let pose_b = Pose::from_translation(Vector::new(bc.x, bc.y, bc.z));
        let co = parry3d::shape::Cuboid::new(Vector::new(o.half.x, o.half.y, o.half.z));
        let cb = parry3d::shape::Cuboid::new(Vector::new(bh.x, bh.y, bh.z));
        parry3d::query::distance(&pose_o, &co, &pose_b, &cb)
            .expect("cuboids")
            .distance
    }

    /// A box about a point within 300 mm of the origin, half sides of 1..300 mm.
    fn random_aabb(rng: &mut Rng) -> Aabb {
        let bc = rng.point(-300.0, 300.0);
        let bh = Vector3::new(
            rng.range(1.0, 300.0),
            rng.range(1.0, 300.0),
            rng.range(1.0, 300.0),
        );
        Aabb::new(bc - bh, bc + bh)
    }

    #[test]
    fn obb_aabb_distance_matches_parry_on_random_boxes() {
        let mut rng = Rng(0x0bb0_0bb0_1234_5678);
        let (mut apart, mut touching) = (0, 0);
        for _ in 0..20_000 {
            let b = random_aabb(&mut rng);
            let o = Obb {
                centre: rng.point(-500.0, 500.0),
                axes: random_rotation(&mut rng),
                half: Vector3::new(
                    rng.range(1.0, 200.0),
                    rng.range(1.0, 200.0),
                    rng.range(1.0, 200.0),
                ),
            };
            let mine = distance_obb_aabb(&o, &b);
            let theirs = parry_obb_aabb(&o, &b);
            // parry's GJK errs from above by its tolerance; both are 0 on contact.
            assert!(
                (mine - theirs).abs() <= 1e-6 * (1.0 + theirs),
                "{o:?} {b:?}: closed form {mine}, parry {theirs}"
            );
            if theirs > 0.0 {
                apart += 1;
            } else {
                touching += 1;
            }
        }
        assert!(
            apart > 5_000 && touching > 1_000,
            "{apart} apart, {touching} touching"
        );
    }

    /// `obb_clear_of_aabb` answers `distance_obb_aabb(o, b) > c` for every case tried: random
    /// oriented boxes (turned at random, by whole quarter turns, and by a hair, where the
    /// separating axes of edge pairs nearly vanish; some with a flat side) against random
    /// boxes, at clearances on the distance to the bit, one ulp either side, within and just
    /// beyond the separating axes' slack, far inside and 0. Both answers must occur often
    /// at the distance's neighbours (an answer read off the separating axes without their slack
    /// differs there, in about 9 % of the cases).
    #[test]
    fn obb_clear_of_aabb_is_the_distance_test() {
        let mut rng = Rng(0x0bb0_c1ea_5eed_0001);
        let (mut clear, mut blocked) = (0usize, 0usize);
        for k in 0..20_000 {
            let b = random_aabb(&mut rng);
            let axes = match k % 4 {
                0 | 1 => random_rotation(&mut rng),
                2 => {
                    // Whole quarter turns about each axis.
                    let q =
                        |rng: &mut Rng| f64::from(rng.range(0.0, 4.0).floor() as i32) * FRAC_PI_2;
                    (Rotation3::from_euler_angles(q(&mut rng), q(&mut rng), q(&mut rng)))
                        .into_inner()
                }
                _ => {
                    let hair = |rng: &mut Rng| rng.range(-1e-3, 1e-3);
                    Rotation3::from_euler_angles(hair(&mut rng), hair(&mut rng), hair(&mut rng))
                        .into_inner()
                }
            };
            let mut half = Vector3::new(
                rng.range(1.0, 200.0),
                rng.range(1.0, 200.0),
                rng.range(1.0, 200.0),
            );
            if k % 7 == 0 {
                half[k % 3] = 0.0;
            }
            let o = Obb {
                centre: rng.point(-500.0, 500.0),
                axes,
                half,
            };
            let d = distance_obb_aabb(&o, &b);
            let step = |x: f64, up: bool| {
                if x <= 0.0 {
                    x
                } else if up {
                    f64::from_bits(x.to_bits() + 1)
                } else {
                    f64::from_bits(x.to_bits() - 1)
                }
            };
            for c in [
                d,
                step(d, false),
                step(d, true),
                d - 0.5 * OBB_AXIS_SLACK_MM,
                d - 2.0 * OBB_AXIS_SLACK_MM,
                d + OBB_AXIS_SLACK_MM,
                0.5 * d,
                d - 30.0,
                0.0,
                rng.range(0.0, 300.0),
            ] {
                let c = c.max(0.0);
                let want = d > c;
                assert_eq!(
                    obb_clear_of_aabb(&o, &b, c),
                    want,
                    "{o:?} {b:?} at {c} (distance {d})"
                );
                if c == step(d, false) && d > 0.0 {
                    clear += usize::from(want);
                }
                if c == d && d > 0.0 {
                    blocked += usize::from(!want);
                }
            }
        }
        assert!(
            clear > 5_000 && blocked > 5_000,
            "{clear} clear, {blocked} blocked"
        );
    }

    /// `upper_distance_aabb` never falls below the exact distance (parry's for boxes; the
    /// closed forms checked against parry elsewhere for cylinders and balls), and is often
    /// close to it where the solid nears the box (else it would never answer anything).
    #[test]
    fn upper_distance_is_never_below_the_exact_distance() {
        let mut rng = Rng(0x5EED_0099_E000_0001);
        let (mut near, mut tight) = (0, 0);
        for k in 0..30_000 {
            let b = random_aabb(&mut rng);
            let centre = rng.point(-600.0, 600.0);
            let solid = match k % 3 {
                0 => Solid::Cylinder(Cylinder {
                    a: centre,
                    b: centre + random_rotation(&mut rng) * Vector3::z() * rng.range(0.0, 600.0),
                    radius: rng.range(0.0, 120.0),
                }),
                1 => Solid::Sphere(Sphere {
                    centre,
                    radius: rng.range(0.0, 200.0),
                }),
                _ => Solid::Box(Obb {
                    centre,
                    axes: random_rotation(&mut rng),
                    half: Vector3::new(
                        rng.range(0.0, 200.0),
                        rng.range(0.0, 200.0),
                        rng.range(0.0, 200.0),
                    ),
                }),
            };
            let exact = match &solid {
                Solid::Box(o) => parry_obb_aabb(o, &b),
                other => other.distance_aabb(&b),
            };
            let upper = solid.upper_distance_aabb(&b);
            assert!(
                upper >= exact - 1e-6 * (1.0 + exact),
                "{solid:?} {b:?}: upper {upper} below exact {exact}"
            );
            if exact < 50.0 {
                near += 1;
                if upper <= exact + 5.0 {
                    tight += 1;
                }
            }
        }
        assert!(near > 3_000 && tight * 2 > near, "{tight} tight of {near}");
    }

    #[test]
    fn obb_aabb_hand_cases() {
        let b = Aabb::new(Point::new(0.0, 0.0, 0.0), Point::new(100.0, 100.0, 100.0));
        // Axis-aligned, 50 mm above the top face.
        let o = Obb {
            centre: Point::new(50.0, 50.0, 160.0),
            axes: Matrix3::identity(),
            half: Vector3::new(10.0, 10.0, 10.0),
        };
        assert!((distance_obb_aabb(&o, &b) - 50.0).abs() < 1e-12);
        // Turned 45 deg about z, its corner pointing at the box's x = 100 face from 20 mm.
        let r = Rotation3::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4);
        let d = 10.0 * std::f64::consts::SQRT_2;
        let o = Obb {
            centre: Point::new(120.0 + d, 50.0, 50.0),
            axes: r.into_inner(),
            half: Vector3::new(10.0, 10.0, 10.0),
        };
        assert!((distance_obb_aabb(&o, &b) - 20.0).abs() < 1e-9);
        // Edge against edge: a box turned about x and y, above the corner (100, 100, 100)
        // along the diagonal of the top face: parry decides.
        let o = Obb {
            centre: Point::new(130.0, 130.0, 150.0),
            axes: (Rotation3::from_axis_angle(&Vector3::x_axis(), 0.5)
                * Rotation3::from_axis_angle(&Vector3::y_axis(), 0.7))
            .into_inner(),
            half: Vector3::new(30.0, 5.0, 20.0),
        };
        let theirs = parry_obb_aabb(&o, &b);
        assert!(theirs > 1.0, "{theirs}");
        assert!((distance_obb_aabb(&o, &b) - theirs).abs() < 1e-6);
        // Inside: 0; the box inside the oriented one: 0.
        let inner = Obb {
            centre: Point::new(50.0, 50.0, 50.0),
            axes: random_rotation(&mut Rng(7)),
            half: Vector3::new(1.0, 2.0, 3.0),
        };
        assert_eq!(distance_obb_aabb(&inner, &b), 0.0);
        let outer = Obb {
            half: Vector3::new(500.0, 500.0, 500.0),
            ..inner
        };
        assert_eq!(distance_obb_aabb(&outer, &b), 0.0);
    }

    #[test]
    fn sphere_aabb_is_the_centre_distance_less_the_radius() {
        let b = Aabb::new(Point::new(0.0, 0.0, 0.0), Point::new(10.0, 10.0, 10.0));
        let s = |x, y, z, r| Sphere {
            centre: Point::new(x, y, z),
            radius: r,
        };
        assert_eq!(distance_sphere_aabb(&s(20.0, 5.0, 5.0, 4.0), &b), 6.0);
        assert!((distance_sphere_aabb(&s(13.0, 14.0, 5.0, 1.0), &b) - 4.0).abs() < 1e-12);
        assert_eq!(distance_sphere_aabb(&s(5.0, 5.0, 5.0, 1.0), &b), 0.0);
        assert_eq!(distance_sphere_aabb(&s(12.0, 5.0, 5.0, 3.0), &b), 0.0);
        // Against parry's ball.
        let mut rng = Rng(99);
        for _ in 0..2_000 {
            let sp = Sphere {
                centre: rng.point(-50.0, 60.0),
                radius: rng.range(0.0, 20.0),
            };
            let ball = parry3d::shape::Ball::new(sp.radius);
            let cub = parry3d::shape::Cuboid::new(Vector::new(5.0, 5.0, 5.0));
            let c = sp.centre - Point::new(5.0, 5.0, 5.0);
            let theirs = parry3d::query::distance(
                &Pose::from_translation(Vector::new(c.x, c.y, c.z)),
                &ball,
                &Pose::identity(),
                &cub,
            )
            .expect("ball-cuboid")
            .distance;
            let mine = distance_sphere_aabb(&sp, &b);
            assert!((mine - theirs).abs() < 1e-9, "{sp:?}: {mine} vs {theirs}");
        }
    }

    #[test]
    fn lower_bounds_never_exceed_the_distance() {
        let mut rng = Rng(5);
        let b = Aabb::new(Point::new(0.0, 0.0, 0.0), Point::new(200.0, 100.0, 50.0));
        for _ in 0..2_000 {
            let c = Cylinder {
                a: rng.point(-300.0, 500.0),
                b: rng.point(-300.0, 500.0),
                radius: rng.range(0.0, 80.0),
            };
            let s = Solid::Cylinder(c);
            assert!(s.lower_bound_aabb(&b) <= s.distance_aabb(&b) + 1e-9);
        }
    }

    #[test]
    fn the_enclosing_box_is_parrys_and_its_gap_bounds_the_distance_from_below() {
        // The enclosing box of each solid against parry's own AABB of the same shape (exact
        // for cylinders, balls and cuboids), and the coarse bound against the exact distance.
        use parry3d::shape::Shape;
        let mut rng = Rng(0xe4c1_05ed);
        let b = Aabb::new(Point::new(0.0, 0.0, 0.0), Point::new(200.0, 100.0, 50.0));
        let (mut culled, mut near) = (0, 0);
        for k in 0..6_000 {
            let centre = rng.point(-200.0, 400.0);
            let rot = random_rotation(&mut rng);
            let q = nalgebra::UnitQuaternion::from_matrix(&rot);
            let pose = Pose::from_parts(
                Vector::new(centre.x, centre.y, centre.z),
                Rotation::from_xyzw(q.i, q.j, q.k, q.w),
            );
            let (solid, theirs) = match k % 3 {
                0 => {
                    // parry's cylinder runs along its local y axis.
                    let (h, r) = (rng.range(0.0, 150.0), rng.range(0.0, 60.0));
                    let y = rot * Vector3::y() * h;
                    let c = Cylinder {
                        a: centre - y,
                        b: centre + y,
                        radius: r,
                    };
                    let aabb = parry3d::shape::Cylinder::new(h, r).compute_aabb(&pose);
                    (Solid::Cylinder(c), aabb)
                }
                1 => {
                    let r = rng.range(0.0, 60.0);
                    let aabb = parry3d::shape::Ball::new(r).compute_aabb(&pose);
                    (Solid::Sphere(Sphere { centre, radius: r }), aabb)
                }
                _ => {
                    let half = Vector3::new(
                        rng.range(0.0, 100.0),
                        rng.range(0.0, 100.0),
                        rng.range(0.0, 100.0),
                    );
                    let aabb = parry3d::shape::Cuboid::new(Vector::new(half.x, half.y, half.z))
                        .compute_aabb(&pose);
                    (
                        Solid::Box(Obb {
                            centre,
                            axes: rot,
                            half,
                        }),
                        aabb,
                    )
                }
            };
            let mine = solid.enclosing_aabb();
            for i in 0..3 {
                assert!(
                    (mine.min[i] - theirs.mins[i]).abs() < 1e-6
                        && (mine.max[i] - theirs.maxs[i]).abs() < 1e-6,
                    "{solid:?}: {mine:?} against parry's {theirs:?}"
                );
            }
            let (coarse, exact) = (solid.coarse_lower_bound_aabb(&b), solid.distance_aabb(&b));
            // The cylinder's distance is a certified lower bound that keeps a rounding slack of
            // 1e-9 mm (`certify.rs`): both are lower bounds, within the slack of each other.
            assert!(coarse <= exact + 1e-8, "{solid:?}: {coarse} > {exact}");
            if coarse > 10.0 {
                culled += 1;
            } else if exact > 10.0 {
                near += 1;
            }
        }
        // Both outcomes occur: most far solids are culled by the coarse bound, some pass it
        // though the exact distance would have cleared them.
        eprintln!("{culled} culled, {near} left to the exact test");
        assert!(
            culled > 1_000 && near > 50,
            "{culled} culled, {near} left to the exact test"
        );
    }
}
