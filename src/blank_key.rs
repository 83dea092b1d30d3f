//! Leaf: the first key of a YAML text given no value (`tool:` whose body is commented out,
//! `mass:` with nothing after it, `wobj: ~`), for the cell and the controller file alike. A typed
//! reading takes an optional key given `null` as left out (serde's `Option`), so a tool whose
//! lines were commented out would become "no tool" without a word; this pass walks the parsed
//! YAML once more, after the typed reading has accepted it, and finds the first mapping entry
//! whose value is null, so the reader can refuse it at its line.

use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_saphyr::Spanned;

/// A mapping key, as text (a key that is not a string is shown as the reader gives it).
struct Key(String);

impl<'de> Deserialize<'de> for Key {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Key;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a key")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Key, E> {
                Ok(Key(s.to_string()))
            }
            fn visit_bool<E: de::Error>(self, b: bool) -> Result<Key, E> {
                Ok(Key(b.to_string()))
            }
            fn visit_i64<E: de::Error>(self, n: i64) -> Result<Key, E> {
                Ok(Key(n.to_string()))
            }
            fn visit_u64<E: de::Error>(self, n: u64) -> Result<Key, E> {
                Ok(Key(n.to_string()))
            }
            fn visit_f64<E: de::Error>(self, n: f64) -> Result<Key, E> {
                Ok(Key(n.to_string()))
            }
            fn visit_unit<E: de::Error>(self) -> Result<Key, E> {
                Ok(Key("~".into()))
            }
            fn visit_none<E: de::Error>(self) -> Result<Key, E> {
                Ok(Key("~".into()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Key, A::Error> {
                while seq.next_element::<de::IgnoredAny>()?.is_some() {}
                Ok(Key("[...]".into()))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Key, A::Error> {
                while map
                    .next_entry::<de::IgnoredAny, de::IgnoredAny>()?
                    .is_some()
                {}
                Ok(Key("{...}".into()))
            }
        }
        d.deserialize_any(V)
    }
}

/// A YAML node walked for its first key without a value: `null` is the node itself being null.
enum Walk {
    Null,
    /// The first key without a value below the node: its name and the place of its value.
    Found(String, u64, u64),
    Fine,
}

impl<'de> Deserialize<'de> for Walk {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Walk;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("any YAML")
            }
            fn visit_unit<E: de::Error>(self) -> Result<Walk, E> {
                Ok(Walk::Null)
            }
            fn visit_none<E: de::Error>(self) -> Result<Walk, E> {
                Ok(Walk::Null)
            }
            fn visit_some<D2: Deserializer<'de>>(self, d: D2) -> Result<Walk, D2::Error> {
                Walk::deserialize(d)
            }
            fn visit_bool<E: de::Error>(self, _: bool) -> Result<Walk, E> {
                Ok(Walk::Fine)
            }
            fn visit_i64<E: de::Error>(self, _: i64) -> Result<Walk, E> {
                Ok(Walk::Fine)
            }
            fn visit_u64<E: de::Error>(self, _: u64) -> Result<Walk, E> {
                Ok(Walk::Fine)
            }
            fn visit_f64<E: de::Error>(self, _: f64) -> Result<Walk, E> {
                Ok(Walk::Fine)
            }
            fn visit_str<E: de::Error>(self, _: &str) -> Result<Walk, E> {
                Ok(Walk::Fine)
            }
            fn visit_bytes<E: de::Error>(self, _: &[u8]) -> Result<Walk, E> {
                Ok(Walk::Fine)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Walk, A::Error> {
                let mut found = Walk::Fine;
                while let Some(item) = seq.next_element::<Walk>()? {
                    if let (Walk::Fine, Walk::Found(..)) = (&found, &item) {
                        found = item;
                    }
                }
                Ok(found)
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Walk, A::Error> {
                let mut found = Walk::Fine;
                while let Some(key) = map.next_key::<Key>()? {
                    let value: Spanned<Walk> = map.next_value()?;
                    if !matches!(found, Walk::Fine) {
                        continue;
                    }
                    found = match value.value {
                        Walk::Null => {
                            Walk::Found(key.0, value.referenced.line(), value.referenced.column())
                        }
                        inner @ Walk::Found(..) => inner,
                        _ => Walk::Fine,
                    };
                }
                Ok(found)
            }
        }
        d.deserialize_any(V)
    }
}

/// A key given no value: its name as written and the place of its (missing) value, 1-based.
pub struct BlankKey {
    pub key: String,
    pub line: u64,
    pub column: u64,
}

impl BlankKey {
    /// The refusal's message, with the key as the caller shows it (bounded by its excerpt).
    pub fn message(shown_key: &str) -> String {
        format!("`{shown_key}:` is given no value (`~`, `null`, or nothing after it)")
    }
}

/// The first key of `text` given no value, if any (module docs). `options` are the reader's,
/// with which the typed reading accepted the text.
pub fn first_blank_key(text: &str, options: serde_saphyr::Options) -> Option<BlankKey> {
    match serde_saphyr::from_str_with_options::<Walk>(text, options) {
        Ok(Walk::Found(key, line, column)) => Some(BlankKey { key, line, column }),
        _ => None,
    }
}
