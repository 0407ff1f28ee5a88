//! Cubic Hermite interpolation within one time step: the explicit solver places the maximum
//! compression there, and both time-stepping solvers the separation and the twist angle, from
//! the values and rates at the step's ends (the modal solver finds maximum compression in
//! closed form).

use crate::numeric::root::{bisect, Bracket};

/// A quantity over one step of length `h` as the cubic Hermite polynomial through its values
/// `p0, p1` and rates (per unit time) `m0, m1` at the step's ends.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Hermite {
    /// The step's length.
    pub h: f64,
    /// Value and rate at the start.
    pub p0: f64,
    pub m0: f64,
    /// Value and rate at the end.
    pub p1: f64,
    pub m1: f64,
}

impl Hermite {
    /// The value at the fraction `s` of the step.
    pub fn eval(&self, s: f64) -> f64 {
        let Hermite { h, p0, m0, p1, m1 } = *self;
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * p0
            + (s3 - 2.0 * s2 + s) * h * m0
            + (-2.0 * s3 + 3.0 * s2) * p1
            + (s3 - s2) * h * m1
    }

    /// The rate (per unit time) at the fraction `s` of the step.
    fn slope(&self, s: f64) -> f64 {
        let Hermite { h, p0, m0, p1, m1 } = *self;
        let s2 = s * s;
        ((6.0 * s2 - 6.0 * s) * p0
            + (3.0 * s2 - 4.0 * s + 1.0) * h * m0
            + (6.0 * s - 6.0 * s2) * p1
            + (3.0 * s2 - 2.0 * s) * h * m1)
            / h
    }

    /// The maximum in a step where the slope goes from > 0 to <= 0: (fraction of the step,
    /// value).
    pub fn max(&self) -> (f64, f64) {
        // the slope's fall through zero (zero counts as past), by bisection from the whole step
        // (60 halvings: to rounding where the maximum is beyond 1/256 of the step)
        let s = bisect(|s| self.slope(s) > 0.0, 0.0, 1.0, 60).mid();
        let v = self.eval(s);
        (s, v.max(self.p0).max(self.p1))
    }

    /// The zero in a step where the value goes from > 0 to <= 0 (fraction of the step): Newton's
    /// method kept inside the bracket (bisection where a step would leave it), to rounding level.
    pub fn root(&self) -> f64 {
        let (p0, p1, h) = (self.p0, self.p1, self.h);
        let mut bracket = Bracket::new(0.0, 1.0);
        // the secant's zero first
        let mut s = if p0 > p1 { p0 / (p0 - p1) } else { 0.5 };
        for _ in 0..100 {
            let v = self.eval(s);
            bracket.narrow(s, v > 0.0);
            let slope = self.slope(s) * h;
            let newton = s - v / slope;
            if newton == s {
                // the Newton step is below rounding: `s` is the root
                return s;
            }
            let next = bracket.inside_or_mid(newton);
            if (next - s).abs() <= 2.0 * f64::EPSILON || bracket.hi - bracket.lo <= 2.0 * f64::EPSILON {
                return next;
            }
            s = next;
        }
        bracket.mid()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn hermite_is_exact_for_cubics() {
        let f = |t: f64| 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t * t * t;
        let df = |t: f64| 2.0 - 6.0 * t + 1.5 * t * t;
        let (a, h) = (0.2, 0.7);
        let cubic = Hermite { h, p0: f(a), m0: df(a), p1: f(a + h), m1: df(a + h) };
        for &s in &[0.0, 0.3, 0.8, 1.0] {
            assert_relative_eq!(cubic.eval(s), f(a + s * h), epsilon = 1e-13);
            assert_relative_eq!(cubic.slope(s), df(a + s * h), epsilon = 1e-12);
        }
    }

    #[test]
    fn roots_and_maxima_of_cubics_are_found_to_rounding() {
        // (t - r)(t + 1)(t - 3) falls through zero at r in [0, 1] (a cubic: the interpolant is exact)
        let h = 1.0;
        for r in [1e-6, 0.013, 0.5, 0.77, 0.999_999] {
            let f = |t: f64| (t - r) * (t + 1.0) * (t - 3.0);
            let df = |t: f64| (t + 1.0) * (t - 3.0) + (t - r) * (t - 3.0) + (t - r) * (t + 1.0);
            let s = Hermite { h, p0: f(0.0), m0: df(0.0), p1: f(1.0), m1: df(1.0) }.root();
            assert!((s - r).abs() <= 4.0 * f64::EPSILON, "root {r}: {s}");
        }
        // a double root at the end (a contact that fades out tangentially): found to where the
        // cubic is below rounding
        let s = Hermite { h: 1.0, p0: 0.3 * 0.2, m0: 0.3 * (1.0 - 0.4), p1: 0.0, m1: 0.0 }.root();
        assert!((s - 1.0).abs() <= 1e-7, "{s}");
        // the maximum of t (1 - t): at 1/2, 1/4
        let (sm, vm) = Hermite { h: 1.0, p0: 0.0, m0: 1.0, p1: 0.0, m1: -1.0 }.max();
        assert_relative_eq!(sm, 0.5, epsilon = 1e-12);
        assert_relative_eq!(vm, 0.25, epsilon = 1e-12);
    }
}
