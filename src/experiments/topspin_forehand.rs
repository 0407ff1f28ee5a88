//! `topspin_forehand` (beyond the paper): a forehand that brushes up the back of the ball. The
//! racket moves at 30 m/s at the impact point along a path tilted 0-40 deg above the
//! horizontal, the string plane vertical across the ball's line, against a ball coming in
//! horizontally at 20 m/s without spin; the centre of the strings of the paper's racket at
//! k_s 4e4 N/m (60 lb), mu 0.4. Outgoing ball speed, launch angle and spin in the court's frame.
//!
//! Model: the impact in the racket's frame ([`crate::solve::swing`]): normal speed
//! `20 + 30 cos(path)`, tangential `30 sin(path)` across the face, then the exit carried back
//! to the court. Expect: topspin rising with the path angle (some 2000-3000 rpm at 20-30 deg,
//! the range measured on tour forehands, data/measured), the ball speed falling a little as
//! the normal closing speed falls, and a launch angle well below the path angle (the strings
//! throw the ball out near their normal).

use super::{col, fit_range, line, on_right, scaled, styled, Context, Experiment, CENTRE_X};
use crate::error::Result;
use crate::render::plot::{Chart, LineStyle};
use crate::render::table::Table;
use crate::solve::swing::Swing;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "topspin_forehand",
    title: "Topspin forehand: ball speed, launch angle and spin against the swing path angle",
    paper_ref: "(beyond the paper) p. 1: the racket is swung towards the ball; Conclusions: spin",
    run,
    chart,
    claims: &[],
};

/// Racket speed at the impact point and incoming ball speed, m/s.
const RACKET_SPEED: f64 = 30.0;
const INCOMING: f64 = 20.0;

/// Swing path angles, degrees above the horizontal: 0 to 40 in steps of 2.5.
pub fn paths_deg() -> Vec<f64> {
    (0..=16).map(|i| 2.5 * i as f64).collect()
}

fn run(ctx: &Context) -> Result<Table> {
    let mut t = Table::new(
        EXPERIMENT.id,
        &["path_deg", "incidence_deg", "ball_speed_m_per_s", "launch_deg", "spin_rpm", "e_a", "slip_fraction"],
    );
    let base = ctx.paper_params(CENTRE_X, 4.0e4);
    for path in paths_deg() {
        let swing = Swing { racket_speed: RACKET_SPEED, path_deg: path, incoming: INCOMING, incoming_spin_rpm: 0.0 };
        let exit = swing.hit(&base)?;
        let slip = if exit.impact.slip_fraction.is_nan() { 0.0 } else { exit.impact.slip_fraction };
        t.push(vec![
            path.into(),
            exit.params.oblique.angle_deg.into(),
            exit.speed.into(),
            exit.launch_deg.into(),
            exit.spin_rpm.into(),
            exit.impact.e_a.into(),
            slip.into(),
        ])?;
    }
    Ok(t)
}

/// km/h per m/s: the figure speaks in the `speed` command's default unit.
const KMH: f64 = 3.6;

/// Angles on the left axis, spin on the right; the ball speed, in km/h on neither scale, is
/// told in the title (its first and last value; the CSV has every one).
fn chart(_: &Context, t: &Table) -> Chart {
    let x = col(t, "path_deg");
    let speed = scaled(col(t, "ball_speed_m_per_s"), KMH);
    let curves = vec![
        line("launch angle (deg)", x.clone(), col(t, "launch_deg"), 2),
        styled(line("path angle (deg)", x.clone(), x.clone(), 0), LineStyle::Faint),
        on_right(line("topspin (rpm), court frame", x.clone(), col(t, "spin_rpm"), 3)),
    ];
    let left = fit_range(curves[..2].iter().flat_map(|c| c.y.clone()), true);
    let ends = match (x.first().zip(speed.first()), x.last().zip(speed.last())) {
        (Some((x0, v0)), Some((x1, v1))) => {
            format!(": ball out at {v0:.0} km/h ({x0:.0} deg path) to {v1:.0} km/h ({x1:.0} deg)")
        }
        _ => String::new(),
    };
    Chart {
        title: format!(
            "Topspin forehand (racket {:.0} km/h, ball in {:.0} km/h, centre, 60 lb, mu 0.4){ends}",
            RACKET_SPEED * KMH,
            INCOMING * KMH
        ),
        x_label: "swing path angle above the horizontal (deg)".into(),
        y_label: "launch angle and path angle (deg)".into(),
        y2_label: Some("topspin in the court's frame (rpm)".into()),
        x_log: false,
        x_range: Some((0.0, 40.0)),
        y_range: left,
        y2_range: fit_range(col(t, "spin_rpm"), true),
        curves,
        bands: vec![],
        vlines: vec![],
        ..Chart::default()
    }
}
