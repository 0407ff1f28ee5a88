//! Where the legend goes: the candidate spot in the plotting area (corners, then edge middles)
//! that covers the fewest curve pixels, and the pixel samples of the curves it must avoid.

use super::clip::Bounds;
pub use crate::render::place::Rect;

/// Gap between the legend box and the plotting area's edge, pixels.
const INSET: i32 = 12;
/// Clearance kept around the legend box when counting covered pixels, pixels.
const CLEARANCE: i32 = 4;
/// Step of the scan over heights, pixels.
pub const SCAN_STEP: i32 = 8;
/// Spacing of the samples taken along a curve, pixels.
const SAMPLE_STEP: f64 = 3.0;

/// The top-left corner of a `size` (width, height) legend box inside `area` that covers the
/// fewest `obstacles` (pixel positions of the drawn data), trying in order: upper right, upper
/// left, lower right, lower left, upper centre, lower centre, middle right, middle left,
/// centre, then every height (in `SCAN_STEP` steps) at the right, left and centre. The first
/// spot with the fewest covered obstacles wins, so with nothing in the way the legend sits
/// upper right.
pub fn place_legend(area: Rect, size: (i32, i32), obstacles: &[(i32, i32)]) -> (i32, i32) {
    let (l, t, r, b) = area;
    let (w, h) = size;
    let (xl, xc, xr) = (l + INSET, (l + r - w) / 2, r - INSET - w);
    let (yt, ym, yb) = (t + INSET, (t + b - h) / 2, b - INSET - h);
    let mut spots = vec![(xr, yt), (xl, yt), (xr, yb), (xl, yb), (xc, yt), (xc, yb), (xr, ym), (xl, ym), (xc, ym)];
    for x in [xr, xl, xc] {
        spots.extend((0..).map(|k| yt + k * SCAN_STEP).take_while(|&y| y <= yb).map(|y| (x, y)));
    }
    let covered = |(x, y): (i32, i32)| {
        let (x0, y0, x1, y1) = (x - CLEARANCE, y - CLEARANCE, x + w + CLEARANCE, y + h + CLEARANCE);
        obstacles.iter().filter(|&&(px, py)| px >= x0 && px <= x1 && py >= y0 && py <= y1).count()
    };
    crate::render::place::first_least(spots.iter().copied(), covered).map_or(spots[0], |(s, _)| s)
}

/// Maps data coordinates on one axis to pixels of the plotting area.
#[derive(Clone, Copy)]
pub(super) struct ToPixel {
    pub(super) bounds: Bounds,
    pub(super) area: Rect,
}

impl ToPixel {
    pub(super) fn px(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let (l, t, r, b) = self.area;
        let (fu, fv) = self.bounds.frac(x, y);
        (f64::from(l) + fu * f64::from(r - l), f64::from(b) - fv * f64::from(b - t))
    }

    /// Pixel samples every few pixels along a polyline (data coordinates).
    pub(super) fn sample_polyline(&self, pts: &[(f64, f64)], out: &mut Vec<(i32, i32)>) {
        for w in pts.windows(2) {
            let (a, b) = (self.px(w[0]), self.px(w[1]));
            let len = (b.0 - a.0).hypot(b.1 - a.1);
            let n = (len / SAMPLE_STEP).ceil().max(1.0) as usize;
            for k in 0..=n {
                let s = k as f64 / n as f64;
                out.push(((a.0 + s * (b.0 - a.0)).round() as i32, (a.1 + s * (b.1 - a.1)).round() as i32));
            }
        }
        if let [p] = pts {
            let q = self.px(*p);
            out.push((q.0.round() as i32, q.1.round() as i32));
        }
    }
}
