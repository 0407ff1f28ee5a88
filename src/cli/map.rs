//! `map`: a quantity over the string face, one impact per grid point, written as CSV, PNG and
//! JSON and summarised on standard output.

use std::path::PathBuf;

use clap::Args;
use racket_impact::command::map::Map;
use racket_impact::command::{execute, Control};
use racket_impact::render::map_files::Outputs;
use racket_impact::Result;

use super::common::{elapsed_line, out, outln, print_diagnostics, warn, Common, Format, Reporter};
use super::options::{MapOptions, Options};
use super::overrides::MapKeys;

#[derive(Args, Debug)]
pub struct MapArgs {
    #[command(flatten)]
    pub common: Common<MapKeys>,
    #[command(flatten)]
    pub options: Options<MapOptions>,
    /// Output CSV; the PNG and JSON go next to it with the same stem (a symbolic link: its
    /// target is written, the link kept, and the PNG and JSON go next to the target, with its stem)
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
}

/// Check, compute, write the three files, then print the chosen format.
pub fn run(a: MapArgs) -> Result<()> {
    // (the inputs read first: no output may be one of them)
    let request = Map::new(&a.common.sources(), &a.options.0)?;
    let total = request.total;
    let default_out = a.out.is_none();
    let outputs = Outputs::for_csv(&a.out.unwrap_or_else(|| request.request.default_csv()))?;
    super::common::check_stdout()?;
    let replaced = default_out && [&outputs.csv, &outputs.png, &outputs.json].iter().any(|p| p.exists());
    let ctl = Control::new();
    let reporter = Reporter::start(&ctl);
    let started = std::time::Instant::now();
    let computed = execute(request, &ctl);
    drop(reporter);
    let racket_impact::command::map::Mapped { map, diagnostics } = computed?;
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
                outln!("wrote {csv}, {}, {}", outputs.png.display(), outputs.json.display());
            }
            Format::Json => out!("{json}"),
            Format::Csv => out!("{csv}"),
        }
        Ok(())
    })?;
    print_diagnostics(&diagnostics);
    if replaced {
        // (without --out the files go into the current folder under a name of the quantity)
        warn(&format!(
            "replaced {}, {} and {} of an earlier map in this folder (--out FILE.csv names them)",
            outputs.csv.display(),
            outputs.png.display(),
            outputs.json.display()
        ));
    }
    // (the time on standard error: the same map twice prints the same standard output)
    elapsed_line(&format!("map: {total} impacts in {:.2} s", started.elapsed().as_secs_f64()));
    Ok(())
}
