//! Cells with a tool, built in code from the example cells (the cell format's `tool:` block is
//! read by another branch; the cell type's `tool` field is what the planner and the dense
//! re-check read): the trunk welded with a bent torch. Every module is held to the independent
//! dense re-check, which places the torch's shapes itself.

use crate::common::dense::check_module;
use crate::common::library::{
    load_cell, plan_every_method, Cell, Frame, Loc, Planned, Robot, Tool, ToolGeometry, ToolShape,
};
use crate::common::root;

/// A bent torch (tool0 frame, mm): a neck reaching 180 mm out, a body at the flange, a cup at
/// the tip bent 60 mm off the axis.
fn torch() -> Tool {
    let shape = |name: &str, geometry| ToolShape {
        name: name.into(),
        geometry,
        loc: Loc::default(),
    };
    Tool {
        name: "tTorch".into(),
        tframe: Frame {
            pos_mm: [60.0, 0.0, 200.0],
            quat_wxyz: [1.0, 0.0, 0.0, 0.0],
        },
        mass_kg: 2.5,
        cog_mm: [0.0, 0.0, 90.0],
        shapes: vec![
            shape(
                "neck",
                ToolGeometry::Cylinder {
                    from_mm: [0.0, 0.0, 0.0],
                    to_mm: [60.0, 0.0, 320.0],
                    radius_mm: 20.0,
                },
            ),
            shape(
                "body",
                ToolGeometry::Box {
                    min_mm: [-40.0, -40.0, 0.0],
                    max_mm: [40.0, 40.0, 80.0],
                },
            ),
            shape(
                "cup",
                ToolGeometry::Sphere {
                    centre_mm: [60.0, 0.0, 330.0],
                    radius_mm: 12.0,
                },
            ),
        ],
        loc: Loc::default(),
    }
}

fn modules(cell: &Cell, grid_deg: f64) -> Vec<(String, String)> {
    plan_every_method(cell, grid_deg)
        .unwrap_or_else(|e| panic!("{e}"))
        .into_iter()
        .filter_map(|(m, r)| match r {
            Planned::Module(text) => Some((m, text)),
            Planned::PlanningFailed(e) => panic!("{m}: {e}"),
        })
        .collect()
}

#[test]
fn the_trunk_with_a_torch_plans_routes_the_dense_check_holds_for_arm_and_torch() {
    let bare = load_cell(&root().join("cells/trunk.yaml"));
    let mut cell = bare.clone();
    cell.tool = Some(torch());
    let robot = Robot::load(&cell.robot.urdf_path).expect("robot");
    let with = modules(&cell, 2.0);
    let without = modules(&bare, 2.0);
    assert_eq!(with.len(), 3);
    for (m, text) in &with {
        let report = check_module(&cell, &robot, text, &format!("trunk with torch, {m}"))
            .unwrap_or_else(|f| panic!("{}", f.join("\n")));
        eprintln!("trunk with torch, {m}: closest {:?}", report.smallest);
    }
    // The torch matters: the routes planned without it, checked with it on, bring it within
    // the clearance of a box (the forearm's cylinder does not cover a 340 mm torch); the routes
    // planned with it differ and keep it clear.
    for (m, text) in &without {
        let f = check_module(&cell, &robot, text, m)
            .expect_err("a tool-less route happens to clear the torch");
        assert!(f.iter().any(|l| l.contains("tool shape")), "{m}: {f:?}");
    }
    assert_ne!(with, without);
}
