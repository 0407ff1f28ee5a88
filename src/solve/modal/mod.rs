//! The fast solver: modal superposition of the same discrete beam as the explicit solver
//! ([`crate::solve::fd`], the accuracy reference), independent of it in method. Every coordinate
//! is propagated exactly between steps, so the step is set by the contact (a tenth of a radian of
//! its stiffest oscillation), not by the stiffest beam mode, and the compression phase takes no
//! step at all: the two solvers agree to about 1e-4 (tests/modal.rs), the modal one at some
//! fifty times less work an impact, which is what makes maps, sweeps and uncertainty studies of
//! thousands of impacts cheap.
//!
//! The free-free beam is written in its mass-normalised modes (rigid translation and rotation
//! about the centre of mass exactly, flexible modes from the nalgebra eigen-decomposition of
//! `M^-1/2 K M^-1/2`); the twist (Eq 7) and the ball (Eq 1, as `sqrt(m_b) y_b`) are rigid
//! coordinates. Every coordinate obeys `q'' + w^2 q = g F(t)` (`w = 0` for the ball and the rigid
//! ones; `g` its amplitude at the load point, `-1/sqrt(m_b)` for the ball), and the total
//! compression is `Y_T = -sum g q - R F`.
//!
//! Until maximum compression the contact is a linear spring (Eq 9), so the compression phase is
//! solved in closed form: the coupled modes of ball, strings and frame are found once per
//! prepared model (a rank-one secular equation, [`crate::numeric::rank_one`]) and the run finds the
//! time of maximum compression and every coordinate there (`compression`). No step is taken
//! before it, so no error is made there, and the steps start where the force's rate is zero on
//! both sides and the expansion law (Eq 10) takes over.
//!
//! From there, over each step of length `h` the contact force is the cubic Hermite polynomial
//! through its values and rates at both ends, `F0, D0` (known) and `F1, D1` (unknown), and every
//! coordinate is advanced *exactly* under it:
//! ```text
//! q(h) = cos(w h) q0 + sin(w h)/w v0 + g (a_F0 F0 + a_D0 D0 + a_F1 F1 + a_D1 D1)
//! ```
//! (and the same for `v(h)`), with the eight response coefficients of each mode computed once per
//! step length (`responses`: a power series for `w h <= 1`, the polynomial particular solution
//! otherwise). `Y_T(h)` and `Y_T'(h)` are then affine in `(F1, D1)`, so the implicit step is the
//! contact law at the end of the step, `F1 = F(Y_T)` and `D1 = F'(Y_T) Y_T'`: Newton on the
//! expansion law with the rate updated from each iterate (its coupling is of order `(w h)^4`).
//! One polynomial per step keeps the scheme fourth order; the step is set by the stiffest contact
//! oscillation, not by the stiffest beam mode. On soft strings the end of the contact needs
//! shorter steps, where the expansion law bends sharply, so every step is checked: where the
//! cubic misses the contact law at the step's midpoint (and at its quarter points where the
//! force falls below a quarter of its start or the ball leaves) by more than the tolerance (as an
//! impulse error), it is taken again at half the length, down to 1/64 of the starting step; a
//! step that misses by less than a sixty-fourth of the tolerance lets the next one be twice as
//! long again (never longer than the starting step). A step at the finest level is accepted as
//! it is, so the tolerance is a target, not a bound; the agreement tests measure what it achieves.
//!
//! Only modes below a cut-off are kept; the flexibility of the others at the load point is added
//! as a static correction `Y_T -= R F`. Separation is interpolated as in [`crate::solve::fd`];
//! after separation the free vibration is evaluated in closed form for the paper's peak bending
//! PE and for re-contact.
//!
//! The contact law's end-of-step solve is the law's own ([`ImplicitLaw`](crate::model::contact::ImplicitLaw)); the coordinates'
//! amplitudes at the contact point come from the same coupling as the explicit solver's
//! ([`crate::model::coupling::Coupling`]). Files: this one prepares the model and reports the
//! result, `compression` solves the compression phase, `steps` builds the step tables, `run`
//! takes the steps.
//!
//! Where the time goes, what was measured and what was tried (the cut-off, a residual mode, a
//! quintic force history) is in `docs/performance.md`.

mod compression;
mod pair;
mod run;
mod shared;
mod steps;

use crate::error::{Error, Result};
use crate::model::contact::{ContactLaw, Cross, Phase};
use crate::model::free::FreeVibration;
use crate::model::tangential::ForcePiece;
use crate::numeric::spare::{pooled, Buf, Pooled};
use crate::params::{Params, TangentialLaw};
use crate::solve::oblique::Follower;
use crate::solve::outcome::ImpactResult;
use crate::solve::prepared::PreparedImpact;
use crate::solve::Solver;
use compression::Compression;
use pair::Pair;
use run::{End, Run};
use shared::{Key, Shared};
use std::sync::Arc;
use steps::Grid;

/// How finely the modal solver resolves an impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// Keep flexible modes up to this multiple of the stiffest contact frequency.
    pub mode_cutoff: f64,
    /// Radians of the stiffest contact oscillation per step.
    pub phase_per_step: f64,
    /// Target for the error of a step's contact impulse, in units of the incident momentum: a
    /// step whose force history misses the contact law at its check points by more is split
    /// (down to 1/64 of the base step, where it is accepted as it is).
    pub impulse_tolerance: f64,
}

/// The default resolution: modal and explicit solvers agree to 1e-4 (tests/modal.rs).
pub const DEFAULT_RESOLUTION: Resolution =
    Resolution { mode_cutoff: 50.0, phase_per_step: 0.1, impulse_tolerance: 2e-8 };

/// The resolution of an oblique impact under a tangential law with mechanisms (any but
/// `elastic`): modes up to 100 times the contact frequency. With the ball's damper and the
/// sliding strings, the slide that starts every such impact ends where the rate of the normal
/// force, within the first ten or so microseconds, meets what the springs can take up; modes
/// above 50 times the contact frequency still shape that rate. Measured over the 75 impacts of
/// tests/oblique.rs that the test then ran under `physical` (all four mechanisms; the others of
/// its 150 under `elastic`): the worst fd/modal difference of the slip fraction is 1.0e-4 with
/// the default cutoff, 7.9e-5 at 75 and 3.4e-5 at 100 (impacts whose switch chatters at an edge
/// aside: SPEC.md section 6, "Known limit"); the prepared modal impact of the benchmark under
/// `loss` costs 8 % more instructions at 100.
pub const MECHANISMS_RESOLUTION: Resolution = Resolution { mode_cutoff: 100.0, ..DEFAULT_RESOLUTION };

impl Resolution {
    /// The resolution an impact needs: [`MECHANISMS_RESOLUTION`] for an oblique or spinning
    /// impact under a law with mechanisms, else [`DEFAULT_RESOLUTION`] (every normal impact,
    /// and every elastic one, as before).
    pub fn of(params: &Params) -> Resolution {
        let o = &params.oblique;
        if !o.is_normal() && o.tangential != TangentialLaw::Elastic {
            MECHANISMS_RESOLUTION
        } else {
            DEFAULT_RESOLUTION
        }
    }
}

/// Step levels, each half the step of the one before: the coarsest is the step the resolution
/// names (`START`, where the steps begin and never exceeded), the finest `1/64` of it.
const LEVELS: usize = 7;
const START: usize = 0;

/// Number of rigid coordinates ahead of the flexible modes: ball, translation, rotation, twist.
const RIGID: usize = 4;

/// Refuse parameters whose free vibration after the impact (two fundamental periods, sampled
/// at [`PHASE_PER_SAMPLE`](crate::model::free::PHASE_PER_SAMPLE) of the fastest kept mode, every
/// kept mode rotated at each sample: the search's worst case) needs more mode-samples than this.
/// A mode-sample is a few floating-point operations, so this is of the order of the explicit
/// solver's limit ([`crate::solve::fd::MAX_NODE_STEPS`], about 15 s); without it a frame of
/// `ei` 1e-2 on 400 segments hit by a stiff ball ran for hours.
pub const MAX_MODE_SAMPLES: f64 = 8.0e9;
/// Steps between two calls of the run's hook ([`crate::control::poll`]), a power of two.
const POLL_STEPS: usize = 1 << 8;

/// A prepared modal model of one impact.
#[derive(Debug, Clone)]
pub struct ModalModel {
    /// The impact itself (parameters, beam, contact, coupling, tangential set-up).
    impact: PreparedImpact,
    /// The contact law (the paper's: validation leaves the modal solver no other).
    law: Cross,
    /// Largest impulse error allowed per step, N s.
    impulse_tolerance: f64,
    /// The set-up shared with every impact of the same racket, point, strings and ball: the
    /// retained coordinates, the compression phase, the step tables (`shared`).
    set: Arc<Shared>,
}

impl ModalModel {
    /// Validate, decompose the beam and choose the retained modes and the step.
    pub fn new(params: &Params) -> Result<Self> {
        Self::with_resolution(params, Resolution::of(params))
    }

    /// As [`ModalModel::new`] with a chosen resolution (for convergence studies). The set-up
    /// that does not depend on the incident speed, angle, azimuth, spin or friction, given the
    /// resolution (the
    /// retained modes, the coupled modes, the step tables) comes from this thread's cache when
    /// an impact of the same racket, point, strings and ball built it (`shared`).
    pub fn with_resolution(params: &Params, res: Resolution) -> Result<Self> {
        Self::build(params, res, true)
    }

    /// As [`ModalModel::with_resolution`], the set-up from the cache (and kept there) if
    /// `cached`, else built afresh.
    fn build(params: &Params, res: Resolution, cached: bool) -> Result<Self> {
        let impact = PreparedImpact::new(params)?;
        let law = Cross::new(&params.ball, &params.strings);
        let key = Key::of(&impact.basis, &impact.coupling, params, res);
        let hit = if cached { Shared::cached(&key) } else { None };
        let built = hit.is_none();
        let shared = match hit {
            Some(shared) => shared,
            None => Self::set_up(&impact, &law, params, res),
        };
        let impulse_tolerance = res.impulse_tolerance * params.ball.mass * impact.params.impact.v1;
        if built && cached {
            Shared::keep(&shared, key);
        }
        let m = ModalModel { impact, law, impulse_tolerance, set: shared };
        m.check_work()?;
        Ok(m)
    }

    /// The set-up shared by every impact of the same racket, point, strings and ball: the
    /// retained modes, their amplitudes at the load point, the static flexibility of the others
    /// the compression phase's coupled modes and the step table at maximum compression.
    fn set_up(impact: &PreparedImpact, law: &Cross, params: &Params, res: Resolution) -> Arc<Shared> {
        let beam = impact.beam();
        let basis = &impact.basis;
        let cp = impact.coupling;
        let mb = params.ball.mass;
        let [g_b, g_t, g_r, g_tw] = cp.rigid_amplitudes(mb, beam, params.racket.ix);
        let k_c = law.max_stiffness();
        let omega_contact = (k_c * (1.0 / mb + g_t * g_t + g_r * g_r + g_tw * g_tw)).sqrt();
        let cutoff = res.mode_cutoff * omega_contact;
        // (modes are ascending: the retained ones are a prefix)
        let kept = basis.lam.iter().take_while(|l| l.sqrt() <= cutoff).count();
        let mut lam = Vec::with_capacity(RIGID + kept);
        let mut g = Vec::with_capacity(RIGID + kept);
        lam.extend([0.0; RIGID]);
        g.extend([g_b, g_t, g_r, g_tw]);
        let mut residual = 0.0;
        for (l, phi) in basis.lam.iter().zip(&basis.shapes) {
            let gk = cp.at_load(phi);
            if l.sqrt() <= cutoff {
                lam.push(*l);
                g.push(gk);
            } else {
                residual += gk * gk / l;
            }
        }
        let compression = Compression::new(&lam, &g, law.compression_stiffness(), residual, mb, impact.time_limit_s);
        Shared::new(lam, g, residual, compression, basis, res.phase_per_step / omega_contact)
    }

    /// The worst case of the free-vibration search after the impact, in mode-samples: two
    /// fundamental periods sampled at [`PHASE_PER_SAMPLE`](crate::model::free::PHASE_PER_SAMPLE)
    /// of the fastest kept mode, every kept mode at each sample (what [`MAX_MODE_SAMPLES`]
    /// bounds, and `study::work` estimates a run by).
    pub fn free_vibration_work(&self) -> f64 {
        let modes = self.retained_modes();
        let fastest = self.set.omega.last().copied().unwrap_or(0.0);
        let samples = 2.0 / self.impact.f1_hz * fastest / crate::model::free::PHASE_PER_SAMPLE;
        samples * modes as f64
    }

    /// Refuse a model whose free-vibration search would exceed [`MAX_MODE_SAMPLES`] (the
    /// steps of the contact are bounded by the time limit and the finest step level).
    fn check_work(&self) -> Result<()> {
        let (modes, f1_hz) = (self.retained_modes(), self.impact.f1_hz);
        let work = self.free_vibration_work();
        if work.is_nan() || work > MAX_MODE_SAMPLES {
            return Err(Error::TooManySamples { work, modes, f1_hz, limit: MAX_MODE_SAMPLES });
        }
        Ok(())
    }

    /// The step tables of a refinement level.
    fn grid(&self, level: usize) -> &Grid {
        self.set.grids[level].get_or_init(|| {
            let h = self.set.grids[START].get().expect("start grid").h * 2f64.powi(START as i32 - level as i32);
            Grid::new(&self.set.lam, &self.set.omega, &self.set.g, self.set.residual, h)
        })
    }

    /// The racket's fundamental frequency, Hz.
    pub fn f1_hz(&self) -> f64 {
        self.impact.f1_hz
    }

    /// Number of retained flexible modes.
    pub fn retained_modes(&self) -> usize {
        self.set.lam.len() - RIGID
    }

    /// The step at maximum compression, where the steps begin, s.
    pub fn step(&self) -> f64 {
        self.grid(START).h
    }

    /// Run the impact: the compression phase in closed form, then steps from maximum
    /// compression to separation.
    pub fn run(&self) -> Result<ImpactResult> {
        let p = &self.impact.params;
        let v1 = p.impact.v1;
        let n = self.set.lam.len();
        let limit = self.impact.time_limit_s;
        let mut s = State { x: Buf::filled(Pair::splat(0.0), n) };
        let mut tangential = Follower::new(self.impact.oblique.as_ref());
        let max = if tangential.is_active() {
            let mut feed = |h: f64, a: (f64, f64), b: (f64, f64)| {
                tangential.advance(|| ForcePiece::hermite(h, a, b));
            };
            self.set.compression.at_max(v1, &mut s, Some((self.step(), &mut feed)))
        } else {
            self.set.compression.at_max(v1, &mut s, None)
        };
        let max = max.ok_or(Error::ImpactDidNotEnd { limit_s: limit })?;
        let y0 = self.law.ball_compression_at_max(max.yt);
        let at_max =
            End { f: max.f, d: 0.0, yt: max.yt, ytd: 0.0, phase: Phase::Expansion { y0 }, u: (1.0, 1.0), t_max: max.t };
        let mut run = Run {
            m: self,
            next: s.clone(),
            s,
            at: at_max,
            t: max.t,
            peak_force: max.f,
            energy_err: 0.0,
            momentum_err: 0.0,
            separated: None,
            tangential,
            level: START,
        };
        let modal_energy = self.energy(&run.s);
        run.ledger(&at_max, modal_energy);
        let mut steps: usize = 0;
        while run.separated.is_none() {
            if run.t > limit {
                return Err(Error::ImpactDidNotEnd { limit_s: limit });
            }
            if steps % POLL_STEPS == POLL_STEPS - 1 {
                // (the time limit is ten contact times: a tenth of it, the expected contact)
                crate::control::poll(0.5 * run.t / (0.1 * limit))?;
            }
            steps += 1;
            run.advance()?;
        }
        let mut result = self.finish(&run, y0);
        // (a search after the impact that a cancelled run cut short is no result)
        crate::control::poll(1.0)?;
        run.tangential.complete(self.impact.oblique.as_ref(), &mut result, v1)?;
        result.check_finite()?;
        Ok(result)
    }

    /// The result of the separated impact `run` whose ball was compressed by `y0` at most, m
    /// (its oblique fields aside).
    fn finish(&self, run: &Run<'_>, y0: f64) -> ImpactResult {
        let (s, (tau, theta)) = (&run.s, run.separated.unwrap_or_default());
        let since_separation = run.t - tau;
        let p = &self.impact.params;
        let e0 = 0.5 * p.ball.mass * p.impact.v1 * p.impact.v1;
        let e_a = -s.v(0) / (p.ball.mass.sqrt() * p.impact.v1);
        // (a fold from +0: an empty sum of f64 is -0)
        let vib = (RIGID..self.set.lam.len())
            .map(|k| 0.5 * (s.v(k) * s.v(k) + self.set.lam[k] * s.q(k) * s.q(k)))
            .fold(0.0, |a, b| a + b);
        let (peak_pe, recontact) = self.after_impact(s, since_separation);
        ImpactResult {
            e_a,
            tau_s: tau,
            theta_end_deg: theta.to_degrees(),
            f_ball: self.law.ball_loss(y0) / e0,
            f_vib: vib / e0,
            f_vib_peak_pe: peak_pe / e0,
            f_hand: 0.0,
            f_spin: 0.5 * s.v(3) * s.v(3) / e0,
            f_rigid: 0.5 * (s.v(1) * s.v(1) + s.v(2) * s.v(2)) / e0,
            f_ke_ball: e_a * e_a,
            peak_force_n: run.peak_force,
            energy_error: run.energy_err,
            momentum_error: run.momentum_err,
            x_load_m: self.impact.coupling.load.x_load,
            t_max_compression_s: run.at.t_max,
            y0_m: y0,
            recontact,
            dt_s: self.step(),
            ..ImpactResult::ZERO
        }
    }

    /// Peak bending PE over two fundamental periods of free vibration from separation, and
    /// whether the frame meets the ball again within that window, in closed form
    /// ([`FreeVibration`]). `s` is the state `lag` seconds after separation.
    fn after_impact(&self, s: &State, lag: f64) -> (f64, bool) {
        let flex = RIGID..self.set.lam.len();
        let (mut q, mut v) = (Buf::with_capacity(flex.len()), Buf::with_capacity(flex.len()));
        for j in flex.clone() {
            q.push(s.q(j));
            v.push(s.v(j));
        }
        let free = FreeVibration::new(&self.set.omega[flex.clone()], &q, &v, &self.set.g[flex]);
        let window = 2.0 / self.impact.f1_hz;
        let peak = free.peak_pe(-lag, window - lag);
        // the gap Y_T without the flexible modes: the ball and the rigid racket
        let gap0 = -(0..RIGID).map(|i| self.set.g[i] * s.q(i)).sum::<f64>();
        let rate = -(0..RIGID).map(|i| self.set.g[i] * s.v(i)).sum::<f64>();
        (peak, free.meets_ball(gap0, rate, window - lag))
    }
}

/// The coordinates (mass-normalised, rigid first) and their rates, `[q, q']` each (storage
/// reused from impact to impact, [`crate::numeric::spare`]).
#[derive(Debug, Clone)]
struct State {
    x: Buf<Pair>,
}

pooled!(Pair);

impl State {
    fn q(&self, j: usize) -> f64 {
        self.x[j].get()[0]
    }

    fn v(&self, j: usize) -> f64 {
        self.x[j].get()[1]
    }
}

impl Solver for ModalModel {
    fn prepare(params: &Params) -> Result<Self> {
        ModalModel::new(params)
    }

    fn run(&self) -> Result<ImpactResult> {
        ModalModel::run(self)
    }
}
