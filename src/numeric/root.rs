//! The crate's one root finder for a switch inside a bracket: a [`Bracket`] `[lo, hi]` with
//! `lo` before the switch and `hi` past it, halved by [`bisect`] to rounding, or kept around
//! the iterates of a faster method that falls back on its midpoint when a step would leave it
//! ([`Bracket::inside_or_mid`]: the Newton steps of `solve::hermite` and of the stiffening
//! strings' expansion, [`crate::model::contact`], the rational steps of [`super::rank_one`]).
//!
//! Each caller says which side a point is on (`before`), and with it its sign convention:
//! `f > 0` before a fall through zero that counts zero as past, `f >= 0` one that counts zero
//! as before. (The event location of the tangential stepper, an Illinois regula falsi on RK4
//! substeps, `crate::model::tangential::stepper`, stays its own: its iterates are whole integration
//! steps, and it restarts on another guard that fails earlier.)
//!
//! Hand-written rather than taken from a crate: `roots` has no plain bisection, and its
//! bracketing methods (Brent, regula falsi) stop at a tolerance or at an exact zero and return
//! their own iterate, where each search here keeps the convention (and so the bits) it had: the
//! first point past the switch, or the midpoint, after a given number of halvings or at
//! rounding.

/// An interval `[lo, hi]` around a switch: `lo` before it, `hi` past it (either may be the
/// larger: a bracket may close from above).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// The end before the switch.
    pub lo: f64,
    /// The end past the switch.
    pub hi: f64,
}

impl Bracket {
    /// The bracket `[lo, hi]`.
    pub fn new(lo: f64, hi: f64) -> Self {
        Bracket { lo, hi }
    }

    /// Narrow the bracket to `x`: its `lo` if `x` is before the switch, else its `hi`.
    #[inline]
    pub fn narrow(&mut self, x: f64, before: bool) {
        if before {
            self.lo = x;
        } else {
            self.hi = x;
        }
    }

    /// Narrow the bracket to `x`: its `hi` if `x` is past the switch, else its `lo` (for a sign
    /// convention that names the far side: `g > 0` past the root of a rising `g`, where a NaN
    /// counts as before).
    #[inline]
    pub fn narrow_past(&mut self, x: f64, past: bool) {
        self.narrow(x, !past);
    }

    /// The midpoint.
    #[inline]
    pub fn mid(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }

    /// `x` where it lies strictly inside the bracket (`lo < x < hi`), else the midpoint: the
    /// safeguard of a faster iteration.
    #[inline]
    pub fn inside_or_mid(&self, x: f64) -> f64 {
        if x > self.lo && x < self.hi {
            x
        } else {
            self.mid()
        }
    }
}

/// Halve the bracket `[lo, hi]` (`before(lo)`, not `before(hi)`) at most `halvings` times,
/// stopping at rounding: once a halving leaves the bracket as it was (its ends are neighbouring
/// floats, or one), every further one would too, so the result is that of all `halvings`.
pub fn bisect(before: impl Fn(f64) -> bool, lo: f64, hi: f64, halvings: usize) -> Bracket {
    let mut bracket = Bracket::new(lo, hi);
    for _ in 0..halvings {
        let mid = bracket.mid();
        let is_before = before(mid);
        // (the end the midpoint would replace is the midpoint already: nothing moves)
        if mid == if is_before { bracket.lo } else { bracket.hi } {
            break;
        }
        bracket.narrow(mid, is_before);
    }
    bracket
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The neighbouring float above `x > 0`.
    fn next_up(x: f64) -> f64 {
        f64::from_bits(x.to_bits() + 1)
    }

    #[test]
    fn bisection_finds_known_roots_to_rounding() {
        // sqrt(2) by x^2 - 2, falling: a root inside, the ends neighbouring floats around it
        let b = bisect(|x| 2.0 - x * x > 0.0, 1.0, 2.0, 200);
        assert_eq!(b.hi, next_up(b.lo), "{b:?}");
        assert!(b.lo * b.lo < 2.0 && b.hi * b.hi >= 2.0, "{b:?}");
        assert!((b.lo - std::f64::consts::SQRT_2).abs() <= f64::EPSILON, "{b:?}");
        // cos on [0, 2]: pi / 2
        let b = bisect(|x| x.cos() > 0.0, 0.0, 2.0, 200);
        assert!(b.hi - b.lo <= f64::EPSILON && (b.mid() - std::f64::consts::FRAC_PI_2).abs() <= f64::EPSILON);
        // a root near zero, where floats are dense: found to its own rounding, not to 1e-16
        let b = bisect(|x| x < 1e-200, 0.0, 1.0, 2000);
        assert_eq!(b.hi, next_up(b.lo), "{b:?}");
        assert!(b.lo < 1e-200 && b.hi >= 1e-200, "{b:?}");
    }

    #[test]
    fn the_sign_convention_decides_where_an_exact_zero_goes() {
        // f(x) = x - 0.5 is exactly zero at the first midpoint
        let f = |x: f64| x - 0.5;
        // zero counts as past (f > 0 before): the bracket closes onto 0.5 from below
        let past = bisect(|x| f(x) < 0.0, 0.0, 1.0, 200);
        assert_eq!(past.hi, 0.5);
        assert_eq!(past.lo, 0.5 - f64::EPSILON / 4.0, "the float below 0.5");
        // zero counts as before (f <= 0 before): onto 0.5 from above
        let before = bisect(|x| f(x) <= 0.0, 0.0, 1.0, 200);
        assert_eq!(before.lo, 0.5);
        assert_eq!(before.hi, next_up(0.5));
        // a bracket closing from above (lo > hi): a falling function seen from the right
        let b = bisect(|x| x > 0.25, 1.0, 0.0, 200);
        assert_eq!(b.hi, 0.25);
        assert_eq!(b.lo, next_up(0.25));
    }

    #[test]
    fn bisection_stops_at_rounding_with_the_result_of_every_halving() {
        // the same result for any count beyond the one that reaches rounding, and that count is
        // about the 53 bits of the mantissa on [1, 2]
        let calls = std::cell::Cell::new(0);
        let before = |x: f64| {
            calls.set(calls.get() + 1);
            x * x < 3.0
        };
        let b = bisect(before, 1.0, 2.0, 60);
        let used = calls.get();
        assert!((52..=54).contains(&used), "{used} halvings");
        assert_eq!(bisect(|x| x * x < 3.0, 1.0, 2.0, 10_000), b);
        // fewer halvings than rounding needs: exactly that many, the bracket 2^-n wide
        let b = bisect(|x| x * x < 3.0, 1.0, 2.0, 20);
        assert_eq!(b.hi - b.lo, 2f64.powi(-20));
        assert!(b.lo * b.lo < 3.0 && b.hi * b.hi >= 3.0);
    }

    #[test]
    fn the_safeguard_keeps_a_step_inside_or_halves() {
        let b = Bracket::new(1.0, 2.0);
        assert_eq!(b.inside_or_mid(1.25), 1.25);
        for outside in [1.0, 2.0, 0.5, 3.0, f64::NAN, f64::INFINITY] {
            assert_eq!(b.inside_or_mid(outside), 1.5, "{outside}");
        }
        let mut b = b;
        b.narrow(1.75, false);
        b.narrow(1.25, true);
        assert_eq!(b, Bracket::new(1.25, 1.75));
        b.narrow_past(1.5, true);
        b.narrow_past(1.375, false);
        assert_eq!(b, Bracket::new(1.375, 1.5));
    }
}
