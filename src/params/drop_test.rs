//! The drop test the ball's values are read from: gravity, the ITF's 100-inch height, the speed
//! a drop reaches, and the stiffness a drop's compression implies for a linear ball spring.

/// Acceleration of gravity used for drop tests, m/s^2.
pub const G: f64 = 9.81;
/// 100 inches in metres (the ITF drop height).
pub const DROP_HEIGHT_100_IN: f64 = 2.54;

/// Speed of a ball dropped from `height` (m) at impact, `sqrt(2 g h)`, m/s.
pub fn drop_speed(height: f64) -> f64 {
    (2.0 * G * height).sqrt()
}

/// The dynamic compression stiffness, N/m, of a ball of mass `mb` (kg) that a drop of
/// [`DROP_HEIGHT_100_IN`] onto concrete compresses by `compression` (m) if it is a linear spring
/// that stores the whole kinetic energy, `k = mb 2 g h / d^2`.
pub const fn kdyn_from_drop(mb: f64, compression: f64) -> f64 {
    mb * 2.0 * G * DROP_HEIGHT_100_IN / (compression * compression)
}

/// The default [`Oblique::ball_kdyn`](super::Oblique::ball_kdyn): the paper's 57 g ball as a linear spring compressed 6 mm
/// by the drop on concrete (data/measured M081), 7.89e4 N/m.
pub const BALL_KDYN: f64 = kdyn_from_drop(0.057, 0.006);
