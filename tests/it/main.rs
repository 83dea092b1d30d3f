//! The integration tests: one binary (`cargo test --release --test it`), one module per subject.
//! Where a new test belongs:
//!
//! - `golden`: the one golden harness. A new example cell, a new edge case that plans, or a new
//!   error needs no code, only files: `cells/<stem>.yaml` + `tests/golden/<stem>.mod` (and
//!   `tests/golden/<stem>.<method>.mod` for `--planner <method>`), `tests/ok/<stem>.yaml` +
//!   `.mod`, `tests/err/<stem>.yaml` + `.stderr`. Refresh them all with `GEN_RAPID_BLESS=1`.
//! - `safety`: the independent controller-like re-check (`docs/recheck.md`) of every module on
//!   file, and of the re-check itself (what the base stands on).
//! - `recheck`: the re-check's own tests: its inverse kinematics, its reading of the robot's
//!   shapes and motion bound, hand-written modules with process moves that pass or fail.
//! - `cli`: the command line as such: stdout, stderr, `-o`, flags, exit statuses, `--help`.
//! - `convention`: the robot convention stated (header lines, the warning, `robot.controller`).
//! - `compare`: `gen-rapid compare` and the paper's comparison of the three searches.
//! - `fuzz`: the seeded fuzz target over loading, validating and placing cells
//!   (`GEN_RAPID_FUZZ_CASES`, `GEN_RAPID_FUZZ_SEED`).
//! - `frames`: `robot.frame: base` (the numbers written in the base frame, by hand; the same
//!   joints as in the cell frame).
//! - `locate`: `base: auto`, `xyz` points and branches, `gen-rapid locate`.
//! - `preview_browser`: the `--html` preview page in headless Chromium (skipped, saying so,
//!   where no Chromium is installed).
//! - `report`: `--report`, against its JSON Schema, the module and independent kinematics.
//! - `templates`: `--template` (the example templates under `templates/`) and `--proc`.
//! - `pictures`: `--svg` when planning fails (the picture of why), and the help lines that
//!   suggest one.
//! - `messages`: error messages bounded whatever the input, and located (their texts are
//!   fixtures in `tests/err/`).
//! - `random_cells`: generated cells (with and without a tool), every method, every module
//!   through the dense re-check.
//! - `process`: the example cells with process moves run as a controller runs them
//!   (`common/process.rs`: MoveL and MoveC sampled along the TCP path by the tests' own IK).
//! - `tool_cells`: the example cells with a tool, every method, and the tool's volume at work.
//! - `warnings`: axes 4 and 6 near their limits (stderr and the report's `near_limits`).
//! - `readme`: every command the README shows, run, against the lines it quotes.
//! - `tidy`: the house rules read from `src/` (dependency direction, no import cycles between
//!   files, file length, no issue numbers, module docs), each checker held to a made-up
//!   violation.
//! - `common`: helpers: running the binary, temporary cells, reading a module (`module`), the
//!   fixtures (`fixtures`), the dense re-check (`dense` and the files it uses: `controller`,
//!   `program`, `sweep`, ...), and `library`, the only file here that names the library's paths.
//!
//! A test about the library's internals belongs in the source file it tests, not here.

mod cli;
mod common;
mod compare;
mod convention;
mod estimate;
mod frames;
mod fuzz;
mod golden;
mod hostile;
mod locate;
mod messages;
mod pictures;
mod preview_browser;
mod process;
mod random_cells;
mod readme;
mod recheck;
mod refine;
mod report;
mod safety;
mod templates;
mod tidy;
mod tool_cells;
mod warnings;
