//! Tests of the cell stage's process keys: `move` (with `via`), `approach`, `retract`, the
//! actions of `do`, `loads`, the signals in the module's name space: what they give, and every
//! refusal at its line.

use super::*;

/// The process example of docs/cell.md: a seam S1 -> S2 (linear) -> S3 (circular).
const SEAM: &str = "module: M
robot:
  urdf: ../robots/r.urdf
  base: [0, -850, 0]
loads:
  - { name: loadPart, mass: 1.2, cog: [0, 0, 60] }
  - { name: loadBox, mass: 0.5 }
points:
  - { name: home, joints: [90, 0, 0, 0, 30, 0] }
  - name: S1
    robtarget: [[330, 280, 0], [0.1830127, -0.6830127, -0.6830127, -0.1830127]]
    approach: 40
    do: [{ set_do: [doWeld, 1] }, { wait_time: 0.3 }]
  - name: S2
    robtarget: [[330, 630, 0], [0.1830127, -0.6830127, -0.6830127, -0.1830127]]
    move: linear
    speed: v20
  - name: S3
    robtarget: [[480, 780, 0], [0.1830127, -0.6830127, -0.6830127, -0.1830127]]
    move: circular
    via: [436.066, 736.066, 0]
    speed: v20
    do: [{ set_do: [doWeld, 0] }, { pulse_do: doDone }, { wait_di: [diReady, 1] }, { grip_load: loadBox }, { grip_load: LOAD0 }]
    retract: 40
";

pub(super) fn parse_str(text: &str) -> Result<Cell, CellError> {
    parse(Path::new("cells/x.yaml"), text)
}

/// The 1-based line of the first occurrence of `needle` in `text`.
pub(super) fn line_of(text: &str, needle: &str) -> u64 {
    let at = text
        .find(needle)
        .unwrap_or_else(|| panic!("'{needle}' not in the text"));
    text[..at].matches('\n').count() as u64 + 1
}

/// Each `(text, message, at)`: the text is refused with the message (a part of it), at the line
/// of the first occurrence of `at`, with a help line.
pub(super) fn refused_at(cases: Vec<(String, &str, &str)>) {
    for (text, needle, at) in cases {
        let err = parse_str(&text).expect_err(needle);
        assert!(err.to_string().contains(needle), "'{err}' lacks '{needle}'");
        assert_eq!(
            err.loc().map(|l| l.line),
            Some(line_of(&text, at)),
            "{needle}: {err}"
        );
        assert!(err.help().is_some(), "{needle}");
    }
}

/// `SEAM` with `from` replaced by `to` (which must be there).
fn seam_with(from: &str, to: &str) -> String {
    assert!(SEAM.contains(from), "'{from}' not in SEAM");
    SEAM.replacen(from, to, 1)
}

#[test]
fn the_process_keys_are_read_as_given() {
    let c = parse_str(SEAM).expect("valid");
    let loads: Vec<_> = c
        .loads
        .iter()
        .map(|l| (l.name.as_str(), l.mass_kg, l.cog_mm, l.loc.line))
        .collect();
    assert_eq!(
        loads,
        [
            ("loadPart", 1.2, [0.0, 0.0, 60.0], 6),
            ("loadBox", 0.5, [0.0; 3], 7)
        ]
    );
    let [home, s1, s2, s3] = c.points.as_slice() else {
        panic!("{} points", c.points.len())
    };
    // home: as before, nothing of the new keys.
    assert_eq!(
        (
            home.arrival,
            home.approach_mm,
            home.retract_mm,
            home.wobj,
            home.revisit_of
        ),
        (Arrival::Joint, None, None, None, None)
    );
    assert!(home.actions.is_empty() && !home.stops());
    // S1: approached by 40 mm along its z axis, two actions in order.
    assert_eq!(
        (s1.arrival, s1.approach_mm, s1.retract_mm),
        (Arrival::Joint, Some(40.0), None)
    );
    assert_eq!(s1.approach_loc.line, line_of(SEAM, "approach: 40"));
    assert_eq!(s1.arrival_loc, s1.loc, "no `move:`: the entry's place");
    let kinds: Vec<&ActionKind> = s1.actions.iter().map(|a| &a.kind).collect();
    assert_eq!(
        kinds,
        [
            &ActionKind::SetDo {
                signal: "doWeld".into(),
                value: true
            },
            &ActionKind::WaitTime { time_s: 0.3 }
        ]
    );
    assert!(s1
        .actions
        .iter()
        .all(|a| a.loc.line == line_of(SEAM, "do: [{ set_do: [doWeld, 1]")));
    assert!(s1.actions[0].loc.column < s1.actions[1].loc.column);
    assert!(s1.stops());
    // S2: linear, at its own speed.
    assert_eq!(
        (s2.arrival, s2.speed.as_deref()),
        (Arrival::Linear, Some("v20"))
    );
    assert_eq!(s2.arrival_loc.line, line_of(SEAM, "move: linear"));
    assert!(!s2.stops());
    // S3: circular through its via, five actions, then a retract.
    assert_eq!(
        s3.arrival,
        Arrival::Circular {
            via_mm: [436.066, 736.066, 0.0],
            via_loc: Loc {
                line: line_of(SEAM, "via: [436.066"),
                column: 10
            }
        }
    );
    assert_eq!((s3.approach_mm, s3.retract_mm), (None, Some(40.0)));
    assert_eq!(s3.retract_loc.line, line_of(SEAM, "retract: 40"));
    let kinds: Vec<&ActionKind> = s3.actions.iter().map(|a| &a.kind).collect();
    assert_eq!(
        kinds,
        [
            &ActionKind::SetDo {
                signal: "doWeld".into(),
                value: false
            },
            &ActionKind::PulseDo {
                signal: "doDone".into()
            },
            &ActionKind::WaitDi {
                signal: "diReady".into(),
                value: true
            },
            &ActionKind::GripLoad { load: Some(1) },
            &ActionKind::GripLoad { load: None },
        ]
    );
    assert_eq!(
        s3.actions
            .iter()
            .map(|a| a.kind.signal())
            .collect::<Vec<_>>(),
        [Some("doWeld"), Some("doDone"), Some("diReady"), None, None]
    );
}

#[test]
fn approach_and_retract_take_1_to_1000_mm_with_3_decimals() {
    for (value, accepted) in [
        ("1", true),
        ("1000", true),
        ("12.345", true),
        ("0.999", false),
        ("1000.001", false),
        ("0", false),
        ("-40", false),
        ("12.3456", false),
        (".nan", false),
        ("1e9", false),
    ] {
        for key in ["approach", "retract"] {
            let text = seam_with(&format!("{key}: 40"), &format!("{key}: {value}"));
            let (point, line) = if key == "approach" { (1, 12) } else { (3, 24) };
            match parse_str(&text) {
                Ok(c) => {
                    assert!(accepted, "{key}: {value}");
                    let got = if key == "approach" {
                        c.points[point].approach_mm
                    } else {
                        c.points[point].retract_mm
                    };
                    assert_eq!(got, Some(value.parse::<f64>().expect("number")));
                }
                Err(e) => {
                    assert!(!accepted, "{key}: {value}: {e}");
                    assert_eq!(e.loc().map(|l| l.line), Some(line), "{key}: {value}: {e}");
                }
            }
        }
    }
}

#[test]
fn wait_time_takes_0_to_3600_s_and_masses_stay_above_0_when_written() {
    for (value, accepted) in [
        ("0", true),
        ("3600", true),
        ("0.001", true),
        ("3600.001", false),
        ("-0.5", false),
        ("0.0005", false),
    ] {
        let text = seam_with("wait_time: 0.3", &format!("wait_time: {value}"));
        assert_eq!(parse_str(&text).is_ok(), accepted, "wait_time: {value}");
    }
    // A mass is > 0 and still > 0 at the module's 3 decimals, and no finer.
    for (mass, needle) in [
        ("0", Some("must be a number > 0")),
        ("-1", Some("must be a number > 0")),
        ("0.0004", Some("is 0 at the module's 3 decimals")),
        ("0.0005", Some("more than 3 decimals")),
        ("0.001", None),
    ] {
        let text = seam_with("mass: 0.5", &format!("mass: {mass}"));
        match (parse_str(&text), needle) {
            (Ok(c), None) => assert_eq!(c.loads[1].mass_kg, 0.001),
            (Err(e), Some(needle)) => {
                assert!(
                    e.to_string().contains(needle),
                    "{mass}: '{e}' lacks '{needle}'"
                );
                assert_eq!(e.loc().map(|l| l.line), Some(7));
            }
            (r, _) => panic!("mass {mass}: {r:?}"),
        }
    }
}

#[test]
fn zones_apply_only_where_the_point_does_not_stop() {
    // Its own zone `fine` (any case) is accepted on a stop point; `motion.zone` is a default and
    // does not apply there.
    for zone in ["fine", "FINE"] {
        let text = seam_with(
            "    approach: 40\n",
            &format!("    approach: 40\n    zone: {zone}\n"),
        );
        parse_str(&text).expect(zone);
    }
    parse_str(&format!("{SEAM}motion:\n  zone: z50\n")).expect("motion.zone z50");
    // S2 (no actions, no lines) keeps its zone.
    let c = parse_str(&seam_with(
        "    speed: v20\n",
        "    speed: v20\n    zone: z10\n",
    ))
    .expect("S2 zoned");
    assert_eq!(c.points[2].zone.as_deref(), Some("z10"));
    // Actions, an approach, a retract: each alone makes the point a stop point.
    for (from, to, why) in [
        (
            "    approach: 40\n",
            "    approach: 40\n    zone: z10\n",
            "has actions (`do`)",
        ),
        (
            "    do: [{ set_do: [doWeld, 1] }, { wait_time: 0.3 }]\n",
            "    zone: z10\n",
            "has an approach line",
        ),
        (
            "    retract: 40\n",
            "    retract: 40\n    zone: z1\n",
            "has actions",
        ),
    ] {
        let text = seam_with(from, to);
        let err = parse_str(&text).expect_err(why);
        assert!(err.to_string().contains(why), "'{err}' lacks '{why}'");
        assert_eq!(
            err.loc().map(|l| l.line),
            Some(line_of(&text, "zone: z1")),
            "{err}"
        );
    }
    let text = seam_with(
        "    do: [{ set_do: [doWeld, 0] }, { pulse_do: doDone }, { wait_di: [diReady, 1] }, { grip_load: loadBox }, { grip_load: LOAD0 }]\n",
        "    zone: z10\n",
    );
    let err = parse_str(&text).expect_err("retract alone");
    assert!(err.to_string().contains("has a retract line"), "{err}");
}

#[test]
fn every_process_refusal_points_at_its_line() {
    // (text, message, the text on the line it points at)
    let cases: Vec<(String, &str, &str)> = vec![
        // move
        (seam_with("move: linear", "move: straight"), "move 'straight' is not one of joint, linear, circular", "move: straight"),
        (seam_with("{ name: home, joints: [90, 0, 0, 0, 30, 0] }", "{ name: home, joints: [90, 0, 0, 0, 30, 0], move: linear }"), "point 'home' is the first point: nothing moves `linear` into it", "name: home"),
        (seam_with("    robtarget: [[330, 630, 0], [0.1830127, -0.6830127, -0.6830127, -0.1830127]]\n", "    joints: [10, 20, 30]\n"), "point 'S2' is reached `linear`, which needs a robtarget, but 'S2' gives joint values", "move: linear"),
        (seam_with("    move: circular\n    via: [436.066, 736.066, 0]\n", "    move: circular\n"), "point 'S3' is reached `circular`, which needs `via`", "move: circular"),
        (seam_with("    move: circular\n", "    move: linear\n"), "point 'S3': `via` applies to `move: circular` only", "via: [436.066"),
        (seam_with("    move: circular\n", ""), "point 'S3': `via` applies to `move: circular` only", "via: [436.066"),
        (seam_with("via: [436.066, 736.066, 0]", "via: [436.0665, 736.066, 0]"), "point 'S3' via = 436.0665 has more than 3 decimals", "via: [436.0665"),
        (seam_with("via: [436.066, 736.066, 0]", "via: [436.066, 736.066]"), "point 'S3' via must have 3 numbers", "via: [436.066"),
        (seam_with("    move: linear\n", "    move: linear\n    retract: 10\n"), "point 'S3' is reached `circular` from point 'S2', which retracts (line 17)", "move: circular"),
        // approach and retract
        (seam_with("    move: linear\n", "    move: linear\n    approach: 10\n"), "point 'S2' approach: the point is reached `move: linear`", "approach: 10"),
        (seam_with("{ name: home, joints: [90, 0, 0, 0, 30, 0] }", "{ name: home, robtarget: [[0, 0, 0], [1, 0, 0, 0]], approach: 50 }"), "point 'home' approach: the first point is where the routine starts", "approach: 50"),
        (seam_with("{ name: home, joints: [90, 0, 0, 0, 30, 0] }", "{ name: home, joints: [90, 0, 0, 0, 30, 0], retract: 50 }"), "point 'home' retract needs a robtarget", "retract: 50"),
        (seam_with("approach: 40", "approach: 1001"), "point 'S1' approach = 1001 must be a number within 1 .. 1000 (mm)", "approach: 1001"),
        (seam_with("retract: 40", "retract: 0.5"), "point 'S3' retract = 0.5 must be a number within 1 .. 1000 (mm)", "retract: 0.5"),
        (seam_with("approach: 40", "approach: 40.0001"), "point 'S1' approach = 40.0001 has more than 3 decimals", "approach: 40.0001"),
        // actions
        (seam_with("{ wait_time: 0.3 }", "{ wait_time: 0.3, pulse_do: doX }"), "point 'S1': one action gives both `pulse_do` and `wait_time`", "wait_time: 0.3, pulse_do"),
        (seam_with("{ wait_time: 0.3 }", "{ }"), "point 'S1': an action gives one of set_do", "{ }"),
        (seam_with("{ wait_time: 0.3 }", "{ set_DO: [doX, 1] }"), "unknown field `set_DO`, expected one of set_do, pulse_do, wait_di, wait_time, grip_load", "set_DO"),
        (seam_with("set_do: [doWeld, 1]", "set_do: [9doWeld, 1]"), "point 'S1' set_do signal '9doWeld' is not a valid RAPID name", "9doWeld"),
        (seam_with("set_do: [doWeld, 1]", "set_do: [If, 1]"), "point 'S1' set_do signal 'If' is not a valid RAPID name: \"IF\" is a RAPID reserved word", "[If, 1]"),
        (seam_with("pulse_do: doDone", "pulse_do: tool0"), "point 'S3' pulse_do signal 'tool0' is not a valid RAPID name", "pulse_do: tool0"),
        (seam_with("set_do: [doWeld, 1]", "set_do: [doWeld, 2]"), "point 'S1' set_do doWeld: the value 2 is not 0 or 1", "[doWeld, 2]"),
        (seam_with("set_do: [doWeld, 1]", "set_do: [doWeld, 'on']"), "the value 'on' is not 0 or 1", "[doWeld, 'on']"),
        (seam_with("set_do: [doWeld, 1]", "set_do: [doWeld, true]"), "the value true is not 0 or 1", "[doWeld, true]"),
        (seam_with("set_do: [doWeld, 1]", "set_do: [doWeld, 0.5]"), "the value 0.5 is not 0 or 1", "[doWeld, 0.5]"),
        (seam_with("wait_di: [diReady, 1]", "wait_di: [diReady]"), "point 'S3' wait_di takes [signal, 0|1], found 1 values", "wait_di: [diReady]"),
        (seam_with("wait_di: [diReady, 1]", "wait_di: [1, diReady]"), "point 'S3' wait_di: the signal must be a name, found 1", "wait_di: [1, diReady]"),
        (seam_with("grip_load: loadBox", "grip_load: loadCrate"), "point 'S3' grip_load 'loadCrate' names no load of the cell", "grip_load: loadCrate"),
        (seam_with("wait_time: 0.3", "wait_time: 3601"), "point 'S1' wait_time = 3601 must be a number within 0 .. 3600 (s)", "wait_time: 3601"),
        (seam_with("wait_time: 0.3", "wait_time: 0.3001"), "point 'S1' wait_time = 0.3001 has more than 3 decimals", "wait_time: 0.3001"),
        // loads
        (seam_with("{ name: loadBox, mass: 0.5 }", "{ name: loadBox, cog: [0, 0, 10] }"), "load 'loadBox' gives no mass", "name: loadBox, cog"),
        (seam_with("{ name: loadBox, mass: 0.5 }", "{ name: load0, mass: 0.5 }"), "load name 'load0' is not a valid RAPID name", "name: load0"),
        (seam_with("cog: [0, 0, 60]", "cog: [0, 60]"), "load 'loadPart' cog must have 3 numbers", "cog: [0, 60]"),
        (seam_with("cog: [0, 0, 60]", "cog: [0, 0, 60.0001]"), "load 'loadPart' cog = 60.0001 has more than 3 decimals", "cog: [0, 0, 60.0001]"),
        // the name space: loads and signals
        (seam_with("{ name: loadBox, mass: 0.5 }", "{ name: LOADPART, mass: 0.5 }").replace("grip_load: loadBox", "grip_load: loadPart"), "load name 'LOADPART' is already the name of the load (line 6)", "name: LOADPART"),
        (seam_with("{ name: loadBox, mass: 0.5 }", "{ name: S2, mass: 0.5 }").replace("grip_load: loadBox", "grip_load: loadPart"), "point name 'S2' is already the name of the load (line 7)", "- name: S2"),
        (seam_with("name: S2", "name: doWeld"), "point name 'doWeld' is already the name of the signal doWeld (line 13)", "- name: doWeld"),
        (seam_with("module: M", "module: diReady"), "module name 'diReady' is already the name of the signal diReady (line 23)", "module: diReady"),
        (seam_with("{ name: loadBox, mass: 0.5 }", "{ name: doDone, mass: 0.5 }").replace("grip_load: loadBox", "grip_load: loadPart"), "load name 'doDone' is already the name of the signal doDone (line 23)", "name: doDone"),
        (seam_with("speed: v20\n    do:", "speed: doWeld\n    do:"), "point 'S3' speed 'doWeld' is already the name of the set_do signal of point 'S1' (line 13)", "speed: doWeld"),
        (seam_with("pulse_do: doDone", "pulse_do: main"), "point 'S3' pulse_do signal 'main' is already the name of the module's PROC main (its default)", "pulse_do: main"),
        (seam_with("wait_di: [diReady, 1]", "wait_di: [DOWELD, 1]"), "point 'S3' wait_di signal 'DOWELD' is already the name of the set_do signal of point 'S1' (line 13)", "wait_di: [DOWELD, 1]"),
        (format!("{SEAM}motion:\n  speed: doDone\n"), "motion.speed 'doDone' is already the name of the pulse_do signal of point 'S3' (line 23)", "speed: doDone"),
    ];
    refused_at(cases);
}

#[test]
fn a_signal_used_twice_the_same_way_is_one_signal() {
    // doWeld is set at S1 and at S3: one output, used twice.
    let c = parse_str(SEAM).expect("valid");
    assert_eq!(
        c.points[1].actions[0].kind.signal(),
        c.points[3].actions[0].kind.signal()
    );
    // An output pulsed and set is one output too.
    parse_str(&seam_with("pulse_do: doDone", "pulse_do: DOWELD")).expect("one output");
}
