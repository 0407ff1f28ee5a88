//! A map as a table and a heat map: its CSV rows and the figure with the face outline, the
//! mode-1 node and the point of maximum e_A.

use super::{DiffMap, Face, FaceMap, Grid, MapPoint, Quantity};
use crate::params::Params;
use crate::render::heatmap::{ColorScale, Ellipse, HeatMap, Marker, Segment};
use crate::render::table::{Table, Value};

impl Face {
    /// The outline in cm, for the heat map.
    fn ellipse_cm(&self) -> Ellipse {
        Ellipse { x0: 0.0, x1: 100.0 * self.length, half_height: 100.0 * self.half_width }
    }
}

impl FaceMap {
    /// The table: x_m, r_m, the fixed ks and v1 (and an oblique ball's angle, azimuth, spin and
    /// friction), every
    /// quantity's column, recontact (0/1); one row per evaluated
    /// point, row-major (x slowest).
    pub fn table(&self) -> Table {
        let p = &self.params;
        let oblique = !p.oblique.is_normal();
        // every row names its whole impact: the point, and what the map holds fixed
        let mut cols = vec!["x_m", "r_m", "ks_n_per_m", "v1_m_per_s"];
        let fixed = crate::render::impact::recorded_oblique(p);
        cols.extend(fixed.iter().map(|(c, _)| *c));
        cols.extend(Quantity::in_table(oblique).map(|q| q.column()));
        cols.push("recontact");
        let mut t = Table::new("map", &cols);
        for (x, r, res) in self.points() {
            let mut row: Vec<Value> = vec![x.into(), r.into(), p.strings.ks.into(), p.impact.v1.into()];
            row.extend(fixed.iter().map(|(_, v)| Value::from(*v)));
            row.extend(Quantity::in_table(oblique).map(|q| Value::Num(q.column_value(res))));
            row.push(Value::Int(i64::from(res.recontact)));
            // the row has one value per column, so push cannot fail
            let _ = t.push(row);
        }
        t
    }

    /// The heat map of `q`, titled with `label` (the racket's name).
    pub fn heatmap(&self, q: Quantity, label: &str) -> HeatMap {
        let face = self.face.ellipse_cm();
        let mut segments = Vec::new();
        for x in self.nodes_in_face() {
            let w = 100.0 * self.face.half_width_at(x);
            segments.push(Segment {
                from: (100.0 * x, -w),
                to: (100.0 * x, w),
                label: format!("mode-1 node, {:.1} cm", 100.0 * x),
            });
        }
        let markers = self
            .max_point(Quantity::EA)
            .map(|m| Marker { at: (100.0 * m.x_m, 100.0 * m.r_m), label: max_label(&m) })
            .into_iter()
            .collect();
        HeatMap {
            title: format!("{}: {}", config_title(label, &self.params), quantity_title(q)),
            subtitle: subtitle(&self.params, &[self.face], &self.grid, self.len()),
            x_label: "x: distance from the tip (cm)".into(),
            y_label: "r: distance from the long axis (cm)".into(),
            bar_label: match q.floor().map(|(_, note)| note).or(q.no_rebound_note()) {
                Some(note) => format!("{}; {note}", bar_label(q, false)),
                None => bar_label(q, false),
            },
            xs: self.grid.xs.iter().map(|x| 100.0 * x).collect(),
            ys: self.grid.rs.iter().map(|r| 100.0 * r).collect(),
            z: self.values(q),
            scale: ColorScale::Sequential,
            clip: vec![face],
            outlines: vec![face],
            segments,
            markers,
            floor: q.floor().map(|(f, _)| f),
            grey_below_zero: if q.no_rebound_note().is_some() { self.normal_rebound() } else { Vec::new() },
        }
    }
}

/// "max e_A 0.4213 at (31.7, 0) cm".
fn max_label(m: &MapPoint) -> String {
    format!("max e_A {:.4} at ({:.1}, {:.1}) cm", m.value, 100.0 * m.x_m, 100.0 * m.r_m + 0.0)
}

/// "tweener, ks 36667 N/m", and for an oblique or spinning ball what it was run at.
fn config_title(label: &str, p: &Params) -> String {
    format!("{label}, ks {:.0} N/m{}", p.strings.ks, oblique_text(p))
}

/// ", angle 30 deg, azimuth 0 deg, spin 1000 rpm, mu 0.4" for an oblique or spinning ball
/// (spin > 0: topspin relative to the ball's incoming motion along the strings), else "".
fn oblique_text(p: &Params) -> String {
    if p.oblique.is_normal() {
        return String::new();
    }
    let o = &p.oblique;
    // a tangential law other than the default one is named (it changes every value)
    let law = if o.tangential == crate::params::TangentialLaw::default() {
        String::new()
    } else {
        format!(", tangential {}", o.tangential.name())
    };
    format!(", angle {} deg, azimuth {} deg, spin {} rpm, mu {}{law}", o.angle_deg, o.azimuth_deg, o.spin_rpm, o.mu)
}

/// "power potential 100 e_A (%)".
fn quantity_title(q: Quantity) -> String {
    match q.unit() {
        "" => q.description().to_string(),
        u => format!("{} ({u})", q.description()),
    }
}

fn bar_label(q: Quantity, difference: bool) -> String {
    let unit = match (q.unit(), difference) {
        ("%", true) => "% points",
        (u, _) => u,
    };
    let sym = if difference { format!("B - A: {}", q.symbol()) } else { q.symbol().to_string() };
    if unit.is_empty() {
        sym
    } else {
        format!("{sym} ({unit})")
    }
}

/// The shared numerics and the grid, one line.
fn subtitle(p: &Params, faces: &[Face], grid: &Grid, evaluated: usize) -> String {
    let face = match faces.first() {
        Some(f) if faces.len() == 1 => format!(
            "{} {:.1} x {:.1} cm",
            if f.from_racket { "head" } else { "default face" },
            100.0 * f.length,
            200.0 * f.half_width
        ),
        _ => "inside both faces".to_string(),
    };
    format!(
        "v1 {:.3} m/s, {} load, N = {}, {} solver; {} x {} grid, {} impacts; {}",
        p.impact.v1,
        p.numerics.load.name(),
        p.numerics.segments,
        p.numerics.solver.name(),
        grid.xs.len(),
        grid.rs.len(),
        evaluated,
        face
    )
}

impl DiffMap {
    /// The table: x_m, r_m, ks of A and B, v1, `<q>_a`, `<q>_b`, `<q>_b_minus_a`, recontact_a, recontact_b; one row
    /// per point inside both faces, row-major.
    pub fn table(&self, q: Quantity) -> Table {
        let c = q.column();
        let (ca, cb, cd) = (format!("{c}_a"), format!("{c}_b"), format!("{c}_b_minus_a"));
        let (pa, pb) = (&self.a.params, &self.b.params);
        // an oblique comparison records its incidence (the same for A and B)
        let fixed = crate::render::impact::recorded_oblique(pa);
        let mut cols = vec!["x_m", "r_m", "ks_a_n_per_m", "ks_b_n_per_m", "v1_m_per_s"];
        cols.extend(fixed.iter().map(|(c, _)| *c));
        cols.extend([ca.as_str(), cb.as_str(), cd.as_str(), "recontact_a", "recontact_b"]);
        let mut t = Table::new("map_diff", &cols);
        for (k, (ra, rb)) in self.a.results.iter().zip(&self.b.results).enumerate() {
            if let (Some(ra), Some(rb)) = (ra, rb) {
                let (x, r) = self.a.grid.point(k);
                let (va, vb) = (q.column_value(ra), q.column_value(rb));
                let mut row: Vec<Value> =
                    vec![x.into(), r.into(), pa.strings.ks.into(), pb.strings.ks.into(), pa.impact.v1.into()];
                row.extend(fixed.iter().map(|(_, v)| Value::from(*v)));
                row.extend([
                    va.into(),
                    vb.into(),
                    (vb - va).into(),
                    Value::Int(i64::from(ra.recontact)),
                    Value::Int(i64::from(rb.recontact)),
                ]);
                let _ = t.push(row);
            }
        }
        t
    }

    /// The heat map of B - A.
    pub fn heatmap(&self, q: Quantity, label_a: &str, label_b: &str) -> HeatMap {
        let (fa, fb) = (self.a.face.ellipse_cm(), self.b.face.ellipse_cm());
        let outlines = if fa == fb { vec![fa] } else { vec![fa, fb] };
        let mut segments = Vec::new();
        let same_nodes = self.a.nodes_in_face() == self.b.nodes_in_face();
        for (m, tag) in [(&self.a, "A"), (&self.b, "B")] {
            if tag == "B" && same_nodes {
                continue;
            }
            for x in m.nodes_in_face() {
                let w = 100.0 * m.face.half_width_at(x);
                let who = if same_nodes { String::new() } else { format!(" ({tag})") };
                segments.push(Segment {
                    from: (100.0 * x, -w),
                    to: (100.0 * x, w),
                    label: format!("mode-1 node{who}, {:.1} cm", 100.0 * x),
                });
            }
        }
        let (pa, pb) = (self.a.max_point(Quantity::EA), self.b.max_point(Quantity::EA));
        let mut markers = Vec::new();
        match (pa, pb) {
            (Some(a), Some(b)) if (a.x_m, a.r_m) == (b.x_m, b.r_m) => markers.push(Marker {
                at: (100.0 * a.x_m, 100.0 * a.r_m),
                label: format!("max e_A of A and B at ({:.1}, {:.1}) cm", 100.0 * a.x_m, 100.0 * a.r_m + 0.0),
            }),
            _ => {
                for (p, tag) in [(pa, "A"), (pb, "B")] {
                    if let Some(m) = p {
                        markers.push(Marker {
                            at: (100.0 * m.x_m, 100.0 * m.r_m),
                            label: format!("max e_A of {tag}: {:.4}", m.value),
                        });
                    }
                }
            }
        }
        let z = self.values(q);
        HeatMap {
            title: format!(
                "B - A: {} (A: {}; B: {}){}",
                q.description(),
                label_a,
                label_b,
                oblique_text(&self.a.params)
            ),
            subtitle: format!(
                "ks A {:.0}, B {:.0} N/m; {}",
                self.a.params.strings.ks,
                self.b.params.strings.ks,
                subtitle(&self.a.params, &[self.a.face, self.b.face], &self.a.grid, self.len())
            ),
            x_label: "x: distance from the tip (cm)".into(),
            y_label: "r: distance from the long axis (cm)".into(),
            bar_label: match q.no_rebound_note() {
                Some(_) => format!("{}; grey: no rebound off A or B", bar_label(q, true)),
                None => bar_label(q, true),
            },
            xs: self.a.grid.xs.iter().map(|x| 100.0 * x).collect(),
            ys: self.a.grid.rs.iter().map(|r| 100.0 * r).collect(),
            scale: ColorScale::for_values(&z),
            z,
            clip: outlines.clone(),
            outlines,
            segments,
            markers,
            floor: None,
            grey_below_zero: if q.no_rebound_note().is_some() { self.normal_rebound() } else { Vec::new() },
        }
    }
}
