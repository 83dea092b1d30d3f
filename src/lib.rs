//! gen-rapid
pub mod geometry;
