//! One vocabulary (trap class 6 of issue 24): each quantity has one name, with its unit, in the
//! flags, the config files, the JSON and every CSV a command writes. The names are declared
//! once: the parameters in params/keys.rs (key and column), the results in solve/outcome.rs
//! (FIELDS), the few other columns in render/columns.rs (OTHER_COLUMNS); this test holds every
//! output to that table.

mod common;

use common::{bin, Scratch};
use std::collections::BTreeSet;

use racket_impact::params::keys;
use racket_impact::params::spec::Values;
use racket_impact::params::{Overrides, Params};
use racket_impact::render::columns::OTHER_COLUMNS;
use racket_impact::solve::outcome::FIELDS;

/// The unit as it is spelled at the end of a name (`N/m` -> `_n_per_m`).
fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        return String::new();
    }
    let spelled = unit.to_lowercase().replace('/', " per ").replace('^', "");
    format!("_{}", spelled.split_whitespace().collect::<Vec<_>>().join("_"))
}

#[test]
fn every_parameter_has_one_name_with_its_unit_in_flags_config_json_and_csv() {
    for spec in &keys::ALL {
        let snake = spec.key.replace('-', "_");
        // the CSV column: the key, then its unit unless the key already ends in it
        let suffix = unit_suffix(spec.unit);
        let expected = if snake.ends_with(&suffix) { snake.clone() } else { format!("{snake}{suffix}") };
        assert_eq!(spec.column, expected, "column of {}", spec.key);
        // the config file takes the key, its JSON spelling and its CSV column, all the same
        let value = match spec.values {
            Values::Choice(c) => {
                let default = keys::value_text(spec.key, &Params::default()).unwrap_or_default();
                format!("\"{}\"", c.iter().find(|c| c.name != default).unwrap().name)
            }
            Values::Count => "10".to_string(),
            Values::Number => "0.5".to_string(),
        };
        let read = |name: &str| {
            Overrides::from_toml_bytes(std::path::Path::new("c.toml"), format!("{name} = {value}\n").as_bytes())
                .unwrap_or_else(|e| panic!("{name}: {e}"))
        };
        let by_key = read(spec.key);
        assert_ne!(by_key, Overrides::default(), "{}", spec.key);
        for alias in keys::aliases(spec) {
            assert_eq!(read(&alias), by_key, "{alias} for {}", spec.key);
        }
        // the JSON of the parameters names it by the key (underscored) where the value changes
        let mut p = Params::default();
        by_key.apply(&mut p);
        let (a, b) = (serde_json::to_value(Params::default()).unwrap(), serde_json::to_value(p).unwrap());
        let changed = changed_leaves(&a, &b, "");
        assert!(
            changed.iter().any(|path| path.rsplit('.').next() == Some(snake.as_str())),
            "{}: the JSON names it {changed:?}",
            spec.key
        );
    }
}

/// The dotted paths of the leaves that differ between two JSON values.
fn changed_leaves(a: &serde_json::Value, b: &serde_json::Value, at: &str) -> Vec<String> {
    let empty = serde_json::Value::Object(serde_json::Map::new());
    // (a part left out while at its default, such as `oblique`, counts as empty)
    let a = if b.is_object() && a.is_null() { &empty } else { a };
    match (a, b) {
        (serde_json::Value::Object(x), serde_json::Value::Object(y)) => y
            .iter()
            .flat_map(|(k, v)| {
                let path = if at.is_empty() { k.clone() } else { format!("{at}.{k}") };
                changed_leaves(x.get(k).unwrap_or(&serde_json::Value::Null), v, &path)
            })
            .collect(),
        _ if a != b => vec![at.to_string()],
        _ => vec![],
    }
}

#[test]
fn every_result_name_carries_its_unit() {
    for f in FIELDS {
        let suffix = unit_suffix(f.unit);
        assert!(f.key.ends_with(&suffix), "{} is in {} but its name does not say so", f.key, f.unit);
    }
}

fn csv_header(args: &[&str], dir: &std::path::Path) -> Vec<String> {
    let o = bin().current_dir(dir).args(args).output().unwrap();
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).lines().next().unwrap().split(',').map(String::from).collect()
}

#[test]
fn every_csv_column_of_every_command_is_a_declared_name() {
    let scratch = Scratch::new("vocabulary");
    let mut vocabulary: BTreeSet<String> = keys::ALL.iter().map(|s| s.column.to_string()).collect();
    vocabulary.extend(FIELDS.iter().map(|f| f.key.to_string()));
    vocabulary.extend(OTHER_COLUMNS.iter().map(|c| c.to_string()));
    vocabulary.extend(racket_impact::render::impact::SERIES_COLUMNS.iter().map(|c| c.to_string()));
    let oblique = ["--angle-deg", "30"];
    let headers = [
        csv_header(&[&["simulate", "--format", "csv"][..], &oblique].concat(), scratch.dir()),
        csv_header(&["speed", "--swing", "100", "--swing-path-deg", "20", "--format", "csv"], scratch.dir()),
        csv_header(&[&["map", "--nx", "3", "--nr", "3", "--format", "csv"][..], &oblique].concat(), scratch.dir()),
        csv_header(&["map", "--nx", "3", "--nr", "3", "--format", "csv", "--compare-tension-lb", "50"], scratch.dir()),
        csv_header(&["sweep", "--angle-deg", "0,30", "--grip", "hand"], scratch.dir()),
        csv_header(&["modes", "--format", "csv"], scratch.dir()),
    ];
    let series = {
        let path = scratch.dir().join("s.csv");
        let o = bin().args(["simulate", "--series"]).arg(&path).output().unwrap();
        assert!(o.status.success());
        std::fs::read_to_string(path).unwrap().lines().next().unwrap().split(',').map(String::from).collect()
    };
    for header in headers.iter().chain([&series]) {
        for column in header {
            let base = ["_b_minus_a", "_a", "_b"].iter().find_map(|s| column.strip_suffix(s)).unwrap_or(column);
            assert!(
                vocabulary.contains(column) || vocabulary.contains(base),
                "column {column} is not a declared name (header {header:?})"
            );
        }
        let unique: BTreeSet<&String> = header.iter().collect();
        assert_eq!(unique.len(), header.len(), "a name twice in {header:?}");
    }
}

#[test]
fn messages_speak_in_the_names_and_units_of_the_command_run() {
    let scratch = Scratch::new("vocabulary");
    let bad_racket = scratch.dir().join("r.toml");
    std::fs::write(&bad_racket, "length_cm = \"long\"\n").unwrap();
    let bad_racket = bad_racket.to_str().unwrap();
    // (arguments, words the one stderr line must hold, words it must not)
    let cases: [(&[&str], &[&str], &[&str]); 7] = [
        (&["speed", "--swing", "5000"], &["invalid swing = 5000", "km/h"], &["v1", "m/s"]),
        (&["speed", "--swing", "5000", "--unit", "mph"], &["invalid swing = 5000", "mph"], &["v1", "km/h"]),
        (&["speed", "--swing", "300"], &["warning: swing + incoming = 300 km/h"], &["v1"]),
        (
            &["speed", "--swing", "100", "--incoming-spin-rpm", "7000"],
            &["warning: incoming-spin-rpm = 7000"],
            &["spin-rpm = -"],
        ),
        (&["simulate", "--racket", "nosuch"], &["invalid racket = nosuch", "preset"], &["config file"]),
        (&["simulate", "--racket", bad_racket], &["racket file", "length_cm"], &["config file"]),
        (&["sweep", "--x", "0.1:0.2:0"], &["invalid sweep = --x 0.1:0.2:0"], &["config file"]),
    ];
    for (args, want, not) in cases {
        let o = bin().args(args).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        for w in want {
            assert!(err.contains(w), "{args:?}: '{w}' not in {err}");
        }
        for w in not {
            assert!(!err.contains(w), "{args:?}: '{w}' in {err}");
        }
    }
}

/// A sweep names each column once, whichever keys are its axes: a swept solver (`--solver
/// modal`, `--solver fd,modal`) is its own column, not repeated as the trailing solver column.
#[test]
fn a_sweep_names_each_column_once() {
    for args in
        [&["--x", "0.1,0.2", "--solver", "modal"][..], &["--solver", "fd,modal"], &["--x", "0.1", "--angle-deg", "30"]]
    {
        let out = bin().arg("sweep").args(args).output().unwrap();
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        let text = String::from_utf8_lossy(&out.stdout);
        let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
        let unique: BTreeSet<&str> = header.iter().copied().collect();
        assert_eq!(unique.len(), header.len(), "{args:?}: {header:?}");
        assert!(header.contains(&"solver"), "{args:?}: {header:?}");
    }
}
