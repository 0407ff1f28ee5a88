//! Oblique and spinning impacts on top of the normal one (SPEC.md section 6): the solvers step
//! the normal impact at the normal speed `v1 cos(angle)` exactly as at normal incidence, feed
//! its force history to the tangential grip-slip law ([`Tangential`]) piece by piece, and this
//! file turns the tangential state at separation into the result's oblique fields.

use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::model::grip::{self, bed::Bed, loss, offset, radius::Compression, Contact};
use crate::model::tangential::{ForcePiece, GripSlip, Tangential};
use crate::params::{Params, TangentialLaw};
use crate::solve::outcome::ImpactResult;

/// Revolutions per minute in rad/s.
pub const RPM: f64 = std::f64::consts::PI / 30.0;

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

/// The tangential side of an oblique or spinning impact, prepared.
#[derive(Debug, Clone, Copy)]
pub struct Setup {
    /// The grip-slip law.
    law: GripSlip,
    /// The physical law with its mechanisms (`None`: the elastic law alone).
    physical: Option<grip::Law>,
    /// Incoming normal and tangential speed, m/s, and spin, rad/s.
    v_n: f64,
    v_t: f64,
    omega: f64,
}

impl Setup {
    /// The tangential side of the impact `p` on `beam` at the load point `x_load` (m from the
    /// tip), or `None` for normal incidence without spin (no tangential force can arise).
    pub(crate) fn of(p: &Params, beam: &Beam, x_load: f64) -> Option<Setup> {
        let o = &p.oblique;
        if o.is_normal() {
            return None;
        }
        let mb = p.ball.mass;
        let (sin_a, cos_a) = o.angle_deg.to_radians().sin_cos();
        let (sin_z, cos_z) = o.azimuth_deg.to_radians().sin_cos();
        // the lever of a force along t about the normal through the centre of mass
        let arm = (x_load - beam.x_cm) * sin_z - p.impact.r * cos_z;
        let (mu, mu_ss) = o.friction();
        let law = GripSlip {
            mu,
            kt: o.kt,
            mb,
            radius: o.ball_radius,
            inertia: o.ball_inertia_factor * mb * o.ball_radius * o.ball_radius,
            racket_inv_mass: 1.0 / beam.total_mass + arm * arm / (beam.i_cm + p.racket.ix),
        };
        let physical = (o.tangential != TangentialLaw::Elastic).then(|| {
            let has = |m| o.tangential.has(m);
            let mut g = grip::Law {
                base: law,
                damping: 0.0,
                offset_loss: if has(TangentialLaw::Offset) { offset::loss_fraction(p.ball.p) } else { 0.0 },
                bed: has(TangentialLaw::Bed).then(|| Bed::of(p.strings.ks, mu_ss)),
                shrink: has(TangentialLaw::Radius),
                compression: Compression { k1: p.ball.k1, p: p.ball.p, radius: law.radius },
            };
            if has(TangentialLaw::Loss) {
                g.damping = loss::damper(loss::damping_ratio(p.ball.p), law.kt, g.inv_red());
            }
            g
        });
        Some(Setup { law, physical, v_n: p.impact.v1 * cos_a, v_t: p.impact.v1 * sin_a, omega: o.spin_rpm * RPM })
    }

    /// The tangential contact before the ball touches.
    pub(crate) fn start(&self) -> Law {
        match self.physical {
            None => Law::Elastic(Tangential::new(self.law, self.v_t - self.law.radius * self.omega)),
            Some(law) => Law::Physical(Contact::new(law, self.v_t, self.omega)),
        }
    }
}

/// The tangential contact in progress, under the elastic law or the physical one.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Law {
    /// The elastic grip-slip law (closed form).
    Elastic(Tangential),
    /// The law with its mechanisms.
    Physical(Contact),
}

/// The tangential contact of an impact in progress (none at normal incidence without spin):
/// each step hands it the piece of the normal force history it covered.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Follower(Option<Law>);

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
        match &mut self.0 {
            Some(Law::Elastic(t)) => t.advance(&piece()),
            Some(Law::Physical(c)) => c.advance(&piece()),
            None => {}
        }
    }

    /// The oblique fields of the result `r` (whose normal fields are set), at separation after
    /// a contact of `tau` seconds; the tangential ledger's error joins `energy_error`.
    /// At normal incidence without spin they are NaN (they do not apply, and the JSON leaves
    /// them out); otherwise each is checked to be finite (but `e_t`, undefined for a contact
    /// point that arrives with too little slip, [`E_T_MIN_SLIP_FRACTION`]).
    pub fn complete(&self, setup: Option<&Setup>, r: &mut ImpactResult, v_n: f64) -> Result<()> {
        let nan = f64::NAN;
        (r.f_tangential_damping, r.f_string_sliding, r.f_rolling) = (nan, nan, nan);
        let (s, t) = match (setup, &self.0) {
            (Some(s), Some(Law::Elastic(t))) => (s, t),
            (Some(s), Some(Law::Physical(c))) => return complete_physical(s, c, r, v_n),
            _ => {
                (r.v2_n, r.v2_t, r.spin_out_rpm, r.rebound_angle_deg, r.e_t) = (nan, nan, nan, nan, nan);
                (r.slip_fraction, r.f_friction, r.f_ball_spin, r.f_racket_inplane) = (nan, nan, nan, nan);
                return Ok(());
            }
        };
        r.v2_n = r.e_a * v_n;
        let law = &s.law;
        let (mb, inertia, radius) = (law.mb, law.inertia, law.radius);
        let j = t.impulse;
        let v2_t = s.v_t + j / mb;
        let omega = s.omega - radius * j / inertia;
        let ke = |v: f64, w: f64| 0.5 * mb * v * v + 0.5 * inertia * w * w;
        let e_in = ke(s.v_n, 0.0) + ke(s.v_t, s.omega);
        let e_t0 = ke(s.v_t, s.omega);
        let inplane = 0.5 * law.racket_inv_mass * j * j;
        let ledger = e_t0 - (ke(v2_t, omega) + inplane + t.friction_loss + t.spring_energy());
        let w_in = s.v_t - radius * s.omega;
        r.v2_t = v2_t;
        r.spin_out_rpm = omega / RPM;
        r.rebound_angle_deg = v2_t.atan2(r.v2_n).to_degrees();
        r.e_t = tangential_cor(w_in, t.slip(), s.v_n.hypot(s.v_t));
        // (the pieces' lengths add up to the contact time only to rounding)
        r.slip_fraction = (t.slide_time / r.tau_s).min(1.0);
        r.f_friction = t.friction_loss / e_in;
        r.f_ball_spin = 0.5 * inertia * omega * omega / e_in;
        r.f_racket_inplane = inplane / e_in;
        r.energy_error = r.energy_error.max(ledger.abs() / e_in);
        check_fields(r)
    }
}

/// The oblique fields of the result `r` under the physical law, from the contact `c` at
/// separation; the ledger of the tangential energies (with each mechanism's loss named) joins
/// `energy_error`.
fn complete_physical(s: &Setup, c: &Contact, r: &mut ImpactResult, v_n: f64) -> Result<()> {
    let law = &s.law;
    let (mb, inertia, radius) = (law.mb, law.inertia, law.radius);
    r.v2_n = r.e_a * v_n;
    let (v2_t, omega, u) = (c.v(), c.omega(), c.u());
    let ke = |v: f64, w: f64| 0.5 * mb * v * v + 0.5 * inertia * w * w;
    let e_in = ke(s.v_n, 0.0) + ke(s.v_t, s.omega);
    let inplane = if law.racket_inv_mass > 0.0 { 0.5 * u * u / law.racket_inv_mass } else { 0.0 };
    let losses = c.friction_loss() + c.damping_loss() + c.bed_loss() + c.rolling_loss();
    let ledger = ke(s.v_t, s.omega) - (ke(v2_t, omega) + inplane + losses + c.spring_energy());
    let w_in = s.v_t - radius * s.omega;
    r.v2_t = v2_t;
    r.spin_out_rpm = omega / RPM;
    r.rebound_angle_deg = v2_t.atan2(r.v2_n).to_degrees();
    r.e_t = tangential_cor(w_in, v2_t - radius * omega - u, s.v_n.hypot(s.v_t));
    r.slip_fraction = (c.slide_time / r.tau_s).min(1.0);
    r.f_friction = c.friction_loss() / e_in;
    r.f_ball_spin = 0.5 * inertia * omega * omega / e_in;
    r.f_racket_inplane = inplane / e_in;
    r.f_tangential_damping = c.damping_loss() / e_in;
    r.f_string_sliding = c.bed_loss() / e_in;
    r.f_rolling = c.rolling_loss() / e_in;
    r.energy_error = r.energy_error.max(ledger.abs() / e_in);
    check_fields(r)
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
