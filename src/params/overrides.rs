//! The `--config` files: [`Overrides`] read from TOML (the flag names as keys), and the TOML
//! reading the racket files share.

use super::Overrides;
use crate::error::{Error, Result};

impl Overrides {
    /// Read a TOML config file with the flag names as keys.
    pub fn from_toml_file(path: &std::path::Path) -> Result<Self> {
        Self::from_toml_bytes(path, &read_file(path)?)
    }

    /// Parse the contents of a config file (`path` only names it in errors). An empty file, a
    /// file that is not UTF-8 text, a TOML syntax error, a wrong type and an unknown key are all
    /// errors with one line naming the file and, where TOML knows it, the key and line.
    pub fn from_toml_bytes(path: &std::path::Path, bytes: &[u8]) -> Result<Self> {
        let hint = "give at least one key, e.g. ks = 4e4";
        unknown_key(path, bytes)?;
        match canonical_keys(path, bytes)? {
            Some(text) => parse_toml(path, text.as_bytes(), hint),
            None => parse_toml(path, bytes, hint),
        }
    }
}

/// Refuse a key of a config file that is no parameter, in one line that says what a config file
/// holds (a file shared between commands holds parameters; a command's own options, such as
/// `speed --swing`, are given on its command line) and the nearest key where one is near. A
/// file that is not a TOML table is left to [`parse_toml`].
fn unknown_key(path: &std::path::Path, bytes: &[u8]) -> Result<()> {
    let Some(text) = std::str::from_utf8(bytes).ok() else { return Ok(()) };
    let Ok(table) = text.parse::<toml::Table>() else { return Ok(()) };
    let Some(name) = table.keys().find(|k| super::keys::find_any(k).is_none()) else { return Ok(()) };
    let line = text
        .lines()
        .position(|l| l.trim_start().trim_start_matches(['"', '\'']).starts_with(name.as_str()))
        .map(|i| format!(" (line {})", i + 1))
        .unwrap_or_default();
    let near = super::keys::ALL
        .iter()
        .map(|s| s.key)
        .filter(|k| strsim::levenshtein(name, k) == 1 || strsim::levenshtein(name, k) * 4 <= name.len().max(k.len()))
        .min_by_key(|k| strsim::levenshtein(name, k))
        .map(|k| format!("did you mean {k}? "))
        .unwrap_or_default();
    Err(Error::Config {
        path: path.into(),
        message: escaped(&format!(
            "unknown key `{name}`{line}: {near}a config file holds parameters, the flags under the headings of \
             `racket-impact simulate --help` (x, ks, mb, ...); a command's own options (speed's --swing, map's --nx, \
             uncertainty's --vary) go on its command line"
        )),
    })
}

/// The config text with every alias of a key ([`super::keys::aliases`]: `angle_deg`,
/// `ks_n_per_m`) spelled as the key, or `None` when it has none (or is not a TOML table, which
/// [`parse_toml`] then reports). A key given twice under two spellings is an error.
fn canonical_keys(path: &std::path::Path, bytes: &[u8]) -> Result<Option<String>> {
    let Some(table) = std::str::from_utf8(bytes).ok().and_then(|t| t.parse::<toml::Table>().ok()) else {
        return Ok(None);
    };
    if table.keys().all(|k| super::keys::find(k).is_some() || super::keys::find_any(k).is_none()) {
        return Ok(None);
    }
    let mut out = toml::Table::new();
    for (name, value) in table {
        let key = super::keys::find_any(&name).map_or(name.clone(), |s| s.key.to_string());
        if out.insert(key.clone(), value).is_some() {
            return Err(Error::Config {
                path: path.into(),
                message: format!("{name} and {key} name the same parameter: give it once"),
            });
        }
    }
    toml::to_string(&out).map(Some).map_err(|e| Error::Config { path: path.into(), message: e.to_string() })
}

/// The bytes of a TOML file; a file that cannot be read is an [`Error::Config`] naming it.
///
/// Only a regular file (or a link to one) is read, and at most
/// [`MAX_INPUT_FILE_BYTES`](super::limits::MAX_INPUT_FILE_BYTES) of it: a device
/// (`/dev/zero`, `/dev/urandom`) would be read without end and a FIFO with no writer would
/// block for ever, so both are refused before the file is opened. (A FIFO is not accepted even
/// with a writer: a config is read once, whole, before any work, and a regular file says so.)
pub(crate) fn read_file(path: &std::path::Path) -> Result<Vec<u8>> {
    use std::io::Read;
    let max = super::limits::MAX_INPUT_FILE_BYTES;
    let err = |message: String| Error::Config { path: path.into(), message };
    let meta = std::fs::metadata(path).map_err(|e| err(e.to_string()))?;
    if !meta.is_file() {
        let kind = if meta.is_dir() { "a directory" } else { "a device, FIFO or socket" };
        return Err(err(format!("is {kind}, not a regular file (give a TOML file)")));
    }
    let too_big = || err(format!("is larger than {} MiB, the most a config or racket file may be", max >> 20));
    if meta.len() > max {
        return Err(too_big());
    }
    let mut bytes = Vec::new();
    let file = std::fs::File::open(path).map_err(|e| err(e.to_string()))?;
    file.take(max + 1).read_to_end(&mut bytes).map_err(|e| err(e.to_string()))?;
    if bytes.len() as u64 > max {
        return Err(too_big());
    }
    super::inputs::record(path);
    Ok(bytes)
}

/// Parse a TOML file's contents (`path` only names it in errors): an empty file (told what to
/// give: `empty_hint`), bytes that are not UTF-8, a syntax error, a wrong type and an unknown
/// key are all [`Error::Config`] with one line naming the file and, where TOML knows it, the
/// key and line.
pub(crate) fn parse_toml<T: serde::de::DeserializeOwned>(
    path: &std::path::Path,
    bytes: &[u8],
    empty_hint: &str,
) -> Result<T> {
    let err = |message: String| Error::Config { path: path.into(), message };
    let text = std::str::from_utf8(bytes).map_err(|_| err("not a UTF-8 text file".into()))?;
    if text.trim().is_empty() {
        return Err(err(format!("is empty ({empty_hint})")));
    }
    toml::from_str(text).map_err(|e| err(one_line(&e.to_string())))
}

/// Fold a multi-line message (e.g. a TOML parse error with a source excerpt) into one line, its
/// control characters escaped ([`escaped`]).
fn one_line(msg: &str) -> String {
    escaped(
        &msg.lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.chars().all(|c| "|^ ".contains(c)))
            .collect::<Vec<_>>()
            .join("; "),
    )
}

/// `msg` with every control character escaped as Rust writes it (`\0` as `\u{0}`, a tab as
/// `\t`): a file's bytes quoted in a message never reach the terminal raw.
fn escaped(msg: &str) -> String {
    msg.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

#[cfg(test)]
mod tests {
    use super::super::{LoadRule, Params};
    use super::*;

    #[test]
    fn config_keys_are_the_flag_names_and_unknown_keys_are_rejected() {
        let o: Overrides = toml::from_str("x = 0.2\nhalf-width = 0.1\nload = \"node\"").unwrap();
        assert_eq!(o.x, Some(0.2));
        assert_eq!(o.half_width, Some(0.1));
        assert_eq!(o.load, Some(LoadRule::Node));
        assert!(toml::from_str::<Overrides>("xx = 0.2").is_err());
    }

    #[test]
    fn an_unknown_key_says_what_a_config_holds_and_raw_bytes_are_escaped() {
        let p = std::path::Path::new("c.toml");
        let msg = Overrides::from_toml_bytes(p, b"x = 0.1\nswing = 30").unwrap_err().to_string();
        assert!(
            msg.starts_with("config file c.toml: unknown key `swing` (line 2): a config file holds parameters"),
            "{msg}"
        );
        assert!(msg.contains("speed's --swing"), "{msg}");
        let msg = Overrides::from_toml_bytes(p, b"kss = 3e4").unwrap_err().to_string();
        assert!(msg.contains("did you mean ks?"), "{msg}");
        let msg = Overrides::from_toml_bytes(p, b"ks = 3e4\x00\x01\n").unwrap_err().to_string();
        assert!(!msg.chars().any(char::is_control) && msg.contains("\\u{0}"), "{msg}");
    }

    #[test]
    fn a_key_may_be_spelled_as_in_the_json_or_the_csv() {
        let p = std::path::Path::new("c.toml");
        let o =
            Overrides::from_toml_bytes(p, b"angle_deg = 30\nks_n_per_m = 3e4\nhalf_width = 0.1\nmb = 0.05").unwrap();
        assert_eq!((o.angle_deg, o.ks, o.half_width, o.mb), (Some(30.0), Some(3.0e4), Some(0.1), Some(0.05)));
        let e = Overrides::from_toml_bytes(p, b"ks = 4e4\nks_n_per_m = 3e4").unwrap_err().to_string();
        assert!(e.contains("name the same parameter"), "{e}");
    }

    #[test]
    fn flags_override_the_config() {
        let flags = Overrides { ks: Some(2.0e4), ..Default::default() };
        let config = Overrides { ks: Some(3.0e4), x: Some(0.3), ..Default::default() };
        let mut p = Params::default();
        flags.or(config).apply(&mut p);
        assert_eq!((p.strings.ks, p.impact.x), (2.0e4, 0.3));
    }
}
