//! The validation uncertainty of each compared value, as ASME V&V 20 builds it (SPEC.md section
//! 7): `u_val = sqrt(u_input^2 + u_num^2 + u_D^2 + u_angle^2)`.
//!
//! - `u_input`: the standard deviation of the value over the declared input uncertainties
//!   (`ks`, as the ±10 % factor its declaration states, `mb`, `k1`, `p`, `ball-ex` under a law
//!   that uses it) and the calibrated `kt` (log-uniform over its 95 % interval), drawn by the
//!   `uncertainty` machinery (a scrambled Sobol' design, [`crate::study::sensitivity`]) with the
//!   modal solver; the hand-held impacts run fd, the only solver with a hand.
//! - `u_num`: the explicit and modal solvers' difference at the nominal inputs (the table's
//!   values are fd's); for the grip-stop angle, half a degree (the scan's step).
//! - `u_D`: the lab's stated or estimated scatter ([`table_scatter`] for the TWU table, which
//!   states none).
//! - `u_angle`: the TWU angle read two ways (40 and 50 deg from the normal), an input of the
//!   experiment: half the difference of the model at the two readings (the standard deviation of
//!   two equally likely values).

use super::shots;
use crate::error::Result;
use crate::params::uncertainty::Dist;
use crate::params::{keys, Overrides, Params, SolverKind, TangentialLaw};
use crate::solve::simulate;
use crate::study::measured::Measured;
use crate::study::sensitivity::{self, Design};

use super::super::Context;
use super::compare::{mean, spin_ratio};

/// Base samples of the input propagation: `SAMPLES (d + 2)` evaluations of every output.
pub const SAMPLES: u64 = 32;
/// The seed of its design.
pub const SEED: u32 = 37;

/// The outputs of one evaluation, in order: the 14 table spins at 40 deg, then these.
pub const RATIO_ALL: usize = 14;
/// The polyester/nylon ratio over the validation strings only.
pub const RATIO_VALIDATION: usize = 15;
/// The hand-held over clamped spin.
pub const HAND_RATIO: usize = 16;
/// The forehand's spin, 20 and 30 deg paths.
pub const FOREHAND: [usize; 2] = [17, 18];

/// The paths of the tour forehand, degrees.
pub const PATHS_DEG: [f64; 2] = [20.0, 30.0];

/// The inputs drawn: a factor on every string stiffness, the declared uncertainties of the ball
/// (those the impact `shot` uses: `ball-ex` under a law with `loss`, `ball-kdyn` under one with
/// `radius` or `offset`), and `kt` log-uniform over `kt_interval`.
pub fn inputs(shot: &Params, kt_interval: (f64, f64)) -> Vec<(&'static str, Dist)> {
    let mut out = vec![("ks-factor", Dist::Uniform { lo: 0.9, hi: 1.1 })];
    for spec in [keys::MB, keys::K1, keys::P, keys::BALL_EX, keys::BALL_KDYN] {
        if crate::params::used::unused(&spec, shot).is_some() {
            continue;
        }
        if let Some(u) = spec.uncertainty {
            out.push((spec.key, u.dist));
        }
    }
    out.push((keys::KT.key, Dist::LogUniform { lo: kt_interval.0, hi: kt_interval.1 }));
    out
}

/// `p` with the drawn values `x` of `inputs`.
fn with(p: &Params, inputs: &[(&'static str, Dist)], x: &[f64]) -> Result<Params> {
    let mut q = *p;
    let mut o = Overrides::default();
    for ((name, _), &v) in inputs.iter().zip(x) {
        if *name == "ks-factor" {
            q.strings.ks *= v;
        } else {
            o.set(name, &v.to_string())?;
        }
    }
    o.apply(&mut q);
    q.validate()?;
    Ok(q)
}

/// The nominal shots of the outputs under `law` with the solver `solver` (the hand-held impact
/// always fd): the 14 table shots at 40 deg, the hand-held and clamped pair, the forehand base.
pub struct Shots {
    /// The table's shots.
    pub table: Vec<Params>,
    /// The hand-held and the clamped shot.
    pub hand: (Params, Params),
    /// The free racket the forehand swings.
    pub forehand: Params,
}

impl Shots {
    /// The shots of `rows` (the TWU table) under `law`.
    pub fn new(ctx: &Context, law: TangentialLaw, rows: &[Measured], solver: SolverKind) -> Result<Shots> {
        let mut table = Vec::new();
        for r in rows {
            let mut p = shots::table_shot(ctx, law, r, shots::TWU_ANGLE_DEG)?;
            p.numerics.solver = solver;
            table.push(p);
        }
        let (hand, mut clamped) = shots::hand_and_clamped(ctx, law);
        clamped.numerics.solver = solver;
        let mut forehand = ctx.paper_params(super::super::CENTRE_X, crate::params::ks_from_tension_lb(60.0));
        forehand.oblique.tangential = law;
        forehand.numerics.solver = solver;
        Ok(Shots { table, hand: (hand, clamped), forehand })
    }

    /// Every output with the inputs `x` (none: the nominal shots).
    pub fn outputs(&self, rows: &[Measured], inputs: &[(&'static str, Dist)], x: &[f64]) -> Result<Vec<f64>> {
        let mut out = Vec::with_capacity(FOREHAND[1] + 1);
        for p in &self.table {
            out.push(simulate(&with(p, inputs, x)?)?.spin_out_rpm);
        }
        out.push(poly_over_nylon(rows, &out, |_| true));
        out.push(poly_over_nylon(rows, &out, |r| r.role == Some(crate::study::measured::Role::Validation)));
        let hand = simulate(&with(&self.hand.0, inputs, x)?)?.spin_out_rpm;
        let clamped = simulate(&with(&self.hand.1, inputs, x)?)?.spin_out_rpm;
        out.push(spin_ratio(hand, clamped));
        for path in PATHS_DEG {
            out.push(shots::forehand_spin(&with(&self.forehand, inputs, x)?, path)?);
        }
        Ok(out)
    }
}

/// The mean spin of the polyesters over that of the nylons among the table `rows` that `keep`
/// selects, from `spins` (one per row, in order).
pub fn poly_over_nylon(rows: &[Measured], spins: &[f64], keep: impl Fn(&Measured) -> bool) -> f64 {
    let of = |material: &str| {
        let v: Vec<f64> = rows
            .iter()
            .zip(spins)
            .filter(|(r, _)| keep(r) && r.string.contains(&format!("({material})")))
            .map(|(_, &s)| s)
            .collect();
        mean(&v)
    };
    spin_ratio(of("polyester"), of("nylon"))
}

/// The standard deviation of each output over the inputs' uncertainty.
pub fn u_input(shots: &Shots, rows: &[Measured], inputs: &[(&'static str, Dist)]) -> Result<Vec<f64>> {
    let design = Design::new(SAMPLES, inputs.len(), SEED)?;
    let dists: Vec<Dist> = inputs.iter().map(|(_, d)| *d).collect();
    let runs = sensitivity::run(&design, &dists, |x| shots.outputs(rows, inputs, x), |_| {})?;
    Ok(sensitivity::summarise_all(&design, &runs).into_iter().map(|s| s.sd).collect())
}

/// The shot-to-shot scatter of the TWU table, rpm, which the table does not state: estimated
/// from its own pairs, each string at 52 and 62 lb, whose differences show no consistent
/// tension effect (data/measured/README.md: mean +0.4 %): if both are one spin measured twice,
/// a pair's difference has `sqrt(2)` times the scatter, `sigma = sqrt(mean(d^2) / 2)`.
pub fn table_scatter(rows: &[Measured]) -> f64 {
    let mut d2 = Vec::new();
    for a in rows.iter().filter(|r| r.tension_lb == Some(52.0)) {
        if let Some(b) = rows.iter().find(|b| b.string == a.string && b.tension_lb == Some(62.0)) {
            d2.push((a.value - b.value).powi(2));
        }
    }
    (mean(&d2) / 2.0).sqrt()
}

/// The scatter of a ratio of the polyesters' mean over the nylons' mean, each a mean of
/// `n_poly` and `n_nylon` table values of scatter `sigma`.
pub fn ratio_scatter(ratio: f64, sigma: f64, (poly, n_poly): (f64, usize), (nylon, n_nylon): (f64, usize)) -> f64 {
    let rel = |m: f64, n: usize| sigma / (n as f64).sqrt() / m;
    ratio * (rel(poly, n_poly).powi(2) + rel(nylon, n_nylon).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::measured;

    /// The table's pairs, 62 minus 52 lb in the table's order of strings: -118, -151, -23, +9,
    /// +29, +79, +215 rpm (as data/measured/README.md lists them): 80.5 rpm.
    #[test]
    fn the_table_s_scatter_comes_from_its_pairs() {
        let rows = measured::rows(&shots::TABLE_IDS).unwrap();
        let d: [f64; 7] = [118.0, 151.0, 23.0, 9.0, 29.0, 79.0, 215.0];
        let expected = (d.iter().map(|x| x * x).sum::<f64>() / 7.0 / 2.0).sqrt();
        assert!((table_scatter(&rows) - expected).abs() < 1e-9, "{}", table_scatter(&rows));
        assert!((expected - 80.5).abs() < 0.1);
    }

    #[test]
    fn the_inputs_are_the_declared_ones_the_law_uses_and_kt() {
        let names = |law| {
            let shot = shots::twu_shot(&Context::paper(), law, crate::params::StringName::None, 60.0);
            inputs(&shot, (5e4, 1e6)).iter().map(|(n, _)| *n).collect::<Vec<_>>()
        };
        assert_eq!(names(TangentialLaw::Loss), ["ks-factor", "mb", "k1", "p", "ball-ex", "kt"]);
        assert_eq!(names(TangentialLaw::Radius), ["ks-factor", "mb", "k1", "p", "ball-kdyn", "kt"]);
        assert_eq!(names(TangentialLaw::Elastic), ["ks-factor", "mb", "k1", "p", "kt"]);
    }
}
