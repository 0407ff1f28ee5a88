//! How the paper's printed numbers and its words are read, stated once: the tolerance a printed
//! value allows ([`relative_tolerance`]), which words make a value approximate
//! ([`APPROXIMATE_WORDS`]), and the one reading of "about" that both the claims' tolerances and
//! the conclusions' `about X` forms apply ([`about_band`]).

/// Smallest relative tolerance: the paper's unstated numerics (time step, rounding of g and of
/// the drop height) are worth this much.
pub const MIN_REL_TOLERANCE: f64 = 0.005;
/// Smallest relative tolerance for values the paper itself calls approximate: the one reading of
/// "about" (and of the other [`APPROXIMATE_WORDS`]).
pub const APPROXIMATE_REL_TOLERANCE: f64 = 0.10;

/// The words that make a value approximate where the paper's sentence stating it uses one of
/// them: "about", "approximately", "typically", "roughly", "almost", "~".
pub const APPROXIMATE_WORDS: [&str; 6] = ["about", "approximately", "typically", "roughly", "almost", "~"];

/// Whether the paper's words (`quote`, its sentences stating the value) call the value
/// approximate: one of [`APPROXIMATE_WORDS`], as a word.
pub fn is_approximate(quote: &str) -> bool {
    let lower = quote.to_lowercase();
    let words: Vec<&str> = lower.split(|c: char| !c.is_alphanumeric() && c != '~').collect();
    APPROXIMATE_WORDS.iter().any(|w| if *w == "~" { lower.contains('~') } else { words.contains(w) })
}

/// The place value of the last digit of a number as printed: 0.01 for "0.44", 1 for "16",
/// 1e4 for "2e4" (the mantissa's last digit, scaled by the exponent), so "2e4" gets the same
/// relative half unit as "2".
pub fn last_digit_unit(printed: &str) -> f64 {
    let (mantissa, exponent) = match printed.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (printed, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    10f64.powi(exponent - decimals)
}

/// The relative tolerance of a value as printed: half a unit of its last digit relative to it,
/// at least [`MIN_REL_TOLERANCE`], or [`APPROXIMATE_REL_TOLERANCE`] for an approximate value.
/// `None` for text that is not a non-zero number.
pub fn relative_tolerance(printed: &str, approximate: bool) -> Option<f64> {
    let v: f64 = printed.trim().parse().ok().filter(|v: &f64| v.is_finite() && *v != 0.0)?;
    let half_unit = 0.5 * last_digit_unit(printed.trim()) / v.abs();
    let floor = if approximate { APPROXIMATE_REL_TOLERANCE } else { MIN_REL_TOLERANCE };
    Some(half_unit.max(floor))
}

/// "about X" as the claims read it: the values within X's approximate tolerance
/// ([`relative_tolerance`] of an approximate value), `(lo, hi)`. `None` for text that is not a
/// non-zero number.
pub fn about_band(printed: &str) -> Option<(f64, f64)> {
    let v: f64 = printed.trim().parse().ok()?;
    let t = relative_tolerance(printed, true)?;
    let half = t * v.abs();
    Some((v - half, v + half))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_tolerance_rule_for_every_way_of_printing_a_digit() {
        assert_eq!(last_digit_unit("0.44"), 0.01);
        assert_eq!(last_digit_unit("16"), 1.0);
        assert_eq!(last_digit_unit("5.90"), 0.01);
        assert_eq!(last_digit_unit("2e4"), 1e4);
        assert!((last_digit_unit("3.33e4") - 100.0).abs() < 1e-9);
        // "2 %" and "2e4" are both one significant digit: the same 25 %
        assert_eq!(relative_tolerance("2", false), Some(0.25));
        assert_eq!(relative_tolerance("2e4", true), Some(0.25));
        // the floors
        assert_eq!(relative_tolerance("125", false), Some(MIN_REL_TOLERANCE));
        assert_eq!(relative_tolerance("19", true), Some(APPROXIMATE_REL_TOLERANCE));
        assert_eq!(relative_tolerance("0", true), None);
        assert_eq!(relative_tolerance("", true), None);
    }

    #[test]
    fn about_is_read_one_way() {
        let (lo, hi) = about_band("20").unwrap();
        assert!((lo - 18.0).abs() < 1e-12 && (hi - 22.0).abs() < 1e-12);
        // at least 10 %, or the half unit of the last digit where that is wider ("about 2": 1.5-2.5)
        let (lo, hi) = about_band("5").unwrap();
        assert!((lo - 4.5).abs() < 1e-12 && (hi - 5.5).abs() < 1e-12);
        let (lo, hi) = about_band("2").unwrap();
        assert!((lo - 1.5).abs() < 1e-12 && (hi - 2.5).abs() < 1e-12);
        assert!(is_approximate("typically about 125 Hz (period T = 8 ms)"));
        assert!(is_approximate("reduced almost to zero"));
        assert!(is_approximate("the peak is ~ 1710 N"));
        assert!(!is_approximate("e_A = 0.44 for the softer strings"));
        // a word, not a part of one
        assert!(!is_approximate("throughout the range"));
    }
}
