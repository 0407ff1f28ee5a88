//! What the time stepping reports each step to: nothing for a plain run ([`Plain`], which
//! compiles to no code in the loop), or a sampler that records the time series ([`Sampler`]).
//! The stepping loop is generic over its observer, so the series is not a branch inside it.

use crate::solve::outcome::{SeriesOptions, SeriesRow};

/// The stepping loop's observer.
pub(crate) trait Observer {
    /// Whether this observer records anything (the loop steps on after the impact only for one
    /// that does).
    const RECORDS: bool;

    /// Step (and record) at least until this time, s.
    fn t_end(&self) -> f64;

    /// Step `step` (0: the start) has ended; `row` builds its sample.
    fn observe(&mut self, step: usize, row: impl FnOnce() -> SeriesRow);
}

/// A plain run: nothing is recorded.
pub(crate) struct Plain;

impl Observer for Plain {
    const RECORDS: bool = false;

    #[inline(always)]
    fn t_end(&self) -> f64 {
        0.0
    }

    #[inline(always)]
    fn observe(&mut self, _step: usize, _row: impl FnOnce() -> SeriesRow) {}
}

/// Records every `stride`-th step.
pub(crate) struct Sampler {
    stride: usize,
    t_end: f64,
    /// The samples so far.
    pub rows: Vec<SeriesRow>,
}

impl Sampler {
    /// Samples spaced as `opts` asks, on steps of `dt` s (at least every step).
    pub fn new(opts: SeriesOptions, dt: f64) -> Self {
        Sampler { stride: ((opts.sample_dt / dt).round() as usize).max(1), t_end: opts.t_end, rows: Vec::new() }
    }
}

impl Observer for Sampler {
    const RECORDS: bool = true;

    fn t_end(&self) -> f64 {
        self.t_end
    }

    #[inline]
    fn observe(&mut self, step: usize, row: impl FnOnce() -> SeriesRow) {
        if step % self.stride == 0 {
            self.rows.push(row());
        }
    }
}
