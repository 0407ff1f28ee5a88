//! The `racket-impact` command-line tool (SPEC.md section 5): parses the command line and
//! dispatches to the command's module in [`cli`].
//!
//! Every error is one line on stderr naming the field and the allowed range, with exit code 2;
//! output files are written only after the computation succeeded, atomically.

use std::process::ExitCode;

use clap::Parser;

mod cli;

use cli::Cli;

/// On SIGINT, SIGTERM or SIGHUP: remove every temporary file the command has staged (a half
/// written `sweep --out big.csv` is a hidden `.big.csv.tmp.*` beside it) and exit with the
/// conventional status, 128 + the signal (130, 143, 129). The handler runs on its own thread
/// (signal-hook's iterator), so the removal is ordinary code, not async-signal-safe code; a set
/// of outputs being renamed into place is finished first ([`racket_impact::render::temps`]).
#[cfg(unix)]
fn remove_staged_on_interrupt() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    match signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
        Ok(mut signals) => {
            std::thread::spawn(move || {
                if let Some(signal) = signals.forever().next() {
                    racket_impact::render::temps::remove_staged();
                    std::process::exit(128 + signal);
                }
            });
        }
        Err(e) => cli::common::stderr_line(&format!(
            "warning: cannot handle interrupts ({e}): an interrupted run may leave temporary files"
        )),
    }
}

#[cfg(not(unix))]
fn remove_staged_on_interrupt() {}

fn main() -> ExitCode {
    remove_staged_on_interrupt();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                // (a closed pipe, as in `--help | head`, is not an error)
                let _ = std::io::Write::write_all(&mut std::io::stdout(), e.to_string().as_bytes());
                return ExitCode::SUCCESS;
            }
            if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                // no command at all (`racket-impact`): the help as clap lays it out, on stderr
                let _ = e.print();
                return ExitCode::from(2);
            }
            // an unknown flag: where its concept lives, or clap's suggestion only if it is near
            let args: Vec<String> = std::env::args().collect();
            let names: Vec<String> =
                <Cli as clap::CommandFactory>::command().get_subcommands().map(|c| c.get_name().to_string()).collect();
            let names: Vec<&str> = names.iter().map(String::as_str).collect();
            if let Some(line) = cli::hints::unknown_flag(&e, &cli::hints::command_of(&args, &names)) {
                cli::common::stderr_line(&line);
                return ExitCode::from(2);
            }
            // clap's message spreads over several lines (the allowed values, usage, a hint):
            // keep what names the field and the allowed values, on one line
            let text = e.render().to_string();
            let parts: Vec<&str> = text
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with("Usage:") && !l.starts_with("For more information"))
                .collect();
            cli::common::stderr_line(&if parts.is_empty() {
                "error: bad arguments".to_string()
            } else {
                parts.join(" ")
            });
            return ExitCode::from(2);
        }
    };
    cli::common::set_quiet(cli.quiet);
    let outcome = cli::run(cli.command);
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(_) if racket_impact::render::temps::interrupted() => loop {
            // the interrupt's handler exits with the signal's status (130, 143, 129) once it has
            // cleaned up; an error its clean-up caused here is not the run's
            std::thread::park();
        },
        Err(e) => {
            cli::common::stderr_line(&format!("error: {e}"));
            ExitCode::from(2)
        }
    }
}
