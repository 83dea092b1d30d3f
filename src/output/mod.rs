//! The render stage: what gen-rapid writes, made from the earlier stages' results only (the
//! cell, the placed job, the plan). Nothing here asks the collision model, the timing or the
//! searches: everything printed is in [`Plan`](crate::refine::Plan) (or, for the comparison,
//! a [`Route`](crate::plan::Route)) or [`Placed`](crate::place::Placed).
//!
//! - [`program`]: the plan as a RAPID program, [`rapid`]: its text (template, number format,
//!   the names of the generated data);
//! - [`cspace_svg`]: the search over the configuration space (paper Figs. 11-13);
//! - [`topview_svg`] and [`location`]: the feasible base region, drawn and reported (paper
//!   section 2, Fig. 1);
//! - [`comparison`]: the three searches side by side (paper section 6);
//! - [`preview`]: the self-contained 3D preview page (HTML + WebGL) of the cell and the motion;
//! - [`report`]: the run's results as JSON (`--report`);
//! - [`robots`]: the robots built into gen-rapid, listed (`gen-rapid robots`);
//! - [`poses`]: the robot's frames in the cell (forward kinematics of the load stage's robot
//!   model, for the preview and the report; kinematics is not collision).

pub mod comparison;
pub mod cspace_svg;
pub mod location;
pub mod poses;
pub mod preview;
pub mod program;
pub mod rapid;
pub mod report;
pub mod robots;
pub mod topview_svg;

use crate::plan::{Clearance, Part};

/// Which part of the robot model a clearance is about: `("link", name)` for a link cylinder,
/// `("tool", name)` for a tool shape. The one place the output reads it.
pub fn clearance_part(c: &Clearance) -> (&'static str, &str) {
    match &c.part {
        Part::Link(name) => ("link", name),
        Part::ToolShape(name) => ("tool", name),
    }
}
