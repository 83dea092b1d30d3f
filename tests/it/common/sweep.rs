//! The clearance along everything the controller runs (`controller.rs`'s [`Run`]), every move
//! but the first (which reaches the start from wherever the robot is): a straight joint move
//! (`MoveAbsJ`, `MoveJ`) sampled so that no point of the arm or the tool moves more than the
//! sampling step between samples (`reach.rs`: a tenth of the clearance, at most 1 mm), a
//! followed `MoveL` or `MoveC` at the samples `follow.rs` took (no point moves more than the
//! step between them either, by the same bound), each sample measured with parry3d
//! (`Scene::nearest`: every collision shape of the robot's URDF and the cell's tool shapes,
//! against every box). So the true minimum along a move lies at most half a step below the
//! smallest sample (along a followed move, between two samples the joints follow the IK, not a
//! straight line; with steps of at most 0.05 deg per axis the two differ far less than that).
//!
//! A corner written with a fly-by zone between two joint moves is sampled over its triangle in
//! joint space (the midpoint of the move in, the waypoint, the midpoint of the move out), as the
//! controller's blend of two joint moves stays in it. A zone at a corner next to a `MoveL` or
//! `MoveC` is refused: the controller's Cartesian blend there is not modelled here. The first
//! and last moves end `fine`.

use super::controller::{JointPath, Run};
use super::dense::{Nearest, Scene};

/// Most motion of any point of the arm or tool between neighbouring samples of a corner
/// triangle, mm (a triangle is sampled over an area, so more coarsely than a move).
pub const CORNER_STEP_MM: f64 = 4.0;

/// What [`sweep`] measured.
#[derive(Debug)]
pub struct Sweep {
    /// Poses measured along the moves and over the zoned corners.
    pub samples: usize,
    /// Corners written with a fly-by zone, each sampled over its triangle.
    pub corners: usize,
    /// The nearest approach seen (infinite without boxes).
    pub smallest: Nearest,
    /// The smallest corner sample less the step reached there (a bound below the corners'
    /// minimum), infinite without corners.
    pub corner_smallest: f64,
    pub failures: Vec<String>,
}

/// The midpoint of two six-axis configurations.
fn mid(a: &[f64; 6], b: &[f64; 6]) -> [f64; 6] {
    std::array::from_fn(|k| 0.5 * (a[k] + b[k]))
}

fn fine(zone: &str) -> bool {
    zone.eq_ignore_ascii_case("fine")
}

/// Measures the clearance along `run` in `scene` against `clearance_mm` (module doc).
pub fn sweep(scene: &Scene, run: &Run, clearance_mm: f64) -> Sweep {
    let mut out = Sweep {
        samples: 0,
        corners: 0,
        smallest: Nearest {
            mm: f64::INFINITY,
            link: String::new(),
            obstacle: String::new(),
        },
        corner_smallest: f64::INFINITY,
        failures: Vec::new(),
    };
    let below = |mm: f64| mm < clearance_mm - 1e-6;
    for (k, m) in run.moves.iter().enumerate() {
        let Some(a) = m.from else { continue };
        match &m.path {
            JointPath::Straight => {
                let b = m.to;
                let n = scene.steps_along(&a, &b);
                for i in 0..=n {
                    let t = i as f64 / n as f64;
                    let axes: [f64; 6] = std::array::from_fn(|k| a[k] + t * (b[k] - a[k]));
                    let near = scene.nearest(axes);
                    out.samples += 1;
                    let hit = below(near.mm);
                    if hit {
                        out.failures.push(format!(
                            "move {} -> {} at t = {t:.4} ({axes:?}): {} is {:.3} mm from {}, below the clearance {clearance_mm} mm",
                            run.moves[k - 1].target, m.target, near.link, near.mm, near.obstacle
                        ));
                    }
                    if near.mm < out.smallest.mm {
                        out.smallest = near;
                    }
                    if hit {
                        break; // one message per move
                    }
                }
            }
            JointPath::Followed { samples, .. } => {
                for smp in samples {
                    let near = scene.nearest(smp.axes);
                    out.samples += 1;
                    let hit = below(near.mm);
                    if hit {
                        out.failures.push(format!(
                            "{} at {:.2} %{} ({:?}): {} is {:.3} mm from {}, below the clearance {clearance_mm} mm",
                            m.label,
                            100.0 * smp.s,
                            m.tcp_at(smp.s),
                            smp.axes,
                            near.link,
                            near.mm,
                            near.obstacle
                        ));
                    }
                    if near.mm < out.smallest.mm {
                        out.smallest = near;
                    }
                    if hit {
                        break;
                    }
                }
            }
        }
    }
    let ends = [run.moves.first(), run.moves.last()];
    for m in ends.into_iter().flatten() {
        if !fine(&m.zone) {
            out.failures
                .push(format!("the move to {} is {}, not fine", m.target, m.zone));
        }
    }
    for k in 1..run.moves.len().saturating_sub(1) {
        let (this, next) = (&run.moves[k], &run.moves[k + 1]);
        if fine(&this.zone) {
            continue;
        }
        let (JointPath::Straight, JointPath::Straight, Some(p)) =
            (&this.path, &next.path, this.from)
        else {
            out.failures.push(format!(
                "{}: zone {} next to a MoveL or MoveC: the controller's blend there is not checked (write fine)",
                this.label, this.zone
            ));
            continue;
        };
        out.corners += 1;
        let (v, n) = (this.to, next.to);
        let tri = [mid(&p, &v), v, mid(&v, &n)];
        let (near, count, step) = scene.nearest_over_triangle(&tri, CORNER_STEP_MM);
        out.samples += count;
        if below(near.mm) {
            out.failures.push(format!(
                "corner at {} ({}): {} is {:.3} mm from {}, below the clearance {clearance_mm} mm",
                this.target, this.zone, near.link, near.mm, near.obstacle
            ));
        }
        out.corner_smallest = out.corner_smallest.min(near.mm - step);
        if near.mm < out.smallest.mm {
            out.smallest = near;
        }
    }
    out
}
