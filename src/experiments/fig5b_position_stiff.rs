//! `fig5b_position_stiff`: paper Fig 5(b), "Impact parameters plotted as a function of impact
//! distance, x, from the tip of the racket when r = 0 and ... (b) k_s = 4e4 N/m."
//!
//! Model: the position sweep of [`super::position`] at k_s = 4e4 N/m. Expect (p. 5): as Fig
//! 5(a), with larger ball and vibration losses; at the centre e_A = 0.41 and tau ~5.0 ms; a
//! dead spot (e_A ~ 0) near the tip and f(vib) ~ 0 at the fundamental node (~16 cm).

use super::position::{centre, chart, run, PaperCentre};
use super::{Context, Experiment, PaperClaim};
use crate::error::Result;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig5b_position_stiff",
    title: "e_A, f(ball), f(vib) and tau along the racket, r 0, ks 4e4 N/m",
    paper_ref: "Fig 5(b) and p. 5: centre e_A 0.41, tau ~5.0 ms",
    run: |ctx| run(ctx, EXPERIMENT.id, 4.0e4),
    chart: |ctx, t| {
        let paper = PaperCentre {
            e_a: "fig5_centre_e_a_stiff",
            tau: "fig5_centre_tau_stiff",
            node_f_vib: Some("fig5_node_f_vib"),
        };
        chart(ctx, t, "Fig 5(b): impact position, ks 4e4 N/m, r 0", paper)
    },
    claims: &[
        PaperClaim { id: "fig5_centre_e_a_stiff", ours: |ctx| centre(ctx, 4.0e4, |r| r.e_a) },
        PaperClaim { id: "fig5_centre_tau_stiff", ours: |ctx| centre(ctx, 4.0e4, |r| r.tau_s * 1e3) },
        PaperClaim { id: "fig5_dead_spot", ours: dead_spot },
        PaperClaim { id: "fig5_node_f_vib", ours: node_f_vib },
    ],
};

/// The smallest |e_A| a reader finds on the Fig 5(b) curve in the outer 10 cm: at the paper's
/// nodes there (nodes 0-5 of N = 39, x <= 9.1 cm), each computed with the context's numerics.
fn dead_spot(ctx: &Context) -> Result<f64> {
    let params: Vec<_> = ctx.paper_nodes().iter().take(6).map(|&x| ctx.paper_params(x, 4.0e4)).collect();
    Ok(ctx.sweep(&params)?.iter().map(|r| r.e_a.abs()).fold(f64::INFINITY, f64::min))
}

/// f(vib) at the fundamental node (16 cm).
fn node_f_vib(ctx: &Context) -> Result<f64> {
    Ok(ctx.impact(&ctx.paper_params(0.16, 4.0e4))?.f_vib_peak_pe)
}
