//! The most work a command accepts from its input, declared once: every count a user's input
//! sizes (sweep ranges and their product, time-series rows, compared variants, map grids,
//! modes) is checked against its limit here, before anything is allocated or run.

use crate::error::{Error, Result};

/// Impacts in one sweep (the product of its ranges and lists): minutes of work and a CSV of
/// a few gigabytes at most.
pub const MAX_SWEEP_POINTS: u64 = 10_000_000;
/// Values of one swept parameter (a range's count).
pub const MAX_AXIS_VALUES: u64 = 1_000_000;
/// Rows of one impact's time series (`simulate --series`): about 200 MB of CSV.
pub const MAX_SERIES_ROWS: u64 = 1_000_000;
/// Variants compared in one `speed` run (tensions or rackets).
pub const MAX_COMPARED: usize = 50;
/// Bytes of one config or racket file: a few hundred keys at most, so 1 MiB is far beyond any
/// real one, and `--config /dev/zero` (or a file of gigabytes) is refused instead of read.
pub const MAX_INPUT_FILE_BYTES: u64 = 1 << 20;
/// Bytes of one measurements CSV (`calibrate`): a row is about 100 bytes, so 64 MiB is over half
/// a million rows, far beyond any lab's table, and `calibrate /dev/zero` is refused instead of
/// read until memory runs out.
pub const MAX_MEASUREMENTS_BYTES: u64 = 64 << 20;

/// Refuse a count `n` (given as a float, so that an overflowing product is caught too) above
/// `max`, as an invalid value of `field`: "`what` must be at most `max`".
pub fn check_count(field: &'static str, n: f64, max: u64, what: &str) -> Result<()> {
    if n.is_finite() && n <= max as f64 {
        Ok(())
    } else {
        Err(Error::invalid(field, n, format!("{what} must be at most {max}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_above_the_limit_or_not_finite_are_refused_with_the_limit() {
        assert!(check_count("sweep", 1e7, MAX_SWEEP_POINTS, "impacts").is_ok());
        let msg = check_count("sweep", 1e9, MAX_SWEEP_POINTS, "the impacts of a sweep").unwrap_err().to_string();
        assert_eq!(msg, "invalid sweep = 1000000000: the impacts of a sweep must be at most 10000000");
        assert!(check_count("x", f64::INFINITY, 10, "values").is_err());
    }
}
