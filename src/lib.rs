//! gen-rapid: cell YAML -> collision-free joint-space path -> ABB RAPID module.
//!
//! The pipeline, one module per stage (see ARCHITECTURE.md):
//! `cell` -> `robot` -> `collision` -> `cspace` -> `wave` -> `search` -> `shorten`/`merge`
//! -> `plan` -> `rapid`.

pub mod collision;
pub mod geometry;
pub mod rapid;
pub mod robot;
