//! Model variants beyond the paper (issue 6): the frame model, the grip and the string law.

use serde::{Deserialize, Serialize};

use super::choice::choice_enum;
use super::keys;
use super::spec::within;
use super::{Racket, SolverKind};
use crate::error::{Error, Result};

choice_enum! {
    /// How the frame is modelled.
    Frame (default Beam) {
        Beam = "beam": "The paper's flexible beam",
        Rigid = "rigid": "The textbook rigid racket (effective mass at the impact point, plus twist), in closed form",
    }
}

choice_enum! {
    /// How the racket is held.
    Grip (default Free) {
        Free = "free": "The paper's freely suspended racket",
        Hand = "hand": "A hand: springs and dampers spread over the grip length from the butt",
    }
}

/// The registry of the tangential mechanisms, one line each, in the order of their
/// `--tangential` choices: `Variant = name: "help",`. Here are only the names: the choice
/// `name` on the command line and in configs, its [`TangentialLaw`] variant and its help line.
/// What each name stands for is `model/tangential`'s: the mechanism `name` is the file
/// `model/tangential/name.rs`, whose type carries the variant's name (`bed` is `bed::Bed`),
/// declared and composed there from this list. A parameter that sizes a mechanism says so in its
/// own declaration (`used In(&TANGENTIAL, ..)` in [`keys`]).
///
/// The list goes to the macro `$then`: the law's choices here ([`TangentialLaw`]), the
/// mechanisms' files and the composition of the combined law in `model/tangential`.
macro_rules! tangential_mechanisms {
    ($then:ident) => {
        $then! {
            Loss = loss: "Elastic plus a damper on the ball's tangential spring (the measured tangential restitution ball-ex)",
            Offset = offset: "Elastic plus the normal force acting ahead of the ball's centre (Tabor's rolling-hysteresis arm), a torque against the spin",
            Bed = bed: "Elastic plus strings that slide sideways over each other against string-to-string friction and snap back",
            Radius = radius: "Elastic plus the friction acting at R minus the ball's compression (its dynamic stiffness ball-kdyn)",
        }
    };
}
pub(crate) use tangential_mechanisms;

/// The tangential laws from the registry of mechanisms ([`tangential_mechanisms`]):
/// the elastic law, each mechanism alone on top of it, and all of them.
macro_rules! tangential_law {
    ($($variant:ident = $name:ident: $help:literal,)+) => {
        choice_enum! {
            /// The tangential contact law of an oblique or spinning impact (SPEC.md section 6): the
            /// elastic grip-slip law, one mechanism of [`crate::model::tangential`] on top of it, or all of them.
            /// Default `elastic`: of every law fitted on the calibration rows of data/measured (with
            /// `kt`, and with `kt` and `mu-scale`), the one the rule of `study::choice` chooses: tied
            /// with the least leave-one-string-out error (overlapping 90 % bootstrap intervals over the
            /// calibration strings), and the cheapest of the tied (experiment `spin_calibration`;
            /// REPORT.md, "Calibrated where nobody measured").
            TangentialLaw (default Elastic) {
                Elastic = "elastic": "The elastic grip-slip law alone (a lossless tangential spring on a laterally rigid bed; the paper-style law; the default, chosen on the calibration rows)",
                $($variant = (stringify!($name)): $help,)+
                Physical = "physical": "Every mechanism above at once",
            }
        }

        impl TangentialLaw {
            /// Each mechanism of the registry, as the law of it alone on the elastic law, in the
            /// registry's order.
            pub const MECHANISMS: [TangentialLaw; [$(stringify!($name)),+].len()] = [$(TangentialLaw::$variant),+];
        }
    };
}

tangential_mechanisms!(tangential_law);

choice_enum! {
    /// The string in the racket, from the string table (data/strings, [`super::strings`]): its
    /// ball/string and string/string friction set `mu` and `mu-ss`.
    StringName (default None) {
        None = "none": "No string named: mu and mu-ss as given (the default)",
        TonicGut16 = "tonic-gut-16": "Babolat Tonic Gut 16 (gut; no friction row of its own: the TWU gut median)",
        AluPower16 = "alu-power-16": "Luxilon ALU Power 16 (polyester)",
        AluRough16 = "alu-rough-16": "Luxilon ALU Rough 16 (polyester)",
        Original16 = "original-16": "Luxilon Original 16 (polyester)",
        Tcs16 = "tcs-16": "Polyfibre TCS 16 (polyester)",
        Nrg2_16 = "nrg2-16": "Tecnifibre NRG2 16 (nylon)",
        Nxt16 = "nxt-16": "Wilson NXT 16 (nylon)",
    }
}

impl TangentialLaw {
    /// Whether the law includes the mechanism `m` (one of the single-mechanism choices).
    pub fn has(self, m: TangentialLaw) -> bool {
        self == m || (self == TangentialLaw::Physical && m != TangentialLaw::Elastic)
    }
}

choice_enum! {
    /// The string bed's force law.
    StringLaw (default Linear) {
        Linear = "linear": "The paper's constant `k_s`",
        Stiffening = "stiffening": "`F = k_s Y_s (1 + s (Y_s / d)^2)`: the secant stiffness grows by the fraction `s` at the deflection `d` (the paper quotes about 10 % for large deflections)",
    }
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
        for (spec, v) in [
            (keys::STRING_STIFFENING, self.string_stiffening),
            (keys::STIFFENING_DEFLECTION, self.stiffening_deflection),
            (keys::HAND_STIFFNESS, self.hand_stiffness),
            (keys::HAND_DAMPING, self.hand_damping),
        ] {
            spec.check(v)?;
        }
        // only a hand needs a grip that fits on the racket
        let longest = if self.grip == Grip::Hand { 0.5 * racket.length } else { keys::LENGTH.range().1 };
        let g = keys::GRIP_LENGTH;
        within(g.key, self.grip_length, g.what, g.unit, (1e-3, longest))?;
        let nonlinear = self.strings == StringLaw::Stiffening || self.grip == Grip::Hand;
        if nonlinear && self.frame == Frame::Rigid {
            return Err(Error::invalid(
                keys::FRAME.key,
                "rigid",
                "must be beam with stiffening strings or a hand grip (the rigid frame is the closed-form limit for linear strings and a free racket)",
            ));
        }
        if nonlinear && solver == SolverKind::Modal {
            return Err(Error::invalid(
                keys::SOLVER.key,
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
