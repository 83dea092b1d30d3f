//! Tests of following a path: the TCP on the line and the arc by the robot's own forward
//! kinematics (`Robot::tool0`, the URDF chain), the branch kept, the deviation bound against
//! dense sampling, and each refusal located.

use super::testing::*;
use super::*;
use crate::geometry::path::CartesianPath;
use crate::rapid_data::predefined_speed;
use crate::robot::ik::interval::{Dual, Interval};
use nalgebra::{Point3, Vector3};

fn speed(name: &str) -> SpeedData {
    predefined_speed(name).expect("a predefined speeddata")
}

/// Distance of `p` from the segment `a -> b`.
fn from_segment(p: &Point3<f64>, a: &Point3<f64>, b: &Point3<f64>) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
    (p - (a + d * t)).norm()
}

/// The example cells' seams and descents follow; at every sample the forward kinematics of the
/// joints puts the TCP on the line within 0.01 mm (and at the path's point for that progress,
/// turned as the path within 0.0001 deg); the configuration never changes between samples (no
/// branch switch: the same cfx, axes 1, 4, 6 moving little); and the controller's inverse of
/// the end pose with the end's confdata is the end joints. Fails with a branch that switches
/// or samples that leave the line.
#[test]
fn the_example_lines_follow_with_the_tcp_on_the_line() {
    let (robot, ik) = irb();
    for (name, frames, f) in example_followed() {
        let path = f.path();
        let (a, b) = (
            Point3::from(path.start().translation.vector),
            Point3::from(path.end().translation.vector),
        );
        let mut worst = 0.0f64;
        let first = ik.conf(&f.samples()[0].joints_deg);
        for (k, x) in f.samples().iter().enumerate() {
            let at = tcp(&robot, &frames, &x.joints_deg);
            let p = Point3::from(at.translation.vector);
            let off = from_segment(&p, &a, &b);
            let there = (p - path.position_at(x.s)).norm();
            worst = worst.max(off).max(there);
            assert!(
                off < 0.01 && there < 0.01,
                "{name} sample {k}: {off} {there}"
            );
            let turn = at.rotation.angle_to(&path.orientation_at(x.s)).to_degrees();
            assert!(turn < 1e-4, "{name} sample {k}: {turn} deg");
            assert_eq!(ik.conf(&x.joints_deg).cfx, first.cfx, "{name} sample {k}");
            if k > 0 {
                let prev = f.samples()[k - 1].joints_deg;
                let (_, step) = largest_change(&prev, &x.joints_deg);
                assert!(
                    step <= 4.0 * MAX_PROBE_STEP_DEG,
                    "{name} sample {k}: {step}"
                );
            }
        }
        let end = f.end_joints();
        let tool0 = frames.cell_from_robot.inverse() * path.end() * frames.tframe.inverse();
        let chosen = ik
            .choose(&tool0, Some(f.end_conf()), None, |_| Ok::<(), ()>(()))
            .expect("the end's confdata chooses a solution");
        assert!(max_abs_diff(&chosen.axes_deg, &end) < 1e-6, "{name}");
        eprintln!(
            "{name}: {} samples, {:.1} mm, TCP within {worst:.2e} mm of the line, end conf {}",
            f.samples().len(),
            path.length_mm(),
            f.end_conf()
        );
    }
}

/// How far the continuing solution, sampled `per_chord` times along every chord of `f` (each
/// sample continuing from the one before), strays from the straight joint chord, against the
/// chord's bound: panics where it passes the bound on any axis; returns the largest ratio.
fn check_bound_densely(name: &str, ik: &SixAxisIk, f: &FollowedPath, per_chord: usize) -> f64 {
    let path = *f.path();
    let frames = f.frames();
    let from_cell = frames.cell_from_robot.inverse();
    let inv = frames.tframe.inverse();
    let mut worst = 0.0f64;
    for (k, w) in f.samples().windows(2).enumerate() {
        let delta = f.deviations_deg()[k];
        let (s0, s1) = (w[0].s, w[1].s);
        let mut q = w[0].joints_deg;
        for m in 1..=per_chord {
            let t = m as f64 / per_chord as f64;
            let s = s0 + t * (s1 - s0);
            q = ik
                .continuing(&(from_cell * path.pose_at(s) * inv), &q)
                .expect("reachable");
            for i in 0..6 {
                let chord = w[0].joints_deg[i] + t * (w[1].joints_deg[i] - w[0].joints_deg[i]);
                let e = (q[i] - chord).abs();
                assert!(
                    e <= delta[i],
                    "{name} chord {k} axis {}: {e} > {}",
                    i + 1,
                    delta[i]
                );
                worst = worst.max(e / delta[i]);
            }
        }
    }
    worst
}

/// The continuing solution sampled 64 times along every chord stays within the chord's
/// deviation bound of the straight joint chord, on every axis, on the example lines. Fails with
/// a bound that leaves out the bend (`h a b / (a + b)`) or the ends' errors.
#[test]
fn the_deviation_bound_holds_against_dense_sampling() {
    let (_, ik) = irb();
    for (name, _, f) in example_followed() {
        let worst = check_bound_densely(name, &ik, &f, 64);
        eprintln!(
            "{name}: {} chords, the dense deviation reaches {worst:.3} of the bound at most",
            f.deviations_deg().len()
        );
    }
}

/// The process moves of the shipped process cells (torch-trunk's seams, gripper-pick's
/// descents and lifts, arc-seam's arc, and every approach and retract line), followed as the
/// follow stage follows them: the continuing solution sampled 32 times along every chord stays
/// within the chord's bound.
#[test]
fn the_deviation_bound_holds_on_the_shipped_process_cells() {
    let (_, ik) = irb();
    for cell in ["torch-trunk", "gripper-pick", "arc-seam"] {
        let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("cells")
            .join(format!("{cell}.yaml"));
        let job = crate::pipeline::load(&path).unwrap_or_else(|f| panic!("{}", f.render()));
        let placed = crate::pipeline::place(&job).unwrap_or_else(|e| panic!("{e}"));
        let model =
            crate::collision::CollisionModel::of_cell(&job.cell, &job.robot, placed.placement);
        let followed = crate::process::follow(&job.cell, &job.robot, &placed, &model)
            .unwrap_or_else(|e| panic!("{e}"));
        let mut moves = 0;
        for reach in &followed.into {
            if let crate::process::Reach::Process(m) = reach {
                let worst = check_bound_densely(cell, &ik, &m.followed, 32);
                eprintln!(
                    "{cell} move {moves}: {} chords, {:.1} mm, dense deviation {worst:.3} of \
                     the bound at most",
                    m.followed.deviations_deg().len(),
                    m.followed.path().length_mm()
                );
                moves += 1;
            }
        }
        assert!(moves >= 3, "{cell}: {moves} process moves");
    }
}

/// Random lines and arcs (the torch on the trunk's base, random start joints, ends 100 to
/// 300 mm away turned up to 30 deg, arcs through a via off the chord): wherever the path
/// follows, the bound holds against 32 samples per chord; most of them follow.
#[test]
fn the_deviation_bound_holds_on_random_lines_and_arcs() {
    let (robot, ik) = irb();
    let frames = torch_frames();
    let mut rng = crate::geometry::testing::Rng(2729);
    let (mut followed, mut tried) = (0, 0);
    while followed < 16 && tried < 300 {
        tried += 1;
        let Some((start, a, end, dir)) = random_move(&mut rng, &robot, &frames) else {
            continue;
        };
        let path = if followed % 2 == 0 {
            CartesianPath::line(&a, &end).expect("a line")
        } else {
            let mid = (a.translation.vector + end.translation.vector) / 2.0;
            let off = dir.cross(&rng.point(-1.0, 1.0).coords).normalize() * rng.range(20.0, 100.0);
            match CartesianPath::arc(&a, &Point3::from(mid + off), &end) {
                Ok(p) => p,
                Err(_) => continue,
            }
        };
        let Ok(f) = follow(&ik, &frames, &path, &start, None) else {
            continue;
        };
        let worst = check_bound_densely("random", &ik, &f, 32);
        eprintln!(
            "random {}: {} chords, dense deviation {worst:.3} of the bound at most",
            if path.is_arc() { "arc" } else { "line" },
            f.deviations_deg().len()
        );
        followed += 1;
    }
    assert!(followed >= 16, "{followed} of {tried} followed");
}

fn k(x: f64) -> Dual {
    Dual::constant(Interval::point(x))
}

/// A joint path given in closed form on enclosures: its value at a point (the middle of the
/// enclosure there) and its enclosure over a range.
type Curve = fn(Dual) -> [Dual; 6];

fn point_of(q: Curve, s: f64) -> Axes6 {
    q(Dual::variable(Interval::point(s))).map(|x| x.v.mid())
}

fn enclosure_of(q: Curve, s: Interval) -> Option<Enclosure> {
    let d = q(Dual::variable(s));
    d.iter().all(Dual::is_valid).then(|| Enclosure {
        value_deg: d.map(|x| x.v),
        rate_deg: d.map(|x| x.d),
    })
}

fn track_curve(q: Curve, limits: &Limits) -> Result<(Vec<PathSample>, Vec<[f64; 6]>), Stop> {
    let solve = |s: f64, _: &Axes6| Ok(point_of(q, s));
    let enclose = |s: Interval| enclosure_of(q, s);
    let at0 = enclosure_of(q, Interval::point(0.0)).expect("defined at 0");
    let error = at0.value_deg.map(|v| v.width());
    track(
        &point_of(q, 0.0),
        &error,
        &solve,
        &enclose,
        limits,
        &FollowSettings::default(),
    )
}

fn wide() -> Limits {
    Limits {
        axes: [(-1e4, 1e4); 6],
        coupled: None,
    }
}

/// `height / (1 + ((s - at) / width)^2)`: a bump of the joints, narrow for a small width.
fn bump(s: Dual, height: f64, at: f64, width: f64) -> Dual {
    k(height) * (k(1.0) + ((s - k(at)) * k(1.0 / width)).sqr()).recip()
}

/// Axis 1 turning evenly with a bump of 0.004 deg, 0.0002 of the progress wide, at progress
/// 1.5 / 64: between the first and second probes of the first chord tried.
fn bumpy(s: Dual) -> [Dual; 6] {
    [
        k(2.0) * s + bump(s, 0.004, 1.5 / 64.0, 1e-4),
        k(1.0),
        k(0.0),
        k(0.0),
        k(40.0),
        k(0.0),
    ]
}

/// The estimate from probes a follower could take instead of a bound: per axis, the largest
/// deviation at the interior probes plus four times the largest second difference over 8.
fn probe_estimate(probes: &[Axes6; 5]) -> [f64; 6] {
    std::array::from_fn(|i| {
        let (q0, q4) = (probes[0][i], probes[4][i]);
        let e: [f64; 5] =
            std::array::from_fn(|j| probes[j][i] - (q0 + (j as f64 / 4.0) * (q4 - q0)));
        let largest = e[1].abs().max(e[2].abs()).max(e[3].abs());
        let bend = (1..4)
            .map(|j| (e[j - 1] - 2.0 * e[j] + e[j + 1]).abs())
            .fold(0.0, f64::max);
        largest + 4.0 * bend / 8.0
    })
}

/// On joint paths given in closed form (smooth, bending more and more towards the end, and
/// one with a narrow bump of 0.004 deg), tracking keeps every chord's bound above the true
/// deviation, found densely, and under the tolerance asked.
#[test]
fn the_deviation_bound_holds_on_closed_form_joint_paths() {
    let settings = FollowSettings::default();
    let curves: [Curve; 4] = [
        |s| {
            [
                k(40.0) * (k(3.0) * s).sin(),
                k(10.0) * s.sqr(),
                k(-20.0) * s,
                k(5.0),
                k(30.0),
                k(90.0) * s,
            ]
        },
        |s| {
            [
                k(30.0) * (k(8.0) * s.sqr()).cos(),
                k(0.0),
                k(0.0),
                k(60.0) * (k(1.0) - s).sqr() * (k(1.0) - s),
                k(45.0),
                k(0.0),
            ]
        },
        |s| {
            [
                (k(1.02) - s).recip(),
                k(0.0),
                k(10.0) * (k(20.0) * s).sin(),
                k(0.0),
                k(-40.0),
                k(0.0),
            ]
        },
        bumpy,
    ];
    for (c, q) in curves.iter().enumerate() {
        let (samples, bounds) = track_curve(*q, &wide()).expect("smooth");
        assert_eq!(samples.last().map(|x| x.s), Some(1.0));
        for (k, w) in samples.windows(2).enumerate() {
            for m in 0..=400 {
                let t = m as f64 / 400.0;
                let exact = point_of(*q, w[0].s + t * (w[1].s - w[0].s));
                for i in 0..6 {
                    let chord = w[0].joints_deg[i] + t * (w[1].joints_deg[i] - w[0].joints_deg[i]);
                    assert!(
                        (exact[i] - chord).abs() <= bounds[k][i],
                        "curve {c} chord {k} axis {i}"
                    );
                }
            }
            assert!(bounds[k].iter().all(|d| *d <= settings.deviation_tol_deg));
        }
    }
}

/// A case built to break an estimate from samples: a bump of 0.004 deg on axis 1, 0.0002 of
/// the progress wide, between the probes of the first chord tried. The probes see almost
/// nothing of it (their estimate is under a hundredth of the deviation dense sampling finds),
/// so a follower trusting them would accept the chord with a bound the joints pass; the bound
/// from the enclosed rates does not accept it (the rate of the bump is enclosed), and tracking
/// refines around the bump until the bound holds (the test above). Fails if the first chord
/// tried were accepted.
#[test]
fn a_bump_between_probes_breaks_an_estimate_but_not_the_bound() {
    let q: Curve = bumpy;
    let h = 1.0 / 16.0;
    let probes: [Axes6; 5] = std::array::from_fn(|j| point_of(q, h * j as f64 / 4.0));
    let estimate = probe_estimate(&probes)[0];
    let dense = (0..=20_000)
        .map(|m| {
            let s = h * m as f64 / 20_000.0;
            (point_of(q, s)[0] - (probes[0][0] + (s / h) * (probes[4][0] - probes[0][0]))).abs()
        })
        .fold(0.0f64, f64::max);
    assert!(dense > 0.0039, "{dense}");
    assert!(estimate < 0.01 * dense, "{estimate} vs {dense}");
    assert!(estimate < DEVIATION_TOL_DEG);
    // The bound on that chord.
    let over = enclosure_of(q, Interval::new(0.0, h)).expect("defined");
    let end = enclosure_of(q, Interval::point(h)).expect("defined");
    // The rates enclosed over the chord reach thousands of degrees per unit of progress:
    // no bound (the end cannot even be placed within a half turn), or one above the tolerance.
    if let Some((bound, _)) =
        chord_bound((0.0, &probes[0], &[0.0; 6]), (h, &probes[4]), &over, &end)
    {
        assert!(bound[0] >= dense, "{} < {dense}", bound[0]);
        assert!(bound[0] > DEVIATION_TOL_DEG);
    }
    // Tracked, the first chord is shorter than the one tried.
    let (samples, _) = track_curve(q, &wide()).expect("smooth");
    assert!(samples[1].s < h / 2.0, "{}", samples[1].s);
}

/// A joint path that jumps (axis 4 by 30 deg at progress 0.37) is refused there as a jump, the
/// place found to the smallest step. Fails if the jump were taken as a fast but continuous
/// change.
#[test]
fn a_joint_path_that_jumps_is_refused_where_it_jumps() {
    let q: Curve = |s| {
        let jump = if s.v.hi() <= 0.37 {
            k(0.0)
        } else if s.v.lo() > 0.37 {
            k(30.0)
        } else {
            // Not a function of the progress across 0.37: no enclosure.
            Dual::constant(Interval::new(1.0, 0.0))
        };
        [
            k(10.0) * s,
            k(5.0) * s,
            k(0.0),
            jump + k(2.0) * s,
            k(40.0),
            k(0.0),
        ]
    };
    match track_curve(q, &wide()) {
        Err(Stop {
            s,
            why: Trouble::Jump {
                axis, change_deg, ..
            },
        }) => {
            assert!((s - 0.37).abs() < 1e-6, "{s}");
            assert_eq!(axis, 3);
            assert!(change_deg > 29.0, "{change_deg}");
        }
        other => panic!("{other:?}"),
    }
    // The same path without the jump follows.
    let smooth: Curve = |s| [k(10.0) * s, k(5.0) * s, k(0.0), k(2.0) * s, k(40.0), k(0.0)];
    assert!(track_curve(smooth, &wide()).is_ok());
}

/// No tool, the base at the origin: the flange turned from axis 5 = 20 deg to -20 deg along a
/// line passes the wrist singularity; refused there, near the middle, with |axis 5| under
/// 1 deg. Fails without the singularity check (the continuing solution crosses axis 5 = 0).
#[test]
fn a_path_through_the_wrist_singularity_is_refused() {
    let (robot, ik) = irb();
    let frames = bare_frames();
    let start = [10.0, 10.0, 20.0, 0.0, 20.0, 0.0];
    let end = tcp(&robot, &frames, &[10.0, 10.0, 20.0, 0.0, -20.0, 0.0]);
    let path = line_from(&robot, &frames, &start, &end);
    match follow(&ik, &frames, &path, &start, None) {
        Err(FollowError::WristSingularity { at, axis5_deg, .. }) => {
            assert!(axis5_deg.abs() < 1.0, "{axis5_deg}");
            assert!(at.progress_pct > 30.0 && at.progress_pct < 70.0, "{at}");
        }
        other => panic!("{other:?}"),
    }
    // Stopping at 5 deg short of it, the same kind of line follows.
    let end = tcp(&robot, &frames, &[10.0, 10.0, 20.0, 0.0, 5.0, 0.0]);
    let path = line_from(&robot, &frames, &start, &end);
    assert!(follow(&ik, &frames, &path, &start, None).is_ok());
}

/// No tool, the base at the origin: a line into a pose asked with the wrist flipped (the
/// other solution of the end pose, axis 5 negative, in range, named by its confdata): reaching
/// it needs a configuration change the continuing solution cannot make (it would have to pass
/// the wrist singularity), so it is refused, naming the configuration reached. Fails if the
/// end configuration were not checked.
#[test]
fn a_path_that_needs_a_configuration_change_is_refused() {
    let (robot, ik) = irb();
    let frames = bare_frames();
    let start = [0.0, 10.0, 20.0, 60.0, 40.0, 0.0];
    let end_joints = [5.0, 15.0, 25.0, 70.0, 45.0, 10.0];
    let end = tcp(&robot, &frames, &end_joints);
    let path = line_from(&robot, &frames, &start, &end);
    let flipped = ik
        .solve(&end, None)
        .expect("the end solves")
        .into_iter()
        .find(|s| s.axes_deg[4] < 0.0)
        .expect("the end has a flipped wrist in range");
    let f = follow(&ik, &frames, &path, &start, None).expect("follows");
    assert!(max_abs_diff(&f.end_joints(), &end_joints) < 1e-6);
    match follow(&ik, &frames, &path, &start, Some(flipped.conf)) {
        Err(FollowError::EndConf {
            reached,
            wanted,
            joints_deg,
        }) => {
            assert_eq!(wanted, flipped.conf);
            assert_eq!(reached, ik.conf(&end_joints));
            assert!(max_abs_diff(&joints_deg, &end_joints) < 1e-6);
        }
        other => panic!("{other:?}"),
    }
}

/// torch-trunk's seam L1 -> L2 with an end confdata that is not the one the path ends in
/// (cf6 one quadrant on, or the wrist flipped) is refused; with the module's own `L2_rt`
/// confdata `[0, 0, -2, 0]` it follows.
#[test]
fn an_end_confdata_mismatch_is_refused() {
    let (robot, ik) = irb();
    let frames = torch_frames();
    let path = line_from(&robot, &frames, &L1, &seam(330.0, 630.0));
    let own = ConfData::from_array([0, 0, -2, 0]);
    let f = follow(&ik, &frames, &path, &L1, Some(own)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(f.end_conf(), own);
    for wrong in [[0, 0, -1, 0], [0, 2, 0, 1]] {
        match follow(&ik, &frames, &path, &L1, Some(ConfData::from_array(wrong))) {
            Err(FollowError::EndConf { reached, .. }) => assert_eq!(reached, own),
            other => panic!("{wrong:?}: {other:?}"),
        }
    }
}

/// Lines whose continuing solution leaves a range are refused where it does: axis 1 past 170,
/// axis 6 past 300 (its turns counted: the end pose's in-range value -50 is not taken), and
/// the coupled axis-3 range (axis 3 - axis 2 past 70, both axes within their own ranges).
#[test]
fn a_range_exit_is_refused_where_it_happens() {
    let (robot, ik) = irb();
    let frames = bare_frames();
    type Case = (Axes6, Axes6, fn(&RangeViolation) -> bool);
    let cases: [Case; 3] = [
        (
            [160.0, 10.0, 20.0, 0.0, 40.0, 0.0],
            [178.0, 10.0, 20.0, 0.0, 40.0, 0.0],
            |v| matches!(v, RangeViolation::Axis { axis: 1, value_deg, .. } if *value_deg > 170.0),
        ),
        (
            [0.0, 10.0, 20.0, 0.0, 40.0, 290.0],
            [0.0, 10.0, 20.0, 0.0, 40.0, 310.0],
            |v| matches!(v, RangeViolation::Axis { axis: 6, value_deg, .. } if *value_deg > 300.0),
        ),
        (
            [0.0, -20.0, 44.0, 0.0, 40.0, 0.0],
            [0.0, -28.0, 44.0, 0.0, 40.0, 0.0],
            |v| matches!(v, RangeViolation::Coupled { value_deg, .. } if *value_deg > 70.0),
        ),
    ];
    for (start, past, is_it) in cases {
        let path = line_from(&robot, &frames, &start, &tcp(&robot, &frames, &past));
        match follow(&ik, &frames, &path, &start, None) {
            Err(FollowError::Range { at, violation }) => {
                assert!(is_it(&violation), "{start:?}: {violation:?}");
                assert!(
                    at.progress_pct > 20.0 && at.progress_pct < 80.0,
                    "{start:?}: {at}"
                );
            }
            other => panic!("{start:?}: {other:?}"),
        }
    }
}

/// A line running out of the arm's reach is refused where the reach ends: the wrist centre
/// there is as far from axis 2 as the arm reaches. (The IRB 1400's coupled axis-3 range stops
/// the arm short of stretching, so the arm here is its URDF as a serial arm with joint 3
/// allowed to stretch.) Start joints off the path's start are refused before anything.
#[test]
fn out_of_reach_and_a_wrong_start_are_refused() {
    let text = include_str!("../../../../robots/irb1400.urdf");
    let from = r#"<limit lower="-1.1344640138" upper="1.2217304764""#;
    assert!(text.contains(from));
    let text = text.replace(from, r#"<limit lower="-2.0" upper="1.2217304764""#);
    let robot = crate::robot::urdf::robot_from_urdf(std::path::Path::new("x.urdf"), &text, None)
        .expect("a serial arm");
    let ik = SixAxisIk::from_robot(&robot).expect("a spherical wrist");
    let frames = bare_frames();
    // The wrist centre 900 mm from axis 2 at 40 deg of elevation, moved 1000 mm straight away
    // from it: the arm stretches (within its ranges at that elevation) and runs out of reach
    // at 1320 mm. The flange points 30 deg below the horizon.
    let (lu, lf) = ik.link_lengths_mm();
    let shoulder = robot.link_poses(&[0.0; 6])[1].translation.vector;
    let out = Vector3::new(40f64.to_radians().cos(), 0.0, 40f64.to_radians().sin());
    let turn = nalgebra::UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 120f64.to_radians());
    let flange =
        |w: Vector3<f64>| Isometry3::from_parts((w - turn * ik.wrist_in_tool0()).into(), turn);
    let from = flange(shoulder + out * 900.0);
    let far = flange(shoulder + out * 1900.0);
    let start = ik
        .choose(&from, None, None, |_| Ok::<(), ()>(()))
        .expect("in reach")
        .axes_deg;
    let path = CartesianPath::line(&tcp(&robot, &frames, &start), &far).expect("a line");
    match follow(&ik, &frames, &path, &start, None) {
        Err(FollowError::Unreachable { at, .. }) => {
            // There the wrist centre is at the arm's full reach from axis 2.
            let w = path.pose_at(at.progress_pct / 100.0) * Point3::from(ik.wrist_in_tool0());
            let reach = (w.coords - shoulder).norm();
            assert!((reach - (lu + lf)).abs() < 0.5, "{reach} vs {}", lu + lf);
            assert!(
                (at.progress_pct - 100.0 * (lu + lf - 900.0) / 1000.0).abs() < 0.1,
                "{at}"
            );
        }
        other => panic!("{other:?}"),
    }
    let elsewhere = [5.0, 20.0, 10.0, 0.0, 40.0, 0.0];
    assert!(matches!(
        follow(&ik, &frames, &path, &elsewhere, None),
        Err(FollowError::StartMismatch { .. })
    ));
}

/// The axis speeds a seam needs at v50 match finite differences of the continuing solution at
/// each sample (within 5 % of the fastest axis); at v50 every axis keeps within its maximum, at
/// v7000 (the seam in 0.05 s) one does not, and the excess named is the fastest need.
#[test]
fn axis_speeds_follow_the_joint_rates_and_excesses_are_found() {
    let (robot, ik) = irb();
    let frames = torch_frames();
    let path = line_from(&robot, &frames, &L1, &seam(330.0, 630.0));
    let f = follow(&ik, &frames, &path, &L1, None).expect("follows");
    let slow = speed("v50");
    let t = f.paced_seconds(&slow);
    assert!((t - path.length_mm() / 50.0).abs() < 1e-9);
    let speeds = f.axis_speeds_deg_s(&slow);
    let from_cell = frames.cell_from_robot.inverse();
    let inv = frames.tframe.inverse();
    let eps = 1e-5;
    for (k, x) in f.samples().iter().enumerate().skip(1) {
        if x.s + eps > 1.0 {
            continue;
        }
        let at = |s: f64| {
            ik.continuing(&(from_cell * path.pose_at(s) * inv), &x.joints_deg)
                .expect("reachable")
        };
        let (a, b) = (at(x.s - eps), at(x.s + eps));
        let fd: [f64; 6] = std::array::from_fn(|i| (b[i] - a[i]).abs() / (2.0 * eps * t));
        let top = fd.iter().fold(0.0f64, |m, v| m.max(*v));
        for i in 0..6 {
            assert!(
                (speeds[k][i] - fd[i]).abs() <= 0.05 * top + 1e-6,
                "sample {k} axis {}: {} vs {}",
                i + 1,
                speeds[k][i],
                fd[i]
            );
        }
    }
    let axes = &robot.controller.axes;
    assert_eq!(f.speed_excess(&slow, axes), None);
    let fast = speed("v7000");
    let excess = f.speed_excess(&fast, axes).expect("too fast for the axes");
    let fastest = f
        .axis_speeds_deg_s(&fast)
        .iter()
        .flat_map(|v| (0..6).map(move |i| v[i] / axes[i].speed_deg_s))
        .fold(0.0f64, f64::max);
    assert!(
        (excess.needed_deg_s / excess.max_deg_s - fastest).abs() < 1e-12,
        "{excess}"
    );
    assert!(fastest > 1.0);
}

/// An arc through a via on torch-trunk's floor (L1, a via 80 mm to the side, L2's end moved
/// 100 mm over): at every sample the TCP by forward kinematics lies on the circle (within
/// 0.01 mm of the radius, in the plane) at the path's point.
#[test]
fn an_arc_is_followed_on_its_circle() {
    let (robot, ik) = irb();
    let frames = torch_frames();
    let start = tcp(&robot, &frames, &L1);
    let end = seam(430.0, 630.0);
    let via = seam(300.0, 480.0).translation.vector.into();
    let path = CartesianPath::arc(&start, &via, &end).expect("an arc");
    let f = follow(&ik, &frames, &path, &L1, None).unwrap_or_else(|e| panic!("{e}"));
    let (centre, r) = path.circle().expect("a circle");
    let a = Point3::from(start.translation.vector);
    let normal = (via - a)
        .cross(&(end.translation.vector - a.coords))
        .normalize();
    for x in f.samples() {
        let p = Point3::from(tcp(&robot, &frames, &x.joints_deg).translation.vector);
        assert!(((p - centre).norm() - r).abs() < 0.01, "s {}", x.s);
        assert!((p - centre).dot(&normal).abs() < 0.01, "s {}", x.s);
        assert!((p - path.position_at(x.s)).norm() < 0.01, "s {}", x.s);
    }
    eprintln!(
        "arc of {:.1} deg, radius {r:.1} mm: {} samples",
        path.arc_deg().unwrap_or(0.0),
        f.samples().len()
    );
}
