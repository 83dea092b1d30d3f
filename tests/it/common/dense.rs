//! The independent whole-move check: read a `.mod` as written (targets, moves, the header's base
//! and yaw), place the robot's link cylinders (every link's, base_link to link_6, as the URDF
//! gives them on its own link: `Robot::collision`, not the enclosures the collision model
//! carries them by) and the cell's tool shapes (`Cell::tool`, carried by the flange: the robot's
//! `tool0`) with the URDF kinematics, and sample every straight
//! six-axis move so densely that no point of the arm or the tool moves more than 1 mm between
//! samples, measuring the exact distance to every box with parry3d's own shapes. It shares no
//! code with `collision` or `geometry`: only the cell types and parser and the robot's
//! kinematics (which `robot`'s tests hold against RobotStudio). It also holds every via's wrist
//! to the wrist schedule (the leg's wrists in proportion to the via's projection onto the leg's
//! line in axes 1..3, clamped, rounded to 0.001 deg), computed here again. Robtarget points, the
//! TCP, the work object and each move's speed and zone are checked in `tcp.rs`.
//!
//! # What the robot stands on: this check's own reading
//!
//! The base cylinder (base_link's, or link 1's on a robot whose base_link carries none, as the
//! IRB 1400's) starts at the mounting plane, so a floor under the robot touches it. This check
//! does not take the collision model's rule for that; it reads it from the geometry it computes
//! itself, pose by pose: a box is not measured against a base_link or link-1 cylinder
//! only when the box lies wholly at or below the mounting plane (the header's base z) *and* the
//! cylinder, placed by this check's forward kinematics, lies wholly on or above the box's top
//! (its lowest point, `min(end z) - r sin(tilt)`, is not below the top). Any other contact
//! counts: a box reaching above the mounting plane, or a base cylinder that dips below the top
//! of what it would stand on. Links 2..6 are measured against every box.
//!
//! # The header's smallest clearance
//!
//! The collision model certifies its smallest clearance for what it checks. Where that is the
//! URDF's cylinders themselves (links 1..3 alone, the IRB 1400), the header is held to within
//! 0.05 mm of the minimum measured here; where the model checks enclosures of some links
//! (base_link about axis 1, link 4 about axis 4, link 5 as a ball: `robot/lumped.rs`), its
//! figure may lie further below, and the header is held to be a lower bound of the minimum
//! measured here (within the rounding) and never negative.

use super::library::{Base, Cell, LinkFrame, Robot, Target, Tool, ToolGeometry};
use super::module::Module;
use super::tcp::{check_tcp, TcpReport};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use parry3d::math::{Pose, Vector};
use parry3d::shape::{Ball, Cuboid, Cylinder, Shape};

/// Heights closer than this count as equal (mm): the box top and the mounting plane, the
/// cylinder's lowest point and the box top.
const STAND_TOL_MM: f64 = 1e-6;

/// No point of the IRB 1400 is farther than this from any joint axis (reach 1.44 m plus the
/// wrist; radius and offsets stay well below 2 m), mm; a larger robot takes its own bound
/// ([`arm_radius_mm`]).
const ARM_RADIUS_MM: f64 = 2000.0;

/// A bound on the distance of any point of any link cylinder from any joint axis, mm: for a
/// cylinder on the child of joint `j` and an axis `i <= j`, the length across axis `i` of joint
/// `i + 1`'s origin, the lengths of the origins after it up to `j`, and the cylinder's farthest
/// point from its link's origin (the ends' distance plus the radius); at least
/// [`ARM_RADIUS_MM`].
fn arm_radius_mm(robot: &Robot) -> f64 {
    let t = |k: usize| robot.joints[k].origin.translation.vector;
    let mut r: f64 = ARM_RADIUS_MM;
    for c in &robot.collision {
        let LinkFrame::Child(j) = c.frame else {
            continue; // base_link does not move
        };
        let far = c.a.coords.norm().max(c.b.coords.norm()) + c.radius_mm;
        for i in 0..=j {
            let u = robot.joints[i].axis.into_inner();
            let across = if i < j {
                let v = t(i + 1);
                (v - u * u.dot(&v)).norm()
            } else {
                0.0
            };
            let chain: f64 = (i + 2..=j).map(|k| t(k).norm()).sum();
            r = r.max(across + chain + far);
        }
    }
    r
}

/// A cell-frame xyz point's written joints must give it back within this, mm (the module's
/// 0.001 deg moves the wrist centre by less than 0.05 mm).
const XYZ_TOL_MM: f64 = 0.05;

/// The header states the min clearance to 0.1 mm, as a lower bound within 0.05 mm of the
/// true minimum (docs/outputs.md).
const HEADER_ROUNDING_MM: f64 = 0.05;
const HEADER_TOL_MM: f64 = 0.05;

/// Most motion of any point of the arm or tool between neighbouring samples of a corner
/// triangle, mm (a triangle is sampled over an area, so more coarsely than a move).
const CORNER_STEP_MM: f64 = 4.0;

/// Most steps along a corner triangle's edge (a wide corner is sampled more coarsely than
/// [`CORNER_STEP_MM`]; the header's bound is then held to the step reached).
const MAX_CORNER_STEPS: usize = 150;

/// The midpoint of two six-axis configurations.
fn mid(a: &[f64; 6], b: &[f64; 6]) -> [f64; 6] {
    std::array::from_fn(|k| 0.5 * (a[k] + b[k]))
}

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
    /// [`arm_radius_mm`] of the robot.
    arm_radius_mm: f64,
    cell_from_robot: Isometry3<f64>,
    blocks: Vec<Block>,
    tool: Vec<ToolPiece>,
    /// How far any point of the tool lies from the tool0 origin, mm.
    tool_extent_mm: f64,
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
        Scene::from_boxes(robot, base_mm, yaw_deg, &boxes).with_tool(cell.tool.as_ref())
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
        Scene {
            robot,
            arm_radius_mm: arm_radius_mm(robot),
            cell_from_robot,
            blocks,
            tool: Vec::new(),
            tool_extent_mm: 0.0,
        }
    }

    /// The most any point of the arm or the tool can move per radian of any joint, mm: the arm
    /// radius plus the tool's extent beyond the flange.
    pub fn radius_mm(&self) -> f64 {
        self.arm_radius_mm + self.tool_extent_mm
    }

    /// Height of the mounting plane (the base frame's origin), cell frame, mm.
    fn mounting_plane_z(&self) -> f64 {
        self.cell_from_robot.translation.vector.z
    }

    /// The smallest distance from the link cylinders and the tool's shapes to the boxes at
    /// controller axes 1..6, and where (a link by name, a tool shape as `tool shape 'name'`);
    /// `mm` is infinite when nothing is measured.
    pub fn nearest(&self, axes: [f64; 6]) -> Nearest {
        let poses = self.robot.link_poses(&axes);
        let mut best = Nearest {
            mm: f64::INFINITY,
            link: String::new(),
            obstacle: String::new(),
        };
        for c in &self.robot.collision {
            let (frame, base) = match c.frame {
                LinkFrame::Base => (self.cell_from_robot, true),
                LinkFrame::Child(k) => (self.cell_from_robot * poses[k], k == 0),
            };
            let (a, b) = (frame * c.a, frame * c.b);
            let axis = b - a;
            let len = axis.norm();
            let dir = axis / len;
            let rot = UnitQuaternion::rotation_between(&Vector3::y(), &dir).unwrap_or_else(|| {
                UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
            });
            let q = rot.quaternion();
            let mid = nalgebra::center(&a, &b);
            let pose = Pose::from_parts(
                Vector::new(mid.x, mid.y, mid.z),
                parry3d::math::Rotation::from_xyzw(q.i, q.j, q.k, q.w),
            );
            let cyl = Cylinder::new(len / 2.0, c.radius_mm);
            let lowest_z = lowest_point_z(a, b, dir, c.radius_mm);
            for block in &self.blocks {
                if base && self.stands_on(lowest_z, block) {
                    continue;
                }
                let d = parry3d::query::distance(&pose, &cyl, &block.pose, &block.cuboid)
                    .expect("convex shapes")
                    .distance;
                if d < best.mm {
                    best = Nearest {
                        mm: d,
                        link: c.link.clone(),
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
    /// sampled as [`check_module`] does (no point of the arm or the tool moves more than 1 mm
    /// between samples, so the true minimum lies at most 0.5 mm below it), with the number of
    /// samples.
    pub fn nearest_along(&self, a: &[f64; 6], b: &[f64; 6]) -> (Nearest, usize) {
        let qa = self.robot.urdf_joints_deg(a);
        let qb = self.robot.urdf_joints_deg(b);
        let turn_rad: f64 = (0..6).map(|k| (qb[k] - qa[k]).abs().to_radians()).sum();
        let n = (self.radius_mm() * turn_rad).ceil().max(1.0) as usize;
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

    /// The nearest approach over the triangle `tri` of controller values, sampled on a
    /// barycentric grid with at most `step_mm` of motion of any point between neighbouring
    /// samples (each edge's joint turn, times the radius), but at most [`MAX_CORNER_STEPS`]
    /// steps along an edge, with the number of samples and the motion between neighbouring
    /// samples it reached, mm.
    pub fn nearest_over_triangle(
        &self,
        tri: &[[f64; 6]; 3],
        step_mm: f64,
    ) -> (Nearest, usize, f64) {
        let q: Vec<[f64; 6]> = tri.iter().map(|t| self.robot.urdf_joints_deg(t)).collect();
        let turn = |a: usize, b: usize| -> f64 {
            (0..6).map(|k| (q[b][k] - q[a][k]).abs().to_radians()).sum()
        };
        let widest = turn(0, 1).max(turn(1, 2)).max(turn(2, 0));
        let n = ((self.radius_mm() * widest / step_mm).ceil() as usize).clamp(1, MAX_CORNER_STEPS);
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
        (best, count, self.radius_mm() * widest / n as f64)
    }

    /// Whether a base_link or link-1 cylinder whose lowest point is at `lowest_z` stands on
    /// `block` (module doc): the block wholly at or below the mounting plane, the cylinder
    /// wholly on or above the block's top.
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

/// Height of the lowest point of a cylinder with axis ends `a`, `b` (unit direction `dir`) and
/// radius `r`: each end disc reaches `r sin(tilt)` below its centre.
fn lowest_point_z(a: Point3<f64>, b: Point3<f64>, dir: Vector3<f64>, r: f64) -> f64 {
    a.z.min(b.z) - r * (1.0 - dir.z * dir.z).max(0.0).sqrt()
}

/// What [`check_module`] measured.
#[derive(Debug)]
pub struct Report {
    pub module: Module,
    /// Poses measured along the moves and over the zoned corners.
    pub samples: usize,
    /// Corners written with a fly-by zone, each sampled over its triangle.
    pub corners: usize,
    /// The nearest approach seen (infinite without boxes).
    pub smallest: Nearest,
    /// Cell points given as `xyz` whose written joints were held against them.
    pub xyz_points: usize,
    /// The robtarget points, tooldata, wobjdata and moves (`tcp.rs`).
    pub tcp: TcpReport,
}

/// Checks a module written for `cell` by `robot` (see the module doc); `label` names it in
/// messages. Every failure is collected; `Err` lists them all.
pub fn check_module(
    cell: &Cell,
    robot: &Robot,
    text: &str,
    label: &str,
) -> Result<Report, Vec<String>> {
    let mut module = Module::parse(text).map_err(|e| vec![format!("{label}: {e}")])?;
    // The moves as the controller runs them: a MoveJ's joints from its robtarget.
    let cell_from_robot = Isometry3::from_parts(
        Translation3::new(module.base_mm[0], module.base_mm[1], module.base_mm[2]),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), module.yaw_deg.to_radians()),
    );
    module
        .resolve_joint_moves(robot, &cell_from_robot)
        .map_err(|e| vec![format!("{label}: {e}")])?;
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
    if module.header_moves + 1 != module.moves.len() {
        fail(format!(
            "header says {} moves, PROC main has {} MoveAbsJ",
            module.header_moves,
            module.moves.len()
        ));
    }
    // Moves name the targets one to one, in order.
    let names: Vec<&str> = module.targets.iter().map(|t| t.0.as_str()).collect();
    if names != module.moves.iter().map(String::as_str).collect::<Vec<_>>() {
        fail(format!(
            "moves {:?} do not name the targets {names:?} in order",
            module.moves
        ));
    }
    // The last: the last cell point's, or the first's after the leg closing the cycle.
    let last_point = match cell.closing_leg() {
        true => cell.points.first(),
        false => cell.points.last(),
    };
    if names.first().copied() != cell.points.first().map(|p| p.name.as_str())
        || names.last().copied() != last_point.map(|p| p.name.as_str())
    {
        fail("the first and last targets are not the first and last cell points".into());
    }

    let scene = Scene::new(robot, module.base_mm, module.yaw_deg, cell);
    // Every cell point appears, in order: joint points exactly as given, xyz points at their
    // wrist centre by forward kinematics from the header's placement.
    let mut k = 0;
    let mut xyz_points = 0;
    for p in &cell.points {
        let Some(at) = module.targets[k..].iter().position(|t| t.0 == p.name) else {
            fail(format!("point {} missing or out of order", p.name));
            continue;
        };
        k += at;
        let axes = module.targets[k].1;
        match &p.target {
            Target::Joints {
                axes_deg,
                wrist_deg,
            } => {
                let w = wrist_deg.unwrap_or(cell.robot.wrist_deg);
                if axes[..3] != axes_deg[..] || axes[3..] != w[..] {
                    fail(format!(
                        "point {} written as {axes:?}, given as {axes_deg:?} wrist {w:?}",
                        p.name
                    ));
                }
            }
            Target::Xyz {
                wrist_centre_mm, ..
            } => {
                xyz_points += 1;
                let back = scene.wrist_centre(&axes);
                let off = (back - Point3::from(*wrist_centre_mm)).norm();
                if off > XYZ_TOL_MM {
                    fail(format!(
                        "point {}: its written joints {axes:?} reach {back:?}, {off:.3} mm from the given {wrist_centre_mm:?}",
                        p.name
                    ));
                }
            }
            // Reached by its jointtarget: `tcp::check_tcp` below.
            Target::Robtarget { .. } => {}
        }
    }
    for (name, axes) in &module.targets {
        if let Err(e) = robot.check_range6(axes) {
            fail(format!("target {name} out of range: {e}"));
        }
    }
    for m in wrist_schedule_errors(cell, &module) {
        fail(m);
    }

    let mut samples = 0;
    let mut smallest = Nearest {
        mm: f64::INFINITY,
        link: String::new(),
        obstacle: String::new(),
    };
    for w in module.targets.windows(2) {
        let (a, b) = (w[0].1, w[1].1);
        let qa = robot.urdf_joints_deg(&a);
        let qb = robot.urdf_joints_deg(&b);
        // Every point lies within `radius_mm` of every joint axis, so it moves at most that much
        // per radian of each joint (the wrist axes move only the tool and the wrist).
        let turn_rad: f64 = (0..6).map(|k| (qb[k] - qa[k]).abs().to_radians()).sum();
        let n = (scene.radius_mm() * turn_rad).ceil().max(1.0) as usize;
        for i in 0..=n {
            let t = i as f64 / n as f64;
            let axes: [f64; 6] = std::array::from_fn(|k| a[k] + t * (b[k] - a[k]));
            let near = scene.nearest(axes);
            samples += 1;
            let below = near.mm < cell.planner.clearance_mm - 1e-6;
            if below {
                fail(format!(
                    "move {} -> {} at t = {t:.4} ({axes:?}): {} is {:.3} mm from {}, below the clearance {} mm",
                    w[0].0, w[1].0, near.link, near.mm, near.obstacle, cell.planner.clearance_mm
                ));
            }
            if near.mm < smallest.mm {
                smallest = near;
            }
            if below {
                break; // one message per move
            }
        }
    }

    // Every corner written with a fly-by zone (issue 10): the triangle of the midpoint of the
    // move into the target, the target and the midpoint of the move out, sampled on a
    // barycentric grid with at most CORNER_STEP_MM of motion of any point between neighbours.
    // The route starts and ends at a stop: the first and last moves are `fine`.
    let last = module.targets.len().saturating_sub(1);
    for k in [0, last] {
        if let Some(m) = module.move_args.get(k) {
            if !m.zone.eq_ignore_ascii_case("fine") {
                fail(format!(
                    "the move to {} is {}, not fine",
                    module.targets[k].0, m.zone
                ));
            }
        }
    }
    let mut corners = 0;
    let mut corner_smallest = f64::INFINITY;
    for k in 1..module.targets.len().saturating_sub(1) {
        let zone = module.move_args.get(k).map_or("fine", |m| m.zone.as_str());
        if zone.eq_ignore_ascii_case("fine") {
            continue;
        }
        corners += 1;
        let (p, v, n) = (
            module.targets[k - 1].1,
            module.targets[k].1,
            module.targets[k + 1].1,
        );
        let tri = [mid(&p, &v), v, mid(&v, &n)];
        let (near, count, step) = scene.nearest_over_triangle(&tri, CORNER_STEP_MM);
        samples += count;
        if near.mm < cell.planner.clearance_mm - 1e-6 {
            fail(format!(
                "corner at {} ({zone}): {} is {:.3} mm from {}, below the clearance {} mm",
                module.targets[k].0, near.link, near.mm, near.obstacle, cell.planner.clearance_mm
            ));
        }
        corner_smallest = corner_smallest.min(near.mm - step);
        if near.mm < smallest.mm {
            smallest = near;
        }
    }

    // The header's min clearance is a lower bound within 0.05 mm of the true minimum, which lies
    // at most 0.5 mm below the smallest sample of a move (1 mm of motion between samples), at
    // most the step reached below that of a corner, and not above either. Where the model
    // checks enclosures of some links (module doc), a lower bound, not below 0.
    let enclosed = robot
        .collision
        .iter()
        .any(|c| matches!(c.frame, LinkFrame::Base | LinkFrame::Child(3..)));
    match (module.min_clearance_mm, smallest.mm.is_finite()) {
        (Some(h), true) => {
            let (lo, hi) = (
                match enclosed {
                    false => {
                        (smallest.mm - 0.5).min(corner_smallest)
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

    let tcp = match check_tcp(cell, robot, &module, &scene.cell_from_robot) {
        Ok(r) => r,
        Err(f) => {
            failures.extend(f.into_iter().map(|m| format!("{label}: {m}")));
            TcpReport::default()
        }
    };
    if failures.is_empty() {
        Ok(Report {
            module,
            samples,
            corners,
            smallest,
            xyz_points,
            tcp,
        })
    } else {
        Err(failures)
    }
}
