//! `report`: the paper's numbers beside ours, written to REPORT.md and printed.

use std::path::PathBuf;

use clap::Args;
use racket_impact::Result;

use super::common::{out, outln};

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Where to write the Markdown report [default: REPORT.md]
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the report without writing the file
    #[arg(long)]
    pub no_write: bool,
    /// Print one line (the file written and the claims' count) instead of the whole report
    /// (`make figures` ends with it)
    #[arg(long, conflicts_with = "no_write")]
    pub summary: bool,
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
    let progress =
        super::common::Progress::spinner("report: every claim of the paper, its robustness and the sections beyond it");
    // (kept for the next run of this build where RACKET_IMPACT_CACHE says: super::cache)
    let md = super::cache::text("report", || racket_impact::report::document(&racket_impact::report::evaluate()?))?;
    drop(progress);
    // REPORT.md is published only once the report has been printed (a device before it)
    let mut staged = racket_impact::render::io::Staged::new();
    if !a.no_write {
        staged.bytes(&out, md.as_bytes())?;
    }
    staged.publish(|| {
        if a.summary {
            outln!("wrote {}: {}", out.display(), headline(&md));
        } else {
            out!("{md}");
        }
        Ok(())
    })
}

/// The report's headline counts in one line, without the Markdown: the claims reproduced (its
/// first bold text) and the conclusions under the inputs' uncertainty (the bold "Conclusions:").
fn headline(md: &str) -> String {
    let bold = |line: &str| line.split("**").nth(1).unwrap_or_default().trim_end_matches('.').to_string();
    let first = md.lines().find(|l| l.starts_with("**")).map(bold).unwrap_or_default();
    match md.lines().find(|l| l.starts_with("**Conclusions:")).map(bold) {
        Some(c) => format!("{first}; {}", c.replacen("Conclusions:", "conclusions under the inputs' uncertainty:", 1)),
        None => first,
    }
}
