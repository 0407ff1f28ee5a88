//! What the commands share: the parameter arguments, the output format, writing to standard
//! output and the progress bar.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use racket_impact::diagnostic::Diagnostic;
use racket_impact::intake::Sources;
use racket_impact::{Error, Result};

use super::overrides::{KeySet, OverrideArgs};

/// `print!` for the commands: a closed pipe (`racket-impact ... | head`) ends the program quietly,
/// as a shell tool should, instead of panicking; other write errors are errors.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::cli::common::write_stdout(format!($($arg)*).as_bytes())?
    };
}

/// `println!` for the commands, as [`out!`].
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::cli::common::write_stdout(format!("{}\n", format_args!($($arg)*)).as_bytes())?
    };
}

pub(crate) use {out, outln};

/// Write to standard output. A reader that has gone away (broken pipe, `| head`) is not an
/// error: the rest of the output is dropped quietly and the command goes on to publish its
/// files. Any other write error (a full disk, `> /dev/full`) is an error, and the command's
/// staged files are then not published.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let mut lock = std::io::stdout().lock();
    match lock.write_all(bytes).and_then(|()| lock.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other.map_err(|e| Error::io("<stdout>", e)),
    }
}

/// Check, before any work, that standard output can be written: an empty write, which writes
/// nothing and fails where every write would (`> /dev/full`: no space left), so that a command
/// whose result cannot be printed fails at once instead of after its work. A reader that has
/// gone away is not an error (as in [`write_stdout`]).
pub fn check_stdout() -> Result<()> {
    #[cfg(unix)]
    {
        use std::io::Write;
        use std::os::fd::AsFd;
        let probe = std::io::stdout().as_fd().try_clone_to_owned().map(std::fs::File::from);
        // (`write`, not `write_all`: an empty `write_all` never calls the system)
        match probe.and_then(|mut f| f.write(&[])) {
            Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => return Err(Error::io("<stdout>", e)),
            _ => {}
        }
    }
    Ok(())
}

/// [`write_stdout`] for a stream that only goes to standard output (`sweep` without `--out`):
/// a reader that has gone away ends the program with success, as a shell tool should, instead
/// of computing what nobody reads.
pub fn stream_stdout(bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let mut lock = std::io::stdout().lock();
    match lock.write_all(bytes).and_then(|()| lock.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        other => other.map_err(|e| Error::io("<stdout>", e)),
    }
}

/// One line on stderr. A stderr that cannot be written (`2> /dev/full`, a closed pipe) is
/// not an error of the command (nothing is left to report it on), and never the panic of
/// `eprintln!`: the command's result and exit code stand. The last guard of every message: a
/// control character in it is escaped (a raw NUL or line break from the user's input never
/// reaches the terminal) and the line is cut at [`STDERR_LINE_CHARS`], saying how much was cut
/// (each quoted value is capped where it is quoted, `numfmt::quoted`; this catches the rest).
pub fn stderr_line(line: &str) {
    use std::io::Write;
    let line = racket_impact::numfmt::quoted_up_to(line, STDERR_LINE_CHARS);
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}

/// The longest line [`stderr_line`] prints, in characters: several times the longest message
/// the commands write (a work estimate with its reasons, about 500).
pub const STDERR_LINE_CHARS: usize = 4000;

/// Set by the global `--quiet`: no warnings.
static QUIET: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Silence the warnings (`--quiet`).
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, std::sync::atomic::Ordering::Relaxed);
}

/// One `warning:` line on stderr, unless `--quiet`. Warnings never change a result or the exit
/// code.
pub fn warn(message: &str) {
    if !QUIET.load(std::sync::atomic::Ordering::Relaxed) {
        stderr_line(&format!("warning: {message}"));
    }
}

/// How long a run took, one line on stderr (`map: 861 impacts in 3.2 s`), unless `--quiet`: not
/// on standard output, which the same command twice prints the same.
pub fn elapsed_line(message: &str) {
    if !QUIET.load(std::sync::atomic::Ordering::Relaxed) {
        stderr_line(message);
    }
}

/// Print each diagnostic as one `warning:` line, unless `--quiet` (the only place the library's
/// diagnostics are printed).
pub fn print_diagnostics<'a>(diagnostics: impl IntoIterator<Item = &'a Diagnostic>) {
    for d in diagnostics {
        warn(&d.sentence);
    }
}

/// The diagnostics as the JSON outputs carry them, under the key `diagnostics`.
pub fn diagnostics_json(diagnostics: &[Diagnostic]) -> Result<serde_json::Value> {
    serde_json::to_value(diagnostics).map_err(|e| Error::io("<json>", e))
}

/// Output format.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
    Csv,
}

/// The parameter arguments of the commands that run impacts: the parameter flags the command
/// takes ([`KeySet`]).
#[derive(Args, Debug)]
pub struct Common<K: KeySet> {
    /// TOML file with any of the parameter flags below as keys (flags win; a key this command
    /// does not use is named in one warning)
    #[arg(long, help_heading = "Impact")]
    pub config: Option<PathBuf>,
    /// Racket description file (TOML, player units) or preset name; see `racket-impact racket --list`
    #[arg(long, help_heading = "Racket")]
    pub racket: Option<String>,
    #[command(flatten)]
    pub overrides: OverrideArgs<K>,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text, help_heading = "Output")]
    pub format: Format,
}

impl<K: KeySet> Common<K> {
    /// Where the parameters come from.
    pub fn sources(&self) -> Sources {
        Sources {
            racket: self.racket.clone(),
            config: self.config.clone(),
            flags: self.overrides.0.clone(),
            command: K::COMMAND,
            not_taken: K::not_taken(),
            set_by_options: Vec::new(),
        }
    }
}

/// A progress bar (or spinner) on stderr for long runs: drawn only on a terminal, without
/// `--quiet`, and only once the run has taken more than [`Progress::DELAY`] (a short run prints
/// nothing); it ticks on its own, so the elapsed time moves during a long step, and it is cleared
/// when dropped.
pub struct Progress {
    bar: indicatif::ProgressBar,
    /// Dropped to tell the watcher the run is over.
    stop: Option<std::sync::mpsc::Sender<()>>,
    /// Shows the bar once [`Progress::DELAY`] has passed.
    watcher: Option<std::thread::JoinHandle<()>>,
}

impl Progress {
    /// How long a run goes before its progress is drawn.
    pub const DELAY: std::time::Duration = std::time::Duration::from_secs(1);

    /// A bar over `total` steps named `unit` (`experiments`), each named as it starts
    /// ([`Progress::at`]), with the time elapsed.
    pub fn steps(total: u64, unit: &str) -> Self {
        Self::start(total, &format!("{{bar:30}} {{pos}}/{{len}} {unit}: {{msg}} ({{elapsed}})"))
    }

    /// A spinner for one long step told in `message`, with the time elapsed.
    pub fn spinner(message: &str) -> Self {
        let p = Self::start(0, "{spinner} {msg} ({elapsed})");
        p.bar.set_message(message.to_string());
        p
    }

    fn start(total: u64, template: &str) -> Self {
        use std::io::IsTerminal;
        let bar = indicatif::ProgressBar::with_draw_target(Some(total), indicatif::ProgressDrawTarget::hidden());
        bar.set_style(
            indicatif::ProgressStyle::with_template(template)
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        if !std::io::stderr().is_terminal() || QUIET.load(std::sync::atomic::Ordering::Relaxed) {
            return Progress { bar, stop: None, watcher: None };
        }
        let (stop, stopped) = std::sync::mpsc::channel::<()>();
        let shown = bar.clone();
        let watcher = std::thread::spawn(move || {
            if let Err(std::sync::mpsc::RecvTimeoutError::Timeout) = stopped.recv_timeout(Self::DELAY) {
                shown.set_draw_target(indicatif::ProgressDrawTarget::stderr());
                shown.enable_steady_tick(std::time::Duration::from_millis(200));
            }
        });
        Progress { bar, stop: Some(stop), watcher: Some(watcher) }
    }

    /// Step `done` (0-based) of the total is `name`.
    pub fn at(&self, done: u64, name: &str) {
        self.bar.set_position(done);
        self.bar.set_message(name.to_string());
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        drop(self.stop.take());
        if let Some(w) = self.watcher.take() {
            let _ = w.join();
        }
        self.bar.finish_and_clear();
    }
}

/// A run's progress and notes on stderr, read from its [`Control`] by a thread of its own every
/// [`Reporter::EVERY`]: each note (the estimate before the work, a run outliving three times its
/// estimate) as one `warning:` line as it comes, unless `--quiet`; the bar, with the position
/// (the impacts in flight counted in part), a rate a person reads and the time left, only on a
/// terminal, without `--quiet`, and once the run has taken [`Progress::DELAY`]. On drop, the
/// notes left are told and the bar is cleared.
///
/// [`Control`]: racket_impact::command::Control
pub struct Reporter {
    /// Dropped to tell the watcher the run is over.
    stop: Option<std::sync::mpsc::Sender<()>>,
    watcher: Option<std::thread::JoinHandle<()>>,
}

impl Reporter {
    /// How often the control is read.
    pub const EVERY: std::time::Duration = std::time::Duration::from_millis(100);

    /// Report the run `ctl` controls.
    pub fn start(ctl: &racket_impact::command::Control) -> Reporter {
        use std::io::IsTerminal;
        let ctl = ctl.clone();
        let quiet = QUIET.load(std::sync::atomic::Ordering::Relaxed);
        let drawn = std::io::stderr().is_terminal() && !quiet;
        let (stop, stopped) = std::sync::mpsc::channel::<()>();
        let watcher = std::thread::spawn(move || {
            let started = std::time::Instant::now();
            let bar = indicatif::ProgressBar::with_draw_target(Some(0), indicatif::ProgressDrawTarget::hidden());
            bar.set_style(
                indicatif::ProgressStyle::with_template("{bar:40} {msg}")
                    .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
            );
            let (mut shown, mut over) = (false, false);
            loop {
                let status = ctl.status();
                let notes = ctl.take_notes();
                if !notes.is_empty() {
                    bar.suspend(|| notes.iter().for_each(|n| warn(n)));
                }
                if over {
                    break;
                }
                if drawn && !shown && started.elapsed() >= Progress::DELAY {
                    bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
                    shown = true;
                }
                if shown {
                    bar.set_length(status.total.max(1) * 1000);
                    bar.set_position((status.position * 1000.0) as u64);
                    bar.set_message(status.words());
                }
                over = !matches!(stopped.recv_timeout(Self::EVERY), Err(std::sync::mpsc::RecvTimeoutError::Timeout));
            }
            bar.finish_and_clear();
        });
        Reporter { stop: Some(stop), watcher: Some(watcher) }
    }
}

impl Drop for Reporter {
    fn drop(&mut self) {
        drop(self.stop.take());
        if let Some(w) = self.watcher.take() {
            let _ = w.join();
        }
    }
}
