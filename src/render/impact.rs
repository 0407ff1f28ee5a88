//! Plain-text, CSV and time-series renderings of one impact, for the command-line tool.

use std::path::Path;

use crate::error::Result;
use crate::params::Params;
use crate::render::table::{fmt_sig, Table, Value};
use crate::solve::outcome::TEXT_ORDER;
use crate::solve::{ImpactResult, SeriesRow};

/// The result as `name value unit` lines, with the impact it describes on top.
pub fn result_text(params: &Params, r: &ImpactResult) -> String {
    let p = params;
    let mut s = format!(
        "impact: x = {} m (force at {:.4} m, {} load, N = {}), r = {} m, v1 = {} m/s\n\
         racket: L = {} m, M = {} kg, EI = {} N m^2, Ix = {} kg m^2; strings ks = {} N/m; \
         ball mb = {} kg, k1 = {} N/m, p = {}\n",
        fmt_sig(p.impact.x, 6),
        r.x_load_m,
        p.numerics.load.name(),
        p.numerics.segments,
        fmt_sig(p.impact.r, 6),
        fmt_sig(p.impact.v1, 6),
        fmt_sig(p.racket.length, 6),
        fmt_sig(p.racket.mass, 6),
        fmt_sig(p.racket.ei, 6),
        fmt_sig(p.racket.ix, 6),
        fmt_sig(p.strings.ks, 6),
        fmt_sig(p.ball.mass, 6),
        fmt_sig(p.ball.k1, 6),
        fmt_sig(p.ball.p, 6)
    );
    if p.variants != crate::params::Variants::default() {
        s.push_str(&format!("model: {}\n", p.variants.label()));
    }
    if !p.oblique.is_normal() {
        let o = &p.oblique;
        s.push_str(&format!(
            "oblique: angle {} deg from the normal, azimuth {} deg, spin {} rpm, mu {}, kt {} N/m, ball R {} m, I = {} m_b R^2\n",
            fmt_sig(o.angle_deg, 6),
            fmt_sig(o.azimuth_deg, 6),
            fmt_sig(o.spin_rpm, 6),
            fmt_sig(o.mu, 6),
            fmt_sig(o.kt, 6),
            fmt_sig(o.ball_radius, 6),
            fmt_sig(o.ball_inertia_factor, 6)
        ));
        if o.tangential != crate::params::TangentialLaw::Elastic {
            s.push_str(&format!(
                "tangential: {} (mu-ss {}{})\n",
                o.tangential.name(),
                fmt_sig(o.mu_ss, 6),
                crate::params::strings::entry(o.string).map_or(String::new(), |e| format!(", string {}", e.name))
            ));
        }
    }
    let held = p.variants.grip == crate::params::Grip::Hand;
    for field in TEXT_ORDER {
        let Some(text) = field.text else { continue };
        if (text.hand_only && !held) || (text.oblique_only && p.oblique.is_normal()) {
            continue;
        }
        let line = format!("{:<18} {:>12} {}", text.label, fmt_sig(field.number(r) * text.scale, 6), text.unit);
        s.push_str(line.trim_end());
        s.push('\n');
    }
    if r.recontact {
        s.push_str("recontact          yes: the frame meets the ball again after separation\n");
    }
    s
}

/// The result as a one-row CSV with the field names of SPEC.md section 2 as the header
/// (full precision), then the impact it describes ([`recorded`]).
pub fn result_csv(params: &Params, r: &ImpactResult) -> String {
    let v = serde_json::to_value(r).unwrap_or_default();
    let mut head = Vec::new();
    let mut row = Vec::new();
    if let serde_json::Value::Object(map) = v {
        for (k, v) in map {
            head.push(k);
            row.push(v.to_string());
        }
    }
    for (column, value) in recorded(params) {
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

/// The time series as a table; every row ends with the impact it belongs to ([`recorded`]).
pub fn series_table(params: &Params, rows: &[SeriesRow]) -> Table {
    let fixed = recorded(params);
    let mut t = Table::new(
        "series",
        &[
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
            fixed[0].0,
            fixed[1].0,
            fixed[2].0,
            fixed[3].0,
        ],
    );
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

/// Write the time series CSV atomically.
pub fn write_series(path: &Path, params: &Params, rows: &[SeriesRow]) -> Result<()> {
    crate::render::io::write_atomic(path, series_table(params, rows).to_csv().as_bytes())
}
