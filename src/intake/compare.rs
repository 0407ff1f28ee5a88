//! The comparison options of `speed` and `map` (tensions or rackets): their checks, what a
//! compared tension sets, and the short name of each compared racket.

use std::path::Path;

use crate::error::{Error, Result};
use crate::params::{Overrides, Params};

/// A racket argument as a short name: the paper's racket, a preset as is, a file by the
/// `name` it gives (else its file stem).
pub fn racket_label(arg: Option<&str>) -> String {
    match arg {
        None => "paper racket".to_string(),
        Some(a) if crate::racket::preset_names().contains(&a) => a.to_string(),
        Some(a) => crate::racket::load(a)
            .ok()
            .and_then(|spec| spec.name)
            .unwrap_or_else(|| Path::new(a).file_stem().and_then(|s| s.to_str()).unwrap_or(a).to_string()),
    }
}

/// The parameter keys a compared tension sets in each configuration it names (k_s =
/// [`crate::params::ks_from_tension_lb`]).
pub const TENSION_SETS: [&str; 1] = ["ks"];

/// The comparison options of `speed` and `map`: tensions or rackets, not both; each tension in
/// range and named once; and, when every compared configuration is at a given tension (two or
/// more tensions), no flag for what the tensions set ([`TENSION_SETS`]): no row would use it.
pub fn check_comparison(tensions_lb: &[f64], rackets_given: bool, flags: &Overrides) -> Result<()> {
    if !tensions_lb.is_empty() && rackets_given {
        return Err(Error::invalid(
            "compare-tension-lb",
            "(with --compare-racket)",
            "compare either tensions or rackets, not both",
        ));
    }
    if let Some(t) = tensions_lb.iter().find(|t| !(t.is_finite() && **t > 0.0 && **t <= 200.0)) {
        return Err(Error::invalid("compare-tension-lb", t, "tension must satisfy 0 < T <= 200 lb"));
    }
    if let Some((i, t)) = tensions_lb.iter().enumerate().find(|(i, t)| tensions_lb[..*i].contains(t)) {
        let list = tensions_lb.iter().map(f64::to_string).collect::<Vec<_>>().join(",");
        return Err(Error::invalid(
            "compare-tension-lb",
            list,
            format!("the tension {t} lb is given twice (item {}): a configuration compared with itself differs nowhere; give different tensions", i + 1),
        ));
    }
    if tensions_lb.len() >= 2 {
        let given = flags.given();
        if let Some(key) = TENSION_SETS.iter().find(|k| given.contains(k)) {
            let mut p = Params::default();
            flags.apply(&mut p);
            let value = crate::params::keys::value_text(key, &p).unwrap_or_default();
            return Err(Error::invalid(
                key,
                value,
                "not used with two or more --compare-tension-lb tensions: every compared configuration takes its k_s \
                 from its tension (4e4 N/m * T / 60 lb); give one tension T to compare this k_s against T",
            ));
        }
    }
    Ok(())
}
