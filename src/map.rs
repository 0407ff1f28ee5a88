//! String-face maps: one impact at every point of a grid over the string face, in parallel,
//! as a table, a heat map and metadata (the `map` command).
//!
//! ## The face
//! A racket with a head outline ([`Racket::head_length`]) has the ellipse from the tip
//! (`x = 0`) to `head_length` along the racket and `2 half_width` across it:
//! `|r| <= half_width sqrt(1 - ((x - a) / a)^2)`, `a = head_length / 2` (the same expression
//! the impact validation uses). The paper's racket has no outline (its face is the strip
//! `0 <= x <= L`, `|r| <= half_width`); its map uses a default face: the ellipse
//! [`DEFAULT_FACE_LENGTH`] = 32 cm long from the tip and `2 half_width` wide (25 cm), whose
//! centre, 16 cm from the tip, is the paper's "centre of the strings" at the mode-1 node
//! (15.8 cm in the paper, 15.9 cm on the N = 39 beam). A racket shorter than 32 cm gets a face
//! as long as the racket.
//!
//! ## The grid
//! `nx` points along x from the tip to the end of the face and `nr` across r from
//! `-half_width` to `half_width`, both ends included (the face's bounding box). A point is
//! evaluated when it lies on or inside the outline, `|r| <= ` the local half width; the two
//! ends of the ellipse, where the width is zero (the tip `x = 0` and the far end), are skipped
//! as degenerate. Rows are in row-major order, x slowest then r, so the CSV is deterministic;
//! the impacts run in parallel (rayon) in chunks of [`CHUNK`] points with a progress callback
//! after each. Every point is one [`simulate`] call with the configuration's parameters and
//! the impact moved to `(x, r)`; a re-contact is kept as a value, flagged in the `recontact`
//! column.
//!
//! ## Quantities
//! `e_a` (apparent coefficient of restitution), `tau` (impact duration, ms), `theta` (twist at
//! the end of the impact, degrees, signed as r), `f_vib` (vibration energy, fraction of the
//! ball's incident kinetic energy) and `power` = 100 e_A (%, the "power potential" players
//! speak of). Each map also records the mode-1 nodes of the free racket inside the face (the
//! node nearest the head is "the node") and the point of maximum e_A.
//!
//! ## Difference maps
//! Two configurations (racket A against racket B, or one racket at two string tensions via
//! [`ks_from_tension_lb`](crate::params::ks_from_tension_lb)) on the same grid, which covers
//! both faces; only points inside both are evaluated, and the table gives A, B and B - A.

use rayon::prelude::*;
use serde::Serialize;

use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::params::{Params, Racket};
use crate::render::heatmap::{ColorScale, Ellipse, HeatMap, Marker, Segment};
use crate::render::table::{Table, Value};
use crate::solve::{simulate, ImpactResult};

/// Length of the default face of a racket without a head outline, m (the paper's "centre of
/// the strings" is its centre, 16 cm from the tip).
pub const DEFAULT_FACE_LENGTH: f64 = 0.32;
/// Fewest grid points along either axis.
pub const MIN_GRID: usize = 2;
/// Most grid points along either axis.
pub const MAX_GRID: usize = 401;
/// Impacts per parallel chunk (the progress callback runs after each).
pub const CHUNK: usize = 256;

/// What a map shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// Apparent coefficient of restitution `e_A = v2 / v1`.
    EA,
    /// Impact duration, ms.
    Tau,
    /// Twist about the long axis at the end of the impact, degrees.
    Theta,
    /// Racket vibration energy after the impact, fraction of the ball's incident energy.
    FVib,
    /// Power potential `100 e_A`, %.
    #[default]
    Power,
}

impl Quantity {
    /// Every quantity, in table order.
    pub const ALL: [Quantity; 5] = [Quantity::EA, Quantity::Tau, Quantity::Theta, Quantity::FVib, Quantity::Power];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::EA => "e_a",
            Quantity::Tau => "tau",
            Quantity::Theta => "theta",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power",
        }
    }

    /// The table column (with its unit).
    pub fn column(self) -> &'static str {
        match self {
            Quantity::EA => "e_a",
            Quantity::Tau => "tau_ms",
            Quantity::Theta => "theta_deg",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power_pct",
        }
    }

    /// What it is, in words.
    pub fn description(self) -> &'static str {
        match self {
            Quantity::EA => "apparent COR e_A",
            Quantity::Tau => "impact duration",
            Quantity::Theta => "twist at the end of impact",
            Quantity::FVib => "vibration energy",
            Quantity::Power => "power potential 100 e_A",
        }
    }

    /// Its symbol on the colour bar.
    pub fn symbol(self) -> &'static str {
        match self {
            Quantity::EA => "e_A",
            Quantity::Tau => "tau",
            Quantity::Theta => "theta",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power 100 e_A",
        }
    }

    /// Its unit (empty for a pure number).
    pub fn unit(self) -> &'static str {
        match self {
            Quantity::EA => "",
            Quantity::Tau => "ms",
            Quantity::Theta => "deg",
            Quantity::FVib => "fraction of the ball's KE",
            Quantity::Power => "%",
        }
    }

    /// Its value for one impact.
    pub fn of(self, r: &ImpactResult) -> f64 {
        match self {
            Quantity::EA => r.e_a,
            Quantity::Tau => 1e3 * r.tau_s,
            Quantity::Theta => r.theta_end_deg,
            Quantity::FVib => r.f_vib,
            Quantity::Power => 100.0 * r.e_a,
        }
    }
}

impl std::str::FromStr for Quantity {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Quantity::ALL
            .into_iter()
            .find(|q| q.name() == s)
            .ok_or_else(|| Error::invalid("quantity", s, "must be one of e_a, tau, theta, f_vib, power".to_string()))
    }
}

impl clap::ValueEnum for Quantity {
    fn value_variants<'a>() -> &'a [Self] {
        &Quantity::ALL
    }
    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let help = match self {
            Quantity::EA => "apparent coefficient of restitution e_A",
            Quantity::Tau => "impact duration, ms",
            Quantity::Theta => "twist at the end of the impact, degrees",
            Quantity::FVib => "vibration energy, fraction of the ball's incident KE",
            Quantity::Power => "power potential 100 e_A, %",
        };
        Some(clap::builder::PossibleValue::new(self.name()).help(help))
    }
}

/// The string face: an ellipse from the tip, `length` along the racket and `2 half_width`
/// across it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Face {
    /// Length from the tip, m.
    pub length: f64,
    /// Half the width, m.
    pub half_width: f64,
    /// `true` if the racket has a head outline, `false` for the default face.
    pub from_racket: bool,
}

impl Face {
    /// The face of a racket: its head outline, else the default face
    /// ([`DEFAULT_FACE_LENGTH`], at most the racket's length, by `2 half_width`).
    pub fn of(racket: &Racket) -> Face {
        match racket.head_length {
            Some(h) => Face { length: h, half_width: racket.half_width, from_racket: true },
            None => Face {
                length: DEFAULT_FACE_LENGTH.min(racket.length),
                half_width: racket.half_width,
                from_racket: false,
            },
        }
    }

    /// Half the width at `x`, m (0 off the face along x). The function behind
    /// [`Racket::face_half_width`], so a point inside is a valid impact.
    pub fn half_width_at(&self, x: f64) -> f64 {
        crate::params::ellipse_half_width(self.length, self.half_width, x).unwrap_or(0.0)
    }

    /// `true` if `(x, r)` is on or inside the outline and the face has a width there.
    pub fn contains(&self, x: f64, r: f64) -> bool {
        let w = self.half_width_at(x);
        w > 0.0 && r.abs() <= w
    }

    /// The centre, m from the tip.
    pub fn centre(&self) -> f64 {
        0.5 * self.length
    }

    /// The outline in cm, for the heat map.
    fn ellipse_cm(&self) -> Ellipse {
        Ellipse { x0: 0.0, x1: 100.0 * self.length, half_height: 100.0 * self.half_width }
    }
}

/// The grid: x along the racket (m from the tip) and r across it (m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Grid {
    /// x values, ascending, from 0.
    pub xs: Vec<f64>,
    /// r values, ascending, symmetric about 0.
    pub rs: Vec<f64>,
}

impl Grid {
    /// `nx` points on `0..=length` and `nr` on `-half_width..=half_width` (ends included).
    pub fn new(length: f64, half_width: f64, nx: usize, nr: usize) -> Result<Grid> {
        check_count("nx", nx)?;
        check_count("nr", nr)?;
        let axis = |lo: f64, hi: f64, n: usize| -> Vec<f64> {
            (0..n).map(|i| if i + 1 == n { hi } else { lo + (hi - lo) * (i as f64 / (n - 1) as f64) }).collect()
        };
        let mut rs = axis(-half_width, half_width, nr);
        if nr % 2 == 1 {
            rs[nr / 2] = 0.0; // exactly on the axis
        }
        Ok(Grid { xs: axis(0.0, length, nx), rs })
    }

    /// The grid covering the bounding box of every face.
    pub fn covering(faces: &[Face], nx: usize, nr: usize) -> Result<Grid> {
        let length = faces.iter().map(|f| f.length).fold(0.0, f64::max);
        let half_width = faces.iter().map(|f| f.half_width).fold(0.0, f64::max);
        Grid::new(length, half_width, nx, nr)
    }

    /// Number of grid points.
    pub fn len(&self) -> usize {
        self.xs.len() * self.rs.len()
    }

    /// `true` for an empty grid (never, for a grid from [`Grid::new`]).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The point with flat index `k` (x slowest).
    pub fn point(&self, k: usize) -> (f64, f64) {
        let n = self.rs.len();
        (self.xs[k / n], self.rs[k % n])
    }

    /// The flat indices of the points inside every face, in row-major order.
    pub fn inside(&self, faces: &[Face]) -> Vec<usize> {
        (0..self.len())
            .filter(|&k| {
                let (x, r) = self.point(k);
                faces.iter().all(|f| f.contains(x, r))
            })
            .collect()
    }
}

/// Check a grid's point count along one axis (`field` is `nx` or `nr`).
pub fn check_count(field: &'static str, n: usize) -> Result<()> {
    if (MIN_GRID..=MAX_GRID).contains(&n) {
        Ok(())
    } else {
        Err(Error::invalid(field, n, format!("grid points must satisfy {MIN_GRID} <= {field} <= {MAX_GRID}")))
    }
}

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
    for chunk in points.chunks(CHUNK) {
        let out: Vec<ImpactResult> = chunk
            .par_iter()
            .map(|&k| {
                let (x, r) = grid.point(k);
                simulate(&params_at(base, x, r)).map_err(|e| {
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
        let params = params_at(base, face.centre(), 0.0);
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

    /// The table: x_m, r_m, every quantity's column, recontact (0/1); one row per evaluated
    /// point, row-major (x slowest).
    pub fn table(&self) -> Table {
        let mut cols = vec!["x_m", "r_m"];
        cols.extend(Quantity::ALL.iter().map(|q| q.column()));
        cols.push("recontact");
        let mut t = Table::new("map", &cols);
        for (x, r, res) in self.points() {
            let mut row: Vec<Value> = vec![x.into(), r.into()];
            row.extend(Quantity::ALL.iter().map(|q| Value::Num(q.of(res))));
            row.push(Value::Int(i64::from(res.recontact)));
            // the row has one value per column, so push cannot fail
            let _ = t.push(row);
        }
        t
    }

    /// The heat map of `q`, titled with `label` (the racket's name).
    pub fn heatmap(&self, q: Quantity, label: &str) -> HeatMap {
        let face = self.face.ellipse_cm();
        let mut segments = Vec::new();
        for x in self.nodes_in_face() {
            let w = 100.0 * self.face.half_width_at(x);
            segments.push(Segment {
                from: (100.0 * x, -w),
                to: (100.0 * x, w),
                label: format!("mode-1 node, {:.1} cm", 100.0 * x),
            });
        }
        let markers = self
            .max_point(Quantity::EA)
            .map(|m| Marker { at: (100.0 * m.x_m, 100.0 * m.r_m), label: max_label(&m) })
            .into_iter()
            .collect();
        HeatMap {
            title: format!("{}: {}", config_title(label, &self.params), quantity_title(q)),
            subtitle: subtitle(&self.params, &[self.face], &self.grid, self.len()),
            x_label: "x: distance from the tip (cm)".into(),
            y_label: "r: distance from the long axis (cm)".into(),
            bar_label: bar_label(q, false),
            xs: self.grid.xs.iter().map(|x| 100.0 * x).collect(),
            ys: self.grid.rs.iter().map(|r| 100.0 * r).collect(),
            z: self.values(q),
            scale: ColorScale::Sequential,
            clip: vec![face],
            outlines: vec![face],
            segments,
            markers,
        }
    }
}

/// "max e_A 0.4213 at (31.7, 0) cm".
fn max_label(m: &MapPoint) -> String {
    format!("max e_A {:.4} at ({:.1}, {:.1}) cm", m.value, 100.0 * m.x_m, 100.0 * m.r_m + 0.0)
}

/// "tweener, ks 36667 N/m".
fn config_title(label: &str, p: &Params) -> String {
    format!("{label}, ks {:.0} N/m", p.strings.ks)
}

/// "power potential 100 e_A (%)".
fn quantity_title(q: Quantity) -> String {
    match q.unit() {
        "" => q.description().to_string(),
        u => format!("{} ({u})", q.description()),
    }
}

fn bar_label(q: Quantity, difference: bool) -> String {
    let unit = match (q.unit(), difference) {
        ("%", true) => "% points",
        (u, _) => u,
    };
    let sym = if difference { format!("B - A: {}", q.symbol()) } else { q.symbol().to_string() };
    if unit.is_empty() {
        sym
    } else {
        format!("{sym} ({unit})")
    }
}

/// The shared numerics and the grid, one line.
fn subtitle(p: &Params, faces: &[Face], grid: &Grid, evaluated: usize) -> String {
    let face = match faces.first() {
        Some(f) if faces.len() == 1 => format!(
            "{} {:.1} x {:.1} cm",
            if f.from_racket { "head" } else { "default face" },
            100.0 * f.length,
            200.0 * f.half_width
        ),
        _ => "inside both faces".to_string(),
    };
    format!(
        "v1 {:.3} m/s, {} load, N = {}, {} solver; {} x {} grid, {} impacts; {}",
        p.impact.v1,
        p.numerics.load.name(),
        p.numerics.segments,
        p.numerics.solver.name(),
        grid.xs.len(),
        grid.rs.len(),
        evaluated,
        face
    )
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
            let centred = params_at(p, f.centre(), 0.0);
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

    /// Number of points in the difference.
    pub fn len(&self) -> usize {
        self.a.results.iter().zip(&self.b.results).filter(|(a, b)| a.is_some() && b.is_some()).count()
    }

    /// `true` if no point is inside both faces.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The table: x_m, r_m, `<q>_a`, `<q>_b`, `<q>_b_minus_a`, recontact_a, recontact_b; one row
    /// per point inside both faces, row-major.
    pub fn table(&self, q: Quantity) -> Table {
        let c = q.column();
        let (ca, cb, cd) = (format!("{c}_a"), format!("{c}_b"), format!("{c}_b_minus_a"));
        let mut t = Table::new("map_diff", &["x_m", "r_m", &ca, &cb, &cd, "recontact_a", "recontact_b"]);
        for (k, (ra, rb)) in self.a.results.iter().zip(&self.b.results).enumerate() {
            if let (Some(ra), Some(rb)) = (ra, rb) {
                let (x, r) = self.a.grid.point(k);
                let (va, vb) = (q.of(ra), q.of(rb));
                let _ = t.push(vec![
                    x.into(),
                    r.into(),
                    va.into(),
                    vb.into(),
                    (vb - va).into(),
                    Value::Int(i64::from(ra.recontact)),
                    Value::Int(i64::from(rb.recontact)),
                ]);
            }
        }
        t
    }

    /// The heat map of B - A.
    pub fn heatmap(&self, q: Quantity, label_a: &str, label_b: &str) -> HeatMap {
        let (fa, fb) = (self.a.face.ellipse_cm(), self.b.face.ellipse_cm());
        let outlines = if fa == fb { vec![fa] } else { vec![fa, fb] };
        let mut segments = Vec::new();
        let same_nodes = self.a.nodes_in_face() == self.b.nodes_in_face();
        for (m, tag) in [(&self.a, "A"), (&self.b, "B")] {
            if tag == "B" && same_nodes {
                continue;
            }
            for x in m.nodes_in_face() {
                let w = 100.0 * m.face.half_width_at(x);
                let who = if same_nodes { String::new() } else { format!(" ({tag})") };
                segments.push(Segment {
                    from: (100.0 * x, -w),
                    to: (100.0 * x, w),
                    label: format!("mode-1 node{who}, {:.1} cm", 100.0 * x),
                });
            }
        }
        let (pa, pb) = (self.a.max_point(Quantity::EA), self.b.max_point(Quantity::EA));
        let mut markers = Vec::new();
        match (pa, pb) {
            (Some(a), Some(b)) if (a.x_m, a.r_m) == (b.x_m, b.r_m) => markers.push(Marker {
                at: (100.0 * a.x_m, 100.0 * a.r_m),
                label: format!("max e_A of A and B at ({:.1}, {:.1}) cm", 100.0 * a.x_m, 100.0 * a.r_m + 0.0),
            }),
            _ => {
                for (p, tag) in [(pa, "A"), (pb, "B")] {
                    if let Some(m) = p {
                        markers.push(Marker {
                            at: (100.0 * m.x_m, 100.0 * m.r_m),
                            label: format!("max e_A of {tag}: {:.4}", m.value),
                        });
                    }
                }
            }
        }
        HeatMap {
            title: format!("B - A: {} (A: {}; B: {})", q.description(), label_a, label_b),
            subtitle: format!(
                "ks A {:.0}, B {:.0} N/m; {}",
                self.a.params.strings.ks,
                self.b.params.strings.ks,
                subtitle(&self.a.params, &[self.a.face, self.b.face], &self.a.grid, self.len())
            ),
            x_label: "x: distance from the tip (cm)".into(),
            y_label: "r: distance from the long axis (cm)".into(),
            bar_label: bar_label(q, true),
            xs: self.a.grid.xs.iter().map(|x| 100.0 * x).collect(),
            ys: self.a.grid.rs.iter().map(|r| 100.0 * r).collect(),
            z: self.values(q),
            scale: ColorScale::Diverging,
            clip: outlines.clone(),
            outlines,
            segments,
            markers,
        }
    }
}

/// What the metadata's parameters mean for the impact point.
const IMPACT_NOTE: &str =
    "params.impact.x and params.impact.r are the face centre; each grid point moves the impact there";

/// The grid for the metadata: the requested counts and the coordinates.
fn grid_metadata(g: &Grid, nx: usize, nr: usize) -> serde_json::Value {
    serde_json::json!({ "nx": nx, "nr": nr, "x_m": g.xs, "r_m": g.rs })
}

impl FaceMap {
    /// The JSON metadata of a map of `q` requested on an `nx x nr` grid: the quantity, the grid
    /// and the configuration ([`config_metadata`]).
    pub fn metadata(&self, label: &str, q: Quantity, (nx, nr): (usize, usize)) -> Result<serde_json::Value> {
        Ok(serde_json::json!({
            "quantity": q.name(), "column": q.column(), "unit": q.unit(),
            "note": IMPACT_NOTE,
            "grid": grid_metadata(&self.grid, nx, nr),
            "points": self.len(),
            "a": config_metadata(label, self, q)?,
        }))
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

    /// The JSON metadata of a difference map (as [`FaceMap::metadata`], both configurations and
    /// the spread of `B - A`).
    pub fn metadata(&self, labels: (&str, &str), q: Quantity, (nx, nr): (usize, usize)) -> Result<serde_json::Value> {
        let spread = self.spread(q);
        Ok(serde_json::json!({
            "quantity": q.name(), "column": q.column(), "unit": q.unit(),
            "note": IMPACT_NOTE,
            "difference": "b - a",
            "grid": grid_metadata(&self.a.grid, nx, nr),
            "points": self.len(),
            "a": config_metadata(labels.0, &self.a, q)?,
            "b": config_metadata(labels.1, &self.b, q)?,
            "b_minus_a": { "min": spread.min, "max": spread.max, "mean": spread.mean },
        }))
    }
}

/// A configuration's description for the metadata: its label, parameters, face, nodes, the
/// maximum of e_A and of the quantity, and the impact at the node.
pub fn config_metadata(label: &str, m: &FaceMap, q: Quantity) -> Result<serde_json::Value> {
    let at_node = m.at_node()?;
    Ok(serde_json::json!({
        "label": label,
        "params": json(&m.params),
        "face": json(&m.face),
        "mode1_nodes_m": m.mode1_nodes,
        "node_x_m": m.node_x(),
        "max_e_a": json(&m.max_point(Quantity::EA)),
        "max_quantity": json(&m.max_point(q)),
        "min_quantity": json(&m.points().fold(None, |best: Option<MapPoint>, (x, r, res)| {
            let v = q.of(res);
            match best {
                Some(b) if b.value <= v => Some(b),
                _ => Some(MapPoint { x_m: x, r_m: r, value: v }),
            }
        })),
        "at_node": at_node.map(|(x, res)| serde_json::json!({
            "x_m": x, "r_m": 0.0, "value": q.of(&res), "result": json(&res),
        })),
        "points": m.len(),
    }))
}

/// `serde_json::to_value` for our plain types (numbers, strings, options), which cannot fail.
fn json<T: Serialize>(v: &T) -> serde_json::Value {
    serde_json::to_value(v).unwrap_or(serde_json::Value::Null)
}

/// The three output files of a map: the CSV as given, the PNG and the JSON next to it (same
/// stem).
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// The table.
    pub csv: std::path::PathBuf,
    /// The heat map.
    pub png: std::path::PathBuf,
    /// The metadata.
    pub json: std::path::PathBuf,
}

impl Outputs {
    /// The files for `--out path` (the PNG and JSON replace its extension); the directory must
    /// exist and the path must not itself end in `.png` or `.json`.
    pub fn for_csv(path: &std::path::Path) -> Result<Outputs> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        if ext == "png" || ext == "json" || path.file_name().is_none() {
            return Err(Error::invalid(
                "out",
                path.display(),
                "the CSV file of the map (the PNG and JSON go next to it with the same stem), e.g. map.csv",
            ));
        }
        crate::render::io::check_output_dir("out", path)?;
        let out =
            Outputs { csv: path.to_path_buf(), png: path.with_extension("png"), json: path.with_extension("json") };
        for p in [&out.csv, &out.png, &out.json] {
            if p.is_dir() {
                return Err(Error::invalid("out", path.display(), format!("{} is a directory", p.display())));
            }
        }
        Ok(out)
    }

    /// Write all three, all or nothing: each goes to a temporary file next to its target
    /// first, and only when all three are complete are they renamed over the targets.
    pub fn write(&self, csv: &str, map: &HeatMap, json: &str) -> Result<()> {
        let tmp_csv = crate::render::io::temp_sibling(&self.csv, "")?;
        let tmp_json = crate::render::io::temp_sibling(&self.json, "")?;
        let tmp_png = crate::render::io::temp_sibling(&self.png, ".png")?;
        let cleanup = || {
            for t in [&tmp_csv, &tmp_json, &tmp_png] {
                let _ = std::fs::remove_file(t);
            }
        };
        let written = (|| -> Result<()> {
            crate::render::io::write_synced(&tmp_csv, &self.csv, csv.as_bytes())?;
            crate::render::io::write_synced(&tmp_json, &self.json, json.as_bytes())?;
            crate::render::heatmap::draw_file(map, &tmp_png)
                .map_err(|message| Error::Plot { id: self.png.display().to_string(), message })
        })();
        if let Err(e) = written {
            cleanup();
            return Err(e);
        }
        for (tmp, path) in [(&tmp_csv, &self.csv), (&tmp_json, &self.json), (&tmp_png, &self.png)] {
            if let Err(e) = crate::render::io::commit_temp(tmp, path) {
                cleanup();
                return Err(e);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::LoadRule;

    fn paper() -> Params {
        let mut p = Params::paper();
        p.numerics.load = LoadRule::Node;
        p
    }

    #[test]
    fn default_face_is_the_32_cm_ellipse_centred_near_the_node() {
        let f = Face::of(&Racket::default());
        assert_eq!((f.length, f.half_width, f.from_racket), (0.32, 0.125, false));
        assert_eq!(f.half_width_at(0.16), 0.125);
        assert_eq!(f.half_width_at(0.0), 0.0);
        assert!(!f.contains(0.0, 0.0), "the degenerate tip is skipped");
        assert!(!f.contains(0.33, 0.0));
        let nodes = mode1_nodes(&paper());
        assert!((nodes[0] - f.centre()).abs() < 0.002, "{nodes:?}");
    }

    #[test]
    fn head_face_matches_the_impact_validation() {
        let racket = Racket { head_length: Some(0.33), half_width: 0.126, ..Racket::default() };
        let f = Face::of(&racket);
        for i in 0..=200 {
            let x = 0.33 * i as f64 / 200.0;
            let w = f.half_width_at(x);
            assert_eq!(Some(w), racket.face_half_width(x), "{x}");
        }
    }

    #[test]
    fn grid_is_symmetric_and_ends_exactly() {
        let g = Grid::new(0.32, 0.125, 25, 13).unwrap();
        assert_eq!((g.xs[0], g.xs[24], g.rs[0], g.rs[6], g.rs[12]), (0.0, 0.32, -0.125, 0.0, 0.125));
        assert_eq!(g.xs[12], 0.16);
        assert!(Grid::new(0.32, 0.125, 1, 13).is_err());
        assert!(Grid::new(0.32, 0.125, 25, 402).is_err());
        // x = 0 and x = L have zero width: skipped; the centre column has every r
        let face = Face::of(&Racket::default());
        let inside = g.inside(&[face]);
        assert!(inside.iter().all(|&k| g.point(k).0 > 0.0 && g.point(k).0 < 0.32));
        assert_eq!(inside.iter().filter(|&&k| g.point(k).0 == 0.16).count(), 13);
    }

    #[test]
    fn small_map_matches_single_runs_and_its_maximum() {
        let p = paper();
        let mut calls = Vec::new();
        let m = FaceMap::compute(&p, 5, 5, &mut |d| calls.push(d)).unwrap();
        assert_eq!(m.len(), FaceMap::count(&p, 5, 5).unwrap());
        assert_eq!(calls.last().copied(), Some(m.len() as u64));
        let t = m.table();
        assert_eq!(t.len(), m.len());
        let e_a = t.column("e_a").unwrap();
        let best = m.max_point(Quantity::EA).unwrap();
        assert_eq!(best.value, e_a.iter().copied().fold(f64::MIN, f64::max));
        for (x, r, res) in m.points() {
            assert_eq!(*res, simulate(&params_at(&p, x, r)).unwrap());
        }
        // the heat map of it renders
        let dir = tempfile::tempdir().unwrap();
        crate::render::heatmap::render_png("map", &m.heatmap(Quantity::Power, "paper"), &dir.path().join("m.png"))
            .unwrap();
    }
}
