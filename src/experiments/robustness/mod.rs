//! `robustness` (ours): every paper claim under the declared input uncertainty. The inputs are
//! the parameters with an uncertainty declared beside them in
//! [`keys`] (ball mass, p through the rules' e, k1, k_s, EI through f1,
//! racket mass, length, I_x, the 30 m/s of Figs 7-8), each drawn as a factor `drawn / nominal`
//! on the context's value, and the shape of the tension calibration between the paper's two
//! statements of it ([`TENSION_SHAPE`]); a Saltelli design of [`SAMPLES`] base samples runs every claim's own
//! computation, under its reading, at each point with the modal solver (within 1e-4 of the
//! explicit one), each load held at the physical point the claim's nominal run loads
//! ([`sampling`]: the discretisation is no input; its size is the `numerical` column), and
//! each claim gets q05-q95, its Sobol' indices and a verdict: the paper's value holds (is
//! within the claim's tolerance) over the whole 5-95 % interval, over part of it, or not at
//! all, or `independent` where no sampled input moves the claim's value. The nominal value is the report's (explicit solver, the paper's inputs); the
//! `numerical` column is the converged value (`hat` load, N = 320) less it, where the claim
//! has one: the paper's numerics beside the physical uncertainty.

mod chart;
mod write;

use super::claims::{computations, evaluate_all, Check, Claim, Ours};
use super::conclusion::Standing;
use super::{Context, Experiment, Scheme};
use crate::error::{Error, Result};
use crate::params::spec::ParamSpec;
use crate::params::uncertainty::{Dist, Uncertainty};
use crate::params::{keys, Overrides, SolverKind};
use crate::render::table::Table;
use crate::study::sensitivity::{self, quantile_sorted, Design, Summary};
pub use write::{json, table, text, COLUMNS};

/// Base samples of the design: 128 x (10 inputs + 2) = 1536 evaluations of every claim; the
/// experiment also runs twice as many (the `_2x` columns, whose first half are the same runs)
/// to show how the intervals move when it doubles (the `make figures` budget is 30 s on two
/// cores).
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
    /// The paper states no number: the claim is judged by its conclusion alone.
    NoNumber,
}

impl Robust {
    /// The word in the table.
    pub fn name(self) -> &'static str {
        match self {
            Robust::Holds => "holds",
            Robust::Part => "part",
            Robust::NotAtAll => "not at all",
            Robust::Independent => "independent",
            Robust::NoNumber => "no number",
        }
    }

    /// Every verdict, in the order the counts are told.
    pub const ALL: [Robust; 5] = [Robust::Holds, Robust::Part, Robust::NotAtAll, Robust::Independent, Robust::NoNumber];

    /// Compare the interval `[q05, q95]` with the band `[lo, hi]`; an interval that is one
    /// point (no sampled input moves the value) is [`Robust::Independent`]; no band (the paper
    /// states no number) is [`Robust::NoNumber`].
    pub fn of(q05: f64, q95: f64, band: Option<(f64, f64)>) -> Robust {
        let Some((lo, hi)) = band else { return Robust::NoNumber };
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
    /// The band within which the paper's value counts as reproduced (`None`: the paper states no
    /// number).
    pub band: Option<(f64, f64)>,
    /// The verdict on the number.
    pub verdict: Robust,
    /// The share of the samples in which the paper's conclusion holds (`None`: no sampled
    /// input moves what it compares).
    pub conclusion_share: Option<f64>,
    /// The verdict on the conclusion.
    pub conclusion: Standing,
    /// How far the sampled 5-95 % range of what the conclusion compares stays from its
    /// threshold, in units of that range's width (negative where it crosses); the nearest of its
    /// thresholds; `None` where no sampled input moves it ([`margins`]).
    pub conclusion_margin: Option<f64>,
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
    /// The conclusion's margin.
    pub conclusion_margin: Option<f64>,
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

/// One uncertain input of the study: a declared parameter's key and uncertainty, or the shape
/// of the tension calibration ([`TENSION_SHAPE`]).
#[derive(Debug, Clone, Copy)]
pub struct Input {
    /// The parameter's key, or [`TENSION_SHAPE`].
    pub key: &'static str,
    /// Its distribution, nominal value and source.
    pub uncertainty: Option<Uncertainty>,
}

/// The key of the tension calibration's shape ([`Context::tension_shape`]): 0 reads the
/// paper's "k_s is approximately proportional to the string tension" (ours, 60 lb = 4e4 N/m),
/// 1 its "typically between 2e4 and 6e4 N/m for string tensions in the range 40 lb to 80 lb" as
/// a straight line; between, the mixture.
pub const TENSION_SHAPE: &str = "tension_shape";

/// The tension calibration's shape as an input: uniform between the paper's two statements.
pub const TENSION_SHAPE_UNCERTAINTY: Uncertainty = Uncertainty {
    dist: Dist::Uniform { lo: 0.0, hi: 1.0 },
    nominal: 0.0,
    source: "the paper's two statements of how k_s follows the tension (p. 3, String parameters: 'typically between \
             2e4 and 6e4 N/m for string tensions in the range 40 lb to 80 lb'; p. 7, Discussion: 'approximately \
             proportional to the string tension'), no proportional law fitting both: 0 is ours, proportional with \
             60 lb = 4e4 N/m, 1 the straight line through 2e4 at 40 lb and 6e4 at 80 lb (50 lb = 3e4 N/m), \
             uniform between; the two agree at 60 lb, so only the tension claims move",
};

/// The declared parameters the paper's impacts use (the ball's tangential properties act only
/// on an oblique or spinning ball, so they would add dimensions that move no claim).
pub fn param_inputs() -> Vec<Input> {
    let paper = crate::params::Params::paper();
    keys::uncertain()
        .filter(|s| crate::params::used::unused(s, &paper).is_none())
        .map(|s: &ParamSpec| Input { key: s.key, uncertainty: s.uncertainty })
        .collect()
}

/// The inputs of the claims' study: [`param_inputs`] and the tension calibration's shape.
pub fn inputs() -> Vec<Input> {
    let mut all = param_inputs();
    all.push(Input { key: TENSION_SHAPE, uncertainty: Some(TENSION_SHAPE_UNCERTAINTY) });
    all
}

/// The context at the drawn values `x` (one per input of `inputs`): each parameter a factor
/// `x / nominal` on `base`'s value (k_s and v1 on the context's factors, the others on its
/// racket and ball), the calibration's shape as drawn.
pub fn context_at(base: &Context, inputs: &[Input], x: &[f64]) -> Result<Context> {
    let mut ctx = base.clone();
    let mut p = base.base_params();
    let mut o = Overrides::default();
    for (spec, &v) in inputs.iter().zip(x) {
        let Some(u) = spec.uncertainty else { continue };
        let factor = v / u.nominal;
        if spec.key == TENSION_SHAPE {
            ctx.tension_shape = v;
        } else if spec.key == keys::KS.key {
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

/// The context every draw of the study starts from ([`context_at`]): `base` with the modal solver
/// and its loads held where `base`'s N = 39 beam puts them ([`Context::holding_loads`]), so that
/// each claim's load stays at the physical point its nominal run loads whatever the drawn
/// length: the discretisation is no input of the study (the report sets the converged-minus-N =
/// 39 shift beside the inputs, column `numerical`), and no input's share carries it.
pub fn sampling(base: &Context) -> Context {
    Context { solver: SolverKind::Modal, scheme: Scheme::Paper, ..base.clone() }.holding_loads()
}

/// A claim at twice the samples: its summary, conclusion share and conclusion margin.
type Twice = (Summary, Option<f64>, Option<f64>);

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
    let sampled = sampling(base);
    let schemes: Vec<Scheme> = claims.iter().map(|c| c.reading.scheme()).collect();
    let rows = sensitivity::run(
        &design,
        &dists,
        |x| {
            // the claims at one draw share their impacts
            let ctx = context_at(&sampled, &specs, x)?.remembering();
            fns.iter().zip(&schemes).map(|(f, &scheme)| (f.ours)(&Context { scheme, ..ctx.clone() })).collect()
        },
        progress,
    )?;
    let (small, small_rows) = sensitivity::prefix(&design, &rows, samples as usize)?;
    let summaries = sensitivity::summarise_all(&small, &small_rows);
    let checks: Vec<Check> = claims.iter().map(Claim::check).collect::<Result<_>>()?;
    let owned_ids: Vec<String> = claims.iter().map(|c| c.id.clone()).collect();
    let ids: Vec<&str> = owned_ids.iter().map(String::as_str).collect();
    let small_ab = &small_rows[..2 * small.samples()];
    let small_shares = shares(&ids, &checks, small_ab);
    let small_margins = margins(&ids, &checks, small_ab);
    let mut twice: Vec<Option<Twice>> = vec![None; claims.len()];
    if doubled {
        let ab = &rows[..2 * design.samples()];
        let (twice_shares, twice_margins) = (shares(&ids, &checks, ab), margins(&ids, &checks, ab));
        twice = sensitivity::summarise_all(&design, &rows)
            .into_iter()
            .zip(twice_shares.into_iter().zip(twice_margins))
            .map(|(s, (share, margin))| Some((s, share, margin)))
            .collect();
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
        .zip(summaries.into_iter().zip(small_shares.into_iter().zip(small_margins)).zip(twice))
        .map(|(((claim, ours), check), ((summary, (share, margin)), twice))| {
            let band = claim.band()?;
            let verdict = Robust::of(summary.q05, summary.q95, band);
            let doubled = twice.map(|(s, share, margin)| Doubled {
                verdict: Robust::of(s.q05, s.q95, band),
                summary: s,
                conclusion_share: share,
                conclusion: Standing::of(share),
                conclusion_margin: margin,
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
                conclusion_margin: margin,
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

/// How far the sampled range of what each claim's conclusion compares stays from its
/// thresholds ([`ClaimRobustness::conclusion_margin`]): per term, the 5 % quantile of the
/// term's slack over `runs` (its distance inside the threshold, the other claims at the same
/// run) over the width of the slack's 5-95 % range; the smallest over the terms. `None` where
/// a slack is missing or every term's slack is the same in every run.
pub fn margins(ids: &[&str], checks: &[Check], runs: &[Vec<f64>]) -> Vec<Option<f64>> {
    let column = |id: &str| ids.iter().position(|i| *i == id);
    (0..ids.len())
        .map(|k| {
            let check = &checks[k];
            let per_run: Vec<Vec<Option<f64>>> =
                runs.iter().map(|r| check.slacks(r[k], |id| column(id).map(|j| r[j]))).collect();
            let mut best: Option<f64> = None;
            for term in 0..check.terms.len() {
                let mut slack: Vec<f64> = per_run.iter().map(|s| s[term]).collect::<Option<Vec<f64>>>()?;
                if slack.iter().any(|v| !v.is_finite()) {
                    return None;
                }
                slack.sort_by(f64::total_cmp);
                let (q05, q95) = (quantile_sorted(&slack, 0.05), quantile_sorted(&slack, 0.95));
                if q95 > q05 {
                    let m = q05 / (q95 - q05);
                    best = Some(best.map_or(m, |b| b.min(m)));
                }
            }
            best
        })
        .collect()
}

/// How many claims have each verdict on the number, in [`Robust::ALL`]'s order, and how many
/// are borderline (a verdict that twice the samples changes; counted apart, not under their
/// verdict).
pub fn tally(rows: &[ClaimRobustness]) -> ([(Robust, usize); 5], usize) {
    let counts = Robust::ALL.map(|v| (v, rows.iter().filter(|r| r.verdict == v && !r.borderline()).count()));
    (counts, rows.iter().filter(|r| r.borderline()).count())
}

/// How many claims have each verdict on the conclusion, in [`Standing::ALL`]'s order, how many
/// are borderline and how many hold by construction (both counted apart, not under their
/// verdict: a conclusion the model makes true by construction is no support).
pub fn conclusion_tally(rows: &[ClaimRobustness]) -> ConclusionTally {
    let counted = |r: &&ClaimRobustness| !r.claim.by_construction() && !r.conclusion_borderline();
    ConclusionTally {
        counts: Standing::ALL.map(|v| (v, rows.iter().filter(counted).filter(|r| r.conclusion == v).count())),
        borderline: rows.iter().filter(|r| !r.claim.by_construction() && r.conclusion_borderline()).count(),
        by_construction: rows.iter().filter(|r| r.claim.by_construction()).count(),
    }
}

/// The conclusions counted ([`conclusion_tally`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConclusionTally {
    /// Each verdict with its count, in [`Standing::ALL`]'s order (neither borderline nor by
    /// construction).
    pub counts: [(Standing, usize); 5],
    /// Verdicts that twice the samples changes.
    pub borderline: usize,
    /// Conclusions that hold by construction of the model.
    pub by_construction: usize,
}

/// The counts in words: "Conclusions: 30 hold, 5 mostly, ...; numbers: 8 hold over the whole
/// interval, ...".
pub fn tally_text(rows: &[ClaimRobustness]) -> String {
    let ConclusionTally {
        counts: [(_, holds), (_, mostly), (_, contested), (_, fails), (_, c_independent)],
        borderline: c_borderline,
        by_construction,
    } = conclusion_tally(rows);
    let ([(_, whole), (_, part), (_, none), (_, independent), (_, no_number)], borderline) = tally(rows);
    format!(
        "Conclusions: {holds} hold in every sample, {mostly} mostly, {contested} contested, {fails} fail; \
         {c_independent} independent; {c_borderline} borderline (the verdict changes at twice the samples); \
         {by_construction} hold by construction (not counted).\n\
         Numbers: {whole} hold over the whole interval, {part} over part of it, {none} not at all; {independent} \
         do not depend on the sampled inputs (independent); {borderline} borderline (the verdict changes at \
         twice the samples); {no_number} state no number (judged by their conclusion)"
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
        assert_eq!(Robust::of(1.0, 2.0, Some((0.0, 3.0))), Robust::Holds);
        assert_eq!(Robust::of(1.0, 4.0, Some((0.0, 3.0))), Robust::Part);
        assert_eq!(Robust::of(-1.0, 0.5, Some((0.0, 3.0))), Robust::Part);
        assert_eq!(Robust::of(3.5, 4.0, Some((0.0, 3.0))), Robust::NotAtAll);
        // a point interval is no test of robustness, inside the band or out of it
        assert_eq!(Robust::of(2.0, 2.0, Some((0.0, 3.0))), Robust::Independent);
        assert_eq!(Robust::of(4.0, 4.0, Some((0.0, 3.0))), Robust::Independent);
        assert_eq!(Robust::of(1.0, 2.0, None), Robust::NoNumber);
    }

    /// The margin is the distance of the sampled 5-95 % range from the threshold in units of its
    /// width: positive inside, negative where the range crosses, the nearest threshold deciding.
    #[test]
    fn the_margin_is_the_distance_from_the_threshold_in_widths() {
        let ids = ["a", "b"];
        let checks = [Check::parse("a", "> 0 and < 10").unwrap(), Check::parse("b", "< a").unwrap()];
        // a runs over 1..=101 (5-95 %: 6 to 96), b is a - 50 (slack 50)
        let runs: Vec<Vec<f64>> = (1..=101).map(|k| vec![k as f64, k as f64 - 50.0]).collect();
        let m = margins(&ids, &checks, &runs);
        // "< 10": slack 10 - a has its 5 % quantile at 10 - 96 = -86, width 90
        assert!((m[0].unwrap() - (-86.0 / 90.0)).abs() < 1e-12, "{m:?}");
        // b's slack is 50 in every run: no width, no margin
        assert_eq!(m[1], None);
        let inside: Vec<Vec<f64>> = (1..=101).map(|k| vec![1.0 + k as f64 / 100.0, 0.0]).collect();
        let m = margins(&ids, &checks, &inside);
        // "> 0": 5 % quantile 1.06, width 0.9
        assert!((m[0].unwrap() - 1.06 / 0.9).abs() < 1e-9, "{m:?}");
    }

    #[test]
    fn the_nominal_draw_is_the_paper_context() {
        let all = inputs();
        let x: Vec<f64> = all.iter().map(|s| s.uncertainty.unwrap().nominal).collect();
        assert_eq!(context_at(&Context::paper(), &all, &x).unwrap(), Context::paper());
        let mut y = x.clone();
        y[0] *= 1.1; // ks
        *y.last_mut().unwrap() = 1.0; // the paper's 2e4-6e4 line
        let ctx = context_at(&Context::paper(), &all, &y).unwrap();
        assert!((ctx.ks_factor - 1.1).abs() < 1e-12 && ctx.racket == Context::paper().racket);
        assert_eq!(ctx.tension_shape, 1.0);
        assert!((ctx.ks_at_tension_lb(50.0) - 3.0e4).abs() < 1e-9 && (ctx.ks_at_tension_lb(60.0) - 4.0e4).abs() < 1e-9);
    }
}
