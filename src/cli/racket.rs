//! `racket`: fit a racket description (file or preset) to the model and show the match.

use clap::Args;
use racket_impact::numfmt::sig;
use racket_impact::params;
use racket_impact::racket::{self, Fitted};
use racket_impact::{Error, Result};

use super::common::{diagnostics_json, out, outln, print_diagnostics, Format};

#[derive(Args, Debug)]
pub struct RacketArgs {
    /// Racket description file (TOML, player units) or preset name
    pub racket: Option<String>,
    /// List the presets and exit
    #[arg(long)]
    pub list: bool,
    /// Number of beam segments N (4..=400): the beam the fit is made for
    #[arg(long, default_value_t = params::Numerics::default().segments, help_heading = params::keys::SEGMENTS.heading.title())]
    pub segments: usize,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

/// List the presets, or fit one racket and show how well it matches.
pub fn run(a: RacketArgs) -> Result<()> {
    if a.list {
        if let Some(arg) = &a.racket {
            return Err(Error::invalid("racket", arg, "--list lists every preset: give a racket or --list, not both"));
        }
        return list(a.segments, a.format);
    }
    let Some(arg) = a.racket.as_deref() else {
        return Err(Error::invalid("racket", "(missing)", "give a racket file or preset name, or --list"));
    };
    let fitted = racket::load(arg)?.to_racket(a.segments)?;
    let diagnostics = racket_impact::intake::diagnose::racket(&fitted, a.segments);
    print_diagnostics(&diagnostics);
    let text = match a.format {
        Format::Text => text(&fitted),
        Format::Csv => fitted.report.table().to_csv(),
        Format::Json => json(&fitted, &diagnostics)?,
    };
    out!("{text}");
    Ok(())
}

/// The presets, fitted for `segments` segments: one line each as text, or a table as CSV or
/// JSON (one object per preset).
fn list(segments: usize, format: Format) -> Result<()> {
    use racket_impact::render::table::Value;
    let table = racket::presets_table(segments)?;
    match format {
        Format::Csv => out!("{}", table.to_csv()),
        Format::Json => out!("{}", table_json(&table, &[])?),
        Format::Text => {
            for row in &table.rows {
                let v = |i: usize| if let Value::Num(x) = row[i] { x } else { f64::NAN };
                outln!(
                    "{:<22} {:.1} cm, {:.0} g, balance {:.1} cm, swingweight {:.0} kg cm^2, twistweight {:.1} kg cm^2, f1 {:.0} Hz, ks {:.0} N/m{}",
                    row[0].to_csv_field(),
                    v(1),
                    v(2),
                    v(3),
                    v(4),
                    v(5),
                    v(6),
                    v(7),
                    if row[8].to_csv_field() == "uniform" { ", uniform (the paper's beam)" } else { "" }
                );
            }
        }
    }
    Ok(())
}

/// A table's rows as JSON objects (`{"<table name>": [...]}` plus `extra` members), pretty-printed.
fn table_json(t: &racket_impact::render::table::Table, extra: &[(&str, serde_json::Value)]) -> Result<String> {
    use racket_impact::render::table::Value;
    // an empty cell of a numeric column (a check without a target) is null, not ""
    let numeric: Vec<bool> =
        (0..t.columns.len()).map(|k| t.rows.iter().any(|r| matches!(r.get(k), Some(Value::Num(_))))).collect();
    let rows: Vec<serde_json::Value> = t
        .rows
        .iter()
        .map(|row| {
            let obj: serde_json::Map<String, serde_json::Value> = t
                .columns
                .iter()
                .zip(row)
                .zip(&numeric)
                .map(|((c, v), &numeric)| {
                    let value = match v {
                        Value::Num(x) => serde_json::json!(x),
                        Value::Int(i) => serde_json::json!(i),
                        Value::Text(s) if s.is_empty() && numeric => serde_json::Value::Null,
                        Value::Text(s) => serde_json::json!(s),
                    };
                    (c.clone(), value)
                })
                .collect();
            serde_json::Value::Object(obj)
        })
        .collect();
    let mut v = serde_json::json!({ t.name.as_str(): rows });
    for (k, x) in extra {
        v[*k] = x.clone();
    }
    racket_impact::render::json::pretty(&v)
}

/// The fit report and the model's values.
fn text(fitted: &Fitted) -> String {
    let r = &fitted.racket;
    let mut s = format!("{}\n", fitted.report);
    s.push_str(&format!(
        "model: L = {} m, M = {} kg, EI = {} N m^2{}, Ix = {} kg m^2, ks = {} N/m, ball {} kg\n",
        sig(r.length, 6),
        sig(r.mass, 6),
        sig(r.ei, 6),
        if r.profile.is_some() { " (times the stiffness profile)" } else { "" },
        sig(r.ix, 6),
        sig(fitted.strings.ks, 6),
        sig(fitted.ball.mass, 6)
    ));
    if let Some(h) = r.head_length {
        s.push_str(&format!(
            "string face: ellipse {:.1} cm x {:.1} cm from the tip\n",
            100.0 * h,
            200.0 * r.half_width
        ));
    }
    s
}

/// The fit report's rows as objects (numbers as numbers), with the model's racket, strings and
/// ball.
fn json(fitted: &Fitted, diagnostics: &[racket_impact::diagnostic::Diagnostic]) -> Result<String> {
    let mut t = fitted.report.table();
    t.name = "fit".to_string();
    let value = |v: serde_json::Result<serde_json::Value>| v.map_err(|e| Error::io("<json>", e));
    table_json(
        &t,
        &[
            ("racket", value(serde_json::to_value(fitted.racket))?),
            ("strings", value(serde_json::to_value(fitted.strings))?),
            ("ball", value(serde_json::to_value(fitted.ball))?),
            ("diagnostics", diagnostics_json(diagnostics)?),
        ],
    )
}
