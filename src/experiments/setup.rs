//! What every experiment runs on: the racket and ball ([`Context`]), the paper's impact
//! parameters on them, and the helpers that run impacts the way the paper's figures do.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use crate::error::{Error, Result};
use crate::model::beam::{Beam, Modes};
use crate::params::{Ball, LoadRule, Params, Racket, SolverKind};
use crate::render::plot::{Chart, LineStyle};
use crate::solve::{simulate, ImpactResult};

/// "Centre of the strings": the node of mode 1 as the paper places it, m from the tip.
pub const CENTRE_X: f64 = 0.158;
/// Incident speed of Figs 7-8, m/s.
pub const V1_OFF_AXIS: f64 = 30.0;

/// The racket and ball an experiment runs on: the paper's ([`Context::paper`]) unless
/// `figures --racket` chose another ([`Context::with_racket`]). The paper-number report always
/// uses the paper's.
#[derive(Debug, Clone, PartialEq)]
pub struct Context {
    /// The racket.
    pub racket: Racket,
    /// The ball.
    pub ball: Ball,
    /// The racket's name when it is not the paper's (`figures --racket`): the figures say it in
    /// their titles and leave out the paper's markers, which belong to the paper's racket.
    pub racket_name: Option<String>,
    /// A factor on every string stiffness the experiments use (1: the paper's tension
    /// calibration; the `robustness` experiment draws it).
    pub ks_factor: f64,
    /// A factor on the 30 m/s of Figs 7-8 (1: the paper's).
    pub v1_factor: f64,
    /// The solver of every impact: the explicit reference (`fd`) for the paper's numbers; the
    /// `robustness` experiment samples with the modal one.
    pub solver: SolverKind,
    /// The shape of the tension calibration the claims use ([`Context::ks_at_tension_lb`]): 0
    /// (ours, the paper's "approximately proportional": 60 lb = 4e4 N/m) to 1 (the paper's
    /// "typically between 2e4 and 6e4 N/m for ... 40 lb to 80 lb" as a straight line); the
    /// `robustness` experiment draws it.
    pub tension_shape: f64,
    /// The numerics of every beam the claims run: the paper's (N = 39, force on the nearest
    /// node) or converged (`hat` load, N = 320). A claim's converged value is its own
    /// computation run again on a converged context.
    pub scheme: Scheme,
    /// What the claims run through [`Context::impact`] and [`Context::modes`], where asked for
    /// ([`Context::recording`]): how the report tells a claim computed from a beam run from a
    /// closed form, and which position each impact was read at.
    pub runs: Runs,
    /// Impacts already run on this context (shared by its clones), where asked for
    /// ([`Context::remembering`]): claims that run the same impact share it.
    pub memo: Memo,
    /// The length (m) of the racket whose N = 39 nodes place every load under the paper's
    /// numerics, where it is not this context's own: the robustness study draws the racket's
    /// length but holds each load at the physical point the nominal run loads
    /// ([`Context::holding_loads`]). `None`: the context's own racket.
    pub grid_length: Option<f64>,
}

/// The numerics of a context's beams.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// The paper's: N = 39 segments, the whole force on the node nearest the impact point (an
    /// impact the paper set up, [`reading_rule`]).
    Paper,
    /// Converged: the force shared between the two neighbouring nodes (`hat`), N = 320.
    Converged,
    /// The paper's beam read as the paper read its printed curves (SPEC.md section 4,
    /// [`reading_rule`]): an impact at a position between two nodes is the straight line between
    /// the impacts on those two nodes ([`ImpactResult::lerp`]).
    Curve,
}

/// Segments of the converged beam.
pub const CONVERGED_SEGMENTS: usize = 320;

impl Scheme {
    /// The load rule and segment count of the scheme.
    pub fn numerics(self) -> (LoadRule, usize) {
        match self {
            Scheme::Paper | Scheme::Curve => (LoadRule::Node, 39),
            Scheme::Converged => (LoadRule::Hat, CONVERGED_SEGMENTS),
        }
    }
}

/// How every claim's value is computed and read, stated once (the report quotes it, SPEC.md
/// section 4 states it too): "computed as the paper computed, read as the paper read". The
/// node positions it names are computed on `racket` (the paper's, for the report).
pub fn reading_rule(racket: &Racket) -> String {
    let at = |x: f64| {
        let (node, at) = paper_node(x, racket);
        format!("node {node} at {:.2} cm", 100.0 * at)
    };
    let s = racket.length / Scheme::Paper.numerics().1 as f64;
    let j = (CENTRE_X / s).floor();
    format!(
        "computed as the paper computed, read as the paper read. The paper computed its impacts at the nodes of its \
         N = 39 beam, with the whole force on the node nearest the impact point (the ball 'impacts on only one of the \
         segments', p. 2; ties go to the node nearer the handle), and it states two kinds of number. An *impact* is \
         the result of a computation it set up: an impact at a position its caption or text states (Fig 4's x = 10 \
         cm, {}; Figs 6 and 9's x = 6 cm, {}; Figs 7 and 8's x = 10 and 15.8 cm, {} and {}), a drop, the beam's \
         modes, or arithmetic on its inputs; we compute it as the paper did, at the node its scheme loads. A *curve* \
         value is one it read off a curve it plotted against position (Fig 5) at a point it did not compute (the \
         centre of the strings, 15.8 cm, between nodes {} and {} at {:.2} and {:.2} cm; the node at 16 cm), or derived \
         from such values; we read it off our N = 39 curve, on the straight line between the two computed nodes. \
         Each claim's reading is decided from its quote alone (column `reading` of `golden/paper_claims.csv`, with \
         the words that decide it in `reading_words`); the other reading is set beside it, and the converged value \
         (`hat` load, N = 320) is the same computation at the nominal position. The figures draw their curves \
         through the computed nodes and print the node used where an impact they set up falls between two",
        at(0.10),
        at(0.06),
        at(0.10),
        at(CENTRE_X),
        j as usize,
        j as usize + 1,
        100.0 * j * s,
        100.0 * (j + 1.0) * s,
    )
}

/// One beam a claim ran: an impact or an eigenproblem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run {
    /// Segments of the beam.
    pub segments: usize,
    /// Its load rule (impacts; `None` for an eigenproblem).
    pub load: Option<LoadRule>,
    /// The nominal impact position, m from the tip (impacts).
    pub x: Option<f64>,
    /// Where the force was applied, m from the tip (impacts; the nearest node under the paper's
    /// scheme).
    pub x_load: Option<f64>,
}

impl Run {
    /// Whether the run used the numerics of `scheme`.
    pub fn under(&self, scheme: Scheme) -> bool {
        let (load, segments) = scheme.numerics();
        self.segments == segments && self.load.is_none_or(|l| l == load)
    }
}

/// A shared record of the beams a context ran (empty unless asked for). Not part of what a
/// context is: two contexts compare equal whatever they recorded.
#[derive(Debug, Clone, Default)]
pub struct Runs(Option<Arc<Mutex<Vec<Run>>>>);

impl PartialEq for Runs {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Runs {
    fn push(&self, run: Run) {
        if let Some(log) = &self.0 {
            log.lock().unwrap_or_else(std::sync::PoisonError::into_inner).push(run);
        }
    }

    /// What was recorded, in the order it ran (for a parallel sweep, in any order).
    pub fn taken(&self) -> Vec<Run> {
        self.0
            .as_ref()
            .map_or_else(Vec::new, |log| log.lock().unwrap_or_else(std::sync::PoisonError::into_inner).clone())
    }
}

/// A shared store of impacts already run (none unless asked for), keyed by their exact
/// parameters. Not part of what a context is.
#[derive(Debug, Clone, Default)]
pub struct Memo(Option<Arc<Mutex<HashMap<String, ImpactResult>>>>);

impl PartialEq for Memo {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Default for Context {
    fn default() -> Self {
        Context::paper()
    }
}

impl Context {
    /// The paper's racket and ball.
    pub fn paper() -> Self {
        let p = Params::paper();
        Context {
            racket: p.racket,
            ball: p.ball,
            racket_name: None,
            ks_factor: 1.0,
            v1_factor: 1.0,
            solver: p.numerics.solver,
            tension_shape: 0.0,
            scheme: Scheme::Paper,
            runs: Runs::default(),
            memo: Memo::default(),
            grid_length: None,
        }
    }

    /// The same context with converged numerics ([`Scheme::Converged`]).
    pub fn converged(mut self) -> Self {
        self.scheme = Scheme::Converged;
        self
    }

    /// The same context recording the beams it runs from now on (a fresh record).
    pub fn recording(mut self) -> Self {
        self.runs = Runs(Some(Arc::default()));
        self
    }

    /// The same context remembering the impacts it runs from now on (a fresh store, shared by
    /// its clones).
    pub fn remembering(mut self) -> Self {
        self.memo = Memo(Some(Arc::default()));
        self
    }

    /// The same context with every load under the paper's numerics held where the paper's
    /// N = 39 beam of this context's racket puts it, whatever racket it is given later
    /// ([`Context::grid_length`]): an impact set up at `x` is loaded at the position of the node
    /// the nominal beam loads, a curve is read between the nominal beam's nodes, each position
    /// loaded with the force shared between the neighbouring nodes of the beam at hand (`hat`),
    /// so that a drawn length moves no load.
    pub fn holding_loads(mut self) -> Self {
        self.grid_length = Some(self.racket.length);
        self
    }

    /// The positions (m from the tip) of the nodes of the paper's N = 39 beam that place the
    /// loads ([`Context::grid_length`], else this context's racket), whatever the context's
    /// numerics: the points the paper's figures computed.
    pub fn paper_nodes(&self) -> Vec<f64> {
        let n = Scheme::Paper.numerics().1;
        let length = self.grid_length.unwrap_or(self.racket.length);
        (0..=n).map(|i| length * i as f64 / n as f64).collect()
    }

    /// One impact for a claim: [`impact`] under this context's record and store. Under the
    /// paper's numerics an impact set up between two nodes is loaded on the nearest
    /// ([`Scheme::Paper`]) or read between the two ([`Scheme::Curve`]); on a context holding its
    /// loads ([`Context::holding_loads`]) the nodes are those of the held beam.
    pub fn impact(&self, p: &Params) -> Result<ImpactResult> {
        let n = p.numerics.segments;
        if self.scheme == Scheme::Converged {
            return self.one_impact(p);
        }
        let s = self.grid_length.unwrap_or(p.racket.length) / n as f64;
        if self.scheme == Scheme::Curve {
            let j = ((p.impact.x / s).floor().max(0.0) as usize).min(n - 1);
            let w = p.impact.x / s - j as f64;
            if w > 1e-9 && w < 1.0 - 1e-9 {
                return Ok(ImpactResult::lerp(&self.at_node(p, j, s)?, &self.at_node(p, j + 1, s)?, w));
            }
        }
        match self.grid_length {
            // the nearest node of the held beam, ties towards the handle as the node rule's
            Some(_) => self.at_node(p, (((p.impact.x / s).max(0.0) + 0.5).floor() as usize).min(n), s),
            None => self.one_impact(p),
        }
    }

    /// The impact `p` loaded at node `j` of a beam of spacing `s`: on a context holding its loads,
    /// at that node's position with the force shared between the nodes of the beam at hand.
    fn at_node(&self, p: &Params, j: usize, s: f64) -> Result<ImpactResult> {
        let mut q = *p;
        q.impact.x = j as f64 * s;
        if self.grid_length.is_some() {
            q.numerics.load = LoadRule::Hat;
        }
        self.one_impact(&q)
    }

    /// One impact under this context's record and store.
    fn one_impact(&self, p: &Params) -> Result<ImpactResult> {
        let done = |r: &ImpactResult| {
            self.runs.push(Run {
                segments: p.numerics.segments,
                load: Some(p.numerics.load),
                x: Some(p.impact.x),
                x_load: Some(r.x_load_m),
            })
        };
        let Some(memo) = &self.memo.0 else {
            let r = impact(p)?;
            done(&r);
            return Ok(r);
        };
        let key = format!("{p:?}");
        let known = memo.lock().unwrap_or_else(std::sync::PoisonError::into_inner).get(&key).copied();
        let r = match known {
            Some(r) => r,
            None => {
                let r = impact(p)?;
                memo.lock().unwrap_or_else(std::sync::PoisonError::into_inner).insert(key, r);
                r
            }
        };
        done(&r);
        Ok(r)
    }

    /// [`Context::impact`] for each parameter set, in parallel, results in the order given.
    pub fn sweep(&self, params: &[Params]) -> Result<Vec<ImpactResult>> {
        use rayon::prelude::*;
        let watch = crate::control::current();
        params.par_iter().map(|p| crate::control::within(watch.as_ref(), || self.impact(p))).collect()
    }

    /// The free-free modes of `racket` on this context's beam (N of its [`Scheme`]).
    pub fn modes(&self, racket: &Racket) -> (Beam, Modes) {
        let segments = self.scheme.numerics().1;
        self.runs.push(Run { segments, load: None, x: None, x_load: None });
        let beam = Beam::new(racket, segments);
        let modes = beam.modes();
        (beam, modes)
    }

    /// Another racket and ball. The paper's figures place impacts along the whole length, as
    /// the paper does, so the racket's head outline is not applied (the face is the strip
    /// `|r| <= half-width`, at least the paper's 12.5 cm).
    pub fn with_racket(mut racket: Racket, ball: Ball) -> Self {
        racket.head_length = None;
        racket.half_width = racket.half_width.max(Racket::default().half_width);
        Context { racket, ball, ..Context::paper() }
    }

    /// The context of the racket `arg` (a file or preset, as `figures --racket` takes it),
    /// fitted at the paper's segment count and named by its `name`, else its file stem.
    pub fn for_racket(arg: &str) -> Result<Self> {
        let spec = crate::racket::load(arg)?;
        let fitted = spec.to_racket(Params::paper().numerics.segments)?;
        let stem = std::path::Path::new(arg).file_stem().and_then(|s| s.to_str()).unwrap_or("custom");
        Ok(Context::with_racket(fitted.racket, fitted.ball)
            .named(spec.name.clone().unwrap_or_else(|| stem.to_string())))
    }

    /// The same context naming its racket (not the paper's).
    pub fn named(mut self, name: impl Into<String>) -> Self {
        self.racket_name = Some(name.into());
        self
    }

    /// An experiment's chart as drawn for this context: on another racket than the paper's,
    /// the paper's values (its [`LineStyle::Paper`] markers and any curve labelled "paper...")
    /// are left out, since they describe the paper's racket, and the title names the racket.
    pub fn adapt(&self, mut chart: Chart) -> Chart {
        if let Some(name) = &self.racket_name {
            chart.curves.retain(|c| c.style != LineStyle::Paper && !c.label.starts_with("paper"));
            chart.title = format!("{} (racket: {name}; the paper's values left out)", chart.title);
        }
        chart
    }

    /// The paper's parameters (the Fig 4 impact) on this racket and ball, with the numerics of
    /// this context's [`Scheme`] (the paper's: node load, N = 39).
    pub fn base_params(&self) -> Params {
        let mut p = Params::paper();
        p.racket = self.racket;
        p.ball = self.ball;
        p.numerics.solver = self.solver;
        (p.numerics.load, p.numerics.segments) = self.scheme.numerics();
        p
    }

    /// The string stiffness (N/m) of a tension (lb) as the paper's k_s scale, before
    /// [`Context::ks`]: [`ks_proportional`] and [`ks_paper_range`] mixed by
    /// [`Context::tension_shape`].
    pub fn ks_at_tension_lb(&self, tension_lb: f64) -> f64 {
        let w = self.tension_shape;
        (1.0 - w) * ks_proportional(tension_lb) + w * ks_paper_range(tension_lb)
    }

    /// The string stiffness standing for the paper's `paper_ks` (N/m): `paper_ks` times
    /// [`Context::ks_factor`].
    pub fn ks(&self, paper_ks: f64) -> f64 {
        paper_ks * self.ks_factor
    }

    /// The incident speed of Figs 7-8, m/s: [`V1_OFF_AXIS`] times [`Context::v1_factor`].
    pub fn v1_off_axis(&self) -> f64 {
        V1_OFF_AXIS * self.v1_factor
    }

    /// The bending stiffness standing for the paper's `paper_ei` (N m^2) on this racket: the
    /// same ratio to the racket's own EI as `paper_ei` has to the paper's 150 N m^2 (exactly
    /// `paper_ei` for the paper's racket), so the frame comparisons of Figs 6 and 9 become
    /// "your frame, and your frame 2.56 times stiffer".
    pub fn frame_ei(&self, paper_ei: f64) -> f64 {
        self.racket.ei * paper_ei / Racket::default().ei
    }

    /// This racket, ball and the context's numerics (the paper's: node load, N = 39) with an
    /// impact on the long axis, the strings at [`Context::ks`] of `ks`.
    pub fn paper_params(&self, x: f64, ks: f64) -> Params {
        let mut p = self.base_params();
        p.impact.x = x;
        p.impact.r = 0.0;
        p.strings.ks = self.ks(ks);
        p
    }
}

/// k_s (N/m) of a string tension (lb) read as the paper's "approximately proportional" (p. 7)
/// and its 60 -> 50 lb arithmetic: proportional, 60 lb = 4e4 N/m (ours, SPEC.md section 3;
/// [`crate::params::ks_from_tension_lb`]).
pub fn ks_proportional(tension_lb: f64) -> f64 {
    crate::params::ks_from_tension_lb(tension_lb)
}

/// k_s (N/m) of a string tension (lb) read as the paper's "typically between 2e4 and 6e4 N/m for
/// string tensions in the range 40 lb to 80 lb" (p. 3): the straight line through 2e4 at 40 lb
/// and 6e4 at 80 lb (50 lb = 3e4, 60 lb = 4e4 N/m).
pub fn ks_paper_range(tension_lb: f64) -> f64 {
    2.0e4 + (tension_lb - 40.0) * (6.0e4 - 2.0e4) / 40.0
}

/// One impact for an experiment: as [`simulate`], but a re-contact after separation (which the
/// model does not follow) is an error rather than a number in a paper figure.
pub fn impact(p: &Params) -> Result<ImpactResult> {
    checked(p, simulate(p)?)
}

/// Refuse a result with a re-contact.
pub fn checked(p: &Params, r: ImpactResult) -> Result<ImpactResult> {
    if r.recontact {
        return Err(Error::Recontact { x: p.impact.x, r: p.impact.r, ks: p.strings.ks });
    }
    Ok(r)
}

/// The same racket with converged numerics: `hat` load on N = 320 segments.
pub fn converged(mut p: Params) -> Params {
    p.numerics.load = LoadRule::Hat;
    p.numerics.segments = 320;
    p
}

/// Positions of the N+1 nodes of the paper's beam, m from the tip.
pub fn node_positions(p: &Params) -> Vec<f64> {
    let n = p.numerics.segments;
    (0..=n).map(|i| p.racket.length * i as f64 / n as f64).collect()
}

/// Where the paper's scheme puts the force of an impact at `x` (m from the tip) on `racket`:
/// the nearest of the N = 39 nodes, ties towards the handle ([`reading_rule`]); (node, m).
pub fn paper_node(x: f64, racket: &Racket) -> (usize, f64) {
    let (load, n) = Scheme::Paper.numerics();
    let point = Beam::new(racket, n).load_point(x, load);
    (point.nodes[0], point.x_load)
}

/// " (N = 39: node 9 at 16.38 cm)" where the paper's scheme loads another point than `x` (m)
/// on `racket`, else "": what a figure's title adds to a nominal position.
pub fn used_position(x: f64, racket: &Racket) -> String {
    let (node, at) = paper_node(x, racket);
    if (at - x).abs() < 1e-9 {
        String::new()
    } else {
        format!(" (N = 39: node {node} at {:.2} cm)", 100.0 * at)
    }
}

/// Run [`impact`] for each parameter set, in parallel, results in the order given.
pub fn sweep(params: &[Params]) -> Result<Vec<ImpactResult>> {
    use rayon::prelude::*;
    let watch = crate::control::current();
    params.par_iter().map(|p| crate::control::within(watch.as_ref(), || impact(p))).collect()
}

/// `n` log-spaced values from `a` to `b` inclusive.
pub fn log_space(a: f64, b: f64, n: usize) -> Vec<f64> {
    let (la, lb) = (a.log10(), b.log10());
    (0..n).map(|i| 10f64.powf(la + (lb - la) * i as f64 / (n - 1) as f64)).collect()
}
