//! A paper claim as an experiment carries it: the claim's id (its row in
//! `golden/paper_claims.csv`, which holds the sentence, the paper's value and the tolerance)
//! and how we compute our number for it. [`crate::report`] collects them from the registry.
//! The claims table itself (the rows of that file, their tolerances and expected verdicts) is
//! read here, below the report, so that experiments that sample the claims (`robustness`) need
//! nothing from the report.

use serde::Deserialize;

pub use super::conclusion::Check;
pub use super::setup::reading_rule;
use super::setup::{Context, Scheme};
use crate::error::{Error, Result};

/// The claims file, compiled in.
pub const CLAIMS_CSV: &str = include_str!("../../golden/paper_claims.csv");

/// How a tolerance is applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ToleranceKind {
    /// |ours - paper| <= tolerance |paper|.
    Relative,
    /// |ours - paper| <= tolerance (for claims of "about zero").
    Absolute,
}

/// Reproduced or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// Within tolerance.
    Reproduced,
    /// Outside tolerance (explained in the report).
    Differs,
}

impl Verdict {
    /// The word used in the report and the claims file.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::Differs => "differs",
        }
    }
}

pub use super::tolerance::{
    about_band, is_approximate, last_digit_unit, APPROXIMATE_REL_TOLERANCE, APPROXIMATE_WORDS, MIN_REL_TOLERANCE,
};

/// What agreement on a claim shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// Our number comes from running the model on something no other claim already checks:
    /// agreement is independent evidence.
    Reproduction,
    /// Our number is arithmetic on the paper's inputs or on other claims' values (Eq 12 on p,
    /// 1/f1, a ratio of two claimed e_A, 30 rad/s times a claimed duration): agreement checks
    /// the paper's arithmetic, not its model.
    Consistency,
    /// Not a number the model computes: two statements of the paper judged against each other
    /// (its 2e4-6e4 N/m for 40-80 lb against its "directly proportional" and its 60 -> 50 lb
    /// arithmetic); counted apart from the claims on the model.
    Statements,
}

impl Kind {
    /// The word used in the report and the claims file.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Reproduction => "reproduction",
            Kind::Consistency => "consistency",
            Kind::Statements => "statements",
        }
    }
}

/// How the paper got a value it states, decided from its quote alone ([`reading_rule`]): the
/// result of a computation it set up, or a value it read off a curve it plotted against
/// position.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Reading {
    /// The result of a computation the paper set up (an impact at a position its caption or
    /// text states, a drop, the beam's modes, arithmetic on its inputs): computed as the paper
    /// computed it, with the force on the node its N = 39 scheme loads ([`Scheme::Paper`]).
    Impact,
    /// A value the paper read off a curve it plotted against position (Fig 5) at a point it
    /// did not compute (the centre of the strings, the node at 16 cm), or derived from such
    /// values: read off our N = 39 curve between the two computed nodes ([`Scheme::Curve`]).
    Curve,
}

impl Reading {
    /// The word used in the report and the claims file.
    pub fn name(self) -> &'static str {
        match self {
            Reading::Impact => "impact",
            Reading::Curve => "curve",
        }
    }

    /// The numerics of the reading on the paper's beam.
    pub fn scheme(self) -> Scheme {
        match self {
            Reading::Impact => Scheme::Paper,
            Reading::Curve => Scheme::Curve,
        }
    }

    /// The other reading, which the report sets beside it.
    pub fn other(self) -> Reading {
        match self {
            Reading::Impact => Reading::Curve,
            Reading::Curve => Reading::Impact,
        }
    }
}

/// One row of `golden/paper_claims.csv`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Claim {
    /// Unique id; also selects the computation.
    pub id: String,
    /// The experiment (figure) the claim belongs to.
    pub experiment: String,
    /// The claim in words.
    pub claim: String,
    /// Where the paper says it.
    pub source: String,
    /// Unit of `paper` and of ours.
    pub unit: String,
    /// The paper's words stating the value, as printed (notation transliterated: `k_s`, `4e4`,
    /// `N/m`, `deg`), and the words its value is derived from where the sentence refers back to
    /// them; pieces from different places joined by " / ", each opening with a label in
    /// brackets where it is not the same paragraph (`(Conclusions) `). Whether the value is
    /// approximate is read from them ([`Claim::approximate`]), and how it is read
    /// ([`Claim::reading`]).
    pub quote: String,
    /// How the paper got the value ([`Reading`]), decided from the quote alone.
    pub reading: Reading,
    /// The words of the quote that decide the reading.
    pub reading_words: String,
    /// The paper's value exactly as printed (its last digit sets the tolerance); empty where
    /// the paper states no number and the claim is its conclusion alone ([`Claim::qualitative`]).
    pub paper: String,
    /// For claims of "about zero" (and of a law's deviation, 0 %): the absolute tolerance;
    /// otherwise empty.
    pub abs_tolerance: Option<f64>,
    /// The verdict we expect (pinned).
    pub expected: Verdict,
    /// The verdict we expect on the converged value (pinned; empty for a claim that runs no
    /// beam).
    pub expected_converged: Option<Verdict>,
    /// An independent reproduction or a consistency check.
    pub kind: Kind,
    /// What the paper concludes from the number, in words.
    pub conclusion: String,
    /// The same in a form [`Check`] evaluates (`> 0 and < 2`, `< other_id`, `> 1.5 * other_id`,
    /// `about 20`).
    pub conclusion_check: String,
    /// Where the conclusion's thresholds come from: the paper's words, or ours with the reason.
    pub threshold_source: String,
    /// Why the model makes the conclusion true by construction, where it does (empty otherwise):
    /// true whatever the inputs, or set by an input chosen to give it (EI chosen for the paper's
    /// 125 and 200 Hz). Such a conclusion is labelled so and not counted as support.
    pub by_construction: String,
    /// Why it differs, or how it is computed (one line; shown in the report).
    pub note: String,
}

impl Claim {
    /// The paper states no number: the claim is judged by its conclusion alone.
    pub fn qualitative(&self) -> bool {
        self.paper.trim().is_empty()
    }

    /// Whether the paper calls the value approximate: its words ([`Claim::quote`]) use one of
    /// [`APPROXIMATE_WORDS`].
    pub fn approximate(&self) -> bool {
        is_approximate(&self.quote)
    }

    /// The conclusion holds by construction of the model ([`Claim::by_construction`]).
    pub fn by_construction(&self) -> bool {
        !self.by_construction.trim().is_empty()
    }

    /// The paper's value as a number (an error for a qualitative claim).
    pub fn paper_value(&self) -> Result<f64> {
        self.paper.parse().map_err(|_| Error::invalid("paper", &self.paper, format!("claim {}: not a number", self.id)))
    }

    /// The tolerance within which we call the claim reproduced ([`tolerance_rule`] in words):
    /// an absolute bound for claims of "about zero"; otherwise half a unit of the last printed
    /// digit ([`last_digit_unit`]) relative to the value, at least [`MIN_REL_TOLERANCE`], or
    /// [`APPROXIMATE_REL_TOLERANCE`] for approximate values; `None` for a qualitative claim.
    pub fn tolerance(&self) -> Result<Option<(ToleranceKind, f64)>> {
        if self.qualitative() {
            return Ok(None);
        }
        if let Some(a) = self.abs_tolerance {
            return Ok(Some((ToleranceKind::Absolute, a)));
        }
        let t = super::tolerance::relative_tolerance(&self.paper, self.approximate()).ok_or_else(|| {
            Error::invalid(
                "paper",
                &self.paper,
                format!("claim {}: a non-zero number, or 0 with abs_tolerance", self.id),
            )
        })?;
        Ok(Some((ToleranceKind::Relative, t)))
    }

    /// The values within which the claim counts as reproduced (`None` for a qualitative claim).
    pub fn band(&self) -> Result<Option<(f64, f64)>> {
        let Some((kind, tol)) = self.tolerance()? else { return Ok(None) };
        let paper = self.paper_value()?;
        let half = match kind {
            ToleranceKind::Relative => tol * paper.abs(),
            ToleranceKind::Absolute => tol,
        };
        Ok(Some((paper - half, paper + half)))
    }

    /// The conclusion's checkable form, parsed.
    pub fn check(&self) -> Result<Check> {
        Check::parse(&self.id, &self.conclusion_check)
    }
}

/// The tolerance rule in words, stated once: the report's head gives it, the robustness
/// section refers to it.
pub fn tolerance_rule() -> String {
    format!(
        "a claim is reproduced when ours is within half a unit of the last digit the paper prints (in \
         scientific notation, of the mantissa's last digit: \"2e4\" is 2 +- 0.5 e4, as \"2\" is 2 +- 0.5), relative \
         to the paper's value and at least {} %; for a value the paper calls approximate (its sentence stating \
         the value says {}) at least {} %, the one reading of \"about\" that the conclusions' `about X` forms \
         apply too; for a claim of \"about zero\" within the absolute bound the claims file states with it; and a \
         claim for which the paper states no number is judged by its conclusion alone",
        100.0 * MIN_REL_TOLERANCE,
        APPROXIMATE_WORDS.iter().map(|w| format!("\"{w}\"")).collect::<Vec<_>>().join(", "),
        100.0 * APPROXIMATE_REL_TOLERANCE
    )
}

/// Parse the compiled-in claims.
pub fn claims() -> Result<Vec<Claim>> {
    parse_claims(CLAIMS_CSV)
}

/// Parse a claims file's text (the columns of [`Claim`], each required).
pub fn parse_claims(text: &str) -> Result<Vec<Claim>> {
    let mut rdr = csv::Reader::from_reader(text.as_bytes());
    rdr.deserialize()
        .map(|r| r.map_err(|e| Error::Config { path: "golden/paper_claims.csv".into(), message: e.to_string() }))
        .collect()
}

/// Our numbers for one claim ([`evaluate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Ours {
    /// Computed as the paper computed it and read as it read it ([`Claim::reading`],
    /// [`reading_rule`]): N = 39, an impact the paper set up with the force on the node its
    /// scheme loads, a value it read off a curve between the two computed nodes.
    pub value: f64,
    /// The same computation with converged numerics (`hat` load, N = 320), for a claim computed
    /// (directly, or through arithmetic on other values) from a beam run; `None` for one that
    /// runs no beam (a closed form, the paper's inputs, the tension calibration).
    pub converged: Option<f64>,
    /// For a claim with an impact between two nodes of the paper's beam: the same computation
    /// under the other reading ([`Reading::other`]), set beside the value.
    pub other: Option<f64>,
    /// The impacts between two nodes of the paper's beam, each position once, in order.
    pub moved: Vec<Moved>,
}

/// An impact position between two nodes of the paper's N = 39 beam, m from the tip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moved {
    /// The nominal position.
    pub x: f64,
    /// The node the paper's scheme loads (the nearest, ties towards the handle).
    pub node: f64,
    /// The two nodes a curve is read between.
    pub between: (f64, f64),
}

/// One claim of the paper that an experiment checks.
#[derive(Clone, Copy)]
pub struct PaperClaim {
    /// The claim's id in `golden/paper_claims.csv`.
    pub id: &'static str,
    /// Our number for it on a context (the report passes the paper's): every beam it runs goes
    /// through [`Context::impact`] or [`Context::modes`], so that the context's numerics
    /// ([`Scheme`]) decide them and its record sees them.
    pub ours: fn(&Context) -> Result<f64>,
}

/// The computation of each claim of the claims file, in its order.
pub fn computations(claims: &[Claim]) -> Result<Vec<PaperClaim>> {
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

/// Every claim's numbers on `base` ([`evaluate`]), in the order of `claims`, computed in
/// parallel; the claims share the impacts they have in common.
pub fn evaluate_all(claims: &[Claim], base: &Context) -> Result<Vec<Ours>> {
    use rayon::prelude::*;
    let base = base.clone().remembering();
    let readings: Vec<Reading> = claims.iter().map(|c| c.reading).collect();
    let watch = crate::control::current();
    computations(claims)?
        .into_par_iter()
        .zip(readings)
        .map(|(pc, reading)| crate::control::within(watch.as_ref(), || evaluate(pc, reading, &base)))
        .collect()
}

/// A claim's numbers on `base` (its numerics the paper's beam): the value under the claim's
/// reading, the other reading beside it where an impact falls between two nodes, and where the
/// computation ran a beam, the same computation on `base` with converged numerics. What the
/// value is computed from decides whether it has a converged counterpart: the record of the
/// beams it ran ([`Context::recording`]), not a column of the claims file. A computation that
/// runs a beam with the paper's numerics on a converged context (numerics of its own, not the
/// context's) is an error: its "converged" value would not be.
pub fn evaluate(claim: PaperClaim, reading: Reading, base: &Context) -> Result<Ours> {
    let ctx = Context { scheme: Scheme::Paper, ..base.clone() }.recording();
    let at_node = (claim.ours)(&ctx)?;
    let runs = ctx.runs.taken();
    let spacing = base.racket.length / Scheme::Paper.numerics().1 as f64;
    let mut moved: Vec<Moved> = runs
        .iter()
        .filter_map(|r| Some((r.x?, r.x_load?)))
        .filter(|(x, at)| (x - at).abs() > 1e-9)
        .map(|(x, node)| {
            let j = (x / spacing).floor();
            Moved { x, node, between: (j * spacing, (j + 1.0) * spacing) }
        })
        .collect();
    moved.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.node.total_cmp(&b.node)));
    moved.dedup();
    let converged = if runs.is_empty() {
        None
    } else {
        let fine = base.clone().converged().recording();
        let v = (claim.ours)(&fine)?;
        if let Some(r) = fine.runs.taken().iter().find(|r| !r.under(Scheme::Converged)) {
            return Err(Error::invalid(
                "claim",
                claim.id,
                format!(
                    "its computation ran a beam of {} segments ({:?} load) on a converged context: it must take its \
                     numerics from the context",
                    r.segments, r.load
                ),
            ));
        }
        Some(v)
    };
    let on_curve = || (claim.ours)(&Context { scheme: Scheme::Curve, ..base.clone() });
    let (value, other) = match (reading, moved.is_empty()) {
        (_, true) => (at_node, None),
        (Reading::Impact, false) => (at_node, Some(on_curve()?)),
        (Reading::Curve, false) => (on_curve()?, Some(at_node)),
    };
    Ok(Ours { value, converged, other, moved })
}

impl std::fmt::Debug for PaperClaim {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PaperClaim").field("id", &self.id).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn approximate_is_read_from_the_papers_words() {
        let claims = claims().unwrap();
        let get = |id: &str| claims.iter().find(|c| c.id == id).unwrap();
        // one sentence, "typically about 125 Hz (period T = 8 ms)": both approximate
        assert!(get("modes_f1").approximate() && get("modes_period").approximate());
        // the Conclusions say "about 0.7 %"
        assert!(get("speeds_60_50_serve_gain").approximate());
        assert!(!get("fig5_centre_e_a_soft").approximate() && !get("fig8_theta_r4_60lb").approximate());
        assert_eq!(get("modes_f1").tolerance().unwrap(), Some((ToleranceKind::Relative, APPROXIMATE_REL_TOLERANCE)));
        for c in &claims {
            assert!(!c.quote.trim().is_empty(), "{}: no quote", c.id);
            assert!(!c.threshold_source.trim().is_empty(), "{}: no threshold source", c.id);
            assert_eq!(c.qualitative(), c.tolerance().unwrap().is_none(), "{}", c.id);
        }
    }

    /// A claim read off a curve takes the straight line between the impacts on the two nodes
    /// around its position, with the node the paper's scheme loads beside it; a claim of an
    /// impact the paper set up takes that node, with the curve beside it; at a node the two
    /// readings are one value and nothing is set beside it.
    #[test]
    fn each_reading_takes_its_value_and_sets_the_other_beside_it() {
        let base = Context::paper();
        let at = |x: f64| {
            let c = Context::paper();
            c.impact(&c.paper_params(x, 4.0e4)).unwrap().e_a
        };
        let s = 0.71 / 39.0;
        let w = 0.158 / s - 8.0;
        let curve = (1.0 - w) * at(8.0 * s) + w * at(9.0 * s);
        let centre = PaperClaim { id: "centre", ours: |c| Ok(c.impact(&c.paper_params(0.158, 4.0e4))?.e_a) };
        let read = evaluate(centre, Reading::Curve, &base).unwrap();
        assert!((read.value - curve).abs() < 1e-12 && read.other == Some(at(9.0 * s)), "{read:?}");
        let set_up = evaluate(centre, Reading::Impact, &base).unwrap();
        assert_eq!((set_up.value, set_up.other), (read.other.unwrap(), Some(read.value)));
        let node = PaperClaim { id: "node", ours: |c| Ok(c.impact(&c.paper_params(0.71 * 9.0 / 39.0, 4.0e4))?.e_a) };
        let (a, b) = (evaluate(node, Reading::Curve, &base).unwrap(), evaluate(node, Reading::Impact, &base).unwrap());
        assert!(a.other.is_none() && a.moved.is_empty() && (a.value - b.value).abs() < 1e-12);
    }

    /// A claim computed from a beam gets its converged value by the same computation on a
    /// converged context; a closed form gets none; and a computation that fixes its own
    /// numerics (so its "converged" value would be the paper's again) is refused.
    #[test]
    fn what_a_value_is_computed_from_decides_its_converged_counterpart() {
        let base = Context::paper();
        let beam = PaperClaim { id: "beam", ours: |c| Ok(c.impact(&c.paper_params(0.158, 4.0e4))?.e_a) };
        let ours = evaluate(beam, Reading::Impact, &base).unwrap();
        let fine = ours.converged.expect("a beam run has a converged value");
        assert!((fine - ours.value).abs() > 1e-4, "{fine} vs {}", ours.value);
        assert_eq!(ours.moved.len(), 1);
        let s = 0.71 / 39.0;
        assert!((ours.moved[0].node - 9.0 * s).abs() < 1e-12, "the centre is computed at node 9");
        assert!((ours.moved[0].between.0 - 8.0 * s).abs() < 1e-12 && (ours.moved[0].between.1 - 9.0 * s).abs() < 1e-12);
        let closed = PaperClaim { id: "closed", ours: |_| Ok(2.0 / 0.762_f64.powi(2) - 1.0) };
        assert_eq!(evaluate(closed, Reading::Curve, &base).unwrap().converged, None);
        let fixed = PaperClaim {
            id: "fixed",
            ours: |c| {
                let mut p = c.paper_params(0.158, 4.0e4);
                p.numerics.segments = 39;
                p.numerics.load = crate::params::LoadRule::Node;
                Ok(c.impact(&p)?.e_a)
            },
        };
        let err = evaluate(fixed, Reading::Impact, &base).unwrap_err().to_string();
        assert!(err.contains("fixed") && err.contains("39 segments"), "{err}");
    }
}
