//! The ball's state and the coupling of the contact point to the frame (Eq 8): the ball meets
//! the strings at the load point ([`LoadPoint`], the nodes that carry the force and their
//! weights) at a distance `r` from the long axis, so
//! ```text
//! Y_T = y_b - (sum_i w_i y_i + r theta)        (translation and bending at the load point, twist)
//! ```
//! and, by reciprocity, the contact force `F` acts back with the same weights: `-F` on the
//! ball, `w_i F` on load node `i`, `F r` on the twist. Both time-stepping solvers take their
//! compression and their force distribution from here: the explicit solver on the nodes, the
//! modal solver as each coordinate's amplitude at the load point.

use crate::model::beam::{Beam, LoadPoint};

/// The ball's state normal to the string plane (it grows with the tangential motion and spin
/// of an oblique impact).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BallState {
    /// Displacement `y_b`, m.
    pub y: f64,
    /// Velocity, m/s.
    pub v: f64,
}

/// Where and how the contact point is tied to the frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coupling {
    /// The load point on the beam.
    pub load: LoadPoint,
    /// Distance of the impact from the long axis, m.
    pub r: f64,
}

impl Coupling {
    /// The coupling of an impact at the load point `load`, `r` from the long axis.
    pub fn new(load: LoadPoint, r: f64) -> Self {
        Coupling { load, r }
    }

    /// The frame's value at the load point of a nodal field (displacement, velocity or a mode
    /// shape): `sum_i w_i y_i`.
    #[inline(always)]
    pub fn at_load(&self, y: &[f64]) -> f64 {
        let [j0, j1] = self.load.nodes;
        let [w0, w1] = self.load.weights;
        w0 * y[j0] + w1 * y[j1]
    }

    /// The total compression `Y_T = y_b - (sum_i w_i y_i + r theta)` of a ball at `yb`, nodes at
    /// `y` and a twist `theta` (and, from the rates, its rate), m.
    #[inline(always)]
    pub fn compression(&self, yb: f64, y: &[f64], theta: f64) -> f64 {
        yb - (self.at_load(y) + self.r * theta)
    }

    /// The contact force `f` on the load nodes: `(node, w_i f)` for each.
    #[inline(always)]
    pub fn nodal_forces(&self, f: f64) -> [(usize, f64); 2] {
        let [j0, j1] = self.load.nodes;
        let [w0, w1] = self.load.weights;
        [(j0, w0 * f), (j1, w1 * f)]
    }

    /// `|g|^2` of the mass-normalised coupling vector of the ball (mass `mb`), the load nodes
    /// (node masses `mass`) and the twist (`ix`), 1/kg: a contact spring `k` adds at most
    /// `k |g|^2` to the system's largest eigenvalue.
    pub fn mobility(&self, mb: f64, mass: &[f64], ix: f64) -> f64 {
        let lp = &self.load;
        1.0 / mb
            + lp.weights[0].powi(2) / mass[lp.nodes[0]]
            + lp.weights[1].powi(2) / mass[lp.nodes[1]]
            + self.r.powi(2) / ix
    }

    /// The amplitudes at the contact point of the rigid coordinates in mass-normalised form:
    /// the ball (`sqrt(m_b) y_b`, amplitude `-1/sqrt(m_b)`), the racket's translation, its
    /// rotation about the centre of mass, and the twist (`sqrt(I_x) theta`).
    pub fn rigid_amplitudes(&self, mb: f64, beam: &Beam, ix: f64) -> [f64; 4] {
        let g_t = 1.0 / beam.total_mass.sqrt();
        let g_r = (self.load.x_load - beam.x_cm) / beam.i_cm.sqrt();
        let g_tw = self.r / ix.sqrt();
        [-1.0 / mb.sqrt(), g_t, g_r, g_tw]
    }
}
