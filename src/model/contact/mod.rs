//! The ball on the strings: the contact law behind one trait ([`ContactLaw`]), with the laws
//! the parameters can select registered in one list ([`Contact`]).
//!
//! The paper's law ([`cross::Cross`]): a hysteretic ball spring (Eqs 3-4) in series with a
//! massless linear string spring (Eq 2), driven by the total compression `Y_T = Y_s + Y_b`
//! (Eq 8):
//! ```text
//! compression:  F = k1 Y_b,            Y_b = k_s Y_T / (k1 + k_s)                     (Eqs 3, 9)
//! expansion:    F = k2 Y_b^p,          Y_b + k2 Y_b^p / k_s = Y_T                     (Eqs 4, 10)
//!               k2 = k1 Y0^(1-p)       (the paper prints p-1: a typo, see SPEC.md)
//! ball loss:    E_b = (p-1) k1 Y0^2 / (2 (p+1))                                       (Eq 11)
//! ```
//! [`stiffening::Stiffening`] is the same ball on strings that stiffen with deflection.
//!
//! A new law is one file implementing [`ContactLaw`] (with [`ContactLaw::select`] saying which
//! parameters ask for it) and one line in the `laws!` list below; the modal solver runs a law
//! that also implements [`ImplicitLaw`].

use crate::error::Result;
use crate::params::Params;

pub mod cross;
mod cross_implicit;
pub mod pow;
pub mod stiffening;

pub use cross::Cross;
pub use pow::PowSeries;
pub use stiffening::Stiffening;

/// The phase of the ball's force law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Phase {
    /// Loading along `F = k1 Y_b`.
    Compression,
    /// Unloading along `F = k2 Y_b^p` after the maximum compression `y0` (m) of the ball.
    Expansion {
        /// Maximum ball compression `Y0`, m.
        y0: f64,
    },
}

/// The force and compressions at one total compression `Y_T`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// Contact force `F` (>= 0), N.
    pub force: f64,
    /// Ball compression `Y_b`, m.
    pub ball_compression: f64,
    /// Expansion-law variable `u = Y_b / Y0` (0 in compression); a warm start for the next solve.
    pub u: f64,
    /// `u^p`, kept with `u` so the next solve starts without a power function.
    pub u_pow: f64,
    /// String-plane deflection `Y_s`, m.
    pub string_deflection: f64,
}

impl ContactState {
    /// No contact.
    pub const ZERO: ContactState =
        ContactState { force: 0.0, ball_compression: 0.0, u: 0.0, u_pow: 0.0, string_deflection: 0.0 };

    /// The warm start `(u, u^p)` this state offers the next expansion solve.
    pub fn guess(&self) -> (f64, f64) {
        (self.u, self.u_pow)
    }
}

/// A ball + strings contact law: the force as a function of the total compression `Y_T` and
/// the phase, with what the solvers and the ledger need of it.
pub trait ContactLaw {
    /// The law the parameters ask for, if it is this one. The paper's law ([`Cross`]) is the
    /// fallback when no registered law selects itself, and keeps this default.
    fn select(_params: &Params) -> Option<Self>
    where
        Self: Sized,
    {
        None
    }

    /// Stiffness `dF/dY_T` in the compression phase at first touch, N/m: it sets the contact's
    /// time scale (the impact's time limit) and the modal solver's compression step.
    fn compression_stiffness(&self) -> f64;

    /// Upper bound of `dF/dY_T` over the whole impact, N/m (for the stability limit and the
    /// modal step).
    fn max_stiffness(&self) -> f64;

    /// Force and compressions at total compression `yt` in the given phase: the inverse solve
    /// `Y_T -> Y_b` (Eqs 9-10). `guess` is a warm start `(u, u^p)`, as
    /// [`ContactState::guess`] returns it.
    fn state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> Result<ContactState>;

    /// Tangent stiffness `dF/dY_T` at the state `st`, N/m: the force's rate is this times the
    /// rate of `Y_T` (the oblique impact's tangential law follows the force and its rate).
    fn stiffness(&self, phase: Phase, st: &ContactState) -> f64;

    /// Maximum ball compression `Y0` for a maximum total compression `yt_max`, m.
    fn ball_compression_at_max(&self, yt_max: f64) -> f64;

    /// Energy held by the ball plus the energy it has already dissipated ("PE ball" of Fig 4), J.
    fn ball_energy_with_loss(&self, phase: Phase, st: &ContactState) -> f64;

    /// Elastic energy of the strings, J.
    fn string_energy(&self, st: &ContactState) -> f64;

    /// Energy dissipated in the ball over a whole impact with maximum compression `y0` (Eq 11), J.
    fn ball_loss(&self, y0: f64) -> f64;
}

/// The series stiffness of a ball whose tangent stiffness is `kb` and strings whose tangent
/// stiffness is `ks`, N/m (0 when either is 0: a ball that has just let go).
pub fn series(kb: f64, ks: f64) -> f64 {
    if kb <= 0.0 || ks <= 0.0 {
        0.0
    } else {
        kb * ks / (kb + ks)
    }
}

/// The ball's tangent stiffness `dF/dY_b`, N/m: `k1` in compression, `p F / Y_b` on the
/// expansion law `F = k2 Y_b^p`.
pub fn ball_stiffness(k1: f64, p: f64, phase: Phase, st: &ContactState) -> f64 {
    match phase {
        Phase::Compression => k1,
        Phase::Expansion { .. } if st.ball_compression > 0.0 => p * st.force / st.ball_compression,
        Phase::Expansion { .. } => 0.0,
    }
}

/// How the modal solver's step couples the force at the end of a step to the compression
/// there: `Y_T(h) = Y_hat - bf F1 - bd D1` and `Y_T'(h) = Yd_hat - cf F1 - cd D1` (`F1`, `D1`:
/// the end force and its rate; m/N, m s/N, 1/(N s), m/N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepCoupling {
    /// `dY_T / dF1`, m/N (with a minus sign).
    pub bf: f64,
    /// `dY_T / dD1`, m s/N (with a minus sign).
    pub bd: f64,
    /// `dY_T' / dF1`, 1/(N s) (with a minus sign).
    pub cf: f64,
    /// `dY_T' / dD1`, m/N (with a minus sign).
    pub cd: f64,
}

/// The contact at the end of an implicit step in expansion: force (N), rate (N/s) and the warm
/// start `(u, u^p)` it offers the next step.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct EndContact {
    /// Force, N.
    pub f: f64,
    /// Its rate, N/s.
    pub d: f64,
    /// `(u, u^p)` of the expansion law.
    pub u: (f64, f64),
}

/// A law the modal solver's implicit step can solve: linear in compression (with
/// [`ContactLaw::compression_stiffness`]), and in expansion an end-of-step solve of the law with
/// the step's coupling ([`StepCoupling`]) and the force rate taken along.
pub trait ImplicitLaw: ContactLaw {
    /// A start `(u, u^p)` for the next expansion solve: the previous `prev` moved along the
    /// compression rate `ytd` (m/s) over a step of `h` s.
    fn expansion_start(&self, y0: f64, prev: (f64, f64), ytd: f64, h: f64) -> (f64, f64);

    /// The end force and rate of a step in expansion from the prediction `pred = (Y_hat,
    /// Yd_hat)` (the end compression and its rate with the end force and rate zero), from the
    /// start `(u, u^p)` and a first guess `d_guess` of the rate. `Ok(None)` when the ball has
    /// left.
    fn expansion_end(
        &self,
        coupling: &StepCoupling,
        y0: f64,
        pred: (f64, f64),
        start: (f64, f64),
        d_guess: f64,
    ) -> Result<Option<EndContact>>;

    /// How far a force `f` (N) misses the expansion law at the compression `ym` (m), as a
    /// force, N.
    fn expansion_miss(&self, y0: f64, ym: f64, f: f64) -> f64;

    /// The contact state of a force `f` (N) with the expansion law's `(u, u^p)` (ignored in
    /// compression), for the energy ledger.
    fn state_at_force(&self, phase: Phase, f: f64, u: (f64, f64)) -> ContactState;
}

/// The registered laws: the enum [`Contact`] of them, with [`ContactLaw`] passed on to each,
/// and [`Contact::of`] choosing the first that [`ContactLaw::select`]s itself (the paper's law,
/// [`Cross`], otherwise).
macro_rules! laws {
    ($($(#[doc = $doc:literal])* $variant:ident($law:ty),)*) => {
        /// The contact law of one impact, one variant per registered law.
        #[derive(Debug, Clone, Copy)]
        pub enum Contact {
            /// The paper's ball on linear strings.
            Paper(Cross),
            $($(#[doc = $doc])* $variant($law),)*
        }

        impl Contact {
            /// The law the parameters ask for.
            pub fn of(params: &Params) -> Contact {
                $(if let Some(law) = <$law as ContactLaw>::select(params) {
                    return Contact::$variant(law);
                })*
                Contact::Paper(Cross::new(&params.ball, &params.strings))
            }
        }

        impl ContactLaw for Contact {
            #[inline]
            fn compression_stiffness(&self) -> f64 {
                match self {
                    Contact::Paper(law) => law.compression_stiffness(),
                    $(Contact::$variant(law) => law.compression_stiffness(),)*
                }
            }
            #[inline]
            fn max_stiffness(&self) -> f64 {
                match self {
                    Contact::Paper(law) => law.max_stiffness(),
                    $(Contact::$variant(law) => law.max_stiffness(),)*
                }
            }
            #[inline]
            fn state(&self, yt: f64, phase: Phase, guess: (f64, f64)) -> Result<ContactState> {
                match self {
                    Contact::Paper(law) => law.state(yt, phase, guess),
                    $(Contact::$variant(law) => law.state(yt, phase, guess),)*
                }
            }
            #[inline]
            fn stiffness(&self, phase: Phase, st: &ContactState) -> f64 {
                match self {
                    Contact::Paper(law) => law.stiffness(phase, st),
                    $(Contact::$variant(law) => law.stiffness(phase, st),)*
                }
            }

            #[inline]
            fn ball_compression_at_max(&self, yt_max: f64) -> f64 {
                match self {
                    Contact::Paper(law) => law.ball_compression_at_max(yt_max),
                    $(Contact::$variant(law) => law.ball_compression_at_max(yt_max),)*
                }
            }
            #[inline]
            fn ball_energy_with_loss(&self, phase: Phase, st: &ContactState) -> f64 {
                match self {
                    Contact::Paper(law) => law.ball_energy_with_loss(phase, st),
                    $(Contact::$variant(law) => law.ball_energy_with_loss(phase, st),)*
                }
            }
            #[inline]
            fn string_energy(&self, st: &ContactState) -> f64 {
                match self {
                    Contact::Paper(law) => law.string_energy(st),
                    $(Contact::$variant(law) => law.string_energy(st),)*
                }
            }
            #[inline]
            fn ball_loss(&self, y0: f64) -> f64 {
                match self {
                    Contact::Paper(law) => law.ball_loss(y0),
                    $(Contact::$variant(law) => law.ball_loss(y0),)*
                }
            }
        }
    };
}

laws! {
    /// The paper's ball on strings that stiffen with deflection (`--strings stiffening`).
    Stiffening(Stiffening),
}
