//! Reach regions (paper section 2, Fig. 1): the base positions from which one working point is
//! reachable, as rings of base distance around the point's top-view position (the "bigger" and
//! "smaller circles" of the paper; how they follow from the arm is in the module docs of
//! [`super`]).

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

/// Can the regions (unions of rings around two centres `d` apart) meet? Exact: rings
/// `[a, b]` and `[c, e]` meet iff `max(0, a - e, c - b) <= d <= b + e`.
pub(super) fn regions_meet(p: &ReachRegion, q: &ReachRegion) -> bool {
    let d = (p.centre_mm[0] - q.centre_mm[0]).hypot(p.centre_mm[1] - q.centre_mm[1]);
    p.rings_mm.iter().any(|&[a, b]| {
        q.rings_mm
            .iter()
            .any(|&[c, e]| d <= b + e && d >= (a - e).max(c - b))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
