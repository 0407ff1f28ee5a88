//! `uncertainty`: an impact's result fields under uncertain inputs (`--vary KEY=DIST`), or every
//! paper claim under the declared input uncertainty (`--claims`): mean, sd, q05, q50, q95 and
//! Sobol' indices with bootstrap intervals.

use std::path::PathBuf;

use clap::Args;
use racket_impact::command::uncertainty::{Uncertain, Uncertainty};
use racket_impact::command::{execute, Control};
use racket_impact::experiments::robustness;
use racket_impact::params::keys;
use racket_impact::Result;

use super::common::{out, print_diagnostics, Common, Format, Reporter};
use super::options::{Options, UncertaintyOptions};
use super::overrides::UncertaintyKeys;

#[derive(Args, Debug)]
pub struct UncertaintyArgs {
    #[command(flatten)]
    pub common: Common<UncertaintyKeys>,
    #[command(flatten)]
    pub options: Options<UncertaintyOptions>,
    /// Write the output (in --format) to this file, atomically, instead of standard output
    #[arg(long, help_heading = "Output")]
    pub out: Option<PathBuf>,
}

/// The long help: its examples, then what is computed.
pub fn long_about() -> String {
    super::examples(
        "An impact's result fields under uncertain inputs, or every paper claim under declared uncertainty",
        &[
            "racket-impact uncertainty --x 0.06 --vary ks=uniform:2e4:6e4 --vary mb=normal:0.057:0.0005",
            "racket-impact uncertainty --x 0.06 --vary ks --vary ei --samples 512 --format json",
            "racket-impact uncertainty --claims --format csv --out claims.csv",
        ],
    ) + "\n\n\
         Every simulate option sets the fixed parameters; each --vary KEY=DIST draws one input (KEY alone: the \
         distribution declared with the parameter, listed at the end). The impact runs N (d + 2) times for d \
         inputs, over a Saltelli design (scrambled Sobol' sequence, deterministic for --seed), on all cores, with \
         the modal solver unless --solver is given or a hand grip or stiffening strings need fd.\n\n\
         Output, for every numeric result field: mean, sd, q05, q50, q95, and each input's first-order (Saltelli \
         2010) and total (Jansen) Sobol' index with 95 % bootstrap intervals. --format json gives \
         {\"samples\", \"seed\", \"inputs\", \"outputs\": {field: {\"mean\", \"sd\", \"q05\", \"q50\", \"q95\", \
         \"first_order\", \"total_order\", \"first_order_ci\", \"total_order_ci\"}}}.\n\n\
         Warnings: an input whose draws reach outside the usual range simulate warns with (a uniform's or \
         log-uniform's bounds; a normal's mean +- 3 sd) earns one warning line.\n\n\
         With --claims: each paper claim (golden/paper_claims.csv) under the uncertainties declared with the \
         paper's inputs (listed at the end), drawn as factors on the paper's values."
}

/// The end of the long help: the declared uncertainties `--claims` uses, and those `--vary KEY`
/// draws for an oblique or spinning ball.
pub fn declared_help() -> String {
    let line = |key: &str, u: Option<racket_impact::params::uncertainty::Uncertainty>| {
        u.map(|u| format!("{key} ~ {} ({})", u.dist.text(), u.source))
    };
    let declared: Vec<String> = robustness::inputs().into_iter().filter_map(|s| line(s.key, s.uncertainty)).collect();
    let claims: Vec<&str> = robustness::inputs().iter().map(|s| s.key).collect();
    let oblique: Vec<String> =
        keys::uncertain().filter(|s| !claims.contains(&s.key)).filter_map(|s| line(s.key, s.uncertainty)).collect();
    format!(
        "Declared uncertainties, drawn by --claims and by --vary KEY:\n  {}\n\n\
         Drawn by --vary KEY for an oblique or spinning ball:\n  {}",
        declared.join("\n  "),
        oblique.join("\n  ")
    )
}

/// Run the study and write its output.
pub fn run(a: UncertaintyArgs) -> Result<()> {
    let request = Uncertainty::new(&a.common.sources(), &a.options.0)?;
    match &a.out {
        Some(path) => racket_impact::render::io::check_output_dir("out", path)?,
        None => super::common::check_stdout()?,
    }
    let formats = [Format::Text, Format::Csv, Format::Json];
    let which = formats.iter().position(|&f| f == a.common.format).unwrap_or(0);
    let (text, diagnostics) = match request {
        Uncertainty::Claims { samples, seed } => {
            // (depends on nothing but the build, the sample count and the seed: kept where
            // RACKET_IMPACT_CACHE says, its three formats from one run, super::cache)
            let names = formats.map(|f| format!("claims-{samples}-{seed}-{}", format!("{f:?}").to_lowercase()));
            let text =
                super::cache::texts(&names.each_ref().map(String::as_str), which, || match run_request(request)? {
                    Uncertain::Claims { rows, samples, seed, .. } => claims_texts(&rows, samples, seed),
                    Uncertain::Fields { .. } => Ok(vec![]),
                })?;
            (text, Uncertainty::claims_diagnostics(samples))
        }
        Uncertainty::Fields { .. } => match run_request(request)? {
            Uncertain::Fields { study, outputs, diagnostics } => {
                let text = match a.common.format {
                    Format::Json => json_text(&study.json(&outputs))?,
                    Format::Csv => study.csv(&outputs),
                    Format::Text => study.text(&outputs),
                };
                (text, diagnostics)
            }
            Uncertain::Claims { rows, samples, seed, diagnostics } => {
                (claims_texts(&rows, samples, seed)?.swap_remove(which), diagnostics)
            }
        },
    };
    emit(a.out.as_ref(), &text)?;
    print_diagnostics(&diagnostics);
    Ok(())
}

/// The claims' study in each of [`Format::Text`], [`Format::Csv`] and [`Format::Json`].
fn claims_texts(rows: &[robustness::ClaimRobustness], samples: u64, seed: u32) -> Result<Vec<String>> {
    Ok(vec![
        robustness::text(rows, samples, seed),
        robustness::table(rows)?.to_csv(),
        json_text(&robustness::json(rows, samples, seed)?)?,
    ])
}

/// Run `request` with its progress reported.
fn run_request(request: Uncertainty) -> Result<Uncertain> {
    let ctl = Control::new();
    let reporter = Reporter::start(&ctl);
    let done = execute(request, &ctl);
    drop(reporter);
    done
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
