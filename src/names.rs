//! The RAPID identifier rule, one for the whole program (long: RAPID's tables of reserved words
//! and predefined names are half of it): what a module, point, speed, zone,
//! tool, work-object, load or signal name may be, and the one name the module derives from a cell name (the
//! `CONST robtarget` of a robtarget point, [`robtarget_name`]). The cell validation applies it to
//! the names a cell gives (an input error at their line) and the renderer applies it again, as a
//! last guard, to every name it writes. Beside it, the types of the predefined names
//! ([`predefined_kind`]): a move's speed must be speeddata, its zone zonedata, its tool tooldata
//! ([`check_data_type`]: `speed: z50` or `zone: tool0` is refused, as the controller would
//! refuse the module at load), and the system modules every task holds ([`SYSTEM_MODULES`]),
//! which a module may not be named like. A leaf: it knows nothing of cells or modules.

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

/// RAPID's data types a move's data may be named like (a user data object must not shadow
/// them either: [`check_identifier`]).
pub const DATA_TYPES: &[&str] = &[
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
];

/// Predefined RAPID names a user data object must not shadow (compared
/// case-insensitively), beside [`DATA_TYPES`]: the signal types, predefined data, motion instructions and the instructions
/// and functions the module writes beside them.
///
/// Besides this list, [`check_identifier`] rejects every name of the form
/// `v<digits>`, `z<digits>`, `vrot<digits>` and `vlin<digits>` (the predefined
/// speeddata `v5`..`v7000`, `vrot1`.., `vlin10`.. and zonedata `z0`..`z200`
/// families; the whole pattern is rejected so no future or unusual member
/// slips through).
pub const PREDEFINED_NAMES: &[&str] = &[
    "signaldi",
    "signaldo",
    // predefined data
    "tool0",
    "wobj0",
    "load0",
    "vmax",
    "fine",
    // predefined data of the num type and the error and interrupt numbers ("num", "errnum",
    // "intnum" in the RAPID reference: `CONST num pi := 3.1415926;` in BASE.SYS, EOF_BIN and
    // EOF_NUM for ReadBin / ReadNum, END_OF_LIST, the `VAR errnum ERRNO`, `VAR intnum INTNO`)
    "pi",
    "EOF_BIN",
    "EOF_NUM",
    "END_OF_LIST",
    "ERRNO",
    "INTNO",
    // motion instructions
    "MoveAbsJ",
    "MoveJ",
    "MoveL",
    "MoveC",
    "MoveExtJ",
    // the instructions and functions of a point's actions, approach and retract lines and
    // configuration control (docs/cell.md)
    "SetDO",
    "PulseDO",
    "WaitDI",
    "WaitTime",
    "GripLoad",
    "RelTool",
    "Offs",
    "OrientZYX",
    "ConfJ",
    "ConfL",
];

/// RAPID's built-in routines a name may not take (compared case-insensitively): a data name
/// that is one is not data of any type, and a declared name that is one hides the routine. The
/// motion instructions are in [`PREDEFINED_NAMES`]; these are the other instructions and the
/// functions a motion program most often calls (ABB, *Technical reference manual - RAPID
/// Instructions, Functions and Data types*). Not every routine of RobotWare: the controller
/// still refuses a module that hides one not listed here.
pub const PREDEFINED_ROUTINES: &[&str] = &[
    // instructions
    "AccSet",
    "ConfJ",
    "ConfL",
    "SingArea",
    "VelSet",
    "PathResol",
    "SoftAct",
    "SoftDeact",
    "WaitTime",
    "WaitUntil",
    "WaitDI",
    "WaitDO",
    "WaitAI",
    "WaitAO",
    "WaitGI",
    "WaitGO",
    "Set",
    "Reset",
    "SetDO",
    "SetAO",
    "SetGO",
    "PulseDO",
    "InvertDO",
    "TPWrite",
    "TPErase",
    "TPReadFK",
    "TPReadNum",
    "ErrWrite",
    "Stop",
    "StopMove",
    "StartMove",
    "Break",
    "Add",
    "Incr",
    "Decr",
    "Clear",
    "Load",
    "UnLoad",
    "Save",
    "EraseModule",
    "ProcCall",
    "SearchL",
    "SearchC",
    "SearchJ",
    "TriggJ",
    "TriggL",
    "TriggC",
    "MoveJDO",
    "MoveLDO",
    "MoveCDO",
    "MoveJSync",
    "MoveLSync",
    "MoveCSync",
    "MoveAbsJSync",
    "IDelete",
    "ISignalDI",
    "CONNECT",
    "IWatch",
    "ISleep",
    "IEnable",
    "IDisable",
    "GripLoad",
    "MechUnitLoad",
    "ActUnit",
    "DeactUnit",
    "EOffsOn",
    "EOffsOff",
    "EOffsSet",
    "PDispOn",
    "PDispOff",
    "PDispSet",
    "CorrCon",
    "CorrDiscon",
    "WorldAccLim",
    "SpeedLimAxis",
    "SpeedLimCheckPoint",
    // functions
    "Offs",
    "RelTool",
    "CRobT",
    "CJointT",
    "CPos",
    "CTool",
    "CWObj",
    "CalcRobT",
    "CalcJointT",
    "Abs",
    "Sqrt",
    "Sin",
    "Cos",
    "Tan",
    "ASin",
    "ACos",
    "ATan",
    "ATan2",
    "Exp",
    "Pow",
    "Round",
    "Trunc",
    "NumToStr",
    "StrToVal",
    "ValToStr",
    "StrLen",
    "StrPart",
    "StrFind",
    "Dim",
    "Present",
    "DOutput",
    "DInput",
    "AOutput",
    "GOutput",
    "ClkRead",
    "CDate",
    "CTime",
    "GetTime",
    "OrientZYX",
    "EulerZYX",
    "PoseInv",
    "PoseMult",
    "PoseVect",
    "Distance",
    "DotProd",
    "NOrient",
    "MaxRobSpeed",
    "IsPers",
    "IsVar",
    "Type",
    "RunMode",
    "OpMode",
    "IsStopMoveAct",
    "TestDI",
];

/// The system modules every task of an IRC5 controller holds from a cold start (ABB, *Technical
/// reference manual - RAPID overview*, "System modules": `BASE`, which declares `tool0`,
/// `wobj0` and `load0`, and `user`; docs/rapid.md). A program module named like one cannot be
/// loaded beside it (names are case-insensitive).
pub const SYSTEM_MODULES: &[&str] = &["BASE", "user"];

/// The RAPID data types of the data a move names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DataType {
    Speed,
    Zone,
    Tool,
    Wobj,
    Load,
}

impl DataType {
    /// The type's RAPID name.
    pub fn rapid(self) -> &'static str {
        match self {
            DataType::Speed => "speeddata",
            DataType::Zone => "zonedata",
            DataType::Tool => "tooldata",
            DataType::Wobj => "wobjdata",
            DataType::Load => "loaddata",
        }
    }
}

/// What a predefined RAPID name is (any case), as a message says it: `"a speeddata"` (`v100`,
/// `vmax`, any `v<digits>`, `vrot<digits>`, `vlin<digits>`), `"a zonedata"` (`fine`,
/// `z<digits>`), `"a tooldata"` (`tool0`), `"a wobjdata"`, `"a loaddata"`, `"a num"` (`pi`, ...),
/// `"a data type"`, `"an instruction or function"`; `None` for a name RAPID does not predefine.
pub fn predefined_kind(name: &str) -> Option<&'static str> {
    let is = |list: &[&str]| list.iter().any(|n| n.eq_ignore_ascii_case(name));
    // Every predefined speeddata is `vmax` or `v<digits>` (rapid_data's table), every
    // predefined zonedata `fine` or `z<digits>`: the shapes alone decide, so this leaf reads
    // no other module.
    if name.eq_ignore_ascii_case("vmax")
        || ["vrot", "vlin", "v"]
            .iter()
            .any(|p| name.is_ascii() && is_prefix_digits(name, p))
    {
        return Some("a speeddata");
    }
    if name.eq_ignore_ascii_case("fine") || (name.is_ascii() && is_prefix_digits(name, "z")) {
        return Some("a zonedata");
    }
    let kinds: [(&[&str], &'static str); 9] = [
        (&["tool0"], "a tooldata"),
        (&["wobj0"], "a wobjdata"),
        (&["load0"], "a loaddata"),
        (&["pi", "EOF_BIN", "EOF_NUM", "END_OF_LIST"], "a num"),
        (&["ERRNO"], "an errnum"),
        (&["INTNO"], "an intnum"),
        (DATA_TYPES, "a data type"),
        (
            &["MoveAbsJ", "MoveJ", "MoveL", "MoveC", "MoveExtJ"],
            "an instruction or function",
        ),
        (PREDEFINED_ROUTINES, "an instruction or function"),
    ];
    kinds
        .iter()
        .find(|(list, _)| is(list))
        .map(|(_, kind)| *kind)
}

/// A data name of the wrong type: what it is and what it had to be.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("'{name}' is {is} in RAPID, not a {}", .wanted.rapid())]
pub struct TypeError {
    pub name: String,
    pub is: &'static str,
    pub wanted: DataType,
}

/// Checks that `name`, used where a move needs data of type `wanted`, is not a predefined name
/// of another type (or a data type, an instruction, a function): `speed: z50`, `speed: tool0`,
/// `zone: tool0`, `tool: wobj0`, `speed: MoveL` would make a module the controller refuses at
/// load. A name RAPID does not predefine is taken as data declared on the controller.
pub fn check_data_type(name: &str, wanted: DataType) -> Result<(), TypeError> {
    let Some(is) = predefined_kind(name) else {
        return Ok(());
    };
    let ok = matches!(
        (wanted, is),
        (DataType::Speed, "a speeddata")
            | (DataType::Zone, "a zonedata")
            | (DataType::Tool, "a tooldata")
            | (DataType::Wobj, "a wobjdata")
            | (DataType::Load, "a loaddata")
    );
    if ok {
        return Ok(());
    }
    Err(TypeError {
        name: name.to_string(),
        is,
        wanted,
    })
}

/// Checks a module's name: a RAPID identifier ([`check_identifier`]) and not the name of a
/// system module every task holds ([`SYSTEM_MODULES`]).
pub fn check_module_name(name: &str) -> Result<(), IdentifierError> {
    check_identifier(name)?;
    match SYSTEM_MODULES.iter().find(|m| m.eq_ignore_ascii_case(name)) {
        Some(m) => Err(IdentifierError::SystemModule { name: m }),
        None => Ok(()),
    }
}

/// What the module appends to a robtarget point's name for its `CONST robtarget` (the point's
/// own name stays its `CONST jointtarget`, the target of the move).
pub const ROBTARGET_SUFFIX: &str = "_rt";

/// The name of the `CONST robtarget` written for the robtarget point `point`: `<point>_rt`
/// (`W1` -> `W1_rt`). It cannot take a via's name (`via<L>_<I>`, possibly `_x<N>`: none ends in
/// `_rt`); the cell validation refuses a cell where it would take another name of the module
/// (a point called `W1_rt` beside a robtarget point `W1`) or break the identifier rule (a point
/// name longer than 29 characters).
pub fn robtarget_name(point: &str) -> String {
    format!("{point}{ROBTARGET_SUFFIX}")
}

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
    /// The name of a system module every task holds (a module's name only).
    #[error(
        "{name:?} is a system module every controller task holds (names are case-insensitive)"
    )]
    SystemModule {
        /// The system module, as RAPID spells it.
        name: &'static str,
    },
}

/// Checks a name that refers to RAPID data the module uses but does not declare (the speed,
/// zone and tool of every move): the shape of an identifier (ASCII letter first, then ASCII
/// letters, digits or `_`, at most 32 characters) and not a reserved word. Predefined names
/// (`v300`, `fine`, `tool0`) are *allowed* here: they are what such a name usually is.
pub fn check_data_name(name: &str) -> Result<(), IdentifierError> {
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
/// name (see [`RESERVED_WORDS`], [`DATA_TYPES`], [`PREDEFINED_NAMES`]). All comparisons
/// ignore letter case, as RAPID does. Checks run in this order: empty, first
/// character, other characters, length, reserved word, predefined name; the
/// error reports the first rule broken.
pub fn check_identifier(name: &str) -> Result<(), IdentifierError> {
    check_data_name(name)?;
    if let Some(p) = DATA_TYPES
        .iter()
        .chain(PREDEFINED_NAMES)
        .chain(PREDEFINED_ROUTINES)
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

#[cfg(test)]
mod tests {
    use super::*;
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
            ("SignalDO", "signaldo"),
            ("setdo", "SetDO"),
            ("WAITTIME", "WaitTime"),
            ("GripLoad", "GripLoad"),
            ("reltool", "RelTool"),
            ("confl", "ConfL"),
            ("PI", "pi"),
            ("errno", "ERRNO"),
            ("Eof_Bin", "EOF_BIN"),
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
    fn check_data_name_allows_predefined_but_not_reserved() {
        assert_eq!(check_data_name("v300"), Ok(()));
        assert_eq!(check_data_name("fine"), Ok(()));
        assert_eq!(check_data_name("tool0"), Ok(()));
        assert_eq!(
            check_data_name("If"),
            Err(IdentifierError::Reserved { word: "IF" })
        );
        assert_eq!(
            check_data_name("9"),
            Err(IdentifierError::BadFirstChar { found: '9' })
        );
    }

    #[test]
    fn a_data_name_must_have_the_type_of_its_use() {
        use DataType::*;
        for (name, ty) in [
            ("v300", Speed),
            ("VMAX", Speed),
            ("vrot10", Speed),
            ("fine", Zone),
            ("Z50", Zone),
            ("tool0", Tool),
            ("wobj0", Wobj),
            ("load0", Load),
            // Not predefined: declared on the controller, of whatever type it must be.
            ("vFast", Speed),
            ("zWeld", Zone),
            ("tTorch", Tool),
            ("main", Speed),
        ] {
            assert_eq!(check_data_type(name, ty), Ok(()), "{name}");
        }
        for (name, ty, is) in [
            ("z50", Speed, "a zonedata"),
            ("fine", Speed, "a zonedata"),
            ("tool0", Speed, "a tooldata"),
            ("tool0", Zone, "a tooldata"),
            ("v300", Zone, "a speeddata"),
            ("wobj0", Tool, "a wobjdata"),
            ("load0", Tool, "a loaddata"),
            ("MoveL", Speed, "an instruction or function"),
            ("offs", Zone, "an instruction or function"),
            ("pi", Speed, "a num"),
            ("num", Tool, "a data type"),
            ("v300", Tool, "a speeddata"),
        ] {
            let e = check_data_type(name, ty).expect_err(name);
            assert_eq!(e.is, is, "{name}");
            assert!(e.to_string().contains(ty.rapid()), "{e}");
        }
    }

    #[test]
    fn a_module_may_not_be_named_like_a_system_module_or_a_routine() {
        assert_eq!(
            check_module_name("user"),
            Err(IdentifierError::SystemModule { name: "user" })
        );
        assert_eq!(
            check_module_name("Base"),
            Err(IdentifierError::SystemModule { name: "BASE" })
        );
        assert_eq!(check_module_name("TrunkWeld"), Ok(()));
        assert!(matches!(
            check_identifier("Offs"),
            Err(IdentifierError::Predefined { .. })
        ));
        assert!(matches!(
            check_identifier("WaitTime"),
            Err(IdentifierError::Predefined { .. })
        ));
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
}
