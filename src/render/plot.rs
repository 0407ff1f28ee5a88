//! One look for every figure: a small declarative layer over `plotters`.
//!
//! An experiment describes its figure as a [`Chart`] (title, axis labels, [`Curve`]s, optional
//! right-hand axis, optional log-scaled x axis, vertical marker lines) and calls
//! [`render_png`]. All figures share the same size ([`WIDTH`] x [`HEIGHT`]), fonts (DejaVu Sans,
//! bundled, so no system fonts are needed), colour-blind-friendly [`PALETTE`], mesh and legend
//! style.
//!
//! Rendering is deterministic (identical bytes for identical charts) and atomic: the PNG is
//! written to a hidden temporary file next to the target and renamed over it only when
//! complete. Non-finite points (and, on a log axis, non-positive x) are skipped, breaking the
//! line there; lines are clipped to the plotting area.

use std::ops::Range;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::{register_font, FontDesc, FontFamily, FontStyle, ShapeStyle};

use crate::error::{Error, Result};
use crate::render::table::fmt_sig;

/// Image width in pixels.
pub const WIDTH: u32 = 1200;
/// Image height in pixels.
pub const HEIGHT: u32 = 800;

/// The curve colours (Okabe–Ito colour-blind-friendly palette), as RGB triples:
/// black, orange, sky blue, bluish green, vermillion, blue, reddish purple, yellow.
/// [`Curve::color`] indexes this list (modulo its length).
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0, 0, 0),
    (230, 159, 0),
    (86, 180, 233),
    (0, 158, 115),
    (213, 94, 0),
    (0, 114, 178),
    (204, 121, 167),
    (240, 228, 66),
];

/// Title font size, pixels.
const TITLE_SIZE: f64 = 30.0;
/// Axis description font size, pixels.
pub(crate) const AXIS_DESC_SIZE: f64 = 22.0;
/// Tick label and legend font size, pixels.
pub(crate) const TICK_SIZE: f64 = 18.0;
/// Relative padding added to data-derived ranges.
const PAD: f64 = 0.05;
/// Colour of vertical marker lines.
const VLINE_COLOR: RGBColor = RGBColor(80, 80, 80);
/// Dash (length, gap) patterns, pixels, for successive vertical marker lines.
const VLINE_DASHES: [(i32, i32); 3] = [(12, 6), (4, 4), (20, 5)];
/// Width of the legend glyph area, pixels.
const LEGEND_GLYPH: i32 = 36;

/// Which y axis a curve is plotted against.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Axis {
    /// The left (primary) axis.
    #[default]
    Left,
    /// The right (secondary) axis; only used when [`Chart::y2_label`] is set, otherwise the
    /// curve goes on the left axis.
    Right,
}

/// How a curve is drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LineStyle {
    /// Solid line, 2 px.
    #[default]
    Solid,
    /// Dashed line, 2 px.
    Dashed,
    /// Thin (1 px) solid line in a light tint of the curve colour, for background curves.
    Faint,
    /// Markers only (filled circles), no connecting line.
    Points,
}

/// One data series.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Curve {
    /// Legend text; curves with an empty label get no legend entry.
    pub label: String,
    /// x values.
    pub x: Vec<f64>,
    /// y values (same length as `x`).
    pub y: Vec<f64>,
    /// Which y axis the curve uses.
    pub axis: Axis,
    /// How it is drawn.
    pub style: LineStyle,
    /// Index into [`PALETTE`] (taken modulo its length).
    pub color: usize,
}

impl Curve {
    /// A solid curve on the left axis in palette colour 0.
    pub fn new(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>) -> Self {
        Curve { label: label.into(), x, y, ..Curve::default() }
    }

    /// The same curve with another line style.
    pub fn with_style(mut self, style: LineStyle) -> Self {
        self.style = style;
        self
    }

    /// The same curve with another palette colour.
    pub fn with_color(mut self, color: usize) -> Self {
        self.color = color;
        self
    }

    /// The same curve on another axis.
    pub fn on_axis(mut self, axis: Axis) -> Self {
        self.axis = axis;
        self
    }
}

/// A vertical marker line across the whole plotting area (e.g. "concrete limit").
///
/// Drawn dashed in dark grey (successive lines use different dash patterns). A line outside
/// the x range (or at x <= 0 on a log axis) is not drawn and gets no legend entry.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VLine {
    /// Position on the x axis.
    pub x: f64,
    /// Legend text (empty: no legend entry).
    pub label: String,
}

impl VLine {
    /// A marker line at `x`.
    pub fn new(x: f64, label: impl Into<String>) -> Self {
        VLine { x, label: label.into() }
    }
}

/// A complete figure description.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chart {
    /// Title at the top of the figure.
    pub title: String,
    /// x axis label, with units.
    pub x_label: String,
    /// Left y axis label, with units.
    pub y_label: String,
    /// Right y axis label; when `Some`, curves with [`Axis::Right`] are drawn against a
    /// secondary axis on the right.
    pub y2_label: Option<String>,
    /// Logarithmic (base 10) x axis.
    pub x_log: bool,
    /// x range; `None`: from the data (and vertical lines) with ~5% padding.
    pub x_range: Option<(f64, f64)>,
    /// Left y range; `None`: from the data with ~5% padding.
    pub y_range: Option<(f64, f64)>,
    /// Right y range; `None`: from the data with ~5% padding.
    pub y2_range: Option<(f64, f64)>,
    /// The data series, drawn in order (later on top).
    pub curves: Vec<Curve>,
    /// Vertical marker lines.
    pub vlines: Vec<VLine>,
}

impl Chart {
    /// A chart with the given title and axis labels and nothing else.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Chart { title: title.into(), x_label: x_label.into(), y_label: y_label.into(), ..Chart::default() }
    }
}

/// Render `chart` as a [`WIDTH`] x [`HEIGHT`] PNG at `path`.
///
/// The directory of `path` must exist. The image is drawn into a temporary file
/// `.<file>.tmp.<pid>.<n>.png` in the same directory and renamed over `path` when complete, so
/// `path` is either the old file or the complete new one. Any failure (invalid ranges,
/// mismatched curve lengths, no finite point in any curve, missing directory, backend or
/// encoder errors) removes the temporary file and returns [`Error::Plot`] with `id`.
pub fn render_png(id: &str, chart: &Chart, path: &Path) -> Result<()> {
    let fail = |message: String| Error::Plot { id: id.to_string(), message };
    if !fonts_registered() {
        return Err(fail("could not load the bundled DejaVu Sans font".to_string()));
    }
    let plan = Plan::new(chart).map_err(&fail)?;
    let tmp = crate::render::io::temp_sibling(path, ".png").map_err(|e| fail(e.to_string()))?;

    // `catch_unwind` is a last line of defence: plotters may panic on inputs we did not
    // foresee, and a figure must never bring down the whole run.
    let drawn = catch_unwind(AssertUnwindSafe(|| -> std::result::Result<(), String> {
        let root = BitMapBackend::new(&tmp, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(msg)?;
        let (x0, x1) = plan.x;
        if plan.x_log {
            draw_chart(&root, chart, &plan, (x0..x1).log_scale())?;
        } else {
            draw_chart(&root, chart, &plan, x0..x1)?;
        }
        root.present().map_err(|e| format!("cannot write {}: {e}", tmp.display()))
        // `root` (and the backend) is dropped here, before the rename.
    }));
    let drawn = match drawn {
        Ok(r) => r,
        Err(panic) => Err(format!("plotting backend panicked: {}", panic_text(&*panic))),
    };
    match drawn {
        Ok(()) => crate::render::io::commit_temp(&tmp, path).map_err(|e| fail(e.to_string())),
        Err(message) => {
            // Dropping an unsaved backend writes the file; remove whatever is there.
            let _ = std::fs::remove_file(&tmp);
            Err(fail(message))
        }
    }
}

/// Register the bundled DejaVu Sans as "sans-serif" (once per process); `false` on failure.
pub(crate) fn fonts_registered() -> bool {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    *REGISTERED.get_or_init(|| {
        let normal = register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular());
        let bold = register_font("sans-serif", FontStyle::Bold, dejavu::sans::bold());
        normal.is_ok() && bold.is_ok()
    })
}

/// Display any error as a `String` (for `map_err`).
pub(crate) fn msg<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// The message of a caught panic.
pub(crate) fn panic_text(panic: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = panic.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = panic.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

/// Tick label for `v` on a linear axis spanning `range`.
///
/// Enough significant digits (at least 6) to tell ticks apart, trailing zeros trimmed, and
/// floating-point noise around zero (e.g. `1e-17` for a tick meant to be 0) shown as `0`.
pub(crate) fn tick_label(v: f64, (lo, hi): (f64, f64)) -> String {
    let span = (hi - lo).abs();
    if v.abs() <= span * 1e-9 {
        return "0".to_string();
    }
    let magnitude = lo.abs().max(hi.abs());
    let digits = if span > 0.0 { ((magnitude / span).log10().ceil() + 3.0).clamp(6.0, 15.0) as usize } else { 6 };
    fmt_sig(v, digits)
}

/// Text style in the bundled sans-serif font.
pub(crate) fn font(size: f64, style: FontStyle) -> TextStyle<'static> {
    TextStyle::from(FontDesc::new(FontFamily::SansSerif, size, style))
}

/// The title font: [`TITLE_SIZE`] bold, shrunk (down to [`TICK_SIZE`]) until `title` fits the
/// image width with a margin.
pub(crate) fn title_font(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    title: &str,
) -> std::result::Result<TextStyle<'static>, String> {
    let max_width = WIDTH.saturating_sub(60);
    let mut size = TITLE_SIZE;
    loop {
        let style = font(size, FontStyle::Bold);
        let (w, _) = root.estimate_text_size(title, &style).map_err(msg)?;
        if w <= max_width || size <= TICK_SIZE {
            return Ok(style);
        }
        size -= 1.0;
    }
}

/// Palette colour `i` (modulo the palette length).
fn palette(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

/// `c` mixed with `frac` white (0 = unchanged, 1 = white).
fn tint(c: RGBColor, frac: f64) -> RGBColor {
    let mix = |v: u8| (f64::from(v) + (255.0 - f64::from(v)) * frac).round().clamp(0.0, 255.0) as u8;
    RGBColor(mix(c.0), mix(c.1), mix(c.2))
}

/// Validated ranges and per-curve axis assignment for one chart.
struct Plan {
    x_log: bool,
    x: (f64, f64),
    y: (f64, f64),
    /// Secondary axis range, when the chart has a right axis.
    y2: Option<(f64, f64)>,
}

impl Plan {
    fn new(chart: &Chart) -> std::result::Result<Plan, String> {
        for (i, c) in chart.curves.iter().enumerate() {
            if c.x.len() != c.y.len() {
                return Err(format!("curve {} ('{}'): x has {} values but y has {}", i, c.label, c.x.len(), c.y.len()));
            }
        }
        let x_log = chart.x_log;
        let usable = |x: f64, y: f64| x.is_finite() && y.is_finite() && (!x_log || x > 0.0);
        if !chart.curves.iter().any(|c| c.x.iter().zip(&c.y).any(|(&x, &y)| usable(x, y))) {
            return Err(if x_log {
                "no curve has a finite point with x > 0 to plot on the log x axis".to_string()
            } else {
                "no curve has a finite point to plot".to_string()
            });
        }

        let x = match chart.x_range {
            Some(r) => check_range("x_range", r, x_log)?,
            None => {
                let xs = chart
                    .curves
                    .iter()
                    .flat_map(|c| c.x.iter().zip(&c.y).filter(|(&x, &y)| usable(x, y)).map(|(&x, _)| x))
                    .chain(chart.vlines.iter().map(|v| v.x).filter(|&x| x.is_finite() && (!x_log || x > 0.0)));
                let r = extent(xs).ok_or("no finite x values")?;
                let padded = if x_log { pad_log(r) } else { pad_linear(r) };
                check_range("x range from data", padded, x_log)?
            }
        };

        let has_y2 = chart.y2_label.is_some();
        let on_right = |c: &Curve| has_y2 && c.axis == Axis::Right;
        let in_x = |xv: f64| {
            let (a, b) = (x.0.min(x.1), x.0.max(x.1));
            xv >= a && xv <= b
        };
        let y_extent =
            |right: bool| {
                extent(chart.curves.iter().filter(|c| on_right(c) == right).flat_map(|c| {
                    c.x.iter().zip(&c.y).filter(|(&xv, &yv)| usable(xv, yv) && in_x(xv)).map(|(_, &yv)| yv)
                }))
            };

        let y = match chart.y_range {
            Some(r) => check_range("y_range", r, false)?,
            None => {
                // With every curve on the right axis, the left axis mirrors the right one.
                let r = y_extent(false).or_else(|| y_extent(true)).unwrap_or((0.0, 1.0));
                check_range("y range from data", pad_linear(r), false)?
            }
        };
        let y2 = if has_y2 {
            Some(match chart.y2_range {
                Some(r) => check_range("y2_range", r, false)?,
                None => match y_extent(true) {
                    Some(r) => check_range("y2 range from data", pad_linear(r), false)?,
                    None => y,
                },
            })
        } else {
            None
        };
        Ok(Plan { x_log, x, y, y2 })
    }
}

/// Smallest and largest of the values (`None` if there are none).
fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// Pad a data range by [`PAD`] of its span on both sides (a zero span gets a nominal width).
fn pad_linear((lo, hi): (f64, f64)) -> (f64, f64) {
    let span = hi - lo;
    let d = if span > 0.0 {
        span * PAD
    } else if lo == 0.0 {
        1.0
    } else {
        lo.abs() * 0.1
    };
    (lo - d, hi + d)
}

/// Pad a positive range by [`PAD`] of its span in log space, and widen it downwards to a
/// power of ten if it would otherwise contain none (the log axis only labels powers of ten
/// and their multiples).
fn pad_log((lo, hi): (f64, f64)) -> (f64, f64) {
    let (l0, l1) = (lo.log10(), hi.log10());
    let span = l1 - l0;
    let d = if span > 0.0 { span * PAD } else { 0.5 };
    let (mut a, b) = (l0 - d, l1 + d);
    if b.floor() < a.ceil() {
        a = a.floor();
    }
    (10f64.powf(a), 10f64.powf(b))
}

/// Check that a range is finite and increasing (and positive on a log axis).
fn check_range(what: &str, (lo, hi): (f64, f64), log: bool) -> std::result::Result<(f64, f64), String> {
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(format!("{what} ({lo}, {hi}) is not finite"));
    }
    if lo >= hi {
        return Err(format!("{what} ({lo}, {hi}) must be increasing"));
    }
    if log && lo <= 0.0 {
        return Err(format!("{what} ({lo}, {hi}) must be positive on a log axis"));
    }
    Ok((lo, hi))
}

/// A data point (x, y).
type Pt = (f64, f64);

/// The visible rectangle in axis space (log10 x on a log axis).
#[derive(Clone, Copy)]
struct Bounds {
    log: bool,
    u0: f64,
    u1: f64,
    v0: f64,
    v1: f64,
}

impl Bounds {
    fn new(x: (f64, f64), y: (f64, f64), log: bool) -> Self {
        let (u0, u1) = if log { (x.0.log10(), x.1.log10()) } else { x };
        Bounds { log, u0, u1, v0: y.0, v1: y.1 }
    }

    /// Axis-space u coordinate of data x.
    fn u(&self, x: f64) -> f64 {
        if self.log {
            x.log10()
        } else {
            x
        }
    }

    /// Data x of axis-space u.
    fn x(&self, u: f64) -> f64 {
        if self.log {
            10f64.powf(u)
        } else {
            u
        }
    }

    /// A point that can be placed on the axes at all.
    fn usable(&self, x: f64, y: f64) -> bool {
        x.is_finite() && y.is_finite() && (!self.log || x > 0.0)
    }

    fn contains(&self, x: f64, y: f64) -> bool {
        if !self.usable(x, y) {
            return false;
        }
        let u = self.u(x);
        u >= self.u0 && u <= self.u1 && y >= self.v0 && y <= self.v1
    }

    /// Liang–Barsky clip of segment a-b; returns the visible part and whether each end moved.
    fn clip(&self, a: Pt, b: Pt) -> Option<(Pt, Pt, bool, bool)> {
        let (ua, ub) = (self.u(a.0), self.u(b.0));
        let (du, dv) = (ub - ua, b.1 - a.1);
        let mut t0 = 0.0_f64;
        let mut t1 = 1.0_f64;
        for (p, q) in [(-du, ua - self.u0), (du, self.u1 - ua), (-dv, a.1 - self.v0), (dv, self.v1 - a.1)] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    if r > t1 {
                        return None;
                    }
                    t0 = t0.max(r);
                } else {
                    if r < t0 {
                        return None;
                    }
                    t1 = t1.min(r);
                }
            }
        }
        if !(t0.is_finite() && t1.is_finite()) || t0 > t1 {
            return None;
        }
        let at = |t: f64| (self.x(ua + t * du), a.1 + t * dv);
        let start = if t0 > 0.0 { at(t0) } else { a };
        let end = if t1 < 1.0 { at(t1) } else { b };
        Some((start, end, t0 > 0.0, t1 < 1.0))
    }

    /// The visible pieces of the polyline through (xs, ys): broken at unusable points and
    /// clipped to the bounds.
    fn polylines(&self, xs: &[f64], ys: &[f64]) -> Vec<Vec<(f64, f64)>> {
        let mut out = Vec::new();
        let mut current: Vec<(f64, f64)> = Vec::new();
        let mut continues = false; // `current` ends at the unclipped previous point
        for (wx, wy) in xs.windows(2).zip(ys.windows(2)) {
            let a = (wx[0], wy[0]);
            let b = (wx[1], wy[1]);
            if !(self.usable(a.0, a.1) && self.usable(b.0, b.1)) {
                continues = false;
                continue;
            }
            match self.clip(a, b) {
                None => continues = false,
                Some((s, e, s_moved, e_moved)) => {
                    if !continues || s_moved {
                        if current.len() >= 2 {
                            out.push(std::mem::take(&mut current));
                        }
                        current.clear();
                        current.push(s);
                    }
                    current.push(e);
                    continues = !e_moved;
                }
            }
        }
        if current.len() >= 2 {
            out.push(current);
        }
        out
    }

    /// The visible points of (xs, ys).
    fn points(&self, xs: &[f64], ys: &[f64]) -> Vec<(f64, f64)> {
        xs.iter().zip(ys).map(|(&x, &y)| (x, y)).filter(|&(x, y)| self.contains(x, y)).collect()
    }
}

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
fn draw_chart<X>(
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

#[cfg(test)]
mod tests {
    use super::*;

    const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];

    fn scratch() -> tempfile::TempDir {
        tempfile::tempdir().expect("create temp dir")
    }

    fn render_bytes(chart: &Chart, dir: &Path, name: &str) -> Vec<u8> {
        let path = dir.join(name);
        render_png("test", chart, &path).expect("render");
        std::fs::read(&path).expect("read png")
    }

    fn files_in(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .expect("read dir")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    fn dual_axis_chart() -> Chart {
        let t: Vec<f64> = (0..200).map(|i| f64::from(i) * 0.05e-3).collect();
        let force: Vec<f64> = t.iter().map(|&s| (s / 10e-3 * std::f64::consts::PI).sin() * 1500.0).collect();
        let mut disp: Vec<f64> = t.iter().map(|&s| s * 1e3 * 2.0).collect();
        disp[50] = f64::NAN; // break in the line
        let mut chart = Chart::new("Impact force and displacement", "time (ms)", "force (N)");
        chart.y2_label = Some("displacement (mm)".to_string());
        let tms: Vec<f64> = t.iter().map(|s| s * 1e3).collect();
        chart.curves.push(Curve::new("force", tms.clone(), force));
        chart.curves.push(
            Curve::new("displacement", tms.clone(), disp)
                .on_axis(Axis::Right)
                .with_style(LineStyle::Dashed)
                .with_color(1),
        );
        chart.curves.push(
            Curve::new("", tms.clone(), tms.iter().map(|v| v * 100.0).collect())
                .with_style(LineStyle::Faint)
                .with_color(2),
        );
        chart.curves.push(
            Curve::new("measured", vec![1.0, 3.0, 5.0, 7.0], vec![400.0, 1100.0, 1450.0, 1200.0])
                .with_style(LineStyle::Points)
                .with_color(4),
        );
        chart.vlines.push(VLine::new(5.0, "ball leaves strings"));
        chart
    }

    fn log_chart() -> Chart {
        let ks: Vec<f64> = (0..40).map(|i| 10f64.powf(3.0 + f64::from(i) * 0.1)).collect();
        let e: Vec<f64> = ks.iter().map(|k| 0.9 - 0.3 / (1.0 + k / 1e5)).collect();
        let mut chart = Chart::new("COR vs string stiffness", "string stiffness ks (N/m)", "e");
        chart.x_log = true;
        chart.curves.push(Curve::new("rigid frame", ks.clone(), e.clone()).with_color(5));
        chart.curves.push(
            Curve::new("flexible frame", ks.clone(), e.iter().map(|v| v - 0.05).collect())
                .with_style(LineStyle::Dashed)
                .with_color(3),
        );
        chart.vlines.push(VLine::new(2e4, "typical strings"));
        chart.vlines.push(VLine::new(-5.0, "invisible on log axis"));
        chart
    }

    #[test]
    fn renders_dual_axis_png_deterministically() {
        let dir = scratch();
        let chart = dual_axis_chart();
        let a = render_bytes(&chart, dir.path(), "dual.png");
        let b = render_bytes(&chart, dir.path(), "dual.png");
        assert_eq!(&a[..8], &PNG_SIGNATURE);
        assert!(a.len() > 10_000, "suspiciously small PNG: {} bytes", a.len());
        assert!(a == b, "rendering is not deterministic");
        assert_eq!(files_in(dir.path()), vec!["dual.png".to_string()]);
        if let Ok(keep) = std::env::var("RACKET_IMPACT_KEEP_TEST_PNG") {
            let _ = std::fs::copy(dir.path().join("dual.png"), Path::new(&keep).join("test_dual.png"));
        }
    }

    #[test]
    fn renders_log_x_png() {
        let dir = scratch();
        let chart = log_chart();
        let a = render_bytes(&chart, dir.path(), "log.png");
        let b = render_bytes(&chart, dir.path(), "log2.png");
        assert_eq!(&a[..8], &PNG_SIGNATURE);
        assert!(a.len() > 10_000);
        assert!(a == b);
        if let Ok(keep) = std::env::var("RACKET_IMPACT_KEEP_TEST_PNG") {
            let _ = std::fs::copy(dir.path().join("log.png"), Path::new(&keep).join("test_log.png"));
        }
    }

    #[test]
    fn log_x_with_right_axis_and_explicit_ranges() {
        let dir = scratch();
        let mut chart = log_chart();
        chart.y2_label = Some("ratio".to_string());
        chart.curves[1].axis = Axis::Right;
        chart.x_range = Some((1e3, 1e6));
        chart.y_range = Some((0.6, 0.8)); // narrower than the data: lines are clipped
        chart.y2_range = Some((0.0, 1.0));
        let a = render_bytes(&chart, dir.path(), "logdual.png");
        assert_eq!(&a[..8], &PNG_SIGNATURE);
    }

    #[test]
    fn long_title_is_shrunk_to_fit() {
        assert!(fonts_registered());
        let mut buf = vec![0u8; (WIDTH * HEIGHT * 3) as usize];
        let root = BitMapBackend::with_buffer(&mut buf, (WIDTH, HEIGHT)).into_drawing_area();
        let short = title_font(&root, "Short").expect("font");
        let long_title = "A very long title that would not fit at thirty pixels in bold, \
                          so it has to be made smaller to fit the figure";
        let long = title_font(&root, long_title).expect("font");
        assert!(long.font.get_size() < short.font.get_size());
        let (w, _) = root.estimate_text_size(long_title, &long).expect("size");
        assert!(w <= WIDTH - 60);
    }

    #[test]
    fn different_charts_give_different_images() {
        let dir = scratch();
        let a = render_bytes(&log_chart(), dir.path(), "a.png");
        let mut other = log_chart();
        other.title = "Another title".to_string();
        let b = render_bytes(&other, dir.path(), "b.png");
        assert!(a != b);
    }

    #[test]
    fn overwrites_existing_file() {
        let dir = scratch();
        let path = dir.path().join("fig.png");
        std::fs::write(&path, b"old").expect("write");
        render_png("t", &log_chart(), &path).expect("render");
        let bytes = std::fs::read(&path).expect("read");
        assert_eq!(&bytes[..8], &PNG_SIGNATURE);
    }

    #[test]
    fn no_finite_points_is_an_error() {
        let dir = scratch();
        let path = dir.path().join("empty.png");
        let mut chart = Chart::new("t", "x", "y");
        chart.curves.push(Curve::new("nan", vec![f64::NAN, 1.0], vec![1.0, f64::INFINITY]));
        let err = render_png("fig0", &chart, &path).expect_err("must fail");
        assert!(matches!(err, Error::Plot { ref id, .. } if id == "fig0"), "{err}");
        assert!(files_in(dir.path()).is_empty());

        // No curves at all.
        let chart = Chart::new("t", "x", "y");
        assert!(render_png("fig0", &chart, &path).is_err());

        // Only non-positive x on a log axis.
        let mut chart = Chart::new("t", "x", "y");
        chart.x_log = true;
        chart.curves.push(Curve::new("c", vec![-1.0, 0.0], vec![1.0, 2.0]));
        assert!(render_png("fig0", &chart, &path).is_err());
        assert!(files_in(dir.path()).is_empty());
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        let dir = scratch();
        let path = dir.path().join("bad.png");
        let good = Curve::new("c", vec![1.0, 2.0], vec![1.0, 2.0]);

        let mut chart = Chart::new("t", "x", "y");
        chart.curves.push(Curve::new("c", vec![1.0, 2.0], vec![1.0]));
        let err = render_png("f", &chart, &path).expect_err("length mismatch");
        assert!(err.to_string().contains("x has 2 values but y has 1"), "{err}");

        for (xr, yr, log) in [
            (Some((2.0, 1.0)), None, false),
            (Some((1.0, 1.0)), None, false),
            (Some((f64::NAN, 1.0)), None, false),
            (Some((0.0, 10.0)), None, true),
            (None, Some((0.0, f64::INFINITY)), false),
        ] {
            let mut chart = Chart::new("t", "x", "y");
            chart.curves.push(good.clone());
            chart.x_range = xr;
            chart.y_range = yr;
            chart.x_log = log;
            assert!(render_png("f", &chart, &path).is_err(), "{xr:?} {yr:?} {log}");
        }

        // Missing directory.
        let mut chart = Chart::new("t", "x", "y");
        chart.curves.push(good);
        let missing = dir.path().join("nope").join("f.png");
        let err = render_png("f", &chart, &missing).expect_err("missing dir");
        assert!(matches!(err, Error::Plot { .. }));
        assert!(files_in(dir.path()).is_empty());
    }

    #[test]
    fn degenerate_data_still_renders() {
        let dir = scratch();
        // One point, constant values, huge magnitudes.
        let mut chart = Chart::new("single", "x", "y");
        chart.curves.push(Curve::new("p", vec![3.0], vec![0.0]).with_style(LineStyle::Points));
        chart.curves.push(Curve::new("flat", vec![1.0, 2.0], vec![0.0, 0.0]).on_axis(Axis::Right));
        render_bytes(&chart, dir.path(), "single.png");

        let mut chart = Chart::new("huge", "x", "y");
        chart.curves.push(Curve::new("big", vec![0.0, 1e300], vec![-1e300, 1e300]));
        render_bytes(&chart, dir.path(), "huge.png");

        let mut chart = Chart::new("narrow log", "x", "y");
        chart.x_log = true;
        chart.curves.push(Curve::new("n", vec![2.0, 3.0, 8.0], vec![1.0, 2.0, 3.0]));
        render_bytes(&chart, dir.path(), "narrow.png");
    }

    #[test]
    fn polylines_break_and_clip() {
        let b = Bounds::new((0.0, 10.0), (0.0, 10.0), false);
        // NaN in the middle splits the line.
        let xs = [1.0, 2.0, 3.0, 4.0, 5.0];
        let ys = [1.0, 2.0, f64::NAN, 4.0, 5.0];
        let p = b.polylines(&xs, &ys);
        assert_eq!(p, vec![vec![(1.0, 1.0), (2.0, 2.0)], vec![(4.0, 4.0), (5.0, 5.0)]]);
        // A segment leaving and re-entering the box is clipped into two pieces.
        let xs = [1.0, 5.0, 9.0];
        let ys = [5.0, 15.0, 5.0];
        let p = b.polylines(&xs, &ys);
        assert_eq!(p.len(), 2);
        assert_eq!(p[0][0], (1.0, 5.0));
        assert!((p[0][1].0 - 3.0).abs() < 1e-12 && (p[0][1].1 - 10.0).abs() < 1e-12);
        assert!((p[1][0].0 - 7.0).abs() < 1e-12 && (p[1][0].1 - 10.0).abs() < 1e-12);
        assert_eq!(p[1][1], (9.0, 5.0));
        // Fully outside: nothing.
        assert!(b.polylines(&[20.0, 30.0], &[1.0, 1.0]).is_empty());
        // Log axis: non-positive x breaks the line.
        let bl = Bounds::new((1.0, 1000.0), (0.0, 10.0), true);
        let p = bl.polylines(&[1.0, 10.0, 0.0, 100.0, 1000.0], &[1.0; 5]);
        assert_eq!(p, vec![vec![(1.0, 1.0), (10.0, 1.0)], vec![(100.0, 1.0), (1000.0, 1.0)]]);
        // Points outside are dropped.
        assert_eq!(b.points(&[1.0, 11.0, f64::NAN], &[1.0, 1.0, 1.0]), vec![(1.0, 1.0)]);
    }

    #[test]
    fn tick_labels() {
        assert_eq!(tick_label(1400.0, (-75.0, 1575.0)), "1400");
        assert_eq!(tick_label(0.30000000000000004, (0.0, 1.0)), "0.3");
        assert_eq!(tick_label(1.1e-17, (-1.0, 1.0)), "0");
        assert_eq!(tick_label(-0.25, (-1.0, 1.0)), "-0.25");
        assert_eq!(tick_label(12345.62, (12345.5, 12345.7)), "12345.62");
        assert_eq!(tick_label(2e7, (0.0, 5e7)), "2e+07");
    }

    #[test]
    fn ranges_from_data() {
        assert_eq!(pad_linear((0.0, 10.0)), (-0.5, 10.5));
        assert_eq!(pad_linear((0.0, 0.0)), (-1.0, 1.0));
        assert_eq!(pad_linear((5.0, 5.0)), (4.5, 5.5));
        let (a, b) = pad_log((10.0, 1000.0));
        assert!((a.log10() - 0.9).abs() < 1e-12 && (b.log10() - 3.1).abs() < 1e-12);
        // No power of ten inside: widened down to one.
        let (a, b) = pad_log((2.0, 8.0));
        assert_eq!(a, 1.0);
        assert!(b > 8.0 && b < 10.0);
        assert_eq!(tint(RGBColor(0, 0, 0), 0.6), RGBColor(153, 153, 153));
        assert_eq!(tint(RGBColor(255, 255, 255), 0.6), RGBColor(255, 255, 255));
    }
}
