//! What `gen-rapid robots` lists: the robots built into gen-rapid (`robot.model`), each with its
//! reach, coupling and axis ranges; as a [`Listing`] (the JSON array's objects) or as text.
//! The figures come from each robot's own files (`Robot::shipped`), the reach from the closed
//! form of the wrist centre (`robot::ik::wrist::horizontal_reach_mm`); `cli::robots` gathers them.

use crate::robot::{Coupling, Robot};
use serde::Serialize;

/// One shipped robot as listed. Lengths mm, angles deg, speeds deg/s.
#[derive(Clone, Debug, Serialize)]
pub struct Listed {
    /// The name `robot.model` takes.
    pub model: String,
    /// ABB's name of the variant.
    pub title: String,
    /// How far the wrist centre reaches from axis 1, horizontally, within the axis ranges
    /// (1 decimal); `None` for an arm the closed form does not take.
    pub reach_mm: Option<f64>,
    /// `"serial"` or `"parallelogram"` (axis 3 = URDF joint 3 + joint 2).
    pub coupling: &'static str,
    /// Axes 1..6: range and speed.
    pub axes: Vec<ListedAxis>,
    /// The range of axis 3 - axis 2 the controller bounds too, when it does.
    pub coupled_axis3_deg: Option<[f64; 2]>,
    /// The collision cylinders of the URDF, per link (names, in chain order).
    pub links: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ListedAxis {
    pub min_deg: f64,
    pub max_deg: f64,
    pub speed_deg_s: f64,
}

/// The listing of `robot` (a shipped model named `model`, ABB's `title`).
pub fn listed(model: &str, title: &str, robot: &Robot, reach_mm: Option<f64>) -> Listed {
    let c = &robot.controller;
    let mut links: Vec<String> = Vec::new();
    for own in &robot.collision {
        if !links.contains(&own.link) {
            links.push(own.link.clone());
        }
    }
    Listed {
        model: model.to_string(),
        title: title.to_string(),
        reach_mm: reach_mm.map(|r| crate::precision::round(r, 1)),
        coupling: match c.coupling {
            Coupling::Serial => "serial",
            Coupling::Parallelogram => "parallelogram",
        },
        axes: c
            .axes
            .iter()
            .map(|a| ListedAxis {
                min_deg: a.min_deg,
                max_deg: a.max_deg,
                speed_deg_s: a.speed_deg_s,
            })
            .collect(),
        coupled_axis3_deg: c.coupled_axis3_deg,
        links,
    }
}

/// The listing as text: per robot a line with its name, ABB's name, reach and coupling, then
/// its axes' ranges and speeds, and the links that carry collision cylinders.
pub fn render_text(list: &[Listed]) -> String {
    let mut out = String::new();
    for (i, l) in list.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let reach = l
            .reach_mm
            .map_or("reach unknown".to_string(), |r| format!("reach {r:.1} mm"));
        let coupling = match l.coupling {
            "parallelogram" => "parallelogram (axis 3 = URDF joint 3 + joint 2)",
            _ => "serial (axes 1..6 = URDF joints 1..6)",
        };
        out += &format!("{}: {}, {reach}, {coupling}\n", l.model, l.title);
        for (k, a) in l.axes.iter().enumerate() {
            out += &format!(
                "  axis {}: {} .. {} deg, {} deg/s\n",
                k + 1,
                a.min_deg,
                a.max_deg,
                a.speed_deg_s
            );
        }
        if let Some([lo, hi]) = l.coupled_axis3_deg {
            out += &format!("  axis 3 - axis 2: {lo} .. {hi} deg (the coupled range)\n");
        }
        out += &format!("  collision cylinders on: {}\n", l.links.join(", "));
    }
    out
}
