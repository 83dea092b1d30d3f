//! An SVG picture read back as XML (quick-xml): its elements with their attributes and text, so
//! that a test can find what was drawn. Parsing fails on anything that is not well-formed XML
//! (unclosed or mismatched tags, bad attributes).

use quick_xml::events::Event;
use quick_xml::Reader;
use std::collections::BTreeMap;

/// One element: its name, attributes and the text directly inside it.
#[derive(Clone, Debug)]
pub struct Element {
    pub name: String,
    pub attrs: BTreeMap<String, String>,
    pub text: String,
}

impl Element {
    pub fn attr(&self, key: &str) -> Option<&str> {
        self.attrs.get(key).map(String::as_str)
    }

    /// A numeric attribute.
    pub fn num(&self, key: &str) -> Option<f64> {
        self.attr(key).and_then(|v| v.parse().ok())
    }
}

/// A parsed SVG document: every element in document order.
#[derive(Debug)]
pub struct Svg {
    pub elements: Vec<Element>,
}

impl Svg {
    /// Parses `text` as XML; the root element must be `<svg>`.
    pub fn parse(text: &str) -> Result<Svg, String> {
        // Text untrimmed: entity references split it, and the spaces around them count.
        let mut reader = Reader::from_str(text);
        let mut elements: Vec<Element> = Vec::new();
        let mut open: Vec<usize> = Vec::new();
        let mut roots = 0;
        loop {
            let event = reader
                .read_event()
                .map_err(|e| format!("not XML at byte {}: {e}", reader.error_position()))?;
            let (start, empty) = match &event {
                Event::Start(e) => (Some(e.clone()), false),
                Event::Empty(e) => (Some(e.clone()), true),
                _ => (None, false),
            };
            if let Some(e) = start {
                let mut attrs = BTreeMap::new();
                for a in e.attributes() {
                    let a = a.map_err(|e| format!("bad attribute: {e}"))?;
                    let value = a.unescape_value().map_err(|e| format!("bad value: {e}"))?;
                    attrs.insert(
                        String::from_utf8_lossy(a.key.as_ref()).into_owned(),
                        value.into_owned(),
                    );
                }
                if open.is_empty() {
                    roots += 1;
                }
                elements.push(Element {
                    name: String::from_utf8_lossy(e.name().as_ref()).into_owned(),
                    attrs,
                    text: String::new(),
                });
                if !empty {
                    open.push(elements.len() - 1);
                }
                continue;
            }
            match event {
                Event::End(_) => {
                    open.pop();
                }
                Event::Text(t) => {
                    let t = t.decode().map_err(|e| format!("bad text: {e}"))?;
                    if let Some(&i) = open.last() {
                        elements[i].text.push_str(&t);
                    }
                }
                Event::GeneralRef(r) => {
                    let name = r.decode().map_err(|e| format!("bad reference: {e}"))?;
                    let c = match name.as_ref() {
                        "lt" => Some('<'),
                        "gt" => Some('>'),
                        "amp" => Some('&'),
                        "quot" => Some('"'),
                        "apos" => Some('\''),
                        _ => r.resolve_char_ref().ok().flatten(),
                    };
                    if let (Some(&i), Some(c)) = (open.last(), c) {
                        elements[i].text.push(c);
                    }
                }
                Event::Eof => break,
                _ => {}
            }
        }
        if !open.is_empty() {
            return Err(format!("{} element(s) left open", open.len()));
        }
        if roots != 1 || elements.first().map(|e| e.name.as_str()) != Some("svg") {
            return Err("the document is not one <svg> element".into());
        }
        Ok(Svg { elements })
    }

    /// Reads and parses a file.
    pub fn read(path: &std::path::Path) -> Svg {
        let text = std::fs::read_to_string(path)
            .unwrap_or_else(|e| panic!("read {}: {e}", path.display()));
        Svg::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    }

    /// The elements named `name`.
    pub fn all<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Element> + 'a {
        self.elements.iter().filter(move |e| e.name == name)
    }

    /// The `<text>` elements whose text, trimmed, is `label`.
    pub fn labels<'a>(&'a self, label: &'a str) -> impl Iterator<Item = &'a Element> + 'a {
        self.all("text").filter(move |e| e.text.trim() == label)
    }
}

#[test]
fn malformed_pictures_are_refused() {
    assert!(Svg::parse("<svg><g></svg>").is_err());
    assert!(Svg::parse("<svg><text>a</text>").is_err());
    assert!(Svg::parse("<svg/><svg/>").is_err());
    assert!(Svg::parse("<g/>").is_err());
    let s = Svg::parse("<svg><text x=\"1\">P&amp;1</text><circle r=\"9\"/></svg>").expect("ok");
    assert_eq!(s.labels("P&1").count(), 1);
    assert_eq!(s.all("circle").next().and_then(|c| c.num("r")), Some(9.0));
}
