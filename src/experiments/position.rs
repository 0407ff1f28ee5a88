//! What Figs 5(a) and 5(b) share ([`super::fig5a_position_soft`], [`super::fig5b_position_stiff`]):
//! the full impact at every node of the paper's N = 39 beam (force on that node), r = 0, for
//! one string stiffness, and its chart. f(vib) is drawn the paper's way (peak bending PE after
//! impact); the CSV also has the exact vibration energy `f_vib`. Fig 6 and 9 use the same
//! columns and curves.

use super::CENTRE_X;
use super::{col, line, node_positions, on_right, scaled, styled, sweep, Context};
use super::{paper_label, paper_points, paper_value};
use crate::error::Result;
use crate::numfmt::fmt_sig;
use crate::params::DEFAULT_FACE_LENGTH;
use crate::render::plot::{Band, Chart, Curve, LineStyle, VLine};
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

/// Length of the string face from the tip, m: the default face of the string-face maps and of
/// the default impact point ([`DEFAULT_FACE_LENGTH`]), as the paper's racket has no head
/// outline. The position figures shade it.
pub const STRING_FACE_LENGTH: f64 = DEFAULT_FACE_LENGTH;

/// Palette colours of the sweep curves: e_A, f(ball), f(vib), tau.
pub const SWEEP_COLORS: [usize; 4] = [0, 1, 2, 6];

/// The paper's values on a position figure: the claim ids of e_A and tau at the centre of the
/// strings, and of f(vib) at the fundamental node (16 cm) where the paper states it.
#[derive(Clone, Copy, Debug)]
pub struct PaperCentre {
    /// e_A at the centre (15.8 cm).
    pub e_a: &'static str,
    /// tau (ms) at the centre.
    pub tau: &'static str,
    /// f(vib) at 16 cm, if stated for this figure.
    pub node_f_vib: Option<&'static str>,
}

/// The figure of a position sweep, with the paper's values at the centre of the strings.
pub fn chart(_: &Context, t: &Table, title: &str, paper: PaperCentre) -> Chart {
    let x = scaled(col(t, "x_m"), 100.0);
    let centre = CENTRE_X * 100.0;
    let mut curves = sweep_curves(x, t);
    let [c_ea, _, c_vib, c_tau] = SWEEP_COLORS;
    curves.push(paper_points(
        paper_label(&format!("e_A {} at {} cm", fmt_sig(paper_value(paper.e_a), 3), fmt_sig(centre, 3))),
        vec![centre],
        &[paper.e_a],
        c_ea,
    ));
    curves.push(on_right(paper_points(
        paper_label(&format!("tau about {} ms at {} cm", fmt_sig(paper_value(paper.tau), 2), fmt_sig(centre, 3))),
        vec![centre],
        &[paper.tau],
        c_tau,
    )));
    if let Some(id) = paper.node_f_vib {
        curves.push(paper_points(
            paper_label(&format!("f(vib) {} at the node, 16 cm", fmt_sig(paper_value(id), 1))),
            vec![16.0],
            &[id],
            c_vib,
        ));
    }
    Chart {
        title: title.into(),
        x_label: "impact distance from the tip x (cm)".into(),
        y_label: "e_A,  f(ball),  f(vib)".into(),
        y2_label: Some("impact duration tau (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 71.0)),
        y_range: Some((-0.1, 1.0)),
        y2_range: Some((0.0, 11.0)),
        curves,
        bands: vec![Band::new(
            0.0,
            STRING_FACE_LENGTH * 100.0,
            format!("string face (tip to {} cm)", fmt_sig(STRING_FACE_LENGTH * 100.0, 3)),
        )],
        // the paper read its centre values off these curves, and so do the claims
        vlines: vec![VLine {
            x: centre,
            label: "centre of the strings (15.8 cm): our centre values are read here".into(),
        }],
        ..Chart::default()
    }
}

/// The paper's four curves: e_A, f(ball), f(vib) on the left, tau (ms, dashed) on the right.
pub fn sweep_curves(x: Vec<f64>, t: &Table) -> Vec<Curve> {
    let [c_ea, c_ball, c_vib, c_tau] = SWEEP_COLORS;
    vec![
        line("e_A", x.clone(), col(t, "e_a"), c_ea),
        line("f(ball)", x.clone(), col(t, "f_ball"), c_ball),
        line("f(vib)", x.clone(), col(t, "f_vib_peak_pe"), c_vib),
        on_right(styled(line("tau", x, scaled(col(t, "tau_s"), 1e3), c_tau), LineStyle::Dashed)),
    ]
}

/// A quantity of the impact at the centre of the strings (r 0), string stiffness `ks`.
pub fn centre(ctx: &Context, ks: f64, q: fn(&ImpactResult) -> f64) -> Result<f64> {
    Ok(q(&ctx.impact(&ctx.paper_params(CENTRE_X, ks))?))
}
