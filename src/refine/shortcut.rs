//! The shortcut pass (beyond the paper): routes shorter than the grid allows.
//!
//! The paper's route keeps the grid's corners: its shortening joins grid nodes `k -> k+2` and its
//! merge joins collinear moves. This pass works on the route as planned, leg by leg, off the
//! grid, in rounds (at most [`ROUNDS`], until nothing changes):
//!
//! 1. **Join.** From each waypoint `i` of a leg, the farthest later waypoint `j` of the leg whose
//!    straight six-axis move `i -> j` is proven safe ([`CollisionModel::move_is_safe`]) follows
//!    `i`; the vias between are dropped. The cell points are never dropped (they end the legs).
//! 2. **Slide.** Each via, in route order, moves along the straight line (axes 1..3) towards the
//!    midpoint of its two neighbours, which shortens its two moves (their summed length is
//!    convex along that line and least at the midpoint): the whole way if both new moves are
//!    proven, else the largest fraction found by bisection ([`SLIDE_STEPS`] halvings). Its
//!    axes 4..6 follow the leg's wrist schedule (`plan::leg::WristSchedule`), as every via's do.
//!
//! Every candidate is rounded to the written precision (0.001 deg) before it is proven, so what
//! is proven is what is written. A change (one leg's joins, one via's slide) is kept only when
//! the time estimate of the route (its motions as planned, `plan::motion::planned`) does not
//! grow. A via slid to the very edge of the clearance leaves no room
//! for a zone's corner (`collision::corner`); so where a fly-by zone is asked, the refine stage
//! also runs this pass on a model asking a margin more clearance and keeps the faster result
//! (`refine`).
//!
//! **On all cores, decided on one** (`crate::parallel::map_on`; beyond the paper, as the pass
//! is). The proofs are almost all the cost; the decisions (the time of the whole route, a float
//! sum, against the best so far) stay one at a time in the order above, so the route is the one
//! a single core makes, bit for bit. At the start of each round (where two legs or more have vias
//! to move: a thread costs about a proof) every leg's proofs are made at
//! once, a leg to a core, as if every proven change were kept (the usual case): its joins, then
//! the chain of its slides, via after via, on the waypoints the joins keep, each slide with the
//! three joints it started from. A leg's joins read only its own waypoints, which no other leg's
//! change touches, so its kept waypoints are the ones the one-core pass proves at its turn. A
//! slide reads only its via, the via's two neighbours and its leg's cell points (the wrist
//! schedule; no change moves them), so the pass, deciding the slides in route order, takes the
//! slide computed ahead where its via and neighbours hold the same joints, bit for bit, and
//! computes it anew where they do not (after a change of its leg was turned down).
//! Deterministic: fixed order of decisions, no randomness, whichever core proves what.

use crate::collision::CollisionModel;
use crate::parallel;
use crate::plan::leg::WristSchedule;
use crate::plan::{Route, Waypoint, WaypointKind};
use crate::precision::quantize_joints;

/// Most rounds of joins and slides.
pub const ROUNDS: usize = 4;

/// Halvings of the slide's fraction when the whole slide is not proven.
pub const SLIDE_STEPS: usize = 6;

/// The continuous shortcut pass (module doc); `time_s` estimates a route's time.
pub fn shortcut(mut route: Route, model: &CollisionModel, time_s: &dyn Fn(&Route) -> f64) -> Route {
    let mut best_s = time_s(&route);
    for _ in 0..ROUNDS {
        let mut changed = false;
        // Every leg's proofs of the round at once (module doc), then the decisions in order.
        let ahead = ahead_of_round(&route, model);
        // 1. Joins, in leg order. Leg `l`'s waypoints are those `ahead` started from: an
        // earlier leg's change moves them in the route, never changes them.
        for (l, a) in ahead.iter().enumerate() {
            if let Some(kept) = &a.kept {
                let c = with_leg(&route, l, kept.clone());
                let t = time_s(&c);
                if t <= best_s {
                    (route, best_s, changed) = (c, t, true);
                }
            }
        }
        // 2. Slides, in route order: a slide computed ahead where its key holds.
        for k in 1..route.waypoints.len().saturating_sub(1) {
            let WaypointKind::Via { leg, .. } = route.waypoints[k].kind else {
                continue;
            };
            let w = &route.waypoints;
            let key = [w[k - 1].joints_deg, w[k].joints_deg, w[k + 1].joints_deg];
            // `slides[i]` is the slide of the leg's waypoint `i + 1` (its first is a cell point).
            let i = k.checked_sub(route.legs[leg].waypoints.start + 1);
            let six = match i.and_then(|i| ahead[leg].slides.get(i)) {
                Some(g) if same_bits(&g.key, &key) => g.six,
                _ => slide_six(&key, &schedule_of(&route, leg), model),
            };
            if let Some(six) = six {
                let mut c = route.clone();
                c.waypoints[k].joints_deg = six;
                let t = time_s(&c);
                if t <= best_s {
                    (route, best_s, changed) = (c, t, true);
                }
            }
        }
        if !changed {
            break;
        }
    }
    route
}

/// A leg's proofs of a round, computed ahead: the waypoints its joins keep (`None`: no via
/// dropped), and the slides of the leg's vias after them, in order.
#[derive(Default)]
struct Ahead {
    kept: Option<Vec<Waypoint>>,
    slides: Vec<Guess>,
}

/// A slide computed ahead: the joints of the via's previous waypoint, the via and its next
/// waypoint it was computed from, and the via's new joints (`None`: no slide proven).
struct Guess {
    key: [[f64; 6]; 3],
    six: Option<[f64; 6]>,
}

/// Every leg's [`Ahead`] for a round of `route`, legs on all cores: its joins, then the chain of
/// its slides on the waypoints the joins keep, as if every proven change were kept (the usual
/// case). A slide reads only its via, the via's two neighbours and the leg's cell points (which
/// no change moves), so where the pass meets a via with the same three joints, bit for bit, as
/// a slide computed ahead, that slide is what it would compute there; where an earlier change of
/// the leg was not kept, the joints differ and the pass computes the slide anew.
fn ahead_of_round(route: &Route, model: &CollisionModel) -> Vec<Ahead> {
    let w = &route.waypoints;
    let legs: Vec<usize> = (0..route.legs.len())
        .filter(|&l| route.legs[l].waypoints.len() > 2)
        .collect();
    // A map costs about a proof's time, and a leg with one via that cannot slide asks one
    // proof (its join): with one leg or none asking more, the legs are proven here, in turn.
    let busy = legs.iter().filter(|&&l| {
        let r = route.legs[l].waypoints.clone();
        r.len() > 3 || (r.start + 1..r.end - 1).any(|k| can_slide(&w[k - 1], &w[k], &w[k + 1]))
    });
    let threads = if busy.count() >= 2 { usize::MAX } else { 1 };
    let per_leg = parallel::map_on(threads, &legs, |&l| {
        let ws = &route.waypoints[route.legs[l].waypoints.clone()];
        let kept = join_kept(ws, model);
        let schedule = schedule_of(route, l);
        let slides = slide_chain(kept.as_deref().unwrap_or(ws), l, &schedule, model);
        Ahead { kept, slides }
    });
    let mut all: Vec<Ahead> = route.legs.iter().map(|_| Ahead::default()).collect();
    for (&l, a) in legs.iter().zip(per_leg) {
        all[l] = a;
    }
    all
}

/// The slides of leg `l`'s vias computed ahead along its waypoints `ws`, each via in order,
/// every proven slide kept for the next, on the leg's wrist `schedule` ([`schedule_of`], the one
/// the pass slides them on); up to the first waypoint that is no via of leg `l` (the pass
/// slides a via on the schedule of the leg it names).
fn slide_chain(
    ws: &[Waypoint],
    l: usize,
    schedule: &WristSchedule,
    model: &CollisionModel,
) -> Vec<Guess> {
    let m = ws.len();
    let mut joints: Vec<[f64; 6]> = ws.iter().map(|w| w.joints_deg).collect();
    let mut slides = Vec::with_capacity(m.saturating_sub(2));
    for i in 1..m.saturating_sub(1) {
        if !matches!(ws[i].kind, WaypointKind::Via { leg, .. } if leg == l) {
            break;
        }
        let key = [joints[i - 1], joints[i], joints[i + 1]];
        let six = slide_six(&key, schedule, model);
        if let Some(six) = six {
            joints[i] = six;
        }
        slides.push(Guess { key, six });
    }
    slides
}

/// Whether via `via` can slide at all between `prev` and `next`: its neighbours' midpoint,
/// rounded, is not where it is (else every fraction of the slide rounds back to it, as the via
/// is at the written precision). Only chooses whether the legs are proven on all cores, never a
/// change.
fn can_slide(prev: &Waypoint, via: &Waypoint, next: &Waypoint) -> bool {
    let (p, v, n) = (prev.arm_deg(), via.arm_deg(), next.arm_deg());
    quantize_joints(std::array::from_fn(|x| 0.5 * (p[x] + n[x]))) != v
}

/// Whether two keys hold the same bits (a `-0.0` is not a `0.0` here).
fn same_bits(a: &[[f64; 6]; 3], b: &[[f64; 6]; 3]) -> bool {
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .all(|(x, y)| x.to_bits() == y.to_bits())
}

/// The wrist schedule of leg `l`, from its cell points.
fn schedule_of(route: &Route, l: usize) -> WristSchedule {
    let range = route.legs[l].waypoints.clone();
    WristSchedule::new(
        &route.waypoints[range.start].joints_deg,
        &route.waypoints[range.end - 1].joints_deg,
    )
}

/// The waypoints a leg `ws` keeps with its greedy farthest joins (module doc), or `None` when
/// it drops no via.
fn join_kept(ws: &[Waypoint], model: &CollisionModel) -> Option<Vec<Waypoint>> {
    let m = ws.len();
    if m <= 2 {
        return None;
    }
    let mut kept = vec![ws[0].clone()];
    let mut i = 0;
    while i + 1 < m {
        let j = (i + 2..m)
            .rev()
            .find(|&j| model.move_is_safe(&ws[i].joints_deg, &ws[j].joints_deg))
            .unwrap_or(i + 1);
        kept.push(ws[j].clone());
        i = j;
    }
    (kept.len() < m).then_some(kept)
}

/// The new joints of a via slid towards the midpoint of its neighbours (module doc), from
/// `[previous, via, next]` joints and its leg's wrist schedule; `None` when no slide is proven.
fn slide_six(
    [prev6, via6, next6]: &[[f64; 6]; 3],
    schedule: &WristSchedule,
    model: &CollisionModel,
) -> Option<[f64; 6]> {
    let arm = |j: &[f64; 6]| [j[0], j[1], j[2]];
    let (prev, via, next) = (arm(prev6), arm(via6), arm(next6));
    let goal: [f64; 3] = std::array::from_fn(|x| 0.5 * (prev[x] + next[x]));
    let at = |f: f64| -> Option<[f64; 6]> {
        let arm = quantize_joints(std::array::from_fn(|x| via[x] + f * (goal[x] - via[x])));
        if arm == via {
            return None;
        }
        let six = schedule.six(&arm);
        (model.move_is_safe(prev6, &six) && model.move_is_safe(&six, next6)).then_some(six)
    };
    if let Some(six) = at(1.0) {
        return Some(six);
    }
    let (mut lo, mut hi, mut best) = (0.0, 1.0, None);
    for _ in 0..SLIDE_STEPS {
        let f = 0.5 * (lo + hi);
        match at(f) {
            Some(six) => {
                (lo, best) = (f, Some(six));
            }
            None => hi = f,
        }
    }
    best
}

/// `route` with leg `l`'s waypoints replaced by `leg` (both ends as before); the vias renumbered
/// in order, the later legs' ranges shifted.
pub(super) fn with_leg(route: &Route, l: usize, leg: Vec<Waypoint>) -> Route {
    let range = route.legs[l].waypoints.clone();
    let (old_len, new_len) = (range.len(), leg.len());
    let mut out = route.clone();
    let mut leg = leg;
    for (index, w) in leg.iter_mut().enumerate().take(new_len - 1).skip(1) {
        w.kind = WaypointKind::Via { leg: l, index };
    }
    out.waypoints.splice(range.clone(), leg);
    out.legs[l].waypoints = range.start..range.start + new_len;
    for later in &mut out.legs[l + 1..] {
        let r = &later.waypoints;
        later.waypoints = (r.start + new_len - old_len)..(r.end + new_len - old_len);
    }
    out
}

#[cfg(test)]
mod tests {
    //! The pass against a one-core pass ([`sequential`]: each leg's joins and each via's slide
    //! proven at its turn), on real cells' routes: the same route, bit for bit, including where
    //! a proven change is not kept (its time grows).
    use super::*;
    use crate::pipeline;
    use crate::plan::motion;
    use crate::timing;
    use std::path::Path;

    /// The pass on one core (the reference), and how many proven slides and joins it did not
    /// keep.
    fn sequential(
        mut route: Route,
        model: &CollisionModel,
        time_s: &dyn Fn(&Route) -> f64,
    ) -> (Route, usize, usize) {
        let mut best_s = time_s(&route);
        let (mut rejected, mut rejected_joins) = (0, 0);
        for _ in 0..ROUNDS {
            let mut changed = false;
            for l in 0..route.legs.len() {
                if let Some(c) = join_leg(&route, l, model) {
                    let t = time_s(&c);
                    if t <= best_s {
                        (route, best_s, changed) = (c, t, true);
                    } else {
                        rejected_joins += 1;
                    }
                }
            }
            for k in 1..route.waypoints.len().saturating_sub(1) {
                if let Some(c) = slide(&route, k, model) {
                    let t = time_s(&c);
                    if t <= best_s {
                        (route, best_s, changed) = (c, t, true);
                    } else {
                        rejected += 1;
                    }
                }
            }
            if !changed {
                break;
            }
        }
        (route, rejected, rejected_joins)
    }

    /// The one-core pass's join of leg `l`, proven at its turn (the joins' proofs are the
    /// pure `join_kept`; what the test holds is when they are made and which are used).
    fn join_leg(route: &Route, l: usize, model: &CollisionModel) -> Option<Route> {
        let ws = &route.waypoints[route.legs[l].waypoints.clone()];
        join_kept(ws, model).map(|kept| with_leg(route, l, kept))
    }

    /// The one-core pass's slide of via `k`, proven at its turn (`slide_six`, as the pass).
    fn slide(route: &Route, k: usize, model: &CollisionModel) -> Option<Route> {
        let WaypointKind::Via { leg, .. } = route.waypoints[k].kind else {
            return None;
        };
        let w = &route.waypoints;
        let key = [w[k - 1].joints_deg, w[k].joints_deg, w[k + 1].joints_deg];
        let six = slide_six(&key, &schedule_of(route, leg), model)?;
        let mut c = route.clone();
        c.waypoints[k].joints_deg = six;
        Some(c)
    }

    /// The waypoints' joints as bits, and the legs' ranges: what must not differ.
    fn bits(p: &Route) -> (Vec<[u64; 6]>, Vec<String>, Vec<std::ops::Range<usize>>) {
        (
            p.waypoints
                .iter()
                .map(|w| w.joints_deg.map(f64::to_bits))
                .collect(),
            p.waypoints
                .iter()
                .map(|w| format!("{:?}", w.kind))
                .collect(),
            p.legs.iter().map(|l| l.waypoints.clone()).collect(),
        )
    }

    #[test]
    fn all_cores_give_the_one_core_plan_bit_for_bit() {
        let (mut rejected, mut rejected_joins, mut changed) = (0, 0, 0);
        for (cell, grids) in [
            ("torch-trunk", &[2.0, 1.5][..]),
            ("gripper-pick", &[2.0, 1.5][..]),
            ("conveyor", &[2.0, 2.5][..]),
            ("shelf", &[1.5][..]),
        ] {
            let path = format!("{}/cells/{cell}.yaml", env!("CARGO_MANIFEST_DIR"));
            let job = pipeline::load(Path::new(&path)).expect("the example cell loads");
            let placed = pipeline::place(&job).expect("the example cell is placed");
            let time_model = timing::TimeModel::new(&job.robot, job.cell.tool.as_ref());
            let real_s = |p: &Route| {
                timing::estimate(p, &motion::planned(p, &placed.points), &time_model).total_s
            };
            for &grid_deg in grids {
                let inspected = pipeline::inspect(&job, &placed, grid_deg);
                let route = pipeline::route(&job, &placed, &inspected, job.cell.planner.method)
                    .expect("the example cell is planned");
                let vias = route.waypoints.len();
                // The cell's model and the margined one the refine stage also runs on.
                let margined = inspected.model.with_margin(super::super::MARGIN_MM);
                for model in [&inspected.model, &margined] {
                    // The real time; one that turns every join down (slides judged by time);
                    // and two that judge by a hash of the route's bits, so that changes of any
                    // kind are kept or turned down in patterns the real time never makes.
                    for judge in 0..4u64 {
                        let time_s = |p: &Route| match judge {
                            0 => real_s(p),
                            1 => real_s(p) + if p.waypoints.len() < vias { 1e3 } else { 0.0 },
                            _ => {
                                let mut h = judge.wrapping_mul(0x9e37_79b9_7f4a_7c15);
                                for j in p.waypoints.iter().flat_map(|w| w.joints_deg) {
                                    h = (h ^ j.to_bits()).wrapping_mul(0x100_0000_01b3);
                                    h ^= h >> 29;
                                }
                                real_s(p) + 0.3 * (h >> 11) as f64 / (1u64 << 53) as f64
                            }
                        };
                        let (want, r, rj) = sequential(route.clone(), model, &time_s);
                        let got = shortcut(route.clone(), model, &time_s);
                        assert_eq!(bits(&got), bits(&want), "{cell} at {grid_deg} deg, {judge}");
                        rejected += r;
                        rejected_joins += rj;
                        changed += usize::from(bits(&want) != bits(&route));
                    }
                }
            }
        }
        // The cases are worth something: the pass changes routes, and some proven join and
        // some proven slide are not kept (the slides computed ahead after them on their leg
        // are then computed again).
        assert!(changed > 0);
        assert!(rejected > 0, "no proven slide was turned down");
        assert!(rejected_joins > 0, "no proven join was turned down");
    }
}
