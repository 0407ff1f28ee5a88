//! What the paper reads off an impact beyond its end result (p. 4-5, Fig 4 and the Fig 6
//! discussion): how much of the ball's energy the ball and strings hold at the height of the
//! compression, and how the vibration left in the frame shares among its modes.
//!
//! The explicit solver (the reference) gives both from its time series. The beam is linear and
//! starts at rest, so after the ball has left, flexible mode `k` (unit modal mass, frequency
//! `w_k`, amplitude `g_k` at the load point) holds
//!
//! ```text
//! E_k = g_k^2 |F^(w_k)|^2 / 2,   F^(w) = integral of F(t) e^(-i w t) dt over the contact
//! ```
//!
//! the impact's spectrum at the mode's frequency, which is the paper's own argument (a 5 ms
//! impact's spectrum reaches the 125 Hz fundamental but not the 345 Hz second mode). The force
//! is the series' (trapezoid rule); the modes' energies sum to the solver's own vibration
//! energy `f_vib` to the series' sampling (a test holds them within 1e-3 of it). The modal
//! solver (the fast path, the robustness study's) keeps no series but is its modes: each
//! flexible coordinate's energy once the ball has left, and the ball and strings' energy at
//! maximum compression ([`ModalModel::run_with_modes`]); a test holds the two paths together.

use crate::error::Result;
use crate::model::beam::Beam;
use crate::params::{Params, SolverKind};
use crate::solve::{FdModel, ImpactResult, ModalModel, SeriesOptions};

/// Sample spacing of the force series, s: about 150 samples a period of the 345 Hz mode.
pub const SAMPLE_DT: f64 = 2.0e-5;

/// Modes whose energies a [`Detail`] keeps one by one (the rest only in the total).
pub const KEPT_MODES: usize = 3;

/// An impact with what the paper reads off it besides its end result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Detail {
    /// The impact's result.
    pub result: ImpactResult,
    /// The largest share of the ball's incident energy held by the ball (compression, with the
    /// loss its expansion has dissipated so far, as the paper's 'PE ball') and the strings
    /// together during the impact.
    pub pe_ball_strings_peak: f64,
    /// The energy each of the first [`KEPT_MODES`] flexible modes holds after the impact, in
    /// ascending frequency, as a share of the ball's incident energy.
    pub modes: [f64; KEPT_MODES],
    /// The vibration energy after the impact, the same share: the solver's own (`f_vib`), which
    /// every flexible mode's energy adds up to (the spectrum of a sampled force cannot give the
    /// modes above its sampling rate, which a fine beam has).
    pub vibration: f64,
}

impl Detail {
    /// The share of the vibration energy in flexible mode `k` (0: the fundamental); NaN where
    /// the frame is left without vibration.
    pub fn share(&self, k: usize) -> f64 {
        if self.vibration > 0.0 {
            self.modes[k] / self.vibration
        } else {
            f64::NAN
        }
    }

    /// The straight line between two details, `w` of the way from `a` to `b` (a curve read
    /// between two nodes, as [`ImpactResult::lerp`]).
    pub fn lerp(a: &Detail, b: &Detail, w: f64) -> Detail {
        let mix = |x: f64, y: f64| (1.0 - w) * x + w * y;
        let mut modes = [0.0; KEPT_MODES];
        for (m, (x, y)) in modes.iter_mut().zip(a.modes.iter().zip(&b.modes)) {
            *m = mix(*x, *y);
        }
        Detail {
            result: ImpactResult::lerp(&a.result, &b.result, w),
            pe_ball_strings_peak: mix(a.pe_ball_strings_peak, b.pe_ball_strings_peak),
            modes,
            vibration: mix(a.vibration, b.vibration),
        }
    }
}

/// Run the impact `p` with the solver it names and read its [`Detail`]: the explicit solver's
/// from its time series ([`explicit_detail`]), the modal solver's from its modes.
pub fn detail(p: &Params) -> Result<Detail> {
    match p.numerics.solver {
        SolverKind::Modal => modal_detail(p),
        SolverKind::Fd => explicit_detail(p),
    }
}

/// The [`Detail`] of the impact `p` from the modal solver: each retained flexible mode's energy
/// once the ball has left, and the ball and strings' energy at maximum compression.
fn modal_detail(p: &Params) -> Result<Detail> {
    let (result, energies, stored) = ModalModel::new(p)?.run_with_modes()?;
    let result = super::checked(p, result)?;
    let ke = 0.5 * p.ball.mass * p.impact.v1 * p.impact.v1;
    let mut modes = [0.0; KEPT_MODES];
    for (m, e) in modes.iter_mut().zip(&energies) {
        *m = e / ke;
    }
    Ok(Detail { result, pe_ball_strings_peak: stored / ke, modes, vibration: result.f_vib })
}

/// The [`Detail`] of the impact `p` from the explicit solver's time series, whatever solver
/// `p` names.
pub fn explicit_detail(p: &Params) -> Result<Detail> {
    let (result, pe_ball_strings_peak, energies) = spectrum(p, KEPT_MODES)?;
    let mut modes = [0.0; KEPT_MODES];
    for (m, e) in modes.iter_mut().zip(&energies) {
        *m = *e;
    }
    Ok(Detail { result, pe_ball_strings_peak, modes, vibration: result.f_vib })
}

/// The explicit solver's impact `p`, the largest share of the ball's energy the ball and strings
/// hold during it, and the energy of the first `count` flexible modes after it from the
/// impact's spectrum (ascending frequency, shares of the ball's energy).
fn spectrum(p: &Params, count: usize) -> Result<(ImpactResult, f64, Vec<f64>)> {
    let model = FdModel::new(p)?;
    let (result, rows) = model.run_with_series(SeriesOptions { sample_dt: SAMPLE_DT, t_end: 0.0 })?;
    let result = super::checked(p, result)?;
    let pe_ball_strings_peak = rows.iter().map(|r| r.pe_ball + r.pe_string).fold(0.0, f64::max);
    let beam: &Beam = model.beam();
    let load = beam.load_point(p.impact.x, p.numerics.load);
    let (omega2, shapes) = beam.modes_mass_normalised();
    let ke = 0.5 * p.ball.mass * p.impact.v1 * p.impact.v1;
    let energies = omega2
        .iter()
        .zip(&shapes)
        .take(count)
        .map(|(w2, phi)| {
            let w = w2.max(0.0).sqrt();
            let g: f64 = load.nodes.iter().zip(&load.weights).map(|(&i, &wt)| wt * phi[i]).sum();
            let (mut re, mut im) = (0.0, 0.0);
            for pair in rows.windows(2) {
                let (a, b) = (&pair[0], &pair[1]);
                let dt = b.t_s - a.t_s;
                let (sa, ca) = (w * a.t_s).sin_cos();
                let (sb, cb) = (w * b.t_s).sin_cos();
                re += 0.5 * dt * (a.force_n * ca + b.force_n * cb);
                im += 0.5 * dt * (a.force_n * sa + b.force_n * sb);
            }
            0.5 * g * g * (re * re + im * im) / ke
        })
        .collect();
    Ok((result, pe_ball_strings_peak, energies))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The modes' energies from the impact's spectrum add up to the vibration energy the solver
    /// finds at separation (a check of the spectrum, the mode shapes and the load point), and
    /// at the Fig 4 impact the fundamental holds nearly all of it.
    #[test]
    fn the_modes_energies_add_up_to_the_solvers_vibration() {
        let mut p = Params::paper();
        p.impact.x = 0.10;
        p.impact.r = 0.05;
        p.strings.ks = 4.0e4;
        let d = explicit_detail(&p).unwrap();
        let (r, _, all) = spectrum(&p, usize::MAX).unwrap();
        let total: f64 = all.iter().sum();
        assert!((total - r.f_vib).abs() < 1e-3 * r.f_vib, "{total} vs {}", r.f_vib);
        assert_eq!(all[..KEPT_MODES], d.modes);
        assert!(d.share(0) > 0.5 && d.modes[0] > d.modes[1], "{d:?}");
        assert!(d.pe_ball_strings_peak > 0.0 && d.pe_ball_strings_peak < 1.0);
        // at a node of the beam the linear read is that node's detail
        let e = Detail::lerp(&d, &d, 0.3);
        assert!((e.vibration - d.vibration).abs() < 1e-15 && (e.share(0) - d.share(0)).abs() < 1e-12);
    }

    /// The modal solver's modes give what the explicit solver's spectrum gives, at the Fig 4
    /// impact and along Fig 5(b) (where the second mode takes most, 23.7 cm, and near the tip,
    /// where the fundamental does): each of the first modes' energies, the vibration and the
    /// ball and strings' peak, to 1e-3 of the ball's energy.
    #[test]
    fn the_modal_modes_are_the_explicit_spectrum() {
        for (x, r) in [(0.10, 0.05), (0.2366, 0.0), (0.0182, 0.0)] {
            let mut p = Params::paper();
            p.impact.x = x;
            p.impact.r = r;
            p.strings.ks = 4.0e4;
            let fd = explicit_detail(&p).unwrap();
            p.numerics.solver = SolverKind::Modal;
            let modal = detail(&p).unwrap();
            let close = |a: f64, b: f64| (a - b).abs() < 1e-3;
            assert!(close(fd.vibration, modal.vibration), "x {x}: {fd:?} vs {modal:?}");
            assert!(close(fd.pe_ball_strings_peak, modal.pe_ball_strings_peak), "x {x}: {fd:?} vs {modal:?}");
            for k in 0..KEPT_MODES {
                assert!(close(fd.modes[k], modal.modes[k]), "x {x}, mode {k}: {fd:?} vs {modal:?}");
            }
        }
    }
}
