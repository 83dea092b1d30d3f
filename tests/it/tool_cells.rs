//! The example cells with a tool, read from their files as the binary reads them
//! (`cells/torch-trunk.yaml`, `cells/gripper-pick.yaml`): every method's route keeps the
//! clearance for the arm and the tool's shapes (the independent dense re-check, which places the
//! shapes itself from the cell's `tool:` block), and the tool's volume matters: the torch cell
//! with its `shapes:` left out (the same TCP, no volume) plans a route that drags the torch
//! within the clearance of a box.

use crate::common::dense::check_module;
use crate::common::library::{load_cell, load_robot, parse_cell, plan_every_method, Cell, Planned};
use crate::common::root;

fn modules(cell: &Cell, grid_deg: f64, what: &str) -> Vec<(String, String)> {
    plan_every_method(cell, grid_deg)
        .unwrap_or_else(|e| panic!("{what}: {e}"))
        .into_iter()
        .filter_map(|(m, r)| match r {
            Planned::Module(text) => Some((m, text)),
            // Depth-first may meet the paper's Fig. 8; the others are complete on their grid.
            Planned::PlanningFailed(e) if m == "depth-first" && e.contains("only diagonally") => {
                None
            }
            Planned::PlanningFailed(e) => panic!("{what}, {m}: {e}"),
        })
        .collect()
}

/// The cell text without the tool's `shapes:` list (its lines up to the next top-level key).
fn without_shapes(text: &str) -> String {
    let mut out = String::new();
    let mut skipping = false;
    for line in text.lines() {
        if line.trim_start().starts_with("shapes:") {
            skipping = true;
            continue;
        }
        if skipping && !line.starts_with(' ') && !line.is_empty() {
            skipping = false;
        }
        if !skipping {
            out += line;
            out += "\n";
        }
    }
    out
}

#[test]
fn the_tool_cells_plan_with_every_method_and_the_dense_check_holds_arm_and_tool() {
    for (stem, grid_deg) in [("torch-trunk", 2.0), ("gripper-pick", 2.0)] {
        let path = root().join(format!("cells/{stem}.yaml"));
        let cell = load_cell(&path);
        assert!(
            cell.tool.as_ref().is_some_and(|t| !t.shapes.is_empty()),
            "{stem} has a tool with shapes"
        );
        let robot = load_robot(&cell);
        let planned = modules(&cell, grid_deg, stem);
        assert!(
            planned.iter().any(|(m, _)| m == "extensile") && planned.len() >= 2,
            "{stem}: {:?}",
            planned.iter().map(|(m, _)| m).collect::<Vec<_>>()
        );
        for (m, text) in &planned {
            let label = format!("{stem}, {m}, {grid_deg} deg");
            let report = check_module(&cell, &robot, text, &label)
                .unwrap_or_else(|f| panic!("{}", f.join("\n")));
            eprintln!(
                "{label}: {} samples, closest {:.2} mm ({} to {})",
                report.samples, report.smallest.mm, report.smallest.link, report.smallest.obstacle
            );
        }
    }
}

#[test]
fn the_torch_without_its_volume_plans_a_route_that_drags_it_through_a_box() {
    let path = root().join("cells/torch-trunk.yaml");
    let text = std::fs::read_to_string(&path).expect("cell");
    let cell = load_cell(&path);
    let bare_text = without_shapes(&text);
    assert_ne!(bare_text, text);
    let bare = parse_cell(&path, &bare_text).unwrap_or_else(|e| panic!("{e}\n{bare_text}"));
    assert!(bare.tool.as_ref().is_some_and(|t| t.shapes.is_empty()));
    let robot = load_robot(&cell);
    let with = modules(&cell, 2.0, "torch-trunk");
    let without = modules(&bare, 2.0, "torch-trunk without shapes");
    // The routes planned without the torch's volume, checked with it: the forearm's cylinder
    // does not cover a torch reaching 336 mm beyond the flange.
    let mut dragged = 0;
    for (m, text) in &without {
        check_module(&bare, &robot, text, m).unwrap_or_else(|f| panic!("{}", f.join("\n")));
        if let Err(f) = check_module(&cell, &robot, text, m) {
            assert!(f.iter().any(|l| l.contains("tool shape")), "{m}: {f:?}");
            dragged += 1;
        }
    }
    assert!(
        dragged >= 1,
        "no tool-less route brings the torch near a box"
    );
    assert_ne!(with, without);
}
