//! The refine stage: the shortcut pass never lengthens a route (moves or estimated time) against
//! the paper's method alone on the example cells and on random cells; without it the module
//! writes the paper's route; the modules it writes pass the dense re-check (moves and zoned
//! corners); the route written is certified as `plan::certify` certifies it anew.

use crate::common::dense::check_module;
use crate::common::library::{
    load_cell, load_robot, paper_and_refined, parse_cell, refined_and_recertified,
};
use crate::common::module::Module;
use crate::common::{arg, gen_rapid, root, stdout};

const EXAMPLES: [&str; 6] = [
    "conveyor",
    "gripper-pick",
    "shelf",
    "torch-trunk",
    "trunk-auto",
    "trunk",
];

#[test]
fn the_shortcut_never_lengthens_an_example_cell_and_writes_only_checked_moves() {
    let mut shorter = 0;
    for name in EXAMPLES {
        let path = root().join(format!("cells/{name}.yaml"));
        let cell = load_cell(&path);
        let r = paper_and_refined(&cell, cell.planner.grid_deg).expect(name);
        assert!(
            r.refined.0 <= r.paper.0 && r.refined.1 <= r.paper.1 + 1e-9,
            "{name}: paper {:?}, refined {:?}",
            r.paper,
            r.refined
        );
        if r.refined.0 < r.paper.0 {
            shorter += 1;
        }
        let robot = load_robot(&cell);
        check_module(&cell, &robot, &r.refined_module, name)
            .unwrap_or_else(|f| panic!("{}", f.join("\n")));
        // With z50 at the vias: the same bounds, every zoned corner sampled.
        let text = std::fs::read_to_string(&path).expect("cell");
        let z50 = match text.contains("\nmotion:\n") {
            true => text.replace("\nmotion:\n", "\nmotion:\n  via_zone: z50\n"),
            false => format!("{text}\nmotion:\n  via_zone: z50\n"),
        };
        let zoned = parse_cell(&path, &z50).expect("z50 cell");
        let z = paper_and_refined(&zoned, cell.planner.grid_deg).expect(name);
        assert!(
            z.refined.1 <= z.paper.1 + 1e-9,
            "{name} z50: {:?} {:?}",
            z.paper,
            z.refined
        );
        let report = check_module(&zoned, &robot, &z.refined_module, &format!("{name} z50"))
            .unwrap_or_else(|f| panic!("{}", f.join("\n")));
        eprintln!(
            "{name}: paper {:?}, shortcut {:?}, z50 {:?} with {} zoned corners",
            r.paper, r.refined, z.refined, report.corners
        );
    }
    assert!(
        shorter >= 2,
        "the shortcut dropped moves on only {shorter} cells"
    );
}

#[test]
fn without_the_shortcut_the_module_is_the_papers() {
    let path = root().join("cells/trunk.yaml");
    let cell = load_cell(&path);
    let r = paper_and_refined(&cell, cell.planner.grid_deg).expect("trunk");
    // On the trunk the shortcut pass moves waypoints: the flag has something to leave out.
    assert_ne!(
        r.refined_route, r.paper_route,
        "the shortcut changes nothing"
    );
    let o = gen_rapid(&[arg(&path), "--no-shortcut"]);
    assert!(o.status.success());
    let module = Module::parse(&stdout(&o)).expect("module");
    assert_eq!(module.header_moves, r.paper.0, "--no-shortcut");
    assert_eq!(module.targets.len(), r.paper_route.len(), "--no-shortcut");
    for ((name, written), planned) in module.targets.iter().zip(&r.paper_route) {
        let off = (0..6)
            .map(|k| (written[k] - planned[k]).abs())
            .fold(0.0, f64::max);
        assert!(
            off < 1e-9,
            "--no-shortcut: {name} {written:?} against {planned:?}"
        );
    }
    let text = std::fs::read_to_string(&path).expect("cell");
    let off = text.replace("\nplanner:\n", "\nplanner:\n  shortcut: false\n");
    assert_ne!(off, text, "the trunk cell has a planner block");
    let cell = parse_cell(&path, &off).expect("shortcut: false");
    let r = paper_and_refined(&cell, cell.planner.grid_deg).expect("trunk");
    assert_eq!(r.refined_route, r.paper_route, "planner.shortcut: false");
    assert_eq!(r.refined, r.paper, "planner.shortcut: false");
}

#[test]
fn on_gripper_pick_z50_splits_the_vias_by_the_cabinet_and_beats_fine() {
    // Both vias of the paper's route hug the cabinet: their corner triangles come within the
    // clearance (sampled: 0 and 9.0 mm), so z50 flies by only where `refine::split` made room.
    let path = root().join("cells/gripper-pick.yaml");
    let cell = load_cell(&path);
    let fine = paper_and_refined(&cell, cell.planner.grid_deg).expect("fine");
    let text = std::fs::read_to_string(&path).expect("cell");
    let z50 = text.replace("\nmotion:\n", "\nmotion:\n  via_zone: z50\n");
    assert_ne!(z50, text, "gripper-pick has a motion block");
    let zoned = parse_cell(&path, &z50).expect("z50 cell");
    let z = paper_and_refined(&zoned, cell.planner.grid_deg).expect("z50");
    assert!(
        z.refined.1 < fine.refined.1,
        "z50 {:?} not below fine {:?}",
        z.refined,
        fine.refined
    );
    let robot = load_robot(&zoned);
    let report = check_module(&zoned, &robot, &z.refined_module, "gripper-pick z50")
        .unwrap_or_else(|f| panic!("{}", f.join("\n")));
    assert!(report.corners >= 1, "no zoned corner sampled");
    let zoned_vias = z
        .refined_module
        .lines()
        .find(|l| l.contains("zoned vias:"))
        .expect("header line");
    assert!(
        !zoned_vias.contains("zoned vias: 0 "),
        "no via zoned: {zoned_vias}"
    );
}

#[test]
fn the_written_route_is_certified_whether_the_shortcut_replaces_the_papers_route_or_not() {
    // A run plans the route without certifying its clearances (the refine stage certifies the
    // route it keeps): the plan written must carry, per move, what `plan::certify` finds anew.
    // (The trunk has no fly-by zone: with one, the zoned corners' clearances also enter the
    // plan's least, which `certify` alone does not give.)
    let path = root().join("cells/trunk.yaml");
    let text = std::fs::read_to_string(&path).expect("cell");
    let no_shortcut = text.replace("\nplanner:\n", "\nplanner:\n  shortcut: false\n");
    // Only B and C: one straight move, which the shortcut pass keeps as it is.
    let straight: String = text
        .lines()
        .filter(|l| {
            !["name: A,", "name: D,", "name: E,", "name: F,"]
                .iter()
                .any(|n| l.contains(n))
        })
        .map(|l| format!("{l}\n"))
        .collect();
    let mut kept_the_papers = 0;
    let mut replaced_it = 0;
    for (what, body) in [
        ("trunk", &text),
        ("trunk without the shortcut", &no_shortcut),
        ("trunk from B to C", &straight),
    ] {
        let cell = parse_cell(&path, body).expect(what);
        let r = refined_and_recertified(&cell, 2.0).expect(what);
        let clearances: Vec<_> = r
            .refined
            .moves
            .iter()
            .map(|m| m.clearance.clone())
            .collect();
        assert_eq!(clearances.len(), r.refined.route.moves(), "{what}");
        assert!(
            clearances.iter().all(Option::is_some),
            "{what}: a move without its clearance"
        );
        assert_eq!(clearances, r.again.clearances, "{what}");
        assert_eq!(r.refined.least, r.again.least, "{what}");
        if r.refined.route.waypoints == r.paper.waypoints {
            kept_the_papers += 1;
        } else {
            replaced_it += 1;
        }
    }
    assert!(
        kept_the_papers >= 2 && replaced_it >= 1,
        "kept {kept_the_papers}, replaced {replaced_it}"
    );
}
