//! The raster of the feasible region `R` (paper eq. 1-2): every cell centre tested exactly
//! against the reach regions and the grown obstacle footprints, and the position of `R`
//! farthest from its edge.

use super::rings::ReachRegion;
use super::TIE_MM;
use crate::cell::Obstacle;
use crate::geometry::Aabb;

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

/// Distance from a point to a box's top-view rectangle (0 inside), mm.
pub(super) fn rect_distance(xy: [f64; 2], b: &Aabb) -> f64 {
    let dx = (b.min.x - xy[0]).max(0.0).max(xy[0] - b.max.x);
    let dy = (b.min.y - xy[1]).max(0.0).max(xy[1] - b.max.y);
    dx.hypot(dy)
}

/// Intersection of the regions' outer discs' bounding boxes, `None` when empty.
pub(super) fn common_bbox(reach: &[ReachRegion]) -> Option<([f64; 2], [f64; 2])> {
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

/// The result of [`scan`].
pub(super) struct Scan {
    pub region: Region,
    /// The inside cell centre with the largest margin, and that margin.
    pub best: Option<([f64; 2], f64)>,
    /// Cells whose centre reaches every point, obstacles ignored.
    pub reach_all: usize,
}

/// Tests every cell centre of an `nx` x `ny` raster of `cell` mm from `origin` against the reach
/// regions and the `blocking` footprints grown by `grow`; keeps the centre with the largest exact
/// margin (ties within [`TIE_MM`] to the smallest `|x| + |y|`, then `x`, then `y`).
pub(super) fn scan(
    reach: &[ReachRegion],
    blocking: &[Obstacle],
    grow: f64,
    origin: [f64; 2],
    [nx, ny]: [usize; 2],
    cell: f64,
) -> Scan {
    let mut region = Region {
        cell_mm: cell,
        origin,
        nx,
        ny,
        inside: vec![false; nx * ny],
        area_mm2: 0.0,
        bbox: None,
    };
    let mut reach_all = 0usize;
    let mut best: Option<([f64; 2], f64)> = None;
    let mut count = 0usize;
    let (mut bmin, mut bmax) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for j in 0..ny {
        for i in 0..nx {
            let c = region.cell_centre(i, j);
            let mut margin = f64::INFINITY;
            let mut ok = true;
            for r in reach {
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
            for o in blocking {
                let m = rect_distance(c, &o.aabb) - grow;
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
    if best.is_some() {
        region.area_mm2 = count as f64 * cell * cell;
        region.bbox = Some((bmin, bmax));
    }
    Scan {
        region,
        best,
        reach_all,
    }
}
