//! Collinear merge: consecutive straight moves in the same direction become one move (paper
//! section 4.2, "merge the nodes in the same manipulation direction"). The merged move covers
//! exactly the configurations of the moves it replaces, so it is as safe as they were.

/// Removes every interior waypoint where the path goes on straight in the same direction.
/// Waypoints are controller values of axes 1..3 (deg); the first and last always stay.
pub fn collinear(path: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let mut out: Vec<[f64; 3]> = Vec::with_capacity(path.len());
    for &p in path {
        if out.len() >= 2 && same_direction(&out[out.len() - 2], &out[out.len() - 1], &p) {
            if let Some(last) = out.last_mut() {
                *last = p;
            }
        } else if out.last() != Some(&p) {
            out.push(p);
        }
    }
    if out.is_empty() {
        if let Some(&p) = path.first() {
            out.push(p);
        }
    }
    out
}

/// True when b - a and c - b point the same way (parallel, same sense).
fn same_direction(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> bool {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - b[0], c[1] - b[1], c[2] - b[2]];
    let cross = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let norm = |w: [f64; 3]| (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    let (nu, nv) = (norm(u), norm(v));
    dot > 0.0 && norm(cross) <= 1e-9 * nu * nv
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merges_runs_in_one_direction_only() {
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [3.0, 1.0, 0.0],
            [4.0, 2.0, 0.0],
            [4.0, 3.0, 0.0],
        ];
        assert_eq!(
            collinear(&p),
            vec![
                [0.0, 0.0, 0.0],
                [2.0, 0.0, 0.0],
                [4.0, 2.0, 0.0],
                [4.0, 3.0, 0.0]
            ]
        );
    }

    #[test]
    fn a_reversal_is_not_merged() {
        let p = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
        assert_eq!(collinear(&p).len(), 3);
    }

    #[test]
    fn parallel_steps_of_different_length_merge_and_duplicates_drop() {
        let p = [
            [0.0, 0.0, 0.0],
            [0.5, 0.5, 0.5],
            [0.5, 0.5, 0.5],
            [2.0, 2.0, 2.0],
        ];
        assert_eq!(collinear(&p), vec![[0.0, 0.0, 0.0], [2.0, 2.0, 2.0]]);
    }
}
