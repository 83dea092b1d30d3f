//! Template settings (`--set NAME=VALUE`, repeatable, with `--template`): text a user's
//! template reads as `settings.NAME`, for names that belong to the site rather than to the cell
//! (an arc-welding template's seamdata and welddata, a signal's name). The cell's keys stay as
//! they are; a template that reads a setting not given fails at its line (strict undefined
//! names) unless it gives a default (`settings.seam | default("seam1")`).
//!
//! A name is a template identifier (a letter or `_`, then letters, digits and `_`, at most
//! [`MAX_NAME_CHARS`]); a value is printable ASCII, 1 to [`MAX_VALUE_CHARS`] characters (it
//! goes into the module's text as it is). A name given twice is refused: which one would win is
//! not obvious on a command line.

use std::collections::BTreeMap;

/// The longest setting name.
pub const MAX_NAME_CHARS: usize = 32;
/// The longest setting value.
pub const MAX_VALUE_CHARS: usize = 256;

/// One `NAME=VALUE` as the command line gives it (clap's value parser: the message is the
/// command-line error's).
pub fn parse_setting(s: &str) -> Result<(String, String), String> {
    let (name, value) = s
        .split_once('=')
        .ok_or_else(|| format!("'{s}' is not NAME=VALUE"))?;
    let name_ok = name.len() <= MAX_NAME_CHARS
        && name
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !name_ok {
        return Err(format!(
            "'{name}' is not a setting name (a letter or '_', then letters, digits and '_', at most {MAX_NAME_CHARS})"
        ));
    }
    let value_ok = !value.is_empty()
        && value.chars().count() <= MAX_VALUE_CHARS
        && value.chars().all(|c| (' '..='~').contains(&c));
    if !value_ok {
        return Err(format!(
            "the value of '{name}' must be 1 to {MAX_VALUE_CHARS} printable ASCII characters"
        ));
    }
    Ok((name.to_string(), value.to_string()))
}

/// The settings by name; a name given twice is refused (the message names it).
pub fn settings_map(list: &[(String, String)]) -> Result<BTreeMap<String, String>, String> {
    let mut map = BTreeMap::new();
    for (name, value) in list {
        if map.insert(name.clone(), value.clone()).is_some() {
            return Err(format!("--set {name} is given more than once"));
        }
    }
    Ok(map)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_setting_is_a_name_and_printable_text() {
        assert_eq!(
            parse_setting("seam=seam_1").unwrap(),
            ("seam".to_string(), "seam_1".to_string())
        );
        // The first '=' splits: a value may hold one.
        assert_eq!(parse_setting("x=a=b").unwrap().1, "a=b");
        for bad in [
            "seam",
            "=v",
            "1seam=v",
            "se-am=v",
            "seam=",
            "seam=a\nb",
            "seam=\u{e9}",
        ] {
            assert!(parse_setting(bad).is_err(), "{bad:?}");
        }
        let long = format!("v={}", "a".repeat(MAX_VALUE_CHARS + 1));
        assert!(parse_setting(&long).is_err());
        let name = format!("{}=v", "n".repeat(MAX_NAME_CHARS + 1));
        assert!(parse_setting(&name).is_err());
    }

    #[test]
    fn a_name_given_twice_is_refused() {
        let one = ("seam".to_string(), "a".to_string());
        let two = ("seam".to_string(), "b".to_string());
        let e = settings_map(&[one.clone(), two]).unwrap_err();
        assert!(e.contains("--set seam"), "{e}");
        assert_eq!(settings_map(&[one]).unwrap()["seam"], "a");
    }
}
