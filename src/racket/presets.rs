//! The built-in racket presets (files `presets/<name>.toml`) and loading a racket by preset
//! name or file path.

use std::path::Path;

use super::spec::RacketSpec;
use crate::error::{Error, Result};

/// The presets: (name, file contents).
pub(super) const PRESETS: [(&str, &str); 5] = [
    ("paper-125hz", include_str!("../../presets/paper-125hz.toml")),
    ("paper-widebody-200hz", include_str!("../../presets/paper-widebody-200hz.toml")),
    ("light", include_str!("../../presets/light.toml")),
    ("tweener", include_str!("../../presets/tweener.toml")),
    ("players", include_str!("../../presets/players.toml")),
];

const PRESET_NAMES: [&str; 5] = [PRESETS[0].0, PRESETS[1].0, PRESETS[2].0, PRESETS[3].0, PRESETS[4].0];

/// Names of the built-in racket presets (files `presets/<name>.toml`).
pub fn preset_names() -> &'static [&'static str] {
    &PRESET_NAMES
}

/// A built-in preset by name.
pub fn preset(name: &str) -> Option<RacketSpec> {
    let (_, text) = PRESETS.iter().find(|(n, _)| *n == name)?;
    toml::from_str(text).ok()
}

/// The presets fitted for `segments` segments, one row each: name, length, mass, balance,
/// swingweight, twistweight, first frequency, string-bed stiffness and whether the beam is
/// fitted to a profile or uniform (`racket --list`).
pub fn presets_table(segments: usize) -> Result<crate::render::table::Table> {
    use crate::render::table::{Table, Value};
    let mut table = Table::new(
        "presets",
        &[
            "name",
            "length_cm",
            "mass_g",
            "balance_cm",
            "swingweight_kg_cm2",
            "twistweight_kg_cm2",
            "f1_hz",
            "ks_n_per_m",
            "profile",
        ],
    );
    for name in preset_names() {
        let fitted = load(name)?.to_racket(segments)?;
        let (r, rep) = (&fitted.racket, &fitted.report);
        table.push(vec![
            Value::Text(name.to_string()),
            Value::Num(100.0 * r.length),
            Value::Num(1e3 * r.mass),
            Value::Num(rep.balance_cm.model),
            Value::Num(rep.swingweight_kg_cm2.model),
            Value::Num(rep.twistweight_kg_cm2.model),
            Value::Num(rep.frequency_hz.model),
            Value::Num(fitted.strings.ks),
            Value::Text(if r.profile.is_none() { "uniform" } else { "fitted" }.to_string()),
        ])?;
    }
    Ok(table)
}

/// A preset by name, else a racket file at the path `arg`. Neither gives an error listing the
/// presets.
pub fn load(arg: &str) -> Result<RacketSpec> {
    if arg.chars().any(char::is_control) {
        return Err(Error::invalid(
            "racket",
            format!("{arg:?}"),
            "a racket's name or path labels rows and tables: no line breaks or control characters",
        ));
    }
    let path = Path::new(arg);
    // (symlink_metadata: a dangling link or a FIFO is there too, and the reader says what it is)
    let is_there = std::fs::symlink_metadata(path).is_ok();
    if let Some(spec) = preset(arg) {
        if is_there {
            return Err(Error::invalid(
                "racket",
                arg,
                format!("names both a preset and a file here: give ./{arg} for the file, or move the file to use the preset"),
            ));
        }
        return Ok(spec);
    }
    if is_there {
        return RacketSpec::from_toml_file(path);
    }
    Err(Error::invalid(
        "racket",
        arg,
        format!("must be a racket preset ({}) or a racket file (none at this path)", PRESET_NAMES.join(", ")),
    ))
}
