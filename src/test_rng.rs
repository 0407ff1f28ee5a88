//! A small deterministic generator for the unit tests' random cases (xorshift64): the same
//! numbers every run, no dependency.

/// Uniform numbers in [0, 1) from `seed` (any value but 0).
pub fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}
