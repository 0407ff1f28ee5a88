//! Golden regression: every experiment's table, formatted at 6 significant digits, must equal
//! its snapshot in `golden/` (insta; with CI=true a changed or missing snapshot fails and
//! nothing is written; `make golden` re-blesses deliberately) and the committed
//! `figures/<id>.csv`. The committed PNGs must be what the code draws now, byte for byte, and
//! drawing twice must give the same bytes. (One test per experiment checks all of it from one
//! run of the experiment: a second test that ran every experiment again for its PNG cost 45
//! CPU-seconds of the suite.)

use std::path::PathBuf;

use racket_impact::experiments::{self, find, Context};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn check(id: &str) {
    let exp = find(id).unwrap();
    let table = (exp.run)(&Context::paper()).unwrap();
    let csv = table.to_csv();
    assert!(!csv.contains("NaN") && !csv.contains("inf"), "{id}: non-finite value in the table");
    insta::with_settings!({snapshot_path => "../golden", prepend_module_to_snapshot => false, omit_expression => true}, {
        insta::assert_snapshot!(id, csv);
    });
    let committed = std::fs::read_to_string(root().join("figures").join(format!("{id}.csv")))
        .unwrap_or_else(|e| panic!("figures/{id}.csv: {e} (run `make figures`)"));
    assert_eq!(committed, csv, "figures/{id}.csv is stale: run `make figures`");
    // the figure, drawn twice from the table
    let chart = (exp.chart)(&Context::paper(), &table);
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = ["a", "b"].map(|n| dir.path().join(format!("{id}-{n}.png")));
    racket_impact::render::plot::render_png(id, &chart, &a).unwrap();
    racket_impact::render::plot::render_png(id, &chart, &b).unwrap();
    let (a, b) = (std::fs::read(a).unwrap(), std::fs::read(b).unwrap());
    assert!(a == b, "{id}: rendering is not deterministic");
    let committed = std::fs::read(root().join("figures").join(format!("{id}.png"))).unwrap();
    assert!(committed == a, "figures/{id}.png is stale: run `make figures`");
}

#[test]
fn variant_rigid() {
    check("variant_rigid");
}
#[test]
fn variant_grip() {
    check("variant_grip");
}
#[test]
fn variant_strings() {
    check("variant_strings");
}
#[test]
fn concrete_drop() {
    check("concrete_drop");
}
#[test]
fn clamped_drop() {
    check("clamped_drop");
}
#[test]
fn modes() {
    check("modes");
}
#[test]
fn fig4_energy() {
    check("fig4_energy");
}
#[test]
fn fig5a_position_soft() {
    check("fig5a_position_soft");
}
#[test]
fn fig5b_position_stiff() {
    check("fig5b_position_stiff");
}
#[test]
fn fig6_string_stiffness() {
    check("fig6_string_stiffness");
}
#[test]
fn fig7_off_axis_x10() {
    check("fig7_off_axis_x10");
}
#[test]
fn fig8_off_axis_centre() {
    check("fig8_off_axis_centre");
}
#[test]
fn fig9_stiff_frame() {
    check("fig9_stiff_frame");
}
#[test]
fn speeds() {
    check("speeds");
}
#[test]
fn convergence() {
    check("convergence");
}
#[test]
fn oblique_angle() {
    check("oblique_angle");
}
#[test]
fn oblique_tension() {
    check("oblique_tension");
}
#[test]
fn topspin_forehand() {
    check("topspin_forehand");
}
#[test]
fn robustness() {
    check("robustness");
}
#[test]
fn sensitivity() {
    check("sensitivity");
}
#[test]
fn validation_spin() {
    check("validation_spin");
}
#[test]
fn spin_calibration() {
    check("spin_calibration");
}

#[test]
fn every_registered_experiment_has_a_golden_test_and_committed_outputs() {
    let src = std::fs::read_to_string(root().join("tests/golden.rs")).unwrap();
    for e in experiments::registry() {
        assert!(src.contains(&format!("check(\"{}\")", e.id)), "no golden test for {}", e.id);
        for ext in ["csv", "png"] {
            assert!(root().join("figures").join(format!("{}.{ext}", e.id)).exists(), "figures/{}.{ext} missing", e.id);
        }
    }
}
