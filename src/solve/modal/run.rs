//! The modal solver's steps: predict every coordinate over a step with the end force and rate
//! zero, solve the contact law at the end of the step ([`ImplicitLaw`]), check the cubic force
//! history against the law inside the step (halving the step where it misses), then add the
//! end force and rate and keep the ledger.

use crate::error::Result;
use crate::model::contact::{ContactLaw, ImplicitLaw, Phase};
use crate::model::tangential::ForcePiece;
use crate::solve::hermite::Hermite;
use crate::solve::modal::pair::Pair;
use crate::solve::modal::steps::Grid;
use crate::solve::modal::{ModalModel, State, LEVELS, START};
use crate::solve::oblique::Follower;

/// A step that misses the law by less than this fraction of the tolerance lets the next be twice
/// as long.
const GROW: f64 = 1.0 / 64.0;

/// The contact at the end of a step.
#[derive(Debug, Clone, Copy)]
pub(super) struct End {
    /// Force, N, and its rate, N/s.
    pub f: f64,
    pub d: f64,
    /// Total compression `Y_T`, m, and its rate, m/s.
    pub yt: f64,
    pub ytd: f64,
    pub phase: Phase,
    /// `(u, u^p)` of the expansion law.
    pub u: (f64, f64),
    /// Time of maximum compression, s (once passed).
    pub t_max: f64,
}

/// An impact in progress.
pub(super) struct Run<'a> {
    pub m: &'a ModalModel,
    pub s: State,
    pub next: State,
    pub at: End,
    pub t: f64,
    pub peak_force: f64,
    pub energy_err: f64,
    pub momentum_err: f64,
    /// Contact time and twist angle at separation, once it has happened.
    pub separated: Option<(f64, f64)>,
    /// The tangential contact of an oblique or spinning ball.
    pub tangential: Follower,
    /// The step level of the next step.
    pub level: usize,
}

impl Run<'_> {
    /// Take one step: at the current level, or, where its force history misses the contact law
    /// by more than the tolerance, at the finest level needed (down to the finest, which is
    /// accepted as it is). A step that misses by less than a sixty-fourth of the tolerance lets
    /// the next one be twice as long (the miss of a cubic history grows as the fifth power of
    /// the step).
    pub fn advance(&mut self) -> Result<()> {
        let m = self.m;
        loop {
            let grid = m.grid(self.level);
            let a = self.at;
            let pred = m.predict(grid, &self.s, a.f, a.d, &mut self.next);
            let end = self.end_of_step(grid, pred)?;
            let miss = self.miss(grid, &end) * grid.h / m.impulse_tolerance;
            if miss > 1.0 && self.level + 1 < LEVELS {
                self.level += 1;
                continue;
            }
            self.accept(grid, end);
            if miss < GROW && self.level > START {
                self.level -= 1;
            }
            return Ok(());
        }
    }

    /// The contact at the end of the step from the prediction `(Y_hat, Yd_hat)` (the steps start
    /// at maximum compression: every step is in expansion).
    fn end_of_step(&self, grid: &Grid, (yh, ydh): (f64, f64)) -> Result<End> {
        let c = &self.m.law;
        let a = self.at;
        let mut end = a;
        let y0 = a.y0();
        let start = c.expansion_start(y0, a.u, a.ytd, grid.h);
        let e = c.expansion_end(&grid.coupling, y0, (yh, ydh), start, a.d)?.unwrap_or_default();
        end.u = e.u;
        let k = &grid.coupling;
        end.f = e.f;
        end.d = e.d;
        end.yt = yh - k.bf * e.f - k.bd * e.d;
        end.ytd = ydh - k.cf * e.f - k.cd * e.d;
        Ok(end)
    }

    /// How far the cubic force history of a step misses the contact law, N: at the midpoint, and
    /// at the quarter points too where the force falls to a quarter of its start or the ball
    /// leaves (there the law nears zero at an unknown point, the cubic can dip below zero after
    /// it, and the midpoint alone can miss that).
    fn miss(&self, grid: &Grid, end: &End) -> f64 {
        let (a, h) = (&self.at, grid.h);
        let c = &self.m.law;
        let y0 = a.y0();
        let f1 = end.f;
        let points: &[f64] = if f1 < 0.25 * a.f { &[0.25, 0.5, 0.75] } else { &[0.5] };
        let compression = Hermite { h, p0: a.yt, m0: a.ytd, p1: end.yt, m1: end.ytd };
        let force = Hermite { h, p0: a.f, m0: a.d, p1: f1, m1: end.d };
        let mut miss: f64 = 0.0;
        for &s in points {
            let (ym, cubic) = (compression.eval(s), force.eval(s));
            miss = miss.max(c.expansion_miss(y0, ym, cubic).abs());
        }
        miss
    }

    /// Take the step to `end`: the coordinates, the time, the ledger and the separation.
    fn accept(&mut self, grid: &Grid, end: End) {
        let m = self.m;
        let (h, a) = (grid.h, self.at);
        let (f1, d1) = (end.f, end.d);
        let modal_energy = m.correct(grid, &mut self.next, f1, d1);
        std::mem::swap(&mut self.s, &mut self.next);
        self.t += h;
        self.peak_force = self.peak_force.max(f1);
        self.ledger(&end, modal_energy);
        if f1 <= 0.0 {
            let sc = Hermite { h, p0: a.yt, m0: a.ytd, p1: end.yt, m1: end.ytd }.root();
            // twist angle at the crossing (`next` now holds the state before the step)
            let ix = m.impact.params.racket.ix;
            let (before, after) = (self.next.x[3].get(), self.s.x[3].get());
            let twist = Hermite { h, p0: before[0], m0: before[1], p1: after[0], m1: after[1] };
            let theta = twist.eval(sc) / ix.sqrt();
            self.separated = Some((self.t - h + sc * h, theta));
            // the last piece ends at the separation with no force and no rate, as in the explicit
            // solver: the ball's tangent stiffness vanishes with its compression (p > 1)
            self.tangential.advance(|| ForcePiece::hermite(sc * h, (a.f, a.d), (0.0, 0.0)));
        } else {
            self.tangential.advance(|| ForcePiece::hermite(h, (a.f, a.d), (f1, d1)));
        }
        self.at = end;
    }

    /// The largest energy and momentum errors so far, with the state `s` at `end` (whose
    /// coordinates carry `modal_energy`).
    pub fn ledger(&mut self, end: &End, modal_energy: f64) {
        let (m, c) = (self.m, &self.m.law);
        let p = &m.impact.params;
        let (mb, v1) = (p.ball.mass, p.impact.v1);
        let e0 = 0.5 * mb * v1 * v1;
        let st = c.state_at_force(end.phase, end.f, end.u);
        let e = modal_energy
            + c.ball_energy_with_loss(end.phase, &st)
            + c.string_energy(&st)
            + 0.5 * m.set.residual * end.f * end.f;
        self.energy_err = self.energy_err.max((e - e0).abs() / e0);
        let pm = mb.sqrt() * self.s.v(0) + self.s.v(1) / m.set.g[1];
        self.momentum_err = self.momentum_err.max((pm - mb * v1).abs() / (mb * v1));
    }
}

impl End {
    /// The ball's compression at maximum compression, m.
    fn y0(&self) -> f64 {
        match self.phase {
            Phase::Expansion { y0 } => y0,
            Phase::Compression => unreachable!("the modal steps start at maximum compression"),
        }
    }
}

impl ModalModel {
    /// Advance `s` over one step with the end force and rate zero into `out`; returns
    /// `(Y_T, Y_T')` of that prediction.
    pub(super) fn predict(&self, grid: &Grid, s: &State, f0: f64, d0: f64, out: &mut State) -> (f64, f64) {
        let (f0, d0) = (Pair::splat(f0), Pair::splat(d0));
        let mut y = Pair::splat(0.0);
        for ((c, x0), x1) in grid.coef.iter().zip(&s.x).zip(&mut out.x) {
            let (q, v) = x0.spread();
            let next = c.from_q.mul(q).add(c.from_v.mul(v)).add(c.f0.mul(f0).add(c.d0.mul(d0)));
            *x1 = next;
            y = y.add(c.g.mul(next));
        }
        let [yq, yv] = y.get();
        (-yq, -yv)
    }

    /// Add the end force and rate to a predicted step; returns the coordinates' energy, J.
    pub(super) fn correct(&self, grid: &Grid, out: &mut State, f1: f64, d1: f64) -> f64 {
        let (f1, d1) = (Pair::splat(f1), Pair::splat(d1));
        let mut e = Pair::splat(0.0);
        for (c, x) in grid.coef.iter().zip(&mut out.x) {
            let next = x.add(c.f1.mul(f1).add(c.d1.mul(d1)));
            *x = next;
            e = e.add(c.lam.mul(next.mul(next)));
        }
        let [eq, ev] = e.get();
        0.5 * (eq + ev)
    }

    /// The coordinates' energy, kinetic plus potential, J.
    pub(super) fn energy(&self, s: &State) -> f64 {
        0.5 * (0..s.x.len()).map(|j| s.v(j) * s.v(j) + self.set.lam[j] * s.q(j) * s.q(j)).sum::<f64>()
    }
}
