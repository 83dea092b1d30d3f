//! The fixtures, discovered by file name (paths relative to the repository root):
//!
//! - `cells/<stem>.yaml` -> `tests/golden/<stem>.mod` (the cell as given) and any
//!   `tests/golden/<stem>.<method>.mod` (planned with `--planner <method>`);
//! - `tests/ok/<stem>.yaml` -> `tests/ok/<stem>.mod` (and `<stem>.<method>.mod` likewise): edge
//!   cases that plan;
//! - `tests/err/<stem>.yaml` -> `tests/err/<stem>.stderr`: cells that fail, the file holding
//!   `exit: N` and then the whole stderr.
//!
//! Every cell has its default partner (missing: a mismatch, written by blessing); a partner
//! without its cell, a `.<method>.mod` of an unknown method, a file of another kind in
//! `tests/golden`, `tests/ok` or `tests/err`, and a source without any case are problems.

use super::{file_names, METHODS};
use std::path::Path;

/// What a case's cell must give.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    /// A module on stdout, exit 0: the expected file holds the module.
    Module,
    /// A failure: the expected file holds `exit: N` and the stderr.
    Failure,
}

/// One run of the binary and the file it must reproduce.
#[derive(Clone, Debug)]
pub struct Case {
    /// The cell file, relative to the root (as passed to the binary).
    pub cell: String,
    /// Arguments after the cell (`--planner <method>`).
    pub args: Vec<String>,
    /// The expected file, relative to the root (it may be missing: then a mismatch).
    pub expected: String,
    pub expect: Expect,
}

impl Case {
    /// The command line, for messages.
    pub fn command(&self) -> String {
        std::iter::once(self.cell.as_str())
            .chain(self.args.iter().map(String::as_str))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// All cases, and what is wrong with the fixtures themselves.
pub struct Fixtures {
    pub cases: Vec<Case>,
    pub problems: Vec<String>,
}

struct Source {
    cells: &'static str,
    expected: &'static str,
    ext: &'static str,
    expect: Expect,
}

const SOURCES: [Source; 3] = [
    Source {
        cells: "cells",
        expected: "tests/golden",
        ext: ".mod",
        expect: Expect::Module,
    },
    Source {
        cells: "tests/ok",
        expected: "tests/ok",
        ext: ".mod",
        expect: Expect::Module,
    },
    Source {
        cells: "tests/err",
        expected: "tests/err",
        ext: ".stderr",
        expect: Expect::Failure,
    },
];

/// Finds every case under `root` (the repository root; sorted by expected file) and every
/// problem.
pub fn discover(root: &Path) -> Fixtures {
    let mut cases = Vec::new();
    let mut problems = Vec::new();
    for s in &SOURCES {
        let before = cases.len();
        let cell_names = names_in(root, s.cells, &mut problems);
        let stems: Vec<&str> = cell_names
            .iter()
            .filter_map(|n| n.strip_suffix(".yaml"))
            .collect();
        for stem in &stems {
            if stem.contains('.') {
                problems.push(format!(
                    "{}/{stem}.yaml: a cell's name may not contain '.' (in a partner's name the part after it names a method)",
                    s.cells
                ));
                continue;
            }
            cases.push(Case {
                cell: format!("{}/{stem}.yaml", s.cells),
                args: vec![],
                expected: format!("{}/{stem}{}", s.expected, s.ext),
                expect: s.expect,
            });
        }
        let expected_names = if s.expected == s.cells {
            cell_names.clone()
        } else {
            names_in(root, s.expected, &mut problems)
        };
        for name in expected_names {
            let path = format!("{}/{name}", s.expected);
            if s.cells == s.expected && name.ends_with(".yaml") {
                continue;
            }
            let Some(base) = name.strip_suffix(s.ext) else {
                problems.push(format!(
                    "{path}: not a fixture (expected <stem>.yaml or <stem>{} here)",
                    s.ext
                ));
                continue;
            };
            let (stem, method) = match base.split_once('.') {
                Some((stem, method)) => (stem, Some(method)),
                None => (base, None),
            };
            if !stems.contains(&stem) {
                problems.push(format!(
                    "{path} has no cell {}/{stem}.yaml: remove it or add the cell",
                    s.cells
                ));
                continue;
            }
            let Some(method) = method else {
                continue; // the default partner, pushed above
            };
            if s.expect == Expect::Failure || !METHODS.contains(&method) {
                problems.push(format!(
                    "{path}: '{method}' is not a method; a planner's module is <stem>.<method>{} with <method> one of {}",
                    s.ext,
                    METHODS.join(", ")
                ));
                continue;
            }
            cases.push(Case {
                cell: format!("{}/{stem}.yaml", s.cells),
                args: vec!["--planner".into(), method.into()],
                expected: path,
                expect: s.expect,
            });
        }
        if cases.len() == before {
            problems.push(format!(
                "no case found in {}: the harness is looking in the wrong place",
                s.cells
            ));
        }
    }
    cases.sort_by(|a, b| a.expected.cmp(&b.expected));
    Fixtures { cases, problems }
}

/// The file names in `root/dir`; a missing directory is a problem.
fn names_in(root: &Path, dir: &str, problems: &mut Vec<String>) -> Vec<String> {
    if root.join(dir).is_dir() {
        file_names(&root.join(dir))
    } else {
        problems.push(format!("{dir}: no such directory"));
        vec![]
    }
}
