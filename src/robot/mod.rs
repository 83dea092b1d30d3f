//! The robot model: a serial chain of six revolute joints read from a URDF, the collision
//! cylinders of its links, and the controller's joint convention.
//!
//! Stage: URDF (+ controller file) -> [`Robot`]. Paper: Ting & Jar (2006) section 3 and 6 lump
//! the arm into its first three links, each a cylinder; this module holds those cylinders and the
//! forward kinematics that places them. Beyond the paper, every link from the base to the flange
//! may carry cylinders ([`Robot::collision`], as the URDF gives them); `lumped.rs` carries them
//! the way the checks do: the base's and link 4's as cylinders about axis 1 and axis 4 that ride
//! on links 1 and 3 ([`Robot::cylinders`]), link 5's and link 6's on the flange
//! ([`Robot::flange_parts`]). `models.rs` holds the robots built into the binary
//! ([`Robot::shipped`], `robot.model`).
//!
//! Units: the URDF speaks metres and radians; [`urdf`] converts once, at load, to millimetres
//! and degrees. Every joint value that crosses this module's API is a **controller value** in
//! degrees (what a RAPID `jointtarget` holds); [`Robot::urdf_joints_deg`] is the one place that
//! applies the controller's coupling ([`controller`]) to get URDF joint values (and
//! [`Robot::urdf_arm_sincos`] the same coupling on sines and cosines, for `chain.rs`: the
//! forward kinematics from sines and cosines the tool looks of a leg use).

mod chain;
pub mod controller;
pub mod ik;
mod lumped;
pub mod models;
#[cfg(test)]
mod models_tests;
pub mod urdf;
mod xml_depth;

use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};
use std::path::{Path, PathBuf};

pub use chain::{MilliDegSinCos, Pose, SinCosChain};
pub use controller::{AxisSpec, Controller, Coupling};

/// Controller values of axes 1..6, degrees.
pub type Axes6 = [f64; 6];
/// Controller values of axes 1..3 (the planning axes), degrees.
pub type Axes3 = [f64; 3];

/// One revolute joint of the chain, in millimetres.
#[derive(Clone, Debug)]
pub struct RevoluteJoint {
    pub name: String,
    /// Name of the child link (the link this joint moves).
    pub child_link: String,
    /// Pose of the joint frame in the parent link frame (fixed joints in between folded in), mm.
    pub origin: Isometry3<f64>,
    /// Rotation axis in the joint frame.
    pub axis: Unit<Vector3<f64>>,
}

/// A collision cylinder of the lumped arm, carried by the child link of `joints[joint_index]`
/// (0, 1 or 2): that link's own cylinder, or one that encloses the cylinder of `link` for every
/// angle of the axis between them (`lumped.rs`: base_link's on link 1, link 4's on link 3).
#[derive(Clone, Debug)]
pub struct LinkCylinder {
    /// The link whose collision geometry it holds (messages name it).
    pub link: String,
    pub joint_index: usize,
    /// Axis end points in the carrying link's frame, mm.
    pub a: Point3<f64>,
    pub b: Point3<f64>,
    pub radius_mm: f64,
}

/// The frame a collision cylinder of the URDF is fixed in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkFrame {
    /// The root link (base_link): fixed to the robot base.
    Base,
    /// The child link of `joints[i]` (`i` 0..5: link_1 .. link_6).
    Child(usize),
}

/// A collision cylinder as the URDF gives it, on its own link.
#[derive(Clone, Debug)]
pub struct OwnCylinder {
    pub link: String,
    pub frame: LinkFrame,
    /// Axis end points in the link's frame, mm.
    pub a: Point3<f64>,
    pub b: Point3<f64>,
    pub radius_mm: f64,
}

/// A part of the robot the flange (link 6) carries besides the tool: link 6's own cylinders,
/// and a ball about axis 6 that holds a link-5 cylinder for every angle of axis 6 (`lumped.rs`).
#[derive(Clone, Debug, PartialEq)]
pub struct FlangePart {
    /// The link whose collision geometry it holds.
    pub link: String,
    pub shape: FlangeShape,
}

/// A flange part's shape in link 6's frame, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FlangeShape {
    Cylinder {
        a: Point3<f64>,
        b: Point3<f64>,
        radius_mm: f64,
    },
    Ball {
        centre: Point3<f64>,
        radius_mm: f64,
    },
}

/// A robot ready for kinematics and collision checks.
#[derive(Clone, Debug)]
pub struct Robot {
    pub name: String,
    /// The URDF file it came from, for messages (a shipped model's: `<model>.urdf`, built in).
    pub urdf_path: PathBuf,
    /// The shipped model it is (`robot.model`; its files are built into the binary), or `None`
    /// for a URDF read from a file.
    pub model: Option<String>,
    /// Exactly six revolute joints, base to flange.
    pub joints: Vec<RevoluteJoint>,
    /// Pose of `tool0` in the last joint's child link frame (identity if the URDF has no tool0).
    pub flange_to_tool0: Isometry3<f64>,
    /// The lumped arm's collision cylinders on links 1..3, in chain order (`lumped.rs`): per
    /// link of base_link .. link_4 in turn, its cylinders in the URDF's order.
    pub cylinders: Vec<LinkCylinder>,
    /// Link 5's and link 6's collision volumes on the flange, in that order (`lumped.rs`).
    pub flange_parts: Vec<FlangePart>,
    /// Every collision cylinder of the URDF on its own link, base_link to link_6 (what the
    /// preview draws; the lumped ones above enclose them).
    pub collision: Vec<OwnCylinder>,
    pub controller: Controller,
}

/// Why a robot could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum RobotError {
    #[error("cannot read URDF {path}: {source}")]
    ReadUrdf {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("URDF {path} is not valid: {message}")]
    ParseUrdf { path: PathBuf, message: String },
    #[error("URDF {path}: {message}")]
    Model { path: PathBuf, message: String },
    #[error("cannot read controller file {path}: {source}")]
    ReadController {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("controller file {path}: {message}")]
    Controller {
        path: PathBuf,
        message: String,
        /// Where in the controller file (1-based; 0 when not known), and that line.
        line: u64,
        column: u64,
        line_text: Option<String>,
    },
    #[error("unknown robot model '{name}'")]
    UnknownModel { name: String },
}

/// Which limit a pose breaks.
#[derive(Clone, Debug, PartialEq)]
pub enum RangeViolation {
    /// Axis (1-based) outside its range.
    Axis {
        axis: usize,
        value_deg: f64,
        min_deg: f64,
        max_deg: f64,
    },
    /// rax3 - rax2 outside the coupled range.
    Coupled {
        value_deg: f64,
        min_deg: f64,
        max_deg: f64,
    },
}

impl std::fmt::Display for RangeViolation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RangeViolation::Axis {
                axis,
                value_deg,
                min_deg,
                max_deg,
            } => write!(
                f,
                "axis {axis} = {value_deg} deg is outside its range {min_deg} .. {max_deg} deg"
            ),
            RangeViolation::Coupled {
                value_deg,
                min_deg,
                max_deg,
            } => write!(
                f,
                "axis 3 - axis 2 = {value_deg} deg is outside the coupled range {min_deg} .. {max_deg} deg"
            ),
        }
    }
}

impl Robot {
    /// Reads a URDF and its controller file: `controller` when given (it must exist), else the
    /// one beside the URDF (`<stem>.controller.yaml`) if there is one. Without a controller file
    /// the robot is a serial arm with the URDF's limits (`controller.source` is `None`).
    pub fn load(urdf_path: &Path, controller: Option<&Path>) -> Result<Robot, RobotError> {
        let text = crate::input::read_text(urdf_path).map_err(|source| RobotError::ReadUrdf {
            path: urdf_path.to_path_buf(),
            source,
        })?;
        let controller_path = controller
            .map(Path::to_path_buf)
            .unwrap_or_else(|| controller::path_beside(urdf_path));
        let controller_text = match crate::input::read_text(&controller_path) {
            Ok(t) => Some(t),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound && controller.is_none() => None,
            Err(source) => {
                return Err(RobotError::ReadController {
                    path: controller_path,
                    source,
                })
            }
        };
        urdf::robot_from_urdf(
            urdf_path,
            &text,
            controller_text
                .as_deref()
                .map(|t| (controller_path.as_path(), t)),
        )
    }

    /// The shipped model `name` (`robot.model`): its URDF and controller file as built into
    /// the binary ([`models`]), "read" here from their text. Its `urdf_path` and controller
    /// source are the file names (`<name>.urdf`, `<name>.controller.yaml`), for the module
    /// header; no file is read.
    pub fn shipped(name: &str) -> Result<Robot, RobotError> {
        let Some(m) = models::find(name) else {
            return Err(RobotError::UnknownModel {
                name: name.to_string(),
            });
        };
        let urdf = PathBuf::from(format!("{}.urdf", m.name));
        let controller = PathBuf::from(format!("{}.controller.yaml", m.name));
        let mut robot =
            urdf::robot_from_urdf(&urdf, m.urdf, Some((controller.as_path(), m.controller)))?;
        robot.model = Some(m.name.to_string());
        Ok(robot)
    }

    /// The bundled IRB 1400 (URDF and controller file compiled in); for tests and benchmarks.
    /// Its paths are the repository's (`robots/irb1400.urdf`), as a cell naming the files would
    /// give them, and it is not marked a shipped model (a cell's `robot.model: irb1400` is).
    pub fn irb1400() -> Robot {
        let path = Path::new("robots/irb1400.urdf");
        let controller = Path::new("robots/irb1400.controller.yaml");
        let Some(m) = models::find("irb1400") else {
            // The table is a constant of the build; reaching this is a build defect.
            panic!("the IRB 1400 is not among the shipped models");
        };
        match urdf::robot_from_urdf(path, m.urdf, Some((controller, m.controller))) {
            Ok(r) => r,
            // The bundled files are tested; reaching this is a build defect, not user input.
            Err(e) => panic!("bundled IRB 1400 model is invalid: {e}"),
        }
    }

    /// URDF joint values (degrees) for controller values: the one place the coupling applies.
    pub fn urdf_joints_deg(&self, axes_deg: &Axes6) -> [f64; 6] {
        let mut q = *axes_deg;
        if self.controller.coupling == Coupling::Parallelogram {
            q[2] = axes_deg[2] - axes_deg[1];
        }
        q
    }

    /// Checks axes 1..3 against the controller ranges (the coupled axis-3 range included).
    pub fn check_range3(&self, axes_deg: &Axes3) -> Result<(), RangeViolation> {
        for (i, (&v, spec)) in axes_deg.iter().zip(&self.controller.axes).enumerate() {
            if v < spec.min_deg || v > spec.max_deg {
                return Err(RangeViolation::Axis {
                    axis: i + 1,
                    value_deg: v,
                    min_deg: spec.min_deg,
                    max_deg: spec.max_deg,
                });
            }
        }
        if let Some([lo, hi]) = self.controller.coupled_axis3_deg {
            let v = axes_deg[2] - axes_deg[1];
            if v < lo || v > hi {
                return Err(RangeViolation::Coupled {
                    value_deg: v,
                    min_deg: lo,
                    max_deg: hi,
                });
            }
        }
        Ok(())
    }

    /// The part of [`check_range3`](Self::check_range3) that axis 3 changes, for axes 1 and 2
    /// known to be in range: axis 3's own range and the coupled one. The grid's per-node check
    /// (axes 1 and 2 are checked once per column).
    #[inline]
    pub fn axis3_in_range(&self, a2_deg: f64, a3_deg: f64) -> bool {
        !self.axis3_below(a2_deg, a3_deg) && !self.axis3_above(a2_deg, a3_deg)
    }

    /// Whether axis 3 at `a3_deg` lies below its own range or below the coupled one (with axis
    /// 2 at `a2_deg`). Monotone in `a3_deg`: true, then false, as it grows.
    #[inline]
    pub fn axis3_below(&self, a2_deg: f64, a3_deg: f64) -> bool {
        a3_deg < self.controller.axes[2].min_deg
            || matches!(self.controller.coupled_axis3_deg, Some([lo, _]) if a3_deg - a2_deg < lo)
    }

    /// Whether axis 3 at `a3_deg` lies above its own range or above the coupled one. Monotone
    /// in `a3_deg`: false, then true, as it grows.
    #[inline]
    pub fn axis3_above(&self, a2_deg: f64, a3_deg: f64) -> bool {
        a3_deg > self.controller.axes[2].max_deg
            || matches!(self.controller.coupled_axis3_deg, Some([_, hi]) if a3_deg - a2_deg > hi)
    }

    /// Checks axes 4..6 alone against the controller ranges (`robot.wrist`).
    pub fn check_wrist(&self, wrist_deg: &[f64; 3]) -> Result<(), RangeViolation> {
        for (k, &v) in wrist_deg.iter().enumerate() {
            let spec = &self.controller.axes[3 + k];
            if v < spec.min_deg || v > spec.max_deg {
                return Err(RangeViolation::Axis {
                    axis: 4 + k,
                    value_deg: v,
                    min_deg: spec.min_deg,
                    max_deg: spec.max_deg,
                });
            }
        }
        Ok(())
    }

    /// Checks all six axes against the controller ranges.
    pub fn check_range6(&self, axes_deg: &Axes6) -> Result<(), RangeViolation> {
        self.check_range3(&[axes_deg[0], axes_deg[1], axes_deg[2]])?;
        for (i, (&v, spec)) in axes_deg
            .iter()
            .zip(&self.controller.axes)
            .enumerate()
            .skip(3)
        {
            if v < spec.min_deg || v > spec.max_deg {
                return Err(RangeViolation::Axis {
                    axis: i + 1,
                    value_deg: v,
                    min_deg: spec.min_deg,
                    max_deg: spec.max_deg,
                });
            }
        }
        Ok(())
    }

    /// Pose of the child link of each of the first `N` joints in the robot base frame, mm.
    fn chain_poses<const N: usize>(&self, urdf_deg: &[f64]) -> [Isometry3<f64>; N] {
        let mut out = [Isometry3::identity(); N];
        let mut pose = Isometry3::identity();
        for (i, slot) in out.iter_mut().enumerate() {
            let j = &self.joints[i];
            let rot = UnitQuaternion::from_axis_angle(&j.axis, urdf_deg[i].to_radians());
            pose = pose * j.origin * Isometry3::from_parts(Translation3::identity(), rot);
            *slot = pose;
        }
        out
    }

    /// Poses of links 1..6 (children of joints 1..6) in the robot base frame, mm.
    pub fn link_poses(&self, axes_deg: &Axes6) -> [Isometry3<f64>; 6] {
        self.chain_poses::<6>(&self.urdf_joints_deg(axes_deg))
    }

    /// Poses of links 1..3 for controller axes 1..3, mm. Axes 4..6 do not move them.
    pub fn arm_link_poses(&self, axes_deg: &Axes3) -> [Isometry3<f64>; 3] {
        let q = self.urdf_joints_deg(&[axes_deg[0], axes_deg[1], axes_deg[2], 0.0, 0.0, 0.0]);
        self.chain_poses::<3>(&q)
    }

    /// Pose of tool0 in the robot base frame, mm.
    pub fn tool0(&self, axes_deg: &Axes6) -> Isometry3<f64> {
        self.link_poses(axes_deg)[5] * self.flange_to_tool0
    }

    /// Wrist centre (origin of the link moved by joint 5) in the robot base frame, mm.
    pub fn wrist_centre(&self, axes_deg: &Axes6) -> Point3<f64> {
        let p = self.link_poses(axes_deg)[4];
        Point3::from(p.translation.vector)
    }
}

#[cfg(test)]
mod tests {
    /// `axis3_in_range` answers as `check_range3` wherever axes 1 and 2 are in range: values
    /// about every bound, NaN included.
    #[test]
    fn axis3_in_range_agrees_with_check_range3() {
        let robot = super::Robot::irb1400();
        let ax = &robot.controller.axes;
        let near = |lo: f64, hi: f64| {
            [
                lo - 1.0,
                lo - 1e-9,
                lo,
                lo + 1e-9,
                0.5 * (lo + hi),
                hi - 1e-9,
                hi,
                hi + 1e-9,
                hi + 1.0,
            ]
        };
        let mut a3s = near(ax[2].min_deg, ax[2].max_deg).to_vec();
        a3s.push(f64::NAN);
        let (mut inside, mut outside) = (0, 0);
        for a1 in near(ax[0].min_deg, ax[0].max_deg) {
            for a2 in near(ax[1].min_deg, ax[1].max_deg) {
                let own = |v: f64, k: usize| v >= ax[k].min_deg && v <= ax[k].max_deg;
                if !own(a1, 0) || !own(a2, 1) {
                    continue;
                }
                let mut values = a3s.clone();
                if let Some([lo, hi]) = robot.controller.coupled_axis3_deg {
                    values.extend(near(lo + a2, hi + a2));
                }
                for a3 in values {
                    let whole = robot.check_range3(&[a1, a2, a3]).is_ok();
                    assert_eq!(robot.axis3_in_range(a2, a3), whole, "{a1} {a2} {a3}");
                    if whole {
                        inside += 1;
                    } else {
                        outside += 1;
                    }
                }
            }
        }
        assert!(inside > 100 && outside > 100, "{inside} {outside}");
    }

    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    /// Joint values read in ABB RobotStudio and the tool0 position it reported
    /// (`docs/irb1400.md`, forward-kinematics check data).
    const ROBOTSTUDIO: [(Axes6, [f64; 3]); 4] = [
        (
            [30.80, -12.13, 15.33, -40.0, 59.80, -28.0],
            [691.03, 356.96, 921.35],
        ),
        (
            [9.07, 39.20, 46.50, -8.0, 62.87, 44.0],
            [1072.34, 160.46, 420.62],
        ),
        (
            [-95.20, 28.93, 6.17, -20.0, 21.47, 40.0],
            [-123.39, -1238.42, 1004.51],
        ),
        (
            [31.73, -8.40, 61.17, 12.0, -36.80, 24.0],
            [508.35, 301.93, 460.09],
        ),
    ];

    #[test]
    fn tool0_matches_robotstudio_within_0_2_mm() {
        let robot = Robot::irb1400();
        for (axes, expected) in ROBOTSTUDIO {
            let p = robot.tool0(&axes).translation.vector;
            let err = (p - Vector3::from(expected)).norm();
            assert!(
                err < 0.2,
                "{axes:?}: tool0 at {p:?}, RobotStudio {expected:?}, off by {err} mm"
            );
        }
    }

    #[test]
    fn zero_pose_matches_the_data_sheet() {
        let robot = Robot::irb1400();
        let poses = robot.link_poses(&[0.0; 6]);
        let t = |i: usize| poses[i].translation.vector;
        assert!(
            (t(1) - Vector3::new(150.0, 0.0, 475.0)).norm() < 1e-9,
            "axis 2"
        );
        assert!(
            (t(2) - Vector3::new(150.0, 0.0, 1075.0)).norm() < 1e-9,
            "axis 3"
        );
        assert!(
            (t(4) - Vector3::new(870.0, 0.0, 1195.0)).norm() < 1e-9,
            "wrist centre"
        );
        let tool = robot.tool0(&[0.0; 6]);
        assert!((tool.translation.vector - Vector3::new(955.0, 0.0, 1195.0)).norm() < 1e-9);
        let q = tool.rotation.quaternion();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!(
            close(q.w, s, 1e-5)
                && close(q.i, 0.0, 1e-9)
                && close(q.j, s, 1e-5)
                && close(q.k, 0.0, 1e-9),
            "{q:?}"
        );
    }

    /// The wrist-centre closed form of `docs/irb1400.md`, an independent computation.
    fn wrist_closed_form(a: Axes3) -> [f64; 3] {
        let [r1, r2, r3] = a.map(f64::to_radians);
        let r = 150.0 + 600.0 * r2.sin() + 720.0 * r3.cos() + 120.0 * r3.sin();
        let z = 475.0 + 600.0 * r2.cos() - 720.0 * r3.sin() + 120.0 * r3.cos();
        [r * r1.cos(), r * r1.sin(), z]
    }

    #[test]
    fn wrist_centre_matches_the_closed_form() {
        let robot = Robot::irb1400();
        for a in [
            [0.0, 0.0, 0.0],
            [90.0, 0.0, 0.0],
            [30.0, 20.0, 10.0],
            [-25.0, 15.0, 10.0],
            [-160.0, -60.0, 65.0],
            [12.5, 69.0, -40.0],
        ] {
            let w = robot.wrist_centre(&[a[0], a[1], a[2], 17.0, -33.0, 80.0]);
            let e = wrist_closed_form(a);
            assert!(
                (w.coords - Vector3::from(e)).norm() < 1e-9,
                "{a:?}: {w:?} vs {e:?}"
            );
        }
    }

    #[test]
    fn coupling_applies_to_axis_3_only() {
        let robot = Robot::irb1400();
        assert_eq!(
            robot.urdf_joints_deg(&[1.0, 20.0, 10.0, 4.0, 5.0, 6.0]),
            [1.0, 20.0, -10.0, 4.0, 5.0, 6.0]
        );
    }

    #[test]
    fn ranges_include_the_coupled_axis_3_limit() {
        let robot = Robot::irb1400();
        assert!(robot.check_range3(&[170.0, 70.0, 70.0]).is_ok());
        assert!(matches!(
            robot.check_range3(&[170.5, 0.0, 0.0]),
            Err(RangeViolation::Axis { axis: 1, .. })
        ));
        assert!(matches!(
            robot.check_range3(&[0.0, 0.0, -65.5]),
            Err(RangeViolation::Axis { axis: 3, .. })
        ));
        // rax2 = -70, rax3 = +70: both in range, but the arms would fold to 140 deg.
        assert!(matches!(
            robot.check_range3(&[0.0, -70.0, 70.0]),
            Err(RangeViolation::Coupled { .. })
        ));
        assert!(matches!(
            robot.check_range3(&[0.0, 60.0, -10.0]),
            Err(RangeViolation::Coupled { .. })
        ));
    }

    #[test]
    fn cylinders_sit_where_irb1400_md_puts_them() {
        let robot = Robot::irb1400();
        let c: Vec<_> = robot
            .cylinders
            .iter()
            .map(|c| (c.link.as_str(), c.joint_index, c.a, c.b, c.radius_mm))
            .collect();
        assert_eq!(c.len(), 3);
        let near = |p: Point3<f64>, q: [f64; 3]| (p.coords - Vector3::from(q)).norm() < 1e-9;
        assert_eq!((c[0].0, c[0].1, c[0].4), ("link_1", 0, 350.0));
        assert!(near(c[0].2, [0.0, 0.0, 0.0]) && near(c[0].3, [0.0, 0.0, 650.0]));
        assert_eq!((c[1].0, c[1].1, c[1].4), ("link_2", 1, 150.0));
        assert!(near(c[1].2, [0.0, 0.0, 0.0]) && near(c[1].3, [0.0, 0.0, 600.0]));
        assert_eq!((c[2].0, c[2].1, c[2].4), ("link_3", 2, 120.0));
        assert!(
            near(c[2].2, [-300.0, 0.0, 120.0]) && near(c[2].3, [805.0, 0.0, 120.0]),
            "{:?} {:?}",
            c[2].2,
            c[2].3
        );
    }

    #[test]
    fn a_urdf_without_controller_file_is_serial_with_its_own_limits() {
        let text = include_str!("../../robots/irb1400.urdf");
        let robot = urdf::robot_from_urdf(Path::new("x.urdf"), text, None).expect("loads");
        assert_eq!(robot.controller.coupling, Coupling::Serial);
        assert!(close(robot.controller.axes[1].max_deg, 70.0, 1e-3));
        assert!(close(robot.controller.axes[0].speed_deg_s, 110.0, 1e-2));
        assert_eq!(
            robot.urdf_joints_deg(&[0.0, 20.0, 10.0, 0.0, 0.0, 0.0])[2],
            10.0
        );
    }

    #[test]
    fn a_robot_without_collision_cylinders_is_refused() {
        let text = include_str!("../../robots/irb1400.urdf");
        let bare: String = text
            .lines()
            .filter(|l| {
                !l.contains("collision")
                    && !l.contains("<origin xyz=\"0 0 0.325\"")
                    && !l.contains("<geometry><cylinder")
            })
            .collect::<Vec<_>>()
            .join("\n");
        let err = urdf::robot_from_urdf(Path::new("x.urdf"), &bare, None).unwrap_err();
        assert!(
            err.to_string().contains(
                "link 'link_1' (moved by joint 1, 'joint_1') carries no <collision> cylinder"
            ),
            "{err}"
        );
        // One link without: the other two cylinders are not enough (the upper arm would go
        // unchecked).
        let start = text
            .find(r#"<collision name="upper_arm">"#)
            .expect("upper arm");
        let end = start + text[start..].find("</collision>").expect("end") + "</collision>".len();
        let one_bare = format!("{}{}", &text[..start], &text[end..]);
        let err = urdf::robot_from_urdf(Path::new("x.urdf"), &one_bare, None).unwrap_err();
        assert!(
            err.to_string().contains(
                "link 'link_2' (moved by joint 2, 'joint_2') carries no <collision> cylinder"
            ),
            "{err}"
        );
    }

    #[test]
    fn a_urdf_of_another_shape_is_refused_with_its_fault() {
        let text = include_str!("../../robots/irb1400.urdf");
        let refused = |urdf: String, needle: &str| {
            let err = urdf::robot_from_urdf(Path::new("x.urdf"), &urdf, None).unwrap_err();
            assert!(err.to_string().contains(needle), "{needle}: {err}");
        };
        // A limit of 1e300 rad: unrefused, the six-axis IK would list every turn of the axis
        // within it and panic (capacity overflow).
        refused(
            text.replace(
                r#"lower="-2.9670597284" upper="2.9670597284""#,
                r#"lower="-1e300" upper="1e300""#,
            ),
            "joint 'joint_1' <limit>: the range -5.729577951308233e301 .. 5.729577951308233e301 deg reaches beyond -720 .. 720 deg",
        );
        // NaN and huge origins: refused here, not later by an IK message about the arm's shape.
        refused(
            text.replace(
                r#"<origin xyz="0.150 0 0.475""#,
                r#"<origin xyz="NaN 0 0.475""#,
            ),
            "joint 'joint_2': its <origin> must hold finite numbers",
        );
        refused(
            text.replace(
                r#"<origin xyz="0.150 0 0.475""#,
                r#"<origin xyz="1e300 0 0.475""#,
            ),
            "joint 'joint_2': its <origin> xyz 1e300 m is beyond 1000 m",
        );
        refused(
            text.replace(r#"<cylinder radius="0.15""#, r#"<cylinder radius="1e300""#),
            "link 'link_2': cylinder radius and length must be at most 1000 m",
        );
        // A seventh revolute joint between joint 6 and tool0: refused, not silently left out
        // (and tool0 with it).
        refused(
            text.replace(
                r#"<parent link="link_6"/><child link="tool0"/>"#,
                r#"<parent link="link_7"/><child link="tool0"/>"#,
            )
            .replace(
                "</robot>",
                r#"<link name="link_7"/><joint name="joint_7" type="revolute"><parent link="link_6"/><child link="link_7"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="0" velocity="1"/></joint></robot>"#,
            ),
            "joint 'joint_7' is a 7th revolute joint in the chain after joint 6 ('joint_6')",
        );
        // A revolute joint below tool0 (a tool's spindle) belongs to the tool: the arm is the
        // same robot as without it.
        let spindle = text.replace(
            "</robot>",
            r#"<link name="spindle"/><joint name="spindle_joint" type="continuous"><parent link="tool0"/><child link="spindle"/><axis xyz="0 0 1"/></joint></robot>"#,
        );
        // A loop of fixed joints after joint 6 (link_6 -> a -> b -> a, no tool0): a walk that
        // does not refuse it never ends.
        refused(
            text.replace(r#"<link name="tool0"/>"#, r#"<link name="a"/><link name="b"/>"#)
                .replace(
                    r#"<parent link="link_6"/><child link="tool0"/>"#,
                    r#"<parent link="link_6"/><child link="a"/>"#,
                )
                .replace(
                    "</robot>",
                    r#"<joint name="jb" type="fixed"><parent link="a"/><child link="b"/></joint><joint name="jc" type="fixed"><parent link="b"/><child link="a"/></joint></robot>"#,
                ),
            "link 'a' is reached twice along the chain (the joints form a loop)",
        );
        let with_spindle =
            urdf::robot_from_urdf(Path::new("x.urdf"), &spindle, None).expect("a spindle");
        let plain = urdf::robot_from_urdf(Path::new("x.urdf"), text, None).expect("the IRB 1400");
        assert_eq!(format!("{with_spindle:?}"), format!("{plain:?}"));
        // A controller file with an axis range of 1e300 deg: the same bound.
        let ctrl = include_str!("../../robots/irb1400.controller.yaml")
            .replace("{ min: -170, max: 170,", "{ min: -1e300, max: 170,");
        let err = controller::parse(&ctrl).unwrap_err();
        assert!(
            err.message
                .contains("axis 1: the range -1e300 .. 170 deg reaches beyond"),
            "{err}"
        );
        // Pointed at in the controller file: axis 1's line, its `min`.
        let line = ctrl
            .lines()
            .position(|l| l.contains("min: -1e300"))
            .expect("the line") as u64
            + 1;
        assert_eq!(err.line, line, "{err}");
        // Speeds and accelerations of 1e-300: accepted, they would write the header's estimated
        // time in over 300 digits.
        let ctrl = include_str!("../../robots/irb1400.controller.yaml");
        for (from, to, needle) in [
            (
                "speed: 110,",
                "speed: 1e-300,",
                "axis 1: speed 1e-300 deg/s is outside 0.1 .. 10000 deg/s",
            ),
            (
                "acceleration: 515.625",
                "acceleration: 1e-300",
                "axis 1: acceleration 1e-300 deg/s^2 is outside 0.1 .. 1000000 deg/s^2",
            ),
        ] {
            let err = controller::parse(&ctrl.replacen(from, to, 1)).unwrap_err();
            assert!(err.message.contains(needle), "{err}");
        }
        refused(
            text.replacen(r#"velocity="1.9198621772""#, r#"velocity="1e-300""#, 1),
            "joint 'joint_1': <limit velocity> 5.729577951308232e-299 deg/s is outside 0.1 .. 10000 deg/s",
        );
    }

    #[test]
    fn non_cylinder_collision_on_the_arm_is_refused() {
        let text = include_str!("../../robots/irb1400.urdf").replace(
            r#"<cylinder radius="0.15" length="0.6"/>"#,
            r#"<box size="0.1 0.1 0.6"/>"#,
        );
        let err = urdf::robot_from_urdf(Path::new("x.urdf"), &text, None).unwrap_err();
        assert!(
            err.to_string().contains("link_2") && err.to_string().contains("cylinder"),
            "{err}"
        );
    }
}
