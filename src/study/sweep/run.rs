//! The runner of a sweep: every impact in parallel chunks, streamed in the sweep's order.

use rayon::prelude::*;

use super::columns::{push_result_cells, Cell};
use super::{Sweep, MAX_POINTS};
use crate::error::Result;
use crate::params::{keys, limits, Overrides, Params};
use crate::solve::simulate;

/// Impacts computed per parallel chunk (bounded memory, deterministic order).
pub const CHUNK: usize = 4096;

impl Sweep {
    /// Run every impact in parallel chunks and hand each finished chunk's CSV rows, in order,
    /// to `sink`; `progress` gets the number of impacts done so far.
    pub fn run(&self, sink: impl FnMut(&[Vec<String>]) -> Result<()>, progress: impl FnMut(u64)) -> Result<()> {
        self.run_rows(|cells| cells.iter().map(Cell::text).collect(), sink, progress)
    }

    /// Run every impact in parallel chunks, make each impact's row with `row` from its typed
    /// cells (a cell per column of [`Sweep::header`]; `row` runs in parallel too), and hand
    /// each finished chunk's rows, in order, to `sink`; `progress` gets the number of impacts
    /// done so far. [`Sweep::run`] makes CSV rows of the cells; the Python package keeps them
    /// as numbers.
    pub fn run_rows<'s, T: Send>(
        &'s self,
        row: impl Fn(Vec<Cell<'s>>) -> T + Sync,
        mut sink: impl FnMut(&[T]) -> Result<()>,
        mut progress: impl FnMut(u64),
    ) -> Result<()> {
        let total = self.len();
        limits::check_count("sweep", total as f64, MAX_POINTS, "the impacts of a sweep (the product of the counts)")?;
        let oblique = self.is_oblique();
        let losses = self.has_losses();
        let fixed = self.fixed_keys(oblique);
        let solver_swept = self.solver_swept();
        let points = Points::of(self)?;
        let width = self.header().len();
        let mut start = 0u64;
        let watch = crate::control::current();
        while start < total {
            let end = (start + CHUNK as u64).min(total);
            let rows: Vec<T> = (start..end)
                .into_par_iter()
                .map(|i| {
                    let (p, vals) = points.at(i);
                    // (`simulate` validates the parameters, as `point` would)
                    let r =
                        crate::control::within(watch.as_ref(), || simulate(&p)).map_err(|e| self.at_point(&vals, e))?;
                    let mut cells = Vec::with_capacity(width);
                    cells.extend(vals.into_iter().map(Cell::Given));
                    cells.extend(fixed.iter().map(|k| Cell::Number(keys::value_number(k, &p).unwrap_or(f64::NAN))));
                    push_result_cells(&mut cells, &r, &p, (oblique, losses), solver_swept);
                    Ok(row(cells))
                })
                // (the first failed point in the sweep's order: the same message every run)
                .collect::<Vec<Result<T>>>()
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
pub(super) struct Points<'a> {
    sweep: &'a Sweep,
    start: Params,
    values: Vec<Vec<Overrides>>,
}

impl<'a> Points<'a> {
    pub(super) fn of(sweep: &'a Sweep) -> Result<Self> {
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
    pub(super) fn at(&self, mut i: u64) -> (Params, Vec<&'a str>) {
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
    use crate::study::sweep::parse_spec;

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
