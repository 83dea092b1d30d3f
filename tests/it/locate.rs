//! Robot location (`base: auto`), points given as positions (`xyz`), and `gen-rapid locate`,
//! end to end: through the library pipeline and through the command line.

use gen_rapid::cell::{self, Base, Target};
use gen_rapid::collision::Placement;
use gen_rapid::ik;
use gen_rapid::pipeline;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gen-rapid"))
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("the binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Writes a cell (with the robot line filled in) into a temporary directory.
fn temp_cell(dir: &Path, name: &str, body: &str) -> PathBuf {
    let urdf = manifest().join("robots/irb1400.urdf");
    let text = body.replace("URDF", &urdf.display().to_string());
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write cell");
    path
}

/// 1-based line of the first line containing `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .map(|i| i + 1)
        .unwrap_or_else(|| panic!("no line with {needle}"))
}

/// Axes 1..3 of every `CONST jointtarget NAME := [[a1,a2,a3,...` line of a module.
fn module_axes(text: &str, name: &str) -> [f64; 3] {
    let prefix = format!("CONST jointtarget {name} := [[");
    let line = text
        .lines()
        .map(str::trim)
        .find(|l| l.starts_with(&prefix))
        .unwrap_or_else(|| panic!("no target {name}"));
    let v: Vec<f64> = line[prefix.len()..]
        .split(']')
        .next()
        .expect("values")
        .split(',')
        .map(|x| x.trim().parse().expect("number"))
        .collect();
    [v[0], v[1], v[2]]
}

/// `! base: [x, y, z] yaw: deg` of a module header.
fn header_base(text: &str) -> ([f64; 3], f64) {
    let line = text
        .lines()
        .map(str::trim)
        .find(|l| l.starts_with("! base: ["))
        .expect("base line");
    let inner = &line["! base: [".len()..line.find(']').expect("]")];
    let v: Vec<f64> = inner
        .split(',')
        .map(|x| x.trim().parse().expect("number"))
        .collect();
    let yaw: f64 = line
        .split("yaw:")
        .nth(1)
        .expect("yaw")
        .trim()
        .parse()
        .expect("yaw number");
    ([v[0], v[1], v[2]], yaw)
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[test]
fn trunk_auto_region_contains_the_papers_base() {
    let (cell, _) = cell::load(&manifest().join("cells/trunk-auto.yaml")).expect("cell");
    assert_eq!(cell.robot.base, Base::Auto);
    let robot = pipeline::load_robot(&cell).expect("robot");
    let geom = pipeline::geometry(&cell, &robot).expect("geometry");
    let loc = pipeline::locate_base(&cell, &robot, &geom).expect("a region");
    let paper = [0.0, -850.0];
    let m = loc.margin_at(paper);
    assert!(m.is_some_and(|m| m > 0.0), "paper's base not in R: {m:?}");
    assert!(loc.region.contains(paper), "raster disagrees");
    // The chosen base is inside, with the margin reported, and is no worse than the paper's.
    assert_eq!(loc.margin_at(loc.base_mm), Some(loc.margin_mm));
    assert!(loc.margin_mm >= m.unwrap_or(f64::INFINITY) - 1e-9);
    // A position under the trunk is not.
    assert!(loc.margin_at([0.0, 0.0]).is_none() && !loc.region.contains([0.0, 0.0]));
}

#[test]
fn trunk_auto_plans_from_the_chosen_base_and_its_points_come_back_by_fk() {
    let path = manifest().join("cells/trunk-auto.yaml");
    let (cell, _) = cell::load(&path).expect("cell");
    let prep = pipeline::prepare(cell.clone()).expect("prepared");
    let loc = prep.location.clone().expect("base: auto located");
    assert_eq!(
        prep.placement.base_mm,
        [loc.base_mm[0], loc.base_mm[1], 0.0]
    );
    assert_eq!(
        prep.placement.yaw_deg, cell.robot.yaw_deg,
        "yaw kept as given"
    );
    let cs = pipeline::cspace(&prep, cell.planner.grid_deg);
    let out = pipeline::plan_and_render(&prep, &cs, cell.planner.method, |_| None).expect("plan");
    // The header carries exactly the base the joints were computed from.
    let (base, yaw) = header_base(&out.text);
    assert_eq!(base, prep.placement.base_mm, "{}", out.text);
    assert_eq!(yaw, 90.0);
    // Every cell point's written joint values give its xyz back within 0.05 mm (FK from the
    // header's placement, read from the text, not from the pipeline's memory).
    let robot = pipeline::load_robot(&cell).expect("robot");
    let geom = pipeline::geometry(&cell, &robot).expect("geometry");
    let placement = Placement {
        base_mm: base,
        yaw_deg: yaw,
    };
    for p in &cell.points {
        let Target::Xyz {
            wrist_centre_mm, ..
        } = p.target
        else {
            panic!("trunk-auto gives positions");
        };
        let axes = module_axes(&out.text, &p.name);
        let back = pipeline::to_cell_frame(ik::forward(&geom, axes), &placement);
        let d = dist(back, wrist_centre_mm);
        assert!(
            d < 0.05,
            "{}: {d} mm off ({back:?} vs {wrist_centre_mm:?})",
            p.name
        );
        assert!(robot.check_range3(&axes).is_ok(), "{} out of range", p.name);
        assert!(prep.model.is_free(&axes), "{} in collision", p.name);
    }
}

#[test]
fn cli_runs_trunk_auto_and_locate_reports_it() {
    let cell = manifest().join("cells/trunk-auto.yaml");
    let cell = cell.to_str().expect("utf-8 path");
    let o = run(&[cell]);
    assert!(o.status.success(), "{}", stderr(&o));
    let module = String::from_utf8(o.stdout).expect("utf-8");
    assert!(module.starts_with("MODULE TrunkWeldAuto"), "{module}");
    let (base, _) = header_base(&module);

    let dir = tempfile::tempdir().expect("tempdir");
    let svg = dir.path().join("r.svg");
    let o = run(&[
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

    let o = run(&["locate", cell]);
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
    let cell = manifest().join("cells/trunk.yaml");
    let o = run(&["locate", cell.to_str().expect("utf-8"), "--json"]);
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
    let o = run(&["locate", path.to_str().expect("utf-8")]);
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
    let o = run(&[
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
    let o = run(&[path.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(3));
    assert!(o.stdout.is_empty());
}

#[test]
fn cli_empty_region_names_the_points_and_writes_nothing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = "module: Apart\nrobot:\n  urdf: URDF\n  base: auto\npoints:\n  - { name: LEFT, xyz: [-3000, 0, 800] }\n  - { name: RIGHT, xyz: [3000, 0, 800] }\n";
    let path = temp_cell(dir.path(), "apart.yaml", body);
    let p = path.to_str().expect("utf-8");
    let svg = dir.path().join("r.svg");
    for args in [
        vec![p],
        vec!["locate", p, "--svg", svg.to_str().expect("utf-8")],
    ] {
        let o = run(&args);
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
    assert!(!svg.exists(), "no drawing on error");
}

#[test]
fn base_auto_refuses_joint_points_at_their_line() {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = "module: Mixed\nrobot:\n  urdf: URDF\n  base: auto\npoints:\n  - { name: P, xyz: [800, 0, 900] }\n  - { name: Q, joints: [10, 0, 0] }\n";
    let path = temp_cell(dir.path(), "mixed.yaml", body);
    let o = run(&[path.to_str().expect("utf-8")]);
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
    let dir = tempfile::tempdir().expect("tempdir");
    // Unforced: the first point takes the most upright arm, facing it (axis 1 = 45).
    // (Back stance for (50, 50, 1550): axes -135, -50.0, -61.4, within the ranges.)
    let free = temp_cell(dir.path(), "free.yaml", &branch_cell(""));
    let (cell, _) = cell::load(&free).expect("cell");
    let prep = pipeline::prepare(cell).expect("prepared");
    assert!(
        (prep.points[0].axes_deg[0] - 45.0).abs() < 1e-3,
        "{:?}",
        prep.points[0]
    );
    // Forced back: axis 1 half a turn round, same wrist centre.
    let back = temp_cell(
        dir.path(),
        "back.yaml",
        &branch_cell(", branch: back-elbow-up"),
    );
    let (cell, _) = cell::load(&back).expect("cell");
    let prep = pipeline::prepare(cell.clone()).expect("prepared");
    let a = prep.points[0].axes_deg;
    assert!((a[0] + 135.0).abs() < 1e-3, "{a:?}");
    let robot = pipeline::load_robot(&cell).expect("robot");
    let geom = pipeline::geometry(&cell, &robot).expect("geometry");
    let w = pipeline::to_cell_frame(ik::forward(&geom, a), &prep.placement);
    assert!(dist(w, [50.0, 50.0, 1550.0]) < 0.05, "{w:?}");
    // Elbow down is out of the IRB 1400's coupled range: a planning failure naming the branch.
    let down = temp_cell(
        dir.path(),
        "down.yaml",
        &branch_cell(", branch: front-elbow-down"),
    );
    let o = run(&[down.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("point 'P'") && stderr(&o).contains("front-elbow-down"));
    // Not a branch: an input error at the `branch:` value.
    let body = branch_cell(", branch: sideways");
    let bad = temp_cell(dir.path(), "bad.yaml", &body);
    let o = run(&[bad.to_str().expect("utf-8")]);
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
    // Review finding: the reach regions ignore the axis-2 range, so the position of R with the
    // largest margin (under the points' middle) left P1 at axis 2 = -70.3. The run and `locate`
    // must both choose a position from which every point is solved in range, and agree.
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = manifest().join("robots/irb1400.urdf");
    let body = format!(
        "module: Auto1\nrobot: {{ urdf: {}, base: auto, yaw: 45 }}\nobstacles: []\npoints:\n  - {{ name: P1, xyz: [800, 200, 900] }}\n  - {{ name: P2, xyz: [600, 700, 1100] }}\n  - {{ name: P3, xyz: [900, -300, 700] }}\n",
        urdf.display()
    );
    let path = temp_cell(dir.path(), "auto1.yaml", &body);
    let (cell, _) = cell::load(&path).expect("cell");
    let prep = pipeline::prepare(cell.clone()).expect("a base that reaches every point");
    let location = prep.location.as_ref().expect("base: auto");
    assert_eq!(
        location.base_mm,
        [prep.placement.base_mm[0], prep.placement.base_mm[1]]
    );
    // The chosen position lies in R, and is not the one with the largest margin (which fails).
    assert!(location.margin_at(location.base_mm).is_some());
    let mut by_margin = location.candidates();
    by_margin.sort_by(|a, b| b.1.total_cmp(&a.1));
    assert_ne!(
        by_margin[0].0, location.base_mm,
        "the largest-margin position should fail here"
    );
    let robot = pipeline::load_robot(&cell).expect("robot");
    let geom = pipeline::geometry(&cell, &robot).expect("geometry");
    for p in &prep.points {
        robot.check_range3(&p.axes_deg).expect("in range");
        let w = pipeline::to_cell_frame(ik::forward(&geom, p.axes_deg), &prep.placement);
        let given = match cell
            .points
            .iter()
            .find(|q| q.name == p.name)
            .map(|q| &q.target)
        {
            Some(gen_rapid::cell::Target::Xyz {
                wrist_centre_mm, ..
            }) => *wrist_centre_mm,
            _ => panic!("xyz point"),
        };
        assert!(dist(w, given) < 0.05, "{}: {w:?} vs {given:?}", p.name);
    }
    let o = run(&["locate", path.to_str().expect("utf-8"), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let chosen = j["base_mm"]
        .as_array()
        .map(|a| [a[0].as_f64(), a[1].as_f64()]);
    assert_eq!(
        chosen,
        Some([
            Some(prep.placement.base_mm[0]),
            Some(prep.placement.base_mm[1])
        ]),
        "{j}"
    );
}
