//! A stroke in the court's frame: the racket moves at the impact point along a path tilted up
//! (or down) from the horizontal, the string plane stands vertical across the ball's line, and
//! the ball comes in horizontally. The impact is computed in the racket's frame, where the
//! racket starts at rest (the paper's frame transformation, Galilean and exact for the
//! translation), and the ball's exit is carried back to the court.
//!
//! ```text
//! court:  X horizontal, the way the ball leaves; Z up.  racket velocity  s (cos b, sin b)
//! racket frame:  normal speed   v_n = v_in + s cos b          (towards the strings)
//!                tangential     v_t = s |sin b|  along t = -sign(b) Z
//!                incidence      atan(v_t / v_n),  azimuth 90 deg (across the face)
//! exit:          (v2_n + s cos b,  s sin b - sign(b) v2_t)    launch angle atan2(Z, X)
//! spin:          topspin in the court's sense = sign(b) spin_out (t points down for b > 0)
//! ```
//! An incoming ball with topspin (in its own flight) meets the strings with its front moving
//! down: in the racket frame that is spin `-sign(b)` times it. Only the translation of the
//! racket at the impact point is carried; its rotation over the 5 ms of contact is not.
//!
//! For a head-on stroke the same transformation is the paper's one line, [`outgoing_speed`]
//! (`e_A v_in + (1 + e_A) v_racket`), which the `speed` command and the `speeds` experiment use.

use crate::error::{Error, Result};
use crate::params::Params;
use crate::solve::{simulate, ImpactResult};

/// The paper's frame transformation (p. 5): a ball arriving at `v_in` on a racket swung at
/// `v_racket` (at the impact point, towards the ball) leaves at `e_A v_in + (1 + e_A) v_racket`,
/// with `e_A` the apparent coefficient of restitution at the relative speed `v_in + v_racket`.
/// Serve (`v_in = 0`): `(1 + e_A) v`; forehand (`v_in = v_racket = v`): `(1 + 2 e_A) v`.
pub fn outgoing_speed(e_a: f64, v_in: f64, v_racket: f64) -> f64 {
    e_a * v_in + (1.0 + e_a) * v_racket
}

/// Percentage change of `b` over `a`.
pub fn gain_pct(a: f64, b: f64) -> f64 {
    100.0 * (b / a - 1.0)
}

/// A stroke: the racket's motion at the impact point and the incoming ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Swing {
    /// Racket speed at the impact point along its path, m/s (>= 0).
    pub racket_speed: f64,
    /// Path angle above the horizontal, degrees (-80..=80; > 0 brushes up for topspin).
    pub path_deg: f64,
    /// Incoming ball speed, horizontal, towards the racket, m/s (>= 0; 0 for a serve).
    pub incoming: f64,
    /// Incoming spin in the ball's own flight, rpm (topspin > 0).
    pub incoming_spin_rpm: f64,
}

/// What leaves the racket, in the court's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exit {
    /// The impact in the racket's frame (`v1` the relative speed).
    pub impact: ImpactResult,
    /// The impact's parameters in the racket's frame.
    pub params: Params,
    /// Ball speed, m/s.
    pub speed: f64,
    /// Launch angle above the horizontal, degrees.
    pub launch_deg: f64,
    /// Spin, rpm (topspin > 0).
    pub spin_rpm: f64,
}

impl Swing {
    /// Check the stroke: every value finite and in range.
    pub fn validate(&self) -> Result<()> {
        let check = |field: &'static str, v: f64, lo: f64, hi: f64, what: &str| {
            if v.is_finite() && v >= lo && v <= hi {
                Ok(())
            } else {
                Err(Error::invalid(field, v, format!("{what} must satisfy {lo} <= {field} <= {hi}")))
            }
        };
        check("swing", self.racket_speed, 0.0, 1.0e3, "racket speed (m/s)")?;
        check("swing-path-deg", self.path_deg, -80.0, 80.0, "swing path angle (degrees above the horizontal)")?;
        check("incoming", self.incoming, 0.0, 1.0e3, "incoming ball speed (m/s)")?;
        check("incoming-spin-rpm", self.incoming_spin_rpm, -2.0e4, 2.0e4, "incoming spin (rpm)")?;
        if self.incoming + self.racket_speed * self.path_deg.to_radians().cos() <= 0.0 {
            return Err(Error::invalid(
                "swing",
                self.racket_speed,
                "racket and ball must close on each other (swing + incoming > 0)",
            ));
        }
        Ok(())
    }

    /// The racket-frame impact of this stroke on the racket, strings and ball of `base` (its
    /// impact point, numerics and friction; its speed, angle, azimuth and spin are the stroke's).
    pub fn impact_params(&self, base: &Params) -> Params {
        let (sin_b, cos_b) = self.path_deg.to_radians().sin_cos();
        let up = if sin_b < 0.0 { -1.0 } else { 1.0 };
        let v_n = self.incoming + self.racket_speed * cos_b;
        let v_t = self.racket_speed * sin_b.abs();
        let mut p = *base;
        p.impact.v1 = v_n.hypot(v_t);
        p.oblique.angle_deg = v_t.atan2(v_n).to_degrees();
        p.oblique.azimuth_deg = 90.0;
        p.oblique.spin_rpm = -up * self.incoming_spin_rpm;
        p
    }

    /// Hit the ball: the impact in the racket's frame, the exit in the court's.
    pub fn hit(&self, base: &Params) -> Result<Exit> {
        self.validate()?;
        let params = self.impact_params(base);
        let impact = simulate(&params)?;
        let (sin_b, cos_b) = self.path_deg.to_radians().sin_cos();
        let up = if sin_b < 0.0 { -1.0 } else { 1.0 };
        // at normal incidence without spin the tangential fields do not apply: nothing along t
        let (v2_n, v2_t, spin) = if impact.v2_t.is_nan() {
            (impact.e_a * params.impact.v1, 0.0, 0.0)
        } else {
            (impact.v2_n, impact.v2_t, impact.spin_out_rpm)
        };
        let x = v2_n + self.racket_speed * cos_b;
        let z = self.racket_speed * sin_b - up * v2_t;
        Ok(Exit { impact, params, speed: x.hypot(z), launch_deg: z.atan2(x).to_degrees(), spin_rpm: up * spin })
    }
}
