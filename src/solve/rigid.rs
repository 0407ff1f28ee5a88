//! The textbook rigid racket (`--frame rigid`): the same ball and strings on a racket that does
//! not bend, in closed form.
//!
//! The racket's rigid-body modes are the beam's (the same masses, centre of mass and moment of
//! inertia, so the two models differ only by the bending); the force acts at the load point
//! `x_F` at distance `b = x_F - x_cm` from the centre of mass and `r` from the long axis:
//! ```text
//! effective mass    1/M_eff = 1/M + b^2/I_cm + r^2/I_x,   mu = m_b M_eff / (m_b + M_eff)
//! ball on strings   e^2 = (1/k_s + 2/((p+1) k1)) / (1/k_s + 1/k1)   (independent of mu and v1)
//! rebound           e_A = (e M_eff - m_b) / (m_b + M_eff),  impulse J = mu (1 + e) v1
//! duration          the head-clamped drop of a ball of mass mu (model::reduced::clamped_drop)
//! twist             theta = (r / I_x) (tau J - int t F dt) = (r / I_x) mu v1 tau
//! ```
//! (`int t F dt = mu e v1 tau` follows from `mu Y'' = -F` with `Y = 0` at both ends.) Nothing
//! vibrates, so `f_vib = 0` and the energy closes exactly: ball KE + ball loss + racket rigid
//! KE + spin KE = 1.

use std::sync::Arc;

use crate::error::Result;
use crate::model::basis::Basis;
use crate::model::beam::LoadPoint;
use crate::model::contact::{ContactLaw, Cross};
use crate::model::reduced::clamped_drop;
use crate::params::{Ball, Params};
use crate::solve::oblique::Follower;
use crate::solve::outcome::ImpactResult;
use crate::solve::Solver;

/// A prepared rigid-racket impact: the parameters, the racket's rigid-body modes (those of its
/// beam) and the load point.
#[derive(Debug, Clone)]
pub struct Rigid {
    params: Params,
    basis: Arc<Basis>,
    load: LoadPoint,
}

impl Solver for Rigid {
    fn prepare(p: &Params) -> Result<Self> {
        p.validate()?;
        let basis = Basis::of(&p.racket, p.numerics.segments);
        let load = basis.beam.load_point(p.impact.x, p.numerics.load);
        Ok(Rigid { params: *p, basis, load })
    }

    fn run(&self) -> Result<ImpactResult> {
        impact(&self.params, &self.basis, &self.load)
    }
}

/// The closed-form rigid-racket impact.
fn impact(p: &Params, basis: &Basis, load: &LoadPoint) -> Result<ImpactResult> {
    let beam = &basis.beam;
    let (mb, v1, r, ix) = (p.ball.mass, p.impact.v1, p.impact.r, p.racket.ix);
    let b = load.x_load - beam.x_cm;
    let m_eff = 1.0 / (1.0 / beam.total_mass + b * b / beam.i_cm + r * r / ix);
    let mu = mb * m_eff / (mb + m_eff);
    let law = Cross::new(&p.ball, &p.strings);
    let e = law.restitution_on_fixed_frame();
    let e_a = (e * m_eff - mb) / (mb + m_eff);
    let j = mu * (1.0 + e) * v1;
    let drop = clamped_drop(&Ball { mass: mu, ..p.ball }, &p.strings, v1);
    let tau = drop.tau_s;
    let theta = r / ix * mu * v1 * tau;
    let e0 = 0.5 * mb * v1 * v1;
    let omega = j * r / ix;
    let f_spin = 0.5 * ix * omega * omega / e0;
    let f_rigid = (j * j / (2.0 * beam.total_mass) + (j * b).powi(2) / (2.0 * beam.i_cm)) / e0;
    let y0 = drop.y0_m;
    let f_ball = law.ball_loss(y0) / e0;
    let f_ke_ball = e_a * e_a;
    let mut result = ImpactResult {
        e_a,
        tau_s: tau,
        theta_end_deg: theta.to_degrees(),
        f_ball,
        f_vib: 0.0,
        f_vib_peak_pe: 0.0,
        f_spin,
        f_rigid,
        f_ke_ball,
        f_hand: 0.0,
        peak_force_n: drop.peak_force_n,
        energy_error: (f_ke_ball + f_ball + f_rigid + f_spin - 1.0).abs(),
        momentum_error: 0.0,
        x_load_m: load.x_load,
        t_max_compression_s: drop.t_max_compression_s,
        y0_m: y0,
        recontact: false,
        dt_s: 0.0,
        ..ImpactResult::ZERO
    };
    // (validation keeps oblique and spinning balls off the rigid frame)
    Follower::new(None).complete(None, &mut result, v1)?;
    result.check_finite()?;
    Ok(result)
}
