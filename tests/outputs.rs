//! Output paths are written, never replaced (trap class 1 of issue 24): a device or FIFO is
//! written through and stays what it was, a symlink's target is written and the link kept, a
//! directory that cannot be written is refused before any work with exit 2 and nothing left,
//! and a command whose standard output fails (`> /dev/full`) publishes none of its files.
//!
//! Run as root, the device nodes are the test's own (`mknod` in a scratch directory), so a
//! regression cannot replace the machine's `/dev/null`; the read-only directory is then tried
//! by the binary run as `nobody`, for whom the permission bits hold.

#![cfg(unix)]

mod common;

use common::{bin, names_in, Scratch};
use std::os::unix::fs::FileTypeExt;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn is_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("Uid:")).map(|l| l.split_whitespace().nth(2) == Some("0")))
        .unwrap_or(false)
}

/// A character device that discards (`null`) or refuses (`full`) what is written: our own node
/// when we may make one, else the system's.
fn device(s: &Scratch, which: &str) -> PathBuf {
    let (minor, system) = match which {
        "null" => ("3", "/dev/null"),
        _ => ("7", "/dev/full"),
    };
    let own = s.path(&format!("{which}-device"));
    let made = is_root()
        && Command::new("mknod").arg(&own).args(["c", "1", minor]).status().map(|st| st.success()).unwrap_or(false);
    if made {
        own
    } else {
        PathBuf::from(system)
    }
}

fn is_char_device(p: &Path) -> bool {
    std::fs::symlink_metadata(p).map(|m| m.file_type().is_char_device()).unwrap_or(false)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every writer of the crate with `path` as its output (one file each).
fn writers(path: &Path) -> Vec<Vec<String>> {
    let p = path.to_str().unwrap().to_string();
    vec![
        vec!["simulate".into(), "--solver".into(), "fd".into(), "--series".into(), p.clone()],
        vec!["sweep".into(), "--out".into(), p.clone(), "--x".into(), "0.1,0.2".into()],
        vec!["report".into(), "--out".into(), p],
    ]
}

fn temp_leftovers(stem: &str) -> Vec<String> {
    names_in(&std::env::temp_dir()).into_iter().filter(|n| n.starts_with(&format!(".{stem}.tmp."))).collect()
}

#[test]
fn a_device_is_written_through_and_stays_a_device() {
    let s = Scratch::new("device");
    let null = device(&s, "null");
    let full = device(&s, "full");
    for args in writers(&null) {
        let o = bin().args(&args).stdout(Stdio::null()).output().unwrap();
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert!(is_char_device(&null), "{args:?} replaced the device {}", null.display());
    }
    for args in writers(&full) {
        let o = bin().args(&args).stdout(Stdio::null()).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: a full device must fail: {}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1, "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("No space left"), "{args:?}: {}", stderr(&o));
        assert!(is_char_device(&full), "{args:?} replaced the device {}", full.display());
    }
    let name = |p: &Path| p.file_name().unwrap().to_string_lossy().into_owned();
    assert!(temp_leftovers(&name(&null)).is_empty() && temp_leftovers(&name(&full)).is_empty());
    // a map is three files named from --out: a device is refused before any work
    let o = bin().args(["map", "--out"]).arg(&null).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("invalid out") && stderr(&o).contains("device"), "{}", stderr(&o));
    assert!(is_char_device(&null));
    let made: Vec<String> = s.names().into_iter().filter(|n| !n.ends_with("-device")).collect();
    assert!(made.is_empty(), "files left: {made:?}");
}

#[test]
fn a_fifo_is_written_through_and_stays_a_fifo() {
    let s = Scratch::new("fifo");
    let fifo = s.path("pipe");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let regular = s.path("regular.csv");
    for (args, reference) in writers(&fifo).into_iter().zip(writers(&regular)).take(2) {
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read(fifo).unwrap())
        };
        let o = bin().args(&args).stdout(Stdio::null()).output().unwrap();
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        let through = reader.join().unwrap();
        let o = bin().args(&reference).stdout(Stdio::null()).output().unwrap();
        assert!(o.status.success(), "{reference:?}: {}", stderr(&o));
        assert!(through == std::fs::read(&regular).unwrap(), "{args:?}: the FIFO carried other bytes than a file");
        assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "{args:?} replaced the FIFO");
    }
    assert_eq!(s.names(), vec!["pipe".to_string(), "regular.csv".to_string()]);
}

/// `--out /dev/stdout` with standard output a pipe (`... | cat`): the link chain ends at
/// `/proc/self/fd/1 -> pipe:[N]`, which is not a path; the path given is opened and the file's
/// bytes come down the pipe. A map (three files) refuses it as it refuses any device.
#[test]
fn standard_output_as_a_pipe_is_written_through() {
    let s = Scratch::new("stdout-pipe");
    let regular = s.path("regular.csv");
    for (args, reference) in writers(Path::new("/dev/stdout")).into_iter().zip(writers(&regular)) {
        let o = bin().args(&args).stdout(Stdio::piped()).output().unwrap();
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        let r = bin().args(&reference).stdout(Stdio::null()).output().unwrap();
        assert!(r.status.success(), "{reference:?}: {}", stderr(&r));
        let file = std::fs::read(&regular).unwrap();
        assert!(!file.is_empty());
        assert!(
            o.stdout.windows(file.len()).any(|w| w == file.as_slice()),
            "{args:?}: the pipe did not carry the file's bytes: {}",
            String::from_utf8_lossy(&o.stdout)
        );
    }
    let o =
        bin().args(["map", "--nx", "5", "--nr", "5", "--out", "/dev/stdout"]).stdout(Stdio::piped()).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("invalid out") && stderr(&o).contains("device or pipe"), "{}", stderr(&o));
    assert!(temp_leftovers("stdout").is_empty());
}

#[test]
fn a_symlink_keeps_pointing_at_its_target_which_is_written() {
    let s = Scratch::new("symlink");
    std::fs::create_dir(s.path("data")).unwrap();
    let target = s.path("data/target.csv");
    std::fs::write(&target, "old\n").unwrap();
    let link = s.path("link.csv");
    std::os::unix::fs::symlink("data/target.csv", &link).unwrap();
    let dangling = s.path("dangling.csv");
    std::os::unix::fs::symlink("data/new.csv", &dangling).unwrap();
    let direct = s.path("direct.csv");
    for (args, reference) in writers(&link).into_iter().zip(writers(&direct)).take(2) {
        for a in [&args, &reference] {
            let o = bin().args(a).stdout(Stdio::null()).output().unwrap();
            assert!(o.status.success(), "{a:?}: {}", stderr(&o));
        }
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "{args:?} replaced the link");
        assert_eq!(std::fs::read_link(&link).unwrap(), Path::new("data/target.csv"));
        assert!(std::fs::read(&target).unwrap() == std::fs::read(&direct).unwrap(), "{args:?}: the target differs");
    }
    for a in [&writers(&dangling)[0], &writers(&direct)[0]] {
        let o = bin().args(a).stdout(Stdio::null()).output().unwrap();
        assert!(o.status.success(), "{a:?}: {}", stderr(&o));
    }
    assert!(std::fs::symlink_metadata(&dangling).unwrap().file_type().is_symlink());
    assert!(std::fs::read(s.path("data/new.csv")).unwrap() == std::fs::read(&direct).unwrap());
    assert_eq!(names_in(&s.path("data")), vec!["new.csv".to_string(), "target.csv".to_string()]);
    assert_eq!(s.names(), vec!["dangling.csv", "data", "direct.csv", "link.csv"]);
}

/// Replacing an output keeps the permissions of the file replaced (`chmod 600 out.csv` stays
/// 600, and a read-only 444 file stays read-only), for every writer and a map's three files.
#[test]
fn a_replaced_output_keeps_its_permissions() {
    use std::os::unix::fs::PermissionsExt;
    let s = Scratch::new("modes");
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o7777;
    for (i, wanted) in [0o640, 0o600, 0o444].into_iter().enumerate() {
        let out = s.path("out.csv");
        // (the slow report once)
        for args in writers(&out).into_iter().take(if i == 0 { 3 } else { 2 }) {
            let _ = std::fs::remove_file(&out);
            std::fs::write(&out, "old\n").unwrap();
            std::fs::set_permissions(&out, std::fs::Permissions::from_mode(wanted)).unwrap();
            let o = bin().args(&args).stdout(Stdio::null()).output().unwrap();
            assert!(o.status.success(), "{args:?}: {}", stderr(&o));
            assert_ne!(std::fs::read(&out).unwrap(), b"old\n", "{args:?}: not written");
            assert_eq!(mode(&out), wanted, "{args:?}: permissions {:o}, were {wanted:o}", mode(&out));
        }
        let files = ["m.csv", "m.png", "m.json"].map(|n| s.path(n));
        for f in &files {
            let _ = std::fs::remove_file(f);
            std::fs::write(f, "old\n").unwrap();
            std::fs::set_permissions(f, std::fs::Permissions::from_mode(wanted)).unwrap();
        }
        let o = bin().args(["map", "--nx", "5", "--nr", "3", "--out"]).arg(&files[0]).output().unwrap();
        assert!(o.status.success(), "map: {}", stderr(&o));
        for f in &files {
            assert_ne!(std::fs::read(f).unwrap(), b"old\n", "{}: not written", f.display());
            assert_eq!(mode(f), wanted, "{}: permissions {:o}, were {wanted:o}", f.display(), mode(f));
        }
    }
    assert_eq!(s.names(), vec!["m.csv", "m.json", "m.png", "out.csv"]);
}

#[test]
fn a_read_only_directory_is_refused_before_any_work_and_nothing_is_left() {
    let s = Scratch::new("readonly");
    let ro = s.path("ro");
    std::fs::create_dir(&ro).unwrap();
    let out = ro.join("out.csv");
    let mut cases = writers(&out);
    cases.push(vec!["map".into(), "--out".into(), out.to_str().unwrap().into()]);
    cases.push(vec!["figures".into(), "--only".into(), "modes".into(), "--out".into(), ro.to_str().unwrap().into()]);
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    for args in &cases {
        let mut cmd = bin();
        cmd.args(args);
        if is_root() {
            cmd.uid(65534).gid(65534); // permission bits do not bind root
        }
        let o = cmd.output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1, "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("permission denied"), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?} printed a result");
        assert!(names_in(&ro).is_empty(), "{args:?} left {:?}", names_in(&ro));
    }
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
}

#[test]
fn a_failed_standard_output_publishes_no_file() {
    let s = Scratch::new("stdout");
    let full = device(&s, "full");
    let cases: Vec<(Vec<String>, Vec<&str>)> = vec![
        (vec!["map".into(), "--nx".into(), "5".into(), "--nr".into(), "3".into()], vec!["m.csv", "m.png", "m.json"]),
        (vec!["simulate".into(), "--solver".into(), "fd".into()], vec!["series.csv"]),
        (vec!["report".into()], vec!["REPORT.md"]),
    ];
    for (args, files) in cases {
        let mut cmd = bin();
        cmd.args(&args);
        match args[0].as_str() {
            "map" => cmd.arg("--out").arg(s.path("m.csv")),
            "simulate" => cmd.arg("--series").arg(s.path("series.csv")),
            _ => cmd.arg("--out").arg(s.path("REPORT.md")),
        };
        let o = cmd.stdout(std::fs::OpenOptions::new().write(true).open(&full).unwrap()).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("<stdout>"), "{args:?}: {}", stderr(&o));
        let left: Vec<String> = s.names().into_iter().filter(|n| !n.ends_with("-device")).collect();
        assert!(left.is_empty(), "{args:?} left {left:?} (expected none of {files:?})");
    }
}

/// A failing output device (`--series /dev/full`) fails the command (exit 2, one line) before
/// its result is printed: the device is written before the standard output, the files after.
#[test]
fn a_failing_output_device_fails_before_the_result_is_printed() {
    let s = Scratch::new("device-first");
    let full = device(&s, "full");
    let mut cases = writers(&full);
    cases.retain(|a| a[0] != "sweep"); // (a sweep to a file prints nothing)
    for format in ["text", "json", "csv"] {
        cases.push(vec![
            "simulate".into(),
            "--series".into(),
            full.to_str().unwrap().into(),
            "--format".into(),
            format.into(),
        ]);
    }
    for args in cases {
        let o = bin().args(&args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1, "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("No space left"), "{args:?}: {}", stderr(&o));
        assert!(
            o.stdout.is_empty(),
            "{args:?} printed its result before failing: {}",
            String::from_utf8_lossy(&o.stdout)
        );
    }
}

/// `map --out LINK.csv`: the link's target is written and the link kept, and the PNG and JSON
/// go beside the target with its stem (the three files of a map stay together); the summary
/// names where they went. A plain path keeps its siblings beside it.
#[test]
fn a_map_through_a_symlink_keeps_its_three_files_beside_the_target() {
    let s = Scratch::new("map-link");
    std::fs::create_dir(s.path("data")).unwrap();
    std::fs::create_dir(s.path("out")).unwrap();
    std::fs::write(s.path("data/t.csv"), "old\n").unwrap();
    std::fs::write(s.path("data/t.png"), "old png\n").unwrap();
    let link = s.path("out/link.csv");
    std::os::unix::fs::symlink("../data/t.csv", &link).unwrap();
    let grid = ["map", "--nx", "3", "--nr", "2", "--out"];
    let o = bin().args(grid).arg(&link).output().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link was replaced");
    assert_eq!(names_in(&s.path("out")), vec!["link.csv"], "siblings left beside the link");
    assert_eq!(names_in(&s.path("data")), vec!["t.csv", "t.json", "t.png"]);
    let o2 = bin().args(grid).arg(s.path("plain.csv")).output().unwrap();
    assert!(o2.status.success(), "{}", stderr(&o2));
    for ext in ["csv", "png", "json"] {
        let (through, plain) = (s.path(&format!("data/t.{ext}")), s.path(&format!("plain.{ext}")));
        assert!(std::fs::read(through).unwrap() == std::fs::read(plain).unwrap(), "{ext} differs from a plain run");
    }
    let printed = String::from_utf8_lossy(&o.stdout);
    let wrote = printed.lines().last().unwrap();
    assert!(wrote.contains("link.csv (a link to ") && wrote.contains("t.png") && wrote.contains("t.json"), "{wrote}");
    // a link to a .png would have the CSV and the PNG in one file: refused, nothing written
    let to_png = s.path("out/to_png.csv");
    std::os::unix::fs::symlink("../data/t.png", &to_png).unwrap();
    let before = std::fs::read(s.path("data/t.png")).unwrap();
    let o = bin().args(grid).arg(&to_png).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("invalid out"), "{}", stderr(&o));
    assert!(std::fs::read(s.path("data/t.png")).unwrap() == before);
}

/// A standard error that cannot be written (`2> /dev/full`) changes neither the result nor the
/// exit code: a warning is dropped (exit 0, the result printed), an error still exits 2, and
/// nothing panics (exit 101).
#[test]
fn a_full_standard_error_changes_no_result_or_exit_code() {
    let s = Scratch::new("stderr");
    let full = device(&s, "full");
    let err = || std::fs::OpenOptions::new().write(true).open(&full).unwrap();
    let o = bin().args(["simulate", "--solver", "modal", "--ks", "3e5"]).stderr(err()).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "a warning on a full stderr");
    let quiet = bin().args(["simulate", "--solver", "modal", "--ks", "3e5", "--quiet"]).output().unwrap();
    assert!(!o.stdout.is_empty() && o.stdout == quiet.stdout);
    for args in [&["simulate", "--ks", "-1"][..], &["simulate", "--no-such-flag"][..]] {
        let o = bin().args(args).stderr(err()).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
    }
}
