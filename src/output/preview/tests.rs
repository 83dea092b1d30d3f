//! Unit tests of the preview page writer (the page in a real browser: tests/preview_browser.rs).

use super::*;
use std::f64::consts::FRAC_1_SQRT_2;

fn pose(x: f64) -> ScenePose {
    ScenePose {
        position_mm: [x, 0.0, 475.0],
        quat_wxyz: [1.0, 0.0, 0.0, 0.0],
    }
}

/// A small scene with one of everything.
fn scene() -> Scene {
    Scene {
        title: "Demo - demo.yaml".into(),
        module: "Demo".into(),
        cell_file: "cells/demo.yaml".into(),
        obstacles: vec![SceneObstacle {
            name: "table".into(),
            min_mm: [500.0, -300.0, 0.0],
            max_mm: [900.0, 300.0, 400.0],
        }],
        base: Some(SceneBase {
            position_mm: [0.0, 0.0, 0.0],
            yaw_deg: 90.0,
        }),
        shapes: vec![
            ShapeDef {
                name: "link_2".into(),
                kind: ShapeKind::Link,
                geometry: ShapeGeometry::Cylinder {
                    radius_mm: 150.0,
                    from_mm: [0.0; 3],
                    to_mm: [0.0, 0.0, 600.0],
                },
            },
            ShapeDef {
                name: "cup".into(),
                kind: ShapeKind::Tool,
                geometry: ShapeGeometry::Sphere {
                    centre_mm: [0.0, 0.0, 100.0],
                    radius_mm: 15.0,
                },
            },
            ShapeDef {
                name: "body".into(),
                kind: ShapeKind::Tool,
                geometry: ShapeGeometry::Box {
                    min_mm: [-45.0, -45.0, 0.0],
                    max_mm: [45.0, 45.0, 110.0],
                },
            },
        ],
        keyframes: vec![
            Keyframe {
                time_s: 0.0,
                poses: vec![pose(150.0); 3],
                tcp_mm: [800.0, 0.0, 900.0],
            },
            Keyframe {
                time_s: 1.5,
                poses: vec![pose(160.0); 3],
                tcp_mm: [800.0, 100.0, 900.0],
            },
        ],
        waypoints: vec![
            SceneWaypoint {
                name: "A".into(),
                kind: WaypointKind::Cell,
                time_s: 0.0,
                tcp_mm: [800.0, 0.0, 900.0],
                actions: Vec::new(),
            },
            SceneWaypoint {
                name: "B".into(),
                kind: WaypointKind::Cell,
                time_s: 1.5,
                tcp_mm: [800.0, 100.0, 900.0],
                actions: vec!["SetDO doWeld, 1".into()],
            },
        ],
        moves: vec![SceneMove {
            kind: "linear".into(),
            instruction: "MoveL B_rt".into(),
        }],
        clearance: Some(SceneClearance {
            distance_mm: 12.34,
            move_index: 0,
            corner_waypoint: None,
            shape: "link_2".into(),
            obstacle: "table".into(),
            time_s: Some(0.75),
            points_mm: Some([[480.0, 0.0, 300.0], [500.0, 0.0, 300.0]]),
        }),
        total_time_s: Some(1.5),
        failure: None,
    }
}

/// The inlined scene JSON of a page.
fn scene_text(html: &str) -> &str {
    let start = html
        .find(r#"<script type="application/json" id="scene">"#)
        .unwrap();
    let rest = &html[start..];
    let open = rest.find('>').unwrap() + 1;
    let close = rest.find("</script>").unwrap();
    &rest[open..close]
}

#[test]
fn template_has_each_marker_once() {
    for marker in ["@TITLE@", "/*@CSS@*/", "/*@SCENE@*/", "/*@JS@*/"] {
        assert_eq!(PAGE_HTML.matches(marker).count(), 1, "{marker}");
    }
}

#[test]
fn page_loads_nothing_from_the_network() {
    let html = render_html(&scene()).unwrap();
    let lower = html.to_ascii_lowercase();
    for bad in [
        "http://",
        "https://",
        "src=\"http",
        "href=\"http",
        "fetch(",
        "xmlhttprequest",
        "import(",
        "@import",
        "url(",
        "<link",
        "<img",
        "<iframe",
        "websocket",
        "eventsource",
    ] {
        assert!(!lower.contains(bad), "the page contains {bad:?}");
    }
    // Every <script> is inline: none has a src attribute.
    assert!(!lower.contains("<script src"));
    assert_eq!(lower.matches("<script").count(), 3);
}

#[test]
fn same_scene_same_bytes() {
    let a = render_html(&scene()).unwrap();
    let b = render_html(&scene().clone()).unwrap();
    assert_eq!(a, b);
    // Not a constant either: a different scene gives a different page.
    let mut other = scene();
    other.obstacles[0].max_mm[2] = 401.0;
    assert_ne!(a, render_html(&other).unwrap());
}

#[test]
fn numbers_have_fixed_precision_and_no_negative_zero() {
    let mut s = scene();
    s.obstacles[0].min_mm = [500.123_456, -0.000_2, 1e-9];
    s.keyframes[1].poses[0].quat_wxyz = [FRAC_1_SQRT_2, 0.0, -FRAC_1_SQRT_2, -0.000_01];
    s.keyframes[1].time_s = 1.234_567_8;
    s.keyframes.truncate(2);
    let html = render_html(&s).unwrap();
    let json = scene_text(&html);
    assert!(json.contains(r#""min_mm":[500.123,0.0,0.0]"#), "{json}");
    assert!(
        json.contains(r#""quat_wxyz":[0.7071,0.0,-0.7071,0.0]"#),
        "{json}"
    );
    assert!(json.contains(r#""time_s":1.235"#), "{json}");
    assert!(!json.contains("-0.0,") && !json.contains("-0.0]"), "{json}");
    // Integers stay integers.
    assert!(json.contains(r#""move_index":0"#), "{json}");
}

#[test]
fn every_float_key_has_a_unit_suffix() {
    // The precision follows the key's unit: a float under a key without one would be written
    // with OTHER_DECIMALS, which no field of the scene should need.
    fn walk(v: &Value, key: &str, bad: &mut Vec<String>) {
        match v {
            Value::Number(n) if n.is_f64() && decimals_for_key(key).is_none() => {
                bad.push(key.to_string())
            }
            Value::Array(a) => a.iter().for_each(|x| walk(x, key, bad)),
            Value::Object(m) => m.iter().for_each(|(k, x)| {
                let k = if decimals_for_key(k).is_some() {
                    k
                } else {
                    key
                };
                walk(x, k, bad)
            }),
            _ => {}
        }
    }
    let mut s = scene();
    s.failure = Some(SceneFailure {
        message: "no path".into(),
        points: vec![FailedPoint {
            name: "A".into(),
            position_mm: [1.5, 2.5, 3.5],
        }],
    });
    let mut bad = Vec::new();
    walk(&serde_json::to_value(&s).unwrap(), "", &mut bad);
    assert!(bad.is_empty(), "floats without a unit suffix: {bad:?}");
}

#[test]
fn names_cannot_close_the_script_or_the_title() {
    let evil = "x</script><script>alert(1)</script><!--&\u{2028}";
    let mut s = scene();
    s.title = evil.into();
    s.obstacles[0].name = evil.into();
    s.waypoints[0].name = evil.into();
    s.failure = Some(SceneFailure {
        message: evil.into(),
        points: vec![],
    });
    let html = render_html(&s).unwrap();
    let plain = render_html(&scene()).unwrap();
    let count = |h: &str, pat: &str| h.to_ascii_lowercase().matches(pat).count();
    assert_eq!(count(&html, "</script"), count(&plain, "</script"));
    assert_eq!(count(&html, "<script"), count(&plain, "<script"));
    assert_eq!(count(&html, "<!--"), count(&plain, "<!--"));
    // A raw line separator would end a JavaScript string literal in older engines.
    assert!(!scene_text(&html).contains('\u{2028}'));
    assert!(html.contains("<title>x&lt;/script&gt;&lt;script&gt;alert(1)"));
    // The JSON still says the same: the escapes decode to the original name.
    let value: Value = serde_json::from_str(scene_text(&html)).unwrap();
    assert_eq!(value["obstacles"][0]["name"], evil);
    assert_eq!(value["failure"]["message"], evil);
}

#[test]
fn refuses_what_the_page_cannot_draw() {
    let mut s = scene();
    s.keyframes[1].poses.pop();
    assert!(matches!(
        render_html(&s),
        Err(PreviewError::PoseCount {
            keyframe: 1,
            expected: 3,
            found: 2
        })
    ));
    let mut s = scene();
    s.keyframes[1].time_s = -1.0;
    assert!(matches!(
        render_html(&s),
        Err(PreviewError::TimeOrder { keyframe: 1 })
    ));
    let mut s = scene();
    s.keyframes[0].tcp_mm[1] = f64::NAN;
    let e = render_html(&s).unwrap_err();
    assert!(e.to_string().contains("keyframe 0"), "{e}");
    let mut s = scene();
    s.total_time_s = Some(f64::INFINITY);
    assert!(matches!(
        render_html(&s),
        Err(PreviewError::NotFinite { .. })
    ));
    let mut s = scene();
    if let Some(c) = &mut s.clearance {
        c.shape = "link_9".into();
    }
    assert!(matches!(
        render_html(&s),
        Err(PreviewError::UnknownShape(_))
    ));
}

#[test]
fn failed_plan_without_motion_is_a_page() {
    let mut s = scene();
    s.keyframes.clear();
    s.waypoints.clear();
    s.clearance = None;
    s.total_time_s = None;
    s.failure = Some(SceneFailure {
        message: "no path from 'A' to 'B'".into(),
        points: vec![
            FailedPoint {
                name: "A".into(),
                position_mm: [800.0, 0.0, 900.0],
            },
            FailedPoint {
                name: "B".into(),
                position_mm: [800.0, 100.0, 900.0],
            },
        ],
    });
    let html = render_html(&s).unwrap();
    let value: Value = serde_json::from_str(scene_text(&html)).unwrap();
    assert_eq!(value["keyframes"].as_array().map(Vec::len), Some(0));
    assert_eq!(value["failure"]["points"][1]["name"], "B");
    assert_eq!(value["clearance"], Value::Null);
}
