//! # racket-impact
//!
//! A replication of R. Cross, "Flexible beam analysis of the effects of string tension and
//! frame stiffness on racket performance", Sports Engineering 3 (2000): a tennis ball hits the
//! strings of a freely suspended racket that bends like a beam and twists about its long axis.
//!
//! ## The model in one page
//! ```text
//! ball       m_b y_b'' = -F                                                  (Eq 1)
//! strings    F = k_s Y_s            (massless, linear)                       (Eq 2)
//! ball law   F = k1 Y_b (compression),  F = k2 Y_b^p (expansion),
//!            k2 = k1 Y0^(1-p)  (Y0: maximum ball compression)                (Eqs 3-4)
//! beam       rho A y_tt = F_o - (EI y_xx)_xx, free ends, lumped on N+1 nodes (Eqs 5-6)
//! twist      I_x theta'' = F r                                               (Eq 7)
//! contact    Y_T = Y_s + Y_b = y_b - (y_n + r theta)                         (Eq 8)
//!            Y_b = k_s Y_T / (k1 + k_s)  |  Y_b + k2 Y_b^p / k_s = Y_T       (Eqs 9-10)
//! ball loss  E_b = (p-1) k1 Y0^2 / (2 (p+1));  on concrete e = sqrt(2/(p+1)) (Eqs 11-12)
//! ```
//! The racket starts at rest; the result is the apparent coefficient of restitution
//! `e_A = v2/v1`, the impact duration, the twist angle and where the ball's energy went.
//!
//! ## Layout
//! The folders are the layers, each using only those below it:
//! ```text
//! src/main.rs, src/cli/  the command line: parse, dispatch, print (clap lives only here)
//!         |              (the Python package, python/, is the other front end on the commands)
//! src/command/           the commands as requests: each built from its inputs, its own options
//!         |              declared once, its work estimated before it runs, run under a Control
//! src/study/             sweeps, string-face maps, swing-speed comparisons, Sobol' uncertainty
//! src/experiments/       one file per result of the paper, each with its paper claims
//! src/report.rs          the claims collected, the paper beside ours
//! src/intake/            where a command's parameters come from (racket, config, flags), what
//!                        a value no impact uses is told, the checks of a run's inputs and results
//! src/racket/            racket files in player units, fitted to the beam, and the fit report
//!         |                            \
//! src/render/            tables (CSV), line charts, heat maps, one impact as text, atomic files
//!         |
//! src/solve/             the prepared impact (no solver's), the solvers behind one trait
//!                        (fd, modal, rigid), the dispatcher, the outcome with its one field
//!                        table, the time-series observer
//!         |
//! src/model/             physics only: contact law (one trait), beam, modes and their cache,
//!                        the contact point's coupling to the frame, free vibration, closed forms
//!         |
//! src/params/            every parameter declared once, validation, config overrides
//!         |
//! src/error.rs           the crate's errors; src/diagnostic.rs, warnings as data
//! src/control.rs         a running command's control: cancel flag and progress, read by the
//!                        solvers' stepping loops (imports only the error type and number words)
//! src/numfmt.rs          how numbers are written in messages and tables (imports nothing)
//! src/numeric/           numerical tools apart from the physics: roots, rank-one modes, short
//!                        turns, reused buffers (imports nothing)
//! ```
//! Arrows point down only: nothing in `model/` or `solve/` knows of tables, plots, files or the
//! command line.
//!
//! - [`params`]: parameter structs (defaults = the paper), each flag parameter declared once
//!   (key, unit, range, doc), validation, `--config` overrides.
//! - [`racket`]: a racket file or preset in spec-sheet units (mass, balance, swingweight, Hz),
//!   fitted exactly to the discrete beam.
//! - [`model`]: physics only: the ball + strings contact law behind one trait (linear or
//!   stiffening strings), the discrete beam and its modes (cached per racket), the contact
//!   point's coupling to the frame, closed-form drop tests, the closed-form free vibration after
//!   separation.
//! - [`solve`]: the impact solvers behind one trait and the dispatcher [`simulate`]: velocity-Verlet
//!   time stepping with the energy ledger (and the hand grip variant), an independent
//!   modal-superposition solver with a contact-sized step, the closed-form rigid racket; the
//!   result with its one field table, and the time series.
//! - [`experiments`]: one module per result of the paper (figure -> module table there), each
//!   with its paper claims; they run on a racket given as an argument ([`experiments::Context`]).
//! - [`study`]: parallel, streamed parameter sweeps, string-face maps, swing-speed comparisons,
//!   uncertainty propagation and Sobol' sensitivity (`uncertainty`, the `robustness` experiment).
//! - [`intake`]: a command's parameters from a racket, a config file and the flags
//!   ([`intake::Sources`]), the notes and refusals of a value no impact uses, the comparison
//!   options, and the physics-validity checks of a run ([`intake::diagnose`]).
//! - [`render`]: result tables, the one look of every figure, heat maps, the text of one
//!   impact, the files of a map, atomic writes.
//! - [`report`]: the paper's numbers beside ours, collected from the experiments' claims.
//! - [`numfmt`]: how numbers are written, in messages and in tables, for every layer.
//! - [`numeric`]: numerical tools apart from the physics (a bracketing root finder, the modes of
//!   oscillators joined by one spring, short turns, buffers reused from impact to impact).
//! - [`command`]: the commands as requests beneath the command line and the Python package:
//!   options declared once, the work estimated before it runs (refused above ten minutes unless
//!   asked for), progress and cancellation through one [`control::Control`].
//! - [`control`]: a running command's cancel flag and progress counters, which the solvers' loops
//!   poll (a hook that reads a flag: results unchanged bit for bit).
//! - [`diagnostic`]: warnings as data, returned with a result ([`intake::diagnose`] checks a run).
//!
//! ## Example
//! The Fig 4 impact with the paper's numerics:
//! ```
//! use racket_impact::{simulate, Params};
//! let r = simulate(&Params::paper()).unwrap();
//! assert!((r.tau_s - 4.78e-3).abs() < 0.05e-3);      // paper: 4.78 ms
//! assert!((r.e_a - 0.166).abs() < 0.003);            // paper: 0.166
//! assert!(r.energy_error < 1e-6);
//! ```
//! Invalid parameters are errors that name the field:
//! ```
//! use racket_impact::{simulate, Params};
//! let mut p = Params::default();
//! p.ball.p = 0.9;
//! let msg = simulate(&p).unwrap_err().to_string();
//! assert_eq!(msg, "invalid p = 0.9: hysteresis exponent must satisfy 1 < p <= 10");
//! ```

pub mod command;
pub mod control;
pub mod diagnostic;
pub mod error;
pub mod experiments;
pub mod intake;
pub mod model;
pub mod numeric;
pub mod numfmt;
pub mod params;
pub mod racket;
pub mod render;
pub mod report;
pub mod solve;
pub mod study;
#[cfg(test)]
mod test_rng;

pub use error::{Error, Result};
pub use params::Params;
pub use solve::{simulate, ImpactResult};
