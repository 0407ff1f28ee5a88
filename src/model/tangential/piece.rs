//! One piece of the normal force history, the input every tangential law advances over: the
//! solvers (fd and modal) cut the normal impact's force `F_n(t)` into steps and hand each step
//! to the law as the cubic Hermite interpolant of the force and its rate at both ends.

/// One piece of the normal force history: `F_n(t0 + tau) = a0 + a1 tau + a2 tau^2 + a3 tau^3`
/// for `0 <= tau <= h`.
#[derive(Debug, Clone, Copy)]
pub struct ForcePiece {
    /// Length, s.
    pub h: f64,
    /// Monomial coefficients.
    pub a: [f64; 4],
}

impl ForcePiece {
    /// The cubic through the force `f0, f1` and its rate `d0, d1` at both ends of a step `h`.
    pub fn hermite(h: f64, (f0, d0): (f64, f64), (f1, d1): (f64, f64)) -> Self {
        let a2 = (3.0 * (f1 - f0) - h * (2.0 * d0 + d1)) / (h * h);
        let a3 = (2.0 * (f0 - f1) + h * (d0 + d1)) / (h * h * h);
        ForcePiece { h, a: [f0, d0, a2, a3] }
    }

    /// The force at `tau`.
    pub fn force(&self, t: f64) -> f64 {
        let a = &self.a;
        a[0] + t * (a[1] + t * (a[2] + t * a[3]))
    }

    /// Its rate at `tau`.
    pub fn rate(&self, t: f64) -> f64 {
        let a = &self.a;
        a[1] + t * (2.0 * a[2] + t * 3.0 * a[3])
    }

    /// The times where the rate vanishes (NaN where it does not).
    pub fn turning_points(&self) -> [f64; 2] {
        // rate a1 + 2 a2 t + 3 a3 t^2 = 0
        let (a, b, c) = (3.0 * self.a[3], 2.0 * self.a[2], self.a[1]);
        if a == 0.0 {
            if b != 0.0 {
                [-c / b, f64::NAN]
            } else {
                [f64::NAN; 2]
            }
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc >= 0.0 {
                let r = disc.sqrt();
                [(-b - r) / (2.0 * a), (-b + r) / (2.0 * a)]
            } else {
                [f64::NAN; 2]
            }
        }
    }

    /// The smallest force over `[t0, t1]`: at an end or where the rate vanishes inside.
    pub fn min_force(&self, t0: f64, t1: f64) -> f64 {
        let inside = self.turning_points().into_iter().filter(|&t| t > t0 && t < t1);
        inside.fold(self.force(t0).min(self.force(t1)), |least, t| least.min(self.force(t)))
    }

    /// The largest force over `[t0, t1]`, given the piece's `turning` points
    /// ([`Self::turning_points`]).
    pub fn max_force(&self, turning: &[f64; 2], t0: f64, t1: f64) -> f64 {
        let inside = turning.iter().filter(|&&t| t > t0 && t < t1);
        inside.fold(self.force(t0).max(self.force(t1)), |most, &t| most.max(self.force(t)))
    }

    /// Its integral from 0 to `tau`.
    pub fn integral(&self, t: f64) -> f64 {
        let a = &self.a;
        t * (a[0] + t * (a[1] / 2.0 + t * (a[2] / 3.0 + t * a[3] / 4.0)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smallest_and_largest_force_of_a_piece_match_fine_sampling() {
        let pieces = [
            ForcePiece { h: 2.0, a: [1.0, -3.0, 0.5, 0.7] },
            ForcePiece { h: 1.0, a: [0.0, 2.0, -1.0, 0.0] },
            ForcePiece { h: 1.0, a: [5.0, 0.0, 0.0, 0.0] },
            ForcePiece { h: 3.0, a: [-1.0, 4.0, -3.0, 0.6] },
        ];
        for p in pieces {
            for (t0, t1) in [(0.0, p.h), (0.3, p.h), (0.1, 0.2 * p.h)] {
                let sampled = (0..=100_000).map(|i| p.force(t0 + (t1 - t0) * i as f64 / 1e5)).fold(f64::MAX, f64::min);
                let least = p.min_force(t0, t1);
                assert!(
                    least <= sampled + 1e-12 && least >= sampled - 1e-8,
                    "{p:?} [{t0}, {t1}]: {least} vs {sampled}"
                );
                let sampled = (0..=100_000).map(|i| p.force(t0 + (t1 - t0) * i as f64 / 1e5)).fold(f64::MIN, f64::max);
                let most = p.max_force(&p.turning_points(), t0, t1);
                assert!(most >= sampled - 1e-12 && most <= sampled + 1e-8, "{p:?} [{t0}, {t1}]: {most} vs {sampled}");
            }
        }
    }
}
