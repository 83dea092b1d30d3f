//! The place stage.

pub mod locate;
