//! Robot location: where on the floor the robot's base may stand so that it reaches every working
//! point without standing on an obstacle.
//!
//! Part of the place stage: working points (wrist centres, cell frame) + obstacles -> the region
//! of base positions, rastered, and its positions ranked for the place stage, which takes the
//! first from which every point is solved (`place`: one rule for where the robot stands).
//! Paper: Ting & Jar (2006) section 2, eq. 1-2:
//! `R = ∩_P (R_P ∩ ∩_i not O_i)`, with `R_P` the base positions from which point `P` is
//! reachable (the "bigger circles", arm stretched, and "smaller circles", arm withdrawn, of their
//! Figure 1) and `O_i` the obstruction area of obstacle `i`.
//!
//! Readings chosen where the paper is vague:
//! - **Top view only.** Base positions `(bx, by)` at a fixed base height `z_b` (the paper also
//!   mentions tests in the Y-Z and Z-X planes "not addressed in detail"; the height enters here
//!   through `dz`).
//! - **Reach region of one point.** With `h` the horizontal distance from the base to `P`,
//!   `dz = P_z - (z_b + d1)` and the shoulder-to-wrist interval `[rho_min, rho_max]` of
//!   [`reach_interval_mm`], `P` is reachable iff
//!   `rho_min <= sqrt((h - a1)^2 + dz^2) <= rho_max` (front stance) or the same with `h + a1`
//!   (back stance, axis 1 half a turn round). With `Ro = sqrt(rho_max^2 - dz^2)` and
//!   `Ri = sqrt(max(0, rho_min^2 - dz^2))` this is
//!   `h ∈ [a1 - Ro, a1 - Ri] ∪ [a1 + Ri, a1 + Ro] ∪ [Ri - a1, Ro - a1]`, clipped to `h >= 0`:
//!   a union of rings around `P`'s top-view position (usually one ring
//!   `max(0, Ri - a1) .. a1 + Ro`; two when `Ro - Ri < 2 a1`; empty when `|dz| > rho_max`).
//!   The inner radius is 0 when `Ri <= a1` (the back stance reaches over the base). The paper's
//!   bigger circle is `a1 + Ro`, its smaller circle `Ri - a1`.
//! - **Outer bound.** The axis-1 range (+-170 deg on the IRB 1400) is ignored: any direction
//!   is taken as reachable. `[rho_min, rho_max]` respects the angle between the arms that the
//!   controller allows but not the axis-2 range. Reach regions are therefore outer bounds; the
//!   plan still checks every pose against the ranges.
//! - **Obstacles.** An obstacle (axis-aligned box) blocks base positions only if its z-range
//!   overlaps the base cylinder's, `z_b .. z_b + base_height` (open overlap: a floor slab whose
//!   top is at `z_b` does not block). A blocking obstacle's top-view rectangle grown by the base
//!   radius plus the clearance (a rounded rectangle, the exact Minkowski sum) is removed: a base
//!   exactly at that distance is allowed. Obstacles that could hit the arm, not the base, are the
//!   planner's business, not this stage's.
//! - **The tool.** `R` is the same with or without a tool, and that is what is sound: the
//!   footprint test is about the base cylinder, which no tool shape is part of (the tool hangs on
//!   the flange), and whether the tool keeps the clearance at a point depends on the joint
//!   solution taken there, which `R` does not know. Removing base positions for the tool would
//!   need a claim about every solution from every position, which this stage cannot make; so `R`
//!   stays an outer bound and the tool is checked where the solutions are known: the place stage
//!   takes `R`'s positions in their ranking and keeps the first from which every point has a
//!   solution whose links *and tool shapes* keep the clearance (`PoseCheck`, the collision model
//!   with the cell's tool on the flange). A position where only the tool hits is passed over
//!   there, not cut out of `R`; `gen-rapid locate` draws `R` as this stage finds it.
//! - **Raster.** `R` is sampled on square cells of `cell_mm` (default [`DEFAULT_CELL_MM`] =
//!   10 mm) over the intersection of the points' outer discs' bounding boxes (which contains
//!   `R`); a cell is in `R` iff its centre is (exact test, [`Location::margin_at`]). Area = cells x cell^2.
//!   The raster's origin is snapped to a multiple of `cell_mm`, so with the default cell every
//!   cell centre, and so a chosen base, is a multiple of 5 mm: the module header's base
//!   (written to 0.1 mm) is exactly the base the joint values were computed from.
//! - **Ranking of positions.** First the cell centre of `R` with the largest margin (the
//!   position [`Location::best_mm`]), the exact Euclidean
//!   distance from the centre to the boundary of the true `R` (min over the points of the
//!   distance to the ring edges, and over blocking obstacles of the distance to the grown
//!   footprint); ties within 1e-6 mm broken by the smallest `|x| + |y|`, then `x`, then `y`.
//!   The paper chooses its point E "via numerical analysis" without saying how; the largest
//!   margin is the position that tolerates the most placement error. Then the other cell centres,
//!   by margin ([`Location::candidates`]).
//! - **Yaw.** Only the position is chosen: the base's yaw stays what the cell gives (`robot.yaw`,
//!   default 0). The reach regions do not depend on it (axis 1 turns all the way round in this
//!   model), so `R` is the same for every yaw; the yaw matters to the axis-1 range and the
//!   collision checks, which the IK and the planner apply from the chosen base.
//!
//! Files: [`rings`] (one point's reach region), [`region`] (the raster and its best position),
//! `diagnose.rs` (why `R` is empty).

mod diagnose;
pub mod region;
pub mod rings;

pub use region::Region;
pub use rings::{reach_rings_mm, ReachRegion};

use crate::cell::Obstacle;
use crate::robot::ik::{reach_interval_mm, ArmGeometry};
use crate::robot::Robot;
use region::rect_distance;

/// Default raster cell, mm: a tenth of the IRB 1400's base radius, fine against the reach
/// (about 1.3 m) and a few 10^4 cells for a typical cell.
pub const DEFAULT_CELL_MM: f64 = 10.0;
/// Largest raster accepted (cells).
pub const MAX_CELLS: usize = 25_000_000;
/// Margin ties closer than this are broken by position, mm.
const TIE_MM: f64 = 1e-6;

/// What [`locate`] needs. Positions in the cell frame, mm.
#[derive(Clone, Debug)]
pub struct LocateInput<'a> {
    pub geom: &'a ArmGeometry,
    /// Working points: name and wrist-centre position.
    pub points_mm: &'a [(String, [f64; 3])],
    /// The cell's obstacles.
    pub obstacles: &'a [Obstacle],
    /// Height of the base mounting plane.
    pub base_z_mm: f64,
    /// Radius of the base's footprint (the link-1 cylinder, see [`base_cylinder_mm`]).
    pub base_radius_mm: f64,
    /// Height of the base cylinder above the mounting plane.
    pub base_height_mm: f64,
    /// Extra distance kept between the base cylinder and obstacle footprints (eq. 2's `O`).
    pub clearance_mm: f64,
    /// Raster cell size ([`DEFAULT_CELL_MM`]).
    pub cell_mm: f64,
}

/// The result of [`locate`]: the feasible region `R` and its positions ranked.
#[derive(Clone, Debug, PartialEq)]
pub struct Location {
    pub region: Region,
    /// The position of `R` with the largest margin (a cell centre of the raster), mm: the first
    /// of [`Location::candidates`].
    pub best_mm: [f64; 2],
    /// Exact distance from `best_mm` to the boundary of the true region, mm.
    pub best_margin_mm: f64,
    /// Per point, in input order.
    pub reach: Vec<ReachRegion>,
    /// The obstacles whose z-range meets the base's (the others cannot block it).
    pub blocking: Vec<Obstacle>,
    /// How far a blocking obstacle's footprint is grown: base radius + clearance, mm.
    pub grow_mm: f64,
}

impl Location {
    /// Every inside cell centre of the raster with its exact margin, best first: the order in
    /// which base positions are tried (largest margin, then the smallest |x| + |y|, then x,
    /// then y: the rule that ranked [`Location::best_mm`], which comes first).
    pub fn candidates(&self) -> Vec<([f64; 2], f64)> {
        let r = &self.region;
        let mut out: Vec<([f64; 2], f64)> = (0..r.ny)
            .flat_map(|j| (0..r.nx).map(move |i| (i, j)))
            .filter(|&(i, j)| r.inside[j * r.nx + i])
            .filter_map(|(i, j)| {
                let c = r.cell_centre(i, j);
                self.margin_at(c).map(|m| (c, m))
            })
            .collect();
        out.sort_by(|a, b| {
            b.1.total_cmp(&a.1)
                .then((a.0[0].abs() + a.0[1].abs()).total_cmp(&(b.0[0].abs() + b.0[1].abs())))
                .then(a.0[0].total_cmp(&b.0[0]))
                .then(a.0[1].total_cmp(&b.0[1]))
        });
        // The best position first, whatever the near-ties ([`TIE_MM`]) in the sort did.
        if let Some(k) = out.iter().position(|(c, _)| *c == self.best_mm) {
            let best = out.remove(k);
            out.insert(0, best);
        }
        out
    }

    /// Exact test of a base position against the true `R` (not the raster): the distance from
    /// `xy` to the boundary of `R` when `xy` lies in it, `None` when it does not. The same
    /// margin as [`Location::best_margin_mm`] for the best position.
    pub fn margin_at(&self, xy: [f64; 2]) -> Option<f64> {
        let mut margin = f64::INFINITY;
        for r in &self.reach {
            margin = margin.min(r.margin(xy)?);
        }
        for o in &self.blocking {
            let m = rect_distance(xy, &o.aabb) - self.grow_mm;
            if m < 0.0 {
                return None;
            }
            margin = margin.min(m);
        }
        Some(margin)
    }
}

/// Why no location was found.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LocateError {
    #[error("robot location: {0}")]
    Input(String),
    #[error(
        "robot location: point {name} is out of reach from any base position: it is \
         {:.1} mm {} the shoulder (base at z = {base_z_mm} mm), and the arm reaches at most \
         {max_mm:.1} mm from the shoulder",
        .dz_mm.abs(),
        if *.dz_mm >= 0.0 { "above" } else { "below" }
    )]
    PointOutOfReach {
        name: String,
        dz_mm: f64,
        max_mm: f64,
        base_z_mm: f64,
    },
    #[error("robot location: the reach regions of {a} and {b} do not meet: {detail}")]
    Disjoint {
        a: String,
        b: String,
        detail: String,
    },
    #[error(
        "robot location: every two reach regions meet, but the common region of {} has no \
         position (sampled every {cell_mm} mm) in the region of {next}",
        .first.join(", ")
    )]
    NoCommon {
        first: Vec<String>,
        next: String,
        cell_mm: f64,
    },
    #[error(
        "robot location: the region of {} holds no cell centre at {cell_mm} mm spacing; use a \
         smaller cell",
        .names.join(", ")
    )]
    TooThin { names: Vec<String>, cell_mm: f64 },
    /// R is not empty, but from none of its positions does every point have a solution within the
    /// axis ranges and free of collision (the reach regions ignore the axis-2 and -3 ranges).
    #[error(
        "robot location: R holds {candidates} base positions, but from none of them does every \
         point have a solution in range and free of collision; from the best one, [{:.1}, {:.1}]: \
         {first}",
        .best_mm[0],
        .best_mm[1]
    )]
    NoReachableBase {
        candidates: usize,
        best_mm: [f64; 2],
        first: String,
    },
    #[error(
        "robot location: the reach regions of all points meet ({common_area_mm2:.0} mm^2), but \
         {} (footprints grown by base radius + clearance = {grow_mm:.1} mm)",
        if .obstacles.len() == 1 {
            format!("every common position is under obstacle {}", .obstacles[0])
        } else {
            format!("the obstacles {} together cover every common position", .obstacles.join(", "))
        }
    )]
    Blocked {
        obstacles: Vec<String>,
        common_area_mm2: f64,
        grow_mm: f64,
    },
}

/// Radius and height (above the base mounting plane) of the base footprint: the collision
/// cylinder(s) of link 1 (`joint_index` 0), swept round axis 1. A vertical cylinder off the axis
/// adds its offset to the radius; a tilted one is bounded by its end points' offsets plus its
/// radius, and its top by the higher end plus its radius. `None` when link 1 has no cylinder.
pub fn base_cylinder_mm(robot: &Robot) -> Option<(f64, f64)> {
    let z0 = robot
        .joints
        .first()
        .map_or(0.0, |j| j.origin.translation.vector.z);
    let mut out: Option<(f64, f64)> = None;
    for c in robot.cylinders.iter().filter(|c| c.joint_index == 0) {
        let off = c.a.x.hypot(c.a.y).max(c.b.x.hypot(c.b.y));
        let vertical = (c.a.x - c.b.x).hypot(c.a.y - c.b.y) < 1e-6;
        let top = c.a.z.max(c.b.z) + if vertical { 0.0 } else { c.radius_mm };
        let (r, h) = (off + c.radius_mm, z0 + top);
        out = Some(match out {
            Some((r0, h0)) => (r0.max(r), h0.max(h)),
            None => (r, h),
        });
    }
    out
}

/// Finds the region of base positions reaching every point clear of the obstacles, and its
/// position with the largest margin (module docs for the rules).
pub fn locate(input: &LocateInput) -> Result<Location, LocateError> {
    let bad = |m: String| Err(LocateError::Input(m));
    let cell = input.cell_mm;
    if !(cell.is_finite() && cell > 0.0) {
        return bad(format!(
            "cell size must be a positive number of mm, got {cell}"
        ));
    }
    for (what, v) in [
        ("base_z", input.base_z_mm),
        ("base_radius", input.base_radius_mm),
        ("base_height", input.base_height_mm),
        ("clearance", input.clearance_mm),
    ] {
        if !v.is_finite() || (what != "base_z" && v < 0.0) {
            return bad(format!(
                "{what} must be a finite, non-negative number of mm, got {v}"
            ));
        }
    }
    if input.points_mm.is_empty() {
        return bad("no working points to reach".into());
    }
    for (name, p) in input.points_mm {
        if !p.iter().all(|c| c.is_finite()) {
            return bad(format!("point {name} has a non-finite coordinate"));
        }
    }
    for o in input.obstacles {
        let (lo, hi) = (o.aabb.min, o.aabb.max);
        if !(lo.iter().chain(hi.iter()).all(|c| c.is_finite()) && (0..3).all(|k| lo[k] <= hi[k])) {
            return bad(format!(
                "obstacle {}: min must be finite and not above max",
                o.name
            ));
        }
    }

    // Reach region of every point.
    let mut reach = Vec::with_capacity(input.points_mm.len());
    for (name, p) in input.points_mm {
        let r = reach_region(input, name, p);
        if r.rings_mm.is_empty() {
            let (dz_mm, max_mm) = reach_from_shoulder(input, p);
            return Err(LocateError::PointOutOfReach {
                name: name.clone(),
                dz_mm,
                max_mm,
                base_z_mm: input.base_z_mm,
            });
        }
        reach.push(r);
    }

    // Raster over the intersection of the outer discs' bounding boxes.
    let Some((lo, hi)) = region::common_bbox(&reach) else {
        // Some two outer discs are apart, so the pairwise test names them.
        return Err(diagnose::disjoint(&reach).unwrap_or_else(|| diagnose::no_common(&reach, cell)));
    };
    let (lo, [nx, ny]) = raster(lo, hi, cell);
    if nx.saturating_mul(ny) > MAX_CELLS {
        return bad(format!(
            "a {cell} mm raster over {:.0} x {:.0} mm needs {nx} x {ny} cells, more than {MAX_CELLS}; \
             use a larger cell",
            hi[0] - lo[0],
            hi[1] - lo[1]
        ));
    }
    let (blocking, grow) = blocking(input);

    let scan = region::scan(&reach, &blocking, grow, lo, [nx, ny], cell);
    let Some((best_mm, best_margin_mm)) = scan.best else {
        if let Some(e) = diagnose::disjoint(&reach) {
            return Err(e);
        }
        if scan.reach_all == 0 {
            return Err(diagnose::no_common(&reach, cell));
        }
        return Err(diagnose::blocked(
            &reach,
            &scan.region,
            &blocking,
            grow,
            scan.reach_all,
        ));
    };
    Ok(Location {
        region: scan.region,
        best_mm,
        best_margin_mm,
        reach,
        blocking,
        grow_mm: grow,
    })
}

/// One point's reach region (no rings: out of reach from any base at this height).
fn reach_region(input: &LocateInput, name: &str, p: &[f64; 3]) -> ReachRegion {
    let g = input.geom;
    let (rho_min, rho_max) = reach_interval_mm(g);
    let (dz, _) = reach_from_shoulder(input, p);
    let rings = reach_rings_mm(g.a1_mm, rho_min, rho_max, dz);
    ReachRegion {
        name: name.to_string(),
        centre_mm: [p[0], p[1]],
        inner_mm: rings.first().map_or(0.0, |r| r[0]),
        outer_mm: rings.last().map_or(0.0, |r| r[1]),
        rings_mm: rings,
    }
}

/// A point's height above the shoulder and the arm's largest reach from it, mm.
fn reach_from_shoulder(input: &LocateInput, p: &[f64; 3]) -> (f64, f64) {
    let g = input.geom;
    let (_, rho_max) = reach_interval_mm(g);
    (p[2] - (input.base_z_mm + g.d1_mm), rho_max)
}

/// The obstacles that can block the base, and how far their footprints grow (base radius +
/// clearance).
fn blocking(input: &LocateInput) -> (Vec<Obstacle>, f64) {
    let grow = input.base_radius_mm + input.clearance_mm;
    let base_top = input.base_z_mm + input.base_height_mm;
    let blocking = input
        .obstacles
        .iter()
        // Boxes the robot stands on (top at or below the mounting plane) do not block it, as in
        // `collision`; a box above the base's top blocks only within the clearance.
        .filter(|o| o.aabb.min.z < base_top + input.clearance_mm && o.aabb.max.z > input.base_z_mm)
        .cloned()
        .collect();
    (blocking, grow)
}

/// The raster over `lo .. hi` at `cell`: its origin, snapped to the cell lattice (module docs,
/// "Raster"), and its size in cells.
fn raster(lo: [f64; 2], hi: [f64; 2], cell: f64) -> ([f64; 2], [usize; 2]) {
    let lo = lo.map(|v| (v / cell).floor() * cell);
    let nx = (((hi[0] - lo[0]) / cell).ceil() as usize).max(1);
    let ny = (((hi[1] - lo[1]) / cell).ceil() as usize).max(1);
    (lo, [nx, ny])
}

/// What can be drawn of the location problem whatever its outcome (the top view of a failure):
/// every point's reach region, the obstacles that can block the base and how far their
/// footprints grow, and R where it is not empty. Computed by the rules of [`locate`].
#[derive(Clone, Debug, PartialEq)]
pub struct Sketch {
    /// The points, by name with their wrist centres (cell frame), as given.
    pub points: Vec<(String, [f64; 3])>,
    /// Per point, in input order; no rings: the point is out of reach from any base.
    pub reach: Vec<ReachRegion>,
    pub blocking: Vec<Obstacle>,
    pub grow_mm: f64,
    /// R, when it holds a position.
    pub region: Option<Region>,
}

/// The [`Sketch`] of a location problem (for a picture of why [`locate`] failed; it does not
/// fail itself: what cannot be computed is left out).
pub fn sketch(input: &LocateInput) -> Sketch {
    let reach: Vec<ReachRegion> = input
        .points_mm
        .iter()
        .map(|(name, p)| reach_region(input, name, p))
        .collect();
    let (blocking, grow_mm) = blocking(input);
    let cell = input.cell_mm;
    let reachable = reach.iter().all(|r| !r.rings_mm.is_empty());
    let region = region::common_bbox(&reach)
        .filter(|_| reachable && cell.is_finite() && cell > 0.0)
        .map(|(lo, hi)| (raster(lo, hi, cell), hi))
        .filter(|((_, [nx, ny]), _)| nx.saturating_mul(*ny) <= MAX_CELLS)
        .map(|((lo, n), _)| region::scan(&reach, &blocking, grow_mm, lo, n, cell).region)
        .filter(|r| r.area_mm2 > 0.0);
    Sketch {
        points: input.points_mm.to_vec(),
        reach,
        blocking,
        grow_mm,
        region,
    }
}

#[cfg(test)]
mod tests;
