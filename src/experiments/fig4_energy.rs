//! `fig4_energy`: paper Fig 4, "Distribution of the initial ball energy as a function of time
//! when k_s = 4e4 N/m for an impact at x = 10 cm from the tip of the racket and r = 5 cm from
//! the long axis ... The impact duration tau = 4.78 ms and e_A = 0.166."
//!
//! Model: the full impact (Eqs 1-10) with the paper's numerics (N = 39, force on the nearest
//! node, which is node 5 at 9.10 cm). Curves, each a fraction of the initial ball KE: KE racket
//! (all beam nodes), PE racket (bending), spin KE (twist), PE ball including its loss, KE ball,
//! and the string PE the paper lumps into "PE ball". Expect: KE ball falls to ~0 at maximum
//! compression and ends at e_A^2 = 0.028; PE racket oscillates at twice 125 Hz after impact.

use super::{col, line, paper_label, paper_value, scaled, styled, used_position, Context, Experiment, PaperClaim};
use crate::error::Result;
use crate::numfmt::fmt_sig;
use crate::params::Params;
use crate::render::plot::{Chart, Curve, LineStyle, VLine};
use crate::render::table::Table;
use crate::solve::{FdModel, ImpactResult, SeriesOptions};

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig4_energy",
    title: "Energy partition against time, x 10 cm, r 5 cm, ks 4e4 N/m",
    paper_ref: "Fig 4 and p. 4, Energy balance: tau 4.78 ms, e_A 0.166, KE ball 0.028",
    run,
    chart,
    claims: &[
        PaperClaim { id: "fig4_tau", ours: |ctx| fig4_claim(ctx, |r| r.tau_s * 1e3) },
        PaperClaim { id: "fig4_e_a", ours: |ctx| fig4_claim(ctx, |r| r.e_a) },
        PaperClaim { id: "fig4_ke_ball", ours: |ctx| fig4_claim(ctx, |r| r.f_ke_ball) },
        PaperClaim {
            id: "fig4_pe_ball_strings",
            ours: |ctx| Ok(ctx.impact_detail(&params(ctx))?.pe_ball_strings_peak),
        },
    ],
};

/// A quantity of the Fig 4 impact.
fn fig4_claim(ctx: &Context, q: fn(&ImpactResult) -> f64) -> Result<f64> {
    Ok(q(&ctx.impact(&params(ctx))?))
}

/// The Fig 4 impact.
pub fn params(ctx: &Context) -> Params {
    let mut p = ctx.base_params();
    p.impact.x = 0.10;
    p.impact.r = 0.05;
    p.strings.ks = ctx.ks(4.0e4);
    p
}

fn run(ctx: &Context) -> Result<Table> {
    let model = FdModel::new(&params(ctx))?;
    let (r, rows) = model.run_with_series(SeriesOptions { sample_dt: 5.0e-5, t_end: 0.025 })?;
    let r = super::checked(&model.impact.params, r)?;
    let mut t = Table::new(
        EXPERIMENT.id,
        &[
            "t_s",
            "force_n",
            "ke_racket",
            "pe_racket",
            "ke_spin",
            "pe_ball",
            "ke_ball",
            "pe_string",
            "total",
            "tau_s",
            "e_a",
        ],
    );
    for s in rows.iter().filter(|s| s.t_s <= 0.025 + 1e-12) {
        t.push(vec![
            s.t_s.into(),
            s.force_n.into(),
            s.ke_racket.into(),
            s.pe_racket.into(),
            s.ke_spin.into(),
            s.pe_ball.into(),
            s.ke_ball.into(),
            s.pe_string.into(),
            s.total.into(),
            r.tau_s.into(),
            r.e_a.into(),
        ])?;
    }
    Ok(t)
}

/// The paper's end of the impact: KE ball 0.028 (= e_A^2, e_A 0.166) at tau = 4.78 ms.
fn paper_end_point() -> Curve {
    let (tau, ke, e_a) = (paper_value("fig4_tau"), paper_value("fig4_ke_ball"), paper_value("fig4_e_a"));
    let label = format!("KE ball {} at tau {} ms (e_A {})", fmt_sig(ke, 2), fmt_sig(tau, 3), fmt_sig(e_a, 3));
    styled(line(paper_label(&label), vec![tau], vec![ke], 0), LineStyle::Paper)
}

fn chart(ctx: &Context, t: &Table) -> Chart {
    let ms = scaled(col(t, "t_s"), 1e3);
    let tau_ms = col(t, "tau_s").first().copied().unwrap_or(f64::NAN) * 1e3;
    let e_a = col(t, "e_a").first().copied().unwrap_or(f64::NAN);
    let c = |label: &str, name: &str, color: usize| line(label, ms.clone(), col(t, name), color);
    Chart {
        title: format!(
            "Fig 4: energy partition, x 10 cm{}, r 5 cm, ks 4e4 N/m: tau = {} ms, e_A = {}",
            used_position(params(ctx).impact.x, &ctx.racket),
            fmt_sig(tau_ms, 3),
            fmt_sig(e_a, 3)
        ),
        x_label: "time (ms)".into(),
        y_label: "fraction of initial ball KE".into(),
        y2_label: None,
        x_log: false,
        x_range: Some((0.0, 25.0)),
        y_range: Some((0.0, 1.05)),
        y2_range: None,
        curves: vec![
            c("KE racket", "ke_racket", 5),
            c("PE racket", "pe_racket", 6),
            c("Spin KE", "ke_spin", 3),
            c("PE ball (incl. loss)", "pe_ball", 1),
            c("KE ball", "ke_ball", 0),
            styled(c("PE strings", "pe_string", 2), LineStyle::Dashed),
            // (dashed vermillion: a faint black, dark grey, was hard to tell from KE ball's black)
            styled(c("total", "total", 4), LineStyle::Dashed),
            paper_end_point(),
        ],
        bands: vec![],
        vlines: vec![VLine { x: tau_ms, label: "end of impact".into() }],
        ..Chart::default()
    }
}
