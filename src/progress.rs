//! Progress of a long run, as the stages report it: a leaf trait the pipeline calls
//! and the command line implements (`cli::progress`, an `indicatif` bar on a terminal).
//!
//! Reporting progress changes nothing a stage computes: [`Silent`] is what every stage gets
//! unless the command line asks for a bar, and the stages' results are the same either way.

/// What the stages report. Implementations are shared by the grid fill's threads.
pub trait Progress: Sync {
    /// A stage begins; `units` is its amount of work when known (0: not known).
    fn stage(&self, name: &str, units: u64);
    /// `n` more units of the current stage are done.
    fn advance(&self, n: u64);
}

/// Reports nothing.
pub struct Silent;

impl Progress for Silent {
    fn stage(&self, _name: &str, _units: u64) {}
    fn advance(&self, _n: u64) {}
}
