//! Every key a cell gives has a value: `tool:` whose body is commented out, `mass:` with
//! nothing after it, `wobj: ~`, are input errors at their line, never "absent". The typed
//! reading (`raw.rs`) takes an optional key given `null` as left out (serde's `Option`), so a
//! tool whose lines were commented out became "no tool" and the TCP the flange, 100 - 300 mm
//! off, without a word. The walk is the leaf `blank_key`'s; this file says the refusal in the cell's
//! words.

use super::{CellError, Loc};
use crate::blank_key::{first_blank_key, BlankKey};

/// The refusal of the first key of `text` given no value, if any (module docs). `options` are
/// the reader's, with which the typed reading accepted the text.
pub(super) fn first_key_without_value(
    text: &str,
    options: serde_saphyr::Options,
) -> Option<CellError> {
    let blank = first_blank_key(text, options)?;
    let key = crate::excerpt::value(&blank.key);
    Some(CellError::Invalid {
        loc: Loc {
            line: blank.line,
            column: blank.column,
        },
        message: BlankKey::message(&key),
        help: Some(format!(
            "give `{key}` its value, or leave the key out for its default; a key whose lines below are commented out is not left out, so it is refused rather than taken as absent"
        )),
    })
}
