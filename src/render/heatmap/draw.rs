//! Drawing a heat map with `plotters`: title block, equal-aspect axes, shading, contour
//! lines, outlines, labelled segments and markers placed where they fit, and the colour bar.

use plotters::coord::types::RangedCoordf64;
use plotters::coord::{ReverseCoordTranslate, Shift};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontStyle;

use super::{color_range, contour_levels, contour_segments, diverging, fill_rim, viridis, Row, BELOW_FLOOR};
use super::{ColorScale, HeatMap, CONTOUR_TARGET};
use crate::numfmt::fmt_sig;
use crate::render::place::{first_least, inside, overlaps, Rect};
use crate::render::plot::{self, AXIS_DESC_SIZE, HEIGHT, TICK_SIZE, WIDTH};

/// Height of the title block (title and subtitle), pixels.
const TITLE_AREA: u32 = 92;
/// Width of the colour-bar block on the right, pixels.
const BAR_AREA: u32 = 190;
/// Margin around the plotting area inside the main block, pixels.
const MARGIN: u32 = 10;
/// Space for the x tick labels and description, pixels.
const X_LABEL_AREA: u32 = 62;
/// Space for the y tick labels and description, pixels.
const Y_LABEL_AREA: u32 = 82;
/// Width of the colour bar itself, pixels.
const BAR_WIDTH: i32 = 30;
/// Colour of outlines.
const OUTLINE_COLOR: RGBColor = RGBColor(40, 40, 40);

/// A tick label on the colour bar: as many decimals as the step needs.
pub(super) fn level_label(v: f64, step: f64) -> String {
    if step.is_nan() || step <= 0.0 || v.abs() >= 1e6 || (v != 0.0 && v.abs() < 1e-4) {
        return fmt_sig(v, 4);
    }
    let decimals = (0..=8).find(|&d| {
        let s = step * 10f64.powi(d);
        (s - s.round()).abs() <= 1e-6 * s
    });
    let d = decimals.unwrap_or(8) as usize;
    let v = if v.abs() < step * 1e-9 { 0.0 } else { v };
    format!("{v:.d$}")
}

/// Axis ranges with equal scales on both axes for a `w` x `h` pixel plotting area.
fn equal_aspect_ranges(map: &HeatMap, w: f64, h: f64) -> ((f64, f64), (f64, f64)) {
    let mut xs: Vec<f64> = map.xs.clone();
    let mut ys: Vec<f64> = map.ys.clone();
    for e in map.outlines.iter().chain(&map.clip) {
        xs.extend([e.x0, e.x1]);
        ys.extend([-e.half_height, e.half_height]);
    }
    for s in &map.segments {
        xs.extend([s.from.0, s.to.0]);
        ys.extend([s.from.1, s.to.1]);
    }
    for m in &map.markers {
        xs.push(m.at.0);
        ys.push(m.at.1);
    }
    let ext = |v: &[f64]| {
        v.iter().fold(None, |acc: Option<(f64, f64)>, &c| match acc {
            None => Some((c, c)),
            Some((lo, hi)) => Some((lo.min(c), hi.max(c))),
        })
    };
    let (x0, x1) = ext(&xs).unwrap_or((0.0, 1.0));
    let (y0, y1) = ext(&ys).unwrap_or((0.0, 1.0));
    let nominal = |lo: f64, hi: f64| if hi > lo { hi - lo } else { lo.abs().max(1.0) };
    let (dx, dy) = (nominal(x0, x1), nominal(y0, y1));
    // room for labels above and below the face
    let (px, py) = (0.04 * dx, 0.16 * dy);
    let scale = (w / (dx + 2.0 * px)).min(h / (dy + 2.0 * py));
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (hx, hy) = (0.5 * w / scale, 0.5 * h / scale);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// Draw a label with a translucent white box whose top-left corner is `(x, y)`.
fn boxed_text(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    text: &str,
    rect: Rect,
    style: &TextStyle<'_>,
) -> std::result::Result<(), String> {
    root.draw(&Rectangle::new([(rect.0, rect.1), (rect.2, rect.3)], WHITE.mix(0.85).filled())).map_err(plot::msg)?;
    root.draw(&Rectangle::new([(rect.0, rect.1), (rect.2, rect.3)], RGBColor(120, 120, 120).stroke_width(1)))
        .map_err(plot::msg)?;
    root.draw_text(text, style, (rect.0 + 5, rect.1 + 3)).map_err(plot::msg)
}

/// Data ranges: ((x0, x1), (y0, y1)).
pub(super) type Ranges = ((f64, f64), (f64, f64));

/// The plotting area's pixel rectangle and its data ranges (x, y) for `map`.
pub(super) fn plot_geometry(map: &HeatMap) -> (Rect, Ranges) {
    let plot_w = WIDTH - BAR_AREA - 2 * MARGIN - Y_LABEL_AREA;
    let plot_h = HEIGHT - TITLE_AREA - 2 * MARGIN - X_LABEL_AREA;
    let (left, top) = ((MARGIN + Y_LABEL_AREA) as i32, (TITLE_AREA + MARGIN) as i32);
    let rect = (left, top, left + plot_w as i32, top + plot_h as i32);
    (rect, equal_aspect_ranges(map, f64::from(plot_w), f64::from(plot_h)))
}

pub(super) fn draw(root: &DrawingArea<BitMapBackend<'_>, Shift>, map: &HeatMap) -> std::result::Result<(), String> {
    draw_titles(root, map)?;

    let (_, body) = root.split_vertically(TITLE_AREA);
    let (main, _) = body.split_horizontally(WIDTH - BAR_AREA);
    let (_, ((x0, x1), (y0, y1))) = plot_geometry(map);

    let mut cc = ChartBuilder::on(&main)
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(plot::msg)?;
    let x_fmt = |v: &f64| plot::tick_label(*v, (x0, x1));
    let y_fmt = |v: &f64| plot::tick_label(*v, (y0, y1));
    cc.configure_mesh()
        .disable_mesh()
        .x_desc(map.x_label.as_str())
        .y_desc(map.y_label.as_str())
        .label_style(plot::font(TICK_SIZE, FontStyle::Normal))
        .axis_desc_style(plot::font(AXIS_DESC_SIZE, FontStyle::Normal))
        .x_labels(12)
        .y_labels(10)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .draw()
        .map_err(plot::msg)?;

    // (the points the mask greys are left out of the scale and the contours)
    let shown = map.shown_values();
    let ((mut lo, mut hi), mut data) = color_range(&shown, map.scale);
    if let Some(floor) = map.floor {
        // the scale starts at the floor (values below are grey), the contours too
        lo = lo.max(floor);
        if hi <= lo {
            hi = lo + 1.0;
        }
        data = data.map(|(dlo, dhi)| (dlo.max(floor), dhi.max(floor)));
    }
    let below = RGBColor(BELOW_FLOOR.0, BELOW_FLOOR.1, BELOW_FLOOR.2);
    let color = |v: f64| {
        if map.floor.is_some_and(|f| v < f) {
            return below;
        }
        let t = (v - lo) / (hi - lo);
        match map.scale {
            ColorScale::Sequential => viridis(t),
            ColorScale::Diverging => diverging(t),
        }
    };

    let plot_rect = draw_shading(root, &cc, map, ((x0, x1), (y0, y1)), &color)?;

    // contour lines
    let (levels, step) = match data {
        Some((dlo, dhi)) => contour_levels(dlo, dhi, CONTOUR_TARGET),
        None => (Vec::new(), 0.0),
    };
    draw_lines(&mut cc, map, &shown, &levels)?;

    let mut labels =
        Labels { root, cc: &mut cc, plot_rect, style: plot::font(TICK_SIZE, FontStyle::Normal), taken: Vec::new() };
    labels.segments(map)?;
    labels.markers(map)?;
    labels.contour_labels(map, &levels, step)?;

    if data.is_none() {
        let style = plot::font(AXIS_DESC_SIZE, FontStyle::Normal).pos(Pos::new(HPos::Center, VPos::Center));
        let c = ((plot_rect.0 + plot_rect.2) / 2, (plot_rect.1 + plot_rect.3) / 2);
        root.draw_text("no data", &style, c).map_err(plot::msg)?;
    }

    draw_color_bar(root, map, plot_rect, (lo, hi), &levels, step, &color)
}

/// Font size of the contour labels, pixels.
const CONTOUR_LABEL_SIZE: f64 = 14.0;

/// The chart's coordinates (data x and y, both linear).
type Coords<'a, 'b> = ChartContext<'a, BitMapBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The title and, below it, the subtitle (shrunk to fit the width).
fn draw_titles(root: &DrawingArea<BitMapBackend<'_>, Shift>, map: &HeatMap) -> std::result::Result<(), String> {
    let title_style = plot::title_font(root, &map.title)?.pos(Pos::new(HPos::Center, VPos::Top));
    root.draw_text(&map.title, &title_style, (WIDTH as i32 / 2, 12)).map_err(plot::msg)?;
    if !map.subtitle.is_empty() {
        let mut size = TICK_SIZE;
        let sub = loop {
            let s = plot::font(size, FontStyle::Normal);
            let (w, _) = root.estimate_text_size(&map.subtitle, &s).map_err(plot::msg)?;
            if w <= WIDTH - 40 || size <= 11.0 {
                break s;
            }
            size -= 1.0;
        };
        let sub = sub.color(&RGBColor(60, 60, 60)).pos(Pos::new(HPos::Center, VPos::Top));
        root.draw_text(&map.subtitle, &sub, (WIDTH as i32 / 2, 56)).map_err(plot::msg)?;
    }
    Ok(())
}

/// Shade the plotting area pixel by pixel (inside every clip ellipse); returns the plotting
/// area's pixel rectangle.
fn draw_shading(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    cc: &Coords<'_, '_>,
    map: &HeatMap,
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
    color: &(dyn Fn(f64) -> RGBColor + Sync),
) -> std::result::Result<Rect, String> {
    let (px_range, py_range) = cc.plotting_area().get_pixel_range();
    let (pw, ph) = (f64::from(px_range.end - px_range.start), f64::from(py_range.end - py_range.start));
    let plot_rect: Rect = (px_range.start, py_range.start, px_range.end, py_range.end);
    // a clipped map's grid extended past its data so the shading reaches the outline
    let shaded = if map.clip.is_empty() { map.z.clone() } else { fill_rim(map.xs.len(), map.ys.len(), &map.z, 2) };
    let grey = match (map.grey_below_zero.is_empty(), map.clip.is_empty()) {
        (true, _) => Vec::new(),
        (false, true) => map.grey_below_zero.clone(),
        (false, false) => fill_rim(map.xs.len(), map.ys.len(), &map.grey_below_zero, 2),
    };
    let below = RGBColor(BELOW_FLOOR.0, BELOW_FLOOR.1, BELOW_FLOOR.2);
    // each pixel row's colours in parallel (a row depends on nothing but the map), then drawn
    // in order
    use rayon::prelude::*;
    let rows: Vec<Vec<(i32, RGBColor)>> = py_range
        .clone()
        .into_par_iter()
        .map(|py| {
            let y = y1 - (f64::from(py - py_range.start) + 0.5) / ph * (y1 - y0);
            let mut out = Vec::new();
            let Some(row) = Row::at(&map.xs, &map.ys, &shaded, y) else { return out };
            let grey_row = Row::at(&map.xs, &map.ys, &grey, y);
            let (mut cursor, mut grey_cursor) = (0, 0);
            for px in px_range.clone() {
                let x = x0 + (f64::from(px - px_range.start) + 0.5) / pw * (x1 - x0);
                if !map.clip.iter().all(|e| e.contains(x, y)) {
                    continue;
                }
                if let Some(v) = row.sample(x, &mut cursor) {
                    let greyed = grey_row.as_ref().and_then(|g| g.sample(x, &mut grey_cursor)).is_some_and(|g| g < 0.0);
                    out.push((px, if greyed { below } else { color(v) }));
                }
            }
            out
        })
        .collect();
    for (py, row) in py_range.clone().zip(rows) {
        for (px, c) in row {
            root.draw_pixel((px, py), &c).map_err(plot::msg)?;
        }
    }
    Ok(plot_rect)
}

/// The contour lines at `levels`, then the outlines (the first solid, the others dashed).
fn draw_lines(cc: &mut Coords<'_, '_>, map: &HeatMap, z: &[f64], levels: &[f64]) -> std::result::Result<(), String> {
    let contour_style = RGBColor(20, 20, 20).mix(0.55).stroke_width(1);
    for &level in levels {
        let segs = contour_segments(&map.xs, &map.ys, z, level);
        cc.draw_series(segs.into_iter().map(|s| PathElement::new(vec![s[0], s[1]], contour_style)))
            .map_err(plot::msg)?;
    }

    // outlines
    for (k, e) in map.outlines.iter().enumerate() {
        let pts = e.polyline(360);
        let style = OUTLINE_COLOR.stroke_width(2);
        if k == 0 {
            cc.draw_series(std::iter::once(PathElement::new(pts, style))).map_err(plot::msg)?;
        } else {
            cc.draw_series(std::iter::once(DashedPathElement::new(pts, 8, 5, style))).map_err(plot::msg)?;
        }
    }
    Ok(())
}

/// Where the labelled parts of a map are drawn (the dashed segments, the markers, the contour
/// labels): the image, the chart's coordinates on it, the plotting area's pixel rectangle, the
/// labels' font, and the label boxes placed so far, which each new label keeps clear of.
struct Labels<'c, 'a, 'b> {
    root: &'c DrawingArea<BitMapBackend<'b>, Shift>,
    cc: &'c mut Coords<'a, 'b>,
    plot_rect: Rect,
    style: TextStyle<'static>,
    taken: Vec<Rect>,
}

impl Labels<'_, '_, '_> {
    /// The dashed segments with their labels at the upper end, placed clear of what is taken.
    fn segments(&mut self, map: &HeatMap) -> std::result::Result<(), String> {
        let Labels { root, cc, plot_rect, style: label_style, taken } = self;
        let (root, plot_rect) = (*root, *plot_rect);
        for s in &map.segments {
            let style = BLACK.stroke_width(2);
            cc.draw_series(std::iter::once(DashedPathElement::new(vec![s.from, s.to], 10, 6, style)))
                .map_err(plot::msg)?;
            let (a, b) = (cc.backend_coord(&s.from), cc.backend_coord(&s.to));
            taken.push((a.0.min(b.0) - 3, a.1.min(b.1) - 3, a.0.max(b.0) + 3, a.1.max(b.1) + 3));
            if s.label.is_empty() {
                continue;
            }
            let (w, h) = root.estimate_text_size(&s.label, label_style).map_err(plot::msg)?;
            let (w, h) = (w as i32 + 10, h as i32 + 6);
            let (top, bottom) = if s.from.1 >= s.to.1 { (s.from, s.to) } else { (s.to, s.from) };
            let pt = cc.backend_coord(&top);
            let pb = cc.backend_coord(&bottom);
            let candidates =
                [(pt.0 - w / 2, pt.1 - 6 - h), (pb.0 - w / 2, pb.1 + 6), (pt.0 + 8, pt.1), (pt.0 - 8 - w, pt.1)];
            let rects = candidates.map(|(l, t)| (l, t, l + w, t + h));
            // the first box inside the plot and clear of the rest, else the first
            let cost = |r: Rect| usize::from(!inside(r, plot_rect) || taken.iter().any(|&o| overlaps(r, o)));
            let rect = first_least(rects, cost).map_or(rects[0], |(r, _)| r);
            boxed_text(root, &s.label, rect, label_style)?;
            taken.push(rect);
        }
        Ok(())
    }

    /// One label per contour line with its value, on a segment of the line (tried from the
    /// middle of the traced segments outwards) where the label box lies inside the plotting area
    /// and every clip ellipse and clear of what is taken; a level with no such place goes
    /// unlabelled.
    fn contour_labels(&mut self, map: &HeatMap, levels: &[f64], step: f64) -> std::result::Result<(), String> {
        let Labels { root, cc, plot_rect, taken, .. } = self;
        let (root, plot_rect) = (*root, *plot_rect);
        let style = plot::font(CONTOUR_LABEL_SIZE, FontStyle::Normal);
        let shown = map.shown_values();
        for &level in levels {
            let segs = contour_segments(&map.xs, &map.ys, &shown, level);
            if segs.is_empty() {
                continue;
            }
            let text = level_label(level, step);
            let (w, h) = root.estimate_text_size(&text, &style).map_err(plot::msg)?;
            let (w, h) = (w as i32 + 6, h as i32 + 4);
            let mid = segs.len() / 2;
            let order = (0..segs.len()).map(|k| if k % 2 == 0 { mid + k / 2 } else { mid.wrapping_sub(k / 2 + 1) });
            let inside_clip = |p: (i32, i32)| {
                cc.as_coord_spec().reverse_translate(p).is_some_and(|(x, y)| map.clip.iter().all(|e| e.contains(x, y)))
            };
            let rects = order.filter(|&k| k < segs.len()).map(|k| {
                let s = segs[k];
                let c = ((s[0].0 + s[1].0) / 2.0, (s[0].1 + s[1].1) / 2.0);
                let p = cc.backend_coord(&c);
                (p.0 - w / 2, p.1 - h / 2, p.0 - w / 2 + w, p.1 - h / 2 + h)
            });
            // the first box inside the plot and every clip ellipse and clear of the rest, or none
            let cost = |rect: Rect| {
                let corners = [(rect.0, rect.1), (rect.2, rect.1), (rect.0, rect.3), (rect.2, rect.3)];
                usize::from(
                    !(inside(rect, plot_rect)
                        && corners.iter().all(|&q| inside_clip(q))
                        && !taken.iter().any(|&o| overlaps(rect, o))),
                )
            };
            if let Some((rect, 0)) = first_least(rects, cost) {
                root.draw(&Rectangle::new([(rect.0, rect.1), (rect.2, rect.3)], WHITE.mix(0.8).filled()))
                    .map_err(plot::msg)?;
                root.draw_text(&text, &style, (rect.0 + 3, rect.1 + 2)).map_err(plot::msg)?;
                taken.push(rect);
            }
        }
        Ok(())
    }

    /// The markers (ringed dots) with their labels where they fit, clear of what is taken.
    fn markers(&mut self, map: &HeatMap) -> std::result::Result<(), String> {
        let Labels { root, cc, plot_rect, style: label_style, taken } = self;
        let (root, plot_rect) = (*root, *plot_rect);
        for m in &map.markers {
            let ring = [
                Circle::new(m.at, 9, WHITE.filled()),
                Circle::new(m.at, 9, BLACK.stroke_width(2)),
                Circle::new(m.at, 3, BLACK.filled()),
            ];
            cc.draw_series(ring).map_err(plot::msg)?;
            if m.label.is_empty() {
                continue;
            }
            let p = cc.backend_coord(&m.at);
            let (w, h) = root.estimate_text_size(&m.label, label_style).map_err(plot::msg)?;
            let (w, h) = (w as i32 + 10, h as i32 + 6);
            let candidates = [
                (p.0 + 14, p.1 - h / 2),
                (p.0 - 14 - w, p.1 - h / 2),
                (p.0 - w / 2, p.1 - 14 - h),
                (p.0 - w / 2, p.1 + 14),
                (p.0 + 10, p.1 - 10 - h),
                (p.0 - 10 - w, p.1 - 10 - h),
                (p.0 + 10, p.1 + 10),
                (p.0 - 10 - w, p.1 + 10),
            ];
            let rects = candidates.map(|(l, t)| (l, t, l + w, t + h));
            // the first box inside the plot and clear of the rest, else the first inside, else the first
            let cost = |r: Rect| match (inside(r, plot_rect), taken.iter().any(|&o| overlaps(r, o))) {
                (true, false) => 0,
                (true, true) => 1,
                (false, _) => 2,
            };
            let rect = first_least(rects, cost).map_or(rects[0], |(r, _)| r);
            boxed_text(root, &m.label, rect, label_style)?;
            taken.push(rect);
        }
        Ok(())
    }
}

/// The colour bar right of the plot, as tall as the plotting area, with the contour levels
/// marked and labelled.
fn draw_color_bar(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    map: &HeatMap,
    plot_rect: Rect,
    (lo, hi): (f64, f64),
    levels: &[f64],
    step: f64,
    color: &dyn Fn(f64) -> RGBColor,
) -> std::result::Result<(), String> {
    let left = (WIDTH - BAR_AREA) as i32 + 22;
    let right = left + BAR_WIDTH;
    let (top, bottom) = (plot_rect.1, plot_rect.3 - 1);
    if bottom <= top {
        return Ok(());
    }
    let y_of = |v: f64| bottom - ((v - lo) / (hi - lo) * f64::from(bottom - top)).round() as i32;
    for py in top..=bottom {
        let v = lo + f64::from(bottom - py) / f64::from(bottom - top) * (hi - lo);
        let c = color(v);
        for px in left..=right {
            root.draw_pixel((px, py), &c).map_err(plot::msg)?;
        }
    }
    root.draw(&Rectangle::new([(left, top), (right, bottom)], BLACK.stroke_width(1))).map_err(plot::msg)?;

    let style = plot::font(TICK_SIZE, FontStyle::Normal).pos(Pos::new(HPos::Left, VPos::Center));
    // the ticks: the contour levels (labelled as densely as the height allows), else the ends
    let (ticks, tick_step): (Vec<f64>, f64) =
        if levels.is_empty() { (vec![lo, hi], 0.0) } else { (levels.to_vec(), step) };
    let spacing = if ticks.len() > 1 {
        (f64::from(bottom - top) * (ticks[1] - ticks[0]) / (hi - lo)).abs()
    } else {
        f64::INFINITY
    };
    let every = ((TICK_SIZE + 6.0) / spacing).ceil().max(1.0) as usize;
    for (k, &v) in ticks.iter().enumerate() {
        let py = y_of(v);
        let line = if levels.is_empty() { BLACK.stroke_width(1) } else { RGBColor(20, 20, 20).stroke_width(1) };
        if !levels.is_empty() {
            root.draw(&PathElement::new(vec![(left, py), (right, py)], line)).map_err(plot::msg)?;
        }
        root.draw(&PathElement::new(vec![(right, py), (right + 6, py)], line)).map_err(plot::msg)?;
        if k % every == 0 {
            let text = if tick_step > 0.0 { level_label(v, tick_step) } else { fmt_sig(v, 4) };
            root.draw_text(&text, &style, (right + 10, py)).map_err(plot::msg)?;
        }
    }
    if !map.bar_label.is_empty() {
        // shrunk (to 11 px at the least) until it fits the image's height
        let mut size = AXIS_DESC_SIZE;
        while size > 11.0 {
            let (w, _) =
                root.estimate_text_size(&map.bar_label, &plot::font(size, FontStyle::Normal)).map_err(plot::msg)?;
            if w <= HEIGHT - 80 {
                break;
            }
            size -= 1.0;
        }
        let style = plot::font(size, FontStyle::Normal)
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Center));
        let x = WIDTH as i32 - 22;
        root.draw_text(&map.bar_label, &style, (x, (top + bottom) / 2)).map_err(plot::msg)?;
    }
    Ok(())
}
