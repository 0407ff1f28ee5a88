//! Determinism and atomicity of the outputs: the same command twice gives byte-identical files,
//! and a `figures` run killed midway leaves every output either as it was or complete (temp
//! file + rename), never truncated.

mod common;

use common::{bin, Scratch};
use std::path::Path;
use std::time::{Duration, Instant};

fn committed(name: &str) -> Vec<u8> {
    std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("figures").join(name)).unwrap()
}

#[test]
fn the_same_command_twice_writes_identical_bytes() {
    let (a, b) = (Scratch::new("det-a"), Scratch::new("det-b"));
    for dir in [a.dir(), b.dir()] {
        let out =
            bin().args(["figures", "--only", "fig4_energy", "--only", "modes", "--out"]).arg(dir).output().unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    for f in ["fig4_energy.csv", "fig4_energy.png", "modes.csv", "modes.png"] {
        let (x, y) = (std::fs::read(a.path(f)).unwrap(), std::fs::read(b.path(f)).unwrap());
        assert!(x == y, "{f} differs between two runs");
        assert!(x == committed(f), "{f} differs from the committed figure");
    }
    let series = |dir: &Path| {
        let p = dir.join("s.csv");
        let out = bin().args(["simulate", "--format", "json", "--series"]).arg(&p).output().unwrap();
        assert!(out.status.success());
        (out.stdout, std::fs::read(p).unwrap())
    };
    assert_eq!(series(a.dir()), series(b.dir()));
}

#[test]
fn a_figures_run_killed_midway_leaves_every_output_old_or_complete() {
    let scratch = Scratch::new("kill");
    let dir = scratch.dir();
    let ids =
        ["fig5a_position_soft", "fig5b_position_stiff", "fig6_string_stiffness", "fig9_stiff_frame", "convergence"];
    let old = b"old output, must survive intact or be replaced whole\n".to_vec();
    let files: Vec<String> = ids.iter().flat_map(|id| [format!("{id}.csv"), format!("{id}.png")]).collect();
    for f in &files {
        std::fs::write(dir.join(f), &old).unwrap();
    }
    let mut cmd = bin();
    cmd.arg("figures").arg("--out").arg(dir);
    for id in ids {
        cmd.args(["--only", id]);
    }
    let mut child = cmd.stderr(std::process::Stdio::null()).spawn().unwrap();
    // kill as soon as the first output has been replaced
    let start = Instant::now();
    loop {
        let replaced = files.iter().any(|f| std::fs::read(dir.join(f)).map(|b| b != old).unwrap_or(true));
        if replaced || start.elapsed() > Duration::from_secs(120) {
            break;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let (mut kept, mut replaced) = (0, 0);
    for f in &files {
        let now = std::fs::read(dir.join(f)).unwrap_or_else(|e| panic!("{f} vanished: {e}"));
        if now == old {
            kept += 1;
        } else {
            assert!(now == committed(f), "{f} is neither the old file nor the complete new one");
            replaced += 1;
        }
    }
    // (figures publishes every experiment's files together at the end, issue 32: a SIGKILL,
    // which nothing can catch, lands during or after the renames, so some or all are new)
    assert!(replaced >= 1, "the kill landed before any output was published ({replaced} replaced, {kept} kept)");
}
