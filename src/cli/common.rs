//! What the commands share: the parameter arguments, the output format, writing to standard
//! output and the progress bar.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use racket_impact::study::Sources;
use racket_impact::{Error, Result};

use super::overrides::OverrideArgs;

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

/// Write to standard output; a reader that has gone away (broken pipe) ends the program with
/// success, all files having been written before anything is printed.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let mut lock = std::io::stdout().lock();
    match lock.write_all(bytes).and_then(|()| lock.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        other => other.map_err(|e| Error::io("<stdout>", e)),
    }
}

/// Output format.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
    Csv,
}

/// The parameter arguments of the commands that run impacts.
#[derive(Args, Debug)]
pub struct Common {
    /// Racket description file (TOML, player units) or preset name; see `racket-impact racket --list`
    #[arg(long)]
    pub racket: Option<String>,
    /// TOML file with any of the flags below as keys (flags win)
    #[arg(long)]
    pub config: Option<PathBuf>,
    #[command(flatten)]
    pub overrides: OverrideArgs,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

impl Common {
    /// Where the parameters come from.
    pub fn sources(&self) -> Sources {
        Sources { racket: self.racket.clone(), config: self.config.clone(), flags: self.overrides.0.clone() }
    }
}

/// A progress bar on stderr for long runs: hidden, and shown only on a terminal once the run
/// has taken more than a second.
pub struct Progress {
    bar: indicatif::ProgressBar,
    /// When the run started.
    pub started: std::time::Instant,
    terminal: bool,
}

impl Progress {
    pub fn new(total: u64) -> Self {
        use std::io::IsTerminal;
        let bar = indicatif::ProgressBar::hidden();
        bar.set_length(total);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} impacts, {per_sec}, eta {eta}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        Progress { bar, started: std::time::Instant::now(), terminal: std::io::stderr().is_terminal() }
    }

    pub fn update(&self, done: u64) {
        if self.terminal && self.bar.is_hidden() && self.started.elapsed().as_secs_f64() > 1.0 {
            self.bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
        self.bar.set_position(done);
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}
