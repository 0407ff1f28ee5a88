//! Model variants (issue 6): the rigid frame against its closed form and against the beam, the
//! hand with nothing in it against the free racket, stiffening strings with no stiffening
//! against linear ones, and the energy ledger of each.

use approx::assert_relative_eq;
use racket_impact::model::beam::Beam;
use racket_impact::model::reduced::clamped_drop;
use racket_impact::params::{Frame, Grip, Params, SolverKind, StringLaw};
use racket_impact::simulate;

fn paper_at(x: f64, r: f64) -> Params {
    let mut p = Params::paper();
    p.impact.x = x;
    p.impact.r = r;
    p
}

#[test]
fn rigid_frame_is_the_closed_form_rigid_body_collision() {
    for (x, r) in [(0.10, 0.05), (0.30, -0.02), (0.0, 0.0)] {
        let mut p = paper_at(x, r);
        p.variants.frame = Frame::Rigid;
        let res = simulate(&p).unwrap();
        // textbook: effective mass at the load point, COR of the ball on clamped strings
        let beam = Beam::new(&p.racket, p.numerics.segments);
        let b = res.x_load_m - beam.x_cm;
        let m_eff = 1.0 / (1.0 / beam.total_mass + b * b / beam.i_cm + r * r / p.racket.ix);
        let e = clamped_drop(&p.ball, &p.strings, p.impact.v1).e;
        let mb = p.ball.mass;
        assert_relative_eq!(res.e_a, (e * m_eff - mb) / (mb + m_eff), max_relative = 1e-12);
        assert_eq!(res.f_vib, 0.0);
        assert!(res.energy_error < 1e-14, "{res:?}");
    }
}

#[test]
fn rigid_frame_is_the_limit_of_a_very_stiff_beam() {
    let mut p = paper_at(0.10, 0.05);
    p.racket.ei = 1.0e6; // f1 about 10 kHz
    p.numerics.solver = SolverKind::Modal;
    let beam = simulate(&p).unwrap();
    p.variants.frame = Frame::Rigid;
    p.numerics.solver = SolverKind::Fd;
    let rigid = simulate(&p).unwrap();
    assert!(beam.f_vib < 1e-3, "{beam:?}");
    assert_relative_eq!(beam.e_a, rigid.e_a, max_relative = 2e-3);
    assert_relative_eq!(beam.tau_s, rigid.tau_s, max_relative = 2e-3);
    assert_relative_eq!(beam.theta_end_deg, rigid.theta_end_deg, max_relative = 2e-3);
}

#[test]
fn rigid_frame_matches_the_beam_at_the_node_within_the_vibration_it_ignores() {
    let at = |x: f64, frame: Frame| {
        let mut p = paper_at(x, 0.0);
        p.variants.frame = frame;
        simulate(&p).unwrap()
    };
    // the node of the N = 39 node scheme nearest the mode-1 node (15.8 cm)
    let node = 8.0 * 0.71 / 39.0;
    let (beam, rigid) = (at(node, Frame::Beam), at(node, Frame::Rigid));
    assert!((beam.e_a - rigid.e_a).abs() <= beam.f_vib, "{} vs {} (f_vib {})", beam.e_a, rigid.e_a, beam.f_vib);
    // near the tip the frame's vibration takes much of the energy and the rigid model is far off
    let (beam, rigid) = (at(0.0, Frame::Beam), at(0.0, Frame::Rigid));
    assert!(rigid.e_a - beam.e_a > 0.1, "{} vs {}", beam.e_a, rigid.e_a);
}

#[test]
fn an_empty_hand_is_the_free_racket() {
    for (x, r) in [(0.10, 0.05), (0.45, 0.0)] {
        let free = simulate(&paper_at(x, r)).unwrap();
        let mut p = paper_at(x, r);
        p.variants.grip = Grip::Hand;
        p.variants.hand_stiffness = 0.0;
        p.variants.hand_damping = 0.0;
        let held = simulate(&p).unwrap();
        assert_relative_eq!(held.e_a, free.e_a, max_relative = 1e-12);
        assert_relative_eq!(held.tau_s, free.tau_s, max_relative = 1e-12);
        assert_relative_eq!(held.theta_end_deg, free.theta_end_deg, max_relative = 1e-12);
        assert_relative_eq!(held.f_vib, free.f_vib, max_relative = 1e-12);
        // stepped on (a held racket has no modal closed form) against the closed form
        assert_relative_eq!(held.f_vib_peak_pe, free.f_vib_peak_pe, max_relative = 1e-5);
        assert_eq!(held.f_hand, 0.0);
    }
}

#[test]
fn the_hand_conserves_energy_with_its_loss_and_takes_momentum() {
    let mut p = paper_at(0.30, 0.02);
    p.variants.grip = Grip::Hand;
    p.variants.hand_stiffness = 5.0e4;
    p.variants.hand_damping = 100.0;
    let r = simulate(&p).unwrap();
    assert!(r.energy_error < 1e-5, "{r:?}");
    assert!(r.momentum_error < 1e-9, "momentum with the hand's impulse: {r:?}");
    assert!(r.f_hand > 0.01, "{r:?}");
    let sum = r.f_ke_ball + r.f_ball + r.f_rigid + r.f_vib + r.f_spin + r.f_hand;
    assert_relative_eq!(sum, 1.0, max_relative = 1e-5);
}

#[test]
fn stiffening_strings_with_no_stiffening_are_linear() {
    let linear = simulate(&Params::paper()).unwrap();
    let mut p = Params::paper();
    p.variants.strings = StringLaw::Stiffening;
    p.variants.string_stiffening = 0.0;
    assert_eq!(simulate(&p).unwrap(), linear);
    // a vanishing stiffening runs the nonlinear string solve and converges to the linear law
    p.variants.string_stiffening = 1e-9;
    let tiny = simulate(&p).unwrap();
    assert_relative_eq!(tiny.e_a, linear.e_a, max_relative = 1e-7);
    assert_relative_eq!(tiny.tau_s, linear.tau_s, max_relative = 1e-7);
}

#[test]
fn stiffening_strings_keep_the_ledger_and_shorten_a_fast_impact() {
    let mut p = paper_at(0.158, 0.0);
    p.impact.v1 = 50.0;
    let linear = simulate(&p).unwrap();
    p.variants.strings = StringLaw::Stiffening;
    let stiff = simulate(&p).unwrap();
    assert!(stiff.energy_error < 1e-5, "{stiff:?}");
    assert!(stiff.tau_s < linear.tau_s && stiff.peak_force_n > linear.peak_force_n);
    // the paper: 'of little consequence' -- a few per cent at most at 50 m/s
    assert!((stiff.e_a / linear.e_a - 1.0).abs() < 0.03, "{} vs {}", stiff.e_a, linear.e_a);
}

#[test]
fn unsupported_combinations_are_refused_with_the_reason() {
    let mut p = Params::paper();
    p.variants.frame = Frame::Rigid;
    p.variants.grip = Grip::Hand;
    assert!(simulate(&p).unwrap_err().to_string().starts_with("invalid frame = rigid"));
    let mut p = Params::paper();
    p.variants.strings = StringLaw::Stiffening;
    p.numerics.solver = SolverKind::Modal;
    assert!(simulate(&p).unwrap_err().to_string().starts_with("invalid solver = modal"));
    let mut p = Params::paper();
    p.variants.grip = Grip::Hand;
    p.variants.grip_length = 0.5;
    assert!(simulate(&p).unwrap_err().to_string().starts_with("invalid grip-length = 0.5"));
    // a free racket has no grip: short rackets keep working with the default grip length
    let mut p = Params::paper();
    p.racket.length = 0.25;
    p.impact.x = 0.1;
    simulate(&p).unwrap();
}

#[test]
fn the_default_hand_damps_the_fundamental_by_a_few_per_cent() {
    // the documented calibration of the default hand (params::Variants)
    let mut p = Params::paper();
    assert_eq!(racket_impact::solve::hand_damping_ratio(&p, 1), 0.0);
    p.variants.grip = Grip::Hand;
    let zeta = racket_impact::solve::hand_damping_ratio(&p, 1);
    eprintln!("default hand: mode-1 damping ratio {:.2} %", 100.0 * zeta);
    assert!((0.02..0.04).contains(&zeta), "{zeta}");
}
