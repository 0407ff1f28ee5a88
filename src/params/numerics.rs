//! Discretisation and time stepping: the segment count, the load rule, the time step and the
//! solver.

use serde::{Deserialize, Serialize};

use super::choice::choice_enum;
use super::keys;
use crate::error::{Error, Result};

pub use super::spec::{MAX_SEGMENTS, MIN_SEGMENTS};

choice_enum! {
    /// How the contact force is applied to the discrete beam (SPEC.md section 1, Contact).
    LoadRule (default Hat) {
        Node = "node": "The paper's scheme: the whole force on the node nearest x (ties go to the higher index)",
        Hat = "hat": "Linear (hat) sharing between the two nodes around x; converges as O(N^-2)",
    }
}

choice_enum! {
    /// Which solver integrates the impact.
    SolverKind (default Fd) {
        Fd = "fd": "Explicit finite differences in time (velocity Verlet), the reference",
        Modal = "modal": "Modal superposition with exact modal propagation and a contact-sized step",
    }
}

/// Discretisation and time stepping.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Numerics {
    /// Number of beam segments `N` (N+1 nodes); 4 <= N <= 400. Paper: 39.
    pub segments: usize,
    /// Load rule; `node` is the paper's, `hat` the default for users' impacts.
    pub load: LoadRule,
    /// Time step, s; `None` picks a converged default. Must be finite, > 0 and below the
    /// stability limit `2 / omega_max` (checked when the beam is built).
    pub dt: Option<f64>,
    /// The solver: `fd` (explicit, the reference) or `modal`.
    #[serde(default)]
    pub solver: SolverKind,
}

impl Default for Numerics {
    fn default() -> Self {
        Numerics { segments: 39, load: LoadRule::Hat, dt: None, solver: SolverKind::Fd }
    }
}

impl Numerics {
    /// The paper's numerics: N = 39 with the force on the nearest node.
    pub fn paper() -> Self {
        Numerics { segments: 39, load: LoadRule::Node, dt: None, solver: SolverKind::Fd }
    }

    /// Check the discretisation (the dt stability limit is checked when the beam is built).
    pub fn validate(&self) -> Result<()> {
        check_segments(self.segments)?;
        if let Some(dt) = self.dt {
            keys::DT.positive(dt)?;
        }
        Ok(())
    }
}

/// Check a number of beam segments.
pub fn check_segments(segments: usize) -> Result<()> {
    if !(MIN_SEGMENTS..=MAX_SEGMENTS).contains(&segments) {
        return Err(Error::invalid(
            keys::SEGMENTS.key,
            segments,
            format!("{} must satisfy {MIN_SEGMENTS} <= N <= {MAX_SEGMENTS}", keys::SEGMENTS.what),
        ));
    }
    Ok(())
}
