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
}

impl Quantity {
    /// Every quantity, in table order.
    pub const ALL: [Quantity; 5] = [Quantity::EA, Quantity::Tau, Quantity::Theta, Quantity::FVib, Quantity::Power];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::EA => "e_a",
            Quantity::Tau => "tau",
            Quantity::Theta => "theta",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power",
        }
    }

    /// The table column (with its unit).
    pub fn column(self) -> &'static str {
        match self {
            Quantity::EA => "e_a",
            Quantity::Tau => "tau_ms",
            Quantity::Theta => "theta_deg",
            Quantity::FVib => "f_vib",
            Quantity::Power => "power_pct",
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
        }
    }

    /// Its value for one impact.
    pub fn of(self, r: &ImpactResult) -> f64 {
        let (field, scale) = self.source();
        scale * field.number(r)
    }
}

impl std::str::FromStr for Quantity {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Quantity::ALL
            .into_iter()
            .find(|q| q.name() == s)
            .ok_or_else(|| Error::invalid("quantity", s, "must be one of e_a, tau, theta, f_vib, power".to_string()))
    }
}
