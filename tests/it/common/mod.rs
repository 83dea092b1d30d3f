//! Shared by the integration tests: running the binary, blessing golden files.
#![allow(dead_code)]

pub mod dense;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `gen-rapid` with `args` in the repository root.
pub fn gen_rapid(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gen-rapid"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("the gen-rapid binary runs")
}

/// True when golden files may be rewritten: GEN_RAPID_BLESS=1, and never under CI.
pub fn blessing() -> bool {
    let bless = std::env::var("GEN_RAPID_BLESS").is_ok_and(|v| v == "1");
    if bless && std::env::var_os("CI").is_some() {
        panic!("GEN_RAPID_BLESS is refused under CI: golden files change only on purpose, on a developer's machine");
    }
    bless
}

/// Compares `actual` with the golden file, or rewrites it when blessing.
pub fn check_golden(path: &Path, actual: &str) {
    if blessing() {
        std::fs::write(path, actual).expect("write golden");
        return;
    }
    let expected = std::fs::read_to_string(path)
        .unwrap_or_else(|_| panic!("missing golden file {}; create it with GEN_RAPID_BLESS=1 and read it before committing", path.display()));
    if expected != actual {
        let diff_line = expected
            .lines()
            .zip(actual.lines())
            .position(|(a, b)| a != b)
            .map(|i| i + 1)
            .unwrap_or(expected.lines().count().min(actual.lines().count()) + 1);
        panic!(
            "{} differs from the output at line {diff_line}\n--- expected\n{expected}\n--- actual\n{actual}",
            path.display()
        );
    }
}

/// Files in `dir` ending in `ext`, sorted.
pub fn files(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(ext))
        .collect();
    v.sort();
    v
}
