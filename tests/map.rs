//! String-face maps (`racket-impact map`): every value is a single `simulate` run, every row is
//! on the face, the maximum and the difference map are what they claim, the heat map survives
//! degenerate fields, the CLI refuses bad input with one line and exit code 2 and writes
//! nothing, runs are byte-identical, and the maps committed in figures/ are current.

mod common;

use common::{bin, run, Scratch};
use std::path::Path;

use racket_impact::params::{ks_from_tension_lb, LoadRule, Overrides, Params};
use racket_impact::render::heatmap::{self, contour_segments, HeatMap};
use racket_impact::study::map::{params_at, DiffMap, Face, FaceMap, Quantity};
use racket_impact::{racket, simulate};

fn preset(name: &str) -> Params {
    racket::resolve(Some(&racket::load(name).unwrap()), &Overrides::default()).unwrap().0
}

fn paper_node() -> Params {
    let mut p = Params::default();
    p.numerics.load = LoadRule::Node;
    p
}

#[test]
fn map_values_are_single_simulate_runs() {
    for p in [paper_node(), preset("tweener")] {
        let m = FaceMap::compute(&p, 9, 7, &mut |_| {}).unwrap();
        let t = m.table();
        assert_eq!(t.len(), m.len());
        assert!(m.len() > 20, "{}", m.len());
        let cols: Vec<Vec<f64>> = Quantity::ALL.iter().map(|q| t.column(q.column()).unwrap()).collect();
        let (xs, rs) = (t.column("x_m").unwrap(), t.column("r_m").unwrap());
        let recontact = t.column("recontact").unwrap();
        // several rows spread over the table, including the first and the last
        for i in [0, 1, t.len() / 3, t.len() / 2, 2 * t.len() / 3, t.len() - 1] {
            let single = simulate(&params_at(&m.params, xs[i], rs[i])).unwrap();
            for (q, col) in Quantity::ALL.iter().zip(&cols) {
                assert_eq!(col[i], q.column_value(&single), "{} at row {i}", q.name());
            }
            assert_eq!(recontact[i], f64::from(u8::from(single.recontact)));
        }
        // every stored result is the single run (all fields)
        for (x, r, res) in m.points() {
            assert_eq!(*res, simulate(&params_at(&m.params, x, r)).unwrap(), "x = {x}, r = {r}");
        }
    }
}

#[test]
fn every_row_is_inside_the_face_and_rows_are_row_major() {
    for p in [paper_node(), preset("tweener"), preset("players")] {
        let m = FaceMap::compute(&p, 11, 9, &mut |_| {}).unwrap();
        let face = Face::of(&p.racket);
        let t = m.table();
        let (xs, rs) = (t.column("x_m").unwrap(), t.column("r_m").unwrap());
        for (&x, &r) in xs.iter().zip(&rs) {
            assert!(face.contains(x, r), "({x}, {r}) outside the face");
            assert!(x > 0.0 && x < face.length);
            params_at(&p, x, r).validate().unwrap();
            if let Some(w) = p.racket.face_half_width(x) {
                assert!(r.abs() <= w);
            }
        }
        // x slowest, then r, both ascending
        for k in 1..xs.len() {
            assert!(xs[k] > xs[k - 1] || (xs[k] == xs[k - 1] && rs[k] > rs[k - 1]), "row {k}");
        }
        // and no inside grid point is missing
        let inside = m.grid.inside(&[face]).len();
        assert_eq!(inside, t.len());
    }
}

#[test]
fn max_point_and_node() {
    let p = preset("tweener");
    let m = FaceMap::compute(&p, 13, 9, &mut |_| {}).unwrap();
    let t = m.table();
    let e_a = t.column("e_a").unwrap();
    let best = m.max_point(Quantity::EA).unwrap();
    let col_max = e_a.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(best.value, col_max);
    let i = e_a.iter().position(|&v| v == col_max).unwrap();
    assert_eq!((best.x_m, best.r_m), (t.column("x_m").unwrap()[i], t.column("r_m").unwrap()[i]));
    // the power column is 100 e_A, and its maximum is at the same point
    let power = m.max_point(Quantity::Power).unwrap();
    assert_eq!((power.x_m, power.r_m, power.value), (best.x_m, best.r_m, 100.0 * best.value));
    // the node: the mode-1 node nearest the head, inside the face
    let node = m.node_x().unwrap();
    assert_eq!(node, m.mode1_nodes[0]);
    assert!(node > 0.0 && node < m.face.length);
    let (x, at) = m.at_node().unwrap().unwrap();
    assert_eq!(x, node);
    assert_eq!(at, simulate(&params_at(&m.params, node, 0.0)).unwrap());
}

/// A map runs the modal solver whenever the model variants allow it and says so; its values
/// agree with the explicit reference's to 1e-4 (the agreement tests/modal.rs holds it to); a
/// hand grip or stiffening strings keep the explicit solver.
#[test]
fn map_uses_the_modal_solver_where_the_variants_allow_it() {
    use racket_impact::params::{Grip, SolverKind, StringLaw};
    let p = paper_node();
    let m = FaceMap::compute(&p, 7, 5, &mut |_| {}).unwrap();
    assert_eq!(m.params.numerics.solver, SolverKind::Modal);
    let summary = racket_impact::study::map::summary::map_summary(&m, Quantity::Power, "paper").unwrap();
    assert!(summary.lines().next().unwrap().ends_with(", modal solver"), "{summary}");
    let meta = m.metadata("paper", Quantity::Power, (7, 5)).unwrap();
    assert_eq!(meta["a"]["solver"], "modal");
    let mut fd = p;
    fd.numerics.solver = SolverKind::Fd;
    let mut worst: f64 = 0.0;
    for (x, r, res) in m.points() {
        let reference = simulate(&params_at(&fd, x, r)).unwrap();
        for q in [Quantity::EA, Quantity::FVib] {
            worst = worst.max((q.of(res) - q.of(&reference)).abs());
        }
    }
    assert!(worst > 0.0 && worst < 1e-4, "modal against fd over the map: {worst:e}");
    for (grip, strings) in [(Grip::Hand, StringLaw::Linear), (Grip::Free, StringLaw::Stiffening)] {
        let mut q = p;
        (q.variants.grip, q.variants.strings) = (grip, strings);
        let m = FaceMap::compute(&q, 3, 3, &mut |_| {}).unwrap();
        assert_eq!(m.params.numerics.solver, SolverKind::Fd, "{grip:?} {strings:?}");
        assert_eq!(m.metadata("x", Quantity::Power, (3, 3)).unwrap()["a"]["solver"], "fd");
    }
}

#[test]
fn difference_map_is_b_minus_a() {
    let a = preset("tweener");
    let mut b = a;
    b.strings.ks = ks_from_tension_lb(60.0);
    let d = DiffMap::compute(&a, &b, 9, 7, &mut |_| {}).unwrap();
    for q in Quantity::ALL {
        let t = d.table(q);
        let c = q.column();
        let (va, vb) = (t.column(&format!("{c}_a")).unwrap(), t.column(&format!("{c}_b")).unwrap());
        let diff = t.column(&format!("{c}_b_minus_a")).unwrap();
        let (xs, rs) = (t.column("x_m").unwrap(), t.column("r_m").unwrap());
        for i in 0..t.len() {
            assert_eq!(diff[i], vb[i] - va[i]);
        }
        // A and B are single runs of each configuration
        for i in [0, t.len() / 2, t.len() - 1] {
            assert_eq!(va[i], q.column_value(&simulate(&params_at(&d.a.params, xs[i], rs[i])).unwrap()));
            assert_eq!(vb[i], q.column_value(&simulate(&params_at(&d.b.params, xs[i], rs[i])).unwrap()));
        }
    }
    // two rackets with different faces: only points inside both
    let (pa, pb) = (preset("tweener"), preset("players"));
    let d = DiffMap::compute(&pa, &pb, 11, 9, &mut |_| {}).unwrap();
    let (fa, fb) = (Face::of(&pa.racket), Face::of(&pb.racket));
    assert_ne!(fa, fb);
    let t = d.table(Quantity::EA);
    assert_eq!(t.len(), d.len());
    for (x, r) in t.column("x_m").unwrap().into_iter().zip(t.column("r_m").unwrap()) {
        assert!(fa.contains(x, r) && fb.contains(x, r));
    }
    assert_eq!(t.len(), d.a.grid.inside(&[fa, fb]).len());
}

#[test]
fn marching_squares_on_a_linear_field_gives_straight_segments() {
    // z = 3 x - y on a 6 x 5 grid: the contour z = 2 is the line y = 3 x - 2
    let xs: Vec<f64> = (0..6).map(|i| 0.5 * i as f64).collect();
    let ys: Vec<f64> = (0..5).map(|j| j as f64 - 2.0).collect();
    let z: Vec<f64> = xs.iter().flat_map(|&x| ys.iter().map(move |&y| 3.0 * x - y)).collect();
    let segs = contour_segments(&xs, &ys, &z, 2.0);
    assert!(!segs.is_empty());
    for s in &segs {
        for &(x, y) in s {
            assert!((y - (3.0 * x - 2.0)).abs() < 1e-12, "({x}, {y}) is off the line");
        }
    }
    // a field constant along y gives vertical segments at the interpolated x
    let z: Vec<f64> = xs.iter().flat_map(|&x| ys.iter().map(move |_| x * x)).collect();
    let segs = contour_segments(&xs, &ys, &z, 2.0);
    assert_eq!(segs.len(), ys.len() - 1, "one segment per cell row");
    let x = 1.0 + (1.0 / 1.25) * 0.5; // between z(1.0) = 1 and z(1.5) = 2.25
    for s in segs {
        assert_eq!((s[0].0, s[1].0), (x, x));
    }
}

#[test]
fn degenerate_heat_maps_render() {
    let dir = Scratch::new("degenerate");
    let nan = HeatMap {
        xs: vec![0.0, 1.0, 2.0],
        ys: vec![-1.0, 0.0, 1.0],
        z: vec![f64::NAN; 9],
        title: "all NaN".into(),
        ..HeatMap::default()
    };
    heatmap::render_png("nan", &nan, Path::new(&dir.arg("nan.png"))).unwrap();
    let constant = HeatMap { z: vec![0.25; 9], title: "constant".into(), ..nan.clone() };
    heatmap::render_png("const", &constant, Path::new(&dir.arg("const.png"))).unwrap();
    let tiny = HeatMap { xs: vec![0.0, 1.0], ys: vec![0.0, 1.0], z: vec![1.0, 2.0, 3.0, 4.0], ..nan.clone() };
    heatmap::render_png("tiny", &tiny, Path::new(&dir.arg("tiny.png"))).unwrap();
    // an empty map from the library (a 2 x 2 grid has no point inside the face) renders too
    let m = FaceMap::compute(&paper_node(), 2, 2, &mut |_| {}).unwrap();
    assert!(m.is_empty());
    heatmap::render_png("empty", &m.heatmap(Quantity::Power, "paper"), Path::new(&dir.arg("empty.png"))).unwrap();
    assert_eq!(dir.names(), vec!["const.png", "empty.png", "nan.png", "tiny.png"]);
}

/// One line on stderr, exit code 2, nothing on stdout, no file in the scratch directory.
fn refused(dir: &Scratch, args: &[&str], names: &str) {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: not one line: {err}");
    assert!(err.contains(names), "{args:?}: '{err}' does not name {names}");
    assert!(out.stdout.is_empty(), "{args:?} printed a result");
    assert!(dir.names().iter().all(|f| f == "bad.toml"), "{args:?} wrote {:?}", dir.names());
}

#[test]
fn bad_input_is_one_line_exit_2_and_writes_nothing() {
    let s = Scratch::new("bad");
    let out = s.arg("m.csv");
    let bad_toml = s.path("bad.toml");
    std::fs::write(&bad_toml, "length_cm = 71\nmass_g = 'heavy'\n").unwrap();
    let bad_toml = bad_toml.to_str().unwrap().to_string();
    let missing_dir = s.arg("no/such/dir/m.csv");
    let png_out = s.arg("m.png");
    let o = out.as_str();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["map", "--nx", "1", "--out", o], "nx"),
        (vec!["map", "--nx", "402", "--out", o], "nx"),
        (vec!["map", "--nr", "0", "--out", o], "nr"),
        (vec!["map", "--nx", "-3", "--out", o], "nx"),
        (vec!["map", "--quantity", "speed", "--out", o], "quantity"),
        (vec!["map", "--compare-racket", "players", "--compare-tension-lb", "50", "--out", o], "compare"),
        (vec!["map", "--compare-tension-lb", "0", "--out", o], "compare-tension-lb"),
        (vec!["map", "--compare-tension-lb", "50,55,60", "--out", o], "compare-tension-lb"),
        (vec!["map", "--racket", "/no/such/racket.toml", "--out", o], "racket.toml"),
        (vec!["map", "--racket", &bad_toml, "--out", o], "bad.toml"),
        (vec!["map", "--compare-racket", "no-such-preset", "--out", o], "no-such-preset"),
        (vec!["map", "--x", "0.1", "--out", o], "x"),
        (vec!["map", "--r", "0.02", "--out", o], "r"),
        (vec!["map", "--ks", "-5", "--out", o], "ks"),
        (vec!["map", "--racket", "tweener", "--ks", "1e20", "--out", o], "ks"),
        (vec!["map", "--nx", "2", "--nr", "2", "--out", o], "inside"),
        (vec!["map", "--out", &missing_dir], "does not exist"),
        (vec!["map", "--out", &png_out], "out"),
    ];
    for (args, names) in &cases {
        refused(&s, args, names);
    }
}

#[test]
fn identical_runs_are_byte_identical_and_match_the_library() {
    let s = Scratch::new("twice");
    let args = |out: &str| {
        vec![
            "map".to_string(),
            "--racket".into(),
            "tweener".into(),
            "--quantity".into(),
            "theta".into(),
            "--nx".into(),
            "9".into(),
            "--nr".into(),
            "7".into(),
            "--out".into(),
            out.to_string(),
        ]
    };
    let (a, b) = (s.arg("a.csv"), s.arg("b.csv"));
    for out in [&a, &b] {
        let o = bin().args(args(out)).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    for ext in ["csv", "png", "json"] {
        let (x, y) =
            (std::fs::read(s.path(&format!("a.{ext}"))).unwrap(), std::fs::read(s.path(&format!("b.{ext}"))).unwrap());
        assert!(x == y, "{ext} differs between identical runs");
    }
    assert_eq!(s.names(), vec!["a.csv", "a.json", "a.png", "b.csv", "b.json", "b.png"]);
    // the CSV is the library's table
    let m = FaceMap::compute(&preset("tweener"), 9, 7, &mut |_| {}).unwrap();
    assert_eq!(std::fs::read_to_string(&a).unwrap(), m.table().to_csv());
    // the metadata carries the full parameters, the quantity and the node
    let meta: serde_json::Value = serde_json::from_slice(&std::fs::read(s.path("a.json")).unwrap()).unwrap();
    assert_eq!(meta["quantity"], "theta");
    assert_eq!(meta["grid"]["nx"], 9);
    let params: Params = serde_json::from_value(meta["a"]["params"].clone()).unwrap();
    assert_eq!(params, m.params);
    assert_eq!(meta["a"]["node_x_m"].as_f64(), m.node_x());
    assert_eq!(meta["a"]["max_e_a"]["value"].as_f64(), m.max_point(Quantity::EA).map(|p| p.value));
}

#[test]
fn flags_and_config_apply_to_every_point_but_config_x_r_are_ignored() {
    let s = Scratch::new("config");
    let cfg = s.path("c.toml");
    std::fs::write(&cfg, "ks = 2.5e4\nx = 0.6\nr = 0.2\nv1 = 20\n").unwrap();
    let out = s.arg("m.csv");
    let o = run(&[
        "map",
        "--config",
        cfg.to_str().unwrap(),
        "--load",
        "node",
        "--nx",
        "5",
        "--nr",
        "5",
        "--out",
        &out,
        "--format",
        "csv",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(o.stdout, std::fs::read(&out).unwrap(), "--format csv prints the table");
    let mut p = paper_node();
    p.strings.ks = 2.5e4;
    p.impact.v1 = 20.0;
    let m = FaceMap::compute(&p, 5, 5, &mut |_| {}).unwrap();
    assert_eq!(std::fs::read_to_string(&out).unwrap(), m.table().to_csv());
    // tensions: T1,T2 against the library's difference map
    let out = s.arg("d.csv");
    let o =
        run(&["map", "--racket", "tweener", "--compare-tension-lb", "50,60", "--nx", "5", "--nr", "5", "--out", &out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (mut a, mut b) = (preset("tweener"), preset("tweener"));
    a.strings.ks = ks_from_tension_lb(50.0);
    b.strings.ks = ks_from_tension_lb(60.0);
    let d = DiffMap::compute(&a, &b, 5, 5, &mut |_| {}).unwrap();
    assert_eq!(std::fs::read_to_string(&out).unwrap(), d.table(Quantity::Power).to_csv());
}

/// The `map` lines of `make figures` regenerate the committed files byte for byte.
#[test]
fn committed_maps_are_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let makefile = std::fs::read_to_string(root.join("Makefile")).unwrap();
    let lines: Vec<&str> = makefile.lines().map(str::trim).filter(|l| l.starts_with("$(BIN) map ")).collect();
    assert!(lines.len() >= 3, "make figures should draw at least three maps");
    let s = Scratch::new("committed");
    for line in lines {
        let mut args: Vec<String> = line.split_whitespace().skip(1).map(String::from).collect();
        let k = args.iter().position(|a| a == "--out").expect("--out in the Makefile line") + 1;
        let committed = root.join(&args[k]);
        let name = committed.file_name().unwrap().to_str().unwrap().to_string();
        args[k] = s.arg(&name);
        let o = bin().args(&args).output().unwrap();
        assert!(o.status.success(), "{line}: {}", String::from_utf8_lossy(&o.stderr));
        for ext in ["csv", "png", "json"] {
            let new = std::fs::read(Path::new(&args[k]).with_extension(ext)).unwrap();
            let old = std::fs::read(committed.with_extension(ext))
                .unwrap_or_else(|e| panic!("{}: {e} (run `make figures`)", committed.with_extension(ext).display()));
            let same = if ext == "json" {
                // full-precision numbers: equal to rounding (the test build is not the release one)
                json_close(&serde_json::from_slice(&new).unwrap(), &serde_json::from_slice(&old).unwrap())
            } else {
                new == old
            };
            assert!(same, "{} is stale: run `make figures`", committed.with_extension(ext).display());
        }
    }
}

/// Structural equality with numbers equal to 1e-12 relative.
fn json_close(a: &serde_json::Value, b: &serde_json::Value) -> bool {
    use serde_json::Value;
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().unwrap_or(f64::NAN), y.as_f64().unwrap_or(f64::NAN));
            x == y || (x - y).abs() <= 1e-12 * x.abs().max(y.abs())
        }
        (Value::Array(x), Value::Array(y)) => x.len() == y.len() && x.iter().zip(y).all(|(x, y)| json_close(x, y)),
        (Value::Object(x), Value::Object(y)) => {
            x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| json_close(v, w)))
        }
        _ => a == b,
    }
}

/// A face map of an oblique quantity (rebound angle, spin) greys the points where the ball does
/// not rebound (v2_n < 0: a rebound angle over 90 degrees), as a power map greys them below
/// its floor, and its colour bar says so; a power map has no such mask.
#[test]
fn oblique_maps_grey_the_points_without_rebound() {
    let mut p = Params::paper();
    p.oblique.angle_deg = 30.0;
    p.numerics.solver = racket_impact::params::SolverKind::Modal;
    let m = FaceMap::compute(&p, 21, 9, &mut |_| {}).unwrap();
    let angles = m.values(Quantity::ReboundAngle);
    assert!(angles.iter().any(|a| a.abs() > 90.0) && angles.iter().any(|a| a.abs() < 90.0), "{angles:?}");
    for q in [Quantity::ReboundAngle, Quantity::Spin] {
        let h = m.heatmap(q, "paper");
        assert_eq!(h.grey_below_zero.len(), angles.len(), "{q:?}");
        for (g, a) in h.grey_below_zero.iter().zip(&angles) {
            assert_eq!(a.is_nan(), g.is_nan());
            if a.is_finite() {
                assert_eq!(*g < 0.0, a.abs() > 90.0, "{q:?}: angle {a} with v2_n {g}");
            }
        }
        assert!(h.bar_label.contains("grey: ") && h.bar_label.contains("no rebound"), "{}", h.bar_label);
        assert!(
            h.shown_values().iter().filter(|v| v.is_finite()).count() < angles.iter().filter(|v| v.is_finite()).count()
        );
    }
    assert!(m.heatmap(Quantity::ReboundAngle, "paper").shown_values().iter().all(|a| a.is_nan() || a.abs() <= 90.0));
    assert!(m.heatmap(Quantity::Power, "paper").grey_below_zero.is_empty());
}
