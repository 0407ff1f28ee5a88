//! `convergence` (ours, not in the paper): how far the paper's numerics (N = 39, whole force on
//! the nearest node) are from the converged model at the Fig 4 point (x 10 cm, r 5 cm,
//! k_s 4e4 N/m), and how the time step matters.
//!
//! The node rule moves the impact to the nearest node: at x = 10 cm and N = 39 that is 9.10 cm,
//! and near the tip e_A changes quickly with x, so the error is first order in 1/N and
//! oscillates with where x falls between nodes. The `hat` rule shares the force between the two
//! neighbouring nodes and converges as O(N^-2). The reference is `hat` with N = 320. The `dt`
//! rows repeat the paper's N = 39 impact with multiples of the default step: the default is
//! converged far below the discretisation error.

use super::{col, fig4_energy, impact, line, paper_label, paper_list, paper_points, styled, Context, Experiment};
use crate::error::Result;
use crate::numfmt::fmt_sig;
use crate::params::{LoadRule, Params};
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::Table;
use crate::solve::FdModel;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "convergence",
    title: "Convergence of e_A, tau and theta with N (node and hat load) and dt at the Fig 4 point",
    paper_ref: "p. 4: 'The beam was numerically divided into N = 39 segments' (ours: how converged that is)",
    run,
    chart,
    claims: &[],
};

/// Segment counts of the study.
pub const SEGMENTS: [usize; 9] = [20, 30, 39, 40, 60, 80, 120, 160, 320];
/// Multiples of the default time step.
pub const DT_FACTORS: [f64; 5] = [4.0, 2.0, 1.0, 0.5, 0.25];

fn run(ctx: &Context) -> Result<Table> {
    let mut t = Table::new(
        EXPERIMENT.id,
        &["study", "load", "segments", "dt_s", "x_load_m", "e_a", "tau_s", "theta_end_deg", "e_a_rel_to_reference"],
    );
    let mut reference = fig4_energy::params(ctx);
    reference.numerics.load = LoadRule::Hat;
    reference.numerics.segments = 320;
    let e_ref = impact(&reference)?.e_a;
    let mut runs: Vec<(&str, Params)> = Vec::new();
    for load in [LoadRule::Node, LoadRule::Hat] {
        for n in SEGMENTS {
            let mut p = fig4_energy::params(ctx);
            p.numerics.load = load;
            p.numerics.segments = n;
            runs.push(("segments", p));
        }
    }
    let paper = fig4_energy::params(ctx);
    let dt0 = FdModel::new(&paper)?.dt;
    for k in DT_FACTORS {
        let mut p = paper;
        p.numerics.dt = Some(dt0 * k);
        runs.push(("dt", p));
    }
    let params: Vec<Params> = runs.iter().map(|(_, p)| *p).collect();
    for ((study, p), r) in runs.iter().zip(super::sweep(&params)?) {
        t.push(vec![
            (*study).into(),
            p.numerics.load.name().into(),
            p.numerics.segments.into(),
            r.dt_s.into(),
            r.x_load_m.into(),
            r.e_a.into(),
            r.tau_s.into(),
            r.theta_end_deg.into(),
            (r.e_a / e_ref - 1.0).into(),
        ])?;
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let seg = t.filter("study", "segments");
    let node = seg.filter("load", "node");
    let hat = seg.filter("load", "hat");
    let e_ref = col(&hat, "e_a").last().copied().unwrap_or(f64::NAN);
    let e39 = node.rows.iter().find(|r| r[2].as_f64() == 39.0).map(|r| r[5].as_f64()).unwrap_or(f64::NAN);
    Chart {
        title: format!(
            "Convergence at the Fig 4 point: paper's N = 39 node scheme e_A = {} vs converged {} ({} %)",
            fmt_sig(e39, 4),
            fmt_sig(e_ref, 4),
            fmt_sig(100.0 * (e39 / e_ref - 1.0), 3)
        ),
        x_label: "number of beam segments N".into(),
        y_label: "apparent COR e_A".into(),
        y2_label: None,
        x_log: true,
        x_range: Some((10.0, 400.0)),
        y_range: Some((0.14, 0.22)),
        y2_range: None,
        curves: vec![
            styled(line("node load (paper), each N", col(&node, "segments"), col(&node, "e_a"), 1), LineStyle::Points),
            line("hat load", col(&hat, "segments"), col(&hat, "e_a"), 5),
            styled(line("converged (hat, N = 320)", vec![10.0, 400.0], vec![e_ref; 2], 0), LineStyle::Dashed),
            paper_points(
                paper_label(&format!("e_A {} at N = 39", paper_list(&["fig4_e_a"]))),
                vec![39.0],
                &["fig4_e_a"],
                4,
            ),
        ],
        bands: vec![],
        vlines: vec![],
        ..Chart::default()
    }
}
