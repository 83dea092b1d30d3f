//! Error messages end to end: bounded whatever the input (a long line is shown as a window
//! around its column, a long value is cut), and located (`file:line:column`, the caret under the
//! character at fault). The message texts themselves are fixtures (`tests/err/`).

use crate::common::{gen_rapid, stderr, temp_cell};

/// No message is longer than this, whatever the input.
const MAX_MESSAGE_BYTES: usize = 2048;

const CELL: &str = "module: Long\nrobot:\n  urdf: URDF\n  base: [0, 0, 0]\nobstacles:\n  - { name: table, box: { min: [600, -300, 0], max: [1000, 300, 400] } }\npoints:\n  - { name: P1, joints: [-30, 0, 0] }\n  - { name: P2, joints: [30, 0, 0] }\n";

/// Runs the cell text and returns (exit status, stderr), checking that stdout stays empty.
fn refused(name: &str, text: &str) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = temp_cell(dir.path(), name, text);
    let o = gen_rapid(&[path.to_str().expect("utf-8")]);
    assert!(o.stdout.is_empty(), "{name}: stdout must stay empty");
    (o.status.code(), stderr(&o))
}

/// The source line and the character under the caret, from a rendered message.
fn under_caret(err: &str) -> (String, Option<char>) {
    let lines: Vec<&str> = err.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.trim_start().starts_with('|') && l.trim_end().ends_with('^'))
        .expect("a caret line");
    let source = lines[at - 1];
    let bar = source.find(" | ").expect("a numbered source line") + 3;
    let caret = lines[at].find('^').expect("caret");
    (
        source[bar..].to_string(),
        source[..].chars().nth(caret).filter(|_| caret >= bar),
    )
}

#[test]
fn a_200000_character_line_of_brackets_gives_a_short_message() {
    let text = format!("module: Deep\npoints: {}\n", "[".repeat(200_000));
    let (code, err) = refused("deep.yaml", &text);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.len() < MAX_MESSAGE_BYTES, "{} bytes:\n{err}", err.len());
    assert!(err.contains("deep.yaml:2:"), "{err}");
    let (source, c) = under_caret(&err);
    assert!(
        source.starts_with("...") && source.ends_with("..."),
        "{source}"
    );
    assert_eq!(c, Some('['), "{err}");
}

#[test]
fn a_long_line_is_cut_around_the_column_and_the_caret_stays_on_its_character() {
    // An inverted box after a 300-character name: the message points at the box's `{`, past
    // column 300.
    let name = format!("table_{}", "x".repeat(300));
    let text = CELL.replace(
        "{ name: table, box: { min: [600, -300, 0], max: [1000, 300, 400] } }",
        &format!("{{ name: {name}, box: {{ min: [1000, -300, 0], max: [1000, 300, 400] }} }}"),
    );
    let (code, err) = refused("long.yaml", &text);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.len() < MAX_MESSAGE_BYTES, "{} bytes:\n{err}", err.len());
    let column = "  - { name: ".len() + name.len() + ", box: ".len() + 1;
    assert!(err.contains(&format!("long.yaml:6:{column}")), "{err}");
    let (source, c) = under_caret(&err);
    assert!(
        source.starts_with("...") && !source.ends_with("..."),
        "{source}"
    );
    assert_eq!(c, Some('{'), "{err}");
    // The name is quoted shortened.
    assert!(err.contains("obstacle 'table_xxx"), "{err}");
    assert!(!err.contains(&name), "{err}");
}

#[test]
fn huge_values_are_quoted_shortened() {
    let huge = "y".repeat(100_000);
    for (what, text) in [
        ("module", CELL.replace("module: Long", &format!("module: {huge}"))),
        ("key", format!("{CELL}{huge}: 1\n")),
        (
            "string value",
            CELL.replace("base: [0, 0, 0]", &format!("base: {huge}")),
        ),
        (
            "number",
            CELL.replace("joints: [30, 0, 0]", &format!("joints: [30, {huge}, 0]")),
        ),
        (
            "duplicate obstacle",
            CELL.replace(
                "  - { name: table,",
                &format!("  - {{ name: {huge}, box: {{ min: [0, 0, 0], max: [1, 1, 1] }} }}\n  - {{ name: {huge},"),
            ),
        ),
        (
            "urdf path",
            CELL.replace("urdf: URDF", &format!("urdf: {huge}.urdf")),
        ),
    ] {
        let (code, err) = refused("huge.yaml", &text);
        assert_eq!(code, Some(1), "{what}: {}", &err[..err.len().min(500)]);
        assert!(
            err.len() < MAX_MESSAGE_BYTES,
            "{what}: {} bytes:\n{}",
            err.len(),
            &err[..err.len().min(3000)]
        );
        assert!(err.contains("huge.yaml:"), "{what}: not located:\n{err}");
        assert!(err.contains("..."), "{what}: nothing cut:\n{err}");
    }
}

#[test]
fn control_characters_of_the_input_do_not_reach_the_terminal() {
    let text = CELL.replace("module: Long", "module: \"L\\e[31mong\"");
    let (code, err) = refused("esc.yaml", &text);
    assert_eq!(code, Some(1), "{err}");
    assert!(!err.contains('\u{1b}'), "{err:?}");
    assert!(err.contains("esc.yaml:1:9"), "{err}");
}
