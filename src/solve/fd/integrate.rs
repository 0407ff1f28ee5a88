//! One impact by the explicit solver: the contact phase stepped with the phase switch at the
//! interpolated maximum of `Y_T` and the separation at its first zero in expansion, then the
//! result from the free vibration in closed form (or stepped on, for a held racket), then, for
//! a recorded time series, the free racket stepped on to the series' end.

use crate::error::{Error, Result};
use crate::model::contact::{ContactLaw, ContactState, Phase};
use crate::model::free::FreeVibration;
use crate::model::tangential::ForcePiece;
use crate::solve::fd::ledger::Motion;
use crate::solve::fd::stepper::Stepper;
use crate::solve::fd::{FdModel, POLL_STEPS};
use crate::solve::hermite::Hermite;
use crate::solve::oblique::Follower;
use crate::solve::observer::Observer;
use crate::solve::outcome::ImpactResult;
use crate::solve::outcome::ENERGY_ERROR_LIMIT;

/// Where the contact phase left an impact.
struct Separated {
    st: Stepper,
    phase: Phase,
    cs: ContactState,
    /// Time (s) and steps at the end of the step that holds the separation.
    t: f64,
    step: usize,
    /// Separation time (s) and twist angle there (rad).
    tau: f64,
    theta_end: f64,
    /// Time of maximum compression (s) and the ball's maximum compression (m).
    t_max: f64,
    y0: f64,
    /// Peak force (N) and the largest deviations of the energy (J) and the momentum (kg m/s).
    peak_force: f64,
    energy_dev: f64,
    momentum_dev: f64,
    /// The tangential contact of an oblique or spinning ball.
    tangential: Follower,
}

impl FdModel {
    /// Run the impact, reporting each step to `obs`.
    pub(super) fn integrate<O: Observer>(&self, obs: &mut O) -> Result<ImpactResult> {
        let mut sep = self.contact_phase(obs)?;
        // the paper's window: two fundamental periods from the separation time itself
        let t_window = sep.tau + 2.0 / self.impact.f1_hz;
        let t_post = t_window.max(obs.t_end());
        let result = self.result(&sep, t_window, t_post)?;
        // A time series is extended by stepping the free racket on (the result above does
        // not depend on it).
        if O::RECORDS {
            self.extend(&mut sep, t_post, obs);
        }
        Ok(result)
    }

    /// Step the contact phase to the separation.
    fn contact_phase<O: Observer>(&self, obs: &mut O) -> Result<Separated> {
        let p = &self.impact.params;
        let (mb, v1) = (p.ball.mass, p.impact.v1);
        let beam = self.beam();
        let dt = self.dt;
        let cp = &self.impact.coupling;
        let e0 = 0.5 * mb * v1 * v1;
        let p0 = mb * v1;
        let t_limit = self.impact.time_limit_s;

        let mut st = Stepper::new(self.impact.basis.pad.lanes, v1);
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
        let mut step: usize = 0;
        let mut tangential = Follower::new(self.impact.oblique.as_ref());
        // the force and its rate at the start of the step (the force history of the tangential
        // contact: a cubic through both over each step)
        let mut force_prev = (0.0, self.impact.contact.compression_stiffness() * v1);
        let yt_of = |st: &Stepper| cp.compression(st.ball.y, &st.y, st.th);
        let motion =
            |t: f64, st: &Stepper, force: f64| Motion { t, force, y_ball: st.ball.y, y_total: yt_of(st), theta: st.th };
        obs.observe(0, || self.ledger(&st, phase, &cs, 0.0, 0.0).row(e0, motion(0.0, &st, cs.force)));
        let (contact_steps, held_steps) = self.expected_steps();

        loop {
            if t > t_limit {
                return Err(Error::ImpactDidNotEnd { limit_s: t_limit });
            }
            if step % POLL_STEPS == POLL_STEPS - 1 {
                crate::control::poll(step as f64 / (contact_steps + held_steps))?;
            }
            let (th_prev, om_prev) = (st.th, st.om);
            let pe = st.drift(dt, &self.impact.basis.pad.kappa);
            let yt = yt_of(&st);
            cs = self.impact.contact.state(yt, phase, cs.guess())?;
            let (mut ke, mut mom) = st.kick(dt, cs.force, self);
            mom += st.hand_impulse;
            let mut ytd = cp.compression(st.ball.v, &st.v, st.om);
            if phase == Phase::Compression && ytd <= 0.0 {
                // The maximum of Y_T lies in this step: switch to the expansion law there.
                let (s_max, yt_max) = Hermite { h: dt, p0: yt_prev, m0: ytd_prev, p1: yt, m1: ytd }.max();
                t_max = t + s_max * dt;
                y0 = self.impact.contact.ball_compression_at_max(yt_max);
                phase = Phase::Expansion { y0 };
                let f_old = cs.force;
                cs = self.impact.contact.state(yt, phase, (1.0, 1.0))?;
                st.correct_force(dt, cs.force - f_old, self);
                ytd = cp.compression(st.ball.v, &st.v, st.om);
                ke = beam.kinetic_energy(&st.v);
                mom = beam.momentum(&st.v) + st.hand_impulse;
            }
            t += dt;
            step += 1;
            peak_force = peak_force.max(cs.force);
            let l = self.ledger(&st, phase, &cs, pe, ke);
            energy_dev = energy_dev.max((l.total() - e0).abs());
            momentum_dev = momentum_dev.max((mb * st.ball.v + mom - p0).abs());
            obs.observe(step, || l.row(e0, motion(t, &st, cs.force)));
            if matches!(phase, Phase::Expansion { .. }) && yt <= 0.0 {
                let s = Hermite { h: dt, p0: yt_prev, m0: ytd_prev, p1: yt, m1: ytd }.root();
                tangential.advance(|| ForcePiece::hermite(s * dt, force_prev, (0.0, 0.0)));
                let theta_end = Hermite { h: dt, p0: th_prev, m0: om_prev, p1: st.th, m1: st.om }.eval(s);
                let tau = t - dt + s * dt;
                return Ok(Separated {
                    st,
                    phase,
                    cs,
                    t,
                    step,
                    tau,
                    theta_end,
                    t_max,
                    y0,
                    peak_force,
                    energy_dev,
                    momentum_dev,
                    tangential,
                });
            }
            let force = (cs.force, self.impact.contact.stiffness(phase, &cs) * ytd);
            tangential.advance(|| ForcePiece::hermite(dt, force_prev, force));
            force_prev = force;
            yt_prev = yt;
            ytd_prev = ytd;
        }
    }

    /// The result: the ball is free; the racket keeps vibrating until `t_post` (s).
    fn result(&self, sep: &Separated, t_window: f64, t_post: f64) -> Result<ImpactResult> {
        let p = &self.impact.params;
        let (mb, v1, ix) = (p.ball.mass, p.impact.v1, p.racket.ix);
        let beam = self.beam();
        let e0 = 0.5 * mb * v1 * v1;
        let p0 = mb * v1;
        let (st, t, tau) = (&sep.st, sep.t, sep.tau);
        let e_a = -st.ball.v / v1;
        let f_rigid = beam.rigid_energy(&st.v) / e0;
        let e_racket = beam.kinetic_energy(&st.v) + beam.bending_energy(&st.y);
        let f_vib = e_racket / e0 - f_rigid;
        let f_spin = 0.5 * ix * st.om * st.om / e0;
        let f_ball = self.impact.contact.ball_loss(sep.y0) / e0;
        let f_hand = st.hand_energy(&self.hand) / e0;
        let (peak_pe, recontact) = if self.hand.is_empty() {
            self.after_impact(st, t - tau, t_post - t)
        } else {
            // a held racket is damped: no modal closed form, step it on
            self.held_after_impact(st, (t, sep.step), t_window, t_post)?
        };
        // (a search after the impact that a cancelled run cut short is no result)
        crate::control::poll(1.0)?;
        let (energy_err, momentum_err) = (sep.energy_dev / e0, sep.momentum_dev / p0);
        if energy_err > ENERGY_ERROR_LIMIT {
            return Err(Error::EnergyDrift { error: energy_err, limit: ENERGY_ERROR_LIMIT });
        }
        let mut result = ImpactResult {
            e_a,
            tau_s: tau,
            theta_end_deg: sep.theta_end.to_degrees(),
            f_ball,
            f_vib,
            f_vib_peak_pe: peak_pe / e0,
            f_spin,
            f_hand,
            f_rigid,
            f_ke_ball: e_a * e_a,
            peak_force_n: sep.peak_force,
            energy_error: energy_err,
            momentum_error: momentum_err,
            x_load_m: self.impact.coupling.load.x_load,
            t_max_compression_s: sep.t_max,
            y0_m: sep.y0,
            recontact,
            dt_s: self.dt,
            ..ImpactResult::ZERO
        };
        sep.tangential.complete(self.impact.oblique.as_ref(), &mut result, v1)?;
        result.check_finite()?;
        Ok(result)
    }

    /// Step the free racket on to `t_post` (s), reporting each step to `obs`.
    fn extend<O: Observer>(&self, sep: &mut Separated, t_post: f64, obs: &mut O) {
        let p = &self.impact.params;
        let (mb, v1) = (p.ball.mass, p.impact.v1);
        let e0 = 0.5 * mb * v1 * v1;
        let cp = &self.impact.coupling;
        let Separated { st, phase, cs, t, step, .. } = sep;
        while *t < t_post {
            let pe = st.drift(self.dt, &self.impact.basis.pad.kappa);
            let (ke, _) = st.kick(self.dt, 0.0, self);
            *t += self.dt;
            *step += 1;
            obs.observe(*step, || {
                let y_total = cp.compression(st.ball.y, &st.y, st.th);
                let at = Motion { t: *t, force: cs.force, y_ball: st.ball.y, y_total, theta: st.th };
                self.ledger(st, *phase, cs, pe, ke).row(e0, at)
            });
        }
    }

    /// The free vibration after separation, in closed form: the peak bending PE over the
    /// paper's window (two fundamental periods from separation) and whether the frame meets the
    /// ball again before `ahead` seconds from now. `st` is the state `lag` seconds after
    /// separation.
    fn after_impact(&self, st: &Stepper, lag: f64, ahead: f64) -> (f64, bool) {
        let basis = &self.impact.basis;
        let beam = &basis.beam;
        let cp = &self.impact.coupling;
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
            g.push(cp.at_load(phi));
        }
        let free = FreeVibration::new(&basis.omega, &q, &qd, &g);
        let peak = free.peak_pe(-lag, 2.0 / self.impact.f1_hz - lag);
        // the gap without the vibration is affine in time: ball minus rigid motion of the load point
        let r = cp.r;
        let flex0: f64 = g.iter().zip(&q).map(|(g, q)| g * q).sum();
        let flex_rate: f64 = g.iter().zip(&qd).map(|(g, v)| g * v).sum();
        let gap0 = st.ball.y - r * st.th - (cp.at_load(&st.y) - flex0);
        let rate = st.ball.v - r * st.om - (cp.at_load(&st.v) - flex_rate);
        (peak, free.meets_ball(gap0, rate, ahead))
    }
}
