//! The stages in order, for the command line, the tests and the benchmarks:
//! cell -> robot -> placement (given, or chosen by `locate`) -> points (given, or solved by `ik`)
//! -> collision model -> grid -> plan -> program -> text.
//!
//! Only `cell` and `robot` read files (the cell, the URDF) and only `cli` writes them; everything
//! after [`prepare`] is a pure function of its inputs.
//!
//! Rules of [`prepare`]:
//! - **Placement.** `base: [x, y, z]` is used as given. `base: auto` runs [`locate_base`] (paper
//!   section 2) and stands the robot on the floor (z = 0) at the position of R with the largest
//!   margin from which every point has a solution in range and free of collision (R's reach
//!   regions ignore the axis-2 and -3 ranges, so positions are tried in order of margin). Either way the
//!   yaw is `robot.yaw` as given (default 0): the location stage chooses a position, never a
//!   yaw. The module header records the placement used (`! base: [x, y, z] yaw: deg`); with the
//!   default 10 mm raster the chosen base is a multiple of 5 mm, so the header's 0.1 mm is exact.
//!   With `base: auto` every point must be an `xyz` point: joint values mean nothing until the
//!   base is known.
//! - **`xyz` points** (wrist centre, cell frame, mm) are moved into the robot frame and solved by
//!   [`ik::choose`] (solution closest to the previous point, or the most upright arm for the
//!   first; `branch:` forces one of the four). The solution is rounded to the written precision
//!   (0.001 deg, [`plan::quantize`]) and it is the *rounded* value that must be in collision-free
//!   space (`model.is_free` is evaluated on it) and that the plan and the module use. Rounding
//!   moves each axis by at most 0.0005 deg = 8.7e-6 rad, so the wrist centre moves by at most
//!   `(r + a2 + L) x 8.7e-6` mm (`r` the wrist's distance from axis 1, `L` the forearm; the
//!   upper arm's lever is `a2` for a parallelogram robot, at most `a2 + L` for a serial one):
//!   about 0.025 mm on the IRB 1400 (`r <= 1444`), always under 0.05 mm. A point that cannot
//!   be solved fails with the point's name, line and the base used (Error::Ik, exit 3).

use crate::cell::{Base, Cell, Method, Target};
use crate::collision::{CollisionModel, Obstacle, Placement};
use crate::error::Error;
use crate::geometry::Aabb;
use crate::output::program::{self, ProgramInput};
use crate::output::rapid;
use crate::place::locate::{self, LocateInput, Location};
use crate::plan::cspace::{CSpace, Grid};
use crate::plan::{self, Plan, Waypoint};
use crate::robot::ik::{self, ArmGeometry};
use crate::robot::Robot;
use crate::timing;
use nalgebra::Point3;

/// Everything fixed before planning: the robot placed, the points resolved.
pub struct Prepared {
    pub cell: Cell,
    pub robot: Robot,
    pub placement: Placement,
    /// The feasible region and chosen base, when the cell says `base: auto`.
    pub location: Option<Location>,
    pub points: Vec<Waypoint>,
    /// Axes 4..6 of each point, deg.
    pub wrists_deg: Vec<[f64; 3]>,
    pub model: CollisionModel,
}

/// A planned cell.
pub struct Outcome {
    pub plan: Plan,
    pub program: rapid::Program,
    pub text: String,
}

fn obstacles(cell: &Cell) -> Vec<Obstacle> {
    cell.obstacles
        .iter()
        .map(|o| Obstacle {
            name: o.name.clone(),
            aabb: Aabb::new(Point3::from(o.min_mm), Point3::from(o.max_mm)),
        })
        .collect()
}

/// Robot-base-frame position -> cell-frame position (inverse of [`to_robot_frame`]).
pub fn to_cell_frame(p: [f64; 3], placement: &Placement) -> [f64; 3] {
    let (s, c) = placement.yaw_deg.to_radians().sin_cos();
    let b = placement.base_mm;
    [
        b[0] + c * p[0] - s * p[1],
        b[1] + s * p[0] + c * p[1],
        b[2] + p[2],
    ]
}

/// Cell-frame position -> robot-base-frame position.
pub fn to_robot_frame(p: [f64; 3], placement: &Placement) -> [f64; 3] {
    let (s, c) = placement.yaw_deg.to_radians().sin_cos();
    let d = [
        p[0] - placement.base_mm[0],
        p[1] - placement.base_mm[1],
        p[2] - placement.base_mm[2],
    ];
    [c * d[0] + s * d[1], -s * d[0] + c * d[1], d[2]]
}

/// Loads the cell's robot (its URDF, relative to the cell file).
pub fn load_robot(cell: &Cell) -> Result<Robot, Error> {
    Robot::load(&cell.robot.urdf_path).map_err(|source| Error::Robot {
        source,
        loc: cell.robot.urdf_loc,
    })
}

/// The closed-form arm geometry (needed by `base: auto`, `xyz` points and `locate`); a robot the
/// closed form cannot handle is an input error pointing at `robot.urdf`.
pub fn geometry(cell: &Cell, robot: &Robot) -> Result<ArmGeometry, Error> {
    ArmGeometry::from_robot(robot).map_err(|source| Error::Arm {
        source,
        loc: cell.robot.urdf_loc,
    })
}

/// The robot with its points resolved at one placement.
struct Resolved {
    model: CollisionModel,
    points: Vec<Waypoint>,
    wrists_deg: Vec<[f64; 3]>,
}

/// Places the robot and resolves every point (module docs for the rules): joint points as given,
/// `xyz` points by [`ik::choose`] with the collision model of this placement.
fn resolve_points(
    cell: &Cell,
    robot: &Robot,
    geom: Option<&ArmGeometry>,
    placement: Placement,
) -> Result<Resolved, Error> {
    let model = CollisionModel::new(robot, placement, obstacles(cell), cell.planner.clearance_mm);
    let mut points: Vec<Waypoint> = Vec::with_capacity(cell.points.len());
    let mut wrists_deg = Vec::with_capacity(cell.points.len());
    for p in &cell.points {
        let (axes_deg, wrist) = match &p.target {
            Target::Joints {
                axes_deg,
                wrist_deg,
            } => (*axes_deg, wrist_deg.unwrap_or(cell.robot.wrist_deg)),
            Target::Xyz {
                wrist_centre_mm,
                branch,
                branch_loc,
            } => {
                let geom = match geom {
                    Some(g) => g,
                    None => &geometry(cell, robot)?,
                };
                let previous = points.last().map(|w| w.axes_deg);
                let local = to_robot_frame(*wrist_centre_mm, &placement);
                let free = |a: [f64; 3]| model.is_free(&plan::quantize(a));
                let sol =
                    ik::choose(robot, geom, local, previous, *branch, free).map_err(|source| {
                        // What blocks the solutions in range, by link and obstacle.
                        let detail = match &source {
                            ik::IkError::InCollision { .. } => {
                                let why: Vec<String> = ik::solve(geom, local)
                                    .into_iter()
                                    .filter(|s| robot.check_range3(&s.axes_deg).is_ok())
                                    .filter_map(|s| {
                                        let a = plan::quantize(s.axes_deg);
                                        model.why_blocked(&a).map(|b| format!("{}: {b}", s.branch))
                                    })
                                    .collect();
                                format!("; {}", why.join("; "))
                            }
                            _ => String::new(),
                        };
                        let loc = match source {
                            ik::IkError::ForcedBranch { .. } => *branch_loc,
                            _ => p.loc,
                        };
                        Error::Ik {
                            point: p.name.clone(),
                            base_mm: placement.base_mm,
                            yaw_deg: placement.yaw_deg,
                            source: Box::new(source),
                            detail,
                            loc,
                        }
                    })?;
                (plan::quantize(sol.axes_deg), cell.robot.wrist_deg)
            }
        };
        points.push(Waypoint {
            name: p.name.clone(),
            axes_deg,
        });
        wrists_deg.push(wrist);
    }
    Ok(Resolved {
        model,
        points,
        wrists_deg,
    })
}

/// Loads the robot, places it and resolves the points (module docs for the rules).
pub fn prepare(cell: Cell) -> Result<Prepared, Error> {
    let robot = load_robot(&cell)?;
    let (placement, location, resolved) = match &cell.robot.base {
        Base::Fixed(b) => {
            let placement = Placement {
                base_mm: *b,
                yaw_deg: cell.robot.yaw_deg,
            };
            let needs_geometry = cell
                .points
                .iter()
                .any(|p| matches!(p.target, Target::Xyz { .. }));
            let geom = if needs_geometry {
                Some(geometry(&cell, &robot)?)
            } else {
                None
            };
            let resolved = resolve_points(&cell, &robot, geom.as_ref(), placement)?;
            (placement, None, resolved)
        }
        Base::Auto => {
            let geom = geometry(&cell, &robot)?;
            let (location, resolved) = locate_and_resolve(&cell, &robot, &geom)?;
            let placement = resolved.model.placement();
            (placement, Some(location), resolved)
        }
    };
    Ok(Prepared {
        cell,
        robot,
        placement,
        location,
        points: resolved.points,
        wrists_deg: resolved.wrists_deg,
        model: resolved.model,
    })
}

/// `base: auto`: the feasible region, then its positions in order of margin until one from which
/// every point has a solution in range and free of collision (the reach regions of section 2 do
/// not know the axis-2 and -3 ranges, so the position with the largest margin may not do). The
/// returned location's base is that position.
fn locate_and_resolve(
    cell: &Cell,
    robot: &Robot,
    geom: &ArmGeometry,
) -> Result<(Location, Resolved), Error> {
    let mut location = locate_base(cell, robot, geom)?;
    let candidates = location.candidates();
    let mut first_failure: Option<(Error, [f64; 2])> = None;
    for (xy, margin) in &candidates {
        let placement = Placement {
            base_mm: [xy[0], xy[1], AUTO_BASE_Z_MM],
            yaw_deg: cell.robot.yaw_deg,
        };
        match resolve_points(cell, robot, Some(geom), placement) {
            Ok(resolved) => {
                location.base_mm = *xy;
                location.margin_mm = *margin;
                return Ok((location, resolved));
            }
            Err(e @ Error::Ik { .. }) => {
                first_failure.get_or_insert((e, *xy));
            }
            Err(e) => return Err(e),
        }
    }
    let (first, best_mm) = first_failure
        .map(|(e, xy)| (e.to_string(), xy))
        .unwrap_or_default();
    Err(Error::Locate {
        source: locate::LocateError::NoReachableBase {
            candidates: candidates.len(),
            best_mm,
            first,
        },
        loc: cell.robot.base_loc,
    })
}

/// Height of the base chosen by `base: auto`: it stands on the floor, mm.
pub const AUTO_BASE_Z_MM: f64 = 0.0;

/// The feasible region of the base (paper section 2) and the chosen base, for a cell with
/// `base: auto` (every point `xyz`; a `joints` point is refused, pointing at it). The base
/// stands on the floor (z = 0). An empty region fails pointing at `robot.base`.
pub fn locate_base(cell: &Cell, robot: &Robot, geom: &ArmGeometry) -> Result<Location, Error> {
    let pts = xyz_points(cell)?;
    locate_points(cell, robot, geom, &pts, AUTO_BASE_Z_MM)
}

/// Working points by name with their wrist centres (cell frame, mm).
pub type NamedPoints = Vec<(String, [f64; 3])>;

/// The points of a `base: auto` cell, all given as `xyz`; a `joints` point is refused, pointing at
/// it (joint values mean nothing until the base is known).
fn xyz_points(cell: &Cell) -> Result<NamedPoints, Error> {
    cell.points
        .iter()
        .map(|p| match &p.target {
            Target::Xyz { wrist_centre_mm, .. } => Ok((p.name.clone(), *wrist_centre_mm)),
            Target::Joints { .. } => Err(Error::Cell(crate::cell::CellError::Invalid {
                loc: p.loc,
                message: format!("point '{}' gives joint values, but `base: auto` needs every point as `xyz` (joint values mean nothing until the base is known)", p.name),
                help: Some("give the point's wrist-centre position `xyz: [x, y, z]` in the cell frame (mm)".into()),
            })),
        })
        .collect()
}

/// The feasible region for any cell, so that it can be reported and drawn (`gen-rapid
/// locate`): with `base: auto` as [`locate_base`]; with a fixed base, from the wrist centres of
/// the points at that base's height (`xyz` points as given, `joints` points by forward
/// kinematics from the given base and yaw). Returns the region and the points used (cell frame).
pub fn locate_any(
    cell: &Cell,
    robot: &Robot,
    geom: &ArmGeometry,
) -> Result<(Location, NamedPoints), Error> {
    let base = match &cell.robot.base {
        Base::Auto => {
            // The base a run would use: verified by solving every point (see `prepare`).
            let (location, _) = locate_and_resolve(cell, robot, geom)?;
            let pts = xyz_points(cell)?;
            return Ok((location, pts));
        }
        Base::Fixed(b) => *b,
    };
    let placement = Placement {
        base_mm: base,
        yaw_deg: cell.robot.yaw_deg,
    };
    let pts: Vec<(String, [f64; 3])> = cell
        .points
        .iter()
        .map(|p| {
            let xyz = match &p.target {
                Target::Xyz {
                    wrist_centre_mm, ..
                } => *wrist_centre_mm,
                Target::Joints { axes_deg, .. } => {
                    to_cell_frame(ik::forward(geom, *axes_deg), &placement)
                }
            };
            (p.name.clone(), xyz)
        })
        .collect();
    let location = locate_points(cell, robot, geom, &pts, base[2])?;
    Ok((location, pts))
}

fn locate_points(
    cell: &Cell,
    robot: &Robot,
    geom: &ArmGeometry,
    pts: &[(String, [f64; 3])],
    base_z_mm: f64,
) -> Result<Location, Error> {
    let boxes: Vec<(String, [f64; 3], [f64; 3])> = cell
        .obstacles
        .iter()
        .map(|o| (o.name.clone(), o.min_mm, o.max_mm))
        .collect();
    let (radius, height) = locate::base_cylinder_mm(robot).unwrap_or((0.0, 0.0));
    locate::locate(&LocateInput {
        geom,
        points_mm: pts,
        obstacles: &boxes,
        base_z_mm,
        base_radius_mm: radius,
        base_height_mm: height,
        clearance_mm: cell.planner.clearance_mm,
        cell_mm: locate::DEFAULT_CELL_MM,
    })
    .map_err(|source| Error::Locate {
        source,
        loc: cell.robot.base_loc,
    })
}

/// The grid over the robot's ranges of axes 1..3 at spacing `grid_deg`, inspected.
pub fn cspace(prep: &Prepared, grid_deg: f64) -> CSpace {
    let a = &prep.robot.controller.axes;
    let grid = Grid::over(
        [
            [a[0].min_deg, a[0].max_deg],
            [a[1].min_deg, a[1].max_deg],
            [a[2].min_deg, a[2].max_deg],
        ],
        grid_deg,
    );
    CSpace::build(grid, &prep.model)
}

/// Plans the route with `method` on an inspected grid (no rendering).
pub fn plan_route(prep: &Prepared, cs: &CSpace, method: Method) -> Result<Plan, Error> {
    plan::plan(cs, &prep.model, &prep.points, method).map_err(|source| {
        let loc = prep
            .cell
            .points
            .get(source.point())
            .map(|p| p.loc)
            .unwrap_or_default();
        Error::Plan { source, loc }
    })
}

/// The manipulation time of a plan (paper section 5; see `timing`), s.
pub fn manipulation_time_s(prep: &Prepared, plan: &Plan) -> f64 {
    timing::plan_time_s(plan, &prep.wrists_deg, &prep.robot.controller.axes)
}

/// Plans with `method` on an inspected grid and renders the module.
pub fn plan_and_render(
    prep: &Prepared,
    cs: &CSpace,
    method: Method,
    estimated_time: impl Fn(&Plan) -> Option<f64>,
) -> Result<Outcome, Error> {
    let plan = plan_route(prep, cs, method)?;
    render(prep, cs, plan, estimated_time)
}

/// Renders the module of a plan made on `cs`.
pub fn render(
    prep: &Prepared,
    cs: &CSpace,
    plan: Plan,
    estimated_time: impl Fn(&Plan) -> Option<f64>,
) -> Result<Outcome, Error> {
    let names: Vec<String> = prep.points.iter().map(|p| p.name.clone()).collect();
    let cell_file = prep
        .cell
        .path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    let program = program::build(
        &plan,
        &prep.model,
        &ProgramInput {
            module: &prep.cell.module,
            cell_file: &cell_file,
            names: &names,
            wrists_deg: &prep.wrists_deg,
            grid_deg: cs.grid.step_deg,
            base_mm: prep.placement.base_mm,
            yaw_deg: prep.placement.yaw_deg,
            speed: &prep.cell.motion.speed,
            zone: &prep.cell.motion.zone,
            tool: &prep.cell.motion.tool,
            estimated_time_s: estimated_time(&plan),
        },
    );
    let text = rapid::render(&program)?;
    Ok(Outcome {
        plan,
        program,
        text,
    })
}
