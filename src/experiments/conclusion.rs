//! What the paper concluded from a claim, as code: each row of `golden/paper_claims.csv` carries
//! its conclusion in words (`conclusion`) and in a checkable form (`conclusion_check`), which
//! [`Check`] parses and evaluates on the claim's value and, where the conclusion is an order
//! or a ratio, on the values of the other claims computed at the same inputs.
//!
//! The form is one or more terms joined by ` and `, each a comparison of the claim's own value
//! with a number, a claim or a multiple of a claim: `> 0 and < 2` (a sign and an "almost
//! negligible"), `< clamped_tau_ks4e4` (an order), `> 1.5 * fig9_e_a_ei150` (a ratio),
//! `< 0.25 * fig5_centre_tau_stiff` ("small compared with", the threshold stated), or the
//! paper's own magnitude `about 20`, read by the one reading of "about"
//! ([`super::tolerance::about_band`]: `> 18 and < 22`). The comparisons are strict: a value at a
//! threshold does not carry the conclusion. Where each threshold comes from is the claims
//! file's `threshold_source`.

use super::tolerance::about_band;
use crate::error::{Error, Result};

/// What the claim's value is compared with.
#[derive(Debug, Clone, PartialEq)]
pub enum Operand {
    /// A number in the claim's unit.
    Number(f64),
    /// `factor` times another claim's value (computed at the same inputs).
    Claim {
        /// The multiple (1 for a plain id).
        factor: f64,
        /// The other claim's id.
        id: String,
    },
}

/// One comparison: the claim's value above (`greater`) or below the operand.
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    /// `>` (true) or `<` (false).
    pub greater: bool,
    /// The other side.
    pub operand: Operand,
}

/// A conclusion's checkable form: every term must hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Check {
    /// The terms, all required.
    pub terms: Vec<Term>,
}

impl Check {
    /// Parse the form (see the module text); `id` names the claim in an error.
    pub fn parse(id: &str, form: &str) -> Result<Check> {
        let bad = |why: &str| {
            Error::invalid(
                "conclusion_check",
                form,
                format!("claim {id}: {why} (e.g. '> 0 and < 1', '< 0.5 * other_id')"),
            )
        };
        let mut terms = Vec::new();
        for term in form.split(" and ") {
            let term = term.trim();
            if let Some(value) = term.strip_prefix("about ") {
                let (lo, hi) = about_band(value).ok_or_else(|| bad("'about' takes a non-zero number"))?;
                terms.push(Term { greater: true, operand: Operand::Number(lo) });
                terms.push(Term { greater: false, operand: Operand::Number(hi) });
                continue;
            }
            terms.push({
                let greater = match term.chars().next() {
                    Some('>') => true,
                    Some('<') => false,
                    _ => return Err(bad("each term starts with > or <")),
                };
                let rest = term[1..].trim();
                let operand = match rest.split_once('*') {
                    Some((factor, other)) => Operand::Claim {
                        factor: factor.trim().parse().map_err(|_| bad("the factor before * is not a number"))?,
                        id: claim_id(other.trim()).ok_or_else(|| bad("no claim id after *"))?,
                    },
                    None => match rest.parse::<f64>() {
                        Ok(v) if v.is_finite() => Operand::Number(v),
                        _ => Operand::Claim {
                            factor: 1.0,
                            id: claim_id(rest).ok_or_else(|| bad("not a number or a claim id"))?,
                        },
                    },
                };
                Term { greater, operand }
            });
        }
        Ok(Check { terms })
    }

    /// The other claims the conclusion compares with.
    pub fn references(&self) -> impl Iterator<Item = &str> {
        self.terms.iter().filter_map(|t| match &t.operand {
            Operand::Claim { id, .. } => Some(id.as_str()),
            Operand::Number(_) => None,
        })
    }

    /// Whether the conclusion holds for the claim's value `own`, the other claims' values
    /// given by `value_of` (a missing or non-finite value fails the term, as a non-finite
    /// `own` does).
    pub fn holds(&self, own: f64, value_of: impl Fn(&str) -> Option<f64>) -> bool {
        own.is_finite() && self.slacks(own, value_of).iter().all(|s| s.is_some_and(|s| s > 0.0))
    }

    /// Each term's threshold, the other claims' values given by `value_of`: `(greater,
    /// threshold)`, `None` where a compared value is missing or not finite.
    pub fn thresholds(&self, value_of: impl Fn(&str) -> Option<f64>) -> Vec<Option<(bool, f64)>> {
        self.terms
            .iter()
            .map(|t| {
                let other = match &t.operand {
                    Operand::Number(v) => Some(*v),
                    Operand::Claim { factor, id } => value_of(id).map(|v| factor * v),
                };
                other.filter(|o| o.is_finite()).map(|o| (t.greater, o))
            })
            .collect()
    }

    /// How far the claim's value `own` is inside each term (positive: the term holds; in the
    /// claim's unit): `own - threshold` for `>`, `threshold - own` for `<`.
    pub fn slacks(&self, own: f64, value_of: impl Fn(&str) -> Option<f64>) -> Vec<Option<f64>> {
        self.thresholds(value_of)
            .into_iter()
            .map(|t| t.map(|(greater, o)| if greater { own - o } else { o - own }))
            .collect()
    }
}

/// `s` if it is a claim id (lower-case letters, digits and underscores, starting with a
/// letter).
fn claim_id(s: &str) -> Option<String> {
    let ok = s.chars().next().is_some_and(|c| c.is_ascii_lowercase())
        && s.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    ok.then(|| s.to_string())
}

/// A share of samples at or above this is `mostly`.
pub const MOSTLY: f64 = 0.9;
/// A share below this is `fails` (the mirror of [`MOSTLY`]).
pub const FAILS_BELOW: f64 = 0.1;

/// Whether the paper's conclusion survives the input uncertainty.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Standing {
    /// In every sample.
    Holds,
    /// In at least [`MOSTLY`] of them.
    Mostly,
    /// Between [`FAILS_BELOW`] and [`MOSTLY`].
    Contested,
    /// In under [`FAILS_BELOW`] of them.
    Fails,
    /// No sampled input moves what the conclusion compares: its share says nothing.
    Independent,
}

impl Standing {
    /// Every verdict, in the order the counts are told.
    pub const ALL: [Standing; 5] =
        [Standing::Holds, Standing::Mostly, Standing::Contested, Standing::Fails, Standing::Independent];

    /// The word in the table (`conclusion_verdict`).
    pub fn name(self) -> &'static str {
        match self {
            Standing::Holds => "holds",
            Standing::Mostly => "mostly",
            Standing::Contested => "contested",
            Standing::Fails => "fails",
            Standing::Independent => "independent",
        }
    }

    /// The verdict of a share (`None`: independent).
    pub fn of(share: Option<f64>) -> Standing {
        match share {
            None => Standing::Independent,
            Some(s) if s >= 1.0 => Standing::Holds,
            Some(s) if s >= MOSTLY => Standing::Mostly,
            Some(s) if s < FAILS_BELOW => Standing::Fails,
            Some(_) => Standing::Contested,
        }
    }
}

/// The rule of the verdicts in words, for the report.
pub fn rule_text() -> String {
    format!(
        "*holds* in every sample, *mostly* in at least {} % of them, *fails* in under {} %, *contested* between; \
         *independent* where no sampled input moves what the conclusion compares",
        (100.0 * MOSTLY).round(),
        (100.0 * FAILS_BELOW).round()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn none(_: &str) -> Option<f64> {
        None
    }

    #[test]
    fn a_claim_whose_sign_flips_fails_its_conclusion() {
        // the paper's "60 -> 50 lb serves slightly faster, by well under 1 %"
        let c = Check::parse("speeds_60_50_serve_gain", "> 0 and < 1").unwrap();
        assert!(c.holds(0.55, none));
        assert!(!c.holds(-0.55, none), "a slower serve contradicts the conclusion");
        assert!(!c.holds(1.2, none), "so does a gain of more than 1 %");
        assert!(!c.holds(0.0, none) && !c.holds(f64::NAN, none));
        let down = Check::parse("speeds_50_60_theta_change", "< 0 and > -10").unwrap();
        assert!(down.holds(-3.7, none) && !down.holds(3.7, none));
    }

    #[test]
    fn orders_and_ratios_compare_with_the_other_claims_at_the_same_inputs() {
        let c = Check::parse("fig9_e_a_ei384", "> 1.5 * fig9_e_a_ei150").unwrap();
        assert_eq!(c.references().collect::<Vec<_>>(), ["fig9_e_a_ei150"]);
        let at = |v: f64| move |id: &str| (id == "fig9_e_a_ei150").then_some(v);
        assert!(c.holds(0.19, at(0.11)));
        assert!(!c.holds(0.19, at(0.13)), "1.5 x 0.13 = 0.195 > 0.19");
        assert!(!c.holds(0.19, none), "a missing claim fails the term");
        let order = Check::parse("concrete_tau", "< clamped_tau_ks4e4").unwrap();
        assert!(order.holds(4.6, |_| Some(5.9)) && !order.holds(6.0, |_| Some(5.9)));
    }

    #[test]
    fn about_is_read_as_every_approximate_value_is() {
        let c = Check::parse("conclusions_theta_cut_ks_double", "about 20").unwrap();
        assert!(c.holds(19.0, none) && c.holds(21.9, none));
        assert!(!c.holds(15.4, none), "a 15.4 % cut is not 'about 20 %'");
        assert!(!c.holds(22.1, none));
        let mixed = Check::parse("c", "about 5.0 and < other").unwrap();
        assert_eq!(mixed.terms.len(), 3);
        assert!(mixed.holds(5.0, |_| Some(6.0)) && !mixed.holds(5.0, |_| Some(4.9)));
    }

    #[test]
    fn malformed_forms_are_refused() {
        for bad in [
            "",
            "0 < 1",
            "> ",
            "> x y",
            "> 2 * ",
            "> two * fig",
            "= 3",
            "> 1 and",
            "> Fig",
            "about",
            "about x",
            "about 0",
        ] {
            assert!(Check::parse("c", bad).is_err(), "{bad:?} should be refused");
        }
    }

    #[test]
    fn shares_map_to_verdicts() {
        assert_eq!(Standing::of(Some(1.0)), Standing::Holds);
        assert_eq!(Standing::of(Some(0.95)), Standing::Mostly);
        assert_eq!(Standing::of(Some(0.9)), Standing::Mostly);
        assert_eq!(Standing::of(Some(0.5)), Standing::Contested);
        assert_eq!(Standing::of(Some(0.1)), Standing::Contested);
        assert_eq!(Standing::of(Some(0.05)), Standing::Fails);
        assert_eq!(Standing::of(Some(0.0)), Standing::Fails);
        assert_eq!(Standing::of(None), Standing::Independent);
    }
}
