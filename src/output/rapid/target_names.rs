//! The names of the generated `CONST jointtarget`s: cell points keep theirs, vias are numbered.

#[cfg(test)]
use super::MoveHow;
use super::{JointTarget, RapidError, TargetKind};
use crate::names::check_identifier;
use std::collections::{HashMap, HashSet};

/// Number of decimal digits of `n` (at least 1).
fn digits(n: usize) -> usize {
    n.checked_ilog10().map_or(1, |d| d as usize + 1)
}

/// The `CONST jointtarget` names for `targets`, in the same order.
///
/// - A cell point keeps its name, which must pass [`check_identifier`]
///   ([`RapidError::InvalidTargetName`] otherwise) and must be unique among
///   cell points ignoring case ([`RapidError::NameClash`] otherwise); the
///   routine's name is checked with the module's other names (`render`).
/// - A via target is named `via<L>_<I>` with `L = leg + 1` and `I = index`,
///   both zero-padded to the same width for the whole program: the number of
///   digits of the largest `leg + 1` (resp. `index`) among the via targets,
///   but at least 2. Examples: `via01_01`, `via01_12`, `via10_03`.
/// - If a via name equals (ignoring case) a cell point name or a name given
///   earlier in the list, the suffix `_x1`, `_x2`, ... is appended, taking the
///   first that is free. Cell point names are reserved before any via is
///   named, so the result does not depend on where the clashing point sits.
/// - An approach or retract pose is named `<point>_app` or `<point>_ret` (declared as a
///   `CONST robtarget` only where it has its own), stepping aside as a via does.
/// - Two via targets with the same `(leg, index)` are a [`RapidError::NameClash`]
///   (an upstream bug), as is a via name that would exceed 32 characters
///   ([`RapidError::InvalidGeneratedName`]).
///
/// The result is a pure function of `targets`: same input, same names.
pub fn target_names(targets: &[JointTarget]) -> Result<Vec<String>, RapidError> {
    target_names_avoiding(targets, &[])
}

/// [`target_names`], with vias also avoiding `reserved` (the module's other names: the module,
/// the speed, zone and tool data), which take a via's name as a cell point does: `_x1`, ....
pub fn target_names_avoiding(
    targets: &[JointTarget],
    reserved: &[&str],
) -> Result<Vec<String>, RapidError> {
    // 1. Cell points: validate and reserve; then the other names.
    let mut taken: HashSet<String> = reserved.iter().map(|n| n.to_ascii_lowercase()).collect();
    let mut owners: HashMap<String, String> = HashMap::new(); // lowercase -> original
    for (position, target) in targets.iter().enumerate() {
        if let TargetKind::CellPoint { name } = &target.kind {
            check_identifier(name).map_err(|source| RapidError::InvalidTargetName {
                name: name.clone(),
                position,
                source,
            })?;
            let key = name.to_ascii_lowercase();
            if let Some(first) = owners.get(&key) {
                return Err(RapidError::NameClash {
                    name: name.clone(),
                    other: format!("cell point `{first}`"),
                });
            }
            owners.insert(key.clone(), name.clone());
            taken.insert(key);
        }
    }

    // 2. Via targets: common padding widths.
    let (mut max_leg, mut max_index) = (0usize, 0usize);
    for target in targets {
        if let TargetKind::Via { leg, index } = target.kind {
            max_leg = max_leg.max(leg.saturating_add(1));
            max_index = max_index.max(index);
        }
    }
    let leg_w = digits(max_leg).max(2);
    let index_w = digits(max_index).max(2);

    // 3. Assign names in order.
    let mut seen_vias: HashSet<(usize, usize)> = HashSet::new();
    let mut names = Vec::with_capacity(targets.len());
    for target in targets {
        match &target.kind {
            TargetKind::CellPoint { name } => names.push(name.clone()),
            // The point's own name: its data, declared once by the point.
            TargetKind::Revisit { point } => names.push(point.clone()),
            // Declared only with a robtarget of their own; named for the report and the
            // pictures too. They step aside as vias do.
            TargetKind::Approach { point } | TargetKind::Retract { point } => {
                let suffix = match target.kind {
                    TargetKind::Approach { .. } => "app",
                    _ => "ret",
                };
                let what = format!("the {suffix} pose of point `{point}`");
                names.push(take_made_up(
                    &format!("{point}_{suffix}"),
                    what,
                    &mut taken,
                )?);
            }
            &TargetKind::Via { leg, index } => {
                let base = format!("via{:0leg_w$}_{:0index_w$}", leg as u128 + 1, index);
                if !seen_vias.insert((leg, index)) {
                    return Err(RapidError::NameClash {
                        name: base,
                        other: format!("another via target with leg {leg} and index {index}"),
                    });
                }
                names.push(take_made_up(
                    &base,
                    format!("via {index} of leg {leg}"),
                    &mut taken,
                )?);
            }
        }
    }
    Ok(names)
}

/// A made-up name (`what` says what it names): `base` stepped aside from the names `taken`, a
/// valid RAPID identifier, then taken.
fn take_made_up(
    base: &str,
    what: String,
    taken: &mut HashSet<String>,
) -> Result<String, RapidError> {
    let name = step_aside(base, taken);
    check_identifier(&name).map_err(|source| RapidError::InvalidGeneratedName {
        name: name.clone(),
        what,
        source,
    })?;
    taken.insert(name.to_ascii_lowercase());
    Ok(name)
}

/// `base`, or where it is taken (any case) the first of `base_x1`, `base_x2`, ... that is free.
fn step_aside(base: &str, taken: &HashSet<String>) -> String {
    let mut name = base.to_string();
    let mut n = 0u64;
    while taken.contains(&name.to_ascii_lowercase()) {
        n += 1;
        name = format!("{base}_x{n}");
    }
    name
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::names::IdentifierError;

    fn point(name: &str) -> JointTarget {
        JointTarget {
            kind: TargetKind::CellPoint {
                name: name.to_string(),
            },
            axes_deg: [0.0; 6],
            speed: "v300".into(),
            zone: "fine".into(),
            robtarget: None,
            how: MoveHow::Joint,
            offset_mm: None,
            actions: Vec::new(),
            wobj: None,
        }
    }
    fn via(leg: usize, index: usize) -> JointTarget {
        JointTarget {
            kind: TargetKind::Via { leg, index },
            axes_deg: [0.0; 6],
            speed: "v300".into(),
            zone: "fine".into(),
            robtarget: None,
            how: MoveHow::Joint,
            offset_mm: None,
            actions: Vec::new(),
            wobj: None,
        }
    }

    #[test]
    fn approach_and_retract_poses_step_aside_as_vias_do() {
        let pose = |kind: TargetKind| JointTarget { kind, ..point("x") };
        let app = pose(TargetKind::Approach { point: "P1".into() });
        let ret = pose(TargetKind::Retract { point: "P1".into() });
        // A cell point named like P1's approach pose, in any case, and a reserved name like its
        // retract pose.
        let t = [point("p1_APP"), app, point("P1"), ret];
        assert_eq!(
            target_names_avoiding(&t, &["P1_ret"]).unwrap(),
            ["p1_APP", "P1_app_x1", "P1", "P1_ret_x1"]
        );
        let long = "P".repeat(29);
        let t = [
            pose(TargetKind::Approach {
                point: long.clone(),
            }),
            point(&long),
        ];
        assert!(matches!(
            target_names(&t),
            Err(RapidError::InvalidGeneratedName { .. })
        ));
    }

    #[test]
    fn vias_avoid_the_modules_other_names() {
        let t = [point("home"), via(0, 1), via(0, 2), point("pick")];
        assert_eq!(
            target_names_avoiding(&t, &["VIA01_01", "v300"]).unwrap(),
            ["home", "via01_01_x1", "via01_02", "pick"]
        );
    }

    #[test]
    fn target_names_keep_cell_points_and_name_vias() {
        let t = [
            point("home"),
            via(0, 1),
            via(0, 2),
            point("pick"),
            via(1, 1),
            point("place"),
        ];
        assert_eq!(
            target_names(&t).unwrap(),
            ["home", "via01_01", "via01_02", "pick", "via02_01", "place"]
        );
    }

    #[test]
    fn target_names_pad_consistently_to_widest() {
        let mut t = vec![point("a")];
        t.push(via(0, 1));
        t.push(via(0, 123));
        t.push(point("b"));
        t.push(via(9, 7));
        t.push(point("c"));
        assert_eq!(
            target_names(&t).unwrap(),
            ["a", "via01_001", "via01_123", "b", "via10_007", "c"]
        );
    }

    #[test]
    fn target_names_resolve_clash_with_cell_point_named_like_a_via() {
        // The clashing cell point comes *after* the via: still reserved first.
        let t = [
            point("home"),
            via(0, 1),
            via(0, 2),
            point("VIA01_01"),
            point("via01_01_x1"),
        ];
        let names = target_names(&t).unwrap();
        assert_eq!(
            names,
            ["home", "via01_01_x2", "via01_02", "VIA01_01", "via01_01_x1"]
        );
        let lower: HashSet<String> = names.iter().map(|n| n.to_ascii_lowercase()).collect();
        assert_eq!(lower.len(), names.len());
        for n in &names {
            assert_eq!(check_identifier(n), Ok(()), "{n}");
        }
    }

    #[test]
    fn target_names_reject_duplicate_cell_points_ignoring_case() {
        let t = [point("Home"), via(0, 1), point("HOME")];
        match target_names(&t) {
            Err(RapidError::NameClash { name, other }) => {
                assert_eq!(name, "HOME");
                assert!(other.contains("Home"), "{other}");
            }
            other => panic!("expected NameClash, got {other:?}"),
        }
    }

    #[test]
    fn target_names_reject_duplicate_via() {
        let t = [point("a"), via(0, 1), via(0, 1), point("b")];
        assert!(matches!(
            target_names(&t),
            Err(RapidError::NameClash { .. })
        ));
    }

    #[test]
    fn target_names_report_invalid_cell_point_with_rule() {
        let t = [point("home"), point("2nd")];
        match target_names(&t) {
            Err(e @ RapidError::InvalidTargetName { .. }) => {
                let msg = e.to_string();
                assert!(msg.contains("2nd") && msg.contains("start with"), "{msg}");
                if let RapidError::InvalidTargetName {
                    position, source, ..
                } = e
                {
                    assert_eq!(position, 1);
                    assert_eq!(source, IdentifierError::BadFirstChar { found: '2' });
                }
            }
            other => panic!("expected InvalidTargetName, got {other:?}"),
        }
        assert!(matches!(
            target_names(&[point("wobj0")]),
            Err(RapidError::InvalidTargetName {
                source: IdentifierError::Predefined { .. },
                ..
            })
        ));
    }

    #[test]
    fn target_names_are_deterministic() {
        let t = [
            point("p"),
            via(2, 5),
            via(0, 1),
            point("via03_05"),
            via(1, 1),
        ];
        let a = target_names(&t).unwrap();
        let b = target_names(&t).unwrap();
        assert_eq!(a, b);
        assert_eq!(a, ["p", "via03_05_x1", "via01_01", "via03_05", "via02_01"]);
    }
}
