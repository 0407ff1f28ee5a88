//! The energy ledger of SPEC.md section 2 at one instant: where the ball's energy is, as a sum
//! that stays 1 up to the integration error, and as a row of the time series.

use crate::model::contact::{ContactLaw, ContactState, Phase};
use crate::solve::fd::stepper::Stepper;
use crate::solve::fd::FdModel;
use crate::solve::outcome::SeriesRow;

/// The energy ledger at one instant, J.
pub(super) struct Ledger {
    ke_ball: f64,
    pe_ball: f64,
    pe_string: f64,
    ke_racket: f64,
    pe_racket: f64,
    ke_spin: f64,
    /// Hand springs plus hand damper loss.
    hand: f64,
}

/// Where the impact is at one instant: the time series' columns beside the ledger's.
pub(super) struct Motion {
    /// Time, s.
    pub t: f64,
    /// Contact force, N.
    pub force: f64,
    /// Ball displacement `y_b` and total compression `Y_T`, m.
    pub y_ball: f64,
    pub y_total: f64,
    /// Twist angle, rad.
    pub theta: f64,
}

impl Ledger {
    pub fn total(&self) -> f64 {
        self.ke_ball + self.pe_ball + self.pe_string + self.ke_racket + self.pe_racket + self.ke_spin + self.hand
    }

    /// The time-series row at `at`, the energies as fractions of the incident `e0` (J).
    pub fn row(&self, e0: f64, at: Motion) -> SeriesRow {
        SeriesRow {
            t_s: at.t,
            force_n: at.force,
            y_ball_m: at.y_ball,
            y_total_m: at.y_total,
            theta_rad: at.theta,
            ke_ball: self.ke_ball / e0,
            pe_ball: self.pe_ball / e0,
            pe_string: self.pe_string / e0,
            ke_racket: self.ke_racket / e0,
            pe_racket: self.pe_racket / e0,
            ke_spin: self.ke_spin / e0,
            hand: self.hand / e0,
            total: self.total() / e0,
        }
    }
}

impl FdModel {
    /// The ledger of the state `st` with the contact `cs` in `phase`, the beam's bending energy
    /// `pe` and kinetic energy `ke` (J).
    #[inline]
    pub(super) fn ledger(&self, st: &Stepper, phase: Phase, cs: &ContactState, pe: f64, ke: f64) -> Ledger {
        let p = &self.impact.params;
        let (mb, ix) = (p.ball.mass, p.racket.ix);
        Ledger {
            ke_ball: 0.5 * mb * st.ball.v * st.ball.v,
            pe_ball: self.impact.contact.ball_energy_with_loss(phase, cs),
            pe_string: self.impact.contact.string_energy(cs),
            ke_racket: ke,
            pe_racket: pe,
            ke_spin: 0.5 * ix * st.om * st.om,
            hand: st.hand_energy(&self.hand),
        }
    }
}
