//! The column layout of a sweep's CSV: the swept keys, the recorded ones, then the result
//! fields, and each impact's row of them as text.

use crate::numfmt::exact;
use crate::params::{keys, Params};
use crate::solve::outcome::{Field, Get, FIELDS};
use crate::solve::ImpactResult;

/// The parameters every sweep row records, swept or not (the impact point, the string bed and
/// the ball speed), and for a sweep of oblique or spinning balls the incidence, azimuth, spin
/// and friction too (what an oblique impact is run at, as its single-impact CSV records it).
pub fn recorded_keys(oblique: bool) -> Vec<&'static str> {
    let mut v = vec![keys::X.key, keys::R.key, keys::KS.key, keys::V1.key];
    if oblique {
        v.extend([keys::ANGLE_DEG.key, keys::AZIMUTH_DEG.key, keys::SPIN_RPM.key, keys::MU.key]);
    }
    v
}

/// Column name of a parameter, with its SI unit (`unknown` for a key that is not a parameter).
pub fn column_name(key: &str) -> &'static str {
    keys::find(key).map_or("unknown", |spec| spec.column)
}

/// The result fields a sweep writes: the sweep columns of the result's field table
/// ([`FIELDS`]), the oblique ones only in a sweep of oblique or spinning balls, and the losses
/// of the named tangential mechanisms only where some impact runs under such a law (`losses`;
/// an empty field for an impact under the elastic law).
fn swept(oblique: bool, losses: bool) -> impl Iterator<Item = &'static Field> {
    FIELDS.iter().filter(move |f| f.sweep && (oblique || !f.is_oblique()) && (losses || !f.is_law_only()))
}

/// Result columns written for every impact: `swept` fields, then the solver (unless the
/// solver is itself a swept axis, whose column already names it: no column twice).
pub fn result_columns(oblique: bool, losses: bool, solver_swept: bool) -> impl Iterator<Item = &'static str> {
    swept(oblique, losses).map(|f| f.key).chain((!solver_swept).then_some("solver"))
}

/// One cell of a sweep row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell<'a> {
    /// A swept value as given (a number or a name, as the flag takes it).
    Given(&'a str),
    /// A number: a recorded parameter or a result field (NaN: undefined).
    Number(f64),
    /// A yes/no result field.
    Flag(bool),
    /// A name (the solver that ran).
    Name(&'static str),
}

impl Cell<'_> {
    /// The cell as its CSV field. Numbers are written in their shortest form that reads back
    /// as the same `f64` (`ryu`: `0.25`, `1.5e-7`, `3.0`; [`exact`]): exact, and without the
    /// noise digits of a fixed 17; an undefined one as an empty field; a flag as 0 or 1.
    pub fn text(&self) -> String {
        match *self {
            Cell::Given(v) | Cell::Name(v) => v.to_string(),
            Cell::Number(v) => exact(v),
            Cell::Flag(f) => u8::from(f).to_string(),
        }
    }
}

/// Append the result columns of one impact ([`result_columns`]) to `row`, as cells.
pub(super) fn push_result_cells(
    row: &mut Vec<Cell<'_>>,
    r: &ImpactResult,
    p: &Params,
    (oblique, losses): (bool, bool),
    solver_swept: bool,
) {
    row.extend(swept(oblique, losses).map(|f| match f.get {
        Get::Number(g) => Cell::Number(g(r)),
        Get::Flag(g) => Cell::Flag(g(r)),
    }));
    if !solver_swept {
        row.push(Cell::Name(p.numerics.solver.name()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Overrides;

    #[test]
    fn every_key_has_its_own_column_name() {
        let names: Vec<&str> = Overrides::KEYS.iter().map(|k| column_name(k)).collect();
        assert!(!names.contains(&"unknown"), "{names:?}");
        let mut unique = names.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), names.len(), "{names:?}");
    }
}
