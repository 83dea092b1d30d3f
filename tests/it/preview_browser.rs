//! The preview page (`--html`) in a real browser: the trunk and the torch cells and a failed
//! plan (`tests/err/no_path.yaml`) go through the `gen-rapid` binary, and each page is loaded
//! from `file://` in headless Chromium, which takes a screenshot and dumps the DOM after the
//! page's scripts ran. The test checks that the page drew its first frame
//! (`<body data-rendered="1">`), recorded no error (no `data-errors`, no uncaught exception
//! on Chromium's console), shows its labels (every waypoint, the smallest clearance as the
//! `--report` of the same run states it, the failed points), and that the screenshot is a
//! picture: several colours, the obstacles' blue, the links' orange and the tool's teal where
//! the cell has them, and the arm in another place at the program's end. Beyond that: the
//! smallest clearance of a fly-by route (the gripper cell with `via_zone: z50`, whose least is
//! a zoned corner's) is shown, named by its corner; the trunk cell with a floor 40 m wide still
//! shows the robot large (the camera frames the robot, the tool and the points, not every box);
//! two points at the same place (`tests/ok/same_point_twice.yaml`) have labels apart; the torch
//! cell's weld actions are labelled and its seams drawn in their own colour.
//!
//! Without Chromium the test prints how to install it and passes. `GEN_RAPID_CHROMIUM` names
//! another browser binary (set but empty: run as without Chromium); `GEN_RAPID_PREVIEW_OUT=DIR` keeps the pages and screenshots there.

use crate::common::{arg, gen_rapid, read, stderr, temp_cell};
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

/// Runs `gen-rapid CELL --html PAGE --report REPORT` in `dir`: the page, the report (when the
/// run succeeds; `None` otherwise), and the run's output.
fn page_of(dir: &Path, cell: &str) -> (String, Option<serde_json::Value>, std::process::Output) {
    let stem = Path::new(cell)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let html = dir.join(format!("{stem}.html"));
    let report = dir.join(format!("{stem}.json"));
    let out = gen_rapid(&[cell, "--html", arg(&html), "--report", arg(&report)]);
    let page = std::fs::read_to_string(&html)
        .unwrap_or_else(|e| panic!("{cell}: no page {}: {e}\n{}", html.display(), stderr(&out)));
    let report = std::fs::read_to_string(&report)
        .ok()
        .map(|t| serde_json::from_str(&t).expect("the report is JSON"));
    (page, report, out)
}

/// The clearance labels the page may show, from the report: the smallest clearance, its link
/// or shape, its obstacle and its move, 1-based (one label for each move that has it: the
/// report rounds to 0.1 mm, so two moves may tie there).
fn clearance_labels(report: &serde_json::Value) -> Vec<String> {
    let least = &report["totals"]["min_clearance"];
    let moves = report["moves"].as_array().expect("moves");
    let labels: Vec<String> = moves
        .iter()
        .enumerate()
        .filter(|(_, m)| m["min_clearance"] == *least)
        .map(|(i, m)| {
            format!(
                "min clearance {} mm: {} \u{2013} {}, move {} ({} \u{2192} {})",
                least["mm"],
                least["name"].as_str().unwrap_or_default(),
                least["obstacle"].as_str().unwrap_or_default(),
                i + 1,
                m["from"].as_str().unwrap_or_default(),
                m["to"].as_str().unwrap_or_default(),
            )
        })
        .collect();
    assert!(!labels.is_empty(), "no move has the smallest clearance");
    labels
}

/// The `top` (px) of the label whose text is `text`, from the DOM after the scripts ran.
fn label_top(dom: &str, text: &str) -> f64 {
    let end = dom
        .find(&format!(">{text}</div>"))
        .unwrap_or_else(|| panic!("no label {text}"));
    let start = dom[..end].rfind("<div").expect("the label's tag");
    let tag = &dom[start..end];
    let top = tag
        .split("top:")
        .nth(1)
        .and_then(|t| t.split("px").next())
        .unwrap_or_else(|| panic!("no top in {tag}"));
    top.trim().parse().unwrap_or_else(|e| panic!("{tag}: {e}"))
}

/// Whether the page shows one of `labels`.
fn shows_one_of(dom: &str, labels: &[String]) -> bool {
    labels.iter().any(|l| dom.contains(l.as_str()))
}

/// When the program reaches waypoint `name`: the sum of the times of the moves up to it.
fn time_at(report: &serde_json::Value, name: &str) -> f64 {
    let moves = report["moves"].as_array().expect("moves");
    let last = moves
        .iter()
        .position(|m| m["to"] == name)
        .unwrap_or_else(|| panic!("no move to {name}"));
    moves[..=last]
        .iter()
        .map(|m| m["time_s"].as_f64().expect("timed moves"))
        .sum()
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
    let dir = tempfile::tempdir().expect("temp dir");

    // The trunk cell through the binary, paused at its start and at its end.
    let (html, report, out) = page_of(dir.path(), "cells/trunk.yaml");
    assert!(out.status.success(), "{}", stderr(&out));
    let report = report.expect("the trunk's report");
    let total = report["totals"]["estimated_time_s"]
        .as_f64()
        .expect("a time estimate");
    let start = load(&browser, &html, "#t=0");
    assert_healthy(&start, "trunk at 0 s");
    let labels = clearance_labels(&report);
    assert!(
        shows_one_of(&start.dom, &labels),
        "the trunk page shows none of {labels:?}"
    );
    let mut shown = vec![
        format!("0.00 / {total:.2} s"),
        ">clamp_post</div>".to_string(),
    ];
    for w in report["waypoints"].as_array().expect("waypoints") {
        shown.push(format!(">{}</div>", w["name"].as_str().unwrap_or_default()));
    }
    for text in &shown {
        assert!(
            start.dom.contains(text.as_str()),
            "the trunk page shows no {text:?}"
        );
    }
    let img = &start.image;
    assert!(
        img.share(orange) > 0.01,
        "links cover {:.2} %",
        img.share(orange) * 100.0
    );
    assert!(img.share(red) > 0.0005, "no clearance marker");
    let end = load(&browser, &html, &format!("#t={total}"));
    assert_healthy(&end, "trunk at its end");
    assert!(end.dom.contains(&format!("{total:.2} / {total:.2} s")));
    // At D (axis 1 near 0, over the trunk) the arm is no longer where it was at A (axis 1 at
    // 90 deg): it covers other pixels. D is reached at the sum of the times of the moves up to
    // it (A and F, at 90 and -90 deg, look alike from the page's first view).
    let middle = load(&browser, &html, &format!("#t={}", time_at(&report, "D")));
    assert_healthy(&middle, "trunk at D");
    let (a, b) = (&start.image, &middle.image);
    let changed = a
        .rgb
        .iter()
        .zip(&b.rgb)
        .filter(|(p, q)| orange(p.map(i32::from)) != orange(q.map(i32::from)))
        .count() as f64
        / a.rgb.len() as f64;
    assert!(
        changed > 0.02,
        "the arm covers the same pixels at A and at D ({:.2} % differ)",
        changed * 100.0
    );

    // The torch cell: the tool's shapes are drawn with the arm.
    let (html, report, out) = page_of(dir.path(), "cells/torch-trunk.yaml");
    assert!(out.status.success(), "{}", stderr(&out));
    let report = report.expect("the torch cell's report");
    let torch = load(&browser, &html, &format!("#t={}", time_at(&report, "L1")));
    assert_healthy(&torch, "torch-trunk at L1");
    let labels = clearance_labels(&report);
    assert!(
        shows_one_of(&torch.dom, &labels),
        "the torch page shows none of {labels:?}"
    );
    assert!(torch.image.share(orange) > 0.01);
    // The tool is small on the screen, seen through a translucent wall, and teal-like pixels
    // occur elsewhere (antialiased lines): draw the same page with the tool's shapes in the
    // links' colour, and count the pixels that change, the tool's own.
    let as_links = html.replace(r#""kind":"tool""#, r#""kind":"link""#);
    assert_ne!(as_links, html, "the page has no tool shapes");
    let recoloured = load(
        &browser,
        &as_links,
        &format!("#t={}", time_at(&report, "L1")),
    );
    let tool_px = torch
        .image
        .rgb
        .iter()
        .zip(&recoloured.image.rgb)
        .filter(|(p, q)| {
            let (p, q) = (p.map(i32::from), q.map(i32::from));
            (0..3).map(|k| (p[k] - q[k]).abs()).sum::<i32>() > 60
        })
        .count();
    eprintln!("torch-trunk at L1: the tool covers {tool_px} px");
    assert!(tool_px > 50, "the tool covers {tool_px} px");
    // The weld's actions are labelled at their points, as the module writes them.
    for action in ["SetDO doWeld, 1", "SetDO doWeld, 0"] {
        assert!(
            torch.dom.contains(&format!(">{action}</div>")),
            "the torch page does not label {action}"
        );
    }
    // The seams are drawn in their own colour: the same page with the seams as air moves
    // differs in the pixels of their trace.
    // The labels (HTML over the canvas) hide the short seams' trace: both pages without them,
    // the robot at its start, away from the seams.
    let unlabelled = html.replace("</style>", "#labels { display: none; }\n</style>");
    let seams_as_air = unlabelled.replace(r#""kind":"linear""#, r#""kind":"joint""#);
    assert_ne!(seams_as_air, unlabelled, "the page has no seam");
    let (seamed, plain) = (
        load(&browser, &unlabelled, "#t=0"),
        load(&browser, &seams_as_air, "#t=0"),
    );
    assert_healthy(&seamed, "torch-trunk without labels");
    // Below the header and its legend (which names the seam colour only where there are
    // seams), so only the drawing counts.
    let below = 200 * seamed.image.width;
    let seam_px = seamed.image.rgb[below..]
        .iter()
        .zip(&plain.image.rgb[below..])
        .filter(|(p, q)| {
            let (p, q) = (p.map(i32::from), q.map(i32::from));
            (0..3).map(|k| (p[k] - q[k]).abs()).sum::<i32>() > 60
        })
        .count();
    eprintln!("torch-trunk: the seams' own colour covers {seam_px} px");
    assert!(seam_px > 20, "the seams' colour covers {seam_px} px");

    // A fly-by route: the gripper cell with `via_zone: z50`, whose smallest clearance is a
    // zoned corner's (no move has it): the page shows it, named by the corner's waypoint.
    let fly_by = read("cells/gripper-pick.yaml")
        .replace("../robots/irb1400.urdf", "URDF")
        .replace("  zone: fine\n", "  zone: fine\n  via_zone: z50\n");
    let cell = temp_cell(dir.path(), "gripper-z50.yaml", &fly_by);
    let (html, report, out) = page_of(dir.path(), arg(&cell));
    assert!(out.status.success(), "{}", stderr(&out));
    let report = report.expect("the fly-by report");
    let least = &report["totals"]["min_clearance"];
    let moves = report["moves"].as_array().expect("moves");
    assert!(
        moves.iter().all(|m| m["min_clearance"] != *least),
        "the gripper cell at z50 no longer has its least at a corner: {least}"
    );
    let page = load(&browser, &html, "");
    assert_healthy(&page, "gripper-pick at z50");
    let text = format!(
        "min clearance {} mm: {} \u{2013} {}, the corner at ",
        least["mm"],
        least["name"].as_str().unwrap_or_default(),
        least["obstacle"].as_str().unwrap_or_default()
    );
    assert!(
        page.dom.contains(&text),
        "the fly-by page shows no {text:?}"
    );
    assert!(page.image.share(red) > 0.0005, "no clearance marker");

    // A floor 40 m wide under the trunk cell: the robot is still drawn large.
    let wide = read("cells/trunk.yaml")
        .replace("../robots/irb1400.urdf", "URDF")
        .replace(
            "obstacles:\n",
            "obstacles:\n  - { name: field, box: { min: [-20000, -20000, -100], max: [20000, 20000, -50] } }\n",
        );
    let cell = temp_cell(dir.path(), "trunk-field.yaml", &wide);
    let (html, _, out) = page_of(dir.path(), arg(&cell));
    assert!(out.status.success(), "{}", stderr(&out));
    let page = load(&browser, &html, "#t=0");
    assert_healthy(&page, "trunk on a wide field");
    assert!(
        page.image.share(orange) > 0.01,
        "on a wide field the links cover {:.2} %",
        page.image.share(orange) * 100.0
    );

    // Two points at the same place: their labels are kept apart (one below the other).
    let (html, _, out) = page_of(dir.path(), "tests/ok/same_point_twice.yaml");
    assert!(out.status.success(), "{}", stderr(&out));
    let page = load(&browser, &html, "#t=0");
    let (p1, p2) = (label_top(&page.dom, "P1"), label_top(&page.dom, "P2"));
    assert!(
        (p1 - p2).abs() >= 12.0,
        "the labels of P1 and P2 overlap: top {p1} and {p2} px"
    );

    // A failed plan: exit 3, nothing on stdout, no report, and a page of the cell, the robot
    // at the first point and the two points that could not be joined, with the message.
    let (html, report, out) = page_of(dir.path(), "tests/err/no_path.yaml");
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    assert!(out.stdout.is_empty() && report.is_none());
    let failed = load(&browser, &html, "");
    assert_healthy(&failed, "failed plan");
    for text in [
        ">P1 (not joined)</div>",
        ">P2 (not joined)</div>",
        ">lintel</div>",
    ] {
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
        dom_box.contains("Planning failed")
            && dom_box.contains("no collision-free path from 'P1' to 'P2'"),
        "the failure box says: {dom_box}"
    );
    assert!(
        failed.image.share(orange) > 0.01,
        "no robot on the failure page"
    );
    assert!(failed.image.share(red) > 0.0005, "no failed points drawn");

    // The error hook works, so the checks above could fail: a script error after the viewer
    // (a stand-in for a bug) is recorded in the DOM.
    let (html, _, _) = page_of(dir.path(), "cells/trunk.yaml");
    let broken = html.replace("</body>", "<script>null.boom();</script></body>");
    let page = load(&browser, &broken, "#broken");
    assert!(
        page.body_tag.contains("data-errors") && page.body_tag.contains("boom"),
        "a script error was not recorded: {}",
        page.body_tag
    );
}
