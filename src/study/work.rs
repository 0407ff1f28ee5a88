//! How long a run of many impacts (`map`, `sweep`, `uncertainty`) will take, estimated before
//! it starts from what its impacts will step: a run estimated above [`NOTE_ABOVE_S`] says so,
//! one above [`REFUSE_ABOVE_S`] is refused unless asked for (`--long`).
//!
//! The estimate is a count, not a clock: the explicit solver's expected steps (two rigid-contact
//! half-periods and the window after the impact, two fundamental periods: what
//! [`FdModel`] is bounded by) times the beam's nodes times [`FD_SECONDS_PER_NODE_STEP`], or
//! [`MODAL_SECONDS_PER_IMPACT`] for the modal solver and the rigid frame, whose cost hardly
//! depends on the parameters. The same command is therefore accepted or refused the same way on
//! every run; the constants were measured on the development machine (2 AMD EPYC cores) and a
//! faster or busier machine takes less or more time than told.

use crate::error::{Error, Result};
use crate::params::{Frame, Grip, Params, SolverKind};
use crate::solve::fd::FdModel;
use crate::solve::modal::ModalModel;
use crate::solve::prepared::IMPACT_TIME_LIMIT_HALF_PERIODS;

/// CPU seconds of the explicit solver per node and step of the contact. Measured (user time of
/// `sweep --solver fd --x 0.05:0.25:200`, one thread's share): 0.35 ms an impact of 10.7k steps
/// on 40 nodes, 0.8 ns a node-step, rounded up.
pub const FD_SECONDS_PER_NODE_STEP: f64 = 1.0e-9;
/// CPU seconds per node and step of a racket held in the hand after the impact (stepped on for
/// two fundamental periods, its bending energy and the gap to the ball at every step). Measured:
/// `sweep --grip hand --mass 1e6 --x 0.1,0.2`, 1.77 s an impact of 9.8e6 steps on 40 nodes
/// (4.5 ns), and `sweep --grip hand --x 0.05:0.25:100`, 3.5 ms an impact (15k steps after it:
/// 5.2 ns).
pub const FD_HELD_SECONDS_PER_NODE_STEP: f64 = 5.0e-9;
/// CPU seconds of one modal (or rigid-frame) impact with its set-up at least: `sweep --solver
/// modal --x 0.05:0.25:20000` takes 17.5 us an impact.
pub const MODAL_SECONDS_PER_IMPACT: f64 = 20.0e-6;
/// CPU seconds per mode-sample of the modal solver's free-vibration search at its worst case (a
/// few floating-point operations each). Measured: `sweep --solver modal --v1 1e-3 --k1 1e9 --ks
/// 1e12 --segments 400 --x 0.05:0.25:8`, every mode of a stiff contact kept, 0.30 s an impact of
/// 1.8e8 mode-samples (1.6 ns); an impact whose search is short costs [`MODAL_SECONDS_PER_IMPACT`].
pub const SECONDS_PER_MODE_SAMPLE: f64 = 1.6e-9;
/// A run estimated above this many seconds (wall clock, on every core) says so before it starts.
pub const NOTE_ABOVE_S: f64 = 60.0;
/// A run estimated above this many seconds (wall clock, on every core: ten minutes) is refused
/// unless asked for (`--long`).
pub const REFUSE_ABOVE_S: f64 = 600.0;
/// Impacts whose cost is worked out (evenly spread over the run) to estimate the rest.
pub const SAMPLED: u64 = 16;

/// The work of one impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactWork {
    /// CPU seconds.
    pub cpu_s: f64,
    /// The explicit solver's expected steps and the beam's nodes (none for the modal solver).
    pub fd: Option<(f64, usize)>,
    /// The modal solver's free-vibration search after the impact, its worst case in
    /// mode-samples ([`ModalModel::free_vibration_work`]; 0 for the explicit solver).
    pub mode_samples: f64,
    /// The racket's fundamental frequency, Hz (the window after the impact is two periods).
    pub f1_hz: f64,
}

/// The work of one impact on parameters `p`, with the solver they name; `None` where the
/// impact cannot be prepared (the run itself then says why).
pub fn impact(p: &Params) -> Option<ImpactWork> {
    if p.variants.frame == Frame::Rigid {
        return Some(ImpactWork { cpu_s: MODAL_SECONDS_PER_IMPACT, fd: None, mode_samples: 0.0, f1_hz: f64::NAN });
    }
    if p.numerics.solver == SolverKind::Modal {
        let model = ModalModel::new(p).ok()?;
        let mode_samples = model.free_vibration_work();
        return Some(ImpactWork {
            cpu_s: MODAL_SECONDS_PER_IMPACT.max(mode_samples * SECONDS_PER_MODE_SAMPLE),
            fd: None,
            mode_samples,
            f1_hz: model.f1_hz(),
        });
    }
    let model = FdModel::new(p).ok()?;
    let nodes = model.beam().nodes();
    let f1_hz = model.impact.f1_hz;
    // the contact (two rigid-contact half-periods, as the solver's own bound counts it), and for
    // a racket held in the hand the window after it, two fundamental periods, stepped too (a
    // free racket's is told in closed form)
    let contact = 2.0 * model.impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS / model.dt;
    let held = if p.variants.grip == Grip::Hand { 2.0 / f1_hz / model.dt } else { 0.0 };
    let steps = contact + held;
    Some(ImpactWork {
        cpu_s: (contact * FD_SECONDS_PER_NODE_STEP + held * FD_HELD_SECONDS_PER_NODE_STEP) * nodes as f64,
        fd: Some((steps, nodes)),
        mode_samples: 0.0,
        f1_hz,
    })
}

/// The estimated work of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Impacts in the run.
    pub impacts: u64,
    /// CPU seconds in all.
    pub cpu_s: f64,
    /// Threads the impacts run on.
    pub threads: usize,
    /// The costliest impact sampled.
    pub heaviest: Option<ImpactWork>,
}

impl Estimate {
    /// The work of `impacts` impacts on `threads` threads, impact `i` on the parameters
    /// `params_of(i)`: the mean cost of [`SAMPLED`] of them, evenly spread (the first and the
    /// last among them), times the count. An impact that cannot be prepared counts nothing.
    pub fn of(impacts: u64, threads: usize, params_of: impl Fn(u64) -> Option<Params>) -> Estimate {
        let n = impacts.min(SAMPLED);
        let picks: Vec<u64> = (0..n).map(|k| if n < 2 { 0 } else { k * (impacts - 1) / (n - 1) }).collect();
        let works: Vec<ImpactWork> = picks.iter().filter_map(|&i| params_of(i).as_ref().and_then(impact)).collect();
        let mean = if works.is_empty() { 0.0 } else { works.iter().map(|w| w.cpu_s).sum::<f64>() / works.len() as f64 };
        let heaviest = works.iter().copied().max_by(|a, b| a.cpu_s.total_cmp(&b.cpu_s));
        Estimate { impacts, cpu_s: mean * impacts as f64, threads: threads.max(1), heaviest }
    }

    /// Wall-clock seconds on every thread.
    pub fn wall_s(&self) -> f64 {
        self.cpu_s / self.threads as f64
    }

    /// The estimate in words: "about 27 min (625 impacts, about 5.2 s each on one core, on 2
    /// cores; the explicit solver: 9.3e6 steps an impact on 40 nodes, ...)".
    pub fn words(&self) -> String {
        let per = self.cpu_s / self.impacts.max(1) as f64;
        let mut why = String::new();
        match self.heaviest {
            Some(ImpactWork { fd: Some((steps, nodes)), f1_hz, .. }) => {
                why = format!("; the explicit solver, up to {steps:.2e} steps an impact on {nodes} nodes");
                // the window after the impact (two fundamental periods) dominates a slow racket's run
                if f1_hz.is_finite() && f1_hz > 0.0 && f1_hz < 20.0 {
                    why += &format!(
                        ", most of them the {} after the impact a racket held in the hand is followed for (two \
                         periods of its fundamental, f1 = {} Hz)",
                        duration(2.0 / f1_hz),
                        crate::numfmt::sig(f1_hz, 3)
                    );
                }
            }
            Some(ImpactWork { fd: None, mode_samples, .. })
                if mode_samples * SECONDS_PER_MODE_SAMPLE > MODAL_SECONDS_PER_IMPACT =>
            {
                why = format!(
                    "; the modal solver, up to {mode_samples:.2e} mode-samples an impact in the search for the peak \
                     vibration after it (two fundamental periods sampled at the fastest mode kept)"
                );
            }
            _ => {}
        }
        format!(
            "about {} ({} impacts, about {} each on one core, on {} cores{why})",
            duration(self.wall_s()),
            self.impacts,
            duration(per),
            self.threads
        )
    }

    /// Refuse a run above [`REFUSE_ABOVE_S`] unless `long`, as an invalid `value` of `field` (what
    /// sizes the run: `samples = 1024`); a note for one above [`NOTE_ABOVE_S`], and for any run
    /// when `long` (asked for a long run, the user is told how long).
    pub fn check(&self, field: &'static str, value: impl std::fmt::Display, long: bool) -> Result<Option<String>> {
        let wall = self.wall_s();
        if wall > REFUSE_ABOVE_S && !long {
            return Err(Error::invalid(
                field,
                value,
                format!(
                    "the run is estimated at {}, above the {} a run may take unless --long is given: give --long \
                     to run it anyway, or fewer impacts",
                    self.words(),
                    duration(REFUSE_ABOVE_S)
                ),
            ));
        }
        // (a long run asked for is always told how long)
        Ok((wall > NOTE_ABOVE_S || long).then(|| format!("this run is estimated at {}", self.words())))
    }
}

pub use crate::numfmt::duration;

/// The CPU time every live thread of this process has used so far, s (Linux: the sum of each
/// thread's time on a CPU, `/proc/self/task/*/schedstat`, in nanoseconds); `None` elsewhere.
/// What the estimates are held against: a busy machine stretches the wall clock, not this.
pub fn process_cpu_s() -> Option<f64> {
    let mut ns: u64 = 0;
    for task in std::fs::read_dir("/proc/self/task").ok()?.flatten() {
        // (a thread that has just ended is skipped)
        let Ok(text) = std::fs::read_to_string(task.path().join("schedstat")) else { continue };
        ns += text.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(ns as f64 * 1e-9)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn the_estimate_is_the_expected_steps_times_the_nodes() {
        let mut p = Params::paper();
        p.numerics.solver = SolverKind::Fd;
        let model = FdModel::new(&p).unwrap();
        let w = impact(&p).unwrap();
        let nodes = model.beam().nodes();
        let (steps, n) = w.fd.unwrap();
        assert_eq!(n, nodes);
        assert_eq!(w.cpu_s, steps * FD_SECONDS_PER_NODE_STEP * nodes as f64);
        // a free racket: the contact's steps only (about 6k of ~1 us); held in the hand, the two
        // fundamental periods after it too
        let contact = 2.0 * model.impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS / model.dt;
        assert_eq!(steps, contact);
        p.variants.grip = Grip::Hand;
        let held = impact(&p).unwrap().fd.unwrap().0;
        let model = FdModel::new(&p).unwrap();
        let after = 2.0 / model.impact.f1_hz / model.dt;
        assert_relative_eq!(held, contact + after, max_relative = 1e-12);
        // the modal solver: the search after the impact at its worst, or the least an impact costs
        p.variants.grip = Grip::Free;
        p.numerics.solver = SolverKind::Modal;
        let w = impact(&p).unwrap();
        let searched = ModalModel::new(&p).unwrap().free_vibration_work();
        assert_eq!(w.mode_samples, searched);
        assert_eq!(w.cpu_s, MODAL_SECONDS_PER_IMPACT.max(searched * SECONDS_PER_MODE_SAMPLE));
    }

    #[test]
    fn a_slow_racket_held_in_the_hand_is_told_and_refused_beyond_the_bound() {
        // the case of issue 40: a 1e6 kg racket in the hand rings at 0.07 Hz, and the held
        // racket is stepped on for two of its periods after the impact, 27 s, millions of steps
        let mut p = Params::paper();
        p.racket.mass = 1.0e6;
        p.variants.grip = Grip::Hand;
        let one = Estimate::of(1, 1, |_| Some(p));
        let (steps, _) = one.heaviest.unwrap().fd.unwrap();
        assert!(steps > 5.0e6, "{steps}");
        assert!(one.words().contains("most of them the 28 s after the impact a racket held in the hand is followed for (two periods of its fundamental, f1 = 0.0727 Hz)"), "{}", one.words());
        let many = Estimate::of(1000, 2, |_| Some(p));
        let e = many.check("samples", 333, false).unwrap_err().to_string();
        assert!(e.starts_with("invalid samples = 333: the run is estimated at about "), "{e}");
        assert!(e.contains("give --long"), "{e}");
        assert!(many.check("samples", 333, true).unwrap().unwrap().starts_with("this run is estimated at about "));
        // the paper's racket, modal: a thousand impacts say nothing
        let mut modal = Params::paper();
        modal.numerics.solver = SolverKind::Modal;
        assert_eq!(Estimate::of(1000, 2, |_| Some(modal)).check("samples", 333, false).unwrap(), None);
    }

    #[test]
    fn durations_read_as_words() {
        assert_eq!(duration(0.05), "0.05 s");
        assert_eq!(duration(42.0), "42 s");
        assert_eq!(duration(1620.0), "27 min");
        assert_eq!(duration(11_000.0), "3.1 h");
    }
}
