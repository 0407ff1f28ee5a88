//! `calibrate`: fit parameters with a declared range to measured rows (data/measured's schema),
//! with intervals, correlation, a leave-one-group-out error and a chart.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use racket_impact::diagnostic::{Diagnostic, Kind};
use racket_impact::study::calibrate::{self, write, Fitted, HoldOut, Problem, Rows, Weights};
use racket_impact::study::measured;
use racket_impact::{Error, Result};

use super::common::{out, print_diagnostics, Common, Format};
use super::overrides::CalibrateKeys;

#[derive(Args, Debug)]
pub struct CalibrateArgs {
    /// Measurements CSV in the schema of data/measured (columns id, quantity, value, unit,
    /// ball_speed_m_s, angle_deg, spin_in_rpm, string_tension_lb, string, support, and role and
    /// uncertainty where used) [default: the shipped data/measured/measurements.csv]
    pub measurements: Option<PathBuf>,
    /// The parameters to fit, KEY[,KEY...]: each one with a declared range (see the long help)
    #[arg(long, value_delimiter = ',', required = true)]
    pub fit: Vec<String>,
    /// Search KEY within LO..HI instead of its declared range (repeatable; within its valid range)
    #[arg(long, value_name = "KEY=LO:HI")]
    pub range: Vec<String>,
    /// Only these rows, ID[,ID...] (a range M001-M014 of ids alike but for their number)
    #[arg(long, value_delimiter = ',')]
    pub rows: Vec<String>,
    /// Residuals in the measured unit (none), or each over the row's stated uncertainty
    #[arg(long, value_enum, default_value_t = WeightsArg::None)]
    pub weights: WeightsArg,
    /// The groups left out one at a time, each refitted without and predicted
    #[arg(long = "hold-out", value_enum, default_value_t = HoldOutArg::String)]
    pub hold_out: HoldOutArg,
    /// Draw model against measured (held-out and validation rows marked) to this PNG
    #[arg(long, help_heading = "Output")]
    pub plot: Option<PathBuf>,
    /// Write the output (in --format) to this file, atomically, instead of standard output
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub common: Common<CalibrateKeys>,
}

/// `--weights`.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum WeightsArg {
    None,
    Uncertainty,
}

/// `--hold-out`.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum HoldOutArg {
    String,
    Row,
    None,
}

/// The long help: its examples, then what is computed.
pub fn long_about() -> String {
    super::examples(
        "Fit parameters with a declared range to measured rows: intervals, correlation, held-out error",
        &[
            "racket-impact calibrate --fit kt --hold-out string --plot kt.png",
            "racket-impact calibrate my-lab.csv --fit kt,mu-scale --weights uncertainty --format json",
            "racket-impact calibrate --fit kt --rows M001-M014 --out fit.txt",
        ],
    ) + "\n\n\
         Each row of the measurements (data/measured's schema; a lab's own CSV as well) is one impact: its ball \
         speed, angle from the normal, incoming spin, tension, string (data/strings) and support (clamped, free, \
         hand_held) on the parameters the flags, --config and --racket give, its quantity a result field \
         (spin_out_rpm, rebound_angle_deg, e_a, ...). The rows with role = calibration are fitted (every row of a \
         CSV without a role column); those with role = validation are predicted and judged, never fitted.\n\n\
         The fit searches each --fit parameter within its declared range (its usual range, else its valid range; \
         logarithmic over a decade or more; the list is at the end): a grid, then Brent (one parameter) or \
         Nelder-Mead. Then each parameter's 95 % profile-likelihood interval (the residual scale estimated from \
         the fit), whether the rows bound it, the correlation from the Jacobian, and each group (--hold-out \
         string: the rows of one string; row: one row) refitted without and predicted. Runs with the modal solver \
         unless --solver is given or a hand grip needs fd.\n\n\
         Refused: a parameter with no declared range, a string's own property (mu, mu-ss of a named string), \
         fewer rows than parameters, a fitted row whose shot the model cannot run (a ratio, a threshold, an \
         unknown string or support), a missing column or a value that is not a number."
}

/// The end of the long help: the parameters that can be fitted, with their ranges.
pub fn fittable_help() -> String {
    let fittable: Vec<String> = calibrate::declared()
        .filter_map(|s| {
            calibrate::declared_range(s).map(|(lo, hi)| format!("{} ({}..{}{})", s.key, lo, hi, unit(s.unit)))
        })
        .collect();
    format!("Parameters with a declared range (--fit):\n  {}", fittable.join("\n  "))
}

fn unit(u: &str) -> String {
    if u.is_empty() {
        String::new()
    } else {
        format!(" {u}")
    }
}

/// `M001-M014` as its ids; any other text as itself.
fn expand(ids: &[String]) -> Vec<String> {
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

/// Fit, then print (and write) the outcome.
pub fn run(a: CalibrateArgs) -> Result<()> {
    if a.common.format == Format::Csv {
        return Err(Error::invalid("format", "csv", "calibrate writes text or json"));
    }
    let sources = a.common.sources();
    let from_config = racket_impact::intake::config_file(sources.config.as_deref())?;
    let given = sources.flags.clone().or(from_config.clone());
    let mut base = sources.params()?;
    if let Some(solver) = racket_impact::study::sweep::default_solver(&given, &[]) {
        base.numerics.solver = solver;
    }
    let (rows, source) = match &a.measurements {
        Some(path) => {
            // (recorded as an input of the run: no output may replace it)
            let max = racket_impact::params::limits::MAX_MEASUREMENTS_BYTES;
            let text = racket_impact::params::inputs::read_text(path, "a measurements CSV", max)?;
            let name = path.display().to_string();
            (measured::parse(&text, &name)?, name)
        }
        None => (measured::shipped()?, measured::SHIPPED_FILE.to_string()),
    };
    let mut ranges: Vec<(String, (f64, f64))> = Vec::new();
    for text in &a.range {
        let bad = || Error::invalid("range", text, "give KEY=LO:HI, e.g. kt=1e4:1e6");
        let (key, span) = text.split_once('=').ok_or_else(bad)?;
        let (lo, hi) = span.split_once(':').ok_or_else(bad)?;
        let number = |s: &str| racket_impact::params::number::parse_number(s.trim()).map_err(|_| bad());
        ranges.push((key.trim().to_string(), (number(lo)?, number(hi)?)));
    }
    let mut params = Vec::new();
    for key in &a.fit {
        let range = ranges.iter().find(|(k, _)| k == key.trim()).map(|(_, r)| *r);
        let fitted = Fitted::new(key, range)?;
        if sources.flags.given().contains(&fitted.spec.key) {
            return Err(Error::invalid(
                "fit",
                fitted.spec.key,
                format!("is both fixed (--{0}) and fitted; give one", fitted.spec.key),
            ));
        }
        params.push(fitted);
    }
    if let Some((key, _)) = ranges.iter().find(|(k, _)| !params.iter().any(|f| f.spec.key == k)) {
        return Err(Error::invalid("range", key, "is not a fitted parameter (--fit)"));
    }
    let rows = Rows::new(&base, &rows, &expand(&a.rows))?;
    if rows.fitted.is_empty() {
        return Err(Error::invalid("rows", source, "no row to fit (every row selected has role = validation)"));
    }
    let weights = match a.weights {
        WeightsArg::None => Weights::None,
        WeightsArg::Uncertainty => Weights::Uncertainty,
    };
    let hold_out = match a.hold_out {
        HoldOutArg::String => HoldOut::String,
        HoldOutArg::Row => HoldOut::Row,
        HoldOutArg::None => HoldOut::None,
    };
    if let Some(path) = &a.plot {
        racket_impact::render::io::check_output_dir("plot", path)?;
    }
    if let Some(path) = &a.out {
        racket_impact::render::io::check_output_dir("out", path)?;
        if let Some(plot) = a.plot.as_deref().filter(|plot| racket_impact::render::io::same_output(path, plot)) {
            return Err(Error::invalid(
                "out",
                path.display(),
                format!("is the same file as --plot {}", plot.display()),
            ));
        }
    }
    // a flag every fitted row sets from its own columns reaches none of them
    for key in sources.flags.given() {
        let columns: Vec<&str> = rows.fitted.iter().filter_map(|c| calibrate::shot::sets(&c.row, key)).collect();
        if columns.len() == rows.fitted.len() {
            let value = racket_impact::params::keys::value_text(key, &base).unwrap_or_default();
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
    let mut noted = a.common.check_used(rows.fitted.iter().map(|c| &c.params))?;
    let fitted_in_config: Vec<&str> =
        params.iter().map(|f| f.spec.key).filter(|k| from_config.given().contains(k)).collect();
    if let (Some(path), false) = (&sources.config, fitted_in_config.is_empty()) {
        let sentence = format!(
            "config file {} sets {}, which --fit fits: the file's value is not used",
            path.display(),
            fitted_in_config.join(", ")
        );
        noted.push(Diagnostic::new(Kind::NotUsed, "config", sentence));
    }
    let fitted_keys: Vec<&str> = params.iter().map(|f| f.spec.key).collect();
    noted.extend(racket_impact::intake::diagnose::parameters([&base], &fitted_keys));
    let problem = Problem::new(params, rows, weights)?;
    let outcome = calibrate::calibrate(&problem, hold_out)?;
    let text = match a.common.format {
        Format::Json => racket_impact::render::json::pretty(&write::json(&outcome, &source, weights))?,
        Format::Text | Format::Csv => write::text(&outcome, &source, weights),
    };
    // the plot and the text published together, all or none
    let mut staged = racket_impact::render::io::Staged::new();
    if let Some(path) = &a.plot {
        racket_impact::render::plot::stage_png(&mut staged, "calibrate", &write::chart(&outcome, &source), path)?;
    }
    if let Some(path) = &a.out {
        staged.bytes(path, text.as_bytes())?;
    }
    staged.publish(|| {
        if a.out.is_none() {
            out!("{text}");
        }
        Ok(())
    })?;
    print_diagnostics(&noted);
    Ok(())
}
