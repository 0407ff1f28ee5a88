//! Drawing a planned chart with `plotters`: mesh and axes, curves, vertical marker lines, and
//! the legend, in that order.

use std::ops::Range;

use plotters::chart::DualCoordChartContext;
use plotters::coord::ranged1d::{AsRangedCoord, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::{FontStyle, ShapeStyle};

use super::clip::Bounds;
use super::plan::Plan;
use super::{font, msg, palette, tick_label, tint, title_font, Axis, Chart, LineStyle};
use super::{AXIS_DESC_SIZE, LEGEND_GLYPH, TICK_SIZE, VLINE_COLOR, VLINE_DASHES};
use crate::render::table::fmt_sig;

/// Draw one curve on the primary or secondary coordinates and attach its legend entry.
macro_rules! draw_curve {
    ($cc:expr, $right:expr, $elems:expr, $label:expr, $legend:expr) => {{
        let anno = if $right {
            $cc.draw_secondary_series($elems).map_err(msg)?
        } else {
            $cc.draw_series($elems).map_err(msg)?
        };
        if !$label.is_empty() {
            anno.label($label).legend($legend);
        }
    }};
}

/// Draw the whole chart on `root`, with x coordinates `x_spec` (linear or log).
pub(super) fn draw_chart<X>(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    chart: &Chart,
    plan: &Plan,
    x_spec: X,
) -> std::result::Result<(), String>
where
    X: AsRangedCoord<Value = f64> + Clone,
    X::CoordDescType: ValueFormatter<f64>,
{
    let (y0, y1) = plan.y;
    // Without a right axis the secondary coordinates mirror the primary ones and stay unused.
    let (s0, s1) = plan.y2.unwrap_or(plan.y);
    let has_y2 = plan.y2.is_some();

    let mut builder = ChartBuilder::on(root);
    builder
        .caption(&chart.title, title_font(root, &chart.title)?)
        .margin(20)
        .x_label_area_size(70)
        .y_label_area_size(110);
    if has_y2 {
        builder.right_y_label_area_size(110);
    }
    let cc = builder.build_cartesian_2d(x_spec.clone(), Range { start: y0, end: y1 }).map_err(msg)?;
    let mut cc = cc.set_secondary_coord(x_spec, Range { start: s0, end: s1 });

    let log_fmt = |v: &f64| fmt_sig(*v, 3);
    let x_fmt = |v: &f64| tick_label(*v, plan.x);
    let y_fmt = |v: &f64| tick_label(*v, plan.y);
    let y2_fmt = |v: &f64| tick_label(*v, (s0, s1));
    {
        let mut mesh = cc.configure_mesh();
        mesh.x_desc(chart.x_label.as_str())
            .y_desc(chart.y_label.as_str())
            .label_style(font(TICK_SIZE, FontStyle::Normal))
            .axis_desc_style(font(AXIS_DESC_SIZE, FontStyle::Normal))
            .bold_line_style(RGBColor(0, 0, 0).mix(0.15))
            .light_line_style(RGBColor(0, 0, 0).mix(0.05))
            .x_labels(10)
            .y_labels(10)
            .y_label_formatter(&y_fmt);
        if chart.x_log {
            mesh.x_label_formatter(&log_fmt);
        } else {
            mesh.x_label_formatter(&x_fmt);
        }
        mesh.draw().map_err(msg)?;
    }
    if let (true, Some(label)) = (has_y2, chart.y2_label.as_deref()) {
        cc.configure_secondary_axes()
            .y_desc(label)
            .label_style(font(TICK_SIZE, FontStyle::Normal))
            .axis_desc_style(font(AXIS_DESC_SIZE, FontStyle::Normal))
            .y_labels(10)
            .y_label_formatter(&y2_fmt)
            .draw()
            .map_err(msg)?;
    }

    let left = Bounds::new(plan.x, plan.y, plan.x_log);
    let right = Bounds::new(plan.x, (s0, s1), plan.x_log);
    let mut legend_entries = draw_curves(&mut cc, chart, left, right, has_y2)?;
    legend_entries += draw_vlines(&mut cc, chart, left, (y0, y1))?;

    if legend_entries > 0 {
        cc.configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .margin(12)
            .legend_area_size(LEGEND_GLYPH)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(font(TICK_SIZE, FontStyle::Normal))
            .draw()
            .map_err(msg)?;
    }
    Ok(())
}

/// The chart's coordinates: x (linear or log) against the left and the right y axis.
type Coords<'a, 'b, XC> =
    DualCoordChartContext<'a, BitMapBackend<'b>, Cartesian2d<XC, RangedCoordf64>, Cartesian2d<XC, RangedCoordf64>>;

/// Draw every curve, clipped to its axis' bounds; returns the number of legend entries.
fn draw_curves<XC: Ranged<ValueType = f64>>(
    cc: &mut Coords<'_, '_, XC>,
    chart: &Chart,
    left: Bounds,
    right: Bounds,
    has_y2: bool,
) -> std::result::Result<usize, String> {
    let mut legend_entries = 0usize;
    for curve in &chart.curves {
        let on_right = has_y2 && curve.axis == Axis::Right;
        let bounds = if on_right { right } else { left };
        let label = if on_right && !curve.label.is_empty() {
            format!("{} (right axis)", curve.label)
        } else {
            curve.label.clone()
        };
        if !label.is_empty() {
            legend_entries += 1;
        }
        let color = palette(curve.color);
        let g = LEGEND_GLYPH - 6;
        match curve.style {
            LineStyle::Solid | LineStyle::Faint => {
                let style: ShapeStyle = if curve.style == LineStyle::Solid {
                    color.stroke_width(2)
                } else {
                    tint(color, 0.6).stroke_width(1)
                };
                let elems = bounds.polylines(&curve.x, &curve.y).into_iter().map(move |p| PathElement::new(p, style));
                draw_curve!(cc, on_right, elems, label, move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + g, y)], style)
                });
            }
            LineStyle::Dashed => {
                let style = color.stroke_width(2);
                let elems = bounds
                    .polylines(&curve.x, &curve.y)
                    .into_iter()
                    .map(move |p| DashedPathElement::new(p, 10, 6, style));
                draw_curve!(cc, on_right, elems, label, move |(x, y)| {
                    DashedPathElement::new(vec![(x, y), (x + g, y)], 8, 5, style)
                });
            }
            LineStyle::Points => {
                let style = color.filled();
                let elems = bounds.points(&curve.x, &curve.y).into_iter().map(move |p| Circle::new(p, 4, style));
                draw_curve!(cc, on_right, elems, label, move |(x, y)| { Circle::new((x + g / 2, y), 4, style) });
            }
        }
    }

    Ok(legend_entries)
}

/// Draw the vertical marker lines inside the x range (y from `y0` to `y1`); returns the number
/// of legend entries.
fn draw_vlines<XC: Ranged<ValueType = f64>>(
    cc: &mut Coords<'_, '_, XC>,
    chart: &Chart,
    left: Bounds,
    (y0, y1): (f64, f64),
) -> std::result::Result<usize, String> {
    let mut legend_entries = 0usize;
    for (i, vline) in chart.vlines.iter().enumerate() {
        let (dash, gap) = VLINE_DASHES[i % VLINE_DASHES.len()];
        let style = VLINE_COLOR.stroke_width(2);
        let visible = left.contains(vline.x, y0);
        let elems = visible.then(|| DashedPathElement::new(vec![(vline.x, y0), (vline.x, y1)], dash, gap, style));
        let anno = cc.draw_series(elems).map_err(msg)?;
        if visible && !vline.label.is_empty() {
            legend_entries += 1;
            let g = LEGEND_GLYPH - 6;
            anno.label(vline.label.as_str())
                .legend(move |(x, y)| DashedPathElement::new(vec![(x, y), (x + g, y)], dash.min(8), gap.min(5), style));
        }
    }
    Ok(legend_entries)
}
