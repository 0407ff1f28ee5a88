//! The modal solver's step tables: for one step length, the exact propagation of every
//! coordinate under a cubic Hermite force history (free part and the responses to the end
//! values and rates of the force), and how the end force and rate move the end compression.

use crate::model::contact::StepCoupling;
use crate::solve::modal::pair::Pair;

/// The exact step of one coordinate under the cubic force history, each coefficient a pair
/// acting on the coordinate's `[q, q']` at once (so that a step is a few two-wide operations a
/// coordinate, and the table is read front to back): the free propagation
/// `[q, q'] = q0 [cos(w h), -w sin(w h)] + q0' [sin(w h)/w, cos(w h)]`, the responses to the
/// force's end values and rates `F0, D0, F1, D1` (already multiplied by the coordinate's `g`), and
/// the coordinate's `[g, g]` and `[w^2, 1]` (its energy is half `[w^2, 1] . [q, q']^2`).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Coef {
    pub from_q: Pair,
    pub from_v: Pair,
    pub f0: Pair,
    pub d0: Pair,
    pub f1: Pair,
    pub d1: Pair,
    pub g: Pair,
    pub lam: Pair,
}

/// The step tables of one step length.
#[derive(Debug, Clone)]
pub(super) struct Grid {
    /// Step, s.
    pub h: f64,
    /// One [`Coef`] a coordinate.
    pub coef: Vec<Coef>,
    /// How the end force and rate move the end compression (static correction included).
    pub coupling: StepCoupling,
}

impl Grid {
    /// The tables for coordinates with `w^2 = lam`, `w = omega` and load-point amplitudes `g`,
    /// the truncated modes' static flexibility `residual` (m/N) and the step `h`, s.
    pub fn new(lam: &[f64], omega: &[f64], g: &[f64], residual: f64, h: f64) -> Grid {
        let coef: Vec<Coef> = lam
            .iter()
            .zip(omega)
            .zip(g)
            .map(|((&lam, &w), &g)| {
                let (s, c) = (w * h).sin_cos();
                let (rq, rv) = responses(lam, h, (s, c));
                let (hq, hv) = (hermite(rq, h), hermite(rv, h));
                let pair = |i: usize| Pair::new(g * hq[i], g * hv[i]);
                Coef {
                    from_q: Pair::new(c, -w * s),
                    from_v: Pair::new(if w > 0.0 { s / w } else { h }, c),
                    f0: pair(0),
                    d0: pair(1),
                    f1: pair(2),
                    d1: pair(3),
                    g: Pair::splat(g),
                    lam: Pair::new(lam, 1.0),
                }
            })
            .collect();
        let n = coef.len();
        let g = |j: usize| g[j];
        let bf = sum4(n, |j| g(j) * coef[j].f1.get()[0]) + residual;
        let bd = sum4(n, |j| g(j) * coef[j].d1.get()[0]);
        let cf = sum4(n, |j| g(j) * coef[j].f1.get()[1]);
        let cd = sum4(n, |j| g(j) * coef[j].d1.get()[1]) + residual;
        Grid { h, coef, coupling: StepCoupling { bf, bd, cf, cd } }
    }
}

/// `sum_i f(i)` over `0..n` with four partial sums (so that it vectorises).
#[inline(always)]
pub(super) fn sum4(n: usize, f: impl Fn(usize) -> f64) -> f64 {
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
