//! A program a cell runs every day: revisits, the closed cycle and several work objects, read
//! off the modules the binary writes (`cells/pick-place.yaml`, `tests/ok/revisit_cycle.yaml`).
//! The expected quaternions are OrientZYX worked out by hand, not read from the output.

use crate::common::dense::check_module;
use crate::common::library::{load_cell, load_robot};
use crate::common::{arg, gen_rapid, root, stderr, stdout};

/// The module `gen-rapid` writes for `cell` (a path in the repository).
fn module_of(cell: &str) -> String {
    let o = gen_rapid(&[arg(&root().join(cell)), "-q"]);
    assert!(o.status.success(), "{cell}: {}", stderr(&o));
    stdout(&o)
}

/// The routine's motion instructions, trimmed.
fn moves(text: &str) -> Vec<&str> {
    text.lines()
        .map(str::trim)
        .filter(|l| l.starts_with("Move"))
        .collect()
}

#[test]
fn the_pick_place_cell_declares_each_point_once_and_each_move_names_its_work_object() {
    let text = module_of("cells/pick-place.yaml");
    // `home` is reached twice (first and revisited at the end) and declared once.
    assert_eq!(
        text.matches("CONST jointtarget home :=").count(),
        1,
        "{text}"
    );
    assert_eq!(text.matches("MoveAbsJ home\\NoEOffs").count(), 2, "{text}");
    assert_eq!(text.matches("CONST robtarget pick_rt :=").count(), 1);
    // OrientZYX by hand: zyx [90, 0, 0] = Rz(90) = [cos 45, 0, 0, sin 45]; zyx [180, 0, 0] =
    // Rz(180) = [0, 0, 0, 1]; zyx [0, 180, 0] = Ry(180) = [0, 0, 1, 0].
    assert!(text.contains("PERS wobjdata wobjConveyor := [FALSE,TRUE,\"\",[[700.000,0.000,750.000],[0.707106781,0.000000000,0.000000000,0.707106781]]"), "{text}");
    assert!(text.contains("PERS wobjdata wobjPallet := [FALSE,TRUE,\"\",[[300.000,700.000,600.000],[0.000000000,0.000000000,0.000000000,1.000000000]]"), "{text}");
    for p in [
        "pick_rt := [[-300.000,-200.000,30.000]",
        "place_rt := [[300.000,-200.000,30.000]",
    ] {
        assert!(
            text.contains(&format!(
                "{p},[0.000000000,0.000000000,1.000000000,0.000000000]"
            )),
            "{p}: {text}"
        );
    }
    // Each move names the work object of the point it goes towards: the pick's approach, line
    // and retract the conveyor's; the leg to the place (its via) and the place's the pallet's;
    // the moves towards home (a jointtarget) none.
    let ms = moves(&text);
    assert_eq!(ms.len(), 10, "{ms:?}");
    for m in &ms {
        let want = if m.contains("pick_rt") {
            Some("wobjConveyor")
        } else if m.contains("place_rt") || m.contains("via02_") {
            Some("wobjPallet")
        } else {
            None
        };
        match want {
            Some(w) => assert!(m.ends_with(&format!("tGripper\\WObj:={w};")), "{m}"),
            None => assert!(m.ends_with(", tGripper;"), "{m}"),
        }
    }
    assert!(
        ms.iter().any(|m| m.starts_with("MoveAbsJ via02_")),
        "{ms:?}"
    );
    // The last entry revisits the first: closed as it stands, no leg added.
    assert_eq!(
        ms.last(),
        Some(&"MoveAbsJ home\\NoEOffs, v1000, fine, tGripper;")
    );
    assert!(text.contains("! cycle: closed: "), "{text}");
}

#[test]
fn the_cycle_is_closed_by_a_proven_leg_and_the_header_says_where_a_routine_ends() {
    let cell_path = "tests/ok/revisit_cycle.yaml";
    let text = module_of(cell_path);
    // Each point declared once; D reached twice (the first time by a revisit at its own speed,
    // before D's place in the list), C twice (the second by a revisit with its own zone).
    for p in ["A", "B", "C", "D", "F"] {
        let decl = format!("CONST jointtarget {p} :=");
        assert_eq!(text.matches(&decl).count(), 1, "{p}: {text}");
    }
    let ms = moves(&text);
    let to_d: Vec<&&str> = ms
        .iter()
        .filter(|m| m.starts_with("MoveAbsJ D\\"))
        .collect();
    assert_eq!(to_d.len(), 2, "{ms:?}");
    assert!(to_d[0].contains(", v100, "), "{to_d:?}");
    // The leg closing the cycle: from C back to A, at motion.speed, fine, through its vias
    // (numbered as the seventh leg's).
    let n = ms.len();
    assert_eq!(
        ms[n - 1],
        "MoveAbsJ A\\NoEOffs, v300, fine, tool0;",
        "{ms:?}"
    );
    assert!(
        ms[n - 2].starts_with("MoveAbsJ via07_01\\NoEOffs, v300, "),
        "{ms:?}"
    );
    assert!(
        ms[n - 3].starts_with("MoveAbsJ C\\NoEOffs, v300, "),
        "{ms:?}"
    );
    assert!(text.contains("! cycle: closed: "), "{text}");
    // The dense re-check measures every move, the closing leg's too, against the clearance.
    let cell = load_cell(&root().join(cell_path));
    let robot = load_robot(&cell);
    let r = check_module(&cell, &robot, &text, cell_path).unwrap_or_else(|f| panic!("{f:?}"));
    assert!(r.smallest.mm >= cell.planner.clearance_mm - 1e-6, "{r:?}");
    // The same cell without the cycle ends at C: the header says so.
    let open = module_of("cells/trunk.yaml");
    assert!(
        open.contains("! cycle: open: the routine ends at F, not where it starts (A); motion.cycle: true closes it\n"),
        "{open}"
    );
}
