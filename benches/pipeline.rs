//! The whole pipeline on `cells/trunk.yaml` after the load stage (loaded once, outside the
//! timing: place, inspection, planning, refining and timing, rendering), at 2 and 1 degree, plus the grid
//! inspection alone.
//! Run: `cargo bench --bench pipeline`. Figures are recorded in benches/README.md.

use criterion::{criterion_group, criterion_main, Criterion};
use gen_rapid::pipeline::{self, Options};
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

fn whole(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("cells/trunk.yaml");
    let job = match pipeline::load(&path) {
        Ok(job) => job,
        Err(f) => panic!("{}", f.render()),
    };
    let method = job.cell.planner.method;
    let mut g = c.benchmark_group("trunk");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(8))
        .warm_up_time(Duration::from_secs(1));
    for grid in [2.0, 1.0] {
        g.bench_function(format!("pipeline_{grid}deg"), |b| {
            b.iter(|| {
                let out = pipeline::run(&job, &Options::new(method, grid)).expect("plan");
                black_box(out.rendered.text.len())
            })
        });
        let placed = pipeline::place(&job).expect("place");
        g.bench_function(format!("grid_inspection_{grid}deg"), |b| {
            b.iter(|| {
                let inspected = pipeline::inspect(&job, &placed, grid);
                black_box(inspected.cspace.free_count())
            })
        });
    }
    g.finish();
}

criterion_group!(benches, whole);
criterion_main!(benches);
