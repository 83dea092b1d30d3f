//! The parts of the robot model besides the link cylinders: the shapes link 6 (the flange)
//! carries, the robot's own (link 5's ball and link 6's cylinders, `Robot::flange_parts`) and the
//! tool's, and the bounds the proofs need for any part: `R[i][P]`, how far any point of part `P`
//! can be from joint `i`'s axis (module doc of `proof.rs`), and the ball about the wrist centre
//! that holds every flange shape for any wrist angles. The checks treat the robot's flange
//! shapes as the tool's (the same looks, proofs and bounds); only their names differ: a message
//! names them as links (`link 'link_5' of the robot`).
//!
//! # The generic bound
//!
//! A part hanging on the child link of joint `j` lies in the convex hull of a few points of that
//! link's frame grown by a radius (a cylinder: its two axis ends and its radius; a ball: its
//! centre and radius; a box: its 8 corners). With `t_k` the translation of `joints[k].origin`
//! and `P_i` the projection across joint `i`'s axis, every point `p` of the part has, in every
//! configuration,
//!
//! ```text
//! dist(p, axis i) <= max |P_i h| + grow                                     if i == j
//! dist(p, axis i) <= |P_i t_{i+1}| + sum_{k=i+2..=j} |t_k| + max |h| + grow  if i <  j
//! ```
//!
//! over the hull points `h` (the norm is convex, so its maximum over the hull is at a point).
//!
//! # Tighter at the wrist
//!
//! For a tool shape (`j` = 5) the generic bound counts the whole chain from joint 4 on. Two
//! facts of the wrist do better, for any robot: joint 5's axis passes through `o5` (the origin
//! of link 5), and the point `C` of joint 4's axis nearest to `o5` lies on that axis. With
//! `p = o5 + R5 (t6 + R_o6 Rot(u6, q6) h)` (link-5 coordinates), `|p - o5| = |t' + Rot(u6, q6) h|`
//! with `t' = R_o6^T t6`, whose largest value over `q6` is, splitting along joint 6's axis `u6`,
//!
//! ```text
//! w(h) = sqrt((t'_par + h_par)^2 + (|t'_perp| + |h_perp|)^2)
//! ```
//!
//! So `dist(p, axis 5) <= max w(h) + grow` and `dist(p, axis 4) <= |p - C| <= |o5 - C| + max
//! w(h) + grow`, whichever is smaller is used. The latter is also the tool's radius about `C`
//! ([`ToolData::radius_mm`]): the ball of that radius about `C` holds every tool shape for any
//! wrist angles. `C` is fixed in link 3's frame (it lies on joint 4's axis), so it moves with
//! axes 1..3 only; for a spherical wrist (axes 4..6 meeting at `o5`, as on the IRB 1400) `C` is
//! the wrist centre and `|o5 - C|` = 0.

use super::Part;
use crate::cell::{Tool, ToolGeometry};
use crate::geometry::{Cylinder, Obb, Point, Solid, Sphere};
use crate::robot::{FlangeShape, Robot};
use nalgebra::{Isometry3, Matrix3, Vector3};

/// A tool shape in the link-6 frame, mm.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Local {
    Cylinder {
        a: Point,
        b: Point,
        radius: f64,
    },
    Sphere {
        centre: Point,
        radius: f64,
    },
    Box {
        centre: Point,
        axes: Matrix3<f64>,
        half: Vector3<f64>,
    },
}

impl Local {
    /// The shape of the cell's tool block, from the flange (tool0) frame into the link-6 frame.
    fn from_tool(g: &ToolGeometry, flange_to_tool0: &Isometry3<f64>) -> Local {
        let p = |v: &[f64; 3]| flange_to_tool0 * Point::from(*v);
        match g {
            ToolGeometry::Cylinder {
                from_mm,
                to_mm,
                radius_mm,
            } => Local::Cylinder {
                a: p(from_mm),
                b: p(to_mm),
                radius: radius_mm.max(0.0),
            },
            ToolGeometry::Sphere {
                centre_mm,
                radius_mm,
            } => Local::Sphere {
                centre: p(centre_mm),
                radius: radius_mm.max(0.0),
            },
            ToolGeometry::Box { min_mm, max_mm } => {
                let c: [f64; 3] = std::array::from_fn(|k| 0.5 * (min_mm[k] + max_mm[k]));
                Local::Box {
                    centre: p(&c),
                    axes: flange_to_tool0.rotation.to_rotation_matrix().into_inner(),
                    half: Vector3::from_fn(|k, _| 0.5 * (max_mm[k] - min_mm[k]).abs()),
                }
            }
        }
    }

    /// A robot's flange part (`Robot::flange_parts`), already in the link-6 frame.
    fn from_flange(shape: &FlangeShape) -> Local {
        match *shape {
            FlangeShape::Cylinder { a, b, radius_mm } => Local::Cylinder {
                a,
                b,
                radius: radius_mm.max(0.0),
            },
            FlangeShape::Ball { centre, radius_mm } => Local::Sphere {
                centre,
                radius: radius_mm.max(0.0),
            },
        }
    }

    /// A ball holding the shape (link-6 frame): its centre and radius, mm, the radius raised a
    /// little over its float value. The cheap first look of the tool test
    /// (`CollisionModel::tool_is_free`).
    fn ball(&self) -> (Point, f64) {
        let (centre, radius) = match self {
            Local::Cylinder { a, b, radius } => (
                nalgebra::center(a, b),
                (0.5 * (b - a).norm()).hypot(*radius),
            ),
            Local::Sphere { centre, radius } => (*centre, *radius),
            Local::Box { centre, half, .. } => (*centre, half.norm()),
        };
        (centre, radius * (1.0 + 1e-9) + 1e-9)
    }

    /// The radius of a ball about the centre of [`ball`](Self::ball) that lies inside the
    /// shape, mm: a cylinder's radius (at most half its length: the centre is its axis's
    /// midpoint), a sphere's, a box's least half side. A point of the shape within the
    /// clearance less this of a box proves the shape within the clearance
    /// (`CollisionModel::tool_look_sincos`'s blocked answers).
    fn inner_radius(&self) -> f64 {
        match self {
            Local::Cylinder { a, b, radius } => radius.min(0.5 * (b - a).norm()),
            Local::Sphere { radius, .. } => *radius,
            Local::Box { half, .. } => half.min(),
        }
    }

    /// Points whose convex hull, grown by the radius returned, holds the shape.
    fn hull(&self) -> (Vec<Point>, f64) {
        match self {
            Local::Cylinder { a, b, radius } => (vec![*a, *b], *radius),
            Local::Sphere { centre, radius } => (vec![*centre], *radius),
            Local::Box { centre, axes, half } => (
                (0..8)
                    .map(|k| {
                        let s = |i: usize| if k >> i & 1 == 1 { half[i] } else { -half[i] };
                        centre + axes * Vector3::new(s(0), s(1), s(2))
                    })
                    .collect(),
                0.0,
            ),
        }
    }

    /// The shape placed by the pose of link 6 (cell frame).
    #[inline]
    pub(super) fn placed(&self, pose: &Isometry3<f64>) -> Solid {
        match self {
            Local::Cylinder { a, b, radius } => Solid::Cylinder(Cylinder {
                a: pose * a,
                b: pose * b,
                radius: *radius,
            }),
            Local::Sphere { centre, radius } => Solid::Sphere(Sphere {
                centre: pose * centre,
                radius: *radius,
            }),
            Local::Box { centre, axes, half } => Solid::Box(Obb {
                centre: pose * centre,
                axes: pose.rotation.to_rotation_matrix().into_inner() * axes,
                half: *half,
            }),
        }
    }
}

/// One flange shape: the part it is (a link's, or a tool shape, by name, for messages), its
/// place on link 6, and `R[i][S]`.
#[derive(Clone, Debug)]
pub(super) struct ShapeData {
    pub part: Part,
    pub local: Local,
    /// A ball holding the shape: centre in the link-6 frame and radius, mm.
    pub ball: (Point, f64),
    /// The radius of a ball about `ball`'s centre inside the shape, mm.
    pub inner_mm: f64,
    /// `R[i][S]` for joints 1..6 (module doc), mm.
    pub reach_mm: [f64; 6],
}

/// What the flange carries: the robot's link-5 and link-6 parts, then the tool's shapes, and the
/// ball about the wrist centre `C` that holds them all.
#[derive(Clone, Debug)]
pub(super) struct ToolData {
    pub shapes: Vec<ShapeData>,
    /// `C` in link 3's frame, mm (module doc).
    pub centre: Vector3<f64>,
    /// `R[i][C]` for joints 1..3: how far `C` can be from each axis, mm.
    pub centre_reach_mm: [f64; 3],
    /// Every point of every shape stays within this of `C`, for any wrist angles, mm.
    pub radius_mm: f64,
}

impl ToolData {
    /// The flange's collision volumes: the robot's flange parts, then the shapes of `tool` (if
    /// any); `None` when there are none (then there is nothing to check). The robot must have
    /// six joints (as [`Robot::load`] guarantees).
    pub fn new(robot: &Robot, tool: Option<&Tool>) -> Option<ToolData> {
        let locals: Vec<(Part, Local)> = robot
            .flange_parts
            .iter()
            .map(|p| (Part::Link(p.link.clone()), Local::from_flange(&p.shape)))
            .chain(tool.into_iter().flat_map(|t| &t.shapes).map(|s| {
                (
                    Part::ToolShape(s.name.clone()),
                    Local::from_tool(&s.geometry, &robot.flange_to_tool0),
                )
            }))
            .collect();
        if locals.is_empty() {
            return None;
        }
        let j = &robot.joints;
        // C: on joint 4's axis, nearest to o5 (module doc); in link 3's frame.
        let u4 = j[3].axis.into_inner();
        let t5 = j[4].origin.translation.vector;
        let on_axis = u4 * u4.dot(&t5);
        let centre = (j[3].origin * Point::from(on_axis)).coords;
        let off_axis = (t5 - on_axis).norm();
        // w(h) of the module doc: the largest |p - o5| of a link-6 point h over joint 6.
        let u6 = j[5].axis.into_inner();
        let t6 = j[5].origin.rotation.inverse() * j[5].origin.translation.vector;
        let (t_par, t_perp) = split(&t6, &u6);
        let wrist = |h: &Point| {
            let (h_par, h_perp) = split(&h.coords, &u6);
            (t_par + h_par).hypot(t_perp + h_perp)
        };
        let mut radius_mm: f64 = 0.0;
        let shapes = locals
            .into_iter()
            .map(|(part, local)| {
                let (hull, grow) = local.hull();
                let mut reach_mm = reach(robot, 5, &hull, grow);
                let about_o5 = hull.iter().map(wrist).fold(0.0, f64::max) + grow;
                reach_mm[4] = reach_mm[4].min(about_o5);
                reach_mm[3] = reach_mm[3].min(off_axis + about_o5);
                radius_mm = radius_mm.max(off_axis + about_o5);
                ShapeData {
                    part,
                    ball: local.ball(),
                    inner_mm: local.inner_radius(),
                    local,
                    reach_mm,
                }
            })
            .collect();
        let r = reach(robot, 2, &[Point::from(centre)], 0.0);
        Some(ToolData {
            shapes,
            centre,
            centre_reach_mm: [r[0], r[1], r[2]],
            radius_mm,
        })
    }
}

/// The component of `v` along the unit `u` and the length of the rest.
fn split(v: &Vector3<f64>, u: &Vector3<f64>) -> (f64, f64) {
    let par = u.dot(v);
    (par, (v - u * par).norm())
}

/// `R[i][P]` (module doc, the generic bound) for a part on the child link of joint `j` held by
/// the hull of `hull` (that link's frame) grown by `grow`; 0 for `i > j`.
pub(super) fn reach(robot: &Robot, j: usize, hull: &[Point], grow: f64) -> [f64; 6] {
    let far = hull.iter().map(|h| h.coords.norm()).fold(0.0, f64::max) + grow;
    let mut out = [0.0; 6];
    for (i, slot) in out.iter_mut().enumerate().take(j + 1) {
        let u = robot.joints[i].axis.into_inner();
        let perp = |v: &Vector3<f64>| (v - u * u.dot(v)).norm();
        *slot = if i == j {
            hull.iter().map(|h| perp(&h.coords)).fold(0.0, f64::max) + grow
        } else {
            let first = perp(&robot.joints[i + 1].origin.translation.vector);
            let rest: f64 = (i + 2..=j)
                .map(|k| robot.joints[k].origin.translation.vector.norm())
                .sum();
            first + rest + far
        };
    }
    out
}

/// How far from the base any point of a part on joint `j` (hull and grow as in [`reach`]) can
/// be, mm: the chain's lengths plus the part's extent.
pub(super) fn extent_from_base(robot: &Robot, j: usize, hull: &[Point], grow: f64) -> f64 {
    let chain: f64 = (0..=j)
        .map(|k| robot.joints[k].origin.translation.vector.norm())
        .sum();
    chain + hull.iter().map(|h| h.coords.norm()).fold(0.0, f64::max) + grow
}

impl ToolData {
    /// How far from the base any point of the tool can be, mm.
    pub fn extent_from_base(&self, robot: &Robot) -> f64 {
        self.shapes
            .iter()
            .map(|s| {
                let (hull, grow) = s.local.hull();
                extent_from_base(robot, 5, &hull, grow)
            })
            .fold(0.0, f64::max)
    }
}
