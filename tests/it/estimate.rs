//! The time estimate through the command line: the speeddata changes it, `vmax` and
//! an unknown speeddata give the axes alone (the latter with one warning per name), a zoned cell
//! point is flown through, and the header, the summary line and the report agree on the time,
//! the zoned vias and the paper's method alone. Lower bounds are computed here from the
//! report's TCP positions (a chord is never longer than the TCP's path).

use crate::common::{arg, gen_rapid, read, stderr, stdout, temp_cell};
use serde_json::Value;

/// The trunk cell with `edit` applied, planned on a 2 deg grid by the paper's method alone
/// (`--no-shortcut`: the route does not depend on the speed): (module, report, stderr).
fn trunk(edit: impl Fn(String) -> String) -> (String, Value, String) {
    trunk_with(&["--no-shortcut"], edit)
}

/// [`trunk`] with the command line's `flags`.
fn trunk_with(flags: &[&str], edit: impl Fn(String) -> String) -> (String, Value, String) {
    let dir = tempfile::tempdir().expect("tempdir");
    let body = edit(read("cells/trunk.yaml").replace("../robots/irb1400.urdf", "URDF"));
    let cell = temp_cell(dir.path(), "trunk.yaml", &body);
    let report = dir.path().join("report.json");
    let mut args = vec![arg(&cell), "--grid", "2", "--report", arg(&report)];
    args.extend_from_slice(flags);
    let o = gen_rapid(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let json = std::fs::read_to_string(&report).expect("report");
    (
        stdout(&o),
        serde_json::from_str(&json).expect("JSON"),
        stderr(&o),
    )
}

fn with_speed(speed: &'static str) -> impl Fn(String) -> String {
    move |t: String| {
        assert!(t.contains("speed: v300"));
        t.replace("speed: v300", &format!("speed: {speed}"))
    }
}

/// The header's value after `key`.
fn header<'a>(module: &'a str, key: &str) -> &'a str {
    module
        .lines()
        .find_map(|l| l.trim().strip_prefix(&format!("! {key}: ")))
        .unwrap_or_else(|| panic!("no '{key}' in the header"))
}

fn time(module: &str) -> f64 {
    header(module, "estimated time (s)")
        .parse()
        .expect("a number")
}

fn xyz(v: &Value) -> [f64; 3] {
    std::array::from_fn(|k| v[k].as_f64().expect("a number"))
}

/// The sum of the straight distances between the TCP positions of consecutive waypoints, mm.
fn chords_mm(report: &Value) -> f64 {
    let w = report["waypoints"].as_array().expect("waypoints");
    w.windows(2)
        .map(|p| {
            let (a, b) = (xyz(&p[0]["tcp_mm"]), xyz(&p[1]["tcp_mm"]));
            (0..3).map(|k| (b[k] - a[k]).powi(2)).sum::<f64>().sqrt()
        })
        .sum()
}

fn limits(report: &Value) -> Vec<String> {
    report["moves"]
        .as_array()
        .expect("moves")
        .iter()
        .map(|m| m["limit"].as_str().expect("a limit").to_string())
        .collect()
}

#[test]
fn the_speeddata_sets_the_estimate_and_vmax_leaves_the_axes_alone() {
    let (m100, r100, _) = trunk(with_speed("v100"));
    let (m1000, r1000, _) = trunk(with_speed("v1000"));
    let (mmax, rmax, _) = trunk(with_speed("vmax"));
    let (t100, t1000, tmax) = (time(&m100), time(&m1000), time(&mmax));
    assert!(t100 > t1000 && t1000 >= tmax, "{t100} {t1000} {tmax}");
    // The same route each time: the speed changes the time, not the path.
    assert_eq!(chords_mm(&r100), chords_mm(&rmax));
    // At v100 no move is faster than its TCP chord at 100 mm/s (the TCP's path is longer).
    let chords = chords_mm(&r100);
    assert!(chords > 1000.0, "{chords}");
    assert!(t100 >= chords / 100.0 - 0.005, "{t100} < {chords} / 100");
    assert!(limits(&r100).iter().all(|l| l == "tcp"), "{r100}");
    // At vmax (5000 mm/s, not reached by an IRB 1400) the axes lead every move.
    assert!(limits(&rmax).iter().all(|l| l == "axis"), "{rmax}");
    // The per-move times add up to the total, as the header states it.
    for (m, r) in [(&m100, &r100), (&m1000, &r1000), (&mmax, &rmax)] {
        let sum: f64 = r["moves"]
            .as_array()
            .expect("moves")
            .iter()
            .map(|m| m["time_s"].as_f64().expect("time"))
            .sum();
        let moves = r["totals"]["moves"].as_f64().expect("moves");
        assert!(
            (sum - time(m)).abs() <= 0.005 * moves + 1e-9,
            "{sum} vs {}",
            time(m)
        );
        assert_eq!(r["totals"]["estimated_time_s"].as_f64(), Some(time(m)));
    }
}

#[test]
fn an_unknown_speeddata_warns_once_and_takes_the_axes_alone() {
    let (mmax, _, quiet) = trunk(with_speed("vmax"));
    assert!(!quiet.contains("warning"), "{quiet}");
    // The cell's speed and one point's, the same name in another case: one warning.
    let (m, r, err) = trunk(|t| {
        with_speed("vMine")(t).replace(
            "{ name: C, joints: [25, 15, 10] }",
            "{ name: C, joints: [25, 15, 10], speed: VMINE }",
        )
    });
    let warnings: Vec<&str> = err.lines().filter(|l| l.contains("warning")).collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(
        warnings[0].contains("speed 'vMine' is not a predefined speeddata")
            && warnings[0].contains("full axis speed"),
        "{err}"
    );
    assert_eq!(time(&m), time(&mmax));
    assert!(limits(&r).iter().all(|l| l == "axis"), "{r}");
    // The module still names the speed as the cell gives it.
    assert!(m.contains(", vMine, fine, tool0;") && m.contains(", VMINE, fine, tool0;"));
}

#[test]
fn a_zoned_cell_point_is_flown_through() {
    let zoned = |t: String| {
        ["B", "C", "D", "E"].iter().fold(t, |t, p| {
            let at = format!("{{ name: {p}, joints: [");
            assert!(t.contains(&at));
            let start = t.find(&at).expect("point");
            let end = start + t[start..].find('}').expect("closing brace");
            format!("{}, zone: z50 {}", &t[..end], &t[end..])
        })
    };
    let (fine, rf, _) = trunk(|t| t);
    let (fly, rz, _) = trunk(zoned);
    // The same route, the four middle points flown through: strictly faster, and no move slower.
    assert_eq!(chords_mm(&rf), chords_mm(&rz));
    assert!(time(&fly) < time(&fine), "{} {}", time(&fly), time(&fine));
    let per_move = |r: &Value| -> Vec<f64> {
        r["moves"]
            .as_array()
            .expect("moves")
            .iter()
            .map(|m| m["time_s"].as_f64().expect("time"))
            .collect()
    };
    for (a, b) in per_move(&rz).iter().zip(per_move(&rf)) {
        assert!(*a <= b, "{a} > {b}");
    }
    assert!(
        fly.contains("MoveAbsJ B\\NoEOffs, v300, z50, tool0;"),
        "{fly}"
    );
    // The last point always stops: a zone there changes nothing.
    let (last, _, _) = trunk(|t| {
        t.replace(
            "{ name: F, joints: [-90, 0, 0] }",
            "{ name: F, joints: [-90, 0, 0], zone: z50 }",
        )
    });
    assert_eq!(time(&last), time(&fine));
}

#[test]
fn header_summary_and_report_state_the_zoned_vias_and_the_papers_method() {
    // With the shortcut (the default), a leg whose straight move is proven goes straight
    // without the grid (the trunk's B -> C and D -> E): the paper's method did not run, and
    // neither the header, the summary nor the report states a figure for it.
    let (shortcut, short_report, err) = trunk_with(&[], |t| t);
    assert!(!shortcut.contains("the paper's method alone"), "{shortcut}");
    assert!(!err.contains("the paper's method alone"), "{err}");
    assert!(short_report["totals"]["paper_method"].is_null());
    // The trunk without C and E: every leg needs the grid. The paper's figure is the route
    // before the shortcut: the same figure the paper's method alone gives as its own time,
    // and never less than the result.
    let no_straight = |t: String| {
        let kept: Vec<&str> = (t.lines())
            .filter(|l| !l.contains("name: C,") && !l.contains("name: E,"))
            .collect();
        assert_eq!(
            kept.len() + 2,
            t.lines().count(),
            "the trunk's points C and E"
        );
        kept.join("\n") + "\n"
    };
    let (alone, ..) = trunk(no_straight);
    let (shortcut, short_report, _) = trunk_with(&[], no_straight);
    let paper = header(&shortcut, "the paper's method alone");
    let alone_figure = format!(
        "{} moves, {} s",
        header(&alone, "moves"),
        header(&alone, "estimated time (s)")
    );
    assert_eq!(paper, alone_figure);
    let paper_s: f64 = paper
        .trim_end_matches(" s")
        .rsplit(' ')
        .next()
        .and_then(|t| t.parse().ok())
        .expect("a time");
    assert!(time(&shortcut) <= paper_s, "{shortcut}");
    let paper_moves = short_report["totals"]["paper_method"]["moves"].as_u64();
    assert!(paper_moves >= short_report["totals"]["moves"].as_u64());
    // The paper's method alone: its own figure.
    let (module, report, err) = trunk(|t| t);
    let vias = report["totals"]["vias"].as_u64().expect("vias");
    let zoned = format!("0 of {vias} (via zone fine)");
    assert_eq!(header(&module, "zoned vias"), zoned);
    let moves = report["totals"]["moves"].as_u64().expect("moves");
    let t = header(&module, "estimated time (s)");
    // Today the route is the paper's method's: the same moves and time.
    let paper = format!("{moves} moves, {t} s");
    assert_eq!(header(&module, "the paper's method alone"), paper);
    let summary = err.lines().last().expect("summary line");
    assert!(
        summary.contains(&format!("zoned vias: {zoned}")),
        "{summary}"
    );
    assert!(
        summary.contains(&format!("the paper's method alone: {paper}")),
        "{summary}"
    );
    assert_eq!(report["totals"]["zoned_vias"]["zoned"], 0);
    assert_eq!(report["totals"]["zoned_vias"]["vias"].as_u64(), Some(vias));
    assert_eq!(report["totals"]["zoned_vias"]["via_zone"], "fine");
    assert_eq!(
        report["totals"]["paper_method"]["moves"].as_u64(),
        Some(moves)
    );
    assert_eq!(
        report["totals"]["paper_method"]["time_s"].as_f64(),
        t.parse::<f64>().ok()
    );
}
