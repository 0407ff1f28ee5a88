//! The tangential-contact mechanisms (SPEC.md section 6, "Mechanisms"): the elastic law kept bit
//! for bit, the limits each mechanism must meet, the ledger with the named losses, and fd
//! against modal.

use racket_impact::params::{Overrides, Params, SolverKind, StringName, TangentialLaw};
use racket_impact::solve::{simulate, ImpactResult};

const RPM: f64 = std::f64::consts::PI / 30.0;
const SOLVERS: [SolverKind; 2] = [SolverKind::Fd, SolverKind::Modal];
const LAWS: [TangentialLaw; TangentialLaw::ALL.len()] = TangentialLaw::ALL;

/// The TWU "String Movement and Spin" shot on a frame too heavy to move: 25.03 m/s at 40 deg
/// across the face with 3820 rpm of backspin, 52 lb (ks = 4e4 x 52/60 N/m), at the centre,
/// with the tangential stiffness of the mechanisms' introduction (2e4 N/m; the default is now
/// calibrated, experiment spin_calibration): the impacts the pins below were taken on.
fn twu(law: TangentialLaw, solver: SolverKind) -> Params {
    let mut p = cli_defaults();
    (p.racket.mass, p.racket.ix) = (1.0e6, 1.0e4);
    (p.impact.v1, p.oblique.angle_deg, p.oblique.azimuth_deg, p.oblique.spin_rpm) = (25.03, 40.0, 90.0, -3820.0);
    p.oblique.kt = 2.0e4;
    p.strings.ks = 34667.0;
    p.oblique.tangential = law;
    p.numerics.solver = solver;
    p
}

/// The parameters the commands start from (the paper's racket hit at the face centre).
fn cli_defaults() -> Params {
    racket_impact::racket::resolve(None, &Overrides::default()).unwrap().0
}

fn rel(a: f64, b: f64, floor: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(floor)
}

/// `elastic` is the law before the mechanisms, bit for bit: these are the outputs of the crate
/// at commit cf0bc08 (before issue 22) for the same impacts (fd; modal since its last-piece fix).
#[test]
fn the_elastic_law_is_todays_bit_for_bit() {
    let r = simulate(&twu(TangentialLaw::Elastic, SolverKind::Fd)).unwrap();
    assert_eq!(r.spin_out_rpm, f64::from_bits(0x40AA_2365_DC5B_E6F6), "{}", r.spin_out_rpm);
    assert_eq!(r.v2_t, f64::from_bits(0x4003_C150_1601_3418), "{}", r.v2_t);
    let mut p = cli_defaults();
    (p.impact.x, p.impact.r, p.numerics.solver) = (0.3, 0.03, SolverKind::Modal);
    (p.oblique.angle_deg, p.oblique.spin_rpm, p.oblique.azimuth_deg) = (55.0, 2000.0, 33.0);
    (p.oblique.tangential, p.oblique.kt) = (TangentialLaw::Elastic, 2.0e4);
    let r = simulate(&p).unwrap();
    // the modal solver's own change since (issue 29): its last piece of the force history ends
    // at the separation with no force and no rate, as the explicit solver's always did
    // (before: 0x409B_F8B8_4946_90F4 and 0x4018_B9DB_2EEA_F727, 5e-10 and 1e-10 away)
    assert_eq!(r.spin_out_rpm, f64::from_bits(0x409B_F8B8_4986_AF5A), "{}", r.spin_out_rpm);
    assert_eq!(r.v2_t, f64::from_bits(0x4018_B9DB_2ECB_C467), "{}", r.v2_t);
    // and names no new loss
    assert!(r.f_tangential_damping.is_nan() && r.f_string_sliding.is_nan() && r.f_rolling.is_nan());
}

/// The model's numbers for the TWU shot, each mechanism alone and all four (fd), pinned: a
/// change of any mechanism shows here. (Measured: 1207-1803 rpm over seven strings.)
#[test]
fn the_twu_shot_under_each_law() {
    let expect = [
        (TangentialLaw::Elastic, 3345.70),
        (TangentialLaw::Loss, 2448.59),
        (TangentialLaw::Offset, 3246.87),
        (TangentialLaw::Bed, 3723.53),
        (TangentialLaw::Radius, 2314.05),
        (TangentialLaw::Physical, 2343.42),
    ];
    for (law, spin) in expect {
        let r = simulate(&twu(law, SolverKind::Fd)).unwrap();
        assert!((r.spin_out_rpm - spin).abs() < 0.01, "{law:?}: {}", r.spin_out_rpm);
    }
}

/// Each mechanism acts in its stated direction on a gripping ball: the tangential damper and
/// the offset normal force take spin off (they oppose the tangential spring's give-back and
/// the spin), the sliding bed adds it (its snap-back), and a bed whose strings cannot slide
/// (string/string friction far above any normal load share) is the elastic law itself.
#[test]
fn each_mechanism_moves_the_spin_its_way_and_a_locked_bed_is_the_elastic_law() {
    let spin = |law, f: &dyn Fn(&mut racket_impact::params::Params)| {
        let mut p = twu(law, SolverKind::Fd);
        f(&mut p);
        simulate(&p).unwrap().spin_out_rpm
    };
    let elastic = spin(TangentialLaw::Elastic, &|_| {});
    assert!(spin(TangentialLaw::Loss, &|_| {}) < elastic - 50.0);
    assert!(spin(TangentialLaw::Offset, &|_| {}) < elastic - 50.0);
    assert!(spin(TangentialLaw::Bed, &|_| {}) > elastic + 50.0);
    let locked = spin(TangentialLaw::Bed, &|p| p.oblique.mu_ss = 2.0);
    assert!((locked - elastic).abs() < 1e-6 * elastic.abs(), "{locked} vs {elastic}");
}

/// Without friction no law changes the ball's tangential speed or its spin.
#[test]
fn without_friction_no_law_changes_the_spin() {
    for law in LAWS {
        for solver in SOLVERS {
            let mut p = twu(law, solver);
            p.oblique.mu = 0.0;
            let r = simulate(&p).unwrap();
            assert_eq!(r.spin_out_rpm, -3820.0, "{law:?} {solver:?}");
            assert_eq!(r.v2_t, 25.03 * 40f64.to_radians().sin(), "{law:?} {solver:?}");
        }
    }
}

/// A rigid ball on an immovable frame with stiff strings: every mechanism fades out (the
/// compression, and with it the offset arm and the shorter lever, goes to zero; the lateral bed
/// is stiff) and the closed forms of SPEC.md section 6 hold: sliding throughout under every
/// law (to within twice the compression over the radius for the two mechanisms that depend on
/// it), leaving rolling under the others.
#[test]
fn a_rigid_ball_on_an_immovable_frame_meets_the_closed_forms_under_every_law() {
    for law in LAWS {
        for solver in SOLVERS {
            // slides throughout: v_t' = v_t - mu J_n / m_b, omega' = omega + mu J_n R / I
            let mut p = twu(law, solver);
            (p.ball.k1, p.strings.ks, p.oblique.kt, p.racket.ei) = (3.0e8, 3.0e8, 1.0e9, 1.0e9);
            p.oblique.ball_kdyn = 3.0e8;
            (p.oblique.angle_deg, p.oblique.spin_rpm, p.oblique.mu) = (60.0, 0.0, 0.1);
            let r = simulate(&p).unwrap();
            let (mb, radius) = (p.ball.mass, p.oblique.ball_radius);
            let tol = |base: f64| {
                if law.has(TangentialLaw::Radius) || law.has(TangentialLaw::Offset) {
                    2.0 * r.y0_m / radius
                } else {
                    base
                }
            };
            assert!(r.y0_m / radius < 0.02, "a rigid ball: {}", r.y0_m);
            let inertia = p.oblique.ball_inertia_factor * mb * radius * radius;
            let v_t = p.impact.v1 * 60f64.to_radians().sin();
            let j_n = mb * (p.impact.v1 * 60f64.to_radians().cos() + r.v2_n);
            assert!((r.slip_fraction - 1.0).abs() < 1e-12, "{law:?} {solver:?}: {}", r.slip_fraction);
            assert!(rel(r.v2_t, v_t - 0.1 * j_n / mb, 0.0) < 1e-6, "{law:?} {solver:?}");
            let spin = 0.1 * j_n * radius / inertia;
            assert!(
                rel(r.spin_out_rpm * RPM, spin, 0.0) < tol(1e-6),
                "{law:?} {solver:?}: {} vs {spin}",
                r.spin_out_rpm * RPM
            );
        }
    }
    // grips on stiff strings: leaves rolling, v_t' = (v_t + alpha R omega) / (1 + alpha); for
    // the mechanisms that do not need the compression (the grip phase lasts many periods of
    // the stiff tangential spring only on the paper's soft ball)
    for law in [TangentialLaw::Elastic, TangentialLaw::Loss, TangentialLaw::Bed] {
        for solver in SOLVERS {
            let mut p = twu(law, solver);
            (p.strings.ks, p.oblique.kt, p.racket.ei) = (3.0e8, 1.0e9, 1.0e9);
            let radius = p.oblique.ball_radius;
            for spin in [0.0, -1500.0, 1500.0] {
                (p.oblique.angle_deg, p.oblique.spin_rpm, p.oblique.mu) = (20.0, spin, 1.0);
                let r = simulate(&p).unwrap();
                let alpha = p.oblique.ball_inertia_factor;
                let v_t = p.impact.v1 * 20f64.to_radians().sin();
                let rolling = (v_t + alpha * radius * spin * RPM) / (1.0 + alpha);
                assert!(rel(r.v2_t, rolling, 0.0) < 1e-3, "{law:?} {solver:?} {spin}: {} vs {rolling}", r.v2_t);
                assert!(rel(r.spin_out_rpm * RPM * radius, r.v2_t, 0.0) < 1e-3, "{law:?} {solver:?} {spin}");
            }
        }
    }
}

/// Impacts over a grid of angles, spins, frictions, tensions and places on a free racket.
fn grid(law: TangentialLaw) -> Vec<Params> {
    let mut out = Vec::new();
    for (i, angle) in [10.0, 30.0, 45.0, 65.0].into_iter().enumerate() {
        for (j, spin) in [-3000.0, 0.0, 2500.0].into_iter().enumerate() {
            for (k, mu) in [0.2, 0.45, 0.8].into_iter().enumerate() {
                let mut p = Params::default();
                p.impact.x = [0.1, 0.16, 0.25][(i + j) % 3];
                p.impact.r = [0.0, 0.03, -0.05][(j + k) % 3];
                p.impact.v1 = [12.0, 25.0, 40.0][(i + k) % 3];
                p.strings.ks = [2.0e4, 4.0e4, 6.0e4][(i + j + k) % 3];
                p.oblique.angle_deg = angle;
                p.oblique.azimuth_deg = [0.0, 90.0, 35.0][k];
                p.oblique.spin_rpm = spin;
                p.oblique.mu = mu;
                p.oblique.mu_ss = [0.05, 0.1, 0.2][i % 3];
                p.oblique.tangential = law;
                // the kt this grid was set at (the calibrated default until the rule's choice moved
                // it to 5e5 N/m: there one point under loss, x 0.1 m, 40 m/s at 30 deg with 2500
                // rpm, parts fd and modal by 1.17e-4 in slip fraction; tests/oblique.rs draws kt)
                p.oblique.kt = 1.18e5;
                out.push(p);
            }
        }
    }
    out
}

/// The energy ledger closes with the losses named (each never negative, each zero when its
/// mechanism is off), and fd and modal agree to 1e-4 under every law.
#[test]
fn the_ledger_closes_and_fd_and_modal_agree_under_every_law() {
    let losses = |r: &ImpactResult| [r.f_friction, r.f_tangential_damping, r.f_string_sliding, r.f_rolling];
    for law in LAWS {
        for p in grid(law) {
            let mut q = p;
            q.numerics.solver = SolverKind::Modal;
            let (a, b) = (simulate(&p).unwrap(), simulate(&q).unwrap());
            for r in [&a, &b] {
                assert!(r.energy_error < 1e-6, "{law:?} {p:?}: {}", r.energy_error);
                let l = losses(r);
                if law == TangentialLaw::Elastic {
                    assert!(l[1].is_nan() && l[2].is_nan() && l[3].is_nan());
                } else {
                    assert!(l.iter().all(|&x| x >= 0.0), "{law:?}: {l:?}");
                    for (i, m) in [(1, TangentialLaw::Loss), (2, TangentialLaw::Bed), (3, TangentialLaw::Offset)] {
                        if !law.has(m) {
                            assert_eq!(l[i], 0.0, "{law:?} {l:?}");
                        }
                    }
                }
            }
            // relative to the value or, near zero, to the scale of the impact: 1 % of v1 (of the
            // rolling spin v1/R, of a fraction) or the incoming spin, which a spin that is
            // turned round passes through
            let v = p.impact.v1;
            let spin_scale = (1e-2 * v / p.oblique.ball_radius / RPM).max(p.oblique.spin_rpm.abs());
            let d = [
                rel(a.v2_t, b.v2_t, 1e-2 * v),
                rel(a.spin_out_rpm, b.spin_out_rpm, spin_scale),
                (a.slip_fraction - b.slip_fraction).abs(),
                rel(a.f_friction, b.f_friction, 1e-2),
            ];
            assert!(d.iter().all(|&x| x <= 1e-4), "{law:?} {d:?} at {p:?}");
        }
    }
}

/// A named string sets the friction of its database entry, the gut its material's median; the
/// elastic law ignores the string-to-string friction.
#[test]
fn a_named_string_sets_its_friction() {
    let mut p = twu(TangentialLaw::Physical, SolverKind::Modal);
    p.oblique.string = StringName::Tcs16;
    assert_eq!(p.oblique.friction(), (0.387, 0.088));
    p.oblique.string = StringName::Nxt16;
    assert_eq!(p.oblique.friction(), (0.453, 0.117));
    p.oblique.string = StringName::TonicGut16;
    assert_eq!(p.oblique.friction(), (0.412, 0.161));
    let mut e = twu(TangentialLaw::Elastic, SolverKind::Modal);
    let a = simulate(&e).unwrap();
    e.oblique.mu_ss = 0.3;
    assert_eq!(simulate(&e).unwrap(), a);
}

/// Run the binary; exit code, stdout, stderr.
fn cli(args: &[&str]) -> (Option<i32>, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_racket-impact")).args(args).output().unwrap();
    (out.status.code(), String::from_utf8_lossy(&out.stdout).into(), String::from_utf8_lossy(&out.stderr).into())
}

/// `--string`: an unknown name is one line listing the known ones (exit 2, no result), a
/// `--mu` beside a string that sets it is refused, the name works in a config file, a command
/// that has no use for it refuses it, and so does `simulate` at normal incidence.
#[test]
fn the_string_option_is_used_or_refused() {
    let (code, out, err) = cli(&["simulate", "--string", "bogus", "--angle-deg", "30"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty() && err.trim_end().lines().count() == 1, "{err}");
    assert!(err.contains("--string") && err.contains("tcs-16") && err.contains("nxt-16"), "{err}");
    let (code, out, err) = cli(&["simulate", "--string", "tcs-16", "--mu", "0.5", "--angle-deg", "30"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty() && err.trim_end().lines().count() == 1 && err.contains("mu"), "{err}");
    let (code, _, err) = cli(&["modes", "--string", "tcs-16"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("string"), "{err}");
    let dir = std::env::temp_dir().join(format!("racket-impact-string-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cfg = dir.join("c.toml");
    std::fs::write(&cfg, "string = \"alu-rough-16\"\ntangential = \"physical\"\nangle-deg = 30\n").unwrap();
    let (code, out, err) = cli(&["simulate", "--config", cfg.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(code, Some(0), "{err}");
    // the echo lists each parameter under its heading, the string's friction among them
    for shown in [
        "mu 0.498",
        "tangential physical",
        "mu-ss 0.077",
        "string alu-rough-16",
        "ball-ex 0.135",
        "ball-kdyn 78905.1 N/m",
    ] {
        assert!(out.contains(shown), "{shown}: {out}");
    }
    // each law echoes only the parameters it uses
    let law_parameters = ["mu-ss ", "ball-ex ", "ball-kdyn "];
    for (law, shown) in [
        ("elastic", &[][..]),
        ("loss", &["ball-ex 0.135"][..]),
        ("bed", &["mu-ss 0.08"][..]),
        ("radius", &["ball-kdyn 78905.1 N/m"][..]),
        ("offset", &["ball-kdyn 78905.1 N/m"][..]),
    ] {
        let (code, out, err) = cli(&["simulate", "--angle-deg", "30", "--tangential", law]);
        assert_eq!(code, Some(0), "{err}");
        assert!(out.contains(&format!("tangential {law}\n")), "{law}: {out}");
        for key in law_parameters {
            let expected = shown.iter().find(|s| s.starts_with(key));
            assert_eq!(out.contains(key), expected.is_some(), "{law} {key}: {out}");
            assert!(expected.is_none_or(|s| out.contains(s)), "{law} {key}: {out}");
        }
    }
    // at normal incidence no tangential force acts: the flags describe the ball and strings a
    // script sets once, so they run with one note each saying they are not exercised
    // (params::used; each note a diagnostic of its own, one line on stderr)
    let (code, out, err) = cli(&["simulate", "--tangential", "physical", "--string", "tcs-16"]);
    assert_eq!(code, Some(0), "{err}");
    let lines: Vec<&str> = err.trim_end().lines().collect();
    assert!(!out.is_empty() && lines.len() == 2, "{err}");
    for (line, flag) in lines.iter().zip(["--tangential physical", "--string tcs-16"]) {
        assert!(
            line.starts_with(&format!("warning: {flag} is not exercised by this impact"))
                && line.contains("oblique or spinning ball"),
            "{err}"
        );
    }
    // and --mu-ss only by a law with the sliding string bed: a property of the strings, which
    // the default law does not exercise, so it runs with one note (issue 39)
    let (code, _, err) = cli(&["simulate", "--angle-deg", "30", "--mu-ss", "0.1"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.trim_end().lines().count() == 1
            && err.starts_with("warning: --mu-ss 0.1 is not exercised by this impact")
            && err.contains("tangential = bed or physical"),
        "{err}"
    );
    let (code, _, err) = cli(&["simulate", "--angle-deg", "30", "--mu-ss", "0.1", "--tangential", "bed"]);
    assert_eq!(code, Some(0), "{err}");
    // a sweep over mu beside a string that sets it would be the string's value at every point
    let (code, out, err) = cli(&["sweep", "--string", "alu-rough-16", "--angle-deg", "30", "--mu", "0.2,0.4"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty() && err.contains("mu") && err.contains("set by string = alu-rough-16"), "{err}");
    let (code, _, err) = cli(&["sweep", "--string", "tcs-16,nxt-16", "--angle-deg", "30"]);
    assert_eq!(code, Some(0), "{err}");
}

/// Issue 32, trap class 1: over the whole accepted range of the ball's inertia factor (0.1 to
/// the thin shell's 2/3), soft to stiff tangential springs, light to heavy balls, both solvers
/// and both laws, every impact comes back with a result whose energy error (the normal ledger's
/// and the tangential one's) is within the limit every result is held to; none is refused.
#[test]
fn every_accepted_ball_passes_the_energy_check() {
    let limit = racket_impact::solve::ENERGY_ERROR_LIMIT;
    for solver in [SolverKind::Fd, SolverKind::Modal] {
        for law in [TangentialLaw::Elastic, TangentialLaw::Physical] {
            for alpha in [0.1, 0.4, 0.55, 2.0 / 3.0] {
                for (kt, mb) in [(1.0e3, 0.057), (2.0e4, 0.057), (1.0e8, 0.057), (2.0e4, 0.01), (2.0e4, 0.3)] {
                    let mut p = Params::default();
                    p.numerics.solver = solver;
                    p.oblique.tangential = law;
                    (p.oblique.angle_deg, p.oblique.spin_rpm) = (30.0, 2000.0);
                    (p.oblique.ball_inertia_factor, p.oblique.kt, p.ball.mass) = (alpha, kt, mb);
                    let r = simulate(&p).unwrap_or_else(|e| panic!("{solver:?} {law:?} {alpha} {kt} {mb}: {e}"));
                    assert!(r.energy_error <= limit, "{solver:?} {law:?} {alpha} {kt} {mb}: {}", r.energy_error);
                    assert!(r.spin_out_rpm.abs() < 1e5, "{solver:?} {law:?} {alpha}: spin {}", r.spin_out_rpm);
                }
            }
        }
    }
}

/// What the dynamic stiffness `ball-kdyn` gives at the 100-inch drop it comes from (data/measured
/// M081-M082). Its derivation treats the ball as a linear spring that stores the drop's
/// energy at 6 mm on concrete; the model's normal force follows the paper's k1 law instead, so
/// `F_model / ball-kdyn` is about 3.7 mm on a rigid bed (measured 6) and 2.8 mm on 60 lb
/// strings (measured about 3). Pinned as computed (fd), not as measured.
#[test]
fn the_dynamic_stiffness_at_the_drop_gives_what_the_model_computes() {
    use racket_impact::model::tangential::compression::Compression;
    use racket_impact::params::oblique::{kdyn_from_drop, BALL_KDYN};
    use racket_impact::params::{drop_speed, DROP_HEIGHT_100_IN};
    let v = drop_speed(DROP_HEIGHT_100_IN);
    let m = cli_defaults().ball.mass;
    // the derivation: a linear spring of BALL_KDYN stores m v^2 / 2 at 6 mm
    assert_eq!(BALL_KDYN, kdyn_from_drop(m, 0.006));
    assert!((v * (m / BALL_KDYN).sqrt() - 0.006).abs() < 1e-12);
    // the model: peak force on a frame too heavy to move, then the mechanisms' compression
    let compression = |ks: f64| {
        let mut p = cli_defaults();
        p.racket.mass = 1.0e6;
        p.racket.ix = 1.0e4;
        p.strings.ks = ks;
        p.impact.v1 = v;
        p.numerics.solver = SolverKind::Fd;
        let peak = simulate(&p).unwrap().peak_force_n;
        let c = Compression { k: BALL_KDYN, p: p.ball.p, radius: p.oblique.ball_radius };
        (peak, c.delta(peak, peak))
    };
    let (concrete, on_concrete) = compression(1.0e12);
    assert!((concrete - 291.95).abs() < 0.05 && (on_concrete - 3.700e-3).abs() < 2e-6, "{concrete} N, {on_concrete} m");
    let (strings, on_strings) = compression(4.0e4);
    assert!((strings - 220.70).abs() < 0.05 && (on_strings - 2.797e-3).abs() < 2e-6, "{strings} N, {on_strings} m");
    // a single linear law through the model's forces and the measured 6 and 3 mm would need
    // about 48.7 and 73.6 kN/m
    assert!((concrete / 0.006 - 48.66e3).abs() < 10.0 && (strings / 0.003 - 73.57e3).abs() < 20.0);
}
