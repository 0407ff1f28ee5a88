//! One look for every figure: a small declarative layer over `plotters`.
//!
//! An experiment describes its figure as a [`Chart`] (title, axis labels, [`Curve`]s, optional
//! right-hand axis, optional log-scaled x axis, vertical marker lines, shaded x bands) and calls
//! [`render_png`]. The paper's own numbers are drawn as [`LineStyle::Paper`] markers. All figures share the same size ([`WIDTH`] x [`HEIGHT`]), fonts (DejaVu Sans,
//! bundled, so no system fonts are needed), colour-blind-friendly [`PALETTE`], mesh and legend
//! style.
//!
//! Rendering is deterministic (identical bytes for identical charts) and atomic: the PNG is
//! written to a hidden temporary file next to the target and renamed over it only when
//! complete. Non-finite points (and, on a log axis, non-positive x) are skipped, breaking the
//! line there; lines are clipped to the plotting area, and a chart that cuts a curve off says
//! so in its legend ([`CLIPPED_NOTE`]). The legend goes in the corner or edge of the plotting
//! area where it covers the fewest curve pixels ([`place_legend`]).

mod clip;
mod draw;
mod legend;
mod plan;
pub mod sheet;
#[cfg(test)]
mod tests;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::{register_font, FontDesc, FontFamily, FontStyle};

use crate::error::{Error, Result};
use crate::numfmt::fmt_sig;
use draw::draw_chart;
pub use draw::FAINT_TINT;
pub use legend::place_legend;
pub use plan::clipped_points;
use plan::Plan;

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
/// Colour of a [`LineStyle::Guide`] line.
pub const GUIDE_COLOR: (u8, u8, u8) = (150, 150, 150);
/// Fill of the shaded x bands ([`Band`]).
const BAND_COLOR: RGBColor = RGBColor(150, 150, 150);
/// Opacity of the band fill.
const BAND_ALPHA: f64 = 0.18;
/// The legend line a chart gets when a curve runs outside the axis ranges and is cut off.
pub const CLIPPED_NOTE: &str = "(curves cut off at the axis limits)";

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
    /// Solid line in a lighter tint of the curve colour (30 % white, 2 px), for background
    /// curves: behind the main curves, still readable.
    Faint,
    /// Markers only (filled circles), no connecting line.
    Points,
    /// A reference level, not data: a thin dashed line in light grey ([`GUIDE_COLOR`]), behind
    /// the curves' colours (a scale to read them against).
    Guide,
    /// A value the paper states: a large ringed marker (white disc, thick ring in the curve
    /// colour, dark centre dot), no connecting line; distinct from any computed curve.
    Paper,
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

/// A shaded strip across the whole plotting area between two x values (e.g. "string face").
///
/// Drawn behind the curves in light grey; the part outside the x range is cut off, and a band
/// wholly outside gets no legend entry.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Band {
    /// One edge on the x axis.
    pub x0: f64,
    /// The other edge.
    pub x1: f64,
    /// Legend text (empty: no legend entry).
    pub label: String,
}

impl Band {
    /// A band from `x0` to `x1`.
    pub fn new(x0: f64, x1: f64, label: impl Into<String>) -> Self {
        Band { x0, x1, label: label.into() }
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
    /// Shaded x bands, drawn behind everything else.
    pub bands: Vec<Band>,
    /// Named x ticks (position, name) in place of the numbered ones (none: numbered), each
    /// with a grid line: an axis of categories, or of a scale whose numbers are not the
    /// data's (an asinh axis labelled in the untransformed values).
    pub x_ticks: Vec<(f64, String)>,
    /// Named y ticks, the same (the label area widens to the longest name; many names share
    /// the height in a smaller font).
    pub y_ticks: Vec<(f64, String)>,
    /// A second chart drawn below this one in the same image (its own title, axes, curves and
    /// legend), taking [`PANEL_SHARE`] of the height: a close-up of what the main chart shows
    /// at another scale. A panel's own panel is not drawn.
    pub panel: Option<Box<Chart>>,
}

/// The share of the image height a [`Chart::panel`] takes.
pub const PANEL_SHARE: f64 = 0.45;

impl Chart {
    /// A chart with the given title and axis labels and nothing else.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Chart { title: title.into(), x_label: x_label.into(), y_label: y_label.into(), ..Chart::default() }
    }

    /// This chart and its panel, if it has one: every plotting area the image draws.
    pub fn panels(&self) -> Vec<&Chart> {
        std::iter::once(self).chain(self.panel.as_deref()).collect()
    }
}

/// Render `chart` as a [`WIDTH`] x [`HEIGHT`] PNG at `path`.
///
/// The directory of `path` must exist. The image is drawn into a temporary file and published
/// by [`crate::render::io::write_with`] when complete, so `path` is either the old file or the
/// complete new one (a symlink's target is written, a device written through). Any failure (invalid ranges,
/// mismatched curve lengths, no finite point in any curve, missing directory, backend or
/// encoder errors) removes the temporary file and returns [`Error::Plot`] with `id`.
pub fn render_png(id: &str, chart: &Chart, path: &Path) -> Result<()> {
    let mut staged = crate::render::io::Staged::new();
    stage_png(&mut staged, id, chart, path)?;
    staged.commit()
}

/// [`render_png`] into `staged`, published with the other files of the same command.
pub fn stage_png(staged: &mut crate::render::io::Staged, id: &str, chart: &Chart, path: &Path) -> Result<()> {
    let fail = |message: String| Error::Plot { id: id.to_string(), message };
    if !fonts_registered() {
        return Err(fail("could not load the bundled DejaVu Sans font".to_string()));
    }
    let plans = chart.panels().into_iter().map(Plan::new).collect::<std::result::Result<Vec<_>, _>>().map_err(&fail)?;
    stage_drawn(staged, id, path, |tmp| {
        let root = BitMapBackend::new(tmp, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(msg)?;
        let areas = if chart.panel.is_some() {
            let (upper, lower) = root.split_vertically((f64::from(HEIGHT) * (1.0 - PANEL_SHARE)).round() as u32);
            vec![upper, lower]
        } else {
            vec![root.clone()]
        };
        for ((area, c), plan) in areas.iter().zip(chart.panels()).zip(&plans) {
            let (x0, x1) = plan.x;
            if plan.x_log {
                draw_chart(area, c, plan, (x0..x1).log_scale())?;
            } else {
                draw_chart(area, c, plan, x0..x1)?;
            }
        }
        root.present().map_err(|e| format!("cannot write {}: {e}", tmp.display()))
        // `root` (and the backend) is dropped here, before the rename.
    })
}

/// Draw a PNG at `path` into `staged` with `draw`, given the temporary file to draw in: a
/// failure is [`Error::Plot`] with `id` and leaves no file. `catch_unwind` is a last line of
/// defence: plotters may panic on inputs we did not foresee, and a figure must never bring down
/// the whole run.
pub(crate) fn stage_drawn(
    staged: &mut crate::render::io::Staged,
    id: &str,
    path: &Path,
    draw: impl FnOnce(&Path) -> std::result::Result<(), String>,
) -> Result<()> {
    let fail = |message: String| Error::Plot { id: id.to_string(), message };
    staged
        .with(path, ".png", |tmp| {
            match catch_unwind(AssertUnwindSafe(|| draw(tmp))) {
                Ok(r) => r,
                Err(panic) => Err(format!("plotting backend panicked: {}", panic_text(&*panic))),
            }
            .map_err(&fail)
        })
        .map_err(|e| match e {
            Error::Plot { .. } => e,
            other => fail(other.to_string()),
        })
}

/// An axis range that fits `values` (non-finite ones skipped): from their smallest (or 0 when
/// `from_zero` and none is negative) to their largest, padded by 5 % of the span and widened
/// outwards to a multiple of a round step (1, 2 or 5 times a power of ten, about a sixth of the
/// span), so the axis neither cuts a curve off nor runs far past the data. `None` without a
/// finite value.
pub fn fit_range(values: impl IntoIterator<Item = f64>, from_zero: bool) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc: Option<(f64, f64)>, v| Some(acc.map_or((v, v), |(l, h)| (l.min(v), h.max(v)))))?;
    if from_zero && lo >= 0.0 {
        lo = 0.0;
    }
    let span = if hi > lo { hi - lo } else { hi.abs().max(1.0) };
    let pad = 0.05 * span;
    let raw = (span + 2.0 * pad) / 6.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].into_iter().map(|k| k * mag).find(|s| *s >= raw).unwrap_or(10.0 * mag);
    let low = if from_zero && lo == 0.0 { 0.0 } else { ((lo - pad) / step).floor() * step };
    hi = ((hi + pad) / step).ceil() * step;
    Some((low, hi))
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

/// The smallest size a chart's title is drawn at before it is broken in two: a title that does
/// not fit one line at the full title size (30 px) is laid out on two ([`title_layout`])
/// rather than shrunk below this.
pub const MIN_TITLE_SIZE: f64 = 24.0;

/// Whether `text` fits the image width (with a margin) in bold at `size` pixels.
fn title_fits(text: &str, size: f64) -> bool {
    let max_width = WIDTH.saturating_sub(60);
    font(size, FontStyle::Bold).font.box_size(text).is_ok_and(|(w, _)| w <= max_width)
}

/// How a chart's title is drawn: its lines and their size in pixels. One line at the full size
/// (30 px, shrunk down to [`MIN_TITLE_SIZE`]) where it fits; else two lines at the largest size that
/// fits both, broken after a `:` (else a `;`, else a `,`, else a space) nearest the middle; a
/// title too long even for that is shrunk on its two lines down to the tick labels' size.
pub fn title_layout(title: &str) -> (Vec<String>, f64) {
    // (the text is measured in the bundled font)
    fonts_registered();
    let sizes = || (0..).map(|i| TITLE_SIZE - f64::from(i)).take_while(|s| *s >= TICK_SIZE);
    if let Some(size) = sizes().take_while(|s| *s >= MIN_TITLE_SIZE).find(|s| title_fits(title, *s)) {
        return (vec![title.to_string()], size);
    }
    // the break points of each kind, the ones nearest the middle first
    let middle = title.len() / 2;
    let splits = |sep: &str| {
        let mut at: Vec<usize> = title.match_indices(sep).map(|(i, _)| i + sep.trim_end().len()).collect();
        at.sort_by_key(|&i| i.abs_diff(middle));
        at
    };
    let kinds: Vec<Vec<usize>> = [": ", "; ", ", ", " "].iter().map(|sep| splits(sep)).collect();
    let lines = |i: usize| vec![title[..i].trim_end().to_string(), title[i..].trim_start().to_string()];
    for size in sizes() {
        for at in &kinds {
            if let Some(&i) = at.iter().find(|&&i| lines(i).iter().all(|l| title_fits(l, size))) {
                return (lines(i), size);
            }
        }
    }
    // nothing fits even at the smallest size: the most even break, at the smallest size
    match kinds[3].first() {
        Some(&i) => (lines(i), TICK_SIZE),
        None => (vec![title.to_string()], TICK_SIZE),
    }
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
