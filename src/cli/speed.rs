//! `speed`: the outgoing ball speed for a swing and an incoming ball, compared across string
//! tensions or rackets.

use clap::Args;
use racket_impact::command::speed::Speed;
use racket_impact::command::{execute, Control};
use racket_impact::Result;

use super::common::{out, print_diagnostics, Common, Format};
use super::options::{Options, SpeedOptions};
use super::overrides::SpeedKeys;

#[derive(Args, Debug)]
pub struct SpeedArgs {
    #[command(flatten)]
    pub common: Common<SpeedKeys>,
    #[command(flatten)]
    pub options: Options<SpeedOptions>,
}

/// Run the comparison and print it in the chosen format.
pub fn run(a: SpeedArgs) -> Result<()> {
    let comparison = execute(Speed::new(&a.common.sources(), &a.options.0)?, &Control::new())?;
    let text = match a.common.format {
        Format::Csv => comparison.table()?.to_csv(),
        Format::Json => comparison.json()?,
        Format::Text => comparison.text(),
    };
    out!("{text}");
    // (the impact speed, incidence and spin come from this command's options: said in them)
    print_diagnostics(&comparison.diagnostics());
    Ok(())
}
