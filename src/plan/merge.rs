//! Collinear merge: consecutive straight moves in the same direction become one move (paper
//! section 4.2, "merge the nodes in the same manipulation direction").
//!
//! Waypoints carry all six axes; the merge looks at the direction of axes 1..3, the axes the
//! paper plans. Where the six axes go on straight (the wrist constant along the leg, or turning
//! in step with axes 1..3), the merged move covers exactly the configurations of the moves it
//! replaces, so it is as safe as they were. Elsewhere the wrists of a straight run of axes 1..3
//! are not on one line: the wrist schedule rounds each to 0.001 deg, and it holds the wrist
//! where the run lies before the leg's start or beyond its end (the projection clamped to
//! `[0, 1]`). There the merged move is a different six-axis move, taken only if `accept` (the
//! whole-move check) proves it; the waypoints left keep their scheduled wrists.

/// Removes every interior waypoint where the path goes on straight in the same direction.
/// Waypoints are controller values (deg) of any number of axes; the first and last always stay.
pub fn collinear<const N: usize>(path: &[[f64; N]]) -> Vec<[f64; N]> {
    collinear_proven(path, &mut |_, _| false)
}

/// [`collinear`] for six-axis waypoints: where axes 1..3 go on straight in the same direction,
/// the waypoint is dropped if all the axes are collinear, or if `accept(a, c)` proves the merged
/// move. Works for any `N` (for `N` <= 3 there is no wrist and `accept` is never asked).
pub fn collinear_proven<const N: usize>(
    path: &[[f64; N]],
    accept: &mut dyn FnMut(&[f64; N], &[f64; N]) -> bool,
) -> Vec<[f64; N]> {
    let mut out: Vec<[f64; N]> = Vec::with_capacity(path.len());
    for &p in path {
        let merged = out.len() >= 2 && {
            let (a, b) = (&out[out.len() - 2], &out[out.len() - 1]);
            let arm = |v: &[f64; N]| {
                std::array::from_fn::<f64, 3, _>(|k| v.get(k).copied().unwrap_or(0.0))
            };
            same_direction(&arm(a), &arm(b), &arm(&p))
                && match wrist_off_line(a, b, &p) {
                    Some(0.0) => true,
                    Some(_) => accept(a, &p),
                    None => false,
                }
        };
        if merged {
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

/// How far the wrist (axes 4..) of `b` lies from the straight line `a -> c` at `b`'s place along
/// axes 1..3 (the largest axis difference, deg): `Some(0.0)` when the six axes are collinear
/// (within the 1e-9 relative slack of the direction test); `None` when axes 1..3 do not move.
fn wrist_off_line<const N: usize>(a: &[f64; N], b: &[f64; N], c: &[f64; N]) -> Option<f64> {
    if N <= 3 {
        return Some(0.0);
    }
    let (ab, ac): (f64, f64) = (0..3).fold((0.0, 0.0), |(x, y), k| {
        (x + (b[k] - a[k]) * (c[k] - a[k]), y + (c[k] - a[k]).powi(2))
    });
    if ac <= 0.0 {
        return None;
    }
    let s = ab / ac;
    let off = (3..N)
        .map(|k| (b[k] - (a[k] + s * (c[k] - a[k]))).abs())
        .fold(0.0, f64::max);
    let scale = (0..N).map(|k| (c[k] - a[k]).abs()).fold(1.0, f64::max);
    Some(if off <= 1e-9 * scale { 0.0 } else { off })
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
    fn six_axes_merge_where_the_wrist_goes_along_and_only_proven_near_misses() {
        // The wrist turns in step with axes 1..3: one move.
        let p = [
            [0.0, 0.0, 0.0, 0.0, 10.0, 0.0],
            [1.0, 0.0, 0.0, 1.0, 10.0, 0.0],
            [2.0, 0.0, 0.0, 2.0, 10.0, 0.0],
        ];
        let mut asked = 0;
        assert_eq!(
            collinear_proven(&p, &mut |_, _| {
                asked += 1;
                false
            }),
            vec![p[0], p[2]]
        );
        assert_eq!(asked, 0, "exactly collinear: nothing to prove");
        // Rounded off the line by 0.001 deg: merged only when the merged move is proven.
        let q = [p[0], [1.0, 0.0, 0.0, 1.001, 10.0, 0.0], p[2]];
        assert_eq!(collinear_proven(&q, &mut |_, _| false).len(), 3);
        assert_eq!(collinear_proven(&q, &mut |_, _| true), vec![q[0], q[2]]);
        // Axes 1..3 straight, the wrist held and then turning (the schedule clamped before
        // the leg's start): merged only when proven.
        let r = [p[0], [1.0, 0.0, 0.0, 0.0, 10.0, 0.0], p[2]];
        assert_eq!(collinear_proven(&r, &mut |_, _| false).len(), 3);
        assert_eq!(collinear_proven(&r, &mut |_, _| true), vec![r[0], r[2]]);
        // Axes 1..3 turning back: never merged.
        let u = [p[0], p[2], [1.0, 0.0, 0.0, 1.0, 10.0, 0.0]];
        assert_eq!(collinear_proven(&u, &mut |_, _| true).len(), 3);
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
