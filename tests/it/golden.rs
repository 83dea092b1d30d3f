//! The golden harness, the one place fixtures are compared and refreshed. Every fixture found by
//! file name (`common/fixtures.rs`: `cells/<stem>.yaml` -> `tests/golden/<stem>.mod` and
//! `tests/golden/<stem>.<method>.mod`, `tests/ok/<stem>.yaml` -> `.mod`, `tests/err/<stem>.yaml`
//! -> `.stderr`) is run through the `gen-rapid` binary and must give its file byte for byte; a
//! module is planned twice and must give the same bytes both times. Every mismatch and every
//! fixture problem is collected and reported at once, each with a diff-like excerpt.
//!
//! Refresh every fixture after a deliberate change with
//! `GEN_RAPID_BLESS=1 cargo test --release --test it golden` (refused when `CI` is set), then
//! read every changed file before committing it.

use crate::common::fixtures::{discover, Case, Expect};
use crate::common::{bless_wanted, blessing, root, stderr};
use std::path::Path;
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// What the harness found.
struct Report {
    cases: usize,
    /// Fixture problems and mismatches, one message each.
    failures: Vec<String>,
    /// Files written by blessing.
    written: Vec<String>,
}

enum Outcome {
    Same,
    Written,
    Mismatch(String),
}

fn run(root: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gen-rapid"))
        .args(args)
        .current_dir(root)
        .output()
        .expect("the gen-rapid binary runs")
}

/// Runs one case in `root` and compares (or, blessing, writes) its file.
fn run_case(root: &Path, case: &Case, bless: bool) -> Outcome {
    let mut args = vec![case.cell.as_str()];
    args.extend(case.args.iter().map(String::as_str));
    let out = run(root, &args);
    let status = out.status.code().unwrap_or(-1);
    let actual = match case.expect {
        Expect::Module => {
            if !out.status.success() {
                return Outcome::Mismatch(format!(
                    "expected a module, but the run failed with exit {status}:\n{}",
                    stderr(&out)
                ));
            }
            let Ok(text) = String::from_utf8(out.stdout) else {
                return Outcome::Mismatch("the module is not UTF-8".into());
            };
            let again = run(root, &args);
            if again.stdout != text.as_bytes() {
                return Outcome::Mismatch(format!(
                    "a second run wrote different bytes:\n{}",
                    diff_excerpt(&text, &String::from_utf8_lossy(&again.stdout))
                ));
            }
            text
        }
        Expect::Failure => {
            if out.status.success() {
                return Outcome::Mismatch("expected a failure, but the run exited 0".into());
            }
            if !out.stdout.is_empty() {
                return Outcome::Mismatch(format!(
                    "stdout must stay empty on error, but got {} bytes",
                    out.stdout.len()
                ));
            }
            format!("exit: {status}\n{}", stderr(&out))
        }
    };
    let path = root.join(&case.expected);
    match std::fs::read_to_string(&path) {
        Ok(expected) if expected == actual => Outcome::Same,
        _ if bless => {
            std::fs::write(&path, &actual)
                .unwrap_or_else(|e| panic!("write {}: {e}", path.display()));
            Outcome::Written
        }
        Ok(expected) => Outcome::Mismatch(format!(
            "differs from the output:\n{}",
            diff_excerpt(&expected, &actual)
        )),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Outcome::Mismatch(
            "is missing: write it with GEN_RAPID_BLESS=1 and read it before committing".into(),
        ),
        Err(e) => Outcome::Mismatch(format!("cannot be read: {e}")),
    }
}

/// Discovers every case under `root`, runs them (on as many threads as there are cores) and
/// collects every problem and mismatch.
fn check_all(root: &Path, bless: bool) -> Report {
    let fixtures = discover(root);
    let cases = &fixtures.cases;
    let next = AtomicUsize::new(0);
    let outcomes = Mutex::new(Vec::with_capacity(cases.len()));
    let workers = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(cases.len());
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                let outcome = run_case(root, case, bless);
                outcomes
                    .lock()
                    .expect("no worker panicked")
                    .push((i, outcome));
            });
        }
    });
    let mut outcomes = outcomes.into_inner().expect("no worker panicked");
    outcomes.sort_by_key(|(i, _)| *i);
    let mut report = Report {
        cases: cases.len(),
        failures: fixtures
            .problems
            .iter()
            .map(|p| format!("fixture problem: {p}"))
            .collect(),
        written: vec![],
    };
    for (i, outcome) in outcomes {
        let case = &cases[i];
        match outcome {
            Outcome::Same => {}
            Outcome::Written => report.written.push(case.expected.clone()),
            Outcome::Mismatch(m) => report.failures.push(format!(
                "gen-rapid {} -> {}: {m}",
                case.command(),
                case.expected
            )),
        }
    }
    report
}

#[test]
fn every_fixture_gives_its_file() {
    let bless = blessing();
    let report = check_all(&root(), bless);
    if !report.written.is_empty() {
        eprintln!(
            "GEN_RAPID_BLESS=1 wrote {} file(s); read every one before committing it:\n  {}",
            report.written.len(),
            report.written.join("\n  ")
        );
    }
    assert!(
        report.failures.is_empty(),
        "golden: {} failure(s) in {} case(s):\n\n{}\n\nAfter a deliberate change of output: GEN_RAPID_BLESS=1 cargo test --release --test it golden (refused under CI), then read every changed file before committing it.",
        report.failures.len(),
        report.cases,
        report
            .failures
            .iter()
            .enumerate()
            .map(|(k, f)| format!("{}. {f}", k + 1))
            .collect::<Vec<_>>()
            .join("\n\n")
    );
}
/// A diff-like excerpt of where `actual` departs from `expected`: the differing lines (a
/// line diff), `-` expected and `+` actual, each run with two lines of context under
/// `@@ line N @@` (N: the line in the expected file); long excerpts are cut.
fn diff_excerpt(expected: &str, actual: &str) -> String {
    const CONTEXT: usize = 2;
    const MAX_LINES: usize = 60;
    let e: Vec<&str> = expected.split_inclusive('\n').collect();
    let a: Vec<&str> = actual.split_inclusive('\n').collect();
    // Longest common subsequence of lines (the files are a few hundred lines).
    let (n, m) = (e.len(), a.len());
    let mut lcs = vec![vec![0u32; m + 1]; n + 1];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            lcs[i][j] = if e[i] == a[j] {
                lcs[i + 1][j + 1] + 1
            } else {
                lcs[i + 1][j].max(lcs[i][j + 1])
            };
        }
    }
    // The edit script: (sign, line, line number in the expected file).
    let mut ops: Vec<(char, &str, usize)> = Vec::new();
    let (mut i, mut j) = (0, 0);
    while i < n || j < m {
        if i < n && j < m && e[i] == a[j] {
            ops.push((' ', e[i], i + 1));
            (i, j) = (i + 1, j + 1);
        } else if j == m || (i < n && lcs[i + 1][j] >= lcs[i][j + 1]) {
            ops.push(('-', e[i], i + 1));
            i += 1;
        } else {
            ops.push(('+', a[j], i + 1));
            j += 1;
        }
    }
    let show = |l: &str| -> String {
        let body = l.strip_suffix('\n');
        let text = body.unwrap_or(l);
        let text = if text.chars().any(|c| c.is_control() && c != '\t') {
            format!("{text:?}")
        } else {
            text.to_string()
        };
        match body {
            Some(_) => text,
            None => format!("{text}    (no newline at end of file)"),
        }
    };
    // Ops within CONTEXT of a change are shown; a gap starts a new hunk.
    let changed: Vec<usize> = (0..ops.len()).filter(|&k| ops[k].0 != ' ').collect();
    let shown = |k: usize| {
        changed
            .iter()
            .any(|&c| c.saturating_sub(CONTEXT) <= k && k <= c + CONTEXT)
    };
    let mut out = String::new();
    let mut lines = 0;
    let mut last: Option<usize> = None;
    for (k, (sign, line, number)) in ops.iter().enumerate() {
        if !shown(k) {
            continue;
        }
        if lines == MAX_LINES {
            out += "... (more differences)\n";
            break;
        }
        if last.is_none_or(|l| l + 1 != k) {
            out += &format!("@@ line {number} @@\n");
        }
        out += &format!("{sign} {}\n", show(line));
        lines += 1;
        last = Some(k);
    }
    out
}

#[test]
fn the_diff_excerpt_shows_each_changed_run_with_context() {
    let e = "a\nb\nc\nd\ne\nf\n";
    assert_eq!(
        diff_excerpt(e, "a\nb\nc\nX\ne\nf\n"),
        "@@ line 2 @@\n  b\n  c\n- d\n+ X\n  e\n  f\n"
    );
    // Two changes far apart: two hunks, not everything between them.
    let e: String = (1..=20).map(|k| format!("{k}\n")).collect();
    let a = e.replace("\n3\n", "\nthree\n").replace("\n18\n", "\n");
    assert_eq!(
        diff_excerpt(&e, &a),
        "@@ line 1 @@\n  1\n  2\n- 3\n+ three\n  4\n  5\n@@ line 16 @@\n  16\n  17\n- 18\n  19\n  20\n"
    );
    // A missing final newline, an inserted line and a carriage return are visible.
    assert_eq!(
        diff_excerpt("a\nb\n", "a\nb"),
        "@@ line 1 @@\n  a\n- b\n+ b    (no newline at end of file)\n"
    );
    assert_eq!(
        diff_excerpt("a\nc\n", "a\nb\nc\n"),
        "@@ line 1 @@\n  a\n+ b\n  c\n"
    );
    assert!(diff_excerpt("x\r\n", "x\n").contains("- \"x\\r\""));
    assert_eq!(diff_excerpt("same\n", "same\n"), "");
}

/// A scratch repository root for the harness's own tests: `files` are (path, text) pairs;
/// `URDF` in a text becomes the bundled robot's absolute path.
fn scratch(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = root().join("robots/irb1400.urdf");
    for d in ["cells", "tests/golden", "tests/ok", "tests/err"] {
        std::fs::create_dir_all(dir.path().join(d)).expect("mkdir");
    }
    for (path, text) in files {
        let text = text.replace("URDF", &urdf.display().to_string());
        std::fs::write(dir.path().join(path), text).expect("write");
    }
    dir
}

#[test]
fn the_harness_refuses_fixtures_without_partners_and_unknown_methods() {
    let dir = scratch(&[
        ("cells/a.yaml", ""),
        ("tests/golden/a.mod", ""),
        ("tests/golden/a.depth-first.mod", ""),
        ("tests/golden/a.sideways.mod", ""),
        ("tests/golden/b.mod", ""),
        ("tests/golden/notes.txt", ""),
        ("tests/err/c.stderr", ""),
        ("tests/err/d.yaml", ""),
    ]);
    let f = discover(dir.path());
    let cases: Vec<(String, String)> = f
        .cases
        .iter()
        .map(|c| (c.command(), c.expected.clone()))
        .collect();
    assert_eq!(
        cases,
        [
            ("tests/err/d.yaml", "tests/err/d.stderr"),
            (
                "cells/a.yaml --planner depth-first",
                "tests/golden/a.depth-first.mod"
            ),
            ("cells/a.yaml", "tests/golden/a.mod"),
        ]
        .map(|(a, b)| (a.to_string(), b.to_string()))
    );
    let expected = [
        "tests/golden/a.sideways.mod: 'sideways' is not a method",
        "tests/golden/b.mod has no cell cells/b.yaml",
        "tests/golden/notes.txt: not a fixture",
        "no case found in tests/ok",
        "tests/err/c.stderr has no cell tests/err/c.yaml",
    ];
    for e in expected {
        assert!(
            f.problems.iter().any(|p| p.starts_with(e)),
            "no problem '{e}' in {:#?}",
            f.problems
        );
    }
    assert_eq!(f.problems.len(), expected.len(), "{:#?}", f.problems);
    assert!(bless_wanted(Some("1"), true).is_err(), "refused under CI");
    assert_eq!(bless_wanted(Some("1"), false), Ok(true));
    assert_eq!(bless_wanted(Some("0"), false), Ok(false));
    assert_eq!(bless_wanted(None, true), Ok(false));
}

#[test]
fn the_harness_reports_every_mismatch_and_blessing_refreshes_them_all() {
    let cell = "module: Demo\nrobot: { urdf: URDF, base: [0, 0, 0] }\nobstacles: []\npoints:\n  - { name: P, joints: [0, 0, 0] }\n  - { name: Q, joints: [20, 10, 0] }\nplanner: { grid: 10 }\n";
    let dir = scratch(&[
        ("cells/demo.yaml", cell),
        ("tests/golden/demo.mod", "MODULE Wrong\n"),
        ("tests/golden/demo.depth-first.mod", "stale\n"),
        ("tests/ok/edge.yaml", cell),
        ("tests/err/bad.yaml", "module: [\n"),
        ("tests/err/bad.stderr", "exit: 1\nsomething else\n"),
    ]);
    let report = check_all(dir.path(), false);
    assert_eq!(report.cases, 4);
    let f = &report.failures;
    assert_eq!(f.len(), 4, "every mismatch, not only the first: {f:#?}");
    assert!(f[0].starts_with("gen-rapid tests/err/bad.yaml -> tests/err/bad.stderr: differs from the output:\n@@ line 1 @@\n  exit: 1\n- something else\n+ error: "), "{}", f[0]);
    assert!(f[1].contains("cells/demo.yaml --planner depth-first -> tests/golden/demo.depth-first.mod: differs from the output:\n@@ line 1 @@\n- stale\n+ MODULE Demo\n"), "{}", f[1]);
    assert!(
        f[2].contains("-> tests/golden/demo.mod: differs")
            && f[2].contains("- MODULE Wrong\n+ MODULE Demo\n"),
        "{}",
        f[2]
    );
    assert!(f[3].contains("tests/ok/edge.mod: is missing"), "{}", f[3]);
    assert!(report.written.is_empty());
    // Blessing writes all four; then everything matches.
    let report = check_all(dir.path(), true);
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.written.len(), 4, "{:?}", report.written);
    let report = check_all(dir.path(), false);
    assert!(report.failures.is_empty() && report.written.is_empty());
    let dfs = std::fs::read_to_string(dir.path().join("tests/golden/demo.depth-first.mod"))
        .expect("written");
    assert!(
        dfs.starts_with("MODULE Demo\n") && dfs.contains("! planner: depth-first\n"),
        "{dfs}"
    );
    let err = std::fs::read_to_string(dir.path().join("tests/err/bad.stderr")).expect("written");
    assert!(err.starts_with("exit: 1\nerror: "), "{err}");
}
