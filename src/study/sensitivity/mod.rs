//! Global sensitivity and uncertainty propagation, independent of the model: a Saltelli
//! [`Design`] over a scrambled Sobol' sequence, inputs drawn through their distributions
//! ([`Dist`]), the model run in parallel ([`run`]) and each output summarised ([`summarise`]:
//! mean, sd, quantiles, first-order and total Sobol' indices with bootstrap intervals).
//! The same seed gives the same numbers on any number of threads.

mod design;
mod estimate;
#[cfg(test)]
mod tests;

pub use design::{Design, MAX_INPUTS, MAX_SAMPLES};
pub use estimate::{quantile_sorted, summarise, Index, Summary, BOOTSTRAP, CONFIDENCE};

use rayon::prelude::*;

use crate::error::Result;
use crate::params::uncertainty::Dist;

/// Runs evaluated per parallel chunk between progress reports.
const CHUNK: usize = 1024;

/// Run `model` at every point of `design`, the unit point mapped to input values through
/// `dists` (one per input), in parallel chunks; `progress` gets the runs done so far. Returns
/// one row of outputs per run, in run order (every row as long as the first).
pub fn run<F>(design: &Design, dists: &[Dist], model: F, mut progress: impl FnMut(usize)) -> Result<Vec<Vec<f64>>>
where
    F: Fn(&[f64]) -> Result<Vec<f64>> + Sync,
{
    assert_eq!(dists.len(), design.inputs(), "one distribution per input");
    let total = design.runs();
    let mut out = Vec::with_capacity(total);
    let mut start = 0;
    let watch = crate::control::current();
    while start < total {
        let end = (start + CHUNK).min(total);
        let chunk: Vec<Vec<f64>> = (start..end)
            .into_par_iter()
            .map(|k| {
                let x: Vec<f64> = design.point(k).iter().zip(dists).map(|(&u, d)| d.quantile(u)).collect();
                crate::control::within(watch.as_ref(), || model(&x))
            })
            .collect::<Result<_>>()?;
        out.extend(chunk);
        progress(end);
        start = end;
    }
    Ok(out)
}

/// The design with the first `samples` base rows of `design` (same seed, same points) and its
/// runs, taken from `rows` (the runs of `design`): the smaller study for free, to show how the
/// estimates move when the sample count doubles.
pub fn prefix(design: &Design, rows: &[Vec<f64>], samples: usize) -> Result<(Design, Vec<Vec<f64>>)> {
    let small = Design::new(samples.min(design.samples()) as u64, design.inputs(), design.seed())?;
    let n = design.samples();
    let runs = (0..small.runs()).map(|k| rows[(k / small.samples()) * n + k % small.samples()].clone()).collect();
    Ok((small, runs))
}

/// Summarise every output column of `rows` (as [`run`] returns them).
pub fn summarise_all(design: &Design, rows: &[Vec<f64>]) -> Vec<Summary> {
    let outputs = rows.first().map_or(0, Vec::len);
    (0..outputs)
        .into_par_iter()
        .map(|o| {
            let column: Vec<f64> = rows.iter().map(|r| r[o]).collect();
            summarise(design, &column, u64::from(design.seed()))
        })
        .collect()
}
