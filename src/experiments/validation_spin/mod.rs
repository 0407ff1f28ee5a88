//! `validation_spin` (beyond the paper): the oblique model against the spin measurements of
//! data/measured, string by string, under each tangential law (SPEC.md section 6,
//! `--tangential`), with the constants the calibration fitted (experiment `spin_calibration`:
//! the default `kt`, fitted on the rows marked `role = calibration`): the 14 points of the TWU
//! "String Movement and Spin" table (seven strings at 52 and 62 lb, M001-M014) each modelled
//! with its own string's friction (data/strings), twice: at 40 deg from the normal
//! (`spin_out_rpm`, the companion study's reading) and at 50 deg (`spin_out_rpm_50deg`, the
//! page's '40 degrees to the stringbed' read from the string plane); and as further rows the
//! polyester/nylon spin ratio (M015; and over the validation strings alone), the hand-held over
//! head-clamped spin ratio (Cross and Lindsey 2011, M016), the incidence angle at which the ball
//! stops gripping (M029-M030) and the spin of a tour forehand (M052-M054, M058).
//!
//! One row per compared value: `quantity, string, tension_lb, measured, model, unit` (`model`
//! under the default law), the measured spread (`spread_lo`, `spread_hi`: for the table points
//! the range of the seven strings at that tension, which the table itself shows; otherwise the
//! stated range or uncertainty), the rows it comes from, the row's `role`, the default law's
//! value fitted without the row's string (`model_held_out`, calibration rows), the validation
//! uncertainty's parts under the default law ([`vv`]: `u_input`, `u_num`, `u_d`, `u_angle`) and
//! `u_val`, and the model under each law. Then per quantity the RMS and the worst error, and for
//! each reading of the angle the Spearman rank correlation with its two-sided p-value, over the
//! 14 points and over the 8 validation points. A ratio whose model denominator is below
//! [`compare::RATIO_FLOOR_RPM`] is undefined (an empty field).
//!
//! The shots are set up in [`shots`], the compared values and summaries in [`compare`], the
//! uncertainty budget in [`vv`]; the measurements are read by [`crate::study::measured`].

pub mod compare;
pub mod shots;
pub mod vv;

use super::{Context, Experiment};
use crate::error::Result;
use crate::params::{Oblique, SolverKind, TangentialLaw};
use crate::render::plot::{Band, Chart, Curve, LineStyle};
use crate::render::table::{Table, Value};
use crate::solve::simulate;
use crate::study::measured::{self, Measured, Role};
use compare::{rank, rms_error, spin_ratio, worst_error, Compared};

pub use compare::{spin_ratio as ratio, RATIO_FLOOR_RPM};
pub use shots::{set_twu_shot, twu_shot, TABLE_IDS};

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "validation_spin",
    title: "Spin against the lab and match measurements, string by string, under each tangential law",
    paper_ref: "(beyond the paper) data/measured M001-M016, M029-M030, M052-M058",
    run,
    chart,
    claims: &[],
};

/// The laws compared, in the order of their columns.
pub const LAWS: [TangentialLaw; TangentialLaw::ALL.len()] = TangentialLaw::ALL;

/// The index of the default law among [`LAWS`].
pub fn default_law() -> usize {
    LAWS.iter().position(|&l| l == Oblique::default().tangential).unwrap_or(0)
}

/// The role of a measured row as the table's column names it.
fn role(row: &Measured) -> &'static str {
    row.role.unwrap_or(Role::Validation).name()
}

/// The columns before the laws'.
pub const COLUMNS: [&str; 16] = [
    "quantity",
    "string",
    "tension_lb",
    "measured",
    "model",
    "unit",
    "spread_lo",
    "spread_hi",
    "source",
    "role",
    "model_held_out",
    "u_input",
    "u_num",
    "u_d",
    "u_angle",
    "u_val",
];

/// The compared values under every law, with the default law's held-out values and
/// uncertainty budget.
pub fn compared(ctx: &Context) -> Result<Vec<Compared>> {
    let d = default_law();
    let law = LAWS[d];
    let table = measured::rows(&TABLE_IDS)?;
    let mut rows: Vec<Compared> = Vec::new();
    let spread_at = |t: f64| {
        let v: Vec<f64> = table.iter().filter(|m| m.tension_lb == Some(t)).map(|m| m.value).collect();
        (v.iter().copied().fold(f64::MAX, f64::min), v.iter().copied().fold(f64::MIN, f64::max))
    };
    let nan4 = [f64::NAN; 4];
    // the 14 table points at each reading
    for (quantity, angle) in [("spin_out_rpm", shots::TWU_ANGLE_DEG), ("spin_out_rpm_50deg", 50.0)] {
        for m in &table {
            let tension = shots::tension_of(m)?;
            let params: Vec<_> =
                LAWS.iter().map(|&l| shots::table_shot(ctx, l, m, angle)).collect::<Result<Vec<_>>>()?;
            let model = super::sweep(&params)?.iter().map(|r| r.spin_out_rpm).collect();
            rows.push(Compared {
                quantity,
                string: shots::string_of(m)?.name().to_string(),
                tension: tension.into(),
                measured: m.value,
                unit: "rpm",
                spread: spread_at(tension),
                source: m.id.clone(),
                role: role(m),
                held_out: f64::NAN,
                u: nan4,
                model,
            });
        }
    }
    // polyester over nylon (M015), over all seven strings as measured, and over the validation
    // strings alone (the same table, no string the calibration saw)
    let at_40: Vec<Vec<f64>> = rows.iter().filter(|c| c.quantity == "spin_out_rpm").map(|c| c.model.clone()).collect();
    let ratio_of = |keep: &dyn Fn(&Measured) -> bool, l: usize| {
        let spins: Vec<f64> = at_40.iter().map(|m| m[l]).collect();
        vv::poly_over_nylon(&table, &spins, keep)
    };
    let measured_ratio = |keep: &dyn Fn(&Measured) -> bool| {
        let spins: Vec<f64> = table.iter().map(|m| m.value).collect();
        vv::poly_over_nylon(&table, &spins, keep)
    };
    let all = |_: &Measured| true;
    let validation = |m: &Measured| m.role == Some(Role::Validation);
    let m015 = &measured::rows(&["M015"])?[0];
    // the measured M015 ratio beside the model's, at 40 deg here and at 50 deg below
    let m015_row = |quantity: &'static str, model: Vec<f64>| Compared {
        quantity,
        string: "polyester (5) / nylon (2)".into(),
        tension: Value::Text("52 and 62".into()),
        measured: m015.value,
        unit: "ratio",
        spread: (m015.value, m015.value),
        source: m015.id.clone(),
        role: role(m015),
        held_out: f64::NAN,
        u: nan4,
        model,
    };
    rows.push(m015_row("spin_ratio_polyester_over_nylon", (0..LAWS.len()).map(|l| ratio_of(&all, l)).collect()));
    let held = measured_ratio(&validation);
    rows.push(Compared {
        quantity: "spin_ratio_polyester_over_nylon_validation",
        string: "validation strings: polyester (3) / nylon (1)".into(),
        tension: Value::Text("52 and 62".into()),
        measured: held,
        unit: "ratio",
        spread: (held, held),
        source: "M005-M010, M013-M014".into(),
        role: Role::Validation.name(),
        held_out: f64::NAN,
        u: nan4,
        model: (0..LAWS.len()).map(|l| ratio_of(&validation, l)).collect(),
    });
    // the same ratio at the other reading of the angle (50 deg from the normal), beside it: not a
    // quantity of its own (the V&V budget takes the two readings as its u_angle)
    let at_50: Vec<Vec<f64>> =
        rows.iter().filter(|c| c.quantity == "spin_out_rpm_50deg").map(|c| c.model.clone()).collect();
    rows.push(m015_row(
        "spin_ratio_polyester_over_nylon:at_50deg",
        (0..LAWS.len())
            .map(|l| vv::poly_over_nylon(&table, &at_50.iter().map(|m| m[l]).collect::<Vec<_>>(), all))
            .collect(),
    ));
    // hand-held over head-clamped (M016)
    let m016 = &measured::rows(&["M016"])?[0];
    let mut model = Vec::new();
    for &l in &LAWS {
        let (hand, clamped) = shots::hand_and_clamped(ctx, l);
        model.push(spin_ratio(simulate(&hand)?.spin_out_rpm, simulate(&clamped)?.spin_out_rpm));
    }
    rows.push(Compared {
        quantity: "spin_out_ratio_handheld_over_clamped",
        string: "none".into(),
        tension: 60.0.into(),
        measured: m016.value,
        unit: "ratio",
        spread: (m016.value - 0.05, m016.value + 0.05),
        source: m016.id.clone(),
        role: role(m016),
        held_out: f64::NAN,
        u: nan4,
        model,
    });
    // the incidence beyond which the ball slides throughout (M029-M030: about 50 deg)
    let stop = &measured::rows(&["M030"])?[0];
    rows.push(Compared {
        quantity: "grip_regime_max_angle_from_normal",
        string: "none".into(),
        tension: 60.0.into(),
        measured: stop.value,
        unit: "deg",
        spread: (stop.value - 5.0, stop.value + 5.0),
        source: "M029, M030".into(),
        role: role(stop),
        held_out: f64::NAN,
        u: nan4,
        model: LAWS
            .iter()
            .map(|&l| shots::grip_stop_deg(&twu_shot(ctx, l, crate::params::StringName::None, 60.0)))
            .collect::<Result<_>>()?,
    });
    // a tour forehand: 30 m/s swing, 20 m/s ball, path 20 and 30 deg; measured the mean of the
    // three 2023 top-10 forehand spins (M052-M054), spread from the 1997 film's 1800 (M058) to
    // the largest player mean (M052)
    let fh = measured::rows(&["M052", "M053", "M054", "M058"])?;
    let fh_mean = compare::mean(&[fh[0].value, fh[1].value, fh[2].value]);
    for path in vv::PATHS_DEG {
        let mut model = Vec::new();
        for &l in &LAWS {
            let mut base = ctx.paper_params(super::CENTRE_X, crate::params::ks_from_tension_lb(60.0));
            base.oblique.tangential = l;
            model.push(shots::forehand_spin(&base, path)?);
        }
        rows.push(Compared {
            quantity: "forehand_spin_rpm",
            string: format!("none; swing path {path} deg"),
            tension: 60.0.into(),
            measured: fh_mean,
            unit: "rpm",
            spread: (fh[3].value, fh[0].value),
            source: "M052-M054, M058".into(),
            role: role(&fh[0]),
            held_out: f64::NAN,
            u: nan4,
            model,
        });
    }
    budget(ctx, law, d, &table, &fh, &mut rows)?;
    Ok(rows)
}

/// Fill in the default law's held-out values (the calibration's leave-one-string-out) and the
/// validation uncertainty's parts ([`vv`]).
fn budget(
    ctx: &Context,
    law: TangentialLaw,
    d: usize,
    table: &[Measured],
    fh: &[Measured],
    rows: &mut [Compared],
) -> Result<()> {
    let fit = super::spin_calibration::fit(ctx, law, &["kt"], shots::TWU_ANGLE_DEG, true)?;
    let kt = fit.estimates[0].interval;
    for c in rows.iter_mut().filter(|c| c.quantity == "spin_out_rpm") {
        if let Some(p) = fit.fitted.iter().find(|p| p.id == c.source) {
            c.held_out = p.held_out;
        }
    }
    // inputs, numerics: the outputs of vv::Shots, by index
    let inputs = vv::inputs(&twu_shot(ctx, law, crate::params::StringName::None, 60.0), kt);
    let modal = vv::Shots::new(ctx, law, table, SolverKind::Modal)?;
    let u_in = vv::u_input(&modal, table, &inputs)?;
    let at_modal = modal.outputs(table, &[], &[])?;
    let sigma = vv::table_scatter(table);
    let fifty: Vec<f64> = rows.iter().filter(|c| c.quantity == "spin_out_rpm_50deg").map(|c| c.model[d]).collect();
    for (k, c) in rows.iter_mut().filter(|c| c.quantity == "spin_out_rpm").enumerate() {
        c.u = [u_in[k], (c.model[d] - at_modal[k]).abs(), sigma, (fifty[k] - c.model[d]).abs() / 2.0];
    }
    let poly_nylon = |keep: &dyn Fn(&Measured) -> bool| {
        let count =
            |material: &str| table.iter().filter(|m| keep(m) && m.string.contains(&format!("({material})"))).count();
        let mean_of = |material: &str| {
            let v: Vec<f64> = table
                .iter()
                .filter(|m| keep(m) && m.string.contains(&format!("({material})")))
                .map(|m| m.value)
                .collect();
            compare::mean(&v)
        };
        ((mean_of("polyester"), count("polyester")), (mean_of("nylon"), count("nylon")))
    };
    for (quantity, index, keep) in [
        ("spin_ratio_polyester_over_nylon", vv::RATIO_ALL, &(|_: &Measured| true) as &dyn Fn(&Measured) -> bool),
        ("spin_ratio_polyester_over_nylon_validation", vv::RATIO_VALIDATION, &|m: &Measured| {
            m.role == Some(Role::Validation)
        }),
    ] {
        let fifty_ratio = vv::poly_over_nylon(table, &fifty, keep);
        if let Some(c) = rows.iter_mut().find(|c| c.quantity == quantity) {
            let (poly, nylon) = poly_nylon(keep);
            c.u = [
                u_in[index],
                (c.model[d] - at_modal[index]).abs(),
                vv::ratio_scatter(c.measured, sigma, poly, nylon),
                (fifty_ratio - c.model[d]).abs() / 2.0,
            ];
        }
    }
    if let Some(c) = rows.iter_mut().find(|c| c.quantity == "spin_out_ratio_handheld_over_clamped") {
        // the abstract states 40 deg from the normal: no second reading
        c.u = [u_in[vv::HAND_RATIO], (c.model[d] - at_modal[vv::HAND_RATIO]).abs(), 0.05, 0.0];
    }
    if let Some(c) = rows.iter_mut().find(|c| c.quantity == "grip_regime_max_angle_from_normal") {
        // a threshold over a scan of angles: inputs not propagated (f64::NAN), the scan's step
        c.u = [f64::NAN, 0.5, 5.0, 0.0];
    }
    let fh_sd = {
        let v = [fh[0].value, fh[1].value, fh[2].value];
        let m = compare::mean(&v);
        (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / 2.0).sqrt()
    };
    for (c, index) in rows.iter_mut().filter(|c| c.quantity == "forehand_spin_rpm").zip(vv::FOREHAND) {
        c.u = [u_in[index], (c.model[d] - at_modal[index]).abs(), fh_sd, 0.0];
    }
    Ok(())
}

fn run(ctx: &Context) -> Result<Table> {
    let rows = compared(ctx)?;
    let mut columns: Vec<&str> = COLUMNS.to_vec();
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
            Value::finite_or_empty(c.model[d]),
            Value::Text(c.unit.into()),
            c.spread.0.into(),
            c.spread.1.into(),
            Value::Text(c.source.clone()),
            Value::Text(c.role.into()),
            Value::finite_or_empty(c.held_out),
        ];
        row.extend(c.u.iter().map(|&u| Value::finite_or_empty(u)));
        row.push(Value::finite_or_empty(c.u_val()));
        row.extend(c.model.iter().map(|&v| Value::finite_or_empty(v)));
        t.push(row)?;
    }
    // the summaries: per quantity the RMS and the worst error (measured 0: no error)
    let mut quantities: Vec<&str> = Vec::new();
    for c in &rows {
        if !quantities.contains(&c.quantity) {
            quantities.push(c.quantity);
        }
    }
    let summary = |name: String, ideal: f64, unit: &str, source: String, f: &dyn Fn(usize) -> f64| {
        let mut row = vec![
            Value::Text(name),
            Value::Text("all".into()),
            Value::Text("all".into()),
            ideal.into(),
            Value::finite_or_empty(f(d)),
            Value::Text(unit.into()),
            ideal.into(),
            ideal.into(),
            Value::Text(source),
            Value::Text(String::new()),
        ];
        row.extend([f64::NAN; 6].map(Value::finite_or_empty));
        row.extend((0..LAWS.len()).map(|l| Value::finite_or_empty(f(l))));
        row
    };
    for q in quantities {
        let of: Vec<&Compared> = rows.iter().filter(|c| c.quantity == q).collect();
        let source = of.iter().map(|c| c.source.as_str()).collect::<Vec<_>>().join(" ");
        let unit = of[0].unit;
        t.push(summary(format!("{q}:rms_error"), 0.0, unit, source.clone(), &|l| rms_error(&of, l)))?;
        t.push(summary(format!("{q}:worst_error"), 0.0, unit, source, &|l| worst_error(&of, l)))?;
    }
    // the rank correlation of the table points under each reading of the angle, with its
    // two-sided p-value: over all 14, and over the 8 validation points
    for q in ["spin_out_rpm", "spin_out_rpm_50deg"] {
        for (suffix, keep) in [("", false), ("_validation", true)] {
            let of: Vec<&Compared> =
                rows.iter().filter(|c| c.quantity == q && (!keep || c.role == Role::Validation.name())).collect();
            let source = if keep { "M005-M010, M013-M014" } else { "M001-M014" };
            t.push(summary(format!("{q}:rank_correlation{suffix}"), 1.0, "1", source.into(), &|l| rank(&of, l).0))?;
            t.push(summary(format!("{q}:rank_correlation{suffix}_p"), 0.0, "1", source.into(), &|l| rank(&of, l).1))?;
        }
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let points = t.filter("quantity", "spin_out_rpm");
    let measured = super::col(&points, "measured");
    let lo = super::col(&points, "spread_lo").into_iter().fold(f64::MAX, f64::min);
    let hi = super::col(&points, "spread_hi").into_iter().fold(f64::MIN, f64::max);
    let d = Oblique::default().tangential;
    let mut curves = vec![Curve::new("model = measured", vec![1000.0, 2000.0], vec![1000.0, 2000.0])
        .with_style(LineStyle::Dashed)
        .with_color(0)];
    for (i, law) in LAWS.iter().enumerate() {
        let y = super::col(&points, &format!("model_{}", law.name()));
        let style = if *law == d { LineStyle::Paper } else { LineStyle::Points };
        let mut label = format!("{} law", law.name());
        if *law == d {
            label.push_str(" (the default)");
        }
        curves.push(Curve::new(label, measured.clone(), y).with_style(style).with_color(i + 1));
    }
    // the default law's calibration rows held out (each string refitted without it)
    let held = super::col(&points, "model_held_out");
    let (hx, hy): (Vec<f64>, Vec<f64>) =
        measured.iter().zip(&held).filter(|(_, h)| h.is_finite()).map(|(m, h)| (*m, *h)).unzip();
    curves.push(
        Curve::new(format!("{} law, calibration strings held out", d.name()), hx, hy)
            .with_style(LineStyle::Points)
            .with_color(LAWS.len() + 2),
    );
    // the other reading of the angle, under the default law
    let fifty = t.filter("quantity", "spin_out_rpm_50deg");
    curves.push(
        Curve::new(
            format!("{} law at 50 deg (the angle read from the string plane)", d.name()),
            super::col(&fifty, "measured"),
            super::col(&fifty, &format!("model_{}", d.name())),
        )
        .with_style(LineStyle::Points)
        .with_color(LAWS.len() + 1),
    );
    // the y range from the points drawn (the laws' spread), with room for the legend above
    let ys: Vec<f64> = curves.iter().skip(1).flat_map(|c| c.y.iter().copied()).filter(|v| v.is_finite()).collect();
    let (ylo, yhi) =
        (ys.iter().copied().fold(f64::INFINITY, f64::min), ys.iter().copied().fold(f64::NEG_INFINITY, f64::max));
    let span = yhi - ylo;
    let y_range = ((ylo - 0.05 * span).max(0.0), yhi + 0.9 * span);
    // the line model = measured within both ranges
    let (a, b) = (y_range.0.max(1000.0), y_range.1.min(2000.0));
    curves[0].x = vec![a, b];
    curves[0].y = vec![a, b];
    Chart {
        title: "TWU spin table (7 strings x 52/62 lb): model against measured, each tangential law (40 deg)".into(),
        x_label: "measured outgoing spin (rpm); clamped racket, 25 m/s, 40 deg, 3820 rpm backspin in".into(),
        y_label: "model outgoing spin (rpm)".into(),
        y2_label: None,
        x_log: false,
        x_range: Some((1000.0, 2000.0)),
        y_range: Some(y_range),
        y2_range: None,
        curves,
        bands: vec![Band::new(lo, hi, "measured spread over the seven strings")],
        vlines: vec![],
        ..Chart::default()
    }
}
