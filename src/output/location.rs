//! What `gen-rapid locate` reports about the place stage's survey (paper section 2): the
//! feasible region R of base positions, its area and bounding box, a base in it with its margin,
//! and each point's reach region; as a [`Report`] (the JSON object's fields) or as text.

use crate::cell::{Base, Cell};
use crate::place::Survey;
use serde::Serialize;

/// What `locate` reports (the JSON object's fields). Lengths mm, areas mm^2 and m^2, angles deg,
/// positions in the cell frame.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// The cell file as given.
    pub cell: String,
    /// `"auto"` or `"fixed"`.
    pub base_mode: &'static str,
    /// Number of working points.
    pub points: usize,
    /// Raster cell `R` was sampled on, mm.
    pub raster_mm: f64,
    pub area_mm2: f64,
    pub area_m2: f64,
    /// Bounding box of `R`, `[[x_min, y_min], [x_max, y_max]]`, mm.
    pub bbox_mm: Option<[[f64; 2]; 2]>,
    /// The chosen base, `[x, y, z]`: with `base: auto` the one the run uses (the position of `R`
    /// with the largest margin from which every point is solved in range and free of collision).
    pub base_mm: [f64; 3],
    /// Its distance to the boundary of `R`, mm.
    pub margin_mm: f64,
    /// The cell's yaw, kept as given.
    pub yaw_deg: f64,
    /// With a fixed base: that base and whether it lies in `R`.
    pub given_base: Option<GivenBase>,
    /// Per point: its wrist centre and the rings of base distance that reach it.
    pub reach: Vec<PointReach>,
    /// Obstacles whose height range meets the base's (only these can block a base position).
    pub blocking_obstacles: Vec<String>,
    /// Their footprints are grown by this (base radius + clearance), mm.
    pub grow_mm: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct GivenBase {
    pub base_mm: [f64; 3],
    pub in_region: bool,
    /// Distance to the boundary of `R` when inside, mm.
    pub margin_mm: Option<f64>,
}

#[derive(Clone, Debug, Serialize)]
pub struct PointReach {
    pub name: String,
    /// Wrist centre, cell frame, mm.
    pub xyz_mm: [f64; 3],
    /// Smallest and largest base distance (top view) that reaches the point, mm.
    pub inner_mm: f64,
    pub outer_mm: f64,
    /// The rings `[from, to]`, mm (usually one).
    pub rings_mm: Vec<[f64; 2]>,
}

/// Builds the report from the survey of the place stage.
pub fn report(cell: &Cell, survey: &Survey) -> Report {
    let location = &survey.location;
    let r = &location.region;
    let given_base = match cell.robot.base {
        Base::Fixed(b) => {
            let margin = location.margin_at([b[0], b[1]]);
            Some(GivenBase {
                base_mm: b,
                in_region: margin.is_some(),
                margin_mm: margin,
            })
        }
        Base::Auto => None,
    };
    Report {
        cell: cell.path.display().to_string(),
        base_mode: match cell.robot.base {
            Base::Fixed(_) => "fixed",
            Base::Auto => "auto",
        },
        points: cell.points.len(),
        raster_mm: r.cell_mm,
        area_mm2: r.area_mm2,
        area_m2: r.area_mm2 * 1e-6,
        bbox_mm: r.bbox.map(|(lo, hi)| [lo, hi]),
        base_mm: survey.base_mm,
        margin_mm: survey.margin_mm,
        yaw_deg: cell.robot.yaw_deg,
        given_base,
        reach: location
            .reach
            .iter()
            .zip(&survey.points)
            .map(|(reach, (name, xyz))| PointReach {
                name: name.clone(),
                xyz_mm: *xyz,
                inner_mm: reach.inner_mm,
                outer_mm: reach.outer_mm,
                rings_mm: reach.rings_mm.clone(),
            })
            .collect(),
        blocking_obstacles: location.blocking.iter().map(|o| o.name.clone()).collect(),
        grow_mm: location.grow_mm,
    }
}

fn fmt_xyz(p: [f64; 3]) -> String {
    format!("[{:.1}, {:.1}, {:.1}] mm", p[0], p[1], p[2])
}

/// The report as text (what `locate` prints without `--json`).
pub fn render_text(r: &Report) -> String {
    let mut out = format!("cell: {} (base: {})\n", r.cell, r.base_mode);
    out += &format!("points: {}\n", r.points);
    for p in &r.reach {
        let rings = p
            .rings_mm
            .iter()
            .map(|g| format!("{:.1} .. {:.1}", g[0], g[1]))
            .collect::<Vec<_>>()
            .join(" and ");
        out += &format!(
            "  {} at ({:.1}, {:.1}, {:.1}): reached from base distances {rings} mm\n",
            p.name, p.xyz_mm[0], p.xyz_mm[1], p.xyz_mm[2]
        );
    }
    out += &format!(
        "region R: {:.3} m^2 ({:.0} mm^2), sampled on a {} mm raster\n",
        r.area_m2, r.area_mm2, r.raster_mm
    );
    if let Some([lo, hi]) = r.bbox_mm {
        out += &format!(
            "  bounding box: x {:.1} .. {:.1} mm, y {:.1} .. {:.1} mm ({:.0} x {:.0} mm)\n",
            lo[0],
            hi[0],
            lo[1],
            hi[1],
            hi[0] - lo[0],
            hi[1] - lo[1]
        );
    }
    if r.blocking_obstacles.is_empty() {
        out += "  no obstacle reaches down to the base\n";
    } else {
        out += &format!(
            "  obstacles that can block the base (footprints grown by {:.1} mm): {}\n",
            r.grow_mm,
            r.blocking_obstacles.join(", ")
        );
    }
    let what = match r.given_base {
        None => "chosen base",
        Some(_) => "base with the largest margin",
    };
    out += &format!(
        "{what}: {}, yaw {} deg (as given), margin {:.1} mm to the edge of R\n",
        fmt_xyz(r.base_mm),
        r.yaw_deg,
        r.margin_mm
    );
    if let Some(g) = &r.given_base {
        out += &match g.margin_mm {
            Some(m) => format!(
                "given base: {}: inside R, margin {m:.1} mm\n",
                fmt_xyz(g.base_mm)
            ),
            None => format!(
                "given base: {}: OUTSIDE R (some point out of reach, or too close to an obstacle)\n",
                fmt_xyz(g.base_mm)
            ),
        };
    }
    out
}
