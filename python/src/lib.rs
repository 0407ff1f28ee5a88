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

mod call;
mod columns;

use pyo3::exceptions::{PySystemError, PyValueError};

use call::{call, commands, drive, pythonic};
use columns::table_py;
use pyo3::prelude::*;
use pyo3::types::{PyCFunction, PyTuple};
use pyo3::BoundObject;

use racket_impact::intake::Sources;
use racket_impact::params::spec::Values;
use racket_impact::params::{keys, Overrides};
use racket_impact::render::table::Table;

/// A library error as the `ValueError` the command line's message becomes, in Python's words
/// ([`pythonic`]).
pub(crate) fn fail(e: racket_impact::Error) -> PyErr {
    PyValueError::new_err(pythonic(&e.to_string()))
}

/// JSON as text (the library's layout: what the commands print).
pub(crate) fn json_text(v: &serde_json::Value) -> PyResult<String> {
    racket_impact::render::json::pretty(v).map_err(fail)
}

/// Positional argument `i`.
pub(crate) fn arg<'py, T: for<'a> FromPyObject<'a, 'py>>(args: &Bound<'py, PyTuple>, i: usize) -> PyResult<T> {
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
pub(crate) fn sources(
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
    add(m, c"result_fields", c"result_fields() -> JSON of every result field", |_, _| result_fields())?;
    add(m, c"commands", c"commands() -> JSON of every command's options", |_, _| commands())?;
    add(m, c"call", c"call(command, racket, config, pairs, options, reporter) -> the command's result", call)?;
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
