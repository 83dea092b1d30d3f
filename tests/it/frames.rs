//! `robot.frame: base`: the torch cell (`cells/torch-trunk.yaml`, base at (0, -850, 0) turned 90
//! deg) with its seams as air moves (the process moves in the base frame: `process.rs`) run with
//! the key, against the same cell in the cell frame (the default). The written numbers are checked against a transform worked out by hand, the
//! vias' jointtargets must be the same (the controller, its world frame its base frame, computes
//! the same joints), and every written robtarget is reached, as the controller reads it, by the
//! forward kinematics of the point's joints (the report's) in the base frame.

use crate::common::library::{irb1400, Robot};
use crate::common::module::Module;
use crate::common::{arg, gen_rapid, read, stderr, stdout, temp_cell};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};

fn iso(p: &[f64; 3], q: &[f64; 4]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3])),
    )
}

/// The torch cell's seams as air moves: no approach, retract, linear move or action.
fn air_only(text: String) -> String {
    text.replace(", approach: 40, do: [{ set_do: [doWeld, 1] }] }", " }")
        .replace(
            ", move: linear, speed: v50, do: [{ set_do: [doWeld, 0] }], retract: 40 }",
            " }",
        )
}

/// The module and the report of the torch cell (air moves only) changed by `edit` (absolute
/// robot path), run by the binary.
fn torch_module(
    dir: &std::path::Path,
    name: &str,
    edit: impl Fn(String) -> String,
) -> (String, serde_json::Value) {
    let text =
        edit(air_only(read("cells/torch-trunk.yaml"))).replace("../robots/irb1400.urdf", "URDF");
    assert!(!text.contains("approach: 40") && !text.contains(", move: linear"));
    let path = temp_cell(dir, name, &text);
    let report = dir.join(format!("{name}.json"));
    let out = gen_rapid(&[arg(&path), "-q", "--report", &report.to_string_lossy()]);
    assert!(out.status.success(), "{name}: {}", stderr(&out));
    let json = serde_json::from_str(&std::fs::read_to_string(&report).expect("report"))
        .expect("report JSON");
    (stdout(&out), json)
}

/// The joints the report states for cell point `name`.
fn joints_of(report: &serde_json::Value, name: &str) -> [f64; 6] {
    let w = report["waypoints"]
        .as_array()
        .expect("waypoints")
        .iter()
        .find(|w| w["name"] == name)
        .unwrap_or_else(|| panic!("no waypoint {name}"));
    std::array::from_fn(|k| w["joints_deg"][k].as_f64().expect("a joint value"))
}

fn with_base_frame(text: String) -> String {
    text.replace("  yaw: 90 ", "  frame: base\n  yaw: 90 ")
}

/// The torch cell without its work object: the seam points given in the cell frame (wobj0).
/// The uframe is a pure translation by (-830, -380, 100), so wobj (x, y, z) is cell
/// (x - 830, y - 380, z + 100).
fn in_wobj0(text: String) -> String {
    text.replace(
        "wobj:\n  name: wobjTrunk\n  uframe: [[-830, -380, 100], [1, 0, 0, 0]]\n",
        "",
    )
    .replace("[[330, 280, 0]", "[[-500, -100, 100]")
    .replace("[[330, 630, 0]", "[[-500, 250, 100]")
    .replace("[[1330, 630, 0]", "[[500, 250, 100]")
    .replace("[[1330, 280, 0]", "[[500, -100, 100]")
}

/// Every robtarget of `m`, read as the controller reads it (its world frame the robot's base
/// frame): the forward kinematics of the point's joints (the report's, to 0.001 deg) through
/// the written tframe, expressed in the written uframe (wobj0: the base frame itself), must give
/// the written pose within 0.1 mm and 0.01 deg.
fn controller_reaches_every_robtarget(
    robot: &Robot,
    m: &Module,
    report: &serde_json::Value,
) -> usize {
    let (_, tool) = &m.tooldata[0];
    let t = &tool.tframe;
    let tframe = iso(&[t[0], t[1], t[2]], &[t[3], t[4], t[5], t[6]]);
    let uframe = match m.wobjdata.first() {
        Some((_, u)) => iso(&[u[0], u[1], u[2]], &[u[3], u[4], u[5], u[6]]),
        None => Isometry3::identity(),
    };
    for (name, r) in &m.robtargets {
        let point = name.trim_end_matches("_rt");
        let axes = joints_of(report, point);
        let reached = uframe.inverse() * robot.tool0(&axes) * tframe;
        let written = iso(&r.pos_mm, &r.quat_wxyz);
        let mm = (reached.translation.vector - written.translation.vector).norm();
        let deg = reached.rotation.angle_to(&written.rotation).to_degrees();
        assert!(mm < 0.1 && deg < 0.01, "{name}: {mm} mm, {deg} deg off");
    }
    m.robtargets.len()
}

/// The lines of two modules that differ, as (left, right).
fn differing<'a>(a: &'a str, b: &'a str) -> Vec<(&'a str, &'a str)> {
    assert_eq!(a.lines().count(), b.lines().count());
    a.lines().zip(b.lines()).filter(|(x, y)| x != y).collect()
}

#[test]
fn frame_base_writes_the_uframe_in_the_base_frame_and_proves_the_same_joints() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (golden, _) = torch_module(dir.path(), "torch-trunk.yaml", |t| t);
    let base_dir = tempfile::tempdir().expect("temp dir");
    // Both cells keep one name, which the header states.
    let (base, report) = torch_module(base_dir.path(), "torch-trunk.yaml", with_base_frame);
    // By hand: from the base at (0, -850, 0) turned 90 deg about z, a cell point (x, y, z) is
    // d = (x, y + 850, z) turned back by 90 deg, (d_y, -d_x, d_z): the uframe's origin
    // (-830, -380, 100) is (470, 830, 100); its orientation (none in the cell) is Rz(-90) =
    // [cos 45, 0, 0, -sin 45]. Robtargets in the work object and every jointtarget stay.
    let diff = differing(&golden, &base);
    assert_eq!(diff.len(), 2, "{diff:#?}");
    assert!(diff[0]
        .0
        .contains("frames: robtargets and the user frame are given in the cell frame"));
    assert!(
        diff[0].1.contains(
            "frames: the user frame and robtargets in wobj0 are written in the robot's base frame"
        ),
        "{}",
        diff[0].1
    );
    assert!(diff[1].0.contains(
        "[[-830.000,-380.000,100.000],[1.000000000,0.000000000,0.000000000,0.000000000]]"
    ));
    assert!(
        diff[1].1.contains(
            "[[470.000,830.000,100.000],[0.707106781,0.000000000,0.000000000,-0.707106781]]"
        ),
        "{}",
        diff[1].1
    );
    let m = Module::parse(&base).expect("module");
    assert_eq!(
        controller_reaches_every_robtarget(&irb1400(), &m, &report),
        4
    );
}

#[test]
fn frame_base_writes_wobj0_robtargets_in_the_base_frame_and_proves_the_same_joints() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (cell, _) = torch_module(dir.path(), "torch-wobj0.yaml", in_wobj0);
    let (base, report) = torch_module(dir.path(), "torch-wobj0-base.yaml", |t| {
        with_base_frame(in_wobj0(t))
    });
    let (mc, mb) = (
        Module::parse(&cell).expect("module"),
        Module::parse(&base).expect("module"),
    );
    // The same seam in another frame: the same vias as in the cell frame.
    assert_eq!(mb.targets, mc.targets);
    assert!(mb.wobjdata.is_empty());
    // By hand (as above, (x, y, z) -> (y + 850, -x, z)): L1 (-500, -100, 100) is (750, 500,
    // 100), L2 (-500, 250, 100) is (1100, 500, 100), R1 (500, 250, 100) is (1100, -500, 100),
    // R2 (500, -100, 100) is (750, -500, 100). The torch's orientation q = [a, -b, -b, -a]
    // (a = 0.1830127, b = 0.6830127) turned back: Rz(-90) q = [c, 0, 0, -c] q (c = cos 45) =
    // [0, -2cb, 0, -2ca], written with its first non-zero component positive:
    // [0, 0.9659258, 0, 0.2588190] (its z axis, (sin 30, 0, -cos 30), leans towards the base).
    let expected = [
        ("L1_rt", [750.0, 500.0, 100.0]),
        ("L2_rt", [1100.0, 500.0, 100.0]),
        ("R1_rt", [1100.0, -500.0, 100.0]),
        ("R2_rt", [750.0, -500.0, 100.0]),
    ];
    for ((name, r), (want, pos)) in mb.robtargets.iter().zip(expected) {
        assert_eq!(name, want);
        assert_eq!(r.pos_mm, pos, "{name}");
        let q = [0.0, 0.9659258, 0.0, 0.2588190];
        assert!(
            r.quat_wxyz.iter().zip(q).all(|(a, b)| (a - b).abs() < 1e-6),
            "{name}: {:?}",
            r.quat_wxyz
        );
        let same = mc
            .robtargets
            .iter()
            .find(|(n, _)| n == name)
            .expect("cell frame");
        assert_eq!(
            same.1.conf, r.conf,
            "{name}: the confdata do not depend on the frame"
        );
    }
    assert_eq!(
        controller_reaches_every_robtarget(&irb1400(), &mb, &report),
        4
    );
}
