//! Drawing a planned chart with `plotters`: mesh and axes, bands, curves, vertical marker
//! lines, and the legend (placed clear of the data), in that order.

use std::ops::Range;

use plotters::chart::DualCoordChartContext;
use plotters::coord::ranged1d::{AsRangedCoord, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontStyle, ShapeStyle};

use super::clip::Bounds;
use super::legend::{place_legend, Rect, ToPixel};
use super::plan::Plan;
use super::{font, msg, palette, tick_label, tint, title_font, title_layout, Axis, Chart, LineStyle};
use super::{AXIS_DESC_SIZE, BAND_ALPHA, BAND_COLOR, CLIPPED_NOTE, LEGEND_GLYPH, TICK_SIZE, VLINE_COLOR, VLINE_DASHES};
use crate::numfmt::fmt_sig;

/// How much white a [`LineStyle::Faint`] curve's colour is mixed with: light enough to sit
/// behind the main curves, dark enough (with 2 px) to read.
pub const FAINT_TINT: f64 = 0.3;

/// Draw a series on the primary or the secondary coordinates.
macro_rules! draw_on {
    ($cc:expr, $right:expr, $elems:expr) => {{
        if $right {
            $cc.draw_secondary_series($elems).map_err(msg)?;
        } else {
            $cc.draw_series($elems).map_err(msg)?;
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

    // named y ticks take the room their longest name needs (and the axis description's)
    let y_named = named_font(chart.y_ticks.len());
    let mut y_area = 110;
    for (_, name) in &chart.y_ticks {
        let (w, _) = root.estimate_text_size(name, &y_named).map_err(msg)?;
        y_area = y_area.max(w as i32 + NAMED_GAP + AXIS_DESC_SIZE as i32 + 24);
    }
    // a title that needs two lines takes them from the top of the figure (plotters' caption
    // is one line); one line is the chart's caption
    let (lines, title_size) = title_layout(&chart.title);
    let area = match &lines[..] {
        [_, _, ..] => {
            let style = font(title_size, FontStyle::Bold);
            let mut area = root.margin(20, 20, 20, 20);
            for line in &lines {
                area = area.titled(line, style.clone()).map_err(msg)?;
            }
            area
        }
        _ => root.clone(),
    };
    let mut builder = ChartBuilder::on(&area);
    if lines.len() == 1 {
        builder.caption(&chart.title, title_font(root, &chart.title)?).margin(20);
    }
    builder.x_label_area_size(70).y_label_area_size(y_area);
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
            .x_labels(if chart.x_ticks.is_empty() { 10 } else { 0 })
            .y_labels(if chart.y_ticks.is_empty() { 10 } else { 0 })
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
    // the plotting area in the pixels `root` draws in (a panel's root starts below the image's top)
    let (px, py) = cc.plotting_area().get_pixel_range();
    let (bx, by) = root.get_base_pixel();
    let area: Rect = (px.start - bx, py.start - by, px.end - bx, py.end - by);
    let pix = |b: Bounds| ToPixel { bounds: b, area };
    draw_named_ticks(root, chart, pix(left), y_named)?;
    let mut entries = draw_bands(&mut cc, chart, left, (y0, y1))?;
    let mut obstacles = Vec::new();
    entries.extend(draw_curves(&mut cc, chart, (pix(left), pix(right)), has_y2, &mut obstacles)?);
    entries.extend(draw_vlines(&mut cc, chart, pix(left), (y0, y1), &mut obstacles)?);
    if plan.clipped(chart) > 0 {
        entries.push(Entry { label: CLIPPED_NOTE.to_string(), glyph: Glyph::None });
    }
    draw_legend(root, &entries, area, &obstacles)
}

/// Pixels between a named tick's label and the plotting area.
const NAMED_GAP: i32 = 8;

/// The font of named ticks: the tick size, smaller when `n` of them share the height.
fn named_font(n: usize) -> TextStyle<'static> {
    let room = f64::from(super::HEIGHT) - 170.0;
    let size = if n == 0 { TICK_SIZE } else { (0.85 * room / n as f64).clamp(10.0, TICK_SIZE) };
    font(size.floor(), FontStyle::Normal)
}

/// The chart's named ticks ([`Chart::x_ticks`], [`Chart::y_ticks`]): a light grid line across
/// the plotting area at each, its name outside the area (left of it for y, below it for x).
/// Ticks outside the axis range are left out.
fn draw_named_ticks(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    chart: &Chart,
    pix: ToPixel,
    y_font: TextStyle<'static>,
) -> std::result::Result<(), String> {
    let (x0, y0, x1, y1) = pix.area;
    let grid = RGBColor(0, 0, 0).mix(0.15);
    let (xr, yr) = (pix.bounds.x_range(), pix.bounds.y_range());
    let within = |v: f64, (lo, hi): (f64, f64)| v.is_finite() && v >= lo.min(hi) && v <= lo.max(hi);
    let y_style = y_font.pos(Pos::new(HPos::Right, VPos::Center));
    for (v, name) in chart.y_ticks.iter().filter(|(v, _)| within(*v, yr)) {
        let y = pix.px((xr.0, *v)).1.round() as i32;
        root.draw(&PathElement::new(vec![(x0, y), (x1, y)], grid)).map_err(msg)?;
        root.draw_text(name, &y_style, (x0 - NAMED_GAP, y)).map_err(msg)?;
    }
    let x_style = font(TICK_SIZE, FontStyle::Normal).pos(Pos::new(HPos::Center, VPos::Top));
    for (v, name) in chart.x_ticks.iter().filter(|(v, _)| within(*v, xr)) {
        let x = pix.px((*v, yr.0)).0.round() as i32;
        root.draw(&PathElement::new(vec![(x, y0), (x, y1)], grid)).map_err(msg)?;
        root.draw_text(name, &x_style, (x, y1 + NAMED_GAP)).map_err(msg)?;
    }
    Ok(())
}

/// What a legend entry shows left of its text.
#[derive(Clone, Copy)]
enum Glyph {
    /// A line in this style.
    Line(ShapeStyle),
    /// A dashed line: style, dash, gap.
    Dashed(ShapeStyle, u32, u32),
    /// A filled dot.
    Dot(RGBColor),
    /// The paper's marker.
    Paper(RGBColor),
    /// A shaded box.
    Band,
    /// Text only.
    None,
}

/// One legend line.
struct Entry {
    label: String,
    glyph: Glyph,
}

/// Legend line height, pixels.
const LEGEND_LINE: i32 = TICK_SIZE as i32 + 8;
/// Padding inside the legend box, pixels.
const LEGEND_PAD: i32 = 8;
/// Radius of the paper marker's ring, pixels.
const PAPER_RADIUS: i32 = 8;

/// The paper's marker at pixel `p`.
fn paper_marker(p: (i32, i32), color: RGBColor) -> [Circle<(i32, i32), i32>; 3] {
    [
        Circle::new(p, PAPER_RADIUS, WHITE.filled()),
        Circle::new(p, PAPER_RADIUS, color.stroke_width(3)),
        Circle::new(p, 2, RGBColor(30, 30, 30).filled()),
    ]
}

/// The legend box (white, framed) in the spot that covers the fewest `obstacles`.
fn draw_legend(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    entries: &[Entry],
    area: Rect,
    obstacles: &[(i32, i32)],
) -> std::result::Result<(), String> {
    if entries.is_empty() {
        return Ok(());
    }
    let style = font(TICK_SIZE, FontStyle::Normal);
    let mut text_w = 0;
    for e in entries {
        text_w = text_w.max(root.estimate_text_size(&e.label, &style).map_err(msg)?.0 as i32);
    }
    let w = LEGEND_PAD * 3 + LEGEND_GLYPH + text_w;
    let h = LEGEND_PAD * 2 + LEGEND_LINE * entries.len() as i32;
    let (x, y) = place_legend(area, (w, h), obstacles);
    root.draw(&Rectangle::new([(x, y), (x + w, y + h)], WHITE.mix(0.92).filled())).map_err(msg)?;
    root.draw(&Rectangle::new([(x, y), (x + w, y + h)], BLACK.stroke_width(1))).map_err(msg)?;
    let text_style = style.pos(Pos::new(HPos::Left, VPos::Center));
    for (k, e) in entries.iter().enumerate() {
        let cy = y + LEGEND_PAD + LEGEND_LINE * k as i32 + LEGEND_LINE / 2;
        let (g0, g1) = (x + LEGEND_PAD, x + LEGEND_PAD + LEGEND_GLYPH);
        match e.glyph {
            Glyph::Line(s) => root.draw(&PathElement::new(vec![(g0, cy), (g1, cy)], s)).map_err(msg)?,
            Glyph::Dashed(s, dash, gap) => {
                root.draw(&DashedPathElement::new(vec![(g0, cy), (g1, cy)], dash, gap, s)).map_err(msg)?
            }
            Glyph::Dot(c) => root.draw(&Circle::new(((g0 + g1) / 2, cy), 4, c.filled())).map_err(msg)?,
            Glyph::Paper(c) => {
                for m in paper_marker(((g0 + g1) / 2, cy), c) {
                    root.draw(&m).map_err(msg)?;
                }
            }
            Glyph::Band => {
                let r = [(g0, cy - 8), (g1, cy + 8)];
                root.draw(&Rectangle::new(r, BAND_COLOR.mix(BAND_ALPHA * 2.0).filled())).map_err(msg)?;
            }
            Glyph::None => {}
        }
        let tx = if matches!(e.glyph, Glyph::None) { g0 } else { g1 + LEGEND_PAD };
        root.draw_text(&e.label, &text_style, (tx, cy)).map_err(msg)?;
    }
    Ok(())
}

/// The chart's coordinates: x (linear or log) against the left and the right y axis.
type Coords<'a, 'b, XC> =
    DualCoordChartContext<'a, BitMapBackend<'b>, Cartesian2d<XC, RangedCoordf64>, Cartesian2d<XC, RangedCoordf64>>;

/// Shade the bands (the part inside the x range); returns their legend entries.
fn draw_bands<XC: Ranged<ValueType = f64>>(
    cc: &mut Coords<'_, '_, XC>,
    chart: &Chart,
    left: Bounds,
    (y0, y1): (f64, f64),
) -> std::result::Result<Vec<Entry>, String> {
    let mut entries = Vec::new();
    let (lo, hi) = left.x_range();
    for band in &chart.bands {
        let (a, b) = (band.x0.min(band.x1).max(lo), band.x0.max(band.x1).min(hi));
        // nothing inside the x range (or a NaN edge)
        if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
            continue;
        }
        let rect = Rectangle::new([(a, y1), (b, y0)], BAND_COLOR.mix(BAND_ALPHA).filled());
        cc.draw_series(std::iter::once(rect)).map_err(msg)?;
        if !band.label.is_empty() {
            entries.push(Entry { label: band.label.clone(), glyph: Glyph::Band });
        }
    }
    Ok(entries)
}

/// Draw every curve, clipped to its axis' bounds; returns the legend entries and adds the
/// drawn pixels to `obstacles`.
fn draw_curves<XC: Ranged<ValueType = f64>>(
    cc: &mut Coords<'_, '_, XC>,
    chart: &Chart,
    (left, right): (ToPixel, ToPixel),
    has_y2: bool,
    obstacles: &mut Vec<(i32, i32)>,
) -> std::result::Result<Vec<Entry>, String> {
    let mut entries = Vec::new();
    for curve in &chart.curves {
        let on_right = has_y2 && curve.axis == Axis::Right;
        let pix = if on_right { right } else { left };
        let bounds = pix.bounds;
        let label = if on_right && !curve.label.is_empty() {
            format!("{}, right axis", curve.label)
        } else {
            curve.label.clone()
        };
        let color = palette(curve.color);
        let glyph = match curve.style {
            LineStyle::Solid | LineStyle::Faint => {
                let style: ShapeStyle = if curve.style == LineStyle::Solid {
                    color.stroke_width(2)
                } else {
                    tint(color, FAINT_TINT).stroke_width(2)
                };
                let lines = bounds.polylines(&curve.x, &curve.y);
                for p in &lines {
                    pix.sample_polyline(p, obstacles);
                }
                draw_on!(cc, on_right, lines.into_iter().map(move |p| PathElement::new(p, style)));
                Glyph::Line(style)
            }
            LineStyle::Guide => {
                let (r, g, b) = super::GUIDE_COLOR;
                let style = RGBColor(r, g, b).stroke_width(2);
                let lines = bounds.polylines(&curve.x, &curve.y);
                draw_on!(cc, on_right, lines.into_iter().map(move |p| DashedPathElement::new(p, 6, 6, style)));
                Glyph::Dashed(style, 6, 6)
            }
            LineStyle::Dashed => {
                let style = color.stroke_width(2);
                let lines = bounds.polylines(&curve.x, &curve.y);
                for p in &lines {
                    pix.sample_polyline(p, obstacles);
                }
                draw_on!(cc, on_right, lines.into_iter().map(move |p| DashedPathElement::new(p, 10, 6, style)));
                Glyph::Dashed(style, 8, 5)
            }
            LineStyle::Points | LineStyle::Paper => {
                let points = bounds.points(&curve.x, &curve.y);
                let paper = curve.style == LineStyle::Paper;
                // a marker covers a few pixels around its centre
                let reach = if paper { PAPER_RADIUS } else { 4 };
                for &p in &points {
                    let (x, y) = pix.px(p);
                    let (x, y) = (x.round() as i32, y.round() as i32);
                    for dx in [-reach, 0, reach] {
                        for dy in [-reach, 0, reach] {
                            obstacles.push((x + dx, y + dy));
                        }
                    }
                }
                if paper {
                    let ring = RGBColor(30, 30, 30);
                    let elems = points.iter().flat_map(|&p| {
                        [
                            Circle::new(p, PAPER_RADIUS, WHITE.filled()),
                            Circle::new(p, PAPER_RADIUS, color.stroke_width(3)),
                            Circle::new(p, 2, ring.filled()),
                        ]
                    });
                    draw_on!(cc, on_right, elems);
                    Glyph::Paper(color)
                } else {
                    let style = color.filled();
                    draw_on!(cc, on_right, points.into_iter().map(move |p| Circle::new(p, 4, style)));
                    Glyph::Dot(color)
                }
            }
        };
        if !label.is_empty() {
            entries.push(Entry { label, glyph });
        }
    }
    Ok(entries)
}

/// Draw the vertical marker lines inside the x range (y from `y0` to `y1`); returns their
/// legend entries and adds the drawn pixels to `obstacles`.
fn draw_vlines<XC: Ranged<ValueType = f64>>(
    cc: &mut Coords<'_, '_, XC>,
    chart: &Chart,
    pix: ToPixel,
    (y0, y1): (f64, f64),
    obstacles: &mut Vec<(i32, i32)>,
) -> std::result::Result<Vec<Entry>, String> {
    let mut entries = Vec::new();
    for (i, vline) in chart.vlines.iter().enumerate() {
        let (dash, gap) = VLINE_DASHES[i % VLINE_DASHES.len()];
        let style = VLINE_COLOR.stroke_width(2);
        let visible = pix.bounds.contains(vline.x, y0);
        if visible {
            pix.sample_polyline(&[(vline.x, y0), (vline.x, y1)], obstacles);
        }
        let elems = visible.then(|| DashedPathElement::new(vec![(vline.x, y0), (vline.x, y1)], dash, gap, style));
        cc.draw_series(elems).map_err(msg)?;
        if visible && !vline.label.is_empty() {
            entries.push(Entry {
                label: vline.label.clone(),
                glyph: Glyph::Dashed(style, dash.min(8) as u32, gap.min(5) as u32),
            });
        }
    }
    Ok(entries)
}
