//! The cell file as written: serde types close to the YAML, unknown keys refused, every item
//! that a later error may point at wrapped in [`Spanned`] so the message can give line:column.

use serde::de::{self, Deserializer, SeqAccess, Visitor};
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

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPoint {
    pub name: Spanned<String>,
    #[serde(default)]
    pub joints: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub xyz: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub branch: Option<Spanned<String>>,
    /// `[[x, y, z], [q1, q2, q3, q4]]` or `[[x, y, z], [q1, q2, q3, q4], [cf1, cf4, cf6, cfx]]`.
    #[serde(default)]
    pub robtarget: Option<Spanned<Vec<Spanned<Vec<f64>>>>>,
    #[serde(default)]
    pub speed: Option<Spanned<String>>,
    #[serde(default)]
    pub zone: Option<Spanned<String>>,
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
}

/// A pose as RAPID writes it, `[[x, y, z], [q1, q2, q3, q4]]`.
pub type RawPose = Spanned<Vec<Spanned<Vec<f64>>>>;

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
