//! `fig9_stiff_frame`: paper Fig 9, "As for Fig. 6 but for a stiffer racket with a fundamental
//! vibration frequency of 200 Hz" (EI = 384 N m^2, same mass and length).
//!
//! Model: the Fig 6 sweep (x = 6 cm, r = 0, N = 39 node scheme) for EI 384, with the EI 150
//! curves drawn faintly. Expect (p. 6): much smaller vibration loss near the tip, so e_A is
//! larger: "at k_s = 4e4, e_A is increased from 0.10 to 0.18, which translates ... to a 7%
//! increase in serve speed".

use super::fig6_string_stiffness::{stiffness_chart, stiffness_sweep, X_TIP};
use super::speeds::tip_setup;
use super::{paper_label, paper_list, paper_points, used_position, Context, Experiment, PaperClaim};
use crate::error::Result;
use crate::solve::swing::gain_pct;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig9_stiff_frame",
    title: "Fig 6 for a wide-body frame, EI 384 N m^2 (200 Hz), with EI 150 for comparison",
    paper_ref: "Fig 9 and p. 6: at ks 4e4, e_A 0.10 -> 0.18, serve speed +7 %",
    run: |ctx| stiffness_sweep(ctx, EXPERIMENT.id, &[ctx.frame_ei(384.0), ctx.frame_ei(150.0)]),
    chart: |ctx, t| {
        let mut c = stiffness_chart(
            t,
            &format!(
                "Fig 9: stiff frame EI 384 N m^2 (200 Hz), x 6 cm{}, r 0; faint: EI 150",
                used_position(X_TIP, &ctx.racket)
            ),
            Some(ctx.frame_ei(150.0)),
        );
        let ids = ["fig9_e_a_ei384", "fig9_e_a_ei150"];
        let label = format!("e_A {} (EI 384, 150) at ks 4e4", paper_list(&ids));
        c.curves.push(paper_points(paper_label(&label), vec![4.0e4; 2], &ids, 0));
        c
    },
    claims: &[
        PaperClaim { id: "fig9_e_a_ei150", ours: |ctx| e_a_at_tip(ctx, ctx.frame_ei(150.0)) },
        PaperClaim { id: "fig9_e_a_ei384", ours: |ctx| e_a_at_tip(ctx, ctx.frame_ei(384.0)) },
        PaperClaim { id: "fig9_serve_gain", ours: serve_gain },
    ],
};

/// e_A at 6 cm, k_s 4e4, for a frame of bending stiffness `ei` (N m^2).
fn e_a_at_tip(ctx: &Context, ei: f64) -> Result<f64> {
    Ok(tip_setup(ctx, ei)?.e_a)
}

/// The serve speed gain of the EI 384 frame over the EI 150 one at 6 cm, %.
fn serve_gain(ctx: &Context) -> Result<f64> {
    let (a, b) = (tip_setup(ctx, ctx.frame_ei(150.0))?, tip_setup(ctx, ctx.frame_ei(384.0))?);
    Ok(gain_pct(1.0 + a.e_a, 1.0 + b.e_a))
}
