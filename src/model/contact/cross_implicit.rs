//! The modal solver's end-of-step solve of the paper's law ([`ImplicitLaw`] for [`Cross`]).
//!
//! In expansion the end force `F1 = k1 Y0 u^p` and rate `D1` of a step satisfy Eq 10 with the
//! step's coupling ([`StepCoupling`]) in series with the strings:
//! `u + (k1/k_s + bf k1) u^p = z` with `z = (Y_hat - bd D1) / Y0`, the rate `D1 = F'(Y_T) Y_T'`
//! updated from each iterate (its coupling `bd` is of order `h^3`).

use crate::error::{Error, Result};
use crate::model::contact::{ContactLaw, ContactState, Cross, EndContact, ImplicitLaw, Phase, StepCoupling};

impl ImplicitLaw for Cross {
    /// The previous `u` moved along its rate: `dY_T = Y0 (1 + alpha p u^(p-1)) du`.
    #[inline]
    fn expansion_start(&self, y0: f64, prev: (f64, f64), ytd: f64, h: f64) -> (f64, f64) {
        let (u0, up0) = prev;
        let r0 = if u0 > 0.0 { self.p * up0 / u0 } else { 0.0 };
        let u1 = u0 + h * ytd / (y0 * (1.0 + r0 * self.k1 / self.ks));
        if u1 > 0.0 && u0 > 0.0 {
            self.pow.advance_fast(u0, up0, u1 / u0 - 1.0)
        } else {
            (0.0, 0.0)
        }
    }

    /// Newton on `u + (k1/k_s + bf k1) u^p = z` from `start = (u, u^p)`, with `D1` updated from
    /// each iterate from its first guess `d_guess`. Each iterate and its power come from the
    /// previous pair by the binomial series ([`PowSeries::advance`](crate::model::contact::PowSeries::advance)),
    /// so a good start needs no power function.
    fn expansion_end(
        &self,
        coupling: &StepCoupling,
        y0: f64,
        pred: (f64, f64),
        start: (f64, f64),
        d_guess: f64,
    ) -> Result<Option<EndContact>> {
        let c = self;
        let grid = coupling;
        let (yh, ydh) = pred;
        if yh <= 0.0 {
            return Ok(None);
        }
        let (alpha, p) = (c.k1 / c.ks, c.p);
        let beta = alpha + grid.bf * c.k1;
        let inv_y0 = 1.0 / y0;
        let (mut u, mut up) = start;
        let mut d1 = d_guess;
        let mut z = (yh - grid.bd * d1) * inv_y0;
        if z <= 0.0 {
            return Ok(None);
        }
        if !(u > 0.0 && up > 0.0 && u <= 1.0) {
            // no usable start: the upper bound min(z, 1) of the root
            u = z.min(1.0);
            up = self.pow.power_fast(u);
        }
        let mut inv_u = 1.0 / u;
        for _ in 0..100 {
            // Newton on an increasing convex function: from the left it lands right of the
            // root, from the right it stays there; halving only guards against rounding
            let r = p * up * inv_u;
            let step = (u + beta * up - z) / (1.0 + beta * r);
            let delta = (-step * inv_u).max(-0.5);
            (u, up) = self.pow.advance_fast(u, up, delta);
            inv_u = 1.0 / u;
            // dF/dY_T along Eq 10 with the strings in series, and the rate from it
            let r = p * up * inv_u;
            let f1 = c.k1 * y0 * up;
            d1 = c.k1 * r * (ydh - grid.cf * f1) / (1.0 + r * (alpha + c.k1 * grid.cd));
            let z_new = (yh - grid.bd * d1) * inv_y0;
            let moved = (z_new - z).abs();
            z = z_new;
            if z <= 0.0 {
                return Ok(None);
            }
            // after a Newton step of 1e-8 the error is of order 1e-16
            if delta.abs() <= 1e-8 && moved <= 1e-15 * z {
                return Ok(Some(EndContact { f: f1, d: d1, u: (u, up) }));
            }
        }
        Err(Error::ContactSolve { z })
    }

    /// `F'(Y) (Y_law(f) - ym)`, with Eq 10 inverted explicitly (`Y_law(F) = Y0 u + F/k_s`,
    /// `u = (F/(k1 Y0))^(1/p)`).
    fn expansion_miss(&self, y0: f64, ym: f64, f: f64) -> f64 {
        let c = self;
        if f <= 0.0 {
            // no negative force is physical; the law lies between 0 and k_s Y_T (Y_T >= F/k_s),
            // so the miss is at most this
            return f - c.compression_stiffness() * ym.max(0.0);
        }
        let up = f / (c.k1 * y0);
        // (the p-th root through the logarithm: a few times cheaper than `powf`, and accurate
        // to rounding for a miss)
        let u = (up.ln() / c.p).exp();
        let r = c.p * up / u;
        let kappa = c.k1 * r / (1.0 + r * c.k1 / c.ks);
        kappa * (y0 * u + f / c.ks - ym)
    }

    #[inline]
    fn state_at_force(&self, phase: Phase, f: f64, u: (f64, f64)) -> ContactState {
        let c = self;
        match phase {
            Phase::Compression => {
                ContactState { force: f, ball_compression: f / c.k1, u: 0.0, u_pow: 0.0, string_deflection: f / c.ks }
            }
            Phase::Expansion { y0 } => {
                ContactState { force: f, ball_compression: u.0 * y0, u: u.0, u_pow: u.1, string_deflection: f / c.ks }
            }
        }
    }
}
