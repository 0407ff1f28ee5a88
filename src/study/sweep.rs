//! Parameter sweeps: the cartesian product of ranges or lists of any parameter, run in
//! parallel (rayon) in chunks, streamed in a deterministic order, so memory stays flat however
//! many impacts a sweep has.
//!
//! A spec is one value (`0.1`), a list (`2e4,4e4`; `node,hat` for the load rule), a linear range
//! `start:stop:count` (both ends included) or a log range `start:stop:count:log`.

use rayon::prelude::*;

use std::path::Path;

use crate::error::{Error, Result};
use crate::params::{keys, limits, Overrides, Params};
use crate::solve::outcome::{Field, Get, FIELDS};
use crate::solve::{simulate, ImpactResult};

/// A number in its shortest exact form (`ryu`), zero of either sign as "0" as in the other
/// tables; an undefined one (NaN: `e_t` at too little incoming slip) as an empty field.
fn number_text(v: f64) -> String {
    if v.is_nan() {
        String::new()
    } else if v == 0.0 {
        "0".to_string()
    } else {
        ryu::Buffer::new().format(v).to_string()
    }
}

/// Impacts computed per parallel chunk (bounded memory, deterministic order).
pub const CHUNK: usize = 4096;
/// The largest sweep accepted ([`limits::MAX_SWEEP_POINTS`]).
pub const MAX_POINTS: u64 = limits::MAX_SWEEP_POINTS;

/// One varied parameter and its values (as text, parsed like a flag).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// The parameter key (`x`, `ks`, ...).
    pub key: String,
    /// Its values.
    pub values: Vec<String>,
}

impl Axis {
    /// The values that bound the axis: the least and the greatest of a numeric axis (a range
    /// may hold a million values; every one lies between these), every value of any other.
    pub fn extremes(&self) -> Vec<&String> {
        let numbers: Option<Vec<f64>> = self.values.iter().map(|v| v.trim().parse::<f64>().ok()).collect();
        match numbers {
            Some(xs) if xs.len() > 2 => {
                let lo = (0..xs.len()).min_by(|&i, &j| xs[i].total_cmp(&xs[j])).unwrap_or(0);
                let hi = (0..xs.len()).max_by(|&i, &j| xs[i].total_cmp(&xs[j])).unwrap_or(0);
                vec![&self.values[lo], &self.values[hi]]
            }
            _ => self.values.iter().collect(),
        }
    }
}

/// Expand a spec into values.
pub fn parse_spec(key: &str, spec: &str) -> Result<Axis> {
    let bad = |why: &str| Error::invalid("sweep", format!("--{key} {spec}"), why);
    let values = if spec.contains(':') {
        let parts: Vec<&str> = spec.split(':').collect();
        let log = match parts.len() {
            3 => false,
            4 if parts[3] == "log" => true,
            _ => return Err(bad("a range is start:stop:count or start:stop:count:log")),
        };
        let a: f64 = parts[0].parse().map_err(|_| bad("start is not a number"))?;
        let b: f64 = parts[1].parse().map_err(|_| bad("stop is not a number"))?;
        // (a count reads as digits or as a whole number in exponent form: 50, 1e3)
        let count: f64 = parts[2].parse().map_err(|_| bad("count is not a number"))?;
        if !(count.is_finite() && count >= 1.0 && count.fract() == 0.0) {
            return Err(bad("count must be a whole number >= 1 (as 50 or 1e3)"));
        }
        // counted before any value is made
        limits::check_count("sweep", count, limits::MAX_AXIS_VALUES, &format!("the count of --{key}"))?;
        let n = count as u64;
        if !a.is_finite() || !b.is_finite() {
            return Err(bad("the ends must be finite"));
        }
        if log && (a <= 0.0 || b <= 0.0) {
            return Err(bad("a log range needs positive ends"));
        }
        (0..n)
            .map(|i| {
                let f = if n == 1 { 0.0 } else { i as f64 / (n - 1) as f64 };
                let v = if log { 10f64.powf(a.log10() + f * (b.log10() - a.log10())) } else { a + f * (b - a) };
                if key == "segments" {
                    format!("{}", v.round())
                } else {
                    format!("{v}")
                }
            })
            .collect()
    } else {
        spec.split(',').map(|s| s.trim().to_string()).collect::<Vec<_>>()
    };
    if values.iter().any(String::is_empty) {
        return Err(bad("empty value"));
    }
    // parse once now so a typo fails before any impact is run
    let mut probe = Overrides::default();
    for v in &values {
        probe.set(key, v)?;
    }
    Ok(Axis { key: key.to_string(), values })
}

/// The solver a sweep uses unless told: the modal one (it agrees with the explicit reference to
/// 2e-5 over the randomized and grid test sets and is about 30 times faster), or the explicit
/// one when a fixed or swept value needs it (a hand grip or stiffening strings), or `solver` is
/// given.
pub fn default_solver(base: &Overrides, axes: &[Axis]) -> Option<crate::params::SolverKind> {
    use crate::params::{Grip, SolverKind, StringLaw};
    if base.solver.is_some() || axes.iter().any(|a| a.key == "solver") {
        return base.solver;
    }
    let swept =
        |key: &str, value: &str| axes.iter().any(|a| a.key == key && a.values.iter().any(|v| v.trim() == value));
    let needs_fd = base.grip == Some(Grip::Hand)
        || base.strings == Some(StringLaw::Stiffening)
        || swept("grip", "hand")
        || swept("strings", "stiffening");
    Some(if needs_fd { SolverKind::Fd } else { SolverKind::Modal })
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
pub const OPTIONS: [&str; 4] = ["out", "config", "racket", "quiet"];

/// The parameters every sweep row records, swept or not (the impact point, the string bed and
/// the ball speed), and for a sweep of oblique or spinning balls the incidence, azimuth, spin
/// and friction too (what an oblique impact is run at, as its single-impact CSV records it).
pub fn recorded_keys(oblique: bool) -> Vec<&'static str> {
    let mut v = vec![keys::X.key, keys::R.key, keys::KS.key, keys::V1.key];
    if oblique {
        v.extend([keys::ANGLE_DEG.key, keys::AZIMUTH_DEG.key, keys::SPIN_RPM.key, keys::MU.key]);
    }
    v
}

/// Column name of a parameter, with its SI unit (`unknown` for a key that is not a parameter).
pub fn column_name(key: &str) -> &'static str {
    keys::find(key).map_or("unknown", |spec| spec.column)
}

/// The result fields a sweep writes: the sweep columns of the result's field table
/// ([`FIELDS`]), the oblique ones only in a sweep of oblique or spinning balls, and the losses
/// of the named tangential mechanisms only where some impact runs under such a law (`losses`;
/// an empty field for an impact under the elastic law).
fn swept(oblique: bool, losses: bool) -> impl Iterator<Item = &'static Field> {
    FIELDS.iter().filter(move |f| f.sweep && (oblique || !f.is_oblique()) && (losses || !f.is_law_only()))
}

/// Result columns written for every impact: `swept` fields, then the solver (unless the
/// solver is itself a swept axis, whose column already names it: no column twice).
pub fn result_columns(oblique: bool, losses: bool, solver_swept: bool) -> impl Iterator<Item = &'static str> {
    swept(oblique, losses).map(|f| f.key).chain((!solver_swept).then_some("solver"))
}

/// The result columns of one impact. Numbers are written in their shortest form that reads back
/// as the same `f64` (`ryu`: `0.25`, `1.5e-7`, `3.0`): exact, and without the noise digits of a
/// fixed 17; a flag as 0 or 1.
fn result_fields<'a>(
    r: &'a ImpactResult,
    p: &Params,
    (oblique, losses): (bool, bool),
    solver_swept: bool,
) -> impl Iterator<Item = String> + 'a {
    let fields = swept(oblique, losses).map(move |f| match f.get {
        Get::Number(g) => number_text(g(r)),
        Get::Flag(g) => u8::from(g(r)).to_string(),
    });
    fields.chain((!solver_swept).then(|| p.numerics.solver.name().to_string()))
}

impl Sweep {
    /// The sweep the command line asks for: the varied parameters as `--KEY SPEC` pairs over
    /// the defaults (the paper's, or those of `racket`, a file or preset, fitted at the config
    /// file's segment count) and the fixed values of the `config` file. The solver is the
    /// [`default_solver`] unless given. Every point is validated before anything runs.
    pub fn from_pairs(racket: Option<&str>, config: Option<&Path>, pairs: &[String]) -> Result<Sweep> {
        let mut base = crate::study::config_file(config)?;
        if let Some(option) = pairs.iter().find(|t| t.strip_prefix("--").is_some_and(|k| OPTIONS.contains(&k))) {
            return Err(Error::invalid(
                "sweep",
                option,
                "options (--out, --config, --racket, --quiet) go before the --KEY SPEC pairs",
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
                    "options (--out, --config, --racket, --quiet) go before the --KEY SPEC pairs",
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
                || match key {
                    "mu" => self.base.mu.is_some(),
                    _ => self.base.mu_ss.is_some(),
                }
        };
        for p in self.representatives()? {
            for key in ["mu", "mu-ss"] {
                if given(key) {
                    crate::params::strings::refuse_if_set(p.oblique.string, key)?;
                }
            }
        }
        Ok(())
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
        self.axes.iter().any(|a| a.key == "solver")
    }

    /// The [`recorded_keys`] that are not swept: their columns follow the swept ones.
    pub fn fixed_keys(&self, oblique: bool) -> Vec<&'static str> {
        recorded_keys(oblique).into_iter().filter(|k| !self.axes.iter().any(|a| a.key == *k)).collect()
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
    fn at_point(&self, vals: &[&str], e: Error) -> Error {
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
            swept.iter().map(|(a, v)| format!("{} = {}", a.key, crate::error::readable(v))).collect();
        Error::AtPoint { point: point.join(", "), source: Box::new(e) }
    }

    /// Run every impact in parallel chunks and hand each finished chunk's CSV rows, in order,
    /// to `sink`; `progress` gets the number of impacts done so far.
    pub fn run(&self, mut sink: impl FnMut(&[Vec<String>]) -> Result<()>, mut progress: impl FnMut(u64)) -> Result<()> {
        let total = self.len();
        limits::check_count("sweep", total as f64, MAX_POINTS, "the impacts of a sweep (the product of the counts)")?;
        let oblique = self.is_oblique();
        let losses = self.has_losses();
        let fixed = self.fixed_keys(oblique);
        let solver_swept = self.solver_swept();
        let points = Points::of(self)?;
        let mut start = 0u64;
        while start < total {
            let end = (start + CHUNK as u64).min(total);
            let rows: Vec<Vec<String>> = (start..end)
                .into_par_iter()
                .map(|i| {
                    let (p, vals) = points.at(i);
                    // (`simulate` validates the parameters, as `point` would)
                    let r = simulate(&p).map_err(|e| self.at_point(&vals, e))?;
                    let fixed = fixed.iter().map(|k| number_text(keys::value_number(k, &p).unwrap_or(f64::NAN)));
                    Ok(vals
                        .into_iter()
                        .map(str::to_string)
                        .chain(fixed)
                        .chain(result_fields(&r, &p, (oblique, losses), solver_swept))
                        .collect())
                })
                // (the first failed point in the sweep's order: the same message every run)
                .collect::<Vec<Result<Vec<String>>>>()
                .into_iter()
                .collect::<Result<_>>()?;
            sink(&rows)?;
            progress(end);
            start = end;
        }
        Ok(())
    }
}

/// The points of a sweep with every value parsed once: the defaults with the fixed overrides
/// applied, and each axis value as an override of its one field. Applying an axis's override
/// after the fixed ones is what [`Sweep::point`] does by setting it on them (each key has its
/// own field), without parsing text or validating per point.
struct Points<'a> {
    sweep: &'a Sweep,
    start: Params,
    values: Vec<Vec<Overrides>>,
}

impl<'a> Points<'a> {
    fn of(sweep: &'a Sweep) -> Result<Self> {
        let mut start = sweep.defaults;
        sweep.base.apply(&mut start);
        let values = sweep
            .axes
            .iter()
            .map(|axis| {
                axis.values
                    .iter()
                    .map(|v| {
                        let mut o = Overrides::default();
                        o.set(&axis.key, v)?;
                        Ok(o)
                    })
                    .collect::<Result<Vec<_>>>()
            })
            .collect::<Result<_>>()?;
        Ok(Points { sweep, start, values })
    }

    /// The parameters of impact `i` (not validated) and its axis values, as [`Sweep::point`].
    fn at(&self, mut i: u64) -> (Params, Vec<&'a str>) {
        let mut p = self.start;
        let mut vals = vec![""; self.values.len()];
        for (k, (axis, values)) in self.sweep.axes.iter().zip(&self.values).enumerate().rev() {
            let n = values.len() as u64;
            let j = (i % n) as usize;
            i /= n;
            values[j].apply(&mut p);
            vals[k] = &axis.values[j];
        }
        (p, vals)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_has_its_own_column_name() {
        let names: Vec<&str> = Overrides::KEYS.iter().map(|k| column_name(k)).collect();
        assert!(!names.contains(&"unknown"), "{names:?}");
        let mut unique = names.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), names.len(), "{names:?}");
    }

    #[test]
    fn specs_expand_to_lists_and_ranges() {
        assert_eq!(parse_spec("ks", "2e4,4e4").unwrap().values, vec!["2e4", "4e4"]);
        assert_eq!(parse_spec("x", "0.1:0.3:3").unwrap().values, vec!["0.1", "0.2", "0.3"]);
        assert_eq!(parse_spec("ks", "1e3:1e5:3:log").unwrap().values, vec!["1000", "10000", "100000"]);
        assert_eq!(parse_spec("load", "node,hat").unwrap().values.len(), 2);
        assert!(parse_spec("ks", "1:2").is_err());
        assert!(parse_spec("ks", "a,b").is_err());
        assert!(parse_spec("nope", "1").is_err());
        assert!(parse_spec("ks", "0:1:3:log").is_err());
        // a count in exponent form is the same count; a fractional or zero one is refused
        assert_eq!(parse_spec("x", "0.1:0.3:3e0").unwrap().values, parse_spec("x", "0.1:0.3:3").unwrap().values);
        assert_eq!(parse_spec("x", "0:1:1e3").unwrap().values.len(), 1000);
        for bad in ["0.1:0.3:2.5", "0.1:0.3:0", "0.1:0.3:-3", "0.1:0.3:nan", "0.1:0.3:inf"] {
            assert!(parse_spec("x", bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn points_are_row_major_and_match_single_runs() {
        let sweep = Sweep {
            defaults: Params::default(),
            // (a fixed value of a swept key is overridden by the axis)
            base: Overrides { load: Some(crate::params::LoadRule::Node), ks: Some(9e4), ..Default::default() },
            axes: vec![parse_spec("ks", "2e4,4e4").unwrap(), parse_spec("x", "0.1:0.2:3").unwrap()],
        };
        assert_eq!(sweep.len(), 6);
        let (p, vals) = sweep.point(4).unwrap();
        assert_eq!(vals, vec!["4e4", "0.15000000000000002"]);
        assert_eq!((p.strings.ks, p.impact.x), (4e4, 0.15000000000000002));
        let mut rows = Vec::new();
        sweep
            .run(
                |chunk| {
                    rows.extend_from_slice(chunk);
                    Ok(())
                },
                |_| {},
            )
            .unwrap();
        assert_eq!(rows.len(), 6);
        // the parsed points are the points
        let points = Points::of(&sweep).unwrap();
        for i in 0..sweep.len() {
            let (a, b) = (sweep.point(i).unwrap(), points.at(i));
            assert_eq!(format!("{a:?}"), format!("{b:?}"));
        }
        // swept ks, x; then the recorded r and v1; then the results
        assert_eq!(sweep.header()[..5], ["ks_n_per_m", "x_m", "r_m", "v1_m_per_s", "e_a"]);
        assert_eq!(rows[4][2], "0.05", "r of the default (Fig 4) parameters is recorded");
        let e_a: f64 = rows[4][4].parse().unwrap();
        assert_eq!(e_a, simulate(&p).unwrap().e_a);
    }
}
