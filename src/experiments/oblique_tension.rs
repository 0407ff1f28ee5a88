//! `oblique_tension` (beyond the paper): "The effects of string tension on power and control,
//! reported by players, could possibly be explained if the coefficient of friction depends on
//! the string tension" (Conclusions). Spin and rebound angle against string tension 40-70 lb
//! (k_s = 4e4 N/m x T / 60 lb) at 30 and 45 deg incidence, 30 m/s, no incoming spin, at the
//! centre of the strings, across the face: once with `mu = 0.4` whatever the tension, and once
//! with the friction made to depend on it as the paper conjectures.
//!
//! The assumed law (ours, an illustration, not a measurement): `mu = 0.4 T / 60 lb`, friction in
//! proportion to the tension (0.27 at 40 lb, 0.47 at 70 lb), the strongest simple dependence;
//! the measured spin of TWU's string tests changes by -8 % to +18 % between 52 and 62 lb
//! depending on the string, +0.4 % on average (data/measured). Expect: with a constant mu the
//! tension moves the spin only through the normal impulse and the contact time, a few per cent;
//! with mu growing with tension the spin of a sliding ball grows with it.

use super::{col, fit_range, line, on_right, styled, sweep, Context, Experiment, CENTRE_X, V1_OFF_AXIS};
use crate::error::Result;
use crate::params::ks_from_tension_lb;
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::{Table, Value};

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "oblique_tension",
    title: "Spin and rebound angle against string tension at 30 and 45 deg, mu constant or growing with tension",
    paper_ref: "(beyond the paper) Conclusions: if the friction depends on the tension",
    run,
    chart,
    claims: &[],
};

/// Incidence angles, degrees.
const ANGLES: [f64; 2] = [30.0, 45.0];
/// The friction at 60 lb (and at every tension under the constant law).
const MU_60: f64 = 0.4;

/// A friction law: its name and `mu(T)` for a tension in lb.
type MuLaw = (&'static str, fn(f64) -> f64);

/// The friction laws.
const LAWS: [MuLaw; 2] = [("constant", |_| MU_60), ("tension", |t| MU_60 * t / 60.0)];

/// String tensions, lb: 40 to 70 in steps of 2.5.
pub fn tensions_lb() -> Vec<f64> {
    (0..=12).map(|i| 40.0 + 2.5 * i as f64).collect()
}

fn run(ctx: &Context) -> Result<Table> {
    let mut t = Table::new(
        EXPERIMENT.id,
        &[
            "mu_law",
            "angle_deg",
            "tension_lb",
            "ks_n_per_m",
            "mu",
            "spin_out_rpm",
            "rebound_angle_deg",
            "e_a",
            "tau_ms",
            "slip_fraction",
        ],
    );
    for (law, mu_of) in LAWS {
        for angle in ANGLES {
            let params: Vec<_> = tensions_lb()
                .into_iter()
                .map(|tension| {
                    let mut p = ctx.paper_params(CENTRE_X, ks_from_tension_lb(tension));
                    p.impact.v1 = V1_OFF_AXIS;
                    p.oblique.angle_deg = angle;
                    p.oblique.azimuth_deg = 90.0;
                    p.oblique.mu = mu_of(tension);
                    p
                })
                .collect();
            for ((p, r), tension) in params.iter().zip(sweep(&params)?).zip(tensions_lb()) {
                t.push(vec![
                    Value::Text(law.into()),
                    angle.into(),
                    tension.into(),
                    p.strings.ks.into(),
                    p.oblique.mu.into(),
                    r.spin_out_rpm.into(),
                    r.rebound_angle_deg.into(),
                    r.e_a.into(),
                    (1e3 * r.tau_s).into(),
                    r.slip_fraction.into(),
                ])?;
            }
        }
    }
    Ok(t)
}

/// The colours of the curves: spin at 30 and 45 deg in warm colours (orange, reddish purple),
/// the rebound angle in cool ones (bluish green, blue), so that a spin curve is never taken for
/// an angle curve ([`crate::render::plot::PALETTE`]).
const SPIN_COLORS: [usize; 2] = [1, 6];
/// See [`SPIN_COLORS`].
const ANGLE_COLORS: [usize; 2] = [3, 5];

fn chart(ctx: &Context, t: &Table) -> Chart {
    // One colour per quantity and incidence angle (spin warm, rebound angle cool), one line
    // style per friction law (named in the title); the spin axis (left) puts its curves in the
    // upper half, the rebound-angle axis (right) in the lower half, so none covers another. The
    // four legend entries name the quantity and the angle of each colour (and the right axis).
    // (the spin curves first, then the angle ones: the legend lists them by quantity)
    let (mut curves, mut angles) = (Vec::new(), Vec::new());
    for (i, (law, _)) in LAWS.into_iter().enumerate() {
        let style = if i == 0 { LineStyle::Solid } else { LineStyle::Dashed };
        for (j, angle) in ANGLES.into_iter().enumerate() {
            let s = t.filter("mu_law", law).filter_num("angle_deg", angle);
            let x = col(&s, "tension_lb");
            let (spin, rebound) = if i == 0 {
                // (the legend adds "right axis" to the rebound angle's)
                (format!("spin at {angle} deg"), format!("rebound angle at {angle} deg"))
            } else {
                (String::new(), String::new())
            };
            curves.push(styled(line(spin, x.clone(), col(&s, "spin_out_rpm"), SPIN_COLORS[j]), style));
            angles.push(styled(on_right(line(rebound, x, col(&s, "rebound_angle_deg"), ANGLE_COLORS[j])), style));
        }
    }
    curves.append(&mut angles);
    let fit = |right: bool| {
        let cs = curves.iter().filter(move |c| (c.axis == crate::render::plot::Axis::Right) == right);
        fit_range(cs.flat_map(|c| c.y.clone()), false).unwrap_or((0.0, 1.0))
    };
    let ((s0, s1), (a0, a1)) = (fit(false), fit(true));
    Chart {
        title: format!(
            "Spin and rebound angle vs tension, solid mu {MU_60}, dashed mu {MU_60} T / 60 lb: 30 m/s, centre, azimuth 90 deg, no spin in"
        ),
        x_label: format!(
            "string tension (lb); ks = 4e4 N/m x T / 60 lb; kt {} N/m",
            crate::numfmt::sig(ctx.paper_params(CENTRE_X, 4.0e4).oblique.kt, 3)
        ),
        y_label: "outgoing spin (rpm)".into(),
        y2_label: Some("rebound angle from the normal (deg)".into()),
        x_log: false,
        x_range: Some((40.0, 70.0)),
        y_range: Some((s0 - 1.2 * (s1 - s0), s1)),
        y2_range: Some((a0, a1 + 1.2 * (a1 - a0))),
        curves,
        bands: vec![],
        vlines: vec![],
        ..Chart::default()
    }
}
