//! The size of a user template's tags, bounded before minijinja parses it: a tag (`{{ ... }}`,
//! `{% ... %}`) of a chain of a million operators (`{{ 1 + 1 + ... }}`) parses into an
//! expression nested a million deep, which minijinja compiles, runs and drops by recursion
//! until the stack overflows (an abort, not an error). Nesting by brackets and blocks is bounded
//! by minijinja's parser; a chain is not, so the tags' length is: [`MAX_TAG_CHARS`] characters
//! hold at most 8 192 operators (a chain of unary minus), well within the template's own
//! stack (`TEMPLATE_STACK_BYTES`: 16 000 fit in 8 MiB).

/// The most characters between a tag's delimiters.
pub const MAX_TAG_CHARS: usize = 8_192;

/// A tag longer than [`MAX_TAG_CHARS`]: its line and column (1-based, in characters) and length.
#[derive(Debug, PartialEq)]
pub struct LongTag {
    pub line: usize,
    pub column: usize,
    pub chars: usize,
}

/// The first tag of `source` longer than [`MAX_TAG_CHARS`], if any. Comments (`{# ... #}`)
/// and `{% raw %}` blocks are text; string literals inside a tag may hold its closing
/// delimiter.
pub fn long_tag(source: &str) -> Option<LongTag> {
    let chars: Vec<char> = source.chars().collect();
    let (mut i, mut line, mut column) = (0usize, 1usize, 1usize);
    // Moves to character `to`, counting lines.
    let advance = |i: &mut usize, line: &mut usize, column: &mut usize, to: usize| {
        let to = to.min(chars.len());
        for &c in &chars[*i..to] {
            if c == '\n' {
                *line += 1;
                *column = 1;
            } else {
                *column += 1;
            }
        }
        *i = to;
    };
    let starts = |i: usize, s: &str| {
        s.chars()
            .enumerate()
            .all(|(k, c)| chars.get(i + k) == Some(&c))
    };
    while i < chars.len() {
        let close = if starts(i, "{{") {
            "}}"
        } else if starts(i, "{%") {
            "%}"
        } else if starts(i, "{#") {
            // A comment: to its end.
            let mut j = i + 2;
            while j < chars.len() && !starts(j, "#}") {
                j += 1;
            }
            advance(&mut i, &mut line, &mut column, j + 2);
            continue;
        } else {
            let next = i + 1;
            advance(&mut i, &mut line, &mut column, next);
            continue;
        };
        let (at_line, at_column) = (line, column);
        let mut j = i + 2;
        let mut quote: Option<char> = None;
        while j < chars.len() {
            let c = chars[j];
            match quote {
                Some(_) if c == '\\' => j += 1,
                Some(q) if c == q => quote = None,
                Some(_) => {}
                None if c == '"' || c == '\'' => quote = Some(c),
                None if starts(j, close) => break,
                None => {}
            }
            j += 1;
        }
        let inner = j.saturating_sub(i + 2);
        if inner > MAX_TAG_CHARS {
            return Some(LongTag {
                line: at_line,
                column: at_column,
                chars: inner,
            });
        }
        let raw = close == "%}" && {
            let body: String = chars[i + 2..j.min(chars.len())].iter().collect();
            body.trim_matches(|c: char| c == '-' || c == '+' || c.is_whitespace()) == "raw"
        };
        advance(&mut i, &mut line, &mut column, j + 2);
        if raw {
            // Text up to `{% endraw %}`.
            let mut k = i;
            while k < chars.len() {
                if starts(k, "{%") {
                    let end: String = chars[k + 2..(k + 40).min(chars.len())].iter().collect();
                    if end
                        .trim_start_matches(|c: char| c == '-' || c == '+' || c.is_whitespace())
                        .starts_with("endraw")
                    {
                        break;
                    }
                }
                k += 1;
            }
            advance(&mut i, &mut line, &mut column, k);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_tag_is_found_where_it_starts_and_text_comments_and_strings_are_not_tags() {
        let chain = format!("{{{{ 1{} }}}}", " + 1".repeat(5_000));
        let source = format!(
            "MODULE x\n  {{# {} #}}\n{}\n  {chain}\n",
            "y".repeat(40_000),
            "z".repeat(40_000)
        );
        let long = long_tag(&source).expect("the chain");
        assert_eq!((long.line, long.column), (4, 3));
        assert_eq!(long.chars, chain.chars().count() - 4);
        // Short tags, a string holding a closing delimiter, a raw block of text.
        let fine = format!(
            "{{{{ 'a }}}}' ~ x }}}}\n{{% raw %}}{{{{ {} }}}}{{% endraw %}}\n{{% if x %}}y{{% endif %}}",
            "1 + ".repeat(10_000)
        );
        assert_eq!(long_tag(&fine), None);
        // Not closed: the rest of the file is the tag.
        let open = format!("{{{{ {}", "a".repeat(MAX_TAG_CHARS + 1));
        assert_eq!(long_tag(&open).map(|t| t.line), Some(1));
    }
}
