//! A point's `do:` list: the actions done at the point, in order, each a mapping of one key
//! (`set_do`, `pulse_do`, `wait_di`, `wait_time`, `grip_load`; another key is refused by the
//! reader, with a suggestion). Signal names are RAPID names of signals the controller declares
//! (the module uses them, as it uses a speeddata, and declares none); `grip_load` names `load0`
//! or one of the cell's `loads:`.

use super::super::raw::{RawAction, RawArg};
use super::super::{defaults, Action, ActionKind, CellError, Load, Loc};
use super::values::{in_range, invalid_help, loc, IDENTIFIER_HELP};
use crate::excerpt;
use crate::names::check_identifier;
use crate::precision::WAIT_TIME_DECIMALS;
use serde_saphyr::Spanned;

/// The help line of an action's form.
const ACTION_HELP: &str = "`do:` is a list of actions, each one of { set_do: [signal, 0|1] }, { pulse_do: signal }, { wait_di: [signal, 0|1] }, { wait_time: s }, { grip_load: load }";

/// The actions of the entry `who` names (`None`: no `do:`).
pub(super) fn actions(
    raw: Option<&Spanned<Vec<Spanned<RawAction>>>>,
    who: &str,
    loads: &[Load],
) -> Result<Vec<Action>, CellError> {
    let Some(raw) = raw else {
        return Ok(Vec::new());
    };
    raw.value.iter().map(|a| action(a, who, loads)).collect()
}

fn action(a: &Spanned<RawAction>, who: &str, loads: &[Load]) -> Result<Action, CellError> {
    let r = &a.value;
    let given: Vec<(&str, Loc)> = [
        r.set_do.as_ref().map(|x| ("set_do", loc(x))),
        r.pulse_do.as_ref().map(|x| ("pulse_do", loc(x))),
        r.wait_di.as_ref().map(|x| ("wait_di", loc(x))),
        r.wait_time.as_ref().map(|x| ("wait_time", loc(x))),
        r.grip_load.as_ref().map(|x| ("grip_load", loc(x))),
    ]
    .into_iter()
    .flatten()
    .collect();
    if let [(first, _), (second, at), ..] = given.as_slice() {
        return Err(invalid_help(
            *at,
            format!("{who}: one action gives both `{first}` and `{second}`; write each as its own action"),
            ACTION_HELP,
        ));
    }
    let kind = if let Some(s) = &r.set_do {
        let (signal, value) = signal_and_value(s, who, "set_do")?;
        ActionKind::SetDo { signal, value }
    } else if let Some(s) = &r.pulse_do {
        ActionKind::PulseDo {
            signal: signal(&s.value, loc(s), who, "pulse_do")?,
        }
    } else if let Some(s) = &r.wait_di {
        let (signal, value) = signal_and_value(s, who, "wait_di")?;
        ActionKind::WaitDi { signal, value }
    } else if let Some(t) = &r.wait_time {
        ActionKind::WaitTime {
            time_s: in_range(
                t,
                &format!("{who} wait_time"),
                (0.0, defaults::MAX_WAIT_S),
                WAIT_TIME_DECIMALS,
                "s",
                "WaitTime waits this many seconds, 0 .. 3600 (an hour)",
            )?,
        }
    } else if let Some(l) = &r.grip_load {
        ActionKind::GripLoad {
            load: load(l, who, loads)?,
        }
    } else {
        return Err(invalid_help(
            loc(a),
            format!(
                "{who}: an action gives one of set_do, pulse_do, wait_di, wait_time, grip_load"
            ),
            ACTION_HELP,
        ));
    };
    Ok(Action { kind, loc: loc(a) })
}

/// `[signal, 0|1]` of `set_do` and `wait_di` (`key`).
fn signal_and_value(
    v: &Spanned<Vec<Spanned<RawArg>>>,
    who: &str,
    key: &str,
) -> Result<(String, bool), CellError> {
    let [s, x] = v.value.as_slice() else {
        return Err(invalid_help(
            loc(v),
            format!(
                "{who} {key} takes [signal, 0|1], found {} values",
                v.value.len()
            ),
            ACTION_HELP,
        ));
    };
    let signal = match &s.value {
        RawArg::Text(name) => signal(name, loc(s), who, key)?,
        other => {
            return Err(invalid_help(
                loc(s),
                format!(
                    "{who} {key}: the signal must be a name, found {}",
                    shown(other)
                ),
                format!("{key} takes [signal, 0|1]: the signal's name first, then the value"),
            ))
        }
    };
    match x.value {
        RawArg::Number(n) if n == 0.0 || n == 1.0 => Ok((signal, n == 1.0)),
        ref other => Err(invalid_help(
            loc(x),
            format!("{who} {key} {signal}: the value {} is not 0 or 1", shown(other)),
            "a digital signal is 0 or 1: set_do sets an output to it, wait_di waits until an input has it",
        )),
    }
}

/// An argument as a message quotes it.
fn shown(a: &RawArg) -> String {
    match a {
        RawArg::Text(t) => format!("'{}'", excerpt::value(t)),
        RawArg::Number(n) => excerpt::number(*n),
        RawArg::Bool(b) => b.to_string(),
        RawArg::Other(what) => (*what).to_string(),
    }
}

/// A signal's name: the RAPID identifier rule (it shares the module's name space).
fn signal(name: &str, at: Loc, who: &str, key: &str) -> Result<String, CellError> {
    check_identifier(name).map_err(|e| {
        invalid_help(
            at,
            format!(
                "{who} {key} signal '{}' is not a valid RAPID name: {e}",
                excerpt::value(name)
            ),
            format!("a signal is named as the controller declares it; {IDENTIFIER_HELP}"),
        )
    })?;
    Ok(name.to_string())
}

/// `grip_load: name`: `None` for `load0`, else the index of the cell's load of that name.
fn load(l: &Spanned<String>, who: &str, loads: &[Load]) -> Result<Option<usize>, CellError> {
    if l.value.eq_ignore_ascii_case("load0") {
        return Ok(None);
    }
    match loads
        .iter()
        .position(|d| d.name.eq_ignore_ascii_case(&l.value))
    {
        Some(i) => Ok(Some(i)),
        None => {
            let declared: Vec<&str> = loads.iter().take(8).map(|d| d.name.as_str()).collect();
            let help = match declared.as_slice() {
                [] => "declare the loaddata under `loads:` ({ name, mass, cog }), or grip load0 (nothing held)".to_string(),
                names => format!(
                    "grip_load names one of the cell's loads ({}{}) or load0 (nothing held)",
                    names.join(", "),
                    if loads.len() > 8 { ", ..." } else { "" }
                ),
            };
            Err(invalid_help(
                loc(l),
                format!(
                    "{who} grip_load '{}' names no load of the cell",
                    excerpt::value(&l.value)
                ),
                help,
            ))
        }
    }
}
