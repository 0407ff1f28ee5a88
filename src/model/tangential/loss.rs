//! Mechanism `loss`: the ball's tangential deformation is not perfectly elastic. A viscous
//! damper `c` in parallel with the tangential spring `k_t` (a Kelvin-Voigt element) dissipates
//! `c (ds/dt)^2` while the spring works.
//!
//! Source of its size (a derivation, not a fit): the ball's rubber loses the same fraction of
//! its stored energy in shear as in compression. On a rigid surface the model's ball returns
//! `e^2 = 2 / (p + 1)` of its normal energy (SPEC Eq 12; `p = 2.55` gives `e = 0.751`, inside
//! the ITF rebound specification 135-147 cm from 254 cm, `e = 0.73-0.76`, data/measured
//! M017-M018). A tangential grip oscillation that completes one half cycle then returns the
//! tangential speed times the same `e`; for a damped oscillator that is
//! `e = exp(-pi zeta / sqrt(1 - zeta^2))`, so `zeta = -ln e / sqrt(pi^2 + ln^2 e)` (0.091 for the
//! paper's ball) and `c = 2 zeta sqrt(k_t m_red)`. Cross (2005, "Bounce of a spinning ball near
//! normal incidence", Am. J. Phys. 73, 914) reports measured tangential COR values of tennis
//! balls, but they could not be read (data/measured/README), so this derivation stands in.

/// The damping ratio of the tangential grip oscillation for a ball of hysteresis exponent `p`
/// (the same restitution per half cycle in shear as in compression).
pub fn damping_ratio(p: f64) -> f64 {
    let ln_e = (2.0 / (p + 1.0)).sqrt().ln();
    -ln_e / (std::f64::consts::PI.powi(2) + ln_e * ln_e).sqrt()
}

/// The damper `c`, N s/m, of damping ratio `zeta` on a spring `kt` (N/m) carrying the reduced
/// mass `1 / inv_red` (kg).
pub fn damper(zeta: f64, kt: f64, inv_red: f64) -> f64 {
    2.0 * zeta * (kt / inv_red).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_cycle_restitution_is_the_normal_one() {
        for p in [1.5, 2.55, 4.0] {
            let z = damping_ratio(p);
            let e = (-std::f64::consts::PI * z / (1.0 - z * z).sqrt()).exp();
            assert!((e - (2.0 / (p + 1.0)).sqrt()).abs() < 1e-12, "{p}: {e}");
        }
        assert!((damping_ratio(2.55) - 0.0909).abs() < 5e-4);
    }
}
