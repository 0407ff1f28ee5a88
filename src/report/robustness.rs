//! "How robust is each claim": every claim's q05-q95 under the input uncertainty declared with
//! the parameters (the `robustness` experiment, computed again here so the report stands on
//! its own), its verdict, the inputs it hinges on, the size of the paper's numerics beside the
//! physical spread, and how the intervals move when the sample count doubles.

use crate::error::Result;
use crate::experiments::robustness::{self, ClaimRobustness, Robust};
use crate::experiments::Context;
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

/// The inputs and their sources, one line each.
fn inputs_list() -> String {
    crate::experiments::robustness::inputs()
        .into_iter()
        .filter_map(|s| s.uncertainty.map(|u| format!("- `{}` ~ {}: {}\n", s.key, u.dist.text(), u.source)))
        .collect()
}

/// The section, from the study's rows.
pub fn markdown(rows: &[ClaimRobustness]) -> String {
    // a claim none of the sampled inputs moves (a closed form, a fixed calibration) has no
    // robustness to report: its verdict is `independent`, listed apart
    let count = |v: Robust| rows.iter().filter(|r| r.verdict == v).count();
    let ids = |v: Robust| -> String {
        let listed: Vec<String> = rows
            .iter()
            .filter(|r| r.verdict == v)
            .map(|r| match &r.doubled {
                // a verdict that twice the samples changes is said to be borderline
                Some((_, twice)) if *twice != r.verdict => {
                    format!("`{}` (borderline: {} at twice the samples)", r.claim.id, twice.name())
                }
                _ => format!("`{}`", r.claim.id),
            })
            .collect();
        if listed.is_empty() {
            "none".to_string()
        } else {
            listed.join(", ")
        }
    };
    let mut s = String::from("\n## How robust is each claim\n\n");
    s.push_str(&format!(
        "Each claim computed again under the uncertainty of the paper's inputs, declared beside each \
         parameter in `src/params/keys.rs` and drawn as a factor on the paper's value (`racket-impact \
         uncertainty --claims`; experiment `robustness`, figures/robustness.csv): {} base samples of a \
         Saltelli design (scrambled Sobol' sequence, seed {}), {} evaluations of every claim with the modal \
         solver. *Verdict*: the paper's value (within the claim's tolerance above) holds over the whole \
         5-95 % interval, over part of it, or not at all; *independent* where no sampled input moves the \
         claim's value (the interval is a point and says nothing of robustness). *Hinges on*: the two inputs with the largest total \
         Sobol' index. *Numerical*: the converged value (`hat`, N = 320) less the N = 39 node-scheme value, \
         where the claim has one. The inputs (each range is the declared one, not centred on the paper's \
         value where the paper computes with a value off its own stated centre: p 2.55 against 2.61 for the \
         rules' mean e 0.745, the ball's 57 g against 56.7 g):\n\n{}\n",
        robustness::SAMPLES,
        robustness::SEED,
        robustness::SAMPLES as usize * (robustness::inputs().len() + 2),
        inputs_list()
    ));
    s.push_str(&format!(
        "**{} claims hold over the whole interval, {} over part of it, {} not at all; {} do not depend on \
         the sampled inputs (independent).** The tolerances are those of the report above (half a unit of the paper's last \
         digit, at least 0.5 %, 10 % for the values the paper calls approximate), far tighter than a +-10 to \
         20 % uncertainty of an input, so most values hold over part of the range. The telling verdicts are \
         the two ends: *holds* (the conclusion survives the 5-95 % range of legal balls and plausible \
         rackets) and *not at all* (no input in that range gives the paper's number in this model).\n\n",
        count(Robust::Holds),
        count(Robust::Part),
        count(Robust::NotAtAll),
        count(Robust::Independent)
    ));
    s.push_str(
        "| id | unit | paper | nominal | q05 to q95 | verdict | hinges on (total index) | numerical | q05 to q95 at 2x samples |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let twice = r
            .doubled
            .as_ref()
            .map_or(String::new(), |(d, _)| format!("{} to {}", fmt_sig(d.q05, 3), fmt_sig(d.q95, 3)));
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            r.claim.id,
            r.claim.unit,
            r.claim.paper,
            fmt_sig(r.nominal, 4),
            interval(r),
            r.verdict.name(),
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
        "- **Do not depend on the sampled inputs** (a closed form of the ball's e, or the fixed tension \
         calibration of SPEC.md; their verdict is that of the report above): {}.\n",
        ids(Robust::Independent)
    ));
    let single: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let top = robustness::top_two(&r.summary);
            (top.first().is_some_and(|t| t.1 > 0.7)).then(|| format!("`{}` on {}", r.claim.id, top[0].0))
        })
        .collect();
    s.push_str(&format!(
        "- **Hinge on one input** (total index above 0.7): {}.\n",
        if single.is_empty() { "none".to_string() } else { single.join(", ") }
    ));
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
            let (d, _) = r.doubled.as_ref()?;
            let width = r.summary.q95 - r.summary.q05;
            (width > 0.0).then(|| ((d.q05 - r.summary.q05).abs().max((d.q95 - r.summary.q95).abs())) / width)
        })
        .collect();
    let mut sorted = moves.clone();
    sorted.sort_by(f64::total_cmp);
    let flips = rows.iter().filter(|r| r.doubled.as_ref().is_some_and(|d| d.1 != r.verdict)).count();
    if !sorted.is_empty() {
        s.push_str(&format!(
            "- **Sampling error**: with twice the samples ({}; the first half are the same runs) the ends of \
             the intervals move by a median {} % and at most {} % of the interval's width, and the verdict \
             changes for {} of the {} claims.\n",
            2 * robustness::SAMPLES,
            fmt_sig(100.0 * sorted[sorted.len() / 2], 2),
            fmt_sig(100.0 * sorted[sorted.len() - 1], 2),
            flips,
            rows.len()
        ));
    }
    s.push_str("\nThe headline claims:\n\n");
    for (id, words) in HEADLINES {
        if let Some(r) = rows.iter().find(|r| r.claim.id == id) {
            let unit = &r.claim.unit;
            s.push_str(&format!(
                "- {} (`{id}`, paper {} {unit}): ours {} {unit} at the paper's inputs, {} {unit} over the 5-95 % \
                 range; {}; hinges on {}.\n",
                words,
                r.claim.paper,
                fmt_sig(r.nominal, 3),
                interval(r),
                match r.verdict {
                    Robust::Holds => "holds throughout",
                    Robust::Part => "holds over part of it",
                    Robust::NotAtAll => "holds nowhere in it",
                    Robust::Independent => "does not depend on the sampled inputs",
                },
                hinges(r)
            ));
        }
    }
    s
}

/// Compute the study (the experiment's sample count, doubled too) and write the section.
pub fn section() -> Result<String> {
    let rows = robustness::study(&Context::paper(), robustness::SAMPLES, robustness::SEED, true, |_| {})?;
    Ok(markdown(&rows))
}
