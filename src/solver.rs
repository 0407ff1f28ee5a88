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
//! After separation the racket is stepped on, force-free, for two periods of its fundamental
//! mode, to measure the paper's vibration energy (peak bending PE) and to extend the time series.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::model::beam::{Beam, LoadPoint};
use crate::model::contact::{Contact, ContactState, Phase};
use crate::params::Params;

/// Fraction of the stability limit used by the default time step.
pub const DEFAULT_DT_FRACTION: f64 = 0.5;
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
    /// The discrete beam.
    pub beam: Beam,
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
}

impl Model {
    /// Validate the parameters, discretise the racket and choose (or check) the time step.
    pub fn new(params: &Params) -> Result<Self> {
        params.validate()?;
        let beam = Beam::new(&params.racket, params.numerics.segments);
        let contact = Contact::new(&params.ball, &params.strings);
        let load = beam.load_point(params.impact.x, params.numerics.load);
        let ev = beam.eigenvalues();
        let f1_hz = ev[2].max(0.0).sqrt() / (2.0 * std::f64::consts::PI);
        // Weyl: the contact spring adds at most k_c |g|^2 to the largest eigenvalue, where g is
        // the mass-normalised coupling vector of the ball, the load nodes and the twist.
        let lp = &load;
        let g2 = 1.0 / params.ball.mass
            + lp.weights[0].powi(2) / beam.mass[lp.nodes[0]]
            + lp.weights[1].powi(2) / beam.mass[lp.nodes[1]]
            + params.impact.r.powi(2) / params.racket.ix;
        let omega_max = (ev[ev.len() - 1] + contact.max_stiffness() * g2).sqrt();
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
        if !(dt.is_finite() && dt > 0.0 && f1_hz.is_finite() && f1_hz > 0.0 && work <= MAX_NODE_STEPS) {
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
        Ok(Model { params: *params, beam, contact, load, f1_hz, dt_limit, dt, time_limit_s: t_limit })
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
        let beam = &self.beam;
        let n = beam.nodes();
        let dt = self.dt;
        let [j0, j1] = self.load.nodes;
        let [w0, w1] = self.load.weights;
        let e0 = 0.5 * mb * v1 * v1;
        let p0 = mb * v1;
        let t_limit = self.time_limit_s;

        let mut st = Stepper {
            yb: 0.0,
            vb: v1,
            ab: 0.0,
            y: vec![0.0; n],
            v: vec![0.0; n],
            a: vec![0.0; n],
            th: 0.0,
            om: 0.0,
            al: 0.0,
            elastic: vec![0.0; n],
            curv: vec![0.0; n],
        };
        let mut phase = Phase::Compression;
        let mut cs = ContactState { force: 0.0, ball_compression: 0.0, u: 0.0 };
        let mut t = 0.0;
        let mut yt_prev = 0.0;
        let mut ytd_prev = v1;
        let mut energy_err: f64 = 0.0;
        let mut momentum_err: f64 = 0.0;
        let mut peak_force: f64 = 0.0;
        let mut t_max = 0.0;
        let mut y0 = 0.0;
        let stride = series.map(|o| ((o.sample_dt / dt).round() as usize).max(1)).unwrap_or(usize::MAX);
        let mut rows = series.map(|_| Vec::new());
        let mut step: usize = 0;

        let ledger = |st: &Stepper, phase: Phase, cs: &ContactState| -> Ledger {
            Ledger {
                ke_ball: 0.5 * mb * st.vb * st.vb,
                pe_ball: self.contact.ball_energy_with_loss(phase, cs),
                pe_string: self.contact.string_energy(cs.force),
                ke_racket: beam.kinetic_energy(&st.v),
                pe_racket: beam.bending_energy(&st.y),
                ke_spin: 0.5 * ix * st.om * st.om,
            }
        };
        let record = |rows: &mut Option<Vec<SeriesRow>>, t: f64, st: &Stepper, cs: &ContactState, l: &Ledger| {
            if let Some(rows) = rows.as_mut() {
                let yt = st.yb - (w0 * st.y[j0] + w1 * st.y[j1] + r * st.th);
                rows.push(l.row(t, e0, cs.force, st.yb, yt, st.th));
            }
        };
        record(&mut rows, 0.0, &st, &cs, &ledger(&st, phase, &cs));

        // contact phase
        let (tau, theta_end) = loop {
            if t > t_limit {
                return Err(Error::ImpactDidNotEnd { limit_s: t_limit });
            }
            let (th_prev, om_prev) = (st.th, st.om);
            st.drift(dt);
            beam.elastic_forces(&st.y, &mut st.curv, &mut st.elastic);
            let yt = st.yb - (w0 * st.y[j0] + w1 * st.y[j1] + r * st.th);
            cs = self.contact.state(yt, phase, cs.u)?;
            st.kick(dt, cs.force, self);
            let mut ytd = st.vb - (w0 * st.v[j0] + w1 * st.v[j1] + r * st.om);
            if phase == Phase::Compression && ytd <= 0.0 {
                // The maximum of Y_T lies in this step: switch to the expansion law there.
                let (s_max, yt_max) = hermite_max(yt_prev, ytd_prev, yt, ytd, dt);
                t_max = t + s_max * dt;
                y0 = self.contact.ball_compression_at_max(yt_max);
                phase = Phase::Expansion { y0 };
                let f_old = cs.force;
                cs = self.contact.state(yt, phase, 1.0)?;
                st.correct_force(dt, cs.force - f_old, self);
                ytd = st.vb - (w0 * st.v[j0] + w1 * st.v[j1] + r * st.om);
            }
            t += dt;
            step += 1;
            peak_force = peak_force.max(cs.force);
            let l = ledger(&st, phase, &cs);
            energy_err = energy_err.max((l.total() - e0).abs() / e0);
            momentum_err = momentum_err.max((mb * st.vb + beam.momentum(&st.v) - p0).abs() / p0);
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
        let mut peak_pe = beam.bending_energy(&st.y);
        let mut recontact = false;
        // the paper's window: two fundamental periods from the separation time itself
        let t_post = (tau + 2.0 / self.f1_hz).max(series.map(|o| o.t_end).unwrap_or(0.0));
        let t_window_end = tau + 2.0 / self.f1_hz;
        while t < t_post {
            st.drift(dt);
            beam.elastic_forces(&st.y, &mut st.curv, &mut st.elastic);
            st.kick(dt, 0.0, self);
            t += dt;
            step += 1;
            let yt = st.yb - (w0 * st.y[j0] + w1 * st.y[j1] + r * st.th);
            recontact |= yt > 0.0;
            let l = ledger(&st, phase, &cs);
            if t <= t_window_end {
                peak_pe = peak_pe.max(l.pe_racket);
            }
            energy_err = energy_err.max((l.total() - e0).abs() / e0);
            momentum_err = momentum_err.max((mb * st.vb + beam.momentum(&st.v) - p0).abs() / p0);
            if step % stride == 0 {
                record(&mut rows, t, &st, &cs, &l);
            }
        }
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
        Ok((result, rows))
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

/// Validate, prepare and run one impact with the solver the parameters name.
pub fn simulate(params: &Params) -> Result<ImpactResult> {
    match params.numerics.solver {
        crate::params::SolverKind::Fd => Model::new(params)?.run(),
        crate::params::SolverKind::Modal => crate::modal::ModalModel::new(params)?.run(),
    }
}

/// The simulated-time limit of the contact phase, s.
fn time_limit(p: &Params, contact: &Contact) -> f64 {
    IMPACT_TIME_LIMIT_HALF_PERIODS * std::f64::consts::PI * (p.ball.mass / contact.compression_stiffness()).sqrt()
}

/// The state of the ball, the beam and the twist, with scratch buffers.
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
    elastic: Vec<f64>,
    curv: Vec<f64>,
}

impl Stepper {
    /// Positions to the end of the step, `y += v dt + a dt^2 / 2`.
    fn drift(&mut self, dt: f64) {
        let h = 0.5 * dt * dt;
        self.yb += self.vb * dt + self.ab * h;
        for i in 0..self.y.len() {
            self.y[i] += self.v[i] * dt + self.a[i] * h;
        }
        self.th += self.om * dt + self.al * h;
    }

    /// New accelerations from the elastic forces and the contact force `f`, and the velocity
    /// half-kicks `v += (a_old + a_new) dt / 2`.
    fn kick(&mut self, dt: f64, f: f64, model: &Model) {
        let half = 0.5 * dt;
        let beam = &model.beam;
        let ab = -f / model.params.ball.mass;
        self.vb += (self.ab + ab) * half;
        self.ab = ab;
        let al = f * model.params.impact.r / model.params.racket.ix;
        self.om += (self.al + al) * half;
        self.al = al;
        let [j0, j1] = model.load.nodes;
        let [w0, w1] = model.load.weights;
        for i in 0..self.y.len() {
            let mut force = self.elastic[i];
            if i == j0 {
                force += w0 * f;
            }
            if i == j1 {
                force += w1 * f;
            }
            let a = force / beam.mass[i];
            self.v[i] += (self.a[i] + a) * half;
            self.a[i] = a;
        }
    }

    /// Replace the contact force of the last kick by one `df` larger (used at the phase switch).
    fn correct_force(&mut self, dt: f64, df: f64, model: &Model) {
        let half = 0.5 * dt;
        let dab = -df / model.params.ball.mass;
        self.ab += dab;
        self.vb += dab * half;
        let dal = df * model.params.impact.r / model.params.racket.ix;
        self.al += dal;
        self.om += dal * half;
        let [j0, j1] = model.load.nodes;
        let [w0, w1] = model.load.weights;
        for (j, w) in [(j0, w0), (j1, w1)] {
            let da = w * df / model.beam.mass[j];
            self.a[j] += da;
            self.v[j] += da * half;
        }
    }
}

/// The energy ledger at one instant, J.
struct Ledger {
    ke_ball: f64,
    pe_ball: f64,
    pe_string: f64,
    ke_racket: f64,
    pe_racket: f64,
    ke_spin: f64,
}

impl Ledger {
    fn total(&self) -> f64 {
        self.ke_ball + self.pe_ball + self.pe_string + self.ke_racket + self.pe_racket + self.ke_spin
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
