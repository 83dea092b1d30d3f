//! Timing of the collision model on the trunk-like scene of the paper's section 6: the grid
//! build's hot path (`inspect_column`, one column of 136 axis-3 values) and the whole-move check;
//! and the leg's tool look on `cells/torch-trunk.yaml` (`tool_look_sincos`, the arm's sines
//! and cosines from a table as `plan::leg` gives them, against `tool_look`, which takes
//! `sin_cos` of the arm, and the exact `tool_is_free`, which places the flange by
//! `Robot::link_poses`).
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use gen_rapid::cell::Obstacle;
use gen_rapid::collision::CollisionModel;
use gen_rapid::geometry::{Aabb, Point};
use gen_rapid::place::Placement;
use gen_rapid::robot::Robot;
use std::hint::black_box;

fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
    Obstacle::new(name, Aabb::new(Point::from(min), Point::from(max)))
}

/// Robot at (0, -850, 0), yaw 90, before a trunk of 1800 x 900 x 500 mm with a tall box in it.
fn trunk_model() -> CollisionModel {
    let obstacles = vec![
        bx("floor", [-900.0, -450.0, 0.0], [900.0, 450.0, 100.0]),
        bx("near wall", [-900.0, -450.0, 0.0], [900.0, -430.0, 500.0]),
        bx("far wall", [-900.0, 430.0, 0.0], [900.0, 450.0, 500.0]),
        bx("left wall", [-900.0, -450.0, 0.0], [-880.0, 450.0, 500.0]),
        bx("right wall", [880.0, -450.0, 0.0], [900.0, 450.0, 500.0]),
        bx("tower", [-150.0, 0.0, 0.0], [150.0, 300.0, 1000.0]),
    ];
    let placement = Placement {
        base_mm: [0.0, -850.0, 0.0],
        yaw_deg: 90.0,
    };
    CollisionModel::new(&Robot::irb1400(), placement, obstacles, 10.0, None)
}

fn bench(c: &mut Criterion) {
    let model = trunk_model();
    // Axis 3 from -65 to +70 at 1 degree: 136 nodes per column.
    let a3: Vec<f64> = (-65..=70).map(f64::from).collect();
    // Columns spread over axes 1 and 2 (in range), visited in turn.
    let columns: Vec<(f64, f64)> = (-17..=17)
        .flat_map(|i| (-7..=7).map(move |j| (i as f64 * 10.0, j as f64 * 10.0)))
        .collect();
    let mut codes = vec![0u8; a3.len()];
    let check = model.grid_check(1.0);
    let mut column = vec![0u8; check.column_bytes()];
    let mut g = c.benchmark_group("collision");
    g.throughput(Throughput::Elements(a3.len() as u64));
    let mut k = 0usize;
    g.bench_function("inspect_column_136", |b| {
        b.iter(|| {
            k = (k + 1) % columns.len();
            let (a1, a2) = columns[k];
            check.inspect_column(
                black_box(a1),
                black_box(a2),
                black_box(&a3),
                &mut codes,
                &mut column,
            );
            codes[0]
        })
    });
    // The same nodes through is_free, for comparison.
    g.bench_function("is_free_136", |b| {
        b.iter(|| {
            k = (k + 1) % columns.len();
            let (a1, a2) = columns[k];
            a3.iter()
                .filter(|&&v| model.arm_is_free(black_box(&[a1, a2, v])))
                .count()
        })
    });
    g.throughput(Throughput::Elements(1));
    // Paper's A -> F: axis 1 from +90 to -90, the forearm passing over the tower.
    let (from, to) = (
        [90.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [-90.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    );
    eprintln!(
        "long move {from:?} -> {to:?}: safe {}, min clearance >= {:.3} mm",
        model.move_is_safe(&from, &to),
        model
            .min_clearance_along(&from, &to, 0.1)
            .map_or(f64::INFINITY, |c| c.mm)
    );
    g.bench_function("move_is_safe_long", |b| {
        b.iter(|| model.move_is_safe(black_box(&from), black_box(&to)))
    });
    // A long move into the trunk (B -> E of the paper).
    let (from2, to2) = (
        [30.0, 20.0, 10.0, 0.0, 0.0, 0.0],
        [-30.0, 20.0, 10.0, 0.0, 0.0, 0.0],
    );
    eprintln!(
        "move {from2:?} -> {to2:?}: safe {}, min clearance >= {:.3} mm",
        model.move_is_safe(&from2, &to2),
        model
            .min_clearance_along(&from2, &to2, 0.1)
            .map_or(f64::INFINITY, |c| c.mm)
    );
    g.bench_function("move_is_safe_b_to_e", |b| {
        b.iter(|| model.move_is_safe(black_box(&from2), black_box(&to2)))
    });
    g.finish();
}

fn bench_tool(c: &mut Criterion) {
    let job = match gen_rapid::pipeline::load(std::path::Path::new("cells/torch-trunk.yaml")) {
        Ok(job) => job,
        Err(f) => panic!("{}", f.render()),
    };
    let placement = Placement {
        base_mm: [0.0, -850.0, 0.0],
        yaw_deg: 90.0,
    };
    let model = CollisionModel::of_cell(&job.cell, &job.robot, placement);
    // Nodes over the trunk at 1 deg, the wrist as a leg turns it (0.001 deg values).
    let poses: Vec<[f64; 6]> = (-40..=40)
        .step_by(4)
        .flat_map(|a1| (0..=40).step_by(4).map(move |a2| (a1, a2)))
        .flat_map(|(a1, a2)| {
            (-20..=40).step_by(6).map(move |a3| {
                let s = f64::from(a1 + a2 + a3) * 0.001;
                [
                    f64::from(a1),
                    f64::from(a2),
                    f64::from(a3),
                    12.345 + s,
                    30.5 - s,
                    -7.25 + s,
                ]
            })
        })
        .collect();
    let sincos: Vec<[(f64, f64); 3]> = poses
        .iter()
        .map(|p| [0, 1, 2].map(|k| p[k].to_radians().sin_cos()))
        .collect();
    let mut g = c.benchmark_group("tool");
    g.throughput(Throughput::Elements(poses.len() as u64));
    g.bench_function("tool_look_sincos", |b| {
        b.iter(|| {
            poses
                .iter()
                .zip(&sincos)
                .filter(|(p, sc)| model.tool_look_sincos(black_box(p), black_box(sc)).0)
                .count()
        })
    });
    g.bench_function("tool_look", |b| {
        b.iter(|| {
            poses
                .iter()
                .filter(|p| model.tool_look(black_box(p)).0)
                .count()
        })
    });
    g.bench_function("tool_is_free", |b| {
        b.iter(|| {
            poses
                .iter()
                .filter(|p| model.tool_is_free(black_box(p)))
                .count()
        })
    });
    // The flange alone: six quaternions (`link_poses`) against the chain of sines and cosines.
    let robot = &job.robot;
    let chain = gen_rapid::robot::SinCosChain::new(robot, &placement.cell_from_robot());
    g.bench_function("flange_link_poses", |b| {
        b.iter(|| {
            poses
                .iter()
                .map(|p| robot.link_poses(black_box(p))[5].translation.x)
                .sum::<f64>()
        })
    });
    g.bench_function("flange_sincos_chain", |b| {
        b.iter(|| {
            poses
                .iter()
                .zip(&sincos)
                .map(|(p, sc)| {
                    let wrist = [3, 4, 5].map(|k| p[k].to_radians().sin_cos());
                    let arm = robot.urdf_arm_sincos(black_box(sc));
                    let link1 = chain.pose1(arm[0]);
                    chain
                        .pose6_from1(&link1, &[arm[1], arm[2]], &wrist)
                        .apply(&[0.0; 3])[0]
                })
                .sum::<f64>()
        })
    });
    g.finish();
}

criterion_group!(benches, bench, bench_tool);
criterion_main!(benches);
