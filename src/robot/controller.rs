//! The controller's joint convention, kept beside the URDF in `<stem>.controller.yaml`.
//!
//! URDF cannot say that the IRB 1400's controller reports axis 3 as the forearm angle to the
//! horizontal (`rax3 = q3 + q2`, a parallelogram drive), nor that axis 3 has a coupled range, nor
//! the controller's axis speeds and accelerations. This small file does. A URDF without one is
//! taken as a serial arm with its own limits and velocities (converted to degrees).
//!
//! Each axis may give `acceleration` (deg/s^2), the peak acceleration the manipulation-time
//! estimate (`timing`) allows. It is optional: without it the axis is taken to reach full speed
//! in [`DEFAULT_RAMP_S`] along the quintic speed ramp of `timing`, whose peak acceleration is
//! 15 v / (8 t_ramp), so the default is `15 * speed / (8 * 0.4 s)`. ABB does not publish axis
//! accelerations; see `robots/irb1400.controller.yaml` for where the 0.4 s comes from.

use serde::Deserialize;
use std::path::{Path, PathBuf};

/// How controller axis values map to URDF joint values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Coupling {
    /// Controller values are URDF values.
    Serial,
    /// Controller axis 3 = URDF q3 + q2 (ABB parallel-arm robots; ROS-Industrial "J23_coupled").
    Parallelogram,
}

/// Time an axis without a stated `acceleration` takes to reach full speed, s (an estimate).
pub const DEFAULT_RAMP_S: f64 = 0.4;

/// Range (deg), maximum speed (deg/s) and, when stated, peak acceleration (deg/s^2) of one
/// controller axis.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisSpec {
    #[serde(rename = "min")]
    pub min_deg: f64,
    #[serde(rename = "max")]
    pub max_deg: f64,
    #[serde(rename = "speed")]
    pub speed_deg_s: f64,
    #[serde(rename = "acceleration", default)]
    pub acceleration_deg_s2: Option<f64>,
}

impl AxisSpec {
    /// The peak acceleration, deg/s^2: as stated, or the one that reaches full speed in
    /// [`DEFAULT_RAMP_S`] on the quintic ramp (15 v / (8 t_ramp)).
    pub fn acceleration(&self) -> f64 {
        self.acceleration_deg_s2
            .unwrap_or(15.0 * self.speed_deg_s / (8.0 * DEFAULT_RAMP_S))
    }
}

/// The controller's convention for one robot.
#[derive(Clone, Debug, PartialEq)]
pub struct Controller {
    pub coupling: Coupling,
    /// Axes 1..6.
    pub axes: [AxisSpec; 6],
    /// Range of rax3 - rax2, when the controller bounds the angle between the arms too.
    pub coupled_axis3_deg: Option<[f64; 2]>,
    /// Where it came from (None: derived from the URDF).
    pub source: Option<PathBuf>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRange {
    min: f64,
    max: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawController {
    coupling: Coupling,
    axes: Vec<AxisSpec>,
    #[serde(default)]
    coupled_axis3: Option<RawRange>,
}

/// The widest axis range gen-rapid takes (deg, each side of zero): two turns. Wider than any
/// industrial arm's axis (axis 6 reaches +-400 deg on some); a wider range (a typo, `1e300` in
/// a URDF limit) is refused, as the six-axis IK lists every turn of an axis within its range.
pub const MAX_AXIS_DEG: f64 = 720.0;

/// Why the range `lo .. hi` (deg) cannot be an axis range, if it cannot: NaN, not increasing,
/// or beyond [`MAX_AXIS_DEG`].
pub fn range_fault(lo: f64, hi: f64) -> Option<String> {
    // Written so that NaN fails too.
    if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
        return Some("min must be below max".into());
    }
    if lo < -MAX_AXIS_DEG || hi > MAX_AXIS_DEG {
        return Some(format!(
            "the range {} .. {} deg reaches beyond -{MAX_AXIS_DEG} .. {MAX_AXIS_DEG} deg (two turns each way)",
            crate::excerpt::number(lo),
            crate::excerpt::number(hi)
        ));
    }
    None
}

/// The axis speeds gen-rapid takes (deg/s): from a crawl to far beyond any arm (an IRB 1400's
/// axes turn 110 .. 280 deg/s). Outside it (a typo, `1e-300`), the time estimate would write
/// hundreds of digits into the module header.
pub const AXIS_SPEED_DEG_S: [f64; 2] = [0.1, 10_000.0];
/// The axis accelerations gen-rapid takes (deg/s^2), for the same reason.
pub const AXIS_ACCELERATION_DEG_S2: [f64; 2] = [0.1, 1_000_000.0];

/// Why `v` cannot be an axis speed or acceleration (`what`, `unit`), if it cannot.
pub fn rate_fault(v: f64, [lo, hi]: [f64; 2], what: &str, unit: &str) -> Option<String> {
    // Written so that NaN fails too.
    (!(lo..=hi).contains(&v)).then(|| {
        format!(
            "{what} {} {unit} is outside {lo} .. {hi} {unit}",
            crate::excerpt::number(v)
        )
    })
}

/// `robots/irb1400.urdf` -> `robots/irb1400.controller.yaml`.
pub fn path_beside(urdf_path: &Path) -> PathBuf {
    urdf_path.with_extension("controller.yaml")
}

/// Parses a controller file; the message says what is wrong (with line:column when YAML is).
pub fn parse(text: &str) -> Result<Controller, String> {
    let raw: RawController = serde_saphyr::from_str(text).map_err(|e| match e.location() {
        Some(loc) => format!(
            "{}:{}: {}",
            loc.line(),
            loc.column(),
            first_line(&e.to_string())
        ),
        None => e.to_string(),
    })?;
    let axes: [AxisSpec; 6] = raw
        .axes
        .try_into()
        .map_err(|v: Vec<AxisSpec>| format!("`axes` must list 6 axes, found {}", v.len()))?;
    for (i, a) in axes.iter().enumerate() {
        if let Some(fault) = range_fault(a.min_deg, a.max_deg) {
            return Err(format!("axis {}: {fault}", i + 1));
        }
        if !(a.speed_deg_s.is_finite() && a.speed_deg_s > 0.0) {
            return Err(format!("axis {}: speed must be positive", i + 1));
        }
        if let Some(fault) = rate_fault(a.speed_deg_s, AXIS_SPEED_DEG_S, "speed", "deg/s") {
            return Err(format!("axis {}: {fault}", i + 1));
        }
        if let Some(acc) = a.acceleration_deg_s2 {
            if !(acc.is_finite() && acc > 0.0) {
                return Err(format!("axis {}: acceleration must be positive", i + 1));
            }
            let fault = rate_fault(acc, AXIS_ACCELERATION_DEG_S2, "acceleration", "deg/s^2");
            if let Some(fault) = fault {
                return Err(format!("axis {}: {fault}", i + 1));
            }
        }
    }
    let coupled_axis3_deg = match raw.coupled_axis3 {
        Some(r) => match range_fault(r.min, r.max) {
            None => Some([r.min, r.max]),
            Some(fault) => return Err(format!("coupled_axis3: {fault}")),
        },
        None => None,
    };
    Ok(Controller {
        coupling: raw.coupling,
        axes,
        coupled_axis3_deg,
        source: None,
    })
}

fn first_line(s: &str) -> &str {
    s.lines().next().unwrap_or(s)
}
