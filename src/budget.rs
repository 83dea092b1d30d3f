//! The budgets of a run: every input whose size drives memory or time is bounded before the
//! work starts, so that no input the cell format allows makes a run abort for memory (4 GB of
//! address space) or last for minutes. It counts and allocates nothing (it knows the accepted
//! grid steps, `cell::defaults`, and nothing else of the stages); the caller
//! (`load::check_budgets`) says where in the input the budget was passed.
//!
//! What drives what, measured on the 2-core machine of `benches/README.md` (figures for
//! choosing the budgets, not promises):
//!
//! - **The grid's memory**: one code byte a node and a bit a node of row sets for the whole run,
//!   and while a leg is planned up to 5.25 bytes a node of address space for its waves and tool
//!   memo (`plan::legs_at_once`; mapped on demand, so a leg pays for the pages it touches, but a
//!   memory cap such as `ulimit -v` counts them all). At most [`MAX_GRID_NODES`] (500 M) nodes:
//!   about 3.2 GB of address space at the worst, 1.2 bytes a node resident on the paper's cell
//!   (the IRB 1400's ranges at 0.25 deg, 413 M nodes: 0.48 GB resident, 2.0 - 3.9 s).
//! - **The inspection of the grid**: each node against each obstacle for each part of the
//!   model (link cylinders, tool shapes); far obstacles are culled cheaply, so the work counted
//!   is nodes x parts x ([`CULL_OBSTACLES`] + obstacles): 1 000 small boxes around the arm at
//!   1 deg (6.5 M nodes, 3 parts) took 2.5 s, 2 000 identical cylinders on link 1 21 s. At
//!   most [`MAX_INSPECTION_WORK`].
//! - **The legs**: each leg's waves and proofs cost up to the whole grid (a trivial leg about
//!   3 ns a node). Legs x nodes x searches (three in `compare`, and
//!   its shortcut row) at most [`MAX_LEG_WORK`].
//! - **Fly-by zones**: certifying corners and splitting vias costs seconds a leg (the shelf
//!   cell with `via_zone: z50`: 2.4 s a leg at 1 deg, 3.4 s at 0.5 deg), more on a finer grid
//!   (more vias): legs x max(1, 1 deg / grid) at most [`MAX_ZONED_LEGS`] when any move asks a
//!   zone other than `fine`.
//! - **Counts** that size every stage and every file written: points ([`MAX_POINTS`]),
//!   obstacles ([`MAX_OBSTACLES`]), tool shapes ([`MAX_TOOL_SHAPES`]), link cylinders of the
//!   URDF ([`MAX_LINK_CYLINDERS`]).
//!
//! Elsewhere: an input file holds at most 64 MiB (`input`), a cell at most 250 000 YAML nodes
//! (the reader's budget, `cell::syntax`), a template runs on `output::rapid::TEMPLATE_FUEL` and
//! writes at most `output::rapid::MAX_MODULE_BYTES`, the preview page is thinned to
//! `output::preview::MAX_KEYFRAMES` keyframes.

/// The most nodes of the grid over axes 1..3 (memory: module docs).
pub const MAX_GRID_NODES: u64 = 500_000_000;
/// Obstacles' worth of culling a node costs, in the inspection's work count (module docs).
pub const CULL_OBSTACLES: u64 = 12;
/// The most inspection work: nodes x parts x (CULL_OBSTACLES + obstacles) (about 25 s).
pub const MAX_INSPECTION_WORK: u64 = 200_000_000_000;
/// The most leg work: legs x nodes x searches (minutes of legs that each search the whole grid;
/// a cell of the most points at 1 deg fits, and the paper's cell at 0.25 deg with 145 legs).
pub const MAX_LEG_WORK: u64 = 60_000_000_000;
/// The most legs x max(1, 1 deg / grid) when a move asks a fly-by zone (minutes at the worst:
/// a daily cell of a few dozen zoned points at 0.25 deg fits).
pub const MAX_ZONED_LEGS: f64 = 240.0;
/// The most points of a cell.
pub const MAX_POINTS: usize = 2_000;
/// The most obstacles of a cell.
pub const MAX_OBSTACLES: usize = 5_000;
/// The most shapes of a tool.
pub const MAX_TOOL_SHAPES: usize = 64;
/// The most collision cylinders of the arm's links in a URDF.
pub const MAX_LINK_CYLINDERS: usize = 32;

/// What a run will ask, counted before it starts.
#[derive(Clone, Copy, Debug)]
pub struct Demand {
    /// The ranges of axes 1..3 (deg) and the grid step over them (deg).
    pub ranges_deg: [[f64; 2]; 3],
    pub grid_deg: f64,
    /// Link cylinders and tool shapes.
    pub parts: usize,
    pub obstacles: usize,
    pub points: usize,
    /// Searches run on every leg: 1 for a run, 4 for `compare`.
    pub searches: usize,
    /// Whether any move asks a zone other than `fine`.
    pub fly_by: bool,
}

/// The budget a run passes, with what it counts, the item that passes it (0-based: the point
/// or obstacle; `None` where the grid does) and how to stay within it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Exceeded {
    #[error("the grid over axes 1..3 at {grid_deg} deg holds {} nodes ({}), more than the {} a run may use (about {} GB of memory at the worst); a grid of {finest_deg} deg or coarser fits", count(*nodes), dims_text(dims), count(MAX_GRID_NODES), gb(MAX_GRID_NODES))]
    GridNodes {
        grid_deg: f64,
        nodes: u64,
        dims: [u64; 3],
        /// The finest step within the budget, rounded up to 0.01 deg (`None`: none of the
        /// accepted steps).
        finest_deg: String,
    },
    #[error("inspecting the grid at {grid_deg} deg ({} nodes) against {obstacles} obstacles with {parts} parts of the robot model (link cylinders and tool shapes) passes the inspection budget ({} node-part-obstacle checks, {} allowed); {hint}", count(*nodes), count(*work), count(MAX_INSPECTION_WORK))]
    Inspection {
        grid_deg: f64,
        nodes: u64,
        obstacles: usize,
        parts: usize,
        work: u64,
        /// The obstacle at which the budget is passed.
        at: Option<usize>,
        hint: String,
    },
    #[error("planning {legs} legs{} over a grid of {} nodes at {grid_deg} deg passes the planning budget ({} leg-nodes, {} allowed); {hint}", if *searches > 1 { format!(" with {searches} searches each") } else { String::new() }, count(*nodes), count(*work), count(MAX_LEG_WORK))]
    Legs {
        grid_deg: f64,
        nodes: u64,
        legs: usize,
        searches: usize,
        work: u64,
        /// The point at which the budget is passed.
        at: Option<usize>,
        hint: String,
    },
    #[error("proving fly-by zones on {legs} legs at {grid_deg} deg passes the zone budget ({MAX_ZONED_LEGS} legs at 1 deg or coarser, fewer on a finer grid: legs x max(1, 1 deg / grid)); certify zones on at most {allowed} legs here, or write every zone fine")]
    ZonedLegs {
        grid_deg: f64,
        legs: usize,
        allowed: usize,
        /// The point at which the budget is passed.
        at: usize,
    },
    #[error("the cell gives {found} {what}, more than the {max} a run takes")]
    Count {
        what: &'static str,
        found: usize,
        max: usize,
        /// The item at which the budget is passed.
        at: usize,
    },
}

/// `n` with a unit prefix (`413 M`, `6.5 M`, `12 k`).
fn count(n: u64) -> String {
    let n = n as f64;
    for (unit, scale) in [("G", 1e9), ("M", 1e6), ("k", 1e3)] {
        if n >= scale {
            let v = n / scale;
            return if v < 10.0 {
                format!("{v:.1} {unit}")
            } else {
                format!("{v:.0} {unit}")
            };
        }
    }
    format!("{n}")
}

fn gb(nodes: u64) -> String {
    format!("{:.1}", nodes as f64 * WORST_BYTES_PER_NODE / 1e9)
}

/// Address space a node may take at the worst (module docs): its code, a bit of row sets,
/// and a leg's waves and tool memo.
const WORST_BYTES_PER_NODE: f64 = 1.0 + 0.125 + 5.25;

fn dims_text(dims: &[u64; 3]) -> String {
    format!("{} x {} x {}", dims[0], dims[1], dims[2])
}

/// The nodes of each axis of the grid over `ranges_deg` at `grid_deg`, counted as
/// `plan::cspace::Grid::over` lays them, without making it (a count that does not fit memory is what this
/// is for).
pub fn grid_dims(ranges_deg: [[f64; 2]; 3], grid_deg: f64) -> [u64; 3] {
    ranges_deg.map(|[lo, hi]| {
        let first = (lo / grid_deg - 1e-9).ceil();
        let last = (hi / grid_deg + 1e-9).floor();
        let n = last - first + 1.0;
        if n.is_finite() && n > 0.0 {
            n as u64
        } else {
            0
        }
    })
}

/// The nodes of the grid (saturating).
pub fn grid_nodes(ranges_deg: [[f64; 2]; 3], grid_deg: f64) -> u64 {
    grid_dims(ranges_deg, grid_deg)
        .iter()
        .fold(1u64, |n, &d| n.saturating_mul(d))
}

/// The finest grid step within `fits`, rounded up to 0.01 deg, among the accepted steps
/// (`cell::defaults::MIN_GRID_DEG` .. `MAX_GRID_DEG`), as text; "none" when even the coarsest
/// does not fit.
fn finest_step(fits: impl Fn(f64) -> bool) -> String {
    use crate::cell::defaults::{MAX_GRID_DEG, MIN_GRID_DEG};
    let hundredths = |x: f64| (x * 100.0).round() as u64;
    let (lo, hi) = (hundredths(MIN_GRID_DEG), hundredths(MAX_GRID_DEG));
    if !fits(hi as f64 / 100.0) {
        return "none of the accepted steps (up to 10 deg)".into();
    }
    // The count only falls as the step grows (fewer nodes): the first step that fits.
    let (mut bad, mut good) = (lo.saturating_sub(1), hi);
    while good - bad > 1 {
        let mid = (bad + good) / 2;
        if fits(mid as f64 / 100.0) {
            good = mid;
        } else {
            bad = mid;
        }
    }
    format!("{:.2}", good as f64 / 100.0)
}

/// Checks a run's demand against every budget (module docs), the grid's memory first.
pub fn check(d: &Demand) -> Result<(), Exceeded> {
    let nodes = grid_nodes(d.ranges_deg, d.grid_deg);
    if nodes > MAX_GRID_NODES {
        return Err(Exceeded::GridNodes {
            grid_deg: d.grid_deg,
            nodes,
            dims: grid_dims(d.ranges_deg, d.grid_deg),
            finest_deg: finest_step(|g| grid_nodes(d.ranges_deg, g) <= MAX_GRID_NODES),
        });
    }
    let inspection = |obstacles: usize, nodes: u64| {
        nodes
            .saturating_mul(d.parts.max(1) as u64)
            .saturating_mul(CULL_OBSTACLES + obstacles as u64)
    };
    let work = inspection(d.obstacles, nodes);
    if work > MAX_INSPECTION_WORK {
        let at = (0..d.obstacles).find(|&k| inspection(k + 1, nodes) > MAX_INSPECTION_WORK);
        let finest = finest_step(|g| {
            inspection(d.obstacles, grid_nodes(d.ranges_deg, g)) <= MAX_INSPECTION_WORK
        });
        return Err(Exceeded::Inspection {
            grid_deg: d.grid_deg,
            nodes,
            obstacles: d.obstacles,
            parts: d.parts,
            work,
            at,
            hint: format!("a grid of {finest} deg or coarser fits, or fewer obstacles or parts"),
        });
    }
    let legs = d.points.saturating_sub(1);
    let leg_work = |legs: usize, nodes: u64| {
        nodes
            .saturating_mul(legs as u64)
            .saturating_mul(d.searches.max(1) as u64)
    };
    let work = leg_work(legs, nodes);
    if work > MAX_LEG_WORK {
        let at = (1..d.points).find(|&k| leg_work(k, nodes) > MAX_LEG_WORK);
        let finest = finest_step(|g| leg_work(legs, grid_nodes(d.ranges_deg, g)) <= MAX_LEG_WORK);
        return Err(Exceeded::Legs {
            grid_deg: d.grid_deg,
            nodes,
            legs,
            searches: d.searches,
            work,
            at,
            hint: format!(
                "a grid of {finest} deg or coarser fits, or split the points into several cells"
            ),
        });
    }
    if d.fly_by {
        let weight = (1.0 / d.grid_deg).max(1.0);
        if legs as f64 * weight > MAX_ZONED_LEGS {
            let allowed = (MAX_ZONED_LEGS / weight).floor() as usize;
            return Err(Exceeded::ZonedLegs {
                grid_deg: d.grid_deg,
                legs,
                allowed,
                at: allowed + 1,
            });
        }
    }
    Ok(())
}

/// Checks a count against its budget: `Err` names the item (0-based) that passes it.
pub fn count_within(what: &'static str, found: usize, max: usize) -> Result<(), Exceeded> {
    if found > max {
        return Err(Exceeded::Count {
            what,
            found,
            max,
            at: max,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::cspace::Grid;

    const IRB1400: [[f64; 2]; 3] = [[-170.0, 170.0], [-70.0, 70.0], [-65.0, 70.0]];
    const WIDE: [[f64; 2]; 3] = [[-720.0, 720.0]; 3];

    fn demand(ranges_deg: [[f64; 2]; 3], grid_deg: f64) -> Demand {
        Demand {
            ranges_deg,
            grid_deg,
            parts: 3,
            obstacles: 9,
            points: 6,
            searches: 1,
            fly_by: false,
        }
    }

    #[test]
    fn the_grid_is_counted_as_it_is_laid() {
        for (ranges, step) in [(IRB1400, 1.0), (IRB1400, 0.25), (IRB1400, 0.7), (WIDE, 3.0)] {
            let g = Grid::over(ranges, step);
            let dims = grid_dims(ranges, step);
            assert_eq!(dims.map(|d| d as usize), g.dims, "{step}");
        }
        // By hand: 341 x 141 x 136 at 1 deg; 1441^3 over -720..720.
        assert_eq!(grid_nodes(IRB1400, 1.0), 341 * 141 * 136);
        assert_eq!(grid_nodes(WIDE, 1.0), 1441u64.pow(3));
    }

    #[test]
    fn the_paper_cell_fits_at_every_accepted_grid_and_wide_ranges_do_not_at_a_fine_one() {
        for g in [0.25, 0.5, 1.0, 10.0] {
            assert_eq!(check(&demand(IRB1400, g)), Ok(()), "{g}");
        }
        // -720 .. 720 on axes 1..3: 2 881^3 = 23.9 G nodes at 0.5 deg (said as 24 G).
        let e = check(&demand(WIDE, 0.5)).expect_err("too many nodes");
        let Exceeded::GridNodes {
            nodes, finest_deg, ..
        } = &e
        else {
            panic!("{e}")
        };
        assert_eq!(*nodes, 2881u64.pow(3));
        // The finest step that fits: 500 M nodes is 793.7^3, so 1441 / 793.7 * 1 deg ~ 1.82.
        let finest: f64 = finest_deg.parse().expect("a step");
        assert!(grid_nodes(WIDE, finest) <= MAX_GRID_NODES, "{finest}");
        assert!(grid_nodes(WIDE, finest - 0.01) > MAX_GRID_NODES, "{finest}");
        assert!((1.75..1.9).contains(&finest), "{finest}");
        assert!(
            e.to_string().contains("24 G nodes (2881 x 2881 x 2881)"),
            "{e}"
        );
    }

    #[test]
    fn work_budgets_name_the_item_that_passes_them() {
        let mut d = demand(IRB1400, 0.5);
        d.obstacles = 4_000;
        let e = check(&d).expect_err("inspection");
        // 52 M nodes x 3 parts x (12 + k) > 2e11 from k = 1 271 on (index 1 270).
        let nodes = grid_nodes(IRB1400, 0.5);
        let first = (0..4_000u64)
            .find(|k| nodes * 3 * (12 + k + 1) > MAX_INSPECTION_WORK)
            .expect("passes");
        assert!(
            matches!(e, Exceeded::Inspection { at: Some(k), .. } if k as u64 == first),
            "{e}"
        );
        let mut d = demand(IRB1400, 0.25);
        d.points = 1_000;
        let e = check(&d).expect_err("legs");
        // 413 M nodes a leg at 0.25 deg: the first leg count past 6e10 leg-nodes passes.
        let nodes = grid_nodes(IRB1400, 0.25);
        let first = (1..1_000u64)
            .find(|k| k * nodes > MAX_LEG_WORK)
            .expect("passes");
        assert!((140..150).contains(&first), "{first}");
        assert!(
            matches!(e, Exceeded::Legs { at: Some(k), .. } if k as u64 == first),
            "{e}"
        );
        let mut d = demand(IRB1400, 0.5);
        d.fly_by = true;
        d.points = 200;
        // 199 legs x 2 > 240: at most 120 legs.
        assert!(matches!(
            check(&d),
            Err(Exceeded::ZonedLegs { allowed: 120, .. })
        ));
        d.grid_deg = 1.0;
        assert_eq!(check(&d), Ok(()));
    }
}
