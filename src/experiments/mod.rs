//! One module per result of the paper. Each experiment has an id, a title and a paper
//! reference, a function that runs the solver on a racket ([`Context`]) and returns one
//! [`Table`], a function that turns that table into a [`Chart`], and the paper's claims it
//! checks ([`PaperClaim`], collected by [`crate::report`]). One experiment = one file = one
//! id = one CSV + one PNG + one golden snapshot.
//!
//! The registry ([`each_experiment!`](crate::each_experiment), below) lists them, one line
//! each: an experiment is its file here and its line there. Its module, its place in
//! [`registry`] (the order of `figures` and of the report) and its golden test
//! (tests/golden.rs) follow from that line; each file's first line and its entry's
//! `paper_ref` say which figure, page or sentence of the paper it reproduces.
//!
//! All paper experiments use the paper's numerics (`node` load, N = 39) as SPEC.md asks;
//! `convergence` shows what that costs. Shared pieces: [`setup`] (the racket an experiment runs
//! on and the paper's impact parameters), [`curves`] (chart helpers), [`claims`] (a claim as an
//! experiment carries it), [`position`], [`off_axis`] and [`variants`] (what two or three
//! experiments share).

use std::path::Path;

use crate::error::{Error, Result};
use crate::render::plot::Chart;
use crate::render::table::{Table, Value};

pub mod claims;
pub mod conclusion;
pub mod curves;
pub mod setup;
pub mod tolerance;

pub mod off_axis;
pub mod position;
pub mod variants;

pub use claims::{Ours, PaperClaim};
pub use curves::{
    col, fit_range, line, on_right, paper_band, paper_label, paper_list, paper_points, paper_text, paper_value, scaled,
    styled,
};
pub use setup::{
    checked, converged, impact, log_space, node_positions, paper_node, reading_rule, sweep, used_position, Context,
    Scheme, CENTRE_X, V1_OFF_AXIS,
};

/// A registered experiment.
#[derive(Clone, Copy)]
pub struct Experiment {
    /// Identifier, also the file stem of its CSV, PNG and snapshot.
    pub id: &'static str,
    /// One-line title.
    pub title: &'static str,
    /// Where in the paper the result is (figure / page / sentence).
    pub paper_ref: &'static str,
    /// Run the solver on the context's racket and return the table.
    pub run: fn(&Context) -> Result<Table>,
    /// Draw the table (made on the same context).
    pub chart: fn(&Context, &Table) -> Chart,
    /// The paper's claims this experiment checks (their rows in `golden/paper_claims.csv`
    /// name this experiment).
    pub claims: &'static [PaperClaim],
}

impl std::fmt::Debug for Experiment {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Experiment").field("id", &self.id).finish()
    }
}

/// The registry of experiments: each experiment's module, one line each, in the paper's order
/// (the order of `figures` and of the report). An experiment is its file in `experiments/`
/// (with its `EXPERIMENT`, whose id is the module's name) and its line here. The list goes to
/// the macro `$then`: the modules and [`registry`](crate::experiments::registry) in the
/// library, a golden test each in tests/golden.rs. (Modules declared by a macro are outside
/// `cargo fmt`'s walk of the modules: `make fmt` and `make lint` name every source file.)
#[macro_export]
macro_rules! each_experiment {
    ($then:ident) => {
        $then! {
            concrete_drop,
            clamped_drop,
            modes,
            fig4_energy,
            fig5a_position_soft,
            fig5b_position_stiff,
            fig6_string_stiffness,
            fig7_off_axis_x10,
            fig8_off_axis_centre,
            fig9_stiff_frame,
            speeds,
            convergence,
            variant_rigid,
            variant_grip,
            variant_strings,
            oblique_angle,
            oblique_tension,
            topspin_forehand,
            robustness,
            sensitivity,
            spin_calibration,
            validation_spin,
        }
    };
}

/// Declares the experiments of the registry ([`each_experiment!`](crate::each_experiment)):
/// their modules and [`registry`].
macro_rules! declare {
    ($($id:ident,)+) => {
        $(pub mod $id;)+

        /// Every experiment, in the paper's order.
        pub fn registry() -> Vec<Experiment> {
            vec![$($id::EXPERIMENT,)+]
        }
    };
}
crate::each_experiment!(declare);

/// The experiment with this id.
pub fn find(id: &str) -> Result<Experiment> {
    registry().into_iter().find(|e| e.id == id).ok_or_else(|| Error::UnknownExperiment(crate::numfmt::quoted(id)))
}

/// The files one experiment writes in `out`: `<id>.csv` and `<id>.png`.
pub fn files(exp: &Experiment, out: &Path) -> [std::path::PathBuf; 2] {
    [out.join(format!("{}.csv", exp.id)), out.join(format!("{}.png", exp.id))]
}

/// Run one experiment on `ctx` and stage `<out>/<id>.csv` and `<out>/<id>.png` ([`files`]) for
/// the caller to publish with the others it runs (all or none).
pub fn run_and_stage(exp: &Experiment, ctx: &Context, out: &Path) -> Result<(Table, crate::render::io::Staged)> {
    let table = (exp.run)(ctx)?;
    if let Some((row, col)) = first_non_finite(&table) {
        return Err(Error::invalid(
            "table",
            format!("{}: row {row}, column {col}", exp.id),
            "every number in an experiment table must be finite",
        ));
    }
    let [csv, png] = files(exp, out);
    let mut staged = crate::render::io::Staged::new();
    staged.bytes(&csv, table.to_csv().as_bytes())?;
    crate::render::plot::stage_png(&mut staged, exp.id, &ctx.adapt((exp.chart)(ctx, &table)), &png)?;
    Ok((table, staged))
}

/// Run one experiment on `ctx` and write `<out>/<id>.csv` and `<out>/<id>.png` (atomically,
/// the table and its figure together or neither).
pub fn run_and_write(exp: &Experiment, ctx: &Context, out: &Path) -> Result<Table> {
    let (table, staged) = run_and_stage(exp, ctx, out)?;
    staged.commit()?;
    Ok(table)
}

/// The first non-finite number in a table: (row, column name).
pub fn first_non_finite(t: &Table) -> Option<(usize, String)> {
    t.rows.iter().enumerate().find_map(|(i, row)| {
        row.iter().position(|v| matches!(v, Value::Num(x) if !x.is_finite())).map(|j| (i, t.columns[j].clone()))
    })
}
