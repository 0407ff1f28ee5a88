//! The fitted parameters' 95 % profile-likelihood intervals, their correlation, and whether the
//! rows identify each one.
//!
//! The profile of parameter `j` is the least sum of squares with `j` held at a value and the
//! others refitted. With the residuals' scale estimated from the fit (unweighted, or weighted
//! by the rows' stated scatter alike), the interval is where the profile stays below
//! `S_min (1 + F(0.95; 1, n - p) / (n - p))` (Bates and Watts 1988, section 6.1); `n` rows,
//! `p` parameters. An end where the profile never rises that far before the range ends is
//! open: the rows do not bound the parameter on that side.

use nalgebra::DMatrix;
use statrs::distribution::{ContinuousCDF, FisherSnedecor};

use super::{Estimate, Point, Problem};
use crate::error::Result;

/// Whether the rows identify a fitted parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Identifiable {
    /// The 95 % interval is bounded on both sides.
    Yes,
    /// No fitted row's model value depends on it.
    Unused,
    /// The interval reaches both ends of the range searched.
    Unbounded,
    /// The interval reaches one end of the range.
    OneSided,
    /// As many rows as parameters: no residual scatter to set an interval by.
    NoDof,
    /// Not computed (the fit alone was asked for).
    NotComputed,
}

impl Identifiable {
    /// The verdict in words.
    pub fn sentence(self) -> &'static str {
        match self {
            Identifiable::Yes => "identifiable (95 % interval bounded on both sides)",
            Identifiable::Unused => "not identifiable: no fitted row's model value depends on it",
            Identifiable::Unbounded => {
                "not identifiable from these rows: the 95 % interval spans the whole range searched"
            }
            Identifiable::OneSided => {
                "bounded on one side only: the 95 % interval reaches an end of the range searched"
            }
            Identifiable::NoDof => "no interval: as many rows as parameters leave no residual scatter",
            Identifiable::NotComputed => "interval not computed",
        }
    }

    /// A short name (JSON).
    pub fn name(self) -> &'static str {
        match self {
            Identifiable::Yes => "yes",
            Identifiable::Unused => "unused",
            Identifiable::Unbounded => "unbounded",
            Identifiable::OneSided => "one_sided",
            Identifiable::NoDof => "no_dof",
            Identifiable::NotComputed => "not_computed",
        }
    }
}

/// The threshold of the profile's 95 % interval: `S_min (1 + F(0.95; 1, dof) / dof)`.
pub fn threshold(ssr_min: f64, dof: usize) -> f64 {
    let f = FisherSnedecor::new(1.0, dof as f64).map_or(f64::NAN, |d| d.inverse_cdf(0.95));
    ssr_min * (1.0 + f / dof as f64)
}

/// The profile of parameter `j` at normalised coordinate `zj`, from the fit `best`.
fn profile(problem: &Problem, best: &Point, j: usize, zj: f64) -> Result<f64> {
    let mut fixed = best.z.clone();
    fixed[j] = zj;
    let free: Vec<usize> = (0..problem.params.len()).filter(|&i| i != j).collect();
    Ok(problem.fit_some(&problem.rows.fitted, &free, &fixed)?.ssr)
}

/// One end of the interval of parameter `j`, searching from the fit towards `dir` (+1 or -1):
/// the coordinate where the profile crosses `limit`, or the range's end (open).
fn end(problem: &Problem, best: &Point, j: usize, limit: f64, dir: f64) -> Result<(f64, bool)> {
    const STEP: f64 = 1.0 / 16.0;
    let mut inside = best.z[j];
    loop {
        let next = (inside + dir * STEP).clamp(0.0, 1.0);
        if next == inside {
            return Ok((inside, true));
        }
        if profile(problem, best, j, next)? > limit {
            let mut outside = next;
            for _ in 0..7 {
                let mid = 0.5 * (inside + outside);
                if profile(problem, best, j, mid)? > limit {
                    outside = mid;
                } else {
                    inside = mid;
                }
            }
            return Ok((0.5 * (inside + outside), false));
        }
        inside = next;
    }
}

/// Each parameter's value at the fit without an interval, and the correlation matrix.
pub fn points(problem: &Problem, best: &Point) -> Result<(Vec<Estimate>, Vec<Vec<f64>>)> {
    let out = problem
        .params
        .iter()
        .enumerate()
        .map(|(j, f)| Estimate {
            key: f.spec.key,
            unit: f.spec.unit,
            range: f.range,
            value: f.value(best.z[j]),
            interval: (f64::NAN, f64::NAN),
            open: (false, false),
            identifiable: Identifiable::NotComputed,
        })
        .collect();
    Ok((out, correlation(problem, best)?))
}

/// Each parameter's estimate with its interval and verdict, and the correlation matrix.
pub fn estimates(problem: &Problem, best: &Point) -> Result<(Vec<Estimate>, Vec<Vec<f64>>)> {
    let cases = &problem.rows.fitted;
    let n = cases.len();
    let p = problem.params.len();
    let limit = if n > p { threshold(best.ssr, n - p) } else { f64::NAN };
    let mut out = Vec::new();
    for (j, f) in problem.params.iter().enumerate() {
        // does any row depend on it at all?
        let mut lo = best.z.clone();
        lo[j] = 0.0;
        let mut hi = best.z.clone();
        hi[j] = 1.0;
        let unused = problem.values(cases, &lo)? == problem.values(cases, &hi)?;
        let (interval, open, identifiable) = if unused {
            (f.range, (true, true), Identifiable::Unused)
        } else if n <= p {
            ((f64::NAN, f64::NAN), (false, false), Identifiable::NoDof)
        } else {
            let (a, open_lo) = end(problem, best, j, limit, -1.0)?;
            let (b, open_hi) = end(problem, best, j, limit, 1.0)?;
            let verdict = match (open_lo, open_hi) {
                (true, true) => Identifiable::Unbounded,
                (false, false) => Identifiable::Yes,
                _ => Identifiable::OneSided,
            };
            ((f.value(a), f.value(b)), (open_lo, open_hi), verdict)
        };
        out.push(Estimate {
            key: f.spec.key,
            unit: f.spec.unit,
            range: f.range,
            value: f.value(best.z[j]),
            interval,
            open,
            identifiable,
        });
    }
    Ok((out, correlation(problem, best)?))
}

/// The correlation of the fitted parameters (in their normalised coordinates) from the
/// Jacobian of the weighted residuals at the fit, central differences of 1 % of the range
/// (one-sided at an end); NaN where `J^T J` is singular.
pub fn correlation(problem: &Problem, best: &Point) -> Result<Vec<Vec<f64>>> {
    let cases = &problem.rows.fitted;
    let p = problem.params.len();
    let h = 0.01;
    let mut jac = DMatrix::<f64>::zeros(cases.len(), p);
    for j in 0..p {
        let (mut a, mut b) = (best.z.clone(), best.z.clone());
        a[j] = (best.z[j] - h).max(0.0);
        b[j] = (best.z[j] + h).min(1.0);
        let (va, vb) = (problem.values(cases, &a)?, problem.values(cases, &b)?);
        for (i, c) in cases.iter().enumerate() {
            jac[(i, j)] = (vb[i] - va[i]) / (b[j] - a[j]) / problem.scale(c);
        }
    }
    let jtj = jac.transpose() * &jac;
    let nan = vec![vec![f64::NAN; p]; p];
    let Some(cov) = jtj.try_inverse() else {
        return Ok(nan);
    };
    if (0..p).any(|i| !(cov[(i, i)] > 0.0 && cov[(i, i)].is_finite())) {
        return Ok(nan);
    }
    Ok((0..p).map(|i| (0..p).map(|k| cov[(i, k)] / (cov[(i, i)] * cov[(k, k)]).sqrt()).collect()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F(0.95; 1, 4) = 7.7086 (tables): the threshold is S (1 + 7.7086 / 4).
    #[test]
    fn the_threshold_is_the_f_quantile() {
        assert!((threshold(4.0, 4) - 4.0 * (1.0 + 7.7086 / 4.0)).abs() < 1e-3);
        assert_eq!(threshold(0.0, 3), 0.0);
    }
}
