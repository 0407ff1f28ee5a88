//! `fig5a_position_soft`, `fig5b_position_stiff`: paper Fig 5, "Impact parameters plotted as a
//! function of impact distance, x, from the tip of the racket when r = 0 and (a) k_s = 2e4 N/m
//! and (b) k_s = 4e4 N/m."
//!
//! Model: the full impact at every node of the paper's N = 39 beam (force on that node), r = 0.
//! Expect (p. 5): e_A ~ 0 at a dead spot near the tip, rising to a broad maximum near the throat;
//! f(vib) ~ 0 at the fundamental node (~16 cm); ball and vibration losses of similar size away
//! from the node, both smaller on soft strings; at the centre e_A = 0.44 (soft) and 0.41 (stiff),
//! tau ~6.0 and ~5.0 ms; tau shorter near the tip. f(vib) is drawn the paper's way (peak bending
//! PE after impact); the CSV also has the exact vibration energy `f_vib`.

use super::{col, line, node_positions, on_right, paper_params, scaled, sweep, Experiment, CENTRE_X};
use crate::error::Result;
use crate::render::plot::{Chart, VLine};
use crate::render::table::Table;

/// Fig 5(a), soft strings.
pub const SOFT: Experiment = Experiment {
    id: "fig5a_position_soft",
    title: "e_A, f(ball), f(vib) and tau along the racket, r 0, ks 2e4 N/m",
    paper_ref: "Fig 5(a) and p. 5: centre e_A 0.44, tau ~6.0 ms; dead spot near the tip",
    run: || run(SOFT.id, 2.0e4),
    chart: |t| chart(t, "Fig 5(a): impact position, ks 2e4 N/m, r 0"),
};

/// Fig 5(b), stiff strings.
pub const STIFF: Experiment = Experiment {
    id: "fig5b_position_stiff",
    title: "e_A, f(ball), f(vib) and tau along the racket, r 0, ks 4e4 N/m",
    paper_ref: "Fig 5(b) and p. 5: centre e_A 0.41, tau ~5.0 ms",
    run: || run(STIFF.id, 4.0e4),
    chart: |t| chart(t, "Fig 5(b): impact position, ks 4e4 N/m, r 0"),
};

/// Table columns shared by the position and stiffness sweeps.
pub const COLUMNS: [&str; 6] = ["e_a", "f_ball", "f_vib", "f_vib_peak_pe", "tau_s", "peak_force_n"];

fn run(id: &str, ks: f64) -> Result<Table> {
    let base = paper_params(0.0, ks);
    let xs = node_positions(&base);
    let params: Vec<_> = xs.iter().map(|&x| paper_params(x, ks)).collect();
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
pub fn sweep_values(r: &crate::solver::ImpactResult) -> Vec<crate::render::table::Value> {
    [r.e_a, r.f_ball, r.f_vib, r.f_vib_peak_pe, r.tau_s, r.peak_force_n].into_iter().map(Into::into).collect()
}

fn chart(t: &Table, title: &str) -> Chart {
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
pub fn sweep_curves(x: Vec<f64>, t: &Table) -> Vec<crate::render::plot::Curve> {
    vec![
        line("e_A", x.clone(), col(t, "e_a"), 0),
        line("f(ball)", x.clone(), col(t, "f_ball"), 1),
        line("f(vib)", x.clone(), col(t, "f_vib_peak_pe"), 2),
        on_right(line("tau (ms)", x, scaled(col(t, "tau_s"), 1e3), 4)),
    ]
}
