//! The uncertainty study's outputs: its JSON document, CSV table and text table, and the
//! summary JSON of one output that `uncertainty --claims` shares. The study itself (its plan,
//! its runs and its diagnostics) is [`super`].

use serde_json::{json, Map, Value};

use super::{Output, Study, MIN_SAMPLES};
use crate::numfmt::{exact_finite, sig};
use crate::params::keys;
use crate::study::sensitivity::{self, Summary};

/// The line a text output opens with at `samples` base samples below [`MIN_SAMPLES`] (none at
/// or above it), ending in a newline.
pub fn not_meaningful(samples: u64) -> Option<String> {
    (samples < MIN_SAMPLES).then(|| {
        format!(
            "NOT MEANINGFUL at {samples} base samples (fewer than {MIN_SAMPLES}): q05/q95 rest on a few runs and the \
             indices' sampling error, of order 1/sqrt(N), is as large as the indices, so the figures below mean nothing\n"
        )
    })
}

/// One output's summary as JSON: mean, sd, q05, q50, q95 and, keyed by input, `first_order`,
/// `total_order`, `first_order_ci` and `total_order_ci` (`[lo, hi]`); an index of an output
/// that does not vary is null.
pub fn summary_json(s: &Summary, inputs: &[&str]) -> Value {
    let per_input = |f: &dyn Fn(usize) -> Value| -> Value {
        Value::Object(inputs.iter().enumerate().map(|(k, key)| (key.to_string(), f(k))).collect())
    };
    json!({
        "mean": s.mean, "sd": s.sd, "q05": s.q05, "q50": s.q50, "q95": s.q95,
        "first_order": per_input(&|k| json!(s.first[k].value)),
        "total_order": per_input(&|k| json!(s.total[k].value)),
        "first_order_ci": per_input(&|k| json!([s.first[k].lo, s.first[k].hi])),
        "total_order_ci": per_input(&|k| json!([s.total[k].lo, s.total[k].hi])),
    })
}

impl Study {
    /// The JSON document: `{"samples", "seed", "inputs": [...], "outputs": {field: {...}}}`
    /// (an index of an output that does not vary is null).
    pub fn json(&self, outputs: &[Output]) -> Value {
        let inputs: Vec<Value> = self
            .inputs
            .iter()
            .map(|i| json!({"key": i.key, "dist": i.dist.text(), "column": keys::find(i.key).map(|s| s.column)}))
            .collect();
        let keys: Vec<&str> = self.inputs.iter().map(|i| i.key).collect();
        let mut out = Map::new();
        for o in outputs {
            let mut v = summary_json(&o.summary, &keys);
            v["unit"] = o.unit.into();
            out.insert(o.key.to_string(), v);
        }
        json!({
            "samples": self.design.samples(),
            "seed": self.design.seed(),
            "runs": self.design.runs(),
            "solver": self.base.numerics.solver.name(),
            "params": serde_json::to_value(self.base).unwrap_or_default(),
            "confidence": sensitivity::CONFIDENCE,
            "inputs": inputs,
            "outputs": out,
            "diagnostics": serde_json::to_value(self.diagnostics()).unwrap_or_default(),
        })
    }

    /// The CSV table: one row per output; per input `first_KEY`, `first_KEY_lo`,
    /// `first_KEY_hi`, `total_KEY`, `total_KEY_lo`, `total_KEY_hi` (empty where undefined;
    /// KEY with underscores, `first_angle_deg`, as the other CSVs spell a column).
    pub fn csv(&self, outputs: &[Output]) -> String {
        let mut head = vec!["output".to_string(), "unit".into()];
        head.extend(["mean", "sd", "q05", "q50", "q95"].map(String::from));
        for i in &self.inputs {
            for kind in ["first", "total"] {
                for end in ["", "_lo", "_hi"] {
                    // (the key as the JSON and config files spell it: angle_deg, not angle-deg)
                    head.push(format!("{kind}_{}{end}", i.key.replace('-', "_")));
                }
            }
        }
        let mut w = crate::render::table::csv_writer(Vec::new());
        let _ = w.write_record(&head);
        for o in outputs {
            let s = &o.summary;
            let mut row = vec![o.key.to_string(), o.unit.to_string()];
            row.extend([s.mean, s.sd, s.q05, s.q50, s.q95].map(exact_finite));
            for k in 0..self.inputs.len() {
                for ix in [s.first[k], s.total[k]] {
                    row.extend([ix.value, ix.lo, ix.hi].map(exact_finite));
                }
            }
            let _ = w.write_record(&row);
        }
        String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
    }

    /// A text table: each output's spread, then each input's indices with their intervals.
    pub fn text(&self, outputs: &[Output]) -> String {
        let inputs: Vec<String> = self.inputs.iter().map(|i| format!("{} ~ {}", i.key, i.dist.text())).collect();
        let mut s = format!(
            "{} base samples x {} = {} impacts ({} solver), seed {}; inputs: {}\nSobol' indices: first-order S and total ST, [{} % bootstrap interval]\n\n",
            self.design.samples(),
            self.design.inputs() + 2,
            self.design.runs(),
            self.base.numerics.solver.name(),
            self.design.seed(),
            inputs.join(", "),
            100.0 * sensitivity::CONFIDENCE
        );
        if let Some(line) = not_meaningful(self.design.samples() as u64) {
            s.insert_str(s.len() - 1, &line);
        }
        let f = |v: f64| if v.is_finite() { sig(v, 4) } else { "-".to_string() };
        for o in outputs {
            let m = &o.summary;
            s.push_str(&format!(
                "{:<22} mean {} sd {}  q05 {} q50 {} q95 {} {}{}\n",
                o.key,
                f(m.mean),
                f(m.sd),
                f(m.q05),
                f(m.q50),
                f(m.q95),
                o.unit,
                // (an output undefined in some draws, e_t, says why)
                if m.mean.is_nan() {
                    format!(" undefined in some draws {}", crate::render::impact::undefined_remark(o.key))
                        .trim_end()
                        .to_string()
                } else {
                    String::new()
                }
            ));
            for (k, i) in self.inputs.iter().enumerate() {
                let (a, b) = (m.first[k], m.total[k]);
                s.push_str(&format!(
                    "    {:<20} S {} [{}, {}]  ST {} [{}, {}]\n",
                    i.key,
                    f(a.value),
                    f(a.lo),
                    f(a.hi),
                    f(b.value),
                    f(b.lo),
                    f(b.hi)
                ));
            }
        }
        s
    }
}
