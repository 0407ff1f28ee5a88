//! The physical model: contact law (ball + strings), the discrete beam, and reduced cases.

pub mod beam;
pub mod contact;
pub mod free;
pub mod reduced;
pub mod rigid;
