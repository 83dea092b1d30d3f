//! gen-rapid: cell YAML -> collision-free joint-space path -> ABB RAPID module.
//!
//! The pipeline, one module per stage (see ARCHITECTURE.md):
//! `cell` -> `robot` -> (`locate`, `ik`) -> `collision` -> `cspace` -> `wave` -> `search`
//! -> `shorten` / `merge` -> `plan` -> `program` -> `rapid`; `timing` (manipulation time, paper
//! section 5) and `picture` (SVG of the search) look at a plan.

pub mod cell;
pub mod cli;
pub mod collision;
pub mod cspace;
pub mod error;
pub mod geometry;
pub mod ik;
pub mod locate;
pub mod merge;
pub mod picture;
pub mod pipeline;
pub mod plan;
pub mod preview;
pub mod program;
pub mod rapid;
pub mod robot;
pub mod search;
pub mod shorten;
pub mod timing;
pub mod wave;
