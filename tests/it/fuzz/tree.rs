//! The fuzz target's structured edits: a cell file read as a YAML tree (keys in order,
//! duplicates allowed), edited (values, keys, lists, nesting), and written back as YAML the way
//! the example cells are written.

use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;

/// A cell file as a tree (keys kept in order, duplicates allowed).
#[derive(Clone, Debug)]
pub(super) enum Y {
    Map(Vec<(String, Y)>),
    Seq(Vec<Y>),
    Scalar(String),
}

impl<'de> Deserialize<'de> for Y {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Y, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Y;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("any YAML")
            }
            fn visit_bool<E>(self, v: bool) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_i64<E>(self, v: i64) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_u64<E>(self, v: u64) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_f64<E>(self, v: f64) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_str<E>(self, v: &str) -> Result<Y, E> {
                Ok(Y::Scalar(v.to_string()))
            }
            fn visit_unit<E>(self) -> Result<Y, E> {
                Ok(Y::Scalar("null".into()))
            }
            fn visit_none<E>(self) -> Result<Y, E> {
                Ok(Y::Scalar("null".into()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut a: A) -> Result<Y, A::Error> {
                let mut v = Vec::new();
                while let Some(y) = a.next_element()? {
                    v.push(y);
                }
                Ok(Y::Seq(v))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut a: A) -> Result<Y, A::Error> {
                let mut v = Vec::new();
                while let Some((k, y)) = a.next_entry::<Y, Y>()? {
                    let k = match k {
                        Y::Scalar(s) => s,
                        other => emit_flow(&other),
                    };
                    v.push((k, y));
                }
                Ok(Y::Map(v))
            }
        }
        d.deserialize_any(V)
    }
}

/// A scalar as YAML: plain where that reads back the same text, else double-quoted.
fn scalar(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "._-+/".contains(c))
        && !s.starts_with(['-', '.'])
        || s.parse::<f64>().is_ok();
    if plain {
        s.to_string()
    } else {
        format!("{s:?}")
    }
}

pub(super) fn emit_flow(y: &Y) -> String {
    match y {
        Y::Scalar(s) => scalar(s),
        Y::Seq(v) => format!(
            "[{}]",
            v.iter().map(emit_flow).collect::<Vec<_>>().join(", ")
        ),
        Y::Map(v) => format!(
            "{{ {} }}",
            v.iter()
                .map(|(k, y)| format!("{}: {}", scalar(k), emit_flow(y)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Block style for mappings, flow style for lists (as the example cells write them).
pub(super) fn emit(y: &Y, indent: usize, out: &mut String) {
    let pad = " ".repeat(indent);
    match y {
        Y::Map(v) => {
            for (k, y) in v {
                match y {
                    Y::Map(m) if !m.is_empty() => {
                        out.push_str(&format!("{pad}{}:\n", scalar(k)));
                        emit(y, indent + 2, out);
                    }
                    Y::Seq(s) if s.iter().any(|i| matches!(i, Y::Map(_))) => {
                        out.push_str(&format!("{pad}{}:\n", scalar(k)));
                        for item in s {
                            out.push_str(&format!("{pad}  - {}\n", emit_flow(item)));
                        }
                    }
                    _ => out.push_str(&format!("{pad}{}: {}\n", scalar(k), emit_flow(y))),
                }
            }
        }
        other => out.push_str(&format!("{pad}{}\n", emit_flow(other))),
    }
}

pub(super) fn size(y: &Y) -> usize {
    match y {
        Y::Scalar(s) => s.len() + 2,
        Y::Seq(v) => 2 + v.iter().map(size).sum::<usize>(),
        Y::Map(v) => v.iter().map(|(k, y)| k.len() + 2 + size(y)).sum(),
    }
}

/// Every node's path (indices from the root).
pub(super) fn paths(y: &Y, at: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
    out.push(at.clone());
    let children: Vec<&Y> = match y {
        Y::Map(v) => v.iter().map(|(_, y)| y).collect(),
        Y::Seq(v) => v.iter().collect(),
        Y::Scalar(_) => return,
    };
    for (i, c) in children.into_iter().enumerate() {
        at.push(i);
        paths(c, at, out);
        at.pop();
    }
}

pub(super) fn node<'a>(y: &'a mut Y, path: &[usize]) -> &'a mut Y {
    let Some((&first, rest)) = path.split_first() else {
        return y;
    };
    match y {
        Y::Map(v) => node(&mut v[first].1, rest),
        Y::Seq(v) => node(&mut v[first], rest),
        Y::Scalar(_) => y,
    }
}

pub(super) const KEYS: &[&str] = &[
    "module",
    "robot",
    "urdf",
    "base",
    "yaw",
    "wrist",
    "obstacles",
    "name",
    "box",
    "min",
    "max",
    "points",
    "joints",
    "xyz",
    "branch",
    "planner",
    "method",
    "grid",
    "clearance",
    "motion",
    "speed",
    "zone",
    "tool",
    "controller",
    "robtarget",
    "tframe",
    "mass",
    "cog",
    "shapes",
    "cylinder",
    "sphere",
    "from",
    "to",
    "radius",
    "centre",
    "wobj",
    "uframe",
    "wobjs",
    "loads",
    "frame",
    "cycle",
    "revisit",
    "move",
    "via",
    "approach",
    "retract",
    "do",
    "set_do",
    "pulse_do",
    "wait_di",
    "wait_time",
    "grip_load",
    "zyx",
];

const NAMES: &[&str] = &[
    "main",
    "Main",
    "MoveAbsJ",
    "If",
    "v300",
    "fine",
    "tool0",
    "wobj0",
    "via01_01",
    "via01_01_x1",
    "tTorch",
    "wobjTrunk",
    "load0",
    "loadPart",
    "doWeld",
    "diReady",
    "linear",
    "circular",
    "joint",
    "base",
    "cell",
    "home",
    "W1_rt",
    "main_rt",
    "tool0_rt",
    "A",
    "a",
    "P1",
    "auto",
    "",
    " ",
    "9lives",
    "é",
    "x y",
    "extensile",
    "depth-first",
    "back-elbow-up",
    "null",
    "~",
    "true",
    "0x10",
    "1e3",
    "'",
    "\"",
    "#",
    "&a",
    "*a",
    "!!str",
    "- x",
    "[",
    "{",
];

fn weird_number(rng: &mut fastrand::Rng) -> String {
    match rng.u32(0..20) {
        0 => ".nan".into(),
        1 => "nan".into(),
        2 => ".inf".into(),
        3 => "-.inf".into(),
        4 => "1e308".into(),
        5 => "-1e308".into(),
        6 => "1e999".into(),
        7 => "1e-320".into(),
        8 => "-0".into(),
        9 => "9".repeat(rng.usize(20..400)),
        10 => format!("0.{}", "1".repeat(rng.usize(4..40))),
        11 => format!("{}.{}", rng.i64(-100000..100000), rng.u32(0..100000)),
        12 => "0x1F".into(),
        13 => "1_000".into(),
        14 => "+5".into(),
        15 => format!("{}", rng.i32(..)),
        16 => format!("{:.3}", rng.f64() * 720.0 - 360.0),
        17 => format!("{:.1}", rng.f64() * 6000.0 - 3000.0),
        18 => format!("-{}", rng.u32(0..100000)),
        _ => format!("{:e}", rng.f64() * 10f64.powi(rng.i32(-300..300))),
    }
}

fn weird_string(rng: &mut fastrand::Rng) -> String {
    match rng.u32(0..6) {
        0 => "x".repeat(rng.usize(33..60_000)),
        1 => NAMES[rng.usize(..NAMES.len())].to_string(),
        2 => (0..rng.usize(1..40))
            .map(|_| char::from_u32(rng.u32(1..0x3000)).unwrap_or('?'))
            .collect(),
        3 => format!("P{}", rng.u32(0..5)),
        4 => format!("../robots/{}.urdf", "r".repeat(rng.usize(0..10))),
        _ => KEYS[rng.usize(..KEYS.len())].to_string(),
    }
}

fn random_node(rng: &mut fastrand::Rng, depth: usize) -> Y {
    match rng.u32(0..if depth > 2 { 2 } else { 4 }) {
        0 => Y::Scalar(weird_number(rng)),
        1 => Y::Scalar(weird_string(rng)),
        2 => Y::Seq(
            (0..rng.usize(0..8))
                .map(|_| random_node(rng, depth + 1))
                .collect(),
        ),
        _ => Y::Map(
            (0..rng.usize(0..5))
                .map(|_| {
                    (
                        KEYS[rng.usize(..KEYS.len())].to_string(),
                        random_node(rng, depth + 1),
                    )
                })
                .collect(),
        ),
    }
}

fn misspell(rng: &mut fastrand::Rng, k: &str) -> String {
    let mut c: Vec<char> = k.chars().collect();
    match rng.u32(0..5) {
        0 if !c.is_empty() => {
            c.remove(rng.usize(..c.len()));
        }
        1 => c.insert(rng.usize(..=c.len()), char::from(rng.u8(b'a'..=b'z'))),
        2 if c.len() > 1 => {
            let i = rng.usize(..c.len() - 1);
            c.swap(i, i + 1);
        }
        3 => return k.to_uppercase(),
        _ => c.push('s'),
    }
    c.into_iter().collect()
}

/// Grafts a section of another cell (`tool:`, `wobj:`, `points:`, `motion:`, ...) into `root`,
/// in place of its own or added: a tool and robtargets land in a cell without them, names of one
/// cell meet those of another.
pub(super) fn graft(rng: &mut fastrand::Rng, root: &mut Y, donor: &Y) {
    let (Y::Map(to), Y::Map(from)) = (root, donor) else {
        return;
    };
    if from.is_empty() {
        return;
    }
    let (key, section) = from[rng.usize(..from.len())].clone();
    match to.iter_mut().find(|(k, _)| *k == key) {
        Some((_, mine)) => *mine = section,
        None => to.push((key, section)),
    }
}

/// One structured edit of the tree.
pub(super) fn mutate_tree(rng: &mut fastrand::Rng, root: &mut Y) {
    let mut all = Vec::new();
    paths(root, &mut Vec::new(), &mut all);
    let path = all[rng.usize(..all.len())].clone();
    let donor = {
        let p = &all[rng.usize(..all.len())];
        node(&mut root.clone(), p).clone()
    };
    let n = node(root, &path);
    match n {
        Y::Scalar(s) => {
            *s = match rng.u32(0..3) {
                0 if s.parse::<f64>().is_ok() => weird_number(rng),
                0 | 1 => weird_string(rng),
                _ => weird_number(rng),
            };
            if rng.u32(0..8) == 0 {
                *n = donor;
            }
        }
        Y::Seq(v) => match rng.u32(0..8) {
            0 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                let item = v[i].clone();
                for _ in 0..rng.usize(1..60) {
                    v.insert(i, item.clone());
                }
            }
            1 if !v.is_empty() => {
                v.remove(rng.usize(..v.len()));
            }
            2 => v.clear(),
            3 => v.push(random_node(rng, 1)),
            4 => v.push(Y::Scalar(weird_number(rng))),
            5 => {
                let mut deep = n.clone();
                for _ in 0..rng.usize(1..400) {
                    deep = Y::Seq(vec![deep]);
                }
                *n = deep;
            }
            6 => *n = donor,
            _ => {
                if v.len() > 1 {
                    v.truncate(rng.usize(1..v.len()));
                }
            }
        },
        Y::Map(v) => match rng.u32(0..8) {
            0 if !v.is_empty() => {
                v.remove(rng.usize(..v.len()));
            }
            1 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                let dup = v[i].clone();
                v.insert(rng.usize(..=v.len()), dup);
            }
            2 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                v[i].0 = misspell(rng, &v[i].0);
            }
            3 => v.push((
                KEYS[rng.usize(..KEYS.len())].to_string(),
                random_node(rng, 1),
            )),
            4 if !v.is_empty() => {
                let i = rng.usize(..v.len());
                v[i].0 = KEYS[rng.usize(..KEYS.len())].to_string();
            }
            5 => *n = donor,
            6 => {
                let mut deep = n.clone();
                for _ in 0..rng.usize(1..300) {
                    deep = Y::Map(vec![("robot".into(), deep)]);
                }
                *n = deep;
            }
            _ => v.reverse(),
        },
    }
}

/// A plausible value for a scalar (the light edits: the cell mostly stays valid).
pub(super) fn plausible(rng: &mut fastrand::Rng, s: &str) -> String {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => match rng.u32(0..6) {
            0 => format!("{}", v.round() + f64::from(rng.i32(-20..20))),
            1 => format!("{:.3}", v + rng.f64() * 10.0 - 5.0),
            2 => format!("{:.1}", v * (0.5 + rng.f64())),
            3 => format!("{}", -v),
            // Extreme values that still pass validation (no more decimals than allowed).
            4 => [
                "1e15",
                "-1e15",
                "1e9",
                "0",
                "9007199254740993",
                "1e300",
                "-1e300",
                "0.001",
            ][rng.usize(..8)]
            .to_string(),
            _ => format!("{}", rng.i64(-10_000_000..10_000_000)),
        },
        _ => match rng.u32(0..3) {
            0 => format!("{s}{}", rng.u32(0..10)),
            1 => s.to_uppercase(),
            _ => s.to_string(),
        },
    }
}
