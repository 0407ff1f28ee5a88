//! The paper's ball on strings that stiffen with deflection (`--strings stiffening`):
//! `F = k_s Y_s (1 + s (Y_s/d)^2)` in series with the hysteretic ball (Eqs 3-4).

use crate::error::Result;
use crate::model::contact::{ball_stiffness, series, ContactLaw, ContactState, Cross, Phase};
use crate::numeric::root::Bracket;
use crate::params::{Params, StringLaw};

/// The paper's ball on stiffening strings.
#[derive(Debug, Clone, Copy)]
pub struct Stiffening {
    /// The ball (and the strings' small-deflection stiffness `k_s`) of the paper's law.
    pub paper: Cross,
    /// String stiffening `s / d^2`, 1/m^2 (> 0).
    stiffening: f64,
    /// Upper bound of the string deflection over the impact, m (for the stiffness bound).
    deflection_bound: f64,
}

impl Stiffening {
    /// Strings that stiffen with deflection: `F = k_s Y_s (1 + s (Y_s/d)^2)`. `energy` (J) is the
    /// incident kinetic energy, which bounds the string deflection by `sqrt(2 energy / k_s)`.
    pub fn new(paper: Cross, s: f64, d: f64, energy: f64) -> Self {
        Stiffening { paper, stiffening: s / (d * d), deflection_bound: (2.0 * energy / paper.ks).sqrt() }
    }

    /// String force at deflection `ys`, N.
    fn string_force(&self, ys: f64) -> f64 {
        self.paper.ks * ys * (1.0 + self.stiffening * ys * ys)
    }

    /// `dF/dY_s`, N/m.
    fn string_stiffness(&self, ys: f64) -> f64 {
        self.paper.ks * (1.0 + 3.0 * self.stiffening * ys * ys)
    }

    /// Stiffening strings, compression: the string deflection with `Y_s + F(Y_s)/k1 = Y_T`
    /// (increasing and convex in `Y_s`; Newton from the linear solution, an upper bound).
    fn stiffening_compression(&self, yt: f64) -> f64 {
        let mut ys = yt * self.paper.k1 / (self.paper.k1 + self.paper.ks);
        for _ in 0..100 {
            let g = ys + self.string_force(ys) / self.paper.k1 - yt;
            let step = g / (1.0 + self.string_stiffness(ys) / self.paper.k1);
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
        let g = |ys: f64| ys + y0 * (self.string_force(ys) / (self.paper.k1 * y0)).powf(1.0 / self.paper.p) - yt;
        let mut bracket = Bracket::new(0.0, yt);
        let mut ys = if guess > 0.0 && guess < yt { guess } else { 0.5 * yt };
        for _ in 0..200 {
            let gy = g(ys);
            bracket.narrow_past(ys, gy > 0.0);
            let f = self.string_force(ys);
            let slope = 1.0
                + y0 / self.paper.p
                    * (f / (self.paper.k1 * y0)).powf(1.0 / self.paper.p - 1.0)
                    * self.string_stiffness(ys)
                    / (self.paper.k1 * y0);
            // (a step that is not finite is not inside)
            let next = bracket.inside_or_mid(ys - gy / slope);
            if (next - ys).abs() <= 4.0 * f64::EPSILON * ys.max(f64::MIN_POSITIVE)
                || bracket.hi - bracket.lo <= 4.0 * f64::EPSILON * bracket.hi
            {
                return next;
            }
            ys = next;
        }
        ys
    }

    /// [`ContactLaw::state`] (`guess.0` is the previous `u`).
    fn stiffening_state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> ContactState {
        match phase {
            Phase::Compression => {
                let ys = self.stiffening_compression(yt);
                let force = self.string_force(ys);
                ContactState {
                    force,
                    ball_compression: force / self.paper.k1,
                    u: 0.0,
                    u_pow: 0.0,
                    string_deflection: ys,
                }
            }
            Phase::Expansion { y0 } => {
                let ys = self.stiffening_expansion(yt, y0, yt - guess.0 * y0);
                let force = self.string_force(ys);
                let u_pow = force / (self.paper.k1 * y0);
                let u = (yt - ys) / y0;
                ContactState { force, ball_compression: u * y0, u, u_pow, string_deflection: ys }
            }
        }
    }
}

impl ContactLaw for Stiffening {
    /// Stiffening strings with a positive stiffening fraction (a zero fraction is the paper's law).
    fn select(params: &Params) -> Option<Self> {
        let v = &params.variants;
        if v.strings == StringLaw::Stiffening && v.string_stiffening > 0.0 {
            let energy = 0.5 * params.ball.mass * params.impact.v1 * params.impact.v1;
            let paper = Cross::new(&params.ball, &params.strings);
            return Some(Stiffening::new(paper, v.string_stiffening, v.stiffening_deflection, energy));
        }
        None
    }

    /// The compression stiffness of the linear law (the strings' stiffness at zero deflection).
    fn compression_stiffness(&self) -> f64 {
        self.paper.compression_stiffness()
    }

    /// The ball is stiffest at maximum compression in expansion (`p k1`), in series with the
    /// strings at their largest deflection.
    fn max_stiffness(&self) -> f64 {
        let kb = self.paper.p * self.paper.k1;
        let ks = self.string_stiffness(self.deflection_bound);
        kb * ks / (kb + ks)
    }

    #[inline]
    fn state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> Result<ContactState> {
        if yt <= 0.0 {
            return Ok(ContactState::ZERO);
        }
        Ok(self.stiffening_state(yt, phase, guess))
    }

    fn stiffness(&self, phase: Phase, st: &ContactState) -> f64 {
        let kb = ball_stiffness(self.paper.k1, self.paper.p, phase, st);
        series(kb, self.string_stiffness(st.string_deflection))
    }

    fn ball_compression_at_max(&self, yt_max: f64) -> f64 {
        self.string_force(self.stiffening_compression(yt_max)) / self.paper.k1
    }

    #[inline]
    fn ball_energy_with_loss(&self, phase: Phase, st: &ContactState) -> f64 {
        self.paper.ball_energy_with_loss(phase, st)
    }

    /// `k_s (Y_s^2 / 2 + (s/d^2) Y_s^4 / 4)`.
    #[inline]
    fn string_energy(&self, st: &ContactState) -> f64 {
        let y2 = st.string_deflection * st.string_deflection;
        self.paper.ks * y2 * (0.5 + 0.25 * self.stiffening * y2)
    }

    fn ball_loss(&self, y0: f64) -> f64 {
        self.paper.ball_loss(y0)
    }
}
