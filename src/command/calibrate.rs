//! `calibrate`: fit parameters with a declared range to measured rows (data/measured's schema),
//! with intervals, correlation and a leave-one-group-out error. The request reads the rows,
//! checks the fit against them and runs it under the control (its impacts count themselves and
//! stop once it is cancelled); the front ends write its text, JSON and chart.

use super::{Control, Given, Kind, Many, Opt, Request, Unit, Work};
use crate::diagnostic::{Diagnostic, Kind as Noted};
use crate::error::{Error, Result};
use crate::intake::Sources;
use crate::study::calibrate::{self, Calibration, Fitted, HoldOut, Problem, Rows, Weights};
use crate::study::measured;

/// The command.
pub const NAME: &str = "calibrate";

/// Its options (the command line takes the measurements file as its argument).
pub const OPTIONS: &[Opt] = &[
    Opt::new(
        "measurements",
        Kind::Text,
        None,
        "Measurements CSV in the schema of data/measured (the shipped data/measured/measurements.csv if not given)",
    )
    .not_on_cli(),
    Opt::new(
        "fit",
        Kind::Text,
        None,
        "The parameters to fit, KEY[,KEY...]: each one with a declared range (see the long help)",
    )
    .many(Many::List)
    .required(),
    Opt::new(
        "range",
        Kind::Text,
        None,
        "Search KEY within LO..HI instead of its declared range, KEY=LO:HI (repeatable; within its valid range)",
    )
    .many(Many::Repeated),
    Opt::new(
        "rows",
        Kind::Text,
        None,
        "Only these rows, ID[,ID...] (a range M001-M014 of ids alike but for their number)",
    )
    .many(Many::List),
    Opt::new(
        "weights",
        Kind::Choice(&["none", "uncertainty"]),
        Some("none"),
        "Residuals in the measured unit (none), or each over the row's stated uncertainty",
    ),
    Opt::new(
        "hold-out",
        Kind::Choice(&["string", "row", "none"]),
        Some("string"),
        "The groups left out one at a time, each refitted without and predicted",
    ),
];

/// A calibration, checked and ready to run.
#[derive(Debug)]
pub struct Calibrate {
    problem: Problem,
    hold_out: HoldOut,
    /// The measurements' name (the file, or the shipped one).
    pub source: String,
    /// The residuals' weights.
    pub weights: Weights,
    noted: Vec<Diagnostic>,
}

/// A calibration, run.
#[derive(Debug)]
pub struct Calibrated {
    /// The fit, its intervals, correlation and held-out errors.
    pub outcome: Calibration,
    /// The measurements' name.
    pub source: String,
    /// The residuals' weights.
    pub weights: Weights,
    /// The notes made before the fit (unused flags and config keys, parameters outside their
    /// usual ranges).
    pub diagnostics: Vec<Diagnostic>,
}

/// `M001-M014` as its ids; any other text as itself.
pub fn expand(ids: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for id in ids {
        let id = id.trim();
        let split = id.split_once('-').and_then(|(a, b)| {
            let digits = |s: &str| s.len() - s.trim_end_matches(|c: char| c.is_ascii_digit()).len();
            let (pa, na) = a.split_at(a.len() - digits(a));
            let (pb, nb) = b.split_at(b.len() - digits(b));
            let (x, y) = (na.parse::<u64>().ok()?, nb.parse::<u64>().ok()?);
            (pa == pb && !na.is_empty() && na.len() == nb.len() && x <= y).then(|| (pa.to_string(), x, y, na.len()))
        });
        match split {
            Some((prefix, x, y, width)) => out.extend((x..=y).map(|k| format!("{prefix}{k:0width$}"))),
            None => out.push(id.to_string()),
        }
    }
    out
}

impl Calibrate {
    /// The calibration of the parameters `given` names (`fit`, with their `range`s) to the rows
    /// of its `measurements` (the shipped ones where not given) on the parameters `sources` give:
    /// every check made before the fit (a parameter with no declared range, one both fixed and
    /// fitted, a range of a parameter not fitted, no row to fit, a flag every fitted row sets
    /// from its own columns).
    pub fn new(sources: &Sources, given: &Given) -> Result<Calibrate> {
        let from_config = crate::intake::config_file(sources.config.as_deref())?;
        let flags = sources.flags.clone().or(from_config.clone());
        let mut base = sources.params()?;
        if let Some(solver) = crate::study::sweep::default_solver(&flags, &[]) {
            base.numerics.solver = solver;
        }
        let (rows, source) = match given.text("measurements").map(std::path::PathBuf::from) {
            Some(path) => {
                // (recorded as an input of the run: no output may replace it)
                let max = crate::params::limits::MAX_MEASUREMENTS_BYTES;
                let text = crate::params::inputs::read_text(&path, "a measurements CSV", max)?;
                let name = path.display().to_string();
                (measured::parse(&text, &name)?, name)
            }
            None => (measured::shipped()?, measured::SHIPPED_FILE.to_string()),
        };
        let mut ranges: Vec<(String, (f64, f64))> = Vec::new();
        for text in given.texts("range") {
            let bad = || Error::invalid("range", &text, "give KEY=LO:HI, e.g. kt=1e4:1e6");
            let (key, span) = text.split_once('=').ok_or_else(bad)?;
            let (lo, hi) = span.split_once(':').ok_or_else(bad)?;
            let number = |s: &str| crate::params::number::parse_number(s.trim()).map_err(|_| bad());
            ranges.push((key.trim().to_string(), (number(lo)?, number(hi)?)));
        }
        let mut params = Vec::new();
        // (a list from Python may hold "kt,mu" as one text, as the command line's flag would)
        let split = |name: &str| -> Vec<String> {
            given
                .texts(name)
                .iter()
                .flat_map(|t| t.split(',').map(|s| s.trim().to_string()))
                .filter(|s| !s.is_empty())
                .collect()
        };
        for key in split("fit") {
            let range = ranges.iter().find(|(k, _)| k == key.trim()).map(|(_, r)| *r);
            let fitted = Fitted::new(&key, range)?;
            if sources.flags.given().contains(&fitted.spec.key) {
                return Err(Error::invalid(
                    "fit",
                    fitted.spec.key,
                    format!("is both fixed (--{0}) and fitted; give one", fitted.spec.key),
                ));
            }
            params.push(fitted);
        }
        if params.is_empty() {
            return Err(Error::invalid("fit", "", "give the parameters to fit, KEY[,KEY...]"));
        }
        if let Some((key, _)) = ranges.iter().find(|(k, _)| !params.iter().any(|f| f.spec.key == k)) {
            return Err(Error::invalid("range", key, "is not a fitted parameter (--fit)"));
        }
        let rows = Rows::new(&base, &rows, &expand(&split("rows")))?;
        if rows.fitted.is_empty() {
            return Err(Error::invalid("rows", source, "no row to fit (every row selected has role = validation)"));
        }
        let weights = match given.choice("weights")? {
            Some("uncertainty") => Weights::Uncertainty,
            _ => Weights::None,
        };
        let hold_out = match given.choice("hold-out")? {
            Some("row") => HoldOut::Row,
            Some("none") => HoldOut::None,
            _ => HoldOut::String,
        };
        // a flag every fitted row sets from its own columns reaches none of them
        for key in sources.flags.given() {
            let columns: Vec<&str> = rows.fitted.iter().filter_map(|c| calibrate::shot::sets(&c.row, key)).collect();
            if columns.len() == rows.fitted.len() {
                let value = crate::params::keys::value_text(key, &base).unwrap_or_default();
                return Err(Error::invalid(
                    key,
                    value,
                    format!(
                        "every fitted row sets {key} from its column {}: a flag applies only to rows that leave it empty",
                        columns[0]
                    ),
                ));
            }
        }
        let fitted_params: Vec<_> = rows.fitted.iter().map(|c| c.params).collect();
        let mut noted = sources.check_used(&fitted_params)?;
        let fitted_in_config: Vec<&str> =
            params.iter().map(|f| f.spec.key).filter(|k| from_config.given().contains(k)).collect();
        if let (Some(path), false) = (&sources.config, fitted_in_config.is_empty()) {
            let sentence = format!(
                "config file {} sets {}, which --fit fits: the file's value is not used",
                path.display(),
                fitted_in_config.join(", ")
            );
            noted.push(Diagnostic::new(Noted::NotUsed, "config", sentence));
        }
        let fitted_keys: Vec<&str> = params.iter().map(|f| f.spec.key).collect();
        noted.extend(crate::intake::diagnose::parameters([&base], &fitted_keys));
        let problem = Problem::new(params, rows, weights)?;
        Ok(Calibrate { problem, hold_out, source, weights, noted })
    }
}

impl Request for Calibrate {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Calibrated;

    /// Not estimated: the fit's impacts depend on how its search goes (they count themselves
    /// and stop when the run is cancelled).
    fn work(&self, _threads: usize) -> Option<Work> {
        None
    }

    fn run(self, ctl: &Control) -> Result<Calibrated> {
        ctl.begin(1, Unit::Named("fits"));
        let outcome = calibrate::calibrate(&self.problem, self.hold_out)?;
        ctl.set_done(1);
        Ok(Calibrated { outcome, source: self.source, weights: self.weights, diagnostics: self.noted })
    }
}
