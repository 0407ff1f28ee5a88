//! Small helpers the experiments use to turn their tables into chart curves.

use crate::render::plot::{Axis, Curve, LineStyle};
use crate::render::table::Table;

/// A solid curve on the left axis.
pub fn line(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>, color: usize) -> Curve {
    Curve { label: label.into(), x, y, axis: Axis::Left, style: LineStyle::Solid, color }
}

/// The same curve on the right axis.
pub fn on_right(mut c: Curve) -> Curve {
    c.axis = Axis::Right;
    c
}

/// The same curve in another style.
pub fn styled(mut c: Curve, style: LineStyle) -> Curve {
    c.style = style;
    c
}

/// A column of a table produced by this crate (the experiments name their own columns, so a
/// missing one is a programming error caught by the snapshot tests).
pub fn col(t: &Table, name: &str) -> Vec<f64> {
    t.column(name).unwrap_or_else(|| vec![f64::NAN; t.rows.len()])
}

/// Multiply every value by `k` (unit changes for plotting, e.g. s -> ms).
pub fn scaled(v: Vec<f64>, k: f64) -> Vec<f64> {
    v.into_iter().map(|x| x * k).collect()
}

/// The paper's claims (compiled in): the values the figures mark.
const CLAIMS_CSV: &str = include_str!("../../golden/paper_claims.csv");

/// The paper's value of the claim `id` in `golden/paper_claims.csv`, exactly as printed
/// (`None` for an unknown id).
pub fn paper_text(id: &str) -> Option<String> {
    let mut rdr = csv::Reader::from_reader(CLAIMS_CSV.as_bytes());
    let headers = rdr.headers().ok()?.clone();
    let id_col = headers.iter().position(|h| h == "id")?;
    let paper_col = headers.iter().position(|h| h == "paper")?;
    rdr.records()
        .filter_map(std::result::Result::ok)
        .find(|r| r.get(id_col) == Some(id))
        .and_then(|r| r.get(paper_col).map(str::to_string))
}

/// The paper's value of the claim `id` as a number (NaN for an unknown id, which draws
/// nothing; the experiments' tests check every id they mark).
pub fn paper_value(id: &str) -> f64 {
    paper_text(id).and_then(|v| v.parse().ok()).unwrap_or(f64::NAN)
}

/// The band of values within which the claim `id` counts as reproduced (`None` for an unknown
/// id or a claim without a number).
pub fn paper_band(id: &str) -> Option<(f64, f64)> {
    super::claims::claims().ok()?.into_iter().find(|c| c.id == id)?.band().ok().flatten()
}

/// The paper's values of `ids` as printed, joined by ", " (for legend labels).
pub fn paper_list(ids: &[&str]) -> String {
    ids.iter().map(|id| paper_text(id).unwrap_or_else(|| "?".into())).collect::<Vec<_>>().join(", ")
}

/// The paper's stated values as marked points at `x`, with the claims' ids: a
/// [`LineStyle::Paper`] curve on the left axis whose label starts with "paper".
pub fn paper_points(label: impl Into<String>, x: Vec<f64>, ids: &[&str], color: usize) -> Curve {
    let y = ids.iter().map(|id| paper_value(id)).collect();
    Curve { label: label.into(), x, y, axis: Axis::Left, style: LineStyle::Paper, color }
}

/// The label of a paper marker: "paper: " and what it marks.
pub fn paper_label(what: &str) -> String {
    format!("paper: {what}")
}

pub use crate::render::plot::fit_range;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiments::{registry, Context};
    use crate::render::plot::clipped_points;
    use crate::render::table::Value;

    /// The committed table of experiment `id` (figures/<id>.csv), numbers as numbers.
    fn committed_table(id: &str) -> Table {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("figures").join(format!("{id}.csv"));
        let mut rdr = csv::Reader::from_path(&path).expect("committed table");
        let headers: Vec<String> = rdr.headers().expect("header").iter().map(str::to_string).collect();
        let cols: Vec<&str> = headers.iter().map(String::as_str).collect();
        let mut t = Table::new(id, &cols);
        for rec in rdr.records() {
            let rec = rec.expect("row");
            t.push(
                rec.iter().map(|f| f.parse::<f64>().map_or_else(|_| Value::Text(f.to_string()), Value::Num)).collect(),
            )
            .expect("row width");
        }
        t
    }

    #[test]
    fn paper_values_come_from_the_claims_file() {
        assert_eq!(paper_value("fig4_tau"), 4.78);
        assert_eq!(paper_text("clamped_tau_ks4e4").as_deref(), Some("5.90"));
        assert_eq!(paper_list(&["fig9_e_a_ei384", "fig9_e_a_ei150"]), "0.18, 0.10");
        assert!(paper_value("no_such_claim").is_nan());
        assert_eq!(paper_text("no_such_claim"), None);
    }

    /// Every figure with claims of the paper marks the paper's values: at least one curve
    /// labelled "paper: ..." (a [`LineStyle::Paper`] marker, or Fig 6's line), every value
    /// finite; and every paper marker is labelled so.
    #[test]
    fn every_figure_with_claims_marks_the_papers_values() {
        let ctx = Context::paper();
        for exp in registry().into_iter().filter(|e| !e.claims.is_empty()) {
            let chart = (exp.chart)(&ctx, &committed_table(exp.id));
            for c in chart.curves.iter().filter(|c| c.style == LineStyle::Paper) {
                assert!(c.label.starts_with("paper: "), "{}: label '{}'", exp.id, c.label);
            }
            // a marker, or a line where the paper gives a value without its x (Fig 6's tau)
            let paper: Vec<_> = chart.curves.iter().filter(|c| c.label.starts_with("paper: ")).collect();
            assert!(!paper.is_empty(), "{}: no paper marker", exp.id);
            for c in paper {
                assert!(!c.x.is_empty() && c.x.len() == c.y.len(), "{}: {}", exp.id, c.label);
                assert!(c.x.iter().chain(&c.y).all(|v| v.is_finite()), "{}: {} has no value", exp.id, c.label);
            }
        }
    }

    /// No committed figure cuts a curve off at its axis limits.
    #[test]
    fn no_figure_clips_a_curve() {
        let ctx = Context::paper();
        for exp in registry() {
            let chart = (exp.chart)(&ctx, &committed_table(exp.id));
            assert_eq!(clipped_points(&chart), Ok(0), "{}", exp.id);
        }
    }

    /// Every title is drawn at [`MIN_TITLE_SIZE`] or larger (a long one on two lines), never
    /// shrunk to a size a reader squints at; and the spin and rebound-angle curves of the
    /// tension figure differ in colour, each named in the legend, not only by where they sit.
    #[test]
    fn titles_are_readable_and_the_tension_figure_names_its_quantities() {
        use crate::render::plot::{title_layout, MIN_TITLE_SIZE};
        let ctx = Context::paper();
        for exp in registry() {
            let chart = (exp.chart)(&ctx, &committed_table(exp.id));
            let (lines, size) = title_layout(&chart.title);
            assert!(size >= MIN_TITLE_SIZE && lines.len() <= 2, "{}: {lines:?} at {size} px", exp.id);
            assert_eq!(lines.join(" "), chart.title, "{}: the lines are the title", exp.id);
        }
        let t = registry().into_iter().find(|e| e.id == "oblique_tension").unwrap();
        let chart = (t.chart)(&ctx, &committed_table(t.id));
        let colours = |right: bool| -> Vec<usize> {
            chart.curves.iter().filter(|c| (c.axis == Axis::Right) == right).map(|c| c.color).collect()
        };
        assert!(colours(false).iter().all(|c| !colours(true).contains(c)), "spin and angle curves share a colour");
        for c in chart.curves.iter().filter(|c| !c.label.is_empty()) {
            let quantity = if c.axis == Axis::Right { "rebound angle" } else { "spin" };
            assert!(c.label.contains(quantity), "{}", c.label);
        }
    }

    /// Curves drawn against the right axis carry no unit in their label (the axis has it), so
    /// the legend never reads "tau (ms), right axis (ms)"-style doubles.
    #[test]
    fn right_axis_labels_carry_no_unit_of_time() {
        let ctx = Context::paper();
        for exp in registry() {
            let chart = (exp.chart)(&ctx, &committed_table(exp.id));
            for c in chart.curves.iter().filter(|c| c.axis == Axis::Right) {
                assert!(!c.label.contains("(ms)"), "{}: '{}'", exp.id, c.label);
            }
        }
    }

    /// CIE L*a*b* of an sRGB colour (D65).
    fn lab((r, g, b): (u8, u8, u8)) -> (f64, f64, f64) {
        let lin = |u: u8| {
            let u = f64::from(u) / 255.0;
            if u <= 0.04045 {
                u / 12.92
            } else {
                ((u + 0.055) / 1.055).powf(2.4)
            }
        };
        let (r, g, b) = (lin(r), lin(g), lin(b));
        let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
        let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
        let f = |t: f64| if t > 0.008856 { t.cbrt() } else { 7.787 * t + 16.0 / 116.0 };
        (116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z)))
    }

    /// Smallest colour difference (CIE76 delta E) between two curves of the same line style on
    /// one figure: the palette's orange and vermillion (33) or sky blue and blue (26) never
    /// meet in one style. A faint curve is a solid line in a lighter tint of its colour, and is
    /// compared with the solid ones of other colours in that tint (a faint blue is 10 from sky
    /// blue); with its own colour it is a twin, drawn faint on purpose.
    const MIN_DELTA_E: f64 = 40.0;

    #[test]
    fn colours_on_one_figure_are_distinguishable() {
        use crate::render::plot::PALETTE;
        let tint = |(r, g, b): (u8, u8, u8), frac: f64| {
            let mix = |v: u8| (f64::from(v) + (255.0 - f64::from(v)) * frac).round() as u8;
            (mix(r), mix(g), mix(b))
        };
        // the colour a curve is drawn in, as the figure draws it
        let drawn = |c: &crate::render::plot::Curve| {
            let rgb = PALETTE[c.color % PALETTE.len()];
            if c.style == LineStyle::Faint {
                tint(rgb, crate::render::plot::FAINT_TINT)
            } else {
                rgb
            }
        };
        let de = |a: (u8, u8, u8), b: (u8, u8, u8)| {
            let (p, q) = (lab(a), lab(b));
            ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2) + (p.2 - q.2).powi(2)).sqrt()
        };
        assert!(de(PALETTE[1], PALETTE[4]) < MIN_DELTA_E, "the threshold separates orange from vermillion");
        assert!(
            de(PALETTE[2], tint(PALETTE[5], crate::render::plot::FAINT_TINT)) < MIN_DELTA_E,
            "and faint blue from sky blue"
        );
        let ctx = Context::paper();
        let mut failures = Vec::new();
        for exp in registry() {
            let chart = (exp.chart)(&ctx, &committed_table(exp.id));
            // solid and faint curves are both solid lines; dashed ones are told apart by their dashes
            for styles in [&[LineStyle::Solid, LineStyle::Faint][..], &[LineStyle::Dashed]] {
                // (palette index, colour drawn)
                let mut colours: Vec<(usize, (u8, u8, u8))> = chart
                    .curves
                    .iter()
                    .filter(|c| styles.contains(&c.style))
                    .map(|c| (c.color % PALETTE.len(), drawn(c)))
                    .collect();
                colours.sort_unstable();
                colours.dedup();
                for (i, &(ia, a)) in colours.iter().enumerate() {
                    // (a faint twin of a solid curve, the same quantity of another case, is
                    // meant to look like it: Fig 9's EI 150 curves)
                    for &(_, b) in colours[i + 1..].iter().filter(|(ib, _)| *ib != ia) {
                        if de(a, b) < MIN_DELTA_E {
                            failures.push(format!(
                                "{}: {styles:?} colours {a:?} and {b:?} differ by delta E {:.0}",
                                exp.id,
                                de(a, b)
                            ));
                        }
                    }
                }
            }
        }
        assert!(failures.is_empty(), "{}", failures.join("\n"));
    }
}
