//! Plain-text, CSV and time-series renderings of one impact, for the command-line tool.

use std::path::Path;

use crate::error::Result;
use crate::numfmt::fmt_sig;
use crate::params::spec::{Heading, Values};
use crate::params::{keys, Params};
use crate::render::table::{Table, Value};
use crate::solve::outcome::TEXT_ORDER;
use crate::solve::{ImpactResult, SeriesRow};

/// The result as `name value unit` lines, with the impact it describes on top ([`echo`]).
pub fn result_text(params: &Params, r: &ImpactResult) -> String {
    let p = params;
    let mut s = echo(p, r);
    let held = p.variants.grip == crate::params::Grip::Hand;
    for field in TEXT_ORDER {
        let Some(text) = field.text else { continue };
        let elastic = p.oblique.tangential == crate::params::TangentialLaw::Elastic;
        if (text.hand_only && !held) || (text.oblique_only && p.oblique.is_normal()) || (text.law_only && elastic) {
            continue;
        }
        let value = field.number(r);
        let line = if value.is_nan() {
            format!("{:<18} {:>12} {}", text.label, "undefined", undefined_remark(field.key))
        } else {
            format!(
                "{:<18} {:>12} {}{}",
                text.label,
                fmt_sig(value * text.scale, 6),
                text.oblique_unit.filter(|_| !p.oblique.is_normal()).unwrap_or(text.unit),
                sign_remark(field.key, r)
            )
        };
        s.push_str(line.trim_end());
        s.push('\n');
    }
    if r.recontact {
        s.push_str("recontact          yes: the frame meets the ball again after separation\n");
    }
    s
}

/// The impact `params` describes, one line a help heading ([`Heading`], in the help's order):
/// each parameter this impact uses ([`crate::params::used`]), as `key value unit`, in the order
/// of the declaration (`racket: ei 150 N m^2, mass 0.34 kg, ...`); the impact line ends with
/// where the force acts (`(force at 0.0910 m)`), an oblique line with a friction scale with
/// the sliding ball's friction (`(sliding mu 0.3)`). A parameter the impact does not use is not
/// echoed (a value given for it was noted or refused).
pub fn echo(params: &Params, r: &ImpactResult) -> String {
    let mut s = String::new();
    for heading in Heading::ALL {
        let used: Vec<String> = keys::ALL
            .iter()
            .filter(|spec| spec.heading == heading && crate::params::used::unused(spec, params).is_none())
            .filter_map(|spec| {
                let value = match keys::value_number(spec.key, params) {
                    Some(v) if !matches!(spec.values, Values::Choice(_)) => fmt_sig(v, 6),
                    _ => keys::value_text(spec.key, params)?,
                };
                let unit =
                    if spec.unit.is_empty() || value == "auto" { String::new() } else { format!(" {}", spec.unit) };
                Some(format!("{} {value}{unit}", spec.key))
            })
            .collect();
        if used.is_empty() {
            continue;
        }
        // what the line's values come to where that is not one of them: where the force acts, the
        // friction of the sliding ball under a scale
        let o = &params.oblique;
        let remark = match heading {
            Heading::Impact => format!(" (force at {:.4} m)", r.x_load_m),
            Heading::Oblique if o.mu_scale != 1.0 => format!(" (sliding mu {})", fmt_sig(o.sliding_mu(), 6)),
            _ => String::new(),
        };
        s.push_str(&format!("{}: {}{remark}\n", heading.title().to_lowercase(), used.join(", ")));
    }
    s
}

/// Why a field of an oblique or spinning impact is undefined (NaN), in its text line.
pub fn undefined_remark(key: &str) -> String {
    match key {
        "e_t" => format!(
            "(incoming slip of the contact point below {} % of the incident speed)",
            100.0 * crate::solve::oblique::E_T_MIN_SLIP_FRACTION
        ),
        _ => String::new(),
    }
}

/// The result's fields as JSON for `params`: every field of an oblique or spinning impact is
/// present, an undefined one (`e_t` at too little incoming slip) as null; at normal incidence
/// without spin the oblique fields, and under the elastic law the losses of the named
/// tangential mechanisms, which do not apply, are left out.
pub fn result_json(params: &Params, r: &ImpactResult) -> serde_json::Value {
    let mut v = serde_json::to_value(r).unwrap_or_default();
    if let (false, serde_json::Value::Object(map)) = (params.oblique.is_normal(), &mut v) {
        for f in crate::solve::outcome::FIELDS.iter().filter(|f| f.is_oblique() && !f.is_law_only()) {
            map.entry(f.key).or_insert(serde_json::Value::Null);
        }
    }
    v
}

/// The sign convention of `--spin-rpm` and `spin_out_rpm`, as the JSON and CSV of an oblique
/// impact print it.
pub const SIMULATE_SPIN_CONVENTION: &str =
    "spin_rpm and spin_out_rpm: > 0 topspin relative to the ball's incoming motion along the strings (not the court's frame)";

/// What the sign of an oblique field means for this result, appended to its text line: the
/// normal rebound velocity says whether the ball rebounds or moves on, and the rebound angle
/// why it is over 90 degrees when it does (the labels themselves are fixed).
/// `key` is the field's JSON and CSV key ([`crate::solve::outcome::Field::key`]).
pub fn sign_remark(key: &str, r: &ImpactResult) -> &'static str {
    let on = r.v2_n < 0.0;
    match key {
        "v2_n_m_per_s" if r.v2_n > 0.0 => ": > 0, rebounds away from the strings",
        "v2_n_m_per_s" if on => ": < 0, moves on in its incoming direction (the frame recoils faster)",
        "v2_n_m_per_s" if r.v2_n == 0.0 => ": 0, no normal motion after impact",
        "rebound_angle_deg" if on => ": |angle| over 90 since v2_n < 0 (the ball moves on, no rebound)",
        _ => "",
    }
}

/// The result as a one-row CSV with the field names of SPEC.md section 2 as the header
/// (full precision), then the impact it describes ([`recorded`], and [`recorded_oblique`] for
/// an oblique or spinning ball).
pub fn result_csv(params: &Params, r: &ImpactResult) -> String {
    let v = result_json(params, r);
    let mut head = Vec::new();
    let mut row = Vec::new();
    if let serde_json::Value::Object(map) = v {
        for (k, v) in map {
            head.push(k);
            // (an undefined field, null in the JSON, is an empty field; a flag is 0/1 as in
            // the sweep and map CSVs)
            row.push(match v {
                serde_json::Value::Null => String::new(),
                serde_json::Value::Bool(b) => u8::from(b).to_string(),
                v => v.to_string(),
            });
        }
    }
    for (column, value) in recorded(params).into_iter().chain(recorded_oblique(params)) {
        head.push(column.to_string());
        row.push(value.to_string());
    }
    format!("{}\n{}\n", head.join(","), row.join(","))
}

/// The parameters every CSV of one impact records, column and value: the impact point, the
/// string bed and the ball speed.
pub fn recorded(p: &Params) -> [(&'static str, f64); 4] {
    use crate::params::keys::{KS, R, V1, X};
    [(X.column, p.impact.x), (R.column, p.impact.r), (KS.column, p.strings.ks), (V1.column, p.impact.v1)]
}

/// The incidence, azimuth, incoming spin and friction of an oblique or spinning impact (none
/// at normal incidence without spin), column and value: the CSV of such an impact records
/// what it was run at (spin with [`SIMULATE_SPIN_CONVENTION`]).
pub fn recorded_oblique(p: &Params) -> Vec<(&'static str, f64)> {
    use crate::params::keys::{ANGLE_DEG, AZIMUTH_DEG, MU, SPIN_RPM};
    if p.oblique.is_normal() {
        return Vec::new();
    }
    let o = &p.oblique;
    vec![
        (ANGLE_DEG.column, o.angle_deg),
        (AZIMUTH_DEG.column, o.azimuth_deg),
        (SPIN_RPM.column, o.spin_rpm),
        (MU.column, o.mu),
    ]
}

/// The columns of the time series ([`SeriesRow`]'s fields: time s, force N, displacements m,
/// twist rad, energies as fractions of the ball's incident energy), before [`recorded`].
pub const SERIES_COLUMNS: [&str; 13] = [
    "t_s",
    "force_n",
    "y_ball_m",
    "y_total_m",
    "theta_rad",
    "ke_ball",
    "pe_ball",
    "pe_string",
    "ke_racket",
    "pe_racket",
    "ke_spin",
    "hand",
    "total",
];

/// The time series as a table; every row ends with the impact it belongs to ([`recorded`]).
pub fn series_table(params: &Params, rows: &[SeriesRow]) -> Table {
    let fixed = recorded(params);
    let columns: Vec<&str> = SERIES_COLUMNS.into_iter().chain(fixed.iter().map(|(c, _)| *c)).collect();
    let mut t = Table::new("series", &columns);
    for r in rows {
        let vals = [
            r.t_s,
            r.force_n,
            r.y_ball_m,
            r.y_total_m,
            r.theta_rad,
            r.ke_ball,
            r.pe_ball,
            r.pe_string,
            r.ke_racket,
            r.pe_racket,
            r.ke_spin,
            r.hand,
            r.total,
        ];
        t.rows.push(vals.iter().chain(fixed.iter().map(|(_, v)| v)).map(|&v| Value::Num(v)).collect());
    }
    t
}

/// Stage the time series CSV in `staged` (published with the command's other outputs).
pub fn stage_series(
    staged: &mut crate::render::io::Staged,
    path: &Path,
    params: &Params,
    rows: &[SeriesRow],
) -> Result<()> {
    staged.bytes(path, series_table(params, rows).to_csv().as_bytes())
}
