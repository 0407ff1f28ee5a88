//! The physical parts of one impact: the ball, the string bed, the racket (with its optional
//! stiffness and mass profile) and the impact point and speed, each with its validation.

use serde::{Deserialize, Serialize};

use super::keys;
use super::spec::{positive, within};
use super::{drop_speed, DROP_HEIGHT_100_IN};
use crate::error::{Error, Result};
use crate::numfmt::sig;

/// Length of the string face of a racket without a head outline (the paper's), m: an ellipse
/// this long from the tip, whose centre, 16 cm from the tip, is the paper's "centre of the
/// strings" at the mode-1 node (15.8 cm in the paper, 15.9 cm on the N = 39 beam).
pub const DEFAULT_FACE_LENGTH: f64 = 0.32;

/// Allowed range (min, max) of the relative bending stiffness of a [`Profile`] knot.
pub const STIFFNESS_REL: (f64, f64) = (1.0e-3, 1.0e3);

/// The tennis ball (Eqs 1, 3, 4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ball {
    /// Ball mass `m_b`, kg; 1e-4..=10 ([`keys::MB`]). Paper: 0.057 kg. Named `mb` in JSON as
    /// on the command line (one name per quantity); `mass` is read too.
    #[serde(rename = "mb", alias = "mass")]
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
/// four knots along the racket (tip, end of the head, start of the handle, butt), the density
/// optionally tilted by `exp(t1 f + t2 f^2)` ([`Profile::tilt`]). The paper
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
    /// Relative bending stiffness at the knots; each 1e-3..=1e3 ([`STIFFNESS_REL`]).
    pub stiffness: [f64; 4],
    /// Exponential tilt `[t1, t2]` of the density: the piecewise-linear density above times
    /// `exp(t1 f + t2 f^2)` at the fraction `f` of the length from the tip; each |t| <= 100
    /// ([`TILT_MAX`]). `[0, 0]` (the default) is no tilt. The family a racket file's balance
    /// and swingweight are fitted with (the `racket` module): with a uniform base it is the
    /// least-informative (maximum-entropy) density with a given mass, balance and swingweight.
    #[serde(default, skip_serializing_if = "no_tilt")]
    pub tilt: [f64; 2],
}

/// Largest |tilt| coefficient of a [`Profile`] (a density ratio of up to e^100 along the
/// racket: far beyond any racket, a bound that keeps the exponential finite).
pub const TILT_MAX: f64 = 100.0;

/// Whether a tilt is the default `[0, 0]` (not serialised then).
fn no_tilt(t: &[f64; 2]) -> bool {
    *t == [0.0; 2]
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

    /// The relative linear density at the fraction `f` (0 = tip, 1 = butt), tilt included.
    pub fn density_at(&self, f: f64) -> f64 {
        let base = self.at(&self.density, f);
        if no_tilt(&self.tilt) {
            base
        } else {
            base * (self.tilt[0] * f + self.tilt[1] * f * f).exp()
        }
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
    /// (The command line's default point is the centre of the string face instead:
    /// [`keys::face_centre_impact`].)
    fn default() -> Self {
        Impact { x: 0.10, r: 0.05, v1: drop_speed(DROP_HEIGHT_100_IN) }
    }
}

impl Ball {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        keys::MB.check(self.mass)?;
        keys::K1.check(self.k1)?;
        if !(self.p.is_finite() && self.p > 1.0 && self.p <= 10.0) {
            return Err(Error::invalid(keys::P.key, self.p, "hysteresis exponent must satisfy 1 < p <= 10"));
        }
        Ok(())
    }
}

impl Strings {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        keys::KS.check(self.ks)
    }
}

impl Racket {
    /// Check every field against the range in its doc.
    pub fn validate(&self) -> Result<()> {
        for (spec, v) in [
            (keys::LENGTH, self.length),
            (keys::MASS, self.mass),
            (keys::EI, self.ei),
            (keys::IX, self.ix),
            (keys::HALF_WIDTH, self.half_width),
        ] {
            spec.check(v)?;
        }
        if let Some(h) = self.head_length {
            if !(h.is_finite() && h > 0.0 && h <= self.length) {
                return Err(Error::invalid(
                    "head-length",
                    h,
                    format!("string-face length must satisfy 0 < head-length <= L = {} m", sig(self.length, 6)),
                ));
            }
        }
        if let Some(p) = &self.profile {
            p.validate()?;
        }
        Ok(())
    }

    /// The centre of the string face along the racket, m from the tip: the middle of the head
    /// outline, or for a racket without one the middle of the default face
    /// ([`DEFAULT_FACE_LENGTH`], at most the racket's length): 16 cm on the paper's racket.
    pub fn face_centre(&self) -> f64 {
        0.5 * self.head_length.unwrap_or(DEFAULT_FACE_LENGTH.min(self.length))
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
            within("profile.stiffness", e, "relative bending stiffness", "at every knot", STIFFNESS_REL)?;
        }
        for &t in &self.tilt {
            within("profile.tilt", t, "density tilt coefficient", "each", (-TILT_MAX, TILT_MAX))?;
        }
        Ok(())
    }
}

impl Impact {
    /// Check the impact against the racket it hits.
    pub fn validate(&self, racket: &Racket) -> Result<()> {
        keys::X.finite(self.x)?;
        let Some(half) = racket.face_half_width(self.x) else {
            let msg = match racket.head_length {
                None => format!("impact point must lie on the racket, 0 <= x <= L = {} m", sig(racket.length, 6)),
                Some(h) => format!("impact point must lie on the string face, 0 <= x <= head-length = {} m", sig(h, 6)),
            };
            return Err(Error::invalid(keys::X.key, self.x, msg));
        };
        keys::R.finite(self.r)?;
        if self.r.abs() > half {
            let msg = match racket.head_length {
                None => {
                    format!("off-axis distance must lie on the string face, |r| <= half-width = {} m", sig(half, 6))
                }
                Some(_) => format!(
                    "off-axis distance must lie inside the head outline, |r| <= {half:.4} m at x = {} m",
                    sig(self.x, 6)
                ),
            };
            return Err(Error::invalid(keys::R.key, self.r, msg));
        }
        keys::V1.check(self.v1)
    }
}
