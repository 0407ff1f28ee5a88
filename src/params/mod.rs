//! Parameters of one impact: plain serde structs whose defaults are the paper's values
//! (SPEC.md section 3), each validated once at the boundary.
//!
//! Every field's doc gives its unit and allowed range; [`Params::validate`] returns the same
//! sentence as an [`Error::InvalidParameter`](crate::error::Error::InvalidParameter) naming the field
//! by its flag / config key.
//!
//! Each parameter a flag or a config file can set is declared once, in [`keys`]: its key,
//! help, unit, range and place in [`Params`]. [`Overrides`] (the flags and the config file),
//! its key list and the validation messages come from that declaration.
//!
//! - [`physical`]: the ball, the strings, the racket and the impact.
//! - [`numerics`]: segments, load rule, time step, solver.
//! - [`variants`]: frame model, grip, string law.
//! - [`oblique`]: incidence angle, azimuth, incoming spin, friction (beyond the paper).
//! - [`drop_test`]: the drop test the ball's values are read from (gravity, the 100-inch height, the
//!   stiffness a drop's compression implies).
//! - [`spec`] and [`keys`]: what a declaration is, and the declarations; [`choice`]: a parameter
//!   that takes one of a list of names, declared from that one list.
//! - [`overrides`]: the `--config` file.
//! - [`inputs`]: the input files a run has read (no output may replace one).
//! - [`limits`]: the most work a command accepts (sweep sizes, series rows, comparisons).
//! - [`used`]: which impacts use a parameter, from its declaration, and what a value given for
//!   one an impact does not use is told (a property noted, a method's option refused).
//! - [`uncertainty`]: the distribution and source of a parameter's uncertainty.

use serde::{Deserialize, Serialize};

use crate::error::Result;

pub mod choice;
pub mod drop_test;
pub mod inputs;
pub mod keys;
pub mod limits;
pub mod number;
pub mod numerics;
pub mod oblique;
pub mod overrides;
pub mod physical;
pub mod spec;
pub mod strings;
pub mod uncertainty;
pub mod used;
pub mod variants;

pub use drop_test::{drop_speed, DROP_HEIGHT_100_IN, G};
pub use keys::Overrides;
pub use numerics::{check_segments, LoadRule, Numerics, SolverKind, MAX_SEGMENTS, MIN_SEGMENTS};
pub use oblique::Oblique;
pub(crate) use overrides::{parse_toml, read_file};
pub use physical::{
    ellipse_half_width, Ball, Impact, Profile, Racket, Strings, DEFAULT_FACE_LENGTH, STIFFNESS_REL, TILT_MAX,
};
pub(crate) use variants::tangential_mechanisms;
pub use variants::{Frame, Grip, StringLaw, StringName, TangentialLaw, Variants};

/// Calibration of SPEC.md section 3: `k_s` is proportional to the tension, 60 lb = 4e4 N/m (ours,
/// inferred from the paper's 60 -> 50 lb arithmetic; the paper states no calibration).
pub fn ks_from_tension_lb(tension_lb: f64) -> f64 {
    4.0e4 * tension_lb / 60.0
}

/// The tension of a string bed `ks` (N/m) by the same calibration, lb (the inverse of
/// [`ks_from_tension_lb`]).
pub fn tension_lb_from_ks(ks: f64) -> f64 {
    60.0 * ks / 4.0e4
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
    /// Oblique incidence, spin and friction (normal incidence by default; left out of the
    /// serialised parameters while it is the default, so normal-incidence metadata is as before).
    #[serde(default, skip_serializing_if = "Oblique::is_default")]
    pub oblique: Oblique,
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
        self.variants.validate(&self.racket, self.numerics.solver)?;
        self.oblique.validate()?;
        if !self.oblique.is_normal() && self.variants.frame == Frame::Rigid {
            return Err(crate::error::Error::invalid(
                keys::FRAME.key,
                "rigid",
                "must be beam for an oblique or spinning ball (the tangential contact follows the normal force history of the fd or modal solver)",
            ));
        }
        Ok(())
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
