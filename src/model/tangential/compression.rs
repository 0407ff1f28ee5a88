//! The ball's compression under the normal force, shared by the mechanisms whose lever or arm
//! follows it (`radius`, `offset`): its law and the contact circle it sets. The source of the
//! dynamic stiffness `k` is given in [`super::radius`].

/// The ball's compression law, from the normal force alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compression {
    /// Dynamic compression stiffness `k`, N/m.
    pub k: f64,
    /// Hysteresis exponent `p`.
    pub p: f64,
    /// Ball radius, m.
    pub radius: f64,
}

impl Compression {
    /// The radius of the contact circle, m, at the compression `delta` (the offset's arm,
    /// [`super::offset`]).
    #[inline]
    pub fn contact_radius(&self, delta: f64) -> f64 {
        (2.0 * self.radius * delta - delta * delta).max(0.0).sqrt()
    }

    /// The compression, m, at the force `f` (N) after the largest force so far `f_max`.
    #[inline]
    pub fn delta(&self, f: f64, f_max: f64) -> f64 {
        let f = f.max(0.0);
        let d = if f >= f_max || f_max <= 0.0 {
            f / self.k
        } else {
            let y0 = f_max / self.k;
            y0 * (f / f_max).powf(1.0 / self.p)
        };
        d.min(self.radius)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compression_follows_the_ball_law_and_is_continuous_at_the_turn() {
        let c = Compression { k: 3.0e4, p: 2.55, radius: 0.033 };
        assert_eq!(c.delta(300.0, 300.0), 0.01);
        assert!((c.delta(300.0 * (1.0 - 1e-12), 300.0) - 0.01).abs() < 1e-12);
        assert!(c.delta(150.0, 300.0) > c.delta(150.0, 150.0));
        assert_eq!(c.delta(1e6, 1e6), 0.033);
        assert!((c.contact_radius(0.033) - 0.033).abs() < 1e-15);
    }
}
