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
//! combined.rs  the combined law: the elastic law plus the switchable mechanisms below, as a
//!              switched ODE in (v, omega, u, s, q) with the energies each mechanism dissipates
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
//! What a new mechanism adds and touches:
//! - **its own file** here: the physics, the source of every size in it (a derivation or a
//!   measurement, as in `loss.rs`), and its constitutive helper (a force, torque or limit);
//! - **the law's variant**: a `TangentialLaw` variant in `params` (its `--tangential` name;
//!   `physical` then includes it) with its doc;
//! - **one registration line** in `Setup::of`: the field of [`CombinedLaw`] that the variant
//!   turns on (its neutral value, e.g. `0.0` or `None`, is the mechanism off);
//! - **its term in the combined law's kinematics** (`Combined::kin` and the rates in
//!   `combined.rs`): the mechanisms couple through the one contact force `P` and the slip, so
//!   a new force path cannot be summed in from outside; and, if it has a mode of its own (as
//!   `bed` has stick and slide), a guard and its switch there. The stepper, the set-up of the
//!   other mechanisms, the solvers and the result's ledger are untouched; a new energy loss
//!   adds a state slot and its field in `MechanismLosses` (setup.rs).

pub mod bed;
pub mod combined;
pub mod elastic;
pub mod loss;
pub mod offset;
pub mod piece;
pub mod radius;
mod setup;
mod stepper;

pub use combined::{Combined, CombinedLaw};
pub use elastic::{Elastic, GripSlip};
pub use piece::ForcePiece;
pub(crate) use setup::Contact;
pub use setup::{Setup, MAX_TANGENTIAL_STEPS, RPM};
