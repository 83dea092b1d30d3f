//! Value checks shared by the sections: numbers finite and no finer than the module states them,
//! triples, poses with normalised quaternions (given as quaternions or as RAPID's `OrientZYX`
//! angles), RAPID names. Each refusal points at the value.

use super::super::raw::{RawPart, RawPose};
use super::super::{CellError, Frame, Loc, QUATERNION_NORM_TOL};
use crate::excerpt;
use crate::input::MAX_MAGNITUDE;
use crate::names::{
    check_data_name, check_data_type, check_identifier, check_module_name, DataType,
    IdentifierError,
};
use crate::precision::{self, JOINT_DECIMALS, MASS_DECIMALS, POSITION_DECIMALS};
use crate::robot::ik::six::ConfData;
use serde_saphyr::Spanned;

pub(super) fn loc<T>(s: &Spanned<T>) -> Loc {
    Loc::from(s.referenced)
}

pub(super) fn invalid(loc: Loc, message: impl Into<String>) -> CellError {
    CellError::Invalid {
        loc,
        message: message.into(),
        help: None,
    }
}

pub(super) fn invalid_help(
    loc: Loc,
    message: impl Into<String>,
    help: impl Into<String>,
) -> CellError {
    CellError::Invalid {
        loc,
        message: message.into(),
        help: Some(help.into()),
    }
}

/// The help line of a NaN or an infinity.
const FINITE_HELP: &str = "write plain numbers: `.nan` and `.inf` are YAML's not-a-number and infinity, no length or angle";

/// Every value of the list finite and within [`MAX_MAGNITUDE`].
pub(super) fn finite(v: &Spanned<Vec<f64>>, what: &str) -> Result<(), CellError> {
    if !v.value.iter().all(|x| x.is_finite()) {
        return Err(invalid_help(
            loc(v),
            format!("{what}: every value must be a finite number"),
            FINITE_HELP,
        ));
    }
    match v.value.iter().find(|x| x.abs() > MAX_MAGNITUDE) {
        Some(x) => Err(too_large(loc(v), what, *x)),
        None => Ok(()),
    }
}

/// A scalar finite and within [`MAX_MAGNITUDE`]; `rule` says what else it must be, for the
/// message of a non-finite value (`a number > 0 (kg)`).
pub(super) fn bounded(v: &Spanned<f64>, what: &str, rule: &str) -> Result<f64, CellError> {
    if !v.value.is_finite() {
        return Err(invalid_help(
            loc(v),
            format!("{what} must be {rule}"),
            FINITE_HELP,
        ));
    }
    if v.value.abs() > MAX_MAGNITUDE {
        return Err(too_large(loc(v), what, v.value));
    }
    Ok(v.value)
}

/// The refusal of a value beyond [`MAX_MAGNITUDE`].
fn too_large(loc: Loc, what: &str, x: f64) -> CellError {
    invalid_help(
        loc,
        format!(
            "{what}: {} is too large: a cell's numbers lie within -{m} .. {m}",
            excerpt::number(x),
            m = MAX_MAGNITUDE
        ),
        "lengths are in mm (1000000 mm is 1 km), angles in degrees and the mass in kg; is a unit or an exponent wrong?",
    )
}

pub(super) fn triple(v: &Spanned<Vec<f64>>, what: &str) -> Result<[f64; 3], CellError> {
    finite(v, what)?;
    <[f64; 3]>::try_from(v.value.as_slice()).map_err(|_| {
        invalid_help(
            loc(v),
            format!("{what} must have 3 numbers, found {}", v.value.len()),
            "write three numbers in brackets, `[x, y, z]` (mm; robot.wrist: axes 4, 5, 6 in deg)",
        )
    })
}

/// Checks that `v` has at most `n` decimals: the module header states it with that many, and
/// must state exactly what was used (`robot.base`, `robot.yaw`).
pub(super) fn decimals(
    v: f64,
    n: usize,
    loc: Loc,
    what: &str,
    unit: &str,
) -> Result<f64, CellError> {
    let s = if n == 1 { "" } else { "s" };
    finer_than(v, n, loc, what, format!("the module header states {what} to {n} decimal{s} ({unit}); give no more, so it states what was used"))
}

/// Refuses `v` with more than `n` decimals.
fn finer_than(v: f64, n: usize, loc: Loc, what: &str, help: String) -> Result<f64, CellError> {
    if precision::exceeds(v, n) {
        let s = if n == 1 { "" } else { "s" };
        return Err(invalid_help(
            loc,
            format!(
                "{what} = {} has more than {n} decimal{s}",
                excerpt::number(v)
            ),
            help,
        ));
    }
    Ok(v)
}

/// A position the module writes (robtarget, tframe, uframe, cog): 3 finite numbers, mm, at most
/// [`POSITION_DECIMALS`] decimals.
pub(super) fn position(v: &Spanned<Vec<f64>>, what: &str) -> Result<[f64; 3], CellError> {
    let p = triple(v, what)?;
    for x in p {
        finer_than(x, POSITION_DECIMALS, loc(v), what, format!("the module writes positions to {POSITION_DECIMALS} decimals (mm); give no more, so it states what was used"))?;
    }
    Ok(p)
}

/// A mass the module writes (the tool's, a load's; kg): finite, > 0 also when rounded to
/// [`MASS_DECIMALS`] decimals, and no finer. `help` says what a mass of 0 would mean.
pub(super) fn mass(v: &Spanned<f64>, what: &str, help: &str) -> Result<f64, CellError> {
    bounded(v, what, "a number > 0 (kg)")?;
    if v.value <= 0.0 {
        return Err(invalid_help(
            loc(v),
            format!(
                "{what} = {} must be a number > 0 (kg)",
                excerpt::number(v.value)
            ),
            help,
        ));
    }
    if precision::round(v.value, MASS_DECIMALS) <= 0.0 {
        return Err(invalid_help(
            loc(v),
            format!(
                "{what} = {} kg is 0 at the module's {MASS_DECIMALS} decimals",
                excerpt::number(v.value)
            ),
            format!("the module writes the mass to {MASS_DECIMALS} decimals (kg) and the controller refuses a mass of 0: give at least 0.001 kg"),
        ));
    }
    finer_than(v.value, MASS_DECIMALS, loc(v), what, format!("the module writes the mass to {MASS_DECIMALS} decimals (kg); give no more, so it states what was used"))
}

/// A number within `min ..= max` (`unit` names its unit) with at most `n` decimals, the
/// precision the module writes it with: `approach`, `retract` (mm), `wait_time` (s).
pub(super) fn in_range(
    v: &Spanned<f64>,
    what: &str,
    (min, max): (f64, f64),
    n: usize,
    unit: &str,
    help: &str,
) -> Result<f64, CellError> {
    let rule = format!("a number within {min} .. {max} ({unit})");
    bounded(v, what, &rule)?;
    if !(min..=max).contains(&v.value) {
        return Err(invalid_help(
            loc(v),
            format!("{what} = {} must be {rule}", excerpt::number(v.value)),
            help,
        ));
    }
    finer_than(v.value, n, loc(v), what, format!("the module writes {what} to {n} decimals ({unit}); give no more, so it states what was used"))
}

/// Checks that a joint value has at most [`JOINT_DECIMALS`] decimals; returns it rounded to them.
pub(super) fn joint_value(v: f64, loc: Loc, what: &str) -> Result<f64, CellError> {
    if precision::exceeds(v, JOINT_DECIMALS) {
        return Err(invalid_help(
            loc,
            format!(
                "{what} = {} has more than {JOINT_DECIMALS} decimals",
                excerpt::number(v)
            ),
            format!(
                "gen-rapid writes joint values to 0.{}1 deg; give at most {JOINT_DECIMALS} decimals so the point appears in the module exactly as given",
                "0".repeat(JOINT_DECIMALS - 1)
            ),
        ));
    }
    Ok(precision::round(v, JOINT_DECIMALS))
}

/// A quaternion `[q1, q2, q3, q4]` = `[w, x, y, z]`, normalised; its norm may be off 1 by at
/// most [`QUATERNION_NORM_TOL`].
pub(super) fn quaternion(v: &Spanned<Vec<f64>>, what: &str) -> Result<[f64; 4], CellError> {
    finite(v, what)?;
    let q = <[f64; 4]>::try_from(v.value.as_slice()).map_err(|_| {
        invalid_help(
            loc(v),
            format!(
                "{what} must have 4 numbers [q1, q2, q3, q4], found {}",
                v.value.len()
            ),
            "a quaternion is [w, x, y, z] as RAPID writes it; [1, 0, 0, 0] is no rotation",
        )
    })?;
    let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    if (norm - 1.0).abs() > QUATERNION_NORM_TOL {
        return Err(invalid_help(
            loc(v),
            format!("{what} {q:?} has norm {norm:.6}, not 1"),
            format!("a rotation is a unit quaternion [w, x, y, z]; gen-rapid normalises it, but a norm off by more than {QUATERNION_NORM_TOL} is taken as a typo"),
        ));
    }
    Ok(q.map(|x| x / norm))
}

/// The help line of a pose's shape.
const POSE_HELP: &str = "positions in mm in the frame the key names; orientations as quaternions [w, x, y, z] or { zyx: [ez, ey, ex] } (deg, RAPID's OrientZYX)";

/// `[[x, y, z], ORIENTATION]`, and with `conf_allowed` optionally a third list
/// `[cf1, cf4, cf6, cfx]`; the orientation a quaternion `[q1, q2, q3, q4]` or `{ zyx: [ez, ey,
/// ex] }` ([`orient_zyx`]).
pub(super) fn pose(
    v: &RawPose,
    what: &str,
    conf_allowed: bool,
) -> Result<(Frame, Option<ConfData>), CellError> {
    let shape = if conf_allowed {
        "[[x, y, z], [q1, q2, q3, q4]] or [[x, y, z], [q1, q2, q3, q4], [cf1, cf4, cf6, cfx]]"
    } else {
        "[[x, y, z], [q1, q2, q3, q4]]"
    };
    let parts = v.value.as_slice();
    let (p, q, c) = match (parts, conf_allowed) {
        ([p, q], _) => (p, q, None),
        ([p, q, c], true) => (p, q, Some(c)),
        _ => {
            return Err(invalid_help(
                loc(v),
                format!("{what} must be {shape}, found {} lists", parts.len()),
                POSE_HELP,
            ))
        }
    };
    let pos_mm = position(&numbers(p, what)?, &format!("{what} position"))?;
    let quat_wxyz = match &q.value {
        RawPart::Zyx(angles) => zyx(angles, &format!("{what} zyx"))?,
        RawPart::Numbers(_) => quaternion(&numbers(q, what)?, &format!("{what} quaternion"))?,
    };
    let frame = Frame { pos_mm, quat_wxyz };
    let conf = match c {
        Some(c) => Some(confdata(&numbers(c, what)?, &format!("{what} confdata"))?),
        None => None,
    };
    Ok((frame, conf))
}

/// A part of a pose that must be a list of numbers (a position, a quaternion, confdata).
fn numbers(part: &Spanned<RawPart>, what: &str) -> Result<Spanned<Vec<f64>>, CellError> {
    match &part.value {
        RawPart::Numbers(v) => Ok(Spanned {
            value: v.clone(),
            referenced: part.referenced,
            defined: part.defined,
        }),
        RawPart::Zyx(_) => Err(invalid_help(
            loc(part),
            format!("{what}: `zyx` gives an orientation, which stands second in a pose"),
            POSE_HELP,
        )),
    }
}

/// `{ zyx: [ez, ey, ex] }` (deg): RAPID's `OrientZYX(ez, ey, ex)`, as a normalised quaternion.
fn zyx(v: &Spanned<Vec<f64>>, what: &str) -> Result<[f64; 4], CellError> {
    finite(v, what)?;
    match v.value.as_slice() {
        [ez, ey, ex] => Ok(orient_zyx(*ez, *ey, *ex)),
        other => Err(invalid_help(
            loc(v),
            format!("{what} must have 3 numbers [ez, ey, ex], found {}", other.len()),
            "{ zyx: [ez, ey, ex] } is RAPID's OrientZYX(ez, ey, ex): the rotation about z by ez, then about the new y by ey, then about the new x by ex, in degrees",
        )),
    }
}

/// RAPID's `OrientZYX(ez, ey, ex)` (deg): the rotation `Rz(ez) Ry(ey) Rx(ex)` as a unit
/// quaternion `[w, x, y, z]`. Of its two signs, the one with `w > 0` (with `w = 0`, the first
/// component that is not 0 positive), so a cell states one quaternion per rotation. The sines
/// and cosines of whole multiples of 45 deg are exact ([`sin_cos_deg`]), so `[0, 180, 0]` is
/// `[0, 0, 1, 0]`, not a quaternion with a 6e-17 residue.
pub(in crate::cell) fn orient_zyx(ez: f64, ey: f64, ex: f64) -> [f64; 4] {
    let half = |a: f64| sin_cos_deg(a / 2.0);
    let (sz, cz) = half(ez);
    let (sy, cy) = half(ey);
    let (sx, cx) = half(ex);
    // qz * qy * qx, each [cos, sin * axis], multiplied out.
    let q = [
        cz * cy * cx + sz * sy * sx,
        cz * cy * sx - sz * sy * cx,
        cz * sy * cx + sz * cy * sx,
        sz * cy * cx - cz * sy * sx,
    ];
    // A product of unit quaternions: normalised where rounding left it more than a few ulps off
    // (else exact values such as sqrt(1/2) would lose their last bit to the division).
    let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    let q = if (norm - 1.0).abs() > 4.0 * f64::EPSILON {
        q.map(|x| x / norm)
    } else {
        q
    };
    let first = q.iter().copied().find(|x| *x != 0.0).unwrap_or(1.0);
    let q = if first < 0.0 { q.map(|x| -x) } else { q };
    // No -0.0 (the module writes no `-0`).
    q.map(|x| if x == 0.0 { 0.0 } else { x })
}

/// `(sin, cos)` of `deg` degrees, exact at whole multiples of 45 deg (0, +-1, +-sqrt(1/2)).
fn sin_cos_deg(deg: f64) -> (f64, f64) {
    let eighths = deg / 45.0;
    if eighths.fract() != 0.0 || eighths.abs() > 1e15 {
        return deg.to_radians().sin_cos();
    }
    let r = std::f64::consts::FRAC_1_SQRT_2;
    // (sin, cos) at k * 45 deg, k = 0..7.
    const TABLE: [(f64, f64); 8] = [
        (0.0, 1.0),
        (1.0, 1.0),
        (1.0, 0.0),
        (1.0, -1.0),
        (0.0, -1.0),
        (-1.0, -1.0),
        (-1.0, 0.0),
        (-1.0, 1.0),
    ];
    let (s, c) = TABLE[eighths.rem_euclid(8.0) as usize];
    let scale = |x: f64, odd: bool| if odd { x * r } else { x };
    let odd = eighths.rem_euclid(2.0) == 1.0;
    (scale(s, odd), scale(c, odd))
}

/// `[cf1, cf4, cf6, cfx]`: integers, cfx 0..7.
fn confdata(v: &Spanned<Vec<f64>>, what: &str) -> Result<ConfData, CellError> {
    let help = "confdata is [cf1, cf4, cf6, cfx]: the quarter turns floor(axis / 90) of axes 1, 4 and 6, and cfx 0..7 (docs/rapid.md)";
    finite(v, what)?;
    let c = <[f64; 4]>::try_from(v.value.as_slice()).map_err(|_| {
        invalid_help(
            loc(v),
            format!("{what} must have 4 numbers, found {}", v.value.len()),
            help,
        )
    })?;
    // `finite` has bounded them (|x| <= MAX_MAGNITUDE), so `as i32` below is exact.
    if let Some(x) = c.iter().find(|x| x.fract() != 0.0) {
        return Err(invalid_help(
            loc(v),
            format!("{what}: {} is not a whole number", excerpt::number(*x)),
            help,
        ));
    }
    if !(0.0..=7.0).contains(&c[3]) {
        return Err(invalid_help(
            loc(v),
            format!("{what}: cfx = {} is not one of 0..7", c[3]),
            help,
        ));
    }
    Ok(ConfData::from_array(c.map(|x| x as i32)))
}

/// The help line of a name that breaks the RAPID identifier rule.
pub(super) const IDENTIFIER_HELP: &str = "a RAPID name is an ASCII letter, then letters, digits or '_', at most 32 characters, and not a reserved word or a predefined name such as tool0, v100 or pi (letter case aside)";

/// A name the module declares (the module, a point, the tool, the work object): the RAPID
/// identifier rule.
pub(super) fn identifier(s: &Spanned<String>, what: &str) -> Result<String, CellError> {
    check_identifier(&s.value).map_err(|e| {
        invalid_help(
            loc(s),
            format!(
                "{what} '{}' is not a valid RAPID name: {e}",
                excerpt::value(&s.value)
            ),
            IDENTIFIER_HELP,
        )
    })?;
    Ok(s.value.clone())
}

/// A name of RAPID data the module uses but does not declare (speed, zone, tool): the same rule,
/// predefined names allowed, but only of the type the use needs (`speed: z50` is a zonedata
/// where a speeddata belongs: [`crate::names::check_data_type`]).
pub(super) fn data_name(
    s: &Spanned<String>,
    what: &str,
    wanted: DataType,
) -> Result<String, CellError> {
    check_data_name(&s.value).map_err(|e| {
        invalid_help(
            loc(s),
            format!(
                "{what} '{}' is not a valid RAPID name: {e}",
                excerpt::value(&s.value)
            ),
            "speed, zone and tool name RAPID data: a predefined one (v300, fine, tool0) or one declared on the controller",
        )
    })?;
    check_data_type(&s.value, wanted).map_err(|e| {
        invalid_help(
            loc(s),
            format!("{what} {e}"),
            format!(
                "{what} names a {}: a predefined one ({}) or one declared on the controller; the controller refuses a module that uses data of another type",
                wanted.rapid(),
                match wanted {
                    DataType::Speed => "v5 .. v7000, vmax",
                    DataType::Zone => "fine, z0 .. z200",
                    DataType::Tool => "tool0",
                    DataType::Wobj => "wobj0",
                    DataType::Load => "load0",
                }
            ),
        )
    })?;
    Ok(s.value.clone())
}

/// The module's name: the identifier rule, and not a system module every controller task holds
/// (`BASE`, `user`: [`crate::names::SYSTEM_MODULES`]).
pub(super) fn module_name(s: &Spanned<String>) -> Result<String, CellError> {
    check_module_name(&s.value).map_err(|e| {
        let help = match e {
            IdentifierError::SystemModule { .. } => "every task of the controller holds the system modules BASE and user (docs/rapid.md); name the module after its job, e.g. TrunkWeld",
            _ => IDENTIFIER_HELP,
        };
        invalid_help(
            loc(s),
            format!(
                "module '{}' is not a valid RAPID name: {e}",
                excerpt::value(&s.value)
            ),
            help,
        )
    })?;
    Ok(s.value.clone())
}
