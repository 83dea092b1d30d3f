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
use serde_saphyr::Spanned;
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
    /// An axis not yet read: every figure zero (each is set before use).
    pub const UNSET: AxisSpec = AxisSpec {
        min_deg: 0.0,
        max_deg: 0.0,
        speed_deg_s: 0.0,
        acceleration_deg_s2: None,
    };

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
    min: Spanned<f64>,
    max: Spanned<f64>,
}

/// One axis as written, every value with its place (a fault is pointed at in the file).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAxis {
    min: Spanned<f64>,
    max: Spanned<f64>,
    speed: Spanned<f64>,
    #[serde(default)]
    acceleration: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawController {
    coupling: Coupling,
    axes: Spanned<Vec<Spanned<RawAxis>>>,
    #[serde(default)]
    coupled_axis3: Option<Spanned<RawRange>>,
}

/// Why a controller file was refused, and where in it (1-based line and column; 0 when the
/// reader gives no place).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct ControllerFault {
    pub message: String,
    pub line: u64,
    pub column: u64,
}

impl ControllerFault {
    fn at<T>(s: &Spanned<T>, message: String) -> ControllerFault {
        ControllerFault {
            message,
            line: s.referenced.line(),
            column: s.referenced.column(),
        }
    }
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

/// Parses a controller file; the fault says what is wrong and where in the file.
pub fn parse(text: &str) -> Result<Controller, ControllerFault> {
    let raw: RawController = serde_saphyr::from_str(text).map_err(|e| {
        let (line, column) = e.location().map_or((0, 0), |l| (l.line(), l.column()));
        ControllerFault {
            message: crate::excerpt::message(first_line(
                &serde_saphyr::MessageFormatter::format_message(
                    &serde_saphyr::DefaultMessageFormatter,
                    &e,
                ),
            ))
            .into_owned(),
            line,
            column,
        }
    })?;
    // A key given no value (`acceleration:` alone) is refused, never taken as left out.
    if let Some(b) = crate::blank_key::first_blank_key(text, serde_saphyr::Options::default()) {
        return Err(ControllerFault {
            message: crate::blank_key::BlankKey::message(&crate::excerpt::value(&b.key)),
            line: b.line,
            column: b.column,
        });
    }
    if raw.axes.value.len() != 6 {
        return Err(ControllerFault::at(
            &raw.axes,
            format!("`axes` must list 6 axes, found {}", raw.axes.value.len()),
        ));
    }
    let mut axes = [AxisSpec::UNSET; 6];
    for (i, (slot, a)) in axes.iter_mut().zip(&raw.axes.value).enumerate() {
        let a = &a.value;
        let axis = i + 1;
        if let Some(fault) = range_fault(a.min.value, a.max.value) {
            return Err(ControllerFault::at(&a.min, format!("axis {axis}: {fault}")));
        }
        let speed = a.speed.value;
        if !(speed.is_finite() && speed > 0.0) {
            return Err(ControllerFault::at(
                &a.speed,
                format!("axis {axis}: speed must be positive"),
            ));
        }
        if let Some(fault) = rate_fault(speed, AXIS_SPEED_DEG_S, "speed", "deg/s") {
            return Err(ControllerFault::at(
                &a.speed,
                format!("axis {axis}: {fault}"),
            ));
        }
        if let Some(acc) = &a.acceleration {
            if !(acc.value.is_finite() && acc.value > 0.0) {
                return Err(ControllerFault::at(
                    acc,
                    format!("axis {axis}: acceleration must be positive"),
                ));
            }
            let fault = rate_fault(
                acc.value,
                AXIS_ACCELERATION_DEG_S2,
                "acceleration",
                "deg/s^2",
            );
            if let Some(fault) = fault {
                return Err(ControllerFault::at(acc, format!("axis {axis}: {fault}")));
            }
        }
        *slot = AxisSpec {
            min_deg: a.min.value,
            max_deg: a.max.value,
            speed_deg_s: speed,
            acceleration_deg_s2: a.acceleration.as_ref().map(|x| x.value),
        };
    }
    let coupled_axis3_deg = match &raw.coupled_axis3 {
        Some(r) => match range_fault(r.value.min.value, r.value.max.value) {
            None => Some([r.value.min.value, r.value.max.value]),
            Some(fault) => {
                return Err(ControllerFault::at(
                    &r.value.min,
                    format!("coupled_axis3: {fault}"),
                ))
            }
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
