//! `racket`: fit a racket description (file or preset) to the model and show the match.

use clap::Args;
use racket_impact::params::{self, spec::sig};
use racket_impact::racket::{self, Fitted};
use racket_impact::{Error, Result};

use super::common::{out, outln, warn_params, Format};

#[derive(Args, Debug)]
pub struct RacketArgs {
    /// Racket description file (TOML, player units) or preset name
    pub racket: Option<String>,
    /// List the presets and exit
    #[arg(long)]
    pub list: bool,
    /// Number of beam segments the fit is made for (4..=400)
    #[arg(long, default_value_t = 39)]
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
        return list(a.segments);
    }
    let Some(arg) = a.racket.as_deref() else {
        return Err(Error::invalid("racket", "(missing)", "give a racket file or preset name, or --list"));
    };
    let fitted = racket::load(arg)?.to_racket(a.segments)?;
    // the same warnings as the impact commands give for this racket (unusual values, frequency,
    // density), at the face centre with the default numerics on the fit's segments
    let numerics = params::Numerics { segments: a.segments, ..Default::default() };
    let mut p = fitted.params(params::Impact::default(), numerics);
    params::keys::face_centre_impact(&mut p);
    warn_params([&p]);
    let text = match a.format {
        Format::Text => text(&fitted),
        Format::Csv => fitted.report.table().to_csv(),
        Format::Json => json(&fitted)?,
    };
    out!("{text}");
    Ok(())
}

/// One line per preset, fitted for `segments` segments.
fn list(segments: usize) -> Result<()> {
    for name in racket::preset_names() {
        let fitted = racket::load(name)?.to_racket(segments)?;
        let (r, rep) = (&fitted.racket, &fitted.report);
        outln!(
            "{name:<22} {:.1} cm, {:.0} g, balance {:.1} cm, swingweight {:.0} kg cm^2, twistweight {:.1} kg cm^2, f1 {:.0} Hz, ks {:.0} N/m{}",
            100.0 * r.length,
            1e3 * r.mass,
            rep.balance_cm.model,
            rep.swingweight_kg_cm2.model,
            rep.twistweight_kg_cm2.model,
            rep.frequency_hz.model,
            fitted.strings.ks,
            if r.profile.is_none() { ", uniform (the paper's beam)" } else { "" }
        );
    }
    Ok(())
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

/// The fit report's rows as objects, with the model's racket, strings and ball.
fn json(fitted: &Fitted) -> Result<String> {
    let t = fitted.report.table();
    let rows: Vec<serde_json::Value> = t
        .rows
        .iter()
        .map(|row| {
            let obj: serde_json::Map<String, serde_json::Value> = t
                .columns
                .iter()
                .zip(row)
                .map(|(c, v)| (c.clone(), serde_json::Value::String(v.to_csv_field())))
                .collect();
            serde_json::Value::Object(obj)
        })
        .collect();
    let v = serde_json::json!({ "fit": rows, "racket": fitted.racket, "strings": fitted.strings, "ball": fitted.ball });
    Ok(format!("{}\n", serde_json::to_string_pretty(&v).map_err(|e| Error::io("<json>", e))?))
}
