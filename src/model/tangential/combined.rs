//! The combined law (`--tangential physical` and each mechanism alone; SPEC.md section 6,
//! "Mechanisms"): the grip-slip law of [`super::elastic`] with the mechanisms of the registry
//! (`tangential_mechanisms!` in `params/variants.rs`: the choice `name` is the type
//! `name::Variant`), each in its own file behind the one trait [`Mechanism`], composed here. The law owns what every mechanism shares:
//!
//! ```text
//! ball     m_b dv/dt = -P,   I_b domega/dt = R_c P + sum of the mechanisms' torques
//! frame    du/dt = P / m_eff                     (u: frame velocity at the contact point)
//! slip     w = v - R_c omega - u                 (R_c: R, or the lever a mechanism sets)
//! ball     P = k_t s + c ds/dt                   (c: the mechanisms' dampers, 0 without)
//! grip     ds/dt + (series) = w                  while |P| <= mu F_n
//! slide    P = sigma mu F_n                      while sigma (w - ds/dt - (series)) > 0
//! ```
//! where `(series)` is the rate of a compliance a mechanism puts in series with the ball's
//! spring (its `path`; 0 without one). With no mechanism this is the elastic law. The elements
//! are massless, so each combination of modes is a small ODE in `(v, omega, u, s)`, the energy
//! lost to sliding and the mechanisms' own slots; it is advanced by the generic stepper
//! (`stepper.rs`: classical Runge-Kutta substeps inside each piece of the normal force history,
//! a cubic as for the elastic law), and every switch (the ball's grip/slide, each mechanism's
//! mode) is located on the substep. The dissipated energies are integrated with the state, so
//! the ledger `KE_in = KE_out + k_t s^2/2 + springs + losses` closes to the integration error.

use super::compression::Compression;
use super::elastic::GripSlip;
use super::mechanism::{inv_red, At, Ball, Drive, Interface, LossField, Mechanism, Pace, Path, Sizes};
use super::mechanism::{GRIP_SUBSTEP, SUBSTEP};
use super::piece::ForcePiece;
use super::stepper::{self, Switched};
use crate::params::TangentialLaw;

/// The core's state slots: `v, omega, u, s` and the energy lost to sliding; the mechanisms'
/// slots follow, in the order of the registry.
const V: usize = 0;
const OM: usize = 1;
const U: usize = 2;
const S: usize = 3;
const E_FRICTION: usize = 4;
const CORE: usize = 5;

/// Where a mechanism's slots and guard sit in the combined law's state and guards.
#[derive(Debug, Clone, Copy)]
struct Place {
    /// Its first state slot.
    slot: usize,
    /// Its guard (`usize::MAX`: it has none).
    guard: usize,
}

impl Place {
    /// The place of the `i`-th mechanism of the registry: its slots after those of the ones
    /// before it; its guard after the ball's, those of the mechanisms in series
    /// ([`Mechanism::SERIES`]) first, each group in the registry's order.
    const fn of(i: usize) -> Place {
        let (mut slot, mut guard, mut j) = (CORE, 1, 0);
        while j < SLOT_COUNTS.len() {
            if j < i {
                slot += SLOT_COUNTS[j];
            }
            let before = if SERIES[i] { SERIES[j] && j < i } else { SERIES[j] || j < i };
            if GUARDED[j] && before {
                guard += 1;
            }
            j += 1;
        }
        Place { slot, guard: if GUARDED[i] { guard } else { usize::MAX } }
    }
}

/// The length of the state: the core's slots and every mechanism's.
const N: usize = Place::of(SLOT_COUNTS.len() - 1).slot + SLOT_COUNTS[SLOT_COUNTS.len() - 1];
/// The number of guards: the ball's grip/slide and one per mechanism with a mode.
const G: usize = {
    let (mut g, mut j) = (1, 0);
    while j < GUARDED.len() {
        g += GUARDED[j] as usize;
        j += 1;
    }
    g
};

/// State: the core's slots, then each mechanism's.
type Y = [f64; N];

/// A term computed over the mechanisms that are on, each with its mode and drive.
trait Visit {
    fn visit<M: Mechanism>(&mut self, m: &M, mode: M::Mode, drive: &M::Drive, at: Place);
}

/// A change of the modes, mechanism by mechanism.
trait Remode {
    fn remode<M: Mechanism>(&mut self, m: &M, mode: M::Mode, at: Place) -> M::Mode;
}

/// Declares, from the registry (`tangential_mechanisms!`), the mechanisms of a law, their modes
/// and drives, where each sits, and the two ways to go over them.
macro_rules! compose {
    ($($ty:ident = $module:ident: $help:literal,)+) => {
        /// The mechanisms of a law, each `None` while it is off.
        #[derive(Debug, Clone, Copy)]
        pub struct Mechanisms {
            $(#[doc = $help] pub $module: Option<super::$module::$ty>,)+
        }

        /// The mechanisms' modes.
        #[derive(Debug, Clone, Copy, PartialEq, Default)]
        struct Modes {
            $($module: <super::$module::$ty as Mechanism>::Mode,)+
        }

        /// What each mechanism takes from the normal force at one time.
        #[derive(Debug, Clone, Copy, Default)]
        struct Drives {
            $($module: <super::$module::$ty as Mechanism>::Drive,)+
        }

        /// The mechanisms' order in the registry.
        #[allow(non_camel_case_types)]
        enum Index {
            $($module,)+
        }

        /// The state slots of each mechanism, in the registry's order.
        const SLOT_COUNTS: &[usize] = &[$(<super::$module::$ty as Mechanism>::SLOTS,)+];
        /// Whether each has a mode of its own (a guard).
        const GUARDED: &[bool] = &[$(<super::$module::$ty as Mechanism>::GUARDED,)+];
        /// Whether each puts a compliance in series with the ball's spring.
        const SERIES: &[bool] = &[$(<super::$module::$ty as Mechanism>::SERIES,)+];

        impl Mechanisms {
            /// The mechanisms of the law `law`, sized for an impact.
            pub fn of(law: TangentialLaw, sizes: &Sizes) -> Mechanisms {
                Mechanisms {
                    $($module: law.has(TangentialLaw::$ty).then(|| <super::$module::$ty as Mechanism>::of(sizes)),)+
                }
            }

            /// No mechanism.
            pub fn none() -> Mechanisms {
                Mechanisms { $($module: None,)+ }
            }

            /// Which terms the mechanisms that are on add.
            fn terms(&self) -> Terms {
                let mut t = Terms::default();
                $(if self.$module.is_some() {
                    type M = super::$module::$ty;
                    t.compression |= <M as Mechanism>::COMPRESSION;
                    t.lever |= <M as Mechanism>::LEVER;
                    t.torque |= <M as Mechanism>::TORQUE;
                    t.series |= <M as Mechanism>::SERIES;
                    t.driven |= std::mem::size_of::<<M as Mechanism>::Drive>() > 0;
                })+
                t
            }

            /// What each takes from the normal force at one time.
            #[inline]
            fn drives(&self, d: &Drive) -> Drives {
                let mut out = Drives::default();
                $(if let Some(m) = &self.$module {
                    out.$module = m.drive(d);
                })+
                out
            }

            /// `v` over each mechanism that is on.
            #[inline(always)]
            fn visit<V: Visit>(&self, modes: &Modes, drives: &Drives, v: &mut V) {
                $(if let Some(m) = &self.$module {
                    v.visit(m, modes.$module, &drives.$module, const { Place::of(Index::$module as usize) });
                })+
            }

            /// `v`'s new mode for each mechanism that is on.
            #[inline(always)]
            fn remode<V: Remode>(&self, modes: &mut Modes, v: &mut V) {
                $(if let Some(m) = &self.$module {
                    modes.$module = v.remode(m, modes.$module, const { Place::of(Index::$module as usize) });
                })+
            }
        }
    };
}

crate::params::tangential_mechanisms!(compose);

/// A sum over the mechanisms that add to it: `None` while none has (so that one term alone is
/// that term, to the bit).
#[derive(Clone, Copy, Default)]
struct Sum(Option<f64>);

impl Sum {
    #[inline(always)]
    fn add(&mut self, x: f64) {
        self.0 = Some(self.0.map_or(x, |s| s + x));
    }
    #[inline(always)]
    fn or_zero(self) -> f64 {
        self.0.unwrap_or(0.0)
    }
}

/// Which terms the mechanisms of a law add (the others are skipped).
#[derive(Debug, Clone, Copy, Default)]
struct Terms {
    /// The ball's compression is needed.
    compression: bool,
    /// A mechanism sets the lever.
    lever: bool,
    /// A mechanism puts a torque on the ball.
    torque: bool,
    /// A mechanism puts a compliance in series.
    series: bool,
    /// A mechanism takes something from the normal force.
    driven: bool,
}

/// The tangential contact law with its mechanisms.
#[derive(Debug, Clone, Copy)]
pub struct CombinedLaw {
    /// The elastic grip-slip law underneath: friction, tangential stiffness, ball and frame.
    pub base: GripSlip,
    /// The mechanisms that are on.
    pub mechanisms: Mechanisms,
    /// The ball's compression law (for the mechanisms that need it).
    pub compression: Compression,
    /// The dampers in parallel with the ball's tangential spring, N s/m.
    damping: f64,
    /// Which terms the mechanisms add.
    terms: Terms,
}

impl CombinedLaw {
    /// The combined law of `mechanisms` on `base`.
    pub fn new(base: GripSlip, mechanisms: Mechanisms, compression: Compression) -> CombinedLaw {
        struct Dampers(Sum);
        impl Visit for Dampers {
            fn visit<M: Mechanism>(&mut self, m: &M, _: M::Mode, _: &M::Drive, _: Place) {
                if m.damper() != 0.0 {
                    self.0.add(m.damper());
                }
            }
        }
        let mut c = Dampers(Sum::default());
        mechanisms.visit(&Modes::default(), &Drives::default(), &mut c);
        CombinedLaw { base, mechanisms, compression, damping: c.0.or_zero(), terms: mechanisms.terms() }
    }

    /// The law `law` of the impact that `sizes` describes.
    pub fn of(law: TangentialLaw, sizes: &Sizes) -> CombinedLaw {
        CombinedLaw::new(sizes.base, Mechanisms::of(law, sizes), sizes.compression)
    }

    /// `1 / m_red` at full radius, 1/kg.
    pub fn inv_red(&self) -> f64 {
        inv_red(&self.base)
    }

    /// The dampers in parallel with the ball's tangential spring, N s/m.
    pub fn damping(&self) -> f64 {
        self.damping
    }
}

/// What the modes make of the state at one instant.
#[derive(Debug, Clone, Copy)]
struct Kin {
    /// The contact at this instant.
    at: At,
    /// The mechanisms' torques on the ball, N m.
    torque: f64,
}

/// What the normal force makes of the contact at one time: the core's part and each
/// mechanism's.
#[derive(Debug, Clone, Copy)]
pub(super) struct Driven {
    core: Drive,
    lever: f64,
    mechanisms: Drives,
}

/// The energies the mechanisms have lost, by the result field that reports them, J.
#[derive(Debug, Clone, Copy, Default)]
pub struct Losses {
    /// In a damper on the ball's spring (`f_tangential_damping`).
    pub damping: f64,
    /// To the strings sliding over each other (`f_string_sliding`).
    pub string_sliding: f64,
    /// To torques against the spin (`f_rolling`).
    pub rolling: f64,
    /// By mechanisms with no result field of their own (the energy ledger only).
    pub ledger_only: f64,
}

/// The combined law's tangential contact of one impact in progress.
#[derive(Debug, Clone, Copy)]
pub struct Combined {
    law: CombinedLaw,
    y: Y,
    ball: Ball,
    modes: Modes,
    /// Largest normal force so far, N.
    f_max: f64,
    /// The turning points of the piece in progress.
    turning: [f64; 2],
    /// Longest substep in each mode, s ([`Substeps`]).
    h_max: Substeps,
    /// Time spent sliding, s.
    pub slide_time: f64,
    /// Whether a piece reached its cap of switches (`stepper::advance`).
    pub chatter: bool,
    started: bool,
}

impl Combined {
    /// The contact before the ball touches: ball velocity `v` and spin `omega` along `t`, the
    /// frame at rest.
    pub fn new(law: CombinedLaw, v: f64, omega: f64) -> Combined {
        let mut y = [0.0; N];
        (y[V], y[OM]) = (v, omega);
        Combined {
            law,
            y,
            ball: Ball::Grip,
            modes: Modes::default(),
            f_max: 0.0,
            turning: [f64::NAN; 2],
            h_max: Substeps::of(&law),
            slide_time: 0.0,
            chatter: false,
            started: false,
        }
    }

    /// The most Runge-Kutta substeps over a contact of `t` seconds (besides those cut at a
    /// switch).
    pub fn steps_within(&self, t: f64) -> f64 {
        struct Shortest<'a>(f64, &'a Pace);
        impl Visit for Shortest<'_> {
            fn visit<M: Mechanism>(&mut self, m: &M, _: M::Mode, _: &M::Drive, _: Place) {
                self.0 = self.0.min(m.shortest_substep(self.1));
            }
        }
        let mut h = Shortest(self.h_max.grip.min(self.h_max.slide), &self.h_max.pace);
        self.law.mechanisms.visit(&self.modes, &Drives::default(), &mut h);
        t / h.0
    }

    /// Ball velocity along `t`, m/s.
    pub fn v(&self) -> f64 {
        self.y[V]
    }
    /// Ball spin, rad/s (topspin positive).
    pub fn omega(&self) -> f64 {
        self.y[OM]
    }
    /// Frame velocity at the contact point along `t`, m/s.
    pub fn u(&self) -> f64 {
        self.y[U]
    }
    /// Energy lost to the ball sliding on the strings, J.
    pub fn friction_loss(&self) -> f64 {
        self.y[E_FRICTION]
    }

    /// The energies the mechanisms lost, by the field that reports them, J.
    pub fn losses(&self) -> Losses {
        struct Collect<'a>(Losses, &'a Y);
        impl Visit for Collect<'_> {
            fn visit<M: Mechanism>(&mut self, _: &M, _: M::Mode, _: &M::Drive, at: Place) {
                let Some(field) = M::LOSS else { return };
                let e = self.1[at.slot + M::SLOTS - 1];
                let l = &mut self.0;
                match field {
                    LossField::Damping => l.damping += e,
                    LossField::StringSliding => l.string_sliding += e,
                    LossField::Rolling => l.rolling += e,
                    LossField::LedgerOnly => l.ledger_only += e,
                }
            }
        }
        let mut c = Collect(Losses::default(), &self.y);
        self.law.mechanisms.visit(&self.modes, &Drives::default(), &mut c);
        c.0
    }

    /// Energy left in the ball's tangential spring and the mechanisms' springs, J.
    pub fn spring_energy(&self) -> f64 {
        struct Springs<'a>(f64, &'a Y);
        impl Visit for Springs<'_> {
            fn visit<M: Mechanism>(&mut self, m: &M, _: M::Mode, _: &M::Drive, at: Place) {
                if M::SLOTS > 0 {
                    self.0 += m.spring_energy(&self.1[at.slot..at.slot + M::SLOTS]);
                }
            }
        }
        let mut e = Springs(0.5 * self.law.base.kt * self.y[S] * self.y[S], &self.y);
        self.law.mechanisms.visit(&self.modes, &Drives::default(), &mut e);
        e.0
    }

    /// Advance over one piece of the normal force history.
    pub fn advance(&mut self, piece: &ForcePiece) {
        if !self.started {
            self.started = true;
            self.first_modes(piece);
        }
        self.turning = piece.turning_points();
        self.chatter |= stepper::advance(self, piece);
    }

    /// The modes at first contact (`F_n = 0`): the ball slides with its slip unless the spring
    /// can take it up as fast as the friction limit grows (as for the elastic law); each
    /// mechanism then takes its first mode.
    fn first_modes(&mut self, piece: &ForcePiece) {
        let law = &self.law;
        let w = self.y[V] - law.base.radius * self.y[OM];
        self.ball = if w != 0.0 && (law.damping > 0.0 || law.base.kt * w.abs() > law.base.mu * piece.rate(0.0)) {
            Ball::Slide(w.signum())
        } else {
            Ball::Grip
        };
        struct First<'a>(Ball, f64, &'a GripSlip);
        impl Remode for First<'_> {
            fn remode<M: Mechanism>(&mut self, m: &M, _: M::Mode, _: Place) -> M::Mode {
                m.first_mode(self.0, self.1, self.2)
            }
        }
        let base = self.law.base;
        self.law.mechanisms.remode(&mut self.modes, &mut First(self.ball, self.y[OM], &base));
    }

    /// What the normal force makes of the contact at `t`.
    #[inline]
    fn drive_at(&self, piece: &ForcePiece, t: f64, peak: Peak) -> Driven {
        let law = &self.law;
        let (f, df) = (piece.force(t).max(0.0), piece.rate(t));
        let delta = if law.terms.compression { law.compression.delta(f, peak.at(piece, t)) } else { 0.0 };
        let core = Drive { f, df, delta };
        struct Lever<'a>(f64, &'a Drive);
        impl Visit for Lever<'_> {
            #[inline(always)]
            fn visit<M: Mechanism>(&mut self, m: &M, _: M::Mode, _: &M::Drive, _: Place) {
                if M::LEVER {
                    self.0 = m.lever(self.0, self.1);
                }
            }
        }
        let mut lever = Lever(law.base.radius, &core);
        let mechanisms = if law.terms.driven { law.mechanisms.drives(&core) } else { Drives::default() };
        if law.terms.lever {
            law.mechanisms.visit(&self.modes, &mechanisms, &mut lever);
        }
        Driven { core, lever: lever.0, mechanisms }
    }

    /// The contact's forces and rates in the current modes.
    #[inline]
    fn kin(&self, y: &Y, d: &Driven) -> Kin {
        let law = &self.law;
        let w = y[V] - d.lever * y[OM] - y[U];
        let i = Interface {
            ball: self.ball,
            mu: law.base.mu,
            kt: law.base.kt,
            c: law.damping,
            s: y[S],
            w,
            f: d.core.f,
            df: d.core.df,
        };
        struct Series<'a>(Option<Path>, &'a Interface, &'a Y);
        impl Visit for Series<'_> {
            #[inline(always)]
            fn visit<M: Mechanism>(&mut self, m: &M, mode: M::Mode, _: &M::Drive, at: Place) {
                if M::SERIES && self.0.is_none() {
                    self.0 = m.path(mode, &self.2[at.slot..at.slot + M::SLOTS], self.1);
                }
            }
        }
        let mut series = Series(None, &i, y);
        if law.terms.series {
            law.mechanisms.visit(&self.modes, &d.mechanisms, &mut series);
        }
        let path = series.0.unwrap_or_else(|| i.rigid());
        let at = At { ball: self.ball, drive: d.core, lever: d.lever, omega: y[OM], w, path };
        struct Torques<'a>(Sum, &'a At);
        impl Visit for Torques<'_> {
            #[inline(always)]
            fn visit<M: Mechanism>(&mut self, m: &M, mode: M::Mode, drive: &M::Drive, _: Place) {
                if M::TORQUE {
                    self.0.add(m.torque(mode, drive, self.1));
                }
            }
        }
        let mut torque = Torques(Sum::default(), &at);
        if law.terms.torque {
            law.mechanisms.visit(&self.modes, &d.mechanisms, &mut torque);
        }
        Kin { at, torque: torque.0.or_zero() }
    }
}

impl Switched<N, G> for Combined {
    type Frozen = Peak;
    type Drive = Driven;

    fn state(&self) -> &Y {
        &self.y
    }

    fn max_substep(&self) -> f64 {
        match self.ball {
            Ball::Slide(_) => self.h_max.slide,
            Ball::Grip if !self.h_max.own => self.h_max.grip,
            Ball::Grip => {
                struct Shorter<'a>(Option<f64>, &'a Pace);
                impl Visit for Shorter<'_> {
                    fn visit<M: Mechanism>(&mut self, m: &M, mode: M::Mode, _: &M::Drive, _: Place) {
                        if let Some(h) = m.substep(mode, Ball::Grip, self.1) {
                            self.0 = Some(self.0.map_or(h, |g| g.min(h)));
                        }
                    }
                }
                let mut h = Shorter(None, &self.h_max.pace);
                self.law.mechanisms.visit(&self.modes, &Drives::default(), &mut h);
                h.0.unwrap_or(self.h_max.grip)
            }
        }
    }

    fn frozen(&self, _piece: &ForcePiece, t: f64) -> Peak {
        Peak { f_max: self.f_max, from: t, turning: self.turning }
    }

    fn drive(&self, piece: &ForcePiece, t: f64, peak: Peak) -> Driven {
        self.drive_at(piece, t, peak)
    }

    /// The rates of the state.
    #[inline]
    fn rates(&self, y: &Y, d: &Driven) -> Y {
        let law = &self.law;
        let k = self.kin(y, d);
        let (at, p) = (&k.at, k.at.path.p);
        let friction = match self.ball {
            Ball::Slide(sign) => sign * law.base.mu * d.core.f * (at.w - at.path.sdot - at.path.rest),
            Ball::Grip => 0.0,
        };
        let mut out = [0.0; N];
        out[V] = -p / law.base.mb;
        out[OM] = (at.lever * p + k.torque) / law.base.inertia;
        out[U] = p * law.base.racket_inv_mass;
        out[S] = at.path.sdot;
        out[E_FRICTION] = friction;
        struct Rates<'a>(&'a mut Y, &'a Y, &'a At);
        impl Visit for Rates<'_> {
            #[inline(always)]
            fn visit<M: Mechanism>(&mut self, m: &M, mode: M::Mode, drive: &M::Drive, at: Place) {
                let r = at.slot..at.slot + M::SLOTS;
                m.rates(mode, drive, self.2, &self.1[r.clone()], &mut self.0[r]);
            }
        }
        law.mechanisms.visit(&self.modes, &d.mechanisms, &mut Rates(&mut out, y, at));
        out
    }

    /// The guards of the current modes at the state `y`, each non-negative while its mode
    /// lasts (infinite where it does not apply): 0 the ball's grip or slide, then each
    /// mechanism's with a mode of its own ([`Place::of`]).
    #[inline]
    fn guards(&self, y: &Y, d: &Driven) -> [f64; G] {
        let law = &self.law;
        let k = self.kin(y, d);
        let at = &k.at;
        let mut out = [f64::INFINITY; G];
        out[0] = match self.ball {
            Ball::Grip => law.base.mu * d.core.f - at.path.p.abs(),
            Ball::Slide(sign) => sign * (at.w - at.path.sdot - at.path.rest),
        };
        struct Guards<'a>(&'a mut [f64; G], &'a Y, &'a At);
        impl Visit for Guards<'_> {
            #[inline(always)]
            fn visit<M: Mechanism>(&mut self, m: &M, mode: M::Mode, drive: &M::Drive, at: Place) {
                if M::GUARDED {
                    self.0[at.guard] = m.guard(mode, drive, self.2, &self.1[at.slot..at.slot + M::SLOTS]);
                }
            }
        }
        law.mechanisms.visit(&self.modes, &d.mechanisms, &mut Guards(&mut out, y, at));
        out
    }

    /// Accept a substep `[t, t + h]` ending at `y`.
    fn commit(&mut self, piece: &ForcePiece, t: f64, h: f64, y: Y) {
        self.y = y;
        if matches!(self.ball, Ball::Slide(_)) {
            self.slide_time += h;
        }
        self.f_max = self.frozen(piece, t).at(piece, t + h);
    }

    /// Change the mode whose guard `g` failed, at `t`: the ball's (0), then the mechanisms
    /// told; or the mechanism whose guard it is.
    fn switch(&mut self, g: usize, piece: &ForcePiece, t: f64) {
        let k = self.kin(&self.y, &self.drive_at(piece, t, self.frozen(piece, t)));
        if g == 0 {
            self.ball = match self.ball {
                Ball::Grip => Ball::Slide(k.at.path.p.signum()),
                Ball::Slide(_) => Ball::Grip,
            };
            struct Told(f64);
            impl Remode for Told {
                fn remode<M: Mechanism>(&mut self, m: &M, mode: M::Mode, _: Place) -> M::Mode {
                    m.ball_switched(mode, self.0)
                }
            }
            self.law.mechanisms.remode(&mut self.modes, &mut Told(self.y[OM]));
        } else {
            struct Switch<'a>(usize, &'a At, &'a Y);
            impl Remode for Switch<'_> {
                fn remode<M: Mechanism>(&mut self, m: &M, mode: M::Mode, at: Place) -> M::Mode {
                    if at.guard == self.0 {
                        m.switch(mode, self.1, &self.2[at.slot..at.slot + M::SLOTS])
                    } else {
                        mode
                    }
                }
            }
            let y = self.y;
            self.law.mechanisms.remode(&mut self.modes, &mut Switch(g, &k.at, &y));
        }
    }
}

/// The longest substep in each mode, from the rates of the mode's own linear dynamics (a
/// Runge-Kutta step's error goes with the step times the rate): [`GRIP_SUBSTEP`] over the
/// grip oscillation's rate `sqrt(k_t / m_red)`, which sets the pace of every mode, and
/// [`SUBSTEP`] over each relaxation the damper brings in: while the ball grips, the decay
/// `c / m_red` of a heavily damped oscillation; while it slides (the force through the damper
/// is then set by friction), the relaxation `k_t / c` of its spring. A mechanism may ask for
/// shorter ones in its own modes ([`Mechanism::substep`]).
#[derive(Debug, Clone, Copy)]
struct Substeps {
    /// The ball grips, s.
    grip: f64,
    /// The ball slides, s.
    slide: f64,
    /// The time scales, for the mechanisms.
    pace: Pace,
    /// Whether a mechanism sets substeps of its own ([`Mechanism::shortest_substep`]).
    own: bool,
}

impl Substeps {
    fn of(law: &CombinedLaw) -> Substeps {
        let inv_red = law.inv_red();
        let (kt, c) = (law.base.kt, law.damping);
        let oscillation = GRIP_SUBSTEP / (kt * inv_red).sqrt();
        let pace = Pace { oscillation, kt, c };
        struct Own<'a>(bool, &'a Pace);
        impl Visit for Own<'_> {
            fn visit<M: Mechanism>(&mut self, m: &M, _: M::Mode, _: &M::Drive, _: Place) {
                self.0 |= m.shortest_substep(self.1).is_finite();
            }
        }
        let mut own = Own(false, &pace);
        law.mechanisms.visit(&Modes::default(), &Drives::default(), &mut own);
        let own = own.0;
        if c > 0.0 {
            Substeps {
                grip: oscillation.min(SUBSTEP / (c * inv_red)),
                slide: oscillation.min(SUBSTEP * c / kt),
                pace,
                own,
            }
        } else {
            Substeps { grip: oscillation, slide: oscillation, pace, own }
        }
    }
}

/// The largest normal force up to a time: the largest before a substep and the piece's own
/// maximum from the substep's start on (the ball's compression follows its expansion branch
/// after the peak, [`Compression::delta`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Peak {
    /// Largest force before `from`, N.
    f_max: f64,
    /// Start of the substep, s into the piece.
    from: f64,
    /// The piece's turning points ([`ForcePiece::turning_points`]).
    turning: [f64; 2],
}

impl Peak {
    /// The largest force up to `t`, N.
    fn at(&self, piece: &ForcePiece, t: f64) -> f64 {
        self.f_max.max(piece.max_force(&self.turning, self.from, t))
    }
}

/// The sign of `x`, 0 for 0 (and NaN).
pub(super) fn sign0(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::tangential::{bed::Bed, loss, offset};

    /// A smooth single-hump normal force of about 1 kN over 5 ms cut into `n` Hermite pieces.
    fn cut(n: usize) -> Vec<ForcePiece> {
        let tau = 5e-3;
        let f = |t: f64| 4e8 * t * (tau - t) * (1e-3 + t);
        let df = |t: f64| 4e8 * ((tau - 2.0 * t) * (1e-3 + t) + t * (tau - t));
        let h = tau / n as f64;
        (0..n)
            .map(|i| {
                let (a, b) = (i as f64 * h, (i + 1) as f64 * h);
                ForcePiece::hermite(h, (f(a), df(a)), (f(b), df(b)))
            })
            .collect()
    }

    fn law(damping: bool, offset: bool, bed: bool, shrink: bool) -> CombinedLaw {
        let (mb, r) = (0.057, 0.033);
        let base = GripSlip { mu: 0.45, kt: 2e4, mb, radius: r, inertia: 0.55 * mb * r * r, racket_inv_mass: 2.0 };
        let compression = Compression { k: 7.9e4, p: 2.55, radius: r };
        let mut m = Mechanisms::none();
        m.loss = damping.then(|| loss::Loss { c: loss::damper(0.09, base.kt, inv_red(&base)) });
        m.offset = offset.then_some(offset::Offset { loss: 0.44, compression });
        m.bed = bed.then(|| Bed::of(4e4, 0.05));
        m.radius = shrink.then_some(super::super::radius::Radius);
        CombinedLaw::new(base, m, compression)
    }

    fn run(law: CombinedLaw, v: f64, omega: f64, pieces: &[ForcePiece]) -> Combined {
        let mut c = Combined::new(law, v, omega);
        for p in pieces {
            c.advance(p);
        }
        c
    }

    /// Every combination of mechanisms: the same force history cut into 1, 7 or 60 pieces gives
    /// the same outcome (the switches are located inside pieces), and the ledger closes.
    #[test]
    fn outcome_does_not_depend_on_the_cut_and_the_ledger_closes() {
        for bits in 0..16u32 {
            let law = law(bits & 1 != 0, bits & 2 != 0, bits & 4 != 0, bits & 8 != 0);
            for (v, omega) in [(4.3, 0.0), (16.0, -400.0), (2.0, 300.0)] {
                let one = run(law, v, omega, &cut(1));
                for n in [7, 60] {
                    let many = run(law, v, omega, &cut(n));
                    let d = (one.omega() - many.omega()).abs() / (v / law.base.radius);
                    assert!(d < 1e-6, "bits {bits:04b} v {v} omega {omega} n {n}: {} vs {}", one.omega(), many.omega());
                }
                let ke = |v: f64, w: f64| 0.5 * law.base.mb * v * v + 0.5 * law.base.inertia * w * w;
                let inplane = 0.5 * one.u() * one.u() / law.base.racket_inv_mass;
                let l = one.losses();
                let losses = one.friction_loss() + l.damping + l.string_sliding + l.rolling + l.ledger_only;
                let ledger = ke(v, omega) - ke(one.v(), one.omega()) - inplane - losses - one.spring_energy();
                assert!(ledger.abs() < 1e-8 * ke(v, omega), "bits {bits:04b}: {ledger}");
            }
        }
    }

    /// A gripping impact on an immovable frame returns the ball's tangential restitution: a
    /// constant normal force (the friction limit never reached) for the damped half period of
    /// the grip oscillation leaves the contact point with `-e_x` of its incoming slip, whatever
    /// the incoming spin and speed, to the accuracy of the Runge-Kutta substeps ([`SUBSTEP`] =
    /// 0.2 of the oscillation's time scale: about 5e-5 over the half cycle, in the spin and in
    /// the ledger, which closes to the same).
    #[test]
    fn a_gripping_impact_on_an_immovable_frame_returns_e_x() {
        let (mb, r) = (0.057, 0.033);
        for e_x in [0.10, 0.135, 0.17] {
            let mut base = law(false, false, false, false);
            base.base.racket_inv_mass = 0.0;
            base.base.mu = 50.0;
            let zeta = loss::damping_ratio(e_x);
            let mut m = Mechanisms::none();
            m.loss = Some(loss::Loss { c: loss::damper(zeta, base.base.kt, base.inv_red()) });
            let law = CombinedLaw::new(base.base, m, base.compression);
            let h = loss::half_period(zeta, law.base.kt, law.inv_red());
            let piece = ForcePiece::hermite(h, (500.0, 0.0), (500.0, 0.0));
            for (v, omega) in [(10.0, 0.0), (10.0, -400.0), (-3.0, 200.0)] {
                let c = run(law, v, omega, &[piece]);
                let (w_in, w_out) = (v - r * omega, c.v() - r * c.omega());
                assert_eq!(c.u(), 0.0);
                assert!((-w_out / w_in / e_x - 1.0).abs() < 1e-4, "e_x {e_x}, v {v}, omega {omega}: {}", -w_out / w_in);
                let ke = |v: f64, w: f64| 0.5 * mb * v * v + 0.5 * law.base.inertia * w * w;
                let ledger =
                    ke(v, omega) - ke(c.v(), c.omega()) - c.losses().damping - c.friction_loss() - c.spring_energy();
                assert!(ledger.abs() < 1e-4 * ke(v, omega), "{}", ledger / ke(v, omega));
                // momentum about the contact point: the ball's angular momentum there is kept
                let l = |v: f64, w: f64| mb * r * v + law.base.inertia * w;
                assert!((l(v, omega) - l(c.v(), c.omega())).abs() < 1e-9 * l(v, omega).abs().max(1e-3));
            }
        }
    }
}
