//! Numerical tools the physics and the solvers use, apart from the physics: a root finder that
//! keeps a bracket around a switch ([`root`]), the modes of oscillators joined by one spring (a
//! rank-one update of a diagonal eigenproblem, [`rank_one`]), sines and cosines of short turns
//! without a trigonometric call ([`short_turn`]), and buffers reused from impact to impact
//! ([`spare`]). Nothing here knows of rackets, balls or strings, and nothing here imports from
//! the rest of the crate. `root` and `spare` say why they are not taken from a crate; `rank_one`
//! and `short_turn` are the fast special cases of what nalgebra's eigensolver and `f64::sin_cos`
//! do in general (order `n^2` against `n^3`; a few multiplications against a library call).

pub mod rank_one;
pub mod root;
pub mod short_turn;
pub mod spare;
