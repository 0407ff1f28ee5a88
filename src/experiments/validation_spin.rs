//! `validation_spin` (beyond the paper): the oblique model against the spin measurements of
//! data/measured, string by string, under each tangential law (SPEC.md section 6,
//! `--tangential`): the 14 points of the TWU "String Movement and Spin" table (seven strings at
//! 52 and 62 lb, M001-M014) each modelled with its own string's friction (data/strings), twice:
//! at 40 deg from the normal (`spin_out_rpm`, the companion study's reading) and at 50 deg
//! (`spin_out_rpm_50deg`, the page's '40 degrees to the stringbed' read from the string plane);
//! and as further rows the polyester/nylon spin ratio (M015), the hand-held over head-clamped
//! spin ratio (Cross and Lindsey 2011, M016), the incidence angle at which the ball stops
//! gripping (M029-M030) and the spin of a tour forehand (M052-M054, M058). Then per quantity the
//! RMS and the worst error over the values it defines, and for each reading of the angle the
//! Spearman rank correlation of the 14 points with its two-sided p-value. Nothing here is tuned
//! to these measurements: every parameter of every law has its source in its declaration.
//!
//! One row per compared value: `quantity, string, tension_lb, measured, model, unit` (`model`
//! under the default law), the measured spread (`spread_lo`, `spread_hi`: for the table points
//! the range of the seven strings at that tension, which the table itself shows; otherwise the
//! stated range or uncertainty), the rows it comes from, and the model under each law. A ratio
//! whose model denominator is below [`RATIO_FLOOR_RPM`] is undefined (an empty field): it would
//! describe how small the denominator happened to be, not the racket.

use super::{Context, Experiment, CENTRE_X};
use crate::error::{Error, Result};
use crate::params::{ks_from_tension_lb, strings, Grip, Oblique, Params, StringName, TangentialLaw};
use crate::render::plot::{Band, Chart, Curve, LineStyle};
use crate::render::table::{Table, Value};
use crate::solve::simulate;
use crate::solve::swing::Swing;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "validation_spin",
    title: "Spin against the lab and match measurements, string by string, under each tangential law",
    paper_ref: "(beyond the paper) data/measured M001-M016, M029-M030, M052-M058",
    run,
    chart,
    claims: &[],
};

pub use crate::study::measured::{parse as parse_measurements, rows as measured, Measured};

/// The smallest model spin, rpm, a ratio of spins is formed over: a tenth of the smallest
/// measured table spin (1207 rpm, M013). Below it the ratio is undefined (NaN).
pub const RATIO_FLOOR_RPM: f64 = 120.0;

/// `num / den`, or NaN when `|den|` is below [`RATIO_FLOOR_RPM`].
pub fn spin_ratio(num: f64, den: f64) -> f64 {
    if den.abs() < RATIO_FLOOR_RPM {
        f64::NAN
    } else {
        num / den
    }
}

/// The two-sided p-value of a rank correlation `rho` over `n` points under the hypothesis of
/// no correlation, through Student's t with `n - 2` degrees of freedom,
/// `t = rho sqrt((n - 2) / (1 - rho^2))` (the usual large-sample form; with ties and 14 points it
/// is an approximation). The t distribution's tail in closed form (Abramowitz and Stegun
/// 26.7.3-4, a finite series for whole degrees of freedom), hand-written because no dependency
/// of the crate has it and it is a dozen lines.
pub fn rank_correlation_p(rho: f64, n: usize) -> f64 {
    if n < 3 || !rho.is_finite() {
        return f64::NAN;
    }
    if rho.abs() >= 1.0 {
        return 0.0;
    }
    let nu = n - 2;
    let t = rho.abs() * ((nu as f64) / (1.0 - rho * rho)).sqrt();
    let theta = (t / (nu as f64).sqrt()).atan();
    let (sin, cos) = theta.sin_cos();
    // A(t|nu) = P(|T| < t)
    let a = if nu % 2 == 0 {
        let (mut term, mut sum) = (1.0, 1.0);
        for k in 1..nu / 2 {
            term *= (2 * k - 1) as f64 / (2 * k) as f64 * cos * cos;
            sum += term;
        }
        sin * sum
    } else {
        let (mut term, mut sum) = (1.0, if nu > 1 { 1.0 } else { 0.0 });
        for k in 1..nu.saturating_sub(1) / 2 {
            term *= (2 * k) as f64 / (2 * k + 1) as f64 * cos * cos;
            sum += term;
        }
        2.0 / std::f64::consts::PI * (theta + sin * cos * sum)
    };
    (1.0 - a).clamp(0.0, 1.0)
}

/// The 14 rows of the TWU table.
pub const TABLE_IDS: [&str; 14] =
    ["M001", "M002", "M003", "M004", "M005", "M006", "M007", "M008", "M009", "M010", "M011", "M012", "M013", "M014"];

/// The laws compared, in the order of their columns.
pub const LAWS: [TangentialLaw; 6] = TangentialLaw::ALL;

/// The string of a measured row (its name in the TWU table begins with the table's name).
pub fn string_of(row: &Measured) -> Result<StringName> {
    let entry = strings::all()
        .iter()
        .find(|e| row.string.starts_with(&e.name))
        .ok_or_else(|| Error::invalid("string", &row.string, "not in data/strings"))?;
    strings::parse(&entry.id)
}

/// The string tension of a measured row, lb (an error naming the row if it has none).
pub fn tension_of(row: &Measured) -> Result<f64> {
    row.tension_lb.ok_or_else(|| Error::invalid("measurements", &row.id, "the row states no string tension"))
}

/// The TWU shot's racket support and incoming ball on any parameters: the clamp (a frame too
/// heavy to move or twist), 56 mph (25.03 m/s) at 40 deg from the normal across the face with
/// 3820 rpm of backspin (data/measured, rows M001-M014).
pub fn set_twu_shot(p: &mut Params) {
    p.racket.mass = 1.0e6;
    p.racket.ix = 1.0e4;
    p.impact.v1 = 25.03;
    p.oblique.angle_deg = 40.0;
    p.oblique.azimuth_deg = 90.0;
    p.oblique.spin_rpm = -3820.0;
}

/// The TWU shot: a head-clamped racket (a frame too heavy to move stands for the clamp), 56 mph
/// (25.03 m/s) at 40 deg from the normal across the face with 3820 rpm of backspin, at the
/// centre, strung at `tension_lb` with `string` (its friction from data/strings).
pub fn twu_shot(ctx: &Context, law: TangentialLaw, string: StringName, tension_lb: f64) -> Params {
    let mut p = ctx.paper_params(CENTRE_X, ks_from_tension_lb(tension_lb));
    set_twu_shot(&mut p);
    p.oblique.tangential = law;
    p.oblique.string = string;
    (p.oblique.mu, p.oblique.mu_ss) = p.oblique.friction();
    p
}

/// The smallest whole incidence angle (1-85 deg) at which the ball slides throughout, on the
/// clamped racket at 25 m/s without spin (default string).
fn grip_stop_deg(ctx: &Context, law: TangentialLaw) -> Result<f64> {
    for a in 1..=85 {
        let mut p = twu_shot(ctx, law, StringName::None, 60.0);
        p.oblique.spin_rpm = 0.0;
        p.oblique.angle_deg = f64::from(a);
        if simulate(&p)?.slip_fraction >= 1.0 - 1e-12 {
            return Ok(f64::from(a));
        }
    }
    Ok(85.0)
}

/// Spearman's rank correlation (ties take their mean rank).
pub fn spearman(a: &[f64], b: &[f64]) -> f64 {
    let ranks = |v: &[f64]| -> Vec<f64> {
        (0..v.len())
            .map(|i| {
                let below = v.iter().filter(|&&x| x < v[i]).count() as f64;
                let equal = v.iter().filter(|&&x| x == v[i]).count() as f64;
                below + (equal + 1.0) / 2.0
            })
            .collect()
    };
    let (ra, rb) = (ranks(a), ranks(b));
    let n = a.len() as f64;
    let mean = (n + 1.0) / 2.0;
    let cov: f64 = ra.iter().zip(&rb).map(|(x, y)| (x - mean) * (y - mean)).sum();
    let var = |r: &[f64]| r.iter().map(|x| (x - mean).powi(2)).sum::<f64>();
    let d = (var(&ra) * var(&rb)).sqrt();
    if d == 0.0 {
        0.0
    } else {
        cov / d
    }
}

/// One compared value: quantity, string, tension, measured, unit, spread, source rows, and the
/// model under each law.
struct Compared {
    quantity: &'static str,
    string: String,
    tension: Value,
    measured: f64,
    unit: &'static str,
    spread: (f64, f64),
    source: String,
    model: Vec<f64>,
}

/// The index of the default law among [`LAWS`].
fn default_law() -> usize {
    LAWS.iter().position(|&l| l == Oblique::default().tangential).unwrap_or(0)
}

fn run(ctx: &Context) -> Result<Table> {
    let mut rows: Vec<Compared> = Vec::new();
    // the 14 table points
    let table = measured(&TABLE_IDS)?;
    let spread_at = |t: f64| {
        let v: Vec<f64> = table.iter().filter(|m| m.tension_lb == Some(t)).map(|m| m.value).collect();
        (v.iter().copied().fold(f64::MAX, f64::min), v.iter().copied().fold(f64::MIN, f64::max))
    };
    for (quantity, angle) in [("spin_out_rpm", 40.0), ("spin_out_rpm_50deg", 50.0)] {
        for m in &table {
            let string = string_of(m)?;
            let tension_lb = tension_of(m)?;
            let params: Vec<Params> = LAWS
                .iter()
                .map(|&l| {
                    let mut p = twu_shot(ctx, l, string, tension_lb);
                    p.oblique.angle_deg = angle;
                    p
                })
                .collect();
            let model = super::sweep(&params)?.iter().map(|r| r.spin_out_rpm).collect();
            rows.push(Compared {
                quantity,
                string: string.name().to_string(),
                tension: tension_lb.into(),
                measured: m.value,
                unit: "rpm",
                spread: spread_at(tension_lb),
                source: m.id.clone(),
                model,
            });
        }
    }
    // polyester over nylon, both tensions (M015)
    let ratio = &measured(&["M015"])?[0];
    // each measured point's 40 deg row, found by its source row (not by position)
    let mean_of = |material: &str, law: usize| {
        let v: Vec<f64> = table
            .iter()
            .filter(|m| m.string.contains(&format!("({material})")))
            .filter_map(|m| rows.iter().find(|c| c.quantity == "spin_out_rpm" && c.source == m.id))
            .map(|c| c.model[law])
            .collect();
        v.iter().sum::<f64>() / v.len() as f64
    };
    rows.push(Compared {
        quantity: "spin_ratio_polyester_over_nylon",
        string: "polyester (5) / nylon (2)".into(),
        tension: Value::Text("52 and 62".into()),
        measured: ratio.value,
        unit: "ratio",
        spread: (ratio.value, ratio.value),
        source: ratio.id.clone(),
        model: (0..LAWS.len()).map(|l| spin_ratio(mean_of("polyester", l), mean_of("nylon", l))).collect(),
    });
    // hand-held over head-clamped (M016): 22.8 m/s, 40 deg; the incoming backspin is not given
    // in the abstract, the TWU table's 3820 rpm stands in; the paper's racket at 60 lb
    let held = &measured(&["M016"])?[0];
    let mut model = Vec::new();
    for &law in &LAWS {
        let mut clamped = twu_shot(ctx, law, StringName::None, 60.0);
        clamped.impact.v1 = 22.8;
        let mut hand = ctx.paper_params(CENTRE_X, ks_from_tension_lb(60.0));
        hand.impact.v1 = 22.8;
        hand.oblique = clamped.oblique;
        hand.variants.grip = Grip::Hand;
        model.push(spin_ratio(simulate(&hand)?.spin_out_rpm, simulate(&clamped)?.spin_out_rpm));
    }
    rows.push(Compared {
        quantity: "spin_out_ratio_handheld_over_clamped",
        string: "none".into(),
        tension: 60.0.into(),
        measured: held.value,
        unit: "ratio",
        spread: (held.value - 0.05, held.value + 0.05),
        source: held.id.clone(),
        model,
    });
    // the incidence beyond which the ball slides throughout (M029-M030: about 50 deg)
    let stop = &measured(&["M030"])?[0];
    rows.push(Compared {
        quantity: "grip_regime_max_angle_from_normal",
        string: "none".into(),
        tension: 60.0.into(),
        measured: stop.value,
        unit: "deg",
        spread: (stop.value - 5.0, stop.value + 5.0),
        source: "M029, M030".into(),
        model: LAWS.iter().map(|&l| grip_stop_deg(ctx, l)).collect::<Result<_>>()?,
    });
    // a tour forehand: 30 m/s swing, 20 m/s ball, path 20 and 30 deg; measured the mean of the
    // three 2023 top-10 forehand spins (M052-M054), spread from the 1997 film's 1800 (M058) to
    // the largest player mean (M052)
    let fh = measured(&["M052", "M053", "M054", "M058"])?;
    let mean = (fh[0].value + fh[1].value + fh[2].value) / 3.0;
    for path in [20.0, 30.0] {
        let mut model = Vec::new();
        for &law in &LAWS {
            let mut base = ctx.paper_params(CENTRE_X, ks_from_tension_lb(60.0));
            base.oblique.tangential = law;
            let stroke = Swing { racket_speed: 30.0, path_deg: path, incoming: 20.0, incoming_spin_rpm: 0.0 };
            model.push(stroke.hit(&base)?.spin_rpm);
        }
        rows.push(Compared {
            quantity: "forehand_spin_rpm",
            string: format!("none; swing path {path} deg"),
            tension: 60.0.into(),
            measured: mean,
            unit: "rpm",
            spread: (fh[3].value, fh[0].value),
            source: "M052-M054, M058".into(),
            model,
        });
    }

    let mut columns =
        vec!["quantity", "string", "tension_lb", "measured", "model", "unit", "spread_lo", "spread_hi", "source"];
    let law_columns: Vec<String> = LAWS.iter().map(|l| format!("model_{}", l.name())).collect();
    columns.extend(law_columns.iter().map(String::as_str));
    let mut t = Table::new(EXPERIMENT.id, &columns);
    let d = default_law();
    for c in &rows {
        let mut row = vec![
            Value::Text(c.quantity.into()),
            Value::Text(c.string.clone()),
            c.tension.clone(),
            c.measured.into(),
            c.model[d].into(),
            Value::Text(c.unit.into()),
            c.spread.0.into(),
            c.spread.1.into(),
            Value::Text(c.source.clone()),
        ];
        row.extend(c.model.iter().map(|&v| Value::from(v)));
        t.push(row)?;
    }
    // the summaries: per quantity the RMS and the worst error (measured 0: no error), and the
    // rank correlation of the 14 table points (measured 1: the measured order)
    let quantities: Vec<&str> = rows.iter().map(|c| c.quantity).fold(Vec::new(), |mut v, q| {
        if !v.contains(&q) {
            v.push(q);
        }
        v
    });
    for q in quantities {
        let of: Vec<&Compared> = rows.iter().filter(|c| c.quantity == q).collect();
        let unit = of[0].unit;
        // the errors of the values the law defines (a ratio over a near-zero spin is not one)
        let err =
            |l: usize| -> Vec<f64> { of.iter().map(|c| c.model[l] - c.measured).filter(|e| e.is_finite()).collect() };
        let rms = |l: usize| {
            let e = err(l);
            if e.is_empty() {
                f64::NAN
            } else {
                (e.iter().map(|e| e * e).sum::<f64>() / e.len() as f64).sqrt()
            }
        };
        let worst = |l: usize| {
            let e = err(l);
            if e.is_empty() {
                f64::NAN
            } else {
                e.into_iter().fold(0.0f64, |w, e| if e.abs() > w.abs() { e } else { w })
            }
        };
        for (name, f) in [("rms_error", &rms as &dyn Fn(usize) -> f64), ("worst_error", &worst)] {
            let mut row = vec![
                Value::Text(format!("{q}:{name}")),
                Value::Text("all".into()),
                Value::Text("all".into()),
                0.0.into(),
                f(d).into(),
                Value::Text(unit.into()),
                0.0.into(),
                0.0.into(),
                Value::Text(of.iter().map(|c| c.source.as_str()).collect::<Vec<_>>().join(" ")),
            ];
            row.extend((0..LAWS.len()).map(|l| Value::from(f(l))));
            t.push(row)?;
        }
    }
    // the rank correlation of the 14 table points under each reading of the angle, and its
    // two-sided p-value
    for q in ["spin_out_rpm", "spin_out_rpm_50deg"] {
        let points: Vec<&Compared> = rows.iter().filter(|c| c.quantity == q).collect();
        let meas: Vec<f64> = points.iter().map(|c| c.measured).collect();
        let rho = |l: usize| spearman(&meas, &points.iter().map(|c| c.model[l]).collect::<Vec<_>>());
        let p = |l: usize| rank_correlation_p(rho(l), points.len());
        for (name, f, ideal) in
            [("rank_correlation", &rho as &dyn Fn(usize) -> f64, 1.0), ("rank_correlation_p", &p, 0.0)]
        {
            let mut row = vec![
                Value::Text(format!("{q}:{name}")),
                Value::Text("all".into()),
                Value::Text("all".into()),
                ideal.into(),
                f(d).into(),
                Value::Text("1".into()),
                ideal.into(),
                ideal.into(),
                Value::Text("M001-M014".into()),
            ];
            row.extend((0..LAWS.len()).map(|l| Value::from(f(l))));
            t.push(row)?;
        }
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let points = t.filter("quantity", "spin_out_rpm");
    let measured = super::col(&points, "measured");
    let lo = super::col(&points, "spread_lo").into_iter().fold(f64::MAX, f64::min);
    let hi = super::col(&points, "spread_hi").into_iter().fold(f64::MIN, f64::max);
    let mut curves = vec![Curve::new("model = measured", vec![1000.0, 2000.0], vec![1000.0, 2000.0])
        .with_style(LineStyle::Dashed)
        .with_color(0)];
    for (i, law) in LAWS.iter().enumerate() {
        let y = super::col(&points, &format!("model_{}", law.name()));
        let style = if law == &Oblique::default().tangential { LineStyle::Paper } else { LineStyle::Points };
        let mut label = format!("{} law", law.name());
        if law == &Oblique::default().tangential {
            label.push_str(" (the default)");
        }
        curves.push(Curve::new(label, measured.clone(), y).with_style(style).with_color(i + 1));
    }
    // the other reading of the angle, under the default law
    let fifty = t.filter("quantity", "spin_out_rpm_50deg");
    let d = Oblique::default().tangential;
    curves.push(
        Curve::new(
            format!("{} law at 50 deg (the angle read from the string plane)", d.name()),
            super::col(&fifty, "measured"),
            super::col(&fifty, &format!("model_{}", d.name())),
        )
        .with_style(LineStyle::Points)
        .with_color(LAWS.len() + 1),
    );
    Chart {
        title: "TWU spin table (7 strings x 52/62 lb): model against measured, each tangential law (40 deg)".into(),
        x_label: "measured outgoing spin (rpm); clamped racket, 25 m/s, 40 deg, 3820 rpm backspin in".into(),
        y_label: "model outgoing spin (rpm)".into(),
        y2_label: None,
        x_log: false,
        x_range: Some((1000.0, 2000.0)),
        y_range: Some((-1000.0, 8000.0)),
        y2_range: None,
        curves,
        bands: vec![Band::new(lo, hi, "measured spread over the seven strings")],
        vlines: vec![],
        ..Chart::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spearman_of_an_order_and_its_reverse() {
        let a = [1.0, 2.0, 3.0, 4.0];
        assert!((spearman(&a, &[10.0, 20.0, 30.0, 40.0]) - 1.0).abs() < 1e-15);
        assert!((spearman(&a, &[4.0, 3.0, 2.0, 1.0]) + 1.0).abs() < 1e-15);
        assert_eq!(spearman(&a, &[5.0; 4]), 0.0);
    }

    /// The p-value against values of Student's t (df 12, two-sided): t = 2.179 at p = 0.05,
    /// 3.055 at 0.01; and the odd-df series against df 1 (Cauchy) and df 3.
    #[test]
    fn rank_correlation_p_matches_the_t_table() {
        let rho_of = |t: f64, n: usize| t / (t * t + (n - 2) as f64).sqrt();
        assert!((rank_correlation_p(rho_of(2.179, 14), 14) - 0.05).abs() < 2e-4);
        assert!((rank_correlation_p(rho_of(3.055, 14), 14) - 0.01).abs() < 1e-4);
        assert!((rank_correlation_p(rho_of(1.0, 3), 3) - 0.5).abs() < 1e-12);
        assert!((rank_correlation_p(rho_of(3.182, 5), 5) - 0.05).abs() < 2e-4);
        assert_eq!(rank_correlation_p(0.0, 14), 1.0);
        assert_eq!(rank_correlation_p(1.0, 14), 0.0);
    }

    #[test]
    fn a_ratio_over_a_near_zero_spin_is_undefined() {
        assert!(spin_ratio(1000.0, RATIO_FLOOR_RPM * 0.99).is_nan());
        assert_eq!(spin_ratio(1000.0, 2000.0), 0.5);
        assert_eq!(spin_ratio(1000.0, -2000.0), -0.5);
    }

    #[test]
    fn every_table_row_names_a_string_of_the_table() {
        let rows = measured(&TABLE_IDS).unwrap();
        for r in &rows {
            assert!(string_of(r).is_ok(), "{r:?}");
            assert!(r.tension_lb == Some(52.0) || r.tension_lb == Some(62.0));
        }
        assert_eq!(rows.iter().filter(|r| string_of(r).unwrap() == StringName::Tcs16).count(), 2);
    }
}
