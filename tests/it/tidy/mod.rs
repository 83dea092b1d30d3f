//! The house rules, read from `src/` (as rust-analyzer's tidy test reads its own source): each
//! module uses only the modules ARCHITECTURE.md allows it (the stages' order and the leaves,
//! written once here as the document states them), no two files import each other round a
//! cycle, a file over [`MAX_LINES`] says why in its first doc line, no comment cites an issue
//! number, and every file opens with a `//!` doc. Each rule is a function of the source files
//! alone, held by `checker_tests.rs` to fail on a small made-up violation.

mod checker_tests;
mod scan;

use scan::{Crate, ModPath, Source};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The stages in pipeline order (ARCHITECTURE.md, "Dependency direction"): a stage may use the
/// stages to its left.
const ORDER: &[&str] = &[
    "robot",
    "cell",
    "budget",
    "place",
    "collision",
    "plan",
    "timing",
    "refine",
    "process",
    "output",
    "error",
    "load",
    "pipeline",
    "cli",
];

/// The leaves: any stage may use them; they use no other module of the crate.
const LEAVES: &[&str] = &[
    "blank_key",
    "excerpt",
    "geometry",
    "input",
    "names",
    "parallel",
    "precision",
    "progress",
    "rapid_data",
    "zeroed",
];

/// The most lines a file may have without saying why in its first doc line.
const MAX_LINES: usize = 800;

/// What the first doc line of a longer file holds before its reason
/// (`//! Tests of the tool's part of the model (long: ...)`).
const LONG_MARK: &str = "long:";

/// The library's source files, by path relative to `src/`.
fn sources() -> Vec<Source> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = Vec::new();
    let mut dirs = vec![src.clone()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("src/ is readable") {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let rel = path.strip_prefix(&src).expect("under src/");
                let rel = rel.to_string_lossy().replace('\\', "/");
                let text = std::fs::read_to_string(&path).expect("a source file is UTF-8");
                out.push(Source { path: rel, text });
            }
        }
    }
    out.sort_by(|a, b| a.path.cmp(&b.path));
    out
}

fn library() -> Crate {
    scan::parse(&sources(), "lib.rs").unwrap_or_else(|e| panic!("src/ does not parse: {e}"))
}

/// Every module the crate's root declares is in [`ORDER`] or [`LEAVES`], once; and every name
/// there is a module.
pub fn unlisted_modules(krate: &Crate, order: &[&str], leaves: &[&str]) -> Vec<String> {
    let tops: BTreeSet<&str> = krate
        .modules
        .keys()
        .filter(|m| m.len() == 1)
        .map(|m| m[0].as_str())
        .collect();
    let mut out = Vec::new();
    for t in &tops {
        let n = order.iter().chain(leaves).filter(|x| *x == t).count();
        if n != 1 {
            out.push(format!(
                "module `{t}` is listed {n} times among the stages and leaves"
            ));
        }
    }
    for t in order.iter().chain(leaves) {
        if !tops.contains(t) {
            out.push(format!("`{t}` is listed but is no module of the crate"));
        }
    }
    out
}

/// Each use of another top-level module that the order does not allow: a stage uses a stage
/// to its right, or a leaf uses any other module (test code aside).
pub fn direction_violations(krate: &Crate, order: &[&str], leaves: &[&str]) -> Vec<String> {
    let top = |m: &ModPath| m.first().cloned();
    let rank = |t: &str| order.iter().position(|x| *x == t);
    let mut out = Vec::new();
    for (file, uses) in &krate.uses {
        for u in uses {
            let (Some(from), Some(to)) = (top(&u.from), top(&u.target)) else {
                continue;
            };
            if from == to {
                continue;
            }
            let allowed = if leaves.contains(&from.as_str()) {
                false
            } else if leaves.contains(&to.as_str()) {
                true
            } else {
                matches!((rank(&from), rank(&to)), (Some(a), Some(b)) if b < a)
            };
            if !allowed {
                out.push(format!(
                    "src/{file}: `{from}` uses `{to}` (`{}`), which the order does not allow",
                    u.written
                ));
            }
        }
    }
    out
}

/// The cycles of files importing each other, outside test code: each a list of files, round
/// the cycle. A file and the module file of its own directory (the `mod.rs` that declares it,
/// or the file a `#[path]` names it from) may use each other: the module file is the face of its
/// files (it declares and re-exports them, they build on its types); any other import counts.
pub fn file_cycles(krate: &Crate) -> Vec<Vec<String>> {
    let parent_file = |file: &str| -> Option<String> {
        let module = krate
            .modules
            .iter()
            .find(|(m, f)| *f == file && !m.is_empty())?
            .0;
        krate.modules.get(&module[..module.len() - 1]).cloned()
    };
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, uses) in &krate.uses {
        let entry = edges.entry(file.clone()).or_default();
        for u in uses {
            let Some(to) = krate.modules.get(&u.target) else {
                continue;
            };
            if to == file || krate.test_files.contains(to) {
                continue;
            }
            let parent_child = parent_file(file).as_deref() == Some(to.as_str())
                || parent_file(to).as_deref() == Some(file.as_str());
            if !parent_child {
                entry.insert(to.clone());
            }
        }
    }
    strongly_connected(&edges)
        .into_iter()
        .filter(|c| c.len() > 1)
        .collect()
}

/// The strongly connected components of a graph (Tarjan), each in a fixed order.
fn strongly_connected(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let i = s.index.len();
        s.index.insert(v, i);
        s.low.insert(v, i);
        s.stack.push(v);
        s.on.insert(v);
        let next: Vec<&'a str> = s
            .edges
            .get(v)
            .map(|n| n.iter().map(String::as_str).collect())
            .unwrap_or_default();
        for w in next {
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low.get_mut(v).expect("visited");
                *lv = (*lv).min(lw);
            } else if s.on.contains(w) {
                let iw = s.index[w];
                let lv = s.low.get_mut(v).expect("visited");
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            comp.sort();
            s.out.push(comp);
        }
    }
    let mut s = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in edges.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out
}

/// The files over `max` lines whose first doc line does not say why ([`LONG_MARK`]), and
/// those within `max` whose first doc line still says they are long.
pub fn long_files(sources: &[Source], max: usize) -> Vec<String> {
    sources
        .iter()
        .filter_map(|s| {
            let n = s.text.lines().count();
            let first = s.text.lines().find(|l| l.starts_with("//!")).unwrap_or("");
            match (n > max, first.contains(LONG_MARK)) {
                (true, false) => Some(format!(
                    "src/{}: {n} lines, over {max}, and its first doc line does not say why \
                     (`{LONG_MARK} ...`)",
                    s.path
                )),
                (false, true) => Some(format!(
                    "src/{}: {n} lines, within {max}, but its first doc line says it is long",
                    s.path
                )),
                _ => None,
            }
        })
        .collect()
}

/// The lines that cite an issue number: `issue 10`, `issues 8`, `issue #3` anywhere, or `#12`
/// after a space or a bracket.
pub fn issue_numbers(sources: &[Source]) -> Vec<String> {
    let mut out = Vec::new();
    for s in sources {
        for (i, line) in s.text.lines().enumerate() {
            if cites_issue(line) {
                out.push(format!("src/{}:{}: {}", s.path, i + 1, line.trim()));
            }
        }
    }
    out
}

fn cites_issue(line: &str) -> bool {
    let lower = line.to_ascii_lowercase();
    let b = lower.as_bytes();
    let digit_at = |k: usize| b.get(k).is_some_and(u8::is_ascii_digit);
    let word_start = |k: usize| k == 0 || !b[k - 1].is_ascii_alphanumeric();
    for (k, _) in lower.match_indices("issue") {
        if !word_start(k) {
            continue;
        }
        let mut j = k + 5;
        if b.get(j) == Some(&b's') {
            j += 1;
        }
        while b.get(j) == Some(&b' ') {
            j += 1;
        }
        if b.get(j) == Some(&b'#') {
            j += 1;
        }
        if digit_at(j) {
            return true;
        }
    }
    (0..b.len()).any(|k| {
        b[k] == b'#'
            && digit_at(k + 1)
            && (k == 0 || matches!(b[k - 1], b' ' | b'(' | b'['))
            && !b[k + 1..]
                .iter()
                .take_while(|c| c.is_ascii_alphanumeric())
                .any(|c| !c.is_ascii_digit())
    })
}

/// The files whose first line that is not blank is not a `//!` doc.
pub fn missing_docs(sources: &[Source]) -> Vec<String> {
    sources
        .iter()
        .filter(|s| {
            !s.text
                .lines()
                .find(|l| !l.trim().is_empty())
                .is_some_and(|l| l.starts_with("//!"))
        })
        .map(|s| format!("src/{}: does not open with a `//!` doc", s.path))
        .collect()
}

/// The order and the leaves as a document states them: the backticked names of its
/// "Dependency direction:" chain (up to the sentence's end), and those in the parentheses after
/// "leaves (" that follow it.
pub fn stated_order(doc: &str) -> Option<(Vec<String>, Vec<String>)> {
    let ticked = |s: &str| -> Vec<String> {
        s.split('`')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect()
    };
    let from = doc.find("Dependency direction:")?;
    let rest = &doc[from..];
    let chain = &rest[..rest.find(". ")?];
    let leaves = &rest[rest.find("leaves (")?..];
    let leaves = &leaves[..leaves.find(')')?];
    Some((ticked(chain), ticked(leaves)))
}

fn assert_none(what: &str, found: Vec<String>) {
    assert!(found.is_empty(), "{what}:\n{}", found.join("\n"));
}

#[test]
fn the_order_here_is_the_one_architecture_md_states() {
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md"))
            .expect("ARCHITECTURE.md is readable");
    let (order, leaves) =
        stated_order(&doc).expect("ARCHITECTURE.md states the dependency direction");
    assert_eq!(order, ORDER, "the stages' order");
    assert_eq!(leaves, LEAVES, "the leaves");
}

#[test]
fn every_module_is_a_stage_or_a_leaf() {
    assert_none("modules", unlisted_modules(&library(), ORDER, LEAVES));
}

#[test]
fn modules_use_only_what_lies_to_their_left_and_the_leaves() {
    assert_none(
        "dependency direction (ARCHITECTURE.md)",
        direction_violations(&library(), ORDER, LEAVES),
    );
}

#[test]
fn no_files_import_each_other_round_a_cycle() {
    let cycles: Vec<String> = file_cycles(&library())
        .iter()
        .map(|c| c.join(" <-> "))
        .collect();
    assert_none("import cycles between files", cycles);
}

#[test]
fn long_files_say_why() {
    assert_none("file length", long_files(&sources(), MAX_LINES));
}

#[test]
fn no_comment_cites_an_issue_number() {
    assert_none("issue numbers", issue_numbers(&sources()));
}

#[test]
fn every_file_opens_with_a_module_doc() {
    assert_none("module docs", missing_docs(&sources()));
}
