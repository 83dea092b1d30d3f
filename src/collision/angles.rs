//! A slice's axis-3 values as the grid's runs read them (*Angles* in `block.rs`): the values,
//! their radians, sines and cosines, and every run's middle with its sine and cosine, made once
//! per slice so the columns take no `sin_cos` per node or run.

/// A slice's axis-3 values (deg, in the columns' order) with what the runs read of them: the
/// values in radians and their sines and cosines, and per run `lo..hi` the middle value
/// `mid_deg[lo + hi - 1]` (between `deg[(lo + hi - 1) / 2]` and `deg[(lo + hi) / 2]`, so inside
/// the run where the values ascend) with its sine and cosine. Made once per slice (`column.rs`),
/// so the columns take no `sin_cos` per node or run; the grid's are made once
/// (`GridCheck::angles`).
#[derive(Clone, Debug)]
pub struct Angles {
    pub deg: Vec<f64>,
    pub(super) rad: Vec<f64>,
    pub(super) sc: Vec<(f64, f64)>,
    pub(super) mid_deg: Vec<f64>,
    pub(super) mid_sc: Vec<(f64, f64)>,
    /// Whether `deg` ascends (the runs need it).
    pub ascending: bool,
}

impl Angles {
    pub fn new(a3_deg: &[f64]) -> Angles {
        let rad: Vec<f64> = a3_deg.iter().map(|v| v.to_radians()).collect();
        let mid_deg: Vec<f64> = (0..(2 * a3_deg.len()).saturating_sub(1))
            .map(|s| 0.5 * (a3_deg[s / 2] + a3_deg[s.div_ceil(2)]))
            .collect();
        Angles {
            deg: a3_deg.to_vec(),
            sc: rad.iter().map(|q| q.sin_cos()).collect(),
            mid_sc: mid_deg.iter().map(|v| v.to_radians().sin_cos()).collect(),
            rad,
            mid_deg,
            ascending: ascending(a3_deg),
        }
    }
}

/// Whether `v` is in ascending order (the runs need it).
#[inline]
fn ascending(v: &[f64]) -> bool {
    v.windows(2).all(|w| w[0] <= w[1])
}
