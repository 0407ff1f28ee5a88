//! Cubic Hermite interpolation within one time step: the explicit solver places the maximum
//! compression there, and both time-stepping solvers the separation and the twist angle, from
//! the values and rates at the step's ends (the modal solver finds maximum compression in
//! closed form).

use crate::numeric::root::{bisect, Bracket};

/// Cubic Hermite interpolant on a step of length `h` with values `p0, p1` and derivatives
/// `m0, m1`, evaluated at the fraction `s` of the step.
pub(crate) fn hermite_eval(p0: f64, m0: f64, p1: f64, m1: f64, h: f64, s: f64) -> f64 {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * h * m0 + (-2.0 * s3 + 3.0 * s2) * p1 + (s3 - s2) * h * m1
}

/// Derivative (per unit time) of the Hermite interpolant.
fn hermite_slope(p0: f64, m0: f64, p1: f64, m1: f64, h: f64, s: f64) -> f64 {
    let s2 = s * s;
    ((6.0 * s2 - 6.0 * s) * p0
        + (3.0 * s2 - 4.0 * s + 1.0) * h * m0
        + (6.0 * s - 6.0 * s2) * p1
        + (3.0 * s2 - 2.0 * s) * h * m1)
        / h
}

/// The maximum of the Hermite interpolant in a step where the slope goes from > 0 to <= 0:
/// (fraction of the step, value).
pub(crate) fn hermite_max(p0: f64, m0: f64, p1: f64, m1: f64, h: f64) -> (f64, f64) {
    // the slope's fall through zero (zero counts as past), by bisection from the whole step
    // (60 halvings: to rounding where the maximum is beyond 1/256 of the step)
    let s = bisect(|s| hermite_slope(p0, m0, p1, m1, h, s) > 0.0, 0.0, 1.0, 60).mid();
    let v = hermite_eval(p0, m0, p1, m1, h, s);
    (s, v.max(p0).max(p1))
}

/// The zero of the Hermite interpolant in a step where the value goes from > 0 to <= 0: Newton's
/// method kept inside the bracket (bisection where a step would leave it), to rounding level.
pub(crate) fn hermite_root(p0: f64, m0: f64, p1: f64, m1: f64, h: f64) -> f64 {
    let f = |s: f64| hermite_eval(p0, m0, p1, m1, h, s);
    let mut bracket = Bracket::new(0.0, 1.0);
    // the secant's zero first
    let mut s = if p0 > p1 { p0 / (p0 - p1) } else { 0.5 };
    for _ in 0..100 {
        let v = f(s);
        bracket.narrow(s, v > 0.0);
        let slope = hermite_slope(p0, m0, p1, m1, h, s) * h;
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

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn hermite_is_exact_for_cubics() {
        let f = |t: f64| 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t * t * t;
        let df = |t: f64| 2.0 - 6.0 * t + 1.5 * t * t;
        let (a, h) = (0.2, 0.7);
        for &s in &[0.0, 0.3, 0.8, 1.0] {
            assert_relative_eq!(hermite_eval(f(a), df(a), f(a + h), df(a + h), h, s), f(a + s * h), epsilon = 1e-13);
            assert_relative_eq!(hermite_slope(f(a), df(a), f(a + h), df(a + h), h, s), df(a + s * h), epsilon = 1e-12);
        }
    }

    #[test]
    fn roots_and_maxima_of_cubics_are_found_to_rounding() {
        // (t - r)(t + 1)(t - 3) falls through zero at r in [0, 1] (a cubic: the interpolant is exact)
        let h = 1.0;
        for r in [1e-6, 0.013, 0.5, 0.77, 0.999_999] {
            let f = |t: f64| (t - r) * (t + 1.0) * (t - 3.0);
            let df = |t: f64| (t + 1.0) * (t - 3.0) + (t - r) * (t - 3.0) + (t - r) * (t + 1.0);
            let s = hermite_root(f(0.0), df(0.0), f(1.0), df(1.0), h);
            assert!((s - r).abs() <= 4.0 * f64::EPSILON, "root {r}: {s}");
        }
        // a double root at the end (a contact that fades out tangentially): found to where the
        // cubic is below rounding
        let s = hermite_root(0.3 * 0.2, 0.3 * (1.0 - 0.4), 0.0, 0.0, 1.0);
        assert!((s - 1.0).abs() <= 1e-7, "{s}");
        // the maximum of t (1 - t): at 1/2, 1/4
        let (sm, vm) = hermite_max(0.0, 1.0, 0.0, -1.0, 1.0);
        assert_relative_eq!(sm, 0.5, epsilon = 1e-12);
        assert_relative_eq!(vm, 0.25, epsilon = 1e-12);
    }
}
