//! Why `R` is empty: the diagnosis that names the culprits, from the simplest reason on. Two
//! points whose reach regions do not meet at all; points that meet pairwise but not all at once
//! (the shortest prefix of them that has no common position); or obstacles covering every
//! common position (the one that covers all of it, else every one that covers some).

use super::region::{common_bbox, rect_distance, Region};
use super::rings::{regions_meet, ReachRegion};
use super::{LocateError, MAX_CELLS};
use crate::cell::Obstacle;

/// The first two points whose reach regions do not meet, if any.
pub(super) fn disjoint(reach: &[ReachRegion]) -> Option<LocateError> {
    for (i, p) in reach.iter().enumerate() {
        for q in &reach[i + 1..] {
            if !regions_meet(p, q) {
                let d = (p.centre_mm[0] - q.centre_mm[0]).hypot(p.centre_mm[1] - q.centre_mm[1]);
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
pub(super) fn no_common(reach: &[ReachRegion], cell: f64) -> LocateError {
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
pub(super) fn blocked(
    reach: &[ReachRegion],
    region: &Region,
    blocking: &[Obstacle],
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
            for (k, o) in blocking.iter().enumerate() {
                let under = rect_distance(c, &o.aabb) < grow;
                covers_all[k] &= under;
                covers_some[k] |= under;
            }
        }
    }
    let obstacles: Vec<String> = match covers_all.iter().position(|&a| a) {
        Some(k) => vec![blocking[k].name.clone()],
        None => blocking
            .iter()
            .zip(&covers_some)
            .filter(|(_, &s)| s)
            .map(|(o, _)| o.name.clone())
            .collect(),
    };
    LocateError::Blocked {
        obstacles,
        common_area_mm2: reach_all as f64 * region.cell_mm * region.cell_mm,
        grow_mm: grow,
    }
}
