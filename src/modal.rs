//! A second, independent solver: modal superposition of the same discrete beam.
//!
//! The free-free beam is written in its mass-normalised modes (rigid translation and rotation
//! about the centre of mass exactly, flexible modes from the nalgebra eigen-decomposition of
//! `M^-1/2 K M^-1/2`); the twist (Eq 7) and the ball (Eq 1) are rigid coordinates. Over one step
//! the contact force is taken linear in time, and every coordinate is then advanced *exactly*:
//! ```text
//! flexible   q'' + w^2 q = g F(t):  q(h) = c (q0 - g F0/w^2) + (s/w)(v0 - g F'/w^2) + g F1/w^2
//! rigid      q'' = g F(t):          q(h) = q0 + v0 h + g h^2 (F0/3 + F1/6)
//! ```
//! (`c, s = cos, sin(w h)`, `F' = (F1 - F0)/h`, `g` the mode's amplitude at the load point).
//! Only modes below a cut-off are kept; the flexibility of the others at the load point is added
//! as a static correction `Y_T -= R F`. `Y_T(h)` is then affine in the unknown end force,
//! `Y_T = A - B F1`, so the implicit step is one scalar solve with the contact law: linear in
//! compression (Eq 9), and of the Eq 10 form `u + (k1/k_s + B k1) u^p = A / Y0` in expansion.
//! The step is set by the contact, not by the stiffest beam mode. Phase switch and separation
//! are interpolated as in [`crate::solver`]; after separation the free vibration is evaluated in
//! closed form for the paper's peak bending PE and for re-contact.

use crate::error::{Error, Result};
use crate::model::contact::{solve_u, Contact, ContactState, Phase};
use crate::model::free::FreeVibration;
use crate::params::Params;
use crate::solver::{hermite_eval, hermite_max, hermite_root, ImpactResult, Model};

/// Keep flexible modes up to this multiple of the stiffest contact frequency.
pub const MODE_CUTOFF: f64 = 100.0;
/// Radians of the stiffest contact oscillation per step.
pub const PHASE_PER_STEP: f64 = 0.005;

/// A prepared modal model of one impact.
#[derive(Debug, Clone)]
pub struct ModalModel {
    base: Model,
    /// Retained flexible modes: w^2, w, load-point amplitude, cos(w h), sin(w h).
    lam: Vec<f64>,
    omega: Vec<f64>,
    g: Vec<f64>,
    cos: Vec<f64>,
    sin: Vec<f64>,
    /// d q(h) / d F1 and d q'(h) / d F1 of each retained mode.
    resp_q: Vec<f64>,
    resp_v: Vec<f64>,
    /// Load-point amplitudes of the rigid coordinates: translation, rotation, twist.
    g_rigid: [f64; 3],
    /// Static flexibility of the truncated modes at the load point, m/N.
    residual: f64,
    /// Compliance `B` of `Y_T(h) = A - B F1`, m/N.
    compliance: f64,
    /// Step, s.
    h: f64,
}

impl ModalModel {
    /// Validate, decompose the beam and choose the retained modes and the step.
    pub fn new(params: &Params) -> Result<Self> {
        let base = Model::new(params)?;
        let beam = &base.beam;
        let basis = std::sync::Arc::clone(&base.basis);
        let lp = base.load;
        let at_load = |phi: &[f64]| lp.weights[0] * phi[lp.nodes[0]] + lp.weights[1] * phi[lp.nodes[1]];
        let g_t = 1.0 / beam.total_mass.sqrt();
        let g_r = (lp.x_load - beam.x_cm) / beam.i_cm.sqrt();
        let g_tw = params.impact.r / params.racket.ix.sqrt();
        let g2_rigid = g_t * g_t + g_r * g_r + g_tw * g_tw;
        let k_c = base.contact.max_stiffness();
        let omega_contact = (k_c * (1.0 / params.ball.mass + g2_rigid)).sqrt();
        let h = PHASE_PER_STEP / omega_contact;
        let cutoff = MODE_CUTOFF * omega_contact;
        let (mut lam, mut omega, mut g, mut cos, mut sin) = (vec![], vec![], vec![], vec![], vec![]);
        let mut residual = 0.0;
        for (l, phi) in basis.lam.iter().zip(&basis.shapes) {
            let gk = at_load(phi);
            let w = l.sqrt();
            if w <= cutoff {
                lam.push(*l);
                omega.push(w);
                g.push(gk);
                cos.push((w * h).cos());
                sin.push((w * h).sin());
            } else {
                residual += gk * gk / l;
            }
        }
        let mut compliance = h * h / (6.0 * params.ball.mass) + g2_rigid * h * h / 6.0 + residual;
        for k in 0..lam.len() {
            compliance += g[k] * g[k] / lam[k] * (1.0 - sin[k] / (omega[k] * h));
        }
        // response of the end-of-step state to the end force F1 (the state is affine in F1)
        let resp_q = (0..lam.len()).map(|k| g[k] / lam[k] * (1.0 - sin[k] / (omega[k] * h))).collect();
        let resp_v = (0..lam.len()).map(|k| g[k] / (lam[k] * h) * (1.0 - cos[k])).collect();
        Ok(ModalModel {
            base,
            lam,
            omega,
            g,
            cos,
            sin,
            resp_q,
            resp_v,
            g_rigid: [g_t, g_r, g_tw],
            residual,
            compliance,
            h,
        })
    }

    /// Number of retained flexible modes.
    pub fn retained_modes(&self) -> usize {
        self.lam.len()
    }

    /// The step, s.
    pub fn step(&self) -> f64 {
        self.h
    }

    /// Run the impact.
    pub fn run(&self) -> Result<ImpactResult> {
        let p = &self.base.params;
        let c = &self.base.contact;
        let (mb, v1) = (p.ball.mass, p.impact.v1);
        let h = self.h;
        let e0 = 0.5 * mb * v1 * v1;
        let kmodes = self.lam.len();
        let g_t = self.g_rigid[0];
        // state: ball, rigid (translation, rotation, twist), flexible modes
        let mut s = State { yb: 0.0, vb: v1, rq: [0.0; 3], rv: [0.0; 3], q: vec![0.0; kmodes], v: vec![0.0; kmodes] };
        let mut next = s.clone();
        let mut phase = Phase::Compression;
        let (mut f0, mut t, mut yt0, mut ytd0) = (0.0, 0.0, 0.0, v1);
        let (mut u, mut y0, mut t_max) = ((0.0, 0.0), 0.0, 0.0);
        let (mut peak_force, mut energy_err, mut momentum_err): (f64, f64, f64) = (0.0, 0.0, 0.0);
        let alpha = c.k1 / c.ks;
        let k_series = c.compression_stiffness();
        let p0 = mb * v1;
        let limit = self.base.time_limit_s;
        loop {
            if t > limit {
                return Err(Error::ImpactDidNotEnd { limit_s: limit });
            }
            // A = Y_T(h) with F1 = 0
            let a = self.advance(&s, f0, 0.0, &mut next);
            let f1 = match phase {
                Phase::Compression => (k_series * a / (1.0 + k_series * self.compliance)).max(0.0),
                Phase::Expansion { y0 } => self.expansion_force(c, alpha, y0, a, &mut u)?,
            };
            self.add_end_force(&mut next, f1);
            let mut yt1 = a - self.compliance * f1;
            let mut ytd1 = self.yt_rate(&next, (f1 - f0) / h);
            let mut f_end = f1;
            if phase == Phase::Compression && ytd1 <= 0.0 {
                let (sm, ytm) = hermite_max(yt0, ytd0, yt1, ytd1, h);
                t_max = t + sm * h;
                y0 = c.ball_compression_at_max(ytm);
                phase = Phase::Expansion { y0 };
                u = (1.0, 1.0);
                f_end = self.expansion_force(c, alpha, y0, a, &mut u)?;
                self.add_end_force(&mut next, f_end - f1);
                yt1 = a - self.compliance * f_end;
                ytd1 = self.yt_rate(&next, (f_end - f0) / h);
            }
            std::mem::swap(&mut s, &mut next);
            t += h;
            peak_force = peak_force.max(f_end);
            let st = self.contact_state(c, phase, f_end, y0, u);
            let e = self.energy(&s, c, phase, &st);
            energy_err = energy_err.max((e - e0).abs() / e0);
            let pm = mb * s.vb + s.rv[0] / g_t;
            momentum_err = momentum_err.max((pm - p0).abs() / p0);
            if matches!(phase, Phase::Expansion { .. }) && f_end <= 0.0 {
                let sc = hermite_root(yt0, ytd0, yt1, ytd1, h);
                let tau = t - h + sc * h;
                // twist angle at the crossing (`next` now holds the state before the step)
                let theta = hermite_eval(next.rq[2], next.rv[2], s.rq[2], s.rv[2], h, sc) / p.racket.ix.sqrt();
                return self.finish(&s, t - tau, y0, tau, theta, t_max, peak_force, energy_err, momentum_err);
            }
            f0 = f_end;
            yt0 = yt1;
            ytd0 = ytd1;
        }
    }

    /// The end force of a step in expansion, from `Y_T(h) = A - B F1` and Eq 10.
    fn expansion_force(&self, c: &Contact, alpha: f64, y0: f64, a: f64, u: &mut (f64, f64)) -> Result<f64> {
        if a <= 0.0 {
            *u = (0.0, 0.0);
            return Ok(0.0);
        }
        *u = solve_u(alpha + self.compliance * c.k1, c.p, a / y0, *u)?;
        Ok(c.k1 * y0 * u.1)
    }

    /// Advance `s` over one step with the force going linearly from `f0` to `f1` into `out`;
    /// returns `Y_T` at the end of the step.
    fn advance(&self, s: &State, f0: f64, f1: f64, out: &mut State) -> f64 {
        let h = self.h;
        let mb = self.base.params.ball.mass;
        let fdot = (f1 - f0) / h;
        out.yb = s.yb + s.vb * h - h * h * (f0 / 3.0 + f1 / 6.0) / mb;
        out.vb = s.vb - h * (f0 + f1) / (2.0 * mb);
        let mut y_imp = 0.0;
        for i in 0..3 {
            let g = self.g_rigid[i];
            out.rq[i] = s.rq[i] + s.rv[i] * h + g * h * h * (f0 / 3.0 + f1 / 6.0);
            out.rv[i] = s.rv[i] + g * h * (f0 + f1) / 2.0;
            y_imp += g * out.rq[i];
        }
        for k in 0..self.lam.len() {
            let (l, w, g, c, sn) = (self.lam[k], self.omega[k], self.g[k], self.cos[k], self.sin[k]);
            let qh = s.q[k] - g * f0 / l;
            let vh = s.v[k] - g * fdot / l;
            out.q[k] = c * qh + sn / w * vh + g * f1 / l;
            out.v[k] = -w * sn * qh + c * vh + g * fdot / l;
            y_imp += g * out.q[k];
        }
        out.yb - y_imp - self.residual * f1
    }

    /// Add `df` to the end force of a step already advanced (`Y_T` changes by `-B df`).
    fn add_end_force(&self, out: &mut State, df: f64) {
        let (h, mb) = (self.h, self.base.params.ball.mass);
        out.yb -= h * h * df / (6.0 * mb);
        out.vb -= h * df / (2.0 * mb);
        for i in 0..3 {
            out.rq[i] += self.g_rigid[i] * h * h * df / 6.0;
            out.rv[i] += self.g_rigid[i] * h * df / 2.0;
        }
        for ((q, v), (rq, rv)) in out.q.iter_mut().zip(out.v.iter_mut()).zip(self.resp_q.iter().zip(&self.resp_v)) {
            *q += rq * df;
            *v += rv * df;
        }
    }

    /// `dY_T/dt` of a state whose force changes at rate `fdot`.
    fn yt_rate(&self, s: &State, fdot: f64) -> f64 {
        let mut v = s.vb;
        for i in 0..3 {
            v -= self.g_rigid[i] * s.rv[i];
        }
        for k in 0..self.lam.len() {
            v -= self.g[k] * s.v[k];
        }
        v - self.residual * fdot
    }

    fn contact_state(&self, c: &Contact, phase: Phase, f: f64, y0: f64, u: (f64, f64)) -> ContactState {
        match phase {
            Phase::Compression => {
                ContactState { force: f, ball_compression: f / c.k1, u: 0.0, u_pow: 0.0, string_deflection: f / c.ks }
            }
            Phase::Expansion { .. } => {
                ContactState { force: f, ball_compression: u.0 * y0, u: u.0, u_pow: u.1, string_deflection: f / c.ks }
            }
        }
    }

    /// Total energy (J): ball, ball store and loss, strings, modes, static correction.
    fn energy(&self, s: &State, c: &Contact, phase: Phase, st: &ContactState) -> f64 {
        let mb = self.base.params.ball.mass;
        let mut e = 0.5 * mb * s.vb * s.vb + c.ball_energy_with_loss(phase, st) + c.string_energy(st);
        e += 0.5 * self.residual * st.force * st.force;
        for i in 0..3 {
            e += 0.5 * s.rv[i] * s.rv[i];
        }
        for k in 0..self.lam.len() {
            e += 0.5 * (s.v[k] * s.v[k] + self.lam[k] * s.q[k] * s.q[k]);
        }
        e
    }

    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        s: &State,
        since_separation: f64,
        y0: f64,
        tau: f64,
        theta: f64,
        t_max: f64,
        peak_force: f64,
        energy_err: f64,
        momentum_err: f64,
    ) -> Result<ImpactResult> {
        let p = &self.base.params;
        let e0 = 0.5 * p.ball.mass * p.impact.v1 * p.impact.v1;
        let e_a = -s.vb / p.impact.v1;
        let vib: f64 = (0..self.lam.len()).map(|k| 0.5 * (s.v[k] * s.v[k] + self.lam[k] * s.q[k] * s.q[k])).sum();
        let (peak_pe, recontact) = self.after_impact(s, since_separation);
        let result = ImpactResult {
            e_a,
            tau_s: tau,
            theta_end_deg: theta.to_degrees(),
            f_ball: self.base.contact.ball_loss(y0) / e0,
            f_vib: vib / e0,
            f_vib_peak_pe: peak_pe / e0,
            f_hand: 0.0,
            f_spin: 0.5 * s.rv[2] * s.rv[2] / e0,
            f_rigid: 0.5 * (s.rv[0] * s.rv[0] + s.rv[1] * s.rv[1]) / e0,
            f_ke_ball: e_a * e_a,
            peak_force_n: peak_force,
            energy_error: energy_err,
            momentum_error: momentum_err,
            x_load_m: self.base.load.x_load,
            t_max_compression_s: t_max,
            y0_m: y0,
            recontact,
            dt_s: self.h,
        };
        result.check_finite()?;
        Ok(result)
    }

    /// Peak bending PE over two fundamental periods of free vibration from separation, and
    /// whether the frame meets the ball again within that window, in closed form
    /// ([`FreeVibration`]). `s` is the state `lag` seconds after separation.
    fn after_impact(&self, s: &State, lag: f64) -> (f64, bool) {
        let free = FreeVibration::new(&self.omega, &s.q, &s.v, &self.g);
        let window = 2.0 / self.base.f1_hz;
        let peak = free.peak_pe(-lag, window - lag);
        let gap0 = s.yb - (0..3).map(|i| self.g_rigid[i] * s.rq[i]).sum::<f64>();
        let rate = s.vb - (0..3).map(|i| self.g_rigid[i] * s.rv[i]).sum::<f64>();
        (peak, free.meets_ball(gap0, rate, window - lag))
    }
}

#[derive(Debug, Clone)]
struct State {
    yb: f64,
    vb: f64,
    rq: [f64; 3],
    rv: [f64; 3],
    q: Vec<f64>,
    v: Vec<f64>,
}
