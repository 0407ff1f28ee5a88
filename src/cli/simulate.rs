//! `simulate`: one impact, as text, JSON or CSV, with an optional time series.

use std::path::PathBuf;

use clap::Args;
use racket_impact::diagnostic::{Diagnostic, Kind};
use racket_impact::numfmt::sig;
use racket_impact::solve::{FdModel, SeriesOptions};
use racket_impact::{Error, Result};

use super::common::{out, print_diagnostics, Common, Format};
use super::overrides::SimulateKeys;

/// Sample spacing of the time series unless given, s.
const DEFAULT_SERIES_DT: f64 = 2.0e-5;
/// Least end time of the time series unless given, s.
const DEFAULT_SERIES_END: f64 = 0.0;

#[derive(Args, Debug)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub common: Common<SimulateKeys>,
    /// Also write the impact's time series (t, F, y_b, Y_T, theta, every energy term) as CSV
    #[arg(long, help_heading = "Output")]
    pub series: Option<PathBuf>,
    /// Sample spacing of the time series, s
    #[arg(long, value_parser = super::common::number, default_value_t = DEFAULT_SERIES_DT, allow_hyphen_values = true, help_heading = "Output")]
    pub series_dt: f64,
    /// Extend the time series to at least this time, s
    #[arg(long, value_parser = super::common::number, default_value_t = DEFAULT_SERIES_END, allow_hyphen_values = true, help_heading = "Output")]
    pub series_end: f64,
}

/// One impact; fail early, before any computation, when an output file's directory does not
/// exist.
pub fn run(a: SimulateArgs) -> Result<()> {
    let params = a.common.sources().params()?;
    let mut noted = a.common.check_used([&params])?;
    if let Some(path) = &a.series {
        racket_impact::render::io::check_output_dir("series", path)?;
    }
    if a.series.is_none() {
        for (flag, given, default) in
            [("series-dt", a.series_dt, DEFAULT_SERIES_DT), ("series-end", a.series_end, DEFAULT_SERIES_END)]
        {
            if given != default {
                return Err(Error::invalid(flag, given, "is used only with --series FILE (the time series)"));
            }
        }
    }
    if !(a.series_dt.is_finite() && a.series_dt > 0.0) {
        return Err(Error::invalid("series-dt", a.series_dt, "sample spacing must be a finite number > 0 s"));
    }
    if !(a.series_end.is_finite() && (0.0..=10.0).contains(&a.series_end)) {
        return Err(Error::invalid("series-end", a.series_end, "must satisfy 0 <= series-end <= 10 s"));
    }
    let (result, series) = if let Some(path) = &a.series {
        if params.numerics.solver != racket_impact::params::SolverKind::Fd {
            return Err(Error::invalid("series", path.display(), "a time series needs --solver fd"));
        }
        let model = FdModel::new(&params)?;
        // the rows, counted before any is made: the impact and the paper's two-period window
        // (or --series-end), one row per sample or per step, whichever is longer
        let f1_hz = racket_impact::model::basis::Basis::of(&params.racket, params.numerics.segments).omega[0]
            / (2.0 * std::f64::consts::PI);
        let span = a.series_end.max(0.05 + 2.0 / f1_hz);
        if span / a.series_dt < 2.0 {
            return Err(Error::invalid(
                "series-dt",
                a.series_dt,
                format!("the sample spacing must leave at least two samples over the series' {} s", sig(span, 3)),
            ));
        }
        let rows = span / a.series_dt.max(model.dt);
        let most = racket_impact::params::limits::MAX_SERIES_ROWS;
        if rows.is_nan() || rows > most as f64 {
            let (field, value) = if a.series_end > 0.05 + 2.0 / f1_hz {
                ("series-end", a.series_end)
            } else {
                ("series-dt", a.series_dt)
            };
            return Err(Error::invalid(
                field,
                value,
                format!("the time series would have about {} rows, at most {most}: a larger --series-dt or a shorter --series-end", sig(rows, 2)),
            ));
        }
        if a.series_dt < model.dt {
            // (the series has one row per step at most: a finer spacing is not honoured)
            noted.push(Diagnostic::new(
                Kind::NotUsed,
                "series-dt",
                format!(
                    "--series-dt {} s is below the solver's step {} s: the series has one row per step (spacing {} s)",
                    sig(a.series_dt, 4),
                    sig(model.dt, 4),
                    sig(model.dt, 4)
                ),
            ));
        }
        let (r, s) = model.run_with_series(SeriesOptions { sample_dt: a.series_dt, t_end: a.series_end })?;
        (r, Some(s))
    } else {
        (racket_impact::simulate(&params)?, None)
    };
    let single = racket_impact::study::impact::Single::of(params, result, noted);
    let text = match a.common.format {
        Format::Json => racket_impact::render::json::pretty(&single.json()?)?,
        Format::Csv => racket_impact::render::impact::result_csv(&single.params, &single.result),
        Format::Text => racket_impact::render::impact::result_text(&single.params, &single.result),
    };
    // a series device is written before the result is printed, a series file renamed after
    let mut staged = racket_impact::render::io::Staged::new();
    if let (Some(path), Some(rows)) = (&a.series, &series) {
        racket_impact::render::impact::stage_series(&mut staged, path, &single.params, rows)?;
    }
    staged.publish(|| {
        out!("{text}");
        Ok(())
    })?;
    print_diagnostics(&single.diagnostics);
    Ok(())
}
