//! Leaf: what a message may echo of the input, bounded. A message quotes the offending source
//! line with a caret under the column, and sometimes a value (a name, a key, a scalar); the
//! input can make either as long as it likes (a 200,000-character line of `[`, a name of a
//! megabyte), so every echo goes through here:
//!
//! - [`line_window`]: the source line, control characters shown as one character each (so the
//!   caret stays under the right one); a line over [`MAX_LINE_CHARS`] becomes a window of
//!   [`WINDOW_CHARS`] around the column with `...` on each side that was cut.
//! - [`value`]: a value quoted in a message, at most [`MAX_VALUE_CHARS`] (its start and end
//!   with `...` between).
//! - [`message`]: the backstop for a whole message line, at most [`MAX_MESSAGE_CHARS`].
//! - [`number`]: a number of the input quoted in a message: as written when short, else in
//!   exponent form (`1e308`, not 309 digits; `1e-300`, not 302).
//!
//! With these, a rendered error stays under a few KB whatever the input. Columns are counted in
//! characters (as the YAML parser counts them), 1-based.

use std::borrow::Cow;
use unicode_width::UnicodeWidthStr;

/// Longest source line shown whole, in characters.
pub const MAX_LINE_CHARS: usize = 160;
/// Characters of a long line shown around the column (the ellipses come on top).
pub const WINDOW_CHARS: usize = 120;
/// Of [`WINDOW_CHARS`], how many come before the column (when the line has them).
const BEFORE_CHARS: usize = 50;
/// Longest value quoted whole in a message, in characters.
pub const MAX_VALUE_CHARS: usize = 64;
/// Longest message line, in characters (a backstop: messages quote values through [`value`]).
pub const MAX_MESSAGE_CHARS: usize = 1000;

const ELLIPSIS: &str = "...";

/// A source line as shown under a message, and where its caret goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Window {
    /// The line (or a window of it), one shown character per character of the source.
    pub text: String,
    /// The caret's 0-based character offset in `text`.
    pub caret: usize,
}

impl Window {
    /// The blanks before the caret: as wide on a terminal as the text before it (a CJK
    /// character takes two columns, a combining mark none), so the caret stands under its
    /// character whatever the script.
    pub fn caret_pad(&self) -> String {
        let end = self
            .text
            .char_indices()
            .nth(self.caret)
            .map_or(self.text.len(), |(i, _)| i);
        " ".repeat(UnicodeWidthStr::width(&self.text[..end]))
    }
}

/// One character as shown: a tab as a space, any other control character as U+FFFD, so each
/// takes one column and the terminal receives no control sequences from the input.
fn shown(c: char) -> char {
    match c {
        '\t' => ' ',
        c if c.is_control() || c == '\u{2028}' || c == '\u{2029}' => '\u{FFFD}',
        c => c,
    }
}

/// The line as shown under a message with its caret under `column` (1-based, characters; 0 for
/// unknown: the first character; past the end: just after the last). A line longer than
/// [`MAX_LINE_CHARS`] is cut to a window of [`WINDOW_CHARS`] around the column, with `...`
/// on each side that was cut.
pub fn line_window(line: &str, column: u64) -> Window {
    let chars: Vec<char> = line.chars().map(shown).collect();
    let n = chars.len();
    let col = (column.max(1) as usize - 1).min(n);
    if n <= MAX_LINE_CHARS {
        return Window {
            text: chars.into_iter().collect(),
            caret: col,
        };
    }
    // The window: BEFORE_CHARS before the column where the line has them, the rest after;
    // shifted left where the line ends first.
    let start = col.saturating_sub(BEFORE_CHARS).min(n - WINDOW_CHARS);
    let end = start + WINDOW_CHARS;
    let mut text = String::with_capacity(WINDOW_CHARS + 2 * ELLIPSIS.len());
    let mut caret = col - start;
    if start > 0 {
        text.push_str(ELLIPSIS);
        caret += ELLIPSIS.len();
    }
    text.extend(&chars[start..end]);
    if end < n {
        text.push_str(ELLIPSIS);
    }
    Window { text, caret }
}

/// The lines of `text`, with line breaks as YAML counts them (`\n`, `\r\n` and a lone `\r`),
/// without their breaks. Text ending in a break has an empty last line (where the parser's
/// end-of-input errors point).
pub fn lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text);
    std::iter::from_fn(move || {
        let t = rest?;
        match t.find(['\n', '\r']) {
            Some(i) => {
                let brk = if t[i..].starts_with("\r\n") { 2 } else { 1 };
                rest = Some(&t[i + brk..]);
                Some(&t[..i])
            }
            None => {
                rest = None;
                Some(t)
            }
        }
    })
}

/// Line `n` (1-based) of `text` ([`lines`]); `None` past the end.
pub fn nth_line(text: &str, n: u64) -> Option<&str> {
    lines(text).nth(usize::try_from(n.checked_sub(1)?).ok()?)
}

/// Cuts `s` to at most `max` characters: its start and end with `...` between. Control
/// characters are escaped first (a value is quoted on one line).
fn cut(s: &str, max: usize) -> Cow<'_, str> {
    let s: Cow<str> = if s.chars().any(|c| c.is_control()) {
        Cow::Owned(s.chars().flat_map(char::escape_debug).collect())
    } else {
        Cow::Borrowed(s)
    };
    let n = s.chars().count();
    if n <= max {
        return s;
    }
    let keep = max.saturating_sub(ELLIPSIS.len());
    let head = keep * 2 / 3;
    let tail = keep - head;
    let mut out: String = s.chars().take(head).collect();
    out.push_str(ELLIPSIS);
    out.extend(s.chars().skip(n - tail));
    Cow::Owned(out)
}

/// A value quoted in a message (a name, a key, a scalar): at most [`MAX_VALUE_CHARS`]
/// characters, control characters escaped.
pub fn value(s: &str) -> Cow<'_, str> {
    cut(s, MAX_VALUE_CHARS)
}

/// A whole message line, at most [`MAX_MESSAGE_CHARS`] characters, control characters escaped
/// (the backstop behind [`value`]).
pub fn message(s: &str) -> Cow<'_, str> {
    cut(s, MAX_MESSAGE_CHARS)
}

/// Longest number quoted as Rust writes it (`{}`); a longer one is written in exponent form.
const MAX_NUMBER_CHARS: usize = 24;

/// A number of the input quoted in a message: as Rust writes it (`30.125`, `-0.7`) when that is
/// at most [`MAX_NUMBER_CHARS`] characters, else in exponent form (`1e308`, `1e-300`), so a
/// huge or tiny value never floods a message.
pub fn number(v: f64) -> String {
    let plain = format!("{v}");
    if plain.chars().count() <= MAX_NUMBER_CHARS {
        plain
    } else {
        format!("{v:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_caret_pad_is_as_wide_as_the_text_before_it() {
        // Two wide characters (two columns each), a combining accent (none), then ASCII.
        let w = line_window("  - { name: 名前e\u{301}, x: ]", 19);
        assert_eq!(under(&w), 'x');
        assert_eq!(w.caret, 18);
        // 12 ASCII + 2 x 2 wide + 1 + 0 combining + 2 (", ") = 19 columns.
        assert_eq!(w.caret_pad(), " ".repeat(19));
        let w = line_window("  - { name: 名前, x: ]", 17);
        assert_eq!(under(&w), 'x');
        assert_eq!(w.caret_pad().len(), 18);
        // ASCII alone: one column a character.
        let w = line_window("abc", 3);
        assert_eq!(w.caret_pad(), "  ");
        // An emoji with its presentation selector takes two columns as a whole (one by its
        // characters); past the end of the line, the whole line's width.
        let w = line_window("a: \u{263A}\u{FE0F}x", 6);
        assert_eq!(under(&w), 'x');
        assert_eq!(w.caret_pad().len(), 5);
        assert_eq!(line_window("名前", 9).caret_pad().len(), 4);
    }

    #[test]
    fn a_number_is_quoted_short() {
        assert_eq!(number(30.125), "30.125");
        assert_eq!(number(-850.0), "-850");
        assert_eq!(number(1e308), "1e308");
        assert_eq!(number(1e-300), "1e-300");
        assert_eq!(number(-1.5e25), "-1.5e25");
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(number(f64::INFINITY), "inf");
    }

    /// The character under the caret.
    fn under(w: &Window) -> char {
        w.text.chars().nth(w.caret).unwrap_or(' ')
    }

    #[test]
    fn a_short_line_is_shown_whole_with_the_caret_under_its_column() {
        let w = line_window("  base: [0, 0, x]", 16);
        assert_eq!(w.text, "  base: [0, 0, x]");
        assert_eq!((w.caret, under(&w)), (15, 'x'));
        // Unknown column: the first character; past the end: just after the last.
        assert_eq!(line_window("ab", 0).caret, 0);
        assert_eq!(line_window("ab", 9).caret, 2);
    }

    #[test]
    fn tabs_and_control_characters_take_one_column_each() {
        let w = line_window("\tkey:\u{1b}[31m x", 12);
        assert_eq!(w.text, " key:\u{FFFD}[31m x");
        assert_eq!(under(&w), 'x');
    }

    #[test]
    fn a_long_line_is_a_window_around_the_column_with_ellipses_on_the_cut_sides() {
        // 200,000 characters, a marker at column 100,000.
        let mut line = "[".repeat(200_000);
        line.replace_range(99_999..100_000, "X");
        let w = line_window(&line, 100_000);
        assert!(w.text.starts_with("...") && w.text.ends_with("..."));
        assert_eq!(w.text.chars().count(), WINDOW_CHARS + 6);
        assert_eq!(under(&w), 'X');
        // Near the start: cut on the right only; near the end: on the left only.
        let w = line_window(&line, 3);
        assert!(!w.text.starts_with("...") && w.text.ends_with("..."));
        assert_eq!(w.caret, 2);
        let mut end = "a".repeat(500);
        end.push('Z');
        let w = line_window(&end, 501);
        assert!(w.text.starts_with("...") && !w.text.ends_with("..."));
        assert_eq!(under(&w), 'Z');
        assert_eq!(w.text.chars().count(), WINDOW_CHARS + 3);
        // Every column of a line just over the limit lands on its own character.
        let line: String = (0..MAX_LINE_CHARS + 7)
            .map(|i| char::from(b'a' + (i % 26) as u8))
            .collect();
        for col in 1..=line.len() {
            let w = line_window(&line, col as u64);
            assert_eq!(under(&w), line.as_bytes()[col - 1] as char, "column {col}");
        }
    }

    #[test]
    fn lines_break_where_yaml_breaks_them() {
        let t = "a\r\nb\rc\nd";
        let lines: Vec<_> = (1..=5).map(|n| nth_line(t, n)).collect();
        assert_eq!(lines, [Some("a"), Some("b"), Some("c"), Some("d"), None]);
        assert_eq!(nth_line("a\n", 2), Some(""));
        assert_eq!(nth_line("a\n", 3), None);
        assert_eq!(nth_line("", 1), Some(""));
        assert_eq!(nth_line("x", 0), None);
    }

    #[test]
    fn values_and_messages_are_cut_in_the_middle() {
        assert_eq!(value("P1"), "P1");
        let long = format!("{}END", "x".repeat(100_000));
        let v = value(&long);
        assert_eq!(v.chars().count(), MAX_VALUE_CHARS);
        assert!(v.contains("...") && v.ends_with("END"));
        assert_eq!(message(&long).chars().count(), MAX_MESSAGE_CHARS);
        assert_eq!(value("a\nb"), "a\\nb");
    }
}
