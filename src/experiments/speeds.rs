//! `speeds`: what the rebound coefficient means for a serve and a forehand (paper p. 5-6 and
//! Conclusions). With the racket at rest the ball leaves at `e_A v1`; in the frame of a serve
//! (ball at rest, racket at `v1`) it leaves at `(1 + e_A) v1`; for a forehand (racket speed
//! equal to the incoming ball speed) at `(1 + 2 e_A) v1`.
//!
//! Paper: at the centre a factor two in k_s changes e_A from 0.41 to 0.44 (+7 %), the serve by
//! +2 % and the forehand by +3.3 %; "A decrease in string tension from 60 lb to 50 lb would
//! therefore result in an increase in serve speed of only 0.7 %" (forehand 1.1 %, tau +0.2 ms,
//! theta -4 % for 50 -> 60 lb); at 6 cm a 200 Hz frame raises e_A from 0.10 to 0.18, serve +7 %.
//!
//! Model: tension maps to k_s proportionally, 60 lb = 4e4 N/m (so 30 lb = 2e4 N/m, the paper's
//! factor two), and every tension is computed directly, not by scaling percentages. Centre
//! values are the impact at x = 15.8 cm by the reading rule ([`super::READING_RULE`]: N = 39,
//! node 9 at 16.38 cm); theta is for r = 4 cm at 30 m/s (Fig 8). The `frame` rows compare EI
//! 150 and 384 at x = 6 cm (node 3 at 5.46 cm), k_s 4e4 (Figs 6, 9).

use super::{fig6_string_stiffness::X_TIP, line, Context, Experiment, PaperClaim, CENTRE_X};
use crate::error::Result;
use crate::params::{ks_from_tension_lb, Params};
use crate::render::plot::{Chart, LineStyle, VLine};
use crate::render::table::Table;
use crate::solve::swing::gain_pct;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "speeds",
    title: "Serve and forehand speed gains against string tension (centre) and frame stiffness (6 cm)",
    paper_ref: "p. 5-6 and Conclusions: ks x2 -> e_A +7 %, serve +2 %, forehand +3.3 %; 60 -> 50 lb: +0.7 %, +1.1 %",
    run,
    chart,
    claims: &[
        PaperClaim { id: "speeds_ks_half_e_a_gain", ours: |c| compare(c, 4.0e4, 2.0e4, |a, b| gain_pct(a.e_a, b.e_a)) },
        PaperClaim { id: "speeds_ks_half_serve_gain", ours: |c| compare(c, 4.0e4, 2.0e4, serve_gain) },
        PaperClaim { id: "speeds_ks_half_forehand_gain", ours: |c| compare(c, 4.0e4, 2.0e4, forehand_gain) },
        PaperClaim { id: "speeds_60_50_serve_gain", ours: |c| compare(c, 4.0e4, lb(50.0), serve_gain) },
        PaperClaim { id: "speeds_60_50_forehand_gain", ours: |c| compare(c, 4.0e4, lb(50.0), forehand_gain) },
        PaperClaim { id: "speeds_60_50_tau_change", ours: |c| compare(c, 4.0e4, lb(50.0), tau_change_ms) },
        PaperClaim {
            id: "speeds_50_60_theta_change",
            ours: |c| compare(c, lb(50.0), 4.0e4, |a, b| gain_pct(a.theta_deg, b.theta_deg)),
        },
        PaperClaim {
            id: "speeds_50_60_tau_change",
            ours: |c| compare(c, lb(50.0), 4.0e4, |a, b| gain_pct(a.tau_s, b.tau_s)),
        },
        PaperClaim { id: "discussion_tau_ks_half", ours: |c| compare(c, 4.0e4, 2.0e4, tau_change_ms) },
        PaperClaim {
            id: "discussion_angle_30_rad_s",
            ours: |c| compare(c, 4.0e4, lb(50.0), |a, b| (30.0 * (b.tau_s - a.tau_s)).to_degrees()),
        },
        PaperClaim { id: "intro_swing_angle", ours: |c| Ok((30.0 * centre_setup(c, 4.0e4)?.tau_s).to_degrees()) },
        PaperClaim { id: "serve_peak_force", ours: serve_peak_force },
        PaperClaim { id: "strings_ks_40lb", ours: |_| Ok(lb(40.0)) },
        PaperClaim { id: "strings_ks_80lb", ours: |_| Ok(lb(80.0)) },
    ],
};

/// k_s for a string tension in lb.
fn lb(tension_lb: f64) -> f64 {
    ks_from_tension_lb(tension_lb)
}

/// A comparison of the centre setups of two string stiffnesses (N/m): `f(a, b)`.
fn compare(ctx: &Context, ks_a: f64, ks_b: f64, f: fn(&Setup, &Setup) -> f64) -> Result<f64> {
    let (a, b) = (centre_setup(ctx, ks_a)?, centre_setup(ctx, ks_b)?);
    Ok(f(&a, &b))
}

/// Serve speed gain of `b` over `a`, %.
fn serve_gain(a: &Setup, b: &Setup) -> f64 {
    gain_pct(1.0 + a.e_a, 1.0 + b.e_a)
}

/// Forehand speed gain of `b` over `a`, %.
fn forehand_gain(a: &Setup, b: &Setup) -> f64 {
    gain_pct(1.0 + 2.0 * a.e_a, 1.0 + 2.0 * b.e_a)
}

/// Impact duration of `b` less that of `a`, ms.
fn tau_change_ms(a: &Setup, b: &Setup) -> f64 {
    (b.tau_s - a.tau_s) * 1e3
}

/// The peak force of a serve sending the ball off at 60 m/s from the centre: the
/// relative speed is 60/(1+e_A) with that impact's own e_A (the model is linear in v1).
fn serve_peak_force(ctx: &Context) -> Result<f64> {
    let mut p = ctx.paper_params(CENTRE_X, 4.0e4);
    p.impact.v1 = 1.0;
    let unit = ctx.impact(&p)?;
    Ok(unit.peak_force_n * 60.0 / (1.0 + unit.e_a))
}

/// Reference tension, lb.
pub const REF_TENSION_LB: f64 = 60.0;
/// Tensions of the curve, lb (30 lb is k_s = 2e4 N/m).
pub const TENSIONS_LB: [f64; 11] = [30.0, 35.0, 40.0, 45.0, 50.0, 55.0, 60.0, 65.0, 70.0, 75.0, 80.0];

/// One racket setup: e_A, tau and theta as the paper's figures give them.
#[derive(Debug, Clone, Copy)]
pub struct Setup {
    /// Apparent coefficient of restitution.
    pub e_a: f64,
    /// Impact duration, s.
    pub tau_s: f64,
    /// Rotation for r = 4 cm at 30 m/s, degrees.
    pub theta_deg: f64,
}

/// e_A, tau (r 0) and theta (r 4 cm, 30 m/s, Fig 8) at the centre of the strings for a string
/// stiffness.
pub fn centre_setup(ctx: &Context, ks: f64) -> Result<Setup> {
    let p = ctx.paper_params(CENTRE_X, ks);
    let mut q = p;
    q.impact.r = 0.04;
    q.impact.v1 = ctx.v1_off_axis();
    let r = ctx.impact(&p)?;
    Ok(Setup { e_a: r.e_a, tau_s: r.tau_s, theta_deg: ctx.impact(&q)?.theta_end_deg })
}

/// e_A and tau at 6 cm (Figs 6, 9) for a frame stiffness, k_s 4e4, and theta there for
/// r = 4 cm at 30 m/s.
pub fn tip_setup(ctx: &Context, ei: f64) -> Result<Setup> {
    let mut p: Params = ctx.paper_params(X_TIP, 4.0e4);
    p.racket.ei = ei;
    let r = ctx.impact(&p)?;
    p.impact.r = 0.04;
    p.impact.v1 = ctx.v1_off_axis();
    Ok(Setup { e_a: r.e_a, tau_s: r.tau_s, theta_deg: ctx.impact(&p)?.theta_end_deg })
}

fn run(ctx: &Context) -> Result<Table> {
    let mut t = Table::new(
        EXPERIMENT.id,
        &[
            "group",
            "tension_lb",
            "ks_n_per_m",
            "ei_n_m2",
            "x_m",
            "e_a",
            "tau_s",
            "theta_r4cm_deg",
            "e_a_gain_pct",
            "serve_gain_pct",
            "forehand_gain_pct",
            "tau_change_s",
            "theta_change_pct",
        ],
    );
    let reference = centre_setup(ctx, ks_from_tension_lb(REF_TENSION_LB))?;
    for lb in TENSIONS_LB {
        let ks = ks_from_tension_lb(lb);
        let s = centre_setup(ctx, ks)?;
        let racket = Racket { tension_lb: lb, ks, ei: ctx.frame_ei(150.0), x: CENTRE_X };
        push(&mut t, "tension", racket, &reference, &s)?;
    }
    let flexible = tip_setup(ctx, ctx.frame_ei(150.0))?;
    for ei in [150.0, 384.0].map(|e| ctx.frame_ei(e)) {
        let s = tip_setup(ctx, ei)?;
        let racket = Racket { tension_lb: REF_TENSION_LB, ks: 4.0e4, ei, x: X_TIP };
        push(&mut t, "frame", racket, &flexible, &s)?;
    }
    Ok(t)
}

/// The racket and impact point of a row of the table.
#[derive(Debug, Clone, Copy)]
struct Racket {
    /// String tension, lb.
    tension_lb: f64,
    /// String stiffness, N/m.
    ks: f64,
    /// Frame stiffness, N m^2.
    ei: f64,
    /// Impact point, m from the tip.
    x: f64,
}

/// A row of the table: the setup `b` of `racket` in `group`, its gains over the setup `a`.
fn push(t: &mut Table, group: &str, racket: Racket, a: &Setup, b: &Setup) -> Result<()> {
    t.push(vec![
        group.into(),
        racket.tension_lb.into(),
        racket.ks.into(),
        racket.ei.into(),
        racket.x.into(),
        b.e_a.into(),
        b.tau_s.into(),
        b.theta_deg.into(),
        gain_pct(a.e_a, b.e_a).into(),
        gain_pct(1.0 + a.e_a, 1.0 + b.e_a).into(),
        gain_pct(1.0 + 2.0 * a.e_a, 1.0 + 2.0 * b.e_a).into(),
        (b.tau_s - a.tau_s).into(),
        gain_pct(a.theta_deg, b.theta_deg).into(),
    ])
}

fn chart(ctx: &Context, t: &Table) -> Chart {
    let tension = t.filter("group", "tension");
    let lb = super::col(&tension, "tension_lb");
    // "<what> +a, +b <unit> at 30, 50 lb" from the paper's values as printed
    let pp = |what: &str, unit: &str, ids: &[&str], color: usize| {
        let values = ids.iter().map(|id| format!("+{}", super::paper_list(&[id]))).collect::<Vec<_>>().join(", ");
        let at = if ids.len() == 2 { "30, 50 lb" } else { "30 lb" };
        let x = if ids.len() == 2 { vec![30.0, 50.0] } else { vec![30.0] };
        super::paper_points(super::paper_label(&format!("{what} {values} {unit} at {at}")), x, ids, color)
    };
    Chart {
        title: format!(
            "Speed gains against string tension, relative to 60 lb, at the centre of the strings{}",
            super::used_position(CENTRE_X, &ctx.racket)
        ),
        x_label: "string tension (lb), ks = 4e4 N/m x tension / 60 lb".into(),
        y_label: "change relative to 60 lb (%)".into(),
        y2_label: Some("impact duration change (ms)".into()),
        x_log: false,
        x_range: Some((28.0, 82.0)),
        y_range: Some((-6.0, 22.0)),
        y2_range: Some((-1.5, 5.5)),
        curves: vec![
            line("e_A", lb.clone(), super::col(&tension, "e_a_gain_pct"), 0),
            line("serve speed (1+e_A) v1", lb.clone(), super::col(&tension, "serve_gain_pct"), 1),
            line("forehand speed (1+2e_A) v1", lb.clone(), super::col(&tension, "forehand_gain_pct"), 2),
            line("rotation, r 4 cm", lb.clone(), super::col(&tension, "theta_change_pct"), 3),
            super::on_right(super::styled(
                line("tau change", lb.clone(), super::scaled(super::col(&tension, "tau_change_s"), 1e3), 6),
                LineStyle::Dashed,
            )),
            pp("e_A", "%", &["speeds_ks_half_e_a_gain"], 0),
            pp("serve", "%", &["speeds_ks_half_serve_gain", "speeds_60_50_serve_gain"], 1),
            pp("forehand", "%", &["speeds_ks_half_forehand_gain", "speeds_60_50_forehand_gain"], 2),
            super::on_right(pp("tau", "ms", &["discussion_tau_ks_half", "speeds_60_50_tau_change"], 6)),
        ],
        bands: vec![],
        vlines: vec![VLine { x: 30.0, label: "30 lb = ks 2e4 N/m".into() }],
        ..Chart::default()
    }
}
