//! Warnings as printed: one line per kind. Warnings that differ only in the name they quote
//! (the first `'...'`: forty speeds that are not predefined, ten points whose zone is written
//! `fine`) are one line, the first of them with the count and the next few names, so that many
//! warnings never bury the one error or the summary line.

use crate::excerpt;

/// The names listed after the first of a kind.
pub const NAMES_SHOWN: usize = 3;

/// The first quoted name of a warning and the warning with it taken out (its kind).
fn kind_of(line: &str) -> (Option<&str>, String) {
    let Some(open) = line.find('\'') else {
        return (None, line.to_string());
    };
    let rest = &line[open + 1..];
    let Some(close) = rest.find('\'') else {
        return (None, line.to_string());
    };
    let name = &rest[..close];
    let kind = format!("{}''{}", &line[..open], &rest[close + 1..]);
    (Some(name), kind)
}

/// The lines to print for `warnings`, in the order each kind first appears.
pub fn grouped(warnings: &[String]) -> Vec<String> {
    // (kind, the first line of the kind, the names of the others)
    let mut kinds: Vec<(String, &str, Vec<&str>)> = Vec::new();
    for w in warnings {
        let (name, kind) = kind_of(w);
        match (name, kinds.iter_mut().find(|(k, _, _)| *k == kind)) {
            (Some(name), Some((_, _, others))) => others.push(name),
            // The same warning twice without a name says nothing new.
            (None, Some(_)) => {}
            (_, None) => kinds.push((kind, w, Vec::new())),
        }
    }
    kinds
        .into_iter()
        .map(|(_, first, others)| {
            if others.is_empty() {
                return excerpt::message(first).into_owned();
            }
            let shown: Vec<String> = others
                .iter()
                .take(NAMES_SHOWN)
                .map(|n| format!("'{}'", excerpt::value(n)))
                .collect();
            let more = if others.len() > NAMES_SHOWN {
                ", ..."
            } else {
                ""
            };
            excerpt::message(&format!(
                "{first} (and {} more like it: {}{more})",
                others.len(),
                shown.join(", ")
            ))
            .into_owned()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn warnings_of_one_kind_are_one_line_with_a_count_and_the_first_names() {
        let mut w: Vec<String> = (0..40)
            .map(|i| format!("warning: speed 'vs{i}' is not a predefined speeddata: ..."))
            .collect();
        w.insert(1, "warning: the robot has no controller file".into());
        w.push("warning: point 'P1' zone 'z50' is written fine".into());
        w.push("warning: point 'P2' zone 'z50' is written fine".into());
        let lines = grouped(&w);
        assert_eq!(
            lines,
            [
                "warning: speed 'vs0' is not a predefined speeddata: ... (and 39 more like it: 'vs1', 'vs2', 'vs3', ...)",
                "warning: the robot has no controller file",
                "warning: point 'P1' zone 'z50' is written fine (and 1 more like it: 'P2')",
            ]
        );
        // One of a kind, and the same line twice, stay one line as written.
        let one = vec!["warning: a 'x' b".to_string()];
        assert_eq!(grouped(&one), one);
        let twice = vec!["warning: plain".to_string(), "warning: plain".to_string()];
        assert_eq!(grouped(&twice), ["warning: plain"]);
    }
}
