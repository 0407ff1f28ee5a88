//! Parameter sweeps: the cartesian product of ranges or lists of any parameter, run in
//! parallel (rayon) in chunks, streamed in a deterministic order, so memory stays flat however
//! many impacts a sweep has.
//!
//! The range grammar is `axis`, the CSV's column layout `columns`, the plan (what each
//! impact is, every point validated first) this file and the runner `run`.

mod axis;
mod columns;
mod run;

pub use axis::{parse_spec, Axis};
pub use columns::{column_name, recorded_keys, result_columns, Cell};
pub use run::CHUNK;

use rayon::prelude::*;

use std::path::Path;

use crate::diagnostic::Diagnostic;
use crate::error::{Error, Result};
use crate::params::spec::ParamSpec;
use crate::params::{keys, limits, Overrides, Params};
use run::Points;

/// The largest sweep accepted ([`limits::MAX_SWEEP_POINTS`]).
pub const MAX_POINTS: u64 = limits::MAX_SWEEP_POINTS;

/// The solver a sweep uses unless told: the modal one (it agrees with the explicit reference to
/// 2e-5 over the randomized and grid test sets and is about 30 times faster), or the explicit
/// one when a fixed or swept value needs it (a hand grip or stiffening strings), or `solver` is
/// given.
pub fn default_solver(base: &Overrides, axes: &[Axis]) -> Option<crate::params::SolverKind> {
    use crate::params::{Grip, SolverKind, StringLaw};
    if base.solver.is_some() || axes.iter().any(|a| a.key == keys::SOLVER.key) {
        return base.solver;
    }
    let swept =
        |key: &str, value: &str| axes.iter().any(|a| a.key == key && a.values.iter().any(|v| v.trim() == value));
    let needs_fd = base.grip == Some(Grip::Hand)
        || base.strings == Some(StringLaw::Stiffening)
        || swept(keys::GRIP.key, Grip::Hand.name())
        || swept(keys::STRINGS.key, StringLaw::Stiffening.name());
    Some(if needs_fd { SolverKind::Fd } else { SolverKind::Modal })
}

/// The diagnostics of a sweep that ran: its notes `noted` ([`Sweep::check_used`]), the
/// parameters of its `representatives` outside their usual ranges, and its largest twist
/// `theta_max_deg` beyond the small-angle model.
pub fn diagnostics(noted: &[Diagnostic], representatives: &[Params], theta_max_deg: f64) -> Vec<Diagnostic> {
    let mut out = noted.to_vec();
    out.extend(crate::intake::diagnose::parameters(representatives, &[]));
    out.extend(crate::intake::diagnose::twist(theta_max_deg));
    out
}

/// A sweep: a base (paper defaults < config) and the varied axes, first axis slowest.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// The parameters every point starts from (the defaults, or a racket file's).
    pub defaults: Params,
    /// Fixed overrides.
    pub base: Overrides,
    /// Varied parameters.
    pub axes: Vec<Axis>,
}

/// The options of the `sweep` command, which go before the `--KEY SPEC` pairs.
pub const OPTIONS: [&str; 5] = ["out", "config", "racket", "quiet", "long"];
impl Sweep {
    /// The sweep the command line asks for: the varied parameters as `--KEY SPEC` pairs over
    /// the defaults (the paper's, or those of `racket`, a file or preset, fitted at the config
    /// file's segment count) and the fixed values of the `config` file. The solver is the
    /// [`default_solver`] unless given. Every point is validated before anything runs.
    pub fn from_pairs(racket: Option<&str>, config: Option<&Path>, pairs: &[String]) -> Result<Sweep> {
        let mut base = crate::intake::config_file(config)?;
        if let Some(option) = pairs.iter().find(|t| t.strip_prefix("--").is_some_and(|k| OPTIONS.contains(&k))) {
            return Err(Error::invalid(
                "sweep",
                option,
                "options (--out, --config, --racket, --quiet, --long) go before the --KEY SPEC pairs",
            ));
        }
        if pairs.len() % 2 != 0 || pairs.is_empty() {
            return Err(Error::invalid(
                "sweep",
                pairs.join(" "),
                "give parameters as --KEY SPEC pairs, e.g. --ks 2e4,4e4",
            ));
        }
        let mut axes: Vec<Axis> = Vec::new();
        for pair in pairs.chunks(2) {
            let key = pair[0].strip_prefix("--").ok_or_else(|| {
                Error::invalid("sweep", &pair[0], "expected --KEY before each SPEC (e.g. --x 0.02:0.60:50)")
            })?;
            if OPTIONS.contains(&key) {
                return Err(Error::invalid(
                    "sweep",
                    &pair[0],
                    "options (--out, --config, --racket, --quiet, --long) go before the --KEY SPEC pairs",
                ));
            }
            if keys::find(key).is_none() {
                return Err(Error::invalid(
                    "sweep",
                    &pair[0],
                    format!("unknown parameter (known: {})", Overrides::KEYS.join(", ")),
                ));
            }
            if axes.iter().any(|ax| ax.key == key) {
                return Err(Error::invalid("sweep", key, "each parameter may be given once"));
            }
            axes.push(parse_spec(key, &pair[1])?);
            // the product so far, before the next axis is made
            let product: f64 = axes.iter().map(|a| a.values.len() as f64).product();
            limits::check_count("sweep", product, MAX_POINTS, "the impacts of a sweep (the product of the counts)")?;
        }
        // the defaults of every command: the racket (or the paper's), hit at its face centre
        let spec = racket.map(crate::racket::load).transpose()?;
        let only_n = Overrides { segments: base.segments, ..Overrides::default() };
        let defaults = crate::racket::resolve(spec.as_ref(), &only_n)?.0;
        base.solver = default_solver(&base, &axes);
        let sweep = Sweep { defaults, base, axes };
        sweep.validate_all()?; // a bad value anywhere fails before anything is written
        sweep.check_friction_not_set_by_string()?;
        Ok(sweep)
    }

    /// A swept or configured `mu` / `mu-ss` beside a named string whose database entry sets it
    /// would be ignored at every point (the string's value is used): refused, as `simulate`
    /// refuses it ([`crate::params::strings::apply`]).
    fn check_friction_not_set_by_string(&self) -> Result<()> {
        let given = |key: &str| {
            self.axes.iter().any(|a| a.key == key)
                || if key == keys::MU.key { self.base.mu.is_some() } else { self.base.mu_ss.is_some() }
        };
        for p in self.representatives()? {
            for key in [keys::MU.key, keys::MU_SS.key] {
                if given(key) {
                    crate::params::strings::refuse_if_set(p.oblique.string, key)?;
                }
            }
        }
        Ok(())
    }

    /// The notes of this sweep over its `representatives` ([`Sweep::representatives`]), as
    /// [`crate::diagnostic::Kind::NotUsed`] diagnostics: one for each swept property none of the impacts
    /// exercises (a method's option none of them can honour is refused, as for `simulate`,
    /// [`crate::params::used`]), and one naming the keys of the `config` file that
    /// none of them uses ([`crate::intake::unused_config_note`]).
    pub fn check_used(&self, representatives: &[Params], config: Option<&Path>) -> Result<Vec<Diagnostic>> {
        let mut noted = Vec::new();
        let swept: Vec<&ParamSpec> = self.axes.iter().filter_map(|ax| keys::find(&ax.key)).collect();
        for spec in &swept {
            let values =
                self.axes.iter().find(|ax| ax.key == spec.key).map(|ax| ax.values.join(",")).unwrap_or_default();
            noted.extend(crate::intake::unused_flag(spec, &values, representatives, "these impacts")?);
        }
        if let Some(path) = config {
            let file = crate::intake::config_file(Some(path))?;
            let swept: Vec<&str> = swept.iter().map(|s| s.key).collect();
            noted.extend(crate::intake::unused_config_note(path, &file, &swept, &[], "sweep", representatives)?);
        }
        Ok(noted)
    }

    /// One impact's parameters per bounding value of each axis ([`Axis::extremes`]; the other
    /// axes at their first value): the range of every parameter, without the whole product
    /// (for the plausibility warnings and the check that each swept parameter is used).
    pub fn representatives(&self) -> Result<Vec<Params>> {
        let (first, _) = self.point(0)?;
        let mut out = vec![first];
        for axis in &self.axes {
            for v in axis.extremes() {
                let mut o = self.base.clone();
                for other in &self.axes {
                    o.set(&other.key, &other.values[0])?;
                }
                o.set(&axis.key, v)?;
                let mut p = self.defaults;
                o.apply(&mut p);
                out.push(p);
            }
        }
        Ok(out)
    }

    /// Number of impacts.
    pub fn len(&self) -> u64 {
        self.axes.iter().map(|a| a.values.len() as u64).product()
    }

    /// True if there is nothing to run (never: an empty axis is rejected when parsed).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether any impact of the sweep is oblique or spinning (its rows then carry the
    /// oblique result fields too).
    pub fn is_oblique(&self) -> bool {
        let varied = self.axes.iter().any(|a| a.key == keys::ANGLE_DEG.key || a.key == keys::SPIN_RPM.key);
        let mut p = self.defaults;
        self.base.apply(&mut p);
        varied || !p.oblique.is_normal()
    }

    /// Whether any impact of the sweep is oblique or spinning under a tangential law with
    /// named loss mechanisms (its rows then carry their losses too).
    pub fn has_losses(&self) -> bool {
        let elastic = crate::params::TangentialLaw::Elastic;
        let mut p = self.defaults;
        self.base.apply(&mut p);
        let law = match self.axes.iter().find(|a| a.key == keys::TANGENTIAL.key) {
            Some(axis) => axis.values.iter().any(|v| v.trim() != elastic.name()),
            None => p.oblique.tangential != elastic,
        };
        self.is_oblique() && law
    }

    /// The CSV header.
    pub fn header(&self) -> Vec<String> {
        let oblique = self.is_oblique();
        let results = result_columns(oblique, self.has_losses(), self.solver_swept()).map(String::from);
        let fixed = self.fixed_keys(oblique).into_iter().map(|k| column_name(k).to_string());
        self.axes.iter().map(|a| column_name(&a.key).to_string()).chain(fixed).chain(results).collect()
    }

    /// Whether the solver is one of the axes (then its column is not repeated at the end).
    pub fn solver_swept(&self) -> bool {
        self.axes.iter().any(|a| a.key == keys::SOLVER.key)
    }

    /// The [`recorded_keys`] that are not swept: their columns follow the swept ones.
    pub fn fixed_keys(&self, oblique: bool) -> Vec<&'static str> {
        recorded_keys(oblique).into_iter().filter(|k| !self.axes.iter().any(|a| a.key == *k)).collect()
    }

    /// The work of the sweep, estimated before it runs ([`crate::study::work`]).
    pub fn estimate(&self, threads: usize) -> crate::study::work::Estimate {
        crate::study::work::Estimate::of(self.len(), threads, |i| self.point(i).ok().map(|(p, _)| p))
    }

    /// The parameters of impact `i` (row-major, first axis slowest) and its axis values.
    pub fn point(&self, mut i: u64) -> Result<(Params, Vec<&str>)> {
        let mut o = self.base.clone();
        let mut vals = vec![""; self.axes.len()];
        for (k, axis) in self.axes.iter().enumerate().rev() {
            let n = axis.values.len() as u64;
            let v = &axis.values[(i % n) as usize];
            i /= n;
            o.set(&axis.key, v)?;
            vals[k] = v;
        }
        let mut p = self.defaults;
        o.apply(&mut p);
        p.validate()?;
        Ok((p, vals))
    }

    /// Validate every point's parameters (cheap, in parallel) so that a bad value anywhere in
    /// the sweep fails before any row is written.
    pub fn validate_all(&self) -> Result<()> {
        let total = self.len();
        limits::check_count("sweep", total as f64, MAX_POINTS, "the impacts of a sweep (the product of the counts)")?;
        let points = Points::of(self)?;
        // the first bad point in the sweep's order, so that the message is the same every run
        let bad = (0..total).into_par_iter().find_first(|&i| points.at(i).0.validate().is_err());
        match bad {
            Some(i) => {
                let (p, vals) = points.at(i);
                p.validate().map_err(|e| self.at_point(&vals, e))
            }
            None => Ok(()),
        }
    }

    /// The error `e` of the point with the swept values `vals`, saying which point it is by
    /// the values of the keys swept over more than one value (`at x = 0.1, segments = 4:
    /// ...`), unless the message names the point already: a bad value of the one such key, or
    /// no such key (the command names the point).
    pub(super) fn at_point(&self, vals: &[&str], e: Error) -> Error {
        if e.is_cancelled() {
            return e;
        }
        let swept: Vec<(&Axis, &str)> =
            self.axes.iter().zip(vals).filter(|(a, _)| a.values.len() > 1).map(|(a, v)| (a, *v)).collect();
        let names_it = match (&e, &swept[..]) {
            (_, []) => true,
            (Error::InvalidParameter { field, .. }, [(axis, _)]) => {
                keys::find(&axis.key).is_some_and(|s| s.key == *field)
            }
            _ => false,
        };
        if names_it {
            return e;
        }
        let point: Vec<String> =
            swept.iter().map(|(a, v)| format!("{} = {}", a.key, crate::numfmt::shown(v))).collect();
        Error::AtPoint { point: point.join(", "), source: Box::new(e) }
    }
}
