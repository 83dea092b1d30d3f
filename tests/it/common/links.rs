//! The robot's collision geometry as the dense check reads it from the URDF itself (urdf-rs), not
//! through the library's reader: every `<collision>` of every link, whichever link carries it
//! (the library keeps the cylinders of links 1..3 and ignores the rest; a shape on the wrist or
//! on `tool0` is measured here all the same), as a parry3d shape: a cylinder or capsule (along
//! its local z axis), a box, a sphere. A mesh is refused: this check has no shape for it.
//!
//! Each shape is placed in the frame of the link moved by the nearest revolute joint above it
//! (the fixed joints in between folded in), so the robot's forward kinematics
//! (`Robot::link_poses`, which `robot`'s tests hold against RobotStudio) carry it; a shape above
//! every revolute joint stands still with the robot's base. URDF metres become mm here, once.

use super::library::Robot;
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use parry3d::math::{Pose, Rotation, Vector};
use parry3d::shape::{Ball, Capsule, Cuboid, Cylinder, Shape};
use std::path::Path;

/// One collision shape of the robot.
pub struct LinkShape {
    /// The link that carries it in the URDF, and the collision's name (or its index).
    pub link: String,
    pub name: String,
    /// The revolute joint (index in `Robot::joints`) whose child link frame carries it; `None`:
    /// the robot's base.
    pub carrier: Option<usize>,
    /// The shape's pose in that frame (parry's axis y along the URDF's local z for cylinders
    /// and capsules), mm.
    pub in_frame: Isometry3<f64>,
    pub shape: Box<dyn Shape>,
    /// How far any point of the shape lies from that frame's origin, mm.
    pub extent_mm: f64,
}

/// A pose as parry3d takes it.
pub fn to_pose(iso: &Isometry3<f64>) -> Pose {
    let (t, q) = (iso.translation.vector, iso.rotation.quaternion());
    Pose::from_parts(
        Vector::new(t.x, t.y, t.z),
        Rotation::from_xyzw(q.i, q.j, q.k, q.w),
    )
}

/// A URDF pose (metres, roll-pitch-yaw: `Rz(yaw) Ry(pitch) Rx(roll)`) in mm.
fn pose(p: &urdf_rs::Pose) -> Isometry3<f64> {
    let (xyz, rpy) = (p.xyz.0, p.rpy.0);
    Isometry3::from_parts(
        Translation3::new(1e3 * xyz[0], 1e3 * xyz[1], 1e3 * xyz[2]),
        UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2]),
    )
}

/// The collision shapes of `robot`'s URDF (module doc), or why they cannot be read. A robot of
/// `robot.model` is built into the binary from its file in the repository's `robots/`, and names
/// only the file: it is read there.
pub fn read(robot: &Robot) -> Result<Vec<LinkShape>, String> {
    let path = &robot.urdf_path;
    match (path.exists(), path.file_name()) {
        (false, Some(name)) => read_file(&super::root().join("robots").join(name), robot),
        _ => read_file(path, robot),
    }
}

/// The same from the URDF at `path`, carried by `robot`'s revolute joints.
pub fn read_file(path: &Path, robot: &Robot) -> Result<Vec<LinkShape>, String> {
    let urdf = urdf_rs::read_file(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut out = Vec::new();
    for link in &urdf.links {
        if link.collision.is_empty() {
            continue;
        }
        // Up the tree to the link a revolute joint moves, folding in the fixed joints.
        let (mut name, mut above) = (link.name.as_str(), Isometry3::identity());
        let carrier = loop {
            if let Some(k) = robot.joints.iter().position(|j| j.child_link == name) {
                break Some(k);
            }
            match urdf.joints.iter().find(|j| j.child.link == name) {
                None => break None,
                Some(j) if matches!(j.joint_type, urdf_rs::JointType::Fixed) => {
                    above = pose(&j.origin) * above;
                    name = j.parent.link.as_str();
                }
                Some(j) => {
                    return Err(format!(
                        "link '{}' hangs below joint '{}', which is not one of the robot's six",
                        link.name, j.name
                    ))
                }
            }
        };
        for (i, col) in link.collision.iter().enumerate() {
            let along_z =
                UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2);
            let (turn, shape): (UnitQuaternion<f64>, Box<dyn Shape>) = match &col.geometry {
                urdf_rs::Geometry::Cylinder { radius, length } => {
                    (along_z, Box::new(Cylinder::new(5e2 * length, 1e3 * radius)))
                }
                urdf_rs::Geometry::Capsule { radius, length } => (
                    along_z,
                    Box::new(Capsule::new_y(5e2 * length, 1e3 * radius)),
                ),
                urdf_rs::Geometry::Box { size } => (
                    UnitQuaternion::identity(),
                    Box::new(Cuboid::new(Vector::new(
                        5e2 * size.0[0],
                        5e2 * size.0[1],
                        5e2 * size.0[2],
                    ))),
                ),
                urdf_rs::Geometry::Sphere { radius } => (
                    UnitQuaternion::identity(),
                    Box::new(Ball::new(1e3 * radius)),
                ),
                urdf_rs::Geometry::Mesh { filename, .. } => {
                    return Err(format!(
                    "link '{}': a mesh collision ({filename}); this check measures primitives only",
                    link.name
                ))
                }
            };
            let in_frame =
                above * pose(&col.origin) * Isometry3::from_parts(Translation3::identity(), turn);
            let sphere = shape.compute_local_bounding_sphere();
            let c = sphere.center();
            let extent_mm = (in_frame * Point3::new(c.x, c.y, c.z)).coords.norm() + sphere.radius();
            out.push(LinkShape {
                link: link.name.clone(),
                name: col.name.clone().unwrap_or_else(|| format!("collision {i}")),
                carrier,
                in_frame,
                shape,
                extent_mm,
            });
        }
    }
    Ok(out)
}
