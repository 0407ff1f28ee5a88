//! `card`: what string tension does to one racket, in one picture and one table.

use std::path::PathBuf;

use clap::Args;
use racket_impact::command::card::CardCommand;
use racket_impact::command::{execute, Control};
use racket_impact::render::map_files::Outputs;
use racket_impact::Result;

use super::common::{elapsed_line, out, outln, print_diagnostics, Common, Format, Reporter};
use super::options::{CardOptions, Options};
use super::overrides::CardKeys;

#[derive(Args, Debug)]
pub struct CardArgs {
    #[command(flatten)]
    pub common: Common<CardKeys>,
    #[command(flatten)]
    pub options: Options<CardOptions>,
    /// Output CSV (default card.csv); the PNG goes next to it with the same stem
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
}

/// Check, estimate, compute, write the two files, then print the chosen format.
pub fn run(a: CardArgs) -> Result<()> {
    let request = CardCommand::new(&a.common.sources(), &a.options.0)?;
    // (the inputs read first: no output may be one of them)
    let outputs = Outputs::for_csv_of(
        &a.out.unwrap_or_else(|| PathBuf::from("card.csv")),
        "the card's CSV file (its PNG goes next to it with the same stem), e.g. card.csv",
        "a card is two files (CSV and PNG with the same stem): give a file path, not a device or pipe \
         (--format csv prints the table)",
    )?;
    super::common::check_stdout()?;
    let total = request.prepared.impacts()?;
    let ctl = Control::new();
    let started = std::time::Instant::now();
    let reporter = Reporter::start(&ctl);
    let computed = execute(request, &ctl);
    drop(reporter);
    let card = computed?;
    let csv = card.csv()?;
    let mut staged = racket_impact::render::io::Staged::new();
    staged.bytes(&outputs.csv, csv.as_bytes())?;
    racket_impact::render::plot::sheet::stage_sheet(&mut staged, "card", &card.sheet()?, &outputs.png)?;
    let text = match a.common.format {
        Format::Text => card.summary()?,
        Format::Json => card.json()?,
        Format::Csv => csv.clone(),
    };
    staged.publish(|| {
        out!("{text}");
        if a.common.format == Format::Text {
            outln!("wrote {}, {}", outputs.csv.display(), outputs.png.display());
        }
        Ok(())
    })?;
    print_diagnostics(&card.diagnostics);
    // (the time on standard error: the same card twice prints the same standard output)
    elapsed_line(&format!("card: {total} impacts in {:.2} s", started.elapsed().as_secs_f64()));
    Ok(())
}
