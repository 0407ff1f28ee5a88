//! The impact solvers, one trait ([`Solver`]) and one dispatcher ([`simulate`]):
//!
//! - [`fd`]: velocity-Verlet time stepping of the lumped beam (the reference), with the energy
//!   ledger, the hand grip and the time series;
//! - [`modal`]: modal superposition with exact modal propagation and a contact-sized step;
//! - [`rigid`]: the rigid racket in closed form (`--frame rigid`).
//!
//! Both beam solvers start from the solver-neutral [`PreparedImpact`] ([`prepared`]: validated
//! parameters, beam, contact, coupling, tangential set-up). The outcome types ([`ImpactResult`],
//! with its field table and its checks, and the time series) are in [`outcome`]; the time
//! series is recorded by an observer (`observer`) the stepping loop is generic over.
//! Everything physical (the contact law, the beam and its modes, the coupling of the contact
//! point to the frame) comes from [`crate::model`].

pub mod fd;
mod hermite;
pub mod modal;
pub mod oblique;
pub(crate) mod observer;
pub mod outcome;
pub mod prepared;
pub mod rigid;
pub mod swing;

use crate::error::Result;
use crate::params::{Frame, Params, SolverKind};

pub use fd::{hand_damping_ratio, FdModel};
pub use modal::{ModalModel, Resolution};
pub use outcome::{ImpactResult, SeriesOptions, SeriesRow, ENERGY_ERROR_LIMIT};
pub use prepared::PreparedImpact;
pub use rigid::Rigid;

/// An impact solver: prepared once from the parameters (validated, discretised, the step
/// chosen), then run.
pub trait Solver: Sized {
    /// Validate the parameters and prepare the impact.
    fn prepare(params: &Params) -> Result<Self>;

    /// Run the impact.
    fn run(&self) -> Result<ImpactResult>;
}

/// Prepare and run one impact with the solver `S`; a result whose energy error exceeds the
/// limit is an error, whichever solver made it ([`ENERGY_ERROR_LIMIT`]).
/// The impact counts itself in the run's progress ([`crate::control`]), done or failed.
pub fn solve<S: Solver>(params: &Params) -> Result<ImpactResult> {
    crate::control::impact_begins();
    // (a cancelled run starts no impact)
    crate::control::poll(0.0)?;
    let r = S::prepare(params).and_then(|s| s.run());
    crate::control::impact_done();
    let r = r?;
    r.check_energy()?;
    Ok(r)
}

/// Validate, prepare and run one impact with the solver (and model variant) the parameters name.
pub fn simulate(params: &Params) -> Result<ImpactResult> {
    if params.variants.frame == Frame::Rigid {
        return solve::<Rigid>(params);
    }
    match params.numerics.solver {
        SolverKind::Fd => solve::<FdModel>(params),
        SolverKind::Modal => solve::<ModalModel>(params),
    }
}
