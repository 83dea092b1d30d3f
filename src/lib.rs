//! gen-rapid
pub mod rapid;
