//! Mechanism `bed`: the strings under the ball move sideways. The set of strings that the
//! tangential force pushes across (the mains for a ball moving across the face) slides over the
//! other set against string-to-string friction and is pulled back by its tension: a lateral
//! spring `k_lat` in series with the ball's tangential spring, with a Coulomb slider of limit
//! `mu_ss N` in parallel. While the slider sticks the bed does not move; when the force on it
//! exceeds the limit the strings slide, and as the normal force falls at the end of the contact
//! the limit falls with it and the strings snap back, returning their stored energy to the ball
//! (if it still grips) or losing it to the sliding.
//!
//! Sizes (derived, not fitted):
//! - `k_lat = k_s / 2`. A string under tension `T` resists a sideways displacement at a point
//!   with the same geometric stiffness `T (1/a + 1/b)` in the string plane as out of it; the
//!   string-plane stiffness `k_s` of the normal impact is that of both sets under the ball,
//!   and only one set is pushed across, so it carries half of it. `k_s` follows the tension
//!   (`ks_from_tension_lb`).
//! - `N = F_n / 2`: the set pushed across carries half the ball's load (equal tension and
//!   spacing of mains and crosses near the centre) and presses that share onto the other set
//!   at the crossings. This is an assumption of the weave, stated as one.
//! - `mu_ss`: the string-to-string friction coefficient of the string in use (TWU string
//!   database, data/strings).

/// The lateral string bed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bed {
    /// Lateral stiffness, N/m.
    pub k_lat: f64,
    /// String-to-string friction coefficient.
    pub mu_ss: f64,
    /// Share of the normal force that presses the moving set onto the other.
    pub share: f64,
}

impl Bed {
    /// The bed of a string plane of stiffness `ks` (N/m) strung with string-to-string friction
    /// `mu_ss`.
    pub fn of(ks: f64, mu_ss: f64) -> Bed {
        Bed { k_lat: 0.5 * ks, mu_ss, share: 0.5 }
    }

    /// The friction limit, N, at the normal force `f`.
    pub fn limit(&self, f: f64) -> f64 {
        self.mu_ss * self.share * f.max(0.0)
    }

    /// Its rate, N/s, at the normal force rate `df`.
    pub fn limit_rate(&self, df: f64) -> f64 {
        self.mu_ss * self.share * df
    }
}
