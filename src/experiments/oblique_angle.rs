//! `oblique_angle` (beyond the paper): the paper leaves oblique impacts open ("the dynamics will
//! depend on the coefficient of friction between the ball and the strings ... it will affect the
//! ball spin and rebound angle"). This answers it on the paper's racket: a ball without spin at
//! 30 m/s on the centre of the strings (x 15.8 cm, r 0), its in-plane direction across the face
//! (azimuth 90 deg), incidence angle 0-70 deg from the normal, at k_s 2e4 and 4e4 N/m, with the
//! default friction `mu = 0.4`, tangential stiffness `k_t` and tangential law (SPEC.md section 6).
//!
//! Model: the normal impact is the paper's at the normal speed `v1 cos(angle)`, so e_A does not
//! change with the angle (the scale law); the tangential grip-slip law (model::tangential)
//! gives the spin and the rebound angle. Expect: at small angles the ball grips and leaves
//! nearly rolling, with spin rising in proportion to the tangential speed; at large angles it
//! slides throughout and the spin levels off at `mu J_n R / I` while the normal impulse falls.

use super::{col, fit_range, line, on_right, styled, sweep, Context, Experiment, CENTRE_X, V1_OFF_AXIS};
use crate::error::Result;
use crate::params::TangentialLaw;
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

/// A spin below this share of the stiffer bed's, at the same angle, is "about zero".
const ABOUT_ZERO: f64 = 0.05;

/// Where the softer bed leaves the ball with about no spin at small angles while the stiffer
/// one spins it, the points (angle, spin) and the note that says why, from the data and the
/// tangential law in use: a ball that keeps its incoming tangential speed (out/in within
/// [`ABOUT_ZERO`] of 1) was given back all the tangential spring took (the elastic law's spring
/// is lossless), one that lost it was slowed by the friction without being spun. `None` where
/// the data show no such thing.
fn spin_about_zero(t: &Table, law: TangentialLaw) -> Option<(Vec<f64>, Vec<f64>, String)> {
    let (soft, stiff) = (t.filter_num("ks_n_per_m", KS[0]), t.filter_num("ks_n_per_m", KS[1]));
    let (a, spin, vt) = (col(&soft, "angle_deg"), col(&soft, "spin_out_rpm"), col(&soft, "v2_t_m_per_s"));
    let stiff_spin = col(&stiff, "spin_out_rpm");
    // the run of small angles (from the first oblique one) where the soft bed's spin is about zero
    let run: Vec<usize> = (0..a.len())
        .skip_while(|&k| a[k] <= 0.0)
        .take_while(|&k| stiff_spin.get(k).is_some_and(|s| spin[k].abs() < ABOUT_ZERO * s.abs()))
        .collect();
    if run.is_empty() {
        return None;
    }
    let kept: Vec<f64> = run.iter().map(|&k| vt[k] / (V1_OFF_AXIS * a[k].to_radians().sin())).collect();
    let ratio = kept.iter().sum::<f64>() / kept.len() as f64;
    let note = if (ratio - 1.0).abs() <= ABOUT_ZERO && law == TangentialLaw::Elastic {
        "lossless elastic spring gives all back".to_string()
    } else if (ratio - 1.0).abs() <= ABOUT_ZERO {
        format!("`{}` law's spring gives all back", law.name())
    } else {
        format!("friction slows, `{}` law", law.name())
    };
    let note = format!("spin ~0 (ks {}e4): {note}", KS[0] / 1e4);
    Some((run.iter().map(|&k| a[k]).collect(), run.iter().map(|&k| spin[k]).collect(), note))
}

fn chart(ctx: &Context, t: &Table) -> Chart {
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
    let (law, kt) = {
        let o = ctx.paper_params(CENTRE_X, KS[0]).oblique;
        (o.tangential, o.kt)
    };
    if let Some((a, spin, note)) = spin_about_zero(t, law) {
        curves.push(styled(on_right(line(note, a, spin, 3)), LineStyle::Points));
    }
    // both axes fit their curves (from 0)
    let on = |right: bool| {
        let cs = curves.iter().filter(move |c| (c.axis == crate::render::plot::Axis::Right) == right);
        fit_range(cs.flat_map(|c| c.y.clone()), true)
    };
    Chart {
        title: format!(
            "Oblique impact at the centre (x 15.8 cm): 30 m/s across the face (azimuth 90 deg), \
             no incoming spin, mu 0.4, kt {} N/m, {} law",
            crate::numfmt::sig(kt, 3),
            law.name()
        ),
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
        ..Chart::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::table::Value;

    /// A table of the two beds' spins at 0, 2.5 and 5 deg (`soft`, `stiff` in rpm) with the
    /// soft bed keeping its incoming tangential speed.
    fn table(soft: [f64; 3], stiff: [f64; 3]) -> Table {
        let mut t = Table::new("oblique_angle", &["ks_n_per_m", "angle_deg", "spin_out_rpm", "v2_t_m_per_s"]);
        for (ks, spins) in [(KS[0], soft), (KS[1], stiff)] {
            for (k, spin) in spins.into_iter().enumerate() {
                let a = 2.5 * k as f64;
                let vt = V1_OFF_AXIS * a.to_radians().sin();
                t.push(vec![Value::Num(ks), Value::Num(a), Value::Num(spin), Value::Num(vt)]).unwrap();
            }
        }
        t
    }

    #[test]
    fn spin_about_zero_is_none_without_a_run_of_small_angles() {
        // the soft bed spins the ball as much as the stiff one from the first oblique angle
        assert_eq!(spin_about_zero(&table([0.0, 300.0, 600.0], [0.0, 310.0, 620.0]), TangentialLaw::Loss), None);
        // about no spin at 2.5 deg on the soft bed: a run of one point, named
        let (a, spin, note) =
            spin_about_zero(&table([0.0, 5.0, 600.0], [0.0, 310.0, 620.0]), TangentialLaw::Elastic).unwrap();
        assert_eq!((a, spin), (vec![2.5], vec![5.0]));
        assert!(note.starts_with("spin ~0 (ks 2e4)"), "{note}");
    }
}
