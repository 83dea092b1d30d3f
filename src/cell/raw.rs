//! The cell file as written: serde types close to the YAML, unknown keys refused, every item
//! that a later error may point at wrapped in [`Spanned`] so the message can give line:column.

use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use serde_saphyr::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCell {
    pub module: Spanned<String>,
    pub robot: Spanned<RawRobot>,
    #[serde(default)]
    pub obstacles: Vec<Spanned<RawObstacle>>,
    pub points: Spanned<Vec<Spanned<RawPoint>>>,
    #[serde(default)]
    pub planner: Option<Spanned<RawPlanner>>,
    #[serde(default)]
    pub motion: Option<Spanned<RawMotion>>,
    #[serde(default)]
    pub tool: Option<Spanned<RawTool>>,
    #[serde(default)]
    pub wobj: Option<Spanned<RawWobj>>,
    /// Several work objects (instead of `wobj:`).
    #[serde(default)]
    pub wobjs: Option<Spanned<Vec<Spanned<RawWobj>>>>,
    /// The loaddata the module declares (for `grip_load`).
    #[serde(default)]
    pub loads: Option<Spanned<Vec<Spanned<RawLoad>>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRobot {
    /// A URDF file; or `model`, a shipped robot (exactly one of the two).
    #[serde(default)]
    pub urdf: Option<Spanned<String>>,
    #[serde(default)]
    pub model: Option<Spanned<String>>,
    pub base: Spanned<RawBase>,
    #[serde(default)]
    pub yaw: Option<Spanned<f64>>,
    #[serde(default)]
    pub wrist: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub controller: Option<Spanned<String>>,
    /// `cell` or `base`: the frame uframes and wobj0 robtargets are written in.
    #[serde(default)]
    pub frame: Option<Spanned<String>>,
}

/// `base: [x, y, z]` or `base: auto`.
#[derive(Debug)]
pub enum RawBase {
    Xyz(Vec<f64>),
    Auto,
}

impl<'de> Deserialize<'de> for RawBase {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = RawBase;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a position [x, y, z] in mm, or `auto`")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<RawBase, E> {
                if s == "auto" {
                    Ok(RawBase::Auto)
                } else {
                    Err(E::invalid_value(de::Unexpected::Str(s), &self))
                }
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<RawBase, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    v.push(x);
                }
                Ok(RawBase::Xyz(v))
            }
        }
        d.deserialize_any(V)
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawObstacle {
    pub name: Spanned<String>,
    #[serde(rename = "box")]
    pub aabb: Spanned<RawBox>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBox {
    pub min: Spanned<Vec<f64>>,
    pub max: Spanned<Vec<f64>>,
}

/// One entry of `points:`: a point (`name` and one of `joints`, `xyz`, `robtarget`) or a
/// revisit (`revisit: NAME`), with how it is reached and what is done there.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPoint {
    /// (A `name: ~` is a text missing, not a point without a name: [`present`].)
    #[serde(default, deserialize_with = "present")]
    pub name: Option<Spanned<String>>,
    #[serde(default, deserialize_with = "present")]
    pub revisit: Option<Spanned<String>>,
    #[serde(default)]
    pub joints: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub xyz: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub branch: Option<Spanned<String>>,
    /// `[[x, y, z], ORIENTATION]` or `[[x, y, z], ORIENTATION, [cf1, cf4, cf6, cfx]]`.
    #[serde(default)]
    pub robtarget: Option<RawPose>,
    /// The work object a robtarget is given in.
    #[serde(default)]
    pub wobj: Option<Spanned<String>>,
    #[serde(default)]
    pub speed: Option<Spanned<String>>,
    #[serde(default)]
    pub zone: Option<Spanned<String>>,
    /// `joint`, `linear` or `circular`.
    #[serde(default, rename = "move")]
    pub arrival: Option<Spanned<String>>,
    /// A point of the arc (`move: circular`).
    #[serde(default)]
    pub via: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub approach: Option<Spanned<f64>>,
    #[serde(default)]
    pub retract: Option<Spanned<f64>>,
    /// The actions at the point, in order.
    #[serde(default, rename = "do")]
    pub actions: Option<Spanned<Vec<Spanned<RawAction>>>>,
}

/// A key that, when given, must hold a value: `key: ~` is refused by the value's own reader (as
/// `name: ~` is for a required name), not read as the key left out.
fn present<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<Option<T>, D::Error> {
    T::deserialize(d).map(Some)
}

/// One action of a point's `do:` list: a mapping of one of these keys.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawAction {
    /// `[signal, 0|1]`.
    #[serde(default)]
    pub set_do: Option<Spanned<Vec<Spanned<RawArg>>>>,
    /// `signal`.
    #[serde(default)]
    pub pulse_do: Option<Spanned<String>>,
    /// `[signal, 0|1]`.
    #[serde(default)]
    pub wait_di: Option<Spanned<Vec<Spanned<RawArg>>>>,
    /// Seconds.
    #[serde(default)]
    pub wait_time: Option<Spanned<f64>>,
    /// `load0` or a `loads:` entry.
    #[serde(default)]
    pub grip_load: Option<Spanned<String>>,
}

/// One argument of `set_do` / `wait_di` as written: a name or a number (anything else is kept as
/// what it is, for the message).
#[derive(Debug, Clone, PartialEq)]
pub enum RawArg {
    Text(String),
    Number(f64),
    Bool(bool),
    /// A list, a mapping or nothing.
    Other(&'static str),
}

impl<'de> Deserialize<'de> for RawArg {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = RawArg;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a signal name or 0 or 1")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<RawArg, E> {
                Ok(RawArg::Text(s.to_string()))
            }
            fn visit_bool<E: de::Error>(self, b: bool) -> Result<RawArg, E> {
                Ok(RawArg::Bool(b))
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> Result<RawArg, E> {
                Ok(RawArg::Number(x as f64))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> Result<RawArg, E> {
                Ok(RawArg::Number(x as f64))
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> Result<RawArg, E> {
                Ok(RawArg::Number(x))
            }
            fn visit_unit<E: de::Error>(self) -> Result<RawArg, E> {
                Ok(RawArg::Other("nothing"))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<RawArg, A::Error> {
                while seq.next_element::<de::IgnoredAny>()?.is_some() {}
                Ok(RawArg::Other("a list"))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<RawArg, A::Error> {
                while map
                    .next_entry::<de::IgnoredAny, de::IgnoredAny>()?
                    .is_some()
                {}
                Ok(RawArg::Other("a mapping"))
            }
        }
        d.deserialize_any(V)
    }
}

/// One entry of `loads:`: loaddata the module declares.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLoad {
    pub name: Spanned<String>,
    #[serde(default)]
    pub mass: Option<Spanned<f64>>,
    #[serde(default)]
    pub cog: Option<Spanned<Vec<f64>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPlanner {
    #[serde(default)]
    pub method: Option<Spanned<String>>,
    #[serde(default)]
    pub grid: Option<Spanned<f64>>,
    #[serde(default)]
    pub clearance: Option<Spanned<f64>>,
    #[serde(default)]
    pub shortcut: Option<Spanned<bool>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMotion {
    #[serde(default)]
    pub speed: Option<Spanned<String>>,
    #[serde(default)]
    pub zone: Option<Spanned<String>>,
    #[serde(default)]
    pub tool: Option<Spanned<String>>,
    #[serde(default)]
    pub proc: Option<Spanned<String>>,
    #[serde(default)]
    pub via_zone: Option<Spanned<String>>,
    /// Plan and write the leg from the last point back to the first.
    #[serde(default)]
    pub cycle: Option<Spanned<bool>>,
}

/// A pose as RAPID writes it, `[[x, y, z], ORIENTATION]` (a robtarget may add its confdata):
/// each part a list of numbers, or for the orientation `{ zyx: [ez, ey, ex] }`.
pub type RawPose = Spanned<Vec<Spanned<RawPart>>>;

/// One part of a pose as written.
#[derive(Debug)]
pub enum RawPart {
    /// A list of numbers: a position, a quaternion or confdata.
    Numbers(Vec<f64>),
    /// `{ zyx: [ez, ey, ex] }`: RAPID's `OrientZYX`, deg.
    Zyx(Spanned<Vec<f64>>),
}

/// The mapping form of an orientation.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawZyx {
    zyx: Spanned<Vec<f64>>,
}

impl<'de> Deserialize<'de> for RawPart {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = RawPart;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a list of numbers, or an orientation `{ zyx: [ez, ey, ex] }`")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<RawPart, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    v.push(x);
                }
                Ok(RawPart::Numbers(v))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<RawPart, A::Error> {
                let z = RawZyx::deserialize(de::value::MapAccessDeserializer::new(map))?;
                Ok(RawPart::Zyx(z.zyx))
            }
        }
        d.deserialize_any(V)
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTool {
    pub name: Spanned<String>,
    pub tframe: RawPose,
    #[serde(default)]
    pub mass: Option<Spanned<f64>>,
    #[serde(default)]
    pub cog: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub shapes: Vec<Spanned<RawShape>>,
}

/// One tool shape: a name and exactly one of `cylinder`, `box`, `sphere`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawShape {
    pub name: Spanned<String>,
    #[serde(default)]
    pub cylinder: Option<Spanned<RawCylinder>>,
    #[serde(default, rename = "box")]
    pub aabb: Option<Spanned<RawBox>>,
    #[serde(default)]
    pub sphere: Option<Spanned<RawSphere>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCylinder {
    pub from: Spanned<Vec<f64>>,
    pub to: Spanned<Vec<f64>>,
    pub radius: Spanned<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSphere {
    pub centre: Spanned<Vec<f64>>,
    pub radius: Spanned<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWobj {
    pub name: Spanned<String>,
    pub uframe: RawPose,
}
