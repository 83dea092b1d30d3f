//! Every key a cell gives has a value: `tool:` whose body is commented out, `mass:` with
//! nothing after it, `wobj: ~`, are input errors at their line, never "absent". The typed
//! reading (`raw.rs`) takes an optional key given `null` as left out (serde's `Option`), so a
//! tool whose lines were commented out became "no tool" and the TCP the flange, 100 - 300 mm
//! off, without a word. This pass walks the parsed YAML once more, after the typed reading has
//! accepted it, and refuses the first mapping entry whose value is null.

use super::{CellError, Loc};
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
    Found(String, Loc),
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
                        Walk::Null => Walk::Found(key.0, Loc::from(value.referenced)),
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

/// The refusal of the first key of `text` given no value, if any (module docs). `options` are
/// the reader's, with which the typed reading accepted the text.
pub(super) fn first_key_without_value(
    text: &str,
    options: serde_saphyr::Options,
) -> Option<CellError> {
    let Ok(Walk::Found(key, loc)) = serde_saphyr::from_str_with_options::<Walk>(text, options)
    else {
        return None;
    };
    let key = crate::excerpt::value(&key);
    Some(CellError::Invalid {
        loc,
        message: format!("`{key}:` is given no value (`~`, `null`, or nothing after it)"),
        help: Some(format!(
            "give `{key}` its value, or leave the key out for its default; a key whose lines below are commented out is not left out, so it is refused rather than taken as absent"
        )),
    })
}
