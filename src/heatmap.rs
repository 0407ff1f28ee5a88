//! Heat maps of a field sampled on a rectangular grid, with contour lines: the look of the
//! string-face maps ([`crate::study::map`]).
//!
//! A [`HeatMap`] is a grid `xs` x `ys` with one value per grid point (`z`, row-major: x slowest,
//! NaN = no data), shaded by a perceptually ordered colour map ([`viridis`]) or, for signed
//! differences, a diverging one centred on zero ([`diverging`]), with a colour bar, contour
//! lines at round levels ([`contour_levels`], traced by marching squares,
//! [`contour_segments`]), ellipse outlines, labelled dashed segments and labelled markers.
//! Both axes use the same scale (equal aspect).
//!
//! Shading: a pixel inside a grid cell whose four corners all have data is coloured by the
//! bilinear interpolation of the corners (the contour lines are the level sets of the same
//! interpolant along the cell edges); a pixel in a cell with only some corners is coloured by
//! the nearest of them, so the shading reaches the outline; the shading is clipped to every
//! ellipse in [`HeatMap::clip`].
//!
//! The image has the size, fonts and determinism of [`crate::plot`]: identical maps give
//! identical bytes, the file is written atomically, and no input (all NaN, a constant field, a
//! 2 x 2 grid, one point) panics.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontStyle;

use crate::error::{Error, Result};
use crate::plot::{self, AXIS_DESC_SIZE, HEIGHT, TICK_SIZE, WIDTH};
use crate::table::fmt_sig;

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
/// Contour lines aimed at (the actual count is 4 to 9, at round values).
pub const CONTOUR_TARGET: usize = 8;
/// Colour of outlines.
const OUTLINE_COLOR: RGBColor = RGBColor(40, 40, 40);

/// Viridis (matplotlib's perceptually uniform colour map) at t = 0, 0.1, ..., 1.
const VIRIDIS: [(u8, u8, u8); 11] = [
    (68, 1, 84),
    (72, 36, 117),
    (65, 68, 135),
    (53, 95, 141),
    (42, 120, 142),
    (33, 145, 140),
    (34, 168, 132),
    (68, 191, 112),
    (122, 209, 81),
    (189, 223, 38),
    (253, 231, 37),
];

/// ColorBrewer RdBu (11 classes), blue (negative) to red (positive), white in the middle.
const RDBU: [(u8, u8, u8); 11] = [
    (5, 48, 97),
    (33, 102, 172),
    (67, 147, 195),
    (146, 197, 222),
    (209, 229, 240),
    (247, 247, 247),
    (253, 219, 199),
    (244, 165, 130),
    (214, 96, 77),
    (178, 24, 43),
    (103, 0, 31),
];

/// Linear interpolation in an 11-stop colour table; `t` is clamped to [0, 1] (NaN gives 0).
fn lerp_table(table: &[(u8, u8, u8); 11], t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let f = t * 10.0;
    let i = (f.floor() as usize).min(9);
    let w = f - i as f64;
    let (a, b) = (table[i], table[i + 1]);
    let mix = |u: u8, v: u8| (f64::from(u) + w * (f64::from(v) - f64::from(u))).round().clamp(0.0, 255.0) as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The sequential colour map: dark purple (0) through teal to yellow (1).
pub fn viridis(t: f64) -> RGBColor {
    lerp_table(&VIRIDIS, t)
}

/// The diverging colour map: blue (0) through white (0.5) to red (1).
pub fn diverging(t: f64) -> RGBColor {
    lerp_table(&RDBU, t)
}

/// How values map to colours.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColorScale {
    /// [`viridis`] from the smallest to the largest value.
    #[default]
    Sequential,
    /// [`diverging`] over `[-m, m]`, `m` the largest |value|: zero is white.
    Diverging,
}

/// An ellipse with its axes along x and y, centred on y = 0, spanning `x0..x1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipse {
    /// Left end.
    pub x0: f64,
    /// Right end.
    pub x1: f64,
    /// Half the extent along y.
    pub half_height: f64,
}

impl Ellipse {
    /// Half the height at `x` (0 outside `x0..x1`).
    pub fn half_height_at(&self, x: f64) -> f64 {
        let a = 0.5 * (self.x1 - self.x0);
        if a.is_nan() || a <= 0.0 {
            return 0.0;
        }
        let q = (x - (self.x0 + a)) / a;
        if q.abs() > 1.0 {
            0.0
        } else {
            self.half_height * (1.0 - q * q).max(0.0).sqrt()
        }
    }

    /// `true` for points on or inside the ellipse.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.x0 && x <= self.x1 && y.abs() <= self.half_height_at(x)
    }

    /// The outline as a closed polyline of `n + 1` points.
    fn polyline(&self, n: usize) -> Vec<(f64, f64)> {
        let (a, c) = (0.5 * (self.x1 - self.x0), 0.5 * (self.x0 + self.x1));
        (0..=n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / n as f64;
                (c + a * t.cos(), self.half_height * t.sin())
            })
            .collect()
    }
}

/// A dashed segment with a label at its upper end (e.g. a vibration node across the face).
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// Start.
    pub from: (f64, f64),
    /// End (the label goes next to the higher end).
    pub to: (f64, f64),
    /// Label text (empty: none).
    pub label: String,
}

/// A point marked with a ringed dot and a label placed where it fits.
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    /// Position.
    pub at: (f64, f64),
    /// Label text (empty: none).
    pub label: String,
}

/// A complete heat-map description.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HeatMap {
    /// Title (bold, shrunk to fit the width).
    pub title: String,
    /// Second line under the title (smaller; empty: none).
    pub subtitle: String,
    /// x axis description.
    pub x_label: String,
    /// y axis description.
    pub y_label: String,
    /// Colour bar description (quantity and unit).
    pub bar_label: String,
    /// Grid x coordinates, strictly increasing.
    pub xs: Vec<f64>,
    /// Grid y coordinates, strictly increasing.
    pub ys: Vec<f64>,
    /// Values, `z[i * ys.len() + j]` at `(xs[i], ys[j])`; NaN (or any non-finite) = no data.
    pub z: Vec<f64>,
    /// Colour scale.
    pub scale: ColorScale,
    /// The shading is drawn only inside every one of these (none: the whole grid).
    pub clip: Vec<Ellipse>,
    /// Outlines drawn on top (solid, dark grey; the second and later dashed).
    pub outlines: Vec<Ellipse>,
    /// Dashed labelled segments.
    pub segments: Vec<Segment>,
    /// Labelled markers.
    pub markers: Vec<Marker>,
}

/// The colour range of the finite values: (lo, hi) with lo < hi, and the data extent (if any).
pub fn color_range(z: &[f64], scale: ColorScale) -> ((f64, f64), Option<(f64, f64)>) {
    let data = z.iter().copied().filter(|v| v.is_finite()).fold(None, |acc: Option<(f64, f64)>, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    });
    let range = match (scale, data) {
        (_, None) => match scale {
            ColorScale::Sequential => (0.0, 1.0),
            ColorScale::Diverging => (-1.0, 1.0),
        },
        (ColorScale::Sequential, Some((lo, hi))) => {
            if hi > lo {
                (lo, hi)
            } else {
                let d = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
                (lo - d, hi + d)
            }
        }
        (ColorScale::Diverging, Some((lo, hi))) => {
            let m = lo.abs().max(hi.abs());
            let m = if m > 0.0 { m } else { 1.0 };
            (-m, m)
        }
    };
    (range, data)
}

/// Round contour levels strictly inside the data range `(lo, hi)`: the multiples of a nice
/// step (1, 2, 2.5 or 5 times a power of ten) whose count is nearest `target` (the larger step
/// on a tie). Returns the levels and the step (empty for an empty, constant or non-finite
/// range).
pub fn contour_levels(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let span = hi - lo;
    if !(lo.is_finite() && hi.is_finite() && span > 0.0 && target > 0) {
        return (Vec::new(), 0.0);
    }
    let eps = span * 1e-9;
    let levels_for = |step: f64| -> Vec<f64> {
        let first = (lo / step).ceil() as i64;
        let last = (hi / step).floor() as i64;
        (first..=last)
            .map(|k| {
                let v = k as f64 * step;
                if v.abs() < eps {
                    0.0
                } else {
                    v
                }
            })
            .filter(|&v| v > lo + eps && v < hi - eps)
            .collect()
    };
    let p = 10f64.powf((span / target as f64).log10().floor());
    let mut best: Option<(usize, f64, Vec<f64>)> = None;
    for step in [0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0].map(|m| m * p) {
        if !(step.is_finite() && step > 0.0) {
            continue;
        }
        let levels = levels_for(step);
        let miss = levels.len().abs_diff(target);
        if best.as_ref().is_none_or(|b| miss <= b.0) {
            best = Some((miss, step, levels));
        }
    }
    match best {
        Some((_, step, levels)) => (levels, step),
        None => (Vec::new(), 0.0),
    }
}

/// A contour segment: two points.
pub type Seg = [(f64, f64); 2];

/// Marching squares: the segments of the contour `z = level` on the grid (bilinear cells,
/// crossings interpolated linearly along the cell edges; saddles resolved by the cell's mean).
/// Cells with a non-finite corner are skipped. A corner counts as above the level when
/// `z > level`.
pub fn contour_segments(xs: &[f64], ys: &[f64], z: &[f64], level: f64) -> Vec<Seg> {
    let (nx, ny) = (xs.len(), ys.len());
    let mut out = Vec::new();
    if nx < 2 || ny < 2 || z.len() != nx * ny || !level.is_finite() {
        return out;
    }
    for i in 0..nx - 1 {
        for j in 0..ny - 1 {
            // corners: 0 bottom-left, 1 bottom-right, 2 top-right, 3 top-left
            let p = [(xs[i], ys[j]), (xs[i + 1], ys[j]), (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])];
            let v = [z[i * ny + j], z[(i + 1) * ny + j], z[(i + 1) * ny + j + 1], z[i * ny + j + 1]];
            if v.iter().any(|c| !c.is_finite()) {
                continue;
            }
            let case = v.iter().enumerate().fold(0usize, |acc, (k, &c)| acc | (usize::from(c > level) << k));
            // the crossing on edge e (between corners e and e+1)
            let edge = |e: usize| {
                let (a, b) = (e, (e + 1) % 4);
                let t = (level - v[a]) / (v[b] - v[a]);
                let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.5 };
                (p[a].0 + t * (p[b].0 - p[a].0), p[a].1 + t * (p[b].1 - p[a].1))
            };
            let centre_above = 0.25 * (v[0] + v[1] + v[2] + v[3]) > level;
            let pairs: &[(usize, usize)] = match case {
                1 | 14 => &[(3, 0)],
                2 | 13 => &[(0, 1)],
                3 | 12 => &[(3, 1)],
                4 | 11 => &[(1, 2)],
                6 | 9 => &[(0, 2)],
                7 | 8 => &[(2, 3)],
                5 if centre_above => &[(0, 1), (2, 3)],
                5 => &[(3, 0), (1, 2)],
                10 if centre_above => &[(3, 0), (1, 2)],
                10 => &[(0, 1), (2, 3)],
                _ => &[],
            };
            out.extend(pairs.iter().map(|&(a, b)| [edge(a), edge(b)]));
        }
    }
    out
}

/// The value at `(x, y)`: bilinear in a cell whose four corners are finite, else the nearest
/// finite corner of the cell; `None` outside the grid or in a cell without data.
pub fn sample(xs: &[f64], ys: &[f64], z: &[f64], x: f64, y: f64) -> Option<f64> {
    let (nx, ny) = (xs.len(), ys.len());
    if nx < 2 || ny < 2 || z.len() != nx * ny {
        return None;
    }
    if !(x >= xs[0] && x <= xs[nx - 1] && y >= ys[0] && y <= ys[ny - 1]) {
        return None;
    }
    let i = xs.partition_point(|&v| v <= x).clamp(1, nx - 1) - 1;
    let j = ys.partition_point(|&v| v <= y).clamp(1, ny - 1) - 1;
    let t = (x - xs[i]) / (xs[i + 1] - xs[i]);
    let u = (y - ys[j]) / (ys[j + 1] - ys[j]);
    let c = [
        (0.0, 0.0, z[i * ny + j]),
        (1.0, 0.0, z[(i + 1) * ny + j]),
        (1.0, 1.0, z[(i + 1) * ny + j + 1]),
        (0.0, 1.0, z[i * ny + j + 1]),
    ];
    if c.iter().all(|k| k.2.is_finite()) {
        let bottom = c[0].2 + t * (c[1].2 - c[0].2);
        let top = c[3].2 + t * (c[2].2 - c[3].2);
        return Some(bottom + u * (top - bottom));
    }
    c.iter()
        .filter(|k| k.2.is_finite())
        .map(|k| ((k.0 - t).powi(2) + (k.1 - u).powi(2), k.2))
        .fold(None, |best: Option<(f64, f64)>, cand| match best {
            Some(b) if b.0 <= cand.0 => Some(b),
            _ => Some(cand),
        })
        .map(|b| b.1)
}

/// The field for the shading only: each missing grid point next to data gets a value
/// extrapolated linearly (in the grid index) from its neighbours along x and y (the mean over
/// the directions that have data; the diagonal neighbours' mean if none), `passes` times, so
/// the shading reaches an outline that runs between grid points. Contours use the data only.
pub fn extend_for_shading(nx: usize, ny: usize, z: &[f64], passes: usize) -> Vec<f64> {
    let mut cur = z.to_vec();
    if z.len() != nx * ny {
        return cur;
    }
    for _ in 0..passes {
        let prev = cur.clone();
        let at = |i: i64, j: i64| -> Option<f64> {
            if i < 0 || j < 0 || i >= nx as i64 || j >= ny as i64 {
                return None;
            }
            let v = prev[i as usize * ny + j as usize];
            v.is_finite().then_some(v)
        };
        for i in 0..nx as i64 {
            for j in 0..ny as i64 {
                if at(i, j).is_some() {
                    continue;
                }
                let (mut sum, mut n) = (0.0, 0u32);
                for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
                    match (at(i + di, j + dj), at(i + 2 * di, j + 2 * dj)) {
                        (Some(a), Some(b)) => (sum, n) = (sum + 2.0 * a - b, n + 1),
                        (Some(a), None) => (sum, n) = (sum + a, n + 1),
                        _ => {}
                    }
                }
                if n == 0 {
                    for (di, dj) in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
                        if let Some(a) = at(i + di, j + dj) {
                            (sum, n) = (sum + a, n + 1);
                        }
                    }
                }
                if n > 0 {
                    cur[i as usize * ny + j as usize] = sum / f64::from(n);
                }
            }
        }
    }
    cur
}

/// A tick label on the colour bar: as many decimals as the step needs.
fn level_label(v: f64, step: f64) -> String {
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

/// Render `map` as a [`WIDTH`] x [`HEIGHT`] PNG at `path`, atomically (see
/// [`crate::plot::render_png`]); errors are [`Error::Plot`] with `id`.
pub fn render_png(id: &str, map: &HeatMap, path: &Path) -> Result<()> {
    let fail = |message: String| Error::Plot { id: id.to_string(), message };
    let tmp = crate::io::temp_sibling(path, ".png").map_err(|e| fail(e.to_string()))?;
    match draw_file(map, &tmp) {
        Ok(()) => crate::io::commit_temp(&tmp, path).map_err(|e| fail(e.to_string())),
        Err(message) => Err(fail(message)),
    }
}

/// Draw `map` into the file `file` (not atomically; on failure the file is removed).
pub(crate) fn draw_file(map: &HeatMap, file: &Path) -> std::result::Result<(), String> {
    if !plot::fonts_registered() {
        return Err("could not load the bundled DejaVu Sans font".to_string());
    }
    check(map)?;
    let drawn = catch_unwind(AssertUnwindSafe(|| -> std::result::Result<(), String> {
        let root = BitMapBackend::new(file, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(plot::msg)?;
        draw(&root, map)?;
        root.present().map_err(|e| format!("cannot write {}: {e}", file.display()))
    }));
    let drawn = match drawn {
        Ok(r) => r,
        Err(panic) => Err(format!("plotting backend panicked: {}", plot::panic_text(&*panic))),
    };
    if drawn.is_err() {
        let _ = std::fs::remove_file(file);
    }
    drawn
}

/// Structural checks: grid sizes and monotone finite coordinates.
fn check(map: &HeatMap) -> std::result::Result<(), String> {
    if map.z.len() != map.xs.len() * map.ys.len() {
        return Err(format!("the grid has {} x {} points but {} values", map.xs.len(), map.ys.len(), map.z.len()));
    }
    for (name, v) in [("xs", &map.xs), ("ys", &map.ys)] {
        if v.iter().any(|c| !c.is_finite()) || v.windows(2).any(|w| w[0] >= w[1]) {
            return Err(format!("grid {name} must be finite and strictly increasing"));
        }
    }
    let finite_pt = |(x, y): (f64, f64)| x.is_finite() && y.is_finite();
    if map.outlines.iter().chain(&map.clip).any(|e| !(finite_pt((e.x0, e.x1)) && e.half_height.is_finite())) {
        return Err("ellipse outlines must be finite".to_string());
    }
    if map.segments.iter().any(|s| !(finite_pt(s.from) && finite_pt(s.to)))
        || map.markers.iter().any(|m| !finite_pt(m.at))
    {
        return Err("segments and markers must be finite".to_string());
    }
    Ok(())
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

/// A pixel rectangle: (left, top, right, bottom).
type Rect = (i32, i32, i32, i32);

fn overlaps(a: Rect, b: Rect) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

fn inside(a: Rect, area: Rect) -> bool {
    a.0 >= area.0 && a.1 >= area.1 && a.2 <= area.2 && a.3 <= area.3
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

fn draw(root: &DrawingArea<BitMapBackend<'_>, Shift>, map: &HeatMap) -> std::result::Result<(), String> {
    // title block
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

    let (_, body) = root.split_vertically(TITLE_AREA);
    let (main, _) = body.split_horizontally(WIDTH - BAR_AREA);
    let plot_w = f64::from(WIDTH - BAR_AREA - 2 * MARGIN - Y_LABEL_AREA);
    let plot_h = f64::from(HEIGHT - TITLE_AREA - 2 * MARGIN - X_LABEL_AREA);
    let ((x0, x1), (y0, y1)) = equal_aspect_ranges(map, plot_w, plot_h);

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

    let ((lo, hi), data) = color_range(&map.z, map.scale);
    let color = |v: f64| {
        let t = (v - lo) / (hi - lo);
        match map.scale {
            ColorScale::Sequential => viridis(t),
            ColorScale::Diverging => diverging(t),
        }
    };

    // shading, pixel by pixel
    let shade = extend_for_shading(map.xs.len(), map.ys.len(), &map.z, 2);
    let (px_range, py_range) = cc.plotting_area().get_pixel_range();
    let (pw, ph) = (f64::from(px_range.end - px_range.start), f64::from(py_range.end - py_range.start));
    let plot_rect: Rect = (px_range.start, py_range.start, px_range.end, py_range.end);
    for py in py_range.clone() {
        let y = y1 - (f64::from(py - py_range.start) + 0.5) / ph * (y1 - y0);
        for px in px_range.clone() {
            let x = x0 + (f64::from(px - px_range.start) + 0.5) / pw * (x1 - x0);
            if !map.clip.iter().all(|e| e.contains(x, y)) {
                continue;
            }
            if let Some(v) = sample(&map.xs, &map.ys, &shade, x, y) {
                root.draw_pixel((px, py), &color(v)).map_err(plot::msg)?;
            }
        }
    }

    // contour lines
    let (levels, step) = match data {
        Some((dlo, dhi)) => contour_levels(dlo, dhi, CONTOUR_TARGET),
        None => (Vec::new(), 0.0),
    };
    let contour_style = RGBColor(20, 20, 20).mix(0.55).stroke_width(1);
    for &level in &levels {
        let segs = contour_segments(&map.xs, &map.ys, &map.z, level);
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

    let label_style = plot::font(TICK_SIZE, FontStyle::Normal);
    let mut taken: Vec<Rect> = Vec::new();

    // dashed segments with their labels at the upper end
    for s in &map.segments {
        let style = BLACK.stroke_width(2);
        cc.draw_series(std::iter::once(DashedPathElement::new(vec![s.from, s.to], 10, 6, style))).map_err(plot::msg)?;
        let (a, b) = (cc.backend_coord(&s.from), cc.backend_coord(&s.to));
        taken.push((a.0.min(b.0) - 3, a.1.min(b.1) - 3, a.0.max(b.0) + 3, a.1.max(b.1) + 3));
        if s.label.is_empty() {
            continue;
        }
        let (w, h) = root.estimate_text_size(&s.label, &label_style).map_err(plot::msg)?;
        let (w, h) = (w as i32 + 10, h as i32 + 6);
        let (top, bottom) = if s.from.1 >= s.to.1 { (s.from, s.to) } else { (s.to, s.from) };
        let pt = cc.backend_coord(&top);
        let pb = cc.backend_coord(&bottom);
        let candidates =
            [(pt.0 - w / 2, pt.1 - 6 - h), (pb.0 - w / 2, pb.1 + 6), (pt.0 + 8, pt.1), (pt.0 - 8 - w, pt.1)];
        let rects: Vec<Rect> = candidates.iter().map(|&(l, t)| (l, t, l + w, t + h)).collect();
        let rect = rects
            .iter()
            .copied()
            .find(|&r| inside(r, plot_rect) && !taken.iter().any(|&o| overlaps(r, o)))
            .unwrap_or(rects[0]);
        boxed_text(root, &s.label, rect, &label_style)?;
        taken.push(rect);
    }

    // markers
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
        let (w, h) = root.estimate_text_size(&m.label, &label_style).map_err(plot::msg)?;
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
        let rects: Vec<Rect> = candidates.iter().map(|&(l, t)| (l, t, l + w, t + h)).collect();
        let rect = rects
            .iter()
            .copied()
            .find(|&r| inside(r, plot_rect) && !taken.iter().any(|&o| overlaps(r, o)))
            .or_else(|| rects.iter().copied().find(|&r| inside(r, plot_rect)))
            .unwrap_or(rects[0]);
        boxed_text(root, &m.label, rect, &label_style)?;
        taken.push(rect);
    }

    if data.is_none() {
        let style = plot::font(AXIS_DESC_SIZE, FontStyle::Normal).pos(Pos::new(HPos::Center, VPos::Center));
        let c = ((plot_rect.0 + plot_rect.2) / 2, (plot_rect.1 + plot_rect.3) / 2);
        root.draw_text("no data", &style, c).map_err(plot::msg)?;
    }

    draw_color_bar(root, map, plot_rect, (lo, hi), &levels, step, &color)
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
        let style = plot::font(AXIS_DESC_SIZE, FontStyle::Normal)
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Center));
        let x = WIDTH as i32 - 22;
        root.draw_text(&map.bar_label, &style, (x, (top + bottom) / 2)).map_err(plot::msg)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let xs: Vec<f64> = (0..nx).map(|i| i as f64).collect();
        let ys: Vec<f64> = (0..ny).map(|j| j as f64).collect();
        let z = xs.iter().flat_map(|&x| ys.iter().map(move |&y| (x, y))).map(|(x, y)| f(x, y)).collect();
        (xs, ys, z)
    }

    #[test]
    fn linear_field_gives_straight_contours_at_the_level() {
        // z = x: the contour z = 1.5 is the vertical line x = 1.5
        let (xs, ys, z) = grid(4, 5, |x, _| x);
        let segs = contour_segments(&xs, &ys, &z, 1.5);
        assert_eq!(segs.len(), 4, "one segment per cell row");
        for s in &segs {
            assert_eq!((s[0].0, s[1].0), (1.5, 1.5));
            assert_eq!((s[0].1 - s[1].1).abs(), 1.0);
        }
        // z = 2x + y: the contour z = 3 is the line y = 3 - 2x; every segment lies on it
        let (xs, ys, z) = grid(5, 5, |x, y| 2.0 * x + y);
        let segs = contour_segments(&xs, &ys, &z, 3.0);
        assert!(!segs.is_empty());
        for s in &segs {
            for p in s {
                assert!((p.1 - (3.0 - 2.0 * p.0)).abs() < 1e-12, "{p:?}");
            }
        }
        // total length: the line from (0, 3) to (1.5, 0) inside the grid
        let len: f64 = segs.iter().map(|s| ((s[1].0 - s[0].0).powi(2) + (s[1].1 - s[0].1).powi(2)).sqrt()).sum();
        assert!((len - (1.5f64.powi(2) + 9.0).sqrt()).abs() < 1e-12, "{len}");
    }

    #[test]
    fn contours_skip_missing_cells_and_constant_fields() {
        let (xs, ys, mut z) = grid(3, 3, |x, _| x);
        z[4] = f64::NAN; // the centre point: every cell touches it
        assert!(contour_segments(&xs, &ys, &z, 0.5).is_empty());
        let (xs, ys, z) = grid(3, 3, |_, _| 2.0);
        assert!(contour_segments(&xs, &ys, &z, 2.0).is_empty());
        assert!(contour_segments(&[0.0], &[0.0], &[1.0], 0.5).is_empty());
    }

    #[test]
    fn saddles_give_two_segments() {
        // corners 1 0 / 0 1 around a cell
        let xs = [0.0, 1.0];
        let ys = [0.0, 1.0];
        let z = [1.0, 0.0, 0.0, 1.0]; // (0,0)=1, (0,1)=0, (1,0)=0, (1,1)=1
        assert_eq!(contour_segments(&xs, &ys, &z, 0.5).len(), 2);
    }

    #[test]
    fn levels_are_round_and_inside() {
        let (l, step) = contour_levels(0.112, 0.418, 8);
        assert_eq!(step, 0.05);
        assert_eq!(l.len(), 6);
        assert!((l[0] - 0.15).abs() < 1e-12 && (l[5] - 0.4).abs() < 1e-12);
        let (l, _) = contour_levels(-2.3, 1.1, 8);
        assert!(l.contains(&0.0));
        assert!(contour_levels(1.0, 1.0, 8).0.is_empty());
        assert!(contour_levels(f64::NAN, 1.0, 8).0.is_empty());
        assert_eq!(level_label(0.15000000000000002, 0.05), "0.15");
        assert_eq!(level_label(-0.0, 0.25), "0.00");
        assert_eq!(level_label(40.0, 5.0), "40");
    }

    #[test]
    fn sampling_is_bilinear_inside_and_nearest_at_the_edge() {
        let (xs, ys, mut z) = grid(3, 3, |x, y| x + 10.0 * y);
        assert!((sample(&xs, &ys, &z, 0.5, 0.25).unwrap() - 3.0).abs() < 1e-12);
        assert_eq!(sample(&xs, &ys, &z, 2.0, 2.0), Some(22.0));
        assert_eq!(sample(&xs, &ys, &z, -0.1, 0.0), None);
        z[0] = f64::NAN;
        // cell (0,0) now has three corners: the nearest one
        assert_eq!(sample(&xs, &ys, &z, 0.2, 0.9), Some(10.0));
        assert_eq!(sample(&xs, &ys, &z, 0.9, 0.1), Some(1.0));
    }

    #[test]
    fn colour_maps_run_from_end_to_end() {
        assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
        assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
        assert_eq!(viridis(2.0), viridis(1.0));
        assert_eq!(diverging(0.5), RGBColor(247, 247, 247));
        let ((lo, hi), _) = color_range(&[-1.0, 3.0, f64::NAN], ColorScale::Diverging);
        assert_eq!((lo, hi), (-3.0, 3.0));
        let ((lo, hi), d) = color_range(&[f64::NAN], ColorScale::Sequential);
        assert_eq!(((lo, hi), d), ((0.0, 1.0), None));
        let ((lo, hi), _) = color_range(&[5.0, 5.0], ColorScale::Sequential);
        assert!(lo < 5.0 && hi > 5.0);
    }

    fn face_map(nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> HeatMap {
        let e = Ellipse { x0: 0.0, x1: 32.0, half_height: 12.5 };
        let xs: Vec<f64> = (0..nx).map(|i| 32.0 * i as f64 / (nx - 1).max(1) as f64).collect();
        let ys: Vec<f64> = (0..ny).map(|j| -12.5 + 25.0 * j as f64 / (ny - 1).max(1) as f64).collect();
        let z = xs
            .iter()
            .flat_map(|&x| ys.iter().map(move |&y| (x, y)))
            .map(|(x, y)| if e.contains(x, y) { f(x, y) } else { f64::NAN })
            .collect();
        HeatMap {
            title: "test map".into(),
            subtitle: "a subtitle".into(),
            x_label: "x (cm)".into(),
            y_label: "r (cm)".into(),
            bar_label: "e_A".into(),
            xs,
            ys,
            z,
            clip: vec![e],
            outlines: vec![e],
            segments: vec![Segment { from: (16.0, -12.5), to: (16.0, 12.5), label: "node".into() }],
            markers: vec![Marker { at: (30.0, 0.0), label: "max".into() }],
            ..HeatMap::default()
        }
    }

    #[test]
    fn degenerate_maps_render_without_panic_and_deterministically() {
        let dir = tempfile::tempdir().unwrap();
        let cases = [
            face_map(25, 13, |x, y| 0.3 + 0.01 * x - 0.001 * y * y),
            face_map(25, 13, |_, _| f64::NAN),
            face_map(25, 13, |_, _| 0.4),
            face_map(2, 2, |x, _| x),
            face_map(1, 1, |x, _| x),
            HeatMap::default(),
        ];
        for (k, m) in cases.iter().enumerate() {
            let a = dir.path().join(format!("m{k}.png"));
            let b = dir.path().join(format!("m{k}b.png"));
            render_png("t", m, &a).unwrap_or_else(|e| panic!("case {k}: {e}"));
            render_png("t", m, &b).unwrap();
            let (a, b) = (std::fs::read(a).unwrap(), std::fs::read(b).unwrap());
            assert_eq!(&a[1..4], b"PNG");
            assert!(a == b, "case {k} not deterministic");
        }
        let mut diff = face_map(9, 7, |x, y| x - 16.0 + y);
        diff.scale = ColorScale::Diverging;
        render_png("t", &diff, &dir.path().join("d.png")).unwrap();
        if let Ok(keep) = std::env::var("RACKET_IMPACT_KEEP_TEST_PNG") {
            for f in ["m0.png", "m1.png", "m2.png", "m3.png", "d.png"] {
                let _ = std::fs::copy(dir.path().join(f), Path::new(&keep).join(format!("heatmap_{f}")));
            }
        }
    }

    #[test]
    fn bad_grids_are_errors() {
        let dir = tempfile::tempdir().unwrap();
        let mut m = face_map(5, 5, |x, _| x);
        m.z.pop();
        assert!(render_png("t", &m, &dir.path().join("a.png")).is_err());
        let mut m = face_map(5, 5, |x, _| x);
        m.xs[2] = m.xs[1];
        assert!(render_png("t", &m, &dir.path().join("a.png")).is_err());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }
}
