//! Beyond the paper, for speed: a leg whose straight move is proven goes straight, without the
//! grid.
//!
//! Before any grid node is read, the straight six-axis move of each leg between its two points
//! (as placed: the values the module writes) is tried with the whole-move proof that every
//! planned move passes (`CollisionModel::move_is_safe`: both ends in range, every link cylinder
//! and tool shape at least the cell's clearance from every box along the whole move). A leg so
//! proven is that one move: no search, no shortening, no grid node inspected for it. The grid,
//! inspected as its waves ask (`cspace`), plans only the other legs, so a cell whose legs are all
//! proven inspects no node at all. A straight joint move is the shortest path in joint space, the
//! one a shortened and straightened grid path tends to. It is not always the fastest in the
//! time estimate (a TCP speed limit slows a long move as a whole, where a route through vias
//! may be slowed only in part); a proven straight leg is taken without planning the grid route
//! that would tell (`docs/planning.md`, "How it plans", 7).
//!
//! The paper plans every leg on its grid: a route with a leg planned here is not the paper's
//! method alone ([`Route::paper_alone`] says so), and `Legs::GridOnly` keeps the paper's method
//! as published. A leg whose two points share axes 1..3 (the wrist turns in place) needs no grid
//! either way and is left to the leg planner, which names what blocks it.

use super::{PlacedPoint, Route};
use crate::cell::Planner;
use crate::collision::CollisionModel;

/// Which legs the plan stage plans on the grid ([`super::route_with`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Legs {
    /// Every leg on the grid: the paper's method as published.
    GridOnly,
    /// A leg whose straight move is proven goes straight ([`proven_straight`]); the others on
    /// the grid.
    StraightFirst,
}

impl Legs {
    /// The legs of a run of a cell with these planner settings: with the refinements beyond
    /// the paper (`planner.shortcut`, whose pass straightens what the grid's path leaves) a
    /// proven straight leg goes straight; without them (`--no-shortcut`) the paper's method
    /// alone, every leg on the grid.
    pub fn of(planner: &Planner) -> Legs {
        match planner.shortcut {
            true => Legs::StraightFirst,
            false => Legs::GridOnly,
        }
    }
}

/// Per leg of the route through `points` (leg `i` from point `i` to point `i + 1`): whether
/// it goes straight, its points differing on axes 1..3 and its straight move proven safe.
/// The proofs run on all cores (`crate::parallel`), each leg's alone, so the answer does not
/// depend on their number.
pub fn proven_straight(model: &CollisionModel, points: &[PlacedPoint]) -> Vec<bool> {
    let legs: Vec<usize> = (0..points.len().saturating_sub(1)).collect();
    crate::parallel::map(&legs, |&i| {
        let (a, b) = (&points[i], &points[i + 1]);
        a.arm_deg() != b.arm_deg() && model.move_is_safe(&a.joints_deg, &b.joints_deg)
    })
}

impl Route {
    /// Whether every leg was planned by the paper's method (no leg gone straight without the
    /// grid: [`Legs::StraightFirst`]), so the route's figure is the paper's method alone.
    pub fn paper_alone(&self) -> bool {
        self.legs.iter().all(|l| !l.straight)
    }
}

#[cfg(test)]
mod tests {
    //! Whole runs of the bench cells: the open cell inspects no grid node; the tool-only cell's
    //! leg that only the tool blocks goes on the grid.
    use super::*;
    use crate::pipeline::{self, Options};
    use crate::plan::Method;
    use std::path::Path;

    fn job(cell: &str) -> pipeline::Loaded {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(cell);
        pipeline::load(&path).unwrap_or_else(|f| panic!("{}", f.render()))
    }

    /// Every straight move of the open cell is free: each leg is its two points, no block of
    /// the grid is inspected, and the paper's figure is not stated (its method did not run).
    /// Without the shortcut pass (the paper's method alone) the grid plans every leg.
    #[test]
    fn the_open_cell_builds_no_grid() {
        let mut job = job("benches/cells/open.yaml");
        let out = pipeline::run(&job, &Options::new(Method::Extensile, 1.0)).expect("run");
        let route = &out.plan.route;
        assert_eq!(out.inspected.cspace.inspected_blocks(), 0);
        assert!(out.inspected.cspace.block_count() > 1000);
        assert_eq!(route.legs.len(), 4);
        assert!(route
            .legs
            .iter()
            .all(|l| l.straight && l.grid_path.is_empty()));
        let six: Vec<[f64; 6]> = route.waypoints.iter().map(|w| w.joints_deg).collect();
        let points: Vec<[f64; 6]> = out.placed.points.iter().map(|p| p.joints_deg).collect();
        assert_eq!(six, points);
        assert!(!route.paper_alone() && out.plan.paper.is_none());
        assert!(!out.rendered.text.contains("the paper's method alone"));
        job.cell.planner.shortcut = false;
        let paper = pipeline::run(&job, &Options::new(Method::Extensile, 1.0)).expect("run");
        assert!(paper.inspected.cspace.inspected_blocks() > 0);
        assert!(paper.plan.route.legs.iter().all(|l| !l.straight));
        assert!(paper.plan.route.paper_alone() && paper.plan.paper.is_some());
        assert!(paper.rendered.text.contains("the paper's method alone"));
    }

    /// On the tool-only cell the arm's links clear the bar on the straight move left -> right
    /// and the gripper's finger does not: the leg is left to the grid (the proof holds the tool
    /// too); the run's route is proven again move by move.
    #[test]
    fn a_leg_only_the_tool_blocks_goes_on_the_grid() {
        let job = job("benches/cells/tool-only.yaml");
        let placed = pipeline::place(&job).expect("place");
        let inspected = pipeline::inspect(&job, &placed, 1.0);
        let model = &inspected.model;
        let p = &placed.points;
        let (left, right) = (p[0].joints_deg, p[1].joints_deg);
        assert!(model.links_move_is_safe(&left, &right));
        assert!(!model.move_is_safe(&left, &right));
        let straight = proven_straight(model, p);
        assert!(!straight[0]);
        let route = pipeline::route_with(
            &job,
            &placed,
            &inspected,
            Method::Extensile,
            Legs::StraightFirst,
        )
        .expect("route");
        let kinds: Vec<bool> = route.legs.iter().map(|l| l.straight).collect();
        assert_eq!(kinds, straight);
        assert!(
            route.legs[0].waypoints.len() > 2,
            "the grid leg turns the tool round the bar"
        );
        assert!(inspected.cspace.inspected_blocks() > 0);
        assert!(route.moves6().all(|(a, b)| model.move_is_safe(&a, &b)));
    }
}
