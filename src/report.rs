//! The claims report: every number the paper states (SPEC.md section 4 and the rest of the
//! text), beside ours, with the relative error and a verdict.
//!
//! The claims live in `golden/paper_claims.csv` (compiled into the binary, so `report` runs from
//! anywhere): id, the experiment it belongs to, the sentence, its source, unit, the paper's
//! value, the tolerance within which we call it reproduced (relative, or absolute for claims of
//! "about zero"), and the verdict we expect, pinned so a regression that flips one fails a test.
//!
//! Every value is computed as the paper computed it and read as it read it, by one rule
//! ([`reading_rule`]: an impact the paper set up at the node its scheme loads, a value it read
//! off a curve between the computed nodes, each claim's reading decided from its quote); every
//! claim computed from a beam run has its converged value beside it (the same computation on
//! the converged beam, [`crate::experiments::claims::evaluate`]).

mod beyond;
mod robustness;

use crate::error::{Error, Result};
use crate::experiments::claims::{computations, evaluate_all, Moved, Reading};
use crate::experiments::{self, reading_rule, Context, Ours};
use crate::numfmt::{decisive, fmt_sig};

pub use crate::experiments::claims::{
    claims, tolerance_rule, Claim, Kind, ToleranceKind, Verdict, APPROXIMATE_REL_TOLERANCE, CLAIMS_CSV,
    MIN_REL_TOLERANCE,
};

/// A claim with our numbers.
#[derive(Debug, Clone)]
pub struct Row {
    /// The claim.
    pub claim: Claim,
    /// Our value, computed as the paper computed it and read as it read it (N = 39,
    /// [`reading_rule`]).
    pub ours: f64,
    /// The same computation with converged numerics (`hat` load, N = 320), for a claim computed
    /// from a beam run ([`Ours::converged`]).
    pub converged: Option<f64>,
    /// The same under the other reading, where an impact falls between two nodes
    /// ([`Ours::other`]).
    pub other: Option<f64>,
    /// The impacts between two nodes of the paper's beam.
    pub moved: Vec<Moved>,
    /// (ours - paper) / |paper|; for absolute claims, ours - paper (`None`: the paper states no
    /// number).
    pub error: Option<f64>,
    /// The tolerance applied, relative or absolute (`None`: the paper states no number, and the
    /// claim is judged by its conclusion at the paper's inputs).
    pub tolerance: Option<(ToleranceKind, f64)>,
    /// The values within which the claim counts as reproduced (`None` as for the tolerance).
    pub band: Option<(f64, f64)>,
    /// The verdict.
    pub verdict: Verdict,
    /// The verdict on the converged value, where there is one.
    pub converged_verdict: Option<Verdict>,
    /// The verdict under the other reading, where there is one ([`Row::other`]).
    pub other_verdict: Option<Verdict>,
}

impl Row {
    /// Reproduced, and the converged value (where the claim runs a beam) within the same
    /// tolerance too.
    pub fn also_converged(&self) -> bool {
        self.verdict == Verdict::Reproduced && self.converged_verdict != Some(Verdict::Differs)
    }
}

/// The verdict on a value against the band of a claim.
fn verdict_of(v: f64, (lo, hi): (f64, f64)) -> Verdict {
    if v >= lo && v <= hi {
        Verdict::Reproduced
    } else {
        Verdict::Differs
    }
}

/// The verdict of a claim the paper states no number for: its conclusion.
fn verdict_of_conclusion(holds: bool) -> Verdict {
    if holds {
        Verdict::Reproduced
    } else {
        Verdict::Differs
    }
}

/// Compute every claim (in parallel; the order of the claims file is kept).
pub fn evaluate() -> Result<Vec<Row>> {
    let claims = claims()?;
    let ours = evaluate_all(&claims, &Context::paper())?;
    rows(claims, ours)
}

/// The report's rows from the claims and their numbers ([`evaluate_all`]). A claim the paper
/// states no number for is judged by its conclusion, on the other claims' values at the same
/// numerics (converged with converged).
pub fn rows(claims: Vec<Claim>, ours: Vec<Ours>) -> Result<Vec<Row>> {
    let ids: Vec<String> = claims.iter().map(|c| c.id.clone()).collect();
    let values: Vec<f64> = ours.iter().map(|o| o.value).collect();
    let fine: Vec<f64> = ours.iter().map(|o| o.converged.unwrap_or(o.value)).collect();
    let others: Vec<f64> = ours.iter().map(|o| o.other.unwrap_or(o.value)).collect();
    let lookup = |all: &[f64], id: &str| ids.iter().position(|i| i == id).map(|j| all[j]);
    claims
        .into_iter()
        .zip(ours)
        .map(|(claim, Ours { value, converged, other, moved })| {
            let tolerance = claim.tolerance()?;
            let band = claim.band()?;
            let check = claim.check()?;
            let judge = |v: f64, all: &[f64]| match band {
                Some(b) => verdict_of(v, b),
                None => verdict_of_conclusion(check.holds(v, |id| lookup(all, id))),
            };
            let error = match tolerance {
                Some((ToleranceKind::Relative, _)) => Some((value - claim.paper_value()?) / claim.paper_value()?.abs()),
                Some((ToleranceKind::Absolute, _)) => Some(value - claim.paper_value()?),
                None => None,
            };
            Ok(Row {
                verdict: judge(value, &values),
                converged_verdict: converged.map(|c| judge(c, &fine)),
                other_verdict: other.map(|o| judge(o, &others)),
                claim,
                ours: value,
                converged,
                other,
                moved,
                error,
                tolerance,
                band,
            })
        })
        .collect()
}

/// A value of a row as the report prints it: to the digit that places it against the band (or
/// its conclusion's thresholds, for a claim without a number).
fn shown(r: &Row, v: f64) -> String {
    let edges: Vec<f64> = match r.band {
        Some((lo, hi)) => vec![lo, hi],
        None => r
            .claim
            .check()
            .map_or_else(|_| vec![], |c| c.thresholds(|_| None).into_iter().flatten().map(|t| t.1).collect()),
    };
    decisive(v, &edges, 4)
}

/// The tolerance column: the tolerance and the band of values it allows, each edge to the digit
/// that tells it from the values printed beside it; for a claim without a number, its
/// conclusion's form.
fn tolerance_text(r: &Row) -> String {
    let (Some((kind, tol)), Some((lo, hi))) = (r.tolerance, r.band) else {
        return format!("its conclusion, `{}`", r.claim.conclusion_check);
    };
    let values: Vec<f64> = std::iter::once(r.ours).chain(r.converged).chain(r.other).collect();
    format!("{} ({} to {})", fmt_rel_or_abs(kind, tol), decisive(lo, &values, 4), decisive(hi, &values, 4))
}

fn fmt_rel_or_abs(kind: ToleranceKind, v: f64) -> String {
    match kind {
        ToleranceKind::Relative => format!("{} %", fmt_sig(100.0 * v, 3)),
        ToleranceKind::Absolute => format!("{} (abs)", fmt_sig(v, 3)),
    }
}

/// " [N = 39: 10 cm -> node at 9.10 cm]" for a claim of an impact the paper set up between
/// two nodes, " [N = 39: 15.8 cm read between the nodes at 14.56 and 16.38 cm]" for one read
/// off a curve.
fn moved_text(r: &Row) -> String {
    if r.moved.is_empty() {
        return String::new();
    }
    let cm = |x: f64| format!("{:.2}", 100.0 * x);
    let pairs: Vec<String> = r
        .moved
        .iter()
        .map(|m| {
            let x = fmt_sig(100.0 * m.x, 4);
            match r.claim.reading {
                Reading::Impact => format!("{x} cm -> node at {} cm", cm(m.node)),
                Reading::Curve => {
                    format!("{x} cm read between the nodes at {} and {} cm", cm(m.between.0), cm(m.between.1))
                }
            }
        })
        .collect();
    format!(" [N = 39: {}]", pairs.join(", "))
}

/// How many of `rows` are of each kind: (reproductions, consistency checks, the paper's
/// statements judged against each other).
fn kinds<'a>(rows: impl Iterator<Item = &'a Row>) -> (usize, usize, usize) {
    rows.fold((0, 0, 0), |(r, c, s), row| match row.claim.kind {
        Kind::Reproduction => (r + 1, c, s),
        Kind::Consistency => (r, c + 1, s),
        Kind::Statements => (r, c, s + 1),
    })
}

/// "`id` (paper 4.78 ms, ours 4.777 ms at N = 39, converged 4.804 ms)".
fn both_text(r: &Row) -> String {
    let unit = if r.claim.unit == "1" { String::new() } else { format!(" {}", r.claim.unit) };
    format!(
        "`{}` (paper {}{unit}, ours {}{unit} at N = 39, converged {}{unit})",
        r.claim.id,
        paper_text(&r.claim),
        shown(r, r.ours),
        r.converged.map_or(String::new(), |c| shown(r, c))
    )
}

/// Text for a Markdown table cell: a `|` in it (`|e_A|`) escaped so it does not end the cell.
pub(crate) fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// The paper's value as printed, or that it states none.
fn paper_text(c: &Claim) -> String {
    if c.qualitative() {
        "(no number)".to_string()
    } else {
        c.paper.clone()
    }
}

fn list_or_none(items: Vec<String>) -> String {
    if items.is_empty() {
        "none".to_string()
    } else {
        items.join(", ")
    }
}

/// The report as Markdown.
pub fn markdown(rows: &[Row]) -> String {
    let model: Vec<&Row> = rows.iter().filter(|r| r.claim.kind != Kind::Statements).collect();
    let reproduced = model.iter().filter(|r| r.verdict == Verdict::Reproduced).count();
    let converged = model.iter().filter(|r| r.also_converged()).count();
    let beam = rows.iter().filter(|r| r.converged.is_some()).count();
    let qualitative = model.iter().filter(|r| r.claim.qualitative()).count();
    let (all_r, all_c, all_s) = kinds(rows.iter());
    let (rep_r, rep_c, _) = kinds(model.iter().copied().filter(|r| r.verdict == Verdict::Reproduced));
    let only_paper: Vec<String> = model
        .iter()
        .filter(|r| r.verdict == Verdict::Reproduced && !r.also_converged())
        .map(|r| both_text(r))
        .collect();
    let only_converged: Vec<String> = model
        .iter()
        .filter(|r| r.verdict == Verdict::Differs && r.converged_verdict == Some(Verdict::Reproduced))
        .map(|r| both_text(r))
        .collect();
    let statements: Vec<String> = rows
        .iter()
        .filter(|r| r.claim.kind == Kind::Statements)
        .map(|r| format!("`{}` ({})", r.claim.id, r.verdict.name()))
        .collect();
    let mut s = String::new();
    s.push_str(REPORT_HEAD);
    s.push_str(&format!("Reading rule, one for every claim: {}.\n\n", reading_rule(&Context::paper().racket)));
    let decided: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let other = r.other_verdict.filter(|v| *v != r.verdict)?;
            Some(format!(
                "`{}` (read as the paper read it, {}: {}; {}: {})",
                r.claim.id,
                r.claim.reading.name(),
                r.verdict.name(),
                match r.claim.reading {
                    Reading::Impact => "read off the curve",
                    Reading::Curve => "computed at the node",
                },
                other.name()
            ))
        })
        .collect();
    s.push_str(&format!(
        "The verdicts the reading decides (the other reading gives the other verdict): {}.\n\n",
        list_or_none(decided)
    ));
    s.push_str(&format!("Tolerances, one rule applied by code to every claim: {}.\n", tolerance_rule()));
    s.push_str(&format!(
        "\n*Kind*: a *reproduction* runs the model on something no other claim already checks; a *consistency* \
         check is arithmetic on the paper's inputs or on other claims' values (Eq 12 on p, 1/f1, a ratio of two \
         claimed e_A values, 30 rad/s times a claimed duration): agreement there confirms the paper's \
         arithmetic, not its model; a *statements* row is not a number the model computes but two statements \
         of the paper judged against each other, and is counted apart. Of the {} claims, {all_r} are \
         reproductions, {all_c} consistency checks and {all_s} statements.\n",
        rows.len()
    ));
    s.push_str(&format!(
        "\n**{reproduced} of the {} claims on the model reproduced with the paper's N = 39 scheme ({rep_r} \
         reproductions, {rep_c} consistency checks), {converged} of them also converged; {} differ** (each \
         difference is explained below; {qualitative} of the claims state no number and are judged by their \
         conclusion at the paper's inputs). Counted apart, the paper's two statements about k_s against each \
         other: {}. {beam} of the {} claims are computed, directly or through arithmetic on other values, from a \
         beam run: each has a converged value, its own computation run again on the converged beam (`hat` load, \
         N = 320, the force at the nominal position; a consistency check takes its inputs' converged values). \
         The other {} run no beam (the closed forms of the two drops, Eq 12, the tension calibration) and do not \
         depend on the discretisation. *Also converged*: reproduced, and the converged value (where there is \
         one) within the same tolerance. Reproduced only with the paper's unconverged scheme: {}. Differ with \
         the paper's scheme but reproduced converged: {}.\n\n",
        model.len(),
        model.len() - reproduced,
        list_or_none(statements),
        rows.len(),
        rows.len() - beam,
        list_or_none(only_paper),
        list_or_none(only_converged),
    ));
    s.push_str(
        "| id | kind | claim | source | unit | paper | tolerance | reading | ours (N = 39) | other reading | converged | error | verdict |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let c = &r.claim;
        let converged = r.converged.map_or(String::new(), |v| {
            let outside = if r.converged_verdict == Some(Verdict::Differs) { " (outside)" } else { "" };
            format!("{}{outside}", shown(r, v))
        });
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            c.id,
            c.kind.name(),
            cell(&c.claim),
            c.source,
            c.unit,
            paper_text(c),
            tolerance_text(r),
            c.reading.name(),
            shown(r, r.ours),
            r.other.map_or(String::new(), |v| shown(r, v)),
            converged,
            match (r.tolerance, r.error) {
                (Some((kind, _)), Some(e)) => fmt_rel_or_abs(kind, e),
                _ => String::new(),
            },
            if r.verdict == Verdict::Reproduced { "reproduced" } else { "**differs**" }
        ));
    }
    s.push_str("\n## Differences explained\n\n");
    for r in rows.iter().filter(|r| r.verdict == Verdict::Differs) {
        let unit = if r.claim.unit == "1" { String::new() } else { format!(" {}", r.claim.unit) };
        s.push_str(&format!(
            "- `{}` (paper {}{unit}, ours {}{unit}{}): {}\n",
            r.claim.id,
            paper_text(&r.claim),
            shown(r, r.ours),
            moved_text(r),
            r.claim.note
        ));
    }
    s.push_str("\n## How each reproduced number was computed\n\n");
    for r in rows.iter().filter(|r| r.verdict == Verdict::Reproduced) {
        s.push_str(&format!("- `{}`: {}{}\n", r.claim.id, r.claim.note, moved_text(r)));
    }
    s.push_str(UNCLAIMED);
    s.push_str(REPORT_TAIL);
    s
}

/// The whole report: the paper's claims ([`markdown`]), how robust each is under the declared
/// input uncertainty (`robustness::section`) and the section beyond the paper
/// (`beyond::section`).
pub fn document(rows: &[Row]) -> Result<String> {
    let ours: Vec<Ours> = rows
        .iter()
        .map(|r| Ours { value: r.ours, converged: r.converged, other: r.other, moved: r.moved.clone() })
        .collect();
    Ok(markdown(rows) + &calibration_table(rows)? + &robustness::section(&ours)? + &beyond::section()?)
}

/// The claims that move with the tension calibration, under both of the paper's readings:
/// ours (k_s proportional to the tension, 60 lb = 4e4 N/m) and the straight line through its
/// 2e4 N/m at 40 lb and 6e4 at 80 lb (`Context::tension_shape` 0 and 1), each with its verdict
/// (N = 39). A claim is listed when its value differs between the two, decided by running it.
pub fn calibration_table(rows: &[Row]) -> Result<String> {
    let claims: Vec<Claim> = rows.iter().map(|r| r.claim.clone()).collect();
    let line = Context { tension_shape: 1.0, ..Context::paper() }.remembering();
    let values: Vec<f64> = computations(&claims)?
        .iter()
        .zip(&claims)
        .map(|(pc, c)| (pc.ours)(&Context { scheme: c.reading.scheme(), ..line.clone() }))
        .collect::<Result<_>>()?;
    let mut s = String::from(
        "\nUnder the paper's other reading of the calibration, the straight line through 2e4 N/m at 40 lb and 6e4 \
         at 80 lb (50 lb = 3e4 N/m; the two readings agree at 60 lb), the tension claims move as follows (N = 39; \
         the `robustness` experiment draws the reading's shape between the two, input `tension_shape`).\n\n\
         | id | paper | tolerance | ks proportional (ours) | verdict | 2e4-6e4 N/m line | verdict |\n\
         |---|---|---|---|---|---|---|\n",
    );
    let (mut neither, mut ours_only, mut line_only) = (Vec::new(), Vec::new(), Vec::new());
    for (r, &v) in rows.iter().zip(&values) {
        if (v - r.ours).abs() <= 1e-12 * v.abs().max(1.0) {
            continue;
        }
        let judge = |x: f64| r.band.map_or(r.verdict, |b| verdict_of(x, b));
        let id = format!("`{}`", r.claim.id);
        match (judge(r.ours), judge(v)) {
            (Verdict::Differs, Verdict::Differs) => neither.push(id),
            (Verdict::Reproduced, Verdict::Differs) => ours_only.push(id),
            (Verdict::Differs, Verdict::Reproduced) => line_only.push(id),
            _ => {}
        }
        let verdict = |x: f64| if judge(x) == Verdict::Reproduced { "reproduced" } else { "**differs**" };
        s.push_str(&format!(
            "| `{}` | {} {} | {} | {} | {} | {} | {} |\n",
            r.claim.id,
            paper_text(&r.claim),
            r.claim.unit,
            tolerance_text(r),
            shown(r, r.ours),
            verdict(r.ours),
            shown(r, v),
            verdict(v),
        ));
    }
    s.push_str(&format!(
        "\nDiffer under both readings, on either side of the paper's values (the calibration, not the model, \
         decides how far): {}. Reproduced only with ours: {}. Reproduced only with the 2e4-6e4 line: {}.\n",
        list_or_none(neither),
        list_or_none(ours_only),
        list_or_none(line_only)
    ));
    Ok(s)
}

/// Check the claims file: unique ids, positive tolerances, a computation for each claim and a
/// conclusion check that parses and compares only with listed claims (cheap: it does not run
/// the solver).
pub fn check_claims_file() -> Result<Vec<Claim>> {
    let claims = claims()?;
    let mut ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
    ids.sort_unstable();
    if let Some(w) = ids.windows(2).find(|w| w[0] == w[1]) {
        return Err(Error::invalid("claim id", w[0], "ids in golden/paper_claims.csv must be unique"));
    }
    for c in &claims {
        let tol = c.tolerance()?.map_or(1.0, |t| t.1);
        if !(tol.is_finite() && tol > 0.0) {
            return Err(Error::invalid("tolerance", tol, format!("claim {} needs a tolerance > 0", c.id)));
        }
        if experiments::find(&c.experiment).is_err() {
            return Err(Error::invalid("experiment", &c.experiment, format!("claim {} names no experiment", c.id)));
        }
        computations(std::slice::from_ref(c))?;
        for other in c.check()?.references() {
            if !claims.iter().any(|o| o.id == other) {
                return Err(Error::invalid(
                    "conclusion_check",
                    &c.conclusion_check,
                    format!("claim {} compares with {other}, which golden/paper_claims.csv does not list", c.id),
                ));
            }
        }
    }
    for e in experiments::registry() {
        for pc in e.claims {
            if !claims.iter().any(|c| c.id == pc.id && c.experiment == e.id) {
                return Err(Error::invalid(
                    "claim id",
                    pc.id,
                    format!("experiment {} computes a claim that golden/paper_claims.csv does not list for it", e.id),
                ));
            }
        }
    }
    Ok(claims)
}

const REPORT_HEAD: &str = "# Replication report: Cross (2000), string tension and frame stiffness\n\n\
Generated by `racket-impact report` (also run by `make figures`); do not edit by hand. Every \
number the paper states is set beside ours. *ours* is computed as the paper computed it and \
read as the paper read it (N = 39 segments; the reading rule below), and carries the verdict: \
the result of an impact the paper set up is computed with the whole force on the node its scheme \
loads, a value it read off a curve against position is read off ours between the two computed \
nodes. *reading* says which (`impact` or `curve`), decided from the claim's quote alone. Where an \
impact falls between two nodes, *other reading* is the same computation read the other way. \
*converged* is the same computation with the force shared between the two neighbouring nodes \
(`hat`) on N = 320 segments, at the nominal position. Each value is printed to the digit \
that places it against the claim's tolerance (given as the band of values it allows). A value \
printed with one significant digit gets a wide tolerance (\"2 %\" covers 1.5 to 2.5 %, \"2e4\" \
1.5e4 to 2.5e4): that is what the paper's precision allows us to check. The claims, their kinds, \
conclusions, tolerances and pinned verdicts are in `golden/paper_claims.csv`.\n\n";

/// The paper's conclusion sentences that carry no claim, and why (the others are claims above).
const UNCLAIMED: &str = "\n## The paper's sentences without a claim\n\n\
Every conclusion the paper draws from its model is a claim above, with a checkable form; these \
sentences are not, and why:\n\n\
- \"The results show that the only vibration mode of any significance is the fundamental mode at \
125 Hz\" (p. 4): an impact's result gives its vibration energy, not its share in each mode.\n\
- \"e_A ... increases to a broad maximum near the throat of the racket\" (p. 5): the paper does not \
place the throat; our uniform beam's curve peaks at its middle (Fig 5), beyond the string face.\n\
- \"the ball usually leaves the strings before the impulse is reflected off the hand\" (p. 2): a \
result the paper cites (Brody 1997; Cross 1999a) for its free racket, not one it computes; \
`variant_grip` sets a hand-held racket beside the free one.\n\
- \"any effect due to the nonlinear nature of the strings is clearly of little consequence\" (p. 3): \
an inference from the factor-two result, with no nonlinear calculation in the paper; \
`variant_strings` sets stiffening strings beside the linear ones.\n\
- \"If the racket head moves in a straight line path, any change in impact duration has no effect at \
all on the initial rebound path of the ball\" (p. 7): kinematics, true whatever the model.\n\
- The paper's reasons why wide-body rackets lost favour and what players report (p. 6-7), and its \
conjecture that tension acts through the ball's friction on the strings (p. 7): not results of its \
model (the conjecture is taken up beyond the paper, `oblique_tension`).\n\
\n\
The paper's figures are not in its text we hold (only their captions), so no curve of ours is \
overlaid on one of the paper's: each figure marks the values the paper states in words.\n";

const REPORT_TAIL: &str = "\n## Parameters the paper did not state, and what we chose\n\n\
- **Ball mass**: the paper gives 56.7 g (rules) and 57 g (force estimate); we use 57 g, which \
reproduces its concrete-drop duration (4.64 ms) and Fig 4.\n\
- **k2**: the paper prints `k2 = k1 Y0^(p-1)`; that contradicts `k1 Y0 = k2 Y0^p` one line \
earlier and has the wrong dimension. We use `k2 = k1 Y0^(1-p)`.\n\
- **Free-end discretisation**: the paper does not say how Eq 6 is closed at the free ends. We \
use `K = (EI/s^3) D^T D` on N+1 nodes with half masses at the ends (energy-consistent, exactly \
two rigid-body modes); it gives 124.7 Hz and 342.6 Hz for the paper's racket (125 and 345 Hz).\n\
- **Which node carries the force**: the paper puts the force on \"only one of the segments\"; \
we use the node nearest x (ties up). At x = 10 cm that is 9.10 cm.\n\
- **Time step**: not stated. Ours is half the stability limit or 2e-3 rad of the stiffest \
contact oscillation per step, whichever is smaller; halving it changes e_A and tau by < 1e-6.\n\
- **Incident speed**: not stated for Figs 4-6 and 9 (e_A, tau and every energy fraction are \
independent of it in this model); we use the 100-inch drop speed 7.06 m/s. Figs 7-8: 30 m/s as \
stated.\n\
- **Vibration energy**: the paper takes the peak bending PE after the impact; we report that \
(`f_vib_peak_pe`, over two fundamental periods) and also the exact vibration energy (racket \
energy minus its rigid-body energy, `f_vib`); they agree to better than 1 % where vibration \
matters.\n\
- **String tension to k_s**: the paper states no calibration. It says k_s is \"directly \
proportional\" to the tension and calls 2e4 and 4e4 N/m a factor two in tension; its 60 -> 50 lb \
serve and forehand gains (its factor-two gains divided by 3) read 4e4 N/m as 60 lb and 2e4 as 30 \
lb. We adopt that reading: k_s proportional to tension, 60 lb = 4e4 N/m (ours, inferred from \
the paper's arithmetic), and compute 50 lb = 3.33e4 N/m directly. Its 2e4-6e4 N/m for 40-80 lb \
fits no proportional calibration (a factor 3 in k_s for a factor 2 in tension): rows \
`strings_ks_40lb` and `strings_ks_80lb` judge those two statements against each other (kind \
*statements*, not a number the model computes, counted apart). Read as a straight line through \
2e4 at 40 lb and 6e4 at 80 lb, 50 lb is 3e4 N/m; both readings are shown below (\"The 60 -> 50 \
lb rule\") and in `speeds` (the lower panel), and the robustness study draws the calibration's \
shape between them.\n\
\n## The 60 -> 50 lb rule\n\n\
The paper derives its tension claims by scaling its factor-two results, and not consistently: \
the serve (+2 % -> +0.7 %) and forehand (+3.3 % -> +1.1 %) gains are divided by 3, while the \
duration (+1 ms -> +0.2 ms) and rotation (19 % -> 4 %) changes are divided by 5. A 60 -> 50 lb \
change is a factor 1.2 in k_s. We compute it directly (rows `speeds_60_50_*`, \
`speeds_50_60_theta_change`, `discussion_angle_30_rad_s`); where our direct value differs from \
the paper's scaled one, the row says so and the explanation gives the paper's scaling.\n";
