//! Every link's collision cylinders carried the way the checks carry them (beyond the paper,
//! which lumps the arm into links 1..3 alone): the URDF's cylinders ([`OwnCylinder`]) ->
//! the lumped arm's cylinders on links 1..3 ([`LinkCylinder`]) and the flange's parts
//! ([`FlangePart`]).
//!
//! - **Links 1..3** carry their own cylinders as they are.
//! - **base_link** is fixed to the base, link 1 turns about axis 1 on it. A cylinder about axis 1
//!   that holds the base's cylinder is the same for every angle of axis 1, so it rides on link 1
//!   (its distance to a box does not depend on axis 1: the static base is checked in every pose,
//!   conservatively by the offset of the base's own cylinder from axis 1).
//! - **link 4** turns about axis 4 on link 3. A cylinder about axis 4 that holds link 4's is the
//!   same for every angle of axis 4, so it rides on link 3 with the forearm.
//! - **link 5** turns about axis 5 on link 4 and carries link 6, which turns about axis 6. Seen
//!   from link 6, a link-5 point turns about axis 6 with axis 6's angle: a ball centred on axis
//!   6 holds it for every angle, so the ball rides on link 6 with the tool's shapes (the
//!   machinery of `collision/parts.rs`). The centre is the point of axis 6 nearest link 5's
//!   origin (on an arm whose axis 6 passes through the wrist centre, as every shipped arm's,
//!   the wrist centre itself).
//! - **link 6** is the flange: its cylinders ride on it as they are.
//!
//! Each enclosure holds the cylinder it stands for in every pose, so a pose or move the checks
//! prove for the enclosures is proven for the URDF's cylinders (conservative: by the
//! enclosure's extra volume). A URDF with cylinders on links 1..3 alone (the IRB 1400's) gives
//! its own cylinders, unchanged, and no flange parts.

use super::{FlangePart, FlangeShape, LinkCylinder, LinkFrame, OwnCylinder, RevoluteJoint};
use nalgebra::{Isometry3, Point3, Vector3};

/// The lumped arm's cylinders and the flange's parts for the URDF's cylinders `own` (in the
/// URDF's order, base_link first) on the chain `joints` (six).
pub(super) fn lump(
    joints: &[RevoluteJoint],
    own: &[OwnCylinder],
) -> (Vec<LinkCylinder>, Vec<FlangePart>) {
    let mut arm = Vec::new();
    let mut flange = Vec::new();
    for c in own {
        let cyl = Cyl {
            a: c.a,
            b: c.b,
            r: c.radius_mm,
        };
        match c.frame {
            LinkFrame::Base => {
                // Into link 1's frame at axis 1 = 0, then about axis 1 through its origin.
                let inv = joints[0].origin.inverse();
                let held = Cyl {
                    a: inv * cyl.a,
                    b: inv * cyl.b,
                    r: cyl.r,
                }
                .about_axis(&joints[0].axis.into_inner());
                arm.push(held.on(&c.link, 0, &Isometry3::identity()));
            }
            LinkFrame::Child(j @ 0..=2) => arm.push(cyl.on(&c.link, j, &Isometry3::identity())),
            LinkFrame::Child(3) => {
                // About axis 4 in link 4's frame, carried into link 3's at axis 4 = 0.
                let held = cyl.about_axis(&joints[3].axis.into_inner());
                arm.push(held.on(&c.link, 2, &joints[3].origin));
            }
            LinkFrame::Child(4) => {
                // In link 6's frame at axis 6 = 0: link 5's points, and link 5's origin.
                let inv = joints[5].origin.inverse();
                let seen = Cyl {
                    a: inv * cyl.a,
                    b: inv * cyl.b,
                    r: cyl.r,
                };
                let u6 = joints[5].axis.into_inner();
                let o5 = inv * Point3::origin();
                let centre = Point3::from(u6 * u6.dot(&o5.coords));
                flange.push(FlangePart {
                    link: c.link.clone(),
                    shape: FlangeShape::Ball {
                        centre,
                        radius_mm: seen.farthest_from(&centre),
                    },
                });
            }
            LinkFrame::Child(_) => flange.push(FlangePart {
                link: c.link.clone(),
                shape: FlangeShape::Cylinder {
                    a: cyl.a,
                    b: cyl.b,
                    radius_mm: cyl.r,
                },
            }),
        }
    }
    // Link 5's balls before link 6's cylinders: the chain's order.
    flange.sort_by_key(|p| !matches!(p.shape, FlangeShape::Ball { .. }));
    (arm, flange)
}

/// A cylinder: axis ends and radius, mm.
#[derive(Clone, Copy, Debug)]
struct Cyl {
    a: Point3<f64>,
    b: Point3<f64>,
    r: f64,
}

impl Cyl {
    /// The cylinder about the axis through the frame's origin along the unit `u` that holds
    /// this one for every turn about that axis: along the axis, the range of the cylinder's
    /// points (`a . u`, `b . u`, widened by `r |d x u|` for an axis `d` tilted from `u`);
    /// across it, the farther end's distance from the axis plus `r`. A rounding's worth is
    /// added to both, so the enclosure holds the cylinder in floating point too.
    fn about_axis(&self, u: &Vector3<f64>) -> Cyl {
        let d = (self.b - self.a).try_normalize(0.0).unwrap_or(*u);
        let tilt = self.r * d.cross(u).norm();
        let (pa, pb) = (u.dot(&self.a.coords), u.dot(&self.b.coords));
        let across = |p: &Point3<f64>, along: f64| (p.coords - u * along).norm();
        let pad = |v: f64| v.abs() * 1e-12 + 1e-9;
        let lo = pa.min(pb) - tilt;
        let hi = pa.max(pb) + tilt;
        let r = across(&self.a, pa).max(across(&self.b, pb)) + self.r;
        Cyl {
            a: Point3::from(u * (lo - pad(lo))),
            b: Point3::from(u * (hi + pad(hi))),
            r: r + pad(r),
        }
    }

    /// The farthest distance of a point of the cylinder from `p`, mm: on one of its two rims,
    /// `sqrt(along^2 + (across + r)^2)` from either end, raised a rounding's worth.
    fn farthest_from(&self, p: &Point3<f64>) -> f64 {
        let d = (self.b - self.a)
            .try_normalize(0.0)
            .unwrap_or_else(Vector3::z);
        let rim = |e: &Point3<f64>| {
            let v = e - p;
            let along = d.dot(&v);
            along.hypot((v - d * along).norm() + self.r)
        };
        let far = rim(&self.a).max(rim(&self.b));
        far + far * 1e-12 + 1e-9
    }

    /// This cylinder (given in a frame placed by `to_link` in the frame of the child link of
    /// `joints[joint_index]`) as a cylinder of the lumped arm holding `link`'s geometry.
    fn on(&self, link: &str, joint_index: usize, to_link: &Isometry3<f64>) -> LinkCylinder {
        LinkCylinder {
            link: link.to_string(),
            joint_index,
            a: to_link * self.a,
            b: to_link * self.b,
            radius_mm: self.r,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::testing::Rng;
    use crate::robot::models::MODELS;
    use crate::robot::Robot;

    /// Points of a cylinder (its rims, the axis, and points within), frame of the cylinder.
    fn points_of(c: &OwnCylinder, rng: &mut Rng, n: usize) -> Vec<Point3<f64>> {
        let d = c.b - c.a;
        let u = d.normalize();
        let e1 = u
            .cross(&Vector3::x())
            .try_normalize(1e-6)
            .unwrap_or_else(|| u.cross(&Vector3::y()).normalize());
        let e2 = u.cross(&e1);
        (0..n)
            .map(|k| {
                let t = if k % 5 == 0 {
                    (k / 5 % 2) as f64
                } else {
                    rng.range(0.0, 1.0)
                };
                let ang = rng.range(0.0, std::f64::consts::TAU);
                let rad = if k % 3 == 0 {
                    c.radius_mm
                } else {
                    c.radius_mm * rng.range(0.0, 1.0)
                };
                c.a + d * t + (e1 * ang.cos() + e2 * ang.sin()) * rad
            })
            .collect()
    }

    fn inside_cylinder(p: &Point3<f64>, a: &Point3<f64>, b: &Point3<f64>, r: f64) -> bool {
        let d = b - a;
        let t = d.dot(&(p - a)) / d.norm_squared();
        let foot = a + d * t;
        (-1e-9..=1.0 + 1e-9).contains(&t) && (p - foot).norm() <= r + 1e-9
    }

    /// For every shipped robot, at random poses, every point of every URDF cylinder lies in
    /// what the checks carry for it: its own cylinder (links 1..3, link 6), the enclosure about
    /// axis 1 or 4 on link 1 or 3, or the ball on the flange. Fails with the ball a millimetre
    /// thinner, or the base's enclosure left out.
    #[test]
    fn the_carried_volumes_hold_every_urdf_cylinder_in_every_pose() {
        let mut rng = Rng(30);
        let mut checked = 0usize;
        for m in MODELS {
            let robot = Robot::shipped(m.name).expect("shipped");
            for _ in 0..40 {
                let axes: [f64; 6] = std::array::from_fn(|i| {
                    let s = &robot.controller.axes[i];
                    rng.range(s.min_deg, s.max_deg)
                });
                let links = robot.link_poses(&axes);
                let flange = links[5];
                for own in &robot.collision {
                    let frame = match own.frame {
                        LinkFrame::Base => Isometry3::identity(),
                        LinkFrame::Child(k) => links[k],
                    };
                    let carried: Vec<(Point3<f64>, Point3<f64>, f64, bool)> = robot
                        .cylinders
                        .iter()
                        .filter(|c| c.link == own.link)
                        .map(|c| {
                            (
                                links[c.joint_index] * c.a,
                                links[c.joint_index] * c.b,
                                c.radius_mm,
                                false,
                            )
                        })
                        .chain(
                            robot
                                .flange_parts
                                .iter()
                                .filter(|p| p.link == own.link)
                                .map(|p| match p.shape {
                                    FlangeShape::Cylinder { a, b, radius_mm } => {
                                        (flange * a, flange * b, radius_mm, false)
                                    }
                                    FlangeShape::Ball { centre, radius_mm } => {
                                        (flange * centre, flange * centre, radius_mm, true)
                                    }
                                }),
                        )
                        .collect();
                    assert!(
                        !carried.is_empty(),
                        "{}: {} carried by nothing",
                        m.name,
                        own.link
                    );
                    for p in points_of(own, &mut rng, 60) {
                        let p = frame * p;
                        let held = carried.iter().any(|(a, b, r, ball)| {
                            if *ball {
                                (p - a).norm() <= r + 1e-9
                            } else {
                                inside_cylinder(&p, a, b, *r)
                            }
                        });
                        assert!(
                            held,
                            "{}: a point of {} at {axes:?} lies outside what carries it",
                            m.name, own.link
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 100_000, "{checked}");
    }

    /// The enclosures are tight where the cylinder is coaxial: a cylinder on the axis gives
    /// itself back (to the rounding pad), one offset by `e` grows by `e`.
    #[test]
    fn an_enclosure_about_an_axis_grows_by_the_offset_alone() {
        let u = Vector3::x();
        let c = Cyl {
            a: Point3::new(100.0, 0.0, 3.0),
            b: Point3::new(400.0, 0.0, 3.0),
            r: 50.0,
        };
        let e = c.about_axis(&u);
        assert!(
            (e.r - 53.0).abs() < 1e-6
                && (e.a.x - 100.0).abs() < 1e-6
                && (e.b.x - 400.0).abs() < 1e-6,
            "{e:?}"
        );
        assert!(e.a.y == 0.0 && e.a.z == 0.0);
        // A cylinder across the axis reaches its radius beyond its ends' projections.
        let across = Cyl {
            a: Point3::new(0.0, -20.0, 0.0),
            b: Point3::new(0.0, 20.0, 0.0),
            r: 30.0,
        };
        let e = across.about_axis(&u);
        assert!(
            (e.a.x + 30.0).abs() < 1e-6 && (e.b.x - 30.0).abs() < 1e-6 && (e.r - 50.0).abs() < 1e-6,
            "{e:?}"
        );
        // The farthest point of a cylinder from its axis' end is its rim's.
        let f = across.farthest_from(&Point3::new(0.0, -20.0, 0.0));
        assert!((f - 40f64.hypot(30.0)).abs() < 1e-6, "{f}");
    }
}
