//! How well the discrete model reproduces a spec: each stated number beside the model's, as a
//! table and as text.

use std::fmt;

use super::convert::{Resolved, Stiffness};
use super::spec::{RacketSpec, SWING_AXIS_FROM_BUTT_M};
use crate::model::beam::Beam;
use crate::params::Racket;
use crate::render::table::{fmt_sig, Table, Value};

/// One fitted quantity: the target in player units (absent when the spec did not state it)
/// and the value on the discrete model, same unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// The stated value.
    pub target: Option<f64>,
    /// The discrete model's value.
    pub model: f64,
}

impl Check {
    /// `(model - target) / |target|`, when there is a target.
    pub fn rel_error(&self) -> Option<f64> {
        self.target.map(|t| (self.model - t) / t.abs())
    }
}

/// How well the discrete model reproduces the spec.
#[derive(Debug, Clone, PartialEq)]
pub struct FitReport {
    /// The spec's name, if any.
    pub name: Option<String>,
    /// Segments `N` of the beam the fit is exact for.
    pub segments: usize,
    /// Strung mass, g.
    pub mass_g: Check,
    /// Balance point from the butt, cm.
    pub balance_cm: Check,
    /// Moment of inertia about the axis 10 cm from the butt, kg cm^2.
    pub swingweight_kg_cm2: Check,
    /// Moment of inertia about the long axis, kg cm^2.
    pub twistweight_kg_cm2: Check,
    /// First free-free bending frequency, Hz.
    pub frequency_hz: Check,
    /// Fitted (or given) `ei`, N m^2 (the scale of `EI(x) = ei * stiffness_ratio(x/L)`).
    pub ei_n_m2: Check,
    /// Knots from the tip, cm: tip, head end, handle start, butt.
    pub knots_cm: [f64; 4],
    /// Linear density at the knots, g/cm.
    pub density_g_per_cm: [f64; 4],
}

impl FitReport {
    /// The report as a table with columns quantity, unit, target, model, rel_error (an absent
    /// target or error is an empty cell).
    pub fn table(&self) -> Table {
        let mut t = Table::new("racket_fit", &["quantity", "unit", "target", "model", "rel_error"]);
        let opt = |v: Option<f64>| v.map_or(Value::Text(String::new()), Value::Num);
        for (q, unit, c) in self.checks() {
            // every row has the five columns, so push cannot fail
            let _ = t.push(vec![q.into(), unit.into(), opt(c.target), c.model.into(), opt(c.rel_error())]);
        }
        let names = ["tip", "head_end", "handle_start", "butt"];
        for (i, n) in names.iter().enumerate() {
            let row = vec![
                format!("density_{n} (x = {} cm)", fmt_sig(self.knots_cm[i], 4)).into(),
                "g/cm".into(),
                opt(None),
                self.density_g_per_cm[i].into(),
                opt(None),
            ];
            let _ = t.push(row);
        }
        t
    }

    fn checks(&self) -> [(&'static str, &'static str, Check); 6] {
        [
            ("mass", "g", self.mass_g),
            ("balance", "cm from butt", self.balance_cm),
            ("swingweight", "kg cm^2", self.swingweight_kg_cm2),
            ("twistweight", "kg cm^2", self.twistweight_kg_cm2),
            ("f1", "Hz", self.frequency_hz),
            ("ei", "N m^2", self.ei_n_m2),
        ]
    }
}

impl fmt::Display for FitReport {
    /// A human-readable table of the fit, one quantity per line.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = self.name.as_deref().unwrap_or("racket");
        writeln!(f, "{name}: fitted on N = {} segments", self.segments)?;
        let t = self.table();
        writeln!(f, "{:<38} {:<13} {:>12} {:>12} {:>10}", "quantity", "unit", "target", "model", "rel_error")?;
        for row in &t.rows {
            let cell = |v: &Value| match v {
                Value::Num(x) => fmt_sig(*x, 6),
                other => other.to_csv_field(),
            };
            let err = match &row[4] {
                Value::Num(e) => format!("{e:.1e}"),
                other => other.to_csv_field(),
            };
            writeln!(
                f,
                "{:<38} {:<13} {:>12} {:>12} {:>10}",
                cell(&row[0]),
                cell(&row[1]),
                cell(&row[2]),
                cell(&row[3]),
                err
            )?;
        }
        Ok(())
    }
}

impl RacketSpec {
    /// The report of the fit of `racket` (on `segments` segments) to this spec.
    pub(super) fn report(&self, r: &Resolved, racket: &Racket, segments: usize) -> FitReport {
        let beam = Beam::new(racket, segments);
        let f1 = beam.modes().frequency_hz(1);
        let x_axis = racket.length - SWING_AXIS_FROM_BUTT_M;
        let sw: f64 = beam.mass.iter().zip(&beam.x).map(|(m, x)| m * (x_axis - x).powi(2)).sum();
        let knots = r.knots;
        // physical density: the relative profile scaled to the mass (its integral is exact)
        let density_g_per_cm = match &racket.profile {
            None => [racket.mass / racket.length * 10.0; 4],
            Some(p) => {
                let integral: f64 =
                    (0..3).map(|j| 0.5 * (knots[j + 1] - knots[j]) * (p.density[j] + p.density[j + 1])).sum();
                p.density.map(|d| d * racket.mass / (racket.length * integral) * 10.0)
            }
        };
        FitReport {
            name: self.name.clone(),
            segments,
            mass_g: Check { target: Some(r.mass * 1000.0), model: beam.total_mass * 1000.0 },
            balance_cm: Check { target: r.shape.map(|s| s.balance_cm), model: (racket.length - beam.x_cm) * 100.0 },
            swingweight_kg_cm2: Check { target: r.shape.map(|s| s.swingweight * 1.0e4), model: sw * 1.0e4 },
            twistweight_kg_cm2: Check { target: Some(r.ix * 1.0e4), model: racket.ix * 1.0e4 },
            frequency_hz: Check {
                target: match r.stiffness {
                    Stiffness::Frequency(f) => Some(f),
                    Stiffness::Ei(_) => None,
                },
                model: f1,
            },
            ei_n_m2: Check {
                target: match r.stiffness {
                    Stiffness::Ei(ei) => Some(ei),
                    Stiffness::Frequency(_) => None,
                },
                model: racket.ei,
            },
            knots_cm: knots.map(|k| k * racket.length * 100.0),
            density_g_per_cm,
        }
    }
}
