//! The robot convention is never silent: the module names the URDF, the
//! controller file and the coupling; a URDF without a controller file warns on stderr (never on
//! stdout); `robot.controller` names one explicitly, so a renamed URDF keeps its convention.

use crate::common::module::Module;
use crate::common::{arg, gen_rapid, read, root, stderr, stdout};

/// tests/ok/no_obstacles_depth_first.yaml with its URDF replaced by `urdf` and `extra` lines
/// added to its robot block.
fn cell_with(dir: &std::path::Path, urdf: &str, extra: &str) -> std::path::PathBuf {
    let text = read("tests/ok/no_obstacles_depth_first.yaml");
    let text = text.replace(
        "urdf: ../../robots/irb1400.urdf",
        &format!("urdf: {urdf}{extra}"),
    );
    assert!(text.contains(urdf), "{text}");
    let path = dir.join("cell.yaml");
    std::fs::write(&path, text).expect("write cell");
    path
}

#[test]
fn the_header_names_the_urdf_the_controller_file_and_the_coupling() {
    let m = Module::parse(&read("tests/golden/trunk.mod")).expect("module");
    assert_eq!(m.urdf.as_deref(), Some("irb1400.urdf"));
    assert_eq!(m.controller.as_deref(), Some("irb1400.controller.yaml"));
    assert_eq!(
        m.coupling.as_deref(),
        Some("parallelogram (axis 3 = URDF joint 3 + joint 2)")
    );
}

#[test]
fn a_renamed_urdf_warns_and_says_so_and_robot_controller_keeps_its_convention() {
    let dir = tempfile::tempdir().expect("tempdir");
    std::fs::copy(
        root().join("robots/irb1400.urdf"),
        dir.path().join("copy.urdf"),
    )
    .expect("copy urdf");

    // The byte-identical copy has no controller file beside it: serial, the URDF's limits.
    let path = cell_with(dir.path(), "copy.urdf", "");
    let o = gen_rapid(&[arg(&path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(
        lines[0].starts_with("warning: ")
            && lines[0]
                .contains("copy.urdf has no controller file beside it (copy.controller.yaml)")
            && lines[0].contains("serial arm")
            && lines[0].contains("robot.controller"),
        "{err}"
    );
    assert!(lines[1].starts_with("gen-rapid: "), "{err}");
    let text = stdout(&o);
    assert!(!text.contains("warning"), "{text}");
    let m = Module::parse(&text).expect("module");
    assert_eq!(m.urdf.as_deref(), Some("copy.urdf"));
    assert_eq!(
        m.controller.as_deref(),
        Some("none: serial arm, the URDF's limits")
    );
    assert_eq!(
        m.coupling.as_deref(),
        Some("serial (axes 1..6 = URDF joints 1..6)")
    );

    // Named explicitly, the controller file restores the convention: the same module as with
    // the original URDF but for the URDF's name, and no warning.
    let controller = root().join("robots/irb1400.controller.yaml");
    let extra = format!("\n  controller: {}", controller.display());
    let path = cell_with(dir.path(), "copy.urdf", &extra);
    let o = gen_rapid(&[arg(&path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
    let expected = read("tests/ok/no_obstacles_depth_first.mod")
        .replace("! urdf: irb1400.urdf", "! urdf: copy.urdf")
        .replace("! cell: no_obstacles_depth_first.yaml", "! cell: cell.yaml");
    assert_eq!(stdout(&o), expected);

    // On failure too, before the error.
    let path = cell_with(dir.path(), "copy.urdf", "");
    let text = std::fs::read_to_string(&path)
        .expect("cell")
        .replace("joints: [10, 10, 0]", "joints: [175, 10, 0]");
    assert!(text.contains("[175, 10, 0]"));
    std::fs::write(&path, text).expect("write");
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.starts_with("warning: ")
            && err.contains("\nerror: point 'Q' is out of range: axis 1 = 175 deg"),
        "{err}"
    );
    assert!(
        err.contains("(ranges from the joint limits of copy.urdf (no controller file))"),
        "{err}"
    );
    assert!(stdout(&o).is_empty());

    // compare and locate warn too.
    let path = cell_with(dir.path(), "copy.urdf", "");
    for cmd in ["compare", "locate"] {
        let o = gen_rapid(&[cmd, arg(&path)]);
        assert!(
            stderr(&o).starts_with("warning: ") && !stdout(&o).contains("warning"),
            "{cmd}: {}",
            stderr(&o)
        );
    }
}

#[test]
fn a_controller_file_that_cannot_be_read_is_an_input_error_at_its_own_line() {
    let dir = tempfile::tempdir().expect("tempdir");
    let urdf = root().join("robots/irb1400.urdf");
    std::fs::write(
        dir.path().join("bad.controller.yaml"),
        "coupling: sideways\n",
    )
    .expect("write");
    let path = cell_with(
        dir.path(),
        &urdf.display().to_string(),
        "\n  controller: bad.controller.yaml",
    );
    let o = gen_rapid(&[arg(&path)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("controller file") && err.contains("bad.controller.yaml"),
        "{err}"
    );
    // Pointed at in the controller file, where the fault is: its line 1, the value at column 11
    // (before: at the cell's robot.controller, 7:15).
    assert!(err.contains("bad.controller.yaml:1:11\n"), "{err}");
    assert!(err.contains("\n1 | coupling: sideways\n"), "{err}");
    assert!(stdout(&o).is_empty());
}
