//! `concrete_drop`: the ITF 100-inch drop on a concrete slab (paper p. 3, "Ball parameters",
//! Eqs 11-12): "For these parameters the impact duration for a 100-inch drop onto concrete is
//! 4.64 ms, and e = 0.751."
//!
//! Model: the ball alone (Eqs 1, 3, 4) on a rigid slab, solved in closed form
//! ([`crate::model::reduced::concrete_drop`]). The table sweeps the drop height to show the
//! paper's point that `e = sqrt(2/(p+1))` and the duration do not depend on the speed, while
//! the compression and the peak force grow with it. Overrides: none (k1 3e4 N/m, p 2.55,
//! m_b 57 g).

use super::{col, line, on_right, paper_label, paper_points, paper_value, scaled, Context, Experiment, PaperClaim};
use crate::error::Result;
use crate::model::reduced::{concrete_drop, DropResult};
use crate::numfmt::fmt_sig;
use crate::params::{drop_speed, Ball, DROP_HEIGHT_100_IN};
use crate::render::plot::{Chart, VLine};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "concrete_drop",
    title: "Ball dropped on concrete: duration and COR against drop height",
    paper_ref: "p. 3, Ball parameters, Eqs 11-12: 100-inch drop, tau 4.64 ms, e 0.751",
    run,
    chart,
    claims: &[
        PaperClaim { id: "concrete_tau", ours: |c| Ok(drop_100_in(c).tau_s * 1e3) },
        PaperClaim { id: "concrete_e", ours: |c| Ok(drop_100_in(c).e) },
        // the p that gives e = 0.762 (the rules' upper limit of 0.745 + 0.017) by Eq 12
        PaperClaim { id: "ball_p_for_e_0_762", ours: |_| Ok(2.0 / (0.745_f64 + 0.017).powi(2) - 1.0) },
    ],
};

/// The context's ball (the paper's) dropped 100 inches on concrete.
fn drop_100_in(ctx: &Context) -> DropResult {
    concrete_drop(&ctx.ball, drop_speed(DROP_HEIGHT_100_IN))
}

/// Drop heights, m (2.54 m is the rules' 100 inches).
const HEIGHTS: [f64; 9] = [0.25, 0.5, 1.0, 1.5, 2.0, DROP_HEIGHT_100_IN, 3.0, 4.0, 5.0];

fn run(_: &Context) -> Result<Table> {
    let ball = Ball::default();
    let mut t = Table::new(EXPERIMENT.id, &["height_m", "v1_m_per_s", "tau_s", "e", "y0_m", "peak_force_n"]);
    for h in HEIGHTS {
        let v1 = drop_speed(h);
        let d = concrete_drop(&ball, v1);
        t.push(vec![h.into(), v1.into(), d.tau_s.into(), d.e.into(), d.y0_m.into(), d.peak_force_n.into()])?;
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let h = col(t, "height_m");
    let d = concrete_drop(&Ball::default(), drop_speed(DROP_HEIGHT_100_IN));
    Chart {
        title: format!(
            "Drop on concrete (p. 3, Eq 12): tau = {} ms, e = {} at 100 in",
            fmt_sig(d.tau_s * 1e3, 4),
            fmt_sig(d.e, 4)
        ),
        x_label: "drop height (m)".into(),
        y_label: "e,  maximum ball compression Y0 (cm)".into(),
        y2_label: Some("impact duration tau (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 5.2)),
        y_range: Some((0.0, 2.0)),
        y2_range: Some((0.0, 6.0)),
        curves: vec![
            line("e", h.clone(), col(t, "e"), 0),
            line("Y0 (cm)", h.clone(), scaled(col(t, "y0_m"), 100.0), 3),
            on_right(line("tau", h, scaled(col(t, "tau_s"), 1e3), 1)),
            paper_points(
                paper_label(&format!("e {} at 100 in", fmt_sig(paper_value("concrete_e"), 3))),
                vec![DROP_HEIGHT_100_IN],
                &["concrete_e"],
                0,
            ),
            on_right(paper_points(
                paper_label(&format!("tau {} ms at 100 in", fmt_sig(paper_value("concrete_tau"), 3))),
                vec![DROP_HEIGHT_100_IN],
                &["concrete_tau"],
                1,
            )),
        ],
        bands: vec![],
        vlines: vec![VLine { x: DROP_HEIGHT_100_IN, label: "100 inches".into() }],
        ..Chart::default()
    }
}
