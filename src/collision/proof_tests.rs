//! The whole-move proof and the certification, which take their decisions on distances known
//! only as well as each needs (`geometry::Measured`), against the same bisections written on
//! the distances themselves (`Solid::distance_aabb` at every point): the same verdicts, the
//! same failure points and the same certified figures, bit for bit, on random moves of a torch
//! through the trunk (link cylinders, a tool cylinder, a box and a ball). And the memo of
//! proven moves: a move proven twice is proven once.

use super::proof::{interval_bound, lerp, lowered, MAX_EVALS_PER_PAIR, MOVE_FLOOR_MM};
use super::tool_tests::{random_six, torch_model};
use super::*;
use crate::geometry::testing::Rng;

/// The distance from part `p` to box `k` at `axes`, as `Solid::distance_aabb` gives it.
fn exact(model: &CollisionModel, p: usize, k: usize, axes: &[f64; 6]) -> f64 {
    let poses = model.poses_for(axes, model.is_tool_part(p));
    model
        .solid(p, &poses)
        .distance_aabb(&model.obstacles[k].aabb)
}

/// The bisection of one pair on exact distances: `None` when it proves the pair, else the
/// failure `(t, d)` (the earliest with `earliest`).
fn reference_pair(
    model: &CollisionModel,
    (p, k): (usize, usize),
    (from, to): (&[f64; 6], &[f64; 6]),
    m: f64,
    c: f64,
    earliest: bool,
) -> Option<(f64, f64)> {
    let at = |t: f64| exact(model, p, k, &lerp(from, to, t));
    let (d0, d1) = (at(0.0), at(1.0));
    if lowered(d0) < c {
        return Some((0.0, d0));
    }
    let mut best = None;
    if lowered(d1) < c {
        if !earliest {
            return Some((1.0, d1));
        }
        best = Some((1.0, d1));
    }
    let mut stack = vec![(0.0f64, 1.0f64, d0, d1)];
    let mut evals = 0;
    while let Some((t0, t1, d0, d1)) = stack.pop() {
        if best.is_some_and(|(tb, _): (f64, f64)| t0 >= tb) {
            continue;
        }
        let reach = m * (t1 - t0);
        let lb = interval_bound(d0, d1, reach);
        if lb >= c {
            continue;
        }
        let tm = 0.5 * (t0 + t1);
        if reach < MOVE_FLOOR_MM || evals >= MAX_EVALS_PER_PAIR || stack.len() + 2 > 64 {
            return Some(if lowered(d1) < c { (t1, d1) } else { (tm, lb) });
        }
        let dm = at(tm);
        evals += 1;
        if lowered(dm) < c {
            if !earliest {
                return Some((tm, dm));
            }
            best = Some((tm, dm));
            stack.push((t0, tm, d0, dm));
            continue;
        }
        stack.push((tm, t1, dm, d1));
        stack.push((t0, tm, d0, dm));
    }
    best
}

/// `min_clearance_along` on exact distances: `(mm, part, box)`.
fn reference_min(
    model: &CollisionModel,
    from: &[f64; 6],
    to: &[f64; 6],
    tol: f64,
) -> Option<(f64, usize, usize)> {
    let speeds = model.part_speeds(from, to);
    let mut upper = (f64::INFINITY, None);
    for p in 0..model.part_count() {
        for axes in [from, to] {
            for (k, _) in model.part_boxes(p) {
                let d = exact(model, p, k, axes);
                if d < upper.0 {
                    upper = (d, Some((p, k)));
                }
            }
        }
    }
    let mut result = f64::INFINITY;
    for (p, &m) in speeds.iter().enumerate() {
        for (k, _) in model.part_boxes(p) {
            let at = |t: f64| exact(model, p, k, &lerp(from, to, t));
            let mut evals = 0;
            let mut stack = vec![(0.0f64, 1.0f64, at(0.0), at(1.0))];
            while let Some((t0, t1, d0, d1)) = stack.pop() {
                let reach = m * (t1 - t0);
                let raw = (0.5 * (d0 + d1 - reach)).min(d0).min(d1);
                if raw >= upper.0 - tol || evals >= MAX_EVALS_PER_PAIR {
                    result = result.min(interval_bound(d0, d1, reach));
                    continue;
                }
                let tm = 0.5 * (t0 + t1);
                let dm = at(tm);
                evals += 1;
                if dm < upper.0 {
                    upper = (dm, Some((p, k)));
                }
                stack.push((tm, t1, dm, d1));
                stack.push((t0, tm, d0, dm));
            }
        }
    }
    let (p, k) = upper.1?;
    Some((result.min(upper.0).max(0.0), p, k))
}

/// Random moves of the torch model, most of them passing near a box (where the bisections go
/// deep and the bounds must be narrowed).
fn near_moves(rng: &mut Rng, model: &CollisionModel, count: usize) -> Vec<([f64; 6], [f64; 6])> {
    let robot = Robot::irb1400();
    let mut out = Vec::new();
    while out.len() < count {
        let from = random_six(rng, &robot);
        let span = rng.range(2.0, 40.0);
        let to = from.map(|a| a + rng.range(-span, span));
        if robot.check_range6(&to).is_err() {
            continue;
        }
        let near = model.clearance_at(&from).min(model.clearance_at(&to)) < 80.0;
        if near || out.len() % 4 == 3 {
            out.push((from, to));
        }
    }
    out
}

#[test]
fn proofs_and_certified_figures_are_those_of_exact_distances() {
    let model = torch_model(10.0);
    let mut rng = Rng(0x0DEC_1DE5_0000_0031);
    let (mut kept, mut refused, mut pairs_failing) = (0, 0, 0);
    for (from, to) in near_moves(&mut rng, &model, 150) {
        // The clearance of the proofs: the model's, or just under the move's own least
        // distance (a grazing move, decided deep in the bisection).
        let least = reference_min(&model, &from, &to, 0.05).map_or(0.0, |r| r.0);
        for c in [10.0, (least - 0.3).max(0.0), least + 0.3] {
            let speeds = model.part_speeds(&from, &to);
            let mut want_keeps = true;
            let mut first: Option<(f64, usize, usize, f64)> = None;
            for (p, &m) in speeds.iter().enumerate() {
                for (k, _) in model.part_boxes(p) {
                    if reference_pair(&model, (p, k), (&from, &to), m, c, false).is_some() {
                        want_keeps = false;
                        pairs_failing += 1;
                    }
                    if let Some((t, d)) = reference_pair(&model, (p, k), (&from, &to), m, c, true) {
                        if first.is_none_or(|(tf, _, _, df)| t < tf || (t == tf && d < df)) {
                            first = Some((t, p, k, d));
                        }
                    }
                }
            }
            assert_eq!(
                model.move_keeps(&from, &to, c),
                want_keeps,
                "{from:?} -> {to:?} at {c}"
            );
            let got = model.first_contact(&from, &to, c);
            let want = first.map(|(t, p, k, d)| (t, model.contact(p, k, d.max(0.0))));
            assert_eq!(got, want, "{from:?} -> {to:?} at {c}");
            if want_keeps {
                kept += 1;
            } else {
                refused += 1;
            }
        }
        let got = model.min_clearance_along(&from, &to, 0.05);
        let want = reference_min(&model, &from, &to, 0.05);
        match (got, want) {
            (Some(g), Some((mm, p, k))) => {
                assert_eq!(
                    g.mm.to_bits(),
                    mm.to_bits(),
                    "{from:?} -> {to:?}: {g:?} vs {mm}"
                );
                assert_eq!(g.part, model.part(p), "{from:?} -> {to:?}");
                assert_eq!(g.obstacle, model.obstacles[k].name, "{from:?} -> {to:?}");
            }
            (g, w) => panic!("{from:?} -> {to:?}: {g:?} vs {w:?}"),
        }
    }
    // Both verdicts are well represented.
    assert!(
        kept >= 100 && refused >= 100,
        "{kept} kept, {refused} refused"
    );
    assert!(pairs_failing >= 100, "{pairs_failing}");
}

#[test]
fn a_move_proven_twice_is_proven_once() {
    let model = torch_model(10.0);
    let mut rng = Rng(0x3E30_0000_0000_0031);
    let moves = near_moves(&mut rng, &model, 40);
    let first: Vec<bool> = moves
        .iter()
        .map(|(a, b)| model.move_is_safe(a, b))
        .collect();
    // Every move in range is in the memo once, whatever its verdict.
    let in_range = moves
        .iter()
        .filter(|(a, b)| model.robot.check_range6(a).is_ok() && model.robot.check_range6(b).is_ok())
        .count();
    assert_eq!(model.proven.len(), in_range);
    assert!(
        first.iter().any(|&v| v) && first.iter().any(|&v| !v),
        "{first:?}"
    );
    // Asked again, the same verdicts, no new proof; and each is the proof's own.
    let again: Vec<bool> = moves
        .iter()
        .map(|(a, b)| model.move_is_safe(a, b))
        .collect();
    assert_eq!(first, again);
    assert_eq!(model.proven.len(), in_range);
    let fresh = torch_model(10.0);
    for ((a, b), v) in moves.iter().zip(&first) {
        assert_eq!(fresh.move_keeps(a, b, 10.0), *v, "{a:?} -> {b:?}");
    }
    // A clone starts empty: a model with more clearance (a clone) proves its moves anew, and
    // refuses the moves this one proved that come within its clearance.
    // The margin: 1 mm beyond the least clearance certified along a proven move.
    let least = (moves.iter().zip(&first))
        .filter(|(_, &v)| v)
        .filter_map(|((a, b), _)| model.min_clearance_along(a, b, 0.05))
        .fold(f64::INFINITY, |m, c| m.min(c.mm));
    let margin = least - 10.0 + 1.0;
    assert!(margin > 0.0 && margin < 100.0, "{least}");
    let wider = model.with_margin(margin);
    assert_eq!(wider.proven.len(), 0);
    let mut now_refused = 0;
    for ((a, b), v) in moves.iter().zip(&first) {
        let w = wider.move_is_safe(a, b);
        assert_eq!(w, fresh.move_keeps(a, b, 10.0 + margin), "{a:?} -> {b:?}");
        if *v && !w {
            now_refused += 1;
        }
    }
    assert!(
        now_refused > 0,
        "no move proven at 10 mm is refused {margin} mm beyond"
    );
}
