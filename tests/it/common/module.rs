//! Reading a written module as text (not through the library's types): the header's facts, the
//! `CONST jointtarget` declarations and the `MoveAbsJ` moves.

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
        for line in text.lines().map(str::trim) {
            if let Some(rest) = line.strip_prefix("MODULE ") {
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
