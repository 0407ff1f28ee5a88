//! The racket as a free-free lumped Euler-Bernoulli beam (Eqs 5-6, SPEC.md section 1).
//!
//! ```text
//! nodes       x_i = i s,  i = 0..N,  s = L/N,  tip at x = 0, butt at x = L
//! masses      m = M/N at interior nodes, m/2 at the two end nodes
//! stiffness   K = D^T diag(kappa_j) D,  kappa_j = EI(x_j) / s^3,
//!             D the (N-1) x (N+1) second difference (rows 1 -2 1)
//! ```
//! `D^T D` is the energy-consistent form of Eq 6 with free ends (`y'' = y''' = 0`): the bending
//! energy is `sum_j kappa_j (y_{j-1} - 2 y_j + y_{j+1})^2 / 2`, and `K` has exactly two zero
//! modes (translation and rotation), so the discrete beam conserves momentum and energy.
//!
//! A non-uniform racket ([`Profile`]) lumps its density (piecewise linear, optionally times
//! the tilt `exp(t1 f + t2 f^2)`) onto the nodes (`m_i = integral of lambda(x) h_i(x) dx` with
//! the hat function `h_i` of node i, which for a uniform density gives the masses above;
//! exact by Simpson's rule without a tilt, by five-point Gauss-Legendre with one), scaled so
//! they sum to `M`, and evaluates
//! `EI(x_j) = EI * stiffness(x_j / L)` at the interior nodes.
//! `K` is applied as a five-point stencil; the dense matrix exists only for the eigenproblem
//! `K phi = omega^2 M phi`, solved as the symmetric problem `M^-1/2 K M^-1/2` with nalgebra.

use nalgebra::DMatrix;

use crate::params::{LoadRule, Profile, Racket};

/// The discrete beam.
#[derive(Debug, Clone)]
pub struct Beam {
    /// Number of segments `N`.
    pub segments: usize,
    /// Segment length `s = L/N`, m.
    pub s: f64,
    /// Node positions from the tip, m (N+1 values).
    pub x: Vec<f64>,
    /// Lumped node masses, kg (N+1 values).
    pub mass: Vec<f64>,
    /// `kappa_j = EI(x_j) / s^3` at each node, N/m (the two end entries are 0: no curvature
    /// is defined there).
    pub kappa: Vec<f64>,
    /// Total mass, kg.
    pub total_mass: f64,
    /// Centre of mass from the tip, m.
    pub x_cm: f64,
    /// Moment of inertia about the transverse axis through the centre of mass, kg m^2.
    pub i_cm: f64,
}

/// Where the contact force acts on the beam and how it is shared (SPEC.md, Contact).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadPoint {
    /// The (up to) two nodes that carry the force.
    pub nodes: [usize; 2],
    /// Their weights; they sum to 1.
    pub weights: [f64; 2],
    /// Where the force effectively acts, `sum w_i x_i`, m.
    pub x_load: f64,
}

/// Eigenfrequencies and mode shapes of the free-free beam.
#[derive(Debug, Clone)]
pub struct Modes {
    /// Angular frequencies `omega_k`, rad/s, ascending; the first two are the rigid-body modes.
    pub omega: Vec<f64>,
    /// Mode shapes (displacement at each node), same order, scaled so the largest |value| is 1
    /// and the tip value is >= 0.
    pub shapes: Vec<Vec<f64>>,
}

impl Beam {
    /// Discretise a racket into `segments` segments.
    pub fn new(racket: &Racket, segments: usize) -> Self {
        let n = segments;
        let s = racket.length / n as f64;
        let x: Vec<f64> = (0..=n).map(|i| i as f64 * s).collect();
        let (mass, mut kappa) = match &racket.profile {
            None => {
                let m = racket.mass / n as f64;
                let mut mass = vec![m; n + 1];
                mass[0] = 0.5 * m;
                mass[n] = 0.5 * m;
                (mass, vec![racket.ei / (s * s * s); n + 1])
            }
            Some(profile) => {
                let raw = lumped_masses(profile, n);
                let scale = racket.mass / raw.iter().sum::<f64>();
                let mass = raw.iter().map(|m| m * scale).collect();
                let kappa = (0..=n)
                    .map(|i| racket.ei * profile.at(&profile.stiffness, i as f64 / n as f64) / (s * s * s))
                    .collect();
                (mass, kappa)
            }
        };
        kappa[0] = 0.0;
        kappa[n] = 0.0;
        let total_mass: f64 = mass.iter().sum();
        let x_cm = mass.iter().zip(&x).map(|(m, x)| m * x).sum::<f64>() / total_mass;
        let i_cm = mass.iter().zip(&x).map(|(m, x)| m * (x - x_cm).powi(2)).sum();
        Beam { segments: n, s, x, mass, kappa, total_mass, x_cm, i_cm }
    }

    /// Number of nodes, N+1.
    pub fn nodes(&self) -> usize {
        self.segments + 1
    }

    /// The bending moments `kappa_j (y_{j-1} - 2 y_j + y_{j+1})` of the interior nodes into
    /// `moment[j + 1]`; returns the bending energy `y^T K y / 2`, J. The explicit solver's
    /// stencil. `kappa` is as long as `y` and `moment` two longer: the end nodes' moments and a
    /// pad on each side stay zero (the solver passes arrays padded with zero-stiffness nodes, see
    /// [`Padded`](crate::model::basis::Padded)).
    pub fn bending_moments(kappa: &[f64], y: &[f64], moment: &mut [f64]) -> f64 {
        // kappa is zero at the two end nodes (and at any padding), so their moments stay zero;
        // the interior nodes' neighbours as shifted slices, in chunks of four and a remainder
        let n = y.len() - 2;
        let whole = n - n % 4;
        let (left, centre, right) = (&y[..n], &y[1..n + 1], &y[2..n + 2]);
        let (kappa, inner) = (&kappa[1..n + 1], &mut moment[2..n + 2]);
        let mut twice_pe = [0.0; 4];
        let neighbours = left.chunks_exact(4).zip(centre.chunks_exact(4)).zip(right.chunks_exact(4));
        for ((m, k), ((l, c), r)) in inner.chunks_exact_mut(4).zip(kappa.chunks_exact(4)).zip(neighbours) {
            for j in 0..4 {
                let curvature = l[j] - 2.0 * c[j] + r[j];
                m[j] = k[j] * curvature;
                twice_pe[j] += m[j] * curvature;
            }
        }
        let mut tail = 0.0;
        for j in whole..n {
            let curvature = left[j] - 2.0 * centre[j] + right[j];
            inner[j] = kappa[j] * curvature;
            tail += inner[j] * curvature;
        }
        0.5 * ((twice_pe[0] + twice_pe[2]) + (twice_pe[1] + twice_pe[3]) + tail)
    }

    /// The elastic force on a node, `(-K y)_i = 2 M_i - M_{i-1} - M_{i+1}`, N, from the three
    /// moments around it (`moment[i..i + 3]` of [`Beam::bending_moments`]).
    #[inline(always)]
    pub fn elastic_force(m: &[f64]) -> f64 {
        2.0 * m[1] - m[0] - m[2]
    }

    /// Bending energy `y^T K y / 2`, J.
    pub fn bending_energy(&self, y: &[f64]) -> f64 {
        let n = self.segments;
        0.5 * (1..n).map(|j| self.kappa[j] * (y[j - 1] - 2.0 * y[j] + y[j + 1]).powi(2)).sum::<f64>()
    }

    /// Kinetic energy of the nodes, J.
    pub fn kinetic_energy(&self, v: &[f64]) -> f64 {
        0.5 * self.mass.iter().zip(v).map(|(m, v)| m * v * v).sum::<f64>()
    }

    /// Linear momentum, kg m/s.
    pub fn momentum(&self, v: &[f64]) -> f64 {
        self.mass.iter().zip(v).map(|(m, v)| m * v).sum()
    }

    /// Kinetic energy of the rigid-body part of a velocity field (translation of the centre of
    /// mass plus rotation about it), J. The rest of the racket's energy is vibration.
    pub fn rigid_energy(&self, v: &[f64]) -> f64 {
        let p = self.momentum(v);
        let l: f64 = self.mass.iter().zip(v).zip(&self.x).map(|((m, v), x)| m * (x - self.x_cm) * v).sum();
        p * p / (2.0 * self.total_mass) + l * l / (2.0 * self.i_cm)
    }

    /// The load point for an impact at `x` (0 <= x <= L) under a load rule.
    pub fn load_point(&self, x: f64, rule: LoadRule) -> LoadPoint {
        let n = self.segments;
        let xi = (x / self.s).clamp(0.0, n as f64);
        match rule {
            LoadRule::Node => {
                // round(x/s) with ties up
                let j = ((xi + 0.5).floor() as usize).min(n);
                LoadPoint { nodes: [j, j], weights: [1.0, 0.0], x_load: self.x[j] }
            }
            LoadRule::Hat => {
                let j = (xi.floor() as usize).min(n - 1);
                let w1 = xi - j as f64;
                let w0 = 1.0 - w1;
                LoadPoint { nodes: [j, j + 1], weights: [w0, w1], x_load: w0 * self.x[j] + w1 * self.x[j + 1] }
            }
        }
    }

    /// The dense stiffness matrix `K = D^T diag(kappa) D`.
    pub fn stiffness_matrix(&self) -> DMatrix<f64> {
        let n = self.nodes();
        let mut k = DMatrix::zeros(n, n);
        let stencil = [1.0, -2.0, 1.0];
        for j in 1..self.segments {
            for (a, sa) in stencil.iter().enumerate() {
                for (b, sb) in stencil.iter().enumerate() {
                    k[(j - 1 + a, j - 1 + b)] += self.kappa[j] * sa * sb;
                }
            }
        }
        k
    }

    /// `M^-1/2 K M^-1/2`, symmetric with the eigenvalues `omega^2`.
    fn mass_normalised_stiffness(&self) -> DMatrix<f64> {
        let mut a = self.stiffness_matrix();
        let n = self.nodes();
        for i in 0..n {
            for j in 0..n {
                a[(i, j)] /= (self.mass[i] * self.mass[j]).sqrt();
            }
        }
        a
    }

    /// Squared angular frequencies `omega^2` (rad^2/s^2), ascending (the first two are ~0).
    pub fn eigenvalues(&self) -> Vec<f64> {
        let mut ev: Vec<f64> = self.mass_normalised_stiffness().symmetric_eigenvalues().iter().copied().collect();
        ev.sort_by(f64::total_cmp);
        ev
    }

    /// All eigenfrequencies and mode shapes.
    pub fn modes(&self) -> Modes {
        let eig = self.mass_normalised_stiffness().symmetric_eigen();
        let mut order: Vec<usize> = (0..self.nodes()).collect();
        order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
        let mut omega = Vec::with_capacity(order.len());
        let mut shapes = Vec::with_capacity(order.len());
        for &k in &order {
            omega.push(eig.eigenvalues[k].max(0.0).sqrt());
            let mut phi: Vec<f64> = (0..self.nodes()).map(|i| eig.eigenvectors[(i, k)] / self.mass[i].sqrt()).collect();
            let peak = phi.iter().fold(0.0_f64, |acc, v| acc.max(v.abs()));
            let sign = if phi[0] < 0.0 { -1.0 } else { 1.0 };
            phi.iter_mut().for_each(|v| *v *= sign / peak);
            shapes.push(phi);
        }
        Modes { omega, shapes }
    }
}

impl Beam {
    /// The flexible modes (the two rigid-body modes left out), ascending: `omega^2` (rad^2/s^2)
    /// and shapes normalised to unit modal mass, `phi^T M phi = 1`.
    pub fn modes_mass_normalised(&self) -> (Vec<f64>, Vec<Vec<f64>>) {
        let eig = self.mass_normalised_stiffness().symmetric_eigen();
        let mut order: Vec<usize> = (0..self.nodes()).collect();
        order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
        let flexible = &order[2..];
        let lam = flexible.iter().map(|&k| eig.eigenvalues[k]).collect();
        let shapes = flexible
            .iter()
            .map(|&k| (0..self.nodes()).map(|i| eig.eigenvectors[(i, k)] / self.mass[i].sqrt()).collect())
            .collect();
        (lam, shapes)
    }
}

/// Node masses (up to a common scale) of a profile on `n` segments of unit total length: the
/// density integrated against each node's hat function on every piece between consecutive
/// breakpoints (the nodes and the knots). Untilted, the piecewise-linear density times a hat is
/// quadratic and Simpson's rule is exact; tilted, five-point Gauss-Legendre (tested against a
/// fine composite rule).
fn lumped_masses(profile: &Profile, n: usize) -> Vec<f64> {
    let h = 1.0 / n as f64;
    let mut mass = vec![0.0; n + 1];
    for seg in 0..n {
        let (a, b) = (seg as f64 * h, (seg + 1) as f64 * h);
        let mut cuts = vec![a];
        cuts.extend(profile.knots.iter().copied().filter(|&k| k > a && k < b));
        cuts.push(b);
        for w in cuts.windows(2) {
            let (lo, hi) = (w[0], w[1]);
            // exact for the untilted (piecewise-linear) density; a tilted one by five-point
            // Gauss-Legendre (exact to degree 9: rounding-level on a piece for any tilt a racket has)
            let simpson = |g: &dyn Fn(f64) -> f64| {
                if profile.tilt == [0.0; 2] {
                    (hi - lo) / 6.0 * (g(lo) + 4.0 * g(0.5 * (lo + hi)) + g(hi))
                } else {
                    gauss5(lo, hi, g)
                }
            };
            let dens = |f: f64| profile.density_at(f);
            // the hat of the left node falls from 1 at a to 0 at b; the right node's rises
            mass[seg] += simpson(&|f| dens(f) * (b - f) / h);
            mass[seg + 1] += simpson(&|f| dens(f) * (f - a) / h);
        }
    }
    mass
}

/// Five-point Gauss-Legendre quadrature of `g` over `lo..hi`.
fn gauss5(lo: f64, hi: f64, g: &dyn Fn(f64) -> f64) -> f64 {
    const NODES: [(f64, f64); 5] = [
        (0.0, 0.568_888_888_888_888_9),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    half * NODES.iter().map(|(t, w)| w * g(mid + half * t)).sum::<f64>()
}

impl Modes {
    /// Frequency of flexible mode `k` (1 = fundamental), Hz.
    pub fn frequency_hz(&self, k: usize) -> f64 {
        self.omega[k + 1] / (2.0 * std::f64::consts::PI)
    }

    /// Positions (m from the tip) where flexible mode `k` crosses zero, by linear interpolation
    /// between nodes.
    pub fn node_positions(&self, k: usize, x: &[f64]) -> Vec<f64> {
        let phi = &self.shapes[k + 1];
        let mut out = Vec::new();
        for i in 0..phi.len() - 1 {
            let (a, b) = (phi[i], phi[i + 1]);
            if a == 0.0 {
                out.push(x[i]);
            } else if a * b < 0.0 {
                out.push(x[i] + (x[i + 1] - x[i]) * a / (a - b));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// A tilted density's node masses (five-point Gauss-Legendre on each piece) equal the hat
    /// integrals computed independently by a 4000-panel composite Simpson rule on every
    /// segment, for tilts from a spec sheet's (|t| ~ 3) to far beyond any racket (|t| = 30).
    #[test]
    fn tilted_node_masses_match_a_fine_quadrature() {
        for tilt in [[-3.2, 3.4], [2.0, -5.0], [-30.0, 30.0], [30.0, -10.0]] {
            let profile =
                Profile { knots: [0.0, 0.48, 0.72, 1.0], density: [1.0, 1.0, 1.2, 1.2], stiffness: [1.0; 4], tilt };
            // five points on a piece are exact to degree 9: a coarse 4-segment beam only with a
            // spec sheet's tilt, the extreme tilts on the model's beams (N >= 39)
            let ns: &[usize] = if tilt[0].abs() < 5.0 { &[4, 39] } else { &[39, 120] };
            for &n in ns {
                let fast = lumped_masses(&profile, n);
                let h = 1.0 / n as f64;
                let fine = |lo: f64, hi: f64, g: &dyn Fn(f64) -> f64| {
                    let m = 4000;
                    let dx = (hi - lo) / m as f64;
                    (0..m)
                        .map(|k| {
                            let a = lo + k as f64 * dx;
                            dx / 6.0 * (g(a) + 4.0 * g(a + 0.5 * dx) + g(a + dx))
                        })
                        .sum::<f64>()
                };
                let mut slow = vec![0.0; n + 1];
                for seg in 0..n {
                    let (a, b) = (seg as f64 * h, (seg + 1) as f64 * h);
                    slow[seg] += fine(a, b, &|f| profile.density_at(f) * (b - f) / h);
                    slow[seg + 1] += fine(a, b, &|f| profile.density_at(f) * (f - a) / h);
                }
                for (i, (x, y)) in fast.iter().zip(&slow).enumerate() {
                    assert!(((x - y) / y).abs() < 1e-9, "tilt {tilt:?} N {n} node {i}: {x} vs {y}");
                }
            }
        }
    }

    #[test]
    fn stencil_equals_dense_stiffness() {
        // every remainder of the stencil's chunks of four, unpadded and padded as the solver runs it
        for segments in 12..=16 {
            let n = segments + 1;
            let beam = Beam::new(&Racket::default(), segments);
            let y: Vec<f64> = (0..n).map(|i| ((i * i) as f64 * 0.37).sin() * 1e-3).collect();
            let k = beam.stiffness_matrix();
            let dense = &k * nalgebra::DVector::from_vec(y.clone());
            let mut moment = vec![0.0; n + 2];
            let pe = Beam::bending_moments(&beam.kappa, &y, &mut moment);
            let f: Vec<f64> = moment.windows(3).map(Beam::elastic_force).collect();
            assert_relative_eq!(pe, beam.bending_energy(&y), max_relative = 1e-12);
            for i in 0..n {
                assert_relative_eq!(-f[i], dense[i], max_relative = 1e-12, epsilon = 1e-9);
            }
            let e_dense = 0.5 * nalgebra::DVector::from_vec(y.clone()).dot(&dense);
            assert_relative_eq!(beam.bending_energy(&y), e_dense, max_relative = 1e-12);
            // the solver's zero-stiffness padding nodes change no moment and add no energy
            let pad = crate::model::basis::Padded::new(&beam);
            let mut y_pad = y.clone();
            y_pad.resize(pad.lanes + 2, 0.0);
            let mut moment_pad = vec![0.0; pad.lanes + 4];
            let pe_pad = Beam::bending_moments(&pad.kappa, &y_pad, &mut moment_pad);
            assert_relative_eq!(pe_pad, pe, max_relative = 1e-14);
            assert_eq!(&moment_pad[..n + 2], &moment[..]);
            assert!(moment_pad[n + 2..].iter().all(|&m| m == 0.0));
        }
    }

    #[test]
    fn rigid_motions_carry_no_bending_force() {
        let beam = Beam::new(&Racket::default(), 39);
        let y: Vec<f64> = beam.x.iter().map(|x| 0.01 + 0.2 * x).collect();
        let mut moment = vec![0.0; 42];
        Beam::bending_moments(&beam.kappa, &y, &mut moment);
        let f: Vec<f64> = moment.windows(3).map(Beam::elastic_force).collect();
        assert!(f.iter().all(|v| v.abs() < 1e-6), "{f:?}");
        assert!(beam.bending_energy(&y) < 1e-12);
    }

    #[test]
    fn a_uniform_profile_gives_the_uniform_beam() {
        let flat = Profile { knots: [0.0, 0.3, 0.55, 1.0], density: [2.0; 4], stiffness: [1.0; 4], tilt: [0.0; 2] };
        let uniform = Beam::new(&Racket::default(), 39);
        let profiled = Beam::new(&Racket { profile: Some(flat), ..Racket::default() }, 39);
        for i in 0..40 {
            assert_relative_eq!(uniform.mass[i], profiled.mass[i], max_relative = 1e-13);
            assert_relative_eq!(uniform.kappa[i], profiled.kappa[i], max_relative = 1e-13);
        }
    }

    #[test]
    fn lumping_keeps_the_mass_and_the_first_moment_of_the_density() {
        // hat functions reproduce constants and linear functions exactly
        let p = Profile {
            knots: [0.0, 0.37, 0.61, 1.0],
            density: [1.0, 3.0, 0.5, 2.0],
            stiffness: [1.0; 4],
            tilt: [0.0; 2],
        };
        let m = lumped_masses(&p, 23);
        let fine = 200_000;
        let (mut m0, mut m1) = (0.0, 0.0);
        for k in 0..fine {
            let f = (k as f64 + 0.5) / fine as f64;
            m0 += p.at(&p.density, f) / fine as f64;
            m1 += f * p.at(&p.density, f) / fine as f64;
        }
        let xs: Vec<f64> = (0..=23).map(|i| i as f64 / 23.0).collect();
        assert_relative_eq!(m.iter().sum::<f64>(), m0, max_relative = 1e-8);
        assert_relative_eq!(m.iter().zip(&xs).map(|(m, x)| m * x).sum::<f64>(), m1, max_relative = 1e-8);
    }

    #[test]
    fn a_stiffer_frame_profile_raises_the_fundamental() {
        let soft = Profile { knots: [0.0, 0.4, 0.6, 1.0], density: [1.0; 4], stiffness: [1.0; 4], tilt: [0.0; 2] };
        let stiff = Profile { stiffness: [1.0, 1.5, 1.5, 1.2], ..soft };
        let f = |p| Beam::new(&Racket { profile: Some(p), ..Racket::default() }, 39).modes().frequency_hz(1);
        assert!(f(stiff) > f(soft) * 1.05);
    }

    #[test]
    fn hat_weights_reproduce_the_impact_point() {
        let beam = Beam::new(&Racket::default(), 39);
        for &x in &[0.0, 0.0123, 0.1, 0.158, 0.71] {
            let lp = beam.load_point(x, LoadRule::Hat);
            assert_relative_eq!(lp.x_load, x, epsilon = 1e-15);
            assert_relative_eq!(lp.weights[0] + lp.weights[1], 1.0);
        }
        // x = 10 cm lies at 5.49 segments: the paper's node rule loads node 5 (9.10 cm)
        let lp = beam.load_point(0.10, LoadRule::Node);
        assert_eq!(lp.nodes[0], 5);
    }
}
