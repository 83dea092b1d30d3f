//! The URDF adapter: urdf-rs types -> [`Robot`]. The only place that reads URDF, and the only
//! place where metres and radians become millimetres and degrees.
//!
//! What it accepts: one serial chain from the root link through exactly six revolute (or
//! continuous) joints; fixed joints anywhere in the chain are folded into the next joint's origin;
//! a fixed child named `tool0` after joint 6 (required: the flange is never guessed) gives the
//! tool0 frame and ends the chain (joints
//! below tool0 belong to a tool and are ignored; a 7th revolute joint before it is refused:
//! gen-rapid plans six-axis arms). Each child link of joints 1..3 must carry
//! collision geometry (the paper's lumped model); the root link (base_link) and links 4..6 may
//! (beyond the paper: `lumped.rs` carries them); every collision geometry is a cylinder. Every
//! number the chain uses must be finite, lengths within 1 km, axis ranges within two turns each
//! way.

use super::controller::{self, AxisSpec, Controller, Coupling};
use super::{LinkFrame, OwnCylinder, RevoluteJoint, Robot, RobotError};
use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};
use std::path::Path;

const MM_PER_M: f64 = 1000.0;

/// The largest length a URDF may give (m): 1 km, as a cell's numbers
/// ([`crate::input::MAX_MAGNITUDE`] mm).
const MAX_LENGTH_M: f64 = crate::input::MAX_MAGNITUDE / MM_PER_M;

/// Why the numbers of an `<origin>` cannot be used, if they cannot: NaN or
/// infinite, or a length beyond [`MAX_LENGTH_M`].
fn pose_fault(p: &urdf_rs::Pose) -> Option<String> {
    let (xyz, rpy) = (*p.xyz, *p.rpy);
    if !xyz.iter().chain(rpy.iter()).all(|v| v.is_finite()) {
        return Some("its <origin> must hold finite numbers".into());
    }
    xyz.iter().find(|v| v.abs() > MAX_LENGTH_M).map(|v| {
        format!(
            "its <origin> xyz {} m is beyond {MAX_LENGTH_M} m",
            crate::excerpt::number(*v)
        )
    })
}

fn pose_mm(p: &urdf_rs::Pose) -> Isometry3<f64> {
    let [x, y, z] = *p.xyz;
    let [roll, pitch, yaw] = *p.rpy;
    Isometry3::from_parts(
        Translation3::new(x * MM_PER_M, y * MM_PER_M, z * MM_PER_M),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    )
}

/// Builds a [`Robot`] from URDF text and an optional controller file `(path, text)`.
pub fn robot_from_urdf(
    path: &Path,
    text: &str,
    controller_file: Option<(&Path, &str)>,
) -> Result<Robot, RobotError> {
    let model_err = |message: String| RobotError::Model {
        path: path.to_path_buf(),
        message,
    };
    if let Some(line) = super::xml_depth::too_deep(text) {
        return Err(RobotError::ParseUrdf {
            path: path.to_path_buf(),
            message: format!(
                "its elements nest more than {} deep (line {line}); a URDF nests a few levels",
                super::xml_depth::MAX_DEPTH
            ),
        });
    }
    let urdf = urdf_rs::read_from_string(text).map_err(|e| RobotError::ParseUrdf {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;

    // The root: the one link that is no joint's child.
    let roots: Vec<&urdf_rs::Link> = urdf
        .links
        .iter()
        .filter(|l| !urdf.joints.iter().any(|j| j.child.link == l.name))
        .collect();
    let root = match roots.as_slice() {
        [r] => r.name.clone(),
        [] => {
            return Err(model_err(
                "no root link (every link is some joint's child)".into(),
            ))
        }
        _ => {
            let names: Vec<&str> = roots.iter().map(|l| l.name.as_str()).collect();
            return Err(model_err(format!(
                "several root links: {}",
                names.join(", ")
            )));
        }
    };

    let mut joints = Vec::new();
    let mut pending = Isometry3::identity(); // fixed joints since the last revolute one
    let mut flange_to_tool0 = Isometry3::identity();
    let mut found_tool0 = false;
    let root_name = root.clone();
    let mut link = root;
    let mut visited = std::collections::HashSet::new();
    loop {
        // A loop of joints (a link its own descendant) would walk for ever.
        if !visited.insert(link.clone()) {
            return Err(model_err(format!(
                "link '{link}' is reached twice along the chain (the joints form a loop); gen-rapid needs one serial chain"
            )));
        }
        // Joint 6's own child named tool0 is the flange frame; what hangs below it is the tool's.
        if joints.len() == 6 && link == "tool0" {
            found_tool0 = true;
            break;
        }
        let children: Vec<&urdf_rs::Joint> = urdf
            .joints
            .iter()
            .filter(|j| j.parent.link == link)
            .collect();
        let next = match children.as_slice() {
            [] => break,
            [j] => *j,
            _ if joints.len() == 6 => {
                // Branches after the flange (tool frames, sensors): only tool0 matters.
                match children.iter().find(|j| j.child.link == "tool0") {
                    Some(j) => *j,
                    None => break,
                }
            }
            _ => {
                let names: Vec<&str> = children.iter().map(|j| j.name.as_str()).collect();
                return Err(model_err(format!(
                    "link '{link}' has several child joints ({}); gen-rapid needs one serial chain",
                    names.join(", ")
                )));
            }
        };
        if let Some(fault) = pose_fault(&next.origin) {
            return Err(model_err(format!("joint '{}': {fault}", next.name)));
        }
        match next.joint_type {
            urdf_rs::JointType::Revolute | urdf_rs::JointType::Continuous if joints.len() < 6 => {
                if !next.axis.xyz.iter().all(|v| v.is_finite()) {
                    return Err(model_err(format!(
                        "joint '{}': its <axis> must hold finite numbers",
                        next.name
                    )));
                }
                let axis = Vector3::from(*next.axis.xyz);
                let axis = Unit::try_new(axis, 1e-9)
                    .ok_or_else(|| model_err(format!("joint '{}' has a zero axis", next.name)))?;
                joints.push((next, pending * pose_mm(&next.origin), axis));
                pending = Isometry3::identity();
            }
            urdf_rs::JointType::Fixed => {
                pending *= pose_mm(&next.origin);
                if joints.len() == 6 && next.child.link == "tool0" {
                    flange_to_tool0 = pending;
                    found_tool0 = true;
                    // What hangs below tool0 (a spindle, a gripper's fingers) is the tool's,
                    // which the cell's `tool:` describes: the arm's chain ends here.
                    break;
                }
            }
            urdf_rs::JointType::Revolute | urdf_rs::JointType::Continuous => {
                return Err(model_err(format!(
                    "joint '{}' is a 7th revolute joint in the chain after joint 6 ('{}'); gen-rapid plans six-axis arms",
                    next.name,
                    joints.last().map_or("", |(j, _, _)| j.name.as_str())
                )))
            }
            _ if joints.len() == 6 => break,
            _ => {
                return Err(model_err(format!(
                    "joint '{}' is {:?}; gen-rapid handles revolute joints only",
                    next.name, next.joint_type
                )))
            }
        }
        link = next.child.link.clone();
    }
    if joints.len() != 6 {
        return Err(model_err(format!(
            "the chain from the root has {} revolute joints; gen-rapid needs 6",
            joints.len()
        )));
    }
    // The flange is the link named tool0 (the ROS-Industrial convention; RAPID's tool0 is the
    // flange): the last link is not taken in its stead, its frame may be turned or offset.
    if !found_tool0 {
        let elsewhere = if urdf.links.iter().any(|l| l.name == "tool0") {
            "; a link named tool0 is in the URDF, but not fixed below joint 6"
        } else {
            ""
        };
        return Err(model_err(format!(
            "no link named tool0 below joint 6 ('{}'): the chain ends at link '{}'{elsewhere}; gen-rapid takes the flange as the link tool0, fixed to joint 6's link, and would not guess it",
            joints.last().map_or("", |(j, _, _)| j.name.as_str()),
            crate::excerpt::value(&link)
        )));
    }

    // The root's cylinders (optional), then each child link's: links 1..3 must carry some.
    let mut collision = cylinders_of(&urdf, &root_name, LinkFrame::Base).map_err(model_err)?;
    for (index, (joint, _, _)) in joints.iter().enumerate() {
        let own =
            cylinders_of(&urdf, &joint.child.link, LinkFrame::Child(index)).map_err(model_err)?;
        if own.is_empty() && index < 3 {
            return Err(model_err(format!(
                "link '{}' (moved by joint {}, '{}') carries no <collision> cylinder: gen-rapid could not check its moves (the paper's model lumps the arm into its first three links, each a cylinder)",
                joint.child.link,
                index + 1,
                joint.name
            )));
        }
        collision.extend(own);
    }

    let controller = match controller_file {
        Some((cpath, ctext)) => {
            let mut c = controller::parse(ctext).map_err(|f| RobotError::Controller {
                path: cpath.to_path_buf(),
                message: f.message,
                line: f.line,
                column: f.column,
                line_text: crate::excerpt::nth_line(ctext, f.line).map(str::to_string),
            })?;
            c.source = Some(cpath.to_path_buf());
            c
        }
        None => serial_controller(&joints.iter().map(|(j, _, _)| *j).collect::<Vec<_>>())
            .map_err(model_err)?,
    };

    let joints: Vec<RevoluteJoint> = joints
        .into_iter()
        .map(|(j, origin, axis)| RevoluteJoint {
            name: j.name.clone(),
            child_link: j.child.link.clone(),
            origin,
            axis,
        })
        .collect();
    let (cylinders, flange_parts) = super::lumped::lump(&joints, &collision);
    Ok(Robot {
        name: urdf.name.clone(),
        urdf_path: path.to_path_buf(),
        model: None,
        joints,
        flange_to_tool0,
        cylinders,
        flange_parts,
        collision,
        controller,
    })
}

/// The collision cylinders of the link named `name` (none when it has no `<collision>`), in
/// the link's frame, mm; the message says what is wrong with one that cannot be used.
fn cylinders_of(
    urdf: &urdf_rs::Robot,
    name: &str,
    frame: LinkFrame,
) -> Result<Vec<OwnCylinder>, String> {
    let Some(l) = urdf.links.iter().find(|l| l.name == name) else {
        return Err(format!("link '{name}' is not defined"));
    };
    let mut out = Vec::new();
    for c in &l.collision {
        let urdf_rs::Geometry::Cylinder { radius, length } = c.geometry else {
            return Err(format!(
                "link '{}': collision geometry must be a cylinder (gen-rapid carries every link as cylinders)",
                l.name
            ));
        };
        if !(radius > 0.0 && length > 0.0) {
            return Err(format!(
                "link '{}': cylinder radius and length must be positive",
                l.name
            ));
        }
        if radius > MAX_LENGTH_M || length > MAX_LENGTH_M {
            return Err(format!(
                "link '{}': cylinder radius and length must be at most {MAX_LENGTH_M} m",
                l.name
            ));
        }
        if let Some(fault) = pose_fault(&c.origin) {
            return Err(format!("link '{}' <collision>: {fault}", l.name));
        }
        // URDF cylinders are centred on their origin, axis along local z.
        let pose = pose_mm(&c.origin);
        let half = length * MM_PER_M / 2.0;
        out.push(OwnCylinder {
            link: l.name.clone(),
            frame,
            a: pose * Point3::new(0.0, 0.0, -half),
            b: pose * Point3::new(0.0, 0.0, half),
            radius_mm: radius * MM_PER_M,
        });
    }
    Ok(out)
}

/// A serial convention from the URDF's own limits and velocities.
fn serial_controller(joints: &[&urdf_rs::Joint]) -> Result<Controller, String> {
    let mut axes = [AxisSpec::UNSET; 6];
    for (a, j) in axes.iter_mut().zip(joints) {
        let (lo, hi) = if j.joint_type == urdf_rs::JointType::Continuous {
            (-180.0, 180.0)
        } else {
            (j.limit.lower.to_degrees(), j.limit.upper.to_degrees())
        };
        // Written so that NaN fails too.
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
            return Err(format!("joint '{}' needs <limit lower < upper>", j.name));
        }
        if let Some(fault) = controller::range_fault(lo, hi) {
            return Err(format!("joint '{}' <limit>: {fault}", j.name));
        }
        if j.limit.velocity.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return Err(format!(
                "joint '{}' needs a positive <limit velocity> (or a controller file beside the URDF)",
                j.name
            ));
        }
        let speed = j.limit.velocity.to_degrees();
        let fault = controller::rate_fault(
            speed,
            controller::AXIS_SPEED_DEG_S,
            "<limit velocity>",
            "deg/s",
        );
        if let Some(fault) = fault {
            return Err(format!("joint '{}': {fault}", j.name));
        }
        *a = AxisSpec {
            min_deg: lo,
            max_deg: hi,
            speed_deg_s: j.limit.velocity.to_degrees(),
            acceleration_deg_s2: None,
        };
    }
    Ok(Controller {
        coupling: Coupling::Serial,
        axes,
        coupled_axis3_deg: None,
        source: None,
    })
}
