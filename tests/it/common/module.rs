//! Reading a written module as text (not through the library's types): a program header
//! (`%%%` ... `%%%`) before it, the header's facts, the `CONST jointtarget` and
//! `CONST robtarget` declarations, the `PERS tooldata` and `PERS wobjdata` (any of them
//! `LOCAL`), the routine's name, and the `MoveAbsJ` moves with their speed, zone, tool and work
//! object.

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
        let mut lines = text.lines().map(str::trim).peekable();
        // A program header: `%%%`, its lines, `%%%`, before the module.
        if lines.peek() == Some(&"%%%") {
            lines.next();
            loop {
                match lines.next() {
                    Some("%%%") => break,
                    Some(l) => program_header.push(l.to_string()),
                    None => return Err("a program header '%%%' without its end".into()),
                }
            }
        }
        for line in lines {
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
            } else if let Some(rest) = line.strip_prefix("MoveAbsJ ") {
                let target = rest.split('\\').next().unwrap_or_default();
                moves.push(target.to_string());
                move_args.push(move_args_of(line)?);
            } else if let Some(rest) = line.strip_prefix("! urdf: ") {
                urdf = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! controller: ") {
                controller = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("! coupling: ") {
                coupling = Some(rest.to_string());
            } else if let Some(rest) = line.strip_prefix("CONST robtarget ") {
                let (name, value) = declaration(line, rest)?;
                let v = numbers(value)?;
                if v.len() != 17 || v[11..] != [9e9; 6] {
                    return Err(format!("'{line}': not [[x,y,z],[q..],[cf..],[9E9 x 6]]"));
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
            }
        }
        let missing = |what: &str| format!("the module has no {what}");
        let (base_mm, yaw_deg) = base.ok_or_else(|| missing("'! base:' line"))?;
        Ok(Module {
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
        })
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

/// The arguments of a `MoveAbsJ` line.
fn move_args_of(line: &str) -> Result<MoveArgs, String> {
    let bad = || format!("'{line}': not MoveAbsJ T\\NoEOffs, speed, zone, tool[\\WObj:=w];");
    let rest = line
        .strip_prefix("MoveAbsJ ")
        .and_then(|r| r.strip_suffix(';'))
        .ok_or_else(bad)?;
    let (target, rest) = rest.split_once("\\NoEOffs, ").ok_or_else(bad)?;
    let parts: Vec<&str> = rest.split(", ").collect();
    let [speed, zone, tool] = parts.as_slice() else {
        return Err(bad());
    };
    let (tool, wobj) = match tool.split_once("\\WObj:=") {
        Some((t, w)) => (t, Some(w.to_string())),
        None => (*tool, None),
    };
    Ok(MoveArgs {
        target: target.to_string(),
        speed: speed.to_string(),
        zone: zone.to_string(),
        tool: tool.to_string(),
        wobj,
    })
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
