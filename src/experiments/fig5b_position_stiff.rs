//! `fig5b_position_stiff`: paper Fig 5(b), "Impact parameters plotted as a function of impact
//! distance, x, from the tip of the racket when r = 0 and ... (b) k_s = 4e4 N/m."
//!
//! Model: the position sweep of [`super::position`] at k_s = 4e4 N/m. Expect (p. 5): as Fig
//! 5(a), with larger ball and vibration losses; at the centre e_A = 0.41 and tau ~5.0 ms; a
//! dead spot (e_A ~ 0) near the tip and f(vib) ~ 0 at the fundamental node (~16 cm).

use super::fig6_string_stiffness::X_TIP;
use super::off_axis::{both_beds, BothBeds, ESSENTIALLY_ZERO, KS_VALUES};
use super::position::{centre, chart, run, PaperCentre, STRING_FACE_LENGTH, THROAT_X};
use super::spectrum::Detail;
use super::{Context, Experiment, PaperClaim};
use crate::error::Result;
use crate::solve::ImpactResult;

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
        PaperClaim { id: "fig5_losses_similar", ours: losses_similar },
        PaperClaim { id: "fig5_tau_tip_throat", ours: tau_tip_throat },
        PaperClaim { id: "fig5_e_a_broad_maximum", ours: broad_maximum },
        PaperClaim { id: "fig5_fundamental_share", ours: fundamental_share },
        PaperClaim { id: "fig5_second_mode_f_vib", ours: second_mode_f_vib },
        PaperClaim { id: "discussion_node_rigid_e_a", ours: node_rigid },
    ],
};

/// The smallest |e_A| a reader finds on the Fig 5(b) curve in the outer 10 cm: at the paper's
/// nodes there (nodes 0-5 of N = 39, x <= 9.1 cm), each computed with the context's numerics.
fn dead_spot(ctx: &Context) -> Result<f64> {
    let params: Vec<_> = ctx.paper_nodes().iter().take(6).map(|&x| ctx.paper_params(x, 4.0e4)).collect();
    Ok(ctx.sweep(&params)?.iter().map(|r| r.e_a.abs()).fold(f64::INFINITY, f64::min))
}

/// Mean f(vib) (the paper's measure) over mean f(ball) at the Fig 5 points of [`both_beds`]
/// removed from the node (where the vibration is not essentially zero on either bed), on each
/// bed; the ratio further from 1.
fn losses_similar(ctx: &Context) -> Result<f64> {
    let beds = both_beds(ctx)?;
    let away: Vec<&BothBeds> = beds
        .iter()
        .filter(|b| b.r == 0.0 && b.soft.f_vib_peak_pe.max(b.stiff.f_vib_peak_pe) >= ESSENTIALLY_ZERO)
        .collect();
    let ratio = |bed: fn(&BothBeds) -> &ImpactResult| {
        let vib: f64 = away.iter().map(|b| bed(b).f_vib_peak_pe).sum();
        vib / away.iter().map(|b| bed(b).f_ball).sum::<f64>()
    };
    let (soft, stiff) = (ratio(|b| &b.soft), ratio(|b| &b.stiff));
    Ok(if soft.ln().abs() >= stiff.ln().abs() { soft } else { stiff })
}

/// Tau (ms) near the throat less near the tip ([`THROAT_X`], the paper's 6 cm), r 0, on each
/// string bed; the smaller.
fn tau_tip_throat(ctx: &Context) -> Result<f64> {
    let tau = |x: f64, ks: f64| -> Result<f64> { Ok(ctx.impact(&ctx.paper_params(x, ks))?.tau_s * 1e3) };
    KS_VALUES.iter().try_fold(f64::INFINITY, |least, &ks| Ok(least.min(tau(THROAT_X, ks)? - tau(X_TIP, ks)?)))
}

/// E_A near the throat over the largest e_A along the racket (the paper's nodes on the string
/// face and the throat itself), less 1 (%), on each string bed; the lower.
fn broad_maximum(ctx: &Context) -> Result<f64> {
    let face: Vec<f64> = ctx.paper_nodes().into_iter().filter(|&x| x <= STRING_FACE_LENGTH).collect();
    let mut lowest = f64::INFINITY;
    for ks in KS_VALUES {
        let at_throat = ctx.impact(&ctx.paper_params(THROAT_X, ks))?.e_a;
        let params: Vec<_> = face.iter().map(|&x| ctx.paper_params(x, ks)).collect();
        let largest = ctx.sweep(&params)?.iter().map(|r| r.e_a).fold(at_throat, f64::max);
        lowest = lowest.min(100.0 * (at_throat / largest - 1.0));
    }
    Ok(lowest)
}

/// The impacts of Fig 5(b) (k_s 4e4 N/m, whose duration is the paper's "5 ms") at the axis
/// points of [`both_beds`] on the string face (every fourth node of the paper's beam from node
/// 1, up to [`STRING_FACE_LENGTH`]), each with how its vibration shares among the modes.
fn axis_details(ctx: &Context) -> Result<Vec<Detail>> {
    let face = ctx.paper_nodes().into_iter().skip(1).step_by(4).filter(|&x| x <= STRING_FACE_LENGTH);
    face.map(|x| ctx.impact_detail(&ctx.paper_params(x, 4.0e4))).collect()
}

/// The fundamental's smallest share of the vibration energy over the impacts of
/// [`axis_details`] removed from the node (where the vibration is not essentially zero).
fn fundamental_share(ctx: &Context) -> Result<f64> {
    Ok(axis_details(ctx)?
        .iter()
        .filter(|d| d.result.f_vib_peak_pe >= ESSENTIALLY_ZERO)
        .map(|d| d.share(0))
        .fold(f64::INFINITY, f64::min))
}

/// The second mode's largest energy after the impacts of [`axis_details`], a share of the
/// ball's energy.
fn second_mode_f_vib(ctx: &Context) -> Result<f64> {
    Ok(axis_details(ctx)?.iter().map(|d| d.modes[1]).fold(0.0, f64::max))
}

/// The vibration node as the paper places it ("at x = 16 cm", p. 5), m from the tip.
const NODE_X: f64 = 0.16;

/// E_A of the beam at the node less that of the rigid racket (the same racket, `frame rigid`:
/// a mass and springs), r 0, k_s 4e4.
fn node_rigid(ctx: &Context) -> Result<f64> {
    let p = ctx.paper_params(NODE_X, 4.0e4);
    let mut rigid = p;
    rigid.variants.frame = crate::params::Frame::Rigid;
    Ok(ctx.impact(&p)?.e_a - ctx.impact(&rigid)?.e_a)
}

/// f(vib) at the fundamental node (16 cm).
fn node_f_vib(ctx: &Context) -> Result<f64> {
    Ok(ctx.impact(&ctx.paper_params(NODE_X, 4.0e4))?.f_vib_peak_pe)
}
