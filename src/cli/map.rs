//! `map`: a quantity over the string face, one impact per grid point, written as CSV, PNG and
//! JSON and summarised on standard output.

use std::path::PathBuf;

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use clap::Args;
use racket_impact::render::map_files::Outputs;
use racket_impact::study::map::{MapRequest, Quantity};
use racket_impact::Result;

use super::common::{out, outln, print_diagnostics, Common, Format, Progress};
use super::overrides::MapKeys;

/// What each quantity is, in the help.
fn quantity_help(q: Quantity) -> &'static str {
    match q {
        Quantity::EA => "apparent coefficient of restitution e_A",
        Quantity::Tau => "impact duration, ms",
        Quantity::Theta => "twist at the end of the impact, degrees",
        Quantity::FVib => "vibration energy, fraction of the ball's incident KE",
        Quantity::Power => "power potential 100 e_A, %",
        Quantity::Spin => "outgoing spin, rpm (oblique or spinning ball)",
        Quantity::ReboundAngle => "rebound angle from the normal, degrees (oblique or spinning ball)",
    }
}

/// `--quantity`: the quantities' names, with their help.
fn quantity_parser() -> impl TypedValueParser<Value = Quantity> {
    PossibleValuesParser::new(Quantity::every().map(|q| PossibleValue::new(q.name()).help(quantity_help(q))))
        .try_map(|name| name.parse::<Quantity>())
}

#[derive(Args, Debug)]
pub struct MapArgs {
    #[command(flatten)]
    pub common: Common<MapKeys>,
    /// The quantity shown in the heat map (the CSV has every one)
    #[arg(long, value_parser = quantity_parser(), default_value = "power")]
    pub quantity: Quantity,
    /// Grid points along the racket, from the tip to the end of the face (2..=401)
    #[arg(long, default_value_t = 41, allow_hyphen_values = true)]
    pub nx: usize,
    /// Grid points across the face, from -half-width to +half-width (2..=401)
    #[arg(long, default_value_t = 21, allow_hyphen_values = true)]
    pub nr: usize,
    /// Output CSV; the PNG and JSON go next to it with the same stem (a symbolic link: its
    /// target is written, the link kept, and the PNG and JSON go next to the target, with its stem)
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
    /// Difference map against this racket (file or preset): B - A with A = --racket
    #[arg(long, conflicts_with = "compare_tension_lb")]
    pub compare_racket: Option<String>,
    /// Difference map between string tensions, lb: T (A = the configuration as given, B = at T)
    /// or T1,T2 (A at T1, B at T2); k_s = 4e4 N/m * T / 60 lb
    #[arg(long, value_parser = super::common::number, value_delimiter = ',', allow_hyphen_values = true)]
    pub compare_tension_lb: Vec<f64>,
}

/// Check, compute, write the three files, then print the chosen format.
pub fn run(a: MapArgs) -> Result<()> {
    let mut sources = a.common.sources();
    if a.compare_tension_lb.len() >= 2 {
        sources.set_by_options.extend(racket_impact::intake::compare::TENSION_SETS);
    }
    let request = MapRequest {
        sources: sources.clone(),
        quantity: a.quantity,
        nx: a.nx,
        nr: a.nr,
        compare_racket: a.compare_racket,
        compare_tension_lb: a.compare_tension_lb,
    };
    request.check()?;
    // (the inputs read first: no output may be one of them)
    let (configs, total) = request.configurations()?;
    let outputs = Outputs::for_csv(&a.out.unwrap_or_else(|| request.default_csv()))?;
    super::common::check_stdout()?;
    let noted = request.check_used(&configs)?;

    let bar = Progress::new(total as u64);
    let started = bar.started;
    let computed = request.run(&configs, &mut |done| bar.update(done));
    drop(bar);
    let map = computed?;
    let json = map.json()?;
    let csv = map.table.to_csv();
    // the files are published only once the printing has succeeded (nothing left otherwise);
    // a device among them is written before the printing
    let staged = outputs.stage(&csv, &map.heatmap, &json)?;
    staged.publish(|| {
        match a.common.format {
            Format::Text => {
                out!("{}", map.summary);
                let csv = match &outputs.csv_target {
                    Some(target) => format!("{} (a link to {})", outputs.csv.display(), target.display()),
                    None => outputs.csv.display().to_string(),
                };
                outln!(
                    "wrote {csv}, {}, {} ({:.2} s)",
                    outputs.png.display(),
                    outputs.json.display(),
                    started.elapsed().as_secs_f64()
                );
            }
            Format::Json => out!("{json}"),
            Format::Csv => out!("{csv}"),
        }
        Ok(())
    })?;
    print_diagnostics(noted.iter().chain(&map.diagnostics(configs.iter().map(|(_, p)| p))));
    Ok(())
}
