//! The cell stage: a YAML cell file -> a validated [`Cell`].
//!
//! Parsing is two steps (see [`raw`]): serde types close to the file, unknown keys refused,
//! then checks that need the whole picture (names unique, boxes well formed, joint values in
//! the output's precision). Every error carries a [`Loc`] (line:column in the cell file) so the
//! user sees where the input is at fault. Lengths are millimetres and angles degrees, as in
//! RAPID; paths are relative to the cell file. This module knows nothing of URDF or planning.

mod raw;

use crate::names::check_identifier;
use crate::robot::ik::Branch;
use raw::{RawBase, RawCell};
use serde_saphyr::{Location, Spanned};
use std::path::{Path, PathBuf};

/// Joint values are written with this many decimals; cell values must not need more, so every
/// cell point appears in the module exactly as given.
pub const JOINT_DECIMALS: i32 = 3;

/// A 1-based line and column in the cell file (0 when unknown).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Loc {
    pub line: u64,
    pub column: u64,
}

impl From<Location> for Loc {
    fn from(l: Location) -> Loc {
        Loc {
            line: l.line(),
            column: l.column(),
        }
    }
}

fn loc<T>(s: &Spanned<T>) -> Loc {
    Loc::from(s.referenced)
}

/// Where the robot stands.
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
    /// `base: [x, y, z]`, mm in the cell frame.
    Fixed([f64; 3]),
    /// `base: auto`: chosen by the location stage (paper section 2), on the floor z = 0.
    Auto,
}

#[derive(Clone, Debug, PartialEq)]
pub struct RobotSpec {
    /// Resolved against the cell file's directory.
    pub urdf_path: PathBuf,
    pub urdf_loc: Loc,
    pub base: Base,
    pub base_loc: Loc,
    pub yaw_deg: f64,
    /// Axes 4..6 held during the moves, deg.
    pub wrist_deg: [f64; 3],
}

#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    pub name: String,
    pub min_mm: [f64; 3],
    pub max_mm: [f64; 3],
    pub loc: Loc,
}

/// What a point gives.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    /// Controller values of axes 1..3, and of 4..6 when the point gives all six.
    Joints {
        axes_deg: [f64; 3],
        wrist_deg: Option<[f64; 3]>,
    },
    /// Wrist-centre position in the cell frame (mm), with an optional forced IK branch.
    Xyz {
        wrist_centre_mm: [f64; 3],
        branch: Option<Branch>,
        branch_loc: Loc,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    pub name: String,
    pub target: Target,
    pub loc: Loc,
}

/// The three path searches of the paper (section 4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Method {
    Neighboring,
    DepthFirst,
    Extensile,
}

impl Method {
    pub const ALL: [Method; 3] = [Method::Neighboring, Method::DepthFirst, Method::Extensile];

    pub fn name(self) -> &'static str {
        match self {
            Method::Neighboring => "neighboring",
            Method::DepthFirst => "depth-first",
            Method::Extensile => "extensile",
        }
    }

    pub fn parse(s: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == s)
    }
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Planner {
    pub method: Method,
    pub grid_deg: f64,
    pub clearance_mm: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    pub speed: String,
    pub zone: String,
    pub tool: String,
}

/// A validated cell.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    /// The file it came from (as given on the command line).
    pub path: PathBuf,
    pub module: String,
    pub robot: RobotSpec,
    pub obstacles: Vec<Obstacle>,
    pub points: Vec<Point>,
    pub planner: Planner,
    pub motion: Motion,
}

/// Defaults for keys a cell may leave out.
pub mod defaults {
    pub const METHOD: super::Method = super::Method::Extensile;
    pub const GRID_DEG: f64 = 1.0;
    pub const CLEARANCE_MM: f64 = 10.0;
    pub const SPEED: &str = "v300";
    pub const ZONE: &str = "fine";
    pub const TOOL: &str = "tool0";
    /// Finest grid accepted (deg): 0.25 deg over the IRB 1400's ranges is ~400 M nodes.
    pub const MIN_GRID_DEG: f64 = 0.25;
    pub const MAX_GRID_DEG: f64 = 10.0;
}

/// Why a cell file was refused. Each variant points at the input.
#[derive(Debug, thiserror::Error)]
pub enum CellError {
    #[error("cannot read {path}: {source}")]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{message}")]
    Syntax { loc: Loc, message: String },
    #[error("{message}")]
    Invalid {
        loc: Loc,
        message: String,
        help: Option<String>,
    },
}

impl CellError {
    pub fn loc(&self) -> Option<Loc> {
        match self {
            CellError::Read { .. } => None,
            CellError::Syntax { loc, .. } | CellError::Invalid { loc, .. } => Some(*loc),
        }
    }

    pub fn help(&self) -> Option<&str> {
        match self {
            CellError::Invalid { help, .. } => help.as_deref(),
            _ => None,
        }
    }
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

/// Reads and validates a cell file.
pub fn load(path: &Path) -> Result<(Cell, String), CellError> {
    let text = std::fs::read_to_string(path).map_err(|source| CellError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let cell = parse(path, &text)?;
    Ok((cell, text))
}

/// Validates cell text; `path` names the file (for messages and to resolve the URDF path).
pub fn parse(path: &Path, text: &str) -> Result<Cell, CellError> {
    let raw: RawCell = serde_saphyr::from_str(text).map_err(|e| CellError::Syntax {
        loc: e.location().map(Loc::from).unwrap_or_default(),
        message: syntax_message(&e),
    })?;
    validate(path, raw)
}

/// serde-saphyr renders a snippet of its own; we render ours, so keep the first line only.
fn syntax_message(e: &serde_saphyr::Error) -> String {
    let full = e.to_string();
    let mut msg = full.lines().next().unwrap_or("").trim();
    // Our report says "error:" and gives the place itself; drop the library's own prefixes.
    if let Some(rest) = msg.strip_prefix("error: ") {
        msg = rest;
    }
    if msg.starts_with("line ") {
        if let Some(i) = msg.find(": ") {
            msg = &msg[i + 2..];
        }
    }
    // ... and a trailing " at line N, column M".
    if let Some(i) = msg.rfind(" at line ") {
        if msg[i + 9..]
            .chars()
            .all(|c| c.is_ascii_digit() || c == ',' || c == ' ' || c.is_ascii_lowercase())
        {
            msg = &msg[..i];
        }
    }
    msg.to_string()
}

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
fn decimals(v: f64, n: i32, loc: Loc, what: &str, unit: &str) -> Result<f64, CellError> {
    let scale = 10f64.powi(n);
    if ((v * scale).round() / scale - v).abs() > 1e-9 * v.abs().max(1.0) {
        let s = if n == 1 { "" } else { "s" };
        return Err(invalid_help(
            loc,
            format!("{what} = {v} has more than {n} decimal{s}"),
            format!("the module header states {what} to {n} decimal{s} ({unit}); give no more, so it states what was used"),
        ));
    }
    Ok(v)
}

/// Checks that `v` has at most [`JOINT_DECIMALS`] decimals.
fn joint_value(v: f64, loc: Loc, what: &str) -> Result<f64, CellError> {
    let scale = 10f64.powi(JOINT_DECIMALS);
    let rounded = (v * scale).round() / scale;
    if (rounded - v).abs() > 1e-9 * v.abs().max(1.0) {
        return Err(invalid_help(
            loc,
            format!("{what} = {v} has more than {JOINT_DECIMALS} decimals"),
            format!(
                "gen-rapid writes joint values to 0.{}1 deg; give at most {JOINT_DECIMALS} decimals so the point appears in the module exactly as given",
                "0".repeat(JOINT_DECIMALS as usize - 1)
            ),
        ));
    }
    Ok(rounded)
}

fn identifier(s: &Spanned<String>, what: &str) -> Result<String, CellError> {
    check_identifier(&s.value).map_err(|e| {
        invalid(
            loc(s),
            format!("{what} '{}' is not a valid RAPID name: {e}", s.value),
        )
    })?;
    Ok(s.value.clone())
}

fn data_name(s: Option<&Spanned<String>>, default: &str, what: &str) -> Result<String, CellError> {
    let Some(s) = s else {
        return Ok(default.to_string());
    };
    let v = &s.value;
    let ok = v.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && v.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && v.len() <= 32;
    if ok {
        Ok(v.clone())
    } else {
        Err(invalid(
            loc(s),
            format!("{what} '{v}' is not a RAPID data name (a letter, then letters, digits or _, at most 32 characters)"),
        ))
    }
}

fn validate(path: &Path, raw: RawCell) -> Result<Cell, CellError> {
    let module = identifier(&raw.module, "module")?;

    // Robot.
    let r = &raw.robot.value;
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
                decimals(x, 1, loc(&v), "robot.base", "mm")?;
            }
            Base::Fixed(b)
        }
    };
    let yaw_deg = match &r.yaw {
        Some(y) if !y.value.is_finite() => {
            return Err(invalid(loc(y), "robot.yaw must be a finite number (deg)"))
        }
        Some(y) => decimals(y.value, JOINT_DECIMALS, loc(y), "robot.yaw", "deg")?,
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

    // Obstacles.
    let mut obstacles: Vec<Obstacle> = Vec::new();
    for o in &raw.obstacles {
        let name = o.value.name.value.clone();
        if name.trim().is_empty() {
            return Err(invalid(loc(&o.value.name), "an obstacle needs a name"));
        }
        if let Some(first) = obstacles.iter().find(|p| p.name == name) {
            return Err(invalid(
                loc(&o.value.name),
                format!(
                    "obstacle name '{name}' is used twice (first at line {})",
                    first.loc.line
                ),
            ));
        }
        let min_mm = triple(
            &o.value.aabb.value.min,
            &format!("obstacle '{name}' box.min"),
        )?;
        let max_mm = triple(
            &o.value.aabb.value.max,
            &format!("obstacle '{name}' box.max"),
        )?;
        if let Some(i) = (0..3).find(|&i| min_mm[i] >= max_mm[i]) {
            return Err(invalid_help(
                loc(&o.value.aabb),
                format!(
                    "obstacle '{name}': box.min {} = {} is not below box.max {} = {}",
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
            min_mm,
            max_mm,
            loc: loc(o),
        });
    }

    // Points.
    if raw.points.value.len() < 2 {
        return Err(invalid(
            loc(&raw.points),
            format!(
                "a cell needs at least 2 points (a start and an end), found {}",
                raw.points.value.len()
            ),
        ));
    }
    let mut points: Vec<Point> = Vec::new();
    for p in &raw.points.value {
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
        let target = match (&p.value.joints, &p.value.xyz) {
            (Some(j), None) => {
                if let Some(b) = &p.value.branch {
                    return Err(invalid(loc(b), format!("point '{name}': `branch` applies to `xyz` points only")));
                }
                finite(j, &format!("point '{name}' joints"))?;
                let l = loc(j);
                let mut v = Vec::with_capacity(6);
                for (i, x) in j.value.iter().enumerate() {
                    v.push(joint_value(*x, l, &format!("point '{name}' axis {}", i + 1))?);
                }
                match v.as_slice() {
                    [a, b, c] => Target::Joints {
                        axes_deg: [*a, *b, *c],
                        wrist_deg: None,
                    },
                    [a, b, c, d, e, f] => Target::Joints {
                        axes_deg: [*a, *b, *c],
                        wrist_deg: Some([*d, *e, *f]),
                    },
                    _ => {
                        return Err(invalid(
                            l,
                            format!("point '{name}': joints must list axes 1..3 or all six axes, found {} values", v.len()),
                        ))
                    }
                }
            }
            (None, Some(x)) => Target::Xyz {
                wrist_centre_mm: triple(x, &format!("point '{name}' xyz"))?,
                branch: match &p.value.branch {
                    Some(b) => Some(b.value.parse::<Branch>().map_err(|why| {
                        invalid(loc(b), format!("point '{name}': {why}"))
                    })?),
                    None => None,
                },
                branch_loc: p.value.branch.as_ref().map(loc).unwrap_or_default(),
            },
            (Some(_), Some(x)) => {
                return Err(invalid(loc(x), format!("point '{name}' gives both `joints` and `xyz`; give one")))
            }
            (None, None) => {
                return Err(invalid_help(
                    loc(p),
                    format!("point '{name}' gives neither `joints` nor `xyz`"),
                    "write `joints: [a1, a2, a3]` (controller values, deg) or `xyz: [x, y, z]` (wrist centre, mm)",
                ))
            }
        };
        points.push(Point {
            name,
            target,
            loc: loc(p),
        });
    }

    // Planner.
    let mut planner = Planner {
        method: defaults::METHOD,
        grid_deg: defaults::GRID_DEG,
        clearance_mm: defaults::CLEARANCE_MM,
    };
    if let Some(p) = &raw.planner {
        if let Some(m) = &p.value.method {
            planner.method = Method::parse(&m.value).ok_or_else(|| {
                invalid(
                    loc(m),
                    format!(
                        "planner.method '{}' is not one of neighboring, depth-first, extensile",
                        m.value
                    ),
                )
            })?;
        }
        if let Some(g) = &p.value.grid {
            planner.grid_deg = check_grid(g.value).map_err(|m| invalid(loc(g), m))?;
        }
        if let Some(c) = &p.value.clearance {
            if !(c.value.is_finite() && c.value >= 0.0) {
                return Err(invalid(
                    loc(c),
                    "planner.clearance must be a number >= 0 (mm)",
                ));
            }
            planner.clearance_mm = c.value;
        }
    }

    // Motion.
    let m = raw.motion.as_ref().map(|m| &m.value);
    let motion = Motion {
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
    };

    // The module's own names: a point named like one of them would clash in the RAPID text.
    let taken = [
        (module.as_str(), "the module"),
        ("main", "the module's PROC main"),
        (motion.speed.as_str(), "motion.speed"),
        (motion.zone.as_str(), "motion.zone"),
        (motion.tool.as_str(), "motion.tool"),
    ];
    for p in &points {
        if let Some((_, what)) = taken.iter().find(|(n, _)| n.eq_ignore_ascii_case(&p.name)) {
            return Err(invalid_help(
                p.loc,
                format!("point name '{}' is already the name of {what}", p.name),
                "RAPID names are case-insensitive and share one name space in a module; rename the point",
            ));
        }
    }

    Ok(Cell {
        path: path.to_path_buf(),
        module,
        robot: RobotSpec {
            urdf_path,
            urdf_loc: loc(&r.urdf),
            base,
            base_loc: loc(&r.base),
            yaw_deg,
            wrist_deg,
        },
        obstacles,
        points,
        planner,
        motion,
    })
}

/// Checks a grid spacing (deg): within [MIN_GRID_DEG, MAX_GRID_DEG].
pub fn check_grid(g: f64) -> Result<f64, String> {
    if g.is_finite() && (defaults::MIN_GRID_DEG..=defaults::MAX_GRID_DEG).contains(&g) {
        Ok(g)
    } else {
        Err(format!(
            "grid spacing {g} deg is outside {} .. {} deg",
            defaults::MIN_GRID_DEG,
            defaults::MAX_GRID_DEG
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = "module: M\nrobot:\n  urdf: ../robots/r.urdf\n  base: [1, 2, 3]\npoints:\n  - { name: A, joints: [1, 2, 3] }\n  - { name: B, joints: [4, 5, 6, 7, 8, 9] }\n";

    fn parse_str(text: &str) -> Result<Cell, CellError> {
        parse(Path::new("cells/x.yaml"), text)
    }

    #[test]
    fn defaults_fill_what_a_cell_leaves_out() {
        let c = parse_str(MINIMAL).expect("valid");
        assert_eq!(c.robot.urdf_path, Path::new("cells/../robots/r.urdf"));
        assert_eq!(c.robot.base, Base::Fixed([1.0, 2.0, 3.0]));
        assert_eq!((c.robot.yaw_deg, c.robot.wrist_deg), (0.0, [0.0; 3]));
        assert_eq!(
            c.planner,
            Planner {
                method: Method::Extensile,
                grid_deg: 1.0,
                clearance_mm: 10.0
            }
        );
        assert_eq!(
            (
                c.motion.speed.as_str(),
                c.motion.zone.as_str(),
                c.motion.tool.as_str()
            ),
            ("v300", "fine", "tool0")
        );
        assert!(c.obstacles.is_empty());
        assert_eq!(
            c.points[1].target,
            Target::Joints {
                axes_deg: [4.0, 5.0, 6.0],
                wrist_deg: Some([7.0, 8.0, 9.0])
            }
        );
    }

    #[test]
    fn points_carry_their_line_and_column() {
        let c = parse_str(MINIMAL).expect("valid");
        assert_eq!(c.points[0].loc.line, 6);
        assert_eq!(c.points[1].loc.line, 7);
        assert!(c.points[0].loc.column > 0);
    }

    #[test]
    fn base_auto_and_xyz_points_with_a_branch() {
        let text = MINIMAL
            .replace("base: [1, 2, 3]", "base: auto")
            .replace(
                "joints: [1, 2, 3]",
                "xyz: [900, 0, 1000], branch: back-elbow-up",
            )
            .replace("joints: [4, 5, 6, 7, 8, 9]", "xyz: [0, 900, 1000]");
        let c = parse_str(&text).expect("valid");
        assert_eq!(c.robot.base, Base::Auto);
        match &c.points[0].target {
            Target::Xyz {
                wrist_centre_mm,
                branch,
                branch_loc,
            } => {
                assert_eq!(*wrist_centre_mm, [900.0, 0.0, 1000.0]);
                assert_eq!(*branch, Some(Branch::BackElbowUp));
                assert_eq!(branch_loc.line, 6);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn refusals_name_the_key_and_its_place() {
        let cases = [
            (
                MINIMAL.replace("base: [1, 2, 3]", "base: [1, 2]"),
                "robot.base must have 3 numbers",
                4,
            ),
            (
                MINIMAL.replace("base: [1, 2, 3]", "base: somewhere"),
                "auto",
                4,
            ),
            (
                MINIMAL.replace("base: [1, 2, 3]", "base: [1, 2.25, 3]"),
                "more than 1 decimal",
                4,
            ),
            (
                MINIMAL.replace("base: [1, 2, 3]", "base: [1, 2, 3]\n  yaw: 45.0004"),
                "robot.yaw",
                5,
            ),
            (
                MINIMAL.replace("joints: [1, 2, 3]", "xyz: [900, 0, 1000], branch: sideways"),
                "unknown branch",
                6,
            ),
            (
                MINIMAL.replace("joints: [1, 2, 3]", "joints: [1, 2, 3], xyz: [1, 2, 3]"),
                "both",
                6,
            ),
            (
                MINIMAL.replace("{ name: A, joints: [1, 2, 3] }", "{ name: A }"),
                "neither",
                6,
            ),
            (
                MINIMAL.replace(
                    "joints: [1, 2, 3]",
                    "joints: [1, 2, 3], branch: front-elbow-up",
                ),
                "xyz",
                6,
            ),
            (
                MINIMAL.replace("module: M", "module: 9lives"),
                "not a valid RAPID name",
                1,
            ),
            (
                format!("{MINIMAL}motion:\n  speed: 'v 300'\n"),
                "motion.speed",
                9,
            ),
            (
                format!("{MINIMAL}planner:\n  clearance: -1\n"),
                "clearance",
                9,
            ),
        ];
        for (text, needle, line) in cases {
            let err = parse_str(&text).expect_err(needle);
            assert!(err.to_string().contains(needle), "'{err}' lacks '{needle}'");
            assert_eq!(err.loc().map(|l| l.line), Some(line), "{err}");
        }
    }

    #[test]
    fn joint_values_keep_at_most_three_decimals() {
        assert!(
            parse_str(&MINIMAL.replace("joints: [1, 2, 3]", "joints: [1.125, -2.5, 3.001]"))
                .is_ok()
        );
        let err = parse_str(&MINIMAL.replace("joints: [1, 2, 3]", "joints: [1.0005, 2, 3]"))
            .expect_err("4 decimals");
        assert!(err.help().is_some_and(|h| h.contains("0.001")), "{err}");
    }

    #[test]
    fn methods_parse_by_their_names() {
        for m in Method::ALL {
            assert_eq!(Method::parse(m.name()), Some(m));
        }
        assert_eq!(Method::parse("Extensile"), None);
        assert!(check_grid(0.25).is_ok() && check_grid(10.0).is_ok());
        assert!(check_grid(0.2).is_err() && check_grid(f64::NAN).is_err());
    }
}
