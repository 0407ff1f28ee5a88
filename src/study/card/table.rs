//! A card as a table: one row per racket and tension with every panel's numbers, the header
//! block that names each panel's assumptions (also the figure's footnote), and the CSV.

use super::compute::{Card, Row, Shot, Who};
use super::{OFF_CENTRE, SPIN_SHOT, TWIST_R, TWIST_V1};
use crate::error::Result;
use crate::numfmt::sig;
use crate::render::table::{Table, Value};
use crate::solve::swing::gain_pct;

/// The card's columns, in order.
pub const COLUMNS: [&str; 27] = [
    "racket",
    "tension_lb",
    "ks_n_per_m",
    "serve_centre_kmh",
    "serve_centre_change_pct",
    "serve_off_centre_kmh",
    "serve_off_centre_change_pct",
    "forehand_centre_kmh",
    "forehand_centre_change_pct",
    "forehand_off_centre_kmh",
    "forehand_off_centre_change_pct",
    "centre_e_a",
    "sweet_spot_cm2",
    "sweet_spot_points",
    "best_e_a",
    "best_x_cm",
    "best_r_cm",
    "twist_deg",
    "tau_ms",
    "swing_deg",
    "tip_e_a",
    "vib_tip_pct",
    "vib_throat_pct",
    "spin_rpm",
    "launch_deg",
    "spin_slip_fraction",
    "solver",
];

/// The strokes of the power panel, with their columns' stem.
pub const STROKES: [(Shot, &str); 4] = [
    (Shot::ServeCentre, "serve_centre"),
    (Shot::ServeOff, "serve_off_centre"),
    (Shot::ForehandCentre, "forehand_centre"),
    (Shot::ForehandOff, "forehand_off_centre"),
];

/// Each panel's assumptions in a sentence or two: the CSV's header block and the figure's
/// footnote say the same.
#[derive(Debug, Clone, PartialEq)]
pub struct Notes {
    /// The racket(s), string, tensions, reference and numerics.
    pub setup: Vec<String>,
    /// The power panel.
    pub power: String,
    /// The sweet-spot panel.
    pub sweet: String,
    /// The control panel.
    pub control: String,
    /// The comfort panel.
    pub comfort: String,
    /// The spin panel: the shot, then what its law was validated on and what not.
    pub spin: Vec<String>,
}

impl Notes {
    /// Every line, each panel's prefixed with its name.
    pub fn lines(&self) -> Vec<String> {
        let mut out = self.setup.clone();
        out.push(format!("power: {}", self.power));
        out.push(format!("sweet spot: {}", self.sweet));
        out.push(format!("control: {}", self.control));
        out.push(format!("comfort: {}", self.comfort));
        out.extend(
            self.spin.iter().enumerate().map(|(i, s)| if i == 0 { format!("spin: {s}") } else { format!("spin, {s}") }),
        );
        out
    }
}

/// A length in cm, as the notes write it.
fn cm(m: f64) -> String {
    sig(100.0 * m, 3)
}

impl Card {
    /// The racket's row at the reference tension (the changes are counted from it).
    fn reference(&self) -> Option<&Row> {
        self.rows.iter().find(|r| r.who == Who::Variant(0) && r.tension_lb == self.prepared.reference_lb)
    }

    /// The label of `who`.
    pub fn label(&self, who: Who) -> String {
        match who {
            Who::Variant(i) => self.prepared.variants[i].label.clone(),
            Who::Widebody => super::WIDEBODY_PRESET.to_string(),
        }
    }

    /// The card's table: one row per racket and tension.
    pub fn table(&self) -> Result<Table> {
        let mut t = Table::new("card", &COLUMNS);
        let reference = self.reference();
        let rate = self.prepared.request.strokes.swing_rad_per_s;
        for row in &self.rows {
            let mut cells = vec![
                Value::Text(self.label(row.who)),
                row.tension_lb.into(),
                row.get(Shot::Centre).0.strings.ks.into(),
            ];
            for (shot, _) in STROKES {
                let v = row.speed(shot);
                let change = reference.map_or(f64::NAN, |r| gain_pct(r.speed(shot), v));
                cells.extend([Value::from(v * super::KMH), Value::from(change)]);
            }
            let tau = row.of(Shot::Centre, |r| r.tau_s);
            cells.push(row.of(Shot::Centre, |r| r.e_a).into());
            match &row.sweet {
                Some(s) => cells.extend([
                    Value::from(1e4 * s.area_m2),
                    Value::from(s.points),
                    Value::from(s.best.value),
                    Value::from(100.0 * s.best.x_m),
                    Value::from(100.0 * s.best.r_m + 0.0),
                ]),
                None => cells.extend((0..5).map(|_| Value::Text(String::new()))),
            }
            let spin = row.spin();
            cells.extend([
                Value::from(row.of(Shot::Twist, |r| r.theta_end_deg)),
                Value::from(1e3 * tau),
                Value::from((rate * tau).to_degrees()),
                Value::from(row.of(Shot::Tip, |r| r.e_a)),
                Value::from(100.0 * row.of(Shot::Tip, |r| r.f_vib)),
                Value::from(100.0 * row.of(Shot::Throat, |r| r.f_vib)),
                Value::finite_or_empty(spin.map_or(f64::NAN, |e| e.spin_rpm)),
                Value::finite_or_empty(spin.map_or(f64::NAN, |e| e.launch_deg)),
                Value::finite_or_empty(spin.map_or(f64::NAN, |e| e.impact.slip_fraction)),
                Value::Text(row.get(Shot::Centre).0.numerics.solver.name().into()),
            ]);
            t.push(cells)?;
        }
        Ok(t)
    }

    /// Each panel's assumptions ([`Notes`]).
    pub fn notes(&self) -> Notes {
        let p = &self.prepared;
        let a = &p.variants[0];
        let req = &p.request;
        let strokes = req.strokes;
        let kmh = |v: f64| sig(v * super::KMH, 3);
        let tensions: Vec<String> = p.tensions_lb.iter().map(|t| sig(*t, 4)).collect();
        let own = req.reference_lb.is_none();
        let numerics = &a.params.numerics;
        let mut setup = vec![format!(
            "racket-impact card: what string tension does to {}{}, string {} (ball/string friction {})",
            a.label,
            p.variants.get(1).map_or(String::new(), |b| format!(" beside {} (B, dashed)", b.label)),
            a.params.oblique.string.name(),
            sig(a.params.oblique.friction().0, 3)
        )];
        setup.push(format!(
            "tensions {} lb (k_s = 4e4 N/m * T / 60 lb); changes counted from {} at {} lb{}",
            tensions.join(", "),
            a.label,
            sig(p.reference_lb, 4),
            if own { " (its own tension)" } else { "" }
        ));
        setup.push(format!(
            "model: {} solver, {} load, N = {} segments, free racket (the paper's); maps: {} solver on a {} x {} grid over the face",
            numerics.solver.name(),
            numerics.load.name(),
            numerics.segments,
            crate::study::map::with_map_solver(&a.params).numerics.solver.name(),
            req.grid.0,
            req.grid.1
        ));
        let pts = a.points;
        let power = format!(
            "serve: racket {} km/h at the impact point, ball at rest, v = (1 + e_A) v_racket; forehand: racket and ball {} km/h each, \
             v = (1 + 2 e_A) v (the paper's frames, p. 5-6; e_A at the relative speed, as `speed`); centre x = {} cm; off-centre \
             x = {} cm, r = {} cm ({} cm towards the tip and {} cm across: the paper's Fig 4 point); changes in % from the reference; \
             the paper calls 60 -> 50 lb (serve 0.7 %, forehand 1.1 %) 'barely noticeable' (p. 6)",
            kmh(strokes.serve_m_per_s),
            kmh(strokes.forehand_m_per_s),
            cm(pts.centre),
            cm(pts.off.0),
            cm(pts.off.1),
            cm(OFF_CENTRE.0),
            cm(OFF_CENTRE.1)
        );
        let sweet_cell = self
            .rows
            .iter()
            .find_map(|r| r.sweet)
            .map_or(String::new(), |s| format!(", each point one {} cm^2 grid cell", sig(1e4 * s.cell_m2, 3)));
        let sweet = format!(
            "the face area where e_A >= {} x its best over the face (`map`: one impact per point of the {} x {} grid, ball at {} m/s, \
             normal incidence{sweet_cell}); each racket against its own best; where that best lies, cm from the tip",
            sig(1.0 - req.sweet_within, 3),
            req.grid.0,
            req.grid.1,
            sig(a.params.impact.v1, 4)
        );
        let control = format!(
            "twist: a ball {} cm off the long axis at the centre at {} m/s (the paper's Fig 8 case), angle at the end of the impact; \
             swing angle: omega tau during the contact at omega = {} rad/s (the paper's 'as high as 30 rad/s', p. 1), tau the centre impact's",
            cm(TWIST_R),
            sig(TWIST_V1, 3),
            sig(strokes.swing_rad_per_s, 3)
        );
        let comfort = format!(
            "vibration energy left in the frame after the impact (% of the ball's kinetic energy, exact: frame energy less its rigid \
             motion) on the long axis near the tip (x = {} cm) and near the throat (x = {} cm) at {} m/s; impact duration at the centre",
            cm(pts.tip),
            cm(pts.throat),
            sig(TWIST_V1, 3)
        );
        let mut spin = vec![format!(
            "topspin forehand: racket {} m/s along a path {} deg above the horizontal, ball {} m/s without spin, at the centre \
             (the spin validation's tour forehand), string {} (mu {}); outgoing spin in the court's frame",
            sig(SPIN_SHOT.racket_speed, 3),
            sig(SPIN_SHOT.path_deg, 3),
            sig(SPIN_SHOT.incoming, 3),
            a.params.oblique.string.name(),
            sig(a.params.oblique.friction().0, 3)
        )];
        spin.extend(self.status.sentences());
        Notes { setup, power, sweet, control, comfort, spin }
    }

    /// The header block: the notes, then the paper beside the model (its racket), each line
    /// starting `# `.
    pub fn header(&self) -> Result<Vec<String>> {
        let mut lines = self.notes().lines();
        if let Some(t) = self.paper_table()? {
            lines.push("the paper beside the model (its racket, the card's inputs):".into());
            for r in &t.rows {
                let text = |k: &str| t.column_index(k).map_or(String::new(), |i| r[i].to_csv_field());
                let model = t.column_index("model").map_or(f64::NAN, |i| r[i].as_f64());
                let unit = if text("unit") == "1" { String::new() } else { format!(" {}", text("unit")) };
                lines.push(format!(
                    "  {}: paper {}{unit}, model {} ({}; {})",
                    text("claim"),
                    text("paper"),
                    sig(model, 3),
                    text("model_reads"),
                    text("source")
                ));
            }
        }
        Ok(lines)
    }

    /// The CSV: the header block (`# ` lines), then the table.
    pub fn csv(&self) -> Result<String> {
        let mut s: String = self.header()?.iter().map(|l| format!("# {l}\n")).collect();
        s.push_str(&self.table()?.to_csv());
        Ok(s)
    }
}

impl Card {
    /// The card in a few lines of text: per racket and tension the panels' main numbers, the
    /// paper beside the model (its racket) and what the spin law was validated on.
    pub fn summary(&self) -> Result<String> {
        let t = self.table()?;
        let mut s = format!("{}\n", self.notes().setup.join("\n"));
        s.push_str(&format!(
            "{:<22} {:>7} {:>9} {:>9} {:>9} {:>8} {:>7} {:>7} {:>8} {:>8} {:>7} {:>7}\n",
            "racket",
            "T lb",
            "serve %",
            "fhand %",
            "off-c %",
            "sweet",
            "twist",
            "swing",
            "vib tip",
            "vib thr",
            "tau ms",
            "spin"
        ));
        let num = |r: &[Value], c: &str| t.column_index(c).map_or(f64::NAN, |i| r[i].as_f64());
        for r in &t.rows {
            s.push_str(&format!(
                "{:<22} {:>7} {:>+9.2} {:>+9.2} {:>+9.2} {:>5.0} cm2 {:>5.2} {:>7.2} {:>7.2} % {:>6.2} % {:>7.3} {:>7.0}\n",
                r[0].to_csv_field(),
                sig(num(r, "tension_lb"), 4),
                num(r, "serve_centre_change_pct"),
                num(r, "forehand_centre_change_pct"),
                num(r, "serve_off_centre_change_pct"),
                num(r, "sweet_spot_cm2"),
                num(r, "twist_deg"),
                num(r, "swing_deg"),
                num(r, "vib_tip_pct"),
                num(r, "vib_throat_pct"),
                num(r, "tau_ms"),
                num(r, "spin_rpm"),
            ));
        }
        if let Some(p) = self.paper_table()? {
            s.push_str("the paper beside the model (its racket):\n");
            for r in &p.rows {
                let text = |k: &str| p.column_index(k).map_or(String::new(), |i| r[i].to_csv_field());
                let model = p.column_index("model").map_or(f64::NAN, |i| r[i].as_f64());
                let unit = if text("unit") == "1" { String::new() } else { format!(" {}", text("unit")) };
                s.push_str(&format!(
                    "  {:<40} paper {:>5} model {:>7}{unit}\n",
                    text("short"),
                    text("paper"),
                    sig(model, 3)
                ));
            }
        }
        for line in &self.notes().spin[1..] {
            s.push_str(&format!("spin law: {line}\n"));
        }
        Ok(s)
    }

    /// The card as pretty JSON: the header lines, the rows (one object per racket and tension,
    /// keyed by the table's columns), the paper beside the model and the diagnostics.
    pub fn json(&self) -> Result<String> {
        let objects = |t: &Table| -> Vec<serde_json::Value> {
            t.rows
                .iter()
                .map(|r| {
                    let o: serde_json::Map<String, serde_json::Value> = t
                        .columns
                        .iter()
                        .zip(r)
                        .map(|(c, v)| {
                            let v = match v {
                                Value::Text(s) => serde_json::Value::from(s.clone()),
                                Value::Int(i) => serde_json::Value::from(*i),
                                Value::Num(x) if x.is_finite() => serde_json::Value::from(*x),
                                Value::Num(_) => serde_json::Value::Null,
                            };
                            (c.clone(), v)
                        })
                        .collect();
                    serde_json::Value::Object(o)
                })
                .collect()
        };
        let paper = self.paper_table()?;
        let v = serde_json::json!({
            "header": self.header()?,
            "rows": objects(&self.table()?),
            "paper": paper.as_ref().map(objects),
            "diagnostics": self.diagnostics,
        });
        crate::render::json::pretty(&v)
    }
}
