//! Helpers the integration tests share: the binary under test and a scratch directory.
//! (Each test file that uses them declares `mod common;`; a file uses only some of them.)
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The command-line binary built with the tests, keeping what it may keep of its build where
/// `make figures` keeps it ([`CACHE`]).
pub fn bin() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_racket-impact"));
    cmd.env("RACKET_IMPACT_CACHE", CACHE);
    cmd
}

/// The folder where the binary keeps the report of its build (src/cli/cache.rs): the one `make
/// figures` names, so that the tests' many runs of `report` (its options, its output paths)
/// read the report `make figures` computed with the same binary instead of computing it again
/// (about 40 CPU-seconds each), and the runs of `uncertainty --claims` at one sample count share
/// one computation. A text of another build is never read.
pub const CACHE: &str = concat!(env!("CARGO_TARGET_TMPDIR"), "/cache");

/// Run the binary with `args` and wait for it.
pub fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("binary runs")
}

/// A fresh directory under the system's temporary directory (named after the test that made
/// it and this process), removed with everything in it when dropped. Made with the usual
/// permissions (not `tempfile`'s owner-only ones): tests/outputs.rs runs the binary as another
/// user inside it.
pub struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

impl Scratch {
    pub fn new(name: &str) -> Self {
        static MADE: AtomicUsize = AtomicUsize::new(0);
        let n = MADE.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("racket-impact-{name}-{}-{n}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("scratch dir");
        Scratch(dir)
    }

    /// The directory itself.
    pub fn dir(&self) -> &Path {
        &self.0
    }

    /// The path of `name` in the directory.
    pub fn path(&self, name: &str) -> PathBuf {
        self.dir().join(name)
    }

    /// The path of `name` in the directory as a command-line argument.
    pub fn arg(&self, name: &str) -> String {
        self.path(name).to_str().expect("a UTF-8 temporary path").to_string()
    }

    /// Write `bytes` to `name` in the directory; its path as a command-line argument.
    pub fn file(&self, name: &str, bytes: impl AsRef<[u8]>) -> String {
        std::fs::write(self.path(name), bytes).unwrap();
        self.arg(name)
    }

    /// Every name in the directory (hidden temporary files too), sorted.
    pub fn names(&self) -> Vec<String> {
        names_in(self.dir())
    }

    /// Every file below the directory with its bytes, sorted by path (to check nothing changed).
    pub fn snapshot(&self) -> Vec<(PathBuf, Vec<u8>)> {
        fn walk(d: &Path, out: &mut Vec<(PathBuf, Vec<u8>)>) {
            let mut entries: Vec<_> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path()).collect();
            entries.sort();
            for p in entries {
                if p.is_dir() {
                    walk(&p, out);
                } else {
                    out.push((p.clone(), std::fs::read(&p).unwrap()));
                }
            }
        }
        let mut out = Vec::new();
        walk(self.dir(), &mut out);
        out
    }

    /// Run the binary with `args` in this directory, with no standard input.
    pub fn run(&self, args: &[&str]) -> Output {
        bin().current_dir(self.dir()).args(args).stdin(Stdio::null()).output().expect("binary runs")
    }
}

/// The names in `dir`, sorted.
pub fn names_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}
