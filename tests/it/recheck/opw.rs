//! The test suite's own inverse kinematics (`common/opw.rs`) against the library's forward
//! kinematics: FK -> IK -> FK on thousands of random poses of the IRB 1400, and of the six ABB
//! arms the project ships beside it, written here as URDFs from their published kinematics
//! (ROS-Industrial's `abb_experimental` and `abb` support packages, Apache-2.0: joint origins,
//! axes and ranges; the IRB 2400 with its parallelogram), so the extraction of the OPW
//! parameters is tested on robots it was not written for. The parameters read off each URDF are
//! held to the published OPW parameters of those arms (Jmeyer1292/opw_kinematics'
//! `opw_parameters_examples.h`, rs-opw-kinematics' `parameters_robots.rs`, the IRB 1600's
//! `opw_parameters_irb1600_8_145.yaml` in ROS-Industrial's `abb`; the IRB 120 and IRB 1200,
//! which have none published, to the URDF's lengths as the OPW paper defines them). An arm with
//! a lateral offset `b` (none of ABB's has one) checks that term.

use crate::common::library::{irb1400, Robot};
use crate::common::opw::{conf_admits, max_diff, Ik, Opw};
use crate::common::tcp::confdata;
use std::path::Path;

/// One arm as its support package gives it: joint origins (mm, parent frame, no rotation), the
/// tool0 offset on link 6, axis ranges (controller values, deg), the coupled axis-3 range of a
/// parallelogram arm, and its published OPW parameters [a1, a2, b, c1, c2, c3, c4].
pub struct Arm {
    pub name: &'static str,
    pub origins: [[f64; 3]; 6],
    pub tool0: [f64; 3],
    pub ranges: [[f64; 2]; 6],
    pub coupled: Option<[f64; 2]>,
    pub opw: [f64; 7],
}

pub const ARMS: [Arm; 7] = [
    Arm {
        name: "irb120_3_58",
        origins: [
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 290.0],
            [0.0, 0.0, 270.0],
            [0.0, 0.0, 70.0],
            [302.0, 0.0, 0.0],
            [72.0, 0.0, 0.0],
        ],
        tool0: [0.0, 0.0, 0.0],
        ranges: [
            [-165.0, 165.0],
            [-110.0, 110.0],
            [-110.0, 70.0],
            [-160.0, 160.0],
            [-120.0, 120.0],
            [-400.0, 400.0],
        ],
        coupled: None,
        opw: [0.0, -70.0, 0.0, 290.0, 270.0, 302.0, 72.0],
    },
    Arm {
        name: "irb1200_5_90",
        origins: [
            [0.0, 0.0, 399.1],
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 448.0],
            [0.0, 0.0, 42.0],
            [451.0, 0.0, 0.0],
            [82.0, 0.0, 0.0],
        ],
        tool0: [0.0, 0.0, 0.0],
        ranges: [
            [-170.0, 170.0],
            [-100.0, 130.0],
            [-200.0, 70.0],
            [-270.0, 270.0],
            [-130.0, 130.0],
            [-360.0, 360.0],
        ],
        coupled: None,
        opw: [0.0, -42.0, 0.0, 399.1, 448.0, 451.0, 82.0],
    },
    Arm {
        name: "irb1600_8_145",
        origins: [
            [0.0, 0.0, 0.0],
            [150.0, 0.0, 486.5],
            [0.0, 0.0, 700.0],
            [300.0, 0.0, 0.0],
            [300.0, 0.0, 0.0],
            [65.0, 0.0, 0.0],
        ],
        tool0: [0.0, 0.0, 0.0],
        ranges: [
            [-180.0, 180.0],
            [-90.0, 120.0],
            [-245.0, 65.0],
            [-200.0, 200.0],
            [-115.0, 115.0],
            [-400.0, 400.0],
        ],
        coupled: None,
        opw: [150.0, 0.0, 0.0, 486.5, 700.0, 600.0, 65.0],
    },
    Arm {
        name: "irb2400_12_155",
        origins: [
            [0.0, 0.0, 0.0],
            [100.0, 0.0, 615.0],
            [0.0, 0.0, 705.0],
            [0.0, 0.0, 135.0],
            [755.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
        ],
        tool0: [85.0, 0.0, 0.0],
        ranges: [
            [-180.0, 180.0],
            [-100.0, 110.0],
            [-60.0, 65.0],
            [-200.0, 200.0],
            [-120.0, 120.0],
            [-400.0, 400.0],
        ],
        coupled: Some([-60.0, 65.0]),
        opw: [100.0, -135.0, 0.0, 615.0, 705.0, 755.0, 85.0],
    },
    Arm {
        name: "irb2600_12_165",
        origins: [
            [0.0, 0.0, 445.0],
            [150.0, 0.0, 0.0],
            [0.0, 0.0, 700.0],
            [0.0, 0.0, 115.0],
            [795.0, 0.0, 0.0],
            [85.0, 0.0, 0.0],
        ],
        tool0: [0.0, 0.0, 0.0],
        ranges: [
            [-180.0, 180.0],
            [-95.0, 155.0],
            [-180.0, 75.0],
            [-400.0, 400.0],
            [-120.0, 120.0],
            [-400.0, 400.0],
        ],
        coupled: None,
        opw: [150.0, -115.0, 0.0, 445.0, 700.0, 795.0, 85.0],
    },
    Arm {
        name: "irb4600_60_205",
        origins: [
            [0.0, 0.0, 495.0],
            [175.0, 0.0, 0.0],
            [0.0, 0.0, 900.0],
            [0.0, 0.0, 175.0],
            [960.0, 0.0, 0.0],
            [135.0, 0.0, 0.0],
        ],
        tool0: [0.0, 0.0, 0.0],
        ranges: [
            [-180.0, 180.0],
            [-90.0, 150.0],
            [-180.0, 75.0],
            [-400.0, 400.0],
            [-125.0, 120.0],
            [-400.0, 400.0],
        ],
        coupled: None,
        opw: [175.0, -175.0, 0.0, 495.0, 900.0, 960.0, 135.0],
    },
    // Not an ABB arm: the IRB 1400's layout with a lateral offset of 60 mm in the shoulder and
    // 25 mm in the elbow (OPW's b = 85), serial.
    Arm {
        name: "offset_b",
        origins: [
            [0.0, 0.0, 0.0],
            [150.0, 60.0, 475.0],
            [0.0, 25.0, 600.0],
            [0.0, 0.0, 120.0],
            [720.0, 0.0, 0.0],
            [85.0, 0.0, 0.0],
        ],
        tool0: [0.0, 0.0, 0.0],
        ranges: [
            [-170.0, 170.0],
            [-70.0, 70.0],
            [-65.0, 70.0],
            [-150.0, 150.0],
            [-115.0, 115.0],
            [-300.0, 300.0],
        ],
        coupled: None,
        opw: [150.0, -120.0, 85.0, 475.0, 600.0, 720.0, 85.0],
    },
];

/// Writes `arm` as a URDF (a small collision cylinder on links 1..3, which the library's loader
/// asks for) and its controller file into `dir`, and loads it.
pub fn load_arm(dir: &Path, arm: &Arm) -> Robot {
    let axes = ["0 0 1", "0 1 0", "0 1 0", "1 0 0", "0 1 0", "1 0 0"];
    let mut urdf = format!(
        "<?xml version=\"1.0\"?>\n<robot name=\"{}\">\n  <link name=\"base_link\"/>\n",
        arm.name
    );
    for k in 1..=6 {
        let collision = match k {
            1..=3 => "<collision><origin xyz=\"0 0 0.05\" rpy=\"0 0 0\"/><geometry><cylinder radius=\"0.05\" length=\"0.1\"/></geometry></collision>",
            _ => "",
        };
        urdf += &format!("  <link name=\"link_{k}\">{collision}</link>\n");
    }
    urdf += "  <link name=\"tool0\"/>\n";
    let m = |v: f64| v / 1000.0;
    for (k, axis) in axes.iter().enumerate() {
        let parent = match k {
            0 => "base_link".to_string(),
            _ => format!("link_{k}"),
        };
        let o = arm.origins[k];
        let [lo, hi] = arm.ranges[k];
        urdf += &format!(
            "  <joint name=\"joint_{}\" type=\"revolute\"><parent link=\"{parent}\"/><child link=\"link_{}\"/><origin xyz=\"{} {} {}\" rpy=\"0 0 0\"/><axis xyz=\"{}\"/><limit lower=\"{}\" upper=\"{}\" effort=\"0\" velocity=\"3\"/></joint>\n",
            k + 1,
            k + 1,
            m(o[0]),
            m(o[1]),
            m(o[2]),
            axis,
            lo.to_radians(),
            hi.to_radians()
        );
    }
    urdf += &format!(
        "  <joint name=\"joint_6-tool0\" type=\"fixed\"><parent link=\"link_6\"/><child link=\"tool0\"/><origin xyz=\"{} {} {}\" rpy=\"0 1.5707963267948966 0\"/></joint>\n</robot>\n",
        m(arm.tool0[0]),
        m(arm.tool0[1]),
        m(arm.tool0[2])
    );
    let mut controller = format!(
        "coupling: {}\naxes:\n",
        match arm.coupled {
            Some(_) => "parallelogram",
            None => "serial",
        }
    );
    for [lo, hi] in arm.ranges {
        controller += &format!("  - {{ min: {lo}, max: {hi}, speed: 150 }}\n");
    }
    if let Some([lo, hi]) = arm.coupled {
        controller += &format!("coupled_axis3: {{ min: {lo}, max: {hi} }}\n");
    }
    let path = dir.join(format!("{}.urdf", arm.name));
    std::fs::write(&path, urdf).expect("write urdf");
    std::fs::write(
        dir.join(format!("{}.controller.yaml", arm.name)),
        controller,
    )
    .expect("write controller");
    Robot::load(&path, None).unwrap_or_else(|e| panic!("{}: {e}", arm.name))
}

/// Random controller values in `robot`'s ranges (the coupled axis-3 range too).
fn random_axes(rng: &mut fastrand::Rng, robot: &Robot) -> [f64; 6] {
    loop {
        let axes: [f64; 6] = std::array::from_fn(|k| {
            let a = &robot.controller.axes[k];
            a.min_deg + rng.f64() * (a.max_deg - a.min_deg)
        });
        if robot.check_range6(&axes).is_ok() {
            return axes;
        }
    }
}

/// What a round trip over `n` random poses found: the worst FK -> IK -> FK position and angle
/// error over every in-range solution, the worst distance of the original joints from the
/// nearest solution, and how many poses had all 8 branches.
struct Trip {
    worst_mm: f64,
    worst_rad: f64,
    worst_back_deg: f64,
    eight: usize,
}

fn round_trip(robot: &Robot, n: usize, seed: u64) -> Trip {
    let ik = Ik::new(robot).unwrap_or_else(|e| panic!("{}: {e}", robot.name));
    let mut rng = fastrand::Rng::with_seed(seed);
    let mut trip = Trip {
        worst_mm: 0.0,
        worst_rad: 0.0,
        worst_back_deg: 0.0,
        eight: 0,
    };
    for _ in 0..n {
        let axes = random_axes(&mut rng, robot);
        let pose = robot.tool0(&axes);
        if ik.branches(&pose).iter().all(Option::is_some) {
            trip.eight += 1;
        }
        let sols = ik.in_range(&pose);
        for s in &sols {
            let back = robot.tool0(&s.axes);
            trip.worst_mm = trip
                .worst_mm
                .max((back.translation.vector - pose.translation.vector).norm());
            trip.worst_rad = trip.worst_rad.max(back.rotation.angle_to(&pose.rotation));
            assert_eq!(s.conf, confdata(robot, &s.axes));
            assert!(robot.check_range6(&s.axes).is_ok());
        }
        // The original is one of them (away from the wrist singularity, where only axis 4 +
        // axis 6 is defined), and its confdata chooses it.
        if axes[4].abs() > 0.5 {
            let back = sols
                .iter()
                .map(|s| max_diff(&s.axes, &axes))
                .fold(f64::INFINITY, f64::min);
            trip.worst_back_deg = trip.worst_back_deg.max(back);
            let conf = confdata(robot, &axes);
            let chosen = ik.with_conf(&pose, &conf);
            assert!(
                chosen.iter().any(|s| max_diff(&s.axes, &axes) < 1e-6),
                "{}: {axes:?} conf {conf:?}: with_conf gives {chosen:?}",
                robot.name
            );
            // Only solutions of that confdata: every other has another.
            for s in &chosen {
                assert!(conf_admits(&s.axes, s.conf[3], &conf));
            }
        }
    }
    trip
}

#[test]
fn opw_round_trips_the_irb1400_on_thousands_of_random_poses() {
    let robot = irb1400();
    let opw = Opw::of(&robot).expect("the IRB 1400 is an OPW arm");
    // docs/irb1400.md's lengths: shoulder 150 out and 475 up, upper arm 600, forearm 720 with
    // axis 4 120 above axis 3, flange 85 beyond the wrist centre.
    assert_eq!(
        [opw.a1, opw.a2, opw.b, opw.c1, opw.c2, opw.c3, opw.c4],
        [150.0, -120.0, 0.0, 475.0, 600.0, 720.0, 85.0]
    );
    let trip = round_trip(&robot, 5000, 1400);
    eprintln!("irb1400: FK -> IK -> FK {:.1e} mm, {:.1e} rad; the original within {:.1e} deg; {} poses with 8 branches", trip.worst_mm, trip.worst_rad, trip.worst_back_deg, trip.eight);
    assert!(
        trip.worst_mm < 1e-6,
        "FK -> IK -> FK off by {} mm",
        trip.worst_mm
    );
    assert!(trip.worst_rad < 1e-9, "off by {} rad", trip.worst_rad);
    assert!(trip.worst_back_deg < 1e-6, "{} deg", trip.worst_back_deg);
    // Far from every pose has all eight branches (the back branches often do not reach), but
    // many do: the count shows the back and flipped branches are exercised.
    assert!(
        trip.eight > 500,
        "{} of 5000 poses with 8 branches",
        trip.eight
    );
}

#[test]
fn opw_reads_every_abb_arm_off_its_urdf_and_round_trips_it() {
    let dir = tempfile::tempdir().expect("tempdir");
    for arm in &ARMS {
        let robot = load_arm(dir.path(), arm);
        let opw = Opw::of(&robot).unwrap_or_else(|e| panic!("{}: {e}", arm.name));
        let got = [opw.a1, opw.a2, opw.b, opw.c1, opw.c2, opw.c3, opw.c4];
        for (g, w) in got.iter().zip(&arm.opw) {
            assert!(
                (g - w).abs() < 1e-9,
                "{}: {got:?}, published {:?}",
                arm.name,
                arm.opw
            );
        }
        let trip = round_trip(&robot, 2000, 7);
        eprintln!("{}: FK -> IK -> FK {:.1e} mm, {:.1e} rad; the original within {:.1e} deg; {} poses with 8 branches", arm.name, trip.worst_mm, trip.worst_rad, trip.worst_back_deg, trip.eight);
        assert!(
            trip.worst_mm < 1e-6 && trip.worst_rad < 1e-9 && trip.worst_back_deg < 1e-6,
            "{}: {} mm, {} rad, back {} deg",
            arm.name,
            trip.worst_mm,
            trip.worst_rad,
            trip.worst_back_deg
        );
    }
}

#[test]
fn opw_refuses_an_arm_that_is_not_ortho_parallel() {
    let dir = tempfile::tempdir().expect("tempdir");
    // The IRB 1400 with its elbow moved 30 mm forward (joint 3 no longer above joint 2): no OPW
    // arm, and the check must say so rather than solve it wrongly.
    let mut arm = ARMS[6].clone_with_origin(2, [30.0, 0.0, 600.0]);
    arm.name = "elbow_forward";
    let robot = load_arm(dir.path(), &arm);
    let e = Opw::of(&robot).expect_err("not an OPW arm");
    assert!(e.contains("joint 3's origin x"), "{e}");
    // A wrist that is not spherical: joint 6 5 mm off axis 5's centre.
    let mut arm = ARMS[6].clone_with_origin(5, [85.0, 0.0, 5.0]);
    arm.name = "wrist_offset";
    let robot = load_arm(dir.path(), &arm);
    let e = Opw::of(&robot).expect_err("not spherical");
    assert!(e.contains("joint 6's origin z"), "{e}");
}

impl Arm {
    /// The same arm with joint `k`'s origin (0-based) moved to `o`.
    fn clone_with_origin(&self, k: usize, o: [f64; 3]) -> Arm {
        let mut origins = self.origins;
        origins[k] = o;
        Arm {
            name: self.name,
            origins,
            tool0: self.tool0,
            ranges: self.ranges,
            coupled: self.coupled,
            opw: self.opw,
        }
    }
}
