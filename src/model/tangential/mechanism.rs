//! The one trait every mechanism of the combined law implements ([`Mechanism`]), and what the
//! combined law hands a mechanism at one instant.
//!
//! The combined law (`combined.rs`) owns the elastic grip-slip contact: the ball (`v`, `omega`),
//! the frame at the contact point (`u`), the ball's tangential spring (`s`, stiffness `k_t`),
//! the grip/slide switch of the ball on the strings and the energy lost to that sliding. A
//! mechanism adds one piece of physics to it through the terms of this trait, each with a
//! neutral default, so that a mechanism states only what it changes:
//!
//! ```text
//! lever         the arm of the friction force about the ball's centre   (radius)
//! damper        a damper in parallel with the ball's tangential spring   (loss)
//! path          a compliance in series with the ball's spring, with its  (bed)
//!               own deflection: the force through the contact and the
//!               rates of both springs in the current modes
//! torque        a torque on the ball                                     (offset)
//! its state     its slots: deflections, then the energy it dissipates,
//!               with their rates (`rates`)
//! its mode      a mode of its own, the guard that ends it (non-negative
//!               while it lasts) and the mode that follows (`switch`)
//! energies      the energy its springs hold and the energy it has lost
//! ```
//!
//! At most one mechanism supplies the series `path` (the first that does is taken): two
//! compliances in series with the ball's spring would make the path a chain to solve, which the
//! combined law does not do.

use super::compression::Compression;
use super::elastic::GripSlip;
use crate::params::Params;

/// Substep length as a fraction of the time scale of a relaxation through the damper.
pub const SUBSTEP: f64 = 0.2;
/// Substep length as a fraction of the grip oscillation's time scale `sqrt(m_red / k_t)`:
/// finer than for a relaxation, as the oscillation carries the spin handed back and the
/// offset torque's switches ride on it (chosen so that the outcomes over the mechanisms' test
/// grid come at least as close to a ten times finer integration as with the former single
/// limit, 0.2 of the fastest time scale of any mode).
pub const GRIP_SUBSTEP: f64 = 0.05;

/// Grip or slide of the ball on the strings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ball {
    /// The contact region moves with the strings.
    Grip,
    /// The contact region slides, in the direction of the sign (+1 or -1).
    Slide(f64),
}

/// What a mechanism is sized from: the impact's parameters and the elastic law underneath.
#[derive(Debug, Clone, Copy)]
pub struct Sizes<'a> {
    /// The impact's parameters.
    pub params: &'a Params,
    /// The elastic grip-slip law the mechanisms are added to.
    pub base: GripSlip,
    /// The string-to-string friction coefficient in use (the named string's, else `mu-ss`).
    pub mu_ss: f64,
    /// The ball's compression law under the normal force ([`Compression`]).
    pub compression: Compression,
}

impl Sizes<'_> {
    /// `1 / m_red` at full radius, 1/kg: ball, its spin and the frame at the contact point.
    pub fn inv_red(&self) -> f64 {
        inv_red(&self.base)
    }
}

/// `1 / m_red` at full radius, 1/kg, of the law `b`.
pub(super) fn inv_red(b: &GripSlip) -> f64 {
    1.0 / b.mb + b.radius * b.radius / b.inertia + b.racket_inv_mass
}

/// What the normal force makes of the contact at one time, for every mechanism (it does not
/// depend on the state).
#[derive(Debug, Clone, Copy)]
pub struct Drive {
    /// Normal force (not below 0), N.
    pub f: f64,
    /// Its rate, N/s.
    pub df: f64,
    /// The ball's compression, m (0 when no mechanism of the law needs it,
    /// [`Mechanism::COMPRESSION`]).
    pub delta: f64,
}

/// The ball's tangential element and the interface at one instant: what a series compliance
/// needs to share the force with the ball's spring.
#[derive(Debug, Clone, Copy)]
pub struct Interface {
    /// Grip or slide of the ball on the strings.
    pub ball: Ball,
    /// Ball-string friction coefficient.
    pub mu: f64,
    /// The ball's tangential stiffness, N/m.
    pub kt: f64,
    /// The damper in parallel with it, N s/m (0 without one).
    pub c: f64,
    /// The deflection of the ball's spring, m.
    pub s: f64,
    /// Slip of the ball's contact point relative to the frame, m/s.
    pub w: f64,
    /// Normal force, N.
    pub f: f64,
    /// Its rate, N/s.
    pub df: f64,
}

impl Interface {
    /// The path with nothing in series with the ball's spring-damper: gripping, the spring
    /// takes up the whole slip; sliding, the friction sets the force.
    #[inline]
    pub fn rigid(&self) -> Path {
        match self.ball {
            Ball::Grip => Path { p: self.kt * self.s + self.c * self.w, sdot: self.w, rest: 0.0 },
            Ball::Slide(sign) => {
                let p = sign * self.mu * self.f;
                Path { p, sdot: self.slide_rate(p, sign), rest: 0.0 }
            }
        }
    }

    /// The rate of the ball's spring while the ball slides with the force `p` in the direction
    /// `sign`: through the damper if there is one, else held at `p / k_t`.
    #[inline]
    pub fn slide_rate(&self, p: f64, sign: f64) -> f64 {
        if self.c > 0.0 {
            (p - self.kt * self.s) / self.c
        } else {
            sign * self.mu * self.df / self.kt
        }
    }
}

/// The force through the contact and the rates of the path's compliances.
#[derive(Debug, Clone, Copy)]
pub struct Path {
    /// Force through the contact (on the strings; the ball feels `-p`), N.
    pub p: f64,
    /// Rate of the ball's spring deflection, m/s.
    pub sdot: f64,
    /// Rate of the deflection of the compliance in series with it, m/s (0 without one).
    pub rest: f64,
}

/// The contact at one instant, the modes applied: what a mechanism's torque, rates and guard
/// are computed from.
#[derive(Debug, Clone, Copy)]
pub struct At {
    /// Grip or slide of the ball on the strings.
    pub ball: Ball,
    /// The normal force and what follows from it.
    pub drive: Drive,
    /// Lever of the friction force about the ball's centre, m.
    pub lever: f64,
    /// Ball spin, rad/s (topspin positive).
    pub omega: f64,
    /// Slip of the ball's contact point relative to the frame, m/s.
    pub w: f64,
    /// The force and the compliances' rates.
    pub path: Path,
}

/// The result field that reports a mechanism's dissipated energy (its last state slot).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LossField {
    /// `f_tangential_damping`.
    Damping,
    /// `f_string_sliding`.
    StringSliding,
    /// `f_rolling`.
    Rolling,
    /// None of its own: the loss joins the energy ledger (and its check) only.
    LedgerOnly,
}

/// One mechanism of the combined law: its sizes (`Self`), and the terms it adds to the law's
/// dynamics. Every term has a neutral default.
pub trait Mechanism: Copy + std::fmt::Debug {
    /// Its mode (`()` for none); the default is the mode at rest.
    type Mode: Copy + PartialEq + Default + std::fmt::Debug;
    /// What it takes from the normal force alone at one time (`()` for nothing).
    type Drive: Copy + Default + std::fmt::Debug;
    /// Its state slots: its deflections, then the energy it dissipates (when [`Self::LOSS`]).
    const SLOTS: usize = 0;
    /// Whether it has a mode of its own (one guard, [`Self::guard`]).
    const GUARDED: bool = false;
    /// Whether it puts a compliance in series with the ball's spring ([`Self::path`]). Such a
    /// mechanism's guard comes before the others' (a torque or a hold follows the force
    /// through the path, not the other way round), so that where two modes end at the same
    /// instant the path switches first.
    const SERIES: bool = false;
    /// Whether it needs the ball's compression ([`Drive::delta`]).
    const COMPRESSION: bool = false;
    /// Whether it sets the lever ([`Self::lever`]).
    const LEVER: bool = false;
    /// Whether it puts a torque on the ball ([`Self::torque`]).
    const TORQUE: bool = false;
    /// Where its dissipated energy, its last state slot, is reported (`None`: it has none).
    const LOSS: Option<LossField> = None;

    /// The mechanism sized for an impact.
    fn of(sizes: &Sizes) -> Self;

    /// Its mode as the ball touches, `ball` the ball's first mode.
    fn first_mode(&self, _ball: Ball, _omega: f64, _base: &GripSlip) -> Self::Mode {
        Self::Mode::default()
    }

    /// What it takes from the normal force at one time.
    fn drive(&self, _d: &Drive) -> Self::Drive {
        Self::Drive::default()
    }

    /// The lever of the friction force about the ball's centre, given the lever so far.
    fn lever(&self, lever: f64, _d: &Drive) -> f64 {
        lever
    }

    /// A damper in parallel with the ball's tangential spring, N s/m.
    fn damper(&self) -> f64 {
        0.0
    }

    /// The force through the contact and the compliances' rates in its mode, if it puts a
    /// compliance in series with the ball's spring (`own`: its state slots).
    fn path(&self, _mode: Self::Mode, _own: &[f64], _i: &Interface) -> Option<Path> {
        None
    }

    /// A torque on the ball, N m (topspin positive).
    fn torque(&self, _mode: Self::Mode, _drive: &Self::Drive, _at: &At) -> f64 {
        0.0
    }

    /// The rates of its state slots into `out`.
    fn rates(&self, _mode: Self::Mode, _drive: &Self::Drive, _at: &At, _own: &[f64], _out: &mut [f64]) {}

    /// Its guard, non-negative while its mode lasts (infinite where it does not apply).
    fn guard(&self, _mode: Self::Mode, _drive: &Self::Drive, _at: &At, _own: &[f64]) -> f64 {
        f64::INFINITY
    }

    /// The mode that follows when its guard failed.
    fn switch(&self, mode: Self::Mode, _at: &At, _own: &[f64]) -> Self::Mode {
        mode
    }

    /// Its mode after the ball switched between grip and slide.
    fn ball_switched(&self, mode: Self::Mode, _omega: f64) -> Self::Mode {
        mode
    }

    /// The longest substep in its mode while the ball is in `ball`, if it is shorter than the
    /// law's own ([`Pace`]).
    fn substep(&self, _mode: Self::Mode, _ball: Ball, _pace: &Pace) -> Option<f64> {
        None
    }

    /// The shortest substep of any of its modes (infinite if it sets none, and then its
    /// [`Self::substep`] is not asked).
    fn shortest_substep(&self, _pace: &Pace) -> f64 {
        f64::INFINITY
    }

    /// The energy its springs hold, J.
    fn spring_energy(&self, _own: &[f64]) -> f64 {
        0.0
    }
}

/// The time scales the combined law's substeps follow ([`GRIP_SUBSTEP`], [`SUBSTEP`]).
#[derive(Debug, Clone, Copy)]
pub struct Pace {
    /// The grip oscillation's substep, [`GRIP_SUBSTEP`] over `sqrt(k_t / m_red)`, s.
    pub oscillation: f64,
    /// The ball's tangential stiffness, N/m.
    pub kt: f64,
    /// The damper in parallel with it, N s/m (0 without one).
    pub c: f64,
}
