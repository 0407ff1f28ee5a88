//! `oblique_angle` (beyond the paper): the paper leaves oblique impacts open ("the dynamics will
//! depend on the coefficient of friction between the ball and the strings ... it will affect the
//! ball spin and rebound angle"). This answers it on the paper's racket: a ball without spin at
//! 30 m/s on the centre of the strings (x 15.8 cm, r 0), its in-plane direction across the face
//! (azimuth 90 deg), incidence angle 0-70 deg from the normal, at k_s 2e4 and 4e4 N/m, with the
//! default friction `mu = 0.4` and tangential stiffness `k_t = 2e4 N/m` (SPEC.md section 6).
//!
//! Model: the normal impact is the paper's at the normal speed `v1 cos(angle)`, so e_A does not
//! change with the angle (the scale law); the tangential grip-slip law (model::tangential)
//! gives the spin and the rebound angle. Expect: at small angles the ball grips and leaves
//! nearly rolling, with spin rising in proportion to the tangential speed; at large angles it
//! slides throughout and the spin levels off at `mu J_n R / I` while the normal impulse falls.

use super::{col, fit_range, line, on_right, styled, sweep, Context, Experiment, CENTRE_X, V1_OFF_AXIS};
use crate::error::Result;
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "oblique_angle",
    title: "Spin, rebound angle and e_A against incidence angle at the centre, ks 2e4 and 4e4 N/m",
    paper_ref: "(beyond the paper) Conclusions: oblique impacts depend on the friction, the spin and the rebound angle",
    run,
    chart,
    claims: &[],
};

/// String-bed stiffnesses, N/m.
const KS: [f64; 2] = [2.0e4, 4.0e4];

/// Incidence angles, degrees: 0 to 70 in steps of 2.5.
pub fn angles() -> Vec<f64> {
    (0..=28).map(|i| 2.5 * i as f64).collect()
}

fn run(ctx: &Context) -> Result<Table> {
    let mut t = Table::new(
        EXPERIMENT.id,
        &[
            "ks_n_per_m",
            "angle_deg",
            "e_a",
            "spin_out_rpm",
            "rebound_angle_deg",
            "v2_n_m_per_s",
            "v2_t_m_per_s",
            "slip_fraction",
        ],
    );
    for ks in KS {
        let params: Vec<_> = angles()
            .into_iter()
            .map(|a| {
                let mut p = ctx.paper_params(CENTRE_X, ks);
                p.impact.v1 = V1_OFF_AXIS;
                p.oblique.angle_deg = a;
                p.oblique.azimuth_deg = 90.0;
                p
            })
            .collect();
        for (p, r) in params.iter().zip(sweep(&params)?) {
            let normal = p.oblique.angle_deg == 0.0;
            let or_zero = |v: f64| if normal { 0.0 } else { v };
            t.push(vec![
                ks.into(),
                p.oblique.angle_deg.into(),
                r.e_a.into(),
                or_zero(r.spin_out_rpm).into(),
                or_zero(r.rebound_angle_deg).into(),
                (if normal { r.e_a * p.impact.v1 } else { r.v2_n }).into(),
                or_zero(r.v2_t).into(),
                or_zero(r.slip_fraction).into(),
            ])?;
        }
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let mut curves = Vec::new();
    for (i, ks) in KS.into_iter().enumerate() {
        let s = t.filter_num("ks_n_per_m", ks);
        let a = col(&s, "angle_deg");
        let style = if i == 0 { LineStyle::Solid } else { LineStyle::Dashed };
        let tag = format!("ks {}e4", ks / 1e4);
        curves.push(styled(line(format!("rebound angle, {tag}"), a.clone(), col(&s, "rebound_angle_deg"), 1), style));
        curves.push(styled(
            line(format!("100 e_A, {tag}"), a.clone(), col(&s, "e_a").iter().map(|e| 100.0 * e).collect(), 2),
            style,
        ));
        curves.push(styled(on_right(line(format!("spin (rpm), {tag}"), a, col(&s, "spin_out_rpm"), 3)), style));
    }
    curves.push(styled(
        line("angle of incidence (mirror rebound)", vec![0.0, 70.0], vec![0.0, 70.0], 0),
        LineStyle::Faint,
    ));
    // both axes fit their curves (from 0)
    let on = |right: bool| {
        let cs = curves.iter().filter(move |c| (c.axis == crate::render::plot::Axis::Right) == right);
        fit_range(cs.flat_map(|c| c.y.clone()), true)
    };
    Chart {
        title: "Oblique impact at the centre (x 15.8 cm): 30 m/s across the face (azimuth 90 deg), \
                no incoming spin, mu 0.4, kt 2e4 N/m"
            .into(),
        x_label: "incidence angle from the normal (deg)".into(),
        y_label: "rebound angle from the normal (deg),  100 e_A".into(),
        y2_label: Some("outgoing spin (rpm; > 0 topspin along the strings)".into()),
        x_log: false,
        x_range: Some((0.0, 70.0)),
        y_range: on(false),
        y2_range: on(true),
        curves,
        bands: vec![],
        vlines: vec![],
    }
}
