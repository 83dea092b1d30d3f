//! The dense check's own reading of the robot (`common/links.rs`, `common/reach.rs`): the URDF's
//! collision shapes read here agree with the library's own cylinders on every shipped robot, a
//! shape the library ignores (one on `tool0`, below a fixed joint) is measured all the same, and
//! the motion bound the sampling stands on holds for every shape and the tool.

use crate::common::dense::Scene;
use crate::common::library::{irb1400, load_cell, LinkFrame, Robot};
use crate::common::links;
use crate::common::reach::Reach;
use crate::common::{file_names, root, temp_cell};
use nalgebra::{Point3, Vector3};
use std::path::{Path, PathBuf};

/// The bundled IRB 1400's URDF with a ball of radius 20 mm on `tool0`, 300 mm along its z axis
/// (a pen the robot file itself carries), written into `dir`.
fn with_pen(dir: &Path) -> (PathBuf, Robot) {
    let text = std::fs::read_to_string(root().join("robots/irb1400.urdf")).expect("urdf");
    let pen = "<link name=\"tool0\">\n    <collision name=\"pen\">\n      <origin xyz=\"0 0 0.3\" rpy=\"0 0 0\"/>\n      <geometry><sphere radius=\"0.02\"/></geometry>\n    </collision>\n  </link>";
    assert!(text.contains("<link name=\"tool0\"/>"));
    let path = dir.join("pen.urdf");
    std::fs::write(&path, text.replace("<link name=\"tool0\"/>", pen)).expect("write urdf");
    let controller = root().join("robots/irb1400.controller.yaml");
    let robot = Robot::load(&path, Some(&controller)).unwrap_or_else(|e| panic!("{e}"));
    (path, robot)
}

#[test]
fn the_urdf_read_here_gives_the_librarys_cylinders_on_every_shipped_robot() {
    let names: Vec<String> = file_names(&root().join("robots"))
        .into_iter()
        .filter_map(|f| f.strip_suffix(".urdf").map(str::to_string))
        .collect();
    assert!(names.len() >= 7, "{names:?}");
    for name in &names {
        let robot = Robot::shipped(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        let shapes = links::read(&robot).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(shapes.len(), robot.collision.len(), "{name}");
        for (s, c) in shapes.iter().zip(&robot.collision) {
            let frame = match c.frame {
                LinkFrame::Base => None,
                LinkFrame::Child(k) => Some(k),
            };
            assert_eq!(
                (s.link.as_str(), s.carrier),
                (c.link.as_str(), frame),
                "{name}"
            );
            // A parry cylinder lies along its local y axis: its bounding box's half extents are
            // (radius, half length, radius).
            let h = s.shape.compute_local_aabb().half_extents();
            let ends = [-h.y, h.y].map(|y| s.in_frame * Point3::new(0.0, y, 0.0));
            let same = |p: &Point3<f64>, q: &Point3<f64>| (p - q).norm() < 1e-9;
            assert!(
                (same(&ends[0], &c.a) && same(&ends[1], &c.b))
                    || (same(&ends[0], &c.b) && same(&ends[1], &c.a)),
                "{name} {}: ends {ends:?}, the library's {:?} {:?}",
                s.link,
                c.a,
                c.b
            );
            assert!((h.x - c.radius_mm).abs() < 1e-9 && (h.z - c.radius_mm).abs() < 1e-9);
        }
    }
}

#[test]
fn a_shape_the_library_ignores_is_measured() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (urdf, pen_robot) = with_pen(dir.path());
    let shapes = links::read(&pen_robot).unwrap_or_else(|e| panic!("{e}"));
    let pen = shapes
        .iter()
        .find(|s| s.link == "tool0")
        .expect("the pen is read");
    assert_eq!(
        pen.carrier,
        Some(5),
        "tool0 hangs below joint 6 by a fixed joint"
    );
    assert_eq!(
        pen_robot.cylinders.len(),
        3,
        "the library keeps links 1..3 only"
    );

    // The pen's ball at axes 0 (tool0 along the base's x axis, level with the forearm): its
    // centre by forward kinematics; a box 45 mm under the centre, 100 mm wide: 45 - 20 = 25 mm
    // from the ball. The forearm cylinder ends 300 mm behind the ball (its end at 805 mm along
    // the forearm, the ball at 720 + 85 + 300), so nothing else comes near.
    let axes = [0.0; 6];
    let c = pen_robot.tool0(&axes) * Point3::new(0.0, 0.0, 300.0);
    let cell_text = format!(
        "module: Pen\nrobot: {{ urdf: {}, base: [0, 0, 0] }}\nobstacles:\n  - {{ name: block, box: {{ min: [{}, {}, {}], max: [{}, {}, {}] }} }}\npoints:\n  - {{ name: P, joints: [0, 0, 0] }}\n  - {{ name: Q, joints: [10, 0, 0] }}\nplanner: {{ clearance: 10 }}\n",
        urdf.display(),
        c.x - 50.0,
        c.y - 50.0,
        c.z - 145.0,
        c.x + 50.0,
        c.y + 50.0,
        c.z - 45.0
    );
    let cell = load_cell(&temp_cell(dir.path(), "pen.yaml", &cell_text));
    let near = Scene::new(&pen_robot, [0.0; 3], 0.0, &cell).nearest(axes);
    assert_eq!(
        (near.link.as_str(), near.obstacle.as_str()),
        ("tool0", "block")
    );
    assert!((near.mm - 25.0).abs() < 1e-6, "{near:?}");
    // Without the pen the same box is far from the arm.
    let bare = irb1400();
    let far = Scene::new(&bare, [0.0; 3], 0.0, &cell).nearest(axes);
    assert!(far.mm > 200.0, "{far:?}");
}

#[test]
fn no_point_of_any_shape_or_the_tool_moves_more_than_the_bound() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (_, pen) = with_pen(dir.path());
    bound_holds(&pen);
    for f in file_names(&root().join("robots")) {
        if let Some(name) = f.strip_suffix(".urdf") {
            bound_holds(&Robot::shipped(name).unwrap_or_else(|e| panic!("{name}: {e}")));
        }
    }
}

/// Random joint moves of `robot` with a tool reaching 350 mm from tool0: no point of a shape or
/// the tool moves farther than the bound, and some come within half of it.
fn bound_holds(robot: &Robot) {
    let shapes = links::read(robot).unwrap_or_else(|e| panic!("{e}"));
    let tool_mm = 350.0;
    let reach = Reach::new(robot, &shapes, tool_mm);
    // Points on each shape's bounding sphere, in its link frame, and on the tool's.
    let dirs = [
        Vector3::x(),
        -Vector3::x(),
        Vector3::y(),
        -Vector3::y(),
        Vector3::z(),
        -Vector3::z(),
    ];
    let mut points: Vec<(Option<usize>, Point3<f64>)> = Vec::new();
    for s in &shapes {
        let b = s.shape.compute_local_bounding_sphere();
        let c = b.center();
        for d in &dirs {
            points.push((
                s.carrier,
                s.in_frame * (Point3::new(c.x, c.y, c.z) + b.radius() * d),
            ));
        }
    }
    let tool: Vec<Point3<f64>> = dirs.iter().map(|d| Point3::from(tool_mm * d)).collect();
    let mut rng = fastrand::Rng::with_seed(31);
    let mut tightest = 0.0f64;
    for _ in 0..2000 {
        let a: [f64; 6] = std::array::from_fn(|k| {
            let s = &robot.controller.axes[k];
            s.min_deg + rng.f64() * (s.max_deg - s.min_deg)
        });
        let b: [f64; 6] = std::array::from_fn(|k| a[k] + 20.0 * (rng.f64() - 0.5));
        let bound = reach.motion_mm(robot, &a, &b);
        let (la, lb) = (robot.link_poses(&a), robot.link_poses(&b));
        let mut moved: Vec<f64> = points
            .iter()
            .map(|(k, p)| match k {
                Some(k) => (la[*k] * p - lb[*k] * p).norm(),
                None => 0.0,
            })
            .collect();
        moved.extend(
            tool.iter()
                .map(|p| (robot.tool0(&a) * p - robot.tool0(&b) * p).norm()),
        );
        for m in moved {
            assert!(
                m <= bound + 1e-9,
                "{}: a point moves {m} mm from {a:?} to {b:?}, the bound says {bound}",
                robot.name
            );
            tightest = tightest.max(m / bound);
        }
    }
    // The bound is a bound, not a guess: some point comes within a few tens of percent of it.
    assert!(
        tightest > 0.5,
        "{}: the bound is loose everywhere: at most {tightest} of it",
        robot.name
    );
}
