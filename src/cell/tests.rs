//! Tests of the cell stage: defaults, locations, refusals at their line.

use super::*;

const MINIMAL: &str = "module: M\nrobot:\n  urdf: ../robots/r.urdf\n  base: [1, 2, 3]\npoints:\n  - { name: A, joints: [1, 2, 3] }\n  - { name: B, joints: [4, 5, 6, 7, 8, 9] }\n";

fn parse_str(text: &str) -> Result<Cell, CellError> {
    parse(Path::new("cells/x.yaml"), text)
}

#[test]
fn defaults_fill_what_a_cell_leaves_out() {
    let c = parse_str(MINIMAL).expect("valid");
    assert_eq!(c.robot.urdf_path, Path::new("cells/../robots/r.urdf"));
    assert_eq!(c.robot.base, Base::Fixed([1.0, 2.0, 3.0]));
    assert_eq!((c.robot.yaw_deg, c.robot.wrist_deg), (0.0, [0.0; 3]));
    assert_eq!(
        c.planner,
        Planner {
            method: Method::Extensile,
            grid_deg: 1.0,
            clearance_mm: 10.0,
            shortcut: true,
            grid_loc: None,
        }
    );
    assert_eq!(
        (
            c.motion.speed.as_str(),
            c.motion.zone.as_str(),
            c.motion.tool.as_str()
        ),
        ("v300", "fine", "tool0")
    );
    assert!(c.obstacles.is_empty());
    assert_eq!(
        c.points[1].target,
        Target::Joints {
            axes_deg: [4.0, 5.0, 6.0],
            wrist_deg: Some([7.0, 8.0, 9.0])
        }
    );
}

#[test]
fn points_carry_their_line_and_column() {
    let c = parse_str(MINIMAL).expect("valid");
    assert_eq!(c.points[0].loc.line, 6);
    assert_eq!(c.points[1].loc.line, 7);
    assert!(c.points[0].loc.column > 0);
}

#[test]
fn base_auto_and_xyz_points_with_a_branch() {
    let text = MINIMAL
        .replace("base: [1, 2, 3]", "base: auto")
        .replace(
            "joints: [1, 2, 3]",
            "xyz: [900, 0, 1000], branch: back-elbow-up",
        )
        .replace("joints: [4, 5, 6, 7, 8, 9]", "xyz: [0, 900, 1000]");
    let c = parse_str(&text).expect("valid");
    assert_eq!(c.robot.base, Base::Auto);
    match &c.points[0].target {
        Target::Xyz {
            wrist_centre_mm,
            branch,
            branch_loc,
        } => {
            assert_eq!(*wrist_centre_mm, [900.0, 0.0, 1000.0]);
            assert_eq!(*branch, Some(Branch::BackElbowUp));
            assert_eq!(branch_loc.line, 6);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn refusals_name_the_key_and_its_place() {
    let cases = [
        (
            MINIMAL.replace("base: [1, 2, 3]", "base: [1, 2]"),
            "robot.base must have 3 numbers",
            4,
        ),
        (
            MINIMAL.replace("base: [1, 2, 3]", "base: somewhere"),
            "auto",
            4,
        ),
        (
            MINIMAL.replace("base: [1, 2, 3]", "base: [1, 2.25, 3]"),
            "more than 1 decimal",
            4,
        ),
        (
            MINIMAL.replace("base: [1, 2, 3]", "base: [1, 2, 3]\n  yaw: 45.0004"),
            "robot.yaw",
            5,
        ),
        (
            MINIMAL.replace("joints: [1, 2, 3]", "xyz: [900, 0, 1000], branch: sideways"),
            "unknown branch",
            6,
        ),
        (
            MINIMAL.replace("joints: [1, 2, 3]", "joints: [1, 2, 3], xyz: [1, 2, 3]"),
            "both",
            6,
        ),
        (
            MINIMAL.replace("{ name: A, joints: [1, 2, 3] }", "{ name: A }"),
            "neither",
            6,
        ),
        (
            MINIMAL.replace(
                "joints: [1, 2, 3]",
                "joints: [1, 2, 3], branch: front-elbow-up",
            ),
            "xyz",
            6,
        ),
        (
            MINIMAL.replace("module: M", "module: 9lives"),
            "not a valid RAPID name",
            1,
        ),
        (
            format!("{MINIMAL}motion:\n  speed: 'v 300'\n"),
            "motion.speed",
            9,
        ),
        (
            format!("{MINIMAL}planner:\n  clearance: -1\n"),
            "clearance",
            9,
        ),
        // The identifier rule of the renderer, applied at the line (not exit 4 at render time).
        (
            format!("{MINIMAL}motion:\n  speed: If\n"),
            "motion.speed 'If' is not a valid RAPID name: \"IF\" is a RAPID reserved word",
            9,
        ),
        (
            format!("{MINIMAL}motion:\n  zone: fine\n  tool: ENDPROC\n"),
            "motion.tool 'ENDPROC'",
            10,
        ),
        (
            format!("{MINIMAL}motion:\n  zone: {}\n", "z".repeat(33)),
            "at most 32",
            9,
        ),
        // One name space: the module may not take the name of PROC main or of the data it uses.
        (MINIMAL.replace("module: M", "module: Main"), "PROC main", 1),
        (
            format!("{MINIMAL}motion:\n  tool: m\n"),
            "module name 'M' is already the name of motion.tool",
            1,
        ),
        (
            MINIMAL.replace("name: B", "name: main"),
            "point name 'main' is already the name of the module's PROC main",
            7,
        ),
        (
            MINIMAL.replace("name: B", "name: m"),
            "point name 'm' is already the name of the module",
            7,
        ),
        (
            format!("{MINIMAL}motion:\n  tool: gripper\n").replace("name: A", "name: Gripper"),
            "point name 'Gripper' is already the name of motion.tool",
            6,
        ),
        // The speed, zone and tool are three data of three types: one name cannot be two.
        (
            format!("{MINIMAL}motion:\n  speed: mine\n  tool: Mine\n"),
            "motion.tool 'Mine' is already the name of motion.speed",
            10,
        ),
        (
            format!("{MINIMAL}motion:\n  speed: vFast\n  zone: VFAST\n"),
            "motion.zone 'VFAST' is already the name of motion.speed",
            10,
        ),
        (
            format!("{MINIMAL}motion:\n  zone: mine\n").replace("module: M", "module: Mine"),
            "module name 'Mine' is already the name of motion.zone",
            1,
        ),
        // A predefined name of another type: the type says it (`zone: v300` is a speeddata).
        (
            format!("{MINIMAL}motion:\n  zone: v300\n"),
            "motion.zone 'v300' is a speeddata in RAPID, not a zonedata",
            9,
        ),
        // Data named like the default routine: refused at the datum's line.
        (
            format!("{MINIMAL}motion:\n  speed: MAIN\n"),
            "motion.speed 'MAIN' is already the name of the module's PROC main",
            9,
        ),
        // `base: auto` needs positions, not joint values.
        (
            MINIMAL.replace("base: [1, 2, 3]", "base: auto"),
            "point 'A' gives joint values, but `base: auto`",
            6,
        ),
    ];
    for (text, needle, line) in cases {
        let err = parse_str(&text).expect_err(needle);
        assert!(err.to_string().contains(needle), "'{err}' lacks '{needle}'");
        assert_eq!(err.loc().map(|l| l.line), Some(line), "{err}");
    }
}

#[test]
fn joint_values_keep_at_most_three_decimals() {
    assert!(
        parse_str(&MINIMAL.replace("joints: [1, 2, 3]", "joints: [1.125, -2.5, 3.001]")).is_ok()
    );
    let err = parse_str(&MINIMAL.replace("joints: [1, 2, 3]", "joints: [1.0005, 2, 3]"))
        .expect_err("4 decimals");
    assert!(err.help().is_some_and(|h| h.contains("0.001")), "{err}");
}

#[test]
fn methods_parse_by_their_names() {
    for m in Method::ALL {
        assert_eq!(Method::parse(m.name()), Some(m));
    }
    assert_eq!(Method::parse("Extensile"), None);
    assert!(check_grid(0.25).is_ok() && check_grid(10.0).is_ok());
    assert!(check_grid(0.2).is_err() && check_grid(f64::NAN).is_err());
}

#[test]
fn data_names_may_be_predefined_but_declared_names_may_not() {
    let c = parse_str(&format!(
        "{MINIMAL}motion:\n  speed: vmax\n  zone: z200\n  tool: Tool0\n"
    ))
    .expect("predefined speed, zone and tool data");
    assert_eq!(
        (
            c.motion.speed.as_str(),
            c.motion.zone.as_str(),
            c.motion.tool.as_str()
        ),
        ("vmax", "z200", "Tool0")
    );
    let err = parse_str(&MINIMAL.replace("name: B", "name: v300")).expect_err("predefined");
    assert!(err.to_string().contains("predefined"), "{err}");
}

#[test]
fn messages_quote_long_input_shortened() {
    let huge = "x".repeat(100_000);
    for text in [
        MINIMAL.replace("module: M", &format!("module: {huge}")),
        format!("{MINIMAL}planner:\n  method: {huge}\n"),
        format!("{MINIMAL}obstacles:\n  - {{ name: {huge}, box: {{ min: [0, 0, 0], max: [0, 1, 1] }} }}\n"),
        format!("{MINIMAL}{huge}: 1\n"),
        MINIMAL.replace("base: [1, 2, 3]", &format!("base: {huge}")),
        MINIMAL.replace("joints: [1, 2, 3]", &format!("joints: [1, {huge}, 3]")),
    ] {
        let err = parse_str(&text).expect_err("refused");
        let m = err.to_string();
        assert!(m.len() < 400 && m.contains("..."), "{} chars: {}", m.len(), &m[..m.len().min(300)]);
        assert!(err.loc().is_some_and(|l| l.line > 0), "{m}");
    }
}

#[test]
fn syntax_errors_point_at_the_fault_with_help() {
    // (text, message, line, column, help)
    let cases = [
        // An unclosed `{` noticed at the next key: the message points at the `{`.
        (
            MINIMAL.replace("joints: [1, 2, 3] }", "joints: [1, 2, 3]"),
            "this '{' is never closed",
            6,
            5,
            "close the mapping with '}'",
        ),
        (
            MINIMAL.replace("  base: [1, 2, 3]", "\tbase: [1, 2, 3]"),
            "a tab character",
            4,
            1,
            "spaces only",
        ),
        (
            MINIMAL.replace("  base: [1, 2, 3]", "   base: [1, 2, 3]"),
            "`base` is indented more than `urdf` on line 3",
            4,
            4,
            "same column",
        ),
        (
            MINIMAL.replace("module: M", "module M"),
            "expected ':' after `module`",
            1,
            7,
            "`key: value`",
        ),
        (
            MINIMAL.replace("points:", "pionts:"),
            "unknown field `pionts`",
            5,
            1,
            "did you mean `points`?",
        ),
        (
            MINIMAL.replace("  base: [1, 2, 3]", "  base: [1, 2, 3]\n  base: [1, 2, 4]"),
            "the key `base` appears twice in this mapping (first at line 4)",
            5,
            3,
            "give each key once",
        ),
    ];
    for (text, needle, line, column, help) in cases {
        let err = parse_str(&text).expect_err(needle);
        assert!(err.to_string().contains(needle), "'{err}' lacks '{needle}'");
        assert_eq!(err.loc(), Some(Loc { line, column }), "{err}");
        assert!(
            err.help().is_some_and(|h| h.contains(help)),
            "{err}: {:?}",
            err.help()
        );
    }
}

#[test]
fn text_that_is_not_utf8_is_refused_at_its_byte() {
    let err = text_of(b"module: M\nrobot: caf\xE9\n".to_vec()).expect_err("latin-1");
    assert_eq!(
        err.loc(),
        Some(Loc {
            line: 2,
            column: 11
        }),
        "{err}"
    );
    assert!(err.to_string().contains("0xE9"), "{err}");
}

#[test]
fn via_zone_and_shortcut_are_read_and_refused_at_their_place() {
    let c = parse_str(MINIMAL).expect("valid");
    assert_eq!(
        (c.motion.via_zone.as_str(), c.planner.shortcut),
        ("fine", true)
    );
    let c = parse_str(&format!(
        "{MINIMAL}planner:\n  shortcut: false\nmotion:\n  via_zone: Z50\n"
    ))
    .expect("valid");
    assert_eq!(
        (c.motion.via_zone.as_str(), c.planner.shortcut),
        ("z50", false)
    );
    // (text, needle, line, column): line 8 is the first line after MINIMAL's seven.
    let cases = [
        (
            format!("{MINIMAL}motion:\n  via_zone: z7\n"),
            "motion.via_zone 'z7' is not a predefined zonedata",
            9,
            13,
        ),
        (
            format!("{MINIMAL}motion:\n  via_zone: myzone\n"),
            "motion.via_zone 'myzone' is not a predefined zonedata",
            9,
            13,
        ),
        (
            format!("{MINIMAL}motion:\n  via_zone: 9z\n"),
            "motion.via_zone '9z' is not a valid RAPID name",
            9,
            13,
        ),
        (
            format!("{MINIMAL}motion:\n  via_zone: [z50]\n"),
            "expected a single value here, found a list",
            9,
            13,
        ),
        (
            format!("{MINIMAL}planner:\n  shortcut: maybe\n"),
            "expected true or false, found `maybe`",
            9,
            13,
        ),
    ];
    for (text, needle, line, column) in cases {
        let err = parse_str(&text).expect_err(needle);
        assert!(err.to_string().contains(needle), "'{err}' lacks '{needle}'");
        assert_eq!(
            err.loc().map(|l| (l.line, l.column)),
            Some((line, column)),
            "{err}"
        );
    }
}

/// A hundred and one points aliasing one anchor (`&j` / `*j`) read as the values written out:
/// the YAML reader's ratio of aliases to anchors (a guard against alias bombs, which the cell's
/// typed fields and the reader's absolute bounds stop anyway) does not refuse an ordinary cell.
#[test]
fn many_aliases_of_one_anchor_are_an_ordinary_cell() {
    let mut text = String::from(
        "module: M\nrobot: { urdf: ../robots/irb1400.urdf, base: [0, 0, 0] }\npoints:\n  - { name: P0, joints: &j [10, 0, 0, 0, 30, 0] }\n",
    );
    for k in 1..=101 {
        text.push_str(&format!("  - {{ name: P{k}, joints: *j }}\n"));
    }
    let cell = parse_str(&text).expect("101 aliases of one anchor");
    assert_eq!(cell.points.len(), 102);
    // The aliases read the anchor's values.
    assert!(cell
        .points
        .iter()
        .all(|p| p.target == cell.points[0].target));
}

/// `robot.model` names a robot instead of `robot.urdf`: one of the two, no controller file
/// beside a model, each refusal at its line. The names themselves are the load stage's.
#[test]
fn robot_model_or_urdf_one_of_the_two() {
    let model = MINIMAL.replace("urdf: ../robots/r.urdf", "model: irb120_3_58");
    let c = parse_str(&model).expect("a model");
    assert_eq!(c.robot.model.as_deref(), Some("irb120_3_58"));
    assert_eq!(c.robot.urdf_path, Path::new(""));
    assert_eq!((c.robot.urdf_loc.line, c.robot.urdf_loc.column), (3, 10));
    assert_eq!(parse_str(MINIMAL).expect("a URDF").robot.model, None);
    let refused = |text: &str, line: u64, needle: &str| {
        let e = parse_str(text).expect_err(needle);
        assert_eq!(e.loc().map(|l| l.line), Some(line), "{needle}: {e}");
        assert!(e.to_string().contains(needle), "{needle}: {e}");
    };
    refused(
        &MINIMAL.replace("  base:", "  model: irb1400\n  base:"),
        4,
        "robot.model and robot.urdf name the robot twice",
    );
    refused(
        &MINIMAL.replace("  urdf: ../robots/r.urdf\n", ""),
        3,
        "names no robot",
    );
    refused(
        &model.replace("  base:", "  controller: r.controller.yaml\n  base:"),
        4,
        "robot.controller goes with robot.urdf",
    );
    refused(
        &model.replace("irb120_3_58", "''"),
        3,
        "robot.model must name a robot",
    );
}
