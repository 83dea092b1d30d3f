//! The example cells with process moves run as a controller runs them (`common/process.rs`),
//! and the check itself held to a seam moved into an obstacle.

use crate::common::library::load_cell;
use crate::common::process::check_process as run_module;
use crate::common::{arg, gen_rapid, root, stderr, stdout};

#[test]
fn the_process_cells_run_as_a_controller_runs_them() {
    for (name, process_moves) in [
        ("torch-trunk", 6),
        ("gripper-pick", 4),
        ("arc-seam", 3),
        ("pick-place", 4),
    ] {
        let path = root().join(format!("cells/{name}.yaml"));
        let cell = load_cell(&path);
        let o = gen_rapid(&[arg(&path), "-q"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let run =
            run_module(&cell, &stdout(&o), name).unwrap_or_else(|f| panic!("{}", f.join("\n")));
        assert_eq!(run.process_moves, process_moves, "{name}");
        assert!(run.samples > 100 * process_moves, "{name}: {run:?}");
        assert!(run.off_path_mm < 0.01, "{name}: {run:?}");
        assert!(
            run.nearest_mm >= cell.planner.clearance_mm - 0.5,
            "{name}: {run:?}"
        );
        eprintln!("{name}: {run:?}");
    }
}

#[test]
fn the_check_sees_a_seam_moved_into_the_clamp_post() {
    // The right seam of the torch cell run through the clamp post (the module written for the
    // cell, its R2 robtarget moved onto the post): the check refuses it.
    let path = root().join("cells/torch-trunk.yaml");
    let cell = load_cell(&path);
    let o = gen_rapid(&[arg(&path), "-q"]);
    let text = stdout(&o);
    let moved = text.replace(
        "CONST robtarget R2_rt := [[1330.000,280.000,0.000]",
        "CONST robtarget R2_rt := [[830.000,280.000,0.000]",
    );
    assert_ne!(moved, text);
    let f = run_module(&cell, &moved, "moved").expect_err("a seam through the post");
    assert!(f.iter().any(|m| m.contains("clamp_post")), "{f:?}");
}
