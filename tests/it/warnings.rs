//! The warning for axes 4 and 6 near their limits: on stderr (after the module, with the other
//! warnings) and in the report's `near_limits`, naming the point, for every written axis-4 or
//! axis-6 value within 20 deg of a limit (the IRB 1400's: axis 4 -150 .. 150, axis 6 -300 ..
//! 300), 20 deg included; none for a value 20.001 deg away, none for axes 1..3 or 5.

use crate::common::{arg, gen_rapid, stderr, temp_cell};

const CELL: &str = "module: Limits
robot: { urdf: URDF, base: [0, 0, 0] }
points:
  - { name: P1, joints: [0, 0, 0, 0, 30, 285] }
  - { name: P2, joints: [10, 0, 0, -140, 30, 0] }
  - { name: P3, joints: [20, 0, 0, 130, 110, -280] }
  - { name: P4, joints: [30, 0, 0, 129.999, 30, 279.999] }
";

#[test]
fn axes_4_and_6_near_a_limit_are_warned_and_reported() {
    let dir = tempfile::tempdir().expect("temp dir");
    let cell = temp_cell(dir.path(), "limits.yaml", CELL);
    let report = dir.path().join("r.json");
    let out = gen_rapid(&[arg(&cell), "-q", "--report", arg(&report)]);
    assert!(out.status.success(), "{}", stderr(&out));
    let err = stderr(&out);
    // By hand: P1 axis 6 285 is 15 from 300; P2 axis 4 -140 is 10 from -150; P3 axis 4 130 and
    // axis 6 -280 are 20 from 150 and -300 (included); P4's 20.001 are not; no axis 5 (110 is
    // 5 from 115, but axis 5 is not warned).
    let warned: Vec<&str> = err.lines().filter(|l| l.starts_with("warning:")).collect();
    let expected = [
        "warning: point 'P1': axis 6 = 285.000 deg is 15.000 deg from its limit 300 deg",
        "warning: point 'P2': axis 4 = -140.000 deg is 10.000 deg from its limit -150 deg",
        "warning: point 'P3': axis 4 = 130.000 deg is 20.000 deg from its limit 150 deg",
        "warning: point 'P3': axis 6 = -280.000 deg is 20.000 deg from its limit -300 deg",
    ];
    assert_eq!(warned.len(), expected.len(), "{err}");
    for (w, e) in warned.iter().zip(expected) {
        assert!(w.starts_with(e), "{w}\nexpected {e}");
    }
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&report).expect("report")).expect("JSON");
    assert_eq!(r["format"], "gen-rapid report 4");
    let near = r["near_limits"].as_array().expect("near_limits");
    let rows: Vec<(String, u64, f64, f64, f64)> = near
        .iter()
        .map(|n| {
            (
                n["point"].as_str().expect("point").to_string(),
                n["axis"].as_u64().expect("axis"),
                n["value_deg"].as_f64().expect("value"),
                n["limit_deg"].as_f64().expect("limit"),
                n["room_deg"].as_f64().expect("room"),
            )
        })
        .collect();
    assert_eq!(
        rows,
        vec![
            ("P1".into(), 6, 285.0, 300.0, 15.0),
            ("P2".into(), 4, -140.0, -150.0, 10.0),
            ("P3".into(), 4, 130.0, 150.0, 20.0),
            ("P3".into(), 6, -280.0, -300.0, 20.0),
        ]
    );
}

#[test]
fn a_cell_far_from_the_limits_has_no_warning_and_an_empty_entry() {
    let dir = tempfile::tempdir().expect("temp dir");
    let report = dir.path().join("r.json");
    let out = gen_rapid(&["cells/trunk.yaml", "-q", "--report", arg(&report)]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(!stderr(&out).contains("from its limit"), "{}", stderr(&out));
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&report).expect("report")).expect("JSON");
    assert_eq!(r["near_limits"], serde_json::json!([]));
}
