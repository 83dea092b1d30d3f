//! The nesting of a URDF's elements, bounded before the XML reader sees it: the reader
//! (urdf-rs over serde) descends an element's children by recursion, so a file of 100 000
//! nested elements overflowed the stack (an abort, not an error). A URDF nests a few levels
//! (`robot` / `link` / `collision` / `geometry` / `cylinder`); [`MAX_DEPTH`] is far beyond.

/// The deepest element nesting a URDF may have.
pub const MAX_DEPTH: usize = 64;

/// The 1-based line of the first element nested deeper than [`MAX_DEPTH`], if any. Comments,
/// CDATA sections, processing instructions and declarations nest nothing; a quoted attribute
/// value may hold `>`.
pub fn too_deep(text: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    let (mut i, mut depth, mut line) = (0usize, 0usize, 1usize);
    let skip_to = |from: usize, end: &str| -> usize {
        text[from..]
            .find(end)
            .map_or(bytes.len(), |k| from + k + end.len())
    };
    while i < bytes.len() {
        match bytes[i] {
            b'\n' => {
                line += 1;
                i += 1;
            }
            b'<' => {
                let rest = &text[i..];
                let end = if rest.starts_with("<!--") {
                    skip_to(i, "-->")
                } else if rest.starts_with("<![CDATA[") {
                    skip_to(i, "]]>")
                } else if rest.starts_with("<?") {
                    skip_to(i, "?>")
                } else {
                    // A tag: to its `>`, past quoted values.
                    let mut j = i + 1;
                    let mut quote = None;
                    while j < bytes.len() {
                        match (quote, bytes[j]) {
                            (Some(q), c) if c == q => quote = None,
                            (None, c @ (b'"' | b'\'')) => quote = Some(c),
                            (None, b'>') => break,
                            _ => {}
                        }
                        j += 1;
                    }
                    let tag = &bytes[i..j.min(bytes.len())];
                    if tag.starts_with(b"</") {
                        depth = depth.saturating_sub(1);
                    } else if !tag.starts_with(b"<!") && !tag.ends_with(b"/") {
                        depth += 1;
                        if depth > MAX_DEPTH {
                            return Some(line);
                        }
                    }
                    j + 1
                };
                let end = end.min(bytes.len());
                line += bytes[i..end].iter().filter(|&&b| b == b'\n').count();
                i = end;
            }
            _ => i += 1,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nesting_is_counted_past_comments_quotes_and_empty_elements() {
        let urdf = include_str!("../../robots/irb1400.urdf");
        assert_eq!(too_deep(urdf), None);
        let deep = format!(
            "<robot>\n<!-- <a><a><a> -->\n{}{}</robot>",
            "<a x='>'>\n".repeat(MAX_DEPTH),
            "</a>".repeat(MAX_DEPTH)
        );
        // robot + 64 a: the 64th <a> is the 65th level, on line 2 + 64.
        assert_eq!(too_deep(&deep), Some(66));
        let flat = format!("<robot>{}</robot>", "<a/><b></b>".repeat(10_000));
        assert_eq!(too_deep(&flat), None);
    }
}
