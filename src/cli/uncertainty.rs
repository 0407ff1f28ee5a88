//! `uncertainty`: an impact's result fields under uncertain inputs (`--vary KEY=DIST`), or every
//! paper claim under the declared input uncertainty (`--claims`): mean, sd, q05, q50, q95 and
//! Sobol' indices with bootstrap intervals.

use std::path::PathBuf;

use clap::Args;
use racket_impact::experiments::robustness;
use racket_impact::params::keys;
use racket_impact::study::sensitivity::Design;
use racket_impact::study::uncertainty::{few_samples, Study, DEFAULT_SAMPLES};
use racket_impact::{Error, Result};

use super::common::{out, print_diagnostics, warn, Common, Format, Progress};
use super::overrides::UncertaintyKeys;

#[derive(Args, Debug)]
pub struct UncertaintyArgs {
    #[command(flatten)]
    pub common: Common<UncertaintyKeys>,
    /// An uncertain input, KEY=DIST (repeatable): KEY any real-valued parameter, DIST
    /// uniform:LO:HI, normal:MEAN:SD or loguniform:LO:HI; every sample must be a valid value.
    /// KEY alone draws the distribution declared with the parameter (see the long help)
    #[arg(long = "vary", value_name = "KEY=DIST")]
    pub vary: Vec<String>,
    /// Base samples N of the Saltelli design, 1..=65536: N (d + 2) impacts for d inputs [default: 256; with --claims 128]
    #[arg(long)]
    pub samples: Option<u64>,
    /// Seed of the scrambled Sobol' sequence and of the bootstrap [default: 0; with --claims 2000]
    #[arg(long)]
    pub seed: Option<u32>,
    /// Write the output (in --format) to this file, atomically, instead of standard output
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
    /// Every paper claim under the declared uncertainty of the paper's inputs (the robustness
    /// experiment); takes only --samples, --seed, --format and --out
    #[arg(long)]
    pub claims: bool,
}

/// The long help: what is computed and the declared uncertainties `--claims` uses.
pub fn long_about() -> String {
    let line = |key: &str, u: Option<racket_impact::params::uncertainty::Uncertainty>| {
        u.map(|u| format!("{key} ~ {} ({})", u.dist.text(), u.source))
    };
    let declared: Vec<String> = robustness::inputs().into_iter().filter_map(|s| line(s.key, s.uncertainty)).collect();
    let claims: Vec<&str> = robustness::inputs().iter().map(|s| s.key).collect();
    let oblique: Vec<String> =
        keys::uncertain().filter(|s| !claims.contains(&s.key)).filter_map(|s| line(s.key, s.uncertainty)).collect();
    format!(
        "An impact's result fields under uncertain inputs, or every paper claim under the declared uncertainty\n\n\
         Example: racket-impact uncertainty --x 0.06 --vary ks=uniform:2e4:6e4 --vary mb=normal:0.057:0.0005\n\n\
         Every simulate option sets the fixed parameters; each --vary KEY=DIST draws one input. The impact \
         runs N (d + 2) times for d inputs, over a Saltelli design (scrambled Sobol' sequence, deterministic for \
         --seed), on all cores, with the modal solver unless --solver is given or a hand grip or stiffening \
         strings need fd.\n\n\
         Output, for every numeric result field: mean, sd, q05, q50, q95, and each input's first-order (Saltelli \
         2010) and total (Jansen) Sobol' index with 95 % bootstrap intervals. --format json gives \
         {{\"samples\", \"seed\", \"inputs\", \"outputs\": {{field: {{\"mean\", \"sd\", \"q05\", \"q50\", \"q95\", \
         \"first_order\", \"total_order\", \"first_order_ci\", \"total_order_ci\"}}}}}}.\n\n\
         Warnings: an input whose draws reach outside the usual range simulate warns with (a uniform's or \
         log-uniform's bounds; a normal's mean +- 3 sd) earns one warning line.\n\n\
         With --claims: each paper claim (golden/paper_claims.csv) under the uncertainties declared with the \
         parameters, drawn as factors on the paper's values:\n  {}\n\n\
         --vary KEY without a distribution draws the one declared with the parameter: those above, and for an \
         oblique or spinning ball:\n  {}",
        declared.join("\n  "),
        oblique.join("\n  ")
    )
}

/// Run the study and write its output.
pub fn run(a: UncertaintyArgs) -> Result<()> {
    if a.claims {
        return run_claims(a);
    }
    let samples = a.samples.unwrap_or(DEFAULT_SAMPLES);
    let study = Study::from_sources(&a.common.sources(), &a.vary, samples, a.seed.unwrap_or(0))?;
    match &a.out {
        Some(path) => racket_impact::render::io::check_output_dir("out", path)?,
        None => super::common::check_stdout()?,
    }
    let progress = Progress::new(study.design.runs() as u64);
    let outputs = study.run(|done| progress.update(done as u64))?;
    drop(progress);
    let text = match a.common.format {
        Format::Json => json_text(&study.json(&outputs))?,
        Format::Csv => study.csv(&outputs),
        Format::Text => study.text(&outputs),
    };
    emit(a.out.as_ref(), &text)?;
    print_diagnostics(&study.diagnostics());
    Ok(())
}

/// `--claims`: the robustness table of every paper claim.
fn run_claims(a: UncertaintyArgs) -> Result<()> {
    let refuse = |what: String| {
        Err(Error::invalid("claims", what, "--claims uses the paper's inputs and their declared uncertainty; it takes only --samples, --seed, --format and --out"))
    };
    if let Some(v) = a.vary.first() {
        return refuse(format!("--vary {v}"));
    }
    if let Some(k) = a.common.overrides.0.given().first() {
        return refuse(format!("--{k}"));
    }
    if a.common.racket.is_some() || a.common.config.is_some() {
        return refuse(if a.common.racket.is_some() { "--racket".into() } else { "--config".into() });
    }
    let samples = a.samples.unwrap_or(robustness::SAMPLES);
    let seed = a.seed.unwrap_or(robustness::SEED);
    let inputs = robustness::inputs();
    let design = Design::new(samples, inputs.len(), seed)?;
    match &a.out {
        Some(path) => racket_impact::render::io::check_output_dir("out", path)?,
        None => super::common::check_stdout()?,
    }
    let progress = Progress::new(design.runs() as u64);
    let rows = robustness::study(&racket_impact::experiments::Context::paper(), samples, seed, false, None, |done| {
        progress.update(done as u64)
    })?;
    drop(progress);
    let text = match a.common.format {
        Format::Csv => robustness::table(&rows)?.to_csv(),
        Format::Text => robustness::text(&rows, samples, seed),
        Format::Json => json_text(&robustness::json(&rows, samples, seed)?)?,
    };
    emit(a.out.as_ref(), &text)?;
    if let Some(line) = few_samples(samples) {
        warn(&line);
    }
    Ok(())
}

fn json_text(v: &serde_json::Value) -> Result<String> {
    racket_impact::render::json::pretty(v)
}

/// To the file (atomically) or standard output.
fn emit(path: Option<&PathBuf>, text: &str) -> Result<()> {
    match path {
        Some(p) => racket_impact::render::io::write_atomic(p, text.as_bytes()),
        None => {
            out!("{text}");
            Ok(())
        }
    }
}
