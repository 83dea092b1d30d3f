//! The TCP paths of `MoveL` and `MoveC` as the module's contract states the controller runs
//! them, computed here on their own (not `geometry`): the position on the straight line, or on
//! the circle through the start, the circle point and the end, traversed through the circle
//! point, at progress `s` in 0 .. 1 (the arc's angle, so the TCP at even speed); the orientation
//! turned from start to end about one fixed axis by the shorter way (slerp), by the same
//! progress. The circle point's orientation and confdata play no part.
//!
//! Refused, as the contract refuses them: an arc whose circle point lies within 0.5 mm of the
//! chord or of either end (no circle to speak of), an arc over 240 deg, and an orientation
//! change within 0.1 deg of a half turn (the shorter way is then ambiguous).

use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};

/// The circle point's least distance from the chord and from each end, mm.
pub const ARC_MIN_OFFSET_MM: f64 = 0.5;
/// The largest arc, deg.
pub const ARC_MAX_DEG: f64 = 240.0;
/// The largest orientation change, deg (a half turn less this margin).
pub const TURN_MAX_DEG: f64 = 179.9;

#[derive(Clone, Debug)]
enum Shape {
    Line {
        from: Point3<f64>,
        to: Point3<f64>,
    },
    Arc {
        centre: Point3<f64>,
        radius: f64,
        /// Unit vectors in the circle's plane: towards the start, and a quarter turn on in the
        /// direction of travel.
        u: Vector3<f64>,
        w: Vector3<f64>,
        /// The arc's angle, rad.
        angle: f64,
    },
}

/// A TCP path with its orientation (poses of the TCP, one frame throughout).
#[derive(Clone, Debug)]
pub struct TcpPath {
    shape: Shape,
    start: UnitQuaternion<f64>,
    /// The turn from start to end: its axis (in the path's frame) and angle (rad, 0 .. pi).
    axis: Unit<Vector3<f64>>,
    turn: f64,
}

impl TcpPath {
    /// MoveL from `from` to `to`.
    pub fn line(from: &Isometry3<f64>, to: &Isometry3<f64>) -> Result<TcpPath, String> {
        TcpPath::with_shape(
            Shape::Line {
                from: from.translation.vector.into(),
                to: to.translation.vector.into(),
            },
            from,
            to,
        )
    }

    /// MoveC from `from` through `circle` (a position) to `to`.
    pub fn arc(
        from: &Isometry3<f64>,
        circle: &Point3<f64>,
        to: &Isometry3<f64>,
    ) -> Result<TcpPath, String> {
        let (a, b, c): (Point3<f64>, Point3<f64>, Point3<f64>) = (
            from.translation.vector.into(),
            *circle,
            to.translation.vector.into(),
        );
        let chord = c - a;
        let off_chord = (b - a).cross(&chord).norm() / chord.norm();
        if chord.norm() < ARC_MIN_OFFSET_MM
            || off_chord < ARC_MIN_OFFSET_MM
            || (b - a).norm() < ARC_MIN_OFFSET_MM
            || (c - b).norm() < ARC_MIN_OFFSET_MM
        {
            return Err(format!(
                "the circle point lies {off_chord:.3} mm off the chord, {:.3} mm from the start and {:.3} mm from the end (at least {ARC_MIN_OFFSET_MM} mm each): no arc",
                (b - a).norm(),
                (c - b).norm()
            ));
        }
        // The circumcentre of a, b, c.
        let (ab, ac) = (b - a, c - a);
        let n = ab.cross(&ac);
        let centre = a
            + (ac.norm_squared() * n.cross(&ab) + ab.norm_squared() * ac.cross(&n))
                / (2.0 * n.norm_squared());
        let radius = (a - centre).norm();
        let u = (a - centre) / radius;
        let angle_of = |p: &Point3<f64>, w: &Vector3<f64>| {
            let d = p - centre;
            let t = d.dot(w).atan2(d.dot(&u));
            if t < 0.0 {
                t + std::f64::consts::TAU
            } else {
                t
            }
        };
        // Travel about the normal that meets the circle point before the end.
        let mut w = n.normalize().cross(&u);
        if angle_of(&b, &w) > angle_of(&c, &w) {
            w = -w;
        }
        let angle = angle_of(&c, &w);
        if angle.to_degrees() > ARC_MAX_DEG {
            return Err(format!(
                "the arc turns {:.1} deg, more than {ARC_MAX_DEG} deg",
                angle.to_degrees()
            ));
        }
        TcpPath::with_shape(
            Shape::Arc {
                centre,
                radius,
                u,
                w,
                angle,
            },
            from,
            to,
        )
    }

    fn with_shape(
        shape: Shape,
        from: &Isometry3<f64>,
        to: &Isometry3<f64>,
    ) -> Result<TcpPath, String> {
        let delta = from.rotation.inverse() * to.rotation;
        let turn = delta.angle();
        if turn.to_degrees() > TURN_MAX_DEG {
            return Err(format!(
                "the orientation turns {:.2} deg from start to end: within {:.1} deg of a half turn, the way is ambiguous",
                turn.to_degrees(),
                180.0 - TURN_MAX_DEG
            ));
        }
        let axis = delta.axis().unwrap_or_else(Vector3::x_axis);
        Ok(TcpPath {
            shape,
            start: from.rotation,
            axis,
            turn,
        })
    }

    /// The TCP pose at progress `s` (0 .. 1).
    pub fn at(&self, s: f64) -> Isometry3<f64> {
        let p = match &self.shape {
            Shape::Line { from, to } => from + s * (to - from),
            Shape::Arc {
                centre,
                radius,
                u,
                w,
                angle,
            } => {
                let (sin, cos) = (s * angle).sin_cos();
                centre + *radius * (cos * u + sin * w)
            }
        };
        let rot = self.start * UnitQuaternion::from_axis_angle(&self.axis, s * self.turn);
        Isometry3::from_parts(Translation3::from(p.coords), rot)
    }

    /// The progress at which an arc passes `p` (a point of its circle: its angle from the start
    /// about the centre over the arc's angle); `None` for a line or a point beyond the arc.
    pub fn progress_at(&self, p: &Point3<f64>) -> Option<f64> {
        let Shape::Arc {
            centre,
            u,
            w,
            angle,
            ..
        } = &self.shape
        else {
            return None;
        };
        let d = p - centre;
        let t = d.dot(w).atan2(d.dot(u)).rem_euclid(std::f64::consts::TAU);
        (t <= *angle).then_some(t / angle)
    }

    /// The TCP's path length, mm.
    pub fn length_mm(&self) -> f64 {
        match &self.shape {
            Shape::Line { from, to } => (to - from).norm(),
            Shape::Arc { radius, angle, .. } => radius * angle,
        }
    }

    /// The orientation's turn from start to end, deg.
    pub fn turn_deg(&self) -> f64 {
        self.turn.to_degrees()
    }

    /// An arc's radius (mm) and angle (deg); `None` for a line.
    pub fn radius_and_angle(&self) -> Option<(f64, f64)> {
        match &self.shape {
            Shape::Arc { radius, angle, .. } => Some((*radius, angle.to_degrees())),
            Shape::Line { .. } => None,
        }
    }
}
