//! `fig7_off_axis_x10`, `fig8_off_axis_centre`: paper Figs 7 and 8, "Effect on e_A and theta of
//! an off-axis impact at x = 10 cm" and "at x = 15.8 cm", with v1 = 30 m/s and k_s = 2e4 or
//! 4e4 N/m; theta is the rotation about the long axis at the end of the impact (Eq 7).
//!
//! Model: the full impact, N = 39 node scheme (x = 10 cm loads node 5 at 9.10 cm, x = 15.8 cm
//! node 9 at 16.4 cm), r from 0 to 10 cm. Expect (p. 6): theta roughly proportional to r and to
//! the impact duration; about 19 % more rotation when k_s is halved; "A ball impacting at r =
//! 4 cm near the centre of the strings causes the racket to rotate by about 10 deg"; e_A falls
//! with r and rises when k_s is reduced.

use super::{col, line, on_right, paper_params, scaled, sweep, Experiment, V1_OFF_AXIS};
use crate::error::Result;
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::Table;

/// Fig 7, x = 10 cm.
pub const X10: Experiment = Experiment {
    id: "fig7_off_axis_x10",
    title: "Rotation angle and e_A against off-axis distance r at x 10 cm, v1 30 m/s",
    paper_ref: "Fig 7 and p. 6: theta +19 % when ks is halved",
    run: || run(X10.id, 0.10),
    chart: |t| chart(t, "Fig 7: off-axis impact at x = 10 cm, v1 = 30 m/s"),
};

/// Fig 8, x = 15.8 cm.
pub const CENTRE: Experiment = Experiment {
    id: "fig8_off_axis_centre",
    title: "Rotation angle and e_A against off-axis distance r at x 15.8 cm, v1 30 m/s",
    paper_ref: "Fig 8 and p. 6: r 4 cm near the centre rotates the racket ~10 deg",
    run: || run(CENTRE.id, super::CENTRE_X),
    chart: |t| chart(t, "Fig 8: off-axis impact at x = 15.8 cm, v1 = 30 m/s"),
};

/// The two string stiffnesses of Figs 7-8, N/m.
pub const KS_VALUES: [f64; 2] = [2.0e4, 4.0e4];

fn run(id: &str, x: f64) -> Result<Table> {
    let mut t = Table::new(id, &["ks_n_per_m", "r_m", "theta_end_deg", "e_a", "tau_s", "f_spin"]);
    for ks in KS_VALUES {
        let params: Vec<_> = (0..=20)
            .map(|i| {
                let mut p = paper_params(x, ks);
                p.impact.r = 0.005 * i as f64;
                p.impact.v1 = V1_OFF_AXIS;
                p
            })
            .collect();
        for (p, r) in params.iter().zip(sweep(&params)?) {
            t.push(vec![
                ks.into(),
                p.impact.r.into(),
                r.theta_end_deg.into(),
                r.e_a.into(),
                r.tau_s.into(),
                r.f_spin.into(),
            ])?;
        }
    }
    Ok(t)
}

fn chart(t: &Table, title: &str) -> Chart {
    let mut curves = Vec::new();
    for (i, ks) in KS_VALUES.iter().enumerate() {
        let s = t.filter_num("ks_n_per_m", *ks);
        let r_cm = scaled(col(&s, "r_m"), 100.0);
        let name = if i == 0 { "ks 2e4" } else { "ks 4e4" };
        curves.push(line(format!("theta, {name}"), r_cm.clone(), col(&s, "theta_end_deg"), 2 * i + 1));
        let mut e = on_right(line(format!("e_A, {name}"), r_cm, col(&s, "e_a"), 2 * i + 1));
        e.style = LineStyle::Dashed;
        curves.push(e);
    }
    Chart {
        title: title.into(),
        x_label: "distance from the long axis r (cm)".into(),
        y_label: "rotation at the end of the impact theta (deg)".into(),
        y2_label: Some("e_A (dashed)".into()),
        x_log: false,
        x_range: Some((0.0, 10.0)),
        y_range: Some((0.0, 30.0)),
        y2_range: Some((0.0, 0.6)),
        curves,
        vlines: vec![],
    }
}
