//! Reading the routine's instructions as RAPID's grammar allows them in a module gen-rapid
//! writes (not through the library's types): the motion instructions `MoveAbsJ`, `MoveJ`,
//! `MoveL` and `MoveC` with a target that is a data name or `RelTool(name, dx, dy, dz)`, their
//! speed, zone, tool and `\WObj:=`; `ConfJ` and `ConfL`; and the actions `SetDO`, `PulseDO`,
//! `WaitDI`, `WaitTime` and `GripLoad` with their plain arguments; and RobotWare Arc's welding
//! instructions, which move the TCP as `MoveL` (`ArcLStart`, `ArcL`, `ArcLEnd`) and `MoveC`
//! (`ArcCStart`, `ArcC`, `ArcCEnd`) do, with a seamdata and a welddata name between the speed
//! and the zone (`ArcL p, v50, seam1, weld1, fine, tTorch\WObj:=wobj1;`, no optional
//! argument). Anything else in the routine
//! (another instruction, an optional argument such as `\SDelay:=`, `\Conc` or `\V:=`, a
//! function other than `RelTool`, a malformed number) is refused with the line, so a module that
//! runs something this check does not simulate fails.
//!
//! Which data a name is (a robtarget for `MoveL`, a jointtarget for `MoveAbsJ`) is resolved
//! once the whole module is read (`module.rs`), since RAPID allows data declared after the
//! routine.

/// How a motion instruction moves the robot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MoveKind {
    /// `MoveAbsJ`: joint interpolation to axis values.
    AbsJ,
    /// `MoveJ`: joint interpolation to the axis values of a robtarget (its confdata chooses).
    J,
    /// `MoveL`: the TCP on a straight line.
    L,
    /// `MoveC`: the TCP on a circle through a circle point.
    C,
}

impl MoveKind {
    pub fn name(self) -> &'static str {
        match self {
            MoveKind::AbsJ => "MoveAbsJ",
            MoveKind::J => "MoveJ",
            MoveKind::L => "MoveL",
            MoveKind::C => "MoveC",
        }
    }

    /// The TCP follows a path (MoveL, MoveC), not joint interpolation.
    pub fn is_process(self) -> bool {
        matches!(self, MoveKind::L | MoveKind::C)
    }
}

/// A motion instruction's target as written.
#[derive(Clone, Debug, PartialEq)]
pub enum ToPoint {
    /// A data name (a `CONST jointtarget` for `MoveAbsJ`, a `CONST robtarget` otherwise).
    Name(String),
    /// `RelTool(base, dx, dy, dz)`: the robtarget `base` moved by (dx, dy, dz) mm in its own
    /// tool frame, with its orientation and confdata.
    RelTool { base: String, offset_mm: [f64; 3] },
}

impl ToPoint {
    /// The data name the target stands on.
    pub fn data(&self) -> &str {
        match self {
            ToPoint::Name(n) => n,
            ToPoint::RelTool { base, .. } => base,
        }
    }
}

impl std::fmt::Display for ToPoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ToPoint::Name(n) => f.write_str(n),
            ToPoint::RelTool { base, offset_mm: d } => {
                write!(f, "RelTool({base},{},{},{})", d[0], d[1], d[2])
            }
        }
    }
}

/// One motion instruction.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    pub kind: MoveKind,
    /// MoveC's circle point.
    pub circle: Option<ToPoint>,
    pub to: ToPoint,
    pub speed: String,
    pub zone: String,
    pub tool: String,
    /// `\WObj:=` (None: wobj0).
    pub wobj: Option<String>,
    /// An arc-welding instruction's name (`ArcLStart`, ...) with its seamdata and welddata;
    /// None for a `Move` instruction.
    pub arc: Option<Box<Arc>>,
}

/// What an arc-welding instruction adds to the move it makes.
#[derive(Clone, Debug, PartialEq)]
pub struct Arc {
    /// `ArcLStart`, `ArcL`, `ArcLEnd`, `ArcCStart`, `ArcC` or `ArcCEnd`.
    pub instruction: String,
    pub seam: String,
    pub weld: String,
}

/// One action between motion instructions, with its arguments as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// `SetDO signal, 0|1;`
    SetDo { signal: String, value: u8 },
    /// `PulseDO signal;`
    PulseDo { signal: String },
    /// `WaitDI signal, 0|1;`
    WaitDi { signal: String, value: u8 },
    /// `WaitTime s;`
    WaitTime { s: f64 },
    /// `GripLoad load;`
    GripLoad { load: String },
}

/// What an instruction does.
#[derive(Clone, Debug, PartialEq)]
pub enum Instruction {
    /// `ConfJ \On;` (true) or `ConfJ \Off;`.
    ConfJ(bool),
    /// `ConfL \On;` (true) or `ConfL \Off;`.
    ConfL(bool),
    Move(Motion),
    Action(Action),
}

/// An instruction with where it stands.
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    /// 1-based line in the module text.
    pub line: usize,
    /// The line as written (trimmed).
    pub text: String,
    pub ins: Instruction,
}

impl Statement {
    /// How messages name it: `line 42 'MoveL L2_rt, v50, ...'`.
    pub fn label(&self) -> String {
        format!("line {} '{}'", self.line, self.text)
    }

    pub fn motion(&self) -> Option<&Motion> {
        match &self.ins {
            Instruction::Move(m) => Some(m),
            _ => None,
        }
    }
}

/// Reads one trimmed line of the routine's body: `None` for a blank line or a comment.
pub fn statement(line: &str) -> Result<Option<Instruction>, String> {
    if line.is_empty() || line.starts_with('!') {
        return Ok(None);
    }
    let bad = |why: &str| format!("'{line}': {why}");
    let body = line
        .strip_suffix(';')
        .ok_or_else(|| bad("no final ';'"))?
        .trim_end();
    let (word, rest) = match body.split_once(' ') {
        Some((w, r)) => (w, r.trim()),
        None => (body, ""),
    };
    let ins = match word {
        "ConfJ" | "ConfL" => {
            let on = match rest {
                "\\On" => true,
                "\\Off" => false,
                _ => return Err(bad("expected \\On or \\Off")),
            };
            match word {
                "ConfJ" => Instruction::ConfJ(on),
                _ => Instruction::ConfL(on),
            }
        }
        "MoveAbsJ" | "MoveJ" | "MoveL" | "MoveC" | "ArcLStart" | "ArcL" | "ArcLEnd"
        | "ArcCStart" | "ArcC" | "ArcCEnd" => {
            Instruction::Move(motion(word, rest).map_err(|e| bad(&e))?)
        }
        "SetDO" | "WaitDI" => {
            let [signal, value] = args(rest).map_err(|e| bad(&e))?[..] else {
                return Err(bad(&format!("{word} takes a signal and a value")));
            };
            let signal = identifier(signal).map_err(|e| bad(&e))?;
            let value = match value {
                "0" => 0,
                "1" => 1,
                _ => return Err(bad("the value is 0 or 1")),
            };
            Instruction::Action(match word {
                "SetDO" => Action::SetDo { signal, value },
                _ => Action::WaitDi { signal, value },
            })
        }
        "PulseDO" => Instruction::Action(Action::PulseDo {
            signal: identifier(rest).map_err(|e| bad(&e))?,
        }),
        "GripLoad" => Instruction::Action(Action::GripLoad {
            load: identifier(rest).map_err(|e| bad(&e))?,
        }),
        "WaitTime" => {
            let s = decimal(rest).map_err(|e| bad(&e))?;
            Instruction::Action(Action::WaitTime { s })
        }
        _ => return Err(bad("not an instruction this check knows (the grammar of the module's routine: MoveAbsJ, MoveJ, MoveL, MoveC, ArcLStart, ArcL, ArcLEnd, ArcCStart, ArcC, ArcCEnd, ConfJ, ConfL, SetDO, PulseDO, WaitDI, WaitTime, GripLoad)")),
    };
    Ok(Some(ins))
}

/// The arguments of a motion instruction `word` (everything after the word).
fn motion(word: &str, rest: &str) -> Result<Motion, String> {
    let kind = match word {
        "MoveAbsJ" => MoveKind::AbsJ,
        "MoveJ" => MoveKind::J,
        "MoveL" | "ArcLStart" | "ArcL" | "ArcLEnd" => MoveKind::L,
        _ => MoveKind::C,
    };
    let welds = word.starts_with("Arc");
    let parts = args(rest)?;
    let points = if kind == MoveKind::C { 2 } else { 1 };
    let data = if welds { 2 } else { 0 };
    if parts.len() != points + 3 + data {
        return Err(format!(
            "{word} takes {} arguments (target{}, speed, {}zone, tool), found {}",
            points + 3 + data,
            if points == 2 { "s" } else { "" },
            if welds { "seam, weld, " } else { "" },
            parts.len()
        ));
    }
    let mut parts = parts;
    let arc = match welds {
        true => {
            let weld = identifier(parts.remove(points + 2))?;
            let seam = identifier(parts.remove(points + 1))?;
            Some(Box::new(Arc {
                instruction: word.to_string(),
                seam,
                weld,
            }))
        }
        false => None,
    };
    let mut targets = Vec::new();
    for p in &parts[..points] {
        targets.push(match kind {
            MoveKind::AbsJ => {
                let name = p
                    .strip_suffix("\\NoEOffs")
                    .ok_or("MoveAbsJ's target is written T\\NoEOffs")?;
                ToPoint::Name(identifier(name)?)
            }
            _ => to_point(p)?,
        });
    }
    let speed = identifier(parts[points])?;
    let zone = identifier(parts[points + 1])?;
    let (tool, wobj) = match parts[points + 2].split_once("\\WObj:=") {
        Some((t, w)) => (identifier(t)?, Some(identifier(w)?)),
        None => (identifier(parts[points + 2])?, None),
    };
    let to = targets.pop().ok_or("no target")?;
    Ok(Motion {
        kind,
        circle: targets.pop(),
        to,
        speed,
        zone,
        tool,
        wobj,
        arc,
    })
}

/// A robtarget argument: a name or `RelTool(name, dx, dy, dz)`.
fn to_point(p: &str) -> Result<ToPoint, String> {
    if let Some(inner) = p.strip_prefix("RelTool(") {
        let inner = inner
            .strip_suffix(')')
            .ok_or_else(|| format!("'{p}': RelTool( without its ')'"))?;
        let [base, dx, dy, dz] = args(inner)?[..] else {
            return Err(format!(
                "'{p}': RelTool takes a robtarget and dx, dy, dz (no \\Rx, \\Ry, \\Rz)"
            ));
        };
        return Ok(ToPoint::RelTool {
            base: identifier(base)?,
            offset_mm: [decimal(dx)?, decimal(dy)?, decimal(dz)?],
        });
    }
    Ok(ToPoint::Name(identifier(p)?))
}

/// Splits an argument list at the commas outside parentheses and brackets, each trimmed.
fn args(s: &str) -> Result<Vec<&str>, String> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in s.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => {
                out.push(s[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
        if depth < 0 {
            return Err(format!("'{s}': unbalanced parentheses"));
        }
    }
    if depth != 0 {
        return Err(format!("'{s}': unbalanced parentheses"));
    }
    out.push(s[start..].trim());
    if out.iter().any(|a| a.is_empty()) {
        return Err(format!("'{s}': an empty argument"));
    }
    Ok(out)
}

/// A RAPID identifier (a letter, then letters, digits and '_', at most 32 characters); an
/// optional argument (`\Conc`, `\V:=...`) or anything else is refused.
pub fn identifier(s: &str) -> Result<String, String> {
    let ok = s.len() <= 32
        && s.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    match ok {
        true => Ok(s.to_string()),
        false => Err(format!(
            "'{s}' is not a plain RAPID name (an optional argument or an expression is not in the module's grammar)"
        )),
    }
}

/// A plain decimal number (`-40.000`, `0`, `0.3`): no exponent, no expression.
fn decimal(s: &str) -> Result<f64, String> {
    let digits = s.strip_prefix('-').unwrap_or(s);
    let ok = !digits.is_empty()
        && digits.chars().all(|c| c.is_ascii_digit() || c == '.')
        && digits.matches('.').count() <= 1
        && !digits.starts_with('.')
        && !digits.ends_with('.');
    match ok {
        true => digits
            .parse::<f64>()
            .map(|v| if s.starts_with('-') { -v } else { v })
            .map_err(|e| format!("'{s}': {e}")),
        false => Err(format!("'{s}' is not a plain decimal number")),
    }
}
