//! The cell file as written ([`RawCell`]) -> a [`Cell`]: one function per YAML section, then the
//! checks that need several sections (the module's one name space, `base: auto` with its
//! points). Every refusal points at the value at fault.
//!
//! Two rules come from elsewhere, so that the cell and the module cannot disagree: the RAPID
//! identifier rule ([`crate::names`]) and the table of output precisions ([`crate::precision`]):
//! a value finer than the module states it is refused, so every value of the cell appears in the
//! module exactly as given.

use super::raw::{RawBase, RawCell, RawMotion, RawObstacle, RawPlanner, RawPoint, RawRobot};
use super::{
    check_grid, defaults, Base, Cell, CellError, Loc, Method, Motion, Obstacle, Planner, Point,
    RobotSpec, Target,
};
use crate::excerpt;
use crate::geometry::Aabb;
use crate::names::{check_data_name, check_identifier};
use crate::precision::{self, JOINT_DECIMALS, LENGTH_DECIMALS, YAW_DECIMALS};
use crate::robot::ik::Branch;
use nalgebra::Point3;
use serde_saphyr::Spanned;
use std::path::Path;

/// Validates every section of a parsed cell file (module docs).
pub(super) fn cell(path: &Path, raw: RawCell) -> Result<Cell, CellError> {
    let module = module(&raw.module)?;
    let robot = robot(path, &raw.robot)?;
    let obstacles = obstacles(&raw.obstacles)?;
    let points = points(&raw.points)?;
    let planner = planner(raw.planner.as_ref().map(|p| &p.value))?;
    let motion = motion(raw.motion.as_ref().map(|m| &m.value))?;
    one_name_space(&module, loc(&raw.module), &points, &motion)?;
    distinct_data(&motion, raw.motion.as_ref().map(|m| &m.value))?;
    if robot.base == Base::Auto {
        every_point_xyz(&points)?;
    }
    Ok(Cell {
        path: path.to_path_buf(),
        module,
        robot,
        obstacles,
        points,
        planner,
        motion,
        tool: None,
        wobj: None,
    })
}

fn loc<T>(s: &Spanned<T>) -> Loc {
    Loc::from(s.referenced)
}

fn invalid(loc: Loc, message: impl Into<String>) -> CellError {
    CellError::Invalid {
        loc,
        message: message.into(),
        help: None,
    }
}

fn invalid_help(loc: Loc, message: impl Into<String>, help: impl Into<String>) -> CellError {
    CellError::Invalid {
        loc,
        message: message.into(),
        help: Some(help.into()),
    }
}

// ---- values ----

fn finite(v: &Spanned<Vec<f64>>, what: &str) -> Result<(), CellError> {
    if v.value.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(invalid(
            loc(v),
            format!("{what}: every value must be a finite number"),
        ))
    }
}

fn triple(v: &Spanned<Vec<f64>>, what: &str) -> Result<[f64; 3], CellError> {
    finite(v, what)?;
    <[f64; 3]>::try_from(v.value.as_slice()).map_err(|_| {
        invalid(
            loc(v),
            format!("{what} must have 3 numbers, found {}", v.value.len()),
        )
    })
}

/// Checks that `v` has at most `n` decimals: the module header states the base and yaw with
/// that many, and must state exactly what was planned with.
fn decimals(v: f64, n: usize, loc: Loc, what: &str, unit: &str) -> Result<f64, CellError> {
    if precision::exceeds(v, n) {
        let s = if n == 1 { "" } else { "s" };
        return Err(invalid_help(
            loc,
            format!("{what} = {v} has more than {n} decimal{s}"),
            format!("the module header states {what} to {n} decimal{s} ({unit}); give no more, so it states what was used"),
        ));
    }
    Ok(v)
}

/// Checks that a joint value has at most [`JOINT_DECIMALS`] decimals; returns it rounded to them.
fn joint_value(v: f64, loc: Loc, what: &str) -> Result<f64, CellError> {
    if precision::exceeds(v, JOINT_DECIMALS) {
        return Err(invalid_help(
            loc,
            format!("{what} = {v} has more than {JOINT_DECIMALS} decimals"),
            format!(
                "gen-rapid writes joint values to 0.{}1 deg; give at most {JOINT_DECIMALS} decimals so the point appears in the module exactly as given",
                "0".repeat(JOINT_DECIMALS - 1)
            ),
        ));
    }
    Ok(precision::round(v, JOINT_DECIMALS))
}

/// A name the module declares (the module, a point): the RAPID identifier rule.
fn identifier(s: &Spanned<String>, what: &str) -> Result<String, CellError> {
    check_identifier(&s.value).map_err(|e| {
        invalid(
            loc(s),
            format!(
                "{what} '{}' is not a valid RAPID name: {e}",
                excerpt::value(&s.value)
            ),
        )
    })?;
    Ok(s.value.clone())
}

/// A name of RAPID data the module uses but does not declare (speed, zone, tool): the same rule,
/// predefined names allowed.
fn data_name(s: Option<&Spanned<String>>, default: &str, what: &str) -> Result<String, CellError> {
    let Some(s) = s else {
        return Ok(default.to_string());
    };
    check_data_name(&s.value).map_err(|e| {
        invalid_help(
            loc(s),
            format!(
                "{what} '{}' is not a valid RAPID name: {e}",
                excerpt::value(&s.value)
            ),
            "speed, zone and tool name RAPID data: a predefined one (v300, fine, tool0) or one declared on the controller",
        )
    })?;
    Ok(s.value.clone())
}

// ---- sections ----

/// `module:`.
fn module(m: &Spanned<String>) -> Result<String, CellError> {
    identifier(m, "module")
}

/// `robot:`.
fn robot(path: &Path, r: &Spanned<RawRobot>) -> Result<RobotSpec, CellError> {
    let r = &r.value;
    if r.urdf.value.trim().is_empty() {
        return Err(invalid(loc(&r.urdf), "robot.urdf must name a URDF file"));
    }
    let dir = path.parent().unwrap_or(Path::new(""));
    let urdf_path = dir.join(&r.urdf.value);
    let base = match &r.base.value {
        RawBase::Auto => Base::Auto,
        RawBase::Xyz(v) => {
            let v = Spanned {
                value: v.clone(),
                referenced: r.base.referenced,
                defined: r.base.defined,
            };
            let b = triple(&v, "robot.base")?;
            for x in b {
                decimals(x, LENGTH_DECIMALS, loc(&v), "robot.base", "mm")?;
            }
            Base::Fixed(b)
        }
    };
    let yaw_deg = match &r.yaw {
        Some(y) if !y.value.is_finite() => {
            return Err(invalid(loc(y), "robot.yaw must be a finite number (deg)"))
        }
        Some(y) => decimals(y.value, YAW_DECIMALS, loc(y), "robot.yaw", "deg")?,
        None => 0.0,
    };
    let wrist_deg = match &r.wrist {
        Some(w) => {
            let t = triple(w, "robot.wrist")?;
            let l = loc(w);
            [
                joint_value(t[0], l, "robot.wrist axis 4")?,
                joint_value(t[1], l, "robot.wrist axis 5")?,
                joint_value(t[2], l, "robot.wrist axis 6")?,
            ]
        }
        None => [0.0; 3],
    };
    Ok(RobotSpec {
        urdf_path,
        urdf_loc: loc(&r.urdf),
        base,
        base_loc: loc(&r.base),
        yaw_deg,
        wrist_deg,
    })
}

/// `obstacles:`.
fn obstacles(raw: &[Spanned<RawObstacle>]) -> Result<Vec<Obstacle>, CellError> {
    let mut obstacles: Vec<Obstacle> = Vec::new();
    for o in raw {
        let name = o.value.name.value.clone();
        // As quoted in messages (a name may be as long as the input).
        let shown = excerpt::value(&name);
        if name.trim().is_empty() {
            return Err(invalid(loc(&o.value.name), "an obstacle needs a name"));
        }
        if let Some(first) = obstacles.iter().find(|p| p.name == name) {
            return Err(invalid(
                loc(&o.value.name),
                format!(
                    "obstacle name '{shown}' is used twice (first at line {})",
                    first.loc.line
                ),
            ));
        }
        let min_mm = triple(
            &o.value.aabb.value.min,
            &format!("obstacle '{shown}' box.min"),
        )?;
        let max_mm = triple(
            &o.value.aabb.value.max,
            &format!("obstacle '{shown}' box.max"),
        )?;
        if let Some(i) = (0..3).find(|&i| min_mm[i] >= max_mm[i]) {
            return Err(invalid_help(
                loc(&o.value.aabb),
                format!(
                    "obstacle '{shown}': box.min {} = {} is not below box.max {} = {}",
                    ["x", "y", "z"][i],
                    min_mm[i],
                    ["x", "y", "z"][i],
                    max_mm[i]
                ),
                "boxes are axis-aligned: min holds the smallest x, y, z and max the largest",
            ));
        }
        obstacles.push(Obstacle {
            name,
            aabb: Aabb::new(Point3::from(min_mm), Point3::from(max_mm)),
            loc: loc(o),
        });
    }
    Ok(obstacles)
}

/// `points:`.
fn points(raw: &Spanned<Vec<Spanned<RawPoint>>>) -> Result<Vec<Point>, CellError> {
    if raw.value.len() < 2 {
        return Err(invalid(
            loc(raw),
            format!(
                "a cell needs at least 2 points (a start and an end), found {}",
                raw.value.len()
            ),
        ));
    }
    let mut points: Vec<Point> = Vec::new();
    for p in &raw.value {
        let name = identifier(&p.value.name, "point name")?;
        if let Some(first) = points.iter().find(|q| q.name.eq_ignore_ascii_case(&name)) {
            return Err(invalid_help(
                loc(&p.value.name),
                format!(
                    "point name '{name}' is used twice (first at line {})",
                    first.loc.line
                ),
                "RAPID names are case-insensitive; give every point its own name",
            ));
        }
        points.push(Point {
            target: target(&name, p)?,
            name,
            loc: loc(p),
        });
    }
    Ok(points)
}

/// What one point gives: `joints` (3 or 6 controller values) or `xyz` (+ `branch`).
fn target(name: &str, p: &Spanned<RawPoint>) -> Result<Target, CellError> {
    let v = &p.value;
    Ok(match (&v.joints, &v.xyz) {
        (Some(j), None) => {
            if let Some(b) = &v.branch {
                return Err(invalid(
                    loc(b),
                    format!("point '{name}': `branch` applies to `xyz` points only"),
                ));
            }
            finite(j, &format!("point '{name}' joints"))?;
            let l = loc(j);
            let mut a = Vec::with_capacity(6);
            for (i, x) in j.value.iter().enumerate() {
                a.push(joint_value(*x, l, &format!("point '{name}' axis {}", i + 1))?);
            }
            match a.as_slice() {
                [a1, a2, a3] => Target::Joints {
                    axes_deg: [*a1, *a2, *a3],
                    wrist_deg: None,
                },
                [a1, a2, a3, a4, a5, a6] => Target::Joints {
                    axes_deg: [*a1, *a2, *a3],
                    wrist_deg: Some([*a4, *a5, *a6]),
                },
                _ => {
                    return Err(invalid(
                        l,
                        format!("point '{name}': joints must list axes 1..3 or all six axes, found {} values", a.len()),
                    ))
                }
            }
        }
        (None, Some(x)) => Target::Xyz {
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
        },
        (Some(_), Some(x)) => {
            return Err(invalid(
                loc(x),
                format!("point '{name}' gives both `joints` and `xyz`; give one"),
            ))
        }
        (None, None) => {
            return Err(invalid_help(
                loc(p),
                format!("point '{name}' gives neither `joints` nor `xyz`"),
                "write `joints: [a1, a2, a3]` (controller values, deg) or `xyz: [x, y, z]` (wrist centre, mm)",
            ))
        }
    })
}

/// `planner:`.
fn planner(p: Option<&RawPlanner>) -> Result<Planner, CellError> {
    let mut planner = Planner {
        method: defaults::METHOD,
        grid_deg: defaults::GRID_DEG,
        clearance_mm: defaults::CLEARANCE_MM,
    };
    let Some(p) = p else {
        return Ok(planner);
    };
    if let Some(m) = &p.method {
        planner.method = Method::parse(&m.value).ok_or_else(|| {
            invalid(
                loc(m),
                format!(
                    "planner.method '{}' is not one of neighboring, depth-first, extensile",
                    excerpt::value(&m.value)
                ),
            )
        })?;
    }
    if let Some(g) = &p.grid {
        planner.grid_deg = check_grid(g.value).map_err(|m| invalid(loc(g), m))?;
    }
    if let Some(c) = &p.clearance {
        if !(c.value.is_finite() && c.value >= 0.0) {
            return Err(invalid(
                loc(c),
                "planner.clearance must be a number >= 0 (mm)",
            ));
        }
        planner.clearance_mm = c.value;
    }
    Ok(planner)
}

/// `motion:`.
fn motion(m: Option<&RawMotion>) -> Result<Motion, CellError> {
    Ok(Motion {
        speed: data_name(
            m.and_then(|m| m.speed.as_ref()),
            defaults::SPEED,
            "motion.speed",
        )?,
        zone: data_name(
            m.and_then(|m| m.zone.as_ref()),
            defaults::ZONE,
            "motion.zone",
        )?,
        tool: data_name(
            m.and_then(|m| m.tool.as_ref()),
            defaults::TOOL,
            "motion.tool",
        )?,
    })
}

// ---- across sections ----

/// RAPID names are case-insensitive and share one name space in a module: the module, its
/// `PROC main`, the speed, zone and tool data and the points must not take each other's names.
fn one_name_space(
    module: &str,
    module_loc: Loc,
    points: &[Point],
    motion: &Motion,
) -> Result<(), CellError> {
    let data = [
        ("main", "the module's PROC main"),
        (motion.speed.as_str(), "motion.speed"),
        (motion.zone.as_str(), "motion.zone"),
        (motion.tool.as_str(), "motion.tool"),
    ];
    if let Some((_, what)) = data.iter().find(|(n, _)| n.eq_ignore_ascii_case(module)) {
        return Err(invalid_help(
            module_loc,
            format!("module name '{module}' is already the name of {what}"),
            "RAPID names are case-insensitive and share one name space in a module; rename the module",
        ));
    }
    for p in points {
        let taken = std::iter::once((module, "the module")).chain(data);
        if let Some((_, what)) = taken
            .into_iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(&p.name))
        {
            return Err(invalid_help(
                p.loc,
                format!("point name '{}' is already the name of {what}", p.name),
                "RAPID names are case-insensitive and share one name space in a module; rename the point",
            ));
        }
    }
    Ok(())
}

/// The speed, zone and tool are three RAPID data objects of three types: one name cannot be two
/// of them (a clash with a default counts: `zone: v300` beside the default speed `v300`).
fn distinct_data(motion: &Motion, raw: Option<&RawMotion>) -> Result<(), CellError> {
    let given = |s: Option<&Spanned<String>>| s.map(loc);
    let data = [
        (
            "motion.speed",
            &motion.speed,
            raw.and_then(|m| given(m.speed.as_ref())),
        ),
        (
            "motion.zone",
            &motion.zone,
            raw.and_then(|m| given(m.zone.as_ref())),
        ),
        (
            "motion.tool",
            &motion.tool,
            raw.and_then(|m| given(m.tool.as_ref())),
        ),
    ];
    for (i, first) in data.iter().enumerate() {
        for second in &data[i + 1..] {
            if !first.1.eq_ignore_ascii_case(second.1) {
                continue;
            }
            // Point at the one given last in the file (a default has no place).
            let (this, other) = match (first.2, second.2) {
                (Some(a), Some(b)) if (a.line, a.column) > (b.line, b.column) => (first, second),
                (_, Some(_)) => (second, first),
                (Some(_), None) => (first, second),
                (None, None) => continue,
            };
            let (what, name, at) = (this.0, this.1, this.2.unwrap_or_default());
            let default = if other.2.is_some() {
                ""
            } else {
                " (its default)"
            };
            return Err(invalid_help(
                at,
                format!("{what} '{name}' is already the name of {}{default}", other.0),
                "the speed, zone and tool are three RAPID data of three types (speeddata, zonedata, tooldata); give each its own name",
            ));
        }
    }
    Ok(())
}

/// `base: auto` needs every point as `xyz`: joint values mean nothing until the base is known.
fn every_point_xyz(points: &[Point]) -> Result<(), CellError> {
    match points
        .iter()
        .find(|p| matches!(p.target, Target::Joints { .. }))
    {
        Some(p) => Err(invalid_help(
            p.loc,
            format!("point '{}' gives joint values, but `base: auto` needs every point as `xyz` (joint values mean nothing until the base is known)", p.name),
            "give the point's wrist-centre position `xyz: [x, y, z]` in the cell frame (mm)",
        )),
        None => Ok(()),
    }
}
