//! The racket file: a spec sheet's numbers, each key carrying its unit (see [`super`] for the
//! format and the conversions), their allowed ranges, and parsing.

use std::path::Path;

use serde::Deserialize;

use crate::error::Result;
use crate::params;

/// Distance of the swingweight axis from the butt, m (the usual swingweight machine's axis).
pub const SWING_AXIS_FROM_BUTT_M: f64 = 0.10;
/// Handle length used for the handle-start knot when `handle_length_cm` is absent, cm (about
/// 7.5 in: a typical tennis grip; an assumption, measure your own frame).
pub const DEFAULT_HANDLE_LENGTH_CM: f64 = 19.0;
/// Head-end knot as a fraction of the length when no head outline is given (a 100 sq in head,
/// 33 cm long, on a 68.6 cm frame).
pub const DEFAULT_HEAD_END_FRACTION: f64 = 0.48;
/// Usual range of a frame's linear density as a multiple of its mean `M / L` (min, max); a
/// fitted density outside it gets a warning. A judgement, stated as such: a real frame's
/// lightest section, the throat's open arms, carries roughly half the mean (a 300 g, 68.6 cm
/// frame: about 2-3 g/cm of a 4.4 g/cm mean), its heaviest, the butt with the grip and butt cap
/// or the hoop's tip with the bumper guard, about twice; a quarter and four times the mean are
/// well beyond that, where the fit has had to squeeze the mass into an end (or the sheet's
/// numbers do not belong together).
pub const PLAUSIBLE_DENSITY: (f64, f64) = (0.25, 4.0);
/// Head aspect (string-face length / width) taken when a file gives `head_size_sq_in` without
/// `head_aspect`: 1.35, the proportion of the largest string face the rules allow, 15.5 in long
/// by 11.5 in wide (ITF Rules of Tennis, Appendix I; quoted e.g. by BBC Sport, "Rules and
/// equipment: racquets"). An assumption about the shape, not a measurement: a 100 sq in head
/// becomes 33.3 cm by 24.7 cm, close to the 33 cm by 25 cm of common mid-plus string beds.
pub const DEFAULT_HEAD_ASPECT: f64 = 1.35;
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
    /// Head length / head width (with [`Self::head_size_sq_in`]); absent = [`DEFAULT_HEAD_ASPECT`].
    pub head_aspect: Option<f64>,
    /// Length of the handle, cm (where the stiffness profile's handle knot sits); default
    /// [`DEFAULT_HANDLE_LENGTH_CM`].
    pub handle_length_cm: Option<f64>,
    /// Reference (stringing-machine) tension, lb.
    pub tension_lb: Option<f64>,
    /// Reference tension, kilograms-force.
    pub tension_kg: Option<f64>,
    /// String-plane stiffness `k_s`, N/m.
    pub string_bed_n_per_m: Option<f64>,
    /// Dynamic-tension meter reading, kp/cm, taken as `k_s` directly (an assumption).
    pub dt_kp_cm: Option<f64>,
    /// Coefficient of friction of a ball on these strings, for oblique impacts (0..=2); absent =
    /// the default of `--mu` (SPEC.md section 6).
    pub mu: Option<f64>,
    /// The string, by its name in data/strings (`--string`): sets the friction coefficients
    /// the string table gives; absent = none.
    pub string: Option<String>,
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

impl RacketSpec {
    /// Read and check a racket file.
    pub fn from_toml_file(path: &Path) -> Result<Self> {
        // (the TOML reading is the config files'; its errors name a racket file here)
        let as_racket = |e: crate::Error| match e {
            crate::Error::Config { path, message } => crate::Error::RacketFile { path, message },
            other => other,
        };
        Self::from_toml_bytes(path, &params::read_file(path).map_err(as_racket)?).map_err(as_racket)
    }

    /// Parse and check the contents of a racket file (`path` only names it in errors). An empty
    /// file, non-UTF-8 bytes, a TOML syntax error, a wrong type and an unknown key are
    /// [`Error::Config`](crate::Error::Config) with one line naming the key and line; a missing, doubled or
    /// out-of-range value is [`Error::InvalidParameter`](crate::Error::InvalidParameter) naming the key ([`Self::validate`]).
    /// Whether a balance and swingweight can be realised is checked by [`Self::to_racket`].
    pub fn from_toml_bytes(path: &Path, bytes: &[u8]) -> Result<Self> {
        let spec: RacketSpec =
            params::parse_toml(path, bytes, "give at least length_cm, mass_g, twistweight_kg_cm2, frequency_hz")?;
        if let Some(name) = spec.name.as_deref().filter(|n| n.chars().any(char::is_control)) {
            return Err(crate::Error::invalid(
                "name",
                format!("{name:?}"),
                "a racket's name labels rows and tables: one line of text, without line breaks or control characters",
            ));
        }
        spec.validate().map_err(|e| match e {
            several @ crate::Error::Several(_) => {
                crate::Error::Config { path: path.into(), message: several.to_string() }
            }
            other => other,
        })?;
        Ok(spec)
    }

    /// Check every key against its range and every group of alternatives.
    pub fn validate(&self) -> Result<()> {
        self.resolve().map(|_| ())
    }
}
