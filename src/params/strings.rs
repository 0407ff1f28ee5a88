//! The string table (data/strings/strings.csv, compiled in; its source is named in
//! data/strings/README.md): for each string that `--string` can name, its material, gauge and
//! the friction coefficients the tangential contact uses, read with the `csv` crate into a
//! serde row (a bad row is an error naming the file and its line).

use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

use super::spec::FlagValue;
use super::{Oblique, StringName};
use crate::error::{Error, Result};

/// The table as shipped.
const TABLE: &str = include_str!("../../data/strings/strings.csv");

/// Where the shipped table lives, for the messages.
const TABLE_FILE: &str = "data/strings/strings.csv";

/// Where a string's friction coefficients come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
pub enum FrictionFrom {
    /// Its own row of the TWU string database.
    #[serde(rename = "entry")]
    Entry,
    /// No row of its own gives them: the median of the database's strings of its material
    /// (data/strings/README.md names the strings).
    #[serde(rename = "material_median")]
    MaterialMedian,
}

/// One string of the table (serialised with the table's column names).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
pub struct StringEntry {
    /// The name `--string` takes.
    pub id: String,
    /// The string as named in the TWU spin table.
    pub name: String,
    /// gut, nylon or polyester.
    pub material: String,
    /// Gauge, mm.
    pub gauge_mm: f64,
    /// Ball-on-string friction coefficient (TWU "String/Ball COF").
    #[serde(rename = "string_ball_cof")]
    pub mu: f64,
    /// String-on-string friction coefficient (TWU "String/String COF").
    #[serde(rename = "string_string_cof")]
    pub mu_ss: f64,
    /// Stiffness, lb/in, if given (recorded, not used by the model).
    pub stiffness_lb_per_in: Option<f64>,
    /// The database row the values were read from.
    pub twu_database_entry: String,
    /// Whether the friction is the string's own or its material's median.
    pub friction_from: FrictionFrom,
}

/// Parse a string table (`file` names it in the messages): every row with every column, a
/// known material and friction coefficients in 0..=2.
pub fn parse_table(text: &str, file: &str) -> Result<Vec<StringEntry>> {
    let mut rdr = csv::Reader::from_reader(text.as_bytes());
    let headers =
        rdr.headers().map_err(|e| Error::csv_row("string table", file, text, &csv::StringRecord::new(), &e))?.clone();
    let mut out = Vec::new();
    for record in rdr.records() {
        let bad = |line: u64, what: String| Error::invalid("string table", format!("{file}:{line}"), what);
        let record = record.map_err(|e| Error::csv_row("string table", file, text, &headers, &e))?;
        let e: StringEntry =
            record.deserialize(Some(&headers)).map_err(|e| Error::csv_row("string table", file, text, &headers, &e))?;
        let line = record.position().map_or(0, |at| crate::error::csv_line(text, at));
        if !["gut", "nylon", "polyester"].contains(&e.material.as_str()) {
            return Err(bad(line, format!("material '{}' is not gut, nylon or polyester", e.material)));
        }
        for (what, v) in [("string_ball_cof", e.mu), ("string_string_cof", e.mu_ss), ("gauge_mm", e.gauge_mm)] {
            if !(v.is_finite() && (0.0..=2.0).contains(&v)) {
                return Err(bad(line, format!("{what} = {v} must lie in 0..=2")));
            }
        }
        out.push(e);
    }
    Ok(out)
}

/// Every string of the table, in its order. The table is compiled in and a test parses it
/// ([`parse_table`]), so a bad row cannot reach a user.
pub fn all() -> &'static [StringEntry] {
    static PARSED: OnceLock<Vec<StringEntry>> = OnceLock::new();
    PARSED.get_or_init(|| parse_table(TABLE, TABLE_FILE).expect("the shipped string table parses (tested)"))
}

/// A one-line note when the named string of an oblique or spinning ball has no friction row of
/// its own in the TWU database: which median is used instead. `None` when no string is named,
/// the ball arrives along the normal, or the entry has its own row.
pub fn missing_data_note(o: &Oblique) -> Option<String> {
    let e = entry(o.string)?;
    (!o.is_normal() && e.friction_from != FrictionFrom::Entry).then(|| {
        // mu-ss only where the law uses it (its declaration says which)
        let mu_ss = if super::used::law_uses(&super::keys::MU_SS, o.tangential) {
            format!(" and mu-ss {} (string/string)", e.mu_ss)
        } else {
            String::new()
        };
        format!(
            "string {}: no friction data of its own in the TWU database ({} has no String/Ball or String/String COF), \
             so the median of the database's {} strings: mu {} (ball/string){mu_ss}",
            e.id, e.twu_database_entry, e.material, e.mu
        )
    })
}

/// The table's entry of a named string (`None` for [`StringName::None`]).
pub fn entry(name: StringName) -> Option<&'static StringEntry> {
    (name != StringName::None).then(|| all().iter().find(|e| e.id == name.name())).flatten()
}

/// The string named `text` (a racket file's `string`), or a one-line refusal listing the names.
pub fn parse(text: &str) -> Result<StringName> {
    StringName::parse_flag(super::keys::STRING.key, text)
}

/// Write the named string's friction coefficients into `o` (so that what is shown is what is
/// used), refusing a `mu` or `mu-ss` given beside a string whose table entry sets it.
pub fn apply(o: &mut Oblique, mu_given: bool, mu_ss_given: bool) -> Result<()> {
    for (key, given) in [(super::keys::MU.key, mu_given), (super::keys::MU_SS.key, mu_ss_given)] {
        if given {
            refuse_if_set(o.string, key)?;
        }
    }
    (o.mu, o.mu_ss) = o.friction();
    Ok(())
}

/// The id of the string `name` when its database entry sets the friction `key` (`mu` or
/// `mu-ss`): a value given for that key beside it would never be used.
pub fn sets(name: StringName, key: &str) -> Option<&'static str> {
    let e = entry(name)?;
    [super::keys::MU.key, super::keys::MU_SS.key].contains(&key).then_some(e.id.as_str())
}

/// Refuse a friction `key` given (as a flag, a config key or a swept axis) beside a string
/// whose entry sets it.
pub fn refuse_if_set(name: StringName, key: &'static str) -> Result<()> {
    match sets(name, key) {
        Some(id) => {
            Err(Error::invalid(key, "given", format!("is set by string = {id} (data/strings); give one or the other")))
        }
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::TangentialLaw;

    #[test]
    fn every_name_has_its_row_and_every_row_its_name() {
        let ids: Vec<&str> = all().iter().map(|e| e.id.as_str()).collect();
        let names: Vec<&str> = StringName::ALL.iter().skip(1).map(|n| n.name()).collect();
        assert_eq!(ids, names);
        for e in all() {
            assert!(e.gauge_mm > 1.0 && e.gauge_mm < 1.5, "{e:?}");
            // only the gut has no row of its own (data/strings/README.md)
            assert_eq!(e.friction_from == FrictionFrom::Entry, e.material != "gut", "{e:?}");
        }
        assert_eq!(entry(StringName::Tcs16).unwrap().mu_ss, 0.088);
        assert_eq!(entry(StringName::Nxt16).unwrap().mu, 0.453);
        assert_eq!(entry(StringName::Nrg2_16).unwrap().mu_ss, 0.155);
        assert_eq!(entry(StringName::None), None);
    }

    #[test]
    fn a_bad_row_is_an_error_naming_the_file_and_line() {
        let head = TABLE.lines().next().unwrap();
        let good = TABLE.lines().nth(1).unwrap();
        let cases = [
            (good.replacen(",gut,", ",wood,", 1), "material 'wood'"),
            (good.replacen(",0.412,", ",x,", 1), "string_ball_cof"),
            (good.replacen(",0.412,", ",3,", 1), "string_ball_cof = 3"),
            (good.replacen(",material_median", ",guess", 1), "guess"),
            ("tcs-16,Polyfibre TCS 16".to_string(), "fields"),
        ];
        for (bad, said) in cases {
            let text = format!("{head}\n{good}\n{bad}\n");
            let msg = parse_table(&text, "t.csv").unwrap_err().to_string();
            assert!(msg.contains("t.csv:3") && msg.contains(said), "{msg}");
            // after a blank line the bad row is on line 4, and the message says so
            let text = format!("{head}\n{good}\n\n{bad}\n");
            let msg = parse_table(&text, "t.csv").unwrap_err().to_string();
            assert!(msg.contains("t.csv:4") && msg.contains(said), "{msg}");
        }
        assert_eq!(parse_table(TABLE, TABLE_FILE).unwrap().len(), 7);
    }

    /// The gut's median note names mu-ss only under a law that uses it (bed, physical).
    #[test]
    fn the_median_note_names_only_what_the_law_uses() {
        let mut o = Oblique { string: StringName::TonicGut16, angle_deg: 30.0, ..Oblique::default() };
        for (law, says_mu_ss) in [
            (TangentialLaw::Loss, false),
            (TangentialLaw::Elastic, false),
            (TangentialLaw::Bed, true),
            (TangentialLaw::Physical, true),
        ] {
            o.tangential = law;
            let note = missing_data_note(&o).unwrap();
            assert!(note.contains("mu 0.") && note.contains("mu-ss") == says_mu_ss, "{note}");
        }
    }
}
