//! The commands as requests, beneath both front ends (the command line and the Python
//! package): each command is a [`Request`] built from its inputs (where the parameters come
//! from, [`Sources`](crate::intake::Sources), and its own options, [`Given`]), which gives its
//! work estimate before the work ([`Request::work`]) and runs with one [`Control`] for its
//! progress and its cancellation, returning its result with its diagnostics. The front ends
//! only parse, present and map errors; [`execute`] applies the one rule of long runs.
//!
//! A new command goes in a file of its own here: its request type with a constructor from its
//! inputs, its options declared once ([`Request::OPTIONS`], from which the command line makes
//! its flags and Python its keywords) and a line in [`ALL`].

pub mod calibrate;
pub mod card;
pub mod map;
pub mod modes;
pub mod options;
pub mod simulate;
pub mod speed;
pub mod sweep;
pub mod uncertainty;

pub use crate::control::{Control, Status, Unit};
pub use options::{Given, Kind, Many, Opt, LONG};

use crate::error::{Error, Result};
use crate::numfmt::duration;
use crate::study::work::{Estimate, NOTE_ABOVE_S, REFUSE_ABOVE_S};

/// A command of the library.
pub trait Request: Sized {
    /// The command, as the command line names it (`sweep`).
    const NAME: &'static str;
    /// Its own options, declared once (the parameters are declared apart, `params::keys`).
    const OPTIONS: &'static [Opt];
    /// What it returns: its result with its diagnostics.
    type Output;

    /// Its work, estimated before it starts on `threads` threads; `None` for a command that
    /// takes a moment (one impact, the modes of a racket).
    fn work(&self, threads: usize) -> Option<Work>;

    /// Run it: its progress told to `ctl` ([`Control::begin`], [`Control::set_done`]; impacts
    /// count themselves), stopped with [`Error::Cancelled`] once `ctl` is cancelled.
    fn run(self, ctl: &Control) -> Result<Self::Output>;
}

/// The work of a run, and how it is to be told.
#[derive(Debug, Clone)]
pub struct Work {
    /// The estimate.
    pub estimate: Estimate,
    /// What the user asked for, opening a refusal: `the default 256 samples (768 impacts)`.
    pub asked: String,
    /// What would make the run shorter: `fewer samples`.
    pub fewer: &'static str,
    /// Whether a long run was asked for ([`LONG`]).
    pub long: bool,
}

impl Work {
    /// Refuse the run above [`REFUSE_ABOVE_S`] unless it was asked for as long
    /// ([`Error::TooLong`]); the note told before a run above [`NOTE_ABOVE_S`], or any run asked
    /// for as long.
    pub fn check(&self) -> Result<Option<String>> {
        let wall = self.estimate.wall_s();
        if wall > REFUSE_ABOVE_S && !self.long {
            return Err(Error::TooLong {
                asked: self.asked.clone(),
                estimate: self.estimate.words(),
                limit: duration(REFUSE_ABOVE_S),
                fewer: self.fewer.to_string(),
            });
        }
        Ok((wall > NOTE_ABOVE_S || self.long).then(|| format!("this run is estimated at {}", self.estimate.words())))
    }
}

/// Threads a run's parallel work uses.
pub fn threads() -> usize {
    rayon::current_num_threads()
}

/// Run `request` under `ctl`: its work checked first (refused above ten minutes unless asked
/// for as long; told above a minute, [`Control::tell`]; the estimate given to `ctl` for the time
/// left and the overrun), then run with `ctl` installed, so that every impact it runs counts
/// itself and stops once `ctl` is cancelled.
pub fn execute<R: Request>(request: R, ctl: &Control) -> Result<R::Output> {
    ctl.check()?;
    if let Some(work) = request.work(threads()) {
        if let Some(note) = work.check()? {
            ctl.tell(note);
        }
        ctl.expect(work.estimate.wall_s());
    }
    ctl.within(|| request.run(ctl))
}

/// A command's options by its name, for a front end that lists them (the Python package).
pub struct Described {
    /// The command.
    pub name: &'static str,
    /// Its options (with [`LONG`] where its work is estimated).
    pub options: &'static [Opt],
    /// Why it does not take the parameter `key` (it sets it itself, or its result does not
    /// depend on it), where it does not: the parameters of a command.
    pub not_taken: fn(&str) -> Option<&'static str>,
}

/// Every parameter is taken.
fn every(_key: &str) -> Option<&'static str> {
    None
}

/// Every command on the layer, with its options.
pub const ALL: &[Described] = &[
    Described { name: simulate::NAME, options: simulate::OPTIONS, not_taken: every },
    Described { name: sweep::NAME, options: sweep::OPTIONS, not_taken: every },
    Described { name: map::NAME, options: map::OPTIONS, not_taken: crate::study::map::set_by_map },
    Described { name: uncertainty::NAME, options: uncertainty::OPTIONS, not_taken: every },
    Described { name: speed::NAME, options: speed::OPTIONS, not_taken: crate::study::speed::set_by_speed },
    Described { name: modes::NAME, options: modes::OPTIONS, not_taken: modes::not_taken },
    Described { name: calibrate::NAME, options: calibrate::OPTIONS, not_taken: every },
    Described { name: card::NAME, options: card::OPTIONS, not_taken: crate::study::card::set_by_card },
];

/// The options of the command `name`.
pub fn options_of(name: &str) -> Option<&'static [Opt]> {
    ALL.iter().find(|d| d.name == name).map(|d| d.options)
}

/// The command `name` as [`ALL`] describes it.
pub fn described(name: &str) -> Option<&'static Described> {
    ALL.iter().find(|d| d.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{Grip, Params, SolverKind};

    /// A racket of 1e6 kg held in the hand: about 2 s of stepping after the impact (issue 47).
    fn held_heavy() -> Params {
        let mut p = Params::paper();
        p.racket.mass = 1.0e6;
        p.variants.grip = Grip::Hand;
        p
    }

    #[test]
    fn a_watched_impact_is_the_same_bit_for_bit() {
        let mut cases = vec![Params::paper()];
        let mut modal = Params::paper();
        modal.numerics.solver = SolverKind::Modal;
        cases.push(modal);
        let mut held = Params::paper();
        held.variants.grip = Grip::Hand;
        cases.push(held);
        let mut oblique = Params::paper();
        oblique.oblique.angle_deg = 30.0;
        cases.push(oblique);
        for p in cases {
            let plain = crate::solve::simulate(&p).unwrap();
            let ctl = Control::new();
            ctl.begin(1, Unit::Impacts);
            let watched = ctl.within(|| crate::solve::simulate(&p)).unwrap();
            assert_eq!(format!("{plain:?}"), format!("{watched:?}"));
            assert_eq!(ctl.status().position, 1.0, "the impact counted itself whole");
        }
    }

    #[test]
    fn cancelling_stops_a_long_impact_from_inside_and_its_progress_moved_before() {
        let ctl = Control::new();
        ctl.begin(1, Unit::Impacts);
        let p = held_heavy();
        let watcher = ctl.clone();
        let (outcome, seen) = std::thread::scope(|s| {
            let run = s.spawn(|| ctl.within(|| crate::solve::simulate(&p)));
            // the impact tells its progress from inside; once a hundredth is told, stop it
            while watcher.status().position < 0.01 {
                std::thread::yield_now();
            }
            let seen = watcher.status().position;
            watcher.cancel();
            (run.join().unwrap(), seen)
        });
        assert!(matches!(outcome, Err(crate::Error::Cancelled)), "{outcome:?}");
        assert!(seen < 0.5, "stopped well inside the impact: {seen}");
    }

    #[test]
    fn a_cancelled_sweep_stops_with_nothing_more_sunk() {
        let pairs: Vec<String> = ["--grip", "hand", "--mass", "1e6", "--x", "0.1,0.12,0.14,0.16,0.18,0.2"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let mut given = Given::new(sweep::OPTIONS);
        given.set("long", "true").unwrap();
        let request = sweep::SweepRequest::new(None, None, &pairs, &given).unwrap();
        let ctl = Control::new();
        let mut sunk = 0;
        let outcome = std::thread::scope(|s| {
            let watcher = ctl.clone();
            s.spawn(move || {
                while watcher.status().position < 0.05 {
                    std::thread::yield_now();
                }
                watcher.cancel();
            });
            execute(
                request.stream(
                    |cells| cells.len(),
                    |rows: &[usize]| {
                        sunk += rows.len();
                        Ok(())
                    },
                ),
                &ctl,
            )
            .map(|_| ())
        });
        assert!(outcome.as_ref().is_err_and(crate::Error::is_cancelled), "{outcome:?}");
        assert_eq!(sunk, 0);
        assert!(ctl.status().position < 6.0);
    }

    #[test]
    fn a_run_above_ten_minutes_is_refused_with_what_was_asked_unless_long() {
        let pairs: Vec<String> =
            ["--grip", "hand", "--mass", "1e6", "--x", "0.05:0.25:2000"].iter().map(|s| s.to_string()).collect();
        let request = sweep::SweepRequest::new(None, None, &pairs, &Given::new(sweep::OPTIONS)).unwrap();
        let ctl = Control::new();
        let e = execute(request.stream(|c| c.len(), |_: &[usize]| Ok(())), &ctl).map(|_| ()).unwrap_err().to_string();
        assert!(e.starts_with("a sweep of 2000 impacts: the run is estimated at about "), "{e}");
        assert!(e.ends_with("give --long to run it anyway, or fewer impacts"), "{e}");
        assert!(ctl.take_notes().is_empty());
    }
}
