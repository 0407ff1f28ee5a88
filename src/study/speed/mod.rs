//! Outgoing ball speeds for a swing and an incoming ball (the `speed` command): one impact per
//! variant (string tensions or rackets), compared with the first.
//!
//! `v_out = e_A v_in + (1 + e_A) v_racket` (the paper's frame transformation), with `e_A`
//! computed at the relative speed `v_in + v_racket` and the racket's swing speed taken at the
//! impact point.
//!
//! Here the request and its run; the comparison's diagnostics in `diagnose.rs`, its table,
//! JSON and text in `write.rs`.

mod diagnose;
mod write;

pub use write::SPEED_SPIN_CONVENTION;

use crate::diagnostic::Diagnostic;
use crate::error::{Error, Result};
use crate::intake::compare::check_comparison;
use crate::intake::Sources;
use crate::params::keys;
use crate::params::spec::ParamSpec;
use crate::params::{ks_from_tension_lb, Params};
use crate::solve::swing::{outgoing_speed, Swing};
use crate::solve::ImpactResult;

/// A unit of speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedUnit {
    /// Metres per second per unit.
    pub si: f64,
    /// Its symbol.
    pub label: &'static str,
}

impl SpeedUnit {
    /// Kilometres per hour.
    pub const KMH: SpeedUnit = SpeedUnit { si: 1.0 / 3.6, label: "km/h" };
    /// Miles per hour.
    pub const MPH: SpeedUnit = SpeedUnit { si: 0.44704, label: "mph" };
    /// Metres per second.
    pub const MS: SpeedUnit = SpeedUnit { si: 1.0, label: "m/s" };
}

/// The parameters `speed` sets itself, each with where it comes from: the ball speed (from the
/// swing and the incoming ball), the incidence (from the swing path) and the spin (from the
/// incoming ball's).
pub const SPEED_SETS: [(ParamSpec, &str); 4] = [
    (keys::V1, "the ball speed comes from --swing and --incoming"),
    (keys::ANGLE_DEG, "the incidence comes from --swing-path-deg"),
    (keys::AZIMUTH_DEG, "the incidence comes from --swing-path-deg"),
    (keys::SPIN_RPM, "the ball's spin comes from --incoming-spin-rpm (court frame)"),
];

/// Where `speed` takes the parameter `key` from, if it sets it itself ([`SPEED_SETS`]).
pub fn set_by_speed(key: &str) -> Option<&'static str> {
    SPEED_SETS.iter().find(|(s, _)| s.key == key).map(|(_, why)| *why)
}

/// A swing, an incoming ball and the variants to compare.
#[derive(Debug, Clone)]
pub struct SpeedRequest {
    /// The configuration: racket, config file and flags.
    pub sources: Sources,
    /// Racket speed at the impact point, towards the ball, in `unit`.
    pub swing: f64,
    /// Incoming ball speed, towards the racket, in `unit` (0 for a serve).
    pub incoming: f64,
    /// The unit of the speeds.
    pub unit: SpeedUnit,
    /// Compare string tensions, lb: T (the configuration as given against it at T) or
    /// T1,T2,... (at T1, the reference, against each of the others).
    pub compare_tension_lb: Vec<f64>,
    /// Compare these rackets (files or presets) against the configuration's (the reference).
    pub compare_racket: Vec<String>,
    /// Swing path angle above the horizontal, degrees (0: the paper's straight-on swing).
    pub path_deg: f64,
    /// Spin of the incoming ball in its own flight, rpm (topspin > 0).
    pub incoming_spin_rpm: f64,
}

/// One variant's impact and outgoing ball speed.
#[derive(Debug, Clone)]
pub struct SpeedRow {
    /// The variant's name.
    pub label: String,
    /// Its parameters (the impact at the relative speed).
    pub params: Params,
    /// The impact.
    pub result: ImpactResult,
    /// Outgoing ball speed, m/s.
    pub v_out: f64,
    /// For a swing along a tilted path or a spinning ball: launch angle above the horizontal
    /// (degrees) and spin (rpm, topspin > 0) in the court's frame.
    pub launch: Option<(f64, f64)>,
}

impl SpeedRow {
    /// A head-on stroke on `base` (its impact point): a ball arriving at `v_in` on a racket
    /// swung at `v_racket` (m/s, at the impact point), with `e_A` computed at the relative speed
    /// `v_in + v_racket` (it does not depend on it; theta scales with it) and carried to the
    /// court by [`outgoing_speed`]. The `speed` command's head-on row, and the `card`'s strokes.
    pub fn head_on(label: String, base: &Params, v_in: f64, v_racket: f64) -> Result<SpeedRow> {
        let mut p = *base;
        p.impact.v1 = v_in + v_racket;
        p.validate()?;
        let r = crate::simulate(&p)?;
        let v_out = outgoing_speed(r.e_a, v_in, v_racket);
        Ok(SpeedRow { label, params: p, result: r, v_out, launch: None })
    }
}

/// The compared variants, the first being the reference.
#[derive(Debug, Clone)]
pub struct SpeedComparison {
    /// What was asked.
    pub request: SpeedRequest,
    /// One row per variant.
    pub rows: Vec<SpeedRow>,
    /// The notes about flags of properties no variant exercises and config-file keys the
    /// command does not use ([`crate::intake::Sources::check_used`]).
    pub noted: Vec<Diagnostic>,
}

impl SpeedRequest {
    /// Check the speeds and the comparison, then run one impact per variant.
    pub fn run(&self) -> Result<SpeedComparison> {
        for (field, v) in [("swing", self.swing), ("incoming", self.incoming)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::invalid(
                    field,
                    v,
                    format!("speed must be a finite number >= 0 {}", self.unit.label),
                ));
            }
        }
        let (v_racket, v_in) = (self.swing * self.unit.si, self.incoming * self.unit.si);
        // the impact runs at the relative speed: its range, said in this command's unit
        let (lo, hi) = crate::params::keys::V1.range();
        if !(lo..=hi).contains(&(v_racket + v_in)) {
            let u = self.unit;
            let field = if self.swing >= self.incoming { "swing" } else { "incoming" };
            let value = if field == "swing" { self.swing } else { self.incoming };
            return Err(Error::invalid(
                field,
                value,
                format!(
                    "swing + incoming (the impact speed) must satisfy {} <= swing + incoming <= {} {}",
                    crate::numfmt::sig(lo / u.si, 3),
                    crate::numfmt::sig(hi / u.si, 3),
                    u.label
                ),
            ));
        }
        check_comparison(&self.compare_tension_lb, !self.compare_racket.is_empty(), &self.sources.flags)?;
        for (field, n) in
            [("compare-tension-lb", self.compare_tension_lb.len()), ("compare-racket", self.compare_racket.len())]
        {
            let most = crate::params::limits::MAX_COMPARED;
            crate::params::limits::check_count(field, n as f64, most as u64, "the number of compared variants")?;
        }
        // each racket compared once, and never with itself (the same name, or the same file)
        for (i, r) in self.compare_racket.iter().enumerate() {
            let earlier = self.sources.racket.iter().chain(&self.compare_racket[..i]).any(|e| e == r);
            if earlier {
                return Err(Error::invalid(
                    "compare-racket",
                    r,
                    format!(
                        "{r} is given twice (item {}): a racket compared with itself differs nowhere; give each once",
                        i + 1
                    ),
                ));
            }
        }
        self.check_unused()?;
        let mut rows = Vec::new();
        for (label, racket, tension) in self.variants() {
            let (mut p, _) = self.sources.resolve(racket.as_deref())?;
            if let Some(t) = tension {
                p.strings.ks = ks_from_tension_lb(t);
            }
            if self.is_stroke() {
                let swing = Swing {
                    racket_speed: v_racket,
                    path_deg: self.path_deg,
                    incoming: v_in,
                    incoming_spin_rpm: self.incoming_spin_rpm,
                };
                let exit = swing.hit(&p)?;
                let launch = Some((exit.launch_deg, exit.spin_rpm));
                rows.push(SpeedRow { label, params: exit.params, result: exit.impact, v_out: exit.speed, launch });
                continue;
            }
            rows.push(SpeedRow::head_on(label, &p, v_in, v_racket)?);
        }
        // a flag no variant can honour refused, one none exercises noted
        let noted = self.sources.check_used(&rows.iter().map(|r| r.params).collect::<Vec<_>>())?;
        Ok(SpeedComparison { request: self.clone(), rows, noted })
    }

    /// Whether the swing brushes the ball (a tilted path) or the ball spins: the impact is then
    /// oblique ([`Swing`]), and the exit has a launch angle and spin.
    pub fn is_stroke(&self) -> bool {
        self.path_deg != 0.0 || self.incoming_spin_rpm != 0.0
    }

    /// The variants: (label, racket argument, tension). A is the configuration as given (the
    /// `--racket`, else the paper's) and every comparison is against it, as in `map`: each
    /// `--compare-racket`, or one tension T (A as given against A at T), or several tensions
    /// (A at the first against A at each of the others).
    fn variants(&self) -> Vec<(String, Option<String>, Option<f64>)> {
        let racket = &self.sources.racket;
        let name = crate::intake::compare::racket_label(racket.as_deref());
        let at = |t: f64| (format!("{name} at {t} lb"), racket.clone(), Some(t));
        let mut variants = Vec::new();
        match self.compare_tension_lb[..] {
            [] => {
                variants.push((name.clone(), racket.clone(), None));
                for r in &self.compare_racket {
                    variants.push((crate::intake::compare::racket_label(Some(r)), Some(r.clone()), None));
                }
            }
            [t] => {
                variants.push((format!("{name} as given"), racket.clone(), None));
                variants.push(at(t));
            }
            ref many => variants.extend(many.iter().map(|&t| at(t))),
        }
        variants
    }

    /// Refuse the parameters `speed` sets itself when given as flags: the ball speed (from
    /// `--swing` and `--incoming`) and the incidence and spin (from `--swing-path-deg` and
    /// `--incoming-spin-rpm`). (The command line has no such flags; a config file's values are
    /// dropped with a note, [`SPEED_SETS`].)
    fn check_unused(&self) -> Result<()> {
        let given = &self.sources.flags;
        match SPEED_SETS.iter().find(|(spec, _)| given.given().contains(&spec.key)) {
            Some((spec, why)) => {
                let mut values = Params::default();
                given.apply(&mut values);
                let value = keys::value_text(spec.key, &values).unwrap_or_default();
                Err(Error::invalid(spec.key, value, format!("speed does not use it: {why}")))
            }
            None => Ok(()),
        }
    }
}
