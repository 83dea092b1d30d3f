//! The load stage, part 1: a YAML cell file -> a validated [`Cell`].
//!
//! Parsing is two steps: `raw.rs` holds serde types close to the file (unknown keys refused,
//! spans kept), then `validate.rs` checks each section and what needs the whole picture (names
//! unique in the module's one name space, boxes well formed, values no finer than the module
//! can state them). Every error carries a [`Loc`] (line:column in the cell file) so the user
//! sees where the input is at fault. Lengths are millimetres and angles degrees, as in RAPID;
//! paths are relative to the cell file. This module reads no URDF and plans nothing: it says
//! what a point may ask of the robot in the robot's own terms (the IK [`Branch`] an `xyz` point
//! may force, the [`ConfData`] a robtarget may ask for), and names the search [`Method`] the
//! planner runs.
//!
//! What the cell says about the tool and the TCP: a `tool:` block ([`Tool`]: tooldata
//! name, TCP frame in the flange frame, load, collision shapes), a `wobj:` block ([`Wobj`]: the
//! user frame robtargets are given in; without it wobj0, whose frame is the cell frame), points
//! as robtargets ([`Target::Robtarget`]: the TCP pose in the work object, with or without
//! confdata), and per-point `speed`/`zone` (the move into the point). Quaternions are
//! `[w, x, y, z]` (RAPID's `[q1, q2, q3, q4]`), normalised when read; a norm off by more than
//! [`QUATERNION_NORM_TOL`] is refused as a typo.
//!
//! What the cell says about the process (docs/cell.md): how each point is reached
//! ([`Arrival`]: the planned joint route, or a `linear` / `circular` process move), an
//! approach and a retract line along the TCP's z axis, the [`Action`]s at the point, the
//! loaddata the module declares ([`Load`], for `grip_load`); several work objects (each robtarget
//! point names its own, [`Point::wobj`]), orientations as RAPID's `OrientZYX` angles (read into
//! the same normalised quaternions), revisits of a point's target ([`Point::revisit_of`]), the
//! closed cycle ([`Motion::cycle`]) and the frame uframes are written in ([`RobotFrame`]).

mod present;
mod raw;
mod syntax;
mod validate;

use crate::geometry::Aabb;
use crate::robot::ik::six::ConfData;
use crate::robot::ik::Branch;
use serde_saphyr::Location;
use std::path::{Path, PathBuf};

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

/// Where the robot stands.
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
    /// `base: [x, y, z]`, mm in the cell frame.
    Fixed([f64; 3]),
    /// `base: auto`: chosen by the place stage (paper section 2), on the floor z = 0.
    Auto,
}

/// How far a quaternion's norm may be off 1 before it is refused.
pub const QUATERNION_NORM_TOL: f64 = 1e-3;

#[derive(Clone, Debug, PartialEq)]
pub struct RobotSpec {
    /// `robot.urdf`, resolved against the cell file's directory; empty with `robot.model`.
    pub urdf_path: PathBuf,
    /// Where the robot is named: `robot.urdf`'s value, or `robot.model`'s.
    pub urdf_loc: Loc,
    /// `robot.model`: a robot built into gen-rapid, by name (the load stage knows the names);
    /// `None` with `robot.urdf`.
    pub model: Option<String>,
    /// `robot.controller`: the controller file named explicitly, resolved against the cell
    /// file's directory. `None`: the `<stem>.controller.yaml` beside the URDF, if there is one.
    pub controller_path: Option<PathBuf>,
    pub controller_loc: Loc,
    pub base: Base,
    pub base_loc: Loc,
    pub yaw_deg: f64,
    /// Axes 4..6 held during the moves, deg.
    pub wrist_deg: [f64; 3],
    /// Where `robot.wrist` is given (`None`: the default).
    pub wrist_loc: Option<Loc>,
    /// `robot.frame`: the frame the module writes uframes and wobj0 robtargets in.
    pub frame: RobotFrame,
    /// Where `robot.frame` is given (the default: `Loc::default()`).
    pub frame_loc: Loc,
}

/// `robot.frame`: the frame the module writes work objects' uframes (and robtargets in wobj0)
/// in. The cell itself always gives them in the cell frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RobotFrame {
    /// The cell frame (the controller's world frame set to the cell's, the default).
    #[default]
    Cell,
    /// The robot's base frame (an IRC5 whose world frame is its base frame).
    Base,
}

/// A box obstacle of the cell: THE obstacle type (the collision model and the location stage
/// use it as it is).
#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    /// Name used in messages.
    pub name: String,
    /// The box, cell frame, mm.
    pub aabb: Aabb,
    /// Where the cell file gives it.
    pub loc: Loc,
}

impl Obstacle {
    /// An obstacle made in code (no place in a cell file).
    pub fn new(name: impl Into<String>, aabb: Aabb) -> Obstacle {
        Obstacle {
            name: name.into(),
            aabb,
            loc: Loc::default(),
        }
    }
}

/// A frame (pose) as RAPID writes it: a position, mm, and a unit quaternion `[w, x, y, z]`
/// (normalised when the cell is read). Used for the tool's `tframe` (TCP in the flange frame), the
/// work object's `uframe` (user frame in the cell frame) and robtarget poses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub pos_mm: [f64; 3],
    /// `[w, x, y, z]`, unit norm.
    pub quat_wxyz: [f64; 4],
}

impl Frame {
    /// The identity frame.
    pub const IDENTITY: Frame = Frame {
        pos_mm: [0.0, 0.0, 0.0],
        quat_wxyz: [1.0, 0.0, 0.0, 0.0],
    };

    /// The frame as the module writes it (positions to [`POSITION_DECIMALS`], quaternion
    /// components to [`QUATERNION_DECIMALS`]): what the controller reads. Its
    /// [`isometry`](Self::isometry) normalises the quaternion, as the controller does.
    ///
    /// [`POSITION_DECIMALS`]: crate::precision::POSITION_DECIMALS
    /// [`QUATERNION_DECIMALS`]: crate::precision::QUATERNION_DECIMALS
    pub fn written(&self) -> Frame {
        use crate::precision::{round, POSITION_DECIMALS, QUATERNION_DECIMALS};
        Frame {
            pos_mm: self.pos_mm.map(|v| round(v, POSITION_DECIMALS)),
            quat_wxyz: self.quat_wxyz.map(|v| round(v, QUATERNION_DECIMALS)),
        }
    }

    /// The frame as a rigid transform (mm).
    pub fn isometry(&self) -> nalgebra::Isometry3<f64> {
        let [w, x, y, z] = self.quat_wxyz;
        nalgebra::Isometry3::from_parts(
            nalgebra::Translation3::new(self.pos_mm[0], self.pos_mm[1], self.pos_mm[2]),
            nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z)),
        )
    }
}

/// The geometry of one tool shape, in the flange (tool0) frame, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ToolGeometry {
    /// A solid cylinder from `from_mm` to `to_mm` (axis end points) of `radius_mm`.
    Cylinder {
        from_mm: [f64; 3],
        to_mm: [f64; 3],
        radius_mm: f64,
    },
    /// A box, axis-aligned in the flange frame.
    Box { min_mm: [f64; 3], max_mm: [f64; 3] },
    /// A ball.
    Sphere { centre_mm: [f64; 3], radius_mm: f64 },
}

/// One collision volume of the tool, carried by axes 4..6 with the flange.
#[derive(Clone, Debug, PartialEq)]
pub struct ToolShape {
    /// Used in messages ("tool shape 'neck' comes within ...").
    pub name: String,
    pub geometry: ToolGeometry,
    pub loc: Loc,
}

/// The cell's `tool:` block: the tooldata to declare and the tool's collision volumes.
#[derive(Clone, Debug, PartialEq)]
pub struct Tool {
    /// tooldata name (a RAPID identifier, not `tool0`).
    pub name: String,
    /// The TCP in the flange (tool0) frame.
    pub tframe: Frame,
    /// Load, kg (> 0).
    pub mass_kg: f64,
    /// Centre of gravity in the flange frame, mm.
    pub cog_mm: [f64; 3],
    pub shapes: Vec<ToolShape>,
    pub loc: Loc,
}

/// A work object of the cell (`wobj:`, or an entry of `wobjs:`): a frame robtarget points are
/// given in.
#[derive(Clone, Debug, PartialEq)]
pub struct Wobj {
    /// wobjdata name (a RAPID identifier, not `wobj0`).
    pub name: String,
    /// The user frame in the cell frame.
    pub uframe: Frame,
    /// Where its name is given.
    pub loc: Loc,
}

/// An entry of `loads:`: loaddata the module declares, for a `grip_load` action.
#[derive(Clone, Debug, PartialEq)]
pub struct Load {
    /// loaddata name (a RAPID identifier in the module's name space, not `load0`).
    pub name: String,
    /// kg, > 0, at most 3 decimals (the module's).
    pub mass_kg: f64,
    /// Centre of gravity in the tool frame, mm (default `[0, 0, 0]`).
    pub cog_mm: [f64; 3],
    /// Where its name is given.
    pub loc: Loc,
}

/// How the TCP reaches a point from where the previous entry left it (`move:`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Arrival {
    /// `joint` (the default): the planned, proven joint route.
    Joint,
    /// `linear`: the straight line from the previous TCP pose, the orientation turning evenly
    /// (MoveL). The point's target is a robtarget, the previous entry has no retract.
    Linear,
    /// `circular`: the arc through the previous TCP pose, `via_mm` and the point (MoveC). As for
    /// `Linear`; whether the three points make an arc is the place stage's to check.
    Circular {
        /// A point of the arc, mm in the point's work object frame (at most 3 decimals).
        via_mm: [f64; 3],
        /// Where `via` is given.
        via_loc: Loc,
    },
}

impl Arrival {
    /// A process move (`linear` or `circular`), not the planned route.
    pub fn is_process(&self) -> bool {
        !matches!(self, Arrival::Joint)
    }
}

/// One action of a point's `do:` list, done in order after the move into the point has ended
/// (the point is reached `fine`) and before its retract.
#[derive(Clone, Debug, PartialEq)]
pub struct Action {
    pub kind: ActionKind,
    /// Where the action is given.
    pub loc: Loc,
}

/// What an action does, with its arguments as RAPID takes them. Signal names are RAPID
/// identifiers of signals declared on the controller (the module does not declare them).
#[derive(Clone, Debug, PartialEq)]
pub enum ActionKind {
    /// `{ set_do: [signal, 0|1] }`: `SetDO signal, 0|1;` (`value` true is 1).
    SetDo { signal: String, value: bool },
    /// `{ pulse_do: signal }`: `PulseDO signal;`.
    PulseDo { signal: String },
    /// `{ wait_di: [signal, 0|1] }`: `WaitDI signal, 0|1;` (`value` true is 1).
    WaitDi { signal: String, value: bool },
    /// `{ wait_time: s }`: `WaitTime s;` (0 .. 3600 s, at most 3 decimals).
    WaitTime { time_s: f64 },
    /// `{ grip_load: name }`: `GripLoad name;`. `None`: the predefined `load0` (nothing held);
    /// `Some(i)`: `Cell::loads[i]`.
    GripLoad { load: Option<usize> },
}

impl ActionKind {
    /// The signal an I/O action names.
    pub fn signal(&self) -> Option<&str> {
        match self {
            ActionKind::SetDo { signal, .. }
            | ActionKind::PulseDo { signal }
            | ActionKind::WaitDi { signal, .. } => Some(signal),
            ActionKind::WaitTime { .. } | ActionKind::GripLoad { .. } => None,
        }
    }
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
    /// A robtarget: the TCP pose in the work object's frame (mm, normalised quaternion), and the
    /// configuration asked for, if any.
    Robtarget { pose: Frame, conf: Option<ConfData> },
}

/// One entry of `points:`, in the order visited: a point, or a revisit of one (`{ revisit:
/// NAME }`), which takes the named point's target (and work object) and nothing else.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// The point's name; a revisit's is the name of the point it revisits (it declares none).
    pub name: String,
    /// What the point gives; a revisit's is a copy of the revisited point's.
    pub target: Target,
    /// The speeddata of the move into this point, its approach line and its retract line
    /// (`None`: `motion.speed`).
    pub speed: Option<String>,
    /// The zonedata of the move into this point (`None`: `motion.zone`). A point that
    /// [`stops`](Point::stops) is reached `fine` whatever `motion.zone` says; its own zone, if
    /// given, is `fine` (validation refuses another).
    pub zone: Option<String>,
    /// Where the entry is given (its `{` or, written as block lines, its first key).
    pub loc: Loc,
    /// How it is reached (`move:`); on the first entry always [`Arrival::Joint`].
    pub arrival: Arrival,
    /// Where `move:` is given (the entry's `loc` when it is not).
    pub arrival_loc: Loc,
    /// `approach`: the route ends this far (mm, 1 .. 1000, at most 3 decimals) back along the
    /// target's TCP z axis (`RelTool(p, 0, 0, -D)`), and a linear move enters the point. Only on
    /// robtarget targets reached by [`Arrival::Joint`], never on the first entry.
    pub approach_mm: Option<f64>,
    /// Where `approach` is given.
    pub approach_loc: Loc,
    /// `retract`: after the actions, a linear move this far (mm, as `approach_mm`) back along the
    /// TCP z axis; the next move starts there (and is not `linear` or `circular`). Robtarget
    /// targets only; allowed on the last entry.
    pub retract_mm: Option<f64>,
    /// Where `retract` is given.
    pub retract_loc: Loc,
    /// `do`: the actions at the point, in order.
    pub actions: Vec<Action>,
    /// The work object a robtarget target is given in: an index into [`Cell::wobjs`]; `None`:
    /// wobj0 (the cell declares none) or not a robtarget.
    pub wobj: Option<usize>,
    /// A revisit: the index in [`Cell::points`] of the point whose target (and work object) it
    /// reaches again, never itself a revisit. The module declares that point's data once.
    pub revisit_of: Option<usize>,
}

impl Point {
    /// The point is reached `fine`: it has actions, an approach line into it or a retract line
    /// out of it.
    pub fn stops(&self) -> bool {
        !self.actions.is_empty() || self.approach_mm.is_some() || self.retract_mm.is_some()
    }

    /// How messages name the entry: `point 'P2'`, or `the revisit of 'home' (line 12)`.
    pub fn label(&self) -> String {
        match self.revisit_of {
            None => format!("point '{}'", self.name),
            Some(_) => format!("the revisit of '{}' (line {})", self.name, self.loc.line),
        }
    }
}

/// The three path searches of the paper (section 4), as `planner.method` names them (the
/// searches themselves are `plan::search`'s).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Method {
    Neighboring,
    DepthFirst,
    Extensile,
}

impl Method {
    pub const ALL: [Method; 3] = [Method::Neighboring, Method::DepthFirst, Method::Extensile];

    /// The name the cell file and the command line use.
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
    /// `planner.shortcut`: after the paper's method, the continuous shortcut pass (`refine`).
    /// `false` keeps the paper's method alone.
    pub shortcut: bool,
    /// Where `planner.grid` is given (`None`: the default), for a budget the grid passes.
    pub grid_loc: Option<Loc>,
}

/// The cell's `motion:` defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// speeddata of a move into a point without its own `speed`.
    pub speed: String,
    /// zonedata of a move into a point without its own `zone`.
    pub zone: String,
    /// The tooldata every move uses: the `tool:` block's name when there is one, else
    /// `motion.tool`.
    pub tool: String,
    /// The name of the routine that makes the moves (`motion.proc`, or `--proc`; default
    /// `main`): a RAPID identifier in the module's one name space.
    pub proc: String,
    /// Where that name comes from.
    pub proc_from: ProcFrom,
    /// `motion.via_zone`: the predefined zonedata a via gets where its corner is proven
    /// (`refine::zones`); `fine` (the default) keeps every via a stop point.
    pub via_zone: String,
    /// `motion.cycle`: the routine ends where it starts, by a leg from the last entry back to the
    /// first (at `motion.speed`, without the first entry's zone or actions), unless the last
    /// entry already reaches the first one's target ([`Cell::closing_leg`]).
    pub cycle: bool,
    /// Where `motion.cycle` is given (the default: `Loc::default()`).
    pub cycle_loc: Loc,
}

/// Where the routine's name comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProcFrom {
    /// Not given: [`defaults::PROC`].
    Default,
    /// `motion.proc`, at this place of the cell file.
    Cell(Loc),
    /// `--proc NAME` on the command line (it overrides `motion.proc`).
    CommandLine,
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
    /// The `tool:` block; without it the TCP is tool0 (the flange) and there is no tool volume.
    pub tool: Option<Tool>,
    /// The work objects (`wobj:` gives one, `wobjs:` any number), in the cell's order; each
    /// robtarget point names its own ([`Point::wobj`]). None: robtargets are in wobj0, whose
    /// frame is the cell frame.
    pub wobjs: Vec<Wobj>,
    /// `loads:`: the loaddata the module declares, in the cell's order.
    pub loads: Vec<Load>,
}

impl Cell {
    /// The work object point `p` is given in (`None`: wobj0).
    pub fn wobj_of(&self, p: &Point) -> Option<&Wobj> {
        p.wobj.and_then(|i| self.wobjs.get(i))
    }

    /// With `motion.cycle`, the routine needs a leg from the last entry back to the first: the
    /// last entry does not already end at the first one's target (a revisit of it, or the point
    /// a first revisit names, without a retract).
    pub fn closing_leg(&self) -> bool {
        let origin = |i: usize| self.points.get(i).and_then(|p| p.revisit_of).unwrap_or(i);
        let n = self.points.len();
        let retracts = self.points.last().is_some_and(|p| p.retract_mm.is_some());
        self.motion.cycle && n > 1 && (origin(0) != origin(n - 1) || retracts)
    }
}

/// Defaults for keys a cell may leave out.
pub mod defaults {
    pub const METHOD: super::Method = super::Method::Extensile;
    pub const GRID_DEG: f64 = 1.0;
    pub const CLEARANCE_MM: f64 = 10.0;
    pub const SPEED: &str = "v300";
    pub const ZONE: &str = "fine";
    pub const VIA_ZONE: &str = "fine";
    pub const SHORTCUT: bool = true;
    pub const TOOL: &str = "tool0";
    /// The routine's name.
    pub const PROC: &str = "main";
    /// The load of a `tool:` block that states no `mass`, kg.
    pub const TOOL_MASS_KG: f64 = 1.0;
    /// The range of `approach` and `retract`, mm.
    pub const MIN_OFFSET_MM: f64 = 1.0;
    pub const MAX_OFFSET_MM: f64 = 1000.0;
    /// The longest `wait_time`, s.
    pub const MAX_WAIT_S: f64 = 3600.0;
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
    /// The YAML reader refused the text (or it is not UTF-8); `help` for the common slips.
    #[error("{message}")]
    Syntax {
        loc: Loc,
        message: String,
        help: Option<String>,
    },
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
            CellError::Syntax { help, .. } | CellError::Invalid { help, .. } => Some(
                help.as_deref()
                    .unwrap_or("docs/cell.md describes every key and the values it takes"),
            ),
            CellError::Read { .. } => Some(
                "CELL is the path of a cell file (YAML text); `gen-rapid --help` shows a minimal cell",
            ),
        }
    }
}

/// Reads a cell file's text (the load stage's one read of it): [`text_of`] its bytes.
pub fn read(path: &Path) -> Result<String, CellError> {
    let bytes = crate::input::read_bytes(path).map_err(|source| CellError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    text_of(bytes)
}

/// A cell file's bytes as text: UTF-8, or refused at the first byte that is not.
pub fn text_of(bytes: Vec<u8>) -> Result<String, CellError> {
    String::from_utf8(bytes).map_err(|e| syntax::not_utf8(e.as_bytes(), &e.utf8_error()))
}

/// Reads and validates a cell file; returns the cell and its text.
pub fn load(path: &Path) -> Result<(Cell, String), CellError> {
    let text = read(path)?;
    let cell = parse(path, &text)?;
    Ok((cell, text))
}

/// Validates cell text; `path` names the file (for messages and to resolve the URDF path).
pub fn parse(path: &Path, text: &str) -> Result<Cell, CellError> {
    // The reader's bounds on alias expansion, less its ratio of aliases to anchors: a cell may
    // well alias one anchor (a quaternion, a tool's orientation) at a hundred points; the
    // absolute bounds still stop a file that expands without end.
    let mut budget = serde_saphyr::Budget::default();
    budget.enforce_alias_anchor_ratio = false;
    let mut options = serde_saphyr::Options::default();
    options.budget = Some(budget);
    let raw: raw::RawCell = serde_saphyr::from_str_with_options(text, options.clone())
        .map_err(|e| syntax::refusal(text, &e))?;
    if let Some(e) = present::first_key_without_value(text, options) {
        return Err(e);
    }
    validate::cell(path, raw)
}

/// Names the routine `name` (`--proc NAME`, overriding `motion.proc`): the RAPID identifier
/// rule and the module's one name space, as for `motion.proc`. The error has no place in the
/// cell unless a name of the cell clashes with it (then it points at that name).
pub fn override_proc(cell: &mut Cell, name: &str) -> Result<(), CellError> {
    validate::override_proc(cell, name)
}

/// Checks a grid spacing (deg): within [MIN_GRID_DEG, MAX_GRID_DEG].
pub fn check_grid(g: f64) -> Result<f64, String> {
    if g.is_finite() && (defaults::MIN_GRID_DEG..=defaults::MAX_GRID_DEG).contains(&g) {
        Ok(g)
    } else {
        Err(format!(
            "grid spacing {} deg is outside {} .. {} deg",
            crate::excerpt::number(g),
            defaults::MIN_GRID_DEG,
            defaults::MAX_GRID_DEG
        ))
    }
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod tests_tcp;

#[cfg(test)]
mod tests_process;

#[cfg(test)]
mod tests_program;
