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
//! interpolant along the cell edges); a pixel in a cell with only some corners takes the value
//! of its nearest corner if that corner has data and stays white otherwise. A map clipped to
//! ellipses ([`HeatMap::clip`], a string face sampled inside its outline) first extends its
//! grid by two rings of points outside the data, each the mean of its neighbours with data
//! ([`fill_rim`]), so the shading reaches the outline smoothly instead of stopping in a
//! staircase of cells; every pixel so coloured is within about a grid step of a computed
//! point, and the contour lines use the data alone. Each contour line carries its value in a
//! small label. [`ColorScale::for_values`] picks the diverging scale only for data of both
//! signs.
//!
//! The image has the size, fonts and determinism of [`crate::render::plot`]: identical maps give
//! identical bytes, the file is written atomically, and no input (all NaN, a constant field, a
//! 2 x 2 grid, one point) panics.
//!
//! Files: [`colour`] (the colour maps and the colour range), [`contour`] (levels, marching
//! squares, sampling and the shading field), `draw` (layout and drawing with `plotters`).

pub mod colour;
pub mod contour;
mod draw;
#[cfg(test)]
mod tests;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

use plotters::prelude::*;

use crate::error::{Error, Result};
use crate::render::plot::{self, HEIGHT, WIDTH};
pub use colour::{color_range, diverging, viridis, ColorScale};
pub use contour::{contour_levels, contour_segments, fill_rim, sample, Row, Seg, CONTOUR_TARGET};

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
    /// The smallest value the quantity can meaningfully take (e.g. 0 for a power): the colour
    /// scale starts there, values below it are shaded [`BELOW_FLOOR`] grey, and no contour
    /// line is drawn below it (say what grey means in [`HeatMap::bar_label`]). `None`: the
    /// scale spans the data.
    pub floor: Option<f64>,
    /// A second field on the grid of `z` (empty: none): where it is below 0 the map is shaded
    /// [`BELOW_FLOOR`] grey whatever `z` is there, and those points' values are left out of
    /// the colour scale and the contour lines (say what grey means in [`HeatMap::bar_label`]).
    /// A face map of an oblique quantity greys the points where the ball does not rebound
    /// with the normal rebound velocity, as a power map greys them with its floor.
    pub grey_below_zero: Vec<f64>,
}

impl HeatMap {
    /// `z` with the points that [`HeatMap::grey_below_zero`] greys left out (NaN): the values
    /// the colour scale and the contour lines are drawn from.
    pub fn shown_values(&self) -> Vec<f64> {
        if self.grey_below_zero.len() != self.z.len() {
            return self.z.clone();
        }
        self.z.iter().zip(&self.grey_below_zero).map(|(&v, &g)| if g < 0.0 { f64::NAN } else { v }).collect()
    }
}

/// The grey of values below a map's [`HeatMap::floor`].
pub const BELOW_FLOOR: (u8, u8, u8) = (190, 190, 190);

/// Render `map` as a [`WIDTH`] x [`HEIGHT`] PNG at `path`, atomically (see
/// [`crate::render::plot::render_png`]); errors are [`Error::Plot`] with `id`.
pub fn render_png(id: &str, map: &HeatMap, path: &Path) -> Result<()> {
    let fail = |message: String| Error::Plot { id: id.to_string(), message };
    crate::render::io::write_with(path, ".png", |tmp| draw_file(map, tmp).map_err(fail)).map_err(|e| match e {
        Error::Plot { .. } => e,
        other => Error::Plot { id: id.to_string(), message: other.to_string() },
    })
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
        draw::draw(&root, map)?;
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
    if !map.grey_below_zero.is_empty() && map.grey_below_zero.len() != map.z.len() {
        return Err(format!("{} values but {} of the grey mask", map.z.len(), map.grey_below_zero.len()));
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
