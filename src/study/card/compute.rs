//! Running a card: the impacts of every racket at every tension (each the call of the command
//! that computes it alone), then one face map per racket and tension, into rows.

use rayon::prelude::*;

use super::spin::SpinStatus;
use super::{Prepared, Strokes, NEAR_END, OFF_CENTRE, SPIN_SHOT, TWIST_R, TWIST_V1};
use crate::diagnostic::Diagnostic;
use crate::error::{Error, Result};
use crate::params::{ks_from_tension_lb, Frame, Params, Racket};
use crate::solve::swing::Exit;
use crate::solve::{simulate, ImpactResult};
use crate::study::map::{params_at, with_map_solver, Face, FaceMap, MapPoint, Quantity};
use crate::study::speed::SpeedRow;
use crate::study::work::Estimate;

/// `p` at the tension `t` (lb): its k_s by the calibration ([`ks_from_tension_lb`]).
pub fn at_tension(p: &Params, t: f64) -> Params {
    let mut q = *p;
    q.strings.ks = ks_from_tension_lb(t);
    q
}

/// Where a card hits a racket, m: the centre of its string face on the long axis, the
/// off-centre point ([`OFF_CENTRE`]), and the long axis near the tip and near the throat
/// ([`NEAR_END`] from either end of the face).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Points {
    /// The face centre, m from the tip.
    pub centre: f64,
    /// The off-centre point: m from the tip, m from the long axis.
    pub off: (f64, f64),
    /// Near the tip, m from the tip.
    pub tip: f64,
    /// Near the throat, m from the tip.
    pub throat: f64,
}

impl Points {
    /// The points on `racket`'s face (the face a map covers, [`Face::of`]); an error saying
    /// which point lies off a face too small for it.
    pub fn of(racket: &Racket) -> std::result::Result<Points, String> {
        let face = Face::of(racket);
        let centre = face.centre();
        let p = Points {
            centre,
            off: (centre - OFF_CENTRE.0, OFF_CENTRE.1),
            tip: NEAR_END,
            throat: face.length - NEAR_END,
        };
        for (what, (x, r)) in [
            ("the off-centre point", p.off),
            ("the twist point", (centre, TWIST_R)),
            ("the point near the tip", (p.tip, 0.0)),
            ("the point near the throat", (p.throat, 0.0)),
        ] {
            if !face.contains(x, r) || p.throat <= p.tip {
                return Err(format!(
                    "{what} (x {} cm, r {} cm) lies off the {} x {} cm face",
                    crate::numfmt::sig(100.0 * x, 3),
                    crate::numfmt::sig(100.0 * r, 3),
                    crate::numfmt::sig(100.0 * face.length, 3),
                    crate::numfmt::sig(200.0 * face.half_width, 3)
                ));
            }
        }
        Ok(p)
    }
}

/// One impact of a card.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Shot {
    /// The serve at the centre.
    ServeCentre,
    /// The serve at the off-centre point.
    ServeOff,
    /// The forehand at the centre.
    ForehandCentre,
    /// The forehand at the off-centre point.
    ForehandOff,
    /// The centre at 30 m/s on the long axis: e_A and the impact duration.
    Centre,
    /// The centre at 30 m/s, 4 cm off the axis: the twist (Fig 8).
    Twist,
    /// Near the tip at 30 m/s: the vibration left and e_A.
    Tip,
    /// Near the throat at 30 m/s: the vibration left.
    Throat,
    /// The topspin forehand at the centre.
    Spin,
}

impl Shot {
    /// Every shot of a racket at a tension, in order.
    pub const ALL: [Shot; 9] = [
        Shot::ServeCentre,
        Shot::ServeOff,
        Shot::ForehandCentre,
        Shot::ForehandOff,
        Shot::Centre,
        Shot::Twist,
        Shot::Tip,
        Shot::Throat,
        Shot::Spin,
    ];
}

impl Shot {
    /// The shot in words.
    pub fn words(self) -> &'static str {
        match self {
            Shot::ServeCentre => "the serve at the centre",
            Shot::ServeOff => "the serve off-centre",
            Shot::ForehandCentre => "the forehand at the centre",
            Shot::ForehandOff => "the forehand off-centre",
            Shot::Centre => "the centre impact at 30 m/s",
            Shot::Twist => "the twist impact (r 4 cm, 30 m/s)",
            Shot::Tip => "the impact near the tip",
            Shot::Throat => "the impact near the throat",
            Shot::Spin => "the topspin forehand",
        }
    }
}

/// Whose impact: a racket of the card, or the paper's 200 Hz frame set beside the paper's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Who {
    /// The card's racket `i` (0: A, 1: B).
    Variant(usize),
    /// The paper's 200 Hz frame ([`super::WIDEBODY_PRESET`]).
    Widebody,
}

/// One impact to run: whose, at which tension, which shot, and its parameters as it runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Job {
    /// Whose.
    pub who: Who,
    /// The tension, lb.
    pub tension_lb: f64,
    /// The shot.
    pub shot: Shot,
    /// Its parameters (the impact point, speed and incidence set).
    pub params: Params,
}

impl Job {
    /// Whether the job runs: all but the spin shot on a rigid frame ([`Outcome::Skipped`]).
    pub fn runs(&self) -> bool {
        !(self.shot == Shot::Spin && self.params.variants.frame == Frame::Rigid)
    }
}

/// The parameters of `shot` on `base` (at its tension) hit at `points`.
pub fn shot_params(base: &Params, points: &Points, strokes: &Strokes, shot: Shot) -> Params {
    let at = |(x, r): (f64, f64), v1: f64| {
        let mut p = params_at(base, x, r);
        p.impact.v1 = v1;
        p
    };
    let (serve, forehand) = (strokes.serve_m_per_s, strokes.forehand_m_per_s);
    match shot {
        Shot::ServeCentre => at((points.centre, 0.0), serve),
        Shot::ServeOff => at(points.off, serve),
        Shot::ForehandCentre => at((points.centre, 0.0), 2.0 * forehand),
        Shot::ForehandOff => at(points.off, 2.0 * forehand),
        Shot::Centre => at((points.centre, 0.0), TWIST_V1),
        Shot::Twist => at((points.centre, TWIST_R), TWIST_V1),
        Shot::Tip => at((points.tip, 0.0), TWIST_V1),
        Shot::Throat => at((points.throat, 0.0), TWIST_V1),
        Shot::Spin => SPIN_SHOT.impact_params(&params_at(base, points.centre, 0.0)),
    }
}

/// What one impact gave.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// A head-on stroke: the impact and the ball's speed ([`SpeedRow::head_on`]).
    Stroke(ImpactResult, f64),
    /// An impact ([`simulate`]).
    Impact(ImpactResult),
    /// The spin shot's exit ([`crate::solve::swing::Swing::hit`]).
    Spin(Box<Exit>),
    /// Not run: the spin shot on a rigid frame, which takes no oblique impact.
    Skipped,
}

impl Outcome {
    /// The impact (none for a shot not run).
    pub fn impact(&self) -> Option<&ImpactResult> {
        match self {
            Outcome::Stroke(r, _) | Outcome::Impact(r) => Some(r),
            Outcome::Spin(e) => Some(&e.impact),
            Outcome::Skipped => None,
        }
    }
}

/// Run `job` as its command does: a stroke as `speed` ([`SpeedRow::head_on`]), the spin shot
/// as `speed`'s stroke ([`crate::solve::swing::Swing::hit`]), any other impact as `simulate`.
pub fn run_job(job: &Job, strokes: &Strokes) -> Result<Outcome> {
    let p = &job.params;
    let (serve, forehand) = (strokes.serve_m_per_s, strokes.forehand_m_per_s);
    let stroke = |v_in: f64, v_racket: f64| {
        SpeedRow::head_on(String::new(), p, v_in, v_racket).map(|row| Outcome::Stroke(row.result, row.v_out))
    };
    match job.shot {
        Shot::ServeCentre | Shot::ServeOff => stroke(0.0, serve),
        Shot::ForehandCentre | Shot::ForehandOff => stroke(forehand, forehand),
        // the rigid frame's closed form has no tangential contact (it follows the beam's normal
        // force history): the card says it has no spin
        Shot::Spin if !job.runs() => Ok(Outcome::Skipped),
        // (the stroke sets the same speed, incidence and spin again: the exit of these parameters)
        Shot::Spin => SPIN_SHOT.hit(p).map(|e| Outcome::Spin(Box::new(e))),
        Shot::Centre | Shot::Twist | Shot::Tip | Shot::Throat => {
            p.validate()?;
            simulate(p).map(Outcome::Impact)
        }
    }
}

/// The sweet spot of one map: the face area where e_A is within `within` of its best.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sweet {
    /// The area, m^2: the points counted times the grid cell.
    pub area_m2: f64,
    /// Map points with `e_A >= threshold`.
    pub points: usize,
    /// The grid cell, m^2 (dx dr).
    pub cell_m2: f64,
    /// The best e_A and where it lies.
    pub best: MapPoint,
    /// `(1 - within) * best`.
    pub threshold: f64,
}

impl Sweet {
    /// The sweet spot of `map`: the points with `e_A >= (1 - within) max e_A`, each standing for
    /// one grid cell `dx dr` (`None` for a map without points).
    pub fn of(map: &FaceMap, within: f64) -> Option<Sweet> {
        let best = map.max_point(Quantity::EA)?;
        let threshold = (1.0 - within) * best.value;
        let points = map.points().filter(|(_, _, r)| r.e_a >= threshold).count();
        let (xs, rs) = (&map.grid.xs, &map.grid.rs);
        let cell_m2 = (xs[1] - xs[0]) * (rs[1] - rs[0]);
        Some(Sweet { area_m2: points as f64 * cell_m2, points, cell_m2, best, threshold })
    }
}

/// One racket at one tension: every panel's numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Whose.
    pub who: Who,
    /// The tension, lb.
    pub tension_lb: f64,
    /// Each shot's parameters and outcome, in [`Shot::ALL`]'s order.
    pub shots: Vec<(Params, Outcome)>,
    /// The sweet spot (for the card's rackets at the card's tensions).
    pub sweet: Option<Sweet>,
}

impl Row {
    /// The parameters and outcome of `shot`.
    pub fn get(&self, shot: Shot) -> (&Params, &Outcome) {
        let i = Shot::ALL.iter().position(|&s| s == shot).unwrap_or(0);
        (&self.shots[i].0, &self.shots[i].1)
    }

    /// The impact of `shot` (none for a shot not run).
    pub fn impact(&self, shot: Shot) -> Option<&ImpactResult> {
        self.get(shot).1.impact()
    }

    /// `f` of the impact of `shot` (NaN for a shot not run).
    pub fn of(&self, shot: Shot, f: impl Fn(&ImpactResult) -> f64) -> f64 {
        self.impact(shot).map_or(f64::NAN, f)
    }

    /// The ball's speed off a stroke, m/s (NaN for another shot).
    pub fn speed(&self, shot: Shot) -> f64 {
        match self.get(shot).1 {
            Outcome::Stroke(_, v) => *v,
            _ => f64::NAN,
        }
    }

    /// The spin shot's exit.
    pub fn spin(&self) -> Option<&Exit> {
        match self.get(Shot::Spin).1 {
            Outcome::Spin(e) => Some(e),
            _ => None,
        }
    }
}

/// A card, run.
#[derive(Debug, Clone)]
pub struct Card {
    /// What ran.
    pub prepared: Prepared,
    /// One row per racket and tension of the card (racket A's tensions, then B's).
    pub rows: Vec<Row>,
    /// For the paper's racket: its rows at 50 and 60 lb and the 200 Hz frame's at 60 lb (the
    /// paper's conclusions are read off them).
    pub paper_rows: Vec<Row>,
    /// What the spin panel's law was validated on.
    pub status: SpinStatus,
    /// The notes about unused flags, then the checks of the impacts' parameters and results.
    pub diagnostics: Vec<Diagnostic>,
}

/// The tensions of the paper's 60 -> 50 lb conclusions, lb.
pub const PAPER_TENSIONS_LB: [f64; 2] = [50.0, 60.0];

impl Prepared {
    /// The base of `who` at its own tension.
    fn base(&self, who: Who) -> Option<(&Params, &Points)> {
        match who {
            Who::Variant(i) => self.variants.get(i).map(|v| (&v.params, &v.points)),
            Who::Widebody => self.widebody.as_ref().map(|p| (p, &self.variants[0].points)),
        }
    }

    /// The rows to compute, (who, tension, with a map): every racket at every tension with its
    /// map; for the paper's racket its rows at the paper's 50 and 60 lb and the 200 Hz frame's
    /// at 60 lb, without.
    fn row_keys(&self) -> Vec<(Who, f64, bool)> {
        let mut keys: Vec<(Who, f64, bool)> = Vec::new();
        for i in 0..self.variants.len() {
            keys.extend(self.tensions_lb.iter().map(|&t| (Who::Variant(i), t, true)));
        }
        if self.widebody.is_some() {
            keys.extend(PAPER_TENSIONS_LB.iter().map(|&t| (Who::Variant(0), t, false)));
            keys.push((Who::Widebody, 60.0, false));
        }
        keys
    }

    /// Every impact the card runs outside its maps, in the order of its rows and shots.
    pub fn jobs(&self) -> Vec<Job> {
        let strokes = &self.request.strokes;
        let mut jobs = Vec::new();
        for (who, t, _) in self.row_keys() {
            if let Some((base, points)) = self.base(who) {
                let base = at_tension(base, t);
                jobs.extend(Shot::ALL.iter().map(|&shot| Job {
                    who,
                    tension_lb: t,
                    shot,
                    params: shot_params(&base, points, strokes, shot),
                }));
            }
        }
        jobs
    }

    /// The maps: (row index among [`Prepared::row_keys`], parameters at the tension, points).
    fn maps(&self) -> Vec<(usize, Params)> {
        self.row_keys()
            .iter()
            .enumerate()
            .filter(|(_, (_, _, map))| *map)
            .filter_map(|(k, &(who, t, _))| self.base(who).map(|(p, _)| (k, at_tension(p, t))))
            .collect()
    }

    /// The impacts of every map.
    fn map_points(&self) -> Result<Vec<usize>> {
        let (nx, nr) = self.request.grid;
        self.maps().iter().map(|(_, p)| FaceMap::count(p, nx, nr)).collect()
    }

    /// The jobs that run (all but the spin shot on a rigid frame, [`Outcome::Skipped`]).
    fn running(&self) -> Vec<Job> {
        self.jobs().into_iter().filter(Job::runs).collect()
    }

    /// How many impacts the card runs: its jobs and its maps' points.
    pub fn impacts(&self) -> Result<u64> {
        Ok((self.running().len() + self.map_points()?.iter().sum::<usize>()) as u64)
    }

    /// The card's work, estimated before it runs ([`crate::study::work`]): its jobs with their
    /// solver, and its maps with the map's.
    pub fn estimate(&self, threads: usize) -> Result<Estimate> {
        let jobs = self.running();
        let single = Estimate::of(jobs.len() as u64, threads, |i| jobs.get(i as usize).map(|j| j.params));
        let maps = self.maps();
        let counts = self.map_points()?;
        let total: usize = counts.iter().sum();
        // the map of impact i: the one whose share of the total holds it
        let map_of = |i: u64| {
            let mut seen = 0;
            maps.iter().zip(&counts).find(|(_, &n)| {
                seen += n;
                (i as usize) < seen
            })
        };
        let mapped = Estimate::of(total as u64, threads, |i| map_of(i).map(|((_, p), _)| with_map_solver(p)));
        let heaviest =
            [single.heaviest, mapped.heaviest].into_iter().flatten().max_by(|a, b| a.cpu_s.total_cmp(&b.cpu_s));
        Ok(Estimate {
            impacts: single.impacts + mapped.impacts,
            cpu_s: single.cpu_s + mapped.cpu_s,
            threads: threads.max(1),
            heaviest,
        })
    }

    /// [`Prepared::estimate`] on the threads the card will run on (rayon's pool).
    pub fn estimate_here(&self) -> Result<Estimate> {
        self.estimate(rayon::current_num_threads())
    }

    /// Run the card: its jobs in parallel, then its maps. Under a control
    /// ([`crate::control`], the command layer's) every impact counts itself and the run stops
    /// once it is cancelled.
    pub fn run(&self) -> Result<Card> {
        let strokes = self.request.strokes;
        let jobs = self.jobs();
        let watch = crate::control::current();
        let outcomes: Vec<Outcome> = jobs
            .par_iter()
            .map(|j| crate::control::within(watch.as_ref(), || run_job(j, &strokes)))
            .collect::<Result<_>>()?;
        let keys = self.row_keys();
        let mut rows: Vec<Row> = keys
            .iter()
            .enumerate()
            .map(|(k, &(who, t, _))| {
                let from = k * Shot::ALL.len();
                let shots = (from..from + Shot::ALL.len()).map(|i| (jobs[i].params, outcomes[i].clone())).collect();
                Row { who, tension_lb: t, shots, sweet: None }
            })
            .collect();
        let (nx, nr) = self.request.grid;
        for (k, p) in self.maps() {
            if let Some(ctl) = &watch {
                ctl.check()?;
            }
            let map = FaceMap::compute(&p, nx, nr, &mut |_| {})?;
            rows[k].sweet = Some(Sweet::of(&map, self.request.sweet_within).ok_or_else(|| {
                Error::invalid("nx", format!("{nx} (with nr = {nr})"), "no map point lies inside the string face")
            })?);
        }
        let paper_rows = rows.split_off(keys.iter().filter(|(_, _, map)| *map).count());
        let a = &self.variants[0].params;
        let status = SpinStatus::of(a.oblique.tangential, a.oblique.string)?;
        // the parameters' checks once, then each result's, the first of each kind, named by its shot
        let mut diagnostics = self.noted.clone();
        diagnostics.extend(crate::intake::diagnose::parameters(jobs.iter().map(|j| &j.params), &[]));
        for (j, r) in jobs.iter().zip(&outcomes).filter_map(|(j, o)| o.impact().map(|r| (j, r))) {
            for mut d in crate::intake::diagnose::impact(&j.params, r) {
                if !diagnostics.iter().any(|e| e.field == d.field) {
                    let who = match j.who {
                        Who::Variant(i) => self.variants[i].label.clone(),
                        Who::Widebody => super::WIDEBODY_PRESET.to_string(),
                    };
                    d.sentence = format!(
                        "{} on {who} at {} lb: {}",
                        j.shot.words(),
                        crate::numfmt::sig(j.tension_lb, 4),
                        d.sentence
                    );
                    diagnostics.push(d);
                }
            }
        }
        Ok(Card { prepared: self.clone(), rows, paper_rows, status, diagnostics })
    }
}
