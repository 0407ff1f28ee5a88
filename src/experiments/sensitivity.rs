//! `sensitivity` (ours): which uncertain input the headline outputs hinge on. The inputs and
//! their distributions are those of [`robustness`](super::robustness) (declared with the
//! parameters); the outputs are e_A at the centre and 6 cm from the tip, the change of the
//! centre e_A for a factor two in k_s, the centre impact duration, the rotation at r 4 cm and
//! 30 m/s, and the vibration loss at 6 cm. Each gets its first-order and total Sobol' index
//! per input with 95 % bootstrap intervals (modal solver, [`SAMPLES`] base samples). Every draw
//! holds its loads where the paper's racket's N = 39 beam puts them
//! ([`robustness::sampling`](super::robustness::sampling)): a drawn length moves no load, so no
//! input's share carries the grid.

use super::fig6_string_stiffness::X_TIP;
use super::robustness::{context_at, param_inputs, sampling};
use super::speeds::{centre_as_read, tip_setup};
use super::{Context, Experiment};
use crate::error::Result;
use crate::params::uncertainty::Dist;
use crate::render::plot::{Chart, Curve, LineStyle};
use crate::render::table::{Table, Value};
use crate::solve::swing::gain_pct;
use crate::study::sensitivity::{self, Design};

/// Base samples: 256 x 11 runs of the six outputs, about 1 s of CPU.
pub const SAMPLES: u64 = 256;
/// The seed of the design.
pub const SEED: u32 = 2001;

/// The outputs: key, what it is.
pub const OUTPUTS: [(&str, &str); 6] = [
    ("e_a_centre", "e_A centre"),
    ("e_a_6cm", "e_A 6 cm from tip"),
    ("e_a_gain_ks_half_pct", "e_A change, ks / 2"),
    ("tau_centre_ms", "tau centre"),
    ("theta_r4_deg", "theta r 4 cm, 30 m/s"),
    ("f_vib_6cm", "f_vib 6 cm"),
];

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "sensitivity",
    title: "Sobol' indices of the headline outputs for each uncertain input",
    paper_ref: "p. 5-6: e_A centre and 6 cm, e_A +7 % for ks / 2, tau, theta (r 4 cm, 30 m/s), f_vib",
    run,
    chart,
    claims: &[],
};

/// The six outputs on one context, each read as the claims read it ([`super::reading_rule`]): at
/// the centre of the strings (k_s 4e4) e_A and tau read off the N = 39 curve, the rotation as
/// Fig 8 computes it; at 6 cm on the EI 150 frame the impact Figs 6 and 9 set up.
fn outputs(ctx: &Context) -> Result<Vec<f64>> {
    let stiff = centre_as_read(ctx, 4.0e4)?;
    let soft = centre_as_read(ctx, 2.0e4)?;
    let tip = tip_setup(ctx, ctx.frame_ei(150.0))?;
    let f_vib = ctx.impact(&ctx.paper_params(X_TIP, 4.0e4))?.f_vib;
    Ok(vec![stiff.e_a, tip.e_a, gain_pct(stiff.e_a, soft.e_a), stiff.tau_s * 1e3, stiff.theta_deg, f_vib])
}

fn run(ctx: &Context) -> Result<Table> {
    let specs = param_inputs();
    let design = Design::new(SAMPLES, specs.len(), SEED)?;
    let dists: Vec<Dist> = specs.iter().filter_map(|s| s.uncertainty.map(|u| u.dist)).collect();
    let sampled = sampling(ctx);
    let rows = sensitivity::run(&design, &dists, |x| outputs(&context_at(&sampled, &specs, x)?.remembering()), |_| {})?;
    let summaries = sensitivity::summarise_all(&design, &rows);
    let mut t = Table::new(
        EXPERIMENT.id,
        &["output", "input", "first", "first_lo", "first_hi", "total", "total_lo", "total_hi", "q05", "q95"],
    );
    for ((key, _), s) in OUTPUTS.iter().zip(&summaries) {
        for (spec, (f, tot)) in specs.iter().zip(s.first.iter().zip(&s.total)) {
            t.push(vec![
                Value::Text(key.to_string()),
                Value::Text(spec.key.to_string()),
                f.value.into(),
                f.lo.into(),
                f.hi.into(),
                tot.value.into(),
                tot.lo.into(),
                tot.hi.into(),
                s.q05.into(),
                s.q95.into(),
            ])?;
        }
    }
    Ok(t)
}

/// A palette colour per output and the style of its interval bars: the palette has five
/// solid colours no two of which are alike, so the sixth output's bars are dashed.
const COLOURS: [(usize, LineStyle); 6] = [
    (1, LineStyle::Solid),
    (2, LineStyle::Solid),
    (3, LineStyle::Solid),
    (6, LineStyle::Solid),
    (0, LineStyle::Solid),
    (5, LineStyle::Dashed),
];

fn chart(_: &Context, t: &Table) -> Chart {
    let names = param_inputs().iter().map(|s| s.key).collect::<Vec<_>>();
    let outputs = t.column_text("output").unwrap_or_default();
    let inputs_col = t.column_text("input").unwrap_or_default();
    let (total, lo, hi) = (super::col(t, "total"), super::col(t, "total_lo"), super::col(t, "total_hi"));
    let mut curves = Vec::new();
    let n_out = OUTPUTS.len() as f64;
    for (o, (key, label)) in OUTPUTS.iter().enumerate() {
        let offset = (o as f64 - (n_out - 1.0) / 2.0) * 0.12;
        let (colour, bars) = COLOURS[o];
        let (mut xs, mut ys) = (Vec::new(), Vec::new());
        for k in (0..t.rows.len()).filter(|&k| outputs[k] == *key) {
            let i = names.iter().position(|n| *n == inputs_col[k]).unwrap_or(0);
            let x = (i + 1) as f64 + offset;
            xs.push(x);
            ys.push(total[k]);
            curves.push(Curve::new("", vec![x, x], vec![lo[k], hi[k]]).with_color(colour).with_style(bars));
        }
        let label = if bars == LineStyle::Dashed { format!("{label} (dashed bars)") } else { label.to_string() };
        curves.push(Curve::new(label, xs, ys).with_style(LineStyle::Points).with_color(colour));
    }
    Chart {
        x_range: Some((0.4, names.len() as f64 + 0.6)),
        y_range: Some((-0.05, 1.1)),
        curves,
        x_ticks: names.iter().enumerate().map(|(i, n)| ((i + 1) as f64, n.to_string())).collect(),
        ..Chart::new(
            format!("Total Sobol' index of the headline outputs (bars: 95 % interval; {SAMPLES} x 11 samples)"),
            "uncertain input (its key in src/params/keys.rs)",
            "total Sobol' index",
        )
    }
}
