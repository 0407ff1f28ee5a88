//! Mechanism `bed`: the strings under the ball move sideways. The set of strings that the
//! tangential force pushes across (the mains for a ball moving across the face) slides over the
//! other set against string-to-string friction and is pulled back by its tension: a lateral
//! spring `k_lat` in series with the ball's tangential spring, with a Coulomb slider of limit
//! `mu_ss N` in parallel. While the slider sticks the bed does not move; when the force on it
//! exceeds the limit the strings slide, and as the normal force falls at the end of the contact
//! the limit falls with it and the strings snap back, returning their stored energy to the ball
//! (if it still grips) or losing it to the sliding.
//!
//! Sizes (derived, not fitted):
//! - `k_lat = k_s / 2`. A string under tension `T` resists a sideways displacement at a point
//!   with the same geometric stiffness `T (1/a + 1/b)` in the string plane as out of it; the
//!   string-plane stiffness `k_s` of the normal impact is that of both sets under the ball,
//!   and only one set is pushed across, so it carries half of it. `k_s` follows the tension
//!   (`ks_from_tension_lb`).
//! - `N = F_n / 2`: the set pushed across carries half the ball's load (equal tension and
//!   spacing of mains and crosses near the centre) and presses that share onto the other set
//!   at the crossings. This is an assumption of the weave, stated as one.
//! - `mu_ss`: the string-to-string friction coefficient of the string in use (TWU string
//!   database, data/strings).

use super::elastic::GripSlip;
use super::mechanism::{At, Ball, Interface, LossField, Mechanism, Pace, Path, Sizes, SUBSTEP};

/// The lateral string bed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bed {
    /// Lateral stiffness, N/m.
    pub k_lat: f64,
    /// String-to-string friction coefficient.
    pub mu_ss: f64,
    /// Share of the normal force that presses the moving set onto the other.
    pub share: f64,
}

impl Bed {
    /// The bed of a string plane of stiffness `ks` (N/m) strung with string-to-string friction
    /// `mu_ss`.
    pub fn of(ks: f64, mu_ss: f64) -> Bed {
        Bed { k_lat: 0.5 * ks, mu_ss, share: 0.5 }
    }

    /// The friction limit, N, at the normal force `f`.
    #[inline]
    pub fn limit(&self, f: f64) -> f64 {
        self.mu_ss * self.share * f.max(0.0)
    }

    /// Its rate, N/s, at the normal force rate `df`.
    #[inline]
    pub fn limit_rate(&self, df: f64) -> f64 {
        self.mu_ss * self.share * df
    }
}

/// Stick or slide of the moving strings over the others.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Strings {
    /// Held by the string-to-string friction: the bed does not move.
    #[default]
    Stuck,
    /// Sliding, in the direction of the sign (+1 or -1).
    Slide(f64),
}

/// The lateral deflection of the strings, m, and the energy lost to their sliding, J.
const Q: usize = 0;

impl Mechanism for Bed {
    type Mode = Strings;
    type Drive = ();
    /// The strings' lateral deflection `q`, then the energy their sliding dissipates.
    const SLOTS: usize = 2;
    const GUARDED: bool = true;
    const SERIES: bool = true;
    const LOSS: Option<LossField> = Some(LossField::StringSliding);

    /// The bed of the impact's string plane (`k_s`) and string-to-string friction.
    fn of(sizes: &Sizes) -> Bed {
        Bed::of(sizes.params.strings.ks, sizes.mu_ss)
    }

    /// The strings slide at once if the ball slides and its friction can push them.
    fn first_mode(&self, ball: Ball, _: f64, base: &GripSlip) -> Strings {
        match ball {
            Ball::Slide(sign) if base.mu > self.mu_ss * self.share => Strings::Slide(sign),
            _ => Strings::Stuck,
        }
    }

    /// While the strings slide: the lateral spring `k_lat q` and the slider's limit carry the
    /// force, in series with the ball's spring (and its damper).
    #[inline]
    fn path(&self, mode: Strings, own: &[f64], i: &Interface) -> Option<Path> {
        let Strings::Slide(sb) = mode else { return None };
        let q = own[Q];
        Some(match i.ball {
            Ball::Grip => {
                let p = self.k_lat * q + sb * self.limit(i.f);
                let sdot = if i.c > 0.0 {
                    (p - i.kt * i.s) / i.c
                } else {
                    (self.k_lat * i.w + sb * self.limit_rate(i.df)) / (i.kt + self.k_lat)
                };
                Path { p: if i.c > 0.0 { p } else { i.kt * i.s }, sdot, rest: i.w - sdot }
            }
            Ball::Slide(sign) => {
                let Path { p, sdot, .. } = i.rigid();
                Path { p, sdot, rest: (sign * i.mu * i.df - sb * self.limit_rate(i.df)) / self.k_lat }
            }
        })
    }

    /// `dq/dt`, and the slider's work `limit dq/dt` while the strings slide.
    #[inline]
    fn rates(&self, mode: Strings, _: &(), at: &At, _: &[f64], out: &mut [f64]) {
        out[Q] = at.path.rest;
        out[1] = match mode {
            Strings::Slide(sb) => sb * self.limit(at.drive.f) * at.path.rest,
            Strings::Stuck => 0.0,
        };
    }

    /// Stuck while the force on the slider stays within its limit; sliding while they move.
    #[inline]
    fn guard(&self, mode: Strings, _: &(), at: &At, own: &[f64]) -> f64 {
        match mode {
            Strings::Stuck => self.limit(at.drive.f) - (at.path.p - self.k_lat * own[Q]).abs(),
            Strings::Slide(sb) => sb * at.path.rest,
        }
    }

    fn switch(&self, mode: Strings, at: &At, own: &[f64]) -> Strings {
        match mode {
            Strings::Stuck => Strings::Slide((at.path.p - self.k_lat * own[Q]).signum()),
            Strings::Slide(_) => Strings::Stuck,
        }
    }

    /// While the strings slide under a gripping ball: the relaxation `(k_t + k_lat) / c` of
    /// the two springs through the damper.
    #[inline]
    fn substep(&self, mode: Strings, ball: Ball, pace: &Pace) -> Option<f64> {
        matches!((mode, ball), (Strings::Slide(_), Ball::Grip)).then(|| self.grip_slide_substep(pace))
    }

    fn shortest_substep(&self, pace: &Pace) -> f64 {
        self.grip_slide_substep(pace)
    }

    /// `k_lat q^2 / 2`.
    fn spring_energy(&self, own: &[f64]) -> f64 {
        0.5 * self.k_lat * own[Q] * own[Q]
    }
}

impl Bed {
    /// The longest substep while the strings slide under a gripping ball, s.
    #[inline]
    fn grip_slide_substep(&self, pace: &Pace) -> f64 {
        if pace.c > 0.0 {
            pace.oscillation.min(SUBSTEP * pace.c / (pace.kt + self.k_lat))
        } else {
            pace.oscillation
        }
    }
}
