//! Small helpers the experiments use to turn their tables into chart curves.

use crate::render::plot::{Axis, Curve, LineStyle};
use crate::render::table::Table;

/// A solid curve on the left axis.
pub fn line(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>, color: usize) -> Curve {
    Curve { label: label.into(), x, y, axis: Axis::Left, style: LineStyle::Solid, color }
}

/// The same curve on the right axis.
pub fn on_right(mut c: Curve) -> Curve {
    c.axis = Axis::Right;
    c
}

/// The same curve in another style.
pub fn styled(mut c: Curve, style: LineStyle) -> Curve {
    c.style = style;
    c
}

/// A column of a table produced by this crate (the experiments name their own columns, so a
/// missing one is a programming error caught by the snapshot tests).
pub fn col(t: &Table, name: &str) -> Vec<f64> {
    t.column(name).unwrap_or_else(|| vec![f64::NAN; t.rows.len()])
}

/// Multiply every value by `k` (unit changes for plotting, e.g. s -> ms).
pub fn scaled(v: Vec<f64>, k: f64) -> Vec<f64> {
    v.into_iter().map(|x| x * k).collect()
}
