//! `figures`: regenerate the paper's experiments, a CSV table and a PNG figure each.

use std::path::PathBuf;

use clap::Args;
use racket_impact::Result;

use super::common::outln;

#[derive(Args, Debug)]
pub struct FiguresArgs {
    /// Only this experiment (repeatable; each runs once, in the order given); see --list
    #[arg(long = "only", value_name = "ID")]
    pub only: Vec<String>,
    /// Output directory (created if missing); default figures/, or figures/racket-NAME with --racket
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Run the experiments on this racket (file or preset) instead of the paper's; the impacts
    /// stay where the paper puts them, along the whole length
    #[arg(long)]
    pub racket: Option<String>,
    /// List the experiment ids with their titles and paper references, and exit
    #[arg(long)]
    pub list: bool,
}

/// Run the selected experiments, writing a CSV table and a PNG figure each.
pub fn run(a: FiguresArgs) -> Result<()> {
    use racket_impact::experiments;
    if a.list {
        let given = [("only", !a.only.is_empty()), ("out", a.out.is_some()), ("racket", a.racket.is_some())];
        if let Some((flag, _)) = given.iter().find(|(_, g)| *g) {
            return Err(racket_impact::Error::invalid(
                flag,
                "(given)",
                "--list only lists the experiments and runs none",
            ));
        }
        for e in experiments::registry() {
            outln!("{:<24} {}\n{:<24} ({})", e.id, e.title, "", e.paper_ref);
        }
        return Ok(());
    }
    let selected = if a.only.is_empty() {
        experiments::registry()
    } else {
        let mut selected: Vec<experiments::Experiment> = Vec::new();
        for id in &a.only {
            let e = experiments::find(id)?;
            // an id given twice runs once, where it was first given
            if !selected.iter().any(|s| s.id == e.id) {
                selected.push(e);
            }
        }
        selected
    };
    let mut ctx = experiments::Context::paper();
    let out = match &a.racket {
        Some(arg) => {
            ctx = experiments::Context::for_racket(arg)?;
            let stem = std::path::Path::new(arg).file_stem().and_then(|s| s.to_str()).unwrap_or("custom");
            let name: String =
                stem.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).collect();
            a.out.clone().unwrap_or_else(|| PathBuf::from("figures").join(format!("racket-{name}")))
        }
        None => a.out.clone().unwrap_or_else(|| PathBuf::from("figures")),
    };
    racket_impact::render::io::check_dir_path("out", &out)?;
    racket_impact::render::io::ensure_dir(&out)?;
    // every destination checked before any work, every file staged, then all published
    // together (none if any experiment fails) and only then named
    for e in &selected {
        for path in experiments::files(e, &out) {
            racket_impact::render::io::check_output_dir("out", &path)?;
        }
    }
    let mut staged = racket_impact::render::io::Staged::new();
    let mut lines = Vec::new();
    for e in &selected {
        let start = std::time::Instant::now();
        let (table, files) = experiments::run_and_stage(e, &ctx, &out)?;
        staged.append(files);
        lines.push(format!(
            "{:<24} {:>4} rows  {:>6.2} s  -> {}/{}.{{csv,png}}",
            e.id,
            table.rows.len(),
            start.elapsed().as_secs_f64(),
            out.display(),
            e.id
        ));
    }
    staged.commit()?;
    for line in lines {
        super::common::stderr_line(&line);
    }
    Ok(())
}
