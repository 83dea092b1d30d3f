//! Inverse kinematics.

pub mod wrist;
pub use wrist::*;
