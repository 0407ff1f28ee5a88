//! The range grammar of a sweep: a spec is one value (`0.1`), a list (`2e4,4e4`; `node,hat` for
//! the load rule), a linear range `start:stop:count` (both ends included) or a log range
//! `start:stop:count:log`, expanded into one [`Axis`] of values.

use crate::error::{Error, Result};
use crate::params::number::parse_number;
use crate::params::spec::Values;
use crate::params::{keys, limits, Overrides};

/// One varied parameter and its values (as text, parsed like a flag).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// The parameter key (`x`, `ks`, ...).
    pub key: String,
    /// Its values.
    pub values: Vec<String>,
}

impl Axis {
    /// The values that bound the axis: the least and the greatest of a numeric axis (a range
    /// may hold a million values; every one lies between these), every value of any other.
    pub fn extremes(&self) -> Vec<&String> {
        let numbers: Option<Vec<f64>> = self.values.iter().map(|v| v.trim().parse::<f64>().ok()).collect();
        match numbers {
            Some(xs) if xs.len() > 2 => {
                let lo = (0..xs.len()).min_by(|&i, &j| xs[i].total_cmp(&xs[j])).unwrap_or(0);
                let hi = (0..xs.len()).max_by(|&i, &j| xs[i].total_cmp(&xs[j])).unwrap_or(0);
                vec![&self.values[lo], &self.values[hi]]
            }
            _ => self.values.iter().collect(),
        }
    }
}

/// Expand a spec into values.
pub fn parse_spec(key: &str, spec: &str) -> Result<Axis> {
    let bad = |why: &str| Error::invalid("sweep", format!("--{key} {spec}"), why);
    // a count (the segments) takes whole values
    let whole = keys::find(key).is_some_and(|s| matches!(s.values, Values::Count));
    let values = if spec.contains(':') {
        let parts: Vec<&str> = spec.split(':').collect();
        let log = match parts.len() {
            3 => false,
            4 if parts[3] == "log" => true,
            _ => return Err(bad("a range is start:stop:count or start:stop:count:log")),
        };
        // (read as a flag's value is: a number too small or too large for an f64 is refused as
        // written, not taken as 0 or inf)
        let number = |text: &str, what: &str| parse_number(text).map_err(|why| bad(&format!("{what} {why}")));
        let a = number(parts[0], "start")?;
        let b = number(parts[1], "stop")?;
        // (a count reads as digits or as a whole number in exponent form: 50, 1e3)
        let count = number(parts[2], "count")?;
        if !(count.is_finite() && count >= 1.0 && count.fract() == 0.0) {
            return Err(bad("count must be a whole number >= 1 (as 50 or 1e3)"));
        }
        // counted before any value is made
        limits::check_count("sweep", count, limits::MAX_AXIS_VALUES, &format!("the count of --{key}"))?;
        let n = count as u64;
        if !a.is_finite() || !b.is_finite() {
            return Err(bad("the ends must be finite"));
        }
        if log && (a <= 0.0 || b <= 0.0) {
            return Err(bad("a log range needs positive ends"));
        }
        // a range says its ends: one value only where they are one, both where they differ
        if n == 1 && a != b {
            return Err(bad("a count of 1 gives the start only and ignores the stop: give one value, or a count >= 2"));
        }
        if n > 1 && a == b {
            return Err(bad("the ends are equal, so every value is the same: give the value once"));
        }
        (0..n)
            .map(|i| {
                let f = if n == 1 { 0.0 } else { i as f64 / (n - 1) as f64 };
                let v = if log { 10f64.powf(a.log10() + f * (b.log10() - a.log10())) } else { a + f * (b - a) };
                if whole {
                    format!("{}", v.round())
                } else {
                    format!("{v}")
                }
            })
            .collect()
    } else {
        spec.split(',').map(|s| s.trim().to_string()).collect::<Vec<_>>()
    };
    if values.iter().any(String::is_empty) {
        return Err(bad("empty value"));
    }
    // parse once now so a typo fails before any impact is run
    let mut probe = Overrides::default();
    for v in &values {
        probe.set(key, v)?;
    }
    // every value runs once: a value given twice (a list, or a range whose rounding to whole
    // segments repeats values) would run the same impacts twice
    if let Some(twice) = repeated(&values) {
        let why = if whole && spec.contains(':') {
            let distinct = distinct_count(&values);
            format!("rounded to whole segments the range repeats {twice}: it has {distinct} different values, so give a count of at most {distinct}")
        } else {
            format!("{twice} is given twice: each value runs once")
        };
        return Err(bad(&why));
    }
    Ok(Axis { key: key.to_string(), values })
}

/// The values as sort keys: numbers by value (`0.1` and `1e-1` are one), names as written.
fn keys_of(values: &[String]) -> Vec<(f64, &str)> {
    let mut keys: Vec<(f64, &str)> = values
        .iter()
        .map(|v| match v.trim().parse::<f64>() {
            Ok(x) => (x, ""),
            Err(_) => (f64::NAN, v.trim()),
        })
        .collect();
    keys.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(b.1)));
    keys
}

/// One value (names carry a NaN number, which equals itself here).
fn same(a: (f64, &str), b: (f64, &str)) -> bool {
    a.0.total_cmp(&b.0).is_eq() && a.1 == b.1
}

/// A value of `values` that another repeats (sorted first: a range may hold a million).
fn repeated(values: &[String]) -> Option<String> {
    let keys = keys_of(values);
    keys.windows(2).find(|w| same(w[0], w[1])).map(|w| {
        if w[0].1.is_empty() {
            crate::numfmt::sig(w[0].0, 12)
        } else {
            w[0].1.to_string()
        }
    })
}

/// How many different values `values` holds.
fn distinct_count(values: &[String]) -> usize {
    let keys = keys_of(values);
    1 + keys.windows(2).filter(|w| !same(w[0], w[1])).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn specs_expand_to_lists_and_ranges() {
        assert_eq!(parse_spec("ks", "2e4,4e4").unwrap().values, vec!["2e4", "4e4"]);
        assert_eq!(parse_spec("x", "0.1:0.3:3").unwrap().values, vec!["0.1", "0.2", "0.3"]);
        assert_eq!(parse_spec("ks", "1e3:1e5:3:log").unwrap().values, vec!["1000", "10000", "100000"]);
        assert_eq!(parse_spec("load", "node,hat").unwrap().values.len(), 2);
        assert!(parse_spec("ks", "1:2").is_err());
        assert!(parse_spec("ks", "a,b").is_err());
        assert!(parse_spec("nope", "1").is_err());
        assert!(parse_spec("ks", "0:1:3:log").is_err());
        // a count in exponent form is the same count; a fractional or zero one is refused
        assert_eq!(parse_spec("x", "0.1:0.3:3e0").unwrap().values, parse_spec("x", "0.1:0.3:3").unwrap().values);
        assert_eq!(parse_spec("x", "0:1:1e3").unwrap().values.len(), 1000);
        for bad in ["0.1:0.3:2.5", "0.1:0.3:0", "0.1:0.3:-3", "0.1:0.3:nan", "0.1:0.3:inf"] {
            assert!(parse_spec("x", bad).is_err(), "{bad}");
        }
        // an end too small or too large for an f64 is refused as a plain value is, not run as 0
        let msg = parse_spec("x", "1e-400:0.2:3").unwrap_err().to_string();
        assert!(msg.contains("start is too small to represent"), "{msg}");
        let msg = parse_spec("ks", "1e3:1e400:3:log").unwrap_err().to_string();
        assert!(msg.contains("stop is too large to represent"), "{msg}");
        assert!(parse_spec("x", "0.1:0.3:1e-400").unwrap_err().to_string().contains("count is too small"));
    }
}
