//! The claims report: every number the paper states (SPEC.md section 4 and the rest of the
//! text), beside ours, with the relative error and a verdict.
//!
//! The claims live in `golden/paper_claims.csv` (compiled into the binary, so `report` runs from
//! anywhere): id, the experiment it belongs to, the sentence, its source, unit, the paper's
//! value, the tolerance within which we call it reproduced (relative, or absolute for claims of
//! "about zero"), and the verdict we expect, pinned so a regression that flips one fails a test.
//!
//! Claims read off a curve at a point between nodes are computed as a reader of the printed
//! figure would (linear interpolation of the N = 39 node-scheme curve), and reported beside the
//! nearest-node value and the converged value (`hat` load, N = 320).

mod beyond;
mod robustness;

use crate::error::{Error, Result};
use crate::experiments::{self, Context, Ours, PaperClaim};
use crate::numfmt::fmt_sig;

pub use crate::experiments::claims::{
    claims, tolerance_rule, Claim, Kind, ToleranceKind, Verdict, APPROXIMATE_REL_TOLERANCE, CLAIMS_CSV,
    MIN_REL_TOLERANCE,
};

/// A claim with our numbers.
#[derive(Debug, Clone)]
pub struct Row {
    /// The claim.
    pub claim: Claim,
    /// Our value, computed as the paper did (N = 39 node scheme, read off as a reader would).
    pub ours: f64,
    /// The value at the nearest node, where the claim is read off between nodes.
    pub nearest_node: Option<f64>,
    /// The converged value (`hat` load, N = 320), where numerics matter.
    pub converged: Option<f64>,
    /// (ours - paper) / |paper|; for absolute claims, ours - paper.
    pub error: f64,
    /// The tolerance applied.
    pub tolerance: f64,
    /// Relative or absolute.
    pub kind: ToleranceKind,
    /// The verdict.
    pub verdict: Verdict,
}

/// Our numbers for one claim, computed by the experiment the claim names, on the paper's
/// racket.
fn compute(claim: &Claim, ctx: &Context) -> Result<Ours> {
    (computation(claim)?.ours)(ctx)
}

/// The experiment's computation of a claim.
fn computation(claim: &Claim) -> Result<PaperClaim> {
    let experiment = experiments::find(&claim.experiment)?;
    experiment
        .claims
        .iter()
        .find(|c| c.id == claim.id)
        .copied()
        .ok_or_else(|| Error::invalid("claim id", &claim.id, "no computation is defined for this claim"))
}

impl Row {
    /// Reproduced, and the converged value (where the numerics matter) within the same
    /// tolerance too.
    pub fn also_converged(&self) -> bool {
        self.verdict == Verdict::Reproduced
            && self.converged.is_none_or(|c| {
                let paper = self.claim.paper_value().unwrap_or(f64::NAN);
                let error = match self.kind {
                    ToleranceKind::Relative => (c - paper) / paper.abs(),
                    ToleranceKind::Absolute => c - paper,
                };
                error.abs() <= self.tolerance
            })
    }
}

/// Compute every claim (in parallel; the order of the claims file is kept).
pub fn evaluate() -> Result<Vec<Row>> {
    use rayon::prelude::*;
    let ctx = Context::paper();
    claims()?
        .into_par_iter()
        .map(|claim| {
            let Ours { value: ours, nearest_node, converged } = compute(&claim, &ctx)?;
            let paper = claim.paper_value()?;
            let (kind, tolerance) = claim.tolerance()?;
            let error = match kind {
                ToleranceKind::Relative => (ours - paper) / paper.abs(),
                ToleranceKind::Absolute => ours - paper,
            };
            let verdict = if error.abs() <= tolerance { Verdict::Reproduced } else { Verdict::Differs };
            Ok(Row { claim, ours, nearest_node, converged, error, tolerance, kind, verdict })
        })
        .collect()
}

fn fmt_opt(v: Option<f64>) -> String {
    fmt_opt_sig(v, 4)
}

fn fmt_opt_sig(v: Option<f64>, digits: usize) -> String {
    v.map(|v| fmt_sig(v, digits)).unwrap_or_default()
}

fn fmt_rel_or_abs(kind: ToleranceKind, v: f64) -> String {
    match kind {
        ToleranceKind::Relative => format!("{} %", fmt_sig(100.0 * v, 3)),
        ToleranceKind::Absolute => format!("{} (abs)", fmt_sig(v, 3)),
    }
}

/// How many of `rows` are of each kind: (reproductions, consistency checks).
fn kinds<'a>(rows: impl Iterator<Item = &'a Row>) -> (usize, usize) {
    rows.fold((0, 0), |(r, c), row| match row.claim.kind {
        Kind::Reproduction => (r + 1, c),
        Kind::Consistency => (r, c + 1),
    })
}

/// The report as Markdown.
pub fn markdown(rows: &[Row]) -> String {
    let reproduced = rows.iter().filter(|r| r.verdict == Verdict::Reproduced).count();
    let converged = rows.iter().filter(|r| r.also_converged()).count();
    let numerics_free = rows.iter().filter(|r| r.verdict == Verdict::Reproduced && r.converged.is_none()).count();
    let (all_r, all_c) = kinds(rows.iter());
    let (rep_r, rep_c) = kinds(rows.iter().filter(|r| r.verdict == Verdict::Reproduced));
    let unconverged: Vec<String> = rows
        .iter()
        .filter(|r| r.verdict == Verdict::Reproduced && !r.also_converged())
        .map(|r| {
            let unit = if r.claim.unit == "1" { String::new() } else { format!(" {}", r.claim.unit) };
            format!(
                "`{}` (paper {}{unit}, ours {}{unit} at N = 39, converged {}{unit})",
                r.claim.id,
                r.claim.paper,
                fmt_sig(r.ours, 3),
                fmt_opt_sig(r.converged, 3)
            )
        })
        .collect();
    let mut s = String::new();
    s.push_str(REPORT_HEAD);
    s.push_str(&format!("Tolerances, one rule applied by code to every claim: {}.\n", tolerance_rule()));
    s.push_str(&format!(
        "\n*Kind*: a *reproduction* runs the model on something no other claim already checks; a *consistency* \
         check is arithmetic on the paper's inputs or on other claims' values (Eq 12 on p, 1/f1, a ratio of two \
         claimed e_A values, 30 rad/s times a claimed duration, the tension calibration): agreement there \
         confirms the paper's arithmetic, not its model. Of the {} claims, {all_r} are reproductions and \
         {all_c} consistency checks.\n",
        rows.len()
    ));
    s.push_str(&format!(
        "\n**{reproduced} of {} claims reproduced with the paper's N = 39 scheme ({rep_r} reproductions, {rep_c} \
         consistency checks), {converged} of them also converged, {} differ** (each difference is explained \
         below). *Also converged*: the converged value (`hat` load, N = 320) is within the same tolerance, or \
         the claim does not depend on the discretisation ({numerics_free} of them, no converged column); the \
         other {} hold only with the paper's unconverged node scheme: {}.\n\n",
        rows.len(),
        rows.len() - reproduced,
        reproduced - converged,
        if unconverged.is_empty() { "none".to_string() } else { unconverged.join(", ") }
    ));
    s.push_str(
        "| id | kind | claim | source | unit | paper | ours | nearest node | converged | error | tolerance | verdict |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let c = &r.claim;
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            c.id,
            c.kind.name(),
            c.claim,
            c.source,
            c.unit,
            c.paper,
            fmt_sig(r.ours, 4),
            fmt_opt(r.nearest_node),
            fmt_opt(r.converged),
            fmt_rel_or_abs(r.kind, r.error),
            fmt_rel_or_abs(r.kind, r.tolerance),
            if r.verdict == Verdict::Reproduced { "reproduced" } else { "**differs**" }
        ));
    }
    s.push_str("\n## Differences explained\n\n");
    for r in rows.iter().filter(|r| r.verdict == Verdict::Differs) {
        let unit = if r.claim.unit == "1" { String::new() } else { format!(" {}", r.claim.unit) };
        s.push_str(&format!(
            "- `{}` (paper {}{unit}, ours {}{unit}): {}\n",
            r.claim.id,
            r.claim.paper,
            fmt_sig(r.ours, 4),
            r.claim.note
        ));
    }
    s.push_str("\n## How each reproduced number was computed\n\n");
    for r in rows.iter().filter(|r| r.verdict == Verdict::Reproduced) {
        s.push_str(&format!("- `{}`: {}\n", r.claim.id, r.claim.note));
    }
    s.push_str(REPORT_TAIL);
    s
}

/// The whole report: the paper's claims ([`markdown`]), how robust each is under the declared
/// input uncertainty (`robustness::section`) and the section beyond the paper
/// (`beyond::section`).
pub fn document(rows: &[Row]) -> Result<String> {
    Ok(markdown(rows) + &robustness::section()? + &beyond::section()?)
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
        let (_, tol) = c.tolerance()?;
        if !(tol.is_finite() && tol > 0.0) {
            return Err(Error::invalid("tolerance", tol, format!("claim {} needs a tolerance > 0", c.id)));
        }
        if experiments::find(&c.experiment).is_err() {
            return Err(Error::invalid("experiment", &c.experiment, format!("claim {} names no experiment", c.id)));
        }
        computation(c)?;
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
number the paper states is set beside ours. *ours* is computed the way the paper computed it \
(N = 39 segments, force on the nearest node); where the paper reads a value off a curve \
between nodes (the centre of the strings, 15.8 cm, lies between nodes 8 and 9), *ours* is the \
linear interpolation of that curve, *nearest node* is node 9 (16.4 cm) and *converged* is the \
same impact with the force shared between neighbouring nodes (`hat`) on N = 320 segments. \
A value printed with one significant digit gets a wide tolerance (\"2 %\" covers 1.5 to 2.5 %, \
\"2e4\" 1.5e4 to 2.5e4): that is what the paper's precision allows us to check. The claims, \
their kinds, conclusions, tolerances and pinned verdicts are in `golden/paper_claims.csv`.\n\n";

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
`strings_ks_40lb` and `strings_ks_80lb`.\n\
\n## The 60 -> 50 lb rule\n\n\
The paper derives its tension claims by scaling its factor-two results, and not consistently: \
the serve (+2 % -> +0.7 %) and forehand (+3.3 % -> +1.1 %) gains are divided by 3, while the \
duration (+1 ms -> +0.2 ms) and rotation (19 % -> 4 %) changes are divided by 5. A 60 -> 50 lb \
change is a factor 1.2 in k_s. We compute it directly (rows `speeds_60_50_*`, \
`speeds_50_60_theta_change`, `discussion_angle_30_rad_s`); where our direct value differs from \
the paper's scaled one, the row says so and the explanation gives the paper's scaling.\n";
