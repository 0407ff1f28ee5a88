//! `make test` on a machine with only the Rust toolchain (issue 32, item 10): without
//! cargo-nextest the Makefile runs the suite with plain `cargo test`, never asking for a third
//! command. Checked with `make -n` (the commands, not a second run of the suite) against a
//! `cargo` on PATH that has no `nextest` subcommand.

use std::path::Path;
use std::process::Command;

/// The commands `make -n test` would run, with `cargo` being `cargo_dir/cargo` first on PATH.
fn planned(cargo_dir: Option<&Path>) -> String {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut cmd = Command::new("make");
    cmd.args(["-n", "-C", root, "test"]).env_remove("MAKEFLAGS").env_remove("CARGO");
    if let Some(dir) = cargo_dir {
        let path = std::env::var_os("PATH").unwrap_or_default();
        let mut dirs = vec![dir.to_path_buf()];
        dirs.extend(std::env::split_paths(&path));
        cmd.env("PATH", std::env::join_paths(dirs).expect("PATH"));
    }
    let out = cmd.output().expect("make runs");
    assert!(out.status.success(), "make -n test failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[cfg(unix)]
#[test]
fn make_test_without_nextest_falls_back_to_cargo_test() {
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
    let plan = planned(Some(dir.path()));
    assert!(!plan.contains("nextest"), "without nextest, make test must not call it:\n{plan}");
    assert!(plan.contains("cargo test --locked --doc"), "{plan}");
    assert!(plan.contains("cargo test --locked --no-fail-fast --lib --bins --tests"), "{plan}");
}

#[test]
fn make_test_uses_nextest_where_it_is_installed() {
    let has_nextest = Command::new("cargo").args(["nextest", "--version"]).output().is_ok_and(|o| o.status.success());
    let plan = planned(None);
    assert_eq!(plan.contains("cargo nextest run --locked --no-fail-fast"), has_nextest, "{plan}");
}
