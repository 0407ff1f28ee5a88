//! `sweep`: the cartesian product of ranges or lists of any parameters, run in parallel and
//! streamed as CSV to a file (atomically) or standard output.

use std::path::PathBuf;

use clap::Args;
use racket_impact::command::sweep::SweepRequest;
use racket_impact::command::{execute, Control};
use racket_impact::params::spec::Values;
use racket_impact::params::{keys, Overrides};
use racket_impact::study::sweep::Cell;
use racket_impact::Result;

use super::common::{print_diagnostics, stream_stdout, Reporter};
use super::options::{Options, SweepOptions};

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// Racket description file (TOML, player units) or preset name; see `racket-impact racket --list`
    #[arg(long)]
    pub racket: Option<String>,
    /// TOML file with fixed values for any parameter (as for `simulate`)
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Output CSV file (written atomically: a new file replaces it, with its permissions; other
    /// hard links to the old file keep the old content); standard output if absent
    #[arg(long)]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub options: Options<SweepOptions>,
    /// The varied parameters: --KEY SPEC pairs
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, value_name = "--KEY SPEC")]
    pub specs: Vec<String>,
}

/// The long help of `sweep`: the spec syntax and every key (from the parameter declarations).
pub fn long_about() -> String {
    format!(
        "Run the cartesian product of ranges or lists of any parameters, in parallel, as CSV\n\n\
         Example: racket-impact sweep --out s.csv --x 0.02:0.60:50 --ks 2e4,4e4 --load node\n\n\
         After the options (--out, --config, --racket, --long), give any parameter as `--KEY SPEC`, where SPEC is a \
         value (0.1), a list (2e4,4e4 or node,hat), a range start:stop:count or a log range \
         start:stop:count:log.\n\n\
         Sweeps use the modal solver (~30x faster, within 2e-5 of fd at normal incidence and 1e-4 for an \
         oblique ball) unless --solver is given or a hand grip or stiffening strings need fd; the last CSV \
         column names the solver.\n\n\
         Keys, each with its default (see `simulate --help`; with --racket, the racket's):\n  {}",
        keys_with_defaults()
    )
}

/// Every key with the default a sweep uses when it is neither swept nor in the config file
/// (`x (0.16 m)`).
fn keys_with_defaults() -> String {
    let defaults = racket_impact::racket::resolve(None, &Overrides::default()).map(|(p, _)| p).unwrap_or_default();
    keys::ALL
        .iter()
        .map(|spec| {
            let value = keys::value_text(spec.key, &defaults).unwrap_or_default();
            let numeric = value.parse::<f64>().is_ok();
            let unit = if spec.unit.is_empty() || !numeric || matches!(spec.values, Values::Choice(_)) {
                ""
            } else {
                spec.unit
            };
            if spec.key == keys::SOLVER.key {
                return format!("{} (modal, see above)", spec.key);
            }
            format!("{} ({})", spec.key, format!("{value} {unit}").trim_end())
        })
        .collect::<Vec<_>>()
        .chunks(6)
        .map(|keys| keys.join(", "))
        .collect::<Vec<_>>()
        .join(",\n  ")
}

/// Run the sweep, writing the header and then each finished chunk's rows.
pub fn run(a: SweepArgs) -> Result<()> {
    // a swept option no impact can honour is refused; a swept property none exercises and a
    // config file's unused keys are noted (printed with the other diagnostics at the end)
    let request = SweepRequest::new(a.racket.as_deref(), a.config.as_deref(), &a.specs, &a.options.0)?;
    if let Some(path) = &a.out {
        racket_impact::render::io::check_output_dir("out", path)?;
    }
    let mut file = match &a.out {
        Some(path) => Some(racket_impact::render::io::AtomicFile::create(path)?),
        None => None,
    };
    let mut emit = |bytes: &[u8]| -> Result<()> {
        match file.as_mut() {
            Some(f) => f.write(bytes),
            None => stream_stdout(bytes),
        }
    };
    // (the header with the first rows: a run refused for its length writes nothing)
    let mut header = Some(request.header());
    let sink = |rows: &[Vec<String>]| {
        if let Some(h) = header.take() {
            emit(&csv_lines(&[h]))?;
        }
        emit(&csv_lines(rows))
    };
    let ctl = Control::new();
    let reporter = Reporter::start(&ctl);
    let swept = execute(request.stream(|cells| cells.iter().map(Cell::text).collect(), sink), &ctl);
    drop(reporter);
    // (on error the temporary file is dropped, the target untouched)
    let diagnostics = swept.map(|s| s.diagnostics)?;
    if let Some(f) = file {
        f.commit()?;
    }
    print_diagnostics(&diagnostics);
    Ok(())
}

/// CSV lines (fields quoted only where needed): a row of two or more fields none of which
/// needs quoting (no comma, quote or line break: every row of numbers) joined as it is, any
/// other through the `csv` writer, which writes the same bytes for the first kind (the sink of
/// a sweep runs on one thread, so this is most of what a sweep does not do in parallel).
fn csv_lines(rows: &[Vec<String>]) -> Vec<u8> {
    let plain = |f: &String| !f.bytes().any(|b| matches!(b, b',' | b'"' | b'\r' | b'\n'));
    let mut out = Vec::with_capacity(rows.iter().map(|r| r.iter().map(|f| f.len() + 1).sum::<usize>()).sum());
    for r in rows {
        if r.len() >= 2 && r.iter().all(plain) {
            for (i, f) in r.iter().enumerate() {
                if i > 0 {
                    out.push(b',');
                }
                out.extend_from_slice(f.as_bytes());
            }
            out.push(b'\n');
        } else {
            let mut w = racket_impact::render::table::csv_writer(out);
            let _ = w.write_record(r);
            out = w.into_inner().unwrap_or_default();
        }
    }
    out
}

#[cfg(test)]
mod tests {
    /// Rows joined as they are and rows that need the `csv` writer's quoting: the bytes the
    /// writer gives for all of them.
    #[test]
    fn csv_lines_are_the_csv_writers() {
        let rows: Vec<Vec<String>> = [
            vec!["x_m", "r_m", "e_a"],
            vec!["0.02", "0", "1.5e-7"],
            vec!["a,b", "c"],
            vec!["say \"hi\"", "2"],
            vec!["two\nlines", "x\ry"],
            vec![""],
            vec!["only"],
            vec!["", ""],
            vec![],
            vec!["node", "modal", "-0.25"],
        ]
        .iter()
        .map(|r| r.iter().map(|f| f.to_string()).collect())
        .collect();
        // (rows of every length here: the sweep's are all as long as its header)
        let mut w = racket_impact::render::table::csv_writer(Vec::new());
        for r in &rows {
            w.write_record(r).unwrap();
        }
        let expected = w.into_inner().unwrap();
        assert_eq!(String::from_utf8(super::csv_lines(&rows)).unwrap(), String::from_utf8(expected).unwrap());
    }
}
