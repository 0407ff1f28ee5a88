//! `fig9_stiff_frame`: paper Fig 9, "As for Fig. 6 but for a stiffer racket with a fundamental
//! vibration frequency of 200 Hz" (EI = 384 N m^2, same mass and length).
//!
//! Model: the Fig 6 sweep (x = 6 cm, r = 0, N = 39 node scheme) for EI 384, with the EI 150
//! curves drawn faintly. Expect (p. 6): much smaller vibration loss near the tip, so e_A is
//! larger: "at k_s = 4e4, e_A is increased from 0.10 to 0.18, which translates ... to a 7%
//! increase in serve speed".

use super::fig6_string_stiffness::{stiffness_chart, stiffness_sweep, X_TIP};
use super::speeds::tip_setup;
use super::{paper_label, paper_list, paper_points, used_position, Context, Experiment, PaperClaim, CENTRE_X};
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
        PaperClaim { id: "fig9_node_serve_gain", ours: node_serve_gain },
        PaperClaim { id: "fig9_f_vib_cut", ours: f_vib_cut },
        PaperClaim { id: "fig9_f_vib_ei384", ours: |ctx| f_vib_at_tip(ctx, ctx.frame_ei(384.0)) },
        PaperClaim { id: "fig9_tau_ei384", ours: |ctx| Ok(tip_setup(ctx, ctx.frame_ei(384.0))?.tau_s * 1e3) },
        PaperClaim { id: "fig9_throat_serve_gain", ours: |ctx| serve_gain_at(ctx, super::position::THROAT_X) },
    ],
};

/// e_A at 6 cm, k_s 4e4, for a frame of bending stiffness `ei` (N m^2).
fn e_a_at_tip(ctx: &Context, ei: f64) -> Result<f64> {
    Ok(tip_setup(ctx, ei)?.e_a)
}

/// The serve speed gain of the EI 384 frame over the EI 150 one at the centre of the strings
/// (the vibration node), k_s 4e4, %.
fn node_serve_gain(ctx: &Context) -> Result<f64> {
    serve_gain_at(ctx, CENTRE_X)
}

/// The serve speed gain (%) of the EI 384 frame over the EI 150 one at `x` (r 0, k_s 4e4).
fn serve_gain_at(ctx: &Context, x: f64) -> Result<f64> {
    let e_a = |ei: f64| -> Result<f64> {
        let mut p = ctx.paper_params(x, 4.0e4);
        p.racket.ei = ei;
        Ok(ctx.impact(&p)?.e_a)
    };
    let (a, b) = (e_a(ctx.frame_ei(150.0))?, e_a(ctx.frame_ei(384.0))?);
    Ok(gain_pct(1.0 + a, 1.0 + b))
}

/// How much less the EI 384 frame vibrates than the EI 150 one at 6 cm, k_s 4e4 (the paper's
/// measure, peak bending PE), %.
fn f_vib_cut(ctx: &Context) -> Result<f64> {
    Ok(100.0 * (1.0 - f_vib_at_tip(ctx, ctx.frame_ei(384.0))? / f_vib_at_tip(ctx, ctx.frame_ei(150.0))?))
}

/// The paper's f(vib) (peak bending PE after the impact) at 6 cm (r 0, k_s 4e4) for a frame
/// stiffness.
fn f_vib_at_tip(ctx: &Context, ei: f64) -> Result<f64> {
    let mut p = ctx.paper_params(X_TIP, 4.0e4);
    p.racket.ei = ei;
    Ok(ctx.impact(&p)?.f_vib_peak_pe)
}

/// The serve speed gain of the EI 384 frame over the EI 150 one at 6 cm, %.
fn serve_gain(ctx: &Context) -> Result<f64> {
    let (a, b) = (tip_setup(ctx, ctx.frame_ei(150.0))?, tip_setup(ctx, ctx.frame_ei(384.0))?);
    Ok(gain_pct(1.0 + a.e_a, 1.0 + b.e_a))
}
