//! Oblique incidence, spin and friction (SPEC.md section 6; beyond the paper). The defaults are
//! the paper's normal incidence without spin, so a parameter set that does not mention them is
//! the paper's impact.

use serde::{Deserialize, Serialize};

pub use super::drop_test::{kdyn_from_drop, BALL_KDYN};
use super::keys;
use super::{StringName, TangentialLaw};
use crate::error::{Error, Result};

/// How the ball arrives when it does not arrive along the string-plane normal, and the
/// tangential contact that then acts.
///
/// Default friction and stiffness: `mu = 0.4`, the low end of the ball-on-string friction
/// coefficients 0.39-0.78 of polyester strings in the Tennis Warehouse University string
/// database (data/measured, rows M076-M078); `k_t` = [`KT`], calibrated on the calibration rows
/// of data/measured (no measurement of it was found); `R = 33 mm` and
/// `alpha = 0.55` are the usual tennis-ball values (ITF diameter 6.54-6.86 cm; a thin rubber
/// shell of finite thickness lies between a solid sphere's 0.4 and a thin shell's 2/3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Oblique {
    /// Incidence angle from the string-plane normal, degrees; 0..=85.
    pub angle_deg: f64,
    /// Direction of the incoming velocity in the string plane, degrees from the long axis
    /// towards the handle (90 = across the face towards +r); -360..=360.
    pub azimuth_deg: f64,
    /// Incoming spin about the in-plane axis perpendicular to the incoming direction, rpm;
    /// topspin positive (the contact point moves slower than the centre); |spin| <= 2e4.
    pub spin_rpm: f64,
    /// Coefficient of friction of ball on strings; 0..=2.
    pub mu: f64,
    /// The ratio of the ball's sliding friction on the strings during an impact to the
    /// coefficient in use (`mu`, or the named string's TWU database COF: a slow pull of felt
    /// over a string, not a friction during a 5 ms impact); 0.05..=3. Default 1 (the tabulated
    /// coefficient as it is). A constant of the impact, the same for every string: the only
    /// friction a calibration may fit (`racket-impact calibrate --fit mu-scale`), since a
    /// string's own coefficient is measured.
    pub mu_scale: f64,
    /// Tangential stiffness of ball and string bed in series, N/m; 1..=1e9.
    pub kt: f64,
    /// Ball radius `R`, m; 1e-3..=1.
    pub ball_radius: f64,
    /// Ball moment of inertia over `m_b R^2` (`alpha`);
    /// [`MIN_BALL_INERTIA_FACTOR`]..=[`MAX_BALL_INERTIA_FACTOR`]. Default 0.55, a tennis ball
    /// (a hollow rubber shell with felt: between the solid sphere's 2/5 and the thin shell's
    /// 2/3).
    pub ball_inertia_factor: f64,
    /// The tangential contact law: `elastic` (the grip-slip law of `model::tangential` alone),
    /// one mechanism of `model::tangential` on top of it, or `physical` (every mechanism). Default
    /// `elastic` ([`TangentialLaw`]), chosen with [`KT`] on the calibration rows by the rule of
    /// `study::choice` (experiment `spin_calibration`: tied with the least leave-one-string-out
    /// error, and the cheapest of the tied).
    pub tangential: TangentialLaw,
    /// String-to-string friction coefficient (mechanism `bed`); 0..=2. Default 0.08: the
    /// middle of the string-to-string COFs of the polyester strings in the TWU string database
    /// (0.057-0.21, most 0.07-0.10; data/strings/README.md); `--string` sets the value of the
    /// string in use.
    pub mu_ss: f64,
    /// The string in use (data/strings): its friction coefficients replace `mu` and `mu_ss`
    /// ([`Oblique::friction`]).
    pub string: StringName,
    /// The ball's tangential coefficient of restitution in a gripping bounce, `e_x` (mechanism
    /// `loss`); 0 < e_x < 1. Default 0.135: the middle of the 0.10-0.17 measured for gripping
    /// tennis-ball bounces (Cross 2002, Table III; data/measured M079-M080). The damping of the
    /// ball's tangential spring is the one that returns `e_x` over half a grip oscillation
    /// ([`crate::model::tangential::loss`]).
    pub ball_ex: f64,
    /// The ball's dynamic compression stiffness for the contact geometry (mechanisms `radius`,
    /// the lever `R - F / k`, and `offset`, Tabor's arm from the contact circle), N/m; 1e3..=1e9.
    /// Default [`BALL_KDYN`]: the stiffness of a linear ball spring that a 100-inch drop on
    /// concrete would compress by 6 mm (data/measured M081), `k = m_b v^2 / d^2` with the paper's
    /// 57 g ball. Not the paper's `k1`, which keeps driving the normal force; since the model's
    /// peak force at that drop (k1 law, about 292 N) is below the linear spring's `m v^2 / d`
    /// (473 N), the mechanisms compute about 3.7 mm there (measured 6) and about 2.8 mm on 60 lb
    /// strings (measured about 3): see [`crate::model::tangential::radius`].
    pub ball_kdyn: f64,
}

/// The default [`Oblique::kt`], N/m: calibrated (experiment `spin_calibration`; `racket-impact
/// calibrate --fit kt` on the shipped table gives the same) on the rows data/measured marks
/// `role = calibration` (the TWU table's Tonic Gut, ALU Power and NRG2 at 52 and 62 lb,
/// M001-M004 and M011-M012, at the rows' 40 deg) under the default law, which was chosen on
/// those rows by the rule of `study::choice`: 5.00e5 N/m (3 significant digits of the fit), its
/// 95 % profile-likelihood interval from about 3.32e5 N/m to the end of the range searched, 1e6:
/// the rows bound it from below only. No measured value was found (the ball's tangential
/// stiffness on strings is in no text read; data/measured/README.md, fourth pass); the earlier
/// estimate, 2/3 of `k1` (2e4 N/m, Mindlin's ratio for rubber with a rigid bed in series), is 25
/// times softer.
pub const KT: f64 = 5.00e5;

/// The largest ball inertia factor `I / (m_b R^2)`: 2/3, a thin hollow shell, with all its
/// mass at the radius `R` (no mass distribution within `R` has more).
pub const MAX_BALL_INERTIA_FACTOR: f64 = 2.0 / 3.0;

/// The smallest ball inertia factor accepted: 0.1, a ball whose whole mass is in a uniform core
/// of half its radius (`0.4 / 4`). No sports ball is that centre-heavy (solid balls are near
/// the uniform sphere's 0.4, hollow ones above it); below it the spin's time scale
/// `sqrt(alpha m_b / k_t)` shrinks without bound and the tangential contact needs ever more
/// steps (a factor of 1e-30 never finished) for a ball that cannot exist.
pub const MIN_BALL_INERTIA_FACTOR: f64 = 0.1;

impl Default for Oblique {
    fn default() -> Self {
        Oblique {
            angle_deg: 0.0,
            azimuth_deg: 0.0,
            spin_rpm: 0.0,
            mu: 0.4,
            mu_scale: 1.0,
            kt: KT,
            ball_radius: 0.033,
            ball_inertia_factor: 0.55,
            tangential: TangentialLaw::Elastic,
            mu_ss: 0.08,
            string: StringName::None,
            ball_ex: 0.135,
            ball_kdyn: BALL_KDYN,
        }
    }
}

impl Oblique {
    /// Whether this is the paper's normal incidence without spin (the tangential contact then
    /// carries no force and is not computed).
    pub fn is_normal(&self) -> bool {
        self.angle_deg == 0.0 && self.spin_rpm == 0.0
    }

    /// The ball/string and string/string friction coefficients in use: the named string's
    /// (every string of the table has both), else `mu` and `mu_ss`.
    pub fn friction(&self) -> (f64, f64) {
        let entry = super::strings::entry(self.string);
        entry.map_or((self.mu, self.mu_ss), |e| (e.mu, e.mu_ss))
    }

    /// The ball/string friction coefficient of the sliding ball during an impact: the one in
    /// use ([`Oblique::friction`]) times [`Oblique::mu_scale`].
    pub fn sliding_mu(&self) -> f64 {
        self.friction().0 * self.mu_scale
    }

    /// Whether every field has its default value.
    pub fn is_default(&self) -> bool {
        *self == Oblique::default()
    }

    /// Check every field against the range of its declaration ([`keys`]).
    pub fn validate(&self) -> Result<()> {
        for (spec, v) in [
            (keys::ANGLE_DEG, self.angle_deg),
            (keys::AZIMUTH_DEG, self.azimuth_deg),
            (keys::SPIN_RPM, self.spin_rpm),
            (keys::MU, self.mu),
            (keys::MU_SCALE, self.mu_scale),
            (keys::KT, self.kt),
            (keys::BALL_RADIUS, self.ball_radius),
            (keys::MU_SS, self.mu_ss),
            (keys::BALL_EX, self.ball_ex),
            (keys::BALL_KDYN, self.ball_kdyn),
        ] {
            spec.check(v)?;
        }
        let alpha = self.ball_inertia_factor;
        if !(alpha.is_finite() && (MIN_BALL_INERTIA_FACTOR..=MAX_BALL_INERTIA_FACTOR).contains(&alpha)) {
            let key = keys::BALL_INERTIA_FACTOR.key;
            return Err(Error::invalid(
                key,
                alpha,
                format!(
                    "ball inertia factor I / (m_b R^2) must satisfy 0.1 <= {key} <= 2/3 (a thin hollow shell, the \
                     most any ball of radius R has, is 2/3; a solid sphere 0.4; a tennis ball about 0.55)"
                ),
            ));
        }
        Ok(())
    }
}
