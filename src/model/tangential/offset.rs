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

use super::combined::sign0;
use super::compression::Compression;
use super::elastic::GripSlip;
use super::mechanism::{At, Ball, Drive, LossField, Mechanism, Sizes};

/// Tabor's moment arm of the normal force, m, for a contact circle of radius `a` (m) and the
/// hysteresis loss fraction `alpha_h`.
#[inline]
pub fn moment_arm(alpha_h: f64, a: f64) -> f64 {
    3.0 / 16.0 * alpha_h * a
}

/// The hysteresis loss fraction of the model's ball of exponent `p`: `1 - e^2` on a rigid
/// surface (SPEC Eq 12).
pub fn loss_fraction(p: f64) -> f64 {
    (p - 1.0) / (p + 1.0)
}

/// The mechanism: Tabor's offset of the normal force, a torque against the ball's spin while it
/// grips. Its mode is the sign of the spin the torque opposes, 0 while the torque holds the spin
/// at zero (while it can balance the friction's torque).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Offset {
    /// The hysteresis loss fraction `alpha_h` ([`loss_fraction`]).
    pub loss: f64,
    /// The ball's compression law, for the contact circle.
    pub compression: Compression,
}

impl Mechanism for Offset {
    /// The sign of the spin the torque opposes (0: held at zero).
    type Mode = f64;
    /// The largest torque, `d F_n`, N m.
    type Drive = f64;
    /// The energy the torque dissipates.
    const SLOTS: usize = 1;
    const GUARDED: bool = true;
    const COMPRESSION: bool = true;
    const TORQUE: bool = true;
    const LOSS: Option<LossField> = Some(LossField::Rolling);

    /// Tabor's arm for the model's ball (its exponent `p`), on the contact circle of the ball's
    /// compression.
    fn of(sizes: &Sizes) -> Offset {
        Offset { loss: loss_fraction(sizes.params.ball.p), compression: sizes.compression }
    }

    fn first_mode(&self, _: Ball, omega: f64, _: &GripSlip) -> f64 {
        sign0(omega)
    }

    #[inline]
    fn drive(&self, d: &Drive) -> f64 {
        moment_arm(self.loss, self.compression.contact_radius(d.delta)) * d.f
    }

    /// While the ball grips: `-sign(omega) d F_n`, or while held, what holds the spin at zero.
    #[inline]
    fn torque(&self, spin: f64, arm: &f64, at: &At) -> f64 {
        match (at.ball, spin) {
            (Ball::Slide(_), _) => 0.0,
            (Ball::Grip, 0.0) => -at.lever * at.path.p,
            (Ball::Grip, sign) => -sign * arm,
        }
    }

    /// `-torque omega`.
    #[inline]
    fn rates(&self, spin: f64, arm: &f64, at: &At, _: &[f64], out: &mut [f64]) {
        out[0] = -self.torque(spin, arm, at) * at.omega;
    }

    /// While the torque acts: the sign of the spin lasts while the spin keeps it; the hold lasts
    /// while `d F_n` can balance the friction's torque.
    #[inline]
    fn guard(&self, spin: f64, arm: &f64, at: &At, _: &[f64]) -> f64 {
        let capacity = if at.ball == Ball::Grip { *arm } else { 0.0 };
        match (capacity > 0.0, spin) {
            (false, _) => f64::INFINITY,
            (true, 0.0) => capacity - self.torque(spin, arm, at).abs(),
            (true, sign) => sign * at.omega,
        }
    }

    /// The spin passed zero: held there; or the hold gave way: it turns with the friction.
    fn switch(&self, spin: f64, at: &At, _: &[f64]) -> f64 {
        if spin == 0.0 {
            sign0(at.lever * at.path.p)
        } else {
            0.0
        }
    }

    fn ball_switched(&self, _: f64, omega: f64) -> f64 {
        sign0(omega)
    }
}
