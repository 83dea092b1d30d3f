//! The module's data declarations against the cell: the `PERS tooldata` of the cell's tool (its
//! tframe, mass and centre of gravity; none without a `tool:` block), one `PERS wobjdata` per
//! work object of the cell, in its order, with its uframe (in the cell frame, or with
//! `robot.frame: base` in the robot's base frame, the header's placement taken out), and one
//! `PERS loaddata` per entry of `loads:` (mass and centre of gravity). Written values carry the
//! module's decimals: positions within 0.0005 mm of the cell's, orientations within 1e-8 rad.

use super::library::{Cell, RobotFrame};
use super::module::Module;
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};

/// A written position may differ from the cell's by its rounding to 3 decimals, mm.
pub const POS_TOL_MM: f64 = 0.0005 + 1e-9;
/// A written quaternion (9 decimals) may turn from the cell's by this, rad.
pub const ROT_TOL_RAD: f64 = 1e-8;

/// A pose from a position and a quaternion `[w, x, y, z]`.
pub fn iso(p: [f64; 3], q: [f64; 4]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3])),
    )
}

/// Whether two poses agree within the module's decimals.
pub fn same_pose(a: &Isometry3<f64>, b: &Isometry3<f64>) -> bool {
    (a.translation.vector - b.translation.vector).norm() <= POS_TOL_MM * 3f64.sqrt()
        && a.rotation.angle_to(&b.rotation) <= ROT_TOL_RAD
}

/// The frame the module writes uframes and wobj0 robtargets in, in the cell frame: the cell
/// frame itself, or the robot base at `cell_from_robot` (`robot.frame: base`).
pub fn written_frame(cell: &Cell, cell_from_robot: &Isometry3<f64>) -> Isometry3<f64> {
    match cell.robot.frame {
        RobotFrame::Cell => Isometry3::identity(),
        RobotFrame::Base => *cell_from_robot,
    }
}

/// The declarations of `module` against `cell` (module doc): the failures.
pub fn check_declarations(
    cell: &Cell,
    module: &Module,
    cell_from_robot: &Isometry3<f64>,
) -> Vec<String> {
    let mut out = Vec::new();
    match (&cell.tool, module.tooldata.as_slice()) {
        (Some(t), [(name, d)]) => {
            let written = iso(
                [d.tframe[0], d.tframe[1], d.tframe[2]],
                [d.tframe[3], d.tframe[4], d.tframe[5], d.tframe[6]],
            );
            if *name != t.name || !same_pose(&written, &t.tframe.isometry()) {
                out.push(format!(
                    "tooldata tframe {:?} of {name}, the cell's tool {} has {:?}",
                    d.tframe, t.name, t.tframe
                ));
            }
            if d.mass_kg != t.mass_kg || d.cog_mm != t.cog_mm {
                out.push(format!(
                    "tooldata load {} kg at {:?}, the cell says {} kg at {:?}",
                    d.mass_kg, d.cog_mm, t.mass_kg, t.cog_mm
                ));
            }
        }
        (None, []) => {}
        (t, d) => out.push(format!(
            "the cell's tool block is {:?}, the module declares {} tooldata",
            t.as_ref().map(|t| &t.name),
            d.len()
        )),
    }
    let frame = written_frame(cell, cell_from_robot);
    let names: Vec<&str> = module.wobjdata.iter().map(|(n, _)| n.as_str()).collect();
    let want: Vec<&str> = cell.wobjs.iter().map(|w| w.name.as_str()).collect();
    if names != want {
        out.push(format!(
            "the module declares wobjdata {names:?}, the cell's work objects are {want:?}"
        ));
    }
    for ((name, u), w) in module.wobjdata.iter().zip(&cell.wobjs) {
        let written = iso([u[0], u[1], u[2]], [u[3], u[4], u[5], u[6]]);
        let expected = frame.inverse() * w.uframe.isometry();
        if !same_pose(&written, &expected) {
            out.push(format!(
                "wobjdata uframe {u:?} of {name}, the cell's is {expected} in the frame the module writes ({:?})",
                cell.robot.frame
            ));
        }
    }
    let names: Vec<&str> = module.loaddata.iter().map(|(n, _)| n.as_str()).collect();
    let want: Vec<&str> = cell.loads.iter().map(|l| l.name.as_str()).collect();
    if names != want {
        out.push(format!(
            "the module declares loaddata {names:?}, the cell's loads are {want:?}"
        ));
    }
    for ((name, d), l) in module.loaddata.iter().zip(&cell.loads) {
        if d.mass_kg != l.mass_kg || d.cog_mm != l.cog_mm {
            out.push(format!(
                "loaddata {name}: {} kg at {:?}, the cell says {} kg at {:?}",
                d.mass_kg, d.cog_mm, l.mass_kg, l.cog_mm
            ));
        }
    }
    out
}
