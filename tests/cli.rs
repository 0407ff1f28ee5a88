//! The command-line contract (SPEC.md section 5): results match the library, and every class of
//! bad input gives one line on stderr naming the field, exit code 2, and no output file.

mod common;

use common::{bin, run, Scratch};

use approx::assert_relative_eq;
use racket_impact::params::{LoadRule, Params};
use racket_impact::simulate;

#[test]
fn json_run_parses_and_matches_the_library() {
    let out = run(&[
        "simulate",
        "--x",
        "0.23",
        "--r",
        "-0.03",
        "--ks",
        "3.1e4",
        "--ei",
        "200",
        "--v1",
        "25",
        "--segments",
        "50",
        "--load",
        "node",
        "--format",
        "json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut p = Params::default();
    p.numerics.load = LoadRule::Node;
    p.numerics.segments = 50;
    (p.impact.x, p.impact.r, p.impact.v1, p.strings.ks, p.racket.ei) = (0.23, -0.03, 25.0, 3.1e4, 200.0);
    let r = simulate(&p).unwrap();
    assert_relative_eq!(v["e_a"].as_f64().unwrap(), r.e_a, max_relative = 1e-15);
    assert_relative_eq!(v["tau_s"].as_f64().unwrap(), r.tau_s, max_relative = 1e-15);
    assert_relative_eq!(v["theta_end_deg"].as_f64().unwrap(), r.theta_end_deg, max_relative = 1e-15);
    for key in [
        "f_ball",
        "f_vib",
        "f_vib_peak_pe",
        "f_spin",
        "f_rigid",
        "f_ke_ball",
        "peak_force_n",
        "energy_error",
        "momentum_error",
        "x_load_m",
    ] {
        assert!(v[key].is_f64(), "missing {key}");
    }
}

#[test]
fn csv_and_text_formats_carry_the_same_e_a() {
    let csv = run(&["simulate", "--format", "csv"]);
    assert!(csv.status.success());
    let text = String::from_utf8(csv.stdout).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let i = head.iter().position(|h| *h == "e_a").unwrap();
    let e_csv: f64 = row[i].parse().unwrap();
    // the command line's default impact: the centre of the string face, on the axis
    let (p, _) = racket_impact::racket::resolve(None, &Default::default()).unwrap();
    assert_eq!((p.impact.x, p.impact.r), (0.16, 0.0));
    assert_relative_eq!(e_csv, simulate(&p).unwrap().e_a, max_relative = 1e-15);
    let txt = run(&["simulate"]);
    assert!(String::from_utf8(txt.stdout).unwrap().lines().any(|l| l.starts_with("e_a ")));
}

#[test]
fn config_file_uses_the_flag_names_and_flags_win() {
    let scratch = Scratch::new("config");
    let dir = scratch.dir();
    let cfg = dir.join("c.toml");
    std::fs::write(&cfg, "x = 0.158\nr = 0.0\nks = 2e4\nload = \"node\"\n").unwrap();
    let cfg_s = cfg.to_str().unwrap();
    let a = run(&["simulate", "--config", cfg_s, "--format", "json"]);
    let b = run(&["simulate", "--config", cfg_s, "--ks", "4e4", "--format", "json"]);
    let va: serde_json::Value = serde_json::from_slice(&a.stdout).unwrap();
    let vb: serde_json::Value = serde_json::from_slice(&b.stdout).unwrap();
    assert_eq!(va["params"]["strings"]["ks"].as_f64(), Some(2.0e4));
    assert_eq!(vb["params"]["strings"]["ks"].as_f64(), Some(4.0e4));
    assert_eq!(vb["params"]["impact"]["x"].as_f64(), Some(0.158));
}

#[test]
fn series_file_holds_time_force_and_every_energy_term() {
    let scratch = Scratch::new("series");
    let dir = scratch.dir();
    let path = dir.join("s.csv");
    let out = run(&["simulate", "--series", path.to_str().unwrap(), "--series-end", "0.02"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&path).unwrap();
    let head = text.lines().next().unwrap();
    for col in [
        "t_s",
        "force_n",
        "y_ball_m",
        "y_total_m",
        "ke_ball",
        "pe_ball",
        "pe_string",
        "ke_racket",
        "pe_racket",
        "ke_spin",
        "total",
    ] {
        assert!(head.split(',').any(|h| h == col), "missing {col} in {head}");
    }
    let last_t: f64 = text.lines().last().unwrap().split(',').next().unwrap().parse().unwrap();
    assert!(last_t >= 0.02 - 1e-4, "series ends at {last_t}");
    // every row records the impact it belongs to (the default: the face centre, on the axis)
    let columns: Vec<&str> = head.split(',').collect();
    let row: Vec<&str> = text.lines().last().unwrap().split(',').collect();
    let at = |c: &str| row[columns.iter().position(|h| *h == c).unwrap()].parse::<f64>().unwrap();
    assert_eq!((at("x_m"), at("r_m"), at("ks_n_per_m")), (0.16, 0.0, 4e4));
    assert!(at("v1_m_per_s") > 7.0);
}

#[test]
fn the_csv_of_one_impact_records_its_parameters() {
    let out = run(&["simulate", "--format", "csv", "--x", "0.2", "--r", "-0.03", "--ks", "3e4", "--v1", "12"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |c: &str| row[head.iter().position(|h| *h == c).unwrap()];
    assert_eq!([at("x_m"), at("r_m"), at("ks_n_per_m"), at("v1_m_per_s")], ["0.2", "-0.03", "30000", "12"]);
}

#[test]
fn modes_reports_125_hz() {
    let out = run(&["modes", "--format", "json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let f1 = v["frequencies_hz"][0].as_f64().unwrap();
    assert!((f1 - 125.0).abs() < 1.25, "{f1}");
}

#[test]
fn unwritable_series_path_is_an_error_and_leaves_nothing() {
    let scratch = Scratch::new("unwritable");
    let dir = scratch.dir();
    let path = dir.join("no-such-dir").join("s.csv");
    let out = run(&["simulate", "--series", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("s.csv"));
    assert!(!dir.join("no-such-dir").exists());
}

#[test]
fn a_recontact_is_reported_on_stderr_and_in_the_json() {
    let out = run(&["simulate", "--x", "0", "--r", "0", "--ks", "1e6", "--format", "json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["recontact"].as_bool(), Some(true));
    let err = String::from_utf8_lossy(&out.stderr);
    // (ks = 1e6 N/m is beyond real strings: warned too)
    assert_eq!(
        err.lines().filter(|l| l.starts_with("warning: the vibrating frame met the ball again")).count(),
        1,
        "{err}"
    );
    assert!(err.lines().all(|l| l.starts_with("warning: ")), "{err}");
}

#[test]
fn sweep_streams_the_cartesian_product_in_order_and_matches_simulate() {
    let scratch = Scratch::new("sweep");
    let dir = scratch.dir();
    let path = dir.join("s.csv");
    let out =
        run(&["sweep", "--out", path.to_str().unwrap(), "--ks", "2e4,4e4", "--x", "0.05:0.25:5", "--load", "node"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 11);
    // the swept columns, then the impact's recorded parameters, then the results
    assert!(lines[0].starts_with("ks_n_per_m,x_m,load,r_m,v1_m_per_s,e_a,tau_s"), "{}", lines[0]);
    let row: Vec<&str> = lines[7].split(',').collect(); // ks 4e4, x = 0.1
    assert_eq!((row[0], row[1]), ("4e4", "0.1"));
    // sweeps default to the modal solver and say so in the last column
    assert_eq!(row.last(), Some(&"modal"));
    let mut p = Params::default();
    p.numerics.load = LoadRule::Node;
    p.impact.x = 0.1;
    p.impact.r = 0.0; // the default impact is on the long axis
    assert_eq!((row[3], row[4]), ("0", &*p.impact.v1.to_string()));
    p.strings.ks = 4e4;
    p.numerics.solver = racket_impact::params::SolverKind::Modal;
    // numbers are written exactly (shortest round-trip form)
    assert_eq!(row[5].parse::<f64>().unwrap(), simulate(&p).unwrap().e_a);
    // the explicit reference on request, and wherever a variant needs it
    let out = run(&["sweep", "--solver", "fd", "--x", "0.1"]);
    let text = String::from_utf8(out.stdout).unwrap();
    p.numerics.solver = racket_impact::params::SolverKind::Fd;
    p.numerics.load = LoadRule::Hat;
    let fd: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
    // (a swept key: `--solver fd` is the first column, and not repeated at the end; e_a after
    // x, r, ks, v1)
    assert_eq!(fd[0], "fd");
    assert_eq!(text.lines().next().unwrap().matches("solver").count(), 1);
    assert_eq!(fd[5].parse::<f64>().unwrap(), simulate(&p).unwrap().e_a);
    let out = run(&["sweep", "--grip", "free,hand", "--x", "0.1"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8(out.stdout).unwrap().lines().skip(1).all(|l| l.ends_with(",fd")));
}

#[test]
fn a_sweep_with_a_bad_value_anywhere_writes_nothing() {
    let scratch = Scratch::new("sweep-bad");
    let dir = scratch.dir();
    let path = dir.join("s.csv");
    let out = run(&["sweep", "--out", path.to_str().unwrap(), "--x", "0.1:0.9:5"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("invalid x = 0.9"));
    assert!(std::fs::read_dir(dir).unwrap().next().is_none(), "left a file behind");
    let stdout = run(&["sweep", "--x", "0.1:0.9:5"]);
    assert!(stdout.stdout.is_empty());
}

#[test]
fn a_reader_that_stops_early_ends_the_program_quietly() {
    // `racket-impact sweep ... | head -1`: the pipe closes while 2000 rows (far more than a pipe
    // buffer) are still to be written
    let mut child = bin()
        .args(["sweep", "--x", "0.01:0.7:2000"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "exit {:?}: {err}", out.status.code());
    assert!(!err.contains("panicked"), "{err}");
}

/// One compared tension T sets only the second row's k_s: the first is the configuration as
/// given, with the --ks flag (only two or more tensions refuse it, tests/bad_input.rs).
#[test]
fn one_compared_tension_keeps_the_given_ks_in_the_first_row() {
    let out = run(&["speed", "--swing", "100", "--ks", "3e4", "--compare-tension-lb", "50", "--format", "csv"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = String::from_utf8(out.stdout).unwrap();
    let ks: Vec<f64> = csv.lines().skip(1).map(|l| l.split(',').nth(3).unwrap().parse().unwrap()).collect();
    assert_eq!(ks.len(), 2);
    assert_relative_eq!(ks[0], 3.0e4);
    assert_relative_eq!(ks[1], 4.0e4 * 50.0 / 60.0, max_relative = 1e-5); // (printed to 6 digits)
}

/// A sweep point that fails says which point it is, by the values of the swept keys (not the
/// fixed ones), the first failing point in the sweep's order; one line, exit 2, no file.
#[test]
fn a_failing_sweep_point_is_named_by_its_swept_values() {
    let scratch = Scratch::new("sweep-point");
    let dir = scratch.dir();
    let out = dir.join("f.csv");
    let o = run(&[
        "sweep",
        "--out",
        out.to_str().unwrap(),
        "--solver",
        "fd",
        "--dt",
        "1e-4",
        "--x",
        "0.1,0.2",
        "--segments",
        "4,39",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("error: at x = 0.1, segments = 4: energy not conserved"), "{err}");
    assert!(!out.exists());
    // a bad value found before anything runs names the point too, its values readable
    let o = run(&["sweep", "--mu", "0:3:11", "--x", "0.1,0.2", "--angle-deg", "30"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: at mu = 2.1, x = 0.1: invalid mu = 2.1: "), "{err}");
}

/// No command at all: clap's usage and command list, laid out on several lines on stderr
/// (not flattened onto one, as an error is), exit 2.
#[test]
fn no_command_prints_the_help_on_several_lines() {
    let o = bin().output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(o.stdout.is_empty());
    assert!(err.lines().any(|l| l.starts_with("Usage: racket-impact")), "{err}");
    assert!(err.lines().any(|l| l.trim_start().starts_with("simulate ")), "{err}");
    assert!(err.lines().all(|l| l.len() < 200), "a line too long: {err}");
}

/// An experiment named twice with --only runs once (one progress line, its two files).
#[test]
fn an_experiment_given_twice_runs_once() {
    let scratch = Scratch::new("only-twice");
    let dir = scratch.dir();
    let out = dir.join("figs");
    let o = run(&["figures", "--only", "modes", "--only", "modes", "--out", out.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert_eq!(err.lines().filter(|l| l.starts_with("modes ")).count(), 1, "{err}");
    let mut names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, vec!["modes.csv", "modes.png"]);
}

/// Each option's help states its default once: the declaration's text carries no default of
/// its own beside the `[default: ...]` the command line adds.
#[test]
fn no_option_states_its_default_twice() {
    for command in ["simulate", "modes", "speed", "sweep", "map", "uncertainty", "figures", "report", "racket", "card"]
    {
        for flag in ["-h", "--help"] {
            let o = run(&[command, flag]);
            assert_eq!(o.status.code(), Some(0), "{command} {flag}");
            let help = String::from_utf8(o.stdout).unwrap();
            for line in help.lines() {
                assert!(line.to_lowercase().matches("default").count() <= 1, "{command} {flag}: {line}");
            }
        }
    }
}

/// Each command's long help opens with its one-line summary and then, where it says more, an
/// example or a short statement, in paragraphs a reader can take in: none of prose over 400
/// characters (a list, its lines indented, may be longer), and the first after the summary
/// short (issue 40: `uncertainty` and `speed` opened with one long paragraph).
#[test]
fn long_helps_come_in_short_paragraphs() {
    for command in ["simulate", "modes", "speed", "sweep", "map", "uncertainty", "figures", "report", "racket", "card"]
    {
        let o = run(&[command, "--help"]);
        assert_eq!(o.status.code(), Some(0), "{command}");
        let help = String::from_utf8(o.stdout).unwrap();
        let intro = &help[..help.find("\nUsage:").unwrap_or(help.len())];
        let paragraphs: Vec<&str> = intro.split("\n\n").map(str::trim_end).filter(|p| !p.is_empty()).collect();
        assert!(paragraphs[0].lines().count() == 1 && paragraphs[0].len() <= 120, "{command}: {}", paragraphs[0]);
        let list = |p: &str| p.lines().count() > 1 && p.lines().skip(1).all(|l| l.starts_with("  "));
        if let Some(second) = paragraphs.get(1) {
            // (or the examples, one a line)
            assert!(
                second.len() <= 120 || (second.starts_with("Examples:") && list(second)),
                "{command}: the help goes on with a long paragraph: {second}"
            );
        }
        for p in &paragraphs {
            assert!(list(p) || p.len() <= 400, "{command}: a paragraph of {} characters: {p}", p.len());
        }
    }
}

/// A zero in JSON is printed without a sign: a stroke's params echo its zero spin as 0.0,
/// not -0.0 (every JSON goes through render::json).
#[test]
fn json_prints_no_negative_zero() {
    for args in [
        &["speed", "--swing", "100", "--swing-path-deg", "10", "--format", "json"][..],
        &["simulate", "--angle-deg", "30", "--format", "json"][..],
    ] {
        let o = run(args);
        assert_eq!(o.status.code(), Some(0), "{args:?}");
        let text = String::from_utf8(o.stdout).unwrap();
        assert!(!text.contains("-0.0,") && !text.contains("-0.0\n"), "{args:?}: {text}");
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert!(v.is_object() || v.is_array());
    }
}

/// A config file's ks, which two or more compared tensions set, is named in the one warning
/// about unused config keys (a config file may be shared, so it is not refused as a flag is).
#[test]
fn a_config_ks_under_two_compared_tensions_is_named_as_unused() {
    let scratch = Scratch::new("tension-config");
    let dir = scratch.dir();
    let cfg = dir.join("cfg.toml");
    std::fs::write(&cfg, "ks = 1000\n").unwrap();
    let o = run(&["speed", "--swing", "100", "--config", cfg.to_str().unwrap(), "--compare-tension-lb", "50,60"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    let notes: Vec<&str> = err.lines().filter(|l| l.contains("not used here")).collect();
    assert_eq!(notes.len(), 1, "{err}");
    assert!(notes[0].contains("ks (set on the command line)"), "{err}");
}
