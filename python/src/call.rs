//! The library's commands as Python calls them: [`call`] runs one command of the layer
//! ([`racket_impact::command`]) under [`drive`] (on the library's threads, while the calling
//! thread watches for Ctrl-C, tells the progress and warns of the notes), [`commands`] lists
//! every command's options, and [`pythonic`] puts a message of the library in Python's words.

use pyo3::exceptions::{PySystemError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};

use racket_impact::params::keys;

use crate::columns::{columns_py, sweep, sweep_pairs, table_py, Column};
use crate::{arg, fail, json_text, sources};

/// A message of the library in Python's words: a flag `--angle-deg` is the keyword `angle_deg`
/// (a switch `--long` is `long=True`), and the parameter or option a message names
/// (`invalid angle-deg = 95: ... 0 <= angle-deg <= 85 deg`) is named by its keyword.
pub(crate) fn pythonic(message: &str) -> String {
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

/// `commands()`: every command on the layer with its options and the parameters it does not
/// take, as JSON: `{command: {"options": [{name, keyword, kind, lo, hi, choices, many, default,
/// required, help}], "not_taken": {key: why}}}`.
pub(crate) fn commands() -> PyResult<String> {
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
                        "choices": choices, "many": o.many != Many::One, "default": o.default,
                        "required": o.required, "help": o.help,
                    })
                })
                .collect();
            let not_taken: serde_json::Map<String, serde_json::Value> = keys::ALL
                .iter()
                .filter_map(|s| (d.not_taken)(s.key).map(|why| (s.key.to_string(), why.into())))
                .collect();
            (d.name.to_string(), serde_json::json!({"options": options, "not_taken": not_taken}))
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
pub(crate) fn drive<T: Send + 'static>(
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
pub(crate) fn given(
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
pub(crate) fn call(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
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
        "map" => {
            let sources = sources(args, 3, (racket, config), "map")?;
            let done =
                drive(py, reporter, move |ctl| execute(racket_impact::command::map::Map::new(&sources, &given)?, ctl))?;
            let map = &done.map;
            let diagnostics =
                serde_json::to_value(&done.diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
            let grid = (
                Column::Numbers(map.grid.xs.clone()).into_py(py)?,
                Column::Numbers(map.grid.rs.clone()).into_py(py)?,
                Column::Numbers(map.heatmap.z.clone()).into_py(py)?,
            );
            let out = (json_text(&map.metadata)?, table_py(py, &map.table)?, grid, json_text(&diagnostics)?);
            Ok(out.into_pyobject(py)?.into_any().unbind())
        }
        "uncertainty" => {
            use racket_impact::command::uncertainty::{Uncertain, Uncertainty};
            use racket_impact::experiments::robustness;
            let sources = sources(args, 3, (racket, config), "uncertainty")?;
            let done = drive(py, reporter, move |ctl| execute(Uncertainty::new(&sources, &given)?, ctl))?;
            match done {
                Uncertain::Fields { study, outputs, .. } => {
                    let doc = json_text(&study.json(&outputs))?;
                    Ok((doc, None::<Py<PyAny>>, "[]").into_pyobject(py)?.into_any().unbind())
                }
                Uncertain::Claims { rows, samples, seed, diagnostics } => {
                    let doc = json_text(&robustness::json(&rows, samples, seed).map_err(fail)?)?;
                    let table = table_py(py, &robustness::table(&rows).map_err(fail)?)?;
                    let diagnostics =
                        serde_json::to_string(&diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
                    Ok((doc, Some(table), diagnostics).into_pyobject(py)?.into_any().unbind())
                }
            }
        }
        "speed" => {
            use racket_impact::command::speed::Speed;
            let sources = sources(args, 3, (racket, config), "speed")?;
            let done = drive(py, reporter, move |ctl| execute(Speed::new(&sources, &given)?, ctl))?;
            let table = table_py(py, &done.table().map_err(fail)?)?;
            let diagnostics =
                serde_json::to_string(&done.diagnostics()).map_err(|e| PyValueError::new_err(e.to_string()))?;
            Ok((table, done.json().map_err(fail)?, diagnostics).into_pyobject(py)?.into_any().unbind())
        }
        "modes" => {
            use racket_impact::command::modes::Modes;
            let sources = sources(args, 3, (racket, config), "modes")?;
            let done = drive(py, reporter, move |ctl| execute(Modes::new(&sources, &given)?, ctl))?;
            Ok(json_text(&done.json().map_err(fail)?)?.into_pyobject(py)?.into_any().unbind())
        }
        "calibrate" => {
            use racket_impact::command::calibrate::Calibrate;
            use racket_impact::study::calibrate::write;
            let sources = sources(args, 3, (racket, config), "calibrate")?;
            let done = drive(py, reporter, move |ctl| execute(Calibrate::new(&sources, &given)?, ctl))?;
            let doc = json_text(&write::json(&done.outcome, &done.source, done.weights))?;
            let diagnostics =
                serde_json::to_string(&done.diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
            Ok((doc, diagnostics).into_pyobject(py)?.into_any().unbind())
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
