//! The compression phase in closed form.
//!
//! Until maximum compression the paper's contact is a linear spring (Eq 9: `F = k Y_T`, `k` the
//! ball and strings in series), and with the static correction of the truncated modes
//! (`Y_T = -g.q - R F`) the force is `F = -kappa g.q`, `kappa = k / (1 + k R)`. Every coordinate
//! then obeys `q'' + (Lambda + kappa g g^T) q = 0`: a linear system whose modes, the *coupled*
//! modes of ball, strings and frame, are found once per prepared model (the eigenpairs of
//! `Lambda + kappa g g^T` that the spring couples, [`crate::numeric::rank_one`]; the part of the
//! ball's arrival they do not carry is a rigid motion the spring does not feel). The ball
//! arrives with the frame at rest, so each coupled mode `k` moves as `c_k v1 sin(s_k t) / s_k`
//! (or `c_k v1 t` for a rigid motion of frequency 0) and the compression rate is
//! `Y_T'(t) = v1 sum_k a_k cos(s_k t)`.
//!
//! The set-up finds the first zero of `Y_T'`, the time of maximum compression (the phase is
//! linear, so the time is the same for every incident speed): none can come before the
//! dominant mode's share stops exceeding the sum of the others' amplitudes; from there it
//! samples every half radian of the fastest mode with a share of the rate (of either sign; each
//! coupled mode's phasor rotated, no trigonometric call per sample), then Newton's method
//! inside the bracket. A run evaluates every coordinate and rate there exactly. No step of the
//! compression phase is taken, so no error is made in it: the stepping starts at maximum
//! compression, where the force's rate is zero on both sides and the expansion law takes over.

use crate::numeric::rank_one::coupled_modes;
use crate::numeric::short_turn::{series_terms, small_sin_cos};
use crate::numeric::spare::Buf;
use crate::solve::modal::pair::Pair;
use crate::solve::modal::State;

/// Coupled modes whose share of the compression rate is below this fraction of the total are
/// not resolved by the sampling (they are in every evaluation; they are assumed not to add a
/// zero of the rate between samples, being far too small to turn it anywhere but right next to
/// the zero the sampling finds).
const RATE_TAIL: f64 = 1e-3;
/// Sample spacing, radians of the fastest resolved coupled mode, and at most of the dominant one.
const PHASE_PER_SAMPLE: f64 = 0.5;
const DOMINANT_PHASE_PER_SAMPLE: f64 = 0.25;

/// The coupled modes of the compression phase, per unit incident speed.
#[derive(Debug, Clone)]
pub(super) struct Compression {
    /// Coordinates.
    n: usize,
    /// Frequencies of the coupled modes, rad/s (0 for a rigid motion).
    sigma: Vec<f64>,
    /// Mode shapes (orthonormal), mode `k` at `z[k n..(k + 1) n]`.
    z: Vec<f64>,
    /// Each mode's velocity amplitude per unit incident speed.
    c: Vec<f64>,
    /// Each mode's share of the compression rate per unit incident speed (`sum a_k = Y_T'(0)`).
    a: Vec<f64>,
    /// Contact stiffness in compression, N/m (`F = k Y_T`).
    k: f64,
    /// Before this time, s, the compression rate cannot reach zero.
    t_safe: f64,
    /// The sample spacing, s, and each mode's rotation over it.
    spacing: f64,
    rotation: Vec<(f64, f64)>,
    /// The first maximum of the compression, found once (it does not depend on the incident
    /// speed: the phase is linear), if it comes within the model's time limit.
    turn: Option<Turn>,
}

/// The first zero of the compression rate: the time, s, and each coupled mode's phasor
/// `(sin, cos)(s_k t)` there.
#[derive(Debug, Clone)]
struct Turn {
    t: f64,
    phasors: Vec<(f64, f64)>,
}

/// Where the force history goes, piece by piece: `(h, (F0, F0'), (F1, F1'))`.
pub(super) type ForceSink<'a> = &'a mut dyn FnMut(f64, (f64, f64), (f64, f64));

/// The state at maximum compression (per the incident speed given to [`Compression::at_max`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct AtMax {
    /// Time from first touch, s.
    pub t: f64,
    /// Total compression `Y_T`, m, and the contact force, N.
    pub yt: f64,
    pub f: f64,
}

impl Compression {
    /// The coupled modes of coordinates with `w^2 = lam`, load-point amplitudes `g`, the ball
    /// first (`g[0] = -1/sqrt(m_b)`), a contact of stiffness `k` in compression and the truncated
    /// modes' static flexibility `residual` in series.
    /// `limit` is the model's time limit, s, within which the first maximum is looked for (it
    /// is the set-up's own: it depends on the ball's mass, `k1` and `k_s` only, all part of the
    /// set-up's key, [`super::shared::Key`]).
    pub fn new(lam: &[f64], g: &[f64], k: f64, residual: f64, ball_mass: f64, limit: f64) -> Self {
        let n = lam.len();
        let kappa = k / (1.0 + k * residual);
        let modes = coupled_modes(lam, g, kappa);
        let count = modes.mu.len() + 1;
        let (mut sigma, mut c, mut a): (Vec<f64>, Vec<f64>, Vec<f64>) =
            (Vec::with_capacity(count), Vec::with_capacity(count), Vec::with_capacity(count));
        // the ball arrives with unit speed: `v(0) = sqrt(m_b) e_0`; what the coupled modes do not
        // carry of it is a rigid motion the spring does not feel
        let mut rest = vec![0.0; n];
        rest[0] = ball_mass.sqrt();
        for (j, &mu) in modes.mu.iter().enumerate() {
            let shape = modes.shape(j);
            let ck = shape[0] * ball_mass.sqrt();
            let gz: f64 = shape.iter().zip(g).map(|(z, g)| z * g).sum();
            sigma.push(mu.max(0.0).sqrt());
            c.push(ck);
            a.push(-gz * ck / (1.0 + k * residual));
            for (r, s) in rest.iter_mut().zip(shape) {
                *r -= ck * s;
            }
        }
        let mut z = modes.shapes;
        z.reserve(n);
        let free = rest.iter().map(|r| r * r).sum::<f64>().sqrt();
        if free > 0.0 {
            sigma.push(0.0);
            z.extend(rest.iter().map(|r| r / free));
            c.push(free);
            a.push(0.0);
        }
        let n_modes = sigma.len();
        let total: f64 = a.iter().map(|a| a.abs()).sum();
        let dominant = (0..n_modes).max_by(|&i, &j| a[i].abs().total_cmp(&a[j].abs())).unwrap_or(0);
        let fastest = (0..n_modes).filter(|&i| a[i].abs() >= RATE_TAIL * total).map(|i| sigma[i]).fold(0.0, f64::max);
        let spacing = (PHASE_PER_SAMPLE / fastest).min(DOMINANT_PHASE_PER_SAMPLE / sigma[dominant]);
        let rotation = sigma.iter().map(|s| (s * spacing).sin_cos()).collect();
        let others = total - a[dominant].abs();
        let t_safe = if a[dominant] > others && sigma[dominant] > 0.0 {
            // (a little early, against the rounding of acos)
            0.999 * (others / a[dominant]).acos() / sigma[dominant]
        } else {
            0.0
        };
        let mut compression = Compression { n, sigma, z, c, a, k, t_safe, spacing, rotation, turn: None };
        compression.turn = compression.find_turn(limit);
        compression
    }

    /// `(Y_T', Y_T'')` per unit incident speed from each mode's phasor `(sin, cos)(s_k t)`.
    fn rate(&self, phasors: &[(f64, f64)]) -> (f64, f64) {
        let (mut d1, mut d2) = (0.0, 0.0);
        for ((a, s), &(sn, cs)) in self.a.iter().zip(&self.sigma).zip(phasors) {
            d1 += a * cs;
            d2 -= a * s * sn;
        }
        (d1, d2)
    }

    /// Advance every mode's phasor by `dt` (short rotations by their Taylor series, long ones
    /// by `sin_cos`).
    fn rotate(&self, phasors: &mut [(f64, f64)], dt: f64) {
        for (p, s) in phasors.iter_mut().zip(&self.sigma) {
            let x = s * dt;
            let (sn, cs) = small_sin_cos(x, series_terms(x.abs()));
            *p = (p.0 * cs + p.1 * sn, p.1 * cs - p.0 * sn);
        }
    }

    /// The first maximum of the compression, and the state there for an incident speed `v1`
    /// into `state`; `None` if the compression still grows at the model's time limit.
    /// `pieces = (h, sink)`: the force history is handed to `sink(h, (F0, F0'), (F1, F1'))` in
    /// pieces of at most `h` seconds (the tangential law follows it).
    pub fn at_max(&self, v1: f64, state: &mut State, pieces: Option<(f64, ForceSink)>) -> Option<AtMax> {
        let turn = self.turn.as_ref()?;
        let (t, ph) = (turn.t, &turn.phasors);
        if let Some((h, piece)) = pieces {
            self.pieces(v1, t, h, piece);
        }
        self.state_at(v1, t, ph, state);
        let yt = v1 * self.displacement(t, ph);
        Some(AtMax { t, yt, f: self.k * yt })
    }

    /// The first zero of the compression rate within `limit` seconds (per unit incident speed,
    /// so for every speed).
    fn find_turn(&self, limit: f64) -> Option<Turn> {
        let m = self.sigma.len();
        // no zero of the rate before `t_safe`: there the dominant mode's share still exceeds the
        // sum of all the others' amplitudes (`a_d cos(s_d t) > sum_(k != d) |a_k|`)
        let mut lo = self.t_safe;
        let mut ph = vec![(0.0, 1.0); m];
        if lo > 0.0 {
            for (p, s) in ph.iter_mut().zip(&self.sigma) {
                *p = (s * lo).sin_cos();
            }
        }
        // bracket: the first sample where the rate is no longer positive
        let mut d_lo = self.rate(&ph).0;
        let d_hi = loop {
            if lo > limit {
                return None;
            }
            for (p, &(s, c)) in ph.iter_mut().zip(&self.rotation) {
                *p = (p.0 * c + p.1 * s, p.1 * c - p.0 * s);
            }
            let d = self.rate(&ph).0;
            if d <= 0.0 {
                break d;
            }
            (lo, d_lo) = (lo + self.spacing, d);
        };
        let mut hi = lo + self.spacing;
        // Newton inside [lo, hi] from the secant estimate (bisection where it would leave), the
        // phasors carried along by short rotations
        let mut t = hi;
        let mut next = lo + self.spacing * d_lo / (d_lo - d_hi);
        for _ in 0..60 {
            self.rotate(&mut ph, next - t);
            t = next;
            let (d1, d2) = self.rate(&ph);
            if d1 > 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let step = if d2 < 0.0 { -d1 / d2 } else { f64::NAN };
            if step.abs() <= 1e-13 * t {
                break;
            }
            next = if t + step >= lo && t + step <= hi { t + step } else { 0.5 * (lo + hi) };
        }
        Some(Turn { t, phasors: ph })
    }

    /// `Y_T` per unit incident speed from the phasors at time `t`.
    fn displacement(&self, t: f64, phasors: &[(f64, f64)]) -> f64 {
        self.a.iter().zip(&self.sigma).zip(phasors).map(|((a, s), p)| if *s > 0.0 { a * p.0 / s } else { a * t }).sum()
    }

    /// The coordinates and rates at time `t` (phasors given) for an incident speed `v1`.
    fn state_at(&self, v1: f64, t: f64, phasors: &[(f64, f64)], state: &mut State) {
        let n = self.n;
        state.x[..n].fill(Pair::splat(0.0));
        for (k, ((c, s), p)) in self.c.iter().zip(&self.sigma).zip(phasors).enumerate() {
            let amp_q = v1 * c * if *s > 0.0 { p.0 / s } else { t };
            let amp_v = v1 * c * p.1;
            let shape = &self.z[k * n..(k + 1) * n];
            let amp = Pair::new(amp_q, amp_v);
            for (x, &z) in state.x[..n].iter_mut().zip(shape) {
                *x = x.add(Pair::splat(z).mul(amp));
            }
        }
    }

    /// The force history from first touch to `t_max` as pieces of at most `h` seconds.
    fn pieces(&self, v1: f64, t_max: f64, h: f64, piece: ForceSink) {
        let count = (t_max / h).ceil().max(1.0) as usize;
        let dt = t_max / count as f64;
        let m = self.sigma.len();
        let rot: Buf<(f64, f64)> = self.sigma.iter().map(|s| (s * dt).sin_cos()).collect();
        let mut ph = Buf::filled((0.0, 1.0), m);
        let force = |t: f64, ph: &[(f64, f64)]| {
            let k = self.k * v1;
            (k * self.displacement(t, ph), k * self.rate(ph).0)
        };
        let mut before = force(0.0, &ph);
        for i in 0..count {
            for (p, &(s, c)) in ph.iter_mut().zip(&rot) {
                *p = (p.0 * c + p.1 * s, p.1 * c - p.0 * s);
            }
            let t1 = (i + 1) as f64 * dt;
            let after = force(t1, &ph);
            piece(dt, before, after);
            before = after;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::error::Error;
    use crate::params::{Params, SolverKind};
    use crate::solve::modal::ModalModel;

    /// A time limit before maximum compression (found once, in the set-up) or before the end of
    /// the contact is an error, not a hang and not a result; a limit past the end changes nothing.
    #[test]
    fn a_limit_before_the_turn_or_the_end_is_an_error() {
        let mut p = Params::paper();
        p.numerics.solver = SolverKind::Modal;
        let m = ModalModel::new(&p).unwrap();
        let r = m.run().unwrap();
        let t_max = r.t_max_compression_s;
        assert!(t_max > 0.0 && t_max < r.tau_s, "{t_max} {}", r.tau_s);
        for (limit, fails) in [(0.2 * t_max, true), (0.5 * (t_max + r.tau_s), true), (2.0 * r.tau_s, false)] {
            let mut short = m.clone();
            short.impact.time_limit_s = limit;
            match short.run() {
                Err(Error::ImpactDidNotEnd { limit_s }) => assert!(fails && limit_s == limit, "limit {limit}"),
                Ok(again) => {
                    assert!(!fails, "limit {limit} gave a result");
                    assert_eq!(format!("{again:?}"), format!("{r:?}"));
                }
                Err(e) => panic!("limit {limit}: {e}"),
            }
        }
    }
}
