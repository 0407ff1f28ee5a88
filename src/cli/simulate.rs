//! `simulate`: one impact, as text, JSON or CSV, with an optional time series.

use std::path::PathBuf;

use clap::Args;
use racket_impact::command::simulate::Simulate;
use racket_impact::command::{execute, Control};
use racket_impact::Result;

use super::common::{out, print_diagnostics, Common, Format};
use super::options::{Options, SimulateOptions};
use super::overrides::SimulateKeys;

#[derive(Args, Debug)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub common: Common<SimulateKeys>,
    /// Also write the impact's time series (t, F, y_b, Y_T, theta, every energy term) as CSV
    #[arg(long, help_heading = "Output")]
    pub series: Option<PathBuf>,
    #[command(flatten)]
    pub options: Options<SimulateOptions>,
}

/// One impact; fail early, before any computation, when an output file's directory does not
/// exist.
pub fn run(a: SimulateArgs) -> Result<()> {
    let mut given = a.options.0.clone();
    if a.series.is_some() {
        given.set("series", "true")?;
    }
    let request = Simulate::new(&a.common.sources(), &given)?;
    if let Some(path) = &a.series {
        racket_impact::render::io::check_output_dir("series", path)?;
    }
    let done = execute(request, &Control::new())?;
    let single = &done.single;
    let text = match a.common.format {
        Format::Json => racket_impact::render::json::pretty(&single.json()?)?,
        Format::Csv => racket_impact::render::impact::result_csv(&single.params, &single.result),
        Format::Text => racket_impact::render::impact::result_text(&single.params, &single.result),
    };
    // a series device is written before the result is printed, a series file renamed after
    let mut staged = racket_impact::render::io::Staged::new();
    if let (Some(path), Some(rows)) = (&a.series, &done.series) {
        racket_impact::render::impact::stage_series(&mut staged, path, &single.params, rows)?;
    }
    staged.publish(|| {
        out!("{text}");
        Ok(())
    })?;
    print_diagnostics(&single.diagnostics);
    Ok(())
}
