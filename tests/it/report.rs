//! `--report FILE`: the JSON report of real runs against its JSON Schema
//! (`docs/report.schema.json`, draft 2020-12, checked with the `jsonschema` crate), and its
//! facts against the module the same run wrote (read as text) and against forward kinematics
//! done here: every waypoint's joint values are the module's jointtarget, its TCP is tool0 of
//! the robot's kinematics at the header's placement through the written tooldata (and, for a
//! robtarget point, the cell's pose in its work object; for an `xyz` point the wrist centre is
//! the cell's position), every move is a `MoveAbsJ` with its speed and zone, and every move's
//! clearance agrees with a dense sampling of that move.

use crate::common::dense::Scene;
use crate::common::library::{load_cell, load_robot, Target};
use crate::common::module::Module;
use crate::common::{arg, gen_rapid, read, root, stderr};
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use serde_json::Value;

/// The cells whose reports are checked: fixed base, tool and work object, `base: auto`.
const CELLS: [&str; 4] = [
    "cells/trunk.yaml",
    "cells/torch-trunk.yaml",
    "cells/trunk-auto.yaml",
    "cells/gripper-pick.yaml",
];

/// Runs `gen-rapid CELL --report FILE`: the module text and the report.
fn run(cell: &str, extra: &[&str]) -> (String, Value, String) {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("report.json");
    let mut args = vec![cell, "--report", arg(&path)];
    args.extend(extra);
    let out = gen_rapid(&args);
    assert!(out.status.success(), "{cell}: {}", stderr(&out));
    let text = std::fs::read_to_string(&path).expect("the report is written");
    let report = serde_json::from_str(&text).expect("the report is JSON");
    (String::from_utf8(out.stdout).expect("UTF-8"), report, text)
}

fn schema() -> jsonschema::Validator {
    let schema: Value =
        serde_json::from_str(&read("docs/report.schema.json")).expect("the schema is JSON");
    jsonschema::draft202012::new(&schema).expect("the schema is a valid draft 2020-12 schema")
}

fn errors(v: &jsonschema::Validator, report: &Value) -> Vec<String> {
    v.iter_errors(report)
        .map(|e| format!("{}: {e}", e.instance_path()))
        .collect()
}

#[test]
fn reports_validate_against_the_schema_and_the_schema_is_strict() {
    let v = schema();
    for cell in CELLS {
        let (_, report, text) = run(cell, &[]);
        let found = errors(&v, &report);
        assert!(found.is_empty(), "{cell}: {found:#?}");
        // The same bytes on a second run.
        assert_eq!(
            run(cell, &[]).2,
            text,
            "{cell}: the report is not deterministic"
        );
    }
    // The schema refuses what a report must not be, so the check above could fail.
    let (_, report, _) = run("cells/trunk.yaml", &[]);
    let broken = [
        ("/format", Value::from("gen-rapid report 0")),
        ("/waypoints/0/kind", Value::from("corner")),
        (
            "/waypoints/0/joints_deg",
            serde_json::json!([1.0, 2.0, 3.0]),
        ),
        ("/moves/0/min_clearance/part", Value::from("wrist")),
        ("/moves/0/speed", Value::from("1st speed")),
        ("/totals/moves", Value::from(0)),
    ];
    for (pointer, value) in broken {
        let mut r = report.clone();
        *r.pointer_mut(pointer).expect("the key exists") = value;
        assert!(!v.is_valid(&r), "the schema accepts {pointer} changed");
    }
    let mut r = report.clone();
    r["moves"][0]["surprise"] = Value::from(1);
    assert!(!v.is_valid(&r), "the schema accepts an unknown key");
    let mut r = report;
    r.as_object_mut().map(|o| o.remove("base"));
    assert!(
        !v.is_valid(&r),
        "the schema accepts a report without its base"
    );
}

fn xyz(v: &Value) -> [f64; 3] {
    let a = v.as_array().expect("[x, y, z]");
    [0, 1, 2].map(|k| a[k].as_f64().expect("a number"))
}

fn pose(p: &[f64; 3], q: &[f64; 4]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3])),
    )
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
}

#[test]
fn report_facts_agree_with_the_module_and_independent_kinematics() {
    let mut tool_named = 0;
    for cell_path in CELLS {
        let (text, report, _) = run(cell_path, &[]);
        let mut module = Module::parse(&text).expect("a module");
        let cell = load_cell(&root().join(cell_path));
        let robot = load_robot(&cell);
        let placed = Isometry3::from_parts(
            Translation3::new(module.base_mm[0], module.base_mm[1], module.base_mm[2]),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), module.yaw_deg.to_radians()),
        );
        // A MoveJ's joints: the independent inverse kinematics of its robtarget.
        module
            .resolve_waypoints(&robot, &placed)
            .expect("joint moves");
        let label = |m: &str| format!("{cell_path}: {m}");

        // Header facts.
        assert_eq!(report["module"], module.name.as_str());
        assert_eq!(report["proc"], module.proc_name.as_str());
        assert_eq!(report["method"], module.planner.as_str());
        assert_eq!(xyz(&report["base"]["position_mm"]), module.base_mm);
        assert_eq!(report["base"]["yaw_deg"].as_f64(), Some(module.yaw_deg));
        assert_eq!(
            report["totals"]["moves"].as_u64(),
            Some(module.header_moves as u64)
        );
        assert_eq!(
            report["totals"]["min_clearance"]["mm"].as_f64(),
            module.min_clearance_mm,
            "{}",
            label("the smallest clearance")
        );
        let header_time = text
            .lines()
            .find_map(|l| l.trim().strip_prefix("! estimated time (s): "))
            .and_then(|t| t.parse::<f64>().ok());
        assert_eq!(report["totals"]["estimated_time_s"].as_f64(), header_time);

        // Waypoints: the module's jointtargets, in order, with their positions.
        let waypoints = report["waypoints"].as_array().expect("waypoints");
        assert_eq!(waypoints.len(), module.targets.len());
        let tframe = match module.tooldata.first() {
            Some((_, t)) => pose(
                &[t.tframe[0], t.tframe[1], t.tframe[2]],
                &[t.tframe[3], t.tframe[4], t.tframe[5], t.tframe[6]],
            ),
            None => Isometry3::identity(),
        };
        let uframe = match module.wobjdata.first() {
            Some((_, u)) => pose(&[u[0], u[1], u[2]], &[u[3], u[4], u[5], u[6]]),
            None => Isometry3::identity(),
        };
        let cell_from_robot = Isometry3::from_parts(
            Translation3::new(module.base_mm[0], module.base_mm[1], module.base_mm[2]),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), module.yaw_deg.to_radians()),
        );
        let mut cell_points = 0;
        let mut worst_mm: f64 = 0.0;
        for (w, (name, axes)) in waypoints.iter().zip(&module.targets) {
            assert_eq!(w["name"], name.as_str());
            let joints: Vec<f64> = w["joints_deg"]
                .as_array()
                .expect("joints")
                .iter()
                .map(|j| j.as_f64().expect("a number"))
                .collect();
            // To the report's 0.001 deg (a robtarget point's joints are exact, not written).
            let off_deg = (0..6)
                .map(|k| (joints[k] - axes[k]).abs())
                .fold(0.0, f64::max);
            assert!(off_deg <= 0.0005 + 1e-6, "{}: {joints:?}", label(name));
            // Forward kinematics of the module's joints, placed as the header says.
            let tcp = cell_from_robot * robot.tool0(axes) * tframe;
            let t = tcp.translation.vector;
            let off = distance(xyz(&w["tcp_mm"]), [t.x, t.y, t.z]);
            let wc = cell_from_robot * robot.wrist_centre(axes);
            let off_wc = distance(xyz(&w["wrist_centre_mm"]), [wc.x, wc.y, wc.z]);
            // Written to 0.001 mm: within 0.0005 mm per coordinate.
            assert!(off < 1e-3 && off_wc < 1e-3, "{}", label(name));
            let point = cell.points.iter().find(|p| p.name == *name);
            assert_eq!(
                w["kind"],
                match (point, name.ends_with("_app"), name.ends_with("_ret")) {
                    (Some(_), _, _) => "cell",
                    (None, true, _) => "approach",
                    (None, _, true) => "retract",
                    _ => "via",
                },
                "{}",
                label(name)
            );
            // A robtarget point's TCP is the cell's pose in its work object (within the 0.1 mm
            // the module promises); an xyz point's wrist centre the cell's position.
            match point.map(|p| &p.target) {
                Some(Target::Robtarget { pose: given, .. }) => {
                    let p = uframe * Point3::from(given.pos_mm);
                    let off = distance(xyz(&w["tcp_mm"]), [p.x, p.y, p.z]);
                    worst_mm = worst_mm.max(off);
                    assert!(off < 0.1, "{}: TCP {off:.4} mm from the pose", label(name));
                }
                Some(Target::Xyz {
                    wrist_centre_mm, ..
                }) => {
                    let off = distance(xyz(&w["wrist_centre_mm"]), *wrist_centre_mm);
                    worst_mm = worst_mm.max(off);
                    assert!(off < 0.05, "{}: wrist centre {off:.4} mm off", label(name));
                }
                _ => {}
            }
            cell_points += usize::from(point.is_some());
        }
        assert_eq!(
            report["totals"]["cell_points"].as_u64(),
            Some(cell_points as u64)
        );
        assert_eq!(cell_points, cell.points.len());

        // Moves: one per MoveAbsJ after the first, with its speed and zone; each clearance
        // against a dense sampling of the move (the true minimum lies at most 0.5 mm below the
        // least sample, and the certified figure at most 0.05 mm below it, rounded to 0.1).
        let scene = Scene::new(&robot, module.base_mm, module.yaw_deg, &cell);
        let moves = report["moves"].as_array().expect("moves");
        assert_eq!(moves.len(), module.move_args.len() - 1);
        let mut least = f64::INFINITY;
        for (i, m) in moves.iter().enumerate() {
            let to = &module.move_args[i + 1];
            assert_eq!(m["from"], module.move_args[i].target.as_str());
            assert_eq!(m["to"], to.target.as_str());
            assert_eq!(
                (m["speed"].as_str(), m["zone"].as_str()),
                (Some(to.speed.as_str()), Some(to.zone.as_str()))
            );
            assert!(m["time_s"].as_f64().is_some_and(|t| t >= 0.0));
            let c = m["min_clearance"]["mm"].as_f64().expect("a clearance");
            let (near, _) = scene.nearest_along(&module.targets[i].1, &module.targets[i + 1].1);
            let (lo, hi) = (near.mm - 0.5 - 0.05 - 0.05, near.mm + 0.05);
            assert!(
                (lo - 1e-9..=hi + 1e-9).contains(&c),
                "{}: move {} clearance {c}, dense {:.3} ({} to {})",
                label("moves"),
                i + 1,
                near.mm,
                near.link,
                near.obstacle
            );
            // The part named: a link cylinder of the robot, or a shape of the cell's tool.
            let named = &m["min_clearance"]["name"];
            match m["min_clearance"]["part"].as_str() {
                Some("link") => assert!(robot.collision.iter().any(|l| named == l.link.as_str())),
                Some("tool") => assert!(cell
                    .tool
                    .as_ref()
                    .is_some_and(|t| t.shapes.iter().any(|s| named == s.name.as_str()))),
                other => panic!("{}: move {} part {other:?}", label("moves"), i + 1),
            }
            tool_named += usize::from(m["min_clearance"]["part"] == "tool");
            assert!(cell
                .obstacles
                .iter()
                .any(|o| m["min_clearance"]["obstacle"] == o.name.as_str()));
            least = least.min(c);
        }
        assert_eq!(
            report["totals"]["min_clearance"]["mm"].as_f64(),
            Some(least)
        );
        eprintln!(
            "{cell_path}: {} waypoints, {} moves; TCP / wrist centre of the cell's poses within {worst_mm:.4} mm",
            waypoints.len(),
            moves.len()
        );
    }
    // The tool cells' closest approach is the tool's on some moves (torch-trunk: its neck and
    // nozzle by the quarter panels).
    assert!(tool_named > 0, "no move's clearance names a tool shape");
}

#[test]
fn report_and_page_are_written_only_for_what_succeeded() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (html, json) = (dir.path().join("p.html"), dir.path().join("r.json"));
    let out = gen_rapid(&[
        "tests/err/no_path.yaml",
        "--html",
        arg(&html),
        "--report",
        arg(&json),
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(out.stdout.is_empty());
    assert!(!json.exists(), "a report of a failed plan");
    // The page of the failure: the message and the two points of the leg.
    let page = std::fs::read_to_string(&html).expect("the failure page");
    for text in [
        r#""failure":{"message":"no collision-free path from 'P1' to 'P2'"#,
        r#""name":"P1""#,
        r#""name":"P2""#,
    ] {
        assert!(page.contains(text), "the page has no {text}");
    }
    // An input error draws nothing.
    let out = gen_rapid(&[
        "tests/err/box_inverted.yaml",
        "--html",
        arg(&dir.path().join("q.html")),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(!dir.path().join("q.html").exists());
    // Same cell, same bytes.
    let again = dir.path().join("p2.html");
    gen_rapid(&["tests/err/no_path.yaml", "--html", arg(&again)]);
    assert_eq!(std::fs::read(&again).ok(), Some(page.into_bytes()));
}

/// Each move of the report says how the module writes it: the instruction, the data its target
/// names, the circle point, the `RelTool` offset and the actions after it, as the module's text
/// says them (read by the strict grammar, move by move), and its kind as the cell asks it (the
/// approach line into a point with `approach`, the `move: linear` / `circular` move, the
/// retract line; air moves `joint`). `start` is the first instruction and its actions.
#[test]
fn report_moves_say_the_instruction_target_and_actions_the_module_writes() {
    use crate::common::routine::{Instruction, ToPoint};
    for (cell, process) in [
        (
            "cells/torch-trunk.yaml",
            ["approach", "linear", "retract"].as_slice(),
        ),
        (
            "cells/arc-seam.yaml",
            ["approach", "circular", "retract"].as_slice(),
        ),
        ("cells/trunk.yaml", [].as_slice()),
    ] {
        let (text, report, _) = run(cell, &[]);
        assert_eq!(report["format"], "gen-rapid report 4");
        let module = Module::parse(&text).expect("the module");
        // The module's motions, each with the actions written after it.
        let mut written: Vec<(&crate::common::routine::Motion, Vec<String>)> = Vec::new();
        for s in &module.body {
            match &s.ins {
                Instruction::Move(m) => written.push((m, Vec::new())),
                Instruction::Action(_) => {
                    let last = written.last_mut().expect("an action after a move");
                    last.1.push(s.text.trim_end_matches(';').to_string());
                }
                _ => {}
            }
        }
        let mut entries = vec![report["start"].clone()];
        entries.extend(report["moves"].as_array().expect("moves").iter().cloned());
        assert_eq!(entries.len(), written.len(), "{cell}: one entry a motion");
        let mut kinds = Vec::new();
        for (k, (e, (m, actions))) in entries.iter().zip(&written).enumerate() {
            let what = format!("{cell}: instruction {k}");
            assert_eq!(e["instruction"], m.kind.name(), "{what}");
            assert_eq!(e["target"], m.to.data(), "{what}");
            let circle = m.circle.as_ref().map(|c| c.data().to_string());
            assert_eq!(
                e["circle_point"].as_str().map(str::to_string),
                circle,
                "{what}"
            );
            let offset = match &m.to {
                ToPoint::RelTool { offset_mm, .. } => Some(offset_mm[2]),
                ToPoint::Name(_) => None,
            };
            assert_eq!(e["offset_mm"].as_f64(), offset, "{what}");
            let texts: Vec<String> = (e["actions"].as_array().expect("actions").iter())
                .map(|a| a["text"].as_str().expect("text").to_string())
                .collect();
            assert_eq!(&texts, actions, "{what}");
            // The action as data says what its text says.
            for a in e["actions"].as_array().expect("actions") {
                let text = a["text"].as_str().expect("text");
                let data = match a["kind"].as_str() {
                    Some("set_do") => {
                        format!("SetDO {}, {}", a["signal"].as_str().unwrap(), a["value"])
                    }
                    Some("pulse_do") => format!("PulseDO {}", a["signal"].as_str().unwrap()),
                    Some("wait_di") => {
                        format!("WaitDI {}, {}", a["signal"].as_str().unwrap(), a["value"])
                    }
                    Some("wait_time") => {
                        format!("WaitTime {:.3}", a["seconds"].as_f64().unwrap())
                    }
                    Some("grip_load") => format!("GripLoad {}", a["load"].as_str().unwrap()),
                    other => panic!("{what}: action kind {other:?}"),
                };
                assert_eq!(data, text, "{what}");
            }
            if k > 0 {
                kinds.push(e["kind"].as_str().expect("kind").to_string());
            }
            match e["kind"].as_str() {
                Some("joint") => assert!(matches!(m.kind.name(), "MoveAbsJ" | "MoveJ"), "{what}"),
                Some("circular") => assert_eq!(m.kind.name(), "MoveC", "{what}"),
                Some("approach" | "linear" | "retract") => {
                    assert_eq!(m.kind.name(), "MoveL", "{what}")
                }
                other => panic!("{what}: kind {other:?}"),
            }
        }
        let process_kinds: Vec<&str> = kinds
            .iter()
            .map(String::as_str)
            .filter(|k| *k != "joint")
            .collect();
        let expected: Vec<&str> = match cell {
            "cells/torch-trunk.yaml" => process.iter().chain(process).copied().collect(),
            _ => process.to_vec(),
        };
        assert_eq!(
            process_kinds, expected,
            "{cell}: the process moves in order"
        );
    }
}
