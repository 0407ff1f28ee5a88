//! A paper claim as an experiment carries it: the claim's id (its row in
//! `golden/paper_claims.csv`, which holds the sentence, the paper's value and the tolerance)
//! and how we compute our number for it. [`crate::report`] collects them from the registry.

use super::Context;
use crate::error::Result;

/// Our numbers for one claim.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ours {
    /// Computed as the paper did (N = 39 node scheme, read off as a reader would).
    pub value: f64,
    /// The value at the nearest node, where the claim is read off between nodes.
    pub nearest_node: Option<f64>,
    /// The converged value (`hat` load, N = 320), where numerics matter.
    pub converged: Option<f64>,
}

impl Ours {
    /// All three numbers.
    pub fn new(value: f64, nearest_node: Option<f64>, converged: Option<f64>) -> Self {
        Ours { value, nearest_node, converged }
    }

    /// A value with neither a nearest-node nor a converged counterpart.
    pub fn plain(value: f64) -> Result<Self> {
        Ok(Ours::new(value, None, None))
    }
}

/// One claim of the paper that an experiment checks.
#[derive(Clone, Copy)]
pub struct PaperClaim {
    /// The claim's id in `golden/paper_claims.csv`.
    pub id: &'static str,
    /// Our numbers for it, on the given racket (the report passes the paper's).
    pub ours: fn(&Context) -> Result<Ours>,
}

impl std::fmt::Debug for PaperClaim {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PaperClaim").field("id", &self.id).finish()
    }
}
