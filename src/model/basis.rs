//! The discrete beam of one racket with its flexible modes, and the explicit solver's padded
//! node arrays: computed once per racket and discretisation and cached, so a sweep over impact
//! points, speeds, strings or balls pays for the eigen-decomposition once.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use crate::model::beam::Beam;
use crate::params::Racket;

/// The discrete beam of one racket with its flexible modes: computed once per racket and
/// discretisation and cached, so a sweep over impact points, speeds, strings or balls pays for
/// the eigen-decomposition once.
#[derive(Debug)]
pub struct Basis {
    /// The discrete beam.
    pub beam: Beam,
    /// The explicit solver's node arrays, padded with zeros to whole chunks of four nodes.
    pub pad: Padded,
    /// Flexible modes, ascending: `omega^2`, rad^2/s^2.
    pub lam: Vec<f64>,
    /// `omega`, rad/s.
    pub omega: Vec<f64>,
    /// Shapes normalised to unit modal mass (`phi^T M phi = 1`), one per flexible mode.
    pub shapes: Vec<Vec<f64>>,
}

/// The explicit solver's node arrays padded with zeros: `lanes` (a multiple of four, at least the
/// node count) entries of mass and inverse mass, `lanes + 2` of `kappa` (the state `y`, `v`, `a`
/// has as many). The padding nodes have no mass, inverse mass or stiffness, so they never move
/// and carry no moment, and the loops over them run in whole chunks of four without a remainder.
#[derive(Debug)]
pub struct Padded {
    /// A multiple of four, at least the node count.
    pub lanes: usize,
    /// `m_i`, kg.
    pub mass: Vec<f64>,
    /// `1 / m_i`, 1/kg.
    pub inv_mass: Vec<f64>,
    /// `kappa_i`, N/m.
    pub kappa: Vec<f64>,
}

impl Padded {
    /// The padded arrays of a beam.
    pub(crate) fn new(beam: &Beam) -> Self {
        let n = beam.nodes();
        let lanes = n.div_ceil(4) * 4;
        let padded = |x: &[f64], len: usize| {
            let mut v = x.to_vec();
            v.resize(len, 0.0);
            v
        };
        let inv_mass: Vec<f64> = beam.mass.iter().map(|m| 1.0 / m).collect();
        Padded {
            lanes,
            mass: padded(&beam.mass, lanes),
            inv_mass: padded(&inv_mass, lanes),
            kappa: padded(&beam.kappa, lanes + 2),
        }
    }
}

/// Cached bases, keyed by the beam-defining numbers of the racket and the segment count, with
/// the bytes they hold.
static BASES: OnceLock<Mutex<BasisCache>> = OnceLock::new();
/// The cached bases and the bytes they hold.
type BasisCache = (HashMap<BasisKey, Arc<Basis>>, usize);
/// The bits of the segment count, length, mass and EI, and of the profile's knots, densities,
/// stiffnesses and tilt when there is one (no heap: looked up once per impact).
type BasisKey = ([u64; 4], Option<[u64; 14]>);
/// The cache is emptied before it would hold more than this many bytes of modes (a sweep over
/// many rackets on fine beams would otherwise keep N^2 numbers per racket).
const BASIS_CACHE_BYTES: usize = 32 << 20;

impl Basis {
    /// The basis of a racket on `segments` segments, from the cache or computed.
    pub fn of(racket: &Racket, segments: usize) -> Arc<Basis> {
        let profile = racket.profile.as_ref().map(|p| {
            let mut bits = [0; 14];
            for (b, v) in bits.iter_mut().zip(p.knots.iter().chain(&p.density).chain(&p.stiffness).chain(&p.tilt)) {
                *b = v.to_bits();
            }
            bits
        });
        let key: BasisKey =
            ([segments as u64, racket.length.to_bits(), racket.mass.to_bits(), racket.ei.to_bits()], profile);
        let cache = BASES.get_or_init(|| Mutex::new((HashMap::new(), 0)));
        if let Some(b) = cache.lock().unwrap_or_else(|e| e.into_inner()).0.get(&key) {
            return Arc::clone(b);
        }
        let beam = Beam::new(racket, segments);
        let (lam, shapes) = beam.modes_mass_normalised();
        let omega = lam.iter().map(|l| l.max(0.0).sqrt()).collect();
        let pad = Padded::new(&beam);
        let basis = Arc::new(Basis { beam, pad, lam, omega, shapes });
        // the shapes, and eight arrays of about one number per node (the beam's x, mass and
        // kappa, the padded mass, inverse mass and kappa, the eigenvalues and frequencies)
        let bytes = 8 * (basis.shapes.len() + 8) * basis.beam.nodes();
        let mut guard = cache.lock().unwrap_or_else(|e| e.into_inner());
        let (map, held) = &mut *guard;
        if *held + bytes > BASIS_CACHE_BYTES {
            map.clear();
            *held = 0;
        }
        if map.insert(key, Arc::clone(&basis)).is_none() {
            *held += bytes;
        }
        basis
    }
}
