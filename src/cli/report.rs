//! `report`: the paper's numbers beside ours, written to REPORT.md and printed.

use std::path::PathBuf;

use clap::Args;
use racket_impact::Result;

use super::common::out;

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Where to write the Markdown report [default: REPORT.md]
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the report without writing the file
    #[arg(long)]
    pub no_write: bool,
}

/// Write REPORT.md (unless told not to) and print it.
pub fn run(a: ReportArgs) -> Result<()> {
    if let (true, Some(out)) = (a.no_write, &a.out) {
        return Err(racket_impact::Error::invalid(
            "out",
            out.display(),
            "--no-write writes no file: give --out or --no-write",
        ));
    }
    let out = a.out.unwrap_or_else(|| PathBuf::from("REPORT.md"));
    if !a.no_write {
        racket_impact::render::io::check_output_dir("out", &out)?;
    }
    super::common::check_stdout()?;
    let rows = racket_impact::report::evaluate()?;
    let md = racket_impact::report::document(&rows)?;
    // REPORT.md is published only once the report has been printed (a device before it)
    let mut staged = racket_impact::render::io::Staged::new();
    if !a.no_write {
        staged.bytes(&out, md.as_bytes())?;
    }
    staged.publish(|| {
        out!("{md}");
        Ok(())
    })
}
