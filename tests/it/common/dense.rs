//! The independent whole-move check: read a `.mod` as written (targets, moves, the header's base
//! and yaw), place every collision shape the robot's URDF gives (`links.rs`, read here, any
//! link) and the cell's tool shapes (`Cell::tool`, carried by the flange: the robot's `tool0`)
//! with the URDF kinematics, and sample every move so densely that no point of the arm or the
//! tool moves more than a tenth of the clearance (at most 1 mm) between samples (`reach.rs`),
//! measuring the exact distance to every box with parry3d's own shapes. It shares no code with
//! `collision` or `geometry`: only the cell types and parser and the robot's forward
//! kinematics (which `robot`'s tests hold against RobotStudio). It also holds every via's wrist
//! to the wrist schedule (the leg's wrists in proportion to the via's projection onto the leg's
//! line in axes 1..3, clamped, rounded to 0.001 deg), computed here again. A module of
//! `MoveAbsJ` alone has its robtarget points, TCP, work object, speeds and zones checked in
//! `tcp.rs`; a module that moves to robtargets is held to the cell's program in `program.rs`.
//! Either way the routine is run as the controller runs it (`controller.rs`) and the clearance
//! measured along all of it (`sweep.rs`); `docs/recheck.md` has the whole picture.
//!
//! # What the robot stands on: this check's own reading
//!
//! The base cylinder (base_link's, or link 1's on a robot whose base_link carries none, as the
//! IRB 1400's) starts at the mounting plane, so a floor under the robot touches it. This check
//! does not take the collision model's rule for that; it reads it from the geometry it computes
//! itself, pose by pose: a box is not measured against a base_link or link-1 shape
//! only when the box lies wholly at or below the mounting plane (the header's base z) *and* the
//! cylinder, placed by this check's forward kinematics, lies wholly on or above the box's top
//! (its lowest point, the bottom of its exact bounding box, is not below the top). Any other
//! contact counts: a box reaching above the mounting plane, or a base cylinder that dips below
//! the top of what it would stand on. Links 2..6 are measured against every box.
//!
//! # The header's smallest clearance
//!
//! The collision model certifies its smallest clearance for what it checks. Where that is the
//! URDF's cylinders themselves (links 1..3 alone, the IRB 1400), the header is held to within
//! 0.05 mm (and half a sampling step) of the minimum measured here; where the model checks
//! enclosures of some links (base_link about axis 1, link 4 about axis 4, link 5 as a ball:
//! `robot/lumped.rs`), its figure may lie further below, and the header is held to be a lower
//! bound of the minimum measured here (within the rounding) and never negative.

use super::controller::{self, Run, Setup};
use super::library::RobotFrame;
use super::library::{Base, Cell, Robot, Target, Tool, ToolGeometry};
use super::links::{self, to_pose, LinkShape};
use super::module::Module;
use super::opw::Ik;
use super::program::{check_program, point_as_written, ProgramReport};
use super::reach::{sample_step_mm, Reach};
use super::sweep::sweep;
use super::tcp::{check_tcp, TcpReport};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use parry3d::math::{Pose, Vector};
use parry3d::shape::{Ball, Cuboid, Cylinder, Shape};

/// Heights closer than this count as equal (mm): the box top and the mounting plane, the
/// cylinder's lowest point and the box top.
const STAND_TOL_MM: f64 = 1e-6;

/// The header states the min clearance to 0.1 mm, as a lower bound within 0.05 mm of the
/// true minimum (docs/outputs.md).
const HEADER_ROUNDING_MM: f64 = 0.05;
const HEADER_TOL_MM: f64 = 0.05;

/// Most steps along a corner triangle's edge (a wide corner is sampled more coarsely than
/// `sweep::CORNER_STEP_MM`; the header's bound is then held to the step reached).
const MAX_CORNER_STEPS: usize = 150;

struct Block {
    name: String,
    cuboid: Cuboid,
    pose: Pose,
    top_z: f64,
}

/// A tool shape as this check places it: its name, its pose in the tool0 frame and its parry
/// shape.
struct ToolPiece {
    name: String,
    in_tool0: Isometry3<f64>,
    shape: Box<dyn Shape>,
}

/// The robot placed in the cell, with the cell's boxes and tool.
pub struct Scene<'a> {
    robot: &'a Robot,
    cell_from_robot: Isometry3<f64>,
    blocks: Vec<Block>,
    /// The robot's collision shapes, read from its URDF here.
    links: Vec<LinkShape>,
    tool: Vec<ToolPiece>,
    /// How far any point of the tool lies from the tool0 origin, mm.
    tool_extent_mm: f64,
    /// How far points move per radian of each joint, and the sampling step (`reach.rs`), mm.
    reach: Reach,
    step_mm: f64,
}

/// The nearest link and box at one pose.
#[derive(Clone, Debug)]
pub struct Nearest {
    pub mm: f64,
    pub link: String,
    pub obstacle: String,
}

impl<'a> Scene<'a> {
    /// The robot at `base_mm` turned by `yaw_deg` about z, among the cell's boxes, with the
    /// cell's tool.
    pub fn new(robot: &'a Robot, base_mm: [f64; 3], yaw_deg: f64, cell: &Cell) -> Scene<'a> {
        let boxes: Vec<_> = cell
            .obstacles
            .iter()
            .map(|o| {
                (
                    o.name.clone(),
                    o.aabb.min.coords.into(),
                    o.aabb.max.coords.into(),
                )
            })
            .collect();
        let mut scene =
            Scene::from_boxes(robot, base_mm, yaw_deg, &boxes).with_tool(cell.tool.as_ref());
        scene.step_mm = sample_step_mm(cell.planner.clearance_mm);
        scene
    }

    /// The same scene carrying `tool`'s shapes on the flange (none: no tool volume).
    fn with_tool(mut self, tool: Option<&Tool>) -> Scene<'a> {
        self.tool.clear();
        self.tool_extent_mm = 0.0;
        for s in tool.map(|t| t.shapes.as_slice()).unwrap_or_default() {
            let (in_tool0, shape, extent): (Isometry3<f64>, Box<dyn Shape>, f64) = match s.geometry
            {
                ToolGeometry::Cylinder {
                    from_mm,
                    to_mm,
                    radius_mm,
                } => {
                    let (a, b) = (Point3::from(from_mm), Point3::from(to_mm));
                    let rot = UnitQuaternion::rotation_between(&Vector3::y(), &(b - a))
                        .unwrap_or_else(|| {
                            UnitQuaternion::from_axis_angle(
                                &Vector3::x_axis(),
                                std::f64::consts::PI,
                            )
                        });
                    (
                        Isometry3::from_parts(nalgebra::center(&a, &b).coords.into(), rot),
                        Box::new(Cylinder::new((b - a).norm() / 2.0, radius_mm)),
                        a.coords.norm().max(b.coords.norm()) + radius_mm,
                    )
                }
                ToolGeometry::Box { min_mm, max_mm } => {
                    let c = Vector3::from_fn(|k, _| (min_mm[k] + max_mm[k]) / 2.0);
                    let h = Vector3::from_fn(|k, _| (max_mm[k] - min_mm[k]).abs() / 2.0);
                    (
                        Isometry3::from_parts(c.into(), UnitQuaternion::identity()),
                        Box::new(Cuboid::new(Vector::new(h.x, h.y, h.z))),
                        c.norm() + h.norm(),
                    )
                }
                ToolGeometry::Sphere {
                    centre_mm,
                    radius_mm,
                } => (
                    Isometry3::from_parts(
                        Vector3::from(centre_mm).into(),
                        UnitQuaternion::identity(),
                    ),
                    Box::new(Ball::new(radius_mm)),
                    Vector3::from(centre_mm).norm() + radius_mm,
                ),
            };
            self.tool_extent_mm = self.tool_extent_mm.max(extent);
            self.tool.push(ToolPiece {
                name: s.name.clone(),
                in_tool0,
                shape,
            });
        }
        self.reach = Reach::new(self.robot, &self.links, self.tool_extent_mm);
        self
    }

    /// The same with the boxes given as (name, min, max), cell frame, mm.
    fn from_boxes(
        robot: &'a Robot,
        base_mm: [f64; 3],
        yaw_deg: f64,
        boxes: &[(String, [f64; 3], [f64; 3])],
    ) -> Scene<'a> {
        let cell_from_robot = Isometry3::from_parts(
            Translation3::new(base_mm[0], base_mm[1], base_mm[2]),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), yaw_deg.to_radians()),
        );
        let blocks = boxes
            .iter()
            .map(|(name, min, max)| {
                let h = [0, 1, 2].map(|k| (max[k] - min[k]) / 2.0);
                let c = [0, 1, 2].map(|k| (max[k] + min[k]) / 2.0);
                Block {
                    name: name.clone(),
                    cuboid: Cuboid::new(Vector::new(h[0], h[1], h[2])),
                    pose: Pose::from_translation(Vector::new(c[0], c[1], c[2])),
                    top_z: max[2],
                }
            })
            .collect();
        let links = links::read(robot).unwrap_or_else(|e| panic!("the dense check: {e}"));
        let reach = Reach::new(robot, &links, 0.0);
        Scene {
            robot,
            cell_from_robot,
            blocks,
            links,
            tool: Vec::new(),
            tool_extent_mm: 0.0,
            reach,
            step_mm: sample_step_mm(0.0),
        }
    }

    /// How far points move per radian of each joint (`reach.rs`).
    pub fn reach(&self) -> Reach {
        self.reach
    }

    /// The sampling step: the most any point moves between neighbouring samples, mm.
    pub fn step_mm(&self) -> f64 {
        self.step_mm
    }

    /// The most any point of the arm or the tool moves along the straight joint move `a -> b`,
    /// mm.
    pub fn motion_mm(&self, a: &[f64; 6], b: &[f64; 6]) -> f64 {
        self.reach.motion_mm(self.robot, a, b)
    }

    /// Height of the mounting plane (the base frame's origin), cell frame, mm.
    fn mounting_plane_z(&self) -> f64 {
        self.cell_from_robot.translation.vector.z
    }

    /// The smallest distance from the robot's collision shapes and the tool's shapes to the
    /// boxes at controller axes 1..6, and where (a link by name, a tool shape as
    /// `tool shape 'name'`); `mm` is infinite when nothing is measured.
    pub fn nearest(&self, axes: [f64; 6]) -> Nearest {
        let poses = self.robot.link_poses(&axes);
        let mut best = Nearest {
            mm: f64::INFINITY,
            link: String::new(),
            obstacle: String::new(),
        };
        for l in &self.links {
            let frame = match l.carrier {
                Some(k) => self.cell_from_robot * poses[k],
                None => self.cell_from_robot,
            };
            let pose = to_pose(&(frame * l.in_frame));
            let lowest_z = l.shape.compute_aabb(&pose).mins.z;
            for block in &self.blocks {
                if l.carrier.is_none_or(|k| k == 0) && self.stands_on(lowest_z, block) {
                    continue;
                }
                let d =
                    parry3d::query::distance(&pose, l.shape.as_ref(), &block.pose, &block.cuboid)
                        .expect("convex shapes")
                        .distance;
                if d < best.mm {
                    best = Nearest {
                        mm: d,
                        link: l.link.clone(),
                        obstacle: block.name.clone(),
                    };
                }
            }
        }
        if !self.tool.is_empty() {
            let flange = self.cell_from_robot * self.robot.tool0(&axes);
            for piece in &self.tool {
                let iso = flange * piece.in_tool0;
                let t = iso.translation.vector;
                let q = iso.rotation.quaternion();
                let pose = Pose::from_parts(
                    Vector::new(t.x, t.y, t.z),
                    parry3d::math::Rotation::from_xyzw(q.i, q.j, q.k, q.w),
                );
                for block in &self.blocks {
                    let d = parry3d::query::distance(
                        &pose,
                        piece.shape.as_ref(),
                        &block.pose,
                        &block.cuboid,
                    )
                    .expect("convex shapes")
                    .distance;
                    if d < best.mm {
                        best = Nearest {
                            mm: d,
                            link: format!("tool shape '{}'", piece.name),
                            obstacle: block.name.clone(),
                        };
                    }
                }
            }
        }
        best
    }

    /// The nearest approach (links and tool shapes) along the straight six-axis move `a -> b`,
    /// sampled as [`check_module`] does (no point of the arm or the tool moves more than
    /// [`step_mm`](Self::step_mm) between samples, so the true minimum lies at most half that
    /// below it), with the number of samples.
    pub fn nearest_along(&self, a: &[f64; 6], b: &[f64; 6]) -> (Nearest, usize) {
        let n = self.steps_along(a, b);
        let mut best = Nearest {
            mm: f64::INFINITY,
            link: String::new(),
            obstacle: String::new(),
        };
        for i in 0..=n {
            let t = i as f64 / n as f64;
            let near = self.nearest(std::array::from_fn(|k| a[k] + t * (b[k] - a[k])));
            if near.mm < best.mm {
                best = near;
            }
        }
        (best, n + 1)
    }

    /// How many steps the straight six-axis move `a -> b` is sampled in so that no point of the
    /// arm or the tool moves more than [`step_mm`](Self::step_mm) between samples (the bound of
    /// `reach.rs`).
    pub fn steps_along(&self, a: &[f64; 6], b: &[f64; 6]) -> usize {
        (self.motion_mm(a, b) / self.step_mm).ceil().max(1.0) as usize
    }

    /// The nearest approach over the triangle `tri` of controller values, sampled on a
    /// barycentric grid with at most `step_mm` of motion of any point between neighbouring
    /// samples (each edge's motion bound, `reach.rs`), but at most [`MAX_CORNER_STEPS`]
    /// steps along an edge, with the number of samples and the motion between neighbouring
    /// samples it reached, mm.
    pub fn nearest_over_triangle(
        &self,
        tri: &[[f64; 6]; 3],
        step_mm: f64,
    ) -> (Nearest, usize, f64) {
        let edge = |a: usize, b: usize| self.motion_mm(&tri[a], &tri[b]);
        let widest = edge(0, 1).max(edge(1, 2)).max(edge(2, 0));
        let n = ((widest / step_mm).ceil() as usize).clamp(1, MAX_CORNER_STEPS);
        let mut best = Nearest {
            mm: f64::INFINITY,
            link: String::new(),
            obstacle: String::new(),
        };
        let mut count = 0;
        for i in 0..=n {
            for j in 0..=(n - i) {
                let (b, c) = (i as f64 / n as f64, j as f64 / n as f64);
                let axes: [f64; 6] = std::array::from_fn(|k| {
                    (1.0 - b - c) * tri[0][k] + b * tri[1][k] + c * tri[2][k]
                });
                let near = self.nearest(axes);
                count += 1;
                if near.mm < best.mm {
                    best = near;
                }
            }
        }
        (best, count, widest / n as f64)
    }

    /// Whether a base or link-1 shape whose lowest point is at `lowest_z` stands on `block` (module
    /// doc): the block wholly at or below the mounting plane, the cylinder wholly on or above
    /// the block's top.
    fn stands_on(&self, lowest_z: f64, block: &Block) -> bool {
        block.top_z <= self.mounting_plane_z() + STAND_TOL_MM
            && lowest_z >= block.top_z - STAND_TOL_MM
    }

    /// The wrist centre (origin of the link moved by joint 5) in the cell frame, mm.
    fn wrist_centre(&self, axes: &[f64; 6]) -> Point3<f64> {
        self.cell_from_robot * self.robot.wrist_centre(axes)
    }
}

/// Every via whose wrist is not the leg's wrist schedule: between two consecutive cell points
/// (six axes `p`, `q` as written), a via at axes 1..3 `v` has axes 4..6
/// `round(w_p + s (w_q - w_p), 0.001)` with `s` the projection of `v - p` onto `q - p` in axes
/// 1..3, clamped to [0, 1] (the module rounds, so a value 1e-6 off a rounding boundary may go
/// either way: 0.0011 deg is allowed).
pub fn wrist_schedule_errors(cell: &Cell, module: &Module) -> Vec<String> {
    let names: Vec<&str> = cell.points.iter().map(|p| p.name.as_str()).collect();
    let marks: Vec<usize> = module
        .targets
        .iter()
        .enumerate()
        .filter(|(_, t)| names.contains(&t.0.as_str()))
        .map(|(i, _)| i)
        .collect();
    let mut out = Vec::new();
    for leg in marks.windows(2) {
        let (p, q) = (module.targets[leg[0]].1, module.targets[leg[1]].1);
        let d: Vec<f64> = (0..3).map(|k| q[k] - p[k]).collect();
        let len2: f64 = d.iter().map(|x| x * x).sum();
        for (name, v) in &module.targets[leg[0] + 1..leg[1]] {
            let s = if len2 > 0.0 {
                ((0..3).map(|k| (v[k] - p[k]) * d[k]).sum::<f64>() / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            for k in 3..6 {
                let want = ((p[k] + s * (q[k] - p[k])) * 1000.0).round() / 1000.0;
                if (v[k] - want).abs() > 0.0011 {
                    out.push(format!(
                        "via {name}: axis {} = {}, the wrist schedule gives {want} (s = {s:.5})",
                        k + 1,
                        v[k]
                    ));
                }
            }
        }
    }
    out
}

/// What [`check_module`] measured.
#[derive(Debug)]
pub struct Report {
    pub module: Module,
    /// The sampling step: the most any point moved between neighbouring samples, mm.
    pub step_mm: f64,
    /// Poses measured along the moves and over the zoned corners.
    pub samples: usize,
    /// Corners written with a fly-by zone, each sampled over its triangle.
    pub corners: usize,
    /// The nearest approach seen (infinite without boxes).
    pub smallest: Nearest,
    /// Cell points given as `xyz` whose written joints were held against them.
    pub xyz_points: usize,
    /// The robtarget points, tooldata, wobjdata and moves of a module of `MoveAbsJ` alone
    /// (`tcp.rs`).
    pub tcp: TcpReport,
    /// The routine as the controller ran it (`controller.rs`).
    pub run: Run,
    /// The program of a module that moves to robtargets or runs actions (`program.rs`).
    pub program: ProgramReport,
}

/// The points of a module of `MoveAbsJ` alone, and the header's count of moves: the moves name
/// the targets one to one, in order, from the first cell point to the last; every cell point
/// appears, in order: joint points exactly as given, xyz points at their wrist centre by forward
/// kinematics from the header's placement; every target in range; every via's wrist on the
/// leg's schedule. The number of xyz points held, and the failures.
fn joint_module_points(
    cell: &Cell,
    robot: &Robot,
    scene: &Scene,
    module: &Module,
) -> (usize, Vec<String>) {
    let mut failures = Vec::new();
    let mut fail = |m: String| failures.push(m);
    if module.header_moves + 1 != module.moves.len() {
        fail(format!(
            "header says {} moves, PROC main has {} MoveAbsJ",
            module.header_moves,
            module.moves.len()
        ));
    }
    let names: Vec<&str> = module.targets.iter().map(|t| t.0.as_str()).collect();
    if names != module.moves.iter().map(String::as_str).collect::<Vec<_>>() {
        fail(format!(
            "moves {:?} do not name the targets {names:?} in order",
            module.moves
        ));
    }
    if names.first().copied() != cell.points.first().map(|p| p.name.as_str())
        || names.last().copied() != cell.points.last().map(|p| p.name.as_str())
    {
        fail("the first and last targets are not the first and last cell points".into());
    }
    let mut k = 0;
    let mut xyz_points = 0;
    for p in &cell.points {
        let Some(at) = module.targets[k..].iter().position(|t| t.0 == p.name) else {
            fail(format!("point {} missing or out of order", p.name));
            continue;
        };
        k += at;
        let axes = module.targets[k].1;
        if matches!(p.target, Target::Xyz { .. }) {
            xyz_points += 1;
        }
        // A robtarget point is reached by its jointtarget: `tcp::check_tcp`.
        if let Some(e) = point_as_written(cell, robot, &scene.cell_from_robot, p, &axes) {
            fail(e);
        }
    }
    for (name, axes) in &module.targets {
        if let Err(e) = robot.check_range6(axes) {
            fail(format!("target {name} out of range: {e}"));
        }
    }
    for m in wrist_schedule_errors(cell, module) {
        fail(m);
    }
    (xyz_points, failures)
}

/// Checks a module written for `cell` by `robot` (see the module doc); `label` names it in
/// messages. Every failure is collected; `Err` lists them all.
pub fn check_module(
    cell: &Cell,
    robot: &Robot,
    text: &str,
    label: &str,
) -> Result<Report, Vec<String>> {
    let module = Module::parse(text).map_err(|e| vec![format!("{label}: {e}")])?;
    let mut failures = Vec::new();
    let mut fail = |m: String| failures.push(format!("{label}: {m}"));

    // The header: the cell's clearance; the base and yaw as given (`base: auto`: on z = 0,
    // the yaw as given); one move fewer than targets.
    if module.clearance_mm != cell.planner.clearance_mm {
        fail(format!(
            "header clearance {} mm, the cell says {}",
            module.clearance_mm, cell.planner.clearance_mm
        ));
    }
    match cell.robot.base {
        Base::Fixed(b) if module.base_mm != b => fail(format!(
            "header base {:?}, the cell says {b:?}",
            module.base_mm
        )),
        Base::Auto if module.base_mm[2] != 0.0 => fail(format!(
            "header base {:?}: base: auto stands on z = 0",
            module.base_mm
        )),
        _ => {}
    }
    if module.yaw_deg != cell.robot.yaw_deg {
        fail(format!(
            "header yaw {}, the cell says {}",
            module.yaw_deg, cell.robot.yaw_deg
        ));
    }

    let scene = Scene::new(robot, module.base_mm, module.yaw_deg, cell);
    // What the module says of the cell: a module of `MoveAbsJ` alone (robtarget points reached
    // by their jointtargets) target by target, with `tcp.rs`; a module that moves to robtargets
    // or runs actions as the contract's program (`program.rs`).
    let joint_moves = module.joint_moves_only();
    let mut xyz_points = 0;
    let mut program = ProgramReport::default();
    if joint_moves {
        let (n, f) = joint_module_points(cell, robot, &scene, &module);
        xyz_points = n;
        f.into_iter().for_each(&mut fail);
    } else {
        match check_program(cell, robot, &module, &scene.cell_from_robot) {
            Ok(r) => program = r,
            Err(f) => f.into_iter().for_each(&mut fail),
        }
    }

    // The routine as the controller runs it, and the clearance along all of it.
    let setup = Setup {
        robot,
        ik: Ik::new(robot),
        world_from_base: match cell.robot.frame {
            RobotFrame::Base => Isometry3::identity(),
            RobotFrame::Cell => scene.cell_from_robot,
        },
        reach: scene.reach(),
        step_mm: scene.step_mm(),
    };
    let (run, f) = controller::run(&module, &setup);
    f.into_iter().for_each(&mut fail);
    let swept = sweep(&scene, &run, cell.planner.clearance_mm);
    swept.failures.iter().cloned().for_each(&mut fail);
    let (samples, corners, smallest, corner_smallest) = (
        swept.samples,
        swept.corners,
        swept.smallest,
        swept.corner_smallest,
    );

    // The header's min clearance is a lower bound within 0.05 mm of the true minimum, which lies
    // at most half the sampling step below the smallest sample of a move (`reach.rs`), at most
    // the step reached below that of a corner, and not above either. Where the model checks
    // enclosures of some links (module doc: a shape on the base or on links 4..6), a lower
    // bound, not below 0.
    let step_mm = scene.step_mm();
    let enclosed = scene.links.iter().any(|l| l.carrier.is_none_or(|k| k >= 3));
    match (module.min_clearance_mm, smallest.mm.is_finite()) {
        (Some(h), true) => {
            let (lo, hi) = (
                match enclosed {
                    false => {
                        (smallest.mm - step_mm / 2.0).min(corner_smallest)
                            - HEADER_TOL_MM
                            - HEADER_ROUNDING_MM
                    }
                    true => 0.0,
                },
                smallest.mm + HEADER_ROUNDING_MM,
            );
            if !(lo - 1e-9..=hi + 1e-9).contains(&h) {
                fail(format!(
                    "header min clearance {h} mm, but the dense check measures {:.3} mm ({} to {}): expected {lo:.3} .. {hi:.3}",
                    smallest.mm, smallest.link, smallest.obstacle
                ));
            }
        }
        (None, false) => {}
        (h, _) => fail(format!(
            "header min clearance {h:?}, but the dense check measures {:.3} mm",
            smallest.mm
        )),
    }

    let tcp = match joint_moves {
        true => match check_tcp(cell, robot, &module, &scene.cell_from_robot) {
            Ok(r) => r,
            Err(f) => {
                failures.extend(f.into_iter().map(|m| format!("{label}: {m}")));
                TcpReport::default()
            }
        },
        false => TcpReport::default(),
    };
    if failures.is_empty() {
        Ok(Report {
            module,
            step_mm,
            samples,
            corners,
            smallest,
            xyz_points,
            tcp,
            run,
            program,
        })
    } else {
        Err(failures)
    }
}
