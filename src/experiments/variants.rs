//! Model variants beside the paper's model (issue 6): which of the paper's simplifications
//! matters where.
//!
//! | id | question |
//! |---|---|
//! | [`super::variant_rigid`] | the textbook rigid racket against the flexible beam, along the racket |
//! | [`super::variant_grip`] | a hand on the grip against the paper's free racket, along the racket |
//! | [`super::variant_strings`] | strings that stiffen with deflection against the paper's linear strings, vs speed |
//!
//! All use the paper's racket, ball and numerics (node load, N = 39) with r = 0. This file
//! holds what the comparisons along the racket share.

use super::{node_positions, Context};
use crate::params::Params;

/// String stiffness of the comparisons along the racket, N/m (the paper's 60 lb).
pub const KS: f64 = 4.0e4;

/// The racket at the nodes of its N = 39 beam up to `x_max` (m), r = 0, ks 4e4.
pub fn along_to(ctx: &Context, x_max: f64, variant: impl Fn(&mut Params)) -> Vec<Params> {
    let xs = node_positions(&ctx.paper_params(0.0, KS));
    xs.iter()
        .filter(|&&x| x <= x_max)
        .map(|&x| {
            let mut p = ctx.paper_params(x, KS);
            variant(&mut p);
            p
        })
        .collect()
}

/// [`along_to`] over the whole racket.
pub fn along(ctx: &Context, variant: impl Fn(&mut Params)) -> Vec<Params> {
    along_to(ctx, f64::INFINITY, variant)
}
