//! The robustness figure: every claim's q05-q95 against the paper's tolerance.

use super::SAMPLES;
use crate::experiments::Context;
use crate::numfmt::fmt_sig;
use crate::render::plot::{Chart, Curve, LineStyle};
use crate::render::table::Table;

/// in tolerances (half the band): 0 at the paper's value, `asinh(+-1)` at the band's edges,
/// and values tens of tolerances away still on the chart.
fn in_band(v: f64, (lo, hi): (f64, f64)) -> f64 {
    ((2.0 * v - lo - hi) / (hi - lo)).asinh()
}

/// Verdict colours (palette indices); an `independent` claim has no interval to draw.
const COLOURS: [(&str, usize); 3] = [("holds", 3), ("part", 1), ("not at all", 5)];

/// The x axis' named ticks: distances from the paper's value in tolerances, on the asinh
/// scale.
fn tolerance_ticks() -> Vec<(f64, String)> {
    [-100.0f64, -10.0, -3.0, -1.0, 0.0, 1.0, 3.0, 10.0, 100.0]
        .iter()
        .map(|&t| {
            let name = if t == 0.0 { "0 (paper)".to_string() } else { format!("{t:+}") };
            (t.asinh(), name)
        })
        .collect()
}

/// The y range of `n` claims' rows.
fn rows_range(n: usize) -> (f64, f64) {
    (0.3, n as f64 + 0.7)
}

pub(super) fn chart(_: &Context, t: &Table) -> Chart {
    let col = |name: &str| crate::experiments::col(t, name);
    let (lo, hi, q05, q95, nominal) = (col("band_lo"), col("band_hi"), col("q05"), col("q95"), col("nominal"));
    let share = col("conclusion_share");
    let ids = t.column_text("id").unwrap_or_default();
    let verdicts = t.column_text("verdict").unwrap_or_default();
    let conclusions = t.column_text("conclusion_verdict").unwrap_or_default();
    let n = t.rows.len();
    // the first claim at the top
    let row = |k: usize| (n - k) as f64;
    let mut curves = Vec::new();
    let mut labelled = Vec::new();
    for k in 0..n {
        let Some(&(_, colour)) = COLOURS.iter().find(|(v, _)| *v == verdicts[k]) else { continue };
        let label = if labelled.contains(&colour) {
            String::new()
        } else {
            labelled.push(colour);
            format!("q05-q95 of the number: {}", verdicts[k])
        };
        let band = (lo[k], hi[k]);
        curves.push(
            Curve::new(label, vec![in_band(q05[k], band), in_band(q95[k], band)], vec![row(k), row(k)])
                .with_color(colour),
        );
    }
    let x: Vec<f64> = (0..n).map(|k| in_band(nominal[k], (lo[k], hi[k]))).collect();
    let y: Vec<f64> = (0..n).map(row).collect();
    curves.push(Curve::new("at the paper's inputs (fd)", x, y).with_style(LineStyle::Points).with_color(0));
    for edge in [-1.0f64, 1.0] {
        let label = if edge > 0.0 { "edges of the claim's tolerance" } else { "" };
        let x = edge.asinh();
        let (y0, y1) = rows_range(n);
        curves.push(Curve::new(label, vec![x, x], vec![y0, y1]).with_style(LineStyle::Dashed).with_color(0));
    }
    let y_ticks = (0..n)
        .map(|k| {
            let said = if share[k].is_finite() {
                format!("{} {} %", conclusions[k], fmt_sig(100.0 * share[k], 3))
            } else {
                conclusions[k].clone()
            };
            (row(k), format!("{}  [{said}]", ids[k]))
        })
        .collect();
    Chart {
        y_range: Some(rows_range(n)),
        curves,
        x_ticks: tolerance_ticks(),
        y_ticks,
        ..Chart::new(
            format!(
                "Paper claims under input uncertainty ({SAMPLES} x {} samples, modal solver)",
                super::runs_per_sample()
            ),
            "our value's distance from the paper's, in tolerances (asinh scale)",
            "claim  [conclusion: verdict, share of samples in which it holds]",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_axis_is_the_distance_from_the_paper_in_tolerances() {
        assert_eq!(in_band(3.0, (1.0, 3.0)), 1.0f64.asinh());
        assert!(tolerance_ticks().iter().any(|(x, name)| *x == 0.0 && name == "0 (paper)"));
    }
}
