//! How well the discrete model reproduces a spec: each stated number beside the model's, as a
//! table and as text.

use std::fmt;

use super::convert::{Resolved, Stiffness};
use super::spec::{RacketSpec, SWING_AXIS_FROM_BUTT_M};
use crate::model::beam::Beam;
use crate::numfmt::fmt_sig;
use crate::params::Racket;
use crate::render::table::{Table, Value};

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
    /// Lowest linear density: (cm from the tip, g/cm).
    pub density_min_g_per_cm: (f64, f64),
    /// Highest linear density: (cm from the tip, g/cm).
    pub density_max_g_per_cm: (f64, f64),
    /// Mean linear density M / L, g/cm.
    pub mean_density_g_per_cm: f64,
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
        for (n, (x, d)) in [("min", self.density_min_g_per_cm), ("max", self.density_max_g_per_cm)] {
            let row = vec![
                format!("density_{n} (x = {} cm)", fmt_sig(x, 4)).into(),
                "g/cm".into(),
                opt(None),
                d.into(),
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
        let ((min_at, min), (max_at, max), scale) = density_extremes(racket);
        let density_g_per_cm = |f: f64| racket.profile.as_ref().map_or(1.0, |p| p.density_at(f)) * scale;
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
            density_g_per_cm: knots.map(density_g_per_cm),
            density_min_g_per_cm: (min_at, min),
            density_max_g_per_cm: (max_at, max),
            mean_density_g_per_cm: racket.mass / racket.length * 10.0,
        }
    }
}

/// The lowest and highest linear density of a racket, each as (cm from the tip, g/cm), sampled
/// on 2001 points, and the factor that turns its profile's relative density into g/cm (its
/// integral by Simpson's rule on the same points). A uniform racket has both at its tip.
pub fn density_extremes(racket: &Racket) -> ((f64, f64), (f64, f64), f64) {
    const SAMPLES: usize = 2000;
    let mean = racket.mass / racket.length * 10.0;
    let Some(p) = &racket.profile else {
        return ((0.0, mean), (0.0, mean), mean);
    };
    let values: Vec<f64> = (0..=SAMPLES).map(|i| p.density_at(i as f64 / SAMPLES as f64)).collect();
    let simpson = |i: usize| {
        if i == 0 || i == SAMPLES {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        }
    };
    let integral: f64 = values.iter().enumerate().map(|(i, v)| v * simpson(i)).sum::<f64>() / (3.0 * SAMPLES as f64);
    let scale = mean / integral;
    let (lo, hi) = (0..=SAMPLES).fold((0, 0), |(lo, hi), i| {
        (if values[i] < values[lo] { i } else { lo }, if values[i] > values[hi] { i } else { hi })
    });
    let at_cm = |i: usize| i as f64 / SAMPLES as f64 * racket.length * 100.0;
    ((at_cm(lo), values[lo] * scale), (at_cm(hi), values[hi] * scale), scale)
}

/// A one-line warning when a racket's linear density leaves
/// [`PLAUSIBLE_DENSITY`](super::spec::PLAUSIBLE_DENSITY) times its mean somewhere (the fit
/// still runs).
pub fn density_warning(racket: &Racket) -> Option<String> {
    let ((min_at, min), (max_at, max), _) = density_extremes(racket);
    let mean = racket.mass / racket.length * 10.0;
    let (lo, hi) = super::spec::PLAUSIBLE_DENSITY;
    let say = |what: &str, at: f64, d: f64, bound: &str| {
        format!(
            "racket density {what} {} g/cm at {} cm from the tip, {bound} the usual {lo}..{hi} times the mean {} g/cm of a frame (fitted anyway; check balance and swingweight)",
            fmt_sig(d, 3),
            fmt_sig(at, 3),
            fmt_sig(mean, 3)
        )
    };
    if min < lo * mean {
        Some(say("falls to", min_at, min, "below"))
    } else if max > hi * mean {
        Some(say("reaches", max_at, max, "above"))
    } else {
        None
    }
}
