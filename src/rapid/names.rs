//! RAPID identifiers: validation and the names of the generated `CONST`s.

use std::collections::HashSet;

use super::{RapidError, Target, TargetKind};

/// Longest identifier RAPID accepts, in characters.
pub const MAX_IDENTIFIER_LEN: usize = 32;

/// RAPID reserved words (RAPID kernel reference, "Reserved words"), upper case.
///
/// `TASK` is not in the classic kernel list but is a keyword of newer
/// RobotWare (`TASK PERS`); it is rejected too, to be safe.
pub const RESERVED_WORDS: &[&str] = &[
    "ALIAS",
    "AND",
    "BACKWARD",
    "CASE",
    "CONNECT",
    "CONST",
    "DEFAULT",
    "DIV",
    "DO",
    "ELSE",
    "ELSEIF",
    "ENDFOR",
    "ENDFUNC",
    "ENDIF",
    "ENDMODULE",
    "ENDPROC",
    "ENDRECORD",
    "ENDTEST",
    "ENDTRAP",
    "ENDWHILE",
    "ERROR",
    "EXIT",
    "FALSE",
    "FOR",
    "FROM",
    "FUNC",
    "GOTO",
    "IF",
    "INOUT",
    "LOCAL",
    "MOD",
    "MODULE",
    "NOSTEPIN",
    "NOT",
    "NOVIEW",
    "OR",
    "PERS",
    "PROC",
    "RAISE",
    "READONLY",
    "RECORD",
    "RETRY",
    "RETURN",
    "STEP",
    "SYSMODULE",
    "TASK",
    "TEST",
    "THEN",
    "TO",
    "TRAP",
    "TRUE",
    "TRYNEXT",
    "UNDO",
    "VAR",
    "VIEWONLY",
    "WHILE",
    "WITH",
    "XOR",
];

/// Predefined RAPID names a user data object must not shadow (compared
/// case-insensitively): data types, predefined data and motion instructions.
///
/// Besides this list, [`check_identifier`] rejects every name of the form
/// `v<digits>`, `z<digits>`, `vrot<digits>` and `vlin<digits>` (the predefined
/// speeddata `v5`..`v7000`, `vrot1`.., `vlin10`.. and zonedata `z0`..`z200`
/// families; the whole pattern is rejected so no future or unusual member
/// slips through).
pub const PREDEFINED_NAMES: &[&str] = &[
    // data types
    "num",
    "dnum",
    "bool",
    "string",
    "byte",
    "jointtarget",
    "robtarget",
    "tooldata",
    "wobjdata",
    "speeddata",
    "zonedata",
    "stoppointdata",
    "pos",
    "orient",
    "pose",
    "confdata",
    "extjoint",
    "robjoint",
    "loaddata",
    // predefined data
    "tool0",
    "wobj0",
    "load0",
    "vmax",
    "fine",
    // motion instructions
    "MoveAbsJ",
    "MoveJ",
    "MoveL",
    "MoveC",
    "MoveExtJ",
];

/// Why a string is not a usable RAPID identifier.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum IdentifierError {
    /// The name is the empty string.
    #[error("name is empty")]
    Empty,
    /// The name is longer than [`MAX_IDENTIFIER_LEN`] characters.
    #[error("name is {len} characters long; RAPID allows at most {max}")]
    TooLong {
        /// Length of the name in characters.
        len: usize,
        /// The limit, [`MAX_IDENTIFIER_LEN`].
        max: usize,
    },
    /// The first character is not an ASCII letter.
    #[error("name must start with an ASCII letter, not {found:?}")]
    BadFirstChar {
        /// The offending first character.
        found: char,
    },
    /// A later character is not an ASCII letter, digit or underscore.
    #[error("character {found:?} at position {position} is not allowed; only ASCII letters, digits and '_'")]
    BadChar {
        /// The offending character.
        found: char,
        /// Its 0-based character position.
        position: usize,
    },
    /// The name is a RAPID reserved word (in any letter case).
    #[error("{word:?} is a RAPID reserved word (names are case-insensitive)")]
    Reserved {
        /// The reserved word, upper case.
        word: &'static str,
    },
    /// The name is a predefined RAPID type, data or instruction name (in any letter case).
    #[error("{name:?} is a predefined RAPID name (names are case-insensitive)")]
    Predefined {
        /// The predefined name it clashes with, as RAPID spells it.
        name: String,
    },
}

/// Checks the shape of an identifier and that it is not a reserved word:
/// ASCII letter first, then ASCII letters, digits or `_`, at most 32 characters.
/// Predefined names are *allowed* here (used for speed/zone/tool references).
pub(crate) fn check_shape(name: &str) -> Result<(), IdentifierError> {
    let mut chars = name.chars();
    let first = chars.next().ok_or(IdentifierError::Empty)?;
    if !first.is_ascii_alphabetic() {
        return Err(IdentifierError::BadFirstChar { found: first });
    }
    if let Some((position, found)) = name
        .chars()
        .enumerate()
        .find(|(_, c)| !(c.is_ascii_alphanumeric() || *c == '_'))
    {
        return Err(IdentifierError::BadChar { found, position });
    }
    let len = name.chars().count();
    if len > MAX_IDENTIFIER_LEN {
        return Err(IdentifierError::TooLong {
            len,
            max: MAX_IDENTIFIER_LEN,
        });
    }
    if let Some(word) = RESERVED_WORDS.iter().find(|w| w.eq_ignore_ascii_case(name)) {
        return Err(IdentifierError::Reserved { word });
    }
    Ok(())
}

/// `name` (already known to be ASCII) is `prefix` followed by one or more digits.
fn is_prefix_digits(name: &str, prefix: &str) -> bool {
    name.len() > prefix.len()
        && name[..prefix.len()].eq_ignore_ascii_case(prefix)
        && name[prefix.len()..].bytes().all(|b| b.is_ascii_digit())
}

/// Checks that `name` can name a user data object (a `CONST`, the module):
/// a RAPID identifier (ASCII letter first, then ASCII letters, digits and
/// `_`; at most 32 characters), not a reserved word and not a predefined
/// name (see [`RESERVED_WORDS`], [`PREDEFINED_NAMES`]). All comparisons
/// ignore letter case, as RAPID does. Checks run in this order: empty, first
/// character, other characters, length, reserved word, predefined name; the
/// error reports the first rule broken.
pub fn check_identifier(name: &str) -> Result<(), IdentifierError> {
    check_shape(name)?;
    if let Some(p) = PREDEFINED_NAMES
        .iter()
        .find(|p| p.eq_ignore_ascii_case(name))
    {
        return Err(IdentifierError::Predefined {
            name: (*p).to_string(),
        });
    }
    for prefix in ["vrot", "vlin", "v", "z"] {
        if is_prefix_digits(name, prefix) {
            return Err(IdentifierError::Predefined {
                name: name.to_ascii_lowercase(),
            });
        }
    }
    Ok(())
}

/// Number of decimal digits of `n` (at least 1).
fn digits(n: usize) -> usize {
    n.checked_ilog10().map_or(1, |d| d as usize + 1)
}

/// The `CONST jointtarget` names for `targets`, in the same order.
///
/// - A cell point keeps its name, which must pass [`check_identifier`]
///   ([`RapidError::InvalidTargetName`] otherwise), must not equal `main`
///   (the generated `PROC`) and must be unique among cell points ignoring
///   case ([`RapidError::NameClash`] otherwise).
/// - A via target is named `via<L>_<I>` with `L = leg + 1` and `I = index`,
///   both zero-padded to the same width for the whole program: the number of
///   digits of the largest `leg + 1` (resp. `index`) among the via targets,
///   but at least 2. Examples: `via01_01`, `via01_12`, `via10_03`.
/// - If a via name equals (ignoring case) a cell point name or a name given
///   earlier in the list, the suffix `_x1`, `_x2`, ... is appended, taking the
///   first that is free. Cell point names are reserved before any via is
///   named, so the result does not depend on where the clashing point sits.
/// - Two via targets with the same `(leg, index)` are a [`RapidError::NameClash`]
///   (an upstream bug), as is a via name that would exceed 32 characters
///   ([`RapidError::InvalidGeneratedName`]).
///
/// The result is a pure function of `targets`: same input, same names.
pub fn target_names(targets: &[Target]) -> Result<Vec<String>, RapidError> {
    // 1. Cell points: validate and reserve.
    let mut taken: HashSet<String> = HashSet::new();
    let mut owners: Vec<(String, String)> = Vec::new(); // lowercase -> original
    for (position, target) in targets.iter().enumerate() {
        if let TargetKind::CellPoint { name } = &target.kind {
            check_identifier(name).map_err(|source| RapidError::InvalidTargetName {
                name: name.clone(),
                position,
                source,
            })?;
            let key = name.to_ascii_lowercase();
            if key == "main" {
                return Err(RapidError::NameClash {
                    name: name.clone(),
                    other: "PROC main of the generated module".to_string(),
                });
            }
            if let Some((_, first)) = owners.iter().find(|(k, _)| *k == key) {
                return Err(RapidError::NameClash {
                    name: name.clone(),
                    other: format!("cell point `{first}`"),
                });
            }
            owners.push((key.clone(), name.clone()));
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
            &TargetKind::Via { leg, index } => {
                let base = format!("via{:0leg_w$}_{:0index_w$}", leg as u128 + 1, index);
                if !seen_vias.insert((leg, index)) {
                    return Err(RapidError::NameClash {
                        name: base,
                        other: format!("another via target with leg {leg} and index {index}"),
                    });
                }
                let mut name = base.clone();
                let mut n = 0u64;
                while taken.contains(&name.to_ascii_lowercase()) {
                    n += 1;
                    name = format!("{base}_x{n}");
                }
                check_identifier(&name).map_err(|source| RapidError::InvalidGeneratedName {
                    name: name.clone(),
                    leg,
                    index,
                    source,
                })?;
                taken.insert(name.to_ascii_lowercase());
                names.push(name);
            }
        }
    }
    Ok(names)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(name: &str) -> Target {
        Target {
            kind: TargetKind::CellPoint {
                name: name.to_string(),
            },
            axes_deg: [0.0; 6],
        }
    }
    fn via(leg: usize, index: usize) -> Target {
        Target {
            kind: TargetKind::Via { leg, index },
            axes_deg: [0.0; 6],
        }
    }

    #[test]
    fn check_identifier_accepts_valid_names() {
        for ok in [
            "home",
            "P1",
            "pick_up_2",
            "a",
            "Z",
            "via01_01",
            "tool1",
            "v",
            "zone",
            "vfast",
            "z1a",
            "wobj1",
            "Modules",
            "proc_1",
            "main",
        ] {
            assert_eq!(check_identifier(ok), Ok(()), "{ok}");
        }
    }

    #[test]
    fn check_identifier_rejects_empty() {
        assert_eq!(check_identifier(""), Err(IdentifierError::Empty));
    }

    #[test]
    fn check_identifier_length_32_ok_33_rejected() {
        let n32 = format!("a{}", "b".repeat(31));
        let n33 = format!("a{}", "b".repeat(32));
        assert_eq!(n32.len(), 32);
        assert_eq!(check_identifier(&n32), Ok(()));
        assert_eq!(
            check_identifier(&n33),
            Err(IdentifierError::TooLong { len: 33, max: 32 })
        );
    }

    #[test]
    fn check_identifier_rejects_bad_first_char() {
        assert_eq!(
            check_identifier("1abc"),
            Err(IdentifierError::BadFirstChar { found: '1' })
        );
        assert_eq!(
            check_identifier("_abc"),
            Err(IdentifierError::BadFirstChar { found: '_' })
        );
        assert_eq!(
            check_identifier("\u{e9}t\u{e9}"),
            Err(IdentifierError::BadFirstChar { found: '\u{e9}' })
        );
        assert_eq!(
            check_identifier(" a"),
            Err(IdentifierError::BadFirstChar { found: ' ' })
        );
    }

    #[test]
    fn check_identifier_rejects_bad_chars() {
        assert_eq!(
            check_identifier("a-b"),
            Err(IdentifierError::BadChar {
                found: '-',
                position: 1
            })
        );
        assert_eq!(
            check_identifier("ab c"),
            Err(IdentifierError::BadChar {
                found: ' ',
                position: 2
            })
        );
        assert_eq!(
            check_identifier("p\u{f6}int"),
            Err(IdentifierError::BadChar {
                found: '\u{f6}',
                position: 1
            })
        );
        assert_eq!(
            check_identifier("a.b"),
            Err(IdentifierError::BadChar {
                found: '.',
                position: 1
            })
        );
        assert_eq!(
            check_identifier("ab\n"),
            Err(IdentifierError::BadChar {
                found: '\n',
                position: 2
            })
        );
    }

    #[test]
    fn check_identifier_counts_characters_not_bytes_for_length_of_bad_names() {
        // Non-ASCII is reported as a bad character before the length rule.
        let name = format!("a{}", "\u{e4}".repeat(20));
        assert!(matches!(
            check_identifier(&name),
            Err(IdentifierError::BadChar { position: 1, .. })
        ));
    }

    #[test]
    fn check_identifier_rejects_reserved_words_in_any_case() {
        assert_eq!(
            check_identifier("Module"),
            Err(IdentifierError::Reserved { word: "MODULE" })
        );
        assert_eq!(
            check_identifier("proc"),
            Err(IdentifierError::Reserved { word: "PROC" })
        );
        assert_eq!(
            check_identifier("ENDPROC"),
            Err(IdentifierError::Reserved { word: "ENDPROC" })
        );
        assert_eq!(
            check_identifier("tryNext"),
            Err(IdentifierError::Reserved { word: "TRYNEXT" })
        );
        assert_eq!(
            check_identifier("xor"),
            Err(IdentifierError::Reserved { word: "XOR" })
        );
        for w in RESERVED_WORDS {
            assert!(check_identifier(w).is_err(), "{w}");
            assert!(check_identifier(&w.to_ascii_lowercase()).is_err(), "{w}");
        }
    }

    #[test]
    fn check_identifier_rejects_predefined_names_in_any_case() {
        for (name, canon) in [
            ("tool0", "tool0"),
            ("TOOL0", "tool0"),
            ("Wobj0", "wobj0"),
            ("load0", "load0"),
            ("fine", "fine"),
            ("VMAX", "vmax"),
            ("movej", "MoveJ"),
            ("MOVEABSJ", "MoveAbsJ"),
            ("moveL", "MoveL"),
            ("MoveC", "MoveC"),
            ("JointTarget", "jointtarget"),
            ("num", "num"),
            ("Bool", "bool"),
            ("string", "string"),
            ("robtarget", "robtarget"),
            ("tooldata", "tooldata"),
            ("wobjdata", "wobjdata"),
            ("speeddata", "speeddata"),
            ("zonedata", "zonedata"),
            ("pos", "pos"),
            ("orient", "orient"),
            ("pose", "pose"),
            ("confdata", "confdata"),
            ("extjoint", "extjoint"),
            ("robjoint", "robjoint"),
            ("loaddata", "loaddata"),
        ] {
            assert_eq!(
                check_identifier(name),
                Err(IdentifierError::Predefined {
                    name: canon.to_string()
                }),
                "{name}"
            );
        }
        for name in [
            "v5", "v300", "V7000", "v1000", "z0", "z10", "Z200", "vrot10", "vlin50",
        ] {
            assert!(
                matches!(
                    check_identifier(name),
                    Err(IdentifierError::Predefined { .. })
                ),
                "{name}"
            );
        }
    }

    #[test]
    fn check_shape_allows_predefined_but_not_reserved() {
        assert_eq!(check_shape("v300"), Ok(()));
        assert_eq!(check_shape("fine"), Ok(()));
        assert_eq!(check_shape("tool0"), Ok(()));
        assert_eq!(
            check_shape("If"),
            Err(IdentifierError::Reserved { word: "IF" })
        );
        assert_eq!(
            check_shape("9"),
            Err(IdentifierError::BadFirstChar { found: '9' })
        );
    }

    #[test]
    fn identifier_error_messages_say_why() {
        let msg = check_identifier("Module").unwrap_err().to_string();
        assert!(msg.contains("reserved"), "{msg}");
        let msg = check_identifier(&"a".repeat(33)).unwrap_err().to_string();
        assert!(msg.contains("33") && msg.contains("32"), "{msg}");
        let msg = check_identifier("tool0").unwrap_err().to_string();
        assert!(msg.contains("predefined"), "{msg}");
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
    fn target_names_reject_cell_point_named_main() {
        assert!(matches!(
            target_names(&[point("Main")]),
            Err(RapidError::NameClash { .. })
        ));
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
