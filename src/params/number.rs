//! How a number written on the command line or in a file is read: every number option, flag,
//! config value, sweep range and drawn distribution reads through [`parse_number`].

/// A number as written on the command line or in a file: refused (with the reason) where it
/// is not a number, or where it does not fit an f64 (`1e-400`, `1e400`: named as written, not
/// as the 0 or inf it rounds to). Every number option reads through this.
pub fn parse_number(text: &str) -> std::result::Result<f64, &'static str> {
    let t = text.trim();
    let v = t.parse::<f64>().map_err(|_| "must be a number")?;
    let mantissa = t.trim_start_matches(['+', '-']).split(['e', 'E']).next().unwrap_or("");
    let written_finite = mantissa.chars().all(|c| c.is_ascii_digit() || c == '.');
    if v == 0.0 && written_finite && mantissa.chars().any(|c| ('1'..='9').contains(&c)) {
        return Err("is too small to represent as a number (below about 1e-308)");
    }
    if v.is_infinite() && written_finite {
        return Err("is too large to represent as a number (above about 1.8e308)");
    }
    Ok(v)
}
