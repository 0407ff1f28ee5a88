//! `sweep`: the cartesian product of ranges or lists of any parameters, run in parallel chunks
//! and handed, chunk by chunk in the sweep's order, to the front end's sink (a CSV file, the
//! Python package's columns): memory stays flat however many impacts a sweep has.

use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

use super::{Control, Given, Opt, Request, Unit, Work, LONG};
use crate::diagnostic::Diagnostic;
use crate::error::Result;
use crate::params::Params;
use crate::study::sweep::{Cell, Sweep};

/// The command.
pub const NAME: &str = "sweep";

/// Its options (the swept parameters are its `--KEY SPEC` pairs).
pub const OPTIONS: &[Opt] = &[LONG];

/// A sweep, checked and ready to run.
#[derive(Debug, Clone)]
pub struct SweepRequest {
    /// The sweep.
    pub sweep: Sweep,
    /// One impact per bounding value of each axis (the plausibility warnings).
    representatives: Vec<Params>,
    /// The notes made before it runs (a swept property none of its impacts exercises, a config
    /// file's unused keys).
    noted: Vec<Diagnostic>,
    long: bool,
}

impl SweepRequest {
    /// The sweep of the `--KEY SPEC` `pairs` over the defaults of `racket` and the `config` file,
    /// with the options `given`: every point validated, a swept option no impact can honour
    /// refused, one none exercises noted.
    pub fn new(racket: Option<&str>, config: Option<&Path>, pairs: &[String], given: &Given) -> Result<SweepRequest> {
        let sweep = Sweep::from_pairs(racket, config, pairs)?;
        let representatives = sweep.representatives()?;
        let noted = sweep.check_used(&representatives, config)?;
        Ok(SweepRequest { sweep, representatives, noted, long: given.switch("long")? })
    }

    /// The columns of its rows.
    pub fn header(&self) -> Vec<String> {
        self.sweep.header()
    }

    /// Its impacts.
    pub fn len(&self) -> u64 {
        self.sweep.len()
    }

    /// Whether it has none (never: an empty axis is refused).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The request run with each impact's row made by `row` from its cells (a cell per column
    /// of [`SweepRequest::header`]; in parallel) and each finished chunk's rows handed to `sink`
    /// in the sweep's order.
    pub fn stream<T, R, S>(self, row: R, sink: S) -> Streaming<R, S>
    where
        T: Send,
        R: for<'s> Fn(Vec<Cell<'s>>) -> T + Sync,
        S: FnMut(&[T]) -> Result<()>,
    {
        Streaming { request: self, row, sink }
    }
}

/// A sweep with its row maker and its sink ([`SweepRequest::stream`]).
pub struct Streaming<R, S> {
    request: SweepRequest,
    row: R,
    sink: S,
}

/// A sweep run: its sink (what it kept) and the diagnostics.
#[derive(Debug)]
pub struct Swept<S> {
    /// The sink, after the last chunk.
    pub sink: S,
    /// The notes made before the run, the parameters outside their usual ranges and the
    /// largest twist beyond the small-angle model.
    pub diagnostics: Vec<Diagnostic>,
}

impl<T, R, S> Request for Streaming<R, S>
where
    T: Send,
    R: for<'s> Fn(Vec<Cell<'s>>) -> T + Sync,
    S: FnMut(&[T]) -> Result<()>,
{
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Swept<S>;

    fn work(&self, threads: usize) -> Option<Work> {
        let r = &self.request;
        Some(Work {
            estimate: r.sweep.estimate(threads),
            asked: format!("a sweep of {} impacts", r.len()),
            fewer: "fewer impacts",
            long: r.long,
        })
    }

    fn run(self, ctl: &Control) -> Result<Swept<S>> {
        let Streaming { request, row, mut sink } = self;
        ctl.begin(request.len(), Unit::Impacts);
        let theta_column = request.header().iter().position(|c| c == "theta_end_deg");
        // the twist of the largest magnitude, kept as its bits (rows are made in parallel)
        let theta_max = AtomicU64::new(0.0f64.to_bits());
        request.sweep.run_rows(
            |cells| {
                if let Some(Cell::Number(theta)) = theta_column.and_then(|k| cells.get(k)) {
                    let _ = theta_max.fetch_update(Ordering::Relaxed, Ordering::Relaxed, |bits| {
                        (theta.abs() > f64::from_bits(bits).abs()).then_some(theta.to_bits())
                    });
                }
                row(cells)
            },
            &mut sink,
            |done| ctl.set_done(done),
        )?;
        let theta = f64::from_bits(theta_max.load(Ordering::Relaxed));
        let diagnostics = crate::study::sweep::diagnostics(&request.noted, &request.representatives, theta);
        Ok(Swept { sink, diagnostics })
    }
}
