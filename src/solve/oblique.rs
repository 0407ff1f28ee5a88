//! Oblique and spinning impacts on top of the normal one (SPEC.md section 6): the solvers step
//! the normal impact at the normal speed `v1 cos(angle)` exactly as at normal incidence, feed
//! its force history to the tangential law ([`crate::model::tangential`]) piece by piece, and
//! this file turns the tangential contact at separation into the result's oblique fields.

use crate::error::{Error, Result};
use crate::model::tangential::{Contact, ForcePiece, Setup, RPM};
use crate::params::Params;
use crate::solve::outcome::ImpactResult;

/// The least incoming slip of the ball's contact point, as a fraction of the incident speed
/// `|(v_n, v_t)|`, for which the tangential coefficient of restitution `e_t` is reported.
///
/// Why: `e_t = -(w_out - u_out) / w_in` divides by the incoming slip `w_in`. Under the laws
/// with a torque that does not vanish with the slip (`offset`, `radius`, `physical`) the
/// outgoing slip stays of the order of the incident speed as `w_in -> 0`, so the quotient grows
/// as `1 / w_in` without bound (a ball arriving at 10 degrees nearly rolling, 354.727 rpm,
/// gave `e_t` = -6e5 under `physical`) and then describes how small `w_in` happened to be,
/// not the contact. Below 1 % of the incident speed `e_t` is undefined (NaN: null in the JSON,
/// an empty CSV field, `undefined` in the text); the outgoing slip itself is in `v2_t` and
/// `spin_out_rpm`. A ball arriving without spin slips at its whole tangential speed,
/// `v1 sin(angle)` (17 % of `v1` at 10 degrees), far above this.
pub const E_T_MIN_SLIP_FRACTION: f64 = 0.01;

/// The tangential coefficient of restitution for the incoming slip `w_in` and the outgoing
/// slip relative to the frame `w_out`, at the incident speed `speed`: undefined (NaN) below
/// [`E_T_MIN_SLIP_FRACTION`].
fn tangential_cor(w_in: f64, w_out: f64, speed: f64) -> f64 {
    if w_in.abs() < E_T_MIN_SLIP_FRACTION * speed || w_in == 0.0 {
        f64::NAN
    } else {
        -w_out / w_in
    }
}

/// The parameters of an impact's normal part: the same impact at the normal speed.
pub(crate) fn normal_part(p: &Params) -> Params {
    let mut n = *p;
    n.impact.v1 = p.impact.v1 * p.oblique.angle_deg.to_radians().cos();
    n
}

/// The tangential contact of an impact in progress (none at normal incidence without spin):
/// each step hands it the piece of the normal force history it covered.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Follower(Option<Contact>);

impl Follower {
    /// Follow the impact set up by `setup`, if any.
    pub fn new(setup: Option<&Setup>) -> Self {
        Follower(setup.map(Setup::start))
    }

    /// Whether there is a tangential contact to follow.
    pub fn is_active(&self) -> bool {
        self.0.is_some()
    }

    /// Advance over one piece of the normal force history.
    #[inline]
    pub fn advance(&mut self, piece: impl FnOnce() -> ForcePiece) {
        if let Some(c) = &mut self.0 {
            c.advance(&piece());
        }
    }

    /// The oblique fields of the result `r` (whose normal fields are set), at separation; the
    /// tangential ledger's error (with each mechanism's loss named under the combined law)
    /// joins `energy_error`. At normal incidence without spin they are NaN (they do not apply,
    /// and the JSON leaves them out), and so are the mechanisms' losses under the elastic law;
    /// otherwise each is checked to be finite (but `e_t`, undefined for a contact point that
    /// arrives with too little slip, [`E_T_MIN_SLIP_FRACTION`]).
    pub fn complete(&self, setup: Option<&Setup>, r: &mut ImpactResult, v_n: f64) -> Result<()> {
        let nan = f64::NAN;
        (r.f_tangential_damping, r.f_string_sliding, r.f_rolling) = (nan, nan, nan);
        r.tangential_chatter = false;
        let (Some(s), Some(c)) = (setup, &self.0) else {
            (r.v2_n, r.v2_t, r.spin_out_rpm, r.rebound_angle_deg, r.e_t) = (nan, nan, nan, nan, nan);
            (r.slip_fraction, r.f_friction, r.f_ball_spin, r.f_racket_inplane) = (nan, nan, nan, nan);
            return Ok(());
        };
        let out = s.separation(c);
        r.v2_n = r.e_a * v_n;
        let (mb, inertia, radius) = (s.law.mb, s.law.inertia, s.law.radius);
        let ke = |v: f64, w: f64| 0.5 * mb * v * v + 0.5 * inertia * w * w;
        let e_in = ke(s.v_n, 0.0) + ke(s.v_t, s.omega);
        let losses = match out.mechanism_losses {
            Some(m) => out.friction_loss + m.damping + m.string_sliding + m.rolling + m.ledger_only,
            None => out.friction_loss,
        };
        let ledger = ke(s.v_t, s.omega) - (ke(out.v_t, out.omega) + out.inplane + losses + out.spring_energy);
        let w_in = s.v_t - radius * s.omega;
        r.v2_t = out.v_t;
        r.spin_out_rpm = out.omega / RPM;
        r.rebound_angle_deg = out.v_t.atan2(r.v2_n).to_degrees();
        r.e_t = tangential_cor(w_in, out.slip, s.v_n.hypot(s.v_t));
        // (the pieces' lengths add up to the contact time only to rounding)
        r.slip_fraction = (out.slide_time / r.tau_s).min(1.0);
        r.tangential_chatter = out.chatter;
        r.f_friction = out.friction_loss / e_in;
        r.f_ball_spin = 0.5 * inertia * out.omega * out.omega / e_in;
        r.f_racket_inplane = out.inplane / e_in;
        if let Some(m) = out.mechanism_losses {
            r.f_tangential_damping = m.damping / e_in;
            r.f_string_sliding = m.string_sliding / e_in;
            r.f_rolling = m.rolling / e_in;
        }
        r.energy_error = r.energy_error.max(ledger.abs() / e_in);
        check_fields(r)?;
        r.check_energy()
    }
}

/// Every oblique field (but `e_t`) finite, or an error naming the first that is not.
fn check_fields(r: &ImpactResult) -> Result<()> {
    let fields = [
        ("v2_n", r.v2_n),
        ("v2_t", r.v2_t),
        ("spin_out_rpm", r.spin_out_rpm),
        ("rebound_angle_deg", r.rebound_angle_deg),
        ("slip_fraction", r.slip_fraction),
        ("f_friction", r.f_friction),
        ("f_ball_spin", r.f_ball_spin),
        ("f_racket_inplane", r.f_racket_inplane),
        ("energy_error", r.energy_error),
    ];
    match fields.iter().find(|(_, v)| !v.is_finite()) {
        Some(&(field, _)) => Err(Error::NonFinite { field }),
        None => Ok(()),
    }
}
