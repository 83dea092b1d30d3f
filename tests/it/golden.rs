//! Golden files. Every `cells/*.yaml` planned by the `gen-rapid` binary must give
//! `tests/golden/<stem>.mod` byte for byte; every `tests/err/<name>.yaml` must fail with the exit
//! status and stderr in `tests/err/<name>.stderr` (first line `exit: N`).
//!
//! Refresh after a deliberate change with `GEN_RAPID_BLESS=1 cargo test --release --test golden`
//! (refused when `CI` is set), then read every changed file before committing it.

use crate::common::{check_golden, files, gen_rapid, root};

#[test]
fn every_example_cell_matches_its_golden_module() {
    let cells = files(&root().join("cells"), ".yaml");
    assert!(
        cells.len() >= 3,
        "expected the example cells, found {cells:?}"
    );
    for cell in cells {
        let stem = cell
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("utf-8 name");
        let rel = format!("cells/{stem}.yaml");
        let out = gen_rapid(&[&rel]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{rel} failed:\n{stderr}");
        let text = String::from_utf8(out.stdout).expect("the module is UTF-8 (ASCII)");
        check_golden(&root().join(format!("tests/golden/{stem}.mod")), &text);
        // The same cell gives the same bytes again.
        let again = gen_rapid(&[&rel]);
        assert_eq!(again.stdout, text.as_bytes(), "{rel}: a second run differs");
    }
}

#[test]
fn every_bad_cell_fails_as_recorded() {
    let cases = files(&root().join("tests/err"), ".yaml");
    assert!(!cases.is_empty(), "no error cases found in tests/err");
    for case in cases {
        let stem = case
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("utf-8 name");
        let rel = format!("tests/err/{stem}.yaml");
        let out = gen_rapid(&[&rel]);
        assert!(
            out.stdout.is_empty(),
            "{rel}: stdout must stay empty on error"
        );
        assert!(!out.status.success(), "{rel}: must fail");
        let actual = format!(
            "exit: {}\n{}",
            out.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&out.stderr)
        );
        check_golden(&root().join(format!("tests/err/{stem}.stderr")), &actual);
    }
}
