//! What every experiment runs on: the racket and ball ([`Context`]), the paper's impact
//! parameters on them, and the helpers that run impacts the way the paper's figures do.

use crate::error::{Error, Result};
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
    /// Whether the claims also compute their converged counterpart (`hat` load, N = 320):
    /// the report's; off while the `robustness` experiment samples.
    pub converged_too: bool,
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
            converged_too: true,
        }
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

    /// The paper's parameters (the Fig 4 impact, node load, N = 39) on this racket and ball.
    pub fn base_params(&self) -> Params {
        let mut p = Params::paper();
        p.racket = self.racket;
        p.ball = self.ball;
        p.numerics.solver = self.solver;
        p
    }

    /// The string stiffness standing for the paper's `paper_ks` (N/m): `paper_ks` times
    /// [`Context::ks_factor`].
    pub fn ks(&self, paper_ks: f64) -> f64 {
        paper_ks * self.ks_factor
    }

    /// A claim's converged counterpart `f()` where [`Context::converged_too`], else `None`.
    pub fn converged(&self, f: impl FnOnce() -> Result<f64>) -> Result<Option<f64>> {
        if self.converged_too {
            f().map(Some)
        } else {
            Ok(None)
        }
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

    /// This racket, ball and the paper's numerics (node load, N = 39) with an impact on the
    /// long axis, the strings at [`Context::ks`] of `ks`.
    pub fn paper_params(&self, x: f64, ks: f64) -> Params {
        let mut p = self.base_params();
        p.impact.x = x;
        p.impact.r = 0.0;
        p.strings.ks = self.ks(ks);
        p
    }
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

/// A quantity of the node-scheme curve read off at `x` the way a reader of the printed figure
/// would: by linear interpolation between the two nodes around `x` (SPEC.md section 4).
pub fn read_off_curve(p: &Params, x: f64, quantity: impl Fn(&ImpactResult) -> f64) -> Result<f64> {
    let s = p.racket.length / p.numerics.segments as f64;
    let j = ((x / s).floor() as usize).min(p.numerics.segments - 1);
    let w = x / s - j as f64;
    let at = |i: usize| -> Result<f64> {
        let mut q = *p;
        q.numerics.load = LoadRule::Node;
        q.impact.x = i as f64 * s;
        impact(&q).map(|r| quantity(&r))
    };
    Ok((1.0 - w) * at(j)? + w * at(j + 1)?)
}

/// Run [`impact`] for each parameter set, in parallel, results in the order given.
pub fn sweep(params: &[Params]) -> Result<Vec<ImpactResult>> {
    use rayon::prelude::*;
    params.par_iter().map(impact).collect()
}

/// `n` log-spaced values from `a` to `b` inclusive.
pub fn log_space(a: f64, b: f64, n: usize) -> Vec<f64> {
    let (la, lb) = (a.log10(), b.log10());
    (0..n).map(|i| 10f64.powf(la + (lb - la) * i as f64 / (n - 1) as f64)).collect()
}
