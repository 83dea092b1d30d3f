//! The fuzz target over loading and validating a cell (and placing it): seeded, deterministic
//! cases of arbitrary bytes, YAML-ish token soup, and mutations of the example cells (byte and
//! line edits; structured edits of the parsed tree: numbers to NaN, infinities, huge, negative,
//! many decimals; keys dropped, duplicated, misspelled, added; lists lengthened, shortened,
//! emptied; strings huge or taken from RAPID's reserved names; nodes swapped; nesting deep),
//! each run through the library's load and validation, and where it validates with a few points,
//! the place stage with the IRB 1400. Every case must end without a panic, in an `Ok` or in a
//! refusal that carries `line:column` and renders to at most [`MAX_MESSAGE_BYTES`]. Inputs are
//! capped at [`MAX_INPUT_BYTES`], so memory stays bounded; no case is timed (a hang shows as a
//! test that does not end).
//!
//! `cargo test --release --test it fuzz` runs [`DEFAULT_CASES`] cases (a few seconds); run it
//! longer with `GEN_RAPID_FUZZ_CASES=200000` and from another seed with `GEN_RAPID_FUZZ_SEED=N`
//! (add `-- --nocapture` for the figures). A failing case is written to `target/fuzz-failures/`
//! with its seed, for replay.

use crate::common::library::{cell_from_bytes, irb1400, place_with, run_with, Refusal, Robot};
use crate::common::{file_names, root};
use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

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

// ---- a YAML tree to mutate ----

/// A cell file as a tree (keys kept in order, duplicates allowed).
#[derive(Clone, Debug)]
enum Y {
    Map(Vec<(String, Y)>),
    Seq(Vec<Y>),
    Scalar(String),
}

impl<'de> Deserialize<'de> for Y {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Y, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Y;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("any YAML")
            }
            fn visit_bool<E>(self, v: bool) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_i64<E>(self, v: i64) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_u64<E>(self, v: u64) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_f64<E>(self, v: f64) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_str<E>(self, v: &str) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_unit<E>(self) -> Result<Y, E> {
                Ok(Y::Scalar("null".into()))
            }
            fn visit_none<E>(self) -> Result<Y, E> {
                Ok(Y::Scalar("null".into()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut a: A) -> Result<Y, A::Error> {
                let mut v = Vec::new();
                while let Some(y) = a.next_element()? {
                    v.push(y);
                }
                Ok(Y::Seq(v))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut a: A) -> Result<Y, A::Error> {
                let mut v = Vec::new();
                while let Some((k, y)) = a.next_entry::<Y, Y>()? {
                    let k = match k {
                        Y::Scalar(s) => s,
                        other => emit_flow(&other),
                    };
                    v.push((k, y));
                }
                Ok(Y::Map(v))
            }
        }
        d.deserialize_any(V)
    }
}

/// A scalar as YAML: plain where that reads back the same text, else double-quoted.
fn scalar(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "._-+/".contains(c))
        && !s.starts_with(['-', '.'])
        || s.parse::<f64>().is_ok();
    if plain {
        s.to_string()
    } else {
        format!("{s:?}")
    }
}

fn emit_flow(y: &Y) -> String {
    match y {
        Y::Scalar(s) => scalar(s),
        Y::Seq(v) => format!(
            "[{}]",
            v.iter().map(emit_flow).collect::<Vec<_>>().join(", ")
        ),
        Y::Map(v) => format!(
            "{{ {} }}",
            v.iter()
                .map(|(k, y)| format!("{}: {}", scalar(k), emit_flow(y)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Block style for mappings, flow style for lists (as the example cells write them).
fn emit(y: &Y, indent: usize, out: &mut String) {
    let pad = " ".repeat(indent);
    match y {
        Y::Map(v) => {
            for (k, y) in v {
                match y {
                    Y::Map(m) if !m.is_empty() => {
                        out.push_str(&format!("{pad}{}:\n", scalar(k)));
                        emit(y, indent + 2, out);
                    }
                    Y::Seq(s) if s.iter().any(|i| matches!(i, Y::Map(_))) => {
                        out.push_str(&format!("{pad}{}:\n", scalar(k)));
                        for item in s {
                            out.push_str(&format!("{pad}  - {}\n", emit_flow(item)));
                        }
                    }
                    _ => out.push_str(&format!("{pad}{}: {}\n", scalar(k), emit_flow(y))),
                }
            }
        }
        other => out.push_str(&format!("{pad}{}\n", emit_flow(other))),
    }
}

fn size(y: &Y) -> usize {
    match y {
        Y::Scalar(s) => s.len() + 2,
        Y::Seq(v) => 2 + v.iter().map(size).sum::<usize>(),
        Y::Map(v) => v.iter().map(|(k, y)| k.len() + 2 + size(y)).sum(),
    }
}

/// Every node's path (indices from the root).
fn paths(y: &Y, at: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
    out.push(at.clone());
    let children: Vec<&Y> = match y {
        Y::Map(v) => v.iter().map(|(_, y)| y).collect(),
        Y::Seq(v) => v.iter().collect(),
        Y::Scalar(_) => return,
    };
    for (i, c) in children.into_iter().enumerate() {
        at.push(i);
        paths(c, at, out);
        at.pop();
    }
}

fn node<'a>(y: &'a mut Y, path: &[usize]) -> &'a mut Y {
    let Some((&first, rest)) = path.split_first() else {
        return y;
    };
    match y {
        Y::Map(v) => node(&mut v[first].1, rest),
        Y::Seq(v) => node(&mut v[first], rest),
        Y::Scalar(_) => y,
    }
}

const KEYS: &[&str] = &[
    "module",
    "robot",
    "urdf",
    "base",
    "yaw",
    "wrist",
    "obstacles",
    "name",
    "box",
    "min",
    "max",
    "points",
    "joints",
    "xyz",
    "branch",
    "planner",
    "method",
    "grid",
    "clearance",
    "motion",
    "speed",
    "zone",
    "tool",
];

const NAMES: &[&str] = &[
    "main",
    "Main",
    "MoveAbsJ",
    "If",
    "v300",
    "fine",
    "tool0",
    "wobj0",
    "via01_01",
    "A",
    "a",
    "P1",
    "auto",
    "",
    " ",
    "9lives",
    "é",
    "x y",
    "extensile",
    "depth-first",
    "back-elbow-up",
    "null",
    "~",
    "true",
    "0x10",
    "1e3",
    "'",
    "\"",
    "#",
    "&a",
    "*a",
    "!!str",
    "- x",
    "[",
    "{",
];

fn weird_number(rng: &mut fastrand::Rng) -> String {
    match rng.u32(0..20) {
        0 => ".nan".into(),
        1 => "nan".into(),
        2 => ".inf".into(),
        3 => "-.inf".into(),
        4 => "1e308".into(),
        5 => "-1e308".into(),
        6 => "1e999".into(),
        7 => "1e-320".into(),
        8 => "-0".into(),
        9 => "9".repeat(rng.usize(20..400)),
        10 => format!("0.{}", "1".repeat(rng.usize(4..40))),
        11 => format!("{}.{}", rng.i64(-100000..100000), rng.u32(0..100000)),
        12 => "0x1F".into(),
        13 => "1_000".into(),
        14 => "+5".into(),
        15 => format!("{}", rng.i32(..)),
        16 => format!("{:.3}", rng.f64() * 720.0 - 360.0),
        17 => format!("{:.1}", rng.f64() * 6000.0 - 3000.0),
        18 => format!("-{}", rng.u32(0..100000)),
        _ => format!("{:e}", rng.f64() * 10f64.powi(rng.i32(-300..300))),
    }
}

fn weird_string(rng: &mut fastrand::Rng) -> String {
    match rng.u32(0..6) {
        0 => "x".repeat(rng.usize(33..60_000)),
        1 => NAMES[rng.usize(..NAMES.len())].to_string(),
        2 => (0..rng.usize(1..40))
            .map(|_| char::from_u32(rng.u32(1..0x3000)).unwrap_or('?'))
            .collect(),
        3 => format!("P{}", rng.u32(0..5)),
        4 => format!("../robots/{}.urdf", "r".repeat(rng.usize(0..10))),
        _ => KEYS[rng.usize(..KEYS.len())].to_string(),
    }
}

fn random_node(rng: &mut fastrand::Rng, depth: usize) -> Y {
    match rng.u32(0..if depth > 2 { 2 } else { 4 }) {
        0 => Y::Scalar(weird_number(rng)),
        1 => Y::Scalar(weird_string(rng)),
        2 => Y::Seq(
            (0..rng.usize(0..8))
                .map(|_| random_node(rng, depth + 1))
                .collect(),
        ),
        _ => Y::Map(
            (0..rng.usize(0..5))
                .map(|_| {
                    (
                        KEYS[rng.usize(..KEYS.len())].to_string(),
                        random_node(rng, depth + 1),
                    )
                })
                .collect(),
        ),
    }
}

fn misspell(rng: &mut fastrand::Rng, k: &str) -> String {
    let mut c: Vec<char> = k.chars().collect();
    match rng.u32(0..5) {
        0 if !c.is_empty() => {
            c.remove(rng.usize(..c.len()));
        }
        1 => c.insert(rng.usize(..=c.len()), char::from(rng.u8(b'a'..=b'z'))),
        2 if c.len() > 1 => {
            let i = rng.usize(..c.len() - 1);
            c.swap(i, i + 1);
        }
        3 => return k.to_uppercase(),
        _ => c.push('s'),
    }
    c.into_iter().collect()
}

/// One structured edit of the tree.
fn mutate_tree(rng: &mut fastrand::Rng, root: &mut Y) {
    let mut all = Vec::new();
    paths(root, &mut Vec::new(), &mut all);
    let path = all[rng.usize(..all.len())].clone();
    let donor = {
        let p = &all[rng.usize(..all.len())];
        node(&mut root.clone(), p).clone()
    };
    let n = node(root, &path);
    match n {
        Y::Scalar(s) => {
            *s = match rng.u32(0..3) {
                0 if s.parse::<f64>().is_ok() => weird_number(rng),
                0 | 1 => weird_string(rng),
                _ => weird_number(rng),
            };
            if rng.u32(0..8) == 0 {
                *n = donor;
            }
        }
        Y::Seq(v) => match rng.u32(0..8) {
            0 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                let item = v[i].clone();
                for _ in 0..rng.usize(1..60) {
                    v.insert(i, item.clone());
                }
            }
            1 if !v.is_empty() => {
                v.remove(rng.usize(..v.len()));
            }
            2 => v.clear(),
            3 => v.push(random_node(rng, 1)),
            4 => v.push(Y::Scalar(weird_number(rng))),
            5 => {
                let mut deep = n.clone();
                for _ in 0..rng.usize(1..400) {
                    deep = Y::Seq(vec![deep]);
                }
                *n = deep;
            }
            6 => *n = donor,
            _ => {
                if v.len() > 1 {
                    v.truncate(rng.usize(1..v.len()));
                }
            }
        },
        Y::Map(v) => match rng.u32(0..8) {
            0 if !v.is_empty() => {
                v.remove(rng.usize(..v.len()));
            }
            1 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                let dup = v[i].clone();
                v.insert(rng.usize(..=v.len()), dup);
            }
            2 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                v[i].0 = misspell(rng, &v[i].0);
            }
            3 => v.push((
                KEYS[rng.usize(..KEYS.len())].to_string(),
                random_node(rng, 1),
            )),
            4 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                v[i].0 = KEYS[rng.usize(..KEYS.len())].to_string();
            }
            5 => *n = donor,
            6 => {
                let mut deep = n.clone();
                for _ in 0..rng.usize(1..300) {
                    deep = Y::Map(vec![("robot".into(), deep)]);
                }
                *n = deep;
            }
            _ => v.reverse(),
        },
    }
}

// ---- byte and line edits ----

const TOKENS: &[&str] = &[
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    ": ",
    "- ",
    "\n",
    "\n  ",
    "  ",
    "\t",
    "#",
    "'",
    "\"",
    "&a ",
    "*a",
    "!!str ",
    "|",
    ">",
    "---\n",
    "...\n",
    "? ",
    "%YAML 1.2\n",
    "\r",
    "\r\n",
    "\\",
    "~",
    "null",
    "1e999",
    ".nan",
    "-",
    "0",
    "module",
    "robot",
    "points",
    "joints",
    "xyz",
    "base",
    "auto",
    "\u{feff}",
    "\u{0}",
    "é",
    "\u{2028}",
];

fn token_soup(rng: &mut fastrand::Rng) -> Vec<u8> {
    let mut out = String::new();
    for _ in 0..rng.usize(0..400) {
        if rng.u32(0..4) == 0 {
            out.push_str(KEYS[rng.usize(..KEYS.len())]);
        } else {
            out.push_str(TOKENS[rng.usize(..TOKENS.len())]);
        }
    }
    out.into_bytes()
}

fn mutate_bytes(rng: &mut fastrand::Rng, mut b: Vec<u8>, other: &[u8]) -> Vec<u8> {
    for _ in 0..rng.usize(1..8) {
        let at = rng.usize(..=b.len());
        match rng.u32(0..7) {
            0 if !b.is_empty() => {
                let i = rng.usize(..b.len());
                b[i] = rng.u8(..);
            }
            1 if !b.is_empty() => {
                let end = (at + rng.usize(1..64)).min(b.len());
                b.drain(at.min(end)..end);
            }
            2 => {
                let t = TOKENS[rng.usize(..TOKENS.len())].as_bytes();
                b.splice(at..at, t.iter().copied());
            }
            3 => {
                let n = rng.usize(1..200_000);
                let c = *b"[{x9 -:".get(rng.usize(..7)).unwrap_or(&b'[');
                b.splice(at..at, std::iter::repeat_n(c, n));
            }
            4 if !other.is_empty() => {
                let s = rng.usize(..other.len());
                let e = (s + rng.usize(1..400)).min(other.len());
                b.splice(at..at, other[s..e].iter().copied());
            }
            5 => b.truncate(at),
            _ => {
                b.splice(at..at, (0..rng.usize(1..16)).map(|_| rng.u8(..)));
            }
        }
    }
    b
}

fn mutate_lines(rng: &mut fastrand::Rng, text: &str) -> Vec<u8> {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for _ in 0..rng.usize(1..5) {
        if lines.is_empty() {
            break;
        }
        let i = rng.usize(..lines.len());
        match rng.u32(0..8) {
            0 => {
                lines.remove(i);
            }
            1 => {
                let l = lines[i].clone();
                lines.insert(i, l);
            }
            2 => lines[i] = format!(" {}", lines[i]),
            3 => lines[i] = lines[i].trim_start().to_string(),
            4 => lines[i] = format!("\t{}", lines[i].trim_start()),
            5 => lines[i] = lines[i].replacen(": ", ":", 1),
            6 => lines[i] = lines[i].replacen(':', "", 1),
            _ => {
                let l = lines[i].clone();
                for _ in 0..rng.usize(1..100) {
                    lines.insert(i, l.clone());
                }
            }
        }
    }
    let mut out = lines.join(if rng.u32(0..10) == 0 { "\r\n" } else { "\n" });
    out.push('\n');
    out.into_bytes()
}

// ---- the target ----

/// What one case did.
#[derive(Default)]
struct Tally {
    cases: u64,
    refused: u64,
    valid: u64,
    placed: u64,
    place_refused: u64,
    place_skipped: u64,
    ran: u64,
    run_refused: u64,
    largest_message: usize,
    largest_input: usize,
}

/// A plausible value for a scalar (the light edits: the cell mostly stays valid).
fn plausible(rng: &mut fastrand::Rng, s: &str) -> String {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => match rng.u32(0..6) {
            0 => format!("{}", v.round() + f64::from(rng.i32(-20..20))),
            1 => format!("{:.3}", v + rng.f64() * 10.0 - 5.0),
            2 => format!("{:.1}", v * (0.5 + rng.f64())),
            3 => format!("{}", -v),
            // Extreme values that still pass validation (no more decimals than allowed).
            4 => [
                "1e15",
                "-1e15",
                "1e9",
                "0",
                "9007199254740993",
                "1e300",
                "-1e300",
                "0.001",
            ][rng.usize(..8)]
            .to_string(),
            _ => format!("{}", rng.i64(-10_000_000..10_000_000)),
        },
        _ => match rng.u32(0..3) {
            0 => format!("{s}{}", rng.u32(0..10)),
            1 => s.to_uppercase(),
            _ => s.to_string(),
        },
    }
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
        "fuzz: {} cases from seed {seed}: {} refused at load, {} valid ({} placed, {} refused by the place stage, {} not placed: too many points or obstacles; {} run on a {RUN_GRID_DEG} deg grid, {} of them refused); largest input {} bytes, largest message {} bytes",
        tally.cases,
        tally.refused,
        tally.valid,
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
    // The generators reach both sides: refusals and valid cells that are placed.
    if cases >= 1000 {
        assert!(
            tally.refused > cases / 10 && tally.placed > cases / 50,
            "{} refused, {} placed",
            tally.refused,
            tally.placed
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
        assert_eq!(a.planner, b.planner, "{name}");
    }
}
