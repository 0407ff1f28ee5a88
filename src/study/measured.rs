//! Measurements in the schema of `data/measured/measurements.csv` (its README names every
//! column): the shipped table, compiled in, or a lab's own CSV with the same columns. Each row
//! carries a `role`: `calibration` rows are the only ones a constant may be fitted on (and a
//! model or law chosen on); every other row is `validation`, judged and never fitted (SPEC.md
//! section 7; the protocol that chose them is in data/measured/README.md).

use crate::numfmt::quoted;
use serde::Deserialize;

use crate::error::{Error, Result};

/// The shipped measurements, compiled in.
const SHIPPED: &str = include_str!("../../data/measured/measurements.csv");

/// Where the shipped measurements live, for the messages.
pub const SHIPPED_FILE: &str = "data/measured/measurements.csv";

/// What a measured row may be used for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// A constant that no measurement fixes may be fitted on it, and a model chosen on it.
    Calibration,
    /// Judged against the model, never fitted on.
    Validation,
}

impl Role {
    /// The name in the `role` column.
    pub fn name(self) -> &'static str {
        match self {
            Role::Calibration => "calibration",
            Role::Validation => "validation",
        }
    }

    /// The role named `text`, if it is one.
    pub fn parse(text: &str) -> Option<Role> {
        [Role::Calibration, Role::Validation].into_iter().find(|r| r.name() == text)
    }
}

/// One measured row: what was measured, its value and stated scatter, its role, and the
/// conditions of the shot (each empty where the source does not state it).
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct Measured {
    /// Row id (`M001`...).
    pub id: String,
    /// `calibration` or `validation` (absent from a lab's CSV that has no `role` column).
    #[serde(skip)]
    pub role: Option<Role>,
    /// `rigid_surface`, `normal_racket`, `oblique_racket`, `oblique_surface`, `match_play`.
    #[serde(default)]
    pub kind: String,
    /// What was measured (`spin_out_rpm`, ...).
    pub quantity: String,
    /// The value, in `unit`.
    pub value: f64,
    /// The stated (or reading) uncertainty, in `unit`.
    #[serde(default)]
    pub uncertainty: Option<f64>,
    /// Unit of `value` and `uncertainty`.
    #[serde(default)]
    pub unit: String,
    /// Incident ball speed, m/s.
    #[serde(default)]
    pub ball_speed_m_s: Option<f64>,
    /// Incidence angle from the string-plane normal, degrees.
    #[serde(default)]
    pub angle_deg: Option<f64>,
    /// Incident spin, rpm (negative = backspin).
    #[serde(default)]
    pub spin_in_rpm: Option<f64>,
    /// Impact position along the long axis from the tip, m.
    #[serde(default)]
    pub impact_x_from_tip_m: Option<f64>,
    /// Off-axis distance of the impact, m.
    #[serde(default)]
    pub impact_r_m: Option<f64>,
    /// Nominal (pull) string tension, lb.
    #[serde(rename = "string_tension_lb", default)]
    pub tension_lb: Option<f64>,
    /// The string product and material (empty if none).
    #[serde(default)]
    pub string: String,
    /// How the racket was held: `free`, `hand_held`, `clamped`, `clamped_head`,
    /// `clamped_handle`, `rigid_surface` (empty = not stated).
    #[serde(default)]
    pub support: String,
    /// The source's key in the README's reference list.
    #[serde(default)]
    pub source_key: String,
}

/// Every row of a measurements table (`file` names it in the messages), read with the `csv`
/// crate: a row that does not parse is an error naming the file, its line and the column.
pub fn parse(text: &str, file: &str) -> Result<Vec<Measured>> {
    let mut rdr = csv::Reader::from_reader(text.as_bytes());
    let headers =
        rdr.headers().map_err(|e| Error::csv_row("measurements", file, text, &csv::StringRecord::new(), &e))?.clone();
    // a column named twice would be read from one of them (or refused by the reader as a
    // "duplicate field" of no column), and a name with a space around it is another name
    // (`support ` left every row with no support): both refused, the header named
    for (i, name) in headers.iter().enumerate() {
        if let Some(j) = headers.iter().take(i).position(|earlier| earlier == name) {
            return Err(Error::invalid(
                "measurements",
                file,
                format!("column '{}' is named twice in the header (columns {} and {})", quoted(name), j + 1, i + 1),
            ));
        }
        if name != name.trim() {
            return Err(Error::invalid(
                "measurements",
                file,
                format!(
                    "column {} of the header, '{}', has a space at its start or end: name it '{}'",
                    i + 1,
                    quoted(name),
                    quoted(name.trim())
                ),
            ));
        }
    }
    for needed in ["id", "quantity", "value"] {
        if !headers.iter().any(|h| h == needed) {
            return Err(Error::invalid("measurements", file, format!("no column '{needed}' in the header")));
        }
    }
    let role_column = headers.iter().position(|h| h == "role");
    let mut out: Vec<Measured> = Vec::new();
    for record in rdr.records() {
        let record = record.map_err(|e| Error::csv_row("measurements", file, text, &headers, &e))?;
        let mut row: Measured =
            record.deserialize(Some(&headers)).map_err(|e| Error::csv_row("measurements", file, text, &headers, &e))?;
        let bad = |what: String| {
            let line = record.position().map_or(0, |at| crate::error::csv_line(text, at));
            Error::invalid("measurements", format!("{file}:{line}"), what)
        };
        if !row.value.is_finite() {
            return Err(bad(format!("column value: {} is not a finite number", row.value)));
        }
        if let Some(at) = role_column {
            let given = record.get(at).unwrap_or("");
            row.role = Some(Role::parse(given).ok_or_else(|| {
                bad(format!("column role: '{}' is neither 'calibration' nor 'validation'", quoted(given)))
            })?);
        }
        // a row is named by its id in every table, fit and plot: two rows of one id would be
        // fitted, held out and reported as one
        if let Some(first) = out.iter().position(|earlier| earlier.id == row.id) {
            return Err(bad(format!(
                "column id: '{}' is the id of row {} already; each row needs an id of its own",
                quoted(&row.id),
                first + 1
            )));
        }
        out.push(row);
    }
    Ok(out)
}

/// Every row of the shipped table.
pub fn shipped() -> Result<Vec<Measured>> {
    parse(SHIPPED, SHIPPED_FILE)
}

/// The shipped rows `ids`, in that order.
pub fn rows(ids: &[&str]) -> Result<Vec<Measured>> {
    let all = shipped()?;
    ids.iter()
        .map(|want| {
            all.iter()
                .find(|r| r.id == *want)
                .cloned()
                .ok_or_else(|| Error::invalid("measurements", want, format!("no such row in {SHIPPED_FILE}")))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_row_has_a_role_and_the_protocol_s_rows_are_calibration() {
        let all = shipped().unwrap();
        assert!(all.len() >= 84);
        assert!(all.iter().all(|r| r.role.is_some()), "a shipped row without a role");
        let calibration: Vec<&str> =
            all.iter().filter(|r| r.role == Some(Role::Calibration)).map(|r| r.id.as_str()).collect();
        // data/measured/README.md, "Calibration and validation rows": the first string of each
        // material in the TWU table, at both tensions
        assert_eq!(calibration, ["M001", "M002", "M003", "M004", "M011", "M012"]);
    }

    #[test]
    fn a_bad_measured_row_is_an_error_naming_the_file_and_line() {
        let head = SHIPPED.lines().next().unwrap();
        let good = SHIPPED.lines().nth(1).unwrap();
        let bad = good.replacen(",1642,", ",about 1642,", 1);
        let msg = parse(&format!("{head}\n{good}\n{bad}\n"), "m.csv").unwrap_err().to_string();
        assert!(msg.contains("m.csv:3") && msg.contains("value"), "{msg}");
        let nan = good.replacen(",1642,", ",NaN,", 1);
        let msg = parse(&format!("{head}\n{nan}\n"), "m.csv").unwrap_err().to_string();
        assert!(msg.contains("m.csv:2") && msg.contains("not a finite number"), "{msg}");
        let msg = parse("id,quantity\nM1,spin_out_rpm\n", "m.csv").unwrap_err().to_string();
        assert!(msg.contains("no column 'value'"), "{msg}");
        let msg = parse(&format!("{head}\n{good}\n{good}\n"), "m.csv").unwrap_err().to_string();
        assert!(msg.contains("m.csv:3") && msg.contains("M001") && msg.contains("row 1"), "{msg}");
    }

    #[test]
    fn a_bad_role_is_an_error_naming_the_column() {
        let text = "id,role,quantity,value\nM1,calibrate,spin_out_rpm,1000\n";
        let msg = parse(text, "m.csv").unwrap_err().to_string();
        assert!(msg.contains("m.csv:2") && msg.contains("role"), "{msg}");
        let lab = parse("id,quantity,value\nM1,spin_out_rpm,1000\n", "m.csv").unwrap();
        assert_eq!(lab[0].role, None);
    }
}
