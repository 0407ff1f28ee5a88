//! The robustness figure: does each paper conclusion survive the input uncertainty, and by how
//! much. One row per claim: the sampled 5-95 % range of what its conclusion compares, placed by
//! its margin (in widths of that range, on an asinh scale) against its threshold at zero; its
//! form, verdict and margin named on the row; one vocabulary, the conclusions' verdicts
//! ([`Standing`]); the legend kept clear of the rows.

use super::{runs_per_sample, SAMPLES};
use crate::experiments::conclusion::Standing;
use crate::experiments::{col, Context};
use crate::numfmt::fmt_sig;
use crate::render::plot::{Chart, Curve, LineStyle};
use crate::render::table::Table;

/// The verdicts with a range to draw, and their palette colours.
const COLOURS: [(Standing, usize); 4] =
    [(Standing::Holds, 3), (Standing::Mostly, 5), (Standing::Contested, 1), (Standing::Fails, 6)];

/// The x axis' named ticks: margins in widths of the sampled range, on the asinh scale.
fn margin_ticks() -> Vec<(f64, String)> {
    [-10.0f64, -3.0, -1.0, 0.0, 1.0, 3.0, 10.0, 30.0]
        .iter()
        .map(|&t| {
            let name = if t == 0.0 { "0".to_string() } else { format!("{t:+}") };
            (t.asinh(), name)
        })
        .collect()
}

/// The y range of `n` claims' rows.
fn rows_range(n: usize) -> (f64, f64) {
    (0.3, n as f64 + 0.7)
}

/// Where the bar of a margin `m` lies on the x axis: from the range's low end (`m` widths
/// inside the threshold) to its high end, one width further, asinh scaled.
fn bar(m: f64) -> [f64; 2] {
    [m.asinh(), (m + 1.0).asinh()]
}

/// The row name: the claim, its conclusion's form, verdict and margin.
fn row_name(id: &str, check: &str, verdict: &str, margin: f64, by_construction: bool) -> String {
    let margin = if margin.is_finite() {
        format!(", {}{}", if margin >= 0.0 { "+" } else { "" }, fmt_sig(margin, 2))
    } else {
        String::new()
    };
    let built = if by_construction { ", by construction" } else { "" };
    format!("{id}  {check}  [{verdict}{margin}{built}]")
}

pub(super) fn chart(_: &Context, t: &Table) -> Chart {
    let margin = col(t, "conclusion_margin");
    let ids = t.column_text("id").unwrap_or_default();
    let checks = t.column_text("conclusion_check").unwrap_or_default();
    let verdicts = t.column_text("conclusion_verdict").unwrap_or_default();
    let built: Vec<bool> = t.column_text("by_construction").unwrap_or_default().iter().map(|b| b == "yes").collect();
    let n = t.rows.len();
    // the first claim at the top
    let row = |k: usize| (n - k) as f64;
    let mut curves = Vec::new();
    let mut labelled: Vec<(usize, bool)> = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..n {
        let Some(&(standing, colour)) = COLOURS.iter().find(|(v, _)| v.name() == verdicts[k]) else { continue };
        if !margin[k].is_finite() {
            continue;
        }
        let x = bar(margin[k]);
        (lo, hi) = (lo.min(x[0]), hi.max(x[1]));
        let label = if labelled.contains(&(colour, built[k])) {
            String::new()
        } else {
            labelled.push((colour, built[k]));
            if built[k] {
                format!("{}, by construction (not counted)", standing.name())
            } else {
                standing.name().to_string()
            }
        };
        let style = if built[k] { LineStyle::Faint } else { LineStyle::Solid };
        curves.push(Curve::new(label, x.to_vec(), vec![row(k), row(k)]).with_color(colour).with_style(style));
    }
    let (y0, y1) = rows_range(n);
    curves.push(
        Curve::new("threshold (named on each row)", vec![0.0, 0.0], vec![y0, y1])
            .with_style(LineStyle::Dashed)
            .with_color(0),
    );
    // room right of every range for the legend
    lo = lo.min((-3.0f64).asinh()) - 0.2;
    hi = hi.max(1.0f64.asinh());
    let x_range = (lo, hi + 0.85 * (hi - lo));
    let y_ticks = (0..n).map(|k| (row(k), row_name(&ids[k], &checks[k], &verdicts[k], margin[k], built[k]))).collect();
    Chart {
        x_range: Some(x_range),
        y_range: Some((y0, y1)),
        curves,
        x_ticks: margin_ticks().into_iter().filter(|(x, _)| *x >= x_range.0 && *x <= x_range.1).collect(),
        y_ticks,
        ..Chart::new(
            format!(
                "Do the paper's conclusions survive the input uncertainty? ({SAMPLES} x {} samples, modal solver)",
                runs_per_sample()
            ),
            "margin: 5-95 % range inside its threshold, in widths of the range (asinh scale)",
            "claim  conclusion  [verdict, margin]",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_is_drawn_by_its_margin_from_the_threshold() {
        // a margin of 2 widths: the range from 2 to 3 widths inside the threshold
        assert_eq!(bar(2.0), [2.0f64.asinh(), 3.0f64.asinh()]);
        // crossing: from 0.5 widths outside to 0.5 inside
        assert_eq!(bar(-0.5), [(-0.5f64).asinh(), 0.5f64.asinh()]);
        assert!(margin_ticks().iter().any(|(x, name)| *x == 0.0 && name == "0"));
        assert_eq!(row_name("a", "> 0", "holds", 1.234, false), "a  > 0  [holds, +1.2]");
        assert_eq!(row_name("b", "< 2", "independent", f64::NAN, true), "b  < 2  [independent, by construction]");
    }
}
