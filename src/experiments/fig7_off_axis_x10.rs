//! `fig7_off_axis_x10`: paper Fig 7, "Effect on e_A and theta of an off-axis impact at
//! x = 10 cm", with v1 = 30 m/s and k_s = 2e4 or 4e4 N/m.
//!
//! Model: the off-axis sweep of [`super::off_axis`] at x = 10 cm (the N = 39 node scheme loads
//! node 5 at 9.10 cm). Expect (p. 6): theta roughly proportional to r and to the impact
//! duration; about 19 % more rotation when k_s is halved; e_A falls with r and rises when k_s
//! is reduced.

use super::off_axis::{chart, paper_gain_point, run, theta_r4};
use super::{used_position, Experiment, PaperClaim};
use crate::solve::swing::gain_pct;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig7_off_axis_x10",
    title: "Rotation angle and e_A against off-axis distance r at x 10 cm, v1 30 m/s",
    paper_ref: "Fig 7 and p. 6: theta +19 % when ks is halved",
    run: |ctx| run(ctx, EXPERIMENT.id, 0.10, &[]),
    chart: |ctx, t| {
        let paper = vec![paper_gain_point(t, "fig7_theta_gain_ks_half")];
        let title = format!("Fig 7: off-axis impact at x = 10 cm{}, v1 = 30 m/s", used_position(0.10, &ctx.racket));
        chart(t, &title, paper)
    },
    claims: &[PaperClaim {
        id: "fig7_theta_gain_ks_half",
        ours: |ctx| Ok(gain_pct(theta_r4(ctx, 0.10, 4.0e4)?, theta_r4(ctx, 0.10, 2.0e4)?)),
    }],
};
