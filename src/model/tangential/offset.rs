//! Mechanism `offset`: a deformed ball rolling or spinning on a surface is pushed back by a
//! normal force that acts ahead of its centre, a torque `-sign(omega) d F_n` that opposes its
//! spin (Cross 2002, "Grip-slip behavior of a bouncing ball", Am. J. Phys. 70, 1093, and 2005,
//! "Bounce of a spinning ball near normal incidence", measured the effect on tennis balls).
//!
//! Source of its size (a derivation): D. Tabor's hysteresis theory of rolling friction
//! ("The mechanism of rolling friction II", Proc. R. Soc. A 229, 1955) gives for a sphere
//! on a flat a moment arm `d = (3/16) alpha_h a`, with `a` the radius of the contact circle
//! and `alpha_h` the fraction of the elastic energy lost per cycle. Here
//! `alpha_h = 1 - e^2 = (p - 1)/(p + 1)` is the model's own ball (SPEC Eq 12) and `a` follows
//! from the ball's compression `delta` (its dynamic stiffness `ball-kdyn`) as the chord of the
//! flattened cap,
//! `a = sqrt(2 R delta - delta^2)` ([`super::radius`]). The torque acts while the ball grips
//! (rolls on the strings, Tabor's case); while it slides the friction torque governs, and
//! without friction the ball's spin is left alone.

/// Tabor's moment arm of the normal force, m, for a contact circle of radius `a` (m) and the
/// hysteresis loss fraction `alpha_h`.
pub fn moment_arm(alpha_h: f64, a: f64) -> f64 {
    3.0 / 16.0 * alpha_h * a
}

/// The hysteresis loss fraction of the model's ball of exponent `p`: `1 - e^2` on a rigid
/// surface (SPEC Eq 12).
pub fn loss_fraction(p: f64) -> f64 {
    (p - 1.0) / (p + 1.0)
}
