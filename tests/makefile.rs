//! `make test` on a machine with only the Rust toolchain (issue 32, item 10): without
//! cargo-nextest the Makefile runs the suite with plain `cargo test`, never asking for a third
//! command; and `make test` after `make figures` reuses the release build (issue 40: every
//! cargo command of the tests builds with the release profile). Checked with `make -n` (the
//! commands, not a second run of the suite) against a `cargo` on PATH that has no `nextest`
//! subcommand; the commands are read as commands (their words), so a checkout whose path
//! holds "nextest" or "--release" proves nothing either way.

mod common;

use std::path::Path;
use std::process::Command;

/// The commands `make -n test` would run, one per line, each split into its words, with
/// `cargo` being `cargo_dir/cargo` first on PATH (make runs in the checkout, printing no
/// directory).
fn planned(cargo_dir: Option<&Path>) -> Vec<Vec<String>> {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut cmd = Command::new("make");
    cmd.args(["-n", "--no-print-directory", "test"]).current_dir(root).env_remove("MAKEFLAGS").env_remove("CARGO");
    if let Some(dir) = cargo_dir {
        let path = std::env::var_os("PATH").unwrap_or_default();
        let mut dirs = vec![dir.to_path_buf()];
        dirs.extend(std::env::split_paths(&path));
        cmd.env("PATH", std::env::join_paths(dirs).expect("PATH"));
    }
    let out = cmd.output().expect("make runs");
    assert!(out.status.success(), "make -n test failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| l.split_whitespace().map(String::from).collect::<Vec<_>>())
        .filter(|words| !words.is_empty())
        .collect()
}

/// The cargo commands of the plan: the words after `cargo` (`["nextest", "run", ...]`).
fn cargo_commands(plan: &[Vec<String>]) -> Vec<Vec<&str>> {
    plan.iter()
        .filter(|words| words[0] == "cargo" || words[0].ends_with("/cargo"))
        .map(|words| words[1..].iter().map(String::as_str).collect())
        .collect()
}

/// Whether `command` (words after `cargo`) starts with `sub` and holds every word of `flags`.
fn is(command: &[&str], sub: &[&str], flags: &[&str]) -> bool {
    command.starts_with(sub) && flags.iter().all(|f| command.contains(f))
}

/// A folder holding a `cargo` that has no `nextest` subcommand (and runs the real cargo
/// otherwise), to put first on PATH.
#[cfg(unix)]
fn cargo_without_nextest() -> tempfile::TempDir {
    use std::os::unix::fs::PermissionsExt;
    let real = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
    let dir = tempfile::tempdir().expect("temp dir");
    let fake = dir.path().join("cargo");
    std::fs::write(
        &fake,
        format!(
            "#!/bin/sh\nif [ \"$1\" = nextest ]; then echo 'error: no such command: `nextest`' >&2; exit 101; fi\nexec '{real}' \"$@\"\n"
        ),
    )
    .expect("write the fake cargo");
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).expect("chmod");
    dir
}

#[cfg(unix)]
#[test]
fn make_test_without_nextest_falls_back_to_cargo_test() {
    let dir = cargo_without_nextest();
    let plan = planned(Some(dir.path()));
    let commands = cargo_commands(&plan);
    assert!(
        !commands.iter().any(|c| c.first() == Some(&"nextest")),
        "without nextest, make test must not call it:\n{plan:?}"
    );
    assert!(commands.iter().any(|c| is(c, &["test"], &["--locked", "--doc"])), "{plan:?}");
    let suite = ["--locked", "--no-fail-fast", "--lib", "--bins", "--tests"];
    assert!(commands.iter().any(|c| is(c, &["test"], &suite)), "{plan:?}");
}

#[test]
fn make_test_uses_nextest_where_it_is_installed() {
    let has_nextest = Command::new("cargo").args(["nextest", "--version"]).output().is_ok_and(|o| o.status.success());
    let plan = planned(None);
    let commands = cargo_commands(&plan);
    let nextest = commands.iter().any(|c| is(c, &["nextest", "run"], &["--locked", "--no-fail-fast"]));
    assert_eq!(nextest, has_nextest, "{plan:?}");
}

/// `make test` after `make figures` builds on the release build: every cargo command of the
/// test target (doc tests, the suite), with nextest or without, uses the release profile, as
/// `make build` does, and none names another profile.
#[cfg(unix)]
#[test]
fn make_test_builds_with_the_release_profile_make_figures_built() {
    let without = cargo_without_nextest();
    for cargo_dir in [None, Some(without.path())] {
        let plan = planned(cargo_dir);
        let commands = cargo_commands(&plan);
        assert!(commands.len() >= 2, "{plan:?}");
        for c in &commands {
            assert!(c.contains(&"--release"), "not the release profile: cargo {}", c.join(" "));
            assert!(!c.iter().any(|w| w.starts_with("--profile") || w.starts_with("--cargo-profile")), "{c:?}");
        }
    }
    let build: Vec<Vec<String>> = {
        let out = Command::new("make")
            .args(["-n", "--no-print-directory", "build"])
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .env_remove("MAKEFLAGS")
            .output()
            .expect("make runs");
        String::from_utf8_lossy(&out.stdout).lines().map(|l| l.split_whitespace().map(String::from).collect()).collect()
    };
    assert!(cargo_commands(&build).iter().any(|c| is(c, &["build"], &["--release"])), "{build:?}");
}

/// `make figures` ends with one line for the report (`report --summary`), not the whole of
/// REPORT.md, which pushed the per-figure lines off the screen; that line names the file and
/// the counts its headline gives.
#[test]
fn make_figures_ends_with_one_line_for_the_report() {
    let root = env!("CARGO_MANIFEST_DIR");
    let out = Command::new("make")
        .args(["-n", "--no-print-directory", "figures"])
        .current_dir(root)
        .env_remove("MAKEFLAGS")
        .output()
        .expect("make runs");
    let plan = String::from_utf8_lossy(&out.stdout);
    let last: Vec<&str> = plan.lines().last().unwrap_or_default().split_whitespace().collect();
    assert_eq!(last.get(1..), Some(&["report", "--summary"][..]), "{plan}");
    let dir = tempfile::tempdir().unwrap();
    let o = common::bin().args(["report", "--summary", "--out", "r.md"]).current_dir(dir.path()).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let printed = String::from_utf8_lossy(&o.stdout);
    assert_eq!(printed.lines().count(), 1, "{printed}");
    let report = std::fs::read_to_string(dir.path().join("r.md")).unwrap();
    let headline = report.lines().find(|l| l.starts_with("**")).unwrap().split("**").nth(1).unwrap();
    assert!(
        printed.starts_with(&format!("wrote r.md: {headline}; conclusions under the inputs' uncertainty: ")),
        "{printed}"
    );
}

/// python/tools.sh, with `python` as the Python asked for and `venv` the environment to set up,
/// in an environment without CI (unless `ci`) and with the package registry `index`: exit code,
/// standard output, standard error.
#[cfg(unix)]
fn python_tools(python: &str, venv: &Path, ci: bool, index: Option<&str>) -> (Option<i32>, String, String) {
    let mut cmd = Command::new("sh");
    cmd.arg("python/tools.sh").arg(python).arg(venv).current_dir(env!("CARGO_MANIFEST_DIR")).env_remove("CI");
    if ci {
        cmd.env("CI", "true");
    }
    if let Some(index) = index {
        cmd.env("PIP_INDEX_URL", index)
            .env("PIP_FIND_LINKS", "")
            .env("PIP_EXTRA_INDEX_URL", "")
            .env_remove("PIP_NO_INDEX");
    }
    let o = cmd.output().expect("sh runs");
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// Without Python 3.9+, `make test` runs the Rust tests and says in one line that the Python
/// ones need it (exit 0); under CI, where every test must run, that line is an error (exit 1).
#[cfg(unix)]
#[test]
fn without_python_the_python_tests_are_said_to_need_it_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let venv = dir.path().join("venv");
    let missing = dir.path().join("no-python3").display().to_string();
    let (code, out, err) = python_tools(&missing, &venv, false, None);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.is_empty(), "{out}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("Python tests not run: they need Python 3.9+"), "{err}");
    let (code, _, err) = python_tools(&missing, &venv, true, None);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.starts_with("error: the Python tests need Python 3.9+") && err.lines().count() == 1, "{err}");
    // a Python older than 3.9 is told the same
    let old = dir.path().join("python3.8");
    std::fs::write(&old, "#!/bin/sh\n[ \"$1\" = -c ] && exit 1\nexit 0\n").unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&old, std::fs::Permissions::from_mode(0o755)).unwrap();
    let (code, out, err) = python_tools(old.to_str().unwrap(), &venv, false, None);
    assert_eq!((code, out.as_str()), (Some(0), ""), "{err}");
    assert!(err.starts_with("Python tests not run: they need Python 3.9+") && err.lines().count() == 1, "{err}");
    assert!(!venv.exists(), "no environment is made without Python");
}

/// With Python 3 but without the tools and without a package registry, the set-up stops with
/// one line that says so and names its log (the Python asked for is `python3 -S`, which sees no
/// installed packages, so the environment is set up whatever this machine has installed).
#[cfg(unix)]
#[test]
fn without_a_registry_the_python_set_up_fails_in_one_line() {
    let has_python3 = Command::new("python3")
        .args(["-c", "import sys, venv; sys.exit(sys.version_info < (3, 9))"])
        .output()
        .is_ok_and(|o| o.status.success());
    let dir = tempfile::tempdir().unwrap();
    let python = dir.path().join("python");
    std::fs::write(&python, "#!/bin/sh\nexec python3 -S \"$@\"\n").unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&python, std::fs::Permissions::from_mode(0o755)).unwrap();
    let venv = dir.path().join("venv");
    // (port 9, discard: nothing answers)
    let (code, out, err) = python_tools(python.to_str().unwrap(), &venv, false, Some("http://127.0.0.1:9/simple"));
    if !has_python3 {
        // this machine has no Python 3.9+ with venv: the one line says so instead
        assert_eq!(code, Some(if err.contains("need Python 3.9+") { 0 } else { 1 }), "{err}");
        return;
    }
    assert_eq!(code, Some(1), "{err}");
    assert!(out.is_empty(), "{out}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(lines[0].starts_with("Python tests: installing maturin, pytest, numpy, pandas"), "{err}");
    let log = format!("{}.log", venv.display());
    assert_eq!(
        lines[1],
        format!(
            "error: cannot install maturin, pytest, numpy, pandas into {} from the package registry (no network, or \
             no registry?); log: {log}",
            venv.display()
        )
    );
    assert!(std::fs::read_to_string(&log).unwrap().contains("maturin"), "the log names what failed");
}

/// `make test` runs the Python tests through python/tools.sh (no step that skips them quietly),
/// and `.ci/run` leaves their set-up to it, as on a fresh machine.
#[test]
fn make_test_runs_the_python_tests_with_the_tools_it_finds_or_installs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = Command::new("make")
        .args(["-n", "--no-print-directory", "python-test"])
        .current_dir(root)
        .env_remove("MAKEFLAGS")
        .output()
        .expect("make runs");
    let plan = String::from_utf8_lossy(&out.stdout);
    assert!(plan.contains("sh python/tools.sh") && plan.contains("-m pytest"), "{plan}");
    assert!(!plan.contains("skipped"), "{plan}");
    let ci = std::fs::read_to_string(root.join(".ci/run")).unwrap();
    let commands: Vec<&str> = ci.lines().map(str::trim).filter(|l| !l.starts_with('#') && !l.is_empty()).collect();
    assert_eq!(commands.last(), Some(&"make test"), "{ci}");
    assert!(!commands.iter().any(|l| l.contains("pip install")), "{ci}");
}
