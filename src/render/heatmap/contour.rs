//! Contour levels at round values, marching squares, and sampling of the grid.

/// Contour lines aimed at (the actual count is 4 to 9, at round values).
pub const CONTOUR_TARGET: usize = 8;

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

/// The value at `(x, y)`: bilinear in a cell whose four corners are finite; in a cell with
/// some corners missing, the value of the nearest corner if that one has data (so a computed
/// point colours the half cell around it, and nothing beyond); `None` outside the grid or where
/// the nearest corner has no data.
pub fn sample(xs: &[f64], ys: &[f64], z: &[f64], x: f64, y: f64) -> Option<f64> {
    let row = Row::at(xs, ys, z, y)?;
    let mut cursor = 0;
    row.sample(x, &mut cursor)
}

/// One row of pixels at height `y`: the grid row and the fraction within it, found once, and
/// then the value at any `x` ([`sample`], pixel by pixel, without a search per pixel).
pub struct Row<'a> {
    xs: &'a [f64],
    z: &'a [f64],
    ny: usize,
    j: usize,
    u: f64,
}

impl<'a> Row<'a> {
    /// The row at `y`, or `None` outside the grid (or for a grid of fewer than 2 x 2 points).
    pub fn at(xs: &'a [f64], ys: &[f64], z: &'a [f64], y: f64) -> Option<Row<'a>> {
        let (nx, ny) = (xs.len(), ys.len());
        if nx < 2 || ny < 2 || z.len() != nx * ny || !(y >= ys[0] && y <= ys[ny - 1]) {
            return None;
        }
        let j = ys.partition_point(|&v| v <= y).clamp(1, ny - 1) - 1;
        let u = (y - ys[j]) / (ys[j + 1] - ys[j]);
        Some(Row { xs, z, ny, j, u })
    }

    /// The value at `x`; `cursor` carries the count of grid columns at or left of the last `x`
    /// asked (start it at 0; with `x` ascending from call to call the search is a step or two).
    pub fn sample(&self, x: f64, cursor: &mut usize) -> Option<f64> {
        let (xs, z, ny, j, u) = (self.xs, self.z, self.ny, self.j, self.u);
        let nx = xs.len();
        if !(x >= xs[0] && x <= xs[nx - 1]) {
            return None;
        }
        // the number of columns at or left of x, as `partition_point(|v| v <= x)` counts it
        if *cursor > nx || (*cursor > 0 && xs[*cursor - 1] > x) {
            *cursor = 0;
        }
        while *cursor < nx && xs[*cursor] <= x {
            *cursor += 1;
        }
        let i = (*cursor).clamp(1, nx - 1) - 1;
        let t = (x - xs[i]) / (xs[i + 1] - xs[i]);
        let c = [z[i * ny + j], z[(i + 1) * ny + j], z[(i + 1) * ny + j + 1], z[i * ny + j + 1]];
        if c.iter().all(|k| k.is_finite()) {
            let bottom = c[0] + t * (c[1] - c[0]);
            let top = c[3] + t * (c[2] - c[3]);
            return Some(bottom + u * (top - bottom));
        }
        let nearest = match (t < 0.5, u < 0.5) {
            (true, true) => c[0],
            (false, true) => c[1],
            (false, false) => c[2],
            (true, false) => c[3],
        };
        nearest.is_finite().then_some(nearest)
    }
}

/// `z` (on an `nx` x `ny` grid, row-major, x slowest) with `rings` rings of missing points next
/// to the data filled in: each pass gives every missing point with a neighbour (of the four
/// along the axes) that has data the mean of those neighbours. Points with data are unchanged.
pub fn fill_rim(nx: usize, ny: usize, z: &[f64], rings: usize) -> Vec<f64> {
    let mut out = z.to_vec();
    if z.len() != nx * ny {
        return out;
    }
    for _ in 0..rings {
        let prev = out.clone();
        for i in 0..nx {
            for j in 0..ny {
                if prev[i * ny + j].is_finite() {
                    continue;
                }
                let mut near = [(i.wrapping_sub(1), j), (i + 1, j), (i, j.wrapping_sub(1)), (i, j + 1)]
                    .into_iter()
                    .filter(|&(a, b)| a < nx && b < ny)
                    .map(|(a, b)| prev[a * ny + b])
                    .filter(|v| v.is_finite());
                if let Some(first) = near.next() {
                    let (sum, n) = near.fold((first, 1.0), |(s, n), v| (s + v, n + 1.0));
                    out[i * ny + j] = sum / n;
                }
            }
        }
    }
    out
}
