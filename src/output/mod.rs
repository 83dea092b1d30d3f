//! The render stage.

pub mod cspace_svg;
pub mod program;
pub mod rapid;
