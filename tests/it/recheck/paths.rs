//! The TCP paths of `MoveL` and `MoveC` (`common/paths.rs`) and following them on the IK branch
//! (`common/follow.rs`), on cases worked out by hand: a half circle and an arc of 230 deg with
//! their radius, angle, length and midpoint, the orientation turned evenly, the refusals (an arc
//! over 240 deg, a circle point on the chord, a half turn of the orientation), and a line
//! through the IRB 1400's wrist singularity, which the controller cannot follow.

use crate::common::follow::{follow, WRIST_MIN_DEG};
use crate::common::library::irb1400;
use crate::common::links;
use crate::common::opw::Ik;
use crate::common::paths::TcpPath;
use crate::common::reach::Reach;
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

fn at(p: [f64; 3], turn_z_deg: f64) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), turn_z_deg.to_radians()),
    )
}

#[test]
fn a_half_circle_and_an_arc_of_230_deg_are_what_they_are_by_hand() {
    // Start (1000, 0), circle point (850, 150), end (700, 0): centre (850, 0), radius 150, half
    // a turn through y > 0, 150 pi mm long, at half way on the circle point; the orientation
    // turns 90 deg about z, 45 deg at half way.
    let half = TcpPath::arc(
        &at([1000.0, 0.0, 400.0], 0.0),
        &Point3::new(850.0, 150.0, 400.0),
        &at([700.0, 0.0, 400.0], 90.0),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let (r, angle) = half.radius_and_angle().expect("an arc");
    assert!((r - 150.0).abs() < 1e-9 && (angle - 180.0).abs() < 1e-9);
    assert!((half.length_mm() - 150.0 * std::f64::consts::PI).abs() < 1e-9);
    let mid = half.at(0.5);
    assert!((mid.translation.vector - Vector3::new(850.0, 150.0, 400.0)).norm() < 1e-9);
    assert!((mid.rotation.angle() - 45f64.to_radians()).abs() < 1e-12);
    assert!(
        (half
            .progress_at(&Point3::new(850.0, 150.0, 400.0))
            .expect("on it")
            - 0.5)
            .abs()
            < 1e-12
    );
    // A quarter on: (700, 0) is at 180 deg, (850, -150) at 270 deg of the same circle, which is
    // beyond the half circle.
    assert!(half
        .progress_at(&Point3::new(850.0, -150.0, 400.0))
        .is_none());

    // Centre 0, radius 100 in the plane z = 0: from 0 deg through 90 deg to 230 deg.
    let on = |deg: f64| {
        let t = deg.to_radians();
        [100.0 * t.cos(), 100.0 * t.sin(), 0.0]
    };
    let arc = TcpPath::arc(&at(on(0.0), 0.0), &on(90.0).into(), &at(on(230.0), 0.0))
        .unwrap_or_else(|e| panic!("{e}"));
    let (r, angle) = arc.radius_and_angle().expect("an arc");
    assert!((r - 100.0).abs() < 1e-9 && (angle - 230.0).abs() < 1e-9);
    // Through 90 deg, 230 deg, not the other way round (130 deg).
    let q = arc.at(90.0 / 230.0).translation.vector;
    assert!((q - Vector3::from(on(90.0))).norm() < 1e-9);
}

#[test]
fn the_shapes_the_contract_refuses_are_refused() {
    let on = |deg: f64| {
        let t = deg.to_radians();
        [100.0 * t.cos(), 100.0 * t.sin(), 0.0]
    };
    // 250 deg: over 240.
    let e = TcpPath::arc(&at(on(0.0), 0.0), &on(90.0).into(), &at(on(250.0), 0.0))
        .expect_err("250 deg");
    assert!(e.contains("turns 250.0 deg"), "{e}");
    // A circle point 0.2 mm off the chord.
    let e = TcpPath::arc(
        &at([0.0; 3], 0.0),
        &Point3::new(50.0, 0.2, 0.0),
        &at([100.0, 0.0, 0.0], 0.0),
    )
    .expect_err("on the chord");
    assert!(e.contains("0.200 mm off the chord"), "{e}");
    // The orientation turning 179.95 deg: within 0.1 deg of a half turn.
    let e =
        TcpPath::line(&at([0.0; 3], 0.0), &at([100.0, 0.0, 0.0], 179.95)).expect_err("half turn");
    assert!(e.contains("179.95 deg"), "{e}");
    assert!(TcpPath::line(&at([0.0; 3], 0.0), &at([100.0, 0.0, 0.0], 179.8)).is_ok());
}

#[test]
fn a_line_through_the_wrist_singularity_cannot_be_followed() {
    // At axes 0 the IRB 1400's tool0 points along the base's x axis, level with the forearm,
    // and axis 5 is 0. A line 100 mm straight up through that pose, tool0's orientation kept,
    // needs axis 3 to tilt the forearm one way then the other and axis 5 to undo it (a5 = -a3
    // with a4 = a6 = 0): axis 5 passes 0 half way, so the following must stop before it,
    // within 1 deg of it.
    let robot = irb1400();
    let ik = Ik::new(&robot).unwrap_or_else(|e| panic!("{e}"));
    let home = robot.tool0(&[0.0; 6]);
    let shift = |dz: f64| Translation3::new(0.0, 0.0, dz) * home;
    let line = TcpPath::line(&shift(-50.0), &shift(50.0)).unwrap_or_else(|e| panic!("{e}"));
    let start = ik.nearest(&shift(-50.0), &[0.0; 6]).expect("in reach");
    assert!(
        start[4].abs() > 2.0,
        "the start is clear of the singularity: {start:?}"
    );
    let shapes = links::read(&robot).unwrap_or_else(|e| panic!("{e}"));
    let reach = Reach::new(&robot, &shapes, 0.0);
    let stop = follow(&ik, &|s| line.at(s), start, &reach, 1.0).expect_err("the singularity");
    assert!(stop.why.contains("wrist singularity"), "{}", stop.why);
    assert!(
        stop.axes[4].abs() >= WRIST_MIN_DEG - 0.05 && stop.axes[4].abs() < 2.0,
        "{:?}",
        stop.axes
    );
    assert!(
        stop.s > 0.25 && stop.s < 0.5,
        "it stops before half way: {}",
        stop.s
    );
}
