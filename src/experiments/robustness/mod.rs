//! `robustness` (ours): every paper claim under the declared input uncertainty. The inputs are
//! the parameters with an uncertainty declared beside them in
//! [`keys`] (ball mass, p through the rules' e, k1, k_s, EI through f1,
//! racket mass, length, I_x, the 30 m/s of Figs 7-8), each drawn as a factor `drawn / nominal`
//! on the context's value; a Saltelli design of [`SAMPLES`] base samples runs every claim's own
//! computation at each point with the modal solver (within 1e-4 of the explicit one), and
//! each claim gets q05-q95, its Sobol' indices and a verdict: the paper's value holds (is
//! within the claim's tolerance) over the whole 5-95 % interval, over part of it, or not at
//! all, or `independent` where no sampled input moves the claim's value. The nominal value is the report's (explicit solver, the paper's inputs); the
//! `numerical` column is the converged value (`hat` load, N = 320) less it, where the claim
//! has one: the paper's numerics beside the physical uncertainty.

mod chart;
mod write;

use super::claims::{computations, evaluate_all, Check, Claim, Ours, ToleranceKind};
use super::conclusion::Standing;
use super::{Context, Experiment, Scheme};
use crate::error::{Error, Result};
use crate::params::spec::ParamSpec;
use crate::params::uncertainty::Dist;
use crate::params::{keys, Overrides, SolverKind};
use crate::render::table::Table;
use crate::study::sensitivity::{self, Design, Summary};
pub use write::{json, table, text, COLUMNS};

/// Base samples of the design: 128 x (9 inputs + 2) = 1408 evaluations of every claim, about
/// 6 s of CPU; the experiment also runs twice as many (the `_2x` columns, whose first half are
/// the same runs) to show how the intervals move when it doubles, about 12 s of CPU in all
/// (the `make figures` budget is 30 s on two cores).
pub const SAMPLES: u64 = 128;
/// The seed of the design.
pub const SEED: u32 = 2000;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "robustness",
    title: "Every paper claim under the declared input uncertainty: q05-q95 against the paper's tolerance",
    paper_ref: "p. 3-4: ball 56.7 +- 0.9 g, e 0.745 +- 0.017, k1 assumed, ks +-10 %, f1 'about 125 Hz', I_x 'typical'",
    run,
    chart: chart::chart,
    claims: &[],
};

/// Whether the paper's statement survives the uncertainty.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Robust {
    /// Within the claim's tolerance over the whole q05-q95 interval.
    Holds,
    /// Over part of it.
    Part,
    /// Nowhere in it.
    NotAtAll,
    /// The claim's value does not change with the sampled inputs (a closed form, a fixed
    /// calibration): the interval is a point and says nothing of its robustness; the claim's
    /// verdict is the report's one at the paper's inputs.
    Independent,
}

impl Robust {
    /// The word in the table.
    pub fn name(self) -> &'static str {
        match self {
            Robust::Holds => "holds",
            Robust::Part => "part",
            Robust::NotAtAll => "not at all",
            Robust::Independent => "independent",
        }
    }

    /// Every verdict, in the order the counts are told.
    pub const ALL: [Robust; 4] = [Robust::Holds, Robust::Part, Robust::NotAtAll, Robust::Independent];

    /// Compare the interval `[q05, q95]` with the band `[lo, hi]`; an interval that is one
    /// point (no sampled input moves the value) is [`Robust::Independent`].
    pub fn of(q05: f64, q95: f64, (lo, hi): (f64, f64)) -> Robust {
        if q05 == q95 {
            Robust::Independent
        } else if q05 >= lo && q95 <= hi {
            Robust::Holds
        } else if q95 < lo || q05 > hi {
            Robust::NotAtAll
        } else {
            Robust::Part
        }
    }
}

/// One claim under uncertainty.
#[derive(Debug, Clone)]
pub struct ClaimRobustness {
    /// The claim (paper value, tolerance, conclusion).
    pub claim: Claim,
    /// Our value with the paper's inputs (explicit solver), as in the report.
    pub nominal: f64,
    /// Converged less nominal, where the claim has a converged value.
    pub numerical: Option<f64>,
    /// The spread and indices under the declared uncertainty.
    pub summary: Summary,
    /// The band within which the paper's value counts as reproduced.
    pub band: (f64, f64),
    /// The verdict on the number.
    pub verdict: Robust,
    /// The share of the samples in which the paper's conclusion holds (`None`: no sampled
    /// input moves what it compares).
    pub conclusion_share: Option<f64>,
    /// The verdict on the conclusion.
    pub conclusion: Standing,
    /// Whether the conclusion holds at the paper's inputs (the report's values).
    pub conclusion_nominal: bool,
    /// The same at twice the base samples (same seed: the first half of its rows are these),
    /// where asked for.
    pub doubled: Option<Doubled>,
}

/// A claim's spread and verdicts at twice the base samples.
#[derive(Debug, Clone)]
pub struct Doubled {
    /// The spread and indices.
    pub summary: Summary,
    /// The verdict on the number.
    pub verdict: Robust,
    /// The conclusion's share.
    pub conclusion_share: Option<f64>,
    /// The verdict on the conclusion.
    pub conclusion: Standing,
}

impl ClaimRobustness {
    /// The verdict on the number changes when the samples double: it is counted apart.
    pub fn borderline(&self) -> bool {
        self.doubled.as_ref().is_some_and(|d| d.verdict != self.verdict)
    }

    /// The verdict on the conclusion changes when the samples double.
    pub fn conclusion_borderline(&self) -> bool {
        self.doubled.as_ref().is_some_and(|d| d.conclusion != self.conclusion)
    }
}

/// Evaluations of every claim per base sample of the Saltelli design: the number of
/// [`inputs`] plus two.
pub fn runs_per_sample() -> usize {
    inputs().len() + 2
}

/// The inputs: every parameter with a declared uncertainty that the paper's impacts use (the
/// ball's tangential properties act only on an oblique or spinning ball, so they would add
/// dimensions that move no claim).
pub fn inputs() -> Vec<&'static ParamSpec> {
    let paper = crate::params::Params::paper();
    keys::uncertain().filter(|s| crate::params::used::unused(s, &paper).is_none()).collect()
}

/// The context at the drawn values `x` (one per [`inputs`]): each a factor `x / nominal` on
/// `base`'s value (k_s and v1 on the context's factors, the others on its racket and ball).
pub fn context_at(base: &Context, x: &[f64]) -> Result<Context> {
    let mut ctx = base.clone();
    let mut p = base.base_params();
    let mut o = Overrides::default();
    for (spec, &v) in inputs().iter().zip(x) {
        let Some(u) = spec.uncertainty else { continue };
        let factor = v / u.nominal;
        if spec.key == keys::KS.key {
            ctx.ks_factor *= factor;
        } else if spec.key == keys::V1.key {
            ctx.v1_factor *= factor;
        } else {
            let value = keys::value_number(spec.key, &p).unwrap_or(f64::NAN) * factor;
            o.set(spec.key, &value.to_string())?;
        }
    }
    o.apply(&mut p);
    p.validate()?;
    ctx.racket = p.racket;
    ctx.ball = p.ball;
    Ok(ctx)
}

/// The band of values within which the claim counts as reproduced.
pub fn band(claim: &Claim) -> Result<(f64, f64)> {
    let paper = claim.paper_value()?;
    let (kind, tol) = claim.tolerance()?;
    let half = match kind {
        ToleranceKind::Relative => tol * paper.abs(),
        ToleranceKind::Absolute => tol,
    };
    Ok((paper - half, paper + half))
}

/// Every claim under the declared uncertainty, on `base` (the paper's context for the
/// report): `samples` base samples from `seed`, and with `doubled` also twice as many (their
/// first half are the same runs); `progress` gets the claim evaluations done. `nominal`: the
/// claims' numbers on `base` ([`evaluate_all`]) where the caller has them, else computed here.
pub fn study(
    base: &Context,
    samples: u64,
    seed: u32,
    doubled: bool,
    nominal: Option<&[Ours]>,
    progress: impl FnMut(usize),
) -> Result<Vec<ClaimRobustness>> {
    let specs = inputs();
    Design::new(samples, specs.len(), seed)?;
    let design = Design::new(if doubled { 2 * samples } else { samples }, specs.len(), seed)?;
    let claims = super::claims::claims()?;
    let fns = computations(&claims)?;
    let dists: Vec<Dist> = specs.iter().filter_map(|s| s.uncertainty.map(|u| u.dist)).collect();
    let mut sampled = base.clone();
    sampled.solver = SolverKind::Modal;
    sampled.scheme = Scheme::Paper;
    let rows = sensitivity::run(
        &design,
        &dists,
        |x| {
            // the claims at one draw share their impacts
            let ctx = context_at(&sampled, x)?.remembering();
            fns.iter().map(|f| (f.ours)(&ctx)).collect()
        },
        progress,
    )?;
    let (small, small_rows) = sensitivity::prefix(&design, &rows, samples as usize)?;
    let summaries = sensitivity::summarise_all(&small, &small_rows);
    let checks: Vec<Check> = claims.iter().map(Claim::check).collect::<Result<_>>()?;
    let owned_ids: Vec<String> = claims.iter().map(|c| c.id.clone()).collect();
    let ids: Vec<&str> = owned_ids.iter().map(String::as_str).collect();
    let small_shares = shares(&ids, &checks, &small_rows[..2 * small.samples()]);
    let mut twice: Vec<Option<(Summary, Option<f64>)>> = vec![None; claims.len()];
    if doubled {
        let twice_shares = shares(&ids, &checks, &rows[..2 * design.samples()]);
        twice = sensitivity::summarise_all(&design, &rows).into_iter().zip(twice_shares).map(Some).collect();
    }
    let ours: Vec<Ours> = match nominal {
        Some(o) if o.len() == claims.len() => o.to_vec(),
        Some(o) => {
            return Err(Error::invalid("nominal", o.len(), format!("{} claims need as many values", claims.len())))
        }
        None => evaluate_all(&claims, base)?,
    };
    let nominal: Vec<f64> = ours.iter().map(|o| o.value).collect();
    let nominal_of = |id: &str| ids.iter().position(|i| *i == id).map(|j| nominal[j]);
    claims
        .into_iter()
        .zip(ours)
        .zip(checks)
        .zip(summaries.into_iter().zip(small_shares).zip(twice))
        .map(|(((claim, ours), check), ((summary, share), twice))| {
            let band = band(&claim)?;
            let verdict = Robust::of(summary.q05, summary.q95, band);
            let doubled = twice.map(|(s, share)| Doubled {
                verdict: Robust::of(s.q05, s.q95, band),
                summary: s,
                conclusion_share: share,
                conclusion: Standing::of(share),
            });
            Ok(ClaimRobustness {
                conclusion_nominal: check.holds(ours.value, nominal_of),
                claim,
                nominal: ours.value,
                numerical: ours.converged.map(|c| c - ours.value),
                summary,
                band,
                verdict,
                conclusion_share: share,
                conclusion: Standing::of(share),
                doubled,
            })
        })
        .collect()
}

/// The share of `runs` (one row of every claim's value per run, claims in `ids`' order) in
/// which each claim's conclusion holds; `None` for a claim whose conclusion compares only
/// values no run changes.
pub fn shares(ids: &[&str], checks: &[Check], runs: &[Vec<f64>]) -> Vec<Option<f64>> {
    let column = |id: &str| ids.iter().position(|i| *i == id);
    ids.iter()
        .zip(checks)
        .enumerate()
        .map(|(k, (_, check))| {
            let compared: Vec<usize> =
                std::iter::once(Some(k)).chain(check.references().map(column)).flatten().collect();
            let first = runs.first()?;
            if runs.iter().all(|r| compared.iter().all(|&j| r[j] == first[j])) {
                return None;
            }
            let held = runs.iter().filter(|r| check.holds(r[k], |id| column(id).map(|j| r[j]))).count();
            Some(held as f64 / runs.len() as f64)
        })
        .collect()
}

/// How many claims have each verdict on the number, in [`Robust::ALL`]'s order, and how many
/// are borderline (a verdict that twice the samples changes; counted apart, not under their
/// verdict).
pub fn tally(rows: &[ClaimRobustness]) -> ([(Robust, usize); 4], usize) {
    let counts = Robust::ALL.map(|v| (v, rows.iter().filter(|r| r.verdict == v && !r.borderline()).count()));
    (counts, rows.iter().filter(|r| r.borderline()).count())
}

/// How many claims have each verdict on the conclusion, in [`Standing::ALL`]'s order, and how
/// many are borderline (counted apart).
pub fn conclusion_tally(rows: &[ClaimRobustness]) -> ([(Standing, usize); 5], usize) {
    let counts =
        Standing::ALL.map(|v| (v, rows.iter().filter(|r| r.conclusion == v && !r.conclusion_borderline()).count()));
    (counts, rows.iter().filter(|r| r.conclusion_borderline()).count())
}

/// The counts in words: "Conclusions: 30 hold, 5 mostly, ...; numbers: 8 hold over the whole
/// interval, ...".
pub fn tally_text(rows: &[ClaimRobustness]) -> String {
    let ([(_, holds), (_, mostly), (_, contested), (_, fails), (_, c_independent)], c_borderline) =
        conclusion_tally(rows);
    let ([(_, whole), (_, part), (_, none), (_, independent)], borderline) = tally(rows);
    format!(
        "Conclusions: {holds} hold in every sample, {mostly} mostly, {contested} contested, {fails} fail; \
         {c_independent} independent; {c_borderline} borderline (the verdict changes at twice the samples).\n\
         Numbers: {whole} hold over the whole interval, {part} over part of it, {none} not at all; {independent} \
         do not depend on the sampled inputs (independent); {borderline} borderline (the verdict changes at \
         twice the samples)"
    )
}

/// Total indices below this are not named as an input a claim hinges on.
pub const NAMED_TOTAL: f64 = 0.01;

/// The two inputs with the largest total index, of those above [`NAMED_TOTAL`] (none for a
/// claim that does not vary).
pub fn top_two(s: &Summary) -> Vec<(&'static str, f64)> {
    let specs = inputs();
    let mut ranked: Vec<(&'static str, f64)> = specs
        .iter()
        .zip(&s.total)
        .filter(|(_, i)| i.value.is_finite() && i.value > NAMED_TOTAL)
        .map(|(spec, i)| (spec.key, i.value))
        .collect();
    ranked.sort_by(|a, b| b.1.total_cmp(&a.1));
    ranked.truncate(2);
    ranked
}

fn run(ctx: &Context) -> Result<Table> {
    table(&study(ctx, SAMPLES, SEED, true, None, |_| {})?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts_compare_the_interval_with_the_band() {
        assert_eq!(Robust::of(1.0, 2.0, (0.0, 3.0)), Robust::Holds);
        assert_eq!(Robust::of(1.0, 4.0, (0.0, 3.0)), Robust::Part);
        assert_eq!(Robust::of(-1.0, 0.5, (0.0, 3.0)), Robust::Part);
        assert_eq!(Robust::of(3.5, 4.0, (0.0, 3.0)), Robust::NotAtAll);
        // a point interval is no test of robustness, inside the band or out of it
        assert_eq!(Robust::of(2.0, 2.0, (0.0, 3.0)), Robust::Independent);
        assert_eq!(Robust::of(4.0, 4.0, (0.0, 3.0)), Robust::Independent);
    }

    #[test]
    fn the_nominal_draw_is_the_paper_context() {
        let x: Vec<f64> = inputs().iter().map(|s| s.uncertainty.unwrap().nominal).collect();
        assert_eq!(context_at(&Context::paper(), &x).unwrap(), Context::paper());
        let mut y = x.clone();
        y[0] *= 1.1; // ks
        let ctx = context_at(&Context::paper(), &y).unwrap();
        assert!((ctx.ks_factor - 1.1).abs() < 1e-12 && ctx.racket == Context::paper().racket);
    }
}
