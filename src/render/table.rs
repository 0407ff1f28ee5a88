//! Result tables: the single source for CSV files, plots and snapshot tests.
//!
//! An experiment produces one or more [`Table`]s of named columns. The same table is written
//! as CSV (numbers formatted deterministically with [`fmt_sig`] to [`SIG_DIGITS`] significant
//! digits), read back column by column to build plots, and compared in snapshot tests.

use crate::error::{Error, Result};
use crate::numfmt::fmt_sig;

/// The `csv` writer of every CSV the crate writes: lines end with `\n` (on every platform),
/// fields are quoted only where needed (RFC 4180), and records may differ in length.
pub fn csv_writer<W: std::io::Write>(out: W) -> csv::Writer<W> {
    csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).flexible(true).from_writer(out)
}

/// Significant digits used for floating-point numbers in CSV output.
pub const SIG_DIGITS: usize = 6;

/// One cell of a [`Table`].
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A floating-point number (written with [`fmt_sig`] to [`SIG_DIGITS`] digits).
    Num(f64),
    /// An integer (written exactly).
    Int(i64),
    /// Free text, e.g. a curve or case label (written as is, quoted when needed).
    Text(String),
}

impl Value {
    /// The value as a number: `Num` as is, `Int` converted, `Text` is NaN.
    pub fn as_f64(&self) -> f64 {
        match self {
            Value::Num(x) => *x,
            Value::Int(i) => *i as f64,
            Value::Text(_) => f64::NAN,
        }
    }

    /// The value as it appears in CSV output.
    pub fn to_csv_field(&self) -> String {
        match self {
            Value::Num(x) => fmt_sig(*x, SIG_DIGITS),
            Value::Int(i) => i.to_string(),
            Value::Text(s) => s.clone(),
        }
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Num(x)
    }
}

impl Value {
    /// A number where it is finite, else an empty field (an undefined value: a ratio over a
    /// near-zero denominator, an interval not computed).
    pub fn finite_or_empty(x: f64) -> Self {
        if x.is_finite() {
            Value::Num(x)
        } else {
            Value::Text(String::new())
        }
    }
}

impl From<i64> for Value {
    fn from(i: i64) -> Self {
        Value::Int(i)
    }
}

impl From<usize> for Value {
    /// Converts to [`Value::Int`]; values beyond `i64::MAX` (impossible in practice) become
    /// [`Value::Num`].
    fn from(u: usize) -> Self {
        match i64::try_from(u) {
            Ok(i) => Value::Int(i),
            Err(_) => Value::Num(u as f64),
        }
    }
}

impl From<&str> for Value {
    fn from(s: &str) -> Self {
        Value::Text(s.to_string())
    }
}

impl From<String> for Value {
    fn from(s: String) -> Self {
        Value::Text(s)
    }
}

/// A named table of results: column names and rows of [`Value`]s.
///
/// Every row has exactly one value per column (enforced by [`Table::push`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// Table name (used for file names such as `<name>.csv`).
    pub name: String,
    /// Column names, in order.
    pub columns: Vec<String>,
    /// Rows; each has `columns.len()` values.
    pub rows: Vec<Vec<Value>>,
}

impl Table {
    /// An empty table with the given name and column names.
    pub fn new(name: impl Into<String>, columns: &[&str]) -> Self {
        Table { name: name.into(), columns: columns.iter().map(|c| c.to_string()).collect(), rows: Vec::new() }
    }

    /// Append a row.
    ///
    /// Returns an [`Error::InvalidParameter`] (field `row`) and leaves the table unchanged if
    /// the row does not have exactly one value per column.
    pub fn push(&mut self, row: Vec<Value>) -> Result<()> {
        if row.len() != self.columns.len() {
            return Err(Error::invalid(
                "row",
                format!("{} values", row.len()),
                format!("table '{}' has {} columns ({})", self.name, self.columns.len(), self.columns.join(", ")),
            ));
        }
        self.rows.push(row);
        Ok(())
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// `true` if the table has no rows.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// Index of the column called `name`, if any.
    pub fn column_index(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|c| c == name)
    }

    /// The column called `name` as numbers (`Int` converted to `f64`, `Text` as NaN), or
    /// `None` if there is no such column. Missing cells (short rows) are NaN.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.column_index(name)?;
        Some(self.rows.iter().map(|r| r.get(i).map_or(f64::NAN, Value::as_f64)).collect())
    }

    /// The column called `name` as text (numbers formatted as in CSV output), or `None` if
    /// there is no such column. Missing cells (short rows) are empty strings.
    pub fn column_text(&self, name: &str) -> Option<Vec<String>> {
        let i = self.column_index(name)?;
        Some(self.rows.iter().map(|r| r.get(i).map_or_else(String::new, Value::to_csv_field)).collect())
    }

    /// A copy of the table keeping only the rows whose `column` is the text `value`.
    ///
    /// Used to split a long table into one curve per case. Only [`Value::Text`] cells match;
    /// an unknown column gives a table with the same columns and no rows.
    pub fn filter(&self, column: &str, value: &str) -> Table {
        let rows = match self.column_index(column) {
            Some(i) => {
                self.rows.iter().filter(|r| matches!(r.get(i), Some(Value::Text(s)) if s == value)).cloned().collect()
            }
            None => Vec::new(),
        };
        Table { name: self.name.clone(), columns: self.columns.clone(), rows }
    }

    /// Only the rows whose numeric `column` equals `value` exactly (an unknown column gives an
    /// empty table). Used to split a long table into curves, e.g. one per string stiffness.
    pub fn filter_num(&self, column: &str, value: f64) -> Table {
        let rows = match self.column_index(column) {
            Some(i) => self.rows.iter().filter(|r| r.get(i).map(Value::as_f64) == Some(value)).cloned().collect(),
            None => Vec::new(),
        };
        Table { name: self.name.clone(), columns: self.columns.clone(), rows }
    }

    /// The distinct text values of `column`, in order of first appearance (empty if the column
    /// does not exist). Handy together with [`Table::filter`].
    pub fn distinct_text(&self, column: &str) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        if let Some(i) = self.column_index(column) {
            for row in &self.rows {
                if let Some(Value::Text(s)) = row.get(i) {
                    if !out.iter().any(|o| o == s) {
                        out.push(s.clone());
                    }
                }
            }
        }
        out
    }

    /// The table as CSV text.
    ///
    /// A header line of column names, then one line per row; floats via
    /// [`fmt_sig`]`(x, `[`SIG_DIGITS`]`)`, integers exactly, text as is. Fields containing
    /// commas, quotes or line breaks are quoted (RFC 4180). Lines end with `\n`. The output is
    /// byte-for-byte deterministic.
    pub fn to_csv(&self) -> String {
        let mut wtr = csv_writer(Vec::new());
        let mut result = wtr.write_record(&self.columns);
        for row in &self.rows {
            if result.is_err() {
                break;
            }
            result = wtr.write_record(row.iter().map(Value::to_csv_field));
        }
        // Writing into a `Vec` with flexible records cannot fail; should the csv crate ever
        // report an error anyway, fall back to the equivalent hand-rolled encoder.
        match (result, wtr.into_inner()) {
            (Ok(()), Ok(bytes)) => String::from_utf8_lossy(&bytes).into_owned(),
            _ => self.to_csv_fallback(),
        }
    }

    /// Hand-rolled CSV encoder with the same output as the `csv` crate path of [`to_csv`].
    ///
    /// [`to_csv`]: Table::to_csv
    fn to_csv_fallback(&self) -> String {
        fn field(s: &str) -> String {
            if s.contains([',', '"', '\n', '\r']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s.to_string()
            }
        }
        let mut out = String::new();
        let header: Vec<String> = self.columns.iter().map(|c| field(c)).collect();
        out.push_str(&header.join(","));
        out.push('\n');
        for row in &self.rows {
            let cells: Vec<String> = row.iter().map(|v| field(&v.to_csv_field())).collect();
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_conversions() {
        assert_eq!(Value::from(1.5), Value::Num(1.5));
        assert_eq!(Value::from(-3i64), Value::Int(-3));
        assert_eq!(Value::from(7usize), Value::Int(7));
        assert_eq!(Value::from("a"), Value::Text("a".into()));
        assert_eq!(Value::from(String::from("b")), Value::Text("b".into()));
        assert_eq!(Value::Int(4).as_f64(), 4.0);
        assert!(Value::Text("x".into()).as_f64().is_nan());
    }

    fn sample() -> Table {
        let mut t = Table::new("demo", &["case", "x", "n", "y"]);
        t.push(vec!["a".into(), 0.1.into(), 1i64.into(), 1234567.0.into()]).expect("push");
        t.push(vec!["b".into(), 0.2.into(), 2i64.into(), f64::NAN.into()]).expect("push");
        t.push(vec!["a".into(), 0.30000000000000004.into(), 3i64.into(), (-0.0).into()]).expect("push");
        t
    }

    #[test]
    fn push_checks_row_length() {
        let mut t = Table::new("t", &["a", "b"]);
        let err = t.push(vec![1.0.into()]).expect_err("short row");
        let msg = err.to_string();
        assert!(msg.contains("row") && msg.contains("2 columns"), "{msg}");
        assert!(t.is_empty());
        t.push(vec![1.0.into(), 2.0.into()]).expect("ok");
        assert_eq!(t.len(), 1);
    }

    #[test]
    fn columns_by_name() {
        let t = sample();
        assert_eq!(t.column("x"), Some(vec![0.1, 0.2, 0.30000000000000004]));
        assert_eq!(t.column("n"), Some(vec![1.0, 2.0, 3.0]));
        assert!(t.column("case").expect("col").iter().all(|v| v.is_nan()));
        assert_eq!(t.column("nope"), None);
        assert_eq!(t.column_text("case"), Some(vec!["a".to_string(), "b".to_string(), "a".to_string()]));
        assert_eq!(t.column_text("x"), Some(vec!["0.1".to_string(), "0.2".to_string(), "0.3".to_string()]));
        assert_eq!(t.column_text("nope"), None);
    }

    #[test]
    fn filter_rows() {
        let t = sample();
        let a = t.filter("case", "a");
        assert_eq!(a.name, "demo");
        assert_eq!(a.columns, t.columns);
        assert_eq!(a.column("n"), Some(vec![1.0, 3.0]));
        assert!(t.filter("case", "zzz").is_empty());
        assert!(t.filter("nope", "a").is_empty());
        // Numeric cells never match text.
        assert!(t.filter("n", "1").is_empty());
        assert_eq!(t.distinct_text("case"), vec!["a".to_string(), "b".to_string()]);
    }

    #[test]
    fn csv_output() {
        let t = sample();
        assert_eq!(t.to_csv(), "case,x,n,y\na,0.1,1,1.23457e+06\nb,0.2,2,NaN\na,0.3,3,0\n");
    }

    #[test]
    fn csv_quotes_when_needed() {
        let mut t = Table::new("q", &["label, with comma", "v"]);
        t.push(vec!["say \"hi\"".into(), 1.0.into()]).expect("push");
        t.push(vec!["two\nlines".into(), 2.0.into()]).expect("push");
        let expected = "\"label, with comma\",v\n\"say \"\"hi\"\"\",1\n\"two\nlines\",2\n";
        assert_eq!(t.to_csv(), expected);
        assert_eq!(t.to_csv_fallback(), expected);
    }

    #[test]
    fn csv_empty_table_and_fallback_agree() {
        let t = Table::new("e", &["a", "b"]);
        assert_eq!(t.to_csv(), "a,b\n");
        let s = sample();
        assert_eq!(s.to_csv(), s.to_csv_fallback());
    }

    #[test]
    fn csv_round_trips_through_reader() {
        let t = sample();
        let csv = t.to_csv();
        let mut rdr = csv::Reader::from_reader(csv.as_bytes());
        let headers = rdr.headers().expect("headers").clone();
        assert_eq!(headers.iter().collect::<Vec<_>>(), vec!["case", "x", "n", "y"]);
        assert_eq!(rdr.records().count(), 3);
    }
}
