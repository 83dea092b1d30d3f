//! Pictures on failure: when planning fails, `--svg FILE` still draws why (the grid's blocked
//! nodes with the points of the failed leg ringed; for `locate`, the reach circles and the
//! obstacles' footprints), written atomically, with the failure's exit status and nothing on
//! stdout. And every help line that suggests a picture names one that is drawn.

use crate::common::svg::{Element, Svg};
use crate::common::{file_names, gen_rapid, read, root, stderr, temp_cell};
use std::path::Path;

/// The colour the failed points are ringed and labelled in (`cspace_svg::FAILED`).
const FAILED: &str = "#DC0000";

/// The rings around failed points.
fn rings(svg: &Svg) -> Vec<&Element> {
    svg.all("circle")
        .filter(|c| c.attr("stroke") == Some(FAILED) && c.attr("fill") == Some("none"))
        .collect()
}

/// The black dots of the cell points.
fn dots(svg: &Svg) -> Vec<&Element> {
    svg.all("circle")
        .filter(|c| c.attr("fill") == Some("#000000"))
        .collect()
}

fn same_centre(a: &Element, b: &Element) -> bool {
    a.num("cx") == b.num("cx") && a.num("cy") == b.num("cy")
}

/// Only `name` in the directory: no temporary file left beside it.
fn alone(dir: &Path, name: &str) {
    let names: Vec<_> = std::fs::read_dir(dir)
        .expect("dir")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, [name], "{names:?}");
}

#[test]
fn no_path_draws_the_blocked_nodes_and_rings_both_points_of_the_leg() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("why.svg");
    // An existing picture is replaced whole.
    std::fs::write(&file, "old").expect("write");
    let o = gen_rapid(&[
        "tests/err/no_path.yaml",
        "--svg",
        file.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(o.stdout.is_empty(), "stdout must stay empty");
    let err = stderr(&o);
    // The message is the fixture's, then a note on the picture.
    let fixture = read("tests/err/no_path.stderr");
    let message = fixture.split_once('\n').map_or("", |(_, m)| m);
    assert!(err.starts_with(message), "{err}");
    assert!(
        err.ends_with(&format!(
            "note: the blocked nodes of the grid are drawn to {}, with P1 and P2 ringed in red\n",
            file.display()
        )),
        "{err}"
    );
    alone(dir.path(), "why.svg");
    let svg = Svg::read(&file);
    // Three projections, each: both points labelled in the failure's colour and ringed, each
    // ring round a point's dot; no route drawn.
    for p in ["P1", "P2"] {
        let labels: Vec<_> = svg.labels(p).collect();
        assert_eq!(labels.len(), 3, "{p}");
        assert!(labels.iter().all(|l| l.attr("fill") == Some(FAILED)), "{p}");
    }
    let (rings, dots) = (rings(&svg), dots(&svg));
    assert_eq!((rings.len(), dots.len()), (6, 6));
    assert!(rings
        .iter()
        .all(|r| r.num("r") == Some(9.0) && dots.iter().any(|d| same_centre(r, d))));
    // No route (the methods' colours, `cspace_svg::colour`).
    assert!(
        svg.all("polyline")
            .all(|l| !matches!(l.attr("stroke"), Some("#E67800" | "#1E5AD2" | "#C80046"))),
        "no route on a failure"
    );
    // Why, under the picture; the blocked nodes (dark: every node of the column blocked).
    assert!(
        svg.all("text").any(|t| t
            .text
            .contains("red rings: no collision-free path from 'P1' to 'P2'")),
        "the reason is written"
    );
    assert!(svg.all("rect").any(|r| r.attr("fill") == Some("#505050")));
}

/// A picture whose directory does not exist can never be written: the run is refused before it
/// plans (exit 4, naming the file), not after minutes of planning with a note.
#[test]
fn a_failure_picture_that_cannot_be_written_is_refused_before_the_run() {
    let o = gen_rapid(&[
        "tests/err/no_path.yaml",
        "--svg",
        "/nonexistent/dir/why.svg",
    ]);
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let err = stderr(&o);
    assert!(
        err.starts_with(
            "error: cannot write /nonexistent/dir/why.svg: its directory does not exist\n"
        ),
        "{err}"
    );
    assert!(!err.contains("no collision-free path"), "{err}");
}

#[test]
fn a_run_that_stops_before_the_grid_says_nothing_was_drawn() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("x.svg");
    let o = gen_rapid(&[
        "tests/err/point_in_collision.yaml",
        "--svg",
        file.to_str().expect("utf-8"),
    ]);
    // A point in collision fails in the plan stage: drawn, that point ringed.
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let svg = Svg::read(&file);
    assert_eq!(rings(&svg).len(), 3);
    assert!(svg.labels("P2").all(|l| l.attr("fill") == Some(FAILED)));
    assert!(svg.labels("P1").all(|l| l.attr("fill") == Some("#000000")));
    // The unknown key fails at load: no grid, nothing drawn, a note says so.
    let file = dir.path().join("y.svg");
    let o = gen_rapid(&[
        "tests/err/unknown_key.yaml",
        "--svg",
        file.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(!file.exists());
}

#[test]
fn locate_with_r_empty_draws_the_reach_circles_and_the_footprints() {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = "module: Apart\nrobot:\n  urdf: URDF\n  base: auto\nobstacles:\n  - { name: pillar, box: { min: [-200, -200, 0], max: [200, 200, 2000] } }\npoints:\n  - { name: LEFT, xyz: [-3000, 0, 800] }\n  - { name: RIGHT, xyz: [3000, 0, 800] }\n  - { name: HIGH, xyz: [0, 0, 4000] }\n";
    let cell = temp_cell(dir.path(), "apart.yaml", body);
    let out = dir.path().join("pictures");
    std::fs::create_dir(&out).expect("dir");
    let file = out.join("r.svg");
    let o = gen_rapid(&[
        "locate",
        cell.to_str().expect("utf-8"),
        "--svg",
        file.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(o.stdout.is_empty(), "stdout must stay empty");
    let err = stderr(&o);
    assert!(
        err.contains("point HIGH is out of reach from any base position"),
        "{err}"
    );
    assert!(
        err.contains("note: the reach regions and the obstacles' footprints are drawn to"),
        "{err}"
    );
    alone(&out, "r.svg");
    let svg = Svg::read(&file);
    assert_eq!(svg.labels("LEFT").count(), 1);
    assert_eq!(svg.labels("RIGHT").count(), 1);
    assert_eq!(svg.labels("HIGH (out of reach)").count(), 1);
    assert!(svg.all("text").any(|t| t.text.contains("R is empty")));
    // A reach circle per reachable point, in its colour (first two of the palette), none for
    // the point out of reach; the pillar's footprint, and its grown outline (dashed).
    let circles = |colour: &str| {
        svg.all("polyline")
            .filter(|p| p.attr("stroke") == Some(colour))
            .count()
    };
    assert!(
        circles("#1F77B4") >= 1 && circles("#FF7F0E") >= 1,
        "reach circles"
    );
    assert_eq!(circles("#9467BD"), 0, "no circle for HIGH");
    assert!(
        svg.all("rect").any(|r| r.attr("fill") == Some("#6E6E6E")),
        "footprint"
    );
    assert!(
        svg.all("polyline")
            .filter(|p| p.attr("stroke") == Some("#6E6E6E"))
            .count()
            > 1,
        "grown footprint"
    );
    // Without --svg: nothing but the message.
    let o = gen_rapid(&["locate", cell.to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(3));
    assert!(!stderr(&o).contains("note:"));
}

#[test]
fn compare_without_a_route_draws_the_points_every_method_failed_at() {
    // The trunk cell with a 50 mm clearance: point A is too close to the trunk floor.
    let dir = tempfile::tempdir().expect("tempdir");
    let text = read("cells/trunk.yaml");
    let urdf = root().join("robots/irb1400.urdf");
    let text = text
        .replace("clearance: 10", "clearance: 50")
        .replace("../robots/irb1400.urdf", urdf.to_str().expect("utf-8"));
    let cell = dir.path().join("tight.yaml");
    std::fs::write(&cell, text).expect("write cell");
    let file = dir.path().join("all.svg");
    let o = gen_rapid(&[
        "compare",
        cell.to_str().expect("utf-8"),
        "--grid",
        "5",
        "--svg",
        file.to_str().expect("utf-8"),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("note: the blocked nodes of the grid are drawn to"));
    let svg = Svg::read(&file);
    assert!(svg.labels("A").all(|l| l.attr("fill") == Some(FAILED)));
    assert_eq!(svg.labels("A").count(), 3);
    assert!(svg.labels("B").all(|l| l.attr("fill") == Some("#000000")));
    assert_eq!(rings(&svg).len(), 3);
}

#[test]
fn every_help_line_that_suggests_a_picture_names_one_that_is_drawn() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut checked = 0;
    for name in file_names(&root().join("tests/err")) {
        let Some(stem) = name.strip_suffix(".stderr") else {
            continue;
        };
        let text = read(&format!("tests/err/{name}"));
        let Some(help) = text
            .lines()
            .find(|l| l.starts_with("help:") && l.contains("--svg"))
        else {
            continue;
        };
        let cell = format!("tests/err/{stem}.yaml");
        let file = dir.path().join(format!("{stem}.svg"));
        let f = file.to_str().expect("utf-8");
        let args: Vec<&str> = if help.contains("`gen-rapid locate CELL --svg FILE`") {
            vec!["locate", &cell, "--svg", f]
        } else if help.contains("`gen-rapid --svg FILE`") {
            vec![&cell, "--svg", f]
        } else {
            panic!("{name}: a help line suggests a picture no test knows: {help}");
        };
        let o = gen_rapid(&args);
        assert!(!o.status.success() && o.stdout.is_empty(), "{args:?}");
        Svg::read(&file);
        checked += 1;
    }
    // no_path (a run) and base_auto_apart (locate).
    assert!(checked >= 2, "{checked}");
}
