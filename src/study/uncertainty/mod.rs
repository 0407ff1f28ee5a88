//! `uncertainty`: one impact's result fields under uncertain inputs. Any numeric parameter is
//! varied by a distribution (`--vary ks=uniform:2e4:6e4`), the impact is run over a Saltelli
//! design ([`sensitivity`]) in parallel, and every numeric result field is
//! summarised: mean, sd, q05, q50, q95, and the first-order and total Sobol' index of each input
//! with bootstrap intervals.
//!
//! This file is the study (its plan, its runs, its diagnostics); [`write`] turns its outputs
//! into the JSON document, the CSV table and the text table.

mod write;

pub use write::{not_meaningful, summary_json};

use super::sensitivity::{self, Design, Summary};
use crate::diagnostic::{Diagnostic, Kind};
use crate::error::{Error, Result};
use crate::intake::Sources;
use crate::numfmt::quoted;
use crate::numfmt::{readable, sig};
use crate::params::spec::{Check, Values};
use crate::params::uncertainty::Dist;
use crate::params::{keys, Overrides, Params};
use crate::solve::outcome::{Get, FIELDS};
use crate::solve::simulate;

/// Base samples unless given (a power of two, as the Sobol' sequence likes).
pub const DEFAULT_SAMPLES: u64 = 256;

/// Fewest base samples whose Sobol' indices mean anything: their sampling error is of order
/// `1/sqrt(N)` (0.125 at 64), as large as the indices themselves below it, and q05/q95 of the
/// 2N independent runs rest on three runs or fewer beyond them.
pub const MIN_SAMPLES: u64 = 64;

/// The one-line warning for a design of `samples` base samples below [`MIN_SAMPLES`] (none at
/// or above it).
pub fn few_samples(samples: u64) -> Option<String> {
    (samples < MIN_SAMPLES).then(|| {
        format!(
            "samples = {samples} is below {MIN_SAMPLES} base samples: the Sobol' indices' sampling error, of order \
             1/sqrt(N), is then as large as the indices and q05/q95 rest on a few runs; the indices and \
             intervals are not meaningful at this count"
        )
    })
}

/// One varied input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Input {
    /// The parameter key.
    pub key: &'static str,
    /// Its distribution.
    pub dist: Dist,
}

/// Parse `KEY=DIST` and check it against the parameter's declaration and the base parameters:
/// a known, real-valued key whose every sample (the distribution's [`extent`](Dist::extent))
/// is a valid value.
pub fn parse_vary(text: &str, base: &Params) -> Result<Input> {
    let (key, dist) = text.split_once('=').unwrap_or((text, ""));
    let spec = keys::find(key.trim()).ok_or_else(|| {
        Error::invalid(
            "vary",
            text,
            format!("unknown parameter '{}' (known: {})", quoted(key), Overrides::KEYS.join(", ")),
        )
    })?;
    if spec.values != Values::Number {
        let numeric: Vec<&str> = keys::ALL.iter().filter(|s| s.values == Values::Number).map(|s| s.key).collect();
        return Err(Error::invalid(
            "vary",
            text,
            format!("only real-valued parameters can be varied ({})", numeric.join(", ")),
        ));
    }
    // KEY alone: the distribution declared with the parameter, if it has one
    let dist = match (dist.trim().is_empty(), spec.uncertainty) {
        (true, Some(u)) => u.dist,
        (true, None) => {
            let declared: Vec<&str> = keys::uncertain().map(|s| s.key).collect();
            return Err(Error::invalid(
                "vary",
                text,
                format!(
                    "give KEY=DIST, DIST uniform:LO:HI, normal:MEAN:SD or loguniform:LO:HI (KEY alone only for a \
                     parameter with a declared uncertainty: {})",
                    declared.join(", ")
                ),
            ));
        }
        (false, _) => Dist::parse(spec.key, dist)?,
    };
    let (lo, hi) = dist.extent();
    let unit = if spec.unit.is_empty() { String::new() } else { format!(" {}", spec.unit) };
    if let Check::Within(min, max) = spec.check {
        if lo < min || hi > max {
            return Err(Error::invalid(
                spec.key,
                dist.text(),
                format!(
                    "samples reach {}..{}{unit}; {} must satisfy {} <= {} <= {}{unit}",
                    sig(lo, 6),
                    sig(hi, 6),
                    spec.what,
                    readable(min),
                    spec.key,
                    readable(max)
                ),
            ));
        }
    }
    // a parameter checked by a rule of its own (the impact point, p, ...): both ends must pass it
    for v in [lo, hi] {
        let mut p = *base;
        let mut o = Overrides::default();
        o.set(spec.key, &v.to_string())?;
        o.apply(&mut p);
        p.validate().map_err(|e| {
            Error::invalid(spec.key, dist.text(), format!("samples reach {}{unit}, where {e}", sig(v, 6)))
        })?;
    }
    Ok(Input { key: spec.key, dist })
}

/// The study: base parameters, varied inputs and the design.
#[derive(Debug, Clone)]
pub struct Study {
    /// The parameters every run starts from.
    pub base: Params,
    /// The varied inputs, in the order given.
    pub inputs: Vec<Input>,
    /// The design.
    pub design: Design,
    /// The notes about what the run does not use (a flag of a property the impact does not
    /// exercise, a config key: [`crate::intake::Sources::check_used`]), first among its
    /// [`diagnostics`](Study::diagnostics); none unless the caller gives them.
    pub noted: Vec<Diagnostic>,
}

/// A result field summarised: its key, unit and value.
pub type OutputField = (&'static str, &'static str, fn(&crate::ImpactResult) -> f64);

/// One output's summary, named.
#[derive(Debug, Clone, PartialEq)]
pub struct Output {
    /// The result field (`e_a`).
    pub key: &'static str,
    /// Its unit.
    pub unit: &'static str,
    /// The summary.
    pub summary: Summary,
}

impl Study {
    /// Check the sample count first (nothing allocated before), then each `--vary` (known,
    /// real-valued, in range, given once).
    pub fn new(base: Params, varies: &[String], samples: u64, seed: u32) -> Result<Study> {
        if varies.is_empty() {
            return Err(Error::invalid("vary", "(none)", "give at least one --vary KEY=DIST"));
        }
        let design = Design::new(samples, varies.len(), seed)?;
        let mut inputs: Vec<Input> = Vec::with_capacity(varies.len());
        for text in varies {
            let input = parse_vary(text, &base)?;
            if inputs.iter().any(|i| i.key == input.key) {
                return Err(Error::invalid(
                    "vary",
                    text,
                    format!("{} is varied twice; vary each parameter once", input.key),
                ));
            }
            inputs.push(input);
        }
        let study = Study { base, inputs, design, noted: Vec::new() };
        study.check_each_input_is_read(varies)?;
        Ok(study)
    }

    /// The study `uncertainty --vary` runs (and the Python package's `uncertainty`): the sample
    /// count checked first, then the fixed parameters from `sources` (a key both fixed by a
    /// flag and varied is refused; a config file's value of a varied key is noted as unused),
    /// the solver the sweeps use unless given ([`crate::study::sweep::default_solver`]), the
    /// notes and refusals of [`Sources::check_used`] with that solver, and each input.
    pub fn from_sources(sources: &Sources, varies: &[String], samples: u64, seed: u32) -> Result<Study> {
        Design::new(samples, varies.len().max(1), 0)?; // the count first, before anything else
        let from_config = crate::intake::config_file(sources.config.as_deref())?;
        let given = sources.flags.clone().or(from_config.clone());
        let mut unused_in_config = Vec::new();
        for text in varies {
            let key = text.split_once('=').map_or(text.as_str(), |(k, _)| k).trim();
            if sources.flags.given().contains(&key) {
                return Err(Error::invalid(
                    "vary",
                    text,
                    format!("{key} is both fixed (--{key}) and varied; give one"),
                ));
            }
            if from_config.given().contains(&key) {
                unused_in_config.push(key);
            }
        }
        let mut noted = Vec::new();
        if let (Some(path), false) = (&sources.config, unused_in_config.is_empty()) {
            // a shared config file may set what this run draws: said once, not refused
            let sentence = format!(
                "config file {} sets {}, which --vary draws: the file's value is not used",
                path.display(),
                unused_in_config.join(", ")
            );
            noted.push(Diagnostic::new(Kind::NotUsed, "config", sentence));
        }
        let mut base = sources.params()?;
        if let Some(solver) = crate::study::sweep::default_solver(&given, &[]) {
            base.numerics.solver = solver;
        }
        // with the solver the runs use: --dt is refused with the modal one
        noted.extend(sources.check_used(&[base])?);
        let mut study = Study::new(base, varies, samples, seed)?;
        study.noted = noted;
        Ok(study)
    }

    /// Refuse an input the model does not read (as the same fixed flag is refused,
    /// [`crate::params::used`]), judged at the runs' upper draws (so that varying the angle
    /// makes the friction count), and a friction that the named string sets from its database
    /// entry (every run would use the string's value whatever was drawn).
    fn check_each_input_is_read(&self, varies: &[String]) -> Result<()> {
        let upper: Vec<f64> = self.inputs.iter().map(|i| i.dist.quantile(0.95)).collect();
        let probe = self.params_at(&upper)?;
        for (input, text) in self.inputs.iter().zip(varies) {
            // (drawing a property the impact does not exercise changes nothing: refused here
            // too, as a study of it would find every index zero)
            if let Some(unused) = keys::find(input.key).and_then(|spec| crate::params::used::unused(spec, &probe)) {
                return Err(Error::invalid("vary", text, format!("{} is {}", input.key, unused.why)));
            }
            if let Some(id) = crate::params::strings::sets(self.base.oblique.string, input.key) {
                return Err(Error::invalid(
                    "vary",
                    text,
                    format!("{} is set by string = {id} (data/strings); vary one or the other", input.key),
                ));
            }
        }
        Ok(())
    }

    /// Whether the runs are oblique or spinning (their oblique result fields are then outputs).
    fn is_oblique(&self) -> bool {
        !self.base.oblique.is_normal()
            || self.inputs.iter().any(|i| i.key == keys::ANGLE_DEG.key || i.key == keys::SPIN_RPM.key)
    }

    /// The result fields summarised: the numeric sweep columns (the losses of the named
    /// tangential mechanisms under a law that has them).
    pub fn output_fields(&self) -> Vec<OutputField> {
        let oblique = self.is_oblique();
        let losses = oblique && self.base.oblique.tangential != crate::params::TangentialLaw::Elastic;
        FIELDS
            .iter()
            .filter(|f| f.sweep && (oblique || !f.is_oblique()) && (losses || !f.is_law_only()))
            .filter_map(|f| match f.get {
                Get::Number(g) => Some((f.key, f.unit, g)),
                Get::Flag(_) => None,
            })
            .collect()
    }

    /// The parameters of one run with the input values `x`.
    pub fn params_at(&self, x: &[f64]) -> Result<Params> {
        let mut o = Overrides::default();
        for (input, v) in self.inputs.iter().zip(x) {
            o.set(input.key, &v.to_string())?;
        }
        let mut p = self.base;
        o.apply(&mut p);
        p.validate()?;
        Ok(p)
    }

    /// The parameters of run `k` of the design, drawn as [`Study::run`] draws them.
    pub fn params_of_run(&self, k: usize) -> Result<Params> {
        let x: Vec<f64> = self.design.point(k).iter().zip(&self.inputs).map(|(&u, i)| i.dist.quantile(u)).collect();
        self.params_at(&x)
    }

    /// The work of the study, estimated before it runs ([`crate::study::work`]).
    pub fn estimate(&self, threads: usize) -> crate::study::work::Estimate {
        crate::study::work::Estimate::of(self.design.runs() as u64, threads, |k| self.params_of_run(k as usize).ok())
    }

    /// Run the design (all cores) and summarise every output; `progress` gets the runs done.
    pub fn run(&self, progress: impl FnMut(usize)) -> Result<Vec<Output>> {
        let fields = self.output_fields();
        let dists: Vec<Dist> = self.inputs.iter().map(|i| i.dist).collect();
        let rows = sensitivity::run(
            &self.design,
            &dists,
            |x| {
                let r = simulate(&self.params_at(x)?)?;
                Ok(fields.iter().map(|(_, _, g)| g(&r)).collect())
            },
            progress,
        )?;
        let summaries = sensitivity::summarise_all(&self.design, &rows);
        Ok(fields.iter().zip(summaries).map(|(&(key, unit, _), summary)| Output { key, unit, summary }).collect())
    }

    /// The study's diagnostics: too few samples for the indices to mean anything
    /// ([`few_samples`]), its notes ([`Study::noted`]), its base parameters outside their
    /// usual ranges, but those drawn (their base value is not used: their draws are judged
    /// instead), and each input whose draws reach outside its usual range.
    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        let drawn: Vec<&str> = self.inputs.iter().map(|i| i.key).collect();
        let few = few_samples(self.design.samples() as u64).map(|s| Diagnostic::new(Kind::Unusual, "samples", s));
        let mut out: Vec<Diagnostic> = few.into_iter().collect();
        out.extend(self.noted.iter().cloned());
        out.extend(crate::intake::diagnose::parameters([&self.base], &drawn));
        for input in &self.inputs {
            let line = keys::find(input.key).and_then(|spec| spec.unusual_draws(&input.dist));
            out.extend(line.map(|s| Diagnostic::new(Kind::Unusual, input.key, s)));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn study(varies: &[&str], samples: u64) -> Result<Study> {
        let mut base = Params::default();
        base.numerics.solver = crate::params::SolverKind::Modal;
        Study::new(base, &varies.iter().map(|s| s.to_string()).collect::<Vec<_>>(), samples, 1)
    }

    #[test]
    fn bad_specs_are_one_line_refusals_naming_the_field_and_range() {
        let msg = |v: &[&str], n: u64| study(v, n).unwrap_err().to_string();
        assert!(msg(&["kz=uniform:1:2"], 8).starts_with("invalid vary = kz=uniform:1:2: unknown parameter 'kz'"));
        assert_eq!(msg(&["ks=uniform:5e4:2e4"], 8), "invalid ks = uniform:5e4:2e4: the range needs LO < HI");
        assert_eq!(msg(&["ks=normal:4e4:-1"], 8), "invalid ks = normal:4e4:-1: a normal needs SD > 0");
        assert_eq!(
            msg(&["ks=uniform:0.5:2e4"], 8),
            "invalid ks = uniform:0.5:20000: samples reach 0.5..20000 N/m; string-plane stiffness must satisfy 1 <= ks <= 1e12 N/m"
        );
        assert!(msg(&["x=uniform:0.1:0.9"], 8).starts_with("invalid x = uniform:0.1:0.9: samples reach 0.9 m, where"));
        assert!(msg(&["p=uniform:0.5:2"], 8).contains("1 < p <= 10"));
        assert!(msg(&["ks=uniform:2e4:3e4", "ks=uniform:3e4:4e4"], 8).contains("ks is varied twice"));
        assert!(msg(&["segments=uniform:10:20"], 8).contains("only real-valued parameters"));
        assert!(msg(&["x"], 8).contains("give KEY=DIST") && msg(&["x"], 8).contains("ball-ex"));
        // KEY alone: the declared distribution
        let declared = study(&["ks"], 8).unwrap();
        assert_eq!(declared.inputs[0].dist, keys::KS.uncertainty.unwrap().dist);
        assert!(msg(&["ks=uniform:2e4:3e4"], 0).starts_with("invalid samples = 0: must satisfy 1 <= samples <= 65536"));
        assert!(msg(&["ks=uniform:2e4:3e4"], u64::MAX).contains("samples <= 65536"));
        for m in [msg(&["ks=uniform:5e4:2e4"], 8), msg(&["x=uniform:0.1:0.9"], 8)] {
            assert!(!m.contains('\n'), "{m}");
        }
    }

    #[test]
    fn outputs_follow_the_inputs_and_are_deterministic() {
        let s = study(&["ks=loguniform:2e4:6e4", "mb=normal:0.057:0.0005"], 16).unwrap();
        let out = s.run(|_| {}).unwrap();
        assert_eq!(s.csv(&out), s.csv(&s.run(|_| {}).unwrap()), "same seed, same numbers");
        let e_a = out.iter().find(|o| o.key == "e_a").unwrap();
        // e_A falls with ks at the Fig 4 point: ks carries most of its variance
        assert!(e_a.summary.q05 < e_a.summary.q50 && e_a.summary.q50 < e_a.summary.q95);
        assert!(e_a.summary.total[0].value > e_a.summary.total[1].value, "{:?}", e_a.summary);
        let json = s.json(&out);
        assert_eq!(json["samples"], 16);
        assert_eq!(json["inputs"][0]["key"], "ks");
        for key in ["mean", "sd", "q05", "q50", "q95"] {
            assert!(json["outputs"]["e_a"][key].is_number(), "{key}");
        }
        assert!(json["outputs"]["e_a"]["first_order"]["ks"].is_number());
        assert!(json["outputs"]["e_a"]["total_order_ci"]["mb"][1].is_number());
        let csv = s.csv(&out);
        assert!(csv.starts_with("output,unit,mean,sd,q05,q50,q95,first_ks,first_ks_lo,first_ks_hi,total_ks"));
        assert_eq!(csv.lines().count(), out.len() + 1);
    }
}
