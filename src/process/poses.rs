//! The approach and retract poses of a robtarget point (follow stage): `RelTool` of its
//! robtarget where the controller reaches the pose in the point's configuration, else a
//! robtarget of its own (`OwnTarget`: `<point>_app`, `<point>_ret`) in the configuration the
//! line reaches it in, its position rounded as the module writes it (module docs of
//! `process`, "The joints at a stop").

use super::{process_move, ProcessError, ProcessMove, Setting};
use crate::cell::{Frame, Point};
use crate::collision::CollisionModel;
use crate::geometry::path::{rel_tool, CartesianPath};
use crate::refine::{MoveKind, OwnTarget};
use crate::robot::ik::follow::{follow as follow_path, FollowError};
use crate::robot::ik::six::ConfData;
use crate::robot::Axes6;
use nalgebra::Isometry3;

/// A robtarget as the module writes it: its numbers (in the frame of the point's robtargets)
/// and its confdata.
#[derive(Clone, Copy, Debug)]
pub(super) struct Written {
    pub(super) data: Frame,
    pub(super) conf: ConfData,
}

/// `RelTool(p, 0, 0, -d)` of robtarget numbers `p`, as its own robtarget writes it (the
/// position rounded, the orientation `p`'s).
fn rel_tool_data(p: &Frame, d: f64) -> Frame {
    let moved = rel_tool(&p.isometry(), 0.0, 0.0, -d).translation.vector;
    Frame {
        pos_mm: [moved.x, moved.y, moved.z],
        quat_wxyz: p.quat_wxyz,
    }
    .written()
}

/// Point `p`'s approach pose, `d` back along its tool's z axis from `target` (the point's pose
/// as written, cell frame), and the joints `MoveJ` reaches there (module docs): in the point's
/// configuration, `RelTool` of its robtarget; where the approach line from the point's joints
/// `at` (followed backwards) reaches it in another configuration, its own robtarget (the
/// position rounded as written) in that configuration, returned as `OwnTarget`.
pub(super) fn approach_pose(
    s: &Setting,
    p: &Point,
    point: &Written,
    target: &Isometry3<f64>,
    at: &Axes6,
    d: f64,
) -> Result<(Isometry3<f64>, Axes6, Option<OwnTarget>), ProcessError> {
    let app = rel_tool(target, 0.0, 0.0, -d);
    if let Some(joints) = s.joints_in(&app, point.conf, at) {
        return Ok((app, joints, None));
    }
    let refused = |why: String| ProcessError::Pose {
        label: p.label(),
        what: "the approach pose",
        why,
        loc: p.approach_loc,
    };
    let data = rel_tool_data(&point.data, d);
    let own = s.in_cell(&data, p.wobj);
    // The approach line run backwards from the point: the configuration the approach pose is
    // reached in when the line into the point continues to the point's joints.
    let back = CartesianPath::line(target, &own)
        .map_err(|e| refused(e.to_string()))
        .and_then(|path| {
            follow_path(&s.ik, &s.frames, &path, at, None).map_err(|e| {
                refused(format!(
                    "RelTool({}, 0, 0, -{d}) has no solution in range in the point's configuration {}, and the line from the point cannot be followed to it: {e}",
                    p.name, point.conf
                ))
            })
        })?;
    let conf = back.end_conf();
    let joints = s.joints_in(&own, conf, &back.end_joints()).ok_or_else(|| {
        refused(format!(
            "its own robtarget {}_app has no solution in range in configuration {conf}",
            p.name
        ))
    })?;
    Ok((own, joints, Some(OwnTarget { pose: data, conf })))
}

/// Point `p`'s retract line from `target` (its pose as written, cell frame; joints `at`), `d`
/// back along its tool's z axis: to `RelTool` of its robtarget where the line ends in the
/// point's configuration, else to its own robtarget (the position rounded as written) in the
/// configuration the line ends in (module docs).
#[allow(clippy::too_many_arguments)]
pub(super) fn retract_line(
    s: &Setting,
    model: &CollisionModel,
    p: &Point,
    speed: &str,
    point: &Written,
    target: &Isometry3<f64>,
    at: &Axes6,
    d: f64,
) -> Result<ProcessMove, ProcessError> {
    let ret = rel_tool(target, 0.0, 0.0, -d);
    let kind = MoveKind::Retract {
        dz_mm: d,
        own: None,
    };
    match process_move(
        s,
        model,
        p,
        speed,
        kind,
        target,
        &ret,
        None,
        at,
        Some(point.conf),
    ) {
        Err(ProcessError::Follow { source, .. })
            if matches!(*source, FollowError::EndConf { .. }) =>
        {
            let data = rel_tool_data(&point.data, d);
            let mut m = process_move(
                s,
                model,
                p,
                speed,
                kind,
                target,
                &s.in_cell(&data, p.wobj),
                None,
                at,
                None,
            )?;
            m.kind = MoveKind::Retract {
                dz_mm: d,
                own: Some(OwnTarget {
                    pose: data,
                    conf: m.followed.end_conf(),
                }),
            };
            Ok(m)
        }
        other => other,
    }
}
