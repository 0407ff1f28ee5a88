//! What the spin panel's tangential law was validated on, and what it was not, read from the
//! validation of the spin model against the measurements of data/measured (experiment
//! `validation_spin`, SPEC.md section 7).
//!
//! The validation's table is shipped as `figures/validation_spin.csv` and compiled in here; the
//! golden test (`tests/golden.rs`) holds that file equal to what the code computes now, so the
//! status read here is the one of the tangential laws on this build, and follows the default
//! law wherever it moves. Its `model` column and its uncertainty budget (`u_val`) are the
//! default law's; every law has its own `model_<law>` column.
//!
//! The rules, stated before any value is read:
//! - **level**: the TWU table's held-out points (role `validation`, the 40 deg reading) within
//!   their validation uncertainty, |E| <= u_val with E = model - measured: counted for the law
//!   whose budget the table holds (the default); for another law only its RMS error is known.
//! - **string order**: validated where Spearman's rho over the held-out points is positive with
//!   a two-sided p below [`ORDER_P`] at both readings of the angle (40 and 50 deg).
//! - **not validated**: every other validation quantity whose |E| exceeds its u_val (default
//!   law), named; the tour forehand (the card's own shot) with its measured and model spin.

use crate::error::{Error, Result};
use crate::params::{Oblique, StringName, TangentialLaw};

/// The validation table as shipped (see the module doc).
const VALIDATION: &str = include_str!("../../../figures/validation_spin.csv");
/// Where it lives, for the messages.
const VALIDATION_FILE: &str = "figures/validation_spin.csv";

/// The p-value below which a positive rank correlation counts as an order validated.
pub const ORDER_P: f64 = 0.05;

/// The validation quantity of the card's spin shot: a tour forehand, read at this swing path.
pub const FOREHAND_QUANTITY: &str = "forehand_spin_rpm";

/// The level of a law on the TWU table's held-out points.
#[derive(Debug, Clone, PartialEq)]
pub struct Level {
    /// Held-out points within their u_val (the default law), else `None`.
    pub within: Option<usize>,
    /// Held-out points.
    pub points: usize,
    /// RMS of E over them, rpm.
    pub rms_rpm: f64,
}

/// The rank correlation of a law's spins with the measured ones over the held-out points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Order {
    /// Spearman's rho and its p-value, at the 40 deg reading.
    pub at_40: (f64, f64),
    /// The same at the 50 deg reading.
    pub at_50: (f64, f64),
}

impl Order {
    /// Whether the order is validated ([`ORDER_P`], both readings).
    pub fn validated(&self) -> bool {
        [self.at_40, self.at_50].iter().all(|&(rho, p)| rho > 0.0 && p < ORDER_P)
    }
}

/// One validation quantity beyond its u_val.
#[derive(Debug, Clone, PartialEq)]
pub struct Miss {
    /// The quantity, as the table names it.
    pub quantity: String,
    /// Its row's label (the string or shot).
    pub label: String,
    /// Measured and model values, and u_val.
    pub measured: f64,
    /// The model's value.
    pub model: f64,
    /// The validation uncertainty.
    pub u_val: f64,
    /// The unit.
    pub unit: String,
}

/// What the spin panel's law was validated on and what it was not.
#[derive(Debug, Clone, PartialEq)]
pub struct SpinStatus {
    /// The law of the card's spin.
    pub law: TangentialLaw,
    /// Whether the table's budget is this law's (it is the default law).
    pub budgeted: bool,
    /// Its level on the TWU table's held-out points.
    pub level: Level,
    /// Its string order.
    pub order: Order,
    /// The quantities beyond their u_val (the default law only).
    pub misses: Vec<Miss>,
    /// The tour forehand rows (the card's shot, on the paper's racket at 60 lb): label,
    /// measured, model (this law), u_val (`NaN` for another law).
    pub forehand: Vec<(String, f64, f64, f64)>,
    /// The calibration strings (the rows the law and its constant were chosen on).
    pub calibration_strings: Vec<String>,
    /// The string in use and its rows' role in the table (`calibration`, `validation`), if it
    /// has rows.
    pub string_role: Option<(StringName, String)>,
}

/// The table: its header and rows.
struct Shipped {
    headers: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Shipped {
    fn read() -> Result<Shipped> {
        let bad = |why: String| Error::invalid("validation table", VALIDATION_FILE, why);
        let mut rdr = csv::Reader::from_reader(VALIDATION.as_bytes());
        let headers = rdr.headers().map_err(|e| bad(e.to_string()))?.iter().map(str::to_string).collect();
        let rows = rdr
            .records()
            .map(|r| r.map(|r| r.iter().map(str::to_string).collect()).map_err(|e| bad(e.to_string())))
            .collect::<Result<_>>()?;
        Ok(Shipped { headers, rows })
    }

    fn column(&self, name: &str) -> Result<usize> {
        self.headers.iter().position(|h| h == name).ok_or_else(|| {
            Error::invalid("validation table", VALIDATION_FILE, format!("has no column {name} (the card reads it)"))
        })
    }

    /// The rows of `quantity`.
    fn of<'a>(&'a self, quantity: &'a str) -> impl Iterator<Item = &'a Vec<String>> + 'a {
        self.rows.iter().filter(move |r| r.first().is_some_and(|q| q == quantity))
    }

    /// The number in column `c` of `row` (NaN where empty).
    fn num(row: &[String], c: usize) -> f64 {
        row.get(c).and_then(|v| v.parse().ok()).unwrap_or(f64::NAN)
    }

    /// The value of `quantity`'s one row in column `c`.
    fn value(&self, quantity: &str, c: usize) -> Result<f64> {
        self.of(quantity).next().map(|r| Self::num(r, c)).ok_or_else(|| {
            Error::invalid("validation table", VALIDATION_FILE, format!("has no row {quantity} (the card reads it)"))
        })
    }
}

impl SpinStatus {
    /// The status of `law`, with the string `string` in use.
    pub fn of(law: TangentialLaw, string: StringName) -> Result<SpinStatus> {
        let t = Shipped::read()?;
        let [quantity, label, measured, model, unit, role, u_val] =
            ["quantity", "string", "measured", "model", "unit", "role", "u_val"].map(|c| t.column(c));
        let (quantity, label, measured, model, unit, role, u_val) =
            (quantity?, label?, measured?, model?, unit?, role?, u_val?);
        let mine = t.column(&format!("model_{}", law.name()))?;
        let default = t.column(&format!("model_{}", Oblique::default().tangential.name()))?;
        // the budget is the default law's: its column is the `model` column
        let budgeted = mine == default
            && t.rows.iter().all(|r| r[model] == r[default])
            && t.rows.iter().any(|r| !r[model].is_empty());
        let text = |r: &Vec<String>, c: usize| r.get(c).cloned().unwrap_or_default();
        let error = |r: &Vec<String>| Shipped::num(r, mine) - Shipped::num(r, measured);
        let held_out: Vec<&Vec<String>> = t.of("spin_out_rpm").filter(|r| r[role] == "validation").collect();
        if held_out.is_empty() {
            return Err(Error::invalid("validation table", VALIDATION_FILE, "has no held-out spin_out_rpm rows"));
        }
        let level = Level {
            within: budgeted.then(|| held_out.iter().filter(|r| error(r).abs() <= Shipped::num(r, u_val)).count()),
            points: held_out.len(),
            rms_rpm: crate::study::stats::rms(held_out.iter().map(|r| error(r))),
        };
        let rank = |reading: &str| -> Result<(f64, f64)> {
            Ok((
                t.value(&format!("{reading}:rank_correlation_validation"), mine)?,
                t.value(&format!("{reading}:rank_correlation_validation_p"), mine)?,
            ))
        };
        let order = Order { at_40: rank("spin_out_rpm")?, at_50: rank("spin_out_rpm_50deg")? };
        let misses = if budgeted {
            t.rows
                .iter()
                .filter(|r| r[role] == "validation" && !r[quantity].contains(':'))
                .filter(|r| !r[quantity].starts_with("spin_out_rpm"))
                .filter(|r| error(r).abs() > Shipped::num(r, u_val))
                .map(|r| Miss {
                    quantity: text(r, quantity),
                    label: text(r, label),
                    measured: Shipped::num(r, measured),
                    model: Shipped::num(r, mine),
                    u_val: Shipped::num(r, u_val),
                    unit: text(r, unit),
                })
                .collect()
        } else {
            Vec::new()
        };
        let forehand = t
            .of(FOREHAND_QUANTITY)
            .map(|r| {
                let u = if budgeted { Shipped::num(r, u_val) } else { f64::NAN };
                (text(r, label), Shipped::num(r, measured), Shipped::num(r, mine), u)
            })
            .collect();
        let mut calibration_strings: Vec<String> =
            t.of("spin_out_rpm").filter(|r| r[role] == "calibration").map(|r| text(r, label)).collect();
        calibration_strings.dedup();
        let string_role = t.of("spin_out_rpm").find(|r| r[label] == string.name()).map(|r| (string, text(r, role)));
        Ok(SpinStatus { law, budgeted, level, order, misses, forehand, calibration_strings, string_role })
    }

    /// The status in a few sentences, each one line of the CSV header and the figure: the law,
    /// what it was validated on, what not, and the string in use.
    pub fn sentences(&self) -> Vec<String> {
        let sig = |v: f64| crate::numfmt::sig(v, 3);
        let mut out = Vec::new();
        let default = Oblique::default().tangential;
        out.push(format!(
            "law {}{}: chosen, with its kt, on the calibration strings {} of the TWU spin table (data/measured)",
            self.law.name(),
            if self.law == default { " (the default)" } else { " (not the default)" },
            self.calibration_strings.join(", ")
        ));
        let level = &self.level;
        out.push(match level.within {
            Some(0) => format!(
                "level not validated: none of {} held-out TWU points within its validation uncertainty (40 deg reading; RMS error {} rpm)",
                level.points,
                sig(level.rms_rpm)
            ),
            Some(n) => format!(
                "level validated on {n} of {} held-out TWU points (|E| <= u_val, 40 deg reading; RMS error {} rpm)",
                level.points,
                sig(level.rms_rpm)
            ),
            None => format!(
                "level not judged for this law (the validation budget is the default law's, {}): RMS error {} rpm over {} held-out TWU points",
                default.name(),
                sig(level.rms_rpm),
                level.points
            ),
        });
        let o = self.order;
        out.push(format!(
            "string order {}: Spearman rho {} (p {}) at 40 deg, {} (p {}) at 50 deg over the held-out strings",
            if o.validated() { "validated" } else { "not validated" },
            sig(o.at_40.0),
            crate::numfmt::sig(o.at_40.1, 2),
            sig(o.at_50.0),
            crate::numfmt::sig(o.at_50.1, 2)
        ));
        if !self.misses.is_empty() {
            let named: Vec<String> = self
                .misses
                .iter()
                .filter(|m| m.quantity != FOREHAND_QUANTITY)
                .map(|m| format!("{} ({} against {} measured)", m.quantity, sig(m.model), sig(m.measured)))
                .collect();
            if !named.is_empty() {
                out.push(format!("not validated: {}", named.join("; ")));
            }
        }
        if let Some((label, measured, model, u)) = self.forehand.first() {
            let verdict = if !u.is_finite() {
                "not judged".to_string()
            } else if (model - measured).abs() <= *u {
                "validated".to_string()
            } else {
                format!(
                    "not validated (|E| {} rpm > u_val {} rpm)",
                    crate::numfmt::sig((model - measured).abs(), 4),
                    crate::numfmt::sig(*u, 3)
                )
            };
            let path = label.rsplit("; ").next().unwrap_or(label);
            out.push(format!(
                "this shot (tour forehand, {path}, paper's racket at 60 lb): model {} rpm against {} rpm measured (three players' means): {verdict}",
                crate::numfmt::sig(*model, 4),
                crate::numfmt::sig(*measured, 4)
            ));
        }
        match &self.string_role {
            Some((s, role)) if role == "calibration" => out
                .push(format!("{}: a calibration string (the law was fitted on its rows: not a prediction)", s.name())),
            Some((s, role)) => out.push(format!("{}: a {role} string (held out from the fit)", s.name())),
            None => {}
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_law_is_the_one_the_shipped_table_budgets() {
        let s = SpinStatus::of(Oblique::default().tangential, StringName::None).unwrap();
        assert!(s.budgeted, "figures/validation_spin.csv is not of the default law: run `make figures`");
        assert_eq!(s.level.points, 8);
        assert!(s.level.within.is_some());
        // another law: its RMS, no count, no misses
        let other =
            crate::params::TangentialLaw::ALL.into_iter().find(|&l| l != Oblique::default().tangential).unwrap();
        let o = SpinStatus::of(other, StringName::None).unwrap();
        assert!(!o.budgeted && o.level.within.is_none() && o.misses.is_empty());
        assert_ne!(o.level.rms_rpm, s.level.rms_rpm);
    }

    #[test]
    fn a_string_is_named_with_its_role() {
        let s = SpinStatus::of(Oblique::default().tangential, StringName::AluPower16).unwrap();
        assert_eq!(s.string_role, Some((StringName::AluPower16, "calibration".into())));
        assert!(s.sentences().iter().any(|l| l.starts_with("alu-power-16: a calibration string")));
        let s = SpinStatus::of(Oblique::default().tangential, StringName::Tcs16).unwrap();
        assert_eq!(s.string_role, Some((StringName::Tcs16, "validation".into())));
        assert_eq!(SpinStatus::of(Oblique::default().tangential, StringName::None).unwrap().string_role, None);
    }

    #[test]
    fn an_order_needs_a_positive_correlation_told_from_chance_at_both_readings() {
        assert!(Order { at_40: (0.8, 0.01), at_50: (0.7, 0.02) }.validated());
        assert!(!Order { at_40: (0.8, 0.01), at_50: (0.7, 0.2) }.validated());
        assert!(!Order { at_40: (-0.8, 0.01), at_50: (0.7, 0.02) }.validated());
    }
}
