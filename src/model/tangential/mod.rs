//! The tangential contact of the ball on the strings (SPEC.md section 6), in one room: what an
//! oblique or spinning impact adds to the normal one. The tangential force acts in the string
//! plane, so it neither bends nor twists the beam: the solvers step the normal impact exactly as
//! at normal incidence and hand the tangential law the normal force history `F_n(t)` piece by
//! piece ([`ForcePiece`]); the law turns it into the ball's tangential speed and spin.
//!
//! ```text
//! piece.rs       ForcePiece: one cubic piece of F_n(t), shared by fd, modal and every law
//! setup.rs       Setup: the law the parameters select; Contact: the law in progress (one
//!                variant per law); Separation: what it leaves when the ball leaves
//! elastic.rs     the elastic grip-slip law (`--tangential elastic`), in closed form
//! mechanism.rs   the one trait a mechanism implements: its terms, state, mode and energies
//! combined.rs    the combined law: the elastic law plus the mechanisms of the registry,
//!                composed as a switched ODE in (v, omega, u, s) and their slots
//! stepper.rs     the generic stepper of a switched ODE: Runge-Kutta substeps within each piece,
//!                every mode switch located on its substep (the combined law is its one user)
//! compression.rs the ball's compression under the normal force (for the mechanisms that need it)
//! NAME.rs        one file per mechanism, named by its `--tangential` choice (the registry,
//!                `tangential_mechanisms!` in `params/variants.rs`, lists them; each file's
//!                first line says what it adds)
//! ```
//!
//! With every mechanism off the parameters select the elastic law itself, kept bit for bit
//! (`tests/tangential.rs`).
//!
//! # Adding a mechanism
//! A mechanism is its own file here and one line in the registry, `tangential_mechanisms!` (in
//! `params/variants.rs`, where the `--tangential` choices are declared, by name only):
//! - **its file** `NAME.rs`: the physics, the source of every size in it (a derivation or a
//!   measurement, as in `loss.rs`), and its type, named as its variant, with its
//!   `impl Mechanism` ([`mechanism::Mechanism`]): the terms it adds to the combined law (a
//!   lever, a damper, a compliance in series, a torque), its state slots and their rates, its
//!   mode with its guard and switch, its springs' energy and where its loss is reported; every
//!   term it leaves out is neutral;
//! - **its line** in the registry: `Variant = NAME: "help",`. The variant, the choice on the
//!   command line, `physical` (every mechanism), the file's module (declared here from the
//!   list), its state and its guard in the combined law, and every list and count of the laws
//!   all follow from it. A parameter it reads says so in its own declaration
//!   (`used In(&TANGENTIAL, ...)` in `params/keys.rs`).
//!
//! The combined law, the stepper, the solvers and the result's ledger are untouched. A loss with
//! no result field of its own ([`mechanism::LossField::LedgerOnly`]) is checked in the energy
//! ledger; a result field for it is a change of the output (`solve/outcome.rs`, CHANGELOG).

pub mod combined;
pub mod compression;
pub mod elastic;
pub mod mechanism;
pub mod piece;
mod setup;
mod stepper;

/// Declares the file of each mechanism of the registry: the choice `NAME` is `NAME.rs`.
/// (Files declared by a macro are outside `cargo fmt`'s walk of the modules: `make fmt` and
/// `make lint` name every source file.)
macro_rules! mechanism_files {
    ($($ty:ident = $module:ident: $help:literal,)+) => {
        $(pub mod $module;)+
    };
}
crate::params::tangential_mechanisms!(mechanism_files);

pub use combined::{Combined, CombinedLaw, Losses, Mechanisms};
pub use elastic::{Elastic, GripSlip};
pub use piece::ForcePiece;
pub(crate) use setup::Contact;
pub use setup::{Setup, MAX_TANGENTIAL_STEPS, RPM};
