//! The whole pipeline on `cells/trunk.yaml` (cell already parsed: robot, grid inspection,
//! planning, rendering), at 2 and 1 degree, plus the grid inspection alone.
//! Run: `cargo bench --bench pipeline`. Figures are recorded in benches/README.md.

use criterion::{criterion_group, criterion_main, Criterion};
use gen_rapid::{cell, pipeline};
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

fn trunk() -> cell::Cell {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("cells/trunk.yaml");
    match cell::load(&path) {
        Ok((c, _)) => c,
        Err(e) => panic!("cells/trunk.yaml: {e}"),
    }
}

fn whole(c: &mut Criterion) {
    let cell = trunk();
    let mut g = c.benchmark_group("trunk");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(8))
        .warm_up_time(Duration::from_secs(1));
    for grid in [2.0, 1.0] {
        g.bench_function(format!("pipeline_{grid}deg"), |b| {
            b.iter(|| {
                let prep = pipeline::prepare(cell.clone()).expect("prepare");
                let cs = pipeline::cspace(&prep, grid);
                let out = pipeline::plan_and_render(&prep, &cs, cell.planner.method, |p| {
                    Some(pipeline::manipulation_time_s(&prep, p))
                })
                .expect("plan");
                black_box(out.text.len())
            })
        });
        let prep = pipeline::prepare(cell.clone()).expect("prepare");
        g.bench_function(format!("grid_inspection_{grid}deg"), |b| {
            b.iter(|| black_box(pipeline::cspace(&prep, grid).free_count()))
        });
    }
    g.finish();
}

criterion_group!(benches, whole);
criterion_main!(benches);
