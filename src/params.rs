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
    /// Ball mass `m_b`, kg; 1e-4..=10 ([`ranges::MB`]). Paper: 0.057 kg.
    pub mass: f64,
    /// Compression spring constant `k1` (Eq 3), N/m; 1..=1e9. Paper: 3e4 N/m.
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
    /// String-plane stiffness `k_s`, N/m; 1..=1e12. Paper: 2e4 (soft) and 4e4 (stiff).
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
    /// Length `L`, m; 0.05..=5. Paper: 0.71 m.
    pub length: f64,
    /// Mass `M`, kg; 1e-3..=1e6 (a very heavy frame emulates a clamped one). Paper: 0.34 kg.
    pub mass: f64,
    /// Bending stiffness `EI`, N m^2; 1e-2..=1e9. Paper: 150 (125 Hz); wide body 384 (200 Hz).
    pub ei: f64,
    /// Moment of inertia about the long axis `I_x`, kg m^2; 1e-7..=1e4. Paper: 0.0015.
    pub ix: f64,
    /// Half-width of the string face, m: the largest allowed |r|; 1e-3..=1.
    /// Not in the paper (its Figs 7-8 go to r = 10 cm); 0.125 m is a typical 25 cm wide head.
    pub half_width: f64,
    /// Length of the string face from the tip, m; 0 < head_length <= L. When set, the string
    /// face is the ellipse with axes `head_length` along and `2 half_width` across the racket
    /// (`x` from 0 to `head_length`), and impacts outside it are refused. When absent (the
    /// paper's racket) the face is the strip `0 <= x <= L`, `|r| <= half_width`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub head_length: Option<f64>,
    /// How mass and stiffness vary along the racket; absent for the paper's uniform beam.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<Profile>,
}

impl Default for Racket {
    fn default() -> Self {
        Racket { length: 0.71, mass: 0.34, ei: 150.0, ix: 0.0015, half_width: 0.125, head_length: None, profile: None }
    }
}

/// A non-uniform racket: linear density and bending stiffness, each piecewise linear between
/// four knots along the racket (tip, end of the head, start of the handle, butt). The paper
/// says its method extends to head-heavy and head-light rackets; this is that extension.
///
/// The density only sets the shape of the mass distribution: node masses are the density
/// integrated against each node's hat function, then scaled so they sum to [`Racket::mass`].
/// The stiffness multiplies [`Racket::ei`]: `EI(x) = ei * stiffness(x)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profile {
    /// Knot positions as fractions of the length from the tip: 0 = k0 < k1 < k2 < k3 = 1.
    pub knots: [f64; 4],
    /// Relative linear density at the knots; each finite and > 0.
    pub density: [f64; 4],
    /// Relative bending stiffness at the knots; each 1e-3..=1e3 ([`ranges::STIFFNESS_REL`]).
    pub stiffness: [f64; 4],
}

impl Profile {
    /// Linear interpolation of knot values `v` at the fraction `f` (0 = tip, 1 = butt).
    pub fn at(&self, v: &[f64; 4], f: f64) -> f64 {
        let k = &self.knots;
        let i = if f <= k[1] {
            0
        } else if f <= k[2] {
            1
        } else {
            2
        };
        let w = ((f - k[i]) / (k[i + 1] - k[i])).clamp(0.0, 1.0);
        v[i] + w * (v[i + 1] - v[i])
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
    /// Incident ball speed `v1` (racket at rest), m/s; 1e-3..=1e3 (results scale exactly with v1).
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

impl clap::ValueEnum for LoadRule {
    fn value_variants<'a>() -> &'a [Self] {
        &[LoadRule::Node, LoadRule::Hat]
    }
    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()))
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

/// Which solver integrates the impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum SolverKind {
    /// Explicit finite differences in time (velocity Verlet), the reference.
    #[default]
    Fd,
    /// Modal superposition with exact modal propagation and a contact-sized step.
    Modal,
}

impl SolverKind {
    /// The name used on the command line and in configs.
    pub fn name(self) -> &'static str {
        match self {
            SolverKind::Fd => "fd",
            SolverKind::Modal => "modal",
        }
    }
}

impl clap::ValueEnum for SolverKind {
    fn value_variants<'a>() -> &'a [Self] {
        &[SolverKind::Fd, SolverKind::Modal]
    }
    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()))
    }
}

impl std::str::FromStr for SolverKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "fd" => Ok(SolverKind::Fd),
            "modal" => Ok(SolverKind::Modal),
            other => Err(Error::invalid("solver", other, "must be 'fd' or 'modal'")),
        }
    }
}

/// Discretisation and time stepping.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Numerics {
    /// Number of beam segments `N` (N+1 nodes); 4 <= N <= 400. Paper: 39.
    pub segments: usize,
    /// Load rule; `node` is the paper's, `hat` the default for users' impacts.
    pub load: LoadRule,
    /// Time step, s; `None` picks a converged default. Must be finite, > 0 and below the
    /// stability limit `2 / omega_max` (checked when the beam is built).
    pub dt: Option<f64>,
    /// The solver: `fd` (explicit, the reference) or `modal`.
    #[serde(default)]
    pub solver: SolverKind,
}

impl Default for Numerics {
    fn default() -> Self {
        Numerics { segments: 39, load: LoadRule::Hat, dt: None, solver: SolverKind::Fd }
    }
}

impl Numerics {
    /// The paper's numerics: N = 39 with the force on the nearest node.
    pub fn paper() -> Self {
        Numerics { segments: 39, load: LoadRule::Node, dt: None, solver: SolverKind::Fd }
    }
}

/// How the frame is modelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, Default, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Frame {
    /// The paper's flexible beam.
    #[default]
    Beam,
    /// The textbook rigid racket (effective mass at the impact point, plus twist), in closed form.
    Rigid,
}

/// How the racket is held.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, Default, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Grip {
    /// The paper's freely suspended racket.
    #[default]
    Free,
    /// A hand: springs and dampers spread over the grip length from the butt.
    Hand,
}

/// The string bed's force law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, Default, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum StringLaw {
    /// The paper's constant `k_s`.
    #[default]
    Linear,
    /// `F = k_s Y_s (1 + s (Y_s / d)^2)`: the secant stiffness grows by the fraction `s` at the
    /// deflection `d` (the paper quotes about 10 % for large deflections).
    Stiffening,
}

/// Model variants beyond the paper (issue 6); the defaults are the paper's model.
///
/// The hand defaults are assumptions, not measurements: a 15 cm grip holding the racket with
/// 5e3 N/m and 10 N s/m in all. The damping gives the 125 Hz mode of the paper's racket a
/// damping ratio of 2.6 % ([`crate::solve::hand_damping_ratio`]; a test pins it), the order at
/// which a hand-held frame's vibration dies away in a few tens of milliseconds; the stiffness makes the whole
/// racket bounce on the hand at a few hertz, far below any frame mode. H. Hatze (Med. Sci.
/// Sports 8, 1976) modelled the racket-hand system the same way; D. Chadefaux et al. (2017)
/// fitted such distributed springs and dampers to measured hand-held rackets. The hand resists
/// bending and translation only, not the twist about the long axis (Eq 7 stays free), so for
/// off-axis impacts near the handle it overstates the twist.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Variants {
    /// `beam` (the paper) or `rigid`.
    pub frame: Frame,
    /// `free` (the paper) or `hand`.
    pub grip: Grip,
    /// `linear` (the paper) or `stiffening`.
    pub strings: StringLaw,
    /// Stiffening fraction `s` (with `strings = stiffening`); 0..=10. Default 0.10.
    pub string_stiffening: f64,
    /// Deflection `d` at which the secant stiffness has grown by `s`, m; 1e-4..=1. Default 0.04:
    /// the string-plane deflection of a 60 m/s serve on 4e4 N/m strings (peak force about 1.7 kN,
    /// the paper's p. 4 estimate), where the paper puts the rise at about 10 %.
    pub stiffening_deflection: f64,
    /// Total hand stiffness (with `grip = hand`), N/m; 0..=1e7.
    pub hand_stiffness: f64,
    /// Total hand damping, N s/m; 0..=1e4.
    pub hand_damping: f64,
    /// Grip length from the butt, m; > 0 and at most half the racket.
    pub grip_length: f64,
}

impl Default for Variants {
    fn default() -> Self {
        Variants {
            frame: Frame::Beam,
            grip: Grip::Free,
            strings: StringLaw::Linear,
            string_stiffening: 0.10,
            stiffening_deflection: 0.04,
            hand_stiffness: 5.0e3,
            hand_damping: 10.0,
            grip_length: 0.15,
        }
    }
}

impl Variants {
    /// Check the values and the combinations the solvers support.
    pub fn validate(&self, racket: &Racket, solver: SolverKind) -> Result<()> {
        within("string-stiffening", self.string_stiffening, "string stiffening fraction", "", (0.0, 10.0))?;
        within("stiffening-deflection", self.stiffening_deflection, "stiffening deflection", "m", (1e-4, 1.0))?;
        within("hand-stiffness", self.hand_stiffness, "hand stiffness", "N/m", (0.0, 1e7))?;
        within("hand-damping", self.hand_damping, "hand damping", "N s/m", (0.0, 1e4))?;
        if self.grip == Grip::Hand {
            // only a hand needs a grip that fits on the racket
            within("grip-length", self.grip_length, "grip length", "m", (1e-3, 0.5 * racket.length))?;
        } else {
            within("grip-length", self.grip_length, "grip length", "m", (1e-3, ranges::LENGTH.1))?;
        }
        let nonlinear = self.strings == StringLaw::Stiffening || self.grip == Grip::Hand;
        if nonlinear && self.frame == Frame::Rigid {
            return Err(Error::invalid(
                "frame",
                "rigid",
                "must be beam with stiffening strings or a hand grip (the rigid frame is the closed-form limit for linear strings and a free racket)",
            ));
        }
        if nonlinear && solver == SolverKind::Modal {
            return Err(Error::invalid(
                "solver",
                "modal",
                "must be fd with stiffening strings or a hand grip (the modal solver needs a linear, undamped system)",
            ));
        }
        Ok(())
    }

    /// Short description for titles and metadata, e.g. `beam, free, linear strings`.
    pub fn label(&self) -> String {
        let frame = match self.frame {
            Frame::Beam => "beam".to_string(),
            Frame::Rigid => "rigid frame".to_string(),
        };
        let grip = match self.grip {
            Grip::Free => "free".to_string(),
            Grip::Hand => format!("hand ({:.0} N/m, {:.0} N s/m)", self.hand_stiffness, self.hand_damping),
        };
        let strings = match self.strings {
            StringLaw::Linear => "linear strings".to_string(),
            StringLaw::Stiffening => format!(
                "strings +{:.0} % at {:.0} mm",
                100.0 * self.string_stiffening,
                1e3 * self.stiffening_deflection
            ),
        };
        format!("{frame}, {grip}, {strings}")
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
    /// Model variants (the paper's model by default).
    #[serde(default)]
    pub variants: Variants,
}

/// Largest allowed number of segments.
pub const MAX_SEGMENTS: usize = 400;
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

/// A physical range check: `lo <= v <= hi`. The ranges are wide (far beyond any racket sport)
/// but keep every energy and frequency representable, so a result is never NaN.
fn within(field: &'static str, v: f64, what: &str, unit: &str, (lo, hi): (f64, f64)) -> Result<()> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(Error::invalid(field, v, format!("{what} must satisfy {lo:e} <= {field} <= {hi:e} {unit}")))
    }
}

/// Allowed ranges, (min, max), in the fields' units.
pub mod ranges {
    /// Ball mass, kg.
    pub const MB: (f64, f64) = (1.0e-4, 10.0);
    /// Ball compression stiffness, N/m.
    pub const K1: (f64, f64) = (1.0, 1.0e9);
    /// String-plane stiffness, N/m.
    pub const KS: (f64, f64) = (1.0, 1.0e12);
    /// Racket length, m.
    pub const LENGTH: (f64, f64) = (0.05, 5.0);
    /// Racket mass, kg.
    pub const MASS: (f64, f64) = (1.0e-3, 1.0e6);
    /// Bending stiffness, N m^2.
    pub const EI: (f64, f64) = (1.0e-2, 1.0e9);
    /// Moment of inertia about the long axis, kg m^2.
    pub const IX: (f64, f64) = (1.0e-7, 1.0e4);
    /// String-face half-width, m.
    pub const HALF_WIDTH: (f64, f64) = (1.0e-3, 1.0);
    /// Incident speed, m/s (results scale exactly with v1, so nothing is lost).
    pub const V1: (f64, f64) = (1.0e-3, 1.0e3);
    /// Relative bending stiffness of a [`super::Profile`] knot.
    pub const STIFFNESS_REL: (f64, f64) = (1.0e-3, 1.0e3);
}

impl Ball {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        within("mb", self.mass, "ball mass", "kg", ranges::MB)?;
        within("k1", self.k1, "ball compression stiffness", "N/m", ranges::K1)?;
        if !(self.p.is_finite() && self.p > 1.0 && self.p <= 10.0) {
            return Err(Error::invalid("p", self.p, "hysteresis exponent must satisfy 1 < p <= 10"));
        }
        Ok(())
    }
}

impl Strings {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        within("ks", self.ks, "string-plane stiffness", "N/m", ranges::KS)
    }
}

impl Racket {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        within("length", self.length, "racket length", "m", ranges::LENGTH)?;
        within("mass", self.mass, "racket mass", "kg", ranges::MASS)?;
        within("ei", self.ei, "bending stiffness EI", "N m^2", ranges::EI)?;
        within("ix", self.ix, "moment of inertia about the long axis", "kg m^2", ranges::IX)?;
        within("half-width", self.half_width, "string-face half-width", "m", ranges::HALF_WIDTH)?;
        if let Some(h) = self.head_length {
            if !(h.is_finite() && h > 0.0 && h <= self.length) {
                return Err(Error::invalid(
                    "head-length",
                    h,
                    format!("string-face length must satisfy 0 < head-length <= L = {} m", self.length),
                ));
            }
        }
        if let Some(p) = &self.profile {
            p.validate()?;
        }
        Ok(())
    }

    /// Half-width of the string face at `x` (m from the tip), m; `None` off the face along x.
    pub fn face_half_width(&self, x: f64) -> Option<f64> {
        match self.head_length {
            None => (0.0..=self.length).contains(&x).then_some(self.half_width),
            Some(h) => ellipse_half_width(h, self.half_width, x),
        }
    }
}

/// Half-width at `x` of the elliptical face that spans `0..=length` along the racket with
/// half-width `half_width` at its middle (all m); `None` beyond its ends.
pub fn ellipse_half_width(length: f64, half_width: f64, x: f64) -> Option<f64> {
    let a = 0.5 * length;
    let q = (x - a) / a;
    (q.abs() <= 1.0).then(|| half_width * (1.0 - q * q).max(0.0).sqrt())
}

impl Profile {
    /// Check the knots and values.
    pub fn validate(&self) -> Result<()> {
        let k = &self.knots;
        let ascending = k.windows(2).all(|w| w[0] < w[1]);
        if !(k.iter().all(|v| v.is_finite()) && k[0] == 0.0 && k[3] == 1.0 && ascending) {
            return Err(Error::invalid(
                "profile.knots",
                format!("{k:?}"),
                "knots must be fractions of the length with 0 = k0 < k1 < k2 < k3 = 1",
            ));
        }
        for &d in &self.density {
            positive("profile.density", d, "relative linear density", "at every knot")?;
        }
        for &e in &self.stiffness {
            within("profile.stiffness", e, "relative bending stiffness", "at every knot", ranges::STIFFNESS_REL)?;
        }
        Ok(())
    }
}

impl Impact {
    /// Check the impact against the racket it hits.
    pub fn validate(&self, racket: &Racket) -> Result<()> {
        finite("x", self.x, "m")?;
        let Some(half) = racket.face_half_width(self.x) else {
            let msg = match racket.head_length {
                None => format!("impact point must lie on the racket, 0 <= x <= L = {} m", racket.length),
                Some(h) => format!("impact point must lie on the string face, 0 <= x <= head-length = {h} m"),
            };
            return Err(Error::invalid("x", self.x, msg));
        };
        finite("r", self.r, "m")?;
        if self.r.abs() > half {
            let msg = match racket.head_length {
                None => format!("off-axis distance must lie on the string face, |r| <= half-width = {half} m"),
                Some(_) => format!(
                    "off-axis distance must lie inside the head outline, |r| <= {half:.4} m at x = {} m",
                    self.x
                ),
            };
            return Err(Error::invalid("r", self.r, msg));
        }
        within("v1", self.v1, "incident ball speed", "m/s", ranges::V1)
    }
}

/// Check a number of beam segments.
pub fn check_segments(segments: usize) -> Result<()> {
    if !(MIN_SEGMENTS..=MAX_SEGMENTS).contains(&segments) {
        return Err(Error::invalid(
            "segments",
            segments,
            format!("number of beam segments must satisfy {MIN_SEGMENTS} <= N <= {MAX_SEGMENTS}"),
        ));
    }
    Ok(())
}

impl Numerics {
    /// Check the discretisation (the dt stability limit is checked when the beam is built).
    pub fn validate(&self) -> Result<()> {
        check_segments(self.segments)?;
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
        self.numerics.validate()?;
        self.variants.validate(&self.racket, self.numerics.solver)
    }
}

/// Overrides of [`Params`], one optional field per command-line flag. The same struct is the
/// `--config` TOML file (keys spelled as the flags, unknown keys rejected), so a config and
/// the flags can never drift apart. Precedence: paper defaults < config file < flags.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize, clap::Args)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct Overrides {
    /// Impact distance from the tip, m (0 <= x <= length)
    #[arg(long, allow_hyphen_values = true)]
    pub x: Option<f64>,
    /// Impact distance from the long axis, m (|r| <= half-width)
    #[arg(long, allow_hyphen_values = true)]
    pub r: Option<f64>,
    /// String-plane stiffness, N/m (1 ..= 1e12)
    #[arg(long, allow_hyphen_values = true)]
    pub ks: Option<f64>,
    /// Frame bending stiffness EI, N m^2 (1e-2 ..= 1e9)
    #[arg(long, allow_hyphen_values = true)]
    pub ei: Option<f64>,
    /// Racket mass, kg (1e-3 ..= 1e6)
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Racket length, m (0.05 ..= 5)
    #[arg(long, allow_hyphen_values = true)]
    pub length: Option<f64>,
    /// Moment of inertia about the long axis, kg m^2 (1e-7 ..= 1e4)
    #[arg(long, allow_hyphen_values = true)]
    pub ix: Option<f64>,
    /// Half-width of the string face, m (1e-3 ..= 1): the largest |r|
    #[arg(long, allow_hyphen_values = true)]
    pub half_width: Option<f64>,
    /// Ball mass, kg (1e-4 ..= 10)
    #[arg(long, allow_hyphen_values = true)]
    pub mb: Option<f64>,
    /// Ball compression stiffness k1, N/m (1 ..= 1e9)
    #[arg(long, allow_hyphen_values = true)]
    pub k1: Option<f64>,
    /// Ball hysteresis exponent p (1 < p <= 10)
    #[arg(long, allow_hyphen_values = true)]
    pub p: Option<f64>,
    /// Incident ball speed, m/s (1e-3 ..= 1e3)
    #[arg(long, allow_hyphen_values = true)]
    pub v1: Option<f64>,
    /// Number of beam segments N (4..=400)
    #[arg(long, allow_hyphen_values = true)]
    pub segments: Option<usize>,
    /// Load rule: node (the paper's) or hat
    #[arg(long)]
    pub load: Option<LoadRule>,
    /// Time step, s (default: converged automatic step; must be below the stability limit)
    #[arg(long, allow_hyphen_values = true)]
    pub dt: Option<f64>,
    /// Solver: fd (explicit time stepping, the reference) or modal (modal superposition)
    #[arg(long)]
    pub solver: Option<SolverKind>,
    /// Frame model: beam (the paper's flexible beam) or rigid (closed-form rigid racket)
    #[arg(long)]
    pub frame: Option<Frame>,
    /// Grip: free (the paper's) or hand (springs and dampers over the grip length)
    #[arg(long)]
    pub grip: Option<Grip>,
    /// String law: linear (the paper's) or stiffening
    #[arg(long)]
    pub strings: Option<StringLaw>,
    /// Stiffening fraction s at the stiffening deflection (0 ..= 10; default 0.10)
    #[arg(long, allow_hyphen_values = true)]
    pub string_stiffening: Option<f64>,
    /// Deflection at which the strings are stiffer by s, m (1e-4 ..= 1; default 0.04)
    #[arg(long, allow_hyphen_values = true)]
    pub stiffening_deflection: Option<f64>,
    /// Total hand stiffness, N/m (0 ..= 1e7; default 5e3)
    #[arg(long, allow_hyphen_values = true)]
    pub hand_stiffness: Option<f64>,
    /// Total hand damping, N s/m (0 ..= 1e4; default 10)
    #[arg(long, allow_hyphen_values = true)]
    pub hand_damping: Option<f64>,
    /// Grip length from the butt, m (up to half the racket; default 0.15)
    #[arg(long, allow_hyphen_values = true)]
    pub grip_length: Option<f64>,
}

impl Overrides {
    /// Read a TOML config file with the flag names as keys.
    pub fn from_toml_file(path: &std::path::Path) -> Result<Self> {
        Self::from_toml_bytes(path, &read_file(path)?)
    }

    /// Parse the contents of a config file (`path` only names it in errors). An empty file, a
    /// file that is not UTF-8 text, a TOML syntax error, a wrong type and an unknown key are all
    /// errors with one line naming the file and, where TOML knows it, the key and line.
    pub fn from_toml_bytes(path: &std::path::Path, bytes: &[u8]) -> Result<Self> {
        parse_toml(path, bytes, "give at least one key, e.g. ks = 4e4")
    }

    /// The keys, spelled as the flags and config keys.
    pub const KEYS: [&'static str; 24] = [
        "x",
        "r",
        "ks",
        "ei",
        "mass",
        "length",
        "ix",
        "half-width",
        "mb",
        "k1",
        "p",
        "v1",
        "segments",
        "load",
        "dt",
        "solver",
        "frame",
        "grip",
        "strings",
        "string-stiffening",
        "stiffening-deflection",
        "hand-stiffness",
        "hand-damping",
        "grip-length",
    ];

    /// Set one field from its text, as a flag would (used by `sweep`, which varies any key).
    pub fn set(&mut self, key: &str, value: &str) -> Result<()> {
        let num = |field: &'static str| -> Result<Option<f64>> {
            value.trim().parse::<f64>().map(Some).map_err(|_| Error::invalid(field, value, "must be a number"))
        };
        match key {
            "x" => self.x = num("x")?,
            "r" => self.r = num("r")?,
            "ks" => self.ks = num("ks")?,
            "ei" => self.ei = num("ei")?,
            "mass" => self.mass = num("mass")?,
            "length" => self.length = num("length")?,
            "ix" => self.ix = num("ix")?,
            "half-width" => self.half_width = num("half-width")?,
            "mb" => self.mb = num("mb")?,
            "k1" => self.k1 = num("k1")?,
            "p" => self.p = num("p")?,
            "v1" => self.v1 = num("v1")?,
            "dt" => self.dt = num("dt")?,
            "segments" => {
                self.segments = Some(value.trim().parse().map_err(|_| {
                    Error::invalid("segments", value, "must be a whole number of segments, 4 <= N <= 400")
                })?)
            }
            "load" => self.load = Some(value.trim().parse()?),
            "solver" => self.solver = Some(value.trim().parse()?),
            "frame" => self.frame = Some(choice("frame", value)?),
            "grip" => self.grip = Some(choice("grip", value)?),
            "strings" => self.strings = Some(choice("strings", value)?),
            "string-stiffening" => self.string_stiffening = num("string-stiffening")?,
            "stiffening-deflection" => self.stiffening_deflection = num("stiffening-deflection")?,
            "hand-stiffness" => self.hand_stiffness = num("hand-stiffness")?,
            "hand-damping" => self.hand_damping = num("hand-damping")?,
            "grip-length" => self.grip_length = num("grip-length")?,
            _ => {
                return Err(Error::Config {
                    path: "<sweep>".into(),
                    message: format!("unknown parameter '{key}' (known: {})", Self::KEYS.join(", ")),
                })
            }
        }
        Ok(())
    }

    /// Field-wise `self` where set, else `base`.
    pub fn or(self, base: Overrides) -> Overrides {
        Overrides {
            x: self.x.or(base.x),
            r: self.r.or(base.r),
            ks: self.ks.or(base.ks),
            ei: self.ei.or(base.ei),
            mass: self.mass.or(base.mass),
            length: self.length.or(base.length),
            ix: self.ix.or(base.ix),
            half_width: self.half_width.or(base.half_width),
            mb: self.mb.or(base.mb),
            k1: self.k1.or(base.k1),
            p: self.p.or(base.p),
            v1: self.v1.or(base.v1),
            segments: self.segments.or(base.segments),
            load: self.load.or(base.load),
            dt: self.dt.or(base.dt),
            solver: self.solver.or(base.solver),
            frame: self.frame.or(base.frame),
            grip: self.grip.or(base.grip),
            strings: self.strings.or(base.strings),
            string_stiffening: self.string_stiffening.or(base.string_stiffening),
            stiffening_deflection: self.stiffening_deflection.or(base.stiffening_deflection),
            hand_stiffness: self.hand_stiffness.or(base.hand_stiffness),
            hand_damping: self.hand_damping.or(base.hand_damping),
            grip_length: self.grip_length.or(base.grip_length),
        }
    }

    /// Apply the set fields to `params` (no validation: call [`Params::validate`] after).
    pub fn apply(&self, params: &mut Params) {
        let set = |dst: &mut f64, v: Option<f64>| {
            if let Some(v) = v {
                *dst = v;
            }
        };
        set(&mut params.impact.x, self.x);
        set(&mut params.impact.r, self.r);
        set(&mut params.strings.ks, self.ks);
        set(&mut params.racket.ei, self.ei);
        set(&mut params.racket.mass, self.mass);
        set(&mut params.racket.length, self.length);
        set(&mut params.racket.ix, self.ix);
        set(&mut params.racket.half_width, self.half_width);
        set(&mut params.ball.mass, self.mb);
        set(&mut params.ball.k1, self.k1);
        set(&mut params.ball.p, self.p);
        set(&mut params.impact.v1, self.v1);
        if let Some(n) = self.segments {
            params.numerics.segments = n;
        }
        if let Some(l) = self.load {
            params.numerics.load = l;
        }
        if self.dt.is_some() {
            params.numerics.dt = self.dt;
        }
        if let Some(s) = self.solver {
            params.numerics.solver = s;
        }
        let v = &mut params.variants;
        if let Some(f) = self.frame {
            v.frame = f;
        }
        if let Some(g) = self.grip {
            v.grip = g;
        }
        if let Some(l) = self.strings {
            v.strings = l;
        }
        set(&mut v.string_stiffening, self.string_stiffening);
        set(&mut v.stiffening_deflection, self.stiffening_deflection);
        set(&mut v.hand_stiffness, self.hand_stiffness);
        set(&mut v.hand_damping, self.hand_damping);
        set(&mut v.grip_length, self.grip_length);
    }
}

/// Parse a model-variant name as the command line does.
fn choice<T: clap::ValueEnum>(field: &'static str, value: &str) -> Result<T> {
    T::from_str(value.trim(), false).map_err(|_| {
        let names: Vec<String> = T::value_variants()
            .iter()
            .filter_map(|v| v.to_possible_value())
            .map(|v| v.get_name().to_string())
            .collect();
        Error::invalid(field, value, format!("must be one of: {}", names.join(", ")))
    })
}

/// The bytes of a TOML file; a file that cannot be read is an [`Error::Config`] naming it.
pub(crate) fn read_file(path: &std::path::Path) -> Result<Vec<u8>> {
    std::fs::read(path).map_err(|e| Error::Config { path: path.into(), message: e.to_string() })
}

/// Parse a TOML file's contents (`path` only names it in errors): an empty file (told what to
/// give: `empty_hint`), bytes that are not UTF-8, a syntax error, a wrong type and an unknown
/// key are all [`Error::Config`] with one line naming the file and, where TOML knows it, the
/// key and line.
pub(crate) fn parse_toml<T: serde::de::DeserializeOwned>(
    path: &std::path::Path,
    bytes: &[u8],
    empty_hint: &str,
) -> Result<T> {
    let err = |message: String| Error::Config { path: path.into(), message };
    let text = std::str::from_utf8(bytes).map_err(|_| err("not a UTF-8 text file".into()))?;
    if text.trim().is_empty() {
        return Err(err(format!("is empty ({empty_hint})")));
    }
    toml::from_str(text).map_err(|e| err(one_line(&e.to_string())))
}

/// Fold a multi-line message (e.g. a TOML parse error with a source excerpt) into one line.
fn one_line(msg: &str) -> String {
    msg.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.chars().all(|c| "|^ ".contains(c)))
        .collect::<Vec<_>>()
        .join("; ")
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

#[cfg(test)]
mod override_tests {
    use super::*;

    #[test]
    fn config_keys_are_the_flag_names_and_unknown_keys_are_rejected() {
        let o: Overrides = toml::from_str("x = 0.2\nhalf-width = 0.1\nload = \"node\"").unwrap();
        assert_eq!(o.x, Some(0.2));
        assert_eq!(o.half_width, Some(0.1));
        assert_eq!(o.load, Some(LoadRule::Node));
        assert!(toml::from_str::<Overrides>("xx = 0.2").is_err());
    }

    #[test]
    fn flags_override_the_config() {
        let flags = Overrides { ks: Some(2.0e4), ..Default::default() };
        let config = Overrides { ks: Some(3.0e4), x: Some(0.3), ..Default::default() };
        let mut p = Params::default();
        flags.or(config).apply(&mut p);
        assert_eq!((p.strings.ks, p.impact.x), (2.0e4, 0.3));
    }
}
