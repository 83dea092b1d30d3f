//! The place stage: [`Cell`] + [`Robot`] -> [`Placed`], where the robot stands and every point
//! resolved to all six axes. Paper: Ting & Jar (2006) section 2 (robot location, [`locate`]);
//! beyond it, points given as wrist-centre positions, solved by closed-form inverse kinematics
//! (`points.rs`), and points given as robtargets (TCP poses in a work object, with a tool),
//! solved by the six-axis inverse kinematics (`robtarget.rs`).
//!
//! **Every value in range**: a cell's own values (a `joints` point, `robot.wrist`)
//! outside the controller's ranges (the URDF's limits without a controller file; all six axes
//! and the coupled axis-3 range) are an input error at their line ([`PlaceError::Range`]); a
//! computed one (IK) is never chosen, and a point without an in-range solution is a planning
//! error naming it.
//!
//! **The motion of each move** ([`MoveMotion`]): every placed point carries the speed and zone
//! of the move into it (its own `speed`/`zone`, else `motion.speed`/`motion.zone`); the plan
//! derives the vias' from them (`Plan::motion_into`).
//!
//! **The one rule for where the robot stands.** `base: [x, y, z]` is used as given. `base: auto`
//! stands the robot on the floor (z = [`AUTO_BASE_Z_MM`]) at the first position of the feasible
//! region R, in R's ranking ([`Location::candidates`]: largest margin first), from which every
//! point has a solution in range and free of collision (R's reach regions ignore the axis-2 and
//! -3 ranges, so the position with the largest margin may not do). Either way the yaw is
//! `robot.yaw` as given (default 0): the place stage chooses a position, never a yaw. The module
//! header records the placement used (`! base: [x, y, z] yaw: deg`); with the default 10 mm
//! raster a chosen base is a multiple of 5 mm, so the header's 0.1 mm is exact. (A `base: auto`
//! cell gives every point as `xyz`: the cell validation refuses joint values there.)
//!
//! Collision checks: this stage asks, through [`PoseCheck`], whether an IK solution is usable
//! from a placement; the pipeline hands it the collision model of each placement it tries. So the
//! stage knows what it asks, not how the answer is found (the model comes after it).

pub mod frames;
mod hints;
pub mod locate;
pub mod near_limit;
mod points;

pub use frames::Placement;
pub use locate::Location;

mod robtarget;

pub use robtarget::{pose_error, ANGLE_TOL_DEG, POSITION_TOL_MM};

use crate::cell::{Base, Cell, Frame, Loc, Target};
use crate::robot::ik::six::{ChooseError, ConfData, SixAxisError};
use crate::robot::ik::{self, ArmGeometry, Branch, IkError};
use crate::robot::{RangeViolation, Robot};
use locate::{LocateError, LocateInput};
use robtarget::Tcp;

/// Height of the base chosen by `base: auto`: it stands on the floor, mm.
pub const AUTO_BASE_Z_MM: f64 = 0.0;

/// Why a pose (controller values of all six axes, deg) cannot be used from one placement: out of
/// range, or a link or tool shape within the clearance of an obstacle (`None`: usable).
/// Implemented by the collision model.
pub trait PoseCheck {
    fn why_blocked(&self, joints_deg: &[f64; 6]) -> Option<String>;
}

/// How a point was given in the cell.
#[derive(Clone, Debug, PartialEq)]
pub enum Origin {
    /// As controller values (three axes, or all six).
    Joints,
    /// As a wrist-centre position (cell frame, mm), solved on `branch`.
    Xyz {
        wrist_centre_mm: [f64; 3],
        branch: Branch,
    },
    /// As a robtarget: the TCP pose in the work object (as given, normalised) and the confdata
    /// of the written joint values (the one asked for, or the chosen solution's).
    Robtarget { pose: Frame, conf: ConfData },
}

/// The speeddata and zonedata of one move (RAPID names).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MoveMotion {
    pub speed: String,
    pub zone: String,
}

/// A cell point resolved to all six axes.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedPoint {
    pub name: String,
    /// Controller values of axes 1..6, deg: at the written precision, except a robtarget
    /// point's, the exact inverse of its robtarget as written (`robtarget.rs`).
    pub joints_deg: [f64; 6],
    /// Where the cell file gives the point.
    pub loc: Loc,
    pub origin: Origin,
    /// The motion of the move into this point (module docs).
    pub motion: MoveMotion,
}

impl PlacedPoint {
    /// Axes 1..3 (the planning axes), deg.
    pub fn arm_deg(&self) -> [f64; 3] {
        [self.joints_deg[0], self.joints_deg[1], self.joints_deg[2]]
    }
}

/// The placed job: where the robot stands and every point on all six axes.
#[derive(Clone, Debug)]
pub struct Placed {
    pub placement: Placement,
    /// The feasible region R the base was chosen in, with `base: auto`.
    pub location: Option<Location>,
    pub points: Vec<PlacedPoint>,
}

/// Why the robot could not be placed or a point not resolved.
#[derive(Debug, thiserror::Error)]
pub enum PlaceError {
    /// The robot's structure does not fit the closed-form inverse kinematics (an input error:
    /// `robot.urdf`).
    #[error("{source}")]
    Arm { source: IkError, loc: Loc },
    /// A point given as a position has no usable solution from the base it was solved from.
    #[error("point '{point}' (robot base at [{:.1}, {:.1}, {:.1}] mm, yaw {} deg): {source}", .base_mm[0], .base_mm[1], .base_mm[2], .yaw_deg)]
    Ik {
        point: String,
        base_mm: [f64; 3],
        yaw_deg: f64,
        source: Box<IkError>,
        loc: Loc,
    },
    /// No base position reaches every point (paper section 2).
    #[error("{source}")]
    Locate { source: LocateError, loc: Loc },
    /// A value the cell gives lies outside the robot's ranges (an input error).
    #[error("{what} is out of range: {violation} (ranges from {ranges})")]
    Range {
        /// "point 'P2'", "robot.wrist".
        what: String,
        violation: RangeViolation,
        /// Where the ranges come from: the controller file, or the URDF's limits.
        ranges: String,
        loc: Loc,
    },
    /// The robot's structure does not fit the six-axis inverse kinematics (an input error:
    /// `robot.urdf`).
    #[error("{source}")]
    SixAxis { source: SixAxisError, loc: Loc },
    /// A robtarget point has no usable solution from the base it was solved from.
    #[error("point '{point}' (robot base at [{:.1}, {:.1}, {:.1}] mm, yaw {} deg): {source}", .base_mm[0], .base_mm[1], .base_mm[2], .yaw_deg)]
    Robtarget {
        point: String,
        base_mm: [f64; 3],
        yaw_deg: f64,
        source: Box<ChooseError<String>>,
        loc: Loc,
        /// The help line when a turn of the tool or a move of the base makes it reachable
        /// (`hints.rs`).
        hint: Option<String>,
    },
}

impl PlaceError {
    /// Where in the cell file the error points.
    pub fn loc(&self) -> Loc {
        match self {
            PlaceError::Arm { loc, .. }
            | PlaceError::Ik { loc, .. }
            | PlaceError::Locate { loc, .. }
            | PlaceError::Range { loc, .. }
            | PlaceError::SixAxis { loc, .. }
            | PlaceError::Robtarget { loc, .. } => *loc,
        }
    }

    /// Whether the input is at fault (rather than the cell being impossible to plan).
    pub fn is_input(&self) -> bool {
        matches!(
            self,
            PlaceError::Arm { .. } | PlaceError::Range { .. } | PlaceError::SixAxis { .. }
        )
    }

    /// Whether another base might do (`base: auto` tries the next position of R).
    fn is_from_this_base(&self) -> bool {
        matches!(self, PlaceError::Ik { .. } | PlaceError::Robtarget { .. })
    }
}

/// Places the robot and resolves every point (module docs for the rule). `check_at` gives the
/// collision model of a placement.
pub fn place<C: PoseCheck>(
    cell: &Cell,
    robot: &Robot,
    check_at: impl Fn(Placement) -> C,
) -> Result<Placed, PlaceError> {
    if let Some(loc) = cell.robot.wrist_loc {
        robot
            .check_wrist(&cell.robot.wrist_deg)
            .map_err(|violation| PlaceError::Range {
                what: "robot.wrist".into(),
                violation,
                ranges: ranges_source(robot),
                loc,
            })?;
    }
    match &cell.robot.base {
        Base::Fixed(b) => {
            let placement = Placement {
                base_mm: *b,
                yaw_deg: cell.robot.yaw_deg,
            };
            let needs_geometry = cell
                .points
                .iter()
                .any(|p| matches!(p.target, Target::Xyz { .. }));
            let geom = match needs_geometry {
                true => Some(geometry(cell, robot)?),
                false => None,
            };
            let check = check_at(placement);
            let points = points::resolve(cell, robot, geom.as_ref(), placement, &check)
                .map_err(|e| hints::with_hint(e, cell, robot, placement, &check, &check_at))?;
            Ok(Placed {
                placement,
                location: None,
                points,
            })
        }
        Base::Auto => {
            let chosen = choose_base(cell, robot, &geometry(cell, robot)?, check_at)?;
            Ok(Placed {
                placement: chosen.placement,
                location: Some(chosen.location),
                points: chosen.points,
            })
        }
    }
}

/// What `gen-rapid locate` reports: R for the cell's points, the points' wrist centres (cell
/// frame) and a base position in R with its margin.
#[derive(Clone, Debug)]
pub struct Survey {
    pub location: Location,
    /// Working points by name with their wrist centres, cell frame, mm.
    pub points: Vec<(String, [f64; 3])>,
    /// With `base: auto` the base the place stage stands the robot on; with a fixed base the
    /// position of R with the largest margin (at the given base's height), for comparison.
    pub base_mm: [f64; 3],
    /// Its distance to the boundary of R, mm.
    pub margin_mm: f64,
}

/// R for any cell, so that it can be reported and drawn: with `base: auto` as [`place`] finds
/// it (and the base it chooses); with a fixed base, from the wrist centres of the points at that
/// base's height (`xyz` points as given, `joints` points by forward kinematics from the given
/// base and yaw).
pub fn survey<C: PoseCheck>(
    cell: &Cell,
    robot: &Robot,
    check_at: impl Fn(Placement) -> C,
) -> Result<Survey, PlaceError> {
    let geom = geometry(cell, robot)?;
    let base = match &cell.robot.base {
        Base::Auto => {
            let chosen = choose_base(cell, robot, &geom, check_at)?;
            return Ok(Survey {
                points: positions(cell, robot)?,
                base_mm: chosen.placement.base_mm,
                margin_mm: chosen.margin_mm,
                location: chosen.location,
            });
        }
        Base::Fixed(b) => *b,
    };
    let (points, base_z) = survey_points(cell, robot, &geom)?;
    let location = locate_points(cell, robot, &geom, &points, base_z)?;
    Ok(Survey {
        base_mm: [location.best_mm[0], location.best_mm[1], base[2]],
        margin_mm: location.best_margin_mm,
        location,
        points,
    })
}

/// Points by name with their wrist centres, cell frame, mm.
type WristCentres = Vec<(String, [f64; 3])>;

/// The points R is computed for by [`survey`], and the height of the base's mounting plane:
/// with `base: auto` the `xyz` and robtarget points ([`positions`]), on the floor; with a fixed
/// base the wrist centres of all points (`joints` points by forward kinematics from the given
/// base and yaw, robtargets by their pose and the tool), at its height.
fn survey_points(
    cell: &Cell,
    robot: &Robot,
    geom: &ArmGeometry,
) -> Result<(WristCentres, f64), PlaceError> {
    let base = match &cell.robot.base {
        Base::Auto => return Ok((positions(cell, robot)?, AUTO_BASE_Z_MM)),
        Base::Fixed(b) => *b,
    };
    let placement = Placement {
        base_mm: base,
        yaw_deg: cell.robot.yaw_deg,
    };
    let tcp = needs_tcp(cell).then(|| Tcp::of(cell, robot)).transpose()?;
    let points = cell
        .points
        .iter()
        .filter_map(|p| {
            let xyz = match &p.target {
                Target::Xyz {
                    wrist_centre_mm, ..
                } => Some(*wrist_centre_mm),
                Target::Joints { axes_deg, .. } => {
                    Some(placement.to_cell_frame(ik::forward(geom, *axes_deg)))
                }
                Target::Robtarget { pose, .. } => {
                    tcp.as_ref().map(|t| t.wrist_centre(pose, p.wobj))
                }
            };
            xyz.map(|x| (p.name.clone(), x))
        })
        .collect();
    Ok((points, base[2]))
}

/// What `gen-rapid locate --svg` draws when [`survey`] fails for want of a base position: the
/// reach regions of the points [`survey`] uses, the obstacles that can block the base, and R
/// where it is not empty ([`locate::sketch`]).
pub fn sketch(cell: &Cell, robot: &Robot) -> Result<locate::Sketch, PlaceError> {
    let geom = geometry(cell, robot)?;
    let (points, base_z) = survey_points(cell, robot, &geom)?;
    Ok(locate::sketch(&locate_input(
        cell, robot, &geom, &points, base_z,
    )))
}

/// The closed-form arm geometry (needed by `base: auto` and `xyz` points); a robot the closed
/// form cannot handle is an input error pointing at `robot.urdf`.
fn geometry(cell: &Cell, robot: &Robot) -> Result<ArmGeometry, PlaceError> {
    ArmGeometry::from_robot(robot).map_err(|source| PlaceError::Arm {
        source,
        loc: cell.robot.urdf_loc,
    })
}

/// The base `base: auto` stands on, R it was chosen in, and the points resolved from it.
struct Chosen {
    location: Location,
    placement: Placement,
    margin_mm: f64,
    points: Vec<PlacedPoint>,
}

/// `base: auto` (module docs): R, then its positions in R's ranking until one from which every
/// point is solved.
fn choose_base<C: PoseCheck>(
    cell: &Cell,
    robot: &Robot,
    geom: &ArmGeometry,
    check_at: impl Fn(Placement) -> C,
) -> Result<Chosen, PlaceError> {
    let location = locate_points(cell, robot, geom, &positions(cell, robot)?, AUTO_BASE_Z_MM)?;
    let candidates = location.candidates();
    let mut first_failure: Option<(PlaceError, [f64; 2])> = None;
    for (xy, margin_mm) in &candidates {
        let placement = Placement {
            base_mm: [xy[0], xy[1], AUTO_BASE_Z_MM],
            yaw_deg: cell.robot.yaw_deg,
        };
        match points::resolve(cell, robot, Some(geom), placement, &check_at(placement)) {
            Ok(points) => {
                return Ok(Chosen {
                    location,
                    placement,
                    margin_mm: *margin_mm,
                    points,
                })
            }
            Err(e) if e.is_from_this_base() => {
                first_failure.get_or_insert((e, *xy));
            }
            Err(e) => return Err(e),
        }
    }
    let (first, best_mm) = first_failure
        .map(|(e, xy)| (e.to_string(), xy))
        .unwrap_or_default();
    Err(PlaceError::Locate {
        source: LocateError::NoReachableBase {
            candidates: candidates.len(),
            best_mm,
            first,
        },
        loc: cell.robot.base_loc,
    })
}

/// The points of a `base: auto` cell as wrist-centre positions by name (cell frame, mm): `xyz`
/// points as given, robtargets by their pose and the tool (`robtarget.rs`). The cell validation
/// refuses `joints` points there.
fn positions(cell: &Cell, robot: &Robot) -> Result<Vec<(String, [f64; 3])>, PlaceError> {
    let tcp = needs_tcp(cell).then(|| Tcp::of(cell, robot)).transpose()?;
    Ok(cell
        .points
        .iter()
        .filter_map(|p| match (&p.target, &tcp) {
            (
                Target::Xyz {
                    wrist_centre_mm, ..
                },
                _,
            ) => Some((p.name.clone(), *wrist_centre_mm)),
            (Target::Robtarget { pose, .. }, Some(tcp)) => {
                Some((p.name.clone(), tcp.wrist_centre(pose, p.wobj)))
            }
            _ => None,
        })
        .collect())
}

/// Whether the cell has robtarget points (and so needs the six-axis IK).
fn needs_tcp(cell: &Cell) -> bool {
    cell.points
        .iter()
        .any(|p| matches!(p.target, Target::Robtarget { .. }))
}

/// Where a robot's ranges come from, for messages: its controller file, or the URDF.
fn ranges_source(robot: &Robot) -> String {
    let name = |p: &std::path::Path| {
        p.file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    match &robot.controller.source {
        Some(path) => name(path),
        None => format!(
            "the joint limits of {} (no controller file)",
            name(&robot.urdf_path)
        ),
    }
}

/// R for `points` with the base mounting plane at `base_z_mm`; an empty R fails pointing at
/// `robot.base`.
fn locate_points(
    cell: &Cell,
    robot: &Robot,
    geom: &ArmGeometry,
    points: &[(String, [f64; 3])],
    base_z_mm: f64,
) -> Result<Location, PlaceError> {
    locate::locate(&locate_input(cell, robot, geom, points, base_z_mm)).map_err(|source| {
        PlaceError::Locate {
            source,
            loc: cell.robot.base_loc,
        }
    })
}

/// The location problem of `points` with the base's mounting plane at `base_z_mm`.
fn locate_input<'a>(
    cell: &'a Cell,
    robot: &Robot,
    geom: &'a ArmGeometry,
    points: &'a [(String, [f64; 3])],
    base_z_mm: f64,
) -> LocateInput<'a> {
    let (radius, height) = locate::base_cylinder_mm(robot).unwrap_or((0.0, 0.0));
    LocateInput {
        geom,
        points_mm: points,
        obstacles: &cell.obstacles,
        base_z_mm,
        base_radius_mm: radius,
        base_height_mm: height,
        clearance_mm: cell.planner.clearance_mm,
        cell_mm: locate::DEFAULT_CELL_MM,
    }
}

#[cfg(test)]
mod tests;
