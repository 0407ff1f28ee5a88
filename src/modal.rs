//! A second, independent solver: modal superposition of the same discrete beam.
//!
//! The free-free beam is written in its mass-normalised modes (rigid translation and rotation
//! about the centre of mass exactly, flexible modes from the nalgebra eigen-decomposition of
//! `M^-1/2 K M^-1/2`); the twist (Eq 7) and the ball (Eq 1, as `sqrt(m_b) y_b`) are rigid
//! coordinates. Every coordinate obeys `q'' + w^2 q = g F(t)` (`w = 0` for the ball and the rigid
//! ones; `g` its amplitude at the load point, `-1/sqrt(m_b)` for the ball), and the total
//! compression is `Y_T = -sum g q - R F`.
//!
//! Over each step of length `h` the contact force is the cubic Hermite polynomial through its
//! values and rates at both ends, `F0, D0` (known) and `F1, D1` (unknown), and every coordinate
//! is advanced *exactly* under it:
//! ```text
//! q(h) = cos(w h) q0 + sin(w h)/w v0 + g (a_F0 F0 + a_D0 D0 + a_F1 F1 + a_D1 D1)
//! ```
//! (and the same for `v(h)`), with the eight response coefficients of each mode computed once per
//! step length (`responses`: a power series for `w h <= 1`, the polynomial particular solution
//! otherwise). `Y_T(h)` and `Y_T'(h)` are then affine in `(F1, D1)`, so the implicit step is the
//! contact law at the end of the step, `F1 = F(Y_T)` and `D1 = F'(Y_T) Y_T'`: a constant 2 x 2
//! linear solve in compression (Eq 9) and, in expansion (Eq 10), Newton on the expansion law with
//! the rate updated from each iterate (its coupling is of order `(w h)^4`).
//! The force is continuous with a continuous rate through maximum compression (both sides have
//! `F' = 0` there), so one polynomial per step keeps the scheme fourth order; the step is set by
//! the stiffest contact oscillation, not by the stiffest beam mode. Two places need shorter
//! steps: the step holding maximum compression (the second rate of the force jumps there) and,
//! on soft strings, the end of the contact, where the expansion law bends sharply. Every step
//! that ends in expansion is therefore checked: where the cubic misses the contact law at the
//! step's midpoint (and at its quarter points where the force falls below a quarter of its start
//! or the ball leaves) by more than the tolerance (as an impulse error), it is taken again as two
//! half steps, down to 1/64 of the base step. A step at that finest level is accepted as it is,
//! so the tolerance is a target, not a bound; the agreement tests measure what it achieves.
//!
//! Only modes below a cut-off are kept; the flexibility of the others at the load point is added
//! as a static correction `Y_T -= R F`. Phase switch and separation are interpolated as in
//! [`crate::solver`]; after separation the free vibration is evaluated in closed form for the
//! paper's peak bending PE and for re-contact.
//!
//! Design note: a quintic force history (carrying `F''` too, 6th order) was tried. Its steps can
//! be twice as long for the same accuracy, but each costs about 1.5 times as much, its set-up
//! twice as much, and the two places above still need split steps, so it was no faster.

use crate::error::{Error, Result};
use crate::model::contact::{ContactState, Phase};
use crate::model::free::FreeVibration;
use crate::params::Params;
use crate::solver::{hermite_eval, hermite_max, hermite_root, ImpactResult, Model};

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
    Resolution { mode_cutoff: 50.0, phase_per_step: 0.1, impulse_tolerance: 1e-7 };

/// Levels of step refinement below the base step, and the ratio between levels.
const LEVELS: usize = 7;
const REFINE: usize = 2;

/// Number of rigid coordinates ahead of the flexible modes: ball, translation, rotation, twist.
const RIGID: usize = 4;

/// The exact step of every coordinate under the cubic force history, one column per
/// coefficient in a single buffer (so the loops over coordinates vectorise and a table is one
/// allocation): free propagation, `cos(w h)`, `sin(w h)/w`, `-w sin(w h)`, then the position and
/// the velocity responses to `F0, D0, F1, D1` (already multiplied by the coordinate's `g`).
#[derive(Debug, Clone)]
struct Steps {
    n: usize,
    data: Vec<f64>,
}

/// Columns of [`Steps`].
const COS: usize = 0;
const SIN_W: usize = 1;
const W_SIN: usize = 2;
const Q_RESPONSE: usize = 3;
const V_RESPONSE: usize = 7;
const COLUMNS: usize = 11;

impl Steps {
    fn col(&self, k: usize) -> &[f64] {
        &self.data[k * self.n..(k + 1) * self.n]
    }
}

/// The step tables of one step length.
#[derive(Debug, Clone)]
struct Grid {
    /// Step, s.
    h: f64,
    steps: Steps,
    /// `Y_T(h) = Y_hat - bf F1 - bd D1` and `Y_T'(h) = Yd_hat - cf F1 - cd D1` (static correction
    /// included): m/N, m s/N, 1/(N s), m/N.
    bf: f64,
    bd: f64,
    cf: f64,
    cd: f64,
    /// Compression: `(F1, D1) = M (Y_hat, Yd_hat)`.
    compression: [[f64; 2]; 2],
}

impl Grid {
    fn new(m: &ModalModel, h: f64) -> Grid {
        let n = m.lam.len();
        let mut data = vec![0.0; COLUMNS * n];
        for (j, ((&l, &w), &gj)) in m.lam.iter().zip(&m.omega).zip(&m.g).enumerate() {
            let (s, c) = (w * h).sin_cos();
            let (rq, rv) = responses(l, h, (s, c));
            let (hq, hv) = (hermite(rq, h), hermite(rv, h));
            data[COS * n + j] = c;
            data[SIN_W * n + j] = if w > 0.0 { s / w } else { h };
            data[W_SIN * n + j] = -w * s;
            for i in 0..4 {
                data[(Q_RESPONSE + i) * n + j] = gj * hq[i];
                data[(V_RESPONSE + i) * n + j] = gj * hv[i];
            }
        }
        let st = Steps { n, data };
        let bf = dot(&m.g, st.col(Q_RESPONSE + 2)) + m.residual;
        let bd = dot(&m.g, st.col(Q_RESPONSE + 3));
        let cf = dot(&m.g, st.col(V_RESPONSE + 2));
        let cd = dot(&m.g, st.col(V_RESPONSE + 3)) + m.residual;
        // F1 = ks (Y_hat - bf F1 - bd D1), D1 = ks (Yd_hat - cf F1 - cd D1)
        let ks = m.base.contact.compression_stiffness();
        let (a11, a12, a21, a22) = (1.0 + ks * bf, ks * bd, ks * cf, 1.0 + ks * cd);
        let det = a11 * a22 - a12 * a21;
        let compression = [[ks * a22 / det, -ks * a12 / det], [-ks * a21 / det, ks * a11 / det]];
        Grid { h, steps: st, bf, bd, cf, cd, compression }
    }
}

/// `sum_i f(i)` over `0..n` with four partial sums (so that it vectorises).
#[inline(always)]
fn sum4(n: usize, f: impl Fn(usize) -> f64) -> f64 {
    let mut acc = [0.0; 4];
    let whole = n - n % 4;
    for j in (0..whole).step_by(4) {
        for (i, a) in acc.iter_mut().enumerate() {
            *a += f(j + i);
        }
    }
    let tail: f64 = (whole..n).map(&f).sum();
    (acc[0] + acc[2]) + (acc[1] + acc[3]) + tail
}

/// `sum a_i b_i` over the shorter slice.
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    sum4(n, |i| a[i] * b[i])
}

/// A prepared modal model of one impact.
#[derive(Debug, Clone)]
pub struct ModalModel {
    base: Model,
    /// Per coordinate (rigid first, then the retained flexible modes): `w^2`, `w`, `g`.
    lam: Vec<f64>,
    omega: Vec<f64>,
    g: Vec<f64>,
    /// Static flexibility of the truncated modes at the load point, m/N.
    residual: f64,
    /// Largest impulse error allowed per step, N s.
    impulse_tolerance: f64,
    /// Step tables: the base step, then each level `REFINE` times shorter (built when needed).
    grids: [std::sync::OnceLock<Grid>; LEVELS],
}

/// `q(h)` and `q'(h)` of `q'' + lam q = t^m`, `q(0) = q'(0) = 0`, for `m = 0..=3`.
fn responses(lam: f64, h: f64, (s, c): (f64, f64)) -> ([f64; 4], [f64; 4]) {
    let mut q = [0.0; 4];
    let mut v = [0.0; 4];
    let x = lam * h * h;
    if x <= 1.0 {
        // q = m! sum_n (-lam)^n h^(2n+m+2) / (2n+m+2)!, v = m! sum_n (-lam)^n h^(2n+m+1) / (2n+m+1)!
        // (first terms h^(m+2)/((m+1)(m+2)) and h^(m+1)/(m+1))
        let mut hm = h;
        for m in 0..4 {
            let mf = m as f64;
            let mut tv = hm / (mf + 1.0);
            let mut tq = tv * h / (mf + 2.0);
            let (mut sq, mut sv) = (0.0, 0.0);
            for n in 0..SERIES_TERMS {
                sq += tq;
                sv += tv;
                if tq.abs() <= 1e-18 * sq.abs() && tv.abs() <= 1e-18 * sv.abs() {
                    break;
                }
                let k = 2 * n + m;
                tq *= -x * RECIPROCAL_PAIR[k + 3];
                tv *= -x * RECIPROCAL_PAIR[k + 2];
            }
            q[m] = sq;
            v[m] = sv;
            hm *= h;
        }
    } else {
        // particular solutions qp = t^m/lam - m(m-1) t^(m-2)/lam^2, plus free oscillation
        let w = lam.sqrt();
        let (il, iw) = (1.0 / lam, 1.0 / w);
        let il2 = il * il;
        let qp = |m: usize, t: f64| match m {
            0 => il,
            1 => t * il,
            2 => t * t * il - 2.0 * il2,
            _ => t * t * t * il - 6.0 * t * il2,
        };
        let vp = |m: usize, t: f64| match m {
            0 => 0.0,
            1 => il,
            2 => 2.0 * t * il,
            _ => 3.0 * t * t * il - 6.0 * il2,
        };
        for m in 0..4 {
            let (q0, v0) = (qp(m, 0.0), vp(m, 0.0));
            q[m] = qp(m, h) - c * q0 - s * iw * v0;
            v[m] = vp(m, h) + w * s * q0 - c * v0;
        }
    }
    (q, v)
}

/// Most terms of the series in [`responses`] (for `lam h^2 <= 1` the 20th is below 1e-40).
const SERIES_TERMS: usize = 20;

/// `1/(j (j + 1))`, the ratio of successive terms of the series in [`responses`].
const RECIPROCAL_PAIR: [f64; 2 * SERIES_TERMS + 8] = {
    let mut r = [0.0; 2 * SERIES_TERMS + 8];
    let mut j = 1;
    while j < r.len() {
        r[j] = 1.0 / (j as f64 * (j + 1) as f64);
        j += 1;
    }
    r
};

/// Responses to the four cubic Hermite basis functions on `[0, h]` (`F0, D0, F1, D1`).
fn hermite(r: [f64; 4], h: f64) -> [f64; 4] {
    let (h2, h3) = (h * h, h * h * h);
    [
        r[0] - 3.0 * r[2] / h2 + 2.0 * r[3] / h3,
        r[1] - 2.0 * r[2] / h + r[3] / h2,
        3.0 * r[2] / h2 - 2.0 * r[3] / h3,
        -r[2] / h + r[3] / h2,
    ]
}

impl ModalModel {
    /// Validate, decompose the beam and choose the retained modes and the step.
    pub fn new(params: &Params) -> Result<Self> {
        Self::with_resolution(params, DEFAULT_RESOLUTION)
    }

    /// As [`ModalModel::new`] with a chosen resolution (for convergence studies).
    pub fn with_resolution(params: &Params, res: Resolution) -> Result<Self> {
        let base = Model::for_modal(params)?;
        let beam = base.beam();
        let basis = std::sync::Arc::clone(&base.basis);
        let lp = base.load;
        let at_load = |phi: &[f64]| lp.weights[0] * phi[lp.nodes[0]] + lp.weights[1] * phi[lp.nodes[1]];
        let mb = params.ball.mass;
        let g_t = 1.0 / beam.total_mass.sqrt();
        let g_r = (lp.x_load - beam.x_cm) / beam.i_cm.sqrt();
        let g_tw = params.impact.r / params.racket.ix.sqrt();
        let k_c = base.contact.max_stiffness();
        let omega_contact = (k_c * (1.0 / mb + g_t * g_t + g_r * g_r + g_tw * g_tw)).sqrt();
        let h = res.phase_per_step / omega_contact;
        let cutoff = res.mode_cutoff * omega_contact;
        // (modes are ascending: the retained ones are a prefix)
        let kept = basis.lam.iter().take_while(|l| l.sqrt() <= cutoff).count();
        let mut lam = Vec::with_capacity(RIGID + kept);
        let mut g = Vec::with_capacity(RIGID + kept);
        lam.extend([0.0; RIGID]);
        g.extend([-1.0 / mb.sqrt(), g_t, g_r, g_tw]);
        let mut residual = 0.0;
        for (l, phi) in basis.lam.iter().zip(&basis.shapes) {
            let gk = at_load(phi);
            if l.sqrt() <= cutoff {
                lam.push(*l);
                g.push(gk);
            } else {
                residual += gk * gk / l;
            }
        }
        let omega: Vec<f64> = lam.iter().map(|l| l.sqrt()).collect();
        let impulse_tolerance = res.impulse_tolerance * mb * params.impact.v1;
        let m = ModalModel { base, lam, omega, g, residual, impulse_tolerance, grids: Default::default() };
        let grid = Grid::new(&m, h);
        let _ = m.grids[0].set(grid);
        Ok(m)
    }

    /// The step tables of a refinement level.
    fn grid(&self, level: usize) -> &Grid {
        self.grids[level].get_or_init(|| {
            let h = self.grids[0].get().expect("base grid").h / (REFINE as f64).powi(level as i32);
            Grid::new(self, h)
        })
    }

    /// Number of retained flexible modes.
    pub fn retained_modes(&self) -> usize {
        self.lam.len() - RIGID
    }

    /// The base step, s.
    pub fn step(&self) -> f64 {
        self.grid(0).h
    }

    /// Run the impact.
    pub fn run(&self) -> Result<ImpactResult> {
        let p = &self.base.params;
        let (mb, v1) = (p.ball.mass, p.impact.v1);
        let n = self.lam.len();
        let ks = self.base.contact.compression_stiffness();
        let mut s = State { q: vec![0.0; n], v: vec![0.0; n] };
        s.v[0] = mb.sqrt() * v1;
        // F = ks Y_T with Y_T' = v1 - R F' at first touch
        let d0 = ks * v1 / (1.0 + ks * self.residual);
        let mut run = Run {
            m: self,
            next: s.clone(),
            s,
            at: End { f: 0.0, d: d0, yt: 0.0, ytd: d0 / ks, phase: Phase::Compression, u: (0.0, 0.0), t_max: 0.0 },
            t: 0.0,
            peak_force: 0.0,
            energy_err: 0.0,
            momentum_err: 0.0,
            separated: None,
        };
        let limit = self.base.time_limit_s;
        while run.separated.is_none() {
            if run.t > limit {
                return Err(Error::ImpactDidNotEnd { limit_s: limit });
            }
            run.advance(0)?;
        }
        let (tau, theta) = run.separated.unwrap_or_default();
        let y0 = match run.at.phase {
            Phase::Expansion { y0 } => y0,
            Phase::Compression => 0.0,
        };
        self.finish(&run.s, run.t - tau, y0, tau, theta, run.at.t_max, run.peak_force, run.energy_err, run.momentum_err)
    }

    /// Advance `s` over one step with the end force and rate zero into `out`; returns
    /// `(Y_T, Y_T')` of that prediction.
    fn predict(&self, grid: &Grid, s: &State, f0: f64, d0: f64, out: &mut State) -> (f64, f64) {
        let n = self.lam.len();
        let st = &grid.steps;
        let (q0, v0, q1, v1) = (&s.q[..n], &s.v[..n], &mut out.q[..n], &mut out.v[..n]);
        let (c, sq, vq) = (&st.col(COS)[..n], &st.col(SIN_W)[..n], &st.col(W_SIN)[..n]);
        let (qf, qd) = (&st.col(Q_RESPONSE)[..n], &st.col(Q_RESPONSE + 1)[..n]);
        let (vf, vd) = (&st.col(V_RESPONSE)[..n], &st.col(V_RESPONSE + 1)[..n]);
        for j in 0..n {
            q1[j] = c[j] * q0[j] + sq[j] * v0[j] + qf[j] * f0 + qd[j] * d0;
            v1[j] = vq[j] * q0[j] + c[j] * v0[j] + vf[j] * f0 + vd[j] * d0;
        }
        (-dot(&self.g, q1), -dot(&self.g, v1))
    }

    /// Add the end force and rate to a predicted step; returns the coordinates' energy, J.
    fn correct(&self, grid: &Grid, out: &mut State, f1: f64, d1: f64) -> f64 {
        let n = self.lam.len();
        let st = &grid.steps;
        let (q, v) = (&mut out.q[..n], &mut out.v[..n]);
        let (qf, qd) = (&st.col(Q_RESPONSE + 2)[..n], &st.col(Q_RESPONSE + 3)[..n]);
        let (vf, vd) = (&st.col(V_RESPONSE + 2)[..n], &st.col(V_RESPONSE + 3)[..n]);
        for j in 0..n {
            q[j] += qf[j] * f1 + qd[j] * d1;
            v[j] += vf[j] * f1 + vd[j] * d1;
        }
        // kinetic plus potential
        let lam = &self.lam[..n];
        let e = sum4(n, |j| v[j] * v[j] + lam[j] * q[j] * q[j]);
        0.5 * e
    }

    /// The end force and rate of a step in expansion from the prediction `(Y_hat, Yd_hat)`:
    /// Newton on Eq 10, `u + (k1/k_s + bf k1) u^p = z` with `z = (Y_hat - bd D1) / Y0`, from
    /// `start = (u, u^p)`, with `D1 = F'(Y_T) Y_T'` updated from each iterate from its first
    /// guess `d_guess` (its coupling `bd` is of order `h^3`). Each iterate and its power come
    /// from the previous pair by the binomial series (`PowSeries::advance`), so a good start
    /// needs no power function. `Ok(None)` when the ball has left.
    fn expansion_end(
        &self,
        grid: &Grid,
        y0: f64,
        pred: (f64, f64),
        start: (f64, f64),
        d_guess: f64,
    ) -> Result<Option<Contact1>> {
        let c = &self.base.contact;
        let (yh, ydh) = pred;
        if yh <= 0.0 {
            return Ok(None);
        }
        let (alpha, p) = (c.k1 / c.ks, c.p);
        let beta = alpha + grid.bf * c.k1;
        let inv_y0 = 1.0 / y0;
        let (mut u, mut up) = start;
        let mut d1 = d_guess;
        let mut z = (yh - grid.bd * d1) * inv_y0;
        if z <= 0.0 {
            return Ok(None);
        }
        if !(u > 0.0 && up > 0.0 && u <= 1.0) {
            // no usable start: the upper bound min(z, 1) of the root
            u = z.min(1.0);
            up = u.powf(p);
        }
        let mut inv_u = 1.0 / u;
        for _ in 0..100 {
            // Newton on an increasing convex function: from the left it lands right of the
            // root, from the right it stays there; halving only guards against rounding
            let r = p * up * inv_u;
            let step = (u + beta * up - z) / (1.0 + beta * r);
            let delta = (-step * inv_u).max(-0.5);
            (u, up) = self.base.contact.pow.advance(u, up, delta);
            inv_u = 1.0 / u;
            // dF/dY_T along Eq 10 with the strings in series, and the rate from it
            let r = p * up * inv_u;
            let f1 = c.k1 * y0 * up;
            d1 = c.k1 * r * (ydh - grid.cf * f1) / (1.0 + r * (alpha + c.k1 * grid.cd));
            let z_new = (yh - grid.bd * d1) * inv_y0;
            let moved = (z_new - z).abs();
            z = z_new;
            if z <= 0.0 {
                return Ok(None);
            }
            // after a Newton step of 1e-8 the error is of order 1e-16
            if delta.abs() <= 1e-8 && moved <= 1e-15 * z {
                return Ok(Some(Contact1 { f: f1, d: d1, u: (u, up) }));
            }
        }
        Err(Error::ContactSolve { z })
    }

    /// The force error of a cubic history whose midpoint force is `f` against the expansion law
    /// at the midpoint compression `ym`: `F'(Y) (Y_law(f) - ym)`, with Eq 10 inverted explicitly
    /// (`Y_law(F) = Y0 u + F/k_s`, `u = (F/(k1 Y0))^(1/p)`), N.
    fn expansion_miss(&self, y0: f64, ym: f64, f: f64) -> f64 {
        let c = &self.base.contact;
        if f <= 0.0 {
            // no negative force is physical; the law lies between 0 and k_s Y_T (Y_T >= F/k_s),
            // so the miss is at most this
            return f - c.compression_stiffness() * ym.max(0.0);
        }
        let up = f / (c.k1 * y0);
        let u = up.powf(1.0 / c.p);
        let r = c.p * up / u;
        let kappa = c.k1 * r / (1.0 + r * c.k1 / c.ks);
        kappa * (y0 * u + f / c.ks - ym)
    }

    fn contact_state(&self, phase: Phase, f: f64, u: (f64, f64)) -> ContactState {
        let c = &self.base.contact;
        match phase {
            Phase::Compression => {
                ContactState { force: f, ball_compression: f / c.k1, u: 0.0, u_pow: 0.0, string_deflection: f / c.ks }
            }
            Phase::Expansion { y0 } => {
                ContactState { force: f, ball_compression: u.0 * y0, u: u.0, u_pow: u.1, string_deflection: f / c.ks }
            }
        }
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
        let e_a = -s.v[0] / (p.ball.mass.sqrt() * p.impact.v1);
        // (a fold from +0: an empty sum of f64 is -0)
        let vib = (RIGID..self.lam.len())
            .map(|k| 0.5 * (s.v[k] * s.v[k] + self.lam[k] * s.q[k] * s.q[k]))
            .fold(0.0, |a, b| a + b);
        let (peak_pe, recontact) = self.after_impact(s, since_separation);
        let result = ImpactResult {
            e_a,
            tau_s: tau,
            theta_end_deg: theta.to_degrees(),
            f_ball: self.base.contact.ball_loss(y0) / e0,
            f_vib: vib / e0,
            f_vib_peak_pe: peak_pe / e0,
            f_hand: 0.0,
            f_spin: 0.5 * s.v[3] * s.v[3] / e0,
            f_rigid: 0.5 * (s.v[1] * s.v[1] + s.v[2] * s.v[2]) / e0,
            f_ke_ball: e_a * e_a,
            peak_force_n: peak_force,
            energy_error: energy_err,
            momentum_error: momentum_err,
            x_load_m: self.base.load.x_load,
            t_max_compression_s: t_max,
            y0_m: y0,
            recontact,
            dt_s: self.step(),
        };
        result.check_finite()?;
        Ok(result)
    }

    /// Peak bending PE over two fundamental periods of free vibration from separation, and
    /// whether the frame meets the ball again within that window, in closed form
    /// ([`FreeVibration`]). `s` is the state `lag` seconds after separation.
    fn after_impact(&self, s: &State, lag: f64) -> (f64, bool) {
        let flex = RIGID..self.lam.len();
        let free = FreeVibration::new(&self.omega[flex.clone()], &s.q[flex.clone()], &s.v[flex.clone()], &self.g[flex]);
        let window = 2.0 / self.base.f1_hz;
        let peak = free.peak_pe(-lag, window - lag);
        // the gap Y_T without the flexible modes: the ball and the rigid racket
        let gap0 = -(0..RIGID).map(|i| self.g[i] * s.q[i]).sum::<f64>();
        let rate = -(0..RIGID).map(|i| self.g[i] * s.v[i]).sum::<f64>();
        (peak, free.meets_ball(gap0, rate, window - lag))
    }
}

#[derive(Debug, Clone)]
struct State {
    q: Vec<f64>,
    v: Vec<f64>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `q(h), q'(h)` of `q'' + lam q = t^m` by RK4 steps of 2e-3 radian.
    fn rk4(lam: f64, h: f64, m: i32) -> (f64, f64) {
        let n = ((lam.sqrt() * h / 2e-3).ceil() as usize).max(2000);
        let dt = h / n as f64;
        let f = |t: f64, q: f64| t.powi(m) - lam * q;
        let (mut q, mut v) = (0.0, 0.0);
        for i in 0..n {
            let t = i as f64 * dt;
            let (k1q, k1v) = (v, f(t, q));
            let (k2q, k2v) = (v + 0.5 * dt * k1v, f(t + 0.5 * dt, q + 0.5 * dt * k1q));
            let (k3q, k3v) = (v + 0.5 * dt * k2v, f(t + 0.5 * dt, q + 0.5 * dt * k2q));
            let (k4q, k4v) = (v + dt * k3v, f(t + dt, q + dt * k3q));
            q += dt / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
            v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        }
        (q, v)
    }

    #[test]
    fn step_responses_match_direct_integration_on_both_branches() {
        let h = 1e-4;
        // lam h^2: rigid, the series branch, both sides of the switch, the closed form
        for x in [0.0, 1e-6, 0.3, 0.999, 1.001, 4.0, 100.0, 1e4] {
            let lam = x / (h * h);
            let (q, v) = responses(lam, h, (lam.sqrt() * h).sin_cos());
            for m in 0..4 {
                let (qr, vr) = rk4(lam, h, m as i32);
                // each compared with the natural size of the response, without and with the spring
                let scale_q = h.powi(m as i32 + 2) / (1.0 + x);
                let scale_v = h.powi(m as i32 + 1) / (1.0 + x.sqrt());
                assert!((q[m] - qr).abs() <= 1e-9 * scale_q, "q, lam h^2 = {x}, m = {m}: {} vs {qr}", q[m]);
                assert!((v[m] - vr).abs() <= 1e-9 * scale_v, "v, lam h^2 = {x}, m = {m}: {} vs {vr}", v[m]);
            }
        }
    }

    #[test]
    fn the_two_branches_meet() {
        let h = 2e-4;
        let (lb, la) = ((1.0 - 1e-12) / (h * h), (1.0 + 1e-12) / (h * h));
        let below = responses(lb, h, (lb.sqrt() * h).sin_cos());
        let above = responses(la, h, (la.sqrt() * h).sin_cos());
        for m in 0..4 {
            assert!((below.0[m] / above.0[m] - 1.0).abs() < 1e-11, "q m {m}");
            assert!((below.1[m] / above.1[m] - 1.0).abs() < 1e-11, "v m {m}");
        }
    }
}

/// The expansion law's end force (N), rate (N/s) and `(u, u^p)` of a step.
#[derive(Debug, Clone, Copy, Default)]
struct Contact1 {
    f: f64,
    d: f64,
    u: (f64, f64),
}

/// The contact at the end of a step.
#[derive(Debug, Clone, Copy)]
struct End {
    /// Force, N, and its rate, N/s.
    f: f64,
    d: f64,
    /// Total compression `Y_T`, m, and its rate, m/s.
    yt: f64,
    ytd: f64,
    phase: Phase,
    /// `(u, u^p)` of the expansion law.
    u: (f64, f64),
    /// Time of maximum compression, s (once passed).
    t_max: f64,
}

/// An impact in progress.
struct Run<'a> {
    m: &'a ModalModel,
    s: State,
    next: State,
    at: End,
    t: f64,
    peak_force: f64,
    energy_err: f64,
    momentum_err: f64,
    /// Contact time and twist angle at separation, once it has happened.
    separated: Option<(f64, f64)>,
}

impl Run<'_> {
    /// Take one step of the given level, or, if its force history misses the contact law by
    /// more than the tolerance, `REFINE` steps of the next level.
    fn advance(&mut self, level: usize) -> Result<()> {
        let m = self.m;
        let grid = m.grid(level);
        let h = grid.h;
        let c = &m.base.contact;
        let ks = c.compression_stiffness();
        let a = self.at;
        let (yh, ydh) = m.predict(grid, &self.s, a.f, a.d, &mut self.next);
        let mut end = a;
        let (mut f1, mut d1) = match a.phase {
            Phase::Compression => {
                let [m0, m1] = grid.compression;
                (m0[0] * yh + m0[1] * ydh, m1[0] * yh + m1[1] * ydh)
            }
            Phase::Expansion { y0 } => {
                // start from the previous u moved along its rate: dY_T = Y0 (1 + alpha p u^(p-1)) du
                let (u0, up0) = a.u;
                let r0 = if u0 > 0.0 { c.p * up0 / u0 } else { 0.0 };
                let u1 = u0 + h * a.ytd / (y0 * (1.0 + r0 * c.k1 / c.ks));
                let start = if u1 > 0.0 && u0 > 0.0 { c.pow.advance(u0, up0, u1 / u0 - 1.0) } else { (0.0, 0.0) };
                let e = m.expansion_end(grid, y0, (yh, ydh), start, a.d)?.unwrap_or_default();
                end.u = e.u;
                (e.f, e.d)
            }
        };
        let mut switch = None;
        if a.phase == Phase::Compression && d1 <= 0.0 {
            // maximum compression within this step: Y_T = F/ks on its compression side
            let (sm, ytm) = hermite_max(a.yt, a.ytd, f1 / ks, d1 / ks, h);
            end.t_max = self.t + sm * h;
            let y0 = c.ball_compression_at_max(ytm);
            end.phase = Phase::Expansion { y0 };
            let e = m.expansion_end(grid, y0, (yh, ydh), (1.0, 1.0), 0.0)?.unwrap_or_default();
            end.u = e.u;
            (f1, d1) = (e.f, e.d);
            switch = Some(sm);
        }
        end.f = f1;
        end.d = d1;
        end.yt = yh - grid.bf * f1 - grid.bd * d1;
        end.ytd = ydh - grid.cf * f1 - grid.cd * d1;
        if let (Phase::Expansion { y0 }, true) = (end.phase, level + 1 < LEVELS) {
            // the cubic force history against the contact law at the midpoint, and at the
            // quarter points too where the force falls to a quarter of its start or the ball
            // leaves: there the law nears zero at an unknown point, the cubic can dip below
            // zero after it, and the midpoint alone can miss that
            let points: &[f64] = if f1 < 0.25 * a.f { &[0.25, 0.5, 0.75] } else { &[0.5] };
            let mut miss: f64 = 0.0;
            for &s in points {
                let ym = hermite_eval(a.yt, a.ytd, end.yt, end.ytd, h, s);
                let cubic = hermite_eval(a.f, a.d, f1, d1, h, s);
                let at = match switch {
                    Some(sm) if sm > s => cubic - ks * ym,
                    _ => m.expansion_miss(y0, ym, cubic),
                };
                miss = miss.max(at.abs());
            }
            if miss * h > m.impulse_tolerance {
                for _ in 0..REFINE {
                    self.advance(level + 1)?;
                    if self.separated.is_some() {
                        break;
                    }
                }
                return Ok(());
            }
        }
        let modal_energy = m.correct(grid, &mut self.next, f1, d1);
        std::mem::swap(&mut self.s, &mut self.next);
        self.t += h;
        self.peak_force = self.peak_force.max(f1);
        let p = &m.base.params;
        let (mb, v1) = (p.ball.mass, p.impact.v1);
        let e0 = 0.5 * mb * v1 * v1;
        let st = m.contact_state(end.phase, f1, end.u);
        let e =
            modal_energy + c.ball_energy_with_loss(end.phase, &st) + c.string_energy(&st) + 0.5 * m.residual * f1 * f1;
        self.energy_err = self.energy_err.max((e - e0).abs() / e0);
        let pm = mb.sqrt() * self.s.v[0] + self.s.v[1] / m.g[1];
        self.momentum_err = self.momentum_err.max((pm - mb * v1).abs() / (mb * v1));
        if matches!(end.phase, Phase::Expansion { .. }) && f1 <= 0.0 {
            let sc = hermite_root(a.yt, a.ytd, end.yt, end.ytd, h);
            // twist angle at the crossing (`next` now holds the state before the step)
            let theta =
                hermite_eval(self.next.q[3], self.next.v[3], self.s.q[3], self.s.v[3], h, sc) / p.racket.ix.sqrt();
            self.separated = Some((self.t - h + sc * h, theta));
        }
        self.at = end;
        Ok(())
    }
}
