//! Tests of the clearance proof along a process path (`path.rs`) against dense sampling: the
//! path sampled finely by the continuing inverse kinematics, every part placed by the robot's
//! own forward kinematics and measured by parry3d (links: `tests.rs`'s reference cylinders;
//! tool shapes: `tool_tests.rs`'s parry shapes).

use super::tests::{parry_distance, reference_cylinders};
use super::tool_tests::{parry_box, parry_tool, torch};
use super::*;
use crate::geometry::path::CartesianPath;
use crate::geometry::testing::Rng;
use crate::robot::ik::follow::testing::{
    example_followed, irb, line_from, random_move, seam, torch_frames, L1,
};
use crate::robot::ik::follow::{follow, FollowedPath, TcpFrames};
use crate::robot::ik::six::SixAxisIk;
use nalgebra::{Point3, Vector3};

const TRUNK: Placement = Placement {
    base_mm: [0.0, -850.0, 0.0],
    yaw_deg: 90.0,
};
const GRIPPER_BASE: Placement = Placement {
    base_mm: [0.0, 0.0, 400.0],
    yaw_deg: 0.0,
};

/// An example cell's obstacles and tool (the cell file as written), its model at `placement`
/// with `clearance` (the cell's own when `None`).
fn cell_model(text: &str, placement: Placement, clearance: Option<f64>) -> (Tool, CollisionModel) {
    let cell = crate::cell::parse(std::path::Path::new("cell.yaml"), text)
        .unwrap_or_else(|e| panic!("{e}"));
    let tool = cell.tool.clone().expect("the cell has a tool");
    let model = CollisionModel::new(
        &Robot::irb1400(),
        placement,
        cell.obstacles.clone(),
        clearance.unwrap_or(cell.planner.clearance_mm),
        Some(&tool),
    );
    (tool, model)
}

fn torch_trunk(clearance: Option<f64>) -> (Tool, CollisionModel) {
    cell_model(
        include_str!("../../cells/torch-trunk.yaml"),
        TRUNK,
        clearance,
    )
}

fn gripper_pick() -> (Tool, CollisionModel) {
    cell_model(
        include_str!("../../cells/gripper-pick.yaml"),
        GRIPPER_BASE,
        None,
    )
}

/// The smallest exact distance (parry3d) of any link cylinder or tool shape from any box at
/// `axes`, with the part's and the obstacle's names; link 1 is not measured against the boxes
/// the robot stands on (their top at or below the base).
fn exact_min(model: &CollisionModel, tool: &Tool, axes: &[f64; 6]) -> (f64, String, String) {
    let robot = model.robot();
    let mut best = (f64::INFINITY, String::new(), String::new());
    let arm = [axes[0], axes[1], axes[2]];
    let cylinders = reference_cylinders(robot, model.placement(), &arm);
    for (c, spec) in cylinders.iter().zip(&robot.cylinders) {
        for o in model.obstacles() {
            if spec.joint_index == 0 && o.aabb.max.z <= model.placement().base_mm[2] + 1e-6 {
                continue;
            }
            let d = parry_distance(c, &o.aabb);
            if d < best.0 {
                best = (d, format!("link '{}'", spec.link), o.name.clone());
            }
        }
    }
    for (name, pose, shape) in parry_tool(robot, model.placement(), tool, axes) {
        for o in model.obstacles() {
            let (bp, cuboid) = parry_box(&o.aabb);
            let d = parry3d::query::distance(&pose, shape.as_ref(), &bp, &cuboid)
                .expect("convex shapes")
                .distance;
            if d < best.0 {
                best = (d, format!("tool shape '{name}'"), o.name.clone());
            }
        }
    }
    best
}

/// The path sampled `per_chord` times along every chord by the continuing inverse kinematics:
/// the smallest exact distance, its progress, part and obstacle.
fn dense_min(
    model: &CollisionModel,
    tool: &Tool,
    ik: &SixAxisIk,
    frames: &TcpFrames,
    f: &FollowedPath,
    per_chord: usize,
) -> (f64, f64, String, String) {
    let from_cell = frames.cell_from_robot.inverse();
    let inv = frames.tframe.inverse();
    let mut best = (f64::INFINITY, 0.0, String::new(), String::new());
    for w in f.samples().windows(2) {
        let mut q = w[0].joints_deg;
        for m in 0..=per_chord {
            let s = w[0].s + (m as f64 / per_chord as f64) * (w[1].s - w[0].s);
            if m > 0 {
                q = ik
                    .continuing(&(from_cell * f.path().pose_at(s) * inv), &q)
                    .expect("reachable");
            }
            let (d, part, obstacle) = exact_min(model, tool, &q);
            if d < best.0 {
                best = (d, s, part, obstacle);
            }
        }
    }
    best
}

/// torch-trunk's seams and gripper-pick's descents, each in its own cell (obstacles, tool,
/// clearance 10 mm): proven, and the certified smallest clearance lies at or under the exact
/// distances of the path sampled densely, which keep the clearance. Fails with a certificate
/// that forgot the chords' margin where it matters, or a proof of a path that does not keep it.
#[test]
fn the_example_lines_prove_and_their_clearance_holds_at_dense_samples() {
    let (_, ik) = irb();
    for (name, frames, f) in example_followed() {
        let (tool, model) = if frames == torch_frames() {
            torch_trunk(None)
        } else {
            gripper_pick()
        };
        let proven = model
            .prove_path(&f)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let certified = proven.clearance.expect("obstacles");
        let (dense, s, part, obstacle) = dense_min(&model, &tool, &ik, &frames, &f, 32);
        assert!(dense >= model.clearance_mm(), "{name}: {dense}");
        assert!(
            certified.mm <= dense + 1e-6,
            "{name}: {certified:?} vs {dense}"
        );
        assert!(
            certified.mm >= dense - proven.margin_mm - PATH_CLEARANCE_TOL_MM - 0.5,
            "{name}: {certified:?} vs {dense}"
        );
        eprintln!(
            "{name}: {} chords, margin {:.4} mm; certified {:.3} mm ({} / {}), dense {dense:.3} \
             mm at {:.1} % ({part} / {obstacle})",
            proven.chords,
            proven.margin_mm,
            certified.mm,
            certified.part,
            certified.obstacle,
            100.0 * s
        );
    }
}

/// A path that only grazes between its samples: a pin on the floor under torch-trunk's seam
/// L1 -> L2, so high that the torch passes over it about 8 mm away, the closest approach between two of the
/// follower's samples; asked a clearance between the dense smallest distance and the smallest
/// at the samples (every sample keeps it, the path does not), the path is refused, naming the
/// tool shape and the pin. Asked 1 mm less than the certified clearance, it is proven. Fails
/// with a proof at the samples only, or with the chords proven without the margin's motion.
#[test]
fn a_path_that_grazes_within_the_clearance_between_samples_is_refused() {
    let (_, ik) = irb();
    let (robot, frames) = (Robot::irb1400(), torch_frames());
    let path = line_from(&robot, &frames, &L1, &seam(330.0, 630.0));
    // Followed at a tolerance of 0.05 deg: chords a few millimetres long, so that the torch
    // passing closest between two samples passes measurably farther at both.
    let settings = crate::robot::ik::follow::FollowSettings {
        deviation_tol_deg: 0.05,
        ..Default::default()
    };
    let f = crate::robot::ik::follow::follow_with(&ik, &frames, &path, &L1, None, &settings)
        .expect("follows");
    let (tool, trunk) = torch_trunk(None);
    // A 1 mm pin on the trunk floor under the seam (its side from cell y = `y`), its top at
    // `x`.
    let with_post = |x: f64, y: f64, clearance: f64| {
        let mut boxes = trunk.obstacles().to_vec();
        boxes.push(Obstacle::new(
            "pin",
            Aabb::new(
                Point3::new(-500.5, y, 100.0),
                Point3::new(-499.5, y + 1.0, x),
            ),
        ));
        CollisionModel::new(&robot, TRUNK, boxes, clearance, Some(&tool))
    };
    let post = |x: f64, y: f64| {
        CollisionModel::new(
            &robot,
            TRUNK,
            vec![with_post(x, y, 0.0).obstacles()[trunk.obstacles().len()].clone()],
            0.0,
            Some(&tool),
        )
    };
    // Its top raised until the torch passes over it 8 mm away (the distance changes by at
    // most the change of height, so a few corrections settle it).
    let settle = |mut x: f64, y: f64| {
        for _ in 0..4 {
            let (d, ..) = dense_min(&post(x, y), &tool, &ik, &frames, &f, 64);
            x += d - 8.0;
        }
        x
    };
    let x = settle(110.0, 75.0);
    // Then moved along the seam (cell y, 350 mm over the path) so that the torch passes it
    // closest half way between two samples, and settled again.
    let (_, s, ..) = dense_min(&post(x, 75.0), &tool, &ik, &frames, &f, 64);
    let chord = f
        .samples()
        .windows(2)
        .find(|w| w[0].s <= s && s <= w[1].s)
        .expect("a chord holds it");
    let y = 75.0 + 350.0 * (0.5 * (chord[0].s + chord[1].s) - s);
    let x = settle(x, y);
    let post = |x: f64| post(x, y);
    let with_post = |x: f64, clearance: f64| with_post(x, y, clearance);
    let (dense, s, part, obstacle) = dense_min(&post(x), &tool, &ik, &frames, &f, 64);
    assert!(
        (dense - 8.0).abs() < 0.5 && obstacle == "pin",
        "{dense} {obstacle}"
    );
    assert!(part.starts_with("tool shape"), "{part}");
    let at_samples = f
        .samples()
        .iter()
        .map(|q| exact_min(&post(x), &tool, &q.joints_deg).0)
        .fold(f64::INFINITY, f64::min);
    assert!(
        at_samples > dense + 0.05,
        "the closest approach lies between samples: {at_samples} vs {dense}"
    );
    // Every sample keeps this clearance from the post (and the trunk keeps more), the path
    // between two of them does not.
    let clearance = dense + 0.5 * (at_samples - dense);
    match with_post(x, clearance).prove_path(&f) {
        Err(e) => {
            let Blocked::Contact { part, obstacle, .. } = &e.blocked else {
                panic!("{e}")
            };
            assert!(matches!(part, Part::ToolShape(_)), "{e}");
            assert_eq!(obstacle, "pin", "{e}");
            assert!((e.at.progress_pct / 100.0 - s).abs() < 0.1, "{e} vs {s}");
            eprintln!(
                "grazing at {dense:.3} mm (samples {at_samples:.3} mm), clearance \
                 {clearance:.3} mm: {e}"
            );
        }
        Ok(p) => panic!("proven: {p:?}"),
    }
    let certified = with_post(x, 0.0)
        .prove_path(&f)
        .expect("proven at 0")
        .clearance
        .expect("boxes");
    assert!(certified.mm <= dense + 1e-6, "{certified:?} vs {dense}");
    assert!(with_post(x, certified.mm - 1.0).prove_path(&f).is_ok());
}

/// A post in the torch's way half way along the seam: refused, naming a tool shape and the
/// post, at a progress and TCP position on the seam where the dense sampling finds the torch
/// inside the post. Fails if the collision between samples were missed.
#[test]
fn a_path_that_collides_is_refused_where_it_collides() {
    let (_, ik) = irb();
    let (robot, frames) = (Robot::irb1400(), torch_frames());
    let path = line_from(&robot, &frames, &L1, &seam(330.0, 630.0));
    let f = follow(&ik, &frames, &path, &L1, None).expect("follows");
    let (tool, trunk) = torch_trunk(None);
    let mut boxes = trunk.obstacles().to_vec();
    boxes.push(Obstacle::new(
        "post",
        Aabb::new(
            Point3::new(-520.0, 40.0, 150.0),
            Point3::new(-480.0, 60.0, 260.0),
        ),
    ));
    let model = CollisionModel::new(&robot, TRUNK, boxes, 10.0, Some(&tool));
    let (dense, s, _, obstacle) = dense_min(&model, &tool, &ik, &frames, &f, 32);
    assert_eq!(
        (dense, obstacle.as_str()),
        (0.0, "post"),
        "the post is in the way"
    );
    match model.prove_path(&f) {
        Err(e @ PathBlocked { .. }) => {
            let Blocked::Contact { part, obstacle, .. } = &e.blocked else {
                panic!("{e}")
            };
            assert!(matches!(part, Part::ToolShape(_)), "{e}");
            assert_eq!(obstacle, "post");
            // Refused no later than the dense sampling's first contact, and on the seam.
            assert!(e.at.progress_pct / 100.0 <= s + 1e-9, "{e} vs {s}");
            let p = Point3::from(e.at.tcp_mm);
            assert!((p - path.position_at(e.at.progress_pct / 100.0)).norm() < 1e-6);
            assert!(e.to_string().contains("tool shape"), "{e}");
        }
        other => panic!("{other:?}"),
    }
}

/// Random lines (random start joints, the TCP moved 100 .. 300 mm and turned up to 30 deg)
/// among random boxes near them, with the test torch: where the proof holds, the densely
/// sampled exact distances keep the clearance and are no smaller than the certificate; where it
/// refuses, the dense distances come within the clearance plus the chord's margin and the
/// dense steps' motion (a refusal of a path that keeps the clearance by more is wrong). Both
/// outcomes occur.
#[test]
fn the_path_proof_agrees_with_dense_sampling_on_random_cells() {
    let (robot, ik) = irb();
    let tool = torch();
    let frames = TcpFrames {
        cell_from_robot: TRUNK.cell_from_robot(),
        tframe: tool.tframe.isometry(),
    };
    let mut rng = Rng(2727);
    let (mut proven, mut refused, mut tried) = (0, 0, 0);
    while proven + refused < 24 && tried < 400 {
        tried += 1;
        let Some((start, a, end, _)) = random_move(&mut rng, &robot, &frames) else {
            continue;
        };
        let path = CartesianPath::line(&a, &end).expect("a line");
        let Ok(f) = follow(&ik, &frames, &path, &start, None) else {
            continue;
        };
        let mid = path.position_at(0.5);
        let boxes: Vec<Obstacle> = (0..3)
            .map(|k| {
                let away = rng.point(-1.0, 1.0).coords.normalize() * rng.range(150.0, 500.0);
                let c = mid + away;
                let h = Vector3::new(
                    rng.range(20.0, 100.0),
                    rng.range(20.0, 100.0),
                    rng.range(20.0, 100.0),
                );
                Obstacle::new(format!("box{k}"), Aabb::new(c - h, c + h))
            })
            .collect();
        let model = CollisionModel::new(&robot, TRUNK, boxes, 10.0, Some(&tool));
        let (dense, s, ..) = dense_min(&model, &tool, &ik, &frames, &f, 32);
        let step_motion = f
            .samples()
            .windows(2)
            .map(|w| {
                let d: [f64; 6] =
                    std::array::from_fn(|i| (w[1].joints_deg[i] - w[0].joints_deg[i]).abs());
                model.motion_bound_mm(&d) / 32.0
            })
            .fold(0.0, f64::max);
        match model.prove_path(&f) {
            Ok(p) => {
                assert!(dense >= 10.0 - 1e-6, "proven, yet {dense} mm at {s}");
                let certified = p.clearance.expect("boxes");
                assert!(certified.mm <= dense + 1e-6, "{certified:?} vs {dense}");
                proven += 1;
            }
            Err(e) => {
                assert!(
                    dense <= 10.0 + e.margin_mm + step_motion + 0.05,
                    "refused ({e}) though the dense distances keep {dense} mm"
                );
                refused += 1;
            }
        }
    }
    eprintln!("{tried} random lines: {proven} proven, {refused} refused");
    assert!(
        proven >= 4 && refused >= 4,
        "{proven} proven, {refused} refused"
    );
}

/// The margin is what the proof needs: followed coarsely (chords refined to 0.5 deg only), the
/// seam's true path bends away from its straight joint chords. A pin placed 5 mm beyond the
/// nozzle's tip on the side away from the chord, at the middle of the chord that strays most:
/// every straight chord keeps a clearance the true path does not (so chords proven without
/// the margin would pass), and the proof along the path refuses it. Fails with the margin left
/// out of the chords' proof.
#[test]
fn chords_proven_without_the_margin_would_miss_the_true_path() {
    use crate::robot::ik::follow::{follow_with, FollowSettings};
    let (_, ik) = irb();
    let (robot, frames) = (Robot::irb1400(), torch_frames());
    let path = line_from(&robot, &frames, &L1, &seam(330.0, 630.0));
    let (tool, _) = torch_trunk(None);
    // The nozzle's tip centre in the flange frame (cells/torch-trunk.yaml).
    let tip = Point3::new(77.782, 0.0, 297.782);
    let flange = |q: &[f64; 6]| TRUNK.cell_from_robot() * robot.tool0(q);
    let from_cell = frames.cell_from_robot.inverse();
    let inv = frames.tframe.inverse();
    // The coarsest chords first: the tolerance grows until a chord strays 0.2 mm.
    let mut found = None;
    for tol in [0.5, 2.0, 8.0, 30.0] {
        let coarse = FollowSettings {
            deviation_tol_deg: tol,
            ..FollowSettings::default()
        };
        let f = follow_with(&ik, &frames, &path, &L1, None, &coarse).expect("follows");
        let (mut worst, mut at) = (0.0, (0, Point3::origin(), Vector3::zeros()));
        for (k, w) in f.samples().windows(2).enumerate() {
            let s = 0.5 * (w[0].s + w[1].s);
            let truth = ik
                .continuing(&(from_cell * path.pose_at(s) * inv), &w[0].joints_deg)
                .expect("reachable");
            let chord: [f64; 6] =
                std::array::from_fn(|i| 0.5 * (w[0].joints_deg[i] + w[1].joints_deg[i]));
            let (p, c) = (flange(&truth) * tip, flange(&chord) * tip);
            if (c - p).norm() > worst {
                worst = (c - p).norm();
                at = (k, p, (c - p) / (c - p).norm());
            }
        }
        eprintln!(
            "tolerance {tol} deg: {} chords stray {worst:.3} mm",
            f.samples().len() - 1
        );
        if worst > 0.2 {
            found = Some((f, worst, at));
            break;
        }
    }
    let (f, worst, (k, p, away)) = found.expect("some tolerance gives chords straying 0.2 mm");
    let pin_at = p - away * (14.0 + 5.0);
    let pin = Obstacle::new(
        "pin",
        Aabb::new(pin_at - Vector3::repeat(0.5), pin_at + Vector3::repeat(0.5)),
    );
    let model = |c: f64| CollisionModel::new(&robot, TRUNK, vec![pin.clone()], c, Some(&tool));
    let (truth, ..) = dense_min(&model(0.0), &tool, &ik, &frames, &f, 256);
    let along_chords = f
        .samples()
        .windows(2)
        .filter_map(|w| model(0.0).min_clearance_along(&w[0].joints_deg, &w[1].joints_deg, 1e-6))
        .map(|c| c.mm)
        .fold(f64::INFINITY, f64::min);
    assert!(
        along_chords > truth + 0.05,
        "chord {k}: {along_chords} vs {truth}"
    );
    let c = 0.5 * (truth + along_chords);
    let m = model(c);
    assert!(f
        .samples()
        .windows(2)
        .all(|w| m.move_keeps(&w[0].joints_deg, &w[1].joints_deg, c)));
    let e = m
        .prove_path(&f)
        .expect_err("the true path comes within the clearance");
    eprintln!(
        "chords stray {worst:.2} mm; the pin: {truth:.3} mm from the path, {along_chords:.3} \
         from the chords; at {c:.3} mm: {e}"
    );
}
