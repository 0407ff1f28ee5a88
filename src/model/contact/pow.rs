//! Powers of nearby points without a power function: the ball law's `u^p` carried from one
//! Newton iterate (or one time step) to the next by the binomial series.

/// Terms of the binomial series for the power of a nearby point.
const BINOMIAL_TERMS: usize = 17;

/// `(u (1 + delta))^p` from `u^p` by the binomial series: both solvers carry the ball law's power
/// from one Newton iterate (or one step) to the next with it instead of calling `powf`.
#[derive(Debug, Clone, Copy)]
pub struct PowSeries {
    /// The exponent `p`.
    pub(crate) p: f64,
    /// `C(p, n)`, the binomial coefficients of `(1 + x)^p`.
    binomial: [f64; BINOMIAL_TERMS],
}

impl PowSeries {
    /// The series for exponent `p`.
    pub fn new(p: f64) -> Self {
        let mut binomial = [1.0; BINOMIAL_TERMS];
        for n in 1..BINOMIAL_TERMS {
            binomial[n] = binomial[n - 1] * (p - (n - 1) as f64) / n as f64;
        }
        PowSeries { p, binomial }
    }

    /// `(u (1 + delta))^p` from `up = u^p`: the binomial series `sum C(p, n) delta^n`, cut where
    /// `|delta|^n` is below 1e-17 (times `C(p, n)`, at most 252 for `p <= 10`: still
    /// rounding-level; tested against `powf` for p from 1.0001 to 10), for `|delta| <= 0.1`
    /// (at most 17 terms), `powf` otherwise.
    #[inline]
    pub fn step(&self, u: f64, up: f64, delta: f64) -> f64 {
        let a = delta.abs();
        let terms = match a {
            _ if a <= 1e-9 => 2,
            _ if a <= 1e-6 => 3,
            _ if a <= 1e-4 => 5,
            _ if a <= 1e-3 => 6,
            _ if a <= 1e-2 => 9,
            _ if a <= 0.1 => BINOMIAL_TERMS,
            _ => return (u * (1.0 + delta)).powf(self.p),
        };
        let b = &self.binomial;
        let mut s = b[terms - 1];
        for k in (0..terms - 1).rev() {
            s = s * delta + b[k];
        }
        up * s
    }

    /// As [`PowSeries::advance`], but a long move's power by [`PowSeries::power_fast`] (the
    /// explicit solver keeps `powf`, so that its results do not move).
    #[inline]
    pub fn advance_fast(&self, u: f64, up: f64, delta: f64) -> (f64, f64) {
        if delta.abs() <= 0.1 {
            return self.advance(u, up, delta);
        }
        let x = u * (1.0 + delta);
        (x, self.power_fast(x))
    }

    /// `x^p` through the logarithm, `exp(p ln x)` (0 for `x <= 0`): a few times cheaper than
    /// `powf` and as accurate to a few units of rounding (the modal solver's choice).
    #[inline]
    pub fn power_fast(&self, x: f64) -> f64 {
        if x > 0.0 {
            (self.p * x.ln()).exp()
        } else {
            0.0
        }
    }

    /// The point `u (1 + delta)` and its power by [`PowSeries::step`]: a pair that stays
    /// consistent however far the move (the fallback's `powf` is of that same point).
    #[inline]
    pub fn advance(&self, u: f64, up: f64, delta: f64) -> (f64, f64) {
        (u * (1.0 + delta), self.step(u, up, delta))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn powers_from_the_binomial_series_match_powf() {
        for p in [1.0001, 1.3, 2.55, 4.0, 7.0, 10.0] {
            let series = PowSeries::new(p);
            let mut worst: f64 = 0.0;
            for u in [1e-6, 0.01, 0.37, 1.0] {
                for k in -2000..=2000 {
                    let delta = k as f64 * 5e-5 * 1.0000003;
                    let exact = (u * (1.0 + delta)).powf(p);
                    worst = worst.max((series.step(u, u.powf(p), delta) / exact - 1.0).abs());
                }
            }
            // rounding of u (1 + delta) alone moves its p-th power by p times 1.1e-16
            assert!(worst < 4e-16 * p.max(2.0), "p {p}: {worst:e}");
        }
    }
}
