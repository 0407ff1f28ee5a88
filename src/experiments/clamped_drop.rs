//! `clamped_drop`: the 100-inch drop on the strings of a head-clamped racket (paper p. 3):
//! "with k_s = 2e4 N/m ... the impact duration is extended to 6.98 ms, and e = 0.908. If k_s is
//! increased to 4e4 N/m, the impact duration is 5.90 ms and e = 0.866."
//!
//! Model: ball (Eqs 1, 3, 4) and massless strings (Eq 2) in series against a fixed frame,
//! solved by quadrature ([`crate::model::reduced::clamped_drop`]). The sweep over k_s from 1e3
//! to 1e6 N/m shows the trend the paper describes: softer strings store more of the energy and
//! return it, so e rises towards 1 and the contact lasts longer; stiff strings tend to the
//! concrete slab (dashed).

use super::{
    col, line, log_space, on_right, paper_label, paper_list, paper_points, scaled, styled, Context, Experiment,
    PaperClaim,
};
use crate::error::Result;
use crate::model::reduced::{clamped_drop, concrete_drop, DropResult};
use crate::params::{drop_speed, Ball, Strings, DROP_HEIGHT_100_IN};
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "clamped_drop",
    title: "Drop on the strings of a head-clamped racket against string stiffness",
    paper_ref: "p. 3, Ball parameters: ks 2e4 -> 6.98 ms, e 0.908; ks 4e4 -> 5.90 ms, e 0.866",
    run,
    chart,
    claims: &[
        PaperClaim { id: "clamped_tau_ks2e4", ours: |c| Ok(drop_100_in(c, 2.0e4).tau_s * 1e3) },
        PaperClaim { id: "clamped_e_ks2e4", ours: |c| Ok(drop_100_in(c, 2.0e4).e) },
        PaperClaim { id: "clamped_tau_ks4e4", ours: |c| Ok(drop_100_in(c, 4.0e4).tau_s * 1e3) },
        PaperClaim { id: "clamped_e_ks4e4", ours: |c| Ok(drop_100_in(c, 4.0e4).e) },
    ],
};

/// The context's ball (the paper's) dropped 100 inches on the strings (the context's
/// [`Context::ks`] of `ks`, N/m) of a clamped racket.
fn drop_100_in(ctx: &Context, ks: f64) -> DropResult {
    clamped_drop(&ctx.ball, &Strings { ks: ctx.ks(ks) }, drop_speed(DROP_HEIGHT_100_IN))
}

fn ks_values() -> Vec<f64> {
    let mut ks = log_space(1.0e3, 1.0e6, 31);
    ks.extend([2.0e4, 4.0e4]);
    ks.sort_by(f64::total_cmp);
    ks
}

fn run(_: &Context) -> Result<Table> {
    let ball = Ball::default();
    let v1 = drop_speed(DROP_HEIGHT_100_IN);
    let mut t = Table::new(EXPERIMENT.id, &["ks_n_per_m", "tau_s", "e", "y0_m", "peak_force_n"]);
    for ks in ks_values() {
        let d = clamped_drop(&ball, &Strings { ks }, v1);
        t.push(vec![ks.into(), d.tau_s.into(), d.e.into(), d.y0_m.into(), d.peak_force_n.into()])?;
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let ks = col(t, "ks_n_per_m");
    let c = concrete_drop(&Ball::default(), drop_speed(DROP_HEIGHT_100_IN));
    let ends = vec![1.0e3, 1.0e6];
    Chart {
        title: "Head-clamped racket, 100-inch drop (p. 3): e and duration against ks".into(),
        x_label: "string-plane stiffness ks (N/m)".into(),
        y_label: "coefficient of restitution e".into(),
        y2_label: Some("impact duration tau (ms)".into()),
        x_log: true,
        x_range: Some((1.0e3, 1.0e6)),
        // headroom above the curves for the legend
        y_range: Some((0.7, 1.1)),
        y2_range: Some((0.0, 30.0)),
        curves: vec![
            line("e", ks.clone(), col(t, "e"), 0),
            on_right(line("tau", ks.clone(), scaled(col(t, "tau_s"), 1e3), 1)),
            styled(line("e on concrete", ends.clone(), vec![c.e; 2], 0), LineStyle::Dashed),
            on_right(styled(line("tau on concrete", ends, vec![c.tau_s * 1e3; 2], 1), LineStyle::Dashed)),
            paper_points(
                paper_label(&format!("e {} at ks 2e4, 4e4", paper_list(&["clamped_e_ks2e4", "clamped_e_ks4e4"]))),
                vec![2.0e4, 4.0e4],
                &["clamped_e_ks2e4", "clamped_e_ks4e4"],
                0,
            ),
            on_right(paper_points(
                paper_label(&format!(
                    "tau {} ms at ks 2e4, 4e4",
                    paper_list(&["clamped_tau_ks2e4", "clamped_tau_ks4e4"])
                )),
                vec![2.0e4, 4.0e4],
                &["clamped_tau_ks2e4", "clamped_tau_ks4e4"],
                1,
            )),
        ],
        bands: vec![],
        // the paper's markers stand at ks 2e4 and 4e4
        vlines: vec![],
        ..Chart::default()
    }
}
