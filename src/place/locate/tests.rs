//! Tests of the location stage: reach regions, R with and without obstacles, the paper's
//! trunk, and the diagnosis of an empty R.

use super::*;
use crate::geometry::Aabb;
use crate::robot::ik::{choose, forward};

fn pts(v: &[(&str, [f64; 3])]) -> Vec<(String, [f64; 3])> {
    v.iter().map(|(n, p)| (n.to_string(), *p)).collect()
}

fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
    Obstacle::new(name, Aabb::new(min.into(), max.into()))
}

fn input<'a>(
    g: &'a ArmGeometry,
    points: &'a [(String, [f64; 3])],
    obstacles: &'a [Obstacle],
) -> LocateInput<'a> {
    LocateInput {
        geom: g,
        points_mm: points,
        obstacles,
        base_z_mm: 0.0,
        base_radius_mm: 350.0,
        base_height_mm: 650.0,
        clearance_mm: 20.0,
        cell_mm: DEFAULT_CELL_MM,
    }
}

#[test]
fn two_far_points_name_each_other() {
    let g = ArmGeometry::irb1400_nominal();
    let p = pts(&[
        ("near", [0.0, 0.0, 800.0]),
        ("A", [0.0, 500.0, 800.0]),
        ("far", [4000.0, 0.0, 800.0]),
    ]);
    let err = locate(&input(&g, &p, &[])).unwrap_err();
    let text = err.to_string();
    assert!(matches!(err, LocateError::Disjoint { .. }), "{text}");
    assert!(text.contains("of near and far do not meet"), "{text}");
    assert!(text.contains("4000.0 mm apart"), "{text}");
}

#[test]
fn one_point_gives_an_annulus() {
    let g = ArmGeometry::irb1400_nominal();
    // Shoulder height: Ri = |600 - L|, Ro = 600 + L; rings (Ri - a1) .. (Ro + a1).
    let l = (120.0f64.powi(2) + 720.0f64.powi(2)).sqrt();
    let (r_in, r_out) = (l - 600.0 - 150.0, 600.0 + l + 150.0);
    assert!(r_in < 0.0); // so the back stance reaches from right under it: a disc
    let p = pts(&[("P", [123.0, -45.0, 475.0])]);
    let loc = locate(&input(&g, &p, &[])).expect("a region");
    assert_eq!(loc.reach[0].inner_mm, 0.0);
    assert!((loc.reach[0].outer_mm - r_out).abs() < 1e-9);
    let exact = std::f64::consts::PI * r_out * r_out;
    assert!(
        (loc.region.area_mm2 - exact).abs() / exact < 0.005,
        "{} vs {exact}",
        loc.region.area_mm2
    );
    // A point 300 mm above the shoulder with the IRB 1400's real interval: a proper ring.
    let robot = Robot::irb1400();
    let g = ArmGeometry::from_robot(&robot).expect("ok");
    let (rmin, rmax) = reach_interval_mm(&g);
    let dz = 300.0;
    let ri = (rmin * rmin - dz * dz).sqrt() - 150.0;
    let ro = (rmax * rmax - dz * dz).sqrt() + 150.0;
    assert!(ri > 0.0);
    let p = pts(&[("Q", [0.0, 0.0, 475.0 + dz])]);
    let loc = locate(&input(&g, &p, &[])).expect("a region");
    assert!((loc.reach[0].inner_mm - ri).abs() < 1e-9 && (loc.reach[0].outer_mm - ro).abs() < 1e-9);
    let exact = std::f64::consts::PI * (ro * ro - ri * ri);
    assert!(
        (loc.region.area_mm2 - exact).abs() / exact < 0.005,
        "{} vs {exact}",
        loc.region.area_mm2
    );
    // Largest margin: midway between the circles.
    let h = loc.best_mm[0].hypot(loc.best_mm[1]);
    assert!((h - 0.5 * (ri + ro)).abs() <= 10.0, "{h}");
    assert!(
        (loc.best_margin_mm - 0.5 * (ro - ri)).abs() <= 10.0,
        "{}",
        loc.best_margin_mm
    );
    assert!(loc.region.contains(loc.best_mm));
    assert!(!loc.region.contains([0.0, 0.0]) && !loc.region.contains([ro + 20.0, 0.0]));
}

#[test]
fn obstacles_remove_area_and_the_base_keeps_clear() {
    let g = ArmGeometry::from_robot(&Robot::irb1400()).expect("ok");
    let p = pts(&[("P", [0.0, 0.0, 775.0]), ("Q", [600.0, 0.0, 775.0])]);
    let free = locate(&input(&g, &p, &[])).expect("free");
    let obs = vec![
        bx("table", [-400.0, -1500.0, 0.0], [1000.0, 300.0, 700.0]),
        bx("shelf", [-2000.0, 500.0, 900.0], [2000.0, 2000.0, 1000.0]), // above the base
    ];
    let loc = locate(&input(&g, &p, &obs)).expect("still room");
    assert!(loc.region.area_mm2 < free.region.area_mm2 - 1e5);
    let blocking: Vec<&str> = loc.blocking.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(blocking, ["table"]);
    let grow = 350.0 + 20.0;
    let d = rect_distance(loc.best_mm, &obs[0].aabb);
    assert!(
        d >= grow,
        "base {:?} only {d} mm from the table",
        loc.best_mm
    );
    // No inside cell is under the grown table; the shelf (z 900 .. 1000) blocks nothing.
    for j in 0..loc.region.ny {
        for i in 0..loc.region.nx {
            if loc.region.inside[j * loc.region.nx + i] {
                assert!(rect_distance(loc.region.cell_centre(i, j), &obs[0].aabb) >= grow);
            }
        }
    }
    // Margin is exact and never more than the distance to the grown table.
    assert!(loc.best_margin_mm <= d - grow + 1e-9);
    assert!(loc.reach.iter().all(|r| r.contains(loc.best_mm)));
}

#[test]
fn an_obstacle_covering_everything_is_named() {
    let g = ArmGeometry::from_robot(&Robot::irb1400()).expect("ok");
    let p = pts(&[("P", [0.0, 0.0, 775.0]), ("Q", [300.0, 0.0, 775.0])]);
    let obs = vec![
        bx("small", [5000.0, 5000.0, 0.0], [5100.0, 5100.0, 100.0]),
        bx("slab", [-3000.0, -3000.0, 0.0], [3000.0, 3000.0, 300.0]),
    ];
    let err = locate(&input(&g, &p, &obs)).unwrap_err();
    let text = err.to_string();
    assert!(
        text.contains("every common position is under obstacle slab"),
        "{text}"
    );
    assert!(text.contains("370.0 mm"), "{text}");
    // A slab whose top is the base plane is the floor: it blocks nothing.
    let floor = vec![bx(
        "floor",
        [-3000.0, -3000.0, -50.0],
        [3000.0, 3000.0, 0.0],
    )];
    assert!(locate(&input(&g, &p, &floor)).is_ok());
}

/// The paper's trunk (section 6 example): the IRB 1400 at (0, -850) turned by 90 deg,
/// the six working points' wrist centres by forward kinematics from the paper's joint values.
#[test]
fn the_paper_trunk_contains_the_papers_base() {
    let robot = Robot::irb1400();
    let g = ArmGeometry::from_robot(&robot).expect("ok");
    let joints = [
        ("A", [90.0, 0.0, 0.0]),
        ("B", [30.0, 20.0, 10.0]),
        ("C", [25.0, 15.0, 10.0]),
        ("D", [-25.0, 15.0, 10.0]),
        ("E", [-30.0, 20.0, 10.0]),
        ("F", [-90.0, 0.0, 0.0]),
    ];
    let base = [0.0, -850.0];
    // Robot +x along cell +y: cell = base + Rz(90) robot.
    let to_cell = |w: [f64; 3]| [base[0] - w[1], base[1] + w[0], w[2]];
    let points: Vec<(String, [f64; 3])> = joints
        .iter()
        .map(|(n, a)| {
            let w = robot.wrist_centre(&[a[0], a[1], a[2], 0.0, 0.0, 0.0]);
            (n.to_string(), to_cell([w.x, w.y, w.z]))
        })
        .collect();
    // A at axis 1 = 90: wrist 870 mm to the robot's left = cell -x.
    assert!((points[0].1[0] + 870.0).abs() < 1e-9 && (points[0].1[1] + 850.0).abs() < 1e-9);
    // Trunk 1800 x 900 x 500 at the origin: floor and four walls.
    let o = bx;
    let obstacles = vec![
        o("trunk floor", [-900.0, -450.0, 0.0], [900.0, 450.0, 100.0]),
        o(
            "trunk front wall",
            [-900.0, -450.0, 0.0],
            [900.0, -400.0, 500.0],
        ),
        o(
            "trunk back wall",
            [-900.0, 400.0, 0.0],
            [900.0, 450.0, 500.0],
        ),
        o(
            "trunk left wall",
            [-900.0, -450.0, 0.0],
            [-850.0, 450.0, 500.0],
        ),
        o(
            "trunk right wall",
            [850.0, -450.0, 0.0],
            [900.0, 450.0, 500.0],
        ),
    ];
    let (radius, height) = base_cylinder_mm(&robot).expect("link_1 cylinder");
    assert_eq!((radius, height), (350.0, 650.0));
    let inp = LocateInput {
        geom: &g,
        points_mm: &points,
        obstacles: &obstacles,
        base_z_mm: 0.0,
        base_radius_mm: radius,
        base_height_mm: height,
        clearance_mm: 20.0,
        cell_mm: DEFAULT_CELL_MM,
    };
    let t = std::time::Instant::now();
    let loc = locate(&inp).expect("the paper found a location");
    let ms = t.elapsed().as_secs_f64() * 1e3;
    eprintln!(
        "trunk: {} x {} cells, area {:.0} mm^2, bbox {:?}, base {:?}, margin {:.1} mm, {ms:.2} ms",
        loc.region.nx,
        loc.region.ny,
        loc.region.area_mm2,
        loc.region.bbox,
        loc.best_mm,
        loc.best_margin_mm
    );
    assert!(loc.region.contains(base), "the paper's base is outside R");
    assert!(loc.reach.iter().all(|r| r.contains(base)));
    assert!(loc.reach.iter().all(|r| r.contains(loc.best_mm)));
    for o in &obstacles {
        assert!(rect_distance(loc.best_mm, &o.aabb) >= radius + 20.0);
    }
    // From the chosen base (same yaw), every point has an in-range solution.
    for (n, p) in &points {
        let rel = [p[0] - loc.best_mm[0], p[1] - loc.best_mm[1], p[2]];
        let w = [rel[1], -rel[0], rel[2]]; // cell -> robot frame (yaw 90)
        let s = choose(&robot, &g, w, None, None, |_| Ok(()));
        assert!(s.is_ok(), "{n} from {:?}: {s:?}", loc.best_mm);
        if let Ok(s) = s {
            let back = forward(&g, s.axes_deg);
            assert!((back[0] - w[0]).abs() < 0.01 && (back[2] - w[2]).abs() < 0.01);
        }
    }
}

#[test]
fn pairwise_meeting_but_no_common_part() {
    let g = ArmGeometry::irb1400_nominal();
    let (_, rmax) = reach_interval_mm(&g);
    let dz = 0.0;
    let ro = (rmax * rmax - dz * dz).sqrt() + 150.0; // disc radius at shoulder height
                                                     // Three discs at the corners of a triangle: every two overlap, all three do not.
    let s = 1.9 * ro; // side: pairs overlap (s < 2 ro), circumradius s / sqrt(3) > ro
    let p = pts(&[
        ("X", [0.0, 0.0, 475.0]),
        ("Y", [s, 0.0, 475.0]),
        ("Z", [0.5 * s, 0.866_025_403_8 * s, 475.0]),
    ]);
    let err = locate(&input(&g, &p, &[])).unwrap_err();
    let text = err.to_string();
    assert!(matches!(err, LocateError::NoCommon { .. }), "{text}");
    assert!(
        text.contains("common region of X, Y has no position") && text.contains("region of Z"),
        "{text}"
    );
}

#[test]
fn bad_input_is_refused() {
    let g = ArmGeometry::irb1400_nominal();
    let p = pts(&[("P", [0.0, 0.0, 800.0])]);
    let mut inp = input(&g, &p, &[]);
    inp.cell_mm = 0.0;
    assert!(matches!(locate(&inp), Err(LocateError::Input(_))));
    let high = pts(&[("sky", [0.0, 0.0, 5000.0])]);
    let err = locate(&input(&g, &high, &[])).unwrap_err().to_string();
    assert!(
        err.contains("point sky") && err.contains("4525.0 mm above"),
        "{err}"
    );
}
