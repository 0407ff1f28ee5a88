//! The compared values of `validation_spin` and their summaries: one [`Compared`] per measured
//! value, the ratio of spins that is undefined over a near-zero denominator, and the summary
//! rows (RMS and worst error, the rank correlation and its p-value).

use crate::render::table::Value;
use crate::study::stats::{rank_correlation_p, rms, spearman};

/// The smallest model spin, rpm, a ratio of spins is formed over: a tenth of the smallest
/// measured table spin (1207 rpm, M013). Below it the ratio is undefined (NaN).
pub const RATIO_FLOOR_RPM: f64 = 120.0;

/// `num / den`, or NaN when `|den|` is below [`RATIO_FLOOR_RPM`].
pub fn spin_ratio(num: f64, den: f64) -> f64 {
    if den.abs() < RATIO_FLOOR_RPM {
        f64::NAN
    } else {
        num / den
    }
}

/// The mean of `values` (NaN for none).
pub fn mean(values: &[f64]) -> f64 {
    if values.is_empty() {
        f64::NAN
    } else {
        values.iter().sum::<f64>() / values.len() as f64
    }
}

/// One compared value: quantity, string, tension, measured, unit, spread, source rows, role,
/// the default law's held-out prediction, the validation uncertainty's parts, and the model
/// under each law.
#[derive(Debug, Clone)]
pub struct Compared {
    /// What is compared (`spin_out_rpm`).
    pub quantity: &'static str,
    /// The string (or what stands for it).
    pub string: String,
    /// The tension, lb (or a text).
    pub tension: Value,
    /// The measured value.
    pub measured: f64,
    /// Its unit.
    pub unit: &'static str,
    /// The measured spread (low, high).
    pub spread: (f64, f64),
    /// The rows it comes from.
    pub source: String,
    /// `calibration` or `validation` (the row's role in data/measured).
    pub role: &'static str,
    /// The default law's value fitted without the row's string (calibration rows), else NaN.
    pub held_out: f64,
    /// The validation uncertainty's parts (V&V 20): inputs, numerics, the lab's scatter, the
    /// reading of the angle; NaN where not computed.
    pub u: [f64; 4],
    /// The model under each law (in the order of [`super::LAWS`]).
    pub model: Vec<f64>,
}

impl Compared {
    /// The validation uncertainty `sqrt(sum u_i^2)` over its computed parts (NaN if none).
    pub fn u_val(&self) -> f64 {
        let parts: Vec<f64> = self.u.iter().copied().filter(|v| v.is_finite()).collect();
        if parts.is_empty() {
            f64::NAN
        } else {
            parts.iter().map(|v| v * v).sum::<f64>().sqrt()
        }
    }
}

/// The RMS error of law `l` over the values of `of` it defines (a ratio over a near-zero spin
/// is not one).
pub fn rms_error(of: &[&Compared], l: usize) -> f64 {
    rms(of.iter().map(|c| c.model[l] - c.measured))
}

/// The largest error by size of law `l` over the values of `of` it defines (NaN if none).
pub fn worst_error(of: &[&Compared], l: usize) -> f64 {
    let e: Vec<f64> = of.iter().map(|c| c.model[l] - c.measured).filter(|e| e.is_finite()).collect();
    if e.is_empty() {
        f64::NAN
    } else {
        e.into_iter().fold(0.0f64, |w, e| if e.abs() > w.abs() { e } else { w })
    }
}

/// Spearman's rank correlation of law `l` with the measured values of `of`, and its two-sided
/// p-value.
pub fn rank(of: &[&Compared], l: usize) -> (f64, f64) {
    let measured: Vec<f64> = of.iter().map(|c| c.measured).collect();
    let model: Vec<f64> = of.iter().map(|c| c.model[l]).collect();
    let rho = spearman(&measured, &model);
    (rho, rank_correlation_p(rho, of.len()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ratio_over_a_near_zero_spin_is_undefined() {
        assert!(spin_ratio(1000.0, RATIO_FLOOR_RPM * 0.99).is_nan());
        assert_eq!(spin_ratio(1000.0, 2000.0), 0.5);
        assert_eq!(spin_ratio(1000.0, -2000.0), -0.5);
    }
}
