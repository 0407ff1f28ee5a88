//! One impact's tangential side: the law the parameters select ([`Setup::of`]), its contact in
//! progress ([`Contact`]), and what that contact leaves at separation ([`Separation`]).

use super::combined::{Combined, CombinedLaw, Losses};
use super::compression::Compression;
use super::elastic::{Elastic, GripSlip};
use super::mechanism::Sizes;
use super::piece::ForcePiece;
use crate::model::beam::Beam;
use crate::params::{Params, TangentialLaw};

/// Revolutions per minute in rad/s.
pub const RPM: f64 = std::f64::consts::PI / 30.0;

/// The tangential side of an oblique or spinning impact, prepared.
#[derive(Debug, Clone, Copy)]
pub struct Setup {
    /// The grip-slip law.
    pub(crate) law: GripSlip,
    /// The combined law with its mechanisms (`None`: the elastic law alone).
    combined: Option<CombinedLaw>,
    /// Incoming normal speed, m/s.
    pub(crate) v_n: f64,
    /// Incoming tangential speed, m/s.
    pub(crate) v_t: f64,
    /// Incoming spin, rad/s (topspin positive).
    pub(crate) omega: f64,
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
        let mu_ss = o.friction().1;
        let law = GripSlip {
            mu: o.sliding_mu(),
            kt: o.kt,
            mb,
            radius: o.ball_radius,
            inertia: o.ball_inertia_factor * mb * o.ball_radius * o.ball_radius,
            racket_inv_mass: 1.0 / beam.total_mass + arm * arm / (beam.i_cm + p.racket.ix),
        };
        // the mechanisms of the law, each sized from the parameters (the registry: `tangential_mechanisms!`)
        let combined = (o.tangential != TangentialLaw::Elastic).then(|| {
            let compression = Compression { k: o.ball_kdyn, p: p.ball.p, radius: law.radius };
            CombinedLaw::of(o.tangential, &Sizes { params: p, base: law, mu_ss, compression })
        });
        Some(Setup { law, combined, v_n: p.impact.v1 * cos_a, v_t: p.impact.v1 * sin_a, omega: o.spin_rpm * RPM })
    }

    /// The most steps the tangential contact can take in a contact of `t` seconds (the
    /// elastic law's switch-search samples, or the combined law's substeps): set by the fastest
    /// tangential time scale, `sqrt(k_t / m_red)`, which a light ball of small inertia makes
    /// short ([`MAX_TANGENTIAL_STEPS`] bounds it).
    pub(crate) fn steps_within(&self, t: f64) -> f64 {
        match self.start() {
            Contact::Elastic(e) => e.steps_within(t),
            Contact::Combined(c) => c.steps_within(t),
        }
    }

    /// The tangential contact before the ball touches.
    pub(crate) fn start(&self) -> Contact {
        match self.combined {
            None => Contact::Elastic(Elastic::new(self.law, self.v_t - self.law.radius * self.omega)),
            Some(law) => Contact::Combined(Combined::new(law, self.v_t, self.omega)),
        }
    }

    /// What the contact `c` of this impact leaves at separation.
    pub(crate) fn separation(&self, c: &Contact) -> Separation {
        let law = &self.law;
        match c {
            Contact::Elastic(t) => {
                let j = t.impulse;
                Separation {
                    v_t: self.v_t + j / law.mb,
                    omega: self.omega - law.radius * j / law.inertia,
                    inplane: 0.5 * law.racket_inv_mass * j * j,
                    slip: t.slip(),
                    friction_loss: t.friction_loss,
                    mechanism_losses: None,
                    spring_energy: t.spring_energy(),
                    slide_time: t.slide_time,
                    chatter: false,
                }
            }
            Contact::Combined(c) => {
                let (v_t, omega, u) = (c.v(), c.omega(), c.u());
                let rim = law.racket_inv_mass;
                Separation {
                    v_t,
                    omega,
                    inplane: if rim > 0.0 { 0.5 * u * u / rim } else { 0.0 },
                    slip: v_t - law.radius * omega - u,
                    friction_loss: c.friction_loss(),
                    mechanism_losses: Some(c.losses()),
                    spring_energy: c.spring_energy(),
                    slide_time: c.slide_time,
                    chatter: c.chatter,
                }
            }
        }
    }
}

/// Refuse parameters whose tangential contact could need more steps than this over the longest
/// contact a solver allows (its time limit): about ten seconds of the combined law's
/// Runge-Kutta substeps, far beyond any ball (the paper's ball at 30 degrees: some fifty).
pub const MAX_TANGENTIAL_STEPS: f64 = 1.0e8;

/// The tangential contact in progress, under the elastic law or the combined one. (One per
/// impact, held on the stack while the solver steps: boxing the larger variant would add an
/// allocation to every impact and an indirection to every step, for no saving.)
#[derive(Debug, Clone, Copy)]
#[allow(clippy::large_enum_variant)]
pub(crate) enum Contact {
    /// The elastic grip-slip law (closed form).
    Elastic(Elastic),
    /// The law with its mechanisms.
    Combined(Combined),
}

impl Contact {
    /// Advance over one piece of the normal force history.
    #[inline]
    pub(crate) fn advance(&mut self, piece: &ForcePiece) {
        match self {
            Contact::Elastic(t) => t.advance(piece),
            Contact::Combined(c) => c.advance(piece),
        }
    }
}

/// The tangential contact at separation: the ball's velocity and spin, the frame's in-plane
/// motion and the energy ledger's terms.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Separation {
    /// Ball velocity along `t`, m/s.
    pub v_t: f64,
    /// Ball spin, rad/s (topspin positive).
    pub omega: f64,
    /// Kinetic energy of the frame's in-plane motion, J.
    pub inplane: f64,
    /// Slip of the ball's contact point relative to the frame, m/s.
    pub slip: f64,
    /// Energy lost to the ball sliding on the strings, J.
    pub friction_loss: f64,
    /// The other mechanisms' losses (`None` under the elastic law, which has none).
    pub mechanism_losses: Option<Losses>,
    /// Energy left in the tangential springs, J.
    pub spring_energy: f64,
    /// Time spent sliding, s.
    pub slide_time: f64,
    /// Whether the grip/slide switch chattered at an edge until a force piece reached its cap
    /// (the combined law only; SPEC.md section 6, "Known limit").
    pub chatter: bool,
}
