//! `fig8_off_axis_centre`: paper Fig 8, "Effect on e_A and theta of an off-axis impact at
//! x = 15.8 cm", with v1 = 30 m/s and k_s = 2e4 or 4e4 N/m.
//!
//! Model: the off-axis sweep of [`super::off_axis`] at the centre of the strings (the N = 39
//! node scheme loads node 9 at 16.38 cm, [`super::READING_RULE`]). Expect (p. 6): theta roughly proportional to r and to
//! the impact duration; "A ball impacting at r = 4 cm near the centre of the strings causes the
//! racket to rotate by about 10 deg"; e_A falls with r and rises when k_s is reduced.

use super::off_axis::{chart, paper_gain_point, paper_theta_point, run, theta_r4};
use super::speeds::centre_setup;
use super::{used_position, Context, Experiment, PaperClaim, CENTRE_X};
use crate::error::Result;
use crate::params::ks_from_tension_lb;
use crate::solve::swing::gain_pct;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig8_off_axis_centre",
    title: "Rotation angle and e_A against off-axis distance r at x 15.8 cm, v1 30 m/s",
    paper_ref: "Fig 8 and p. 6: r 4 cm near the centre rotates the racket ~10 deg",
    run: |ctx| run(ctx, EXPERIMENT.id, CENTRE_X),
    chart: |ctx, t| {
        let paper = vec![
            paper_theta_point("fig8_theta_r4_50lb", true, "50 lb (ks 3.33e4)", 0),
            paper_theta_point("fig8_theta_r4_60lb", false, "60 lb (ks 4e4)", 3),
            paper_gain_point(t, "fig8_theta_gain_ks_half"),
        ];
        let title =
            format!("Fig 8: off-axis impact at x = 15.8 cm{}, v1 = 30 m/s", used_position(CENTRE_X, &ctx.racket));
        chart(t, &title, paper)
    },
    claims: &[
        PaperClaim { id: "fig8_theta_r4_50lb", ours: |ctx| Ok(centre_setup(ctx, ks_from_tension_lb(50.0))?.theta_deg) },
        PaperClaim { id: "fig8_theta_r4_60lb", ours: |ctx| Ok(centre_setup(ctx, 4.0e4)?.theta_deg) },
        PaperClaim {
            id: "fig8_theta_gain_ks_half",
            ours: |ctx| Ok(gain_pct(theta_r4(ctx, CENTRE_X, 4.0e4)?, theta_r4(ctx, CENTRE_X, 2.0e4)?)),
        },
        PaperClaim { id: "conclusions_theta_cut_ks_double", ours: theta_cut_ks_double },
    ],
};

/// How much less the racket turns (r 4 cm at the centre) when k_s is doubled, %.
fn theta_cut_ks_double(ctx: &Context) -> Result<f64> {
    let (soft, stiff) = (theta_r4(ctx, CENTRE_X, 2.0e4)?, theta_r4(ctx, CENTRE_X, 4.0e4)?);
    Ok(100.0 * (1.0 - stiff / soft))
}
