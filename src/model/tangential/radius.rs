//! Mechanism `radius`: the friction force acts at the contact face of the deformed ball, at
//! `R - delta` from its centre rather than `R` (`delta` the ball's compression), so it spins the
//! ball less per unit of force. The compression is the model's own (SPEC Eqs 3-4): the normal
//! force is the same in ball and strings, so `delta = F / k1` while the ball is compressed and
//! `delta = Y0 (F / (k1 Y0))^(1/p)` on the way back (`Y0 = F_max / k1`). The contact circle of
//! the flattened cap, `a = sqrt(2 R delta - delta^2)`, sets the offset arm ([`super::offset`]).
//! The compression is capped at `R` (the lever never turns negative).

/// The ball's compression law, from the normal force alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compression {
    /// Compression stiffness `k1`, N/m.
    pub k1: f64,
    /// Hysteresis exponent `p`.
    pub p: f64,
    /// Ball radius, m.
    pub radius: f64,
}

impl Compression {
    /// The compression, m, at the force `f` (N) after the largest force so far `f_max`.
    pub fn delta(&self, f: f64, f_max: f64) -> f64 {
        let f = f.max(0.0);
        let d = if f >= f_max || f_max <= 0.0 {
            f / self.k1
        } else {
            let y0 = f_max / self.k1;
            y0 * (f / f_max).powf(1.0 / self.p)
        };
        d.min(self.radius)
    }

    /// The radius of the contact circle, m, at the compression `delta`.
    pub fn contact_radius(&self, delta: f64) -> f64 {
        (2.0 * self.radius * delta - delta * delta).max(0.0).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compression_follows_the_ball_law_and_is_continuous_at_the_turn() {
        let c = Compression { k1: 3.0e4, p: 2.55, radius: 0.033 };
        assert_eq!(c.delta(300.0, 300.0), 0.01);
        assert!((c.delta(300.0 * (1.0 - 1e-12), 300.0) - 0.01).abs() < 1e-12);
        assert!(c.delta(150.0, 300.0) > c.delta(150.0, 150.0));
        assert_eq!(c.delta(1e6, 1e6), 0.033);
        assert!((c.contact_radius(0.033) - 0.033).abs() < 1e-15);
    }
}
