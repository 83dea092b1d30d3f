//! The controller-like re-check's own tests (`common/opw.rs`, `common/routine.rs`,
//! `common/controller.rs` and the files it uses): its inverse kinematics against the library's
//! forward kinematics, its own reading of the robot's collision shapes and motion bound, the TCP
//! paths and their following worked out by hand, and hand-written modules with process moves
//! that it must pass or refuse.

mod links;
mod opw;
mod paths;
mod process;
