//! The elastic law (`--tangential elastic`): the tangential grip-slip contact of the ball on the
//! strings, driven by the normal force (SPEC.md section 6), advanced in closed form.
//!
//! ```text
//! ball        m_b dv_t/dt = F_t,   I_b domega/dt = -R F_t,   I_b = alpha m_b R^2
//! frame       m_eff du/dt = -F_t   (u: the frame's tangential velocity at the contact point)
//!             1/m_eff = 1/M + (rho x t)^2 / I_z,   I_z = I_cm + I_x   (0 when head-clamped)
//! slip        w = v_t - R omega - u,   dw/dt = F_t / m_red,   1/m_red = 1/m_b + R^2/I_b + 1/m_eff
//! grip        F_t = -k_t s,   ds/dt = w                      while k_t |s| <= mu F_n
//! slide       F_t = -sigma mu F_n,   s = sigma mu F_n / k_t  while sigma (w - ds/dt) > 0
//! ```
//! `v_t` is the ball's velocity along `t` (the in-plane direction of its incoming velocity),
//! `omega` its spin with topspin positive (a ball rolling forward along `t` on still strings has
//! `w = 0`), `s` the deflection of the tangential spring (ball and string bed in series,
//! stiffness `k_t`), `sigma` the direction of the slip at the interface. The switch from grip to
//! slide happens when the spring's force reaches `mu F_n`; back to grip when the interface slip
//! stops. `rho` is the contact point from the racket's centre of mass in the string plane
//! (`x_load - x_cm` along the axis, `r` across it): the frame answers a tangential force as the
//! rigid body it is in its own plane, translation plus rotation about the string-plane normal
//! through its centre of mass, with `I_z` from the perpendicular-axis theorem for a flat frame
//! (the beam's own transverse moment of inertia `I_cm` plus `I_x`).
//!
//! The tangential force acts in the string plane, so it neither bends the beam nor twists it
//! about the long axis: the normal impact (Eqs 1-10) is exactly the normal-incidence impact at the
//! normal speed, and this law is driven by its force history `F_n(t)` alone. Each piece of that
//! history is a cubic in time (the solvers' Hermite interpolant of the force and its rate at both
//! ends of a step), and over a piece every quantity here
//! is advanced in closed form: a polynomial while sliding, a rotation while gripping. Switches are
//! found by sampling and located by bisection to rounding level, so the result does not depend
//! on how the history is cut into pieces (tested).
//!
//! Sources: R. Cross, "Grip-slip behavior of a bouncing ball", Am. J. Phys. 70 (2002) 1093-1102
//! (the tangential spring and the grip-slip switching); R. Cross, "Oblique impact of a tennis
//! ball on the strings of a tennis racket", Sports Eng. 6 (2003) 235-254 (the same picture on
//! strings). The point contact stays where it first touched: the ball's roll across the strings
//! during the impact (a few centimetres at 30 m/s) is not followed, and the normal force acts
//! through the ball's centre (no rolling resistance).

use super::piece::ForcePiece;

/// The tangential contact law of one impact.
#[derive(Debug, Clone, Copy)]
pub struct GripSlip {
    /// Friction coefficient of ball on strings.
    pub mu: f64,
    /// Tangential stiffness of ball and string bed in series, N/m.
    pub kt: f64,
    /// Ball mass, kg.
    pub mb: f64,
    /// Ball radius, m.
    pub radius: f64,
    /// Ball moment of inertia, kg m^2.
    pub inertia: f64,
    /// Inverse effective tangential mass of the frame at the contact point, 1/kg (0: clamped).
    pub racket_inv_mass: f64,
}

/// Whether the contact grips or slides.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mode {
    /// The contact region moves with the strings; the spring carries the force.
    Grip,
    /// The contact region slides; `sign` is the direction of the slip (+1 or -1).
    Slide { sign: f64 },
}

/// The tangential state, with the impulse from which the ball and frame velocities follow.
#[derive(Debug, Clone, Copy)]
pub struct Elastic {
    /// The law.
    law: GripSlip,
    /// `1 / m_red`, 1/kg.
    inv_red: f64,
    /// `sqrt(k_t / m_red)`, rad/s.
    omega_grip: f64,
    /// Incoming slip velocity `w` of the contact point, m/s.
    w0: f64,
    /// Tangential impulse on the ball so far, N s.
    pub impulse: f64,
    /// Spring deflection `s`, m (force on the ball `-k_t s`).
    pub s: f64,
    /// Grip or slide.
    pub mode: Mode,
    /// Energy dissipated by sliding, J.
    pub friction_loss: f64,
    /// Time spent sliding, s.
    pub slide_time: f64,
    /// Whether the contact has started (the first piece decides the first mode).
    started: bool,
}

/// Samples per piece in the search for a switch (plus one per radian of the grip oscillation).
const SAMPLES: usize = 8;
/// Bisection steps for a switch time (the piece length over 2^60: rounding level).
const BISECTIONS: usize = 60;

impl Elastic {
    /// The state before contact, for a ball whose contact point slips at `w0` (m/s) relative to
    /// the strings.
    pub fn new(law: GripSlip, w0: f64) -> Self {
        let inv_red = 1.0 / law.mb + law.radius * law.radius / law.inertia + law.racket_inv_mass;
        Elastic {
            law,
            inv_red,
            omega_grip: (law.kt * inv_red).sqrt(),
            w0,
            impulse: 0.0,
            s: 0.0,
            mode: Mode::Grip,
            friction_loss: 0.0,
            slide_time: 0.0,
            started: false,
        }
    }

    /// The most samples the switch search takes over a contact of `t` seconds (one per radian
    /// of the grip oscillation, besides a few per force piece).
    pub fn steps_within(&self, t: f64) -> f64 {
        self.omega_grip * t
    }

    /// Slip velocity of the contact point now, m/s.
    pub fn slip(&self) -> f64 {
        self.w0 + self.impulse * self.inv_red
    }

    /// Tangential force on the ball now, N.
    pub fn force(&self) -> f64 {
        -self.law.kt * self.s
    }

    /// Potential energy in the tangential spring, J.
    pub fn spring_energy(&self) -> f64 {
        0.5 * self.law.kt * self.s * self.s
    }

    /// Advance over one piece of the normal force history.
    pub fn advance(&mut self, piece: &ForcePiece) {
        if !self.started {
            self.started = true;
            self.mode = self.first_mode(piece);
        }
        let mut t = 0.0;
        // a switch always moves on in time or ends the piece; the count only guards rounding
        for _ in 0..64 {
            if t >= piece.h {
                return;
            }
            let (end, switched) = match self.mode {
                Mode::Slide { sign } => self.slide(piece, t, sign),
                Mode::Grip => self.grip(piece, t),
            };
            t = end;
            if !switched {
                return;
            }
        }
    }

    /// The mode at first contact (`F_n = 0`): slide with the slip, unless the spring can take
    /// the slip up as fast as the friction limit grows (`|w| <= mu F_n' / k_t`).
    fn first_mode(&self, piece: &ForcePiece) -> Mode {
        let w = self.slip();
        if w != 0.0 && self.law.kt * w.abs() > self.law.mu * piece.rate(0.0) {
            Mode::Slide { sign: w.signum() }
        } else {
            Mode::Grip
        }
    }

    /// Slide from `t0` until the interface slip stops or the piece ends; returns the time
    /// reached and whether the mode switched.
    fn slide(&mut self, piece: &ForcePiece, t0: f64, sign: f64) -> (f64, bool) {
        let (mu, kt) = (self.law.mu, self.law.kt);
        let (j0, i0) = (self.impulse, piece.integral(t0));
        let inv_red = self.inv_red;
        let w0 = self.w0;
        // sign times the interface slip w - ds/dt at time t
        let gap = |t: f64| {
            let j = j0 - sign * mu * (piece.integral(t) - i0);
            sign * (w0 + j * inv_red) - mu * piece.rate(t) / kt
        };
        let end = first_root(gap, t0, piece.h, SAMPLES);
        let t1 = end.unwrap_or(piece.h);
        self.friction_loss += gauss4(|t| mu * piece.force(t) * gap(t).max(0.0), t0, t1);
        self.impulse = j0 - sign * mu * (piece.integral(t1) - i0);
        self.s = sign * mu * piece.force(t1) / kt;
        self.slide_time += t1 - t0;
        if end.is_some() {
            self.mode = Mode::Grip;
        }
        (t1, end.is_some())
    }

    /// Grip from `t0` until the spring reaches the friction limit or the piece ends.
    fn grip(&mut self, piece: &ForcePiece, t0: f64) -> (f64, bool) {
        let (mu, kt, om) = (self.law.mu, self.law.kt, self.omega_grip);
        let (s0, w0) = (self.s, self.slip());
        let at = |t: f64| {
            let (sn, cs) = (om * (t - t0)).sin_cos();
            (s0 * cs + w0 / om * sn, -s0 * om * sn + w0 * cs)
        };
        // the spring's deflection never exceeds its amplitude: where the friction limit stays
        // above that over the rest of the piece no switch can happen, and the sampling (which
        // would find none either) is skipped; the margin covers the rounding of both sides
        let amplitude = s0.hypot(w0 / om);
        let end = if mu * piece.min_force(t0, piece.h) > kt * amplitude * (1.0 + 1e-9) {
            None
        } else {
            let samples = SAMPLES + (om * (piece.h - t0)) as usize;
            let margin = |t: f64| mu * piece.force(t) - kt * at(t).0.abs();
            // the samples' deflections by rotating the phasor `(s, (ds/dt)/om)` one sample
            // at a time (no trigonometric call per sample); the bracket found is bisected on
            // the closed form
            let dt = (piece.h - t0) / samples as f64;
            let (sn, cs) = (om * dt).sin_cos();
            let (mut s, mut p) = (s0, w0 / om);
            let mut lo = t0;
            let mut found = None;
            for k in 1..=samples {
                let hi = if k == samples { piece.h } else { t0 + dt * k as f64 };
                (s, p) = (s * cs + p * sn, p * cs - s * sn);
                if mu * piece.force(hi) - kt * s.abs() < 0.0 {
                    found = Some(bisect(margin, lo, hi));
                    break;
                }
                lo = hi;
            }
            found
        };
        let t1 = end.unwrap_or(piece.h);
        let (s1, w1) = at(t1);
        self.s = s1;
        self.impulse += (w1 - w0) / self.inv_red;
        if end.is_some() {
            self.mode = Mode::Slide { sign: s1.signum() };
        }
        (t1, end.is_some())
    }
}

/// The first time in `(t0, t1]` where `f` turns negative (after being positive), located by
/// sampling and bisection; `None` if it stays positive. A start at zero (just after a switch)
/// counts as positive.
fn first_root(f: impl Fn(f64) -> f64, t0: f64, t1: f64, samples: usize) -> Option<f64> {
    let dt = (t1 - t0) / samples as f64;
    let mut lo = t0;
    for k in 1..=samples {
        let hi = if k == samples { t1 } else { t0 + dt * k as f64 };
        if f(hi) < 0.0 {
            return Some(bisect(f, lo, hi));
        }
        lo = hi;
    }
    None
}

/// The sign change of `f` in `[lo, hi]` (`f(lo) >= 0 > f(hi)`) by bisection
/// ([`crate::numeric::root::bisect`]; zero counts as before, a NaN too): the first time where it
/// is negative, to rounding level.
fn bisect(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let before = |t| {
        let v = f(t);
        v >= 0.0 || v.is_nan()
    };
    crate::numeric::root::bisect(before, lo, hi, BISECTIONS).hi
}

/// Four-point Gauss-Legendre quadrature on [a, b] (exact for polynomials of degree 7).
fn gauss4(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const X: [f64; 2] = [0.339_981_043_584_856_3, 0.861_136_311_594_052_6];
    const W: [f64; 2] = [0.652_145_154_862_546_1, 0.347_854_845_137_453_9];
    let (m, r) = (0.5 * (a + b), 0.5 * (b - a));
    let mut s = 0.0;
    for i in 0..2 {
        s += W[i] * (f(m - r * X[i]) + f(m + r * X[i]));
    }
    s * r
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// A half-sine normal force of peak `f` over `tau`, as Hermite pieces.
    fn half_sine(f: f64, tau: f64, pieces: usize) -> Vec<ForcePiece> {
        let w = std::f64::consts::PI / tau;
        let h = tau / pieces as f64;
        (0..pieces)
            .map(|i| {
                let (a, b) = (i as f64 * h, (i + 1) as f64 * h);
                ForcePiece::hermite(
                    h,
                    (f * (w * a).sin(), f * w * (w * a).cos()),
                    (f * (w * b).sin(), f * w * (w * b).cos()),
                )
            })
            .collect()
    }

    fn ball(mu: f64, kt: f64) -> GripSlip {
        let (mb, r) = (0.057, 0.033);
        GripSlip { mu, kt, mb, radius: r, inertia: 0.55 * mb * r * r, racket_inv_mass: 0.0 }
    }

    fn run(law: GripSlip, w0: f64, pieces: &[ForcePiece]) -> Elastic {
        let mut t = Elastic::new(law, w0);
        for p in pieces {
            t.advance(p);
        }
        t
    }

    #[test]
    fn sliding_throughout_changes_v_t_by_mu_jn_over_m() {
        let pieces = half_sine(1000.0, 5e-3, 40);
        let jn: f64 = pieces.iter().map(|p| p.integral(p.h)).sum();
        let law = ball(0.2, 1e5);
        let t = run(law, 50.0, &pieces);
        assert_eq!(t.mode, Mode::Slide { sign: 1.0 });
        assert_relative_eq!(t.impulse, -0.2 * jn, max_relative = 1e-12);
        assert_relative_eq!(t.slide_time, 5e-3, max_relative = 1e-12);
    }

    #[test]
    fn gripping_with_a_stiff_spring_leaves_rolling() {
        let pieces = half_sine(1000.0, 5e-3, 400);
        let law = ball(0.8, 1e9);
        let (v, om) = (3.0, 0.0);
        let t = run(law, v - law.radius * om, &pieces);
        let v_out = v + t.impulse / law.mb;
        let om_out = om - law.radius * t.impulse / law.inertia;
        let alpha = 0.55;
        assert_relative_eq!(v_out, (v + alpha * law.radius * om) / (1.0 + alpha), max_relative = 1e-4);
        assert_relative_eq!(om_out * law.radius, v_out, max_relative = 1e-3);
    }

    #[test]
    fn energy_ledger_closes() {
        let pieces = half_sine(800.0, 5e-3, 37);
        for &(mu, kt, w) in &[(0.4, 2e4, 1.0), (0.4, 2e4, 5.0), (1.0, 1e5, 0.5), (0.3, 3e3, -2.0)] {
            let mut law = ball(mu, kt);
            law.racket_inv_mass = 1.0 / 0.3;
            let t = run(law, w, &pieces);
            let ke0 = 0.5 * w * w / t.inv_red;
            let w1 = t.slip();
            let ke1 = 0.5 * w1 * w1 / t.inv_red;
            assert_relative_eq!(ke0, ke1 + t.friction_loss + t.spring_energy(), max_relative = 1e-10);
            assert!(t.friction_loss >= 0.0);
        }
    }

    #[test]
    fn no_friction_no_change() {
        let pieces = half_sine(800.0, 5e-3, 37);
        let t = run(ball(0.0, 1e5), 4.0, &pieces);
        assert_eq!(t.impulse, 0.0);
        assert_eq!(t.friction_loss, 0.0);
    }

    /// The same cubic force cut into 1, 7 or 50 pieces gives the same result: the switches are
    /// located inside pieces, not at their ends.
    #[test]
    fn result_does_not_depend_on_how_the_history_is_cut() {
        let tau = 5e-3;
        let f = |t: f64| 4e8 * t * (tau - t) * (1e-3 + t);
        let df = |t: f64| 4e8 * ((tau - 2.0 * t) * (1e-3 + t) + t * (tau - t));
        let cut = |n: usize| {
            let h = tau / n as f64;
            (0..n)
                .map(|i| {
                    ForcePiece::hermite(
                        h,
                        (f(i as f64 * h), df(i as f64 * h)),
                        (f((i + 1) as f64 * h), df((i + 1) as f64 * h)),
                    )
                })
                .collect::<Vec<_>>()
        };
        for &(mu, kt, w) in &[(0.4, 2e4, 1.0), (0.4, 5e4, 6.0), (1.0, 1e5, 0.5), (0.3, 3e3, -2.0), (0.5, 1e6, 3.0)] {
            let mut law = ball(mu, kt);
            law.racket_inv_mass = 2.0;
            let one = run(law, w, &cut(1));
            for n in [7, 50] {
                let many = run(law, w, &cut(n));
                assert_relative_eq!(one.impulse, many.impulse, max_relative = 1e-11);
                assert_relative_eq!(one.friction_loss, many.friction_loss, max_relative = 1e-9, epsilon = 1e-15);
                assert_relative_eq!(one.slide_time, many.slide_time, max_relative = 1e-9, epsilon = 1e-15);
            }
        }
    }
}
