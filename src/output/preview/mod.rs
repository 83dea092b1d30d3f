//! The 3D preview page (`--html FILE`): one self-contained HTML file that shows the
//! cell's boxes, the robot's collision cylinders and the tool's shapes, and plays the program
//! along its estimated timing, with the waypoints, the TCP trace and the place of the smallest
//! clearance; on a failed plan, the cell and the points that could not be joined.
//!
//! This is an output stage and goes beyond the paper (which has no such picture). Two parts:
//! [`scene`] (`scene.rs`) samples a run into a [`Scene`]: every shape's pose in the cell frame
//! at a list of keyframe times, by the robot's forward kinematics along the estimated timing,
//! from the cell, the placed job and the plan (or, for a failed plan, [`failure_scene`]);
//! [`render_html`] (this file) writes the page, which only draws the shapes and interpolates
//! between keyframes (positions linearly, quaternions by normalised linear interpolation).
//! Whatever the page shows is therefore what Rust computed.
//!
//! The page is assembled from three embedded assets under `templates/preview/` (the HTML
//! skeleton, the stylesheet and a few hundred lines of plain WebGL 1 script, documented at its
//! top) and the scene as JSON, inlined in a `<script type="application/json">` element. It
//! loads nothing at all from the network (no CDN, no fonts, no images), so it opens from
//! `file://` in any browser with WebGL.
//!
//! Deterministic bytes: the scene is written with fixed precisions chosen by the unit suffix of
//! each JSON key ([`decimals_for_key`], from the one table [`crate::precision`]: 3 decimals for
//! `_mm`, `_s`, `_deg`; 4 for the quaternions `_wxyz`), no `-0`, sorted keys, and no timestamp anywhere. `<`, `>`, `&` and
//! the JavaScript line separators are written as `\u` escapes inside the JSON, so no name can
//! close the script element (`</script>`) or open a comment.
//!
//! Frames and units: the cell frame, z up, millimetres, seconds; quaternions `[w, x, y, z]` as
//! RAPID writes them.

use serde::Serialize;
use serde_json::Value;

mod scene;
#[cfg(test)]
mod tests;

pub use scene::{failure_scene, scene};

/// The HTML skeleton; `/*@CSS@*/`, `/*@SCENE@*/`, `/*@JS@*/` and `@TITLE@` are filled in.
const PAGE_HTML: &str = include_str!("../../../templates/preview/page.html");
/// The stylesheet of the page.
const PAGE_CSS: &str = include_str!("../../../templates/preview/preview.css");
/// The WebGL viewer (plain WebGL 1, no library).
const PAGE_JS: &str = include_str!("../../../templates/preview/preview.js");

// The decimals of the scene's numbers, by unit suffix: the one table, `crate::precision`.
pub use crate::precision::{
    PREVIEW_DEG_DECIMALS as DEG_DECIMALS, PREVIEW_MM_DECIMALS as MM_DECIMALS,
    PREVIEW_OTHER_DECIMALS as OTHER_DECIMALS, PREVIEW_QUAT_DECIMALS as QUAT_DECIMALS,
    PREVIEW_SECONDS_DECIMALS as SECONDS_DECIMALS,
};

/// Everything the preview page shows; filled by the pipeline, drawn by the page as it is.
///
/// All positions are in the cell frame (z up), in millimetres; times in seconds from the start
/// of the program; quaternions `[w, x, y, z]` (need not be exactly normalised: the page
/// normalises them).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scene {
    /// Heading of the page (for example "TrunkWeld - trunk.yaml").
    pub title: String,
    /// The RAPID module's name.
    pub module: String,
    /// The cell file the run read, as the user gave it (shown, never opened).
    pub cell_file: String,
    /// The cell's boxes.
    pub obstacles: Vec<SceneObstacle>,
    /// Where the robot stands; `None` when it is not known (a failed choice of base).
    pub base: Option<SceneBase>,
    /// The robot's collision shapes (link cylinders) and the tool's shapes, each in its own
    /// frame; [`Keyframe::poses`] places them.
    pub shapes: Vec<ShapeDef>,
    /// The sampled motion, in time order. Empty or a single keyframe on a failed plan (the
    /// robot is then drawn still, or not at all).
    pub keyframes: Vec<Keyframe>,
    /// The program's waypoints (cell points and vias) in order; move `i` runs from waypoint
    /// `i` to waypoint `i + 1`.
    pub waypoints: Vec<SceneWaypoint>,
    /// The moves, move `i` from waypoint `i` to waypoint `i + 1`: how each runs and the
    /// instruction it is written with (the page colours the TCP trace by kind).
    pub moves: Vec<SceneMove>,
    /// The smallest clearance of the whole program and where it occurs, if known.
    pub clearance: Option<SceneClearance>,
    /// The estimated time of the whole program (s), if estimated, as the module header
    /// states it (rounded to the header's precision, so that the page, which shows it with 2
    /// decimals, agrees with the header). The page's time axis runs to the larger of this and
    /// the last keyframe's time.
    pub total_time_s: Option<f64>,
    /// Why planning failed, with the points that could not be joined; `None` on success.
    pub failure: Option<SceneFailure>,
}

/// One box of the cell: axis-aligned in the cell frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneObstacle {
    pub name: String,
    /// Lower corner (mm).
    pub min_mm: [f64; 3],
    /// Upper corner (mm).
    pub max_mm: [f64; 3],
}

/// The robot base: its origin in the cell frame and its rotation about z.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneBase {
    pub position_mm: [f64; 3],
    pub yaw_deg: f64,
}

/// Whether a shape belongs to the arm or to the tool (drawn in different colours).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ShapeKind {
    /// A link's collision cylinder (the paper's lumped arm model).
    Link,
    /// A collision volume of the tool, carried by the flange.
    Tool,
}

/// One collision shape, in its own frame (the link's frame or the flange frame); the
/// keyframes give that frame's pose in the cell frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShapeDef {
    /// The name the clearance refers to (`link_3`, or a tool shape's name such as `neck`).
    pub name: String,
    pub kind: ShapeKind,
    pub geometry: ShapeGeometry,
}

/// A shape's geometry in its own frame (mm). Serialised with a `"type"` tag.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum ShapeGeometry {
    /// A solid cylinder around the segment `from_mm` - `to_mm`.
    Cylinder {
        radius_mm: f64,
        from_mm: [f64; 3],
        to_mm: [f64; 3],
    },
    /// A box, axis-aligned in the shape's own frame.
    Box { min_mm: [f64; 3], max_mm: [f64; 3] },
    /// A ball.
    Sphere { centre_mm: [f64; 3], radius_mm: f64 },
}

/// A pose in the cell frame: the frame's origin and its orientation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ScenePose {
    pub position_mm: [f64; 3],
    /// Orientation as a quaternion `[w, x, y, z]`.
    pub quat_wxyz: [f64; 4],
}

/// The robot at one instant.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Keyframe {
    /// Time from the program's start (s); keyframes are in non-decreasing time order.
    pub time_s: f64,
    /// The pose of each shape's frame, in the order of [`Scene::shapes`] (same length).
    pub poses: Vec<ScenePose>,
    /// The TCP (tool0 without a tool) in the cell frame (mm); the page draws their trace.
    pub tcp_mm: [f64; 3],
}

/// Whether a waypoint is one of the cell's points or a via the planner added.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum WaypointKind {
    /// A point of the cell file.
    Cell,
    /// An intermediate waypoint of the planner.
    Via,
    /// A point's approach pose (where its approach line starts).
    Approach,
    /// A point's retract pose (where its retract line ends).
    Retract,
}

/// A move of the program as the module writes it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneMove {
    /// `joint` (an air move), `approach`, `linear`, `circular` or `retract`: the TCP runs the
    /// line or arc of a process move (its keyframes follow the path), joint interpolation on
    /// an air move.
    pub kind: String,
    /// The instruction and its target as written (`MoveL L2_rt`, `MoveC S2_via, S2_rt`).
    pub instruction: String,
}

/// A waypoint of the program.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneWaypoint {
    /// Its name in the module (`A`, `via01_02`).
    pub name: String,
    pub kind: WaypointKind,
    /// When the robot reaches it (s).
    pub time_s: f64,
    /// The TCP position there (mm).
    pub tcp_mm: [f64; 3],
    /// The actions done there, after the move into it, as the module writes them (`SetDO
    /// doWeld, 1`); the page marks the point and lists them.
    pub actions: Vec<String>,
}

/// The smallest clearance of the program: how small, on which move, between which shape and
/// which obstacle.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneClearance {
    /// The clearance (mm), as the module header states it (rounded to its precision; the
    /// page shows 1 decimal).
    pub distance_mm: f64,
    /// The move it occurs on, 0-based: move `i` runs from waypoint `i` to waypoint `i + 1`
    /// (the page shows it 1-based, as "move i+1").
    pub move_index: usize,
    /// Where the smallest clearance is a zoned corner's (a fly-by waypoint's blend, which no
    /// single move holds): that waypoint's index, which the page names instead of the move.
    pub corner_waypoint: Option<usize>,
    /// The link or tool shape (a [`ShapeDef::name`]).
    pub shape: String,
    /// The obstacle (a [`SceneObstacle::name`]).
    pub obstacle: String,
    /// When it occurs (s), if known; clicking the page's clearance label shows the robot
    /// then (else at the start of the move).
    pub time_s: Option<f64>,
    /// The two closest points, on the shape and on the obstacle (mm), if known; the page
    /// draws a line between them. Without them the obstacle is highlighted.
    pub points_mm: Option<[[f64; 3]; 2]>,
}

/// A failed plan: the message and the points that could not be joined.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneFailure {
    /// The error message, as printed on stderr (one or more lines).
    pub message: String,
    /// The points that could not be joined (usually the two ends of the leg that failed).
    pub points: Vec<FailedPoint>,
}

/// A point named in a failure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FailedPoint {
    pub name: String,
    /// Its position in the cell frame (mm): the TCP, or the wrist centre where that is what
    /// the point gives.
    pub position_mm: [f64; 3],
}

/// Why the page could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PreviewError {
    #[error(
        "cannot write the preview page: {path} holds a number that is not finite (NaN or infinite)"
    )]
    NotFinite { path: String },
    #[error(
        "cannot write the preview page: keyframe {keyframe} has {found} poses, \
         but the scene has {expected} shapes"
    )]
    PoseCount {
        keyframe: usize,
        expected: usize,
        found: usize,
    },
    #[error("cannot write the preview page: keyframe {keyframe} is earlier than the one before")]
    TimeOrder { keyframe: usize },
    #[error(
        "cannot write the preview page: the clearance names shape '{0}', which is not in the scene"
    )]
    UnknownShape(String),
    #[error("cannot write the preview page: {0}")]
    Json(#[from] serde_json::Error),
}

/// Writes the preview page for `scene`: one self-contained HTML document (UTF-8), the same
/// bytes for the same scene.
pub fn render_html(scene: &Scene) -> Result<String, PreviewError> {
    check(scene)?;
    let json = scene_json(scene)?;
    let title = html_escape(&scene.title);
    Ok(fill(
        PAGE_HTML,
        &[
            ("@TITLE@", &title),
            ("/*@CSS@*/", PAGE_CSS),
            ("/*@SCENE@*/", &json),
            ("/*@JS@*/", PAGE_JS),
        ],
    ))
}

/// The checks the page relies on: finite numbers, one pose per shape in every keyframe,
/// keyframes in time order, a clearance that names a known shape.
fn check(scene: &Scene) -> Result<(), PreviewError> {
    check_finite(scene)?;
    let expected = scene.shapes.len();
    for (i, k) in scene.keyframes.iter().enumerate() {
        if k.poses.len() != expected {
            return Err(PreviewError::PoseCount {
                keyframe: i,
                expected,
                found: k.poses.len(),
            });
        }
        if i > 0 && k.time_s < scene.keyframes[i - 1].time_s {
            return Err(PreviewError::TimeOrder { keyframe: i });
        }
    }
    if let Some(c) = &scene.clearance {
        if !scene.shapes.iter().any(|s| s.name == c.shape) {
            return Err(PreviewError::UnknownShape(c.shape.clone()));
        }
    }
    Ok(())
}

/// Every number of the scene is finite (serde_json would silently write NaN as `null`).
fn check_finite(scene: &Scene) -> Result<(), PreviewError> {
    fn f(path: impl Fn() -> String, xs: &[f64]) -> Result<(), PreviewError> {
        if xs.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(PreviewError::NotFinite { path: path() })
        }
    }
    for o in &scene.obstacles {
        f(
            || format!("obstacle '{}'", o.name),
            &[o.min_mm, o.max_mm].concat(),
        )?;
    }
    if let Some(b) = &scene.base {
        f(
            || "the base".into(),
            &[&b.position_mm[..], &[b.yaw_deg]].concat(),
        )?;
    }
    for s in &scene.shapes {
        let xs = match &s.geometry {
            ShapeGeometry::Cylinder {
                radius_mm,
                from_mm,
                to_mm,
            } => [&[*radius_mm][..], from_mm, to_mm].concat(),
            ShapeGeometry::Box { min_mm, max_mm } => [*min_mm, *max_mm].concat(),
            ShapeGeometry::Sphere {
                centre_mm,
                radius_mm,
            } => [&centre_mm[..], &[*radius_mm]].concat(),
        };
        f(|| format!("shape '{}'", s.name), &xs)?;
    }
    for (i, k) in scene.keyframes.iter().enumerate() {
        let path = || format!("keyframe {i}");
        f(path, &[&[k.time_s][..], &k.tcp_mm].concat())?;
        for p in &k.poses {
            f(path, &[&p.position_mm[..], &p.quat_wxyz].concat())?;
        }
    }
    for w in &scene.waypoints {
        f(
            || format!("waypoint '{}'", w.name),
            &[&[w.time_s][..], &w.tcp_mm].concat(),
        )?;
    }
    if let Some(c) = &scene.clearance {
        let pts = c.points_mm.map(|p| p.concat()).unwrap_or_default();
        let t: Vec<f64> = c.time_s.into_iter().collect();
        f(
            || "the clearance".into(),
            &[&[c.distance_mm][..], &pts, &t].concat(),
        )?;
    }
    if let Some(t) = scene.total_time_s {
        f(|| "the total time".into(), &[t])?;
    }
    if let Some(fail) = &scene.failure {
        for p in &fail.points {
            f(|| format!("failed point '{}'", p.name), &p.position_mm)?;
        }
    }
    Ok(())
}

/// The scene as compact JSON with fixed precisions, safe to inline in a `<script>` element.
fn scene_json(scene: &Scene) -> Result<String, PreviewError> {
    let mut value = serde_json::to_value(scene)?;
    round_value(&mut value, OTHER_DECIMALS);
    let text = serde_json::to_string(&value)?;
    Ok(script_safe(&text))
}

/// Decimals for the numbers under a JSON key, by the key's unit suffix.
pub fn decimals_for_key(key: &str) -> Option<usize> {
    if key.ends_with("_mm") {
        Some(MM_DECIMALS)
    } else if key.ends_with("_s") {
        Some(SECONDS_DECIMALS)
    } else if key.ends_with("_deg") {
        Some(DEG_DECIMALS)
    } else if key.ends_with("_wxyz") {
        Some(QUAT_DECIMALS)
    } else {
        None
    }
}

/// Rounds every float in `v` to the decimals of its nearest enclosing key (`decimals` for
/// numbers under no unit key); integers stay as they are. (Non-finite numbers were refused by
/// [`check`]: serde_json would have written them as `null`.)
fn round_value(v: &mut Value, decimals: usize) {
    match v {
        Value::Number(n) if n.is_f64() => {
            if let Some(r) = n.as_f64().and_then(|x| rounded(x, decimals)) {
                *n = r;
            }
        }
        Value::Array(items) => items
            .iter_mut()
            .for_each(|item| round_value(item, decimals)),
        Value::Object(map) => {
            for (key, item) in map.iter_mut() {
                round_value(item, decimals_for_key(key).unwrap_or(decimals));
            }
        }
        _ => {}
    }
}

/// `x` rounded to `decimals` places as a JSON number with no `-0`; `None` when not finite.
fn rounded(x: f64, decimals: usize) -> Option<serde_json::Number> {
    if !x.is_finite() {
        return None;
    }
    let scale = 10f64.powi(decimals as i32);
    let mut r = (x * scale).round() / scale;
    if r == 0.0 {
        r = 0.0; // also turns -0.0 into 0.0
    }
    serde_json::Number::from_f64(r)
}

/// JSON text that cannot end or comment out the `<script>` element it is inlined in, nor be
/// cut by a JavaScript line separator: `<`, `>`, `&`, U+2028 and U+2029 become `\u` escapes.
/// (They can only occur inside JSON strings, where the escape means the same character.)
fn script_safe(json: &str) -> String {
    let mut out = String::with_capacity(json.len());
    for c in json.chars() {
        match c {
            '<' => out.push_str("\\u003c"),
            '>' => out.push_str("\\u003e"),
            '&' => out.push_str("\\u0026"),
            '\u{2028}' => out.push_str("\\u2028"),
            '\u{2029}' => out.push_str("\\u2029"),
            _ => out.push(c),
        }
    }
    out
}

/// Text safe inside an HTML element (the `<title>`).
fn html_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// Replaces each marker of `template` by its text in one pass, so text put in is never
/// searched for markers again. (The embedded template holds each marker once; a unit test
/// holds it to that.)
fn fill(template: &str, parts: &[(&str, &str)]) -> String {
    let mut found: Vec<(usize, &str, &str)> = parts
        .iter()
        .filter_map(|(marker, text)| template.find(marker).map(|at| (at, *marker, *text)))
        .collect();
    found.sort_by_key(|f| f.0);
    let extra: usize = parts.iter().map(|p| p.1.len()).sum();
    let mut out = String::with_capacity(template.len() + extra);
    let mut at = 0;
    for (pos, marker, text) in found {
        out.push_str(&template[at..pos]);
        out.push_str(text);
        at = pos + marker.len();
    }
    out.push_str(&template[at..]);
    out
}
