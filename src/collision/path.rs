//! The clearance proof along a process move: the whole robot model (link cylinders and tool
//! shapes) keeps the clearance along the path the controller runs, not only at its samples.
//!
//! Input: a [`FollowedPath`] (`robot::ik::follow`): joint samples along a `MoveL` line or
//! `MoveC` arc, and per chord between two samples a bound `delta_i` (per controller axis) on how
//! far the joints the controller runs stray from the straight joint chord between them.
//!
//! # The argument
//! Take a chord from sample `q_k` to `q_{k+1}`. Every configuration `p` the controller passes
//! between the two samples lies within `delta_i` of a configuration `c` of the chord on every
//! axis `i` (the follower's bound). Through the controller's linear coupling, URDF joint `j`
//! differs by at most `dq_j = sum_i |A_ji| delta_i` between them. Along the straight joint segment
//! from `c` to `p`, any point of part `P` moves at most `sum_j R[j][P] dq_j` (the reach bounds
//! of `proof.rs`: `R[j][P]` bounds the distance of any point of `P` from joint `j`'s axis in any
//! configuration). So with the chord's margin
//!
//! ```text
//! m_k = max_P sum_j R[j][P] dq_j
//! ```
//!
//! the distance between any part and any box at `p` is at least its distance at `c` less
//! `m_k`. Hence if the straight chord keeps `clearance + m_k` (the whole-move proof,
//! [`CollisionModel::move_keeps`], conservative and exact in its own right), the controller's
//! path between the two samples keeps `clearance`. The chords cover the path from its start to
//! its end, so the whole path keeps it. The smallest clearance certified for the path is the
//! least over the chords of the chord's certified smallest clearance
//! ([`CollisionModel::min_clearance_along`], within [`PATH_CLEARANCE_TOL_MM`]) less its margin,
//! with the part and obstacle of that chord's witness.
//!
//! The follower's `delta` is a proof, not an estimate (`robot::ik::follow`, "The deviation
//! bound": the branch's closed form enclosed in interval arithmetic with derivatives over the
//! chord), under its one assumption: the controller runs the continuous inverse kinematics of
//! the path's pose from the start joints. With the follower's tolerance of 0.005 deg on every
//! axis, `m_k` is at most about half a millimetre on an arm of the IRB 1400's size with a tool,
//! typically far less (most axes bend much less than the tolerance).
//!
//! Where a chord fails, the place is where the whole-move proof at `clearance + m_k` fails on
//! it ([`CollisionModel::first_contact`]: the earliest pair closer than that, or that cannot
//! be proven), as a progress and the TCP position there, with the part and the obstacle. A path
//! that only grazes (its parts come within the clearance without touching) is refused as one
//! that collides; one whose clearance lies within `m_k` above the clearance may be refused too
//! (the proof is conservative).
//!
//! The model is not rebuilt per chord: the proof asks the cell's model at the raised clearance
//! (the boxes are clipped with [`super::CLIP_MARGIN_MM`] to spare, far above any margin).

use super::{Blocked, Clearance, CollisionModel};
use crate::robot::ik::follow::{FollowedPath, Where};
use std::fmt;

/// The tolerance of each chord's certified smallest clearance, mm (that of the planned moves).
pub const PATH_CLEARANCE_TOL_MM: f64 = 0.05;

/// A path proven to keep the clearance.
#[derive(Clone, Debug, PartialEq)]
pub struct PathClearance {
    /// The certified smallest clearance along the path and where (part, obstacle); `None`
    /// without obstacles.
    pub clearance: Option<Clearance>,
    /// The largest margin any chord took for the path between its samples, mm.
    pub margin_mm: f64,
    /// How many chords were proven.
    pub chords: usize,
}

/// Where and why a path does not keep the clearance.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub struct PathBlocked {
    pub at: Where,
    /// The part, the obstacle and the distance (or the failing bound) on the chord there.
    pub blocked: Blocked,
    /// The clearance asked, mm.
    pub clearance_mm: f64,
    /// The margin the chord took for the path between its samples, mm: the chord had to keep
    /// `clearance_mm + margin_mm`.
    pub margin_mm: f64,
}

impl fmt::Display for PathBlocked {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.blocked {
            Blocked::Contact {
                part,
                obstacle,
                distance_mm,
            } if *distance_mm >= self.clearance_mm => write!(
                f,
                "{}: {part} cannot be proven to keep {:.1} mm from obstacle '{obstacle}' \
                 ({distance_mm:.1} mm there on the straight joint move between two samples, \
                 which must keep {:.3} mm more for the path the controller runs)",
                self.at, self.clearance_mm, self.margin_mm
            ),
            blocked => write!(f, "{}: {blocked}", self.at),
        }
    }
}

impl CollisionModel {
    /// The most any point of any part (link cylinder or tool shape) moves when every controller
    /// axis `i` changes by at most `delta_deg[i]`: `max_P sum_j R[j][P] dq_j` with
    /// `dq_j = sum_i |A_ji| delta_i` through the coupling (module docs), raised a little over
    /// its float value.
    pub fn motion_bound_mm(&self, delta_deg: &[f64; 6]) -> f64 {
        let zero = self.robot.urdf_joints_deg(&[0.0; 6]);
        let mut dq = [0.0f64; 6];
        for (i, d) in delta_deg.iter().enumerate() {
            let mut unit = [0.0; 6];
            unit[i] = 1.0;
            let column = self.robot.urdf_joints_deg(&unit);
            for (j, q) in dq.iter_mut().enumerate() {
                *q += (column[j] - zero[j]).abs() * d.abs();
            }
        }
        (0..self.part_count())
            .map(|p| {
                let r = self.part_reach(p);
                (0..6).map(|j| r[j] * dq[j].to_radians()).sum::<f64>()
            })
            .fold(0.0, f64::max)
            * (1.0 + 1e-9)
            + 1e-9
    }

    /// Proves that the controller's path of `followed` keeps the clearance for every link
    /// cylinder and tool shape, and certifies its smallest clearance (module docs). The samples
    /// are in range (the follower checks it).
    pub fn prove_path(&self, followed: &FollowedPath) -> Result<PathClearance, PathBlocked> {
        let samples = followed.samples();
        let deviations = followed.deviations_deg();
        // A path that does not move is its one configuration.
        let chords: Vec<(usize, usize, [f64; 6])> = if samples.len() < 2 {
            vec![(0, 0, [0.0; 6])]
        } else {
            (0..samples.len() - 1)
                .map(|k| (k, k + 1, deviations.get(k).copied().unwrap_or([0.0; 6])))
                .collect()
        };
        let mut least: Option<Clearance> = None;
        let mut largest_margin = 0.0f64;
        for &(i, j, delta) in &chords {
            let (Some(a), Some(b)) = (samples.get(i), samples.get(j)) else {
                continue;
            };
            let (from, to) = (&a.joints_deg, &b.joints_deg);
            let margin = self.motion_bound_mm(&delta);
            let c = self.clearance_mm + margin;
            if !self.move_keeps(from, to, c) {
                let (t, blocked) = self.first_contact(from, to, c).unwrap_or_else(|| {
                    // `first_contact` finds what `move_keeps` refused; should it not, the
                    // chord's closest pair is named.
                    let witness = self.min_clearance_along(from, to, PATH_CLEARANCE_TOL_MM);
                    (
                        0.5,
                        witness.map_or(
                            Blocked::Contact {
                                part: self.part(0),
                                obstacle: String::new(),
                                distance_mm: 0.0,
                            },
                            |w| Blocked::Contact {
                                part: w.part,
                                obstacle: w.obstacle,
                                distance_mm: w.mm,
                            },
                        ),
                    )
                });
                let s = a.s + t * (b.s - a.s);
                return Err(PathBlocked {
                    at: followed.place_at(s),
                    blocked,
                    clearance_mm: self.clearance_mm,
                    margin_mm: margin,
                });
            }
            largest_margin = largest_margin.max(margin);
            if let Some(w) = self.min_clearance_along(from, to, PATH_CLEARANCE_TOL_MM) {
                let mm = (w.mm - margin).max(0.0);
                if least.as_ref().is_none_or(|l| mm < l.mm) {
                    least = Some(Clearance { mm, ..w });
                }
            }
        }
        Ok(PathClearance {
            clearance: least,
            margin_mm: largest_margin,
            chords: chords.len(),
        })
    }
}
