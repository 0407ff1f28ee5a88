//! The ball on the strings: a hysteretic ball spring (Eqs 3-4) in series with a massless linear
//! string spring (Eq 2), driven by the total compression `Y_T = Y_s + Y_b` (Eq 8).
//!
//! ```text
//! compression:  F = k1 Y_b,            Y_b = k_s Y_T / (k1 + k_s)                     (Eqs 3, 9)
//! expansion:    F = k2 Y_b^p,          Y_b + k2 Y_b^p / k_s = Y_T                     (Eqs 4, 10)
//!               k2 = k1 Y0^(1-p)       (the paper prints p-1: a typo, see SPEC.md)
//! ball loss:    E_b = (p-1) k1 Y0^2 / (2 (p+1))                                       (Eq 11)
//! ```
//!
//! In the expansion phase the law is written in the scale-free variable `u = Y_b / Y0`:
//! `F = k1 Y0 u^p` and Eq 10 becomes `u + (k1/k_s) u^p = Y_T / Y0`. The left side is increasing
//! and convex in `u`, so Newton's method started at or right of the root converges
//! monotonically and never leaves `[0, hi]`: the safeguarded solve cannot fail or go negative.

use crate::error::{Error, Result};
use crate::params::{Ball, Strings};

/// The phase of the ball's force law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Phase {
    /// Loading along `F = k1 Y_b`.
    Compression,
    /// Unloading along `F = k2 Y_b^p` after the maximum compression `y0` (m) of the ball.
    Expansion {
        /// Maximum ball compression `Y0`, m.
        y0: f64,
    },
}

/// Ball and string springs in series.
#[derive(Debug, Clone, Copy)]
pub struct Contact {
    /// Ball compression stiffness `k1`, N/m.
    pub k1: f64,
    /// String-plane stiffness `k_s`, N/m.
    pub ks: f64,
    /// Hysteresis exponent `p`.
    pub p: f64,
    /// `k1 / k_s`.
    alpha: f64,
    /// Series stiffness in compression `k1 k_s / (k1 + k_s)`, N/m.
    k_series: f64,
}

/// The force and compressions at one total compression `Y_T`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// Contact force `F` (>= 0), N.
    pub force: f64,
    /// Ball compression `Y_b`, m.
    pub ball_compression: f64,
    /// Expansion-law variable `u = Y_b / Y0` (0 in compression); a warm start for the next solve.
    pub u: f64,
}

impl Contact {
    /// The contact of a ball on a string bed.
    pub fn new(ball: &Ball, strings: &Strings) -> Self {
        let (k1, ks) = (ball.k1, strings.ks);
        Contact { k1, ks, p: ball.p, alpha: k1 / ks, k_series: k1 * ks / (k1 + ks) }
    }

    /// Series stiffness in the compression phase, N/m.
    pub fn compression_stiffness(&self) -> f64 {
        self.k_series
    }

    /// Upper bound of `dF/dY_T` over the whole impact, N/m: the ball is stiffest at maximum
    /// compression in expansion (`p k1`), in series with `k_s`. Used for the stability limit.
    pub fn max_stiffness(&self) -> f64 {
        let kb = self.p * self.k1;
        kb * self.ks / (kb + self.ks)
    }

    /// Maximum ball compression for a maximum total compression `yt_max` (Eq 9), m.
    pub fn ball_compression_at_max(&self, yt_max: f64) -> f64 {
        self.ks * yt_max / (self.k1 + self.ks)
    }

    /// Force and compressions at total compression `yt` in the given phase. `u_guess` is the
    /// previous step's `u` (any value is safe: it is only used when it lies right of the root).
    pub fn state(&self, yt: f64, phase: Phase, u_guess: f64) -> Result<ContactState> {
        if yt <= 0.0 {
            return Ok(ContactState { force: 0.0, ball_compression: 0.0, u: 0.0 });
        }
        match phase {
            Phase::Compression => {
                let force = self.k_series * yt;
                Ok(ContactState { force, ball_compression: force / self.k1, u: 0.0 })
            }
            Phase::Expansion { y0 } => {
                let z = yt / y0;
                let u = self.solve_expansion(z, u_guess)?;
                let force = self.k1 * y0 * u.powf(self.p);
                Ok(ContactState { force, ball_compression: u * y0, u })
            }
        }
    }

    /// Solve `u + alpha u^p = z` for `u >= 0` (Eq 10 in units of `Y0`).
    fn solve_expansion(&self, z: f64, u_guess: f64) -> Result<f64> {
        solve_u(self.alpha, self.p, z, u_guess)
    }

    /// Energy held by the ball plus the energy it has already dissipated ("PE ball" of Fig 4), J.
    pub fn ball_energy_with_loss(&self, phase: Phase, st: &ContactState) -> f64 {
        match phase {
            Phase::Compression => 0.5 * self.k1 * st.ball_compression * st.ball_compression,
            Phase::Expansion { y0 } => {
                let q = self.p + 1.0;
                let full = self.k1 * y0 * y0;
                0.5 * full - full * (1.0 - st.u.powf(q)) / q
            }
        }
    }

    /// Elastic energy of the strings `F^2 / (2 k_s)`, J.
    pub fn string_energy(&self, force: f64) -> f64 {
        force * force / (2.0 * self.ks)
    }

    /// Energy dissipated in the ball over a whole impact with maximum compression `y0` (Eq 11), J.
    pub fn ball_loss(&self, y0: f64) -> f64 {
        (self.p - 1.0) * self.k1 * y0 * y0 / (2.0 * (self.p + 1.0))
    }
}

/// Solve `u + a u^p = z` for `u >= 0` with `a > 0`, `p > 1`, `z >= 0`: Eq 10 in units of `Y0`
/// (`a = k1/k_s`), and, with `a` enlarged by a compliance term, the implicit contact step of the
/// modal solver. Newton from an upper bound of the root converges monotonically (the left side
/// is increasing and convex), so the result is never negative and the loop always ends.
pub fn solve_u(a: f64, p: f64, z: f64, u_guess: f64) -> Result<f64> {
    let h = |u: f64| u + a * u.powf(p) - z;
    // Upper bounds of the root (h >= 0 there): z itself, (z/a)^(1/p), and 1 whenever
    // z <= 1 + a (Y_T at or below its maximum; above it the frame has sprung back and
    // reloads the ball on its expansion curve). The smallest keeps Newton short.
    let mut hi = z.min((z / a).powf(1.0 / p));
    if z <= 1.0 + a {
        hi = hi.min(1.0);
    }
    let mut u = if u_guess > 0.0 && u_guess < hi && h(u_guess) >= 0.0 { u_guess } else { hi };
    for _ in 0..200 {
        let hu = h(u);
        if hu <= 0.0 {
            return Ok(u);
        }
        let step = hu / (1.0 + a * p * u.powf(p - 1.0));
        let next = (u - step).max(0.0);
        if step <= 4.0 * f64::EPSILON * u || next == u {
            return Ok(next);
        }
        u = next;
    }
    Err(Error::ContactSolve { z })
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn contact(ks: f64) -> Contact {
        Contact::new(&Ball::default(), &Strings { ks })
    }

    #[test]
    fn expansion_force_matches_compression_at_the_turning_point() {
        let c = contact(4.0e4);
        let yt_max = 0.01;
        let y0 = c.ball_compression_at_max(yt_max);
        let fc = c.state(yt_max, Phase::Compression, 0.0).unwrap().force;
        let fe = c.state(yt_max, Phase::Expansion { y0 }, 0.3).unwrap();
        assert_relative_eq!(fc, fe.force, max_relative = 1e-13);
        assert_relative_eq!(fe.u, 1.0, max_relative = 1e-13);
    }

    #[test]
    fn expansion_solve_satisfies_eq10_from_any_start() {
        let c = contact(2.0e4);
        let y0 = 0.008;
        for &yt in &[1e-9, 1e-5, 0.003, 0.0119, 0.02] {
            for &guess in &[0.0, 0.5, 1.0, 7.0] {
                let st = c.state(yt, Phase::Expansion { y0 }, guess).unwrap();
                let k2 = c.k1 * y0.powf(1.0 - c.p);
                let yb = st.ball_compression;
                assert!(yb >= 0.0);
                assert_relative_eq!(yb + k2 * yb.powf(c.p) / c.ks, yt, max_relative = 1e-12);
                assert_relative_eq!(st.force, c.ks * (yt - yb), max_relative = 1e-9);
            }
        }
    }

    #[test]
    fn expansion_solve_converges_at_the_extremes_of_the_parameter_ranges() {
        for &p in &[1.0 + 1e-9, 1.01, 2.55, 10.0] {
            for &ks in &[1.0, 1.0e3, 1.0e6, 1.0e12] {
                let c = Contact::new(&Ball { mass: 0.057, k1: 3.0e4, p }, &Strings { ks });
                let y0 = 0.01;
                for &z in &[1e-300, 1e-12, 1e-3, 0.5, 1.0, 1.0 + c.alpha, 2.0 * (1.0 + c.alpha)] {
                    let st = c.state(z * y0, Phase::Expansion { y0 }, 0.7).unwrap();
                    let u = st.u;
                    assert!(u.is_finite() && u >= 0.0);
                    let lhs = u + c.alpha * u.powf(p);
                    assert!((lhs - z).abs() <= 1e-12 * z.max(1e-300) + 1e-300, "p {p} ks {ks} z {z}: {lhs}");
                }
            }
        }
    }

    #[test]
    fn ball_ledger_at_the_end_of_expansion_is_the_eq11_loss() {
        let c = contact(4.0e4);
        let y0 = 0.01;
        let st = ContactState { force: 0.0, ball_compression: 0.0, u: 0.0 };
        assert_relative_eq!(
            c.ball_energy_with_loss(Phase::Expansion { y0 }, &st),
            c.ball_loss(y0),
            max_relative = 1e-14
        );
    }
}
