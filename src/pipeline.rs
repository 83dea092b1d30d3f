//! The stages in order, for the command line, the tests and the benchmarks:
//! cell -> robot -> placement (given, or chosen by `locate`) -> points (given, or solved by `ik`)
//! -> collision model -> grid -> plan -> program -> text.
//!
//! Only this module and `cell`/`robot` touch files (the cell and the URDF); everything after
//! [`prepare`] is a pure function of its inputs.

use crate::cell::{Base, Cell, Loc, Method, Target};
use crate::collision::{CollisionModel, Obstacle, Placement};
use crate::cspace::{CSpace, Grid};
use crate::error::Error;
use crate::geometry::Aabb;
use crate::ik::{self, ArmGeometry, Branch};
use crate::locate::{self, Location, LocateInput};
use crate::plan::{self, Plan, Waypoint};
use crate::program::{self, ProgramInput};
use crate::rapid;
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

/// Cell-frame position -> robot-base-frame position.
fn to_robot_frame(p: [f64; 3], placement: &Placement) -> [f64; 3] {
    let (s, c) = placement.yaw_deg.to_radians().sin_cos();
    let d = [p[0] - placement.base_mm[0], p[1] - placement.base_mm[1], p[2] - placement.base_mm[2]];
    [c * d[0] + s * d[1], -s * d[0] + c * d[1], d[2]]
}

/// Loads the robot, places it and resolves the points.
pub fn prepare(cell: Cell) -> Result<Prepared, Error> {
    let robot = Robot::load(&cell.robot.urdf_path).map_err(|source| Error::Robot {
        source,
        loc: cell.robot.urdf_loc,
    })?;
    // The closed-form geometry, needed only for `base: auto` and `xyz` points.
    let geometry = || {
        ArmGeometry::from_robot(&robot).map_err(|source| Error::Ik {
            point: cell.points[0].name.clone(),
            source,
            loc: cell.robot.urdf_loc,
        })
    };
    let (base_mm, location) = match &cell.robot.base {
        Base::Fixed(b) => (*b, None),
        Base::Auto => {
            let location = locate_base(&cell, &robot, &geometry()?)?;
            ([location.base_mm[0], location.base_mm[1], 0.0], Some(location))
        }
    };
    let placement = Placement {
        base_mm,
        yaw_deg: cell.robot.yaw_deg,
    };
    let model = CollisionModel::new(&robot, placement, obstacles(&cell), cell.planner.clearance_mm);

    let mut points = Vec::with_capacity(cell.points.len());
    let mut wrists_deg = Vec::with_capacity(cell.points.len());
    for p in &cell.points {
        let (axes_deg, wrist) = match &p.target {
            Target::Joints { axes_deg, wrist_deg } => (*axes_deg, wrist_deg.unwrap_or(cell.robot.wrist_deg)),
            Target::Xyz {
                wrist_centre_mm,
                branch,
                branch_loc,
            } => {
                let ik_err = |source, loc: Loc| Error::Ik {
                    point: p.name.clone(),
                    source,
                    loc,
                };
                let branch = match branch {
                    Some(b) => Some(b.parse::<Branch>().map_err(|_| {
                        Error::Cell(crate::cell::CellError::Invalid {
                            loc: *branch_loc,
                            message: format!("point '{}': branch '{b}' is not one of front-elbow-up, front-elbow-down, back-elbow-up, back-elbow-down", p.name),
                            help: None,
                        })
                    })?),
                    None => None,
                };
                let geom = geometry()?;
                let previous = points.last().map(|w: &Waypoint| w.axes_deg);
                let local = to_robot_frame(*wrist_centre_mm, &placement);
                let sol = ik::choose(&robot, &geom, local, previous, branch, |a| model.is_free(&plan::quantize(a)))
                    .map_err(|e| ik_err(e, p.loc))?;
                (plan::quantize(sol.axes_deg), cell.robot.wrist_deg)
            }
        };
        points.push(Waypoint {
            name: p.name.clone(),
            axes_deg,
        });
        wrists_deg.push(wrist);
    }
    Ok(Prepared {
        cell,
        robot,
        placement,
        location,
        points,
        wrists_deg,
        model,
    })
}

/// The feasible region of the base (paper section 2) and the chosen base.
pub fn locate_base(cell: &Cell, robot: &Robot, geom: &ArmGeometry) -> Result<Location, Error> {
    let err = |source| Error::Locate {
        source,
        loc: cell.robot.base_loc,
    };
    let mut pts = Vec::new();
    for p in &cell.points {
        match &p.target {
            Target::Xyz { wrist_centre_mm, .. } => pts.push((p.name.clone(), *wrist_centre_mm)),
            Target::Joints { .. } => {
                return Err(Error::Cell(crate::cell::CellError::Invalid {
                    loc: p.loc,
                    message: format!("point '{}' gives joint values, but `base: auto` needs every point as `xyz` (joint values mean nothing until the base is known)", p.name),
                    help: Some("give the point's wrist-centre position `xyz: [x, y, z]` in the cell frame (mm)".into()),
                }))
            }
        }
    }
    let boxes: Vec<(String, [f64; 3], [f64; 3])> = cell.obstacles.iter().map(|o| (o.name.clone(), o.min_mm, o.max_mm)).collect();
    let (radius, height) = locate::base_cylinder_mm(robot).unwrap_or((0.0, 0.0));
    locate::locate(&LocateInput {
        geom,
        points_mm: &pts,
        obstacles: &boxes,
        base_z_mm: 0.0,
        base_radius_mm: radius,
        base_height_mm: height,
        clearance_mm: cell.planner.clearance_mm,
        cell_mm: locate::DEFAULT_CELL_MM,
    })
    .map_err(err)
}

/// The grid over the robot's ranges of axes 1..3 at spacing `grid_deg`, inspected.
pub fn cspace(prep: &Prepared, grid_deg: f64) -> CSpace {
    let a = &prep.robot.controller.axes;
    let grid = Grid::over(
        [[a[0].min_deg, a[0].max_deg], [a[1].min_deg, a[1].max_deg], [a[2].min_deg, a[2].max_deg]],
        grid_deg,
    );
    CSpace::build(grid, &prep.model)
}

/// Plans the route with `method` on an inspected grid (no rendering).
pub fn plan_route(prep: &Prepared, cs: &CSpace, method: Method) -> Result<Plan, Error> {
    plan::plan(cs, &prep.model, &prep.points, method).map_err(|source| {
        let loc = prep.cell.points.get(source.point()).map(|p| p.loc).unwrap_or_default();
        Error::Plan { source, loc }
    })
}

/// The manipulation time of a plan (paper section 5; see `timing`), s.
pub fn manipulation_time_s(prep: &Prepared, plan: &Plan) -> f64 {
    timing::plan_time_s(plan, &prep.wrists_deg, &prep.robot.controller.axes)
}

/// Plans with `method` on an inspected grid and renders the module.
pub fn plan_and_render(prep: &Prepared, cs: &CSpace, method: Method, estimated_time: impl Fn(&Plan) -> Option<f64>) -> Result<Outcome, Error> {
    let plan = plan_route(prep, cs, method)?;
    render(prep, cs, plan, estimated_time)
}

/// Renders the module of a plan made on `cs`.
pub fn render(prep: &Prepared, cs: &CSpace, plan: Plan, estimated_time: impl Fn(&Plan) -> Option<f64>) -> Result<Outcome, Error> {
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
    Ok(Outcome { plan, program, text })
}
