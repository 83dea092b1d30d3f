//! The fuzz target's unstructured cases: YAML-ish token soup, and byte and line edits of a
//! cell file.

use super::tree::KEYS;

const TOKENS: &[&str] = &[
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    ": ",
    "- ",
    "\n",
    "\n  ",
    "  ",
    "\t",
    "#",
    "'",
    "\"",
    "&a ",
    "*a",
    "!!str ",
    "|",
    ">",
    "---\n",
    "...\n",
    "? ",
    "%YAML 1.2\n",
    "\r",
    "\r\n",
    "\\",
    "~",
    "null",
    "1e999",
    ".nan",
    "-",
    "0",
    "module",
    "robot",
    "points",
    "joints",
    "xyz",
    "base",
    "auto",
    "\u{feff}",
    "\u{0}",
    "é",
    "\u{2028}",
];

pub(super) fn token_soup(rng: &mut fastrand::Rng) -> Vec<u8> {
    let mut out = String::new();
    for _ in 0..rng.usize(0..400) {
        if rng.u32(0..4) == 0 {
            out.push_str(KEYS[rng.usize(..KEYS.len())]);
        } else {
            out.push_str(TOKENS[rng.usize(..TOKENS.len())]);
        }
    }
    out.into_bytes()
}

pub(super) fn mutate_bytes(rng: &mut fastrand::Rng, mut b: Vec<u8>, other: &[u8]) -> Vec<u8> {
    for _ in 0..rng.usize(1..8) {
        let at = rng.usize(..=b.len());
        match rng.u32(0..7) {
            0 if !b.is_empty() => {
                let i = rng.usize(..b.len());
                b[i] = rng.u8(..);
            }
            1 if !b.is_empty() => {
                let end = (at + rng.usize(1..64)).min(b.len());
                b.drain(at.min(end)..end);
            }
            2 => {
                let t = TOKENS[rng.usize(..TOKENS.len())].as_bytes();
                b.splice(at..at, t.iter().copied());
            }
            3 => {
                let n = rng.usize(1..200_000);
                let c = *b"[{x9 -:".get(rng.usize(..7)).unwrap_or(&b'[');
                b.splice(at..at, std::iter::repeat_n(c, n));
            }
            4 if !other.is_empty() => {
                let s = rng.usize(..other.len());
                let e = (s + rng.usize(1..400)).min(other.len());
                b.splice(at..at, other[s..e].iter().copied());
            }
            5 => b.truncate(at),
            _ => {
                b.splice(at..at, (0..rng.usize(1..16)).map(|_| rng.u8(..)));
            }
        }
    }
    b
}

pub(super) fn mutate_lines(rng: &mut fastrand::Rng, text: &str) -> Vec<u8> {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for _ in 0..rng.usize(1..5) {
        if lines.is_empty() {
            break;
        }
        let i = rng.usize(..lines.len());
        match rng.u32(0..8) {
            0 => {
                lines.remove(i);
            }
            1 => {
                let l = lines[i].clone();
                lines.insert(i, l);
            }
            2 => lines[i] = format!(" {}", lines[i]),
            3 => lines[i] = lines[i].trim_start().to_string(),
            4 => lines[i] = format!("\t{}", lines[i].trim_start()),
            5 => lines[i] = lines[i].replacen(": ", ":", 1),
            6 => lines[i] = lines[i].replacen(':', "", 1),
            _ => {
                let l = lines[i].clone();
                for _ in 0..rng.usize(1..100) {
                    lines.insert(i, l.clone());
                }
            }
        }
    }
    let mut out = lines.join(if rng.u32(0..10) == 0 { "\r\n" } else { "\n" });
    out.push('\n');
    out.into_bytes()
}
