//! One impact as the `simulate` command and the Python package run it: the parameters from
//! their [`Sources`], the notes about what the impact does not use, the result, its
//! diagnostics, and the JSON document `simulate --format json` prints (which the Python
//! package's result object is).

use crate::diagnostic::Diagnostic;
use crate::error::{Error, Result};
use crate::params::Params;
use crate::solve::ImpactResult;

use crate::intake::Sources;

/// One impact, run.
#[derive(Debug, Clone)]
pub struct Single {
    /// Its parameters, validated.
    pub params: Params,
    /// Its result.
    pub result: ImpactResult,
    /// The notes about what it does not use, then the physics-validity checks of the run
    /// ([`crate::intake::diagnose::impact`]), in the order the command line prints them.
    pub diagnostics: Vec<Diagnostic>,
}

impl Single {
    /// Run the impact `sources` describe: a flag for an option it cannot honour is refused, a
    /// flag or config key of a property it does not exercise noted ([`Sources::check_used`]).
    pub fn run(sources: &Sources) -> Result<Single> {
        let params = sources.params()?;
        let noted = sources.check_used(&[params])?;
        let result = crate::solve::simulate(&params)?;
        Ok(Single::of(params, result, noted))
    }

    /// The impact `result` of `params`, with the notes `noted` made before it ran.
    pub fn of(params: Params, result: ImpactResult, noted: Vec<Diagnostic>) -> Single {
        let diagnostics = noted.into_iter().chain(crate::intake::diagnose::impact(&params, &result)).collect();
        Single { params, result, diagnostics }
    }

    /// The JSON document of `simulate --format json`: every result field
    /// ([`crate::render::impact::result_json`]), the parameters, the spin convention of an
    /// oblique or spinning ball, the first free-free frame frequency and the diagnostics.
    pub fn json(&self) -> Result<serde_json::Value> {
        let params = &self.params;
        let mut v = crate::render::impact::result_json(params, &self.result);
        v["params"] = serde_json::to_value(params).map_err(|e| Error::io("<json>", e))?;
        if !params.oblique.is_normal() {
            v["spin_convention"] = crate::render::impact::SIMULATE_SPIN_CONVENTION.into();
        }
        // (from the cached modes: the modal solver runs where the explicit one would refuse)
        v["f1_hz"] = first_frequency_hz(params).into();
        v["diagnostics"] = serde_json::to_value(&self.diagnostics).map_err(|e| Error::io("<json>", e))?;
        Ok(v)
    }
}

/// The free racket's first bending frequency on the impact's beam, Hz.
pub fn first_frequency_hz(params: &Params) -> f64 {
    crate::model::basis::Basis::of(&params.racket, params.numerics.segments).omega[0] / (2.0 * std::f64::consts::PI)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Overrides;

    #[test]
    fn the_document_has_every_field_the_parameters_and_the_notes() {
        let mut flags = Overrides::default();
        flags.set("mu", "0.3").unwrap();
        let s = Single::run(&Sources { flags, command: "simulate", ..Sources::default() }).unwrap();
        let v = s.json().unwrap();
        assert_eq!(v["e_a"].as_f64(), Some(s.result.e_a));
        assert_eq!(v["params"]["strings"]["ks"].as_f64(), Some(s.params.strings.ks));
        assert_eq!(v["diagnostics"][0]["field"], "mu", "friction at normal incidence is noted");
        assert!(v.get("spin_convention").is_none());
        assert!((v["f1_hz"].as_f64().unwrap() - 125.0).abs() < 5.0);
    }
}
