//! Free vibration of the beam after the ball has left, in closed form.
//!
//! Once the contact force is zero the discrete beam is a linear system: each flexible mode
//! moves as `q_k(t) = a_k cos(w_k t) + b_k sin(w_k t)`, with bending energy
//! `PE(t) = sum_k E_k cos^2(w_k t - phi_k)` (`E_k` the mode's energy). Both solvers project
//! their state at separation onto the modes and ask two questions of this closed form instead
//! of stepping the free beam for two fundamental periods:
//!
//! - the paper's vibration measure, the peak of `PE(t)` over the window. `PE(t) <= E_d cos^2 +
//!   (E - E_d)` for the dominant mode `d`, and `PE >= E_d` at each of its maxima, so the peak lies
//!   where `E_d cos^2(w_d t - phi_d) >= PE_best - (E - E_d)`: usually narrow windows around the
//!   maxima of the dominant mode, sampled at a quarter radian of the fastest mode that carries
//!   energy, the best samples refined by a parabola through their neighbours;
//! - whether the vibrating frame meets the ball again: the gap is affine in time minus the
//!   load-point vibration, which is bounded by the sum of its modal amplitudes, so only the
//!   times where the affine part is within that bound of zero need sampling.
//!
//! Modes carrying less than [`ENERGY_TAIL`] of the vibration energy (or, for the gap, less than
//! [`AMPLITUDE_TAIL`] of the displacement) are left out of the sampling; their contribution is
//! bounded by that tail.

use crate::numeric::short_turn::{series_terms, small_sin_cos};
use crate::numeric::spare::Buf;
use std::cell::RefCell;

/// Highest modes whose summed energy is below this fraction of the total are not sampled.
pub const ENERGY_TAIL: f64 = 1.0e-10;
/// Highest modes whose summed load-point amplitude is below this fraction of the total are not
/// sampled for the gap (and the bound is widened by their sum).
pub const AMPLITUDE_TAIL: f64 = 1.0e-6;
/// Sample spacing, radians of the fastest sampled mode.
pub const PHASE_PER_SAMPLE: f64 = 0.25;
/// A candidate peak is polished only if the peak of its local quadratic is within this fraction
/// of the best value found: a margin, not a bound (the quadratic's error is far below it, the
/// parabola step leaving the candidate within about 1e-3 of a sample spacing of the peak; on
/// 200,000 random vibrations the pruning moved no result by more than 3e-14).
const QUADRATIC_MARGIN: f64 = 1e-6;
/// Samples of a search between two looks at whether its run is cancelled
/// ([`crate::control::cancelled`]: a long search stops within a few milliseconds).
const CANCEL_SAMPLES: usize = 1 << 14;

/// A sampled peak after the parabola step: time, value, sample spacing, the peak of the local
/// quadratic, and the phasors there.
type Candidate = (f64, f64, f64, f64, Phasors);

thread_local! {
    /// The storage of the candidate list, reused from peak to peak on a thread.
    static CANDIDATES: RefCell<Vec<Candidate>> = const { RefCell::new(Vec::new()) };
}

/// Each mode's phasor at one time: `q_k` and `q_k'/w_k`.
#[derive(Debug, Clone)]
struct Phasors {
    q: Buf<f64>,
    p: Buf<f64>,
}

impl Phasors {
    /// Take the values of `other` (as long), keeping this one's storage.
    fn copy_from(&mut self, other: &Phasors) {
        self.q.copy_from_slice(&other.q);
        self.p.copy_from_slice(&other.p);
    }

    /// Advance by the rotations `(sin, cos)(w_k dt)`.
    fn rotate(&mut self, rot: &[(f64, f64)]) {
        for ((q, p), &(s, c)) in self.q.iter_mut().zip(self.p.iter_mut()).zip(rot) {
            (*q, *p) = (*q * c + *p * s, *p * c - *q * s);
        }
    }

    /// Advance by a short time `dt` (`|w_k dt| <= 1` by series, longer directly; `omega`
    /// ascending).
    fn rotate_small(&mut self, omega: &[f64], dt: f64) {
        let terms = series_terms(omega.last().map_or(0.0, |w| (w * dt).abs()));
        for ((q, p), w) in self.q.iter_mut().zip(self.p.iter_mut()).zip(omega) {
            let (s, c) = small_sin_cos(w * dt, terms);
            (*q, *p) = (*q * c + *p * s, *p * c - *q * s);
        }
    }
}

/// The free vibration of the flexible modes from a reference time `t = 0`.
#[derive(Debug, Clone)]
pub struct FreeVibration {
    /// `w_k`, rad/s, ascending.
    omega: Buf<f64>,
    /// `q_k(0)`.
    a: Buf<f64>,
    /// `q_k'(0) / w_k`.
    b: Buf<f64>,
    /// Mode amplitude at the load point.
    g: Buf<f64>,
}

impl FreeVibration {
    /// Modes `omega` (ascending, > 0), coordinates `q` and rates `qdot` at `t = 0`, and each
    /// mode's amplitude at the load point `g`.
    pub fn new(omega: &[f64], q: &[f64], qdot: &[f64], g: &[f64]) -> Self {
        let b = qdot.iter().zip(omega).map(|(v, w)| v / w).collect();
        FreeVibration {
            omega: omega.iter().copied().collect(),
            a: q.iter().copied().collect(),
            b,
            g: g.iter().copied().collect(),
        }
    }

    /// Energy of mode `k`, J (for mass-normalised modes).
    fn energy(&self, k: usize) -> f64 {
        0.5 * self.omega[k] * self.omega[k] * (self.a[k] * self.a[k] + self.b[k] * self.b[k])
    }

    /// Number of low modes that carry all but a fraction `tail` of `weight` (summed from the top).
    fn kept(&self, weight: impl Fn(usize) -> f64, tail: f64) -> (usize, f64) {
        let total: f64 = (0..self.omega.len()).map(&weight).sum();
        let mut k = self.omega.len();
        let mut dropped = 0.0;
        while k > 1 && dropped + weight(k - 1) <= tail * total {
            dropped += weight(k - 1);
            k -= 1;
        }
        (k, dropped)
    }

    /// Bending energy of the first `k` modes at time `t`, J.
    fn pe_first(&self, k: usize, t: f64) -> f64 {
        (0..k)
            .map(|i| {
                let q = self.phasor(i, t).0;
                0.5 * self.omega[i] * self.omega[i] * q * q
            })
            .sum()
    }

    /// Mode `i`'s phasor `(q_i, q_i'/w_i)` at time `t`.
    fn phasor(&self, i: usize, t: f64) -> (f64, f64) {
        let (s, c) = (self.omega[i] * t).sin_cos();
        (self.a[i] * c + self.b[i] * s, self.b[i] * c - self.a[i] * s)
    }

    /// Bending energy at time `t`, J.
    pub fn pe(&self, t: f64) -> f64 {
        self.pe_first(self.omega.len(), t)
    }

    /// Displacement of the load point due to the vibration at time `t`, m.
    pub fn load_displacement(&self, t: f64) -> f64 {
        (0..self.omega.len()).map(|i| self.g[i] * self.phasor(i, t).0).sum()
    }

    /// Samples of `sum_k weight_k(q_k)` over the first `k` modes at `m + 1` equally spaced times
    /// from `lo` to `hi`, by rotating each mode's phasor (no trigonometric call per sample).
    fn sample(&self, k: usize, lo: f64, hi: f64, m: usize, f: impl Fn(usize, f64) -> f64) -> Buf<f64> {
        let mut ph = self.phasors(k, lo);
        let rot = self.rotation(k, (hi - lo) / m as f64);
        let mut out = Buf::with_capacity(m + 1);
        out.push((0..k).map(|i| f(i, ph.q[i])).sum());
        for j in 0..m {
            // (a cancelled run's search ends short: its solver's next poll ends the impact)
            if j % CANCEL_SAMPLES == CANCEL_SAMPLES - 1 && crate::control::cancelled() {
                break;
            }
            ph.rotate(&rot);
            out.push(ph.q.iter().enumerate().fold(0.0, |sum, (i, &q)| sum + f(i, q)));
        }
        out
    }

    /// Phasors `(q_k, q_k'/w_k)` of the first `k` modes at time `t`.
    fn phasors(&self, k: usize, t: f64) -> Phasors {
        let (mut q, mut p) = (Buf::with_capacity(k), Buf::with_capacity(k));
        for i in 0..k {
            let (qi, pi) = self.phasor(i, t);
            q.push(qi);
            p.push(pi);
        }
        Phasors { q, p }
    }

    /// `(sin, cos)(w_k dt)` of the first `k` modes.
    /// (Short turns by the Taylor series, [`small_sin_cos`], as accurate and a few times cheaper.)
    fn rotation(&self, k: usize, dt: f64) -> Buf<(f64, f64)> {
        self.omega[..k]
            .iter()
            .map(|w| {
                let x = w * dt;
                small_sin_cos(x, series_terms(x.abs()))
            })
            .collect()
    }

    /// Bending energy of phasors, J.
    fn pe_of(&self, ph: &Phasors) -> f64 {
        ph.q.iter().zip(&self.omega).map(|(q, w)| 0.5 * w * w * q * q).sum()
    }

    /// The largest bending energy over `[t0, t1]`, J.
    pub fn peak_pe(&self, t0: f64, t1: f64) -> f64 {
        let n = self.omega.len();
        if n == 0 || t1 <= t0 {
            return if n == 0 { 0.0 } else { self.pe(t0) };
        }
        let (k, _) = self.kept(|i| self.energy(i), ENERGY_TAIL);
        let d = (0..k).max_by(|&i, &j| self.energy(i).total_cmp(&self.energy(j))).unwrap_or(0);
        let e_d = self.energy(d);
        let rest: f64 = (0..k).filter(|&i| i != d).map(|i| self.energy(i)).sum();
        let w_d = self.omega[d];
        let phi = self.b[d].atan2(self.a[d]);
        // maxima of the dominant mode, w_d t - phi = j pi, and every mode's phasor there (the
        // first directly, the others by rotating it through half a period of the dominant mode)
        let half_period = std::f64::consts::PI / w_d;
        let j_lo = ((w_d * t0 - phi) / std::f64::consts::PI).floor() as i64;
        let j_hi = ((w_d * t1 - phi) / std::f64::consts::PI).ceil() as i64;
        let peaks: Buf<f64> = (j_lo..=j_hi).map(|j| (phi + j as f64 * std::f64::consts::PI) / w_d).collect();
        // (the phasors at the j-th maximum are those at the first rotated j times: once here and
        // again, the same way, window by window below)
        let turn = self.rotation(k, half_period);
        let first = self.phasors(k, peaks[0]);
        let mut at = first.clone();
        let mut best: f64 = 0.0;
        for t in &peaks {
            if (t0..=t1).contains(t) {
                best = best.max(self.pe_of(&at));
            }
            at.rotate(&turn);
        }
        // the window's ends, where the dominant mode's bound `E_d cos^2 + rest` does not rule
        // them out (the bound's rounding is far inside the margin)
        for end in [t0, t1] {
            let bound = e_d * (w_d * end - phi).cos().powi(2) + rest;
            if bound * (1.0 + 1e-9) >= best {
                best = best.max(self.pe_first(k, end));
            }
        }
        // where the peak can be: windows of half-width `half` around the dominant maxima
        let floor = (best - rest) / e_d;
        let half = if floor <= 0.0 || e_d <= 0.0 { f64::INFINITY } else { floor.min(1.0).sqrt().acos() / w_d };
        let spacing = PHASE_PER_SAMPLE / self.omega[k - 1];
        // a whole window (not cut by t0 or t1) has the same samples relative to its peak
        let whole_m = ((2.0 * half / spacing).ceil() as usize).max(2);
        let whole_dt = 2.0 * half / whole_m as f64;
        let (mut back, mut whole_step) = (None, None);
        // (time, value, sample spacing, the peak of the local quadratic, phasors) of each
        // sampled peak after the parabola step
        let mut candidates = CANDIDATES.try_with(|c| std::mem::take(&mut *c.borrow_mut())).unwrap_or_default();
        // one window over [t0, t1] when the dominant mode does not bound the peak, else one
        // around each maximum; the buffers are reused from window to window
        let windows = if half.is_infinite() { 1 } else { peaks.len() };
        at.copy_from(&first);
        // (no whole window when the dominant mode does not bound the peak: `whole_m` is then
        // meaningless, saturated from an infinite width)
        let samples = if half.is_finite() { whole_m + 1 } else { 0 };
        let (mut ph, mut start, mut v) = (first.clone(), first, Buf::with_capacity(samples));
        for (j, &peak) in peaks.iter().enumerate().take(windows) {
            // (a cancelled run's search ends short: its solver's next poll ends the impact)
            if crate::control::cancelled() {
                return best;
            }
            if j > 0 {
                at.rotate(&turn);
            }
            let (lo, hi, around) = if half.is_infinite() { (t0, t1, false) } else { (peak - half, peak + half, true) };
            let (lo, hi, whole) = (lo.max(t0), hi.min(t1), lo >= t0 && hi <= t1 && around);
            if hi <= lo {
                continue;
            }
            // a window that cannot beat the best value found is not sampled: within `half` of the
            // dominant maximum each mode has `|q(t)| <= |q| + |q'/w| w half` (its phasor there)
            // and never more than its energy
            if around {
                let bound: f64 = (0..k)
                    .map(|i| {
                        let w = self.omega[i];
                        let r = at.q[i].abs() + at.p[i].abs() * w * half;
                        (0.5 * w * w * r * r).min(self.energy(i))
                    })
                    .sum();
                if bound * (1.0 + 1e-12) < best {
                    continue;
                }
            }
            let (m, dt, step) = if whole {
                let back = back.get_or_insert_with(|| self.rotation(k, -half));
                let step = whole_step.get_or_insert_with(|| self.rotation(k, whole_dt));
                ph.copy_from(&at);
                ph.rotate(back);
                (whole_m, whole_dt, std::borrow::Cow::Borrowed(&*step))
            } else {
                let m = (((hi - lo) / spacing).ceil() as usize).max(2);
                let dt = (hi - lo) / m as f64;
                ph = self.phasors(k, lo);
                (m, dt, std::borrow::Cow::Owned(self.rotation(k, dt)))
            };
            // the samples (`ph` is left at the window's start)
            start.copy_from(&ph);
            v.clear();
            for i in 0..=m {
                if i % CANCEL_SAMPLES == CANCEL_SAMPLES - 1 && crate::control::cancelled() {
                    return best;
                }
                if i > 0 {
                    ph.rotate(&step);
                }
                v.push(self.pe_of(&ph));
            }
            best = best.max(v[0]).max(v[m]);
            // every interior local maximum within the sampling error (a few per cent at a
            // quarter radian) of the highest sample may hold the peak
            // (the window's ends count: a peak may sit just inside one)
            let top = v.iter().copied().fold(0.0, f64::max);
            let is_max = |i: usize| (i == 0 || v[i] >= v[i - 1]) && (i == m || v[i] >= v[i + 1]);
            // (the candidates' phasors are rotated on from one candidate to the next: the same
            // rotations as from the window's start each time, in O(m) instead of O(m^2) for
            // a window with many local maxima)
            let (mut walk, mut walked) = (start.clone(), 0);
            for i in (0..=m).filter(|&i| is_max(i) && v[i] >= 0.9 * top) {
                let shift = if i > 0 && i < m {
                    let curv = v[i - 1] - 2.0 * v[i] + v[i + 1];
                    if curv < 0.0 {
                        (0.5 * (v[i - 1] - v[i + 1]) / curv).clamp(-1.0, 1.0)
                    } else {
                        0.0
                    }
                } else {
                    0.0
                };
                for _ in walked..i {
                    walk.rotate(&step);
                }
                walked = i;
                let mut ph = walk.clone();
                ph.rotate_small(&self.omega[..k], shift * dt);
                let (pe, d1, d2) = self.derivatives(&ph);
                let value = pe.max(v[i]);
                best = best.max(value);
                let quadratic = if d2 < 0.0 { pe - 0.5 * d1 * d1 / d2 } else { f64::INFINITY };
                candidates.push((lo + (i as f64 + shift) * dt, value, dt, quadratic, ph));
            }
        }
        // the parabola step is good to about 1e-3 of the peak; polish the candidates that could
        // still be the largest by Newton on dPE/dt = 0 (analytic derivatives), the highest local
        // quadratic first: a candidate whose quadratic peaks below the best found so far (by
        // more than its error, of the order of the cube of the parabola's miss) cannot hold it
        candidates.sort_by(|a, b| b.3.total_cmp(&a.3));
        for (t, value, dt, quadratic, ph) in candidates.drain(..) {
            if value >= best * (1.0 - 1e-2) && quadratic >= best * (1.0 - QUADRATIC_MARGIN) {
                best = best.max(self.newton_peak(t, ph, (t - 2.0 * dt).max(t0), (t + 2.0 * dt).min(t1)));
            }
        }
        // (the list's storage kept for the next peak on this thread)
        let _ = CANDIDATES.try_with(|c| *c.borrow_mut() = candidates);
        best
    }

    /// Bending energy of phasors, J, and its first and second time derivatives.
    fn derivatives(&self, ph: &Phasors) -> (f64, f64, f64) {
        let (mut pe, mut d1, mut d2) = (0.0, 0.0, 0.0);
        for i in 0..ph.q.len() {
            let w = self.omega[i];
            let (q, qd) = (ph.q[i], w * ph.p[i]);
            let w2 = w * w;
            pe += 0.5 * w2 * q * q;
            d1 += w2 * q * qd;
            d2 += w2 * (qd * qd - w2 * q * q);
        }
        (pe, d1, d2)
    }

    /// The largest bending energy found by Newton steps on `dPE/dt = 0` from `t`, where the
    /// modes have phasors `ph`, kept inside `[lo, hi]`.
    fn newton_peak(&self, mut t: f64, mut ph: Phasors, lo: f64, hi: f64) -> f64 {
        let k = ph.q.len();
        let mut best: f64 = 0.0;
        for _ in 0..4 {
            let (pe, d1, d2) = self.derivatives(&ph);
            best = best.max(pe);
            if d2 >= 0.0 || d1 == 0.0 {
                break;
            }
            let next = (t - d1 / d2).clamp(lo, hi);
            if next == t {
                break;
            }
            ph.rotate_small(&self.omega[..k], next - t);
            t = next;
        }
        best
    }

    /// Whether `gap(t) = gap0 + rate t - load_displacement(t)` becomes positive for some
    /// `t` in `(0, t1]`: the frame catching the ball again (`gap0`, `rate`: the ball's
    /// position minus the rigid-body motion of the load point, m and m/s).
    pub fn meets_ball(&self, gap0: f64, rate: f64, t1: f64) -> bool {
        let n = self.omega.len();
        // (a and b are modal amplitudes, far from overflow: no need for hypot's care)
        let amp = |i: usize| self.g[i].abs() * (self.a[i] * self.a[i] + self.b[i] * self.b[i]).sqrt();
        if n == 0 {
            return gap0 + rate * t1.max(0.0) > 0.0 || gap0 > 0.0;
        }
        // the gap's rate is `rate - y'(t)` with `|y'| <= sum |g_k| w_k (amplitude)`: a gap that
        // starts closed and cannot open at that bound never opens
        let speed: f64 = (0..n).map(|i| amp(i) * self.omega[i]).sum();
        let y0: f64 = (0..n).map(|i| self.g[i] * self.a[i]).sum();
        if rate + speed < 0.0 && gap0 - y0 <= 0.0 {
            return false;
        }
        let (k, dropped) = self.kept(amp, AMPLITUDE_TAIL);
        let bound: f64 = (0..k).map(amp).sum::<f64>() + dropped;
        // times where the affine part is within `bound` of zero: gap0 + rate t > -bound
        let (lo, hi) = if rate < 0.0 {
            (0.0, ((-bound - gap0) / rate).min(t1))
        } else if rate > 0.0 {
            (((-bound - gap0) / rate).max(0.0), t1)
        } else if gap0 > -bound {
            (0.0, t1)
        } else {
            return false;
        };
        if hi <= lo {
            return false;
        }
        let m = (((hi - lo) * self.omega[k - 1] / PHASE_PER_SAMPLE).ceil() as usize).max(2);
        let flex = self.sample(k, lo, hi, m, |i, q| self.g[i] * q);
        let dt = (hi - lo) / m as f64;
        flex.iter().enumerate().any(|(i, y)| {
            let t = lo + i as f64 * dt;
            t > 0.0 && gap0 + rate * t - y + dropped > 0.0 && gap0 + rate * t - self.load_displacement(t) > 0.0
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Reference: a fine grid, its ten highest local maxima refined by golden section (energy
    /// evaluations only, independent of the fast method's derivatives).
    fn brute_peak(f: &FreeVibration, t0: f64, t1: f64) -> f64 {
        let m = 200_000;
        let h = (t1 - t0) / m as f64;
        let v: Vec<f64> = (0..=m).map(|i| f.pe(t0 + h * i as f64)).collect();
        let mut maxima: Vec<usize> = (1..m).filter(|&i| v[i] >= v[i - 1] && v[i] >= v[i + 1]).collect();
        maxima.sort_by(|&i, &j| v[j].total_cmp(&v[i]));
        let mut best = v[0].max(v[m]);
        let r = 0.5 * (5f64.sqrt() - 1.0);
        for &i in maxima.iter().take(10) {
            let (mut lo, mut hi) = (t0 + h * (i - 1) as f64, t0 + h * (i + 1) as f64);
            for _ in 0..60 {
                let (a, b) = (hi - r * (hi - lo), lo + r * (hi - lo));
                if f.pe(a) > f.pe(b) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            best = best.max(v[i]).max(f.pe(0.5 * (lo + hi)));
        }
        best
    }

    #[test]
    fn peak_matches_brute_force_for_dominant_and_shared_energy() {
        let omega = [785.0, 2170.0, 4200.0, 6900.0, 30000.0];
        let g = [1.0, -0.8, 0.5, 0.3, 0.1];
        let cases: [[f64; 5]; 4] = [
            [6e-4, 1e-6, 3e-7, 1e-7, 1e-9], // mode 1 dominates (the paper's impacts)
            [1e-4, 1e-4, 3e-5, 1e-5, 1e-7], // energy shared: wide candidate windows
            [0.0, 2e-4, 0.0, 0.0, 0.0],     // a single higher mode (impact at the mode-1 node)
            // five modes of nearly equal energy (the slowest a little ahead): no dominant mode
            // bounds the peak, one window over the whole interval
            [1.005e-4, 1e-4 * 785.0 / 2170.0, 1e-4 * 785.0 / 4200.0, 1e-4 * 785.0 / 6900.0, 1e-4 * 785.0 / 30000.0],
        ];
        for q in cases {
            let qdot: Vec<f64> = q.iter().zip(&omega).map(|(q, w)| 0.7 * q * w).collect();
            let f = FreeVibration::new(&omega, &q, &qdot, &g);
            let (t0, t1) = (-3e-6, 0.016);
            let fast = f.peak_pe(t0, t1);
            let slow = brute_peak(&f, t0, t1);
            assert!(fast >= slow * (1.0 - 1e-9), "{fast} < {slow}");
            assert_relative_eq!(fast, slow, max_relative = 1e-7);
        }
    }

    #[test]
    fn peak_matches_brute_force_on_random_vibrations() {
        // 100 vibrations of 2 to 7 modes with random
        // frequencies, amplitudes and phases
        let mut rnd = crate::test_rng::uniform(0x2545_f491_4f6c_dd1d);
        let mut worst: f64 = 0.0;
        for _ in 0..100 {
            let n = 2 + (rnd() * 6.0) as usize;
            let mut omega: Vec<f64> = (0..n).map(|_| 500.0 + 4e4 * rnd() * rnd()).collect();
            omega.sort_by(f64::total_cmp);
            let q: Vec<f64> = omega.iter().map(|w| (rnd() - 0.5) * 1e-3 * (785.0 / w).powi(2)).collect();
            let qdot: Vec<f64> = omega.iter().zip(&q).map(|(w, q)| (rnd() - 0.5) * 2.0 * w * q).collect();
            let f = FreeVibration::new(&omega, &q, &qdot, &vec![1.0; n]);
            let (t0, t1) = (-2e-6, 0.016);
            let (fast, slow) = (f.peak_pe(t0, t1), brute_peak(&f, t0, t1));
            worst = worst.max((slow - fast).abs() / slow);
        }
        assert!(worst < 1e-9, "fast peak differs from the refined brute-force one by {worst:e}");
    }

    #[test]
    fn gap_test_finds_a_late_catch_and_rejects_a_clean_separation() {
        let omega = [785.0, 2170.0];
        let f = FreeVibration::new(&omega, &[1e-3, 0.0], &[0.0, 0.0], &[1.0, 0.5]);
        // moving apart at 1 m/s: the 1 mm vibration never closes a gap growing from 0
        assert!(!f.meets_ball(-0.5e-3, -1.0, 0.02));
        // moving apart at 1 cm/s: the frame swings back into the ball within a period
        assert!(f.meets_ball(-0.5e-3, -0.01, 0.02));
        // moving apart at 5 mm/s, slower than the load point can swing (so the rate bound
        // cannot rule it out and the gap is sampled), but the 10 um swing never closes the gap
        let small = FreeVibration::new(&[785.0], &[1e-5], &[0.0], &[1.0]);
        assert!(!small.meets_ball(-0.5e-5, -5e-3, 0.02));
    }
}
