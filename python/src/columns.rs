//! Tables and sweeps as Python takes them: columns of numbers as little-endian bytes (no
//! per-impact Python object), names as lists; a sweep's axes from Python's values, and its
//! rows kept as typed columns.

use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes, PyList, PyString};

use racket_impact::params::keys;
use racket_impact::params::spec::Values;
use racket_impact::render::table::{Table, Value};
use racket_impact::study::sweep::Cell;

/// One column of numbers, ints or flags as bytes, or of names as a list.
pub(crate) enum Column {
    Numbers(Vec<f64>),
    Counts(Vec<i64>),
    Flags(Vec<u8>),
    Names(Vec<String>),
}

impl Column {
    pub(crate) fn kind(&self) -> &'static str {
        match self {
            Column::Numbers(_) => "float64",
            Column::Counts(_) => "int64",
            Column::Flags(_) => "bool",
            Column::Names(_) => "str",
        }
    }

    pub(crate) fn into_py(self, py: Python<'_>) -> PyResult<Py<PyAny>> {
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
pub(crate) fn columns_py(py: Python<'_>, names: Vec<String>, columns: Vec<Column>) -> PyResult<Py<PyAny>> {
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
pub(crate) fn table_columns(t: &Table) -> Vec<Column> {
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
pub(crate) fn table_py(py: Python<'_>, t: &Table) -> PyResult<Py<PyAny>> {
    let columns = columns_py(py, t.columns.clone(), table_columns(t))?;
    Ok((t.name.clone(), columns).into_pyobject(py)?.into_any().unbind())
}

/// The values of one swept parameter as the sweep's `SPEC`: a spec as the command line takes
/// it (`0.1:0.3:3`, `2e4,4e4`), a list of values, or little-endian f64 bytes (a numpy array),
/// each number written in its shortest exact form.
pub(crate) fn axis_spec(value: &Bound<'_, PyAny>) -> PyResult<String> {
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
pub(crate) fn sweep_pairs(axes: &[(String, Bound<'_, PyAny>)]) -> PyResult<Vec<String>> {
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
pub(crate) fn sweep(
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
