//! `modes`: the free racket's vibration modes (paper p. 3-4, "Racket parameters" and Fig 6
//! discussion): "The fundamental vibration frequency of such a racket, when freely suspended,
//! is typically about 125 Hz ... EI is equal to 150 Nm"; the second mode is at 345 Hz; the
//! fundamental node is "near the middle of the strings, at x = 16 cm"; the wide-body frame of
//! Fig 9 has "EI = 384 Nm" for 200 Hz.
//!
//! Model: the lumped N = 39 free-free beam (Eqs 5-6, SPEC.md section 1), eigenproblem
//! `K phi = omega^2 M phi`. A uniform beam's mode shapes do not depend on EI (all frequencies
//! scale with sqrt(EI)), so the shapes are drawn once with both frequencies in the legend.

use super::{col, line, paper_label, paper_list, paper_value, styled, Context, Experiment, PaperClaim};
use crate::error::Result;
use crate::model::beam::Beam;
use crate::numfmt::fmt_sig;
use crate::params::Racket;
use crate::render::plot::{Chart, LineStyle, VLine};
use crate::render::table::Table;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "modes",
    title: "Free-free racket: first four bending modes for EI 150 and 384 N m^2",
    paper_ref: "p. 3-4, Racket parameters: 125 Hz (EI 150), 345 Hz, node 16 cm; Fig 9: 200 Hz (EI 384)",
    run,
    chart,
    claims: &[
        PaperClaim { id: "modes_f1", ours: |c| Ok(c.modes(&c.racket).1.frequency_hz(1)) },
        PaperClaim { id: "modes_period", ours: |c| Ok(1e3 / c.modes(&c.racket).1.frequency_hz(1)) },
        PaperClaim { id: "modes_f2", ours: |c| Ok(c.modes(&c.racket).1.frequency_hz(2)) },
        PaperClaim { id: "modes_node", ours: node_cm },
        PaperClaim {
            id: "modes_f1_ei384",
            ours: |c| Ok(c.modes(&Racket { ei: c.frame_ei(384.0), ..c.racket }).1.frequency_hz(1)),
        },
    ],
};

/// The node of the fundamental mode, cm from the tip.
fn node_cm(ctx: &Context) -> Result<f64> {
    let (beam, modes) = ctx.modes(&ctx.racket);
    Ok(100.0 * modes.node_positions(1, &beam.x)[0])
}

/// Bending stiffnesses of the paper's two frames, N m^2.
pub const EI_VALUES: [f64; 2] = [150.0, 384.0];
const MODES: usize = 4;

fn run(ctx: &Context) -> Result<Table> {
    let base = ctx.base_params().racket;
    let beams: Vec<Beam> =
        EI_VALUES.iter().map(|&ei| Beam::new(&Racket { ei: ctx.frame_ei(ei), ..base }, 39)).collect();
    let modes: Vec<_> = beams.iter().map(Beam::modes).collect();
    let mut t = Table::new(EXPERIMENT.id, &["mode", "x_m", "shape", "frequency_ei150_hz", "frequency_ei384_hz"]);
    for k in 1..=MODES {
        for (i, x) in beams[0].x.iter().enumerate() {
            t.push(vec![
                k.into(),
                (*x).into(),
                modes[0].shapes[k + 1][i].into(),
                modes[0].frequency_hz(k).into(),
                modes[1].frequency_hz(k).into(),
            ])?;
        }
    }
    Ok(t)
}

fn chart(_: &Context, t: &Table) -> Chart {
    let mode = col(t, "mode");
    let mut curves = Vec::new();
    let mut vlines = Vec::new();
    for k in 1..=MODES {
        let rows: Vec<usize> = (0..t.rows.len()).filter(|&i| mode[i] == k as f64).collect();
        let pick = |name: &str| -> Vec<f64> {
            let c = col(t, name);
            rows.iter().map(|&i| c[i]).collect()
        };
        let x: Vec<f64> = pick("x_m").iter().map(|x| x * 100.0).collect();
        let shape = pick("shape");
        let (f150, f384) = (pick("frequency_ei150_hz")[0], pick("frequency_ei384_hz")[0]);
        if k == 1 {
            for i in 0..shape.len() - 1 {
                if shape[i] * shape[i + 1] < 0.0 {
                    let xn = x[i] + (x[i + 1] - x[i]) * shape[i] / (shape[i] - shape[i + 1]);
                    vlines.push(VLine { x: xn, label: format!("mode-1 node {} cm", fmt_sig(xn, 3)) });
                }
            }
        }
        let label = format!("mode {k}: {} Hz (EI 150), {} Hz (EI 384)", fmt_sig(f150, 4), fmt_sig(f384, 4));
        curves.push(line(label, x, shape, k - 1));
    }
    // the paper's node of the fundamental: where the mode-1 shape crosses zero
    let node = paper_label(&format!("fundamental node {} cm from the tip", paper_list(&["modes_node"])));
    curves.push(styled(line(node, vec![paper_value("modes_node")], vec![0.0], 0), LineStyle::Paper));
    Chart {
        title: "Free racket modes, N = 39 (p. 3-4): 125 / 345 Hz, node 16 cm; EI 384: 200 Hz".into(),
        x_label: "distance from the tip x (cm)".into(),
        y_label: "mode shape (max |y| = 1)".into(),
        y2_label: None,
        x_log: false,
        x_range: Some((0.0, 71.0)),
        y_range: Some((-1.1, 1.6)),
        y2_range: None,
        curves,
        vlines,
        bands: vec![],
        ..Chart::default()
    }
}
