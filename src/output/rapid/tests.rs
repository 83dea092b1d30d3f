//! Tests of [`render`](super::render) (long: one test a rule of the module text; format and
//! names have their own).

use super::*;
use crate::cell::RobotFrame;
use crate::names::check_identifier;

fn point(name: &str, axes_deg: [f64; 6]) -> JointTarget {
    JointTarget {
        kind: TargetKind::CellPoint {
            name: name.to_string(),
        },
        axes_deg,
        speed: "v300".into(),
        zone: "fine".into(),
        robtarget: None,
        how: MoveHow::Joint,
        offset_mm: None,
        actions: Vec::new(),
        wobj: None,
    }
}
fn via(leg: usize, index: usize, axes_deg: [f64; 6]) -> JointTarget {
    JointTarget {
        kind: TargetKind::Via { leg, index },
        axes_deg,
        speed: "v300".into(),
        zone: "fine".into(),
        robtarget: None,
        how: MoveHow::Joint,
        offset_mm: None,
        actions: Vec::new(),
        wobj: None,
    }
}

/// The IRB 1400's ranges (docs/irb1400.md).
const IRB1400: AxisRanges = AxisRanges {
    axes_deg: [
        [-170.0, 170.0],
        [-70.0, 70.0],
        [-65.0, 70.0],
        [-150.0, 150.0],
        [-115.0, 115.0],
        [-300.0, 300.0],
    ],
    coupled_axis3_deg: Some([-65.0, 70.0]),
};

fn header(moves: usize) -> Header {
    Header {
        generator: "gen-rapid 0.1.0".to_string(),
        cell_file: "trunk.yaml".to_string(),
        model: None,
        urdf: "irb1400.urdf".to_string(),
        controller: Some("irb1400.controller.yaml".to_string()),
        parallelogram: true,
        planner: "extensile".to_string(),
        grid_deg: 5.0,
        clearance_mm: 10.0,
        base_mm: [0.0, -250.5, 12.26],
        yaw_deg: -90.0,
        moves,
        min_clearance_mm: Some(14.04),
        estimated_time_s: Some(3.456),
        zoned_vias: (1, 2),
        via_zone: "z50".to_string(),
        paper: Some((moves + 1, 4.0)),
        frame: RobotFrame::Cell,
        ends: Ends::Elsewhere {
            first: "home".to_string(),
            last: "pick".to_string(),
        },
    }
}

fn small_program() -> Program {
    Program {
        module: "Trunk".to_string(),
        header: header(3),
        targets: vec![
            point("home", [0.0, 0.0, 0.0, 0.0, 30.0, 0.0]),
            via(0, 1, [10.5, -0.0004, 20.0, -0.0, 29.99951, -180.0]),
            via(0, 2, [21.0, 1.23456, 19.9996, 0.0, 30.0, 179.9999]),
            point("pick", [45.0, 10.0, -5.0, 0.0, 60.0, 90.0]),
        ],
        tool: "tool0".to_string(),
        tooldata: None,
        wobjs: Vec::new(),
        ranges: IRB1400,
        proc_name: "main".into(),
        loads: Vec::new(),
    }
}

/// Written by hand from the specification, not copied from the output.
const SMALL_EXPECTED: &str = r"MODULE Trunk
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 5.000
    ! clearance (mm): 10.0
    ! base: [0.0, -250.5, 12.3] yaw: -90.000
    ! moves: 3
    ! min clearance (mm): 14.0
    ! estimated time (s): 3.46
    ! cycle: open: the routine ends at pick, not where it starts (home); motion.cycle: true closes it
    ! zoned vias: 1 of 2 (via zone z50)
    ! the paper's method alone: 4 moves, 4.00 s

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[10.500,0.000,20.000,0.000,30.000,-180.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[21.000,1.235,20.000,0.000,30.000,180.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget pick := [[45.000,10.000,-5.000,0.000,60.000,90.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ pick\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
";

/// A bigger program with awkward values and name clashes.
fn awkward_program() -> Program {
    let mut targets = vec![point(
        "Start",
        [-0.0, -0.0004, 0.0004, -1e-12, 123456.7894, -165.0005],
    )];
    for i in 1..=12 {
        let x = i as f64;
        targets.push(via(
            0,
            i,
            [-x * 0.0001, x * 13.333_333, -x * 7.77777, 1e-9, -1e-7, x],
        ));
    }
    targets.push(point("VIA01_03", [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]));
    targets.push(via(
        1,
        1,
        [-0.00049, 0.00049, -0.0005, 0.0005, 170.0, -170.0],
    ));
    targets.push(point("End_point", [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]));
    Program {
        module: "CellX_01".to_string(),
        header: Header {
            generator: "gen-rapid 0.1.0".to_string(),
            cell_file: "c\u{e9}ll\tfile.yaml ".to_string(),
            model: None,
            urdf: "robot.urdf".to_string(),
            controller: None,
            parallelogram: false,
            planner: "depth-first".to_string(),
            grid_deg: 2.5e-3,
            clearance_mm: -0.04,
            base_mm: [1e7, -0.04, 3.0],
            yaw_deg: -0.0001,
            moves: targets.len() - 1,
            min_clearance_mm: Some(1e-20),
            estimated_time_s: None,
            zoned_vias: (0, 1),
            via_zone: "fine".to_string(),
            paper: None,
            frame: RobotFrame::Cell,
            ends: Ends::AtStart,
        },
        targets: targets
            .into_iter()
            .map(|t| JointTarget {
                speed: "v1000".into(),
                zone: "z10".into(),
                ..t
            })
            .collect(),
        tool: "gripper".to_string(),
        tooldata: None,
        wobjs: Vec::new(),
        ranges: AxisRanges::UNBOUNDED,
        proc_name: "main".into(),
        loads: Vec::new(),
    }
}

/// Checks the textual guarantees that hold for any rendered module.
fn assert_properties(text: &str) {
    assert!(
        text.ends_with('\n') && !text.ends_with("\n\n"),
        "must end with exactly one newline"
    );
    assert!(!text.contains('\r'), "no CR");
    assert!(!text.contains('\t'), "no tabs");
    assert!(text.is_ascii(), "ASCII only");
    assert!(
        !text.contains("-0.000") && !text.contains("-0.0,") && !text.contains("-0.0]"),
        "no negative zero"
    );
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("MODULE "));
    assert_eq!(*lines.last().unwrap(), "ENDMODULE");
    for line in &lines {
        assert_eq!(line.trim_end(), *line, "trailing whitespace in {line:?}");
    }
    // Numbers: no exponent apart from the literal 9E9 of unused external axes.
    for token in
        text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-' || c == '+'))
    {
        let body = token.trim_start_matches(['-', '+']);
        if body.starts_with(|c: char| c.is_ascii_digit()) && body != "9E9" {
            assert!(!body.contains(['e', 'E']), "exponent in number {token:?}");
        }
    }
    // Indentation and pairing of CONSTs and MoveAbsJs.
    let mut consts = Vec::new();
    let mut moves = Vec::new();
    for line in &lines {
        if let Some(rest) = line.strip_prefix("    CONST jointtarget ") {
            let (name, value) = rest.split_once(" := ").expect("CONST shape");
            assert!(
                value.starts_with("[[") && value.ends_with("],[9E9,9E9,9E9,9E9,9E9,9E9]];"),
                "{line}"
            );
            let axes = &value[2..value.find(']').unwrap()];
            let axes: Vec<&str> = axes.split(',').collect();
            assert_eq!(axes.len(), 6, "{line}");
            for a in axes {
                let (_, frac) = a.split_once('.').expect("decimal point");
                assert_eq!(frac.len(), 3, "{line}");
                assert!(a.parse::<f64>().unwrap().is_finite());
            }
            consts.push(name.to_string());
        } else if let Some(rest) = line.strip_prefix("        MoveAbsJ ") {
            let (name, _) = rest.split_once("\\NoEOffs, ").expect("MoveAbsJ shape");
            assert!(rest.ends_with(';'));
            moves.push(name.to_string());
        } else if line.contains("CONST") || line.contains("MoveAbsJ") {
            panic!("badly indented line {line:?}");
        }
    }
    assert_eq!(
        consts, moves,
        "each CONST used by exactly one MoveAbsJ, in order"
    );
    let mut lower: Vec<String> = consts.iter().map(|n| n.to_ascii_lowercase()).collect();
    lower.sort();
    lower.dedup();
    assert_eq!(
        lower.len(),
        consts.len(),
        "CONST names unique ignoring case"
    );
    for name in &consts {
        assert_eq!(check_identifier(name), Ok(()), "{name}");
    }
}

#[test]
fn render_small_program_matches_hand_written_text() {
    let text = render(&small_program()).unwrap();
    assert_eq!(text, SMALL_EXPECTED);
}

/// A shipped robot (`robot.model`): its own header line between the cell and the URDF, the
/// rest as for a URDF file; without one, no such line.
#[test]
fn a_shipped_robot_is_named_on_its_own_header_line() {
    let mut program = small_program();
    program.header.model = Some("irb1400 (ABB IRB 1400, built into gen-rapid)".into());
    let text = render(&program).unwrap();
    let want = SMALL_EXPECTED.replace(
        "    ! cell: trunk.yaml\n",
        "    ! cell: trunk.yaml\n    ! model: irb1400 (ABB IRB 1400, built into gen-rapid)\n",
    );
    assert_ne!(want, SMALL_EXPECTED);
    assert_eq!(text, want);
    assert!(!SMALL_EXPECTED.contains("! model:"));
}

#[test]
fn render_small_program_has_properties() {
    assert_properties(&render(&small_program()).unwrap());
    assert_properties(SMALL_EXPECTED); // the property checker itself accepts a known-good text
}

#[test]
fn render_awkward_program_has_properties() {
    let program = awkward_program();
    let text = render(&program).unwrap();
    assert_properties(&text);
    // Clash resolution visible in the output.
    assert!(text.contains("CONST jointtarget VIA01_03 := "), "{text}");
    assert!(text.contains("CONST jointtarget via01_03_x1 := "), "{text}");
    assert!(
        text.contains("MoveAbsJ via02_01\\NoEOffs, v1000, z10, gripper;"),
        "{text}"
    );
    // Header text sanitized, time line absent.
    assert!(text.contains("    ! cell: c?ll?file.yaml\n"), "{text}");
    assert!(!text.contains("estimated time"), "{text}");
    assert!(
        text.contains("    ! base: [10000000.0, 0.0, 3.0] yaw: 0.000\n"),
        "{text}"
    );
    assert!(text.contains("    ! grid (deg): 0.003\n"), "{text}");
    assert!(text.contains("    ! clearance (mm): 0.0\n"), "{text}");
    assert!(text.contains("    ! min clearance (mm): 0.0\n"), "{text}");
    assert!(text.contains("    ! moves: 15\n"), "{text}");
    assert!(
        text.contains("    ! urdf: robot.urdf\n    ! controller: none: serial arm, the URDF's limits\n    ! coupling: serial (axes 1..6 = URDF joints 1..6)\n"),
        "{text}"
    );
    // -165.0005 is stored as -165.000499999..., so it rounds towards zero.
    assert!(
        text.contains("[[0.000,0.000,0.000,0.000,123456.789,-165.000]"),
        "{text}"
    );
    assert_eq!(text.matches("MoveAbsJ ").count(), program.targets.len());
}

#[test]
fn render_is_deterministic() {
    let a = render(&awkward_program()).unwrap();
    let b = render(&awkward_program()).unwrap();
    assert_eq!(a.as_bytes(), b.as_bytes());
}

#[test]
fn render_without_targets() {
    let mut p = small_program();
    p.targets.clear();
    p.header.moves = 0;
    p.header.estimated_time_s = None;
    p.header.zoned_vias = (0, 0);
    p.header.paper = None;
    let text = render(&p).unwrap();
    let expected = r"MODULE Trunk
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 5.000
    ! clearance (mm): 10.0
    ! base: [0.0, -250.5, 12.3] yaw: -90.000
    ! moves: 0
    ! min clearance (mm): 14.0
    ! cycle: open: the routine ends at pick, not where it starts (home); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone z50)


    PROC main()
    ENDPROC
ENDMODULE
";
    assert_eq!(text, expected);
    assert_properties(&text);
}

#[test]
fn render_rejects_invalid_module_name() {
    for bad in [
        "",
        "1trunk",
        "my-cell",
        "Module",
        "jointtarget",
        &"m".repeat(33),
    ] {
        let mut p = small_program();
        p.module = bad.to_string();
        assert!(
            matches!(render(&p), Err(RapidError::InvalidModuleName { .. })),
            "{bad:?}"
        );
    }
}

#[test]
fn render_checks_speed_zone_tool_shape_but_allows_predefined() {
    let mut p = small_program();
    p.targets[1].speed = "vmax".into();
    p.targets[2].zone = "z200".into();
    p.tool = "Tool0".into();
    let text = render(&p).unwrap();
    assert!(
        text.contains("MoveAbsJ via01_01\\NoEOffs, vmax, fine, Tool0;\n        MoveAbsJ via01_02\\NoEOffs, v300, z200, Tool0;"),
        "{text}"
    );
    for (field, bad) in [
        (0, "v 300"),
        (1, "If"),
        (2, "tool-1"),
        (0, ""),
        (1, "9fine"),
    ] {
        let mut p = small_program();
        match field {
            0 => p.targets[2].speed = bad.into(),
            1 => p.targets[3].zone = bad.into(),
            _ => p.tool = bad.into(),
        }
        let role = ["speed", "zone", "tool"][field];
        match render(&p) {
            Err(RapidError::InvalidDataName { role: r, name, .. }) => {
                assert_eq!(r, role);
                assert_eq!(name, bad);
            }
            other => panic!("{bad:?}: expected InvalidDataName, got {other:?}"),
        }
    }
}

#[test]
fn render_rejects_target_named_like_module_or_tool() {
    let mut p = small_program();
    p.targets[3] = point("TRUNK", [0.0; 6]);
    assert!(matches!(render(&p), Err(RapidError::NameClash { .. })));
    let mut p = small_program();
    p.tool = "gripper".into();
    p.targets[3] = point("Gripper", [0.0; 6]);
    let err = render(&p).unwrap_err();
    assert!(matches!(err, RapidError::NameClash { .. }));
    assert!(err.to_string().contains("tool"), "{err}");
    let mut p = small_program();
    p.module = "gripper".into();
    p.tool = "Gripper".into();
    let err = render(&p).unwrap_err();
    assert!(err.to_string().contains("the tool data `Gripper`"), "{err}");
    let mut p = small_program();
    p.module = "main".into();
    assert!(matches!(render(&p), Err(RapidError::NameClash { .. })));
    // A cell point takes the routine's name: refused, whatever the routine is called.
    let mut p = small_program();
    p.targets[3] = point("Main", [0.0; 6]);
    let err = render(&p).unwrap_err();
    assert!(err.to_string().contains("PROC main"), "{err}");
    p.proc_name = "Weld".into();
    let text = render(&p).expect("a point may be called main when the routine is not");
    assert!(text.contains("    PROC Weld()\n") && text.contains("MoveAbsJ Main\\NoEOffs"));
    p.targets[3] = point("weld", [0.0; 6]);
    assert!(matches!(render(&p), Err(RapidError::NameClash { .. })));
    p.proc_name = "MoveJ".into();
    assert!(matches!(
        render(&p),
        Err(RapidError::InvalidProcName { .. })
    ));
}

#[test]
fn vias_take_no_name_of_the_module_or_its_data() {
    // A module or tool called like a via is valid RAPID; the via steps aside (no name clash,
    // exit 4, at render time).
    let mut p = small_program();
    p.module = "Via01_01".into();
    p.tool = "VIA01_02".into();
    let text = render(&p).expect("renders");
    assert!(text.starts_with("MODULE Via01_01\n"), "{text}");
    assert!(text.contains("CONST jointtarget via01_01_x1 := "), "{text}");
    assert!(text.contains("CONST jointtarget via01_02_x1 := "), "{text}");
    assert!(
        text.contains("MoveAbsJ via01_02_x1\\NoEOffs, v300, fine, VIA01_02;"),
        "{text}"
    );
    assert!(!text.contains("CONST jointtarget via01_01 :="), "{text}");
}

#[test]
fn render_reports_invalid_cell_point_by_name_and_rule() {
    let mut p = small_program();
    p.targets[3] = point("Proc", [0.0; 6]);
    let err = render(&p).unwrap_err();
    let msg = err.to_string();
    assert!(msg.contains("`Proc`") && msg.contains("reserved"), "{msg}");
}

#[test]
fn render_rejects_non_finite_values() {
    let mut p = small_program();
    p.targets[2].axes_deg[4] = f64::NAN;
    let err = render(&p).unwrap_err();
    assert!(matches!(err, RapidError::NonFinite { .. }));
    assert!(
        err.to_string().contains("axis 5 of target `via01_02`"),
        "{err}"
    );
    let mut p = small_program();
    p.header.min_clearance_mm = Some(f64::INFINITY);
    assert!(matches!(render(&p), Err(RapidError::NonFinite { .. })));
    let mut p = small_program();
    p.header.estimated_time_s = Some(f64::NEG_INFINITY);
    assert!(matches!(render(&p), Err(RapidError::NonFinite { .. })));
}

#[test]
fn render_rejects_moves_mismatch() {
    let mut p = small_program();
    p.header.moves = 4;
    assert!(matches!(
        render(&p),
        Err(RapidError::MovesMismatch {
            header: 4,
            actual: 3
        })
    ));
}

#[test]
fn template_source_is_ascii_lf_with_one_final_newline() {
    assert!(TEMPLATE.is_ascii());
    assert!(!TEMPLATE.contains('\r'));
    assert!(TEMPLATE.ends_with("ENDMODULE\n"));
    assert!(!TEMPLATE.ends_with("\n\n"));
}

#[test]
fn comment_text_is_printable_ascii() {
    assert_eq!(comment_text("tr\u{e4}d.yaml"), "tr?d.yaml");
    assert_eq!(comment_text("a\nb\r"), "a?b?");
    assert_eq!(comment_text("  x  "), "x");
    assert_eq!(comment_text(""), "-");
    assert_eq!(comment_text("   "), "-");
}

/// A program with a declared tool and work object and two robtarget points.
fn tcp_program() -> Program {
    let (c, s) = (0.9238795325112867, 0.3826834323650898);
    let mut w1 = point("W1", [10.0, 20.0, 30.0, 0.0, 40.0, 0.0]);
    w1.speed = "v100".into();
    w1.zone = "z10".into();
    w1.robtarget = Some(RobTarget {
        pose: Pose {
            pos_mm: [600.0, -100.0, 300.0],
            quat_wxyz: [0.0, 0.0, 1.0, 0.0],
        },
        conf: [0, 0, 0, 1],
    });
    let mut v = via(1, 1, [-5.0, 20.0, 30.0, 0.0, 40.0, 0.0]);
    v.speed = "v100".into();
    let mut w2 = point("W2", [-10.5, 20.0, 30.0, -100.0, -40.0, -95.0]);
    w2.speed = "v100".into();
    w2.robtarget = Some(RobTarget {
        pose: Pose {
            pos_mm: [612.5, 0.25, 300.0],
            quat_wxyz: [c, 0.0, s, -0.0],
        },
        conf: [-1, -2, -2, 1],
    });
    Program {
        module: "Weld".to_string(),
        header: header(3),
        // With one work object every move names it.
        targets: [point("home", [0.0, 0.0, 0.0, 0.0, 30.0, 0.0]), w1, v, w2]
            .map(|t| JointTarget { wobj: Some(0), ..t })
            .into(),
        tool: "tTorch".into(),
        tooldata: Some(ToolData {
            tframe: Pose {
                pos_mm: [0.0, 0.0, 350.0],
                quat_wxyz: [c, 0.0, s, 0.0],
            },
            mass_kg: 2.5,
            cog_mm: [0.0, 0.0, 120.0],
            shapes: vec!["neck".into(), "body".into()],
        }),
        wobjs: vec![WobjData {
            name: "wobjTrunk".into(),
            uframe: Pose {
                pos_mm: [400.0, 0.0, 500.0],
                quat_wxyz: [1.0, 0.0, 0.0, 0.0],
            },
        }],
        ranges: IRB1400,
        proc_name: "main".into(),
        loads: Vec::new(),
    }
}

#[test]
fn vias_take_no_name_of_the_work_object_or_a_points_speed_or_zone() {
    // The via of leg 2 would be via02_01: a work object, or the speed or zone of a point, of
    // that name is valid RAPID, so the via steps aside.
    let stepped = "CONST jointtarget via02_01_x1 := ";
    let mut p = tcp_program();
    p.wobjs[0].name = "Via02_01".into();
    let text = render(&p).expect("renders");
    assert!(text.contains("PERS wobjdata Via02_01 := "), "{text}");
    assert!(text.contains(stepped), "{text}");
    assert!(!text.contains("CONST jointtarget via02_01 :="), "{text}");

    let mut p = tcp_program();
    p.targets[3].zone = "VIA02_01".into();
    let text = render(&p).expect("renders");
    assert!(text.contains(stepped), "{text}");
    assert!(
        text.contains("v100, VIA02_01, tTorch\\WObj:=wobjTrunk;"),
        "{text}"
    );

    // Without a clash the via keeps its name.
    let text = render(&tcp_program()).expect("renders");
    assert!(text.contains("CONST jointtarget via02_01 := "), "{text}");
}

/// Written by hand from docs/rapid.md's formats (tooldata, wobjdata, robtarget, MoveAbsJ with
/// `\WObj`, a robtarget point moved to by `MoveJ` on its robtarget with ConfJ and ConfL on, and
/// no jointtarget of it), not copied from the output.
const TCP_EXPECTED: &str = r#"MODULE Weld
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 5.000
    ! clearance (mm): 10.0
    ! base: [0.0, -250.5, 12.3] yaw: -90.000
    ! tool: tTorch (declared below; collision shapes: neck, body)
    ! wobj: wobjTrunk (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 3
    ! min clearance (mm): 14.0
    ! estimated time (s): 3.46
    ! cycle: open: the routine ends at pick, not where it starts (home); motion.cycle: true closes it
    ! zoned vias: 1 of 2 (via zone z50)
    ! the paper's method alone: 4 moves, 4.00 s

    PERS tooldata tTorch := [TRUE,[[0.000,0.000,350.000],[0.923879533,0.000000000,0.382683432,0.000000000]],[2.500,[0.000,0.000,120.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTrunk := [FALSE,TRUE,"",[[400.000,0.000,500.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget W1_rt := [[600.000,-100.000,300.000],[0.000000000,0.000000000,1.000000000,0.000000000],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[-5.000,20.000,30.000,0.000,40.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget W2_rt := [[612.500,0.250,300.000],[0.923879533,0.000000000,0.382683432,0.000000000],[-1,-2,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v300, fine, tTorch\WObj:=wobjTrunk;
        MoveJ W1_rt, v100, z10, tTorch\WObj:=wobjTrunk;
        MoveAbsJ via02_01\NoEOffs, v100, fine, tTorch\WObj:=wobjTrunk;
        MoveJ W2_rt, v100, fine, tTorch\WObj:=wobjTrunk;
    ENDPROC
ENDMODULE
"#;

#[test]
fn render_tcp_program_matches_hand_written_text() {
    let text = render(&tcp_program()).unwrap();
    assert_eq!(text, TCP_EXPECTED);
}

#[test]
fn a_module_of_joint_moves_says_nothing_of_tools_and_frames() {
    let text = render(&small_program()).unwrap();
    assert!(
        !text.contains("! tool:") && !text.contains("! frames:") && !text.contains("Conf"),
        "{text}"
    );
    // A robtarget alone (tool0, wobj0) brings the tool, wobj and frames lines.
    let mut p = small_program();
    p.targets[3].robtarget = tcp_program().targets[1].robtarget;
    let text = render(&p).unwrap();
    assert!(
        text.contains("    ! tool: tool0 (predefined: the flange; no tool volume)\n    ! wobj: wobj0 (robtargets are in the world frame)\n    ! frames: "),
        "{text}"
    );
    assert!(
        text.contains("ConfL \\On;\n        MoveAbsJ ")
            && text.contains("MoveJ pick_rt, v300, fine, tool0;")
            && !text.contains("jointtarget pick "),
        "{text}"
    );
    assert!(text.contains("CONST robtarget pick_rt := "), "{text}");
    assert!(!text.contains("PERS "), "{text}");
}

#[test]
fn render_refuses_a_joint_value_out_of_range_as_a_last_guard() {
    for (k, v, why) in [
        (
            3,
            150.001,
            "axis 4 = 150.001 deg is outside -150 .. 150 deg",
        ),
        (4, -115.5, "axis 5 = -115.5 deg is outside -115 .. 115 deg"),
        (5, 300.5, "axis 6 = 300.5 deg is outside -300 .. 300 deg"),
        (0, -171.0, "axis 1 = -171 deg is outside -170 .. 170 deg"),
    ] {
        let mut p = small_program();
        p.targets[2].axes_deg[k] = v;
        match render(&p) {
            Err(e @ RapidError::OutOfRange { .. }) => {
                let msg = e.to_string();
                assert!(
                    msg.contains("target `via01_02` is out of range") && msg.contains(why),
                    "{msg}"
                );
            }
            other => panic!("{k}: expected OutOfRange, got {other:?}"),
        }
    }
    // The coupled range: both axes in range, the angle between the arms not.
    let mut p = small_program();
    p.targets[0].axes_deg[1] = -60.0;
    p.targets[0].axes_deg[2] = 30.0;
    let msg = render(&p).unwrap_err().to_string();
    assert!(msg.contains("axis 3 - axis 2 = 90 deg"), "{msg}");
    // At the limits is in range.
    let mut p = small_program();
    p.targets[1].axes_deg = [170.0, 70.0, 70.0, -150.0, 115.0, -300.0];
    assert!(render(&p).is_ok());
}

#[test]
fn declared_tool_wobj_and_robtarget_names_share_the_name_space() {
    // A point named like its neighbour's robtarget.
    let mut p = tcp_program();
    p.targets[0] = point("w2_RT", [0.0; 6]);
    let err = render(&p).unwrap_err();
    assert!(
        matches!(&err, RapidError::NameClash { name, .. } if name == "W2_rt"),
        "{err}"
    );
    // The tool and the work object are declared: named like a point, they clash.
    let mut p = tcp_program();
    p.tool = "Home".into();
    assert!(matches!(render(&p), Err(RapidError::NameClash { .. })));
    let mut p = tcp_program();
    p.wobjs[0].name = "weld".into();
    let err = render(&p).unwrap_err().to_string();
    assert!(err.contains("the module name `Weld`"), "{err}");
    // Declared names follow the identifier rule: tool0 cannot be declared again.
    let mut p = tcp_program();
    p.tool = "tool0".into();
    assert!(matches!(
        render(&p),
        Err(RapidError::InvalidDataName { role: "tool", .. })
    ));
    // A robtarget name past 32 characters.
    let mut p = tcp_program();
    let long = format!("W{}", "x".repeat(30));
    p.targets[1].kind = TargetKind::CellPoint { name: long };
    assert!(matches!(
        render(&p),
        Err(RapidError::InvalidGeneratedName { .. })
    ));
    // A speed named like a declared point.
    let mut p = tcp_program();
    p.targets[2].speed = "W1".into();
    assert!(matches!(render(&p), Err(RapidError::NameClash { .. })));
}

#[test]
fn a_huge_module_renders_within_the_fuel_and_a_runaway_template_is_stopped() {
    // 20 000 targets through the embedded template: the fuel is no limit for a real module.
    let mut p = small_program();
    p.targets = (0..20_000)
        .map(|i| {
            via(
                i / 1000,
                i % 1000 + 1,
                [(i % 100) as f64, 0.0, 0.0, 0.0, 30.0, 0.0],
            )
        })
        .collect();
    p.header = header(p.targets.len() - 1);
    let text = render(&p).expect("renders");
    assert_eq!(text.matches("MoveAbsJ").count(), 20_000);
    // A template looping 10^10 times: an error after the fuel (before: a hang).
    let path = std::path::Path::new("loop.mod.j2");
    let source = "{% for i in range(100000) %}{% for j in range(100000) %}{% endfor %}{% endfor %}";
    let t = ModuleTemplate::user(path, source.into()).expect("compiles");
    let err = render_with(&small_program(), &t).expect_err("out of fuel");
    assert!(err.to_string().contains("out of fuel"), "{err}");
    // Its help line says what stopped it (not the help of an undefined name).
    let help = crate::error::Error::Rapid(err).help().expect("a help line");
    assert!(
        help.contains("at most 16000000 of minijinja's fuel"),
        "{help}"
    );
    // A template that writes past the module's cap: refused at the expression that passes it
    // (line 2), having kept no more than the cap (before: gigabytes written until the memory ran
    // out, the fuel counting instructions only).
    let big = "MODULE x\n{% for i in range(100000) %}{{ 'x' * 1000 }}\n{% endfor %}";
    let t = ModuleTemplate::user(path, big.into()).expect("compiles");
    let err = render_with(&small_program(), &t).expect_err("over the cap");
    match &err {
        RapidError::UserTemplate(TemplateError::Invalid { line, over_cap, .. }) => {
            assert_eq!((*line, *over_cap), (Some(2), true), "{err}")
        }
        e => panic!("{e}"),
    }
    let help = crate::error::Error::Rapid(err).help().expect("a help line");
    assert!(help.contains("at most 64 MiB"), "{help}");
    // A macro doubling a string 40 times (a terabyte): the fuel counts the bytes it makes.
    let doubling = "{% macro d(s, n) %}{% if n > 0 %}{{ d(s ~ s, n - 1) }}{% else %}{{ s }}{% endif %}{% endmacro %}{{ d('x', 40) | length }}";
    let t = ModuleTemplate::user(path, doubling.into()).expect("compiles");
    let err = render_with(&small_program(), &t).expect_err("out of fuel");
    assert!(err.to_string().contains("out of fuel"), "{err}");
    // A tag of a million operators is refused before it is parsed (before: a stack overflow).
    let chain = format!("{{{{ 1{} }}}}", " + 1".repeat(1_000_000));
    assert!(matches!(
        ModuleTemplate::user(path, chain),
        Err(TemplateError::Invalid { line: Some(1), .. })
    ));
    let undefined = ModuleTemplate::user(path, "{{ no_such_name }}".into()).expect("compiles");
    let err = render_with(&small_program(), &undefined).expect_err("strict");
    let help = crate::error::Error::Rapid(err).help().expect("a help line");
    assert!(help.contains("strict undefined names"), "{help}");
}

/// A template fault's column counts characters, as a cell's columns do: non-ASCII text before
/// it on its line (the range minijinja gives is in bytes) does not push it right.
#[test]
fn a_template_faults_column_counts_characters() {
    let path = Path::new("t.mod.j2");
    let source = "! Größe: {{ no_such_name }}\n";
    let undefined = ModuleTemplate::user(path, source.into()).expect("compiles");
    let err = render_with(&small_program(), &undefined).expect_err("strict");
    let RapidError::UserTemplate(TemplateError::Invalid { line, column, .. }) = err else {
        panic!("not a template fault: {err:?}");
    };
    assert_eq!(line, Some(1));
    // `no_such_name` starts at character 13 (byte 15: ö and ß take two bytes each).
    let chars: Vec<char> = source.chars().collect();
    let col = column.expect("a column");
    assert_eq!(
        chars[col - 1..col - 1 + 12].iter().collect::<String>(),
        "no_such_name"
    );
}
