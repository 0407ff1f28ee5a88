//! `fig5a_position_soft`: paper Fig 5(a), "Impact parameters plotted as a function of impact
//! distance, x, from the tip of the racket when r = 0 and (a) k_s = 2e4 N/m".
//!
//! Model: the position sweep of [`super::position`] at k_s = 2e4 N/m. Expect (p. 5): e_A ~ 0
//! at a dead spot near the tip, rising to a broad maximum near the throat; f(vib) ~ 0 at the
//! fundamental node (~16 cm); ball and vibration losses of similar size away from the node,
//! both smaller on soft strings than on the stiff strings of Fig 5(b); at the centre
//! e_A = 0.44 and tau ~6.0 ms; tau shorter near the tip.

use super::off_axis::{both_beds, ESSENTIALLY_ZERO};
use super::position::{centre, chart, run, PaperCentre};
use super::{Context, Experiment, PaperClaim};
use crate::error::Result;

/// The smallest cut of the ball loss and of the vibration loss (the paper's measure) when k_s is
/// halved, over the Fig 5 points of [`both_beds`] where the vibration is not essentially zero
/// on either bed ("at impact points removed from the node").
fn softer_strings_lose_less(ctx: &Context) -> Result<f64> {
    Ok(both_beds(ctx)?
        .iter()
        .filter(|b| b.r == 0.0 && b.soft.f_vib_peak_pe.max(b.stiff.f_vib_peak_pe) >= ESSENTIALLY_ZERO)
        .map(|b| (b.stiff.f_ball - b.soft.f_ball).min(b.stiff.f_vib_peak_pe - b.soft.f_vib_peak_pe))
        .fold(f64::INFINITY, f64::min))
}

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig5a_position_soft",
    title: "e_A, f(ball), f(vib) and tau along the racket, r 0, ks 2e4 N/m",
    paper_ref: "Fig 5(a) and p. 5: centre e_A 0.44, tau ~6.0 ms; dead spot near the tip",
    run: |ctx| run(ctx, EXPERIMENT.id, 2.0e4),
    chart: |ctx, t| {
        let paper = PaperCentre { e_a: "fig5_centre_e_a_soft", tau: "fig5_centre_tau_soft", node_f_vib: None };
        chart(ctx, t, "Fig 5(a): impact position, ks 2e4 N/m, r 0", paper)
    },
    claims: &[
        PaperClaim { id: "fig5_centre_e_a_soft", ours: |ctx| centre(ctx, 2.0e4, |r| r.e_a) },
        PaperClaim { id: "fig5_centre_tau_soft", ours: |ctx| centre(ctx, 2.0e4, |r| r.tau_s * 1e3) },
        PaperClaim { id: "fig5_softer_strings_lose_less", ours: softer_strings_lose_less },
    ],
};
