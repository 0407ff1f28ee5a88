//! The `racket-impact` command-line tool (SPEC.md section 5): parses the command line and
//! dispatches to the command's module in [`cli`].
//!
//! Every error is one line on stderr naming the field and the allowed range, with exit code 2;
//! output files are written only after the computation succeeded, atomically.

use std::process::ExitCode;

use clap::Parser;

mod cli;

use cli::Cli;

fn main() -> ExitCode {
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
        Err(e) => {
            cli::common::stderr_line(&format!("error: {e}"));
            ExitCode::from(2)
        }
    }
}
