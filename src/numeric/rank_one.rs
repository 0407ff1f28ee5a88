//! The modes of uncoupled oscillators joined by one spring at a point: the eigenpairs of
//! `diag(lam) + kappa g g^T` (the ball, the frame's modes and the contact spring between them in
//! the compression phase, [`crate::solve::modal`]).
//!
//! The spring only couples the direction `g`, so the problem reduces to the secular equation
//! `1 + kappa sum_i g_i^2 / (lam_i - mu) = 0`: one root between each pair of distinct poles `lam_i`
//! and one above the last; the mode of root `mu` is `g_i / (lam_i - mu)`, normalised (Golub 1973;
//! the divide-and-conquer eigensolvers rest on it). Poles that coincide (the rigid coordinates,
//! all at `lam = 0`) are first merged into one along their part of `g`; a coordinate with no part
//! in `g` is not coupled and is left out. Each root is found by the rational iteration of Bunch,
//! Nielsen and Sorensen (1978; the poles on each side of the root replaced by one pole with the
//! same value and slope, whose root is a quadratic's), kept inside its interval by bisection
//! ([`super::root::Bracket`]), with `mu` measured from the nearer pole so that no digits are
//! lost next to it: three to seven iterations a root. The cost is of order `n^2`, against `n^3`
//! for a dense decomposition.

use super::root::Bracket;

/// Poles closer than this fraction of the largest are one pole.
const SAME_POLE: f64 = 1e-12;
/// A coordinate whose share of `g^2` is below this is not coupled.
const UNCOUPLED: f64 = 1e-28;

/// The coupled modes: frequencies squared `mu` (ascending) and mode shapes (unit length, over
/// all `n` coordinates; mode `k` at `shapes[k n..(k + 1) n]`).
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledModes {
    pub mu: Vec<f64>,
    pub shapes: Vec<f64>,
}

impl CoupledModes {
    /// Mode `k`'s shape.
    pub fn shape(&self, k: usize) -> &[f64] {
        let n = self.shapes.len() / self.mu.len().max(1);
        &self.shapes[k * n..(k + 1) * n]
    }
}

/// A pole of the secular equation: `lam`, the summed weight `g^2`, and its coordinates (a run of
/// consecutive ones, the poles ascending).
struct Pole {
    lam: f64,
    weight: f64,
    members: std::ops::Range<usize>,
}

/// The eigenpairs of `diag(lam) + kappa g g^T` (`kappa > 0`, `lam >= 0` ascending) whose mode has
/// a part in `g`, ascending. The eigenpairs left out are the coordinates (or combinations of
/// coordinates at one pole) orthogonal to `g`, unchanged by the spring.
pub fn coupled_modes(lam: &[f64], g: &[f64], kappa: f64) -> CoupledModes {
    debug_assert!(lam.windows(2).all(|w| w[0] <= w[1]), "poles must ascend");
    let total: f64 = g.iter().map(|g| g * g).sum();
    let top = lam.iter().fold(0.0f64, |a, &b| a.max(b));
    let mut poles: Vec<Pole> = Vec::new();
    for (i, (&l, &gi)) in lam.iter().zip(g).enumerate() {
        if gi * gi <= UNCOUPLED * total {
            continue;
        }
        match poles.last_mut() {
            // (a coordinate left out between two at the same pole gets its own tiny g in the
            // shape: below 1e-14 of it)
            Some(p) if l - p.lam <= SAME_POLE * top => {
                p.weight += gi * gi;
                p.members.end = i + 1;
            }
            _ => poles.push(Pole { lam: l, weight: gi * gi, members: i..i + 1 }),
        }
    }
    let (n, m) = (lam.len(), poles.len());
    let mut modes = CoupledModes { mu: Vec::with_capacity(m), shapes: vec![0.0; m * n] };
    let mut delta = vec![0.0; m];
    // `kappa g^2` of each pole
    let weight: Vec<f64> = poles.iter().map(|p| kappa * p.weight).collect();
    for k in 0..m {
        // the interval of root k, and the nearer of its poles as the origin
        let lo = poles[k].lam;
        let hi = if k + 1 < m { poles[k + 1].lam } else { lo + kappa * total };
        let mid = 0.5 * (lo + hi);
        let at_mid = 1.0 + kappa * poles.iter().map(|p| p.weight / (p.lam - mid)).sum::<f64>();
        let origin = if at_mid >= 0.0 || k + 1 == m { k } else { k + 1 };
        let o = poles[origin].lam;
        for (d, p) in delta.iter_mut().zip(&poles) {
            *d = p.lam - o;
        }
        // tau = mu - o within (lo - o, hi - o), on the side of the origin
        let last = k + 1 == m;
        let mut bracket = match (origin == k, last) {
            (true, true) => Bracket::new(0.0, hi - o),
            (true, false) => Bracket::new(0.0, mid - o),
            _ => Bracket::new(mid - o, 0.0),
        };
        let mut tau = bracket.mid();
        for _ in 0..100 {
            // the poles left of the root (through k) and right of it, their sums and slopes
            let sums = |range: std::ops::Range<usize>| {
                let (mut s, mut ds) = (0.0, 0.0);
                for (d, w) in delta[range.clone()].iter().zip(&weight[range]) {
                    let r = 1.0 / (d - tau);
                    let t = w * r;
                    s += t;
                    ds += t * r;
                }
                (s, ds)
            };
            let ((psi, dpsi), (phi, dphi)) = (sums(0..k + 1), sums(k + 1..m));
            let f = 1.0 + psi + phi;
            bracket.narrow(tau, f < 0.0);
            // each side as one pole with the same value and slope, and the root of that
            // (Bunch, Nielsen and Sorensen 1978): a quadratic, solved without cancellation
            // from the origin's side
            let a_l = delta[k] - tau;
            let q_l = dpsi * a_l * a_l;
            let c = 1.0 + (psi - dpsi * a_l);
            let next = if last {
                if c > 0.0 {
                    delta[k] + q_l / c
                } else {
                    f64::NAN
                }
            } else {
                let a_r = delta[k + 1] - tau;
                let q_r = dphi * a_r * a_r;
                let c = c + (phi - dphi * a_r);
                let d = a_r - a_l;
                // distance y from the left pole: c y^2 - bb y + q_l d = 0; from the right pole:
                // c y^2 - e y - q_r d = 0; each root in the form without cancellation (as
                // LAPACK's dlaed4 chooses it)
                let bb = c * d + q_l + q_r;
                let e = c * d - q_l - q_r;
                let sq = (bb * bb - 4.0 * c * q_l * d).max(0.0).sqrt();
                if origin == k {
                    delta[k] + if bb >= 0.0 { 2.0 * q_l * d / (bb + sq) } else { (bb - sq) / (2.0 * c) }
                } else {
                    delta[k + 1] - if e <= 0.0 { 2.0 * q_r * d / (sq - e) } else { (e + sq) / (2.0 * c) }
                }
            };
            let tol = 4.0 * f64::EPSILON * (o.abs() + tau.abs());
            // converged: the step is at rounding level, or `f` is (its terms cancel to about
            // `m eps` of their size; no step can do better)
            let noise = 8.0 * f64::EPSILON * m as f64 * (1.0 + psi.abs() + phi.abs());
            if f.abs() <= noise || bracket.hi - bracket.lo <= tol {
                break;
            }
            if next >= bracket.lo && next <= bracket.hi && (next - tau).abs() <= tol {
                tau = next;
                break;
            }
            tau = bracket.inside_or_mid(next);
            if bracket.hi <= bracket.lo {
                break;
            }
        }
        // the mode: g_i / (lam_i - mu) on each pole, spread over its coordinates along g
        let shape = &mut modes.shapes[k * n..(k + 1) * n];
        for (d, p) in delta.iter().zip(&poles) {
            let r = 1.0 / (d - tau);
            for i in p.members.clone() {
                shape[i] = g[i] * r;
            }
        }
        let norm = shape.iter().map(|s| s * s).sum::<f64>().sqrt();
        shape.iter_mut().for_each(|s| *s /= norm);
        modes.mu.push(o + tau);
    }
    modes
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rigid poles (four at zero, as the modal solver has them), well separated and close flexible
    /// poles, one uncoupled coordinate: the coupled pairs match a dense decomposition and are
    /// eigenpairs to rounding.
    #[test]
    fn coupled_modes_are_the_eigenpairs_of_the_dense_matrix() {
        let lam = [0.0, 0.0, 0.0, 0.0, 6.1e5, 4.6e6, 4.6e6 * (1.0 + 1e-6), 1.8e7, 4.8e7, 1.3e9];
        let g = [-4.2, 1.1, -2.0, 0.7, 0.9, -0.4, 0.3, 0.0, 0.2, 0.05];
        let kappa = 2.0e4;
        let n = lam.len();
        let modes = coupled_modes(&lam, &g, kappa);
        let dense = nalgebra::DMatrix::from_fn(n, n, |i, j| kappa * g[i] * g[j] + if i == j { lam[i] } else { 0.0 });
        let eigen = nalgebra::SymmetricEigen::new(dense.clone());
        // one root per distinct coupled pole: zero, 6.1e5, the two close ones, 4.8e7, 1.3e9
        assert_eq!(modes.mu.len(), 6);
        for (k, &mu) in modes.mu.iter().enumerate() {
            let z = nalgebra::DVector::from_column_slice(modes.shape(k));
            let residual = (&dense * &z - mu * &z).norm();
            assert!(residual <= 1e-12 * 1.3e9, "mu {mu}: residual {residual:e}");
            assert!((z.norm() - 1.0).abs() < 1e-14);
            // the same eigenvalue in the dense spectrum
            let nearest = eigen.eigenvalues.iter().map(|e| (e - mu).abs()).fold(f64::INFINITY, f64::min);
            assert!(nearest <= 1e-9 * mu.max(1.0), "mu {mu}: {nearest:e}");
        }
        // rigid poles only (every flexible mode truncated): one coupled mode, kappa |g|^2
        let one = coupled_modes(&[0.0; 3], &[-4.2, 1.1, 0.3], kappa);
        assert_eq!(one.mu.len(), 1);
        let expected = kappa * (4.2f64 * 4.2 + 1.1 * 1.1 + 0.3 * 0.3);
        assert!((one.mu[0] / expected - 1.0).abs() < 1e-14, "{} vs {expected}", one.mu[0]);
        // the modes are orthogonal
        for i in 0..modes.mu.len() {
            for j in i + 1..modes.mu.len() {
                let dot: f64 = modes.shape(i).iter().zip(modes.shape(j)).map(|(x, y)| x * y).sum();
                assert!(dot.abs() < 1e-10, "{dot:e}");
            }
        }
    }

    /// Random spectra (clusters of close poles, weights over many decades, soft to stiff springs):
    /// every coupled pair is an eigenpair to rounding and its eigenvalue is the dense one.
    #[test]
    fn coupled_modes_of_random_spectra_are_eigenpairs_to_rounding() {
        let mut rnd = crate::test_rng::uniform(0x9e37_79b9_7f4a_7c15);
        let mut worst: f64 = 0.0;
        for _ in 0..2000 {
            let n = 2 + (rnd() * 12.0) as usize;
            let mut lam: Vec<f64> = (0..n)
                .map(|i| {
                    if i < 2 {
                        0.0
                    } else {
                        10f64.powf(4.0 + 5.0 * rnd()) * if rnd() < 0.2 { 1.0 } else { 1.0 + rnd() }
                    }
                })
                .collect();
            lam.sort_by(f64::total_cmp);
            let g: Vec<f64> = (0..n).map(|_| (rnd() - 0.5) * 10f64.powf(-3.0 * rnd())).collect();
            let kappa = 10f64.powf(2.0 + 6.0 * rnd());
            let modes = coupled_modes(&lam, &g, kappa);
            let dense =
                nalgebra::DMatrix::from_fn(n, n, |i, j| kappa * g[i] * g[j] + if i == j { lam[i] } else { 0.0 });
            let scale = dense.norm();
            for (k, &mu) in modes.mu.iter().enumerate() {
                let z = nalgebra::DVector::from_column_slice(modes.shape(k));
                worst = worst.max((&dense * &z - mu * &z).norm() / scale);
            }
        }
        // the quadratic's root must be taken in its stable form: here (a review's random case:
        // a heavy rigid pole, two poles 1e-13 apart) the other form cancels to 8 digits
        let lam = [
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            5.817219917722922,
            7.505972290999782,
            7.505972291000709,
            34.16230324285774,
            61.43881333517675,
            165.47066056850954,
            46708.80629080856,
            191251.7812075173,
            295459.61268992553,
            1822674.4455295948,
            3633649.05455003,
            265121258.45183626,
            411954505.42754567,
            1904009962.1855974,
        ];
        let g = [
            0.02078134334223303,
            0.030882152296971666,
            354.83546564712066,
            0.0,
            -0.001481546930035708,
            0.12817613137591677,
            -0.013774826995441025,
            0.005220760268135376,
            -1.5194284324256562,
            0.0058687909914302925,
            0.18599488162712532,
            -1.08243558505006,
            -0.0007054709046554313,
            -0.023535449468362103,
            -0.28672658013151336,
            -0.005720046632335435,
            -0.00040818592007424036,
            -0.0013249422192553714,
            0.010783177553771891,
        ];
        let (kappa, n) = (1.0287538849087548e4, lam.len());
        let modes = coupled_modes(&lam, &g, kappa);
        let dense = nalgebra::DMatrix::from_fn(n, n, |i, j| kappa * g[i] * g[j] + if i == j { lam[i] } else { 0.0 });
        let eigen = nalgebra::SymmetricEigen::new(dense.clone());
        for (k, &mu) in modes.mu.iter().enumerate() {
            let nearest = eigen.eigenvalues.iter().map(|e| (e - mu).abs()).fold(f64::INFINITY, f64::min);
            assert!(nearest <= 1e-13 * dense.norm(), "mu {mu}: {nearest:e}");
            let z = nalgebra::DVector::from_column_slice(modes.shape(k));
            worst = worst.max((&dense * &z - mu * &z).norm() / dense.norm());
        }
        assert!(worst < 1e-10, "largest residual {worst:e} of the matrix norm");
    }
}
