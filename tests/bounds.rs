//! Work is bounded before it starts (trap class 2 of issue 24): every count a user's input
//! sizes (a sweep's ranges and their product, a time series' rows, compared variants, a map's
//! grid, modes, segments) is checked against its declared limit (params/limits.rs and the
//! ranges of the parameters) before anything is allocated. Each case runs under a 1 GB limit
//! of virtual memory: allocating first would abort (not exit 2), so the test cannot pass by
//! waiting.

#![cfg(unix)]

use std::process::Command;

fn run_limited(args: &[&str], dir: &std::path::Path) -> std::process::Output {
    // `ulimit -v` in KiB: 1 GiB of address space, far below what any of these would allocate
    let script = "ulimit -v 1048576 && exec \"$0\" \"$@\"";
    Command::new("sh")
        .current_dir(dir)
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_racket-impact"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn every_count_from_the_input_is_checked_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let many_tensions: String = (1..=60).map(|t| t.to_string()).collect::<Vec<_>>().join(",");
    let cases: Vec<(Vec<&str>, &str, &str)> = vec![
        (vec!["sweep", "--x", "0.1:0.2:1000000000"], "invalid sweep", "at most 1000000"),
        (vec!["sweep", "--x", "0.1:0.2:99999999999999999999999"], "invalid sweep", "at most 1000000"),
        (vec!["sweep", "--x", "0.1:0.2:1e9"], "invalid sweep", "at most 1000000"),
        (vec!["sweep", "--x", "0.1:0.2:2.5"], "invalid sweep", "whole number >= 1"),
        (
            vec!["sweep", "--x", "0.1:0.2:1000", "--ks", "1e4:5e4:1000", "--mb", "0.05:0.06:1000"],
            "invalid sweep",
            "at most 10000000",
        ),
        (
            vec!["simulate", "--series", "s.csv", "--series-dt", "1e-9", "--series-end", "10"],
            "invalid series-end",
            "at most 1000000",
        ),
        (
            vec!["speed", "--swing", "100", "--compare-tension-lb", &many_tensions],
            "invalid compare-tension-lb",
            "at most 50",
        ),
        (vec!["map", "--nx", "100000"], "invalid nx", "<= 401"),
        (vec!["map", "--nr", "18446744073709551615"], "invalid nr", "<= 401"),
        (vec!["modes", "--count", "1000000"], "invalid count", "count <= 20"),
        (vec!["racket", "tweener", "--segments", "100000000"], "invalid segments", "<= 400"),
        (vec!["simulate", "--segments", "100000000"], "invalid segments", "<= 400"),
    ];
    let mut failures = Vec::new();
    for (args, field, limit) in &cases {
        let o = run_limited(args, dir.path());
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        let ok = o.status.code() == Some(2)
            && err.lines().count() == 1
            && err.contains(field)
            && err.contains(limit)
            && o.stdout.is_empty();
        if !ok {
            failures.push(format!("{args:?}: exit {:?}, {err}", o.status.code()));
        }
    }
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none(), "a refused run wrote a file");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_limits_admit_the_work_they_are_meant_for() {
    // a million-value axis is made (within 1 GB) before the product refuses the sweep; a
    // second-long time series runs
    let dir = tempfile::tempdir().unwrap();
    let o = run_limited(
        &["sweep", "--x", "0.1:0.2:1000000", "--ks", "1e4:5e4:10", "--mb", "0.05:0.06:2", "--v1", "1"],
        dir.path(),
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("at most 10000000"), "{err}");
    let o = run_limited(&["simulate", "--series", "s.csv", "--series-end", "1"], dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = std::fs::read_to_string(dir.path().join("s.csv")).unwrap().lines().count();
    // one row per 2e-5 s (rounded to whole steps of 1.27e-6 s) over 1 s
    assert!(rows > 45_000, "{rows} rows");
}

/// Work estimated before it starts (issue 40, item 3): a `map`, `sweep` or `uncertainty`
/// estimated above ten minutes is refused, before anything is written, with the estimate and
/// what makes it long, unless `--long` is given; one above a minute says so on its first line
/// of standard error before the work. The cases are the issue's: a racket of 1e6 kg held in the
/// hand rings at 0.07 Hz and is followed for two of its periods after every impact (millions of
/// steps, about 2 s an impact), and a stiff contact on 400 segments keeps every mode in the
/// modal solver's search after the impact (about 0.3 s an impact).
#[test]
fn long_work_is_told_before_it_starts_and_refused_beyond_the_bound_unless_asked() {
    let dir = tempfile::tempdir().unwrap();
    let held = ["--grip", "hand", "--mass", "1e6"];
    let refused: Vec<Vec<&str>> = vec![
        [&["uncertainty", "--vary", "ks", "--samples", "1024", "--out", "u.json"][..], &held[..]].concat(),
        [&["sweep", "--out", "s.csv"][..], &held[..], &["--x", "0.05:0.25:2000"][..]].concat(),
        [&["map", "--nx", "61", "--out", "m.csv"][..], &held[..]].concat(),
    ];
    for args in &refused {
        let o = run_limited(args, dir.path());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(": the run is estimated at about "), "{args:?}: {err}");
        assert!(err.contains("two periods of its fundamental, f1 = 0.0727 Hz"), "{args:?}: {err}");
        assert!(err.contains("give --long to run it anyway"), "{args:?}: {err}");
    }
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "nothing written");
    // told, then run: the first line of standard error is the estimate (the run is stopped there)
    let told: Vec<Vec<&str>> = vec![
        [&["uncertainty", "--vary", "ks", "--samples", "1024", "--out", "u.json", "--long"][..], &held[..]].concat(),
        vec!["map", "--v1", "1e-3", "--k1", "1e9", "--ks", "1e12", "--segments", "400", "--out", "m.csv"],
    ];
    for args in &told {
        use std::io::BufRead;
        let mut child = Command::new(env!("CARGO_BIN_EXE_racket-impact"))
            .current_dir(dir.path())
            .args(args)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let mut first = String::new();
        std::io::BufReader::new(child.stderr.take().unwrap()).read_line(&mut first).unwrap();
        child.kill().unwrap();
        child.wait().unwrap();
        assert!(first.starts_with("warning: this run is estimated at about "), "{args:?}: {first}");
    }
    let first = {
        let o = run_limited(
            &[
                "map",
                "--v1",
                "1e-3",
                "--k1",
                "1e9",
                "--ks",
                "1e12",
                "--segments",
                "400",
                "--nx",
                "3",
                "--nr",
                "2",
                "--out",
                "m.csv",
            ],
            dir.path(),
        );
        String::from_utf8_lossy(&o.stderr).into_owned()
    };
    assert!(!first.contains("estimated"), "a small map says nothing: {first}");
}
