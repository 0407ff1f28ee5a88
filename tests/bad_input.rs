//! The bad-input catalogue: every malformed or out-of-range input, through flags, config files
//! and output paths, gives exit code 2, exactly one line on stderr naming the field (and, for
//! range violations, the allowed range), prints no result, and creates or changes no file.

mod common;

use common::{bin, Scratch};

const SENTINEL: &str = "previous content\n";

/// What a case must name: the field, and whether it is a range check (our validation, whose
/// message states the allowed range) or a parse error (clap or TOML, which names the flag/key).
struct Case {
    args: Vec<String>,
    field: &'static str,
    range: bool,
}

fn case(args: &[&str], field: &'static str, range: bool) -> Case {
    Case { args: args.iter().map(|s| s.to_string()).collect(), field, range }
}

#[test]
fn every_bad_input_exits_2_names_the_field_and_writes_nothing() {
    let s = Scratch::new("catalogue");
    let series = s.file("series.csv", SENTINEL.as_bytes());
    let unknown_key = s.file("unknown.toml", b"ks = 4e4\nstring_tension = 55\n");
    let wrong_type = s.file("wrong_type.toml", b"ks = \"stiff\"\n");
    let empty = s.file("empty.toml", b"");
    let blank = s.file("blank.toml", b"  \n\n");
    let binary = s.file("binary.toml", [0xff, 0xfe, 0x00, 0x81, 0x13, 0x37, 0xc3, 0x28]);
    let nul = s.file("nul.toml", b"ks = 4e4\0\n");
    let nan_cfg = s.file("nan.toml", b"ks = nan\n");
    let p_cfg = s.file("p.toml", b"p = 1\n");
    let syntax = s.file("syntax.toml", b"ks = \n");
    let dup = s.file("dup.toml", b"ks = 4e4\nks = 5e4\n");
    let table_cfg = s.file("table.toml", b"[racket]\nei = 150\n");
    let neg_seg = s.file("negseg.toml", b"segments = -3\n");
    let missing = s.arg("missing.toml");
    let a_file = s.file("a_file", b"not a directory\n");
    let under_file = format!("{a_file}/out");
    let no_dir_series = s.arg("no/such/dir/series.csv");
    let no_dir_report = s.arg("no/such/dir/REPORT.md");
    let bad_racket =
        s.file("bad_racket.toml", b"length_in = 27\nmass_g = -300\ntwistweight_kg_cm2 = 14\nei_n_m2 = 150\n");
    let many_racket = s.file(
        "many.toml",
        b"length_cm = 6860\nmass_g = 300\ntwistweight_kg_cm2 = -14\nfrequency_hz = 150\ntension_lb = 900\n",
    );
    let typo_racket = s.file("typo.toml", b"length_in = 27\nmass_g = 300\nbalanse_cm = 33\n");
    let half_racket =
        s.file("half.toml", b"length_in = 27\nmass_g = 300\nbalance_cm = 33\ntwistweight_kg_cm2 = 14\nei_n_m2 = 150\n");

    let sim = |extra: &[&str]| -> Vec<String> {
        let mut v = vec!["simulate".to_string(), "--series".to_string(), series.clone()];
        v.extend(extra.iter().map(|x| x.to_string()));
        v
    };
    let mut cases: Vec<Case> = vec![
        case(&["--mb", "-0.057"], "mb", true),
        case(&["--mb", "0"], "mb", true),
        case(&["--mass", "0"], "mass", true),
        case(&["--mass", "-0.34"], "mass", true),
        case(&["--ks", "NaN"], "ks", true),
        case(&["--ks", "inf"], "ks", true),
        case(&["--ks", "-4e4"], "ks", true),
        case(&["--ei", "-inf"], "ei", true),
        case(&["--ei", "0"], "ei", true),
        case(&["--k1", "-1"], "k1", true),
        case(&["--ix", "0"], "ix", true),
        case(&["--length", "-0.7"], "length", true),
        case(&["--p", "1.0"], "p", true),
        case(&["--p", "0.5"], "p", true),
        case(&["--p", "11"], "p", true),
        case(&["--x", "0.8"], "x", true),
        case(&["--x", "-0.01"], "x", true),
        case(&["--x", "nan"], "x", true),
        case(&["--r", "0.3"], "r", true),
        case(&["--r", "-0.2"], "r", true),
        case(&["--half-width", "0"], "half-width", true),
        case(&["--v1", "0"], "v1", true),
        case(&["--v1", "-30"], "v1", true),
        case(&["--segments", "3"], "segments", true),
        case(&["--segments", "100000"], "segments", true),
        case(&["--segments", "-5"], "--segments", false),
        case(&["--segments", "39.5"], "--segments", false),
        case(&["--dt", "1e-3"], "dt", true),
        case(&["--dt", "-1e-6"], "dt", true),
        case(&["--dt", "0"], "dt", true),
        case(&["--dt", "1e-15"], "dt", true),
        case(&["--ks", "abc"], "--ks", false),
        case(&["--ks", ""], "--ks", false),
        case(&["--load", "spread"], "node, hat", false),
        case(&["--x", "0.1", "--x", "0.2"], "--x", false),
        case(&["--format", "xml"], "--format", false),
        case(&["--series-dt", "0"], "series-dt", true),
        case(&["--angle-deg", "90"], "angle-deg", true),
        case(&["--angle-deg", "-5"], "angle-deg", true),
        case(&["--angle-deg", "nan"], "angle-deg", true),
        case(&["--azimuth-deg", "400"], "azimuth-deg", true),
        case(&["--spin-rpm", "1e5"], "spin-rpm", true),
        case(&["--spin-rpm", "-inf"], "spin-rpm", true),
        case(&["--mu", "-0.1"], "mu", true),
        case(&["--mu", "3"], "mu", true),
        case(&["--kt", "0"], "kt", true),
        case(&["--kt", "1e12"], "kt", true),
        case(&["--ball-radius", "0"], "ball-radius", true),
        case(&["--ball-radius", "2"], "ball-radius", true),
        case(&["--ball-inertia-factor", "0"], "ball-inertia-factor", true),
        case(&["--ball-inertia-factor", "1.5"], "ball-inertia-factor", true),
        case(&["--angle-deg", "30", "--frame", "rigid"], "frame", true),
        case(&["--mu", "abc"], "--mu", false),
        case(&["--config", &unknown_key], "string_tension", false),
        case(&["--config", &wrong_type], "ks", false),
        case(&["--config", &empty], "empty", false),
        case(&["--config", &blank], "empty", false),
        case(&["--config", &binary], "UTF-8", false),
        case(&["--config", &nul], "nul.toml", false),
        case(&["--config", &nan_cfg], "ks", true),
        case(&["--config", &p_cfg], "p", true),
        case(&["--config", &syntax], "ks", false),
        case(&["--config", &dup], "ks", false),
        case(&["--config", &table_cfg], "racket", false),
        case(&["--config", &neg_seg], "segments", false),
        case(&["--config", &missing], "missing.toml", false),
        case(&["--ei", "1e-6"], "ei", true),
        case(&["--mass", "1e300"], "mass", true),
        case(&["--ei", "1e9", "--mass", "1e-3"], "ei", false),
        case(&["--v1", "1e-300"], "v1", true),
        case(&["--k1", "1e-300"], "k1", true),
        case(&["--half-width", "1e300", "--r", "1e200"], "half-width", true),
        case(&["--segments", "1000"], "segments", true),
        case(&["--series-end", "-1"], "series-end", true),
    ]
    .into_iter()
    .map(|c| Case { args: sim(&c.args.iter().map(String::as_str).collect::<Vec<_>>()), ..c })
    .collect();
    cases.extend([
        case(&["simulate", "--series", &no_dir_series], "series", true),
        case(&["simulate", "--series", &format!("{a_file}/s.csv")], "series", true),
        case(&["figures", "--only", "fig4_energy", "--out", &under_file], "out", false),
        case(&["figures", "--only", "modes", "--out", &a_file], "invalid out", false),
        case(&["figures", "--only", "modes", "--out", &under_file], "a_file is a file, not a directory", false),
        case(&["figures", "--only", "no_such_experiment", "--out", &s.arg("figs")], "no_such_experiment", false),
        case(&["report", "--out", &no_dir_report], "out", true),
        case(&["modes", "--count", "0"], "count", true),
        case(&["modes", "--ei", "-150"], "ei", true),
        case(&["modes", "--segments", "2"], "segments", true),
        case(&["modes", "--count", "-1"], "count", true),
        case(&["modes", "--length", "1e-300"], "length", true),
        case(&["no-such-command"], "no-such-command", false),
        // model variants
        case(&["simulate", "--frame", "bendy"], "--frame", false),
        case(&["simulate", "--grip", "hand", "--solver", "modal"], "solver", true),
        case(&["simulate", "--frame", "rigid", "--strings", "stiffening"], "frame", true),
        case(&["simulate", "--strings", "stiffening", "--string-stiffening", "-0.1"], "string-stiffening", true),
        case(&["simulate", "--grip", "hand", "--hand-damping", "nan"], "hand-damping", true),
        case(&["simulate", "--grip", "hand", "--grip-length", "0.5"], "grip-length", true),
        // own racket and speed
        case(&["simulate", "--racket", &bad_racket], "mass_g", true),
        case(&["simulate", "--racket", &typo_racket], "balanse_cm", false),
        case(&["racket"], "racket", false),
        case(&["racket", &half_racket], "swingweight_kg_cm2", false),
        case(&["speed", "--swing", "30", "--incoming", "-5"], "incoming", true),
        case(&["speed", "--swing", "30", "--compare-tension-lb", "0"], "compare-tension-lb", true),
        case(&["speed", "--swing", "30", "--compare-tension-lb", "50", "--compare-racket", "light"], "compare", false),
        case(&["speed", "--incoming", "20"], "--swing", false),
        // what two or more compared tensions set (k_s) is not taken from a flag as well
        case(&["speed", "--swing", "100", "--ks", "1e3", "--compare-tension-lb", "50,60"], "compare-tension-lb", false),
        case(&["map", "--out", &s.arg("t.csv"), "--ks", "1e3", "--compare-tension-lb", "50,60"], "ks", false),
        case(&["map", "--out", &s.arg("t.csv"), "--compare-tension-lb", "50,50"], "given twice", false),
        case(&["speed", "--swing", "100", "--compare-tension-lb", "50,60,50"], "given twice", false),
        case(&["sweep", "--out", &s.arg("sw.csv"), "--solver", "modal", "--grip", "hand,free"], "solver", true),
        // options a command does not use are refused, with the reason
        case(&["simulate", "--series-dt", "1e-4"], "series-dt", false),
        case(&["simulate", "--series-end", "0.02"], "series-end", false),
        case(&["speed", "--swing", "30", "--v1", "20"], "v1", false),
        case(&["speed", "--swing", "30", "--swing-path-deg", "20", "--angle-deg", "10"], "angle-deg", false),
        case(&["speed", "--swing", "30", "--spin-rpm", "1000"], "spin-rpm", false),
        case(&["modes", "--ks", "2e4"], "ks", false),
        case(&["modes", "--x", "0.1"], "x", false),
        case(&["racket", "tweener", "--list"], "racket", false),
        // options after the swept pairs, and unknown keys, say so
        case(&["sweep", "--x", "0.1,0.2", "--out", &s.arg("late.csv")], "go before the --KEY SPEC pairs", false),
        case(&["sweep", "--x", "0.1", "--quiet"], "go before the --KEY SPEC pairs", false),
        case(&["sweep", "--xx", "0.1"], "unknown parameter", false),
        // every problem of a racket file at once
        case(&["simulate", "--racket", &many_racket], "3 problems", false),
    ]);
    assert!(cases.len() >= 30);

    for c in &cases {
        let before = s.snapshot();
        let out = bin().args(&c.args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{:?}: exit {:?}, stderr {err}", c.args, out.status.code());
        assert_eq!(err.trim_end().lines().count(), 1, "{:?}: not one line: {err}", c.args);
        assert!(err.contains(c.field), "{:?}: message does not name {}: {err}", c.args, c.field);
        if c.range {
            assert!(
                ["must", "<=", ">", "does not exist"].iter().any(|w| err.contains(w)),
                "{:?}: no allowed range in: {err}",
                c.args
            );
        }
        assert!(out.stdout.is_empty(), "{:?}: printed a result", c.args);
        assert!(s.snapshot() == before, "{:?}: created or changed a file", c.args);
        assert!(!err.contains("panicked"), "{:?}: panic", c.args);
    }
    assert_eq!(std::fs::read_to_string(&series).unwrap(), SENTINEL);
    assert!(!s.path("figs").exists(), "figures created its output directory for an unknown id");
}

/// Numbers in messages read as numbers: a huge value with an exponent, not 31 digits; a
/// computed sweep value without its binary noise (`2.1`, not `2.0999999999999996`); the
/// allowed range in plain bounds (`0 <= mu <= 2`, `1 <= ks <= 1e12`, not `0e0`, `1e0`).
#[test]
fn numbers_in_messages_are_short_and_readable() {
    let stderr = |args: &[&str]| {
        let o = bin().args(args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        String::from_utf8(o.stderr).unwrap()
    };
    assert_eq!(
        stderr(&["simulate", "--ks", "1e30"]),
        "error: invalid ks = 1e30: string-plane stiffness must satisfy 1 <= ks <= 1e12 N/m\n"
    );
    assert_eq!(
        stderr(&["sweep", "--mu", "0:3:11"]),
        "error: invalid mu = 2.1: friction coefficient must satisfy 0 <= mu <= 2\n"
    );
    let far = stderr(&["sweep", "--x", "0:1e30:3"]);
    assert!(far.starts_with("error: invalid x = 5e29: "), "{far}");
    // a refused value keeps the digits that tell it from the bound beside it
    let near = stderr(&["simulate", "--x", "0.7100001"]);
    assert!(near.starts_with("error: invalid x = 0.7100001: ") && near.contains("L = 0.71 m"), "{near}");
    // a number too small or too large for an f64 is named as written, not as 0 or inf
    assert_eq!(
        stderr(&["simulate", "--ks", "1e-400"]),
        "error: invalid ks = 1e-400: is too small to represent as a number (below about 1e-308)\n"
    );
    let huge = stderr(&["sweep", "--ks", "2e4,1e400"]);
    assert!(huge.starts_with("error: invalid ks = 1e400: is too large to represent"), "{huge}");
}
