//! Hostile input end to end: output devices that fail (a full stdout or stderr, a closed
//! stdout or pipe), outputs that name one file twice under two spellings, warnings that would
//! bury the error, budgets passed, and a run under a 4 GB memory cap. Each refusal: the right
//! exit status, at most 20 lines and 4 KB of stderr, nothing on stdout, no file left.

use crate::common::{arg, gen_rapid, root, stderr};
use std::path::Path;
use std::process::{Command, Stdio};

/// The binary with its stdio set by the caller, from the project's root.
fn command(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gen-rapid"));
    c.args(args).current_dir(root());
    c
}

/// A refusal's stderr is short: at most 20 lines and 4 KB.
fn short(err: &str) {
    assert!(
        err.lines().count() <= 20 && err.len() <= 4096,
        "{} lines, {} bytes:\n{err}",
        err.lines().count(),
        err.len()
    );
}

/// The files left in `dir`.
fn left(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

const CELL: &str = "tests/ok/tool_wobj_robtargets.yaml";

#[test]
fn a_full_stderr_fails_the_run_and_leaves_no_file() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        eprintln!("skipped: no /dev/full on this machine");
        return;
    };
    let dir = tempfile::tempdir().expect("tempdir");
    let module = dir.path().join("x.mod");
    // Before: a panic (exit 101) writing the summary line, after the module was in place.
    let o = command(&[
        CELL,
        "-o",
        arg(&module),
        "--svg",
        arg(&dir.path().join("x.svg")),
    ])
    .stderr(full)
    .output()
    .expect("runs");
    assert_eq!(o.status.code(), Some(4));
    assert!(left(dir.path()).is_empty(), "{:?}", left(dir.path()));
    // With --quiet nothing goes to stderr: the run succeeds.
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("full");
    // (A cell whose run warns of nothing: a warning that cannot be written fails the run too.)
    let o = command(&["cells/trunk.yaml", "-q", "-o", arg(&module)])
        .stderr(full)
        .output()
        .expect("runs");
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(left(dir.path()), ["x.mod"]);
}

#[test]
fn a_full_or_closed_stdout_fails_the_run_and_leaves_no_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let svg = dir.path().join("x.svg");
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        // Before: the picture was in place when the module failed on stdout.
        let o = command(&["cells/trunk.yaml", "--svg", arg(&svg)])
            .stdout(full)
            .output()
            .expect("runs");
        assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
        let err = stderr(&o);
        assert!(err.starts_with("error: cannot write <stdout>: "), "{err}");
        assert!(!err.contains("gen-rapid: "), "no summary line: {err}");
        short(&err);
        assert!(left(dir.path()).is_empty(), "{:?}", left(dir.path()));
    }
    // A pipe whose reader is gone: an error, not a signal or a panic.
    let mut child = command(&[CELL, "--svg", arg(&svg)])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    drop(child.stdout.take());
    let o = child.wait_with_output().expect("ends");
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    assert!(left(dir.path()).is_empty(), "{:?}", left(dir.path()));
    // stdout closed (`>&-`): before, the module went to /dev/null (the runtime opens it there)
    // and the run exited 0. Closed by a shell, as a user closes it.
    let sh = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "exec >&- ; {} {CELL}",
            env!("CARGO_BIN_EXE_gen-rapid")
        ))
        .current_dir(root())
        .output();
    if let Ok(o) = sh {
        assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
        let err = stderr(&o);
        assert!(err.contains("stdout is closed"), "{err}");
        short(&err);
    }
    // `--help` to a full stdout: exit 4, not 0.
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        let o = command(&["--help"]).stdout(full).output().expect("runs");
        assert_eq!(o.status.code(), Some(4));
    }
}

#[test]
fn two_spellings_of_one_new_file_are_a_usage_error() {
    let dir = tempfile::tempdir().expect("tempdir");
    std::fs::create_dir(dir.path().join("d")).expect("d");
    let (a, b) = (
        dir.path().join("d/../a.svg"),
        dir.path().join(".").join("a.svg"),
    );
    // Before: both "succeeded" and the report overwrote the picture.
    let o = gen_rapid(&[CELL, "--svg", arg(&a), "--report", arg(&b)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("names the same file as --svg"),
        "{}",
        stderr(&o)
    );
    assert_eq!(left(dir.path()), ["d"]);
    // A link to a file not yet written, and the file: one file.
    std::os::unix::fs::symlink(dir.path().join("c.json"), dir.path().join("l.json")).expect("link");
    let o = gen_rapid(&[
        CELL,
        "--report",
        arg(&dir.path().join("l.json")),
        "--html",
        arg(&dir.path().join("c.json")),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    // An output naming the file stdout goes to, while stdout takes the module.
    let out = dir.path().join("out.txt");
    let file = std::fs::File::create(&out).expect("out");
    let o = command(&[CELL, "--svg", arg(&out)])
        .stdout(file)
        .output()
        .expect("runs");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("names the file stdout goes to"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn forty_warnings_are_one_line_and_do_not_bury_the_error() {
    // Forty points with speeds of their own that RAPID does not predefine, and a point in
    // collision: before, 40 warning lines and then the error (46 lines, 8 KB).
    let dir = tempfile::tempdir().expect("tempdir");
    let mut text = format!(
        "module: Many\nrobot:\n  urdf: {}\n  base: [0, 0, 0]\nobstacles:\n  - {{ name: table, box: {{ min: [600, -300, 0], max: [1000, 300, 400] }} }}\npoints:\n",
        root().join("robots/irb1400.urdf").display()
    );
    for i in 0..40 {
        text += &format!(
            "  - {{ name: P{i}, joints: [{}, 0, 0], speed: vSpeed{i} }}\n",
            i - 20
        );
    }
    text += "  - { name: Hit, joints: [0, 60, 50] }\n";
    let path = crate::common::temp_cell(dir.path(), "many.yaml", &text);
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let err = stderr(&o);
    short(&err);
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning: ")).collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(
        warnings[0].contains("'vSpeed0'")
            && warnings[0].contains("(and 39 more like it: 'vSpeed1', 'vSpeed2', 'vSpeed3', ...)"),
        "{err}"
    );
    assert_eq!(err.matches("error: ").count(), 1, "{err}");
}

#[test]
fn budgets_are_refused_at_the_item_that_passes_them() {
    let dir = tempfile::tempdir().expect("tempdir");
    // 3 000 points: more than a run takes, refused at the 2 001st (before: 55 s of planning).
    let mut text = format!(
        "module: Many\nrobot:\n  urdf: {}\n  base: [0, 0, 0]\npoints:\n",
        root().join("robots/irb1400.urdf").display()
    );
    for i in 0..3000 {
        text += &format!(
            "  - {{ name: P{i}, joints: [{}, 0, 0] }}\n",
            (i % 2) * 60 - 30
        );
    }
    let path = crate::common::temp_cell(dir.path(), "many.yaml", &text);
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    short(&err);
    assert!(
        err.contains("the cell gives 3000 points, more than the 2000"),
        "{err}"
    );
    assert!(err.contains("many.yaml:2006:5"), "{err}");
    // The legs' budget: 600 points at 0.25 deg (413 M nodes a leg, 145 legs at most).
    let six_hundred: String = text
        .lines()
        .take(5 + 600)
        .map(|l| format!("{l}\n"))
        .collect();
    let path = crate::common::temp_cell(dir.path(), "six.yaml", &six_hundred);
    let o = gen_rapid(&[arg(&path), "--grid", "0.25"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("passes the planning budget"),
        "{}",
        stderr(&o)
    );
    // With --grid 3, 600 points fit: the same cell plans.
    let o = gen_rapid(&[arg(&path), "--grid", "3", "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // 250 001 YAML nodes: said as the reader's budget, at its place, with a help line.
    let mut big =
        String::from("module: Big\nrobot: { urdf: r.urdf, base: [0, 0, 0] }\nobstacles:\n");
    for i in 0..20_000 {
        big += &format!(
            "  - {{ name: o{i}, box: {{ min: [0, 0, {i}], max: [1, 1, {}] }} }}\n",
            i + 1
        );
    }
    let path = crate::common::temp_cell(dir.path(), "big.yaml", &big);
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    short(&err);
    assert!(
        err.starts_with(
            "error: the cell file passes the YAML reader's budget: more than 250000 YAML nodes"
        ),
        "{err}"
    );
    assert!(
        err.contains("\nhelp: a cell file holds at most 250000 YAML nodes"),
        "{err}"
    );
}

/// Runs `sh -c SCRIPT` with a 4 GB address-space cap (`ulimit -v`); `None` where there is no
/// shell to do it.
fn capped(script: &str) -> Option<std::process::Output> {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v 4000000 && {script}"))
        .current_dir(root())
        .output()
        .ok()
}

#[test]
fn under_a_4_gb_memory_cap_wide_ranges_are_refused_and_the_finest_grid_runs() {
    let bin = env!("CARGO_BIN_EXE_gen-rapid");
    // Axes 1..3 over -720 .. 720 deg at 0.25 deg: 191 G nodes (before: an abort allocating
    // them). Refused before the grid is made.
    let Some(o) = capped(&format!("{bin} tests/err/budget_grid_fine.yaml")) else {
        eprintln!("skipped: no sh");
        return;
    };
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    // The widest grid the budget allows over those ranges plans under the cap.
    let o = capped(&format!(
        "{bin} tests/err/budget_grid_default.yaml --grid 1.82 -q"
    ))
    .expect("sh");
    assert!(
        matches!(o.status.code(), Some(0) | Some(3)),
        "{:?}: {}",
        o.status,
        stderr(&o)
    );
    // The paper's cell at the finest accepted grid: 413 M nodes, within the cap.
    let o = capped(&format!("{bin} cells/trunk.yaml --grid 0.25 -q")).expect("sh");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}
