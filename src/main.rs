//! The `racket-impact` command-line tool (SPEC.md section 5).
//!
//! Every error is one line on stderr naming the field and the allowed range, with exit code 2;
//! output files are written only after the computation succeeded, atomically.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use racket_impact::map::Quantity;
use racket_impact::model::beam::Beam;
use racket_impact::params::{Overrides, Params};
use racket_impact::racket::Fitted;
use racket_impact::solve::{Model, SeriesOptions};
use racket_impact::{Error, Result};

/// `print!` for the commands: a closed pipe (`racket-impact ... | head`) ends the program quietly,
/// as a shell tool should, instead of panicking; other write errors are errors.
macro_rules! out {
    ($($arg:tt)*) => {
        write_stdout(format!($($arg)*).as_bytes())?
    };
}

/// `println!` for the commands, as [`out!`].
macro_rules! outln {
    ($($arg:tt)*) => {
        write_stdout(format!("{}\n", format_args!($($arg)*)).as_bytes())?
    };
}

/// Write to standard output; a reader that has gone away (broken pipe) ends the program with
/// success, all files having been written before anything is printed.
fn write_stdout(bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let mut lock = std::io::stdout().lock();
    match lock.write_all(bytes).and_then(|()| lock.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        other => other.map_err(|e| Error::io("<stdout>", e)),
    }
}

#[derive(Parser, Debug)]
#[command(name = "racket-impact", version, about = "Ball on a flexible tennis racket: R. Cross (2000) replicated")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// One impact: e_a, tau, theta, energy partition (defaults: the paper's racket, `--load hat`)
    Simulate(SimulateArgs),
    /// Eigenfrequencies of the free racket and the nodes of its fundamental mode
    Modes(ModesArgs),
    /// Regenerate the paper's experiments: a CSV table and a PNG figure each
    Figures(FiguresArgs),
    /// The paper's numbers beside ours: writes REPORT.md and prints it
    Report(ReportArgs),
    /// Fit a racket description (file or preset) to the model and show how well it matches
    Racket(RacketArgs),
    /// Outgoing ball speed for a swing and an incoming ball; compare tensions or rackets
    ///
    /// v_out = e_A v_in + (1 + e_A) v_racket (the paper's frame transformation), with e_A
    /// computed at the relative speed v_in + v_racket and the racket's swing speed taken at the
    /// impact point. Example: racket-impact speed --racket tweener --swing 100 --incoming 60
    /// --compare-tension-lb 50,60
    Speed(SpeedArgs),
    /// Run the cartesian product of ranges or lists of any parameters, in parallel, as CSV
    ///
    /// After the options, give any parameter as `--KEY SPEC`, where SPEC is a value (0.1), a
    /// list (2e4,4e4 or node,hat), a range start:stop:count or a log range start:stop:count:log.
    /// Keys: x r ks ei mass length ix half-width mb k1 p v1 segments load dt solver frame grip strings
    /// string-stiffening stiffening-deflection hand-stiffness hand-damping grip-length. Options
    /// (--out, --config, --racket) go before the pairs. Sweeps use the modal solver (~30x faster,
    /// within 2e-5 of fd) unless --solver is given or a hand grip or stiffening strings need fd;
    /// the last CSV column names the solver.
    /// Example: racket-impact sweep --out s.csv --x 0.02:0.60:50 --ks 2e4,4e4 --load node
    Sweep(SweepArgs),
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
    Map(MapArgs),
}

#[derive(Args, Debug)]
struct MapArgs {
    #[command(flatten)]
    common: Common,
    /// The quantity shown in the heat map (the CSV has every one)
    #[arg(long, value_enum, default_value_t = Quantity::Power)]
    quantity: Quantity,
    /// Grid points along the racket, from the tip to the end of the face (2..=401)
    #[arg(long, default_value_t = 41, allow_hyphen_values = true)]
    nx: usize,
    /// Grid points across the face, from -half-width to +half-width (2..=401)
    #[arg(long, default_value_t = 21, allow_hyphen_values = true)]
    nr: usize,
    /// Output CSV; the PNG and JSON go next to it with the same stem
    #[arg(long)]
    out: Option<PathBuf>,
    /// Difference map against this racket (file or preset): B - A with A = --racket
    #[arg(long, conflicts_with = "compare_tension_lb")]
    compare_racket: Option<String>,
    /// Difference map between string tensions, lb: T (A = the configuration as given, B = at T)
    /// or T1,T2 (A at T1, B at T2); k_s = 4e4 N/m * T / 60 lb
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    compare_tension_lb: Vec<f64>,
}

#[derive(Args, Debug)]
struct SweepArgs {
    /// Racket description file (TOML, player units) or preset name; see `racket-impact racket --list`
    #[arg(long)]
    racket: Option<String>,
    /// TOML file with fixed values for any parameter (as for `simulate`)
    #[arg(long)]
    config: Option<PathBuf>,
    /// Output CSV file (written atomically); standard output if absent
    #[arg(long)]
    out: Option<PathBuf>,
    /// The varied parameters: --KEY SPEC pairs
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, value_name = "--KEY SPEC")]
    specs: Vec<String>,
}

#[derive(Args, Debug)]
struct FiguresArgs {
    /// Only this experiment (repeatable); see --list
    #[arg(long = "only", value_name = "ID")]
    only: Vec<String>,
    /// Output directory (created if missing); default figures/, or figures/racket-NAME with --racket
    #[arg(long)]
    out: Option<PathBuf>,
    /// Run the experiments on this racket (file or preset) instead of the paper's; the impacts
    /// stay where the paper puts them, along the whole length
    #[arg(long)]
    racket: Option<String>,
    /// List the experiment ids with their titles and paper references, and exit
    #[arg(long)]
    list: bool,
}

#[derive(Args, Debug)]
struct ReportArgs {
    /// Where to write the Markdown report
    #[arg(long, default_value = "REPORT.md")]
    out: PathBuf,
    /// Print the report without writing the file
    #[arg(long)]
    no_write: bool,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Text,
    Json,
    Csv,
}

#[derive(Args, Debug)]
struct RacketArgs {
    /// Racket description file (TOML, player units) or preset name
    racket: Option<String>,
    /// List the presets and exit
    #[arg(long)]
    list: bool,
    /// Number of beam segments the fit is made for (4..=400)
    #[arg(long, default_value_t = 39)]
    segments: usize,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum SpeedUnit {
    /// kilometres per hour
    Kmh,
    /// miles per hour
    Mph,
    /// metres per second
    Ms,
}

impl SpeedUnit {
    /// Metres per second per unit.
    fn si(self) -> f64 {
        match self {
            SpeedUnit::Kmh => 1.0 / 3.6,
            SpeedUnit::Mph => 0.44704,
            SpeedUnit::Ms => 1.0,
        }
    }
    fn label(self) -> &'static str {
        match self {
            SpeedUnit::Kmh => "km/h",
            SpeedUnit::Mph => "mph",
            SpeedUnit::Ms => "m/s",
        }
    }
}

#[derive(Args, Debug)]
struct SpeedArgs {
    #[command(flatten)]
    common: Common,
    /// Racket speed at the impact point, towards the ball (in --unit)
    #[arg(long, allow_hyphen_values = true)]
    swing: f64,
    /// Incoming ball speed, towards the racket (in --unit); 0 for a serve
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    incoming: f64,
    /// Unit of the speeds
    #[arg(long, value_enum, default_value_t = SpeedUnit::Kmh)]
    unit: SpeedUnit,
    /// Compare these string tensions, lb (e.g. 50,60); the first is the reference
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    compare_tension_lb: Vec<f64>,
    /// Compare these rackets (files or presets, e.g. light,players); the first is the reference
    #[arg(long, value_delimiter = ',')]
    compare_racket: Vec<String>,
}

#[derive(Args, Debug)]
struct Common {
    /// Racket description file (TOML, player units) or preset name; see `racket-impact racket --list`
    #[arg(long)]
    racket: Option<String>,
    /// TOML file with any of the flags below as keys (flags win)
    #[arg(long)]
    config: Option<PathBuf>,
    #[command(flatten)]
    overrides: Overrides,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Args, Debug)]
struct SimulateArgs {
    #[command(flatten)]
    common: Common,
    /// Also write the impact's time series (t, F, y_b, Y_T, theta, every energy term) as CSV
    #[arg(long)]
    series: Option<PathBuf>,
    /// Sample spacing of the time series, s
    #[arg(long, default_value_t = 2.0e-5, allow_hyphen_values = true)]
    series_dt: f64,
    /// Extend the time series to at least this time, s
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    series_end: f64,
}

#[derive(Args, Debug)]
struct ModesArgs {
    #[command(flatten)]
    common: Common,
    /// Number of flexible modes to list (1..=20, at most N-1)
    #[arg(long, default_value_t = 4, allow_hyphen_values = true)]
    count: usize,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                print!("{e}");
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
    let outcome = match cli.command {
        Command::Simulate(a) => simulate(a),
        Command::Modes(a) => modes(a),
        Command::Figures(a) => figures(a),
        Command::Report(a) => report(a),
        Command::Racket(a) => racket_cmd(a),
        Command::Speed(a) => speed(a),
        Command::Sweep(a) => sweep(a),
        Command::Map(a) => map(a),
    };
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Paper defaults (with the user default `hat` load) < racket file < config file < flags,
/// validated.
fn params_from(common: &Common) -> Result<Params> {
    resolve(common.racket.as_deref(), common).map(|(p, _)| p)
}

/// As [`params_from`] with the racket given separately, also returning the fit.
fn resolve(racket: Option<&str>, common: &Common) -> Result<(Params, Option<Fitted>)> {
    let config = config_file(common.config.as_deref())?;
    let spec = racket.map(racket_impact::racket::load).transpose()?;
    racket_impact::racket::resolve(spec.as_ref(), &common.overrides.clone().or(config))
}

/// The overrides of a `--config` file, or none.
fn config_file(path: Option<&std::path::Path>) -> Result<Overrides> {
    path.map_or_else(|| Ok(Overrides::default()), Overrides::from_toml_file)
}

/// A progress bar on stderr for long runs: hidden, and shown only on a terminal once the run
/// has taken more than a second.
struct Progress {
    bar: indicatif::ProgressBar,
    started: std::time::Instant,
    terminal: bool,
}

impl Progress {
    fn new(total: u64) -> Self {
        use std::io::IsTerminal;
        let bar = indicatif::ProgressBar::hidden();
        bar.set_length(total);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} impacts, {per_sec}, eta {eta}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        Progress { bar, started: std::time::Instant::now(), terminal: std::io::stderr().is_terminal() }
    }

    fn update(&self, done: u64) {
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

/// The comparison options of `speed` and `map`: tensions or rackets, not both; each tension in
/// range.
fn check_comparison(tensions_lb: &[f64], rackets_given: bool) -> Result<()> {
    if !tensions_lb.is_empty() && rackets_given {
        return Err(Error::invalid(
            "compare-tension-lb",
            "(with --compare-racket)",
            "compare either tensions or rackets, not both",
        ));
    }
    match tensions_lb.iter().find(|t| !(t.is_finite() && **t > 0.0 && **t <= 200.0)) {
        Some(t) => Err(Error::invalid("compare-tension-lb", t, "tension must satisfy 0 < T <= 200 lb")),
        None => Ok(()),
    }
}

/// Fail early, before any computation, when an output file's directory does not exist.
fn simulate(a: SimulateArgs) -> Result<()> {
    let params = params_from(&a.common)?;
    if let Some(path) = &a.series {
        racket_impact::render::io::check_output_dir("series", path)?;
    }
    if !(a.series_dt.is_finite() && a.series_dt > 0.0) {
        return Err(Error::invalid("series-dt", a.series_dt, "sample spacing must be a finite number > 0 s"));
    }
    if !(a.series_end.is_finite() && (0.0..=10.0).contains(&a.series_end)) {
        return Err(Error::invalid("series-end", a.series_end, "must satisfy 0 <= series-end <= 10 s"));
    }
    let (result, series) = if let Some(path) = &a.series {
        if params.numerics.solver != racket_impact::params::SolverKind::Fd {
            return Err(Error::invalid("series", path.display(), "a time series needs --solver fd"));
        }
        let model = Model::new(&params)?;
        let (r, s) = model.run_with_series(SeriesOptions { sample_dt: a.series_dt, t_end: a.series_end })?;
        (r, Some(s))
    } else {
        (racket_impact::simulate(&params)?, None)
    };
    // (from the cached modes: the modal solver runs where the explicit one would refuse)
    let f1_hz = racket_impact::model::basis::Basis::of(&params.racket, params.numerics.segments).omega[0]
        / (2.0 * std::f64::consts::PI);
    let text = match a.common.format {
        Format::Json => {
            let mut v = serde_json::to_value(result).map_err(|e| Error::io("<json>", e))?;
            v["params"] = serde_json::to_value(params).map_err(|e| Error::io("<json>", e))?;
            v["f1_hz"] = f1_hz.into();
            format!("{}\n", serde_json::to_string_pretty(&v).map_err(|e| Error::io("<json>", e))?)
        }
        Format::Csv => racket_impact::render::impact::result_csv(&result),
        Format::Text => racket_impact::render::impact::result_text(&params, &result),
    };
    if let (Some(path), Some(rows)) = (&a.series, &series) {
        racket_impact::render::impact::write_series(path, rows)?;
    }
    out!("{text}");
    if result.recontact {
        eprintln!("warning: the vibrating frame met the ball again after separation (re-contact not modelled)");
    }
    Ok(())
}

fn modes(a: ModesArgs) -> Result<()> {
    let params = params_from(&a.common)?;
    let n = params.numerics.segments;
    if a.count == 0 || a.count > 20 || a.count > n - 1 {
        return Err(Error::invalid("count", a.count, format!("must satisfy 1 <= count <= min(20, N-1 = {})", n - 1)));
    }
    let beam = Beam::new(&params.racket, n);
    let modes = beam.modes();
    let freqs: Vec<f64> = (1..=a.count).map(|k| modes.frequency_hz(k)).collect();
    let nodes = modes.node_positions(1, &beam.x);
    let text = match a.common.format {
        Format::Json => {
            let v = serde_json::json!({
                "frequencies_hz": freqs,
                "mode1_nodes_m": nodes,
                "segments": n,
                "params": params.racket,
            });
            format!("{}\n", serde_json::to_string_pretty(&v).map_err(|e| Error::io("<json>", e))?)
        }
        Format::Csv => {
            let mut s = String::from("mode,frequency_hz\n");
            for (k, f) in freqs.iter().enumerate() {
                s.push_str(&format!("{},{}\n", k + 1, f));
            }
            s
        }
        Format::Text => {
            let mut s = format!(
                "free-free racket: L = {} m, M = {} kg, EI = {} N m^2, N = {}\n",
                params.racket.length, params.racket.mass, params.racket.ei, n
            );
            for (k, f) in freqs.iter().enumerate() {
                s.push_str(&format!("mode {}: {:9.2} Hz\n", k + 1, f));
            }
            let list: Vec<String> = nodes.iter().map(|x| format!("{:.2} cm", 100.0 * x)).collect();
            s.push_str(&format!("mode-1 nodes from the tip: {}\n", list.join(", ")));
            s
        }
    };
    out!("{text}");
    Ok(())
}

fn figures(a: FiguresArgs) -> Result<()> {
    use racket_impact::experiments;
    if a.list {
        for e in experiments::registry() {
            outln!("{:<24} {}\n{:<24} ({})", e.id, e.title, "", e.paper_ref);
        }
        return Ok(());
    }
    let selected = if a.only.is_empty() {
        experiments::registry()
    } else {
        a.only.iter().map(|id| experiments::find(id)).collect::<Result<Vec<_>>>()?
    };
    let mut ctx = experiments::Context::paper();
    let out = match &a.racket {
        Some(arg) => {
            let spec = racket_impact::racket::load(arg)?;
            let fitted = spec.to_racket(Params::paper().numerics.segments)?;
            ctx = experiments::Context::with_racket(fitted.racket, fitted.ball);
            let stem = std::path::Path::new(arg).file_stem().and_then(|s| s.to_str()).unwrap_or("custom");
            let name: String =
                stem.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).collect();
            a.out.clone().unwrap_or_else(|| PathBuf::from("figures").join(format!("racket-{name}")))
        }
        None => a.out.clone().unwrap_or_else(|| PathBuf::from("figures")),
    };
    racket_impact::render::io::ensure_dir(&out)?;
    for e in &selected {
        let start = std::time::Instant::now();
        let table = experiments::run_and_write(e, &ctx, &out)?;
        eprintln!(
            "{:<24} {:>4} rows  {:>6.2} s  -> {}/{}.{{csv,png}}",
            e.id,
            table.rows.len(),
            start.elapsed().as_secs_f64(),
            out.display(),
            e.id
        );
    }
    Ok(())
}

fn report(a: ReportArgs) -> Result<()> {
    if !a.no_write {
        racket_impact::render::io::check_output_dir("out", &a.out)?;
    }
    let rows = racket_impact::report::evaluate()?;
    let md = racket_impact::report::markdown(&rows);
    if !a.no_write {
        racket_impact::render::io::write_atomic(&a.out, md.as_bytes())?;
    }
    out!("{md}");
    Ok(())
}

fn sweep(a: SweepArgs) -> Result<()> {
    use racket_impact::sweep::{parse_spec, Sweep};
    let base = config_file(a.config.as_deref())?;
    if a.specs.len() % 2 != 0 || a.specs.is_empty() {
        return Err(Error::invalid(
            "sweep",
            a.specs.join(" "),
            "give parameters as --KEY SPEC pairs, e.g. --ks 2e4,4e4",
        ));
    }
    let mut axes = Vec::new();
    for pair in a.specs.chunks(2) {
        let key = pair[0].strip_prefix("--").ok_or_else(|| {
            Error::invalid("sweep", &pair[0], "expected --KEY before each SPEC (e.g. --x 0.02:0.60:50)")
        })?;
        if axes.iter().any(|ax: &racket_impact::sweep::Axis| ax.key == key) {
            return Err(Error::invalid("sweep", key, "each parameter may be given once"));
        }
        axes.push(parse_spec(key, &pair[1])?);
    }
    let defaults = match &a.racket {
        Some(arg) => {
            let spec = racket_impact::racket::load(arg)?;
            let only_n = Overrides { segments: base.segments, ..Overrides::default() };
            racket_impact::racket::resolve(Some(&spec), &only_n)?.0
        }
        None => Params::default(),
    };
    let mut base = base;
    base.solver = racket_impact::sweep::default_solver(&base, &axes);
    let sweep = Sweep { defaults, base, axes };
    sweep.validate_all()?; // a bad value anywhere fails before anything is written
    if let Some(path) = &a.out {
        racket_impact::render::io::check_output_dir("out", path)?;
    }
    let progress = Progress::new(sweep.len());
    let mut file = match &a.out {
        Some(path) => Some(racket_impact::render::io::AtomicFile::create(path)?),
        None => None,
    };
    let mut emit = |bytes: &[u8]| -> Result<()> {
        match file.as_mut() {
            Some(f) => f.write(bytes),
            None => write_stdout(bytes),
        }
    };
    emit(&csv_lines(&[sweep.header()]))?;
    let outcome = sweep.run(|rows| emit(&csv_lines(rows)), |done| progress.update(done));
    drop(progress);
    outcome?; // on error the temporary file is dropped, the target untouched
    match file {
        Some(f) => f.commit(),
        None => Ok(()),
    }
}

/// CSV lines (fields quoted only where needed), one writer for them all.
fn csv_lines(rows: &[Vec<String>]) -> Vec<u8> {
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(Vec::new());
    for r in rows {
        let _ = w.write_record(r);
    }
    w.into_inner().unwrap_or_default()
}

fn racket_cmd(a: RacketArgs) -> Result<()> {
    use racket_impact::racket;
    if a.list {
        for name in racket::preset_names() {
            let fitted = racket::load(name)?.to_racket(a.segments)?;
            let (r, rep) = (&fitted.racket, &fitted.report);
            outln!(
                "{name:<22} {:.1} cm, {:.0} g, balance {:.1} cm, swingweight {:.0} kg cm^2, twistweight {:.1} kg cm^2, f1 {:.0} Hz, ks {:.0} N/m{}",
                100.0 * r.length,
                1e3 * r.mass,
                rep.balance_cm.model,
                rep.swingweight_kg_cm2.model,
                rep.twistweight_kg_cm2.model,
                rep.frequency_hz.model,
                fitted.strings.ks,
                if r.profile.is_none() { ", uniform (the paper's beam)" } else { "" }
            );
        }
        return Ok(());
    }
    let Some(arg) = a.racket.as_deref() else {
        return Err(Error::invalid("racket", "(missing)", "give a racket file or preset name, or --list"));
    };
    let spec = racket::load(arg)?;
    let fitted = spec.to_racket(a.segments)?;
    let text = match a.format {
        Format::Text => {
            let r = &fitted.racket;
            let mut s = format!("{}\n", fitted.report);
            s.push_str(&format!(
                "model: L = {} m, M = {} kg, EI = {:.6} N m^2{}, Ix = {} kg m^2, ks = {:.6} N/m, ball {} kg\n",
                r.length,
                r.mass,
                r.ei,
                if r.profile.is_some() { " (times the stiffness profile)" } else { "" },
                r.ix,
                fitted.strings.ks,
                fitted.ball.mass
            ));
            if let Some(h) = r.head_length {
                s.push_str(&format!(
                    "string face: ellipse {:.1} cm x {:.1} cm from the tip\n",
                    100.0 * h,
                    200.0 * r.half_width
                ));
            }
            s
        }
        Format::Csv => fitted.report.table().to_csv(),
        Format::Json => {
            let t = fitted.report.table();
            let rows: Vec<serde_json::Value> = t
                .rows
                .iter()
                .map(|row| {
                    let obj: serde_json::Map<String, serde_json::Value> = t
                        .columns
                        .iter()
                        .zip(row)
                        .map(|(c, v)| (c.clone(), serde_json::Value::String(v.to_csv_field())))
                        .collect();
                    serde_json::Value::Object(obj)
                })
                .collect();
            let v = serde_json::json!({ "fit": rows, "racket": fitted.racket, "strings": fitted.strings, "ball": fitted.ball });
            format!("{}\n", serde_json::to_string_pretty(&v).map_err(|e| Error::io("<json>", e))?)
        }
    };
    out!("{text}");
    Ok(())
}

fn speed(a: SpeedArgs) -> Result<()> {
    use racket_impact::experiments::speeds::{gain_pct, outgoing_speed};
    use racket_impact::render::table::{Table, Value};
    let unit = a.unit.si();
    for (field, v) in [("swing", a.swing), ("incoming", a.incoming)] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(Error::invalid(field, v, format!("speed must be a finite number >= 0 {}", a.unit.label())));
        }
    }
    let (v_racket, v_in) = (a.swing * unit, a.incoming * unit);
    check_comparison(&a.compare_tension_lb, !a.compare_racket.is_empty())?;
    // the variants: (label, racket argument, tension)
    let mut variants: Vec<(String, Option<String>, Option<f64>)> = Vec::new();
    for &t in &a.compare_tension_lb {
        variants.push((format!("{t} lb"), a.common.racket.clone(), Some(t)));
    }
    for r in &a.compare_racket {
        variants.push((r.clone(), Some(r.clone()), None));
    }
    if variants.is_empty() {
        variants.push((a.common.racket.clone().unwrap_or_else(|| "paper".into()), a.common.racket.clone(), None));
    }
    let mut rows = Vec::new();
    for (label, racket, tension) in &variants {
        let (mut p, _) = resolve(racket.as_deref(), &a.common)?;
        if let Some(t) = tension {
            p.strings.ks = racket_impact::params::ks_from_tension_lb(*t);
        }
        // e_A is computed at the relative speed (it does not depend on it; theta scales with it)
        p.impact.v1 = v_in + v_racket;
        p.validate()?;
        let r = racket_impact::simulate(&p)?;
        let v_out = outgoing_speed(r.e_a, v_in, v_racket);
        rows.push((label.clone(), p, r, v_out));
    }
    let v_ref = rows[0].3;
    let mut t = Table::new(
        "speed",
        &["variant", "x_m", "r_m", "ks_n_per_m", "e_a", "tau_ms", "theta_deg", "ball_speed_out", "change_pct", "unit"],
    );
    for (label, p, r, v_out) in &rows {
        t.push(vec![
            Value::Text(label.clone()),
            p.impact.x.into(),
            p.impact.r.into(),
            p.strings.ks.into(),
            r.e_a.into(),
            (1e3 * r.tau_s).into(),
            r.theta_end_deg.into(),
            (v_out / unit).into(),
            gain_pct(v_ref, *v_out).into(),
            Value::Text(a.unit.label().into()),
        ])?;
    }
    let text = match a.common.format {
        Format::Csv => t.to_csv(),
        Format::Json => {
            let v: Vec<serde_json::Value> = rows
                .iter()
                .map(|(label, p, r, v_out)| {
                    serde_json::json!({
                        "variant": label, "params": p, "result": r,
                        "ball_speed_out": v_out / unit, "change_pct": gain_pct(v_ref, *v_out), "unit": a.unit.label(),
                    })
                })
                .collect();
            format!("{}\n", serde_json::to_string_pretty(&v).map_err(|e| Error::io("<json>", e))?)
        }
        Format::Text => {
            let mut s = format!(
                "swing {} {u} at the impact point, incoming ball {} {u}: v_out = e_A v_in + (1 + e_A) v_racket\n",
                a.swing,
                a.incoming,
                u = a.unit.label()
            );
            s.push_str(&format!(
                "{:<22} {:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>12} {:>9}\n",
                "variant", "x cm", "r cm", "ks N/m", "e_A", "tau ms", "theta deg", "ball out", "change"
            ));
            for (label, p, r, v_out) in &rows {
                s.push_str(&format!(
                    "{:<22} {:>7.1} {:>6.1} {:>9.0} {:>8.4} {:>8.3} {:>9.2} {:>7.1} {:<4} {:>+8.2} %\n",
                    label,
                    100.0 * p.impact.x,
                    100.0 * p.impact.r,
                    p.strings.ks,
                    r.e_a,
                    1e3 * r.tau_s,
                    r.theta_end_deg,
                    v_out / unit,
                    a.unit.label(),
                    gain_pct(v_ref, *v_out)
                ));
            }
            s
        }
    };
    out!("{text}");
    Ok(())
}

/// The configuration of a map: as [`resolve`], with the impact position taken out of the
/// flags (rejected) and the config file (ignored); the grid sets it.
fn map_params(racket: Option<&str>, common: &Common) -> Result<Params> {
    if let Some(x) = common.overrides.x {
        return Err(Error::invalid("x", x, "a map chooses the impact points itself: give --nx/--nr, not --x"));
    }
    if let Some(r) = common.overrides.r {
        return Err(Error::invalid("r", r, "a map chooses the impact points itself: give --nx/--nr, not --r"));
    }
    let mut config = config_file(common.config.as_deref())?;
    // an on-axis point at the tip is valid on every face; the grid replaces it
    config.x = Some(0.0);
    config.r = Some(0.0);
    let spec = racket.map(racket_impact::racket::load).transpose()?;
    Ok(racket_impact::racket::resolve(spec.as_ref(), &common.overrides.clone().or(config))?.0)
}

/// A racket argument as a short name: a preset as is, a file by its stem.
fn racket_label(arg: Option<&str>) -> String {
    match arg {
        None => "paper racket".to_string(),
        Some(a) if racket_impact::racket::preset_names().contains(&a) => a.to_string(),
        Some(a) => std::path::Path::new(a).file_stem().and_then(|s| s.to_str()).unwrap_or(a).to_string(),
    }
}

fn map(a: MapArgs) -> Result<()> {
    use racket_impact::map::{check_count, DiffMap, FaceMap, Outputs};
    use racket_impact::params::ks_from_tension_lb;
    check_count("nx", a.nx)?;
    check_count("nr", a.nr)?;
    check_comparison(&a.compare_tension_lb, a.compare_racket.is_some())?;
    if a.compare_tension_lb.len() > 2 {
        return Err(Error::invalid(
            "compare-tension-lb",
            a.compare_tension_lb.iter().map(f64::to_string).collect::<Vec<_>>().join(","),
            "give one tension T (the configuration against T) or two, T1,T2",
        ));
    }
    let diff = a.compare_racket.is_some() || !a.compare_tension_lb.is_empty();
    let out = a
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("map_{}{}.csv", a.quantity.name(), if diff { "_diff" } else { "" })));
    let outputs = Outputs::for_csv(&out)?;

    // the configurations: (label, params)
    let name_a = racket_label(a.common.racket.as_deref());
    let base = map_params(a.common.racket.as_deref(), &a.common)?;
    let mut configs: Vec<(String, Params)> = Vec::new();
    if let Some(b) = &a.compare_racket {
        configs.push((name_a.clone(), base));
        configs.push((racket_label(Some(b)), map_params(Some(b), &a.common)?));
    } else if !a.compare_tension_lb.is_empty() {
        let at = |t: f64| {
            let mut p = base;
            p.strings.ks = ks_from_tension_lb(t);
            (format!("{name_a} at {t} lb"), p)
        };
        match a.compare_tension_lb[..] {
            [t] => {
                configs.push((format!("{name_a} as given"), base));
                configs.push(at(t));
            }
            [t1, t2] => {
                configs.push(at(t1));
                configs.push(at(t2));
            }
            _ => {}
        }
    } else {
        configs.push((name_a.clone(), base));
    }
    for (_, p) in &configs {
        p.validate()?;
    }
    let total = match &configs[..] {
        [(_, p)] => FaceMap::count(p, a.nx, a.nr)?,
        [(_, pa), (_, pb)] => DiffMap::count(pa, pb, a.nx, a.nr)?,
        _ => 0,
    };
    if total == 0 {
        return Err(Error::invalid(
            "nx",
            format!("{} (with nr = {})", a.nx, a.nr),
            "no grid point lies inside the string face; use more points (e.g. --nx 5 --nr 5)",
        ));
    }

    let bar = Progress::new(total as u64);
    let started = bar.started;
    let mut progress = |done: u64| bar.update(done);
    let q = a.quantity;
    let counts = (a.nx, a.nr);
    let computed = (|| -> Result<_> {
        Ok(match &configs[..] {
            [(la, pa), (lb, pb)] => {
                let d = DiffMap::compute(pa, pb, a.nx, a.nr, &mut progress)?;
                let meta = d.metadata((la, lb), q, counts)?;
                let summary = diff_summary(&d, q, la, lb);
                (d.table(q), d.heatmap(q, la, lb), meta, summary)
            }
            [(la, pa)] => {
                let m = FaceMap::compute(pa, a.nx, a.nr, &mut progress)?;
                let meta = m.metadata(la, q, counts)?;
                let summary = map_summary(&m, q, la)?;
                (m.table(), m.heatmap(q, la), meta, summary)
            }
            _ => return Err(Error::invalid("map", configs.len(), "one or two configurations")),
        })
    })();
    drop(bar);
    let (table, heat, meta, summary) = computed?;
    let json = format!("{}\n", serde_json::to_string_pretty(&meta).map_err(|e| Error::io("<json>", e))?);
    let csv = table.to_csv();
    outputs.write(&csv, &heat, &json)?;
    match a.common.format {
        Format::Text => {
            out!("{summary}");
            outln!(
                "wrote {}, {}, {} ({:.2} s)",
                outputs.csv.display(),
                outputs.png.display(),
                outputs.json.display(),
                started.elapsed().as_secs_f64()
            );
        }
        Format::Json => out!("{json}"),
        Format::Csv => out!("{csv}"),
    }
    let recontacts = table.column("recontact").or_else(|| table.column("recontact_b")).unwrap_or_default();
    let n_re = recontacts.iter().filter(|&&v| v != 0.0).count();
    if n_re > 0 {
        eprintln!("warning: {n_re} map points have a re-contact after separation (flagged in the recontact column)");
    }
    Ok(())
}

fn map_summary(m: &racket_impact::map::FaceMap, q: Quantity, label: &str) -> Result<String> {
    let mut s = format!(
        "map of {} on {}: {} x {} grid, {} impacts inside the face ({:.1} x {:.1} cm{})\n",
        q.name(),
        label,
        m.grid.xs.len(),
        m.grid.rs.len(),
        m.len(),
        100.0 * m.face.length,
        200.0 * m.face.half_width,
        if m.face.from_racket { "" } else { ", default face" }
    );
    let unit = if q.unit().is_empty() { String::new() } else { format!(" {}", q.unit()) };
    if let Some((x, r)) = m.at_node()? {
        s.push_str(&format!(
            "mode-1 node {:.2} cm from the tip: e_A {:.4}, {} {:.4}{unit} (on the axis)\n",
            100.0 * x,
            r.e_a,
            q.name(),
            q.of(&r)
        ));
    }
    if let Some(p) = m.max_point(racket_impact::map::Quantity::EA) {
        s.push_str(&format!(
            "max e_A {:.4} at x = {:.2} cm, r = {:.2} cm\n",
            p.value,
            100.0 * p.x_m,
            100.0 * p.r_m + 0.0
        ));
    }
    if let Some(p) = m.max_point(q) {
        s.push_str(&format!(
            "max {} {:.4}{unit} at x = {:.2} cm, r = {:.2} cm\n",
            q.name(),
            p.value,
            100.0 * p.x_m,
            100.0 * p.r_m + 0.0
        ));
    }
    Ok(s)
}

fn diff_summary(d: &racket_impact::map::DiffMap, q: Quantity, la: &str, lb: &str) -> String {
    let unit = if q.unit().is_empty() { String::new() } else { format!(" {}", q.unit()) };
    let mut s = format!(
        "difference map of {}: B - A, A = {la} (ks {:.0} N/m), B = {lb} (ks {:.0} N/m); {} x {} grid, {} points inside both faces\n",
        q.name(),
        d.a.params.strings.ks,
        d.b.params.strings.ks,
        d.a.grid.xs.len(),
        d.a.grid.rs.len(),
        d.len()
    );
    if let racket_impact::map::Spread { min: Some(lo), max: Some(hi), .. } = d.spread(q) {
        s.push_str(&format!("B - A from {lo:.4} to {hi:.4}{unit}\n"));
    }
    s
}
