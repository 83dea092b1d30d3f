//! Whole-pipeline timing by stage, for benches/README.md: `cargo run --release --example profile -- CELL GRID`.
use gen_rapid::plan::{search, wave};
use gen_rapid::{cell, pipeline};
use std::time::Instant;
fn main() {
    let path = std::env::args().nth(1).unwrap_or("cells/trunk.yaml".into());
    let grid: f64 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    let t = Instant::now();
    let (c, _) = cell::load(std::path::Path::new(&path)).expect("cell");
    let prep = pipeline::prepare(c).expect("prepare");
    eprintln!("prepare {:?}", t.elapsed());
    let t = Instant::now();
    let cs = pipeline::cspace(&prep, grid);
    eprintln!(
        "cspace {:?} ({} nodes, {} free)",
        t.elapsed(),
        cs.grid.len(),
        cs.free_count()
    );
    let nodes: Vec<_> = prep
        .points
        .iter()
        .map(|p| cs.grid.node_at(&p.axes_deg))
        .collect();
    if let [Some(a), Some(b), ..] = nodes[..] {
        let t = Instant::now();
        let w = wave::expand(&cs, a, b, wave::Connectivity::TwentySix).expect("wave");
        eprintln!(
            "one wave leg 1: {:?} ({} numbered)",
            t.elapsed(),
            w.numbered()
        );
        let t = Instant::now();
        let mut calls = 0;
        let _ = search::extensile::search(&cs, a, b, &mut |x, y| {
            calls += 1;
            prep.model
                .move_is_safe(&cs.grid.axes_deg(x), &cs.grid.axes_deg(y))
        });
        eprintln!(
            "extensile search leg 1: {:?} ({calls} edge checks)",
            t.elapsed()
        );
    }
    for m in gen_rapid::cell::Method::ALL {
        let t = Instant::now();
        match pipeline::plan_and_render(&prep, &cs, m, |p| {
            Some(pipeline::manipulation_time_s(&prep, p))
        }) {
            Ok(o) => eprintln!(
                "{m}: {:?}, {} moves, {:.1} deg",
                t.elapsed(),
                o.plan.moves(),
                o.plan.path_length_deg()
            ),
            Err(e) => eprintln!("{m}: {:?} failed: {e}", t.elapsed()),
        }
    }
}
