//! Tests of the cell stage's tool, work object, robtarget and per-point motion keys and
//! `robot.controller`: what they give, and every refusal at its line.

use super::*;

/// A cell with a tool, a work object and robtarget points, lines numbered for the refusals.
const TCP: &str = "module: M
robot:
  urdf: ../robots/r.urdf
  base: [1, 2, 3]
  controller: ../robots/r.controller.yaml
tool:
  name: tTorch
  tframe: [[0, 0, 350], [0.9238795, 0, 0.3826834, 0]]
  mass: 2.5
  cog: [0, 0, 120]
  shapes:
    - { name: neck, cylinder: { from: [0, 0, 0], to: [0, 0, 300], radius: 25 } }
    - { name: body, box: { min: [-45, -45, 0], max: [45, 45, 110] } }
    - { name: cup, sphere: { centre: [120, 0, 320], radius: 15 } }
wobj:
  name: wobjDoor
  uframe: [[400, 0, 500], [1, 0, 0, 0]]
points:
  - { name: home, joints: [90, 0, 0, 0, 30, 0] }
  - { name: W1, robtarget: [[600, -100, 300], [0, 0, 1, 0]] }
  - { name: W2, robtarget: [[600, 100, 300], [0, 0, 1, 0], [0, -1, 2, 1]] }
  - { name: W3, robtarget: [[650, 0, 250.125], [0, 0, 2, 0]], speed: v100, zone: fine }
";

fn parse_str(text: &str) -> Result<Cell, CellError> {
    parse(Path::new("cells/x.yaml"), text)
}

#[test]
fn the_tool_the_work_object_and_robtargets_are_read_as_given() {
    let c = parse_str(&TCP.replace("[0, 0, 2, 0]", "[0, 0, 1, 0]")).expect("valid");
    assert_eq!(
        c.robot.controller_path.as_deref(),
        Some(Path::new("cells/../robots/r.controller.yaml"))
    );
    assert_eq!(c.robot.controller_loc.line, 5);
    // Every move uses the tool block's tooldata.
    assert_eq!(c.motion.tool, "tTorch");
    let t = c.tool.expect("tool");
    assert_eq!(
        (t.name.as_str(), t.mass_kg, t.cog_mm),
        ("tTorch", 2.5, [0.0, 0.0, 120.0])
    );
    assert_eq!(t.tframe.pos_mm, [0.0, 0.0, 350.0]);
    // Normalised: [0.9238795, 0, 0.3826834, 0] has norm 0.99999997...
    let q = t.tframe.quat_wxyz;
    assert!((q.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-15);
    assert!((q[0] - 0.9238795).abs() < 1e-7 && (q[2] - 0.3826834).abs() < 1e-7);
    let names: Vec<&str> = t.shapes.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["neck", "body", "cup"]);
    assert_eq!(
        t.shapes[0].geometry,
        ToolGeometry::Cylinder {
            from_mm: [0.0; 3],
            to_mm: [0.0, 0.0, 300.0],
            radius_mm: 25.0
        }
    );
    assert_eq!(
        t.shapes[2].geometry,
        ToolGeometry::Sphere {
            centre_mm: [120.0, 0.0, 320.0],
            radius_mm: 15.0
        }
    );
    assert_eq!(t.shapes[1].loc.line, 13);
    let [w] = c.wobjs.as_slice() else {
        panic!("one wobj, {} found", c.wobjs.len())
    };
    assert_eq!(
        (w.name.as_str(), w.uframe.pos_mm),
        ("wobjDoor", [400.0, 0.0, 500.0])
    );
    assert_eq!(
        c.points[1].target,
        Target::Robtarget {
            pose: Frame {
                pos_mm: [600.0, -100.0, 300.0],
                quat_wxyz: [0.0, 0.0, 1.0, 0.0]
            },
            conf: None
        }
    );
    assert_eq!(
        c.points[2].target,
        Target::Robtarget {
            pose: Frame {
                pos_mm: [600.0, 100.0, 300.0],
                quat_wxyz: [0.0, 0.0, 1.0, 0.0]
            },
            conf: Some(ConfData::from_array([0, -1, 2, 1]))
        }
    );
    // A norm off by 5e-4 is normalised.
    let c = parse_str(&TCP.replace("[0, 0, 2, 0]", "[0, 0, 1.0005, 0]")).expect("norm 1.0005");
    match &c.points[3].target {
        Target::Robtarget { pose, .. } => {
            assert_eq!(pose.quat_wxyz, [0.0, 0.0, 1.0, 0.0]);
            assert_eq!(pose.pos_mm, [650.0, 0.0, 250.125]);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(
        (c.points[3].speed.as_deref(), c.points[3].zone.as_deref()),
        (Some("v100"), Some("fine"))
    );
    assert_eq!(
        (c.points[1].speed.as_ref(), c.points[1].zone.as_ref()),
        (None, None)
    );
}

#[test]
fn a_tool_block_has_defaults_and_a_cell_may_go_without_one() {
    let c = parse_str(
        &TCP.replace("  mass: 2.5\n  cog: [0, 0, 120]\n", "")
            .replace("[0, 0, 2, 0]", "[0, 0, 1, 0]"),
    )
    .expect("valid");
    let t = c.tool.expect("tool");
    assert_eq!((t.mass_kg, t.cog_mm), (defaults::TOOL_MASS_KG, [0.0; 3]));
    // Without tool and wobj blocks robtargets are tool0 poses in wobj0.
    let text = TCP.replace("[0, 0, 2, 0]", "[0, 0, 1, 0]");
    let start = text.find("tool:").expect("tool");
    let end = text.find("points:").expect("points");
    let c = parse_str(&format!("{}{}", &text[..start], &text[end..])).expect("no blocks");
    assert!(c.tool.is_none() && c.wobjs.is_empty());
    assert_eq!(
        c.robot.controller_path.as_deref().map(|p| p.is_relative()),
        Some(true)
    );
}

#[test]
fn every_refusal_points_at_its_line() {
    let ok = TCP.replace("[0, 0, 2, 0]", "[0, 0, 1, 0]");
    let cases: Vec<(String, &str, u64)> = vec![
        (TCP.to_string(), "has norm 2.000000, not 1", 22),
        (ok.replace("[0.9238795, 0, 0.3826834, 0]", "[0.9, 0, 0.38, 0]"), "tool.tframe quaternion", 8),
        (ok.replace("[[400, 0, 500], [1, 0, 0, 0]]", "[[400, 0, 500], [1, 0, 0]]"), "must have 4 numbers", 17),
        (ok.replace("[[400, 0, 500], [1, 0, 0, 0]]", "[[400, 0, 500]]"), "wobj.uframe must be [[x, y, z], [q1, q2, q3, q4]], found 1 lists", 17),
        (ok.replace("[[400, 0, 500], [1, 0, 0, 0]]", "[[400, 0, 500], [1, 0, 0, 0], [0, 0, 0, 0]]"), "found 3 lists", 17),
        (ok.replace("[[600, -100, 300], [0, 0, 1, 0]]", "[[600, -100], [0, 0, 1, 0]]"), "robtarget position must have 3 numbers", 20),
        (ok.replace("[[600, -100, 300], [0, 0, 1, 0]]", "[[600, -100, 300.0001], [0, 0, 1, 0]]"), "more than 3 decimals", 20),
        (ok.replace("[0, -1, 2, 1]", "[0, -1, 2.5, 1]"), "2.5 is not a whole number", 21),
        (ok.replace("[0, -1, 2, 1]", "[0, -1, 2, 8]"), "cfx = 8 is not one of 0..7", 21),
        (ok.replace("[0, -1, 2, 1]", "[0, -1, 2]"), "confdata must have 4 numbers", 21),
        (ok.replace("name: tTorch", "name: tool0"), "tool name 'tool0' is not a valid RAPID name", 7),
        (ok.replace("name: wobjDoor", "name: WOBJ0"), "work object name 'WOBJ0'", 16),
        (ok.replace("mass: 2.5", "mass: 0"), "tool.mass = 0 must be a number > 0", 9),
        (ok.replace("mass: 2.5", "mass: 2.5001"), "more than 3 decimals", 9),
        (ok.replace("cog: [0, 0, 120]", "cog: [0, 120]"), "tool.cog must have 3 numbers", 10),
        (ok.replace("name: body", "name: neck"), "tool shape name 'neck' is used twice (first at line 12)", 13),
        (ok.replace("radius: 25", "radius: 0"), "cylinder.radius = 0 must be a number > 0", 12),
        (ok.replace("to: [0, 0, 300]", "to: [0, 0, 0]"), "from and to are the same point", 12),
        (ok.replace("max: [45, 45, 110]", "max: [45, -45, 110]"), "box.min y = -45 is not below box.max y = -45", 13),
        (ok.replace("radius: 15", "radius: -1"), "sphere.radius = -1", 14),
        (ok.replace("{ name: cup, sphere:", "{ name: cup, cylinder: { from: [0, 0, 0], to: [1, 0, 0], radius: 1 }, sphere:"), "exactly one of cylinder, box, sphere", 14),
        (ok.replace("{ name: cup, sphere: { centre: [120, 0, 320], radius: 15 } }", "{ name: cup }"), "exactly one of cylinder, box, sphere", 14),
        (ok.replace("radius: 15 }", "radius: 15, colour: red }"), "unknown field `colour`", 14),
        (ok.replace("robtarget: [[600, -100, 300], [0, 0, 1, 0]]", "robtarget: [[600, -100, 300], [0, 0, 1, 0]], joints: [1, 2, 3]"), "gives both `joints` and `robtarget`", 20),
        (ok.replace("robtarget: [[600, -100, 300], [0, 0, 1, 0]]", "robtarget: [[600, -100, 300], [0, 0, 1, 0]], branch: front-elbow-up"), "`branch` applies to `xyz` points only", 20),
        (ok.replace("speed: v100", "speed: 'v 100'"), "point 'W3' speed 'v 100' is not a valid RAPID name", 22),
        (ok.replace("zone: fine", "zone: If"), "point 'W3' zone 'If'", 22),
        (format!("{ok}motion:\n  tool: tGun\n"), "motion.tool 'tGun' is given beside the tool block (tool 'tTorch' at line 7)", 24),
        // One name space: the tool, the work object, the points and their robtargets.
        (ok.replace("name: wobjDoor", "name: TTORCH"), "work object name 'TTORCH' is already the name of the tool (line 7)", 16),
        (ok.replace("name: home", "name: wobjdoor"), "point name 'wobjdoor' is already the name of the work object (line 16)", 19),
        (ok.replace("name: home", "name: m"), "point name 'm' is already the name of the module", 19),
        (ok.replace("name: W3", "name: W1_RT"), "point name 'W1_RT' is already the name of the robtarget of point 'W1' (line 20)", 22),
        (ok.replace("name: home", "name: w2_rt"), "point 'W2' is a robtarget, written as CONST robtarget 'W2_rt', which is already the name of point 'w2_rt' (line 19)", 21),
        (ok.replace("speed: v100", "speed: W1"), "point name 'W1' is already the name of the speed of point 'W3'", 20),
        (ok.replace("name: W1", &format!("name: W{}", "x".repeat(30))), "would be named 'Wxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx_rt', not a valid RAPID name", 20),
        (ok.replace("controller: ../robots/r.controller.yaml", "controller: ''"), "robot.controller must name a controller file", 5),
        // `base: auto` takes robtargets, not joint values.
        (ok.replace("base: [1, 2, 3]", "base: auto"), "point 'home' gives joint values, but `base: auto` needs every point as `xyz` or `robtarget`", 19),
    ];
    for (text, needle, line) in cases {
        let err = parse_str(&text).expect_err(needle);
        assert!(err.to_string().contains(needle), "'{err}' lacks '{needle}'");
        assert_eq!(err.loc().map(|l| l.line), Some(line), "{needle}: {err}");
    }
}

#[test]
fn robtargets_need_the_tools_tcp() {
    let ok = TCP.replace("[0, 0, 2, 0]", "[0, 0, 1, 0]");
    let start = ok.find("tool:").expect("tool");
    let end = ok.find("wobj:").expect("wobj");
    let no_tool = format!("{}{}", &ok[..start], &ok[end..]);
    // motion.tool tool0 (any case) is the TCP robtargets are poses of.
    assert!(parse_str(&format!("{no_tool}motion:\n  tool: TOOL0\n")).is_ok());
    let err = parse_str(&format!("{no_tool}motion:\n  tool: tGripper\n")).expect_err("tGripper");
    assert!(
        err.to_string().contains(
            "motion.tool 'tGripper' is not tool0, but point 'W1' (line 11) is a robtarget"
        ),
        "{err}"
    );
    assert!(
        err.help().is_some_and(|h| h.contains("`tool:` block")),
        "{err}"
    );
    // Without robtargets, motion.tool names any tooldata of the controller, as before.
    let joints_only = "module: M\nrobot: { urdf: r.urdf, base: [0, 0, 0] }\npoints:\n  - { name: A, joints: [1, 2, 3] }\n  - { name: B, joints: [4, 5, 6] }\nmotion: { tool: tGripper }\n";
    assert!(parse_str(joints_only).is_ok());
}

#[test]
fn a_quaternion_may_be_off_by_at_most_1e_3() {
    let ok = TCP.replace("[0, 0, 2, 0]", "[0, 0, 1, 0]");
    for (q, accepted) in [
        ("[1.000999, 0, 0, 0]", true),
        ("[0.999001, 0, 0, 0]", true),
        ("[1.0011, 0, 0, 0]", false),
        ("[0.9989, 0, 0, 0]", false),
        ("[0, 0, 0, 0]", false),
        ("[0.5, 0.5, 0.5, 0.5]", true),
    ] {
        let text = ok.replace(
            "[[400, 0, 500], [1, 0, 0, 0]]",
            &format!("[[400, 0, 500], {q}]"),
        );
        assert_eq!(parse_str(&text).is_ok(), accepted, "{q}");
    }
}
