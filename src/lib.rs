//! racket-impact
pub mod error;
pub mod model;
pub mod params;
pub mod solver;

pub use error::{Error, Result};
pub use params::Params;
pub use solver::{simulate, ImpactResult, Model};
