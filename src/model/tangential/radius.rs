//! Mechanism `radius`: the friction force acts at the contact face of the deformed ball, at
//! `R - delta` from its centre rather than `R` (`delta` the ball's compression), so it spins the
//! ball less per unit of force. The compression follows the normal force (the same in ball and
//! strings) through the ball's *dynamic* stiffness `k` (the parameter `ball-kdyn`), not the
//! paper's `k1`, which keeps driving the normal force: `delta = F / k` while the ball is
//! compressed and `delta = Y0 (F / (k Y0))^(1/p)` on the way back (`Y0 = F_max / k`, the
//! unloading shape of SPEC Eqs 3-4). The contact circle of the flattened cap,
//! `a = sqrt(2 R delta - delta^2)`, sets the offset arm ([`super::offset`]).
//!
//! Source of `k`: a 100-inch (7.06 m/s) drop compresses a tennis ball about 6 mm on concrete
//! and about 3 mm on strings (data/measured M081-M082). A linear spring storing the drop's
//! kinetic energy at 6 mm is `k = m v^2 / d^2` = 7.89e4 N/m for 57 g, at a peak force
//! `m v^2 / d` = 473 N. The model's normal force is not that spring's but the paper's `k1` law,
//! whose peak at that drop is about 292 N on a rigid bed and 221 N on 60 lb strings, so this
//! mechanism computes `F / k` = 3.7 mm on concrete (measured 6) and 2.8 mm on the strings
//! (measured about 3; tested in tests/tangential.rs). No single linear law fits both the model's
//! forces and the measured compressions: it would take about 48.7 kN/m on concrete and 73.6 kN/m
//! on strings, and the ITF static test (80 N for 5.6-7.4 mm, M035-M036, 11-14 kN/m) is softer
//! still (SPEC.md section 6). The paper's `k1` = 3e4 N/m would give 9.7 mm on concrete at the
//! model's force. The compression is capped at `R` (the lever never turns negative).

use super::mechanism::{Drive, Mechanism, Sizes};

/// The mechanism: the friction's lever shortened by the ball's compression.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Radius;

impl Mechanism for Radius {
    type Mode = ();
    type Drive = ();
    const COMPRESSION: bool = true;
    const LEVER: bool = true;

    fn of(_: &Sizes) -> Radius {
        Radius
    }

    /// `R - delta`.
    #[inline]
    fn lever(&self, lever: f64, d: &Drive) -> f64 {
        lever - d.delta
    }
}
