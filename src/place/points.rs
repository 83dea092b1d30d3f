//! Every cell point resolved to all six axes from one placement.
//!
//! - **`joints` points** are used as given (the cell validation has them at the written
//!   precision); axes 4..6 are the point's own when it gives all six, else `robot.wrist`.
//! - **`xyz` points** (wrist centre, cell frame, mm) are moved into the robot frame and solved by
//!   [`ik::choose`] (solution closest to the previous point, or the most upright arm for the
//!   first; `branch:` forces one of the four), with `robot.wrist` for axes 4..6. The solution is
//!   rounded to the written precision ([`quantize_joints`]) and it is the *rounded* value that
//!   must be in range and free of collision and that the plan and the module use. Rounding moves
//!   each axis by at most 0.0005 deg = 8.7e-6 rad, so the wrist centre moves by at most
//!   `(r + a2 + L) x 8.7e-6` mm (`r` the wrist's distance from axis 1, `L` the forearm; the
//!   upper arm's lever is `a2` for a parallelogram robot, at most `a2 + L` for a serial one):
//!   about 0.025 mm on the IRB 1400 (`r <= 1444`), always under 0.05 mm. A point that cannot be
//!   solved fails with the point's name, its line, the base used and why each solution was
//!   refused (out of range by how much, or which link hits which obstacle), as `ik::choose`
//!   found it.
//! - **`robtarget` points** (TCP pose in the work object) are solved on all six axes by
//!   `robtarget.rs`, nearest the previous point unless the point gives its confdata.
//! - **revisits** (`{ revisit: NAME }`) take the very joints (and origin) of the point they
//!   name, earlier or later in the list, with their own motion; the point after a revisit of a
//!   later point is solved near the last point resolved before it.
//!
//! A `joints` point outside the robot's ranges (all six axes, its own wrist or `robot.wrist`) is
//! an input error at its line. Every point also gets the motion of the move into it.

use super::robtarget::Tcp;
use super::{ranges_source, MoveMotion, Origin, PlaceError, PlacedPoint, Placement, PoseCheck};
use crate::cell::{Cell, Target};
use crate::precision::quantize_joints;
use crate::robot::ik::{self, ArmGeometry, IkError};
use crate::robot::{RangeViolation, Robot};

/// Resolves every point of `cell` with the robot at `placement`; `check` is the collision model
/// of that placement. `geom` is the arm geometry when the caller has it (else it is derived
/// here, for the first `xyz` point).
pub(super) fn resolve(
    cell: &Cell,
    robot: &Robot,
    geom: Option<&ArmGeometry>,
    placement: Placement,
    check: &impl PoseCheck,
) -> Result<Vec<PlacedPoint>, PlaceError> {
    let tcp = super::needs_tcp(cell)
        .then(|| Tcp::of(cell, robot))
        .transpose()?;
    let mut points: Vec<PlacedPoint> = Vec::with_capacity(cell.points.len());
    // A revisit of a later point: its place in `points` until that point is resolved.
    let mut later: Vec<(usize, usize)> = Vec::new();
    for (i, p) in cell.points.iter().enumerate() {
        let motion = MoveMotion {
            speed: p.speed.clone().unwrap_or_else(|| cell.motion.speed.clone()),
            zone: p.zone.clone().unwrap_or_else(|| cell.motion.zone.clone()),
        };
        // A revisit reaches the very joints of the point it names (its data is written once).
        if let Some(j) = p.revisit_of {
            // An earlier point is resolved already (`j < i`); a later one is not.
            let base = points.get(j).cloned().unwrap_or_else(|| {
                later.push((i, j));
                // Filled in below, once point `j` is resolved.
                PlacedPoint {
                    name: p.name.clone(),
                    joints_deg: [0.0; 6],
                    loc: p.loc,
                    origin: Origin::Joints,
                    motion: motion.clone(),
                }
            });
            points.push(PlacedPoint {
                loc: p.loc,
                motion,
                ..base
            });
            continue;
        }
        let (axes_deg, wrist_deg, origin) = match &p.target {
            Target::Joints {
                axes_deg,
                wrist_deg,
            } => {
                let wrist = wrist_deg.unwrap_or(cell.robot.wrist_deg);
                robot
                    .check_range6(&six(*axes_deg, wrist))
                    .map_err(|violation| PlaceError::Range {
                        what: match (wrist_deg, &violation) {
                            (None, RangeViolation::Axis { axis: 4.., .. }) => {
                                format!("point '{}' (axes 4..6 from robot.wrist)", p.name)
                            }
                            _ => format!("point '{}'", p.name),
                        },
                        violation,
                        ranges: ranges_source(robot),
                        loc: p.loc,
                    })?;
                (*axes_deg, wrist, Origin::Joints)
            }
            Target::Robtarget { pose, conf } => {
                let derived;
                let tcp = match &tcp {
                    Some(t) => t,
                    None => {
                        derived = Tcp::of(cell, robot)?;
                        &derived
                    }
                };
                let previous = previous_of(&points, &later);
                let (q, conf) = tcp.solve(p, pose, *conf, placement, previous.as_ref(), check)?;
                (
                    arm(&q),
                    [q[3], q[4], q[5]],
                    Origin::Robtarget { pose: *pose, conf },
                )
            }
            Target::Xyz {
                wrist_centre_mm,
                branch,
                branch_loc,
            } => {
                let local = placement.to_robot_frame(*wrist_centre_mm);
                let fail = |source: IkError| {
                    let loc = match source {
                        IkError::ForcedBranch { .. } => *branch_loc,
                        _ => p.loc,
                    };
                    PlaceError::Ik {
                        point: p.name.clone(),
                        base_mm: placement.base_mm,
                        yaw_deg: placement.yaw_deg,
                        source: Box::new(source),
                        loc,
                    }
                };
                let derived;
                let geom = match geom {
                    Some(g) => g,
                    None => {
                        derived = super::geometry(cell, robot)?;
                        &derived
                    }
                };
                let previous = previous_of(&points, &later).map(|j| arm(&j));
                let wrist = cell.robot.wrist_deg;
                let usable = |a: [f64; 3]| {
                    let a = quantize_joints(a);
                    let joints = [a[0], a[1], a[2], wrist[0], wrist[1], wrist[2]];
                    match check.why_blocked(&joints) {
                        None => Ok(()),
                        Some(why) => Err(why),
                    }
                };
                let sol =
                    ik::choose(robot, geom, local, previous, *branch, usable).map_err(fail)?;
                (
                    quantize_joints(sol.axes_deg),
                    cell.robot.wrist_deg,
                    Origin::Xyz {
                        wrist_centre_mm: *wrist_centre_mm,
                        branch: sol.branch,
                    },
                )
            }
        };
        points.push(PlacedPoint {
            name: p.name.clone(),
            joints_deg: six(axes_deg, wrist_deg),
            loc: p.loc,
            origin,
            motion,
        });
    }
    for (i, j) in later {
        if let (Some(source), Some(revisit)) = (points.get(j).cloned(), points.get(i)) {
            let (loc, motion) = (revisit.loc, revisit.motion.clone());
            if let Some(slot) = points.get_mut(i) {
                *slot = PlacedPoint {
                    loc,
                    motion,
                    ..source
                };
            }
        }
    }
    Ok(points)
}

/// The joints the next point is solved near: the last point resolved (a revisit of a later
/// point is not yet, and is skipped).
fn previous_of(points: &[PlacedPoint], later: &[(usize, usize)]) -> Option<[f64; 6]> {
    (0..points.len())
        .rev()
        .find(|k| !later.iter().any(|(i, _)| i == k))
        .and_then(|k| points.get(k))
        .map(|w| w.joints_deg)
}

/// Axes 1..3 of six.
fn arm(j: &[f64; 6]) -> [f64; 3] {
    [j[0], j[1], j[2]]
}

/// Six axes from the arm's three and the wrist's three.
fn six(a: [f64; 3], w: [f64; 3]) -> [f64; 6] {
    [a[0], a[1], a[2], w[0], w[1], w[2]]
}
