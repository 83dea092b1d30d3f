//! Whole-pipeline timing by stage, for benches/README.md: `cargo run --release --example profile -- CELL GRID`.
use gen_rapid::output::rapid::ModuleTemplate;
use gen_rapid::pipeline;
use gen_rapid::plan::leg::{LegGraph, ToolMemo, WristSchedule};
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
        // Leg 1's graph, optimistic (the paper's wave) and eager (accepted steps only).
        let check = inspected.model.grid_check(cs.grid.step_deg);
        let schedule =
            WristSchedule::new(&placed.points[0].joints_deg, &placed.points[1].joints_deg);
        for eager in [false, true] {
            let memo = ToolMemo::new(cs, &check, &schedule);
            let graph = LegGraph {
                cs,
                check: &check,
                schedule: &schedule,
                eager,
                floor: None,
                memo: &memo,
            };
            let t = Instant::now();
            let w = wave::expand(cs, &graph, a, b, wave::Connectivity::TwentySix);
            eprintln!(
                "one {} wave leg 1: {:?} ({} numbered)",
                if eager { "eager" } else { "optimistic" },
                t.elapsed(),
                w.map_or(0, |w| w.numbered())
            );
        }
    }
    let template = ModuleTemplate::embedded();
    for m in Method::ALL {
        let t = Instant::now();
        match pipeline::route(&job, &placed, &inspected, m) {
            Ok(route) => {
                let planned = t.elapsed();
                let shortcut = job.cell.planner.shortcut;
                let plan = pipeline::refine(&job, &placed, &inspected, route, shortcut).plan;
                let refined = t.elapsed();
                let text = pipeline::render(&job, &placed, &plan, &template).map(|r| r.text.len());
                eprintln!(
                    "{m}: plan {planned:?}, with refine {refined:?}, with render {:?}, {} moves, {:.1} deg, {} bytes",
                    t.elapsed(),
                    plan.route.moves(),
                    plan.route.path_length_deg(),
                    text.unwrap_or(0)
                );
            }
            Err(e) => eprintln!("{m}: {:?} failed: {e}", t.elapsed()),
        }
    }
}
