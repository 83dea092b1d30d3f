//! The wave expansion alone on `cells/trunk.yaml` at 1 degree (the grid inspected once, outside
//! the timing): leg 1's optimistic 26-neighbour wave both ways (the extensile search's two
//! waves whole, numbered row by row), the two numbered together from both ends keeping only
//! the shortest paths' nodes (what the extensile search numbers now, `wave::expand_both`), and
//! its 6-neighbour wave (the depth-first search's, node by node).
//! Run: `cargo bench --bench wave`. Figures are recorded in benches/README.md.

use criterion::{criterion_group, criterion_main, Criterion};
use gen_rapid::pipeline;
use gen_rapid::plan::leg::{LegGraph, ToolMemo, WristSchedule};
use gen_rapid::plan::wave::{self, Connectivity};
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

fn waves(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("cells/trunk.yaml");
    let job = match pipeline::load(&path) {
        Ok(job) => job,
        Err(f) => panic!("{}", f.render()),
    };
    let placed = pipeline::place(&job).expect("place");
    let inspected = pipeline::inspect(&job, &placed, 1.0);
    let cs = &inspected.cspace;
    let node = |k: usize| {
        cs.grid
            .node_at(&placed.points[k].arm_deg())
            .expect("the trunk's points lie on the 1 deg grid")
    };
    let (a, b) = (node(0), node(1));
    let check = inspected.model.grid_check(cs.grid.step_deg);
    let schedule = WristSchedule::new(&placed.points[0].joints_deg, &placed.points[1].joints_deg);
    let memo = ToolMemo::new(cs, &check, &schedule);
    let graph = LegGraph {
        cs,
        check: &check,
        schedule: &schedule,
        eager: false,
        floor: None,
        memo: &memo,
    };
    let mut g = c.benchmark_group("trunk_1deg_leg1");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(5))
        .warm_up_time(Duration::from_secs(1));
    for (name, from, to, conn) in [
        ("wave26_forward", a, b, Connectivity::TwentySix),
        ("wave26_backward", b, a, Connectivity::TwentySix),
        ("wave6_forward", a, b, Connectivity::Six),
    ] {
        g.bench_function(name, |bench| {
            bench.iter(|| {
                let w = wave::expand(cs, &graph, from, to, conn).expect("joined");
                black_box(w.n())
            })
        });
    }
    g.bench_function("wave26_both_corridor", |bench| {
        bench.iter(|| {
            let (here, there) = wave::expand_both(cs, &graph, a, b);
            black_box(here.expect("joined").n() + there.expect("joined").n())
        })
    });
    g.finish();
}

criterion_group!(benches, waves);
criterion_main!(benches);
