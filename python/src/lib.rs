//! `racket_impact._native`: the library as the Python package `racket_impact` calls it.
//!
//! The binding is thin on purpose: every value is read, checked and refused by the library (a
//! parameter is set from its text through the same setter as its command-line flag, so a bad
//! value gets the command line's one-line message, raised as `ValueError`), every diagnostic
//! comes from the library and is returned as data (`racket_impact` turns each into a Python
//! warning), and the parameters' names, units, ranges and defaults are read off the one
//! declaration (`params::keys::ALL`). Documents are handed over as the JSON the commands print;
//! columns of numbers as little-endian bytes (`numpy.frombuffer`), so no per-impact Python
//! object is made. The work runs with the Python thread state detached (the GIL released) and,
//! for sweeps, maps and studies, on all cores as on the command line.
//!
//! No `#[pymodule]` / `#[pyfunction]`: PyO3's macros switch on two features of `syn` that the
//! library's own derive macros (serde, clap, thiserror) do not use, and cargo's feature
//! unification would then compile `syn`, those macros and so the whole library a second time
//! for this crate (about two minutes on two cores) instead of reusing the release build's. The
//! functions are closures ([`PyCFunction::new_closure`]) added to a module created by hand
//! ([`PyInit__native`]).

use std::ffi::CStr;

use pyo3::exceptions::{PySystemError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes, PyCFunction, PyList, PyString, PyTuple};
use pyo3::BoundObject;

use racket_impact::intake::Sources;
use racket_impact::params::spec::Values;
use racket_impact::params::{keys, Overrides};
use racket_impact::render::table::{Table, Value};
use racket_impact::study::sweep::Cell;

/// A library error as the `ValueError` the command line's message becomes, in Python's words
/// ([`pythonic`]).
fn fail(e: racket_impact::Error) -> PyErr {
    PyValueError::new_err(pythonic(&e.to_string()))
}

/// A message of the library in Python's words: a flag `--angle-deg` is the keyword `angle_deg`
/// (a switch `--long` is `long=True`), and the parameter or option a message names
/// (`invalid angle-deg = 95: ... 0 <= angle-deg <= 85 deg`) is named by its keyword.
fn pythonic(message: &str) -> String {
    use racket_impact::command::{Kind, ALL};
    // every name a message can spell with dashes: the parameters' keys and the options' names
    let keyword = |name: &str| -> Option<(String, bool)> {
        if let Some(spec) = keys::find(name) {
            return Some((spec.name.to_string(), false));
        }
        ALL.iter()
            .flat_map(|d| d.options.iter())
            .find(|o| o.name == name)
            .map(|o| (o.keyword(), o.kind == Kind::Switch))
    };
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while !rest.is_empty() {
        let word_len = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_')).unwrap_or(rest.len());
        if word_len == 0 {
            let c = rest.chars().next().unwrap_or(' ');
            out.push(c);
            rest = &rest[c.len_utf8()..];
            continue;
        }
        let word = &rest[..word_len];
        rest = &rest[word_len..];
        let (dashes, name) = match word.strip_prefix("--") {
            Some(name) => (true, name),
            None => (false, word),
        };
        match keyword(name) {
            Some((kw, switch)) if dashes => out.push_str(&if switch { format!("{kw}=True") } else { kw }),
            // (a bare key with a dash is a name too; one without, `ks`, reads the same)
            Some((kw, _)) if name.contains('-') => out.push_str(&kw),
            _ => out.push_str(word),
        }
    }
    out
}

/// JSON as text (the library's layout: what the commands print).
fn json_text(v: &serde_json::Value) -> PyResult<String> {
    racket_impact::render::json::pretty(v).map_err(fail)
}

/// Positional argument `i`.
fn arg<'py, T: for<'a> FromPyObject<'a, 'py>>(args: &Bound<'py, PyTuple>, i: usize) -> PyResult<T> {
    args.get_item(i)?.extract::<T>().map_err(Into::into)
}

/// The parameter flags `(name, text)`: each name a parameter's key or one of its aliases (the
/// key with underscores, as Python spells it; its CSV column), each value its text as on the
/// command line. A parameter given twice (under two of its names) is refused.
fn overrides(pairs: &[(String, String)]) -> racket_impact::Result<Overrides> {
    let mut flags = Overrides::default();
    for (name, text) in pairs {
        let spec = keys::find_any(name).ok_or_else(|| {
            racket_impact::Error::invalid(
                "parameter",
                name,
                format!("unknown parameter (known: {})", Overrides::KEYS.join(", ")),
            )
        })?;
        if flags.given().contains(&spec.key) {
            return Err(racket_impact::Error::invalid(spec.key, text, "is given twice (under two of its names)"));
        }
        flags.set(spec.key, text)?;
    }
    Ok(flags)
}

/// Where an impact's parameters come from, as a command's flags would give them: the racket,
/// the config file and the parameters `(name, text)` at argument `at` of `args`.
fn sources(
    args: &Bound<'_, PyTuple>,
    at: usize,
    (racket, config): (Option<String>, Option<String>),
    command: &'static str,
) -> PyResult<Sources> {
    let pairs: Vec<(String, String)> = arg(args, at)?;
    Ok(Sources {
        racket,
        config: config.map(Into::into),
        flags: overrides(&pairs).map_err(fail)?,
        command,
        not_taken: Vec::new(),
        set_by_options: Vec::new(),
    })
}

/// The defaults every impact command starts from: the paper's racket hit at the centre of its
/// strings (the command line's defaults).
fn defaults() -> racket_impact::Params {
    racket_impact::racket::resolve(None, &Overrides::default()).map(|(p, _)| p).unwrap_or_default()
}

/// The declaration of every parameter, as JSON: key (the flag), name (the identifier, the
/// Python keyword), help, what it is, unit, CSV column, help heading, role (property or method
/// option), when an impact uses it (in words), kind (number, count, choice) with the choices,
/// the allowed range (as numbers where it is one, and in words), the usual range, the default
/// as the flag spells it with how it is chosen, and the declared uncertainty.
fn parameters() -> PyResult<String> {
    use racket_impact::params::spec::{Check, Role};
    let defaults = defaults();
    let rows: Vec<serde_json::Value> = keys::ALL
        .iter()
        .map(|s| {
            let (kind, choices) = match s.values {
                Values::Number => ("number", vec![]),
                Values::Count => ("count", vec![]),
                Values::Choice(c) => {
                    ("choice", c.iter().map(|c| serde_json::json!({"name": c.name, "help": c.help})).collect())
                }
            };
            let range = match s.check {
                Check::Within(lo, hi) => serde_json::json!([lo, hi]),
                _ => serde_json::Value::Null,
            };
            serde_json::json!({
                "key": s.key,
                "name": s.name,
                "help": s.help(),
                "what": s.what,
                "unit": s.unit,
                "column": s.column,
                "heading": s.heading.title(),
                "role": match s.role { Role::Property => "property", Role::MethodOption => "method option" },
                "used_when": racket_impact::params::used::words(&s.used_when),
                "kind": kind,
                "choices": choices,
                "range": range,
                "range_text": s.range_text(),
                "usual": s.usual.map(|(lo, hi)| [lo, hi]),
                "default": keys::value_text(s.key, &defaults),
                "default_words": s.default_words,
                "uncertainty": s.uncertainty.map(|u| serde_json::json!({
                    "dist": u.dist.text(), "nominal": u.nominal, "source": u.source
                })),
            })
        })
        .collect();
    json_text(&serde_json::Value::Array(rows))
}

/// The parameters a map sets itself, each with why (`study::map::MAP_SETS`), as JSON pairs.
fn map_sets() -> PyResult<String> {
    let rows: Vec<(&str, &str)> = racket_impact::study::map::MAP_SETS.iter().map(|(s, why)| (s.key, *why)).collect();
    serde_json::to_string(&rows).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The result fields of one impact (`solve::outcome::FIELDS`), as JSON: key, unit, doc, flag
/// or number, and whether it is a field of an oblique or spinning ball or of a tangential law
/// with named losses.
fn result_fields() -> PyResult<String> {
    use racket_impact::solve::outcome::{Get, FIELDS};
    let rows: Vec<serde_json::Value> = FIELDS
        .iter()
        .map(|f| {
            serde_json::json!({
                "key": f.key, "unit": f.unit, "doc": f.doc.trim(),
                "kind": match f.get { Get::Number(_) => "number", Get::Flag(_) => "flag" },
                "oblique": f.is_oblique(), "law_only": f.is_law_only(), "sweep": f.sweep,
            })
        })
        .collect();
    json_text(&serde_json::Value::Array(rows))
}

/// `commands()`: every command on the layer with its options, as JSON: `{command: [{name,
/// keyword, kind, lo, hi, choices, many, default, help}]}`.
fn commands() -> PyResult<String> {
    use racket_impact::command::{Kind, Many, ALL};
    let table: serde_json::Map<String, serde_json::Value> = ALL
        .iter()
        .map(|d| {
            let options: Vec<serde_json::Value> = d
                .options
                .iter()
                .map(|o| {
                    let (kind, lo, hi, choices): (&str, Option<u64>, Option<u64>, &[&str]) = match o.kind {
                        Kind::Switch => ("switch", None, None, &[]),
                        Kind::Count { lo, hi } => ("count", Some(lo), Some(hi), &[]),
                        Kind::Number => ("number", None, None, &[]),
                        Kind::Text => ("text", None, None, &[]),
                        Kind::Choice(c) => ("choice", None, None, c),
                    };
                    serde_json::json!({
                        "name": o.name, "keyword": o.keyword(), "kind": kind, "lo": lo, "hi": hi,
                        "choices": choices, "many": o.many != Many::One, "default": o.default, "help": o.help,
                    })
                })
                .collect();
            (d.name.to_string(), serde_json::Value::Array(options))
        })
        .collect();
    json_text(&serde_json::Value::Object(table))
}

/// How long the calling thread waits for the work between two looks at its signals and its
/// progress (Ctrl-C stops a call within this and the solvers' poll, a few milliseconds).
const WATCH_EVERY: std::time::Duration = std::time::Duration::from_millis(50);

/// Run `work` on the library's thread pool under a new [`Control`] while this thread waits with
/// the GIL released, [`WATCH_EVERY`] at a time; between waits the signals are checked (Ctrl-C:
/// the control is cancelled, and once the work has stopped, which it does within milliseconds,
/// the `KeyboardInterrupt` is raised; nothing is returned, and a call writes no file) and
/// `reporter` is told the notes (`reporter.note(text)`) and the progress
/// (`reporter.update(position, total, unit, words, elapsed_s)`).
///
/// [`Control`]: racket_impact::command::Control
fn drive<T: Send + 'static>(
    py: Python<'_>,
    reporter: Option<&Bound<'_, PyAny>>,
    work: impl FnOnce(&racket_impact::command::Control) -> racket_impact::Result<T> + Send + 'static,
) -> PyResult<T> {
    use std::sync::mpsc::RecvTimeoutError;
    let ctl = racket_impact::command::Control::new();
    let (tx, rx) = std::sync::mpsc::channel();
    let watched = ctl.clone();
    rayon::spawn(move || {
        // (a panic is an error of the call, not the end of the interpreter)
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(&watched)));
        let _ = tx.send(outcome);
    });
    let tell = |ctl: &racket_impact::command::Control| -> PyResult<()> {
        let Some(r) = reporter else { return Ok(()) };
        for note in ctl.take_notes() {
            r.call_method1("note", (note,))?;
        }
        let s = ctl.status();
        r.call_method1("update", (s.position, s.total, s.unit.name(), s.words(), s.elapsed_s))?;
        Ok(())
    };
    // (the receiver goes into each wait and comes back: it is not shared between threads)
    let mut rx = rx;
    loop {
        let (got, back) = py.detach(move || (rx.recv_timeout(WATCH_EVERY), rx));
        rx = back;
        match got {
            Ok(Ok(outcome)) => {
                tell(&ctl)?;
                return outcome.map_err(fail);
            }
            Ok(Err(_)) => {
                return Err(PySystemError::new_err("racket_impact: the work panicked (a bug: please report it)"))
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PySystemError::new_err("racket_impact: the work ended without a result"))
            }
            Err(RecvTimeoutError::Timeout) => {}
        }
        if let Err(e) = py.check_signals().and_then(|()| tell(&ctl)) {
            ctl.cancel();
            // (the work stops at its next poll; nothing of it is kept)
            let _ = py.detach(move || rx.recv());
            return Err(e);
        }
    }
}

/// The options `(name, [texts])` of the command `opts` declares, as [`Given`].
///
/// [`Given`]: racket_impact::command::Given
fn given(
    opts: &'static [racket_impact::command::Opt],
    pairs: &[(String, Vec<String>)],
) -> racket_impact::Result<racket_impact::command::Given> {
    let mut given = racket_impact::command::Given::new(opts);
    for (name, texts) in pairs {
        for t in texts {
            given.set(name, t.as_str())?;
        }
    }
    Ok(given)
}

/// `call(command, racket, config, pairs, options, reporter)`: the command `command` of the
/// layer ([`racket_impact::command`]) with the parameters `pairs` and its options `options`
/// (`(keyword, [texts])`), run under [`drive`]: what each returns is in its arm below.
fn call(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
    use racket_impact::command::{execute, options_of};
    let command: String = arg(args, 0)?;
    let racket: Option<String> = arg(args, 1)?;
    let config: Option<String> = arg(args, 2)?;
    let options: Vec<(String, Vec<String>)> = arg(args, 4)?;
    let reporter: Option<Bound<'_, PyAny>> = arg(args, 5)?;
    let opts = options_of(&command).ok_or_else(|| PyValueError::new_err(format!("no command {command:?}")))?;
    let given = given(opts, &options).map_err(fail)?;
    let reporter = reporter.as_ref();
    match command.as_str() {
        "simulate" => {
            let sources = sources(args, 3, (racket, config), "simulate")?;
            let done = drive(py, reporter, move |ctl| {
                execute(racket_impact::command::simulate::Simulate::new(&sources, &given)?, ctl)
            })?;
            let doc = json_text(&done.single.json().map_err(fail)?)?;
            let series = match &done.series {
                Some(rows) => {
                    Some(table_py(py, &racket_impact::render::impact::series_table(&done.single.params, rows))?)
                }
                None => None,
            };
            Ok((doc, series).into_pyobject(py)?.into_any().unbind())
        }
        "sweep" => {
            let axes: Vec<(String, Bound<'_, PyAny>)> = arg(args, 3)?;
            let pairs = sweep_pairs(&axes)?;
            let config = config.map(std::path::PathBuf::from);
            let (header, columns, diagnostics) =
                drive(py, reporter, move |ctl| sweep(ctl, racket, config, pairs, given))?;
            let diagnostics = serde_json::to_value(&diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
            Ok((columns_py(py, header, columns)?, json_text(&diagnostics)?).into_pyobject(py)?.into_any().unbind())
        }
        "card" => {
            let sources = sources(args, 3, (racket, config), "card")?;
            let card = drive(py, reporter, move |ctl| {
                let request = racket_impact::command::card::CardCommand::new(&sources, &given)?;
                let card = execute(request, ctl)?;
                let png = racket_impact::render::plot::sheet::sheet_png("card", &card.sheet()?)?;
                Ok((card.table()?, card.header()?, card.paper_table()?, card.csv()?, png, card.diagnostics))
            })?;
            let (table, header, paper, csv, png, diagnostics) = card;
            let paper = paper.map(|t| table_py(py, &t)).transpose()?;
            let diagnostics = serde_json::to_value(&diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
            let out = (table_py(py, &table)?, header, paper, csv, PyBytes::new(py, &png), json_text(&diagnostics)?);
            Ok(out.into_pyobject(py)?.into_any().unbind())
        }
        other => Err(PyValueError::new_err(format!("no command {other:?} in this package"))),
    }
}

/// One column of numbers, ints or flags as bytes, or of names as a list.
enum Column {
    Numbers(Vec<f64>),
    Counts(Vec<i64>),
    Flags(Vec<u8>),
    Names(Vec<String>),
}

impl Column {
    fn kind(&self) -> &'static str {
        match self {
            Column::Numbers(_) => "float64",
            Column::Counts(_) => "int64",
            Column::Flags(_) => "bool",
            Column::Names(_) => "str",
        }
    }

    fn into_py(self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        Ok(match self {
            Column::Numbers(v) => {
                PyByteArray::new(py, &v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>()).into_any().unbind()
            }
            Column::Counts(v) => {
                PyByteArray::new(py, &v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>()).into_any().unbind()
            }
            Column::Flags(v) => PyByteArray::new(py, &v).into_any().unbind(),
            Column::Names(v) => PyList::new(py, v)?.into_any().unbind(),
        })
    }
}

/// Columns as `[(name, dtype, payload)]`.
fn columns_py(py: Python<'_>, names: Vec<String>, columns: Vec<Column>) -> PyResult<Py<PyAny>> {
    let items = names
        .into_iter()
        .zip(columns)
        .map(|(name, c)| {
            let kind = c.kind();
            Ok((name, kind, c.into_py(py)?))
        })
        .collect::<PyResult<Vec<_>>>()?;
    Ok(PyList::new(py, items)?.into_any().unbind())
}

/// A table's columns: numbers where every cell is one (an empty text cell among numbers is
/// NaN), whole numbers where every cell is one, else text as the CSV writes it.
fn table_columns(t: &Table) -> Vec<Column> {
    (0..t.columns.len())
        .map(|k| {
            let cells: Vec<&Value> = t.rows.iter().filter_map(|r| r.get(k)).collect();
            let blank = |v: &Value| matches!(v, Value::Text(s) if s.is_empty());
            if cells.iter().all(|v| matches!(v, Value::Int(_))) && !cells.is_empty() {
                Column::Counts(cells.iter().map(|v| if let Value::Int(i) = v { *i } else { 0 }).collect())
            } else if cells.iter().all(|v| matches!(v, Value::Num(_) | Value::Int(_)) || blank(v))
                && cells.iter().any(|v| !blank(v))
            {
                Column::Numbers(cells.iter().map(|v| v.as_f64()).collect())
            } else {
                Column::Names(cells.iter().map(|v| v.to_csv_field()).collect())
            }
        })
        .collect()
}

/// A table as `(name, [(column, dtype, payload)])`.
fn table_py(py: Python<'_>, t: &Table) -> PyResult<Py<PyAny>> {
    let columns = columns_py(py, t.columns.clone(), table_columns(t))?;
    Ok((t.name.clone(), columns).into_pyobject(py)?.into_any().unbind())
}

/// The values of one swept parameter as the sweep's `SPEC`: a spec as the command line takes
/// it (`0.1:0.3:3`, `2e4,4e4`), a list of values, or little-endian f64 bytes (a numpy array),
/// each number written in its shortest exact form.
fn axis_spec(value: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(s.to_cow()?.into_owned());
    }
    if let Ok(b) = value.cast::<PyBytes>() {
        let bytes = b.as_bytes();
        let values: Vec<String> = bytes
            .chunks_exact(8)
            .map(|c| {
                // (a value the sweep refuses, NaN or inf, as a scalar one reads: named, not empty)
                let v = f64::from_le_bytes(c.try_into().unwrap_or_default());
                if v.is_finite() {
                    racket_impact::numfmt::exact(v)
                } else {
                    v.to_string()
                }
            })
            .collect();
        return Ok(values.join(","));
    }
    let list: Vec<String> = value.extract()?;
    Ok(list.join(","))
}

/// The swept parameters `(name, values)` as the sweep's `--KEY SPEC` pairs, in order, first
/// slowest.
fn sweep_pairs(axes: &[(String, Bound<'_, PyAny>)]) -> PyResult<Vec<String>> {
    let mut pairs = Vec::with_capacity(2 * axes.len());
    for (name, value) in axes {
        // (a name Python spells with underscores, as its key)
        let key = keys::find_any(name).map_or(name.as_str(), |s| s.key);
        pairs.push(format!("--{key}"));
        pairs.push(axis_spec(value)?);
    }
    Ok(pairs)
}

/// A sweep's impacts as `sweep` runs them (`pairs`: its `--KEY SPEC` pairs), under `ctl`:
/// the columns (the CSV's names) and the diagnostics.
fn sweep(
    ctl: &racket_impact::command::Control,
    racket: Option<String>,
    config: Option<std::path::PathBuf>,
    pairs: Vec<String>,
    given: racket_impact::command::Given,
) -> racket_impact::Result<(Vec<String>, Vec<Column>, Vec<racket_impact::diagnostic::Diagnostic>)> {
    use racket_impact::command::sweep::SweepRequest;
    let request = SweepRequest::new(racket.as_deref(), config.as_deref(), &pairs, &given)?;
    let header = request.header();
    // what each swept column holds, as its parameter is declared (a number, a count, a name)
    let swept: Vec<Option<Values>> = request.sweep.axes.iter().map(|a| keys::find(&a.key).map(|s| s.values)).collect();
    let typed = move |cells: Vec<Cell<'_>>| -> Vec<Typed> {
        cells.iter().enumerate().map(|(k, c)| Typed::of(c, swept.get(k).copied().flatten())).collect()
    };
    let mut columns: Vec<Column> = Vec::new();
    let sink = |rows: &[Vec<Typed>]| -> racket_impact::Result<()> {
        for row in rows {
            if columns.is_empty() {
                columns = row.iter().map(Typed::column).collect();
            }
            for (column, cell) in columns.iter_mut().zip(row) {
                cell.push(column);
            }
        }
        Ok(())
    };
    let diagnostics = racket_impact::command::execute(request.stream(typed, sink), ctl)?.diagnostics;
    Ok((header, columns, diagnostics))
}

/// A sweep's cell as its column keeps it (made in parallel, with the rows).
enum Typed {
    Number(f64),
    Count(i64),
    Flag(bool),
    Name(String),
}

impl Typed {
    /// The cell `c`, a swept value read as its parameter `swept` is declared (a number, a
    /// whole number, a name), as its flag reads it: it was checked when the sweep was made.
    fn of(c: &Cell<'_>, swept: Option<Values>) -> Typed {
        match (*c, swept) {
            (Cell::Given(t), Some(Values::Number)) => {
                Typed::Number(racket_impact::params::number::parse_number(t).unwrap_or(f64::NAN))
            }
            (Cell::Given(t), Some(Values::Count)) => Typed::Count(t.trim().parse().unwrap_or(-1)),
            (Cell::Number(x), _) => Typed::Number(x),
            (Cell::Flag(f), _) => Typed::Flag(f),
            (c, _) => Typed::Name(c.text()),
        }
    }

    /// The column of a cell like this one.
    fn column(&self) -> Column {
        match self {
            Typed::Number(_) => Column::Numbers(Vec::new()),
            Typed::Count(_) => Column::Counts(Vec::new()),
            Typed::Flag(_) => Column::Flags(Vec::new()),
            Typed::Name(_) => Column::Names(Vec::new()),
        }
    }

    /// Append the cell to its column.
    fn push(&self, column: &mut Column) {
        match (column, self) {
            (Column::Numbers(v), Typed::Number(x)) => v.push(*x),
            (Column::Counts(v), Typed::Count(i)) => v.push(*i),
            (Column::Flags(v), Typed::Flag(f)) => v.push(u8::from(*f)),
            (Column::Names(v), Typed::Name(t)) => v.push(t.clone()),
            (Column::Numbers(v), _) => v.push(f64::NAN),
            (Column::Counts(v), _) => v.push(-1),
            (Column::Flags(v), _) => v.push(0),
            (Column::Names(v), _) => v.push(String::new()),
        }
    }
}

/// `card_files(out, csv, png)`: the card's two files, the CSV at `out` and the PNG beside it
/// (same stem), written together and atomically; with `csv` and `png` None, only checked (a
/// path the card cannot write, or an input of the run, refused before the work).
fn card_files(args: &Bound<'_, PyTuple>) -> PyResult<()> {
    let out: String = arg(args, 0)?;
    let csv: Option<String> = arg(args, 1)?;
    let png: Option<Vec<u8>> = arg(args, 2)?;
    let outputs = racket_impact::render::map_files::Outputs::for_csv_of(
        std::path::Path::new(&out),
        "the card's CSV file (its PNG goes next to it with the same stem), e.g. card.csv",
        "a card is two files (CSV and PNG with the same stem): give a file path, not a device or pipe",
    )
    .map_err(fail)?;
    if let (Some(csv), Some(png)) = (csv, png) {
        let mut staged = racket_impact::render::io::Staged::new();
        staged.bytes(&outputs.csv, csv.as_bytes()).map_err(fail)?;
        staged.bytes(&outputs.png, &png).map_err(fail)?;
        staged.commit().map_err(fail)?;
    }
    Ok(())
}

/// The parameters a card sets itself, with why (as JSON pairs).
fn card_sets() -> PyResult<String> {
    let pairs: Vec<(&str, &str)> = racket_impact::study::card::CARD_SETS.iter().map(|(s, why)| (s.key, *why)).collect();
    serde_json::to_string(&pairs).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// `face_map(racket, config, pairs, quantity, nx, nr, compare_racket, compare_tension_lb)`:
/// the map `map` computes, without its files: (metadata JSON, table, (x, r, values), diagnostics
/// JSON).
fn face_map(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
    use racket_impact::study::map::{MapRequest, Quantity, MAP_SETS};
    let mut sources = sources(args, 2, (arg(args, 0)?, arg(args, 1)?), "map")?;
    let quantity: String = arg(args, 3)?;
    let (nx, nr): (usize, usize) = (arg(args, 4)?, arg(args, 5)?);
    let compare_racket: Option<String> = arg(args, 6)?;
    let compare_tension_lb: Vec<f64> = arg(args, 7)?;
    // (the command has no flag for what the grid sets: a config file's values are noted)
    sources.not_taken = MAP_SETS.iter().map(|(s, _)| s.key).collect();
    if compare_tension_lb.len() >= 2 {
        sources.set_by_options.extend(racket_impact::intake::compare::TENSION_SETS);
    }
    let quantity: Quantity = quantity.parse().map_err(fail)?;
    let request = MapRequest { sources, quantity, nx, nr, compare_racket, compare_tension_lb };
    let run = move |ctl: &racket_impact::command::Control| -> racket_impact::Result<_> {
        request.check()?;
        let (configs, _) = request.configurations()?;
        let noted = request.check_used(&configs)?;
        let map = ctl.within(|| request.run(&configs, &mut |_| {}))?;
        let diagnostics: Vec<_> = noted.into_iter().chain(map.diagnostics(configs.iter().map(|(_, p)| p))).collect();
        Ok((map, diagnostics))
    };
    let (map, diagnostics) = drive(py, None, run)?;
    let diagnostics = serde_json::to_value(&diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let grid = (
        Column::Numbers(map.grid.xs.clone()).into_py(py)?,
        Column::Numbers(map.grid.rs.clone()).into_py(py)?,
        Column::Numbers(map.heatmap.z.clone()).into_py(py)?,
    );
    let out = (json_text(&map.metadata)?, table_py(py, &map.table)?, grid, json_text(&diagnostics)?);
    Ok(out.into_pyobject(py)?.into_any().unbind())
}

/// `uncertainty(racket, config, pairs, vary, samples, seed)`: the JSON document of
/// `uncertainty --format json`.
fn uncertainty(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<String> {
    use racket_impact::study::uncertainty::{Study, DEFAULT_SAMPLES};
    let sources = sources(args, 2, (arg(args, 0)?, arg(args, 1)?), "uncertainty")?;
    let vary: Vec<String> = arg(args, 3)?;
    let samples: Option<u64> = arg(args, 4)?;
    let seed: Option<u32> = arg(args, 5)?;
    let run = move |ctl: &racket_impact::command::Control| -> racket_impact::Result<serde_json::Value> {
        let study = Study::from_sources(&sources, &vary, samples.unwrap_or(DEFAULT_SAMPLES), seed.unwrap_or(0))?;
        let outputs = ctl.within(|| study.run(|_| {}))?;
        Ok(study.json(&outputs))
    };
    json_text(&drive(py, None, run)?)
}

/// `presets(segments)`: the presets' table (`racket --list`).
fn presets(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
    let segments: usize = arg(args, 0)?;
    let table = py.detach(|| racket_impact::racket::presets_table(segments)).map_err(fail)?;
    table_py(py, &table)
}

/// `racket(source, segments)`: a racket file or preset fitted to the model: (its name, the
/// model's racket, strings and ball as JSON, the fit table, the diagnostics' JSON).
fn racket(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
    let source: String = arg(args, 0)?;
    let segments: usize = arg(args, 1)?;
    let run = || -> racket_impact::Result<_> {
        let spec = racket_impact::racket::load(&source)?;
        let fitted = spec.to_racket(segments)?;
        let diagnostics = racket_impact::intake::diagnose::racket(&fitted, segments);
        let model = serde_json::json!({
            "racket": serde_json::to_value(fitted.racket).map_err(|e| racket_impact::Error::io("<json>", e))?,
            "strings": serde_json::to_value(fitted.strings).map_err(|e| racket_impact::Error::io("<json>", e))?,
            "ball": serde_json::to_value(fitted.ball).map_err(|e| racket_impact::Error::io("<json>", e))?,
            "diagnostics": serde_json::to_value(&diagnostics).map_err(|e| racket_impact::Error::io("<json>", e))?,
        });
        Ok((racket_impact::intake::compare::racket_label(Some(&source)), model, fitted.report.table()))
    };
    let (name, model, table) = py.detach(run).map_err(fail)?;
    let out = (name, json_text(&model)?, table_py(py, &table)?);
    Ok(out.into_pyobject(py)?.into_any().unbind())
}

/// `strings()`: the string table (data/strings), as JSON rows.
fn strings() -> PyResult<String> {
    // (serialised directly, not through a JSON value, so that the columns keep the table's order)
    serde_json::to_string(racket_impact::params::strings::all()).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// `experiments()`: every experiment's id, title and paper reference, as JSON.
fn experiments() -> PyResult<String> {
    let rows: Vec<serde_json::Value> = racket_impact::experiments::registry()
        .iter()
        .map(|e| serde_json::json!({"id": e.id, "title": e.title, "paper_ref": e.paper_ref}))
        .collect();
    json_text(&serde_json::Value::Array(rows))
}

/// `run_experiment(id, racket)`: one experiment's table, on the paper's racket or another.
fn run_experiment(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
    use racket_impact::experiments::{find, Context};
    let id: String = arg(args, 0)?;
    let racket: Option<String> = arg(args, 1)?;
    let run = move |ctl: &racket_impact::command::Control| -> racket_impact::Result<Table> {
        let e = find(&id)?;
        let ctx = match &racket {
            Some(r) => Context::for_racket(r)?,
            None => Context::paper(),
        };
        ctl.within(|| (e.run)(&ctx))
    };
    let table = drive(py, None, run)?;
    table_py(py, &table)
}

/// Add `f` to the module as `name`.
fn add<F, R>(m: &Bound<'_, PyModule>, name: &'static CStr, doc: &'static CStr, f: F) -> PyResult<()>
where
    F: Fn(Python<'_>, &Bound<'_, PyTuple>) -> PyResult<R> + Send + Sync + 'static,
    R: for<'py> IntoPyObject<'py>,
{
    let function =
        PyCFunction::new_closure(m.py(), Some(name), Some(doc), move |args, _kwargs| -> PyResult<Py<PyAny>> {
            let py = args.py();
            Ok(f(py, args)?.into_pyobject(py).map_err(Into::into)?.into_any().unbind())
        })?;
    m.add_function(function)
}

/// The module's functions.
fn module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    add(m, c"parameters", c"parameters() -> JSON of every declared parameter", |_, _| parameters())?;
    add(m, c"map_sets", c"map_sets() -> JSON [(key, why)] of what a map sets itself", |_, _| map_sets())?;
    add(m, c"result_fields", c"result_fields() -> JSON of every result field", |_, _| result_fields())?;
    add(m, c"commands", c"commands() -> JSON of every command's options", |_, _| commands())?;
    add(m, c"call", c"call(command, racket, config, pairs, options, reporter) -> the command's result", call)?;
    add(m, c"face_map", c"face_map(racket, config, pairs, quantity, nx, nr, compare_racket, tensions)", face_map)?;
    add(m, c"uncertainty", c"uncertainty(racket, config, pairs, vary, samples, seed) -> JSON", uncertainty)?;
    add(m, c"card_sets", c"card_sets() -> JSON [(key, why)] of what a card sets itself", |_, _| card_sets())?;
    add(m, c"card_files", c"card_files(out, csv, png): the card's files (None, None: checked only)", |_, a| {
        card_files(a)
    })?;
    add(m, c"presets", c"presets(segments) -> table", presets)?;
    add(m, c"racket", c"racket(source, segments) -> (name, JSON, fit table)", racket)?;
    add(m, c"strings", c"strings() -> JSON rows", |_, _| strings())?;
    add(m, c"experiments", c"experiments() -> JSON rows", |_, _| experiments())?;
    add(m, c"run_experiment", c"run_experiment(id, racket) -> table", run_experiment)?;
    Ok(())
}

/// The module's definition (single-phase initialisation; see the module doc for why by hand).
static mut MODULE_DEF: pyo3::ffi::PyModuleDef = pyo3::ffi::PyModuleDef {
    m_base: pyo3::ffi::PyModuleDef_HEAD_INIT,
    m_name: c"racket_impact._native".as_ptr(),
    m_doc: c"The racket-impact library, as the racket_impact package calls it.".as_ptr(),
    m_size: -1,
    m_methods: std::ptr::null_mut(),
    m_slots: std::ptr::null_mut(),
    m_traverse: None,
    m_clear: None,
    m_free: None,
};

/// The module's initialisation, called by the interpreter (which holds the GIL) on import.
///
/// # Safety
/// Called only by the Python interpreter, once per import, with the GIL held.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn PyInit__native() -> *mut pyo3::ffi::PyObject {
    let outcome = std::panic::catch_unwind(|| {
        // SAFETY: the interpreter calls this with the GIL held
        let py = unsafe { Python::assume_attached() };
        // SAFETY: MODULE_DEF is a valid static definition, used only here
        let raw = unsafe { pyo3::ffi::PyModule_Create(std::ptr::addr_of_mut!(MODULE_DEF)) };
        // SAFETY: a new reference, or null with the error set
        let m = unsafe { Bound::from_owned_ptr_or_err(py, raw) }?.cast_into::<PyModule>()?;
        module(&m).map(|()| m.into_ptr()).map_err(|e| (py, e)).or_else(|(py, e)| {
            e.restore(py);
            Ok::<_, PyErr>(std::ptr::null_mut())
        })
    });
    match outcome {
        Ok(Ok(ptr)) => ptr,
        Ok(Err(e)) => {
            // SAFETY: as above
            e.restore(unsafe { Python::assume_attached() });
            std::ptr::null_mut()
        }
        Err(_) => {
            // SAFETY: as above
            let py = unsafe { Python::assume_attached() };
            PySystemError::new_err("racket_impact._native panicked while loading").restore(py);
            std::ptr::null_mut()
        }
    }
}
