//! Outgoing ball speeds for a swing and an incoming ball (the `speed` command): one impact per
//! variant (string tensions or rackets), compared with the first.
//!
//! `v_out = e_A v_in + (1 + e_A) v_racket` (the paper's frame transformation), with `e_A`
//! computed at the relative speed `v_in + v_racket` and the racket's swing speed taken at the
//! impact point.

use crate::diagnostic::{Diagnostic, Kind};
use crate::error::{Error, Result};
use crate::intake::compare::check_comparison;
use crate::intake::diagnose;
use crate::intake::Sources;
use crate::numfmt::sig;
use crate::params::keys;
use crate::params::spec::ParamSpec;
use crate::params::{ks_from_tension_lb, Params};
use crate::render::table::{Table, Value};
use crate::solve::swing::{gain_pct, outgoing_speed, Swing};
use crate::solve::ImpactResult;

/// The sign conventions of the spins a stroke's JSON prints.
pub const SPEED_SPIN_CONVENTION: &str =
    "spin_rpm (the ball's spin as it leaves) and incoming_spin_rpm: > 0 topspin in the \
     court's frame (the ball's top moving forward in its flight); params.oblique.spin_rpm and result.spin_out_rpm: the \
     racket's frame, > 0 topspin relative to the ball's incoming motion along the strings";

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
            // e_A is computed at the relative speed (it does not depend on it; theta scales with it)
            p.impact.v1 = v_in + v_racket;
            p.validate()?;
            let r = crate::simulate(&p)?;
            let v_out = outgoing_speed(r.e_a, v_in, v_racket);
            rows.push(SpeedRow { label, params: p, result: r, v_out, launch: None });
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

impl SpeedComparison {
    /// The reference's outgoing speed, m/s.
    fn v_ref(&self) -> f64 {
        self.rows[0].v_out
    }

    /// The comparison as a table (speeds in the request's unit).
    pub fn table(&self) -> Result<Table> {
        let unit = self.request.unit;
        let mut cols = vec![
            "variant",
            "x_m",
            "r_m",
            "ks_n_per_m",
            "e_a",
            "tau_s",
            "theta_end_deg",
            "ball_speed_out",
            "change_pct",
            "unit",
        ];
        if self.request.is_stroke() {
            cols.extend(["launch_deg", "launch_spin_rpm"]);
        }
        let mut t = Table::new("speed", &cols);
        for SpeedRow { label, params: p, result: r, v_out, launch } in &self.rows {
            let mut row = vec![
                Value::Text(label.clone()),
                p.impact.x.into(),
                p.impact.r.into(),
                p.strings.ks.into(),
                r.e_a.into(),
                r.tau_s.into(),
                r.theta_end_deg.into(),
                (v_out / unit.si).into(),
                gain_pct(self.v_ref(), *v_out).into(),
                Value::Text(unit.label.into()),
            ];
            if let Some((launch_deg, spin_rpm)) = launch {
                row.extend([Value::from(*launch_deg), Value::from(*spin_rpm)]);
            }
            t.push(row)?;
        }
        Ok(t)
    }

    /// The comparison as pretty JSON (one object per variant) with a final newline.
    pub fn json(&self) -> Result<String> {
        let unit = self.request.unit;
        let v: Vec<serde_json::Value> = self
            .rows
            .iter()
            .map(|row| {
                let SpeedRow { label, params: p, result: r, v_out, launch } = row;
                let mut v = serde_json::json!({
                    "variant": label, "params": p, "result": crate::render::impact::result_json(p, r),
                    "ball_speed_out": v_out / unit.si, "change_pct": gain_pct(self.v_ref(), *v_out), "unit": unit.label,
                    "diagnostics": self.diagnostics_of(&[row]),
                });
                if let (Some((launch_deg, spin_rpm)), Some(o)) = (launch, v.as_object_mut()) {
                    o.insert("launch_deg".into(), (*launch_deg).into());
                    o.insert("spin_rpm".into(), (*spin_rpm).into());
                    o.insert("incoming_spin_rpm".into(), self.request.incoming_spin_rpm.into());
                    o.insert("spin_convention".into(), SPEED_SPIN_CONVENTION.into());
                }
                v
            })
            .collect();
        crate::render::json::pretty(&v)
    }

    /// The comparison's diagnostics, once each: the notes about what no variant uses, the
    /// variants' parameters but those the stroke sets (said in its own terms: the impact speed,
    /// the incoming spin, the incidence), the largest twist. Each variant's own are in its JSON
    /// row (with the notes, which hold for every variant).
    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        self.diagnostics_of(&self.rows.iter().collect::<Vec<_>>())
    }

    fn diagnostics_of(&self, rows: &[&SpeedRow]) -> Vec<Diagnostic> {
        let (req, u) = (&self.request, self.request.unit);
        let mut out = self.noted.clone();
        out.extend(diagnose::parameters(rows.iter().map(|r| &r.params), &SPEED_SETS.map(|(s, _)| s.key)));
        if let Some((lo, hi)) = keys::V1.usual {
            let v = (req.swing + req.incoming) * u.si;
            if !(lo..=hi).contains(&v) {
                out.push(Diagnostic::new(
                    Kind::Unusual,
                    keys::V1.key,
                    format!(
                        "swing + incoming = {} {} (the impact speed) is outside the usual {}..{} {} (computed anyway)",
                        sig(req.swing + req.incoming, 4),
                        u.label,
                        sig(lo / u.si, 3),
                        sig(hi / u.si, 3),
                        u.label
                    ),
                ));
            }
        }
        if let Some(line) = keys::SPIN_RPM.unusual(req.incoming_spin_rpm) {
            out.push(Diagnostic::new(
                Kind::Unusual,
                "incoming-spin-rpm",
                line.replacen(keys::SPIN_RPM.key, "incoming-spin-rpm", 1),
            ));
        }
        if let Some(angle) =
            rows.iter().map(|r| r.params.oblique.angle_deg).find(|&d| keys::ANGLE_DEG.unusual(d).is_some())
        {
            out.push(Diagnostic::new(
                Kind::Unusual,
                keys::ANGLE_DEG.key,
                format!(
                    "the swing path of {} deg meets the face at {} deg from its normal, beyond the usual incidences (computed anyway)",
                    req.path_deg,
                    sig(angle, 3)
                ),
            ));
        }
        let theta = rows.iter().map(|r| r.result.theta_end_deg).max_by(|a, b| a.abs().total_cmp(&b.abs()));
        out.extend(theta.and_then(diagnose::twist));
        out
    }

    /// The comparison as text: the swing, then one line per variant.
    pub fn text(&self) -> String {
        if self.request.is_stroke() {
            return self.stroke_text();
        }
        let (req, unit) = (&self.request, self.request.unit);
        let mut s = format!(
            "swing {} {u} at the impact point, incoming ball {} {u}: v_out = e_A v_in + (1 + e_A) v_racket\n",
            req.swing,
            req.incoming,
            u = unit.label
        );
        s.push_str(&format!(
            "{:<22} {:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>12} {:>9}\n",
            "variant", "x cm", "r cm", "ks N/m", "e_A", "tau ms", "theta deg", "ball out", "change"
        ));
        for SpeedRow { label, params: p, result: r, v_out, .. } in &self.rows {
            s.push_str(&format!(
                "{:<22} {:>7.1} {:>6.1} {:>9.0} {:>8.4} {:>8.3} {:>9.2} {:>7.1} {:<4} {:>+8.2} %\n",
                label,
                100.0 * p.impact.x,
                100.0 * p.impact.r,
                p.strings.ks,
                r.e_a,
                1e3 * r.tau_s,
                r.theta_end_deg,
                v_out / unit.si,
                unit.label,
                gain_pct(self.v_ref(), *v_out)
            ));
        }
        s
    }

    /// The text of a stroke along a tilted path or with a spinning ball: speed, launch angle and
    /// spin in the court's frame.
    fn stroke_text(&self) -> String {
        let (req, unit) = (&self.request, self.request.unit);
        let mut s = format!(
            "swing {} {u} along a path {} deg above the horizontal, incoming ball {} {u} with {} rpm of topspin \
             (court frame; the impact computed in the racket's frame)\n",
            req.swing,
            req.path_deg,
            req.incoming,
            req.incoming_spin_rpm,
            u = unit.label
        );
        s.push_str(
            "spin: > 0 is topspin in the court's frame (the ball's top moving forward in its flight), \
             for the incoming ball and the spin column alike\n",
        );
        // a tangential law other than the default one is named (it changes every spin)
        if let Some(p) = self.rows.first().map(|r| &r.params) {
            if p.oblique.tangential != crate::params::TangentialLaw::default() {
                s.push_str(&format!("tangential contact law: {}\n", p.oblique.tangential.name()));
            }
        }
        s.push_str(&format!(
            "{:<22} {:>7} {:>9} {:>8} {:>10} {:>12} {:>9} {:>10} {:>9}\n",
            "variant", "x cm", "ks N/m", "e_A", "incidence", "ball out", "change", "launch", "spin rpm"
        ));
        for SpeedRow { label, params: p, result: r, v_out, launch } in &self.rows {
            let (launch_deg, spin_rpm) = launch.unwrap_or((0.0, 0.0));
            s.push_str(&format!(
                "{:<22} {:>7.1} {:>9.0} {:>8.4} {:>6.1} deg {:>7.1} {:<4} {:>+8.2} % {:>6.1} deg {:>9.0}\n",
                label,
                100.0 * p.impact.x,
                p.strings.ks,
                r.e_a,
                p.oblique.angle_deg,
                v_out / unit.si,
                unit.label,
                gain_pct(self.v_ref(), *v_out),
                launch_deg,
                spin_rpm
            ));
        }
        s
    }
}
