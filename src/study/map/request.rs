//! The `map` command's request: its checks, its configurations (one, or two to compare) and
//! running them into a table, a heat map, metadata and a summary.

use std::path::PathBuf;

use super::summary::{diff_summary, map_summary};
use super::{check_count, DiffMap, FaceMap, Quantity};
use crate::diagnostic::{Diagnostic, Kind};
use crate::error::{Error, Result};
use crate::intake::compare::{check_comparison, racket_label};
use crate::intake::diagnose;
use crate::intake::Sources;
use crate::params::{ks_from_tension_lb, Params};
use crate::render::heatmap::HeatMap;
use crate::render::table::Table;

/// A map of one configuration, or the difference of two.
#[derive(Debug, Clone)]
pub struct MapRequest {
    /// The configuration (A): racket, config file and flags; the flags may not set the impact
    /// position and the config file's is ignored (the grid sets it).
    pub sources: Sources,
    /// The quantity shown in the heat map (the table has every one).
    pub quantity: Quantity,
    /// Grid points along the racket.
    pub nx: usize,
    /// Grid points across the face.
    pub nr: usize,
    /// Compare against this racket (file or preset): B - A with A = [`Sources::racket`].
    pub compare_racket: Option<String>,
    /// Compare string tensions, lb: T (A as given, B at T) or T1,T2 (A at T1, B at T2).
    pub compare_tension_lb: Vec<f64>,
}

/// What a map produced.
#[derive(Debug, Clone)]
pub struct MapOutcome {
    /// The CSV table.
    pub table: Table,
    /// The heat map.
    pub heatmap: HeatMap,
    /// The JSON metadata.
    pub metadata: serde_json::Value,
    /// The text summary.
    pub summary: String,
    /// The grid, m (the heat map's axes are in cm): its points along the racket from the tip
    /// and across the face from the long axis; `heatmap.z[i * rs.len() + j]` is the quantity at
    /// `(xs[i], rs[j])`.
    pub grid: super::Grid,
}

impl MapOutcome {
    /// The metadata as pretty JSON with a final newline.
    pub fn json(&self) -> Result<String> {
        crate::render::json::pretty(&self.metadata)
    }

    /// Number of points with a re-contact after separation (in either configuration).
    pub fn recontacts(&self) -> usize {
        let flags = self.table.column("recontact").or_else(|| self.table.column("recontact_b")).unwrap_or_default();
        flags.iter().filter(|&&v| v != 0.0).count()
    }

    /// The map's diagnostics: those of its configurations' parameters `params`, the largest twist
    /// over the face and the points with a re-contact.
    pub fn diagnostics<'a>(&self, params: impl IntoIterator<Item = &'a Params>) -> Vec<Diagnostic> {
        let mut out = diagnose::parameters(params, &[]);
        let theta = ["theta_end_deg", "theta_end_deg_a", "theta_end_deg_b"]
            .iter()
            .filter_map(|c| self.table.column(c))
            .flatten()
            .filter(|v| v.is_finite())
            .max_by(|a, b| a.abs().total_cmp(&b.abs()));
        out.extend(theta.and_then(diagnose::twist));
        let n_re = self.recontacts();
        if n_re > 0 {
            out.push(Diagnostic::new(
                Kind::BeyondModel,
                "recontact",
                format!("{n_re} map points have a re-contact after separation (flagged in the recontact column)"),
            ));
        }
        out
    }
}

impl MapRequest {
    /// Check the grid counts and the comparison options, before anything is read.
    pub fn check(&self) -> Result<()> {
        check_count("nx", self.nx)?;
        check_count("nr", self.nr)?;
        check_comparison(&self.compare_tension_lb, self.compare_racket.is_some(), &self.sources.flags)?;
        if self.compare_tension_lb.len() > 2 {
            return Err(Error::invalid(
                "compare-tension-lb",
                self.compare_tension_lb.iter().map(f64::to_string).collect::<Vec<_>>().join(","),
                "give one tension T (the configuration against T) or two, T1,T2",
            ));
        }
        Ok(())
    }

    /// `true` for a difference map.
    pub fn is_difference(&self) -> bool {
        self.compare_racket.is_some() || !self.compare_tension_lb.is_empty()
    }

    /// The CSV file when none is given: `map_<quantity>.csv` or `map_<quantity>_diff.csv`.
    pub fn default_csv(&self) -> PathBuf {
        PathBuf::from(format!("map_{}{}.csv", self.quantity.name(), if self.is_difference() { "_diff" } else { "" }))
    }

    /// The configurations, (label, params) each, validated, and the number of impacts they run.
    pub fn configurations(&self) -> Result<(Vec<(String, Params)>, usize)> {
        let name_a = racket_label(self.sources.racket.as_deref());
        let base = self.params(self.sources.racket.as_deref())?;
        let mut configs: Vec<(String, Params)> = Vec::new();
        if let Some(b) = &self.compare_racket {
            configs.push((name_a.clone(), base));
            configs.push((racket_label(Some(b)), self.params(Some(b))?));
        } else if !self.compare_tension_lb.is_empty() {
            let at = |t: f64| {
                let mut p = base;
                p.strings.ks = ks_from_tension_lb(t);
                (format!("{name_a} at {t} lb"), p)
            };
            match self.compare_tension_lb[..] {
                [t] => {
                    configs.push((format!("{name_a} as given"), base));
                    configs.push(at(t));
                }
                [t1, t2] => {
                    configs.push(at(t1));
                    configs.push(at(t2));
                }
                _ => {}
            }
        } else {
            configs.push((name_a.clone(), base));
        }
        for (_, p) in &configs {
            p.validate()?;
        }
        let total = match &configs[..] {
            [(_, p)] => FaceMap::count(p, self.nx, self.nr)?,
            [(_, pa), (_, pb)] => DiffMap::count(pa, pb, self.nx, self.nr)?,
            _ => 0,
        };
        if total == 0 {
            return Err(Error::invalid(
                "nx",
                format!("{} (with nr = {})", self.nx, self.nr),
                "no grid point lies inside the string face; use more points (e.g. --nx 5 --nr 5)",
            ));
        }
        Ok((configs, total))
    }

    /// Refuse a flag for an option none of the map's impacts can honour; return the notes about
    /// flags and config keys they do not use ([`Sources::check_used`]), judged on the
    /// configurations `configs` as the grid runs them (the map's solver, and off the long axis).
    pub fn check_used(&self, configs: &[(String, Params)]) -> Result<Vec<Diagnostic>> {
        let solved: Vec<Params> = configs
            .iter()
            .map(|(_, p)| {
                let mut p = super::with_map_solver(p);
                p.impact.r = 0.5 * p.racket.half_width;
                p
            })
            .collect();
        self.sources.check_used(&solved)
    }

    /// Run the map of `configs` (from [`MapRequest::configurations`]); `progress(done)` after
    /// each chunk of impacts.
    pub fn run(&self, configs: &[(String, Params)], progress: &mut dyn FnMut(u64)) -> Result<MapOutcome> {
        let (q, counts) = (self.quantity, (self.nx, self.nr));
        if q.is_oblique() && configs.iter().any(|(_, p)| p.oblique.is_normal()) {
            return Err(Error::invalid(
                "quantity",
                q.name(),
                "is a quantity of an oblique or spinning ball: give --angle-deg or --spin-rpm",
            ));
        }
        let (table, heatmap, metadata, summary, grid) = match configs {
            [(la, pa), (lb, pb)] => {
                let d = DiffMap::compute(pa, pb, self.nx, self.nr, progress)?;
                let meta = d.metadata((la, lb), q, counts)?;
                let summary = diff_summary(&d, q, la, lb);
                (d.table(q), d.heatmap(q, la, lb), meta, summary, d.a.grid.clone())
            }
            [(la, pa)] => {
                let m = FaceMap::compute(pa, self.nx, self.nr, progress)?;
                let meta = m.metadata(la, q, counts)?;
                let summary = map_summary(&m, q, la)?;
                (m.table(), m.heatmap(q, la), meta, summary, m.grid.clone())
            }
            _ => return Err(Error::invalid("map", configs.len(), "one or two configurations")),
        };
        Ok(MapOutcome { table, heatmap, metadata, summary, grid })
    }

    /// The work of the map, estimated before it runs ([`crate::study::work`]): its `total`
    /// impacts shared evenly among `configs`, each sampled impact costed at its own point of the
    /// configuration's `nx` x `nr` grid with the solver the map runs
    /// ([`super::compute::with_map_solver`]: the step, and with it the cost, moves over the face).
    pub fn estimate(
        configs: &[(String, Params)],
        nx: usize,
        nr: usize,
        total: usize,
        threads: usize,
    ) -> crate::study::work::Estimate {
        use super::face::{Face, Grid};
        let faces: Vec<(Params, Grid, Vec<usize>)> = configs
            .iter()
            .filter_map(|(_, p)| {
                let face = Face::of(&p.racket);
                let grid = Grid::new(face.length, face.half_width, nx, nr).ok()?;
                let points = grid.inside(&[face]);
                Some((*p, grid, points))
            })
            .collect();
        crate::study::work::Estimate::of(total as u64, threads, |i| {
            // (the configuration of impact i, and its place among that configuration's points)
            let at = i as f64 / total.max(1) as f64 * faces.len() as f64;
            let (p, grid, points) = faces.get(at as usize)?;
            let k = *points.get(((at.fract() * points.len() as f64) as usize).min(points.len().max(1) - 1))?;
            let (x, r) = grid.point(k);
            Some(super::compute::with_map_solver(&super::compute::params_at(p, x, r)))
        })
    }

    /// The configuration with the racket `racket`: as [`Sources::resolve`], with what a map
    /// sets itself ([`super::MAP_SETS`]) refused as a flag and the config file's impact position
    /// ignored; the grid sets it.
    fn params(&self, racket: Option<&str>) -> Result<Params> {
        let flags = &self.sources.flags;
        if let Some((spec, why)) = super::MAP_SETS.iter().find(|(s, _)| flags.given().contains(&s.key)) {
            let mut values = Params::default();
            flags.apply(&mut values);
            let value = crate::params::keys::value_text(spec.key, &values).unwrap_or_default();
            return Err(Error::invalid(spec.key, value, format!("map does not take it: {why}")));
        }
        let (mut config, _) = self.sources.config()?;
        // an on-axis point at the tip is valid on every face; the grid replaces it
        config.x = Some(0.0);
        config.r = Some(0.0);
        let spec = racket.map(crate::racket::load).transpose()?;
        Ok(crate::racket::resolve(spec.as_ref(), &flags.clone().or(config))?.0)
    }
}
