//! `points:`: each point's name, what it gives (`joints`, `xyz` + `branch`, or `robtarget`) and
//! the motion of the move into it (`speed`, `zone`).

use super::super::raw::RawPoint;
use super::super::{CellError, Point, Target};
use super::values::{
    data_name, finite, identifier, invalid, invalid_help, joint_value, loc, pose, triple,
};
use crate::names::DataType;
use crate::robot::ik::Branch;
use serde_saphyr::Spanned;
use std::collections::HashMap;

/// The help line of a point given in no way or in two.
const POINT_HELP: &str = "a point is given one way: `joints` (controller values, deg), `xyz` (the wrist centre, mm) or `robtarget` (the TCP pose)";

/// `points:`.
pub(super) fn points(raw: &Spanned<Vec<Spanned<RawPoint>>>) -> Result<Vec<Point>, CellError> {
    if raw.value.len() < 2 {
        return Err(invalid_help(
            loc(raw),
            format!(
                "a cell needs at least 2 points (a start and an end), found {}",
                raw.value.len()
            ),
            "the points are visited in order, the first is the start and the last the end; list at least two",
        ));
    }
    let mut points: Vec<Point> = Vec::new();
    // Each name (RAPID's case folding) and the line of its first point: one look-up a point.
    let mut first_line: HashMap<String, u64> = HashMap::new();
    for p in &raw.value {
        let name = identifier(&p.value.name, "point name")?;
        if let Some(first) = first_line.get(&name.to_ascii_lowercase()) {
            return Err(invalid_help(
                loc(&p.value.name),
                format!("point name '{name}' is used twice (first at line {first})"),
                "RAPID names are case-insensitive; give every point its own name",
            ));
        }
        let speed = match &p.value.speed {
            Some(s) => Some(data_name(
                s,
                &format!("point '{name}' speed"),
                DataType::Speed,
            )?),
            None => None,
        };
        let zone = match &p.value.zone {
            Some(z) => Some(data_name(
                z,
                &format!("point '{name}' zone"),
                DataType::Zone,
            )?),
            None => None,
        };
        first_line.insert(name.to_ascii_lowercase(), loc(p).line);
        points.push(Point {
            target: target(&name, p)?,
            name,
            speed,
            zone,
            loc: loc(p),
        });
    }
    Ok(points)
}

/// What one point gives: `joints` (3 or 6 controller values), `xyz` (+ `branch`) or `robtarget`.
fn target(name: &str, p: &Spanned<RawPoint>) -> Result<Target, CellError> {
    let v = &p.value;
    let given: Vec<(&str, crate::cell::Loc)> = [
        v.joints.as_ref().map(|j| ("joints", loc(j))),
        v.xyz.as_ref().map(|x| ("xyz", loc(x))),
        v.robtarget.as_ref().map(|r| ("robtarget", loc(r))),
    ]
    .into_iter()
    .flatten()
    .collect();
    if let [(first, _), (second, at), ..] = given.as_slice() {
        return Err(invalid_help(
            *at,
            format!("point '{name}' gives both `{first}` and `{second}`; give one"),
            POINT_HELP,
        ));
    }
    if let (Some(b), None) = (&v.branch, &v.xyz) {
        return Err(invalid_help(
            loc(b),
            format!("point '{name}': `branch` applies to `xyz` points only"),
            "`branch` picks one of the four arm solutions of a wrist-centre position; a robtarget picks its solution with its confdata [cf1, cf4, cf6, cfx], joint values need none",
        ));
    }
    if let Some(j) = &v.joints {
        return joints(name, j);
    }
    if let Some(x) = &v.xyz {
        return Ok(Target::Xyz {
            wrist_centre_mm: triple(x, &format!("point '{name}' xyz"))?,
            branch: match &v.branch {
                Some(b) => Some(
                    b.value
                        .parse::<Branch>()
                        .map_err(|why| invalid(loc(b), format!("point '{name}': {why}")))?,
                ),
                None => None,
            },
            branch_loc: v.branch.as_ref().map(loc).unwrap_or_default(),
        });
    }
    if let Some(r) = &v.robtarget {
        let (pose, conf) = pose(r, &format!("point '{name}' robtarget"), true)?;
        return Ok(Target::Robtarget { pose, conf });
    }
    Err(invalid_help(
        loc(p),
        format!("point '{name}' gives neither `joints`, `xyz` nor `robtarget`"),
        "write `joints: [a1, a2, a3]` (controller values, deg), `xyz: [x, y, z]` (wrist centre, mm) or `robtarget: [[x, y, z], [q1, q2, q3, q4]]` (TCP pose in the work object)",
    ))
}

/// `joints: [a1, a2, a3]` or all six.
fn joints(name: &str, j: &Spanned<Vec<f64>>) -> Result<Target, CellError> {
    finite(j, &format!("point '{name}' joints"))?;
    let l = loc(j);
    let mut a = Vec::with_capacity(6);
    for (i, x) in j.value.iter().enumerate() {
        a.push(joint_value(
            *x,
            l,
            &format!("point '{name}' axis {}", i + 1),
        )?);
    }
    Ok(match a.as_slice() {
        [a1, a2, a3] => Target::Joints {
            axes_deg: [*a1, *a2, *a3],
            wrist_deg: None,
        },
        [a1, a2, a3, a4, a5, a6] => Target::Joints {
            axes_deg: [*a1, *a2, *a3],
            wrist_deg: Some([*a4, *a5, *a6]),
        },
        _ => {
            return Err(invalid_help(
                l,
                format!(
                    "point '{name}': joints must list axes 1..3 or all six axes, found {} values",
                    a.len()
                ),
                "`joints: [a1, a2, a3]` (axes 4..6 from robot.wrist) or `[a1, a2, a3, a4, a5, a6]`, controller values in degrees",
            ))
        }
    })
}
