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

/// A library error as the `ValueError` the command line's message becomes.
fn fail(e: racket_impact::Error) -> PyErr {
    PyValueError::new_err(e.to_string())
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

/// Where an impact's parameters come from, as a command's flags would give them.
fn sources(args: &Bound<'_, PyTuple>, command: &'static str) -> PyResult<Sources> {
    let racket: Option<String> = arg(args, 0)?;
    let config: Option<String> = arg(args, 1)?;
    let pairs: Vec<(String, String)> = arg(args, 2)?;
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

/// `simulate(racket, config, pairs)`: the JSON document of `simulate --format json`.
fn simulate(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<String> {
    let sources = sources(args, "simulate")?;
    let doc = py.detach(|| racket_impact::study::impact::Single::run(&sources).and_then(|s| s.json())).map_err(fail)?;
    json_text(&doc)
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
            .map(|c| racket_impact::numfmt::exact(f64::from_le_bytes(c.try_into().unwrap_or_default())))
            .collect();
        return Ok(values.join(","));
    }
    let list: Vec<String> = value.extract()?;
    Ok(list.join(","))
}

/// `sweep(racket, config, axes)`: every impact of the cartesian product of `axes` (`(name,
/// values)` each, in order, first slowest), as the `sweep` command runs them; returns the
/// columns (the CSV's names) and the diagnostics' JSON.
fn sweep(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<(Py<PyAny>, String)> {
    use racket_impact::study::sweep::{self, Sweep};
    let racket: Option<String> = arg(args, 0)?;
    let config: Option<String> = arg(args, 1)?;
    let axes: Vec<(String, Bound<'_, PyAny>)> = arg(args, 2)?;
    let mut pairs = Vec::with_capacity(2 * axes.len());
    for (name, value) in &axes {
        // (a name Python spells with underscores, as its key)
        let key = keys::find_any(name).map_or(name.as_str(), |s| s.key);
        pairs.push(format!("--{key}"));
        pairs.push(axis_spec(value)?);
    }
    let config = config.map(std::path::PathBuf::from);
    // a signal (Ctrl-C in a notebook) stops the sweep after the chunk it arrives in
    let mut interrupted: Option<PyErr> = None;
    let run = || -> racket_impact::Result<(Vec<String>, Vec<Column>, Vec<racket_impact::diagnostic::Diagnostic>)> {
        let sweep = Sweep::from_pairs(racket.as_deref(), config.as_deref(), &pairs)?;
        let representatives = sweep.representatives()?;
        let noted = sweep.check_used(&representatives, config.as_deref())?;
        let header = sweep.header();
        let mut columns: Vec<Column> = Vec::new();
        sweep.run_rows(
            |cells| cells,
            |rows| {
                for row in rows {
                    if columns.is_empty() {
                        columns = row.iter().enumerate().map(|(k, c)| new_column(&sweep, k, c)).collect();
                    }
                    for (column, cell) in columns.iter_mut().zip(row) {
                        push(column, cell);
                    }
                }
                if let Err(e) = Python::attach(|py| py.check_signals()) {
                    interrupted = Some(e);
                    return Err(racket_impact::Error::invalid("sweep", "(interrupted)", "stopped by a signal"));
                }
                Ok(())
            },
            |_| {},
        )?;
        let theta = header.iter().position(|c| c == "theta_end_deg").and_then(|k| match &columns[k] {
            Column::Numbers(v) => {
                v.iter().copied().filter(|x| x.is_finite()).max_by(|a, b| a.abs().total_cmp(&b.abs()))
            }
            _ => None,
        });
        let diagnostics = sweep::diagnostics(&noted, &representatives, theta.unwrap_or(0.0));
        Ok((header, columns, diagnostics))
    };
    let outcome = py.detach(run);
    if let Some(e) = interrupted {
        return Err(e);
    }
    let (header, columns, diagnostics) = outcome.map_err(fail)?;
    let diagnostics = serde_json::to_value(&diagnostics).map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok((columns_py(py, header, columns)?, json_text(&diagnostics)?))
}

/// The column of the sweep's `k`-th cell, `first` its first row's: a swept value is a number,
/// a whole number or a name as its parameter is declared.
fn new_column(sweep: &racket_impact::study::sweep::Sweep, k: usize, first: &Cell<'_>) -> Column {
    match first {
        Cell::Given(_) => match sweep.axes.get(k).and_then(|a| keys::find(&a.key)).map(|s| s.values) {
            Some(Values::Number) => Column::Numbers(Vec::new()),
            Some(Values::Count) => Column::Counts(Vec::new()),
            _ => Column::Names(Vec::new()),
        },
        Cell::Number(_) => Column::Numbers(Vec::new()),
        Cell::Flag(_) => Column::Flags(Vec::new()),
        Cell::Name(_) => Column::Names(Vec::new()),
    }
}

/// Append a cell to its column (a swept value read as its flag reads it: it was checked when
/// the sweep was made).
fn push(column: &mut Column, cell: &Cell<'_>) {
    match (column, *cell) {
        (Column::Numbers(v), Cell::Number(x)) => v.push(x),
        (Column::Numbers(v), Cell::Given(t)) => {
            v.push(racket_impact::params::number::parse_number(t).unwrap_or(f64::NAN))
        }
        (Column::Counts(v), Cell::Given(t)) => v.push(t.trim().parse().unwrap_or(-1)),
        (Column::Flags(v), Cell::Flag(f)) => v.push(u8::from(f)),
        (Column::Names(v), c) => v.push(c.text()),
        (Column::Numbers(v), _) => v.push(f64::NAN),
        (Column::Counts(v), _) => v.push(-1),
        (Column::Flags(v), _) => v.push(0),
    }
}

/// `face_map(racket, config, pairs, quantity, nx, nr, compare_racket, compare_tension_lb)`:
/// the map `map` computes, without its files: (metadata JSON, table, (x, r, values), diagnostics
/// JSON).
fn face_map(py: Python<'_>, args: &Bound<'_, PyTuple>) -> PyResult<Py<PyAny>> {
    use racket_impact::study::map::{MapRequest, Quantity, MAP_SETS};
    let mut sources = sources(args, "map")?;
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
    let run = || -> racket_impact::Result<_> {
        request.check()?;
        let (configs, _) = request.configurations()?;
        let noted = request.check_used(&configs)?;
        let map = request.run(&configs, &mut |_| {})?;
        let diagnostics: Vec<_> = noted.into_iter().chain(map.diagnostics(configs.iter().map(|(_, p)| p))).collect();
        Ok((map, diagnostics))
    };
    let (map, diagnostics) = py.detach(run).map_err(fail)?;
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
    let sources = sources(args, "uncertainty")?;
    let vary: Vec<String> = arg(args, 3)?;
    let samples: Option<u64> = arg(args, 4)?;
    let seed: Option<u32> = arg(args, 5)?;
    let run = || -> racket_impact::Result<serde_json::Value> {
        let study = Study::from_sources(&sources, &vary, samples.unwrap_or(DEFAULT_SAMPLES), seed.unwrap_or(0))?;
        let outputs = study.run(|_| {})?;
        Ok(study.json(&outputs))
    };
    json_text(&py.detach(run).map_err(fail)?)
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
    let run = || -> racket_impact::Result<Table> {
        let e = find(&id)?;
        let ctx = match &racket {
            Some(r) => Context::for_racket(r)?,
            None => Context::paper(),
        };
        (e.run)(&ctx)
    };
    let table = py.detach(run).map_err(fail)?;
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
    add(m, c"simulate", c"simulate(racket, config, pairs) -> simulate's JSON", simulate)?;
    add(m, c"sweep", c"sweep(racket, config, axes) -> (columns, diagnostics JSON)", sweep)?;
    add(m, c"face_map", c"face_map(racket, config, pairs, quantity, nx, nr, compare_racket, tensions)", face_map)?;
    add(m, c"uncertainty", c"uncertainty(racket, config, pairs, vary, samples, seed) -> JSON", uncertainty)?;
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
