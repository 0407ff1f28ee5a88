//! The `racket-impact` command-line tool (SPEC.md section 5): parses the command line and
//! dispatches to the command's module in [`cli`].
//!
//! Every error is one line on stderr naming the field and the allowed range, with exit code 2;
//! output files are written only after the computation succeeded, atomically.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cli;

#[derive(Parser, Debug)]
#[command(name = "racket-impact", version, about = "Ball on a flexible tennis racket: R. Cross (2000) replicated")]
struct Cli {
    /// No warnings on stderr (an implausible but valid value still runs, unremarked)
    #[arg(long, global = true)]
    quiet: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// One impact: e_a, tau, theta, energy partition (defaults: the paper's racket, `--load hat`)
    Simulate(cli::simulate::SimulateArgs),
    /// Eigenfrequencies of the free racket and the nodes of its fundamental mode
    Modes(cli::modes::ModesArgs),
    /// Regenerate the paper's experiments: a CSV table and a PNG figure each
    Figures(cli::figures::FiguresArgs),
    /// The paper's numbers beside ours: writes REPORT.md and prints it
    Report(cli::report::ReportArgs),
    /// Fit a racket description (file or preset) to the model and show how well it matches
    Racket(cli::racket::RacketArgs),
    /// Outgoing ball speed for a swing and an incoming ball; compare tensions or rackets
    ///
    /// v_out = e_A v_in + (1 + e_A) v_racket (the paper's frame transformation), with e_A
    /// computed at the relative speed v_in + v_racket and the racket's swing speed taken at the
    /// impact point. Example: racket-impact speed --racket tweener --swing 100 --incoming 60
    /// --compare-tension-lb 50,60
    Speed(cli::speed::SpeedArgs),
    /// Run the cartesian product of ranges or lists of any parameters, in parallel, as CSV
    #[command(long_about = cli::sweep::long_about())]
    Sweep(cli::sweep::SweepArgs),
    /// Map a quantity over the string face: one impact per grid point, as CSV, PNG and JSON
    ///
    /// Runs an impact at every point of an nx x nr grid over the string face (the racket's head
    /// ellipse; for a racket without one, such as the paper's, a 32 cm ellipse from the tip,
    /// 2 half-width wide, centred 16 cm from the tip at the paper's mode-1 node) and writes the table (--out, default
    /// map_<quantity>.csv, or map_<quantity>_diff.csv for a comparison), the heat map (same
    /// stem, .png) and metadata (same stem, .json: the full parameters, the mode-1 node, the
    /// point of maximum e_A). Every parameter flag and --config apply to every point, except the
    /// impact position: --x and --r are rejected (the grid chooses the points), and x and r in
    /// a --config file are ignored. --format selects what is printed: a text summary, the JSON
    /// metadata or the CSV table. Example: racket-impact map --racket tweener --quantity power
    /// --compare-tension-lb 50,60
    Map(cli::map::MapArgs),
    /// An impact's result fields under uncertain inputs, or every paper claim under the declared uncertainty
    #[command(long_about = cli::uncertainty::long_about())]
    Uncertainty(cli::uncertainty::UncertaintyArgs),
}

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
            // clap's message spreads over several lines (the allowed values, usage, a hint):
            // keep what names the field and the allowed values, on one line
            let text = e.render().to_string();
            let parts: Vec<&str> = text
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with("Usage:") && !l.starts_with("For more information"))
                .collect();
            eprintln!("{}", if parts.is_empty() { "error: bad arguments".to_string() } else { parts.join(" ") });
            return ExitCode::from(2);
        }
    };
    cli::common::set_quiet(cli.quiet);
    let outcome = match cli.command {
        Command::Simulate(a) => cli::simulate::run(a),
        Command::Modes(a) => cli::modes::run(a),
        Command::Figures(a) => cli::figures::run(a),
        Command::Report(a) => cli::report::run(a),
        Command::Racket(a) => cli::racket::run(a),
        Command::Speed(a) => cli::speed::run(a),
        Command::Sweep(a) => cli::sweep::run(a),
        Command::Map(a) => cli::map::run(a),
        Command::Uncertainty(a) => cli::uncertainty::run(a),
    };
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
