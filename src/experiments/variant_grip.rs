//! `variant_grip` (ours): a hand on the grip against the paper's free racket, e_A along the
//! head and throat, k_s 4e4 N/m, r = 0 (see [`super::variants`]); with the time a bending wave
//! takes to reach the hand and come back.

use super::variants::{along_to, KS};
use super::{col, line, on_right, scaled, styled, sweep, Context, Experiment, CENTRE_X};
use crate::error::Result;
use crate::params::{Grip, Params};
use crate::render::plot::{Chart, LineStyle, VLine};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "variant_grip",
    title: "Hand-held against free racket: e_A along the racket, ks 4e4 N/m, r 0",
    paper_ref: "p. 2: the ball leaves before the impulse reflected off the hand returns (Brody 1997; Cross 1999a)",
    run,
    chart,
    claims: &[],
};

/// A firm grip: ten times the default hand.
const FIRM: f64 = 10.0;

fn run(ctx: &Context) -> Result<Table> {
    // impacts on the head and throat, not on the hand itself
    let base = ctx.paper_params(0.0, KS);
    let grip_start = base.racket.length - base.variants.grip_length;
    let free = sweep(&along_to(ctx, grip_start, |_| {}))?;
    let hand = sweep(&along_to(ctx, grip_start, |p| p.variants.grip = Grip::Hand))?;
    let firm = sweep(&along_to(ctx, grip_start, |p| {
        p.variants.grip = Grip::Hand;
        p.variants.hand_stiffness *= FIRM;
        p.variants.hand_damping *= FIRM;
    }))?;
    let mut t = Table::new(
        EXPERIMENT.id,
        &["x_m", "e_a_free", "e_a_hand", "e_a_firm", "tau_s", "wave_return_s", "f_hand", "f_hand_firm"],
    );
    for (i, p) in along_to(ctx, grip_start, |_| {}).iter().enumerate() {
        let (f, h, m) = (&free[i], &hand[i], &firm[i]);
        t.push(vec![
            p.impact.x.into(),
            f.e_a.into(),
            h.e_a.into(),
            m.e_a.into(),
            f.tau_s.into(),
            wave_return(p, grip_start - p.impact.x, f.tau_s).into(),
            h.f_hand.into(),
            m.f_hand.into(),
        ])?;
    }
    Ok(t)
}

/// Time for a bending wave to run `distance` (m) to the hand and back, s, at the group
/// velocity `2 (EI / (M/L))^(1/4) sqrt(omega)` of the frequency `1 / (2 tau)` that dominates an
/// impact of duration `tau` (bending waves are dispersive; this is the usual estimate). Zero
/// when the impact is on the grip.
fn wave_return(p: &Params, distance: f64, tau: f64) -> f64 {
    if distance <= 0.0 {
        return 0.0;
    }
    let rho_a = p.racket.mass / p.racket.length;
    let omega = std::f64::consts::PI / tau;
    let c_g = 2.0 * (p.racket.ei / rho_a).powf(0.25) * omega.sqrt();
    2.0 * distance / c_g
}

fn chart(ctx: &Context, t: &Table) -> Chart {
    let x = scaled(col(t, "x_m"), 100.0);
    Chart {
        title: format!(
            "Hand-held vs free racket, ks 4e4 N/m, r 0 (hand: 15 cm grip, mode-1 damping {:.1} %)",
            100.0 * {
                let mut p = ctx.paper_params(0.0, KS);
                p.variants.grip = Grip::Hand;
                crate::solve::hand_damping_ratio(&p, 1)
            }
        ),
        x_label: "impact distance from the tip x (cm)".into(),
        y_label: "e_A".into(),
        y2_label: Some("time (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 56.0)),
        // headroom above the curves for the legend
        y_range: Some((-0.1, 1.0)),
        y2_range: Some((0.0, 12.0)),
        curves: vec![
            line("e_A free (the paper)", x.clone(), col(t, "e_a_free"), 0),
            styled(line("e_A hand 5e3 N/m, 10 N s/m", x.clone(), col(t, "e_a_hand"), 1), LineStyle::Dashed),
            styled(line("e_A firm hand 5e4 N/m, 100 N s/m", x.clone(), col(t, "e_a_firm"), 3), LineStyle::Dashed),
            on_right(styled(line("impact duration", x.clone(), scaled(col(t, "tau_s"), 1e3), 5), LineStyle::Faint)),
            on_right(styled(
                line("wave to the hand and back", x, scaled(col(t, "wave_return_s"), 1e3), 6),
                LineStyle::Faint,
            )),
        ],
        bands: vec![],
        vlines: vec![VLine { x: CENTRE_X * 100.0, label: "mode-1 node (15.8 cm)".into() }],
        ..Chart::default()
    }
}
