//! `report`: the paper's numbers beside ours, written to REPORT.md and printed.

use std::path::PathBuf;

use clap::Args;
use racket_impact::Result;

use super::common::out;

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Where to write the Markdown report
    #[arg(long, default_value = "REPORT.md")]
    pub out: PathBuf,
    /// Print the report without writing the file
    #[arg(long)]
    pub no_write: bool,
}

/// Write REPORT.md (unless told not to) and print it.
pub fn run(a: ReportArgs) -> Result<()> {
    if !a.no_write {
        racket_impact::render::io::check_output_dir("out", &a.out)?;
    }
    let rows = racket_impact::report::evaluate()?;
    let md = racket_impact::report::document(&rows)?;
    // REPORT.md is published only once the report has been printed
    let mut staged = racket_impact::render::io::Staged::new();
    if !a.no_write {
        staged.bytes(&a.out, md.as_bytes())?;
    }
    out!("{md}");
    staged.commit()?;
    Ok(())
}
