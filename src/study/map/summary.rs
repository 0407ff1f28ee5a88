//! The text summary the `map` command prints: the grid, the impact at the mode-1 node and the
//! maxima, or the spread of a difference.

use super::{DiffMap, FaceMap, Quantity, Spread};
use crate::error::Result;

/// The summary of one configuration's map of `q`, titled with `label`.
pub fn map_summary(m: &FaceMap, q: Quantity, label: &str) -> Result<String> {
    let mut s = format!(
        "map of {} on {}: {} x {} grid, {} impacts inside the face ({:.1} x {:.1} cm{}), {} solver\n",
        q.name(),
        label,
        m.grid.xs.len(),
        m.grid.rs.len(),
        m.len(),
        100.0 * m.face.length,
        200.0 * m.face.half_width,
        if m.face.from_racket { "" } else { ", default face" },
        m.params.numerics.solver.name()
    );
    let unit = if q.unit().is_empty() { String::new() } else { format!(" {}", q.unit()) };
    if let Some((x, r)) = m.at_node()? {
        s.push_str(&format!(
            "mode-1 node {:.2} cm from the tip: e_A {:.4}, {} {:.4}{unit} (on the axis)\n",
            100.0 * x,
            r.e_a,
            q.name(),
            q.of(&r)
        ));
    }
    if let Some(p) = m.max_point(Quantity::EA) {
        s.push_str(&format!(
            "max e_A {:.4} at x = {:.2} cm, r = {:.2} cm\n",
            p.value,
            100.0 * p.x_m,
            100.0 * p.r_m + 0.0
        ));
    }
    if let Some(p) = m.max_point(q) {
        s.push_str(&format!(
            "max {} {:.4}{unit} at x = {:.2} cm, r = {:.2} cm\n",
            q.name(),
            p.value,
            100.0 * p.x_m,
            100.0 * p.r_m + 0.0
        ));
    }
    Ok(s)
}

/// The summary of a difference map of `q` between A (`la`) and B (`lb`).
pub fn diff_summary(d: &DiffMap, q: Quantity, la: &str, lb: &str) -> String {
    let unit = if q.unit().is_empty() { String::new() } else { format!(" {}", q.unit()) };
    let mut s = format!(
        "difference map of {}: B - A, A = {la} (ks {:.0} N/m), B = {lb} (ks {:.0} N/m); {} x {} grid, {} points inside both faces, {} solver\n",
        q.name(),
        d.a.params.strings.ks,
        d.b.params.strings.ks,
        d.a.grid.xs.len(),
        d.a.grid.rs.len(),
        d.len(),
        d.a.params.numerics.solver.name()
    );
    if let Spread { min: Some(lo), max: Some(hi), .. } = d.spread(q) {
        s.push_str(&format!("B - A from {lo:.4} to {hi:.4}{unit}\n"));
    }
    s
}
