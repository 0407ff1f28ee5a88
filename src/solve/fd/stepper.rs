//! The explicit solver's state and its velocity-Verlet steps: drift, kick (allocation-free: the
//! banded stiffness applied as a five-point stencil through the bending moments
//! `kappa_j c_j`, the kinetic energy and momentum accumulated in the same pass) and the force
//! correction at the phase switch.

use crate::model::basis::Padded;
use crate::model::beam::Beam;
use crate::model::coupling::BallState;
use crate::solve::fd::FdModel;

/// The state of the ball, the beam and the twist, with the bending-moment buffer.
#[derive(Clone)]
pub(super) struct Stepper {
    /// The ball.
    pub ball: BallState,
    /// The ball's acceleration, m/s^2.
    pub ab: f64,
    pub y: Vec<f64>,
    pub v: Vec<f64>,
    pub a: Vec<f64>,
    pub th: f64,
    pub om: f64,
    pub al: f64,
    /// `moment[i + 1] = kappa_i c_i` for node i; zero padding at both ends.
    pub moment: Vec<f64>,
    /// The contact force on each node, N: zero but at the load nodes during a kick.
    pub load: Vec<f64>,
    /// Energy dissipated by the hand's dampers so far, J.
    pub hand_loss: f64,
    /// Momentum given to the hand so far, kg m/s.
    pub hand_impulse: f64,
}

impl Stepper {
    /// At rest with the ball at `v1` (m/s), for a beam padded to `lanes` nodes ([`Padded`]).
    pub fn new(lanes: usize, v1: f64) -> Self {
        let zeros = vec![0.0; lanes + 2];
        Stepper {
            ball: BallState { y: 0.0, v: v1 },
            ab: 0.0,
            y: zeros.clone(),
            v: zeros.clone(),
            a: zeros,
            th: 0.0,
            om: 0.0,
            al: 0.0,
            moment: vec![0.0; lanes + 4],
            load: vec![0.0; lanes],
            hand_loss: 0.0,
            hand_impulse: 0.0,
        }
    }

    /// The half-kicks of the ball and of the twist under the contact force `f`.
    pub(super) fn kick_ball_and_twist(&mut self, half: f64, f: f64, model: &FdModel) {
        let ab = -f * model.inv_ball_mass;
        self.ball.v += (self.ab + ab) * half;
        self.ab = ab;
        let al = f * model.twist_per_force;
        self.om += (self.al + al) * half;
        self.al = al;
    }

    /// Positions to the end of the step, `y += v dt + a dt^2 / 2`, then the bending moments
    /// `kappa_j (y_{j-1} - 2 y_j + y_{j+1})`; returns the bending energy, J.
    pub fn drift(&mut self, dt: f64, kappa: &[f64]) -> f64 {
        let h = 0.5 * dt * dt;
        self.ball.y += self.ball.v * dt + self.ab * h;
        self.th += self.om * dt + self.al * h;
        drift_nodes(&mut self.y, &self.v, &self.a, dt, h);
        Beam::bending_moments(kappa, &self.y, &mut self.moment)
    }

    /// New accelerations from the bending moments and the contact force `f`, and the velocity
    /// half-kicks `v += (a_old + a_new) dt / 2`; returns the beam's kinetic energy (J) and
    /// momentum (kg m/s).
    pub fn kick(&mut self, dt: f64, f: f64, model: &FdModel) -> (f64, f64) {
        if !model.hand.is_empty() {
            return self.kick_held(dt, f, model);
        }
        let half = 0.5 * dt;
        self.kick_ball_and_twist(half, f, model);
        let forces = model.impact.coupling.nodal_forces(f);
        for (j, f) in forces {
            self.load[j] += f;
        }
        let [twice_ke, mom] =
            kick_nodes(&mut self.v, &mut self.a, &self.moment, &self.load, &model.impact.basis.pad, half);
        for (j, _) in forces {
            self.load[j] = 0.0;
        }
        (0.5 * twice_ke, mom)
    }

    /// Replace the contact force of the last kick by one `df` larger (used at the phase switch).
    pub fn correct_force(&mut self, dt: f64, df: f64, model: &FdModel) {
        let half = 0.5 * dt;
        let dab = -df * model.inv_ball_mass;
        self.ab += dab;
        self.ball.v += dab * half;
        let dal = df * model.twist_per_force;
        self.al += dal;
        self.om += dal * half;
        let [j0, j1] = model.impact.coupling.load.nodes;
        let [w0, w1] = model.impact.coupling.load.weights;
        for (j, w) in [(j0, w0), (j1, w1)] {
            let im = model.impact.basis.pad.inv_mass[j];
            // a hand's damper at the node takes part implicitly, as in the kick
            let c = model.hand.get(j).map_or(0.0, |h| h.1);
            let dv = w * df * im * half / (1.0 + c * im * half);
            let v_old = self.v[j];
            self.v[j] += dv;
            self.a[j] += (w * df - c * dv) * im;
            self.hand_loss += half * c * (self.v[j] * self.v[j] - v_old * v_old);
            self.hand_impulse += half * c * dv;
        }
    }
}

/// The nodes' drift `y += v dt + a h` (`h = dt^2 / 2`). A function of its own so that the slices
/// are known not to overlap and the loop vectorises without run-time checks.
#[inline]
fn drift_nodes(y: &mut [f64], v: &[f64], a: &[f64], dt: f64, h: f64) {
    for ((y, v), a) in y.iter_mut().zip(v).zip(a) {
        *y += v * dt + a * h;
    }
}

/// The nodes' accelerations from the bending moments (`moment[i..i + 3]` around node i) and the
/// contact force `load`, the half-kicks `v += (a_old + a_new) dt / 2` (`half = dt / 2`), and the
/// sums `[sum m v^2, sum m v]` of the new velocities (four partial sums each, over the chunks of
/// four nodes of [`Padded`]); as [`drift_nodes`], a function of its own so that the loops
/// vectorise.
#[inline]
fn kick_nodes(v: &mut [f64], a: &mut [f64], moment: &[f64], load: &[f64], pad: &Padded, half: f64) -> [f64; 2] {
    let lanes = pad.lanes;
    let (v, a) = (&mut v[..lanes], &mut a[..lanes]);
    // the three moments around node i as three shifted slices
    let (left, centre, right) = (&moment[..lanes], &moment[1..lanes + 1], &moment[2..lanes + 2]);
    let moments = left.iter().zip(centre).zip(right);
    let nodes = load.iter().zip(&pad.inv_mass);
    for (((v, a), ((l, c), r)), (f, im)) in v.iter_mut().zip(a.iter_mut()).zip(moments).zip(nodes) {
        let an = (Beam::elastic_force(&[*l, *c, *r]) + f) * im;
        *v += (*a + an) * half;
        *a = an;
    }
    let (mut twice_ke, mut momentum) = ([0.0; 4], [0.0; 4]);
    for (v, m) in v.chunks_exact(4).zip(pad.mass.chunks_exact(4)) {
        for k in 0..4 {
            let p = m[k] * v[k];
            twice_ke[k] += p * v[k];
            momentum[k] += p;
        }
    }
    let total = |x: [f64; 4]| (x[0] + x[2]) + (x[1] + x[3]);
    [total(twice_ke), total(momentum)]
}
