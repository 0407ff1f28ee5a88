//! Mechanism `loss`: the ball's tangential deformation is not perfectly elastic. A viscous
//! damper `c` in parallel with the tangential spring `k_t` (a Kelvin-Voigt element) dissipates
//! `c (ds/dt)^2` while the spring works.
//!
//! Source of its size: the measured tangential coefficient of restitution of a gripping tennis
//! ball, `e_x = -(v_x2 - R w_2) / (v_x1 - R w_1)` = 0.10-0.17 (Cross 2002, "Grip-slip behavior
//! of a bouncing ball", Am. J. Phys. 70, Table III; data/measured M079-M080; the parameter
//! `ball-ex`). The relation used: while the ball grips, its contact point is a damped
//! oscillator on `k_t` carrying the reduced mass `m_red` (`1/m_red = 1/m_b + R^2/I_b + 1/m_frame`),
//! and `e_x` is what it returns over one half cycle, from the spring relaxed to relaxed again:
//! `e_x = exp(-pi zeta / sqrt(1 - zeta^2))`, so `zeta = -ln e_x / sqrt(pi^2 + ln^2 e_x)`
//! (0.54 for `e_x` = 0.135) and `c = 2 zeta sqrt(k_t m_red)`. On an immovable frame a ball
//! that grips for that half cycle leaves with exactly `e_x` (tested); a contact that ends
//! earlier or later returns a little more or less.

use super::mechanism::{At, LossField, Mechanism, Sizes};

/// The damping ratio of the tangential grip oscillation that returns the tangential
/// restitution `e_x` (0 < e_x < 1) over one half cycle.
pub fn damping_ratio(e_x: f64) -> f64 {
    let ln_e = e_x.ln();
    -ln_e / (std::f64::consts::PI.powi(2) + ln_e * ln_e).sqrt()
}

/// The damper `c`, N s/m, of damping ratio `zeta` on a spring `kt` (N/m) carrying the reduced
/// mass `1 / inv_red` (kg).
#[inline]
pub fn damper(zeta: f64, kt: f64, inv_red: f64) -> f64 {
    2.0 * zeta * (kt / inv_red).sqrt()
}

/// The length of that half cycle, s: `pi / (w0 sqrt(1 - zeta^2))`, `w0 = sqrt(k_t / m_red)`.
pub fn half_period(zeta: f64, kt: f64, inv_red: f64) -> f64 {
    std::f64::consts::PI / ((kt * inv_red).sqrt() * (1.0 - zeta * zeta).sqrt())
}

/// The mechanism: the damper on the ball's tangential spring.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loss {
    /// The damper, N s/m.
    pub c: f64,
}

impl Mechanism for Loss {
    type Mode = ();
    type Drive = ();
    /// The energy the damper dissipates.
    const SLOTS: usize = 1;
    const LOSS: Option<LossField> = Some(LossField::Damping);

    /// The damper that returns `ball-ex` over half a grip cycle.
    fn of(sizes: &Sizes) -> Loss {
        let o = &sizes.params.oblique;
        Loss { c: damper(damping_ratio(o.ball_ex), sizes.base.kt, sizes.inv_red()) }
    }

    #[inline]
    fn damper(&self) -> f64 {
        self.c
    }

    /// `c (ds/dt)^2`.
    #[inline]
    fn rates(&self, _: (), _: &(), at: &At, _: &[f64], out: &mut [f64]) {
        out[0] = self.c * at.path.sdot * at.path.sdot;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_cycle_restitution_is_e_x() {
        for e_x in [0.10, 0.135, 0.17, 0.5, 0.9] {
            let z = damping_ratio(e_x);
            let e = (-std::f64::consts::PI * z / (1.0 - z * z).sqrt()).exp();
            assert!((e - e_x).abs() < 1e-12, "{e_x}: {e}");
        }
        assert!((damping_ratio(0.135) - 0.5375).abs() < 5e-4);
    }
}
