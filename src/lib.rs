//! gen-rapid: cell YAML -> collision-free joint-space path -> ABB RAPID module.
//!
//! The pipeline (`pipeline`), one module per stage, each a function of the previous stages'
//! typed results (ARCHITECTURE.md has the code map and the invariants):
//!
//! ```text
//! load (cell, robot) -> place -> inspect (collision) -> plan -> refine (with time) -> render (output)
//! ```

// Leaves, used by any stage.
/// The first YAML key given no value (the cell's and the controller file's refusal).
pub mod blank_key;
pub mod excerpt;
pub mod geometry;
pub mod input;
pub mod names;
pub mod parallel;
pub mod precision;
/// Progress of long runs as the stages report it (a trait; the terminal bar is in `cli`).
pub mod progress;
/// RAPID's predefined speeddata and zonedata (docs/rapid.md).
pub mod rapid_data;
/// Large all-zero buffers paid for by the pages touched (the waves' planes and numbers).
pub mod zeroed;

// The stages, in pipeline order.

// load: URDF, controller convention, kinematics, IK
pub mod robot;

// load: the cell file
/// The budgets of a run (memory and time), checked before the work.
pub mod budget;
pub mod cell;

// place: where the robot stands, every point on six axes
pub mod place;

// inspect: the robot among the boxes, nodes and whole moves
pub mod collision;

// plan: the grid, the wave, the searches, the route
pub mod plan;

// time: manipulation time per move
pub mod timing;

// refine: the shortcut pass, the certified zones at waypoints, the plan the module writes
pub mod refine;

// follow: the process moves followed and proven, the stops the air route runs between, the
// plans spliced into one
pub mod process;

// render: the RAPID module, pictures, reports
pub mod output;

// The order of the stages, the errors, the commands.
pub mod cli;
pub mod error;
/// The load stage: reads the cell file and its robot files into `Loaded`.
pub mod load;
pub mod pipeline;
