//! Robot location: where on the floor the robot's base may stand so that it reaches every working
//! point without standing on an obstacle.
//!
//! Stage: working points (wrist centres, cell frame) + obstacles -> a region of base positions
//! and one chosen base position. Paper: Ting & Jar (2006) section 2, eq. 1-2:
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
//! - **Raster.** `R` is sampled on square cells of `cell_mm` (default [`DEFAULT_CELL_MM`] =
//!   10 mm) over the intersection of the points' outer discs' bounding boxes (which contains
//!   `R`); a cell is in `R` iff its centre is (exact test, [`margin_at`]). Area = cells x cell^2.
//!   The raster's origin is snapped to a multiple of `cell_mm`, so with the default cell every
//!   cell centre, and so the chosen base, is a multiple of 5 mm: the module header's base
//!   (written to 0.1 mm) is exactly the base the joint values were computed from.
//! - **Choice of base.** The cell centre of `R` with the largest margin, the exact Euclidean
//!   distance from the centre to the boundary of the true `R` (min over the points of the
//!   distance to the ring edges, and over blocking obstacles of the distance to the grown
//!   footprint); ties within 1e-6 mm broken by the smallest `|x| + |y|`, then `x`, then `y`.
//!   The paper chooses its point E "via numerical analysis" without saying how; the largest
//!   margin is the position that tolerates the most placement error.
//! - **Yaw.** Only the position is chosen: the base's yaw stays what the cell gives (`robot.yaw`,
//!   default 0). The reach regions do not depend on it (axis 1 turns all the way round in this
//!   model), so `R` is the same for every yaw; the yaw matters to the axis-1 range and the
//!   collision checks, which the IK and the planner apply from the chosen base.

use crate::robot::ik::{reach_interval_mm, ArmGeometry};
use crate::robot::Robot;

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
    /// Obstacles: name, min corner, max corner (axis-aligned boxes).
    pub obstacles: &'a [(String, [f64; 3], [f64; 3])],
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

/// The base positions from which one point is reachable: rings around its top-view position.
#[derive(Clone, Debug, PartialEq)]
pub struct ReachRegion {
    pub name: String,
    /// Top-view position of the point, mm.
    pub centre_mm: [f64; 2],
    /// Smallest base distance that reaches the point (0: also from right under it), mm.
    pub inner_mm: f64,
    /// Largest base distance that reaches the point, mm.
    pub outer_mm: f64,
    /// The rings `[from, to]` of base distance, ascending and disjoint (usually one).
    pub rings_mm: Vec<[f64; 2]>,
}

impl ReachRegion {
    fn distance(&self, xy: [f64; 2]) -> f64 {
        (xy[0] - self.centre_mm[0]).hypot(xy[1] - self.centre_mm[1])
    }

    /// Whether a base at `xy` reaches the point (exact).
    pub fn contains(&self, xy: [f64; 2]) -> bool {
        let h = self.distance(xy);
        self.rings_mm.iter().any(|r| h >= r[0] && h <= r[1])
    }

    /// Distance from `xy` to the edge of the region if inside, `None` outside.
    pub fn margin(&self, xy: [f64; 2]) -> Option<f64> {
        let h = self.distance(xy);
        let r = self.rings_mm.iter().find(|r| h >= r[0] && h <= r[1])?;
        let inner = if r[0] > 0.0 { h - r[0] } else { f64::INFINITY };
        Some(inner.min(r[1] - h))
    }

    /// "ring 211.3 .. 1254.0 mm", "disc of radius 800.0 mm", or several joined by "and".
    pub fn describe(&self) -> String {
        self.rings_mm
            .iter()
            .map(|r| {
                if r[0] <= 0.0 {
                    format!("disc of radius {:.1} mm", r[1])
                } else {
                    format!("ring {:.1} .. {:.1} mm", r[0], r[1])
                }
            })
            .collect::<Vec<_>>()
            .join(" and ")
    }
}

/// The feasible region `R`, rastered.
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    pub cell_mm: f64,
    /// Lower-left corner of cell (0, 0), mm; cell (i, j) covers
    /// `origin + [i, i + 1] x [j, j + 1] * cell_mm`.
    pub origin: [f64; 2],
    pub nx: usize,
    pub ny: usize,
    /// Row-major: cell (i, j) at `j * nx + i` (rows run along x).
    pub inside: Vec<bool>,
    /// Inside cells x cell^2, mm^2.
    pub area_mm2: f64,
    /// Extent (min, max corners) of the inside cells, mm; `None` when empty.
    pub bbox: Option<([f64; 2], [f64; 2])>,
}

impl Region {
    /// Centre of cell (i, j), mm.
    pub fn cell_centre(&self, i: usize, j: usize) -> [f64; 2] {
        [
            self.origin[0] + (i as f64 + 0.5) * self.cell_mm,
            self.origin[1] + (j as f64 + 0.5) * self.cell_mm,
        ]
    }

    /// Whether the cell holding `xy` is inside (false outside the raster).
    pub fn contains(&self, xy: [f64; 2]) -> bool {
        let fi = ((xy[0] - self.origin[0]) / self.cell_mm).floor();
        let fj = ((xy[1] - self.origin[1]) / self.cell_mm).floor();
        if !(fi >= 0.0 && fj >= 0.0 && fi < self.nx as f64 && fj < self.ny as f64) {
            return false;
        }
        self.inside[fj as usize * self.nx + fi as usize]
    }
}

/// The result of [`locate`].
#[derive(Clone, Debug, PartialEq)]
pub struct Location {
    pub region: Region,
    /// The chosen base position (a cell centre of the region), mm.
    pub base_mm: [f64; 2],
    /// Exact distance from `base_mm` to the boundary of the true region, mm.
    pub margin_mm: f64,
    /// Per point, in input order.
    pub reach: Vec<ReachRegion>,
    /// Names of the obstacles whose z-range meets the base's (the others cannot block it).
    pub blocking_obstacles: Vec<String>,
    /// Their boxes (min, max corners, mm), in the same order.
    pub blocking_boxes_mm: Vec<([f64; 3], [f64; 3])>,
    /// How far a blocking obstacle's footprint is grown: base radius + clearance, mm.
    pub grow_mm: f64,
}

impl Location {
    /// Every inside cell centre of the raster with its exact margin, best first: the order in
    /// which base positions are tried (largest margin, then the smallest |x| + |y|, then x,
    /// then y: the rule that chose [`Location::base_mm`], which comes first).
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
        // The chosen base first, whatever the near-ties ([`TIE_MM`]) in the sort did.
        if let Some(k) = out.iter().position(|(c, _)| *c == self.base_mm) {
            let chosen = out.remove(k);
            out.insert(0, chosen);
        }
        out
    }

    /// Exact test of a base position against the true `R` (not the raster): the distance from
    /// `xy` to the boundary of `R` when `xy` lies in it, `None` when it does not. The same
    /// margin as [`Location::margin_mm`] for the chosen base.
    pub fn margin_at(&self, xy: [f64; 2]) -> Option<f64> {
        let mut margin = f64::INFINITY;
        for r in &self.reach {
            margin = margin.min(r.margin(xy)?);
        }
        for (lo, hi) in &self.blocking_boxes_mm {
            let m = rect_distance(xy, *lo, *hi) - self.grow_mm;
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
         {dz_mm:.1} mm {} the shoulder (base at z = {base_z_mm} mm), and the arm reaches at most \
         {max_mm:.1} mm from the shoulder",
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

/// The rings of base distance from which a point `dz` above the shoulder height is reachable
/// (see the module docs), merged and ascending. Empty when `|dz| > rho_max`.
pub fn reach_rings_mm(a1: f64, rho_min: f64, rho_max: f64, dz: f64) -> Vec<[f64; 2]> {
    let ro2 = rho_max * rho_max - dz * dz;
    if ro2 < 0.0 {
        return Vec::new();
    }
    let ro = ro2.sqrt();
    let ri = (rho_min * rho_min - dz * dz).max(0.0).sqrt();
    let mut iv: Vec<[f64; 2]> = [[a1 - ro, a1 - ri], [a1 + ri, a1 + ro], [ri - a1, ro - a1]]
        .into_iter()
        .filter_map(|[lo, hi]| {
            let lo = lo.max(0.0);
            (lo <= hi).then_some([lo, hi])
        })
        .collect();
    iv.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(iv.len());
    for r in iv {
        match out.last_mut() {
            Some(last) if r[0] <= last[1] => last[1] = last[1].max(r[1]),
            _ => out.push(r),
        }
    }
    out
}

/// Distance from a point to an axis-aligned rectangle (0 inside), mm.
fn rect_distance(xy: [f64; 2], min: [f64; 3], max: [f64; 3]) -> f64 {
    let dx = (min[0] - xy[0]).max(0.0).max(xy[0] - max[0]);
    let dy = (min[1] - xy[1]).max(0.0).max(xy[1] - max[1]);
    dx.hypot(dy)
}

/// Can the regions (unions of rings around two centres `d` apart) meet? Exact: rings
/// `[a, b]` and `[c, e]` meet iff `max(0, a - e, c - b) <= d <= b + e`.
fn regions_meet(p: &ReachRegion, q: &ReachRegion) -> bool {
    let d = (p.centre_mm[0] - q.centre_mm[0]).hypot(p.centre_mm[1] - q.centre_mm[1]);
    p.rings_mm.iter().any(|&[a, b]| {
        q.rings_mm
            .iter()
            .any(|&[c, e]| d <= b + e && d >= (a - e).max(c - b))
    })
}

/// Finds the region of base positions reaching every point clear of the obstacles, and the base
/// position with the largest margin in it (module docs for the rules).
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
    for (name, lo, hi) in input.obstacles {
        if !(lo.iter().chain(hi).all(|c| c.is_finite()) && (0..3).all(|k| lo[k] <= hi[k])) {
            return bad(format!(
                "obstacle {name}: min must be finite and not above max"
            ));
        }
    }

    // Reach region of every point.
    let g = input.geom;
    let (rho_min, rho_max) = reach_interval_mm(g);
    let shoulder_z = input.base_z_mm + g.d1_mm;
    let mut reach = Vec::with_capacity(input.points_mm.len());
    for (name, p) in input.points_mm {
        let dz = p[2] - shoulder_z;
        let rings = reach_rings_mm(g.a1_mm, rho_min, rho_max, dz);
        let (Some(first), Some(last)) = (rings.first(), rings.last()) else {
            return Err(LocateError::PointOutOfReach {
                name: name.clone(),
                dz_mm: dz,
                max_mm: rho_max,
                base_z_mm: input.base_z_mm,
            });
        };
        reach.push(ReachRegion {
            name: name.clone(),
            centre_mm: [p[0], p[1]],
            inner_mm: first[0],
            outer_mm: last[1],
            rings_mm: rings,
        });
    }

    let disjoint = || -> Option<LocateError> {
        for (i, p) in reach.iter().enumerate() {
            for q in &reach[i + 1..] {
                if !regions_meet(p, q) {
                    let d =
                        (p.centre_mm[0] - q.centre_mm[0]).hypot(p.centre_mm[1] - q.centre_mm[1]);
                    return Some(LocateError::Disjoint {
                        a: p.name.clone(),
                        b: q.name.clone(),
                        detail: format!(
                            "{} is reached from the {} around ({:.1}, {:.1}), {} from the {} \
                             around ({:.1}, {:.1}); the points are {d:.1} mm apart (top view)",
                            p.name,
                            p.describe(),
                            p.centre_mm[0],
                            p.centre_mm[1],
                            q.name,
                            q.describe(),
                            q.centre_mm[0],
                            q.centre_mm[1],
                        ),
                    });
                }
            }
        }
        None
    };

    // Raster over the intersection of the outer discs' bounding boxes.
    let Some((lo, hi)) = common_bbox(&reach) else {
        // Some two outer discs are apart, so the pairwise test names them.
        return Err(disjoint().unwrap_or_else(|| no_common(&reach, cell)));
    };
    // Snap the origin to the cell lattice (module docs, "Raster").
    let lo = lo.map(|v| (v / cell).floor() * cell);
    let nx = (((hi[0] - lo[0]) / cell).ceil() as usize).max(1);
    let ny = (((hi[1] - lo[1]) / cell).ceil() as usize).max(1);
    if nx.saturating_mul(ny) > MAX_CELLS {
        return bad(format!(
            "a {cell} mm raster over {:.0} x {:.0} mm needs {nx} x {ny} cells, more than {MAX_CELLS}; \
             use a larger cell",
            hi[0] - lo[0],
            hi[1] - lo[1]
        ));
    }
    let grow = input.base_radius_mm + input.clearance_mm;
    let base_top = input.base_z_mm + input.base_height_mm;
    let blocking: Vec<&(String, [f64; 3], [f64; 3])> = input
        .obstacles
        .iter()
        // Boxes the robot stands on (top at or below the mounting plane) do not block it, as in
        // `collision`; a box above the base's top blocks only within the clearance.
        .filter(|(_, lo, hi)| lo[2] < base_top + input.clearance_mm && hi[2] > input.base_z_mm)
        .collect();

    let mut region = Region {
        cell_mm: cell,
        origin: lo,
        nx,
        ny,
        inside: vec![false; nx * ny],
        area_mm2: 0.0,
        bbox: None,
    };
    let mut reach_all = 0usize; // cells reaching every point, obstacles ignored
    let mut best: Option<([f64; 2], f64)> = None;
    let mut count = 0usize;
    let (mut bmin, mut bmax) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for j in 0..ny {
        for i in 0..nx {
            let c = region.cell_centre(i, j);
            let mut margin = f64::INFINITY;
            let mut ok = true;
            for r in &reach {
                match r.margin(c) {
                    Some(m) => margin = margin.min(m),
                    None => {
                        ok = false;
                        break;
                    }
                }
            }
            if !ok {
                continue;
            }
            reach_all += 1;
            for (_, omin, omax) in &blocking {
                let m = rect_distance(c, *omin, *omax) - grow;
                if m < 0.0 {
                    ok = false;
                    break;
                }
                margin = margin.min(m);
            }
            if !ok {
                continue;
            }
            region.inside[j * nx + i] = true;
            count += 1;
            for k in 0..2 {
                bmin[k] = bmin[k].min(c[k] - 0.5 * cell);
                bmax[k] = bmax[k].max(c[k] + 0.5 * cell);
            }
            let better = match best {
                None => true,
                Some((b, bm)) => {
                    if margin > bm + TIE_MM {
                        true
                    } else if margin < bm - TIE_MM {
                        false
                    } else {
                        let key = |p: [f64; 2]| (p[0].abs() + p[1].abs(), p[0], p[1]);
                        let (kc, kb) = (key(c), key(b));
                        kc.0.total_cmp(&kb.0)
                            .then(kc.1.total_cmp(&kb.1))
                            .then(kc.2.total_cmp(&kb.2))
                            .is_lt()
                    }
                }
            };
            if better {
                best = Some((c, margin));
            }
        }
    }

    let Some((base_mm, margin_mm)) = best else {
        if let Some(e) = disjoint() {
            return Err(e);
        }
        if reach_all == 0 {
            return Err(no_common(&reach, cell));
        }
        return Err(blocked(&reach, &region, &blocking, grow, reach_all));
    };
    region.area_mm2 = count as f64 * cell * cell;
    region.bbox = Some((bmin, bmax));
    Ok(Location {
        region,
        base_mm,
        margin_mm,
        reach,
        blocking_obstacles: blocking.iter().map(|(n, _, _)| n.clone()).collect(),
        blocking_boxes_mm: blocking.iter().map(|(_, lo, hi)| (*lo, *hi)).collect(),
        grow_mm: grow,
    })
}

/// Intersection of the regions' outer discs' bounding boxes, `None` when empty.
fn common_bbox(reach: &[ReachRegion]) -> Option<([f64; 2], [f64; 2])> {
    let mut lo = [f64::NEG_INFINITY; 2];
    let mut hi = [f64::INFINITY; 2];
    for r in reach {
        for k in 0..2 {
            lo[k] = lo[k].max(r.centre_mm[k] - r.outer_mm);
            hi[k] = hi[k].min(r.centre_mm[k] + r.outer_mm);
        }
    }
    (lo[0] <= hi[0] && lo[1] <= hi[1]).then_some((lo, hi))
}

/// Whether some cell centre of a `cell` raster over their common bounding box lies in every
/// region (the raster the main search would use for exactly these points).
fn any_common_cell(reach: &[ReachRegion], cell: f64) -> bool {
    let Some((lo, hi)) = common_bbox(reach) else {
        return false;
    };
    // Diagnosis only: coarsen rather than refuse a raster above MAX_CELLS.
    let area = (hi[0] - lo[0] + cell) * (hi[1] - lo[1] + cell);
    let cell = cell.max((area / MAX_CELLS as f64).sqrt());
    let nx = (((hi[0] - lo[0]) / cell).ceil() as usize).max(1);
    let ny = (((hi[1] - lo[1]) / cell).ceil() as usize).max(1);
    (0..ny).any(|j| {
        (0..nx).any(|i| {
            let c = [
                lo[0] + (i as f64 + 0.5) * cell,
                lo[1] + (j as f64 + 0.5) * cell,
            ];
            reach.iter().all(|r| r.contains(c))
        })
    })
}

/// Every pair meets but not all at once: the shortest prefix whose common part misses the next.
fn no_common(reach: &[ReachRegion], cell: f64) -> LocateError {
    for k in 1..reach.len() {
        if !any_common_cell(&reach[..=k], cell) {
            return LocateError::NoCommon {
                first: reach[..k].iter().map(|r| r.name.clone()).collect(),
                next: reach[k].name.clone(),
                cell_mm: cell,
            };
        }
    }
    // Only reachable with a single point whose region holds no cell centre.
    LocateError::TooThin {
        names: reach.iter().map(|r| r.name.clone()).collect(),
        cell_mm: cell,
    }
}

/// The points' regions meet but obstacles cover the common part: which obstacles.
fn blocked(
    reach: &[ReachRegion],
    region: &Region,
    blocking: &[&(String, [f64; 3], [f64; 3])],
    grow: f64,
    reach_all: usize,
) -> LocateError {
    let mut covers_all = vec![true; blocking.len()];
    let mut covers_some = vec![false; blocking.len()];
    for j in 0..region.ny {
        for i in 0..region.nx {
            let c = region.cell_centre(i, j);
            if !reach.iter().all(|r| r.contains(c)) {
                continue;
            }
            for (k, (_, lo, hi)) in blocking.iter().enumerate() {
                let under = rect_distance(c, *lo, *hi) < grow;
                covers_all[k] &= under;
                covers_some[k] |= under;
            }
        }
    }
    let obstacles: Vec<String> = match covers_all.iter().position(|&a| a) {
        Some(k) => vec![blocking[k].0.clone()],
        None => blocking
            .iter()
            .zip(&covers_some)
            .filter(|(_, &s)| s)
            .map(|(o, _)| o.0.clone())
            .collect(),
    };
    LocateError::Blocked {
        obstacles,
        common_area_mm2: reach_all as f64 * region.cell_mm * region.cell_mm,
        grow_mm: grow,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::ik::{choose, forward};

    fn pts(v: &[(&str, [f64; 3])]) -> Vec<(String, [f64; 3])> {
        v.iter().map(|(n, p)| (n.to_string(), *p)).collect()
    }

    fn input<'a>(
        g: &'a ArmGeometry,
        points: &'a [(String, [f64; 3])],
        obstacles: &'a [(String, [f64; 3], [f64; 3])],
    ) -> LocateInput<'a> {
        LocateInput {
            geom: g,
            points_mm: points,
            obstacles,
            base_z_mm: 0.0,
            base_radius_mm: 350.0,
            base_height_mm: 650.0,
            clearance_mm: 20.0,
            cell_mm: DEFAULT_CELL_MM,
        }
    }

    #[test]
    fn rings_of_one_point() {
        // a1 150, rho 361 .. 1318, point 720 above the shoulder:
        // Ro = sqrt(1318^2 - 720^2), Ri = 0 (361 < 720) -> back stance covers 0 .. Ro - 150,
        // front 0 .. 150 + Ro: one disc.
        let ro = (1318.0f64.powi(2) - 720.0f64.powi(2)).sqrt();
        let r = reach_rings_mm(150.0, 361.0, 1318.0, 720.0);
        assert_eq!(r.len(), 1);
        assert!(
            r[0][0] == 0.0 && (r[0][1] - (150.0 + ro)).abs() < 1e-9,
            "{r:?}"
        );
        // At shoulder height: Ri = 361 -> back 211 .. 1168, front 511 .. 1468: ring 211 .. 1468.
        let r = reach_rings_mm(150.0, 361.0, 1318.0, 0.0);
        assert_eq!(r, vec![[211.0, 1468.0]]);
        // Thin interval, large a1: two rings (back 100 .. 200, front 700 .. 800).
        let r = reach_rings_mm(300.0, 400.0, 500.0, 0.0);
        assert_eq!(r, vec![[100.0, 200.0], [700.0, 800.0]]);
        // Too high.
        assert!(reach_rings_mm(150.0, 361.0, 1318.0, 1318.5).is_empty());
    }

    #[test]
    fn two_far_points_name_each_other() {
        let g = ArmGeometry::irb1400_nominal();
        let p = pts(&[
            ("near", [0.0, 0.0, 800.0]),
            ("A", [0.0, 500.0, 800.0]),
            ("far", [4000.0, 0.0, 800.0]),
        ]);
        let err = locate(&input(&g, &p, &[])).unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, LocateError::Disjoint { .. }), "{text}");
        assert!(text.contains("of near and far do not meet"), "{text}");
        assert!(text.contains("4000.0 mm apart"), "{text}");
    }

    #[test]
    fn one_point_gives_an_annulus() {
        let g = ArmGeometry::irb1400_nominal();
        // Shoulder height: Ri = |600 - L|, Ro = 600 + L; rings (Ri - a1) .. (Ro + a1).
        let l = (120.0f64.powi(2) + 720.0f64.powi(2)).sqrt();
        let (r_in, r_out) = (l - 600.0 - 150.0, 600.0 + l + 150.0);
        assert!(r_in < 0.0); // so the back stance reaches from right under it: a disc
        let p = pts(&[("P", [123.0, -45.0, 475.0])]);
        let loc = locate(&input(&g, &p, &[])).expect("a region");
        assert_eq!(loc.reach[0].inner_mm, 0.0);
        assert!((loc.reach[0].outer_mm - r_out).abs() < 1e-9);
        let exact = std::f64::consts::PI * r_out * r_out;
        assert!(
            (loc.region.area_mm2 - exact).abs() / exact < 0.005,
            "{} vs {exact}",
            loc.region.area_mm2
        );
        // A point 300 mm above the shoulder with the IRB 1400's real interval: a proper ring.
        let robot = Robot::irb1400();
        let g = ArmGeometry::from_robot(&robot).expect("ok");
        let (rmin, rmax) = reach_interval_mm(&g);
        let dz = 300.0;
        let ri = (rmin * rmin - dz * dz).sqrt() - 150.0;
        let ro = (rmax * rmax - dz * dz).sqrt() + 150.0;
        assert!(ri > 0.0);
        let p = pts(&[("Q", [0.0, 0.0, 475.0 + dz])]);
        let loc = locate(&input(&g, &p, &[])).expect("a region");
        assert!(
            (loc.reach[0].inner_mm - ri).abs() < 1e-9 && (loc.reach[0].outer_mm - ro).abs() < 1e-9
        );
        let exact = std::f64::consts::PI * (ro * ro - ri * ri);
        assert!(
            (loc.region.area_mm2 - exact).abs() / exact < 0.005,
            "{} vs {exact}",
            loc.region.area_mm2
        );
        // Largest margin: midway between the circles.
        let h = loc.base_mm[0].hypot(loc.base_mm[1]);
        assert!((h - 0.5 * (ri + ro)).abs() <= 10.0, "{h}");
        assert!(
            (loc.margin_mm - 0.5 * (ro - ri)).abs() <= 10.0,
            "{}",
            loc.margin_mm
        );
        assert!(loc.region.contains(loc.base_mm));
        assert!(!loc.region.contains([0.0, 0.0]) && !loc.region.contains([ro + 20.0, 0.0]));
    }

    #[test]
    fn obstacles_remove_area_and_the_base_keeps_clear() {
        let g = ArmGeometry::from_robot(&Robot::irb1400()).expect("ok");
        let p = pts(&[("P", [0.0, 0.0, 775.0]), ("Q", [600.0, 0.0, 775.0])]);
        let free = locate(&input(&g, &p, &[])).expect("free");
        let obs = vec![
            (
                "table".to_string(),
                [-400.0, -1500.0, 0.0],
                [1000.0, 300.0, 700.0],
            ),
            (
                "shelf".to_string(),
                [-2000.0, 500.0, 900.0],
                [2000.0, 2000.0, 1000.0],
            ), // above the base
        ];
        let loc = locate(&input(&g, &p, &obs)).expect("still room");
        assert!(loc.region.area_mm2 < free.region.area_mm2 - 1e5);
        assert_eq!(loc.blocking_obstacles, vec!["table".to_string()]);
        let grow = 350.0 + 20.0;
        let d = rect_distance(loc.base_mm, obs[0].1, obs[0].2);
        assert!(
            d >= grow,
            "base {:?} only {d} mm from the table",
            loc.base_mm
        );
        // No inside cell is under the grown table; the shelf (z 900 .. 1000) blocks nothing.
        for j in 0..loc.region.ny {
            for i in 0..loc.region.nx {
                if loc.region.inside[j * loc.region.nx + i] {
                    assert!(
                        rect_distance(loc.region.cell_centre(i, j), obs[0].1, obs[0].2) >= grow
                    );
                }
            }
        }
        // Margin is exact and never more than the distance to the grown table.
        assert!(loc.margin_mm <= d - grow + 1e-9);
        assert!(loc.reach.iter().all(|r| r.contains(loc.base_mm)));
    }

    #[test]
    fn an_obstacle_covering_everything_is_named() {
        let g = ArmGeometry::from_robot(&Robot::irb1400()).expect("ok");
        let p = pts(&[("P", [0.0, 0.0, 775.0]), ("Q", [300.0, 0.0, 775.0])]);
        let obs = vec![
            (
                "small".to_string(),
                [5000.0, 5000.0, 0.0],
                [5100.0, 5100.0, 100.0],
            ),
            (
                "slab".to_string(),
                [-3000.0, -3000.0, 0.0],
                [3000.0, 3000.0, 300.0],
            ),
        ];
        let err = locate(&input(&g, &p, &obs)).unwrap_err();
        let text = err.to_string();
        assert!(
            text.contains("every common position is under obstacle slab"),
            "{text}"
        );
        assert!(text.contains("370.0 mm"), "{text}");
        // A slab whose top is the base plane is the floor: it blocks nothing.
        let floor = vec![(
            "floor".to_string(),
            [-3000.0, -3000.0, -50.0],
            [3000.0, 3000.0, 0.0],
        )];
        assert!(locate(&input(&g, &p, &floor)).is_ok());
    }

    /// The paper's trunk (section 6 example): the IRB 1400 at (0, -850) turned by 90 deg,
    /// the six working points' wrist centres by forward kinematics from the paper's joint values.
    #[test]
    fn the_paper_trunk_contains_the_papers_base() {
        let robot = Robot::irb1400();
        let g = ArmGeometry::from_robot(&robot).expect("ok");
        let joints = [
            ("A", [90.0, 0.0, 0.0]),
            ("B", [30.0, 20.0, 10.0]),
            ("C", [25.0, 15.0, 10.0]),
            ("D", [-25.0, 15.0, 10.0]),
            ("E", [-30.0, 20.0, 10.0]),
            ("F", [-90.0, 0.0, 0.0]),
        ];
        let base = [0.0, -850.0];
        // Robot +x along cell +y: cell = base + Rz(90) robot.
        let to_cell = |w: [f64; 3]| [base[0] - w[1], base[1] + w[0], w[2]];
        let points: Vec<(String, [f64; 3])> = joints
            .iter()
            .map(|(n, a)| {
                let w = robot.wrist_centre(&[a[0], a[1], a[2], 0.0, 0.0, 0.0]);
                (n.to_string(), to_cell([w.x, w.y, w.z]))
            })
            .collect();
        // A at axis 1 = 90: wrist 870 mm to the robot's left = cell -x.
        assert!((points[0].1[0] + 870.0).abs() < 1e-9 && (points[0].1[1] + 850.0).abs() < 1e-9);
        // Trunk 1800 x 900 x 500 at the origin: floor and four walls.
        let o = |n: &str, lo: [f64; 3], hi: [f64; 3]| (n.to_string(), lo, hi);
        let obstacles = vec![
            o("trunk floor", [-900.0, -450.0, 0.0], [900.0, 450.0, 100.0]),
            o(
                "trunk front wall",
                [-900.0, -450.0, 0.0],
                [900.0, -400.0, 500.0],
            ),
            o(
                "trunk back wall",
                [-900.0, 400.0, 0.0],
                [900.0, 450.0, 500.0],
            ),
            o(
                "trunk left wall",
                [-900.0, -450.0, 0.0],
                [-850.0, 450.0, 500.0],
            ),
            o(
                "trunk right wall",
                [850.0, -450.0, 0.0],
                [900.0, 450.0, 500.0],
            ),
        ];
        let (radius, height) = base_cylinder_mm(&robot).expect("link_1 cylinder");
        assert_eq!((radius, height), (350.0, 650.0));
        let inp = LocateInput {
            geom: &g,
            points_mm: &points,
            obstacles: &obstacles,
            base_z_mm: 0.0,
            base_radius_mm: radius,
            base_height_mm: height,
            clearance_mm: 20.0,
            cell_mm: DEFAULT_CELL_MM,
        };
        let t = std::time::Instant::now();
        let loc = locate(&inp).expect("the paper found a location");
        let ms = t.elapsed().as_secs_f64() * 1e3;
        eprintln!(
            "trunk: {} x {} cells, area {:.0} mm^2, bbox {:?}, base {:?}, margin {:.1} mm, {ms:.2} ms",
            loc.region.nx, loc.region.ny, loc.region.area_mm2, loc.region.bbox, loc.base_mm, loc.margin_mm
        );
        assert!(loc.region.contains(base), "the paper's base is outside R");
        assert!(loc.reach.iter().all(|r| r.contains(base)));
        assert!(loc.reach.iter().all(|r| r.contains(loc.base_mm)));
        for (_, lo, hi) in &obstacles {
            assert!(rect_distance(loc.base_mm, *lo, *hi) >= radius + 20.0);
        }
        // From the chosen base (same yaw), every point has an in-range solution.
        for (n, p) in &points {
            let rel = [p[0] - loc.base_mm[0], p[1] - loc.base_mm[1], p[2]];
            let w = [rel[1], -rel[0], rel[2]]; // cell -> robot frame (yaw 90)
            let s = choose(&robot, &g, w, None, None, |_| true);
            assert!(s.is_ok(), "{n} from {:?}: {s:?}", loc.base_mm);
            if let Ok(s) = s {
                let back = forward(&g, s.axes_deg);
                assert!((back[0] - w[0]).abs() < 0.01 && (back[2] - w[2]).abs() < 0.01);
            }
        }
    }

    #[test]
    fn pairwise_meeting_but_no_common_part() {
        let g = ArmGeometry::irb1400_nominal();
        let (_, rmax) = reach_interval_mm(&g);
        let dz = 0.0;
        let ro = (rmax * rmax - dz * dz).sqrt() + 150.0; // disc radius at shoulder height
                                                         // Three discs at the corners of a triangle: every two overlap, all three do not.
        let s = 1.9 * ro; // side: pairs overlap (s < 2 ro), circumradius s / sqrt(3) > ro
        let p = pts(&[
            ("X", [0.0, 0.0, 475.0]),
            ("Y", [s, 0.0, 475.0]),
            ("Z", [0.5 * s, 0.866_025_403_8 * s, 475.0]),
        ]);
        let err = locate(&input(&g, &p, &[])).unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, LocateError::NoCommon { .. }), "{text}");
        assert!(
            text.contains("common region of X, Y has no position") && text.contains("region of Z"),
            "{text}"
        );
    }

    #[test]
    fn bad_input_is_refused() {
        let g = ArmGeometry::irb1400_nominal();
        let p = pts(&[("P", [0.0, 0.0, 800.0])]);
        let mut inp = input(&g, &p, &[]);
        inp.cell_mm = 0.0;
        assert!(matches!(locate(&inp), Err(LocateError::Input(_))));
        let high = pts(&[("sky", [0.0, 0.0, 5000.0])]);
        let err = locate(&input(&g, &high, &[])).unwrap_err().to_string();
        assert!(
            err.contains("point sky") && err.contains("4525.0 mm above"),
            "{err}"
        );
    }
}
