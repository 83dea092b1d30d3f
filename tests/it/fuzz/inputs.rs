//! The fuzz target beyond the cell file: the robot files (URDF and controller file), the
//! user's module template, and the command line. Seeded and deterministic like the cell's
//! cases; each case must end without a panic, in an `Ok` or a refusal with the right exit
//! status and a message of at most [`super::MAX_MESSAGE_BYTES`] (the controller file's located
//! in the controller file, the template's in the template). The command line runs the binary
//! (a panic there is exit 101, an abort 134): every exit status is one of 0..4, and a refusal
//! leaves stdout empty and stderr short.

use super::edits::{mutate_bytes, mutate_lines};
use super::{env_u64, MAX_MESSAGE_BYTES};
use crate::common::library::{robot_from_texts, Refusal, TemplateBench};
use crate::common::root;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// Cases of each kind run by `cargo test` (`GEN_RAPID_FUZZ_CASES` / 10 overrides).
const DEFAULT_CASES: u64 = 300;
/// Command lines run (each a process).
const COMMAND_LINES: u64 = 60;

/// Numbers an attacker writes.
const WEIRD: &[&str] = &[
    "1e300",
    "-1e300",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "1e-300",
    "0",
    "-0",
    "1e999",
    "",
    "x",
    "0.0000001",
    "720.0001",
    "-720",
    "99999999999999999999",
];

/// Replaces a few numbers of `text` with weird ones.
fn weird_numbers(rng: &mut fastrand::Rng, text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if (c.is_ascii_digit() || c == '-') && rng.u32(0..12) == 0 {
            while chars
                .peek()
                .is_some_and(|d| d.is_ascii_digit() || *d == '.' || *d == 'e' || *d == '-')
            {
                chars.next();
            }
            out += WEIRD[rng.usize(..WEIRD.len())];
        } else {
            out.push(c);
        }
    }
    out
}

/// A mutation of `base`: byte edits, line edits, weird numbers, or a line repeated many times.
fn mutate(rng: &mut fastrand::Rng, base: &str, other: &str) -> String {
    match rng.u32(0..5) {
        0 => String::from_utf8_lossy(&mutate_bytes(
            rng,
            base.as_bytes().to_vec(),
            other.as_bytes(),
        ))
        .into_owned(),
        1 => String::from_utf8_lossy(&mutate_lines(rng, base)).into_owned(),
        2 => weird_numbers(rng, base),
        3 => {
            let lines: Vec<&str> = base.lines().collect();
            let k = rng.usize(..lines.len().max(1));
            let n = rng.usize(1..2000);
            let mut out = String::new();
            for (i, l) in lines.iter().enumerate() {
                out += l;
                out.push('\n');
                if i == k {
                    out += &format!("{l}\n").repeat(n);
                }
            }
            out
        }
        _ => {
            let mut s = weird_numbers(rng, base);
            for (from, to) in [
                ("tool0", "flange"),
                ("link_3", "link_9"),
                ("revolute", "prismatic"),
            ] {
                if rng.bool() {
                    s = s.replacen(from, to, 1);
                }
            }
            s
        }
    }
}

/// Runs `f` catching a panic: `Err` says what broke.
fn unpanicked<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    catch_unwind(AssertUnwindSafe(f)).map_err(|panic| {
        let what = panic
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        format!("panic: {what}")
    })
}

/// A refusal's exit status and size.
fn short_refusal(r: &Refusal, exit: u8) -> Result<(), String> {
    if r.exit != exit {
        return Err(format!("exit {} (not {exit}):\n{}", r.exit, r.message));
    }
    if r.message.len() > MAX_MESSAGE_BYTES || !r.message.starts_with("error: ") {
        return Err(format!(
            "a message of {} bytes:\n{}",
            r.message.len(),
            r.message
        ));
    }
    Ok(())
}

/// Runs `cases` seeded cases of `one` and fails with the first problems found.
fn run_cases(
    name: &str,
    cases: u64,
    mut one: impl FnMut(&mut fastrand::Rng) -> Result<(), String>,
) {
    let seed = env_u64("GEN_RAPID_FUZZ_SEED", 0x6e72_6170_6964);
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut failures = Vec::new();
    for i in 0..cases {
        let case_seed = seed.wrapping_add(i);
        let mut rng = fastrand::Rng::with_seed(case_seed);
        if std::env::var_os("GEN_RAPID_FUZZ_TRACE").is_some() {
            eprintln!("{name} case {i} seed {case_seed}");
        }
        match unpanicked(|| one(&mut rng)) {
            Ok(Ok(())) => {}
            Ok(Err(why)) | Err(why) => failures.push(format!(
                "{name} case {i} (GEN_RAPID_FUZZ_SEED={case_seed}): {}",
                &why[..why.len().min(2000)]
            )),
        }
        if failures.len() >= 10 {
            break;
        }
    }
    std::panic::set_hook(hook);
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn the_robot_files_never_panic_and_a_controller_fault_is_located_in_its_file() {
    let urdf = std::fs::read_to_string(root().join("robots/irb1400.urdf")).expect("urdf");
    let controller =
        std::fs::read_to_string(root().join("robots/irb1400.controller.yaml")).expect("c");
    let (upath, cpath) = (Path::new("arm.urdf"), Path::new("arm.controller.yaml"));
    let cases = env_u64("GEN_RAPID_FUZZ_CASES", DEFAULT_CASES * 10) / 10;
    run_cases("robot files", cases, |rng| {
        let (u, c) = match rng.u32(0..3) {
            0 => (mutate(rng, &urdf, &controller), controller.clone()),
            1 => (urdf.clone(), mutate(rng, &controller, &urdf)),
            _ => (
                mutate(rng, &urdf, &controller),
                mutate(rng, &controller, &urdf),
            ),
        };
        let with_controller = rng.u32(0..4) > 0;
        let result = robot_from_texts(upath, &u, cpath, with_controller.then_some(c.as_str()));
        let Err(r) = result else { return Ok(()) };
        short_refusal(&r, 1)?;
        // A controller file's fault with a place is pointed at in the controller file.
        if let Some(at) = r.message.lines().find(|l| l.starts_with("  --> ")) {
            if r.message.starts_with("error: controller file") {
                let place = at.trim_start_matches("  --> ");
                let line: usize = place
                    .strip_prefix("arm.controller.yaml:")
                    .and_then(|p| p.split(':').next())
                    .and_then(|n| n.parse().ok())
                    .ok_or_else(|| format!("not located in the controller file:\n{}", r.message))?;
                if line == 0 || line > c.lines().count() + 1 {
                    return Err(format!("line {line} outside the file:\n{}", r.message));
                }
            }
        }
        Ok(())
    });
}

/// Template pieces an attacker writes.
const TEMPLATE_TOKENS: &[&str] = &[
    "{{ ",
    " }}",
    "{% ",
    " %}",
    "{# ",
    " #}",
    "for t in targets",
    "endfor",
    "if ",
    "endif",
    "macro m(x)",
    "endmacro",
    "m(",
    ")",
    "(",
    "[",
    "]",
    "~",
    " * ",
    " + ",
    "100000",
    "range(",
    "namespace(",
    "set ",
    " = ",
    "'x'",
    "\"",
    "module",
    "targets",
    "moves",
    "|length",
    "|join",
    "|list",
    "|tojson",
    "loop.index",
    "raw",
    "endraw",
    "call",
    "endcall",
    "filter upper",
    "endfilter",
    "\n",
    "-",
    "undefined_name",
    "1e308",
    "recursive",
    "loop(",
];

#[test]
fn templates_never_panic_and_every_refusal_is_an_input_error_in_the_template() {
    let bench = TemplateBench::new();
    let mut sources = Vec::new();
    for name in crate::common::file_names(&root().join("templates")) {
        if name.ends_with(".j2") {
            sources.push(std::fs::read_to_string(root().join("templates").join(name)).expect("t"));
        }
    }
    let path = Path::new("fuzz.mod.j2");
    let cases = env_u64("GEN_RAPID_FUZZ_CASES", DEFAULT_CASES * 10) / 10;
    run_cases("templates", cases, |rng| {
        let base = &sources[rng.usize(..sources.len())];
        let source = match rng.u32(0..3) {
            0 => (0..rng.usize(1..60))
                .map(|_| TEMPLATE_TOKENS[rng.usize(..TEMPLATE_TOKENS.len())])
                .collect::<String>(),
            1 => mutate(rng, base, &sources[0]),
            _ => {
                // A piece of soup spliced into a real template.
                let soup: String = (0..rng.usize(1..12))
                    .map(|_| TEMPLATE_TOKENS[rng.usize(..TEMPLATE_TOKENS.len())])
                    .collect();
                let at = base
                    .char_indices()
                    .map(|(i, _)| i)
                    .nth(rng.usize(..base.chars().count().max(1)))
                    .unwrap_or(0);
                format!("{}{soup}{}", &base[..at], &base[at..])
            }
        };
        if std::env::var_os("GEN_RAPID_FUZZ_TRACE").is_some() {
            let dir = root().join("target").join("fuzz-failures");
            let _ = std::fs::create_dir_all(&dir);
            let _ = std::fs::write(dir.join("last-template.j2"), &source);
        }
        match bench.render(path, &source) {
            Ok(text) if text.len() <= 64 << 20 => Ok(()),
            Ok(text) => Err(format!("a module of {} bytes", text.len())),
            Err(r) => {
                short_refusal(&r, 1)?;
                match r.message.lines().nth(1) {
                    Some(l) if l.starts_with("  --> fuzz.mod.j2") => Ok(()),
                    _ => Err(format!("not located in the template:\n{}", r.message)),
                }
            }
        }
    });
}

/// Arguments an attacker passes.
fn argument(rng: &mut fastrand::Rng, dir: &Path) -> Vec<String> {
    let file = |name: &str| dir.join(name).display().to_string();
    let pick = |rng: &mut fastrand::Rng, list: &[String]| list[rng.usize(..list.len())].clone();
    let paths = vec![
        file("a.svg"),
        format!("{}/d/../a.svg", dir.display()),
        file("./a.svg"),
        file("d"),
        file("missing/x"),
        "/dev/null".into(),
        "/dev/stdout".into(),
        "/dev/full".into(),
        "cells/trunk.yaml".into(),
        "robots/irb1400.urdf".into(),
        file("\u{e9}t\u{e9} \u{1F600}.svg"),
        file(&"x".repeat(300)),
        String::new(),
    ];
    let cells = vec![
        "cells/trunk.yaml".to_string(),
        "tests/err/budget_grid_default.yaml".into(),
        "tests/ok/tool_wobj_robtargets.yaml".into(),
        file("d"),
        "/dev/zero".into(),
        "/nonexistent.yaml".into(),
        "-".into(),
    ];
    let grids: Vec<String> = ["3", "5", "10", "0.1", "nan", "-1", "1e999", "abc", "0.25"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut args = Vec::new();
    match rng.u32(0..6) {
        0 => args.push("compare".into()),
        1 => args.push("locate".into()),
        _ => {}
    }
    args.push(pick(rng, &cells));
    for _ in 0..rng.usize(0..5) {
        match rng.u32(0..9) {
            0 => args.extend(["-o".into(), pick(rng, &paths)]),
            1 => args.extend(["--svg".into(), pick(rng, &paths)]),
            2 => args.extend(["--html".into(), pick(rng, &paths)]),
            3 => args.extend(["--report".into(), pick(rng, &paths)]),
            4 => args.extend(["--grid".into(), pick(rng, &grids)]),
            5 => args.extend([
                "--proc".into(),
                ["main", "MoveL", "x y", "Weld", ""][rng.usize(..5)].into(),
            ]),
            6 => args.push(
                ["-q", "--json", "--no-shortcut", "--bogus", "--help"][rng.usize(..5)].into(),
            ),
            7 => args.extend(["--template".into(), pick(rng, &paths)]),
            _ => args.extend([
                "--planner".into(),
                ["depth-first", "nope", ""][rng.usize(..3)].into(),
            ]),
        }
    }
    // Planning stays quick: a coarse grid unless the case set one.
    if !args.iter().any(|a| a == "--grid") && !args.iter().any(|a| a == "locate") {
        args.extend(["--grid".into(), "10".into()]);
    }
    args
}

#[test]
fn command_lines_never_panic_and_a_refusal_leaves_stdout_empty() {
    let cases = env_u64("GEN_RAPID_FUZZ_CASES", COMMAND_LINES * 50) / 50;
    run_cases("command lines", cases, |rng| {
        let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
        std::fs::create_dir(dir.path().join("d")).map_err(|e| e.to_string())?;
        let args = argument(rng, dir.path());
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_gen-rapid"))
            .args(&args)
            .current_dir(root())
            .stdin(std::process::Stdio::null())
            .output()
            .map_err(|e| e.to_string())?;
        let err = String::from_utf8_lossy(&o.stderr);
        let code = o.status.code();
        if !matches!(code, Some(0..=4)) {
            return Err(format!("{args:?}: exit {code:?}:\n{err}"));
        }
        if code != Some(0) && !o.stdout.is_empty() && !args.iter().any(|a| a == "compare") {
            return Err(format!("{args:?}: exit {code:?} with stdout:\n{err}"));
        }
        if code != Some(0) && (err.len() > 4096 || err.lines().count() > 20) {
            return Err(format!("{args:?}: {} bytes of stderr:\n{err}", err.len()));
        }
        // No temporary file of an output is left behind.
        for entry in std::fs::read_dir(dir.path()).map_err(|e| e.to_string())? {
            let name = entry.map_err(|e| e.to_string())?.file_name();
            if name.to_string_lossy().ends_with(".tmp") {
                return Err(format!("{args:?}: left {name:?}"));
            }
        }
        Ok(())
    });
}
