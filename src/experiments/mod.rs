//! One module per result of the paper. Each experiment has an id, a title and a paper
//! reference, a function that runs the solver on a racket ([`Context`]) and returns one
//! [`Table`], a function that turns that table into a [`Chart`], and the paper's claims it
//! checks ([`PaperClaim`], collected by [`crate::report`]). One experiment = one file = one
//! id = one CSV + one PNG + one golden snapshot.
//!
//! | id | paper | module |
//! |---|---|---|
//! | `concrete_drop` | p. 3, Eqs 11-12: 100-inch drop on concrete | [`concrete_drop`] |
//! | `clamped_drop` | p. 3: drop on the strings of a head-clamped racket | [`clamped_drop`] |
//! | `modes` | p. 3-4: 125 Hz, 345 Hz, node 16 cm; wide body 200 Hz | [`modes`] |
//! | `fig4_energy` | Fig 4: energy partition, x 10 cm, r 5 cm, ks 4e4 | [`fig4_energy`] |
//! | `fig5a_position_soft` | Fig 5 (a) | [`fig5a_position_soft`] |
//! | `fig5b_position_stiff` | Fig 5 (b) | [`fig5b_position_stiff`] |
//! | `fig6_string_stiffness` | Fig 6 | [`fig6_string_stiffness`] |
//! | `fig7_off_axis_x10` | Fig 7 | [`fig7_off_axis_x10`] |
//! | `fig8_off_axis_centre` | Fig 8 | [`fig8_off_axis_centre`] |
//! | `fig9_stiff_frame` | Fig 9 | [`fig9_stiff_frame`] |
//! | `speeds` | p. 5-6 and Conclusions: serve / forehand gains | [`speeds`] |
//! | `convergence` | (ours) the paper's N = 39 node scheme against converged numerics | [`convergence`] |
//! | `variant_rigid` | (ours) rigid frame against the paper's beam | [`variant_rigid`] |
//! | `variant_grip` | (ours) hand grip against the paper's free racket | [`variant_grip`] |
//! | `variant_strings` | (ours) stiffening strings against the paper's linear strings | [`variant_strings`] |
//! | `oblique_angle` | (beyond) spin and rebound angle against incidence angle | [`oblique_angle`] |
//! | `oblique_tension` | (beyond) spin against tension, friction constant or tension-dependent | [`oblique_tension`] |
//! | `topspin_forehand` | (beyond) a forehand brushing up: speed, launch angle, spin | [`topspin_forehand`] |
//! | `robustness` | (ours) every claim under the declared input uncertainty | [`robustness`] |
//! | `sensitivity` | (ours) Sobol' indices of the headline outputs per uncertain input | [`sensitivity`] |
//! | `validation_spin` | (beyond) spin against the TWU table and further measurements, each tangential law | [`validation_spin`] |
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

pub mod clamped_drop;
pub mod concrete_drop;
pub mod convergence;
pub mod fig4_energy;
pub mod fig5a_position_soft;
pub mod fig5b_position_stiff;
pub mod fig6_string_stiffness;
pub mod fig7_off_axis_x10;
pub mod fig8_off_axis_centre;
pub mod fig9_stiff_frame;
pub mod modes;
pub mod oblique_angle;
pub mod oblique_tension;
pub mod off_axis;
pub mod position;
pub mod robustness;
pub mod sensitivity;
pub mod speeds;
pub mod spin_calibration;
pub mod topspin_forehand;
pub mod validation_spin;
pub mod variant_grip;
pub mod variant_rigid;
pub mod variant_strings;
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

/// Every experiment, in the paper's order.
pub fn registry() -> Vec<Experiment> {
    vec![
        concrete_drop::EXPERIMENT,
        clamped_drop::EXPERIMENT,
        modes::EXPERIMENT,
        fig4_energy::EXPERIMENT,
        fig5a_position_soft::EXPERIMENT,
        fig5b_position_stiff::EXPERIMENT,
        fig6_string_stiffness::EXPERIMENT,
        fig7_off_axis_x10::EXPERIMENT,
        fig8_off_axis_centre::EXPERIMENT,
        fig9_stiff_frame::EXPERIMENT,
        speeds::EXPERIMENT,
        convergence::EXPERIMENT,
        variant_rigid::EXPERIMENT,
        variant_grip::EXPERIMENT,
        variant_strings::EXPERIMENT,
        oblique_angle::EXPERIMENT,
        oblique_tension::EXPERIMENT,
        topspin_forehand::EXPERIMENT,
        robustness::EXPERIMENT,
        sensitivity::EXPERIMENT,
        spin_calibration::EXPERIMENT,
        validation_spin::EXPERIMENT,
    ]
}

/// The experiment with this id.
pub fn find(id: &str) -> Result<Experiment> {
    registry().into_iter().find(|e| e.id == id).ok_or_else(|| Error::UnknownExperiment(id.to_string()))
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
