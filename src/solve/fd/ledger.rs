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

impl Ledger {
    pub fn total(&self) -> f64 {
        self.ke_ball + self.pe_ball + self.pe_string + self.ke_racket + self.pe_racket + self.ke_spin + self.hand
    }

    pub fn row(&self, t: f64, e0: f64, force: f64, yb: f64, yt: f64, th: f64) -> SeriesRow {
        SeriesRow {
            t_s: t,
            force_n: force,
            y_ball_m: yb,
            y_total_m: yt,
            theta_rad: th,
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
