//! The Saltelli design: two independent blocks A and B of a scrambled Sobol' sequence in the
//! unit cube, and for each input i the block A with its column i taken from B (Saltelli et al.
//! 2010, "Variance based sensitivity analysis of model output", Comput. Phys. Commun. 181).
//!
//! The sequence is `sobol_burley`'s Owen-scrambled Sobol' sequence (Joe-Kuo direction numbers,
//! up to 256 dimensions and 2^16 points): A takes dimensions `0..d`, B `d..2d`, and the
//! scramble comes from the seed, so a seed fixes every point.

use crate::error::{Error, Result};
use crate::params::uncertainty::U_MIN;

/// The most base samples (rows of A): the length of `sobol_burley`'s sequence.
pub const MAX_SAMPLES: u64 = 1 << 16;
/// The most varied inputs: A and B together use `2 d` of the sequence's 256 dimensions.
pub const MAX_INPUTS: usize = 128;

/// A Saltelli design of `samples` base rows over `inputs` inputs: `samples (inputs + 2)` runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Design {
    samples: usize,
    inputs: usize,
    seed: u32,
}

impl Design {
    /// A design; `samples` must be 1 ..= [`MAX_SAMPLES`] and `inputs` 1 ..= [`MAX_INPUTS`]
    /// (checked before anything is allocated).
    pub fn new(samples: u64, inputs: usize, seed: u32) -> Result<Design> {
        if !(1..=MAX_SAMPLES).contains(&samples) {
            return Err(Error::invalid(
                "samples",
                samples,
                format!("must satisfy 1 <= samples <= {MAX_SAMPLES} (the length of the Sobol' sequence)"),
            ));
        }
        if !(1..=MAX_INPUTS).contains(&inputs) {
            return Err(Error::invalid("vary", inputs, format!("vary between 1 and {MAX_INPUTS} inputs")));
        }
        Ok(Design { samples: samples as usize, inputs, seed })
    }

    /// Base samples N (rows of A).
    pub fn samples(&self) -> usize {
        self.samples
    }

    /// Number of inputs d.
    pub fn inputs(&self) -> usize {
        self.inputs
    }

    /// The seed.
    pub fn seed(&self) -> u32 {
        self.seed
    }

    /// Model runs: `N (d + 2)` (A, B and one mixed block per input).
    pub fn runs(&self) -> usize {
        self.samples * (self.inputs + 2)
    }

    /// Coordinate `dim` of sequence point `row`, strictly inside (0, 1).
    fn unit(&self, row: usize, dim: usize) -> f64 {
        f64::from(sobol_burley::sample(row as u32, dim as u32, self.seed)) + U_MIN
    }

    /// The unit-cube point of run `k`: runs `0..N` are A, `N..2N` are B, and block `2 + i`
    /// is A with coordinate `i` from B.
    pub fn point(&self, k: usize) -> Vec<f64> {
        let (block, row) = (k / self.samples, k % self.samples);
        let d = self.inputs;
        (0..d)
            .map(|i| {
                let from_b = block == 1 || block == 2 + i;
                self.unit(row, if from_b { d + i } else { i })
            })
            .collect()
    }
}
