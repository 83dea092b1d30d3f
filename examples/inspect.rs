//! The grid inspection alone, REPS times, for benches/README.md (CPU time with `perf stat -e
//! task-clock`): `cargo run --release --example inspect -- CELL GRID REPS`.
use gen_rapid::pipeline;
use std::time::Instant;
fn main() {
    let path = std::env::args().nth(1).unwrap_or("cells/trunk.yaml".into());
    let grid: f64 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    let reps: usize = std::env::args()
        .nth(3)
        .and_then(|s| s.parse().ok())
        .unwrap_or(5);
    let job = match pipeline::load(std::path::Path::new(&path)) {
        Ok(job) => job,
        Err(f) => panic!("{}", f.render()),
    };
    let placed = pipeline::place(&job).expect("place");
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let t = Instant::now();
        let inspected = pipeline::inspect(&job, &placed, grid);
        let n = inspected.cspace.free_count();
        let e = t.elapsed().as_secs_f64();
        best = best.min(e);
        eprintln!("inspect {:.1} ms ({} free)", e * 1e3, n);
    }
    eprintln!("best {:.1} ms", best * 1e3);
}
