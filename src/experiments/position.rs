//! What Figs 5(a) and 5(b) share ([`super::fig5a_position_soft`], [`super::fig5b_position_stiff`]):
//! the full impact at every node of the paper's N = 39 beam (force on that node), r = 0, for
//! one string stiffness, and its chart. f(vib) is drawn the paper's way (peak bending PE after
//! impact); the CSV also has the exact vibration energy `f_vib`. Fig 6 and 9 use the same
//! columns and curves.

use super::CENTRE_X;
use super::{col, converged, impact, line, node_positions, on_right, read_off_curve, scaled, sweep, Context, Ours};
use crate::error::Result;
use crate::render::plot::{Chart, Curve, VLine};
use crate::render::table::{Table, Value};
use crate::solve::ImpactResult;

/// Table columns shared by the position and stiffness sweeps.
pub const COLUMNS: [&str; 6] = ["e_a", "f_ball", "f_vib", "f_vib_peak_pe", "tau_s", "peak_force_n"];

/// The impact at every node along the racket for string stiffness `ks`.
pub fn run(ctx: &Context, id: &str, ks: f64) -> Result<Table> {
    let base = ctx.paper_params(0.0, ks);
    let xs = node_positions(&base);
    let params: Vec<_> = xs.iter().map(|&x| ctx.paper_params(x, ks)).collect();
    let results = sweep(&params)?;
    let mut cols = vec!["x_m"];
    cols.extend(COLUMNS);
    let mut t = Table::new(id, &cols);
    for (x, r) in xs.iter().zip(&results) {
        let mut row = vec![(*x).into()];
        row.extend(sweep_values(r));
        t.push(row)?;
    }
    Ok(t)
}

/// The values of [`COLUMNS`] for one impact.
pub fn sweep_values(r: &ImpactResult) -> Vec<Value> {
    [r.e_a, r.f_ball, r.f_vib, r.f_vib_peak_pe, r.tau_s, r.peak_force_n].into_iter().map(Into::into).collect()
}

/// The figure of a position sweep.
pub fn chart(t: &Table, title: &str) -> Chart {
    let x = scaled(col(t, "x_m"), 100.0);
    Chart {
        title: title.into(),
        x_label: "impact distance from the tip x (cm)".into(),
        y_label: "e_A,  f(ball),  f(vib)".into(),
        y2_label: Some("impact duration tau (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 71.0)),
        y_range: Some((-0.1, 0.6)),
        y2_range: Some((0.0, 8.0)),
        curves: sweep_curves(x, t),
        vlines: vec![VLine { x: CENTRE_X * 100.0, label: "centre of the strings (15.8 cm)".into() }],
    }
}

/// The paper's four curves: e_A, f(ball), f(vib) on the left, tau (ms) on the right.
pub fn sweep_curves(x: Vec<f64>, t: &Table) -> Vec<Curve> {
    vec![
        line("e_A", x.clone(), col(t, "e_a"), 0),
        line("f(ball)", x.clone(), col(t, "f_ball"), 1),
        line("f(vib)", x.clone(), col(t, "f_vib_peak_pe"), 2),
        on_right(line("tau (ms)", x, scaled(col(t, "tau_s"), 1e3), 4)),
    ]
}

/// A centre quantity three ways: read off the node curve, at node 9, converged.
pub fn centre_three(ctx: &Context, ks: f64, q: fn(&ImpactResult) -> f64) -> Result<Ours> {
    let p = ctx.paper_params(CENTRE_X, ks);
    Ok(Ours::new(read_off_curve(&p, CENTRE_X, q)?, Some(q(&impact(&p)?)), Some(q(&impact(&converged(p))?))))
}
