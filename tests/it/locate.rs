//! Robot location (`base: auto`), points given as positions (`xyz`), and `gen-rapid locate`, end
//! to end. The modules of the edge cases are fixtures (`tests/ok/branch_*`,
//! `tests/ok/base_auto_in_range`), held to the output by the golden harness and, like every
//! module on file, to the dense re-check (which also brings every `xyz` point back by forward
//! kinematics from the header's base); the tests here read them for what each case is about.

use crate::common::library::{load_cell, locate_auto, Base};
use crate::common::module::Module;
use crate::common::{arg, gen_rapid, line_of, read, root, stderr, temp_cell};

#[test]
fn trunk_auto_region_contains_the_papers_base() {
    let cell = load_cell(&root().join("cells/trunk-auto.yaml"));
    assert_eq!(cell.robot.base, Base::Auto);
    let survey = locate_auto(&root().join("cells/trunk-auto.yaml"));
    let loc = &survey.location;
    let paper = [0.0, -850.0];
    let m = loc.margin_at(paper);
    assert!(m.is_some_and(|m| m > 0.0), "paper's base not in R: {m:?}");
    assert!(loc.region.contains(paper), "raster disagrees");
    // The chosen base is inside, with the margin reported, and is no worse than the paper's.
    assert_eq!(loc.margin_at(loc.best_mm), Some(loc.best_margin_mm));
    assert!(loc.best_margin_mm >= m.unwrap_or(f64::INFINITY) - 1e-9);
    let base = [survey.base_mm[0], survey.base_mm[1]];
    assert_eq!(loc.margin_at(base), Some(survey.margin_mm));
    // A position under the trunk is not.
    assert!(loc.margin_at([0.0, 0.0]).is_none() && !loc.region.contains([0.0, 0.0]));
}

#[test]
fn trunk_auto_plans_from_the_chosen_base_with_the_yaw_as_given() {
    // The module of cells/trunk-auto.yaml (held to the output by the golden harness; its points
    // brought back by FK from the header's base, in range and clear, by the dense re-check:
    // safety::every_move_of_every_module_on_file_keeps_the_clearance).
    let module = Module::parse(&read("tests/golden/trunk-auto.mod")).expect("module");
    let cell = load_cell(&root().join("cells/trunk-auto.yaml"));
    let survey = locate_auto(&root().join("cells/trunk-auto.yaml"));
    // The base is the one the place stage chooses (here R's position with the largest margin),
    // on the floor; the yaw as given.
    assert_eq!(module.base_mm, survey.base_mm);
    assert_eq!(
        survey.base_mm,
        [survey.location.best_mm[0], survey.location.best_mm[1], 0.0]
    );
    assert_eq!(module.yaw_deg, cell.robot.yaw_deg, "yaw kept as given");
    assert_eq!(module.yaw_deg, 90.0);
}

#[test]
fn cli_runs_trunk_auto_and_locate_reports_it() {
    let cell = "cells/trunk-auto.yaml";
    // The run's module (held to the output by the golden harness).
    let module = Module::parse(&read("tests/golden/trunk-auto.mod")).expect("module");
    assert_eq!(module.name, "TrunkWeldAuto");
    let base = module.base_mm;

    let dir = tempfile::tempdir().expect("tempdir");
    let svg = dir.path().join("r.svg");
    let o = gen_rapid(&[
        "locate",
        cell,
        "--json",
        "--svg",
        svg.to_str().expect("utf-8"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    assert_eq!(v["base_mode"], "auto");
    assert_eq!(v["points"], 6);
    let b: Vec<f64> = (0..3)
        .map(|k| v["base_mm"][k].as_f64().expect("number"))
        .collect();
    assert_eq!(b, base.to_vec(), "locate and the run choose the same base");
    let area = v["area_mm2"].as_f64().expect("area");
    assert!(area > 0.0 && (v["area_m2"].as_f64().expect("m2") - area * 1e-6).abs() < 1e-12);
    let lo = v["bbox_mm"][0].as_array().expect("bbox");
    let hi = v["bbox_mm"][1].as_array().expect("bbox");
    let inside =
        |k: usize, x: f64| lo[k].as_f64().expect("n") <= x && x <= hi[k].as_f64().expect("n");
    assert!(inside(0, 0.0) && inside(1, -850.0) && inside(0, b[0]) && inside(1, b[1]));
    assert!(v["margin_mm"].as_f64().expect("margin") > 0.0);
    assert!(v["given_base"].is_null());
    let drawing = std::fs::read_to_string(&svg).expect("svg written");
    assert!(drawing.starts_with("<svg") && drawing.trim_end().ends_with("</svg>"));
    let texts: Vec<&str> = drawing.lines().map(str::trim).collect();
    assert!(
        texts.contains(&"A") && texts.contains(&"F"),
        "points labelled"
    );
    assert!(drawing.contains("x (mm)") && drawing.contains("chosen base"));

    let o = gen_rapid(&["locate", cell]);
    assert!(o.status.success());
    let text = String::from_utf8(o.stdout).expect("utf-8");
    assert!(text.contains("points: 6"), "{text}");
    assert!(
        text.contains("region R: ") && text.contains(" m^2 ("),
        "{text}"
    );
    assert!(text.contains("bounding box: x "), "{text}");
    assert!(
        text.contains(&format!("chosen base: [{:.1}, {:.1}, 0.0] mm", b[0], b[1])),
        "{text}"
    );
}

#[test]
fn locate_on_a_fixed_base_with_joint_points_says_whether_the_base_is_in_r() {
    let cell = root().join("cells/trunk.yaml");
    let o = gen_rapid(&["locate", cell.to_str().expect("utf-8"), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["base_mode"], "fixed");
    assert_eq!(v["given_base"]["in_region"], true, "{v}");
    assert!(v["given_base"]["margin_mm"].as_f64().expect("margin") > 0.0);
    // A's wrist centre by FK from (0, -850) yaw 90 with joints [90, 0, 0]: 870 mm to -x.
    let a = &v["reach"][0]["xyz_mm"];
    assert!((a[0].as_f64().expect("x") + 870.0).abs() < 1e-6, "{a}");
    assert!((a[1].as_f64().expect("y") + 850.0).abs() < 1e-6, "{a}");

    // A fixed base under an obstacle: computed, and reported outside.
    let dir = tempfile::tempdir().expect("tempdir");
    let path = temp_cell(
        dir.path(),
        "under.yaml",
        "module: Under\nrobot:\n  urdf: URDF\n  base: [0, 0, 0]\nobstacles:\n  - name: table\n    box: { min: [-100, -100, 0], max: [100, 100, 300] }\npoints:\n  - { name: P, joints: [0, 0, 0] }\n  - { name: Q, joints: [30, 10, 0] }\n",
    );
    let o = gen_rapid(&["locate", path.to_str().expect("utf-8")]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).expect("utf-8");
    assert!(
        text.contains("given base: [0.0, 0.0, 0.0] mm: OUTSIDE R"),
        "{text}"
    );
}

#[test]
fn cli_unreachable_point_names_it_with_its_distance_and_line() {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = "module: Far\nrobot:\n  urdf: URDF\n  base: [0, 0, 0]\npoints:\n  - { name: W1, xyz: [900, 0, 1000] }\n  - { name: W2, xyz: [3000, 0, 500] }\n";
    let path = temp_cell(dir.path(), "far.yaml", body);
    let out_file = dir.path().join("far.mod");
    let o = gen_rapid(&[
        path.to_str().expect("utf-8"),
        "-o",
        out_file.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    assert!(!out_file.exists(), "no module on error");
    let e = stderr(&o);
    assert!(e.contains("point 'W2'"), "{e}");
    // Shoulder at (150, 0, 475): 2850 mm in x, 25 mm in z.
    let d = (2850.0f64.powi(2) + 25.0f64.powi(2)).sqrt();
    assert!(e.contains(&format!("{d:.1} mm from the shoulder")), "{e}");
    assert!(e.contains("the arm reaches 129.9 .. 1329.9 mm"), "{e}");
    let line = line_of(body, "name: W2");
    assert!(e.contains(&format!("far.yaml:{line}:")), "{e}");
    // Without -o: nothing on stdout either.
    let o = gen_rapid(&[path.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(3));
    assert!(o.stdout.is_empty());
}

#[test]
fn cli_empty_region_names_the_points_and_leaves_stdout_empty() {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = "module: Apart\nrobot:\n  urdf: URDF\n  base: auto\npoints:\n  - { name: LEFT, xyz: [-3000, 0, 800] }\n  - { name: RIGHT, xyz: [3000, 0, 800] }\n";
    let path = temp_cell(dir.path(), "apart.yaml", body);
    let p = path.to_str().expect("utf-8");
    let svg = dir.path().join("r.svg");
    for args in [
        vec![p],
        vec!["locate", p, "--svg", svg.to_str().expect("utf-8")],
    ] {
        let o = gen_rapid(&args);
        assert_eq!(o.status.code(), Some(3), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}");
        let e = stderr(&o);
        assert!(
            e.contains("reach regions of LEFT and RIGHT do not meet"),
            "{e}"
        );
        assert!(e.contains("6000.0 mm apart"), "{e}");
        let line = line_of(body, "base: auto");
        assert!(e.contains(&format!("apart.yaml:{line}:")), "{e}");
    }
    // locate --svg draws why (tests/it/pictures.rs reads such pictures).
    assert!(svg.exists(), "the picture of the failure");
}

#[test]
fn base_auto_refuses_joint_points_at_their_line() {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = "module: Mixed\nrobot:\n  urdf: URDF\n  base: auto\npoints:\n  - { name: P, xyz: [800, 0, 900] }\n  - { name: Q, joints: [10, 0, 0] }\n";
    let path = temp_cell(dir.path(), "mixed.yaml", body);
    let o = gen_rapid(&[path.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("point 'Q' gives joint values, but `base: auto`"),
        "{e}"
    );
    assert!(
        e.contains(&format!("mixed.yaml:{}:", line_of(body, "name: Q"))),
        "{e}"
    );
}

fn branch_cell(branch: &str) -> String {
    format!(
        "module: Branch\nrobot:\n  urdf: URDF\n  base: [0, 0, 0]\npoints:\n  - {{ name: P, xyz: [50, 50, 1550]{branch} }}\n  - {{ name: Q, xyz: [900, 0, 900] }}\n"
    )
}

#[test]
fn branch_forces_the_back_stance_and_bad_branches_point_at_their_line() {
    // tests/ok/branch_free.yaml: unforced, the first point takes the most upright arm, facing
    // it (axis 1 = 45). tests/ok/branch_back_elbow_up.yaml: forced back, axis 1 half a turn
    // round, the same wrist centre (the dense re-check brings both back by FK).
    let free = Module::parse(&read("tests/ok/branch_free.mod")).expect("module");
    let a = free.target("P");
    assert!((a[0] - 45.0).abs() < 1e-3, "{a:?}");
    let back = Module::parse(&read("tests/ok/branch_back_elbow_up.mod")).expect("module");
    let a = back.target("P");
    assert!((a[0] + 135.0).abs() < 1e-3, "{a:?}");
    let dir = tempfile::tempdir().expect("tempdir");
    // Elbow down is out of the IRB 1400's coupled range: a planning failure naming the branch.
    let down = temp_cell(
        dir.path(),
        "down.yaml",
        &branch_cell(", branch: front-elbow-down"),
    );
    let o = gen_rapid(&[down.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("point 'P'") && stderr(&o).contains("front-elbow-down"));
    // Not a branch: an input error at the `branch:` value.
    let body = branch_cell(", branch: sideways");
    let bad = temp_cell(dir.path(), "bad.yaml", &body);
    let o = gen_rapid(&[bad.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("unknown branch `sideways`; expected one of"),
        "{e}"
    );
    let line = line_of(&body, "sideways");
    let col = body
        .lines()
        .nth(line - 1)
        .and_then(|l| l.find("sideways"))
        .expect("col")
        + 1;
    assert!(e.contains(&format!("bad.yaml:{line}:{col}")), "{e}");
    assert!(o.stdout.is_empty());
}

#[test]
fn base_auto_skips_positions_from_which_a_point_is_out_of_range() {
    // tests/ok/base_auto_in_range.yaml, a review finding: the reach regions ignore the axis-2
    // range, so the position of R with the largest margin (under the points' middle) left P1 at
    // axis 2 = -70.3. The run and `locate` must both choose a position from which every point
    // is solved in range (the dense re-check holds the module's points to their ranges and
    // brings them back by FK), and agree.
    let path = root().join("tests/ok/base_auto_in_range.yaml");
    let module = Module::parse(&read("tests/ok/base_auto_in_range.mod")).expect("module");
    let chosen = [module.base_mm[0], module.base_mm[1]];
    let location = locate_auto(&path).location;
    // The chosen position lies in R, and is not the one with the largest margin (which fails).
    assert!(location.margin_at(chosen).is_some(), "{chosen:?}");
    let mut by_margin = location.candidates();
    by_margin.sort_by(|a, b| b.1.total_cmp(&a.1));
    assert_ne!(
        by_margin[0].0, chosen,
        "the largest-margin position should fail here"
    );
    let o = gen_rapid(&["locate", arg(&path), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let located = j["base_mm"]
        .as_array()
        .map(|a| [a[0].as_f64(), a[1].as_f64()]);
    assert_eq!(located, Some([Some(chosen[0]), Some(chosen[1])]), "{j}");
}
