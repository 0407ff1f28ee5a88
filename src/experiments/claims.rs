//! A paper claim as an experiment carries it: the claim's id (its row in
//! `golden/paper_claims.csv`, which holds the sentence, the paper's value and the tolerance)
//! and how we compute our number for it. [`crate::report`] collects them from the registry.
//! The claims table itself (the rows of that file, their tolerances and expected verdicts) is
//! read here, below the report, so that experiments that sample the claims (`robustness`) need
//! nothing from the report.

use serde::Deserialize;

use super::Context;
use crate::error::{Error, Result};

/// The claims file, compiled in.
pub const CLAIMS_CSV: &str = include_str!("../../golden/paper_claims.csv");

/// How a tolerance is applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ToleranceKind {
    /// |ours - paper| <= tolerance |paper|.
    Relative,
    /// |ours - paper| <= tolerance (for claims of "about zero").
    Absolute,
}

/// Reproduced or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// Within tolerance.
    Reproduced,
    /// Outside tolerance (explained in the report).
    Differs,
}

impl Verdict {
    /// The word used in the report and the claims file.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::Differs => "differs",
        }
    }
}

/// Smallest relative tolerance: the paper's unstated numerics (time step, rounding of g and of
/// the drop height) are worth this much.
pub const MIN_REL_TOLERANCE: f64 = 0.005;
/// Smallest relative tolerance for values the paper itself calls approximate ("about", "~").
pub const APPROXIMATE_REL_TOLERANCE: f64 = 0.10;

/// One row of `golden/paper_claims.csv`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Claim {
    /// Unique id; also selects the computation.
    pub id: String,
    /// The experiment (figure) the claim belongs to.
    pub experiment: String,
    /// The claim in words.
    pub claim: String,
    /// Where the paper says it.
    pub source: String,
    /// Unit of `paper` and of ours.
    pub unit: String,
    /// The paper's value exactly as printed (its last digit sets the tolerance).
    pub paper: String,
    /// True where the paper calls the value approximate ("about", "~", "typically").
    pub approximate: bool,
    /// For claims of "about zero": the absolute tolerance; otherwise empty.
    pub abs_tolerance: Option<f64>,
    /// The verdict we expect (pinned).
    pub expected: Verdict,
    /// Why it differs, or how it is computed (one line; shown in the report).
    pub note: String,
}

impl Claim {
    /// The paper's value as a number.
    pub fn paper_value(&self) -> Result<f64> {
        self.paper.parse().map_err(|_| Error::invalid("paper", &self.paper, format!("claim {}: not a number", self.id)))
    }

    /// The tolerance within which we call the claim reproduced: an absolute bound for claims of
    /// "about zero"; otherwise half a unit of the last printed digit relative to the value, at
    /// least [`MIN_REL_TOLERANCE`], or [`APPROXIMATE_REL_TOLERANCE`] for approximate values.
    pub fn tolerance(&self) -> Result<(ToleranceKind, f64)> {
        if let Some(a) = self.abs_tolerance {
            return Ok((ToleranceKind::Absolute, a));
        }
        let v = self.paper_value()?;
        let decimals = self.paper.split_once('.').map(|(_, d)| d.len()).unwrap_or(0) as i32;
        let half_unit = 0.5 * 10f64.powi(-decimals) / v.abs();
        let floor = if self.approximate { APPROXIMATE_REL_TOLERANCE } else { MIN_REL_TOLERANCE };
        Ok((ToleranceKind::Relative, half_unit.max(floor)))
    }
}

/// Parse the compiled-in claims.
pub fn claims() -> Result<Vec<Claim>> {
    let mut rdr = csv::Reader::from_reader(CLAIMS_CSV.as_bytes());
    rdr.deserialize()
        .map(|r| r.map_err(|e| Error::Config { path: "golden/paper_claims.csv".into(), message: e.to_string() }))
        .collect()
}

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
