//! One impact of a ball on a freely suspended flexible racket: velocity-Verlet time stepping of
//! Eqs 1, 6, 7 coupled through the contact law (Eqs 2-4, 8-10), with the phase switch at the
//! interpolated maximum of `Y_T`, the separation time interpolated at the first `Y_T = 0` of the
//! expansion phase, and the full energy ledger of SPEC.md section 2.
//!
//! ```text
//! ball      m_b y_b''  = -F                                                        (Eq 1)
//! beam      m_i y_i''  = -(K y)_i + w_i F         (w_i: load weights, node or hat)  (Eq 6)
//! twist     I_x theta'' = F r                                                      (Eq 7)
//! contact   Y_T = y_b - (sum_i w_i y_i + r theta),  F = F(Y_T, phase)              (Eq 8)
//! ```
//! The stepping is allocation-free: the banded stiffness is applied as a five-point stencil
//! through the bending moments `kappa_j c_j`, and the energy ledger and momentum are
//! accumulated in the same passes. After separation the free racket is linear, so the paper's
//! vibration measure (peak bending PE over two fundamental periods) and the re-contact check
//! come from the closed-form modal solution of the discrete beam ([`FreeVibration`]), whose
//! modes are computed once per racket and cached. A time series, when asked for, is extended by
//! stepping on.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use serde::Serialize;

use crate::error::{Error, Result};
use crate::model::beam::{Beam, LoadPoint};
use crate::model::contact::{Contact, ContactState, Phase};
use crate::model::free::FreeVibration;
use crate::params::{Grip, Params, Racket, StringLaw, Variants};

/// Fraction of the stability limit used by the default time step.
pub const DEFAULT_DT_FRACTION: f64 = 0.9;
/// The default step also resolves the contact: at most this many radians of the stiffest
/// contact oscillation per step.
pub const DEFAULT_CONTACT_PHASE_PER_STEP: f64 = 2.0e-3;
/// The impact must end within this many compression half-periods `pi sqrt(m_b / k_series)`.
pub const IMPACT_TIME_LIMIT_HALF_PERIODS: f64 = 20.0;
/// An impact whose relative energy error exceeds this is an error, never a result.
pub const ENERGY_ERROR_LIMIT: f64 = 1.0e-4;
/// Refuse parameters whose expected run (two rigid-contact half-periods plus the post-impact
/// window of two fundamental periods) needs more node-steps than this (about 15 s here).
pub const MAX_NODE_STEPS: f64 = 1.0e9;

/// What one impact reports (SPEC.md section 2). Energies are fractions of `m_b v1^2 / 2`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactResult {
    /// Apparent coefficient of restitution `v2 / v1` (racket initially at rest).
    pub e_a: f64,
    /// Impact duration, s.
    pub tau_s: f64,
    /// Rotation about the long axis at the end of the impact, degrees.
    pub theta_end_deg: f64,
    /// Energy dissipated in the ball (Eq 11).
    pub f_ball: f64,
    /// Racket vibration energy after impact: racket energy minus its rigid-body energy.
    pub f_vib: f64,
    /// The paper's vibration measure: peak bending PE during two fundamental periods after impact.
    pub f_vib_peak_pe: f64,
    /// Kinetic energy of twist about the long axis.
    pub f_spin: f64,
    /// Energy taken by the hand (`--grip hand`: its springs' energy plus what its dampers
    /// dissipated) at separation; 0 for the paper's free racket.
    pub f_hand: f64,
    /// Rigid-body kinetic energy of the racket (translation + rotation about the centre of mass).
    pub f_rigid: f64,
    /// Rebound kinetic energy of the ball (= e_a^2).
    pub f_ke_ball: f64,
    /// Maximum contact force, N.
    pub peak_force_n: f64,
    /// Largest relative deviation of the total energy from its initial value, over the run.
    pub energy_error: f64,
    /// Largest relative deviation of the total linear momentum from `m_b v1`, over the run.
    pub momentum_error: f64,
    /// Where the force really acted, m from the tip.
    pub x_load_m: f64,
    /// Time of maximum total compression `Y_T`, s.
    pub t_max_compression_s: f64,
    /// Maximum ball compression `Y0`, m.
    pub y0_m: f64,
    /// True if the vibrating frame caught the ball again within the post-impact window.
    pub recontact: bool,
    /// Time step used, s.
    pub dt_s: f64,
}

/// One sample of the time series.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SeriesRow {
    /// Time, s.
    pub t_s: f64,
    /// Contact force, N.
    pub force_n: f64,
    /// Ball displacement `y_b`, m.
    pub y_ball_m: f64,
    /// Total compression `Y_T` (ball + strings), m; negative after separation.
    pub y_total_m: f64,
    /// Rotation about the long axis, rad.
    pub theta_rad: f64,
    /// Ball kinetic energy (fraction of the initial).
    pub ke_ball: f64,
    /// Ball elastic energy plus the energy it has dissipated.
    pub pe_ball: f64,
    /// String elastic energy.
    pub pe_string: f64,
    /// Kinetic energy of all beam nodes (translation, rotation and vibration).
    pub ke_racket: f64,
    /// Bending potential energy of the beam.
    pub pe_racket: f64,
    /// Kinetic energy of twist about the long axis.
    pub ke_spin: f64,
    /// Energy in the hand's springs plus what its dampers dissipated (`--grip hand`).
    pub hand: f64,
    /// Sum of the above (1 up to the integration error).
    pub total: f64,
}

/// Options for recording the time series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesOptions {
    /// Spacing of the samples, s (rounded to a whole number of steps).
    pub sample_dt: f64,
    /// Record (and step) at least until this time, s.
    pub t_end: f64,
}

impl Default for SeriesOptions {
    fn default() -> Self {
        SeriesOptions { sample_dt: 2.0e-5, t_end: 0.0 }
    }
}

/// A prepared impact: validated parameters, the discrete beam, the load point and the time step.
#[derive(Debug, Clone)]
pub struct Model {
    /// The parameters.
    pub params: Params,
    /// The contact law.
    pub contact: Contact,
    /// Where the force acts.
    pub load: LoadPoint,
    /// Fundamental (first flexible) frequency of the free beam, Hz.
    pub f1_hz: f64,
    /// Stability limit of the explicit scheme, s.
    pub dt_limit: f64,
    /// The time step in use, s.
    pub dt: f64,
    /// The contact phase must end within this simulated time, s (a guard, not physics).
    pub time_limit_s: f64,
    /// The racket's modes (shared by every impact on the same racket).
    pub basis: Arc<Basis>,
    /// The hand (`--grip hand`): stiffness (N/m) and damping (N s/m) at each node; empty for
    /// the free racket.
    hand: Vec<(f64, f64)>,
    /// `1 / m_b`, 1/kg: the ball's acceleration per unit force.
    inv_ball_mass: f64,
    /// `r / I_x`, 1/(kg m): the twist's angular acceleration per unit force.
    twist_per_force: f64,
}

/// The discrete beam of one racket with its flexible modes: computed once per racket and
/// discretisation and cached, so a sweep over impact points, speeds, strings or balls pays for
/// the eigen-decomposition once.
#[derive(Debug)]
pub struct Basis {
    /// The discrete beam.
    pub beam: Beam,
    /// The explicit solver's node arrays, padded with zeros to whole chunks of four nodes.
    pub pad: Padded,
    /// Flexible modes, ascending: `omega^2`, rad^2/s^2.
    pub lam: Vec<f64>,
    /// `omega`, rad/s.
    pub omega: Vec<f64>,
    /// Shapes normalised to unit modal mass (`phi^T M phi = 1`), one per flexible mode.
    pub shapes: Vec<Vec<f64>>,
}

/// The explicit solver's node arrays padded with zeros: `lanes` (a multiple of four, at least the
/// node count) entries of mass and inverse mass, `lanes + 2` of `kappa` (the state `y`, `v`, `a`
/// has as many). The padding nodes have no mass, inverse mass or stiffness, so they never move
/// and carry no moment, and the loops over them run in whole chunks of four without a remainder.
#[derive(Debug)]
pub struct Padded {
    /// A multiple of four, at least the node count.
    pub lanes: usize,
    /// `m_i`, kg.
    pub mass: Vec<f64>,
    /// `1 / m_i`, 1/kg.
    pub inv_mass: Vec<f64>,
    /// `kappa_i`, N/m.
    pub kappa: Vec<f64>,
}

impl Padded {
    /// The padded arrays of a beam.
    pub(crate) fn new(beam: &Beam) -> Self {
        let n = beam.nodes();
        let lanes = n.div_ceil(4) * 4;
        let padded = |x: &[f64], len: usize| {
            let mut v = x.to_vec();
            v.resize(len, 0.0);
            v
        };
        let inv_mass: Vec<f64> = beam.mass.iter().map(|m| 1.0 / m).collect();
        Padded {
            lanes,
            mass: padded(&beam.mass, lanes),
            inv_mass: padded(&inv_mass, lanes),
            kappa: padded(&beam.kappa, lanes + 2),
        }
    }
}

/// Cached bases, keyed by the beam-defining numbers of the racket and the segment count, with
/// the bytes they hold.
static BASES: OnceLock<Mutex<BasisCache>> = OnceLock::new();
/// The cached bases and the bytes they hold.
type BasisCache = (HashMap<BasisKey, Arc<Basis>>, usize);
/// The bits of the segment count, length, mass and EI, and of the profile's knots, densities and
/// stiffnesses when there is one (no heap: looked up once per impact).
type BasisKey = ([u64; 4], Option<[u64; 12]>);
/// The cache is emptied before it would hold more than this many bytes of modes (a sweep over
/// many rackets on fine beams would otherwise keep N^2 numbers per racket).
const BASIS_CACHE_BYTES: usize = 32 << 20;

impl Basis {
    /// The basis of a racket on `segments` segments, from the cache or computed.
    pub fn of(racket: &Racket, segments: usize) -> Arc<Basis> {
        let profile = racket.profile.as_ref().map(|p| {
            let mut bits = [0; 12];
            for (b, v) in bits.iter_mut().zip(p.knots.iter().chain(&p.density).chain(&p.stiffness)) {
                *b = v.to_bits();
            }
            bits
        });
        let key: BasisKey =
            ([segments as u64, racket.length.to_bits(), racket.mass.to_bits(), racket.ei.to_bits()], profile);
        let cache = BASES.get_or_init(|| Mutex::new((HashMap::new(), 0)));
        if let Some(b) = cache.lock().unwrap_or_else(|e| e.into_inner()).0.get(&key) {
            return Arc::clone(b);
        }
        let beam = Beam::new(racket, segments);
        let (lam, shapes) = beam.modes_mass_normalised();
        let omega = lam.iter().map(|l| l.max(0.0).sqrt()).collect();
        let pad = Padded::new(&beam);
        let basis = Arc::new(Basis { beam, pad, lam, omega, shapes });
        // the shapes, and eight arrays of about one number per node (the beam's x, mass and
        // kappa, the padded mass, inverse mass and kappa, the eigenvalues and frequencies)
        let bytes = 8 * (basis.shapes.len() + 8) * basis.beam.nodes();
        let mut guard = cache.lock().unwrap_or_else(|e| e.into_inner());
        let (map, held) = &mut *guard;
        if *held + bytes > BASIS_CACHE_BYTES {
            map.clear();
            *held = 0;
        }
        if map.insert(key, Arc::clone(&basis)).is_none() {
            *held += bytes;
        }
        basis
    }
}

impl Model {
    /// The discrete beam.
    pub fn beam(&self) -> &Beam {
        &self.basis.beam
    }

    /// Validate the parameters, discretise the racket and choose (or check) the time step.
    pub fn new(params: &Params) -> Result<Self> {
        Self::build(params, true)
    }

    /// As [`Model::new`] for the modal solver, which takes its own steps: the explicit scheme's
    /// work limit (too many node-steps for its step) does not apply.
    pub(crate) fn for_modal(params: &Params) -> Result<Self> {
        Self::build(params, false)
    }

    fn build(params: &Params, limit_work: bool) -> Result<Self> {
        params.validate()?;
        let basis = Basis::of(&params.racket, params.numerics.segments);
        let beam = &basis.beam;
        let mut contact = Contact::new(&params.ball, &params.strings);
        let v = &params.variants;
        if v.strings == StringLaw::Stiffening && v.string_stiffening > 0.0 {
            let energy = 0.5 * params.ball.mass * params.impact.v1 * params.impact.v1;
            contact = contact.with_stiffening(v.string_stiffening, v.stiffening_deflection, energy);
        }
        let hand = if v.grip == Grip::Hand { hand_per_node(beam, v) } else { Vec::new() };
        let load = beam.load_point(params.impact.x, params.numerics.load);
        let f1_hz = basis.omega[0] / (2.0 * std::f64::consts::PI);
        // Weyl: the contact spring adds at most k_c |g|^2 to the largest eigenvalue, where g is
        // the mass-normalised coupling vector of the ball, the load nodes and the twist.
        let lp = &load;
        let g2 = 1.0 / params.ball.mass
            + lp.weights[0].powi(2) / beam.mass[lp.nodes[0]]
            + lp.weights[1].powi(2) / beam.mass[lp.nodes[1]]
            + params.impact.r.powi(2) / params.racket.ix;
        let lam_max = basis.lam.last().copied().unwrap_or(0.0);
        // the hand adds at most its largest stiffness per mass to the top eigenvalue
        let hand_max = hand.iter().zip(&beam.mass).map(|((k, _), m)| k / m).fold(0.0, f64::max);
        let omega_max = (lam_max + hand_max + contact.max_stiffness() * g2).sqrt();
        let dt_limit = 2.0 / omega_max;
        let t_limit = time_limit(params, &contact);
        let dt = match params.numerics.dt {
            Some(dt) => {
                if dt >= dt_limit {
                    return Err(Error::invalid(
                        "dt",
                        dt,
                        format!("time step must be below the stability limit 2/omega_max = {dt_limit:.4e} s"),
                    ));
                }
                dt
            }
            None => {
                let omega_contact = (contact.max_stiffness() * g2).sqrt();
                (DEFAULT_DT_FRACTION * dt_limit).min(DEFAULT_CONTACT_PHASE_PER_STEP / omega_contact)
            }
        };
        let t_expected = 2.0 * t_limit / IMPACT_TIME_LIMIT_HALF_PERIODS + 2.0 / f1_hz;
        let steps = t_expected / dt;
        let work = steps * beam.nodes() as f64;
        if !(dt.is_finite() && dt > 0.0 && f1_hz.is_finite() && f1_hz > 0.0 && (work <= MAX_NODE_STEPS || !limit_work))
        {
            if let Some(user_dt) = params.numerics.dt {
                return Err(Error::invalid(
                    "dt",
                    user_dt,
                    format!(
                        "time step is so small that the run needs about {steps:.2e} steps on {} nodes \
                         (limit {MAX_NODE_STEPS:.0e} node-steps); use dt >= {:.3e} s",
                        beam.nodes(),
                        dt * work / MAX_NODE_STEPS
                    ),
                ));
            }
            return Err(Error::TooManySteps { steps, dt_s: dt, nodes: beam.nodes(), limit: MAX_NODE_STEPS });
        }
        Ok(Model {
            params: *params,
            contact,
            load,
            f1_hz,
            dt_limit,
            dt,
            time_limit_s: t_limit,
            basis,
            hand,
            inv_ball_mass: 1.0 / params.ball.mass,
            twist_per_force: params.impact.r / params.racket.ix,
        })
    }

    /// Run the impact.
    pub fn run(&self) -> Result<ImpactResult> {
        self.integrate(None).map(|(r, _)| r)
    }

    /// Run the impact and record the time series.
    pub fn run_with_series(&self, opts: SeriesOptions) -> Result<(ImpactResult, Vec<SeriesRow>)> {
        self.integrate(Some(opts)).map(|(r, s)| (r, s.unwrap_or_default()))
    }

    fn integrate(&self, series: Option<SeriesOptions>) -> Result<(ImpactResult, Option<Vec<SeriesRow>>)> {
        let p = &self.params;
        let (mb, v1, r, ix) = (p.ball.mass, p.impact.v1, p.impact.r, p.racket.ix);
        let beam = self.beam();
        let dt = self.dt;
        let [j0, j1] = self.load.nodes;
        let [w0, w1] = self.load.weights;
        let e0 = 0.5 * mb * v1 * v1;
        let p0 = mb * v1;
        let t_limit = self.time_limit_s;

        let mut st = Stepper::new(self.basis.pad.lanes, v1);
        let mut phase = Phase::Compression;
        let mut cs = ContactState::ZERO;
        let mut t = 0.0;
        let mut yt_prev = 0.0;
        let mut ytd_prev = v1;
        // the largest deviations of the energy and the momentum from their initial values, J and
        // kg m/s (made relative once, after the loop)
        let mut energy_dev: f64 = 0.0;
        let mut momentum_dev: f64 = 0.0;
        let mut peak_force: f64 = 0.0;
        let mut t_max = 0.0;
        let mut y0 = 0.0;
        let stride = series.map(|o| ((o.sample_dt / dt).round() as usize).max(1)).unwrap_or(usize::MAX);
        let mut rows = series.map(|_| Vec::new());
        let mut step: usize = 0;

        let ledger = |st: &Stepper, phase: Phase, cs: &ContactState, pe: f64, ke: f64| -> Ledger {
            Ledger {
                ke_ball: 0.5 * mb * st.vb * st.vb,
                pe_ball: self.contact.ball_energy_with_loss(phase, cs),
                pe_string: self.contact.string_energy(cs),
                ke_racket: ke,
                pe_racket: pe,
                ke_spin: 0.5 * ix * st.om * st.om,
                hand: st.hand_energy(&self.hand),
            }
        };
        let record = |rows: &mut Option<Vec<SeriesRow>>, t: f64, st: &Stepper, cs: &ContactState, l: &Ledger| {
            if let Some(rows) = rows.as_mut() {
                let yt = st.yb - (w0 * st.y[j0] + w1 * st.y[j1] + r * st.th);
                rows.push(l.row(t, e0, cs.force, st.yb, yt, st.th));
            }
        };
        record(&mut rows, 0.0, &st, &cs, &ledger(&st, phase, &cs, 0.0, 0.0));

        // contact phase
        let (tau, theta_end) = loop {
            if t > t_limit {
                return Err(Error::ImpactDidNotEnd { limit_s: t_limit });
            }
            let (th_prev, om_prev) = (st.th, st.om);
            let pe = st.drift(dt, &self.basis.pad.kappa);
            let yt = st.yb - (w0 * st.y[j0] + w1 * st.y[j1] + r * st.th);
            cs = self.contact.state(yt, phase, cs.guess())?;
            let (mut ke, mut mom) = st.kick(dt, cs.force, self);
            mom += st.hand_impulse;
            let mut ytd = st.vb - (w0 * st.v[j0] + w1 * st.v[j1] + r * st.om);
            if phase == Phase::Compression && ytd <= 0.0 {
                // The maximum of Y_T lies in this step: switch to the expansion law there.
                let (s_max, yt_max) = hermite_max(yt_prev, ytd_prev, yt, ytd, dt);
                t_max = t + s_max * dt;
                y0 = self.contact.ball_compression_at_max(yt_max);
                phase = Phase::Expansion { y0 };
                let f_old = cs.force;
                cs = self.contact.state(yt, phase, (1.0, 1.0))?;
                st.correct_force(dt, cs.force - f_old, self);
                ytd = st.vb - (w0 * st.v[j0] + w1 * st.v[j1] + r * st.om);
                ke = beam.kinetic_energy(&st.v);
                mom = beam.momentum(&st.v) + st.hand_impulse;
            }
            t += dt;
            step += 1;
            peak_force = peak_force.max(cs.force);
            let l = ledger(&st, phase, &cs, pe, ke);
            energy_dev = energy_dev.max((l.total() - e0).abs());
            momentum_dev = momentum_dev.max((mb * st.vb + mom - p0).abs());
            if step % stride == 0 {
                record(&mut rows, t, &st, &cs, &l);
            }
            if matches!(phase, Phase::Expansion { .. }) && yt <= 0.0 {
                let s = hermite_root(yt_prev, ytd_prev, yt, ytd, dt);
                let theta = hermite_eval(th_prev, om_prev, st.th, st.om, dt, s);
                break (t - dt + s * dt, theta);
            }
            yt_prev = yt;
            ytd_prev = ytd;
        };

        // The ball is free; the racket keeps vibrating.
        let e_a = -st.vb / v1;
        let f_rigid = beam.rigid_energy(&st.v) / e0;
        let e_racket = beam.kinetic_energy(&st.v) + beam.bending_energy(&st.y);
        let f_vib = e_racket / e0 - f_rigid;
        let f_spin = 0.5 * ix * st.om * st.om / e0;
        let f_ball = self.contact.ball_loss(y0) / e0;
        let f_hand = st.hand_energy(&self.hand) / e0;
        // the paper's window: two fundamental periods from the separation time itself
        let t_window = tau + 2.0 / self.f1_hz;
        let t_post = t_window.max(series.map(|o| o.t_end).unwrap_or(0.0));
        let (peak_pe, recontact) = if self.hand.is_empty() {
            self.after_impact(&st, t - tau, t_post - t)
        } else {
            // a held racket is damped: no modal closed form, step it on
            let mut s2 = st.clone();
            let (mut peak, mut meets) = (beam.bending_energy(&s2.y), false);
            let mut t2 = t;
            while t2 < t_post {
                let pe = s2.drift(dt, &self.basis.pad.kappa);
                s2.kick(dt, 0.0, self);
                t2 += dt;
                if t2 <= t_window {
                    peak = peak.max(pe);
                }
                meets |= s2.yb - (w0 * s2.y[j0] + w1 * s2.y[j1] + r * s2.th) > 0.0;
            }
            (peak, meets)
        };
        let (energy_err, momentum_err) = (energy_dev / e0, momentum_dev / p0);
        if energy_err > ENERGY_ERROR_LIMIT {
            return Err(Error::EnergyDrift { error: energy_err, limit: ENERGY_ERROR_LIMIT });
        }
        let result = ImpactResult {
            e_a,
            tau_s: tau,
            theta_end_deg: theta_end.to_degrees(),
            f_ball,
            f_vib,
            f_vib_peak_pe: peak_pe / e0,
            f_spin,
            f_hand,
            f_rigid,
            f_ke_ball: e_a * e_a,
            peak_force_n: peak_force,
            energy_error: energy_err,
            momentum_error: momentum_err,
            x_load_m: self.load.x_load,
            t_max_compression_s: t_max,
            y0_m: y0,
            recontact,
            dt_s: dt,
        };
        result.check_finite()?;
        // A time series is extended by stepping the free racket on (the result above does
        // not depend on it).
        if rows.is_some() {
            while t < t_post {
                let pe = st.drift(dt, &self.basis.pad.kappa);
                let (ke, _) = st.kick(dt, 0.0, self);
                t += dt;
                step += 1;
                if step % stride == 0 {
                    record(&mut rows, t, &st, &cs, &ledger(&st, phase, &cs, pe, ke));
                }
            }
        }
        Ok((result, rows))
    }

    /// The free vibration after separation, in closed form: the peak bending PE over the
    /// paper's window (two fundamental periods from separation) and whether the frame meets the
    /// ball again before `ahead` seconds from now. `st` is the state `lag` seconds after
    /// separation.
    fn after_impact(&self, st: &Stepper, lag: f64, ahead: f64) -> (f64, bool) {
        let basis = &self.basis;
        let beam = &basis.beam;
        let [j0, j1] = self.load.nodes;
        let [w0, w1] = self.load.weights;
        let k = basis.lam.len();
        let (mut q, mut qd, mut g) = (Vec::with_capacity(k), Vec::with_capacity(k), Vec::with_capacity(k));
        for phi in &basis.shapes {
            let (mut a, mut b) = (0.0, 0.0);
            for (((f, m), y), v) in phi.iter().zip(&beam.mass).zip(&st.y).zip(&st.v) {
                let pm = f * m;
                a += pm * y;
                b += pm * v;
            }
            q.push(a);
            qd.push(b);
            g.push(w0 * phi[j0] + w1 * phi[j1]);
        }
        let free = FreeVibration::new(&basis.omega, &q, &qd, &g);
        let peak = free.peak_pe(-lag, 2.0 / self.f1_hz - lag);
        // the gap without the vibration is affine in time: ball minus rigid motion of the load point
        let r = self.params.impact.r;
        let flex0: f64 = g.iter().zip(&q).map(|(g, q)| g * q).sum();
        let flex_rate: f64 = g.iter().zip(&qd).map(|(g, v)| g * v).sum();
        let gap0 = st.yb - r * st.th - (w0 * st.y[j0] + w1 * st.y[j1] - flex0);
        let rate = st.vb - r * st.om - (w0 * st.v[j0] + w1 * st.v[j1] - flex_rate);
        (peak, free.meets_ball(gap0, rate, ahead))
    }
}

impl ImpactResult {
    /// Every field finite, or an error naming the first that is not (`f64::max` would hide a
    /// NaN in the running error maxima, so the check is on the final numbers).
    pub fn check_finite(&self) -> Result<()> {
        let fields = [
            ("e_a", self.e_a),
            ("tau_s", self.tau_s),
            ("theta_end_deg", self.theta_end_deg),
            ("f_ball", self.f_ball),
            ("f_vib", self.f_vib),
            ("f_vib_peak_pe", self.f_vib_peak_pe),
            ("f_spin", self.f_spin),
            ("f_hand", self.f_hand),
            ("f_rigid", self.f_rigid),
            ("f_ke_ball", self.f_ke_ball),
            ("peak_force_n", self.peak_force_n),
            ("energy_error", self.energy_error),
            ("momentum_error", self.momentum_error),
        ];
        match fields.iter().find(|(_, v)| !v.is_finite()) {
            Some((field, _)) => Err(Error::NonFinite { field }),
            None => Ok(()),
        }
    }
}

/// Validate, prepare and run one impact with the solver (and model variant) the parameters name.
pub fn simulate(params: &Params) -> Result<ImpactResult> {
    if params.variants.frame == crate::params::Frame::Rigid {
        return crate::model::rigid::impact(params);
    }
    match params.numerics.solver {
        crate::params::SolverKind::Fd => Model::new(params)?.run(),
        crate::params::SolverKind::Modal => crate::modal::ModalModel::new(params)?.run(),
    }
}

/// The simulated-time limit of the contact phase, s.
fn time_limit(p: &Params, contact: &Contact) -> f64 {
    IMPACT_TIME_LIMIT_HALF_PERIODS * std::f64::consts::PI * (p.ball.mass / contact.compression_stiffness()).sqrt()
}

/// The state of the ball, the beam and the twist, with the bending-moment buffer.
#[derive(Clone)]
struct Stepper {
    yb: f64,
    vb: f64,
    ab: f64,
    y: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    th: f64,
    om: f64,
    al: f64,
    /// `moment[i + 1] = kappa_i c_i` for node i; zero padding at both ends.
    moment: Vec<f64>,
    /// The contact force on each node, N: zero but at the load nodes during a kick.
    load: Vec<f64>,
    /// Energy dissipated by the hand's dampers so far, J.
    hand_loss: f64,
    /// Momentum given to the hand so far, kg m/s.
    hand_impulse: f64,
}

impl Stepper {
    /// At rest with the ball at `v1` (m/s), for a beam padded to `lanes` nodes ([`Padded`]).
    fn new(lanes: usize, v1: f64) -> Self {
        let zeros = vec![0.0; lanes + 2];
        Stepper {
            yb: 0.0,
            vb: v1,
            ab: 0.0,
            y: zeros.clone(),
            v: zeros.clone(),
            a: zeros,
            th: 0.0,
            om: 0.0,
            al: 0.0,
            moment: vec![0.0; lanes + 4],
            load: vec![0.0; lanes],
            hand_loss: 0.0,
            hand_impulse: 0.0,
        }
    }

    /// The half-kicks of the ball and of the twist under the contact force `f`.
    fn kick_ball_and_twist(&mut self, half: f64, f: f64, model: &Model) {
        let ab = -f * model.inv_ball_mass;
        self.vb += (self.ab + ab) * half;
        self.ab = ab;
        let al = f * model.twist_per_force;
        self.om += (self.al + al) * half;
        self.al = al;
    }

    /// Energy stored in the hand's springs plus what its dampers dissipated, J.
    fn hand_energy(&self, hand: &[(f64, f64)]) -> f64 {
        self.hand_loss + 0.5 * hand.iter().zip(&self.y).map(|((k, _), y)| k * y * y).sum::<f64>()
    }

    /// The kick with a hand: springs `-k y` at the new positions and dampers `-c v` taken
    /// implicitly (trapezoidal in `v`, so any damping is stable), the damper loss and the hand's
    /// impulse integrated by the trapezoidal rule.
    fn kick_held(&mut self, dt: f64, f: f64, model: &Model) -> (f64, f64) {
        let half = 0.5 * dt;
        self.kick_ball_and_twist(half, f, model);
        let basis = &model.basis;
        let [j0, j1] = model.load.nodes;
        let [w0, w1] = model.load.weights;
        let (mut twice_ke, mut mom) = (0.0, 0.0);
        for (i, &(k, c)) in model.hand.iter().enumerate() {
            let im = basis.pad.inv_mass[i];
            let mut force = Beam::elastic_force(&self.moment[i..i + 3]) - k * self.y[i];
            if i == j0 {
                force += w0 * f;
            }
            if i == j1 {
                force += w1 * f;
            }
            let v_old = self.v[i];
            let hand_old = -k * (self.y[i] - self.v[i] * dt - self.a[i] * half * dt) - c * v_old;
            let v_new = (v_old + self.a[i] * half + force * im * half) / (1.0 + c * im * half);
            self.a[i] = (force - c * v_new) * im;
            self.v[i] = v_new;
            self.hand_loss += half * c * (v_old * v_old + v_new * v_new);
            self.hand_impulse -= half * (hand_old + (-k * self.y[i] - c * v_new));
            let m = basis.beam.mass[i];
            twice_ke += m * v_new * v_new;
            mom += m * v_new;
        }
        (0.5 * twice_ke, mom)
    }

    /// Positions to the end of the step, `y += v dt + a dt^2 / 2`, then the bending moments
    /// `kappa_j (y_{j-1} - 2 y_j + y_{j+1})`; returns the bending energy, J.
    fn drift(&mut self, dt: f64, kappa: &[f64]) -> f64 {
        let h = 0.5 * dt * dt;
        self.yb += self.vb * dt + self.ab * h;
        self.th += self.om * dt + self.al * h;
        drift_nodes(&mut self.y, &self.v, &self.a, dt, h);
        Beam::bending_moments(kappa, &self.y, &mut self.moment)
    }

    /// New accelerations from the bending moments and the contact force `f`, and the velocity
    /// half-kicks `v += (a_old + a_new) dt / 2`; returns the beam's kinetic energy (J) and
    /// momentum (kg m/s).
    fn kick(&mut self, dt: f64, f: f64, model: &Model) -> (f64, f64) {
        if !model.hand.is_empty() {
            return self.kick_held(dt, f, model);
        }
        let half = 0.5 * dt;
        self.kick_ball_and_twist(half, f, model);
        let [j0, j1] = model.load.nodes;
        let [w0, w1] = model.load.weights;
        self.load[j0] += w0 * f;
        self.load[j1] += w1 * f;
        let [twice_ke, mom] = kick_nodes(&mut self.v, &mut self.a, &self.moment, &self.load, &model.basis.pad, half);
        self.load[j0] = 0.0;
        self.load[j1] = 0.0;
        (0.5 * twice_ke, mom)
    }

    /// Replace the contact force of the last kick by one `df` larger (used at the phase switch).
    fn correct_force(&mut self, dt: f64, df: f64, model: &Model) {
        let half = 0.5 * dt;
        let dab = -df * model.inv_ball_mass;
        self.ab += dab;
        self.vb += dab * half;
        let dal = df * model.twist_per_force;
        self.al += dal;
        self.om += dal * half;
        let [j0, j1] = model.load.nodes;
        let [w0, w1] = model.load.weights;
        for (j, w) in [(j0, w0), (j1, w1)] {
            let im = model.basis.pad.inv_mass[j];
            // a hand's damper at the node takes part implicitly, as in the kick
            let c = model.hand.get(j).map_or(0.0, |h| h.1);
            let dv = w * df * im * half / (1.0 + c * im * half);
            let v_old = self.v[j];
            self.v[j] += dv;
            self.a[j] += (w * df - c * dv) * im;
            self.hand_loss += half * c * (self.v[j] * self.v[j] - v_old * v_old);
            self.hand_impulse += half * c * dv;
        }
    }
}

/// The nodes' drift `y += v dt + a h` (`h = dt^2 / 2`). A function of its own so that the slices
/// are known not to overlap and the loop vectorises without run-time checks.
#[inline]
fn drift_nodes(y: &mut [f64], v: &[f64], a: &[f64], dt: f64, h: f64) {
    for ((y, v), a) in y.iter_mut().zip(v).zip(a) {
        *y += v * dt + a * h;
    }
}

/// The nodes' accelerations from the bending moments (`moment[i..i + 3]` around node i) and the
/// contact force `load`, the half-kicks `v += (a_old + a_new) dt / 2` (`half = dt / 2`), and the
/// sums `[sum m v^2, sum m v]` of the new velocities (four partial sums each, over the chunks of
/// four nodes of [`Padded`]); as [`drift_nodes`], a function of its own so that the loops
/// vectorise.
#[inline]
fn kick_nodes(v: &mut [f64], a: &mut [f64], moment: &[f64], load: &[f64], pad: &Padded, half: f64) -> [f64; 2] {
    let lanes = pad.lanes;
    let (v, a) = (&mut v[..lanes], &mut a[..lanes]);
    // the three moments around node i as three shifted slices
    let (left, centre, right) = (&moment[..lanes], &moment[1..lanes + 1], &moment[2..lanes + 2]);
    let moments = left.iter().zip(centre).zip(right);
    let nodes = load.iter().zip(&pad.inv_mass);
    for (((v, a), ((l, c), r)), (f, im)) in v.iter_mut().zip(a.iter_mut()).zip(moments).zip(nodes) {
        let an = (Beam::elastic_force(&[*l, *c, *r]) + f) * im;
        *v += (*a + an) * half;
        *a = an;
    }
    let (mut twice_ke, mut momentum) = ([0.0; 4], [0.0; 4]);
    for (v, m) in v.chunks_exact(4).zip(pad.mass.chunks_exact(4)) {
        for k in 0..4 {
            let p = m[k] * v[k];
            twice_ke[k] += p * v[k];
            momentum[k] += p;
        }
    }
    let total = |x: [f64; 4]| (x[0] + x[2]) + (x[1] + x[3]);
    [total(twice_ke), total(momentum)]
}

/// The damping ratio the hand gives flexible mode `k` (1 = fundamental) of the racket, from
/// the hand's dampers projected on the mode: `zeta_k = phi_k^T C phi_k / (2 omega_k)` with
/// mass-normalised `phi_k` (the modal damping of a lightly damped mode). 0 without a hand.
pub fn hand_damping_ratio(params: &Params, k: usize) -> f64 {
    if params.variants.grip != Grip::Hand || k == 0 {
        return 0.0;
    }
    let basis = Basis::of(&params.racket, params.numerics.segments);
    let (Some(phi), Some(w)) = (basis.shapes.get(k - 1), basis.omega.get(k - 1)) else {
        return 0.0;
    };
    let hand = hand_per_node(&basis.beam, &params.variants);
    hand.iter().zip(phi).map(|((_, c), f)| c * f * f).sum::<f64>() / (2.0 * w)
}

/// The hand's stiffness and damping at each node: the totals spread over the grip length from
/// the butt in proportion to each node's share of it (a node's share is the part of its half
/// segments on either side that lies in the grip).
fn hand_per_node(beam: &Beam, v: &Variants) -> Vec<(f64, f64)> {
    let l = beam.x[beam.segments];
    let start = l - v.grip_length;
    let share: Vec<f64> = beam
        .x
        .iter()
        .map(|&x| {
            let (lo, hi) = ((x - 0.5 * beam.s).max(0.0), (x + 0.5 * beam.s).min(l));
            (hi - lo.max(start)).max(0.0)
        })
        .collect();
    let total: f64 = share.iter().sum();
    share.iter().map(|w| (v.hand_stiffness * w / total, v.hand_damping * w / total)).collect()
}

/// The energy ledger at one instant, J.
struct Ledger {
    ke_ball: f64,
    pe_ball: f64,
    pe_string: f64,
    ke_racket: f64,
    pe_racket: f64,
    ke_spin: f64,
    /// Hand springs plus hand damper loss.
    hand: f64,
}

impl Ledger {
    fn total(&self) -> f64 {
        self.ke_ball + self.pe_ball + self.pe_string + self.ke_racket + self.pe_racket + self.ke_spin + self.hand
    }

    fn row(&self, t: f64, e0: f64, force: f64, yb: f64, yt: f64, th: f64) -> SeriesRow {
        SeriesRow {
            t_s: t,
            force_n: force,
            y_ball_m: yb,
            y_total_m: yt,
            theta_rad: th,
            ke_ball: self.ke_ball / e0,
            pe_ball: self.pe_ball / e0,
            pe_string: self.pe_string / e0,
            ke_racket: self.ke_racket / e0,
            pe_racket: self.pe_racket / e0,
            ke_spin: self.ke_spin / e0,
            hand: self.hand / e0,
            total: self.total() / e0,
        }
    }
}

/// Cubic Hermite interpolant on a step of length `h` with values `p0, p1` and derivatives
/// `m0, m1`, evaluated at the fraction `s` of the step.
pub(crate) fn hermite_eval(p0: f64, m0: f64, p1: f64, m1: f64, h: f64, s: f64) -> f64 {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * h * m0 + (-2.0 * s3 + 3.0 * s2) * p1 + (s3 - s2) * h * m1
}

/// Derivative (per unit time) of the Hermite interpolant.
fn hermite_slope(p0: f64, m0: f64, p1: f64, m1: f64, h: f64, s: f64) -> f64 {
    let s2 = s * s;
    ((6.0 * s2 - 6.0 * s) * p0
        + (3.0 * s2 - 4.0 * s + 1.0) * h * m0
        + (6.0 * s - 6.0 * s2) * p1
        + (3.0 * s2 - 2.0 * s) * h * m1)
        / h
}

/// Bisection for the sign change of `f` on [0, 1], given f(0) > 0 >= f(1).
fn bisect(f: impl Fn(f64) -> f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The maximum of the Hermite interpolant in a step where the slope goes from > 0 to <= 0:
/// (fraction of the step, value).
pub(crate) fn hermite_max(p0: f64, m0: f64, p1: f64, m1: f64, h: f64) -> (f64, f64) {
    let s = bisect(|s| hermite_slope(p0, m0, p1, m1, h, s));
    let v = hermite_eval(p0, m0, p1, m1, h, s);
    (s, v.max(p0).max(p1))
}

/// The zero of the Hermite interpolant in a step where the value goes from > 0 to <= 0.
pub(crate) fn hermite_root(p0: f64, m0: f64, p1: f64, m1: f64, h: f64) -> f64 {
    bisect(|s| hermite_eval(p0, m0, p1, m1, h, s))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn hermite_is_exact_for_cubics() {
        let f = |t: f64| 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t * t * t;
        let df = |t: f64| 2.0 - 6.0 * t + 1.5 * t * t;
        let (a, h) = (0.2, 0.7);
        for &s in &[0.0, 0.3, 0.8, 1.0] {
            assert_relative_eq!(hermite_eval(f(a), df(a), f(a + h), df(a + h), h, s), f(a + s * h), epsilon = 1e-13);
            assert_relative_eq!(hermite_slope(f(a), df(a), f(a + h), df(a + h), h, s), df(a + s * h), epsilon = 1e-12);
        }
    }

    #[test]
    fn an_impact_that_does_not_end_in_time_is_an_error_not_a_hang() {
        let mut model = Model::new(&Params::paper()).unwrap();
        model.time_limit_s = 1.0e-3;
        let msg = model.run().unwrap_err().to_string();
        assert!(msg.starts_with("impact did not end within 1.0000e-3 s"), "{msg}");
    }

    #[test]
    fn tiny_time_step_is_refused_rather_than_run_for_hours() {
        let mut p = Params::paper();
        p.numerics.dt = Some(1e-14);
        let msg = Model::new(&p).unwrap_err().to_string();
        assert!(msg.starts_with("invalid dt = ") && msg.contains("steps"), "{msg}");
    }

    #[test]
    fn a_step_at_the_stability_limit_is_caught_by_the_energy_guard() {
        let mut p = Params::paper();
        let limit = Model::new(&p).unwrap().dt_limit;
        p.numerics.dt = Some(limit * 0.9999);
        match simulate(&p) {
            Err(Error::EnergyDrift { error, .. }) => assert!(error > ENERGY_ERROR_LIMIT),
            Ok(r) => assert!(r.energy_error <= ENERGY_ERROR_LIMIT, "{r:?}"),
            Err(e) => panic!("unexpected error {e}"),
        }
    }

    #[test]
    fn unstable_time_step_is_refused() {
        let mut p = Params::paper();
        let limit = Model::new(&p).unwrap().dt_limit;
        p.numerics.dt = Some(limit * 1.01);
        let msg = Model::new(&p).unwrap_err().to_string();
        assert!(msg.starts_with("invalid dt = ") && msg.contains("stability limit"), "{msg}");
    }
}
