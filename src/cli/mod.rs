//! The command-line layer: one module per command, each with its clap arguments and a thin
//! `run` that calls the library and prints; [`common`] holds what they share and
//! [`overrides`] the parameter flags built from the parameter declarations.

pub mod common;
pub mod figures;
pub mod map;
pub mod modes;
pub mod overrides;
pub mod racket;
pub mod report;
pub mod simulate;
pub mod speed;
pub mod sweep;
pub mod uncertainty;
