//! The robustness study's outputs: its table (`figures/robustness.csv`, and `uncertainty
//! --claims --format csv`), the JSON document and the text table of `uncertainty --claims`.

use serde_json::{json, Map, Value as Json};

use super::{conclusion_tally, inputs, runs_per_sample, tally, tally_text, top_two, ClaimRobustness, EXPERIMENT};
use crate::error::Result;
use crate::numfmt::sig;
use crate::render::table::{Table, Value};
use crate::study::uncertainty::{not_meaningful, summary_json};

/// The table columns.
pub const COLUMNS: [&str; 29] = [
    "id",
    "unit",
    "paper",
    "band_lo",
    "band_hi",
    "nominal",
    "numerical",
    "q05",
    "q50",
    "q95",
    "verdict",
    "conclusion",
    "conclusion_share",
    "conclusion_verdict",
    "top_input",
    "top_total",
    "second_input",
    "second_total",
    "q05_2x",
    "q50_2x",
    "q95_2x",
    "verdict_2x",
    "conclusion_share_2x",
    "conclusion_verdict_2x",
    "conclusion_check",
    "conclusion_margin",
    "conclusion_margin_2x",
    "by_construction",
    "conclusion_from",
];

/// The claims as a table, one row each in the claims file's order.
pub fn table(rows: &[ClaimRobustness]) -> Result<Table> {
    let mut t = Table::new(EXPERIMENT.id, &COLUMNS);
    let num = |v: Option<f64>| v.filter(|v| v.is_finite()).map_or(Value::Text(String::new()), Value::Num);
    for r in rows {
        let s = &r.summary;
        let top = top_two(s);
        let name = |k: usize| Value::Text(top.get(k).map_or(String::new(), |t| t.0.to_string()));
        let total = |k: usize| num(top.get(k).map(|t| t.1));
        t.push(vec![
            Value::Text(r.claim.id.clone()),
            Value::Text(r.claim.unit.clone()),
            num(r.claim.paper_value().ok()),
            num(r.band.map(|b| b.0)),
            num(r.band.map(|b| b.1)),
            Value::Num(r.nominal),
            num(r.numerical),
            Value::Num(s.q05),
            Value::Num(s.q50),
            Value::Num(s.q95),
            Value::Text(r.verdict.name().to_string()),
            Value::Text(r.claim.conclusion.clone()),
            num(r.conclusion_share),
            Value::Text(r.conclusion.name().to_string()),
            name(0),
            total(0),
            name(1),
            total(1),
            num(r.doubled.as_ref().map(|d| d.summary.q05)),
            num(r.doubled.as_ref().map(|d| d.summary.q50)),
            num(r.doubled.as_ref().map(|d| d.summary.q95)),
            Value::Text(r.doubled.as_ref().map_or(String::new(), |d| d.verdict.name().to_string())),
            num(r.doubled.as_ref().and_then(|d| d.conclusion_share)),
            Value::Text(r.doubled.as_ref().map_or(String::new(), |d| d.conclusion.name().to_string())),
            Value::Text(r.claim.conclusion_check.clone()),
            num(r.conclusion_margin),
            num(r.doubled.as_ref().and_then(|d| d.conclusion_margin)),
            Value::Text(if r.claim.by_construction() { "yes" } else { "no" }.to_string()),
            Value::Text(if r.claim.conclusion_is_ours() { "ours" } else { "paper" }.to_string()),
        ])?;
    }
    Ok(t)
}

/// The JSON document of `uncertainty --claims`: `{"samples", "seed", "runs", "inputs": [...],
/// "outputs": {claim: {summary, "unit", "paper", "band", "nominal", "numerical", "verdict",
/// "conclusion", "conclusion_share", "conclusion_verdict", "conclusion_check",
/// "conclusion_margin", "by_construction", "conclusion_from"}}, "verdicts", "conclusion_verdicts"}` (`paper` and
/// `band` null for a claim the paper states no number for).
pub fn json(rows: &[ClaimRobustness], samples: u64, seed: u32) -> Result<Json> {
    let inputs = inputs();
    let keys: Vec<&str> = inputs.iter().map(|s| s.key).collect();
    let mut outputs = Map::new();
    for r in rows {
        let mut v = summary_json(&r.summary, &keys);
        v["unit"] = r.claim.unit.clone().into();
        v["paper"] = r.claim.paper_value().ok().into();
        v["band"] = r.band.map_or(Json::Null, |b| json!([b.0, b.1]));
        v["nominal"] = r.nominal.into();
        v["numerical"] = r.numerical.into();
        v["verdict"] = r.verdict.name().into();
        v["conclusion"] = r.claim.conclusion.clone().into();
        v["conclusion_share"] = r.conclusion_share.into();
        v["conclusion_verdict"] = r.conclusion.name().into();
        v["conclusion_check"] = r.claim.conclusion_check.clone().into();
        v["conclusion_margin"] = r.conclusion_margin.into();
        v["by_construction"] = r.claim.by_construction().into();
        v["conclusion_from"] = if r.claim.conclusion_is_ours() { "ours" } else { "paper" }.into();
        outputs.insert(r.claim.id.clone(), v);
    }
    let inputs: Vec<Json> = inputs
        .iter()
        .filter_map(|s| {
            s.uncertainty
                .map(|u| json!({"key": s.key, "dist": u.dist.text(), "nominal": u.nominal, "source": u.source}))
        })
        .collect();
    let (counts, borderline) = tally(rows);
    let mut verdicts: Map<String, Json> = counts.iter().map(|(v, n)| (v.name().to_string(), (*n).into())).collect();
    verdicts.insert("borderline".into(), borderline.into());
    let c = conclusion_tally(rows);
    let mut conclusion_verdicts: Map<String, Json> =
        c.counts.iter().map(|(v, n)| (v.name().to_string(), (*n).into())).collect();
    conclusion_verdicts.insert("borderline".into(), c.borderline.into());
    conclusion_verdicts.insert("by_construction".into(), c.by_construction.into());
    conclusion_verdicts.insert("ours".into(), c.ours.into());
    Ok(json!({
        "samples": samples, "seed": seed, "runs": samples as usize * runs_per_sample(), "inputs": inputs,
        "outputs": outputs, "verdicts": verdicts, "conclusion_verdicts": conclusion_verdicts
    }))
}

/// The text table of `uncertainty --claims`: one line per claim (nominal, q05-q95, verdict,
/// the two inputs it hinges on), then the verdicts counted.
pub fn text(rows: &[ClaimRobustness], samples: u64, seed: u32) -> String {
    let mut s = format!(
        "{samples} base samples x {} = {} evaluations of every claim (modal solver), seed {seed}\n\
         {:<32} {:>10} {:>10} {:>10} {:>10}  {:<11} {:<11} {:>10}  top inputs (total index)\n",
        runs_per_sample(),
        samples as usize * runs_per_sample(),
        "claim",
        "nominal",
        "q05",
        "q50",
        "q95",
        "verdict",
        "conclusion",
        "share"
    );
    if rows.iter().any(|r| r.doubled.is_some()) {
        // (the verdicts were checked at twice the samples: say so on the first line)
        let at = s.find('\n').unwrap_or(0);
        s.insert_str(at, &format!("; every verdict checked again at {} base samples", 2 * samples));
    }
    if let Some(line) = not_meaningful(samples) {
        s.insert_str(s.find('\n').unwrap_or(0) + 1, &line);
    }
    for r in rows {
        let top: Vec<String> = top_two(&r.summary).iter().map(|(k, v)| format!("{k} {}", sig(*v, 2))).collect();
        s.push_str(&format!(
            "{:<32} {:>10} {:>10} {:>10} {:>10}  {:<11} {:<11} {:>10}  {}\n",
            r.claim.id,
            sig(r.nominal, 4),
            sig(r.summary.q05, 4),
            sig(r.summary.q50, 4),
            sig(r.summary.q95, 4),
            r.verdict.name(),
            r.conclusion.name(),
            r.conclusion_share.map_or("-".to_string(), |v| sig(v, 3)),
            top.join(", ")
        ));
    }
    s.push_str(&format!("{}\n", tally_text(rows)));
    s
}
