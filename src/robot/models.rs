//! The robots built into the binary: each one's URDF and controller file from `robots/`, as
//! text (`include_str!`), so an installed gen-rapid has them all and a cell names one by
//! `robot.model` instead of `robot.urdf`. [`Robot::shipped`](super::Robot::shipped) reads one
//! from this text as [`Robot::load`](super::Robot::load) reads files. The facts behind each
//! file and their public sources: `docs/irb1400.md` and `docs/robots.md`.

/// One shipped robot.
#[derive(Clone, Copy, Debug)]
pub struct Model {
    /// The name a cell gives (`robot.model`), also the stem of its files in `robots/`.
    pub name: &'static str,
    /// ABB's name of the variant.
    pub title: &'static str,
    /// The URDF's text.
    pub urdf: &'static str,
    /// The controller file's text.
    pub controller: &'static str,
}

macro_rules! model {
    ($name:literal, $title:literal) => {
        Model {
            name: $name,
            title: $title,
            urdf: include_str!(concat!("../../robots/", $name, ".urdf")),
            controller: include_str!(concat!("../../robots/", $name, ".controller.yaml")),
        }
    };
}

/// Every shipped robot, the IRB 1400 first, then by size.
pub const MODELS: [Model; 7] = [
    model!("irb1400", "ABB IRB 1400"),
    model!("irb120_3_58", "ABB IRB 120-3/0.58"),
    model!("irb1200_5_90", "ABB IRB 1200-5/0.90"),
    model!("irb1600_8_145", "ABB IRB 1600-8/1.45"),
    model!("irb2400_12_155", "ABB IRB 2400-12/1.55"),
    model!("irb2600_12_165", "ABB IRB 2600-12/1.65"),
    model!("irb4600_60_205", "ABB IRB 4600-60/2.05"),
];

/// The shipped robot of that name (exactly as [`Model::name`] spells it).
pub fn find(name: &str) -> Option<&'static Model> {
    MODELS.iter().find(|m| m.name == name)
}

/// The names, comma-separated in [`MODELS`]' order (for messages).
pub fn names() -> String {
    MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
}
