//! `points:`: each entry a point (its name and what it gives: `joints`, `xyz` + `branch`, or
//! `robtarget` with the work object it is given in) or a revisit of one (`revisit: NAME`: the
//! named point's target again, earlier or later in the list), then the motion of the move into
//! it (`speed`, `zone`), how it is reached and left (`process.rs`) and what is done there
//! (`actions.rs`).

use super::super::raw::RawPoint;
use super::super::{Arrival, CellError, Load, Loc, Point, Target, Wobj};
use super::values::{
    data_name, finite, identifier, invalid, invalid_help, joint_value, loc, pose, triple,
};
use super::{actions, process};
use crate::excerpt;
use crate::names::DataType;
use crate::robot::ik::Branch;
use serde_saphyr::Spanned;
use std::collections::HashMap;

/// The help line of a point given in no way or in two.
const POINT_HELP: &str = "a point is given one way: `joints` (controller values, deg), `xyz` (the wrist centre, mm) or `robtarget` (the TCP pose)";

/// The help line of a revisit that gives what only a point gives.
const REVISIT_HELP: &str = "a revisit gives `revisit: NAME` and optionally `speed`, `zone`, `move`, `via`, `approach`, `retract` and `do`; for another target, make it a point with its own name";

/// A point's name, target and work object (pass 1 of [`points`]).
type Named = (String, Target, Option<usize>);

/// `points:`. Two passes: the points' names and targets in order (a revisit may name a later
/// point), then every entry whole in order.
pub(super) fn points(
    raw: &Spanned<Vec<Spanned<RawPoint>>>,
    wobjs: &[Wobj],
    loads: &[Load],
) -> Result<Vec<Point>, CellError> {
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
    let mut named: Vec<Option<Named>> = Vec::with_capacity(raw.value.len());
    // Each name (RAPID's case folding) and its entry: one look-up a point.
    let mut index: HashMap<String, usize> = HashMap::new();
    for (i, p) in raw.value.iter().enumerate() {
        match (&p.value.name, &p.value.revisit) {
            (Some(n), None) => {
                let name = identifier(n, "point name")?;
                let key = name.to_ascii_lowercase();
                if let Some(&first) = index.get(&key) {
                    return Err(invalid_help(
                        loc(n),
                        format!(
                            "point name '{name}' is used twice (first at line {})",
                            loc(&raw.value[first]).line
                        ),
                        "RAPID names are case-insensitive; give every point its own name, and to reach a point's target again write `{ revisit: NAME }`",
                    ));
                }
                let target = target(&name, p)?;
                let wobj = work_object(&name, p, &target, wobjs)?;
                index.insert(key, i);
                named.push(Some((name, target, wobj)));
            }
            (None, Some(r)) => {
                gives_no_target(r, &p.value)?;
                named.push(None);
            }
            (Some(_), Some(r)) => {
                return Err(invalid_help(
                    loc(r),
                    "an entry of `points:` is a point (`name`) or a revisit (`revisit`), not both",
                    REVISIT_HELP,
                ))
            }
            (None, None) => {
                return Err(invalid_help(
                    loc(p),
                    "a point needs a name",
                    "a point is `{ name: P1, ... }` (a RAPID name) with `joints`, `xyz` or `robtarget`; `{ revisit: NAME }` reaches a named point's target again",
                ))
            }
        }
    }
    let mut points: Vec<Point> = Vec::with_capacity(raw.value.len());
    for (p, found) in raw.value.iter().zip(&named) {
        let ((name, target, wobj), revisit_of) = match (found, &p.value.revisit) {
            (Some(found), _) => (found.clone(), None),
            (None, Some(r)) => {
                let j = index
                    .get(&r.value.to_ascii_lowercase())
                    .copied()
                    .ok_or_else(|| {
                        invalid_help(
                            loc(r),
                            format!("revisit '{}' names no point", excerpt::value(&r.value)),
                            "`revisit:` names a point of this cell (its `name:`), earlier or later in the list; a revisit declares no name of its own",
                        )
                    })?;
                match &named[j] {
                    Some(found) => (found.clone(), Some(j)),
                    None => return Err(invalid(loc(r), "a revisit names a revisit")),
                }
            }
            (None, None) => return Err(invalid(loc(p), "a point needs a name")),
        };
        let who = match revisit_of {
            None => format!("point '{name}'"),
            Some(_) => format!("the revisit of '{name}'"),
        };
        let speed = match &p.value.speed {
            Some(s) => Some(data_name(s, &format!("{who} speed"), DataType::Speed)?),
            None => None,
        };
        let zone = match &p.value.zone {
            Some(z) => Some(data_name(z, &format!("{who} zone"), DataType::Zone)?),
            None => None,
        };
        let mut point = Point {
            name,
            target,
            speed,
            zone,
            loc: loc(p),
            arrival: Arrival::Joint,
            arrival_loc: loc(p),
            approach_mm: None,
            approach_loc: Loc::default(),
            retract_mm: None,
            retract_loc: Loc::default(),
            actions: Vec::new(),
            wobj,
            revisit_of,
        };
        process::reach(&mut point, &who, &p.value, points.last())?;
        point.actions = actions::actions(p.value.actions.as_ref(), &who, loads)?;
        process::stop_zone(&point, &who, &p.value)?;
        points.push(point);
    }
    one_arc_per_point(&points)?;
    Ok(points)
}

/// A circular move's circle point is written once per point, `<point>_via`: a point reached by
/// two circular moves (by its own entry and a revisit, or by two revisits) is refused at the
/// second's `move` line.
fn one_arc_per_point(points: &[Point]) -> Result<(), CellError> {
    let mut arcs: HashMap<String, u64> = HashMap::new();
    for p in points {
        if !matches!(p.arrival, Arrival::Circular { .. }) {
            continue;
        }
        let key = p.name.to_ascii_lowercase();
        if let Some(first) = arcs.get(&key) {
            return Err(invalid_help(
                p.arrival_loc,
                format!(
                    "{} is a second circular move into '{}' (the first at line {first}): the module writes one circle point `{}_via` per point",
                    p.label(),
                    p.name,
                    p.name
                ),
                "reach the point by `move: circular` once; for another arc ending there, give that end a point of its own (a new `name:` with the same `robtarget`)",
            ));
        }
        arcs.insert(key, p.arrival_loc.line);
    }
    Ok(())
}

/// A revisit takes the named point's target: it gives none of its own (nor a work object, the
/// frame of that target).
fn gives_no_target(r: &Spanned<String>, v: &RawPoint) -> Result<(), CellError> {
    let given = [
        v.joints.as_ref().map(|j| ("joints", loc(j))),
        v.xyz.as_ref().map(|x| ("xyz", loc(x))),
        v.robtarget.as_ref().map(|x| ("robtarget", loc(x))),
        v.branch.as_ref().map(|x| ("branch", loc(x))),
        v.wobj.as_ref().map(|x| ("wobj", loc(x))),
    ];
    match given.into_iter().flatten().next() {
        Some((key, at)) => Err(invalid_help(
            at,
            format!(
                "the revisit of '{}' reaches that point's target: it gives no `{key}`",
                excerpt::value(&r.value)
            ),
            REVISIT_HELP,
        )),
        None => Ok(()),
    }
}

/// The work object a point is given in: a robtarget's `wobj:` (one of the cell's), or without
/// one the cell's only work object (`None`: the cell declares none, wobj0). Other points give
/// none.
fn work_object(
    name: &str,
    p: &Spanned<RawPoint>,
    target: &Target,
    wobjs: &[Wobj],
) -> Result<Option<usize>, CellError> {
    let robtarget = matches!(target, Target::Robtarget { .. });
    let declared = || {
        let names: Vec<&str> = wobjs.iter().take(8).map(|w| w.name.as_str()).collect();
        let more = if wobjs.len() > 8 { ", ..." } else { "" };
        format!("{}{more}", names.join(", "))
    };
    match (&p.value.wobj, robtarget) {
        (Some(w), false) => Err(invalid_help(
            loc(w),
            format!("point '{name}': `wobj` applies to robtarget points only"),
            "a work object is the frame a robtarget's pose is given in; joint values and wrist-centre positions (xyz) need none",
        )),
        (Some(w), true) => match wobjs
            .iter()
            .position(|d| d.name.eq_ignore_ascii_case(&w.value))
        {
            Some(i) => Ok(Some(i)),
            None if wobjs.is_empty() => Err(invalid_help(
                loc(w),
                format!(
                    "point '{name}': work object '{}' is not declared (the cell declares none)",
                    excerpt::value(&w.value)
                ),
                "declare it under `wobj: { name, uframe }` (or several under `wobjs:`); without one, robtargets are in wobj0, the cell frame",
            )),
            None => Err(invalid_help(
                loc(w),
                format!(
                    "point '{name}': work object '{}' is not one of the cell's",
                    excerpt::value(&w.value)
                ),
                format!("a robtarget names one of the cell's work objects: {}", declared()),
            )),
        },
        (None, true) if wobjs.len() > 1 => Err(invalid_help(
            loc(p),
            format!(
                "point '{name}' is a robtarget but names no work object, and the cell has {}",
                wobjs.len()
            ),
            format!(
                "with several work objects each robtarget names its own, `wobj: NAME`: {}",
                declared()
            ),
        )),
        (None, true) => Ok((!wobjs.is_empty()).then_some(0)),
        (None, false) => Ok(None),
    }
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
