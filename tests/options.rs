//! Every option of every command is used or refused, and each command's help lists exactly
//! the options it takes (trap classes 3 and 4 of issue 24).
//!
//! The options are not listed by hand: they are read from the command line's own clap
//! definition ([`cli::Cli`], compiled into this test from `src/cli`). For each command and
//! each option it accepts, a probe runs the command with and without the option (in the
//! context the option needs, e.g. an incidence angle for the friction coefficient) and the
//! outputs (standard output, warnings and every file written) must differ; where a context is
//! needed, the option given without it must change the output, be refused with exit 2, or be
//! accepted with one note (a property the impact does not exercise, issue 32). The
//! parameter options get their probe from the parameter declarations; any other option needs
//! an entry in [`PROBES`], so a new option fails here until it is shown to do something.
//! The same holds for a config file's keys: each changes the output or is named in one
//! warning line.

#[allow(dead_code, unused_imports, unused_macros)]
#[path = "../src/cli/mod.rs"]
mod cli;
mod common;

use common::{bin, Scratch};
use std::collections::{BTreeMap, HashMap};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use clap::CommandFactory;
use cli::overrides::KeySet;
use racket_impact::params::spec::{Heading, UsedWhen, Values};
use racket_impact::params::{keys, used, Overrides, Params};

/// What a run produced: its exit code and everything a user sees of it.
#[derive(Debug, Clone, Default, PartialEq)]
struct Seen {
    code: Option<i32>,
    /// Standard output with the elapsed times (`(0.02 s)`) taken out.
    stdout: String,
    /// The warning lines.
    warnings: Vec<String>,
    /// Every file written below the working directory, with its bytes.
    files: BTreeMap<String, Vec<u8>>,
    /// The error line, if any.
    error: String,
}

/// A JSON output without its echo of the parameters (every `params` member), so that what
/// is compared is what was computed; any other text as it is.
fn results_only(text: &str) -> String {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                m.remove("params");
                m.values_mut().for_each(strip);
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    match serde_json::from_str::<serde_json::Value>(text) {
        Ok(mut v) => {
            strip(&mut v);
            v.to_string()
        }
        Err(_) => text.to_string(),
    }
}

/// Remove the elapsed times `(<number> s)` a command prints.
fn without_times(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(i) = rest.find('(') {
        out.push_str(&rest[..i]);
        let tail = &rest[i + 1..];
        let end = tail.find(" s)").filter(|&e| tail[..e].chars().all(|c| c.is_ascii_digit() || c == '.'));
        match end {
            Some(e) if e > 0 => rest = &tail[e + 3..],
            _ => {
                out.push('(');
                rest = tail;
            }
        }
    }
    out.push_str(rest);
    out
}

fn files_below(dir: &Path, root: &Path, out: &mut BTreeMap<String, Vec<u8>>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            files_below(&p, root, out);
        } else if p.file_name().is_some_and(|n| n != "cfg.toml") {
            let mut bytes = std::fs::read(&p).unwrap();
            if p.extension().is_some_and(|e| e == "json") {
                bytes = results_only(&String::from_utf8_lossy(&bytes)).into_bytes();
            }
            out.insert(p.strip_prefix(root).unwrap().display().to_string(), bytes);
        }
    }
}

/// Accepted with one note naming the option as not exercised by the impact (a property of the
/// racket, ball or strings this impact does not exercise, `params::used`).
fn noted(seen: &Seen, key: &str) -> bool {
    seen.code == Some(0)
        && seen.warnings.iter().filter(|w| w.contains(&format!("--{key} ")) && w.contains("not exercised")).count() == 1
}

/// Run `racket-impact <command> <args>` in a fresh directory holding `cfg.toml` = `config`.
fn run(command: &str, args: &[String], config: &str) -> Seen {
    let s = Scratch::new(&format!("{command}-{}", args.join("_").replace(['/', '.', ' '], "-")));
    std::fs::write(s.path("cfg.toml"), config).unwrap();
    let o = bin().current_dir(s.dir()).arg(command).args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    let mut files = BTreeMap::new();
    files_below(s.dir(), s.dir(), &mut files);
    Seen {
        code: o.status.code(),
        stdout: results_only(&without_times(&String::from_utf8_lossy(&o.stdout))),
        warnings: stderr.lines().filter(|l| l.starts_with("warning:")).map(String::from).collect(),
        files,
        error: stderr.lines().filter(|l| l.starts_with("error")).collect::<Vec<_>>().join(" "),
    }
}

/// A run: the command, its arguments and the text of its config file.
type Request = (String, Vec<String>, String);

/// The runs of a check. A check is written as if it ran each command where it needs it; it is
/// called twice ([`in_parallel`]): first its runs are only recorded (each answered with an
/// empty successful run, so that every run any branch needs is asked for), then all of them are
/// made at once, in parallel, each distinct one once (the commands are deterministic:
/// tests/outputs.rs checks that a rerun gives the same bytes), and the check is called again
/// with their outputs.
enum Runs {
    Recording(Mutex<Vec<Request>>),
    Made(HashMap<Request, Seen>),
}

impl Runs {
    /// What `racket-impact <command> <args>` with `config` as `cfg.toml` produced ([`run`]).
    fn run(&self, command: &str, args: &[String], config: &str) -> Seen {
        let request = (command.to_string(), args.to_vec(), config.to_string());
        match self {
            Runs::Recording(requests) => {
                requests.lock().unwrap().push(request);
                Seen { code: Some(0), ..Seen::default() }
            }
            Runs::Made(made) => made.get(&request).cloned().unwrap_or_else(|| run(command, args, config)),
        }
    }
}

/// Run `check` over its runs made in parallel (see [`Runs`]): on a 2-core machine the runs of
/// the slow commands (`report`, `uncertainty --claims`) overlap with each other and with the
/// many short ones, which go first to the longest.
fn in_parallel<T>(check: impl Fn(&Runs) -> T) -> T {
    let recording = Runs::Recording(Mutex::new(Vec::new()));
    check(&recording);
    let Runs::Recording(requests) = recording else { unreachable!("made as recording") };
    let mut requests = requests.into_inner().unwrap();
    // each distinct run once, the slowest commands first (the others fill in around them)
    let slow = |(c, a, _): &Request| !(c == "report" || (c == "uncertainty" && a.iter().any(|w| w == "--claims")));
    requests.sort_by(|x, y| slow(x).cmp(&slow(y)).then(x.cmp(y)));
    requests.dedup();
    let next = AtomicUsize::new(0);
    let made = Mutex::new(HashMap::new());
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                while let Some((command, args, config)) = requests.get(next.fetch_add(1, Ordering::Relaxed)) {
                    let seen = run(command, args, config);
                    made.lock().unwrap().insert((command.clone(), args.clone(), config.clone()), seen);
                }
            });
        }
    });
    check(&Runs::Made(made.into_inner().unwrap()))
}

/// An option: its clap id and its long name (none for a positional argument).
type Opt = (String, Option<String>);

/// Each command's options as clap defines them: (command, [(option id, long name)]), the
/// global `--quiet` included, help and version left out.
fn option_table() -> Vec<(String, Vec<Opt>)> {
    let mut cmd = cli::Cli::command();
    cmd.build();
    cmd.get_subcommands()
        .filter(|c| c.get_name() != "help")
        .map(|c| {
            let opts = c
                .get_arguments()
                .filter(|a| !matches!(a.get_action(), clap::ArgAction::Help | clap::ArgAction::Version))
                .map(|a| (a.get_id().to_string(), a.get_long().map(String::from)))
                .collect();
            (c.get_name().to_string(), opts)
        })
        .collect()
}

/// The arguments every parameter probe of a command runs with (a small map, a swing), in
/// JSON, whose numbers are printed in full: a parameter must change what is computed, not
/// only its echo in the output (which [`results_only`] leaves out).
fn base(command: &str) -> Vec<&'static str> {
    match command {
        "speed" => vec!["--swing", "100", "--format", "json"],
        "map" => vec!["--nx", "7", "--nr", "5", "--format", "json"],
        "sweep" => vec!["--x", "0.1,0.2"],
        "card" => vec!["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--format", "json"],
        "uncertainty" => vec!["--vary", "v1=uniform:6:8", "--samples", "8", "--format", "json"],
        // normal incidence: a frame of either kind runs it, and an oblique ball's parameters are
        // noted as not exercised (the probes of the oblique fit run over LAB)
        "calibrate" => vec![NORMAL, "--fit", "ks", "--hold-out", "none", "--format", "json"],
        _ => vec!["--format", "json"],
    }
}

/// `calibrate`'s measurements in its probes: free-racket oblique shots that leave every
/// parameter to the flags (no tension, string or impact point of their own).
const LAB: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/calibrate_lab.csv");
/// The same shots with the racket in a hand (the hand's parameters).
const HAND: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/calibrate_hand.csv");
/// Normal-incidence rows (e_a): the base of calibrate's parameter probes.
const NORMAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/calibrate_normal.csv");

/// The probes of the options that are not impact parameters: (command, option id, the
/// arguments with the option, the same without it). The config file of every run is
/// `cfg.toml` in the working directory ([`config_for`]).
const PROBES: &[(&str, &str, &[&str], &[&str])] = &[
    ("*", "quiet", &["--quiet", "--ks", "1e3"], &["--ks", "1e3"]),
    ("*", "racket", &["--racket", "tweener"], &[]),
    ("*", "config", &["--config", "cfg.toml"], &[]),
    ("*", "format", &["--format", "json"], &[]),
    ("simulate", "series", &["--series", "s.csv"], &[]),
    ("simulate", "series_dt", &["--series", "s.csv", "--series-dt", "4e-5"], &["--series", "s.csv"]),
    ("simulate", "series_end", &["--series", "s.csv", "--series-end", "0.05"], &["--series", "s.csv"]),
    ("modes", "count", &["--count", "6"], &[]),
    ("modes", "quiet", &["--quiet", "--mass", "5"], &["--mass", "5"]),
    ("speed", "quiet", &["--swing", "100", "--quiet", "--ks", "1e3"], &["--swing", "100", "--ks", "1e3"]),
    ("speed", "racket", &["--swing", "100", "--racket", "tweener"], &["--swing", "100"]),
    ("speed", "config", &["--swing", "100", "--config", "cfg.toml"], &["--swing", "100"]),
    ("speed", "format", &["--swing", "100", "--format", "json"], &["--swing", "100"]),
    ("speed", "swing", &["--swing", "120"], &["--swing", "100"]),
    ("speed", "incoming", &["--swing", "100", "--incoming", "60"], &["--swing", "100"]),
    ("speed", "unit", &["--swing", "100", "--unit", "mph"], &["--swing", "100"]),
    ("speed", "compare_tension_lb", &["--swing", "100", "--compare-tension-lb", "50"], &["--swing", "100"]),
    ("speed", "compare_racket", &["--swing", "100", "--compare-racket", "light"], &["--swing", "100"]),
    ("speed", "swing_path_deg", &["--swing", "100", "--swing-path-deg", "20"], &["--swing", "100"]),
    ("speed", "incoming_spin_rpm", &["--swing", "100", "--incoming-spin-rpm", "1000"], &["--swing", "100"]),
    ("map", "quiet", &["--nx", "7", "--nr", "5", "--quiet", "--ks", "1e3"], &["--nx", "7", "--nr", "5", "--ks", "1e3"]),
    ("map", "racket", &["--nx", "7", "--nr", "5", "--racket", "tweener"], &["--nx", "7", "--nr", "5"]),
    ("map", "config", &["--nx", "7", "--nr", "5", "--config", "cfg.toml"], &["--nx", "7", "--nr", "5"]),
    ("map", "format", &["--nx", "7", "--nr", "5", "--format", "json"], &["--nx", "7", "--nr", "5"]),
    ("map", "quantity", &["--nx", "7", "--nr", "5", "--quantity", "tau"], &["--nx", "7", "--nr", "5"]),
    ("map", "nx", &["--nx", "8", "--nr", "5"], &["--nx", "7", "--nr", "5"]),
    ("map", "nr", &["--nx", "7", "--nr", "6"], &["--nx", "7", "--nr", "5"]),
    ("map", "out", &["--nx", "7", "--nr", "5", "--out", "m.csv"], &["--nx", "7", "--nr", "5"]),
    ("map", "long", &["--nx", "7", "--nr", "5", "--long"], &["--nx", "7", "--nr", "5"]),
    ("map", "compare_racket", &["--nx", "7", "--nr", "5", "--compare-racket", "light"], &["--nx", "7", "--nr", "5"]),
    (
        "map",
        "compare_tension_lb",
        &["--nx", "7", "--nr", "5", "--compare-tension-lb", "50"],
        &["--nx", "7", "--nr", "5"],
    ),
    ("card", "quiet", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--quiet"], CARD),
    ("card", "racket", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--racket", "tweener"], CARD),
    ("card", "config", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--config", "cfg.toml"], CARD),
    ("card", "format", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--format", "json"], CARD),
    ("card", "tensions_lb", &["--tensions-lb", "50,55", "--nx", "5", "--nr", "5"], CARD),
    ("card", "reference_lb", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--reference-lb", "50"], CARD),
    ("card", "compare", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--compare", "light"], CARD),
    ("card", "serve_kmh", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--serve-kmh", "140"], CARD),
    ("card", "forehand_kmh", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--forehand-kmh", "100"], CARD),
    ("card", "swing_rad_per_s", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--swing-rad-per-s", "20"], CARD),
    (
        "card",
        "sweet_within",
        &["--tensions-lb", "50,60", "--nx", "11", "--nr", "7", "--sweet-within", "0.3"],
        &["--tensions-lb", "50,60", "--nx", "11", "--nr", "7"],
    ),
    ("card", "nx", &["--tensions-lb", "50,60", "--nx", "6", "--nr", "5"], CARD),
    ("card", "nr", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "6"], CARD),
    ("card", "out", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--out", "c.csv"], CARD),
    ("card", "long", &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5", "--long"], CARD),
    ("sweep", "racket", &["--racket", "tweener", "--x", "0.1,0.2"], &["--x", "0.1,0.2"]),
    ("sweep", "config", &["--config", "cfg.toml", "--x", "0.1,0.2"], &["--x", "0.1,0.2"]),
    ("sweep", "out", &["--out", "s.csv", "--x", "0.1,0.2"], &["--x", "0.1,0.2"]),
    ("sweep", "long", &["--long", "--x", "0.1,0.2"], &["--x", "0.1,0.2"]),
    ("sweep", "quiet", &["--quiet", "--ks", "1e3,2e3"], &["--ks", "1e3,2e3"]),
    ("sweep", "specs", &["--x", "0.1,0.3"], &["--x", "0.1,0.2"]),
    // uncertainty's other probes run over UNCERTAINTY_STUDY (see [`probes`]); its own probe of
    // --v1 varies ks instead
    (
        "uncertainty",
        "samples",
        &["--vary", "v1=uniform:6:8", "--samples", "16"],
        &["--vary", "v1=uniform:6:8", "--samples", "8"],
    ),
    ("uncertainty", "claims", &["--claims", "--samples", "8"], &["--vary", "v1=uniform:6:8", "--samples", "8"]),
    (
        "uncertainty",
        "v1",
        &["--vary", "ks=uniform:3e4:5e4", "--samples", "8", "--v1", "10"],
        &["--vary", "ks=uniform:3e4:5e4", "--samples", "8"],
    ),
    (
        "calibrate",
        "quiet",
        &[LAB, "--fit", "kt", "--hold-out", "none", "--quiet", "--mb", "0.3"],
        &[LAB, "--fit", "kt", "--hold-out", "none", "--mb", "0.3"],
    ),
    (
        "calibrate",
        "racket",
        &[LAB, "--fit", "kt", "--hold-out", "none", "--racket", "tweener"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "config",
        &[LAB, "--fit", "kt", "--hold-out", "none", "--config", "cfg.toml"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "format",
        &[LAB, "--fit", "kt", "--hold-out", "none", "--format", "json"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    ("calibrate", "measurements", &[LAB, "--fit", "kt", "--hold-out", "none"], &["--fit", "kt", "--hold-out", "none"]),
    (
        "calibrate",
        "fit",
        &[LAB, "--fit", "mu-scale", "--hold-out", "none"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "range",
        &[LAB, "--fit", "kt", "--range", "kt=1e4:1e5", "--hold-out", "none"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "rows",
        &[LAB, "--fit", "kt", "--rows", "L01-L03", "--hold-out", "none"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "weights",
        &[LAB, "--fit", "kt", "--weights", "uncertainty", "--hold-out", "none"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    ("calibrate", "hold_out", &[LAB, "--fit", "kt", "--hold-out", "row"], &[LAB, "--fit", "kt", "--hold-out", "none"]),
    (
        "calibrate",
        "plot",
        &[LAB, "--fit", "kt", "--hold-out", "none", "--plot", "c.png"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "out",
        &[LAB, "--fit", "kt", "--hold-out", "none", "--out", "c.txt"],
        &[LAB, "--fit", "kt", "--hold-out", "none"],
    ),
    // the fitted parameter's own flag is refused: probed while another is fitted
    (
        "calibrate",
        "kt",
        &[LAB, "--fit", "mu-scale", "--hold-out", "none", "--kt", "3e4"],
        &[LAB, "--fit", "mu-scale", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "hand-stiffness",
        &[HAND, "--fit", "kt", "--hold-out", "none", "--hand-stiffness", "8000"],
        &[HAND, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "hand-damping",
        &[HAND, "--fit", "kt", "--hold-out", "none", "--hand-damping", "30"],
        &[HAND, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "grip-length",
        &[HAND, "--fit", "kt", "--hold-out", "none", "--grip-length", "0.2"],
        &[HAND, "--fit", "kt", "--hold-out", "none"],
    ),
    (
        "calibrate",
        "ks",
        &[NORMAL, "--fit", "k1", "--hold-out", "none", "--ks", "3e4"],
        &[NORMAL, "--fit", "k1", "--hold-out", "none"],
    ),
    // (`figures` without `--only` runs every experiment, 45 CPU-seconds: `make figures` is that
    // run, and tests/golden.rs checks every experiment's table and figure; here `--only` is shown
    // to select and `--list` to run nothing against runs of one experiment)
    ("figures", "only", &["--only", "modes"], &["--only", "modes", "--only", "clamped_drop"]),
    ("figures", "out", &["--only", "modes", "--out", "elsewhere"], &["--only", "modes"]),
    ("figures", "racket", &["--only", "modes", "--racket", "tweener"], &["--only", "modes"]),
    ("figures", "list", &["--list"], &["--only", "modes"]),
    ("figures", "quiet", &["--quiet", "--only", "modes"], &["--only", "modes"]),
    ("report", "out", &["--out", "r.md"], &[]),
    ("report", "no_write", &["--no-write"], &[]),
    ("report", "summary", &["--summary", "--out", "r.md"], &["--out", "r.md"]),
    ("report", "quiet", &["--quiet", "--no-write"], &["--no-write"]),
    ("racket", "racket", &["tweener"], &["players"]),
    ("racket", "list", &["--list"], &["players"]),
    ("racket", "segments", &["players", "--segments", "60"], &["players"]),
    ("racket", "format", &["players", "--format", "json"], &["players"]),
    ("racket", "quiet", &["--quiet", "--list"], &["--list"]),
];

/// The small card the `card` probes run over: two tensions, a 5 x 5 grid.
const CARD: &[&str] = &["--tensions-lb", "50,60", "--nx", "5", "--nr", "5"];

/// The small study most `uncertainty` probes run over: v1 drawn, 8 base samples.
const UNCERTAINTY_STUDY: &[&str] = &["--vary", "v1=uniform:6:8", "--samples", "8"];

/// The `uncertainty` probes over [`UNCERTAINTY_STUDY`]: option id, the arguments after the
/// study with the option, the same without it.
const UNCERTAINTY_PROBES: &[(&str, &[&str], &[&str])] = &[
    ("quiet", &["--quiet", "--ks", "1e3"], &["--ks", "1e3"]),
    ("racket", &["--racket", "tweener"], &[]),
    ("config", &["--config", "cfg.toml"], &[]),
    ("format", &["--format", "json"], &[]),
    ("vary", &["--vary", "ks=uniform:3e4:5e4"], &[]),
    ("seed", &["--seed", "3"], &[]),
    ("long", &["--long"], &[]),
    ("out", &["--out", "u.json"], &[]),
    ("dt", &["--solver", "fd", "--dt", "1e-6"], &["--solver", "fd"]),
];

/// Every probe: [`PROBES`] and the `uncertainty` ones with their study in front.
type Probe = (&'static str, &'static str, Vec<&'static str>, Vec<&'static str>);
fn probes() -> Vec<Probe> {
    let study = |args: &[&'static str]| UNCERTAINTY_STUDY.iter().chain(args).copied().collect::<Vec<_>>();
    PROBES
        .iter()
        .map(|(c, o, with, without)| (*c, *o, with.to_vec(), without.to_vec()))
        .chain(UNCERTAINTY_PROBES.iter().map(|(o, with, without)| ("uncertainty", *o, study(with), study(without))))
        .collect()
}

/// Options that print nothing different for any input of the command (`--quiet` where the
/// command never warns): pinned here, so a command that starts to warn must show its
/// `--quiet` working.
const SILENT: &[(&str, &str)] = &[("report", "quiet"), ("racket", "quiet"), ("figures", "quiet")];

/// The config file of a command's runs: a value its probe can see.
fn config_for(command: &str) -> &'static str {
    match command {
        "modes" => "ei = 200\n",
        _ => "ks = 30000\n",
    }
}

/// The parameters the commands start from (the paper's racket hit at its face centre).
fn defaults() -> Params {
    racket_impact::racket::resolve(None, &Overrides::default()).unwrap().0
}

/// A value of parameter `key` other than its default, inside its range.
fn sample_value(key: &str) -> String {
    let spec = keys::find(key).unwrap();
    let default = keys::value_text(key, &defaults()).unwrap_or_default();
    match (key, spec.values) {
        (_, Values::Choice(choices)) => choices.iter().find(|c| c.name != default).unwrap().name.to_string(),
        (_, Values::Count) => "50".to_string(),
        ("x", _) => "0.2".to_string(),
        ("r", _) => "0.02".to_string(),
        ("angle-deg", _) => "30".to_string(),
        ("azimuth-deg", _) => "90".to_string(),
        ("spin-rpm", _) => "1000".to_string(),
        ("dt", _) => "1e-6".to_string(),
        _ => {
            let d: f64 = default.parse().unwrap_or_else(|_| panic!("{key}: default {default:?} is not a number"));
            format!("{}", d * 1.1)
        }
    }
}

/// The flags a parameter needs to be used by `command`, read from its row's `used_when` (a
/// variant selected, an oblique ball, an impact off the long axis), so that a new parameter
/// needs no entry here.
fn context(command: &str, key: &str) -> Vec<String> {
    let spec = keys::find(key).unwrap();
    let takes = |flag: &str| {
        option_table()
            .iter()
            .any(|(c, opts)| c == command && opts.iter().any(|(_, long)| long.as_deref() == Some(flag)))
    };
    match spec.used_when {
        // (modes runs no impact: its parameters describe the free racket)
        _ if command == cli::overrides::ModesKeys::COMMAND => vec![],
        // calibrate's base rows set the shot (its point, incidence and grip are theirs)
        UsedWhen::Oblique | UsedWhen::OffAxis | UsedWhen::Twisted if command == "calibrate" => vec![],
        UsedWhen::Always => vec![],
        // a card's twist impact is off the axis and its spin shot oblique
        UsedWhen::OffAxis | UsedWhen::Twisted | UsedWhen::Oblique if command == "card" => vec![],
        UsedWhen::Oblique if command == "speed" => strings(&["--swing-path-deg", "20"]),
        UsedWhen::Oblique => strings(&["--angle-deg", "30"]),
        // a map's grid is off the long axis; elsewhere the twist needs r != 0 and the face's
        // width an impact beyond the default one (0.125 m)
        UsedWhen::OffAxis | UsedWhen::Twisted if command == "map" => vec![],
        UsedWhen::OffAxis => strings(&["--r", "0.13"]),
        UsedWhen::Twisted => strings(&["--r", "0.03"]),
        UsedWhen::In(selector, names) => {
            let mut ctx = context(command, selector.key);
            if takes(selector.key) {
                ctx.extend([format!("--{}", selector.key), names[0].to_string()]);
            }
            ctx
        }
    }
}

fn strings(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

fn differs(a: &Seen, b: &Seen) -> bool {
    a.stdout != b.stdout || a.warnings != b.warnings || a.files != b.files
}

#[test]
fn every_option_of_every_command_changes_the_output_or_is_refused() {
    let (probed, failures) = in_parallel(every_option_changes_the_output_or_is_refused);
    assert!(probed > 100, "only {probed} options probed");
    assert!(failures.is_empty(), "{} options not shown to work:\n{}", failures.len(), failures.join("\n"));
}

/// How many options were probed, and the failures.
fn every_option_changes_the_output_or_is_refused(runs: &Runs) -> (usize, Vec<String>) {
    let run = |command: &str, args: &[String], config: &str| runs.run(command, args, config);
    let mut failures = Vec::new();
    let mut probed = 0;
    let probes = probes();
    for (command, options) in option_table() {
        let config = config_for(&command);
        for (id, long) in options {
            let table = probes.iter().find(|(c, o, _, _)| *c == command && *o == id).or_else(|| {
                probes.iter().find(|(c, o, _, _)| {
                    *c == "*" && *o == id && !["speed", "map", "sweep", "uncertainty", "card"].contains(&&*command)
                })
            });
            let (with, without, bare) = match (table, keys::find(&id)) {
                (Some((_, _, with, without)), _) => (strings(with), strings(without), None),
                (None, Some(spec)) => {
                    // sweep and uncertainty run modal unless told: their other solver is fd
                    let value = match (spec.key, command.as_str()) {
                        ("solver", "sweep" | "uncertainty" | "calibrate") => "fd".to_string(),
                        _ => sample_value(spec.key),
                    };
                    let flag = [format!("--{}", spec.key), value];
                    let b = strings(&base(&command));
                    let ctx = context(&command, spec.key);
                    let without: Vec<String> = ctx.iter().chain(&b).cloned().collect();
                    let with: Vec<String> = flag.iter().chain(&without).cloned().collect();
                    let bare = (!ctx.is_empty()).then(|| (flag.iter().chain(&b).cloned().collect::<Vec<_>>(), b));
                    (with, without, bare)
                }
                (None, None) => {
                    failures.push(format!("{command} --{}: no probe; add one to PROBES", long.unwrap_or(id)));
                    continue;
                }
            };
            probed += 1;
            let (a, b) = (run(&command, &with, config), run(&command, &without, config));
            let silent = SILENT.contains(&(command.as_str(), id.as_str()));
            // (a parameter's context may be refused without it: --r 0.13 beyond the face)
            let refused_without = bare.is_some() && b.code == Some(2);
            if a.code != Some(0) || !(b.code == Some(0) || refused_without) {
                failures.push(format!("{command} {with:?} / {without:?}: must both run: {} {}", a.error, b.error));
            } else if (differs(&a, &b) || refused_without) == silent {
                failures.push(format!(
                    "{command} {with:?} vs {without:?}: the output {}",
                    if silent { "changed" } else { "did not change" }
                ));
            }
            // without its context, the option changes the output or is refused
            if let Some((bare_with, bare_without)) = bare {
                let (a, b) = (run(&command, &bare_with, config), run(&command, &bare_without, config));
                let refused = a.code == Some(2) && a.error.contains(&format!("invalid {id}"));
                if !(refused || noted(&a, &id) || (a.code == Some(0) && differs(&a, &b))) {
                    failures.push(format!("{command} {bare_with:?}: silently ignored without its context"));
                }
            }
        }
    }
    // every probe is for an option that exists (a stale entry would hide a removed option)
    let table = option_table();
    for (c, o, _, _) in &probes {
        let exists = table.iter().any(|(name, opts)| (*c == "*" || name == c) && opts.iter().any(|(id, _)| id == o));
        if !exists {
            failures.push(format!("PROBES names {c} {o}, which is no option"));
        }
    }
    (probed, failures)
}

#[test]
fn config_keys_change_the_output_or_are_named_in_one_warning_or_refused() {
    let failures = in_parallel(config_keys_change_the_output_or_are_named);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The failures.
fn config_keys_change_the_output_or_are_named(runs: &Runs) -> Vec<String> {
    let run = |command: &str, args: &[String], config: &str| runs.run(command, args, config);
    let mut failures = Vec::new();
    for (command, options) in option_table() {
        if !options.iter().any(|(id, _)| id == "config") {
            continue;
        }
        let b = strings(&base(&command));
        let with_config = |extra: &[String]| -> Vec<String> {
            ["--config".to_string(), "cfg.toml".to_string()].iter().chain(extra).chain(&b).cloned().collect()
        };
        // (a config file needs a key: the default number of segments)
        let plain = run(&command, &with_config(&[]), "segments = 39\n");
        assert_eq!(plain.code, Some(0), "{command}: {}", plain.error);
        for spec in &keys::ALL {
            // a choice is used if any of its values changes the output (the command's own
            // default may not be the paper's: sweep runs modal)
            let values: Vec<String> = match spec.values {
                Values::Choice(choices) => choices.iter().map(|c| format!("\"{}\"", c.name)).collect(),
                _ => vec![sample_value(spec.key)],
            };
            let other = if spec.key == "segments" { "" } else { "segments = 39\n" };
            let (mut used, mut said, mut refused, mut seen_last) = (false, false, false, None);
            for toml_value in values {
                let seen = run(&command, &with_config(&[]), &format!("{other}{} = {toml_value}\n", spec.key));
                let named = seen.warnings.iter().filter(|w| w.contains("config file") && w.contains(spec.key)).count();
                used |= seen.code == Some(0) && differs(&seen, &plain) && named == 0;
                said |= seen.code == Some(0) && named == 1;
                // a method's option none of the impacts can honour is refused, as its flag is
                refused |= seen.code == Some(2)
                    && seen.error.contains(&format!("invalid {}", spec.key))
                    && seen.error.contains("(config file cfg.toml)")
                    && spec.role == racket_impact::params::spec::Role::MethodOption;
                seen_last = Some(seen);
            }
            let seen = seen_last.unwrap();
            if !(used || said || refused) {
                failures.push(format!(
                    "{command}: config key {} neither changes the output nor is named in one warning nor refused ({:?}, {})",
                    spec.key, seen.warnings, seen.error
                ));
            }
        }
    }
    failures
}

#[test]
fn help_lists_exactly_the_options_each_command_takes() {
    for (command, options) in option_table() {
        let o = bin().args([command.as_str(), "--help"]).output().unwrap();
        assert!(o.status.success());
        let help = String::from_utf8_lossy(&o.stdout).into_owned();
        // the option lines of clap's help: indented by 2 (`-h, --help`) or 6 (`--name`), starting
        // with -x, or --name (wrapped prose, at 0, or an option's description, at 10, may open
        // with a flag's name too)
        let listed: std::collections::BTreeSet<String> = help
            .lines()
            .filter(|l| [2, 6].contains(&(l.len() - l.trim_start().len())))
            .map(str::trim_start)
            .filter(|l| l.starts_with('-'))
            .filter_map(|l| l.split([' ', ',']).find(|w| w.starts_with("--")).map(|w| w[2..].to_string()))
            .filter(|n| n != "help")
            .collect();
        let taken: std::collections::BTreeSet<String> = options.iter().filter_map(|(_, long)| long.clone()).collect();
        assert_eq!(listed, taken, "{command} --help");
        assert!(!taken.is_empty() || command == "report", "{command}: no options found");
    }
}

/// The model selections a parameter may depend on: another solver, frame, grip or string law,
/// an oblique ball, an impact off the long axis.
const SELECTIONS: &[&[&str]] = &[
    &["--solver", "modal"],
    &["--frame", "rigid"],
    &["--grip", "hand"],
    &["--strings", "stiffening"],
    &["--angle-deg", "30"],
    &["--r", "0.03"],
];

/// The parameters of `simulate` run with the flags `args` (pairs of `--KEY VALUE`, every one a
/// parameter), as the command resolves them.
fn simulate_params(args: &[String]) -> Option<Params> {
    let mut o = Overrides::default();
    for pair in args.chunks(2) {
        o.set(pair[0].trim_start_matches("--"), pair.get(1)?).ok()?;
    }
    racket_impact::racket::resolve(None, &o).ok().map(|(p, _)| p)
}

#[test]
fn every_parameter_under_every_model_selection_does_what_its_row_says() {
    let (checked, failures) = in_parallel(every_parameter_under_every_selection);
    assert!(checked > 100, "only {checked} combinations ran");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// How many combinations ran, and the failures.
fn every_parameter_under_every_selection(runs: &Runs) -> (usize, Vec<String>) {
    // simulate takes every parameter; which impacts use one is its row's used_when, and what a
    // value it does not use is told its row's role (params/used.rs): used -> the output
    // changes; a property not exercised -> one note; a method's option not honoured -> refused
    let run = |command: &str, args: &[String], config: &str| runs.run(command, args, config);
    let mut failures = Vec::new();
    let mut checked = 0;
    for spec in &keys::ALL {
        for selection in SELECTIONS {
            if selection[0] == format!("--{}", spec.key) {
                continue;
            }
            // (the selection replaces a model the context selects, dt's --frame beam under --frame
            // rigid; a selection of the impact the context also sets is not run, --r twice)
            let context = context("simulate", spec.key);
            let selected_too = context.iter().any(|a| *a == selection[0]);
            let is_choice = keys::find(selection[0].trim_start_matches("--"))
                .is_some_and(|s| matches!(s.values, racket_impact::params::spec::Values::Choice(_)));
            if selected_too && !is_choice {
                continue;
            }
            let ctx: Vec<String> = context
                .chunks(2)
                .filter(|pair| pair[0] != selection[0])
                .flatten()
                .cloned()
                .chain(strings(selection))
                .chain(strings(&base("simulate")))
                .collect();
            let without = run("simulate", &ctx, "");
            if without.code != Some(0) {
                continue; // the selection itself is refused with this context (rigid + hand, ...)
            }
            checked += 1;
            let flag = [format!("--{}", spec.key), sample_value(spec.key)];
            let with: Vec<String> = flag.iter().cloned().chain(ctx.clone()).collect();
            let seen = run("simulate", &with, "");
            let pairs: Vec<String> =
                flag.iter().chain(ctx.iter().filter(|a| *a != "--format" && *a != "json")).cloned().collect();
            let refused = seen.code == Some(2) && seen.error.contains(&format!("invalid {}", spec.key));
            let ok = match simulate_params(&pairs).as_ref().map(|p| used::unused(spec, p)) {
                Some(Some(unused)) if unused.refused => refused && seen.error.contains(&unused.why),
                Some(Some(unused)) => noted(&seen, spec.key) && seen.warnings.iter().any(|w| w.contains(&unused.why)),
                // used: the output changes, or the value is one the selection cannot take
                // (refused naming another field: rigid with a spinning ball)
                Some(None) => (seen.code == Some(0) && differs(&seen, &without)) || seen.code == Some(2),
                None => seen.code == Some(2),
            };
            if !ok {
                failures.push(format!(
                    "simulate {with:?}: not as its row says ({:?}, {}, {:?})",
                    simulate_params(&pairs).map(|p| used::unused(spec, &p)),
                    seen.error,
                    seen.warnings
                ));
            }
        }
    }
    (checked, failures)
}

#[test]
fn every_parameter_flag_is_under_its_declared_heading_and_says_when_it_is_used() {
    // the help is derived from the rows (params/keys.rs): each flag under its row's heading,
    // and, where not every impact uses it, the row's used_when in words
    let mut cmd = cli::Cli::command();
    cmd.build();
    let mut checked = 0;
    for command in cmd.get_subcommands() {
        for arg in command.get_arguments() {
            let Some(spec) = keys::find(arg.get_id().as_str()) else { continue };
            let at = format!("{} --{}", command.get_name(), spec.key);
            assert_eq!(arg.get_help_heading(), Some(spec.heading.title()), "{at}");
            let help = arg.get_help().map(ToString::to_string).unwrap_or_default();
            assert!(help.starts_with(spec.help()), "{at}: {help}");
            let said = help.rsplit_once(" [used only ").map(|(_, w)| w.trim_end_matches(']'));
            // (modes runs no impact: its parameters are the free racket's, always used)
            let impacts = command.get_name() != cli::overrides::ModesKeys::COMMAND;
            match spec.used_when {
                _ if !impacts => assert_eq!(said, None, "{at}: {help}"),
                UsedWhen::Always => assert_eq!(said, None, "{at}: {help}"),
                when => assert_eq!(said, Some(used::words(&when).as_str()), "{at}: {help}"),
            }
            checked += 1;
        }
    }
    assert!(checked > 100, "only {checked} parameter flags");
}

#[test]
fn every_parameter_flag_is_printed_under_its_declared_heading() {
    // the help as clap prints it: each `--KEY <KEY>` line in the section its row names, and the
    // sections in the order of Heading::ALL
    let mut cmd = cli::Cli::command();
    cmd.build();
    let mut checked = 0;
    for command in cmd.get_subcommands_mut() {
        let help = command.render_help().to_string();
        let mut section = "";
        let mut order: Vec<&str> = Vec::new();
        for line in help.lines() {
            if !line.starts_with(' ') && line.ends_with(':') {
                section = line.trim_end_matches(':');
                order.push(section);
                continue;
            }
            let Some(flag) = line.trim_start().strip_prefix("--") else { continue };
            let Some(spec) = keys::find(flag.split([' ', '=']).next().unwrap_or_default()) else { continue };
            assert_eq!(section, spec.heading.title(), "{} --{}:\n{help}", command.get_name(), spec.key);
            checked += 1;
        }
        let headings: Vec<&str> =
            order.iter().copied().filter(|o| Heading::ALL.iter().any(|h| h.title() == *o)).collect();
        let expected: Vec<&str> = Heading::ALL.iter().map(|h| h.title()).filter(|t| headings.contains(t)).collect();
        assert_eq!(headings, expected, "{}", command.get_name());
    }
    assert!(checked > 100, "only {checked} parameter flags printed");
}
