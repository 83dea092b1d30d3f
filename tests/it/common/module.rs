//! Reading a written module as text (not through the library's types): a program header
//! (`%%%` ... `%%%`) before it, the header's facts, the `CONST jointtarget` and
//! `CONST robtarget` declarations, the `PERS tooldata`, `PERS wobjdata` (any number) and
//! `PERS loaddata` (any of them `LOCAL`), the routine's name, and its instructions in order
//! (`routine.rs`: `ConfJ`, `ConfL`, `MoveAbsJ`, `MoveJ`, `MoveL`, `MoveC`, the actions), the
//! `MoveAbsJ` moves also as a list of their own.
//!
//! The reading is strict: a line outside the routine that is not a comment, a declaration of
//! those types, `MODULE`, `ENDMODULE`, `PROC` or `ENDPROC` is refused, and so is a line of the
//! routine that is not in its grammar. Once read, every name an instruction uses is resolved: a
//! `MoveAbsJ` target must be a declared jointtarget, a `MoveJ`, `MoveL` or `MoveC` target (or
//! `RelTool`'s first argument) a declared robtarget (a `MoveL` to a jointtarget is refused), a
//! `\WObj:=` a declared wobjdata or `wobj0`, a `GripLoad` a declared loaddata or `load0`.

use super::routine::{self, Action, Instruction, MoveKind, Statement, ToPoint};

/// What a module says.
#[derive(Clone, Debug)]
pub struct Module {
    /// The name after `MODULE`.
    pub name: String,
    /// `! planner: ...`
    pub planner: String,
    /// `! base: [x, y, z] yaw: deg`
    pub base_mm: [f64; 3],
    pub yaw_deg: f64,
    /// `! clearance (mm): ...`
    pub clearance_mm: f64,
    /// `! moves: ...`
    pub header_moves: usize,
    /// `! min clearance (mm): ...`; None for `none (no obstacles)`.
    pub min_clearance_mm: Option<f64>,
    /// Every `CONST jointtarget NAME := [[a1, .., a6], [9E9, ..]]`, in order.
    pub targets: Vec<(String, [f64; 6])>,
    /// The target of every `MoveAbsJ`, in order.
    pub moves: Vec<String>,
    /// Every `MoveAbsJ` as written, in order.
    pub move_args: Vec<MoveArgs>,
    /// Every `CONST robtarget NAME := [[x,y,z],[q1..q4],[cf1,cf4,cf6,cfx],[9E9,..]]`.
    pub robtargets: Vec<(String, RobTarget)>,
    /// `PERS tooldata NAME := [TRUE,[[x,y,z],[q..]],[mass,[cx,cy,cz],[1,0,0,0],0,0,0]]`.
    pub tooldata: Vec<(String, ToolData)>,
    /// `PERS wobjdata NAME := [FALSE,TRUE,"",[[x,y,z],[q..]],[[0,0,0],[1,0,0,0]]]`.
    pub wobjdata: Vec<(String, [f64; 7])>,
    /// The header's `! urdf:`, `! controller:` and `! coupling:` lines.
    pub urdf: Option<String>,
    pub controller: Option<String>,
    pub coupling: Option<String>,
    /// The routine's name (`PROC <name>()`).
    pub proc_name: String,
    /// How many declarations are `LOCAL` (module-local data).
    pub local: usize,
    /// The program header before `MODULE` (`%%%`, `VERSION:1`, ..., `%%%`), if any.
    pub program_header: Vec<String>,
    /// `PERS loaddata NAME := [mass,[cx,cy,cz],[1,0,0,0],0,0,0]`.
    pub loaddata: Vec<(String, LoadData)>,
    /// The header's `! frames:` line.
    pub frames: Option<String>,
    /// The routine's instructions, in order.
    pub body: Vec<Statement>,
}

/// A written loaddata: a point mass at its centre of gravity.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadData {
    pub mass_kg: f64,
    pub cog_mm: [f64; 3],
}

/// One `MoveAbsJ <target>\NoEOffs, <speed>, <zone>, <tool>[\WObj:=<wobj>];`.
#[derive(Clone, Debug, PartialEq)]
pub struct MoveArgs {
    pub target: String,
    pub speed: String,
    pub zone: String,
    pub tool: String,
    pub wobj: Option<String>,
}

/// A written robtarget.
#[derive(Clone, Debug, PartialEq)]
pub struct RobTarget {
    pub pos_mm: [f64; 3],
    pub quat_wxyz: [f64; 4],
    pub conf: [i32; 4],
}

/// A written tooldata: tframe (position, quaternion), mass and centre of gravity.
#[derive(Clone, Debug, PartialEq)]
pub struct ToolData {
    pub tframe: [f64; 7],
    pub mass_kg: f64,
    pub cog_mm: [f64; 3],
}

impl Module {
    /// Reads a module; a header line missing or malformed is an error naming it.
    pub fn parse(text: &str) -> Result<Module, String> {
        let mut name = None;
        let mut planner = None;
        let mut base = None;
        let mut clearance = None;
        let mut header_moves = None;
        let mut min_clearance = None;
        let mut targets = Vec::new();
        let mut moves = Vec::new();
        let mut move_args = Vec::new();
        let mut robtargets = Vec::new();
        let mut tooldata = Vec::new();
        let mut wobjdata = Vec::new();
        let (mut urdf, mut controller, mut coupling) = (None, None, None);
        let mut proc_name = None;
        let mut local = 0;
        let mut program_header = Vec::new();
        let mut loaddata = Vec::new();
        let mut frames = None;
        let mut body = Vec::new();
        // In the routine: between `PROC` and `ENDPROC`.
        let mut in_routine = false;
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .peekable();
        // A program header: `%%%`, its lines, `%%%`, before the module.
        if lines.peek().map(|l| l.1) == Some("%%%") {
            lines.next();
            loop {
                match lines.next() {
                    Some((_, "%%%")) => break,
                    Some((_, l)) => program_header.push(l.to_string()),
                    None => return Err("a program header '%%%' without its end".into()),
                }
            }
        }
        for (line_no, line) in lines {
            if in_routine {
                if line == "ENDPROC" {
                    in_routine = false;
                } else if let Some(ins) =
                    routine::statement(line).map_err(|e| format!("line {line_no}: {e}"))?
                {
                    if let Instruction::Move(m) = &ins {
                        if m.kind == MoveKind::AbsJ {
                            moves.push(m.to.data().to_string());
                            move_args.push(MoveArgs {
                                target: m.to.data().to_string(),
                                speed: m.speed.clone(),
                                zone: m.zone.clone(),
                                tool: m.tool.clone(),
                                wobj: m.wobj.clone(),
                            });
                        }
                    }
                    body.push(Statement {
                        line: line_no,
                        text: line.to_string(),
                        ins,
                    });
                }
                continue;
            }
            // `LOCAL` makes a declaration module-local; it is read as any other.
            let line = match line.strip_prefix("LOCAL ") {
                Some(rest) => {
                    local += 1;
                    rest
                }
                None => line,
            };
            if let Some(rest) = line.strip_prefix("PROC ") {
                let name = rest
                    .strip_suffix("()")
                    .ok_or_else(|| format!("'{line}': not PROC <name>()"))?;
                if proc_name.replace(name.to_string()).is_some() {
                    return Err("more than one PROC".into());
                }
                in_routine = true;
            } else if let Some(rest) = line.strip_prefix("MODULE ") {
                name = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! planner: ") {
                planner = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! base: ") {
                match numbers(rest)?.as_slice() {
                    [x, y, z, yaw] => base = Some(([*x, *y, *z], *yaw)),
                    _ => return Err(format!("header line '{line}': expected [x, y, z] yaw: deg")),
                }
            } else if let Some(rest) = line.strip_prefix("! clearance (mm): ") {
                clearance = Some(number(rest)?);
            } else if let Some(rest) = line.strip_prefix("! moves: ") {
                header_moves = Some(
                    rest.parse::<usize>()
                        .map_err(|e| format!("'{line}': {e}"))?,
                );
            } else if let Some(rest) = line.strip_prefix("! min clearance (mm): ") {
                min_clearance = Some(match rest {
                    "none (no obstacles)" => None,
                    v => Some(number(v)?),
                });
            } else if let Some(rest) = line.strip_prefix("CONST jointtarget ") {
                let (target, value) = rest
                    .split_once(" := ")
                    .ok_or_else(|| format!("'{line}': no ' := '"))?;
                let axes = value
                    .strip_prefix("[[")
                    .and_then(|v| v.split(']').next())
                    .ok_or_else(|| format!("'{line}': no [[axes]]"))?;
                let v = numbers(axes)?;
                let axes: [f64; 6] = v
                    .try_into()
                    .map_err(|v: Vec<f64>| format!("'{line}': {} axes, expected 6", v.len()))?;
                if !value.ends_with(",[9E9,9E9,9E9,9E9,9E9,9E9]];") {
                    return Err(format!("'{line}': external axes are not 9E9"));
                }
                targets.push((target.to_string(), axes));
            } else if let Some(rest) = line.strip_prefix("! urdf: ") {
                urdf = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! controller: ") {
                controller = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! coupling: ") {
                coupling = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! frames: ") {
                frames = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("CONST robtarget ") {
                let (name, value) = declaration(line, rest)?;
                let v = numbers(value)?;
                if v.len() != 17 || v[11..] != [9e9; 6] {
                    return Err(format!("'{line}': not [[x,y,z],[q..],[cf..],[9E9 x 6]]"));
                }
                if v[7..11].iter().any(|c| c.fract() != 0.0) {
                    return Err(format!("'{line}': confdata is not four integers"));
                }
                robtargets.push((
                    name,
                    RobTarget {
                        pos_mm: [v[0], v[1], v[2]],
                        quat_wxyz: [v[3], v[4], v[5], v[6]],
                        conf: [v[7], v[8], v[9], v[10]].map(|c| c as i32),
                    },
                ));
            } else if let Some(rest) = line.strip_prefix("PERS tooldata ") {
                let (name, value) = declaration(line, rest)?;
                let value = value
                    .strip_prefix("[TRUE,")
                    .ok_or_else(|| format!("'{line}': robhold is not TRUE"))?;
                let v = numbers(value)?;
                if v.len() != 18 || v[11..] != [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0] {
                    return Err(format!("'{line}': not a point-mass tooldata"));
                }
                tooldata.push((
                    name,
                    ToolData {
                        tframe: [v[0], v[1], v[2], v[3], v[4], v[5], v[6]],
                        mass_kg: v[7],
                        cog_mm: [v[8], v[9], v[10]],
                    },
                ));
            } else if let Some(rest) = line.strip_prefix("PERS wobjdata ") {
                let (name, value) = declaration(line, rest)?;
                let value = value
                    .strip_prefix("[FALSE,TRUE,\"\",")
                    .ok_or_else(|| format!("'{line}': not a fixed, not robot-held wobjdata"))?;
                let v = numbers(value)?;
                if v.len() != 14 || v[7..] != [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0] {
                    return Err(format!("'{line}': oframe is not the identity"));
                }
                wobjdata.push((name, [v[0], v[1], v[2], v[3], v[4], v[5], v[6]]));
            } else if let Some(rest) = line.strip_prefix("PERS loaddata ") {
                let (name, value) = declaration(line, rest)?;
                let v = numbers(value)?;
                if v.len() != 11 || v[4..] != [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0] {
                    return Err(format!(
                        "'{line}': not a point-mass loaddata [mass,[cog],[1,0,0,0],0,0,0]"
                    ));
                }
                loaddata.push((
                    name,
                    LoadData {
                        mass_kg: v[0],
                        cog_mm: [v[1], v[2], v[3]],
                    },
                ));
            } else if !(line.is_empty() || line.starts_with('!') || line == "ENDMODULE") {
                return Err(format!(
                    "line {line_no}: '{line}' is neither a comment nor a declaration this check reads"
                ));
            }
        }
        if in_routine {
            return Err("the routine has no ENDPROC".into());
        }
        let missing = |what: &str| format!("the module has no {what}");
        let (base_mm, yaw_deg) = base.ok_or_else(|| missing("'! base:' line"))?;
        Module {
            name: name.ok_or_else(|| missing("MODULE line"))?,
            planner: planner.ok_or_else(|| missing("'! planner:' line"))?,
            base_mm,
            yaw_deg,
            clearance_mm: clearance.ok_or_else(|| missing("'! clearance (mm):' line"))?,
            header_moves: header_moves.ok_or_else(|| missing("'! moves:' line"))?,
            min_clearance_mm: min_clearance
                .ok_or_else(|| missing("'! min clearance (mm):' line"))?,
            targets,
            moves,
            move_args,
            robtargets,
            tooldata,
            wobjdata,
            urdf,
            controller,
            coupling,
            proc_name: proc_name.ok_or_else(|| missing("PROC"))?,
            local,
            program_header,
            loaddata,
            frames,
            body,
        }
        .resolved()
    }

    /// The module with every name its instructions use resolved (module doc), or why not.
    fn resolved(self) -> Result<Module, String> {
        let declared = |list: &[(String, RobTarget)], n: &str| list.iter().any(|(k, _)| k == n);
        let jointtarget = |n: &str| self.targets.iter().any(|(k, _)| k == n);
        for s in &self.body {
            let bad = |why: String| Err(format!("{}: {why}", s.label()));
            match &s.ins {
                Instruction::Move(m) => {
                    let points = m.circle.iter().chain(std::iter::once(&m.to));
                    for p in points {
                        let name = p.data();
                        match (m.kind, p) {
                            (MoveKind::AbsJ, _) if !jointtarget(name) => {
                                return bad(format!(
                                    "MoveAbsJ's target '{name}' is not a declared jointtarget"
                                ))
                            }
                            (MoveKind::AbsJ, _) => {}
                            (k, _) if !declared(&self.robtargets, name) => {
                                let what = match jointtarget(name) {
                                    true => "a jointtarget; its ToPoint is a robtarget",
                                    false => "not a declared robtarget",
                                };
                                return bad(format!("{}'s target '{name}' is {what}", k.name()));
                            }
                            _ => {}
                        }
                    }
                    if let Some(w) = &m.wobj {
                        if w != "wobj0" && !self.wobjdata.iter().any(|(k, _)| k == w) {
                            return bad(format!("\\WObj:={w} names no declared wobjdata"));
                        }
                    }
                }
                Instruction::Action(Action::GripLoad { load })
                    if load != "load0" && !self.loaddata.iter().any(|(k, _)| k == load) =>
                {
                    return bad(format!("GripLoad {load}: no declared loaddata"));
                }
                _ => {}
            }
        }
        Ok(self)
    }

    /// The declared robtarget `name`.
    pub fn robtarget(&self, name: &str) -> Option<&RobTarget> {
        self.robtargets
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, r)| r)
    }

    /// The motion instructions, in order.
    pub fn motions(&self) -> impl Iterator<Item = (&Statement, &routine::Motion)> {
        self.body.iter().filter_map(|s| s.motion().map(|m| (s, m)))
    }

    /// The module moves only by `MoveAbsJ` and runs no action: the form of a module whose robtarget
    /// points are reached by their jointtargets.
    pub fn joint_moves_only(&self) -> bool {
        self.body.iter().all(|s| match &s.ins {
            Instruction::Move(m) => m.kind == MoveKind::AbsJ,
            Instruction::Action(_) => false,
            Instruction::ConfJ(_) | Instruction::ConfL(_) => true,
        })
    }

    /// The waypoints as the controller reaches them: [`targets`](Self::targets),
    /// [`moves`](Self::moves) and [`move_args`](Self::move_args) rebuilt in the routine's
    /// order from every `MoveAbsJ` (its jointtarget as written) and every move to a robtarget
    /// (named `<point>`, `<point>_app` for a MoveJ to a RelTool pose and `<point>_ret` for a
    /// MoveL to one, as the report names them), taken by where it ends: its joints the
    /// independent inverse kinematics of the robtarget as written (moved by `RelTool`), through
    /// the tooldata and wobjdata it names, robot base at `cell_from_robot`, of the written
    /// confdata: ConfJ on; of several such solutions, the one nearest the joints before. An
    /// error when a robtarget has no such solution. The waypoints only, not the paths between
    /// them (`process.rs` runs those).
    pub fn resolve_waypoints(
        &mut self,
        robot: &super::library::Robot,
        cell_from_robot: &nalgebra::Isometry3<f64>,
    ) -> Result<(), String> {
        use super::opw::{max_diff, Ik};
        let ik = Ik::new(robot)?;
        let iso = |v: &[f64]| {
            nalgebra::Isometry3::from_parts(
                nalgebra::Translation3::new(v[0], v[1], v[2]),
                nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
                    v[3], v[4], v[5], v[6],
                )),
            )
        };
        let mut targets: Vec<(String, [f64; 6])> = Vec::new();
        let mut moves = Vec::new();
        let mut move_args = Vec::new();
        let motions: Vec<(String, routine::Motion)> = self
            .motions()
            .map(|(s, m)| (s.label(), m.clone()))
            .collect();
        for (label, m) in motions {
            let name = m.to.data().to_string();
            let (point, axes) = match m.kind {
                MoveKind::AbsJ => {
                    let axes = self.target(&name);
                    (name.clone(), axes)
                }
                MoveKind::J | MoveKind::L | MoveKind::C => {
                    let r = self
                        .robtarget(&name)
                        .ok_or_else(|| format!("{label}: no robtarget {name}"))?;
                    let tframe = match self.tooldata.iter().find(|(n, _)| *n == m.tool) {
                        Some((_, t)) => iso(&t.tframe),
                        None => nalgebra::Isometry3::identity(),
                    };
                    let uframe = match self
                        .wobjdata
                        .iter()
                        .find(|(n, _)| Some(n) == m.wobj.as_ref())
                    {
                        Some((_, w)) => iso(w),
                        None => nalgebra::Isometry3::identity(),
                    };
                    let pose = [r.pos_mm.as_slice(), r.quat_wxyz.as_slice()].concat();
                    let offset = match &m.to {
                        ToPoint::RelTool { offset_mm: d, .. } => {
                            nalgebra::Translation3::new(d[0], d[1], d[2])
                        }
                        ToPoint::Name(_) => nalgebra::Translation3::identity(),
                    };
                    let tool0 =
                        cell_from_robot.inverse() * uframe * iso(&pose) * offset * tframe.inverse();
                    let before = targets.last().map(|t| t.1);
                    let axes = ik
                        .with_conf(&tool0, &r.conf)
                        .into_iter()
                        .map(|s| s.axes)
                        .min_by(|a, b| {
                            let d = |x: &[f64; 6]| before.map_or(0.0, |p| max_diff(x, &p));
                            d(a).total_cmp(&d(b))
                        })
                        .ok_or_else(|| {
                            format!("{label}: {name} has no solution of confdata {:?}", r.conf)
                        })?;
                    let point = name.strip_suffix("_rt").unwrap_or(&name);
                    let point = match (&m.to, m.kind) {
                        (ToPoint::RelTool { .. }, MoveKind::J) => format!("{point}_app"),
                        (ToPoint::RelTool { .. }, _) => format!("{point}_ret"),
                        _ => point.to_string(),
                    };
                    (point, axes)
                }
            };
            moves.push(point.clone());
            move_args.push(MoveArgs {
                target: point.clone(),
                speed: m.speed.clone(),
                zone: m.zone.clone(),
                tool: m.tool.clone(),
                wobj: m.wobj.clone(),
            });
            targets.push((point, axes));
        }
        self.targets = targets;
        self.moves = moves;
        self.move_args = move_args;
        Ok(())
    }

    /// The axes of target `name`.
    pub fn target(&self, name: &str) -> [f64; 6] {
        self.targets
            .iter()
            .find(|t| t.0 == name)
            .map(|t| t.1)
            .unwrap_or_else(|| panic!("the module has no target {name}"))
    }
}

/// `NAME := VALUE;` -> (NAME, VALUE without the `;`).
fn declaration<'a>(line: &str, rest: &'a str) -> Result<(String, &'a str), String> {
    let (name, value) = rest
        .split_once(" := ")
        .ok_or_else(|| format!("'{line}': no ' := '"))?;
    let value = value
        .strip_suffix(';')
        .ok_or_else(|| format!("'{line}': no final ';'"))?;
    Ok((name.to_string(), value))
}

fn number(s: &str) -> Result<f64, String> {
    s.trim()
        .parse::<f64>()
        .map_err(|_| format!("'{s}' is not a number"))
}

/// The numbers in `s`, separated by anything but digits, '.', '-' and 'E'.
fn numbers(s: &str) -> Result<Vec<f64>, String> {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'E'))
        .filter(|t| !t.is_empty())
        .map(number)
        .collect()
}
