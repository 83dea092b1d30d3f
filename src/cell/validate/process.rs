//! How an entry of `points:` is reached and left: `move` (`joint`, `linear`, `circular` with its
//! `via`), `approach` and `retract`, and the rules that need the previous entry (nothing moves
//! linear into the first point or out of a retract) or the whole entry (a point with actions, an
//! approach or a retract is reached `fine`). What needs the poses (an arc's shape, the path's
//! clearance) is the place stage's to check; the Locs kept on the [`Point`] let it point here.

use super::super::raw::RawPoint;
use super::super::{defaults, Arrival, CellError, Point, Target};
use super::values::{in_range, invalid_help, loc, position};
use crate::excerpt;
use crate::names::check_identifier;
use crate::precision::POSITION_DECIMALS;
use serde_saphyr::Spanned;

/// The help line of `approach` and `retract` out of range.
const OFFSET_HELP: &str = "approach and retract are lines along the TCP's own z axis, 1 .. 1000 mm (RelTool(p, 0, 0, -D))";

/// `move`, `via`, `approach` and `retract` of `point` (`who` names it in messages), whose
/// previous entry is `previous` (`None`: the first).
pub(super) fn reach(
    point: &mut Point,
    who: &str,
    raw: &RawPoint,
    previous: Option<&Point>,
) -> Result<(), CellError> {
    let robtarget = matches!(point.target, Target::Robtarget { .. });
    let gives = match point.target {
        Target::Joints { .. } => "joint values",
        Target::Xyz { .. } => "a wrist-centre position (xyz)",
        Target::Robtarget { .. } => "a robtarget",
    };
    if let Some(m) = &raw.arrival {
        point.arrival_loc = loc(m);
        let key = m.value.as_str();
        point.arrival = match key {
            "joint" => Arrival::Joint,
            "linear" | "circular" => {
                let Some(previous) = previous else {
                    return Err(invalid_help(
                        loc(m),
                        format!("{who} is the first point: nothing moves `{key}` into it"),
                        "the routine starts at the first point (a joint move from wherever the robot stands); make a later point linear or circular",
                    ));
                };
                if !robtarget {
                    return Err(invalid_help(
                        loc(m),
                        format!(
                            "{who} is reached `{key}`, which needs a robtarget, but '{}' gives {gives}",
                            point.name
                        ),
                        "a linear or circular move is a TCP path to a pose: give the point as `robtarget: [[x, y, z], ...]`, or reach it by `move: joint`",
                    ));
                }
                if previous.retract_mm.is_some() {
                    return Err(invalid_help(
                        loc(m),
                        format!(
                            "{who} is reached `{key}` from {}, which retracts (line {})",
                            previous.label(),
                            previous.retract_loc.line
                        ),
                        "a linear or circular move starts at the previous point's pose: remove that point's `retract`, or reach this one by `move: joint`",
                    ));
                }
                match (key, &raw.via) {
                    ("circular", Some(v)) => Arrival::Circular {
                        via_mm: position(v, &format!("{who} via"))?,
                        via_loc: loc(v),
                    },
                    ("circular", None) => {
                        return Err(invalid_help(
                            loc(m),
                            format!("{who} is reached `circular`, which needs `via`, a point of the arc"),
                            "`via: [x, y, z]` (mm, in the point's work object frame) is a point of the arc between the previous point and this one",
                        ))
                    }
                    _ => Arrival::Linear,
                }
            }
            other => {
                return Err(invalid_help(
                    loc(m),
                    format!(
                        "{who}: move '{}' is not one of joint, linear, circular",
                        excerpt::value(other)
                    ),
                    "joint (the default): the planned, proven route; linear: a straight TCP line (MoveL); circular: an arc through `via` (MoveC)",
                ))
            }
        };
    }
    if let (Some(v), false) = (&raw.via, matches!(point.arrival, Arrival::Circular { .. })) {
        return Err(invalid_help(
            loc(v),
            format!("{who}: `via` applies to `move: circular` only"),
            "via is a point of the arc of a circular move: add `move: circular`, or remove via",
        ));
    }
    if let Some(a) = &raw.approach {
        let what = format!("{who} approach");
        point.approach_mm = Some(offset(a, &what, point, gives)?);
        point.approach_loc = loc(a);
        if point.arrival.is_process() {
            return Err(invalid_help(
                loc(a),
                format!("{what}: the point is reached `move: {}`, not by the planned route", arrival_key(&point.arrival)),
                "an approach line ends the planned joint route; a linear or circular move reaches the point itself: remove approach (or the move)",
            ));
        }
        if previous.is_none() {
            return Err(invalid_help(
                loc(a),
                format!("{what}: the first point is where the routine starts, so nothing approaches it"),
                "start the routine at another point (a home position) before this one, or remove approach",
            ));
        }
    }
    if let Some(r) = &raw.retract {
        point.retract_mm = Some(offset(r, &format!("{who} retract"), point, gives)?);
        point.retract_loc = loc(r);
    }
    Ok(())
}

/// `approach` or `retract` (`what`): mm within 1 .. 1000 at the module's precision, on a
/// robtarget (the line runs along its TCP's z axis); `gives` says what the point gives instead.
fn offset(v: &Spanned<f64>, what: &str, point: &Point, gives: &str) -> Result<f64, CellError> {
    let range = (defaults::MIN_OFFSET_MM, defaults::MAX_OFFSET_MM);
    let d = in_range(v, what, range, POSITION_DECIMALS, "mm", OFFSET_HELP)?;
    if !matches!(point.target, Target::Robtarget { .. }) {
        return Err(invalid_help(
            loc(v),
            format!(
                "{what} needs a robtarget (a line along the TCP's z axis), but '{}' gives {gives}",
                point.name
            ),
            "give the point as `robtarget: [[x, y, z], ORIENTATION]`, the TCP pose the line runs along",
        ));
    }
    Ok(d)
}

/// The key `move:` takes for `a`.
fn arrival_key(a: &Arrival) -> &'static str {
    match a {
        Arrival::Joint => "joint",
        Arrival::Linear => "linear",
        Arrival::Circular { .. } => "circular",
    }
}

/// A point that [`stops`](Point::stops) is reached `fine`: its own `zone`, if given, must be
/// fine (`motion.zone` is a default and does not apply there).
pub(super) fn stop_zone(point: &Point, who: &str, raw: &RawPoint) -> Result<(), CellError> {
    let Some(z) = &raw.zone else {
        return Ok(());
    };
    if z.value.eq_ignore_ascii_case("fine") || !point.stops() {
        return Ok(());
    }
    let why = if !point.actions.is_empty() {
        "actions (`do`)"
    } else if point.approach_mm.is_some() {
        "an approach line"
    } else {
        "a retract line"
    };
    Err(invalid_help(
        loc(z),
        format!("{who} has {why}, so it is reached fine: zone '{}' cannot apply", z.value),
        "actions run once the move into the point has ended, and approach and retract lines start and end at a stop: remove the zone (or write fine)",
    ))
}

/// The names an approach or retract pose in another configuration than its point is written
/// under, `CONST robtarget <point>_app` or `<point>_ret` (stepping aside, `_x1`, from a name
/// taken): whether it is, planning tells, so the name must be one RAPID takes.
pub(super) fn own_pose_names(points: &[Point]) -> Result<(), CellError> {
    for p in points.iter().filter(|p| p.revisit_of.is_none()) {
        for (given, suffix, pose, loc) in [
            (p.approach_mm, "app", "approach", p.approach_loc),
            (p.retract_mm, "ret", "retract", p.retract_loc),
        ] {
            let name = format!("{}_{suffix}", p.name);
            if let (Some(_), Err(e)) = (given, check_identifier(&name)) {
                return Err(invalid_help(
                    loc,
                    format!("the {pose} pose of this point may be written as CONST robtarget '{name}', not a valid RAPID name: {e}"),
                    "an approach or retract pose in another configuration than its point is written as a CONST robtarget named <name>_app or <name>_ret; shorten the point's name".to_string(),
                ));
            }
        }
    }
    Ok(())
}
