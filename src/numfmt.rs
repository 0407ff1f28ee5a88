//! How numbers are written, in one place at the bottom of the house (it imports nothing of the
//! crate, so every layer, the error type included, may use it):
//!
//! - in messages: [`sig`] (rounded to some significant digits), [`readable`] (exact), and
//!   [`shown`] (a value given as text, as an error message shows it), with [`quoted`] (any text
//!   from the user's input, escaped and capped);
//! - in tables, CSV files, plots and the report: [`fmt_sig`] (C's `%g` without trailing zeros);
//! - in the exact columns of a sweep and of the uncertainty table: [`exact`] and
//!   [`exact_finite`] (the shortest text that reads back as the same `f64`);
//! - a count in prose: [`in_words`] ("four mechanisms", counted, never typed).

/// The digits a value in an error message is shown to ([`shown`]): enough to tell a refused
/// value from the bound beside it, not the binary noise of a computed one
/// (`0.30000000000000004`).
pub const MESSAGE_DIGITS: usize = 12;

/// `v` rounded to `digits` significant digits, in its shortest form (`36666.7`, `0.16`,
/// `1e30`: see [`readable`]).
pub fn sig(v: f64, digits: usize) -> String {
    let rounded: f64 = format!("{:.*e}", digits.saturating_sub(1), v).parse().unwrap_or(v);
    readable(rounded)
}

/// `v` as a message shows a value that was given: to `digits` significant digits, or to as
/// many more (at most [`MESSAGE_DIGITS`]) as it takes to show it exactly where that is possible
/// (`1.000001`, not `1`, which reads as another value; a computed `36666.666...` to `digits`).
pub fn given(v: f64, digits: usize) -> String {
    (digits.max(1)..=MESSAGE_DIGITS)
        .map(|d| sig(v, d))
        .find(|text| text.parse::<f64>() == Ok(v))
        .unwrap_or_else(|| sig(v, digits))
}

/// `v` as a message shows it: the shortest form that reads back as `v`, plain (`0.16`,
/// `40000`) or, where the plain form would run to many zeros (`|v| >= 1e7` or `|v| < 1e-4`),
/// with an exponent (`1e30`, not 31 digits; `1.5e-7`).
pub fn readable(v: f64) -> String {
    if v.is_finite() && v != 0.0 && (v.abs() >= 1e7 || v.abs() < 1e-4) {
        format!("{v:e}")
    } else {
        v.to_string()
    }
}

/// A value as a message shows it: a number to [`MESSAGE_DIGITS`] significant digits (`2.1`,
/// not `2.0999999999999996`; an integer of up to 15 digits, a count, exactly as it is), any
/// other text as it is.
pub fn shown(text: &str) -> String {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && (text.contains('.') || text.len() > 15) => sig(v, MESSAGE_DIGITS),
        _ => quoted(text),
    }
}

/// The most characters of a text a message quotes ([`quoted`]): a parameter's value, a CSV cell,
/// a name; room for any real one, where an 8 MiB cell echoed whole made 8 MB of standard error.
pub const QUOTED_CHARS: usize = 80;

/// Text from the user's input as a message quotes it: every control character escaped as Rust
/// writes it (a NUL byte as `\u{0}`, a tab as `\t`: never raw on a terminal), and no more than
/// [`QUOTED_CHARS`] characters, the rest said by its count (`LLL... (8388528 more characters)`).
pub fn quoted(text: &str) -> String {
    quoted_up_to(text, QUOTED_CHARS)
}

/// [`quoted`] with at most `max` characters: for a message of a library below that may quote a
/// cell in it (a CSV reader's reason).
pub fn quoted_up_to(text: &str, max: usize) -> String {
    let mut out = String::new();
    let mut chars = text.chars();
    for c in chars.by_ref().take(max) {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    let rest = chars.count();
    if rest > 0 {
        out.push_str(&format!("... ({rest} more character{})", if rest == 1 { "" } else { "s" }));
    }
    out
}

/// Seconds in words: "0.05 s", "42 s", "27 min", "3.1 h".
pub fn duration(s: f64) -> String {
    if s < 1.0 {
        format!("{} s", sig(s, 2))
    } else if s < 120.0 {
        format!("{s:.0} s")
    } else if s < 7200.0 {
        format!("{:.0} min", s / 60.0)
    } else {
        format!("{} h", sig(s / 3600.0, 2))
    }
}

/// Format `x` with `digits` significant digits, like C's `%.{digits}g` with trailing zeros
/// removed.
///
/// * `0` and `-0` give `"0"`, NaN gives `"NaN"`, infinities give `"inf"` / `"-inf"`.
/// * Plain decimal notation when the decimal exponent of the rounded value is in
///   `[-4, digits)`, e.g. `0.000123457`, `12.5`, `10`.
/// * Scientific notation otherwise, e.g. `1.23457e-05`, `1e+06`: trimmed mantissa, signed
///   exponent with at least two digits.
///
/// Rounding is done once, correctly (round-half-even on the exact binary value), by Rust's
/// `{:e}` formatting. `digits = 0` is treated as 1.
pub fn fmt_sig(x: f64, digits: usize) -> String {
    if x.is_nan() {
        return "NaN".to_string();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.max(1);
    // Correctly rounded mantissa and exponent, e.g. "-1.23457e-5".
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exp) = match sci.split_once('e') {
        Some(parts) => parts,
        None => return sci, // unreachable: `{:e}` always has an exponent
    };
    let exp: i64 = match exp.parse() {
        Ok(e) => e,
        Err(_) => return sci, // unreachable
    };
    let negative = mantissa.starts_with('-');
    let sign = if negative { "-" } else { "" };
    // All significant digits, without sign or point: exactly `digits` of them.
    let sig: String = mantissa.chars().filter(char::is_ascii_digit).collect();

    if exp < -4 || exp >= digits as i64 {
        let (first, rest) = sig.split_at(1);
        let rest = rest.trim_end_matches('0');
        let exp_sign = if exp < 0 { '-' } else { '+' };
        if rest.is_empty() {
            format!("{sign}{first}e{exp_sign}{:02}", exp.unsigned_abs())
        } else {
            format!("{sign}{first}.{rest}e{exp_sign}{:02}", exp.unsigned_abs())
        }
    } else if exp >= 0 {
        // 0 <= exp < digits, so the integer part takes exp + 1 <= digits digits.
        let split = (exp as usize + 1).min(sig.len());
        let (int_part, frac) = sig.split_at(split);
        let frac = frac.trim_end_matches('0');
        if frac.is_empty() {
            format!("{sign}{int_part}")
        } else {
            format!("{sign}{int_part}.{frac}")
        }
    } else {
        // -4 <= exp <= -1: leading zeros after the point.
        let zeros = "0".repeat((-exp - 1) as usize);
        let frac = sig.trim_end_matches('0');
        format!("{sign}0.{zeros}{frac}")
    }
}

/// `v` to at least `digits` significant digits, and to as many more as it takes for the
/// printed number to fall on the same side of each of `bounds` as `v` itself (at most 12):
/// a value printed beside a tolerance shows the digit that decides it (4.80415 beside a bound of
/// 4.8039 prints as `4.804`, not `4.8`, which reads as inside).
pub fn decisive(v: f64, bounds: &[f64], digits: usize) -> String {
    let side = |x: f64, b: f64| x.partial_cmp(&b);
    (digits.max(1)..=12)
        .map(|d| fmt_sig(v, d))
        .find(|text| {
            text.parse::<f64>()
                .is_ok_and(|shown| bounds.iter().all(|&b| !b.is_finite() || side(shown, b) == side(v, b)))
        })
        .unwrap_or_else(|| fmt_sig(v, 12))
}

/// A number in its shortest exact form (`ryu`: `0.25`, `1.5e-7`, `3.0`, reading back as the same
/// `f64`), zero of either sign as "0" as in the other tables; an undefined one (NaN: `e_t` at too
/// little incoming slip) as an empty field. A sweep's columns.
pub fn exact(v: f64) -> String {
    if v.is_nan() {
        String::new()
    } else if v == 0.0 {
        "0".to_string()
    } else {
        ryu::Buffer::new().format(v).to_string()
    }
}

/// A finite number in its shortest exact form as `ryu` writes it (zero as `0.0`), a non-finite
/// one (an undefined index) as an empty field. The uncertainty table's columns.
pub fn exact_finite(v: f64) -> String {
    if v.is_finite() {
        ryu::Buffer::new().format(v).to_string()
    } else {
        String::new()
    }
}

/// A count as prose writes it: in words up to twelve (`four`), in digits above.
pub fn in_words(n: usize) -> String {
    const WORDS: [&str; 13] =
        ["no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve"];
    WORDS.get(n).map_or_else(|| n.to_string(), |w| w.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_text_is_escaped_and_capped_with_the_count_cut() {
        assert_eq!(quoted("free"), "free");
        assert_eq!(quoted("fr\0ee\tx\n"), "fr\\u{0}ee\\tx\\n");
        let long = "L".repeat(8 << 20);
        let q = quoted(&long);
        assert_eq!(q, format!("{}... ({} more characters)", "L".repeat(QUOTED_CHARS), (8 << 20) - QUOTED_CHARS));
        // characters, not bytes: a multi-byte text is cut between characters
        let wide = "é".repeat(QUOTED_CHARS + 1);
        assert_eq!(quoted(&wide), format!("{}... (1 more character)", "é".repeat(QUOTED_CHARS)));
        assert_eq!(quoted(&"x".repeat(QUOTED_CHARS)), "x".repeat(QUOTED_CHARS));
        // a value given as text goes through it; a number is shown as a number
        assert_eq!(shown("a\u{0}b"), "a\\u{0}b");
        assert_eq!(shown("0.30000000000000004"), "0.3");
    }

    #[test]
    fn counts_in_words_up_to_twelve_then_digits() {
        assert_eq!([in_words(0), in_words(4), in_words(12), in_words(13)], ["no", "four", "twelve", "13"]);
    }

    #[test]
    fn messages_round_then_write_the_shortest_form() {
        assert_eq!(sig(36666.666, 6), "36666.7");
        assert_eq!(sig(0.16, 6), "0.16");
        assert_eq!(sig(1e30, 6), "1e30");
        assert_eq!(sig(1.5e-7, 3), "1.5e-7");
        assert_eq!(readable(40000.0), "40000");
        assert_eq!(readable(1e7), "1e7");
        assert_eq!(shown("2.0999999999999996"), "2.1");
        assert_eq!(shown("123456789012345"), "123456789012345");
        assert_eq!(shown("hat"), "hat");
    }

    #[test]
    fn exact_forms_read_back_as_the_same_number() {
        for v in [0.25, 1.5e-7, 3.0, 0.1 + 0.2, -2.5e30] {
            assert_eq!(exact(v).parse::<f64>().unwrap(), v);
            assert_eq!(exact_finite(v).parse::<f64>().unwrap(), v);
        }
        assert_eq!((exact(0.0).as_str(), exact(-0.0).as_str(), exact(f64::NAN).as_str()), ("0", "0", ""));
        assert_eq!((exact_finite(0.0).as_str(), exact_finite(f64::INFINITY).as_str()), ("0.0", ""));
    }

    #[test]
    fn fmt_sig_special_values() {
        assert_eq!(fmt_sig(0.0, 6), "0");
        assert_eq!(fmt_sig(-0.0, 6), "0");
        assert_eq!(fmt_sig(f64::NAN, 6), "NaN");
        assert_eq!(fmt_sig(f64::INFINITY, 6), "inf");
        assert_eq!(fmt_sig(f64::NEG_INFINITY, 6), "-inf");
    }

    #[test]
    fn fmt_sig_plain_decimal() {
        assert_eq!(fmt_sig(1.0, 6), "1");
        assert_eq!(fmt_sig(-1.0, 6), "-1");
        assert_eq!(fmt_sig(0.5, 6), "0.5");
        assert_eq!(fmt_sig(12.5, 6), "12.5");
        assert_eq!(fmt_sig(std::f64::consts::PI, 6), "3.14159");
        assert_eq!(fmt_sig(-std::f64::consts::E, 6), "-2.71828");
        assert_eq!(fmt_sig(123456.0, 6), "123456");
        assert_eq!(fmt_sig(123456.4, 6), "123456");
        assert_eq!(fmt_sig(100.0, 6), "100");
        assert_eq!(fmt_sig(0.1 + 0.2, 6), "0.3");
        assert_eq!(fmt_sig(0.0001, 6), "0.0001");
        assert_eq!(fmt_sig(0.000123456789, 6), "0.000123457");
        assert_eq!(fmt_sig(-0.000123456789, 6), "-0.000123457");
        assert_eq!(fmt_sig(0.001, 3), "0.001");
    }

    #[test]
    fn fmt_sig_scientific() {
        assert_eq!(fmt_sig(1234567.0, 6), "1.23457e+06");
        assert_eq!(fmt_sig(1e6, 6), "1e+06");
        assert_eq!(fmt_sig(-1e6, 6), "-1e+06");
        assert_eq!(fmt_sig(0.0000123456789, 6), "1.23457e-05");
        assert_eq!(fmt_sig(0.00001, 6), "1e-05");
        assert_eq!(fmt_sig(6.02214076e23, 6), "6.02214e+23");
        assert_eq!(fmt_sig(1.5e-300, 6), "1.5e-300");
        assert_eq!(fmt_sig(f64::MAX, 6), "1.79769e+308");
        assert_eq!(fmt_sig(f64::MIN_POSITIVE, 6), "2.22507e-308");
        assert_eq!(fmt_sig(5e-324, 6), "4.94066e-324");
        assert_eq!(fmt_sig(1e100, 6), "1e+100");
    }

    #[test]
    fn fmt_sig_rounding_boundaries() {
        assert_eq!(fmt_sig(9.9999996, 6), "10");
        assert_eq!(fmt_sig(-9.9999996, 6), "-10");
        assert_eq!(fmt_sig(99999.95, 6), "99999.9"); // 99999.95 is below .95 in binary
        assert_eq!(fmt_sig(999999.6, 6), "1e+06"); // rounds up into scientific range
        assert_eq!(fmt_sig(999999.4, 6), "999999");
        assert_eq!(fmt_sig(0.000099999996, 6), "0.0001"); // rounds up into decimal range
        assert_eq!(fmt_sig(0.0000999999, 6), "9.99999e-05");
        assert_eq!(fmt_sig(1.0000004, 6), "1");
        assert_eq!(fmt_sig(1.000004, 6), "1");
        assert_eq!(fmt_sig(1.000006, 6), "1.00001");
        assert_eq!(fmt_sig(0.30000000000000004, 17), "0.30000000000000004");
    }

    #[test]
    fn fmt_sig_other_digit_counts() {
        assert_eq!(fmt_sig(3.25, 1), "3");
        assert_eq!(fmt_sig(3.25, 0), "3");
        assert_eq!(fmt_sig(15.0, 1), "2e+01");
        assert_eq!(fmt_sig(1234.5, 3), "1.23e+03");
        assert_eq!(fmt_sig(123.0, 3), "123");
        assert_eq!(fmt_sig(0.5, 3), "0.5");
    }

    #[test]
    fn fmt_sig_matches_round_trip_for_many_values() {
        // Parsing the output must give the value rounded to 6 significant digits.
        for &x in &[1.2345678e-7, 2.5e-3, 7.77777777, 42.0, 1.0 / 3.0, 2.0 / 3.0 * 1e9] {
            let s = fmt_sig(x, 6);
            let back: f64 = s.parse().expect("parse");
            let expect: f64 = format!("{x:.5e}").parse().expect("parse");
            assert_eq!(back, expect, "{x} -> {s}");
        }
    }

    #[test]
    fn a_given_value_shows_every_digit_it_was_given_with() {
        // `--p 1.000001` once warned "p = 1 is outside the usual range"
        assert_eq!(given(1.000001, 6), "1.000001");
        assert_eq!(given(4e4 * 55.0 / 60.0, 6), "36666.7");
        assert_eq!(given(0.057, 6), "0.057");
    }

    #[test]
    fn a_value_beside_a_bound_shows_the_digit_that_decides() {
        // 4.80415 is outside 4.78 +- 0.5 % (up to 4.8039): three digits would print 4.8 (inside)
        assert_eq!(decisive(4.80415, &[4.7561, 4.8039], 3), "4.804");
        assert_eq!(decisive(4.80385, &[4.7561, 4.8039], 3), "4.8", "inside, and so is 4.8");
        assert_eq!(decisive(0.4427, &[0.435, 0.445], 4), "0.4427");
        assert_eq!(decisive(0.44499999, &[0.435, 0.445], 4), "0.44499999");
        // no bound: the digits asked for
        assert_eq!(decisive(1.23456, &[], 3), "1.23");
    }
}
