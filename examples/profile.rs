//! Whole-pipeline timing by stage, for benches/README.md: `cargo run --release --example profile -- CELL GRID`.
use gen_rapid::pipeline;
use gen_rapid::plan::{wave, Method};
use std::time::Instant;
fn main() {
    let path = std::env::args().nth(1).unwrap_or("cells/trunk.yaml".into());
    let grid: f64 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    let t = Instant::now();
    let job = match pipeline::load(std::path::Path::new(&path)) {
        Ok(job) => job,
        Err(f) => panic!("{}", f.render()),
    };
    eprintln!("load {:?}", t.elapsed());
    let t = Instant::now();
    let placed = pipeline::place(&job).expect("place");
    eprintln!("place {:?}", t.elapsed());
    let t = Instant::now();
    let inspected = pipeline::inspect(&job, &placed, grid);
    let cs = &inspected.cspace;
    eprintln!(
        "inspect {:?} ({} nodes, {} free)",
        t.elapsed(),
        cs.grid.len(),
        cs.free_count()
    );
    let nodes: Vec<_> = placed
        .points
        .iter()
        .map(|p| cs.grid.node_at(&p.arm_deg()))
        .collect();
    if let [Some(a), Some(b), ..] = nodes[..] {
        let t = Instant::now();
        let w = wave::expand(cs, a, b, wave::Connectivity::TwentySix).expect("wave");
        eprintln!(
            "one wave leg 1: {:?} ({} numbered)",
            t.elapsed(),
            w.numbered()
        );
        let t = Instant::now();
        let mut calls = 0;
        let _ = Method::Extensile.search(cs, a, b, &mut |x, y| {
            calls += 1;
            inspected
                .model
                .move_is_safe(&cs.grid.axes_deg(x), &cs.grid.axes_deg(y))
        });
        eprintln!(
            "extensile search leg 1: {:?} ({calls} edge checks)",
            t.elapsed()
        );
    }
    for m in Method::ALL {
        let t = Instant::now();
        match pipeline::plan(&job, &placed, &inspected, m) {
            Ok(plan) => {
                let planned = t.elapsed();
                let plan = pipeline::time(&job, plan);
                let text = pipeline::render(&job, &placed, &plan).map(|r| r.text.len());
                eprintln!(
                    "{m}: plan {planned:?}, with time and render {:?}, {} moves, {:.1} deg, {} bytes",
                    t.elapsed(),
                    plan.moves(),
                    plan.path_length_deg(),
                    text.unwrap_or(0)
                );
            }
            Err(e) => eprintln!("{m}: {:?} failed: {e}", t.elapsed()),
        }
    }
}
