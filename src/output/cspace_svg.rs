//! A picture of the search (the paper's Figs. 11-13): the route(s) over the blocked nodes of
//! the configuration space, as an SVG document (`--svg FILE` on a run and on `compare`).
//!
//! The grid of axes 1..3 (paper section 3) is drawn in its three axis-pair projections, side by
//! side: axis 1 - axis 2, axis 1 - axis 3, axis 2 - axis 3. A node of a projection stands for the
//! whole column of grid nodes along the projected-out axis, and is **shaded by the fraction of
//! that column's in-range nodes that are blocked** by an obstacle: white when every node is
//! free, light to mid grey as more are blocked (ten steps), dark grey when all are blocked (the
//! only shade that means "no way through at this pair of values"); pale blue when no node of the
//! column is within the axis ranges (the coupled axis-3 range cuts off corners of the grid). A
//! column that is partly blocked can still be passed at other values of the third axis, which
//! is why the paths may cross grey areas.
//!
//! Each route is drawn as its straight moves (the waypoints after shortening and merging, i.e.
//! what the module drives) in the method's colour, with a legend; the cell points are black
//! dots labelled with their names. When planning fails ([`render_failure_svg`]) there is no route:
//! the points the failure is about (both ends of a leg that could not be planned) are ringed and
//! labelled in red, and the reason is written under the picture. Text is plain SVG `<text>` (plotters' built-in size
//! estimate, no font files), so rendering needs nothing beyond the Rust toolchain. The output is
//! deterministic for the same grid and plans.

use crate::place::PlacedPoint;
use crate::plan::cspace::{CSpace, FREE};
use crate::plan::{Method, Route};
use plotters::prelude::*;

/// Why a picture could not be drawn.
#[derive(Debug, thiserror::Error)]
pub enum PictureError {
    #[error("cannot draw the picture: {0}")]
    Draw(String),
    #[error("cannot draw the picture: the grid is empty")]
    EmptyGrid,
}

/// The colour each method's route is drawn in.
pub fn colour(m: Method) -> RGBColor {
    match m {
        Method::Neighboring => RGBColor(230, 120, 0),
        Method::DepthFirst => RGBColor(30, 90, 210),
        Method::Extensile => RGBColor(200, 0, 70),
    }
}

/// Shade steps for partly blocked columns.
const LEVELS: usize = 10;
const PANEL_W: u32 = 560;
const PANEL_H: u32 = 520;

/// Level of a column with no node in range.
const OUT_OF_RANGE: u8 = (LEVELS + 2) as u8;

/// For the projection onto axes (`u`, `v`): the shade level of each (u, v) column from its
/// count of blocked in-range nodes and of in-range nodes: 0 = all free, 1..=LEVELS partly
/// blocked, LEVELS + 1 = all blocked, [`OUT_OF_RANGE`] = no node in range. Indexed
/// `[iu * dims[v] + iv]`.
fn levels(blocked: &[u32], in_range: &[u32]) -> Vec<u8> {
    blocked
        .iter()
        .zip(in_range)
        .map(|(&c, &depth)| {
            if depth == 0 {
                OUT_OF_RANGE
            } else if c == 0 {
                0
            } else if c >= depth {
                (LEVELS + 1) as u8
            } else {
                (1 + (c as usize * LEVELS / depth as usize).min(LEVELS - 1)) as u8
            }
        })
        .collect()
}

fn shade(level: u8) -> RGBColor {
    if level == OUT_OF_RANGE {
        RGBColor(222, 232, 245)
    } else if level as usize > LEVELS {
        RGBColor(80, 80, 80)
    } else {
        let g = 235 - (level as u32 * 110 / LEVELS as u32) as u8;
        RGBColor(g, g, g)
    }
}

/// The colour of the points a failure is about.
pub const FAILED: RGBColor = RGBColor(220, 0, 0);

/// Draws the grid's blocked nodes, the cell points and each route; `title` heads the picture.
/// `in_range` tells a node out of the axis ranges (drawn apart) from one blocked by an obstacle.
pub fn render_svg(
    cs: &CSpace,
    in_range: &dyn Fn(&[f64; 3]) -> bool,
    points: &[PlacedPoint],
    routes: &[&Route],
    title: &str,
) -> Result<String, PictureError> {
    draw(cs, in_range, points, routes, None, title)
}

/// What a picture of a failed plan marks: the points the failure is about (indices into the
/// points; both ends of a leg that could not be planned), ringed in [`FAILED`], and why.
pub struct Marked<'a> {
    pub points: &'a [usize],
    pub why: &'a str,
}

/// The picture of a plan that failed: the grid's blocked nodes and the cell points as
/// [`render_svg`] draws them, no route, the points of `marked` ringed and labelled in
/// [`FAILED`], and why under the picture.
pub fn render_failure_svg(
    cs: &CSpace,
    in_range: &dyn Fn(&[f64; 3]) -> bool,
    points: &[PlacedPoint],
    marked: &Marked,
    title: &str,
) -> Result<String, PictureError> {
    draw(cs, in_range, points, &[], Some(marked), title)
}

fn draw(
    cs: &CSpace,
    in_range: &dyn Fn(&[f64; 3]) -> bool,
    points: &[PlacedPoint],
    routes: &[&Route],
    marked: Option<&Marked>,
    title: &str,
) -> Result<String, PictureError> {
    let grid = &cs.grid;
    if grid.is_empty() {
        return Err(PictureError::EmptyGrid);
    }
    let d = grid.dims;
    // Blocked counts of the three projections: (0,1) over axis 3, (0,2) over axis 2, (1,2) over
    // axis 1.
    // Per projection: blocked in-range nodes, and in-range nodes, of each column.
    let mut c01 = vec![[0u32; 2]; d[0] * d[1]];
    let mut c02 = vec![[0u32; 2]; d[0] * d[2]];
    let mut c12 = vec![[0u32; 2]; d[1] * d[2]];
    // The picture shows every node: the nodes no wave reached are inspected now, on all cores.
    cs.inspect_all(&crate::progress::Silent);
    for i in 0..grid.len() {
        let n = grid.node(i);
        if !in_range(&grid.axes_deg(n)) {
            continue;
        }
        let blocked = u32::from(cs.code_in(n) & FREE == 0);
        let (a, b, c) = (n[0] as usize, n[1] as usize, n[2] as usize);
        for cell in [
            &mut c01[a * d[1] + b],
            &mut c02[a * d[2] + c],
            &mut c12[b * d[2] + c],
        ] {
            cell[0] += blocked;
            cell[1] += 1;
        }
    }
    let split = |c: &[[u32; 2]]| {
        let blocked: Vec<u32> = c.iter().map(|x| x[0]).collect();
        let in_range: Vec<u32> = c.iter().map(|x| x[1]).collect();
        levels(&blocked, &in_range)
    };
    let projections = [
        ((0usize, 1usize), split(&c01)),
        ((0, 2), split(&c02)),
        ((1, 2), split(&c12)),
    ];

    let err = |e: &dyn std::fmt::Display| PictureError::Draw(e.to_string());
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (PANEL_W * 3, PANEL_H + 70)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let root = root
            .titled(title, ("sans-serif", 20))
            .map_err(|e| err(&e))?;
        let (body, foot) = root.split_vertically(PANEL_H);
        foot.draw(&Text::new(
            "grey: share of the in-range grid nodes along the third axis blocked by an obstacle (darker = more); dark: all blocked; pale blue: out of range",
            (20, 10),
            ("sans-serif", 14).into_font().color(&BLACK),
        ))
        .map_err(|e| err(&e))?;
        if let Some(m) = marked {
            foot.draw(&Text::new(
                format!("red rings: {}", crate::excerpt::message(m.why)),
                (20, 30),
                ("sans-serif", 14).into_font().color(&FAILED),
            ))
            .map_err(|e| err(&e))?;
        }
        let is_marked = |k: usize| marked.is_some_and(|m| m.points.contains(&k));
        let panels = body.split_evenly((1, 3));
        let step = grid.step_deg;
        for (panel, ((u, v), lv)) in panels.iter().zip(&projections) {
            let (u, v) = (*u, *v);
            let lo = |k: usize| grid.value(k, 0) - step / 2.0;
            let hi = |k: usize| grid.value(k, d[k] as i64 - 1) + step / 2.0;
            let mut chart = ChartBuilder::on(panel)
                .caption(
                    format!("axis {} - axis {}", u + 1, v + 1),
                    ("sans-serif", 16),
                )
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(50)
                .build_cartesian_2d(lo(u)..hi(u), lo(v)..hi(v))
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(format!("axis {} (deg)", u + 1))
                .y_desc(format!("axis {} (deg)", v + 1))
                .label_style(("sans-serif", 12))
                .draw()
                .map_err(|e| err(&e))?;
            // Runs of equal shade along v become one rectangle each.
            let mut rects = Vec::new();
            for iu in 0..d[u] {
                let mut iv = 0;
                while iv < d[v] {
                    let l = lv[iu * d[v] + iv];
                    let start = iv;
                    while iv < d[v] && lv[iu * d[v] + iv] == l {
                        iv += 1;
                    }
                    if l > 0 {
                        let x0 = grid.value(u, iu as i64) - step / 2.0;
                        let y0 = grid.value(v, start as i64) - step / 2.0;
                        let y1 = grid.value(v, iv as i64 - 1) + step / 2.0;
                        rects.push(Rectangle::new(
                            [(x0, y0), (x0 + step, y1)],
                            shade(l).filled(),
                        ));
                    }
                }
            }
            chart.draw_series(rects).map_err(|e| err(&e))?;
            for route in routes {
                let c = colour(route.method);
                let line: Vec<(f64, f64)> = route
                    .waypoints
                    .iter()
                    .map(|w| (w.joints_deg[u], w.joints_deg[v]))
                    .collect();
                chart
                    .draw_series(LineSeries::new(line.iter().copied(), c.stroke_width(2)))
                    .map_err(|e| err(&e))?
                    .label(format!("{} ({} moves)", route.method, route.moves()))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3))
                    });
                chart
                    .draw_series(line.iter().map(|&p| Circle::new(p, 2, c.filled())))
                    .map_err(|e| err(&e))?;
            }
            chart
                .draw_series(points.iter().enumerate().map(|(k, p)| {
                    let at = (p.joints_deg[u], p.joints_deg[v]);
                    let label = if is_marked(k) { FAILED } else { BLACK };
                    EmptyElement::at(at)
                        + Circle::new((0, 0), 4, BLACK.filled())
                        + Text::new(
                            p.name.clone(),
                            (6, -16),
                            ("sans-serif", 14).into_font().color(&label),
                        )
                }))
                .map_err(|e| err(&e))?;
            chart
                .draw_series(
                    points
                        .iter()
                        .enumerate()
                        .filter(|(k, _)| is_marked(*k))
                        .map(|(_, p)| {
                            let at = (p.joints_deg[u], p.joints_deg[v]);
                            Circle::new(at, 9, FAILED.stroke_width(2))
                        }),
                )
                .map_err(|e| err(&e))?;
            if !routes.is_empty() {
                chart
                    .configure_series_labels()
                    .position(SeriesLabelPosition::LowerRight)
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .label_font(("sans-serif", 13))
                    .draw()
                    .map_err(|e| err(&e))?;
            }
        }
        root.present().map_err(|e| err(&e))?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cell::Loc;
    use crate::place::Origin;
    use crate::plan::cspace::{CSpace, Grid};
    use crate::plan::{Leg, Waypoint, WaypointKind};

    #[test]
    fn shades_by_the_blocked_fraction() {
        // Depth 4: 0 blocked -> 0, 1 -> 1 + 10/4 = 3, 3 -> 1 + 30/4 = 8, 4 -> all (11).
        assert_eq!(levels(&[0, 1, 3, 4], &[4; 4]), vec![0, 3, 8, 11]);
        // Depth 0: no node in range; depth 2 with 1 blocked: 1 + 10/2 = 6.
        assert_eq!(levels(&[0, 1], &[0, 2]), vec![OUT_OF_RANGE, 6]);
        assert!(shade(1).0 > shade(10).0 && shade(10).0 > shade(11).0);
    }

    #[test]
    fn draws_points_routes_and_legend() {
        let g = Grid::over([[0.0, 9.0], [0.0, 4.0], [0.0, 3.0]], 1.0);
        // Axis-1 values 4 and 5 blocked for every axis 3 when axis 2 < 3: fully blocked in the
        // axis 1 - axis 2 projection there, partly in the others.
        let cs = CSpace::from_fn(g, |n| !((n[0] == 4 || n[0] == 5) && n[1] < 3));
        let point = |name: &str, a1: f64| PlacedPoint {
            name: name.into(),
            joints_deg: [a1, 0.0, 0.0, 0.0, 0.0, 0.0],
            loc: Loc::default(),
            origin: Origin::Joints,
            motion: crate::place::MoveMotion {
                speed: "v300".into(),
                zone: "fine".into(),
            },
        };
        let points = vec![point("P1", 0.0), point("P2", 9.0)];
        let arm = [
            [0.0, 0.0, 0.0],
            [3.0, 3.0, 0.0],
            [6.0, 3.0, 0.0],
            [9.0, 0.0, 0.0],
        ];
        let route = Route {
            method: Method::Extensile,
            grid_deg: 1.0,
            waypoints: arm
                .iter()
                .enumerate()
                .map(|(k, a)| Waypoint {
                    kind: match k {
                        0 => WaypointKind::CellPoint(0),
                        3 => WaypointKind::CellPoint(1),
                        _ => WaypointKind::Via { leg: 0, index: k },
                    },
                    joints_deg: [a[0], a[1], a[2], 0.0, 0.0, 0.0],
                })
                .collect(),
            legs: vec![Leg {
                from: 0,
                to: 1,
                grid_path: Vec::new(),
                straight: false,
                waypoints: 0..4,
            }],
        };
        let svg = render_svg(&cs, &|_| true, &points, &[&route], "test").expect("svg");
        assert!(svg.starts_with("<svg"));
        assert!(svg.contains("P1\n</text>") && svg.contains("P2\n</text>"));
        assert!(svg.contains("extensile (3 moves)"));
        assert!(svg.contains("axis 1 - axis 2") && svg.contains("axis 2 - axis 3"));
        // The dark "all blocked" shade appears and the route's colour.
        assert!(svg.contains("#505050"), "no fully blocked shade");
        assert!(svg.contains("#C80046"), "no extensile colour");
        // Same input, same bytes.
        assert_eq!(
            svg,
            render_svg(&cs, &|_| true, &points, &[&route], "test").expect("svg")
        );
        // A failure: no route, P2 ringed (once per projection) and labelled in red, why below.
        let marked = Marked {
            points: &[1],
            why: "no path from 'P1' to 'P2'",
        };
        let svg = render_failure_svg(&cs, &|_| true, &points, &marked, "test").expect("svg");
        assert_eq!(svg.matches("stroke=\"#DC0000\"").count(), 3, "{svg}");
        assert!(!svg.contains("#C80046") && !svg.contains("extensile ("));
        assert_eq!(svg.matches("fill=\"#DC0000\">\nP2\n</text>").count(), 3);
        assert_eq!(svg.matches("fill=\"#000000\">\nP1\n</text>").count(), 3);
        assert!(svg.contains("red rings: no path from &apos;P1&apos; to &apos;P2&apos;"));
    }
}
