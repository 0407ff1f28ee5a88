//! The hand (`--grip hand`): springs and dampers spread over the grip length from the butt,
//! their share of each node, their part in the explicit solver's kick, and the damped free
//! racket after the impact (stepped on: a damped racket has no modal closed form).

use crate::error::Result;
use crate::model::basis::Basis;
use crate::model::beam::Beam;
use crate::params::{Grip, Params, Variants};
use crate::solve::fd::stepper::Stepper;
use crate::solve::fd::{FdModel, POLL_STEPS};

impl Stepper {
    /// Energy stored in the hand's springs plus what its dampers dissipated, J.
    pub fn hand_energy(&self, hand: &[(f64, f64)]) -> f64 {
        self.hand_loss + 0.5 * hand.iter().zip(&self.y).map(|((k, _), y)| k * y * y).sum::<f64>()
    }

    /// The kick with a hand: springs `-k y` at the new positions and dampers `-c v` taken
    /// implicitly (trapezoidal in `v`, so any damping is stable), the damper loss and the hand's
    /// impulse integrated by the trapezoidal rule.
    pub(super) fn kick_held(&mut self, dt: f64, f: f64, model: &FdModel) -> (f64, f64) {
        let half = 0.5 * dt;
        self.kick_ball_and_twist(half, f, model);
        let basis = &model.impact.basis;
        let [j0, j1] = model.impact.coupling.load.nodes;
        let [w0, w1] = model.impact.coupling.load.weights;
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
}

impl FdModel {
    /// The held racket after separation, stepped on from `st` at time `t` (s), `steps` into the
    /// impact, until `t_post`: the peak bending PE (J) up to `t_window` and whether the frame
    /// meets the ball again.
    pub(super) fn held_after_impact(
        &self,
        st: &Stepper,
        (t, steps): (f64, usize),
        t_window: f64,
        t_post: f64,
    ) -> Result<(f64, bool)> {
        let beam = self.beam();
        let dt = self.dt;
        let cp = &self.impact.coupling;
        let mut s2 = st.clone();
        let (mut peak, mut meets) = (beam.bending_energy(&s2.y), false);
        let mut t2 = t;
        // (the steps of the whole impact, for the progress told from inside it)
        let total = steps as f64 + (t_post - t) / dt;
        let mut k: usize = 0;
        while t2 < t_post {
            if k % POLL_STEPS == POLL_STEPS - 1 {
                crate::control::poll((steps + k) as f64 / total)?;
            }
            k += 1;
            let pe = s2.drift(dt, &self.impact.basis.pad.kappa);
            s2.kick(dt, 0.0, self);
            t2 += dt;
            if t2 <= t_window {
                peak = peak.max(pe);
            }
            meets |= cp.compression(s2.ball.y, &s2.y, s2.th) > 0.0;
        }
        Ok((peak, meets))
    }
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
pub(super) fn hand_per_node(beam: &Beam, v: &Variants) -> Vec<(f64, f64)> {
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
