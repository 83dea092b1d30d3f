//! The top view of the place stage's survey, like the paper's Fig. 1: the obstacles'
//! footprints (solid) and, for those that can touch the base, the footprints grown by base
//! radius + clearance (dashed); each point's reach region (its outer and inner circles, one
//! colour per point); R shaded; the base marked; the points labelled; axes in mm with equal
//! scales. Text is SVG `<text>` (plotters without a font backend only estimates label widths),
//! so drawing needs no fonts.

use super::location::Report;
use crate::cell::{Base, Cell, Obstacle};
use crate::geometry::Aabb;
use crate::place::locate::{ReachRegion, Region, Sketch};
use crate::place::Survey;
use plotters::prelude::*;

/// Pixel width of the plotting area; the height follows from the data (equal scales).
const PLOT_W: u32 = 760;
const MARGIN: u32 = 12;
const X_LABELS: u32 = 44;
const Y_LABELS: u32 = 64;
const TITLE: u32 = 48;
/// Vertices of a drawn circle.
const CIRCLE_N: usize = 180;

const R_FILL: RGBColor = RGBColor(150, 215, 150);
const OBSTACLE: RGBColor = RGBColor(110, 110, 110);
const BASE: RGBColor = RGBColor(200, 0, 0);

fn circle(c: [f64; 2], r: f64) -> Vec<(f64, f64)> {
    (0..=CIRCLE_N)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / CIRCLE_N as f64;
            (c[0] + r * t.cos(), c[1] + r * t.sin())
        })
        .collect()
}

/// A rectangle grown by `g`: its outline with quarter circles at the corners (closed).
fn rounded_rect(b: &Aabb, g: f64) -> Vec<(f64, f64)> {
    let (lo, hi) = ([b.min.x, b.min.y], [b.max.x, b.max.y]);
    let corners = [
        ([hi[0], hi[1]], 0.0),
        ([lo[0], hi[1]], 90.0),
        ([lo[0], lo[1]], 180.0),
        ([hi[0], lo[1]], 270.0),
    ];
    let mut v = Vec::new();
    for (c, start) in corners {
        for k in 0..=12 {
            let t = (start + 90.0 * k as f64 / 12.0_f64).to_radians();
            v.push((c[0] + g * t.cos(), c[1] + g * t.sin()));
        }
    }
    if let Some(&first) = v.first() {
        v.push(first);
    }
    v
}

/// A distinct, dark-enough colour per point.
fn colour(i: usize) -> RGBColor {
    const C: [RGBColor; 8] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(148, 103, 189),
        RGBColor(23, 150, 190),
        RGBColor(214, 39, 40),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(188, 189, 34),
    ];
    C[i % C.len()]
}

/// What a top view draws.
struct Scene<'a> {
    /// First title line.
    title: String,
    reach: &'a [ReachRegion],
    /// The points by name with their wrist centres (cell frame).
    points: &'a [(String, [f64; 3])],
    obstacles: &'a [Obstacle],
    /// The obstacles that can block the base, and how far their footprints grow.
    blocking: &'a [Obstacle],
    grow_mm: f64,
    region: Option<&'a Region>,
    /// The base marked with a cross: position, label beside it, legend entry.
    base: Option<([f64; 2], String, String)>,
    /// A given base, marked with a triangle.
    given: Option<[f64; 2]>,
}

/// The SVG text, or why plotters could not draw it.
pub fn render(cell: &Cell, survey: &Survey, rep: &Report) -> Result<String, String> {
    let loc = &survey.location;
    let mode = match &rep.given_base {
        None => "chosen base".to_string(),
        Some(g) if g.in_region => "given base (inside R)".to_string(),
        Some(_) => "given base (OUTSIDE R)".to_string(),
    };
    let label = match &rep.given_base {
        None => "chosen base".to_string(),
        Some(_) => "largest margin".to_string(),
    };
    let b = [rep.base_mm[0], rep.base_mm[1]];
    draw(&Scene {
        title: format!(
            "{}: feasible base region R = {:.3} m^2 (shaded), {mode}",
            cell.module, rep.area_m2
        ),
        reach: &loc.reach,
        points: &survey.points,
        obstacles: &cell.obstacles,
        blocking: &loc.blocking,
        grow_mm: loc.grow_mm,
        region: Some(&loc.region),
        base: Some((
            b,
            format!("{label} ({:.0}, {:.0})", b[0], b[1]),
            format!("{label}, margin {:.0} mm", rep.margin_mm),
        )),
        given: rep
            .given_base
            .as_ref()
            .map(|g| [g.base_mm[0], g.base_mm[1]]),
    })
}

/// The top view when no base position will do (R empty, or none of its positions solves every
/// point): the reach regions, the obstacles and their grown footprints, R where it is not
/// empty, and the given base if there is one. A point out of reach from any base is labelled so.
pub fn render_failure(cell: &Cell, sketch: &Sketch) -> Result<String, String> {
    let title = match &sketch.region {
        None => format!(
            "{}: R is empty: no base position reaches every point clear of the obstacles",
            cell.module
        ),
        Some(r) => format!(
            "{}: R = {:.3} m^2 (shaded), but from none of its positions is every point solved",
            cell.module,
            r.area_mm2 * 1e-6
        ),
    };
    draw(&Scene {
        title,
        reach: &sketch.reach,
        points: &sketch.points,
        obstacles: &cell.obstacles,
        blocking: &sketch.blocking,
        grow_mm: sketch.grow_mm,
        region: sketch.region.as_ref(),
        base: None,
        given: match cell.robot.base {
            Base::Fixed(b) => Some([b[0], b[1]]),
            Base::Auto => None,
        },
    })
}

fn draw(scene: &Scene) -> Result<String, String> {
    // Data extent: every outer circle and every grown obstacle (and each point), plus 5 %.
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let mut grow = |x: f64, y: f64, r: f64| {
        lo = [lo[0].min(x - r), lo[1].min(y - r)];
        hi = [hi[0].max(x + r), hi[1].max(y + r)];
    };
    for r in scene.reach {
        grow(r.centre_mm[0], r.centre_mm[1], r.outer_mm);
    }
    for o in scene.obstacles {
        grow(o.aabb.min.x, o.aabb.min.y, scene.grow_mm);
        grow(o.aabb.max.x, o.aabb.max.y, scene.grow_mm);
    }
    for b in scene.base.iter().map(|b| b.0).chain(scene.given) {
        grow(b[0], b[1], scene.grow_mm);
    }
    if !(lo.iter().chain(&hi).all(|v| v.is_finite()) && hi[0] > lo[0] && hi[1] > lo[1]) {
        return Err("nothing to draw".into());
    }
    let pad = 0.05 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let (mut x0, mut x1, mut y0, mut y1) = (lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad);
    // Equal scales: the plot's pixel height follows from its width, capped; widen the
    // narrower data range to the pixel aspect.
    let plot_w = PLOT_W;
    let plot_h = ((PLOT_W as f64 * (y1 - y0) / (x1 - x0)).round() as u32).clamp(300, 1000);
    let aspect = plot_h as f64 / plot_w as f64;
    if (y1 - y0) < aspect * (x1 - x0) {
        let extra = aspect * (x1 - x0) - (y1 - y0);
        y0 -= 0.5 * extra;
        y1 += 0.5 * extra;
    } else {
        let extra = (y1 - y0) / aspect - (x1 - x0);
        x0 -= 0.5 * extra;
        x1 += 0.5 * extra;
    }
    let width = plot_w + Y_LABELS + 2 * MARGIN;
    let height = plot_h + X_LABELS + TITLE + 2 * MARGIN;

    let mut buf = String::new();
    {
        let e = |e: DrawingAreaErrorKind<_>| e.to_string();
        let root = SVGBackend::with_string(&mut buf, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(e)?;
        let (title, body) = root.split_vertically(TITLE);
        title
            .draw_text(
                &scene.title,
                &("sans-serif", 17).into_font().color(&BLACK),
                (MARGIN as i32 + Y_LABELS as i32, 8),
            )
            .map_err(e)?;
        title
            .draw_text(
                &format!(
                    "top view, cell frame (mm); circles: each point's reach region (outer and inner); dashed: footprints grown by {:.0} mm",
                    scene.grow_mm
                ),
                &("sans-serif", 13).into_font().color(&RGBColor(70, 70, 70)),
                (MARGIN as i32 + Y_LABELS as i32, 28),
            )
            .map_err(e)?;
        let mut chart = ChartBuilder::on(&body)
            .margin(MARGIN)
            .x_label_area_size(X_LABELS)
            .y_label_area_size(Y_LABELS)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(e)?;
        chart
            .configure_mesh()
            .light_line_style(WHITE.mix(0.0))
            .bold_line_style(RGBColor(225, 225, 225))
            .x_desc("x (mm)")
            .y_desc("y (mm)")
            .x_label_formatter(&|v| format!("{v:.0}"))
            .y_label_formatter(&|v| format!("{v:.0}"))
            .draw()
            .map_err(e)?;

        // R: one rectangle per run of inside cells in a raster row.
        let mut runs = Vec::new();
        if let Some(r) = scene.region {
            for j in 0..r.ny {
                let mut i = 0;
                while i < r.nx {
                    if r.inside[j * r.nx + i] {
                        let start = i;
                        while i < r.nx && r.inside[j * r.nx + i] {
                            i += 1;
                        }
                        let a = r.cell_centre(start, j);
                        let b = r.cell_centre(i - 1, j);
                        let h = 0.5 * r.cell_mm;
                        runs.push(Rectangle::new(
                            [(a[0] - h, a[1] - h), (b[0] + h, b[1] + h)],
                            R_FILL.filled(),
                        ));
                    } else {
                        i += 1;
                    }
                }
            }
        }
        let r_series = chart.draw_series(runs).map_err(e)?;
        if scene.region.is_some() {
            r_series
                .label("R: feasible base positions")
                .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 16, y + 5)], R_FILL.filled()));
        }

        // Obstacles: footprints, and the grown footprints of those that can block the base.
        chart
            .draw_series(scene.obstacles.iter().map(|o| {
                Rectangle::new(
                    [(o.aabb.min.x, o.aabb.min.y), (o.aabb.max.x, o.aabb.max.y)],
                    OBSTACLE.mix(0.35).filled(),
                )
            }))
            .map_err(e)?
            .label("obstacle footprint")
            .legend(|(x, y)| {
                Rectangle::new([(x, y - 5), (x + 16, y + 5)], OBSTACLE.mix(0.35).filled())
            });
        for (k, o) in scene.blocking.iter().enumerate() {
            let s = chart
                .draw_series(DashedLineSeries::new(
                    rounded_rect(&o.aabb, scene.grow_mm),
                    6,
                    4,
                    OBSTACLE.stroke_width(1),
                ))
                .map_err(e)?;
            if k == 0 {
                s.label("grown footprint (base radius + clearance)")
                    .legend(|(x, y)| {
                        PathElement::new(vec![(x, y), (x + 16, y)], OBSTACLE.stroke_width(1))
                    });
            }
        }

        // Reach regions: every ring's two circles, one colour per point.
        for (i, reach) in scene.reach.iter().enumerate() {
            let c = colour(i);
            for ring in &reach.rings_mm {
                chart
                    .draw_series(LineSeries::new(
                        circle(reach.centre_mm, ring[1]),
                        c.stroke_width(2),
                    ))
                    .map_err(e)?;
                if ring[0] > 0.0 {
                    chart
                        .draw_series(LineSeries::new(
                            circle(reach.centre_mm, ring[0]),
                            c.stroke_width(1),
                        ))
                        .map_err(e)?;
                }
            }
        }

        // Points, labelled.
        for (i, (name, p)) in scene.points.iter().enumerate() {
            let c = colour(i);
            let out_of_reach = scene.reach.get(i).is_some_and(|r| r.rings_mm.is_empty());
            let name = if out_of_reach {
                format!("{name} (out of reach)")
            } else {
                name.clone()
            };
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((p[0], p[1]))
                        + Circle::new((0, 0), 4, c.filled())
                        + Text::new(
                            name,
                            // Alternate above / below: neighbouring points stay readable.
                            (6, if i % 2 == 0 { -20 } else { 6 }),
                            ("sans-serif", 14).into_font().color(&c),
                        ),
                ))
                .map_err(e)?;
        }

        // The base: a cross (its label beside it, its legend entry).
        if let Some((b, label, legend)) = &scene.base {
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((b[0], b[1]))
                        + Cross::new((0, 0), 7, BASE.stroke_width(2))
                        + Text::new(
                            label.clone(),
                            (9, 4),
                            ("sans-serif", 14).into_font().color(&BASE),
                        ),
                ))
                .map_err(e)?
                .label(legend.clone())
                .legend(|(x, y)| Cross::new((x + 8, y), 5, BASE.stroke_width(2)));
        }
        if let Some(gb) = scene.given {
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((gb[0], gb[1]))
                        + TriangleMarker::new((0, 0), 7, BLACK.filled())
                        + Text::new(
                            format!("given base ({:.0}, {:.0})", gb[0], gb[1]),
                            (9, -18),
                            ("sans-serif", 14).into_font().color(&BLACK),
                        ),
                ))
                .map_err(e)?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(e)?;
        root.present().map_err(e)?;
    }
    Ok(buf)
}
