//! The module's robtargets, tool and work object, checked as the controller would read them,
//! independently of the library's inverse kinematics: for every robtarget point, the forward
//! kinematics of its written jointtarget, carried through the written tooldata's tframe and
//! expressed in the written wobjdata's user frame (robot base at the header's placement), must
//! give the written robtarget within 0.1 mm and 0.01 deg; the written robtarget must
//! be the cell's pose (as given, normalised) and its confdata that of the jointtarget, computed
//! here from the RAPID definition (and the cell's, when it gives one). Also the motion of every
//! move: the tool and work object the cell names, the point's speed and zone (the cell's
//! `motion` by default), and for a via the speed of its leg's end point and `motion.via_zone`;
//! any zone may be `fine` instead (a corner not proven), the first and last always are.

use super::data::check_declarations;
use super::library::{Cell, Robot, Target};
use super::module::Module;
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};

/// The written joint values must reach the robtarget within these.
pub const TCP_TOL_MM: f64 = 0.1;
pub const TCP_TOL_DEG: f64 = 0.01;

/// What [`check_tcp`] measured.
#[derive(Clone, Copy, Debug, Default)]
pub struct TcpReport {
    /// Robtarget points checked.
    pub points: usize,
    /// The largest position and angle error found.
    pub worst_mm: f64,
    pub worst_deg: f64,
}

fn iso(v: &[f64; 7]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(v[0], v[1], v[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(v[3], v[4], v[5], v[6])),
    )
}

/// `[cf1, cf4, cf6, cfx]` of controller values, from the RAPID reference's definition
/// (docs/rapid.md, docs/irb1400.md): the quarter turns of axes 1, 4 and 6; cfx = 4 (wrist centre
/// behind axis 1) + 2 (behind the lower arm) + 1 (axis 5 negative). "Behind axis 1": against
/// the arm's forward direction (+x of the base turned by axis 1); "behind the lower arm": on the
/// other side of the line axis 2 -> axis 3 than at the zero pose.
pub fn confdata(robot: &Robot, a: &[f64; 6]) -> [i32; 4] {
    let quadrant = |v: f64| (v / 90.0).floor() as i32;
    let side = |a: &[f64; 6]| {
        let poses = robot.link_poses(a);
        let shoulder = Point3::from(poses[1].translation.vector);
        let elbow = Point3::from(poses[2].translation.vector);
        let u2 = poses[1].rotation * robot.joints[1].axis.into_inner();
        let w = robot.wrist_centre(a);
        u2.dot(&(elbow - shoulder).cross(&(w - shoulder)))
    };
    let w = robot.wrist_centre(a);
    let forward = Vector3::new(a[0].to_radians().cos(), a[0].to_radians().sin(), 0.0);
    let behind_axis1 = forward.dot(&w.coords) < 0.0;
    let behind_lower_arm = side(a) * side(&[0.0; 6]) < 0.0;
    let cfx = 4 * i32::from(behind_axis1) + 2 * i32::from(behind_lower_arm) + i32::from(a[4] < 0.0);
    [quadrant(a[0]), quadrant(a[3]), quadrant(a[5]), cfx]
}

/// Checks the robtargets, tooldata, wobjdata and moves of `module` against `cell` (module doc);
/// `cell_from_robot` is the header's placement.
pub fn check_tcp(
    cell: &Cell,
    robot: &Robot,
    module: &Module,
    cell_from_robot: &Isometry3<f64>,
) -> Result<TcpReport, Vec<String>> {
    let mut failures = Vec::new();
    let mut fail = |m: String| failures.push(m);
    let mut report = TcpReport::default();

    // The declarations: what the cell says, no more (`data.rs`).
    for m in check_declarations(cell, module, cell_from_robot) {
        fail(m);
    }
    let tool_name = cell.tool.as_ref().map(|t| t.name.clone());
    let tframe = match module.tooldata.as_slice() {
        [(_, d)] => iso(&d.tframe),
        _ => Isometry3::identity(),
    };
    let uframe = match module.wobjdata.as_slice() {
        [(_, u)] => iso(u),
        _ => Isometry3::identity(),
    };

    // The moves: the tool and work object, the speed and zone of the move into each target.
    let tool = tool_name.unwrap_or_else(|| cell.motion.tool.clone());
    let wobj = cell.wobjs.first().map(|w| w.name.clone());
    let mut next_point = 0;
    for m in &module.move_args {
        if m.tool != tool || m.wobj != wobj {
            fail(format!(
                "MoveAbsJ {} uses {}{:?}, the cell names {tool}{wobj:?}",
                m.target, m.tool, m.wobj
            ));
        }
        let Some(p) = cell.points.get(next_point) else {
            fail(format!("MoveAbsJ {} after the last cell point", m.target));
            break;
        };
        let speed = p.speed.clone().unwrap_or_else(|| cell.motion.speed.clone());
        // The zone asked for, or `fine` where its corner was not proven (the dense
        // check samples every corner written with a fly-by zone), and `fine` at the ends.
        let asked = match m.target == p.name {
            true => p.zone.clone().unwrap_or_else(|| cell.motion.zone.clone()),
            false => cell.motion.via_zone.clone(),
        };
        let at_end = std::ptr::eq(m, &module.move_args[0])
            || std::ptr::eq(m, &module.move_args[module.move_args.len() - 1]);
        let zone_ok = match at_end {
            true => m.zone == "fine",
            false => m.zone == asked || m.zone == "fine",
        };
        if m.speed != speed || !zone_ok {
            fail(format!(
                "MoveAbsJ {} with {}, {}: expected {speed}, {asked} (or fine)",
                m.target, m.speed, m.zone
            ));
        }
        if m.target == p.name {
            next_point += 1;
        }
    }

    // Every robtarget point: written beside its jointtarget, reached by it.
    for p in &cell.points {
        let Target::Robtarget { pose, conf } = &p.target else {
            if module
                .robtargets
                .iter()
                .any(|(n, _)| n.eq_ignore_ascii_case(&format!("{}_rt", p.name)))
            {
                fail(format!("point {} is no robtarget but has one", p.name));
            }
            continue;
        };
        let name = format!("{}_rt", p.name);
        let Some((_, r)) = module.robtargets.iter().find(|(n, _)| *n == name) else {
            fail(format!(
                "robtarget point {} has no CONST robtarget {name}",
                p.name
            ));
            continue;
        };
        let Some((_, axes)) = module.targets.iter().find(|(n, _)| *n == p.name) else {
            continue; // reported by the dense check
        };
        let written = [r.pos_mm.as_slice(), r.quat_wxyz.as_slice()].concat();
        let given = [pose.pos_mm.as_slice(), pose.quat_wxyz.as_slice()].concat();
        if given
            .iter()
            .zip(&written)
            .any(|(a, b)| (a - b).abs() > 1e-9 + 5e-10)
        {
            fail(format!(
                "{name} is {written:?}, the cell says {given:?} (normalised)"
            ));
        }
        // As the controller reads it: the TCP of the jointtarget, in the work object.
        let tcp = uframe.inverse() * cell_from_robot * robot.tool0(axes) * tframe;
        let target = iso(&[
            r.pos_mm[0],
            r.pos_mm[1],
            r.pos_mm[2],
            r.quat_wxyz[0],
            r.quat_wxyz[1],
            r.quat_wxyz[2],
            r.quat_wxyz[3],
        ]);
        let mm = (tcp.translation.vector - target.translation.vector).norm();
        let deg = tcp.rotation.angle_to(&target.rotation).to_degrees();
        report.points += 1;
        report.worst_mm = report.worst_mm.max(mm);
        report.worst_deg = report.worst_deg.max(deg);
        if mm > TCP_TOL_MM || deg > TCP_TOL_DEG {
            fail(format!(
                "point {}: its jointtarget {axes:?} puts the TCP {mm:.4} mm and {deg:.5} deg from {name}",
                p.name
            ));
        }
        // Admitted within half the written step of a quadrant bound: the joints are the exact
        // inverse of the robtarget, which may lie on a bound.
        let computed = confdata(robot, axes);
        if !super::opw::conf_admits(axes, computed[3], &r.conf) {
            fail(format!(
                "{name} has confdata {:?}, its jointtarget's is {computed:?}",
                r.conf
            ));
        }
        if let Some(c) = conf {
            if c.to_array() != r.conf {
                fail(format!(
                    "{name} has confdata {:?}, the cell asks {:?}",
                    r.conf,
                    c.to_array()
                ));
            }
        }
    }
    match failures.is_empty() {
        true => Ok(report),
        false => Err(failures),
    }
}
