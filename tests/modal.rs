//! The modal solver against the explicit reference: the same impacts, agreement to 1e-4 in
//! e_A, tau, theta and the energy fractions over a randomized set of positions, offsets,
//! string and frame stiffnesses, segment counts and both load rules.

use proptest::prelude::*;
use proptest::test_runner::Config;
use racket_impact::params::{LoadRule, Params, SolverKind};
use racket_impact::solver::{simulate, ImpactResult};

/// Relative agreement required; quantities are compared relative to max(|value|, FLOOR) so a
/// fraction that is almost zero (vibration at the node) is held to 1e-4 of FLOOR.
const TOL: f64 = 1e-4;
const FLOOR: f64 = 1e-2;

fn both(p: &Params) -> (ImpactResult, ImpactResult) {
    let mut m = *p;
    m.numerics.solver = SolverKind::Modal;
    (simulate(p).unwrap(), simulate(&m).unwrap())
}

fn check(p: &Params) -> std::result::Result<(), TestCaseError> {
    let (a, b) = both(p);
    let theta_scale = a.theta_end_deg.abs().max(FLOOR * 10.0);
    let pairs = [
        ("e_a", a.e_a, b.e_a, 1.0f64),
        ("tau", a.tau_s, b.tau_s, a.tau_s),
        ("theta", a.theta_end_deg, b.theta_end_deg, theta_scale),
        ("f_ball", a.f_ball, b.f_ball, 1.0),
        ("f_vib", a.f_vib, b.f_vib, 1.0),
        ("f_vib_peak_pe", a.f_vib_peak_pe, b.f_vib_peak_pe, 1.0),
        ("f_spin", a.f_spin, b.f_spin, 1.0),
        ("f_rigid", a.f_rigid, b.f_rigid, 1.0),
        ("f_ke_ball", a.f_ke_ball, b.f_ke_ball, 1.0),
    ];
    for (name, x, y, scale) in pairs {
        let s = if scale == 1.0 { x.abs().max(FLOOR) } else { scale.abs() };
        prop_assert!((x - y).abs() <= TOL * s, "{name}: fd {x} vs modal {y} ({:e})", (x - y).abs() / s);
    }
    prop_assert_eq!(a.recontact, b.recontact);
    prop_assert!(b.momentum_error < 1e-9);
    Ok(())
}

fn params() -> impl Strategy<Value = Params> {
    (0.0..1.0f64, -0.10..0.10f64, 3.0..6.0f64, 50.0..1000.0f64, 8usize..60, prop::bool::ANY).prop_map(
        |(xf, r, log_ks, ei, segments, hat)| {
            let mut p = Params::paper();
            p.impact.x = xf * p.racket.length;
            p.impact.r = r;
            p.strings.ks = 10f64.powf(log_ks);
            p.racket.ei = ei;
            p.numerics.segments = segments;
            p.numerics.load = if hat { LoadRule::Hat } else { LoadRule::Node };
            p
        },
    )
}

proptest! {
    // a fixed seed: CI runs the same 300 cases every time
    #![proptest_config(Config {
        cases: 300,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(20001122),
        ..Config::default()
    })]

    #[test]
    fn modal_solver_agrees_with_the_explicit_one(p in params()) {
        check(&p)?;
    }
}

#[test]
fn modal_solver_agrees_on_fine_beams() {
    for (n, x, ks) in [(160, 0.10, 4.0e4), (240, 0.03, 1.0e6), (320, 0.45, 2.0e4)] {
        let mut p = Params::paper();
        p.numerics.segments = n;
        p.numerics.load = LoadRule::Hat;
        p.impact.x = x;
        p.strings.ks = ks;
        check(&p).unwrap();
    }
}
