//! The stepper of a switched ODE driven by the normal force: a law whose state `y` follows
//! `dy/dt = f_mode(t, y)` in each of its modes and switches mode where one of its guards
//! `g_mode(t, y)` (non-negative while the mode lasts) turns negative. Each piece of the normal
//! force history ([`ForcePiece`]) is crossed in classical Runge-Kutta substeps no longer than
//! the law's own limit; a substep that ends with a guard violated is cut back to the switch
//! time, found to rounding by the Illinois variant of regula falsi on the substep (restarted on
//! any guard that fails earlier), and the law changes the mode whose guard failed there.
//!
//! The law supplies its rates, its guards and what happens at a switch ([`Switched`]); this
//! file knows nothing of balls or strings.

use super::piece::ForcePiece;

/// Switches per piece at most (each moves on in time; the count guards rounding).
const MAX_SWITCHES: usize = 64;
/// Iterations at most to locate a switch time.
const BISECTIONS: usize = 100;

/// A switched law of `N` state variables with `G` guards.
pub(super) trait Switched<const N: usize, const G: usize> {
    /// What the law holds fixed over one substep (set at its start).
    type Frozen: Copy;
    /// What the rates and guards take from the time alone (the normal force and what follows
    /// from it), computed once for each time a substep visits.
    type Drive: Copy;

    /// The state now.
    fn state(&self) -> &[f64; N];
    /// The longest substep, s.
    fn max_substep(&self) -> f64;
    /// What is held fixed over a substep that starts at `t` (s into the piece).
    fn frozen(&self, piece: &ForcePiece, t: f64) -> Self::Frozen;
    /// The drive at `t`.
    fn drive(&self, piece: &ForcePiece, t: f64, frozen: Self::Frozen) -> Self::Drive;
    /// The rates of the state `y` under the drive `d` in the current modes.
    fn rates(&self, y: &[f64; N], d: &Self::Drive) -> [f64; N];
    /// The guards of the current modes at the state `y` under the drive `d`, each
    /// non-negative while its mode lasts (infinite where it does not apply).
    fn guards(&self, y: &[f64; N], d: &Self::Drive) -> [f64; G];
    /// Accept the substep `[t, t + h]` ending at `y`.
    fn commit(&mut self, piece: &ForcePiece, t: f64, h: f64, y: [f64; N]);
    /// Change the mode whose guard `g` failed, at `t`.
    fn switch(&mut self, g: usize, piece: &ForcePiece, t: f64);
}

/// Advance the law over one piece of the normal force history; `true` if the piece reached its
/// cap of [`MAX_SWITCHES`] and took its rest in the mode it was in, unchecked (a chatter at an
/// edge between two modes: SPEC.md section 6, "Known limit").
pub(super) fn advance<L: Switched<N, G>, const N: usize, const G: usize>(law: &mut L, piece: &ForcePiece) -> bool {
    let mut t = 0.0;
    let mut switches = 0;
    let mut capped = false;
    // the drive at the start of each substep: the one at the end of the substep before (the
    // same numbers: what a law freezes for a substep must not change its drive at the start)
    let mut d0 = law.drive(piece, t, law.frozen(piece, t));
    while t < piece.h {
        let h = (piece.h - t).min(law.max_substep());
        let frozen = law.frozen(piece, t);
        let (end, drive) = step(law, piece, t, law.state(), &d0, h, frozen);
        match violated(law, &end, &drive) {
            None => {
                law.commit(piece, t, h, end);
                t += h;
                d0 = drive;
            }
            Some(_) if switches >= MAX_SWITCHES => {
                capped = true;
                law.commit(piece, t, h, end);
                t += h;
                d0 = drive;
            }
            Some(first) => {
                // the shortest substep whose end violates a guard, to rounding
                let (hi, y, drive) = locate(law, piece, t, &d0, h, frozen, first);
                let which = violated(law, &y, &drive);
                law.commit(piece, t, hi, y);
                t += hi;
                d0 = drive;
                if let Some(g) = which {
                    law.switch(g, piece, t);
                }
                switches += 1;
            }
        }
    }
    capped
}

/// One classical Runge-Kutta step of length `h` from `(t, y)` with the drive `d0` at `t`:
/// the state at `t + h` and the drive there.
fn step<L: Switched<N, G>, const N: usize, const G: usize>(
    law: &L,
    piece: &ForcePiece,
    t: f64,
    y: &[f64; N],
    d0: &L::Drive,
    h: f64,
    frozen: L::Frozen,
) -> ([f64; N], L::Drive) {
    let add = |a: &[f64; N], b: &[f64; N], s: f64| -> [f64; N] { std::array::from_fn(|i| a[i] + s * b[i]) };
    let (dm, d1) = (law.drive(piece, t + 0.5 * h, frozen), law.drive(piece, t + h, frozen));
    let k1 = law.rates(y, d0);
    let k2 = law.rates(&add(y, &k1, 0.5 * h), &dm);
    let k3 = law.rates(&add(y, &k2, 0.5 * h), &dm);
    let k4 = law.rates(&add(y, &k3, h), &d1);
    (std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])), d1)
}

/// The first guard the state `y` under the drive `d` violates, if any ([`Switched::guards`]).
fn violated<L: Switched<N, G>, const N: usize, const G: usize>(law: &L, y: &[f64; N], d: &L::Drive) -> Option<usize> {
    law.guards(y, d).iter().position(|&g| g < 0.0)
}

/// The earliest time in `(0, h]` after `t` at which a guard fails (one fails at `h`), to
/// rounding: the Illinois variant of regula falsi on the guard that fails, restarted on
/// any guard that fails earlier. Returns the time, the state there and the drive. (Not the
/// crate's bisection, [`crate::numeric::root`]: each iterate here is a whole RK4 step from the
/// substep's start, so the fewer the better, and the search restarts on another guard.)
fn locate<L: Switched<N, G>, const N: usize, const G: usize>(
    law: &L,
    piece: &ForcePiece,
    t: f64,
    d0: &L::Drive,
    h: f64,
    frozen: L::Frozen,
    first: usize,
) -> (f64, [f64; N], L::Drive) {
    let y0 = law.state();
    let start = law.guards(y0, d0);
    let (mut g, mut lo, mut hi) = (first, 0.0, h);
    let (mut at_hi, mut drive_hi) = step(law, piece, t, y0, d0, h, frozen);
    for _ in 0..MAX_SWITCHES {
        let value = |(y, d): &([f64; N], L::Drive)| law.guards(y, d)[g];
        let (mut a, mut fa) = (lo, start[g].max(0.0));
        if a > 0.0 {
            fa = value(&step(law, piece, t, y0, d0, a, frozen)).max(0.0);
        }
        let (mut b, mut fb) = (hi, law.guards(&at_hi, &drive_hi)[g]);
        let mut side = 0;
        for _ in 0..BISECTIONS {
            if b - a <= 1e-13 * h {
                break;
            }
            let mut c = (a * fb - b * fa) / (fb - fa);
            if !(c > a && c < b) {
                c = 0.5 * (a + b);
            }
            let at_c = step(law, piece, t, y0, d0, c, frozen);
            let fc = value(&at_c);
            if fc < 0.0 {
                (b, fb, (at_hi, drive_hi)) = (c, fc, at_c);
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            } else {
                (a, fa) = (c, fc);
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            }
        }
        // another guard failing before this one's root takes over
        let (y, d) = step(law, piece, t, y0, d0, a, frozen);
        match violated(law, &y, &d) {
            Some(other) if a > 0.0 => {
                (g, hi, at_hi, drive_hi) = (other, a, y, d);
                lo = 0.0;
            }
            _ => return (b, at_hi, drive_hi),
        }
    }
    (hi, at_hi, drive_hi)
}
