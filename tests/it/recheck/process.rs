//! Hand-written modules with process moves through the controller-like re-check
//! (`common/dense.rs`'s `check_module`), their expected results worked out by hand below.
//!
//! # The cell
//!
//! The IRB 1400 at the origin, yaw 0. A pen tool: TCP 300 mm along the flange's z axis, one
//! collision shape, a ball of radius 20 mm centred on the TCP. A table (box) under the pen:
//! x 600 .. 1100, y -300 .. 300, z 0 .. 350. Three robtargets, all at z = 400, the same
//! orientation `R = Ry(180 deg) Rz(30 deg)` (the tool's z axis straight down, turned 30 deg about
//! it), quaternion `[0, sin 15, cos 15, 0] = [0, 0.258819045, 0.965925826, 0]`:
//!
//! - `S1` (700, 0, 400), reached by `MoveJ` (the first instruction, not checked for clearance);
//! - `S2` (1000, 0, 400), `move: linear` (`MoveL`, 300 mm along x), actions `SetDO doPen, 1;
//!   WaitTime 0.500;`;
//! - `S3` (700, 0, 400), `move: circular` through `via` (850, 150, 400): the circle of centre
//!   (850, 0, 400) and radius 150 mm in the plane z = 400, half of it (180 deg), through y > 0;
//!   `retract: 40`: `MoveL RelTool(S3_rt,0,0,-40.000)`, 40 mm back along the tool's z axis
//!   (down), so up: the TCP ends at (700, 0, 440);
//! - `S4` (1000, 100, 400), reached by joint with `approach: 50`: `MoveJ RelTool(S4_rt,0,0,
//!   -50.000)` (the TCP at (1000, 100, 450)), then the approach line `MoveL S4_rt`.
//!
//! The same cell is also written with its robtargets in a work object `wPen` (uframe at
//! (600, -300, 0) turned 90 deg about z), every move naming it: the poses in the cell frame, and
//! so everything worked out below, are the same. And once more with the robot standing at
//! (100, 200, 0) turned 90 deg and `robot.frame: base`: every box and pose of the cell moved
//! with it (cell (100 - y, 200 + x, z) for base (x, y, z), orientations `Rz(90) R = Ry(180)
//! Rz(-60)`), so the module's robtargets, written in the base frame, are the first module's.
//!
//! # What the check must find, by hand
//!
//! - Clearance: the ball's lowest point is at z = 400 - 20 = 380 everywhere on the line and the
//!   arc, and the whole path lies over the table (x 700 .. 1000, |y| <= 150), so the ball keeps
//!   exactly 380 - 350 = 30 mm from the table there; the retract, the joint move (both ends at
//!   least 40 mm higher, between two nearby configurations) and the approach line (coming down
//!   to z = 400) stay at least that far. The arm is much farther: the flange is 300 mm
//!   above the TCP, the wrist centre 85 mm above that (z 785), and the base cylinder (radius
//!   350 mm) ends 250 mm short of the table's x = 600. So the smallest distance is 30 mm, from
//!   the tool's ball to the table.
//! - Joints: on the IRB 1400 (parallelogram) tool0's orientation at axes (a1, a2, a3, a4, a5, a6)
//!   with a4 = 0 is `Rz(a1) Ry(90 + a3 + a5) Rz(a6)` (tool0 points along x at zero, axes 3 and 5
//!   tilt it down about y, axis 6 turns it about its own z). With `Rz(a1) Ry(180) =
//!   Ry(180) Rz(-a1)` the pose R needs a3 + a5 = 90, a4 = 0 and a6 = 30 + a1: along both paths
//!   a6 - a1 = 30 deg and a4 = 0. Axis 1 points at the TCP (the wrist is straight above it):
//!   a1 = atan2(y, x), 0 on the line; on the arc it peaks where the line from the origin touches
//!   the circle: asin(150 / 850) = 10.164 deg (not at the via, atan2(150, 850) = 10.008 deg).
//! - Confdata: every point in front of axis 1, elbow up, a5 > 0 (cfx 0); a1 in 0 .. 10 deg,
//!   a4 = 0, a6 in 30 .. 40 deg: `[0, 0, 0, 0]` everywhere (a4 = 0 lies on a quadrant bound, which
//!   the check admits either way). The flipped wrist (a4 - 180, -a5, a6 - 180) of the same pose
//!   is `[0, -2, -2, 1]` (a4 = -180, a6 = -150, a5 < 0): another branch, which `ConfL \On` must
//!   refuse at the end of a `MoveL` that starts in the first.
//!
//! # What makes each case fail
//!
//! - a post on the line (x 830 .. 870, |y| <= 20, z 350 .. 450): the ball's centre passes through
//!   it at x = 850 (distance 0 < 10 mm); the arc stays 130 - 20 - 20 = 90 mm from it at least;
//! - a post on the arc (x 830 .. 870, y 130 .. 170, z 350 .. 450): the arc passes through its
//!   middle (850, 150); the line (y = 0) stays 130 - 20 = 110 mm from it;
//! - `S2_rt` written with the flipped wrist's confdata `[0, -2, -2, 1]`;
//! - the actions written in the other order;
//! - `S3_via` written turned 90 deg further about the tool's z axis (`Ry(180) Rz(120)`,
//!   `[0, sin 60, cos 60, 0]`): both ends have R, so the orientation at every arc fraction is R,
//!   and a circle point 90 deg off tells the controller another way of turning;
//! - the retract written `RelTool(S3_rt,0,0,40.000)`: 40 mm down, the ball's lowest point at
//!   z = 340, inside the table (and not the cell's retract).

use crate::common::controller::JointPath;
use crate::common::dense::{check_module, Report};
use crate::common::library::{irb1400, load_cell, load_robot};
use crate::common::temp_cell;
use nalgebra::Point3;

/// The orientation R of every robtarget, `[w, x, y, z]` with the module's 9 decimals.
const R: &str = "[0.000000000,0.258819045,0.965925826,0.000000000]";

/// A box as the cell file writes it.
type Post = ([f64; 3], [f64; 3]);

/// The post on the line and the post on the arc (module doc).
const ON_LINE: Post = ([830.0, -20.0, 350.0], [870.0, 20.0, 450.0]);
const ON_ARC: Post = ([830.0, 130.0, 350.0], [870.0, 170.0, 450.0]);

/// The confdata of every point, and of the flipped wrist (module doc).
const UPRIGHT: [i32; 4] = [0, 0, 0, 0];
const FLIPPED: [i32; 4] = [0, -2, -2, 1];

/// A robtarget's position as the cell and module write it: in the cell frame, or (`wobj`) in the
/// work object `wPen`, whose uframe is at (600, -300, 0) turned 90 deg about z (its x axis the
/// cell's y): cell (x, y, z) is wobj (y + 300, 600 - x, z).
fn written(p: [f64; 3], wobj: bool) -> [f64; 3] {
    match wobj {
        true => [p[1] + 300.0, 600.0 - p[0], p[2]],
        false => p,
    }
}

/// R as the cell writes it: in the cell frame, or in `wPen`: `Rz(-90) R = Ry(180) Rz(120)`
/// (`Rz(a) Ry(180) = Ry(180) Rz(-a)`), `[0, sin 60, cos 60, 0]`.
fn cell_q(wobj: bool) -> &'static str {
    match wobj {
        true => "[0, 0.866025404, 0.5, 0]",
        false => "[0, 0.258819045, 0.965925826, 0]",
    }
}

/// The same with the module's 9 decimals.
fn module_q(wobj: bool) -> &'static str {
    match wobj {
        true => "[0.000000000,0.866025404,0.500000000,0.000000000]",
        false => R,
    }
}

/// `[x, y, z]` as the cell file writes it.
fn xyz(p: [f64; 3]) -> String {
    format!("[{}, {}, {}]", p[0], p[1], p[2])
}

/// The cell (module doc), with `post` as a second box, its robtargets in the work object `wPen`
/// when `wobj`.
fn cell_text(post: Option<Post>, wobj: bool) -> String {
    let post = post.map_or(String::new(), |(lo, hi)| {
        format!(
            "  - {{ name: post, box: {{ min: [{}, {}, {}], max: [{}, {}, {}] }} }}\n",
            lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]
        )
    });
    let q = cell_q(wobj);
    let w = |p: [f64; 3]| xyz(written(p, wobj));
    let frame = match wobj {
        true => "wobj: { name: wPen, uframe: [[600, -300, 0], { zyx: [90, 0, 0] }] }\n",
        false => "",
    };
    format!(
        "module: Pen\n\
         robot: {{ urdf: URDF, base: [0, 0, 0] }}\n\
         tool:\n  name: tPen\n  tframe: [[0, 0, 300], [1, 0, 0, 0]]\n  mass: 1\n  cog: [0, 0, 150]\n\
         \x20 shapes:\n    - {{ name: tip, sphere: {{ centre: [0, 0, 300], radius: 20 }} }}\n\
         {frame}\
         obstacles:\n  - {{ name: table, box: {{ min: [600, -300, 0], max: [1100, 300, 350] }} }}\n{post}\
         points:\n\
         \x20 - {{ name: S1, robtarget: [{}, {q}] }}\n\
         \x20 - {{ name: S2, robtarget: [{}, {q}], move: linear, do: [{{ set_do: [doPen, 1] }}, {{ wait_time: 0.5 }}] }}\n\
         \x20 - {{ name: S3, robtarget: [{}, {q}], move: circular, via: {}, retract: 40 }}\n\
         \x20 - {{ name: S4, robtarget: [{}, {q}], approach: 50 }}\n\
         planner: {{ clearance: 10 }}\n\
         motion: {{ speed: v100, zone: fine }}\n",
        w(S1),
        w(S2),
        w(S1),
        w(VIA),
        w(S4),
    )
}

/// The cell-frame positions of S1 (and S3), S2, the arc's via and S4 (module doc).
const S1: [f64; 3] = [700.0, 0.0, 400.0];
const S2: [f64; 3] = [1000.0, 0.0, 400.0];
const VIA: [f64; 3] = [850.0, 150.0, 400.0];
const S4: [f64; 3] = [1000.0, 100.0, 400.0];

fn robtarget(name: &str, at: [f64; 3], conf: [i32; 4], wobj: bool) -> String {
    let p = written(at, wobj);
    format!(
        "    CONST robtarget {name} := [[{:.3},{:.3},{:.3}],{},[{},{},{},{}],[9E9,9E9,9E9,9E9,9E9,9E9]];\n",
        p[0], p[1], p[2], module_q(wobj), conf[0], conf[1], conf[2], conf[3]
    )
}

/// The module the contract writes for the cell, with `S2_rt`'s confdata `s2_conf`, the actions
/// `actions` (RAPID lines), the retract's `dz` and the header's min clearance `min_mm`.
fn module_text(s2_conf: [i32; 4], actions: &[&str], retract_dz: f64, min_mm: f64) -> String {
    module_in(s2_conf, actions, retract_dz, min_mm, false)
}

/// The same with the robtargets in `wPen` when `wobj` (every move names it).
fn module_in(
    s2_conf: [i32; 4],
    actions: &[&str],
    retract_dz: f64,
    min_mm: f64,
    wobj: bool,
) -> String {
    let mut body = String::new();
    for a in actions {
        body += &format!("        {a}\n");
    }
    let (wobjdata, on) = match wobj {
        true => (
            "    PERS wobjdata wPen := [FALSE,TRUE,\"\",[[600.000,-300.000,0.000],[0.707106781,0.000000000,0.000000000,0.707106781]],[[0,0,0],[1,0,0,0]]];\n",
            "\\WObj:=wPen",
        ),
        false => ("", ""),
    };
    format!(
        "MODULE Pen\n\
         \x20   ! planner: extensile\n\
         \x20   ! clearance (mm): 10.0\n\
         \x20   ! base: [0.0, 0.0, 0.0] yaw: 0.000\n\
         \x20   ! tool: tPen (declared below; collision shapes: tip)\n\
         \x20   ! frames: robtargets are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above\n\
         \x20   ! moves: 5\n\
         \x20   ! min clearance (mm): {min_mm:.1}\n\n\
         \x20   PERS tooldata tPen := [TRUE,[[0.000,0.000,300.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[1.000,[0.000,0.000,150.000],[1,0,0,0],0,0,0]];\n\
         {wobjdata}\n\
         {}{}{}{}{}\n\
         \x20   PROC main()\n\
         \x20       ConfJ \\On;\n\
         \x20       ConfL \\On;\n\
         \x20       MoveJ S1_rt, v100, fine, tPen{on};\n\
         \x20       MoveL S2_rt, v100, fine, tPen{on};\n\
         {body}\
         \x20       MoveC S3_via, S3_rt, v100, fine, tPen{on};\n\
         \x20       MoveL RelTool(S3_rt,0,0,{retract_dz:.3}), v100, fine, tPen{on};\n\
         \x20       MoveJ RelTool(S4_rt,0,0,-50.000), v100, fine, tPen{on};\n\
         \x20       MoveL S4_rt, v100, fine, tPen{on};\n\
         \x20   ENDPROC\n\
         ENDMODULE\n",
        robtarget("S1_rt", S1, UPRIGHT, wobj),
        robtarget("S2_rt", S2, s2_conf, wobj),
        robtarget("S3_via", VIA, UPRIGHT, wobj),
        robtarget("S3_rt", S1, UPRIGHT, wobj),
        robtarget("S4_rt", S4, UPRIGHT, wobj),
    )
}

const ACTIONS: [&str; 2] = ["SetDO doPen, 1;", "WaitTime 0.500;"];

/// Runs the check on the cell with `post` and the module.
fn check(post: Option<Post>, module: &str) -> Result<Report, Vec<String>> {
    check_in(post, module, false)
}

/// The same with the cell's robtargets in `wPen` when `wobj`.
fn check_in(post: Option<Post>, module: &str, wobj: bool) -> Result<Report, Vec<String>> {
    check_text(&cell_text(post, wobj), module)
}

/// The check of `module` for the cell file `cell`.
fn check_text(cell: &str, module: &str) -> Result<Report, Vec<String>> {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = temp_cell(dir.path(), "pen.yaml", cell);
    let cell = load_cell(&path);
    let robot = load_robot(&cell);
    check_module(&cell, &robot, module, "pen")
}

#[test]
fn a_line_and_an_arc_over_the_table_keep_the_clearance_worked_out_by_hand() {
    for wobj in [false, true] {
        let module = module_in(UPRIGHT, &ACTIONS, -40.0, 30.0, wobj);
        let r = check_in(None, &module, wobj).unwrap_or_else(|f| panic!("{}", f.join("\n")));
        worked_out_by_hand(&r);
    }
}

/// What the module doc works out for the cell without posts, in either frame.
fn worked_out_by_hand(r: &Report) {
    // The smallest distance: the ball to the table, 30 mm, on the line and the arc.
    assert_eq!(r.smallest.link, "tool shape 'tip'");
    assert_eq!(r.smallest.obstacle, "table");
    assert!((r.smallest.mm - 30.0).abs() < 0.01, "{:?}", r.smallest);
    assert_eq!(
        (r.run.followed, r.program.lines_and_arcs, r.program.actions),
        (4, 4, 2)
    );
    // Where each move ends: the TCP by forward kinematics of the joints the controller reached.
    let robot = irb1400();
    let ends: Vec<[f64; 3]> = r
        .run
        .moves
        .iter()
        .map(|m| {
            (robot.tool0(&m.to) * Point3::new(0.0, 0.0, 300.0))
                .coords
                .into()
        })
        .collect();
    let by_hand = [
        [700.0, 0.0, 400.0],    // S1
        [1000.0, 0.0, 400.0],   // S2
        [700.0, 0.0, 400.0],    // S3
        [700.0, 0.0, 440.0],    // S3's retract, 40 mm up
        [1000.0, 100.0, 450.0], // S4's approach pose, 50 mm up
        [1000.0, 100.0, 400.0], // S4
    ];
    assert_eq!(ends.len(), by_hand.len());
    for (e, h) in ends.iter().zip(&by_hand) {
        assert!(
            (0..3).all(|k| (e[k] - h[k]).abs() < 0.01),
            "a move ends at {e:?}, by hand {h:?}"
        );
    }
    // The arc: radius 150 mm, half a turn.
    let arcs: Vec<_> = r
        .run
        .moves
        .iter()
        .filter_map(|m| match &m.path {
            JointPath::Followed { tcp, samples, .. } => Some((tcp.radius_and_angle(), samples)),
            JointPath::Straight => None,
        })
        .collect();
    assert_eq!(arcs.len(), 4);
    assert!(
        [0, 2, 3].iter().all(|&k| arcs[k].0.is_none()),
        "the MoveLs are lines"
    );
    let (radius, angle) = arcs[1].0.expect("the MoveC is an arc");
    assert!((radius - 150.0).abs() < 1e-6 && (angle - 180.0).abs() < 1e-6);
    // The joints: a4 = 0, a6 - a1 = 30, a1 = atan2(y, x) of the TCP; on the line and the
    // retract a1 = 0, on the approach line atan2(100, 1000), on the arc at most asin(150 / 850),
    // where the line from the origin touches the circle.
    let mut top = 0.0f64;
    for (k, (_, samples)) in arcs.iter().enumerate() {
        for s in samples.iter() {
            let a = s.axes;
            assert!(
                a[3].abs() < 1e-6 && (a[5] - a[0] - 30.0).abs() < 1e-6,
                "{a:?}"
            );
            match k {
                1 => top = top.max(a[0]),
                3 => assert!((a[0] - 0.1f64.atan().to_degrees()).abs() < 1e-6, "{a:?}"),
                _ => assert!(a[0].abs() < 1e-6, "{a:?}"),
            }
        }
    }
    let want = (150.0f64 / 850.0).asin().to_degrees();
    assert!(
        (top - want).abs() < 0.01,
        "axis 1 peaks at {top}, by hand {want}"
    );
}

#[test]
fn a_line_through_a_post_fails() {
    let f = check(Some(ON_LINE), &module_text(UPRIGHT, &ACTIONS, -40.0, 0.0))
        .expect_err("the line crosses the post");
    assert!(
        f.iter().any(|m| m.contains("MoveL S2_rt")
            && m.contains("tool shape 'tip'")
            && m.contains("from post")),
        "{f:#?}"
    );
    assert!(
        !f.iter().any(|m| m.contains("MoveC")),
        "the arc misses the post: {f:#?}"
    );
}

#[test]
fn an_arc_through_a_post_fails() {
    let f = check(Some(ON_ARC), &module_text(UPRIGHT, &ACTIONS, -40.0, 0.0))
        .expect_err("the arc crosses the post");
    assert!(
        f.iter().any(|m| m.contains("MoveC S3_via, S3_rt")
            && m.contains("tool shape 'tip'")
            && m.contains("from post")),
        "{f:#?}"
    );
    assert!(
        !f.iter().any(|m| m.contains("MoveL")),
        "the line misses the post: {f:#?}"
    );
}

#[test]
fn a_line_ending_in_another_branchs_confdata_fails() {
    let f = check(None, &module_text(FLIPPED, &ACTIONS, -40.0, 30.0))
        .expect_err("ConfL stops the controller");
    assert!(
        f.iter()
            .any(|m| m.contains("MoveL S2_rt") && m.contains("ConfL would stop the controller")),
        "{f:#?}"
    );
}

#[test]
fn actions_out_of_the_cells_order_fail() {
    let f = check(
        None,
        &module_text(UPRIGHT, &[ACTIONS[1], ACTIONS[0]], -40.0, 30.0),
    )
    .expect_err("the actions' order");
    assert!(
        f.iter().any(|m| m.contains("its actions are written")),
        "{f:#?}"
    );
}

#[test]
fn a_retract_written_the_wrong_way_fails() {
    let f =
        check(None, &module_text(UPRIGHT, &ACTIONS, 40.0, 30.0)).expect_err("down into the table");
    assert!(
        f.iter()
            .any(|m| m.contains("its target must be RelTool(S3_rt,0,0,-40.000)")),
        "{f:#?}"
    );
    assert!(
        f.iter()
            .any(|m| m.contains("MoveL RelTool(S3_rt,0,0,40.000)") && m.contains("from table")),
        "{f:#?}"
    );
}

#[test]
fn a_circle_point_turned_off_the_path_fails() {
    let module = module_text(UPRIGHT, &ACTIONS, -40.0, 30.0);
    let turned = "[0.000000000,0.866025404,0.500000000,0.000000000]";
    let module: String = module
        .lines()
        .map(|l| match l.contains("CONST robtarget S3_via") {
            true => l.replace(R, turned),
            false => l.to_string(),
        } + "\n")
        .collect();
    assert!(module.contains(turned));
    let f = check(None, &module).expect_err("the circle point's orientation");
    assert!(
        f.iter().any(|m| m.contains("MoveC S3_via")
            && m.contains("lies 90.0000 deg from the path's at its arc fraction 0.5000")),
        "{f:#?}"
    );
}

/// The cell with a revisit of `S2` by a line from `S4` (along -y at z = 400, over the table)
/// and `motion.cycle`, and its module: `MoveL S2_rt` (the revisit), then the closing leg
/// `MoveJ S1_rt` (with `closing`), seven moves after the first.
fn cycle(closing: bool) -> (String, String) {
    let cell = cell_text(None, false)
        .replace("planner:", "  - { revisit: S2, move: linear }\nplanner:")
        .replace("zone: fine }", "zone: fine, cycle: true }");
    let close = match closing {
        true => "        MoveJ S1_rt, v100, fine, tPen;\n",
        false => "",
    };
    let module = module_text(UPRIGHT, &ACTIONS, -40.0, 30.0)
        .replace(
            "! moves: 5",
            &format!("! moves: {}", 6 + usize::from(closing)),
        )
        .replace(
            "    ENDPROC",
            &format!("        MoveL S2_rt, v100, fine, tPen;\n{close}    ENDPROC"),
        );
    (cell, module)
}

#[test]
fn a_revisit_and_the_closing_leg_are_run_and_held_to_the_cell() {
    let (cell, module) = cycle(true);
    let r = check_text(&cell, &module).unwrap_or_else(|f| panic!("{}", f.join("\n")));
    // Eight motions: the revisit's line is followed, the closing leg is a joint move ending at
    // S1 (700, 0, 400); the line keeps the ball 30 mm over the table, so nothing is farther.
    assert_eq!((r.run.moves.len(), r.run.followed), (8, 5));
    let robot = irb1400();
    let tcp = |k: usize| robot.tool0(&r.run.moves[k].to) * Point3::new(0.0, 0.0, 300.0);
    assert!((tcp(6) - Point3::new(1000.0, 0.0, 400.0)).norm() < 0.01);
    assert!((tcp(7) - Point3::new(700.0, 0.0, 400.0)).norm() < 0.01);
    assert!(r.smallest.mm <= 30.0 + 1e-6, "{:?}", r.smallest);
    // Without the closing leg the routine ends away from the first point.
    let (cell, module) = cycle(false);
    let f = check_text(&cell, &module).expect_err("the cycle is not closed");
    assert!(
        f.iter().any(|m| m.contains("the closing leg to point 'S1'")
            && m.contains("found the routine's end")),
        "{f:#?}"
    );
}

/// The cell moved with the robot to (100, 200, 0), yaw 90, `robot.frame: base` (module doc),
/// and its module.
fn in_base_frame() -> (String, String) {
    let turned = |p: [f64; 3]| xyz([100.0 - p[1], 200.0 + p[0], p[2]]);
    let mut cell = cell_text(None, false)
        .replace(
            "base: [0, 0, 0] }",
            "base: [100, 200, 0], yaw: 90, frame: base }",
        )
        .replace(
            "min: [600, -300, 0], max: [1100, 300, 350]",
            "min: [-200, 800, 0], max: [400, 1300, 350]",
        )
        .replace(cell_q(false), "[0, -0.5, 0.866025404, 0]");
    for p in [S1, S2, VIA, S4] {
        cell = cell.replace(&xyz(p), &turned(p));
    }
    let module = module_text(UPRIGHT, &ACTIONS, -40.0, 30.0)
        .replace(
            "! base: [0.0, 0.0, 0.0] yaw: 0.000",
            "! base: [100.0, 200.0, 0.0] yaw: 90.000",
        )
        .lines()
        .map(|l| match l.trim_start().starts_with("! frames:") {
            true => "    ! frames: robtargets are given in the robot's base frame\n".to_string(),
            false => format!("{l}\n"),
        })
        .collect();
    (cell, module)
}

#[test]
fn the_same_cell_moved_with_the_robot_and_written_in_its_base_frame_gives_the_same_figures() {
    let (cell, module) = in_base_frame();
    assert!(cell.contains("[100, 900, 400]") && cell.contains("via: [-50, 1050, 400]"));
    let r = check_text(&cell, &module).unwrap_or_else(|f| panic!("{}", f.join("\n")));
    worked_out_by_hand(&r);
}
