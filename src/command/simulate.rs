//! `simulate`: one impact, with its time series if asked for.

use super::{Control, Given, Kind, Opt, Request, Work};
use crate::diagnostic::{Diagnostic, Kind as Note};
use crate::error::{Error, Result};
use crate::intake::Sources;
use crate::numfmt::sig;
use crate::params::{limits, Params, SolverKind};
use crate::solve::{FdModel, SeriesOptions, SeriesRow};
use crate::study::impact::{first_frequency_hz, Single};

/// The command.
pub const NAME: &str = "simulate";

/// Its options.
pub const OPTIONS: &[Opt] = &[
    Opt::new(
        "series",
        Kind::Switch,
        None,
        "Also record the impact's time series (t, F, y_b, Y_T, theta, every energy term); needs the fd solver",
    )
    .not_on_cli(),
    Opt::new("series-dt", Kind::Number, Some("2e-5"), "Sample spacing of the time series, s").heading("Output"),
    Opt::new("series-end", Kind::Number, Some("0"), "Extend the time series to at least this time, s")
        .heading("Output"),
];

/// One impact, checked and ready to run.
#[derive(Debug, Clone)]
pub struct Simulate {
    /// Its parameters, validated.
    pub params: Params,
    /// The notes made before it runs (what it does not use).
    noted: Vec<Diagnostic>,
    /// The time series asked for.
    series: Option<(FdModel, SeriesOptions)>,
}

/// One impact, run.
#[derive(Debug, Clone)]
pub struct Simulated {
    /// The impact with its diagnostics.
    pub single: Single,
    /// Its time series, if asked for.
    pub series: Option<Vec<SeriesRow>>,
}

impl Simulate {
    /// The impact `sources` describe, with the options `given`: a flag for an option it cannot
    /// honour is refused, one of a property it does not exercise noted; a time series is
    /// checked (its solver, its spacing, its rows counted) before anything runs.
    pub fn new(sources: &Sources, given: &Given) -> Result<Simulate> {
        let params = sources.params()?;
        let mut noted = sources.check_used(&[params])?;
        let recorded = given.switch("series")?;
        let sample_dt = given.number("series-dt")?.unwrap_or_default();
        let t_end = given.number("series-end")?.unwrap_or_default();
        if !recorded {
            for name in ["series-dt", "series-end"] {
                if given.is_given(name) {
                    return Err(Error::invalid(
                        super::Given::find(OPTIONS, name).map_or("series", |o| o.name),
                        given.text(name).unwrap_or_default(),
                        "is used only with the time series (--series)",
                    ));
                }
            }
        }
        if sample_dt <= 0.0 {
            return Err(Error::invalid("series-dt", sample_dt, "sample spacing must be a finite number > 0 s"));
        }
        if !(0.0..=10.0).contains(&t_end) {
            return Err(Error::invalid("series-end", t_end, "must satisfy 0 <= series-end <= 10 s"));
        }
        let series = if recorded {
            if params.numerics.solver != SolverKind::Fd {
                return Err(Error::invalid(
                    "solver",
                    params.numerics.solver.name(),
                    "a time series (--series) needs the fd solver: give --solver fd",
                ));
            }
            let model = FdModel::new(&params)?;
            // the rows, counted before any is made: the impact and the paper's two-period window
            // (or --series-end), one row per sample or per step, whichever is longer
            let f1_hz = first_frequency_hz(&params);
            let span = t_end.max(0.05 + 2.0 / f1_hz);
            if span / sample_dt < 2.0 {
                return Err(Error::invalid(
                    "series-dt",
                    sample_dt,
                    format!("the sample spacing must leave at least two samples over the series' {} s", sig(span, 3)),
                ));
            }
            let rows = span / sample_dt.max(model.dt);
            let most = limits::MAX_SERIES_ROWS;
            if rows.is_nan() || rows > most as f64 {
                let (field, value) =
                    if t_end > 0.05 + 2.0 / f1_hz { ("series-end", t_end) } else { ("series-dt", sample_dt) };
                return Err(Error::invalid(
                    field,
                    value,
                    format!(
                        "the time series would have about {} rows, at most {most}: a larger --series-dt or a \
                         shorter --series-end",
                        sig(rows, 2)
                    ),
                ));
            }
            if sample_dt < model.dt {
                // (the series has one row per step at most: a finer spacing is not honoured)
                noted.push(Diagnostic::new(
                    Note::NotUsed,
                    "series-dt",
                    format!(
                        "--series-dt {} s is below the solver's step {} s: the series has one row per step (spacing {} s)",
                        sig(sample_dt, 4),
                        sig(model.dt, 4),
                        sig(model.dt, 4)
                    ),
                ));
            }
            Some((model, SeriesOptions { sample_dt, t_end }))
        } else {
            None
        };
        Ok(Simulate { params, noted, series })
    }
}

impl Request for Simulate {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Simulated;

    fn work(&self, _threads: usize) -> Option<Work> {
        None
    }

    fn run(self, ctl: &Control) -> Result<Simulated> {
        ctl.begin(1, super::Unit::Impacts);
        let (result, series) = match &self.series {
            Some((model, opts)) => {
                crate::control::impact_begins();
                let run = model.run_with_series(*opts);
                crate::control::impact_done();
                let (r, s) = run?;
                (r, Some(s))
            }
            None => (crate::solve::simulate(&self.params)?, None),
        };
        Ok(Simulated { single: Single::of(self.params, result, self.noted), series })
    }
}
