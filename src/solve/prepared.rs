//! The prepared impact, the problem apart from the method: validated parameters, the discrete
//! beam and its modes, the contact law, where the force acts, the tangential contact of an
//! oblique or spinning ball, and how long the contact may last. Both beam solvers start from
//! it ([`crate::solve::fd::FdModel`] adds its time step and the hand, [`crate::solve::modal::ModalModel`]
//! its retained modes and step tables); what each method needs of its own is prepared there.

use std::sync::Arc;

use crate::error::{Error, Result};
use crate::model::basis::Basis;
use crate::model::beam::Beam;
use crate::model::contact::{Contact, ContactLaw};
use crate::model::coupling::Coupling;
use crate::model::tangential::{Setup, MAX_TANGENTIAL_STEPS};
use crate::params::Params;
use crate::solve::oblique;

/// The impact must end within this many compression half-periods `pi sqrt(m_b / k_series)`.
pub const IMPACT_TIME_LIMIT_HALF_PERIODS: f64 = 20.0;

/// One impact prepared for a beam solver (the solver's own set-up aside).
#[derive(Debug, Clone)]
pub struct PreparedImpact {
    /// The parameters of the normal impact (for an oblique ball, those given with `v1` the
    /// normal speed `v1 cos(angle)`).
    pub params: Params,
    /// The tangential contact of an oblique or spinning ball (none at normal incidence).
    pub oblique: Option<Setup>,
    /// The contact law.
    pub contact: Contact,
    /// Where the force acts and how the contact point is tied to the frame.
    pub coupling: Coupling,
    /// Fundamental (first flexible) frequency of the free beam, Hz.
    pub f1_hz: f64,
    /// The contact phase must end within this simulated time, s (a guard, not physics).
    pub time_limit_s: f64,
    /// The racket's modes (shared by every impact on the same racket).
    pub basis: Arc<Basis>,
}

impl PreparedImpact {
    /// Validate the parameters, discretise the racket (its modes from the per-racket cache),
    /// place the load and set up the tangential contact; refuse a tangential contact that would
    /// need more steps than [`MAX_TANGENTIAL_STEPS`] within the time limit.
    pub fn new(given: &Params) -> Result<Self> {
        given.validate()?;
        // the normal impact, stepped as at normal incidence at the normal speed
        let params = oblique::normal_part(given);
        let basis = Basis::of(&params.racket, params.numerics.segments);
        let contact = Contact::of(&params);
        let coupling = Coupling::new(basis.beam.load_point(params.impact.x, params.numerics.load), params.impact.r);
        let f1_hz = basis.omega[0] / (2.0 * std::f64::consts::PI);
        let time_limit_s = time_limit(&params, &contact);
        let oblique = Setup::of(given, &basis.beam, coupling.load.x_load);
        if let Some(setup) = &oblique {
            let steps = setup.steps_within(time_limit_s);
            if steps.is_nan() || steps > MAX_TANGENTIAL_STEPS {
                return Err(Error::TooManyTangentialSteps { steps, limit: MAX_TANGENTIAL_STEPS });
            }
        }
        Ok(PreparedImpact { params, oblique, contact, coupling, f1_hz, time_limit_s, basis })
    }

    /// The discrete beam.
    pub fn beam(&self) -> &Beam {
        &self.basis.beam
    }
}

/// The simulated-time limit of the contact phase, s.
fn time_limit(p: &Params, contact: &Contact) -> f64 {
    IMPACT_TIME_LIMIT_HALF_PERIODS * std::f64::consts::PI * (p.ball.mass / contact.compression_stiffness()).sqrt()
}
