//! `variant_strings` (ours): strings that stiffen with deflection (+10 % at 4 cm) against the
//! paper's linear strings, e_A at the centre against the incident speed (see
//! [`super::variants`]).

use super::variants::KS;
use super::{col, line, styled, sweep, Context, Experiment, CENTRE_X};
use crate::error::Result;
use crate::params::StringLaw;
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "variant_strings",
    title: "Strings stiffening 10 % at 4 cm against linear strings: e_A at the centre vs incident speed",
    paper_ref: "p. 4: k_s rises ~10 % at large deflections; 'of little consequence'",
    run,
    chart,
    claims: &[],
};

/// Incident speeds of the string comparison, m/s.
fn speeds() -> Vec<f64> {
    (1..=12).map(|i| 5.0 * i as f64).collect()
}

fn run(ctx: &Context) -> Result<Table> {
    let cases = [
        (2.0e4, StringLaw::Linear),
        (2.0e4, StringLaw::Stiffening),
        (KS, StringLaw::Linear),
        (KS, StringLaw::Stiffening),
    ];
    let mut params = Vec::new();
    for &v1 in &speeds() {
        for &(ks, law) in &cases {
            let mut p = ctx.paper_params(CENTRE_X, ks);
            p.impact.v1 = v1;
            p.variants.strings = law;
            params.push(p);
        }
    }
    let results = sweep(&params)?;
    let mut t = Table::new(
        EXPERIMENT.id,
        &[
            "v1_m_s",
            "e_a_linear_2e4",
            "e_a_stiffening_2e4",
            "e_a_linear_4e4",
            "e_a_stiffening_4e4",
            "tau_s_stiffening_4e4",
        ],
    );
    for (i, v1) in speeds().iter().enumerate() {
        let r = &results[4 * i..4 * i + 4];
        t.push(vec![
            (*v1).into(),
            r[0].e_a.into(),
            r[1].e_a.into(),
            r[2].e_a.into(),
            r[3].e_a.into(),
            r[3].tau_s.into(),
        ])?;
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let v = col(t, "v1_m_s");
    Chart {
        title: "Stiffening strings (+10 % at 4 cm) vs linear, centre x 15.8 cm, r 0".into(),
        x_label: "incident ball speed v1 (m/s)".into(),
        y_label: "e_A".into(),
        y2_label: None,
        x_log: false,
        x_range: Some((0.0, 62.0)),
        y_range: Some((0.40, 0.48)),
        y2_range: None,
        curves: vec![
            line("linear, ks 2e4", v.clone(), col(t, "e_a_linear_2e4"), 0),
            styled(line("stiffening, ks 2e4", v.clone(), col(t, "e_a_stiffening_2e4"), 0), LineStyle::Dashed),
            line("linear, ks 4e4", v.clone(), col(t, "e_a_linear_4e4"), 4),
            styled(line("stiffening, ks 4e4", v, col(t, "e_a_stiffening_4e4"), 4), LineStyle::Dashed),
        ],
        bands: vec![],
        vlines: vec![],
        ..Chart::default()
    }
}
