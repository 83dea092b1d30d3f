//! The example cells with process moves run as a controller runs them (`common/process.rs`),
//! in the cell frame and with `robot.frame: base`, and the check itself held to a seam moved
//! into an obstacle.

use crate::common::library::load_cell;
use crate::common::process::{check_process as run_module, Run};
use crate::common::{arg, gen_rapid, read, root, stderr, stdout, temp_cell};

#[test]
fn the_process_cells_run_as_a_controller_runs_them() {
    for (name, process_moves) in [
        ("torch-trunk", 6),
        ("gripper-pick", 4),
        ("arc-seam", 3),
        ("pick-place", 4),
    ] {
        let path = root().join(format!("cells/{name}.yaml"));
        let cell = load_cell(&path);
        let o = gen_rapid(&[arg(&path), "-q"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let run =
            run_module(&cell, &stdout(&o), name).unwrap_or_else(|f| panic!("{}", f.join("\n")));
        assert_eq!(run.process_moves, process_moves, "{name}");
        assert!(run.samples > 100 * process_moves, "{name}: {run:?}");
        assert!(run.off_path_mm < 0.01, "{name}: {run:?}");
        assert!(
            run.nearest_mm >= cell.planner.clearance_mm - 0.5,
            "{name}: {run:?}"
        );
        assert_eq!(run.circle_points, usize::from(name == "arc-seam"), "{name}");
        eprintln!("{name}: {run:?}");
    }
}

#[test]
fn the_check_sees_a_seam_moved_into_the_clamp_post() {
    // The right seam of the torch cell run through the clamp post (the module written for the
    // cell, its R2 robtarget moved onto the post): the check refuses it.
    let path = root().join("cells/torch-trunk.yaml");
    let cell = load_cell(&path);
    let o = gen_rapid(&[arg(&path), "-q"]);
    let text = stdout(&o);
    let moved = text.replace(
        "CONST robtarget R2_rt := [[1330.000,280.000,0.000]",
        "CONST robtarget R2_rt := [[830.000,280.000,0.000]",
    );
    assert_ne!(moved, text);
    let f = run_module(&cell, &moved, "moved").expect_err("a seam through the post");
    assert!(f.iter().any(|m| m.contains("clamp_post")), "{f:?}");
}

/// The cell `text` (its URDF path absolute) written as `name` in `dir`, run by the binary and
/// its module run as a controller runs it.
fn run_text(dir: &std::path::Path, name: &str, text: &str) -> (String, Run) {
    let text = text.replace("../robots/irb1400.urdf", "URDF");
    let path = temp_cell(dir, name, &text);
    let cell = load_cell(&path);
    let o = gen_rapid(&[arg(&path), "-q"]);
    assert!(o.status.success(), "{name}: {}", stderr(&o));
    let module = stdout(&o);
    let run = run_module(&cell, &module, name).unwrap_or_else(|f| panic!("{}", f.join("\n")));
    assert!(run.off_path_mm < 0.01, "{name}: {run:?}");
    assert!(
        run.nearest_mm >= cell.planner.clearance_mm - 0.5,
        "{name}: {run:?}"
    );
    (module, run)
}

/// The torch and arc cells without their work object: the seam points and the arc's via in the
/// cell frame (wobj0). The uframe is a pure translation by (-830, -380, 100), so wobj (x, y, z)
/// is cell (x - 830, y - 380, z + 100); the robot turned 91 deg instead of 90, so that the
/// base frame's numbers are rounded.
fn in_wobj0_turned(text: &str) -> String {
    let t = text
        .replace(
            "wobj:\n  name: wobjTrunk\n  uframe: [[-830, -380, 100], [1, 0, 0, 0]]\n",
            "",
        )
        .replace("yaw: 90 ", "yaw: 91 ")
        .replace("[[330, 280, 0]", "[[-500, -100, 100]")
        .replace("[[330, 630, 0]", "[[-500, 250, 100]")
        .replace("[[1330, 630, 0]", "[[500, 250, 100]")
        .replace("[[1330, 280, 0]", "[[500, -100, 100]")
        .replace("[[530, 480, 0]", "[[-300, 100, 100]")
        .replace("via: [388.579, 421.421, 0]", "via: [-441.421, 41.421, 100]");
    assert!(
        !t.contains("wobjTrunk") && !t.contains(", 0]], [0.18"),
        "{t}"
    );
    t
}

fn with_base_frame(text: &str) -> String {
    let t = text.replace("  yaw: 9", "  frame: base\n  yaw: 9");
    assert_ne!(t, text);
    t
}

#[test]
fn the_base_frame_runs_the_same_process_path_as_the_cell_frame() {
    // The torch cell's two seams and the arc cell's circular seam, with their work object and in
    // wobj0 (the robot turned 91 deg: the base frame's robtargets rounded to 0.001 mm), each
    // with `robot.frame: base` against the same cell in the cell frame: both modules run as a
    // controller runs them (the TCP on the line and the clearance along every move), and each
    // process move starts, ends and passes its circle point at the same place in the cell.
    let dir = tempfile::tempdir().expect("temp dir");
    let mut compared = 0;
    for (name, moves) in [("torch-trunk", 6), ("arc-seam", 3)] {
        let given = read(&format!("cells/{name}.yaml"));
        for (variant, text) in [("wobj", given.clone()), ("wobj0", in_wobj0_turned(&given))] {
            let label = format!("{name}-{variant}");
            let (cell_module, cell_run) = run_text(dir.path(), &format!("{label}.yaml"), &text);
            let (base_module, base_run) = run_text(
                dir.path(),
                &format!("{label}-base.yaml"),
                &with_base_frame(&text),
            );
            assert!(
                base_module.contains("written in the robot's base frame"),
                "{label}"
            );
            assert_ne!(cell_module, base_module, "{label}");
            assert_eq!(cell_run.process_moves, moves, "{label}");
            assert_eq!(base_run.ends.len(), cell_run.ends.len(), "{label}");
            for (k, (a, b)) in cell_run.ends.iter().zip(&base_run.ends).enumerate() {
                for (x, y) in [(a.0, b.0), (a.1, b.1)] {
                    let mm = (x.translation.vector - y.translation.vector).norm();
                    let deg = x.rotation.angle_to(&y.rotation).to_degrees();
                    // The base frame's rounding: 0.0005 mm a coordinate, 5e-10 a quaternion
                    // component.
                    assert!(
                        mm < 2e-3 && deg < 1e-5,
                        "{label} move {k}: {mm} mm {deg} deg"
                    );
                }
                match (a.2, b.2) {
                    (Some(x), Some(y)) => assert!((x - y).norm() < 2e-3, "{label} move {k}"),
                    (None, None) => {}
                    other => panic!("{label} move {k}: {other:?}"),
                }
                compared += 1;
            }
            if name == "arc-seam" {
                assert_eq!(base_run.circle_points, 1, "{label}");
            }
        }
    }
    assert_eq!(compared, 2 * (6 + 3));
}

#[test]
fn poses_in_another_configuration_are_written_as_their_own_robtargets() {
    // tests/ok/approach_other_quadrant.yaml (its comments say how it is made): P1's and P3's
    // approach poses and P3's retract pose lie across axis 6 = 90 deg from their point, so each
    // is its own robtarget with its own confdata (by hand: axis 6 at 91.979 deg is cf6 = 1, the
    // point's 87.963 deg cf6 = 0; the position 100 mm back along the tool's z axis
    // (0, 0.5, -0.866): (700, 50, 486.603)); the arc P1 -> P2's circle point keeps the
    // confdata of the joints at its arc fraction (axis 1 still below 0: cf1 = -1), not the
    // end's. The module runs as a controller runs it: MoveJ to the written data in their own
    // confdata, the lines and the arc followed, the circle point's confdata checked at its arc
    // fraction by the tests' own IK.
    let path = root().join("tests/ok/approach_other_quadrant.yaml");
    let cell = load_cell(&path);
    let o = gen_rapid(&[arg(&path), "-q"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let own = "[[700.000,50.000,486.603],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,1,0],";
    for name in ["P1_app", "P3_app", "P3_ret"] {
        assert!(
            text.contains(&format!("CONST robtarget {name} := {own}")),
            "{name}\n{text}"
        );
    }
    for line in [
        "MoveJ P1_app, v300, fine, tGrip;",
        "MoveC P2_via, P2_rt, v50, fine, tGrip;",
        "MoveL RelTool(P2_rt,0,0,-100.000), v50, fine, tGrip;",
        "MoveJ P3_app, v300, fine, tGrip;",
        "MoveL P3_ret, v300, fine, tGrip;",
    ] {
        assert!(text.contains(line), "{line}\n{text}");
    }
    assert!(text.contains("CONST robtarget P1_rt := [[700.000,100.000,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,0,0],"));
    assert!(text.contains("CONST robtarget P2_via := [[737.500,110.048,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,0,0],"));
    assert!(text.contains("CONST robtarget P2_rt := [[764.952,212.500,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[0,0,1,0],"));
    let run = run_module(&cell, &text, "approach_other_quadrant")
        .unwrap_or_else(|f| panic!("{}", f.join("\n")));
    // The approach lines into P1 and P3, the arc, P2's and P3's retract lines.
    assert_eq!(run.process_moves, 5, "{run:?}");
    assert_eq!(run.circle_points, 1, "{run:?}");
    assert!(run.off_path_mm < 0.01, "{run:?}");
    // The same module with the approach written as RelTool of P1 (P1's confdata) or the circle
    // point with the end's confdata is refused by the run.
    let rel_tool = text.replace("MoveJ P1_app,", "MoveJ RelTool(P1_rt,0,0,-100.000),");
    let f = run_module(&cell, &rel_tool, "rel_tool").expect_err("P1's confdata");
    assert!(
        f.iter()
            .any(|m| m.contains("no solution in range of confdata [-1, 0, 0, 0]")),
        "{f:?}"
    );
    let end_conf = text.replace(
        "110.048,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[-1,0,0,0]",
        "110.048,400.000],[0.223463188,-0.833976055,-0.487336274,-0.130581393],[0,0,1,0]",
    );
    assert_ne!(end_conf, text);
    let f = run_module(&cell, &end_conf, "end_conf").expect_err("the end's confdata");
    assert!(
        f.iter().any(|m| m.contains("the circle point's confdata")),
        "{f:?}"
    );
}

#[test]
fn a_zone_next_to_a_process_move_is_written_fine_with_a_warning() {
    // The torch cell with L1 reached by the air route and left by the seam L1 -> L2 (MoveL), its
    // approach and action replaced by a zone: the corner between the air move and the seam is
    // not proven, so L1 is reached `fine`, and stderr says why.
    let dir = tempfile::tempdir().expect("temp dir");
    let text = read("cells/torch-trunk.yaml")
        .replace(
            ", approach: 40, do: [{ set_do: [doWeld, 1] }] }",
            ", zone: z10 }",
        )
        .replace("../robots/irb1400.urdf", "URDF");
    assert_eq!(text.matches("zone: z10").count(), 2, "L1 and R1");
    let path = temp_cell(dir.path(), "zoned.yaml", &text);
    let o = gen_rapid(&[arg(&path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let module = stdout(&o);
    assert!(
        module.contains("MoveJ L1_rt, v300, fine, tTorch"),
        "{module}"
    );
    assert!(
        module.contains("MoveJ R1_rt, v300, fine, tTorch"),
        "{module}"
    );
    assert!(!module.contains("z10"), "{module}");
    assert!(
        stderr(&o).contains("warning: point 'L1': zone z10 is written fine: the corner next to a process move is not proven (and 1 more like it: 'R1')"),
        "{}",
        stderr(&o)
    );
}
