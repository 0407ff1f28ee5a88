//! The paper's own conclusions beside the card's, for the paper's racket: its 60 -> 50 lb
//! serve and forehand gains, the impact duration and swing angle, the twist at 50 and 60 lb,
//! and the 200 Hz frame's gain near the tip (Fig 9). The paper's numbers, claims, pages and
//! quotes are read from the claims table (golden/paper_claims.csv, compiled in, the one place
//! they are typed); the model's are read off the card's rows at the same inputs.

use super::compute::{Card, Row, Shot, Who};
use super::SWING_RAD_PER_S;
use crate::error::{Error, Result};
use crate::render::table::{Table, Value};
use crate::solve::swing::gain_pct;

/// The paper's claims as the claims table holds them.
const CLAIMS: &str = include_str!("../../../golden/paper_claims.csv");

/// One of the paper's claims: its words, page and number.
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    /// Its id in the claims table.
    pub id: String,
    /// What it says, in the table's words.
    pub claim: String,
    /// Where in the paper.
    pub source: String,
    /// The paper's value as printed.
    pub paper: String,
    /// Its unit.
    pub unit: String,
}

/// The claim `id` of the claims table.
pub fn claim(id: &str) -> Result<Claim> {
    let bad = |why: String| Error::invalid("claims table", "golden/paper_claims.csv", why);
    let mut rdr = csv::Reader::from_reader(CLAIMS.as_bytes());
    let headers = rdr.headers().map_err(|e| bad(e.to_string()))?.clone();
    let col = |name: &str| headers.iter().position(|h| h == name).ok_or_else(|| bad(format!("has no column {name}")));
    let (i, c, s, p, u) = (col("id")?, col("claim")?, col("source")?, col("paper")?, col("unit")?);
    for r in rdr.records() {
        let r = r.map_err(|e| bad(e.to_string()))?;
        if r.get(i) == Some(id) {
            let f = |k: usize| r.get(k).unwrap_or_default().to_string();
            return Ok(Claim { id: f(i), claim: f(c), source: f(s), paper: f(p), unit: f(u) });
        }
    }
    Err(bad(format!("has no claim {id} (the card reads it)")))
}

/// The paper's conclusions the card sets beside its own, each with how the card reads its
/// value off its rows at 50 and 60 lb (A) and the 200 Hz frame's at 60 lb (W).
#[allow(clippy::type_complexity)]
const READ: [(&str, &str, &str, fn(&Row, &Row, &Row) -> f64); 11] = [
    ("speeds_60_50_serve_gain", "serve, 60 -> 50 lb", "centre serve", |a50, a60, _| {
        gain_pct(a60.speed(Shot::ServeCentre), a50.speed(Shot::ServeCentre))
    }),
    ("speeds_60_50_forehand_gain", "forehand, 60 -> 50 lb", "centre forehand", |a50, a60, _| {
        gain_pct(a60.speed(Shot::ForehandCentre), a50.speed(Shot::ForehandCentre))
    }),
    ("speeds_60_50_tau_change", "impact duration, 60 -> 50 lb", "centre, 30 m/s", |a50, a60, _| {
        1e3 * (a50.of(Shot::Centre, |r| r.tau_s) - a60.of(Shot::Centre, |r| r.tau_s))
    }),
    (
        "discussion_angle_30_rad_s",
        "swing angle at 30 rad/s, 60 -> 50 lb",
        "the paper's 30 rad/s times the duration's change",
        |a50, a60, _| {
            (SWING_RAD_PER_S * (a50.of(Shot::Centre, |r| r.tau_s) - a60.of(Shot::Centre, |r| r.tau_s))).to_degrees()
        },
    ),
    ("fig8_theta_r4_50lb", "twist at 50 lb", "r 4 cm, 30 m/s", |a50, _, _| a50.of(Shot::Twist, |r| r.theta_end_deg)),
    ("fig8_theta_r4_60lb", "twist at 60 lb", "r 4 cm, 30 m/s", |_, a60, _| a60.of(Shot::Twist, |r| r.theta_end_deg)),
    ("speeds_50_60_theta_change", "twist, 50 -> 60 lb", "r 4 cm, 30 m/s", |a50, a60, _| {
        gain_pct(a50.of(Shot::Twist, |r| r.theta_end_deg), a60.of(Shot::Twist, |r| r.theta_end_deg))
    }),
    ("fig9_e_a_ei150", "e_A near the tip, 125 Hz frame", "near the tip, 60 lb", |_, a60, _| {
        a60.of(Shot::Tip, |r| r.e_a)
    }),
    ("fig9_e_a_ei384", "e_A near the tip, 200 Hz frame", "near the tip, 60 lb", |_, _, w| w.of(Shot::Tip, |r| r.e_a)),
    ("fig9_serve_gain", "serve near the tip, 200 over 125 Hz", "(1 + e_A) near the tip, 60 lb", |_, a60, w| {
        gain_pct(1.0 + a60.of(Shot::Tip, |r| r.e_a), 1.0 + w.of(Shot::Tip, |r| r.e_a))
    }),
    (
        "fig9_f_vib_cut",
        "vibration near the tip, 200 Hz cut",
        "near the tip, 60 lb: the card's vibration left (f_vib)",
        |_, a60, w| 100.0 * (1.0 - w.of(Shot::Tip, |r| r.f_vib) / a60.of(Shot::Tip, |r| r.f_vib)),
    ),
];

impl Card {
    /// The paper beside the card (its racket only, else `None`): one row per conclusion with
    /// its id, words, page, the paper's value, the model's and how the card reads it.
    pub fn paper_table(&self) -> Result<Option<Table>> {
        let find = |who: Who, t: f64| self.paper_rows.iter().find(|r| r.who == who && r.tension_lb == t);
        let (Some(a50), Some(a60), Some(w)) =
            (find(Who::Variant(0), 50.0), find(Who::Variant(0), 60.0), find(Who::Widebody, 60.0))
        else {
            return Ok(None);
        };
        let mut t =
            Table::new("card_paper", &["id", "short", "claim", "source", "paper", "model", "unit", "model_reads"]);
        for (id, short, reads, read) in READ {
            let c = claim(id)?;
            t.push(vec![
                Value::Text(c.id),
                Value::Text(short.into()),
                Value::Text(c.claim),
                Value::Text(c.source),
                Value::Text(c.paper),
                read(a50, a60, w).into(),
                Value::Text(c.unit),
                Value::Text(reads.into()),
            ])?;
        }
        Ok(Some(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_conclusion_the_card_reads_is_in_the_claims_table() {
        for (id, _, _, _) in READ {
            let c = claim(id).unwrap();
            assert!(!c.paper.is_empty() && !c.claim.is_empty(), "{id}");
        }
        assert_eq!(claim("speeds_60_50_serve_gain").unwrap().paper, "0.7");
        assert!(claim("no_such_claim").is_err());
    }
}
