//! Studies built from many impacts, the library logic behind the commands that run them:
//! [`sweep`] (the cartesian product of any parameters, streamed), [`map`] (one impact per
//! point of the string face) and [`speed`] (outgoing ball speeds for a swing, compared across
//! tensions or rackets), [`sensitivity`] (Sobol'/Saltelli uncertainty propagation and global
//! sensitivity for any model), [`impact`] (one impact as `simulate` runs it), [`work`] (how long
//! a run of many impacts will take, estimated before it starts), [`choice`] (the rule that
//! chooses among candidate models on calibration rows, with what the rows cannot tell apart). Each starts from
//! the parameter intake ([`crate::intake`]: a racket, a config file and the flags, and what is
//! told of a value no impact uses).

pub mod calibrate;
pub mod card;
pub mod choice;
pub mod impact;
pub mod map;
pub mod measured;
pub mod sensitivity;
pub mod speed;
pub mod stats;
pub mod sweep;
pub mod uncertainty;
pub mod work;
