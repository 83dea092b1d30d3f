//! The preview page (`output::preview`) in a real browser: each page is written to a temp
//! dir and loaded from `file://` in headless Chromium, which takes a screenshot and dumps the
//! DOM after the page's scripts ran. The test checks that the page drew its first frame
//! (`<body data-rendered="1">`), recorded no error (no `data-errors`, no uncaught exception
//! on Chromium's console), shows its labels, and that the screenshot is a picture: several
//! colours, the obstacles' blue, the links' orange and the tool's teal where the scene has
//! them, and the robot in another place at another time.
//!
//! Without Chromium the test prints how to install it and passes. `GEN_RAPID_CHROMIUM` names
//! another browser binary (set but empty: run as without Chromium); `GEN_RAPID_PREVIEW_OUT=DIR` keeps the pages and screenshots there.

use crate::common::library::preview::{
    render_html, FailedPoint, Keyframe, Scene, SceneBase, SceneClearance, SceneFailure,
    SceneObstacle, ScenePose, SceneWaypoint, ShapeDef, ShapeGeometry, ShapeKind, WaypointKind,
};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Chromium's flags: headless, software WebGL (SwiftShader through ANGLE, no GPU needed), no
/// network activity of its own, no first-run UI; a fresh profile is added per run.
const FLAGS: &[&str] = &[
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-default-apps",
    "--disable-extensions",
    "--no-first-run",
    "--no-default-browser-check",
    "--hide-scrollbars",
    "--enable-logging=stderr",
    "--v=0",
];
const WIDTH: u32 = 800;
const HEIGHT: u32 = 600;
/// A generous bound for one page on a busy machine (a page takes about a second).
const TIMEOUT: Duration = Duration::from_secs(120);

/// `$GEN_RAPID_CHROMIUM` (empty: none), else `chromium` or `chromium-browser` on PATH, else /usr/bin/chromium.
fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("GEN_RAPID_CHROMIUM") {
        // Set but empty: behave as on a machine without Chromium.
        return (!p.is_empty()).then(|| PathBuf::from(p));
    }
    let path = std::env::var_os("PATH").unwrap_or_default();
    for name in ["chromium", "chromium-browser"] {
        for dir in std::env::split_paths(&path) {
            let candidate = dir.join(name);
            if candidate.is_file() {
                return Some(candidate);
            }
        }
    }
    let fallback = PathBuf::from("/usr/bin/chromium");
    fallback.is_file().then_some(fallback)
}

/// What Chromium made of a page.
struct Loaded {
    /// The `<body ...>` start tag of the DOM after the scripts ran.
    body_tag: String,
    /// The whole DOM dump.
    dom: String,
    /// Console lines Chromium logged on stderr.
    console: Vec<String>,
    image: Image,
}

struct Image {
    width: usize,
    height: usize,
    /// RGB, row by row.
    rgb: Vec<[u8; 3]>,
}

/// Loads `html` (with the address fragment `fragment`) in headless Chromium.
fn load(browser: &Path, html: &str, fragment: &str) -> Loaded {
    let dir = tempfile::tempdir().expect("temp dir");
    let page = dir.path().join("preview.html");
    std::fs::write(&page, html).expect("write the page");
    let shot = dir.path().join("shot.png");
    let profile = dir.path().join("profile");
    let url = format!("file://{}{fragment}", page.display());
    let mut child = Command::new(browser)
        .args(FLAGS)
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--window-size={WIDTH},{HEIGHT}"))
        .arg(format!("--screenshot={}", shot.display()))
        .arg("--dump-dom")
        .arg(&url)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start {}: {e}", browser.display()));
    let mut out = child.stdout.take().expect("stdout");
    let mut err = child.stderr.take().expect("stderr");
    let out_thread = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = out.read_to_string(&mut s);
        s
    });
    let err_thread = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = err.read_to_string(&mut s);
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for chromium") {
            break status;
        }
        if start.elapsed() > TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            panic!("chromium did not finish within {TIMEOUT:?} on {url}");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let dom = out_thread.join().unwrap_or_default();
    let stderr = err_thread.join().unwrap_or_default();
    assert!(
        status.success(),
        "chromium failed ({status}) on {url}:\n{stderr}"
    );
    let console = stderr
        .lines()
        .filter(|l| l.contains(":CONSOLE"))
        .map(str::to_string)
        .collect();
    // The body element follows the head; the head's scripts mention no body tag.
    let body_at = dom
        .find("</head>")
        .and_then(|h| dom[h..].find("<body").map(|b| h + b))
        .unwrap_or_else(|| panic!("no <body> in the DOM dump:\n{dom}\n{stderr}"));
    let body_end = dom[body_at..]
        .find('>')
        .map_or(dom.len(), |e| body_at + e + 1);
    let body_tag = dom[body_at..body_end].to_string();
    if let Some(keep) = std::env::var_os("GEN_RAPID_PREVIEW_OUT") {
        // Keep the page and the screenshot for a look (a debugging aid).
        let stem = format!("preview{}", fragment.replace(['#', '='], "_"));
        let keep = Path::new(&keep);
        let _ = std::fs::create_dir_all(keep);
        let _ = std::fs::copy(&page, keep.join(format!("{stem}.html")));
        let _ = std::fs::copy(&shot, keep.join(format!("{stem}.png")));
    }
    let image = decode(
        &std::fs::read(&shot)
            .unwrap_or_else(|e| panic!("no screenshot {}: {e}\n{stderr}", shot.display())),
    );
    Loaded {
        body_tag,
        dom,
        console,
        image,
    }
}

fn decode(bytes: &[u8]) -> Image {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size().expect("PNG size")];
    let info = reader.next_frame(&mut buf).expect("PNG frame");
    let channels = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        other => panic!("unexpected PNG colour type {other:?}"),
    };
    let (width, height) = (info.width as usize, info.height as usize);
    let mut rgb = Vec::with_capacity(width * height);
    for y in 0..height {
        let row = &buf[y * info.line_size..][..width * channels];
        rgb.extend(row.chunks(channels).map(|p| [p[0], p[1], p[2]]));
    }
    Image { width, height, rgb }
}

impl Image {
    /// Share of pixels (0..1) for which `f` holds.
    fn share(&self, f: impl Fn([i32; 3]) -> bool) -> f64 {
        let n = self.rgb.iter().filter(|p| f(p.map(i32::from))).count();
        n as f64 / self.rgb.len() as f64
    }

    /// Mean position (x, y) of the pixels for which `f` holds.
    fn centroid(&self, f: impl Fn([i32; 3]) -> bool) -> (f64, f64) {
        let (mut sx, mut sy, mut n) = (0.0, 0.0, 0.0);
        for (i, p) in self.rgb.iter().enumerate() {
            if f(p.map(i32::from)) {
                sx += (i % self.width) as f64;
                sy += (i / self.width) as f64;
                n += 1.0;
            }
        }
        (sx / n, sy / n)
    }

    /// Colours (16 levels a channel) that each cover at least 0.2 % of the picture, and the
    /// largest share of one colour.
    fn palette(&self) -> (usize, f64) {
        let mut counts = std::collections::HashMap::new();
        for p in &self.rgb {
            *counts.entry(p.map(|c| c >> 4)).or_insert(0usize) += 1;
        }
        let total = self.rgb.len() as f64;
        let common = counts
            .values()
            .filter(|&&c| c as f64 >= 0.002 * total)
            .count();
        let largest = counts.values().copied().max().unwrap_or(0) as f64 / total;
        (common, largest)
    }
}

// Colour families of the page (see COLOURS in templates/preview/preview.js), lit from
// 0.38 to 1.15 of their colour; the thresholds hold over that range.
/// The links' orange.
fn orange([r, g, b]: [i32; 3]) -> bool {
    r > 90 && r - g > 40 && g - b > 35
}
/// The tool's teal.
fn teal([r, g, b]: [i32; 3]) -> bool {
    g - r > 35 && b - r > 30 && (g - b).abs() < 40
}
/// The translucent obstacles' blue over the light background.
fn obstacle_blue([r, g, b]: [i32; 3]) -> bool {
    b - r > 15 && b >= g && r > 60
}
/// The clearance and failure red.
fn red([r, g, b]: [i32; 3]) -> bool {
    r > 150 && r - g > 90 && (g - b).abs() < 45
}

/// Robot: a base cylinder and an arm that swings 90 deg about z in 2 s, a tool box and ball
/// at the arm's end; a table and a pillar.
fn scene() -> Scene {
    let cyl = |name: &str, radius_mm, to_mm| ShapeDef {
        name: name.into(),
        kind: ShapeKind::Link,
        geometry: ShapeGeometry::Cylinder {
            radius_mm,
            from_mm: [0.0; 3],
            to_mm,
        },
    };
    let shapes = vec![
        cyl("link_1", 200.0, [0.0, 0.0, 500.0]),
        cyl("link_2", 90.0, [800.0, 0.0, 0.0]),
        ShapeDef {
            name: "body".into(),
            kind: ShapeKind::Tool,
            geometry: ShapeGeometry::Box {
                min_mm: [800.0, -70.0, -180.0],
                max_mm: [940.0, 70.0, 0.0],
            },
        },
        ShapeDef {
            name: "cup".into(),
            kind: ShapeKind::Tool,
            geometry: ShapeGeometry::Sphere {
                centre_mm: [870.0, 0.0, -240.0],
                radius_mm: 70.0,
            },
        },
    ];
    let steps = 10;
    let keyframes: Vec<Keyframe> = (0..=steps)
        .map(|k| {
            let u = k as f64 / steps as f64;
            let yaw = u * std::f64::consts::FRAC_PI_2;
            let q = [(yaw / 2.0).cos(), 0.0, 0.0, (yaw / 2.0).sin()];
            let at = |z| ScenePose {
                position_mm: [0.0, 0.0, z],
                quat_wxyz: q,
            };
            Keyframe {
                time_s: 2.0 * u,
                poses: vec![at(0.0), at(500.0), at(500.0), at(500.0)],
                tcp_mm: [870.0 * yaw.cos(), 870.0 * yaw.sin(), 190.0],
            }
        })
        .collect();
    let waypoint = |name: &str, time_s, tcp_mm| SceneWaypoint {
        name: name.into(),
        kind: WaypointKind::Cell,
        time_s,
        tcp_mm,
    };
    Scene {
        title: "Browser test - test.yaml".into(),
        module: "BrowserTest".into(),
        cell_file: "test.yaml".into(),
        obstacles: vec![
            SceneObstacle {
                name: "table".into(),
                min_mm: [300.0, -700.0, 0.0],
                max_mm: [1100.0, -250.0, 350.0],
            },
            SceneObstacle {
                name: "pillar".into(),
                min_mm: [-900.0, 300.0, 0.0],
                max_mm: [-600.0, 600.0, 1200.0],
            },
        ],
        base: SceneBase {
            position_mm: [0.0; 3],
            yaw_deg: 0.0,
        },
        shapes,
        waypoints: vec![
            waypoint("A", 0.0, keyframes[0].tcp_mm),
            waypoint("B", 2.0, keyframes[steps].tcp_mm),
        ],
        keyframes,
        clearance: Some(SceneClearance {
            distance_mm: 60.0,
            move_index: 0,
            shape: "body".into(),
            obstacle: "table".into(),
            time_s: Some(0.0),
            points_mm: Some([[800.0, -70.0, 320.0], [800.0, -250.0, 320.0]]),
        }),
        total_time_s: Some(2.0),
        failure: None,
    }
}

/// A failed plan: the cell, the robot at the start, the two points that could not be joined.
fn failure_scene() -> Scene {
    let mut s = scene();
    s.keyframes.truncate(1);
    s.waypoints.clear();
    s.clearance = None;
    s.total_time_s = None;
    s.failure = Some(SceneFailure {
        message: "no path from 'A' to 'B': the grid holds no free route between them".into(),
        points: vec![
            FailedPoint {
                name: "A".into(),
                position_mm: [870.0, 0.0, 190.0],
            },
            FailedPoint {
                name: "B".into(),
                position_mm: [0.0, 870.0, 190.0],
            },
        ],
    });
    s
}

/// The checks every page must pass: drawn, no error, a picture of several colours.
fn assert_healthy(page: &Loaded, what: &str) {
    assert!(
        page.body_tag.contains(r#"data-rendered="1""#),
        "{what}: the page did not draw its first frame: {}\nconsole: {:#?}",
        page.body_tag,
        page.console
    );
    assert!(
        !page.body_tag.contains("data-errors"),
        "{what}: the page recorded errors: {}",
        page.body_tag
    );
    let uncaught: Vec<_> = page
        .console
        .iter()
        .filter(|l| l.contains("Uncaught"))
        .collect();
    assert!(uncaught.is_empty(), "{what}: console errors: {uncaught:#?}");
    let img = &page.image;
    assert_eq!((img.width, img.height), (WIDTH as usize, HEIGHT as usize));
    let (colours, largest) = img.palette();
    assert!(
        colours >= 8,
        "{what}: only {colours} colours cover 0.2 % each"
    );
    assert!(
        largest < 0.85,
        "{what}: one colour covers {:.0} %",
        largest * 100.0
    );
    let blue = img.share(obstacle_blue);
    eprintln!(
        "{what}: {colours} colours, largest {:.1} %, obstacles {:.2} %, links {:.2} %, \
         tool {:.2} %, red {:.2} %",
        largest * 100.0,
        blue * 100.0,
        img.share(orange) * 100.0,
        img.share(teal) * 100.0,
        img.share(red) * 100.0
    );
    assert!(blue > 0.02, "{what}: obstacles cover {:.2} %", blue * 100.0);
}

#[test]
fn preview_pages_render_in_headless_chromium() {
    let Some(browser) = chromium() else {
        eprintln!(
            "SKIPPED preview_browser: chromium not found: install it with \
             `apt-get install chromium` to run the browser test"
        );
        return;
    };

    // A planned program, paused at its start and at its end.
    let html = render_html(&scene()).expect("page");
    let start = load(&browser, &html, "#t=0");
    assert_healthy(&start, "program at 0 s");
    for text in [
        ">A</div>",
        ">B</div>",
        ">table</div>",
        "min clearance 60.0 mm: body \u{2013} table, move 1 (A \u{2192} B)",
        "0.00 / 2.00 s",
    ] {
        assert!(start.dom.contains(text), "the page shows no {text:?}");
    }
    let img = &start.image;
    let (orange_share, teal_share) = (img.share(orange), img.share(teal));
    assert!(
        orange_share > 0.01,
        "links cover {:.2} %",
        orange_share * 100.0
    );
    assert!(
        teal_share > 0.002,
        "tool covers {:.2} %",
        teal_share * 100.0
    );
    assert!(img.share(red) > 0.0005, "no clearance marker");

    let end = load(&browser, &html, "#t=2");
    assert_healthy(&end, "program at 2 s");
    assert!(end.dom.contains("2.00 / 2.00 s"));
    // The arm swung 90 degrees: the tool is elsewhere on the screen.
    let (a, b) = (start.image.centroid(teal), end.image.centroid(teal));
    let moved = ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt();
    assert!(
        moved > 60.0,
        "the tool moved only {moved:.0} px between 0 s and 2 s"
    );

    // A failed plan: the cell, the robot still, the unjoined points and the message.
    let html = render_html(&failure_scene()).expect("failure page");
    let failed = load(&browser, &html, "");
    assert_healthy(&failed, "failed plan");
    for text in [">A (not joined)</div>", ">B (not joined)</div>"] {
        assert!(
            failed.dom.contains(text),
            "the failure page shows no {text:?}"
        );
    }
    // The message box (the same words are also in the inlined scene: read the element).
    let at = failed
        .dom
        .find(r#"<div id="failure""#)
        .expect("the failure box");
    let dom_box = &failed.dom[at..];
    let dom_box = &dom_box[..dom_box.find("</div>").unwrap_or(dom_box.len())];
    assert!(
        !dom_box.contains("hidden"),
        "the failure box is hidden: {dom_box}"
    );
    assert!(
        dom_box.contains("Planning failed") && dom_box.contains("no path from 'A' to 'B'"),
        "the failure box says: {dom_box}"
    );
    assert!(
        failed.image.share(orange) > 0.01,
        "no robot on the failure page"
    );
    assert!(failed.image.share(red) > 0.001, "no failed points drawn");

    // The error hook works, so the checks above could fail: a script error after the viewer
    // (a stand-in for a bug) is recorded in the DOM.
    let broken = render_html(&scene())
        .expect("page")
        .replace("</body>", "<script>null.boom();</script></body>");
    let page = load(&browser, &broken, "#broken");
    assert!(
        page.body_tag.contains("data-errors") && page.body_tag.contains("boom"),
        "a script error was not recorded: {}",
        page.body_tag
    );
}
