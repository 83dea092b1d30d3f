//! The cell file as written ([`RawCell`]) -> a [`Cell`]: one function per YAML section
//! (`points.rs` the points and revisits, `process.rs` how each is reached and left, `actions.rs`
//! what is done there, `tool.rs` the tool, the work objects and the loads, `values.rs` the value
//! checks they share), then the checks that need several sections (the module's one name space,
//! the speeds, zones, tool and signals named apart, the tool and `motion.tool`, `base: auto` with
//! its points).
//! Every refusal points at the value at fault; a value quoted in a message that is not already
//! a RAPID name (at most 32 characters) goes through [`crate::excerpt`].
//!
//! Two rules come from elsewhere, so that the cell and the module cannot disagree: the RAPID
//! identifier rule ([`crate::names`], with the name of a robtarget point's `CONST robtarget`) and
//! the table of output precisions ([`crate::precision`]): a value finer than the module states
//! it is refused, so every value of the cell appears in the module exactly as given
//! (quaternions are normalised, and written to 9 decimals).

mod actions;
mod points;
mod process;
mod tool;
mod values;

#[cfg(test)]
pub(super) use values::orient_zyx;

use super::raw::{RawBase, RawCell, RawMotion, RawObstacle, RawPlanner, RawPoint, RawRobot};
use super::{
    check_grid, defaults, ActionKind, Base, Cell, CellError, Load, Loc, Method, Motion, Obstacle,
    Planner, Point, ProcFrom, RobotFrame, RobotSpec, Target, Tool, Wobj,
};
use crate::excerpt;
use crate::geometry::Aabb;
use crate::names::{check_identifier, robtarget_name, DataType, ROBTARGET_SUFFIX};
use crate::precision::{LENGTH_DECIMALS, YAW_DECIMALS};
use nalgebra::Point3;
use serde_saphyr::Spanned;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use values::{
    bounded, data_name, decimals, identifier, invalid, invalid_help, joint_value, loc, triple,
};

/// Validates every section of a parsed cell file (module docs).
pub(super) fn cell(path: &Path, raw: RawCell) -> Result<Cell, CellError> {
    let module = values::module_name(&raw.module)?;
    let robot = robot(path, &raw.robot)?;
    let obstacles = obstacles(&raw.obstacles)?;
    // The work objects and loads first: points name them.
    let wobjs = tool::wobjs(raw.wobj.as_ref(), raw.wobjs.as_ref())?;
    let loads = tool::loads(raw.loads.as_ref())?;
    let points = points::points(&raw.points, &wobjs, &loads)?;
    let planner = planner(raw.planner.as_ref().map(|p| &p.value))?;
    let raw_motion = raw.motion.as_ref().map(|m| &m.value);
    let mut motion = motion(raw_motion)?;
    let tool = raw.tool.as_ref().map(tool::tool).transpose()?;
    tool_and_motion(tool.as_ref(), raw_motion, &points)?;
    if let Some(t) = &tool {
        motion.tool = t.name.clone();
    }
    let declared = Declared {
        module: &module,
        module_loc: loc(&raw.module),
        tool: tool.as_ref(),
        wobjs: &wobjs,
        loads: &loads,
    };
    one_name_space(&declared, &points, &motion)?;
    distinct_data(
        &motion,
        raw_motion,
        tool.is_some(),
        &raw.points.value,
        &points,
    )?;
    if robot.base == Base::Auto {
        every_point_positioned(&points)?;
    }
    Ok(Cell {
        path: path.to_path_buf(),
        module,
        robot,
        obstacles,
        points,
        planner,
        motion,
        tool,
        wobjs,
        loads,
    })
}

// ---- sections ----

/// The help line of a `robot:` that names no robot.
const MODEL_HELP: &str = "`model: irb2600_12_165` names a robot built into gen-rapid (`gen-rapid robots` lists them), `urdf: FILE` a URDF file (relative to the cell file)";

/// `robot:`.
fn robot(path: &Path, r: &Spanned<RawRobot>) -> Result<RobotSpec, CellError> {
    let whole = loc(r);
    let r = &r.value;
    let dir = path.parent().unwrap_or(Path::new(""));
    let (urdf_path, urdf_loc, model) = match (&r.urdf, &r.model) {
        (Some(u), None) => {
            if u.value.trim().is_empty() {
                return Err(invalid(loc(u), "robot.urdf must name a URDF file"));
            }
            (dir.join(&u.value), loc(u), None)
        }
        (None, Some(m)) => {
            if m.value.trim().is_empty() {
                return Err(invalid_help(
                    loc(m),
                    "robot.model must name a robot",
                    MODEL_HELP,
                ));
            }
            if let Some(c) = &r.controller {
                return Err(invalid_help(
                    loc(c),
                    "robot.controller goes with robot.urdf, not with robot.model",
                    "a shipped model brings its own controller file; to use another, name the URDF with robot.urdf and the controller file with robot.controller",
                ));
            }
            (PathBuf::new(), loc(m), Some(m.value.clone()))
        }
        (Some(_), Some(m)) => {
            return Err(invalid_help(
                loc(m),
                "robot.model and robot.urdf name the robot twice",
                "give one of them: robot.model names a robot built into gen-rapid (`gen-rapid robots` lists them), robot.urdf a URDF file",
            ))
        }
        (None, None) => {
            return Err(invalid_help(
                whole,
                "the robot section names no robot: give robot.model or robot.urdf",
                MODEL_HELP,
            ))
        }
    };
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
        Some(y) => {
            bounded(y, "robot.yaw", "a finite number (deg)")?;
            decimals(y.value, YAW_DECIMALS, loc(y), "robot.yaw", "deg")?
        }
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
    let controller_path = match &r.controller {
        Some(c) if c.value.trim().is_empty() => {
            return Err(invalid(
                loc(c),
                "robot.controller must name a controller file",
            ))
        }
        Some(c) => Some(dir.join(&c.value)),
        None => None,
    };
    let frame = match &r.frame {
        None => RobotFrame::Cell,
        Some(f) => match f.value.as_str() {
            "cell" => RobotFrame::Cell,
            "base" => RobotFrame::Base,
            other => {
                return Err(invalid_help(
                    loc(f),
                    format!("robot.frame '{}' is not cell or base", excerpt::value(other)),
                    "the frame the module writes uframes (and wobj0 robtargets) in: cell (the default: the controller's world frame is the cell's) or base (the robot's base frame, an IRC5's world frame unless configured)",
                ))
            }
        },
    };
    Ok(RobotSpec {
        urdf_path,
        urdf_loc,
        model,
        controller_path,
        controller_loc: r.controller.as_ref().map(loc).unwrap_or_default(),
        base,
        base_loc: loc(&r.base),
        yaw_deg,
        wrist_deg,
        wrist_loc: r.wrist.as_ref().map(loc),
        frame,
        frame_loc: r.frame.as_ref().map(loc).unwrap_or_default(),
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
            return Err(invalid_help(
                loc(&o.value.name),
                format!(
                    "obstacle name '{shown}' is used twice (first at line {})",
                    first.loc.line
                ),
                "give every obstacle its own name: messages name the obstacle a link or a tool shape comes closest to",
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

/// `planner:`.
fn planner(p: Option<&RawPlanner>) -> Result<Planner, CellError> {
    let mut planner = Planner {
        method: defaults::METHOD,
        grid_deg: defaults::GRID_DEG,
        clearance_mm: defaults::CLEARANCE_MM,
        shortcut: defaults::SHORTCUT,
        grid_loc: None,
    };
    let Some(p) = p else {
        return Ok(planner);
    };
    if let Some(m) = &p.method {
        planner.method = Method::parse(&m.value).ok_or_else(|| {
            invalid_help(
                loc(m),
                format!(
                    "planner.method '{}' is not one of neighboring, depth-first, extensile",
                    excerpt::value(&m.value)
                ),
                "the paper's three searches: neighboring (4.1), depth-first (4.2), extensile (4.3, the default); `gen-rapid compare CELL` runs all three",
            )
        })?;
    }
    if let Some(g) = &p.grid {
        planner.grid_deg = check_grid(g.value).map_err(|m| {
            invalid_help(loc(g), m, "planner.grid is the grid spacing d in degrees (default 1; finer is slower and needs more memory: 0.25 deg holds 413 M nodes)")
        })?;
        planner.grid_loc = Some(loc(g));
    }
    if let Some(c) = &p.clearance {
        bounded(c, "planner.clearance", "a number >= 0 (mm)")?;
        if c.value < 0.0 {
            return Err(invalid(
                loc(c),
                "planner.clearance must be a number >= 0 (mm)",
            ));
        }
        planner.clearance_mm = c.value;
    }
    if let Some(s) = &p.shortcut {
        planner.shortcut = s.value;
    }
    Ok(planner)
}

/// `motion:`.
fn motion(m: Option<&RawMotion>) -> Result<Motion, CellError> {
    let (proc, proc_from) = match m.and_then(|m| m.proc.as_ref()) {
        Some(p) => (identifier(p, "motion.proc")?, ProcFrom::Cell(loc(p))),
        None => (defaults::PROC.to_string(), ProcFrom::Default),
    };
    let name = |s: Option<&Spanned<String>>, default: &str, what: &str, ty| match s {
        Some(s) => data_name(s, what, ty),
        None => Ok(default.to_string()),
    };
    Ok(Motion {
        speed: name(
            m.and_then(|m| m.speed.as_ref()),
            defaults::SPEED,
            "motion.speed",
            DataType::Speed,
        )?,
        zone: name(
            m.and_then(|m| m.zone.as_ref()),
            defaults::ZONE,
            "motion.zone",
            DataType::Zone,
        )?,
        tool: name(
            m.and_then(|m| m.tool.as_ref()),
            defaults::TOOL,
            "motion.tool",
            DataType::Tool,
        )?,
        proc,
        proc_from,
        via_zone: match m.and_then(|m| m.via_zone.as_ref()) {
            Some(z) => via_zone(z)?,
            None => defaults::VIA_ZONE.to_string(),
        },
        cycle: m.and_then(|m| m.cycle.as_ref()).is_some_and(|c| c.value),
        cycle_loc: m
            .and_then(|m| m.cycle.as_ref())
            .map(loc)
            .unwrap_or_default(),
    })
}

/// `motion.via_zone`: a RAPID name, and one of the predefined zonedata (`fine`, `z0` ..
/// `z200`): the planner certifies a via's corner with the zone's geometry in mind, and a stop
/// point must be told from a fly-by point, which only the predefined data say here. Written as
/// the table spells it (`Z50` is `z50`).
fn via_zone(z: &Spanned<String>) -> Result<String, CellError> {
    data_name(z, "motion.via_zone", DataType::Zone)?;
    match crate::rapid_data::PREDEFINED_ZONES
        .iter()
        .find(|(name, _)| name.eq_ignore_ascii_case(&z.value))
    {
        Some((name, _)) => Ok(name.to_string()),
        None => Err(invalid_help(
            loc(z),
            format!(
                "motion.via_zone '{}' is not a predefined zonedata",
                excerpt::value(&z.value)
            ),
            "use fine (every via stops) or one of z0, z1, z5, z10, z15, z20, z30, z40, z50, z60, z80, z100, z150, z200",
        )),
    }
}

/// `--proc NAME` (module docs of `cell`): the identifier rule, then the name space again.
pub(super) fn override_proc(cell: &mut Cell, name: &str) -> Result<(), CellError> {
    check_identifier(name).map_err(|e| {
        invalid_help(
            Loc::default(),
            format!(
                "--proc '{}' is not a valid RAPID name: {e}",
                excerpt::value(name)
            ),
            values::IDENTIFIER_HELP,
        )
    })?;
    cell.motion.proc = name.to_string();
    cell.motion.proc_from = ProcFrom::CommandLine;
    let declared = Declared {
        module: &cell.module,
        module_loc: Loc::default(),
        tool: cell.tool.as_ref(),
        wobjs: &cell.wobjs,
        loads: &cell.loads,
    };
    one_name_space(&declared, &cell.points, &cell.motion)
}

// ---- across sections ----

/// The tool the moves use is the `tool:` block's (then `motion.tool` must be absent) or
/// `motion.tool`. Robtarget points are TCP poses of a tool the cell describes: without a `tool:`
/// block that is tool0, so `motion.tool` must then be tool0 too.
fn tool_and_motion(
    tool: Option<&Tool>,
    motion: Option<&RawMotion>,
    points: &[Point],
) -> Result<(), CellError> {
    let Some(given) = motion.and_then(|m| m.tool.as_ref()) else {
        return Ok(());
    };
    if let Some(t) = tool {
        return Err(invalid_help(
            loc(given),
            format!(
                "motion.tool '{}' is given beside the tool block (tool '{}' at line {})",
                given.value, t.name, t.loc.line
            ),
            "with a `tool:` block every move uses that tool; remove motion.tool",
        ));
    }
    let robtarget = points
        .iter()
        .find(|p| matches!(p.target, Target::Robtarget { .. }));
    if let Some(p) = robtarget {
        if !given.value.eq_ignore_ascii_case(defaults::TOOL) {
            return Err(invalid_help(
                loc(given),
                format!(
                    "motion.tool '{}' is not tool0, but point '{}' (line {}) is a robtarget, a TCP pose: gen-rapid must know the tool's TCP",
                    given.value, p.name, p.loc.line
                ),
                "describe the tool in a `tool:` block (name, tframe, shapes) instead of motion.tool",
            ));
        }
    }
    Ok(())
}

/// One name of the module's name space and what it is, for messages.
struct Named<'a> {
    name: String,
    /// "point name", "tool name", ...: how a message introduces it.
    kind: &'a str,
    /// What it is when another name clashes with it ("the module", "tool 'tTorch'").
    what: String,
    loc: Loc,
}

/// The names the module declares outside its points and routine, for [`one_name_space`].
struct Declared<'a> {
    module: &'a str,
    module_loc: Loc,
    tool: Option<&'a Tool>,
    wobjs: &'a [Wobj],
    loads: &'a [Load],
}

/// RAPID names are case-insensitive and share one name space in a module: the names the module
/// declares (the module, the tool, the work objects, the loads, the points and their `CONST
/// robtarget`s, the routine when `motion.proc` or `--proc` names it, last; a revisit declares
/// none) must differ from each other and from the names it uses (`PROC main` by default, every
/// speed and zone, the tool when it is not declared, every signal of an action). A clash of two
/// declared names is refused at the later one's line; a declared name that a used one takes, at
/// the declared name's line (the module can rename what it declares, not the data it uses).
/// Exit status 1, like every input error.
fn one_name_space(d: &Declared, points: &[Point], motion: &Motion) -> Result<(), CellError> {
    let (module, module_loc, tool) = (d.module, d.module_loc, d.tool);
    let mut used: Vec<(String, String)> = vec![
        (motion.speed.clone(), "motion.speed".into()),
        (motion.zone.clone(), "motion.zone".into()),
    ];
    if motion.proc_from == ProcFrom::Default {
        used.insert(
            0,
            (
                motion.proc.clone(),
                format!("the module's PROC {}", motion.proc),
            ),
        );
    }
    if tool.is_none() {
        used.push((motion.tool.clone(), "motion.tool".into()));
    }
    for p in points {
        if let Some(s) = &p.speed {
            used.push((s.clone(), format!("the speed of {}", p.label())));
        }
        if let Some(z) = &p.zone {
            used.push((z.clone(), format!("the zone of {}", p.label())));
        }
        for a in &p.actions {
            if let Some(signal) = a.kind.signal() {
                used.push((
                    signal.to_string(),
                    format!("the signal {signal} (line {})", a.loc.line),
                ));
            }
        }
    }
    let mut declared = vec![Named {
        name: module.to_string(),
        kind: "module name",
        what: "the module".into(),
        loc: module_loc,
    }];

    if let Some(t) = tool {
        declared.push(Named {
            name: t.name.clone(),
            kind: "tool name",
            what: format!("the tool (line {})", t.loc.line),
            loc: t.loc,
        });
    }
    for w in d.wobjs {
        declared.push(Named {
            name: w.name.clone(),
            kind: "work object name",
            what: format!("the work object (line {})", w.loc.line),
            loc: w.loc,
        });
    }
    for l in d.loads {
        declared.push(Named {
            name: l.name.clone(),
            kind: "load name",
            what: format!("the load (line {})", l.loc.line),
            loc: l.loc,
        });
    }
    for p in points.iter().filter(|p| p.revisit_of.is_none()) {
        declared.push(Named {
            name: p.name.clone(),
            kind: "point name",
            what: format!("point '{}' (line {})", p.name, p.loc.line),
            loc: p.loc,
        });
        if matches!(p.target, Target::Robtarget { .. }) {
            declared.push(Named {
                name: robtarget_name(&p.name),
                kind: "robtarget name",
                what: format!("the robtarget of point '{}' (line {})", p.name, p.loc.line),
                loc: p.loc,
            });
        }
        // A MoveC's circle point is written as CONST robtarget <point>_via.
        if let super::Arrival::Circular { via_loc, .. } = p.arrival {
            declared.push(Named {
                name: format!("{}_via", p.name),
                kind: "circle point name",
                what: format!(
                    "the circle point of point '{}' (line {})",
                    p.name, p.loc.line
                ),
                loc: via_loc,
            });
        }
    }
    // The routine last: `motion:` follows the points in a cell file, and `--proc` has no line
    // there, so a clash is told about the routine's name.
    match motion.proc_from {
        ProcFrom::Default => {}
        ProcFrom::Cell(loc) => declared.push(Named {
            name: motion.proc.clone(),
            kind: "routine name",
            what: format!("the routine (motion.proc, line {})", loc.line),
            loc,
        }),
        ProcFrom::CommandLine => declared.push(Named {
            name: motion.proc.clone(),
            kind: "routine name",
            what: "the routine (--proc)".into(),
            loc: Loc::default(),
        }),
    }
    // Each name (RAPID's case folding) and what it first was: the used names first, then
    // the declared ones in order, so a clash names the same as a scan of them in that order.
    let mut taken: HashMap<String, &str> = HashMap::new();
    for (n, w) in &used {
        taken.entry(n.to_ascii_lowercase()).or_insert(w.as_str());
    }
    for d in &declared {
        if d.kind == "robtarget name" {
            check_identifier(&d.name).map_err(|e| {
                invalid_help(
                    d.loc,
                    format!("the robtarget of this point would be named '{}', not a valid RAPID name: {e}", d.name),
                    format!("a robtarget point is written as a CONST jointtarget of its own name and a CONST robtarget named <name>{ROBTARGET_SUFFIX}; shorten the point's name"),
                )
            })?;
        }
        if d.kind == "circle point name" {
            check_identifier(&d.name).map_err(|e| {
                invalid_help(
                    d.loc,
                    format!("the circle point of this move would be named '{}', not a valid RAPID name: {e}", d.name),
                    "a `move: circular` point's circle point is written as a CONST robtarget named <name>_via; shorten the point's name".to_string(),
                )
            })?;
        }
        let key = d.name.to_ascii_lowercase();
        if let Some(what) = taken.get(&key) {
            let rename = d.kind.trim_end_matches(" name");
            let message = match d.kind {
                "robtarget name" => format!(
                    "point '{}' is a robtarget, written as CONST robtarget '{}', which is already the name of {what}",
                    d.name.strip_suffix(ROBTARGET_SUFFIX).unwrap_or(&d.name),
                    d.name
                ),
                _ => format!("{} '{}' is already the name of {what}", d.kind, d.name),
            };
            let rename = if rename == "robtarget" || rename == "circle point" {
                "point"
            } else {
                rename
            };
            return Err(invalid_help(
                d.loc,
                message,
                format!("RAPID names are case-insensitive and share one name space in a module; rename the {rename}"),
            ));
        }
        taken.insert(key, d.what.as_str());
    }
    process::own_pose_names(points)
}

/// One speeddata, zonedata, tooldata or signal name the module uses, for [`distinct_data`].
struct Datum {
    /// The data type: [`SPEED`], [`ZONE`], [`TOOL`], [`OUTPUT`], [`INPUT`], [`ROUTINE`].
    kind: usize,
    /// How a message introduces it ("motion.zone", "point 'P2' zone") and names it as the
    /// datum clashed with ("motion.zone", "the zone of point 'P2'").
    what: String,
    of: String,
    name: String,
    /// Where the cell gives it; `None` for a default.
    loc: Option<Loc>,
}

/// The kinds of [`Datum`]: RAPID data types (a digital output and a digital input signal are
/// `signaldo` and `signaldi`) and the default routine, a name the module uses too.
const SPEED: usize = 0;
const ZONE: usize = 1;
const TOOL: usize = 2;
const OUTPUT: usize = 3;
const INPUT: usize = 4;
const ROUTINE: usize = 5;

/// The speeds, the zones, the tool and the signals the module uses (not declared by it) are
/// RAPID data of five types (speeddata, zonedata, tooldata, signaldo, signaldi), and the default
/// routine `main` is a name it uses too: one name cannot be two of them (a clash with a default
/// counts: `zone: v300` beside the default speed `v300`). The same name twice in one type is one
/// datum, used twice. Refused at the later of the two in the file (a default has no place). The
/// tool of a `tool:` block is declared by the module: [`one_name_space`] has checked it.
fn distinct_data(
    motion: &Motion,
    raw: Option<&RawMotion>,
    tool_block: bool,
    raw_points: &[Spanned<RawPoint>],
    points: &[Point],
) -> Result<(), CellError> {
    let mut data: Vec<Datum> = Vec::new();
    let mut given = |kind: usize, what: String, of: String, name: &str, at: Option<Loc>| {
        data.push(Datum {
            kind,
            what,
            of,
            name: name.to_string(),
            loc: at,
        })
    };
    let key = |what: &str| (what.to_string(), what.to_string());
    let at = |s: Option<&Spanned<String>>| s.map(loc);
    let (what, of) = key("motion.speed");
    given(
        SPEED,
        what,
        of,
        &motion.speed,
        at(raw.and_then(|m| m.speed.as_ref())),
    );
    let (what, of) = key("motion.zone");
    given(
        ZONE,
        what,
        of,
        &motion.zone,
        at(raw.and_then(|m| m.zone.as_ref())),
    );
    if let Some(z) = raw.and_then(|m| m.via_zone.as_ref()) {
        let (what, of) = key("motion.via_zone");
        given(ZONE, what, of, &motion.via_zone, Some(loc(z)));
    }
    if !tool_block {
        let (what, of) = key("motion.tool");
        given(
            TOOL,
            what,
            of,
            &motion.tool,
            at(raw.and_then(|m| m.tool.as_ref())),
        );
    }
    if motion.proc_from == ProcFrom::Default {
        let of = format!("the module's PROC {}", motion.proc);
        given(ROUTINE, of.clone(), of, &motion.proc, None);
    }
    for (p, point) in raw_points.iter().zip(points) {
        let p = &p.value;
        // "point 'P2'", or "the revisit of 'home'".
        let who = match point.revisit_of {
            None => format!("point '{}'", point.name),
            Some(_) => format!("the revisit of '{}'", point.name),
        };
        if let Some(s) = &p.speed {
            let (what, of) = (format!("{who} speed"), format!("the speed of {who}"));
            given(SPEED, what, of, &s.value, Some(loc(s)));
        }
        if let Some(z) = &p.zone {
            let (what, of) = (format!("{who} zone"), format!("the zone of {who}"));
            given(ZONE, what, of, &z.value, Some(loc(z)));
        }
        for a in &point.actions {
            let (kind, key) = match &a.kind {
                ActionKind::SetDo { .. } => (OUTPUT, "set_do"),
                ActionKind::PulseDo { .. } => (OUTPUT, "pulse_do"),
                ActionKind::WaitDi { .. } => (INPUT, "wait_di"),
                ActionKind::WaitTime { .. } | ActionKind::GripLoad { .. } => continue,
            };
            if let Some(signal) = a.kind.signal() {
                let what = format!("{who} {key} signal");
                let of = format!("the {key} signal of {who} (line {})", a.loc.line);
                given(kind, what, of, signal, Some(a.loc));
            }
        }
    }
    // In file order, defaults first; by name (ignoring case), the first datum of each type.
    data.sort_by_key(|d| d.loc.map(|l| (l.line, l.column)));
    let mut first: BTreeMap<String, [Option<usize>; 6]> = BTreeMap::new();
    for (i, d) in data.iter().enumerate() {
        let kinds = first.entry(d.name.to_ascii_lowercase()).or_default();
        if kinds[d.kind].is_some() {
            continue;
        }
        let other = kinds.iter().flatten().next().map(|&k| &data[k]);
        match (other, d.loc) {
            (Some(other), Some(at)) => {
                let default = if other.loc.is_some() {
                    ""
                } else {
                    " (its default)"
                };
                let help = if d.kind <= TOOL && other.kind <= TOOL {
                    "the speed, zone and tool are three RAPID data of three types (speeddata, zonedata, tooldata); give each its own name"
                } else if d.kind == ROUTINE || other.kind == ROUTINE {
                    "the routine shares the module's one name space with the data the moves use; name the routine another way (motion.proc) or the data"
                } else {
                    "a signal is RAPID data of its own type (signaldo, signaldi), in the module's one name space with the routine, the speeds, zones and the tool; one name cannot be two of them"
                };
                return Err(invalid_help(
                    at,
                    format!(
                        "{} '{}' is already the name of {}{default}",
                        d.what, d.name, other.of
                    ),
                    help,
                ));
            }
            // Two defaults (never the same name).
            _ => kinds[d.kind] = Some(i),
        }
    }
    Ok(())
}

/// `base: auto` needs every point as a position (`xyz`) or a pose (`robtarget`): joint values
/// mean nothing until the base is known.
fn every_point_positioned(points: &[Point]) -> Result<(), CellError> {
    match points
        .iter()
        .find(|p| matches!(p.target, Target::Joints { .. }))
    {
        Some(p) => Err(invalid_help(
            p.loc,
            format!("point '{}' gives joint values, but `base: auto` needs every point as `xyz` or `robtarget` (joint values mean nothing until the base is known)", p.name),
            "give the point's wrist-centre position `xyz: [x, y, z]` in the cell frame (mm), or its TCP pose as a robtarget",
        )),
        None => Ok(()),
    }
}
