//! The YAML reader's refusals, said for a cell file (long: each common slip is read from the
//! text in its own way): where the fault is, one line on what is wrong, and a help line for the
//! common slips (wrong indentation, a tab, an unclosed `[` or `{`, a key given twice, a missing
//! `:` or the space after it, a misspelled key, a word where a number belongs).
//!
//! The reader (serde-saphyr over the granit parser) reports a structured error with a location;
//! where that location is not where the fault is, this module moves it there from the text:
//!
//! - an unclosed `[` or `{` is noticed where the parser gives up (often the next key, lines
//!   later); the text before that point is scanned for flow brackets ([`open_brackets`]) and the
//!   message points at the one left open;
//! - a tab is noticed where the scalar before it started: the message points at the tab;
//! - a missing `:` is noticed at the next key: the message points at the line that lacks it.
//!
//! The typed reading of a cell stops at the first problem it meets, which for a malformed file is
//! often a consequence ("missing field `base`" for a mis-indented `base:`). So a refusal that is
//! not the parser's own is checked against a plain syntax pass over the whole text first: a
//! syntax error wins. Every echo of the input is bounded ([`crate::excerpt`]).

use super::{CellError, Loc};
use crate::excerpt;
use serde_saphyr::budget::BudgetBreach;
use serde_saphyr::granit_parser::ErrorKind;
use serde_saphyr::{DefaultMessageFormatter, Error, ExternalMessageSource, MessageFormatter};

/// The cell file's refusal by the YAML reader, as the cell's error (module docs).
pub(super) fn refusal(text: &str, typed: &Error) -> CellError {
    let plain;
    let e = if scan_kind(typed).is_some() {
        typed
    } else {
        match serde_saphyr::from_str::<serde::de::IgnoredAny>(text) {
            Err(e) if scan_kind(&e).is_some() => {
                plain = e;
                &plain
            }
            _ => typed,
        }
    };
    let said = describe(original(e), &Text::of(text));
    CellError::Syntax {
        loc: said.loc,
        message: excerpt::message(&said.message).into_owned(),
        help: said.help.map(|h| excerpt::message(&h).into_owned()),
    }
}

/// Text that is not UTF-8 is refused at its first bad byte (line and column of the valid text
/// before it).
pub(super) fn not_utf8(bytes: &[u8], e: &std::str::Utf8Error) -> CellError {
    let valid = &bytes[..e.valid_up_to()];
    let valid = std::str::from_utf8(valid).unwrap_or_default();
    let loc = end_of(valid);
    let byte = bytes.get(e.valid_up_to()).copied().unwrap_or_default();
    CellError::Syntax {
        loc,
        message: format!("the cell file is not UTF-8 text: byte 0x{byte:02X} at line {}, column {} cannot be read", loc.line, loc.column),
        help: Some("save the cell file as UTF-8 (plain text)".into()),
    }
}

/// The line and column just after `text`.
fn end_of(text: &str) -> Loc {
    let mut loc = Loc { line: 1, column: 1 };
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '\n' || (c == '\r' && chars.peek() != Some(&'\n')) {
            loc = Loc {
                line: loc.line + 1,
                column: 1,
            };
        } else if c != '\r' {
            loc.column += 1;
        }
    }
    loc
}

/// A refusal as said to the user.
struct Said {
    loc: Loc,
    message: String,
    help: Option<String>,
}

impl Said {
    fn new(loc: Loc, message: impl Into<String>, help: Option<String>) -> Said {
        Said {
            loc,
            message: message.into(),
            help,
        }
    }
}

/// The error under the reader's wrappers (snippet, alias).
fn original(mut e: &Error) -> &Error {
    loop {
        match e {
            Error::WithSnippet { error, .. } | Error::AliasError { error, .. } => e = error,
            _ => return e,
        }
    }
}

/// The parser's own error kind, if the error is the parser's.
fn scan_kind(e: &Error) -> Option<&ErrorKind> {
    match original(e) {
        Error::ExternalMessage { source, .. } => match &**source {
            ExternalMessageSource::Parser(scan) => Some(scan.kind()),
            _ => None,
        },
        _ => None,
    }
}

/// The reader's own wording, control characters escaped and bounded.
fn reader_text(e: &Error) -> String {
    excerpt::message(&DefaultMessageFormatter.format_message(e)).into_owned()
}

/// The cell text by lines (1-based, as the reader counts them).
struct Text<'a> {
    whole: &'a str,
    lines: Vec<&'a str>,
}

impl<'a> Text<'a> {
    fn of(whole: &'a str) -> Text<'a> {
        Text {
            whole,
            lines: excerpt::lines(whole).collect(),
        }
    }

    /// Line `n` (empty past the end).
    fn line(&self, n: u64) -> &'a str {
        let i = n.checked_sub(1).and_then(|i| usize::try_from(i).ok());
        i.and_then(|i| self.lines.get(i)).copied().unwrap_or("")
    }

    /// The nearest line above `n` with content (not blank, not only a comment).
    fn content_above(&self, n: u64) -> Option<(u64, &'a str)> {
        (1..n)
            .rev()
            .map(|k| (k, self.line(k)))
            .find(|(_, l)| is_content(l))
    }

    /// The character at `loc`.
    fn char_at(&self, loc: Loc) -> Option<char> {
        self.line(loc.line)
            .chars()
            .nth(loc.column.checked_sub(1)? as usize)
    }
}

fn describe(e: &Error, text: &Text) -> Said {
    let loc = e.location().map(Loc::from).unwrap_or_default();
    let said = |message: String, help: Option<String>| Said::new(loc, message, help);
    match e {
        Error::ExternalMessage { .. } => match scan_kind(e) {
            Some(kind) => scan(kind, loc, text, reader_text(e)),
            None => said(reader_text(e), None),
        },
        Error::Eof { .. } if text.lines.iter().all(|l| !is_content(l)) => said(
            "the cell file is empty".into(),
            Some(KEYS_HELP.into()),
        ),
        Error::Unexpected {
            expected: "mapping start",
            ..
        } if loc.line <= 1 => said(
            "a cell file is a mapping of keys (`module: ...`, `robot: ...`, `points: ...`)".into(),
            Some(KEYS_HELP.into()),
        ),
        Error::Unexpected {
            expected: "sequence start",
            ..
        } => said(
            format!("expected a list here, found {}", found_at(text, loc)),
            Some("a list is `[a, b, c]` on one line, or one `- item` per line indented under its key".into()),
        ),
        Error::Unexpected {
            expected: "mapping start",
            ..
        } => said(
            format!("expected a mapping here, found {}", found_at(text, loc)),
            Some("a mapping is `key: value` lines indented under its key, or `{ key: value, ... }` on one line".into()),
        ),
        Error::Unexpected {
            expected: "string scalar",
            ..
        } => said(
            format!("expected a single value here, found {}", found_at(text, loc)),
            Some("a number or a name stands here, not a list or a mapping; is a bracket misplaced?".into()),
        ),
        Error::NullIntoString { .. } => said(
            "expected a text value here, found nothing".into(),
            Some("write the value after the key's `: ` (a name such as `P1`); `~` and `null` mean no value".into()),
        ),
        Error::DuplicateMappingKey { key, .. } => duplicate_key(key.as_deref(), loc, text),
        Error::SerdeUnknownField {
            field, expected, ..
        } => {
            let help = suggestion(field, expected)
                .map(|k| format!("did you mean `{k}`?"))
                .or_else(|| Some("remove the key, or check its spelling and indentation (docs/cell.md lists every key)".into()));
            said(
                format!(
                    "unknown field `{}`, expected one of {}",
                    excerpt::value(field),
                    expected.join(", ")
                ),
                help,
            )
        }
        Error::SerdeMissingField { field, .. } => said(
            format!("missing field `{field}`"),
            Some(format!("add `{field}:` to this mapping; if it is there, check that it is indented like the other keys of the mapping (spaces only)")),
        ),
        Error::SerdeInvalidType {
            unexpected,
            expected,
            ..
        } => said(
            format!(
                "invalid type: {}, expected {}",
                excerpt::value(unexpected),
                excerpt::value(expected)
            ),
            Some(FORM_HELP.into()),
        ),
        Error::SerdeInvalidValue {
            unexpected,
            expected,
            ..
        } => said(
            format!(
                "invalid value: {}, expected {}",
                excerpt::value(unexpected),
                excerpt::value(expected)
            ),
            Some(FORM_HELP.into()),
        ),
        Error::InvalidScalar { ty, .. } => match scalar_at(text, loc) {
            Some(found) if ty.contains("float") || ty.contains("int") => said(
                format!("expected a number, found `{}`", excerpt::value(found)),
                Some("write the number alone, without a unit or quotes (lengths in mm, angles in degrees, the mass in kg), e.g. `2.5`".into()),
            ),
            Some(found) if ty.contains("bool") => said(
                format!("expected true or false, found `{}`", excerpt::value(found)),
                Some("a switch such as planner.shortcut is `true` or `false`".into()),
            ),
            _ => said(reader_text(e), None),
        },
        Error::Budget {
            breach:
                BudgetBreach::AliasAnchorRatio { aliases, .. } | BudgetBreach::Aliases { aliases },
            ..
        } => Said::new(
            first_alias(text).unwrap_or(loc),
            format!("the cell file repeats its anchors too often ({aliases} aliases `*name`)"),
            Some("write the repeated values out (or give them anchors of their own); the YAML reader bounds how far aliases may expand a file".into()),
        ),
        Error::Budget { breach, .. } => {
            let (what, limit) = budget_breach(breach);
            said(
                format!("the cell file passes the YAML reader's budget: {what}"),
                Some(format!("{limit}; a cell of the largest size a run takes (docs/limits.md: 2 000 points, 5 000 obstacles, 64 tool shapes) stays well within it; split a larger job into several cells")),
            )
        }
        _ => said(reader_text(e), None),
    }
}

/// What a breach of the YAML reader's budget counts, and the limit, in words.
fn budget_breach(breach: &BudgetBreach) -> (String, String) {
    let b = serde_saphyr::Budget::default();
    match breach {
        BudgetBreach::Nodes { nodes } => (
            format!("more than {} YAML nodes (values, lists and mappings; {nodes} read when it stopped)", b.max_nodes),
            format!("a cell file holds at most {} YAML nodes", b.max_nodes),
        ),
        BudgetBreach::Events { events } => (
            format!("more than {} YAML events ({events} read when it stopped)", b.max_events),
            format!("a cell file holds at most {} YAML events", b.max_events),
        ),
        BudgetBreach::Depth { depth } => (
            format!("lists and mappings nested {depth} deep"),
            format!("a cell file nests at most {} levels", b.max_depth),
        ),
        BudgetBreach::ScalarBytes { total_scalar_bytes } => (
            format!("{total_scalar_bytes} bytes of values"),
            format!("a cell file's values hold at most {} bytes", b.max_total_scalar_bytes),
        ),
        BudgetBreach::Documents { documents } => (
            format!("{documents} YAML documents"),
            "a cell file is one YAML document".into(),
        ),
        BudgetBreach::Anchors { anchors } => (
            format!("{anchors} anchors"),
            format!("a cell file defines at most {} anchors", b.max_anchors),
        ),
        BudgetBreach::MergeKeys { merge_keys } => (
            format!("{merge_keys} merge keys"),
            format!("a cell file has at most {} merge keys", b.max_merge_keys),
        ),
        other => (
            excerpt::value(&format!("{other:?}")).into_owned(),
            "the YAML reader bounds the size of a file it reads".into(),
        ),
    }
}

const FORM_HELP: &str = "docs/cell.md and docs/guide.md show the form of every key";

const KEYS_HELP: &str = "a cell gives `module: Name`, `robot:` (with `urdf:` and `base:`) and `points:` (at least two), and may give `obstacles:`, `planner:`, `motion:`, `tool:`, `wobj:` or `wobjs:`, and `loads:` (docs/cell.md)";

/// The parser's refusals (module docs).
fn scan(kind: &ErrorKind, loc: Loc, text: &Text, reader: String) -> Said {
    let said = |message: String, help: Option<String>| Said::new(loc, message, help);
    match kind {
        ErrorKind::UnclosedFlowCollection { open } => said(
            format!("this '{open}' is never closed"),
            Some(format!(
                "close the {} with '{}'",
                collection(*open),
                closing(*open)
            )),
        ),
        ErrorKind::MismatchedFlowCollectionEnd { open, close } => said(
            format!("this '{open}' is closed by '{close}'"),
            Some(format!(
                "a list `[ ... ]` is closed by ']', a mapping `{{ ... }}` by '}}'; close this {} with '{}'",
                collection(*open),
                closing(*open)
            )),
        ),
        ErrorKind::MisplacedFlowCollectionEnd => {
            let c = text.char_at(loc).unwrap_or(']');
            said(
                format!("this '{c}' closes nothing"),
                Some("remove it, or open the list `[` or mapping `{` it should close".into()),
            )
        }
        ErrorKind::ExpectedFlowMappingSeparator
        | ErrorKind::ExpectedFlowSequenceSeparator
        | ErrorKind::UnexpectedEofFlowMapping
        | ErrorKind::UnexpectedEofFlowSequence
        | ErrorKind::UnexpectedEofImplicitFlowMapping
        | ErrorKind::BlockEntryInFlowCollection => flow(kind, loc, text, reader),
        ErrorKind::MappingValueNotAllowed => indentation(loc, text, true)
            .unwrap_or_else(|| said("a `key:` is not allowed here".into(), Some(INDENT_HELP.into()))),
        ErrorKind::ExpectedBlockMappingKey => indentation(loc, text, false)
            .unwrap_or_else(|| said("expected a `key:` here".into(), Some(INDENT_HELP.into()))),
        ErrorKind::SimpleKeyExpected => missing_colon(loc, text),
        ErrorKind::TabInIndentation
        | ErrorKind::TabInPlainScalar
        | ErrorKind::TabNotAllowed
        | ErrorKind::TabInBlockIndentation
        | ErrorKind::TabAtBlockScalarStart => Said::new(
            tab_at_or_after(text, loc).unwrap_or(loc),
            "a tab character in the indentation",
            Some("YAML indents with spaces only; replace the tab with spaces".into()),
        ),
        ErrorKind::RecursionLimitExceeded => said(
            "lists and mappings are nested too deeply".into(),
            Some("a cell nests a few levels at most, e.g. `points:` / `- { name: A, joints: [0, 0, 0] }`; is a ']' or '}' missing?".into()),
        ),
        ErrorKind::UnclosedQuotedScalar => said(
            "this quote is never closed".into(),
            Some("end the text with the quote it starts with (' or \")".into()),
        ),
        _ => said(reader, None),
    }
}

const INDENT_HELP: &str =
    "keys of one mapping start in the same column; indent with spaces only, and put a nested mapping under a key that has no value on its own line";

fn collection(open: char) -> &'static str {
    if open == '{' {
        "mapping"
    } else {
        "list"
    }
}

fn closing(open: char) -> char {
    if open == '{' {
        '}'
    } else {
        ']'
    }
}

/// A flow collection's separator or end is missing: an unclosed bracket on an earlier line (the
/// parser noticed at the next key or entry) points at that bracket; on the same line, a comma is
/// probably missing.
fn flow(kind: &ErrorKind, loc: Loc, text: &Text, reader: String) -> Said {
    let open = open_brackets(text.whole, loc).pop();
    match open {
        Some(b) if b.loc.line < loc.line || matches!(kind, ErrorKind::UnexpectedEofFlowMapping | ErrorKind::UnexpectedEofFlowSequence) => {
            Said::new(
                b.loc,
                format!("this '{}' is never closed", b.open),
                Some(format!(
                    "close the {} with '{}' (the reader was still inside it at line {}); a {} that goes on over several lines must indent them deeper than its key",
                    collection(b.open),
                    closing(b.open),
                    loc.line,
                    collection(b.open)
                )),
            )
        }
        Some(b) => {
            let word = word_before_colon(text, loc);
            let missing = match &word {
                Some(w) => format!("is a ',' missing before `{}`? ", excerpt::value(w)),
                None => String::new(),
            };
            Said::new(
                loc,
                format!("expected ',' or '{}' in this {}", closing(b.open), collection(b.open)),
                Some(format!(
                    "{missing}entries of a {} are separated by commas: {}",
                    collection(b.open),
                    if b.open == '{' {
                        "`{ name: P1, joints: [0, 0, 0] }`"
                    } else {
                        "`[0, 0, 0]`"
                    }
                )),
            )
        }
        None => Said::new(loc, reader, None),
    }
}

/// The column (0-based, characters) where a line's content starts, past any `- ` entry
/// markers: where its key is.
fn key_column(l: &str) -> usize {
    let mut col = 0;
    let mut rest = l;
    loop {
        let trimmed = rest.trim_start_matches(' ');
        col += rest.len() - trimmed.len();
        if let Some(after) = trimmed.strip_prefix("- ") {
            col += 2;
            rest = after;
        } else {
            return col;
        }
    }
}

fn indent(l: &str) -> usize {
    l.len() - l.trim_start_matches(' ').len()
}

/// The key a line gives (the text before its first `: `), if it gives one.
fn key_of(l: &str) -> Option<&str> {
    let content = &l[key_column(l).min(l.len())..];
    let end = content
        .find(": ")
        .or_else(|| content.strip_suffix(':').map(str::len))?;
    let key = content[..end].trim();
    (!key.is_empty() && !key.starts_with(['{', '[', '#', '"', '\''])).then_some(key)
}

fn is_content(l: &str) -> bool {
    let t = l.trim();
    !t.is_empty() && !t.starts_with('#')
}

fn spaces(n: usize) -> String {
    format!("{n} space{}", if n == 1 { "" } else { "s" })
}

/// A key where none may stand, or none where one must: a missing `:` on the line above, or a
/// key indented unlike its neighbours. `value_here`: the parser refused a `key:` at `loc`
/// (else it wanted one). `None` when the lines do not show which.
fn indentation(loc: Loc, text: &Text, value_here: bool) -> Option<Said> {
    let here = text.line(loc.line);
    let (above_n, above) = text.content_above(loc.line)?;
    let col = key_column(here);
    let key_loc = Loc {
        line: loc.line,
        column: col as u64 + 1,
    };
    let name = key_of(here).map(|k| format!("`{}`", excerpt::value(k)));
    let name = name.unwrap_or_else(|| "this line".into());
    if value_here && key_of(above).is_none() && !above.trim_end().ends_with([',', '[', '{']) {
        // `module Name` then `robot:`: the line above has no `:`, so the parser read it as the
        // start of a text running on into this line.
        let above_col = key_column(above);
        let word_end = above[above_col..]
            .find(' ')
            .map_or(above.trim_end().len(), |i| above_col + i)
            .max(above_col);
        let word = &above[above_col..word_end];
        return Some(Said::new(
            Loc {
                line: above_n,
                column: word_end as u64 + 1,
            },
            format!("expected ':' after `{}`", excerpt::value(word)),
            Some(format!(
                "every entry of a mapping is `key: value` (a ':' and a space); the reader took line {above_n} as a text running on into line {}",
                loc.line
            )),
        ));
    }
    let above_col = key_column(above);
    let above_key = key_of(above)?;
    if col == above_col {
        return None;
    }
    let ends_with_key = above.trim_end().ends_with(':');
    if col > above_col && ends_with_key {
        // A nested mapping under a key: the parser had another complaint.
        return None;
    }
    let (more, less) = ("more", "less");
    Some(Said::new(
        key_loc,
        format!(
            "{name} is indented {} than `{}` on line {above_n} ({} against {above_col})",
            if col > above_col { more } else { less },
            excerpt::value(above_key),
            spaces(col),
        ),
        Some(INDENT_HELP.into()),
    ))
}

/// `simple key expected ':'`: a key without its `:`, or a `:` without the space after it.
fn missing_colon(loc: Loc, text: &Text) -> Said {
    let here = text.line(loc.line);
    let col = key_column(here);
    let content = &here[col.min(here.len())..];
    if let Some(i) = content.find(':').filter(|&i| {
        content[i + 1..]
            .chars()
            .next()
            .is_some_and(|c| !c.is_whitespace())
    }) {
        let key = &content[..i];
        return Said::new(
            Loc {
                line: loc.line,
                column: (col + i) as u64 + 2,
            },
            format!("expected a space after `{}:`", excerpt::value(key.trim())),
            Some("every entry of a mapping is `key: value`, with a space after the ':'".into()),
        );
    }
    let word = content.split([' ', '#']).next().unwrap_or_default();
    Said::new(
        Loc {
            line: loc.line,
            column: (col + word.len()) as u64 + 1,
        },
        format!("expected ':' after `{}`", excerpt::value(word)),
        Some("every entry of a mapping is `key: value` (a ':' and a space)".into()),
    )
}

/// The first tab in the indentation of a line at or after `loc`'s, else the first tab after
/// `loc` on its line.
fn tab_at_or_after(text: &Text, loc: Loc) -> Option<Loc> {
    let first = loc.line.max(1);
    for (n, l) in (first..).zip(text.lines.iter().skip(first as usize - 1)) {
        let lead = l.len() - l.trim_start_matches([' ', '\t']).len();
        if let Some(i) = l[..lead].find('\t') {
            return Some(Loc {
                line: n,
                column: l[..i].chars().count() as u64 + 1,
            });
        }
        if n == loc.line {
            let from = l
                .char_indices()
                .nth(loc.column.saturating_sub(1) as usize)
                .map_or(l.len(), |(i, _)| i);
            if let Some(i) = l[from..].find('\t') {
                return Some(Loc {
                    line: n,
                    column: l[..from + i].chars().count() as u64 + 1,
                });
            }
        }
    }
    None
}

/// A key given twice: the second, and where the first is (a block mapping: the same key at the
/// same column above, within the mapping).
fn duplicate_key(key: Option<&str>, loc: Loc, text: &Text) -> Said {
    let Some(key) = key else {
        return Said::new(
            loc,
            "a key appears twice in this mapping",
            Some("give each key once".into()),
        );
    };
    let col = loc.column.saturating_sub(1) as usize;
    let here = text.line(loc.line);
    let same_line = here
        .char_indices()
        .nth(col)
        .and_then(|(i, _)| {
            let before = &here[..i];
            before
                .match_indices(&format!("{key}:"))
                .find(|(j, _)| before[..*j].ends_with([' ', '{', ',']))
                .map(|(j, _)| before[..j].chars().count() + 1)
        })
        .map(|c| format!(" (first at column {c})"));
    let mut first = same_line;
    if first.is_none() {
        for n in (1..loc.line).rev() {
            let l = text.line(n);
            if !is_content(l) {
                continue;
            }
            if key_column(l) == col && key_of(l) == Some(key) {
                first = Some(format!(" (first at line {n})"));
                break;
            }
            if indent(l) < col {
                // The start of this mapping's list entry, or its parent.
                break;
            }
        }
    }
    Said::new(
        loc,
        format!(
            "the key `{}` appears twice in this mapping{}",
            excerpt::value(key),
            first.unwrap_or_default()
        ),
        Some("give each key once: remove one of them".into()),
    )
}

/// The key of `expected` closest to `field` (a misspelling: edit distance at most 2, or the same
/// but for case).
fn suggestion<'a>(field: &str, expected: &[&'a str]) -> Option<&'a str> {
    if field.chars().count() > 40 {
        return None;
    }
    let f = field.to_ascii_lowercase();
    expected
        .iter()
        .map(|k| (edit_distance(&f, k), *k))
        .filter(|(d, k)| *d <= 2 && *d < k.len())
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            cur[j + 1] = (prev[j] + usize::from(ca != cb))
                .min(prev[j + 1] + 1)
                .min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The plain scalar starting at `loc` (up to a flow indicator, a comment or the line's end).
fn scalar_at<'a>(text: &Text<'a>, loc: Loc) -> Option<&'a str> {
    let l = text.line(loc.line);
    let start = l.char_indices().nth(loc.column.checked_sub(1)? as usize)?.0;
    let rest = &l[start..];
    let end = rest.find([',', ']', '}', '#']).unwrap_or(rest.len());
    let s = rest[..end].trim();
    (!s.is_empty()).then_some(s)
}

/// Where the first alias (`*name`) of the text is, if the lines show one: a `*` where a node
/// starts (after `: `, `- `, `[`, `{` or `,`), then a name character.
fn first_alias(text: &Text) -> Option<Loc> {
    text.lines.iter().enumerate().find_map(|(i, l)| {
        let chars: Vec<char> = l.chars().collect();
        let content_end = chars
            .iter()
            .enumerate()
            .find(|(k, c)| **c == '#' && (*k == 0 || chars[k - 1] == ' '))
            .map_or(chars.len(), |(k, _)| k);
        (0..content_end).find_map(|k| {
            let before = chars[..k].iter().rev().find(|c| **c != ' ');
            let starts_node = matches!(before, None | Some(':' | '-' | '[' | '{' | ','));
            let named = chars
                .get(k + 1)
                .is_some_and(|c| c.is_alphanumeric() || *c == '_');
            (chars[k] == '*' && starts_node && named).then_some(Loc {
                line: i as u64 + 1,
                column: k as u64 + 1,
            })
        })
    })
}

/// What stands at `loc` where the reader wanted another kind of node, for a message: nothing
/// (a key without a value: the reader points at its `:`), a list, a mapping, or the scalar.
fn found_at(text: &Text, loc: Loc) -> String {
    let l = text.line(loc.line);
    let start = loc
        .column
        .checked_sub(1)
        .and_then(|c| l.char_indices().nth(c as usize))
        .map_or(l.len(), |(i, _)| i);
    let rest = l[start..].strip_prefix(':').unwrap_or(&l[start..]).trim();
    if rest.is_empty() || rest.starts_with('#') || rest == "~" || rest == "null" {
        "nothing (no value)".into()
    } else if rest.starts_with('[') || rest == "-" || rest.starts_with("- ") {
        "a list".into()
    } else if rest.starts_with('{') {
        "a mapping".into()
    } else {
        match scalar_at(text, loc) {
            Some(s) => format!("`{}`", excerpt::value(s)),
            None => "another kind of value".into(),
        }
    }
}

/// The word before the `:` at `loc` (`joints` in `{ name: P1 joints: [...] }`).
fn word_before_colon(text: &Text, loc: Loc) -> Option<String> {
    let l = text.line(loc.line);
    let chars: Vec<char> = l.chars().collect();
    let mut end = (loc.column.checked_sub(1)? as usize).min(chars.len());
    if chars.get(end) != Some(&':') {
        return None;
    }
    while end > 0 && chars[end - 1] == ' ' {
        end -= 1;
    }
    let start = chars[..end]
        .iter()
        .rposition(|c| c.is_whitespace() || matches!(c, ',' | '{' | '['))
        .map_or(0, |i| i + 1);
    (start < end).then(|| chars[start..end].iter().collect())
}

/// A flow bracket left open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Open {
    open: char,
    loc: Loc,
}

/// The flow brackets (`[`, `{`) still open when the text reaches `until`, outermost first. A
/// light scan, not a parser: quotes and comments are skipped, and outside brackets a `[` or `{`
/// counts only where a value starts (after `: `, `- `, or at the start of a line), so that
/// `a[1]` in a plain text does not.
fn open_brackets(text: &str, until: Loc) -> Vec<Open> {
    let mut stack: Vec<Open> = Vec::new();
    let (mut line, mut column) = (1u64, 0u64);
    // The last character that is not white space (in block context: on this line).
    let mut prev: Option<char> = None;
    let mut quote: Option<char> = None;
    let mut comment = false;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '\n' || c == '\r' {
            if c == '\r' && chars.peek() == Some(&'\n') {
                chars.next();
            }
            line += 1;
            column = 0;
            comment = false;
            if stack.is_empty() {
                prev = None;
            }
            if line > until.line {
                break;
            }
            continue;
        }
        column += 1;
        if (line, column) >= (until.line, until.column) {
            break;
        }
        if comment {
            continue;
        }
        if let Some(q) = quote {
            match c {
                '\\' if q == '"' => {
                    chars.next();
                    column += 1;
                }
                c if c == q => {
                    if q == '\'' && chars.peek() == Some(&'\'') {
                        chars.next();
                        column += 1;
                    } else {
                        quote = None;
                        prev = Some(c);
                    }
                }
                _ => {}
            }
            continue;
        }
        let value_starts = matches!(prev, None | Some(':' | '-' | ',' | '[' | '{' | '?'));
        match c {
            ' ' | '\t' => continue,
            '#' => {
                comment = true;
                continue;
            }
            '[' | '{' if value_starts || !stack.is_empty() => stack.push(Open {
                open: c,
                loc: Loc { line, column },
            }),
            ']' | '}' => {
                stack.pop();
            }
            '\'' | '"' if value_starts => quote = Some(c),
            _ => {}
        }
        prev = Some(c);
    }
    stack
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(line: u64, column: u64) -> Loc {
        Loc { line, column }
    }

    #[test]
    fn open_brackets_skip_quotes_comments_and_plain_text() {
        let t = "a: [1, 2]\nb: { c: '[', d: \"}\" } # {\ne: x[1]\nf: [1, {g: 2\nh: 1\n";
        let open = open_brackets(t, at(5, 1));
        assert_eq!(
            open,
            vec![
                Open {
                    open: '[',
                    loc: at(4, 4)
                },
                Open {
                    open: '{',
                    loc: at(4, 8)
                }
            ]
        );
        assert!(open_brackets(t, at(4, 1)).is_empty());
    }

    #[test]
    fn misspelled_keys_get_a_suggestion() {
        let keys = [
            "module",
            "robot",
            "obstacles",
            "points",
            "planner",
            "motion",
        ];
        assert_eq!(suggestion("obstacle", &keys), Some("obstacles"));
        assert_eq!(suggestion("Points", &keys), Some("points"));
        assert_eq!(suggestion("pionts", &keys), Some("points"));
        assert_eq!(suggestion("colour", &keys), None);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }

    #[test]
    fn keys_and_columns_of_lines() {
        assert_eq!(key_column("  - - name: x"), 6);
        assert_eq!(key_of("  - name: table"), Some("name"));
        assert_eq!(key_of("robot:"), Some("robot"));
        assert_eq!(key_of("  - { name: A }"), None);
        assert_eq!(key_of("module ErrCase"), None);
        assert_eq!(end_of("ab\ncd"), at(2, 3));
        assert_eq!(end_of("a\r\nb\rc"), at(3, 2));
    }

    #[test]
    fn a_line_above_of_only_a_dash_is_no_key() {
        // Found by the fuzz target (tests/fuzz/dash_line_above_a_key*.yaml): `- ` above a
        // refused `key:` sliced past its end.
        let text = Text::of("- \nkey: 1\n");
        let said = indentation(Loc { line: 2, column: 4 }, &text, true).expect("said");
        assert_eq!(said.loc, Loc { line: 1, column: 3 }, "{}", said.message);
    }

    #[test]
    fn a_tab_is_found_where_it_is() {
        let t = "a: 1\nb: x\n\tc: 2\n";
        assert_eq!(tab_at_or_after(&Text::of(t), at(2, 4)), Some(at(3, 1)));
        let t = Text::of("a: [1,\t2]");
        assert_eq!(tab_at_or_after(&t, at(1, 2)), Some(at(1, 7)));
    }
}
