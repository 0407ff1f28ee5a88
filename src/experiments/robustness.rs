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

use super::claims::{Claim, ToleranceKind};
use super::{Context, Experiment, PaperClaim};
use crate::error::{Error, Result};
use crate::params::spec::ParamSpec;
use crate::params::uncertainty::Dist;
use crate::params::{keys, Overrides, SolverKind};
use crate::render::plot::{Chart, Curve, LineStyle};
use crate::render::table::{Table, Value};
use crate::study::sensitivity::{self, Design, Summary};

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
    chart,
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
    /// The claim (paper value, tolerance).
    pub claim: Claim,
    /// Our value with the paper's inputs (explicit solver), as in the report.
    pub nominal: f64,
    /// Converged less nominal, where the claim has a converged value.
    pub numerical: Option<f64>,
    /// The spread and indices under the declared uncertainty.
    pub summary: Summary,
    /// The band within which the paper's value counts as reproduced.
    pub band: (f64, f64),
    /// The verdict.
    pub verdict: Robust,
    /// The same at twice the base samples (same seed: the first half of its rows are these),
    /// where asked for.
    pub doubled: Option<(Summary, Robust)>,
}

/// The inputs: every parameter with a declared uncertainty that the paper's impacts use (the
/// ball's tangential properties act only on an oblique or spinning ball, so they would add
/// dimensions that move no claim).
pub fn inputs() -> Vec<&'static ParamSpec> {
    let paper = crate::params::Params::paper();
    keys::uncertain().filter(|s| crate::params::used::unused_reason(s.key, &paper).is_none()).collect()
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

/// The computation of each claim of the claims file, in its order.
fn computations(claims: &[Claim]) -> Result<Vec<PaperClaim>> {
    let all: Vec<PaperClaim> = super::registry().iter().flat_map(|e| e.claims.iter().copied()).collect();
    claims
        .iter()
        .map(|c| {
            all.iter()
                .find(|pc| pc.id == c.id)
                .copied()
                .ok_or_else(|| Error::invalid("claim id", &c.id, "no computation is defined for this claim"))
        })
        .collect()
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
/// first half are the same runs); `progress` gets the claim evaluations done.
pub fn study(
    base: &Context,
    samples: u64,
    seed: u32,
    doubled: bool,
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
    sampled.converged_too = false;
    let rows = sensitivity::run(
        &design,
        &dists,
        |x| {
            let ctx = context_at(&sampled, x)?;
            fns.iter().map(|f| (f.ours)(&ctx).map(|o| o.value)).collect()
        },
        progress,
    )?;
    let (small, small_rows) = sensitivity::prefix(&design, &rows, samples as usize)?;
    let summaries = sensitivity::summarise_all(&small, &small_rows);
    let mut twice: Vec<Option<Summary>> = vec![None; claims.len()];
    if doubled {
        twice = sensitivity::summarise_all(&design, &rows).into_iter().map(Some).collect();
    }
    claims
        .into_iter()
        .zip(fns)
        .zip(summaries.into_iter().zip(twice))
        .map(|((claim, f), (summary, twice))| {
            let ours = (f.ours)(base)?;
            let band = band(&claim)?;
            let verdict = Robust::of(summary.q05, summary.q95, band);
            let doubled = twice.map(|s| {
                let v = Robust::of(s.q05, s.q95, band);
                (s, v)
            });
            Ok(ClaimRobustness {
                claim,
                nominal: ours.value,
                numerical: ours.converged.map(|c| c - ours.value),
                summary,
                band,
                verdict,
                doubled,
            })
        })
        .collect()
}

/// How many claims have each verdict, in [`Robust::ALL`]'s order.
pub fn tally(rows: &[ClaimRobustness]) -> [(Robust, usize); 4] {
    Robust::ALL.map(|v| (v, rows.iter().filter(|r| r.verdict == v).count()))
}

/// The counts in words: "9 hold over the whole interval, 28 over part of it, 4 not at all; 3
/// do not depend on the sampled inputs (independent)".
pub fn tally_text(rows: &[ClaimRobustness]) -> String {
    let [(_, holds), (_, part), (_, none), (_, independent)] = tally(rows);
    format!(
        "{holds} hold over the whole interval, {part} over part of it, {none} not at all; {independent} do not \
         depend on the sampled inputs (independent)"
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

/// The table columns.
pub const COLUMNS: [&str; 19] = [
    "id",
    "unit",
    "paper",
    "band_lo",
    "band_hi",
    "nominal",
    "numerical",
    "q05",
    "q50",
    "q95",
    "verdict",
    "top_input",
    "top_total",
    "second_input",
    "second_total",
    "q05_2x",
    "q50_2x",
    "q95_2x",
    "verdict_2x",
];

/// The claims as a table, one row each in the claims file's order.
pub fn table(rows: &[ClaimRobustness]) -> Result<Table> {
    let mut t = Table::new(EXPERIMENT.id, &COLUMNS);
    let num = |v: Option<f64>| v.filter(|v| v.is_finite()).map_or(Value::Text(String::new()), Value::Num);
    for r in rows {
        let s = &r.summary;
        let top = top_two(s);
        let name = |k: usize| Value::Text(top.get(k).map_or(String::new(), |t| t.0.to_string()));
        let total = |k: usize| num(top.get(k).map(|t| t.1));
        t.push(vec![
            Value::Text(r.claim.id.clone()),
            Value::Text(r.claim.unit.clone()),
            Value::Num(r.claim.paper_value()?),
            Value::Num(r.band.0),
            Value::Num(r.band.1),
            Value::Num(r.nominal),
            num(r.numerical),
            Value::Num(s.q05),
            Value::Num(s.q50),
            Value::Num(s.q95),
            Value::Text(r.verdict.name().to_string()),
            name(0),
            total(0),
            name(1),
            total(1),
            num(r.doubled.as_ref().map(|d| d.0.q05)),
            num(r.doubled.as_ref().map(|d| d.0.q50)),
            num(r.doubled.as_ref().map(|d| d.0.q95)),
            Value::Text(r.doubled.as_ref().map_or(String::new(), |d| d.1.name().to_string())),
        ])?;
    }
    Ok(t)
}

fn run(ctx: &Context) -> Result<Table> {
    table(&study(ctx, SAMPLES, SEED, true, |_| {})?)
}

/// Where a value sits against the claim's band, `asinh` of the distance from the paper's value
/// in half tolerances: 0 at the paper's value, `asinh(+-1)` at the band's edges, and values
/// tens of tolerances away still on the chart.
fn in_band(v: f64, (lo, hi): (f64, f64)) -> f64 {
    ((2.0 * v - lo - hi) / (hi - lo)).asinh()
}

/// Verdict colours (palette indices).
const COLOURS: [(&str, usize); 4] = [("holds", 3), ("part", 1), ("not at all", 5), ("independent", 6)];

fn chart(_: &Context, t: &Table) -> Chart {
    let col = |name: &str| super::col(t, name);
    let (lo, hi, q05, q95, nominal) = (col("band_lo"), col("band_hi"), col("q05"), col("q95"), col("nominal"));
    let verdicts = t.column_text("verdict").unwrap_or_default();
    let n = t.rows.len();
    let mut curves = Vec::new();
    let mut labelled = Vec::new();
    for k in 0..n {
        let band = (lo[k], hi[k]);
        let colour = COLOURS.iter().find(|(v, _)| *v == verdicts[k]).map_or(0, |c| c.1);
        let label = if labelled.contains(&colour) {
            String::new()
        } else {
            labelled.push(colour);
            format!("q05-q95: {}", verdicts[k])
        };
        let x = (k + 1) as f64;
        let (a, b) = (in_band(q05[k], band), in_band(q95[k], band));
        // a claim that does not vary is a short bar, so it is seen
        let (a, b) = if (b - a).abs() < 0.1 { (a - 0.05, b + 0.05) } else { (a, b) };
        curves.push(Curve::new(label, vec![x, x], vec![a, b]).with_color(colour));
    }
    let x: Vec<f64> = (1..=n).map(|k| k as f64).collect();
    let y: Vec<f64> = (0..n).map(|k| in_band(nominal[k], (lo[k], hi[k]))).collect();
    curves.push(Curve::new("nominal (the paper's inputs, fd)", x, y).with_style(LineStyle::Points).with_color(0));
    for edge in [-1.0f64, 1.0] {
        let label = if edge > 0.0 { "edges of the claim's tolerance" } else { "" };
        let y = edge.asinh();
        curves
            .push(Curve::new(label, vec![0.0, n as f64 + 1.0], vec![y, y]).with_style(LineStyle::Dashed).with_color(0));
    }
    Chart {
        x_range: Some((0.0, n as f64 + 1.0)),
        curves,
        ..Chart::new(
            format!("Claims under input uncertainty ({SAMPLES} x 11 samples, modal solver)"),
            "claim (row of figures/robustness.csv)",
            "asinh((value - paper) / half tolerance)",
        )
    }
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
        assert_eq!(in_band(3.0, (1.0, 3.0)), 1.0f64.asinh());
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
