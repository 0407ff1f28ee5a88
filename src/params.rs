//! Parameters of one impact: plain serde structs whose defaults are the paper's values
//! (SPEC.md section 3), each validated once at the boundary.
//!
//! Every field's doc gives its unit and allowed range; [`Params::validate`] returns the same
//! sentence as an [`Error::InvalidParameter`] naming the field by its flag / config key.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// Acceleration of gravity used for drop tests, m/s^2.
pub const G: f64 = 9.81;
/// 100 inches in metres (the ITF drop height).
pub const DROP_HEIGHT_100_IN: f64 = 2.54;

/// Speed of a ball dropped from `height` (m) at impact, `sqrt(2 g h)`, m/s.
pub fn drop_speed(height: f64) -> f64 {
    (2.0 * G * height).sqrt()
}

/// The tennis ball (Eqs 1, 3, 4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ball {
    /// Ball mass `m_b`, kg; finite and > 0. Paper: 0.057 kg.
    pub mass: f64,
    /// Compression spring constant `k1` (Eq 3), N/m; finite and > 0. Paper: 3e4 N/m.
    pub k1: f64,
    /// Hysteresis exponent `p` of the expansion law (Eq 4); 1 < p <= 10
    /// (p = 1 would be lossless). Paper: 2.55.
    pub p: f64,
}

impl Default for Ball {
    fn default() -> Self {
        Ball { mass: 0.057, k1: 3.0e4, p: 2.55 }
    }
}

/// The string bed: a massless linear spring (Eq 2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Strings {
    /// String-plane stiffness `k_s`, N/m; finite and > 0. Paper: 2e4 (soft) and 4e4 (stiff).
    pub ks: f64,
}

impl Default for Strings {
    fn default() -> Self {
        Strings { ks: 4.0e4 }
    }
}

/// Calibration of SPEC.md section 3: `k_s` is proportional to the tension, 60 lb = 4e4 N/m.
pub fn ks_from_tension_lb(tension_lb: f64) -> f64 {
    4.0e4 * tension_lb / 60.0
}

/// The racket: a uniform free-free Euler-Bernoulli beam (Eqs 5-6) that also twists rigidly
/// about its long axis (Eq 7). `x = 0` is the tip, `x = L` the butt.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Racket {
    /// Length `L`, m; finite and > 0. Paper: 0.71 m.
    pub length: f64,
    /// Mass `M`, kg; finite and > 0. Paper: 0.34 kg.
    pub mass: f64,
    /// Bending stiffness `EI`, N m^2; finite and > 0. Paper: 150 (125 Hz); wide body 384 (200 Hz).
    pub ei: f64,
    /// Moment of inertia about the long axis `I_x`, kg m^2; finite and > 0. Paper: 0.0015.
    pub ix: f64,
    /// Half-width of the string face, m: the largest allowed |r|; finite and > 0.
    /// Not in the paper (its Figs 7-8 go to r = 10 cm); 0.125 m is a typical 25 cm wide head.
    pub half_width: f64,
}

impl Default for Racket {
    fn default() -> Self {
        Racket { length: 0.71, mass: 0.34, ei: 150.0, ix: 0.0015, half_width: 0.125 }
    }
}

/// Where and how fast the ball arrives.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Impact {
    /// Impact distance from the tip along the long axis, m; 0 <= x <= L.
    pub x: f64,
    /// Impact distance from the long axis, m (signed: -r mirrors the impact); |r| <= half_width.
    pub r: f64,
    /// Incident ball speed `v1` (racket at rest), m/s; finite and > 0.
    pub v1: f64,
}

impl Default for Impact {
    /// The Fig 4 impact: x = 10 cm, r = 5 cm, at the 100-inch drop speed (results scale with v1).
    fn default() -> Self {
        Impact { x: 0.10, r: 0.05, v1: drop_speed(DROP_HEIGHT_100_IN) }
    }
}

/// How the contact force is applied to the discrete beam (SPEC.md section 1, Contact).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum LoadRule {
    /// The paper's scheme: the whole force on the node nearest `x` (ties go to the higher index).
    Node,
    /// Linear (hat) sharing between the two nodes around `x`; converges as O(N^-2).
    #[default]
    Hat,
}

impl LoadRule {
    /// The name used on the command line and in configs.
    pub fn name(self) -> &'static str {
        match self {
            LoadRule::Node => "node",
            LoadRule::Hat => "hat",
        }
    }
}

impl std::str::FromStr for LoadRule {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "node" => Ok(LoadRule::Node),
            "hat" => Ok(LoadRule::Hat),
            other => Err(Error::invalid("load", other, "must be 'node' or 'hat'")),
        }
    }
}

/// Discretisation and time stepping.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Numerics {
    /// Number of beam segments `N` (N+1 nodes); 4 <= N <= 1000. Paper: 39.
    pub segments: usize,
    /// Load rule; `node` is the paper's, `hat` the default for users' impacts.
    pub load: LoadRule,
    /// Time step, s; `None` picks a converged default. Must be finite, > 0 and below the
    /// stability limit `2 / omega_max` (checked when the beam is built).
    pub dt: Option<f64>,
}

impl Default for Numerics {
    fn default() -> Self {
        Numerics { segments: 39, load: LoadRule::Hat, dt: None }
    }
}

impl Numerics {
    /// The paper's numerics: N = 39 with the force on the nearest node.
    pub fn paper() -> Self {
        Numerics { segments: 39, load: LoadRule::Node, dt: None }
    }
}

/// Everything one impact needs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The ball.
    pub ball: Ball,
    /// The string bed.
    pub strings: Strings,
    /// The racket.
    pub racket: Racket,
    /// The impact point and speed.
    pub impact: Impact,
    /// Discretisation.
    pub numerics: Numerics,
}

/// Largest allowed number of segments.
pub const MAX_SEGMENTS: usize = 1000;
/// Smallest allowed number of segments (a free-free beam needs interior curvature points).
pub const MIN_SEGMENTS: usize = 4;

fn finite(field: &'static str, v: f64, unit: &str) -> Result<()> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(Error::invalid(field, v, format!("must be a finite number ({unit})")))
    }
}

fn positive(field: &'static str, v: f64, what: &str, unit: &str) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(field, v, format!("{what} must be a finite number > 0 {unit}")))
    }
}

impl Ball {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        positive("mb", self.mass, "ball mass", "kg")?;
        positive("k1", self.k1, "ball compression stiffness", "N/m")?;
        if !(self.p.is_finite() && self.p > 1.0 && self.p <= 10.0) {
            return Err(Error::invalid("p", self.p, "hysteresis exponent must satisfy 1 < p <= 10"));
        }
        Ok(())
    }
}

impl Strings {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        positive("ks", self.ks, "string-plane stiffness", "N/m")
    }
}

impl Racket {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        positive("length", self.length, "racket length", "m")?;
        positive("mass", self.mass, "racket mass", "kg")?;
        positive("ei", self.ei, "bending stiffness EI", "N m^2")?;
        positive("ix", self.ix, "moment of inertia about the long axis", "kg m^2")?;
        positive("half_width", self.half_width, "string-face half-width", "m")
    }
}

impl Impact {
    /// Check the impact against the racket it hits.
    pub fn validate(&self, racket: &Racket) -> Result<()> {
        finite("x", self.x, "m")?;
        if !(0.0..=racket.length).contains(&self.x) {
            return Err(Error::invalid(
                "x",
                self.x,
                format!("impact point must lie on the racket, 0 <= x <= L = {} m", racket.length),
            ));
        }
        finite("r", self.r, "m")?;
        if self.r.abs() > racket.half_width {
            return Err(Error::invalid(
                "r",
                self.r,
                format!(
                    "off-axis distance must lie on the string face, |r| <= half_width = {} m",
                    racket.half_width
                ),
            ));
        }
        positive("v1", self.v1, "incident ball speed", "m/s")
    }
}

impl Numerics {
    /// Check the discretisation (the dt stability limit is checked when the beam is built).
    pub fn validate(&self) -> Result<()> {
        if !(MIN_SEGMENTS..=MAX_SEGMENTS).contains(&self.segments) {
            return Err(Error::invalid(
                "segments",
                self.segments,
                format!("number of beam segments must satisfy {MIN_SEGMENTS} <= N <= {MAX_SEGMENTS}"),
            ));
        }
        if let Some(dt) = self.dt {
            positive("dt", dt, "time step", "s")?;
        }
        Ok(())
    }
}

impl Params {
    /// The paper's racket, ball and strings at the Fig 4 impact, with the paper's numerics.
    pub fn paper() -> Self {
        Params { numerics: Numerics::paper(), ..Params::default() }
    }

    /// Validate every part; the first violation is returned.
    pub fn validate(&self) -> Result<()> {
        self.ball.validate()?;
        self.strings.validate()?;
        self.racket.validate()?;
        self.impact.validate(&self.racket)?;
        self.numerics.validate()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_parameters_are_valid() {
        Params::paper().validate().unwrap();
        Params::default().validate().unwrap();
    }

    #[test]
    fn hysteresis_exponent_of_one_is_rejected() {
        let mut p = Params::default();
        p.ball.p = 1.0;
        let msg = p.validate().unwrap_err().to_string();
        assert!(msg.starts_with("invalid p = 1:"), "{msg}");
    }

    #[test]
    fn impact_beyond_the_butt_is_rejected() {
        let mut p = Params::default();
        p.impact.x = 0.72;
        let msg = p.validate().unwrap_err().to_string();
        assert!(msg.contains("invalid x = 0.72") && msg.contains("0 <= x <= L"), "{msg}");
    }

    #[test]
    fn nan_stiffness_is_rejected() {
        let mut p = Params::default();
        p.strings.ks = f64::NAN;
        assert!(p.validate().unwrap_err().to_string().contains("invalid ks = NaN"));
    }

    #[test]
    fn tension_calibration_is_sixty_pounds_for_4e4() {
        assert_eq!(ks_from_tension_lb(60.0), 4.0e4);
        assert!((ks_from_tension_lb(50.0) - 4.0e4 * 5.0 / 6.0).abs() < 1e-9);
    }
}
