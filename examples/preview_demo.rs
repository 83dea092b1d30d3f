//! A demo of the preview page, with a scene built by hand (not by the planner): an IRB-1400-like
//! arm (the link cylinders of `robots/irb1400.urdf`) with a straight welding torch lifts over
//! a clamp post, from point A through one via to point B, among a few boxes.
//!
//!     cargo run --release --example preview_demo -- preview-demo.html
//!
//! The picture in `docs/preview.png` is this page in headless Chromium:
//!
//!     chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
//!       --window-size=1200,800 --screenshot=docs/preview.png \
//!       'file:///PATH/preview-demo.html#t=1.4'
//!
//! The motion is sampled here with the URDF's serial kinematics and a quintic time profile per
//! move; the smallest clearance is found by sampling points of each shape (a demo value, not
//! the planner's certified one).

use gen_rapid::output::preview::{
    render_html, Keyframe, Scene, SceneBase, SceneClearance, SceneObstacle, ScenePose,
    SceneWaypoint, ShapeDef, ShapeGeometry, ShapeKind, WaypointKind,
};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

/// Axes 1..6 (controller values, deg) of A, the via and B.
const WAYPOINTS: [(&str, WaypointKind, [f64; 6]); 3] = [
    ("A", WaypointKind::Cell, [50.0, 25.0, 5.0, 0.0, 60.0, 0.0]),
    (
        "via01_01",
        WaypointKind::Via,
        [0.0, 5.0, -20.0, 0.0, 50.0, 0.0],
    ),
    ("B", WaypointKind::Cell, [-50.0, 25.0, 5.0, 0.0, 60.0, 0.0]),
];
/// Axis speed used by the demo's time profile (deg/s).
const AXIS_SPEED_DEG_S: f64 = 110.0;
/// Keyframes per second.
const RATE_HZ: f64 = 25.0;
/// TCP of the straight torch in the tool0 frame (mm).
const TCP_MM: [f64; 3] = [0.0, 0.0, 260.0];

fn shapes() -> Vec<ShapeDef> {
    let cyl = |name: &str, kind, radius_mm, from_mm, to_mm| ShapeDef {
        name: name.into(),
        kind,
        geometry: ShapeGeometry::Cylinder {
            radius_mm,
            from_mm,
            to_mm,
        },
    };
    vec![
        cyl(
            "link_1",
            ShapeKind::Link,
            350.0,
            [0.0; 3],
            [0.0, 0.0, 650.0],
        ),
        cyl(
            "link_2",
            ShapeKind::Link,
            150.0,
            [0.0; 3],
            [0.0, 0.0, 600.0],
        ),
        cyl(
            "link_3",
            ShapeKind::Link,
            120.0,
            [-300.0, 0.0, 120.0],
            [805.0, 0.0, 120.0],
        ),
        ShapeDef {
            name: "body".into(),
            kind: ShapeKind::Tool,
            geometry: ShapeGeometry::Box {
                min_mm: [-40.0, -40.0, 0.0],
                max_mm: [40.0, 40.0, 90.0],
            },
        },
        cyl(
            "neck",
            ShapeKind::Tool,
            18.0,
            [0.0, 0.0, 90.0],
            [0.0, 0.0, 225.0],
        ),
        ShapeDef {
            name: "nozzle".into(),
            kind: ShapeKind::Tool,
            geometry: ShapeGeometry::Sphere {
                centre_mm: [0.0, 0.0, 232.0],
                radius_mm: 14.0,
            },
        },
    ]
}

fn obstacles() -> Vec<SceneObstacle> {
    let b = |name: &str, min_mm, max_mm| SceneObstacle {
        name: name.into(),
        min_mm,
        max_mm,
    };
    vec![
        b("floor", [-700.0, -1100.0, -40.0], [1500.0, 1100.0, 0.0]),
        b("table", [650.0, -900.0, 0.0], [1300.0, 900.0, 550.0]),
        b("clamp_post", [880.0, -90.0, 550.0], [1040.0, 90.0, 1150.0]),
        b("fixture_left", [700.0, 420.0, 550.0], [980.0, 640.0, 800.0]),
        b(
            "fixture_right",
            [700.0, -640.0, 550.0],
            [980.0, -420.0, 800.0],
        ),
    ]
}

/// Frames of link_1, link_2, link_3 and tool0 in the robot base frame, from the URDF's serial
/// joints (the controller's axis 3 is q3 + q2).
fn frames(axes_deg: &[f64; 6]) -> [Isometry3<f64>; 4] {
    let r = |axis: Vector3<f64>, deg: f64| {
        UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(axis), deg.to_radians())
    };
    let joint = |x, y, z, rot| Isometry3::from_parts(Translation3::new(x, y, z), rot);
    let [a1, a2, a3, a4, a5, a6] = *axes_deg;
    let f1 = joint(0.0, 0.0, 0.0, r(Vector3::z(), a1));
    let f2 = f1 * joint(150.0, 0.0, 475.0, r(Vector3::y(), a2));
    let f3 = f2 * joint(0.0, 0.0, 600.0, r(Vector3::y(), a3 - a2));
    let f4 = f3 * joint(0.0, 0.0, 120.0, r(Vector3::x(), a4));
    let f5 = f4 * joint(720.0, 0.0, 0.0, r(Vector3::y(), a5));
    let f6 = f5 * joint(85.0, 0.0, 0.0, r(Vector3::x(), a6));
    let tool0 = f6 * joint(0.0, 0.0, 0.0, r(Vector3::y(), 90.0));
    [f1, f2, f3, tool0]
}

fn pose(iso: &Isometry3<f64>) -> ScenePose {
    let q = iso.rotation;
    ScenePose {
        position_mm: iso.translation.vector.into(),
        quat_wxyz: [q.w, q.i, q.j, q.k],
    }
}

/// Distance from `p` to the box and the box's closest point.
fn to_box(p: &Point3<f64>, o: &SceneObstacle) -> (f64, Point3<f64>) {
    let c = Point3::from(std::array::from_fn::<f64, 3, _>(|i| {
        p[i].clamp(o.min_mm[i], o.max_mm[i])
    }));
    ((p - c).norm(), c)
}

/// Sample points of a shape in its own frame, with the radius to subtract (0 for boxes).
fn samples(g: &ShapeGeometry) -> Vec<(Point3<f64>, f64)> {
    match g {
        ShapeGeometry::Cylinder {
            radius_mm,
            from_mm,
            to_mm,
        } => (0..=60)
            .map(|i| {
                let s = i as f64 / 60.0;
                let p =
                    Point3::from(*from_mm) + (Point3::from(*to_mm) - Point3::from(*from_mm)) * s;
                (p, *radius_mm)
            })
            .collect(),
        ShapeGeometry::Box { min_mm, max_mm } => {
            let mut v = Vec::new();
            for i in 0..=4 {
                for j in 0..=4 {
                    for k in 0..=4 {
                        let t = [i, j, k].map(|n| n as f64 / 4.0);
                        v.push((
                            Point3::from(std::array::from_fn::<f64, 3, _>(|a| {
                                min_mm[a] + t[a] * (max_mm[a] - min_mm[a])
                            })),
                            0.0,
                        ));
                    }
                }
            }
            v
        }
        ShapeGeometry::Sphere {
            centre_mm,
            radius_mm,
        } => vec![(Point3::from(*centre_mm), *radius_mm)],
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "preview-demo.html".into());
    let base = Isometry3::translation(0.0, 0.0, 0.0);
    let shapes = shapes();
    let obstacles = obstacles();
    let frame_of = [0usize, 1, 2, 3, 3, 3]; // shape -> index into frames()
    let tcp_local = Point3::from(TCP_MM);

    let mut keyframes = Vec::new();
    let mut waypoints = Vec::new();
    let mut t0 = 0.0;
    let mut best: Option<SceneClearance> = None;
    for (m, pair) in WAYPOINTS.windows(2).enumerate() {
        let (from, to) = (pair[0].2, pair[1].2);
        let span = (0..6).map(|i| (to[i] - from[i]).abs()).fold(0.0, f64::max);
        let duration = 1.875 * span / AXIS_SPEED_DEG_S; // quintic: peak speed 1.875 x mean
        let steps = (duration * RATE_HZ).ceil().max(1.0) as usize;
        let first = if m == 0 { 0 } else { 1 };
        for k in first..=steps {
            let u = k as f64 / steps as f64;
            let s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
            let axes: [f64; 6] = std::array::from_fn(|i| from[i] + s * (to[i] - from[i]));
            let time_s = t0 + u * duration;
            let f = frames(&axes).map(|f| base * f);
            let tcp = f[3] * tcp_local;
            for (n, shape) in shapes.iter().enumerate() {
                for (p, r) in samples(&shape.geometry) {
                    let world = f[frame_of[n]] * p;
                    for obstacle in &obstacles {
                        // The robot stands on the floor: its base cylinder touches it.
                        if n == 0 && obstacle.name == "floor" {
                            continue;
                        }
                        let (d, c) = to_box(&world, obstacle);
                        let on_shape = c + (world - c) * ((d - r) / d.max(1e-9));
                        if best.as_ref().is_none_or(|b| d - r < b.distance_mm) {
                            best = Some(SceneClearance {
                                distance_mm: d - r,
                                move_index: m,
                                shape: shape.name.clone(),
                                obstacle: obstacle.name.clone(),
                                time_s: Some(time_s),
                                points_mm: Some([on_shape.into(), c.into()]),
                            });
                        }
                    }
                }
            }
            keyframes.push(Keyframe {
                time_s,
                poses: f
                    .iter()
                    .enumerate()
                    .flat_map(|(i, fr)| std::iter::repeat_n(pose(fr), if i == 3 { 3 } else { 1 }))
                    .collect(),
                tcp_mm: tcp.into(),
            });
        }
        if m == 0 {
            waypoints.push(waypoint(&pair[0], 0.0, &base, &tcp_local));
        }
        t0 += duration;
        waypoints.push(waypoint(&pair[1], t0, &base, &tcp_local));
    }

    let scene = Scene {
        title: "PreviewDemo - demo.yaml (hand-built scene)".into(),
        module: "PreviewDemo".into(),
        cell_file: "demo.yaml".into(),
        obstacles,
        base: SceneBase {
            position_mm: [0.0; 3],
            yaw_deg: 0.0,
        },
        shapes,
        keyframes,
        waypoints,
        // As a module header would state them: 0.1 mm, 0.01 s.
        clearance: best.map(|c| SceneClearance {
            distance_mm: (c.distance_mm * 10.0).round() / 10.0,
            ..c
        }),
        total_time_s: Some((t0 * 100.0).round() / 100.0),
        failure: None,
    };
    let html = render_html(&scene)?;
    std::fs::write(&out, &html)?;
    eprintln!(
        "wrote {out}: {} bytes, {} keyframes, {:.2} s, min clearance {:.1} mm",
        html.len(),
        scene.keyframes.len(),
        t0,
        scene.clearance.as_ref().map_or(f64::NAN, |c| c.distance_mm)
    );
    Ok(())
}

fn waypoint(
    w: &(&str, WaypointKind, [f64; 6]),
    time_s: f64,
    base: &Isometry3<f64>,
    tcp_local: &Point3<f64>,
) -> SceneWaypoint {
    let tool0 = base * frames(&w.2)[3];
    SceneWaypoint {
        name: w.0.into(),
        kind: w.1,
        time_s,
        tcp_mm: (tool0 * tcp_local).into(),
    }
}
