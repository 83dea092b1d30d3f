//! The fuzz target over loading and validating a cell (and placing it): seeded, deterministic
//! cases of arbitrary bytes, YAML-ish token soup, and mutations of the example cells (byte and
//! line edits; structured edits of the parsed tree: numbers to NaN, infinities, huge, negative,
//! many decimals; keys dropped, duplicated, misspelled, added; lists lengthened, shortened,
//! emptied; strings huge or taken from RAPID's reserved names; nodes swapped; sections grafted
//! from another cell, e.g. a `tool:`, `wobj:` or robtarget points; the keys of docs/cell.md
//! among the keys added; nesting deep),
//! each run through the library's load and validation, and where it validates with a few points,
//! the place stage with the IRB 1400 (one placed cell in [`RUN_EVERY`] also through the rest of
//! the run, on a coarse grid). Every case must end without a panic, in an `Ok` or in a
//! refusal that carries `line:column` and renders to at most [`MAX_MESSAGE_BYTES`]. Inputs are
//! capped at [`MAX_INPUT_BYTES`], so memory stays bounded; no case is timed (a hang shows as a
//! test that does not end).
//!
//! `cargo test --release --test it fuzz` runs [`DEFAULT_CASES`] cases (a few seconds); run it
//! longer with `GEN_RAPID_FUZZ_CASES=200000` and from another seed with `GEN_RAPID_FUZZ_SEED=N`
//! (add `-- --nocapture` for the figures). A failing case is written to `target/fuzz-failures/`
//! with its seed, for replay; its input, once fixed, goes to `tests/fuzz/`, replayed by every run.
//!
//! Files: `tree.rs` (the structured edits), `edits.rs` (token soup, byte and line edits).

mod edits;
mod inputs;
mod tree;

use crate::common::library::{
    cell_from_bytes, irb1400, place_with, run_with, Refusal, Robot, Target,
};
use crate::common::{file_names, root};
use edits::{mutate_bytes, mutate_lines, token_soup};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use tree::{emit, node, paths, plausible, size, Y};
use tree::{graft, mutate_tree};

/// Cases run by `cargo test` (`GEN_RAPID_FUZZ_CASES` overrides).
const DEFAULT_CASES: u64 = 3000;
/// First seed (`GEN_RAPID_FUZZ_SEED` overrides); case `i` uses seed `SEED + i`.
const DEFAULT_SEED: u64 = 0x6e72_6170_6964;
/// Largest input tried, bytes.
const MAX_INPUT_BYTES: usize = 256 * 1024;
/// Longest message allowed, bytes.
const MAX_MESSAGE_BYTES: usize = 4096;
/// The place stage runs for valid cells with at most this many points and obstacles (cheap).
const MAX_PLACED_POINTS: usize = 12;
const MAX_PLACED_OBSTACLES: usize = 40;
/// One placed cell in this many also runs the rest of the pipeline, on a coarse grid (deg).
const RUN_EVERY: u64 = 8;
const RUN_GRID_DEG: f64 = 10.0;

fn env_u64(name: &str, default: u64) -> u64 {
    match std::env::var(name) {
        Ok(v) => v
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v} is not a number")),
        Err(_) => default,
    }
}

/// The example cells: every cell the repository holds (`cells/`, `tests/ok/`, `tests/err/`), with
/// the path it is read as (so a relative URDF resolves as for the real file).
fn corpus() -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    for dir in ["cells", "tests/ok", "tests/err"] {
        for name in file_names(&root().join(dir)) {
            if name.ends_with(".yaml") {
                let rel = PathBuf::from(dir).join(&name);
                let bytes = std::fs::read(root().join(&rel)).expect("read corpus");
                out.push((rel, bytes));
            }
        }
    }
    assert!(out.len() > 20, "corpus");
    out
}

/// What one case did.
#[derive(Default)]
struct Tally {
    cases: u64,
    refused: u64,
    valid: u64,
    /// Valid cells with a `tool:` block, and with a robtarget point.
    with_tool: u64,
    with_robtarget: u64,
    placed: u64,
    place_refused: u64,
    place_skipped: u64,
    ran: u64,
    run_refused: u64,
    largest_message: usize,
    largest_input: usize,
}

/// The generators, by case number: arbitrary bytes, token soup, byte edits, line edits,
/// structured edits (heavy: 1 to 4 of any kind), and light edits (one plausible value, so that
/// many cases validate and reach the place stage).
const GENERATORS: [&str; 6] = [
    "bytes",
    "tokens",
    "byte edits",
    "line edits",
    "tree edits",
    "light edits",
];

/// A case of generator `kind`: the path it is read as and its bytes.
fn generate(
    kind: usize,
    rng: &mut fastrand::Rng,
    corpus: &[(PathBuf, Vec<u8>)],
    valid: &[(PathBuf, Vec<u8>)],
) -> (PathBuf, Vec<u8>) {
    let (path, base) = if kind >= 4 && rng.u32(0..5) > 0 {
        &valid[rng.usize(..valid.len())]
    } else {
        &corpus[rng.usize(..corpus.len())]
    };
    let (_, other) = &corpus[rng.usize(..corpus.len())];
    let bytes = match kind {
        0 => (0..rng.usize(0..2048)).map(|_| rng.u8(..)).collect(),
        1 => token_soup(rng),
        2 => mutate_bytes(rng, base.clone(), other),
        3 => mutate_lines(rng, &String::from_utf8_lossy(base)),
        _ => match serde_saphyr::from_slice::<Y>(base) {
            Ok(mut tree) => {
                if kind == 4 {
                    if rng.u32(0..4) == 0 {
                        if let Ok(donor) = serde_saphyr::from_slice::<Y>(other) {
                            graft(rng, &mut tree, &donor);
                        }
                    }
                    for _ in 0..rng.usize(1..5) {
                        mutate_tree(rng, &mut tree);
                        if size(&tree) > MAX_INPUT_BYTES {
                            break;
                        }
                    }
                } else {
                    let mut all = Vec::new();
                    paths(&tree, &mut Vec::new(), &mut all);
                    for _ in 0..rng.usize(1..4) {
                        let p = &all[rng.usize(..all.len())];
                        if let Y::Scalar(s) = node(&mut tree, p) {
                            *s = plausible(rng, s);
                        }
                    }
                }
                let mut out = String::new();
                emit(&tree, 0, &mut out);
                out.into_bytes()
            }
            // A refused example (tests/err): edit its lines instead.
            Err(_) => mutate_lines(rng, &String::from_utf8_lossy(base)),
        },
    };
    (path.clone(), bytes)
}

/// Checks a refusal: located, and short.
fn check_refusal(r: &Refusal, file: &str, lines: usize, what: &str) -> Result<(), String> {
    if r.message.len() > MAX_MESSAGE_BYTES {
        return Err(format!("{what}: a message of {} bytes", r.message.len()));
    }
    let Some((line, column)) = r.loc else {
        return Err(format!("{what}: no location:\n{}", r.message));
    };
    if line == 0 || column == 0 || line as usize > lines + 1 {
        return Err(format!(
            "{what}: location {line}:{column} outside the file ({lines} lines):\n{}",
            r.message
        ));
    }
    if !r.message.contains(&format!("--> {file}:{line}:{column}\n")) {
        return Err(format!(
            "{what}: the message does not say where:\n{}",
            r.message
        ));
    }
    Ok(())
}

/// Runs one input through load, validation and (for a small valid cell) the place stage.
fn check(path: &Path, bytes: Vec<u8>, robot: &Robot, tally: &mut Tally) -> Result<(), String> {
    let file = "fuzz.yaml";
    // Lines as YAML counts them, for the location check.
    let lines = bytes
        .iter()
        .enumerate()
        .filter(|&(i, &c)| c == b'\n' || (c == b'\r' && bytes.get(i + 1) != Some(&b'\n')))
        .count()
        + 1;
    tally.largest_input = tally.largest_input.max(bytes.len());
    match cell_from_bytes(path, file, bytes) {
        Err(r) => {
            tally.refused += 1;
            tally.largest_message = tally.largest_message.max(r.message.len());
            if r.exit != 1 {
                return Err(format!("a refused cell exits {}:\n{}", r.exit, r.message));
            }
            check_refusal(&r, file, lines, "load")
        }
        Ok((cell, text)) => {
            tally.valid += 1;
            tally.with_tool += u64::from(cell.tool.is_some());
            tally.with_robtarget += u64::from(
                cell.points
                    .iter()
                    .any(|p| matches!(p.target, Target::Robtarget { .. })),
            );
            if cell.points.len() > MAX_PLACED_POINTS || cell.obstacles.len() > MAX_PLACED_OBSTACLES
            {
                tally.place_skipped += 1;
                return Ok(());
            }
            match place_with(&cell, &text, file, robot) {
                Ok(n) if n == cell.points.len() => {
                    tally.placed += 1;
                    if tally.placed % RUN_EVERY != 0 {
                        return Ok(());
                    }
                    // The rest of the pipeline: a module, or a located planning failure.
                    tally.ran += 1;
                    match run_with(&cell, &text, file, robot, RUN_GRID_DEG) {
                        Ok(module) if module.starts_with("MODULE ") => Ok(()),
                        Ok(module) => Err(format!("not a module:\n{module}")),
                        Err(r) if r.exit == 3 => {
                            tally.run_refused += 1;
                            check_refusal(&r, file, lines, "plan")
                        }
                        Err(r) => Err(format!("the run exits {}:\n{}", r.exit, r.message)),
                    }
                }
                Ok(n) => Err(format!("{n} of {} points placed", cell.points.len())),
                Err(r) => {
                    tally.place_refused += 1;
                    tally.largest_message = tally.largest_message.max(r.message.len());
                    check_refusal(&r, file, lines, "place")
                }
            }
        }
    }
}

#[test]
fn loading_validating_and_placing_never_panic_and_always_say_where() {
    let cases = env_u64("GEN_RAPID_FUZZ_CASES", DEFAULT_CASES);
    let seed = env_u64("GEN_RAPID_FUZZ_SEED", DEFAULT_SEED);
    let corpus = corpus();
    let valid: Vec<(PathBuf, Vec<u8>)> = corpus
        .iter()
        .filter(|(p, _)| !p.starts_with("tests/err"))
        .cloned()
        .collect();
    let robot = irb1400();
    let mut tally = Tally::default();
    let mut failures: Vec<String> = Vec::new();
    let out_dir = root().join("target").join("fuzz-failures");
    // The panic hook would print every caught panic; the failures say it once each.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    for i in 0..cases {
        let case_seed = seed.wrapping_add(i);
        let mut rng = fastrand::Rng::with_seed(case_seed);
        let kind = (case_seed % GENERATORS.len() as u64) as usize;
        let (path, mut bytes) = generate(kind, &mut rng, &corpus, &valid);
        bytes.truncate(MAX_INPUT_BYTES);
        let input = bytes.clone();
        tally.cases += 1;
        let outcome = catch_unwind(AssertUnwindSafe(|| check(&path, bytes, &robot, &mut tally)));
        let problem = match outcome {
            Ok(Ok(())) => continue,
            Ok(Err(why)) => why,
            Err(panic) => {
                let what = panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                format!("panic: {what}")
            }
        };
        let _ = std::fs::create_dir_all(&out_dir);
        let saved = out_dir.join(format!("seed-{case_seed}.yaml"));
        let _ = std::fs::write(&saved, &input);
        failures.push(format!(
            "case {i} (replay: GEN_RAPID_FUZZ_SEED={case_seed} GEN_RAPID_FUZZ_CASES=1; generator: {}, from {}; input in {}): {}",
            GENERATORS[kind],
            path.display(),
            saved.display(),
            &problem[..problem.len().min(2000)]
        ));
        if failures.len() >= 20 {
            break;
        }
    }
    std::panic::set_hook(hook);
    eprintln!(
        "fuzz: {} cases from seed {seed}: {} refused at load, {} valid ({} with a tool block, {} with robtarget points; {} placed, {} refused by the place stage, {} not placed: too many points or obstacles; {} run on a {RUN_GRID_DEG} deg grid, {} of them refused); largest input {} bytes, largest message {} bytes",
        tally.cases,
        tally.refused,
        tally.valid,
        tally.with_tool,
        tally.with_robtarget,
        tally.placed,
        tally.place_refused,
        tally.place_skipped,
        tally.ran,
        tally.run_refused,
        tally.largest_input,
        tally.largest_message
    );
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n\n")
    );
    // The generators reach both sides: refusals and valid cells that are placed, some with a
    // tool and robtarget points.
    if cases >= 1000 {
        assert!(
            tally.refused > cases / 10 && tally.placed > cases / 50,
            "{} refused, {} placed",
            tally.refused,
            tally.placed
        );
        assert!(
            tally.with_tool > cases / 100 && tally.with_robtarget > cases / 100,
            "{} valid cells with a tool, {} with robtargets",
            tally.with_tool,
            tally.with_robtarget
        );
    }
}

#[test]
fn the_inputs_the_fuzzer_found_stay_fixed() {
    // Each file of tests/fuzz/ is an input a run of the fuzz target found failing (named for
    // what it broke); each must now pass the same checks.
    let robot = irb1400();
    let dir = root().join("tests/fuzz");
    let names = file_names(&dir);
    assert!(!names.is_empty());
    for name in names {
        let bytes = std::fs::read(dir.join(&name)).expect("read");
        let mut tally = Tally::default();
        let path = Path::new("tests/fuzz").join(&name);
        check(&path, bytes, &robot, &mut tally).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}

#[test]
fn the_tree_reads_back_what_it_writes() {
    // The emitter of the structured mutations writes the example cells so that they still load
    // to the same cell (else the mutations would test the emitter).
    for name in [
        "cells/trunk.yaml",
        "cells/conveyor.yaml",
        "cells/trunk-auto.yaml",
        "cells/torch-trunk.yaml",
        "cells/gripper-pick.yaml",
        "tests/ok/tool_wobj_robtargets.yaml",
    ] {
        let bytes = std::fs::read(root().join(name)).expect("read");
        let tree: Y = serde_saphyr::from_slice(&bytes).expect("tree");
        let mut out = String::new();
        emit(&tree, 0, &mut out);
        let path = Path::new(name);
        let (a, _) = cell_from_bytes(path, name, bytes).expect("original loads");
        let (b, _) = cell_from_bytes(path, name, out.clone().into_bytes())
            .unwrap_or_else(|r| panic!("{}\n{out}", r.message));
        assert_eq!(a.points.len(), b.points.len(), "{name}");
        let boxes = |c: &crate::common::library::Cell| {
            c.obstacles
                .iter()
                .map(|o| (o.name.clone(), o.aabb.min, o.aabb.max))
                .collect::<Vec<_>>()
        };
        assert_eq!(boxes(&a), boxes(&b), "{name}");
        let robot = |c: &crate::common::library::Cell| {
            let r = &c.robot;
            (r.urdf_path.clone(), r.base.clone(), r.yaw_deg, r.wrist_deg)
        };
        assert_eq!(robot(&a), robot(&b), "{name}");
        // The planner, but where its grid stands in the file.
        let planner = |c: &crate::common::library::Cell| {
            let mut p = c.planner.clone();
            p.grid_loc = p.grid_loc.map(|_| Default::default());
            p
        };
        assert_eq!(planner(&a), planner(&b), "{name}");
        // The points, the motion, the tool and the work object, but where they stand in the file
        // (the comments are not written back).
        let unplaced = |c: &crate::common::library::Cell| {
            let mut c = c.clone();
            for p in &mut c.points {
                p.loc = Default::default();
                p.arrival_loc = Default::default();
                p.approach_loc = Default::default();
                p.retract_loc = Default::default();
                for a in &mut p.actions {
                    a.loc = Default::default();
                }
                if let Target::Xyz { branch_loc, .. } = &mut p.target {
                    *branch_loc = Default::default();
                }
            }
            c.motion.cycle_loc = Default::default();
            for l in &mut c.loads {
                l.loc = Default::default();
            }
            if let Some(t) = &mut c.tool {
                t.loc = Default::default();
                for s in &mut t.shapes {
                    s.loc = Default::default();
                }
            }
            for w in &mut c.wobjs {
                w.loc = Default::default();
            }
            (c.points, c.motion, c.tool, c.wobjs, c.loads)
        };
        assert_eq!(unplaced(&a), unplaced(&b), "{name}");
    }
}
