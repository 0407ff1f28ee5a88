//! The paper's contact law: the hysteretic ball (Eqs 3-4) in series with linear strings (Eq 2).
//!
//! In the expansion phase the law is written in the scale-free variable `u = Y_b / Y0`:
//! `F = k1 Y0 u^p` and Eq 10 becomes `u + (k1/k_s) u^p = Y_T / Y0`. The left side is increasing
//! and convex in `u`, so Newton's method started at or right of the root converges
//! monotonically and never leaves `[0, hi]`; the solve starts there (a warm start left of the
//! root is first stepped across it, or replaced by an upper bound), so it cannot go negative,
//! and it converges from every start.

use crate::error::{Error, Result};
use crate::model::contact::{ball_stiffness, series, ContactLaw, ContactState, Phase, PowSeries};
use crate::params::{Ball, Strings};

/// The paper's ball and linear string springs in series.
#[derive(Debug, Clone, Copy)]
pub struct Cross {
    /// Ball compression stiffness `k1`, N/m.
    pub k1: f64,
    /// String-plane stiffness `k_s`, N/m.
    pub ks: f64,
    /// Hysteresis exponent `p`.
    pub p: f64,
    /// `k1 / k_s`.
    pub(crate) alpha: f64,
    /// Series stiffness in compression `k1 k_s / (k1 + k_s)`, N/m.
    k_series: f64,
    /// Powers `u^p` of nearby points without a power function.
    pub pow: PowSeries,
}

impl Cross {
    /// The contact of a ball on a string bed.
    pub fn new(ball: &Ball, strings: &Strings) -> Self {
        let (k1, ks) = (ball.k1, strings.ks);
        Cross { k1, ks, p: ball.p, alpha: k1 / ks, k_series: k1 * ks / (k1 + ks), pow: PowSeries::new(ball.p) }
    }

    /// The coefficient of restitution of the ball on these strings against a fixed frame:
    /// `e^2 = (1/k_s + 2/((p+1) k1)) / (1/k_s + 1/k1)` (independent of the ball's mass and speed).
    pub fn restitution_on_fixed_frame(&self) -> f64 {
        let (k1, ks, q) = (self.k1, self.ks, self.p + 1.0);
        ((1.0 / ks + 2.0 / (q * k1)) / (1.0 / ks + 1.0 / k1)).sqrt()
    }
}

impl ContactLaw for Cross {
    fn compression_stiffness(&self) -> f64 {
        self.k_series
    }

    /// The ball is stiffest at maximum compression in expansion (`p k1`), in series with `k_s`.
    fn max_stiffness(&self) -> f64 {
        let kb = self.p * self.k1;
        let ks = self.ks;
        kb * ks / (kb + ks)
    }

    /// Any `u` of `guess` is safe (one left of the root is used only when a short Newton step
    /// takes it right of the root, one far above it not at all), but `u^p` must be `u`'s power
    /// (checked in debug builds).
    #[inline]
    fn state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> Result<ContactState> {
        if yt <= 0.0 {
            return Ok(ContactState::ZERO);
        }
        match phase {
            Phase::Compression => {
                let force = self.k_series * yt;
                let ball_compression = force / self.k1;
                Ok(ContactState {
                    force,
                    ball_compression,
                    u: 0.0,
                    u_pow: 0.0,
                    string_deflection: yt - ball_compression,
                })
            }
            Phase::Expansion { y0 } => {
                let z = yt / y0;
                let (u, up) = solve_u(self.alpha, &self.pow, z, guess)?;
                let ball_compression = u * y0;
                Ok(ContactState {
                    force: self.k1 * y0 * up,
                    ball_compression,
                    u,
                    u_pow: up,
                    string_deflection: yt - ball_compression,
                })
            }
        }
    }

    fn stiffness(&self, phase: Phase, st: &ContactState) -> f64 {
        match phase {
            Phase::Compression => self.k_series,
            Phase::Expansion { .. } => series(ball_stiffness(self.k1, self.p, phase, st), self.ks),
        }
    }

    /// Eq 9 at the turning point.
    fn ball_compression_at_max(&self, yt_max: f64) -> f64 {
        self.ks * yt_max / (self.k1 + self.ks)
    }

    #[inline]
    fn ball_energy_with_loss(&self, phase: Phase, st: &ContactState) -> f64 {
        match phase {
            Phase::Compression => 0.5 * self.k1 * st.ball_compression * st.ball_compression,
            Phase::Expansion { y0 } => {
                let q = self.p + 1.0;
                let full = self.k1 * y0 * y0;
                0.5 * full - full * (1.0 - st.u * st.u_pow) / q
            }
        }
    }

    /// `F^2 / (2 k_s)`.
    #[inline]
    fn string_energy(&self, st: &ContactState) -> f64 {
        st.force * st.force / (2.0 * self.ks)
    }

    fn ball_loss(&self, y0: f64) -> f64 {
        (self.p - 1.0) * self.k1 * y0 * y0 / (2.0 * (self.p + 1.0))
    }
}

/// Solve `u + a u^p = z` for `u >= 0` with `a > 0`, `p > 1`, `z >= 0`: Eq 10 in units of `Y0`
/// (`a = k1/k_s`), for the explicit solver. (The modal solver's implicit step solves the same law
/// with its rate coupled in: [`ImplicitLaw::expansion_end`](super::ImplicitLaw::expansion_end).) Newton from an upper bound of
/// the root converges monotonically (the left side is increasing and convex), so the result is
/// never negative and the loop always ends; a start left of the root is first moved right of it
/// by one Newton step when that step is short, and replaced by the smallest cheap upper bound
/// otherwise. Returns `(u, u^p)`. `guess` is `(u, u^p)` of the previous solve (any `u`; `u^p`
/// must be its power: checked in debug builds); `u^p` of each iterate is carried from the
/// previous one by the binomial series ([`PowSeries::step`]), so a warm-started solve needs no
/// power function.
fn solve_u(a: f64, pow: &PowSeries, z: f64, guess: (f64, f64)) -> Result<(f64, f64)> {
    let p = pow.p;
    let powf = |u: f64| if u > 0.0 { u.powf(p) } else { 0.0 };
    let (mut u, mut up) = guess;
    debug_assert!(
        !(u > 0.0 && up > 0.0) || (up / u.powf(p) - 1.0).abs() < 1e-9,
        "solve_u: guess {guess:?} is not (u, u^p) for p = {p}"
    );
    // Upper bounds of the root (h >= 0 there): z itself (u < z always), (z/a)^(1/p), and 1
    // whenever z <= 1 + a (Y_T at or below its maximum; above it the frame has sprung back and
    // reloads the ball on its expansion curve). A start far above the root would lose digits to
    // cancellation in `u - step`, so a start must also lie below the cheap ones.
    let cheap = if z <= 1.0 + a { z.min(1.0) } else { z };
    let mut warm = u > 0.0 && up > 0.0 && up.is_finite() && u <= cheap;
    if warm && u + a * up - z < 0.0 {
        // The previous root lies left of this one (z has grown): one Newton step from the left
        // lands right of the root (convexity). A short step (the usual time step) starts the
        // iteration below a short way off; a long one could land far above the root, where
        // Newton on a steep power law crawls back, so that start is cold instead.
        let next = (u - (u + a * up - z) / (1.0 + a * p * up / u)).min(cheap);
        let delta = next / u - 1.0;
        if delta <= 0.1 {
            up = pow.step(u, up, delta);
            u = next;
        } else {
            warm = false;
        }
    }
    if !warm {
        // no usable start: the smallest of the upper bounds keeps Newton short
        u = z.min((z / a).powf(1.0 / p));
        if z <= 1.0 + a {
            u = u.min(1.0);
        }
        up = powf(u);
    }
    for _ in 0..200 {
        let hu = u + a * up - z;
        if hu <= 0.0 || u <= 0.0 {
            return Ok((u, up));
        }
        let inv_u = 1.0 / u;
        let g = a * p * up * inv_u;
        let d1 = 1.0 + g;
        let mut step = hu / d1;
        let halley = step < 1e-5 * u;
        if halley {
            // close to the root: Halley's correction (third order; its overshoot is of the
            // order of the cube of the step, below rounding)
            let d2 = (p - 1.0) * g * inv_u;
            step = hu * d1 / (d1 * d1 - 0.5 * hu * d2);
        }
        let next = (u - step).max(0.0);
        // the power of `next = u (1 + delta)`: by the series from `up = u^p` when the move is
        // short, else of `next` itself (a long move's `1 + delta` has lost digits to cancellation)
        let delta = -step * inv_u;
        let next_pow = if next > 0.0 && delta.abs() <= 0.1 { pow.step(u, up, delta) } else { powf(next) };
        // after a Halley step of 1e-6 the error is of order 1e-18: done
        if (halley && step <= 1e-6 * u) || step <= 4.0 * f64::EPSILON * u || next == u {
            return Ok((next, next_pow));
        }
        u = next;
        up = next_pow;
    }
    Err(Error::ContactSolve { z })
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn contact(ks: f64) -> Cross {
        Cross::new(&Ball::default(), &Strings { ks })
    }

    #[test]
    fn expansion_force_matches_compression_at_the_turning_point() {
        let c = contact(4.0e4);
        let yt_max = 0.01;
        let y0 = c.ball_compression_at_max(yt_max);
        let fc = c.state(yt_max, Phase::Compression, (0.0, 0.0)).unwrap().force;
        let fe = c.state(yt_max, Phase::Expansion { y0 }, (0.3, 0.3f64.powf(c.p))).unwrap();
        assert_relative_eq!(fc, fe.force, max_relative = 1e-13);
        assert_relative_eq!(fe.u, 1.0, max_relative = 1e-13);
    }

    #[test]
    fn expansion_solve_satisfies_eq10_from_any_start() {
        let c = contact(2.0e4);
        let y0 = 0.008;
        for &yt in &[1e-9, 1e-5, 0.003, 0.0119, 0.02] {
            let root = c.state(yt, Phase::Expansion { y0 }, (0.0, 0.0)).unwrap().u;
            // cold, far above and below, and just left and right of the root (the warm starts
            // of a time step: a start left of the root takes one Newton step to its right)
            let near = [0.9, 0.999, 1.0 - 1e-9, 1.001, 1.05].map(|f| f * root);
            for &guess in [0.0, 0.5, 1.0, 7.0].iter().chain(&near) {
                let st = c.state(yt, Phase::Expansion { y0 }, (guess, guess.powf(c.p))).unwrap();
                let k2 = c.k1 * y0.powf(1.0 - c.p);
                let yb = st.ball_compression;
                assert!(yb >= 0.0);
                assert_relative_eq!(yb + k2 * yb.powf(c.p) / c.ks, yt, max_relative = 1e-12);
                assert_relative_eq!(st.force, c.ks * (yt - yb), max_relative = 1e-9);
                // the carried power is the power of the returned u
                assert_relative_eq!(st.u_pow, st.u.powf(c.p), max_relative = 1e-14);
            }
        }
    }

    #[test]
    fn expansion_solve_converges_at_the_extremes_of_the_parameter_ranges() {
        for &p in &[1.0 + 1e-9, 1.01, 2.55, 10.0] {
            for &ks in &[1.0, 1.0e3, 1.0e6, 1.0e12] {
                let c = Cross::new(&Ball { mass: 0.057, k1: 3.0e4, p }, &Strings { ks });
                let y0 = 0.01;
                for &z in &[1e-300, 1e-12, 1e-3, 0.5, 1.0, 1.0 + c.alpha, 2.0 * (1.0 + c.alpha)] {
                    let st = c.state(z * y0, Phase::Expansion { y0 }, (0.7, 0.7f64.powf(p))).unwrap();
                    let u = st.u;
                    assert!(u.is_finite() && u >= 0.0);
                    let lhs = u + c.alpha * u.powf(p);
                    assert!((lhs - z).abs() <= 1e-12 * z.max(1e-300) + 1e-300, "p {p} ks {ks} z {z}: {lhs}");
                }
            }
        }
    }

    #[test]
    fn a_warm_start_far_left_of_the_root_starts_cold_instead() {
        // a steep law (p 10, k1/ks 1e9) with z above 1 + a and the guess far below the root: one
        // Newton step from the guess lands near z, about 1e9 times the root, from where Newton
        // would need hundreds of steps; the solve must start from an upper bound instead
        let c = Cross::new(&Ball { mass: 0.057, k1: 1e9, p: 10.0 }, &Strings { ks: 1.0 });
        let y0 = 1e-3;
        let z = 1e9 + 2.0;
        for guess in [1e-3, 0.5, 0.999] {
            let st = c.state(z * y0, Phase::Expansion { y0 }, (guess, f64::powf(guess, 10.0))).unwrap();
            assert_relative_eq!(st.u + c.alpha * st.u.powf(10.0), z, max_relative = 1e-12);
            assert_relative_eq!(st.u_pow, st.u.powf(10.0), max_relative = 1e-14);
        }
    }

    #[test]
    fn ball_ledger_at_the_end_of_expansion_is_the_eq11_loss() {
        let c = contact(4.0e4);
        let y0 = 0.01;
        let st = ContactState::ZERO;
        assert_relative_eq!(
            c.ball_energy_with_loss(Phase::Expansion { y0 }, &st),
            c.ball_loss(y0),
            max_relative = 1e-14
        );
    }
}
