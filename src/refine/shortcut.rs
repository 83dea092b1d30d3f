//! The shortcut pass (issue 10, item 3; beyond the paper): routes shorter than the grid allows.
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
//! the time estimate does not grow. A via slid to the very edge of the clearance leaves no room
//! for a zone's corner (`collision::corner`); so where a fly-by zone is asked, the refine stage
//! also runs this pass on a model asking a margin more clearance and keeps the faster result
//! (`refine`).
//! Deterministic: fixed order, no randomness.

use crate::collision::CollisionModel;
use crate::plan::leg::WristSchedule;
use crate::plan::{Plan, Waypoint, WaypointKind};
use crate::precision::quantize_joints;

/// Most rounds of joins and slides.
pub const ROUNDS: usize = 4;

/// Halvings of the slide's fraction when the whole slide is not proven.
pub const SLIDE_STEPS: usize = 6;

/// The continuous shortcut pass (module doc); `time_s` estimates a plan's time.
pub fn shortcut(mut plan: Plan, model: &CollisionModel, time_s: &dyn Fn(&Plan) -> f64) -> Plan {
    let mut best_s = time_s(&plan);
    for _ in 0..ROUNDS {
        let mut changed = false;
        for l in 0..plan.legs.len() {
            if let Some(c) = join_leg(&plan, l, model) {
                let t = time_s(&c);
                if t <= best_s {
                    (plan, best_s, changed) = (c, t, true);
                }
            }
        }
        for k in 1..plan.waypoints.len().saturating_sub(1) {
            if let Some(c) = slide(&plan, k, model) {
                let t = time_s(&c);
                if t <= best_s {
                    (plan, best_s, changed) = (c, t, true);
                }
            }
        }
        if !changed {
            break;
        }
    }
    plan
}

/// Leg `l` with its greedy farthest joins (module doc), or `None` when it drops no via.
fn join_leg(plan: &Plan, l: usize, model: &CollisionModel) -> Option<Plan> {
    let range = plan.legs[l].waypoints.clone();
    let ws = &plan.waypoints[range.clone()];
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
    (kept.len() < m).then(|| with_leg(plan, l, kept))
}

/// Via `k` slid towards the midpoint of its neighbours (module doc), or `None` when it is no
/// via or no slide is proven.
fn slide(plan: &Plan, k: usize, model: &CollisionModel) -> Option<Plan> {
    let WaypointKind::Via { leg, .. } = plan.waypoints[k].kind else {
        return None;
    };
    let range = plan.legs[leg].waypoints.clone();
    let (first, last) = (
        &plan.waypoints[range.start].joints_deg,
        &plan.waypoints[range.end - 1].joints_deg,
    );
    let schedule = WristSchedule::new(first, last);
    let (prev, via, next) = (
        plan.waypoints[k - 1].arm_deg(),
        plan.waypoints[k].arm_deg(),
        plan.waypoints[k + 1].arm_deg(),
    );
    let goal: [f64; 3] = std::array::from_fn(|x| 0.5 * (prev[x] + next[x]));
    let at = |f: f64| -> Option<Plan> {
        let arm = quantize_joints(std::array::from_fn(|x| via[x] + f * (goal[x] - via[x])));
        if arm == via {
            return None;
        }
        let six = schedule.six(&arm);
        let w = &plan.waypoints;
        if !(model.move_is_safe(&w[k - 1].joints_deg, &six)
            && model.move_is_safe(&six, &w[k + 1].joints_deg))
        {
            return None;
        }
        let mut c = plan.clone();
        c.waypoints[k].joints_deg = six;
        Some(c)
    };
    if let Some(c) = at(1.0) {
        return Some(c);
    }
    let (mut lo, mut hi, mut best) = (0.0, 1.0, None);
    for _ in 0..SLIDE_STEPS {
        let f = 0.5 * (lo + hi);
        match at(f) {
            Some(c) => {
                (lo, best) = (f, Some(c));
            }
            None => hi = f,
        }
    }
    best
}

/// `plan` with leg `l`'s waypoints replaced by `leg` (both ends as before); the vias renumbered
/// in order, the later legs' ranges shifted.
pub(super) fn with_leg(plan: &Plan, l: usize, leg: Vec<Waypoint>) -> Plan {
    let range = plan.legs[l].waypoints.clone();
    let (old_len, new_len) = (range.len(), leg.len());
    let mut out = plan.clone();
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
    out.move_clearances = Vec::new();
    out.min_clearance = None;
    out.estimate = None;
    out.zones = Vec::new();
    out
}
