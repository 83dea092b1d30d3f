//! The independent dense re-check (`common/dense.rs`) of every module on file (the golden modules
//! of `cells/` and the modules of `tests/ok/`), a check that the trunk cell really blocks the
//! direct moves it claims to block, and the dense check's own reading of what the base stands on
//! (it can disagree with the collision model's rule, and does where that rule would be unsound).

use crate::common::dense::{check_module, Scene};
use crate::common::fixtures::{discover, Expect};
use crate::common::library::{load_cell, load_robot, Base, Target};
use crate::common::{arg, gen_rapid, root, stderr};
use std::path::Path;

#[test]
fn every_move_of_every_module_on_file_keeps_the_clearance() {
    let modules: Vec<_> = discover(&root())
        .cases
        .into_iter()
        .filter(|c| c.expect == Expect::Module && root().join(&c.expected).exists())
        .collect();
    for dir in ["tests/golden/", "tests/ok/"] {
        assert!(
            modules.iter().any(|c| c.expected.starts_with(dir)),
            "no module found in {dir}"
        );
    }
    let mut failures = Vec::new();
    for case in &modules {
        let cell = load_cell(&root().join(&case.cell));
        let robot = load_robot(&cell);
        let text = std::fs::read_to_string(root().join(&case.expected)).expect("module");
        // A module with process moves (MoveL, MoveC) is run as the controller runs them.
        if text.contains("\n        MoveL ") || text.contains("\n        MoveC ") {
            match crate::common::process::check_process(&cell, &text, &case.expected) {
                Ok(r) => eprintln!("{}: {r:?}", case.expected),
                Err(f) => failures.extend(f),
            }
            continue;
        }
        match check_module(&cell, &robot, &text, &case.expected) {
            Ok(r) => {
                // A cell of cells/ is a real cell: its moves are long.
                if case.cell.starts_with("cells/") && r.samples <= 100 {
                    failures.push(format!("{}: only {} samples", case.expected, r.samples));
                }
                let smallest = match r.smallest.mm.is_finite() {
                    true => format!(
                        "smallest distance {:.3} mm ({} to {})",
                        r.smallest.mm, r.smallest.link, r.smallest.obstacle
                    ),
                    false => "no boxes".into(),
                };
                eprintln!(
                    "{}: {} samples (step {} mm), {smallest}, header {:?} mm, {} xyz points, {} robtarget points (TCP within {:.4} mm, {:.5} deg)",
                    case.expected,
                    r.samples,
                    r.step_mm,
                    r.module.min_clearance_mm,
                    r.xyz_points,
                    r.tcp.points,
                    r.tcp.worst_mm,
                    r.tcp.worst_deg
                );
            }
            Err(f) => failures.extend(f),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_trunk_cells_direct_moves_are_blocked_so_planning_matters() {
    // cells/trunk.yaml claims that the straight moves A -> B, C -> D and E -> F hit something
    // (the quarter panels and the clamp post); the same dense check must see it.
    let cell = load_cell(&root().join("cells/trunk.yaml"));
    let robot = load_robot(&cell);
    let Base::Fixed(base) = cell.robot.base else {
        panic!("the trunk cell has a fixed base")
    };
    let scene = Scene::new(&robot, base, cell.robot.yaw_deg, &cell);
    let joints = |name: &str| match cell
        .points
        .iter()
        .find(|p| p.name == name)
        .map(|p| &p.target)
    {
        Some(Target::Joints { axes_deg, .. }) => *axes_deg,
        _ => panic!("point {name}"),
    };
    for (from, to) in [("A", "B"), ("C", "D"), ("E", "F")] {
        let (a, b) = (joints(from), joints(to));
        let six = |x: [f64; 3]| [x[0], x[1], x[2], 0.0, 0.0, 0.0];
        let d_ends = scene.nearest(six(a)).mm.min(scene.nearest(six(b)).mm);
        assert!(
            d_ends > cell.planner.clearance_mm,
            "{from} and {to} are free"
        );
        let worst = (0..=200)
            .map(|i| {
                let t = i as f64 / 200.0;
                scene
                    .nearest(six([0, 1, 2].map(|k| a[k] + t * (b[k] - a[k]))))
                    .mm
            })
            .fold(f64::INFINITY, f64::min);
        assert!(
            worst < cell.planner.clearance_mm,
            "the direct move {from} -> {to} keeps {worst:.1} mm: the cell should block it"
        );
    }
}

/// A cell in `dir` (robot file `urdf`, base, boxes as YAML lines) with the points P = (0, 0, 0)
/// and Q = (90, 0, 0), and a module for it as the generator would write it (one move P -> Q,
/// stating `min_clearance` mm).
fn stand_case(
    dir: &Path,
    urdf: &str,
    base: [f64; 3],
    boxes: &str,
    min_clearance: f64,
) -> (std::path::PathBuf, String) {
    let cell = format!(
        "module: Stand\nrobot: {{ urdf: {urdf}, base: [{}, {}, {}] }}\nobstacles:\n{boxes}points:\n  - {{ name: P, joints: [0, 0, 0] }}\n  - {{ name: Q, joints: [90, 0, 0] }}\nplanner: {{ grid: 10 }}\n",
        base[0], base[1], base[2]
    );
    let path = dir.join("stand.yaml");
    std::fs::write(&path, cell).expect("write cell");
    let target = |name: &str, a1: f64| {
        format!("    CONST jointtarget {name} := [[{a1:.3},0.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];\n")
    };
    let module = format!(
        "MODULE Stand\n    ! planner: extensile\n    ! clearance (mm): 10.0\n    ! base: [{:.1}, {:.1}, {:.1}] yaw: 0.000\n    ! moves: 1\n    ! min clearance (mm): {min_clearance:.1}\n\n{}{}\n    PROC main()\n        MoveAbsJ P\\NoEOffs, v300, fine, tool0;\n        MoveAbsJ Q\\NoEOffs, v300, fine, tool0;\n    ENDPROC\nENDMODULE\n",
        base[0],
        base[1],
        base[2],
        target("P", 0.0),
        target("Q", 90.0)
    );
    (path, module)
}

const FLOOR: &str =
    "  - { name: floor, box: { min: [-3000, -3000, -50], max: [3000, 3000, 0] } }\n";

#[test]
fn the_dense_check_reads_what_the_base_stands_on_from_the_geometry() {
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = root().join("robots/irb1400.urdf");
    let urdf = urdf.display().to_string();
    let check = |path: &Path, module: &str| {
        let cell = load_cell(path);
        let robot = load_robot(&cell);
        check_module(&cell, &robot, module, "stand")
    };

    // On a floor whose top is the mounting plane, the base cylinder (z 0 .. 650) stands on it:
    // not measured. The nearest approach is the upper arm's bottom cap at axis 2's height,
    // 475 mm above the floor (link_2 spans z 475 .. 1075 at axes 1..3 = 0).
    let (path, module) = stand_case(dir.path(), &urdf, [0.0, 0.0, 0.0], FLOOR, 475.0);
    let r = check(&path, &module).unwrap_or_else(|f| panic!("{f:#?}"));
    assert!((r.smallest.mm - 475.0).abs() < 1e-6, "{:?}", r.smallest);
    assert_eq!(
        (r.smallest.link.as_str(), r.smallest.obstacle.as_str()),
        ("link_2", "floor")
    );

    // On a 400 mm pedestal, with the floor below: both are under the base, neither is measured
    // against it; the upper arm is 475 mm above the pedestal.
    let boxes = format!(
        "{FLOOR}  - {{ name: pedestal, box: {{ min: [-400, -400, 0], max: [400, 400, 400] }} }}\n"
    );
    let (path, module) = stand_case(dir.path(), &urdf, [0.0, 0.0, 400.0], &boxes, 475.0);
    let r = check(&path, &module).unwrap_or_else(|f| panic!("{f:#?}"));
    assert!((r.smallest.mm - 475.0).abs() < 1e-6, "{:?}", r.smallest);
    assert_eq!(r.smallest.obstacle, "pedestal");

    // A mat reaching 1 mm above the mounting plane is not what the robot stands on: the base
    // cylinder goes 1 mm into it, and the dense check says so.
    let mat = "  - { name: mat, box: { min: [-3000, -3000, -50], max: [3000, 3000, 1] } }\n";
    let (path, module) = stand_case(dir.path(), &urdf, [0.0, 0.0, 0.0], mat, 474.0);
    let f = check(&path, &module).expect_err("the base touches the mat");
    assert!(
        f.iter().any(|m| m.contains("move P -> Q at t = 0.0000")
            && m.contains("link_1 is 0.000 mm from mat")),
        "{f:#?}"
    );
    // The collision model agrees: the generator refuses the cell.
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("link 'link_1' of the robot hits obstacle 'mat'"),
        "{}",
        stderr(&o)
    );

    // The same robot with its base cylinder lowered 125 mm into the floor (z -125 .. 525). The
    // floor's top is still at the mounting plane, so a rule that reads only "top at or below
    // the mounting plane" (the one this check once copied from the model) would exempt it. This
    // check measures the cylinder's own lowest point and flags the contact.
    let robots = dir.path().join("robots");
    std::fs::create_dir_all(&robots).expect("mkdir");
    let lowered = std::fs::read_to_string(root().join("robots/irb1400.urdf"))
        .expect("urdf")
        .replace(
            r#"<origin xyz="0 0 0.325" rpy="0 0 0"/>"#,
            r#"<origin xyz="0 0 0.2" rpy="0 0 0"/>"#,
        );
    assert!(lowered.contains(r#"<origin xyz="0 0 0.2" rpy="0 0 0"/>"#));
    std::fs::write(robots.join("low.urdf"), lowered).expect("write urdf");
    std::fs::copy(
        root().join("robots/irb1400.controller.yaml"),
        robots.join("low.controller.yaml"),
    )
    .expect("copy controller");
    let (path, module) = stand_case(dir.path(), "robots/low.urdf", [0.0, 0.0, 0.0], FLOOR, 475.0);
    let f = check(&path, &module).expect_err("the lowered base cylinder is in the floor");
    assert!(
        f.iter()
            .any(|m| m.contains("link_1 is 0.000 mm from floor")),
        "{f:#?}"
    );
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("link 'link_1' of the robot hits obstacle 'floor'"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn the_tcp_check_sees_a_module_the_controller_reads_otherwise() {
    // tests/ok/tool_wobj_robtargets.mod passes; each edit below makes a module the controller
    // would read differently from the cell, and the check must say so.
    let case = "tests/ok/tool_wobj_robtargets";
    let cell = load_cell(&root().join(format!("{case}.yaml")));
    let robot = load_robot(&cell);
    let text = std::fs::read_to_string(root().join(format!("{case}.mod"))).expect("module");
    let r = check_module(&cell, &robot, &text, case).unwrap_or_else(|f| panic!("{f:#?}"));
    assert_eq!(r.program.robtargets, 2, "{:?}", r.program);
    for (edit, needle) in [
        (
            ("[[100.000,200.000,150.000]", "[[100.000,200.200,150.000]"),
            // Not the cell's pose, or (moved off its quadrant) no solution of its confdata.
            "W1_rt",
        ),
        (("[0,-1,0,0],[9E9", "[0,-1,0,1],[9E9"), "confdata"),
        (
            ("[[0.000,0.000,250.000]", "[[0.000,0.000,250.500]"),
            "tooldata tframe",
        ),
        (
            ("[[700.000,-200.000,400.000]", "[[700.000,-200.000,401.000]"),
            "wobjdata uframe",
        ),
        (
            ("MoveJ W2_rt, v100, fine,", "MoveJ W2_rt, v200, fine,"),
            "must be MoveJ with v100",
        ),
        // The last point asks z5: the route ends at a stop point all the same.
        (
            ("MoveJ W2_rt, v100, fine,", "MoveJ W2_rt, v100, z5,"),
            "the move to W2_rt is z5, not fine",
        ),
        (
            (
                "tTorch\\WObj:=wobjTable;\n    ENDPROC",
                "tTorch;\n    ENDPROC",
            ),
            // Without its work object the robtarget is another pose: the move to W2 is refused.
            "W2",
        ),
    ] {
        assert!(text.contains(edit.0), "{needle}: {}", edit.0);
        let bad = text.replacen(edit.0, edit.1, 1);
        let f = check_module(&cell, &robot, &bad, case).expect_err(needle);
        assert!(f.iter().any(|m| m.contains(needle)), "{needle}: {f:#?}");
    }
}

/// `robots/irb1600_8_145.urdf` without the collision cylinders of links 4..6 (the lumped arm of
/// links 1..3 alone, as gen-rapid checked a URDF before it carried every link).
fn without_the_wrist(urdf: &str) -> String {
    let mut out = urdf.to_string();
    for link in ["link_4", "link_5", "link_6"] {
        let open = format!(r#"<collision name="{link}">"#);
        let start = out
            .find(&open)
            .unwrap_or_else(|| panic!("{link}'s collision"));
        let end =
            start + out[start..].find("</collision>").expect("its end") + "</collision>".len();
        out.replace_range(start..end, "");
    }
    out
}

#[test]
fn the_dense_check_carries_every_link_and_a_route_for_links_1_to_3_alone_fails_it() {
    // tests/ok/irb1600_link4_detour.yaml: a sensor box only link 4 can reach on the direct
    // swing. Planned for the same robot with links 4..6 stripped from its URDF, the route goes
    // straight through it; the dense check, carrying every link of the shipped robot, says
    // which link hits, and holds the stripped robot's route clear for links 1..3.
    let case = root().join("tests/ok/irb1600_link4_detour.yaml");
    let text = std::fs::read_to_string(&case).expect("cell");
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = std::fs::read_to_string(root().join("robots/irb1600_8_145.urdf")).expect("urdf");
    std::fs::write(dir.path().join("bare.urdf"), without_the_wrist(&urdf)).expect("write urdf");
    std::fs::copy(
        root().join("robots/irb1600_8_145.controller.yaml"),
        dir.path().join("bare.controller.yaml"),
    )
    .expect("copy controller");
    let bare_text = text.replace("model: irb1600_8_145", "urdf: bare.urdf");
    assert_ne!(bare_text, text);
    let bare_path = dir.path().join("bare.yaml");
    std::fs::write(&bare_path, &bare_text).expect("write cell");
    let o = gen_rapid(&[arg(&bare_path), "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let module = String::from_utf8(o.stdout).expect("utf-8");
    assert!(
        !module.contains("via01_01"),
        "links 1..3 alone swing straight:\n{module}"
    );

    let bare_cell = load_cell(&bare_path);
    let bare_robot = load_robot(&bare_cell);
    check_module(&bare_cell, &bare_robot, &module, "links 1..3")
        .unwrap_or_else(|f| panic!("{f:#?}"));
    let cell = load_cell(&case);
    let robot = load_robot(&cell);
    let f = check_module(&cell, &robot, &module, "every link").expect_err("link 4 hits the sensor");
    assert!(
        f.iter()
            .any(|m| m.contains("link_4 is") && m.contains("from sensor")),
        "{f:#?}"
    );
    // And the module on file, planned with every link, passes.
    let golden =
        std::fs::read_to_string(root().join("tests/ok/irb1600_link4_detour.mod")).expect("module");
    check_module(&cell, &robot, &golden, "on file").unwrap_or_else(|f| panic!("{f:#?}"));
}
