//! A racket description in the units of a spec sheet, fitted to the model's [`Racket`].
//!
//! A [`RacketSpec`] is a TOML file (or a built-in preset, [`preset_names`]) whose keys carry
//! their unit in the name. [`RacketSpec::to_racket`] turns it into the model's parameters for a
//! beam of `N` segments and reports how well the discrete model reproduces each stated number
//! ([`FitReport`]).
//!
//! ```toml
//! name = "my frame"
//! length_in = 27                 # or length_cm
//! mass_g = 305                   # strung
//! balance_cm = 33.0              # from the butt; or balance_pts_hl = 4
//! swingweight_kg_cm2 = 305       # about the axis 10 cm from the butt
//! twistweight_kg_cm2 = 14.5      # about the long axis
//! frequency_hz = 150             # free-free first bending; or ei_n_m2 = 150
//! stiffness_ratio = [1.0, 1.4, 1.4, 1.2]    # optional EI shape at tip, head end, handle start, butt
//! head_size_sq_in = 100          # with head_aspect; or head_length_cm + head_width_cm
//! head_aspect = 1.30
//! handle_length_cm = 19          # optional
//! tension_lb = 55                # or tension_kg, string_bed_n_per_m, dt_kp_cm; default 4e4 N/m
//! [ball]                         # optional; defaults are the paper's ball
//! mass_g = 57
//! k1_n_per_m = 3e4
//! p = 2.55
//! ```
//!
//! ## Conversions and the assumptions behind them
//! ```text
//! length      L = length_cm / 100 m,  or  L = 0.0254 length_in m
//! mass        M = mass_g / 1000 kg, the STRUNG mass: the model's strings are massless
//!             (Eq 2), so the strings, grip and bumper are lumped into the frame's density
//! balance     b = balance_cm (from the butt),  or  b = L/2 - balance_pts_hl * 1/8 in
//!             (1 point = 3.175 mm head-light; negative = head-heavy); x_cm = L - b from the tip
//! swingweight SW = sum_i m_i (x_a - x_i)^2 on the discrete beam, x_a = L - 10 cm (the usual
//!             swingweight machine axis); kg cm^2 / 1e4 = kg m^2
//! twistweight I_x = twistweight_kg_cm2 / 1e4 kg m^2 (Eq 7's rigid twist about the long axis)
//! stiffness   EI(x) = ei * stiffness_ratio(x/L); with frequency_hz, ei is scaled so that the
//!             discrete beam's first free-free bending frequency equals it at N (omega^2 is
//!             proportional to ei at fixed masses; exact to the eigen solver's rounding, about
//!             1e-9 relative at N = 160); with ei_n_m2, ei is taken as is
//! head        string face = ellipse from the tip, length l along and width w across the
//!             racket; from head_size_sq_in = A and head_aspect = a = l/w:
//!             A = pi/4 l w  =>  w = sqrt(4 A / (pi a)), l = a w   (1 sq in = 6.4516 cm^2).
//!             The quoted head size is the strung area; its ellipse is placed at the tip,
//!             ignoring the frame's thickness there. No head keys: the paper's strip over the
//!             whole length with half-width 0.125 m.
//! strings     k_s = 4e4 N/m * T / 60 lb (SPEC.md section 3: k_s proportional to tension);
//!             tension_kg is kilograms-force, T = tension_kg / 0.45359237 lb;
//!             string_bed_n_per_m is k_s directly; dt_kp_cm (a stringing-shop "dynamic
//!             tension" meter, 1 kp/cm = 980.665 N/m) is TAKEN AS k_s DIRECTLY. That is an
//!             assumption: DT is measured on a clamped frame with the meter's own load, not the
//!             model's string-plane constant; typical DT values of 30-40 kp/cm (2.9-3.9e4 N/m)
//!             are at least of the paper's order (4e4 N/m at 60 lb).
//!             None of them: the paper's k_s = 4e4 N/m.
//! frame flex  RA ratings (a clamped-handle static deflection index) have no published
//!             conversion to EI, so they are not accepted: give frequency_hz (measure it by
//!             tapping a loosely hung racket) or ei_n_m2.
//! ```
//!
//! ## Mass distribution
//! Without balance and swingweight the racket is the paper's uniform beam (no profile). With
//! them the linear density is piecewise linear over the knots `[0, head end, handle start, L]`
//! (head end = the head length, or 48 % of L without head keys, as a 100 sq in head is 33 cm of
//! a 68.6 cm frame; handle start = L - handle_length_cm, default [`DEFAULT_HANDLE_LENGTH_CM`])
//! and constant along the handle. Its three knot values are the unique solution of the 3x3
//! linear system that makes the DISCRETE beam's mass, first moment (balance) and swingweight
//! equal the targets; the node masses are linear in the knot values, so this is exact. A
//! solution with a density <= 0 means the combination cannot be realised by such a profile,
//! and is an error that gives the realisable range.
//!
//! The fit is for the `N` it is given: the same racket on another `N` reproduces the targets
//! only to the discretisation error (O(N^-2)).
//!
//! ## Sources of the presets' typical values
//! The modern presets (`light`, `tweener`, `players`) are round typical numbers, not any
//! frame's data, chosen inside commonly quoted ranges: strung mass about 255-340 g, lighter
//! frames balanced head-heavy and heavier ones head-light, 1 balance point = 1/8 in (retailers'
//! guides, e.g. Tennis Warehouse University, C. Lindsey, "Weight, balance and swingweight";
//! Tennis Express, "Racquet information"); swingweights of about 300-340 kg cm^2 for adult
//! frames and twistweights of about 13-16 kg cm^2 (racket guides; H. Brody, "A new twist on the
//! twistweight", Tennis Industry, 2005, explains the quantity); head sizes of 95-110 sq in on
//! 27 in frames; free-free frequencies of composite frames above the < 120 Hz of wooden ones
//! (L. Taraborrelli et al., "Materials have driven the historical development of the tennis
//! racket", Appl. Sci. 9 (2019) 4352), taken here as 135-160 Hz. The three-knot density cannot
//! realise every measured frame: at a given balance it reaches a limited swingweight range
//! (the error says which), and the presets' swingweights sit inside it. Each preset file
//! states its values.

use std::fmt;
use std::path::Path;

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use serde::Deserialize;

use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::params::{self, Ball, Profile, Racket, Strings};
use crate::table::{fmt_sig, Table, Value};

/// Distance of the swingweight axis from the butt, m (the usual swingweight machine's axis).
pub const SWING_AXIS_FROM_BUTT_M: f64 = 0.10;
/// Handle length used for the handle-start knot when `handle_length_cm` is absent, cm (about
/// 7.5 in: a typical tennis grip; an assumption, measure your own frame).
pub const DEFAULT_HANDLE_LENGTH_CM: f64 = 19.0;
/// Head-end knot as a fraction of the length when no head outline is given (a 100 sq in head,
/// 33 cm long, on a 68.6 cm frame).
pub const DEFAULT_HEAD_END_FRACTION: f64 = 0.48;
/// One kilopond per centimetre, N/m.
pub const KP_PER_CM: f64 = 980.665;
/// One balance point (1/8 inch), cm.
pub const BALANCE_POINT_CM: f64 = 0.3175;
/// One pound, kg (so a tension in kilograms-force is `kg / LB_KG` pounds).
pub const LB_KG: f64 = 0.45359237;
/// One square inch, cm^2.
pub const SQ_IN_CM2: f64 = 6.4516;

/// A racket as printed on a spec sheet. Every key carries its unit; of each group of
/// alternatives exactly one is required (length, stiffness) or at most one is allowed (balance,
/// head, strings). Allowed ranges are in [`ranges`].
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RacketSpec {
    /// Free text naming the racket.
    pub name: Option<String>,
    /// Length, inches; or [`Self::length_cm`].
    pub length_in: Option<f64>,
    /// Length, cm.
    pub length_cm: Option<f64>,
    /// Strung mass (frame, strings, grip), g. Required.
    pub mass_g: Option<f64>,
    /// Balance point from the butt, cm; or [`Self::balance_pts_hl`]. Given together with
    /// [`Self::swingweight_kg_cm2`], or both absent (the paper's uniform beam).
    pub balance_cm: Option<f64>,
    /// Balance in points head-light (1 point = 1/8 in from the middle towards the butt;
    /// negative = head-heavy).
    pub balance_pts_hl: Option<f64>,
    /// Moment of inertia about the axis 10 cm from the butt, kg cm^2.
    pub swingweight_kg_cm2: Option<f64>,
    /// Moment of inertia about the long axis (the model's `I_x`), kg cm^2. Required.
    pub twistweight_kg_cm2: Option<f64>,
    /// First free-free bending frequency, Hz; or [`Self::ei_n_m2`].
    pub frequency_hz: Option<f64>,
    /// Bending stiffness EI (the paper's parameter), N m^2.
    pub ei_n_m2: Option<f64>,
    /// Relative EI at [tip, head end, handle start, butt], piecewise linear; default all 1.
    pub stiffness_ratio: Option<[f64; 4]>,
    /// Length of the string face along the racket, cm (with [`Self::head_width_cm`]).
    pub head_length_cm: Option<f64>,
    /// Width of the string face, cm (with [`Self::head_length_cm`]).
    pub head_width_cm: Option<f64>,
    /// Strung area, sq in (with [`Self::head_aspect`]).
    pub head_size_sq_in: Option<f64>,
    /// Head length / head width (with [`Self::head_size_sq_in`]).
    pub head_aspect: Option<f64>,
    /// Length of the constant-density handle, cm; default [`DEFAULT_HANDLE_LENGTH_CM`].
    pub handle_length_cm: Option<f64>,
    /// Reference (stringing-machine) tension, lb.
    pub tension_lb: Option<f64>,
    /// Reference tension, kilograms-force.
    pub tension_kg: Option<f64>,
    /// String-plane stiffness `k_s`, N/m.
    pub string_bed_n_per_m: Option<f64>,
    /// Dynamic-tension meter reading, kp/cm, taken as `k_s` directly (an assumption).
    pub dt_kp_cm: Option<f64>,
    /// The ball; absent = the paper's ball.
    pub ball: Option<BallSpec>,
}

/// The ball in spec-sheet units; every key optional, defaults = the paper's ball.
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BallSpec {
    /// Ball mass, g; default 57.
    pub mass_g: Option<f64>,
    /// Compression stiffness `k1` (Eq 3), N/m; default 3e4.
    pub k1_n_per_m: Option<f64>,
    /// Hysteresis exponent `p` (Eq 4), 1 < p <= 10; default 2.55.
    pub p: Option<f64>,
}

/// Allowed ranges (min, max) of the spec keys, in the keys' units: wide enough for tennis
/// (junior to extended), squash and badminton rackets.
pub mod ranges {
    /// Length, cm.
    pub const LENGTH_CM: (f64, f64) = (30.0, 100.0);
    /// Length, in.
    pub const LENGTH_IN: (f64, f64) = (12.0, 40.0);
    /// Strung mass, g.
    pub const MASS_G: (f64, f64) = (20.0, 1000.0);
    /// Balance in points head-light (the point must also lie on the racket).
    pub const BALANCE_PTS: (f64, f64) = (-150.0, 150.0);
    /// Swingweight, kg cm^2.
    pub const SWINGWEIGHT: (f64, f64) = (1.0, 2000.0);
    /// Twistweight, kg cm^2.
    pub const TWISTWEIGHT: (f64, f64) = (0.1, 100.0);
    /// Free-free first bending frequency, Hz.
    pub const FREQUENCY_HZ: (f64, f64) = (20.0, 1000.0);
    /// Bending stiffness, N m^2.
    pub const EI: (f64, f64) = (0.1, 1.0e5);
    /// Relative stiffness at a knot.
    pub const STIFFNESS_RATIO: (f64, f64) = (0.01, 100.0);
    /// Head length and width, cm.
    pub const HEAD_CM: (f64, f64) = (5.0, 60.0);
    /// Head size, sq in.
    pub const HEAD_SQ_IN: (f64, f64) = (10.0, 300.0);
    /// Head aspect ratio (length / width).
    pub const HEAD_ASPECT: (f64, f64) = (0.5, 3.0);
    /// Handle length, cm.
    pub const HANDLE_CM: (f64, f64) = (1.0, 60.0);
    /// Tension, lb.
    pub const TENSION_LB: (f64, f64) = (5.0, 120.0);
    /// Tension, kilograms-force.
    pub const TENSION_KG: (f64, f64) = (2.0, 55.0);
    /// String-plane stiffness, N/m.
    pub const STRING_BED: (f64, f64) = (100.0, 1.0e7);
    /// Dynamic tension, kp/cm.
    pub const DT_KP_CM: (f64, f64) = (1.0, 200.0);
    /// Ball mass, g.
    pub const BALL_MASS_G: (f64, f64) = (1.0, 1000.0);
    /// Ball compression stiffness, N/m.
    pub const BALL_K1: (f64, f64) = (10.0, 1.0e8);
}

/// The model's parameters fitted to a [`RacketSpec`], with the report of the fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    /// The racket (SI units).
    pub racket: Racket,
    /// The string bed.
    pub strings: Strings,
    /// The ball.
    pub ball: Ball,
    /// Targets beside what the discrete model has.
    pub report: FitReport,
}

impl Fitted {
    /// Full impact parameters: this racket, strings and ball with the given impact and
    /// numerics (use the same `segments` as the fit for an exact match of the targets).
    pub fn params(&self, impact: params::Impact, numerics: params::Numerics) -> params::Params {
        params::Params {
            ball: self.ball,
            strings: self.strings,
            racket: self.racket,
            impact,
            numerics,
            variants: Default::default(),
        }
    }
}

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

/// How the frame stiffness is given.
#[derive(Debug, Clone, Copy)]
enum Stiffness {
    Frequency(f64),
    Ei(f64),
}

/// Balance (from the tip, m), swingweight (kg m^2) and the key the balance was given as.
#[derive(Debug, Clone, Copy)]
struct Shape {
    x_cm: f64,
    swingweight: f64,
    /// The swingweight as given, kg cm^2.
    sw_given: f64,
    balance_key: &'static str,
    /// The balance as given, in its key's unit.
    balance_given: f64,
    /// The balance from the butt, cm.
    balance_cm: f64,
}

/// A checked spec in SI units.
#[derive(Debug, Clone, Copy)]
struct Resolved {
    length: f64,
    mass: f64,
    shape: Option<Shape>,
    ix: f64,
    stiffness: Stiffness,
    ratio: [f64; 4],
    head: Option<(f64, f64)>,
    knots: [f64; 4],
    ks: f64,
    ball: Ball,
}

/// `v` within `lo..=hi`, else an error naming the key, the allowed range and the unit.
fn check(key: &'static str, v: f64, what: &str, unit: &str, (lo, hi): (f64, f64)) -> Result<f64> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(Error::invalid(key, v, format!("{what} must satisfy {lo} <= {key} <= {hi} {unit}")))
    }
}

/// At most one of a group of alternative keys; `label` names the group in errors.
fn one_of<T: Copy>(label: &'static str, keys: &[(&'static str, Option<T>)]) -> Result<Option<(&'static str, T)>> {
    let given: Vec<_> = keys.iter().filter_map(|(k, v)| v.map(|v| (*k, v))).collect();
    match given.as_slice() {
        [] => Ok(None),
        [one] => Ok(Some(*one)),
        _ => {
            let names: Vec<&str> = keys.iter().map(|(k, _)| *k).collect();
            Err(Error::invalid(label, "(several given)", format!("give only one of {}", names.join(", "))))
        }
    }
}

/// Exactly one of a group of alternative keys.
fn required<T: Copy>(label: &'static str, keys: &[(&'static str, Option<T>)]) -> Result<(&'static str, T)> {
    one_of(label, keys)?.ok_or_else(|| {
        let names: Vec<&str> = keys.iter().map(|(k, _)| *k).collect();
        Error::invalid(label, "(missing)", format!("give exactly one of {}", names.join(", ")))
    })
}

impl RacketSpec {
    /// Read and check a racket file.
    pub fn from_toml_file(path: &Path) -> Result<Self> {
        Self::from_toml_bytes(path, &params::read_file(path)?)
    }

    /// Parse and check the contents of a racket file (`path` only names it in errors). An empty
    /// file, non-UTF-8 bytes, a TOML syntax error, a wrong type and an unknown key are
    /// [`Error::Config`] with one line naming the key and line; a missing, doubled or
    /// out-of-range value is [`Error::InvalidParameter`] naming the key ([`Self::validate`]).
    /// Whether a balance and swingweight can be realised is checked by [`Self::to_racket`].
    pub fn from_toml_bytes(path: &Path, bytes: &[u8]) -> Result<Self> {
        let spec: RacketSpec =
            params::parse_toml(path, bytes, "give at least length_cm, mass_g, twistweight_kg_cm2, frequency_hz")?;
        spec.validate()?;
        Ok(spec)
    }

    /// Check every key against its range and every group of alternatives.
    pub fn validate(&self) -> Result<()> {
        self.resolve().map(|_| ())
    }

    fn resolve(&self) -> Result<Resolved> {
        use ranges::*;
        let length_cm =
            match required("length_in/length_cm", &[("length_in", self.length_in), ("length_cm", self.length_cm)])? {
                ("length_in", v) => check("length_in", v, "racket length", "in", LENGTH_IN)? * 2.54,
                (_, v) => check("length_cm", v, "racket length", "cm", LENGTH_CM)?,
            };
        let length = length_cm / 100.0;
        let mass_g = self.mass_g.ok_or_else(|| Error::invalid("mass_g", "(missing)", "give the strung mass in g"))?;
        let mass = check("mass_g", mass_g, "strung mass", "g", MASS_G)? / 1000.0;

        let balance = one_of(
            "balance_cm/balance_pts_hl",
            &[("balance_cm", self.balance_cm), ("balance_pts_hl", self.balance_pts_hl)],
        )?;
        let shape = match (balance, self.swingweight_kg_cm2) {
            (None, None) => None,
            (Some((key, _)), None) => {
                return Err(Error::invalid(
                    "swingweight_kg_cm2",
                    "(missing)",
                    format!("{key} needs swingweight_kg_cm2 (give both, or neither for the paper's uniform beam)"),
                ))
            }
            (None, Some(_)) => {
                return Err(Error::invalid(
                    "balance_cm/balance_pts_hl",
                    "(missing)",
                    "swingweight_kg_cm2 needs a balance (give both, or neither for the paper's uniform beam)",
                ))
            }
            (Some((key, b)), Some(sw)) => {
                let (balance_key, balance_cm) = if key == "balance_cm" {
                    ("balance_cm", b)
                } else {
                    let pts = check("balance_pts_hl", b, "balance", "points head-light", BALANCE_PTS)?;
                    ("balance_pts_hl", 0.5 * length_cm - pts * BALANCE_POINT_CM)
                };
                if !(balance_cm.is_finite() && balance_cm > 0.0 && balance_cm < length_cm) {
                    return Err(Error::invalid(
                        balance_key,
                        b,
                        format!("the balance point must lie on the racket, 0 < balance < {length_cm} cm from the butt"),
                    ));
                }
                let sw = check("swingweight_kg_cm2", sw, "swingweight", "kg cm^2", SWINGWEIGHT)?;
                Some(Shape {
                    x_cm: length - balance_cm / 100.0,
                    swingweight: sw / 1.0e4,
                    sw_given: sw,
                    balance_key,
                    balance_given: b,
                    balance_cm,
                })
            }
        };
        let tw = self.twistweight_kg_cm2.ok_or_else(|| {
            Error::invalid("twistweight_kg_cm2", "(missing)", "give the twistweight (moment about the long axis)")
        })?;
        let ix = check("twistweight_kg_cm2", tw, "twistweight", "kg cm^2", TWISTWEIGHT)? / 1.0e4;

        let stiffness = match required(
            "frequency_hz/ei_n_m2",
            &[("frequency_hz", self.frequency_hz), ("ei_n_m2", self.ei_n_m2)],
        )? {
            ("frequency_hz", f) => {
                Stiffness::Frequency(check("frequency_hz", f, "free-free frequency", "Hz", FREQUENCY_HZ)?)
            }
            (_, ei) => Stiffness::Ei(check("ei_n_m2", ei, "bending stiffness", "N m^2", EI)?),
        };
        let ratio = self.stiffness_ratio.unwrap_or([1.0; 4]);
        for &r in &ratio {
            check("stiffness_ratio", r, "relative stiffness at each knot", "", STIFFNESS_RATIO)?;
        }

        let head = self.head(length_cm)?;
        let head_end = head.map_or(DEFAULT_HEAD_END_FRACTION * length_cm, |(l, _)| l * 100.0);
        let handle_cm = match self.handle_length_cm {
            Some(h) => check("handle_length_cm", h, "handle length", "cm", HANDLE_CM)?,
            None => DEFAULT_HANDLE_LENGTH_CM,
        };
        if head_end + handle_cm >= length_cm {
            return Err(Error::invalid(
                "handle_length_cm",
                handle_cm,
                format!(
                    "the head end ({} cm from the tip{}) and the handle must leave a throat: head + handle < length = {} cm",
                    fmt_sig(head_end, 4),
                    if head.is_some() { "" } else { ", by default 48 % of the length" },
                    fmt_sig(length_cm, 4)
                ),
            ));
        }
        let knots = [0.0, head_end / length_cm, 1.0 - handle_cm / length_cm, 1.0];

        let tension = one_of(
            "tension_lb/tension_kg/string_bed_n_per_m/dt_kp_cm",
            &[
                ("tension_lb", self.tension_lb),
                ("tension_kg", self.tension_kg),
                ("string_bed_n_per_m", self.string_bed_n_per_m),
                ("dt_kp_cm", self.dt_kp_cm),
            ],
        )?;
        let ks = match tension {
            None => Strings::default().ks,
            Some(("tension_lb", t)) => params::ks_from_tension_lb(check("tension_lb", t, "tension", "lb", TENSION_LB)?),
            Some(("tension_kg", t)) => {
                params::ks_from_tension_lb(check("tension_kg", t, "tension", "kg", TENSION_KG)? / LB_KG)
            }
            Some(("string_bed_n_per_m", k)) => {
                check("string_bed_n_per_m", k, "string-bed stiffness", "N/m", STRING_BED)?
            }
            Some((_, dt)) => check("dt_kp_cm", dt, "dynamic tension", "kp/cm", DT_KP_CM)? * KP_PER_CM,
        };

        let mut ball = Ball::default();
        if let Some(b) = &self.ball {
            if let Some(m) = b.mass_g {
                ball.mass = check("ball.mass_g", m, "ball mass", "g", BALL_MASS_G)? / 1000.0;
            }
            if let Some(k1) = b.k1_n_per_m {
                ball.k1 = check("ball.k1_n_per_m", k1, "ball compression stiffness", "N/m", BALL_K1)?;
            }
            if let Some(p) = b.p {
                if !(p.is_finite() && p > 1.0 && p <= 10.0) {
                    return Err(Error::invalid("ball.p", p, "hysteresis exponent must satisfy 1 < p <= 10"));
                }
                ball.p = p;
            }
        }
        Ok(Resolved { length, mass, shape, ix, stiffness, ratio, head, knots, ks, ball })
    }

    /// The string face as (length, half-width) in m, if any head keys are given.
    fn head(&self, length_cm: f64) -> Result<Option<(f64, f64)>> {
        use ranges::*;
        let by_size = self.head_length_cm.is_some() || self.head_width_cm.is_some();
        let by_area = self.head_size_sq_in.is_some() || self.head_aspect.is_some();
        let (l_cm, w_cm) = match (by_size, by_area) {
            (false, false) => return Ok(None),
            (true, true) => {
                return Err(Error::invalid(
                    "head_length_cm/head_size_sq_in",
                    "(several given)",
                    "give either head_length_cm with head_width_cm, or head_size_sq_in with head_aspect",
                ))
            }
            (true, false) => {
                let (Some(l), Some(w)) = (self.head_length_cm, self.head_width_cm) else {
                    let missing = if self.head_length_cm.is_none() { "head_length_cm" } else { "head_width_cm" };
                    return Err(Error::invalid(missing, "(missing)", "head_length_cm and head_width_cm go together"));
                };
                (
                    check("head_length_cm", l, "head length", "cm", HEAD_CM)?,
                    check("head_width_cm", w, "head width", "cm", HEAD_CM)?,
                )
            }
            (false, true) => {
                let (Some(a), Some(r)) = (self.head_size_sq_in, self.head_aspect) else {
                    let missing = if self.head_size_sq_in.is_none() { "head_size_sq_in" } else { "head_aspect" };
                    return Err(Error::invalid(missing, "(missing)", "head_size_sq_in and head_aspect go together"));
                };
                let area = check("head_size_sq_in", a, "head size", "sq in", HEAD_SQ_IN)? * SQ_IN_CM2;
                let aspect = check("head_aspect", r, "head length / width", "", HEAD_ASPECT)?;
                let w = (4.0 * area / (std::f64::consts::PI * aspect)).sqrt();
                (aspect * w, w)
            }
        };
        if l_cm >= length_cm {
            let (key, given) = match (self.head_length_cm, self.head_size_sq_in) {
                (Some(l), _) => ("head_length_cm", l),
                (_, a) => ("head_size_sq_in", a.unwrap_or(f64::NAN)),
            };
            return Err(Error::invalid(
                key,
                given,
                format!("the head ({} cm long) must be shorter than the racket ({length_cm} cm)", fmt_sig(l_cm, 4)),
            ));
        }
        Ok(Some((l_cm / 100.0, 0.5 * w_cm / 100.0)))
    }

    /// Fit the model's racket to this spec for a beam of `segments` segments: the discrete
    /// beam reproduces the mass, balance, swingweight and free-free frequency exactly (to
    /// rounding). Errors name the key that cannot be met.
    pub fn to_racket(&self, segments: usize) -> Result<Fitted> {
        params::check_segments(segments)?;
        let r = self.resolve()?;
        let (half_width, head_length) = match r.head {
            Some((l, hw)) => (hw, Some(l)),
            None => (Racket::default().half_width, None),
        };
        let mut density = [1.0; 4];
        if let Some(shape) = &r.shape {
            let d = fit_density(&r, shape, segments)?;
            density = [d[0], d[1], d[2], d[2]];
        }
        let uniform = r.shape.is_none() && r.ratio == [1.0; 4];
        let profile = (!uniform).then_some(Profile { knots: r.knots, density, stiffness: r.ratio });
        let mut racket = Racket { length: r.length, mass: r.mass, ei: 1.0, ix: r.ix, half_width, head_length, profile };
        racket.ei = match r.stiffness {
            Stiffness::Ei(ei) => ei,
            Stiffness::Frequency(f) => fit_ei(&racket, f, segments)?,
        };
        racket.validate()?;
        let strings = Strings { ks: r.ks };
        strings.validate()?;
        r.ball.validate()?;
        let report = self.report(&r, &racket, segments);
        Ok(Fitted { racket, strings, ball: r.ball, report })
    }

    fn report(&self, r: &Resolved, racket: &Racket, segments: usize) -> FitReport {
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

/// Node masses of the three basis densities (tip, head end, handle) on the discrete beam, in
/// the units of a density of 1 kg per unit of relative length: `m = L * sum_k d_k B_k` for a
/// density `d_k` (kg/m) at the knots. `Beam::new` scales its lumped masses to the racket's mass;
/// the hat functions sum to one, so the unscaled masses sum to the basis function's integral,
/// which is known exactly and undoes the scaling.
fn basis_masses(knots: [f64; 4], length: f64, segments: usize) -> ([Vec<f64>; 3], Vec<f64>) {
    let [_, k1, k2, _] = knots;
    let bases = [
        ([1.0, 0.0, 0.0, 0.0], 0.5 * k1),
        ([0.0, 1.0, 0.0, 0.0], 0.5 * k2),
        ([0.0, 0.0, 1.0, 1.0], 0.5 * (k2 - k1) + (1.0 - k2)),
    ];
    let mut x = Vec::new();
    let masses = bases.map(|(density, integral)| {
        let profile = Profile { knots, density, stiffness: [1.0; 4] };
        let racket = Racket { length, mass: 1.0, profile: Some(profile), ..Racket::default() };
        let beam = Beam::new(&racket, segments);
        x = beam.x;
        beam.mass.iter().map(|m| m * integral).collect()
    });
    (masses, x)
}

/// Knot densities (tip, head end, handle; arbitrary common scale) whose discrete beam has the
/// spec's mass, balance and swingweight; an error names balance or swingweight when no
/// positive density does.
fn fit_density(r: &Resolved, shape: &Shape, segments: usize) -> Result<[f64; 3]> {
    let (basis, x) = basis_masses(r.knots, r.length, segments);
    let x_axis = r.length - SWING_AXIS_FROM_BUTT_M;
    // moments of each basis: mass, first moment about the tip, second moment about the axis
    let moments = basis.clone().map(|m| {
        let m0: f64 = m.iter().sum();
        let m1: f64 = m.iter().zip(&x).map(|(m, x)| m * x).sum();
        let m2: f64 = m.iter().zip(&x).map(|(m, x)| m * (x_axis - x).powi(2)).sum();
        [m0, m1, m2]
    });
    let a = Matrix3::from_fn(|i, k| moments[k][i]);
    let b = Vector3::new(r.mass, r.mass * shape.x_cm, shape.swingweight);
    let d = a.lu().solve(&b);
    if let Some(d) = d.filter(|d| d.iter().all(|v| v.is_finite() && *v > 0.0)) {
        return Ok([d[0], d[1], d[2]]);
    }
    // Diagnose. With positive densities the centre of mass is a weighted mean of the bases'
    // centroids, so it must lie between them.
    let centroids = moments.map(|m| m[1] / m[0]);
    let (lo, hi) = centroids.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &c| (l.min(c), h.max(c)));
    // the stated ranges are rounded inwards, so every value they admit is accepted
    let to_butt = |x: f64, up: bool| fmt_sig(round_sig(up, (r.length - x) * 100.0, 4), 4);
    if !(shape.x_cm > lo && shape.x_cm < hi) {
        return Err(Error::invalid(
            shape.balance_key,
            shape.balance_given,
            format!(
                "no positive density (linear over head and throat, constant handle) balances there; \
                 this racket's profile reaches {} < balance < {} cm from the butt",
                to_butt(hi, true),
                to_butt(lo, false)
            ),
        ));
    }
    // At this balance the positive densities form a segment whose ends have one density 0;
    // the swingweight is linear along it, so its range is spanned by the ends.
    let mut sw_ends = Vec::new();
    for zero in 0..3 {
        let [i, j] = match zero {
            0 => [1, 2],
            1 => [0, 2],
            _ => [0, 1],
        };
        let m = Matrix2::new(moments[i][0], moments[j][0], moments[i][1], moments[j][1]);
        if let Some(c) = m.lu().solve(&Vector2::new(r.mass, r.mass * shape.x_cm)) {
            if c.iter().all(|v| v.is_finite() && *v >= 0.0) {
                sw_ends.push(c[0] * moments[i][2] + c[1] * moments[j][2]);
            }
        }
    }
    let (sw_lo, sw_hi) = sw_ends.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &s| (l.min(s), h.max(s)));
    let range = if sw_lo.is_finite() && sw_hi.is_finite() {
        let at = match shape.balance_key {
            "balance_cm" => format!("balance_cm = {}", shape.balance_given),
            key => format!("{key} = {} ({} cm from the butt)", shape.balance_given, fmt_sig(shape.balance_cm, 6)),
        };
        format!(
            "; at {at} this profile realises {} < swingweight_kg_cm2 < {} kg cm^2",
            fmt_sig(round_sig(true, sw_lo * 1.0e4, 4), 4),
            fmt_sig(round_sig(false, sw_hi * 1.0e4, 4), 4)
        )
    } else {
        String::new()
    };
    Err(Error::invalid(
        "swingweight_kg_cm2",
        shape.sw_given,
        format!(
            "this balance and swingweight cannot be realised by a positive density (linear over head and \
             throat, constant handle){range}"
        ),
    ))
}

/// The `ei` whose discrete beam has the first free-free frequency `f_hz`: `omega^2` is
/// proportional to `ei` at fixed masses, so one solve and a rescale suffice; a second pass
/// removes any rounding.
fn fit_ei(racket: &Racket, f_hz: f64, segments: usize) -> Result<f64> {
    let mut trial = Racket { ei: 100.0, ..*racket };
    for _ in 0..2 {
        let f = Beam::new(&trial, segments).modes().frequency_hz(1);
        if !(f.is_finite() && f > 0.0) {
            return Err(Error::invalid(
                "frequency_hz",
                f_hz,
                "the discrete beam has no finite fundamental frequency for this mass and length",
            ));
        }
        trial.ei *= (f_hz / f).powi(2);
    }
    let (lo, hi) = const { params::keys::EI.range() };
    if trial.ei.is_finite() && (lo..=hi).contains(&trial.ei) {
        Ok(trial.ei)
    } else {
        Err(Error::invalid(
            "frequency_hz",
            f_hz,
            format!(
                "this frequency needs EI = {} N m^2 for this mass and length, outside the model's {lo:e}..={hi:e} N m^2",
                fmt_sig(trial.ei, 4)
            ),
        ))
    }
}

const PRESETS: [(&str, &str); 5] = [
    ("paper-125hz", include_str!("../presets/paper-125hz.toml")),
    ("paper-widebody-200hz", include_str!("../presets/paper-widebody-200hz.toml")),
    ("light", include_str!("../presets/light.toml")),
    ("tweener", include_str!("../presets/tweener.toml")),
    ("players", include_str!("../presets/players.toml")),
];

const PRESET_NAMES: [&str; 5] = [PRESETS[0].0, PRESETS[1].0, PRESETS[2].0, PRESETS[3].0, PRESETS[4].0];

/// Names of the built-in racket presets (files `presets/<name>.toml`).
pub fn preset_names() -> &'static [&'static str] {
    &PRESET_NAMES
}

/// A built-in preset by name.
pub fn preset(name: &str) -> Option<RacketSpec> {
    let (_, text) = PRESETS.iter().find(|(n, _)| *n == name)?;
    toml::from_str(text).ok()
}

/// A preset by name, else a racket file at the path `arg`. Neither gives an error listing the
/// presets.
pub fn load(arg: &str) -> Result<RacketSpec> {
    if let Some(spec) = preset(arg) {
        return Ok(spec);
    }
    let path = Path::new(arg);
    if path.is_file() {
        return RacketSpec::from_toml_file(path);
    }
    Err(Error::Config {
        path: path.into(),
        message: format!("is neither a racket preset ({}) nor a file", PRESET_NAMES.join(", ")),
    })
}

/// Impact parameters for a command: the defaults (the paper's racket, ball and strings with the
/// `hat` load), replaced by the racket description when one is given (fitted at the segment
/// count the overrides ask for, else the default 39; a racket with a head outline is hit at
/// the centre of its face unless `x` and `r` say otherwise), then the config-file and flag overrides
/// (`overrides` = flags already merged over the config). Validated. Returns the fit too.
pub fn resolve(spec: Option<&RacketSpec>, overrides: &params::Overrides) -> Result<(params::Params, Option<Fitted>)> {
    let mut p = params::Params::default();
    let fitted = match spec {
        Some(spec) => {
            let f = spec.to_racket(overrides.segments.unwrap_or(p.numerics.segments))?;
            p.racket = f.racket;
            p.strings = f.strings;
            p.ball = f.ball;
            if let Some(h) = f.racket.head_length {
                // a racket with a head outline is hit, by default, at the centre of its face
                p.impact.x = 0.5 * h;
                p.impact.r = 0.0;
            }
            Some(f)
        }
        None => None,
    };
    overrides.apply(&mut p);
    p.validate()?;
    Ok((p, fitted))
}

/// `x` rounded up (or down) to `digits` significant digits.
fn round_sig(up: bool, x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let e = 10f64.powi(x.abs().log10().floor() as i32 - digits as i32 + 1);
    let r = if up { (x / e).ceil() * e } else { (x / e).floor() * e };
    // undo representation error of the product (e.g. 273.90000000000003)
    let snapped: f64 = fmt_sig(r, digits).parse().unwrap_or(r);
    snapped
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(text: &str) -> Result<RacketSpec> {
        RacketSpec::from_toml_bytes(Path::new("t.toml"), text.as_bytes())
    }

    const BASE: &str = "length_cm = 71\nmass_g = 340\ntwistweight_kg_cm2 = 15\nei_n_m2 = 150\n";

    #[test]
    fn balance_points_are_eighths_of_an_inch_from_the_middle() {
        let s = spec(&format!("{BASE}balance_pts_hl = 8\nswingweight_kg_cm2 = 340")).unwrap();
        let r = s.resolve().unwrap();
        let shape = r.shape.unwrap();
        // 8 points head-light = 1 inch towards the butt from 35.5 cm
        assert!((shape.balance_cm - (35.5 - 2.54)).abs() < 1e-12);
        assert!((shape.x_cm - (0.71 - 0.3296)).abs() < 1e-12);
    }

    #[test]
    fn tension_units_convert_to_the_spec_calibration() {
        let ks = |line: &str| spec(&format!("{BASE}{line}")).unwrap().resolve().unwrap().ks;
        assert_eq!(ks("tension_lb = 60"), 4.0e4);
        assert!((ks("tension_kg = 27.2155422") - 4.0e4).abs() < 1e-3, "60 lb is 27.2155422 kgf");
        assert_eq!(ks("string_bed_n_per_m = 3.3e4"), 3.3e4);
        assert!((ks("dt_kp_cm = 40") - 39226.6).abs() < 1e-9);
        assert_eq!(ks(""), 4.0e4);
    }

    #[test]
    fn head_size_and_aspect_give_the_ellipse_of_that_area() {
        let s = spec(&format!("{BASE}head_size_sq_in = 100\nhead_aspect = 1.3")).unwrap();
        let (l, hw) = s.resolve().unwrap().head.unwrap();
        let area_cm2 = std::f64::consts::PI / 4.0 * (l * 100.0) * (2.0 * hw * 100.0);
        assert!((area_cm2 - 645.16).abs() < 1e-9);
        assert!((l / (2.0 * hw) - 1.3).abs() < 1e-12);
    }

    #[test]
    fn groups_of_alternatives_name_their_keys() {
        let both = spec(&format!("{BASE}length_in = 28")).unwrap_err().to_string();
        assert!(both.contains("length_in/length_cm") && both.contains("only one"), "{both}");
        let none = spec("mass_g = 340\ntwistweight_kg_cm2 = 15\nei_n_m2 = 150").unwrap_err().to_string();
        assert!(none.contains("length_in/length_cm = (missing)"), "{none}");
        let half = spec(&format!("{BASE}head_length_cm = 33")).unwrap_err().to_string();
        assert!(half.contains("head_width_cm"), "{half}");
        let mixed = spec(&format!("{BASE}head_length_cm = 33\nhead_width_cm = 25\nhead_aspect = 1.3")).unwrap_err();
        assert!(mixed.to_string().contains("head_length_cm/head_size_sq_in"), "{mixed}");
    }

    #[test]
    fn the_density_fit_is_exact_on_the_discrete_beam() {
        let s =
            spec(&format!("{BASE}balance_cm = 33\nswingweight_kg_cm2 = 330\nhead_length_cm = 34\nhead_width_cm = 26"))
                .unwrap();
        for n in [8, 39, 161] {
            let rep = s.to_racket(n).unwrap().report;
            for c in [rep.mass_g, rep.balance_cm, rep.swingweight_kg_cm2] {
                assert!(c.rel_error().unwrap().abs() < 1e-12, "{n}: {c:?}");
            }
        }
    }

    #[test]
    fn an_unreachable_swingweight_reports_the_reachable_range() {
        let s = spec(&format!("{BASE}balance_cm = 33\nswingweight_kg_cm2 = 150")).unwrap();
        let msg = s.to_racket(39).unwrap_err().to_string();
        assert!(
            msg.starts_with("invalid swingweight_kg_cm2 = 150:") && msg.contains("< swingweight_kg_cm2 <"),
            "{msg}"
        );
        let s = spec(&format!("{BASE}balance_cm = 3\nswingweight_kg_cm2 = 300")).unwrap();
        let msg = s.to_racket(39).unwrap_err().to_string();
        assert!(msg.starts_with("invalid balance_cm = 3:") && msg.contains("< balance <"), "{msg}");
    }

    #[test]
    fn every_preset_parses_and_validates() {
        assert_eq!(preset_names().len(), PRESETS.len());
        for name in preset_names() {
            let s = preset(name).unwrap_or_else(|| panic!("preset {name} does not parse"));
            s.validate().unwrap();
            assert_eq!(s.name.as_deref(), Some(*name));
        }
    }
}
