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
//! come from the closed-form modal solution of the discrete beam ([`FreeVibration`](crate::model::free::FreeVibration)), whose
//! modes are computed once per racket and cached ([`Basis`](crate::model::basis::Basis)). A time series, when asked for, is
//! recorded by an observer (`solve::observer`) and extended by stepping on.
//!
//! Files: this one prepares the explicit scheme on the [`PreparedImpact`] (the time step, the
//! work limit, the hand's springs and dampers per node); `integrate` runs it,
//! `stepper` holds the state and the Verlet steps, `ledger` the energy ledger, `hand` the hand
//! grip.

mod hand;
mod integrate;
mod ledger;
mod stepper;

use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::model::contact::ContactLaw;
use crate::params::{Grip, Params};
use crate::solve::observer::{Plain, Sampler};
use crate::solve::outcome::{ImpactResult, SeriesOptions, SeriesRow};
use crate::solve::prepared::{PreparedImpact, IMPACT_TIME_LIMIT_HALF_PERIODS};
use crate::solve::Solver;

pub use hand::hand_damping_ratio;
use hand::hand_per_node;

/// Fraction of the stability limit used by the default time step.
pub const DEFAULT_DT_FRACTION: f64 = 0.9;
/// The default step also resolves the contact: at most this many radians of the stiffest
/// contact oscillation per step.
pub const DEFAULT_CONTACT_PHASE_PER_STEP: f64 = 2.0e-3;
/// Refuse parameters whose expected run (two rigid-contact half-periods plus the post-impact
/// window of two fundamental periods) needs more node-steps than this (about 15 s here).
pub const MAX_NODE_STEPS: f64 = 1.0e9;
/// Steps between two calls of the run's hook ([`crate::control::poll`]: cancellation and the
/// progress inside an impact), a power of two; about a millisecond on 40 nodes.
pub(crate) const POLL_STEPS: usize = 1 << 10;

/// An impact prepared for the explicit solver: the prepared impact, the time step and the hand.
#[derive(Debug, Clone)]
pub struct FdModel {
    /// The impact itself (parameters, beam, contact, coupling, tangential set-up).
    pub impact: PreparedImpact,
    /// Stability limit of the explicit scheme, s.
    pub dt_limit: f64,
    /// The time step in use, s.
    pub dt: f64,
    /// The hand (`--grip hand`): stiffness (N/m) and damping (N s/m) at each node; empty for
    /// the free racket.
    hand: Vec<(f64, f64)>,
    /// `1 / m_b`, 1/kg: the ball's acceleration per unit force.
    inv_ball_mass: f64,
    /// `r / I_x`, 1/(kg m): the twist's angular acceleration per unit force.
    twist_per_force: f64,
}

impl FdModel {
    /// The discrete beam.
    pub fn beam(&self) -> &Beam {
        self.impact.beam()
    }

    /// Validate the parameters, prepare the impact and choose (or check) the time step.
    pub fn new(params: &Params) -> Result<Self> {
        let impact = PreparedImpact::new(params)?;
        let params = &impact.params;
        let (basis, contact, coupling, f1_hz) = (&impact.basis, &impact.contact, &impact.coupling, impact.f1_hz);
        let beam = &basis.beam;
        let v = &params.variants;
        let hand = if v.grip == Grip::Hand { hand_per_node(beam, v) } else { Vec::new() };
        // Weyl: the contact spring adds at most k_c |g|^2 to the largest eigenvalue, where g is
        // the mass-normalised coupling vector of the ball, the load nodes and the twist.
        let g2 = coupling.mobility(params.ball.mass, &beam.mass, params.racket.ix);
        let lam_max = basis.lam.last().copied().unwrap_or(0.0);
        // the hand adds at most its largest stiffness per mass to the top eigenvalue
        let hand_max = hand.iter().zip(&beam.mass).map(|((k, _), m)| k / m).fold(0.0, f64::max);
        let omega_max = (lam_max + hand_max + contact.max_stiffness() * g2).sqrt();
        let dt_limit = 2.0 / omega_max;
        let dt = match params.numerics.dt {
            Some(dt) => {
                if dt >= dt_limit {
                    return Err(Error::invalid(
                        crate::params::keys::DT.key,
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
        let t_expected = 2.0 * impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS + 2.0 / f1_hz;
        let steps = t_expected / dt;
        let work = steps * beam.nodes() as f64;
        if !(dt.is_finite() && dt > 0.0 && f1_hz.is_finite() && f1_hz > 0.0 && work <= MAX_NODE_STEPS) {
            if let Some(user_dt) = params.numerics.dt {
                return Err(Error::invalid(
                    crate::params::keys::DT.key,
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
        let (inv_ball_mass, twist_per_force) = (1.0 / params.ball.mass, params.impact.r / params.racket.ix);
        Ok(FdModel { impact, dt_limit, dt, hand, inv_ball_mass, twist_per_force })
    }

    /// The steps the impact is expected to take: the contact (two rigid-contact half-periods,
    /// as the time limit counts them) and, for a racket held in the hand, the window after it
    /// (two fundamental periods, stepped too; a free racket's is told in closed form). What the
    /// work estimate counts (`study::work`) and the progress told from inside an impact.
    pub fn expected_steps(&self) -> (f64, f64) {
        let contact = 2.0 * self.impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS / self.dt;
        let held = if self.hand.is_empty() { 0.0 } else { 2.0 / self.impact.f1_hz / self.dt };
        (contact, held)
    }

    /// Run the impact.
    pub fn run(&self) -> Result<ImpactResult> {
        self.integrate(&mut Plain)
    }

    /// Run the impact and record the time series.
    pub fn run_with_series(&self, opts: SeriesOptions) -> Result<(ImpactResult, Vec<SeriesRow>)> {
        let mut sampler = Sampler::new(opts, self.dt);
        let result = self.integrate(&mut sampler)?;
        Ok((result, sampler.rows))
    }
}

impl Solver for FdModel {
    fn prepare(params: &Params) -> Result<Self> {
        FdModel::new(params)
    }

    fn run(&self) -> Result<ImpactResult> {
        FdModel::run(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_impact_that_does_not_end_in_time_is_an_error_not_a_hang() {
        let mut model = FdModel::new(&Params::paper()).unwrap();
        model.impact.time_limit_s = 1.0e-3;
        let msg = model.run().unwrap_err().to_string();
        assert!(msg.starts_with("impact did not end within 1.0000e-3 s"), "{msg}");
    }

    #[test]
    fn tiny_time_step_is_refused_rather_than_run_for_hours() {
        let mut p = Params::paper();
        p.numerics.dt = Some(1e-14);
        let msg = FdModel::new(&p).unwrap_err().to_string();
        assert!(msg.starts_with("invalid dt = ") && msg.contains("steps"), "{msg}");
    }

    #[test]
    fn a_step_at_the_stability_limit_is_caught_by_the_energy_guard() {
        let mut p = Params::paper();
        let limit = FdModel::new(&p).unwrap().dt_limit;
        p.numerics.dt = Some(limit * 0.9999);
        match crate::solve::simulate(&p) {
            Err(Error::EnergyDrift { error, .. }) => assert!(error > crate::solve::ENERGY_ERROR_LIMIT),
            Ok(r) => assert!(r.energy_error <= crate::solve::ENERGY_ERROR_LIMIT, "{r:?}"),
            Err(e) => panic!("unexpected error {e}"),
        }
    }

    #[test]
    fn unstable_time_step_is_refused() {
        let mut p = Params::paper();
        let limit = FdModel::new(&p).unwrap().dt_limit;
        p.numerics.dt = Some(limit * 1.01);
        let msg = FdModel::new(&p).unwrap_err().to_string();
        assert!(msg.starts_with("invalid dt = ") && msg.contains("stability limit"), "{msg}");
    }
}
