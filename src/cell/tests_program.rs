//! Tests of the cell stage's keys for a program a cell runs every day: several work objects
//! (`wobjs`, a point's `wobj`), orientations as `{ zyx: [ez, ey, ex] }`, revisits, the closed
//! cycle (`motion.cycle`) and `robot.frame`: what they give, and every refusal at its line.

use super::tests_process::{parse_str, refused_at};
use super::validate::orient_zyx;
use super::*;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// A pick-and-place cell with two work objects, `zyx` orientations, revisits and a closed cycle.
const PICK: &str = "module: M
robot:
  urdf: ../robots/r.urdf
  base: [0, 0, 0]
  frame: base
wobjs:
  - { name: wobjConveyor, uframe: [[600, -700, 300], [1, 0, 0, 0]] }
  - { name: wobjPallet, uframe: [[-400, 900, 100], { zyx: [90, 0, 0] }] }
points:
  - { name: home, joints: [90, 0, 0, 0, 30, 0] }
  - { name: pick, robtarget: [[100, 50, 20], { zyx: [0, 180, 0] }], wobj: wobjConveyor, approach: 100 }
  - { revisit: place, speed: v500, retract: 20 }
  - { name: place, robtarget: [[200, 200, 80], { zyx: [0, 180, 0] }, [1, 0, 2, 0]], wobj: WOBJPALLET }
  - { revisit: pick, move: linear, zone: z10 }
  - { revisit: HOME, speed: v1000 }
motion:
  cycle: true
";

fn pick_with(from: &str, to: &str) -> String {
    assert!(PICK.contains(from), "'{from}' not in PICK");
    PICK.replacen(from, to, 1)
}

#[test]
fn work_objects_revisits_cycle_and_frame_are_read_as_given() {
    let c = parse_str(PICK).expect("valid");
    assert_eq!(
        (c.robot.frame, c.robot.frame_loc.line),
        (RobotFrame::Base, 5)
    );
    assert_eq!((c.motion.cycle, c.motion.cycle_loc.line), (true, 17));
    let names: Vec<&str> = c.wobjs.iter().map(|w| w.name.as_str()).collect();
    assert_eq!(names, ["wobjConveyor", "wobjPallet"]);
    assert_eq!(c.wobjs[1].uframe.quat_wxyz, orient_zyx(90.0, 0.0, 0.0));
    // Each entry: name, wobj, revisit_of.
    let entries: Vec<(&str, Option<usize>, Option<usize>)> = c
        .points
        .iter()
        .map(|p| (p.name.as_str(), p.wobj, p.revisit_of))
        .collect();
    assert_eq!(
        entries,
        [
            ("home", None, None),
            ("pick", Some(0), None),
            ("place", Some(1), Some(3)),
            ("place", Some(1), None),
            ("pick", Some(0), Some(1)),
            ("home", None, Some(0)),
        ]
    );
    // A revisit takes the target (a later point's too) and nothing else: its own speed, zone,
    // move, approach, retract, actions.
    let (place, again) = (&c.points[3], &c.points[2]);
    assert_eq!(again.target, place.target);
    assert_eq!(
        (
            again.speed.as_deref(),
            again.retract_mm,
            place.speed.as_deref(),
            place.retract_mm
        ),
        (Some("v500"), Some(20.0), None, None)
    );
    assert_eq!(again.loc.line, 12);
    let (pick, again) = (&c.points[1], &c.points[4]);
    assert_eq!(again.target, pick.target);
    assert_eq!((again.approach_mm, pick.approach_mm), (None, Some(100.0)));
    assert_eq!(
        (again.arrival, again.zone.as_deref()),
        (Arrival::Linear, Some("z10"))
    );
    assert_eq!(c.points[5].label(), "the revisit of 'home' (line 15)");
    assert_eq!(c.points[1].label(), "point 'pick'");
    // The last entry revisits the first: the cycle is closed as it stands.
    assert!(c.motion.cycle && !c.closing_leg());
    assert!(c
        .wobj_of(&c.points[3])
        .is_some_and(|w| w.name == "wobjPallet"));
    assert!(c.wobj_of(&c.points[0]).is_none());
}

#[test]
fn the_closing_leg_is_needed_unless_the_ends_reach_one_target() {
    let closing = |text: &str| parse_str(text).expect("valid").closing_leg();
    assert!(!closing(PICK));
    // Without the last revisit of home, the routine ends at pick: a leg back is needed.
    let open = pick_with("  - { revisit: HOME, speed: v1000 }\n", "");
    assert!(closing(&open));
    assert!(!closing(&open.replace("cycle: true", "cycle: false")));
    assert!(!closing(&open.replace("motion:\n  cycle: true\n", "")));
    // A first entry that revisits the last point: the ends are one target.
    let moved = open
        .replacen("points:\n", "points:\n  - { revisit: last }\n", 1)
        .replacen(
            "motion:",
            "  - { name: last, joints: [0, 0, 0] }\nmotion:",
            1,
        );
    let c = parse_str(&moved).expect("valid");
    assert_eq!(c.points[0].revisit_of, Some(c.points.len() - 1));
    assert!(!c.closing_leg());
}

#[test]
fn a_work_object_may_be_left_out_only_when_there_is_one() {
    // One work object in the list, or as `wobj:`: every robtarget is in it.
    let one = pick_with(
        "  - { name: wobjPallet, uframe: [[-400, 900, 100], { zyx: [90, 0, 0] }] }\n",
        "",
    )
    .replace(", wobj: WOBJPALLET", "");
    let c = parse_str(&one).expect("one in the list");
    assert_eq!(c.points[3].wobj, Some(0));
    let single = one
        .replace(
            "wobjs:\n  - { name: wobjConveyor, uframe: [[600, -700, 300], [1, 0, 0, 0]] }\n",
            "wobj: { name: wobjConveyor, uframe: [[600, -700, 300], [1, 0, 0, 0]] }\n",
        )
        .replace(", wobj: wobjConveyor", "");
    let c = parse_str(&single).expect("wobj:");
    assert_eq!(c.wobjs.len(), 1);
    assert_eq!(
        (c.points[1].wobj, c.points[3].wobj, c.points[0].wobj),
        (Some(0), Some(0), None)
    );
    // None: robtargets in wobj0.
    let start = single.find("wobj:").expect("wobj");
    let end = single.find("points:").expect("points");
    let none = format!("{}{}", &single[..start], &single[end..]);
    let c = parse_str(&none).expect("no work object");
    assert!(c.wobjs.is_empty() && c.points.iter().all(|p| p.wobj.is_none()));
}

#[test]
fn every_refusal_of_the_daily_keys_points_at_its_line() {
    // (text, message, the text on the line it points at)
    let cases: Vec<(String, &str, &str)> = vec![
        (pick_with(", wobj: WOBJPALLET", ""), "point 'place' is a robtarget but names no work object, and the cell has 2", "name: place"),
        (pick_with("wobj: WOBJPALLET", "wobj: wobjShelf"), "point 'place': work object 'wobjShelf' is not one of the cell's", "wobj: wobjShelf"),
        (pick_with("wobj: WOBJPALLET", "wobj: wobj0"), "work object 'wobj0' is not one of the cell's", "wobj: wobj0"),
        (pick_with("[90, 0, 0, 0, 30, 0] }", "[90, 0, 0, 0, 30, 0], wobj: wobjPallet }"), "point 'home': `wobj` applies to robtarget points only", "name: home"),
        (format!("wobj: {{ name: w, uframe: [[0, 0, 0], [1, 0, 0, 0]] }}\n{PICK}"), "`wobj:` and `wobjs:` are both given; this `wobjs:` list is the second", "  - { name: wobjConveyor"),
        (format!("{PICK}wobj: {{ name: w, uframe: [[0, 0, 0], [1, 0, 0, 0]] }}\n"), "`wobj:` and `wobjs:` are both given; this `wobj:` is the second", "wobj: { name: w"),
        (pick_with("name: wobjPallet", "name: WobjConveyor").replace("WOBJPALLET", "wobjConveyor"), "work object name 'WobjConveyor' is already the name of the work object (line 7)", "name: WobjConveyor"),
        (pick_with("name: wobjPallet", "name: wobj0"), "work object name 'wobj0' is not a valid RAPID name", "name: wobj0"),
        (pick_with("name: place", "name: wobjPallet").replace("revisit: place", "revisit: wobjPallet"), "point name 'wobjPallet' is already the name of the work object (line 8)", "name: wobjPallet, robtarget"),
        (pick_with("{ zyx: [90, 0, 0] }", "{ zyx: [90, 0] }"), "work object 'wobjPallet' uframe zyx must have 3 numbers [ez, ey, ex], found 2", "zyx: [90, 0]"),
        (pick_with("{ zyx: [90, 0, 0] }", "{ zyx: [90, .nan, 0] }"), "work object 'wobjPallet' uframe zyx: every value must be a finite number", "zyx: [90, .nan"),
        (pick_with("{ zyx: [90, 0, 0] }", "{ zyx: [90, 0, 0], zyz: [1, 2, 3] }"), "unknown field `zyz`", "zyz: [1, 2, 3]"),
        (pick_with("{ zyx: [90, 0, 0] }", "{ xyz: [90, 0, 0] }"), "unknown field `xyz`, expected one of zyx", "xyz: [90, 0, 0]"),
        (pick_with("[[100, 50, 20], { zyx: [0, 180, 0] }]", "[{ zyx: [0, 180, 0] }, [100, 50, 20]]"), "point 'pick' robtarget: `zyx` gives an orientation, which stands second in a pose", "name: pick"),
        (pick_with("[1, 0, 2, 0]", "{ zyx: [1, 0, 2] }"), "`zyx` gives an orientation, which stands second", "name: place"),
        // revisits
        (pick_with("revisit: place", "revisit: plaice"), "revisit 'plaice' names no point", "revisit: plaice"),
        (pick_with("{ revisit: place, speed: v500", "{ revisit: place, joints: [1, 2, 3], speed: v500"), "the revisit of 'place' reaches that point's target: it gives no `joints`", "revisit: place"),
        (pick_with("{ revisit: place, speed: v500", "{ revisit: place, wobj: wobjPallet, speed: v500"), "it gives no `wobj`", "revisit: place"),
        (pick_with("{ revisit: place, speed: v500", "{ name: again, revisit: place, speed: v500"), "an entry of `points:` is a point (`name`) or a revisit (`revisit`), not both", "revisit: place"),
        (pick_with("{ revisit: HOME, speed: v1000 }", "{ speed: v1000 }"), "a point needs a name", "{ speed: v1000 }"),
        (pick_with("{ revisit: HOME, speed: v1000 }", "{ revisit: HOME, move: linear }"), "the revisit of 'home' is reached `linear`, which needs a robtarget, but 'home' gives joint values", "revisit: HOME"),
        (pick_with("{ revisit: HOME, speed: v1000 }", "{ revisit: HOME, speed: 'v 1000' }"), "the revisit of 'home' speed 'v 1000' is not a valid RAPID name", "revisit: HOME"),
        (pick_with("{ revisit: HOME, speed: v1000 }", "{ revisit: HOME, speed: home }"), "point name 'home' is already the name of the speed of the revisit of 'home' (line 15)", "name: home"),
        (pick_with("{ revisit: HOME, speed: v1000 }", "{ revisit: HOME, speed: z10 }"), "the revisit of 'home' speed 'z10' is a zonedata in RAPID, not a speeddata", "revisit: HOME"),
        // the second `pick` is a duplicate, not a revisit: the help says how to revisit.
        (pick_with("{ revisit: pick, move: linear", "{ name: PICK, move: linear"), "point name 'PICK' is used twice (first at line 11)", "name: PICK"),
        // robot.frame
        (pick_with("frame: base", "frame: world"), "robot.frame 'world' is not cell or base", "frame: world"),
        (pick_with("cycle: true", "cycle: yes please"), "expected true or false, found `yes please`", "cycle: yes"),
    ];
    refused_at(cases);
    // The duplicate's help says how to reach a target again.
    let err = parse_str(&pick_with(
        "{ revisit: pick, move: linear",
        "{ name: PICK, move: linear",
    ))
    .expect_err("twice");
    assert!(
        err.help().is_some_and(|h| h.contains("{ revisit: NAME }")),
        "{err:?}"
    );
}

/// `Rz(ez) Ry(ey) Rx(ex)` multiplied out by hand from the three axis rotations' matrices.
fn zyx_matrix(ez: f64, ey: f64, ex: f64) -> Matrix3<f64> {
    let (sz, cz) = ez.to_radians().sin_cos();
    let (sy, cy) = ey.to_radians().sin_cos();
    let (sx, cx) = ex.to_radians().sin_cos();
    let rz = Matrix3::new(cz, -sz, 0.0, sz, cz, 0.0, 0.0, 0.0, 1.0);
    let ry = Matrix3::new(cy, 0.0, sy, 0.0, 1.0, 0.0, -sy, 0.0, cy);
    let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, cx, -sx, 0.0, sx, cx);
    rz * ry * rx
}

fn matrix_of(q: [f64; 4]) -> Matrix3<f64> {
    let [w, x, y, z] = q;
    *UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z))
        .to_rotation_matrix()
        .matrix()
}

#[test]
fn zyx_is_rapids_orient_zyx_rz_ry_rx() {
    let angles = [
        -180.0, -135.0, -90.0, -45.0, -30.0, 0.0, 12.5, 30.0, 45.0, 60.0, 90.0, 135.0, 170.0,
        180.0, 270.0, 359.0, 720.5,
    ];
    for &ez in &angles {
        for &ey in &angles {
            for &ex in &angles {
                let q = orient_zyx(ez, ey, ex);
                let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
                assert!((norm - 1.0).abs() < 1e-15, "{ez} {ey} {ex}: norm {norm}");
                // The sign: w > 0, or w = 0 and the first other component > 0.
                let first = q.iter().find(|x| **x != 0.0).expect("not zero");
                assert!(*first > 0.0, "{ez} {ey} {ex}: {q:?}");
                assert!(
                    q.iter().all(|x| x.to_bits() != (-0.0f64).to_bits()),
                    "{q:?}"
                );
                // Against the matrices multiplied by hand.
                let by_hand = zyx_matrix(ez, ey, ex);
                assert!(
                    (matrix_of(q) - by_hand).abs().max() < 1e-12,
                    "{ez} {ey} {ex}"
                );
                // Against nalgebra's Euler angles: roll about x, then pitch about y, then yaw
                // about z (fixed axes), which is Rz(yaw) Ry(pitch) Rx(roll).
                let n = UnitQuaternion::from_euler_angles(
                    ex.to_radians(),
                    ey.to_radians(),
                    ez.to_radians(),
                );
                let n = [n.w, n.i, n.j, n.k];
                let same = (0..4).all(|k| (q[k] - n[k]).abs() < 1e-12);
                let opposite = (0..4).all(|k| (q[k] + n[k]).abs() < 1e-12);
                assert!(same || opposite, "{ez} {ey} {ex}: {q:?} against {n:?}");
            }
        }
    }
}

#[test]
fn zyx_at_known_orientations_and_the_gimbal_lock() {
    // Turned 180 deg about y: the tool's z axis points down, as a gripper's over a table.
    assert_eq!(orient_zyx(0.0, 180.0, 0.0), [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(orient_zyx(0.0, 0.0, 0.0), [1.0, 0.0, 0.0, 0.0]);
    let r = std::f64::consts::FRAC_1_SQRT_2;
    assert_eq!(orient_zyx(90.0, 0.0, 0.0), [r, 0.0, 0.0, r]);
    assert_eq!(orient_zyx(-90.0, 0.0, 0.0), [r, 0.0, 0.0, -r]);
    // Rz(180) Ry(180) is Rx(180); the sign makes x positive where w is 0.
    assert_eq!(orient_zyx(180.0, 180.0, 0.0), [0.0, 1.0, 0.0, 0.0]);
    // The first column of Rz(90): x goes to y.
    let m = matrix_of(orient_zyx(90.0, 0.0, 0.0));
    assert!((m * Vector3::x() - Vector3::y()).norm() < 1e-15);
    // Ry(90) first: x goes to -z (z goes to x).
    let m = matrix_of(orient_zyx(0.0, 90.0, 0.0));
    assert!((m * Vector3::z() - Vector3::x()).norm() < 1e-15);
    // Gimbal lock at ey = +-90: only ez - ex (ey = 90) or ez + ex (ey = -90) matters.
    for (a, b) in [(10.0, 0.0), (40.0, 30.0), (-20.0, -30.0), (135.0, 125.0)] {
        let m1 = matrix_of(orient_zyx(a, 90.0, b));
        let m2 = matrix_of(orient_zyx(a + 17.0, 90.0, b + 17.0));
        assert!((m1 - m2).abs().max() < 1e-12, "{a} {b}");
        let m3 = matrix_of(orient_zyx(a, -90.0, b));
        let m4 = matrix_of(orient_zyx(a + 17.0, -90.0, b - 17.0));
        assert!((m3 - m4).abs().max() < 1e-12, "{a} {b}");
        // And it is the rotation about y by 90 deg after one about z by a - b.
        let want = Rotation3::from_axis_angle(&Vector3::z_axis(), (a - b).to_radians())
            * Rotation3::from_axis_angle(&Vector3::y_axis(), 90f64.to_radians());
        assert!((m1 - want.matrix()).abs().max() < 1e-12, "{a} {b}");
    }
}

#[test]
fn zyx_and_the_quaternion_it_means_give_the_same_cell() {
    let q = orient_zyx(30.0, -45.0, 120.0);
    let as_quaternion = format!("[{}, {}, {}, {}]", q[0], q[1], q[2], q[3]);
    let a = parse_str(PICK).expect("zyx");
    // Every `zyx` of PICK at once would need each replaced by its own quaternion; one suffices.
    let b_text = pick_with("{ zyx: [90, 0, 0] }", "{ zyx: [30, -45, 120] }");
    let c_text = pick_with("{ zyx: [90, 0, 0] }", &as_quaternion);
    let (b, c) = (
        parse_str(&b_text).expect("zyx"),
        parse_str(&c_text).expect("quaternion"),
    );
    assert_eq!(b.wobjs[1].uframe.quat_wxyz, q);
    assert!(
        (0..4).all(|k| (c.wobjs[1].uframe.quat_wxyz[k] - q[k]).abs() < 1e-15),
        "{:?} against {q:?}",
        c.wobjs[1].uframe.quat_wxyz
    );
    assert_ne!(a.wobjs[1].uframe, b.wobjs[1].uframe);
    // In a tool's tframe and a robtarget too.
    let tool = "tool:\n  name: tGrip\n  tframe: [[0, 0, 150], { zyx: [0, 0, 180] }]\n";
    let d = parse_str(&format!("{PICK}{tool}")).expect("tframe zyx");
    assert_eq!(d.tool.expect("tool").tframe.quat_wxyz, [0.0, 1.0, 0.0, 0.0]);
    match &d.points[1].target {
        Target::Robtarget { pose, conf } => {
            assert_eq!((pose.quat_wxyz, *conf), ([0.0, 0.0, 1.0, 0.0], None));
        }
        other => panic!("{other:?}"),
    }
    match &d.points[3].target {
        Target::Robtarget { conf, .. } => {
            assert_eq!(
                *conf,
                Some(crate::robot::ik::six::ConfData::from_array([1, 0, 2, 0]))
            )
        }
        other => panic!("{other:?}"),
    }
}
