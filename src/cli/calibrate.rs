//! `calibrate`: fit parameters with a declared range to measured rows (data/measured's schema),
//! with intervals, correlation, a leave-one-group-out error and a chart.

use std::path::PathBuf;

use clap::Args;
use racket_impact::command::calibrate::{Calibrate, Calibrated};
use racket_impact::command::{execute, Control};
use racket_impact::study::calibrate::{self, write};
use racket_impact::{Error, Result};

use super::common::{out, print_diagnostics, Common, Format, Reporter};
use super::options::{CalibrateOptions, Options};
use super::overrides::CalibrateKeys;

#[derive(Args, Debug)]
pub struct CalibrateArgs {
    /// Measurements CSV in the schema of data/measured (columns id, quantity, value, unit,
    /// ball_speed_m_s, angle_deg, spin_in_rpm, string_tension_lb, string, support, and role and
    /// uncertainty where used) [default: the shipped data/measured/measurements.csv]
    pub measurements: Option<PathBuf>,
    #[command(flatten)]
    pub options: Options<CalibrateOptions>,
    /// Draw model against measured (held-out and validation rows marked) to this PNG
    #[arg(long, help_heading = "Output")]
    pub plot: Option<PathBuf>,
    /// Write the output (in --format) to this file, atomically, instead of standard output
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub common: Common<CalibrateKeys>,
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

/// Fit, then print (and write) the outcome.
pub fn run(a: CalibrateArgs) -> Result<()> {
    if a.common.format == Format::Csv {
        return Err(Error::invalid("format", "csv", "calibrate writes text or json"));
    }
    // (the request reads the measurements, recorded as an input of the run: no output may
    // replace it, checked here before the work)
    let mut given = a.options.0.clone();
    if let Some(path) = &a.measurements {
        given.set("measurements", path.to_string_lossy())?;
    }
    let request = Calibrate::new(&a.common.sources(), &given)?;
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
    let ctl = Control::new();
    let reporter = Reporter::start(&ctl);
    let done = execute(request, &ctl);
    drop(reporter);
    let Calibrated { outcome, source, weights, diagnostics: noted } = done?;
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
