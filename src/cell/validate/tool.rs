//! The data the module declares beside its targets: `tool:` (the tooldata: name, TCP frame in
//! the flange frame, load, with the tool's collision shapes), `wobj:` or `wobjs:` (the work
//! objects robtargets are given in) and `loads:` (loaddata for `grip_load`). Their names join
//! the module's one name space (`mod.rs`).

use super::super::raw::{RawLoad, RawShape, RawTool, RawWobj};
use super::super::{defaults, CellError, Frame, Load, Tool, ToolGeometry, ToolShape, Wobj};
use super::values::{
    bounded, identifier, invalid, invalid_help, loc, mass, pose, position, triple,
};
use crate::excerpt;
use serde_saphyr::Spanned;

/// `tool:`.
pub(super) fn tool(t: &Spanned<RawTool>) -> Result<Tool, CellError> {
    let r = &t.value;
    let name = identifier(&r.name, "tool name").map_err(|e| with_help(e, "the tool block declares tooldata: name it (e.g. tTorch); tool0 is the flange itself, predefined, and is what the moves use without a tool block"))?;
    let (tframe, _) = pose(&r.tframe, "tool.tframe", false)?;
    let mass_kg = match &r.mass {
        Some(m) => mass(
            m,
            "tool.mass",
            "the tool's load as tooldata declares it; leave it out for 1 kg",
        )?,
        None => defaults::TOOL_MASS_KG,
    };
    let cog_mm = match &r.cog {
        Some(c) => position(c, "tool.cog")?,
        None => [0.0; 3],
    };
    let mut shapes: Vec<ToolShape> = Vec::new();
    for s in &r.shapes {
        let shape = shape(s)?;
        if let Some(first) = shapes.iter().find(|p| p.name == shape.name) {
            return Err(invalid_help(
                loc(&s.value.name),
                format!(
                    "tool shape name '{}' is used twice (first at line {})",
                    excerpt::value(&shape.name),
                    first.loc.line
                ),
                "give every tool shape its own name: messages and the header name the shape that comes closest",
            ));
        }
        shapes.push(shape);
    }
    Ok(Tool {
        name,
        tframe,
        mass_kg,
        cog_mm,
        shapes,
        loc: loc(&r.name),
    })
}

fn with_help(e: CellError, help: &str) -> CellError {
    match e {
        CellError::Invalid { loc, message, .. } => invalid_help(loc, message, help),
        other => other,
    }
}

/// One tool shape: exactly one of cylinder, box, sphere, in the flange frame (mm).
fn shape(s: &Spanned<RawShape>) -> Result<ToolShape, CellError> {
    let r = &s.value;
    let name = r.name.value.clone();
    if name.trim().is_empty() {
        return Err(invalid(loc(&r.name), "a tool shape needs a name"));
    }
    // As quoted in messages (a shape's name is free text, as long as the input).
    let shown = excerpt::value(&name);
    let what = |key: &str| format!("tool shape '{shown}' {key}");
    let positive = |v: &Spanned<f64>, key: &str| {
        bounded(v, &what(key), "a number > 0 (mm)")?;
        if v.value > 0.0 {
            Ok(v.value)
        } else {
            Err(invalid_help(
                loc(v),
                format!(
                    "{} = {} must be a number > 0 (mm)",
                    what(key),
                    excerpt::number(v.value)
                ),
                "a tool shape has a volume: its radius in mm, more than 0; leave out a shape that has none",
            ))
        }
    };
    let geometry = match (&r.cylinder, &r.aabb, &r.sphere) {
        (Some(c), None, None) => {
            let c = &c.value;
            let from_mm = triple(&c.from, &what("cylinder.from"))?;
            let to_mm = triple(&c.to, &what("cylinder.to"))?;
            let radius_mm = positive(&c.radius, "cylinder.radius")?;
            if from_mm == to_mm {
                return Err(invalid_help(
                    loc(&c.to),
                    format!("{}: from and to are the same point", what("cylinder")),
                    "a cylinder runs from `from` to `to` (its axis, flange frame, mm); for a ball use `sphere: { centre: [x, y, z], radius: r }`",
                ));
            }
            ToolGeometry::Cylinder {
                from_mm,
                to_mm,
                radius_mm,
            }
        }
        (None, Some(b), None) => {
            let min_mm = triple(&b.value.min, &what("box.min"))?;
            let max_mm = triple(&b.value.max, &what("box.max"))?;
            if let Some(i) = (0..3).find(|&i| min_mm[i] >= max_mm[i]) {
                let axis = ["x", "y", "z"][i];
                return Err(invalid_help(
                    loc(b),
                    format!(
                        "{}: box.min {axis} = {} is not below box.max {axis} = {}",
                        what("box"),
                        min_mm[i],
                        max_mm[i]
                    ),
                    "a tool box is axis-aligned in the flange frame: min holds the smallest x, y, z and max the largest",
                ));
            }
            ToolGeometry::Box { min_mm, max_mm }
        }
        (None, None, Some(p)) => ToolGeometry::Sphere {
            centre_mm: triple(&p.value.centre, &what("sphere.centre"))?,
            radius_mm: positive(&p.value.radius, "sphere.radius")?,
        },
        _ => {
            return Err(invalid_help(
                loc(s),
                format!("tool shape '{shown}' must give exactly one of cylinder, box, sphere"),
                "cylinder: { from: [x, y, z], to: [x, y, z], radius: r }, box: { min: [..], max: [..] } or sphere: { centre: [..], radius: r }, in the flange frame (mm)",
            ))
        }
    };
    Ok(ToolShape {
        name,
        geometry,
        loc: loc(s),
    })
}

/// `wobj:` (one work object) or `wobjs:` (a list), not both.
pub(super) fn wobjs(
    one: Option<&Spanned<RawWobj>>,
    many: Option<&Spanned<Vec<Spanned<RawWobj>>>>,
) -> Result<Vec<Wobj>, CellError> {
    match (one, many) {
        (Some(w), None) => Ok(vec![wobj(w, "wobj")?]),
        (None, Some(list)) => list.value.iter().map(|w| wobj(w, "wobjs")).collect(),
        (None, None) => Ok(Vec::new()),
        (Some(w), Some(list)) => {
            let (at, this) = if (loc(w).line, loc(w).column) > (loc(list).line, loc(list).column) {
                (loc(w), "this `wobj:` is the second")
            } else {
                (loc(list), "this `wobjs:` list is the second")
            };
            Err(invalid_help(
                at,
                format!("`wobj:` and `wobjs:` are both given; {this}"),
                "give one work object as `wobj: { name, uframe }` or several as `wobjs:` (a list of them), not both",
            ))
        }
    }
}

/// One work object (`key` is `wobj` or `wobjs`, for messages).
fn wobj(w: &Spanned<RawWobj>, key: &str) -> Result<Wobj, CellError> {
    let r = &w.value;
    let name = identifier(&r.name, "work object name").map_err(|e| with_help(e, "the wobj block declares wobjdata: name it (e.g. wobjTrunk); wobj0 is predefined (the world frame) and is what robtargets use without a wobj block"))?;
    let what = match key {
        "wobj" => "wobj.uframe".to_string(),
        _ => format!("work object '{name}' uframe"),
    };
    let (uframe, _): (Frame, _) = pose(&r.uframe, &what, false)?;
    Ok(Wobj {
        name,
        uframe,
        loc: loc(&r.name),
    })
}

/// `loads:`: each a name, a mass (required) and a centre of gravity in the tool frame.
pub(super) fn loads(raw: Option<&Spanned<Vec<Spanned<RawLoad>>>>) -> Result<Vec<Load>, CellError> {
    let Some(raw) = raw else {
        return Ok(Vec::new());
    };
    raw.value.iter().map(load).collect()
}

fn load(l: &Spanned<RawLoad>) -> Result<Load, CellError> {
    let r = &l.value;
    let name = identifier(&r.name, "load name").map_err(|e| with_help(e, "a load declares loaddata for grip_load: name it (e.g. loadPart); load0 is predefined (nothing held) and needs no declaration"))?;
    let Some(m) = &r.mass else {
        return Err(invalid_help(
            loc(l),
            format!("load '{name}' gives no mass"),
            "a load is { name, mass, cog }: its mass in kg (> 0) is what GripLoad tells the controller the tool holds; cog defaults to [0, 0, 0]",
        ));
    };
    let mass_kg = mass(
        m,
        &format!("load '{name}' mass"),
        "a load is what the tool holds, in kg; for nothing held, grip_load names load0",
    )?;
    let cog_mm = match &r.cog {
        Some(c) => position(c, &format!("load '{name}' cog"))?,
        None => [0.0; 3],
    };
    Ok(Load {
        name,
        mass_kg,
        cog_mm,
        loc: loc(&r.name),
    })
}
