//! The string face a map covers and the grid of impact points over it.

use serde::Serialize;

use super::{DEFAULT_FACE_LENGTH, MAX_GRID, MIN_GRID};
use crate::error::{Error, Result};
use crate::params::Racket;

/// The string face: an ellipse from the tip, `length` along the racket and `2 half_width`
/// across it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Face {
    /// Length from the tip, m.
    pub length: f64,
    /// Half the width, m.
    pub half_width: f64,
    /// `true` if the racket has a head outline, `false` for the default face.
    pub from_racket: bool,
}

impl Face {
    /// The face of a racket: its head outline, else the default face
    /// ([`DEFAULT_FACE_LENGTH`], at most the racket's length, by `2 half_width`).
    pub fn of(racket: &Racket) -> Face {
        match racket.head_length {
            Some(h) => Face { length: h, half_width: racket.half_width, from_racket: true },
            None => Face {
                length: DEFAULT_FACE_LENGTH.min(racket.length),
                half_width: racket.half_width,
                from_racket: false,
            },
        }
    }

    /// Half the width at `x`, m (0 off the face along x). The function behind
    /// [`Racket::face_half_width`], so a point inside is a valid impact.
    pub fn half_width_at(&self, x: f64) -> f64 {
        crate::params::ellipse_half_width(self.length, self.half_width, x).unwrap_or(0.0)
    }

    /// `true` if `(x, r)` is on or inside the outline and the face has a width there.
    pub fn contains(&self, x: f64, r: f64) -> bool {
        let w = self.half_width_at(x);
        w > 0.0 && r.abs() <= w
    }

    /// The centre, m from the tip.
    pub fn centre(&self) -> f64 {
        0.5 * self.length
    }
}

/// The grid: x along the racket (m from the tip) and r across it (m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Grid {
    /// x values, ascending, from 0.
    pub xs: Vec<f64>,
    /// r values, ascending, symmetric about 0.
    pub rs: Vec<f64>,
}

impl Grid {
    /// `nx` points on `0..=length` and `nr` on `-half_width..=half_width` (ends included).
    pub fn new(length: f64, half_width: f64, nx: usize, nr: usize) -> Result<Grid> {
        check_count("nx", nx)?;
        check_count("nr", nr)?;
        let axis = |lo: f64, hi: f64, n: usize| -> Vec<f64> {
            (0..n).map(|i| if i + 1 == n { hi } else { lo + (hi - lo) * (i as f64 / (n - 1) as f64) }).collect()
        };
        let mut rs = axis(-half_width, half_width, nr);
        if nr % 2 == 1 {
            rs[nr / 2] = 0.0; // exactly on the axis
        }
        Ok(Grid { xs: axis(0.0, length, nx), rs })
    }

    /// The grid covering the bounding box of every face.
    pub fn covering(faces: &[Face], nx: usize, nr: usize) -> Result<Grid> {
        let length = faces.iter().map(|f| f.length).fold(0.0, f64::max);
        let half_width = faces.iter().map(|f| f.half_width).fold(0.0, f64::max);
        Grid::new(length, half_width, nx, nr)
    }

    /// Number of grid points.
    pub fn len(&self) -> usize {
        self.xs.len() * self.rs.len()
    }

    /// `true` for an empty grid (never, for a grid from [`Grid::new`]).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The point with flat index `k` (x slowest).
    pub fn point(&self, k: usize) -> (f64, f64) {
        let n = self.rs.len();
        (self.xs[k / n], self.rs[k % n])
    }

    /// The flat indices of the points inside every face, in row-major order.
    pub fn inside(&self, faces: &[Face]) -> Vec<usize> {
        (0..self.len())
            .filter(|&k| {
                let (x, r) = self.point(k);
                faces.iter().all(|f| f.contains(x, r))
            })
            .collect()
    }
}

/// Check a grid's point count along one axis (`field` is `nx` or `nr`).
pub fn check_count(field: &'static str, n: usize) -> Result<()> {
    if (MIN_GRID..=MAX_GRID).contains(&n) {
        Ok(())
    } else {
        Err(Error::invalid(field, n, format!("grid points must satisfy {MIN_GRID} <= {field} <= {MAX_GRID}")))
    }
}
