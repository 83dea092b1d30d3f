//! The README's examples, run: every command its `console` blocks show, each checked against the
//! lines the README quotes under it, so the README and the program cannot drift apart.
//!
//! A `console` block holds commands (`$ ` lines) and what each prints. A `yaml` block whose first
//! line is a comment naming a file (`# my-cell.yaml`) is that file: the commands may use it. The
//! commands run in a scratch directory that sees the repository's `cells/`, `robots/`,
//! `templates/` and `tests/` (symbolic links), so the paths the README shows are the paths the
//! program prints, and the files the commands write land in the scratch directory.
//!
//! What a quoted output means: its lines match the command's output (stderr, then stdout) line
//! for line from the first; a line `...` skips any number of lines; the output may go on after
//! the last quoted line. The one figure that differs from run to run, the run's own time at the
//! end of the summary line (`..., 1 deg grid, 1.01 s`), is compared as "a time". A command
//! whose quoted output starts with `error:` must fail; every other command must succeed.

use crate::common::{root, stderr, stdout};
use std::path::Path;
use std::process::Command;

/// A fenced block of the README: its info string, its first line's number, its lines (without the
/// fence's indentation).
struct Block {
    info: String,
    line: usize,
    lines: Vec<String>,
}

/// The fenced blocks of `text` (fences may be indented, as in a list item).
fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<(usize, Block)> = None;
    for (i, raw) in text.lines().enumerate() {
        let indent = raw.len() - raw.trim_start().len();
        let trimmed = raw.trim_start();
        match open.take() {
            None => {
                if let Some(info) = trimmed.strip_prefix("```") {
                    open = Some((
                        indent,
                        Block {
                            info: info.trim().to_string(),
                            line: i + 2,
                            lines: Vec::new(),
                        },
                    ));
                }
            }
            Some((fence_indent, mut block)) => {
                if trimmed.starts_with("```") {
                    out.push(block);
                } else {
                    let cut = raw.len().min(fence_indent);
                    let body = if raw[..cut].trim().is_empty() {
                        &raw[cut..]
                    } else {
                        raw
                    };
                    block.lines.push(body.to_string());
                    open = Some((fence_indent, block));
                }
            }
        }
    }
    assert!(open.is_none(), "README: a fenced block is never closed");
    out
}

/// One command of a `console` block and the output lines quoted under it.
struct Example {
    line: usize,
    command: String,
    quoted: Vec<String>,
}

fn examples(block: &Block) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    for (k, l) in block.lines.iter().enumerate() {
        if let Some(cmd) = l.strip_prefix("$ ") {
            out.push(Example {
                line: block.line + k,
                command: cmd.trim().to_string(),
                quoted: Vec::new(),
            });
        } else {
            let last = out.last_mut().unwrap_or_else(|| {
                panic!(
                    "README line {}: a console block starts with output, not a `$ ` command",
                    block.line + k
                )
            });
            last.quoted.push(l.clone());
        }
    }
    out
}

/// The summary line's closing run time (`, 1.01 s`) replaced by a placeholder; other lines as
/// they are.
fn normalised(line: &str) -> String {
    if line.starts_with("gen-rapid: ") {
        if let Some((head, tail)) = line.rsplit_once(", ") {
            let figure = tail.strip_suffix(" s").unwrap_or("");
            if !figure.is_empty() && figure.chars().all(|c| c.is_ascii_digit() || c == '.') {
                return format!("{head}, <the run's time> s");
            }
        }
    }
    line.to_string()
}

/// Where `quoted` does not match `actual` (see the module doc), or `None`.
fn mismatch(quoted: &[String], actual: &[String]) -> Option<String> {
    let mut at = 0;
    let mut skipping = false;
    for q in quoted {
        if q.trim() == "..." {
            skipping = true;
            continue;
        }
        let want = normalised(q);
        let found = if skipping {
            actual[at..]
                .iter()
                .position(|a| normalised(a) == want)
                .map(|p| at + p)
        } else {
            (actual.get(at).map(|a| normalised(a)) == Some(want.clone())).then_some(at)
        };
        match found {
            Some(i) => at = i + 1,
            None => {
                return Some(format!(
                    "the README quotes\n    {q}\nbut the output has {}",
                    actual
                        .get(at)
                        .map_or("no more lines".to_string(), |a| format!("\n    {a}"))
                ))
            }
        }
        skipping = false;
    }
    None
}

/// Runs one README command in `dir`: its output lines (stderr, then stdout) and whether it
/// succeeded; `None` for the cargo commands, which this test does not run.
fn run(dir: &Path, command: &str) -> Option<(Vec<String>, bool)> {
    let words: Vec<&str> = command.split_whitespace().collect();
    match words.as_slice() {
        ["cargo", "run", "--release", "--", "cells/trunk.yaml", ">", "trunk.mod"] | ["cargo", "test", "--release"] => None,
        ["head", "-n", n, file] => {
            let n: usize = n.parse().unwrap_or_else(|_| panic!("README: `{command}`: a line count"));
            let text = std::fs::read_to_string(dir.join(file)).unwrap_or_else(|e| panic!("README: `{command}`: {e}"));
            Some((text.lines().take(n).map(str::to_string).collect(), true))
        }
        ["gen-rapid", args @ ..] => {
            let (args, to) = match args {
                [a @ .., ">", file] => (a, Some(*file)),
                a => (a, None),
            };
            let o = Command::new(env!("CARGO_BIN_EXE_gen-rapid"))
                .args(args)
                .current_dir(dir)
                .output()
                .expect("the gen-rapid binary runs");
            let mut lines: Vec<String> = stderr(&o).lines().map(str::to_string).collect();
            match to {
                Some(file) => std::fs::write(dir.join(file), &o.stdout).expect("write the redirected stdout"),
                None => lines.extend(stdout(&o).lines().map(str::to_string)),
            }
            Some((lines, o.status.success()))
        }
        _ => panic!("README shows `{command}`, a command this test does not know how to run: teach it (tests/it/readme.rs)"),
    }
}

/// A scratch directory that sees the repository's inputs under their own names.
fn scratch() -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("a scratch directory");
    for name in ["cells", "robots", "templates", "tests"] {
        std::os::unix::fs::symlink(root().join(name), dir.path().join(name))
            .expect("link an input directory");
    }
    dir
}

#[test]
fn the_readme_commands_print_what_the_readme_quotes() {
    let text = std::fs::read_to_string(root().join("README.md")).expect("read README.md");
    let dir = scratch();
    let all = blocks(&text);
    for b in all.iter().filter(|b| b.info == "yaml") {
        if let Some(name) = b
            .lines
            .first()
            .and_then(|l| l.strip_prefix("# "))
            .filter(|n| n.ends_with(".yaml"))
        {
            std::fs::write(dir.path().join(name.trim()), b.lines.join("\n") + "\n")
                .expect("write a README cell");
        }
    }
    let mut ran = 0;
    let mut failures = Vec::new();
    for b in all.iter().filter(|b| b.info == "console") {
        for ex in examples(b) {
            let Some((lines, ok)) = run(dir.path(), &ex.command) else {
                continue;
            };
            ran += 1;
            let should_fail = ex.quoted.first().is_some_and(|q| q.starts_with("error:"));
            if ok == should_fail {
                failures.push(format!(
                    "README line {}: `{}` {}:\n{}",
                    ex.line,
                    ex.command,
                    if ok {
                        "succeeded, but the README quotes an error"
                    } else {
                        "failed"
                    },
                    lines.join("\n")
                ));
            } else if let Some(why) = mismatch(&ex.quoted, &lines) {
                failures.push(format!("README line {}: `{}`: {why}", ex.line, ex.command));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(
        ran >= 5,
        "README: only {ran} commands ran; are its console blocks still marked `console`?"
    );
}

/// Every option the README's command-line table names is one `gen-rapid --help` describes, and
/// every relative link of the README leads to a file of the repository.
#[test]
fn the_readme_options_and_links_exist() {
    let text = std::fs::read_to_string(root().join("README.md")).expect("read README.md");
    let help = stdout(&crate::common::gen_rapid(&["--help"]));
    let mut missing = Vec::new();
    for row in text.lines().filter(|l| l.starts_with("| `-")) {
        let flag = row[3..].split(['`', ' ']).next().unwrap_or("");
        if !help.contains(flag) {
            missing.push(format!("option {flag} (not in --help)"));
        }
    }
    for (_, rest) in text.match_indices("](").map(|(i, _)| ((), &text[i + 2..])) {
        let target = rest.split(')').next().unwrap_or("");
        if !target.contains("://") && !target.starts_with('#') && !root().join(target).exists() {
            missing.push(format!("link {target}"));
        }
    }
    assert!(missing.is_empty(), "README: {}", missing.join(", "));
}

#[test]
fn the_matcher_holds_quotes_to_the_output() {
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    let out = s(&["a", "b", "c", "gen-rapid: x: 10 moves, 1 deg grid, 0.31 s"]);
    assert!(mismatch(&s(&["a", "b"]), &out).is_none());
    assert!(
        mismatch(&s(&["a", "c"]), &out).is_some(),
        "a skipped line needs `...`"
    );
    assert!(mismatch(&s(&["...", "c"]), &out).is_none());
    assert!(mismatch(
        &s(&["...", "gen-rapid: x: 10 moves, 1 deg grid, 2.50 s"]),
        &out
    )
    .is_none());
    assert!(mismatch(
        &s(&["...", "gen-rapid: x: 11 moves, 1 deg grid, 0.31 s"]),
        &out
    )
    .is_some());
    assert!(
        mismatch(&s(&["a", "b", "c", "d", "e"]), &out).is_some(),
        "a line beyond the output"
    );
}
