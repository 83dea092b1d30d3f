//! gen-rapid: cell YAML -> collision-free joint-space path -> ABB RAPID module.

pub mod cell;
pub mod cli;
pub mod collision;
pub mod error;
pub mod geometry;
pub mod names;
pub mod output;
pub mod pipeline;
pub mod place;
pub mod plan;
pub mod precision;
pub mod robot;
pub mod timing;
