//! The set-up of a prepared modal model that one impact shares with every other impact of the
//! same racket, impact point, strings and ball: the retained coordinates (`w^2`, `w`, `g`), the
//! truncated modes' static flexibility, the coupled modes of the compression phase and the time
//! of maximum compression (per unit incident speed) and the step tables (per step length). None of them depends on the incident
//! speed, angle, azimuth, spin or friction (but for the resolution, [`super::Resolution::of`]:
//! an oblique or spinning impact under a law with mechanisms keeps more modes than a normal one
//! or one under `elastic`, so those two kinds have set-ups of their own), so a sweep or an
//! uncertainty run over those builds them once per impact point (the beam's own modes are shared more widely still, by racket,
//! [`crate::model::basis`]).
//!
//! Each thread keeps the last set-up it built, keyed by the exact bits of everything it is
//! computed from, so a model built from it is the one built afresh, bit for bit. A sweep whose
//! inner axes are the speed, angle, azimuth, spin or friction finds its set-up there (a sweep of
//! 1000 points over x, r and v1: 123,000 instructions a point against 204,000 without); a sweep
//! over impact points and strings, where no two points share one, pays a key comparison a point
//! and frees each set-up one point later. Keeping more set-ups (16 were tried) would serve an
//! inner impact-point axis too, but on a million-point sweep over x, r and ks the held set-ups
//! cost more in the allocator and the caches than they save (a few per cent of the CPU time).

use std::cell::RefCell;
use std::sync::{Arc, OnceLock};

use crate::model::basis::Basis;
use crate::model::coupling::Coupling;
use crate::params::Params;
use crate::solve::modal::compression::Compression;
use crate::solve::modal::steps::Grid;
use crate::solve::modal::{Resolution, LEVELS, START};

/// The shared set-up (a model holds it behind a reference count).
#[derive(Debug)]
pub(super) struct Shared {
    /// Per coordinate (rigid first, then the retained flexible modes): `w^2`, `w`, `g`.
    pub lam: Vec<f64>,
    pub omega: Vec<f64>,
    pub g: Vec<f64>,
    /// Static flexibility of the truncated modes at the load point, m/N.
    pub residual: f64,
    /// Step tables of each level (the coarsest built with the set-up, the others when first
    /// needed by any impact that shares them).
    pub grids: [OnceLock<Grid>; LEVELS],
    /// The compression phase in closed form.
    pub compression: Compression,
    /// The beam the set-up was built on (held so that its address, part of the key, is not
    /// reused by another beam while the set-up is cached).
    _basis: Arc<Basis>,
}

/// Everything a [`Shared`] set-up is computed from: the beam (by address), the load nodes and
/// the bits of their weights, the offset `r`, the roll inertia, the ball's mass, `k1` and `p`,
/// the string-plane stiffness and the resolution's mode cut-off and step phase. (The model's time
/// limit, within which the set-up looks for maximum compression, follows from the ball's mass,
/// `k1` and the string-plane stiffness, so it needs no bits of its own.)
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(super) struct Key {
    basis: usize,
    nodes: [usize; 2],
    bits: [u64; 10],
}

impl Key {
    /// The key of the set-up for `params` (the given ones: ball and strings) on the normal
    /// model's beam `basis` and `coupling`.
    pub fn of(basis: &Arc<Basis>, coupling: &Coupling, params: &Params, res: Resolution) -> Key {
        let l = &coupling.load;
        Key {
            basis: Arc::as_ptr(basis) as usize,
            nodes: l.nodes,
            bits: [
                l.weights[0].to_bits(),
                l.weights[1].to_bits(),
                coupling.r.to_bits(),
                params.racket.ix.to_bits(),
                params.ball.mass.to_bits(),
                params.ball.k1.to_bits(),
                params.ball.p.to_bits(),
                params.strings.ks.to_bits(),
                res.mode_cutoff.to_bits(),
                res.phase_per_step.to_bits(),
            ],
        }
    }
}

thread_local! {
    /// This thread's last set-up and its key.
    static LAST: RefCell<Option<(Key, Arc<Shared>)>> = const { RefCell::new(None) };
}

impl Shared {
    /// A new set-up, not yet cached, with the step table of the coarsest level (step `h`, s).
    pub fn new(
        lam: Vec<f64>,
        g: Vec<f64>,
        residual: f64,
        compression: Compression,
        basis: &Arc<Basis>,
        h: f64,
    ) -> Arc<Shared> {
        let omega: Vec<f64> = lam.iter().map(|l| l.sqrt()).collect();
        let grids: [OnceLock<Grid>; LEVELS] = Default::default();
        let _ = grids[START].set(Grid::new(&lam, &omega, &g, residual, h));
        Arc::new(Shared { lam, omega, g, residual, grids, compression, _basis: Arc::clone(basis) })
    }

    /// This thread's cached set-up of `key`, if any.
    pub fn cached(key: &Key) -> Option<Arc<Shared>> {
        LAST.with(|c| c.borrow().as_ref().filter(|(k, _)| k == key).map(|(_, s)| Arc::clone(s)))
    }

    /// Keep `shared` as this thread's set-up of `key` (in place of the one kept before).
    pub fn keep(shared: &Arc<Shared>, key: Key) {
        LAST.with(|c| *c.borrow_mut() = Some((key, Arc::clone(shared))));
    }
}

#[cfg(test)]
mod tests {
    use crate::params::{Params, SolverKind};
    use crate::solve::modal::{ModalModel, Resolution};

    /// The paper's impact at `x`, `r`, `ks` with the modal solver.
    fn at(x: f64, r: f64, ks: f64) -> Params {
        let mut p = Params::paper();
        p.numerics.solver = SolverKind::Modal;
        (p.impact.x, p.impact.r, p.strings.ks) = (x, r, ks);
        p
    }

    /// Every result a model built from the cache gives is the fresh model's, bit for bit (the
    /// `Debug` text of an `f64` is its shortest exact form): over speeds, angles, azimuths,
    /// spins and friction that share a set-up, and over impact points and strings that do not.
    #[test]
    fn a_cached_set_up_gives_the_fresh_models_results_bit_for_bit() {
        for (x, r, ks) in [(0.16, 0.05, 2.74e4), (0.30, 0.0, 1.5e4), (0.45, 0.08, 4e4), (0.16, 0.05, 2.74e4)] {
            for (v1, angle, azimuth, spin, mu) in [
                (7.0, 0.0, 0.0, 0.0, 0.4),
                (25.0, 0.0, 0.0, 0.0, 0.4),
                (15.0, 30.0, 0.0, 2000.0, 0.4),
                (15.0, 45.0, 90.0, -1500.0, 0.2),
                (3.0, 10.0, 180.0, 500.0, 0.6),
            ] {
                let mut p = at(x, r, ks);
                p.impact.v1 = v1;
                (p.oblique.angle_deg, p.oblique.azimuth_deg, p.oblique.spin_rpm, p.oblique.mu) =
                    (angle, azimuth, spin, mu);
                let cached = ModalModel::new(&p).unwrap();
                let fresh = ModalModel::build(&p, Resolution::of(&p), false).unwrap();
                assert_eq!(format!("{:?}", cached.run().unwrap()), format!("{:?}", fresh.run().unwrap()), "{p:?}");
            }
        }
        let a = ModalModel::new(&at(0.2, 0.03, 3e4)).unwrap();
        let mut faster = at(0.2, 0.03, 3e4);
        faster.impact.v1 = 30.0;
        let b = ModalModel::new(&faster).unwrap();
        assert!(std::sync::Arc::ptr_eq(&a.set, &b.set), "a speed shares the set-up");
        let c = ModalModel::new(&at(0.2, 0.03, 3.1e4)).unwrap();
        assert!(!std::sync::Arc::ptr_eq(&a.set, &c.set), "other strings do not");
    }
}
