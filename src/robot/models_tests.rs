//! The shipped robots held to their published data: an OPW forward kinematics written here from
//! each robot's OPW parameters (Brandstötter, Angerer, Hofbaur 2014; the parameter sets of
//! `docs/robots.md`, as rs-opw-kinematics and opw_kinematics publish them) against the robot's
//! own URDF chain (`Robot::tool0`) at random joints in range; the zero poses, the collision
//! cylinders and the reach the data give; the closed-form wrist IK on each of them. Nothing here
//! uses the robot module's kinematics but the function under test.

use super::ik::{wrap_deg, wrist};
use super::models::MODELS;
use super::{Axes3, Axes6, Robot};
use crate::geometry::testing::Rng;
use nalgebra::{Matrix3, Vector3};

/// OPW parameters, mm (b = 0 for all of them), and whether the controller's axis 3 is the
/// parallelogram's (URDF q3 = axis 3 - axis 2).
struct Opw {
    name: &'static str,
    a1: f64,
    a2: f64,
    c1: f64,
    c2: f64,
    c3: f64,
    c4: f64,
    parallelogram: bool,
}

/// `docs/robots.md` (and `docs/irb1400.md` for the IRB 1400, whose set the six-axis IK's
/// module doc derives).
const OPW: [Opw; 7] = [
    Opw {
        name: "irb1400",
        a1: 150.0,
        a2: -120.0,
        c1: 475.0,
        c2: 600.0,
        c3: 720.0,
        c4: 85.0,
        parallelogram: true,
    },
    Opw {
        name: "irb120_3_58",
        a1: 0.0,
        a2: -70.0,
        c1: 290.0,
        c2: 270.0,
        c3: 302.0,
        c4: 72.0,
        parallelogram: false,
    },
    Opw {
        name: "irb1200_5_90",
        a1: 0.0,
        a2: -42.0,
        c1: 399.1,
        c2: 448.0,
        c3: 451.0,
        c4: 82.0,
        parallelogram: false,
    },
    Opw {
        name: "irb1600_8_145",
        a1: 150.0,
        a2: 0.0,
        c1: 486.5,
        c2: 700.0,
        c3: 600.0,
        c4: 65.0,
        parallelogram: false,
    },
    Opw {
        name: "irb2400_12_155",
        a1: 100.0,
        a2: -135.0,
        c1: 615.0,
        c2: 705.0,
        c3: 755.0,
        c4: 85.0,
        parallelogram: true,
    },
    Opw {
        name: "irb2600_12_165",
        a1: 150.0,
        a2: -115.0,
        c1: 445.0,
        c2: 700.0,
        c3: 795.0,
        c4: 85.0,
        parallelogram: false,
    },
    Opw {
        name: "irb4600_60_205",
        a1: 175.0,
        a2: -175.0,
        c1: 495.0,
        c2: 900.0,
        c3: 960.0,
        c4: 135.0,
        parallelogram: false,
    },
];

impl Opw {
    /// The OPW forward kinematics of controller axes (deg): the end frame's position (mm) and
    /// rotation. The joint offsets are (0, 0, -90, 0, 0, 0) deg, every sign +1, fed with the
    /// URDF's joint values (the parallelogram's q3 = axis 3 - axis 2).
    fn forward(&self, axes: &Axes6) -> (Vector3<f64>, Matrix3<f64>) {
        let mut q = axes.map(f64::to_radians);
        if self.parallelogram {
            q[2] -= q[1];
        }
        q[2] += std::f64::consts::FRAC_PI_2;
        let psi3 = self.a2.atan2(self.c3);
        let k = self.a2.hypot(self.c3);
        let cx1 = self.c2 * q[1].sin() + k * (q[1] + q[2] + psi3).sin() + self.a1;
        let cz1 = self.c2 * q[1].cos() + k * (q[1] + q[2] + psi3).cos();
        let (s1, c1) = q[0].sin_cos();
        let centre = Vector3::new(cx1 * c1, cx1 * s1, cz1 + self.c1);
        let (s2, c2) = q[1].sin_cos();
        let (s3, c3) = q[2].sin_cos();
        let (s4, c4) = q[3].sin_cos();
        let (s5, c5) = q[4].sin_cos();
        let (s6, c6) = q[5].sin_cos();
        #[rustfmt::skip]
        let r_0c = Matrix3::new(
            c1 * c2 * c3 - c1 * s2 * s3, -s1, c1 * c2 * s3 + c1 * s2 * c3,
            s1 * c2 * c3 - s1 * s2 * s3, c1, s1 * c2 * s3 + s1 * s2 * c3,
            -s2 * c3 - c2 * s3, 0.0, -s2 * s3 + c2 * c3,
        );
        #[rustfmt::skip]
        let r_ce = Matrix3::new(
            c4 * c5 * c6 - s4 * s6, -c4 * c5 * s6 - s4 * c6, c4 * s5,
            s4 * c5 * c6 + c4 * s6, -s4 * c5 * s6 + c4 * c6, s4 * s5,
            -s5 * c6, s5 * s6, c5,
        );
        let r = r_0c * r_ce;
        (centre + r * Vector3::z() * self.c4, r)
    }
}

/// Every shipped robot's tool0 (its URDF chain, through its controller file's coupling) agrees
/// with the OPW forward kinematics of its published parameters within 0.01 mm and 1e-6 rad,
/// at 2000 random joint vectors in range each. Fails with any length of a URDF off by 0.01 mm,
/// an axis turned the other way, or the coupling left out.
#[test]
fn every_shipped_robot_agrees_with_its_opw_parameters() {
    let mut rng = Rng(0x0_0b3);
    for opw in &OPW {
        let robot = Robot::shipped(opw.name).expect("shipped");
        let (mut worst_mm, mut worst_rad) = (0.0f64, 0.0f64);
        let mut n = 0;
        while n < 2000 {
            let a: Axes6 = std::array::from_fn(|i| {
                let s = &robot.controller.axes[i];
                rng.range(s.min_deg, s.max_deg)
            });
            if robot.check_range6(&a).is_err() {
                continue;
            }
            n += 1;
            let t = robot.tool0(&a);
            let (p, r) = opw.forward(&a);
            let mm = (t.translation.vector - p).norm();
            // The largest chord between the frames' axes: the angle, for small angles.
            let own = t.rotation.to_rotation_matrix().into_inner();
            let rad = (0..3)
                .map(|c| (own.column(c) - r.column(c)).norm())
                .fold(0.0, f64::max);
            worst_mm = worst_mm.max(mm);
            worst_rad = worst_rad.max(rad);
            assert!(
                mm <= 0.01 && rad <= 1e-6,
                "{}: {a:?}: {mm} mm, {rad} rad",
                opw.name
            );
        }
        eprintln!(
            "{}: OPW against the URDF chain, {n} poses in range: worst {worst_mm:.2e} mm, {worst_rad:.2e} rad",
            opw.name
        );
    }
    assert_eq!(OPW.len(), MODELS.len());
}

/// The zero poses `docs/robots.md` states: wrist centre and tool0 (mm), tool0's quaternion
/// (0.70711, 0, 0.70711, 0), from each URDF.
#[test]
fn the_zero_poses_are_the_data_sheets() {
    for (name, wrist, tool0) in [
        ("irb120_3_58", [302.0, 0.0, 630.0], [374.0, 0.0, 630.0]),
        ("irb1200_5_90", [451.0, 0.0, 889.1], [533.0, 0.0, 889.1]),
        ("irb1600_8_145", [750.0, 0.0, 1186.5], [815.0, 0.0, 1186.5]),
        ("irb2400_12_155", [855.0, 0.0, 1455.0], [940.0, 0.0, 1455.0]),
        (
            "irb2600_12_165",
            [945.0, 0.0, 1260.0],
            [1030.0, 0.0, 1260.0],
        ),
        (
            "irb4600_60_205",
            [1135.0, 0.0, 1570.0],
            [1270.0, 0.0, 1570.0],
        ),
    ] {
        let robot = Robot::shipped(name).expect("shipped");
        let w = robot.wrist_centre(&[0.0; 6]);
        let t = robot.tool0(&[0.0; 6]);
        assert!(
            (w.coords - Vector3::from(wrist)).norm() < 1e-9,
            "{name}: {w:?}"
        );
        assert!(
            (t.translation.vector - Vector3::from(tool0)).norm() < 1e-9,
            "{name}: {t:?}"
        );
        let q = t.rotation.quaternion();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!(
            (q.w - s).abs() < 1e-9
                && q.i.abs() < 1e-9
                && (q.j - s).abs() < 1e-9
                && q.k.abs() < 1e-9,
            "{name}: {q:?}"
        );
        assert_eq!(robot.model.as_deref(), Some(name));
    }
}

/// The names are the contract's, each loads from its built-in text, and nothing else does.
#[test]
fn the_shipped_names_and_an_unknown_one() {
    let names: Vec<&str> = MODELS.iter().map(|m| m.name).collect();
    assert_eq!(
        names,
        [
            "irb1400",
            "irb120_3_58",
            "irb1200_5_90",
            "irb1600_8_145",
            "irb2400_12_155",
            "irb2600_12_165",
            "irb4600_60_205"
        ]
    );
    for m in MODELS {
        let r = Robot::shipped(m.name).expect("loads");
        assert!(
            r.controller.source.is_some(),
            "{}: a controller file",
            m.name
        );
    }
    for bad in ["IRB1400", "irb2600", "", "irb1400 "] {
        assert!(matches!(
            Robot::shipped(bad),
            Err(super::RobotError::UnknownModel { .. })
        ));
    }
}

/// Each URDF's collision cylinders, read back (`Robot::collision`: the URDF's centre, length and
/// rpy turned into axis ends), are the fits of `docs/robots.md`: axis end points in the link's
/// frame and radius, mm (base_link from the mounting plane). Fails with a cylinder turned about
/// the wrong axis, moved, or on another link; the carried volumes are only as good as these.
#[test]
fn the_collision_cylinders_are_the_documented_fits() {
    type Row = (&'static str, [f64; 3], [f64; 3], f64);
    let fits: [(&str, &[Row]); 6] = [
        (
            "irb120_3_58",
            &[
                ("base_link", [-54.0, 0.0, 0.0], [-54.0, 0.0, 167.0], 168.0),
                ("link_1", [0.0, 1.0, 148.0], [0.0, 1.0, 358.0], 118.0),
                ("link_2", [0.0, 0.0, -86.0], [0.0, 0.0, 334.0], 132.0),
                ("link_3", [-97.0, 5.0, 42.0], [162.0, 5.0, 42.0], 111.0),
                ("link_4", [143.0, 0.0, -1.0], [348.0, 0.0, -1.0], 75.0),
                ("link_5", [3.0, -39.0, 0.0], [3.0, 39.0, 0.0], 78.0),
                ("link_6", [-14.0, 0.0, 0.0], [1.0, 0.0, 0.0], 22.0),
            ],
        ),
        (
            "irb1200_5_90",
            &[
                ("base_link", [-33.0, 0.0, 0.0], [-33.0, 0.0, 235.0], 165.0),
                ("link_1", [0.0, -2.0, -181.0], [0.0, -2.0, 82.0], 138.0),
                ("link_2", [-5.0, 0.0, -78.0], [-5.0, 0.0, 522.0], 133.0),
                ("link_3", [-82.0, 0.0, 25.0], [290.0, 0.0, 25.0], 107.0),
                ("link_4", [287.0, -1.0, 8.0], [502.0, -1.0, 8.0], 85.0),
                ("link_5", [13.0, -34.0, 0.0], [13.0, 34.0, 0.0], 70.0),
                ("link_6", [-6.0, 0.0, 0.0], [1.0, 0.0, 0.0], 21.0),
            ],
        ),
        (
            "irb1600_8_145",
            &[
                ("base_link", [-89.0, 0.0, 0.0], [-89.0, 0.0, 172.0], 369.0),
                ("link_1", [34.0, -3.0, 123.0], [34.0, -3.0, 652.0], 301.0),
                ("link_2", [0.0, -194.0, -89.0], [0.0, -194.0, 771.0], 100.0),
                ("link_3", [-176.0, 27.0, -17.0], [315.0, 27.0, -17.0], 160.0),
                ("link_4", [13.0, -3.0, 0.0], [356.0, -3.0, 0.0], 73.0),
                ("link_5", [0.0, -25.0, 0.0], [0.0, 25.0, 0.0], 43.0),
                ("link_6", [-66.0, 0.0, 0.0], [1.0, 0.0, 0.0], 26.0),
            ],
        ),
        (
            "irb2400_12_155",
            &[
                ("base_link", [-95.0, 0.0, 0.0], [-95.0, 0.0, 204.0], 401.0),
                ("link_1", [-11.0, 28.0, 174.0], [-11.0, 28.0, 775.0], 423.0),
                ("link_2", [16.0, 2.0, -87.0], [16.0, 2.0, 737.0], 159.0),
                ("link_2", [-83.0, -94.0, 4.0], [-83.0, -29.0, 4.0], 189.0),
                (
                    "link_2",
                    [-167.0, -44.0, -186.0],
                    [-167.0, -44.0, 890.0],
                    55.0,
                ),
                (
                    "link_2",
                    [-62.0, -44.0, -194.0],
                    [-62.0, -44.0, 907.0],
                    58.0,
                ),
                ("link_3", [-227.0, -23.0, 73.0], [265.0, -23.0, 73.0], 180.0),
                ("link_4", [257.0, 3.0, 0.0], [832.0, 3.0, 0.0], 99.0),
                ("link_5", [0.0, -22.0, 0.0], [0.0, 22.0, 0.0], 62.0),
                ("link_6", [-47.0, 0.0, 0.0], [86.0, 0.0, 0.0], 32.0),
            ],
        ),
        (
            "irb2600_12_165",
            &[
                ("base_link", [-74.0, 3.0, 0.0], [-74.0, 3.0, 231.0], 351.0),
                ("link_1", [54.0, 40.0, -292.0], [54.0, 40.0, 164.0], 280.0),
                ("link_2", [0.0, -172.0, -101.0], [0.0, -172.0, 771.0], 103.0),
                ("link_3", [-140.0, 18.0, 51.0], [306.0, 18.0, 51.0], 206.0),
                ("link_4", [286.0, 3.0, 0.0], [872.0, 3.0, 0.0], 98.0),
                ("link_5", [0.0, -22.0, 0.0], [0.0, 22.0, 0.0], 59.0),
                ("link_6", [-35.0, 0.0, 0.0], [1.0, 0.0, 0.0], 32.0),
            ],
        ),
        (
            "irb4600_60_205",
            &[
                ("base_link", [-75.0, 4.0, 0.0], [-75.0, 4.0, 214.0], 351.0),
                ("link_1", [52.0, 73.0, -343.0], [52.0, 73.0, 212.0], 327.0),
                (
                    "link_2",
                    [0.0, -165.0, -141.0],
                    [0.0, -165.0, 1003.0],
                    149.0,
                ),
                ("link_3", [-182.0, 39.0, 95.0], [354.0, 39.0, 95.0], 269.0),
                ("link_4", [330.0, -8.0, 0.0], [1063.0, -8.0, 0.0], 133.0),
                ("link_5", [0.0, -68.0, 0.0], [0.0, 65.0, 0.0], 81.0),
                ("link_6", [-71.0, 0.0, 0.0], [1.0, 0.0, 0.0], 63.0),
            ],
        ),
    ];
    for (name, rows) in fits {
        let robot = Robot::shipped(name).expect("shipped");
        assert_eq!(robot.collision.len(), rows.len(), "{name}");
        for (own, (link, a, b, r)) in robot.collision.iter().zip(rows) {
            let (a, b) = (Vector3::from(*a), Vector3::from(*b));
            let same = |p: &Vector3<f64>, q: &Vector3<f64>| (p - q).norm() < 1e-9;
            let ends = (own.a.coords, own.b.coords);
            assert!(
                own.link == *link
                    && (same(&ends.0, &a) && same(&ends.1, &b)
                        || same(&ends.0, &b) && same(&ends.1, &a))
                    && (own.radius_mm - r).abs() < 1e-9,
                "{name}: {own:?} is not {link} {a:?} .. {b:?} r {r}"
            );
        }
    }
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The wrist centre by the robot's URDF chain (axes 4..6 at 0).
fn urdf_wrist(robot: &Robot, a: [f64; 3]) -> [f64; 3] {
    let w = robot.wrist_centre(&[a[0], a[1], a[2], 0.0, 0.0, 0.0]);
    [w.x, w.y, w.z]
}

/// Every shipped robot's lengths read from its URDF give its wrist centre by the closed form
/// (held to the URDF chain at random in-range poses), and every solution of a point goes
/// back to it, the pose it came from among them. Fails where a length the closed form
/// needs is read from the wrong joint (the IRB 1600 puts half of d4 on joint 4).
#[test]
fn every_shipped_robot_has_the_closed_form() {
    let mut rng = Rng(0x3_0001);
    for m in MODELS {
        let robot = Robot::shipped(m.name).expect("shipped");
        let g =
            wrist::ArmGeometry::from_robot(&robot).unwrap_or_else(|e| panic!("{}: {e}", m.name));
        let mut n = 0;
        while n < 500 {
            let a: Axes3 = std::array::from_fn(|i| {
                let s = &robot.controller.axes[i];
                rng.range(s.min_deg, s.max_deg)
            });
            if robot.check_range3(&a).is_err() {
                continue;
            }
            let w = wrist::forward(&g, a);
            assert!(dist(w, urdf_wrist(&robot, a)) < 1e-6, "{}: {a:?}", m.name);
            if w[0].hypot(w[1]) < 1.0 {
                continue;
            }
            let sols = wrist::solve(&g, w);
            for s in &sols {
                assert!(
                    dist(urdf_wrist(&robot, s.axes_deg), w) < 0.01,
                    "{}: {s:?}",
                    m.name
                );
            }
            let same = |x: f64, y: f64| wrap_deg(x - y).abs() < 1e-6;
            assert!(
                sols.iter()
                    .any(|s| (0..3).all(|k| same(s.axes_deg[k], a[k]))),
                "{}: {a:?} not among {sols:?}",
                m.name
            );
            n += 1;
        }
    }
}

/// The reach each data sheet names the robot by (docs/robots.md and docs/irb1400.md give the
/// figures from the lengths: a1 + a2 + L where the ranges let the arm stretch out, the
/// IRB 1400's at axis 2 = 70 and the IRB 2400's where its coupled range stops the forearm),
/// and the search holds a sampled maximum of the closed form from above and within 0.01 mm.
#[test]
fn the_reach_of_every_shipped_robot() {
    for (name, want) in [
        ("irb1400", 1443.7),
        ("irb120_3_58", 580.0),
        ("irb1200_5_90", 901.0),
        ("irb1600_8_145", 1450.0),
        ("irb2400_12_155", 1550.0),
        ("irb2600_12_165", 1653.3),
        ("irb4600_60_205", 2050.8),
    ] {
        let robot = Robot::shipped(name).expect("shipped");
        let g = wrist::ArmGeometry::from_robot(&robot).expect("closed form");
        let r = wrist::horizontal_reach_mm(&robot, &g);
        assert!((r - want).abs() < 0.06, "{name}: {r}");
        // Sampled over the whole range (both axes), by the closed form.
        let mut sampled = f64::NEG_INFINITY;
        let ax = &robot.controller.axes;
        for i in 0..=400 {
            for j in 0..=400 {
                let a2 = ax[1].min_deg + (ax[1].max_deg - ax[1].min_deg) * i as f64 / 400.0;
                let a3 = ax[2].min_deg + (ax[2].max_deg - ax[2].min_deg) * j as f64 / 400.0;
                if robot.check_range3(&[0.0, a2, a3]).is_ok() {
                    sampled = sampled.max(wrist::forward(&g, [0.0, a2, a3])[0]);
                }
            }
        }
        assert!(
            sampled <= r + 1e-6 && sampled > r - 0.5,
            "{name}: {sampled} vs {r}"
        );
    }
}
