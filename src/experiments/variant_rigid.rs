//! `variant_rigid` (ours): the textbook rigid racket (effective mass at the impact point, plus
//! twist, in closed form) against the paper's flexible beam, e_A along the racket, k_s 4e4 N/m,
//! r = 0 (see [`super::variants`]).

use super::variants::along;
use super::{col, line, on_right, scaled, styled, sweep, Context, Experiment, CENTRE_X};
use crate::error::Result;
use crate::params::Frame;
use crate::render::plot::{Chart, LineStyle, VLine};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "variant_rigid",
    title: "Rigid racket (closed form) against the flexible beam: e_A along the racket, ks 4e4 N/m, r 0",
    paper_ref: "p. 2: rigid-body models with an assumed COR vs the beam; p. 5: no vibration at the node",
    run,
    chart,
    claims: &[],
};

fn run(ctx: &Context) -> Result<Table> {
    let beam = sweep(&along(ctx, |_| {}))?;
    let rigid = sweep(&along(ctx, |p| p.variants.frame = Frame::Rigid))?;
    let mut t = Table::new(EXPERIMENT.id, &["x_m", "e_a_beam", "e_a_rigid", "f_vib_beam", "tau_s_beam", "tau_s_rigid"]);
    for ((p, b), r) in along(ctx, |_| {}).iter().zip(&beam).zip(&rigid) {
        t.push(vec![p.impact.x.into(), b.e_a.into(), r.e_a.into(), b.f_vib.into(), b.tau_s.into(), r.tau_s.into()])?;
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let x = scaled(col(t, "x_m"), 100.0);
    Chart {
        title: "Rigid racket vs flexible beam, ks 4e4 N/m, r 0".into(),
        x_label: "impact distance from the tip x (cm)".into(),
        y_label: "e_A,  f(vib)".into(),
        y2_label: Some("impact duration tau (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 71.0)),
        y_range: Some((-0.1, 0.9)),
        y2_range: Some((0.0, 9.0)),
        curves: vec![
            line("e_A, flexible beam (the paper)", x.clone(), col(t, "e_a_beam"), 0),
            styled(line("e_A, rigid racket", x.clone(), col(t, "e_a_rigid"), 4), LineStyle::Dashed),
            line("f(vib), beam", x.clone(), col(t, "f_vib_beam"), 2),
            // (not blue: f(vib) is sky blue, and a faint blue is hard to tell from it)
            on_right(styled(line("tau beam", x.clone(), scaled(col(t, "tau_s_beam"), 1e3), 3), LineStyle::Faint)),
            on_right(styled(line("tau rigid", x, scaled(col(t, "tau_s_rigid"), 1e3), 6), LineStyle::Faint)),
        ],
        bands: vec![],
        vlines: vec![VLine { x: CENTRE_X * 100.0, label: "mode-1 node (15.8 cm)".into() }],
        ..Chart::default()
    }
}
