//! Reduced cases with closed-form or quadrature solutions (paper p. 3, "Ball parameters").
//!
//! **Rigid slab** (the 100-inch concrete drop). Compression is a quarter period of
//! `sqrt(k1/m_b)`; in expansion energy conservation gives the speed at each compression, so
//! ```text
//! tau = (pi/2) sqrt(m_b/k1) + sqrt(m_b (p+1) / (2 k1)) B(1/(p+1), 1/2) / (p+1)
//! e   = sqrt(2 / (p+1))                                                       (Eq 12)
//! ```
//! both independent of the drop speed and, for `e`, of the mass.
//!
//! **Head-clamped racket**: ball and strings in series against a fixed frame. Compression is a
//! quarter period of the series stiffness; in expansion (Eq 10) the recoverable energy at ball
//! compression `Y_b = u Y0` is `E(u) = k1 Y0^2 u^(p+1)/(p+1) + (k1 Y0 u^p)^2 / (2 k_s)`, so
//! `e = sqrt(E(1) / (m_b v1^2 / 2))` and the expansion time is the quadrature
//! `int_0^1 Y0 (1 + p (k1/k_s) u^(p-1)) du / sqrt(2 (E(1) - E(u)) / m_b)`, evaluated after the
//! substitution `u = 1 - w^2` that removes the inverse-square-root end point.

use crate::params::{Ball, Strings};

/// Outcome of a drop on a fixed support.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct DropResult {
    /// Contact duration, s.
    pub tau_s: f64,
    /// Coefficient of restitution.
    pub e: f64,
    /// Time to maximum compression, s.
    pub t_max_compression_s: f64,
    /// Maximum ball compression `Y0`, m.
    pub y0_m: f64,
    /// Peak force, N.
    pub peak_force_n: f64,
}

/// The 100-inch drop on concrete (a rigid slab), closed form.
pub fn concrete_drop(ball: &Ball, v1: f64) -> DropResult {
    let (m, k1, p) = (ball.mass, ball.k1, ball.p);
    let q = p + 1.0;
    let t_c = 0.5 * std::f64::consts::PI * (m / k1).sqrt();
    // Euler's beta function B(1/(p+1), 1/2) (statrs; NaN, as the rest of the formula gives,
    // for a ball whose p has not been validated to exceed 1)
    let beta = statrs::function::beta::checked_beta(1.0 / q, 0.5).unwrap_or(f64::NAN);
    let t_e = (m * q / (2.0 * k1)).sqrt() * beta / q;
    let y0 = v1 * (m / k1).sqrt();
    DropResult { tau_s: t_c + t_e, e: (2.0 / q).sqrt(), t_max_compression_s: t_c, y0_m: y0, peak_force_n: k1 * y0 }
}

/// A drop on the strings of a head-clamped racket (frame fixed), by quadrature.
pub fn clamped_drop(ball: &Ball, strings: &Strings, v1: f64) -> DropResult {
    let (m, k1, p, ks) = (ball.mass, ball.k1, ball.p, strings.ks);
    let q = p + 1.0;
    let k_series = k1 * ks / (k1 + ks);
    let t_c = 0.5 * std::f64::consts::PI * (m / k_series).sqrt();
    let yt_max = v1 * (m / k_series).sqrt();
    let y0 = ks * yt_max / (k1 + ks);
    let f0 = k1 * y0;
    let alpha = k1 / ks;
    // E(1) - E(1 - w^2), computed without cancellation near w = 0
    let drop = |w: f64| {
        let ln_u = (-w * w).ln_1p();
        let one_minus = |k: f64| -(k * ln_u).exp_m1();
        f0 * y0 * one_minus(q) / q + f0 * f0 * one_minus(2.0 * p) / (2.0 * ks)
    };
    let integrand = |w: f64| {
        if w == 0.0 {
            // limit: E(1) - E(1-w^2) ~ E'(1) w^2 with E'(1) = f0 Y0 + f0^2 p / (k1 ks) ... per unit u
            let e_prime = f0 * y0 + f0 * f0 * p / ks;
            return 2.0 * y0 * (1.0 + p * alpha) / (2.0 * e_prime / m).sqrt();
        }
        let u = 1.0 - w * w;
        y0 * (1.0 + p * alpha * u.powf(p - 1.0)) * 2.0 * w / (2.0 * drop(w) / m).sqrt()
    };
    let t_e = gauss_legendre(integrand, 0.0, 1.0, 400);
    let e_rec = f0 * y0 / q + f0 * f0 / (2.0 * ks);
    DropResult {
        tau_s: t_c + t_e,
        e: (e_rec / (0.5 * m * v1 * v1)).sqrt(),
        t_max_compression_s: t_c,
        y0_m: y0,
        peak_force_n: f0,
    }
}

/// Composite 5-point Gauss-Legendre quadrature on `panels` equal panels.
fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    const X: [f64; 5] =
        [0.0, -0.538_469_310_105_683_1, 0.538_469_310_105_683_1, -0.906_179_845_938_664, 0.906_179_845_938_664];
    const W: [f64; 5] = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
        0.236_926_885_056_189_1,
    ];
    let h = (b - a) / panels as f64;
    let mut sum = 0.0;
    for k in 0..panels {
        let mid = a + (k as f64 + 0.5) * h;
        for (x, w) in X.iter().zip(W) {
            sum += w * f(mid + 0.5 * h * x);
        }
    }
    0.5 * h * sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn lossless_ball_on_concrete_is_half_a_period() {
        let ball = Ball { mass: 0.05, k1: 2.0e4, p: 1.0 + 1e-12 };
        let d = concrete_drop(&ball, 3.0);
        assert_relative_eq!(d.tau_s, std::f64::consts::PI * (0.05_f64 / 2.0e4).sqrt(), max_relative = 1e-9);
        assert_relative_eq!(d.e, 1.0, max_relative = 1e-9);
    }

    #[test]
    fn very_stiff_strings_approach_concrete() {
        let ball = Ball::default();
        let c = concrete_drop(&ball, 7.0);
        let s = clamped_drop(&ball, &Strings { ks: 1e12 }, 7.0);
        assert_relative_eq!(s.tau_s, c.tau_s, max_relative = 1e-6);
        assert_relative_eq!(s.e, c.e, max_relative = 1e-6);
    }
}
