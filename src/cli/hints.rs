//! What an unknown flag is told: clap's "a similar argument exists" picks the nearest flag by
//! spelling, which for a known concept a command does not take is a wrong lead (`speed
//! --spin-rpm` -> `--p`, `map --r` -> `--grip`, `map --dt` -> `--hand-stiffness`,
//! `uncertainty --series` -> `--ei`). Here a parameter a command sets itself, or an option of
//! another command, is answered with where that concept lives; any other unknown flag keeps
//! clap's suggestion only when it is a near spelling of it (a typo), else gets none.

use clap::error::{ContextKind, ContextValue, ErrorKind};
use racket_impact::params::keys;

use super::overrides::{KeySet, ModesKeys};

/// Why `command` has no flag for the parameter `key` and where it comes from, if the
/// parameter is one the command sets or does not use (the library says which, and why).
fn parameter_hint(command: &str, key: &str) -> Option<String> {
    use racket_impact::study::{map::set_by_map, speed::set_by_speed};
    let spec = keys::find(key)?;
    let why = match command {
        "speed" => set_by_speed(spec.key)?.to_string(),
        "map" => set_by_map(spec.key)?.to_string(),
        "modes" if !ModesKeys::takes(spec.key) => {
            let free: Vec<String> = keys::FREE_RACKET.iter().map(|s| format!("--{}", s.key)).collect();
            let (last, init) = free.split_last()?;
            format!("the free racket's modes depend only on {} and {last}", init.join(", "))
        }
        _ => return None,
    };
    Some(format!("{command} does not take --{}: {why}", spec.key))
}

/// Options of other commands, where a user looks for them.
fn option_hint(command: &str, flag: &str) -> Option<String> {
    let hint = match flag {
        "series" | "series-dt" | "series-end" => "a time series is written by simulate --solver fd --series FILE",
        "out" => "this command prints its result on standard output (redirect it: > FILE)",
        "vary" | "samples" | "seed" => {
            "uncertain inputs are the uncertainty command's (racket-impact uncertainty --help)"
        }
        "quantity" | "nx" | "nr" => "a map of the string face is the map command's (racket-impact map --help)",
        "swing" | "incoming" => "swing speeds are the speed command's (racket-impact speed --help)",
        _ => return None,
    };
    let _ = command;
    Some(hint.to_string())
}

/// Whether clap's suggestion `suggested` is a near spelling of `typed` (both without dashes):
/// at most a third of the letters changed, or one is the start of the other.
fn near(typed: &str, suggested: &str) -> bool {
    let distance = strsim::levenshtein(typed, suggested);
    distance * 3 <= typed.len().max(suggested.len()) || (typed.len() >= 3 && suggested.starts_with(typed))
}

/// The one line for clap's unknown-argument error `e` in `command`, or `None` for any other
/// error.
pub fn unknown_flag(e: &clap::Error, command: &str) -> Option<String> {
    if e.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(given)) = e.get(ContextKind::InvalidArg) else { return None };
    let name = given.trim_start_matches('-').split('=').next().unwrap_or_default();
    let suggested = match e.get(ContextKind::SuggestedArg) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        _ => None,
    };
    let hint = parameter_hint(command, name).or_else(|| option_hint(command, name)).or_else(|| {
        suggested
            .filter(|s| near(name, s.trim_start_matches('-').split(' ').next().unwrap_or_default()))
            .map(|s| format!("did you mean {s}?"))
    });
    let command = if command.is_empty() { "racket-impact".to_string() } else { format!("racket-impact {command}") };
    let given = racket_impact::numfmt::quoted(given);
    Some(match hint {
        Some(h) => format!("error: {command} has no option '{given}': {h}"),
        None => format!("error: {command} has no option '{given}' (see {command} --help)"),
    })
}

/// The command named on the command line `args` (the first word that is one), or "".
pub fn command_of(args: &[String], names: &[&str]) -> String {
    args.iter().skip(1).find(|a| names.contains(&a.as_str())).cloned().unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_near_spelling_is_a_typo_and_a_far_one_is_not() {
        assert!(near("segmets", "segments"));
        assert!(near("ang", "angle-deg"));
        assert!(!near("spin-rpm", "p"));
        assert!(!near("r", "grip"));
        assert!(!near("dt", "hand-stiffness"));
        assert!(!near("series", "ei"));
    }
}
