//! The joints a controller runs along a TCP path (`MoveL`, `MoveC`): the IK branch that continues
//! from the joints where the move starts. At each step the solution of the path's pose nearest
//! the previous joints (`Ik::nearest`: every branch, its axes turned by whole turns nearest the
//! previous ones) is taken; a step is accepted only when no axis moves more than [`STEP_DEG`]
//! and no point of the arm or tool more than the dense check's sampling step (by the bound of
//! `reach.rs`, as the dense check bounds a straight move), else it is halved. A step
//! that cannot be made small enough (the nearest solution stays far from the previous one at a
//! progress step of [`MIN_STEP`]) is a jump: a configuration change or a singularity the
//! controller cannot follow. Every accepted sample must lie in the axis ranges (the coupled
//! axis-3 range too) and keep axis 5 at least [`WRIST_MIN_DEG`] from 0; between samples no axis
//! moves more than [`STEP_DEG`], so those hold within that much everywhere.

use super::opw::{max_diff, Ik};
use super::reach::Reach;
use nalgebra::Isometry3;

/// The most any axis moves between accepted samples, deg.
pub const STEP_DEG: f64 = 0.05;
/// The smallest progress step tried before a step is called a jump.
pub const MIN_STEP: f64 = 1e-9;
/// The largest progress step, so a path whose joints hardly move is still sampled.
pub const MAX_STEP: f64 = 1.0 / 64.0;
/// Axis 5 must stay at least this far from 0 (the wrist singularity), deg.
pub const WRIST_MIN_DEG: f64 = 1.0;

/// One accepted sample: the progress along the path and the joints (controller values).
#[derive(Clone, Copy, Debug)]
pub struct Sample {
    pub s: f64,
    pub axes: [f64; 6],
}

/// Where and why the controller cannot follow the path.
#[derive(Clone, Debug)]
pub struct Stop {
    /// The progress where it stops.
    pub s: f64,
    /// The last joints it reached.
    pub axes: [f64; 6],
    pub why: String,
}

/// Follows `tool0_at` (tool0's pose in the robot base frame at progress 0 .. 1) from `start`,
/// no point of the arm or tool moving more than `step_mm` between samples by `reach`'s bound.
pub fn follow(
    ik: &Ik,
    tool0_at: &dyn Fn(f64) -> Isometry3<f64>,
    start: [f64; 6],
    reach: &Reach,
    step_mm: f64,
) -> Result<Vec<Sample>, Stop> {
    let robot = ik.robot;
    let motion_mm = |a: &[f64; 6], b: &[f64; 6]| reach.motion_mm(robot, a, b);
    let admissible = |s: f64, axes: &[f64; 6]| -> Result<(), Stop> {
        let stop = |why: String| Stop {
            s,
            axes: *axes,
            why,
        };
        if let Err(e) = robot.check_range6(axes) {
            return Err(stop(format!("out of range: {e}")));
        }
        if axes[4].abs() < WRIST_MIN_DEG {
            return Err(stop(format!(
                "within {WRIST_MIN_DEG} deg of the wrist singularity (axis 5 = {:.3} deg)",
                axes[4]
            )));
        }
        Ok(())
    };
    admissible(0.0, &start)?;
    let mut samples = vec![Sample {
        s: 0.0,
        axes: start,
    }];
    let (mut s, mut q, mut ds) = (0.0, start, MAX_STEP);
    while s < 1.0 {
        let t = (s + ds).min(1.0);
        match ik.nearest(&tool0_at(t), &q) {
            Some(n) if max_diff(&n, &q) <= STEP_DEG && motion_mm(&q, &n) <= step_mm => {
                admissible(t, &n)?;
                samples.push(Sample { s: t, axes: n });
                (s, q) = (t, n);
                ds = (2.0 * ds).min(MAX_STEP);
            }
            _ if t - s > MIN_STEP => ds = (t - s) / 2.0,
            None => {
                return Err(Stop {
                    s: t,
                    axes: q,
                    why: "the pose is out of reach".into(),
                })
            }
            Some(n) => {
                let k = (0..6)
                    .max_by(|&i, &j| (n[i] - q[i]).abs().total_cmp(&(n[j] - q[j]).abs()))
                    .unwrap_or(0);
                return Err(Stop {
                    s: t,
                    axes: q,
                    why: format!(
                        "a jump: at a progress step of {:.0e} the nearest solution moves axis {} from {:.3} to {:.3} deg (a configuration change or a singularity)",
                        t - s,
                        k + 1,
                        q[k],
                        n[k]
                    ),
                });
            }
        }
    }
    Ok(samples)
}
