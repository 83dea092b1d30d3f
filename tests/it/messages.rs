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

/// A cell with a tool, a work object and robtarget points (tests/ok/tool_wobj_robtargets.yaml).
const TOOL_CELL: &str = "module: Long\nrobot:\n  urdf: URDF\n  base: [0, 0, 0]\ntool:\n  name: tTorch\n  tframe: [[0, 0, 250], [0.9659258, 0, 0.2588190, 0]]\n  shapes:\n    - { name: neck, cylinder: { from: [0, 0, 0], to: [0, 0, 200], radius: 20 } }\nwobj:\n  name: wobjTable\n  uframe: [[700, -200, 400], [1, 0, 0, 0]]\nobstacles:\n  - { name: table, box: { min: [600, -300, 0], max: [1000, 300, 400] } }\npoints:\n  - { name: P1, joints: [-30, 0, 0] }\n  - { name: W1, robtarget: [[100, 200, 150], [0, 0, 1, 0]] }\n  - { name: W2, robtarget: [[200, 300, 150], [0, 0, 1, 0], [0, -1, 0, 0]], speed: v100, zone: z5 }\n";

#[test]
fn tool_work_object_and_robtarget_messages_are_bounded_too() {
    // The tool, work object and robtarget refusals quote names, lists and quaternions from
    // lines the input can make as long as it likes: each message stays short, says where, and
    // is the refusal meant (not some other one).
    let pad = " ".repeat(200_000);
    let huge = "y".repeat(100_000);
    let one = |from: &str, to: String| {
        assert!(TOOL_CELL.contains(from), "{from}");
        TOOL_CELL.replacen(from, &to, 1)
    };
    let neck = "{ name: neck, cylinder: { from: [0, 0, 0], to: [0, 0, 200], radius: 20 } }";
    let cases = [
        (
            "tframe quaternion after 200,000 spaces",
            one(
                "[[0, 0, 250], [0.9659258, 0, 0.2588190, 0]]",
                format!("[[0, 0, 250],{pad}[2, 0, 0.2588190, 0]]"),
            ),
            "tool.tframe quaternion [2.0, 0.0, 0.258819, 0.0] has norm",
            7,
            Some('['),
        ),
        (
            "tframe with 20,000 lists",
            one(
                "[[0, 0, 250], [0.9659258, 0, 0.2588190, 0]]",
                format!(
                    "[[0, 0, 250], [0.9659258, 0, 0.2588190, 0]{}]",
                    ", [1, 0, 0, 0]".repeat(20_000)
                ),
            ),
            "tool.tframe must be [[x, y, z], [q1, q2, q3, q4]], found 20002 lists",
            7,
            Some('['),
        ),
        (
            "huge tool name",
            one("name: tTorch", format!("name: t{huge}")),
            "tool name 'tyyy",
            6,
            Some('t'),
        ),
        (
            "tool shape with a huge name and radius 0",
            one(
                neck,
                format!("{{ name: {huge}, cylinder: {{ from: [0, 0, 0], to: [0, 0, 200], radius: 0 }} }}"),
            ),
            "cylinder.radius = 0 must be a number > 0 (mm)",
            9,
            Some('0'),
        ),
        (
            "tool shape with a huge name and no kind",
            one(neck, format!("{{ name: {huge} }}")),
            "must give exactly one of cylinder, box, sphere",
            9,
            Some('{'),
        ),
        (
            "tool shape with a huge name twice",
            one(
                neck,
                format!("{{ name: {huge}, sphere: {{ centre: [0, 0, 0], radius: 5 }} }}\n    - {{ name: {huge}, sphere: {{ centre: [0, 0, 9], radius: 5 }} }}"),
            ),
            "is used twice (first at line 9)",
            10,
            Some('y'),
        ),
        (
            "huge work object name",
            one("name: wobjTable", format!("name: w{huge}")),
            "work object name 'wyyy",
            11,
            Some('w'),
        ),
        (
            "uframe position of 50,003 numbers",
            one("[[700, -200, 400],", format!("[[700, -200, 400{}],", ", 1".repeat(50_000))),
            "wobj.uframe position must have 3 numbers, found 50003",
            12,
            Some('['),
        ),
        (
            "robtarget quaternion after 200,000 spaces",
            one(
                "[[100, 200, 150], [0, 0, 1, 0]]",
                format!("[[100, 200, 150],{pad}[0, 0, 1, 0.5]]"),
            ),
            "point 'W1' robtarget quaternion [0.0, 0.0, 1.0, 0.5] has norm 1.118034, not 1",
            17,
            Some('['),
        ),
        (
            "huge robtarget point name",
            one("name: W1,", format!("name: W{huge},")),
            "point name 'Wyyy",
            17,
            Some('W'),
        ),
        (
            "motion.tool beside the tool block, on a long line",
            format!("{TOOL_CELL}motion:\n  tool: {}{pad}\n", "t".repeat(30)),
            "is given beside the tool block (tool 'tTorch' at line 6)",
            20,
            Some('t'),
        ),
    ];
    for (what, text, expected, line, at_caret) in cases {
        let (code, err) = refused("tool.yaml", &text);
        let head = &err[..err.len().min(3000)];
        assert_eq!(code, Some(1), "{what}: {head}");
        assert!(
            err.len() < MAX_MESSAGE_BYTES,
            "{what}: {} bytes:\n{head}",
            err.len()
        );
        assert!(
            err.contains(expected),
            "{what}: not the refusal meant:\n{err}"
        );
        // A value is quoted cut to a few dozen characters (not only by the backstop on a whole
        // message line, 1000 characters).
        let first = err.lines().next().unwrap_or_default();
        assert!(first.len() < 300, "{what}: a long first line:\n{first}");
        assert!(
            err.contains(&format!("tool.yaml:{line}:")),
            "{what}: not at line {line}:\n{err}"
        );
        assert!(err.contains("..."), "{what}: nothing cut:\n{err}");
        let (_, c) = under_caret(&err);
        assert_eq!(
            c, at_caret,
            "{what}: the caret is not on its character:\n{err}"
        );
    }
}

#[test]
fn the_warning_about_a_urdf_without_a_controller_file_is_bounded_too() {
    // The warning quotes the URDF's path as the cell gives it: here 3,000 characters of `./`
    // before a copy of the IRB 1400's URDF that has no controller file beside it.
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = crate::common::root().join("robots/irb1400.urdf");
    std::fs::copy(urdf, dir.path().join("copy.urdf")).expect("copy urdf");
    let long = format!("{}copy.urdf", "./".repeat(1500));
    let path = temp_cell(dir.path(), "warn.yaml", &CELL.replace("URDF", &long));
    let o = gen_rapid(&[path.to_str().expect("utf-8")]);
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    let warning = err.lines().next().unwrap_or_default();
    assert!(
        warning.starts_with("warning: ") && warning.contains("has no controller file"),
        "{err}"
    );
    assert!(warning.contains("..."), "nothing cut: {warning}");
    assert!(warning.len() < MAX_MESSAGE_BYTES, "{} bytes", warning.len());
}

/// Every refusal on file (`tests/err/`) says what to do about it: one `error:` line, and a
/// `help:` line after it (the contract: where, what was expected, a help line).
#[test]
fn every_error_fixture_has_one_error_and_a_help_line() {
    let dir = crate::common::root().join("tests/err");
    let (mut missing, mut read) = (Vec::new(), 0);
    for entry in std::fs::read_dir(&dir).expect("tests/err") {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "stderr") {
            read += 1;
            let text = std::fs::read_to_string(&path).expect("fixture");
            let errors = text.lines().filter(|l| l.starts_with("error: ")).count();
            let helps = text.lines().filter(|l| l.starts_with("help: ")).count();
            if errors != 1 || helps != 1 {
                missing.push(format!("{}: {errors} error, {helps} help", path.display()));
            }
        }
    }
    assert!(read >= 90, "only {read} fixtures read in {}", dir.display());
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}
