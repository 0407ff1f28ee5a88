//! The string table (data/strings/strings.csv, compiled in; its source is named in
//! data/strings/README.md): for each string that `--string` can name, its material, gauge and
//! the friction coefficients the tangential contact uses.

use std::sync::OnceLock;

use super::spec::FlagValue;
use super::{Oblique, StringName};
use crate::error::{Error, Result};

/// The table as shipped.
const TABLE: &str = include_str!("../../data/strings/strings.csv");

/// One string of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct StringEntry {
    /// The name `--string` takes.
    pub id: String,
    /// The string as named in the TWU spin table.
    pub name: String,
    /// gut, nylon or polyester.
    pub material: String,
    /// Gauge, mm.
    pub gauge_mm: f64,
    /// Ball-on-string friction coefficient (TWU "String/Ball COF"), if the database gives it.
    pub mu: Option<f64>,
    /// String-on-string friction coefficient (TWU "String/String COF"), if given.
    pub mu_ss: Option<f64>,
    /// Stiffness, lb/in, if given (recorded, not used by the model).
    pub stiffness_lb_per_in: Option<f64>,
}

/// Every string of the table, in its order.
pub fn all() -> &'static [StringEntry] {
    static PARSED: OnceLock<Vec<StringEntry>> = OnceLock::new();
    PARSED.get_or_init(|| {
        let number = |t: &str| if t.is_empty() { None } else { t.parse::<f64>().ok() };
        TABLE
            .lines()
            .skip(1)
            .filter(|l| !l.trim().is_empty())
            .map(|line| {
                let c: Vec<&str> = line.split(',').map(str::trim).collect();
                StringEntry {
                    id: c[0].to_string(),
                    name: c[1].to_string(),
                    material: c[2].to_string(),
                    gauge_mm: number(c[3]).unwrap_or(f64::NAN),
                    mu: number(c[4]),
                    mu_ss: number(c[5]),
                    stiffness_lb_per_in: number(c[6]),
                }
            })
            .collect()
    })
}

/// A one-line note when the named string of an oblique or spinning ball lacks a friction
/// coefficient in the table (gut and nylon have none in the TWU database): which value is used
/// instead. `None` when no string is named, the ball arrives along the normal, or the entry has
/// both.
pub fn missing_data_note(o: &Oblique) -> Option<String> {
    let e = entry(o.string)?;
    let mut missing = Vec::new();
    if e.mu.is_none() {
        missing.push(format!("mu {} (ball/string)", o.mu));
    }
    if e.mu_ss.is_none() && o.tangential.has(super::TangentialLaw::Bed) {
        missing.push(format!("mu-ss {} (string/string)", o.mu_ss));
    }
    (!o.is_normal() && !missing.is_empty()).then(|| {
        format!(
            "string {}: no friction data in the TWU database ({}), so {} as given or by default",
            e.id,
            e.material,
            missing.join(" and ")
        )
    })
}

/// The table's entry of a named string (`None` for [`StringName::None`]).
pub fn entry(name: StringName) -> Option<&'static StringEntry> {
    (name != StringName::None).then(|| all().iter().find(|e| e.id == name.name())).flatten()
}

/// The string named `text` (a racket file's `string`), or a one-line refusal listing the names.
pub fn parse(text: &str) -> Result<StringName> {
    StringName::parse_flag("string", text)
}

/// Write the named string's friction coefficients into `o` (so that what is shown is what is
/// used), refusing a `mu` or `mu-ss` given beside a string whose table entry sets it.
pub fn apply(o: &mut Oblique, mu_given: bool, mu_ss_given: bool) -> Result<()> {
    for (key, given) in [("mu", mu_given), ("mu-ss", mu_ss_given)] {
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
    let set = match key {
        "mu" => e.mu.is_some(),
        "mu-ss" => e.mu_ss.is_some(),
        _ => false,
    };
    set.then_some(e.id.as_str())
}

/// Refuse a friction `key` given (as a flag, a config key or a swept axis) beside a string
/// whose entry sets it.
pub fn refuse_if_set(name: StringName, key: &'static str) -> Result<()> {
    match sets(name, key) {
        Some(id) => Err(Error::invalid(
            key,
            "given",
            format!("is set by string = {id} (its TWU database value); give one or the other"),
        )),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_has_its_row_and_every_row_its_name() {
        let ids: Vec<&str> = all().iter().map(|e| e.id.as_str()).collect();
        let names: Vec<&str> = StringName::ALL.iter().skip(1).map(|n| n.name()).collect();
        assert_eq!(ids, names);
        for e in all() {
            assert!(e.gauge_mm > 1.0 && e.gauge_mm < 1.5, "{e:?}");
            assert_eq!(e.mu.is_some(), e.material == "polyester", "{e:?}");
            assert_eq!(e.mu_ss.is_some(), e.mu.is_some(), "{e:?}");
        }
        assert_eq!(entry(StringName::Tcs16).unwrap().mu_ss, Some(0.088));
        assert_eq!(entry(StringName::None), None);
    }
}
