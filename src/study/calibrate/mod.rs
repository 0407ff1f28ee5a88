//! `calibrate`: fit parameters that have a declared range to measured rows (the schema of
//! `data/measured`, a lab's own CSV as well), by least squares in the measured units or
//! weighted by the rows' stated scatter; then 95 % profile-likelihood intervals, the fitted
//! parameters' correlation, whether each is identifiable from the rows, a leave-one-group-out
//! error (each group refitted without it and predicted), and the model at the rows not fitted
//! (`role = validation`).
//!
//! The fit runs in each parameter's normalised coordinate `z` in `0..=1` over its range
//! (logarithmic where the range spans a decade or more): a grid first (the model's spin is not
//! smooth in its inputs: a ball that grips or slides is a different branch), then argmin's
//! Brent (one parameter) or Nelder-Mead (several) from the best grid point.

pub mod profile;
pub mod shot;
pub mod write;

use std::sync::atomic::{AtomicUsize, Ordering};

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::brent::BrentOpt;
use argmin::solver::neldermead::NelderMead;
use nalgebra::DVector;
use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::params::keys;
use crate::params::spec::{Check, ParamSpec, Values};
use crate::params::{Overrides, Params};
use crate::solve::outcome::Field;
use crate::solve::simulate;
use crate::study::measured::{Measured, Role};

/// A fitted parameter: its declaration and the range searched.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fitted {
    /// Its declaration.
    pub spec: &'static ParamSpec,
    /// The range searched, in the parameter's unit.
    pub range: (f64, f64),
    /// Whether the search runs in its logarithm (a positive range of a decade or more).
    pub log: bool,
}

impl Fitted {
    /// A parameter to fit, by key: one with a declared range (its usual range where it has one,
    /// else its valid range), or `range` within its valid range.
    pub fn new(key: &str, range: Option<(f64, f64)>) -> Result<Fitted> {
        let spec = keys::find_any(key.trim()).ok_or_else(|| {
            let known: Vec<&str> = declared().map(|s| s.key).collect();
            Error::invalid(
                "fit",
                key,
                format!("unknown parameter (parameters with a declared range: {})", known.join(", ")),
            )
        })?;
        let declared_range = declared_range(spec).ok_or_else(|| {
            let known: Vec<&str> = declared().map(|s| s.key).collect();
            Error::invalid(
                "fit",
                spec.key,
                format!(
                    "{} has no declared range to fit within (parameters with one: {})",
                    spec.what,
                    known.join(", ")
                ),
            )
        })?;
        let range = match range {
            None => declared_range,
            Some((lo, hi)) => {
                let (min, max) = match spec.check {
                    Check::Within(min, max) => (min, max),
                    _ => declared_range,
                };
                if !(lo.is_finite() && hi.is_finite() && min <= lo && lo < hi && hi <= max) {
                    return Err(Error::invalid(
                        "range",
                        format!("{}={lo}:{hi}", spec.key),
                        format!("need {min} <= LO < HI <= {max}, the valid range of {}", spec.key),
                    ));
                }
                (lo, hi)
            }
        };
        Ok(Fitted { spec, range, log: range.0 > 0.0 && range.1 / range.0 >= 10.0 })
    }

    /// The value at normalised coordinate `z` (clamped to `0..=1`).
    pub fn value(&self, z: f64) -> f64 {
        let z = z.clamp(0.0, 1.0);
        let (lo, hi) = self.range;
        if self.log {
            lo * (hi / lo).powf(z)
        } else {
            lo + z * (hi - lo)
        }
    }

    /// The normalised coordinate of `value` (clamped to the range).
    pub fn z(&self, value: f64) -> f64 {
        let (lo, hi) = self.range;
        let z = if self.log { (value / lo).ln() / (hi / lo).ln() } else { (value - lo) / (hi - lo) };
        if z.is_finite() {
            z.clamp(0.0, 1.0)
        } else {
            0.5
        }
    }
}

/// The range a parameter is fitted within by default: its usual range, else its valid range
/// (`None` for a parameter with neither: a choice, a count, or one checked by a rule alone).
pub fn declared_range(spec: &ParamSpec) -> Option<(f64, f64)> {
    if spec.values != Values::Number {
        return None;
    }
    spec.usual.or(match spec.check {
        Check::Within(lo, hi) => Some((lo, hi)),
        _ => None,
    })
}

/// The parameters that can be fitted: those with a declared range.
pub fn declared() -> impl Iterator<Item = &'static ParamSpec> {
    keys::ALL.iter().filter(|s| declared_range(s).is_some())
}

/// How the residuals are weighted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Weights {
    /// Least squares in the measured units (every fitted row in one unit).
    None,
    /// Each residual over the row's stated uncertainty (every fitted row states one).
    Uncertainty,
}

/// The groups left out one at a time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HoldOut {
    /// The rows of one string (a row without one is its own group).
    String,
    /// One row.
    Row,
    /// None.
    None,
}

impl HoldOut {
    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            HoldOut::String => "string",
            HoldOut::Row => "row",
            HoldOut::None => "none",
        }
    }
}

/// One measured row with the impact that measured it.
#[derive(Debug, Clone)]
pub struct Case {
    /// The measured row.
    pub row: Measured,
    /// Its impact (the fitted parameters are set on it for each evaluation).
    pub params: Params,
    /// The result field its quantity is.
    pub field: &'static Field,
}

impl Case {
    /// The case of `row` on `base`, or the reason the model cannot run it.
    pub fn new(base: &Params, row: &Measured) -> Result<Case> {
        let field = shot::field_of(row)?;
        let params = shot::shot(base, row)?;
        Ok(Case { row: row.clone(), params, field })
    }

    /// Its hold-out group.
    pub fn group(&self, hold_out: HoldOut) -> String {
        match hold_out {
            HoldOut::String if !self.row.string.trim().is_empty() => self.row.string.trim().to_string(),
            _ => self.row.id.clone(),
        }
    }
}

/// The rows of a measurements table sorted for a calibration: those fitted (role
/// `calibration`, or every row of a table without roles; all must run), those judged (role
/// `validation` that the model can run) and those left out with the reason.
#[derive(Debug, Clone, Default)]
pub struct Rows {
    /// Fitted.
    pub fitted: Vec<Case>,
    /// Predicted and judged, not fitted.
    pub judged: Vec<Case>,
    /// Validation rows whose shot the model cannot run: id and reason.
    pub skipped: Vec<(String, String)>,
}

impl Rows {
    /// Sort `rows` (the `only` ids if given) on `base`. A fitted row whose shot the model cannot
    /// run is an error.
    pub fn new(base: &Params, rows: &[Measured], only: &[String]) -> Result<Rows> {
        for id in only {
            if !rows.iter().any(|r| &r.id == id) {
                return Err(Error::invalid("rows", id, "no row with this id in the measurements"));
            }
        }
        let mut out = Rows::default();
        for row in rows.iter().filter(|r| only.is_empty() || only.contains(&r.id)) {
            if row.role == Some(Role::Validation) {
                match Case::new(base, row) {
                    Ok(c) => out.judged.push(c),
                    Err(e) => out.skipped.push((row.id.clone(), e.to_string())),
                }
            } else {
                out.fitted.push(Case::new(base, row)?);
            }
        }
        Ok(out)
    }
}

/// A calibration problem: the fitted parameters and rows, the weights, and the count of
/// impacts run.
#[derive(Debug)]
pub struct Problem {
    /// The parameters fitted.
    pub params: Vec<Fitted>,
    /// The rows.
    pub rows: Rows,
    /// How residuals are weighted.
    pub weights: Weights,
    /// Impacts run so far.
    pub impacts: AtomicUsize,
}

/// The rows' model values and the weighted sum of squared residuals at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Normalised coordinates of the fitted parameters.
    pub z: Vec<f64>,
    /// Weighted sum of squared residuals over the fitted rows.
    pub ssr: f64,
}

impl Problem {
    /// Check the fit is posed: no parameter twice, at least as many fitted rows as parameters,
    /// the weights defined (one unit unweighted; a stated positive uncertainty on every row
    /// weighted), every fitted row run once at the parameters' start.
    pub fn new(params: Vec<Fitted>, rows: Rows, weights: Weights) -> Result<Problem> {
        if params.is_empty() {
            return Err(Error::invalid("fit", "(none)", "give at least one parameter to fit (--fit KEY[,KEY...])"));
        }
        for (i, p) in params.iter().enumerate() {
            if params[..i].iter().any(|q| q.spec.key == p.spec.key) {
                return Err(Error::invalid("fit", p.spec.key, "is given twice; fit each parameter once"));
            }
        }
        let n = rows.fitted.len();
        if n < params.len() {
            return Err(Error::invalid(
                "rows",
                n,
                format!(
                    "{} parameters cannot be fitted to {n} rows (role calibration): need at least as many rows as parameters",
                    params.len()
                ),
            ));
        }
        match weights {
            Weights::None => {
                let first = rows.fitted[0].row.unit.trim();
                if let Some(other) = rows.fitted.iter().find(|c| c.row.unit.trim() != first) {
                    return Err(Error::invalid(
                        "weights",
                        "none",
                        format!(
                            "rows {} ({first}) and {} ({}) are in different units: least squares needs one unit, or \
                             --weights uncertainty",
                            rows.fitted[0].row.id,
                            other.row.id,
                            other.row.unit.trim()
                        ),
                    ));
                }
            }
            Weights::Uncertainty => {
                if let Some(c) =
                    rows.fitted.iter().find(|c| !c.row.uncertainty.is_some_and(|u| u > 0.0 && u.is_finite()))
                {
                    return Err(Error::invalid(
                        "weights",
                        "uncertainty",
                        format!("row {} states no positive uncertainty to weight it by", c.row.id),
                    ));
                }
            }
        }
        for p in &params {
            let shots: Vec<Params> = rows.fitted.iter().map(|c| c.params).collect();
            if let Some((spec, unused)) = crate::params::used::first_unused(&[p.spec], &shots) {
                return Err(Error::invalid(
                    "fit",
                    spec.key,
                    format!("no fitted row uses it: {} is {}", spec.key, unused.why),
                ));
            }
            // a key the rows set themselves: a fitted value would overwrite each row's own (a
            // named string's friction has its own message below)
            let own: Vec<(&str, &str)> = rows
                .fitted
                .iter()
                .filter_map(|c| {
                    shot::sets(&c.row, p.spec.key).filter(|&col| col != "string").map(|col| (c.row.id.as_str(), col))
                })
                .collect();
            if let Some(&(_, column)) = own.first() {
                let ids: Vec<&str> = own.iter().map(|(id, _)| *id).collect();
                return Err(Error::invalid(
                    "fit",
                    p.spec.key,
                    format!(
                        "rows {} set {} themselves (column {column}{}): a fitted value would overwrite each row's own; \
                         fit a constant the rows leave open",
                        if ids.len() > 8 {
                            format!("{} and {} more", ids[..8].join(" "), ids.len() - 8)
                        } else {
                            ids.join(" ")
                        },
                        p.spec.key,
                        if column == "support" { ": a clamped racket" } else { "" },
                    ),
                ));
            }
            for c in &rows.fitted {
                if let Some(id) = crate::params::strings::sets(c.params.oblique.string, p.spec.key) {
                    return Err(Error::invalid(
                        "fit",
                        p.spec.key,
                        format!(
                            "row {} names string {id}, whose data/strings entry sets {}: a string's own property is \
                             measured, not fitted",
                            c.row.id, p.spec.key
                        ),
                    ));
                }
            }
        }
        let problem = Problem { params, rows, weights, impacts: AtomicUsize::new(0) };
        let start = problem.start();
        problem.values(&problem.rows.fitted, &start).map_err(|e| match e {
            Error::AtPoint { point, source } => {
                Error::invalid("row", point, format!("the model cannot run its shot: {source}"))
            }
            other => other,
        })?;
        Ok(problem)
    }

    /// The start: each parameter's declared default (the paper's parameters), clamped to its
    /// range; a value given for a fitted parameter is not used.
    pub fn start(&self) -> Vec<f64> {
        let p = Params::paper();
        self.params.iter().map(|f| f.z(keys::value_number(f.spec.key, &p).unwrap_or(f64::NAN))).collect()
    }

    /// The parameters of `case` at normalised coordinates `z`.
    pub fn params_at(&self, case: &Case, z: &[f64]) -> Result<Params> {
        let mut o = Overrides::default();
        for (f, &z) in self.params.iter().zip(z) {
            o.set(f.spec.key, &f.value(z).to_string())?;
        }
        let mut p = case.params;
        o.apply(&mut p);
        p.validate()?;
        Ok(p)
    }

    /// The model value of each of `cases` at `z` (all cores); an impact that fails is an error
    /// naming its row.
    pub fn values(&self, cases: &[Case], z: &[f64]) -> Result<Vec<f64>> {
        self.impacts.fetch_add(cases.len(), Ordering::Relaxed);
        let watch = crate::control::current();
        cases
            .par_iter()
            .map(|c| {
                let r = crate::control::within(watch.as_ref(), || simulate(&self.params_at(c, z)?))
                    .map_err(|e| Error::AtPoint { point: c.row.id.clone(), source: Box::new(e) })?;
                Ok(c.field.number(&r))
            })
            .collect()
    }

    /// The weight of a case's residual (its divisor).
    pub fn scale(&self, case: &Case) -> f64 {
        match self.weights {
            Weights::None => 1.0,
            Weights::Uncertainty => case.row.uncertainty.unwrap_or(1.0),
        }
    }

    /// The weighted sum of squared residuals over `cases` at `z`; +inf where the model fails or
    /// a value is not finite (the search then avoids the point).
    pub fn ssr(&self, cases: &[Case], z: &[f64]) -> f64 {
        match self.values(cases, z) {
            Ok(v) => {
                let s: f64 = v.iter().zip(cases).map(|(m, c)| ((m - c.row.value) / self.scale(c)).powi(2)).sum();
                if s.is_finite() {
                    s
                } else {
                    f64::INFINITY
                }
            }
            Err(_) => f64::INFINITY,
        }
    }

    /// The least-squares fit over `cases` with the parameters `free` (indices into
    /// [`Problem::params`]) searched and the others held at `fixed` (normalised coordinates of
    /// every parameter; the free entries are the start). One or two free parameters: nested
    /// line searches (each a grid, then Brent in the best cell), since the sum of squares has
    /// narrow valleys where a ball turns from gripping to sliding; more: Nelder-Mead from the
    /// best points of a grid.
    pub fn fit_some(&self, cases: &[Case], free: &[usize], fixed: &[f64]) -> Result<Point> {
        match free {
            [] => Ok(Point { z: fixed.to_vec(), ssr: self.ssr(cases, fixed) }),
            [i] => {
                let at = |v: f64| {
                    let mut z = fixed.to_vec();
                    z[*i] = v;
                    z
                };
                let (v, s) = line(fixed[*i], |v| self.ssr(cases, &at(v)))?;
                Ok(Point { z: at(v), ssr: s })
            }
            [i, rest @ ..] if rest.len() == 1 => {
                let at = |v: f64| {
                    let mut z = fixed.to_vec();
                    z[*i] = v;
                    z
                };
                let inner = |v: f64| self.fit_some(cases, rest, &at(v)).map_or(f64::INFINITY, |p| p.ssr);
                let (v, _) = line(fixed[*i], inner)?;
                self.fit_some(cases, rest, &at(v))
            }
            _ => self.simplex(cases, free, fixed),
        }
    }

    /// Nelder-Mead over the `free` coordinates from each of the best points of a grid.
    fn simplex(&self, cases: &[Case], free: &[usize], fixed: &[f64]) -> Result<Point> {
        let at = |zf: &[f64]| -> Vec<f64> {
            let mut z = fixed.to_vec();
            for (&i, &v) in free.iter().zip(zf) {
                z[i] = v;
            }
            z
        };
        let per = if free.len() == 3 { 5 } else { 3 };
        let mut grid: Vec<(Vec<f64>, f64)> = Vec::new();
        let start: Vec<f64> = free.iter().map(|&i| fixed[i]).collect();
        grid.push((start.clone(), self.ssr(cases, &at(&start))));
        let total = (per as u64).pow(free.len() as u32);
        for k in 0..total {
            let mut rest = k;
            let zf: Vec<f64> = (0..free.len())
                .map(|_| {
                    let j = rest % per as u64;
                    rest /= per as u64;
                    (j as f64 + 0.5) / per as f64
                })
                .collect();
            let s = self.ssr(cases, &at(&zf));
            grid.push((zf, s));
        }
        // the best points first (a stable sort: ties keep the grid's order)
        grid.sort_by(|a, b| a.1.total_cmp(&b.1));
        let (z0, s0) = grid[0].clone();
        if !s0.is_finite() {
            return Err(Error::invalid("fit", "(all)", "the model failed at every point of the search grid"));
        }
        let h = 0.5 / per as f64;
        let mut best = (z0, s0);
        for (start, _) in grid.iter().take(STARTS).filter(|(_, s)| s.is_finite()) {
            let mut simplex = vec![DVector::from_column_slice(start)];
            for i in 0..start.len() {
                let mut v = DVector::from_column_slice(start);
                v[i] = if v[i] + h <= 1.0 { v[i] + h } else { v[i] - h };
                simplex.push(v);
            }
            let cost = Cost { f: |z: &[f64]| penalised(|q| self.ssr(cases, &at(q)), z) };
            let solver = NelderMead::new(simplex)
                .with_sd_tolerance(1e-8)
                .map_err(|e| Error::invalid("fit", "nelder-mead", e.to_string()))?;
            let res = Executor::new(cost, solver)
                .configure(|s| s.max_iters(400))
                .run()
                .map_err(|e| Error::invalid("fit", "nelder-mead", e.to_string()))?;
            let z: Vec<f64> = res.state().get_best_param().map_or(start.clone(), |p| p.as_slice().to_vec());
            let z: Vec<f64> = z.iter().map(|v| v.clamp(0.0, 1.0)).collect();
            let s = self.ssr(cases, &at(&z));
            if s < best.1 {
                best = (z, s);
            }
        }
        Ok(Point { z: at(&best.0), ssr: best.1 })
    }

    /// The fit of every parameter over `cases`.
    pub fn fit(&self, cases: &[Case]) -> Result<Point> {
        let all: Vec<usize> = (0..self.params.len()).collect();
        self.fit_some(cases, &all, &self.start())
    }
}

/// Grid points of a line search over `0..=1`.
const LINE_GRID: usize = 17;

/// The minimum of `f` over `0..=1`: the best of a grid (with `start`), then Brent within one
/// grid cell of it (argmin's `BrentOpt`). An error if `f` is infinite at every grid point.
fn line(start: f64, f: impl Fn(f64) -> f64) -> Result<(f64, f64)> {
    let mut best = (start, f(start));
    for k in 0..LINE_GRID {
        let z = (k as f64 + 0.5) / LINE_GRID as f64;
        let s = f(z);
        if s < best.1 {
            best = (z, s);
        }
    }
    if !best.1.is_finite() {
        return Err(Error::invalid("fit", "(all)", "the model failed at every point of the search grid"));
    }
    let h = 1.0 / LINE_GRID as f64;
    let (a, b) = ((best.0 - h).max(0.0), (best.0 + h).min(1.0));
    let solver = BrentOpt::new(a, b).set_tolerance(1e-6, 1e-6);
    let res = Executor::new(OneDim(|z: f64| f(z)), solver)
        .configure(|s| s.param(best.0).max_iters(60))
        .run()
        .map_err(|e| Error::invalid("fit", "brent", e.to_string()))?;
    let z = res.state().get_best_param().copied().unwrap_or(best.0);
    let s = res.state().get_best_cost();
    Ok(if s < best.1 { (z, s) } else { best })
}

/// The grid points Nelder-Mead starts from, best first.
const STARTS: usize = 3;

/// `f` at `z` clamped into the unit box, plus a penalty growing with the distance outside it
/// (Nelder-Mead is unconstrained; the parameters are not).
fn penalised(f: impl Fn(&[f64]) -> f64, z: &[f64]) -> f64 {
    let clamped: Vec<f64> = z.iter().map(|v| v.clamp(0.0, 1.0)).collect();
    let outside: f64 = z.iter().zip(&clamped).map(|(a, b)| (a - b).powi(2)).sum();
    let v = f(&clamped);
    if outside > 0.0 {
        v * (1.0 + 1e3 * outside) + 1e3 * outside
    } else {
        v
    }
}

/// A cost function over a parameter vector for argmin.
struct Cost<F: Fn(&[f64]) -> f64> {
    f: F,
}

impl<F: Fn(&[f64]) -> f64> CostFunction for Cost<F> {
    type Param = DVector<f64>;
    type Output = f64;
    fn cost(&self, p: &Self::Param) -> std::result::Result<f64, argmin::core::Error> {
        Ok((self.f)(p.as_slice()))
    }
}

/// A cost function over one number, for Brent.
struct OneDim<F: Fn(f64) -> f64>(F);

impl<F: Fn(f64) -> f64> CostFunction for OneDim<F> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, p: &f64) -> std::result::Result<f64, argmin::core::Error> {
        Ok((self.0)(*p))
    }
}

/// One row's measured value beside the model's.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// The row id.
    pub id: String,
    /// Its hold-out group (its string, or its id).
    pub group: String,
    /// Its quantity.
    pub quantity: String,
    /// Its unit.
    pub unit: String,
    /// Measured.
    pub measured: f64,
    /// The model at the fit.
    pub model: f64,
    /// The model at the fit made without the row's group (NaN where that fit is not posed, or
    /// for a row not fitted).
    pub held_out: f64,
}

/// A fitted parameter's estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// The parameter key.
    pub key: &'static str,
    /// Its unit.
    pub unit: &'static str,
    /// The range searched.
    pub range: (f64, f64),
    /// The fitted value.
    pub value: f64,
    /// The 95 % profile-likelihood interval; an end at the range's end where the profile never
    /// rose to the threshold on that side (`open`).
    pub interval: (f64, f64),
    /// Whether each end of the interval is the range's end (the rows do not bound it there).
    pub open: (bool, bool),
    /// Whether the rows bound it on both sides, with the reason where they do not.
    pub identifiable: profile::Identifiable,
}

/// A calibration's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    /// Each parameter's estimate.
    pub estimates: Vec<Estimate>,
    /// The parameters' correlation matrix at the fit (from the Jacobian); NaN where singular.
    pub correlation: Vec<Vec<f64>>,
    /// The weighted sum of squared residuals at the fit.
    pub ssr: f64,
    /// The fitted rows.
    pub fitted: Vec<Prediction>,
    /// The rows judged, not fitted.
    pub judged: Vec<Prediction>,
    /// Validation rows not run: id and reason.
    pub skipped: Vec<(String, String)>,
    /// The groups left out.
    pub hold_out: HoldOut,
    /// Impacts run.
    pub impacts: usize,
    /// The tangential law of the fitted rows' impacts.
    pub tangential: crate::params::TangentialLaw,
    /// The solver of the (first) fitted row's impact.
    pub solver: crate::params::SolverKind,
}

impl Calibration {
    /// The RMS error of the fitted rows at the fit (in-sample).
    pub fn rms_in_sample(&self) -> f64 {
        crate::study::stats::rms(self.fitted.iter().map(|p| p.model - p.measured))
    }

    /// The RMS error of the fitted rows each predicted by the fit without its group.
    pub fn rms_held_out(&self) -> f64 {
        crate::study::stats::rms(self.fitted.iter().map(|p| p.held_out - p.measured))
    }

    /// The RMS error of the judged (validation) rows.
    pub fn rms_judged(&self) -> f64 {
        crate::study::stats::rms(self.judged.iter().map(|p| p.model - p.measured))
    }
}

/// Run a calibration: fit, intervals and correlation, leave-one-group-out, the judged rows.
pub fn calibrate(problem: &Problem, hold_out: HoldOut) -> Result<Calibration> {
    calibrate_with(problem, hold_out, true)
}

/// [`calibrate`], with the profile-likelihood intervals only where `intervals` (they cost the
/// most: each point of a profile is a fit of the other parameters).
pub fn calibrate_with(problem: &Problem, hold_out: HoldOut, intervals: bool) -> Result<Calibration> {
    let cases = &problem.rows.fitted;
    // (by string where no fitted row names one is by row)
    let hold_out = if hold_out == HoldOut::String && cases.iter().all(|c| c.row.string.trim().is_empty()) {
        HoldOut::Row
    } else {
        hold_out
    };
    let best = problem.fit(cases)?;
    let model = problem.values(cases, &best.z)?;
    let (estimates, correlation) =
        if intervals { profile::estimates(problem, &best)? } else { profile::points(problem, &best)? };
    // leave one group out: refit without it, predict it
    let mut held_out = vec![f64::NAN; cases.len()];
    if hold_out != HoldOut::None {
        let mut groups: Vec<String> = Vec::new();
        for c in cases {
            let g = c.group(hold_out);
            if !groups.contains(&g) {
                groups.push(g);
            }
        }
        if groups.len() >= 2 {
            for g in &groups {
                let (out, keep): (Vec<usize>, Vec<usize>) =
                    (0..cases.len()).partition(|&i| &cases[i].group(hold_out) == g);
                if keep.len() < problem.params.len() {
                    continue;
                }
                let kept: Vec<Case> = keep.iter().map(|&i| cases[i].clone()).collect();
                let fit = problem.fit(&kept)?;
                let left: Vec<Case> = out.iter().map(|&i| cases[i].clone()).collect();
                for (&i, v) in out.iter().zip(problem.values(&left, &fit.z)?) {
                    held_out[i] = v;
                }
            }
        }
    }
    let prediction = |c: &Case, model: f64, held: f64| Prediction {
        id: c.row.id.clone(),
        group: c.group(hold_out),
        quantity: c.row.quantity.clone(),
        unit: c.row.unit.clone(),
        measured: c.row.value,
        model,
        held_out: held,
    };
    let fitted = cases.iter().zip(&model).zip(&held_out).map(|((c, &m), &h)| prediction(c, m, h)).collect();
    let judged_values = problem.values(&problem.rows.judged, &best.z)?;
    let judged = problem.rows.judged.iter().zip(judged_values).map(|(c, m)| prediction(c, m, f64::NAN)).collect();
    Ok(Calibration {
        estimates,
        correlation,
        ssr: best.ssr,
        fitted,
        judged,
        skipped: problem.rows.skipped.clone(),
        hold_out,
        impacts: problem.impacts.load(Ordering::Relaxed),
        tangential: cases[0].params.oblique.tangential,
        solver: cases[0].params.numerics.solver,
    })
}
