//! The physical model, and nothing above it: the ball + strings contact law behind one trait,
//! the discrete beam with its modes (and their cache), the contact point's coupling to the
//! frame, the free vibration after separation, the tangential contact of an oblique or spinning
//! ball, and closed-form reduced cases.

pub mod basis;
pub mod beam;
pub mod contact;
pub mod coupling;
pub mod free;
pub mod reduced;
pub mod tangential;
