//! Value checks shared by the sections: numbers finite and no finer than the module states them,
//! triples, poses with normalised quaternions, RAPID names. Each refusal points at the value.

use super::super::{CellError, Frame, Loc, MAX_MAGNITUDE, QUATERNION_NORM_TOL};
use crate::excerpt;
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

/// The tool's mass (kg): finite, > 0, at most [`MASS_DECIMALS`] decimals.
pub(super) fn mass(v: &Spanned<f64>) -> Result<f64, CellError> {
    bounded(v, "tool.mass", "a number > 0 (kg)")?;
    if v.value <= 0.0 {
        return Err(invalid_help(
            loc(v),
            format!(
                "tool.mass = {} must be a number > 0 (kg)",
                excerpt::number(v.value)
            ),
            "the tool's load as tooldata declares it; leave it out for 1 kg",
        ));
    }
    finer_than(v.value, MASS_DECIMALS, loc(v), "tool.mass", format!("the module writes the mass to {MASS_DECIMALS} decimals (kg); give no more, so it states what was used"))?;
    positive_as_written(v, "tool.mass", MASS_DECIMALS, "kg")
}

/// A value that must be positive stays positive as the module writes it (`decimals`
/// decimals): `1e-300` passes `> 0` and the decimals rule (it is 0.000 within them) but would
/// be written 0.000, which the controller refuses (a tool's load must be positive).
pub(super) fn positive_as_written(
    v: &Spanned<f64>,
    what: &str,
    decimals: usize,
    unit: &str,
) -> Result<f64, CellError> {
    if precision::round(v.value, decimals) > 0.0 {
        return Ok(v.value);
    }
    Err(invalid_help(
        loc(v),
        format!(
            "{what} = {} is written {:.*} {unit} at the module's {decimals} decimals, not a number > 0",
            excerpt::number(v.value),
            decimals,
            0.0
        ),
        format!("give at least 0.{}1 {unit}", "0".repeat(decimals.saturating_sub(1))),
    ))
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

/// `[[x, y, z], [q1, q2, q3, q4]]`, and with `conf_allowed` optionally a third list
/// `[cf1, cf4, cf6, cfx]`.
pub(super) fn pose(
    v: &Spanned<Vec<Spanned<Vec<f64>>>>,
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
                "positions in mm in the frame the key names; quaternions [w, x, y, z]",
            ))
        }
    };
    let frame = Frame {
        pos_mm: position(p, &format!("{what} position"))?,
        quat_wxyz: quaternion(q, &format!("{what} quaternion"))?,
    };
    let conf = match c {
        Some(c) => Some(confdata(c, &format!("{what} confdata"))?),
        None => None,
    };
    Ok((frame, conf))
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
