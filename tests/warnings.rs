//! Implausible but valid inputs: they run, give the same result as with `--quiet`, exit 0, and
//! print exactly one `warning:` line on stderr naming the value and the usual range; `--quiet`
//! silences it. And the defaults a new user meets: `--help` shows them, the default impact is
//! the centre of the string face, `speed` compares against A and shows both sides.

mod common;

use common::run;
use std::process::Output;

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// `args` warns once with every one of `words`, the result is the quiet run's, exit 0.
/// A racket file `name` with `contents` in a scratch folder (removed when the returned guard
/// is dropped).
fn racket_file(name: &str, contents: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, contents).unwrap();
    (dir, path)
}

fn warns_once(args: &[&str], words: &[&str]) {
    let loud = run(args);
    let quiet = run(&[&["--quiet"], args].concat());
    assert_eq!(loud.status.code(), Some(0), "{args:?}: {}", stderr(&loud));
    assert_eq!(quiet.status.code(), Some(0), "{args:?}");
    let err = stderr(&loud);
    let lines: Vec<&str> = err.lines().filter(|l| l.starts_with("warning:")).collect();
    assert_eq!(lines.len(), 1, "{args:?}: {err}");
    for w in words {
        assert!(lines[0].contains(w), "{args:?}: '{w}' not in {}", lines[0]);
    }
    assert!(stderr(&quiet).is_empty(), "{args:?}: --quiet still printed {}", stderr(&quiet));
    assert_eq!(stdout(&loud), stdout(&quiet), "{args:?}: the warning changed the result");
}

#[test]
fn implausible_values_run_and_warn_once() {
    // a stiffness in kN/m or lb, not N/m
    warns_once(&["simulate", "--ks", "40", "--format", "json"], &["ks = 40 N/m", "5000..200000 N/m"]);
    warns_once(&["simulate", "--ks", "5e5"], &["ks = 500000 N/m"]);
    warns_once(&["simulate", "--mass", "0.1"], &["mass = 0.1 kg", "0.15..1 kg"]);
    // (a ball stiff enough not to be squashed beyond its radius at 90 m/s, which warns too)
    warns_once(&["simulate", "--v1", "90", "--k1", "1.5e5"], &["v1 = 90 m/s", "1..70 m/s"]);
    warns_once(&["simulate", "--mu", "1.5", "--angle-deg", "30"], &["mu = 1.5", "0..1"]);
    warns_once(&["simulate", "--angle-deg", "84", "--v1", "20"], &["angle-deg = 84 deg", "0..80 deg"]);
    // a frame frequency no racket has: EI 20 on the paper's frame is about 46 Hz
    warns_once(&["simulate", "--ei", "20"], &["f1 = ", "60..300 Hz"]);
    warns_once(&["modes", "--ei", "5000"], &["f1 = ", "60..300 Hz"]);
    // a twist beyond the small-angle model, with every input in its usual range
    warns_once(&["simulate", "--x", "0.16", "--r", "0.12", "--ix", "5e-4", "--v1", "40"], &["theta_end = ", "15 deg"]);
    warns_once(&["speed", "--swing", "100", "--ks", "40"], &["ks = 40 N/m"]);
    warns_once(&["sweep", "--ks", "40,4e4", "--x", "0.1"], &["ks = 40 N/m"]);
}

/// A ball squashed beyond its own radius (every input in its usual range) is outside the
/// paper's linear ball; under the radius law the friction lever is clamped at zero.
#[test]
fn a_ball_compressed_beyond_its_radius_warns() {
    warns_once(&["simulate", "--v1", "69"], &["y0 = 61.7 mm", "radius 33 mm", "linear ball", "outside its range"]);
    warns_once(&["simulate", "--v1", "69", "--k1", "5000"], &["y0 = 191 mm", "radius 33 mm"]);
    let oblique = ["simulate", "--angle-deg", "30", "--azimuth-deg", "90", "--tangential", "radius", "--v1", "45"];
    warns_once(&oblique, &["radius 33 mm", "friction lever R - delta is clamped at 0"]);
    // within the radius: no warning
    let ok = run(&["simulate", "--v1", "30"]);
    assert!(stderr(&ok).is_empty(), "{}", stderr(&ok));
}

#[test]
fn a_racket_file_with_a_mass_typo_warns() {
    let (_dir, path) = racket_file(
        "typo.toml",
        "name = \"typo\"\nlength_cm = 68.6\nmass_g = 30\ntwistweight_kg_cm2 = 14\nfrequency_hz = 150\n",
    );
    warns_once(&["simulate", "--racket", path.to_str().unwrap()], &["mass = 0.03 kg"]);
}

#[test]
fn usual_values_do_not_warn() {
    for args in [
        vec!["simulate"],
        vec!["simulate", "--x", "0.10", "--r", "0.05", "--load", "node"],
        vec!["simulate", "--racket", "tweener"],
        vec!["speed", "--racket", "tweener", "--swing", "100", "--incoming", "60"],
        vec!["modes"],
    ] {
        let o = run(&args);
        assert!(o.status.success() && o.stderr.is_empty(), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn help_shows_every_default() {
    let help = stdout(&run(&["simulate", "--help"]));
    // (the help is wrapped at 100 columns: a flag's description is the lines up to a blank one)
    let words = |text: &str| text.split_whitespace().collect::<Vec<_>>().join(" ");
    for key in racket_impact::params::Overrides::KEYS {
        let lines: Vec<&str> = help
            .lines()
            .skip_while(|l| !l.trim_start().starts_with(&format!("--{key} ")))
            .skip(1)
            .take_while(|l| !l.trim().is_empty())
            .collect();
        let description = words(&lines.join(" "));
        assert!(description.contains("[default: "), "--{key}: {description}");
    }
    assert!(words(&help).contains("[default: 0.16 m, the centre of the string face"), "{help}");
    assert!(words(&help).contains("[default: 40000 N/m"), "{help}");
    let sweep = stdout(&run(&["sweep", "--help"]));
    assert!(words(&sweep).contains("x (0.16 m), r (0 m), ks (40000 N/m)"), "{sweep}");
}

#[test]
fn the_default_impact_is_the_centre_of_the_face_on_the_axis() {
    let v: serde_json::Value = serde_json::from_str(&stdout(&run(&["simulate", "--format", "json"]))).unwrap();
    assert_eq!((v["params"]["impact"]["x"].as_f64(), v["params"]["impact"]["r"].as_f64()), (Some(0.16), Some(0.0)));
    assert_eq!(v["theta_end_deg"].as_f64(), Some(0.0));
    // a racket file: the centre of its head outline
    let v: serde_json::Value =
        serde_json::from_str(&stdout(&run(&["simulate", "--racket", "tweener", "--format", "json"]))).unwrap();
    let head = v["params"]["racket"]["head_length"].as_f64().unwrap();
    assert_eq!(v["params"]["impact"]["x"].as_f64(), Some(0.5 * head));
    assert_eq!(v["params"]["impact"]["r"].as_f64(), Some(0.0));
}

#[test]
fn speed_compares_each_racket_or_tension_against_a_and_shows_both() {
    let text = stdout(&run(&["speed", "--racket", "tweener", "--compare-racket", "players", "--swing", "100"]));
    let rows: Vec<&str> = text.lines().skip(2).collect();
    assert_eq!(rows.len(), 2, "{text}");
    assert!(rows[0].starts_with("tweener ") && rows[0].contains("+0.00 %"), "{text}");
    assert!(rows[1].starts_with("players "), "{text}");
    // one tension: A as given against A at T
    let text = stdout(&run(&["speed", "--swing", "100", "--compare-tension-lb", "50"]));
    let rows: Vec<&str> = text.lines().skip(2).collect();
    assert_eq!(rows.len(), 2, "{text}");
    assert!(rows[0].starts_with("paper racket as given") && rows[1].starts_with("paper racket at 50 lb"), "{text}");
    // kph is km/h
    assert_eq!(
        stdout(&run(&["speed", "--swing", "100", "--unit", "kph"])),
        stdout(&run(&["speed", "--swing", "100", "--unit", "kmh"]))
    );
}

#[test]
fn a_racket_is_labelled_with_its_name() {
    let (_dir, path) = racket_file(
        "frame_v2.toml",
        "name = \"My frame\"\nlength_cm = 68.6\nmass_g = 300\ntwistweight_kg_cm2 = 14\nfrequency_hz = 150\n",
    );
    let text = stdout(&run(&["speed", "--racket", path.to_str().unwrap(), "--swing", "100"]));
    assert!(text.lines().nth(2).is_some_and(|l| l.starts_with("My frame ")), "{text}");
}

#[test]
fn text_output_prints_meaningful_digits() {
    let text = stdout(&run(&["simulate", "--racket", "tweener"]));
    assert!(text.contains("ks 36666.7 N/m"), "{text}");
    assert!(!text.contains("666666"), "{text}");
}

#[test]
fn sweep_rows_record_the_impact() {
    let text = stdout(&run(&["sweep", "--ks", "2e4", "--angle-deg", "30"]));
    let head = text.lines().next().unwrap();
    assert!(head.starts_with("ks_n_per_m,angle_deg,x_m,r_m,v1_m_per_s,azimuth_deg,spin_rpm,mu,e_a"), "{head}");
}

#[test]
fn map_says_when_a_config_files_impact_point_is_not_used() {
    let dir = tempfile::tempdir().unwrap();
    let cfg = dir.path().join("c.toml");
    std::fs::write(&cfg, "x = 0.1\nks = 3e4\n").unwrap();
    let out = dir.path().join("m.csv");
    let (cfg, out) = (cfg.to_str().unwrap(), out.to_str().unwrap());
    let args = ["map", "--config", cfg, "--nx", "3", "--nr", "3", "--format", "csv", "--out", out];
    warns_once(&args, &["config file", "x (not used by map)"]);
}

/// `racket` warns as `simulate` does for the same racket file (issue 24, class 7): a mass
/// outside the usual range, a frequency no racket has, a density squeezed into the ends; and a
/// real spec sheet runs without a warning.
#[test]
fn the_racket_command_warns_as_simulate_does() {
    let light = "length_cm = 68.58\nmass_g = 120\ntwistweight_kg_cm2 = 14\nfrequency_hz = 150\n";
    let (_d1, path) = racket_file("light.toml", light);
    let file = path.to_str().unwrap();
    warns_once(&["racket", file], &["mass = 0.12 kg", "0.15..1 kg"]);
    warns_once(&["simulate", "--racket", file], &["mass = 0.12 kg", "0.15..1 kg"]);
    let squeezed = "length_cm = 68.58\nmass_g = 300\nbalance_cm = 32.5\nswingweight_kg_cm2 = 400\n\
                    twistweight_kg_cm2 = 14\nfrequency_hz = 150\n";
    let (_d2, path) = racket_file("squeezed.toml", squeezed);
    let file = path.to_str().unwrap();
    warns_once(&["racket", file], &["racket density falls to", "0.25..4 times the mean"]);
    warns_once(&["simulate", "--racket", file], &["racket density falls to", "0.25..4 times the mean"]);
    let sheet = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/spec_sheets/babolat_pure_drive_2025.toml");
    let out = run(&["racket", sheet]);
    assert_eq!(out.status.code(), Some(0));
    assert!(stderr(&out).is_empty(), "{}", stderr(&out));
}

/// The warnings are data: the JSON output carries each under `diagnostics` (kind, field, the
/// sentence stderr prints), with `--quiet` too, which silences only the printing.
#[test]
fn json_output_carries_the_warnings_quiet_or_not() {
    let loud = run(&["simulate", "--ks", "40", "--format", "json"]);
    let quiet = run(&["--quiet", "simulate", "--ks", "40", "--format", "json"]);
    assert_eq!(stdout(&loud), stdout(&quiet));
    assert!(stderr(&quiet).is_empty(), "{}", stderr(&quiet));
    let v: serde_json::Value = serde_json::from_str(&stdout(&quiet)).unwrap();
    let d = v["diagnostics"].as_array().unwrap();
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!((d[0]["kind"].as_str(), d[0]["field"].as_str()), (Some("unusual"), Some("ks")));
    let line = stderr(&loud).lines().find(|l| l.starts_with("warning:")).unwrap().to_string();
    assert_eq!(line, format!("warning: {}", d[0]["sentence"].as_str().unwrap()));
    // a plausible run says nothing, as an empty list
    let calm: serde_json::Value = serde_json::from_str(&stdout(&run(&["simulate", "--format", "json"]))).unwrap();
    assert_eq!(calm["diagnostics"], serde_json::json!([]));
}

/// A property the impact does not exercise is a note among the diagnostics (kind `not_used`,
/// field its key; a config file's unused keys field `config`): printed as before, one
/// `warning:` line each, and carried by the JSON under `diagnostics`, with `--quiet` too.
#[test]
fn notes_about_what_the_impact_does_not_exercise_are_diagnostics() {
    let dir = tempfile::tempdir().unwrap();
    let cfg = dir.path().join("c.toml");
    // at the default impact point, on the long axis, the moment of inertia is not exercised
    std::fs::write(&cfg, "ix = 0.0012\n").unwrap();
    let cfg = cfg.to_str().unwrap();
    let simulate = ["simulate", "--config", cfg, "--mu", "0.4", "--format", "json"];
    let uncertainty =
        ["uncertainty", "--mu", "0.4", "--vary", "ks=uniform:2e4:6e4", "--samples", "64", "--format", "json"];
    let speed = ["speed", "--swing", "100", "--mu", "0.4", "--format", "json"];
    for (args, fields) in [(&simulate[..], &["mu", "config"][..]), (&uncertainty, &["mu"]), (&speed, &["mu"])] {
        let loud = run(args);
        assert_eq!(loud.status.code(), Some(0), "{args:?}: {}", stderr(&loud));
        let quiet = run(&[&["--quiet"][..], args].concat());
        assert_eq!(stdout(&loud), stdout(&quiet), "{args:?}");
        assert!(stderr(&quiet).is_empty(), "{args:?}: {}", stderr(&quiet));
        let v: serde_json::Value = serde_json::from_str(&stdout(&quiet)).unwrap();
        // (speed: each variant's row carries the notes, which hold for every variant)
        let d = if v.is_array() { v[0]["diagnostics"].clone() } else { v["diagnostics"].clone() };
        let notes: Vec<&serde_json::Value> = d.as_array().unwrap().iter().filter(|d| d["kind"] == "not_used").collect();
        let noted: Vec<&str> = notes.iter().map(|d| d["field"].as_str().unwrap()).collect();
        assert_eq!(noted, fields, "{args:?}: {d}");
        let err = stderr(&loud);
        let printed: Vec<&str> = err.lines().collect();
        for n in &notes {
            let line = format!("warning: {}", n["sentence"].as_str().unwrap());
            assert_eq!(printed.iter().filter(|l| **l == line).count(), 1, "{args:?}: {line} in {printed:?}");
        }
        assert!(notes[0]["sentence"].as_str().unwrap().starts_with("--mu 0.4 is not exercised by this impact"), "{d}");
    }
}
