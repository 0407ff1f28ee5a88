//! String-face maps: one impact at every point of a grid over the string face, in parallel,
//! as a table, a heat map and metadata (the `map` command).
//!
//! ## The face
//! A racket with a head outline
//! ([`Racket::head_length`](crate::params::Racket::head_length)) has the ellipse from the tip
//! (`x = 0`) to `head_length` along the racket and `2 half_width` across it:
//! `|r| <= half_width sqrt(1 - ((x - a) / a)^2)`, `a = head_length / 2` (the same expression
//! the impact validation uses). The paper's racket has no outline (its face is the strip
//! `0 <= x <= L`, `|r| <= half_width`); its map uses a default face: the ellipse
//! [`DEFAULT_FACE_LENGTH`] = 32 cm long from the tip and `2 half_width` wide (25 cm), whose
//! centre, 16 cm from the tip, is the paper's "centre of the strings" at the mode-1 node
//! (15.8 cm in the paper, 15.9 cm on the N = 39 beam). A racket shorter than 32 cm gets a face
//! as long as the racket.
//!
//! ## The grid
//! `nx` points along x from the tip to the end of the face and `nr` across r from
//! `-half_width` to `half_width`, both ends included (the face's bounding box). A point is
//! evaluated when it lies on or inside the outline, `|r| <= ` the local half width; the two
//! ends of the ellipse, where the width is zero (the tip `x = 0` and the far end), are skipped
//! as degenerate. Rows are in row-major order, x slowest then r, so the CSV is deterministic;
//! the impacts run in parallel (rayon) in chunks of [`CHUNK`] points with a progress callback
//! after each. Every point is one [`simulate`](crate::solve::simulate) call with the
//! configuration's parameters and the impact moved to `(x, r)`; a re-contact is kept as a
//! value, flagged in the `recontact` column.
//!
//! ## Quantities
//! `e_a` (apparent coefficient of restitution), `tau` (impact duration, ms), `theta` (twist at
//! the end of the impact, degrees, signed as r), `f_vib` (vibration energy, fraction of the
//! ball's incident kinetic energy) and `power` = 100 e_A (%, the "power potential" players
//! speak of). Each map also records the mode-1 nodes of the free racket inside the face (the
//! node nearest the head is "the node") and the point of maximum e_A.
//!
//! ## Difference maps
//! Two configurations (racket A against racket B, or one racket at two string tensions via
//! [`ks_from_tension_lb`](crate::params::ks_from_tension_lb)) on the same grid, which covers
//! both faces; only points inside both are evaluated, and the table gives A, B and B - A.
//!
//! ## Files
//! - [`quantity`]: what a map shows; [`face`]: the face and the grid; [`compute`]: running the
//!   impacts; [`figure`] and [`metadata`]: the table, heat map and JSON of a map;
//!   [`request`]: the `map` command's configurations; [`summary`]: its text summary. The files
//!   are written by [`crate::render::map_files`].

pub mod compute;
pub mod face;
pub mod figure;
pub mod metadata;
pub mod quantity;
pub mod request;
pub mod summary;

pub use compute::{mode1_nodes, params_at, validate_points, with_map_solver, DiffMap, FaceMap, MapPoint, Spread};
pub use face::{check_count, Face, Grid};
pub use metadata::config_metadata;
pub use quantity::Quantity;
pub use request::{MapOutcome, MapRequest};

/// Length of the default face of a racket without a head outline, m (the paper's "centre of
/// the strings" is its centre, 16 cm from the tip); declared with the racket's parameters.
pub use crate::params::DEFAULT_FACE_LENGTH;
/// Fewest grid points along either axis.
pub const MIN_GRID: usize = 2;
/// Most grid points along either axis.
pub const MAX_GRID: usize = 401;
/// Impacts per parallel chunk (the progress callback runs after each).
pub const CHUNK: usize = 256;

/// The parameters a map sets itself, each with why: the impact point (the grid sets it), and
/// the solver and its step ([`with_map_solver`]).
pub const MAP_SETS: [(crate::params::spec::ParamSpec, &str); 4] = {
    use crate::params::keys::{DT, R, SOLVER, X};
    const GRID: &str = "the grid sets the impact point (--nx, --nr over the string face)";
    const SOLVER_WHY: &str =
        "a map runs the modal solver wherever the model allows it, else fd with its automatic step";
    [(X, GRID), (R, GRID), (SOLVER, SOLVER_WHY), (DT, SOLVER_WHY)]
};

/// Why a map does not take the parameter `key`, if it sets it itself ([`MAP_SETS`]).
pub fn set_by_map(key: &str) -> Option<&'static str> {
    MAP_SETS.iter().find(|(s, _)| s.key == key).map(|(_, why)| *why)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{LoadRule, Params, Racket};
    use crate::solve::simulate;

    fn paper() -> Params {
        let mut p = Params::paper();
        p.numerics.load = LoadRule::Node;
        p
    }

    #[test]
    fn default_face_is_the_32_cm_ellipse_centred_near_the_node() {
        let f = Face::of(&Racket::default());
        assert_eq!((f.length, f.half_width, f.from_racket), (0.32, 0.125, false));
        assert_eq!(f.half_width_at(0.16), 0.125);
        assert_eq!(f.half_width_at(0.0), 0.0);
        assert!(!f.contains(0.0, 0.0), "the degenerate tip is skipped");
        assert!(!f.contains(0.33, 0.0));
        let nodes = mode1_nodes(&paper());
        assert!((nodes[0] - f.centre()).abs() < 0.002, "{nodes:?}");
    }

    #[test]
    fn head_face_matches_the_impact_validation() {
        let racket = Racket { head_length: Some(0.33), half_width: 0.126, ..Racket::default() };
        let f = Face::of(&racket);
        for i in 0..=200 {
            let x = 0.33 * i as f64 / 200.0;
            let w = f.half_width_at(x);
            assert_eq!(Some(w), racket.face_half_width(x), "{x}");
        }
    }

    #[test]
    fn grid_is_symmetric_and_ends_exactly() {
        let g = Grid::new(0.32, 0.125, 25, 13).unwrap();
        assert_eq!((g.xs[0], g.xs[24], g.rs[0], g.rs[6], g.rs[12]), (0.0, 0.32, -0.125, 0.0, 0.125));
        assert_eq!(g.xs[12], 0.16);
        assert!(Grid::new(0.32, 0.125, 1, 13).is_err());
        assert!(Grid::new(0.32, 0.125, 25, 402).is_err());
        // x = 0 and x = L have zero width: skipped; the centre column has every r
        let face = Face::of(&Racket::default());
        let inside = g.inside(&[face]);
        assert!(inside.iter().all(|&k| g.point(k).0 > 0.0 && g.point(k).0 < 0.32));
        assert_eq!(inside.iter().filter(|&&k| g.point(k).0 == 0.16).count(), 13);
    }

    #[test]
    fn small_map_matches_single_runs_and_its_maximum() {
        let p = paper();
        let mut calls = Vec::new();
        let m = FaceMap::compute(&p, 5, 5, &mut |d| calls.push(d)).unwrap();
        assert_eq!(m.len(), FaceMap::count(&p, 5, 5).unwrap());
        assert_eq!(calls.last().copied(), Some(m.len() as u64));
        let t = m.table();
        assert_eq!(t.len(), m.len());
        let e_a = t.column("e_a").unwrap();
        let best = m.max_point(Quantity::EA).unwrap();
        assert_eq!(best.value, e_a.iter().copied().fold(f64::MIN, f64::max));
        for (x, r, res) in m.points() {
            assert_eq!(*res, simulate(&params_at(&m.params, x, r)).unwrap());
        }
        // the heat map of it renders
        let dir = tempfile::tempdir().unwrap();
        crate::render::heatmap::render_png("map", &m.heatmap(Quantity::Power, "paper"), &dir.path().join("m.png"))
            .unwrap();
    }
}
