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

/// One golden test per experiment of the registry, named by its id.
macro_rules! golden_tests {
    ($($id:ident,)+) => {
        $(
            #[test]
            fn $id() {
                check(stringify!($id));
            }
        )+
    };
}
racket_impact::each_experiment!(golden_tests);

/// Every experiment of the registry has its committed outputs (its golden test is generated
/// from the same registry, above).
#[test]
fn every_registered_experiment_has_committed_outputs() {
    for e in experiments::registry() {
        for ext in ["csv", "png"] {
            assert!(root().join("figures").join(format!("{}.{ext}", e.id)).exists(), "figures/{}.{ext} missing", e.id);
        }
    }
}
