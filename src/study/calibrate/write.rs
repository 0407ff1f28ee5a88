//! A calibration's outputs: the text summary, the JSON document and the chart of model against
//! measured (held-out and judged points marked).

use serde_json::json;

use super::{Calibration, HoldOut, Prediction, Weights};
use crate::numfmt::sig;
use crate::render::plot::{Chart, Curve, LineStyle};

/// `v` to `digits` significant digits, or `-` where it is not a number.
fn num(v: f64, digits: usize) -> String {
    if v.is_finite() {
        sig(v, digits)
    } else {
        "-".into()
    }
}

/// What the rows are called in the summaries.
fn hold_out_words(h: HoldOut) -> &'static str {
    match h {
        HoldOut::String => "leave-one-string-out",
        HoldOut::Row => "leave-one-row-out",
        HoldOut::None => "no hold-out",
    }
}

/// The plain-text summary: the fit, each parameter's value, interval and verdict, the
/// correlation, the in-sample and held-out errors, each row, the judged rows.
pub fn text(c: &Calibration, source: &str, weights: Weights) -> String {
    let unit = c.fitted.first().map_or(String::new(), |p| p.unit.trim().to_string());
    let mut s = format!(
        "calibrate: {} rows fitted of {source} ({}), tangential law {}, {} solver, {} impacts\n",
        c.fitted.len(),
        match weights {
            Weights::None => format!("least squares in {unit}"),
            Weights::Uncertainty => "residuals over each row's stated uncertainty".to_string(),
        },
        c.tangential.name(),
        c.solver.name(),
        c.impacts
    );
    s.push_str(&format!(
        "{:<22} {:>12} {:>12} {:>12}  {:<6}  verdict\n",
        "parameter", "value", "95 % lo", "95 % hi", "unit"
    ));
    for e in &c.estimates {
        let end = |v: f64, open: bool| if open { format!("({})", num(v, 4)) } else { num(v, 4) };
        s.push_str(&format!(
            "{:<22} {:>12} {:>12} {:>12}  {:<6}  {}\n",
            e.key,
            num(e.value, 5),
            end(e.interval.0, e.open.0),
            end(e.interval.1, e.open.1),
            e.unit,
            e.identifiable.sentence()
        ));
    }
    if c.estimates.iter().any(|e| e.open.0 || e.open.1) {
        s.push_str(
            "(an end in parentheses is the end of the range searched: the rows do not bound the parameter there)\n",
        );
    }
    if c.estimates.len() > 1 {
        s.push_str("correlation:\n");
        for (e, row) in c.estimates.iter().zip(&c.correlation) {
            let cells: Vec<String> = row.iter().map(|v| format!("{:>7}", num(*v, 3))).collect();
            s.push_str(&format!("  {:<20} {}\n", e.key, cells.join(" ")));
        }
    }
    let held = match c.hold_out {
        HoldOut::None => String::new(),
        h => format!("; {} {} {unit}", hold_out_words(h), num(c.rms_held_out(), 4)),
    };
    s.push_str(&format!("RMS error: in-sample {} {unit}{held}\n", num(c.rms_in_sample(), 4)));
    s.push_str(&format!(
        "{:<8} {:<34} {:>10} {:>10} {:>10} {:>10}\n",
        "row", "group", "measured", "model", "held out", "error"
    ));
    for p in &c.fitted {
        s.push_str(&row_line(p, p.held_out));
    }
    if !c.judged.is_empty() {
        let judged_unit = c.judged.first().map_or(String::new(), |p| p.unit.trim().to_string());
        s.push_str(&format!(
            "validation rows (not fitted): {} judged, RMS error {} {judged_unit}\n",
            c.judged.len(),
            num(c.rms_judged(), 4)
        ));
        for p in &c.judged {
            s.push_str(&row_line(p, f64::NAN));
        }
    }
    if !c.skipped.is_empty() {
        let ids: Vec<&str> = c.skipped.iter().map(|(id, _)| id.as_str()).collect();
        s.push_str(&format!(
            "{} validation rows are not one impact the model can run (not judged): {}\n",
            ids.len(),
            ids.join(" ")
        ));
    }
    s
}

/// One row of the text table.
fn row_line(p: &Prediction, held: f64) -> String {
    let group: String = p.group.chars().take(34).collect();
    format!(
        "{:<8} {:<34} {:>10} {:>10} {:>10} {:>10}\n",
        p.id,
        group,
        num(p.measured, 5),
        num(p.model, 5),
        num(held, 5),
        num(p.model - p.measured, 4)
    )
}

/// A row as JSON (a non-finite number as null).
fn row_json(p: &Prediction) -> serde_json::Value {
    let n = |v: f64| if v.is_finite() { json!(v) } else { serde_json::Value::Null };
    json!({
        "id": p.id, "group": p.group, "quantity": p.quantity, "unit": p.unit,
        "measured": n(p.measured), "model": n(p.model), "held_out": n(p.held_out),
        "error": n(p.model - p.measured), "held_out_error": n(p.held_out - p.measured),
    })
}

/// The JSON document.
pub fn json(c: &Calibration, source: &str, weights: Weights) -> serde_json::Value {
    let n = |v: f64| if v.is_finite() { json!(v) } else { serde_json::Value::Null };
    let params: Vec<serde_json::Value> = c
        .estimates
        .iter()
        .map(|e| {
            json!({
                "key": e.key, "unit": e.unit, "value": n(e.value),
                "range": [e.range.0, e.range.1],
                "interval_95": [n(e.interval.0), n(e.interval.1)],
                "interval_open": [e.open.0, e.open.1],
                "identifiable": e.identifiable.name(),
                "identifiable_sentence": e.identifiable.sentence(),
            })
        })
        .collect();
    let correlation: Vec<Vec<serde_json::Value>> =
        c.correlation.iter().map(|r| r.iter().map(|&v| n(v)).collect()).collect();
    json!({
        "source": source,
        "weights": match weights { Weights::None => "none", Weights::Uncertainty => "uncertainty" },
        "hold_out": c.hold_out.name(),
        "tangential": c.tangential.name(),
        "solver": c.solver.name(),
        "impacts": c.impacts,
        "ssr": n(c.ssr),
        "params": params,
        "correlation": correlation,
        "rms_in_sample": n(c.rms_in_sample()),
        "rms_held_out": n(c.rms_held_out()),
        "rms_validation": n(c.rms_judged()),
        "rms_unit": c.fitted.first().or(c.judged.first()).map_or(String::new(), |p| p.unit.trim().to_string()),
        "fitted": c.fitted.iter().map(row_json).collect::<Vec<_>>(),
        "validation": c.judged.iter().map(row_json).collect::<Vec<_>>(),
        "skipped": c.skipped.iter().map(|(id, why)| json!({"id": id, "reason": why})).collect::<Vec<_>>(),
    })
}

/// Model against measured: the fitted rows at the fit, each again as predicted without its
/// group (held out), the validation rows, and the line model = measured.
pub fn chart(c: &Calibration, source: &str) -> Chart {
    let unit = c.fitted.first().map_or(String::new(), |p| p.unit.trim().to_string());
    let all: Vec<&Prediction> = c.fitted.iter().chain(&c.judged).collect();
    let values: Vec<f64> =
        all.iter().flat_map(|p| [p.measured, p.model, p.held_out]).filter(|v| v.is_finite()).collect();
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let pad = 0.05 * (hi - lo).max(hi.abs() * 1e-3).max(1e-12);
    let range = (lo - pad, hi + pad);
    let xy = |ps: &[Prediction], model: fn(&Prediction) -> f64| -> (Vec<f64>, Vec<f64>) {
        ps.iter().filter(|p| model(p).is_finite()).map(|p| (p.measured, model(p))).unzip()
    };
    let mut curves =
        vec![Curve::new("model = measured", vec![range.0, range.1], vec![range.0, range.1])
            .with_style(LineStyle::Dashed)];
    let (x, y) = xy(&c.fitted, |p| p.model);
    curves.push(
        Curve::new(format!("fitted rows, at the fit ({})", x.len()), x, y).with_style(LineStyle::Points).with_color(1),
    );
    let (x, y) = xy(&c.fitted, |p| p.held_out);
    if !x.is_empty() {
        curves.push(
            Curve::new(format!("the same rows held out ({}, refitted without)", hold_out_words(c.hold_out)), x, y)
                .with_style(LineStyle::Paper)
                .with_color(2),
        );
    }
    let (x, y) = xy(&c.judged, |p| p.model);
    if !x.is_empty() {
        curves.push(
            Curve::new(format!("validation rows, not fitted ({})", x.len()), x, y)
                .with_style(LineStyle::Points)
                .with_color(3),
        );
    }
    let names: Vec<String> = c.estimates.iter().map(|e| format!("{} = {}", e.key, num(e.value, 3))).collect();
    Chart {
        title: format!("calibrate: {} ({})", source, names.join(", ")),
        x_label: format!("measured ({unit})"),
        y_label: format!("model ({unit})"),
        x_range: Some(range),
        y_range: Some(range),
        curves,
        ..Chart::default()
    }
}
