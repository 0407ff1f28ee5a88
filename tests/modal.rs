//! The modal solver against the explicit reference: the same impacts, agreement to 1e-4 in
//! e_A, tau, theta and the energy fractions over a randomized set of positions, offsets,
//! string and frame stiffnesses, segment counts, both load rules and non-uniform rackets.

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use racket_impact::params::{LoadRule, Params, Profile, SolverKind};
use racket_impact::solve::{simulate, ImpactResult};

/// Relative agreement required: half the 1e-4 the solvers are specified to, so that a regression
/// of the size of the one pinned below (7e-5) fails here too (measured: 1.5e-5 over the random
/// set, 1.5e-5 over the grid). Quantities are compared relative to max(|value|, FLOOR) so a
/// fraction that is almost zero (vibration at the node) is held to TOL of FLOOR.
const TOL: f64 = 5e-5;
const FLOOR: f64 = 1e-2;

fn both(p: &Params) -> (ImpactResult, ImpactResult) {
    let mut m = *p;
    m.numerics.solver = SolverKind::Modal;
    (simulate(p).unwrap(), simulate(&m).unwrap())
}

/// The relative difference of each compared quantity, modal against fd, after checking it.
fn check(p: &Params) -> Vec<(&'static str, f64)> {
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
    let d: Vec<(&str, f64)> = pairs
        .iter()
        .map(|&(name, x, y, scale)| {
            let s = if scale == 1.0 { x.abs().max(FLOOR) } else { scale.abs() };
            (name, (x - y).abs() / s)
        })
        .collect();
    for &(name, rel) in &d {
        assert!(rel <= TOL, "{name}: relative difference {rel:e} at {p:?}");
    }
    // both solvers ask the same closed form (model::free) about re-contact, so this checks the
    // state each hands it; tests/physics.rs checks the closed form against stepping on
    assert_eq!(a.recontact, b.recontact, "{p:?}");
    assert!(b.momentum_error < 1e-9);
    d
}

fn params() -> impl Strategy<Value = Params> {
    let beam = (0.0..1.0f64, -0.10..0.10f64, 3.0..6.0f64, 50.0..1000.0f64, 8usize..60, prop::bool::ANY);
    // a third of the rackets are non-uniform: random density and stiffness at the four knots
    let profile =
        prop::option::weighted(1.0 / 3.0, (prop::array::uniform4(0.3..3.0f64), prop::array::uniform4(0.5..2.0f64)));
    // the ball too: hysteresis exponent over its whole range, stiffness, mass and speed
    let ball = (1.05..10.0f64, 3.5..5.0f64, 0.03..0.1f64, 2.0..60.0f64);
    (beam, profile, ball).prop_map(|((xf, r, log_ks, ei, segments, hat), profile, (exponent, log_k1, mb, v1))| {
        let mut p = Params::paper();
        p.ball.p = exponent;
        p.ball.k1 = 10f64.powf(log_k1);
        p.ball.mass = mb;
        p.impact.v1 = v1;
        p.impact.x = xf * p.racket.length;
        p.impact.r = r;
        p.strings.ks = 10f64.powf(log_ks);
        p.racket.ei = ei;
        p.racket.profile = profile.map(|(density, stiffness)| Profile {
            knots: [0.0, 0.45, 0.72, 1.0],
            density,
            stiffness,
            tilt: [0.0; 2],
        });
        p.numerics.segments = segments;
        p.numerics.load = if hat { LoadRule::Hat } else { LoadRule::Node };
        p
    })
}

/// 300 seeded random impacts (the same every run); prints the largest difference of each
/// quantity (`cargo test --test modal -- --nocapture`).
#[test]
fn modal_solver_agrees_with_the_explicit_one() {
    let config = Config { cases: 300, failure_persistence: None, ..Config::default() };
    let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]));
    let strategy = params();
    let mut worst: Vec<(&str, f64)> = Vec::new();
    for _ in 0..300 {
        let p = strategy.new_tree(&mut runner).unwrap().current();
        for (name, rel) in check(&p) {
            match worst.iter_mut().find(|(n, _)| *n == name) {
                Some(w) => w.1 = w.1.max(rel),
                None => worst.push((name, rel)),
            }
        }
    }
    let line: Vec<String> = worst.iter().map(|(n, w)| format!("{n} {w:.1e}")).collect();
    eprintln!("modal vs fd, largest relative difference over 300 cases: {}", line.join(", "));
}

#[test]
fn modal_solver_agrees_on_fine_beams() {
    for (n, x, ks) in [(160, 0.10, 4.0e4), (240, 0.03, 1.0e6), (320, 0.45, 2.0e4)] {
        let mut p = Params::paper();
        p.numerics.segments = n;
        p.numerics.load = LoadRule::Hat;
        p.impact.x = x;
        p.strings.ks = ks;
        check(&p);
    }
}

/// A regular grid over the face and the parameter ranges' corners (tip to butt, on and off the
/// axis, very soft to very stiff strings, soft and stiff frames, both load rules): 864 impacts,
/// each held to the same agreement as the random set.
#[test]
fn modal_solver_agrees_over_a_grid_of_impacts() {
    let mut grid = Vec::new();
    for i in 0..12 {
        for r in [0.0, 0.045, 0.09] {
            for ks in racket_impact::experiments::log_space(1e3, 1e6, 6) {
                for ei in [50.0, 1000.0] {
                    for load in [LoadRule::Node, LoadRule::Hat] {
                        let mut p = Params::paper();
                        p.impact.x = 0.01 + 0.69 * i as f64 / 11.0;
                        p.impact.r = r;
                        p.strings.ks = ks;
                        p.racket.ei = ei;
                        p.numerics.load = load;
                        grid.push(p);
                    }
                }
            }
        }
    }
    let modal: Vec<Params> = grid
        .iter()
        .map(|p| {
            let mut m = *p;
            m.numerics.solver = SolverKind::Modal;
            m
        })
        .collect();
    use rayon::prelude::*;
    let run = |ps: &[Params]| ps.par_iter().map(|p| simulate(p).unwrap()).collect::<Vec<_>>();
    let (a, b) = (run(&grid), run(&modal));
    let mut worst: f64 = 0.0;
    for ((p, a), b) in grid.iter().zip(&a).zip(&b) {
        let e_a = (a.e_a - b.e_a).abs() / a.e_a.abs().max(FLOOR);
        let f_vib = (a.f_vib - b.f_vib).abs() / a.f_vib.abs().max(FLOOR);
        let tau = (a.tau_s - b.tau_s).abs() / a.tau_s;
        let theta = (a.theta_end_deg - b.theta_end_deg).abs() / a.theta_end_deg.abs().max(FLOOR * 10.0);
        for (name, rel) in [("e_a", e_a), ("f_vib", f_vib), ("tau", tau), ("theta", theta)] {
            assert!(rel <= TOL, "{name}: relative difference {rel:e} at {p:?}");
            worst = worst.max(rel);
        }
        assert_eq!(a.recontact, b.recontact, "{p:?}");
    }
    eprintln!("modal vs fd over the grid: largest relative difference {worst:.1e}");
}

/// Regression: the step in which the ball leaves is checked at its quarter points, not only at
/// its midpoint (where the cubic and the law can both be near zero while the cubic dips below
/// zero later in the step). At this impact, found in a one-million-point sweep, the midpoint
/// check alone let e_A differ from fd by 7e-5 (relative to 1e-2); now it is within 1e-5.
#[test]
fn the_separation_step_is_checked_beyond_its_midpoint() {
    let mut p = Params::paper();
    p.impact.x = 0.02585858585858586;
    p.impact.r = 0.07171717171717172;
    p.strings.ks = 12915.496650148827;
    p.numerics.load = LoadRule::Hat;
    let (a, b) = both(&p);
    let rel = (a.e_a - b.e_a).abs() / a.e_a.abs().max(FLOOR);
    assert!(rel < 1e-5, "{rel:e}");
}

/// The modal solver's own discretisation: with every mode kept it converges to a finely stepped
/// explicit solution as its step shrinks, for the paper's impact and for very soft strings
/// (where the step refinement near separation matters most).
#[test]
fn modal_solver_converges_to_the_explicit_one_as_its_step_shrinks() {
    use racket_impact::solve::modal::{ModalModel, Resolution};
    for (x, ks) in [(0.16, 4.0e4), (0.03, 1.5e3)] {
        let mut p = Params::paper();
        p.impact.x = x;
        p.strings.ks = ks;
        p.numerics.load = LoadRule::Node;
        let mut fd = p;
        fd.numerics.dt = Some(2.5e-7);
        let reference = simulate(&fd).unwrap().e_a;
        let error = |phase_per_step: f64, impulse_tolerance: f64| {
            let res = Resolution { mode_cutoff: 1e9, phase_per_step, impulse_tolerance };
            (ModalModel::with_resolution(&p, res).unwrap().run().unwrap().e_a - reference).abs()
        };
        let (coarse, fine) = (error(0.4, 1e-6), error(0.025, 1e-9));
        assert!(fine < 1e-7, "x {x}, ks {ks}: {fine:e}");
        assert!(coarse > 10.0 * fine, "x {x}, ks {ks}: {coarse:e} vs {fine:e}");
    }
}

/// The compression phase in closed form, at its limits: on a frame too heavy and stiff to move,
/// the ball on the contact spring (`k = k1 k_s / (k1 + k_s)`) reaches maximum compression after
/// a quarter period, `pi/2 sqrt(m_b / k)`, with force `v1 sqrt(k m_b)`; and the rate of the
/// compression there is zero by construction, so the modal and explicit solvers place it at the
/// same time on the paper's racket.
#[test]
fn maximum_compression_is_the_closed_form_quarter_period_on_an_immovable_frame() {
    let mut p = Params::paper();
    p.numerics.solver = SolverKind::Modal;
    p.racket.mass = 1e6;
    p.racket.ix = 1e4;
    p.racket.ei = 1e9;
    let r = simulate(&p).unwrap();
    let k = p.ball.k1 * p.strings.ks / (p.ball.k1 + p.strings.ks);
    let quarter = 0.5 * std::f64::consts::PI * (p.ball.mass / k).sqrt();
    assert!((r.t_max_compression_s / quarter - 1.0).abs() < 1e-6, "{} vs {quarter}", r.t_max_compression_s);
    let peak = p.impact.v1 * (k * p.ball.mass).sqrt();
    assert!((r.peak_force_n / peak - 1.0).abs() < 1e-6, "{} vs {peak}", r.peak_force_n);

    let mut paper = Params::paper();
    paper.impact.r = 0.05;
    let (a, b) = both(&paper);
    assert!((a.t_max_compression_s - b.t_max_compression_s).abs() < 5e-5 * a.t_max_compression_s, "{a:?} {b:?}");
}
