//! The axes of a chart: validated ranges (given, or from the data with padding) and which
//! curves go on the right axis.

use super::clip::Bounds;
use super::{Axis, Chart, Curve, PAD};

/// Validated ranges and per-curve axis assignment for one chart.
pub(super) struct Plan {
    pub(super) x_log: bool,
    pub(super) x: (f64, f64),
    pub(super) y: (f64, f64),
    /// Secondary axis range, when the chart has a right axis.
    pub(super) y2: Option<(f64, f64)>,
}

impl Plan {
    pub(super) fn new(chart: &Chart) -> std::result::Result<Plan, String> {
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
pub(super) fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// Pad a data range by [`PAD`] of its span on both sides (a zero span gets a nominal width).
pub(super) fn pad_linear((lo, hi): (f64, f64)) -> (f64, f64) {
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
pub(super) fn pad_log((lo, hi): (f64, f64)) -> (f64, f64) {
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
pub(super) fn check_range(what: &str, (lo, hi): (f64, f64), log: bool) -> std::result::Result<(f64, f64), String> {
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

impl Plan {
    /// How many usable points of `chart`'s curves lie outside the ranges they are drawn
    /// against (and so are cut off).
    pub(super) fn clipped(&self, chart: &Chart) -> usize {
        let left = Bounds::new(self.x, self.y, self.x_log);
        let right = Bounds::new(self.x, self.y2.unwrap_or(self.y), self.x_log);
        chart
            .curves
            .iter()
            .map(|c| {
                let b = if self.y2.is_some() && c.axis == Axis::Right { right } else { left };
                c.x.iter().zip(&c.y).filter(|(&x, &y)| b.usable(x, y) && !b.contains(x, y)).count()
            })
            .sum()
    }
}

/// How many points of `chart`'s curves (finite, and x > 0 on a log axis) fall outside the
/// ranges the chart is drawn with and are cut off; an error for a chart [`super::render_png`]
/// refuses.
pub fn clipped_points(chart: &Chart) -> std::result::Result<usize, String> {
    chart.panels().into_iter().map(|c| Ok(Plan::new(c)?.clipped(c))).sum()
}
