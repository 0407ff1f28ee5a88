//! One module per result of the paper. Each experiment has an id, a title and a paper
//! reference, a function that runs the solver and returns one [`Table`], and a function that
//! turns that table into a [`Chart`]. One experiment = one file = one id = one CSV + one PNG
//! + one golden snapshot.
//!
//! | id | paper | module |
//! |---|---|---|
//! | `concrete_drop` | p. 3, Eqs 11-12: 100-inch drop on concrete | [`concrete_drop`] |
//! | `clamped_drop` | p. 3: drop on the strings of a head-clamped racket | [`clamped_drop`] |
//! | `modes` | p. 3-4: 125 Hz, 345 Hz, node 16 cm; wide body 200 Hz | [`modes`] |
//! | `fig4_energy` | Fig 4: energy partition, x 10 cm, r 5 cm, ks 4e4 | [`fig4_energy`] |
//! | `fig5a_position_soft`, `fig5b_position_stiff` | Fig 5 (a), (b) | [`fig5_position`] |
//! | `fig6_string_stiffness` | Fig 6 | [`fig6_string_stiffness`] |
//! | `fig7_off_axis_x10`, `fig8_off_axis_centre` | Figs 7, 8 | [`fig78_off_axis`] |
//! | `fig9_stiff_frame` | Fig 9 | [`fig9_stiff_frame`] |
//! | `speeds` | p. 5-6 and Conclusions: serve / forehand gains | [`speeds`] |
//! | `convergence` | (ours) the paper's N = 39 node scheme against converged numerics | [`convergence`] |
//! | `variant_rigid`, `variant_grip`, `variant_strings` | (ours) rigid frame, hand grip, stiffening strings against the paper's model | [`variants`] |
//!
//! All paper experiments use the paper's numerics (`node` load, N = 39) as SPEC.md asks;
//! `convergence` shows what that costs.

use std::path::Path;

use crate::error::{Error, Result};
use crate::params::{Ball, LoadRule, Params, Racket};
use crate::render::plot::Chart;
use crate::solver::{simulate, ImpactResult};

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
use crate::render::table::Table;

pub mod clamped_drop;
pub mod concrete_drop;
pub mod convergence;
pub mod fig4_energy;
pub mod fig5_position;
pub mod fig6_string_stiffness;
pub mod fig78_off_axis;
pub mod fig9_stiff_frame;
pub mod modes;
pub mod speeds;
pub mod variants;

/// A registered experiment.
#[derive(Clone, Copy)]
pub struct Experiment {
    /// Identifier, also the file stem of its CSV, PNG and snapshot.
    pub id: &'static str,
    /// One-line title.
    pub title: &'static str,
    /// Where in the paper the result is (figure / page / sentence).
    pub paper_ref: &'static str,
    /// Run the solver and return the table.
    pub run: fn() -> Result<Table>,
    /// Draw the table.
    pub chart: fn(&Table) -> Chart,
}

impl std::fmt::Debug for Experiment {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Experiment").field("id", &self.id).finish()
    }
}

/// Every experiment, in the paper's order.
pub fn registry() -> Vec<Experiment> {
    vec![
        concrete_drop::EXPERIMENT,
        clamped_drop::EXPERIMENT,
        modes::EXPERIMENT,
        fig4_energy::EXPERIMENT,
        fig5_position::SOFT,
        fig5_position::STIFF,
        fig6_string_stiffness::EXPERIMENT,
        fig78_off_axis::X10,
        fig78_off_axis::CENTRE,
        fig9_stiff_frame::EXPERIMENT,
        speeds::EXPERIMENT,
        convergence::EXPERIMENT,
        variants::RIGID,
        variants::GRIP,
        variants::STRINGS,
    ]
}

/// The experiment with this id.
pub fn find(id: &str) -> Result<Experiment> {
    registry().into_iter().find(|e| e.id == id).ok_or_else(|| Error::UnknownExperiment(id.to_string()))
}

/// Run one experiment and write `<out>/<id>.csv` and `<out>/<id>.png` (atomically).
pub fn run_and_write(exp: &Experiment, out: &Path) -> Result<Table> {
    let table = (exp.run)()?;
    if let Some((row, col)) = first_non_finite(&table) {
        return Err(Error::invalid(
            "table",
            format!("{}: row {row}, column {col}", exp.id),
            "every number in an experiment table must be finite",
        ));
    }
    crate::render::io::write_atomic(&out.join(format!("{}.csv", exp.id)), table.to_csv().as_bytes())?;
    crate::render::plot::render_png(exp.id, &(exp.chart)(&table), &out.join(format!("{}.png", exp.id)))?;
    Ok(table)
}

/// The first non-finite number in a table: (row, column name).
pub fn first_non_finite(t: &Table) -> Option<(usize, String)> {
    t.rows.iter().enumerate().find_map(|(i, row)| {
        row.iter()
            .position(|v| matches!(v, crate::render::table::Value::Num(x) if !x.is_finite()))
            .map(|j| (i, t.columns[j].clone()))
    })
}

/// "Centre of the strings": the node of mode 1 as the paper places it, m from the tip.
pub const CENTRE_X: f64 = 0.158;
/// Incident speed of Figs 7-8, m/s.
pub const V1_OFF_AXIS: f64 = 30.0;

/// The racket and ball the experiments run on: the paper's, unless `figures --racket` chose
/// another (see [`use_racket`]).
static RACKET: std::sync::RwLock<Option<(Racket, Ball)>> = std::sync::RwLock::new(None);

/// Run the experiments on another racket and ball (`None`: the paper's). The paper's figures
/// place impacts along the whole length, as the paper does, so the racket's head outline is
/// not applied (the face is the strip `|r| <= half-width`, at least the paper's 12.5 cm). The
/// paper-number report always uses the paper's racket.
pub fn use_racket(racket: Option<(Racket, Ball)>) {
    let racket = racket.map(|(mut r, b)| {
        r.head_length = None;
        r.half_width = r.half_width.max(Racket::default().half_width);
        (r, b)
    });
    *RACKET.write().unwrap_or_else(|e| e.into_inner()) = racket;
}

/// The paper's parameters (the Fig 4 impact, node load, N = 39) on the chosen racket.
pub fn base_params() -> Params {
    let mut p = Params::paper();
    if let Some((racket, ball)) = *RACKET.read().unwrap_or_else(|e| e.into_inner()) {
        p.racket = racket;
        p.ball = ball;
    }
    p
}

/// The bending stiffness standing for the paper's `paper_ei` (N m^2) on the chosen racket: the
/// same ratio to the racket's own EI as `paper_ei` has to the paper's 150 N m^2 (exactly
/// `paper_ei` for the paper's racket), so the frame comparisons of Figs 6 and 9 become "your
/// frame, and your frame 2.56 times stiffer".
pub fn frame_ei(paper_ei: f64) -> f64 {
    base_params().racket.ei * paper_ei / Racket::default().ei
}

/// The paper's racket, ball and numerics (node load, N = 39) with an impact on the long axis.
pub fn paper_params(x: f64, ks: f64) -> Params {
    let mut p = base_params();
    p.impact.x = x;
    p.impact.r = 0.0;
    p.strings.ks = ks;
    p
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

/// A solid curve on the left axis.
pub fn line(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>, color: usize) -> crate::render::plot::Curve {
    crate::render::plot::Curve {
        label: label.into(),
        x,
        y,
        axis: crate::render::plot::Axis::Left,
        style: crate::render::plot::LineStyle::Solid,
        color,
    }
}

/// The same curve on the right axis.
pub fn on_right(mut c: crate::render::plot::Curve) -> crate::render::plot::Curve {
    c.axis = crate::render::plot::Axis::Right;
    c
}

/// The same curve in another style.
pub fn styled(mut c: crate::render::plot::Curve, style: crate::render::plot::LineStyle) -> crate::render::plot::Curve {
    c.style = style;
    c
}

/// A column of a table produced by this crate (the experiments name their own columns, so a
/// missing one is a programming error caught by the snapshot tests).
pub fn col(t: &Table, name: &str) -> Vec<f64> {
    t.column(name).unwrap_or_else(|| vec![f64::NAN; t.rows.len()])
}

/// Multiply every value by `k` (unit changes for plotting, e.g. s -> ms).
pub fn scaled(v: Vec<f64>, k: f64) -> Vec<f64> {
    v.into_iter().map(|x| x * k).collect()
}
