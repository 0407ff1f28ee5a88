//! `fig9_stiff_frame`: paper Fig 9, "As for Fig. 6 but for a stiffer racket with a fundamental
//! vibration frequency of 200 Hz" (EI = 384 N m^2, same mass and length).
//!
//! Model: the Fig 6 sweep (x = 6 cm, r = 0, N = 39 node scheme) for EI 384, with the EI 150
//! curves drawn faintly. Expect (p. 6): much smaller vibration loss near the tip, so e_A is
//! larger: "at k_s = 4e4, e_A is increased from 0.10 to 0.18, which translates ... to a 7%
//! increase in serve speed".

use super::fig6_string_stiffness::{stiffness_chart, stiffness_sweep};
use super::Experiment;

/// The registry entry.
pub const EXPERIMENT: Experiment = Experiment {
    id: "fig9_stiff_frame",
    title: "Fig 6 for a wide-body frame, EI 384 N m^2 (200 Hz), with EI 150 for comparison",
    paper_ref: "Fig 9 and p. 6: at ks 4e4, e_A 0.10 -> 0.18, serve speed +7 %",
    run: || stiffness_sweep(EXPERIMENT.id, &[super::frame_ei(384.0), super::frame_ei(150.0)]),
    chart: |t| {
        stiffness_chart(
            t,
            "Fig 9: stiff frame EI 384 N m^2 (200 Hz), x 6 cm, r 0; faint: EI 150",
            Some(super::frame_ei(150.0)),
        )
    },
};
