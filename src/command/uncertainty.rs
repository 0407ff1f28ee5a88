//! `uncertainty`: an impact's result fields under uncertain inputs (`vary`), or every paper
//! claim under the declared input uncertainty (`claims`).

use super::{Control, Given, Kind, Many, Opt, Request, Unit, Work, LONG};
use crate::diagnostic::{Diagnostic, Kind as Note};
use crate::error::{Error, Result};
use crate::experiments::robustness::{self, ClaimRobustness};
use crate::intake::Sources;
use crate::study::sensitivity::{Design, MAX_SAMPLES};
use crate::study::uncertainty::{few_samples, Output, Study, DEFAULT_SAMPLES};

/// The command.
pub const NAME: &str = "uncertainty";

/// Its options.
pub const OPTIONS: &[Opt] = &[
    Opt::new(
        "vary",
        Kind::Text,
        None,
        "An uncertain input, KEY=DIST (repeatable): KEY any real-valued parameter, DIST uniform:LO:HI, \
         normal:MEAN:SD or loguniform:LO:HI; every sample must be a valid value. KEY alone draws the \
         distribution declared with the parameter (see the long help)",
    )
    .many(Many::Repeated),
    Opt::new(
        "samples",
        Kind::Count { lo: 1, hi: MAX_SAMPLES },
        None,
        "Base samples N of the Saltelli design: N (d + 2) impacts for d inputs (with --claims at most 32768, each \
         verdict checked again at 2N) [default: 256; with --claims 128]",
    ),
    Opt::new(
        "seed",
        Kind::Count { lo: 0, hi: u32::MAX as u64 },
        None,
        "Seed of the scrambled Sobol' sequence and of the bootstrap [default: 0; with --claims 2000]",
    ),
    Opt::new(
        "claims",
        Kind::Switch,
        None,
        "Every paper claim under the declared uncertainty of the paper's inputs (the robustness experiment); takes \
         only --samples, --seed and the output's options",
    ),
    LONG,
];

/// A study, checked and ready to run.
#[derive(Debug, Clone)]
pub enum Uncertainty {
    /// The result fields of one impact under the inputs drawn (`vary`).
    Fields {
        /// The study.
        study: Box<Study>,
        /// What was asked for, in words (`the default 256 samples (768 impacts)`).
        asked: String,
        /// Whether a long run was asked for.
        long: bool,
    },
    /// Every paper claim under the declared uncertainty (`claims`).
    Claims {
        /// Base samples.
        samples: u64,
        /// Seed.
        seed: u32,
    },
}

/// A study, run.
#[derive(Debug, Clone)]
pub enum Uncertain {
    /// The result fields' summaries.
    Fields {
        /// The study.
        study: Box<Study>,
        /// Each output's summary.
        outputs: Vec<Output>,
        /// The diagnostics.
        diagnostics: Vec<Diagnostic>,
    },
    /// Every claim's robustness.
    Claims {
        /// One row per claim.
        rows: Vec<ClaimRobustness>,
        /// Base samples.
        samples: u64,
        /// Seed.
        seed: u32,
        /// The diagnostics (too few samples).
        diagnostics: Vec<Diagnostic>,
    },
}

impl Uncertainty {
    /// What the claims' study at `samples` base samples tells beside its result (too few samples
    /// for its indices to mean anything): a function of the count alone.
    pub fn claims_diagnostics(samples: u64) -> Vec<Diagnostic> {
        few_samples(samples).map(|s| Diagnostic::new(Note::Unusual, "samples", s)).into_iter().collect()
    }

    /// The study `sources` and the options `given` describe: the sample count first, then the
    /// inputs; with `claims`, only the sample count and the seed are taken.
    pub fn new(sources: &Sources, given: &Given) -> Result<Uncertainty> {
        let samples = given.count("samples")?;
        let seed = given.count("seed")?.map(|s| s as u32);
        let vary = given.texts("vary");
        let long = given.switch("long")?;
        if given.switch("claims")? {
            let refuse = |what: String| -> Result<Uncertainty> {
                Err(Error::invalid(
                    "claims",
                    what,
                    "--claims uses the paper's inputs and their declared uncertainty; it takes only --samples, --seed \
                     and the output's options",
                ))
            };
            if let Some(v) = vary.first() {
                return refuse(format!("--vary {v}"));
            }
            if let Some(k) = sources.flags.given().first() {
                return refuse(format!("--{k}"));
            }
            if long {
                return refuse("--long".into());
            }
            if sources.racket.is_some() || sources.config.is_some() {
                return refuse(if sources.racket.is_some() { "--racket".into() } else { "--config".into() });
            }
            let samples = samples.unwrap_or(robustness::SAMPLES);
            let seed = seed.unwrap_or(robustness::SEED);
            Design::new(samples, robustness::inputs().len(), seed)?; // the count first
            let most = MAX_SAMPLES / 2;
            if samples > most {
                return Err(Error::invalid(
                    "samples",
                    samples,
                    format!(
                        "with --claims must be at most {most} (every verdict is checked again at twice the samples)"
                    ),
                ));
            }
            return Ok(Uncertainty::Claims { samples, seed });
        }
        let n = samples.unwrap_or(DEFAULT_SAMPLES);
        let study = Study::from_sources(sources, &vary, n, seed.unwrap_or(0))?;
        let asked = format!("{} ({} impacts)", given.asked("samples", n, "samples"), study.design.runs());
        Ok(Uncertainty::Fields { study: Box::new(study), asked, long })
    }
}

impl Request for Uncertainty {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Uncertain;

    fn work(&self, threads: usize) -> Option<Work> {
        match self {
            Uncertainty::Fields { study, asked, long } => Some(Work {
                estimate: study.estimate(threads),
                asked: asked.clone(),
                fewer: "fewer samples",
                long: *long,
            }),
            // (the claims' study runs the experiments at every draw: not estimated)
            Uncertainty::Claims { .. } => None,
        }
    }

    fn run(self, ctl: &Control) -> Result<Uncertain> {
        match self {
            Uncertainty::Fields { study, .. } => {
                ctl.begin(study.design.runs() as u64, Unit::Impacts);
                let outputs = study.run(|done| ctl.set_done(done as u64))?;
                let diagnostics = study.diagnostics();
                Ok(Uncertain::Fields { study, outputs, diagnostics })
            }
            Uncertainty::Claims { samples, seed } => {
                // twice the samples too, as the report does: a verdict that changes there is
                // borderline, counted apart (the first half are the same runs)
                let doubled = Design::new(2 * samples, robustness::inputs().len(), seed)?;
                ctl.begin(doubled.runs() as u64, Unit::Named("claim evaluations"));
                let context = crate::experiments::Context::paper();
                let rows = robustness::study(&context, samples, seed, true, None, |done| ctl.set_done(done as u64))?;
                Ok(Uncertain::Claims { rows, samples, seed, diagnostics: Uncertainty::claims_diagnostics(samples) })
            }
        }
    }
}
