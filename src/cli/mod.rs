//! The command-line layer: one module per command, each with its clap arguments and a thin
//! `run` that calls the library and prints; [`common`] holds what they share and
//! [`overrides`] the parameter flags built from the parameter declarations. [`Cli`] is the
//! whole command line (its clap `Command` is what the option tests walk).

use clap::{Parser, Subcommand};

pub mod cache;
pub mod calibrate;
pub mod card;
pub mod common;
pub mod figures;
pub mod hints;
pub mod map;
pub mod modes;
pub mod options;
pub mod overrides;
pub mod racket;
pub mod report;
pub mod simulate;
pub mod speed;
pub mod sweep;
pub mod uncertainty;

#[derive(Parser, Debug)]
#[command(
    name = "racket-impact",
    version,
    // help wrapped to the terminal, and to 100 columns at most (or where it is not a terminal)
    max_term_width = 100,
    about = "Ball on a flexible tennis racket: R. Cross (2000) replicated",
    after_help = "Start here: racket-impact simulate (one ball on the paper's racket at the centre of its strings: e_A, contact time, twist, where the energy went)\n\
                  Examples:\n  \
                  racket-impact simulate --x 0.1 --ks 3e4\n  \
                  racket-impact simulate --racket tweener --angle-deg 30 --spin-rpm 2000\n  \
                  racket-impact map --racket tweener --quantity power\n  \
                  racket-impact speed --racket tweener --swing 100 --incoming 60 --compare-tension-lb 50,60\n\
                  Each command's --help groups its options (impact, racket, ball, strings, oblique impact, numerics, output)."
)]
pub struct Cli {
    /// No warnings on stderr (an implausible but valid value still runs, unremarked)
    #[arg(long, global = true)]
    pub quiet: bool,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// One impact: e_a, tau, theta, energy partition (defaults: the paper's racket, `--load hat`)
    #[command(long_about = examples(
        "One impact: e_a, tau, theta, energy partition (defaults: the paper's racket, `--load hat`)",
        &[
            "racket-impact simulate --x 0.10 --r 0.05 --ks 4e4 --load node",
            "racket-impact simulate --racket tweener --angle-deg 30 --spin-rpm 2000 --format json",
            "racket-impact simulate --grip hand --series series.csv",
        ],
    ))]
    Simulate(simulate::SimulateArgs),
    /// Eigenfrequencies of the free racket and the nodes of its fundamental mode
    #[command(long_about = examples(
        "Eigenfrequencies of the free racket and the nodes of its fundamental mode",
        &["racket-impact modes", "racket-impact modes --racket tweener --count 6 --format json"],
    ))]
    Modes(modes::ModesArgs),
    /// Regenerate the paper's experiments: a CSV table and a PNG figure each
    #[command(long_about = examples(
        "Regenerate the paper's experiments: a CSV table and a PNG figure each",
        &[
            "racket-impact figures",
            "racket-impact figures --list",
            "racket-impact figures --only fig4_energy --out my-figures",
            "racket-impact figures --racket tweener",
        ],
    ))]
    Figures(figures::FiguresArgs),
    /// The paper's numbers beside ours: writes REPORT.md and prints it
    #[command(long_about = examples(
        "The paper's numbers beside ours: writes REPORT.md and prints it",
        &["racket-impact report --summary", "racket-impact report --no-write"],
    ))]
    Report(report::ReportArgs),
    /// Fit a racket description (file or preset) to the model and show how well it matches
    ///
    /// Example: racket-impact racket examples/my-racket.toml
    ///
    /// A racket file is TOML in player units (README "Your own racket";
    /// examples/my-racket.toml is one to start from).
    ///
    /// Keys: name; length_in or length_cm; mass_g (strung, required); balance_cm or
    /// balance_pts_hl (head-light points), with swingweight_kg_cm2 (about 10 cm from the butt),
    /// or neither (a uniform beam); twistweight_kg_cm2 (required); frequency_hz or ei_n_m2;
    /// stiffness_ratio (relative EI at tip, head end, handle start, butt).
    ///
    /// More keys: head_length_cm with head_width_cm, or head_size_sq_in with head_aspect;
    /// handle_length_cm; one of tension_lb, tension_kg, string_bed_n_per_m, dt_kp_cm; mu; string
    /// (a name from data/strings); and a [ball] table with mass_g, k1_n_per_m, p.
    Racket(racket::RacketArgs),
    /// Outgoing ball speed for a swing and an incoming ball; compare tensions or rackets
    ///
    /// Example: racket-impact speed --racket tweener --swing 100 --incoming 60
    /// --compare-tension-lb 50,60
    ///
    /// v_out = e_A v_in + (1 + e_A) v_racket (the paper's frame transformation), with e_A
    /// computed at the relative speed v_in + v_racket and the racket's swing speed taken at the
    /// impact point.
    ///
    /// Output: text and CSV give each variant's speeds with e_A, tau and theta (a deliberate
    /// subset); --format json gives every result field of each impact, as simulate's JSON does.
    ///
    /// Launch angle: taken with the face as it was at first contact. An off-axis impact (--r)
    /// twists the face by theta (shown, and warned of beyond the small-angle range), which the
    /// launch direction does not include, so +r and -r launch alike.
    ///
    /// At stroke speeds the paper's soft ball (k1 = 3e4 N/m) compresses by more than its radius
    /// (y0 about 40 mm at 160 km/h; see simulate's y0): the speeds follow the paper's model
    /// extrapolated.
    Speed(speed::SpeedArgs),
    /// Run the cartesian product of ranges or lists of any parameters, in parallel, as CSV
    #[command(long_about = sweep::long_about())]
    Sweep(sweep::SweepArgs),
    /// Map a quantity over the string face: one impact per grid point, as CSV, PNG and JSON
    ///
    /// Example: racket-impact map --racket tweener --quantity power --compare-tension-lb 50,60
    ///
    /// Runs an impact at every point of an nx x nr grid over the string face: the racket's head
    /// ellipse; for a racket without one, such as the paper's, a 32 cm ellipse from the tip, 2
    /// half-width wide, centred 16 cm from the tip at the paper's mode-1 node.
    ///
    /// Files: the table (--out, default map_<quantity>.csv, or map_<quantity>_diff.csv for a
    /// comparison), the heat map (same stem, .png) and metadata (same stem, .json: the full
    /// parameters, the mode-1 node, the point of maximum e_A).
    ///
    /// Every parameter flag and --config apply to every point. The impact point, the solver and
    /// its step are not options: the grid chooses the points, and a map runs the modal solver
    /// wherever the model variants allow it, else fd with its automatic step (a --config file's
    /// x, r, solver and dt are named as unused).
    ///
    /// --format selects what is printed: a text summary, the JSON metadata or the CSV table (the
    /// map quantities at every point, a deliberate subset of the result fields: simulate --x X
    /// --r R gives all of one point).
    Map(map::MapArgs),
    /// An impact's result fields under uncertain inputs, or every paper claim under declared uncertainty
    #[command(long_about = uncertainty::long_about(), after_long_help = uncertainty::declared_help())]
    Uncertainty(uncertainty::UncertaintyArgs),
    /// What string tension does to one racket: power, sweet spot, control, comfort, spin (a PNG, a CSV)
    ///
    /// Example: racket-impact card --racket tweener --string alu-power-16
    ///
    /// For a racket (preset, file or flags), a string (--string, data/strings) and a range of
    /// tensions (--tensions-lb, default 45:65:9 lb), five panels against the tension, each
    /// computed as the command that computes it alone: speed's conversions for the ball speeds,
    /// map for the sweet spot, simulate for the twist, vibration and contact time, speed's stroke
    /// for the spin.
    ///
    /// Each panel's assumptions are in the CSV's header block (# lines) and under the panel in
    /// the PNG; the spin panel says what its law was validated on and what not. --compare draws a
    /// second racket beside the first (dashed). On the paper's racket the card sets the paper's
    /// own conclusions beside the model's.
    ///
    /// Files: --out (default card.csv) and the PNG next to it (same stem). The card sets the
    /// impact points, ball speeds, incidence and k_s itself: --x, --r, --v1, --angle-deg,
    /// --azimuth-deg, --spin-rpm and --ks are not its flags.
    Card(card::CardArgs),
    /// Fit parameters with a declared range to measured rows: intervals, correlation, held-out error
    #[command(long_about = calibrate::long_about(), after_long_help = calibrate::fittable_help())]
    Calibrate(calibrate::CalibrateArgs),
}

/// A command's long help: its one line, then its examples, one a line (a doc comment would join
/// them into one paragraph).
pub fn examples(about: &str, lines: &[&str]) -> String {
    format!("{about}\n\nExamples:\n  {}", lines.join("\n  "))
}

/// Run one command.
pub fn run(command: Command) -> racket_impact::Result<()> {
    match command {
        Command::Simulate(a) => simulate::run(a),
        Command::Modes(a) => modes::run(a),
        Command::Figures(a) => figures::run(a),
        Command::Report(a) => report::run(a),
        Command::Racket(a) => racket::run(a),
        Command::Speed(a) => speed::run(a),
        Command::Sweep(a) => sweep::run(a),
        Command::Map(a) => map::run(a),
        Command::Uncertainty(a) => uncertainty::run(a),
        Command::Calibrate(a) => calibrate::run(a),
        Command::Card(a) => card::run(a),
    }
}
