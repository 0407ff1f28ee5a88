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
//! monotonically and never leaves `[0, hi]`; the solve starts there (a warm start left of the
//! root is first stepped across it, or replaced by an upper bound), so it cannot go negative,
//! and it converges from every start.

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
    /// String stiffening `s / d^2`, 1/m^2 (0: the paper's linear strings).
    stiffening: f64,
    /// Upper bound of the string deflection over the impact, m (for the stiffness bound).
    deflection_bound: f64,
    /// Powers `u^p` of nearby points without a power function.
    pub pow: PowSeries,
}

/// Terms of the binomial series for the power of a nearby point.
const BINOMIAL_TERMS: usize = 17;

/// `(u (1 + delta))^p` from `u^p` by the binomial series: both solvers carry the ball law's power
/// from one Newton iterate (or one step) to the next with it instead of calling `powf`.
#[derive(Debug, Clone, Copy)]
pub struct PowSeries {
    /// The exponent `p`.
    p: f64,
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

    /// The point `u (1 + delta)` and its power by [`PowSeries::step`]: a pair that stays
    /// consistent however far the move (the fallback's `powf` is of that same point).
    #[inline]
    pub fn advance(&self, u: f64, up: f64, delta: f64) -> (f64, f64) {
        (u * (1.0 + delta), self.step(u, up, delta))
    }
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
    /// `u^p`, kept with `u` so the next solve starts without a power function.
    pub u_pow: f64,
    /// String-plane deflection `Y_s`, m.
    pub string_deflection: f64,
}

impl ContactState {
    /// No contact.
    pub const ZERO: ContactState =
        ContactState { force: 0.0, ball_compression: 0.0, u: 0.0, u_pow: 0.0, string_deflection: 0.0 };

    /// The warm start `(u, u^p)` this state offers the next expansion solve.
    pub fn guess(&self) -> (f64, f64) {
        (self.u, self.u_pow)
    }
}

impl Contact {
    /// The contact of a ball on a string bed.
    pub fn new(ball: &Ball, strings: &Strings) -> Self {
        let (k1, ks) = (ball.k1, strings.ks);
        Contact {
            k1,
            ks,
            p: ball.p,
            alpha: k1 / ks,
            k_series: k1 * ks / (k1 + ks),
            stiffening: 0.0,
            deflection_bound: 0.0,
            pow: PowSeries::new(ball.p),
        }
    }

    /// Strings that stiffen with deflection: `F = k_s Y_s (1 + s (Y_s/d)^2)`. `energy` (J) is the
    /// incident kinetic energy, which bounds the string deflection by `sqrt(2 energy / k_s)`.
    pub fn with_stiffening(mut self, s: f64, d: f64, energy: f64) -> Self {
        self.stiffening = s / (d * d);
        self.deflection_bound = (2.0 * energy / self.ks).sqrt();
        self
    }

    /// String force at deflection `ys`, N.
    fn string_force(&self, ys: f64) -> f64 {
        self.ks * ys * (1.0 + self.stiffening * ys * ys)
    }

    /// `dF/dY_s`, N/m.
    fn string_stiffness(&self, ys: f64) -> f64 {
        self.ks * (1.0 + 3.0 * self.stiffening * ys * ys)
    }

    /// Series stiffness in the compression phase, N/m.
    pub fn compression_stiffness(&self) -> f64 {
        self.k_series
    }

    /// Upper bound of `dF/dY_T` over the whole impact, N/m: the ball is stiffest at maximum
    /// compression in expansion (`p k1`), in series with `k_s`. Used for the stability limit.
    pub fn max_stiffness(&self) -> f64 {
        let kb = self.p * self.k1;
        let ks = self.string_stiffness(self.deflection_bound);
        kb * ks / (kb + ks)
    }

    /// Maximum ball compression for a maximum total compression `yt_max` (Eq 9), m.
    pub fn ball_compression_at_max(&self, yt_max: f64) -> f64 {
        if self.stiffening > 0.0 {
            return self.string_force(self.stiffening_compression(yt_max)) / self.k1;
        }
        self.ks * yt_max / (self.k1 + self.ks)
    }

    /// Stiffening strings, compression: the string deflection with `Y_s + F(Y_s)/k1 = Y_T`
    /// (increasing and convex in `Y_s`; Newton from the linear solution, an upper bound).
    fn stiffening_compression(&self, yt: f64) -> f64 {
        let mut ys = yt * self.k1 / (self.k1 + self.ks);
        for _ in 0..100 {
            let g = ys + self.string_force(ys) / self.k1 - yt;
            let step = g / (1.0 + self.string_stiffness(ys) / self.k1);
            ys = (ys - step).max(0.0);
            if step.abs() <= 4.0 * f64::EPSILON * ys {
                break;
            }
        }
        ys
    }

    /// Stiffening strings, expansion: the string deflection with
    /// `Y_s + Y0 (F(Y_s) / (k1 Y0))^(1/p) = Y_T`, by Newton safeguarded with bisection on
    /// `[0, Y_T]` (the left side increases from 0).
    fn stiffening_expansion(&self, yt: f64, y0: f64, guess: f64) -> f64 {
        let g = |ys: f64| ys + y0 * (self.string_force(ys) / (self.k1 * y0)).powf(1.0 / self.p) - yt;
        let (mut lo, mut hi) = (0.0, yt);
        let mut ys = if guess > 0.0 && guess < yt { guess } else { 0.5 * yt };
        for _ in 0..200 {
            let gy = g(ys);
            if gy > 0.0 {
                hi = ys;
            } else {
                lo = ys;
            }
            let f = self.string_force(ys);
            let slope = 1.0
                + y0 / self.p * (f / (self.k1 * y0)).powf(1.0 / self.p - 1.0) * self.string_stiffness(ys)
                    / (self.k1 * y0);
            let mut next = ys - gy / slope;
            if !(next > lo && next < hi && next.is_finite()) {
                next = 0.5 * (lo + hi);
            }
            if (next - ys).abs() <= 4.0 * f64::EPSILON * ys.max(f64::MIN_POSITIVE) || hi - lo <= 4.0 * f64::EPSILON * hi
            {
                return next;
            }
            ys = next;
        }
        ys
    }

    /// Force and compressions at total compression `yt` in the given phase. `guess` is a warm
    /// start `(u, u^p)`, as [`ContactState::guess`] returns it: any `u` is safe (one left of the
    /// root is used only when a short Newton step takes it right of the root, one far above it
    /// not at all), but `u^p` must be `u`'s power (checked in debug builds).
    pub fn state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> Result<ContactState> {
        if yt <= 0.0 {
            return Ok(ContactState::ZERO);
        }
        if self.stiffening > 0.0 {
            return Ok(self.stiffening_state(yt, phase, guess));
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

    /// [`Contact::state`] for stiffening strings (`guess.0` is the previous `u`).
    fn stiffening_state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> ContactState {
        match phase {
            Phase::Compression => {
                let ys = self.stiffening_compression(yt);
                let force = self.string_force(ys);
                ContactState { force, ball_compression: force / self.k1, u: 0.0, u_pow: 0.0, string_deflection: ys }
            }
            Phase::Expansion { y0 } => {
                let ys = self.stiffening_expansion(yt, y0, yt - guess.0 * y0);
                let force = self.string_force(ys);
                let u_pow = force / (self.k1 * y0);
                let u = (yt - ys) / y0;
                ContactState { force, ball_compression: u * y0, u, u_pow, string_deflection: ys }
            }
        }
    }

    /// Energy held by the ball plus the energy it has already dissipated ("PE ball" of Fig 4), J.
    pub fn ball_energy_with_loss(&self, phase: Phase, st: &ContactState) -> f64 {
        match phase {
            Phase::Compression => 0.5 * self.k1 * st.ball_compression * st.ball_compression,
            Phase::Expansion { y0 } => {
                let q = self.p + 1.0;
                let full = self.k1 * y0 * y0;
                0.5 * full - full * (1.0 - st.u * st.u_pow) / q
            }
        }
    }

    /// Elastic energy of the strings, J: `F^2 / (2 k_s)` for linear strings,
    /// `k_s (Y_s^2 / 2 + (s/d^2) Y_s^4 / 4)` for stiffening ones.
    pub fn string_energy(&self, st: &ContactState) -> f64 {
        if self.stiffening > 0.0 {
            let y2 = st.string_deflection * st.string_deflection;
            return self.ks * y2 * (0.5 + 0.25 * self.stiffening * y2);
        }
        st.force * st.force / (2.0 * self.ks)
    }

    /// Energy dissipated in the ball over a whole impact with maximum compression `y0` (Eq 11), J.
    pub fn ball_loss(&self, y0: f64) -> f64 {
        (self.p - 1.0) * self.k1 * y0 * y0 / (2.0 * (self.p + 1.0))
    }
}

/// Solve `u + a u^p = z` for `u >= 0` with `a > 0`, `p > 1`, `z >= 0`: Eq 10 in units of `Y0`
/// (`a = k1/k_s`), for the explicit solver. (The modal solver's implicit step solves the same law
/// with its rate coupled in: `modal::ModalModel::expansion_end`.) Newton from an upper bound of
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

    fn contact(ks: f64) -> Contact {
        Contact::new(&Ball::default(), &Strings { ks })
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
                let c = Contact::new(&Ball { mass: 0.057, k1: 3.0e4, p }, &Strings { ks });
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
        let c = Contact::new(&Ball { mass: 0.057, k1: 1e9, p: 10.0 }, &Strings { ks: 1.0 });
        let y0 = 1e-3;
        let z = 1e9 + 2.0;
        for guess in [1e-3, 0.5, 0.999] {
            let st = c.state(z * y0, Phase::Expansion { y0 }, (guess, f64::powf(guess, 10.0))).unwrap();
            assert_relative_eq!(st.u + c.alpha * st.u.powf(10.0), z, max_relative = 1e-12);
            assert_relative_eq!(st.u_pow, st.u.powf(10.0), max_relative = 1e-14);
        }
    }

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
