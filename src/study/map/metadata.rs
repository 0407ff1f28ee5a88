//! The JSON metadata written next to a map: the quantity, the grid, every configuration's
//! parameters, face, mode-1 nodes, extremes and the impact at the node.

use serde::Serialize;

use super::{DiffMap, FaceMap, Grid, MapPoint, Quantity};
use crate::error::Result;

/// What the metadata's parameters mean for the impact point.
const IMPACT_NOTE: &str =
    "params.impact.x and params.impact.r are the face centre; each grid point moves the impact there";

/// The grid for the metadata: the requested counts and the coordinates.
fn grid_metadata(g: &Grid, nx: usize, nr: usize) -> serde_json::Value {
    serde_json::json!({ "nx": nx, "nr": nr, "x_m": g.xs, "r_m": g.rs })
}

impl FaceMap {
    /// The JSON metadata of a map of `q` requested on an `nx x nr` grid: the quantity, the grid
    /// and the configuration ([`config_metadata`]).
    pub fn metadata(&self, label: &str, q: Quantity, (nx, nr): (usize, usize)) -> Result<serde_json::Value> {
        let mut v = serde_json::json!({
            "quantity": q.name(), "column": q.column(), "unit": q.unit(),
            "note": IMPACT_NOTE,
            "grid": grid_metadata(&self.grid, nx, nr),
            "points": self.len(),
            "a": config_metadata(label, self, q)?,
        });
        name_spin_convention(&mut v, &self.params);
        Ok(v)
    }
}

impl DiffMap {
    /// The JSON metadata of a difference map (as [`FaceMap::metadata`], both configurations and
    /// the spread of `B - A`).
    pub fn metadata(&self, labels: (&str, &str), q: Quantity, (nx, nr): (usize, usize)) -> Result<serde_json::Value> {
        let spread = self.spread(q);
        let mut v = serde_json::json!({
            "quantity": q.name(), "column": q.column(), "unit": q.unit(),
            "note": IMPACT_NOTE,
            "difference": "b - a",
            "grid": grid_metadata(&self.a.grid, nx, nr),
            "points": self.len(),
            "a": config_metadata(labels.0, &self.a, q)?,
            "b": config_metadata(labels.1, &self.b, q)?,
            "b_minus_a": { "min": spread.min, "max": spread.max, "mean": spread.mean },
        });
        name_spin_convention(&mut v, &self.a.params);
        Ok(v)
    }
}

/// A configuration's description for the metadata: its label, parameters, face, nodes, the
/// maximum of e_A and of the quantity, and the impact at the node.
pub fn config_metadata(label: &str, m: &FaceMap, q: Quantity) -> Result<serde_json::Value> {
    let at_node = m.at_node()?;
    Ok(serde_json::json!({
        "label": label,
        "solver": m.params.numerics.solver.name(),
        "params": json(&m.params),
        "face": json(&m.face),
        "mode1_nodes_m": m.mode1_nodes,
        "node_x_m": m.node_x(),
        "max_e_a": json(&m.max_point(Quantity::EA)),
        "max_quantity": json(&m.max_point(q)),
        "min_quantity": json(&m.points().fold(None, |best: Option<MapPoint>, (x, r, res)| {
            let v = q.of(res);
            match best {
                Some(b) if b.value <= v => Some(b),
                _ => Some(MapPoint { x_m: x, r_m: r, value: v }),
            }
        })),
        "at_node": at_node.map(|(x, res)| serde_json::json!({
            "x_m": x, "r_m": 0.0, "value": q.of(&res), "result": json(&res),
        })),
        "points": m.len(),
    }))
}

/// `serde_json::to_value` for our plain types (numbers, strings, options), which cannot fail.
fn json<T: Serialize>(v: &T) -> serde_json::Value {
    serde_json::to_value(v).unwrap_or(serde_json::Value::Null)
}

/// An oblique or spinning map's metadata says which way its spins count (the sign convention of
/// `--spin-rpm` and `spin_out_rpm`); a normal-incidence map has no spin to explain.
fn name_spin_convention(v: &mut serde_json::Value, p: &crate::params::Params) {
    if let (false, Some(o)) = (p.oblique.is_normal(), v.as_object_mut()) {
        o.insert("spin_convention".into(), crate::render::impact::SIMULATE_SPIN_CONVENTION.into());
    }
}
