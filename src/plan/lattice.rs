//! The lattice of the configuration-space grid (paper section 3): nodes at integer multiples of
//! the spacing within the axis ranges, their indices and values (`cspace.rs` keeps their codes).

/// A grid node: indices along axes 1..3 (0-based within the grid).
pub type Node = [i32; 3];

/// The lattice: node `n` has controller values `(origin[k] + n[k]) * step_deg`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub step_deg: f64,
    /// Integer multiple of `step_deg` of the first node along each axis.
    pub origin: [i64; 3],
    pub dims: [usize; 3],
}

/// Largest grid a run makes (nodes; `budget::MAX_GRID_NODES`, checked before the grid is
/// made); 0.25 deg over the IRB 1400's ranges is 413 M.
pub const MAX_NODES: usize = crate::budget::MAX_GRID_NODES as usize;

impl Grid {
    /// The nodes k*step inside `[lo, hi]` of each axis (deg).
    pub fn over(ranges_deg: [[f64; 2]; 3], step_deg: f64) -> Grid {
        let mut origin = [0i64; 3];
        let mut dims = [0usize; 3];
        for k in 0..3 {
            let [lo, hi] = ranges_deg[k];
            let first = (lo / step_deg - 1e-9).ceil() as i64;
            let last = (hi / step_deg + 1e-9).floor() as i64;
            origin[k] = first;
            dims[k] = (last - first + 1).max(0) as usize;
        }
        Grid {
            step_deg,
            origin,
            dims,
        }
    }

    pub fn len(&self) -> usize {
        self.dims.iter().product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn contains(&self, n: Node) -> bool {
        (0..3).all(|k| n[k] >= 0 && (n[k] as usize) < self.dims[k])
    }

    /// Linear index; axis 3 varies fastest so a column (fixed axes 1, 2) is contiguous.
    #[inline]
    pub fn index(&self, n: Node) -> usize {
        (n[0] as usize * self.dims[1] + n[1] as usize) * self.dims[2] + n[2] as usize
    }

    #[inline]
    pub fn node(&self, i: usize) -> Node {
        let z = i % self.dims[2];
        let r = i / self.dims[2];
        [
            (r / self.dims[1]) as i32,
            (r % self.dims[1]) as i32,
            z as i32,
        ]
    }

    /// Controller value (deg) of index `i` along axis `k`.
    #[inline]
    pub fn value(&self, k: usize, i: i64) -> f64 {
        (self.origin[k] + i) as f64 * self.step_deg
    }

    /// Controller values of a node, deg.
    pub fn axes_deg(&self, n: Node) -> [f64; 3] {
        [
            self.value(0, n[0] as i64),
            self.value(1, n[1] as i64),
            self.value(2, n[2] as i64),
        ]
    }

    /// The node at `axes` if `axes` lies on the lattice (within 1e-9 deg) and in the grid.
    pub fn node_at(&self, axes: &[f64; 3]) -> Option<Node> {
        let mut n = [0i32; 3];
        for k in 0..3 {
            let f = axes[k] / self.step_deg;
            let r = f.round();
            if (f - r).abs() * self.step_deg > 1e-9 {
                return None;
            }
            n[k] = (r as i64 - self.origin[k]) as i32;
        }
        self.contains(n).then_some(n)
    }

    /// Grid nodes within `rings` cells of `axes` (Chebyshev), nearest first (Euclidean in
    /// degrees, ties by index): the candidates to join an off-grid point to the grid.
    pub fn nodes_near(&self, axes: &[f64; 3], rings: i32) -> Vec<Node> {
        let base: Vec<i64> = (0..3)
            .map(|k| (axes[k] / self.step_deg).floor() as i64 - self.origin[k])
            .collect();
        let mut out = Vec::new();
        for d0 in -rings + 1..=rings {
            for d1 in -rings + 1..=rings {
                for d2 in -rings + 1..=rings {
                    let n = [
                        (base[0] + d0 as i64) as i32,
                        (base[1] + d1 as i64) as i32,
                        (base[2] + d2 as i64) as i32,
                    ];
                    if self.contains(n) {
                        out.push(n);
                    }
                }
            }
        }
        let dist = |n: &Node| {
            let v = self.axes_deg(*n);
            (0..3).map(|k| (v[k] - axes[k]).powi(2)).sum::<f64>()
        };
        out.sort_by(|a, b| dist(a).total_cmp(&dist(b)).then(a.cmp(b)));
        out
    }
}
