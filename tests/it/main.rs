//! The integration tests: one binary, one module per subject.
mod cli;
mod common;
mod compare;
mod golden;
mod locate;
mod random_cells;
mod safety;
