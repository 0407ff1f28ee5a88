//! A running command's control ([`Control`]): the one interface through which a command tells
//! its progress and learns that it is to stop, whichever front end runs it.
//!
//! - The command (its request, [`crate::command`]) says what it counts ([`Control::begin`]) and
//!   how far it is ([`Control::set_done`]); every impact run on a thread the control is
//!   installed on ([`Control::within`], carried into parallel tasks by [`within`]) counts
//!   itself, in millionths of an impact, from inside the solvers' stepping loops ([`poll`]), so
//!   progress moves during a long impact too.
//! - A front end polls it: [`Control::status`] for its progress bar (with a rate a person reads,
//!   [`Status::words`]), [`Control::take_notes`] for what is to be told as the run goes (the
//!   estimate, a run outliving three times its estimate); [`Control::cancel`] to stop the run.
//! - The solvers call [`poll`] every few thousand steps: once the control is cancelled the
//!   impact ends with [`Error::Cancelled`]. The hook reads a flag and adds to a counter, so a
//!   result is the same bit for bit with or without it.
//!
//! It sits at the bottom of the house (it imports only the error type and the number words):
//! the solvers below the commands call it without knowing of them.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use crate::error::{Error, Result};
use crate::numfmt::{duration, sig};

/// An impact counted whole, in [`Status::position`]'s millionths.
const MICRO: u64 = 1_000_000;

/// A run that has taken this many times its estimate says so, once, as it goes (once it has
/// run [`OVERRUN_AFTER_S`]).
pub const OVERRUN_FACTOR: f64 = 3.0;

/// A run shorter than this is not told to have outlived its estimate: nobody waits for it.
pub const OVERRUN_AFTER_S: f64 = 10.0;

/// What a run counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unit {
    /// Impacts: each counts itself from inside the solver, in flight too.
    Impacts,
    /// Items the command counts itself ([`Control::set_done`]), named (`experiments`).
    Named(&'static str),
}

impl Unit {
    /// The unit's name, plural (`impacts`).
    pub fn name(self) -> &'static str {
        match self {
            Unit::Impacts => "impacts",
            Unit::Named(n) => n,
        }
    }
}

/// The part of a control behind its lock: what is read rarely.
#[derive(Debug)]
struct Told {
    unit: Unit,
    started: Instant,
    /// The run's estimated wall-clock time, s.
    expected_s: Option<f64>,
    /// Notes not yet taken by the front end.
    notes: Vec<String>,
    /// Whether the overrun has been told.
    overrun_told: bool,
}

#[derive(Debug)]
struct Inner {
    cancelled: AtomicBool,
    /// Impacts done, in millionths, with the parts of those in flight.
    micro: AtomicU64,
    /// Items done as the command counts them.
    done: AtomicU64,
    /// Items in the run.
    total: AtomicU64,
    told: Mutex<Told>,
}

/// A running command's control: a cancel flag, the progress counters and the notes told as the
/// run goes. A clone is the same run.
#[derive(Debug, Clone)]
pub struct Control(Arc<Inner>);

impl Default for Control {
    fn default() -> Self {
        Control::new()
    }
}

impl Control {
    /// A control for a new run, counting nothing yet.
    pub fn new() -> Control {
        Control(Arc::new(Inner {
            cancelled: AtomicBool::new(false),
            micro: AtomicU64::new(0),
            done: AtomicU64::new(0),
            total: AtomicU64::new(0),
            told: Mutex::new(Told {
                unit: Unit::Impacts,
                started: Instant::now(),
                expected_s: None,
                notes: Vec::new(),
                overrun_told: false,
            }),
        }))
    }

    fn told(&self) -> std::sync::MutexGuard<'_, Told> {
        self.0.told.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Stop the run: every impact in flight ends at its next [`poll`], and the command with
    /// [`Error::Cancelled`].
    pub fn cancel(&self) {
        self.0.cancelled.store(true, Ordering::SeqCst);
    }

    /// Whether the run has been cancelled.
    pub fn is_cancelled(&self) -> bool {
        self.0.cancelled.load(Ordering::Relaxed)
    }

    /// [`Error::Cancelled`] once the run has been cancelled.
    pub fn check(&self) -> Result<()> {
        if self.is_cancelled() {
            Err(Error::Cancelled)
        } else {
            Ok(())
        }
    }

    /// The run counts `total` items of `unit`; its clock starts now.
    pub fn begin(&self, total: u64, unit: Unit) {
        self.0.total.store(total, Ordering::Relaxed);
        self.0.done.store(0, Ordering::Relaxed);
        self.0.micro.store(0, Ordering::Relaxed);
        let mut told = self.told();
        told.unit = unit;
        told.started = Instant::now();
    }

    /// `done` items are done (whole ones; for [`Unit::Impacts`] the impacts count themselves
    /// too, and the larger count is shown).
    pub fn set_done(&self, done: u64) {
        self.0.done.fetch_max(done, Ordering::Relaxed);
    }

    /// The run is estimated at `wall_s` seconds: the remaining time is told by it until the run
    /// has gone far enough to tell by its own rate, and a run past [`OVERRUN_FACTOR`] times it
    /// says so.
    pub fn expect(&self, wall_s: f64) {
        self.told().expected_s = (wall_s.is_finite() && wall_s > 0.0).then_some(wall_s);
    }

    /// A note for the user, told as the run goes (the front end takes it: [`Control::take_notes`]).
    pub fn tell(&self, note: impl Into<String>) {
        self.told().notes.push(note.into());
    }

    /// The notes told since the last call, in order.
    pub fn take_notes(&self) -> Vec<String> {
        std::mem::take(&mut self.told().notes)
    }

    /// Where the run is; a run past [`OVERRUN_FACTOR`] times its estimate (and
    /// [`OVERRUN_AFTER_S`]) tells so, once.
    pub fn status(&self) -> Status {
        let total = self.0.total.load(Ordering::Relaxed);
        let done = self.0.done.load(Ordering::Relaxed) as f64;
        let mut told = self.told();
        let position = match told.unit {
            Unit::Impacts => done.max(self.0.micro.load(Ordering::Relaxed) as f64 / MICRO as f64),
            Unit::Named(_) => done,
        };
        let status = Status {
            position: position.min(total as f64),
            total,
            unit: told.unit,
            elapsed_s: told.started.elapsed().as_secs_f64(),
            expected_s: told.expected_s,
        };
        if let Some(expected) = status.expected_s {
            let over = status.elapsed_s > (OVERRUN_FACTOR * expected).max(OVERRUN_AFTER_S);
            if !told.overrun_told && over && status.fraction() < 1.0 {
                told.overrun_told = true;
                told.notes.push(format!(
                    "this run has taken {}, more than {} times its estimate of {} ({} done): the estimate \
                     is wrong for these inputs; the run goes on",
                    duration(status.elapsed_s),
                    OVERRUN_FACTOR,
                    duration(expected),
                    status.done_words()
                ));
            }
        }
        status
    }

    /// Run `f` with this control installed on the current thread: the impacts it runs count
    /// themselves here and stop once it is cancelled. Parallel work inside `f` carries the
    /// control into its tasks with [`current`] and [`within`].
    pub fn within<T>(&self, f: impl FnOnce() -> T) -> T {
        within(Some(self), f)
    }
}

/// Where a run is, for a progress bar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Status {
    /// Items done, with the parts of the impacts in flight.
    pub position: f64,
    /// Items in the run (0: not yet told).
    pub total: u64,
    /// What is counted.
    pub unit: Unit,
    /// Seconds since the run began.
    pub elapsed_s: f64,
    /// The run's estimate, s (wall clock).
    pub expected_s: Option<f64>,
}

impl Status {
    /// The part done, 0..=1 (0 before the total is told).
    pub fn fraction(&self) -> f64 {
        if self.total == 0 {
            0.0
        } else {
            (self.position / self.total as f64).clamp(0.0, 1.0)
        }
    }

    /// Seconds left: by the run's own rate once a twentieth is done (or ten seconds have
    /// passed with some progress), else by the estimate less the time taken; `None` when
    /// neither tells.
    pub fn remaining_s(&self) -> Option<f64> {
        let f = self.fraction();
        if f >= 1.0 {
            return Some(0.0);
        }
        if f > 0.0 && (f >= 0.05 || self.elapsed_s >= 10.0) {
            return Some(self.elapsed_s * (1.0 - f) / f);
        }
        self.expected_s.map(|e| (e - self.elapsed_s).max(0.0))
    }

    /// The rate in words a person reads: `120 impacts/s`, `2.5 impacts/s`, `4.1 s an impact`
    /// (three significant digits at most, no thousands of a count); `None` before any progress.
    pub fn rate_words(&self) -> Option<String> {
        if self.position <= 0.0 || self.elapsed_s <= 0.0 {
            return None;
        }
        let rate = self.position / self.elapsed_s;
        let unit = self.unit.name();
        Some(if rate >= 1.0 {
            format!("{} {unit}/s", if rate >= 100.0 { format!("{rate:.0}") } else { sig(rate, 2) })
        } else {
            format!("{} s per {}", sig(1.0 / rate, 2), singular(unit))
        })
    }

    /// `3.4 of 8 impacts` (whole items once past ten, or where none is in flight).
    pub fn done_words(&self) -> String {
        let shown = if self.total > 10 || self.position.fract() == 0.0 {
            format!("{}", self.position.floor())
        } else {
            format!("{:.1}", self.position)
        };
        format!("{shown} of {} {}", self.total, self.unit.name())
    }

    /// The status in words: `3.4 of 8 impacts, 2.1 s per impact, about 12 s left`.
    pub fn words(&self) -> String {
        let mut out = self.done_words();
        if let Some(rate) = self.rate_words() {
            out += &format!(", {rate}");
        }
        if let Some(left) = self.remaining_s() {
            out += &format!(", about {} left", duration(left));
        }
        out
    }
}

/// `impacts` -> `impact`.
fn singular(unit: &str) -> &str {
    unit.strip_suffix('s').unwrap_or(unit)
}

/// The control installed on this thread and what the impact in flight has counted so far.
struct Watching {
    control: Control,
    /// Millionths of an impact the impact in flight has added.
    counted: u64,
}

thread_local! {
    static CURRENT: RefCell<Option<Watching>> = const { RefCell::new(None) };
}

/// The control installed on this thread, to carry into parallel tasks ([`within`]).
pub fn current() -> Option<Control> {
    CURRENT.with(|c| c.borrow().as_ref().map(|w| w.control.clone()))
}

/// Run `f` with `control` (or none) installed on this thread, then put back what was there
/// (also if `f` panics).
pub fn within<T>(control: Option<&Control>, f: impl FnOnce() -> T) -> T {
    struct Restore(Option<Watching>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let old = self.0.take();
            CURRENT.with(|c| *c.borrow_mut() = old);
        }
    }
    let new = control.map(|c| Watching { control: c.clone(), counted: 0 });
    let _restore = Restore(CURRENT.with(|c| std::mem::replace(&mut *c.borrow_mut(), new)));
    f()
}

/// The solvers' hook, called every few thousand steps of an impact with the part of the
/// impact done (`fraction`, 0..1, an estimate): [`Error::Cancelled`] once the control installed
/// on this thread is cancelled; otherwise the impact's progress is counted. Without a control,
/// nothing.
pub fn poll(fraction: f64) -> Result<()> {
    CURRENT.with(|c| {
        let mut c = c.borrow_mut();
        let Some(w) = c.as_mut() else { return Ok(()) };
        if w.control.is_cancelled() {
            return Err(Error::Cancelled);
        }
        // (never a whole impact: that is counted when it ends, [`impact_done`])
        let at = (fraction.clamp(0.0, 0.999) * MICRO as f64) as u64;
        if at > w.counted {
            w.control.0.micro.fetch_add(at - w.counted, Ordering::Relaxed);
            w.counted = at;
        }
        Ok(())
    })
}

/// Whether the control installed on this thread is cancelled (for a search that cannot return
/// an error: it ends early, and its solver's next [`poll`] ends the impact).
pub fn cancelled() -> bool {
    CURRENT.with(|c| c.borrow().as_ref().is_some_and(|w| w.control.is_cancelled()))
}

/// An impact begins on this thread (what an earlier one left uncounted is dropped).
pub fn impact_begins() {
    CURRENT.with(|c| {
        if let Some(w) = c.borrow_mut().as_mut() {
            w.counted = 0;
        }
    });
}

/// The impact on this thread has ended (done or failed): it counts whole.
pub fn impact_done() {
    CURRENT.with(|c| {
        if let Some(w) = c.borrow_mut().as_mut() {
            w.control.0.micro.fetch_add(MICRO - w.counted.min(MICRO), Ordering::Relaxed);
            w.counted = 0;
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn impacts_count_themselves_in_flight_and_whole() {
        let ctl = Control::new();
        ctl.begin(4, Unit::Impacts);
        ctl.within(|| {
            impact_begins();
            poll(0.25).unwrap();
            poll(0.2).unwrap(); // (never backwards)
            assert_eq!(ctl.status().position, 0.25);
            impact_done();
            assert_eq!(ctl.status().position, 1.0);
            impact_begins();
            poll(0.5).unwrap();
        });
        assert_eq!(ctl.status().position, 1.5);
        assert_eq!(ctl.status().done_words(), "1.5 of 4 impacts");
        // outside, nothing is counted
        poll(0.9).unwrap();
        impact_done();
        assert_eq!(ctl.status().position, 1.5);
        ctl.set_done(3);
        assert_eq!(ctl.status().position, 3.0);
    }

    #[test]
    fn a_cancelled_control_stops_the_impact_at_its_next_poll_on_every_thread_it_is_carried_to() {
        let ctl = Control::new();
        let seen = ctl.within(|| {
            let carried = current();
            std::thread::scope(|s| {
                s.spawn(|| {
                    within(carried.as_ref(), || {
                        assert!(poll(0.1).is_ok());
                        ctl.cancel();
                        assert!(cancelled());
                        poll(0.2)
                    })
                })
                .join()
                .unwrap()
            })
        });
        assert!(matches!(seen, Err(Error::Cancelled)));
        assert!(current().is_none(), "put back");
        assert!(!cancelled());
    }

    #[test]
    fn the_rate_reads_as_words_and_an_overrun_is_told_once() {
        let s = Status { position: 44808.221, total: 100_000, unit: Unit::Impacts, elapsed_s: 1.0, expected_s: None };
        assert_eq!(s.rate_words().unwrap(), "44808 impacts/s");
        let s = Status { position: 2.5, total: 8, unit: Unit::Impacts, elapsed_s: 1.0, expected_s: Some(2.0) };
        assert_eq!(s.words(), "2.5 of 8 impacts, 2.5 impacts/s, about 2 s left");
        let s = Status { position: 0.3, total: 8, unit: Unit::Impacts, elapsed_s: 1.0, expected_s: Some(30.0) };
        assert_eq!(s.words(), "0.3 of 8 impacts, 3.3 s per impact, about 29 s left");
        let ctl = Control::new();
        ctl.begin(8, Unit::Named("experiments"));
        ctl.expect(1.0);
        // (a run begun 20 s ago, of an estimated second: past three times it and ten seconds)
        let long_ago = Instant::now().checked_sub(std::time::Duration::from_secs(20));
        ctl.told().started = long_ago.unwrap_or_else(Instant::now);
        ctl.status();
        ctl.status();
        let notes = ctl.take_notes();
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].starts_with(
                "this run has taken 20 s, more than 3 times its estimate of 1 s (0 of 8 experiments done)"
            ),
            "{}",
            notes[0]
        );
        // a short run is not told: nobody waits for it
        let short = Control::new();
        short.begin(8, Unit::Impacts);
        short.expect(1e-9);
        std::thread::sleep(std::time::Duration::from_millis(2));
        short.status();
        assert!(short.take_notes().is_empty());
    }
}
