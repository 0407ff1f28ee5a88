//! The quantities a map shows, each read off one impact's result.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::solve::outcome::{field, Field};
use crate::solve::ImpactResult;

/// What a map shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// Apparent coefficient of restitution `e_A = v2 / v1`.
    EA,
    /// Impact duration, ms.
    Tau,
    /// Twist about the long axis at the end of the impact, degrees.
    Theta,
    /// Racket vibration energy after the impact, fraction of the ball's incident energy.
    FVib,
    /// Power potential `100 e_A`, %.
    #[default]
    Power,
    /// Outgoing spin of an oblique or spinning ball, rpm (topspin > 0).
    Spin,
    /// Rebound angle of an oblique or spinning ball from the string-plane normal, degrees.
    ReboundAngle,
}

impl Quantity {
    /// The quantities of every impact, in table order.
    pub const ALL: [Quantity; 5] = [Quantity::EA, Quantity::Tau, Quantity::Theta, Quantity::FVib, Quantity::Power];

    /// The quantities of an oblique or spinning ball, after those in a table.
    pub const OBLIQUE: [Quantity; 2] = [Quantity::Spin, Quantity::ReboundAngle];

    /// Every quantity a map can show.
    pub fn every() -> impl Iterator<Item = Quantity> {
        Quantity::ALL.into_iter().chain(Quantity::OBLIQUE)
    }

    /// Whether it is a quantity of an oblique or spinning ball only.
    pub fn is_oblique(self) -> bool {
        self.source().0.is_oblique()
    }

    /// The quantities of a map's table: the oblique ones only for an oblique or spinning ball.
    pub fn in_table(oblique: bool) -> impl Iterator<Item = Quantity> {
        Quantity::every().filter(move |q| oblique || !q.is_oblique())
    }

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::EA => "e_a",
            Quantity::Tau => "tau",
            Quantity::Theta => "theta",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power",
            Quantity::Spin => "spin",
            Quantity::ReboundAngle => "rebound_angle",
        }
    }

    /// The table column (with its unit): the result field's own name
    /// ([`crate::solve::outcome::FIELDS`]), in its SI unit; `power_pct` for the power.
    pub fn column(self) -> &'static str {
        match self {
            Quantity::EA => "e_a",
            Quantity::Tau => "tau_s",
            Quantity::Theta => "theta_end_deg",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power_pct",
            Quantity::Spin => "spin_out_rpm",
            Quantity::ReboundAngle => "rebound_angle_deg",
        }
    }

    /// What it is, in words.
    pub fn description(self) -> &'static str {
        match self {
            Quantity::EA => "apparent COR e_A",
            Quantity::Tau => "impact duration",
            Quantity::Theta => "twist at the end of impact",
            Quantity::FVib => "vibration energy",
            Quantity::Power => "power potential 100 e_A",
            Quantity::Spin => "outgoing spin",
            Quantity::ReboundAngle => "rebound angle from the normal",
        }
    }

    /// Its symbol on the colour bar.
    pub fn symbol(self) -> &'static str {
        match self {
            Quantity::EA => "e_A",
            Quantity::Tau => "tau",
            Quantity::Theta => "theta",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power 100 e_A",
            Quantity::Spin => "spin out (> 0: topspin relative to the incoming motion)",
            Quantity::ReboundAngle => "rebound angle",
        }
    }

    /// Its unit (empty for a pure number).
    pub fn unit(self) -> &'static str {
        match self {
            Quantity::EA => "",
            Quantity::Tau => "ms",
            Quantity::Theta => "deg",
            Quantity::FVib => "fraction of the ball's KE",
            Quantity::Power => "%",
            Quantity::Spin => "rpm",
            Quantity::ReboundAngle => "deg",
        }
    }

    /// The result field it is read from ([`crate::solve::outcome::FIELDS`]), and the factor it
    /// is shown with.
    pub fn source(self) -> (&'static Field, f64) {
        match self {
            Quantity::EA => const { (field("e_a"), 1.0) },
            Quantity::Tau => const { (field("tau_s"), 1e3) },
            Quantity::Theta => const { (field("theta_end_deg"), 1.0) },
            Quantity::FVib => const { (field("f_vib"), 1.0) },
            Quantity::Power => const { (field("e_a"), 100.0) },
            Quantity::Spin => const { (field("spin_out_rpm"), 1.0) },
            Quantity::ReboundAngle => const { (field("rebound_angle_deg"), 1.0) },
        }
    }

    /// The smallest value that means what the name says, and what a value below it means: a
    /// power potential (or e_A) below 0 is a ball that does not come back off a racket at rest
    /// (it moves on behind the recoiling frame), not a negative power. A map shades such
    /// points grey and starts its colour scale at the floor.
    pub fn floor(self) -> Option<(f64, &'static str)> {
        match self {
            Quantity::EA | Quantity::Power => Some((0.0, "grey: below 0, no rebound")),
            _ => None,
        }
    }

    /// For a quantity of an oblique or spinning ball, what the grey of a map means: the points
    /// where the ball does not rebound (`v2_n` < 0, a rebound angle over 90 degrees: it moves
    /// on behind the recoiling frame, as where a power map is below its floor), greyed so that
    /// a spin or an angle of a ball that never comes back is not read as a shot's.
    pub fn no_rebound_note(self) -> Option<&'static str> {
        match self {
            Quantity::Spin => Some("grey: no rebound"),
            Quantity::ReboundAngle => Some("grey: over 90, no rebound"),
            _ => None,
        }
    }

    /// Its value for one impact, as shown (in [`Quantity::unit`]: tau in ms).
    pub fn of(self, r: &ImpactResult) -> f64 {
        let (field, scale) = self.source();
        scale * field.number(r)
    }

    /// Its value for one impact as in the table's [`Quantity::column`] (SI: tau in s; the power
    /// in %).
    pub fn column_value(self, r: &ImpactResult) -> f64 {
        match self {
            Quantity::Power => self.of(r),
            _ => self.source().0.number(r),
        }
    }
}

impl std::str::FromStr for Quantity {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Quantity::every().find(|q| q.name() == s).ok_or_else(|| {
            Error::invalid(
                "quantity",
                s,
                "must be one of e_a, tau, theta, f_vib, power, spin, rebound_angle".to_string(),
            )
        })
    }
}
