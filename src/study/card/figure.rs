//! The card drawn from its table: five panels against the tension (power, sweet spot, control,
//! comfort, spin), each with its assumptions under it, and a sixth cell in words (the paper
//! beside the model on the paper's racket; else the racket at the ends of the range and at the
//! reference). The compared racket is dashed in the same colours.

use super::table::Notes;
use crate::numfmt::sig;
use crate::render::plot::sheet::{Cell, Sheet};
use crate::render::plot::{fit_range, Axis, Chart, Curve, LineStyle};
use crate::render::table::Table;

/// Palette colours of the panels' curves.
const BLUE: usize = 5;
const SKY: usize = 2;
const VERMILLION: usize = 4;
const ORANGE: usize = 1;
const GREEN: usize = 3;
const PURPLE: usize = 6;
const BLACK: usize = 0;
/// Room left above the power panel's curves for its legend, as a fraction of their span.
const LEGEND_ROOM: f64 = 0.75;

/// The table's rows of one racket: `(label, rows)`, in the table's order.
fn rackets(t: &Table) -> Vec<(String, Table)> {
    t.distinct_text("racket")
        .into_iter()
        .map(|r| {
            let rows = t.filter("racket", &r);
            (r, rows)
        })
        .collect()
}

/// A column of `t` (NaN where it is missing).
fn col(t: &Table, name: &str) -> Vec<f64> {
    t.column(name).unwrap_or_else(|| vec![f64::NAN; t.len()])
}

/// The paper's value of the conclusion `id` in the paper table, as a number.
fn paper_value(paper: Option<&Table>, id: &str) -> Option<f64> {
    let t = paper?;
    let (i, p) = (t.column_index("id")?, t.column_index("paper")?);
    t.rows.iter().find(|r| r[i].to_csv_field() == id).and_then(|r| r[p].to_csv_field().parse().ok())
}

/// The curves of `column` for each racket: A solid, B dashed, in `color`; labelled once.
fn per_racket(rs: &[(String, Table)], column: &str, label: &str, color: usize) -> Vec<Curve> {
    rs.iter()
        .enumerate()
        .map(|(i, (_, t))| Curve {
            label: if i == 0 { label.to_string() } else { String::new() },
            x: col(t, "tension_lb"),
            y: col(t, column),
            axis: Axis::Left,
            style: if i == 0 { LineStyle::Solid } else { LineStyle::Dashed },
            color,
        })
        .collect()
}

/// A legend line for the compared racket (a dashed grey line, no points drawn).
fn dashed_note(rs: &[(String, Table)]) -> Option<Curve> {
    rs.get(1).map(|(b, _)| Curve {
        label: format!("dashed: {b}"),
        x: vec![f64::NAN],
        y: vec![f64::NAN],
        style: LineStyle::Dashed,
        color: BLACK,
        ..Curve::default()
    })
}

/// The x range of the card: its tensions, padded by half a step.
fn x_range(t: &Table) -> Option<(f64, f64)> {
    let x = col(t, "tension_lb");
    let lo = x.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let pad = 0.04 * (hi - lo);
    (hi > lo).then_some((lo - pad, hi + pad))
}

/// The y range of `curves` on one axis, from zero.
fn from_zero(curves: &[Curve], axis: Axis) -> Option<(f64, f64)> {
    fit_range(curves.iter().filter(|c| c.axis == axis && c.style != LineStyle::Paper).flat_map(|c| c.y.clone()), true)
}

/// The power panel: the change of the four strokes' ball speed from the reference, beside the
/// size the paper calls 'barely noticeable' (its 60 -> 50 lb forehand gain, +-1.1 %), and on
/// the paper's racket its 60 -> 50 lb values at 50 lb.
fn power(t: &Table, rs: &[(String, Table)], paper: Option<&Table>, reference: f64) -> Chart {
    let mut curves = Vec::new();
    for (column, label, color) in [
        ("serve_centre_change_pct", "serve, centre", BLUE),
        ("serve_off_centre_change_pct", "serve, off-centre", SKY),
        ("forehand_centre_change_pct", "forehand, centre", VERMILLION),
        ("forehand_off_centre_change_pct", "forehand, off-centre", ORANGE),
    ] {
        curves.extend(per_racket(rs, column, label, color));
    }
    let data: Vec<f64> = curves.iter().flat_map(|c| c.y.clone()).collect();
    let scale = paper_value(paper, "speeds_60_50_forehand_gain")
        .or_else(|| super::paper::claim("speeds_60_50_forehand_gain").ok()?.paper.parse().ok());
    let (x0, x1) = x_range(t).unwrap_or((0.0, 1.0));
    if let Some(s) = scale {
        for (k, y) in [s, -s].into_iter().enumerate() {
            curves.push(Curve {
                label: if k == 0 { format!("paper's 'barely noticeable': +-{s} %") } else { String::new() },
                x: vec![x0, x1],
                y: vec![y, y],
                style: LineStyle::Guide,
                color: BLACK,
                ..Curve::default()
            });
        }
    }
    // the paper's own 60 -> 50 lb gains, where the changes count from 60 lb on its racket
    if let (Some(serve), Some(forehand), true) = (
        paper_value(paper, "speeds_60_50_serve_gain"),
        paper_value(paper, "speeds_60_50_forehand_gain"),
        reference == 60.0,
    ) {
        curves.push(Curve {
            label: format!("paper at 50 lb: serve {serve} %, forehand {forehand} %"),
            x: vec![50.0, 50.0],
            y: vec![serve, forehand],
            style: LineStyle::Paper,
            color: BLACK,
            ..Curve::default()
        });
    }
    curves.extend(dashed_note(rs));
    // the scale always in view, and room above the curves for the legend (seven lines)
    let bound = scale.unwrap_or(1.0) * 1.3;
    let (lo, hi) =
        data.iter().copied().filter(|v| v.is_finite()).fold((-bound, bound), |(l, h), v| (l.min(v), h.max(v)));
    Chart {
        title: "Power: ball speed".into(),
        x_label: "string tension (lb)".into(),
        y_label: format!("change from {} lb (%)", sig(reference, 4)),
        x_range: x_range(t),
        y_range: fit_range([lo, hi + LEGEND_ROOM * (hi - lo)], false),
        curves,
        ..Chart::default()
    }
}

/// The sweet-spot panel: its area (left) and where its best e_A lies (right).
fn sweet(t: &Table, rs: &[(String, Table)], within: &str) -> Chart {
    let mut curves =
        per_racket(rs, "sweet_spot_cm2", &format!("area with e_A within {within} of its best (cm^2)"), GREEN);
    let mut right = per_racket(rs, "best_x_cm", "where e_A is best (cm from the tip)", PURPLE);
    for c in &mut right {
        c.axis = Axis::Right;
    }
    curves.extend(right);
    curves.extend(dashed_note(rs));
    Chart {
        title: "Sweet spot".into(),
        x_label: "string tension (lb)".into(),
        y_label: "area (cm^2)".into(),
        y2_label: Some("best e_A at x (cm from the tip)".into()),
        x_range: x_range(t),
        y_range: from_zero(&curves, Axis::Left),
        y2_range: from_zero(&curves, Axis::Right),
        curves,
        ..Chart::default()
    }
}

/// The control panel: the twist at r = 4 cm and the swing angle during the contact, with the
/// paper's twist at 50 and 60 lb on its racket.
fn control(t: &Table, rs: &[(String, Table)], paper: Option<&Table>) -> Chart {
    let mut curves = per_racket(rs, "twist_deg", "twist, ball 4 cm off the axis", VERMILLION);
    curves.extend(per_racket(rs, "swing_deg", "swing angle during the contact", BLUE));
    if let (Some(t50), Some(t60)) = (paper_value(paper, "fig8_theta_r4_50lb"), paper_value(paper, "fig8_theta_r4_60lb"))
    {
        curves.push(Curve {
            label: format!("paper: twist {t50} deg at 50 lb, {t60} at 60 lb"),
            x: vec![50.0, 60.0],
            y: vec![t50, t60],
            style: LineStyle::Paper,
            color: VERMILLION,
            ..Curve::default()
        });
    }
    curves.extend(dashed_note(rs));
    let y_range = fit_range(curves.iter().flat_map(|c| c.y.clone()), true);
    Chart {
        title: "Control: twist and swing angle".into(),
        x_label: "string tension (lb)".into(),
        y_label: "angle (deg)".into(),
        x_range: x_range(t),
        y_range,
        curves,
        ..Chart::default()
    }
}

/// The comfort panel: the vibration left after an impact near the tip and near the throat
/// (left), the impact duration (right).
fn comfort(t: &Table, rs: &[(String, Table)]) -> Chart {
    let mut curves = per_racket(rs, "vib_tip_pct", "vibration left, near the tip", VERMILLION);
    curves.extend(per_racket(rs, "vib_throat_pct", "vibration left, near the throat", ORANGE));
    let mut tau = per_racket(rs, "tau_ms", "impact duration (ms)", BLUE);
    for c in &mut tau {
        c.axis = Axis::Right;
    }
    curves.extend(tau);
    curves.extend(dashed_note(rs));
    Chart {
        title: "Comfort: vibration and contact time".into(),
        x_label: "string tension (lb)".into(),
        y_label: "vibration left (% of the ball's energy)".into(),
        y2_label: Some("impact duration (ms)".into()),
        x_range: x_range(t),
        y_range: from_zero(&curves, Axis::Left),
        y2_range: from_zero(&curves, Axis::Right),
        curves,
        ..Chart::default()
    }
}

/// The spin panel: the outgoing spin of the topspin forehand, with its law's status under it
/// (`note`); in words where no spin was computed (a rigid frame takes no oblique impact).
fn spin(t: &Table, rs: &[(String, Table)], note: Vec<String>) -> Cell {
    let title = "Spin: topspin forehand";
    if !col(t, "spin_rpm").iter().any(|v| v.is_finite()) {
        let why = "No spin: the rigid frame's closed form takes no oblique impact (the tangential contact follows the \
                   beam's normal force history), so the card has no topspin forehand.";
        return Cell::Text { title: title.into(), rows: Vec::new(), note: vec![why.into()] };
    }
    let mut curves = per_racket(rs, "spin_rpm", "topspin forehand, centre", GREEN);
    curves.extend(dashed_note(rs));
    let chart = Chart {
        title: title.into(),
        x_label: "string tension (lb)".into(),
        y_label: "spin (rpm)".into(),
        x_range: x_range(t),
        y_range: from_zero(&curves, Axis::Left),
        curves,
        ..Chart::default()
    };
    Cell::Chart { chart: Box::new(chart), note }
}

/// The sixth cell: the paper beside the model (its racket), else racket A at the ends of the
/// range and at the reference (and B at the reference).
fn words(rs: &[(String, Table)], paper: Option<&Table>, reference: f64) -> Cell {
    if let Some(p) = paper {
        let text = |r: &[crate::render::table::Value], k: &str| {
            p.column_index(k).map_or(String::new(), |i| r[i].to_csv_field())
        };
        let mut rows = vec![vec!["the paper's racket".to_string(), "paper".into(), "model".into(), "".into()]];
        for r in &p.rows {
            let model = p.column_index("model").map_or(f64::NAN, |i| r[i].as_f64());
            let unit = text(r, "unit");
            rows.push(vec![
                text(r, "short"),
                text(r, "paper"),
                sig(model, 3),
                if unit == "1" { String::new() } else { unit },
            ]);
        }
        return Cell::Text {
            title: "The paper beside the model".into(),
            rows,
            note: vec![
                "Paper: its Conclusions and Figs 8-9, as quoted in the CSV's header. Model: this card's inputs (hat load unless \
                 --load node; the paper's 0.7 and 1.1 % scale its factor-two gains by 1/3, REPORT.md explains)."
                    .into(),
            ],
        };
    }
    let Some((a, ta)) = rs.first() else {
        return Cell::Text { title: String::new(), rows: Vec::new(), note: Vec::new() };
    };
    let x = col(ta, "tension_lb");
    let (lo, hi) = (0, x.len().saturating_sub(1));
    let at_ref = x.iter().position(|&v| v == reference).unwrap_or(0);
    let mut header = vec![
        a.clone(),
        format!("{} lb", sig(x[lo], 4)),
        format!("{} lb", sig(reference, 4)),
        format!("{} lb", sig(x[hi], 4)),
    ];
    let b = rs.get(1);
    if let Some((name, _)) = b {
        header.push(format!("{name}, {} lb", sig(reference, 4)));
    }
    let mut rows = vec![header];
    for (column, what, digits) in [
        ("serve_centre_kmh", "serve, centre (km/h)", 4),
        ("forehand_centre_kmh", "forehand, centre (km/h)", 4),
        ("sweet_spot_cm2", "sweet spot (cm^2)", 3),
        ("twist_deg", "twist (deg)", 3),
        ("swing_deg", "swing angle (deg)", 3),
        ("vib_tip_pct", "vibration near the tip (%)", 3),
        ("tau_ms", "impact duration (ms)", 3),
        ("spin_rpm", "spin (rpm)", 4),
    ] {
        let v = col(ta, column);
        let mut row = vec![what.to_string(), sig(v[lo], digits), sig(v[at_ref], digits), sig(v[hi], digits)];
        if let Some((_, tb)) = b {
            let xb = col(tb, "tension_lb");
            let k = xb.iter().position(|&v| v == reference).unwrap_or(0);
            row.push(sig(col(tb, column)[k], digits));
        }
        rows.push(row);
    }
    Cell::Text { title: "The racket across the range".into(), rows, note: Vec::new() }
}

/// The card's sheet from its table `t`, the paper table `paper` (the paper's racket) and its
/// notes.
pub fn sheet(t: &Table, paper: Option<&Table>, notes: &Notes, reference: f64, within: f64, string: &str) -> Sheet {
    let string = if string.is_empty() || string == "none" { String::new() } else { format!(" strung with {string}") };
    let rs = rackets(t);
    let names: Vec<&str> = rs.iter().map(|(n, _)| n.as_str()).collect();
    let x = col(t, "tension_lb");
    let span = format!(
        "{}-{} lb",
        sig(x.iter().copied().fold(f64::INFINITY, f64::min), 4),
        sig(x.iter().copied().fold(f64::NEG_INFINITY, f64::max), 4)
    );
    let cells = vec![
        Cell::Chart { chart: Box::new(power(t, &rs, paper, reference)), note: vec![notes.power.clone()] },
        Cell::Chart {
            chart: Box::new(sweet(t, &rs, &format!("{} %", sig(100.0 * within, 3)))),
            note: vec![notes.sweet.clone()],
        },
        Cell::Chart { chart: Box::new(control(t, &rs, paper)), note: vec![notes.control.clone()] },
        Cell::Chart { chart: Box::new(comfort(t, &rs)), note: vec![notes.comfort.clone()] },
        spin(t, &rs, notes.spin.clone()),
        words(&rs, paper, reference),
    ];
    Sheet {
        title: format!("What string tension does to {}{string} ({span})", names.join(" and ")),
        columns: 3,
        cells,
        footnote: notes.setup.clone(),
    }
}

impl super::Card {
    /// The card's sheet, drawn from its table ([`sheet`]).
    pub fn sheet(&self) -> crate::error::Result<Sheet> {
        let t = self.table()?;
        let paper = self.paper_table()?;
        let string = self.prepared.variants[0].params.oblique.string.name();
        Ok(sheet(
            &t,
            paper.as_ref(),
            &self.notes(),
            self.prepared.reference_lb,
            self.prepared.request.sweet_within,
            string,
        ))
    }
}
