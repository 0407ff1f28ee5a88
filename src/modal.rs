//! A second, independent solver: modal superposition of the same discrete beam.
//!
//! The free-free beam is written in its mass-normalised modes (rigid translation and rotation
//! about the centre of mass exactly, flexible modes from the nalgebra eigen-decomposition of
//! `M^-1/2 K M^-1/2`); the twist (Eq 7) and the ball (Eq 1) are rigid coordinates. Over the
//! first step the contact force is taken linear in time, and every coordinate is then advanced
//! *exactly*:
//! ```text
//! flexible   q'' + w^2 q = g F(t):  q(h) = c (q0 - g F0/w^2) + (s/w)(v0 - g F'/w^2) + g F1/w^2
//! rigid      q'' = g F(t):          q(h) = q0 + v0 h + g h^2 (F0/3 + F1/6)
//! ```
//! (`c, s = cos, sin(w h)`, `F' = (F1 - F0)/h`, `g` the mode's amplitude at the load point).
//! After the first step the force is taken as the parabola through the previous, current and end
//! forces, `F(t) = F0 + b t + c t^2` with `b = (F1 - Fm)/(2h)`, `c = (F1 - 2 F0 + Fm)/(2h^2)`,
//! and each mode is advanced exactly under it (particular solution `(g/w^2)(F - 2c/w^2)` plus free
//! oscillation); this third-order force history lets the step be twice as long as with a
//! linear one at the same accuracy.
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
pub const PHASE_PER_STEP: f64 = 0.01;

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
    /// The first step's force history (a line from 0) and every later one's (a parabola
    /// through the previous, the current and the end force).
    first: Scheme,
    later: Scheme,
    /// Load-point amplitudes of the rigid coordinates: translation, rotation, twist.
    g_rigid: [f64; 3],
    /// Static flexibility of the truncated modes at the load point, m/N.
    residual: f64,
    /// Step, s.
    h: f64,
}

/// How the force varies over a step: `F(t) = F0 + b t + c t^2` on `[0, h]` with
/// `b = b0 + b1 F1` and `c = c0 + c1 F1` (`b0, c0` from the known forces), so that the end state
/// is affine in the unknown end force `F1`.
#[derive(Debug, Clone)]
struct Scheme {
    /// `b1` (1/s) and `c1` (1/s^2).
    b1: f64,
    c1: f64,
    /// End-state response to `F1`: flexible modes (position, velocity), and per unit amplitude
    /// `g` for the rigid coordinates (and, with `g = -1/m_b`, the ball).
    resp_q: Vec<f64>,
    resp_v: Vec<f64>,
    rigid_q: f64,
    rigid_v: f64,
    /// Compliance `B` of `Y_T(h) = A - B F1`, m/N.
    compliance: f64,
}

impl Scheme {
    /// The response of a step to `F1` through `b1, c1`, from the exact solution of
    /// `q'' + w^2 q = g (F0 + b t + c t^2)`: the particular solution is
    /// `(g/w^2) (F(t) - 2c/w^2)` and the rest is free oscillation.
    fn new(b1: f64, c1: f64, h: f64, m: &ModalModel, mb: f64) -> Scheme {
        let mut resp_q = Vec::with_capacity(m.lam.len());
        let mut resp_v = Vec::with_capacity(m.lam.len());
        for k in 0..m.lam.len() {
            let (l, w, g, c, s) = (m.lam[k], m.omega[k], m.g[k], m.cos[k], m.sin[k]);
            resp_q.push(g / l * (b1 * h + c1 * h * h - 2.0 * c1 / l * (1.0 - c) - s / w * b1));
            resp_v.push(g / l * (b1 * (1.0 - c) + 2.0 * c1 * (h - s / w)));
        }
        let rigid_q = b1 * h.powi(3) / 6.0 + c1 * h.powi(4) / 12.0;
        let rigid_v = b1 * h * h / 2.0 + c1 * h.powi(3) / 3.0;
        let g2_rigid: f64 = m.g_rigid.iter().map(|g| g * g).sum();
        let flexible: f64 = m.g.iter().zip(&resp_q).map(|(g, r)| g * r).sum();
        let compliance = rigid_q / mb + g2_rigid * rigid_q + m.residual + flexible;
        Scheme { b1, c1, resp_q, resp_v, rigid_q, rigid_v, compliance }
    }
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
        let empty =
            Scheme { b1: 0.0, c1: 0.0, resp_q: vec![], resp_v: vec![], rigid_q: 0.0, rigid_v: 0.0, compliance: 0.0 };
        let mut m = ModalModel {
            base,
            lam,
            omega,
            g,
            cos,
            sin,
            first: empty.clone(),
            later: empty,
            g_rigid: [g_t, g_r, g_tw],
            residual,
            h,
        };
        let mb = params.ball.mass;
        // first step: F rises linearly from 0; later: b = (F1 - Fm)/(2h), c = (F1 - 2 F0 + Fm)/(2 h^2)
        m.first = Scheme::new(1.0 / h, 0.0, h, &m, mb);
        m.later = Scheme::new(0.5 / h, 0.5 / (h * h), h, &m, mb);
        Ok(m)
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
        let (mut f0, mut fm, mut t, mut yt0, mut ytd0) = (0.0, 0.0, 0.0, 0.0, v1);
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
            // the force history of this step, less its end-force part: F0 + b0 t + c0 t^2
            let (scheme, b0, c0) = if t == 0.0 {
                (&self.first, -f0 / h, 0.0)
            } else {
                (&self.later, -fm / (2.0 * h), (fm - 2.0 * f0) / (2.0 * h * h))
            };
            let rate_at_end = |f1: f64| b0 + scheme.b1 * f1 + 2.0 * h * (c0 + scheme.c1 * f1);
            // A = Y_T(h) with F1 = 0
            let a = self.advance(&s, f0, b0, c0, &mut next);
            let bc = scheme.compliance;
            let f1 = match phase {
                Phase::Compression => (k_series * a / (1.0 + k_series * bc)).max(0.0),
                Phase::Expansion { y0 } => self.expansion_force(c, alpha, y0, a, bc, &mut u)?,
            };
            self.add_end_force(scheme, &mut next, f1);
            let mut yt1 = a - bc * f1;
            let mut ytd1 = self.yt_rate(&next, rate_at_end(f1));
            let mut f_end = f1;
            if phase == Phase::Compression && ytd1 <= 0.0 {
                let (sm, ytm) = hermite_max(yt0, ytd0, yt1, ytd1, h);
                t_max = t + sm * h;
                y0 = c.ball_compression_at_max(ytm);
                phase = Phase::Expansion { y0 };
                u = (1.0, 1.0);
                f_end = self.expansion_force(c, alpha, y0, a, bc, &mut u)?;
                self.add_end_force(scheme, &mut next, f_end - f1);
                yt1 = a - bc * f_end;
                ytd1 = self.yt_rate(&next, rate_at_end(f_end));
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
            fm = f0;
            f0 = f_end;
            yt0 = yt1;
            ytd0 = ytd1;
        }
    }

    /// The end force of a step in expansion, from `Y_T(h) = A - B F1` and Eq 10.
    fn expansion_force(&self, c: &Contact, alpha: f64, y0: f64, a: f64, b: f64, u: &mut (f64, f64)) -> Result<f64> {
        if a <= 0.0 {
            *u = (0.0, 0.0);
            return Ok(0.0);
        }
        *u = solve_u(alpha + b * c.k1, c.p, a / y0, *u)?;
        Ok(c.k1 * y0 * u.1)
    }

    /// Advance `s` over one step with the force `F0 + b t + c t^2` into `out` (exactly, mode by
    /// mode); returns `Y_T` at the end of the step.
    fn advance(&self, s: &State, f0: f64, b: f64, c: f64, out: &mut State) -> f64 {
        let h = self.h;
        let mb = self.base.params.ball.mass;
        let (h2, h3, h4) = (h * h, h * h * h, h * h * h * h);
        let dq = f0 * h2 / 2.0 + b * h3 / 6.0 + c * h4 / 12.0;
        let dv = f0 * h + b * h2 / 2.0 + c * h3 / 3.0;
        out.yb = s.yb + s.vb * h - dq / mb;
        out.vb = s.vb - dv / mb;
        let mut y_imp = 0.0;
        for i in 0..3 {
            let g = self.g_rigid[i];
            out.rq[i] = s.rq[i] + s.rv[i] * h + g * dq;
            out.rv[i] = s.rv[i] + g * dv;
            y_imp += g * out.rq[i];
        }
        let fh = f0 + b * h + c * h2;
        for k in 0..self.lam.len() {
            let (l, w, g, cs, sn) = (self.lam[k], self.omega[k], self.g[k], self.cos[k], self.sin[k]);
            let gl = g / l;
            let (qp0, vp0) = (gl * (f0 - 2.0 * c / l), gl * b);
            let (qph, vph) = (gl * (fh - 2.0 * c / l), gl * (b + 2.0 * c * h));
            let (qh, vh) = (s.q[k] - qp0, s.v[k] - vp0);
            out.q[k] = qph + cs * qh + sn / w * vh;
            out.v[k] = vph - w * sn * qh + cs * vh;
            y_imp += g * out.q[k];
        }
        out.yb - y_imp - self.residual * fh
    }

    /// Add `df` to the end force of a step already advanced (`Y_T` changes by `-B df`).
    fn add_end_force(&self, scheme: &Scheme, out: &mut State, df: f64) {
        let mb = self.base.params.ball.mass;
        out.yb -= scheme.rigid_q * df / mb;
        out.vb -= scheme.rigid_v * df / mb;
        for i in 0..3 {
            out.rq[i] += self.g_rigid[i] * scheme.rigid_q * df;
            out.rv[i] += self.g_rigid[i] * scheme.rigid_v * df;
        }
        for ((q, v), (rq, rv)) in out.q.iter_mut().zip(out.v.iter_mut()).zip(scheme.resp_q.iter().zip(&scheme.resp_v)) {
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
