//! A TCP path as a robot controller runs it: the straight line of `MoveL`, the circular arc of
//! `MoveC`, and `RelTool`, the pose moved along its own axes (approach and retract lines).
//!
//! A [`CartesianPath`] is a pose (TCP frame) at every progress `s` in `[0, 1]`, in whatever frame
//! its ends are given (a work object, the cell, the robot base): both shapes commute with a
//! change of frame ([`CartesianPath::transformed`]), since positions interpolate affinely and a
//! rotation applied to both ends of a turn turns the whole turn with them.
//!
//! - **Line** (`MoveL`): the position runs linearly from the start to the end, and the tool's
//!   orientation turns evenly (a slerp: about one fixed axis at a constant rate, the shorter
//!   way) with the same progress.
//! - **Arc** (`MoveC`): the circle through the start position, a via position and the end
//!   position, traversed from the start through the via to the end, at a constant rate along
//!   the arc; the orientation turns as on a line, with the arc-length fraction as its progress.
//!   Refused: an arc over [`MAX_ARC_DEG`], and a via less than [`MIN_VIA_OFFSET_MM`] off the
//!   chord's line or from either end (the three points do not define a circle one can trust:
//!   "collinear").
//!
//! Both refuse an orientation change of 180 deg between the ends (within [`TURN_TOL_DEG`]):
//! there the shorter way is not defined, and which way the tool turns would be up to the
//! rounding of the written quaternions.
//!
//! **The CirPoint's orientation.** RAPID's `MoveC` takes a `CirPoint` robtarget, but uses its
//! orientation only to tell a short turn from a long one between the start and the end (the
//! reorientation along the arc follows the ends). gen-rapid's arcs always turn the short way,
//! so [`CartesianPath::cir_point`] gives the CirPoint the orientation the path has at the via's
//! arc fraction: it lies on the short turn, so the controller takes the short turn, and the
//! CirPoint is a pose the tool truly passes through.
//!
//! Units: mm and radians inside, degrees where a name says so. Quaternions of nalgebra
//! (`[w, x, y, z]` as RAPID writes them).

use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use std::f64::consts::PI;

/// The least distance of an arc's via from the chord's line and from either end, mm.
pub const MIN_VIA_OFFSET_MM: f64 = 0.5;
/// The longest arc `MoveC` is asked to run, deg.
pub const MAX_ARC_DEG: f64 = 240.0;
/// An orientation change within this of 180 deg between a path's ends is refused as ambiguous,
/// deg (the written quaternions, 9 decimals, hold an orientation to about 1e-7 deg).
pub const TURN_TOL_DEG: f64 = 1e-6;
/// Slack on [`MAX_ARC_DEG`] for the rounding of the circle's construction, deg.
const ARC_SLACK_DEG: f64 = 1e-9;

/// Why a path cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PathError {
    #[error("a pose of the path is not finite")]
    NotFinite,
    #[error(
        "the via point does not make a circle with the ends: it lies {off_chord_mm:.3} mm off \
         the line through them, {from_start_mm:.3} mm from the start and {from_end_mm:.3} mm \
         from the end (at least {MIN_VIA_OFFSET_MM} mm each)"
    )]
    Collinear {
        off_chord_mm: f64,
        from_start_mm: f64,
        from_end_mm: f64,
    },
    #[error("the arc spans {angle_deg:.1} deg; a circular move spans at most {MAX_ARC_DEG} deg")]
    ArcTooLong { angle_deg: f64 },
    #[error(
        "the tool turns {turn_deg:.6} deg between the ends of the path: at 180 deg the shorter \
         way is not defined"
    )]
    AmbiguousTurn { turn_deg: f64 },
}

/// The shape of a path's positions.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    Line,
    /// The circle `centre + r (cos(a) u + sin(a) w)` for `a` from 0 to `angle_rad`.
    Arc {
        centre: Point3<f64>,
        radius_mm: f64,
        /// Unit vector from the centre to the start.
        u: Vector3<f64>,
        /// Unit vector of the plane a quarter turn ahead of `u`, in the direction of travel.
        w: Vector3<f64>,
        angle_rad: f64,
        /// The via's arc fraction, in (0, 1).
        via_fraction: f64,
        /// The via as given.
        via: Point3<f64>,
    },
}

/// How a path's position is made from the progress `s` (for a caller that encloses the pose
/// over a range of progress, the follower's deviation bound); the orientation is
/// `start * exp(s turn)` ([`CartesianPath::form`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PathForm {
    /// `from + s (to - from)`.
    Line {
        from: Vector3<f64>,
        to: Vector3<f64>,
    },
    /// `centre + radius_mm (cos(angle_rad s) u + sin(angle_rad s) w)`.
    Arc {
        centre: Vector3<f64>,
        radius_mm: f64,
        u: Vector3<f64>,
        w: Vector3<f64>,
        angle_rad: f64,
    },
}

/// A TCP path: a pose at every progress `s` in `[0, 1]` (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CartesianPath {
    start: Isometry3<f64>,
    end: Isometry3<f64>,
    /// The turn from the start's orientation to the end's, the shorter way, as a scaled axis in
    /// the start's own frame (rad): `end = start * exp(turn)`.
    turn: Vector3<f64>,
    shape: Shape,
}

/// `RelTool(p, dx, dy, dz)`: pose `p` moved by `(dx, dy, dz)` mm along its own axes, its
/// orientation kept. An approach or retract pose D mm back along the tool's z axis is
/// `rel_tool(p, 0, 0, -D)`.
pub fn rel_tool(p: &Isometry3<f64>, dx: f64, dy: f64, dz: f64) -> Isometry3<f64> {
    p * Translation3::new(dx, dy, dz)
}

/// The shorter turn from `a` to `b` as a scaled axis in `a`'s frame (rad); refused at 180 deg
/// ([`TURN_TOL_DEG`]).
fn shorter_turn(
    a: &UnitQuaternion<f64>,
    b: &UnitQuaternion<f64>,
) -> Result<Vector3<f64>, PathError> {
    let r = (a.inverse() * b).into_inner();
    // q and -q are one rotation: the one with w >= 0 turns by at most half a turn.
    let (w, v) = if r.w < 0.0 {
        (-r.w, -r.imag())
    } else {
        (r.w, r.imag())
    };
    let sin_half = v.norm();
    let angle = 2.0 * sin_half.atan2(w);
    if angle.to_degrees() >= 180.0 - TURN_TOL_DEG {
        return Err(PathError::AmbiguousTurn {
            turn_deg: angle.to_degrees(),
        });
    }
    Ok(if sin_half > 0.0 {
        v * (angle / sin_half)
    } else {
        Vector3::zeros()
    })
}

fn is_finite(p: &Isometry3<f64>) -> bool {
    p.translation.vector.iter().all(|v| v.is_finite())
        && p.rotation.coords.iter().all(|v| v.is_finite())
}

impl CartesianPath {
    /// The straight line from `start` to `end` (`MoveL`).
    pub fn line(start: &Isometry3<f64>, end: &Isometry3<f64>) -> Result<CartesianPath, PathError> {
        if !is_finite(start) || !is_finite(end) {
            return Err(PathError::NotFinite);
        }
        Ok(CartesianPath {
            start: *start,
            end: *end,
            turn: shorter_turn(&start.rotation, &end.rotation)?,
            shape: Shape::Line,
        })
    }

    /// The arc from `start` through the position `via` to `end` (`MoveC`; module docs).
    pub fn arc(
        start: &Isometry3<f64>,
        via: &Point3<f64>,
        end: &Isometry3<f64>,
    ) -> Result<CartesianPath, PathError> {
        if !is_finite(start) || !is_finite(end) || !via.coords.iter().all(|v| v.is_finite()) {
            return Err(PathError::NotFinite);
        }
        let a = Point3::from(start.translation.vector);
        let c = Point3::from(end.translation.vector);
        let b = *via;
        let chord = c - a;
        let from_start_mm = (b - a).norm();
        let from_end_mm = (b - c).norm();
        let off_chord_mm = if chord.norm() > 0.0 {
            (b - a).cross(&chord).norm() / chord.norm()
        } else {
            0.0
        };
        if off_chord_mm < MIN_VIA_OFFSET_MM
            || from_start_mm < MIN_VIA_OFFSET_MM
            || from_end_mm < MIN_VIA_OFFSET_MM
        {
            return Err(PathError::Collinear {
                off_chord_mm,
                from_start_mm,
                from_end_mm,
            });
        }
        // The circumcentre: with p = a - c and q = b - c,
        // centre = c + ((|p|^2 q - |q|^2 p) x (p x q)) / (2 |p x q|^2).
        let (p, q) = (a - c, b - c);
        let pxq = p.cross(&q);
        let centre = c
            + (q * p.norm_squared() - p * q.norm_squared()).cross(&pxq)
                / (2.0 * pxq.norm_squared());
        let radius_mm = (a - centre).norm();
        // Three points of a circle visited counter-clockwise about n make a counter-clockwise
        // triangle, so with n = (b - a) x (c - a) the arc a -> b -> c runs positively about n.
        let n = (b - a).cross(&(c - a)).normalize();
        let u = (a - centre) / radius_mm;
        let w = n.cross(&u);
        let angle_of = |x: &Point3<f64>| {
            let d = x - centre;
            let t = w.dot(&d).atan2(u.dot(&d));
            if t <= 0.0 {
                t + 2.0 * PI
            } else {
                t
            }
        };
        let angle_rad = angle_of(&c);
        if angle_rad.to_degrees() > MAX_ARC_DEG + ARC_SLACK_DEG {
            return Err(PathError::ArcTooLong {
                angle_deg: angle_rad.to_degrees(),
            });
        }
        let via_fraction = (angle_of(&b) / angle_rad).clamp(0.0, 1.0);
        Ok(CartesianPath {
            start: *start,
            end: *end,
            turn: shorter_turn(&start.rotation, &end.rotation)?,
            shape: Shape::Arc {
                centre,
                radius_mm,
                u,
                w,
                angle_rad,
                via_fraction,
                via: b,
            },
        })
    }

    /// The formula of [`pose_at`](Self::pose_at) inside `(0, 1)`: the positions' form, the
    /// start's orientation, and the turn as a scaled axis in the start's frame (rad).
    pub fn form(&self) -> (PathForm, UnitQuaternion<f64>, Vector3<f64>) {
        let form = match self.shape {
            Shape::Line => PathForm::Line {
                from: self.start.translation.vector,
                to: self.end.translation.vector,
            },
            Shape::Arc {
                centre,
                radius_mm,
                u,
                w,
                angle_rad,
                ..
            } => PathForm::Arc {
                centre: centre.coords,
                radius_mm,
                u,
                w,
                angle_rad,
            },
        };
        (form, self.start.rotation, self.turn)
    }

    /// The pose at the start (`s` = 0).
    pub fn start(&self) -> Isometry3<f64> {
        self.start
    }

    /// The pose at the end (`s` = 1).
    pub fn end(&self) -> Isometry3<f64> {
        self.end
    }

    /// Whether the path is an arc.
    pub fn is_arc(&self) -> bool {
        matches!(self.shape, Shape::Arc { .. })
    }

    /// The TCP position at progress `s` (clamped into `[0, 1]`; the ends exactly as given).
    pub fn position_at(&self, s: f64) -> Point3<f64> {
        if s <= 0.0 {
            return Point3::from(self.start.translation.vector);
        }
        if s >= 1.0 {
            return Point3::from(self.end.translation.vector);
        }
        match self.shape {
            Shape::Line => {
                let (a, b) = (self.start.translation.vector, self.end.translation.vector);
                Point3::from(a + (b - a) * s)
            }
            Shape::Arc {
                centre,
                radius_mm,
                u,
                w,
                angle_rad,
                ..
            } => {
                let (sin, cos) = (angle_rad * s).sin_cos();
                centre + (u * cos + w * sin) * radius_mm
            }
        }
    }

    /// The tool's orientation at progress `s` (clamped; the ends exactly as given).
    pub fn orientation_at(&self, s: f64) -> UnitQuaternion<f64> {
        if s <= 0.0 {
            return self.start.rotation;
        }
        if s >= 1.0 {
            return self.end.rotation;
        }
        self.start.rotation * UnitQuaternion::from_scaled_axis(self.turn * s)
    }

    /// The TCP pose at progress `s` in `[0, 1]` (clamped).
    pub fn pose_at(&self, s: f64) -> Isometry3<f64> {
        Isometry3::from_parts(
            Translation3::from(self.position_at(s).coords),
            self.orientation_at(s),
        )
    }

    /// The length of the TCP's path, mm.
    pub fn length_mm(&self) -> f64 {
        match self.shape {
            Shape::Line => (self.end.translation.vector - self.start.translation.vector).norm(),
            Shape::Arc {
                radius_mm,
                angle_rad,
                ..
            } => radius_mm * angle_rad,
        }
    }

    /// The tool's total turn from the start to the end, deg (below 180).
    pub fn turn_deg(&self) -> f64 {
        self.turn.norm().to_degrees()
    }

    /// An arc's angle at its centre, deg (`None` for a line).
    pub fn arc_deg(&self) -> Option<f64> {
        match self.shape {
            Shape::Line => None,
            Shape::Arc { angle_rad, .. } => Some(angle_rad.to_degrees()),
        }
    }

    /// An arc's centre and radius (mm; `None` for a line).
    pub fn circle(&self) -> Option<(Point3<f64>, f64)> {
        match self.shape {
            Shape::Line => None,
            Shape::Arc {
                centre, radius_mm, ..
            } => Some((centre, radius_mm)),
        }
    }

    /// An arc's via as the arc fraction where the path passes it (`None` for a line).
    pub fn via_fraction(&self) -> Option<f64> {
        match self.shape {
            Shape::Line => None,
            Shape::Arc { via_fraction, .. } => Some(via_fraction),
        }
    }

    /// The pose an arc's `CirPoint` robtarget gets: the via's position, with the orientation
    /// the path has at the via's arc fraction (module docs); `None` for a line.
    pub fn cir_point(&self) -> Option<Isometry3<f64>> {
        match self.shape {
            Shape::Line => None,
            Shape::Arc {
                via_fraction, via, ..
            } => Some(Isometry3::from_parts(
                Translation3::from(via.coords),
                self.orientation_at(via_fraction),
            )),
        }
    }

    /// The same path seen from another frame: `frame * pose_at(s)` at every `s` (`frame` is
    /// this path's frame in the new one).
    pub fn transformed(&self, frame: &Isometry3<f64>) -> CartesianPath {
        let r = frame.rotation;
        let shape = match self.shape {
            Shape::Line => Shape::Line,
            Shape::Arc {
                centre,
                radius_mm,
                u,
                w,
                angle_rad,
                via_fraction,
                via,
            } => Shape::Arc {
                centre: frame * centre,
                radius_mm,
                u: r * u,
                w: r * w,
                angle_rad,
                via_fraction,
                via: frame * via,
            },
        };
        CartesianPath {
            start: frame * self.start,
            end: frame * self.end,
            // A turn in the start's own frame is the same from any frame.
            turn: self.turn,
            shape,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Quaternion, Unit};
    use std::f64::consts::FRAC_1_SQRT_2;

    fn pose(p: [f64; 3], q: [f64; 4]) -> Isometry3<f64> {
        Isometry3::from_parts(
            Translation3::new(p[0], p[1], p[2]),
            UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3])),
        )
    }

    fn turned(axis: [f64; 3], deg: f64) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), deg.to_radians())
    }

    fn angle_deg(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
        a.angle_to(b).to_degrees()
    }

    /// The torch-trunk seam's orientation (cell file): the tool's z axis into the seam.
    const SEAM_Q: [f64; 4] = [0.1830127, -0.6830127, -0.6830127, -0.1830127];

    /// A line's positions are the affine interpolation of its ends and its orientation is
    /// nalgebra's slerp (the shorter way) at the same progress; the ends are exact. Fails with
    /// the orientation turned the long way, or at another rate than the position.
    #[test]
    fn a_line_runs_straight_and_turns_evenly_the_shorter_way() {
        let a = pose([330.0, 280.0, 0.0], SEAM_Q);
        // 350 mm along y, the tool turned 60 deg about a skew axis.
        let end_rot = a.rotation * turned([0.3, -0.2, 0.9], 60.0);
        let b = Isometry3::from_parts(Translation3::new(330.0, 630.0, 0.0), end_rot);
        let line = CartesianPath::line(&a, &b).expect("a line");
        assert!((line.length_mm() - 350.0).abs() < 1e-9);
        assert!((line.turn_deg() - 60.0).abs() < 1e-9);
        assert_eq!(line.pose_at(0.0), a);
        assert_eq!(line.pose_at(1.0), b);
        for k in 0..=40 {
            let s = k as f64 / 40.0;
            let p = line.pose_at(s);
            let expected = a.translation.vector * (1.0 - s) + b.translation.vector * s;
            assert!((p.translation.vector - expected).norm() < 1e-9, "s {s}");
            let slerp = a
                .rotation
                .try_slerp(&b.rotation, s, 1e-12)
                .expect("not half a turn");
            assert!(angle_deg(&p.rotation, &slerp) < 1e-9, "s {s}");
            assert!((angle_deg(&a.rotation, &p.rotation) - 60.0 * s).abs() < 1e-8);
        }
        // The end given by -q (the same rotation) makes the same path.
        let neg =
            Isometry3::from_parts(b.translation, Unit::new_unchecked(-b.rotation.into_inner()));
        let same = CartesianPath::line(&a, &neg).expect("a line");
        for s in [0.25, 0.5, 0.75] {
            assert!(angle_deg(&same.orientation_at(s), &line.orientation_at(s)) < 1e-9);
        }
        // A turn of 270 deg about z is 90 deg the other way.
        let c = Isometry3::from_parts(a.translation, a.rotation * turned([0.0, 0.0, 1.0], 270.0));
        let short = CartesianPath::line(&a, &c).expect("a line");
        assert!((short.turn_deg() - 90.0).abs() < 1e-9);
        let mid = short.orientation_at(0.5);
        assert!(angle_deg(&mid, &(a.rotation * turned([0.0, 0.0, 1.0], -45.0))) < 1e-9);
    }

    /// An orientation change of 180 deg is refused for lines and arcs; just under it is not.
    #[test]
    fn half_a_turn_between_the_ends_is_ambiguous() {
        let a = pose([0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
        let flip = Isometry3::from_parts(
            Translation3::new(100.0, 0.0, 0.0),
            turned([0.0, 1.0, 0.0], 180.0),
        );
        assert!(matches!(
            CartesianPath::line(&a, &flip),
            Err(PathError::AmbiguousTurn { .. })
        ));
        let via = Point3::new(50.0, 50.0, 0.0);
        assert!(matches!(
            CartesianPath::arc(&a, &via, &flip),
            Err(PathError::AmbiguousTurn { .. })
        ));
        let almost = Isometry3::from_parts(flip.translation, turned([0.0, 1.0, 0.0], 179.9));
        let line = CartesianPath::line(&a, &almost).expect("below half a turn");
        assert!((line.turn_deg() - 179.9).abs() < 1e-9);
    }

    /// An arc's points lie on the circle through its three points (centre found independently
    /// by the perpendicular bisectors), in their plane, at a constant rate along the arc; it
    /// passes the via at the via's fraction, and its length is the radius times the angle.
    /// Fails with the arc traversed the other way round (it would miss the via) or at an uneven
    /// rate.
    #[test]
    fn an_arc_runs_on_the_circle_through_its_points() {
        // A quarter circle about (480, 630, 0) of radius 150 from (330, 630, 0) to
        // (480, 780, 0), the via half way, at 135 deg: (480 - 150 cos 45, 630 + 150 sin 45).
        let a = pose([330.0, 630.0, 0.0], SEAM_Q);
        let b = pose([480.0, 780.0, 0.0], SEAM_Q);
        let via = Point3::new(373.934, 736.066, 0.0);
        let arc = CartesianPath::arc(&a, &via, &b).expect("an arc");
        let (centre, r) = arc.circle().expect("a circle");
        assert!(
            (centre - Point3::new(480.0, 630.0, 0.0)).norm() < 1e-3,
            "{centre}"
        );
        assert!((r - 150.0).abs() < 1e-3);
        assert!((arc.arc_deg().unwrap_or(0.0) - 90.0).abs() < 1e-3);
        assert!((arc.via_fraction().unwrap_or(0.0) - 0.5).abs() < 1e-4);
        assert!((arc.length_mm() - 150.0 * PI / 2.0).abs() < 1e-2);
        // Independent circle: equidistant from the three points, in their plane.
        let n = 64;
        let pts: Vec<Point3<f64>> = (0..=n)
            .map(|k| arc.position_at(k as f64 / n as f64))
            .collect();
        for p in &pts {
            assert!(((p - centre).norm() - r).abs() < 1e-9);
            assert!(p.z.abs() < 1e-9);
            // On the short side: between the start and the end, x from 330 to 480, y >= 630.
            assert!(p.y >= 630.0 - 1e-9 && p.x <= 480.0 + 1e-9);
        }
        let steps: Vec<f64> = pts.windows(2).map(|w| (w[1] - w[0]).norm()).collect();
        for s in &steps {
            assert!((s - steps[0]).abs() < 1e-9, "even rate");
        }
        assert!((arc.position_at(0.5) - via).norm() < 1e-2);

        // A skew arc: the circle through three points, the via passed at its fraction, every
        // point on the circle and in the plane of the three.
        let a = pose([100.0, -20.0, 400.0], [1.0, 0.0, 0.0, 0.0]);
        let b = pose([-50.0, 180.0, 520.0], [0.9, 0.1, -0.3, 0.2]);
        let via = Point3::new(60.0, 150.0, 600.0);
        let arc = CartesianPath::arc(&a, &via, &b).expect("an arc");
        let (centre, r) = arc.circle().expect("a circle");
        for p in [a.translation.vector, b.translation.vector, via.coords] {
            assert!(((Point3::from(p) - centre).norm() - r).abs() < 1e-9);
        }
        let f = arc.via_fraction().expect("an arc");
        assert!((arc.position_at(f) - via).norm() < 1e-9);
        let normal = (via - Point3::from(a.translation.vector))
            .cross(&(b.translation.vector - a.translation.vector))
            .normalize();
        for k in 0..=32 {
            let p = arc.position_at(k as f64 / 32.0);
            assert!(((p - centre).norm() - r).abs() < 1e-9);
            assert!((p - centre).dot(&normal).abs() < 1e-9);
        }
        assert_eq!(arc.pose_at(1.0), b);
    }

    /// Arcs up to 240 deg are made, longer ones refused; a via on the chord's line, or too near
    /// an end, is refused as collinear, one 0.6 mm off is not.
    #[test]
    fn arcs_over_240_deg_and_collinear_vias_are_refused() {
        let at = |deg: f64| {
            let t = deg.to_radians();
            pose(
                [100.0 * t.cos(), 100.0 * t.sin(), 0.0],
                [1.0, 0.0, 0.0, 0.0],
            )
        };
        let p = |deg: f64| Point3::from(at(deg).translation.vector);
        let a = at(0.0);
        let ok = CartesianPath::arc(&a, &p(119.0), &at(238.0)).expect("238 deg");
        assert!((ok.arc_deg().unwrap_or(0.0) - 238.0).abs() < 1e-9);
        match CartesianPath::arc(&a, &p(121.0), &at(242.0)) {
            Err(PathError::ArcTooLong { angle_deg }) => assert!((angle_deg - 242.0).abs() < 1e-9),
            other => panic!("{other:?}"),
        }
        let a = pose([0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
        let b = pose([200.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
        for via in [
            Point3::new(100.0, 0.0, 0.0),
            Point3::new(100.0, 0.4, 0.0),
            Point3::new(300.0, 0.0, 0.0),
            Point3::new(0.3, 0.3, 0.0),
            Point3::new(199.8, 0.45, 0.0),
        ] {
            assert!(
                matches!(
                    CartesianPath::arc(&a, &via, &b),
                    Err(PathError::Collinear { .. })
                ),
                "{via}"
            );
        }
        let shallow = CartesianPath::arc(&a, &Point3::new(100.0, 0.6, 0.0), &b).expect("an arc");
        assert!(shallow.arc_deg().unwrap_or(0.0) < 2.0);
        // Ends that coincide make no chord.
        assert!(matches!(
            CartesianPath::arc(&a, &Point3::new(50.0, 50.0, 0.0), &a),
            Err(PathError::Collinear { .. })
        ));
    }

    /// The CirPoint's orientation is the path's at the via's fraction: on the short turn, so the
    /// angles start -> CirPoint -> end add up to the whole turn.
    #[test]
    fn the_cir_point_lies_on_the_short_turn() {
        let a = pose([0.0, 0.0, 0.0], SEAM_Q);
        let end_rot = a.rotation * turned([1.0, 2.0, -0.5], 150.0);
        let b = Isometry3::from_parts(Translation3::new(300.0, 0.0, 0.0), end_rot);
        let via = Point3::new(60.0, 120.0, 0.0);
        let arc = CartesianPath::arc(&a, &via, &b).expect("an arc");
        let cir = arc.cir_point().expect("an arc's CirPoint");
        assert_eq!(Point3::from(cir.translation.vector), via);
        let f = arc.via_fraction().expect("an arc");
        assert!(f > 0.0 && f < 1.0);
        let (to_via, from_via) = (
            angle_deg(&a.rotation, &cir.rotation),
            angle_deg(&cir.rotation, &b.rotation),
        );
        assert!((to_via - 150.0 * f).abs() < 1e-8);
        assert!((to_via + from_via - 150.0).abs() < 1e-8);
        assert!(CartesianPath::line(&a, &b)
            .expect("line")
            .cir_point()
            .is_none());
    }

    /// `RelTool(p, 0, 0, -D)` is D mm back along p's own z axis, orientation kept; x and y
    /// move along p's x and y.
    #[test]
    fn rel_tool_moves_along_the_pose_s_own_axes() {
        let p = pose([330.0, 280.0, 0.0], SEAM_Q);
        let back = rel_tool(&p, 0.0, 0.0, -40.0);
        assert_eq!(back.rotation, p.rotation);
        // The seam's tool z axis is (0, sin 30, -cos 30) (cell file): back is up and towards -y.
        let z = Vector3::new(0.0, 0.5, -(3f64.sqrt()) / 2.0);
        let expected = p.translation.vector - z * 40.0;
        assert!((back.translation.vector - expected).norm() < 1e-5, "{back}");
        let side = rel_tool(&p, 10.0, -5.0, 0.0);
        let (x, y) = (p.rotation * Vector3::x(), p.rotation * Vector3::y());
        let expected = p.translation.vector + x * 10.0 - y * 5.0;
        assert!((side.translation.vector - expected).norm() < 1e-9);
    }

    /// A path seen from another frame is the frame times the path, pose by pose.
    #[test]
    fn a_transformed_path_is_the_frame_times_the_path() {
        let frame = pose(
            [-830.0, -380.0, 100.0],
            [FRAC_1_SQRT_2, 0.0, 0.0, FRAC_1_SQRT_2],
        );
        let a = pose([330.0, 280.0, 0.0], SEAM_Q);
        let b = Isometry3::from_parts(
            Translation3::new(480.0, 780.0, 30.0),
            a.rotation * turned([0.0, 1.0, 0.0], 40.0),
        );
        for path in [
            CartesianPath::line(&a, &b).expect("line"),
            CartesianPath::arc(&a, &Point3::new(373.934, 736.066, 0.0), &b).expect("arc"),
        ] {
            let moved = path.transformed(&frame);
            for k in 0..=10 {
                let s = k as f64 / 10.0;
                let (x, y) = (moved.pose_at(s), frame * path.pose_at(s));
                assert!((x.translation.vector - y.translation.vector).norm() < 1e-9);
                assert!(angle_deg(&x.rotation, &y.rotation) < 1e-9);
            }
            assert!((moved.length_mm() - path.length_mm()).abs() < 1e-9);
        }
    }
}
