//! How long a run of many impacts (`map`, `sweep`, `uncertainty`) will take, estimated before
//! it starts from what its impacts will step: a run estimated above [`NOTE_ABOVE_S`] says so,
//! one above [`REFUSE_ABOVE_S`] is refused unless asked for (`--long`).
//!
//! The estimate is a count, not a clock: the explicit solver's expected steps (two rigid-contact
//! half-periods and the window after the impact, two fundamental periods: what [`FdModel`] is
//! bounded by) times what a step costs on the beam's nodes (with the string law and the
//! tangential contact it steps), and the search after a free impact by its worst-case samples
//! ([`ModalModel::free_vibration_work`]); [`MODAL_SECONDS_PER_IMPACT`] and that search for the
//! modal solver, the first alone for the rigid frame. The same command is therefore accepted or
//! refused the same way on every run; the constants were measured on the development machine
//! (2 AMD EPYC cores) and a faster or busier machine takes less or more time than told.

use crate::error::{Error, Result};
use crate::params::{Frame, Params, SolverKind, StringLaw};
use crate::solve::fd::FdModel;
use crate::solve::modal::ModalModel;
use crate::solve::prepared::{PreparedImpact, IMPACT_TIME_LIMIT_HALF_PERIODS};

// The constants below were fitted (least relative error, none negative) to the CPU time of 400
// random impacts on the development machine (2 AMD EPYC cores shared with other work) by
// `benches/estimates.rs impacts`: both solvers, both grips, linear and stiffening strings, normal
// and oblique balls, 10 to 120 segments, rackets of 0.2 to 1000 kg, stiff and soft contacts;
// then raised by [`MARGIN`], so that the estimate bounds the time from above (issue 48: an upper
// bound within a factor of 3 for at least 99 % of random runs; the study's figures are in
// benches/estimates.rs: 98.9 % of the usual set's runs of 0.1 CPU-s or more, 88.9 % of a
// wider set's).

/// The factor the fitted cost is raised by: the 99th percentile of measured over fitted time
/// (1.8 for fd impacts, 2.5 for modal ones; the median 1.0).
pub const MARGIN: f64 = 2.0;
/// CPU seconds of the explicit solver per step of the contact, the nodes apart (the contact law,
/// the ledger, the checks): fitted 37 ns.
pub const FD_SECONDS_PER_STEP: f64 = 3.7e-8 * MARGIN;
/// CPU seconds of the explicit solver per node and step of the contact: fitted 0.87 ns.
pub const FD_SECONDS_PER_NODE_STEP: f64 = 0.87e-9 * MARGIN;
/// CPU seconds a stiffening string law adds to each step of the contact (its deflection solved
/// at every step): fitted 350 ns.
pub const FD_STIFFENING_SECONDS_PER_STEP: f64 = 3.5e-7 * MARGIN;
/// CPU seconds an oblique or spinning ball adds to each step of the contact (the tangential
/// law): fitted 84 ns.
pub const FD_OBLIQUE_SECONDS_PER_STEP: f64 = 8.4e-8 * MARGIN;
/// CPU seconds per node and step of a racket held in the hand after the impact (stepped on for
/// two fundamental periods, its bending energy and the gap to the ball at every step): fitted
/// 9.4 ns.
pub const FD_HELD_SECONDS_PER_NODE_STEP: f64 = 9.4e-9 * MARGIN;
/// CPU seconds of one modal (or rigid-frame) impact with its set-up at least: fitted 29 us.
pub const MODAL_SECONDS_PER_IMPACT: f64 = 2.9e-5 * MARGIN;
/// CPU seconds an oblique or spinning ball adds to a modal impact (the tangential law over the
/// contact): fitted 4.1 ns a step of the explicit solver's, about 30 us.
pub const MODAL_OBLIQUE_SECONDS: f64 = 3.0e-5 * MARGIN;
/// CPU seconds per mode-sample of the free-vibration search after an impact where no mode
/// bounds the peak and the whole window is sampled ([`ModalModel::free_vibration_work`], a few
/// floating-point operations each): fitted 1.8 ns (up to 3.7 ns measured on a busy machine).
pub const SECONDS_PER_MODE_SAMPLE: f64 = 1.8e-9 * MARGIN;
/// The search is whole for an impact shorter than this fraction of the racket's fundamental
/// period (the rigid-contact half-period times f1): a short impact (a stiff contact, a heavy or
/// soft racket) spreads the vibration over many modes, none of which bounds the peak. Above
/// it, the search narrows to windows around the dominant mode's maxima as the square of the
/// ratio, down to [`MODAL_SEARCH_FLOOR`] or [`FD_SEARCH_FLOOR`] of the whole (measured: 1 to 3.7
/// ns a mode-sample below 0.035, 0.1 to 0.7 ns above 0.1).
pub const WHOLE_SEARCH_BELOW: f64 = 0.05;
/// The least share of the whole search the modal solver's takes (its retained modes): fitted
/// 0.056 ns a mode-sample of its worst case.
pub const MODAL_SEARCH_FLOOR: f64 = 0.03;
/// The least share of the whole search the explicit solver's takes (over every mode of its
/// beam, counted by the modal solver's retained ones): fitted 0.24 ns.
pub const FD_SEARCH_FLOOR: f64 = 0.13;

/// The share of its worst case the search after an impact takes, for an impact lasting
/// `tau_f1` of the racket's fundamental period, at least `floor` ([`WHOLE_SEARCH_BELOW`]).
pub fn search_share(tau_f1: f64, floor: f64) -> f64 {
    if tau_f1.is_nan() || tau_f1 <= WHOLE_SEARCH_BELOW {
        return 1.0;
    }
    (WHOLE_SEARCH_BELOW / tau_f1).powi(2).max(floor)
}

/// CPU seconds a run spends once, whatever its impacts: its threads started, the first racket's
/// modes found and its set-up built (fitted to the runs of a few impacts: 1 to 4 ms).
pub const SET_UP_SECONDS: f64 = 1.0e-3 * MARGIN;
/// CPU seconds of the racket's modes per cubed node (a dense eigenproblem), once a run: about
/// 2 ms for 120 segments.
pub const SECONDS_PER_CUBED_NODE: f64 = 1.2e-9 * MARGIN;
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
    let oblique = !p.oblique.is_normal();
    // the search after a free impact, the share of its worst case that the impact's length
    // against the racket's fundamental period tells
    let impact = PreparedImpact::new(p).ok()?;
    let tau_f1 = impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS * impact.f1_hz;
    let search = |mode_samples: f64, floor: f64| mode_samples * SECONDS_PER_MODE_SAMPLE * search_share(tau_f1, floor);
    if p.numerics.solver == SolverKind::Modal {
        let model = ModalModel::new(p).ok()?;
        let mode_samples = model.free_vibration_work();
        let tangential = if oblique { MODAL_OBLIQUE_SECONDS } else { 0.0 };
        return Some(ImpactWork {
            cpu_s: MODAL_SECONDS_PER_IMPACT + tangential + search(mode_samples, MODAL_SEARCH_FLOOR),
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
    // free racket's is told in closed form, the search after the impact)
    let (contact, held) = model.expected_steps();
    let stiffening = p.variants.strings == StringLaw::Stiffening && p.variants.string_stiffening > 0.0;
    let per_step = FD_SECONDS_PER_STEP
        + FD_SECONDS_PER_NODE_STEP * nodes as f64
        + if stiffening { FD_STIFFENING_SECONDS_PER_STEP } else { 0.0 }
        + if oblique { FD_OBLIQUE_SECONDS_PER_STEP } else { 0.0 };
    let mode_samples = if held > 0.0 {
        0.0
    } else {
        let mut modal = *p;
        modal.numerics.solver = SolverKind::Modal;
        ModalModel::new(&modal).map(|m| m.free_vibration_work()).unwrap_or(0.0)
    };
    Some(ImpactWork {
        cpu_s: contact * per_step
            + held * nodes as f64 * FD_HELD_SECONDS_PER_NODE_STEP
            + search(mode_samples, FD_SEARCH_FLOOR),
        fd: Some((contact + held, nodes)),
        mode_samples,
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
    /// last among them), times the count, and the run's set-up once ([`SET_UP_SECONDS`],
    /// [`SECONDS_PER_CUBED_NODE`]). An impact that cannot be prepared counts nothing.
    pub fn of(impacts: u64, threads: usize, params_of: impl Fn(u64) -> Option<Params>) -> Estimate {
        let n = impacts.min(SAMPLED);
        let picks: Vec<u64> = (0..n).map(|k| if n < 2 { 0 } else { k * (impacts - 1) / (n - 1) }).collect();
        let works: Vec<ImpactWork> = picks.iter().filter_map(|&i| params_of(i).as_ref().and_then(impact)).collect();
        let mean = if works.is_empty() { 0.0 } else { works.iter().map(|w| w.cpu_s).sum::<f64>() / works.len() as f64 };
        let heaviest = works.iter().copied().max_by(|a, b| a.cpu_s.total_cmp(&b.cpu_s));
        // (and once, the run's set-up on the largest beam sampled)
        let nodes = picks.iter().filter_map(|&i| params_of(i)).map(|p| p.numerics.segments + 1).max().unwrap_or(0);
        let set_up =
            if works.is_empty() { 0.0 } else { SET_UP_SECONDS + SECONDS_PER_CUBED_NODE * (nodes as f64).powi(3) };
        Estimate { impacts, cpu_s: mean * impacts as f64 + set_up, threads: threads.max(1), heaviest }
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
    fn the_estimate_is_the_expected_steps_times_their_cost_and_the_search() {
        use crate::params::Grip;
        let mut p = Params::paper();
        p.numerics.solver = SolverKind::Fd;
        let model = FdModel::new(&p).unwrap();
        let w = impact(&p).unwrap();
        let nodes = model.beam().nodes();
        let (steps, n) = w.fd.unwrap();
        assert_eq!(n, nodes);
        // a free racket: the contact's steps (about 6k of ~1 us) and the search after it
        let contact = 2.0 * model.impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS / model.dt;
        assert_eq!(steps, contact);
        let mut modal = p;
        modal.numerics.solver = SolverKind::Modal;
        let searched = ModalModel::new(&modal).unwrap().free_vibration_work();
        assert_eq!(w.mode_samples, searched);
        let per_step = FD_SECONDS_PER_STEP + FD_SECONDS_PER_NODE_STEP * nodes as f64;
        let tau_f1 = model.impact.time_limit_s / IMPACT_TIME_LIMIT_HALF_PERIODS * model.impact.f1_hz;
        let share = search_share(tau_f1, FD_SEARCH_FLOOR);
        assert!(share < 0.5, "the paper's impact, 4 ms against a 10 ms period, narrows its search: {share}");
        assert_relative_eq!(
            w.cpu_s,
            contact * per_step + searched * SECONDS_PER_MODE_SAMPLE * share,
            max_relative = 1e-12
        );
        // each step of a stiffening string law and of an oblique ball costs more
        let mut stiff = p;
        stiff.variants.strings = crate::params::StringLaw::Stiffening;
        let mut oblique = p;
        oblique.oblique.angle_deg = 30.0;
        assert!(impact(&stiff).unwrap().cpu_s > w.cpu_s + 0.9 * contact * FD_STIFFENING_SECONDS_PER_STEP);
        assert!(impact(&oblique).unwrap().cpu_s > w.cpu_s);
        // held in the hand, the two fundamental periods after it are stepped too, and not searched
        p.variants.grip = Grip::Hand;
        let held = impact(&p).unwrap();
        let model = FdModel::new(&p).unwrap();
        let after = 2.0 / model.impact.f1_hz / model.dt;
        assert_relative_eq!(held.fd.unwrap().0, contact + after, max_relative = 1e-12);
        assert_eq!(held.mode_samples, 0.0);
        // the modal solver: the least an impact costs and its share of the search's worst case;
        // a very stiff contact (an impact of microseconds), the worst case itself
        let w = impact(&modal).unwrap();
        assert_eq!(w.mode_samples, searched);
        let share = search_share(tau_f1, MODAL_SEARCH_FLOOR);
        assert_relative_eq!(
            w.cpu_s,
            MODAL_SECONDS_PER_IMPACT + searched * SECONDS_PER_MODE_SAMPLE * share,
            max_relative = 1e-12
        );
        modal.ball.k1 = 1e9;
        modal.strings.ks = 1e12;
        let short = impact(&modal).unwrap();
        assert_eq!(short.cpu_s, MODAL_SECONDS_PER_IMPACT + short.mode_samples * SECONDS_PER_MODE_SAMPLE);
        assert_eq!(search_share(0.01, 0.1), 1.0);
        assert_eq!(search_share(0.1, 0.1), 0.25);
        assert_eq!(search_share(1.0, 0.1), 0.1);
    }

    #[test]
    fn a_slow_racket_held_in_the_hand_is_told_and_refused_beyond_the_bound() {
        use crate::params::Grip;
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
