//! Running a map: one impact at every grid point inside the face, in parallel chunks, for one
//! configuration or two on a shared grid, and what can be read off the results.

use rayon::prelude::*;
use serde::Serialize;

use super::{Face, Grid, Quantity, CHUNK};
use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::params::{Frame, Grip, Params, SolverKind, StringLaw};
use crate::solve::{simulate, ImpactResult};

/// A grid point with a value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MapPoint {
    /// m from the tip.
    pub x_m: f64,
    /// m from the long axis.
    pub r_m: f64,
    /// The value there.
    pub value: f64,
}

/// One configuration's map.
#[derive(Debug, Clone)]
pub struct FaceMap {
    /// The configuration, with the impact at the face centre on the axis (each grid point
    /// moves it).
    pub params: Params,
    /// Its face.
    pub face: Face,
    /// The grid.
    pub grid: Grid,
    /// One entry per grid point (row-major, x slowest): the impact, or `None` where the point
    /// was not evaluated (outside the face).
    pub results: Vec<Option<ImpactResult>>,
    /// The mode-1 nodes of the free racket, m from the tip (all of them).
    pub mode1_nodes: Vec<f64>,
}

/// The parameters of `base` with the impact at `(x, r)`.
pub fn params_at(base: &Params, x: f64, r: f64) -> Params {
    let mut p = *base;
    p.impact.x = x;
    p.impact.r = r;
    p
}

/// `base` with the solver a map runs: the modal one whenever the model variants allow it
/// (linear strings and a free grip on the beam frame: it agrees with the explicit reference to
/// 1e-4, tests/modal.rs, and is about 20 times faster), the explicit one otherwise (stiffening
/// strings or a hand grip need it; the rigid frame has its own closed form and keeps `base`'s).
pub fn with_map_solver(base: &Params) -> Params {
    let mut p = *base;
    let v = &p.variants;
    if v.frame == Frame::Beam && v.strings != StringLaw::Stiffening && v.grip != Grip::Hand {
        p.numerics.solver = SolverKind::Modal;
    }
    p
}

/// The mode-1 nodes of the free racket, m from the tip.
pub fn mode1_nodes(p: &Params) -> Vec<f64> {
    let beam = Beam::new(&p.racket, p.numerics.segments);
    beam.modes().node_positions(1, &beam.x)
}

/// Validate the configuration at every listed point (cheap): a bad value fails before any
/// impact is run.
pub fn validate_points(base: &Params, grid: &Grid, points: &[usize]) -> Result<()> {
    points.par_iter().try_for_each(|&k| {
        let (x, r) = grid.point(k);
        params_at(base, x, r).validate()
    })
}

/// Run the impacts at `points` of `grid`, in parallel chunks, in order; `progress(done)` after
/// each chunk, `done` counted from `offset`.
fn evaluate(
    base: &Params,
    grid: &Grid,
    points: &[usize],
    offset: u64,
    progress: &mut dyn FnMut(u64),
) -> Result<Vec<Option<ImpactResult>>> {
    let mut results = vec![None; grid.len()];
    let mut done = offset;
    let watch = crate::control::current();
    for chunk in points.chunks(CHUNK) {
        let out: Vec<ImpactResult> = chunk
            .par_iter()
            .map(|&k| {
                let (x, r) = grid.point(k);
                crate::control::within(watch.as_ref(), || simulate(&params_at(base, x, r))).map_err(|e| {
                    if e.is_cancelled() {
                        return e;
                    }
                    Error::invalid("map point", format!("x = {x} m, r = {r} m"), format!("the impact failed: {e}"))
                })
            })
            .collect::<Result<_>>()?;
        for (&k, r) in chunk.iter().zip(out) {
            results[k] = Some(r);
        }
        done += chunk.len() as u64;
        progress(done);
    }
    Ok(results)
}

impl FaceMap {
    /// The map of one configuration on `nx` x `nr` points over its face; `progress(done)`
    /// after each chunk of impacts (see [`FaceMap::count`] for the total).
    pub fn compute(base: &Params, nx: usize, nr: usize, progress: &mut dyn FnMut(u64)) -> Result<FaceMap> {
        let face = Face::of(&base.racket);
        let grid = Grid::new(face.length, face.half_width, nx, nr)?;
        let points = grid.inside(&[face]);
        FaceMap::on_points(base, face, grid, &points, 0, progress)
    }

    /// The number of impacts [`FaceMap::compute`] runs for this configuration and grid size.
    pub fn count(base: &Params, nx: usize, nr: usize) -> Result<usize> {
        let face = Face::of(&base.racket);
        Ok(Grid::new(face.length, face.half_width, nx, nr)?.inside(&[face]).len())
    }

    fn on_points(
        base: &Params,
        face: Face,
        grid: Grid,
        points: &[usize],
        offset: u64,
        progress: &mut dyn FnMut(u64),
    ) -> Result<FaceMap> {
        let params = with_map_solver(&params_at(base, face.centre(), 0.0));
        params.validate()?;
        validate_points(&params, &grid, points)?;
        let results = evaluate(&params, &grid, points, offset, progress)?;
        Ok(FaceMap { params, face, grid, results, mode1_nodes: mode1_nodes(&params) })
    }

    /// The evaluated points: (x, r, result), row-major.
    pub fn points(&self) -> impl Iterator<Item = (f64, f64, &ImpactResult)> + '_ {
        self.results.iter().enumerate().filter_map(|(k, r)| {
            let (x, rr) = self.grid.point(k);
            r.as_ref().map(|res| (x, rr, res))
        })
    }

    /// Number of evaluated points.
    pub fn len(&self) -> usize {
        self.results.iter().filter(|r| r.is_some()).count()
    }

    /// `true` if no point was evaluated.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The quantity at every grid point (NaN where not evaluated).
    pub fn values(&self, q: Quantity) -> Vec<f64> {
        self.results.iter().map(|r| r.as_ref().map_or(f64::NAN, |r| q.of(r))).collect()
    }

    /// The normal rebound velocity `v2_n` at every grid point (NaN where not evaluated, or at
    /// normal incidence without spin): below 0 where the ball does not rebound.
    pub fn normal_rebound(&self) -> Vec<f64> {
        self.results.iter().map(|r| r.as_ref().map_or(f64::NAN, |r| r.v2_n)).collect()
    }

    /// The mode-1 nodes inside the face (along x), ascending.
    pub fn nodes_in_face(&self) -> Vec<f64> {
        self.mode1_nodes.iter().copied().filter(|&x| self.face.half_width_at(x) > 0.0).collect()
    }

    /// The node: the mode-1 node inside the face nearest the head (the tip).
    pub fn node_x(&self) -> Option<f64> {
        self.nodes_in_face().first().copied()
    }

    /// The point where `q` is largest (the first in row-major order on a tie).
    pub fn max_point(&self, q: Quantity) -> Option<MapPoint> {
        self.points().fold(None, |best, (x, r, res)| {
            let v = q.of(res);
            match best {
                Some(MapPoint { value, .. }) if value >= v => best,
                _ => Some(MapPoint { x_m: x, r_m: r, value: v }),
            }
        })
    }

    /// One impact on the long axis at the node (`None` without a node in the face).
    pub fn at_node(&self) -> Result<Option<(f64, ImpactResult)>> {
        match self.node_x() {
            Some(x) => Ok(Some((x, simulate(&params_at(&self.params, x, 0.0))?))),
            None => Ok(None),
        }
    }
}

/// Two configurations on one grid.
#[derive(Debug, Clone)]
pub struct DiffMap {
    /// Configuration A (the reference).
    pub a: FaceMap,
    /// Configuration B.
    pub b: FaceMap,
}

impl DiffMap {
    /// Both maps on the grid covering both faces, evaluated at the points inside both;
    /// `progress(done)` counts the impacts of A then B (see [`DiffMap::count`]).
    pub fn compute(a: &Params, b: &Params, nx: usize, nr: usize, progress: &mut dyn FnMut(u64)) -> Result<DiffMap> {
        let faces = [Face::of(&a.racket), Face::of(&b.racket)];
        let grid = Grid::covering(&faces, nx, nr)?;
        let points = grid.inside(&faces);
        // validate both before running either
        for (p, f) in [(a, faces[0]), (b, faces[1])] {
            let centred = with_map_solver(&params_at(p, f.centre(), 0.0));
            centred.validate()?;
            validate_points(&centred, &grid, &points)?;
        }
        let ma = FaceMap::on_points(a, faces[0], grid.clone(), &points, 0, progress)?;
        let mb = FaceMap::on_points(b, faces[1], grid, &points, points.len() as u64, progress)?;
        Ok(DiffMap { a: ma, b: mb })
    }

    /// The number of impacts [`DiffMap::compute`] runs (both configurations).
    pub fn count(a: &Params, b: &Params, nx: usize, nr: usize) -> Result<usize> {
        let faces = [Face::of(&a.racket), Face::of(&b.racket)];
        Ok(2 * Grid::covering(&faces, nx, nr)?.inside(&faces).len())
    }

    /// B - A of `q` at every grid point (NaN where either is missing).
    pub fn values(&self, q: Quantity) -> Vec<f64> {
        self.a.values(q).iter().zip(self.b.values(q)).map(|(a, b)| b - a).collect()
    }

    /// The smaller normal rebound velocity of A and B at every grid point: below 0 where the
    /// ball does not rebound off either.
    pub fn normal_rebound(&self) -> Vec<f64> {
        self.a.normal_rebound().iter().zip(self.b.normal_rebound()).map(|(a, b)| a.min(b)).collect()
    }

    /// Number of points in the difference.
    pub fn len(&self) -> usize {
        self.a.results.iter().zip(&self.b.results).filter(|(a, b)| a.is_some() && b.is_some()).count()
    }

    /// `true` if no point is inside both faces.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Smallest, largest and mean of the finite values, `None` when there are none.
pub struct Spread {
    /// Smallest value.
    pub min: Option<f64>,
    /// Largest value.
    pub max: Option<f64>,
    /// Mean value.
    pub mean: Option<f64>,
}

impl DiffMap {
    /// Spread of `B - A` of `q` over the points inside both faces.
    pub fn spread(&self, q: Quantity) -> Spread {
        let vals: Vec<f64> = self.values(q).into_iter().filter(|v| v.is_finite()).collect();
        Spread {
            min: vals.iter().copied().reduce(f64::min),
            max: vals.iter().copied().reduce(f64::max),
            mean: if vals.is_empty() { None } else { Some(vals.iter().sum::<f64>() / vals.len() as f64) },
        }
    }
}
