//! The combined law (`--tangential physical` and each mechanism alone; SPEC.md section 6,
//! "Mechanisms"): the grip-slip law of [`super::elastic`] with switchable mechanisms, each in
//! its own file, that the elastic law leaves out:
//!
//! - [`loss`](super::loss): a damper in parallel with the ball's tangential spring (tangential
//!   hysteresis, sized by the ball's measured tangential restitution `e_x`);
//! - [`offset`]: the normal force acting ahead of the ball's centre (Tabor's
//!   rolling-hysteresis arm), a torque against its spin;
//! - [`bed`](super::bed): the strings sliding sideways over each other and snapping back;
//! - [`radius`](super::radius): the friction force acting at `R - delta`, the deformed ball's
//!   contact face (`delta` from the ball's measured dynamic stiffness).
//!
//! ```text
//! ball     m_b dv/dt = -P,   I_b domega/dt = R_c P + tau,   tau = -sign(omega) d F_n  (offset,
//!          while the ball grips: Tabor's arm is that of a ball rolling without slip)
//! frame    du/dt = P / m_eff                     (u: frame velocity at the contact point)
//! slip     w = v - R_c omega - u,                R_c = R - delta (radius) or R
//! ball     P = k_t s + c ds/dt                   (force through the ball's spring-damper)
//! bed      P = k_lat q + friction,  |friction| <= mu_ss N   (stuck: dq/dt = 0)
//! grip     ds/dt + dq/dt = w                     while |P| <= mu F_n
//! slide    P = sigma mu F_n                      while sigma (w - ds/dt - dq/dt) > 0
//! ```
//! With every mechanism off this is the elastic law (the bed infinitely stiff, `c = 0`,
//! `tau = 0`, `R_c = R`). The elements are massless, so each mode is a small ODE in
//! `(v, omega, u, s, q)`; it is advanced by the generic stepper (`stepper.rs`: classical
//! Runge-Kutta substeps inside each piece of the normal force history, a cubic as for the
//! elastic law), and every switch (grip/slide, stick/slide of the bed, the sign of the spin) is
//! located on the substep. The dissipated energies are integrated with the state, so the ledger
//! `KE_in = KE_out + k_t s^2/2 + k_lat q^2/2 + losses` closes to the integration error.

use super::bed::Bed;
use super::elastic::GripSlip;
use super::offset;
use super::piece::ForcePiece;
use super::radius::Compression;
use super::stepper::{self, Switched};

/// The tangential contact law with its mechanisms.
#[derive(Debug, Clone, Copy)]
pub struct CombinedLaw {
    /// The elastic grip-slip law underneath: friction, tangential stiffness, ball and frame.
    pub base: GripSlip,
    /// Damper in parallel with `kt`, N s/m (0: mechanism `loss` off).
    pub damping: f64,
    /// Hysteresis loss fraction for Tabor's offset arm (mechanism `offset`; 0: off).
    pub offset_loss: f64,
    /// The lateral string bed (mechanism `bed`; `None`: a laterally rigid bed).
    pub bed: Option<Bed>,
    /// Whether the friction acts at `R - delta` (mechanism `radius`).
    pub shrink: bool,
    /// The ball's compression law (used by `offset` and `radius`).
    pub compression: Compression,
}

impl CombinedLaw {
    /// `1 / m_red` at full radius, 1/kg.
    pub fn inv_red(&self) -> f64 {
        let b = &self.base;
        1.0 / b.mb + b.radius * b.radius / b.inertia + b.racket_inv_mass
    }
}

/// Grip or slide of the ball on the strings.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Ball {
    Grip,
    Slide(f64),
}

/// Stick or slide of the moving strings over the others.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Strings {
    Stuck,
    Slide(f64),
}

/// The modes of one stretch of time.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Modes {
    ball: Ball,
    strings: Strings,
    /// Sign of the spin the offset torque opposes; 0: the spin is held at zero by the offset
    /// torque (while the ball grips and that torque can balance the friction's).
    spin: f64,
}

/// State: `v, omega, u, s, q` and the energies lost to sliding, damping, the strings' sliding
/// and the offset torque.
type Y = [f64; 9];
const V: usize = 0;
const OM: usize = 1;
const U: usize = 2;
const S: usize = 3;
const Q: usize = 4;
const E_FRICTION: usize = 5;
const E_DAMPING: usize = 6;
const E_BED: usize = 7;
const E_ROLLING: usize = 8;

/// What the mode makes of the state at one instant.
#[derive(Debug, Clone, Copy)]
struct Kin {
    /// Force through the contact (on the bed; the ball feels `-p`), N.
    p: f64,
    sdot: f64,
    qdot: f64,
    /// Slip of the ball's contact point relative to the frame, m/s.
    w: f64,
    /// Lever of the friction force, m.
    lever: f64,
    /// Offset torque on the ball, N m.
    torque: f64,
    /// The largest offset torque, `d F_n`, N m (0 while it does not act).
    capacity: f64,
}

/// Substep length as a fraction of the time scale of a relaxation through the damper.
const SUBSTEP: f64 = 0.2;
/// Substep length as a fraction of the grip oscillation's time scale `sqrt(m_red / k_t)`:
/// finer than for a relaxation, as the oscillation carries the spin handed back and the
/// offset torque's switches ride on it (chosen so that the outcomes over the mechanisms' test
/// grid come at least as close to a ten times finer integration as with the former single
/// limit, 0.2 of the fastest time scale of any mode).
const GRIP_SUBSTEP: f64 = 0.05;

/// The combined law's tangential contact of one impact in progress.
#[derive(Debug, Clone, Copy)]
pub struct Combined {
    law: CombinedLaw,
    y: Y,
    modes: Modes,
    /// Largest normal force so far, N.
    f_max: f64,
    /// The turning points of the piece in progress.
    turning: [f64; 2],
    /// Longest substep in each mode, s ([`Substeps`]).
    h_max: Substeps,
    /// Time spent sliding, s.
    pub slide_time: f64,
    /// Whether a piece reached its cap of switches (`stepper::advance`).
    pub chatter: bool,
    started: bool,
}

impl Combined {
    /// The contact before the ball touches: ball velocity `v` and spin `omega` along `t`, the
    /// frame at rest.
    pub fn new(law: CombinedLaw, v: f64, omega: f64) -> Combined {
        Combined {
            law,
            y: [v, omega, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            modes: Modes { ball: Ball::Grip, strings: Strings::Stuck, spin: 0.0 },
            f_max: 0.0,
            turning: [f64::NAN; 2],
            h_max: Substeps::of(&law),
            slide_time: 0.0,
            chatter: false,
            started: false,
        }
    }

    /// The most Runge-Kutta substeps over a contact of `t` seconds (besides those cut at a
    /// switch).
    pub fn steps_within(&self, t: f64) -> f64 {
        t / self.h_max.shortest()
    }

    /// Ball velocity along `t`, m/s.
    pub fn v(&self) -> f64 {
        self.y[V]
    }
    /// Ball spin, rad/s (topspin positive).
    pub fn omega(&self) -> f64 {
        self.y[OM]
    }
    /// Frame velocity at the contact point along `t`, m/s.
    pub fn u(&self) -> f64 {
        self.y[U]
    }
    /// Energy lost to the ball sliding on the strings, J.
    pub fn friction_loss(&self) -> f64 {
        self.y[E_FRICTION]
    }
    /// Energy lost in the ball's tangential damper, J.
    pub fn damping_loss(&self) -> f64 {
        self.y[E_DAMPING]
    }
    /// Energy lost to the strings sliding over each other, J.
    pub fn bed_loss(&self) -> f64 {
        self.y[E_BED]
    }
    /// Energy lost to the offset torque, J.
    pub fn rolling_loss(&self) -> f64 {
        self.y[E_ROLLING]
    }
    /// Energy left in the ball's tangential spring and the strings' lateral spring, J.
    pub fn spring_energy(&self) -> f64 {
        let bed = self.law.bed.map_or(0.0, |b| 0.5 * b.k_lat * self.y[Q] * self.y[Q]);
        0.5 * self.law.base.kt * self.y[S] * self.y[S] + bed
    }

    /// Advance over one piece of the normal force history.
    pub fn advance(&mut self, piece: &ForcePiece) {
        if !self.started {
            self.started = true;
            self.modes = self.first_modes(piece);
        }
        self.turning = piece.turning_points();
        self.chatter |= stepper::advance(self, piece);
    }

    /// The modes at first contact (`F_n = 0`): the ball slides with its slip unless the spring
    /// can take it up as fast as the friction limit grows (as for the elastic law); the strings
    /// slide at once if the ball's friction can push them.
    fn first_modes(&self, piece: &ForcePiece) -> Modes {
        let law = &self.law;
        let w = self.y[V] - law.base.radius * self.y[OM];
        let ball = if w != 0.0 && (law.damping > 0.0 || law.base.kt * w.abs() > law.base.mu * piece.rate(0.0)) {
            Ball::Slide(w.signum())
        } else {
            Ball::Grip
        };
        let strings = match (ball, law.bed) {
            (Ball::Slide(sign), Some(b)) if law.base.mu > b.mu_ss * b.share => Strings::Slide(sign),
            _ => Strings::Stuck,
        };
        Modes { ball, strings, spin: sign0(self.y[OM]) }
    }

    /// What the normal force makes of the contact at `t`: the force, its rate, the lever of
    /// the friction and the offset torque's capacity.
    fn drive_at(&self, piece: &ForcePiece, t: f64, peak: Peak) -> Drive {
        let law = &self.law;
        let (f, df) = (piece.force(t).max(0.0), piece.rate(t));
        let needs_delta = law.shrink || law.offset_loss > 0.0;
        let delta = if needs_delta { law.compression.delta(f, peak.at(piece, t)) } else { 0.0 };
        let lever = if law.shrink { law.base.radius - delta } else { law.base.radius };
        let arm = if law.offset_loss > 0.0 {
            offset::moment_arm(law.offset_loss, law.compression.contact_radius(delta)) * f
        } else {
            0.0
        };
        Drive { f, df, lever, arm }
    }

    /// The contact's forces and rates in the current modes.
    fn kin(&self, y: &Y, d: &Drive) -> Kin {
        let law = &self.law;
        let (f, df, lever) = (d.f, d.df, d.lever);
        let w = y[V] - lever * y[OM] - y[U];
        let (kt, c) = (law.base.kt, law.damping);
        let (p, sdot, qdot) = match (self.modes.ball, self.modes.strings, law.bed) {
            (Ball::Grip, Strings::Stuck, _) | (Ball::Grip, _, None) => (kt * y[S] + c * w, w, 0.0),
            (Ball::Slide(sign), Strings::Stuck, _) | (Ball::Slide(sign), _, None) => {
                let p = sign * law.base.mu * f;
                let sdot = if c > 0.0 { (p - kt * y[S]) / c } else { sign * law.base.mu * df / kt };
                (p, sdot, 0.0)
            }
            (Ball::Grip, Strings::Slide(sb), Some(b)) => {
                let p = b.k_lat * y[Q] + sb * b.limit(f);
                let sdot =
                    if c > 0.0 { (p - kt * y[S]) / c } else { (b.k_lat * w + sb * b.limit_rate(df)) / (kt + b.k_lat) };
                (if c > 0.0 { p } else { kt * y[S] }, sdot, w - sdot)
            }
            (Ball::Slide(sign), Strings::Slide(sb), Some(b)) => {
                let p = sign * law.base.mu * f;
                let sdot = if c > 0.0 { (p - kt * y[S]) / c } else { sign * law.base.mu * df / kt };
                (p, sdot, (sign * law.base.mu * df - sb * b.limit_rate(df)) / b.k_lat)
            }
        };
        let (torque, capacity) = if law.offset_loss > 0.0 && self.modes.ball == Ball::Grip {
            let arm = d.arm;
            match self.modes.spin {
                0.0 => (-lever * p, arm),
                sign => (-sign * arm, arm),
            }
        } else {
            (0.0, 0.0)
        };
        Kin { p, sdot, qdot, w, lever, torque, capacity }
    }
}

impl Switched<9, 3> for Combined {
    type Frozen = Peak;
    type Drive = Drive;

    fn state(&self) -> &Y {
        &self.y
    }

    fn max_substep(&self) -> f64 {
        match (self.modes.ball, self.modes.strings) {
            (Ball::Slide(_), _) => self.h_max.slide,
            (Ball::Grip, Strings::Stuck) => self.h_max.grip,
            (Ball::Grip, Strings::Slide(_)) => self.h_max.grip_bed,
        }
    }

    fn frozen(&self, _piece: &ForcePiece, t: f64) -> Peak {
        Peak { f_max: self.f_max, from: t, turning: self.turning }
    }

    /// The rates of the state.
    fn drive(&self, piece: &ForcePiece, t: f64, peak: Peak) -> Drive {
        self.drive_at(piece, t, peak)
    }

    fn rates(&self, y: &Y, d: &Drive) -> Y {
        let law = &self.law;
        let k = self.kin(y, d);
        let f = d.f;
        let friction = match self.modes.ball {
            Ball::Slide(sign) => sign * law.base.mu * f * (k.w - k.sdot - k.qdot),
            Ball::Grip => 0.0,
        };
        let bed = match (self.modes.strings, law.bed) {
            (Strings::Slide(sb), Some(b)) => sb * b.limit(f) * k.qdot,
            _ => 0.0,
        };
        [
            -k.p / law.base.mb,
            (k.lever * k.p + k.torque) / law.base.inertia,
            k.p * law.base.racket_inv_mass,
            k.sdot,
            k.qdot,
            friction,
            law.damping * k.sdot * k.sdot,
            bed,
            -k.torque * y[OM],
        ]
    }

    /// The guards of the current modes at state `y` and time `t`, each non-negative while its
    /// mode lasts (infinite where it does not apply): 0 the ball's grip or slide, 1 the
    /// strings' stick or slide, 2 the sign of the spin (or its hold at zero) while the offset
    /// torque acts.
    fn guards(&self, y: &Y, d: &Drive) -> [f64; 3] {
        let law = &self.law;
        let k = self.kin(y, d);
        let f = d.f;
        let ball = match self.modes.ball {
            Ball::Grip => law.base.mu * f - k.p.abs(),
            Ball::Slide(sign) => sign * (k.w - k.sdot - k.qdot),
        };
        let strings = match (law.bed, self.modes.strings) {
            (Some(b), Strings::Stuck) => b.limit(f) - (k.p - b.k_lat * y[Q]).abs(),
            (Some(_), Strings::Slide(sb)) => sb * k.qdot,
            (None, _) => f64::INFINITY,
        };
        let spin = match (k.capacity > 0.0, self.modes.spin) {
            (false, _) => f64::INFINITY,
            (true, 0.0) => k.capacity - k.torque.abs(),
            (true, sign) => sign * y[OM],
        };
        [ball, strings, spin]
    }

    /// Accept a substep `[t, t + h]` ending at `y`.
    fn commit(&mut self, piece: &ForcePiece, t: f64, h: f64, y: Y) {
        self.y = y;
        if matches!(self.modes.ball, Ball::Slide(_)) {
            self.slide_time += h;
        }
        self.f_max = self.frozen(piece, t).at(piece, t + h);
    }

    /// Change the mode whose guard `g` failed, at `t`.
    fn switch(&mut self, g: usize, piece: &ForcePiece, t: f64) {
        let k = self.kin(&self.y, &self.drive_at(piece, t, self.frozen(piece, t)));
        match g {
            0 => {
                self.modes.ball = match self.modes.ball {
                    Ball::Grip => Ball::Slide(k.p.signum()),
                    Ball::Slide(_) => Ball::Grip,
                };
                self.modes.spin = sign0(self.y[OM]);
            }
            1 => {
                let b = self.law.bed.expect("a strings guard only with a bed");
                self.modes.strings = match self.modes.strings {
                    Strings::Stuck => Strings::Slide((k.p - b.k_lat * self.y[Q]).signum()),
                    Strings::Slide(_) => Strings::Stuck,
                }
            }
            // the spin passed zero: held there; or the hold gave way: it turns with the friction
            _ => self.modes.spin = if self.modes.spin == 0.0 { sign0(k.lever * k.p) } else { 0.0 },
        }
    }
}

/// What the normal force makes of the contact at one time (it does not depend on the state).
#[derive(Debug, Clone, Copy)]
pub(super) struct Drive {
    /// Normal force (not below 0), N.
    f: f64,
    /// Its rate, N/s.
    df: f64,
    /// Lever of the friction force, m.
    lever: f64,
    /// The largest offset torque, `d F_n`, N m (0 without the mechanism).
    arm: f64,
}

/// The longest substep in each mode, from the rates of the mode's own linear dynamics (a
/// Runge-Kutta step's error goes with the step times the rate): [`GRIP_SUBSTEP`] over the
/// grip oscillation's rate `sqrt(k_t / m_red)`, which sets the pace of every mode, and
/// [`SUBSTEP`] over each relaxation the damper brings in: while the ball grips on stuck
/// strings, the decay `c / m_red` of a heavily damped oscillation; while the strings slide
/// under a gripping ball, the relaxation `(k_t + k_lat) / c` of the two springs through the
/// damper; and while the ball slides (the force through the damper is then set by friction),
/// the relaxation `k_t / c` of its spring.
#[derive(Debug, Clone, Copy)]
struct Substeps {
    /// The ball grips, the strings are stuck, s.
    grip: f64,
    /// The ball grips, the strings slide, s.
    grip_bed: f64,
    /// The ball slides, s.
    slide: f64,
}

impl Substeps {
    /// The shortest substep of any mode, s.
    fn shortest(&self) -> f64 {
        self.grip.min(self.grip_bed).min(self.slide)
    }

    fn of(law: &CombinedLaw) -> Substeps {
        let inv_red = law.inv_red();
        let (kt, c) = (law.base.kt, law.damping);
        let oscillation = GRIP_SUBSTEP / (kt * inv_red).sqrt();
        if c > 0.0 {
            let k_beds = kt + law.bed.map_or(0.0, |b| b.k_lat);
            Substeps {
                grip: oscillation.min(SUBSTEP / (c * inv_red)),
                grip_bed: oscillation.min(SUBSTEP * c / k_beds),
                slide: oscillation.min(SUBSTEP * c / kt),
            }
        } else {
            Substeps { grip: oscillation, grip_bed: oscillation, slide: oscillation }
        }
    }
}

/// The largest normal force up to a time: the largest before a substep and the piece's own
/// maximum from the substep's start on (the ball's compression follows its expansion branch
/// after the peak, [`Compression::delta`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Peak {
    /// Largest force before `from`, N.
    f_max: f64,
    /// Start of the substep, s into the piece.
    from: f64,
    /// The piece's turning points ([`ForcePiece::turning_points`]).
    turning: [f64; 2],
}

impl Peak {
    /// The largest force up to `t`, N.
    fn at(&self, piece: &ForcePiece, t: f64) -> f64 {
        self.f_max.max(piece.max_force(&self.turning, self.from, t))
    }
}

/// The sign of `x`, 0 for 0 (and NaN).
fn sign0(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::tangential::loss;

    /// A smooth single-hump normal force of about 1 kN over 5 ms cut into `n` Hermite pieces.
    fn cut(n: usize) -> Vec<ForcePiece> {
        let tau = 5e-3;
        let f = |t: f64| 4e8 * t * (tau - t) * (1e-3 + t);
        let df = |t: f64| 4e8 * ((tau - 2.0 * t) * (1e-3 + t) + t * (tau - t));
        let h = tau / n as f64;
        (0..n)
            .map(|i| {
                let (a, b) = (i as f64 * h, (i + 1) as f64 * h);
                ForcePiece::hermite(h, (f(a), df(a)), (f(b), df(b)))
            })
            .collect()
    }

    fn law(damping: bool, offset: bool, bed: bool, shrink: bool) -> CombinedLaw {
        let (mb, r) = (0.057, 0.033);
        let mut law = CombinedLaw {
            base: GripSlip { mu: 0.45, kt: 2e4, mb, radius: r, inertia: 0.55 * mb * r * r, racket_inv_mass: 2.0 },
            damping: 0.0,
            offset_loss: if offset { 0.44 } else { 0.0 },
            bed: bed.then(|| Bed::of(4e4, 0.05)),
            shrink,
            compression: Compression { k: 7.9e4, p: 2.55, radius: r },
        };
        if damping {
            law.damping = loss::damper(0.09, law.base.kt, law.inv_red());
        }
        law
    }

    fn run(law: CombinedLaw, v: f64, omega: f64, pieces: &[ForcePiece]) -> Combined {
        let mut c = Combined::new(law, v, omega);
        for p in pieces {
            c.advance(p);
        }
        c
    }

    /// Every combination of mechanisms: the same force history cut into 1, 7 or 60 pieces gives
    /// the same outcome (the switches are located inside pieces), and the ledger closes.
    #[test]
    fn outcome_does_not_depend_on_the_cut_and_the_ledger_closes() {
        for bits in 0..16u32 {
            let law = law(bits & 1 != 0, bits & 2 != 0, bits & 4 != 0, bits & 8 != 0);
            for (v, omega) in [(4.3, 0.0), (16.0, -400.0), (2.0, 300.0)] {
                let one = run(law, v, omega, &cut(1));
                for n in [7, 60] {
                    let many = run(law, v, omega, &cut(n));
                    let d = (one.omega() - many.omega()).abs() / (v / law.base.radius);
                    assert!(d < 1e-6, "bits {bits:04b} v {v} omega {omega} n {n}: {} vs {}", one.omega(), many.omega());
                }
                let ke = |v: f64, w: f64| 0.5 * law.base.mb * v * v + 0.5 * law.base.inertia * w * w;
                let inplane = 0.5 * one.u() * one.u() / law.base.racket_inv_mass;
                let losses = one.friction_loss() + one.damping_loss() + one.bed_loss() + one.rolling_loss();
                let ledger = ke(v, omega) - ke(one.v(), one.omega()) - inplane - losses - one.spring_energy();
                assert!(ledger.abs() < 1e-8 * ke(v, omega), "bits {bits:04b}: {ledger}");
            }
        }
    }

    /// A gripping impact on an immovable frame returns the ball's tangential restitution: a
    /// constant normal force (the friction limit never reached) for the damped half period of
    /// the grip oscillation leaves the contact point with `-e_x` of its incoming slip, whatever
    /// the incoming spin and speed, to the accuracy of the Runge-Kutta substeps ([`SUBSTEP`] =
    /// 0.2 of the oscillation's time scale: about 5e-5 over the half cycle, in the spin and in
    /// the ledger, which closes to the same).
    #[test]
    fn a_gripping_impact_on_an_immovable_frame_returns_e_x() {
        let (mb, r) = (0.057, 0.033);
        for e_x in [0.10, 0.135, 0.17] {
            let mut law = law(false, false, false, false);
            law.base.racket_inv_mass = 0.0;
            law.base.mu = 50.0;
            let zeta = loss::damping_ratio(e_x);
            law.damping = loss::damper(zeta, law.base.kt, law.inv_red());
            let h = loss::half_period(zeta, law.base.kt, law.inv_red());
            let piece = ForcePiece::hermite(h, (500.0, 0.0), (500.0, 0.0));
            for (v, omega) in [(10.0, 0.0), (10.0, -400.0), (-3.0, 200.0)] {
                let c = run(law, v, omega, &[piece]);
                let (w_in, w_out) = (v - r * omega, c.v() - r * c.omega());
                assert_eq!(c.u(), 0.0);
                assert!((-w_out / w_in / e_x - 1.0).abs() < 1e-4, "e_x {e_x}, v {v}, omega {omega}: {}", -w_out / w_in);
                let ke = |v: f64, w: f64| 0.5 * mb * v * v + 0.5 * law.base.inertia * w * w;
                let ledger =
                    ke(v, omega) - ke(c.v(), c.omega()) - c.damping_loss() - c.friction_loss() - c.spring_energy();
                assert!(ledger.abs() < 1e-4 * ke(v, omega), "{}", ledger / ke(v, omega));
                // momentum about the contact point: the ball's angular momentum there is kept
                let l = |v: f64, w: f64| mb * r * v + law.base.inertia * w;
                assert!((l(v, omega) - l(c.v(), c.omega())).abs() < 1e-9 * l(v, omega).abs().max(1e-3));
            }
        }
    }
}
