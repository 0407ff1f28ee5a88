//! The tangential contact of the ball on the strings (SPEC.md section 6), in one room: what an
//! oblique or spinning impact adds to the normal one. The tangential force acts in the string
//! plane, so it neither bends nor twists the beam: the solvers step the normal impact exactly as
//! at normal incidence and hand the tangential law the normal force history `F_n(t)` piece by
//! piece ([`ForcePiece`]); the law turns it into the ball's tangential speed and spin.
//!
//! ```text
//! piece.rs     ForcePiece: one cubic piece of F_n(t), shared by fd, modal and every law
//! setup.rs     Setup: the law the parameters select; Contact: the law in progress (one
//!              variant per law); Separation: what it leaves when the ball leaves
//! elastic.rs   the elastic grip-slip law (`--tangential elastic`), in closed form
//! mechanism.rs the one trait a mechanism implements: its terms, state, mode and energies
//! combined.rs  the combined law: the elastic law plus the mechanisms of the registry
//!              (params), composed as a switched ODE in (v, omega, u, s) and their slots
//! stepper.rs   the generic stepper of a switched ODE: Runge-Kutta substeps within each piece,
//!              every mode switch located on its substep (the combined law is its one user)
//! loss.rs      mechanism `loss`: a damper in parallel with the ball's tangential spring,
//!              sized by the ball's measured tangential restitution (`ball-ex`)
//! offset.rs    mechanism `offset`: the normal force acting ahead of the ball's centre
//! bed.rs       mechanism `bed`: the strings sliding sideways over each other
//! radius.rs    mechanism `radius`: the friction acting at the deformed ball's face, R - delta,
//!              delta from the ball's measured dynamic stiffness (`ball-kdyn`, not `k1`)
//! ```
//!
//! With every mechanism off the parameters select the elastic law itself, kept bit for bit
//! (`tests/tangential.rs`).
//!
//! # Adding a mechanism
//! A mechanism is its own file here and one line in the registry, `tangential_mechanisms!` (in
//! `params/variants.rs`, where the `--tangential` choices are declared):
//! - **its file**: the physics, the source of every size in it (a derivation or a
//!   measurement, as in `loss.rs`), and its `impl Mechanism` ([`mechanism::Mechanism`]): the
//!   terms it adds to the combined law (a lever, a damper, a compliance in series, a torque),
//!   its state slots and their rates, its mode with its guard and switch, its springs' energy
//!   and where its loss is reported; every term it leaves out is neutral;
//! - **its line** in the registry: its `TangentialLaw` variant, its `--tangential` name, its
//!   type and its help line. The variant, the choice on the command line, `physical` (every
//!   mechanism), its state and its guard in the combined law all follow from it (and its
//!   `pub mod` line here, which Rust needs for any file). A parameter it reads says so in its
//!   own declaration (`used In(&TANGENTIAL, ...)` in `params/keys.rs`).
//!
//! The combined law, the stepper, the solvers and the result's ledger are untouched. A loss with
//! no result field of its own ([`mechanism::LossField::LedgerOnly`]) is checked in the energy
//! ledger; a result field for it is a change of the output (`solve/outcome.rs`, CHANGELOG).

pub mod bed;
pub mod combined;
pub mod compression;
pub mod elastic;
pub mod loss;
pub mod mechanism;
pub mod offset;
pub mod piece;
pub mod radius;
mod setup;
mod stepper;

pub use combined::{Combined, CombinedLaw, Losses, Mechanisms};
pub use elastic::{Elastic, GripSlip};
pub use piece::ForcePiece;
pub(crate) use setup::Contact;
pub use setup::{Setup, MAX_TANGENTIAL_STEPS, RPM};
