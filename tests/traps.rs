//! The traps a hostile user found, class by class, and the tests that pin each: the one place
//! that lists them. Each class is fixed as a class (every output path, every input reader,
//! every list option), and each hostile case that found it is a named test.
//!
//! Issue 24 (first passes):
//! 1. Outputs written, never replaced (links, devices, read-only folders): `tests/outputs.rs`.
//! 2. Work bounded before it starts: `tests/bounds.rs`.
//! 3. and 4. Every option used or refused, help as accepted: `tests/options.rs`.
//! 5. Bad input: one line naming the field, exit 2, nothing written: `tests/bad_input.rs`.
//! 6. One vocabulary: `tests/vocabulary.rs`.
//! 9. The README's examples do what it says: `tests/readme.rs`.
//!
//! Issue 32 (third pass), in this file unless named:
//! 1. Nothing hangs inside the documented ranges, and what runs passes the energy checks:
//!    [`inertia_factor_1e_30_is_refused_by_every_command`],
//!    [`tiny_inertia_factors_never_run_to_nonsense`],
//!    [`modal_stiff_contact_is_refused_like_fd`]; the solvers' step bounds and the tangential
//!    ledger in `tests/tangential.rs` (`every_accepted_ball_passes_the_energy_check`).
//! 2. No output is an input: [`an_output_that_is_an_input_is_refused_before_any_work`],
//!    [`an_output_linked_to_an_input_is_refused`], [`no_command_writes_toml`].
//! 3. Sets of files published all or none, "wrote" said after:
//!    [`figures_publish_all_or_none`], [`map_says_wrote_only_after_publishing`]; the rollback
//!    in `src/render/io.rs` (`a_failed_print_puts_back_every_replaced_file`,
//!    `a_destination_that_changed_fails_before_any_rename`).
//! 4. An interrupted run leaves nothing: [`sigint_during_sweep_removes_its_temporary_file`],
//!    [`sigterm_during_sweep_removes_its_temporary_file`].
//! 5. Bounded reads: [`config_and_racket_files_must_be_regular_and_small`].
//! 6. A property this impact does not exercise is noted, an option a method cannot honour is
//!    refused: `tests/options.rs` and [`unused_properties_are_noted_not_refused`].
//! 7. Small silent acceptances: [`sweep_ranges_say_what_they_run`],
//!    [`duplicates_in_lists_are_refused`], [`series_values_too_small_are_refused_as_written`],
//!    [`a_name_with_a_line_break_is_refused`], [`a_preset_name_shadowed_by_a_file_is_refused`],
//!    [`an_impact_outside_the_racket_files_head_is_refused`].
//! 8. Where to start: [`help_names_a_first_command_and_groups_options`],
//!    [`suggestions_name_the_real_flag_or_nothing`].
//! 9. A project others can cite: [`licence_citation_and_changelog_are_there`].
//! 10. `make test` with only the Rust toolchain: `tests/makefile.rs`.
//!
//! Issue 40 (the first hour), item 4, at the end of this file:
//! [`an_interrupted_figures_run_leaves_no_directory_it_created`],
//! [`an_immutable_output_is_refused_before_the_work`],
//! [`figures_name_their_files_with_one_slash`],
//! [`map_prints_the_same_standard_output_twice`],
//! [`a_map_without_out_says_it_replaced_an_earlier_one`],
//! [`a_config_key_of_another_command_says_where_it_goes`],
//! [`a_warning_shows_the_digits_given`]; raw bytes of a config file escaped:
//! `src/params/overrides.rs` (`an_unknown_key_says_what_a_config_holds_and_raw_bytes_are_escaped`).
//!
//! Issue 48 (the first hour, second pass), item 7, at the end of this file: every output path
//! checked before the work ([`an_output_path_ending_in_a_slash_is_refused_before_the_work`]), one
//! rule for every input ([`calibrate_never_replaces_its_measurements`]), messages that cap and
//! escape what they quote ([`messages_cap_and_escape_what_they_quote`]; `numfmt::quoted`), and a
//! measurements header read as written ([`measurement_headers_named_twice_or_with_spaces_are_refused`]).

#![cfg(unix)]

mod common;

use common::{bin, names_in, Scratch};
use std::path::Path;
use std::process::{Command, Output, Stdio};

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Refused: exit 2, one line on stderr containing `says`, nothing on stdout.
#[track_caller]
fn refused(o: &Output, says: &str) {
    let e = stderr(o);
    assert_eq!(o.status.code(), Some(2), "must be refused: {e}");
    assert_eq!(e.lines().count(), 1, "one line: {e}");
    assert!(e.contains(says), "'{says}' expected in: {e}");
    assert!(o.stdout.is_empty(), "no output when refused: {}", stdout(o));
}

const CONFIG: &str = "ks = 3e4\n";
const RACKET: &str = "name = \"g\"\nlength_in = 27\nmass_g = 300\nbalance_cm = 33\nswingweight_kg_cm2 = 320\n\
                      twistweight_kg_cm2 = 14\nfrequency_hz = 130\nhead_size_sq_in = 100\ntension_lb = 55\n";

// ---- 1. hangs and nonsense inside the documented ranges ----

#[test]
fn inertia_factor_1e_30_is_refused_by_every_command() {
    let s = Scratch::new("traps");
    for args in [
        vec!["simulate", "--angle-deg", "30", "--ball-inertia-factor", "1e-30"],
        vec!["sweep", "--angle-deg", "30", "--ball-inertia-factor", "1e-30", "--x", "0.1,0.2"],
        vec!["speed", "--swing", "100", "--ball-inertia-factor", "1e-30"],
    ] {
        refused(&s.run(&args), "invalid ball-inertia-factor = 1e-30");
    }
}

#[test]
fn tiny_inertia_factors_never_run_to_nonsense() {
    let s = Scratch::new("traps");
    for alpha in ["1e-25", "1e-100", "1e-300", "0.05", "0.7", "1"] {
        let o = s.run(&["simulate", "--angle-deg", "30", "--ball-inertia-factor", alpha]);
        refused(&o, "ball-inertia-factor");
        assert!(stderr(&o).contains("2/3"), "the range is stated: {}", stderr(&o));
    }
    // the ends of the range run and pass the energy check
    for alpha in ["0.1", "0.4", "0.55", "0.6666"] {
        let o = s.run(&["simulate", "--angle-deg", "30", "--ball-inertia-factor", alpha, "--format", "json"]);
        assert!(o.status.success(), "{alpha}: {}", stderr(&o));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let err = v["energy_error"].as_f64().unwrap();
        assert!(err < 1e-4, "{alpha}: energy_error {err}");
    }
}

/// Accepted: exit 0 with a result that passes the energy and momentum checks of any impact;
/// or refused in one line naming the limit.
#[track_caller]
fn bounded(o: &Output, what: &str) {
    if o.status.success() {
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
        let (e, m) = (v["energy_error"].as_f64().unwrap(), v["momentum_error"].as_f64().unwrap());
        assert!(e < 1e-4 && m < 1e-6, "{what}: energy_error {e}, momentum_error {m}");
    } else {
        assert_eq!(o.status.code(), Some(2), "{what}: {}", stderr(o));
        assert_eq!(stderr(o).lines().count(), 1, "{what}: {}", stderr(o));
        assert!(stderr(o).contains("limit"), "{what}: {}", stderr(o));
    }
}

#[test]
fn modal_stiff_contact_is_refused_like_fd() {
    let s = Scratch::new("traps");
    let stiff = ["--v1", "1e-3", "--k1", "1e9", "--ks", "1e12", "--segments", "400", "--ei", "1e-2"];
    let mut args = vec!["simulate", "--solver", "fd"];
    args.extend(stiff);
    refused(&s.run(&args), "limit");
    // the modal solver takes no time step: its contact steps and its search of the free
    // vibration are bounded (solve::modal::MAX_MODE_SAMPLES), so it finishes or refuses
    let mut args = vec!["simulate", "--solver", "modal", "--format", "json"];
    args.extend(stiff);
    bounded(&s.run(&args), "simulate --solver modal");
}

// ---- 2. an output that is an input ----

#[test]
fn an_output_that_is_an_input_is_refused_before_any_work() {
    let s = Scratch::new("traps");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["sweep", "--racket", "g.toml", "--out", "g.toml", "--x", "0.1"], "g.toml"),
        (vec!["sweep", "--config", "c.toml", "--out", "./c.toml", "--x", "0.1"], "c.toml"),
        (vec!["simulate", "--config", "c.toml", "--solver", "fd", "--series", "c.toml"], "c.toml"),
        (
            vec![
                "uncertainty",
                "--config",
                "c.toml",
                "--vary",
                "v1=uniform:20:40",
                "--samples",
                "8",
                "--out",
                "c.toml",
            ],
            "c.toml",
        ),
        (vec!["map", "--config", "m.json", "--nx", "3", "--nr", "3", "--out", "m.csv"], "m.json"),
        (vec!["map", "--racket", "h.csv", "--nx", "3", "--nr", "3", "--out", "h.csv"], "h.csv"),
        (
            vec!["card", "--racket", "h.csv", "--tensions-lb", "50,60", "--nx", "3", "--nr", "3", "--out", "h.csv"],
            "h.csv",
        ),
        (
            vec!["card", "--config", "m.png", "--tensions-lb", "50,60", "--nx", "3", "--nr", "3", "--out", "m.csv"],
            "m.png",
        ),
    ];
    for (args, input) in cases {
        s.file("c.toml", CONFIG);
        s.file("m.json", CONFIG);
        s.file("m.png", CONFIG);
        s.file("g.toml", RACKET);
        s.file("h.csv", RACKET);
        let before = std::fs::read(s.path(input)).unwrap();
        let o = s.run(&args);
        refused(&o, "an input of this command");
        assert_eq!(std::fs::read(s.path(input)).unwrap(), before, "{args:?} changed {input}");
        let left: Vec<String> = s.names().into_iter().filter(|n| n.starts_with('.')).collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
}

#[test]
fn an_output_linked_to_an_input_is_refused() {
    let s = Scratch::new("traps");
    s.file("c.toml", CONFIG);
    std::os::unix::fs::symlink("c.toml", s.path("out.csv")).unwrap();
    std::fs::hard_link(s.path("c.toml"), s.path("hard.csv")).unwrap();
    for out in ["out.csv", "hard.csv"] {
        let o = s.run(&["sweep", "--config", "c.toml", "--out", out, "--x", "0.1"]);
        refused(&o, "is the same file as c.toml");
        assert_eq!(std::fs::read_to_string(s.path("c.toml")).unwrap(), CONFIG);
    }
    // the absolute spelling too
    let abs = s.path("c.toml");
    let o = s.run(&["simulate", "--config", "c.toml", "--solver", "fd", "--series", abs.to_str().unwrap()]);
    refused(&o, "an input of this command");
}

#[test]
fn no_command_writes_toml() {
    let s = Scratch::new("traps");
    s.file("g.toml", RACKET);
    for args in [
        vec!["report", "--out", "g.toml"],
        vec!["sweep", "--out", "new.toml", "--x", "0.1"],
        vec!["simulate", "--solver", "fd", "--series", "g.toml"],
    ] {
        refused(&s.run(&args), ".toml");
    }
    assert_eq!(std::fs::read_to_string(s.path("g.toml")).unwrap(), RACKET);
    assert!(!s.path("new.toml").exists());
}

// ---- 3. sets of files published all or none ----

#[test]
fn figures_publish_all_or_none() {
    let s = Scratch::new("traps");
    std::fs::create_dir(s.path("out")).unwrap();
    std::fs::write(s.path("out/fig4_energy.csv"), "old").unwrap();
    // the later experiment's figure cannot be written: a directory is in its place
    std::fs::create_dir(s.path("out/modes.png")).unwrap();
    let o = s.run(&["figures", "--only", "fig4_energy", "--only", "modes", "--out", "out"]);
    refused(&o, "modes.png");
    assert!(!stderr(&o).contains("->"), "nothing said written: {}", stderr(&o));
    assert_eq!(std::fs::read_to_string(s.path("out/fig4_energy.csv")).unwrap(), "old");
    let mut names: Vec<String> =
        std::fs::read_dir(s.path("out")).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    names.sort();
    assert_eq!(names, ["fig4_energy.csv", "modes.png"]);
    // and when every destination can be written, every file is, then named
    std::fs::remove_dir(s.path("out/modes.png")).unwrap();
    let o = s.run(&["figures", "--only", "fig4_energy", "--only", "modes", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stderr(&o).lines().filter(|l| l.contains("->")).count(), 2, "{}", stderr(&o));
    for f in ["fig4_energy.csv", "fig4_energy.png", "modes.csv", "modes.png"] {
        assert!(s.path("out").join(f).is_file(), "{f}");
    }
}

#[test]
fn map_says_wrote_only_after_publishing() {
    let s = Scratch::new("traps");
    let o = s.run(&["map", "--nx", "3", "--nr", "3", "--out", "m.csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("wrote m.csv, m.png, m.json"), "{}", stdout(&o));
    // a failing standard output after the renames puts every file back as it was
    for f in ["m.csv", "m.png", "m.json"] {
        std::fs::write(s.path(f), "old").unwrap();
    }
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
    let o = bin()
        .current_dir(s.dir())
        .args(["map", "--nx", "3", "--nr", "3", "--out", "m.csv"])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    for f in ["m.csv", "m.png", "m.json"] {
        assert_eq!(std::fs::read_to_string(s.path(f)).unwrap(), "old", "{f} put back");
    }
    assert_eq!(s.names(), ["m.csv", "m.json", "m.png"], "nothing left beside them");
}

// ---- 4. an interrupted run leaves nothing ----

/// Start a sweep too long to finish (a million impacts) writing `big.csv`, wait until its
/// temporary file exists, send `signal`, and check the exit status and that nothing is left.
fn interrupt_sweep(signal: &str, status: i32) {
    let s = Scratch::new("traps");
    let mut child = bin()
        .current_dir(s.dir())
        .args(["sweep", "--out", "big.csv", "--x", "0.02:0.6:1000", "--ks", "1e4:6e4:1000"])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    // poll for the staged file (no clock: the loop ends when it appears or the run ends)
    loop {
        if s.names().iter().any(|n| n.starts_with(".big.csv.tmp.")) {
            break;
        }
        if let Some(st) = child.try_wait().unwrap() {
            panic!("the sweep ended before it was interrupted: {st}");
        }
        std::thread::yield_now();
    }
    let sent = Command::new("kill").args([&format!("-{signal}"), &child.id().to_string()]).status().unwrap();
    assert!(sent.success());
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(status), "{signal}: {}", stderr(&o));
    assert!(s.names().is_empty(), "{signal} left {:?}", s.names());
}

#[test]
fn sigint_during_sweep_removes_its_temporary_file() {
    interrupt_sweep("INT", 130);
}

#[test]
fn sigterm_during_sweep_removes_its_temporary_file() {
    interrupt_sweep("TERM", 143);
}

// ---- 5. bounded reads ----

#[test]
fn config_and_racket_files_must_be_regular_and_small() {
    let s = Scratch::new("traps");
    let fifo = s.path("fifo.toml");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let big = s.path("big.toml");
    let mut text = String::from("# padding\n");
    while text.len() <= 1 << 20 {
        text.push_str("# a comment line that makes the file larger than any config needs to be\n");
    }
    text.push_str("ks = 3e4\n");
    std::fs::write(&big, text).unwrap();
    for (file, says) in [
        ("/dev/zero", "not a regular file"),
        ("/dev/urandom", "not a regular file"),
        ("fifo.toml", "not a regular file"),
        ("big.toml", "MiB"),
    ] {
        refused(&s.run(&["simulate", "--config", file]), says);
        refused(&s.run(&["simulate", "--racket", file]), says);
        refused(&s.run(&["sweep", "--config", file, "--x", "0.1"]), says);
    }
    refused(&s.run(&["simulate", "--config", "."]), "directory");
}

// ---- 9. a project others can cite ----

#[test]
fn licence_citation_and_changelog_are_there() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |f: &str| std::fs::read_to_string(root.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
    let cargo = read("Cargo.toml");
    assert!(cargo.contains("license = \"MIT OR Apache-2.0\""));
    assert!(read("LICENSE-MIT").contains("Permission is hereby granted, free of charge"));
    assert!(read("LICENSE-APACHE").contains("Apache License") && read("LICENSE-APACHE").contains("Version 2.0"));
    let cff = read("CITATION.cff");
    assert!(cff.contains("cff-version: 1.2.0") && cff.contains("type: software"), "the software is cited");
    assert!(cff.contains("Flexible beam analysis") && cff.contains("Sports Engineering"), "the paper is cited");
    let version = cargo.lines().find(|l| l.starts_with("version")).unwrap().split('"').nth(1).unwrap();
    assert!(cff.contains(&format!("version: {version}")), "CITATION.cff's version is Cargo.toml's");
    let log = read("CHANGELOG.md");
    assert!(log.contains("## Unreleased"));
    assert!(log.contains("`v2_t` -> `v2_t_m_per_s`"), "the rename that broke scripts is recorded");
}

// ---- 7. small silent acceptances ----

#[test]
fn sweep_ranges_say_what_they_run() {
    let s = Scratch::new("traps");
    refused(&s.run(&["sweep", "--x", "0.1:0.2:1"]), "ignores the stop");
    refused(&s.run(&["sweep", "--x", "0.1:0.1:5"]), "the ends are equal");
    refused(&s.run(&["sweep", "--segments", "4:400:1000"]), "give a count of at most 397");
    // a count of 1 on equal ends is the one value; 397 whole segment counts run once each
    assert!(s.run(&["sweep", "--x", "0.1:0.1:1"]).status.success());
    let o = s.run(&["sweep", "--out", "s.csv", "--segments", "4:400:397", "--solver", "modal", "--x", "0.1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(s.path("s.csv")).unwrap().lines().count(), 1 + 397);
}

#[test]
fn duplicates_in_lists_are_refused() {
    let s = Scratch::new("traps");
    refused(&s.run(&["sweep", "--load", "node,hat,node"]), "node is given twice");
    refused(&s.run(&["sweep", "--x", "0.1,1e-1"]), "given twice");
    refused(&s.run(&["speed", "--swing", "100", "--compare-racket", "tweener,tweener"]), "given twice");
    refused(&s.run(&["speed", "--swing", "100", "--racket", "tweener", "--compare-racket", "tweener"]), "given twice");
    refused(&s.run(&["speed", "--swing", "100", "--compare-tension-lb", "50,50"]), "given twice");
}

#[test]
fn series_values_too_small_are_refused_as_written() {
    let s = Scratch::new("traps");
    let series = ["simulate", "--solver", "fd", "--series", "t.csv"];
    for (flag, value) in [("--series-end", "1e-400"), ("--series-dt", "1e-400")] {
        let mut args = series.to_vec();
        args.extend([flag, value]);
        refused(&s.run(&args), "too small to represent");
    }
    refused(&s.run(&["speed", "--swing", "1e-400"]), "too small to represent");
    let mut args = series.to_vec();
    args.extend(["--series-dt", "1e308"]);
    refused(&s.run(&args), "at least two samples");
    assert!(!s.path("t.csv").exists());
    // (issue 40) the ends of a sweep's range and of a drawn distribution, as any number option
    refused(&s.run(&["sweep", "--x", "1e-400:0.2:3"]), "start is too small to represent");
    refused(&s.run(&["sweep", "--ks", "1e3:1e400:3:log"]), "stop is too large to represent");
    refused(&s.run(&["uncertainty", "--vary", "ks=uniform:1e-400:1e4"]), "LO is too small to represent");
}

/// A sample spacing below the solver's step cannot be honoured (the series has one row per
/// step at most): the run says so in one note, naming the step (issue 40; it used the step
/// silently).
#[test]
fn a_series_spacing_below_the_step_is_noted() {
    let s = Scratch::new("traps");
    let o = s.run(&["simulate", "--solver", "fd", "--series", "t.csv", "--series-dt", "1e-9"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let notes: Vec<String> = stderr(&o).lines().filter(|l| l.contains("--series-dt")).map(String::from).collect();
    assert_eq!(notes.len(), 1, "{}", stderr(&o));
    assert!(notes[0].starts_with("warning: --series-dt 1e-9 s is below the solver's step"), "{}", notes[0]);
    assert!(notes[0].contains("one row per step"), "{}", notes[0]);
    // at or above the step: no note
    let o = s.run(&["simulate", "--solver", "fd", "--series", "t.csv", "--series-dt", "2e-5"]);
    assert!(!stderr(&o).contains("--series-dt"), "{}", stderr(&o));
}

#[test]
fn a_name_with_a_line_break_is_refused() {
    let s = Scratch::new("traps");
    s.file("g.toml", RACKET.replace("name = \"g\"", "name = \"two\\nlines\""));
    refused(&s.run(&["racket", "g.toml"]), "line breaks");
    refused(&s.run(&["speed", "--swing", "100", "--compare-racket", "a\nb"]), "line breaks");
}

#[test]
fn a_preset_name_shadowed_by_a_file_is_refused() {
    let s = Scratch::new("traps");
    s.file("tweener", RACKET);
    refused(&s.run(&["racket", "tweener"]), "./tweener");
    let o = s.run(&["racket", "./tweener"]);
    assert!(o.status.success(), "the file, named as a path: {}", stderr(&o));
}

#[test]
fn an_impact_outside_the_racket_files_head_is_refused() {
    let s = Scratch::new("traps");
    s.file("g.toml", RACKET);
    refused(&s.run(&["simulate", "--racket", "g.toml", "--half-width", "0.2", "--r", "0.15"]), "head outline");
    refused(&s.run(&["simulate", "--racket", "g.toml", "--r", "0.15"]), "r");
}

// ---- 8. where to start ----

#[test]
fn help_names_a_first_command_and_groups_options() {
    let top = stdout(&bin().arg("--help").output().unwrap());
    assert!(top.contains("Start here: racket-impact simulate"), "{top}");
    assert!(top.contains("Examples:"), "{top}");
    for command in ["simulate", "speed", "map", "uncertainty"] {
        let help = stdout(&bin().args([command, "--help"]).output().unwrap());
        for heading in ["Impact:", "Racket:", "Ball:", "Strings:", "Numerics:", "Output:"] {
            assert!(help.contains(&format!("\n{heading}\n")), "{command} --help has no {heading}");
        }
    }
}

/// Every command's long help opens with its examples (before the usage line and the options:
/// `calibrate --help` had its one example at the end of a 1,316-character line) and reads at 100
/// columns: no line wider where the width is not a terminal's (`uncertainty --help` ran 216 lines
/// with lines of 500), nor on a terminal wider (`COLUMNS=200`); a narrower one is followed.
#[test]
fn every_help_opens_with_examples_and_reads_at_100_columns() {
    // the commands as the top-level help lists them
    let top = stdout(&bin().arg("--help").output().unwrap());
    let commands: Vec<String> = top
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next().map(String::from))
        .filter(|c| c != "help")
        .collect();
    assert!(commands.len() >= 11, "{commands:?}");
    // (the usage line is clap's, never wrapped: about 70 characters at most)
    let widest =
        |text: &str| text.lines().filter(|l| !l.starts_with("Usage:")).map(|l| l.chars().count()).max().unwrap_or(0);
    for command in &commands {
        let help = stdout(&bin().args([command.as_str(), "--help"]).output().unwrap());
        let usage = help.find("\nUsage:").unwrap_or_else(|| panic!("{command} --help has no usage"));
        let example = help
            .find(&format!("\n  racket-impact {command}"))
            .or_else(|| help.find(&format!("Example: racket-impact {command}")));
        assert!(example.is_some_and(|e| e < usage), "{command} --help does not open with an example:\n{help}");
        assert!(widest(&help) <= 100, "{command} --help has a line of {} characters", widest(&help));
        for columns in ["200", "60"] {
            let o = bin().args([command.as_str(), "--help"]).env("COLUMNS", columns).output().unwrap();
            let most = columns.parse::<usize>().unwrap().min(100);
            assert!(widest(&stdout(&o)) <= most, "{command} --help at COLUMNS={columns}: {}", widest(&stdout(&o)));
        }
    }
    assert!(widest(&stdout(&bin().arg("--help").output().unwrap())) <= 100);
}

#[test]
fn suggestions_name_the_real_flag_or_nothing() {
    let s = Scratch::new("traps");
    for (args, says, not) in [
        (vec!["speed", "--swing", "100", "--spin-rpm", "100"], "--incoming-spin-rpm", "'--p'"),
        (vec!["map", "--r", "0.1"], "the grid sets the impact point", "--grip"),
        (vec!["map", "--dt", "1e-6"], "modal solver", "--hand-stiffness"),
        (vec!["uncertainty", "--series", "t.csv"], "simulate --solver fd --series", "--ei"),
        (vec!["simulate", "--segmets", "40"], "did you mean --segments", "similar"),
    ] {
        let o = s.run(&args);
        refused(&o, says);
        assert!(!stderr(&o).contains(not), "{args:?}: {}", stderr(&o));
    }
}

// ---- 6. a property this impact does not exercise is noted; a method's option refused ----

#[test]
fn unused_properties_are_noted_not_refused() {
    let s = Scratch::new("traps");
    for (args, key) in [
        (vec!["simulate", "--r", "0", "--ix", "0.0012"], "--ix"),
        (vec!["simulate", "--mu", "0.4"], "--mu"),
        (vec!["simulate", "--angle-deg", "0", "--ball-inertia-factor", "0.4"], "--ball-inertia-factor"),
        (vec!["sweep", "--mu", "0.3,0.4", "--x", "0.1"], "--mu"),
    ] {
        let o = s.run(&args);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let notes: Vec<&str> = err.lines().filter(|l| l.contains("not exercised")).collect();
        assert_eq!(notes.len(), 1, "{args:?}: one note: {}", stderr(&o));
        assert!(notes[0].contains(key), "{args:?}: {}", notes[0]);
    }
    // the result is the impact's, as without the unexercised property
    let with = s.run(&["simulate", "--mu", "0.4", "--format", "csv"]);
    let without = s.run(&["simulate", "--format", "csv"]);
    assert_eq!(stdout(&with), stdout(&without));
    // an option a chosen method cannot honour stays refused
    refused(&s.run(&["simulate", "--solver", "modal", "--dt", "1e-6"]), "invalid dt");
    refused(&s.run(&["sweep", "--solver", "modal", "--dt", "1e-6,2e-6", "--x", "0.1"]), "invalid dt");
    refused(&s.run(&["simulate", "--hand-stiffness", "1e4"]), "invalid hand-stiffness");
}

// ---- issue 40, item 4: the last small traps ----

/// `figures --out figs/sub` interrupted while it computes removes the directories it created
/// (it left an empty `figs/`); a directory that was there before is kept.
#[test]
fn an_interrupted_figures_run_leaves_no_directory_it_created() {
    let s = Scratch::new("traps");
    std::fs::create_dir(s.path("kept")).unwrap();
    for (out, created) in [("figs/sub", "figs"), ("kept", "")] {
        let mut child = bin()
            .current_dir(s.dir())
            .args(["figures", "--out", out])
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("spawn");
        // poll (no clock) for the directory it creates, or for the first file it stages in the
        // one that was there: the run is then under way, its interrupt handler in place
        let started = || {
            if created.is_empty() {
                std::fs::read_dir(s.path(out)).unwrap().next().is_some()
            } else {
                s.path(out).is_dir()
            }
        };
        while !started() {
            assert!(child.try_wait().unwrap().is_none(), "figures ended before it was interrupted");
            std::thread::yield_now();
        }
        let sent = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
        assert!(sent.success());
        let o = child.wait_with_output().unwrap();
        use std::os::unix::process::ExitStatusExt;
        assert_eq!(o.status.code(), Some(130), "{:?} {}", o.status.signal(), stderr(&o));
        if created.is_empty() {
            assert!(s.path(out).is_dir(), "{out} was there before: kept");
            assert_eq!(std::fs::read_dir(s.path(out)).unwrap().count(), 0, "nothing left in {out}");
        } else {
            assert!(!s.path(created).exists(), "{created} left behind");
        }
    }
}

/// An existing output marked immutable (`chattr +i`) is refused before the work, the option and
/// the reason named (it failed after the work with a bare "Operation not permitted"). Needs a
/// file system and a user that may set the attribute; elsewhere the test says so and checks
/// nothing.
#[test]
fn an_immutable_output_is_refused_before_the_work() {
    let s = Scratch::new("traps");
    let out = s.file("u.csv", "old");
    let set = Command::new("chattr").arg("+i").arg(&out).stderr(Stdio::null()).status();
    if !set.is_ok_and(|st| st.success()) {
        eprintln!("chattr +i is not permitted here: the immutable output is not checked");
        return;
    }
    let o = s.run(&["uncertainty", "--vary", "ks", "--samples", "1", "--out", "u.csv"]);
    let _ = Command::new("chattr").arg("-i").arg(&out).status();
    refused(&o, "invalid out = u.csv: the existing file cannot be replaced");
    assert!(stderr(&o).contains("immutable"), "{}", stderr(&o));
}

/// The files `figures` names are joined as paths (`figures --out /` printed `//modes.csv`).
#[test]
fn figures_name_their_files_with_one_slash() {
    let s = Scratch::new("traps");
    let o = s.run(&["figures", "--only", "modes", "--out", "figs/"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("-> figs/modes.{csv,png}"), "{}", stderr(&o));
}

/// The same map twice prints the same standard output: the time goes to standard error, and
/// not at all under `--quiet` (it printed "(0.05 s)" in its summary line).
#[test]
fn map_prints_the_same_standard_output_twice() {
    let s = Scratch::new("traps");
    let args = ["map", "--nx", "3", "--nr", "2", "--out", "m.csv"];
    let (a, b) = (s.run(&args), s.run(&args));
    assert!(a.status.success() && b.status.success(), "{}", stderr(&a));
    assert_eq!(stdout(&a), stdout(&b));
    assert!(stderr(&a).lines().any(|l| l.starts_with("map: 2 impacts in ")), "{}", stderr(&a));
    let quiet = s.run(&["--quiet", "map", "--nx", "3", "--nr", "2", "--out", "m.csv"]);
    assert_eq!(stdout(&quiet), stdout(&a));
    assert!(quiet.stderr.is_empty(), "{}", stderr(&quiet));
}

/// `map` without `--out` writes `map_<quantity>.*` into the current folder; replacing an
/// earlier map there is said in one line (it was silent). The root's .gitignore ignores them.
#[test]
fn a_map_without_out_says_it_replaced_an_earlier_one() {
    let s = Scratch::new("traps");
    let first = s.run(&["map", "--nx", "3", "--nr", "2"]);
    assert!(first.status.success(), "{}", stderr(&first));
    assert!(!stderr(&first).contains("replaced"), "{}", stderr(&first));
    let again = s.run(&["map", "--nx", "3", "--nr", "2"]);
    let notes: Vec<String> = stderr(&again).lines().filter(|l| l.contains("replaced")).map(String::from).collect();
    assert_eq!(notes.len(), 1, "{}", stderr(&again));
    assert!(notes[0].starts_with("warning: replaced map_power.csv, map_power.png and map_power.json"), "{}", notes[0]);
    let ignore = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/.gitignore")).unwrap();
    for pattern in ["/map_*.csv", "/map_*.png", "/map_*.json"] {
        assert!(ignore.lines().any(|l| l == pattern), ".gitignore lacks {pattern}");
    }
}

/// A config file holds parameters; a command's own option in it (`swing`, which `speed` takes
/// on its command line) is refused in one line that says where it goes, as README says.
#[test]
fn a_config_key_of_another_command_says_where_it_goes() {
    let s = Scratch::new("traps");
    s.file("shared.toml", "ks = 3e4\nswing = 30\n");
    let o = s.run(&["simulate", "--config", "shared.toml"]);
    refused(&o, "unknown key `swing` (line 2): a config file holds parameters");
    assert!(stderr(&o).contains("speed's --swing"), "{}", stderr(&o));
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let readme = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(readme.contains("A config file holds parameters only: a command's own option (`speed --swing`"));
}

/// A value outside the usual range is shown with the digits it was given (`--p 1.000001`
/// warned "p = 1 is outside the usual range").
#[test]
fn a_warning_shows_the_digits_given() {
    let s = Scratch::new("traps");
    let o = s.run(&["simulate", "--p", "1.000001"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("warning: p = 1.000001 is outside the usual 1.2..5"), "{}", stderr(&o));
}

// ---- Issue 48 (the first hour, second pass), item 7: nothing learnt only after the work ----

/// The lab rows of the option tests (free racket, oblique shots), written into `s` as `name`.
fn lab_csv(s: &Scratch, name: &str) -> String {
    s.file(name, std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/calibrate_lab.csv")).unwrap())
}

/// An output path that can only name a directory (`sub/`, `new/`, `sub/.`) is refused before the
/// work by every command that writes one, naming its option: `sweep --out new/` ran the whole
/// sweep and then failed with "Not a directory", as `calibrate --out` and `--plot` did (and
/// `--plot` was named `out`). The message is the pre-work check's (`invalid <option> = ...`; the
/// late failure named the path alone), and nothing is left.
#[test]
fn an_output_path_ending_in_a_slash_is_refused_before_the_work() {
    let s = Scratch::new("traps");
    std::fs::create_dir(s.path("sub")).unwrap();
    let lab = lab_csv(&s, "lab.csv");
    for path in ["sub/", "new/", "sub/.", "m.csv/"] {
        let cases: Vec<(Vec<&str>, &str)> = vec![
            (vec!["sweep", "--out", path, "--x", "0.1,0.2"], "out"),
            (vec!["calibrate", &lab, "--fit", "kt", "--hold-out", "none", "--out", path], "out"),
            (vec!["calibrate", &lab, "--fit", "kt", "--hold-out", "none", "--plot", path], "plot"),
            (vec!["map", "--nx", "3", "--nr", "2", "--out", path], "out"),
            (vec!["simulate", "--solver", "fd", "--series", path], "series"),
            (vec!["uncertainty", "--vary", "v1=uniform:6:8", "--samples", "8", "--out", path], "out"),
            (vec!["report", "--out", path], "out"),
        ];
        for (args, field) in cases {
            let o = s.run(&args);
            refused(&o, &format!("invalid {field} = {path}: "));
            assert!(stderr(&o).contains("give a file name"), "{args:?}: {}", stderr(&o));
        }
    }
    assert_eq!(s.names(), ["lab.csv", "sub"]);
    assert!(names_in(&s.path("sub")).is_empty());
}

/// Every input of every command is protected by one rule: `calibrate`'s measurements CSV is an
/// input as a config or racket file is (`--plot lab.csv` replaced the lab's data with a PNG, and
/// an `--out` that was a link to it replaced it with the fit), so an output that is the same file
/// (spelled otherwise, a symbolic or hard link) is refused before the work; and the command's two
/// outputs cannot be one file.
#[test]
fn calibrate_never_replaces_its_measurements() {
    let s = Scratch::new("traps");
    let lab = lab_csv(&s, "lab.csv");
    let before = std::fs::read(&lab).unwrap();
    std::os::unix::fs::symlink("lab.csv", s.path("link.csv")).unwrap();
    std::fs::hard_link(&lab, s.path("hard.csv")).unwrap();
    for (option, out) in [("--plot", "lab.csv"), ("--out", "./lab.csv"), ("--out", "link.csv"), ("--plot", "hard.csv")]
    {
        let o = s.run(&["calibrate", "lab.csv", "--fit", "kt", "--hold-out", "none", option, out]);
        refused(&o, &format!("invalid {} = {out}: is the same file as lab.csv, an input", &option[2..]));
        assert_eq!(std::fs::read(&lab).unwrap(), before, "{option} {out} changed the measurements");
    }
    let o = s.run(&[
        "calibrate",
        "lab.csv",
        "--fit",
        "kt",
        "--hold-out",
        "none",
        "--out",
        "./fit.txt",
        "--plot",
        "fit.txt",
    ]);
    refused(&o, "invalid out = ./fit.txt: is the same file as --plot fit.txt");
    assert_eq!(s.names(), ["hard.csv", "lab.csv", "link.csv"]);
    // two files, written together
    let o =
        s.run(&["calibrate", "lab.csv", "--fit", "kt", "--hold-out", "none", "--out", "fit.txt", "--plot", "fit.png"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(s.path("fit.txt")).unwrap().starts_with("calibrate: "));
    assert!(std::fs::read(s.path("fit.png")).unwrap().starts_with(b"\x89PNG"));
}

/// What a message quotes from the user's input is escaped and capped, saying how much it cut: an
/// 8 MiB CSV cell came back as 8.4 MB of standard error, a NUL byte in a cell was printed raw, a
/// list of ten thousand ids was echoed whole.
#[test]
fn messages_cap_and_escape_what_they_quote() {
    let s = Scratch::new("traps");
    let header = "id,role,quantity,value,uncertainty,unit,ball_speed_m_s,angle_deg,spin_in_rpm,string_tension_lb,string,support\n";
    let row = |support: &str| format!("L01,calibration,spin_out_rpm,1720,20,rpm,20,30,0,,,{support}\n");
    let huge = "x".repeat(8 << 20);
    s.file("huge.csv", format!("{header}{}", row(&huge)));
    s.file("nul.csv", format!("{header}{}", row("fr\0ee")));
    s.file("huge_unit.csv", format!("{header}{}", row("free").replace(",rpm,", &format!(",{huge},"))));
    let ids = vec!["modes"; 10_000].join(",");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["calibrate", "huge.csv", "--fit", "kt"], "more characters)"),
        (vec!["calibrate", "huge_unit.csv", "--fit", "kt"], "more characters)"),
        (vec!["calibrate", "nul.csv", "--fit", "kt"], "support 'fr\\u{0}ee' has no racket"),
        (vec!["figures", "--only", &ids], "more characters)"),
    ];
    for (args, says) in cases {
        let o = s.run(&args);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{}", &e[..e.len().min(500)]);
        assert!(e.len() < 1000, "{:?}: {} bytes of stderr: {}", &args[..2], e.len(), &e[..500]);
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(e.contains(says), "'{says}' expected in: {e}");
        assert!(!e.trim_end().chars().any(char::is_control), "a raw control character: {e:?}");
    }
    // the count cut is said: 8 MiB less what is shown
    let o = s.run(&["calibrate", "huge.csv", "--fit", "kt"]);
    assert!(stderr(&o).contains(&format!("x... ({} more characters)", (8 << 20) - 80)), "{}", stderr(&o));
}

/// A measurements CSV whose header names a column twice is refused, naming it and both columns
/// (it was read from one of them without a word, or refused as a "duplicate field" of column
/// `?`); a header name with a space at its end (`support `) is refused naming it (every row was
/// refused instead with "no support").
#[test]
fn measurement_headers_named_twice_or_with_spaces_are_refused() {
    let s = Scratch::new("traps");
    let lab = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/calibrate_lab.csv")).unwrap();
    let (header, rows) = lab.split_once('\n').unwrap();
    let (header, rows): (&str, Vec<&str>) = (header.trim_end(), rows.lines().collect());
    let with = |extra: &str| rows.iter().map(|r| format!("{r},{extra}\n")).collect::<String>();
    s.file("twice.csv", format!("{header},support\n{}", with("free")));
    s.file("notes.csv", format!("{header},notes\n{}", with("again")));
    s.file("space.csv", format!("{}\n{}\n", header.replace("support", "support "), rows.join("\n")));
    refused(
        &s.run(&["calibrate", "twice.csv", "--fit", "kt"]),
        "invalid measurements = twice.csv: column 'support' is named twice in the header (columns 12 and 14)",
    );
    refused(&s.run(&["calibrate", "notes.csv", "--fit", "kt"]), "column 'notes' is named twice in the header");
    refused(
        &s.run(&["calibrate", "space.csv", "--fit", "kt"]),
        "column 12 of the header, 'support ', has a space at its start or end: name it 'support'",
    );
}
