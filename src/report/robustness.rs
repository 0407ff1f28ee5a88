//! "How robust is each claim": every claim's q05-q95 under the input uncertainty declared with
//! the parameters (the `robustness` experiment, computed again here so the report stands on
//! its own), its verdict, the inputs it hinges on, the size of the paper's numerics beside the
//! physical spread, and how the intervals move when the sample count doubles.

use crate::error::Result;
use crate::experiments::conclusion::{self, Standing};
use crate::experiments::robustness::{self, ClaimRobustness, Robust};
use crate::experiments::{Context, Ours};
use crate::numfmt::fmt_sig;

/// The paper's headline claims, quoted in the section's sentences.
const HEADLINES: [(&str, &str); 6] = [
    ("speeds_ks_half_e_a_gain", "a factor two in k_s changes e_A by 7 %"),
    ("speeds_ks_half_serve_gain", "that is a 2 % faster serve"),
    ("speeds_60_50_serve_gain", "60 -> 50 lb gives a 0.7 % faster serve"),
    ("speeds_60_50_forehand_gain", "and a 1.1 % faster forehand"),
    ("fig8_theta_r4_50lb", "the racket rotates about 10 deg (r 4 cm, 30 m/s)"),
    ("fig9_serve_gain", "the 200 Hz frame serves 7 % faster from 6 cm"),
];

fn interval(r: &ClaimRobustness) -> String {
    format!("{} to {}", fmt_sig(r.summary.q05, 3), fmt_sig(r.summary.q95, 3))
}

fn hinges(r: &ClaimRobustness) -> String {
    robustness::top_two(&r.summary)
        .iter()
        .map(|(k, v)| format!("{k} {}", fmt_sig(*v, 2)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The inputs and their sources, one line each, and the discretisation's line.
fn inputs_list() -> String {
    let paper = Context::paper();
    let (node, at) = crate::experiments::paper_node(0.10, &paper.racket);
    let mut s: String = crate::experiments::robustness::inputs()
        .into_iter()
        .filter_map(|s| s.uncertainty.map(|u| format!("- `{}` ~ {}: {}\n", s.key, u.dist.text(), u.source)))
        .collect();
    s.push_str(&format!(
        "- the discretisation, not drawn: every draw holds each load at the physical point the claim's nominal run \
         loads, whatever the drawn length (Fig 4's x = 10 cm at {:.2} cm, node {node} of the paper's beam; a curve \
         read between the same two points), the force shared between the drawn beam's neighbouring nodes where the \
         point falls between them, so that no input's share carries the grid; the N = 39 beam's own error is the \
         converged-minus-N = 39 shift (*numerical* below, and beside the inputs' spread in the last list)\n",
        100.0 * at
    ));
    s
}

/// A list of ids, or "none".
fn id_list(listed: Vec<String>) -> String {
    if listed.is_empty() {
        "none".to_string()
    } else {
        listed.join(", ")
    }
}

/// The conclusion's share in words: "100 %", or "independent".
fn share_text(share: Option<f64>) -> String {
    share.map_or("independent".to_string(), |v| format!("{} %", fmt_sig(100.0 * v, 3)))
}

/// The section, from the study's rows.
pub fn markdown(rows: &[ClaimRobustness]) -> String {
    let mut s = String::from("\n## How robust is each claim\n\n");
    s.push_str(&format!(
        "Each claim computed again under the uncertainty of the paper's inputs, declared beside each \
         parameter in `src/params/keys.rs` and drawn as a factor on the paper's value (`racket-impact \
         uncertainty --claims`; experiment `robustness`, figures/robustness.csv): {} base samples of a \
         Saltelli design (scrambled Sobol' sequence, seed {}), {} evaluations of every claim with the modal \
         solver. A reviewer asks two things of each claim: does the paper's *conclusion* stand, and is its \
         *number* right. Both are judged here, the conclusions first. *Hinges on*: the two inputs with the \
         largest total Sobol' index of the claim's value. *Borderline*: a verdict that changes when the \
         samples are doubled ({}; the first half are the same runs); borderline verdicts are counted apart, \
         not under the verdict they have at {} samples. The inputs (each range is the declared one, not \
         centred on the paper's value where the paper computes with a value off its own stated centre: p \
         2.55 against 2.61 for the rules' mean e 0.745, the ball's 57 g against 56.7 g):\n\n{}",
        robustness::SAMPLES,
        robustness::SEED,
        robustness::SAMPLES as usize * (robustness::inputs().len() + 2),
        2 * robustness::SAMPLES,
        robustness::SAMPLES,
        inputs_list()
    ));
    s.push_str(&conclusions(rows));
    s.push_str(&headlines(rows));
    s.push_str(&numbers(rows));
    s
}

/// A conclusion's margin in words: "+5.6", "-0.42", or "" where nothing moves it.
fn margin_text(m: Option<f64>) -> String {
    m.map_or(String::new(), |m| format!("{}{}", if m >= 0.0 { "+" } else { "" }, fmt_sig(m, 2)))
}

/// The conclusions: counts, the table, where ours and the paper's part.
fn conclusions(rows: &[ClaimRobustness]) -> String {
    let robustness::ConclusionTally {
        counts: [(_, holds), (_, mostly), (_, contested), (_, fails), (_, independent)],
        borderline,
        by_construction,
    } = robustness::conclusion_tally(rows);
    let mut s = String::from("\n### Does the paper's conclusion stand?\n\n");
    s.push_str(&format!(
        "Every claim carries the conclusion the paper draws from it, in words and in a checkable form (a \
         sign, an order between two claims, a ratio band, or \"small compared with\" with its threshold \
         stated; columns `conclusion` and `conclusion_check` of `golden/paper_claims.csv`, evaluated by \
         code on every sample, the other claims of an order or ratio computed at the same inputs). *Share*: \
         the fraction of the {} independent samples (the design's A and B blocks) in which it holds. \
         *Verdict*: {}. *Margin*: how far the sampled 5-95 % range of what the conclusion compares (the claim's \
         value less the threshold, at the same inputs) stays from the threshold, in units of that range's \
         width, at the nearest threshold: +1 clears it by a whole width, a negative margin crosses it. *Threshold \
         from*: the paper's words, or ours with the reason (`threshold_source` of the claims file). A conclusion \
         the model makes true whatever the inputs, or that an input was chosen to give (EI for the paper's 125 \
         and 200 Hz), is *by construction*: labelled so, with the reason, and not \
         counted as support.\n\n**Conclusions: {holds} hold in every sample, {mostly} mostly, {contested} \
         contested, {fails} fail; {independent} do not depend on the sampled inputs; borderline, counted \
         apart: {borderline}; by construction, not counted: {by_construction}.**\n\n",
        2 * robustness::SAMPLES,
        conclusion::rule_text(),
    ));
    s.push_str(
        "| id | kind | the paper concludes | checked as | threshold from | share | margin | verdict | at the paper's inputs |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let mut verdict = match &r.doubled {
            Some(d) if r.conclusion_borderline() => {
                format!("{} (borderline: {} at 2x)", r.conclusion.name(), d.conclusion.name())
            }
            _ => r.conclusion.name().to_string(),
        };
        if r.claim.by_construction() {
            verdict = format!("{verdict}; by construction, not counted: {}", r.claim.by_construction);
        }
        s.push_str(&format!(
            "| `{}` | {} | {} | `{}` | {} | {} | {} | {} | {} |\n",
            r.claim.id,
            r.claim.kind.name(),
            super::cell(&r.claim.conclusion),
            r.claim.conclusion_check,
            super::cell(&r.claim.threshold_source),
            share_text(r.conclusion_share),
            margin_text(r.conclusion_margin),
            verdict,
            if r.conclusion_nominal { "holds" } else { "fails" }
        ));
    }
    let parted: Vec<String> = rows
        .iter()
        .filter(|r| {
            !r.claim.by_construction()
                && (matches!(r.conclusion, Standing::Contested | Standing::Fails) || !r.conclusion_nominal)
        })
        .map(|r| {
            format!(
                "- `{}` ({}, {}; at the paper's inputs it {}): decided by {}.\n",
                r.claim.id,
                r.conclusion.name(),
                share_text(r.conclusion_share),
                if r.conclusion_nominal { "holds" } else { "fails" },
                match hinges(r).as_str() {
                    "" => "no sampled input".to_string(),
                    h => h.to_string(),
                }
            )
        })
        .collect();
    s.push_str(
        "\nWhere the paper's conclusion and ours part (contested, failing, or failing at the paper's \
                 own inputs), and the inputs that decide it (total Sobol' index of the claim's value):\n\n",
    );
    s.push_str(&if parted.is_empty() { "- none.\n".to_string() } else { parted.concat() });
    s
}

/// The numbers: counts, the table, the lists.
fn numbers(rows: &[ClaimRobustness]) -> String {
    let ([(_, whole), (_, part), (_, none), (_, independent), (_, no_number)], borderline) = robustness::tally(rows);
    // a verdict that twice the samples changes is listed under neither: borderline
    let ids = |v: Robust| -> String {
        id_list(
            rows.iter().filter(|r| r.verdict == v && !r.borderline()).map(|r| format!("`{}`", r.claim.id)).collect(),
        )
    };
    let mut s = String::from("\n### Is the paper's number right?\n\n");
    s.push_str(&format!(
        "*Verdict*: the paper's value, within the tolerance of the report's head (the one rule stated \
         there), holds over the whole 5-95 % interval, over part of it, or not at all; *independent* where \
         no sampled input moves the claim's value (the interval is a point and says nothing of \
         robustness; the verdict is that of the report above). *Numerical*: the converged value (`hat`, \
         N = 320) less the N = 39 node-scheme value, where the claim has one.\n\n\
         **Numbers: {whole} hold over the whole interval, {part} over part of it, {none} not at all; \
         {independent} do not depend on the sampled inputs; {no_number} state no number (judged by their \
         conclusion above); borderline, counted apart: {borderline}.** A tolerance of \
         half a unit of the paper's last digit is far tighter than a +-10 to 20 % uncertainty of an input, \
         so most numbers hold over part of the range; that is why the conclusions above are judged \
         too.\n\n"
    ));
    s.push_str(
        "| id | unit | paper | nominal | q05 to q95 | verdict | hinges on (total index) | numerical | q05 to q95 at 2x samples |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let twice = r
            .doubled
            .as_ref()
            .map_or(String::new(), |d| format!("{} to {}", fmt_sig(d.summary.q05, 3), fmt_sig(d.summary.q95, 3)));
        let verdict = match &r.doubled {
            Some(d) if r.borderline() => format!("{} (borderline: {} at 2x)", r.verdict.name(), d.verdict.name()),
            _ => r.verdict.name().to_string(),
        };
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            r.claim.id,
            r.claim.unit,
            r.claim.paper,
            fmt_sig(r.nominal, 4),
            interval(r),
            verdict,
            hinges(r),
            r.numerical.map_or(String::new(), |n| fmt_sig(n, 2)),
            twice
        ));
    }
    s.push('\n');
    s.push_str(&format!(
        "- **Stand over the 5-95 % range of legal balls and plausible rackets** (the whole interval within \
         the tolerance): {}.\n",
        ids(Robust::Holds)
    ));
    s.push_str(&format!("- **Hold for part of the range only**: {}.\n", ids(Robust::Part)));
    s.push_str(&format!("- **Do not hold anywhere in it**: {}.\n", ids(Robust::NotAtAll)));
    s.push_str(&format!(
        "- **Do not depend on the sampled inputs** (arithmetic on the rules' e, or a law the model obeys \
         exactly whatever the inputs; their verdict is that of the report above): {}.\n",
        ids(Robust::Independent)
    ));
    let flagged: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let d = r.doubled.as_ref().filter(|_| r.borderline())?;
            Some(format!(
                "`{}` ({} at {}, {} at {} samples)",
                r.claim.id,
                r.verdict.name(),
                robustness::SAMPLES,
                d.verdict.name(),
                2 * robustness::SAMPLES
            ))
        })
        .collect();
    s.push_str(&format!("- **Borderline** (counted apart): {}.\n", id_list(flagged)));
    let single: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let top = robustness::top_two(&r.summary);
            (top.first().is_some_and(|t| t.1 > 0.7)).then(|| format!("`{}` on {}", r.claim.id, top[0].0))
        })
        .collect();
    s.push_str(&format!("- **Hinge on one input** (total index above 0.7): {}.\n", id_list(single)));
    let numerical: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let n = r.numerical?;
            let width = r.summary.q95 - r.summary.q05;
            Some(format!("`{}` {} % of it", r.claim.id, fmt_sig(100.0 * n.abs() / width, 2)))
        })
        .collect();
    s.push_str(&format!(
        "- **The paper's numerics (N = 39, force on one node) beside the physical uncertainty**: the \
         converged-minus-N = 39 shift as a share of the 5-95 % width: {}.\n",
        numerical.join(", ")
    ));
    let moves: Vec<f64> = rows
        .iter()
        .filter_map(|r| {
            let d = r.doubled.as_ref()?;
            let width = r.summary.q95 - r.summary.q05;
            (width > 0.0)
                .then(|| ((d.summary.q05 - r.summary.q05).abs().max((d.summary.q95 - r.summary.q95).abs())) / width)
        })
        .collect();
    let mut sorted = moves.clone();
    sorted.sort_by(f64::total_cmp);
    if !sorted.is_empty() {
        s.push_str(&format!(
            "- **Sampling error**: with twice the samples ({}; the first half are the same runs) the ends of \
             the intervals move by a median {} % and at most {} % of the interval's width; the verdict on the \
             number changes for {} of the {} claims, that on the conclusion for {}.\n",
            2 * robustness::SAMPLES,
            fmt_sig(100.0 * sorted[sorted.len() / 2], 2),
            fmt_sig(100.0 * sorted[sorted.len() - 1], 2),
            rows.iter().filter(|r| r.borderline()).count(),
            rows.len(),
            rows.iter().filter(|r| r.conclusion_borderline()).count(),
        ));
    }
    s
}

/// The paper's headline claims, conclusion then number.
fn headlines(rows: &[ClaimRobustness]) -> String {
    let mut s = String::from("\nThe headline claims, conclusion then number:\n\n");
    for (id, words) in HEADLINES {
        if let Some(r) = rows.iter().find(|r| r.claim.id == id) {
            let unit = &r.claim.unit;
            s.push_str(&format!(
                "- {} (`{id}`, paper {} {unit}). The conclusion ({}) {}: {} of the samples. The number: ours {} \
                 {unit} at the paper's inputs, {} {unit} over the 5-95 % range; {}; hinges on {}.\n",
                words,
                r.claim.paper,
                r.claim.conclusion,
                r.conclusion.name(),
                share_text(r.conclusion_share),
                fmt_sig(r.nominal, 3),
                interval(r),
                match r.verdict {
                    Robust::Holds => "the paper's value holds throughout",
                    Robust::Part => "the paper's value holds over part of it",
                    Robust::NotAtAll => "the paper's value holds nowhere in it",
                    Robust::Independent => "it does not depend on the sampled inputs",
                    Robust::NoNumber => "the paper states no number",
                },
                hinges(r)
            ));
        }
    }
    s
}

/// Compute the study (the experiment's sample count, doubled too) and write the section;
/// `nominal` is every claim's numbers on the paper's inputs, as the report has them.
pub fn section(nominal: &[Ours]) -> Result<String> {
    let rows =
        robustness::study(&Context::paper(), robustness::SAMPLES, robustness::SEED, true, Some(nominal), |_| {})?;
    Ok(markdown(&rows))
}
