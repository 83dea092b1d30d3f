//! The command line end to end: what goes to stdout, stderr and files, and the exit statuses.

use crate::common::module::Module;
use crate::common::{arg, gen_rapid, read, root, stderr, stdout, METHODS};
use std::path::Path;

#[test]
fn help_teaches_the_format_examples_and_exit_statuses() {
    let o = gen_rapid(&["--help"]);
    assert!(o.status.success());
    let h = stdout(&o);
    for needle in [
        "Examples:",
        "gen-rapid cells/trunk.yaml > trunk.mod",
        "--planner",
        "--grid",
        "Exit status",
        "extensile",
        "--html <FILE>",
        "--report <FILE>",
        "--template <FILE>",
        "--proc <NAME>",
        "--quiet",
        "progress bar",
        "motion.speed/zone/tool/proc",
    ] {
        assert!(h.contains(needle), "--help lacks '{needle}':\n{h}");
    }
    // The methods it offers are the ones the tests know (`common::METHODS`).
    let offered: Vec<&str> = h
        .lines()
        .skip_while(|l| !l.trim().starts_with("--planner"))
        .skip_while(|l| !l.trim().starts_with("Possible values:"))
        .skip(1)
        .map_while(|l| l.trim().strip_prefix("- "))
        .map(|l| l.split(':').next().unwrap_or_default())
        .collect();
    assert_eq!(offered, METHODS, "{h}");
}

#[test]
fn the_minimal_cell_in_help_plans_as_printed() {
    let h = stdout(&gen_rapid(&["--help"]));
    let cell: String = h
        .lines()
        .skip_while(|l| !l.starts_with("A minimal cell"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .map(|l| format!("{}\n", &l[2..]))
        .collect();
    assert!(cell.contains("points:"), "{h}");
    // Written where its relative URDF path holds: a directory beside robots/.
    let dir = root().join("target").join("help-cell");
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("demo.yaml");
    std::fs::write(&path, cell.replace("../robots/", "../../robots/")).expect("write");
    let o = gen_rapid(&[path.to_str().expect("utf-8")]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("MODULE Demo\n"));
}

#[test]
fn a_run_writes_the_module_to_stdout_and_one_summary_line_to_stderr() {
    let o = gen_rapid(&["cells/conveyor.yaml"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.starts_with("MODULE ConveyorPick\n") && text.ends_with("ENDMODULE\n"));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("moves") && err.contains("clearance"), "{err}");
}

#[test]
fn output_file_gets_the_same_bytes_and_stdout_stays_empty() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("out.mod");
    let o = gen_rapid(&[
        "cells/conveyor.yaml",
        "-o",
        file.to_str().expect("utf-8 path"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let written = std::fs::read(&file).expect("file written");
    assert_eq!(written, gen_rapid(&["cells/conveyor.yaml"]).stdout);
    // No temporary file is left beside it.
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .expect("dir")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name())
        .collect();
    assert_eq!(names.len(), 1, "{names:?}");
}

#[test]
fn on_error_nothing_is_written_and_an_existing_file_is_kept() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("out.mod");
    std::fs::write(&file, "previous\n").expect("write");
    let o = gen_rapid(&[
        "tests/err/no_path.yaml",
        "-o",
        file.to_str().expect("utf-8 path"),
    ]);
    assert_eq!(o.status.code(), Some(3), "planning failed: {}", stderr(&o));
    assert!(o.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&file).expect("kept"), "previous\n");
    let fresh = dir.path().join("fresh.mod");
    let o = gen_rapid(&[
        "tests/err/unknown_key.yaml",
        "-o",
        fresh.to_str().expect("utf-8 path"),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(!fresh.exists(), "no file on error");
}

#[test]
fn a_missing_cell_file_is_named() {
    let o = gen_rapid(&["cells/no_such_cell.yaml"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty());
    assert!(
        stderr(&o).contains("cells/no_such_cell.yaml"),
        "{}",
        stderr(&o)
    );
    // A directory is no cell either; both say what CELL is (the help line).
    let d = gen_rapid(&["cells"]);
    assert_eq!(d.status.code(), Some(1));
    assert!(d.stdout.is_empty());
    for e in [stderr(&o), stderr(&d)] {
        assert!(
            e.lines()
                .any(|l| l.starts_with("help: CELL is the path of a cell file")),
            "{e}"
        );
    }
}

#[test]
fn planner_and_grid_flags_override_the_cell() {
    let o = gen_rapid(&[
        "cells/conveyor.yaml",
        "--planner",
        "neighboring",
        "--grid",
        "3",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.contains("! planner: neighboring\n"), "{text}");
    assert!(text.contains("! grid (deg): 3.000\n"), "{text}");
}

#[test]
fn bad_flags_are_usage_errors() {
    for args in [
        vec!["cells/trunk.yaml", "--grid", "0.01"],
        vec!["cells/trunk.yaml", "--planner", "astar"],
        vec![],
    ] {
        let o = gen_rapid(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty());
    }
}

#[test]
fn a_cell_written_anywhere_finds_its_urdf_and_plans_depth_first() {
    // tests/ok/no_obstacles_depth_first.yaml copied outside the repository, naming the URDF by
    // absolute path: the same module, byte for byte (the header names the file, not its place).
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = root().join("robots/irb1400.urdf");
    let cell = read("tests/ok/no_obstacles_depth_first.yaml")
        .replace("../../robots/irb1400.urdf", &urdf.display().to_string());
    assert!(cell.contains(&urdf.display().to_string()));
    let path = dir.path().join("no_obstacles_depth_first.yaml");
    std::fs::write(&path, cell).expect("write");
    let o = gen_rapid(&[arg(&path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert_eq!(text, read("tests/ok/no_obstacles_depth_first.mod"));
    assert!(text.contains("! planner: depth-first"));
    assert!(
        text.contains("! min clearance (mm): none (no obstacles)"),
        "{text}"
    );
    // Axis steps only: P -> (10, 0, 0) -> Q, or the other way round; the shortcut pass then
    // joins P and Q in one move (no obstacles).
    assert!(text.contains("! moves: 1"), "{text}");
    let o = gen_rapid(&[arg(&path), "--no-shortcut"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("! moves: 2"), "{}", stdout(&o));
}

#[test]
fn a_picture_that_cannot_be_written_leaves_stdout_empty() {
    for args in [
        vec!["cells/conveyor.yaml", "--svg", "/nonexistent/dir/x.svg"],
        vec![
            "compare",
            "cells/conveyor.yaml",
            "--grid",
            "3",
            "--svg",
            "/nonexistent/dir/x.svg",
        ],
    ] {
        let o = gen_rapid(&args);
        assert_eq!(o.status.code(), Some(4), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}: stdout must stay empty");
        assert!(stderr(&o).contains("/nonexistent/dir/x.svg"));
    }
}

#[test]
fn a_run_writes_all_its_files_or_none() {
    let dir = tempfile::tempdir().expect("tempdir");
    let p = |name: &str| arg(&dir.path().join(name)).to_string();
    let (svg, report, html) = (p("route.svg"), p("run.json"), p("run.html"));
    // The module's FILE cannot be written (its directory is missing, or it is a directory):
    // before, the picture, page and report were in place already when the module failed.
    for module in [p("missing/x.mod"), arg(dir.path()).into()] {
        let o = gen_rapid(&[
            "tests/ok/tool_wobj_robtargets.yaml",
            "--svg",
            &svg,
            "--report",
            &report,
            "--html",
            &html,
            "-o",
            &module,
        ]);
        assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
        assert!(o.stdout.is_empty());
        assert!(stderr(&o).contains(&module), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("\nhelp: the file's directory must exist"),
            "{}",
            stderr(&o)
        );
        let left: Vec<_> = std::fs::read_dir(dir.path())
            .expect("dir")
            .map(|e| e.expect("entry").file_name())
            .collect();
        assert!(left.is_empty(), "{module}: left behind {left:?}");
    }
    // All of them can: all are written, and no temporary file stays.
    let module = p("x.mod");
    let o = gen_rapid(&[
        "tests/ok/tool_wobj_robtargets.yaml",
        "--svg",
        &svg,
        "--report",
        &report,
        "-o",
        &module,
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut left: Vec<_> = std::fs::read_dir(dir.path())
        .expect("dir")
        .map(|e| e.expect("entry").file_name().into_string().expect("utf-8"))
        .collect();
    left.sort();
    assert_eq!(left, ["route.svg", "run.json", "x.mod"]);
}

#[test]
fn an_output_naming_another_file_of_the_run_is_a_usage_error() {
    let dir = tempfile::tempdir().expect("tempdir");
    let cell = dir.path().join("cell.yaml");
    let text = read("tests/ok/tool_wobj_robtargets.yaml")
        .replace("../../robots/", &format!("{}/robots/", root().display()));
    std::fs::write(&cell, &text).expect("write");
    let cell = arg(&cell);
    let out = arg(&dir.path().join("out")).to_string();
    let dotted = dir.path().join(".").join("out");
    let dotted = arg(&dotted);
    for (args, flags) in [
        (vec![cell, "-o", cell], "--output"),
        (vec![cell, "--svg", &out, "--report", dotted], "--report"),
        (vec![cell, "--html", &out, "-o", &out], "--html"),
    ] {
        let o = gen_rapid(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty());
        assert!(
            stderr(&o).contains(&format!("error: {flags} ")),
            "{args:?}: {}",
            stderr(&o)
        );
    }
    assert_eq!(
        std::fs::read_to_string(cell).expect("cell"),
        text,
        "the cell is kept"
    );
    assert!(!Path::new(&out).exists());
}

#[test]
fn the_same_point_twice_is_one_move_that_stays_put() {
    // The golden harness holds the module to the output of tests/ok/same_point_twice.yaml.
    let text = read("tests/ok/same_point_twice.mod");
    assert!(
        text.contains("! moves: 1\n")
            && text.contains("! zoned vias: 0 of 0 ")
            && !text.contains("jointtarget via"),
        "{text}"
    );
    let m = Module::parse(&text).expect("module");
    assert_eq!(m.target("P1"), m.target("P2"), "{text}");
}

#[test]
fn the_tool_example_in_help_plans_as_printed() {
    // The minimal cell's module, robot and obstacles with --help's tool, work object and points.
    let h = stdout(&gen_rapid(&["--help"]));
    let block = |first: &str| -> String {
        h.lines()
            .skip_while(|l| !l.starts_with(first))
            .skip(1)
            .take_while(|l| l.starts_with("  "))
            .map(|l| format!("{}\n", &l[2..]))
            .collect()
    };
    let minimal = block("A minimal cell");
    let tcp = block("A tool, a work object");
    for key in [
        "tool:",
        "tframe:",
        "shapes:",
        "wobj:",
        "robtarget:",
        "speed:",
    ] {
        assert!(tcp.contains(key), "--help's tool example lacks {key}:\n{h}");
    }
    let head = &minimal[..minimal.find("points:").expect("points")];
    let dir = root().join("target").join("help-cell");
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("tcp.yaml");
    std::fs::write(
        &path,
        format!("{head}{tcp}").replace("../robots/", "../../robots/"),
    )
    .expect("write");
    let o = gen_rapid(&[arg(&path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.contains("PERS tooldata tTorch := [TRUE,"), "{text}");
    assert!(text.contains("CONST robtarget W2_rt := "), "{text}");
    assert!(
        text.contains("MoveJ W2_rt, v100, fine, tTorch\\WObj:=wobjDoor;"),
        "{text}"
    );
}

/// `--quiet` (and `-q`) leaves stderr empty on a cell without warnings; the module is the same
/// bytes as without it.
#[test]
fn quiet_drops_the_summary_line_and_nothing_else() {
    let loud = gen_rapid(&["cells/trunk.yaml", "--grid", "2"]);
    assert!(loud.status.success(), "{}", stderr(&loud));
    assert_eq!(stderr(&loud).lines().count(), 1, "{}", stderr(&loud));
    assert!(stderr(&loud).starts_with("gen-rapid: cells/trunk.yaml: "));
    for flag in ["--quiet", "-q"] {
        let quiet = gen_rapid(&["cells/trunk.yaml", "--grid", "2", flag]);
        assert!(quiet.status.success(), "{}", stderr(&quiet));
        assert_eq!(stderr(&quiet), "", "{flag}");
        assert_eq!(quiet.stdout, loud.stdout, "{flag} changed the module");
    }
    // An error still says why under --quiet.
    let failed = gen_rapid(&["tests/err/not_a_number.yaml", "--quiet"]);
    assert_eq!(failed.status.code(), Some(1));
    assert!(stderr(&failed).contains("error"), "{}", stderr(&failed));
    assert!(failed.stdout.is_empty());
}

/// Runs the binary under a pseudo-terminal (`script`), so that stderr is a terminal; `None`
/// (with a note) where `script` is missing.
fn under_a_terminal(args: &str, show_after_ms: &str) -> Option<String> {
    let bin = env!("CARGO_BIN_EXE_gen-rapid");
    let out = std::process::Command::new("script")
        .args(["-qec", &format!("'{bin}' {args}"), "/dev/null"])
        .env("GEN_RAPID_PROGRESS_AFTER_MS", show_after_ms)
        .current_dir(root())
        .output();
    match out {
        Ok(o) if o.status.success() => Some(String::from_utf8_lossy(&o.stdout).into_owned()),
        Ok(o) => panic!(
            "gen-rapid under script failed: {:?}\n{}",
            o.status,
            stdout(&o)
        ),
        Err(e) => {
            eprintln!("skipped: no `script` (util-linux) to give gen-rapid a terminal: {e}");
            None
        }
    }
}

/// On a terminal the bar shows the stages (here at once: the delay set to 0) and is cleared
/// before the summary line, which comes last; `--quiet` shows neither.
#[test]
fn a_terminal_gets_a_progress_bar_and_a_pipe_gets_none() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("trunk.mod");
    let args = format!("cells/trunk.yaml --grid 1 -o {}", arg(&out));
    let Some(seen) = under_a_terminal(&args, "0") else {
        return;
    };
    // Whichever stage the bar first shows (a fast run may be past the grid fill).
    let stages = [
        "placing the robot",
        "inspecting the grid",
        "planning and proving the moves",
        "writing the module",
    ];
    assert!(stages.iter().any(|s| seen.contains(s)), "{seen:?}");
    assert!(
        seen.contains("\u{1b}[2K"),
        "the bar is not cleared: {seen:?}"
    );
    let last = seen.rsplit(['\r', '\n']).find(|l| !l.trim().is_empty());
    let last = last.unwrap_or_default().trim_start_matches("\u{1b}[2K");
    assert!(
        last.starts_with("gen-rapid: cells/trunk.yaml: "),
        "{seen:?}"
    );
    assert!(last.contains(" moves"), "{seen:?}");
    let quiet = under_a_terminal(&format!("{args} --quiet"), "0");
    assert_eq!(quiet.as_deref().map(str::trim), Some(""));
    // A pipe: the same delay, no bar, only the summary line.
    let piped = std::process::Command::new(env!("CARGO_BIN_EXE_gen-rapid"))
        .args(["cells/trunk.yaml", "--grid", "1", "-o", arg(&out)])
        .env("GEN_RAPID_PROGRESS_AFTER_MS", "0")
        .current_dir(root())
        .output()
        .expect("gen-rapid runs");
    assert!(piped.status.success());
    let err = stderr(&piped);
    assert_eq!(err.lines().count(), 1, "{err:?}");
    assert!(!err.contains("inspecting"), "{err:?}");
}

/// Writes the conveyor's module (at 3 deg) to `path` with `-o`: exit 0.
fn module_to(path: &std::path::Path) {
    let o = gen_rapid(&["cells/conveyor.yaml", "--grid", "3", "-o", arg(path)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// An output that is not a file (a pipe here, as `/dev/null` or `/dev/stdout` on a pipe) is
/// written in place: the pipe stays a pipe and its reader gets the module (before, a run as
/// root renamed its temporary file over such a path: over `/dev/null` itself). A pipe made
/// in a temporary directory, so that a regression cannot replace a device of the machine.
#[test]
fn an_output_that_is_a_pipe_stays_a_pipe() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().expect("tempdir");
    let fifo = dir.path().join("module.pipe");
    match std::process::Command::new("mkfifo").arg(&fifo).status() {
        Ok(s) if s.success() => {}
        _ => {
            eprintln!("skipped: no mkfifo on this machine");
            return;
        }
    }
    let (tx, rx) = std::sync::mpsc::channel();
    let reader = fifo.clone();
    std::thread::spawn(move || {
        let _ = tx.send(std::fs::read_to_string(&reader));
    });
    module_to(&fifo);
    let kind = std::fs::symlink_metadata(&fifo).expect("pipe").file_type();
    assert!(kind.is_fifo(), "the pipe was replaced by {kind:?}");
    // (A guard against a hang, not a timing: the reader has the module once the run is done.)
    let read = rx
        .recv_timeout(std::time::Duration::from_secs(60))
        .expect("the reader ends")
        .expect("read");
    assert!(read.starts_with("MODULE "), "{read}");
}

/// No output overwrites a file the run reads: the robot's URDF (known once the cell is read:
/// exit 4, the URDF intact), or the cell itself through `locate --svg` or `compare --svg`
/// (exit 2, as the plain run's `-o CELL`). Before, all three wrote over their input.
#[test]
fn no_output_overwrites_an_input() {
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = dir.path().join("arm.urdf");
    std::fs::copy("robots/irb1400.urdf", &urdf).expect("urdf");
    std::fs::copy(
        "robots/irb1400.controller.yaml",
        dir.path().join("arm.controller.yaml"),
    )
    .expect("controller");
    let cell = dir.path().join("cell.yaml");
    let text = std::fs::read_to_string("cells/conveyor.yaml")
        .expect("cell")
        .replace("../robots/irb1400.urdf", "arm.urdf");
    assert!(text.contains("urdf: arm.urdf"), "the cell names the URDF");
    std::fs::write(&cell, &text).expect("cell");
    let (urdf_s, cell_s) = (arg(&urdf), arg(&cell));
    let o = gen_rapid(&[cell_s, "--grid", "3", "-o", urdf_s]);
    assert_eq!(o.status.code(), Some(4), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    assert!(
        stderr(&o).contains("it is a file the run reads"),
        "{}",
        stderr(&o)
    );
    let kept = std::fs::read("robots/irb1400.urdf").expect("urdf");
    assert_eq!(
        std::fs::read(&urdf).expect("urdf"),
        kept,
        "the URDF overwritten"
    );
    // The controller file beside the URDF (not named in the cell), and the pictures of
    // `locate` and `compare` onto the URDF: refused alike.
    let controller = dir.path().join("arm.controller.yaml");
    let controller_s = arg(&controller);
    let controller_text = std::fs::read("robots/irb1400.controller.yaml").expect("controller");
    for args in [
        vec![cell_s, "--grid", "3", "-o", controller_s],
        vec!["locate", cell_s, "--svg", urdf_s],
        vec!["compare", cell_s, "--grid", "3", "--svg", urdf_s],
    ] {
        let o = gen_rapid(&args);
        assert_eq!(o.status.code(), Some(4), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}");
        assert!(
            stderr(&o).contains("it is a file the run reads"),
            "{}",
            stderr(&o)
        );
        assert_eq!(std::fs::read(&urdf).expect("urdf"), kept, "{args:?}");
        assert_eq!(
            std::fs::read(&controller).expect("c"),
            controller_text,
            "{args:?}"
        );
    }
    for command in ["locate", "compare"] {
        let o = gen_rapid(&[command, cell_s, "--svg", cell_s]);
        assert_eq!(o.status.code(), Some(2), "{command}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("names the same file as CELL"),
            "{}",
            stderr(&o)
        );
        assert_eq!(
            std::fs::read_to_string(&cell).expect("cell"),
            text,
            "{command}"
        );
    }
}

/// An output that is a link to a file (as `/dev/stdout` is when stdout goes to a file) writes
/// the file it leads to and keeps the link (before, the rename replaced the link itself).
#[test]
fn an_output_that_is_a_link_writes_the_file_it_leads_to() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (file, link) = (dir.path().join("out.mod"), dir.path().join("link.mod"));
    std::fs::write(&file, "old").expect("file");
    std::os::unix::fs::symlink(&file, &link).expect("symlink");
    module_to(&link);
    let kept = std::fs::symlink_metadata(&link).expect("link");
    assert!(kept.file_type().is_symlink(), "the link was replaced");
    let written = std::fs::read_to_string(&file).expect("file");
    assert!(written.starts_with("MODULE "), "{written}");
}

#[test]
fn robots_lists_the_shipped_models_as_text_and_json() {
    let names = [
        "irb1400",
        "irb120_3_58",
        "irb1200_5_90",
        "irb1600_8_145",
        "irb2400_12_155",
        "irb2600_12_165",
        "irb4600_60_205",
    ];
    let o = gen_rapid(&["robots"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for n in names {
        assert!(
            text.contains(&format!("\n{n}: ")) || text.starts_with(&format!("{n}: ")),
            "{n}:\n{text}"
        );
    }
    assert!(
        text.contains("irb2400_12_155: ABB IRB 2400-12/1.55, reach 1550.0 mm, parallelogram"),
        "{text}"
    );
    assert!(
        text.contains("  axis 3 - axis 2: -60 .. 65 deg (the coupled range)"),
        "{text}"
    );
    assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
    let o = gen_rapid(&["robots", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let list: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    let list = list.as_array().expect("an array");
    assert_eq!(
        list.iter()
            .map(|r| r["model"].as_str().unwrap_or(""))
            .collect::<Vec<_>>(),
        names
    );
    for r in list {
        assert_eq!(r["axes"].as_array().map(Vec::len), Some(6), "{r}");
        assert!(r["reach_mm"].as_f64().is_some_and(|x| x > 500.0), "{r}");
    }
    assert_eq!(list[6]["reach_mm"].as_f64(), Some(2050.8));
    assert_eq!(list[6]["axes"][4]["min_deg"].as_f64(), Some(-120.0));
    // A subcommand reads no cell: a stray argument is a usage error.
    let o = gen_rapid(&["robots", "cells/trunk.yaml"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}
