//! Shared by the integration tests: running the binary, temporary cells, reading modules, the
//! fixtures, the dense re-check, and (in `library`) every library path the tests use.
#![allow(dead_code)]

pub mod actions;
pub mod controller;
pub mod data;
pub mod dense;
pub mod fixtures;
pub mod follow;
pub mod library;
pub mod links;
pub mod module;
pub mod opw;
pub mod paths;
pub mod process;
pub mod program;
pub mod reach;
pub mod routine;
pub mod svg;
pub mod sweep;
pub mod tcp;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The search methods as the cell format spells them (`planner.method`, `--planner`; docs/cell.md).
/// `cli::help_teaches_the_format_examples_and_exit_statuses` holds them against `--help`.
pub const METHODS: [&str; 3] = ["neighboring", "depth-first", "extensile"];

/// The repository root (the package directory).
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

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A path as the command line takes it.
pub fn arg(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 path")
}

/// Writes a cell into `dir`, with `URDF` in `body` replaced by the bundled robot's absolute path.
pub fn temp_cell(dir: &Path, name: &str, body: &str) -> PathBuf {
    let urdf = root().join("robots/irb1400.urdf");
    let text = body.replace("URDF", &urdf.display().to_string());
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write cell");
    path
}

/// 1-based number of the first line of `text` containing `needle`.
pub fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .map(|i| i + 1)
        .unwrap_or_else(|| panic!("no line with {needle}"))
}

/// A file of the repository, as text (`rel` from the root).
pub fn read(rel: &str) -> String {
    std::fs::read_to_string(root().join(rel)).unwrap_or_else(|e| panic!("read {rel}: {e}"))
}

/// True when golden files may be rewritten: `GEN_RAPID_BLESS=1`, and never under CI (panics).
pub fn blessing() -> bool {
    bless_wanted(
        std::env::var("GEN_RAPID_BLESS").ok().as_deref(),
        std::env::var_os("CI").is_some(),
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

/// The rule of [`blessing`], given the value of `GEN_RAPID_BLESS` and whether `CI` is set.
pub fn bless_wanted(var: Option<&str>, ci: bool) -> Result<bool, String> {
    match var {
        Some("1") if ci => Err("GEN_RAPID_BLESS is refused under CI: golden files change only on purpose, on a developer's machine".into()),
        Some("1") => Ok(true),
        _ => Ok(false),
    }
}

/// Names of the files in `dir` (sorted).
pub fn file_names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .filter_map(|e| e.ok())
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}
