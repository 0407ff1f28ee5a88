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
