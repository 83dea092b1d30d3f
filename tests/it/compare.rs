//! The comparison of the three search methods (paper sections 4-6) through the command line:
//! `gen-rapid compare`, `--svg`, the manipulation time in the module header and the depth-first
//! failure. (The modules of each method on the trunk cell, `tests/golden/trunk.<method>.mod`, are
//! the golden harness's.)

use crate::common::dense::check_module;
use crate::common::library::{load_cell, load_robot};
use crate::common::{gen_rapid, root, stderr, stdout};
use serde_json::Value;
use std::process::Output;

const TRUNK: &str = "cells/trunk.yaml";
/// A cell whose free space joins its two points only through diagonal steps (the paper's
/// Fig. 8); its error fixture is the depth-first run.
const FIG8: &str = "tests/err/depth_first_fig8.yaml";

fn compare_json(extra: &[&str]) -> Value {
    compare_json_of(TRUNK, extra)
}

fn compare_json_of(cell: &str, extra: &[&str]) -> Value {
    let mut args = vec!["compare", cell, "--json"];
    args.extend_from_slice(extra);
    let o = gen_rapid(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).expect("JSON on stdout")
}

fn row<'a>(j: &'a Value, method: &str) -> &'a Value {
    j["methods"]
        .as_array()
        .and_then(|a| a.iter().find(|r| r["method"] == method))
        .unwrap_or_else(|| panic!("no row for {method}: {j}"))
}

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

#[test]
fn trunk_moves_and_time_order_the_methods_as_in_the_paper() {
    let j = compare_json(&[]);
    let (nb, df, ex) = (
        row(&j, "neighboring"),
        row(&j, "depth-first"),
        row(&j, "extensile"),
    );
    for r in [nb, df, ex] {
        assert_eq!(r["ok"], true, "{r}");
        assert!(r["error"].is_null());
    }
    // Paper section 6: 33, 16 and 13 moves. Ours: extensile <= depth-first < neighboring.
    let moves = |r: &Value| num(r, "moves");
    assert!(moves(ex) <= moves(df) && moves(df) < moves(nb), "{j}");
    // Manipulation time: the extensile route is the fastest (the paper: 8.5, 9.7 and 18.8 s).
    // At the cell's v300 the TCP's speed leads most moves and depth-first and neighboring come
    // close (their order swaps on a 2 deg grid, docs/planning.md); the paper's full order is held at
    // vmax below.
    let time = |r: &Value| num(r, "manipulation_time_s");
    assert!(time(ex) <= time(df) && time(ex) <= time(nb), "{j}");
    // Every time is plausible against the profile (wrist fixed on this cell; axes 1-3 at
    // 110 deg/s, 0.4 s ramps): a move's leading axis covers at least length / sqrt 3 at no more
    // than full speed. At the cell's v300 the TCP's speed leads most moves (a longer time); at
    // vmax the axes lead, and a move takes at most its length at full speed plus one ramp.
    for r in [nb, df, ex] {
        assert!(
            time(r) > num(r, "path_length_deg") / 110.0 / 3f64.sqrt(),
            "{r}"
        );
    }
    let dir = tempfile::tempdir().expect("tempdir");
    let vmax = dir.path().join("trunk.yaml");
    let text = std::fs::read_to_string(root().join(TRUNK)).expect("trunk");
    let urdf = root().join("robots/irb1400.urdf");
    let text = text
        .replace("../robots/irb1400.urdf", &urdf.display().to_string())
        .replace("speed: v300", "speed: vmax");
    assert!(text.contains("speed: vmax"));
    std::fs::write(&vmax, text).expect("write");
    let j_max = compare_json_of(&vmax.display().to_string(), &[]);
    for method in ["neighboring", "depth-first", "extensile"] {
        let (r, fast) = (row(&j, method), row(&j_max, method));
        let (len, t, m) = (num(fast, "path_length_deg"), time(fast), moves(fast));
        assert_eq!(m, moves(r), "the same route");
        assert!(t > len / 110.0 / 3f64.sqrt(), "{fast}");
        assert!(t <= len / 110.0 + 0.4 * m + 1e-9, "{fast}");
        assert!(t <= time(r), "vmax is never slower than v300: {fast} {r}");
    }
    // The paper's order holds at vmax too.
    let time_max = |m: &str| time(row(&j_max, m));
    assert!(time_max("extensile") <= time_max("depth-first"));
    assert!(time_max("depth-first") < time_max("neighboring"));
}

#[test]
fn compare_is_deterministic_except_the_planning_time() {
    let strip = |mut j: Value| {
        for r in j["methods"].as_array_mut().expect("rows") {
            assert!(r["planning_time_ms"].as_f64().is_some_and(|t| t >= 0.0));
            r["planning_time_ms"] = Value::Null;
        }
        j
    };
    let a = strip(compare_json(&["--grid", "2"]));
    let b = strip(compare_json(&["--grid", "2"]));
    assert_eq!(a, b);
    assert_eq!(a["grid_deg"], 2.0);
    // The table: same rows but for the last column.
    let table = |o: Output| -> Vec<String> {
        stdout(&o)
            .lines()
            .map(|l| match l.split_whitespace().next() {
                // Fields but the last: the planning time's width varies with its value.
                Some("neighboring" | "depth-first" | "extensile") => {
                    let fields: Vec<&str> = l.split_whitespace().collect();
                    fields[..fields.len() - 1].join(" ")
                }
                _ => l.to_string(),
            })
            .collect()
    };
    let ta = table(gen_rapid(&["compare", TRUNK, "--grid", "2"]));
    let tb = table(gen_rapid(&["compare", TRUNK, "--grid", "2"]));
    assert_eq!(ta, tb);
    assert!(
        ta.iter().any(|l| l.contains("manipulation time (s)")),
        "{ta:?}"
    );
    assert_eq!(
        ta.iter()
            .filter(|l| l.starts_with("extensile")
                || l.starts_with("neighboring")
                || l.starts_with("depth-first"))
            .count(),
        4
    );
    // The row beyond the paper: the extensile route shortened, never longer.
    let rows = a["methods"].as_array().expect("rows");
    assert_eq!(rows.len(), 4);
    assert_eq!(rows[3]["method"], "extensile + shortcut");
    let (ex, sc) = (&rows[2], &rows[3]);
    assert_eq!(ex["method"], "extensile");
    assert!(sc["moves"].as_u64() <= ex["moves"].as_u64(), "{sc} {ex}");
    assert!(
        sc["manipulation_time_s"].as_f64() <= ex["manipulation_time_s"].as_f64(),
        "{sc} {ex}"
    );
}

#[test]
fn a_failing_method_is_a_row_and_the_others_still_count() {
    // The free space joins P0 and P1 only through diagonal steps: depth-first fails (Fig. 8),
    // the others plan.
    let o = gen_rapid(&["compare", FIG8]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let df = out
        .lines()
        .find(|l| l.starts_with("depth-first"))
        .expect("depth-first row");
    assert!(
        df.contains("failed: the depth-first search found no path from 'P0' to 'P1'"),
        "{out}"
    );
    for m in ["extensile", "neighboring"] {
        assert!(
            out.lines()
                .any(|l| l.starts_with(m) && !l.contains("failed")),
            "{out}"
        );
    }
    let j = compare_json_of(FIG8, &[]);
    assert_eq!(row(&j, "depth-first")["ok"], false);
    assert!(row(&j, "depth-first")["moves"].is_null());
    assert_eq!(row(&j, "extensile")["ok"], true);
}

#[test]
fn depth_first_no_longer_gives_up_where_its_axis_steps_have_a_way() {
    // The trunk on a 4 deg grid: the axis-step walk once ran out of steps the whole-move check
    // accepted and gave up with the Fig. 8 message, though the grid's safe axis steps join A
    // and B; the complete search plans it, and the dense check holds the module.
    let o = gen_rapid(&[TRUNK, "--planner", "depth-first", "--grid", "4"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let cell = load_cell(&root().join(TRUNK));
    let robot = load_robot(&cell);
    check_module(&cell, &robot, &stdout(&o), "trunk depth-first 4 deg")
        .unwrap_or_else(|f| panic!("{}", f.join("\n")));
}

#[test]
fn depth_first_failure_names_the_leg_exits_3_writes_no_module_and_draws_why() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (module, svg) = (dir.path().join("out.mod"), dir.path().join("out.svg"));
    let o = gen_rapid(&[
        FIG8,
        "-o",
        module.to_str().expect("utf-8"),
        "--svg",
        svg.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("error: the depth-first search found no path from 'P0' to 'P1'"),
        "{err}"
    );
    assert!(err.contains("try --planner extensile"), "{err}");
    // Points at point P1 in the cell.
    assert!(
        err.contains(&format!("--> {FIG8}:")) && err.contains("name: P1"),
        "{err}"
    );
    assert!(o.stdout.is_empty());
    assert!(!module.exists());
    // The picture of why: the leg's two points ringed (tests/it/pictures.rs reads such pictures).
    let pic = std::fs::read_to_string(&svg).expect("picture of the failure");
    assert_eq!(
        pic.matches("stroke=\"#DC0000\"").count(),
        6,
        "P0 and P1 ringed in 3 projections"
    );
}

#[test]
fn no_method_succeeding_prints_the_table_exits_3_and_draws_why() {
    // The trunk cell with a 50 mm clearance: point A is then too close to the trunk floor.
    let dir = tempfile::tempdir().expect("tempdir");
    let text = std::fs::read_to_string(root().join(TRUNK)).expect("trunk");
    let urdf = root().join("robots/irb1400.urdf");
    let text = text
        .replace("clearance: 10", "clearance: 50")
        .replace("../robots/irb1400.urdf", urdf.to_str().expect("utf-8"));
    assert!(text.contains("clearance: 50"));
    let cell = dir.path().join("tight.yaml");
    std::fs::write(&cell, text).expect("write cell");
    let svg = dir.path().join("all.svg");
    let o = gen_rapid(&[
        "compare",
        cell.to_str().expect("utf-8"),
        "--grid",
        "5",
        "--svg",
        svg.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let out = stdout(&o);
    assert_eq!(
        out.lines()
            .filter(|l| l.contains("failed: point 'A' cannot be used"))
            .count(),
        3,
        "{out}"
    );
    assert!(
        stderr(&o).contains("error: no method found a route"),
        "{}",
        stderr(&o)
    );
    // The picture of why (tests/it/pictures.rs reads it).
    assert!(svg.exists());
}

#[test]
fn compare_svg_draws_every_route_with_a_legend() {
    let dir = tempfile::tempdir().expect("tempdir");
    let svg = dir.path().join("all.svg");
    let o = gen_rapid(&[
        "compare",
        TRUNK,
        "--grid",
        "2",
        "--svg",
        svg.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    for m in ["neighboring (", "depth-first (", "extensile ("] {
        assert!(text.contains(m), "legend lacks {m}");
    }
    for p in ["A", "B", "C", "D", "E", "F"] {
        assert!(
            text.contains(&format!("\n{p}\n</text>")),
            "point {p} not labelled"
        );
    }
    // No temporary file left beside it.
    assert_eq!(std::fs::read_dir(dir.path()).expect("dir").count(), 1);
}

#[test]
fn run_states_the_time_in_the_header_and_draws_its_route() {
    let dir = tempfile::tempdir().expect("tempdir");
    let svg = dir.path().join("run.svg");
    let o = gen_rapid(&[TRUNK, "--grid", "2", "--svg", svg.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let module = stdout(&o);
    let line = module
        .lines()
        .find(|l| l.contains("! estimated time (s):"))
        .expect("time in the header");
    let t: f64 = line
        .rsplit(' ')
        .next()
        .and_then(|s| s.parse().ok())
        .expect("a number");
    let j = compare_json(&["--grid", "2"]);
    // A run writes the extensile route with the shortcut pass: the fourth row.
    assert!(
        (t - num(row(&j, "extensile + shortcut"), "manipulation_time_s")).abs() < 0.005,
        "{line}"
    );
    let pic = std::fs::read_to_string(&svg).expect("svg written");
    assert!(pic.contains("extensile (") && !pic.contains("neighboring ("));
}
