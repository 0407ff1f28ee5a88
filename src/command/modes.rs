//! `modes`: the eigenfrequencies of the free racket and the nodes of its fundamental mode.

use super::{Control, Given, Kind, Opt, Request, Work};
use crate::diagnostic::Diagnostic;
use crate::error::{Error, Result};
use crate::intake::Sources;
use crate::model::beam::Beam;
use crate::params::Params;

/// The command.
pub const NAME: &str = "modes";

/// Its options.
pub const OPTIONS: &[Opt] =
    &[Opt::new("count", Kind::Count { lo: 1, hi: 20 }, Some("4"), "Number of flexible modes to list (at most N-1)")];

/// Why `modes` does not take the parameter `key`: the free racket's modes depend on its
/// length, mass, stiffness and segments alone ([`crate::params::keys::FREE_RACKET`]).
pub fn not_taken(key: &str) -> Option<&'static str> {
    (!crate::params::keys::FREE_RACKET.iter().any(|s| s.key == key))
        .then_some("the free racket's modes depend on its length, mass, stiffness and segments alone")
}

/// The modes asked for, checked.
#[derive(Debug, Clone)]
pub struct Modes {
    params: Params,
    count: usize,
    noted: Vec<Diagnostic>,
}

/// The free racket's modes.
#[derive(Debug, Clone)]
pub struct Moded {
    /// The parameters (the racket and its segments).
    pub params: Params,
    /// The first `count` flexible modes' frequencies, Hz.
    pub frequencies_hz: Vec<f64>,
    /// The nodes of the fundamental mode, m from the tip.
    pub mode1_nodes_m: Vec<f64>,
    /// The notes about what the modes do not use, then the racket's parameters outside their
    /// usual ranges.
    pub diagnostics: Vec<Diagnostic>,
}

impl Modes {
    /// The modes of the racket `sources` describe, `count` of them (at most N-1).
    pub fn new(sources: &Sources, given: &Given) -> Result<Modes> {
        let params = sources.params()?;
        let noted = sources.check_used(&[params])?;
        let n = params.numerics.segments;
        let count = given.count("count")?.unwrap_or(4) as usize;
        if count > n - 1 {
            return Err(Error::invalid("count", count, format!("must satisfy 1 <= count <= min(20, N-1 = {})", n - 1)));
        }
        Ok(Modes { params, count, noted })
    }
}

impl Request for Modes {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Moded;

    fn work(&self, _threads: usize) -> Option<Work> {
        None
    }

    fn run(self, _ctl: &Control) -> Result<Moded> {
        let n = self.params.numerics.segments;
        let beam = Beam::new(&self.params.racket, n);
        let modes = beam.modes();
        let frequencies_hz = (1..=self.count).map(|k| modes.frequency_hz(k)).collect();
        let mode1_nodes_m = modes.node_positions(1, &beam.x);
        let diagnostics =
            self.noted.into_iter().chain(crate::intake::diagnose::parameters([&self.params], &[])).collect();
        Ok(Moded { params: self.params, frequencies_hz, mode1_nodes_m, diagnostics })
    }
}

impl Moded {
    /// The JSON document of `modes --format json`.
    pub fn json(&self) -> Result<serde_json::Value> {
        let json = |e: serde_json::Error| Error::io("<json>", e);
        Ok(serde_json::json!({
            "frequencies_hz": self.frequencies_hz,
            "mode1_nodes_m": self.mode1_nodes_m,
            "segments": self.params.numerics.segments,
            "params": serde_json::to_value(self.params.racket).map_err(json)?,
            "diagnostics": serde_json::to_value(&self.diagnostics).map_err(json)?,
        }))
    }
}
