//! Planning the route through the cell's points, leg by leg (paper section 4, applied to
//! A -> B -> ... -> F).
//!
//! For each leg: join both points to the grid (a point on a node is that node; a point off the
//! grid joins the nearest free node whose straight move to it is proven safe); search the grid
//! with the chosen method, every step accepted only if its straight move is proven safe; for the
//! extensile method shorten recursively; merge collinear moves; round to the written precision
//! (0.001 deg) and prove every move again. The route starts at the first point, visits every
//! point in the cell's order, and each cell point is a waypoint exactly as given.

use crate::cell::{Method, JOINT_DECIMALS};
use crate::collision::{Blocked, CollisionModel};
use crate::plan::cspace::{CSpace, Node};
pub mod cspace;
pub mod merge;
pub mod search;
pub mod shorten;
pub mod wave;

/// A cell point with its axes 1..3 resolved (controller values, deg).
#[derive(Clone, Debug, PartialEq)]
pub struct Waypoint {
    pub name: String,
    pub axes_deg: [f64; 3],
}

/// One leg: from point `from` to point `to` (indices into the points).
#[derive(Clone, Debug)]
pub struct Leg {
    pub from: usize,
    pub to: usize,
    /// The grid path the search returned (before shortening and merging), for pictures.
    pub grid_path: Vec<Node>,
    /// The straight moves: waypoints from the `from` point to the `to` point, both included.
    pub waypoints: Vec<[f64; 3]>,
}

/// The route through all points.
#[derive(Clone, Debug)]
pub struct Plan {
    pub method: Method,
    pub legs: Vec<Leg>,
}

impl Plan {
    /// Number of straight moves.
    pub fn moves(&self) -> usize {
        self.legs.iter().map(|l| l.waypoints.len() - 1).sum()
    }

    /// Every straight move, in order.
    pub fn segments(&self) -> impl Iterator<Item = ([f64; 3], [f64; 3])> + '_ {
        self.legs
            .iter()
            .flat_map(|l| l.waypoints.windows(2).map(|w| (w[0], w[1])))
    }

    /// Sum of the moves' lengths in joint space (Euclidean over axes 1..3, deg).
    pub fn path_length_deg(&self) -> f64 {
        self.segments()
            .map(|(a, b)| (0..3).map(|k| (b[k] - a[k]).powi(2)).sum::<f64>().sqrt())
            .sum()
    }
}

/// Why a route could not be planned. Each variant names the point(s) concerned.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    #[error("point '{name}' cannot be used: {reason}")]
    PointBlocked {
        point: usize,
        name: String,
        reason: Blocked,
    },
    #[error("point '{name}' is off the grid and no free grid node next to it can be reached by a safe straight move")]
    NoJoin { point: usize, name: String },
    #[error("no collision-free path from '{from_name}' to '{to_name}': the free space between them is not connected on a {grid_deg} deg grid with {clearance_mm} mm clearance")]
    NoPath {
        from: usize,
        to: usize,
        from_name: String,
        to_name: String,
        grid_deg: f64,
        clearance_mm: f64,
    },
    #[error("the {method} search found no path from '{from_name}' to '{to_name}'{}", method_hint(*.method))]
    SearchFailed {
        from: usize,
        to: usize,
        from_name: String,
        to_name: String,
        method: Method,
    },
    #[error("internal error: the move {from_axes:?} -> {to_axes:?} on the leg '{from_name}' -> '{to_name}' could not be proven safe after rounding")]
    Unsafe {
        from: usize,
        from_name: String,
        to_name: String,
        from_axes: [f64; 3],
        to_axes: [f64; 3],
    },
}

fn method_hint(m: Method) -> &'static str {
    match m {
        Method::DepthFirst => " (depth-first walks axis steps only and the free space there is joined only diagonally, the paper's Fig. 8; try --planner extensile)",
        _ => " (every path the wave offers was refused by the whole-move safety check)",
    }
}

impl PlanError {
    /// The cell point an error is about, for pointing at the input.
    pub fn point(&self) -> usize {
        match self {
            PlanError::PointBlocked { point, .. } | PlanError::NoJoin { point, .. } => *point,
            PlanError::NoPath { to, .. } | PlanError::SearchFailed { to, .. } => *to,
            PlanError::Unsafe { from, .. } => *from,
        }
    }
}

/// Rounds to the written precision (0.001 deg), so what we prove is what we write.
pub fn quantize(a: [f64; 3]) -> [f64; 3] {
    let s = 10f64.powi(JOINT_DECIMALS);
    a.map(|x| {
        let r = (x * s).round() / s;
        if r == 0.0 {
            0.0
        } else {
            r
        }
    })
}

fn join(cs: &CSpace, model: &CollisionModel, p: &[f64; 3]) -> Option<Node> {
    if let Some(n) = cs.grid.node_at(p) {
        return cs.is_free(n).then_some(n);
    }
    for rings in 1..=3 {
        for n in cs.grid.nodes_near(p, rings) {
            if cs.is_free(n) && model.move_is_safe(p, &cs.grid.axes_deg(n)) {
                return Some(n);
            }
        }
    }
    None
}

/// Plans the route through `points` (at least two), in order.
pub fn plan(
    cs: &CSpace,
    model: &CollisionModel,
    points: &[Waypoint],
    method: Method,
) -> Result<Plan, PlanError> {
    let mut nodes = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        if let Some(reason) = model.why_blocked(&p.axes_deg) {
            return Err(PlanError::PointBlocked {
                point: i,
                name: p.name.clone(),
                reason,
            });
        }
        let n = join(cs, model, &p.axes_deg).ok_or_else(|| PlanError::NoJoin {
            point: i,
            name: p.name.clone(),
        })?;
        nodes.push(n);
    }
    let grid = &cs.grid;
    let mut accept_nodes =
        |a: Node, b: Node| model.move_is_safe(&grid.axes_deg(a), &grid.axes_deg(b));
    let mut legs = Vec::with_capacity(points.len() - 1);
    for i in 0..points.len() - 1 {
        let (s, g) = (nodes[i], nodes[i + 1]);
        let (p, q) = (points[i].axes_deg, points[i + 1].axes_deg);
        if p == q {
            // The same axes 1..3 twice (the wrist may differ): one move that stays put.
            legs.push(Leg {
                from: i,
                to: i + 1,
                grid_path: vec![s],
                waypoints: vec![p, q],
            });
            continue;
        }
        let found = match method {
            Method::Neighboring => search::neighboring::search(cs, s, g, &mut accept_nodes),
            Method::DepthFirst => search::depth_first::search(cs, s, g, &mut accept_nodes),
            Method::Extensile => search::extensile::search(cs, s, g, &mut accept_nodes),
        };
        let Some(grid_path) = found else {
            let connected = wave::expand(cs, s, g, wave::Connectivity::TwentySix).is_some();
            let (from_name, to_name) = (points[i].name.clone(), points[i + 1].name.clone());
            return Err(if connected {
                PlanError::SearchFailed {
                    from: i,
                    to: i + 1,
                    from_name,
                    to_name,
                    method,
                }
            } else {
                PlanError::NoPath {
                    from: i,
                    to: i + 1,
                    from_name,
                    to_name,
                    grid_deg: grid.step_deg,
                    clearance_mm: model.clearance_mm(),
                }
            });
        };
        let mut waypoints = vec![p];
        waypoints.extend(grid_path.iter().map(|&n| grid.axes_deg(n)));
        waypoints.push(q);
        waypoints.dedup();
        if method == Method::Extensile {
            shorten::shorten(cs, &mut waypoints, &mut |a, b| model.move_is_safe(a, b));
        }
        let mut waypoints: Vec<[f64; 3]> = merge::collinear(&waypoints)
            .into_iter()
            .map(quantize)
            .collect();
        waypoints.dedup();
        if waypoints.len() == 1 {
            // The two points coincide: one (empty) move keeps both in the program.
            waypoints.push(q);
        }
        for w in waypoints.windows(2) {
            if !model.move_is_safe(&w[0], &w[1]) {
                return Err(PlanError::Unsafe {
                    from: i,
                    from_name: points[i].name.clone(),
                    to_name: points[i + 1].name.clone(),
                    from_axes: w[0],
                    to_axes: w[1],
                });
            }
        }
        legs.push(Leg {
            from: i,
            to: i + 1,
            grid_path,
            waypoints,
        });
    }
    Ok(Plan { method, legs })
}

#[cfg(test)]
mod tests {
    //! The paper's figures through the plan layer: a hand-made grid (`CSpace::from_fn`) with the
    //! real IRB 1400 model and no obstacles, so every move inside the axis ranges is safe and
    //! only the hand-made free nodes steer the search.
    use super::*;
    use crate::collision::Placement;
    use crate::plan::cspace::Grid;
    use crate::robot::Robot;

    fn open_model() -> CollisionModel {
        let placement = Placement {
            base_mm: [0.0, 0.0, 0.0],
            yaw_deg: 0.0,
        };
        CollisionModel::new(&Robot::irb1400(), placement, Vec::new(), 0.0)
    }

    fn point(name: &str, axes_deg: [f64; 3]) -> Waypoint {
        Waypoint {
            name: name.into(),
            axes_deg,
        }
    }

    #[test]
    fn fig8_depth_first_fails_with_the_leg_named_and_extensile_takes_the_diagonal() {
        // 3 x 3 nodes in the axis 1 - axis 2 plane; free only on the diagonal, so the free
        // nodes touch only at corners (paper Fig. 8).
        let g = Grid::over([[0.0, 2.0], [0.0, 2.0], [0.0, 0.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| n[0] == n[1]);
        let model = open_model();
        let pts = [point("P", [0.0, 0.0, 0.0]), point("Q", [2.0, 2.0, 0.0])];
        match plan(&cs, &model, &pts, Method::DepthFirst) {
            Err(e @ PlanError::SearchFailed { from: 0, to: 1, .. }) => {
                let msg = e.to_string();
                assert!(
                    msg.contains("depth-first search found no path from 'P' to 'Q'"),
                    "{msg}"
                );
                assert_eq!(e.point(), 1);
            }
            other => panic!("expected SearchFailed, got {other:?}"),
        }
        let p = plan(&cs, &model, &pts, Method::Extensile).expect("extensile plans");
        assert_eq!(p.moves(), 1);
        assert_eq!(p.legs[0].waypoints, vec![[0.0, 0.0, 0.0], [2.0, 2.0, 0.0]]);
        assert_eq!(p.legs[0].grid_path, vec![[0, 0, 0], [1, 1, 0], [2, 2, 0]]);
    }

    #[test]
    fn fig6_neighboring_saw_tooth_and_extensile_straightens_it() {
        // A band of free nodes along axis 2 = axis 1 / 2 (|2 n2 - n1| <= 1), from (0, 0) to
        // (10, 5). On the 26-neighbour wave node (x, y) carries x + 1. Back from (10, 5) the
        // neighbouring search takes, among the smaller numbers in the band, the node nearest the
        // start: (9, 4) (97 against 106 for (9, 5)), then only (8, 4), then (7, 3), ...
        // a diagonal step and an axis step in turn: ten steps, no two in the same direction, so
        // ten moves even after the collinear merge (the saw-tooth of Fig. 6).
        let g = Grid::over([[0.0, 10.0], [0.0, 5.0], [0.0, 0.0]], 1.0);
        let cs = CSpace::from_fn(g, |n| (2 * n[1] - n[0]).abs() <= 1);
        let model = open_model();
        let pts = [point("P", [0.0, 0.0, 0.0]), point("Q", [10.0, 5.0, 0.0])];
        let nb = plan(&cs, &model, &pts, Method::Neighboring).expect("neighboring plans");
        assert_eq!(nb.moves(), 10, "{:?}", nb.legs[0].waypoints);
        assert_eq!(nb.legs[0].waypoints[1], [1.0, 0.0, 0.0]);
        assert_eq!(nb.legs[0].waypoints[2], [2.0, 1.0, 0.0]);
        // Extensile: search, shorten (k -> k+2 where the inspected nodes are free) and merge.
        // The straight line (0, 0) -> (10, 5) passes only band nodes (at x = i its axis-2 value
        // i / 2 rounds into the band), but the shortening cuts k -> k+2 greedily from the start,
        // so it ends with at most a few pieces and never more than the saw-tooth.
        let ex = plan(&cs, &model, &pts, Method::Extensile).expect("extensile plans");
        assert!(ex.moves() <= 2, "{:?}", ex.legs[0].waypoints);
        assert!(ex.path_length_deg() < nb.path_length_deg());
        for (a, b) in ex.segments() {
            let (na, nb_) = (cs.grid.node_at(&a), cs.grid.node_at(&b));
            let (Some(na), Some(nb_)) = (na, nb_) else {
                panic!("waypoints on the grid")
            };
            assert!(crate::plan::shorten::inspected_nodes(na, nb_)
                .iter()
                .all(|&q| cs.is_free(q)));
        }
    }
}
